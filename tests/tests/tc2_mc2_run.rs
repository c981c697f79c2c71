//! Beckhoff Tc2_MC2 motion blocks as TwinCAT projects call them (issue #13), run end to end through
//! `ladderc run` (C built with the sanitizers): MC_Power's `Enable_Positive` / `Enable_Negative`,
//! the `MC_Direction` enumeration on MC_MoveVelocity and on MC_MoveAbsolute of a modulo axis, the
//! `Tc2_MC2.` qualifier, Acceleration and Deceleration left to the axis configuration, and E1041
//! for the Tc2_MC2 pins ladderc's simulated axis has no counterpart for
//! (`crates/ladderc/src/tc2_mc2.rs`). The project under `fixtures/tc2_mc2/` is written for these
//! tests (README there).
//!
//! Record of the public projects tried (snapshots of 2026-12-04, `ladderc run FILE --cycles 20
//! --axes` one 2000 mm/s axis): the five `.plcproj` of the mirrors that declare `AXIS_REF` or call
//! MC_Power, and LilKiddy007's hand-written `src/main.st`.
//!
//! | project | before (errors) | after |
//! |---|---|---|
//! | LilKiddy007/twincat3-plc-motion-control `main.st` | E1003 MC_Direction, E1011 x2 Enable_Positive/Negative, E1001 x3 the MC_Direction values | runs |
//! | MatheusNespolo/TwinCAT Motion-Control/MotionControl | 12: E1011 x6, E1021 x4 (ReadStatus, Status), E1003, E1001 | 2: E1003 MC_MoveModulo (no counterpart block), E1041 `Override := lrOverride_Eixo2` |
//! | MatheusNespolo/TwinCAT ScopeTest | 4: E1011 x3, E1021 | runs |
//! | MatheusNespolo/TwinCAT HMI-Supervisorio PLC | 5: E1011 x3, E1021 x2 | runs |
//! | ergouliu/Twincat PLC_Pro (TC2_MC2.MC_Power ...) | 11: E1011 x10, E1001 | 1: E1001 `aa`, a name the project never declares |
//! | SeanyCash/TwinCAT_CNC Main | 5 E0001 (`{` attribute pragmas in an enum DUT) | the same: stops before any motion block |
//!
//! (The limits this round left, every `AXIS_REF` engine axis 0 and LilKiddy's reversal after
//! MC_Halt not starting, are lifted in `tc2_mc2_more_run.rs`.)

mod common;
use common::{column, ladderc, run_traced_files};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/tc2_mc2")
        .join(rel)
}

const WATCH: &str = "MAIN.nState,MAIN.bPowered,MAIN.bAbsDone,MAIN.bInVelocity,MAIN.bHaltDone,\
                     MAIN.bError,MAIN.rActPos,MAIN.bStandStill,axis.X1.position,axis.X1.velocity,\
                     axis.X1.acceleration";

