//! Round 27 of unseen projects (issue #13): one located diagnostic per cause, never a cascade,
//! nothing hidden behind an unrelated error:
//! - a name with letters beyond ASCII (`Мотор`, `Motor_ä`, which CODESYS 3 accepts) is one E1089
//!   per name and file, at its first occurrence, and read as one name (before: one E0001 or E0101
//!   per character and use, 2166 in one project);
//! - an unknown type used by several declarations in ST is one E1003 counting its uses, as the
//!   PLCopen XML reader's E3009 does (before: one E1003 per declaration);
//! - a block whose EXTENDS base is missing keeps its IMPLEMENTS: only the E0330 (before: an E0340
//!   at every assignment of an instance to the interface);
//! - `LOWER_BOUND`/`UPPER_BOUND` of a field of a variable whose library type is missing: only the
//!   E1032 of the library (before: one E1070 per call);
//! - an array bound naming an undeclared constant (E0022) no longer hides the file's unknown types
//!   (before: they came only once the constant was supplied);
//! - `VAR_TEMP ... END_VAR` among the statements is one error at its keyword (before: one per
//!   line, one at END_VAR and a false W1426 "jumps" for a declaration read as a label);
//! - `METHOD m : T;` among a block's declarations is named a METHOD (before: "this PROPERTY
//!   cannot be read" with PROPERTY's hint);
//! - a `#` comment line in IL is one E0001 (before: one error per odd character of the line);
//! - a body that is the empty statement `;` is no W0017 (the fix came with `unseen_projects_r27`;
//!   checked here on the input where it showed beside E0022).

mod common;
use common::{check_text, column, run_text};

/// Names with letters beyond ASCII: one E1089 per name, at the first occurrence (the enum value in
/// the TYPE, the declarations), none at the uses, no E0001/E0101 per character; exit 1.
#[test]
fn a_non_ascii_name_is_one_error_per_name() {
    let src = "TYPE E_Axis : (Lift := 1, Turn := 2, Motor_\u{e4} := 3); END_TYPE
PROGRAM Main
VAR
  \u{41c}\u{43e}\u{442}\u{43e}\u{440} : BOOL;
  \u{8c03}\u{6a21}A\u{8f74} : INT;
  n : INT;
END_VAR
\u{41c}\u{43e}\u{442}\u{43e}\u{440} := TRUE;
\u{8c03}\u{6a21}A\u{8f74} := \u{8c03}\u{6a21}A\u{8f74} + 1;
n := \u{8c03}\u{6a21}A\u{8f74};
END_PROGRAM
";
    let (code, lines) = check_text("intl.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 3, "{lines:?}");
    assert!(
        lines.iter().all(|l| l.contains("error[E1089]")),
        "{lines:?}"
    );
    assert!(lines[0].starts_with("intl.st:1:"), "{lines:?}");
    assert!(lines[0].contains("`Motor_\u{e4}`"), "{lines:?}");
    assert!(lines[1].starts_with("intl.st:4:3:"), "{lines:?}");
    assert!(lines[2].starts_with("intl.st:5:3:"), "{lines:?}");
    // in IL too, also on a line `LD name` read in one piece
    let il =
        "PROGRAM Main\nVAR \u{fc}ber : BOOL; x : BOOL; END_VAR\nLD \u{fc}ber\nST x\nEND_PROGRAM\n";
    let (code, lines) = check_text("intl.il", il);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("intl.il:2:5: error[E1089]"),
        "{lines:?}"
    );
    // letters beyond ASCII in comments and strings stay fine: the same program renamed runs
    let ok = "PROGRAM Main
VAR
  motor : BOOL; (* \u{41c}\u{43e}\u{442}\u{43e}\u{440} *)
  n : INT;
  s : STRING := '\u{e4}';
END_VAR
motor := TRUE;
n := n + 1;
END_PROGRAM
";
    let (trace, stderr) = run_text("intl_ok.st", ok, 2, "Main.n");
    assert_eq!(column(&trace, "Main.n"), [1.0, 2.0], "{stderr}");
}

/// Three instances of a block nothing declares: one E1003 at the first, "(3 uses)".
#[test]
fn an_unknown_type_of_several_declarations_is_one_error() {
    let src = "PROGRAM Sim
VAR
  motor  : DeviceModel;
  valve1 : DeviceModel;
  valve2 : DeviceModel;
  n : INT;
END_VAR
motor();
valve1();
valve2();
n := n + 1;
END_PROGRAM
";
    let (code, lines) = check_text("sim.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("sim.st:3:12: error[E1003]: unknown type `DeviceModel` (3 uses)"),
        "{lines:?}"
    );
}

