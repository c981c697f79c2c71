//! Beckhoff Tc2_MC2 motion as real TwinCAT projects use it, the rest (issue #13), run end to end
//! through `ladderc run` (C built with the sanitizers): several `AXIS_REF`s, each its own
//! simulated axis linked from the axes file (`crates/ladderc/src/axis_links.rs`, E1056, E1057);
//! MC_MoveModulo and MC_Jog (`tc2_blocks.rs`); MC_Power's `Override` (`tc2_override.rs`); a
//! block input written as an expression (`block_temps.rs`); the UDINT `ErrorID`
//! (`tc2_error_id.rs`); a halted MC_MoveVelocity started again (motion-lib's `ExecCore`). The
//! fixtures under `fixtures/tc2_mc2_more/` are written for these tests (README there).
//!
//! Record of the public projects tried (snapshots of 2026-12-04; `ladderc run PROJECT --cycles 20`
//! with an axes file that names the project's axes, 100 mm/s each; "before" is main's ladderc):
//!
//! | project | before (errors) | after |
//! |---|---|---|
//! | MatheusNespolo/TwinCAT Motion-Control/MotionControl (GVL_Axes.Axis1/Axis2, MC_MoveModulo, `Override := lrOverride_Eixo2`, `Execute := ResetaEixo AND GVL_Axes.Axis1.Status.Error`) | 14: E1002 x2 (the GVL's axes declared again by the axes file), E1003 MC_MoveModulo, E1041 Override, E1001 x10 cascading | runs |
//! | MatheusNespolo/TwinCAT ScopeTest (Axes.Axis1) | 2: E1002, E1001 | runs |
//! | MatheusNespolo/TwinCAT HMI-Supervisorio PLC (Eixos.Eixo1/Eixo2) | 3: E1002 x2, E1001 | runs |
//! | ergouliu/Twincat PLC_Pro (five AXIS_REFs of MAIN, axes named like them) | 1: E1001 `aa` (the five shared axis 0) | 1: E1001 `aa`, a name the project never declares (five axes) |
//! | SeanyCash/TwinCAT_CNC Main (no axes file) | 107 | 95: MC_Jog and E_JogMode known (-8), UDINT ErrorIDs (-5), E1056 for the four axes of `GVL.fbCNC` (+1); NCI, event logger, MC_PowerStepper, MC_TouchProbe remain |
//! | LilKiddy007/twincat3-plc-motion-control `main.st` | runs, but the reversal after MC_Halt never starts (the rising Execute on the aborted MC_MoveVelocity was ignored as Busy) | runs, and reverses: +300, -300, +1000 mm/s as programmed |

mod common;
mod lsp_client;
use common::{column, ladderc, run_traced_files};

use lsp_client::Client;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/tc2_mc2_more")
        .join(rel)
}

const EPS: f64 = 1e-9;

/// Every value of `v` within `[lo, hi]` (with rounding room).
fn within(v: &[f64], lo: f64, hi: f64) -> bool {
    v.iter().all(|&x| x >= lo - 1e-6 && x <= hi + 1e-6)
}

