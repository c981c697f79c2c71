//! Transports that carry text lines to a PMAC: a file, and TCP to a Power PMAC `gpascii`-style line protocol.
//!
//! Input: lines without line ends; a lines-remaining query.
//! Output: the lines written (file) or sent (socket, `\n`-terminated); the controller's lines-remaining count.
//! Invariants: every wait is bounded (socket read timeout; the streamer bounds the number of polls). The TCP
//! protocol (documented in the crate README): on connect the controller sends a banner containing
//! "STDIN Open for ASCII Input"; the host sends lines; the query `PR` is answered by the number of unexecuted
//! lines in the rotary buffer; any reply line containing "error" (any case) is an error report (E7004);
//! other reply lines (echoes, blank lines, control characters such as ACK) are ignored.

use crate::error::PmacError;
use std::io::{BufRead, BufReader, Write};
use std::net::{TcpStream, ToSocketAddrs};
use std::time::Duration;

/// Where buffer lines go.
pub trait Transport {
    /// Sends one line (no line end).
    fn send(&mut self, line: &str) -> Result<(), PmacError>;
    /// Rotary buffer capacity in lines; `None` for a sink that never fills (a file).
    fn capacity(&self) -> Option<usize>;
    /// Unexecuted lines in the buffer (`PR`); also reports any error reply that arrived since the last query.
    fn lines_remaining(&mut self) -> Result<usize, PmacError>;
    /// Pause before polling a full buffer again.
    fn wait(&mut self);
    /// Pushes out anything buffered.
    fn flush(&mut self) -> Result<(), PmacError>;
}

/// Writes the lines to any writer (a `.pmc` file), one per line. Never full.
pub struct FileTransport<W: Write> {
    out: W,
}

impl<W: Write> FileTransport<W> {
    pub fn new(out: W) -> Self {
        FileTransport { out }
    }
    pub fn into_inner(self) -> W {
        self.out
    }
}

impl FileTransport<std::io::BufWriter<std::fs::File>> {
    /// Creates (truncates) the file at `path`.
    pub fn create(path: &std::path::Path) -> Result<Self, PmacError> {
        let f = std::fs::File::create(path)
            .map_err(|e| PmacError::transport(format!("cannot create {}: {e}", path.display())))?;
        Ok(FileTransport::new(std::io::BufWriter::new(f)))
    }
}

impl<W: Write> Transport for FileTransport<W> {
    fn send(&mut self, line: &str) -> Result<(), PmacError> {
        writeln!(self.out, "{line}").map_err(|e| PmacError::transport(format!("write failed: {e}")))
    }
    fn capacity(&self) -> Option<usize> {
        None
    }
    fn lines_remaining(&mut self) -> Result<usize, PmacError> {
        Ok(0)
    }
    fn wait(&mut self) {}
    fn flush(&mut self) -> Result<(), PmacError> {
        self.out
            .flush()
            .map_err(|e| PmacError::transport(format!("write failed: {e}")))
    }
}

/// Settings of the TCP line protocol.
#[derive(Debug, Clone, PartialEq)]
pub struct GpasciiOptions {
    /// Rotary buffer capacity in lines (what the controller was told to hold, e.g. with I17/I16 on Turbo).
    pub capacity_lines: usize,
    /// Read timeout for the banner and each reply.
    pub timeout: Duration,
    /// Pause between polls of a full buffer.
    pub poll_interval: Duration,
    /// The lines-remaining query.
    pub query: String,
    /// Text the banner must contain; empty = do not wait for a banner.
    pub banner: String,
    /// Reply lines to skip while waiting for a count before giving up.
    pub max_reply_lines: usize,
}

impl Default for GpasciiOptions {
    fn default() -> Self {
        GpasciiOptions {
            capacity_lines: 256,
            timeout: Duration::from_secs(5),
            poll_interval: Duration::from_millis(20),
            query: "PR".to_string(),
            banner: "STDIN Open for ASCII Input".to_string(),
            max_reply_lines: 100,
        }
    }
}

