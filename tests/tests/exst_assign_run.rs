//! Issue #13: ExST's assignment as an expression, `a := b := e;` (CODESYS and Beckhoff
//! "ExST assignment as expression": every place of the chain receives the value of `e`), as a
//! TwinCAT project wrote `bStart := bStop := FALSE;`. Before: E0104 "missing `;`" at the second `:=`.

mod common;
use common::{column, run_traced};

/// Each scan: `a` and `b` get `c + 9`; `arr[3]` and `arr[1]` get `a * 2`; both REALs get `c`
/// (converted); three BOOLs get `c > 5` (FALSE on the first scan, TRUE from the second, although
/// `lamp` and `alarm` start TRUE); then `c` counts up.
#[test]
fn a_chained_assignment_gives_the_value_to_every_place() {
    let fixture = common::repo_root().join("tests/tests/fixtures/exst_assign/chain.st");
    let (trace, _) = run_traced(
        &fixture,
        3,
        "Main.a,Main.b,Main.arr[1],Main.arr[3],Main.r1,Main.r2,Main.running,Main.lamp,Main.alarm",
    );
    assert_eq!(column(&trace, "Main.a"), [13.0, 14.0, 15.0], "{trace}");
    assert_eq!(column(&trace, "Main.b"), [13.0, 14.0, 15.0]);
    assert_eq!(column(&trace, "Main.arr[1]"), [26.0, 28.0, 30.0]);
    assert_eq!(column(&trace, "Main.arr[3]"), [26.0, 28.0, 30.0]);
    assert_eq!(column(&trace, "Main.r1"), [4.0, 5.0, 6.0]);
    assert_eq!(column(&trace, "Main.r2"), [4.0, 5.0, 6.0]);
    for name in ["Main.running", "Main.lamp", "Main.alarm"] {
        assert_eq!(column(&trace, name), [0.0, 0.0, 1.0], "{name}: {trace}");
    }
}