/// The TwinCAT project `Cell`: two axes of a global variable list (named like the axes of the
/// axes file), an axis inside each of two FB_Station instances and the two elements of an
/// `ARRAY [1..2] OF AXIS_REF` (linked with `"link"`). Each moves on its own, as commanded, within
/// its own limits.
#[test]
fn every_axis_ref_instance_is_its_own_axis_with_its_own_limits() {
    let axes = ["Axis1", "Axis2", "StationA", "StationB", "Table1", "Table2"];
    let mut watch: Vec<String> = Vec::new();
    for a in axes {
        for q in ["position", "velocity", "acceleration"] {
            watch.push(format!("axis.{a}.{q}"));
        }
    }
    watch.push("MAIN.fbTurn1.Done".into());
    watch.push("MAIN.fbTurn2.Done".into());
    let (trace, stderr) = run_traced_files(&[&fixture("Cell.plcproj")], 250, &watch.join(","));
    assert!(!stderr.contains("error"), "{stderr}");
    let col = |a: &str, q: &str| column(&trace, &format!("axis.{a}.{q}"));
    let last = |a: &str| *col(a, "position").last().unwrap();
    // where each ends: its own command, not another axis's
    assert!((last("Axis1") - 100.0).abs() < EPS, "{}", last("Axis1"));
    assert!((last("Axis2") + 50.0).abs() < EPS, "{}", last("Axis2"));
    assert!((last("StationA") - 30.0).abs() < EPS);
    assert!((last("StationB") - 70.0).abs() < EPS);
    assert!((last("Table1") - 90.0).abs() < 1e-6, "{}", last("Table1"));
    assert!((last("Table2") - 270.0).abs() < 1e-6, "{}", last("Table2"));
    // the limits of each axis hold; asked 500 mm/s, Axis1 runs at its 200, Axis2 at its 100
    for (a, v, acc) in [
        ("Axis1", 200.0, 1000.0),
        ("Axis2", 100.0, 500.0),
        ("StationA", 150.0, 1500.0),
        ("StationB", 250.0, 2500.0),
        ("Table1", 720.0, 3600.0),
        ("Table2", 180.0, 1800.0),
    ] {
        assert!(within(&col(a, "velocity"), -v, v), "{a} velocity");
        assert!(
            within(&col(a, "acceleration"), -acc, acc),
            "{a} acceleration"
        );
    }
    // Acceleration and Deceleration left out: each station's own configured limits (Tc2_MC2: "the
    // standard acceleration from the axis configuration"), though both run one FB_Station's code
    assert!(col("StationA", "acceleration").contains(&1500.0));
    assert!(col("StationB", "acceleration").contains(&2500.0));
    assert!(col("StationB", "acceleration").contains(&-2500.0));
    let peak = |a: &str| {
        col(a, "velocity")
            .iter()
            .fold(0.0f64, |m, &x| m.max(x.abs()))
    };
    assert!((peak("Axis1") - 200.0).abs() < EPS && (peak("Axis2") - 100.0).abs() < EPS);
    // Table1: MC_MoveModulo to 450 deg, MC_Positive_Direction: one full turn and 90 deg, forward
    let t1 = col("Table1", "position");
    assert!(col("Table1", "velocity").iter().all(|&v| v >= 0.0));
    assert_eq!(t1.windows(2).filter(|w| w[1] < w[0]).count(), 1, "one wrap");
    // Table2: MC_Shortest_Way to 270 deg from 0: 90 deg back
    assert!(col("Table2", "velocity").iter().all(|&v| v <= 0.0));
    assert_eq!(column(&trace, "MAIN.fbTurn1.Done").last(), Some(&1.0));
    assert_eq!(column(&trace, "MAIN.fbTurn2.Done").last(), Some(&1.0));
}

/// A program's own `AXIS_REF`s named like axes of the axes file are those axes (the file lists
/// them in the other order): the spindle turns at its 60 deg/s limit (100 asked), the feed stops
/// at 10 mm at its 50 mm/s.
#[test]
fn a_programs_axis_refs_named_like_axes_are_those_axes() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("Spindle.st")],
        100,
        "axis.Spindle.velocity,axis.Feed.velocity,axis.Feed.position",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let spin = column(&trace, "axis.Spindle.velocity");
    let feed = column(&trace, "axis.Feed.velocity");
    assert!(within(&spin, 0.0, 60.0) && (spin[99] - 60.0).abs() < EPS);
    assert!(within(&feed, 0.0, 50.0) && feed.iter().any(|&v| (v - 50.0).abs() < EPS));
    assert!((column(&trace, "axis.Feed.position")[99] - 10.0).abs() < EPS);
}