/// `FUNCTION_BLOCK FB_Item EXTENDS Lib.Base IMPLEMENTS I_Item` with the base missing: the E0330
/// alone, no E0340 at `it := item`; with the base given, the same program runs through the
/// interface.
#[test]
fn a_missing_base_keeps_the_interfaces() {
    let prog = "INTERFACE I_Item
METHOD Get : INT
END_METHOD
END_INTERFACE

FUNCTION_BLOCK FB_Item EXTENDS BASE_REF IMPLEMENTS I_Item
METHOD Get : INT
Get := 7;
END_METHOD
END_FUNCTION_BLOCK

PROGRAM Main
VAR item : FB_Item; it : I_Item; n : INT; END_VAR
it := item;
n := it.Get();
END_PROGRAM
";
    let (code, lines) = check_text("items.st", &prog.replace("BASE_REF", "LibX.ElementBase"));
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(lines[0].contains("error[E0330]"), "{lines:?}");
    let with_base = format!(
        "FUNCTION_BLOCK ElementBase\nVAR x : INT; END_VAR\nEND_FUNCTION_BLOCK\n\n{}",
        prog.replace("BASE_REF", "ElementBase")
    );
    let (trace, stderr) = run_text("items_ok.st", &with_base, 1, "Main.n");
    assert_eq!(column(&trace, "Main.n"), [7.0], "{stderr}");
}

/// `LOWER_BOUND(pos.v, 1)` with `pos : LibMotion.POS_REF` (a library not given): the E1032 of the
/// library alone. A field that is no array of a known type is still E1070.
#[test]
fn the_bounds_of_a_field_of_a_missing_library_type_are_no_error() {
    let src = "PROGRAM Main
VAR
  pos : LibMotion.POS_REF;
  i : DINT;
  sum : LREAL;
END_VAR
FOR i := LOWER_BOUND(pos.v, 1) TO UPPER_BOUND(pos.v, 1) DO
  sum := sum + pos.v[i];
END_FOR
END_PROGRAM
";
    let (code, lines) = check_text("bounds.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(lines[0].contains("error[E1032]"), "{lines:?}");
    let known = "PROGRAM Main
VAR
  t : TON;
  i : DINT;
END_VAR
i := LOWER_BOUND(t.PT, 1);
END_PROGRAM
";
    let (code, lines) = check_text("bounds2.st", known);
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(lines[0].contains("error[E1070]"), "{lines:?}");
}

/// `ARRAY[0..BUF_SIZE]` with `BUF_SIZE` declared nowhere, beside two library types: the E0022 and
/// both E1003 in one run; the body `;` is no W0017.
#[test]
fn an_undeclared_bound_constant_hides_no_unknown_type() {
    let src = "FUNCTION_BLOCK FB_Fifo
VAR_INPUT
    sPut : T_LibString;
END_VAR
VAR
    fbRing : FB_LibRing;
    buffer : ARRAY[0..BUF_SIZE] OF BYTE;
END_VAR
;
END_FUNCTION_BLOCK
";
    let (code, lines) = check_text("fifo.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 3, "{lines:?}");
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("fifo.st:3:12: error[E1003]: unknown type `T_LibString`")),
        "{lines:?}"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("fifo.st:6:14: error[E1003]: unknown type `FB_LibRing`")),
        "{lines:?}"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("fifo.st:7:23: error[E0022]")),
        "{lines:?}"
    );
}

/// `VAR_TEMP k : REAL; m : REAL; END_VAR` after the first statement: one E0106 at VAR_TEMP, no
/// W1426; moved before the body, the same block runs.
#[test]
fn a_declaration_block_among_the_statements_is_one_error() {
    let src = "FUNCTION_BLOCK FB_Scale
VAR_INPUT
    x : REAL;
END_VAR
VAR_OUTPUT
    y : REAL;
END_VAR
y := x;
VAR_TEMP
    k : REAL;
    m : REAL;
END_VAR
k := 2.0;
y := x * k;
END_FUNCTION_BLOCK

PROGRAM Main
VAR
    fb : FB_Scale;
    r : REAL;
END_VAR
fb(x := 1.5);
r := fb.y;
END_PROGRAM
";
    let (code, lines) = check_text("scale.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("scale.st:9:1: error[E0106]: a declaration block `VAR_TEMP"),
        "{lines:?}"
    );
    let moved = src
        .replace("y := x;\nVAR_TEMP", "VAR_TEMP")
        .replace("END_VAR\nk := 2.0;", "END_VAR\ny := x;\nk := 2.0;");
    let (trace, stderr) = run_text("scale_ok.st", &moved, 1, "Main.r");
    assert_eq!(column(&trace, "Main.r"), [3.0], "{stderr}");
}

/// `METHOD Twice : INT;` among a block's declarations: one E0100 that says METHOD, with a
/// method's hint, not PROPERTY's.
#[test]
fn a_method_line_in_a_declaration_is_named_a_method() {
    let src = "FUNCTION_BLOCK FB_Twice
METHOD Twice : INT;

VAR_INPUT
    a : INT;
END_VAR
Twice := a * 2;
END_FUNCTION_BLOCK
";
    let (code, lines) = check_text("twice.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(lines[0].contains("error[E0100]"), "{lines:?}");
    assert!(lines[0].contains("this METHOD cannot be read"), "{lines:?}");
    assert!(lines[0].contains("END_METHOD"), "{lines:?}");
    assert!(!lines[0].contains("PROPERTY"), "{lines:?}");
}

/// A `# note: área` line in an IL body: one E0001 at the `#`, the rest of the line skipped.
#[test]
fn a_hash_comment_line_in_il_is_one_error() {
    let src = "PROGRAM main
VAR a : BOOL; END_VAR
# note: \u{e1}rea, x + y
LD a
ST a
END_PROGRAM
";
    let (code, lines) = check_text("hash.il", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("hash.il:3:1: error[E0001]: unexpected character `#`"),
        "{lines:?}"
    );
}
