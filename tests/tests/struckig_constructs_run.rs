//! Issue #13 (helper `struckig`): the constructs of stefanbesler/struckig (TwinCAT 3, ruckig's port
//! to Structured Text; GPLv3, so the fixtures are our own small programs reproducing each
//! construct, none of its code) compile and run:
//! - a METHOD's VAR_IN_OUT (also `VAR_IN_OUT CONSTANT`, which takes a literal), from outside the
//!   block and from its own body;
//! - positional and formal arguments in one call (W1422), a FUNCTION without result type (its
//!   value used: E0354), `FUNCTION INTERNAL Name` (the access specifier is not the name);
//! - method calls in an ELSIF, WHILE or UNTIL condition, after AND_THEN / OR_ELSE, and twice in
//!   one statement: each runs once, where the source evaluates it;
//! - an INTERFACE method with POINTER TO / REFERENCE TO parameters matches its implementation;
//! - a method's VAR initialised by an expression with calls is assigned when the method starts.
//!
//! Before (`ladderc check Struckig.plcproj`): 248 errors (E1011 x100, E0303 x33, E0108 x32, E3106
//! x19, E0018, E0335 ...); after: 58, all VAR_INST blocks read as IL (helper `oop2`'s part) but
//! two E3100 (a BYTE FOR variable: CODESYS arithmetic on bit strings, not compiled yet).

mod common;
use common::{check_text, run_traced};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    common::repo_root()
        .join("tests/tests/fixtures/struckig_constructs")
        .join(name)
}

/// `Bump(k; VAR_IN_OUT n, arr)` adds k to the caller's n and the new n to its arr[1]: from the
/// block's body on its own variables (own, ownarr), from outside formally (x, buf) and
/// positionally (vals[i], buf). `Note` takes a literal through a VAR_IN_OUT CONSTANT; `Shift`
/// writes the element its call named although it moves the index (`slots[idx]`, then idx + 1).
/// Before: E0303 at each VAR_IN_OUT block and E1011 at each call.
#[test]
fn a_method_reads_and_writes_its_callers_variables_through_var_in_out() {
    let (trace, _) = run_traced(
        &fixture("method_in_out.st"),
        2,
        "Main.x,Main.buf[1],Main.res,Main.vals[2],Main.a.own,Main.a.ownarr[1],Main.a.r,\
         Main.a.calls,Main.a.lastNote,Main.a.slots[2],Main.a.slots[3],Main.a.idx",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.x,Main.buf[1],Main.res,Main.vals[2],Main.a.own,Main.a.ownarr[1],\
         Main.a.r,Main.a.calls,Main.a.lastNote,Main.a.slots[2],Main.a.slots[3],Main.a.idx\n\
         0,0,4,8,40,4,2,2,20,3,\"body\",100,0,3\n\
         1,10,7,23,70,8,4,6,40,6,\"body\",100,100,4\n"
    );
}

/// A method's in-out given an expression is one located error.
#[test]
fn a_value_for_a_methods_var_in_out_is_one_located_error() {
    let src = "FUNCTION_BLOCK Fb\nVAR n : INT; END_VAR\n\
               METHOD Bump\nVAR_IN_OUT k : INT; END_VAR\nk := k + 1;\nEND_METHOD\n\
               Bump(n + 1);\nEND_FUNCTION_BLOCK\n\
               PROGRAM Main\nVAR f : Fb; END_VAR\nf();\nEND_PROGRAM\n";
    let (code, lines) = check_text("m.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "m.st:7:6: error[E0353]: VAR_IN_OUT `k` of method `Bump` needs a variable"
        ),
        "{lines:?}"
    );
}

/// `Scale(4, offset := 1, factor := 3)` is 4 * 3 + 1, `Scale(x := 2, 5, offset := 7)` binds 5 to
/// the second parameter (2 * 5 + 7); `Integ(2, 5, p := pos, v := vel)` (a FUNCTION without result
/// type) adds 5 * 2 to pos each scan and sets vel to 7; `bx.Add(1, 2, scale := 10)` adds 30 each
/// scan. One W1422 for the POU. Before: E3106 at each call, E0018 at `FUNCTION Integ`.
#[test]
fn positional_then_formal_arguments_bind_by_position_and_name() {
    let (trace, stderr) = run_traced(
        &fixture("mixed_args.st"),
        2,
        "Main.r,Main.r2,Main.q,Main.pos,Main.vel,Main.bx.sum",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.r,Main.r2,Main.q,Main.pos,Main.vel,Main.bx.sum\n\
         0,0,13,17,30,10,7,30\n\
         1,10,13,17,60,20,7,60\n"
    );
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("W1422")).collect();
    assert_eq!(warnings.len(), 1, "{stderr}");
    assert!(
        warnings[0].contains("mixed_args.st:45:16: warning[W1422]"),
        "{stderr}"
    );
}

