//! Object-oriented constructs of CODESYS and TwinCAT left over from the first rounds (issue #13),
//! run end to end through `ladderc run` on files written for these tests
//! (`fixtures/oop_substitution/`): a method's VAR_INST (kept in the instance between calls), a
//! derived instance passed where its base is expected (VAR_IN_OUT, `REFERENCE TO`, `POINTER TO`,
//! `REF=`; IEC 61131-3 ed. 3, 6.6.5 substitutability) with the methods called through the base view
//! dispatched to the derived block's overrides; methods and properties returning an interface,
//! methods returning a `POINTER TO`, property accessors with their own access modifier, and
//! structures that EXTEND others.
//!
//! Record of public projects (this round): the 42 `.plcproj` of 30 mirrored TwinCAT repositories
//! (TcUnit, TwinCat-Dynamic-Collections, struckig, tc3-object-simple-packml, ...), `ladderc check`
//! before and after: compiled 14 -> 14, errors 2305 -> 2145 (TcDynCollections 215 -> 141: E0342
//! 13 -> 0, E0335 9 -> 0, E1011 30 -> 0, E0011 32 -> 2; TcUnit 222 -> 206; Struckig 353 -> 293).
//! None newly compiles: what stops them is formal outputs after positional inputs (E3106),
//! Beckhoff libraries (E1032), calls on a method's result (`a.Get(p).Pop()`), enumeration values
//! of several types (tc3-object-simple-packml), pointer initial values of method variables.
//! (mtagg/OrbPlantUmlGen holds no PLC source.)

mod common;
use common::{column, rejected_heads, run_traced};

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

/// One `FB_Meter`, called four times a cycle, gets a plain `FB_Shape`, an `FB_Circle`, an
/// `FB_Square` and an `FB_BigSquare` (which EXTENDS `FB_Square`) in its `VAR_IN_OUT shape :
/// FB_Shape`: `shape.Area()` runs each block's own override (0, 3 r², s², s² + 1000 through
/// `SUPER^.Area()`), `shape.calls` is the base part of each instance, and `shape(...)` runs each
/// instance's own body (`bodies` +1, +10, +100; `FB_BigSquare` has no body of its own, so none).
#[test]
fn a_derived_instance_in_a_base_in_out_runs_its_own_methods_and_body() {
    let (trace, stderr) = run_traced(
        &fixture("shapes.st"),
        2,
        "Main.viaPlain,Main.viaCircle,Main.viaSquare,Main.viaBig,Main.meter.total,\
         Main.plain.calls,Main.circle.calls,Main.square.calls,Main.big.calls,\
         Main.plain.bodies,Main.circle.bodies,Main.square.bodies,Main.big.bodies",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.viaPlain"), [0.0, 0.0]);
    assert_eq!(column(&trace, "Main.viaCircle"), [12.0, 12.0]);
    assert_eq!(column(&trace, "Main.viaSquare"), [9.0, 9.0]);
    // big.size is 4, then 5 (written through a REFERENCE TO FB_Shape below)
    assert_eq!(column(&trace, "Main.viaBig"), [1016.0, 1025.0]);
    assert_eq!(column(&trace, "Main.meter.total"), [1037.0, 2083.0]);
    for shape in ["plain", "circle", "square", "big"] {
        assert_eq!(column(&trace, &format!("Main.{shape}.calls")), [1.0, 2.0]);
    }
    assert_eq!(column(&trace, "Main.plain.bodies"), [1.0, 2.0]);
    assert_eq!(column(&trace, "Main.circle.bodies"), [10.0, 20.0]);
    assert_eq!(column(&trace, "Main.square.bodies"), [100.0, 200.0]);
    assert_eq!(column(&trace, "Main.big.bodies"), [0.0, 0.0]);
}

/// `pShape : POINTER TO FB_Shape := ADR(circle)`: `pShape^.Area()` is the circle's (12, and its
/// own counter `own` counts this call and the meter's); `rShape : REFERENCE TO FB_Shape`,
/// `rShape REF= big`: `rShape.Area()` is the big square's, and `rShape.size := rShape.size + 1.0`
/// changes `big.size`; a FUNCTION's `REFERENCE TO FB_Shape` input given the square calls its
/// `Area` (9 + 0.5).
#[test]
fn pointers_and_references_to_a_base_reach_the_derived_instance() {
    let (trace, stderr) = run_traced(
        &fixture("shapes.st"),
        2,
        "Main.viaPointer,Main.circle.own,Main.viaReference,Main.bigSize,Main.viaFunction",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.viaPointer"), [12.0, 12.0]);
    assert_eq!(column(&trace, "Main.circle.own"), [2.0, 4.0]);
    assert_eq!(column(&trace, "Main.viaReference"), [1016.0, 1025.0]);
    assert_eq!(column(&trace, "Main.bigSize"), [5.0, 6.0]);
    assert_eq!(column(&trace, "Main.viaFunction"), [9.5, 9.5]);
}

/// `itf := itf.Next()` walks the list n1 (1) -> n2 (20) -> n3 (300) through the interface until
/// the unassigned end (`itf <> 0`): 321; `n1.Next()` on the instance is n2 (20); a FUNCTION
/// returning `I_Node` gives n3 (300); `list.First` (a block's PROPERTY of type `I_Node`, set to
/// n2) and `itf.Following` (an interface's PROPERTY of type `I_Node`, through the interface)
/// give n2 (20) and n3 (300).
#[test]
fn methods_and_properties_returning_an_interface_are_called_through_an_interface() {
    let (trace, stderr) = run_traced(
        &fixture("interface_results.st"),
        2,
        "Main.sum,Main.direct,Main.viaFunction,Main.viaProperty,Main.viaItfProperty",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.sum"), [321.0, 321.0]);
    assert_eq!(column(&trace, "Main.direct"), [20.0, 20.0]);
    assert_eq!(column(&trace, "Main.viaFunction"), [300.0, 300.0]);
    assert_eq!(column(&trace, "Main.viaProperty"), [20.0, 20.0]);
    assert_eq!(column(&trace, "Main.viaItfProperty"), [300.0, 300.0]);
}

/// Inside a METHOD of a derived block, `other.Get()` through its `VAR_IN_OUT other : FB_Base`:
/// given the base instance, the base's `Get` (n + 1); given another `FB_D`, its override
/// (n + 100); plus the method's input 1000.
#[test]
fn a_base_view_in_a_method_of_a_derived_block_dispatches() {
    let (trace, stderr) = run_traced(&fixture("in_method.st"), 1, "Main.x,Main.y");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), [1001.0]);
    assert_eq!(column(&trace, "Main.y"), [1100.0]);
}

/// An IL body's `CAL u(io := d)` passes a derived instance to an ST block's VAR_IN_OUT of the base
/// (which ladderc passes by reference): `io.Get()` runs `FB_D`'s override (100).
#[test]
fn an_il_body_passes_a_derived_instance_to_a_base_in_out() {
    let (trace, stderr) = run_traced(&fixture("il_caller.st"), 1, "Main.x");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), [100.0]);
}

