//! Per-call cost of the two parameter-passing methods (paper A): a program calling `MC_MoveAbsolute`
//! through K instances per scan is built with `--strategy il` and `--strategy template`, compiled with
//! `-O2` by its Makefile and run for many cycles; the cost of one call is the time difference between K =
//! 41 and K = 1 divided by 40 calls and the cycles (both runs step the same engine, so the engine's own
//! cost cancels). Run: `cargo bench -p ladderc --bench param_passing` (with `cargo test --benches` it
//! runs a few cycles only, as a smoke test).
#![forbid(unsafe_code)]

use std::path::Path;
use std::process::Command;
use std::time::Instant;

fn program(k: usize) -> String {
    let mut s = String::from("PROGRAM bench\nVAR\n");
    for i in 0..k {
        s.push_str(&format!("    mv{i} : MC_MoveAbsolute;\n"));
    }
    s.push_str("    go : BOOL;\nEND_VAR\n");
    for i in 0..k {
        s.push_str(&format!(
            "    CAL mv{i}(Axis := X1, Execute := go, Position := 1.0, Velocity := 1.0, Acceleration := 1.0, Deceleration := 1.0)\n"
        ));
    }
    s.push_str("END_PROGRAM\n");
    s
}

/// Seconds to run `cycles` scans of the program with `k` calls built by `strategy`.
fn seconds(dir: &Path, strategy: &str, k: usize, cycles: u64) -> f64 {
    let work = dir.join(format!("{strategy}-{k}"));
    std::fs::create_dir_all(&work).unwrap();
    let src = work.join("bench.il");
    std::fs::write(&src, program(k)).unwrap();
    std::fs::write(
        work.join("bench.axes.json"),
        r#"{ "cycle_ms": 1, "axes": [ { "name": "X1", "velocity": 10, "acceleration": 10, "deceleration": 10 } ] }"#,
    )
    .unwrap();
    let out_dir = work.join("out");
    let st = Command::new(env!("CARGO_BIN_EXE_ladderc"))
        .args(["build", "--strategy", strategy, "-o"])
        .arg(&out_dir)
        .arg(&src)
        .status()
        .unwrap();
    assert!(st.success());
    let st = Command::new("make")
        .arg("-s")
        .arg("CFLAGS=-O2")
        .current_dir(&out_dir)
        .status()
        .unwrap();
    assert!(st.success());
    let trace = work.join("trace.csv");
    let t = Instant::now();
    let st = Command::new(out_dir.join("program"))
        .args([
            "--cycles",
            &cycles.to_string(),
            "--watch",
            "bench.go",
            "--trace",
        ])
        .arg(&trace)
        .status()
        .unwrap();
    let elapsed = t.elapsed().as_secs_f64();
    assert!(st.success());
    elapsed
}

fn main() {
    let full = std::env::args().any(|a| a == "--bench");
    let cycles: u64 = if full { 200_000 } else { 100 };
    let dir = tempfile::tempdir().unwrap();
    println!("method    ns/call  (K=41 vs K=1, {cycles} cycles, best of 3)");
    for strategy in ["il", "template"] {
        let best = |k| {
            (0..if full { 3 } else { 1 })
                .map(|_| seconds(dir.path(), strategy, k, cycles))
                .fold(f64::INFINITY, f64::min)
        };
        let (one, many) = (best(1), best(41));
        let ns = (many - one) / (40.0 * cycles as f64) * 1e9;
        println!("{strategy:<9} {ns:8.1}");
    }
}
