//! Round 32 of issue #13: TwinCAT language points found in Beckhoff's own sample repositories,
//! end to end.
//! - `FOR e := E.a + 1 TO E.b - 1` over an enumeration without `{attribute 'strict'}` counts
//!   through its numbers, as `e := E.a + 1` already did (Beckhoff Infosys, "Attribute 'strict'":
//!   only under the attribute is arithmetic on an enumeration variable a compile error); a strict
//!   one stays E3100 (before: E3100 for both; Boot-folder-swap-from-PLC);
//! - `R_Edge : R_TRIG;` in a `.TcPOU` is a variable (W1451): TwinCAT's "Keywords" list and its
//!   future-reserved list (Compiler Error C0543) have no R_EDGE / F_EDGE (before: E1031 and the
//!   body not compiled; TF6350_SMS_SMTP);
//! - Tc2_Standard's WSTRING functions (`WMID`, `WLEN`, `WCONCAT` ...; Beckhoff Infosys,
//!   Tc2_Standard, "WMID": `FUNCTION WMID : WSTRING(255)` with STR, LEN, POS) are the string
//!   functions on WSTRING (before: E1019 unknown function; TF6100_Samples);
//! - a property of the interface a property returns is written through it
//!   (`fut.executor.keepJob := TRUE;`): an interface value refers to an instance (Infosys,
//!   "Interface"), so the write calls that instance's Set accessor (before: E0338 "the
//!   property's value is a copy"; PLC_JobManagementFramework).

mod common;
use common::{check_text, column, run_stimulated, run_text};

