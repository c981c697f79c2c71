//! IL formal calls of the standard functions that share an IL operator's name (issue #13): `MOD(`,
//! `GT(`, `ADD(` followed by `IN1 := ...` lines is the IEC 61131-3 formal function call (matiec accepts
//! it, Beremiz writes it), not a deferred operator. The layout pass tells the two apart by looking past
//! the `(` (over line ends and comments) for `name :=` or `name =>`; `MUL( b` and `AND(` with a nested
//! instruction list stay deferred operators. Before, each argument line was E0011.

mod common;
use common::ladderc;

fn run(src: &str, watch: &str, cycles: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("formal.il");
    std::fs::write(&file, src).unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .arg("run")
        .arg(&file)
        .args(["--cycles", cycles, "--sanitize", "--trace"])
        .arg(&trace)
        .args(["--watch", watch])
        .output()
        .unwrap();
    common::assert_ok(&out);
    std::fs::read_to_string(&trace).unwrap()
}

#[test]
fn formal_calls_of_operator_named_functions_run_beside_deferred_operators() {
    let src = "PROGRAM p\nVAR\n  x : INT := 17;\n  b : INT := 4;\n  lim : INT;\n  m : INT;\n  \
               ok : BOOL;\n  s : INT;\n  g : BOOL;\n  d : INT;\n  n : BOOL;\nEND_VAR\n  \
               LIMIT(\n    MN := 0,\n    IN := x,\n    MX := 10\n  )\n  ST lim\n  \
               MOD(\n    IN1 := x, (* the dividend *)\n    IN2 := 5,\n    ENO => ok\n  )\n  ST m\n  \
               ADD(IN1 := x, IN2 := b)\n  ST s\n  \
               GT(\n    IN1 := b,\n    IN2 := x\n  )\n  ST g\n  \
               LD x\n  MUL( b\n  ADD 1\n  )\n  ST d\n  \
               LD TRUE\n  AND(\n    LD g\n    OR TRUE\n  )\n  ST n\n\
               END_PROGRAM\n";
    // LIMIT(0, 17, 10) = 10; MOD(17, 5) = 2 with ENO TRUE; 17 + 4 = 21; 4 > 17 is FALSE;
    // the deferred 17 * (4 + 1) = 85; TRUE AND (FALSE OR TRUE) = TRUE.
    assert_eq!(
        run(src, "p.lim,p.m,p.ok,p.s,p.g,p.d,p.n", "1"),
        "cycle,time_ms,p.lim,p.m,p.ok,p.s,p.g,p.d,p.n\n0,0,10,2,1,21,0,85,1\n"
    );
}

#[test]
fn a_formal_operator_call_missing_an_input_is_one_located_error() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("bad.il");
    std::fs::write(
        &file,
        "PROGRAM p\nVAR\n  x : INT := 17;\n  m : INT;\nEND_VAR\n  MOD(\n    IN1 := x\n  )\n  ST m\nEND_PROGRAM\n",
    )
    .unwrap();
    let out = ladderc()
        .arg("check")
        .arg(&file)
        .args(["--message-format", "short"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    let errors: Vec<&str> = err.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{err}");
    assert!(errors[0].contains("bad.il:6:3"), "{err}");
}
