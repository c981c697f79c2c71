//! Round 28 of unseen projects (issue #13): one cause, one located diagnostic that names it.
//! - an `ARRAY [*]` in-out passed on to a function declared nowhere (a vendor library's, SIMATIC
//!   AX's `SerializeBig`) is that function's E1019, once per POU (before: E1072 "used as a whole"
//!   once per call, and the function never named);
//! - `Unknown(x)^`, the dereferenced result of a function declared nowhere (SIMATIC AX's
//!   `AsAxisRef(axis)^`), is E1019 naming it (before: E0349 "is no method", plus E1088 when it was
//!   given to an in-out);
//! - an interface METHOD with an `ARRAY [*]` in-out is implemented by a block's method declared
//!   the same (before: a false E0335 comparing the block's hidden `__VLA`/`__LB1`/`__UB1` inputs
//!   with an interface method that had lost the parameter), and E0335 writes types as IEC does
//!   (`STRING(80)`, `POINTER TO LREAL`; before: `STRINGfalseSome(80)`, `Pointer TO LREAL`);
//! - `SIZEOF(T)` in a constant expression, `T` holding a field of a type declared nowhere, is that
//!   type's E1003 alone (before: also an E0022 saying `T` itself was not declared);
//! - an IL formal CAL whose parameter is split over two lines (`Q` alone, `=> done,` on the next)
//!   is one E0011 (before: three);
//! - an invalid operand on an IL deferred operator (`ADD( %MF3`) is its E0006 alone (before: also
//!   "unmatched `)`" at the `)` that closes it);
//! - an IEC 61131-10 XML file: the note says the format is IEC 61131-10, which ladderc does not
//!   read, as the E3002 after it (before: "read as PLCopen XML").

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

/// The lines of `lines` that are errors.
fn errors(lines: &[String]) -> Vec<&String> {
    lines.iter().filter(|l| l.contains("error[")).collect()
}

