//! Initial values that call a function (CODESYS, TwinCAT; issue #13): Struckig's `RandomTest`
//! declares `_position_random_3 : UDINT := MIN(250000, _number_trajectories / 25);`, which was
//! E0011 ("unexpected literal"); one naming a variable declared before it, E0022. A FUNCTION_BLOCK's or PROGRAM's VAR, VAR_INPUT, VAR_OUTPUT (and
//! VAR_TEMP) declared so is assigned in declaration order when each instance is initialised,
//! before its FB_init, as CODESYS initialises declarations, and, for an instance that
//! initialisation does not reach, when it first runs; a FUNCTION's VAR at each call. `ADR(x)`
//! initial values stay the declaration's (the C starts the pointer with the address).

mod common;
use common::{column, rejected_heads, run_traced};

use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/run_time_inits")
        .join(name)
}

/// `b := MIN(250000, n / 25)` of `n = 262144` is 10485, which FB_init already sees (`seen`);
/// the body adds 1 to `b` each scan, and the initial value is not computed again.
#[test]
fn a_blocks_computed_initial_values_come_before_fb_init() {
    let (trace, stderr) = run_traced(
        &fixture("block.st"),
        2,
        "main.f.out,main.f.r,main.f.viaP,main.f.seen",
    );
    assert_eq!(column(&trace, "main.f.seen"), [10485.0, 10485.0]);
    assert_eq!(column(&trace, "main.f.out"), [20970.0, 20971.0]);
    assert_eq!(column(&trace, "main.f.r"), [4.0, 4.0]);
    // the ADR initial value stays the declaration's
    assert_eq!(column(&trace, "main.f.viaP"), [262144.0, 262144.0]);
    // W1433 once per POU, at the first (`b`; `c` is not reported)
    assert_eq!(stderr.matches("warning[W1433]").count(), 1, "{stderr}");
    assert!(
        stderr.contains(
            "block.st:5:13: warning[W1433]: the initial value of `b` is computed at run time"
        ),
        "{stderr}"
    );
}

/// The program reads `f.b` (`MAX(3, 7, 5)`) before `f` first runs: 7; `k := MIN(b, 4)` comes
/// after `b` in declaration order.
#[test]
fn an_output_is_initialised_before_the_first_scan() {
    let (trace, _) = run_traced(&fixture("before_first_run.st"), 2, "main.before,main.f.b");
    assert_eq!(column(&trace, "main.before"), [7.0, 11.0]);
    assert_eq!(column(&trace, "main.f.b"), [11.0, 15.0]);
}

/// A FUNCTION's `t : INT := ABS(-10)` starts at 10 at each call; the program's `n := MAX(2, 5)`
/// once.
#[test]
fn a_functions_computed_initial_value_is_assigned_at_each_call() {
    let (trace, _) = run_traced(&fixture("function.st"), 2, "main.n,main.r1,main.r2");
    assert_eq!(column(&trace, "main.r1"), [11.0, 11.0]);
    assert_eq!(column(&trace, "main.r2"), [15.0, 16.0]);
    assert_eq!(column(&trace, "main.n"), [6.0, 7.0]);
}

/// A FUNCTION's input and a constant initialised by a standard function of constants
/// (`ABS(-3)`) take its value, computed while the declarations are read (issue #13's twentieth
/// round; before: E0011, a call was no constant expression); a call of a user function there stays
/// an error (E0022: not computed while declarations are read).
#[test]
fn a_functions_input_and_a_constant_take_a_standard_function_of_constants() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("f.st");
    std::fs::write(
        &f,
        "FUNCTION F : INT\nVAR_INPUT\n  a : INT := ABS(-3);\nEND_VAR\nF := a * 10;\nEND_FUNCTION\n\
         PROGRAM main\nVAR CONSTANT\n  c : INT := ABS(-4);\nEND_VAR\nVAR\n  r : INT;\n  s : INT;\nEND_VAR\n\
         r := F(a := c);\ns := F();\nEND_PROGRAM\n",
    )
    .unwrap();
    let (trace, _) = run_traced(&f, 1, "main.r,main.s");
    assert_eq!(column(&trace, "main.r"), [40.0]);
    assert_eq!(column(&trace, "main.s"), [30.0]);
    let heads = rejected_heads(
        "g.st",
        "FUNCTION G : INT\nVAR_INPUT x : INT; END_VAR\nG := x;\nEND_FUNCTION\n\
         PROGRAM main\nVAR CONSTANT\n  c : INT := G(3);\nEND_VAR\nVAR\n  r : INT;\nEND_VAR\n\
         r := c;\nEND_PROGRAM\n",
    );
    assert_eq!(heads.len(), 1, "{heads:?}");
    assert!(heads[0].starts_with("g.st:7:14: error[E0022]"), "{heads:?}");
}

/// `a : UDINT := n / 25;` names a variable declared before it (was E0022 "not a constant"); the
/// block's body is empty (read as ST for its initial values): both are 10485 before the first scan.
#[test]
fn an_initial_value_naming_a_variable_in_a_block_with_an_empty_body() {
    let (trace, _) = run_traced(&fixture("empty_body.st"), 1, "main.f.a,main.f.b");
    assert_eq!(column(&trace, "main.f.a"), [10485.0]);
    assert_eq!(column(&trace, "main.f.b"), [10485.0]);
}

/// A derived block's instance gets its base's computed initial value (`k := MAX(1, 4)`) before its
/// own, which reads it (`j := MIN(k, 9) + 1`). Before this was tested, the derived instance's `k`
/// stayed 0 and `j` was 1: the base's assignments were not inherited.
#[test]
fn a_derived_block_computes_its_bases_initial_values_first() {
    let (trace, _) = run_traced(&fixture("inherited.st"), 1, "main.b.k,main.d.k,main.d.j");
    assert_eq!(trace.lines().nth(1), Some("0,0,4,4,5"), "{trace}");
}

/// `p : POINTER TO UDINT := ADR(n)` stays the declaration's (the C starts the pointer with the
/// address: `other`, which runs first, reads 5 through it); `m := n + SIZEOF(n)` is computed.
#[test]
fn an_address_initial_value_stays_the_declarations() {
    let (trace, _) = run_traced(&fixture("program_pointer.st"), 1, "o.seen,i.s,i.m");
    assert_eq!(trace.lines().nth(1), Some("0,0,5,4,9"), "{trace}");
}

/// An interface variable started with an instance (`iDrive : I_Drive := fbNc;`, MatheusNespolo's
/// AbstractDrive tutorial) keeps the interface's own initial value (no W1433): a variable alone
/// given to a variable of a user type is no computed value.
#[test]
fn an_interface_started_with_an_instance_is_no_computed_value() {
    let (code, lines) = common::check_text(
        "itf.st",
        "INTERFACE I_Drive\nMETHOD Speed : INT\nEND_METHOD\nEND_INTERFACE\n\
         FUNCTION_BLOCK FB_Nc IMPLEMENTS I_Drive\nMETHOD Speed : INT\nSpeed := 3;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\
         PROGRAM main\nVAR\n  fbNc : FB_Nc;\n  iDrive : I_Drive := fbNc;\n  n : INT := MAX(1, 2);\nEND_VAR\n\
         n := iDrive.Speed();\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(0), "{lines:?}");
    // only `n` is reported
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("itf.st:14:11: warning[W1433]: the initial value of `n`"),
        "{lines:?}"
    );
}
