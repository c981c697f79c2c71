//! Motion blocks as real projects hold them (issue #13), run end to end through `ladderc run` (C
//! built with the sanitizers): arrays of motion block instances called in a FOR loop with a
//! variable index (`fbPower[i](Axis := axes[i], ...)`, param-passing's lowering of an element of
//! an array of instances), motion blocks inside a function block that is itself in an array, and
//! each element its own block state bound to the axis it is called with, within that axis's
//! limits; MC_MoveModulo queued behind a running move (measured from the end of the queue),
//! MC_Jog's MC_JOGMODE_INCHING_MODULO, members of `ARRAY OF AXIS_REF` elements, NcToPlc.ErrorCode,
//! MC_GearOut, and E1053 for a motion block held in a structure. The fixtures under
//! `fixtures/motion_arrays/` are written for these tests (README there).
//!
//! Record of the public projects tried (snapshots of 2026-12-04; `ladderc check PROJECT --axes F`
//! with an axes file linking every AXIS_REF the project declares, 100 mm/s each; "before" is
//! main's ladderc at 0d674c7; error counts):
//!
//! | project | before | after |
//! |---|---|---|
//! | zhaoshutao/PWFACLM_PLC (`GVL.axisRefs : ARRAY[1..10] OF AXIS_REF`, `fbAxes : ARRAY OF FB_AxisControl`, `mcSetPos : ARRAY OF MC_SetPosition`) | 13: E1021 x2 (`GVL.axisRefs[_i].NcToPlc.ActPos`/`ActVelo`), E1042 `NcToPlc.ErrorCode`, 10 of Beckhoff libraries (Tc2_SUPS, TC_Restart, recipes); with those parts cut out, `run` stops on E1018 (`mcSetPos[_i](...)`) | 10, all of the libraries; with those parts cut out it runs: the axes' positions restored by the MC_SetPosition array, `GVL.initStatus` after the 3 s start delay |
//! | zhaoshutao/HEPSCollimator | 11: E1042 x2 `NcToPlc.ErrorCode` | 9, all of libraries (Tc2_SUPS, TC_Restart) |
//! | zhaoshutao/AKPLC, HEPSPLC, TEST | 270, 273, 153 | 268, 271, 151: MC_GearOut known; left: `NcToPlc.CoupleState` (304 reads in the five IDPLC projects), `PosDiff`, `ActTorque`, `Status.Homed`, MC_Power's `Active`, the whole `NcToPlc` passed to Tc2_SoE's FB_SoEReadDiagMessage (E1021), Beckhoff libraries |
//! | zhaoshutao/IAMWPLC, PSPLC | 333, 48 | 333, 48 (the same kinds) |
//! | SeanyCash/TwinCAT_CNC | 96 | 95: MC_GearOut known; left: NCI, event logger, MC_PowerStepper, MC_TouchProbe, `MC_HomingMode`, `NcToPlc.CoupleState`/`AxisId`, `Status.Homed` |
//! | MatheusNespolo/TwinCAT (3 projects), LilKiddy007/twincat3-plc-motion-control | run | run, every common trace column equal (MotionControl, 300 cycles) |
//! | ta-ichihashi/TwinCATHowTo, Scope view example (`axes : ARRAY [0..2] OF AXIS_REF`, `axes[i].Status.InTargetPosition`, `axes[i].NcToPlc.SetPos`; reproduced in `Trigger.st`) | E1003 `AXIS_REF` (a program whose motion declarations are all arrays was not read as one) | runs |
//! | n312-coder/Automatisierungstechnik, koreacomp5/real_press_plc, nrwslac/sds_geneva | 9+1, 6, 30 | the same: none in motion (Tc3_IotBase MQTT, a CFC body, BYTE arithmetic, Tc2_System) |

mod common;
use common::{column, run_traced_files};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/motion_arrays")
        .join(rel)
}

const EPS: f64 = 1e-9;

/// Every value of `v` within `[lo, hi]` (with rounding room).
fn within(v: &[f64], lo: f64, hi: f64) -> bool {
    v.iter().all(|&x| x >= lo - 1e-6 && x <= hi + 1e-6)
}

/// The largest magnitude of `v`.
fn peak(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, &x| m.max(x.abs()))
}

