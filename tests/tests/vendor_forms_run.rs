//! Issue #13: forms CODESYS and TwinCAT projects write that ladderc refused, found by the TwinCAT sweep
//! of Session 34 (77 `.plcproj` of 20 public repositories):
//! - the counters of CODESYS's Standard and TwinCAT's Tc2_Standard library name IEC's R and LD
//!   `RESET` and `LOAD` (`CTU(CU, RESET, PV)`, `CTD(CD, LOAD, PV)`, `CTUD(CU, CD, RESET, LOAD, PV)`;
//!   CODESYS online help "CTU", Beckhoff Infosys "Tc2_Standard: CTU"): in ST calls, as members
//!   (`ctu.RESET := x`) and as pins of LD/FBD boxes (Keiji01's LabsTreino TwinCAT LD). Was E1011
//!   (ST) and E3018 (XML). In these `.st` and plain PLCopen XML files the counters keep IEC's INT
//!   `PV`/`CV`; in TwinCAT objects and CODESYS files they are the vendors' WORD counters (round 29,
//!   `tc_forms_r29_run.rs`);
//! - a number times a duration, `PT := 2 * tCycletime` (MatheusNespolo's FlashGen tutorial): IEC
//!   61131-3 defines MUL_TIME as TIME * ANY_NUM; CODESYS and TwinCAT also take the number first.
//!   With both sides plain operands (no call, so no order of side effects to keep) it is read as the
//!   duration times the number. Was E1004 "MUL is not defined for TIME";
//! - an ARRAY OF an interface started with instances, `LampCtrl : ARRAY[0..1] OF I_LampCtrl :=
//!   [fbLamp1, fbLamp2];` (MatheusNespolo's LightControl tutorial). Was E0336;
//! - TwinCAT's `{flow}`/`{noflow}`, `{analysis ...}` and an empty `{}` pragma are notes (were W0300);
//! - the string functions with the vendors' input names (`LEFT(STR := s, SIZE := n)`; was E1011).

mod common;
use common::{column, run_stimulated, run_traced};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    common::repo_root()
        .join("tests/tests/fixtures/vendor_forms")
        .join(name)
}

/// counters.st: `pulse` toggles every scan, so each counter sees a rising edge in scans 0, 2, 4 ...
/// `clear` (RESET) is TRUE in scan 6 only, `preset` (LOAD) in scan 8 only.
#[test]
fn counters_take_the_vendor_names_reset_and_load() {
    let (trace, _) = run_stimulated(
        &fixture("counters.st"),
        12,
        "6,Main.clear,TRUE\n7,Main.clear,FALSE\n8,Main.preset,TRUE\n9,Main.preset,FALSE\n",
        "Main.up.CV,Main.upDone,Main.down.CV,Main.both.CV,Main.member.CV,Main.resetSeen",
    );
    // up: 1 1 2 2 3 3, RESET in 6 -> 0, then counts again from scan 8
    assert_eq!(
        column(&trace, "Main.up.CV"),
        [1., 1., 2., 2., 3., 3., 0., 0., 1., 1., 2., 2.]
    );
    // Q := CV >= PV (3)
    assert_eq!(
        column(&trace, "Main.upDone"),
        [0., 0., 0., 0., 1., 1., 0., 0., 0., 0., 0., 0.]
    );
    // down counts below zero (IEC: down to INT's minimum) until LOAD puts PV (5) back in scan 8
    assert_eq!(
        column(&trace, "Main.down.CV"),
        [-1., -1., -2., -2., -3., -3., -4., -4., 5., 5., 4., 4.]
    );
    // updown: RESET in 6 -> 0; LOAD in 8 -> PV (4), counting up again in 10
    assert_eq!(
        column(&trace, "Main.both.CV"),
        [1., 1., 2., 2., 3., 3., 0., 0., 4., 4., 5., 5.]
    );
    // `member.RESET := clear` before the call resets it in scan 6; reading it back gives the input
    assert_eq!(
        column(&trace, "Main.member.CV"),
        [1., 1., 2., 2., 3., 3., 0., 0., 1., 1., 2., 2.]
    );
    assert_eq!(
        column(&trace, "Main.resetSeen"),
        [0., 0., 0., 0., 0., 0., 1., 0., 0., 0., 0., 0.]
    );
}

