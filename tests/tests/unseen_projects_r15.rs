//! PLCopen XML projects and IL programs of the fifteenth acceptance run of issue #13 (2026-12-04,
//! branch `round15`).
//!
//! **The round.** Units no earlier round had tried, run as a new user would (`ladderc run FILE
//! --cycles N --stimulus S --watch ...`, or `check`), values checked against the logic:
//! - PLCopen XML (`tc6_0201`, OpenPLC Editor / Beremiz): Salnet86/OpenPlc_Lezioni `Led_ST` (ST),
//!   `ST/SR_TIMER1_ST` (ST, TON + SR), `contatore` and `contatore_up` (LD, CTU with an edge-marked CU,
//!   the second resetting itself from Q), `FDB_CONTA` (FBD, the same), `FDB_SR` (FBD, SR),
//!   `FlipFlopSR` (LD, two SR with variables named S1 and RESET), `cancello` (LD, a gate: %MX memory
//!   bits, set/reset coils, two TONs), `Tele` (LD, a reversing starter), `Tapparella` (LD, a roller
//!   shutter), `FDB_TEMP_SR` (a project without POUs: checks, runs nothing);
//!   codermery/OpenPLC-with-julide `gate` (LD as the OpenPLC Editor v4 writes it); matiec's own
//!   `tests/SFC_TEST.xml` (tc6 v1, SFC with simultaneous and selection branches, P and N actions);
//!   elian15122000/TINF19C-PLCOpen-Editor's test project `plc_valid.xml` (FBD, a variable named
//!   `Input/OutputVariable`: rejected, located).
//! - IL, after vendor manuals and IL teaching pages (reproduced, no licence to copy): CODESYS's help
//!   "Programming in IL" (ADD network, CTU call), KVPAC's Beremiz manual (`LD A / ANDN B / ST C`),
//!   Panasonic FPWIN Pro's CALC/CALCN pages, Fuji Electric's SPF manual (a label on a line of its
//!   own), plc3000.com's "Instructions in IL" (parenthesised operators), the CR-group table of John
//!   and Tiegelkamp's IEC 61131-3 book (ST and JMPC leave the CR unchanged), and the instruction set
//!   of "IEC61131-3 Instruction List Language Processor for FPGAs" (RETC/RETCN, CALC/CALCN): seven
//!   programs in `tests/fixtures/matiec_diff/r15_*.il`, compared cycle by cycle with matiec there,
//!   and two more here that matiec refuses.
//!
//! | | units | run and behave | rejected, naming what is missing | ladderc gap |
//! |---|---|---|---|---|
//! | before | 21 (14 PLCopen XML, 7 IL) | 20 | 1: a name that is no identifier | 1: a double coil in one network went unreported |
//! | after | 21 | 20 | 1 (the error now names the bad name, at it) | 0 (W1423 below) |
//!
//! matiec side by side (`scripts/matiec-diff.sh`, iec2c 6bb2c33): of the seven IL programs five
//! agree in every value; two differ only in counter CV past PV, the documented counter-limit row
//! (IEC 61131-3: CTU counts while CV < PVmax). matiec refuses two IL forms the standard allows,
//! tested here against values computed from the logic: `R := x` in a call's parameter list (it
//! reads R as the IL operator) and a parenthesised list nested in another whose inner list goes past
//! its operand ("Data type mismatch"). iec2c also crashed (SIGSEGV) on the first version of
//! `r15_plc3000_parens`, which declared nine BOOLs in two declarations (`I0, I1, I2, I3, I4 : BOOL;`),
//! as round 13 saw with three TONs; the corpus file declares one name a declaration. matiec's
//! `SFC_TEST.xml` chart, written as textual SFC, agrees with matiec in every value (live only: GPL);
//! a chart of our own with the same constructs (`r15_sfc_branches`) does too, and
//! `r15_sfc_final_scan` documents the two SFC rows where ladderc follows the standard's action
//! control and matiec does not (an N action's final scan, the initial step's P action in scan 0).
//!
//! The gap, fixed here: Salnet86's `Tapparella` writes `LAMPADA1` from two coils of one network (the
//! down rung's lamp names the up lamp; `LAMPADA2` is declared and never written). The coil written
//! last wins every scan and the other never shows; W3400 only compared networks, so nothing was said.
//! W1423 now reports it (the second writer located, the first labelled). Closed in Session 33 (lead):
//! ladderc joined every rung hanging on the body's one left rail into one network, evaluated before
//! any coil was written, so `Tapparella`'s interlocked contactors both switched on in the first scan
//! and then blinked together, where Beremiz's generator (coil after coil) lets the up contactor win;
//! a rail now joins no rungs (`tests/tests/ladder_rungs_run.rs`), the two lamp coils are in two
//! networks (W3400, W1423 stays for one rung), and the chart
//! of `Tele` (interlock contacts not negated) never starts either contactor, in both.
//!
//! No project carries a licence: the constructs are reproduced in files of our own
//! (`tests/fixtures/unseen/r15/`).