/// A TON in a method's VAR_INST keeps its elapsed time from call to call (one call per cycle of
/// 10 ms): with `PT := T#20MS` it elapses in cycle 2; `IN := NOT t.Q` resets it in cycle 3 and
/// starts it again in cycle 4, so it elapses again in cycle 6; `n` counts the elapses (so `q`,
/// `n > 1`, from cycle 6).
#[test]
fn a_timer_in_var_inst_keeps_running_between_calls() {
    let (trace, stderr) = run_traced(&fixture("var_inst_timer.st"), 9, "Main.r,Main.b.q");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(
        column(&trace, "Main.r"),
        [0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]
    );
    assert_eq!(
        column(&trace, "Main.b.q"),
        [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0]
    );
}

/// VAR_INST outside a method (a FUNCTION, a PROGRAM): one E0348 at each keyword, the rest of the
/// file still checked (the block read as VAR).
#[test]
fn var_inst_outside_a_method_is_one_located_error() {
    let src = "FUNCTION F : INT\nVAR_INST k : INT; END_VAR\nk := k + 1;\nF := k;\nEND_FUNCTION\n\
PROGRAM Main\nVAR_INST n : INT; END_VAR\nn := F();\nEND_PROGRAM\n";
    assert_eq!(
        rejected_heads("v.st", src),
        [
            "v.st:2:1: error[E0348]: VAR_INST in a FUNCTION: only a METHOD declares VAR_INST",
            "v.st:7:1: error[E0348]: VAR_INST in a PROGRAM: only a METHOD declares VAR_INST",
        ]
    );
}

/// `VAR_INST p : FB_Part;` in a method: `FB_Part`'s FB_init (id := 42) runs before the first
/// cycle, as for the block's own instances.
#[test]
fn fb_init_runs_for_an_instance_in_var_inst() {
    let (trace, stderr) = run_traced(&fixture("var_inst_fb_init.st"), 2, "Main.r");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.r"), [42.0, 42.0]);
}