/// The TwinCAT project: power on, MC_MoveAbsolute to 200 mm asking 400 mm/s of a 250 mm/s axis
/// (Acceleration and Deceleration from the axes file: 1000 and 500 mm/s²), MC_MoveVelocity with
/// `Direction := MC_Direction.MC_Negative_Direction` at 50 mm/s for one second, MC_Halt at
/// 100 mm/s². The axis is a global `AXIS_REF` of `GVL_Axes`, called qualified by the list's name;
/// `ReadStatus()`, `NcToPlc.ActPos` and `Status.StandStill` read it.
#[test]
fn a_twincat_project_written_with_tc2_mc2_moves_the_axis_as_commanded() {
    let (trace, stderr) = run_traced_files(&[&fixture("Motion.plcproj")], 300, WATCH);
    assert!(!stderr.contains("error"), "{stderr}");
    let state = column(&trace, "MAIN.nState");
    let pos = column(&trace, "axis.X1.position");
    let vel = column(&trace, "axis.X1.velocity");
    let acc = column(&trace, "axis.X1.acceleration");
    let abs_done = column(&trace, "MAIN.bAbsDone");
    let in_vel = column(&trace, "MAIN.bInVelocity");
    let halt_done = column(&trace, "MAIN.bHaltDone");
    // MC_Power with Enable_Positive / Enable_Negative powers the axis in the first scan
    assert_eq!(column(&trace, "MAIN.bPowered")[0], 1.0);
    assert!(column(&trace, "MAIN.bError").iter().all(|&e| e == 0.0));
    // the absolute move: Done at 200 mm; 250 mm/s is the axis limit (400 asked); ramps at the
    // configured 1000 mm/s² up (31.25 mm in 0.25 s) and 500 mm/s² down (62.5 mm in 0.5 s), the
    // 106.25 mm between at 250 mm/s (0.425 s): 1.175 s
    let done = abs_done
        .iter()
        .position(|&d| d == 1.0)
        .expect("MC_MoveAbsolute Done");
    assert!((117..=121).contains(&done), "Done at cycle {done}");
    assert!((pos[done - 1] - 200.0).abs() < 1e-9, "{}", pos[done - 1]);
    assert!(vel[..done]
        .iter()
        .all(|&v| (0.0..=250.0 + 1e-9).contains(&v)));
    assert!(vel[..done].iter().any(|&v| (v - 250.0).abs() < 1e-9));
    assert!(acc[..done]
        .iter()
        .all(|&a| (-500.0 - 1e-9..=1000.0 + 1e-9).contains(&a)));
    assert!(acc[..done].contains(&1000.0) && acc[..done].contains(&-500.0));
    // MC_Negative_Direction: the velocity move goes back at 50 mm/s
    let at_speed = in_vel.iter().position(|&v| v == 1.0).expect("InVelocity");
    assert!(state[at_speed] == 20.0 && (vel[at_speed] + 50.0).abs() < 1e-9);
    assert!(pos[at_speed + 50] < pos[at_speed]);
    // MC_Halt at 100 mm/s²: Done, the axis stands still and stays there
    let halted = halt_done
        .iter()
        .position(|&d| d == 1.0)
        .expect("MC_Halt Done");
    assert_eq!(vel[halted], 0.0);
    assert!(pos[halted..].iter().all(|&p| p == pos[halted]));
    assert!(pos[halted] < 200.0 - 50.0);
    let halt_from = state.iter().position(|&s| s == 30.0).unwrap();
    assert!(acc[halt_from..halted]
        .iter()
        .all(|&a| (0.0..=100.0 + 1e-9).contains(&a)));
    // 50 mm/s to 0 at 100 mm/s²: 0.5 s
    assert!(
        (49..=53).contains(&(halted - halt_from)),
        "{halt_from}..{halted}"
    );
}

