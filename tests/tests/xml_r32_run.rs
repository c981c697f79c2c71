//! Round 32 (PLCopen XML projects never seen before), through `ladderc run` and `ladderc check`:
//! - TP with `PT = T#0s` gives a one-scan pulse at the rising edge of IN (IEC 61131-3 ed. 3 Table
//!   45's diagram: Q rises with IN; CODESYS help, TP: "Rising edge starts the pulse timer and sets
//!   Q to TRUE"; matiec's TP sets Q on the edge and clears it in a later call). Before, the edge was
//!   lost: Q never rose (EnzoG14/TPA-LABORATORIOS LAB2's four TP/TOF blinkers never fired).
//! - An FBD numbered from 0 (`executionOrderId` 0, 1, 2, all different) runs the element numbered 0
//!   first, as CFC editors number (Beckhoff Infosys, TC3 CFC "Command Move to Beginning": "the
//!   lowest numbers starting with 0"). Before, 0 was read as "no order" and that element ran last
//!   (RuSTy's CFC test charts). A body whose elements are all 0 (Beremiz, OpenPLC Editor) keeps
//!   running by position.
//! - A PLCopen XML file recognised from its content (`.cfc`) is one project with the other inputs,
//!   as a `.xml` one is. Before, its block calling a FUNCTION of the `.st` given with it was E3007.
//! - Inputs of different sizes whose bits overlap in the target profile (`%IW0` and `%IX1.0`) get
//!   W1460, not under `--profile openplc`. Before, nothing: a stimulus of the word pressed the button.

mod common;
use common::{check_files, check_text, column, ladderc, run_stimulated, run_text};

/// A PLCopen project of one program `main` (DINT variables `a`, `b`, `c`) whose FBD body is `body`,
/// run by a 10 ms task as `inst`.
fn project(body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="main" pouType="program">
      <interface><localVars>
        <variable name="a"><type><DINT/></type></variable>
        <variable name="b"><type><DINT/></type></variable>
        <variable name="c"><type><DINT/></type></variable>
      </localVars></interface>
      <body><FBD>
{body}      </FBD></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="C"><resource name="R"><task name="T" interval="T#10ms" priority="0"><pouInstance name="inst" typeName="main"/></task></resource></configuration></configurations></instances>
</project>
"#
    )
}

