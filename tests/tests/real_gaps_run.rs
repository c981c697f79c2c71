//! Gaps found on real projects (issue #13), each closed end to end through `ladderc run`: actions
//! called from other POUs, global variable lists sharing member names, trace columns of qualified
//! globals and `--trace -`, SFC indicator variables, overlapping CASE labels, integer division of
//! integer literals, and names the standard reserves.

mod common;
use common::ladderc;

use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/real_gaps")
        .join(name)
}

/// `ladderc run FILE --cycles N --sanitize --watch WATCH --trace -`: the trace (standard output)
/// and standard error; asserts exit 0.
fn run(file: &Path, cycles: u32, watch: &str) -> (String, String) {
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(file)
        .args([
            "--cycles",
            &cycles.to_string(),
            "--sanitize",
            "--trace",
            "-",
        ])
        .args(["--watch", watch])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("Sanitizer"), "{stderr}");
    (String::from_utf8_lossy(&out.stdout).into_owned(), stderr)
}

/// `ladderc check` of `src` written to `dir/name`: exit code and the diagnostic lines (short
/// format), with the temporary folder left out.
fn check_text(name: &str, src: &str) -> (Option<i32>, Vec<String>) {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join(name);
    std::fs::write(&f, src).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&f)
        .output()
        .unwrap();
    let prefix = format!("{}/", dir.path().display());
    let lines = String::from_utf8_lossy(&out.stderr)
        .lines()
        .filter(|l| l.contains("error[") || l.contains("warning["))
        .map(|l| l.replace(&prefix, ""))
        .collect();
    (out.status.code(), lines)
}

// ------------------------------------------------------------------ 1. actions called from outside

#[test]
fn actions_of_fb_instances_run_once_per_call_from_st_and_il() {
    // main calls c.Reset() in cycle 2 (n = 3), after c(step := 2): the count drops to 0 and the next
    // call adds 2 again; cs[2].Bump() twice a cycle (the second with step := 7 passed as in a call of
    // the instance) adds 100 and counts 1 each time: the body never runs for cs[2]; il_side's
    // CALC d.Reset resets d once its count reaches 3
    let (trace, _) = run(
        &fixture("actions.st"),
        5,
        "main.c.count,main.cs[2].count,main.cs[2].calls,main.cs[2].step,il_side.d.count",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,main.c.count,main.cs[2].count,main.cs[2].calls,main.cs[2].step,il_side.d.count\n\
         0,0,2,200,2,7,1\n\
         1,10,4,400,4,7,2\n\
         2,20,0,600,6,7,0\n\
         3,30,2,800,8,7,1\n\
         4,40,4,1000,10,7,2\n"
    );
}

#[test]
fn codesys_fb_actions_run_from_st_and_il_bodies() {
    // FB_Tank adds rIn to rLevel; its ST action Drain halves rLevel. PLC_PRG drains every second
    // cycle; PRG_IL calls the instance with 8.0 and then `CAL fbTank.Drain(rIn := 0.0)`.
    let (trace, stderr) = run(
        &fixture("fb_actions.xml"),
        4,
        "PLC_PRG.fbTank.rLevel,PRG_IL.fbTank.rLevel,PRG_IL.fbTank.rIn",
    );
    assert!(!stderr.contains("W3401"), "{stderr}");
    assert_eq!(
        trace,
        "cycle,time_ms,PLC_PRG.fbTank.rLevel,PRG_IL.fbTank.rLevel,PRG_IL.fbTank.rIn\n\
         0,0,4,4,0\n\
         1,10,4,6,0\n\
         2,20,8,7,0\n\
         3,30,6,7.5,0\n"
    );
}

#[test]
fn an_action_of_a_program_called_from_another_pou_is_a_located_error() {
    let src = "PROGRAM counter\nVAR n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n\
               ACTIONS\nACTION Reset:\nn := 0;\nEND_ACTION\nEND_ACTIONS\n\
               PROGRAM other\ncounter.Reset();\nEND_PROGRAM\n";
    let (code, lines) = check_text("p.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        lines,
        vec![
            "p.st:11:1: error[E3135]: action `Reset` of program `counter` is called from another POU \
             (hint: call it from `counter` itself (`Reset();`), or make `counter` a FUNCTION_BLOCK and \
             call the action through an instance)"
        ]
    );
}
