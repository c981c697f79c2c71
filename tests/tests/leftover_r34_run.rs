//! Round 34 leftovers of earlier rounds:
//! - a CODESYS body with neither a POU header nor an END (its `VAR_INPUT ... END_VAR` blocks then
//!   its statements) is one E0307, whose hint names the header to add; E1102 stays for VAR blocks
//!   a POU header really follows (before: E1102, or the note W0018, beside E0307);
//! - a PROPERTY whose type is an INTERFACE, read from an interface variable: a property of the
//!   instance it refers to is read and written through it, and its methods called
//!   (`ifut.executor.keepJob := TRUE;`, `ifut.executor.Run()`), while a component of a STRUCT
//!   property stays E0338 (a copy).

mod common;
use common::{check_text, column, run_text};

/// A function block's declarations and body without `FUNCTION_BLOCK name` and
/// `END_FUNCTION_BLOCK` (AlessandroBinci/Winding-machine-simulation's `FB_Mover.st`): one E0307 at
/// the first statement, its hint naming `FUNCTION_BLOCK Mover` (the file's stem) since the blocks
/// hold inputs (before round 34: E0307 and an E1102 "a VAR_INPUT block outside any POU" at 1:1).
#[test]
fn headless_function_block_body_is_one_e0307() {
    let src = "VAR_INPUT
    speed : REAL;
END_VAR
VAR_OUTPUT
    position : REAL;
END_VAR
position := position + speed;
IF position > 100.0 THEN
    position := 0.0;
END_IF
";
    let (code, lines) = check_text("Mover.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("Mover.st:7:1: error[E0307]: statements outside any POU"),
        "{lines:?}"
    );
    assert!(
        lines[0].contains("CODESYS body without its header")
            && lines[0].contains("`FUNCTION_BLOCK Mover`")
            && lines[0].contains("`END_FUNCTION_BLOCK`"),
        "{lines:?}"
    );
    assert!(!lines.iter().any(|l| l.contains("E1102")), "{lines:?}");
}

/// The same body under a line holding its name alone (`FB_Lift` on line 1, as the real files
/// have it) and with only a `VAR` block: one E0307 at 1:1 whose hint proposes `PROGRAM FB_Lift`
/// in place of that line, and no note W0018 ("read as global variables") for the block (before
/// round 34: E0307 and W0018).
#[test]
fn headless_body_under_its_name_is_one_e0307_naming_it() {
    let src = "FB_Lift


VAR
    height : INT;
END_VAR
height := height + 1;
";
    let dir = tempfile::tempdir().unwrap();
    common::write_in(dir.path(), "Lift.st", src);
    let (code, _, stderr) = common::in_dir(dir.path(), &["check", "Lift.st"]);
    let lines: Vec<&str> = stderr.lines().filter(|l| l.contains("Lift.st:")).collect();
    assert_eq!(code, Some(1), "{stderr}");
    assert_eq!(lines.len(), 1, "{stderr}");
    assert!(
        lines[0].starts_with("Lift.st:1:1: error[E0307]: statements outside any POU"),
        "{stderr}"
    );
    assert!(
        lines[0].contains("`PROGRAM FB_Lift` instead of the line holding its name alone"),
        "{stderr}"
    );
    assert!(!stderr.contains("W0018"), "{stderr}");
}

/// A VAR_INPUT block that a `FUNCTION_BLOCK` header follows stays one E1102 at the block (the
/// header is there, the block misplaced), with no E0307: the statements are inside the block.
#[test]
fn interface_block_before_a_header_stays_one_e1102() {
    let src = "VAR_INPUT
    speed : REAL;
END_VAR
FUNCTION_BLOCK Mover
VAR_OUTPUT
    position : REAL;
END_VAR
position := position + speed;
END_FUNCTION_BLOCK
";
    let (code, lines) = check_text("Mover.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "Mover.st:1:1: error[E1102]: a VAR_INPUT block outside any POU: it belongs after a POU's header"
        ),
        "{lines:?}"
    );
    assert!(lines[0].contains("`FUNCTION_BLOCK Mover`"), "{lines:?}");
}

