//! Issue #13, thirteenth round (helper `small4`): small constructs that stopped real TwinCAT and
//! CODESYS projects, each through `ladderc run` on fixtures written here
//! (`tests/tests/fixtures/lang_left_r13/`):
//! - **A FOR whose control variable is an array element** (`FOR Offset[1] := 0 TO n DO`, TcUnit's
//!   FB_TestSuite): one E1044 per loop in this round; compiled since the `enumctx` round, as
//!   TwinCAT does. Before: E0100 at `[`, then E3101 for each EXIT inside the loop and E0100 for
//!   its `END_FOR`.
//! - **An attribute pragma without its `}` before an enumeration** (`{attribute 'qualified only'`
//!   then `{attribute 'strict'}`, SeanyCash/TwinCAT_CNC): attributes do not nest, so the pragma ends
//!   at the next `}`, with warning W1420; per-value attributes inside the enumeration are notes.
//!   Before: E0001 at each `{` and `}`, the enumeration unknown.
//! - **ExST assignment as a condition** (`IF b := (i = 1) THEN`, `WHILE more := (n < 5) DO`): the
//!   IF's first condition assigns before the IF and tests the variable; a WHILE condition assigns at
//!   every test (also after a CONTINUE); in an ELSIF or UNTIL condition too (`enum_context_run.rs`). Before:
//!   E0100/E0104 at the `:=`.
//! - **`SIZEOF` in IL** as the TwinCAT help writes it (`LD arr1` / `SIZEOF` / `ST var1`): the bytes
//!   of the loaded variable, as ST's `SIZEOF(arr1)`. Before: E1019.
//! - **`TYPE INTERNAL Name :`** (an access specifier on a data type, stefanbesler/struckig): one
//!   W0304, as for `FUNCTION_BLOCK INTERNAL`. Before: E0011 at the name and each member.

mod common;
use common::run_traced;
use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/lang_left_r13")
        .join(name)
}

// ------------------------------------------------------------------ 1. FOR over an array element

/// Two nested FORs counting in `Offset[1]` and `Offset[2]`, with an EXIT and an `END_FOR` without
/// `;` (E1044 until the `enumctx` round, see `enum_context_run.rs`): the inner loop counts 0 and 1
/// and leaves at 2, four times: Sum grows by 8 + 100 per scan.
#[test]
fn for_over_an_array_element_runs() {
    let (trace, _) = run_traced(
        &fixture("for_element_control.st"),
        2,
        "Main.Sum,Main.Offset[1],Main.Offset[2]",
    );
    let rows: Vec<&str> = trace.lines().skip(1).collect();
    assert_eq!(rows, ["0,0,108,4,2", "1,10,216,4,2"], "{trace}");
}

// ------------------------------------------------------------------ 2. pragmas in an enumeration

/// enum_pragmas.st: `{attribute 'qualified only'` without `}` runs into `{attribute 'strict'}`
/// (W1420), per-value attributes sit between the values; the enumeration keeps its values
/// (Idle = 1, Ready = 2, Started = 5): Idle -> Ready -> Started, Code follows the state.
#[test]
fn unclosed_attribute_and_value_attributes_leave_the_enumeration_intact() {
    let (trace, stderr) = run_traced(&fixture("enum_pragmas.st"), 3, "Main.Code,Main.State");
    let rows: Vec<&str> = trace.lines().collect();
    assert_eq!(rows[0], "cycle,time_ms,Main.Code,Main.State");
    assert_eq!(&rows[1..], ["0,0,2,2", "1,10,5,5", "2,20,5,5"]);
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("warning[")).collect();
    assert_eq!(warnings.len(), 1, "{stderr}");
    assert!(
        warnings[0].contains("enum_pragmas.st:3:1: warning[W1420]: pragma `{attribute 'qualified only'` is not closed"),
        "{stderr}"
    );
}

// ------------------------------------------------------------------ 3. ExST assignment as a condition

/// exst_condition_assign.st, per scan: i counts 1, 2, 3; `IF b := (i = 1)` sets b TRUE only in the
/// first scan (hits stays 1 after it); `WHILE more := (n < 5)` runs for n = 0..4, the body counting
/// n = 2 as skipped (CONTINUE) and the others as tests, and the last test assigns more FALSE.
#[test]
fn assignment_as_if_and_while_condition_runs_before_each_test() {
    let (trace, _) = run_traced(
        &fixture("exst_condition_assign.st"),
        3,
        "Main.i,Main.b,Main.hits,Main.n,Main.more,Main.skipped,Main.tests",
    );
    let rows: Vec<&str> = trace.lines().skip(1).collect();
    assert_eq!(
        rows,
        [
            "0,0,1,1,1,5,0,1,4",
            "1,10,2,0,1,5,0,2,8",
            "2,20,3,0,1,5,0,3,12"
        ]
    );
}

/// An assignment as an ELSIF or an UNTIL condition (E1045 until the `enumctx` round, see
/// `enum_context_run.rs`): the ELSIF assigns `b := (i = 4)`, TRUE in the second scan only (x + 2),
/// the UNTIL counts i up to 4 in the first scan and stops after one pass in the others.
#[test]
fn assignment_as_elsif_or_until_condition_runs() {
    let (trace, _) = run_traced(
        &fixture("exst_condition_assign_bad.st"),
        3,
        "Main.i,Main.x,Main.b",
    );
    let rows: Vec<&str> = trace.lines().skip(1).collect();
    assert_eq!(rows, ["0,0,4,0,1", "1,10,5,2,1", "2,20,6,2,1"], "{trace}");
}

// ------------------------------------------------------------------ 4. SIZEOF in IL

/// il_sizeof.il: `LD arr1 SIZEOF` of an ARRAY[0..4] OF INT is 10, of a STRUCT of two DINTs 8, of
/// one INT element 2; nPair + (nElem + 1) = 11 shows the sizes are ordinary values.
#[test]
fn sizeof_in_il_counts_the_bytes_of_the_loaded_variable() {
    let (trace, _) = run_traced(
        &fixture("il_sizeof.il"),
        1,
        "Main.var1,Main.nPair,Main.nElem,Main.total",
    );
    let rows: Vec<&str> = trace.lines().collect();
    assert_eq!(
        rows,
        [
            "cycle,time_ms,Main.var1,Main.nPair,Main.nElem,Main.total",
            "0,0,10,8,2,11"
        ]
    );
}

// ------------------------------------------------------------------ 5. TYPE INTERNAL

/// type_internal.st: `TYPE INTERNAL Interval : STRUCT ...`: one W0304 at `INTERNAL`; the struct is
/// used as declared: width = Right - Left = 2.0 - 1.5, then 4.0 - 1.5.
#[test]
fn access_specifier_on_a_data_type_is_one_warning() {
    let (trace, stderr) = run_traced(&fixture("type_internal.st"), 2, "Main.width");
    let rows: Vec<&str> = trace.lines().skip(1).collect();
    assert_eq!(rows, ["0,0,0.5", "1,10,2.5"]);
    assert!(
        stderr.contains("type_internal.st:3:6: warning[W0304]: `TYPE INTERNAL` of `Interval`: the modifier is ignored"),
        "{stderr}"
    );
}
