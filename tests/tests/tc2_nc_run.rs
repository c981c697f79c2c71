//! TwinCAT solutions as they are written (issue #13): without an axes file, `ladderc run` takes
//! the axes from the solution's NC configuration (`_Config/NC`, or inside the `.tsproj`), links
//! each to the PLC `AXIS_REF` its "Link To PLC" mapping names, and the simulated axes honour the
//! NC's limits (`crates/ladderc/src/nc_axes.rs`). The solution under `fixtures/tc2_nc/Cell/` is
//! written for these tests in the format of the public solutions read for them (README there).

mod common;
use common::{column, ladderc, run_traced_files};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/tc2_nc")
        .join(rel)
}

const WATCH: &str = "MAIN.nState,MAIN.bTableDone,MAIN.bLiftDone,MAIN.bLiftError,\
                     MAIN.nLiftErrorID,MAIN.rLiftPos,axis.Lift.position,axis.Lift.velocity,\
                     axis.Lift.acceleration,axis.Table_Axis.position,axis.Table_Axis.velocity,\
                     axis.Table_Axis.acceleration";

/// A copy of the `Cell` solution in a temporary folder, for the tests that change it.
fn copy_of_cell() -> tempfile::TempDir {
    common::copy_of_folder(&fixture("Cell"))
}

fn max(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::MIN, f64::max)
}

fn min(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::MAX, f64::min)
}

/// The NC limits of `Lift.xti` hold on the trace: 150 mm/s (400 asked), the standard dynamics
/// 500 / 250 mm/s² for the Acceleration and Deceleration the program leaves out (below the NC's
/// maxima 800 / 400), the software limit at 300 mm (a move to 400 mm is refused, the axis stays).
/// `Table Axis.xti` gives only `Velo Maximum="90"`: 90 mm/s, and TwinCAT's default 15000 mm/s²
/// caps the program's 100000. Each NC axis moves its own PLC `AXIS_REF`, as the mappings link
/// them (`GVL_Axes.LiftAxis`, `MAIN.Table`); the axis names become trace names (`Table_Axis`).
#[test]
fn nc_axes_of_the_solution_are_the_simulated_axes_with_their_limits() {
    let (trace, stderr) = run_traced_files(&[&fixture("Cell/Cell/Cell.plcproj")], 400, WATCH);
    assert!(!stderr.contains("error"), "{stderr}");
    let (lv, la, lp) = (
        column(&trace, "axis.Lift.velocity"),
        column(&trace, "axis.Lift.acceleration"),
        column(&trace, "axis.Lift.position"),
    );
    assert!((max(&lv) - 150.0).abs() < 1e-9, "{}", max(&lv));
    assert!(min(&lv) >= -1e-9);
    assert!((max(&la) - 500.0).abs() < 1e-9, "{}", max(&la));
    assert!((min(&la) + 250.0).abs() < 1e-9, "{}", min(&la));
    assert!(max(&lp) <= 300.0, "{}", max(&lp));
    let done = column(&trace, "MAIN.bTableDone");
    let at = done
        .iter()
        .position(|&d| d == 1.0)
        .expect("both moves Done");
    assert!(
        (lp[at] - 280.0).abs() < 1e-9 && (column(&trace, "MAIN.rLiftPos")[at] - 280.0).abs() < 1e-9
    );
    // the move beyond the software limit: Error, the axis stays at 280 mm
    let err = column(&trace, "MAIN.bLiftError");
    assert_eq!(*err.last().unwrap(), 1.0);
    assert!(column(&trace, "MAIN.nLiftErrorID").last().unwrap() > &0.0);
    assert!(column(&trace, "MAIN.bLiftDone").iter().all(|&d| d == 0.0));
    assert!((lp.last().unwrap() - 280.0).abs() < 1e-9);
    let (tv, ta, tp) = (
        column(&trace, "axis.Table_Axis.velocity"),
        column(&trace, "axis.Table_Axis.acceleration"),
        column(&trace, "axis.Table_Axis.position"),
    );
    assert!((max(&tv) - 90.0).abs() < 1e-9, "{}", max(&tv));
    assert!(max(&ta) <= 15000.0 + 1e-6 && min(&ta) >= -15000.0 - 1e-6);
    assert!((tp[at] - 100.0).abs() < 1e-9);
    // one located note names what `Table Axis.xti` does not give, with the defaults used
    let note = stderr
        .lines()
        .find(|l| l.contains("W1428"))
        .expect("W1428 note");
    assert!(
        note.contains("_Config/NC/Axes/Table Axis.xti:3:2: note[W1428]")
            && note.contains("acceleration 15000")
            && note.contains("jerk 2250000"),
        "{note}"
    );
    assert_eq!(stderr.matches("[W1428]").count(), 1, "{stderr}");
}