/// `fbPower : ARRAY[1..4] OF Tc2_MC2.MC_Power`, `fbMove : ARRAY[0..2] OF MC_MoveAbsolute` and
/// `fbMod : ARRAY[1..1] OF MC_MoveModulo` over `axes : ARRAY[1..4] OF AXIS_REF`, called in FOR
/// loops (`fbMove[i - 1](Axis := axes[i], ...)`): each element moves its own axis to its own
/// target, at most at that axis's velocity and acceleration (500 mm/s and 10000 mm/s² asked),
/// with MC_Power's `Override` of its own element (50 % on the third axis); Done and Busy read as
/// `fbMove[i - 1].Done` belong to that element.
#[test]
fn arrays_of_motion_blocks_each_drive_their_own_axis() {
    let watch = [
        "MAIN.nDone",
        "MAIN.aDone[1]",
        "MAIN.aDone[2]",
        "MAIN.aDone[3]",
        "MAIN.aBusy[1]",
        "MAIN.aBusy[2]",
        "MAIN.bModDone",
        "MAIN.fbMove[1].Done",
    ]
    .into_iter()
    .map(String::from)
    .chain(["Lift", "Slide", "Gripper", "Table"].iter().flat_map(|a| {
        ["position", "velocity", "acceleration"]
            .iter()
            .map(move |q| format!("axis.{a}.{q}"))
    }))
    .collect::<Vec<_>>()
    .join(",");
    let (trace, stderr) = run_traced_files(&[&fixture("Arrays.st")], 150, &watch);
    assert!(!stderr.contains("error"), "{stderr}");
    let col = |a: &str, q: &str| column(&trace, &format!("axis.{a}.{q}"));
    let last = |a: &str| *col(a, "position").last().unwrap();
    // each axis at its own element's target
    assert!((last("Lift") - 40.0).abs() < 1e-6, "{}", last("Lift"));
    assert!((last("Slide") + 30.0).abs() < 1e-6, "{}", last("Slide"));
    assert!((last("Gripper") - 25.0).abs() < 1e-6, "{}", last("Gripper"));
    // MC_MoveModulo to 270 deg in MC_Negative_Direction from 0: 90 deg backward
    assert!((last("Table") - 270.0).abs() < 1e-6, "{}", last("Table"));
    assert!(col("Table", "velocity").iter().all(|&v| v <= 0.0));
    // the limits of each axis hold; the Gripper's element has 50 % override: 40 of its 80 mm/s
    for (a, v, acc) in [
        ("Lift", 100.0, 1000.0),
        ("Slide", 50.0, 500.0),
        ("Gripper", 40.0, 800.0),
        ("Table", 180.0, 900.0),
    ] {
        assert!(within(&col(a, "velocity"), -v, v), "{a} velocity");
        assert!((peak(&col(a, "velocity")) - v).abs() < EPS, "{a} peak");
        assert!(
            within(&col(a, "acceleration"), -acc, acc),
            "{a} acceleration"
        );
    }
    // the Slide accelerates at its 250 and brakes at its 500
    assert!(peak(&col("Slide", "acceleration")) <= 500.0 + 1e-6);
    // Done per element, when its axis arrives: Lift (40 mm at 100) first, Slide (30 at 50) last
    let done = |k: usize| column(&trace, &format!("MAIN.aDone[{k}]"));
    let first = |v: &[f64]| v.iter().position(|&x| x == 1.0).unwrap();
    let lift_at = col("Lift", "position")
        .iter()
        .position(|&p| (p - 40.0).abs() < 1e-9)
        .unwrap();
    assert!(first(&done(1)) >= lift_at && first(&done(1)) <= lift_at + 1);
    assert!(first(&done(1)) < first(&done(3)) && first(&done(3)) < first(&done(2)));
    assert_eq!(column(&trace, "MAIN.fbMove[1].Done"), done(2));
    // Busy while its own axis moves, not another's
    let busy2 = column(&trace, "MAIN.aBusy[2]");
    let busy1 = column(&trace, "MAIN.aBusy[1]");
    let k = first(&done(1)) + 2;
    assert_eq!((busy1[k], busy2[k]), (0.0, 1.0));
    assert_eq!(column(&trace, "MAIN.nDone").last(), Some(&3.0));
    assert_eq!(column(&trace, "MAIN.bModDone").last(), Some(&1.0));
}

