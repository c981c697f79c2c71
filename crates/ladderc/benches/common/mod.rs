//! The measurement harness shared by the compile-speed benches (`il_to_c`, `ladder_to_c`).
//!
//! Input: a bench's named jobs. Output: one fresh child process per job (this bench binary re-executed
//! with [`CHILD_ENV`] set to the job's name), whose `key=value` lines on stdout the parent collects.
//! Invariants: each job runs alone in its own process, so its peak resident memory (`VmHWM` from
//! `/proc/self/status`) is that job's and not the parent's or another job's; wall times come from
//! `Instant`, CPU times from `/proc/thread-self/schedstat` (nanoseconds on CPU, the compiler is
//! single-threaded), which stays meaningful when other processes load the machine.

#![allow(dead_code)] // each bench uses a different part of the harness

use std::collections::BTreeMap;
use std::process::Command;
use std::time::Instant;

/// The environment variable that turns the bench binary into a measuring child.
pub const CHILD_ENV: &str = "LADDERC_BENCH_CHILD";

/// The job this process must run, when it is a measuring child.
pub fn child_job() -> Option<String> {
    std::env::var(CHILD_ENV).ok()
}

/// The number of timed runs: `default`, or `LADDERC_BENCH_RUNS` when set (e.g. 1 under a profiler).
pub fn runs(default: usize) -> usize {
    std::env::var("LADDERC_BENCH_RUNS")
        .ok()
        .and_then(|v| v.parse().ok())
        .filter(|&n| n > 0)
        .unwrap_or(default)
}

/// Runs `job` in a child process and returns its `key=value` report.
pub fn run_child(job: &str) -> BTreeMap<String, String> {
    let exe = std::env::current_exe().expect("the bench binary's own path");
    let out = Command::new(exe)
        .env(CHILD_ENV, job)
        .output()
        .expect("re-executing the bench binary");
    let stdout = String::from_utf8_lossy(&out.stdout);
    if !out.status.success() {
        panic!(
            "bench job {job} failed ({}):\n{stdout}\n{}",
            out.status,
            String::from_utf8_lossy(&out.stderr)
        );
    }
    stdout
        .lines()
        .filter_map(|l| l.split_once('='))
        .map(|(k, v)| (k.trim().to_string(), v.trim().to_string()))
        .collect()
}

/// A number from a child's report (panics with the report when missing: a bench bug).
pub fn num(report: &BTreeMap<String, String>, key: &str) -> f64 {
    report
        .get(key)
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no number {key} in {report:?}"))
}

/// A field of `/proc/self/status` in KiB (`VmHWM` = peak resident set, `VmRSS` = current).
pub fn status_kib(field: &str) -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix(field)?.strip_prefix(':'))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        .unwrap_or(0)
}

/// Seconds this thread has spent on a CPU so far.
pub fn cpu_seconds() -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<u64>().ok())
        .map_or(0.0, |ns| ns as f64 * 1e-9)
}

/// A stopwatch over wall and CPU time.
pub struct Stopwatch {
    wall: Instant,
    cpu: f64,
}

impl Stopwatch {
    pub fn start() -> Self {
        Stopwatch {
            wall: Instant::now(),
            cpu: cpu_seconds(),
        }
    }
    /// `(wall seconds, CPU seconds)` since start.
    pub fn lap(&self) -> (f64, f64) {
        (self.wall.elapsed().as_secs_f64(), cpu_seconds() - self.cpu)
    }
}

/// The median of a non-empty list.
pub fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    let n = xs.len();
    if n % 2 == 1 {
        xs[n / 2]
    } else {
        (xs[n / 2 - 1] + xs[n / 2]) / 2.0
    }
}

/// Prints one `key=value` line of a child's report.
pub fn report(key: &str, value: impl std::fmt::Display) {
    println!("{key}={value}");
}

/// Machine facts for the table header: CPUs and the 1-minute load average (other processes share
/// the machine, which inflates wall times but not CPU times).
pub fn machine_line() -> String {
    let cpus = std::thread::available_parallelism().map_or(0, |n| n.get());
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    let load = load
        .split_whitespace()
        .take(3)
        .collect::<Vec<_>>()
        .join(" ");
    format!("machine: {cpus} CPUs available, load average {load}")
}