/// `--axes FILE` replaces the NC configuration (documented precedence: `--axes`, then
/// `<stem>.axes.json`, then `_Config/NC`): its 50 mm/s axis is the lift, and no NC file is read.
#[test]
fn an_axes_file_given_replaces_the_nc_configuration() {
    let dir = tempfile::tempdir().unwrap();
    let axes = dir.path().join("cell.axes.json");
    std::fs::write(
        &axes,
        r#"{ "axes": [
  { "name": "Lift", "velocity": 50, "acceleration": 1000, "deceleration": 1000,
    "link": "GVL_Axes.LiftAxis" },
  { "name": "Table_Axis", "velocity": 40, "acceleration": 1000, "deceleration": 1000,
    "link": "MAIN.Table" } ] }"#,
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture("Cell/Cell/Cell.plcproj"))
        .arg("--axes")
        .arg(&axes)
        .args(["--cycles", "300", "--trace", "-", "--watch", WATCH])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("W1428"), "{stderr}");
    let trace = String::from_utf8_lossy(&out.stdout);
    assert!((max(&column(&trace, "axis.Lift.velocity")) - 50.0).abs() < 1e-9);
    assert!((max(&column(&trace, "axis.Table_Axis.velocity")) - 40.0).abs() < 1e-9);
}

/// The NC configuration inside the `.tsproj` (as TwinCAT 3.1.4022 and earlier save it, or with
/// "independent files" off): `<NC>` holds the `<Axis>` elements with their names and parameters,
/// and the mapping's owners are the other way round (`OwnerA` the PLC instance, `OwnerB` the
/// axis). The same limits hold; the folder holding the `.tsproj` is given instead of the
/// `.plcproj`.
#[test]
fn nc_axes_inside_the_tsproj_are_read_too() {
    let dir = copy_of_cell();
    let lift = std::fs::read_to_string(dir.path().join("_Config/NC/Axes/Lift.xti")).unwrap();
    let table = std::fs::read_to_string(dir.path().join("_Config/NC/Axes/Table Axis.xti")).unwrap();
    let axis = |xti: &str, name: &str| -> String {
        let s = xti.find("<Axis ").unwrap();
        let e = xti.find("</Axis>").unwrap() + "</Axis>".len();
        xti[s..e].replace("__FILENAME__", name)
    };
    let tsproj = dir.path().join("Cell.tsproj");
    let text = std::fs::read_to_string(&tsproj).unwrap().replace(
        "<NC File=\"NC.xti\"/>",
        &format!(
            "<NC>\n<SafTask Priority=\"4\" CycleTime=\"20000\"><Name>NC-Task 1 SAF</Name></SafTask>\n{}\n{}\n</NC>",
            axis(&lift, "Lift"),
            axis(&table, "Table Axis")
        ),
    );
    std::fs::write(&tsproj, text).unwrap();
    std::fs::remove_dir_all(dir.path().join("_Config")).unwrap();
    let (trace, stderr) = run_traced_files(&[dir.path()], 400, WATCH);
    assert!(!stderr.contains("error"), "{stderr}");
    assert!((max(&column(&trace, "axis.Lift.velocity")) - 150.0).abs() < 1e-9);
    assert!((max(&column(&trace, "axis.Table_Axis.velocity")) - 90.0).abs() < 1e-9);
    assert!(
        stderr.contains("Cell.tsproj") && stderr.contains("note[W1428]"),
        "{stderr}"
    );
}

