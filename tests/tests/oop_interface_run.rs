//! Variables of an interface type and dynamic dispatch (issue #13): `itf : I_Shape;` holds any
//! instance of a block that implements `I_Shape` (directly or through a base it EXTENDS), and
//! `itf.Area()` runs the method of the block the instance really is. Run end to end through
//! `ladderc run` on files written for these tests (`fixtures/oop_interface/`): the classic array of
//! shapes filled with three block types and summed in a FOR loop, interface inputs, VAR_IN_OUT,
//! VAR_GLOBAL, function and method variables, comparisons with 0 and between interfaces, a call
//! through an unassigned interface (result 0, reported at the end of the run), and the located
//! errors (E0336, E0340-E0344).
//!
//! Record of public projects (issue #13's interface round): the 36 `.plcproj` files of 18 TwinCAT
//! repositories' snapshots (TcUnit, struckig, EventLogger, ...), 50 scans, before and after: run
//! 11 -> 11, rejected 25 -> 25; projects with E0336 (interface variables) 3 -> 0 (TcUnit: 5 -> 0,
//! its `itf : I_TestResultLogger := AdsTestResultLogger;` idiom compiled), with E0335 2 -> 0
//! (struckig's `IRandom.TcIO`, whose `METHOD Next : LREAL` declaration ends without a line
//! break). They stay rejected for other causes: FB_init arguments (E0329), Beckhoff libraries
//! (E1032), a FOR whose control variable is an array element (E0100, TcUnit), graphical bodies.

mod common;
use common::{column, rejected_heads, run_traced};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/oop_interface")
        .join(rel)
}

