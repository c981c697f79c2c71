//! Round 34: a property chain of two levels (a PROPERTY whose value is an INTERFACE or a
//! `REFERENCE TO` a function block, then a property or a method of what it refers to:
//! `ifut.executor.keepJob`, `fut.worker.level`, `ifut.executor.Run()`) read anywhere a value is
//! read, not only in a plain statement: a REPEAT ... UNTIL and a WHILE condition, an IF / ELSIF
//! condition, a CASE selector, FOR bounds, function arguments, array indexes (the written
//! element's and a read one's). Each form runs with `ladderc run` and its values are checked
//! cycle by cycle (Beckhoff Infosys TC3 PLC "Interface": a variable of an interface type refers to
//! a function block instance; "Property": a read runs the Get accessor of that instance).

mod common;
use common::{column, run_text};

/// `I_Job` (PROPERTY keepJob, PROPERTY level, METHOD Run), `I_Future` (PROPERTY executor : I_Job),
/// `FB_Job` and `FB_Future` implementing them; `FB_Future.worker` a `REFERENCE TO FB_Job`
/// property (Beckhoff-JP's PLC_JobManagementFramework reads `executor` of its futures so).
const JOBS: &str = "INTERFACE I_Job
PROPERTY keepJob : BOOL
GET END_GET
SET END_SET
END_PROPERTY
PROPERTY level : INT
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
  lvl : INT;
END_VAR
PROPERTY keepJob : BOOL
GET
  keepJob := kept;
END_GET
SET
  kept := keepJob;
END_SET
END_PROPERTY
PROPERTY level : INT
GET
  level := lvl;
END_GET
SET
  lvl := level;
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
  owned : FB_Job;
END_VAR
PROPERTY executor : I_Job
GET
  executor := job;
END_GET
SET
  job := executor;
END_SET
END_PROPERTY
PROPERTY worker : REFERENCE TO FB_Job
GET
  worker REF= owned;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
";

/// `UNTIL ifut.executor.keepJob`, `UNTIL fut.executor.keepJob` (through an interface variable and
/// through the instance), `UNTIL fut.worker.level >= 2 * cycle` (a `REFERENCE TO` property),
/// `UNTIL ifut.executor.Run() >= 3 * cycle` (a method of the interface the property returns) and
/// `WHILE NOT ifut.executor.keepJob`: each loop tests the value of the instance the property
/// refers to, after every pass of its body. Before round 34 the getter called for the UNTIL test
/// dropped what follows it: E1006 "cannot store I_Job into BOOL" (twice), E1005 "GE of FB_Job
/// and INT".
#[test]
fn loop_conditions_read_the_property_of_the_instance_a_property_returns() {
    let src = format!(
        "{JOBS}
PROGRAM main
VAR
  job : FB_Job;
  fut : FB_Future;
  ifut : I_Future;
  cycle : INT;
  nItf : INT;
  nFb : INT;
  nRef : INT;
  nRun : INT;
  nWhile : INT;
END_VAR
cycle := cycle + 1;
fut.executor := job;
ifut := fut;
nItf := 0;
REPEAT
  nItf := nItf + 1;
  ifut.executor.keepJob := nItf >= cycle;
UNTIL ifut.executor.keepJob END_REPEAT
nFb := 0;
REPEAT
  nFb := nFb + 1;
  fut.executor.keepJob := nFb >= cycle + 1;
UNTIL fut.executor.keepJob END_REPEAT
nRef := 0;
REPEAT
  nRef := nRef + 1;
  fut.worker.level := nRef;
UNTIL fut.worker.level >= 2 * cycle END_REPEAT
nRun := 0;
REPEAT
  nRun := nRun + 1;
UNTIL ifut.executor.Run() >= 3 * cycle END_REPEAT
nWhile := 0;
ifut.executor.keepJob := FALSE;
WHILE NOT ifut.executor.keepJob DO
  nWhile := nWhile + 1;
  fut.executor.keepJob := nWhile >= 2 * cycle;
END_WHILE
END_PROGRAM
"
    );
    let (trace, _) = run_text(
        "jobs.st",
        &src,
        4,
        "main.nItf,main.nFb,main.nRef,main.nRun,main.job.runs,main.nWhile",
    );
    assert_eq!(column(&trace, "main.nItf"), [1., 2., 3., 4.]);
    assert_eq!(column(&trace, "main.nFb"), [2., 3., 4., 5.]);
    assert_eq!(column(&trace, "main.nRef"), [2., 4., 6., 8.]);
    assert_eq!(column(&trace, "main.nRun"), [3., 3., 3., 3.]);
    assert_eq!(column(&trace, "main.job.runs"), [3., 6., 9., 12.]);
    assert_eq!(column(&trace, "main.nWhile"), [2., 4., 6., 8.]);
}