/// A positional argument after a named one for the same parameter stays E3106; the value of a
/// FUNCTION without result type is E0354.
#[test]
fn mixed_arguments_that_cannot_bind_and_a_used_void_result_are_located_errors() {
    let src = "FUNCTION Two : INT\nVAR_INPUT a, b : INT; END_VAR\nTwo := a + b;\nEND_FUNCTION\n\
               FUNCTION Nothing\nVAR_INPUT a : INT; END_VAR\nVAR_IN_OUT r : INT; END_VAR\nr := a;\nEND_FUNCTION\n\
               PROGRAM Main\nVAR x, y : INT; END_VAR\n\
               x := Two(a := 1, 2, 3);\ny := Nothing(1, r := x) + 1;\nEND_PROGRAM\n";
    let (code, lines) = check_text("m.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let heads: Vec<&str> = lines
        .iter()
        .filter(|l| l.contains("error["))
        .map(|l| l.split_once(" (hint").map_or(l.as_str(), |(h, _)| h))
        .collect();
    assert_eq!(
        heads,
        vec![
            "m.st:12:18: error[E3106]: formal and non-formal arguments are mixed in one call",
            "m.st:13:6: error[E0354]: function `Nothing` returns no value",
        ],
        "{lines:?}"
    );
}

/// `FUNCTION INTERNAL Half : INT` (TwinCAT's access specifier) is the function `Half`, with one
/// W0304. Before: a function named INTERNAL (E0018), its body read as IL.
#[test]
fn an_access_specifier_on_a_function_is_not_its_name() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("f.st");
    std::fs::write(
        &f,
        "FUNCTION INTERNAL Half : INT\nVAR_INPUT x : INT; END_VAR\n\
         Half := x / 2; // the access specifier changes nothing here\nEND_FUNCTION\n\
         PROGRAM Main\nVAR y : INT; END_VAR\ny := Half(10) + 1;\nEND_PROGRAM\n",
    )
    .unwrap();
    let (trace, stderr) = run_traced(&f, 1, "Main.y");
    assert_eq!(trace, "cycle,time_ms,Main.y\n0,0,6\n");
    assert!(
        stderr.contains("f.st:1:10: warning[W0304]: `FUNCTION INTERNAL` of `Half`"),
        "{stderr}"
    );
}

/// Each method call runs once, where the source evaluates it (the digits in `order` record the
/// calls in their order): `Bump(1) + Bump(2) * 10` gives 1 + 3 * 10; `a AND_THEN Small()` calls
/// Small, `a OR_ELSE Small()` does not; the nested `NOT a OR_ELSE (Bump(1) > 0 AND_THEN Small())`
/// calls both; the first ELSIF's `Bump(3)` runs, the second's does not; `WHILE Small() AND ...`
/// tests before each of the 3 passes and once more; `UNTIL Bump(0) < 15` after each of the 3
/// passes of its REPEAT. From outside: `c.Next(2) * 100 + c.Next(3)` is 205, `x < 0 AND_THEN
/// c.Check(..)` never checks, the ELSIF and WHILE conditions call `c.Next` and `c.Check` once per
/// test. Before: E0108 at each of these calls.
#[test]
fn method_calls_in_late_conditions_and_after_short_circuits_run_once_in_order() {
    let (trace, _) = run_traced(
        &fixture("method_flow.st"),
        2,
        "Main.run.r1,Main.run.b1,Main.run.b2,Main.run.b3,Main.run.r2,Main.run.loops,\
         Main.run.r3,Main.run.order,Main.run.smalls,Main.x,Main.ok,Main.ok2,Main.y,Main.i,\
         Main.c.order,Main.c.checks,Main.c.n",
    );
    let lines: Vec<&str> = trace.lines().collect();
    assert_eq!(
        lines[..2],
        [
            "cycle,time_ms,Main.run.r1,Main.run.b1,Main.run.b2,Main.run.b3,Main.run.r2,\
             Main.run.loops,Main.run.r3,Main.run.order,Main.run.smalls,Main.x,Main.ok,Main.ok2,\
             Main.y,Main.i,Main.c.order,Main.c.checks,Main.c.n",
            "0,0,31,1,1,1,2,3,13,1213000,6,205,1,0,2,4,2311111,6,10",
        ],
        "{trace}"
    );
}

