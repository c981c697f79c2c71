//! `ladderc explain` and the usage exit code, through the real binary.

use std::process::Command;

fn ladderc() -> Command {
    Command::new(env!("CARGO_BIN_EXE_ladderc"))
}

#[test]
fn explain_prints_the_explanation_file() {
    let out = ladderc().args(["explain", "e9001"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.starts_with("# E9001: cannot read an input file"),
        "{text}"
    );
}

#[test]
fn explain_without_code_lists_every_code() {
    let out = ladderc().arg("explain").output().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text.lines().count(), diagnostics::all_codes().len());
    assert!(text.lines().any(|l| l.starts_with("E9002  ")));
}

#[test]
fn unknown_code_and_bad_usage_exit_2() {
    assert_eq!(
        ladderc()
            .args(["explain", "E0000x"])
            .status()
            .unwrap()
            .code(),
        Some(2)
    );
    assert_eq!(
        ladderc().arg("no-such-command").status().unwrap().code(),
        Some(2)
    );
}
