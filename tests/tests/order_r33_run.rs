//! Round 33 (issue #13): evaluation order of unnumbered FBD/CFC elements, and errors inside a
//! TwinCAT chart's condition taken from a `<Transition>` object, end to end:
//! - in an FBD/CFC whose elements are numbered (`executionOrderId`), an element without a number
//!   (an input variable, a connector) is evaluated where the data flow first needs it: just before
//!   the first numbered element that reads it, so it reads what the elements numbered before that
//!   one wrote (RuSTy's `plc_xml`: only numbered elements become statements, the others are
//!   expressions inside them; CODESYS, "Dialog: Properties: CFC Execution Order": "The POUs and
//!   the outputs are numbered internally"). RuSTy's `connection_var_source_multi_sink.cfc` returns
//!   4 as its test `connection_sink_source` expects (before: 2). A body numbered nowhere
//!   (Beremiz's all-zero files) keeps running by position;
//! - an error in the condition a TwinCAT chart takes from a `<Transition>` object is shown in the
//!   object: an ST condition at the name inside the object's text, an LD/FBD one at the network's
//!   element naming it (before: at the chart's element in the `<SFC>` archive plus the word's
//!   place in the condition, an unrelated line).

mod common;
use common::{check_files, column, run_text};
use std::path::Path;

/// A PLCopen project of one program `main` (DINT variables `x` = 2, `y`, `r`) whose FBD body is
/// `body`, run by a 10 ms task as `inst`.
fn project(body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="main" pouType="program">
      <interface><localVars>
        <variable name="x"><type><DINT/></type><initialValue><simpleValue value="2"/></initialValue></variable>
        <variable name="y"><type><DINT/></type></variable>
        <variable name="r"><type><DINT/></type></variable>
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

/// RuSTy's `connection_var_source_multi_sink` drawn again: `x` through the connector `s1` to the
/// output variable `y` (numbered `first`) and to ADD's second input; the input variable `y`, drawn
/// at the top and numbered nowhere, feeds ADD's first input; ADD (numbered `second`) to `r`
/// (numbered `third`).
fn sink_source(first: u32, second: u32, third: u32) -> String {
    format!(
        r#"<inVariable localId="2"><position x="10" y="130"/><connectionPointOut/><expression>x</expression></inVariable>
<connector name="s1" localId="1"><position x="100" y="130"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn></connector>
<continuation name="s1" localId="3"><position x="200" y="140"/><connectionPointOut/></continuation>
<outVariable localId="8" executionOrderId="{first}"><position x="300" y="140"/><connectionPointIn><connection refLocalId="3"/></connectionPointIn><expression>y</expression></outVariable>
<inVariable localId="7"><position x="300" y="10"/><connectionPointOut/><expression>y</expression></inVariable>
<block localId="9" typeName="ADD" executionOrderId="{second}"><position x="400" y="10"/>
  <inputVariables>
    <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="7"/></connectionPointIn></variable>
    <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></variable>
  </inputVariables>
  <inOutVariables/>
  <outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
</block>
<outVariable localId="4" executionOrderId="{third}"><position x="500" y="10"/><connectionPointIn><connection refLocalId="9" formalParameter="OUT"/></connectionPointIn><expression>r</expression></outVariable>
"#
    )
}

/// Numbered 0, 1, 2 (CFC, RuSTy's file): `y := x` runs first, then ADD reads `y` through the
/// unnumbered input variable, which is evaluated just before ADD: `r = y + x = 4` from the first
/// scan. Before, the unnumbered `y` (drawn at the top) was read first, before `y := x`: r = 0 + 2
/// = 2 in the first scan.
#[test]
fn unnumbered_input_variable_is_read_where_its_numbered_reader_runs() {
    let (trace, _) = run_text(
        "cfc_order.xml",
        &project(&sink_source(0, 1, 2)),
        2,
        "inst.y,inst.r",
    );
    assert_eq!(column(&trace, "inst.y"), [2.0, 2.0], "{trace}");
    assert_eq!(column(&trace, "inst.r"), [4.0, 4.0], "{trace}");
}

/// The same rule with numbers from 1 (ADD numbered 2 reads `y` after `y := x`, numbered 1): 4.
#[test]
fn unnumbered_input_variable_follows_the_write_numbered_before_its_reader() {
    let (trace, _) = run_text(
        "fbd_order.xml",
        &project(&sink_source(1, 2, 3)),
        1,
        "inst.r",
    );
    assert_eq!(column(&trace, "inst.r"), [4.0], "{trace}");
}

/// Beremiz and the OpenPLC Editor write `executionOrderId="0"` everywhere: no order, the network
/// runs by data flow and position, as before: the input variable `y` at the top is read before
/// `y := x` writes it, so `r` is 2 in the first scan and 4 from the second.
#[test]
fn all_zero_body_still_runs_by_position() {
    let (trace, _) = run_text(
        "allzero_order.xml",
        &project(&sink_source(0, 0, 0)),
        2,
        "inst.r",
    );
    assert_eq!(column(&trace, "inst.r"), [2.0, 4.0], "{trace}");
}

/// The test fixture `fixtures/twincat_sfc/<dir>MAIN.TcPOU` with `from` replaced by `to` once.
fn fixture_with(dir: &str, from: &str, to: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/twincat_sfc")
        .join(dir)
        .join("MAIN.TcPOU");
    let text = std::fs::read_to_string(&path).unwrap();
    assert_eq!(text.matches(from).count(), 1, "{from} in {path:?}");
    text.replacen(from, to, 1)
}

/// The chart's transition names the ST `<Transition>` object `T_Full` (`(* full at 50 *)` on line
/// 651, `nLevel >= 50` on line 652); `nLevelX` there is undeclared: one E1001 at 652:1, the name
/// in the object's text. Before: at 238:42, inside the chart's `<SFC>` archive (the transition's
/// element plus the word's place in the condition).
#[test]
fn undeclared_name_in_an_st_transition_object_is_shown_in_the_object() {
    let pou = fixture_with("", "nLevel >= 50]]>", "nLevelX >= 50]]>");
    let (code, errors) = check_files(&[("MAIN.TcPOU", &pou)]);
    assert_eq!(code, Some(1), "{errors:?}");
    assert_eq!(
        errors,
        ["MAIN.TcPOU:652:1: error[E1001]: undeclared name `nLevelX`"],
    );
}

/// The same in a transition object drawn in FBD (`T_Full := nLevel >= 50`, a GE box): the
/// undeclared operand `nLevelX` is one E1001 at its element in the object's network (line 692,
/// `<v n="Operand">"nLevelX"</v>`). Before: in the chart's `<SFC>` archive.
#[test]
fn undeclared_name_in_an_fbd_transition_object_is_shown_at_its_element() {
    let pou = fixture_with(
        "fbd_transition",
        r#"<v n="Operand">"nLevel"</v>"#,
        r#"<v n="Operand">"nLevelX"</v>"#,
    );
    let (code, errors) = check_files(&[("MAIN.TcPOU", &pou)]);
    assert_eq!(code, Some(1), "{errors:?}");
    assert_eq!(
        errors,
        ["MAIN.TcPOU:692:1: error[E1001]: undeclared name `nLevelX`"],
    );
}