/// MC_MoveModulo's rules (Infosys, Tc2_MC2 > MC_MoveModulo): from standstill 450 deg forward is
/// one turn and 90 deg; 90 deg from 90 deg is no motion; 450 deg backward from 90 deg one turn
/// back; started while the axis turns forward, MC_Negative_Direction cannot reverse it: it stops
/// at 10 deg going forward. On an axis without a modulo period: Error, ErrorID 24, no motion.
#[test]
fn mc_move_modulo_turns_as_tc2_mc2_documents() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("Turn.st")],
        450,
        "MAIN.nState,MAIN.mm.Done,MAIN.mmL.Error,MAIN.mmL.ErrorID,axis.T.position,\
         axis.T.velocity,axis.T.acceleration,axis.L.position",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let state = column(&trace, "MAIN.nState");
    let pos = column(&trace, "axis.T.position");
    let vel = column(&trace, "axis.T.velocity");
    let from = |s: f64| state.iter().position(|&x| x == s).unwrap();
    let (s2, s3, s4, s5, s6) = (from(2.0), from(3.0), from(4.0), from(5.0), from(6.0));
    // limits: 360 deg/s (720 asked), 3600 up, 1800 down
    assert!(within(&vel, -360.0, 360.0));
    assert!(within(
        &column(&trace, "axis.T.acceleration"),
        -3600.0,
        3600.0
    ));
    assert!(vel.iter().any(|&v| (v - 360.0).abs() < EPS));
    // 1: forward, one wrap, at 90
    assert!(vel[..s2].iter().all(|&v| v >= 0.0));
    assert_eq!(pos[..s2].windows(2).filter(|w| w[1] < w[0]).count(), 1);
    assert!((pos[s2 - 1] - 90.0).abs() < 1e-6, "{}", pos[s2 - 1]);
    // 2: 90 from 90: Done with no motion
    assert!(s3 - s2 <= 3, "{s2}..{s3}");
    assert!(pos[s2..s3].iter().all(|&p| (p - pos[s2 - 1]).abs() < 1e-6));
    // 3: backward one full turn (about 1 s at 360 deg/s), at 90 again
    assert!(vel[s3..s4].iter().all(|&v| v <= 0.0));
    assert!(vel[s3..s4].iter().any(|&v| (v + 360.0).abs() < EPS));
    assert_eq!(pos[s3..s4].windows(2).filter(|w| w[1] > w[0]).count(), 1);
    assert!((pos[s4 - 1] - 90.0).abs() < 1e-6);
    assert!((100..=130).contains(&(s4 - s3)), "{s3}..{s4}");
    // 5: started while turning forward: stays forward, stops at 10
    assert!(vel[s5..s6].iter().all(|&v| v >= 0.0));
    assert!(vel[s5] > 0.0);
    assert!((pos.last().unwrap() - 10.0).abs() < 1e-6);
    assert_eq!(*vel.last().unwrap(), 0.0);
    // the linear axis refuses, and does not move
    assert!(column(&trace, "MAIN.mmL.Error")[1..]
        .iter()
        .all(|&e| e == 1.0));
    assert!(column(&trace, "MAIN.mmL.ErrorID")[1..]
        .iter()
        .all(|&e| e == 24.0));
    assert!(column(&trace, "axis.L.position").iter().all(|&p| p == 0.0));
}

/// MC_Power's `Override` (percent, 0..100) scales the running move: 100 % runs at the commanded
/// 100 mm/s, 50 % at 50, 150 % is limited to 100 %, 0 % brakes to standstill; each change is a
/// transition within the axis's acceleration (500 mm/s²) and jerk (5000 mm/s³) limits.
#[test]
fn mc_power_override_scales_the_moves_within_the_limits() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("Override.st")],
        400,
        "MAIN.ovr,axis.X.velocity,axis.X.acceleration",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let v = column(&trace, "axis.X.velocity");
    let a = column(&trace, "axis.X.acceleration");
    assert!((v[95] - 100.0).abs() < EPS, "{}", v[95]);
    assert!((v[195] - 50.0).abs() < EPS, "{}", v[195]);
    assert!((v[295] - 100.0).abs() < EPS, "{}", v[295]);
    assert!(v[350..].iter().all(|&x| x == 0.0));
    // the transitions: from 100 to 50 takes time (no step), and the limits hold throughout
    assert!(v[100] > 50.0 + 1.0 && v[100] < 100.0);
    assert!(within(&v, 0.0, 100.0));
    assert!(within(&a, -500.0, 500.0));
    let jerk: Vec<f64> = a.windows(2).map(|w| (w[1] - w[0]) / 0.01).collect();
    assert!(within(&jerk, -5000.0, 5000.0), "jerk");
    let dv: Vec<f64> = v.windows(2).map(|w| (w[1] - w[0]) / 0.01).collect();
    assert!(within(&dv, -500.0, 500.0));
}