/// The same in FBD (a CODESYS-style box whose pin is `RESET`): counts 1, 2 (Q at PV 2), reset in
/// scan 4, counts again in scan 5.
#[test]
fn an_fbd_counter_box_takes_the_reset_pin() {
    let (trace, _) = run_stimulated(
        &fixture("fbd_counter_reset.xml"),
        7,
        "0,main.PULSE,TRUE\n1,main.PULSE,FALSE\n2,main.PULSE,TRUE\n3,main.PULSE,FALSE\n\
         4,main.CLEAR,TRUE\n5,main.CLEAR,FALSE\n5,main.PULSE,TRUE\n",
        "main.COUNT,main.DONE",
    );
    assert_eq!(column(&trace, "main.COUNT"), [1., 1., 2., 2., 0., 1., 1.]);
    assert_eq!(column(&trace, "main.DONE"), [0., 0., 1., 1., 0., 0., 0.]);
}

/// A name that is no counter input stays E1011, with the IEC names in the hint; `RESET` on a block
/// without an R input (TON) is no alias.
#[test]
fn other_names_stay_unknown_parameters() {
    let (code, lines) = common::check_text(
        "bad.st",
        "PROGRAM Main\nVAR c : CTU; t : TON; END_VAR\nc(CU := TRUE, CLEAR := TRUE);\nt(IN := TRUE, RESET := TRUE);\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines[0].starts_with("bad.st:3:15: error[E1011]: CTU has no parameter `CLEAR`"),
        "{lines:?}"
    );
    assert!(
        lines[1].starts_with("bad.st:4:15: error[E1011]: TON has no parameter `RESET`"),
        "{lines:?}"
    );
    assert_eq!(lines.len(), 2, "{lines:?}");
}

/// time_times_number.st: tCycle = 150 ms, k = 3, r = 0.5; `T#1S + 4 * tCycle * 2` = 2200 ms; the
/// TON behind `PT := 2 * tCycle` (300 ms) gives Q every 31st scan of 10 ms.
#[test]
fn a_number_times_a_duration_is_the_duration_times_the_number() {
    let (trace, _) = run_traced(
        &fixture("time_times_number.st"),
        32,
        "Main.doubled,Main.tripled,Main.halved,Main.sum,Main.blink.Q",
    );
    let first = trace.lines().nth(1).unwrap();
    assert_eq!(first, "0,0,T#300ms,T#450ms,T#75ms,T#2200ms,0");
    let q = column(&trace, "Main.blink.Q");
    assert_eq!(q.iter().filter(|v| **v == 1.0).count(), 1, "{trace}");
    assert_eq!(q[30], 1.0, "{trace}");
}

/// interface_array.st: `lamps : ARRAY[1..4] OF I_Lamp := [dim, sw, 0]`: element 1 calls the
/// dimmer's Level (40), element 2 the switch's (100), element 3 is unassigned (`<> 0` FALSE).
#[test]
fn an_array_of_an_interface_starts_with_its_instances() {
    let (trace, _) = run_traced(
        &fixture("interface_array.st"),
        2,
        "Main.levels[1],Main.levels[2],Main.third",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.levels[1],Main.levels[2],Main.third\n0,0,40,100,0\n1,10,40,100,0\n"
    );
}