/// `stations : ARRAY[1..3] OF FB_Station`, each FB_Station with its own `AXIS_REF` and PLCopen
/// `MC_Power` / `MC_MoveAbsolute` (spelled `EnablePositive`), linked `MAIN.stations[k].Axis` in
/// the axes file: each station's axis goes to 15 k mm when its start comes (20 cycles apart), at
/// its own limits (1000 mm/s asked).
#[test]
fn motion_blocks_in_an_array_of_function_blocks_one_axis_each() {
    let watch = "MAIN.nInPos,MAIN.stations[2].bMoving,MAIN.stations[2].bInPos,\
                 axis.Feeder.position,axis.Feeder.velocity,axis.Press.position,\
                 axis.Press.velocity,axis.Press.acceleration,axis.Stacker.position,\
                 axis.Stacker.velocity";
    let (trace, stderr) = run_traced_files(&[&fixture("Stations.st")], 200, watch);
    assert!(!stderr.contains("error"), "{stderr}");
    let pos = |a: &str| column(&trace, &format!("axis.{a}.position"));
    let vel = |a: &str| column(&trace, &format!("axis.{a}.velocity"));
    let moved = |a: &str| pos(a).iter().position(|&p| p != 0.0).unwrap();
    // each starts with its own station's start: 0, 20, 40 cycles
    assert!(moved("Feeder") < 3);
    assert!((20..23).contains(&moved("Press")), "{}", moved("Press"));
    assert!((40..43).contains(&moved("Stacker")), "{}", moved("Stacker"));
    for (a, target, v) in [
        ("Feeder", 15.0, 60.0),
        ("Press", 30.0, 30.0),
        ("Stacker", 45.0, 90.0),
    ] {
        assert!((pos(a).last().unwrap() - target).abs() < 1e-6, "{a}");
        assert!(within(&vel(a), 0.0, v), "{a} velocity");
        assert!((peak(&vel(a)) - v).abs() < EPS, "{a} peak");
    }
    // the Press brakes at its 150 mm/s², accelerates at its 300
    let acc = column(&trace, "axis.Press.acceleration");
    assert!(within(&acc, -150.0, 300.0));
    assert!(acc.contains(&-150.0) && acc.contains(&300.0));
    // station 2's Busy and Done are its own
    let busy = column(&trace, "MAIN.stations[2].bMoving");
    let done = column(&trace, "MAIN.stations[2].bInPos");
    let press = pos("Press");
    let arrived = press.iter().position(|&p| (p - 30.0).abs() < 1e-9).unwrap();
    assert_eq!(busy[moved("Press")], 1.0);
    assert_eq!(busy[arrived + 2], 0.0);
    assert_eq!(done[arrived + 2], 1.0);
    assert_eq!(done[moved("Press")], 0.0);
    assert_eq!(column(&trace, "MAIN.nInPos").last(), Some(&3.0));
}

/// The travel of a modulo axis from its wrapped positions (each step taken the short way).
fn unwrapped(pos: &[f64], period: f64) -> Vec<f64> {
    let mut out = vec![pos[0]];
    for w in pos.windows(2) {
        let d = (w[1] - w[0] + period / 2.0).rem_euclid(period) - period / 2.0;
        out.push(out.last().unwrap() + d);
    }
    out
}