/// An `ARRAY [*]` in-out passed on, whole, to a function nothing declares: the function may well
/// take an `ARRAY [*]` (IEC 61131-3 ed. 3, 6.5.3), so the one error is the unknown function's
/// E1019, once per POU however many calls; a function passing it on to a declared `ARRAY [*]`
/// in-out still runs.
#[test]
fn an_array_star_passed_to_an_unknown_function_is_that_function_s_error() {
    let src = "FUNCTION Pack : UDINT
VAR_INPUT
    offset : UDINT;
END_VAR
VAR_IN_OUT
    buffer : ARRAY[*] OF BYTE;
END_VAR
Pack := VendorSerialize(offset := offset, value := 16#1234, buffer := buffer);
Pack := VendorSerialize(offset := offset + 2, value := 16#5678, buffer := buffer);
END_FUNCTION

PROGRAM Main
VAR
    b : ARRAY[0..3] OF BYTE;
    n : UDINT;
END_VAR
n := Pack(offset := 0, buffer := b);
END_PROGRAM
";
    let (code, lines) = check_text("pack.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].starts_with("pack.st:8:9: error[E1019]: unknown function `VendorSerialize`"),
        "{lines:?}"
    );

    // passed on to a declared ARRAY [*] in-out: compiled and run as before
    let src = "FUNCTION Total : INT
VAR_IN_OUT
    xs : ARRAY[*] OF INT;
END_VAR
VAR
    i : DINT;
END_VAR
Total := 0;
FOR i := LOWER_BOUND(xs, 1) TO UPPER_BOUND(xs, 1) DO
    Total := Total + xs[i];
END_FOR
END_FUNCTION

FUNCTION Outer : INT
VAR_IN_OUT
    ys : ARRAY[*] OF INT;
END_VAR
Outer := Total(xs := ys) * 2;
END_FUNCTION

PROGRAM Main
VAR
    a : ARRAY[1..3] OF INT := [1, 2, 4];
    r : INT;
END_VAR
r := Outer(ys := a);
END_PROGRAM
";
    let (trace, _) = run_text("outer.st", src, 1, "Main.r");
    assert_eq!(column(&trace, "Main.r"), vec![14.0], "{trace}");
}

/// `VendorAsRef(cnt)^` with `VendorAsRef` declared nowhere: E1019 names the function (as for a
/// plain call), and the in-out it is given has no E1088 of its own. A declared function's result
/// dereferenced stays E0349 (README "Call chains": only a method's result is accessed at once).
#[test]
fn the_dereferenced_result_of_an_unknown_function_names_it() {
    let src = "FUNCTION_BLOCK Counter
VAR_INPUT
    step : INT;
END_VAR
VAR_OUTPUT
    n : INT;
END_VAR
n := n + step;
END_FUNCTION_BLOCK

FUNCTION_BLOCK UseAxis
VAR_IN_OUT
    c : Counter;
END_VAR
c(step := 2);
END_FUNCTION_BLOCK

PROGRAM Main
VAR
    cnt : Counter;
    user : UseAxis;
    total : INT;
END_VAR
user(c := VendorAsRef(cnt)^);
total := VendorAsRef(cnt)^.n;
END_PROGRAM
";
    let (code, lines) = check_text("axis.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].starts_with("axis.st:24:11: error[E1019]: unknown function `VendorAsRef`"),
        "{lines:?}"
    );

    let src = "FUNCTION RefOf : REF_TO INT
VAR_IN_OUT
    x : INT;
END_VAR
RefOf := REF(x);
END_FUNCTION

PROGRAM Main
VAR
    a : INT := 4;
    b : INT;
END_VAR
b := RefOf(a)^;
END_PROGRAM
";
    let (_, lines) = check_text("declared.st", src);
    assert!(
        lines
            .iter()
            .any(|l| l.contains("error[E0349]: `RefOf` is no method")),
        "{lines:?}"
    );
}

/// An interface METHOD with an `ARRAY [*]` in-out (Beckhoff Infosys "ARRAY with variable length",
/// TcUnit-style assertion libraries): the block's method declared the same implements it, and
/// runs; a method that differs is E0335 with the types written as IEC writes them.
#[test]
fn an_interface_method_with_an_array_star_in_out_is_implemented() {
    let src = "INTERFACE I_Sum
METHOD M_Sum : LREAL
VAR_IN_OUT
    aValues : ARRAY[*] OF LREAL;
END_VAR
VAR_INPUT
    sTag : STRING(80);
END_VAR
END_METHOD
END_INTERFACE

FUNCTION_BLOCK FB_Sum IMPLEMENTS I_Sum
METHOD M_Sum : LREAL
VAR_IN_OUT
    aValues : ARRAY[*] OF LREAL;
END_VAR
VAR_INPUT
    sTag : STRING(80);
END_VAR
VAR
    i : DINT;
END_VAR
M_Sum := 0;
FOR i := LOWER_BOUND(aValues, 1) TO UPPER_BOUND(aValues, 1) DO
    M_Sum := M_Sum + aValues[i];
END_FOR
END_METHOD
END_FUNCTION_BLOCK

PROGRAM Main
VAR
    fb : FB_Sum;
    a : ARRAY[1..3] OF LREAL := [1.0, 2.0, 3.5];
    r : LREAL;
END_VAR
r := fb.M_Sum(aValues := a, sTag := 'x');
END_PROGRAM
";
    let (trace, _) = run_text("sum.st", src, 1, "Main.r");
    assert_eq!(column(&trace, "Main.r"), vec![6.5], "{trace}");

    // another length of the STRING input: E0335, both signatures in IEC spelling
    let wrong = src.replacen(
        "sTag : STRING(80);\nEND_VAR\nVAR\n",
        "sTag : STRING(40);\nEND_VAR\nVAR\n",
        1,
    );
    assert_ne!(wrong, src);
    let (code, lines) = check_text("sum.st", &wrong);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].contains(
            "error[E0335]: method `M_Sum` of `FB_Sum` is `M_Sum(aValues : ARRAY[*] OF LREAL, \
             sTag : STRING(40)) : LREAL`, but interface `I_Sum` declares `M_Sum(aValues : \
             ARRAY[*] OF LREAL, sTag : STRING(80)) : LREAL`"
        ),
        "{lines:?}"
    );
}

