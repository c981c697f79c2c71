//! Round 24 of unseen projects (issue #13): what real programs need, run end to end through
//! `ladderc run`:
//! - a comma after the last positional argument, `f(a, b, )` (Beckhoff's own samples write
//!   `ADSLOGSTR(t, 'msg', 'arg',);`; before: E0107; the formal form was accepted);
//! - CASE labels without their `CASE x OF` line: one error (before: one per label and one at
//!   END_CASE);
//! - a FUNCTION called without qualifier beside a `{attribute 'qualified_only'}` global of the same
//!   name (`StartUp()` beside `GVL.startUp`) calls the function (before: E3103 / E2005);
//! - `SIZEOF(x)` in a structured initial value (`(pData := ADR(v[1]), nSize := SIZEOF(v))`, also in
//!   a method's VAR_INST next to a computed field) is the constant it is in any declaration
//!   (before: E0022, E1075);
//! - Tc2_MC2 `MC_Power.Override` written as the instance's input before the call
//!   (`pw.Override := pct;`) scales the moves as the call's argument does (before: E1015, E1006 and
//!   E1041 for one statement);
//! - `ADR(Axis.NcToPlc.ActPos)` points at the member the simulated axis refreshes each scan
//!   (before: E1021 "AXIS_REF has no field NcToPlc", while the plain read was accepted);
//! - a comparison of two integer types neither of which holds the other (`INT < UDINT`) hints at
//!   the type that holds both (`LINT`), not at a conversion that changes the outcome;
//! - Tc2_System's `PVOID` (an untyped address) is a bounded `POINTER TO BYTE`: `p := ADR(x)`,
//!   MEMCPY through it, a method returning one (before: E1003 unknown type);
//! - a memory function given a pointer variable moved back, `MEMCPY(ADR(d), p - n, n)` (the last
//!   n characters before where `p` points, RoddenLab's RIGHT of a big string): bounded as the
//!   pointer it makes (before: E1035);
//! - an IEC 61131-10 XML file (B&R Automation Studio 6's LD) is one E3002 that names the format
//!   (before: "root element is <Project>, expected a PLCopen <project>");
//! - run-time sites of an `ARRAY [*]` element and of an ANY input's `pValue` are named as written
//!   (`varlen_arrays_run.rs`, `lang_left_r18.rs`).

mod common;
use common::{check_text, column, run_traced_files};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/unseen_r24")
        .join(name)
}

/// `Scale(3, 4, )` and `Scale(a := 3, b := 4, )` both call with two arguments.
#[test]
fn a_comma_after_the_last_positional_argument_ends_the_list() {
    let (trace, _) = common::run_text(
        "calls.st",
        "FUNCTION Scale : INT
VAR_INPUT
  a : INT;
  b : INT;
END_VAR
Scale := a * b;
END_FUNCTION

PROGRAM Main
VAR
  r1, r2 : INT;
END_VAR
r1 := Scale(a := 3, b := 4, );
r2 := Scale(5, 6, );
END_PROGRAM
",
        1,
        "Main.r1,Main.r2",
    );
    assert_eq!(trace.lines().nth(1), Some("0,0,12,30"), "{trace}");
}

/// Four labels and END_CASE without `CASE step OF`: one error at the first label; the statement
/// after END_CASE is read (its own syntax error is reported).
#[test]
fn case_labels_without_case_are_one_error() {
    let (code, lines) = check_text(
        "steps.st",
        "PROGRAM Main
VAR
  step, x : INT;
END_VAR
step := step + 1;
  1:
    x := 10;
  2, 3:
    x := 20;
  4..6:
    x := 30;
END_CASE;
x := ;
END_PROGRAM
",
    );
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        [
            "steps.st:6:3: error[E0100]: a CASE label outside a CASE statement (hint: write `CASE <selector> OF` before the first label)",
            "steps.st:13:6: error[E0107]: expected an expression, found `;` (hint: an expression is a variable, a literal, a function call or a combination with operators)",
        ]
    );
}