/// MC_MoveModulo queued (Infosys, Tc2_MC2 > MC_MoveModulo: a start with MC_Buffered is a start
/// from standstill): m2 (MC_Buffered, 180 deg) issued while m1 turns to 90 deg starts where m1
/// ends and goes 90 deg further (before: measured from where the axis was when m2 was issued, it
/// stopped at 262 deg); m3 (MC_BlendingLow, 405 deg: one full turn and 45) blends onto m2 at 180
/// deg without stopping and ends at 45 deg after 585 deg; the axis's 360 deg/s (720 asked) and
/// 1800 deg/s² hold. m4 and m5 ask queued full turns the shortest way and in the current
/// direction (which only the end of the queue decides): ErrorID 25, no motion.
#[test]
fn a_buffered_mc_move_modulo_measures_from_the_end_of_the_queue() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("Buffered.st")],
        400,
        "MAIN.m1.Done,MAIN.m2.Done,MAIN.m2.Busy,MAIN.m2.Active,MAIN.m3.Done,MAIN.m3.Active,\
         MAIN.m4.Error,MAIN.m4.ErrorID,MAIN.m5.ErrorID,axis.T.position,axis.T.velocity,\
         axis.T.acceleration",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let pos = column(&trace, "axis.T.position");
    let vel = column(&trace, "axis.T.velocity");
    let travel = unwrapped(&pos, 360.0);
    let first = |c: &str| {
        column(&trace, c)
            .iter()
            .position(|&x| x == 1.0)
            .unwrap_or_else(|| panic!("{c} never rises"))
    };
    // m1 ends at 90, at standstill (m2 may start within the same cycle: the engine runs into
    // the successor); m2 is Busy (queued) before, Active only after
    let m1 = first("MAIN.m1.Done");
    assert!(travel[m1 - 1] <= 90.0 + 1e-6 && travel[m1] >= 90.0 - 1e-6);
    assert!(vel[m1 - 1] + vel[m1] < 2.0 * 1800.0 * 0.01, "no stop at 90");
    assert!(first("MAIN.m2.Busy") < m1);
    assert!(first("MAIN.m2.Active") >= m1 - 1);
    // m2 ends 90 further, at 180, passed at speed (m3 blends onto it)
    let m2 = first("MAIN.m2.Done");
    assert!(travel[m2 - 1] <= 180.0 + 1e-6 && travel[m2] >= 180.0 - 1e-6);
    assert!(vel[m2] > 100.0, "{}", vel[m2]);
    // m3: 225 to 45 and one full turn, blended: no stop after m2's start until the end
    let m3 = first("MAIN.m3.Done");
    assert!((travel[m3] - 765.0).abs() < 1e-6, "{}", travel[m3]);
    assert!((pos[m3] - 45.0).abs() < 1e-6, "{}", pos[m3]);
    let started2 = (m1..).find(|&k| vel[k] > 0.0).unwrap();
    assert!(
        vel[started2..m3 - 1].iter().all(|&v| v > 0.0),
        "a stop inside"
    );
    // the limits hold; 720 asked of m3, 360 run
    assert!(within(&vel, 0.0, 360.0));
    assert!((peak(&vel) - 360.0).abs() < EPS);
    assert!(within(
        &column(&trace, "axis.T.acceleration"),
        -1800.0,
        1800.0
    ));
    // m4, m5: refused, the axis stays at 45
    assert_eq!(column(&trace, "MAIN.m4.Error")[380], 1.0);
    assert_eq!(column(&trace, "MAIN.m4.ErrorID")[380], 25.0);
    assert_eq!(column(&trace, "MAIN.m5.ErrorID")[380], 25.0);
    assert!(pos[m3..].iter().all(|&p| (p - 45.0).abs() < 1e-6));
}

