//! Round 27 of unseen projects (issue #13): initial values, pointers and constant expressions
//! that real CODESYS/TwinCAT/IEC projects write, run end to end through `ladderc run`:
//! - a structure field initialised from a VAR_GLOBAL CONSTANT (`Magic : BYTE := C_MAGIC;`),
//!   declared before or after the type, in another file or in a CONFIGURATION (before: E1025
//!   "not a constant known here");
//! - a pointer moved by a bit-string byte count (`p + n` of a DWORD `n`) and the difference of two
//!   pointers typed DWORD as CODESYS documents (before: E1004 on `p + DWORD`, and `p - q` was an
//!   LINT, so `DWORD_TO_DINT(q - p)` was E1012);
//! - `ADR(v)` of a FUNCTION's own input or local, used during the call (before: E0305); a pointer
//!   to one stored where it outlives the call is W1444;
//! - a function block instance's structured initial value in a CONFIGURATION's VAR_GLOBAL
//!   (`t1 : Tank := (volume := 100.0);`; before: one E1025 per field);
//! - constant expressions inside structure initial values, also inside array initial values
//!   (`(dX := len / 2.0, dY := -len)`; before: E0011);
//! - a constant expression as a CASE label (`ST_RUN + ST_ERR:`, also in a range; before: E0106)
//!   and a CHAR literal label on a CHAR selector (`'0':`; before: two E0100 per branch);
//! - an array bound named by an enumerated value, `ARRAY[0..Limits#BUF_UPPER]` (before: E0011 and
//!   a cascading E1070);
//! - a bound naming a constant of a list that is not given (`RobotLibParams.TOOL_MAX`) is one E0022
//!   naming the constant as written and its list (before: `TOOL_MAX` alone);
//! - a misplaced `ARRAY [*]` (a FUNCTION's VAR_INPUT) is one E1072 (before: also one E1017 per
//!   LOWER_BOUND/UPPER_BOUND of it, naming an internal value, `literal -1701...728`).

mod common;
use common::{check_text, column, run_text, run_traced_files};

