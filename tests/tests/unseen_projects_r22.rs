//! Round 22 of unseen projects (issue #13): forms that real programs use, run end to end through
//! `ladderc run`:
//! - a Tc2_MC2 `AXIS_REF` held in a structure (`ST_AxisControl.Axis` of ISIS's DrivePLC, in a
//!   global array of them and as an FB's VAR_IN_OUT): its `ReadStatus()`, `Status.` and
//!   `NcToPlc.` members read the simulated axis as those of a plain AXIS_REF do (before: E1021
//!   "AXIS_REF has no field `NcToPlc`", 28 errors in ISIS), and an integer division forced on
//!   `(a.NcToPlc.ActPos + b.NcToPlc.ActPos) / 2` is gone (before: a false E1012 "LINT_TO_LREAL
//!   converts from LINT");
//! - an instance or structure initializer that starts a pointer as the address of a variable of
//!   the POU (`fbM : FB_M := (pLamp := ADR(lamp));`, CODESYS, TwinCAT; before: E0011 "unexpected
//!   `(`"), with the same checks as `p : POINTER TO BOOL := ADR(lamp);`.

mod common;
use common::{check_text, column, run_text, run_traced_files};

/// Two axes held as `axes[i].Axis` in a global array of structures, each driven by an FB through
/// its VAR_IN_OUT structure: `AxisController.Axis.ReadStatus()`, `.Status.Moving`,
/// `.NcToPlc.ActPos` inside the FB, `axes[1].Axis.NcToPlc.ActPos` in the program (a mean and a
/// gap, as ISIS's slit gaps and centres are computed).
#[test]
fn an_axis_inside_a_structure_reads_its_members() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("drive.axes.json"),
        r#"{ "cycle_ms": 10, "axes": [
 { "name": "X", "unit": "mm", "velocity": 100, "acceleration": 1000, "deceleration": 1000, "jerk": 0, "link": "axes[1].Axis" },
 { "name": "Y", "unit": "mm", "velocity": 100, "acceleration": 1000, "deceleration": 1000, "jerk": 0, "link": "axes[2].Axis" } ] }"#,
    )
    .unwrap();
    let f = dir.path().join("drive.st");
    std::fs::write(
        &f,
        "TYPE ST_AxisControl : STRUCT
  bExecute : BOOL;
  fPosition : LREAL;
  fActPosition : LREAL;
  bMoving : BOOL;
  bDone : BOOL;
  Axis : AXIS_REF;
END_STRUCT;
END_TYPE
VAR_GLOBAL
  axes : ARRAY [1..2] OF ST_AxisControl;
END_VAR
FUNCTION_BLOCK FB_AxisDrive
VAR_IN_OUT AxisController : ST_AxisControl; END_VAR
VAR pw : MC_Power; mv : MC_MoveAbsolute; END_VAR
AxisController.Axis.ReadStatus();
AxisController.fActPosition := AxisController.Axis.NcToPlc.ActPos;
AxisController.bMoving := AxisController.Axis.Status.Moving;
pw(Axis := AxisController.Axis, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);
mv(Axis := AxisController.Axis, Execute := AxisController.bExecute AND pw.Status,
   Position := AxisController.fPosition, Velocity := 100.0, Acceleration := 1000.0, Deceleration := 1000.0);
AxisController.bDone := mv.Done;
END_FUNCTION_BLOCK
PROGRAM MAIN
VAR drive : ARRAY [1..2] OF FB_AxisDrive; i : INT; mid, gap : LREAL; END_VAR
axes[1].fPosition := 10.0; axes[2].fPosition := 30.0;
axes[1].bExecute := TRUE; axes[2].bExecute := TRUE;
FOR i := 1 TO 2 DO drive[i](AxisController := axes[i]); END_FOR
mid := (axes[1].Axis.NcToPlc.ActPos + axes[2].Axis.NcToPlc.ActPos) / 2;
gap := axes[2].Axis.NcToPlc.ActPos - axes[i - 2].Axis.NcToPlc.ActPos;
END_PROGRAM
",
    )
    .unwrap();
    let watch = "axes[1].fActPosition,axes[2].fActPosition,axes[1].bMoving,axes[2].bMoving,axes[1].bDone,axes[2].bDone,MAIN.mid,MAIN.gap,axis.X.position,axis.Y.position";
    let (trace, stderr) = run_traced_files(&[&f], 60, watch);
    assert!(!stderr.contains("error"), "{stderr}");
    let col = |n: &str| column(&trace, n);
    let (x, y) = (col("axis.X.position"), col("axis.Y.position"));
    let (ax, ay) = (col("axes[1].fActPosition"), col("axes[2].fActPosition"));
    let (mid, gap) = (col("MAIN.mid"), col("MAIN.gap"));
    let (mx, my) = (col("axes[1].bMoving"), col("axes[2].bMoving"));
    let (dx, dy) = (col("axes[1].bDone"), col("axes[2].bDone"));
    for k in 1..60 {
        // the FB reads its axis at the start of its body: the position the last cycle ended at
        assert!((ax[k] - x[k - 1]).abs() < 1e-9, "cycle {k}: {trace}");
        assert!((ay[k] - y[k - 1]).abs() < 1e-9, "cycle {k}: {trace}");
        // the program reads both axes at the start of its body, before it calls the FBs
        assert!(
            (mid[k] - (x[k - 1] + y[k - 1]) / 2.0).abs() < 1e-9,
            "cycle {k}"
        );
        assert!((gap[k] - (y[k - 1] - x[k - 1])).abs() < 1e-9, "cycle {k}");
    }
    // X (10 mm) stops first; Y (30 mm) still moves; then both stand at their targets, done
    assert_eq!((mx[10], my[10]), (1.0, 1.0), "{trace}");
    assert_eq!(
        (mx[30], my[30], dx[30], dy[30]),
        (0.0, 1.0, 1.0, 0.0),
        "{trace}"
    );
    assert_eq!(
        (mx[59], my[59], dx[59], dy[59]),
        (0.0, 0.0, 1.0, 1.0),
        "{trace}"
    );
    assert_eq!(
        (x[59], y[59], mid[59], gap[59]),
        (10.0, 30.0, 20.0, 20.0),
        "{trace}"
    );
}