/// MC_Jog in MC_JOGMODE_INCHING_MODULO (Infosys, E_JogMode: "stop position is rounded to the
/// distance value"): from 22.5 mm with Position 10, forward to 30 then 40, backward to 30 then
/// 20, each step Done at a multiple of 10 (before: Error, ErrorID 32, no motion); 80 mm/s asked,
/// the axis's 50 run, the block's 400 / 800 mm/s² held. A Position of 0: ErrorID 24, no motion.
#[test]
fn inching_modulo_steps_stop_on_multiples_of_the_step() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("Inching.st")],
        330,
        "MAIN.fbJog.Done,MAIN.fbJog.Busy,MAIN.fbJog.Error,MAIN.fbJog.ErrorID,axis.X.position,\
         axis.X.velocity,axis.X.acceleration",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let pos = column(&trace, "axis.X.position");
    let vel = column(&trace, "axis.X.velocity");
    let done = column(&trace, "MAIN.fbJog.Done");
    // standing before each edge (cycles 60, 120, 180, 240 are rows 59 ...), and where each step ends
    for (row, before, after) in [
        (59, 22.5, 30.0),
        (119, 30.0, 40.0),
        (179, 40.0, 30.0),
        (239, 30.0, 20.0),
    ] {
        assert!(
            (pos[row - 1] - before).abs() < 1e-6,
            "{row}: {}",
            pos[row - 1]
        );
        assert!(
            (pos[row + 55] - after).abs() < 1e-6,
            "{row}: {}",
            pos[row + 55]
        );
        assert_eq!(done[row + 55], 1.0, "{row}");
        assert_eq!(done[row + 1], 0.0, "{row}");
        // the step runs the jog's way only
        let sign = (after - before).signum();
        assert!(vel[row..row + 55].iter().all(|&v| v * sign >= 0.0));
    }
    assert_eq!(column(&trace, "MAIN.fbJog.Busy")[70], 1.0);
    assert!(within(&vel, -50.0, 50.0) && (peak(&vel) - 50.0).abs() < EPS);
    let acc = column(&trace, "axis.X.acceleration");
    // the block's 400 up and 800 down during the steps (the first move, MC_MoveAbsolute, takes
    // the axis's 1000)
    assert!(within(&acc[59..], -800.0, 800.0));
    assert!(acc[59..].contains(&400.0) && acc[59..].contains(&-400.0));
    // Position 0: refused, the axis stays at 20
    assert_eq!(column(&trace, "MAIN.fbJog.Error")[299], 1.0);
    assert_eq!(column(&trace, "MAIN.fbJog.ErrorID")[299], 24.0);
    assert!(pos[280..].iter().all(|&p| (p - 20.0).abs() < 1e-6));
}

/// A TwinCAT project laid out as zhaoshutao/PWFACLM_PLC's collimator is (our own code):
/// `GVL.axisRefs : ARRAY[1..cMaxAxes] OF AXIS_REF`, `fbAxes : ARRAY[1..GVL.cMaxAxes] OF
/// FB_AxisControl` (each with `VAR_IN_OUT Axis : AXIS_REF` and its own MC_Power and
/// MC_MoveAbsolute, instances named like their types), `mcSetPos : ARRAY[1..GVL.cMaxAxes] OF
/// MC_SetPosition` whose inputs are written as `mcSetPos[_i].Position := ...`, and the axes' members
/// read per element: `GVL.axisRefs[_i].NcToPlc.ActPos` / `ActVelo` (before: E1021 "AXIS_REF has no
/// field NcToPlc"), `Axis.Status.Moving` inside the array's FB. Each axis is set to 5 mm, then
/// moves to its own target within its own limits (500 mm/s asked).
#[test]
fn an_array_of_axes_in_a_global_list_read_and_driven_element_by_element() {
    let watch = "GVL.bInit,GVL.aActPos[1],GVL.aActPos[2],GVL.aActPos[3],GVL.aActVelo[2],\
                 GVL.aMoving[2],MAIN.fbAxes[2].bDone,axis.Jaw1.position,axis.Jaw2.position,\
                 axis.Jaw3.position,axis.Jaw1.velocity,axis.Jaw2.velocity,axis.Jaw3.velocity";
    let (trace, stderr) =
        run_traced_files(&[&fixture("Collimator/Collimator.plcproj")], 200, watch);
    assert!(!stderr.contains("error"), "{stderr}");
    for (k, axis, target, v) in [
        (1, "Jaw1", 12.0, 40.0),
        (2, "Jaw2", -8.0, 20.0),
        (3, "Jaw3", 30.0, 60.0),
    ] {
        let pos = column(&trace, &format!("axis.{axis}.position"));
        let vel = column(&trace, &format!("axis.{axis}.velocity"));
        // MC_SetPosition per element: each starts from 5 mm (set in cycle 1, moving from there)
        assert_eq!(pos[0], 0.0);
        assert!((pos[1] - 5.0).abs() < 0.1, "{axis} {}", pos[1]);
        assert!((pos.last().unwrap() - target).abs() < 1e-6, "{axis}");
        assert!(
            within(&vel, -v, v) && (peak(&vel) - v).abs() < EPS,
            "{axis}"
        );
        // `GVL.axisRefs[k].NcToPlc.ActPos` is this axis's position as of the scan's start
        let act = column(&trace, &format!("GVL.aActPos[{k}]"));
        for c in 1..pos.len() {
            assert!((act[c] - pos[c - 1]).abs() < 1e-9, "{axis} cycle {c}");
        }
    }
    let velo = column(&trace, "GVL.aActVelo[2]");
    let vel2 = column(&trace, "axis.Jaw2.velocity");
    assert!((1..vel2.len()).all(|c| (velo[c] - vel2[c - 1]).abs() < 1e-9));
    // Status.Moving of the second FB's own axis, and its Done
    let moving = column(&trace, "GVL.aMoving[2]");
    let done = column(&trace, "MAIN.fbAxes[2].bDone");
    assert_eq!(moving[40], 1.0);
    assert_eq!((moving[150], done[150]), (0.0, 1.0));
    assert_eq!(done[40], 0.0);
}

