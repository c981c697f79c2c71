//! Round 25 of unseen projects (issue #13), names and literals, run end to end through `ladderc`:
//! - a structure's field named with a keyword, an elementary type or a standard block (`Type`,
//!   `Configuration`, `program`, `byte`, `dT`, `tp`, `ton`: B&R's own library types) is declared
//!   and used as `s.Type` (before: E1031 at each, and the POU not compiled);
//! - an undeclared name alone as a statement (`gAimPos;`) is sema's E1001, reported with every
//!   other error of the project (before: reported by the lowering, which stopped every other check);
//! - a name alone as the first statement of a CASE branch (`0: Bump;`) is W1431, or B&R's call of
//!   an action, as anywhere else (before: E0106);
//! - an untyped integer literal beside an operand whose type cannot hold it takes the smallest type
//!   that operand widens to and that holds it: `b0 + 256 * b1` of USINT operands is a UINT
//!   (before: E1017 "literal 256 does not fit USINT").

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

/// Fields named `Type`, `Configuration`, `program` (block keywords), `byte`, `dT` (elementary
/// types), `tp`, `ton` (standard blocks) and `Continue` are written and read through `.`; a
/// variable named `Configuration` stays one E1031.
#[test]
fn struct_fields_named_with_keywords_types_and_blocks_run() {
    let src = "TYPE
  Rec : STRUCT
    Type : USINT;
    Configuration : INT;
    byte : USINT;
    dT : LREAL;
    tp, ton : LREAL;
    Continue : BOOL;
    program : INT := 7;
  END_STRUCT;
END_TYPE
PROGRAM P
VAR r : Rec; n : LREAL; END_VAR
r.Type := 3; r.Configuration := 4; r.byte := 5; r.dT := 1.5; r.tp := 2.0; r.ton := 0.25;
r.Continue := TRUE;
n := r.dT + r.tp + r.ton + USINT_TO_LREAL(r.Type) + USINT_TO_LREAL(r.byte)
  + INT_TO_LREAL(r.Configuration) + INT_TO_LREAL(r.program);
END_PROGRAM
";
    let (trace, stderr) = run_text("fields.st", src, 1, "P.n,P.r.Type,P.r.tp");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "P.n"), vec![22.75]);
    assert_eq!(column(&trace, "P.r.Type"), vec![3.0]);
    assert_eq!(column(&trace, "P.r.tp"), vec![2.0]);
    // a variable is still no place for a keyword
    let (code, lines) = check_text(
        "var.st",
        "PROGRAM P\nVAR Configuration : INT; END_VAR\nConfiguration := 1;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert!(
        lines.iter().any(|l| l.contains("var.st:2:5: error[E1031]")),
        "{lines:?}"
    );
}

/// `undeclared_x;` is one E1001 of sema, and the unknown type, the name declared twice and the
/// other undeclared name of the file are reported with it.
#[test]
fn an_undeclared_name_alone_hides_no_other_error() {
    let src = "PROGRAM P
VAR
  a : NoSuchType;
  b : INT;
  b : INT;
END_VAR
undeclared_x;
b := undeclared_y;
undeclared_x;
END_PROGRAM
";
    let (code, lines) = check_text("bare.st", src);
    assert_eq!(code, Some(1));
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    for want in [
        "bare.st:3:7: error[E1003]",
        "bare.st:5:3: error[E1002]",
        "bare.st:7:1: error[E1001]: undeclared name `undeclared_x`",
        "bare.st:8:6: error[E1001]: undeclared name `undeclared_y`",
    ] {
        assert!(errors.iter().any(|l| l.contains(want)), "{want}: {lines:?}");
    }
    // one E1001 per POU and name
    assert_eq!(errors.len(), 4, "{lines:?}");
}

/// `0: x;` is W1431 as the same statement elsewhere, and the program runs.
#[test]
fn a_name_alone_first_in_a_case_branch_is_w1431() {
    let src = "PROGRAM P
VAR s : INT; x : INT; n : INT; END_VAR
CASE s OF
  0: x;
     n := n + 1;
  1, 2: x; n := n + 10;
END_CASE
s := s + 1;
END_PROGRAM
";
    let (code, lines) = check_text("case.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(
        lines
            .iter()
            .any(|l| l.contains("case.st:4:6: warning[W1431]")),
        "{lines:?}"
    );
    assert!(!lines.iter().any(|l| l.contains("error[")), "{lines:?}");
    let (trace, _) = run_text("case.st", src, 4, "P.n");
    assert_eq!(column(&trace, "P.n"), vec![1.0, 11.0, 21.0, 21.0]);
}

/// A B&R program calls its action `Bump` as the first statement of branch 0 as in branch 1.
#[test]
fn a_bnr_action_called_first_in_a_case_branch_runs() {
    let dir = tempfile::tempdir().unwrap();
    let prog = dir.path().join("Counter");
    write_in(
        &prog,
        "Main.st",
        "PROGRAM _INIT\n\tstep := 0;\nEND_PROGRAM\n\nPROGRAM _CYCLIC\n\tCASE step OF\n\t\t0:\n\t\t\tBump;\n\t\t1:\n\t\t\tcount := count + 100;\n\t\t\tBump;\n\tEND_CASE\n\tstep := step + 1;\n\tIF step > 1 THEN step := 0; END_IF\nEND_PROGRAM\n",
    );
    write_in(
        &prog,
        "Act.st",
        "ACTION Bump:\n\tcount := count + 1;\nEND_ACTION\n",
    );
    write_in(
        &prog,
        "Variables.var",
        "VAR\n\tstep : INT;\n\tcount : INT;\nEND_VAR\n",
    );
    let (code, out, err) = in_dir(
        &prog,
        &[
            "run",
            "Main.st",
            "Act.st",
            "Variables.var",
            "--lang",
            "st",
            "--cycles",
            "4",
            "--watch",
            "Counter.count",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("W1431") && !err.contains("E0106"), "{err}");
    assert_eq!(
        column(&out, "Counter.count"),
        vec![1.0, 102.0, 103.0, 204.0]
    );
}

/// `bytes[0] + 256 * bytes[1]` of USINT into a UINT is 16#1234; `b + 256` (literal on the right),
/// `s - 1000` (SINT into INT) and `b < 300` compute in the wider type; a result stored back into
/// USINT stays E1006 (no silent truncation).
#[test]
fn a_literal_beyond_its_operand_type_takes_a_wider_type() {
    let src = "PROGRAM P
VAR
  bytes : ARRAY[0..1] OF USINT := [16#34, 16#12];
  word16 : UINT;
  b : USINT := 200;
  s : SINT := -100;
  u : UINT;
  i : INT;
  big : BOOL;
END_VAR
word16 := bytes[0] + 256 * bytes[1];
u := b + 256;
i := s - 1000;
big := b < 300;
END_PROGRAM
";
    let (trace, stderr) = run_text("lit.st", src, 1, "P.word16,P.u,P.i,P.big");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "P.word16"), vec![4660.0]);
    assert_eq!(column(&trace, "P.u"), vec![456.0]);
    assert_eq!(column(&trace, "P.i"), vec![-1100.0]);
    assert_eq!(column(&trace, "P.big"), vec![1.0]);
    let (code, lines) = check_text(
        "narrow.st",
        "PROGRAM P\nVAR b : USINT; x : USINT; END_VAR\nx := b + 256;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert!(
        lines
            .iter()
            .any(|l| l.contains("narrow.st:3:1: error[E1006]")),
        "{lines:?}"
    );
}