mod common;
use common::{column, ladderc, run_stimulated, run_traced};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/unseen/r15")
        .join(name)
}

/// The stimulus rows `cycle,instance0.VAR,value` of `(cycle, VAR, value)` triples.
fn stimulus(rows: &[(u32, &str, u8)]) -> String {
    rows.iter()
        .map(|(c, v, x)| format!("{c},instance0.{v},{x}\n"))
        .collect()
}

/// A watch list `instance0.A,instance0.B,...`.
fn watch(vars: &[&str]) -> String {
    vars.iter()
        .map(|v| format!("instance0.{v}"))
        .collect::<Vec<_>>()
        .join(",")
}

/// plc3000's parenthesised IL operators, nested two deep with more than an operand inside: every
/// one of the 32 input combinations gives the value of the Boolean expression written in the
/// comment, computed here from the traced inputs.
#[test]
fn il_parentheses_nested_two_deep_evaluate_the_inner_list_first() {
    let (trace, _) = run_traced(
        &fixture("nested_parens.il"),
        32,
        "p.I0,p.I1,p.I2,p.I3,p.I4,p.Q1,p.Q2",
    );
    let col = |n: &str| column(&trace, &format!("p.{n}"));
    let bits: Vec<Vec<bool>> = ["I0", "I1", "I2", "I3", "I4"]
        .iter()
        .map(|n| col(n).iter().map(|&v| v != 0.0).collect())
        .collect();
    let (q1, q2) = (col("Q1"), col("Q2"));
    let mut seen = std::collections::BTreeSet::new();
    for k in 0..32 {
        let [i0, i1, i2, i3, i4] = [0, 1, 2, 3, 4].map(|b| bits[b][k]);
        seen.insert((i0, i1, i2, i3, i4));
        let want1 = (!i0 || (i1 && !i2)) ^ (i3 || (i4 && i0));
        let want2 = i0 && (i1 || (i2 && (i3 || !i4)));
        assert_eq!(q1[k] != 0.0, want1, "Q1 in cycle {k}");
        assert_eq!(q2[k] != 0.0, want2, "Q2 in cycle {k}");
    }
    assert_eq!(seen.len(), 32, "every combination of the five inputs");
}