/// Both of paper A's lowering methods call the element the index names: `Arrays.st` run with
/// `--strategy il` (TM transfers of `fbMove[i - 1]`'s fields, one static function) and with
/// `--strategy template` (one synthesised function per call site, reading the element's fields)
/// traces the same axes, cycle by cycle, each axis at its own target.
#[test]
fn both_lowering_methods_call_the_element_the_index_names() {
    let run = |strategy: &str| {
        let out = common::ladderc()
            .args(["--message-format", "short", "run"])
            .arg(fixture("Arrays.st"))
            .args(["--strategy", strategy, "--cycles", "150", "--sanitize"])
            .args(["--trace", "-", "--watch"])
            .arg(
                "axis.Lift.position,axis.Slide.position,axis.Gripper.position,\
                 axis.Table.position,MAIN.nDone",
            )
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
        assert_eq!(out.status.code(), Some(0), "{strategy}: {stderr}");
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let (il, template) = (run("il"), run("template"));
    assert_eq!(il, template);
    for (a, target) in [
        ("Lift", 40.0),
        ("Slide", -30.0),
        ("Gripper", 25.0),
        ("Table", 270.0),
    ] {
        let last = *column(&il, &format!("axis.{a}.position")).last().unwrap();
        assert!((last - target).abs() < 1e-6, "{a}: {last}");
    }
    assert_eq!(column(&il, "MAIN.nDone").last(), Some(&3.0));
}

/// `axes : ARRAY[0..2] OF AXIS_REF` whose elements' members are read in a FOR loop as a scope
/// trigger (the pattern of ta-ichihashi/TwinCATHowTo's Scope view example):
/// `axes[i].Status.InTargetPosition` (Infosys, ST_AxisStatus: in the target position window; the
/// simulated drive follows its set point exactly, so: standing with no motion) and
/// `axes[i].NcToPlc.SetPos`. Before: a program whose only motion declarations are arrays was not
/// read as a motion program (E1003 `AXIS_REF`, `MC_Power`, `MC_MoveAbsolute`).
#[test]
fn members_of_axis_array_elements_trigger_per_axis() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("Trigger.st")],
        60,
        "MAIN.export_trigger[0],MAIN.export_trigger[1],MAIN.export_trigger[2],\
         MAIN.aInTarget[0],MAIN.aInTarget[2],axis.X.position,axis.Z.position,axis.Z.velocity",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let x = column(&trace, "axis.X.position");
    let z = column(&trace, "axis.Z.position");
    let zv = column(&trace, "axis.Z.velocity");
    // in target exactly when its own axis stands at its goal (read as of the scan's start)
    let at_x = x.iter().position(|&p| (p - 20.0).abs() < 1e-9).unwrap();
    let at_z = z.iter().position(|&p| (p + 20.0).abs() < 1e-9).unwrap();
    let in0 = column(&trace, "MAIN.aInTarget[0]");
    let in2 = column(&trace, "MAIN.aInTarget[2]");
    assert!(in0[..=at_x].iter().all(|&b| b == 0.0));
    assert!(in0[at_x + 2..].iter().all(|&b| b == 1.0));
    assert!(in2[..=at_z].iter().all(|&b| b == 0.0));
    assert!(in2[at_z + 2..].iter().all(|&b| b == 1.0));
    assert!(at_z > at_x, "Z runs at its 50 mm/s");
    assert!(within(&zv, -50.0, 0.0) && (peak(&zv) - 50.0).abs() < EPS);
    // the trigger: in target with the set position 0 (only the second axis, whose goal is 0)
    assert!(column(&trace, "MAIN.export_trigger[0]")
        .iter()
        .all(|&b| b == 0.0));
    assert!(column(&trace, "MAIN.export_trigger[2]")
        .iter()
        .all(|&b| b == 0.0));
    assert!(column(&trace, "MAIN.export_trigger[1]")[1..]
        .iter()
        .all(|&b| b == 1.0));
}

