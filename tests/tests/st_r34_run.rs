//! Round 34 of unseen projects (issue #13), plain Structured Text points, run end to end through
//! `ladderc run` / `ladderc check`:
//! - an integer initial value of an enumeration without `{attribute 'strict'}` (`k : E := 0;`,
//!   B&R's own `MpAlarmX.typ`: `Type : MpAlarmXActionEnum := 0;`) is taken as the assignment of
//!   that integer is, with one W1439 (before: E1025 while `e := 2;` in the body was W1439); a
//!   strict enumeration keeps E1025;
//! - a `.txt` file that holds no program (a Modbus register list) is one E1107 at its first line
//!   that is no comment (before: read as IL, two errors a line);
//! - a CASE label that names a value of the selector's enumeration is that value, also beside a
//!   variable of the same name in another letter case (before: the BOOL variable was compared with
//!   the selector, a false E1005 "EQ of Mode and BOOL").

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

/// A non-strict enumeration's initial values given as integers, in a variable declaration and in
/// a structure's field, run: the field's `1` is the value `b` (so `s1.k = b` holds each cycle),
/// `5` is `c`, and `7`, which no value has, is held as the number (CODESYS and TwinCAT hold such
/// an enumeration as its integer base type). One W1439 for the initial values of `E` (and the
/// body's own W1439), no error. Before round 34: E1025 "this initial value is not a E" twice.
#[test]
fn integer_initial_values_of_a_loose_enumeration_run() {
    let src = "TYPE E : (a := 0, b := 1, c := 5); END_TYPE
TYPE S : STRUCT k : E := 1; END_STRUCT; END_TYPE
PROGRAM main
VAR
  e1 : E;
  e2 : E := 5;
  e3 : E := 7;
  s1 : S;
  n : INT;
  seen_c : BOOL;
END_VAR
IF s1.k = b THEN n := n + 1; END_IF
seen_c := e2 = c;
e1 := 2;
END_PROGRAM
";
    let (trace, err) = run_text(
        "loose.st",
        src,
        3,
        "main.e1,main.e2,main.e3,main.s1.k,main.n,main.seen_c",
    );
    assert_eq!(column(&trace, "main.s1.k"), [1.0, 1.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "main.n"), [1.0, 2.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "main.e2"), [5.0, 5.0, 5.0], "{trace}");
    assert_eq!(column(&trace, "main.seen_c"), [1.0, 1.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "main.e3"), [7.0, 7.0, 7.0], "{trace}");
    assert_eq!(column(&trace, "main.e1"), [2.0, 2.0, 2.0], "{trace}");
    assert!(!err.contains("error["), "{err}");
    let inits: Vec<&str> = err
        .lines()
        .filter(|l| l.contains("W1439") && l.contains("initialised with an integer"))
        .collect();
    assert_eq!(inits.len(), 1, "{err}");
    assert!(inits[0].contains("loose.st:2:26:"), "{err}");
}

/// The B&R form: a library's `.typ` initialises an enumeration field with `0` (as B&R's
/// `MpAlarmX.typ` does), a program folder compares it with the value numbered 0 and counts. Run
/// with `--lang st` as a B&R `Logical/` tree: the count rises each cycle. Before round 34: E1025 in
/// the library file, nothing ran.
#[test]
fn br_library_enumeration_field_initialised_with_zero_runs() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "Logical/Libraries/Lib/Lib.typ",
        "TYPE
