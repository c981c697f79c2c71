//! Issue #13 (helper `enumctx`): three ST constructs of real TwinCAT/CODESYS projects.
//! - **Implicit (inline) enumerations typed by their context**: `state : (IDLE, RUN);` gets the
//!   internal type `IMPLICIT_ENUM_<POU>_<variable>` (as CODESYS documents), so a bare value that
//!   several enumerations declare is typed by the assignment target, the comparison partner, the
//!   CASE selector or the input it is passed to; a CASE label is typed by the selector for named
//!   enumerations too. Truly ambiguous: E1051. Before: E1001 "is a value of several
//!   enumerations" at each use (54 in benhar-dev/tc3-object-simple-packml).
//! - **ExST assignment in ELSIF and UNTIL conditions** (and inside parentheses in any condition):
//!   before, E1045 / E0100.
//! - **Fixed values in implicit enumerations** (`(Zero, Alfa := 10, Bravo := 20, Echo)`, as CODESYS
//!   documents them; before, E0011 at `:=`), and **implicit enumerations of PLCopen XML
//!   interfaces** (`<type><enum>`, with `value="10"`) typed by context like ST's (before, E1051 at
//!   `mode := Run` when two of them declare `Run`).
//! - **FOR over an array element or structure member** (`FOR Offset[1] := 0 TO n DO`, TcUnit),
//!   as TwinCAT compiles it; the element is chosen once, when the loop starts. Before: E1044.

mod common;
use common::{column, ladderc, run_traced, run_with_stimulus};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    common::repo_root()
        .join("tests/tests/fixtures/enum_context")
        .join(name)
}

/// The short-format diagnostics of `ladderc check` on a fixture that must be rejected (exit 1),
/// each up to its hint, with the fixture folder left out.
fn rejected(name: &str) -> Vec<String> {
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(fixture(name))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    common::diagnostic_heads(
        &out.stderr,
        &common::repo_root().join("tests/tests/fixtures/enum_context"),
        false,
    )
}

// ------------------------------------------------------------------ 1. implicit enumerations

/// implicit.st: `main.phase : (OFF, SLOW, FAST, DONE)` steps OFF -> SLOW (scan 1) -> FAST (scan 4)
/// -> DONE (scan 7) in a CASE on it. Two FB_Pump instances (whose `request : (OFF, SLOW, FAST)`
/// and `mode : (OFF, STARTING, RUNNING, STOPPING)` share `OFF` with the other enumerations): p1
/// gets the phase as its request, p2 always FAST. Each pump steps OFF -> STARTING -> RUNNING while
/// requested, then STOPPING -> OFF (an ELSIF with `STOPPING = mode`, the value on the left); its
/// method `Level` maps the request to its own `step : (OFF, LOW, HIGH)` (a method's implicit
/// enumeration) and returns 0, 1, 2. `direct` adds the function results for SLOW (formal input)
/// and FAST (non-formal): 10 + 100.
#[test]
fn implicit_enumeration_values_are_typed_by_their_context() {
    let (trace, _) = run_traced(
        &fixture("implicit.st"),
        10,
        "main.phase,main.p1.mode,main.p2.mode,main.r1,main.r2,main.c1,main.c2,main.direct",
    );
    let col = |n: &str| column(&trace, n);
    assert_eq!(
        col("main.phase"),
        [0.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 3.0, 3.0, 3.0],
        "{trace}"
    );
    assert_eq!(
        col("main.p1.mode"),
        [0.0, 1.0, 2.0, 2.0, 2.0, 2.0, 2.0, 3.0, 0.0, 0.0]
    );
    assert_eq!(col("main.p2.mode")[1..], [2.0; 9]);
    assert_eq!(
        col("main.r1"),
        [0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0]
    );
    assert_eq!(col("main.r2")[1..], [1.0; 9]);
    assert_eq!(
        col("main.c1"),
        [0.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 0.0, 0.0, 0.0]
    );
    assert_eq!(col("main.c2"), [2.0; 10]);
    assert_eq!(col("main.direct"), [110.0; 10]);
}