/// A STRUCT field whose initial value names a VAR_GLOBAL CONSTANT (IEC 61131-3 ed. 3: an initial
/// value is a constant expression, named constants included): declared before the type, after it,
/// and in a CONFIGURATION's VAR_GLOBAL CONSTANT; each instance starts with the constant's value.
#[test]
fn a_structure_field_starts_from_a_global_constant() {
    let src = "VAR_GLOBAL CONSTANT
    C_MAGIC : BYTE := 112;
    C_LIMIT : INT := C_LATE + 1;
END_VAR
TYPE T_Handle :
STRUCT
    Magic : BYTE := C_MAGIC;
    Limit : INT := C_LIMIT;
    Late : INT := C_LATE;
    Scale : REAL := C_SCALE;
END_STRUCT;
END_TYPE
VAR_GLOBAL CONSTANT
    C_LATE : INT := 41;
END_VAR
PROGRAM Main
VAR
    h : T_Handle;
    arr : ARRAY[0..1] OF T_Handle;
    m : BYTE;
END_VAR
m := h.Magic;
END_PROGRAM
CONFIGURATION Cell
    VAR_GLOBAL CONSTANT
        C_SCALE : REAL := 2.5;
    END_VAR
    RESOURCE R ON PLC
        TASK T (INTERVAL := T#10ms, PRIORITY := 1);
        PROGRAM P1 WITH T : Main;
    END_RESOURCE
END_CONFIGURATION
";
    let (trace, _) = run_text(
        "handle.st",
        src,
        1,
        "P1.m,P1.h.Limit,P1.h.Late,P1.arr[1].Magic,P1.arr[1].Scale",
    );
    assert_eq!(column(&trace, "P1.m"), [112.0], "{trace}");
    assert_eq!(column(&trace, "P1.h.Limit"), [42.0]);
    assert_eq!(column(&trace, "P1.h.Late"), [41.0]);
    assert_eq!(column(&trace, "P1.arr[1].Magic"), [112.0]);
    assert_eq!(column(&trace, "P1.arr[1].Scale"), [2.5]);
}

/// The same over three files (a CODESYS V2.3 export's global list, type and program): the
/// constant is declared in another file than the structure.
#[test]
fn a_structure_field_starts_from_a_constant_of_another_file() {
    let dir = tempfile::tempdir().unwrap();
    let files = [
        ("A_Consts.st", "VAR_GLOBAL CONSTANT\n    C_MAGIC : BYTE := 112;\nEND_VAR\n"),
        (
            "B_Type.st",
            "TYPE T_Handle :\nSTRUCT\n    Magic : BYTE := C_MAGIC;\nEND_STRUCT;\nEND_TYPE\n",
        ),
        (
            "C_Main.st",
            "PROGRAM Main\nVAR\n    h : T_Handle;\n    m : BYTE;\nEND_VAR\nm := h.Magic;\nEND_PROGRAM\n",
        ),
    ];
    let paths: Vec<_> = files
        .iter()
        .map(|(n, t)| {
            let p = dir.path().join(n);
            std::fs::write(&p, t).unwrap();
            p
        })
        .collect();
    let refs: Vec<&std::path::Path> = paths.iter().map(|p| p.as_path()).collect();
    let (trace, _) = run_traced_files(&refs, 1, "Main.m");
    assert_eq!(column(&trace, "Main.m"), [112.0], "{trace}");
}

/// A field initialised from a name that is no constant stays one E1025 at the name.
#[test]
fn a_structure_field_from_a_variable_stays_an_error() {
    let src = "VAR_GLOBAL
    g : BYTE := 3;
END_VAR
TYPE T_H : STRUCT Magic : BYTE := g; END_STRUCT; END_TYPE
PROGRAM Main
VAR h : T_H; END_VAR
END_PROGRAM
";
    let (code, lines) = check_text("h.st", src);
    assert_eq!(code, Some(1));
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("h.st:4:35: error[E1025]"),
        "{lines:?}"
    );
}

/// `q := p + n` with a DWORD `n` moves the pointer by n bytes (CODESYS: `piTemp + DWORD#1`), as
/// with BYTE, WORD and LWORD counts; `q - p` is a DWORD (CODESYS: the difference of two pointers
/// is of type DWORD), so `DWORD_TO_DINT(q - p)` is 3.
#[test]
fn a_pointer_moves_by_a_bit_string_and_a_difference_is_a_dword() {
    let src = "PROGRAM Main
VAR
    buf : ARRAY[0..7] OF BYTE;
    p, q : POINTER TO BYTE;
    n : DWORD := 3;
    w : WORD := 5;
    b : BYTE := 1;
    lw : LWORD := 6;
    d : DINT;
    dw : DWORD;
    x, y, z, u : BYTE;
END_VAR
buf[3] := 42; buf[5] := 55; buf[1] := 11; buf[6] := 66;
p := ADR(buf[0]);
q := p + n;
x := q^;
d := DWORD_TO_DINT(q - p);
dw := (p + w) - p;
q := p + w;
y := q^;
q := p + b;
z := q^;
q := p + lw;
u := q^;
END_PROGRAM
";
    let (trace, _) = run_text(
        "ptr.st",
        src,
        1,
        "Main.x,Main.d,Main.dw,Main.y,Main.z,Main.u",
    );
    assert_eq!(column(&trace, "Main.x"), [42.0], "{trace}");
    assert_eq!(column(&trace, "Main.d"), [3.0]);
    assert_eq!(column(&trace, "Main.dw"), [5.0]);
    assert_eq!(column(&trace, "Main.y"), [55.0]);
    assert_eq!(column(&trace, "Main.z"), [11.0]);
    assert_eq!(column(&trace, "Main.u"), [66.0]);
}