/// The interfaces and blocks of the property tests: `I_Future.executor` is a PROPERTY of type
/// `I_Job`, `I_Job.keepJob` a PROPERTY and `I_Job.Run` a METHOD (Beckhoff-JP's
/// PLC_JobManagementFramework has `created_future.executor.persistent_job := FALSE;` with
/// `created_future : I_Future`).
const JOBS: &str = "INTERFACE I_Job
PROPERTY keepJob : BOOL
GET END_GET
SET END_SET
END_PROPERTY
METHOD Run : INT
END_METHOD
END_INTERFACE

INTERFACE I_Future
PROPERTY executor : I_Job
GET END_GET
SET END_SET
END_PROPERTY
END_INTERFACE

FUNCTION_BLOCK FB_Job IMPLEMENTS I_Job
VAR
  kept : BOOL;
  runs : INT;
END_VAR
PROPERTY keepJob : BOOL
GET
  keepJob := kept;
END_GET
SET
  kept := keepJob;
END_SET
END_PROPERTY
METHOD Run : INT
runs := runs + 1;
Run := runs;
END_METHOD
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB_Future IMPLEMENTS I_Future
VAR
  job : I_Job;
END_VAR
PROPERTY executor : I_Job
GET
  executor := job;
END_GET
SET
  job := executor;
END_SET
END_PROPERTY
END_FUNCTION_BLOCK
";

/// Through an interface variable (`ifut : I_Future`), `ifut.executor.keepJob := v;` calls the Set
/// accessor of the instance `executor` refers to, `ifut.executor.keepJob` (in an assignment and
/// an ELSIF) its Get accessor, and `ifut.executor.Run()` its method: the instance's values change
/// cycle by cycle (Beckhoff Infosys TC3 PLC "Interface": a variable of an interface type refers
/// to a function block instance). Before round 34: E0338 "the property's value is a copy" for the
/// write (4 in the real project), E1021 "I_Future has no field `__GET_EXECUTOR`" for the reads and
/// the call.
#[test]
fn property_of_the_interface_a_property_returns_is_that_instances() {
    let src = format!(
        "{JOBS}
PROGRAM main
VAR
  job : FB_Job;
  fut : FB_Future;
  ifut : I_Future;
  cycle : INT;
  seen : BOOL;
  flag : INT;
  runs : INT;
END_VAR
cycle := cycle + 1;
fut.executor := job;
ifut := fut;
ifut.executor.keepJob := (cycle MOD 3) = 0;
seen := ifut.executor.keepJob;
IF cycle < 0 THEN
  flag := -1;
ELSIF ifut.executor.keepJob THEN
  flag := cycle;
END_IF
runs := ifut.executor.Run();
ifut.executor.Run();
END_PROGRAM
"
    );
    let (trace, _) = run_text(
        "jobs.st",
        &src,
        6,
        "main.seen,main.flag,main.runs,main.job.kept,main.job.runs",
    );
    assert_eq!(column(&trace, "main.job.kept"), [0., 0., 1., 0., 0., 1.]);
    assert_eq!(column(&trace, "main.seen"), [0., 0., 1., 0., 0., 1.]);
    assert_eq!(column(&trace, "main.flag"), [0., 0., 3., 3., 3., 6.]);
    assert_eq!(column(&trace, "main.runs"), [1., 3., 5., 7., 9., 11.]);
    assert_eq!(column(&trace, "main.job.runs"), [2., 4., 6., 8., 10., 12.]);
}

/// A component of a STRUCT-valued property written through an interface variable stays one
/// E0338: the property's value is a copy, the write would be lost.
#[test]
fn component_of_a_struct_property_through_an_interface_stays_e0338() {
    let src = "TYPE ST_Pos : STRUCT x : INT; END_STRUCT; END_TYPE

INTERFACE I_Axis
PROPERTY pos : ST_Pos
GET END_GET
SET END_SET
END_PROPERTY
END_INTERFACE

FUNCTION_BLOCK FB_Axis IMPLEMENTS I_Axis
VAR
  p : ST_Pos;
END_VAR
PROPERTY pos : ST_Pos
GET
  pos := p;
END_GET
SET
  p := pos;
END_SET
END_PROPERTY
END_FUNCTION_BLOCK

PROGRAM main
VAR
  axis : FB_Axis;
  a : I_Axis;
END_VAR
a := axis;
a.pos.x := 5;
END_PROGRAM
";
    let (code, lines) = check_text("axis.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("axis.st:30:1: error[E0338]: a component of property `pos`"),
        "{lines:?}"
    );
}
