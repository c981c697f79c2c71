//! Round 29 of unseen projects, plain Structured Text (issue #13): one cause, one located
//! diagnostic, and the rest of the file still read.
//! - text outside every POU of an `.st` file (PC WORX writes a POU's description as bare text
//!   between `(*@KEY@:DESCRIPTION*)` and `(*@KEY@:END_DESCRIPTION*)`, OSCAT for PC WORX) is one
//!   E0307 at its first line, also when it holds the word `function`, `var` or `type` (before: read
//!   as IL, "unexpected `function` after the instruction" with IL advice, and the FUNCTION after
//!   it swallowed, its `END_FUNCTION` a second error);
//! - `END_STRUCT` without `;` before the next type is one E0011, the `;` supplied (before: a second
//!   E0011 at `END_TYPE`);
//! - an undeclared instance used (`fbAxis.Enable`) and called (`fbAxis();`) is one error (before:
//!   E1001 and E1019 "unknown function");
//! - an unknown library qualifier (E1032) no longer hides the program's independent errors;
//! - a RuSTy generic header `FUNCTION Pick<T : ANY_INT> : T` is one E1085 (before: E0100, W1426,
//!   E0106 and a misleading E0354/E1020 at its calls);
//! - E0335 shows the VAR_OUTPUT parameters of both signatures (before: two identical texts);
//! - `run` of an input that declares nothing warns W1441, as for one holding only functions.

mod common;
use common::{check_text, in_dir, write_in};

/// The lines of `lines` that are errors.
fn errors(lines: &[String]) -> Vec<&String> {
    lines.iter().filter(|l| l.contains("error[")).collect()
}

/// IEC 61131-3 (ed. 3, 6.1 and Annex B.0: a library is made of POU, type, configuration and
/// global declarations; other text only in comments) has no bare text outside a POU. A
/// description written as bare text before a FUNCTION (PC WORX's export of OSCAT: "this function
/// calculates the arcus cos hyperbolicus" above `FUNCTION ACOSH:REAL`) is one E0307 at its first
/// line, and the FUNCTION after it is read (no error at its `END_FUNCTION`); the words `function`,
/// `var`, `type` in the text start no block. Before: E0011 "unexpected `function` after the
/// instruction" with IL advice, then E0011 "unexpected `END_FUNCTION`" (the FUNCTION was taken
/// for a POU named `adds` and never compiled).
#[test]
fn text_outside_any_pou_is_one_error_and_the_pou_after_it_is_read() {
    let src = "this function adds one to an external var of type INT
version 1.0 by hugo

FUNCTION AddOne : INT
VAR_INPUT x : INT; END_VAR
AddOne := x + 1;
END_FUNCTION

PROGRAM Main
VAR n : INT; END_VAR
n := AddOne(n);
END_PROGRAM
";
    let (code, lines) = check_text("addone.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].starts_with("addone.st:1:1: error[E0307]: text outside any POU"),
        "{lines:?}"
    );
    assert!(errs[0].contains("in comments"), "{lines:?}");
    assert!(!lines.iter().any(|l| l.contains("W0001")), "{lines:?}");

    // the same text after the program: one error there; the program before it stays whole
    let src = "PROGRAM Main
VAR n : INT; END_VAR
n := n + 1;
END_PROGRAM
revision history: the function counts
";
    let (_, lines) = check_text("tail.st", src);
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].starts_with("tail.st:5:1: error[E0307]: text outside any POU"),
        "{lines:?}"
    );

    // the description in a comment: the program runs
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "ok.st",
        "(* this function adds one *)\nFUNCTION AddOne : INT\nVAR_INPUT x : INT; END_VAR\nAddOne := x + 1;\nEND_FUNCTION\nPROGRAM Main\nVAR n : INT; END_VAR\nn := AddOne(n);\nEND_PROGRAM\n",
    );
    let (code, stdout, stderr) = in_dir(
        dir.path(),
        &["run", "ok.st", "--cycles", "3", "--watch", "Main.n"],
    );
    assert_eq!(code, Some(0), "{stderr}");
    let n = common::column(&stdout, "Main.n");
    assert_eq!(n, vec![1.0, 2.0, 3.0], "{stdout}");
}

/// `END_STRUCT` then the next type's name without the `;` between (nni537014-collab/stGeo): IEC
/// 61131-3 ends each type declaration with `;` (ed. 3, B.1.3), so one E0011 where it belongs, and
/// the `;` supplied as its hint says: `Pts` is read as the next type. Before: a second E0011
/// "unexpected `END_TYPE`", `Pts` read as one more field of the closed structure.
#[test]
fn a_missing_semicolon_after_end_struct_is_one_error() {
    let src = "TYPE
P2 : STRUCT
  X : LREAL;
  Y : LREAL;
END_STRUCT
Pts : ARRAY[0..3] OF P2;
END_TYPE

PROGRAM M
VAR p : Pts; END_VAR
p[0].X := 1.0;
END_PROGRAM
";
    let (code, lines) = check_text("types.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].starts_with(
            "types.st:5:11: error[E0011]: missing `;` after `END_STRUCT` before `Pts`"
        ),
        "{lines:?}"
    );
    assert!(errs[0].contains("`END_STRUCT;`"), "{lines:?}");
}

