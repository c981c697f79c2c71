//! Round 30 of unseen projects (issue #13): initial values, VAR_INST and reference properties as
//! TwinCAT writes them, run end to end through `ladderc run`:
//! - a field computed at run time (a call, a variable, `THIS^`) nested in a structure's or an
//!   array of structures' initial value (`w : FB_Wrap := (View := (iParent := THIS^));`, `aRcp :
//!   ARRAY[1..3] OF ST_Rcp := [(id := 1), (id := 2, days := F_Days(TRUE, FALSE))];`, Beckhoff's
//!   TF8040 samples), and `THIS^` in a `VAR_INPUT CONSTANT` (an instance's parameter, CODESYS
//!   "Command: Edit Parameters"): assigned when the instance is initialised, to the element at
//!   its position whatever the array's first index (before: E1031 "TRUE cannot name a variable",
//!   E0011, E0001 at `^`);
//! - such a field in a repeated element (`[4((id := 1, n := Twice(3)))]`) or after a repetition
//!   counted by a name: one E1069 at the element (before: E0011 at the call's argument);
//! - a field of a property returning `REFERENCE TO` a structure bound to a block's output or given
//!   to a VAR_IN_OUT (`rd(ErrId => stAxis.nErr)`, ESS tc_mca_std_lib): the getter runs before the
//!   call and the output is written through the reference (before: E0338);
//! - `[N(7)]` (a repetition counted by a named constant) in a METHOD's VAR_INST: the
//!   declaration's initial value, as in the block's VAR (before: E0107 at `[`).

mod common;
use common::{check_text, column, rejected_heads, run_text};

const NESTED: &str = "TYPE ST_Days :
STRUCT
    mon : BOOL;
    tue : BOOL;
END_STRUCT;
END_TYPE

TYPE ST_Rcp :
STRUCT
    id : INT;
    days : ST_Days;
END_STRUCT;
END_TYPE

TYPE ST_Limits :
STRUCT
    lo : INT;
    hi : INT;
END_STRUCT;
END_TYPE

TYPE ST_Axis :
STRUCT
    lim : ST_Limits;
    gain : INT;
END_STRUCT;
END_TYPE

FUNCTION F_Days : ST_Days
VAR_INPUT
    a : BOOL;
    b : BOOL;
END_VAR
F_Days.mon := a;
F_Days.tue := b;
END_FUNCTION

FUNCTION Twice : INT
VAR_INPUT
    x : INT;
END_VAR
Twice := 2 * x;
END_FUNCTION

INTERFACE I_View
METHOD Level : INT
END_METHOD
END_INTERFACE

FUNCTION_BLOCK FB_Child
VAR_INPUT
    iParent : I_View;
END_VAR
VAR_OUTPUT
    lvl : INT;
END_VAR
lvl := iParent.Level();
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB_Wrap
VAR_INPUT
    n : INT;
    View : FB_Child;
END_VAR
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB_Parent IMPLEMENTS I_View
VAR_INPUT CONSTANT
    c2 : FB_Child := (iParent := THIS^);
END_VAR
VAR
    w : FB_Wrap := (n := 5, View := (iParent := THIS^));
END_VAR
VAR_OUTPUT
    a : INT;
    b : INT;
END_VAR
METHOD Level : INT
Level := 7;
END_METHOD
w.View();
c2();
a := w.View.lvl + w.n;
b := c2.lvl;
END_FUNCTION_BLOCK

PROGRAM MAIN
VAR
    aRcp : ARRAY[1..3] OF ST_Rcp := [(id := 1), (id := 2, days := F_Days(TRUE, FALSE)),
                                     (id := Twice(5), days := (mon := FALSE, tue := Twice(1) = 2))];
    bRcp : ARRAY[0..3] OF ST_Rcp := [2((id := 4)), (id := 6, days := F_Days(a := FALSE, b := TRUE))];
    ax : ST_Axis := (lim := (lo := Twice(-4), hi := 9), gain := 3);
    p : FB_Parent;
