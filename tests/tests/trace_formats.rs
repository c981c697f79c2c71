//! The trace is the same text whoever formats it: `ladderc run` (the harness writes REAL/LREAL values as raw
//! bits and ladderc formats them with ryu) and the built program on its own (`./program --trace`, the C
//! harness's `%g` loop), byte for byte, on values that take every path of the formatter.

mod common;
use common::*;
use std::process::Command;

fn fixture() -> std::path::PathBuf {
    repo_root().join("tests/tests/fixtures/trace_floats.il")
}

/// The trace of `ladderc run` (into a file, or on standard output without `--trace`).
fn run_trace(dir: &std::path::Path, to_file: bool) -> String {
    let trace = dir.join("run.csv");
    let mut cmd = ladderc();
    cmd.arg("run")
        .arg(fixture())
        .args(["--cycles", "400", "--cycle-ms", "10"]);
    if to_file {
        cmd.arg("--trace").arg(&trace);
    }
    let out = cmd.output().unwrap();
    assert_ok(&out);
    if to_file {
        std::fs::read_to_string(&trace).unwrap()
    } else {
        String::from_utf8(out.stdout).unwrap()
    }
}

#[test]
fn ladderc_run_writes_the_trace_the_c_harness_writes() {
    let dir = tempfile::tempdir().unwrap();
    let out = ladderc()
        .arg("build")
        .arg(fixture())
        .arg("-o")
        .arg(dir.path().join("out"))
        .output()
        .unwrap();
    assert_ok(&out);
    let make = Command::new("make")
        .arg("-s")
        .current_dir(dir.path().join("out"))
        .output()
        .unwrap();
    assert!(
        make.status.success(),
        "{}",
        String::from_utf8_lossy(&make.stderr)
    );
    let c_trace = dir.path().join("c.csv");
    let harness = Command::new(dir.path().join("out/program"))
        .args(["--cycles", "400", "--cycle-ms", "10", "--trace"])
        .arg(&c_trace)
        .output()
        .unwrap();
    assert_ok(&harness);
    let c = std::fs::read_to_string(&c_trace).unwrap();
    // the fixture reaches every kind of text the formatter writes
    for needle in [
        ",inf,",
        "nan",
        "e+",
        "e-3",
        "e-4",
        "0.30000000000000004",
        "\"a,\"\"b\"\"\"",
    ] {
        assert!(c.contains(needle), "the C trace has no `{needle}`");
    }
    assert!(c.lines().any(|l| l.contains("e-32")), "no subnormal LREAL");
    assert_eq!(c.lines().count(), 401);
    let to_file = run_trace(dir.path(), true);
    assert!(
        to_file == c,
        "ladderc run --trace differs from the C harness"
    );
    let on_stdout = run_trace(dir.path(), false);
    assert!(
        on_stdout == c,
        "ladderc run (trace on stdout) differs from the C harness"
    );
}
