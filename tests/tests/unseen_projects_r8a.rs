//! Issue #13, eighth round (helper `lang5`): four forms real projects write that ladderc refused.
//! Each case is a small program written here, in `tests/fixtures/unseen/`, run through `ladderc run`
//! (traces) or `ladderc check`:
//! - **`END_STRUCT END_TYPE` without `;`** (CODESYS and TwinCAT DUTs, `(A, B) END_TYPE`,
//!   `T : INT (0..100) END_TYPE`): IEC 61131-3's grammar ends each type declaration with `;`, so it
//!   is warning W0013, and the types work. Before: E0011 "expected `;` before `END_TYPE`".
//! - **An XML POU whose interface declares `POINTER TO` / `REFERENCE TO`** (a CODESYS export):
//!   one E0305 for the POU, naming the first such type (the others as labels), and the body is not
//!   compiled, as for an ST file. Before: E3012 per declaration and a cascade from the body (`^`).
//! - **Hierarchical direct addresses** (`%IX1.0.0`, `%IW0.0`, `%QW0.0.0.0`): each distinct one is
//!   a slot of its own after the profile's area (see the c-backend README, "Hierarchical
//!   addresses"); stimulus and trace name it by its text, and two variables at one address alias.
//!   Before: E2002.
//! - **VAR_ACCESS** in a configuration (IEC 61131-3 access paths): each path is checked and its
//!   name is a trace/stimulus name; READ_ONLY refuses a stimulus. Before: E0019.

mod common;
use common::{column, ladderc, run_traced};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    common::repo_root()
        .join("tests/tests/fixtures/unseen")
        .join(name)
}

/// `ladderc check FILE` (short format): exit code and the error and warning lines.
fn check(name: &str) -> (Option<i32>, Vec<String>) {
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(fixture(name))
        .output()
        .unwrap();
    let lines = String::from_utf8_lossy(&out.stderr)
        .lines()
        .filter(|l| l.contains("error[") || l.contains("warning["))
        .map(str::to_string)
        .collect();
    (out.status.code(), lines)
}

/// The tank fills by 20 per scan up to the structure's initial `high_limit` (80), then the
/// enumeration's FULL state sets the flag: the structure, the enumeration and the subrange all come
/// from TYPE blocks whose last declaration has no `;`. Each of the three gets W0013 at its `END_TYPE`.
#[test]
fn codesys_types_without_semicolon_before_end_type_run() {
    let (trace, stderr) = run_traced(
        &fixture("codesys_types_without_semicolon.st"),
        7,
        "PLC_PRG.tank.level,PLC_PRG.tank.filling,PLC_PRG.tank_full",
    );
    assert_eq!(
        column(&trace, "PLC_PRG.tank.level"),
        [0.0, 20.0, 40.0, 60.0, 80.0, 80.0, 80.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "PLC_PRG.tank.filling"),
        [1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "PLC_PRG.tank_full"),
        [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0],
        "{trace}"
    );
    let w: Vec<&str> = stderr.lines().filter(|l| l.contains("W0013")).collect();
    assert_eq!(w.len(), 3, "{stderr}");
    for at in [
        ":9:1: warning[W0013]",
        ":11:43: warning[W0013]",
        ":13:31: warning[W0013]",
    ] {
        assert!(w.iter().any(|l| l.contains(at)), "{at}: {stderr}");
    }
}

/// A `;` missing between two declarations of one TYPE block is still a syntax error: only the one
/// before `END_TYPE` is supplied.
#[test]
fn only_the_semicolon_before_end_type_is_supplied() {
    let (code, lines) = common::check_text(
        "two.st",
        "TYPE A : INT END_TYPE\nTYPE B : INT; C : BOOL D : INT; END_TYPE\nPROGRAM p\nVAR x : A; END_VAR\nx := 1;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines
            .iter()
            .any(|l| l.contains("two.st:1:14: warning[W0013]")),
        "{lines:?}"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.contains("two.st:2:") && l.contains("error[E0011]")),
        "{lines:?}"
    );
}

/// The function block declares `pSamples : POINTER TO INT` and `total : REFERENCE TO DINT`, and its
/// body dereferences the pointer: one E0305 at the first, naming both, placed in the POU; nothing
/// from the body, nothing from the program that calls the block.
#[test]
fn xml_pou_with_pointer_declarations_is_one_located_error() {
    let (code, lines) = check("codesys_pointer_fb.xml");
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    let l = &lines[0];
    assert!(
        l.contains("codesys_pointer_fb.xml:14:21: error[E0305]"),
        "{l}"
    );
    assert!(
        l.contains("`FB_Average` declares `POINTER TO INT` and 1 more"),
        "{l}"
    );
    assert!(l.contains("[POU `FB_Average`]"), "{l}");
}
