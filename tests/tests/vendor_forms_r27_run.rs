//! Round 27 of unseen projects (issue #13): vendor forms of CODESYS and TwinCAT programs, run end
//! to end through `ladderc run`:
//! - CODESYS SoftMotion SM3_Basic: `AXIS_REF_SM3` is ladderc's `AXIS_REF`, MC_Power powers the
//!   axis on `Enable AND bRegulatorOn AND bDriveStart` and gives `bRegulatorRealState` /
//!   `bDriveStartRealState`, MC_SetPosition's `Mode` is `Relative` (before: E1003 `AXIS_REF_SM3`,
//!   E1011 `bRegulatorOn`, `bDriveStart`, although ladderc said it provides SM3_Basic).
//! - a literal given to a FUNCTION_BLOCK's or FUNCTION's `VAR_IN_OUT CONSTANT` goes through a
//!   temporary (before: E2005 from the C backend); to a plain `VAR_IN_OUT` it is E1088 at the
//!   literal (before: E2005, two for a function call).
//! - TwinCAT's and CODESYS's global namespace operator, `.x` and `.GVL.x`, names the global even
//!   where a local of that name hides it (before: E0100 per statement).
//! - a value of an `{attribute 'strict'}` enumeration stored into an integer or a bit string that
//!   holds every value is its number, with W1439 (before: E1006; Beckhoff's 'strict' forbids
//!   arithmetic and storing other values into the enumeration only).

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

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

/// A literal given to a FUNCTION_BLOCK's and a FUNCTION's `VAR_IN_OUT CONSTANT` (CODESYS,
/// TwinCAT: read-only, takes any value) is passed through a temporary: LEN of 'abc' and 'abcd',
/// then a variable passed as before.
#[test]
fn a_literal_to_a_var_in_out_constant_of_a_block_or_function_runs() {
    let src = "FUNCTION_BLOCK FB_Count
VAR_IN_OUT CONSTANT
    sText : STRING;
END_VAR
VAR_OUTPUT
    n : INT;
END_VAR
n := LEN(sText);
END_FUNCTION_BLOCK
FUNCTION F_Count : INT
VAR_IN_OUT CONSTANT
    sText : STRING;
END_VAR
F_Count := LEN(sText);
END_FUNCTION
PROGRAM Main
VAR
    counter : FB_Count;
    a, b, c : INT;
    greeting : STRING := 'hello';
END_VAR
counter(sText := 'abc', n => a);
b := F_Count(sText := 'abcd');
counter(sText := greeting);
c := counter.n;
END_PROGRAM
";
    let (trace, stderr) = run_text("inout_const.st", src, 2, "Main.a,Main.b,Main.c");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.a"), vec![3.0, 3.0]);
    assert_eq!(column(&trace, "Main.b"), vec![4.0, 4.0]);
    assert_eq!(column(&trace, "Main.c"), vec![5.0, 5.0]);
}

/// A literal given to a plain `VAR_IN_OUT` (passed by reference) is one E1088 per argument, at the
/// literal, from the front end (before: E2005 from the C backend, two for the function call).
#[test]
fn a_literal_to_a_plain_var_in_out_is_e1088() {
    let src = "FUNCTION_BLOCK FB_Count
VAR_IN_OUT
    sText : STRING;
END_VAR
VAR_OUTPUT
    n : INT;
END_VAR
n := LEN(sText);
END_FUNCTION_BLOCK
FUNCTION F_Count : INT
VAR_IN_OUT
    sText : STRING;
END_VAR
F_Count := LEN(sText);
END_FUNCTION
PROGRAM Main
VAR
    counter : FB_Count;
    a, b : INT;
END_VAR
counter(sText := 'abc', n => a);
b := F_Count(sText := 'abcd');
END_PROGRAM
";
    let (code, diags) = check_text("inout_plain.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(diags.len(), 2, "{diags:?}");
    assert!(diags[0].contains(":21:18: error[E1088]"), "{diags:?}");
    assert!(diags[1].contains(":22:23: error[E1088]"), "{diags:?}");
    assert!(diags.iter().all(|d| !d.contains("E2005")), "{diags:?}");
}

/// `.nCount` (TwinCAT's global namespace operator) is the global `nCount` of `GVL_Demo` although
/// MAIN declares its own `nCount`; `.GVL_Demo.bSeen` is the list's variable; `.nCount` reads in a
/// condition too.
#[test]
fn the_global_namespace_operator_names_the_global_behind_a_local() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "MAIN.TcPOU",
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1">
  <POU Name="MAIN" Id="{3d1c0a52-0000-4000-8000-000000000001}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
    nCount : INT;
    bBig : BOOL;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[nCount := 100;
.nCount := .nCount + 1;
.GVL_Demo.bSeen := TRUE;
IF .nCount > 2 THEN
    bBig := TRUE;
END_IF
]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
"#,
    );
    write_in(
        dir.path(),
        "GVL_Demo.TcGVL",
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1">
  <GVL Name="GVL_Demo" Id="{3d1c0a52-0000-4000-8000-000000000002}">
    <Declaration><![CDATA[VAR_GLOBAL
    nCount : INT;
    bSeen : BOOL;
END_VAR
]]></Declaration>
  </GVL>
</TcPlcObject>
"#,
    );
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "MAIN.TcPOU",
            "GVL_Demo.TcGVL",
            "--cycles",
            "3",
            "--watch",
            "MAIN.nCount,GVL_Demo.nCount,GVL_Demo.bSeen,MAIN.bBig",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&trace, "MAIN.nCount"), vec![100.0; 3]);
    assert_eq!(column(&trace, "GVL_Demo.nCount"), vec![1.0, 2.0, 3.0]);
    assert_eq!(column(&trace, "GVL_Demo.bSeen"), vec![1.0; 3]);
    assert_eq!(column(&trace, "MAIN.bBig"), vec![0.0, 0.0, 1.0]);
}

/// A strict enumeration's values stored into a BYTE and an INT (as TwinCAT projects write
/// `Q_.Stack := eColors.COLOR_RED;`) run as their numbers, one W1439 for the POU.
#[test]
fn a_strict_enumeration_value_is_stored_into_an_integer() {
    let src = "{attribute 'qualified_only'}
{attribute 'strict'}
TYPE E_Lamp :
(
    OFF := 0,
    RED := 1,
    GREEN := 2
) BYTE;
END_TYPE
PROGRAM Main
VAR
    run : BOOL;
    lamp : BYTE;
    lampCode : INT;
    n : INT;
END_VAR
n := n + 1;
run := n > 1;
IF run THEN
    lamp := E_Lamp.GREEN;
ELSE
    lamp := E_Lamp.RED;
END_IF
lampCode := E_Lamp.GREEN;
END_PROGRAM
";
    let (trace, stderr) = run_text("strict_enum.st", src, 3, "Main.lamp,Main.lampCode");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(stderr.matches("W1439").count(), 1, "{stderr}");
    assert_eq!(column(&trace, "Main.lamp"), vec![1.0, 2.0, 2.0]);
    assert_eq!(column(&trace, "Main.lampCode"), vec![2.0; 3]);
}