END_VAR
p();
END_PROGRAM
";

/// Fields computed at run time nested in structure and array initial values, and `THIS^` in a
/// VAR_INPUT CONSTANT, hold their values from the first cycle; the constant fields beside them
/// keep theirs; an element after a repetition with a literal count is the right one. Before: the
/// declarations were E1031, E0011 and E0001.
#[test]
fn nested_computed_fields_are_assigned_at_initialisation() {
    let watch = "MAIN.aRcp[1].id,MAIN.aRcp[1].days.mon,MAIN.aRcp[2].id,MAIN.aRcp[2].days.mon,\
MAIN.aRcp[2].days.tue,MAIN.aRcp[3].id,MAIN.aRcp[3].days.tue,MAIN.bRcp[1].id,MAIN.bRcp[2].id,\
MAIN.bRcp[2].days.tue,MAIN.bRcp[3].id,MAIN.ax.lim.lo,MAIN.ax.lim.hi,MAIN.ax.gain,MAIN.p.a,MAIN.p.b";
    let (trace, stderr) = run_text("nested.st", NESTED, 2, watch);
    let expect = [
        ("MAIN.aRcp[1].id", 1.0),
        ("MAIN.aRcp[1].days.mon", 0.0),
        ("MAIN.aRcp[2].id", 2.0),
        ("MAIN.aRcp[2].days.mon", 1.0),
        ("MAIN.aRcp[2].days.tue", 0.0),
        ("MAIN.aRcp[3].id", 10.0),
        ("MAIN.aRcp[3].days.tue", 1.0),
        ("MAIN.bRcp[1].id", 4.0),
        ("MAIN.bRcp[2].id", 6.0),
        ("MAIN.bRcp[2].days.tue", 1.0),
        ("MAIN.bRcp[3].id", 0.0),
        ("MAIN.ax.lim.lo", -8.0),
        ("MAIN.ax.lim.hi", 9.0),
        ("MAIN.ax.gain", 3.0),
        // the wrapped child and the constant input both call back into their parent
        ("MAIN.p.a", 12.0),
        ("MAIN.p.b", 7.0),
    ];
    for (name, value) in expect {
        assert_eq!(column(&trace, name), vec![value; 2], "{name}: {stderr}");
    }
    assert!(!stderr.contains("error["), "{stderr}");
}

/// A computed field inside a repeated element, or in an element after a repetition counted by a
/// name, has no single place: one E1069 at the element each, nothing else (no W1433 for them, no
/// parse error of the value). Before: E0011 at the call's argument, E0011 at `:=`.
#[test]
fn a_computed_field_in_a_repeated_element_is_one_located_error() {
    let src = "TYPE ST_Rcp :
STRUCT
    id : INT;
    n : INT;
END_STRUCT;
END_TYPE

FUNCTION Twice : INT
VAR_INPUT
    x : INT;
END_VAR
Twice := 2 * x;
END_FUNCTION

PROGRAM MAIN
VAR CONSTANT
    K : INT := 2;
END_VAR
VAR
    a : ARRAY[0..3] OF ST_Rcp := [4((id := 1, n := Twice(3)))];
    b : ARRAY[0..3] OF ST_Rcp := [K((id := 1)), (id := 2, n := Twice(3))];
END_VAR
END_PROGRAM
";
    let heads = rejected_heads("repeated.st", src);
    assert_eq!(heads.len(), 2, "{heads:#?}");
    assert!(
        heads[0].starts_with("repeated.st:20:35: error[E1069]"),
        "{heads:#?}"
    );
    assert!(
        heads[1].starts_with("repeated.st:21:49: error[E1069]"),
        "{heads:#?}"
    );
    assert!(heads[0].contains("`a`") && heads[0].contains("repeated array element"));
    assert!(heads[1].contains("`b`") && heads[1].contains("counted by a name"));
}

const REF_PROPERTY: &str = "TYPE ST_Status :
STRUCT
    nErr : UDINT;
    nCount : UDINT;
END_STRUCT;
END_TYPE