/// `SIZEOF(ST_Log)` in a constant expression, `ST_Log` declared with a field of a type declared
/// nowhere: the unknown type's E1003 is the one error. A structure whose fields are all known is
/// measured as before (its size in the run).
#[test]
fn sizeof_of_a_structure_with_an_unknown_field_type_is_that_type_s_error() {
    let src = "TYPE ST_Log :
STRUCT
    nId : UDINT;
    eSev : T_VendorSeverity;
END_STRUCT;
END_TYPE

TYPE ST_Entry :
STRUCT
    log : ST_Log;
    nCount : UINT;
END_STRUCT;
END_TYPE

PROGRAM Main
VAR CONSTANT
    cSize : UDINT := SIZEOF(ST_Log);
    cEntry : UDINT := SIZEOF(ST_Entry);
END_VAR
VAR
    n : UDINT;
END_VAR
n := cSize + cEntry;
END_PROGRAM
";
    let (code, lines) = check_text("log.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].starts_with("log.st:4:12: error[E1003]: unknown type `T_VendorSeverity`"),
        "{lines:?}"
    );

    let known = src.replace("T_VendorSeverity", "DINT");
    let (trace, _) = run_text("log.st", &known, 1, "Main.n");
    // ST_Log: 4 + 4 bytes; ST_Entry: 8 + 2, padded to 12
    assert_eq!(column(&trace, "Main.n"), vec![20.0], "{trace}");
}

/// IEC 61131-3 ed. 2 B.2.2: in IL a formal CAL's argument list has one assignment per line
/// (`il_param_out_assignment` is `variable_name '=>' variable`, then `',' EOL`), so `Q` alone with
/// `=> done,` on the next line is one error, at `Q`; the rest of the list is not reported again.
#[test]
fn an_il_call_parameter_split_over_two_lines_is_one_error() {
    let src = "PROGRAM Main
VAR
  t : TON;
  go : BOOL;
  done : BOOL;
  el : TIME;
END_VAR
  CAL t(
    IN := go,
    PT := T#1s,
    Q
    => done,
    ET => el)
  LD done
  ST go
END_PROGRAM
";
    let (code, lines) = check_text("split.il", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].starts_with("split.il:11:6: error[E0011]: expected `:=` or `=>`"),
        "{lines:?}"
    );

    // written on one line (and started), the same call runs: `done` is TRUE once 1 s has passed
    let fixed = src
        .replace("    Q\n    => done,", "    Q => done,")
        .replace("IN := go,", "IN := TRUE,");
    let (trace, _) = run_text("split.il", &fixed, 110, "Main.done");
    let done = column(&trace, "Main.done");
    assert_eq!((done[0], done[109]), (0.0, 1.0), "{trace}");
}

/// `ADD( %MF3` with an invalid direct address: its E0006 is the one error; the `)` on its own line
/// closes that `ADD(` and is no "unmatched `)`". A `)` that closes nothing still is.
#[test]
fn an_invalid_operand_of_a_deferred_operator_is_one_error() {
    let src = "PROGRAM Main
VAR
  a : REAL;
  b : REAL;
  c : REAL;
END_VAR
  LD a
  ADD( %MF3
  DIV b
  )
  ST c
END_PROGRAM
";
    let (code, lines) = check_text("paren.il", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].starts_with("paren.il:8:8: error[E0006]: invalid direct address"),
        "{lines:?}"
    );

    let stray = "PROGRAM Main
VAR
  a : REAL;
  c : REAL;
END_VAR
  LD a
  )
  ST c
END_PROGRAM
";
    let (_, lines) = check_text("stray.il", stray);
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("stray.il:7:3: error[E0011]: unmatched `)`")),
        "{lines:?}"
    );
}

/// An IEC 61131-10 XML exchange file (`<Project xmlns="www.iec.ch/public/TC65SC65BWG7TF10">`,
/// nodalis and B&R Automation Studio 6 write it) given without a telling extension: the note says
/// it is IEC 61131-10 XML, which ladderc does not read, as the E3002 after it does.
#[test]
fn an_iec_61131_10_file_is_named_so_by_its_note() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "plant.iec",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>
<Project xmlns=\"www.iec.ch/public/TC65SC65BWG7TF10\" schemaVersion=\"1.0\">
  <FileHeader companyName=\"Someone\" productName=\"Editor\" productVersion=\"1\"/>
  <ContentHeader name=\"Plant\"/>
  <Types/>
</Project>
",
    );
    let (code, _, stderr) = in_dir(dir.path(), &["check", "plant.iec"]);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains(
            "plant.iec:1:1: note[W0302]: detected from the content as IEC 61131-10 XML, which \
             ladderc does not read"
        ),
        "{stderr}"
    );
    assert!(!stderr.contains("PLCopen XML (detected"), "{stderr}");
    assert!(
        stderr.contains("error[E3002]: an IEC 61131-10 XML file"),
        "{stderr}"
    );
}
