//! A method's VAR_IN_OUT passed on by reference inside its block (issue #13; Struckig's
//! `VelocityThirdOrderStep1.Get` passes its in-out `block` to `CalculateBlock(block)` and
//! `block.A` to `AddInterval`, and `VelocitySecondOrderStep1.Get` writes `p REF= block.Pmin` into a
//! `REFERENCE TO` variable of the method). A VAR_IN_OUT may stand for a variable of the caller that
//! lives for one call, so ladderc binds such a reference for the call only: a `REFERENCE TO` input
//! of the block's own method is reset to NULL when the call returns, a method's VAR / VAR_TEMP
//! starts again at each call, and no reference may be kept through either (E0305). Before, each
//! such use was E0305.

mod common;
use common::{column, diagnostic_heads, rejected_heads, run_traced};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/codesys_loose")
        .join(rel)
}

#[test]
fn an_in_out_passes_on_to_the_blocks_own_methods_for_one_call() {
    let f = fixture("method_refs.st");
    let (trace, stderr) = run_traced(
        &f,
        2,
        "main.b1.n,main.b1.Tmin,main.b1.A.Left,main.b1.A.Right,main.b2.n,main.b2.Tmin,main.ok1,main.ok2,main.none,main.s.stale",
    );
    // Get(b1) once a scan, Get(b2) twice: CalculateBlock counts in the caller's block through
    // both references, AddInterval writes its interval `block.A`
    assert_eq!(column(&trace, "main.b1.n"), [1.0, 2.0]);
    assert_eq!(column(&trace, "main.b1.Tmin"), [2.5, 5.0]);
    assert_eq!(column(&trace, "main.b1.A.Left"), [2.5, 5.0]);
    assert_eq!(column(&trace, "main.b1.A.Right"), [3.5, 6.0]);
    assert_eq!(column(&trace, "main.b2.n"), [2.0, 4.0]);
    assert_eq!(column(&trace, "main.b2.Tmin"), [5.0, 10.0]);
    assert_eq!(column(&trace, "main.ok1"), [1.0, 1.0]);
    assert_eq!(column(&trace, "main.ok2"), [1.0, 1.0]);
    // CalculateBlock called without its block finds no reference left from Get's calls (1000
    // each scan), and Get's `p` starts unbound at each call (no 1)
    assert_eq!(column(&trace, "main.none"), [0.0, 0.0]);
    assert_eq!(column(&trace, "main.s.stale"), [1000.0, 2000.0]);
    assert!(
        diagnostic_heads(stderr.as_bytes(), f.parent().unwrap(), false).is_empty(),
        "{stderr}"
    );
}

/// What would keep such a reference past the call stays E0305: into a variable of the block,
/// through `ADR`, into a method's VAR_INST (kept from call to call), and into the input of
/// another instance's method.
#[test]
fn a_reference_kept_past_the_call_is_e0305() {
    let heads = rejected_heads(
        "keep.st",
        "TYPE Block : STRUCT n : INT; END_STRUCT; END_TYPE\n\
         FUNCTION_BLOCK Other\n\
         METHOD Take : BOOL\nVAR_INPUT\n  r : REFERENCE TO Block;\nEND_VAR\nTake := TRUE;\nEND_METHOD\n\
         END_FUNCTION_BLOCK\n\
         FUNCTION_BLOCK Step\nVAR\n  keep : REFERENCE TO Block;\n  pn : POINTER TO INT;\n  o : Other;\nEND_VAR\n\
         METHOD Calc : BOOL\nVAR_INPUT\n  block : REFERENCE TO Block;\nEND_VAR\n\
         keep REF= block;\npn := ADR(block.n);\nCalc := o.Take(block);\nEND_METHOD\n\
         METHOD Get : BOOL\nVAR_IN_OUT\n  block : Block;\nEND_VAR\nVAR\n  p : REFERENCE TO Block;\nEND_VAR\n\
         VAR_INST\n  q : REFERENCE TO Block;\nEND_VAR\n\
         p REF= block;\nkeep REF= p;\nq REF= block;\nGet := Calc(block);\nEND_METHOD\n\
         END_FUNCTION_BLOCK\n\
         PROGRAM main\nVAR\n  s : Step;\n  b : Block;\n  ok : BOOL;\nEND_VAR\nok := s.Get(b);\nEND_PROGRAM\n",
    );
    let kept = "is not allowed: the method's `BLOCK` may refer to a VAR_IN_OUT or a temporary of a caller, which lives for one call";
    assert_eq!(
        heads,
        [
            format!("keep.st:20:6: error[E0305]: a reference to `BLOCK` {kept}"),
            format!("keep.st:21:7: error[E0305]: a reference to `BLOCK.n` {kept}"),
            format!("keep.st:22:16: error[E0305]: a reference to `BLOCK` {kept}"),
            "keep.st:35:6: error[E0305]: a reference to `P` is not allowed: the method's `P` may refer to a VAR_IN_OUT or a temporary of a caller, which lives for one call".to_string(),
            "keep.st:36:3: error[E0305]: a reference to `BLOCK` is not allowed: a VAR_IN_OUT may stand for a temporary variable of the caller".to_string(),
        ]
    );
}