/// An axis file the NC configuration names but the solution lacks: one located E1047 (exit 1),
/// not an axis silently left out; a value that is no number: one located W1428 warning, the
/// default used.
#[test]
fn a_missing_nc_file_is_e1047_and_an_unreadable_value_w1428() {
    let dir = copy_of_cell();
    std::fs::remove_file(dir.path().join("_Config/NC/Axes/Table Axis.xti")).unwrap();
    let (code, stderr) = common::check_stderr(&dir.path().join("Cell/Cell.plcproj"));
    assert_eq!(code, Some(1), "{stderr}");
    let e = stderr.lines().find(|l| l.contains("E1047")).expect("E1047");
    assert!(
        e.contains("_Config/NC/NC.xti:17:15: error[E1047]") && e.contains("Table Axis.xti"),
        "{e}"
    );
    assert_eq!(stderr.matches("error[").count(), 1, "{stderr}");

    let dir = copy_of_cell();
    let lift = dir.path().join("_Config/NC/Axes/Lift.xti");
    let text = std::fs::read_to_string(&lift)
        .unwrap()
        .replace("Maximum=\"150\"", "Maximum=\"fast\"");
    std::fs::write(&lift, text).unwrap();
    let (trace, stderr) = run_traced_files(&[&dir.path().join("Cell/Cell.plcproj")], 200, WATCH);
    let w = stderr
        .lines()
        .find(|l| l.contains("warning[W1428]"))
        .expect("W1428 warning");
    assert!(
        w.contains("Lift.xti:8:") && w.contains("Velo Maximum"),
        "{w}"
    );
    assert_eq!(stderr.matches("[W1428]").count(), 2, "{stderr}");
    // TwinCAT's default maximum velocity, 2000 mm/s, instead of the 150 mm/s it could not read
    assert!(max(&column(&trace, "axis.Lift.velocity")) > 150.0 + 1.0);
}

const PRESS: &str =
    "MAIN.nStep,MAIN.bHomed,MAIN.rPos,MAIN.nStateDWord,MAIN.bHasJob,MAIN.bPositive,\
                     MAIN.bOperational,MAIN.rPosDiff,MAIN.rTorque,MAIN.nCouple,MAIN.bBitHomed,\
                     MAIN.bHomeError,MAIN.nHomeErrorID,MAIN.nAxisId,axis.Press.position,\
                     axis.Press.velocity,axis.Press.acceleration";