/// More elements than the array holds, or an element that is not an instance: one E0336.
#[test]
fn an_interface_array_initialiser_that_does_not_fit_is_e0336() {
    let src = "INTERFACE I_A\nMETHOD M : INT\nEND_METHOD\nEND_INTERFACE\n\
               FUNCTION_BLOCK FB_A IMPLEMENTS I_A\nMETHOD M : INT\nM := 1;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\
               PROGRAM Main\nVAR a : FB_A; b : FB_A; c : FB_A;\n\
               two : ARRAY[0..1] OF I_A := [a, b, c];\n\
               odd : ARRAY[0..1] OF I_A := [a, 5];\nEND_VAR\nEND_PROGRAM\n";
    let (code, lines) = common::check_text("fit.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let e0336: Vec<_> = lines
        .iter()
        .filter(|l| l.contains("error[E0336]"))
        .collect();
    assert_eq!(e0336.len(), 2, "{lines:?}");
    assert!(
        e0336[0].starts_with("fit.st:12:1: error[E0336]: `two`"),
        "{lines:?}"
    );
    assert!(
        e0336[1].starts_with("fit.st:13:1: error[E0336]: `odd`"),
        "{lines:?}"
    );
}

/// array_bounds.st: `LOWER_BOUND`/`UPPER_BOUND` (IEC 61131-3 edition 3, also CODESYS and TwinCAT;
/// TcUnit's assertions write them) of a two-dimensional array, an element of an array of arrays, a
/// structure field, and as the bounds of a FOR loop (3 + 4 + 5 + 6 + 7 = 25). Before: E1019
/// "unknown function".
#[test]
fn lower_and_upper_bound_of_declared_arrays() {
    let (trace, _) = run_traced(
        &fixture("array_bounds.st"),
        1,
        "Main.lo,Main.hi,Main.lo2,Main.hi2,Main.inner,Main.field,Main.sum",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.lo,Main.hi,Main.lo2,Main.hi2,Main.inner,Main.field,Main.sum\n\
         0,0,3,7,0,1,12,-2,25\n"
    );
}

/// A dimension the array does not have, one that is not a literal, a value that is not an array:
/// one E1070 each.
#[test]
fn a_bound_of_no_array_or_dimension_is_e1070() {
    let heads = common::rejected_heads(
        "bounds.st",
        "PROGRAM Main\nVAR a : ARRAY[3..7, 0..1] OF INT; k : INT := 1; n : DINT; x : INT; END_VAR\n\
         n := UPPER_BOUND(a, 3);\nn := LOWER_BOUND(a, k);\nn := LOWER_BOUND(x, 1);\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        [
            "bounds.st:3:6: error[E1070]: `UPPER_BOUND`: the dimension must be an integer literal from 1 to 2",
            "bounds.st:4:6: error[E1070]: `LOWER_BOUND`: the dimension must be an integer literal from 1 to 2",
            "bounds.st:5:6: error[E1070]: `LOWER_BOUND` takes a declared array and the number of one of its dimensions",
        ]
    );
}

/// flow_pragmas.st: TwinCAT's `{flow}` / `{noflow}` (flow control of online monitoring), `{analysis
/// -33}` and an empty `{}` hold no code: each is a W0301 note (was W0300 "holds code that does not
/// run", 20 times in Keiji01's HTTPS_Request and 12 in Struckig), and the code between them runs.
#[test]
fn flow_control_and_empty_pragmas_are_notes() {
    let (trace, stderr) = run_stimulated(&fixture("flow_pragmas.st"), 4, "", "Main.n,Main.big");
    assert_eq!(column(&trace, "Main.n"), [1., 2., 3., 4.]);
    assert_eq!(column(&trace, "Main.big"), [0., 0., 1., 1.]);
    assert!(!stderr.contains("W0300"), "{stderr}");
    for p in ["{flow}", "{noflow}", "{analysis -33}", "{}"] {
        assert!(
            stderr.contains(&format!("note[W0301]: pragma `{p}` is informational")),
            "{p}: {stderr}"
        );
    }
}

/// string_names.st: the string functions called with CODESYS's / TwinCAT's input names (`LEFT(STR,
/// SIZE)`, `FIND(STR1, STR2)`, `MID(STR, LEN, POS)`, ... CODESYS online help "String functions",
/// Beckhoff Infosys "Tc2_Standard"), each the same input as IEC 61131-3's `IN`/`IN1`/`IN2`/`L`/`P`
/// (was E1011 "LEFT has no parameter `STR`" in Keiji01's IPC diagnostics). The values are IEC's.
#[test]
fn string_functions_take_the_vendor_input_names() {
    let (trace, stderr) = run_stimulated(
        &fixture("string_names.st"),
        1,
        "",
        "Main.sLeft,Main.nAt,Main.sRight,Main.sMid,Main.sCat,Main.sIns,Main.sDel,Main.sRep,Main.nLen",
    );
    assert_eq!(
        trace.lines().nth(1),
        Some(r#"0,0,"CPU ",6,"2]","slot","CPU !","ABC","CPUt 2]","CPU [bay 2]",12"#),
        "{stderr}"
    );
}