/// CODESYS's IL call of a counter with its reset given by name in the call (`R := xReset`): the
/// counter counts a rising edge every 4 scans, Q at PV 5, and the reset in scan 29 clears CV.
#[test]
fn il_call_gives_a_counters_reset_by_name() {
    let (trace, _) = run_traced(&fixture("reset_in_call.il"), 40, "p.n,p.iCount,p.xDone");
    let cv = column(&trace, "p.iCount");
    let done = column(&trace, "p.xDone");
    // n is 1 in scan 0; xPulse = n MOD 4 < 2 rises when n is 4, 8, ... (scans 3, 7, ...), and in scan 0
    assert_eq!(cv[0], 1.0);
    assert_eq!(cv[2], 1.0);
    assert_eq!(cv[3], 2.0);
    assert_eq!(cv[15], 5.0);
    assert_eq!(done[14], 0.0);
    assert_eq!(done[15], 1.0);
    assert_eq!(cv[28], 8.0);
    // n = 30 in scan 29: R clears CV and Q in that scan; counting starts again at the next edge
    assert_eq!(cv[29], 0.0);
    assert_eq!(done[29], 0.0);
    assert_eq!(cv[31], 1.0);
    assert_eq!(cv[35], 2.0);
}

/// Tapparella's slip: LAMP_UP written by the up rung and again by the down rung, two rungs on one
/// left rail. Since Session 33 each rung is a network of its own (a rail joins none), so this is
/// W3400 (two networks), at the second coil (line 75); the lamp follows the down rung, the rung
/// run last; SEEN_UP, two coils in series on one power flow, is not reported. The same slip inside
/// one rung (the second lamp coil on the up rung's first contact) is W1423, naming both localIds.
#[test]
fn two_coils_of_one_variable_in_one_network_are_reported() {
    let p = fixture("shutter_double_coil.xml");
    let rows = [(2, "UP", 1), (4, "UP", 0), (6, "DOWN", 1), (8, "DOWN", 0)];
    let (trace, stderr) = run_stimulated(
        &p,
        10,
        &stimulus(&rows),
        &watch(&["K_UP", "K_DOWN", "LAMP_UP", "LAMP_DOWN", "SEEN_UP"]),
    );
    let warnings: Vec<&str> = stderr
        .lines()
        .filter(|l| l.contains("W1423") || l.contains("W3400"))
        .collect();
    assert_eq!(warnings.len(), 1, "{stderr}");
    assert!(
        warnings[0].contains("shutter_double_coil.xml:75:19: warning[W3400]: `LAMP_UP` is written by network 1 (localId 5) and again by network 2"),
        "{stderr}"
    );
    assert!(warnings[0].contains("localId 9"), "{stderr}");
    let at = |n: &str| column(&trace, &format!("instance0.{n}"));
    // up pressed: the up contactor runs, but its lamp stays dark (the down rung's coil wins)
    assert_eq!(at("K_UP")[2], 1.0);
    assert_eq!(at("LAMP_UP")[2], 0.0);
    assert_eq!(at("SEEN_UP")[2], 1.0);
    // down pressed: the "up" lamp lights
    assert_eq!(at("K_DOWN")[6], 1.0);
    assert_eq!(at("K_UP")[6], 0.0);
    assert_eq!(at("LAMP_UP")[6], 1.0);
    assert!(at("LAMP_DOWN").iter().all(|&v| v == 0.0));

    // `ladderc check` of the fixture with `from` replaced by `to` (once): exit code and stderr
    let variant = |name: &str, from: &str, to: &str| {
        let text = std::fs::read_to_string(&p).unwrap();
        let changed = text.replacen(from, to, 1);
        assert_ne!(changed, text);
        let dir = tempfile::tempdir().unwrap();
        let f = dir.path().join(name);
        std::fs::write(&f, changed).unwrap();
        let out = ladderc()
            .args(["--message-format", "short", "check"])
            .arg(&f)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr).into_owned();
        (out.status.code(), err)
    };

    // the slip inside one rung: the second lamp coil hangs on the up rung's UP contact (localId 2),
    // a different power flow than the first lamp coil's (after NOT K_DOWN): W1423
    let (code, err) = variant(
        "shutter_one_rung.xml",
        "<position x=\"430\" y=\"240\"/>\n        <connectionPointIn><relPosition x=\"0\" y=\"10\"/><connection refLocalId=\"7\"/>",
        "<position x=\"430\" y=\"240\"/>\n        <connectionPointIn><relPosition x=\"0\" y=\"10\"/><connection refLocalId=\"2\"/>",
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("warning[W1423]: `LAMP_UP` is written twice in network 1 (localId 5 and 9)"),
        "{err}"
    );

    // without the slip (the second lamp coil names LAMP_DOWN) nothing is reported
    let (code, err) = variant(
        "shutter_fixed.xml",
        "<variable>LAMP_UP</variable>\n      </coil>\n      <contact localId=\"10\"",
        "<variable>LAMP_DOWN</variable>\n      </coil>\n      <contact localId=\"10\"",
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("W1423") && !err.contains("W3400"), "{err}");
}