/// An INTERFACE method taking POINTER TO and REFERENCE TO parameters, implemented with the same
/// ones: the block runs, writing through the pointers (0.5 * 2 * 3^2 = 9, 2 * 3 = 6). Before:
/// E0335, the interface's parameters read as LREAL.
#[test]
fn interface_methods_with_pointer_and_reference_parameters_match_their_implementation() {
    let (trace, _) = run_traced(&fixture("interface_pointers.st"), 1, "Main.p,Main.v");
    assert_eq!(trace, "cycle,time_ms,Main.p,Main.v\n0,0,9,6\n");
}

/// A method's VAR initialised by `SIZEOF(Pair) * SINT_TO_UDINT(count)` is assigned when the method
/// starts, from that call's input: Reserve(3) gives 12 bytes (result 24), Reserve(1) 4 (result 8);
/// `total` adds 16 per scan. Before: E0011 at the `(` of the declaration.
#[test]
fn a_method_variable_initialised_by_an_expression_is_set_at_each_call() {
    let (trace, _) = run_traced(
        &fixture("method_inits.st"),
        2,
        "Main.r,Main.r2,Main.p.total",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.r,Main.r2,Main.p.total\n0,0,24,8,16\n1,10,24,8,32\n"
    );
}

/// Through an interface variable: `i.Next(1) + i.Next(2) * 10` is 1 + 3 * 10, the ELSIF's
/// `i.Next(3)` reaches 6, the WHILE tests `i.Next(1)` before each of its 5 passes and once more
/// (n ends at 12). Before: E0108 at each of these calls.
#[test]
fn interface_method_calls_in_late_conditions_run_once_in_order() {
    let (trace, _) = run_traced(
        &fixture("interface_method_flow.st"),
        1,
        "Main.x,Main.y,Main.z,Main.c.n",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.x,Main.y,Main.z,Main.c.n\n0,0,31,2,5,12\n"
    );
}

/// `A(VAR_IN_OUT x)` adds 1 and passes x on to `B(VAR_IN_OUT y)`, which doubles it: from the
/// block's body on `own` (0 -> 2 -> 6) and from outside on `v` (3 -> 8 -> 18).
#[test]
fn a_method_passes_its_in_out_on_to_another_method() {
    let (trace, _) = run_traced(&fixture("nested_in_out.st"), 2, "Main.v,Main.f.own");
    assert_eq!(
        trace,
        "cycle,time_ms,Main.v,Main.f.own\n0,0,8,2\n1,10,18,6\n"
    );
}

/// `r REF= data[k]` in a method with its own `k`: the method's variables are renamed inside the
/// reference too (data[1] + data[2] + data[3] = 9). Before: E1001 "undeclared name `k`".
#[test]
fn a_reference_assigned_in_a_method_reads_the_methods_own_index() {
    let (trace, _) = run_traced(&fixture("method_ref_assign.st"), 1, "Main.s");
    assert_eq!(trace, "cycle,time_ms,Main.s\n0,0,9\n");
}

/// A method's REFERENCE TO input refers to the variable passed: `f.Twice(q := b)` and
/// `f.Twice(c)` double b and c, the body's `Twice(q := own)` and `Twice(own)` quadruple `own`
/// per scan. Before: E1012 from outside ("REF_TO INT, not INT"); inside, the value was written
/// through the reference the input held (none at the first call).
#[test]
fn a_methods_reference_input_refers_to_the_variable_passed() {
    let (trace, _) = run_traced(
        &fixture("method_reference_input.st"),
        2,
        "Main.a,Main.b,Main.c,Main.f.own",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.a,Main.b,Main.c,Main.f.own\n0,0,6,14,2,40\n1,10,7,28,4,160\n"
    );
}