/// `dst := expr` as an input variable wired to an output variable, drawn at row `y`, the output
/// variable numbered `order` (none when `None`), local ids from `id`.
fn assign(id: u32, y: i64, expr: &str, dst: &str, order: Option<u32>) -> String {
    let order = order.map_or(String::new(), |o| format!(r#" executionOrderId="{o}""#));
    format!(
        r#"<inVariable localId="{id}"><position x="10" y="{y}"/><connectionPointOut/><expression>{expr}</expression></inVariable>
<outVariable localId="{out}"{order}><position x="100" y="{y}"/><connectionPointIn><connection refLocalId="{id}"/></connectionPointIn><expression>{dst}</expression></outVariable>
"#,
        out = id + 1
    )
}

/// A TP with `PT := T#0s` gives Q for exactly the scan that sees IN rise, and again at the next
/// rising edge; TON with PT 0 gives Q at once while IN is TRUE, TOF with PT 0 follows IN (no delay,
/// ladderc's documented reading; matiec sets those one scan late). Before, the TP's Q never rose and
/// `n` stayed 0.
#[test]
fn tp_with_zero_pt_gives_a_one_scan_pulse() {
    let src = r#"
PROGRAM main
VAR p : TP; on : TON; off : TOF; i : BOOL; q, qon, qoff : BOOL; n : INT; END_VAR
p(IN := i, PT := T#0s);
on(IN := i, PT := T#0s);
off(IN := i, PT := T#0s);
q := p.Q; qon := on.Q; qoff := off.Q;
IF p.Q THEN n := n + 1; END_IF;
END_PROGRAM
CONFIGURATION C RESOURCE R ON PLC
  TASK t(INTERVAL := T#10ms, PRIORITY := 0);
  PROGRAM inst WITH t : main;
END_RESOURCE END_CONFIGURATION
"#;
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("tp0.st");
    std::fs::write(&f, src).unwrap();
    let (trace, _) = run_stimulated(
        &f,
        9,
        "2,inst.i,TRUE\n5,inst.i,FALSE\n7,inst.i,TRUE\n",
        "inst.q,inst.n,inst.qon,inst.qoff",
    );
    assert_eq!(
        column(&trace, "inst.q"),
        [0., 0., 1., 0., 0., 0., 0., 1., 0.],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "inst.n"),
        [0., 0., 1., 1., 1., 1., 1., 2., 2.],
        "{trace}"
    );
    let held = [0., 0., 1., 1., 1., 0., 0., 1., 1.];
    assert_eq!(column(&trace, "inst.qon"), held, "{trace}");
    assert_eq!(column(&trace, "inst.qoff"), held, "{trace}");
}

/// OpenPLC Editor's blinker: a TP whose PT is left unconnected (T#0s) feeding a TOF that switches
/// the TP off, the TP's pulses counted by a CTU (EnzoG14/TPA-LABORATORIOS LAB2's form, written
/// here in ST): the counter counts. Before, the TP never fired and the counter stayed 0.
#[test]
fn tp_tof_blinker_with_unconnected_pt_counts() {
    let src = r#"
PROGRAM main
VAR p : TP; off : TOF; cnt : CTU; END_VAR
p(IN := NOT off.Q);
off(IN := p.Q, PT := T#30ms);
cnt(CU := p.Q, PV := 100);
END_PROGRAM
CONFIGURATION C RESOURCE R ON PLC
  TASK t(INTERVAL := T#10ms, PRIORITY := 0);
  PROGRAM inst WITH t : main;
END_RESOURCE END_CONFIGURATION
"#;
    let (trace, _) = run_text("blink.st", src, 12, "inst.p.Q,inst.cnt.CV");
    let cv = column(&trace, "inst.cnt.CV");
    assert_eq!(cv[0], 1.0, "{trace}");
    assert!(cv[11] >= 2.0, "the blinker fires again: {trace}");
}

/// Elements numbered 0, 1, 2 run in that order, whatever their position (drawn bottom to top
/// here): `a := 1`, then `b := a`, then `c := b + 1` give 1, 1, 2 in the first scan. Before, the
/// element numbered 0 ran last (a = 1, b = 0, c = 1).
#[test]
fn fbd_numbered_from_zero_runs_zero_first() {
    let body = [
        assign(1, 200, "1", "a", Some(0)),
        assign(3, 100, "a", "b", Some(1)),
        assign(5, 0, "b + 1", "c", Some(2)),
    ]
    .concat();
    let (trace, _) = run_text("zero.xml", &project(&body), 1, "inst.a,inst.b,inst.c");
    assert_eq!(column(&trace, "inst.a"), [1.0], "{trace}");
    assert_eq!(column(&trace, "inst.b"), [1.0], "{trace}");
    assert_eq!(column(&trace, "inst.c"), [2.0], "{trace}");
}

/// Beremiz and the OpenPLC Editor write `executionOrderId="0"` on every element: no order, the
/// body runs by position (top to bottom: `c := b + 1`, `b := a`, `a := 1` give 1, 0, 1 in the
/// first scan), as before.
#[test]
fn fbd_all_zero_runs_by_position() {
    let body = [
        assign(1, 200, "1", "a", Some(0)),
        assign(3, 100, "a", "b", Some(0)),
        assign(5, 0, "b + 1", "c", Some(0)),
    ]
    .concat();
    let (trace, _) = run_text("allzero.xml", &project(&body), 1, "inst.a,inst.b,inst.c");
    assert_eq!(column(&trace, "inst.a"), [1.0], "{trace}");
    assert_eq!(column(&trace, "inst.b"), [0.0], "{trace}");
    assert_eq!(column(&trace, "inst.c"), [1.0], "{trace}");
}

/// A `.cfc` file holding a PLCopen `<pou>` (read as PLCopen XML from its content, note W0302)
/// whose FBD calls `myAdd`, a FUNCTION of the `.st` file given with it (which also holds the
/// configuration): one project, `r = 2 + 3`. Before, E3007 "unknown block type" and exit 1.
#[test]
fn xml_recognised_by_content_is_one_project_with_the_other_files() {
    let cfc = r#"<?xml version="1.0" encoding="UTF-8"?>
<pou xmlns="http://www.plcopen.org/xml/tc6_0201" name="main" pouType="program">
  <interface><localVars><variable name="r"><type><DINT/></type></variable></localVars></interface>
  <body><FBD>
    <inVariable localId="1"><position x="10" y="10"/><connectionPointOut/><expression>2</expression></inVariable>
    <inVariable localId="2"><position x="10" y="40"/><connectionPointOut/><expression>3</expression></inVariable>
    <block localId="3" typeName="myAdd"><position x="80" y="10"/>
      <inputVariables>
        <variable formalParameter="a"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
        <variable formalParameter="b"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
      </inputVariables><inOutVariables/>
      <outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
    </block>
    <outVariable localId="4"><position x="200" y="10"/><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn><expression>r</expression></outVariable>
  </FBD></body>
</pou>
"#;
    let st = r#"FUNCTION myAdd : DINT
VAR_INPUT a, b : DINT; END_VAR
myAdd := a + b;
END_FUNCTION
CONFIGURATION C RESOURCE R ON PLC
  TASK t(INTERVAL := T#10ms, PRIORITY := 0);
  PROGRAM inst WITH t : main;
END_RESOURCE END_CONFIGURATION
"#;
    let (code, errors) = check_files(&[("chart.cfc", cfc), ("lib.st", st)]);
    assert_eq!(code, Some(0), "{errors:?}");
    assert!(errors.is_empty(), "{errors:?}");
    let dir = tempfile::tempdir().unwrap();
    let (c, s) = (dir.path().join("chart.cfc"), dir.path().join("lib.st"));
    std::fs::write(&c, cfc).unwrap();
    std::fs::write(&s, st).unwrap();
    let (trace, stderr) = common::run_traced_files(&[&c, &s], 1, "inst.r");
    assert_eq!(column(&trace, "inst.r"), [5.0], "{trace}");
    assert!(stderr.contains("note[W0302]"), "{stderr}");
}

/// ST with an analog word `%IW0` and a push button `%IX1.0`, bit 0 of byte 1 of that word in the
/// default profile; two variables read the same bit `%IX2.0` (no overlap warning: one signal).
const INPUTS: &str = r#"PROGRAM main
VAR
  level  AT %IW0   : WORD;
  button AT %IX1.0 : BOOL;
  start  AT %IX2.0 : BOOL;
  start2 AT %IX2.0 : BOOL;
  high : BOOL;
END_VAR
high := button OR start OR start2 OR level > 100;
END_PROGRAM
CONFIGURATION C RESOURCE R ON PLC
  TASK t(INTERVAL := T#10ms, PRIORITY := 0);
  PROGRAM inst WITH t : main;
END_RESOURCE END_CONFIGURATION
"#;

/// The button inside the word is one W1460 at its address (line 4, column 13), naming both and
/// `--profile openplc`; the two variables at `%IX2.0` get none. Before, no diagnostic.
#[test]
fn overlapping_inputs_of_different_sizes_warn() {
    let (code, lines) = check_text("inputs.st", INPUTS);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "inputs.st:4:13: warning[W1460]: `main.button` at %IX1.0 shares input bits with `main.level` at %IW0"
        ),
        "{lines:?}"
    );
    assert!(lines[0].contains("--profile openplc"), "{lines:?}");
}

/// Under `--profile openplc` (one image per size, as OpenPLC and matiec have) the word and the
/// button are apart: no W1460.
#[test]
fn overlapping_inputs_are_apart_under_the_openplc_profile() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("inputs.st");
    std::fs::write(&f, INPUTS).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check", "--profile", "openplc"])
        .arg(&f)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("W1460"), "{stderr}");
}
