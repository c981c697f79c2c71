//! Object-oriented constructs of CODESYS and TwinCAT left over from the first rounds (issue #13),
//! run end to end through `ladderc run` on files written for these tests
//! (`fixtures/oop_substitution/`): a method's VAR_INST (kept in the instance between calls), a
//! derived instance passed where its base is expected (VAR_IN_OUT, `REFERENCE TO`, `POINTER TO`,
//! `REF=`; IEC 61131-3 ed. 3, 6.6.5 substitutability) with the methods called through the base view
//! dispatched to the derived block's overrides.

mod common;
use common::{column, run_traced};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/oop_substitution")
        .join(rel)
}

/// `VAR_INST calls : INT := 100;` in `Count`: each instance keeps its own count from call to call
/// and from cycle to cycle (two calls of `a` per cycle, one of `b`), starting at 100; the method's
/// `VAR scratch` starts again at 0 at each call (the `+ 1` in every result). The derived `FB_Twice`
/// inherits the method and its VAR_INST, kept in its own instance.
#[test]
fn var_inst_of_a_method_is_kept_in_each_instance_between_calls() {
    let (trace, stderr) = run_traced(
        &fixture("var_inst.st"),
        3,
        "Main.ra,Main.rb,Main.rt,Main.a.total,Main.b.total,Main.t.total",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    // a: calls 102, 104, 106 after its second call of each cycle
    assert_eq!(column(&trace, "Main.ra"), [1021.0, 1041.0, 1061.0]);
    assert_eq!(column(&trace, "Main.rb"), [1011.0, 1021.0, 1031.0]);
    assert_eq!(column(&trace, "Main.rt"), [1012.0, 1022.0, 1032.0]);
    assert_eq!(column(&trace, "Main.a.total"), [2.0, 4.0, 6.0]);
    assert_eq!(column(&trace, "Main.b.total"), [5.0, 10.0, 15.0]);
    assert_eq!(column(&trace, "Main.t.total"), [2.0, 4.0, 6.0]);
}
