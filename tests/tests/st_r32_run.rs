//! Round 32 of unseen projects (issue #13), plain Structured Text points, run end to end through
//! `ladderc run` / `ladderc check`:
//! - B&R Automation Studio's system stub `operator.fun` declares functions named by operator
//!   keywords (`FUNCTION AND : ANY`, `OR`, `XOR`, `NOT`, `MOD`): read as its other stubs, one note
//!   W0021, ladderc's operators stay (before: E0307, E0011 and E0008 per stub, and the project's
//!   own diagnostics hidden behind these parse errors);
//! - SIMATIC AX conditional compilation `{::ifdef X}` / `{::elseif Y}` / `{::else}` /
//!   `{::endif}` is evaluated as `{IF defined (X)}` (before: every branch compiled, W0300 "holds
//!   code that does not run" at each pragma);
//! - 4CONTROL's `#import "file.gvl"` is read as nothing with one note W1458 (before: E0023 "this
//!   file is Siemens SCL", the file not compiled); its `CONST ... END_CONST` is one E1095 per file;
//! - a variable named `this` (IEC 61131-3 ed. 2 code, where THIS is no keyword) is that variable
//!   (before: E1021 "`^` cannot follow it" at each use);
//! - a located variable, a direct bit address and a bit of a variable passed to a VAR_IN_OUT run,
//!   copied in and back (IEC 61131-3 ed. 3, 6.5.5 and 6.6.1.2.2; before: E2005);
//! - SHL, SHR, ROL and ROR of a BOOL (ed. 3 Table 24, IN is ANY_BIT) run: a rotation gives IN, a
//!   shift by N >= 1 gives FALSE (before: E2005).

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

/// B&R's `operator.fun` as Automation Studio ships it (its stubs, written here from the
/// library's interface: name, result, inputs, no statements).
const OPERATOR_FUN: &str = "{REDUND_OK} FUNCTION ADD : ANY (*adds*)
\tVAR_INPUT
\t\tINx\t:ANY;
\tEND_VAR
END_FUNCTION
{REDUND_OK} FUNCTION AND : ANY (*bitwise AND*)
\tVAR_INPUT
\t\tINx\t:ANY;
\tEND_VAR
END_FUNCTION
{REDUND_OK} FUNCTION XOR : ANY
\tVAR_INPUT
\t\tINx\t:ANY;
\tEND_VAR
END_FUNCTION
{REDUND_OK} FUNCTION OR : ANY
\tVAR_INPUT
\t\tINx\t:ANY;
\tEND_VAR
END_FUNCTION
{REDUND_OK} FUNCTION NOT : ANY
\tVAR_INPUT
\t\tIN\t:ANY;
\tEND_VAR
END_FUNCTION
{REDUND_OK} FUNCTION MOD : ANY_INT
\tVAR_INPUT
\t\tIN1\t:ANY_INT;
\t\tIN2\t:ANY_INT;
\tEND_VAR
END_FUNCTION
";

/// `operator.fun` with its keyword-named stubs (AND, XOR, OR, NOT, MOD) is one note W0021 naming
/// them; the program's own error (an undeclared name) is reported, alone (before round 32: 16
/// parse errors in `operator.fun` and the program's E1001 hidden).
#[test]
fn br_operator_fun_keyword_stubs_are_one_note() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "Logical/Libraries/operator/operator.fun",
        OPERATOR_FUN,
    );
    write_in(
        dir.path(),
        "Logical/Main/Main.st",
        "PROGRAM Main
VAR x : INT; b : BOOL; END_VAR
x := ADD(1, 2);
b := NOT b AND TRUE;
x := undeclaredName;
END_PROGRAM
",
    );
    let (code, _, err) = in_dir(
        dir.path(),
        &[
            "check",
            "--lang",
            "st",
            "Logical/Libraries/operator/operator.fun",
            "Logical/Main/Main.st",
        ],
    );
    assert_eq!(code, Some(1), "{err}");
    let errors: Vec<&str> = err.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{err}");
    assert!(
        errors[0].starts_with("Logical/Main/Main.st:5:6: error[E1001]")
            && errors[0].contains("undeclaredName"),
        "{err}"
    );
    let notes: Vec<&str> = err.lines().filter(|l| l.contains("note[W0021]")).collect();
    assert_eq!(notes.len(), 1, "{err}");
    assert!(
        notes[0].starts_with("Logical/Libraries/operator/operator.fun:1:22:")
            && notes[0].contains("declares 6 block(s)")
            && ["`AND`", "`XOR`", "`OR`", "`NOT`", "`MOD`"]
                .iter()
                .all(|n| notes[0].contains(n)),
        "{err}"
    );
}