/// MC_Direction on MC_MoveAbsolute of a modulo axis (Infosys: MC_MoveAbsolute's Direction is for
/// modulo axes): from 0 deg to 270 deg, `MC_Positive_Direction` turns +270, `MC_Shortest_Way` -90,
/// `MC_Negative_Direction` -90 too, each from 0 on its own axis.
#[test]
fn mc_direction_chooses_the_way_round_a_modulo_axis() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("table.st");
    std::fs::write(
        &src,
        "PROGRAM MAIN\nVAR\n  pA, pB, pC : MC_Power;\n\
         \x20 mA, mB, mC : Tc2_MC2.MC_MoveAbsolute;\n  eWay : MC_Direction := MC_Shortest_Way;\n\
         \x20 bGo : BOOL;\nEND_VAR\n\
         pA(Axis := A, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);\n\
         pB(Axis := B, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);\n\
         pC(Axis := C, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);\n\
         bGo := pA.Status AND pB.Status AND pC.Status;\n\
         mA(Axis := A, Execute := bGo, Position := 270.0, Velocity := 360.0, Direction := MC_Positive_Direction);\n\
         mB(Axis := B, Execute := bGo, Position := 270.0, Velocity := 360.0, Direction := eWay);\n\
         mC(Axis := C, Execute := bGo, Position := 270.0, Velocity := 360.0, Direction := MC_Negative_Direction,\n\
         \x20  Acceleration := 0, Deceleration := 0);\nEND_PROGRAM\n",
    )
    .unwrap();
    let axis = |n: &str| {
        format!(
            "{{ \"name\": \"{n}\", \"unit\": \"deg\", \"velocity\": 360, \"acceleration\": 3600, \
             \"deceleration\": 3600, \"modulo_period\": 360 }}"
        )
    };
    std::fs::write(
        dir.path().join("table.axes.json"),
        format!(
            "{{ \"cycle_ms\": 10, \"axes\": [ {}, {}, {} ] }}",
            axis("A"),
            axis("B"),
            axis("C")
        ),
    )
    .unwrap();
    let (trace, stderr) = run_traced_files(
        &[&src],
        150,
        "MAIN.mA.Done,MAIN.mB.Done,MAIN.mC.Done,axis.A.velocity,axis.B.velocity,axis.C.velocity,\
         axis.A.position,axis.B.position,axis.C.position",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    for (ax, sign) in [("A", 1.0), ("B", -1.0), ("C", -1.0)] {
        let v = column(&trace, &format!("axis.{ax}.velocity"));
        assert!(
            v.iter().all(|&x| x * sign >= 0.0),
            "axis {ax} turns one way"
        );
        assert!(v.iter().any(|&x| x != 0.0), "axis {ax} turns");
        let done = column(&trace, &format!("MAIN.m{ax}.Done"));
        let last = *column(&trace, &format!("axis.{ax}.position"))
            .last()
            .unwrap();
        assert_eq!(*done.last().unwrap(), 1.0, "axis {ax} Done");
        assert!(
            (last.rem_euclid(360.0) - 270.0).abs() < 1e-6,
            "axis {ax} at {last}"
        );
    }
}

