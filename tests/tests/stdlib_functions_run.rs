//! The standard functions added after comparing ladderc's catalogue with IEC 61131-3 and matiec's
//! `lib/standard_functions.txt` (issue #13), end to end through `ladderc run --sanitize`: the typed
//! names of the overloaded functions (`ADD_INT`, `MAX_REAL`, `MUX_INT_DINT`, edition 2, 2.5.1.4),
//! edition 2's `MULTIME`/`DIVTIME`, edition 3's `TRUNC_INT`/`REAL_TRUNC_INT`, `TO_INT`-style
//! conversions, `CONCAT_DATE`/`CONCAT_TOD`/`CONCAT_DT`/`DAY_OF_WEEK`; each value checked against the
//! standard's result, edge cases included (wrap-around at the named width, halves, saturation,
//! invalid dates, the ends of the DT range). Then the located E1410 of a typed name given inputs of
//! another type, and a user FUNCTION named like a typed name, which stays the user's.

mod common;
use common::ladderc;

use std::collections::BTreeMap;

/// (result type, ST expression, expected trace value).
const CASES: &[(&str, &str, &str)] = &[
    // typed names: the arithmetic is done at the named width
    ("INT", "ADD_INT(32767, 1)", "-32768"),
    ("SINT", "ADD_SINT(127, 1)", "-128"),
    ("DINT", "ADD_DINT(32767, 1)", "32768"),
    ("INT", "ADD_INT(1, 2, 3, 4)", "10"),
    ("LINT", "MUL_LINT(4294967296, 4294967296)", "0"),
    ("INT", "SUB_INT(-32768, 1)", "32767"),
    ("INT", "DIV_INT(7, -2)", "-3"),
    ("INT", "DIV_INT(7, 0)", "0"),
    ("DINT", "MOD_DINT(-7, 2)", "-1"),
    ("UINT", "MOD_UINT(7, 0)", "0"),
    ("REAL", "SUB_REAL(0.5, 2.0)", "-1.5"),
    ("INT", "ABS_INT(-5)", "5"),
    ("REAL", "ABS_REAL(-2.5)", "2.5"),
    ("LREAL", "SQRT_LREAL(2.25)", "1.5"),
    ("REAL", "EXPT_REAL(2.0, 10)", "1024"),
    ("INT", "MAX_INT(3, 9, -2)", "9"),
    ("TIME", "MIN_TIME(T#1s, T#2s, T#1500ms)", "T#1000ms"),
    ("INT", "LIMIT_INT(0, 50, 10)", "10"),
    ("INT", "LIMIT_INT(0, -50, 10)", "0"),
    ("INT", "SEL_INT(TRUE, 1, 2)", "2"),
    ("DINT", "MUX_INT_DINT(2, 5, 6, 7)", "7"),
    ("BOOL", "EQ_STRING('ab', 'ab')", "1"),
    ("BOOL", "GT_TIME(T#2s, T#1s, T#1s)", "0"),
    ("BOOL", "LE_DATE(D#2024-01-01, D#2024-01-01)", "1"),
    ("WORD", "AND_WORD(16#FF0F, 16#0FF0)", "3840"),
    ("BYTE", "NOT_BYTE(0)", "255"),
    ("BOOL", "XOR_BOOL(TRUE, TRUE, TRUE)", "1"),
    ("REAL", "MOVE_REAL(2.5)", "2.5"),
    ("STRING", "CONCAT_STRING('ab', 'cd')", "\"abcd\""),
    // edition 2 spellings of MUL_TIME / DIV_TIME
    ("TIME", "MULTIME(T#1s, 2.5)", "T#2500ms"),
    ("TIME", "DIVTIME(T#1s, 4)", "T#250ms"),
    ("TIME", "DIVTIME(T#1s, 0)", "T#0ms"),
    // edition 3 truncation: toward zero, saturated at the target's limits
    ("INT", "TRUNC_INT(-2.7)", "-2"),
    ("DINT", "REAL_TRUNC_DINT(3.9)", "3"),
    ("SINT", "LREAL_TRUNC_SINT(1000.0)", "127"),
    ("UINT", "TRUNC_UINT(-1.5)", "0"),
    // edition 3 TO_*: the rules of X_TO_Y for the input's type (REAL to integer: halves to even)
    ("INT", "TO_INT(-2.5)", "-2"),
    ("INT", "TO_INT(REAL#3.5)", "4"),
    ("DINT", "TO_DINT(INT#-3)", "-3"),
    ("USINT", "TO_USINT(INT#300)", "44"),
    ("STRING", "TO_STRING(T#1500ms)", "\"T#1500ms\""),
    ("WSTRING", "TO_WSTRING(42)", "\"42\""),
    ("TIME", "TO_TIME(1500)", "T#1500ms"),
    ("BOOL", "TO_BOOL(5)", "1"),
    ("LREAL", "TO_LREAL(INT#-3)", "-3"),
    ("DATE", "TO_DATE(DT#2024-01-31-12:30:00)", "D#2024-01-31"),
    // edition 3 date functions; an invalid part gives the zero value
    ("DATE", "CONCAT_DATE(2024, 2, 29)", "D#2024-02-29"),
    ("DATE", "CONCAT_DATE(2023, 2, 29)", "D#1970-01-01"),
    ("DATE", "CONCAT_DATE(2000, 2, 29)", "D#2000-02-29"),
    ("DATE", "CONCAT_DATE(1900, 2, 29)", "D#1970-01-01"),
    ("DATE", "CONCAT_DATE(2024, 13, 1)", "D#1970-01-01"),
    ("DATE", "CONCAT_DATE(2024, 4, 31)", "D#1970-01-01"),
    ("DATE", "CONCAT_DATE(1677, 9, 22)", "D#1677-09-22"),
    ("DATE", "CONCAT_DATE(1677, 9, 21)", "D#1970-01-01"),
    ("TOD", "CONCAT_TOD(23, 59, 59, 999)", "TOD#23:59:59.999"),
    ("TOD", "CONCAT_TOD(24, 0, 0, 0)", "TOD#00:00:00"),
    ("TOD", "CONCAT_TOD(12, 60, 0, 0)", "TOD#00:00:00"),
    ("TOD", "CONCAT_TOD(0, 0, 0, 1000)", "TOD#00:00:00"),
    (
        "DT",
        "CONCAT_DT(1969, 12, 31, 23, 0, 0, 5)",
        "DT#1969-12-31-23:00:00.005",
    ),
    (
        "DT",
        "CONCAT_DT(2262, 4, 10, 23, 59, 59, 999)",
        "DT#2262-04-10-23:59:59.999",
    ),
    (
        "DT",
        "CONCAT_DT(2262, 4, 11, 0, 0, 0, 0)",
        "DT#1970-01-01-00:00:00",
    ),
    (
        "DT",
        "CONCAT_DT(2024, 1, 31, 12, -1, 0, 0)",
        "DT#1970-01-01-00:00:00",
    ),
    ("INT", "DAY_OF_WEEK(D#2024-01-31)", "3"),
    ("INT", "DAY_OF_WEEK(D#1969-12-28)", "0"),
    ("INT", "DAY_OF_WEEK(D#2000-01-01)", "6"),
    ("INT", "DAY_OF_WEEK(D#1970-01-01)", "4"),
    ("INT", "DAY_OF_WEEK(CONCAT_DATE(1677, 9, 22))", "3"),
];

