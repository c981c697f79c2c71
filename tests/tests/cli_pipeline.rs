//! `ladderc check/build/run` end to end: IL in, C built by the system compiler, scan cycles traced.

mod common;
use common::{ladderc, write_file};

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Runs a program and returns the trace text.
fn run(program: &str, stimulus: &str, extra: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let src = write_file(dir.path(), "prog.il", program);
    let stim = write_file(dir.path(), "stim.csv", stimulus);
    let trace = dir.path().join("trace.csv");
    let out = ladderc()
        .arg("run")
        .arg(&src)
        .arg("--stimulus")
        .arg(&stim)
        .arg("--trace")
        .arg(&trace)
        .args(extra)
        .output()
        .unwrap();
    common::assert_ok(&out);
    std::fs::read_to_string(&trace).unwrap()
}

#[test]
fn counter_example_counts_edges_and_the_off_delay_holds_100_ms() {
    let ex = root().join("examples/counter");
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .arg("run")
        .arg(ex.join("counter.il"))
        .args(["--cycles", "25", "--cycle-ms", "10", "--stimulus"])
        .arg(ex.join("stimulus.csv"))
        .arg("--trace")
        .arg(&trace)
        .args(["--watch", "main.count,main.full,%QX0.1", "--sanitize"])
        .output()
        .unwrap();
    common::assert_ok(&out);
    insta::assert_snapshot!(std::fs::read_to_string(&trace).unwrap());
}

#[test]
fn nested_deferred_operators_evaluate_as_written() {
    // (a AND (b OR c)) OR (NOT d AND e), checked on all 32 input combinations, one per cycle.
    let program = "PROGRAM main\nVAR a, b, c, d, e, q : BOOL; END_VAR\n    LD a\n    AND( b\n    OR c\n    )\n    OR( d\n    NOT\n    AND e\n    )\n    ST q\nEND_PROGRAM\n";
    let mut stim = String::from("cycle,variable,value\n");
    for n in 0..32u32 {
        for (i, v) in ["a", "b", "c", "d", "e"].iter().enumerate() {
            stim.push_str(&format!("{n},main.{v},{}\n", (n >> i) & 1));
        }
    }
    let trace = run(program, &stim, &["--cycles", "32", "--watch", "main.q"]);
    for (n, line) in trace.lines().skip(1).enumerate() {
        let bit = |i: u32| (n as u32 >> i) & 1 == 1;
        let (a, b, c, d, e) = (bit(0), bit(1), bit(2), bit(3), bit(4));
        let want = (a && (b || c)) || (!d && e);
        assert_eq!(
            line.rsplit(',').next().unwrap(),
            if want { "1" } else { "0" },
            "cycle {n}"
        );
    }
}

#[test]
fn int_overflow_wraps_and_real_stays_real() {
    let program = "PROGRAM main\nVAR i : INT := 32766; r : REAL := 0.5; END_VAR\n    LD i\n    ADD 1\n    ST i\n    LD r\n    MUL 3.0\n    ST r\nEND_PROGRAM\n";
    let trace = run(
        program,
        "cycle,variable,value\n",
        &["--cycles", "3", "--watch", "main.i,main.r"],
    );
    insta::assert_snapshot!(trace);
}

#[test]
fn ton_output_rises_exactly_when_pt_has_elapsed() {
    let program = "PROGRAM main\nVAR t : TON; go : BOOL; q : BOOL; END_VAR\n    CAL t(IN := go, PT := T#30ms)\n    LD t.Q\n    ST q\nEND_PROGRAM\n";
    let trace = run(
        program,
        "cycle,variable,value\n2,main.go,TRUE\n",
        &["--cycles", "8", "--cycle-ms", "10", "--watch", "main.q"],
    );
    insta::assert_snapshot!(trace);
}

#[test]
fn check_reports_errors_with_exit_1_and_json_positions() {
    let dir = tempfile::tempdir().unwrap();
    let src = write_file(
        dir.path(),
        "bad.il",
        "PROGRAM main\nVAR x : INT; END_VAR\n    LD x\n    JMPC nowhere\nEND_PROGRAM\n",
    );
    let out = ladderc()
        .args(["--message-format", "json", "check"])
        .arg(&src)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8(out.stderr).unwrap();
    let first: serde_json::Value = serde_json::from_str(text.lines().next().unwrap()).unwrap();
    assert_eq!(first["line"], 4);
    assert!(first["code"].as_str().unwrap().starts_with('E'), "{text}");
}