/// Tc2_MC2 MC_Jog (Infosys): MC_JOGMODE_CONTINOUS moves while the key is held with the block's
/// Velocity (80 mm/s), Acceleration (400) and Deceleration (800), and stops when it is released;
/// MC_JOGMODE_INCHING moves `Position` (5 mm) per rising edge, and an edge while the step runs is
/// not taken; MC_JOGMODE_STANDARD_SLOW runs at the axis's slow manual velocity (`jog_velocity_slow`,
/// 20 mm/s) with the axis's dynamics. Done once each jog has stopped; the limits hold.
#[test]
fn mc_jog_moves_while_held_and_steps_per_edge() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("Jog.st")],
        400,
        "MAIN.n,MAIN.fbJog.Busy,MAIN.fbJog.Done,MAIN.fbJog.Error,axis.X.position,\
         axis.X.velocity,axis.X.acceleration",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let pos = column(&trace, "axis.X.position");
    let vel = column(&trace, "axis.X.velocity");
    let acc = column(&trace, "axis.X.acceleration");
    let busy = column(&trace, "MAIN.fbJog.Busy");
    let done = column(&trace, "MAIN.fbJog.Done");
    assert!(column(&trace, "MAIN.fbJog.Error").iter().all(|&e| e == 0.0));
    assert!(within(&vel, -100.0, 100.0) && within(&acc, -1000.0, 1000.0));
    // continuous: 80 mm/s while held (scans 11..60), ramps of 400 up and 800 down, then Done
    assert!((vel[40] - 80.0).abs() < EPS);
    assert!(within(&acc[..100], -800.0, 400.0));
    assert!(acc[..100].contains(&400.0) && acc[..100].contains(&-800.0));
    let first_stop = (60..100).find(|&k| vel[k] == 0.0).unwrap();
    assert!(first_stop <= 72, "{first_stop}");
    assert!(busy[first_stop + 2] == 0.0 && done[first_stop + 2] == 1.0);
    // inching: one step of 5 mm back, the second pulse (during the step) not taken
    assert!(vel[100..240].iter().all(|&v| v <= 0.0));
    assert!(
        (pos[240] - (pos[140] - 5.0)).abs() < EPS,
        "{} {}",
        pos[140],
        pos[240]
    );
    assert_eq!(done[240], 1.0);
    // standard slow: 20 mm/s, the axis's 1000 mm/s² (not the block's 400)
    assert!((vel[280] - 20.0).abs() < EPS);
    assert!(acc[245..260].contains(&1000.0));
    assert!(vel[320..].iter().all(|&v| v == 0.0) && done[399] == 1.0);
}

/// One MC_MoveVelocity instance, halted (MC_Halt aborts it) and started again the other way by
/// its next rising Execute, as LilKiddy007's project drives its axis: the second command starts
/// (before: the rising edge came while the block still showed Busy from the aborted command, as
/// of its last call, and was ignored; the axis stood still). PLCopen: a block that is not Busy
/// takes a rising Execute; the aborted command ended in the engine's step before this call.
#[test]
fn a_halted_move_velocity_starts_again_on_its_next_rising_execute() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("Reverse.st")],
        160,
        "MAIN.nStep,MAIN.fbVel.Busy,MAIN.fbVel.CommandAborted,axis.X.velocity,axis.X.acceleration",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let step = column(&trace, "MAIN.nStep");
    let vel = column(&trace, "axis.X.velocity");
    let one = step.iter().position(|&s| s == 1.0).unwrap();
    let two = step.iter().position(|&s| s == 2.0).unwrap();
    assert!(vel[..one].iter().any(|&v| (v - 50.0).abs() < EPS));
    // halted, then backward at 50 mm/s within the limits
    assert!(
        vel[one..two].iter().any(|&v| (v + 50.0).abs() < EPS),
        "no reversal"
    );
    assert!(within(&vel, -100.0, 100.0));
    assert!(within(
        &column(&trace, "axis.X.acceleration"),
        -500.0,
        500.0
    ));
    assert_eq!(column(&trace, "MAIN.fbVel.Busy")[two - 1], 1.0);
}