/// A qualified_only list's `startUp` and the FUNCTION `StartUp`: the unqualified calls (a call
/// statement and one in an expression) run the function, twice a scan while `GVL.startUp` is
/// FALSE; `GVL.startUp` is the variable.
#[test]
fn a_function_beside_a_qualified_only_global_of_its_name_is_called() {
    let (trace, _) = run_traced_files(
        &[
            &fixture("GVL.TcGVL"),
            &fixture("StartUp.TcPOU"),
            &fixture("MAIN.TcPOU"),
        ],
        3,
        "GVL.count,MAIN.ok,GVL.startUp",
    );
    // scan 1: 2 calls (1, 2); scan 2: 2 calls (3, 4), then startUp; scan 3: one call (5)
    assert_eq!(column(&trace, "GVL.count"), [2.0, 4.0, 5.0]);
    assert_eq!(column(&trace, "MAIN.ok"), [1.0, 1.0, 0.0]);
    assert_eq!(column(&trace, "GVL.startUp"), [0.0, 1.0, 1.0]);
}

/// `nSize := SIZEOF(values)` inside a structure's initial value (ten INTs: 20 bytes), in a
/// program's VAR and in a method's VAR_INST beside `pWork := ADR(vals[1])` (ten LREALs: 80).
#[test]
fn sizeof_in_a_structured_initial_value_is_a_constant() {
    let (trace, _) = common::run_text(
        "bufs.st",
        "TYPE ST_Buf :
STRUCT
  n : INT;
  pData : POINTER TO INT;
  nSize : UDINT;
END_STRUCT
END_TYPE
TYPE ST_Par :
STRUCT
  n : INT;
  pWork : POINTER TO LREAL;
  nSize : UDINT;
END_STRUCT
END_TYPE

FUNCTION_BLOCK FB_Filter
METHOD Check : UDINT
VAR_INST
  vals : ARRAY[1..10] OF LREAL;
  par : ST_Par := (n := 10, pWork := ADR(vals[1]), nSize := SIZEOF(vals));
END_VAR
par.pWork^ := 2.5;
Check := par.nSize + INT_TO_UDINT(par.n) + LREAL_TO_UDINT(vals[1]);
END_METHOD
END_FUNCTION_BLOCK

PROGRAM Main
VAR
  values : ARRAY [1..10] OF INT;
  buf : ST_Buf := (n := 10, pData := ADR(values[1]), nSize := SIZEOF(values));
  size, checked : UDINT;
  f : FB_Filter;
END_VAR
size := buf.nSize;
checked := f.Check();
END_PROGRAM
",
        1,
        "Main.size,Main.checked",
    );
    // 80 + 10 + 2 (2.5 rounds to even)
    assert_eq!(trace.lines().nth(1), Some("0,0,20,92"), "{trace}");
}

/// `pw.Override := ovr;` before `pw(...)` without an Override argument: 100 % runs at the
/// commanded 100 mm/s, 50 % at 50, 0 % stands; the field reads back what was written.
#[test]
fn mc_power_override_written_as_an_input_scales_the_moves() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("OverrideField.st")],
        300,
        "MAIN.shown,axis.X.velocity",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let v = column(&trace, "axis.X.velocity");
    let shown = column(&trace, "MAIN.shown");
    assert!((v[95] - 100.0).abs() < 1e-9, "{}", v[95]);
    assert!((v[195] - 50.0).abs() < 1e-9, "{}", v[195]);
    assert!(v[290..].iter().all(|&x| x == 0.0));
    assert_eq!((shown[95], shown[195], shown[295]), (100.0, 50.0, 0.0));
    assert!(v.iter().all(|&x| (0.0..=100.0 + 1e-9).contains(&x)));
}

/// `pPos := ADR(Axis.NcToPlc.ActPos); viaPointer := pPos^;` reads what `Axis.NcToPlc.ActPos`
/// reads, scan by scan, up to the target 50 mm (under the sanitizers).
#[test]
fn the_address_of_an_axis_member_reads_the_simulated_axis() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("AxisMemberAddress.st")],
        150,
        "MAIN.viaPointer,MAIN.direct",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let via = column(&trace, "MAIN.viaPointer");
    let direct = column(&trace, "MAIN.direct");
    assert_eq!(via, direct);
    assert!(via[30] > 10.0 && via[30] < 50.0, "{}", via[30]);
    assert_eq!(via[149], 50.0);
}