fn run(dir: &std::path::Path, name: &str, src: &str) -> (BTreeMap<String, String>, String) {
    common::run_one_scan(dir, name, src)
}

#[test]
fn added_standard_functions_give_the_iec_values() {
    let mut decl = String::new();
    let mut body = String::new();
    for (k, (ty, expr, _)) in CASES.iter().enumerate() {
        decl.push_str(&format!("  r{k} : {ty};\n"));
        body.push_str(&format!("  r{k} := {expr};\n"));
    }
    let src = format!("PROGRAM main\nVAR\n{decl}END_VAR\n{body}END_PROGRAM\n");
    let dir = tempfile::tempdir().unwrap();
    let (col, stderr) = run(dir.path(), "f.st", &src);
    let failures: Vec<String> = CASES
        .iter()
        .enumerate()
        .filter_map(|(k, (_, expr, want))| {
            let got = &col[&format!("main.r{k}")];
            (got != want).then(|| format!("{expr}: got {got}, want {want}"))
        })
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    // the invalid dates, saturations and divisions by zero were flagged
    assert!(
        stderr.contains("runtime: conversion out of range"),
        "{stderr}"
    );
}

/// The typed names in IL: the current result is the first input.
#[test]
fn typed_names_work_as_il_operators() {
    let src = "PROGRAM main\nVAR\n  x : INT := 32767;\n  a : INT;\n  b : DINT;\n  m : DINT;\nEND_VAR\n  \
               LD x\n  ADD_INT 1\n  ST a\n  LD 3\n  MUL_DINT 100000\n  ST b\n  LD 1\n  MUX_INT_DINT 10, 20, 30\n  ST m\nEND_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    let (col, _) = run(dir.path(), "f.il", src);
    assert_eq!(col["main.a"], "-32768");
    assert_eq!(col["main.b"], "300000");
    assert_eq!(col["main.m"], "20");
}

#[test]
fn typed_name_with_other_input_types_is_e1410_and_user_functions_win() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("e.st");
    std::fs::write(
        &file,
        "PROGRAM main\nVAR\n  a : INT;\n  d : DINT;\nEND_VAR\n  a := ADD_INT(d, 1);\nEND_PROGRAM\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&file)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("e.st:6:8: error[E1410]: `ADD_INT` takes INT inputs, not DINT"),
        "{stderr}"
    );
    assert_eq!(stderr.matches("error[").count(), 1, "{stderr}");

    // a user FUNCTION MAX_REAL is called, not the typed MAX
    let src = "FUNCTION MAX_REAL : REAL\nVAR_INPUT\n  x : REAL;\nEND_VAR\n  MAX_REAL := x * 2.0;\nEND_FUNCTION\n\
               PROGRAM main\nVAR\n  o : REAL;\nEND_VAR\n  o := MAX_REAL(1.5);\nEND_PROGRAM\n";
    let (col, _) = run(dir.path(), "u.st", src);
    assert_eq!(col["main.o"], "3");
}
