//! Round 27 of issue #13: what real projects met, fixed outside the helpers' files.
//!
//! - A `;` after the last `END_VAR` that the body follows (SIMATIC AX and TwinCAT blocks whose body
//!   is only `;`) is the body's empty statement, valid ST (IEC 61131-3 edition 2:
//!   `statement ::= NIL | ...`): no warning (before: W0017 "a `;` after END_VAR: skipped, ends no
//!   declaration" on 5 inputs of round 27). Where declarations or the end of the text follow, it
//!   is still W0017.

mod common;
use common::{check_text, run_text};

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