\tKindEnum :
\t\t(
\t\tkind_NONE := 0,
\t\tkind_REACT := 1
\t\t);
\tConfigType : \tSTRUCT
\t\tKind : KindEnum := 0;
\t\tLimit : INT := 3;
\tEND_STRUCT;
END_TYPE
",
    );
    write_in(
        dir.path(),
        "Logical/Prog/Main.st",
        "PROGRAM _CYCLIC
\tIF cfg.Kind = kind_NONE THEN
\t\tn := n + 1;
\tEND_IF
END_PROGRAM
",
    );
    write_in(
        dir.path(),
        "Logical/Prog/Variables.var",
        "VAR
\tcfg : ConfigType;
\tn : INT;
END_VAR
",
    );
    let (code, trace, err) = in_dir(
        dir.path(),
        &[
            "run",
            "--lang",
            "st",
            "Logical/Libraries/Lib/Lib.typ",
            "Logical/Prog/Main.st",
            "Logical/Prog/Variables.var",
            "--cycles",
            "3",
            "--trace",
            "-",
            "--watch",
            "Prog.n,Prog.cfg.Kind",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(column(&trace, "Prog.n"), [1.0, 2.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "Prog.cfg.Kind"), [0.0, 0.0, 0.0], "{trace}");
    assert!(
        err.contains("Logical/Libraries/Lib/Lib.typ:8:22: warning[W1439]"),
        "{err}"
    );
}

/// Under `{attribute 'strict'}` an integer initial value stays one E1025 (Beckhoff Infosys,
/// "Attribute 'strict'": storing another value into the enumeration is a compile error).
#[test]
fn strict_enumeration_integer_initial_value_stays_an_error() {
    let src = "{attribute 'strict'}
TYPE E : (a := 0, b := 1); END_TYPE
PROGRAM main
VAR e2 : E := 1; END_VAR
e2 := E.a;
END_PROGRAM
";
    let (code, lines) = check_text("strict.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("strict.st:4:15: error[E1025]: this initial value is not a E"),
        "{lines:?}"
    );
}

/// A `.txt` register list (no IL operator, no label, no POU or declaration on any line): one
/// E1107 at its first line that is no comment, saying it holds no program in any language
/// ladderc reads; no W0302 note that it was read as IL. Before round 34: the note, then an E0011
/// and an E0001 on each line (12 errors for these 6 lines).
#[test]
fn a_txt_register_list_is_one_error() {
    let src = "// ======
// HOLDING REGISTERS
// ======
0 - SPV_DAC
1 - SPV_W4_20
2 - SPV_PWM
(* COILS *)
0 - SPV_D2
1 - SPV_D3
2 - SPV_D4
";
    let (code, lines) = check_text("registers.txt", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "registers.txt:4:1: error[E1107]: this file holds no program in any language ladderc reads"
        ),
        "{lines:?}"
    );
    assert!(
        lines[0].contains("(hint: give the program's source"),
        "{lines:?}"
    );
}

/// A `.txt` of IL instructions outside any POU is still read as IL (W0302 says so) and runs as
/// before: the E1107 check does not take real IL for a note.
#[test]
fn a_txt_of_il_is_still_read_as_il() {
    let src = "PROGRAM main
VAR n : INT; END_VAR
(* count *)
    LD n
    ADD 1
    ST n
END_PROGRAM
";
    let (trace, err) = run_text("count.txt", src, 3, "main.n");
    assert!(err.contains("W0302"), "{err}");
    assert!(!err.contains("E1107"), "{err}");
    assert_eq!(column(&trace, "main.n"), [1.0, 2.0, 3.0], "{trace}");
}

/// A CASE label naming a value of the selector's enumeration (`BG_OPEN:`) beside a BOOL input of
/// the same name in another letter case (`bg_open`; IEC 61131-3 names ignore case) is the
/// enumerated value: IEC 61131-3 ed. 3, 7.3.3.3.3, a case label is a constant (ed. 2 B.3.2.2:
/// `case_list_element ::= subrange | signed_integer | enumerated_value`), never a variable. Run
/// with the mode stepping through the values: `Pos` follows the arm of each. Before round 34: two
/// E1005 "EQ of Mode and BOOL" at the labels (Mairooriam/automationLearning: 10 such errors).
#[test]
fn case_label_is_the_selector_enumeration_value_not_a_variable() {
    let src = "TYPE Mode : (BG_NONE := 0, BG_BOTH := 1, BG_OPEN := 2, BG_CLOSED := 3); END_TYPE
FUNCTION_BLOCK Valve
VAR_INPUT
    bg_open : BOOL;
    bg_closed : BOOL;
    bg_mode : Mode;
END_VAR
VAR_OUTPUT
    Pos : INT;
END_VAR
CASE bg_mode OF
    BG_BOTH:   Pos := 1;
    BG_OPEN:   Pos := 2;
    BG_CLOSED: Pos := 3;
ELSE
    Pos := 0;
END_CASE;
END_FUNCTION_BLOCK
PROGRAM main
VAR
    v : Valve;
    m : Mode;
    k : INT;
    p : INT;
END_VAR
CASE k OF
    0: m := BG_OPEN;
    1: m := BG_CLOSED;
    2: m := BG_BOTH;
ELSE
    m := BG_NONE;
END_CASE;
v(bg_open := TRUE, bg_closed := FALSE, bg_mode := m);
p := v.Pos;
k := k + 1;
END_PROGRAM
";
    let (trace, err) = run_text("valve.st", src, 4, "main.p");
    assert!(!err.contains("E1005"), "{err}");
    assert_eq!(column(&trace, "main.p"), [2.0, 3.0, 1.0, 0.0], "{trace}");
}