/// With `operator.fun` given, ladderc's own operators run (AND, OR, XOR, NOT, MOD, ADD as a
/// function): the values cycle by cycle.
#[test]
fn br_operator_fun_program_runs_with_ladderc_operators() {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "operator.fun", OPERATOR_FUN);
    write_in(
        dir.path(),
        "Main.st",
        "PROGRAM Main
VAR n : INT; m : INT; w : WORD; b : BOOL; END_VAR
n := ADD(n, 1);
m := n MOD 3;
w := (INT_TO_WORD(n) AND 16#0006) OR 16#0100 XOR 16#0001;
b := NOT (m = 0);
END_PROGRAM
",
    );
    let (code, out, err) = in_dir(
        dir.path(),
        &[
            "run",
            "--lang",
            "st",
            "operator.fun",
            "Main.st",
            "--cycles",
            "4",
            "--trace",
            "-",
            "--watch",
            "Main.n,Main.m,Main.w,Main.b",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(column(&out, "Main.n"), [1.0, 2.0, 3.0, 4.0]);
    assert_eq!(column(&out, "Main.m"), [1.0, 2.0, 0.0, 1.0]);
    // (n AND 6) OR (16#100 XOR 1)
    assert_eq!(column(&out, "Main.w"), [257.0, 259.0, 259.0, 261.0]);
    assert_eq!(column(&out, "Main.b"), [1.0, 1.0, 0.0, 1.0]);
}

/// SIMATIC AX `{::ifdef}` sections: with no define the `{::else}` branch runs and the branches
/// naming variables of other variants are not compiled (no E1001); a `{define}` of the text
/// selects its branch. Before round 32 every branch was compiled (an E1001 for the name only the
/// other variant declares) and each pragma was W0300.
#[test]
fn ax_ifdef_sections_are_evaluated() {
    let src = "PROGRAM Main
VAR
    x : INT;
    y : INT;
END_VAR
{::ifdef VARIANT_A}
    x := 1;
{::elseif VARIANT_B}
    x := onlyInVariantB;
{::else}
    x := 3;
{::endif}
{define VARIANT_B}
{::ifdef VARIANT_A}
    y := onlyInVariantA;
{::elseif VARIANT_B}
    y := 20;
{::endif}
END_PROGRAM
";
    let (code, lines) = check_text("main.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(lines.is_empty(), "no W0300 any more: {lines:?}");
    let (trace, err) = run_text("main.st", src, 2, "Main.x,Main.y");
    assert_eq!(column(&trace, "Main.x"), [3.0, 3.0]);
    assert_eq!(column(&trace, "Main.y"), [20.0, 20.0]);
    // the note says which symbol is taken as not defined, once per name (VARIANT_A, VARIANT_B)
    assert_eq!(err.matches("note[W1419]").count(), 2, "{err}");
    assert!(
        err.contains("main.st:6:1: note[W1419]: `VARIANT_A` is not defined"),
        "{err}"
    );
}

/// 4CONTROL's `#import "Globals.gvl"` is one note W1458 at the directive; the globals come from
/// the file given as an input, and the program runs (before round 32: E0023 "this file is
/// Siemens SCL", the program not compiled).
#[test]
fn four_control_import_is_a_note_and_runs() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "globals.st",
        "VAR_GLOBAL\n    total : INT;\nEND_VAR\n",
    );
    write_in(
        dir.path(),
        "counter.st",
        "PROGRAM Counter_P
#import \"Globals.gvl\"
#import \"Other.gvl\"
VAR
    n : INT;
END_VAR
    n := n + 1;
    total := total + 2;
END_PROGRAM
",
    );
    let (code, _, err) = in_dir(dir.path(), &["check", "globals.st", "counter.st"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("E0023"), "{err}");
    let notes: Vec<&str> = err.lines().filter(|l| l.contains("W1458")).collect();
    assert_eq!(notes.len(), 1, "one note per file: {err}");
    assert!(
        notes[0].starts_with("counter.st:2:1: note[W1458]: `#import \"Globals.gvl\"` (4CONTROL"),
        "{err}"
    );
    let (code, out, err) = in_dir(
        dir.path(),
        &[
            "run",
            "globals.st",
            "counter.st",
            "--cycles",
            "3",
            "--trace",
            "-",
            "--watch",
            "globals.total,Counter_P.n",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(column(&out, "globals.total"), [2.0, 4.0, 6.0]);
    assert_eq!(column(&out, "Counter_P.n"), [1.0, 2.0, 3.0]);
}

/// 4CONTROL's block of constants `CONST ... END_CONST` (after `#import`) is
/// one E1095 at `CONST` for the file, which is not compiled: one error for the dialect, not one
/// E0106 per declaration read as a statement (which the file gave once `#import` was read).
#[test]
fn four_control_const_block_is_one_error() {
    let (code, lines) = check_text(
        "check_p.st",
        "PROGRAM Check_P
#import \"Resource1.gvl\"
CONST
    this : INT := 25;
    cases : INT := 5;
END_CONST
VAR
    r : ARRAY [1..cases] OF BOOL;
END_VAR
    r[1] := this > 0;
END_PROGRAM
",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("check_p.st:3:1: error[E1095]: `CONST ... END_CONST` is a block of constants of 4CONTROL"),
        "{lines:?}"
    );
    assert!(lines[0].contains("VAR CONSTANT"), "{lines:?}");
}

/// A POU's own variable named `this` (IEC 61131-3 ed. 2 code; 4CONTROL's test programs) is read
/// as that variable, given to a function and used in an expression (before round 32: E1021
/// "`this` is INT, not a reference: `^` cannot follow it" at each use).
#[test]
fn variable_named_this_is_that_variable() {
    let src = "FUNCTION Report : INT
VAR_INPUT id : INT; END_VAR
Report := id * 2;
END_FUNCTION
PROGRAM Main
VAR CONSTANT
    this : INT := 48;
END_VAR
VAR
    r, s : INT;
END_VAR
    r := Report(this);
    s := this + 1;
END_PROGRAM
";
    let (code, lines) = check_text("this.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    let (trace, _) = run_text("this.st", src, 2, "Main.r,Main.s");
    assert_eq!(column(&trace, "Main.r"), [96.0, 96.0]);
    assert_eq!(column(&trace, "Main.s"), [49.0, 49.0]);
}

/// A located variable (`counter AT %QW0`), a located BOOL (`flag AT %QX0.3`) and a bit of a
/// variable (`w.2`) given to a FUNCTION's VAR_IN_OUT: the function's writes reach them, and the
/// process image, cycle by cycle (before round 32: E2005 "a missing or located IN_OUT argument").
#[test]
fn located_variables_to_in_out_run() {
    let src = "VAR_GLOBAL
    counter AT %QW0 : UINT;
    flag AT %QX4.3 : BOOL;
END_VAR
FUNCTION Bump : BOOL
VAR_IN_OUT c : UINT; END_VAR
    c := c + 1;
    Bump := TRUE;
END_FUNCTION
FUNCTION Toggle : BOOL
VAR_IN_OUT b : BOOL; END_VAR
    b := NOT b;
    Toggle := b;
END_FUNCTION
PROGRAM Main
VAR ok, t : BOOL; w : WORD; END_VAR
    ok := Bump(counter);
    t := Toggle(flag);
    t := Toggle(w.2);
END_PROGRAM
";
    let (trace, _) = run_text(
        "located.st",
        src,
        3,
        "counter,flag,Main.ok,Main.w,%QW0,%QB4",
    );
    assert_eq!(column(&trace, "counter"), [1.0, 2.0, 3.0]);
    assert_eq!(column(&trace, "%QW0"), [1.0, 2.0, 3.0]);
    assert_eq!(column(&trace, "Main.ok"), [1.0, 1.0, 1.0]);
    assert_eq!(column(&trace, "flag"), [1.0, 0.0, 1.0]);
    assert_eq!(column(&trace, "%QB4"), [8.0, 0.0, 8.0]);
    assert_eq!(column(&trace, "Main.w"), [4.0, 0.0, 4.0]);
}

/// SHL, SHR, ROL and ROR of a BOOL: a rotation by any N gives IN back, a shift by N >= 1 gives
/// FALSE, by 0 (or a negative N) IN (before round 32: E2005 "the C backend does not support ROL on this type").
#[test]
fn shifts_and_rotations_of_a_bool_run() {
    let src = "PROGRAM Main
VAR
    b : BOOL := TRUE;
    n : INT;
    r1, r2, s1, s2, s3 : BOOL;
END_VAR
    r1 := ROL(b, n + 3);
    r2 := ROR(b, 1);
    s1 := SHL(b, n);
    s2 := SHR(b, 0);
    s3 := SHR(NOT b, n - 2);
    n := n + 1;
    IF n = 2 THEN b := FALSE; END_IF
END_PROGRAM
";
    let (trace, _) = run_text(
        "shifts.st",
        src,
        3,
        "Main.r1,Main.r2,Main.s1,Main.s2,Main.s3",
    );
    assert_eq!(column(&trace, "Main.r1"), [1.0, 1.0, 0.0]);
    assert_eq!(column(&trace, "Main.r2"), [1.0, 1.0, 0.0]);
    // n = 0, 1, 2: SHL by 0 keeps b, by 1 or more gives FALSE
    assert_eq!(column(&trace, "Main.s1"), [1.0, 0.0, 0.0]);
    assert_eq!(column(&trace, "Main.s2"), [1.0, 1.0, 0.0]);
    // a negative count leaves IN, as for the wider bit strings: SHR(FALSE, -2), SHR(FALSE, -1),
    // SHR(TRUE, 0)
    assert_eq!(column(&trace, "Main.s3"), [0.0, 0.0, 1.0]);
}
