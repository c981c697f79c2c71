//! The additional function blocks of Beremiz and OpenPLC Editor (issue #13): `HYSTERESIS`,
//! `INTEGRAL`, `DERIVATIVE`, `RAMP`, `PID` (IEC 61131-3 ed. 2 Annex F) and `SEMA`, which OpenPLC
//! projects instantiate without declaring them (stargieg/openplc-feed's `pid_program.st`,
//! sofialctv/integracao-modbusTCP-IP's `INTEGRAL` in ST and in its editor's `plc.xml`: E1003 /
//! E3009 before). ladderc compiles its own copy with the project (W1435, once); a project's own
//! block of such a name is used instead; `RTC` runs on the scan clock. Their values against
//! matiec's library: `matiec_diff.rs`, `additional_blocks_agree_with_matiec_to_real_rounding`.

mod common;
use common::{check_text, column, run_traced};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/additional_blocks")
        .join(rel)
}

/// An FBD program of PLCopen XML with INTEGRAL and HYSTERESIS boxes: the integral of a flow of
/// 2.0 over 500 ms samples (a TIME in seconds, as OpenPLC counts it) and a level switch at 4.0 +/-
/// 0.5.
#[test]
fn plcopen_fbd_boxes_of_the_editors_blocks_run() {
    let out = common::ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture("integral_fbd.xml"))
        .args([
            "--cycles",
            "6",
            "--cycle-ms",
            "500",
            "--sanitize",
            "--trace",
            "-",
        ])
        .args(["--watch", "inst.VOLUME,inst.FULL"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let notes: Vec<&str> = stderr.lines().filter(|l| l.contains("[W1435]")).collect();
    assert_eq!(notes.len(), 1, "{stderr}");
    assert!(
        notes[0].contains("integral_fbd.xml:13:52:")
            && notes[0].contains("`INTEGRAL`, `HYSTERESIS` are of the additional function blocks"),
        "{stderr}"
    );
    let trace = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        column(&trace, "inst.VOLUME"),
        [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
    );
    assert_eq!(column(&trace, "inst.FULL"), [0.0, 0.0, 0.0, 0.0, 1.0, 1.0]);
}

const ST_PROGRAM: &str = "PROGRAM Main
VAR
  ctrl : PID;
  ramp_up : RAMP;
  lock : SEMA;
  pv : REAL;
  out : REAL;
  sp : REAL;
  busy : BOOL;
END_VAR
ramp_up(RUN := TRUE, X0 := 0.0, X1 := 10.0, TR := T#400ms, CYCLE := T#100ms);
sp := ramp_up.XOUT;
ctrl(AUTO := TRUE, PV := pv, SP := 10.0, X0 := 0.0, KP := -2.0, TR := 1.0, TD := 0.0, CYCLE := T#100ms);
out := ctrl.XOUT;
pv := pv + out * 0.1;
lock(CLAIM := sp > 4.0 AND sp < 9.0, RELEASE := sp > 9.0);
busy := lock.BUSY;
END_PROGRAM
";

/// A PID (with its INTEGRAL and DERIVATIVE), a RAMP and a SEMA in an ST program: values as Annex F
/// computes them with a TIME in seconds. First scan: error -10, integral -10 x 0.1 s = -1, output
/// -2 x (-10 + -1 / 1.0) = 22; the ramp goes 0, 2.5, 5, 7.5, 10 in 400 ms.
#[test]
fn st_pid_ramp_and_semaphore_compute_as_annex_f() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("tank.st");
    std::fs::write(&file, ST_PROGRAM).unwrap();
    let (trace, stderr) = run_traced(&file, 6, "Main.out,Main.pv,Main.sp,Main.busy");
    assert!(
        stderr.contains("tank.st:3:10: note[W1435]: `PID`, `RAMP`, `SEMA` are of the additional"),
        "{stderr}"
    );
    let out = column(&trace, "Main.out");
    assert!((out[0] - 22.0).abs() < 1e-4, "{out:?}");
    // second scan: pv 2.2, error -7.8, integral -1.78: -2 x (-7.8 - 1.78) = 19.16
    assert!((out[1] - 19.16).abs() < 1e-3, "{out:?}");
    assert_eq!(column(&trace, "Main.sp"), [0.0, 2.5, 5.0, 7.5, 10.0, 10.0]);
    assert_eq!(column(&trace, "Main.busy"), [0.0, 0.0, 1.0, 1.0, 0.0, 0.0]);
}

/// A project's own `PID` is its own (no note, its pins); CODESYS Util's `PID` (its pins `ACTUAL`, `SET_POINT` ...) is one error
/// saying so, not one per pin.
#[test]
fn a_declared_block_of_that_name_wins() {
    let (code, lines) = check_text(
        "own.st",
        "FUNCTION_BLOCK PID\nVAR_INPUT e : REAL; END_VAR\nVAR_OUTPUT y : REAL; END_VAR\n\
         y := 3.0 * e;\nEND_FUNCTION_BLOCK\n\
         PROGRAM Main\nVAR c : PID; r : REAL; END_VAR\nc(e := 2.0);\nr := c.y;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(lines.iter().all(|l| !l.contains("W1435")), "{lines:?}");
    let (code, lines) = check_text(
        "util.st",
        "PROGRAM PLC_PRG\nVAR ctrl : PID; t : REAL; y : REAL; END_VAR\n\
         ctrl(ACTUAL := t, SET_POINT := 20.0, KP := 2.0, TN := 10.0, Y_MIN := 0.0);\n\
         y := ctrl.Y;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with(
            "util.st:3:6: error[E1011]: this `PID` is another library's (its pins `ACTUAL`, \
             `SET_POINT`, `TN`, `Y_MIN`, `Y`): ladderc provides the `PID` of Beremiz and OpenPLC \
             Editor (IEC 61131-3 Annex F) only"
        ),
        "{lines:?}"
    );
}

/// `RTC` (edition 1's real-time clock, matiec's and so Beremiz's and OpenPLC's; round 23 of
/// issue #13: an Elna/Beremiz project's `RTC` was E1003): without IN, CDT is the clock, which a
/// simulated run starts at DT#1970-01-01-00:00:00 and moves with the scan clock; when IN rises,
/// CDT is PDT and counts on from there; Q is IN.
#[test]
fn rtc_counts_from_the_preset_on_the_scan_clock() {
    let (trace, stderr) = common::run_text(
        "clock.st",
        "PROGRAM Main
VAR clock : RTC; set : BOOL; n : INT;
  at_start, at_preset, two_later, q : BOOL; END_VAR
n := n + 1;
set := n >= 3;
clock(IN := set, PDT := DT#2024-05-01-12:00:00);
at_start := clock.CDT = DT#1970-01-01-00:00:00;
at_preset := clock.CDT = DT#2024-05-01-12:00:00;
two_later := clock.CDT = DT#2024-05-01-12:00:00.02;
q := clock.Q;
END_PROGRAM
",
        5,
        "Main.at_start,Main.at_preset,Main.two_later,Main.q",
    );
    assert!(stderr.contains("W1435"), "{stderr}");
    assert_eq!(
        column(&trace, "Main.at_start"),
        [1.0, 0.0, 0.0, 0.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "Main.at_preset"),
        [0.0, 0.0, 1.0, 0.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "Main.two_later"),
        [0.0, 0.0, 0.0, 0.0, 1.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "Main.q"),
        [0.0, 0.0, 1.0, 1.0, 1.0],
        "{trace}"
    );
}
