//! Bit strings counted as unsigned integers, as CODESYS and TwinCAT count them (issue #13; W1436):
//! a BYTE FOR control variable (Struckig's `Roots.PolyMonicDeri`: `FOR i := 1 TO coeffsCount - 1`
//! of BYTEs), arithmetic on BYTE, WORD, DWORD wrapping around as USINT, UINT, UDINT, a BYTE stored
//! into an INT, a BYTE index. IEC 61131-3 gives bit strings no arithmetic: everything else stays as
//! the standard says (BOOL is no number; a WORD does not fit an INT implicitly).

mod common;
use common::{column, diagnostic_heads, ladderc, rejected_heads, run_traced};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/bit_strings")
        .join(rel)
}

#[test]
fn bit_strings_count_as_unsigned_integers() {
    let f = fixture("counting.st");
    let (trace, stderr) = run_traced(
        &f,
        2,
        "main.p.s,main.p.count,main.p.i,main.p.out[1],main.b,main.w,main.d,main.k,main.down,main.j,main.m",
    );
    // FOR i := 1 TO n - 1 of a BYTE: 3 rounds, out[i] := (n - i) * 0.5
    assert_eq!(column(&trace, "main.p.count"), [3.0, 3.0]);
    assert_eq!(column(&trace, "main.p.s"), [3.0, 3.0]);
    assert_eq!(column(&trace, "main.p.out[1]"), [1.5, 1.5]);
    assert_eq!(column(&trace, "main.p.i"), [4.0, 4.0]);
    // wrap-around of the unsigned type: BYTE 254 + 1 = 255, + 1 = 0; WORD 16#FFFE likewise
    assert_eq!(column(&trace, "main.b"), [255.0, 0.0]);
    assert_eq!(column(&trace, "main.w"), [65535.0, 0.0]);
    assert_eq!(column(&trace, "main.d"), [29.0, 86.0]);
    // a BYTE into an INT
    assert_eq!(column(&trace, "main.k"), [255.0, 0.0]);
    // FOR j := 1 TO 7 BY 3 of a BYTE: 1, 4, 7, then j = 10
    assert_eq!(column(&trace, "main.down"), [147.0, 147.0]);
    assert_eq!(column(&trace, "main.j"), [10.0, 10.0]);
    // MOD and / of a BYTE: 7 MOD 4 + 7 / 2 = 6, then 6 MOD 4 + 6 / 2 = 5
    assert_eq!(column(&trace, "main.m"), [6.0, 5.0]);
    // once per POU, at the first use
    let heads = diagnostic_heads(stderr.as_bytes(), f.parent().unwrap(), true);
    assert_eq!(
        heads,
        [
            "counting.st:16:15: warning[W1436]: BYTE counted as the unsigned integer USINT: IEC 61131-3 gives bit strings no arithmetic (its other uses in this POU are not reported)",
            "counting.st:35:6: warning[W1436]: BYTE counted as the unsigned integer USINT: IEC 61131-3 gives bit strings no arithmetic (its other uses in this POU are not reported)",
        ]
    );
}

/// A FOR loop over a BYTE counter with nothing but the counter's own step: the warning is at the
/// control variable.
#[test]
fn a_byte_counter_alone_is_reported_at_the_counter() {
    let out = ladderc()
        .args(["--message-format", "short", "check", "-"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .and_then(|mut c| {
            use std::io::Write;
            c.stdin.take().unwrap().write_all(
                b"PROGRAM main\nVAR\n  i : BYTE;\n  n : INT;\nEND_VAR\nFOR i := 0 TO 9 DO\n  n := n + 1;\nEND_FOR\nEND_PROGRAM\n",
            )?;
            c.wait_with_output()
        })
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(
        stderr.contains("<stdin>:6:5: warning[W1436]: BYTE counted as the unsigned integer USINT"),
        "{stderr}"
    );
    assert_eq!(stderr.matches("W1436").count(), 1, "{stderr}");
}

/// Everything else stays IEC: BOOL has no arithmetic and is no FOR counter; a WORD (UINT) does not
/// widen to INT; an FB instance is stored only into an instance of its own block.
#[test]
fn other_types_keep_the_standard_rules() {
    let heads = rejected_heads(
        "strict.st",
        "FUNCTION_BLOCK A\nVAR_OUTPUT\n  q : INT;\nEND_VAR\nq := q + 1;\nEND_FUNCTION_BLOCK\n\
         FUNCTION_BLOCK B\nVAR_OUTPUT\n  q : INT;\nEND_VAR\nq := q + 2;\nEND_FUNCTION_BLOCK\n\
         PROGRAM main\nVAR\n  x : BOOL;\n  w : WORD;\n  n : INT;\n  a : A;\n  b : B;\nEND_VAR\n\
         x := x + 1;\nn := w;\nb := a;\nn := a;\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        [
            "strict.st:21:6: error[E1004]: ADD is not defined for BOOL",
            "strict.st:22:1: error[E1006]: cannot store WORD into INT",
            "strict.st:23:1: error[E1021]: an FB instance is not a value",
            "strict.st:24:1: error[E1006]: cannot store A into INT",
        ]
    );
    let heads = rejected_heads(
        "bool_counter.st",
        "PROGRAM main\nVAR\n  x : BOOL;\nEND_VAR\nFOR x := 0 TO 1 DO\nEND_FOR\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        ["bool_counter.st:5:5: error[E3100]: the FOR control variable `x` must be an integer variable, but it is BOOL"]
    );
}
