//! Round 27 of issue #13: what real projects met, fixed outside the helpers' files.
//!
//! - A `;` after the last `END_VAR` that the body follows (SIMATIC AX and TwinCAT blocks whose body
//!   is only `;`) is the body's empty statement, valid ST (IEC 61131-3 edition 2:
//!   `statement ::= NIL | ...`): no warning (before: W0017 "a `;` after END_VAR: skipped, ends no
//!   declaration" on 5 inputs of round 27). Where declarations or the end of the text follow, it
//!   is still W0017.
//! - A method a derived class inherits, calling a PRIVATE method of another instance of the class
//!   that declares it (`Compare` of `Account` calling `other.Secret()`, run by a `Savings EXTENDS
//!   Account`), is the declaring class's code: it runs (IEC 61131-3 ed. 3, 6.6.5; before: E1021,
//!   once round 27 checked methods nothing calls, on the copy a derived class inherits). The
//!   derived class's own method calling it stays E1021.

mod common;
use common::{check_text, column, run_text};

/// A body of only `;`, and `;` before the first statement: no W0017, the program runs; `END_VAR;`
/// before another VAR block and at the end of a list of globals: W0017 each.
#[test]
fn an_empty_statement_after_end_var_is_no_warning() {
    let (code, lines) = check_text(
        "empty.st",
        "FUNCTION_BLOCK Idle\nVAR_INPUT a : INT; END_VAR\n    ;\nEND_FUNCTION_BLOCK\n\
PROGRAM Main\nVAR x : INT; i : Idle; END_VAR\n;\nx := x + 1;\ni(a := x);\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(lines.iter().all(|l| !l.contains("W0017")), "{lines:?}");
    let (trace, stderr) = run_text(
        "empty.st",
        "PROGRAM Main\nVAR x : INT; END_VAR\n;\nx := x + 1;\n;\nEND_PROGRAM\n",
        3,
        "Main.x",
    );
    assert_eq!(trace, "cycle,time_ms,Main.x\n0,0,1\n1,10,2\n2,20,3\n");
    assert!(!stderr.contains("W0017"), "{stderr}");

    let (code, lines) = check_text(
        "decl.st",
        "VAR_GLOBAL g : INT; END_VAR;\nPROGRAM Main\nVAR x : INT; END_VAR;\nVAR y : INT := 2; END_VAR\nx := y + g;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(0), "{lines:?}");
    let w: Vec<&String> = lines.iter().filter(|l| l.contains("W0017")).collect();
    assert_eq!(w.len(), 2, "{lines:?}");
    assert!(w[0].starts_with("decl.st:1:28:"), "{lines:?}");
    assert!(w[1].starts_with("decl.st:3:21:"), "{lines:?}");
}

const ACCOUNT: &str = "CLASS Account
VAR PRIVATE balance : INT; END_VAR
METHOD PRIVATE Secret : INT
    Secret := balance;
END_METHOD
METHOD PUBLIC Deposit
VAR_INPUT n : INT; END_VAR
    balance := balance + n;
END_METHOD
METHOD PUBLIC Compare : INT
VAR_IN_OUT other : Account; END_VAR
    Compare := Secret() - other.Secret();
END_METHOD
END_CLASS
";

/// `Compare` (Account's) run by a `Savings` instance reaches `other.Secret()`: 1 - 3 = -2; with a
/// `Savings` that declares nothing and none of it called, the program checks clean too.
#[test]
fn an_inherited_method_reaches_its_declaring_class_private_members() {
    let src = format!(
        "{ACCOUNT}CLASS Savings EXTENDS Account\nEND_CLASS\n\
PROGRAM Main\nVAR a, b : Account; s : Savings; d, e : INT; END_VAR\n\
a.Deposit(n := 10);\nb.Deposit(n := 3);\ns.Deposit(n := 1);\n\
d := a.Compare(other := b);\ne := s.Compare(other := b);\nEND_PROGRAM\n"
    );
    let (trace, stderr) = run_text("acc.st", &src, 2, "Main.d,Main.e");
    assert_eq!(column(&trace, "Main.d"), [7.0, 14.0], "{stderr}");
    assert_eq!(column(&trace, "Main.e"), [-2.0, -4.0], "{stderr}");

    let own = format!(
        "{ACCOUNT}CLASS Savings EXTENDS Account\nMETHOD PUBLIC Peek : INT\n\
VAR_IN_OUT o : Account; END_VAR\n    Peek := o.Secret();\nEND_METHOD\nEND_CLASS\n\
PROGRAM Main\nVAR b : Account; s : Savings; e : INT; END_VAR\ne := s.Peek(o := b);\nEND_PROGRAM\n"
    );
    let (code, lines) = check_text("own.st", &own);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("own.st:18:15: error[E1021]: METHOD `Secret` is PRIVATE to `Account`"),
        "{lines:?}"
    );
}
