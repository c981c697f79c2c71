//! `ladderc explain` and the usage exit code, through the real binary.

mod common;
use common::ladderc;

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

#[test]
fn motion_plan_recomputes_oracle_durations() {
    let oracle = common::repo_root().join("crates/motion-lib/tests/data/ruckig-profiles.jsonl");
    let text =
        std::fs::read_to_string(&oracle).unwrap_or_else(|e| panic!("{}: {e}", oracle.display()));
    let dir = tempfile::tempdir().unwrap();
    let sample: String = text.lines().take(40).map(|l| format!("{l}\n")).collect();
    let input = dir.path().join("p.jsonl");
    std::fs::write(&input, &sample).unwrap();
    let out = ladderc()
        .args(["motion", "plan"])
        .arg(&input)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let planned = String::from_utf8(out.stdout).unwrap();
    for (want, got) in sample.lines().zip(planned.lines()) {
        let w: serde_json::Value = serde_json::from_str(want).unwrap();
        let g: serde_json::Value = serde_json::from_str(got).unwrap();
        let (w, g) = (
            w["duration"].as_f64().unwrap(),
            g["duration"].as_f64().unwrap(),
        );
        assert!((w - g).abs() <= 1e-6 * w, "{w} vs {g}");
    }
    assert_eq!(planned.lines().count(), 40);
}