/// benhar-dev/tc3-object-simple-packml (MIT, unmodified; README.md): T_Station's
/// `StationState : (UNINITIALISED, ..., IDLE, ..., COMPLETE, ...)` and the derived
/// T_LidApplyStation's `processState : (IDLE, ..., COMPLETE)` share value names. The station
/// initialises (1) and idles (2); `MAIN.start` at scan 3 starts it (3), it executes (4): the
/// derived block's Execute extends the cylinder (output TRUE), waits 2 s on its TON, retracts it,
/// completes (5, 6), resets (9) and idles again (2). Before: 54 E1001.
#[test]
fn the_packml_station_runs_its_state_machine() {
    let trace = run_with_stimulus(
        &fixture("packml/MainProject"),
        215,
        "3,MAIN.start,TRUE\n",
        &[
            "MAIN.LidApplyStation.StationState",
            "MAIN.LidApplyStation.processState",
            "MAIN.LidApplicatiorCylinder.output",
        ],
    );
    let station = column(&trace, "MAIN.LidApplyStation.StationState");
    let process = column(&trace, "MAIN.LidApplyStation.processState");
    let output = column(&trace, "MAIN.LidApplicatiorCylinder.output");
    assert_eq!(station[..6], [1.0, 2.0, 2.0, 3.0, 4.0, 4.0], "{trace}");
    assert_eq!(process[4..8], [0.0, 1.0, 2.0, 2.0]);
    assert_eq!(output[..7], [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
    // the 2 s wait (T#2S at 10 ms scans) ends at scan 207: retract, complete, reset, idle
    assert_eq!(process[206..210], [2.0, 3.0, 4.0, 0.0]);
    assert_eq!(output[207..210], [1.0, 0.0, 0.0]);
    assert_eq!(station[208..213], [4.0, 5.0, 6.0, 9.0, 2.0]);
    assert_eq!(station[213..], [2.0, 2.0]);
}

/// implicit_members.st: the method Set's input `m : (OFF, ON, AUTO)`, called through the
/// instance `f.Set(m := AUTO)`, `f.Set(ON)` and `f.Set(m := ON)`, adds 10 + 1 + 1 per scan and
/// sets the block's output `mode : (OFF, ON)`; a structure field `kind : (EMPTY, FULL)` and a
/// global `g : (EMPTY, HALF, FULL)` share EMPTY and FULL; a user type already named
/// `IMPLICIT_ENUM_FB_M_mode` keeps its values (q = Q2). Before: 8 errors.
#[test]
fn method_inputs_fields_and_globals_type_implicit_values() {
    let (trace, _) = run_traced(
        &fixture("implicit_members.st"),
        3,
        "main.f.r,main.s.kind,main.f.mode,main.f.q,g",
    );
    assert_eq!(column(&trace, "main.f.r"), [12.0, 24.0, 36.0], "{trace}");
    assert_eq!(column(&trace, "main.s.kind"), [0.0, 1.0, 1.0]);
    assert_eq!(column(&trace, "main.f.mode"), [1.0; 3]);
    assert_eq!(column(&trace, "main.f.q"), [1.0; 3]);
    assert_eq!(column(&trace, "g"), [1.0, 2.0, 2.0]);
}

/// implicit_scope.il: `ALPHA` is a value of main's and FB_Other's implicit enumerations, and IL's
/// `LD ALPHA` gives no context: each POU's own enumeration is the one (CODESYS: an implicit
/// enumeration is valid in its own POU). main.x gets its ALPHA (1), FB_Other's y its ALPHA (0,
/// from its initial GAMMA). Before: three E1001.
#[test]
fn implicit_enumeration_values_belong_to_their_own_pou() {
    let (trace, _) = run_traced(
        &fixture("implicit_scope.il"),
        2,
        "main.x,main.same,main.o.y",
    );
    assert_eq!(column(&trace, "main.x"), [1.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "main.same"), [1.0, 1.0]);
    assert_eq!(column(&trace, "main.o.y"), [0.0, 0.0]);
}

/// A value that two enumerations declare, one of them implicit, where nothing tells which: one
/// E1051 at the value (no `Type#` can be written for an implicit enumeration).
/// implicit_values.st: `st : (Zero, Alfa := 10, Bravo := 20, Echo) := Echo` starts at 21 (a value
/// without `:=` is the one before plus 1, as CODESYS numbers them), is set to Zero in scan 1 and to
/// Bravo (20) in scan 2, and the CASE on it takes the matching branch; the named `E_Named : (A :=
/// 5, B, C := 1) := B` starts at B = 6. Before: E0011 "unexpected `:=`" at `Alfa :=`.
#[test]
fn implicit_enumerations_take_fixed_values() {
    let (trace, _) = run_traced(
        &fixture("implicit_values.st"),
        4,
        "Main.st,Main.hit,Main.nm",
    );
    let col = |n: &str| column(&trace, n);
    assert_eq!(col("Main.st"), [21.0, 0.0, 20.0, 20.0], "{trace}");
    assert_eq!(col("Main.hit"), [41.0, 0.0, 20.0, 20.0], "{trace}");
    assert_eq!(col("Main.nm"), [6.0; 4], "{trace}");
}

/// implicit_xml.xml: a PLCopen XML program whose interface declares `mode` as `<enum>` of Idle,
/// Run (`value="10"`), Fault and `light` as `<enum>` of Off, Run. Its ST body writes `mode := Run;
/// light := Run;` in scan 1 and `mode := Fault` in scan 2, and a CASE on `mode` has a `Run:` label:
/// each `Run` is typed by its context, as in an ST file. Before: three E1051 ("a value of several
/// enumerations").
#[test]
fn implicit_enumerations_of_an_xml_interface_are_typed_by_context() {
    let (trace, _) = run_traced(&fixture("implicit_xml.xml"), 4, "i0.mode,i0.light,i0.hit");
    let col = |n: &str| column(&trace, n);
    assert_eq!(col("i0.mode"), [0.0, 10.0, 11.0, 11.0], "{trace}");
    assert_eq!(col("i0.light"), [0.0, 1.0, 1.0, 1.0], "{trace}");
    assert_eq!(col("i0.hit"), [1.0, 2.0, 3.0, 3.0], "{trace}");
}

#[test]
fn an_implicit_enumeration_value_without_context_is_e1051() {
    assert_eq!(
        rejected("implicit_ambiguous.st"),
        ["implicit_ambiguous.st:9:13: error[E1051]: `IDLE` is a value of several enumerations, and nothing here tells which"]
    );
}

// ------------------------------------------------------------------ 2. ExST assignments in conditions

/// exst_conditions.st. FB_Seq's ELSIF `(evals := evals + 1) > 0 AND start > 10` runs only when
/// `start > 100` is FALSE (s2, start 200, never counts), its next ELSIF `(x := start * 2) >= 10`
/// only when that one is FALSE too (x stays 16 in scan 3). Its method Walk runs a REPEAT whose
/// `UNTIL (c := c + 1) >= 2` makes two passes, each a WHILE `(w := w - 1) > 0` counting n - 1:
/// 2 (n - 1) steps. The program's REPEAT with a CONTINUE in its second pass still runs three
/// passes (the UNTIL assignment runs after the CONTINUE), `UNTIL done := tests >= cycle` runs
/// `cycle` passes, the WHILE counts 4 and 3 (w ends at 2), the IF `(m := cycle * 3) > 5` counts
/// from scan 2.
#[test]
fn assignments_in_elsif_until_and_while_conditions_run_once_per_test() {
    let (trace, _) = run_traced(
        &fixture("exst_conditions.st"),
        3,
        "main.s1.evals,main.s1.picked,main.s1.x,main.s1.steps,main.s2.evals,main.s2.picked,\
         main.s2.steps,main.k,main.loops,main.tests,main.done,main.w,main.cnt,main.m,main.big",
    );
    let col = |n: &str| column(&trace, n);
    assert_eq!(col("main.s1.evals"), [1.0, 2.0, 3.0], "{trace}");
    assert_eq!(col("main.s1.picked"), [4.0, 3.0, 2.0]);
    assert_eq!(col("main.s1.x"), [8.0, 16.0, 16.0]);
    assert_eq!(col("main.s1.steps"), [6.0, 14.0, 22.0]);
    assert_eq!(col("main.s2.evals"), [0.0; 3]);
    assert_eq!(col("main.s2.picked"), [1.0; 3]);
    assert_eq!(col("main.s2.steps"), [398.0; 3]);
    assert_eq!(col("main.k"), [3.0; 3]);
    assert_eq!(col("main.loops"), [3.0; 3]);
    assert_eq!(col("main.tests"), [1.0, 2.0, 3.0]);
    assert_eq!(col("main.done"), [1.0; 3]);
    assert_eq!(col("main.w"), [2.0; 3]);
    assert_eq!(col("main.cnt"), [2.0; 3]);
    assert_eq!(col("main.m"), [3.0, 6.0, 9.0]);
    assert_eq!(col("main.big"), [0.0, 1.0, 2.0]);
}

/// An assignment in the right operand of AND_THEN (which runs only when `ready` is TRUE): one
/// E1052 at the assignment.
#[test]
fn an_assignment_after_and_then_is_e1052() {
    assert_eq!(
        rejected("exst_short_circuit.st"),
        ["exst_short_circuit.st:8:20: error[E1052]: an assignment in the right operand of AND_THEN or OR_ELSE is not supported"]
    );
}

// ------------------------------------------------------------------ 3. FOR over an element or member

/// for_element.st. FB_Grid's method Fill counts in `Offset[1]` and `Offset[2]` (nested, as TcUnit
/// does) over a `size` x `size` grid: g3 fills 9 cells (corner grid[2, 1] = 21), g2 4 (grid[1, 0]
/// = 10); the elements end at `size`. `FOR slots[k] := 10 TO 14 BY 2` counts in slots[1] although
/// the body sets k to 3 (the element is chosen when the loop starts): 3 passes, slots[1] ends at
/// 16, slots[3] untouched. `FOR cur.i := 5 TO 1 BY -1` with a CONTINUE at 3 adds 5 + 4 + 2 + 1.
#[test]
fn for_counts_in_an_array_element_or_a_structure_member() {
    let (trace, _) = run_traced(
        &fixture("for_element.st"),
        2,
        "main.g3.cells,main.g3.corner,main.g2.cells,main.g2.corner,main.g3.Offset[1],\
         main.g3.Offset[2],main.g2.Offset[1],main.slots[1],main.slots[3],main.k,main.passes,\
         main.cur.i,main.cur.total,main.skipped",
    );
    let col = |n: &str| column(&trace, n);
    assert_eq!(col("main.g3.cells"), [9.0; 2], "{trace}");
    assert_eq!(col("main.g3.corner"), [21.0; 2]);
    assert_eq!(col("main.g2.cells"), [4.0; 2]);
    assert_eq!(col("main.g2.corner"), [10.0; 2]);
    assert_eq!(col("main.g3.Offset[1]"), [3.0; 2]);
    assert_eq!(col("main.g3.Offset[2]"), [3.0; 2]);
    assert_eq!(col("main.g2.Offset[1]"), [2.0; 2]);
    assert_eq!(col("main.slots[1]"), [16.0; 2]);
    assert_eq!(col("main.slots[3]"), [0.0; 2]);
    assert_eq!(col("main.k"), [3.0; 2]);
    assert_eq!(col("main.passes"), [3.0; 2]);
    assert_eq!(col("main.cur.i"), [0.0; 2]);
    assert_eq!(col("main.cur.total"), [12.0; 2]);
    assert_eq!(col("main.skipped"), [1.0; 2]);
}

/// A write to the control element inside its loop (`Offset[1] := 5;`, never run here) is one
/// W3141 at the write, as for a control variable; a write to another element is not. The loop
/// runs its 4 passes.
#[test]
fn writing_the_control_element_in_its_loop_is_w3141() {
    let (trace, stderr) = run_traced(&fixture("for_element_write.st"), 1, "main.n,main.Offset[1]");
    assert_eq!(column(&trace, "main.n"), [4.0], "{trace}");
    assert_eq!(column(&trace, "main.Offset[1]"), [4.0]);
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("warning[")).collect();
    assert_eq!(warnings.len(), 1, "{stderr}");
    assert!(
        warnings[0].contains("for_element_write.st:5:21: warning[W3141]: the FOR control variable `Offset[1]` is changed inside its loop"),
        "{stderr}"
    );
}

/// A FOR counting in an element of a REAL array: one E3100 at the element, as for a REAL variable.
#[test]
fn a_for_over_a_real_element_is_e3100() {
    assert_eq!(
        rejected("for_element_real.st"),
        ["for_element_real.st:6:5: error[E3100]: the FOR control variable `fa[1]` must be an integer variable, but it is REAL"]
    );
}
