//! Round 33 (PLCopen XML, behaviour checked against an independent model), through `ladderc run`
//! and `ladderc check`:
//! - Separate LD/FBD networks run in the row order of their output elements (coils, output
//!   variables), as Beremiz/OpenPLC Editor write them (`PLCGenerator.py`, `ComputeProgram`: the coils
//!   and output variables sorted by `SortInstances`, one row when less than 10 units apart in y, a
//!   row left to right). Before, a network ran at the place of its top-most element, so a rung with a
//!   branch drawn higher ran before the rung to its left on the same row, one scan late
//!   (ingvago/ESP32-PLC semaforo-v2/v3).
//! - An SFC step that no transition follows (a final step) is the warning W1464 and stays active
//!   once reached (IEC 61131-3 ed. 2 2.6.2-2.6.3 asks for no successor; Beremiz compiles it).
//!   Before, it was the error E3121 (Acabaxi/Simple: 5 errors).

mod common;
use common::{check_text, column, run_text};

/// A PLCopen project of one program `main` with the BOOL variables `vars` (`name` or `name=TRUE`)
/// and the LD body `body`, run by a 10 ms task as `inst`.
fn ld_project(vars: &[&str], body: &str) -> String {
    let decls: String = vars
        .iter()
        .map(|v| match v.split_once('=') {
            Some((n, init)) => format!(
                r#"<variable name="{n}"><type><BOOL/></type><initialValue><simpleValue value="{init}"/></initialValue></variable>"#
            ),
            None => format!(r#"<variable name="{v}"><type><BOOL/></type></variable>"#),
        })
        .collect();
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="main" pouType="program">
      <interface><localVars>{decls}</localVars></interface>
      <body><LD>
<leftPowerRail localId="1"><position x="10" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
{body}<rightPowerRail localId="2"><position x="900" y="0"/></rightPowerRail>
      </LD></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="C"><resource name="R"><task name="T" interval="T#10ms" priority="0"><pouInstance name="inst" typeName="main"/></task></resource></configuration></configurations></instances>
</project>
"#
    )
}

