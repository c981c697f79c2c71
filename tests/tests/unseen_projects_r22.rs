//! Round 22 of unseen projects (issue #13): forms that real programs use, run end to end through
//! `ladderc run`:
//! - a Tc2_MC2 `AXIS_REF` held in a structure (`ST_AxisControl.Axis` of ISIS's DrivePLC, in a
//!   global array of them and as an FB's VAR_IN_OUT): its `ReadStatus()`, `Status.` and
//!   `NcToPlc.` members read the simulated axis as those of a plain AXIS_REF do (before: E1021
//!   "AXIS_REF has no field `NcToPlc`", 28 errors in ISIS), and an integer division forced on
//!   `(a.NcToPlc.ActPos + b.NcToPlc.ActPos) / 2` is gone (before: a false E1012 "LINT_TO_LREAL
//!   converts from LINT").

mod common;
use common::{column, run_traced_files};

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