/// `i < u` of an INT and a UDINT (IEC 61131-3 has no implicit conversion between them): the hint
/// names LINT, which holds both, instead of UDINT_TO_INT (which changes the outcome of a large
/// u); INT and UINT: DINT.
#[test]
fn a_mixed_comparison_hints_at_the_type_holding_both() {
    let (code, lines) = check_text(
        "cmp.st",
        "PROGRAM P
VAR i : INT := 3; u : UDINT := 5; w : UINT := 2; b : BOOL; END_VAR
IF (i < u) THEN b := TRUE; END_IF;
b := w <= i;
END_PROGRAM
",
    );
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].ends_with("(hint: convert both to LINT, which holds every value of each (INT_TO_LINT, UDINT_TO_LINT))"),
        "{lines:?}"
    );
    assert!(
        lines[1].ends_with("(hint: convert both to DINT, which holds every value of each (UINT_TO_DINT, INT_TO_DINT))"),
        "{lines:?}"
    );
}

/// `p : PVOID := ADR(x)` then `MEMCPY(ADR(y), p, SIZEOF(x))` copies x; a method declared
/// `: PVOID` (Beckhoff's samples return nothing so) gives 0 (NULL); one W1425 (the pointer reads
/// an INT as bytes), no error.
#[test]
fn pvoid_is_an_untyped_bounded_address() {
    let (trace, stderr) = common::run_text(
        "pvoid.st",
        "FUNCTION_BLOCK FB_Station
METHOD Execute : PVOID
Execute := 0;
END_METHOD
END_FUNCTION_BLOCK

PROGRAM Main
VAR
  x : INT := 1234;
  y : INT;
  p : PVOID;
  st : FB_Station;
  isNull : BOOL;
END_VAR
p := ADR(x);
MEMCPY(ADR(y), p, SIZEOF(x));
isNull := st.Execute() = 0;
END_PROGRAM
",
        1,
        "Main.y,Main.isNull",
    );
    assert_eq!(trace.lines().nth(1), Some("0,0,1234,1"), "{trace}");
    assert_eq!(stderr.matches("warning[W1425]").count(), 1, "{stderr}");
    assert!(!stderr.contains("error"), "{stderr}");
}

/// B&R Automation Studio 6 writes LD in IEC 61131-10's XML (`<Project xmlns="www.iec.ch/public/
/// TC65SC65BWG7TF10">`): one error naming that format, not a PLCopen one.
#[test]
fn an_iec_61131_10_file_is_named_as_such() {
    let (code, lines) = check_text(
        "Cyclic.ld",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>
<?AutomationStudio FileVersion=\"6.0\"?>
<Project schemaVersion=\"1.0\" xmlns=\"www.iec.ch/public/TC65SC65BWG7TF10\">
  <FileHeader companyName=\"B&amp;R Industrial Automation GmbH\" productName=\"Automation Studio\" />
</Project>
",
    );
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        ["Cyclic.ld:3:1: error[E3002]: an IEC 61131-10 XML file (B&R Automation Studio 6 writes its LD and FBD so): ladderc reads PLCopen TC6 XML, not this format (hint: leave the file out (a B&R program's own declarations are then not compiled either, W0022), or give the POU as ST)"]
    );
}

/// `p` points just after a STRING's last character; `MEMCPY(ADR(d), p - n, n)` copies the last n
/// characters; moved before the string (`p - far`), the count is clipped to 0 and the site named
/// at the end of the run (under the sanitizers).
#[test]
fn a_pointer_variable_moved_back_bounds_a_memory_function() {
    let (trace, stderr) = common::run_text(
        "right.st",
        "PROGRAM Main
VAR
  s : STRING(20) := 'abcdefgh';
  d : ARRAY[0..9] OF BYTE;
  p : POINTER TO BYTE;
  n : DINT := 3;
  far : DINT := 40;
END_VAR
p := ADR(s) + 2 + 8; (* past the 2-byte length and the 8 characters *)
MEMCPY(ADR(d), p - n, n);
MEMCPY(ADR(d[5]), p - far, 2);
END_PROGRAM
",
        1,
        "Main.d[0],Main.d[1],Main.d[2],Main.d[5]",
    );
    assert_eq!(trace.lines().nth(1), Some("0,0,102,103,104,0"), "{trace}");
    assert!(
        stderr.contains("runtime: memory function count beyond its variables (first: MEMCPY in Main at right.st:11;"),
        "{stderr}"
    );
}