/// `ADR(v)` of a FUNCTION's input and of an element of its local array, dereferenced during the
/// call (CODESYS: the idiom for reading an input's bytes): the low byte of 258 is 2 (little
/// endian), plus the local element 7; clean under the sanitizers, with no W1444.
#[test]
fn the_address_of_a_functions_variable_is_used_during_the_call() {
    let src = "FUNCTION LowByte : BYTE
VAR_INPUT
    v : UINT;
END_VAR
VAR
    p : POINTER TO BYTE;
    arr : ARRAY[0..3] OF BYTE;
END_VAR
p := ADR(v);
LowByte := p^;
arr[2] := 7;
p := ADR(arr[1]) + 1;
LowByte := LowByte + p^;
END_FUNCTION

PROGRAM Main
VAR
    r : BYTE;
END_VAR
r := LowByte(258);
END_PROGRAM
";
    let (trace, stderr) = run_text("low.st", src, 2, "Main.r");
    assert_eq!(column(&trace, "Main.r"), [9.0, 9.0], "{trace}");
    assert!(!stderr.contains("W1444"), "{stderr}");
}

/// `REF(v)` of a FUNCTION's variable stays E0305 (IEC 61131-3 ed. 3, 6.4.4.10); `ADR(v)` stored
/// into a global or the function's result is W1444 at the target (the pointer outlives the
/// call), once per store.
#[test]
fn the_address_of_a_functions_variable_kept_beyond_the_call_is_w1444() {
    let src = "VAR_GLOBAL
    gp : POINTER TO INT;
END_VAR
FUNCTION Keep : POINTER TO INT
VAR_INPUT
    v : INT;
END_VAR
gp := ADR(v);
Keep := ADR(v);
END_FUNCTION
PROGRAM Main
VAR
    p : POINTER TO INT;
END_VAR
p := Keep(1);
END_PROGRAM
";
    let (code, lines) = check_text("keep.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].starts_with("keep.st:8:1: warning[W1444]: `gp` keeps the address"),
        "{lines:?}"
    );
    assert!(
        lines[1].starts_with("keep.st:9:1: warning[W1444]: `Keep` keeps the address"),
        "{lines:?}"
    );
    let refd = src.replace("gp := ADR(v);\nKeep := ADR(v);", "gp := REF(v);");
    let (code, lines) = check_text("keep.st", &refd);
    assert_eq!(code, Some(1));
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("keep.st:8:7: error[E0305]"),
        "{lines:?}"
    );
}