FUNCTION_BLOCK FB_Reader
VAR_INPUT
    seed : UDINT;
END_VAR
VAR_OUTPUT
    ErrId : UDINT;
END_VAR
ErrId := seed + 40;
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB_Counter
VAR_IN_OUT
    n : UDINT;
END_VAR
n := n + 1;
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB_Axis
VAR
    _st : ST_Status;
    rd : FB_Reader;
    cnt : FB_Counter;
END_VAR
VAR_OUTPUT
    err : UDINT;
    count : UDINT;
END_VAR
PROPERTY stAxis : REFERENCE TO ST_Status
GET
    stAxis REF= _st;
END_GET
END_PROPERTY
rd(seed := 2, ErrId => stAxis.nErr);
cnt(n := stAxis.nCount);
err := _st.nErr;
count := _st.nCount;
END_FUNCTION_BLOCK

PROGRAM MAIN
VAR
    ax : FB_Axis;
END_VAR
ax();
END_PROGRAM
";

/// A field of a property returning `REFERENCE TO` a structure, bound to an output (`=>`) or given
/// to a VAR_IN_OUT, is the field of the structure the reference points to: the output lands in
/// it, the in-out counts it up each cycle. Before: E0338 "a property is code, not a variable".
#[test]
fn a_reference_property_field_receives_an_output() {
    let (trace, stderr) = run_text("refprop.st", REF_PROPERTY, 3, "MAIN.ax.err,MAIN.ax.count");
    assert_eq!(column(&trace, "MAIN.ax.err"), vec![42.0; 3], "{stderr}");
    assert_eq!(
        column(&trace, "MAIN.ax.count"),
        vec![1.0, 2.0, 3.0],
        "{stderr}"
    );
    assert!(!stderr.contains("error["), "{stderr}");
}

/// A property returning a structure by value still cannot take an output: its value is a copy
/// (one E0338 at the argument).
#[test]
fn a_value_property_field_still_cannot_receive_an_output() {
    let src = REF_PROPERTY
        .replace(
            "PROPERTY stAxis : REFERENCE TO ST_Status",
            "PROPERTY stAxis : ST_Status",
        )
        .replace("stAxis REF= _st;", "stAxis := _st;")
        .replace("cnt(n := stAxis.nCount);", "");
    let heads = rejected_heads("valprop.st", &src);
    assert_eq!(heads.len(), 1, "{heads:#?}");
    assert!(
        heads[0].starts_with("valprop.st:40:24: error[E0338]"),
        "{heads:#?}"
    );
    assert!(heads[0].contains("`stAxis`") && heads[0].contains("an output"));
}

/// `[N(7)]` in a METHOD's VAR_INST, `N` a constant of the block: the array holds 7 three times,
/// kept in the instance. Before: E0107 "expected an expression, found `[`".
#[test]
fn a_named_repetition_in_a_method_var_inst_is_the_declarations() {
    let src = "FUNCTION_BLOCK FB_Mon
VAR CONSTANT
    N : UINT := 3;
END_VAR
VAR_OUTPUT
    s : INT;
END_VAR
METHOD M
VAR_INST
    a : ARRAY[1..N] OF INT := [N(7)];
    names : ARRAY[1..N] OF STRING := [N('x')];
END_VAR
a[2] := a[2] + 1;
s := a[1] + a[2] + a[3] + LEN(names[3]);
END_METHOD
M();
END_FUNCTION_BLOCK

PROGRAM MAIN
VAR
    fb : FB_Mon;
    r : INT;
END_VAR
fb();
r := fb.s;
END_PROGRAM
";
    let (trace, stderr) = run_text("varinst.st", src, 3, "MAIN.r");
    // 7 + (7 + k) + 7 + 1: the VAR_INST keeps its value between calls
    assert_eq!(column(&trace, "MAIN.r"), vec![23.0, 24.0, 25.0], "{stderr}");
    let (code, lines) = check_text("varinst.st", src);
    assert_eq!(code, Some(0), "{lines:#?}");
}
