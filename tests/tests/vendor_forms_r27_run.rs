//! Round 27 of unseen projects (issue #13): vendor forms of CODESYS and TwinCAT programs, run end
//! to end through `ladderc run`:
//! - CODESYS SoftMotion SM3_Basic: `AXIS_REF_SM3` is ladderc's `AXIS_REF`, MC_Power powers the
//!   axis on `Enable AND bRegulatorOn AND bDriveStart` and gives `bRegulatorRealState` /
//!   `bDriveStartRealState`, MC_SetPosition's `Mode` is `Relative` (before: E1003 `AXIS_REF_SM3`,
//!   E1011 `bRegulatorOn`, `bDriveStart`, although ladderc said it provides SM3_Basic).

mod common;
use common::{column, in_dir, write_in};

/// An SM3 axis powered by SM3_Basic's MC_Power with `bDriveStart` rising at the sixth scan, its
/// position set to 10 mm (MC_SetPosition, `Mode := FALSE`: absolute), then moved to 50 mm by
/// MC_MoveAbsolute at 100 mm/s: not powered before `bDriveStart`, both real states follow the
/// power, the axis ends at 50 mm.
#[test]
fn an_sm3_basic_axis_is_powered_by_regulator_and_drive_start_and_moves() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "sm3.st",
        "PROGRAM Main
VAR
  X1 : SM3_Basic.AXIS_REF_SM3;
  power : SM3_Basic.MC_Power;
  setPos : MC_SetPosition;
  move : SM3_Basic.MC_MoveAbsolute;
  driveStart, powered, regulatorReal, driveStartReal, done : BOOL;
  scans : INT;
END_VAR
scans := scans + 1;
driveStart := scans > 5;
power(Axis := X1, Enable := TRUE, bRegulatorOn := TRUE, bDriveStart := driveStart,
      bRegulatorRealState => regulatorReal, bDriveStartRealState => driveStartReal);
powered := power.Status;
setPos(Axis := X1, Execute := powered, Position := 10.0, Mode := FALSE);
move(Axis := X1, Execute := setPos.Done, Position := 50.0, Velocity := 100.0,
     Acceleration := 1000.0, Deceleration := 1000.0);
done := move.Done;
END_PROGRAM
",
    );
    write_in(
        dir.path(),
        "sm3.axes.json",
        r#"{ "cycle_ms": 10, "axes": [ { "name": "X1", "unit": "mm", "velocity": 250, "acceleration": 1000, "deceleration": 1000 } ] }"#,
    );
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "sm3.st",
            "--cycles",
            "100",
            "--watch",
            "Main.powered,Main.regulatorReal,Main.driveStartReal,Main.done,axis.X1.position",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    let powered = column(&trace, "Main.powered");
    assert!(powered[..5].iter().all(|&p| p == 0.0), "{powered:?}");
    assert!(powered[5..].iter().all(|&p| p == 1.0), "{powered:?}");
    assert_eq!(column(&trace, "Main.regulatorReal"), powered);
    assert_eq!(column(&trace, "Main.driveStartReal"), powered);
    let pos = column(&trace, "axis.X1.position");
    assert!(pos[..5].iter().all(|&p| p == 0.0), "{pos:?}");
    // set to 10 mm, then moved up to 50 mm
    assert!(pos[5] >= 10.0 && pos[5] < 11.0, "{}", pos[5]);
    assert!((pos[99] - 50.0).abs() < 1e-9, "{}", pos[99]);
    assert_eq!(column(&trace, "Main.done")[99], 1.0);
}