/// Tc2_MC2's MC_Home with each HomingMode on the `Press` solution (its NC axis inside the
/// `.tsproj`, linked to `MAIN.fbStation.Axis`), and the AXIS_REF members real code reads, each
/// from the simulated axis: not homed at the start; `MC_AbsoluteHoming` sets 50 mm without motion
/// and homes; the move to 120 mm keeps the NC's 100 mm/s and 1000 mm/s² (80 mm/s asked) while
/// `Status.HasJob`, `PositiveDirection` and the state word's bits say so; `MC_RelativeHoming`
/// shifts by 10 mm (130); `MC_ResetCalibration` / `MC_ForceCalibration` clear and set `Homed`
/// without motion; `MC_DefaultHoming` with `DEFAULT_HOME_POSITION` homes to the calibration value
/// 0; `MC_AbsoluteHoming` without a position is ErrorID 24. `PosDiff` is 0 (the drive follows
/// exactly), `ActTorque` 0 with one W1429 note, `CoupleState` 0 (a single axis), `AxisId` the NC
/// axis's `Id` (4).
#[test]
fn tc2_homing_modes_and_axis_ref_members_follow_the_simulated_axis() {
    let (trace, stderr) = run_traced_files(&[&fixture("Press/Press/Press.plcproj")], 200, PRESS);
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(stderr.matches("note[W1429]").count(), 1, "{stderr}");
    let step = column(&trace, "MAIN.nStep");
    let homed = column(&trace, "MAIN.bHomed");
    let pos = column(&trace, "axis.Press.position");
    let word = column(&trace, "MAIN.nStateDWord");
    let first = |s: f64| step.iter().position(|&x| x == s).unwrap();
    // powered, not homed: Operational (bit 0), NotMoving (2), in position (3, 4), loop closed (20)
    assert_eq!(homed[0], 0.0);
    assert_eq!(word[1] as u32, 1 | 4 | 8 | 16 | 1 << 20);
    // absolute homing: 50 mm, homed, no motion
    let moving = first(20.0);
    assert!((pos[moving] - 50.0).abs() < 1e-9 && homed[moving] == 1.0);
    assert!(column(&trace, "axis.Press.velocity")[..moving]
        .iter()
        .all(|&v| v == 0.0));
    // the move: within the NC's limits; the state word of an axis moving forward, homed
    let vel = column(&trace, "axis.Press.velocity");
    let acc = column(&trace, "axis.Press.acceleration");
    assert!(
        (max(&vel) - 80.0).abs() < 1e-9
            && max(&acc) <= 1000.0 + 1e-9
            && min(&acc) >= -1000.0 - 1e-9
    );
    let mid = moving + 20;
    assert_eq!(
        word[mid] as u32,
        1 | 2 | 1 << 8 | 1 << 9 | 1 << 20,
        "{}",
        word[mid]
    );
    assert_eq!(column(&trace, "MAIN.bHasJob")[mid], 1.0);
    assert_eq!(column(&trace, "MAIN.bPositive")[mid], 1.0);
    assert_eq!(column(&trace, "MAIN.bBitHomed")[mid], 1.0);
    assert_eq!(column(&trace, "MAIN.bOperational")[mid], 1.0);
    // relative homing: 120 + 10
    let rel = first(40.0);
    assert!((pos[rel] - 130.0).abs() < 1e-9, "{}", pos[rel]);
    // reset and force calibration: Homed follows, the position stays
    let reset = first(50.0);
    assert_eq!(homed[reset], 0.0);
    assert_eq!(homed[first(55.0)], 1.0);
    assert_eq!(homed[first(60.0)], 0.0);
    assert!((pos[first(60.0)] - 130.0).abs() < 1e-9);
    // default homing to DEFAULT_HOME_POSITION: the calibration value 0
    let default = first(70.0);
    assert!(pos[default].abs() < 1e-9 && homed[default] == 1.0);
    // absolute homing without a position: ErrorID 24
    assert_eq!(*column(&trace, "MAIN.bHomeError").last().unwrap(), 1.0);
    assert_eq!(*column(&trace, "MAIN.nHomeErrorID").last().unwrap(), 24.0);
    assert!(column(&trace, "MAIN.nAxisId").iter().all(|&v| v == 4.0));
    for c in ["MAIN.rPosDiff", "MAIN.rTorque", "MAIN.nCouple"] {
        assert!(column(&trace, c).iter().all(|&v| v == 0.0), "{c}");
    }
}