/// A Tc2_MC2 pin without a counterpart in ladderc's axis is one located E1041, and nothing else is
/// said about it (before: E1011 "MC_Power has no parameter"); `Override := 100.0` is accepted
/// (any other override scales the moves: `tc2_mc2_more_run.rs`).
#[test]
fn pins_without_a_counterpart_are_one_e1041_each() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("ovr.st");
    std::fs::write(
        &src,
        "PROGRAM MAIN\nVAR\n  Axis : AXIS_REF;\n  fbPower : MC_Power;\n  rOvr : LREAL := 50.0;\n\
         \x20 b : BOOL;\nEND_VAR\n\
         fbPower(Axis := Axis, Enable := TRUE, Enable_Positive := TRUE, BufferMode := MC_Aborting);\n\
         fbPower(Axis := Axis, Enable := TRUE, Enable_Negative := TRUE, Override := 100.0);\n\
         b := fbPower.Busy;\nEND_PROGRAM\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("ovr.axes.json"),
        "{ \"axes\": [ { \"name\": \"X1\", \"velocity\": 10, \"acceleration\": 10, \"deceleration\": 10 } ] }",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&src)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let heads = common::diagnostic_heads(&out.stderr, dir.path(), true);
    assert_eq!(
        heads,
        vec![
            "ovr.st:8:64: error[E1041]: Tc2_MC2's `BufferMode` of MC_Power has no counterpart in ladderc's simulated axis",
            "ovr.st:10:14: error[E1041]: Tc2_MC2's `Busy` of MC_Power has no counterpart in ladderc's simulated axis",
        ],
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// `Axis.ReadStatus()`, `Axis.Status.*` and `Axis.NcToPlc.*` of a local Tc2_MC2 `AXIS_REF` read the
/// simulated axis: position and velocity as of the start of the scan (the engine steps after the
/// program), Moving while the move runs, StandStill and NotMoving once it is done.
#[test]
fn axis_ref_status_and_nc_to_plc_read_the_simulated_axis() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("status.st");
    std::fs::write(
        &src,
        "PROGRAM MAIN\nVAR\n  Axis : AXIS_REF;\n  fbPower : MC_Power;\n  fbMove : MC_MoveAbsolute;\n\
         \x20 bMoving, bStill, bNot, bErr : BOOL;\n  p, v : LREAL;\nEND_VAR\n\
         fbPower(Axis := Axis, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);\n\
         fbMove(Axis := Axis, Execute := fbPower.Status, Position := 10.0, Velocity := 100.0);\n\
         Axis.ReadStatus();\nbMoving := Axis.Status.Moving;\nbNot := Axis.Status.NotMoving;\n\
         bStill := Axis.Status.StandStill;\np := Axis.NcToPlc.ActPos;\nv := Axis.NcToPlc.ActVelo;\n\
         IF Axis.Status.Error THEN bErr := TRUE; END_IF\nEND_PROGRAM\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("status.axes.json"),
        "{ \"cycle_ms\": 10, \"axes\": [ { \"name\": \"X1\", \"unit\": \"mm\", \"velocity\": 100, \
         \"acceleration\": 3000, \"deceleration\": 3000 } ] }",
    )
    .unwrap();
    let (trace, stderr) = run_traced_files(
        &[&src],
        30,
        "MAIN.bMoving,MAIN.bNot,MAIN.bStill,MAIN.p,MAIN.v,MAIN.bErr,axis.X1.position,axis.X1.velocity",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let (p, v) = (column(&trace, "MAIN.p"), column(&trace, "MAIN.v"));
    let (pos, vel) = (
        column(&trace, "axis.X1.position"),
        column(&trace, "axis.X1.velocity"),
    );
    for k in 1..30 {
        assert_eq!((p[k], v[k]), (pos[k - 1], vel[k - 1]), "scan {k}");
    }
    let moving = column(&trace, "MAIN.bMoving");
    let still = column(&trace, "MAIN.bStill");
    let not = column(&trace, "MAIN.bNot");
    let stop = pos.iter().position(|&x| x == 10.0).unwrap();
    assert!((1..=stop).all(|k| moving[k] == 1.0 && still[k] == 0.0 && not[k] == 0.0));
    assert!((stop + 1..30).all(|k| moving[k] == 0.0 && still[k] == 1.0 && not[k] == 1.0));
    assert!(column(&trace, "MAIN.bErr").iter().all(|&e| e == 0.0));
}

/// An AXIS_REF member the simulated axis has no counterpart for is one located E1042 (before:
/// E1021 "AXIS_REF has no field"). (`Status.Homed` and `NcToPlc.StateDWord`, once such members,
/// are read since: `tc2_nc_run.rs`.)
#[test]
fn axis_ref_members_without_a_counterpart_are_one_e1042_each() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("homed.st");
    std::fs::write(
        &src,
        "PROGRAM MAIN\nVAR\n  Axis : AXIS_REF;\n  fbPower : MC_Power;\n  b : BOOL;\n  d : DWORD;\nEND_VAR\n\
         fbPower(Axis := Axis, Enable := TRUE);\nAxis.ReadStatus();\nb := Axis.Status.ExtSetPointGenEnabled;\n\
         d := Axis.NcToPlc.TouchProbeState;\nEND_PROGRAM\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("homed.axes.json"),
        "{ \"axes\": [ { \"name\": \"X1\", \"velocity\": 10, \"acceleration\": 10, \"deceleration\": 10 } ] }",
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
            "homed.st:10:18: error[E1042]: AXIS_REF's `Status.ExtSetPointGenEnabled` has no counterpart in ladderc's simulated axis",
            "homed.st:11:19: error[E1042]: AXIS_REF's `NcToPlc.TouchProbeState` has no counterpart in ladderc's simulated axis",
        ],
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
