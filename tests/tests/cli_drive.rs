//! `ladderc drive build/run/debug` wired to the drive-script crate, through the real binary.

mod common;
use common::ladderc;

use std::io::Write;
use std::process::Stdio;

const SCRIPT: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../crates/drive-script/tests/scripts/three_motions.ds"
);

#[test]
fn build_then_run_the_image_writes_a_trace() {
    let dir = tempfile::tempdir().unwrap();
    let image = dir.path().join("three.img");
    let out = ladderc()
        .args(["drive", "build", SCRIPT, "-o"])
        .arg(&image)
        .output()
        .unwrap();
    common::assert_ok(&out);
    assert!(String::from_utf8_lossy(&out.stdout).contains("3 Motions, 13 Events"));
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .args(["drive", "run"])
        .arg(&image)
        .args(["--cycles", "7", "--trace"])
        .arg(&trace)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = std::fs::read_to_string(&trace).unwrap();
    assert!(text.starts_with("cycle,time_ms,motion,event,phase,"));
    assert_eq!(text.lines().count(), 1 + 7);
}

#[test]
fn debugger_reads_commands_from_stdin() {
    let mut child = ladderc()
        .args(["drive", "debug", SCRIPT])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(b"break 0 1 if\nrun\nprint MD0\nquit\n")
        .unwrap();
    let out = child.wait_with_output().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("stopped at Motion 0 Event 1 before IF"),
        "{text}"
    );
    assert!(text.contains("MD0 = 1"), "{text}");
}

#[test]
fn a_bad_script_exits_1_with_a_json_diagnostic() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.ds");
    std::fs::write(
        &bad,
        "S:: MOTION 0;\nS:: EVENT 0;\nS:: IF MD0 = 1 OR MD1 = 2;\nS:: THEN MD2 = 3;\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "json", "drive", "build"])
        .arg(&bad)
        .arg("-o")
        .arg(dir.path().join("x.img"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let line = String::from_utf8(out.stderr).unwrap();
    let v: serde_json::Value = serde_json::from_str(line.lines().next().unwrap()).unwrap();
    assert_eq!(v["line"], 3);
    assert!(v["code"].as_str().unwrap().starts_with("E6"));
    assert!(!dir.path().join("x.img").exists());
}

#[test]
fn the_drive_option_selects_the_motion_lib_axis_or_the_simple_simulation() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("paper.ds");
    std::fs::write(
        &script,
        "S:: MOTION 0;\nS:: EVENT 0;\nS:: IF MD0 = 0;\nS:: THEN DO_0=HIGH AND RelativeTargetPosition=10000 AND MD0 = 1;\n",
    )
    .unwrap();
    let mut second_rows = Vec::new();
    for drive in ["motion-lib", "sim"] {
        let trace = dir.path().join(format!("{drive}.csv"));
        let out = ladderc()
            .args(["drive", "run"])
            .arg(&script)
            .args(["--cycles", "3", "--drive", drive, "--trace"])
            .arg(&trace)
            .output()
            .unwrap();
        common::assert_ok(&out);
        let text = std::fs::read_to_string(&trace).unwrap();
        second_rows.push(text.lines().nth(2).unwrap().to_string());
    }
    // A jerk-limited axis starts slower than the trapezoidal simulation: the traces differ.
    assert_ne!(second_rows[0], second_rows[1]);
}