/// An `AXIS_REF` inside a function block instance that is a global (SeanyCash/TwinCAT_CNC's
/// `GVL.fbCNC.X_Ref`, linked by its NC mapping) is linked and moves: the link gives the global
/// instance an initializer naming the block's own variable (before: E1025 "FB_CNC has no field or
/// input `X_Ref`", the block's variables being declared after the globals).
#[test]
fn an_axis_ref_inside_a_global_function_block_instance_is_linked() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("cnc.st");
    std::fs::write(
        &src,
        "FUNCTION_BLOCK FB_CNC\nVAR\n  X_Ref : AXIS_REF;\n  fbPower : MC_Power;\n  fbMove : MC_MoveAbsolute;\nEND_VAR\n\
         fbPower(Axis := X_Ref, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);\n\
         fbMove(Axis := X_Ref, Execute := fbPower.Status, Position := 20.0, Velocity := 10.0);\n\
         END_FUNCTION_BLOCK\n\
         VAR_GLOBAL\n  fbCNC : FB_CNC;\nEND_VAR\n\
         PROGRAM MAIN\nfbCNC();\nEND_PROGRAM\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("cnc.axes.json"),
        r#"{ "axes": [ { "name": "X", "velocity": 10, "acceleration": 100, "deceleration": 100,
            "link": "fbCNC.X_Ref" } ] }"#,
    )
    .unwrap();
    let (trace, stderr) = run_traced_files(&[&src], 300, "axis.X.position,axis.X.velocity");
    assert!(!stderr.contains("error"), "{stderr}");
    assert!((column(&trace, "axis.X.position").last().unwrap() - 20.0).abs() < 1e-9);
    assert!((max(&column(&trace, "axis.X.velocity")) - 10.0).abs() < 1e-9);
}

/// An `AXIS_REF` no NC axis is linked to (its "Link To PLC" mapping missing from the `.tsproj`, as
/// in several public solutions) is E1056 naming the solution and the unlinked NC axes.
#[test]
fn an_axis_ref_without_an_nc_link_is_e1056_naming_the_nc_axes() {
    let dir = copy_of_cell();
    let tsproj = dir.path().join("Cell.tsproj");
    let text = std::fs::read_to_string(&tsproj).unwrap();
    let s = text
        .find("<OwnerB Name=\"TINC^NC-Task 1 SAF^Axes^Table Axis\">")
        .unwrap();
    let e = s + text[s..].find("</OwnerB>").unwrap() + "</OwnerB>".len();
    std::fs::write(&tsproj, format!("{}{}", &text[..s], &text[e..])).unwrap();
    let (code, stderr) = common::check_stderr(&dir.path().join("Cell/Cell.plcproj"));
    assert_eq!(code, Some(1), "{stderr}");
    let e = stderr.lines().find(|l| l.contains("E1056")).expect("E1056");
    assert!(
        e.contains(
            "MAIN.TcPOU:6:2: error[E1056]: AXIS_REF `MAIN.Table` is linked to no NC axis of "
        ) && e.contains("Cell.tsproj")
            && e.contains("link one of the NC axes (Table_Axis) to it in TwinCAT"),
        "{e}"
    );
}

