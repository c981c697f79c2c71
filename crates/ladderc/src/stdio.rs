//! Writes to standard output and standard error that end quietly on a closed pipe.
//!
//! Input: text to print. Output: it is written and flushed, or, when the reader went away
//! (`ladderc run ... | head -1`), dropped without a panic or a message: the command goes on and still writes
//! the files it was asked for. Invariant: `print!`/`println!` (which panic on a closed pipe) are not used on
//! the pipeline commands' output paths; these functions are.

use std::io::{ErrorKind, Write};

/// Writes `text` to standard output. `Err` only for a failure other than a closed pipe (a full disk
/// behind a redirection), which the caller reports as an I/O error.
pub fn out(text: &str) -> std::io::Result<()> {
    quiet(std::io::stdout().lock(), text)
}

/// Writes `text` to standard error; every failure is ignored (there is nowhere left to report it).
pub fn err(text: &str) {
    let _ = quiet(std::io::stderr().lock(), text);
}

fn quiet(mut w: impl Write, text: &str) -> std::io::Result<()> {
    match w.write_all(text.as_bytes()).and_then(|()| w.flush()) {
        Err(e) if e.kind() == ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Closed;
    impl Write for Closed {
        fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
            Err(ErrorKind::BrokenPipe.into())
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }
    struct Full;
    impl Write for Full {
        fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
            Err(std::io::Error::other("disk full"))
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn a_closed_pipe_is_not_an_error_and_a_full_disk_is() {
        assert!(quiet(Closed, "x").is_ok());
        assert!(quiet(Full, "x").is_err());
        let mut v = Vec::new();
        quiet(&mut v, "abc").unwrap();
        assert_eq!(v, b"abc");
    }
}