/// Through `VAR_IN_OUT io : FB_Base`, `io.Level := 5` runs the setter of the instance's block
/// (FB_D: n := 6), `io.Level` its getter (n * 10 = 60) and `io.Both(a := 7, twice => o)` its
/// method with the output (3 * 7); given the base, the base's versions (5, 5, 14).
#[test]
fn properties_and_method_outputs_through_a_base_view_dispatch() {
    let (trace, stderr) = run_traced(
        &fixture("properties.st"),
        1,
        "Main.u1.got,Main.u1.o,Main.u2.got,Main.u2.o,Main.b.n,Main.d.n",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.u1.got"), [5.0]);
    assert_eq!(column(&trace, "Main.u1.o"), [14.0]);
    assert_eq!(column(&trace, "Main.b.n"), [5.0]);
    assert_eq!(column(&trace, "Main.u2.got"), [60.0]);
    assert_eq!(column(&trace, "Main.u2.o"), [21.0]);
    assert_eq!(column(&trace, "Main.d.n"), [6.0]);
}

/// `p^.Get()` with `p : POINTER TO FB_Base` never assigned: nothing crashes, the result reads 0
/// (read through the NULL reference, as any), and the run reports "NULL reference dereferenced
/// (first: p^ in Main ...)", the read of the instance's class.
#[test]
fn a_call_through_a_null_base_pointer_is_reported_not_crashed() {
    let (trace, stderr) = run_traced(&fixture("null_view.st"), 1, "Main.x");
    assert_eq!(column(&trace, "Main.x"), [0.0]);
    assert!(
        stderr.contains("NULL reference dereferenced (first: p^ in Main"),
        "{stderr}"
    );
}

/// `VAR_INST n : INT := 10;` in a PROPERTY's Get accessor (TwinCAT, as `TcDynCollections` writes
/// it): each read adds one to the instance's own `n` (a: two reads a cycle, b: one).
#[test]
fn var_inst_of_a_property_accessor_is_kept_in_each_instance() {
    let (trace, stderr) = run_traced(&fixture("var_inst_property.st"), 2, "Main.x,Main.y");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), [12.0, 14.0]);
    assert_eq!(column(&trace, "Main.y"), [11.0, 12.0]);
}

/// `METHOD Take : POINTER TO ST_Node` returning `ADR(pool[i])` (`i` the method's input): the
/// caller's `q^.v := q^.v + 5` changes `p.pool[2].v` (5, then 10), `q^.v := 7` `p.pool[1].v`.
#[test]
fn a_method_returns_a_pointer_into_its_instance() {
    let (trace, stderr) = run_traced(&fixture("method_pointer.st"), 2, "Main.x,Main.y");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), [5.0, 10.0]);
    assert_eq!(column(&trace, "Main.y"), [7.0, 7.0]);
}

/// An INTERFACE method `Take : POINTER TO ST_Node` and the block's implementation have the same
/// signature (before: the interface's result read without its `POINTER TO`, E0335), and
/// `itf.Take(i := 2)` gives the pointer into the instance (3 added per cycle).
#[test]
fn an_interface_method_returning_a_pointer_is_implemented_and_called() {
    let (trace, stderr) = run_traced(&fixture("interface_pointer.st"), 2, "Main.x");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), [3.0, 6.0]);
}

/// `SET PROTECTED VAR END_VAR ...`: the accessor's own access modifier (TwinCAT) is read past
/// (before: E0106 at it); `Grow` sets `Size := Size + 1` through it (n := 2 (n + 1)): 2, 6, 14.
#[test]
fn an_accessor_with_its_own_access_modifier_runs() {
    let (trace, stderr) = run_traced(&fixture("accessor_modifier.st"), 3, "Main.x");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), [2.0, 6.0, 14.0]);
}

/// `TYPE ST_Point3 EXTENDS ST_Point2 : STRUCT z ... END_STRUCT`: `p3` has `x`, `y` (with their
/// initial values 1, 2) and `z` (3), `x` written (+10 per cycle); `ST_Point4` extends `ST_Point3`
/// and is declared before it: 1 + 2 + 3 + 4.
#[test]
fn a_structure_that_extends_another_has_its_fields() {
    let (trace, stderr) = run_traced(
        &fixture("struct_extends.st"),
        2,
        "Main.sum3,Main.sum4,Main.p4.w,Main.p3.x",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.sum3"), [16.0, 26.0]);
    assert_eq!(column(&trace, "Main.sum4"), [10.0, 10.0]);
    assert_eq!(column(&trace, "Main.p3.x"), [11.0, 21.0]);
}