/// `t1 : Tank := (volume := 100.0);` in a CONFIGURATION's VAR_GLOBAL (and a RESOURCE's): the
/// instance starts with its inputs set, as a top-level VAR_GLOBAL's does.
#[test]
fn a_block_instance_in_a_configuration_global_starts_initialised() {
    let src = "FUNCTION_BLOCK Tank
VAR_INPUT
    volume : LREAL;
    level : INT;
END_VAR
END_FUNCTION_BLOCK
PROGRAM Main
VAR_EXTERNAL
    t1 : Tank;
    t2 : Tank;
END_VAR
VAR
    x : LREAL;
    l : INT;
END_VAR
x := t1.volume + t2.volume;
l := t1.level;
END_PROGRAM
CONFIGURATION C
    VAR_GLOBAL
        t1 : Tank := (volume := 100.0, level := 3);
    END_VAR
    RESOURCE R ON PLC
        VAR_GLOBAL
            t2 : Tank := (volume := 0.5);
        END_VAR
        TASK T (INTERVAL := T#10ms, PRIORITY := 1);
        PROGRAM P1 WITH T : Main;
    END_RESOURCE
END_CONFIGURATION
";
    let (trace, stderr) = run_text("tank.st", src, 1, "P1.x,P1.l");
    assert_eq!(column(&trace, "P1.x"), [100.5], "{trace}{stderr}");
    assert_eq!(column(&trace, "P1.l"), [3.0]);
    assert!(!stderr.contains("E1025"), "{stderr}");
}

/// Constant expressions as the values of a structure initializer (IEC 61131-3 ed. 3:
/// Struct_Elem_Init takes a Constant_Expr), also inside an array's initial value, with named
/// constants, a sign, parentheses, `*`, `/`, `MOD`.
#[test]
fn constant_expressions_inside_structure_initial_values() {
    let src = "TYPE Vec : STRUCT dX, dY, dZ : LREAL; n : INT; END_STRUCT; END_TYPE
PROGRAM Main
VAR CONSTANT
  len : LREAL := 0.4;
  N : INT := 7;
END_VAR
VAR
  a : Vec := (dX := len / 2.0, dY := 0.0, dZ := 1.0 + len, n := N MOD 4);
  b : Vec := (dX := 0.0, dY := -len, dZ := (len + 0.1) * 2.0, n := 2 * N - 1);
  arr : ARRAY[0..1] OF Vec := [(dX := len * 2.0, dY := 0, dZ := 0), (dX := 0, dY := 1, n := N + 1)];
END_VAR
END_PROGRAM
";
    let (trace, _) = run_text(
        "vec.st",
        src,
        1,
        "Main.a.dX,Main.a.dZ,Main.a.n,Main.b.dY,Main.b.dZ,Main.b.n,Main.arr[0].dX,Main.arr[1].n",
    );
    assert_eq!(column(&trace, "Main.a.dX"), [0.2], "{trace}");
    assert_eq!(column(&trace, "Main.a.dZ"), [1.4]);
    assert_eq!(column(&trace, "Main.a.n"), [3.0]);
    assert_eq!(column(&trace, "Main.b.dY"), [-0.4]);
    assert_eq!(column(&trace, "Main.b.dZ"), [1.0]);
    assert_eq!(column(&trace, "Main.b.n"), [13.0]);
    assert_eq!(column(&trace, "Main.arr[0].dX"), [0.8]);
    assert_eq!(column(&trace, "Main.arr[1].n"), [8.0]);
}

/// CASE labels that are constant expressions (IEC 61131-3 ed. 3: Case_List_Elem is a Subrange or
/// a Constant_Expr; CODESYS documents it): `ST_RUN + ST_ERR`, `2 * ST_RUN` in a list, and a range
/// with expression bounds; the selector steps by 10 through every branch and ELSE.
#[test]
fn a_case_label_may_be_a_constant_expression() {
    let src = "PROGRAM Main
VAR CONSTANT
  ST_RUN : INT := 10;
  ST_ERR : INT := 100;
END_VAR
VAR
  state : INT;
  n : INT;
END_VAR
state := state + 10;
CASE state OF
  ST_RUN:
    n := 1;
  ST_RUN + ST_ERR, 2 * ST_RUN:
    n := 2;
  (ST_ERR - 10) .. ST_ERR + ST_RUN - 1:
    n := 3;
ELSE
    n := 0;
END_CASE;
END_PROGRAM
";
    let (trace, _) = run_text("labels.st", src, 12, "Main.n");
    assert_eq!(
        column(&trace, "Main.n"),
        [1.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 3.0, 3.0, 2.0, 0.0],
        "{trace}"
    );
}

/// CHAR literals as CASE labels of a CHAR selector (`'0':`, `'a', 'A':`; edition 3 writes a CHAR
/// literal `'0'`), as `CHAR#'0':` already was: a hex digit's value, 255 for another character.
#[test]
fn char_literals_are_case_labels_of_a_char_selector() {
    let src = "FUNCTION HexVal : BYTE
    VAR_INPUT c : CHAR; END_VAR
    CASE c OF
        '0':
            HexVal := 0;
            RETURN;
        '1', '2':
            HexVal := CHAR_TO_BYTE(c) - 48;
            RETURN;
        'a', 'A':
            HexVal := 10;
    ELSE
        HexVal := 255;
    END_CASE;
END_FUNCTION

PROGRAM Main
    VAR a, b, c, d : BYTE; END_VAR
    a := HexVal('A');
    b := HexVal('0');
    c := HexVal('2');
    d := HexVal('x');
END_PROGRAM
";
    let (trace, _) = run_text("hex.st", src, 1, "Main.a,Main.b,Main.c,Main.d");
    assert_eq!(column(&trace, "Main.a"), [10.0], "{trace}");
    assert_eq!(column(&trace, "Main.b"), [0.0]);
    assert_eq!(column(&trace, "Main.c"), [2.0]);
    assert_eq!(column(&trace, "Main.d"), [255.0]);
}

/// `ARRAY[0..Limits#BUF_UPPER]` with `Limits` an INT-based enumeration (IEC 61131-3 ed. 3,
/// 6.4.4.3: named values are constants): the array has 8 elements, UPPER_BOUND is 7 and the last
/// element is written.
#[test]
fn an_array_bound_may_be_an_enumerated_value() {
    let src = "TYPE
    Limits : INT (
        BUF_UPPER := 7,
        MODES_UPPER := 3
    );
END_TYPE
PROGRAM Main
    VAR
        buf : ARRAY[0..Limits#BUF_UPPER] OF INT;
        modes : ARRAY[1..Limits#MODES_UPPER + 1] OF BOOL;
        n, m : DINT;
    END_VAR
    buf[7] := 5;
    n := UPPER_BOUND(buf, 1);
    m := UPPER_BOUND(modes, 1);
END_PROGRAM
";
    let (trace, _) = run_text("limits.st", src, 1, "Main.n,Main.m,Main.buf[7]");
    assert_eq!(column(&trace, "Main.n"), [7.0], "{trace}");
    assert_eq!(column(&trace, "Main.m"), [4.0]);
    assert_eq!(column(&trace, "Main.buf[7]"), [5.0]);
}

/// `ARRAY [*]` as a FUNCTION's VAR_INPUT (ladderc compiles it as a VAR_IN_OUT only) is one E1072
/// at the `*`; its LOWER_BOUND and UPPER_BOUND say nothing more (no internal value in a message).
#[test]
fn a_misplaced_variable_length_array_is_one_error() {
    let src = "FUNCTION SumAll : DINT
    VAR_INPUT
        values : ARRAY[*] OF DINT;
    END_VAR
    VAR lo, hi, i : DINT; END_VAR
    lo := LOWER_BOUND(values, 1);
    hi := UPPER_BOUND(values, 1);
    FOR i := lo TO hi DO
        SumAll := SumAll + values[i];
    END_FOR;
END_FUNCTION

PROGRAM Main
    VAR a : ARRAY[1..3] OF DINT := [1, 2, 3]; s : DINT; END_VAR
    s := SumAll(a);
END_PROGRAM
";
    let (code, lines) = check_text("vla.st", src);
    assert_eq!(code, Some(1));
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("vla.st:3:24: error[E1072]"),
        "{lines:?}"
    );
}

/// `ARRAY[0..RobotLibParams.TOOL_MAX - 1]` with no list `RobotLibParams` given (a library's
/// parameter list): one E0022 that names the constant as written and the list.
#[test]
fn a_bound_from_a_list_not_given_names_the_list() {
    let src = "TYPE Tool : STRUCT id : INT; END_STRUCT; END_TYPE
VAR_GLOBAL
  tools : ARRAY[0..RobotLibParams.TOOL_MAX - 1] OF Tool;
END_VAR
";
    let (code, lines) = check_text("robot.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "robot.st:3:35: error[E0022]: constant expression `RobotLibParams.TOOL_MAX - 1`: \
             `RobotLibParams.TOOL_MAX` names no constant with a value in the files given: no global \
             variable list or library parameter list `RobotLibParams` given with the file declares \
             `TOOL_MAX`"
        ),
        "{lines:?}"
    );
}