/// `NcToPlc.CoupleState` of an `AXIS_REF` geared to a master (MC_GearIn; zhaoshutao's IDPLC
/// projects read it 304 times): 3 ("slave") while the coupling runs, 0 ("single axis") before it
/// and after MC_GearOut; `Status.CoupledMode` the same as a BOOL.
#[test]
fn couple_state_follows_the_gear_coupling() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("gear.st");
    std::fs::write(
        &src,
        "PROGRAM MAIN\nVAR\n  Slave : AXIS_REF;\n  pwM : MC_Power;\n  pwS : MC_Power;\n  mvM : MC_MoveVelocity;\n\
         gin : MC_GearIn;\n  gout : MC_GearOut;\n  n : INT;\n  nCouple : UDINT;\n  bCoupled : BOOL;\nEND_VAR\n\
         n := n + 1;\n\
         pwM(Axis := M, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);\n\
         pwS(Axis := Slave, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);\n\
         mvM(Axis := M, Execute := pwM.Status, Velocity := 40.0, Acceleration := 400.0, Deceleration := 400.0);\n\
         gin(Master := M, Slave := Slave, Execute := pwS.Status AND n > 5, RatioNumerator := 1.0,\n\
             RatioDenominator := 2.0, Acceleration := 1000.0, Deceleration := 1000.0);\n\
         gout(Slave := Slave, Execute := n > 60);\n\
         nCouple := Slave.NcToPlc.CoupleState;\n\
         bCoupled := Slave.Status.CoupledMode;\nEND_PROGRAM\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("gear.axes.json"),
        r#"{ "axes": [
  { "name": "M", "velocity": 100, "acceleration": 1000, "deceleration": 1000 },
  { "name": "S", "velocity": 100, "acceleration": 1000, "deceleration": 1000, "link": "MAIN.Slave" } ] }"#,
    )
    .unwrap();
    let (trace, stderr) = run_traced_files(
        &[&src],
        100,
        "MAIN.n,MAIN.nCouple,MAIN.bCoupled,axis.S.velocity",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let couple = column(&trace, "MAIN.nCouple");
    let coupled = column(&trace, "MAIN.bCoupled");
    assert_eq!(couple[0], 0.0);
    let on = couple.iter().position(|&c| c == 3.0).expect("slave");
    let off = on
        + couple[on..]
            .iter()
            .position(|&c| c == 0.0)
            .expect("geared out");
    assert!(
        (5..=10).contains(&on) && (60..=64).contains(&off),
        "{on} {off}"
    );
    assert!((0..couple.len()).all(|k| (couple[k] == 3.0) == (coupled[k] == 1.0)));
    assert!((column(&trace, "axis.S.velocity")[on + 20] - 20.0).abs() < 1e-9);
}

/// TwinCAT 3.1 with independent project files: the PLC instance lives in `_Config/PLC/Cell.xti`
/// (`<Plc><Project File="Cell.xti"/>`), and so do its "Link To PLC" mappings; they link the
/// axes as the `.tsproj`'s own did (before: E1056 for both, the mappings not read).
#[test]
fn mappings_in_the_plc_projects_xti_link_the_axes() {
    let dir = copy_of_cell();
    let tsproj = dir.path().join("Cell.tsproj");
    let text = std::fs::read_to_string(&tsproj).unwrap();
    let plc_start = text.find("\t\t\t<Project GUID").unwrap();
    let plc_end = text.find("\t\t</Plc>").unwrap();
    let maps_start = text.find("\t<Mappings>").unwrap();
    let maps_end = text.find("</Mappings>").unwrap() + "</Mappings>\n".len();
    let instance = &text[plc_start..plc_end];
    let mappings = &text[maps_start..maps_end];
    let moved = format!(
        "{}\t\t\t<Project File=\"Cell.xti\"/>\n{}{}",
        &text[..plc_start],
        &text[plc_end..maps_start],
        &text[maps_end..]
    );
    std::fs::write(&tsproj, moved).unwrap();
    std::fs::create_dir_all(dir.path().join("_Config/PLC")).unwrap();
    std::fs::write(
        dir.path().join("_Config/PLC/Cell.xti"),
        format!("<?xml version=\"1.0\"?>\n<TcSmItem xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" TcSmVersion=\"1.0\" TcVersion=\"3.1.4024.35\" ClassName=\"CNestedPlcProjDef\">\n{instance}{mappings}</TcSmItem>\n"),
    )
    .unwrap();
    let (trace, stderr) = run_traced_files(&[&dir.path().join("Cell/Cell.plcproj")], 400, WATCH);
    assert!(!stderr.contains("error"), "{stderr}");
    assert!((max(&column(&trace, "axis.Lift.velocity")) - 150.0).abs() < 1e-9);
    assert!((max(&column(&trace, "axis.Table_Axis.velocity")) - 90.0).abs() < 1e-9);
    // without the file the solution names: E1047 at the name
    std::fs::remove_file(dir.path().join("_Config/PLC/Cell.xti")).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(dir.path().join("Cell/Cell.plcproj"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("error[E1047]"), "{stderr}");
}