/// An enumeration without `{attribute 'strict'}` as a FOR counter (Boot-folder-swap-from-PLC's
/// `FOR eVariantIndex := E_Variant.Unknown + 1 TO E_Variant.End - 1 DO`): the loop runs over the
/// values 1 and 2 (`n` = 2, `sum` = 1 + 2, the elements 1 and 2 of an array indexed by the
/// enumeration set, 0 and 3 not), and the counter ends one past the limit (3), as an integer
/// counter does. One W1439 for the POU. Before: E3100 "the FOR control variable `e` must be an
/// integer variable, but it is E_Variant", though `e := E_Variant.Unknown + 1;` was accepted.
#[test]
fn for_counter_over_a_non_strict_enumeration_runs_through_its_numbers() {
    let src = "TYPE E_Variant : (Unknown := 0, RevA := 1, RevB := 2, Last := 3); END_TYPE
PROGRAM main
VAR
  e : E_Variant;
  n : INT;
  sum : INT;
  after : E_Variant;
  seen : ARRAY[E_Variant.Unknown..E_Variant.Last] OF BOOL;
END_VAR
n := 0;
sum := 0;
FOR e := E_Variant.Unknown + 1 TO E_Variant.Last - 1 DO
  seen[e] := TRUE;
  n := n + 1;
  sum := sum + e;
END_FOR
after := e;
END_PROGRAM
";
    let (code, lines) = check_text("enum_for.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(lines.iter().all(|l| !l.contains("error[")), "{lines:?}");
    let (trace, _) = run_text(
        "enum_for.st",
        src,
        2,
        "main.n,main.sum,main.after,main.seen[0],main.seen[1],main.seen[2],main.seen[3]",
    );
    for (name, want) in [
        ("main.n", 2.0),
        ("main.sum", 3.0),
        ("main.after", 3.0),
        ("main.seen[0]", 0.0),
        ("main.seen[1]", 1.0),
        ("main.seen[2]", 1.0),
        ("main.seen[3]", 0.0),
    ] {
        assert_eq!(column(&trace, name), [want, want], "{name}: {trace}");
    }
}

/// Under `{attribute 'strict'}` the enumeration keeps IEC 61131-3's strong typing (Infosys,
/// "Attribute 'strict'": arithmetic on its variables is a compile error): one E3100 at the
/// counter, as before.
#[test]
fn for_counter_over_a_strict_enumeration_stays_e3100() {
    let src = "{attribute 'strict'}
TYPE E_Strict : (sA, sB, sC); END_TYPE
PROGRAM main
VAR
  s : E_Strict;
  n : INT;
END_VAR
FOR s := E_Strict.sA TO E_Strict.sC DO
  n := n + 1;
END_FOR
END_PROGRAM
";
    let (code, lines) = check_text("strict_for.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("strict_for.st:8:5: error[E3100]: the FOR control variable `s` must be an integer variable, but it is E_Strict"),
        "{lines:?}"
    );
}

/// TF6350_SMS_SMTP's edge detector named `R_Edge` in a TwinCAT object.
const R_EDGE_NAMED: &str = "<?xml version=\"1.0\" encoding=\"utf-8\"?>
<TcPlcObject Version=\"1.1.0.1\">
  <POU Name=\"MAIN\" Id=\"{00000000-0000-4000-8000-000000000032}\" SpecialFunc=\"None\">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
\tbIn : BOOL;
\tR_Edge : R_TRIG;
\tF_Edge : F_TRIG;
\tnRising : INT;
\tnFalling : INT;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[R_Edge(CLK := bIn);
F_Edge(CLK := bIn);
IF R_Edge.Q THEN
\tnRising := nRising + 1;
END_IF
IF F_Edge.Q THEN
\tnFalling := nFalling + 1;
END_IF]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
";

/// `R_Edge : R_TRIG;` and `F_Edge : F_TRIG;` in a `.TcPOU` are variables: one W1451 at each
/// declaration, no error, and the instances count the edges of `bIn` (TRUE at cycles 1 and 5,
/// FALSE at 3: rising edges at 1 and 5; F_TRIG fires at the first scan, its memory starting
/// FALSE as IEC 61131-3 declares it, and at 3). Before: E1031 "`R_Edge` is
/// reserved in IEC 61131-3 (a keyword)" and the POU's body was not compiled.
#[test]
fn twincat_variable_named_r_edge_counts_edges() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("MAIN.TcPOU");
    std::fs::write(&file, R_EDGE_NAMED).unwrap();
    let out = common::ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let lines = common::diagnostic_heads(&out.stderr, dir.path(), true);
    assert_eq!(
        lines,
        [
            "MAIN.TcPOU:7:2: warning[W1451]: `R_Edge` is an IEC 61131-3 edge qualifier (`x : BOOL R_EDGE;`): accepted as a variable name, as TwinCAT does",
            "MAIN.TcPOU:8:2: warning[W1451]: `F_Edge` is an IEC 61131-3 edge qualifier (`x : BOOL R_EDGE;`): accepted as a variable name, as TwinCAT does",
        ],
        "{lines:?}"
    );
    let (trace, _) = run_stimulated(
        &file,
        7,
        "1,MAIN.bIn,TRUE\n3,MAIN.bIn,FALSE\n5,MAIN.bIn,TRUE\n",
        "MAIN.nRising,MAIN.nFalling",
    );
    assert_eq!(
        column(&trace, "MAIN.nRising"),
        [0.0, 1.0, 1.0, 1.0, 1.0, 2.0, 2.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "MAIN.nFalling"),
        [1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 2.0],
        "{trace}"
    );
}

/// In an IEC 61131-3 text (`.st`) the same name stays one E1031 at the declaration: ed. 3
/// reserves R_EDGE as the qualifier of an edge-triggered input.
#[test]
fn st_variable_named_r_edge_stays_one_e1031() {
    let (code, lines) = check_text(
        "edge.st",
        "PROGRAM main\nVAR\n  R_Edge : R_TRIG;\n  b : BOOL;\nEND_VAR\nR_Edge(CLK := b);\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("edge.st:3:3: error[E1031]: `R_Edge` is reserved in IEC 61131-3"),
        "{lines:?}"
    );
}

/// Tc2_Standard's nine WSTRING functions, formal (with Tc2_Standard's input names) and
/// positional, give the values of their STRING namesakes on WSTRING; a position out of range is
/// the run-time check's report, as for MID. Before: E1019 "unknown function `WMID`" (likewise
/// `WLEN`, `WCONCAT`).
#[test]
fn tc2_standard_wstring_functions_run() {
    let src = r#"PROGRAM main
VAR
  w : WSTRING := "Hello World";
  l, m, c, r, i, d, x, beyond : WSTRING;
  n, p : INT;
END_VAR
l := WLEFT(STR := w, SIZE := 5);
m := WMID(STR := w, LEN := 5, POS := 7);
n := WLEN(w);
c := WCONCAT(l, m);
r := WRIGHT(w, 3);
i := WINSERT(STR1 := l, STR2 := "__", POS := 2);
d := WDELETE(w, 6, 1);
x := WREPLACE(w, "XY", 2, 1);
p := WFIND(w, "World");
beyond := WMID(w, 5, 20);
END_PROGRAM
"#;
    let (trace, stderr) = run_text(
        "wstring.st",
        src,
        1,
        "main.l,main.m,main.n,main.c,main.r,main.i,main.d,main.x,main.p,main.beyond",
    );
    assert_eq!(
        trace.lines().nth(1),
        Some(r#"0,0,"Hello","World",11,"HelloWorld","rld","He__llo","World","XYllo World",7,"""#),
        "{trace}"
    );
    assert!(
        stderr.contains("string length or position out of range"),
        "{stderr}"
    );
}

/// Tc2_Standard's WLEN takes a WSTRING: a STRING given to it is one E1410 at the call.
#[test]
fn tc2_standard_wlen_of_a_string_is_e1410() {
    let (code, lines) = check_text(
        "wlen.st",
        "PROGRAM main\nVAR\n  s : STRING := 'abc';\n  n : INT;\nEND_VAR\nn := WLEN(s);\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("wlen.st:6:6: error[E1410]: `WLEN` takes WSTRING inputs, not STRING"),
        "{lines:?}"
    );
}

/// PLC_JobManagementFramework's pattern: `PROPERTY executor : I_Job` of a future, and
/// `keepJob` a PROPERTY of the interface I_Job.
const INTERFACE_PROPERTY: &str = "INTERFACE I_Job
PROPERTY keepJob : BOOL
GET END_GET
SET END_SET
END_PROPERTY
END_INTERFACE

FUNCTION_BLOCK FB_Job IMPLEMENTS I_Job
VAR
  _keep : BOOL;
END_VAR
PROPERTY keepJob : BOOL
GET
  keepJob := _keep;
END_GET
SET
  _keep := keepJob;
END_SET
END_PROPERTY
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB_Future
VAR
  _job : I_Job;
END_VAR
PROPERTY executor : I_Job
GET
  executor := _job;
END_GET
SET
  _job := executor;
END_SET
END_PROPERTY
END_FUNCTION_BLOCK

PROGRAM main
VAR
  job, other : FB_Job;
  fut, unbound : FB_Future;
  seen, seenOther : BOOL;
  cycle : INT;
END_VAR
fut.executor := job;
fut.executor.keepJob := cycle < 2;
seen := job.keepJob;
unbound.executor.keepJob := TRUE;
seenOther := other.keepJob;
cycle := cycle + 1;
END_PROGRAM
";

/// `fut.executor.keepJob := cycle < 2;` reaches the job the future's interface refers to: its
/// keepJob is TRUE in the first two scans and FALSE after (written through, each scan); another
/// job is untouched, and a future whose interface was never assigned drops the write (the
/// run-time check's NULL report, no crash under the sanitizers). Before: E0338 "a component of
/// property `executor` cannot be written: the property's value is a copy".
#[test]
fn property_of_an_interface_a_property_returns_is_written_through() {
    let (trace, stderr) = run_text(
        "future.st",
        INTERFACE_PROPERTY,
        4,
        "main.seen,main.seenOther",
    );
    assert_eq!(column(&trace, "main.seen"), [1.0, 1.0, 0.0, 0.0], "{trace}");
    assert_eq!(column(&trace, "main.seenOther"), [0.0; 4], "{trace}");
    assert!(stderr.contains("unassigned interface"), "{stderr}");
}