/// A contact on `var` at (`x`, `y`), numbered `id`, fed by the elements `from` (1 is the rail).
fn contact(id: u32, x: i64, y: i64, var: &str, from: &[u32]) -> String {
    let wires: String = from
        .iter()
        .map(|f| format!(r#"<connection refLocalId="{f}"/>"#))
        .collect();
    format!(
        r#"<contact localId="{id}"><position x="{x}" y="{y}"/><connectionPointIn>{wires}</connectionPointIn><connectionPointOut/><variable>{var}</variable></contact>
"#
    )
}

/// A coil on `var` at (`x`, `y`), numbered `id`, fed by the elements `from`.
fn coil(id: u32, x: i64, y: i64, var: &str, from: &[u32]) -> String {
    contact(id, x, y, var, from)
        .replace("<contact ", "<coil ")
        .replace("</contact>", "</coil>")
}

/// Two rungs on one row: `go -> a` on the left, `(a OR spare) -> b` on the right with its `spare`
/// branch drawn 40 units higher. Both coils are on the row y=100, `a`'s to the left, so `a`'s rung
/// runs first and `b` follows `a` in the same scan, as Beremiz writes `a := go; b := a OR spare;`.
/// Before, the right rung ran first (its top-most element is higher) and `b` was one scan late.
#[test]
fn side_by_side_rungs_run_left_to_right_by_their_coils() {
    let body = [
        contact(3, 100, 100, "go", &[1]),
        coil(4, 300, 100, "a", &[3]),
        contact(5, 500, 100, "a", &[1]),
        contact(6, 500, 60, "spare", &[1]),
        coil(7, 700, 100, "b", &[5, 6]),
    ]
    .concat();
    let src = ld_project(&["go=TRUE", "spare", "a", "b"], &body);
    let (trace, _) = run_text("rows.xml", &src, 3, "inst.a,inst.b");
    assert_eq!(column(&trace, "inst.a"), [1.0, 1.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "inst.b"), [1.0, 1.0, 1.0], "{trace}");
}

/// A latch drawn above the outputs (semaforo-v3's shape): the outputs network starts with a
/// `NOT stop` contact at the very top (y=20) but its coil `lamp` sits lower (y=120); the latch
/// `go -> stop` has its coil at y=40. The latch's coil is the higher, so it runs first and `lamp`
/// goes out in the scan `stop` rises. Two coils 5 units apart (y=200 and y=205) are on one row:
/// the left one (`c`, the lower) runs first, as Beremiz's `SortInstances` tolerance has it.
/// Before, `lamp` stayed on one scan after `stop` (its network's top-most element is the higher),
/// and `d := c` read `c` from the previous scan.
#[test]
fn a_network_runs_at_the_row_of_its_first_coil() {
    let body = [
        // outputs: NOT stop (top) -> lamp (lower)
        contact(3, 100, 20, "stop", &[1]).replace("<contact ", r#"<contact negated="true" "#),
        coil(4, 400, 120, "lamp", &[3]),
        // the latch, its coil above lamp's
        contact(5, 100, 40, "go", &[1]),
        coil(6, 400, 40, "stop", &[5]),
        // one row, 5 units apart: d := c (right, higher), c := go (left, lower)
        contact(7, 500, 200, "c", &[1]),
        coil(8, 700, 200, "d", &[7]),
        contact(9, 100, 205, "go", &[1]),
        coil(10, 300, 205, "c", &[9]),
    ]
    .concat();
    let src = ld_project(&["go=TRUE", "stop", "lamp", "c", "d"], &body);
    let (trace, _) = run_text("latch.xml", &src, 3, "inst.stop,inst.lamp,inst.c,inst.d");
    assert_eq!(column(&trace, "inst.stop"), [1.0, 1.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "inst.lamp"), [0.0, 0.0, 0.0], "{trace}");
    assert_eq!(column(&trace, "inst.c"), [1.0, 1.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "inst.d"), [1.0, 1.0, 1.0], "{trace}");
}

/// An SFC program: `Init`, a transition on `go`, then the final step `Done` driving the Boolean
/// action `done` (N), nothing below it.
const FINAL_STEP: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="main" pouType="program">
      <interface><localVars>
        <variable name="go"><type><BOOL/></type></variable>
        <variable name="done"><type><BOOL/></type></variable>
      </localVars></interface>
      <body><SFC>
<step localId="1" name="Init" initialStep="true"><position x="100" y="20"/><connectionPointOut/></step>
<transition localId="2"><position x="110" y="80"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/>
  <condition><inline name=""><ST><xhtml:p>go</xhtml:p></ST></inline></condition></transition>
<step localId="3" name="Done"><position x="100" y="120"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOutAction/></step>
<actionBlock localId="4"><position x="180" y="120"/><connectionPointIn><connection refLocalId="3"/></connectionPointIn>
  <action localId="0" qualifier="N"><reference name="done"/></action></actionBlock>
      </SFC></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="C"><resource name="R"><task name="T" interval="T#10ms" priority="0"><pouInstance name="inst" typeName="main"/></task></resource></configuration></configurations></instances>
</project>
"#;

/// A final step is one W1464 at the step, and the project builds. Before: E3121, exit 1.
#[test]
fn a_final_sfc_step_is_a_warning() {
    let (code, lines) = check_text("final.xml", FINAL_STEP);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0]
            .starts_with("final.xml:15:1: warning[W1464]: step `Done` has no following transition"),
        "{lines:?}"
    );
    // textual SFC: the same, at the step's name
    let st = "PROGRAM p\nVAR go : BOOL; END_VAR\nINITIAL_STEP Init: END_STEP\n\
              TRANSITION FROM Init TO Done := go; END_TRANSITION\nSTEP Done: END_STEP\nEND_PROGRAM\n";
    let (code, lines) = check_text("final.st", st);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0]
            .starts_with("final.st:5:6: warning[W1464]: step `Done` has no following transition"),
        "{lines:?}"
    );
}

/// Once the transition fires (scan 2, where `go` is TRUE, the step's N action runs in that scan),
/// the final step stays active and `done` stays TRUE in every later scan although `go` falls
/// again: nothing leaves `Done`. Before: E3121, not runnable.
#[test]
fn a_final_sfc_step_stays_active() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("final.xml");
    std::fs::write(&file, FINAL_STEP).unwrap();
    let stim = "2,inst.go,1\n3,inst.go,0\n";
    let (trace, _) = common::run_stimulated(&file, 6, stim, "inst.go,inst.done");
    assert_eq!(
        column(&trace, "inst.go"),
        [0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "inst.done"),
        [0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
        "{trace}"
    );
}