/// Tc2_MC2's `NcToPlc.ErrorCode` (UDINT, 0 while the axis has no error; zhaoshutao's projects
/// test `IF Axis.NcToPlc.ErrorCode = 0`, before: E1042) of each element of an array of axes: the
/// Lift runs into its positive software limit (20 mm) and stops there, its ErrorCode is the axis
/// error (100, SoftwareLimitPositive) until MC_Reset; the Feed's stays 0.
#[test]
fn nc_to_plc_error_code_reads_each_axis_s_own_error() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("ErrorCode.st")],
        200,
        "MAIN.aCode[1],MAIN.aCode[2],MAIN.aFault[2],axis.Lift.position,axis.Lift.velocity",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    let pos = column(&trace, "axis.Lift.position");
    let code = column(&trace, "MAIN.aCode[2]");
    assert!(within(&pos, -10.0, 20.0), "the software limit holds");
    let stopped = pos.iter().position(|&p| (p - 20.0).abs() < 1e-9).unwrap();
    assert!(code[..stopped].iter().all(|&c| c == 0.0));
    assert!(code[stopped + 2..150].iter().all(|&c| c == 100.0));
    assert_eq!(column(&trace, "MAIN.aFault[2]")[120], 1.0);
    // MC_Reset (cycle 151) clears it
    assert!(code[155..].iter().all(|&c| c == 0.0));
    assert!(column(&trace, "MAIN.aCode[1]").iter().all(|&c| c == 0.0));
}

/// PLCopen MC_GearOut (before: no such block, E1003; SeanyCash/TwinCAT_CNC declares one) per
/// element of an array: two slaves geared 1:2 to a master at 40 mm/s run at 20; slave 1 geared
/// out at cycle 101 keeps its 20 mm/s (ContinuousMotion) when the master goes to 80 at cycle 121,
/// slave 2, still geared, follows to 40; the limits hold.
#[test]
fn mc_gear_out_releases_its_own_slave_only() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("GearOut.st")],
        200,
        "MAIN.gin[1].InGear,MAIN.gin[2].InGear,MAIN.gout[1].Done,MAIN.gout[2].Done,\
         MAIN.gout[2].Busy,axis.M.velocity,axis.S1.velocity,axis.S2.velocity,\
         axis.S1.acceleration,axis.S2.acceleration",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    let s1 = column(&trace, "axis.S1.velocity");
    let s2 = column(&trace, "axis.S2.velocity");
    let m = column(&trace, "axis.M.velocity");
    assert_eq!((m[95], s1[95], s2[95]), (40.0, 20.0, 20.0));
    let done1 = column(&trace, "MAIN.gout[1].Done");
    assert_eq!(done1[99], 0.0);
    assert!(done1[101..].iter().all(|&d| d == 1.0));
    assert!(column(&trace, "MAIN.gin[1].InGear")[101..]
        .iter()
        .all(|&g| g == 0.0));
    // after the master's change: slave 1 stays at 20, slave 2 follows at half the master's 80
    assert!(s1[100..].iter().all(|&v| (v - 20.0).abs() < EPS));
    assert_eq!((m[199], s2[199]), (80.0, 40.0));
    assert!(column(&trace, "MAIN.gin[2].InGear")[150..]
        .iter()
        .all(|&g| g == 1.0));
    assert!(column(&trace, "MAIN.gout[2].Done")
        .iter()
        .all(|&d| d == 0.0));
    for a in ["S1", "S2"] {
        let acc = column(&trace, &format!("axis.{a}.acceleration"));
        assert!(within(&acc, -1000.0, 1000.0), "{a}");
    }
}