/// Tc2_MC2's `ErrorID` is UDINT (Infosys): `ErrorID => stOut.nMoveErrorID` (a UDINT field of a
/// structure) receives ladderc's ErrorID, here 20 InvalidVelocity for Velocity 0 (before: E1012
/// "output ErrorID of MC_MoveAbsolute is WORD, cannot be stored into UDINT"); a WORD target is
/// bound as before.
#[test]
fn tc2_udint_error_ids_receive_the_block_error() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("ErrorId.st")],
        5,
        "MAIN.stOut.bMoveError,MAIN.stOut.nMoveErrorID,MAIN.nPowerErrorID,MAIN.nMove2ErrorID",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    for k in 0..5 {
        assert_eq!(column(&trace, "MAIN.stOut.bMoveError")[k], 1.0);
        assert_eq!(column(&trace, "MAIN.stOut.nMoveErrorID")[k], 20.0);
        assert_eq!(column(&trace, "MAIN.nMove2ErrorID")[k], 20.0);
        assert_eq!(column(&trace, "MAIN.nPowerErrorID")[k], 0.0);
    }
}

/// An `AXIS_REF` without an axis is one located E1056 per declaration, a `"link"` that names no
/// `AXIS_REF` one E1057 at the path in the axes file; an `AXIS_REF` the program never names
/// (`spare`) needs no axis.
#[test]
fn axis_refs_without_an_axis_and_bad_links_are_located_diagnostics() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("two.st");
    std::fs::write(
        &src,
        "FUNCTION_BLOCK FB_Station\nVAR\n  Axis : AXIS_REF;\n  pw : MC_Power;\nEND_VAR\n\
         pw(Axis := Axis, Enable := TRUE);\nEND_FUNCTION_BLOCK\n\
         PROGRAM MAIN\nVAR\n  stA : FB_Station;\n  stB : FB_Station;\n\
         \x20 aAxes : ARRAY[1..3] OF AXIS_REF;\n  spare : AXIS_REF;\n  mp : MC_Power;\nEND_VAR\n\
         stA();\nstB();\nmp(Axis := aAxes[1], Enable := TRUE);\nEND_PROGRAM\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("two.axes.json"),
        "{ \"axes\": [\n\
         { \"name\": \"A\", \"velocity\": 10, \"acceleration\": 10, \"deceleration\": 10, \"link\": \"MAIN.stA.Axis\" },\n\
         { \"name\": \"B\", \"velocity\": 10, \"acceleration\": 10, \"deceleration\": 10, \"link\": \"MAIN.aAxes[2]\" },\n\
         { \"name\": \"C\", \"velocity\": 10, \"acceleration\": 10, \"deceleration\": 10, \"link\": \"MAIN.stC.Axis\" } ] }\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&src)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let heads = common::diagnostic_heads(&out.stderr, dir.path(), false);
    assert_eq!(
        heads,
        vec![
            "two.st:11:3: error[E1056]: AXIS_REF `MAIN.stB.Axis` is linked to no axis of the axes file",
            "two.st:12:3: error[E1056]: AXIS_REF `MAIN.aAxes[1]` (and 1 more AXIS_REF of this declaration) is linked to no axis of the axes file",
            "two.axes.json:4:80: error[E1057]: axis `C` links `MAIN.stC.Axis`, which is no AXIS_REF of the program",
        ],
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

// ---------------------------------------------------------------- the language server

const TC2_DOC: &str = "VAR_GLOBAL\n    Axis1 : AXIS_REF;\nEND_VAR\nPROGRAM MAIN\nVAR\n    fbPower : MC_Power;\n    fbTurn : Tc2_MC2.MC_MoveModulo;\nEND_VAR\n\
fbPower(Axis := Axis1, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE, Override := 50.0);\n\
fbTurn(Axis := Axis1, Execute := fbPower.Status, Position := 90.0, Velocity := 100.0,\n\
    Direction := MC_Direction.MC_Shortest_Way);\nEND_PROGRAM\n";

fn labels(items: &Value) -> Vec<String> {
    items
        .as_array()
        .unwrap()
        .iter()
        .map(|i| i["label"].as_str().unwrap().to_string())
        .collect()
}

/// The language server treats the Tc2_MC2 spellings as `ladderc check` does: no diagnostic for
/// `Enable_Positive`, `Override`, MC_MoveModulo, a qualified MC_Direction value or a global
/// `AXIS_REF` named like an axis (before: E1011, E1003, E1002); hover lists the Tc2_MC2 inputs and
/// MC_MoveModulo's interface; completion offers them, and the members of a Tc2_MC2 `AXIS_REF`.
#[test]
fn the_language_server_reads_tc2_mc2_as_the_command_line_does() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cell.st");
    std::fs::write(&path, TC2_DOC).unwrap();
    std::fs::write(
        dir.path().join("cell.axes.json"),
        "{ \"axes\": [ { \"name\": \"Axis1\", \"velocity\": 100, \"acceleration\": 1000, \
         \"deceleration\": 1000, \"modulo_period\": 360 } ] }",
    )
    .unwrap();
    // the command line accepts it
    let out = ladderc().arg("check").arg(&path).output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let uri = format!("file://{}", path.display());
    let mut c = Client::start(dir.path());
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": uri, "languageId": "iec-st", "version": 1, "text": TC2_DOC}}),
    );
    let d = c.diagnostics();
    assert_eq!(d["diagnostics"], json!([]), "{d}");
    // hover on the declarations of fbPower (line 6) and fbTurn (line 7)
    let hover = |c: &mut Client, line: u32| {
        let h = c.request(
            "textDocument/hover",
            json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": 6}}),
        );
        h["contents"]["value"].as_str().unwrap().to_string()
    };
    let md = hover(&mut c, 5);
    assert!(md.contains("`Enable_Positive` : `BOOL`"), "{md}");
    assert!(md.contains("`Override` : `LREAL`"), "{md}");
    let md = hover(&mut c, 6);
    assert!(md.contains("FUNCTION_BLOCK `MC_MoveModulo`"), "{md}");
    assert!(md.contains("`Direction` : `USINT` (VAR_INPUT)"), "{md}");
    // completion: in `fbPower(`, after `Axis1.`, after `Axis1.Status.` and `Axis1.NcToPlc.`
    let edited = TC2_DOC.replace(
        "END_PROGRAM",
        "fbPower(\nAxis1.\nAxis1.Status.\nAxis1.NcToPlc.\nEND_PROGRAM",
    );
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": uri, "version": 2}, "contentChanges": [{"text": edited}]}),
    );
    let _ = c.diagnostics();
    let mut complete = |line: u32, character: u32| {
        let items = c.request(
            "textDocument/completion",
            json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": character}}),
        );
        labels(&items)
    };
    let l = complete(11, 8);
    assert!(
        l.contains(&"Enable_Positive :=".to_string()) && l.contains(&"Override :=".to_string()),
        "{l:?}"
    );
    let l = complete(12, 6);
    // `PlcToNc` since round 31 (its `Override` is written and read back: `tc_r31_run.rs`)
    assert_eq!(l, ["ReadStatus", "Status", "NcToPlc", "PlcToNc"]);
    let l = complete(13, 13);
    assert!(
        l.contains(&"StandStill".to_string()) && l.contains(&"Moving".to_string()),
        "{l:?}"
    );
    let l = complete(14, 14);
    assert_eq!(
        l,
        [
            "ActPos",
            "SetPos",
            "ActVelo",
            "SetVelo",
            "PosDiff",
            "ActTorque",
            "SetTorque",
            "ErrorCode",
            "CoupleState",
            "AxisId",
            "StateDWord"
        ]
    );
    let _ = c.request("shutdown", json!(null));
    c.notify("exit", json!(null));
    assert!(c.child.wait().unwrap().success());
}
