//! Data types with named values on an integer base type (IEC 61131-3 edition 3, 6.4.4.3):
//! `TYPE Lvl : INT (Low := 1, Mid := 50, High := 100) := Low; END_TYPE` in `.st` and `.il` TYPE
//! blocks. Such a type is read as the enumeration with these explicit values: its values are used
//! by name, qualified `Lvl#High` or `Lvl.High`, as an initial value, as CASE labels and in
//! comparisons, and the trace shows their numbers. As for every enumeration, arithmetic and
//! stores to or from the base type are refused (the base type is checked, not kept). Before:
//! E0011 "expected a number" at the `(`.
//!
//! Each program is written here and run through `ladderc run` (C compiled with the sanitizers) or
//! `ladderc check`.

mod common;
use common::{rejected_heads, run_traced};

/// A level that steps Low (1) -> Mid (50) -> High (100) -> Low, starting from the type's initial
/// value `Low`; CASE labels name the values three ways; a variable initialised `Lvl#High`.
const LEVELS_ST: &str = "\
TYPE Lvl : INT (Low := 1, Mid := 50, High := 100) := Low; END_TYPE
PROGRAM main
VAR
  l : Lvl;
  start : Lvl;
  top : Lvl := Lvl#High;
  code : INT;
  at_top : BOOL;
END_VAR
start := l;
CASE l OF
  Low: code := 10;
  Lvl#Mid: code := 20;
  Lvl.High: code := 30;
END_CASE;
at_top := l = top;
IF l = Low THEN
  l := Mid;
ELSIF l = Lvl.Mid THEN
  l := Lvl#High;
ELSE
  l := Low;
END_IF;
END_PROGRAM
";

#[test]
fn st_type_with_named_values_runs_with_their_numbers() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("levels.st");
    std::fs::write(&f, LEVELS_ST).unwrap();
    let (trace, stderr) = run_traced(&f, 4, "main.start,main.l,main.top,main.code,main.at_top");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(
        trace,
        "cycle,time_ms,main.start,main.l,main.top,main.code,main.at_top\n\
         0,0,1,50,100,10,0\n\
         1,10,50,100,100,20,0\n\
         2,20,100,1,100,30,1\n\
         3,30,1,50,100,10,0\n"
    );
}

/// The same form in an IL file's TYPE block, with a qualified value loaded and compared.
#[test]
fn il_type_block_with_named_values_runs() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("levels.il");
    std::fs::write(
        &f,
        "TYPE Lvl : UINT (Low := 1, High := 100) := Low; END_TYPE\n\
         PROGRAM main\nVAR l : Lvl; was_low : BOOL; END_VAR\n\
         \x20 LD l\n  EQ Lvl#Low\n  ST was_low\n  LD Lvl#High\n  ST l\nEND_PROGRAM\n",
    )
    .unwrap();
    let (trace, _) = run_traced(&f, 2, "main.l,main.was_low");
    assert_eq!(
        trace,
        "cycle,time_ms,main.l,main.was_low\n0,0,100,1\n1,10,100,0\n"
    );
}

/// A base type that is not an integer type is E0011 at its name.
#[test]
fn named_values_on_a_non_integer_base_are_rejected() {
    let heads = rejected_heads(
        "real.st",
        "TYPE Lvl : REAL (Low := 1, High := 100); END_TYPE\n\
         PROGRAM main\nVAR l : Lvl; END_VAR\nl := Low;\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        ["real.st:1:12: error[E0011]: `REAL` cannot carry named values in ladderc"]
    );
}

/// The values keep the enumeration's semantics: under `{attribute 'strict'}`, adding to one or
/// storing an INT into the type are refused as for `(Low := 1, High := 100)`; storing the type into
/// an INT is W1439 (Beckhoff's 'strict' forbids arithmetic and stores into the enumeration only;
/// round 27, before E1006); without it they count as their numbers, with one W1439 (CODESYS and
/// TwinCAT; `tests/tests/codesys_loose_types_run.rs`).
#[test]
fn named_values_refuse_arithmetic_and_base_type_stores() {
    let body = "TYPE Lvl : INT (Low := 1, High := 100); END_TYPE\n\
         PROGRAM main\nVAR l : Lvl; n : INT; END_VAR\n\
         n := l;\nl := 5;\nn := l + 1;\nEND_PROGRAM\n";
    let heads = rejected_heads("arith.st", &format!("{{attribute 'strict'}}\n{body}"));
    assert_eq!(
        heads,
        [
            "arith.st:5:1: warning[W1439]: the enumeration Lvl used as an integer: IEC 61131-3 enumerations are no numbers (its other uses in this POU are not reported)",
            "arith.st:6:1: error[E1006]: cannot store an integer literal into Lvl",
            "arith.st:7:6: error[E1004]: ADD is not defined for Lvl",
        ]
    );
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("loose.st");
    std::fs::write(&f, body).unwrap();
    let (trace, stderr) = run_traced(&f, 1, "main.l,main.n");
    // l = 5 (no named value), n := l + 1 = 6
    assert_eq!(trace.lines().nth(1), Some("0,0,5,6"), "{trace}");
    assert_eq!(stderr.matches("warning[W1439]").count(), 1, "{stderr}");
}
