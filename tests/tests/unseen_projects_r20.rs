//! Round 20 of unseen projects (issue #13): forms that the round's real programs use, run end to
//! end through `ladderc run`:
//! - a method called through an interface that is a function block's output (`d.itf.Get()`,
//!   trofimich/TwinCAT.OpenFramework; before: a false E1015 "`itf` is an output of FB instance
//!   `d`");
//! - standard functions of constants in a declaration's constant expression (`SQRT(4.0)`,
//!   `MAX(3, 7, 5)`, `REAL_TO_INT(2.5)`, `TO_REAL(LOG(-1))`, TwinCAT's way to write NaN; before:
//!   E0011 "unexpected literal `-1` (hint: expected a name)");
//! - TwinCAT's `XSIZEOF` (before: E1003, an unknown function).

mod common;
use common::{check_text, column, run_traced};

fn run_text(name: &str, src: &str, cycles: u32, watch: &str) -> (String, String) {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join(name);
    std::fs::write(&file, src).unwrap();
    run_traced(&file, cycles, watch)
}

/// `d.itf.Get()` runs the method of the instance that `d` put in its output `itf`, and writing
/// the output itself from outside stays E1015.
#[test]
fn a_method_is_called_through_an_interface_output_of_a_block() {
    let src = "INTERFACE I_Get
METHOD Get : INT
END_METHOD
END_INTERFACE

FUNCTION_BLOCK Impl IMPLEMENTS I_Get
VAR_INPUT k : INT := 3; END_VAR
METHOD Get : INT
Get := k * 2;
END_METHOD
END_FUNCTION_BLOCK

FUNCTION_BLOCK Holder
VAR_OUTPUT itf : I_Get; END_VAR
VAR inner : Impl; END_VAR
inner.k := inner.k + 1;
itf := inner;
END_FUNCTION_BLOCK

PROGRAM main
VAR d : Holder; v : INT; before : INT; END_VAR
IF d.itf <> 0 THEN
  before := 99;
END_IF
d();
IF d.itf <> 0 THEN
  v := d.itf.Get();
END_IF
END_PROGRAM
";
    let (trace, stderr) = run_text("itf_out.st", src, 3, "main.v,main.before");
    assert_eq!(column(&trace, "main.v"), [8.0, 10.0, 12.0], "{stderr}");
    assert_eq!(column(&trace, "main.before"), [0.0, 99.0, 99.0]);
    let (code, lines) = check_text(
        "itf_write.st",
        &src.replace("  v := d.itf.Get();", "  d.itf := 0;"),
    );
    assert_eq!(code, Some(1));
    assert!(
        lines.iter().any(|l| l.starts_with(
            "itf_write.st:27:3: error[E1015]: `itf` is an output of FB instance `d`"
        )),
        "{lines:?}"
    );
}

/// Constants initialised by standard functions of constants take the functions' values (the
/// conversion rounds halves to even), NaN included; a call of something else is one E0022 that
/// says what a constant expression may call.
#[test]
fn standard_functions_of_constants_initialise_constants() {
    let src = "VAR_GLOBAL CONSTANT
  NAN_L : LREAL := LOG(-1);
  NAN_R : REAL := TO_REAL(LOG(-1));
  TWO : LREAL := SQRT(4.0);
  BIG : INT := MAX(3, 7, 5);
  R : INT := REAL_TO_INT(2.5);
  N : DINT := LIMIT(0, 12, 10) * 2;
  LEN : INT := MIN(4, 9);
  T : DINT := TRUNC(-2.7);
END_VAR
PROGRAM main
VAR x : LREAL; y : INT; z : DINT; is_nan : BOOL; a : ARRAY[1..LEN] OF INT; t1 : DINT; END_VAR
x := TWO;
y := BIG * 10 + R;
z := N;
t1 := T;
is_nan := NAN_L <> NAN_L AND NAN_R <> NAN_R;
a[LEN] := 5;
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "const_calls.st",
        src,
        1,
        "main.x,main.y,main.z,main.t1,main.is_nan,main.a[4]",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "main.x"), [2.0]);
    assert_eq!(column(&trace, "main.y"), [72.0]);
    assert_eq!(column(&trace, "main.z"), [20.0]);
    assert_eq!(column(&trace, "main.t1"), [-2.0]);
    assert_eq!(column(&trace, "main.is_nan"), [1.0]);
    assert_eq!(column(&trace, "main.a[4]"), [5.0]);

    let (code, lines) = check_text(
        "const_bad.st",
        "VAR_GLOBAL CONSTANT\n  K : INT := MY_F(2);\n  J : INT := REAL_TO_INT(1.0E10);\nEND_VAR\n\
         PROGRAM main\nVAR x : INT; END_VAR\nx := K + J;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 2, "{lines:?}");
    assert!(
        errors[0].starts_with("const_bad.st:2:14: error[E0022]")
            && errors[0].contains("`MY_F(...)` is a call"),
        "{lines:?}"
    );
    assert!(
        errors[1].starts_with("const_bad.st:3:14: error[E0022]")
            && errors[1].contains("out of INT's range"),
        "{lines:?}"
    );
}

/// TwinCAT's `XSIZEOF` measures as `SIZEOF` does.
#[test]
fn xsizeof_measures_as_sizeof() {
    let src = "TYPE ST_A : STRUCT x : DINT; y : LREAL; END_STRUCT; END_TYPE
PROGRAM main
VAR n : UDINT; m : UDINT; a : ST_A; END_VAR
n := XSIZEOF(a) * 2;
m := SIZEOF(ST_A);
END_PROGRAM
";
    let (trace, stderr) = run_text("xsizeof.st", src, 1, "main.n,main.m");
    assert_eq!(column(&trace, "main.m"), [16.0], "{stderr}");
    assert_eq!(column(&trace, "main.n"), [32.0]);
}

/// An INTERFACE that extends an unknown interface is one located E0330 (before: accepted
/// silently, its missing methods unchecked); TwinCAT's `__SYSTEM.IQueryInterface` stays known,
/// and a method through such an interface runs.
#[test]
fn an_interface_extending_an_unknown_interface_is_one_error() {
    let (code, lines) = check_text(
        "itf_ext.st",
        "INTERFACE I_A EXTENDS I_Missing\nMETHOD Get : INT\nEND_METHOD\nEND_INTERFACE\n\
         PROGRAM main\nVAR x : INT; END_VAR\nx := 1;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with(
            "itf_ext.st:1:23: error[E0330]: `I_A` EXTENDS `I_Missing`, which names no INTERFACE"
        ),
        "{lines:?}"
    );
    let src = "INTERFACE I_A EXTENDS __SYSTEM.IQueryInterface
METHOD Get : INT
END_METHOD
END_INTERFACE
FUNCTION_BLOCK B IMPLEMENTS I_A
METHOD Get : INT
Get := 4;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM main
VAR x : INT; b : B; i : I_A; END_VAR
i := b;
x := i.Get();
END_PROGRAM
";
    let (trace, stderr) = run_text("itf_system.st", src, 1, "main.x");
    assert_eq!(column(&trace, "main.x"), [4.0], "{stderr}");
}