/// The same chains in an ELSIF condition, an IF condition, a CASE selector, the three FOR bounds,
/// the arguments of a function and of LIMIT, the index of the element written and of one read:
/// each reads the instance's value of this cycle. Before round 34 an index reading through an
/// interface variable (`arr[ifut.executor.level]`) was E1021 "I_Future has no field
/// `__GET_EXECUTOR`": the interface call's result, kept in a variable of the caller, was not
/// read inside indexes.
#[test]
fn conditions_bounds_arguments_and_indexes_read_a_property_chain() {
    let src = format!(
        "{JOBS}
FUNCTION Twice : INT
VAR_INPUT x : INT; END_VAR
Twice := 2 * x;
END_FUNCTION

PROGRAM main
VAR
  job : FB_Job;
  fut : FB_Future;
  ifut : I_Future;
  cycle : INT;
  i : INT;
  nIf : INT;
  nThen : INT;
  nCase : INT;
  nFor : INT;
  nArg : INT;
  nIdx : INT;
  arr : ARRAY[0..3] OF INT;
END_VAR
cycle := cycle + 1;
fut.executor := job;
ifut := fut;
job.level := cycle MOD 4;
fut.worker.level := cycle MOD 3;
IF cycle < 0 THEN
  nIf := -1;
ELSIF ifut.executor.level = 2 THEN
  nIf := cycle;
ELSIF fut.worker.level = 1 THEN
  nIf := 100 + cycle;
ELSE
  nIf := 0;
END_IF
IF fut.executor.level = 3 THEN
  nThen := cycle;
END_IF
CASE ifut.executor.level OF
  0: nCase := 10;
  1: nCase := 11;
  2: nCase := 12;
ELSE
  nCase := 13;
END_CASE
nFor := 0;
FOR i := ifut.executor.level TO fut.worker.level + 3 BY fut.executor.level + 1 DO
  nFor := nFor + 1;
END_FOR
nArg := Twice(ifut.executor.level) * 10 + LIMIT(0, fut.worker.level, 9);
arr[ifut.executor.level] := cycle;
nIdx := arr[fut.worker.level];
END_PROGRAM
"
    );
    let (trace, _) = run_text(
        "jobs.st",
        &src,
        6,
        "main.nIf,main.nThen,main.nCase,main.nFor,main.nArg,main.nIdx",
    );
    // level = cycle MOD 4 (through `ifut`), worker.level = cycle MOD 3
    assert_eq!(column(&trace, "main.nIf"), [101., 2., 0., 104., 0., 6.]);
    assert_eq!(column(&trace, "main.nThen"), [0., 0., 3., 3., 3., 3.]);
    assert_eq!(column(&trace, "main.nCase"), [11., 12., 13., 10., 11., 12.]);
    assert_eq!(column(&trace, "main.nFor"), [2., 2., 1., 5., 3., 1.]);
    assert_eq!(column(&trace, "main.nArg"), [21., 42., 60., 1., 22., 40.]);
    assert_eq!(column(&trace, "main.nIdx"), [1., 2., 0., 1., 2., 4.]);
}