/// A motion block instance held in a structure field, also of an array of structures, is one
/// located E1053 per call (before: an E1018 "`st` is MC_Power, not an FB instance" from the check
/// of the lowered program, as if the user's program were wrong); an array of arrays of instances
/// is called like an array (`pw[1][i](...)`) and runs.
#[test]
fn a_motion_block_inside_a_structure_is_one_e1053_an_array_of_arrays_runs() {
    let src = "TYPE ST_Axis :\nSTRUCT\n  pw : MC_Power;\nEND_STRUCT;\nEND_TYPE\n\
               FUNCTION_BLOCK FB_Station\nVAR_IN_OUT\n  ax : AXIS_REF;\nEND_VAR\n\
               VAR\n  st : ST_Axis;\n  ast : ARRAY[1..2] OF ST_Axis;\n  i : INT := 1;\nEND_VAR\n\
               st.pw(Axis := ax, Enable := TRUE);\n\
               ast[i].pw(Axis := ax, Enable := TRUE);\nEND_FUNCTION_BLOCK\n";
    let heads = common::rejected_heads("Station.st", src);
    assert_eq!(
        heads,
        [
            "Station.st:15:1: error[E1053]: `st.pw` is an instance of MC_Power inside a \
             structure: ladderc calls motion blocks declared in a POU, a global list or an array",
            "Station.st:16:1: error[E1053]: `ast[..].pw` is an instance of MC_Power inside a \
             structure: ladderc calls motion blocks declared in a POU, a global list or an array",
        ]
    );
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("Grid.st");
    std::fs::write(
        &f,
        "PROGRAM MAIN\nVAR\n  axes : ARRAY[1..2] OF AXIS_REF;\n\
         pw : ARRAY[1..2] OF ARRAY[1..2] OF MC_Power;\n\
         mv : ARRAY[1..2] OF ARRAY[1..2] OF MC_MoveRelative;\n  i : INT;\nEND_VAR\n\
         FOR i := 1 TO 2 DO\n\
         pw[2][i](Axis := axes[i], Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE);\n\
         mv[2][i](Axis := axes[i], Execute := pw[2][i].Status, Distance := 5.0 * INT_TO_LREAL(i),\n\
         Velocity := 100.0, Acceleration := 1000.0, Deceleration := 1000.0);\nEND_FOR\nEND_PROGRAM\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("Grid.axes.json"),
        r#"{ "cycle_ms": 10, "axes": [
            { "name": "A", "velocity": 50, "acceleration": 500, "deceleration": 500, "link": "MAIN.axes[1]" },
            { "name": "B", "velocity": 50, "acceleration": 500, "deceleration": 500, "link": "MAIN.axes[2]" } ] }"#,
    )
    .unwrap();
    let (trace, stderr) = run_traced_files(
        &[&f],
        60,
        "axis.A.position,axis.B.position,MAIN.mv[2][2].Done,MAIN.mv[1][1].Busy",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert!((column(&trace, "axis.A.position").last().unwrap() - 5.0).abs() < 1e-9);
    assert!((column(&trace, "axis.B.position").last().unwrap() - 10.0).abs() < 1e-9);
    assert_eq!(column(&trace, "MAIN.mv[2][2].Done").last(), Some(&1.0));
    assert!(column(&trace, "MAIN.mv[1][1].Busy")
        .iter()
        .all(|&b| b == 0.0));
}

/// A member of an `ARRAY OF AXIS_REF` element read with the wrong number of indexes is reported
/// on the user's names (E1021 at `axes`), never on the hidden blocks that read the members.
#[test]
fn a_wrong_index_count_on_an_axis_array_names_the_user_s_array() {
    let src =
        "PROGRAM MAIN\nVAR\n  axes : ARRAY[1..2] OF AXIS_REF;\n  pw : ARRAY[1..2] OF MC_Power;\n\
               b : BOOL;\nEND_VAR\npw[1](Axis := axes[1], Enable := TRUE);\n\
               b := axes[1, 2].Status.Error;\nEND_PROGRAM\n";
    let heads = common::rejected_heads("Axes.st", src);
    assert!(heads.iter().all(|h| !h.contains("__TC2")), "{heads:?}");
    assert!(
        heads.contains(
            &"Axes.st:8:6: error[E1021]: `axes` has 1 dimension(s) but 2 index(es) are given"
                .to_string()
        ),
        "{heads:?}"
    );
}