/// An instance whose declaration is missing (a B&R program without its `.var` file), used as
/// `fbAxis.Enable := TRUE;` and called `fbAxis();`: one E1001 at its first use; the call is not a
/// second error "unknown function" (it never was a function). Called first, it is one E1019 and
/// the later uses are not reported. Before: E1001 and E1019, for one missing declaration.
#[test]
fn an_undeclared_instance_used_and_called_is_one_error() {
    let (code, lines) = check_text(
        "axis.st",
        "PROGRAM P\nfbAxis.Enable := TRUE;\nfbAxis();\nfbAxis.Enable := FALSE;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].starts_with("axis.st:2:1: error[E1001]: undeclared name `fbAxis`"),
        "{lines:?}"
    );
    let (_, lines) = check_text(
        "call.st",
        "PROGRAM P\nfbAxis();\nfbAxis.Enable := TRUE;\nEND_PROGRAM\n",
    );
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].starts_with("call.st:2:1: error[E1019]: unknown function `fbAxis`"),
        "{lines:?}"
    );
}

/// An unknown library qualifier (`Vendor.Connect()`, `c : Vendor.Client`; katrinemrahbek's
/// `DC_ECP.TcpClientByteStream`) is one E1032, and the program's other, independent errors are
/// reported in the same run: the undeclared `carrierId`, the missing global list `GVL`. Uses of
/// the library's names are not reported again (no E1019 or E1003 for them). Before: the E1032
/// alone; the rest appeared only once it was fixed.
#[test]
fn an_unknown_library_does_not_hide_independent_errors() {
    let src = "PROGRAM P
VAR
  s : STRING;
  c : Vendor.Client;
END_VAR
Vendor.Connect();
c(Host := 'plc');
s := UINT_TO_STRING(carrierId);
GVL.xMotor := TRUE;
Vendor.Disconnect();
END_PROGRAM
";
    let (code, lines) = check_text("lib.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 3, "{lines:?}");
    assert!(
        errs[0]
            .starts_with("lib.st:4:7: error[E1032]: `Vendor` is neither a variable nor a library"),
        "{lines:?}"
    );
    assert!(
        errs[1].starts_with("lib.st:8:21: error[E1001]: undeclared name `carrierId`"),
        "{lines:?}"
    );
    assert!(
        errs[2].starts_with("lib.st:9:1: error[E1001]: undeclared name `GVL`"),
        "{lines:?}"
    );
}

/// `FUNCTION Pick<T : ANY_INT> : T` (RuSTy's generic functions; DoubleCouponDay/stickle's `SQRT<T :
/// ANY_REAL>`): IEC 61131-3 has generic types for its standard functions only (ed. 3, 6.6.2.5), so
/// one E1085 at the name and its type parameters; the function is not compiled and its calls are
/// not reported, while the program's own error is. Before: E0100 at `<`, W1426 (`b : T;` read as a
/// label), two E0106, and E1020 "Pick takes 0 inputs, 2 given" at the call.
#[test]
fn a_generic_function_header_is_one_error() {
    let src = "FUNCTION Pick<T : ANY_INT> : T
VAR_INPUT
  a : T;
  b : T;
END_VAR
Pick := a;
END_FUNCTION

PROGRAM P
VAR x : INT; END_VAR
Pick(1, 2);
x := Pick(3, 4) + y;
END_PROGRAM
";
    let (code, lines) = check_text("pick.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "pick.st:1:10: error[E1085]: `Pick<T : ANY_INT>`: a generic function (RuSTy) is not IEC 61131-3"
        ),
        "{lines:?}"
    );
    assert!(
        lines[1].starts_with("pick.st:12:19: error[E1001]: undeclared name `y`"),
        "{lines:?}"
    );
}

/// A method that implements an interface's method with another VAR_OUTPUT (Moilion-Group/tankvalve:
/// `valveState` where the interface says `outPutSignal`) is rejected (IEC 61131-3 ed. 3, 6.6.5: the
/// implementation has the interface method's signature), and E0335 shows both signatures with their
/// outputs. Before: "is `WriteCyclic()`, but interface `IValve` declares `WriteCyclic()`".
#[test]
fn e0335_shows_the_outputs_that_differ() {
    let src = "INTERFACE IValve
  METHOD WriteCyclic
    VAR_OUTPUT outSignal : BOOL; END_VAR
  END_METHOD
END_INTERFACE

CLASS Valve IMPLEMENTS IValve
  VAR _open : BOOL; END_VAR
  METHOD PUBLIC WriteCyclic
    VAR_OUTPUT state : BOOL; END_VAR
    state := _open;
  END_METHOD
END_CLASS
";
    let (code, lines) = check_text("valve.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].starts_with("valve.st:9:17: error[E0335]: method `WriteCyclic` of `Valve` is `WriteCyclic(VAR_OUTPUT state : BOOL)`, but interface `IValve` declares `WriteCyclic(VAR_OUTPUT outSignal : BOOL)`"),
        "{lines:?}"
    );
}

/// `run` of an input that declares nothing (john-savill/plc_build_env's placeholder: two comment
/// lines) warns W1441 at the start of the file, as it does for inputs holding only functions;
/// the cycles still run (exit 0). Before: no word at all.
#[test]
fn running_an_input_that_declares_nothing_warns() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "plc.st",
        "// empty .st file\n// nothing here yet\n",
    );
    let (code, stdout, stderr) = in_dir(dir.path(), &["run", "plc.st", "--cycles", "2"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        stderr.contains("plc.st:1:1: warning[W1441]: nothing to run: the inputs declare no PROGRAM (no POU at all)"),
        "{stderr}"
    );
    assert_eq!(stderr.matches("warning[").count(), 1, "{stderr}");
    assert!(stdout.starts_with("cycle,time_ms"), "{stdout}");
}
