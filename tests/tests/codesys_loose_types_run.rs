//! What CODESYS and TwinCAT accept beyond IEC 61131-3's typing, as Struckig (the TwinCAT port of
//! ruckig) writes it (issue #13): bit-string functions on integers (W1438: `SHL(b, 32)` and `AND`
//! of ULINTs), an integer given to an ANY_REAL input (IEC's own implicit conversion: `TRUNC(n / 2)`
//! of INTs, `SQRT(n)`), and an enumeration without `{attribute 'strict'}` used as an integer
//! (W1439). Each runs through `ladderc run --sanitize` and its values are checked; what the
//! standard and `{attribute 'strict'}` still refuse stays refused.

mod common;
use common::{column, diagnostic_heads, rejected_heads, run_traced};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/codesys_loose")
        .join(rel)
}

#[test]
fn bit_string_functions_work_on_an_integers_bit_pattern() {
    let f = fixture("int_bits.st");
    let (trace, stderr) = run_traced(
        &f,
        2,
        "main.high,main.low,main.either,main.low2,main.right,main.left,main.inverted,main.rolled",
    );
    // raw = 3, then 4: SHL by 32, (raw + 16#FFF) AND 16#FF00, raw OR 4
    assert_eq!(
        column(&trace, "main.high"),
        [3.0 * 2f64.powi(32), 4.0 * 2f64.powi(32)]
    );
    assert_eq!(column(&trace, "main.low"), [4096.0, 4096.0]);
    assert_eq!(column(&trace, "main.either"), [7.0, 4.0]);
    assert_eq!(column(&trace, "main.low2"), [2.0, 2.0]);
    // a signed INT as its WORD: SHR(-16, 2) zero-fills (16#FFF0 -> 16#3FFC), SHL(-16, 2) is
    // 16#FFC0 = -64, NOT 6 = -7; ROL of DINT -1 by 3 is -1, XOR 5 gives -6
    assert_eq!(column(&trace, "main.right"), [16380.0, 16380.0]);
    assert_eq!(column(&trace, "main.left"), [-64.0, -64.0]);
    assert_eq!(column(&trace, "main.inverted"), [-7.0, -7.0]);
    assert_eq!(column(&trace, "main.rolled"), [-6.0, -6.0]);
    // once per POU, at the first use
    assert_eq!(
        diagnostic_heads(stderr.as_bytes(), f.parent().unwrap(), true),
        ["int_bits.st:14:9: warning[W1438]: SHL of ULINT: IEC 61131-3 defines bit-string functions for ANY_BIT only (its other uses in this POU are not reported)"]
    );
}

#[test]
fn an_integer_converts_to_the_real_an_any_real_input_takes() {
    let f = fixture("int_to_real.st");
    let (trace, stderr) = run_traced(
        &f,
        1,
        "main.r[0],main.r[1],main.r[2],main.r[3],main.hits,main.s,main.l,main.l2,main.t",
    );
    // TRUNC of an integer division: 7/2 = 3, 9/2 = 4, -7/2 = -3, 2/2 = 1
    let r: Vec<f64> = (0..4)
        .map(|k| column(&trace, &format!("main.r[{k}]"))[0])
        .collect();
    assert_eq!(r, [3.0, 4.0, -3.0, 1.0]);
    // the CASE on TRUNC(...) takes -3 and 4
    assert_eq!(column(&trace, "main.hits"), [2.0]);
    // SQRT of an INT (as REAL), of a DINT and a UDINT (as LREAL); TRUNC_DINT of an INT
    assert_eq!(column(&trace, "main.s"), [3.0]);
    assert_eq!(column(&trace, "main.l"), [4.0]);
    assert_eq!(column(&trace, "main.l2"), [4_000_000_000f64.sqrt()]);
    assert_eq!(column(&trace, "main.t"), [9.0]);
    // IEC's own implicit conversion: nothing to report
    assert!(
        diagnostic_heads(stderr.as_bytes(), f.parent().unwrap(), true).is_empty(),
        "{stderr}"
    );
    // LINT widens to no real (Figure 11): still refused
    let heads = rejected_heads(
        "lint.st",
        "PROGRAM main\nVAR\n  n : LINT := 9;\n  l : LREAL;\n  t : DINT;\nEND_VAR\n\
         l := SQRT(n);\nt := TRUNC(n);\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        [
            "lint.st:7:6: error[E1004]: SQRT is not defined for LINT",
            "lint.st:8:6: error[E1004]: TRUNC_DINT is not defined for LINT",
        ]
    );
}

#[test]
fn an_enumeration_without_strict_counts_as_its_number() {
    let f = fixture("loose_enum.st");
    let (trace, stderr) = run_traced(
        &f,
        1,
        "main.o.msg,main.c,main.n,main.m,main.c2,main.isFailed,main.p,main.s",
    );
    // Abort(errorId := Code.Failed) stores 7 into the INT, which CASE finds as Code.Failed
    assert_eq!(column(&trace, "main.o.msg"), [2.0]);
    // the INT back into the enumeration (ErrorCode), and out into INTs: 7, 7 + 1
    assert_eq!(column(&trace, "main.c"), [7.0]);
    assert_eq!(column(&trace, "main.n"), [7.0]);
    assert_eq!(column(&trace, "main.m"), [8.0]);
    assert_eq!(column(&trace, "main.c2"), [1.0]);
    assert_eq!(column(&trace, "main.isFailed"), [1.0]);
    // 5 is no value of Code: CASE takes ELSE, TO_STRING gives the number
    assert_eq!(column(&trace, "main.p"), [2.0]);
    assert!(trace.lines().nth(1).unwrap().ends_with(",\"5\""), "{trace}");
    // once per POU
    assert_eq!(
        diagnostic_heads(stderr.as_bytes(), f.parent().unwrap(), true),
        [
            "loose_enum.st:22:7: warning[W1439]: the enumeration Code used as an integer: IEC 61131-3 enumerations are no numbers (its other uses in this POU are not reported)",
            "loose_enum.st:41:1: warning[W1439]: the enumeration Code used as an integer: IEC 61131-3 enumerations are no numbers (its other uses in this POU are not reported)",
        ]
    );
}

/// `{attribute 'strict'}` (also below another attribute) keeps IEC's strong typing where Beckhoff
/// Infosys ("Attribute 'strict'") lists compile errors: an integer (variable or literal) stored
/// into the enumeration, arithmetic with it (and, as before, a comparison with an integer). Its
/// value stored into an integer is no error there (round 27: `vendor_forms_r27_run.rs`).
#[test]
fn a_strict_enumeration_stays_no_number() {
    let heads = rejected_heads(
        "strict.st",
        "{attribute 'strict'}\nTYPE Strict : (A, B); END_TYPE\n\
         {attribute 'strict'}\n{attribute 'qualified_only'}\nTYPE Strict2 : (C, D); END_TYPE\n\
         PROGRAM main\nVAR\n  s : Strict;\n  t : Strict2;\n  n : INT;\nEND_VAR\n\
         s := n;\ns := 1;\nt := n;\nIF s = 0 THEN n := 2; END_IF\nn := s + 1;\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        [
            "strict.st:12:1: error[E1006]: cannot store INT into Strict",
            "strict.st:13:1: error[E1006]: cannot store an integer literal into Strict",
            "strict.st:14:1: error[E1006]: cannot store INT into Strict2",
            "strict.st:15:8: error[E1005]: EQ of Strict with an integer literal",
            "strict.st:16:6: error[E1004]: ADD is not defined for Strict",
        ]
    );
}
