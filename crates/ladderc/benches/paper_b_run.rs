//! Paper B's run, the README's main command (`examples/paper-b/paper_b.il`, three MC_MoveLinearAbsolute
//! blocks on a 3-axis group, 220,000 cycles at the axes file's cycle time), with the FULL trace (no
//! `--watch`: every variable and every axis column) beside the anchor, the same run with one traced column.
//!
//! Measured in one run, interleaved, median of the repetitions:
//! - `ladderc run`'s own figure: the run phase (the program runs while ladderc turns its raw trace into the
//!   CSV), simulated time / wall time as the run summary prints it;
//! - the whole command (front end, C compile, run, trace written, junction summary), wall time;
//! - the main command itself with the full trace (`--plot`, `--pmac` too);
//! - the built program on its own (`ladderc build`, `make`, `./program --trace`: the C harness formats the
//!   floats itself, no ryu);
//! - the run phase as `ladderc run` does it (`./program --trace-raw` into ladderc's converter on a thread),
//!   in wall time and in CPU time (the program's and this process's, from /proc/self/stat): on a shared,
//!   loaded machine the CPU figure is the one that does not depend on the other jobs.
//!
//! Run: `cargo bench -p ladderc --bench paper_b_run` (3 repetitions; `cargo test --benches` runs 200
//! cycles once as a smoke test). The figures are in crates/ladderc/BENCHMARKS.md and the README.
#![forbid(unsafe_code)]

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-b")
}