/// `aShapes : ARRAY[1..3] OF I_Shape` holds a circle (3 r²), a rectangle (w h) and a square, whose
/// block EXTENDS the rectangle's and overrides `Area` (w² + 1000): the FOR loop adds 3 + 6 + 1016;
/// in cycle 2 `aShapes[2].Scale(k := 2.0)` doubles the rectangle's sides through the interface, so
/// cycle 3 adds 3 + 24 + 1016. An instance passed to an interface input (`report(shape :=
/// circle)`) is called there.
#[test]
fn an_array_of_an_interface_dispatches_each_call_on_the_instance_it_holds() {
    let (trace, stderr) = run_traced(
        &fixture("shapes.st"),
        3,
        "Main.total,Main.rect.w,Main.rect.h,Main.square.w,Main.reported,Main.report.has",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.total"), [1025.0, 1025.0, 1043.0]);
    assert_eq!(column(&trace, "Main.rect.w"), [2.0, 4.0, 4.0]);
    assert_eq!(column(&trace, "Main.rect.h"), [3.0, 6.0, 6.0]);
    // the square (a FB_Rect by EXTENDS) is not scaled: the call went to the rectangle only
    assert_eq!(column(&trace, "Main.square.w"), [4.0, 4.0, 4.0]);
    assert_eq!(column(&trace, "Main.reported"), [3.0, 3.0, 3.0]);
    assert_eq!(column(&trace, "Main.report.has"), [1.0, 1.0, 1.0]);
}

/// `itf = 0` before the first assignment, `itf <> 0` after; `itf = aShapes[3]` (the same instance)
/// and `itf <> other` (another one) compare the instances held.
#[test]
fn interfaces_compare_with_0_and_with_each_other_by_the_instance_they_hold() {
    let (trace, stderr) = run_traced(
        &fixture("shapes.st"),
        2,
        "Main.empty,Main.assigned,Main.same,Main.differ",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    // `itf` keeps the square from cycle 1 on
    assert_eq!(column(&trace, "Main.empty"), [1.0, 0.0]);
    assert_eq!(column(&trace, "Main.assigned"), [1.0, 1.0]);
    assert_eq!(column(&trace, "Main.same"), [1.0, 1.0]);
    assert_eq!(column(&trace, "Main.differ"), [1.0, 1.0]);
}

/// An `I_Named EXTENDS I_Counter` variable assigned to a VAR_GLOBAL `I_Counter` steps `up` by 100
/// each cycle; `I_Named.Code()` is the extended interface's own method; a FUNCTION's interface
/// input and local (two steps of -1 on `down`), a function block's VAR_IN_OUT (-10) and a method's
/// unassigned local interface (its call reads 0 and is reported once at the end of the run).
#[test]
fn interface_variables_work_in_globals_functions_in_outs_and_methods() {
    let (trace, stderr) = run_traced(
        &fixture("scopes.st"),
        2,
        "Main.viaGlobal,Main.code,Main.viaFunction,Main.viaInOut,Main.probed,Main.up.n,Main.down.n",
    );
    assert_eq!(column(&trace, "Main.viaGlobal"), [100.0, 200.0]);
    assert_eq!(column(&trace, "Main.up.n"), [100.0, 200.0]);
    assert_eq!(column(&trace, "Main.code"), [1.0, 1.0]);
    assert_eq!(column(&trace, "Main.viaFunction"), [-2.0, -14.0]);
    assert_eq!(column(&trace, "Main.viaInOut"), [-12.0, -24.0]);
    assert_eq!(column(&trace, "Main.down.n"), [-12.0, -24.0]);
    assert_eq!(column(&trace, "Main.probed"), [0.0, 0.0]);
    assert!(
        stderr.contains(
            "NULL reference dereferenced (first: a call through the unassigned interface"
        ),
        "{stderr}"
    );
    assert!(stderr.contains("in FB_Driver"), "{stderr}");
}

/// An instance of a block that does not implement the interface, assigned or passed to an input
/// of the interface type: one E0340 at the value each.
#[test]
fn an_instance_that_does_not_implement_the_interface_is_one_located_error() {
    let src = std::fs::read_to_string(fixture("not_implemented.st")).unwrap();
    assert_eq!(
        rejected_heads("bad.st", &src),
        [
            "bad.st:22:8: error[E0340]: function block `FB_Lamp` does not implement interface `I_Shape`",
            "bad.st:23:17: error[E0340]: function block `FB_Lamp` does not implement interface `I_Shape`",
        ]
    );
}

const AXES_WATCH: &str = "speeds[0],speeds[1],positions[0],positions[1],moves";

/// The trace of `properties.st` (program `prog`): `axes[k].Speed := 50` runs the Set accessor of
/// the block each element holds (the rotary one caps it at 30), `axes[k].Speed` its Get, and
/// `axes[k].Moves` (a Get-only property: the rotary one counts in hundreds) after one `Move()`.
fn assert_axes_trace(trace: &str, prog: &str) {
    let col = |v: &str| column(trace, &format!("{prog}.{v}"));
    assert_eq!(col("speeds[0]"), [50.0, 50.0, 50.0]);
    assert_eq!(col("speeds[1]"), [30.0, 30.0, 30.0]);
    assert_eq!(col("positions[0]"), [50.0, 100.0, 150.0]);
    assert_eq!(col("positions[1]"), [30.0, 60.0, 90.0]);
    assert_eq!(col("moves"), [101.0, 202.0, 303.0]);
}

fn watch(prog: &str) -> String {
    AXES_WATCH
        .split(',')
        .map(|v| format!("{prog}.{v}"))
        .collect::<Vec<_>>()
        .join(",")
}

/// Properties declared in an interface (`PROPERTY Speed : INT GET END_GET SET END_SET
/// END_PROPERTY`), written and read through an array of the interface.
#[test]
fn properties_of_an_interface_run_the_accessors_of_the_instance_held() {
    let (trace, stderr) = run_traced(&fixture("properties.st"), 3, &watch("Main"));
    assert!(!stderr.contains("error"), "{stderr}");
    assert_axes_trace(&trace, "Main");
}

/// The same program as TwinCAT 3 object files: the interface's `<Property>` with its `<Get>` and
/// `<Set>` in the `.TcIO`, the blocks' properties and method in `.TcPOU` files. The interface's
/// method declaration ends without a line break (`METHOD Move : INT]]>`, as in struckig's
/// `IRandom.TcIO`): it is still read with its result type (before: E0342 here, E0335 there).
#[test]
fn the_same_interface_as_twincat_files_gives_the_same_trace() {
    let files: Vec<PathBuf> = [
        "I_Axis.TcIO",
        "FB_Linear.TcPOU",
        "FB_Rotary.TcPOU",
        "MAIN.TcPOU",
    ]
    .iter()
    .map(|f| fixture(&format!("twincat/{f}")))
    .collect();
    let refs: Vec<&Path> = files.iter().map(PathBuf::as_path).collect();
    let (trace, stderr) = common::run_traced_files(&refs, 3, &watch("MAIN"));
    assert!(!stderr.contains("error"), "{stderr}");
    assert_axes_trace(&trace, "MAIN");
}

/// `__QUERYINTERFACE(iBase1, iSub1)` succeeds when the instance held (fb1) implements I_Sub1 and
/// clears the destination when it does not (fb2, tested in an IF condition); an FB instance as
/// source; `__QUERYPOINTER(iBase1, p1)` gives a `POINTER TO FB_1` whose method runs on fb1 (its
/// call counter goes on from the interface's call), and fails for a `POINTER TO FB_2`.
#[test]
fn query_interface_and_query_pointer_convert_at_run_time() {
    let (trace, stderr) = run_traced(
        &fixture("query.st"),
        2,
        "Main.ok1,Main.ok2,Main.sub1Set,Main.ok3,Main.sub2Set,Main.ok4,Main.r1,Main.okPtr,Main.viaPointer,Main.okNoPtr",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    for (v, want) in [
        ("ok1", 1.0),
        ("ok2", 0.0),
        ("sub1Set", 0.0),
        ("ok3", 1.0),
        ("sub2Set", 1.0),
        ("ok4", 1.0),
        ("okPtr", 1.0),
        ("okNoPtr", 0.0),
    ] {
        assert_eq!(column(&trace, &format!("Main.{v}")), [want, want], "{v}");
    }
    assert_eq!(column(&trace, "Main.r1"), [11.0, 13.0]);
    assert_eq!(column(&trace, "Main.viaPointer"), [12.0, 14.0]);
}

/// A query in a WHILE condition (evaluated again each time round) is one E0341.
#[test]
fn a_query_in_a_while_condition_is_one_located_error() {
    let src = std::fs::read_to_string(fixture("query.st"))
        .unwrap()
        .replace(
            "END_PROGRAM",
            "WHILE __QUERYINTERFACE(iBase1, iSub1) DO\n    r1 := 0;\nEND_WHILE;\nEND_PROGRAM",
        );
    let heads = rejected_heads("q.st", &src);
    assert_eq!(
        heads,
        ["q.st:66:7: error[E0341]: `__QUERYINTERFACE` in an ELSIF, WHILE or UNTIL condition is not supported"]
    );
}

/// `logger : I_Logger := sum;` (the vendors' and TcUnit's way): the program's interface holds its
/// FB_Sum from the first cycle (10 a cycle); FB_Runner's is already assigned when its method
/// `Report` runs before its body does (100, then the body's 1); `spare : I_Logger := 0` stays
/// unassigned.
#[test]
fn interface_variables_start_with_their_initial_instance() {
    let (trace, stderr) = run_traced(
        &fixture("initial.st"),
        3,
        "Main.viaProgram,Main.viaMethod,Main.viaBody,Main.runner.empty,Main.runner.sum.total",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert!(!stderr.contains("NULL"), "{stderr}");
    assert_eq!(column(&trace, "Main.viaProgram"), [10.0, 20.0, 30.0]);
    assert_eq!(column(&trace, "Main.viaMethod"), [100.0, 201.0, 302.0]);
    assert_eq!(column(&trace, "Main.viaBody"), [101.0, 202.0, 303.0]);
    assert_eq!(
        column(&trace, "Main.runner.sum.total"),
        [101.0, 202.0, 303.0]
    );
    assert_eq!(column(&trace, "Main.runner.empty"), [1.0, 1.0, 1.0]);
}

/// A call through an interface of a method it does not declare: one E0342 at the method's name,
/// no error more for the result read (a method returning an interface is called since issue #13's
/// substitution round: `oop_substitution_run.rs`).
#[test]
fn a_call_through_an_interface_that_cannot_be_compiled_is_one_located_error() {
    let src = "INTERFACE I_Node\nMETHOD Next : I_Node\nEND_METHOD\nMETHOD Val : INT\nEND_METHOD\nEND_INTERFACE\n\
FUNCTION_BLOCK FB_N IMPLEMENTS I_Node\nVAR nxt : I_Node; v : INT; END_VAR\n\
METHOD Next : I_Node\nNext := nxt;\nEND_METHOD\nMETHOD Val : INT\nVal := v;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\
PROGRAM Main\nVAR a : FB_N; i, j : I_Node; x : INT; END_VAR\ni := a;\nx := i.Missing() + 1;\nj := i.Next();\nEND_PROGRAM\n";
    assert_eq!(
        rejected_heads("n.st", src),
        ["n.st:19:8: error[E0342]: interface `I_Node` has no method `Missing`"]
    );
}

/// A structure holding itself by value (here through an array of another structure) has no size:
/// one E0343 at the field closing the cycle, and no crash (before: the C generation recursed
/// without end).
#[test]
fn a_structure_that_contains_itself_is_one_located_error() {
    let src = "TYPE A : STRUCT b : ARRAY[1..2] OF B; END_STRUCT; END_TYPE\n\
TYPE B : STRUCT a : A; r : REF_TO A; END_STRUCT; END_TYPE\n\
PROGRAM Main\nVAR x : A; END_VAR\nEND_PROGRAM\n";
    assert_eq!(
        rejected_heads("s.st", src),
        ["s.st:2:17: error[E0343]: structure `A` contains itself (through field `a`)"]
    );
}

/// Instances handed to a method's input of interface type, positionally (`registry.Add(c, 1)`),
/// by name in another order, and from inside the block (`Add(own, 1)`): the registry keeps them
/// in an array of the interface and its body polls them all (7 + the ramp's 1, 2, 3 + 1000). The
/// third call (weight 0) is refused: its result starts FALSE, not at the previous call's TRUE (a
/// method's result starts at its default each call).
#[test]
fn instances_passed_to_a_methods_interface_input_are_kept_and_called() {
    let (trace, stderr) = run_traced(
        &fixture("registry.st"),
        3,
        "Main.added,Main.registry.sum,Main.registry.count",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.added"), [3.0, 3.0, 3.0]);
    assert_eq!(column(&trace, "Main.registry.count"), [3.0, 3.0, 3.0]);
    assert_eq!(
        column(&trace, "Main.registry.sum"),
        [1008.0, 1009.0, 1010.0]
    );
}

/// FB_Base IMPLEMENTS I_Get and FB_Derived EXTENDS it, overriding `Get` (q + 10, then
/// `SUPER^.Get(k) * 100`): an input and a VAR_IN_OUT of the interface take either instance, and
/// the derived one runs its override (late binding on the instance's real type).
#[test]
fn a_parameter_of_an_interface_takes_a_base_or_a_derived_instance() {
    let (trace, stderr) = run_traced(
        &fixture("base_or_derived.st"),
        2,
        "Main.uBase.x,Main.uBase.y,Main.uDerived.x,Main.uDerived.y,Main.base.q,Main.derived.q",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.uBase.x"), [2.0, 2.0]);
    assert_eq!(column(&trace, "Main.uBase.y"), [3.0, 3.0]);
    assert_eq!(column(&trace, "Main.uDerived.x"), [200.0, 200.0]);
    assert_eq!(column(&trace, "Main.uDerived.y"), [300.0, 300.0]);
    assert_eq!(column(&trace, "Main.base.q"), [2.0, 4.0]);
    assert_eq!(column(&trace, "Main.derived.q"), [22.0, 44.0]);
}

/// A derived instance passed to a VAR_IN_OUT or `REFERENCE TO` of its base block (E0344 before
/// issue #13's substitution round): now compiled, the calls through them run the derived block's
/// `Get` (more in `oop_substitution_run.rs`).
#[test]
fn a_derived_instance_for_a_base_parameter_runs_its_own_method() {
    let src = "FUNCTION_BLOCK FB_Base\nVAR_OUTPUT q : INT; END_VAR\nMETHOD Get : INT\nGet := 1;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\
FUNCTION_BLOCK FB_D EXTENDS FB_Base\nMETHOD Get : INT\nGet := 2;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\
FUNCTION_BLOCK FB_User\nVAR_IN_OUT b : FB_Base; END_VAR\nVAR_INPUT r : REFERENCE TO FB_Base; END_VAR\nVAR_OUTPUT x, y : INT; END_VAR\n\
x := b.Get();\ny := r.Get();\nEND_FUNCTION_BLOCK\n\
PROGRAM Main\nVAR d : FB_D; u : FB_User; END_VAR\nu(b := d, r := d);\nEND_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("d.st");
    std::fs::write(&f, src).unwrap();
    let (trace, stderr) = run_traced(&f, 1, "Main.u.x,Main.u.y");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.u.x"), [2.0]);
    assert_eq!(column(&trace, "Main.u.y"), [2.0]);
}

/// `hub.Reg(THIS^)`: each FB_Node passes itself (the instance running the body) to the hub's
/// interface input once; the hub's body then calls both back (3 + 4).
#[test]
fn a_block_passes_itself_as_this_to_an_interface() {
    let (trace, stderr) = run_traced(&fixture("this_register.st"), 2, "Main.h.sum,Main.h.n");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.h.sum"), [7.0, 7.0]);
    assert_eq!(column(&trace, "Main.h.n"), [2.0, 2.0]);
}

/// `gSlots : ARRAY[1..2] OF ST_Slot` (a VAR_GLOBAL), each slot holding `dev : I_A`: the first
/// slot's interface is assigned and called (5), the second is unassigned (`= 0`), and its call
/// reads 0 and is reported with its path.
#[test]
fn an_interface_in_a_structure_field_is_assigned_called_and_compared() {
    let (trace, stderr) = run_traced(&fixture("struct_fields.st"), 1, "Main.x,Main.y,Main.ok");
    assert_eq!(column(&trace, "Main.x"), [5.0]);
    assert_eq!(column(&trace, "Main.y"), [0.0]);
    assert_eq!(column(&trace, "Main.ok"), [1.0]);
    assert!(
        stderr.contains("a call through the unassigned interface gSlots[2].dev in Main"),
        "{stderr}"
    );
}

/// Instances passed to a FUNCTION's interface input inside an expression (by name, positionally,
/// twice in one statement): each call gets a temporary interface holding its instance
/// (100 x 1.5 + 200 x 0.5; 200 x 0.5).
#[test]
fn instances_passed_to_a_functions_interface_input_are_called_there() {
    let (trace, stderr) = run_traced(&fixture("function_input.st"), 2, "Main.total,Main.single");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.total"), [250.0, 250.0]);
    assert_eq!(column(&trace, "Main.single"), [100.0, 100.0]);
}