/// The OpenPLC Editor v4 way of writing LD (codermery's gate): a rail pair per rung, connections
/// naming `left-rail`/`output`, initial values `False`/`True`. The handshake latches through its
/// states: ready, request (ASK), pass allowed (ALLOW, barrier open), ready again (PASSED);
/// the emergency stop drops every state and lights the alarm, RESET brings back ready.
#[test]
fn openplc_v4_rungs_latch_a_gate_handshake() {
    let rows = [
        (10, "ASK", 1),
        (12, "ASK", 0),
        (20, "ALLOW", 1),
        (22, "ALLOW", 0),
        (30, "PASSED", 1),
        (32, "PASSED", 0),
        (40, "ESTOP_CMD", 1),
        (42, "ESTOP_CMD", 0),
        (50, "RESET", 1),
        (52, "RESET", 0),
    ];
    let (trace, stderr) = run_stimulated(
        &fixture("rung_rails_handshake.xml"),
        56,
        &stimulus(&rows),
        &watch(&[
            "READY",
            "REQUEST",
            "PASS",
            "ESTOP",
            "BARRIER_OPEN",
            "ALARM_LAMP",
        ]),
    );
    assert!(!stderr.contains("warning["), "{stderr}");
    let row = |c: usize| -> Vec<f64> {
        [
            "READY",
            "REQUEST",
            "PASS",
            "ESTOP",
            "BARRIER_OPEN",
            "ALARM_LAMP",
        ]
        .iter()
        .map(|n| column(&trace, &format!("instance0.{n}"))[c])
        .collect()
    };
    // the task runs every 20 ms: on even scans
    assert_eq!(row(0), [1.0, 0.0, 0.0, 0.0, 0.0, 0.0], "READY starts True");
    assert_eq!(row(10), [0.0, 1.0, 0.0, 0.0, 0.0, 0.0]);
    assert_eq!(row(20), [0.0, 0.0, 1.0, 0.0, 1.0, 0.0]);
    assert_eq!(row(30), [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    assert_eq!(row(40), [0.0, 0.0, 0.0, 1.0, 0.0, 1.0]);
    assert_eq!(row(48), [0.0, 0.0, 0.0, 1.0, 0.0, 1.0]);
    assert_eq!(row(50), [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
}

/// A counter input marked `edge="rising"` (Salnet86's `FDB_CONTA` and `contatore`) counts once per
/// press, as CU alone does; one marked `edge="falling"` counts on the releases, and once in the first
/// scan: the edge detector is IEC 61131-3's F_TRIG, whose memory starts FALSE (`Q := NOT CLK AND NOT
/// M`; matiec's lib/edge_detection.txt is the same). Q at PV 3; R clears both.
#[test]
fn edge_marks_on_counter_inputs_count_presses_and_releases() {
    let mut rows = Vec::new();
    for k in 0..4 {
        rows.push((1 + 4 * k, "pulse", 1));
        rows.push((3 + 4 * k, "pulse", 0));
    }
    rows.push((17, "reset", 1));
    rows.push((18, "reset", 0));
    let (trace, _) = run_stimulated(
        &fixture("counter_edge_inputs.xml"),
        20,
        &stimulus(&rows),
        &watch(&["rising_cv", "rising_q", "falling_cv", "falling_q"]),
    );
    let at = |n: &str| column(&trace, &format!("instance0.{n}"));
    let (rise, fall) = (at("rising_cv"), at("falling_cv"));
    assert_eq!(rise[0], 0.0);
    assert_eq!(fall[0], 1.0, "F_TRIG's first scan with CLK FALSE");
    // presses at 1, 5, 9, 13; releases at 3, 7, 11, 15
    assert_eq!([rise[1], rise[5], rise[9], rise[13]], [1.0, 2.0, 3.0, 4.0]);
    assert_eq!([rise[2], rise[4]], [1.0, 1.0]);
    assert_eq!(
        [fall[2], fall[3], fall[7], fall[11], fall[15]],
        [1.0, 2.0, 3.0, 4.0, 5.0]
    );
    assert_eq!(at("rising_q")[8], 0.0);
    assert_eq!(at("rising_q")[9], 1.0);
    assert_eq!(at("falling_q")[7], 1.0);
    assert_eq!([rise[17], fall[17], at("rising_q")[17]], [0.0, 0.0, 0.0]);
}

/// elian15122000/TINF19C-PLCOpen-Editor's test project `plc_valid.xml` (an FBD program written by
/// Beremiz's editor) names a variable `Input/OutputVariable`, which no IEC 61131-3 compiler takes:
/// rejected, exit 1, each error located at the name, the declaration's saying which name is wrong
/// (before: "variable without a valid `name`" at the element).
#[test]
fn a_variable_name_that_is_not_an_identifier_is_named_where_it_is_declared() {
    let src = r#"<?xml version='1.0' encoding='utf-8'?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="Unknown" productName="Unnamed" productVersion="1" creationDateTime="2021-04-23T13:43:33"/>
  <contentHeader name="Unnamed"><coordinateInfo><fbd><scaling x="10" y="10"/></fbd><ld><scaling x="10" y="10"/></ld><sfc><scaling x="10" y="10"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Connections" pouType="program">
      <interface><localVars>
        <variable name="InputVariable"><type><DINT/></type></variable>
        <variable name="Input/OutputVariable"><type><DINT/></type></variable>
        <variable name="OutputVariable"><type><DINT/></type></variable>
      </localVars></interface>
      <body><FBD>
        <inVariable localId="1" height="30" width="90"><position x="170" y="70"/><connectionPointOut><relPosition x="90" y="20"/></connectionPointOut><expression>InputVariable</expression></inVariable>
        <inOutVariable localId="2" height="30" width="90"><position x="350" y="130"/><connectionPointIn><relPosition x="0" y="20"/><connection refLocalId="1"/></connectionPointIn><connectionPointOut><relPosition x="90" y="20"/></connectionPointOut><expression>Input/OutputVariable</expression></inOutVariable>
        <outVariable localId="3" height="30" width="90"><position x="550" y="70"/><connectionPointIn><relPosition x="0" y="20"/><connection refLocalId="2"/></connectionPointIn><expression>OutputVariable</expression></outVariable>
      </FBD></body>
    </pou></pous></types>
  <instances><configurations><configuration name="Config0"><resource name="Res0">
    <task name="task0" priority="0" interval="T#20ms"><pouInstance name="instance0" typeName="Connections"/></task>
  </resource></configuration></configurations></instances>
</project>
"#;
    let heads = common::rejected_heads("plc_valid.xml", src);
    assert_eq!(
        heads,
        [
            "plc_valid.xml:9:25: error[E3013]: variable name `Input/OutputVariable` is not an IEC 61131-3 identifier (letters, digits and `_`, not starting with a digit) [POU `Connections`]",
            "plc_valid.xml:14:261: error[E3011]: `Input/OutputVariable` is not a variable, direct address or literal [POU `Connections`, network 1, localId 2]",
        ]
    );
}