/// The cycle time of the axes file, in seconds.
fn cycle_s() -> f64 {
    let text = std::fs::read_to_string(example().join("paper_b.axes.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["cycle_ms"].as_f64().unwrap() / 1000.0
}

/// Runs `cmd`; returns the wall time and standard error.
fn timed(cmd: &mut Command) -> (f64, String) {
    let t = Instant::now();
    let out = cmd.output().unwrap();
    let s = t.elapsed().as_secs_f64();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{err}");
    (s, err)
}

/// The run phase's wall time from the summary line `ran N cycles: S s simulated in W s (...)`.
fn run_phase(stderr: &str) -> f64 {
    let line = stderr
        .lines()
        .find(|l| l.starts_with("ran "))
        .unwrap_or_else(|| panic!("no summary line in {stderr}"));
    let w = line.split(" simulated in ").nth(1).unwrap();
    w.split(' ').next().unwrap().parse().unwrap()
}

/// CPU seconds used so far by this process (user + system) and by its waited-for children.
fn cpu_seconds() -> (f64, f64) {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    let after = stat.rsplit(')').next().unwrap_or("");
    let f: Vec<f64> = after
        .split_whitespace()
        .map(|x| x.parse().unwrap_or(0.0))
        .collect();
    let tick = Command::new("getconf")
        .arg("CLK_TCK")
        .output()
        .ok()
        .and_then(|o| String::from_utf8_lossy(&o.stdout).trim().parse().ok())
        .unwrap_or(100.0);
    // fields 14-17 of stat(5) are utime, stime, cutime, cstime; `after` starts at field 3
    let at = |k: usize| f.get(k - 3).copied().unwrap_or(0.0) / tick;
    (at(14) + at(15), at(16) + at(17))
}

/// The run phase as `ladderc run` does it: the program's raw trace through the converter into a file.
/// Returns (wall, CPU) seconds.
fn raw_run_phase(mut program: Command, trace: &Path) -> (f64, f64) {
    let (own0, kids0) = cpu_seconds();
    let t = Instant::now();
    let mut child = program
        .args(["--trace", "-", "--trace-raw"])
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let pipe = child.stdout.take().unwrap();
    let file = std::fs::File::create(trace).unwrap();
    let conv = std::thread::spawn(move || {
        let mut w = std::io::BufWriter::with_capacity(1 << 16, file);
        ladderc::trace_raw::convert(pipe, &mut w).unwrap()
    });
    assert!(child.wait().unwrap().success());
    conv.join().unwrap();
    let wall = t.elapsed().as_secs_f64();
    let (own1, kids1) = cpu_seconds();
    (wall, (own1 - own0) + (kids1 - kids0))
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let full = std::env::args().any(|a| a == "--bench");
    let cycles: u64 = if full { 220_000 } else { 200 };
    let reps = if full { 3 } else { 1 };
    let sim = cycles as f64 * cycle_s();
    let dir = tempfile::tempdir().unwrap();
    let src = example().join("paper_b.il");
    let trace = dir.path().join("trace.csv");
    let one = "paper_b.move_c.Done";
    let ladderc = |watch: Option<&str>, main: bool| {
        let mut c = Command::new(env!("CARGO_BIN_EXE_ladderc"));
        c.arg("run")
            .arg(&src)
            .args(["--cycles", &cycles.to_string()]);
        if let Some(w) = watch {
            c.args(["--watch", w]);
        }
        c.arg("--trace").arg(&trace);
        if main {
            c.arg("--plot")
                .arg(dir.path().join("p.svg"))
                .arg("--pmac")
                .arg(dir.path().join("p.pmc"));
        }
        c
    };
    // the built program on its own
    let out_dir = dir.path().join("out");
    timed(
        Command::new(env!("CARGO_BIN_EXE_ladderc"))
            .arg("build")
            .arg(&src)
            .arg("-o")
            .arg(&out_dir),
    );
    timed(Command::new("make").arg("-s").current_dir(&out_dir));
    let program_raw = |watch: Option<&str>| {
        let mut c = Command::new(out_dir.join("program"));
        c.args(["--cycles", &cycles.to_string(), "--cycle-ms"])
            .arg((cycle_s() * 1000.0).to_string());
        if let Some(w) = watch {
            c.args(["--watch", w]);
        }
        c
    };
    let program = |watch: Option<&str>| {
        let mut c = program_raw(watch);
        c.arg("--trace").arg(&trace);
        c
    };

    let mut columns = 0;
    let (mut phase_full, mut phase_one, mut cmd_full, mut cmd_one, mut main_full) =
        (vec![], vec![], vec![], vec![], vec![]);
    let (mut prog_full, mut prog_one) = (vec![], vec![]);
    let (mut raw_full, mut raw_one, mut cpu_full, mut cpu_one) = (vec![], vec![], vec![], vec![]);
    for _ in 0..reps {
        let (w, e) = timed(&mut ladderc(None, false));
        cmd_full.push(w);
        phase_full.push(run_phase(&e));
        let text = std::fs::read_to_string(&trace).unwrap();
        columns = text.lines().next().unwrap().split(',').count() - 2;
        assert_eq!(text.lines().count() as u64, cycles + 1);
        drop(text);
        let (w, e) = timed(&mut ladderc(Some(one), false));
        cmd_one.push(w);
        phase_one.push(run_phase(&e));
        main_full.push(timed(&mut ladderc(None, true)).0);
        prog_full.push(timed(&mut program(None)).0);
        prog_one.push(timed(&mut program(Some(one))).0);
        let (w, c) = raw_run_phase(program_raw(None), &trace);
        raw_full.push(w);
        cpu_full.push(c);
        let (w, c) = raw_run_phase(program_raw(Some(one)), &trace);
        raw_one.push(w);
        cpu_one.push(c);
    }
    let row = |what: &str, wall: f64| {
        println!("{what:<62} {wall:8.3} s  {:7.0}x real time", sim / wall);
    };
    println!(
        "paper B, {cycles} cycles of {} ms = {sim} s simulated; full trace = {columns} columns; \
         median of {reps}, interleaved, wall time",
        cycle_s() * 1000.0
    );
    row("ladderc run, run phase, full trace", median(phase_full));
    row(
        "ladderc run, run phase, one traced column (anchor)",
        median(phase_one),
    );
    row("ladderc run, whole command, full trace", median(cmd_full));
    row(
        "ladderc run, whole command, one traced column (anchor)",
        median(cmd_one),
    );
    row(
        "the main command with the full trace (+ --plot --pmac)",
        median(main_full),
    );
    row(
        "built program alone, C harness formats, full trace",
        median(prog_full),
    );
    row("built program alone, one traced column", median(prog_one));
    row(
        "run phase (program --trace-raw + converter), full trace",
        median(raw_full),
    );
    row(
        "run phase (program --trace-raw + converter), one column",
        median(raw_one),
    );
    row("  the same in CPU time, full trace", median(cpu_full));
    row(
        "  the same in CPU time, one traced column (anchor)",
        median(cpu_one),
    );
}