/// A TCP connection to a controller speaking the gpascii-style line protocol.
pub struct GpasciiTcp {
    reader: BufReader<TcpStream>,
    writer: std::io::BufWriter<TcpStream>,
    opts: GpasciiOptions,
}

fn io_err(what: &str, e: std::io::Error) -> PmacError {
    use std::io::ErrorKind::{TimedOut, WouldBlock};
    if matches!(e.kind(), TimedOut | WouldBlock) {
        PmacError::transport(format!("{what}: no reply within the timeout"))
    } else {
        PmacError::transport(format!("{what}: {e}"))
    }
}

impl GpasciiTcp {
    /// Connects and waits for the banner.
    pub fn connect(addr: impl ToSocketAddrs, opts: GpasciiOptions) -> Result<Self, PmacError> {
        let addrs: Vec<_> = addr
            .to_socket_addrs()
            .map_err(|e| io_err("resolve address", e))?
            .collect();
        let first = addrs
            .first()
            .ok_or_else(|| PmacError::transport("no address to connect to"))?;
        let stream = TcpStream::connect_timeout(first, opts.timeout)
            .map_err(|e| io_err(&format!("connect {first}"), e))?;
        stream
            .set_read_timeout(Some(opts.timeout))
            .and_then(|()| stream.set_write_timeout(Some(opts.timeout)))
            .and_then(|()| stream.set_nodelay(true))
            .map_err(|e| io_err("configure socket", e))?;
        let reader = BufReader::new(
            stream
                .try_clone()
                .map_err(|e| io_err("configure socket", e))?,
        );
        let mut me = GpasciiTcp {
            reader,
            writer: std::io::BufWriter::new(stream),
            opts,
        };
        if !me.opts.banner.is_empty() {
            me.wait_for_banner()?;
        }
        Ok(me)
    }

    fn read_reply_line(&mut self, what: &str) -> Result<String, PmacError> {
        let mut line = String::new();
        let n = self
            .reader
            .read_line(&mut line)
            .map_err(|e| io_err(what, e))?;
        if n == 0 {
            return Err(PmacError::transport(format!(
                "{what}: the controller closed the connection"
            )));
        }
        Ok(line
            .chars()
            .filter(|c| !c.is_control())
            .collect::<String>()
            .trim()
            .to_string())
    }

    fn wait_for_banner(&mut self) -> Result<(), PmacError> {
        for _ in 0..self.opts.max_reply_lines {
            let line = self.read_reply_line("waiting for the banner")?;
            if line.contains(&self.opts.banner) {
                return Ok(());
            }
        }
        Err(PmacError::transport(format!(
            "no banner \"{}\" from the controller",
            self.opts.banner
        )))
    }
}

impl Transport for GpasciiTcp {
    fn send(&mut self, line: &str) -> Result<(), PmacError> {
        writeln!(self.writer, "{line}").map_err(|e| io_err("send", e))
    }
    fn capacity(&self) -> Option<usize> {
        Some(self.opts.capacity_lines)
    }
    fn lines_remaining(&mut self) -> Result<usize, PmacError> {
        let query = self.opts.query.clone();
        self.send(&query)?;
        self.flush()?;
        for _ in 0..self.opts.max_reply_lines {
            let line = self.read_reply_line("lines-remaining query")?;
            if line.to_ascii_lowercase().contains("error") {
                return Err(PmacError::controller(&line));
            }
            if let Ok(n) = line.parse::<usize>() {
                return Ok(n);
            }
            // echo of a sent line, prompt or blank line: skip
        }
        Err(PmacError::transport(format!(
            "no number in reply to `{query}`"
        )))
    }
    fn wait(&mut self) {
        std::thread::sleep(self.opts.poll_interval);
    }
    fn flush(&mut self) -> Result<(), PmacError> {
        self.writer.flush().map_err(|e| io_err("send", e))
    }
}
