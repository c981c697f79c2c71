//! Paper B's whole experiment at a 1 ms cycle through the compiled program: `examples/paper-b/paper_b.il`
//! (three MC_MoveLinearAbsolute blocks on a 3-axis group) for 195,000 scan cycles = 195 s of simulated
//! time, with every axis's set position, velocity and acceleration and the blocks' outputs traced to a file.
//!
//! Measured (wall time, best of 3): (1) `ladderc run` as a user runs it (front end + C compile + run);
//! (2) the run phase alone: the project is built once with `ladderc build` and its Makefile (`-O2`), then
//! `./program --cycles 195000` is timed, with the full trace and with a one-column trace. The ratio
//! simulated / wall time of the run phase is the figure in crates/ladderc/BENCHMARKS.md.
//! Run: `cargo bench -p ladderc --bench paper_b_run` (`cargo test --benches` runs 100 cycles as a smoke test).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

const BLOCKS: [&str; 3] = ["move_a", "move_b", "move_c"];
const OUTPUTS: [&str; 4] = ["Done", "Busy", "Active", "CommandAborted"];
const AXES: [&str; 3] = ["AxisX", "AxisY", "AxisZ"];

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-b")
}

fn full_watch() -> String {
    let mut w: Vec<String> = Vec::new();
    for b in BLOCKS {
        for o in OUTPUTS {
            w.push(format!("paper_b.{b}.{o}"));
        }
    }
    for a in AXES {
        for s in ["position", "velocity", "acceleration"] {
            w.push(format!("axis.{a}.{s}"));
        }
    }
    w.join(",")
}

fn timed(cmd: &mut Command) -> f64 {
    let t = Instant::now();
    let out = cmd.output().unwrap();
    let s = t.elapsed().as_secs_f64();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    s
}

fn main() {
    let full = std::env::args().any(|a| a == "--bench");
    let cycles: u64 = if full { 195_000 } else { 100 };
    let runs = if full { 3 } else { 1 };
    let dir = tempfile::tempdir().unwrap();
    let src = example().join("paper_b.il");
    let axes = example().join("paper_b.axes.json");
    let trace = dir.path().join("trace.csv");
    let watch = full_watch();
    let best = |f: &dyn Fn() -> f64| (0..runs).map(|_| f()).fold(f64::INFINITY, f64::min);

    // (1) ladderc run, everything included
    let cli = best(&|| {
        timed(
            Command::new(env!("CARGO_BIN_EXE_ladderc"))
                .arg("run")
                .arg(&src)
                .arg("--axes")
                .arg(&axes)
                .args([
                    "--cycles",
                    &cycles.to_string(),
                    "--watch",
                    &watch,
                    "--trace",
                ])
                .arg(&trace),
        )
    });
    let rows = std::fs::read_to_string(&trace).unwrap().lines().count() - 1;
    assert_eq!(rows as u64, cycles);

    // (2) the run phase alone
    let out_dir = dir.path().join("out");
    timed(
        Command::new(env!("CARGO_BIN_EXE_ladderc"))
            .arg("build")
            .arg(&src)
            .arg("--axes")
            .arg(&axes)
            .arg("-o")
            .arg(&out_dir),
    );
    timed(
        Command::new("make")
            .arg("-s")
            .arg("CFLAGS=-O2")
            .current_dir(&out_dir),
    );
    let program = out_dir.join("program");
    let run = |w: &str| {
        best(&|| {
            timed(
                Command::new(&program)
                    .args([
                        "--cycles",
                        &cycles.to_string(),
                        "--cycle-ms",
                        "1",
                        "--watch",
                        w,
                        "--trace",
                    ])
                    .arg(&trace),
            )
        })
    };
    let traced = run(&watch);
    let one = run("paper_b.move_c.Done");
    let sim = cycles as f64 * 0.001;
    println!("paper B, {cycles} cycles of 1 ms = {sim} s simulated (best of {runs}, wall time)");
    println!("ladderc run (front end + C compile + run, full trace): {cli:8.3} s");
    println!(
        "run phase, full trace (21 columns):                     {traced:8.3} s  simulated/wall = {:8.0}",
        sim / traced
    );
    println!(
        "run phase, one-column trace:                            {one:8.3} s  simulated/wall = {:8.0}",
        sim / one
    );
}