/// `(pLamp := ADR(lamp))` in an FB instance's initializer and `(p := ADR(arr[2]))` in a
/// structure's: the pointers start at those variables (the FB toggles `lamp` through its input;
/// `s.p^` reads `arr[2]`), beside plain values of the same initializers; an address of no variable
/// of the POU, one stored into an INT input, and another function are located errors.
#[test]
fn an_instance_initializer_may_start_a_pointer_at_a_variable() {
    let src = "TYPE ST_P : STRUCT
  p : POINTER TO INT;
  n : INT;
END_STRUCT;
END_TYPE
FUNCTION_BLOCK FB_M
VAR_INPUT
    pLamp : POINTER TO BOOL;
    k : INT;
END_VAR
pLamp^ := NOT pLamp^;
END_FUNCTION_BLOCK
PROGRAM MAIN
VAR
    lamp : BOOL;
    arr : ARRAY [1..3] OF INT := [1, 2, 3];
    fbM : FB_M := (pLamp := ADR(lamp), k := 4);
    s : ST_P := (n := 7, p := ADR(arr[2]));
    v : INT;
END_VAR
fbM();
v := s.p^ + s.n;
arr[2] := arr[2] + 1;
END_PROGRAM
";
    let (trace, stderr) = run_text("init.st", src, 3, "MAIN.lamp,MAIN.v,MAIN.fbM.k");
    assert_eq!(
        trace, "cycle,time_ms,MAIN.lamp,MAIN.v,MAIN.fbM.k\n0,0,1,9,4\n1,10,0,10,4\n2,20,1,11,4\n",
        "{stderr}"
    );
    let bad = "FUNCTION_BLOCK FB_M
VAR_INPUT
    pLamp : POINTER TO BOOL;
    k : INT;
END_VAR
END_FUNCTION_BLOCK
PROGRAM MAIN
VAR
    lamp : BOOL;
    a : FB_M := (pLamp := ADR(nope));
    b : FB_M := (k := ADR(lamp));
END_VAR
a(); b();
END_PROGRAM
";
    let (code, lines) = check_text("bad.st", bad);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        lines,
        [
            "bad.st:10:27: error[E0305]: `a.pLamp` cannot start as `ADR(nope)`: `nope` is no variable of this POU (hint: start it as `ADR(x)` of a variable of the same POU whose type it refers to, or set it in the body (`p := ADR(x);`))",
            "bad.st:11:23: error[E1006]: cannot store an address into INT (hint: `k` is no POINTER TO, REF_TO or REFERENCE TO)",
        ]
    );
    let (code, lines) = check_text("call.st", &bad.replace("ADR(nope)", "FOO(lamp)"));
    assert_eq!(code, Some(1));
    assert_eq!(
        lines[0],
        "call.st:10:27: error[E0022]: `FOO(...)` is computed at run time (hint: an initial value is a constant, or `ADR(x)` / `REF(x)` of a variable of the POU; set this one in the body)"
    );
}
