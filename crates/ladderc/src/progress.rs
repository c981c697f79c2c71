//! Runs the built program for `run`: timed, with a progress bar on a terminal.
//!
//! Input: the executable, the harness options and a scratch directory. Output: the program's exit status,
//! standard output and standard error (as [`c_backend::run`] gives them) and the wall time of the run.
//! The trace: the harness writes it raw (`--trace-raw`) on its standard output, and a thread turns it into
//! the CSV ([`crate::trace_raw`], floats by ryu) while the program runs, into `opts.trace` or, without
//! one, into the returned standard output (the generated program writes nothing else there). The wall
//! time ends when the program has exited and its trace is written.
//! When standard error is a terminal, the harness is asked to report the cycles done into a file of the
//! scratch directory (`--progress FILE`, rewritten about ten times a second), and once the run has taken
//! longer than a second (`LADDERC_PROGRESS_AFTER_MS` overrides the delay) an `indicatif` bar shows it;
//! the bar is cleared when the program ends. Invariant: without a terminal nothing is drawn and the
//! harness gets no extra option.

use c_backend::{BuildError, RunOptions, RunOutput};
use std::io::{IsTerminal, Read};
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The program's output and how long it ran.
pub struct Timed {
    /// The exit status, standard output and standard error.
    pub output: RunOutput,
    /// The wall time of the run.
    pub wall: Duration,
}

/// Runs `exe` with `opts`; see the module header.
pub fn run(exe: &Path, opts: &RunOptions, scratch: &Path) -> Result<Timed, BuildError> {
    let harness = RunOptions {
        trace: None,
        ..opts.clone()
    };
    let mut args = c_backend::toolchain::run_args(&harness);
    args.push("--trace-raw".into());
    let bar = std::io::stderr().is_terminal();
    let progress_file = scratch.join("progress");
    if bar {
        args.push("--progress".into());
        args.push(progress_file.display().to_string());
    }
    let fail = |e: std::io::Error| BuildError::Run {
        path: exe.display().to_string(),
        message: e.to_string(),
    };
    let start = Instant::now();
    let mut child = Command::new(exe)
        .args(&args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(fail)?;
    let out_reader = csv_trace(child.stdout.take(), opts.trace.clone());
    let err_reader = drain(child.stderr.take());
    let delay = Duration::from_millis(
        std::env::var("LADDERC_PROGRESS_AFTER_MS")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(1000),
    );
    let mut shown: Option<indicatif::ProgressBar> = None;
    let status = if !bar {
        child.wait().map_err(fail)?
    } else {
        loop {
            if let Some(status) = child.try_wait().map_err(fail)? {
                break status;
            }
            std::thread::sleep(Duration::from_millis(20));
            if start.elapsed() >= delay {
                let done = read_progress(&progress_file).map(|d| d.min(opts.cycles));
                let pb = shown.get_or_insert_with(|| {
                    new_bar(opts.cycles, done.unwrap_or(0), start.elapsed())
                });
                if let Some(done) = done {
                    pb.set_position(done);
                }
            }
        }
    };
    let stdout = out_reader
        .join()
        .unwrap_or_else(|_| Err(std::io::Error::other("the trace thread panicked")))
        .map_err(|e| BuildError::Run {
            path: exe.display().to_string(),
            message: format!("cannot write the trace: {e}"),
        });
    let wall = start.elapsed();
    if let Some(pb) = shown {
        pb.finish_and_clear();
    }
    let stderr = err_reader.join().unwrap_or_default();
    let stdout = stdout?;
    Ok(Timed {
        output: RunOutput {
            status: status.code(),
            stdout: String::from_utf8_lossy(&stdout).into_owned(),
            stderr: String::from_utf8_lossy(&stderr).into_owned(),
        },
        wall,
    })
}

/// A bar of `cycles`, starting at `done` after `elapsed` (the time estimate counts from there).
fn new_bar(cycles: u64, done: u64, elapsed: Duration) -> indicatif::ProgressBar {
    let pb = indicatif::ProgressBar::new(cycles)
        .with_position(done)
        .with_elapsed(elapsed);
    pb.reset_eta();
    let style = indicatif::ProgressStyle::with_template(
        "{elapsed_precise} [{wide_bar}] {pos}/{len} cycles, {eta} left",
    )
    .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
    .progress_chars("=> ");
    pb.set_style(style);
    pb
}

/// The cycles done, as the harness last wrote them (`None` while the file is empty or being rewritten).
fn read_progress(path: &Path) -> Option<u64> {
    std::fs::read_to_string(path).ok()?.trim().parse().ok()
}

/// Turns the raw trace on `pipe` into CSV on a thread: into the file `dest`, or returned when `dest` is
/// `None`. The pipe is read to its end even after a write error, so the program never blocks on it.
fn csv_trace<R: Read + Send + 'static>(
    pipe: Option<R>,
    dest: Option<std::path::PathBuf>,
) -> std::thread::JoinHandle<std::io::Result<Vec<u8>>> {
    std::thread::spawn(move || {
        let Some(mut pipe) = pipe else {
            return Ok(Vec::new());
        };
        let result = match dest {
            Some(path) => std::fs::File::create(&path).and_then(|f| {
                let mut w = std::io::BufWriter::with_capacity(1 << 16, f);
                crate::trace_raw::convert(&mut pipe, &mut w).map(|_| Vec::new())
            }),
            None => {
                let mut v = Vec::new();
                crate::trace_raw::convert(&mut pipe, &mut v).map(|_| v)
            }
        };
        if result.is_err() {
            let _ = std::io::copy(&mut pipe, &mut std::io::sink());
        }
        result
    })
}

/// Reads a pipe to its end on a thread (so that a full pipe never blocks the program).
fn drain<R: Read + Send + 'static>(pipe: Option<R>) -> std::thread::JoinHandle<Vec<u8>> {
    std::thread::spawn(move || {
        let mut buf = Vec::new();
        if let Some(mut p) = pipe {
            let _ = p.read_to_end(&mut buf);
        }
        buf
    })
}