#[test]
fn a_failed_build_leaves_no_output_and_a_good_one_replaces_it_whole() {
    let dir = tempfile::tempdir().unwrap();
    let out_dir = dir.path().join("out");
    let bad = write_file(
        dir.path(),
        "bad.il",
        "PROGRAM main\n    LD undeclared\nEND_PROGRAM\n",
    );
    let st = ladderc()
        .arg("build")
        .arg(&bad)
        .arg("-o")
        .arg(&out_dir)
        .status()
        .unwrap();
    assert_eq!(st.code(), Some(1));
    assert!(!out_dir.exists());
    let good = write_file(
        dir.path(),
        "good.il",
        "PROGRAM main\nVAR x : INT; END_VAR\n    LD x\n    ADD 1\n    ST x\nEND_PROGRAM\n",
    );
    let st = ladderc()
        .arg("build")
        .arg(&good)
        .arg("-o")
        .arg(&out_dir)
        .status()
        .unwrap();
    assert_eq!(st.code(), Some(0));
    assert!(out_dir.join("Makefile").exists());
    // The Makefile builds the program with the system compiler.
    let make = Command::new("make").current_dir(&out_dir).output().unwrap();
    assert!(
        make.status.success(),
        "{}",
        String::from_utf8_lossy(&make.stderr)
    );
    let leftovers: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(leftovers.len(), 3, "{leftovers:?}");
}

#[test]
fn missing_input_is_an_io_diagnostic() {
    let out = ladderc()
        .args(["check", "/nonexistent/x.il", "--message-format", "short"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "an I/O error exits 2");
    assert!(String::from_utf8_lossy(&out.stderr).contains("error[E9001]"));
}

#[test]
fn motion_example_moves_to_100_then_backs_off_to_60_and_plots() {
    let ex = root().join("examples/motion");
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.csv");
    let svg = dir.path().join("move.svg");
    let out = ladderc()
        .arg("run")
        .arg(ex.join("move.il"))
        .args([
            "--cycles",
            "2200",
            "--watch",
            "axis.X1.position,main.at_100,main.back",
            "--trace",
        ])
        .arg(&trace)
        .arg("--plot")
        .arg(&svg)
        .output()
        .unwrap();
    common::assert_ok(&out);
    let text = std::fs::read_to_string(&trace).unwrap();
    // `--plot` adds the columns it draws (the velocity) after the watched ones.
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    assert_eq!(
        &header[..5],
        [
            "cycle",
            "time_ms",
            "axis.X1.position",
            "main.at_100",
            "main.back"
        ]
    );
    let last: Vec<&str> = text.lines().last().unwrap().split(',').collect();
    assert!(
        (last[2].parse::<f64>().unwrap() - 60.0).abs() < 1e-9,
        "{last:?}"
    );
    assert_eq!(&last[3..5], ["1", "1"]);
    // The first move reached 100 when its Done rose (the back-off, started in that scan, has moved the axis
    // by one engine cycle of its jerk-limited start since).
    let done_row = text
        .lines()
        .skip(1)
        .find(|l| l.split(',').nth(3) == Some("1"))
        .unwrap();
    assert!(
        (done_row.split(',').nth(2).unwrap().parse::<f64>().unwrap() - 100.0).abs() < 1e-4,
        "{done_row}"
    );
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
}

#[test]
fn an_array_input_of_a_function_is_passed_by_value() {
    // SUM3 reads its array input; the caller's array changes after the call and between cycles. The
    // function sees the caller's values at the call, and (being a copy) cannot alias the caller's array.
    let program = "FUNCTION SUM3 : INT
VAR_INPUT
    a : ARRAY[0..2] OF INT;
END_VAR
    LD a[0]
    ADD a[1]
    ADD a[2]
    ST SUM3
END_FUNCTION

PROGRAM main
VAR
    v : ARRAY[0..2] OF INT := [1, 2, 3];
    s : INT;
END_VAR
    SUM3(a := v)
    ST s
    LD v[1]
    ADD 10
    ST v[1]
END_PROGRAM
";
    let trace = run(
        program,
        "",
        &["--cycles", "3", "--watch", "main.s,main.v[1]", "--sanitize"],
    );
    assert_eq!(
        trace,
        "cycle,time_ms,main.s,main.v[1]\n0,0,6,12\n1,10,16,22\n2,20,26,32\n"
    );
}
