//! Round 31 (issue #13): a CODESYS V3 CFC body (PLCopen XML export: an empty `<ST>` plus the chart
//! in `<addData><data name="http://www.3s-software.com/plcopenxml/cfc"><CFC>`) is read as FBD and
//! run in its `executionOrderId` order (CODESYS online help, "CFC Execution Order" and "Automatic
//! Execution Order by Data Flow": the elements are numbered and run in that order). Wires pass
//! through unnamed wire points (`<connector>` without continuation) as CODESYS writes them; an
//! instance output read before its box runs is the previous cycle's. Before: one E0321 "ladderc
//! does not read" per chart (round 30), and before that an empty body.

mod common;

use common::{check_text, column, run_text, run_with_stimulus};

/// An input variable `expr` (localId `id`) and a wire point `point` from it, as CODESYS writes
/// them (the connection names the variable in `formalParameter`).
fn input(id: u32, point: u32, y: u32, expr: &str) -> String {
    format!(
        r#"<inVariable localId="{id}"><position x="2" y="{y}"/><connectionPointOut><expression/></connectionPointOut><expression>{expr}</expression></inVariable>
<connector localId="{point}" name=""><position x="0" y="0"/><connectionPointIn><connection refLocalId="{id}" formalParameter="{expr}"/></connectionPointIn></connector>
"#
    )
}

/// A wire point `point` on the output `pin` of element `from` (`""`: an operator's result).
fn wire(point: u32, from: u32, pin: &str) -> String {
    format!(
        r#"<connector localId="{point}" name=""><position x="0" y="0"/><connectionPointIn><connection refLocalId="{from}" formalParameter="{pin}"/></connectionPointIn></connector>
"#
    )
}

/// A box: `inputs` are (pin, wire point), `outputs` its output pins.
fn block(
    id: u32,
    order: u32,
    y: u32,
    ty: &str,
    instance: &str,
    inputs: &[(&str, u32)],
    outputs: &[&str],
) -> String {
    let inst = if instance.is_empty() {
        String::new()
    } else {
        format!(r#" instanceName="{instance}""#)
    };
    let ins: String = inputs
        .iter()
        .map(|(p, w)| format!(r#"<variable formalParameter="{p}"><connectionPointIn><relPosition x="0" y="0"/><connection refLocalId="{w}"/></connectionPointIn></variable>"#))
        .collect();
    let outs: String = outputs
        .iter()
        .map(|p| format!(r#"<variable formalParameter="{p}"><connectionPointOut><relPosition x="0" y="0"/><expression/></connectionPointOut></variable>"#))
        .collect();
    let call = if instance.is_empty() {
        "operator"
    } else {
        "functionblock"
    };
    format!(
        r#"<block localId="{id}" executionOrderId="{order}" typeName="{ty}"{inst}><position x="14" y="{y}"/><inputVariables>{ins}</inputVariables><inOutVariables/><outputVariables>{outs}</outputVariables><addData><data name="http://www.3s-software.com/plcopenxml/cfccalltype" handleUnknown="implementation"><CallType xmlns="">{call}</CallType></data></addData></block>
"#
    )
}

/// An output variable `expr` written from wire point `from`.
fn output(id: u32, order: u32, y: u32, from: u32, expr: &str) -> String {
    format!(
        r#"<outVariable localId="{id}" executionOrderId="{order}"><position x="40" y="{y}"/><connectionPointIn><relPosition x="0" y="0"/><connection refLocalId="{from}"/></connectionPointIn><expression>{expr}</expression></outVariable>
"#
    )
}

/// A body in CFC as CODESYS V3 exports it.
fn cfc_body(chart: &str) -> String {
    format!(
        r#"<body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml"/></ST>
<addData><data name="http://www.3s-software.com/plcopenxml/cfc" handleUnknown="implementation"><CFC>
{chart}</CFC></data></addData></body>"#
    )
}

/// A CODESYS V3 project of `pous`, whose task runs program `Main` as `m` every 10 ms.
fn project(pous: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
<fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP16 Patch 6" creationDateTime="2025-01-01T00:00:00"/>
<contentHeader name="t.project"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
<types><dataTypes/><pous>
{pous}
</pous></types>
<instances><configurations><configuration name="c"><resource name="r">
<task name="t" interval="PT0.01S" priority="1"><pouInstance name="m" typeName="Main"/></task>
</resource></configuration></configurations></instances>
</project>
"#
    )
}

/// A variable declaration.
fn var(name: &str, ty: &str) -> String {
    format!(r#"<variable name="{name}"><type><{ty}/></type></variable>"#)
}

/// Program `Main` counting `x := x + 1` and doubling `y := x * 2`, with the doubling drawn above
/// the count (so by position it would come first), in the execution order `add_first` or the
/// other one.
fn counter(add_first: bool) -> String {
    let (add, mul) = if add_first { (0, 2) } else { (2, 0) };
    let chart = [
        input(1, 2, 20, "x"),
        input(3, 4, 21, "1"),
        block(5, add, 20, "ADD", "", &[("In1", 2), ("In2", 4)], &["Out1"]),
        wire(6, 5, ""),
        output(7, add + 1, 20, 6, "x"),
        input(11, 12, 10, "x"),
        input(13, 14, 11, "2"),
        block(
            15,
            mul,
            10,
            "MUL",
            "",
            &[("In1", 12), ("In2", 14)],
            &["Out1"],
        ),
        wire(16, 15, ""),
        output(17, mul + 1, 10, 16, "y"),
    ]
    .concat();
    project(&format!(
        r#"<pou name="Main" pouType="program"><interface><localVars>{}{}</localVars></interface>{}</pou>"#,
        var("x", "INT"),
        var("y", "INT"),
        cfc_body(&chart)
    ))
}

/// A CFC program runs in `executionOrderId` order, not by position: with the count numbered
/// first, `y` doubles this cycle's `x` (2, 4, 6); numbered after the doubling, `y` doubles the
/// previous cycle's (0, 2, 4). Before: E0321, the chart not compiled (round 30), and before that
/// an empty body (x and y stayed 0).
#[test]
fn a_cfc_program_runs_in_its_execution_order() {
    let (trace, stderr) = run_text("count.xml", &counter(true), 3, "m.x,m.y");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "m.x"), [1.0, 2.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "m.y"), [2.0, 4.0, 6.0], "{trace}");
    let (trace, _) = run_text("count.xml", &counter(false), 3, "m.x,m.y");
    assert_eq!(column(&trace, "m.x"), [1.0, 2.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "m.y"), [0.0, 2.0, 4.0], "{trace}");
}

/// A function block `Guard` in CFC: `TON_0` (IN := Start, PT := T#30ms) sets `RS_0`, the
/// comparison `Level > 100` resets it, and `Alarm := RS_0.Q1`. `Alarm` is numbered before
/// `RS_0` (as in the real export this test is modelled on): it writes the flip-flop's output of
/// the previous cycle, one cycle late, and `Latched` (numbered after) the current one. Program
/// `Main` calls an instance of it. Before: E0321 (round 30), before that an empty FB.
#[test]
fn a_cfc_function_block_with_timer_flip_flop_and_comparison_runs_cycle_by_cycle() {
    let chart = [
        input(1, 2, 10, "Start"),
        input(3, 4, 11, "T#30ms"),
        block(
            5,
            1,
            10,
            "TON",
            "TON_0",
            &[("IN", 2), ("PT", 4)],
            &["Q", "ET"],
        ),
        wire(6, 5, "Q"),
        input(7, 8, 20, "Level"),
        input(9, 10, 21, "100"),
        block(11, 4, 20, "GT", "", &[("In1", 8), ("In2", 10)], &["Out1"]),
        wire(12, 11, ""),
        block(
            13,
            5,
            10,
            "RS",
            "RS_0",
            &[("SET", 6), ("RESET1", 12)],
            &["Q1"],
        ),
        wire(14, 13, "Q1"),
        output(15, 2, 10, 14, "Alarm"),
        wire(16, 13, "Q1"),
        output(17, 6, 12, 16, "Latched"),
    ]
    .concat();
    let guard = format!(
        r#"<pou name="Guard" pouType="functionBlock"><interface>
<inputVars>{}{}</inputVars><outputVars>{}{}</outputVars>
<localVars><variable name="TON_0"><type><derived name="TON"/></type></variable><variable name="RS_0"><type><derived name="RS"/></type></variable></localVars>
</interface>{}</pou>"#,
        var("Start", "BOOL"),
        var("Level", "INT"),
        var("Alarm", "BOOL"),
        var("Latched", "BOOL"),
        cfc_body(&chart)
    );
    let main = format!(
        r#"<pou name="Main" pouType="program"><interface><localVars>{}{}{}{}<variable name="g"><type><derived name="Guard"/></type></variable></localVars></interface>
<body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">g(Start := start, Level := level);
alarm := g.Alarm;
latched := g.Latched;</xhtml></ST></body></pou>"#,
        var("start", "BOOL"),
        var("level", "INT"),
        var("alarm", "BOOL"),
        var("latched", "BOOL"),
    );
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("guard.xml");
    std::fs::write(&file, project(&format!("{guard}\n{main}"))).unwrap();
    let trace = run_with_stimulus(
        &file,
        10,
        "0,m.start,1\n6,m.level,150\n7,m.start,0\n",
        &["m.start", "m.level", "m.latched", "m.alarm"],
    );
    // the timer's Q rises at 30 ms (cycle 3); Latched follows at once, Alarm one cycle later; the
    // level above 100 resets both from cycle 6 (Alarm a cycle later again)
    assert_eq!(
        column(&trace, "m.latched"),
        [0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "m.alarm"),
        [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0],
        "{trace}"
    );
}

/// A program and its action both in CFC, as CODESYS writes them: the program's chart calls the
/// action by a box of its name (numbered 0), so the action's chart runs there. Before: two E0321
/// (round 30's `detect_r30_run.rs`), and before that two empty bodies.
#[test]
fn a_cfc_action_of_a_cfc_program_runs_where_the_chart_calls_it() {
    let copy = [input(1, 2, 10, "a"), output(3, 0, 10, 2, "c")].concat();
    let chart = [
        input(1, 2, 10, "c"),
        output(3, 1, 10, 2, "b"),
        block(4, 0, 20, "Copy", "", &[], &[]),
    ]
    .concat();
    let src = project(&format!(
        r#"<pou name="Main" pouType="program"><interface><localVars><variable name="a"><type><BOOL/></type><initialValue><simpleValue value="TRUE"/></initialValue></variable>{}{}</localVars></interface>
<actions><action name="Copy">{}</action></actions>{}</pou>"#,
        var("b", "BOOL"),
        var("c", "BOOL"),
        cfc_body(&copy),
        cfc_body(&chart)
    ));
    let (trace, stderr) = run_text("relay.xml", &src, 2, "m.b,m.c");
    assert!(!stderr.contains("error["), "{stderr}");
    // the action (numbered 0) copies a into c before b := c (numbered 1)
    assert_eq!(column(&trace, "m.c"), [1.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "m.b"), [1.0, 1.0], "{trace}");
}

/// A wire point with no source (a `<connector>` without continuation and without connection) is
/// one E1059 at the connector, naming its localId and POU; the rest of the chart compiles.
#[test]
fn a_wire_point_without_source_is_one_located_error() {
    let chart = [
        r#"<connector localId="2" name=""><position x="0" y="0"/><connectionPointIn/></connector>
"#
        .to_string(),
        output(3, 0, 10, 2, "b"),
    ]
    .concat();
    let src = project(&format!(
        r#"<pou name="Main" pouType="program"><interface><localVars>{}</localVars></interface>{}</pou>"#,
        var("b", "BOOL"),
        cfc_body(&chart)
    ));
    let (code, lines) = check_text("open.xml", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("open.xml:8:1: error[E1059]: CFC wire point (connector, localId 2) is wired to no source"),
        "{lines:?}"
    );
    assert!(errors[0].contains("POU `Main`"), "{lines:?}");
}

/// An element the FBD reader does not know, inside a `<CFC>`, is a located error naming it (not
/// dropped): E3012 at the element.
#[test]
fn an_unknown_element_of_a_chart_is_a_located_error() {
    let chart = [
        input(1, 2, 10, "a"),
        output(3, 0, 10, 2, "b"),
        "<selector localId=\"9\"><position x=\"0\" y=\"0\"/></selector>\n".to_string(),
    ]
    .concat();
    let src = project(&format!(
        r#"<pou name="Main" pouType="program"><interface><localVars>{}{}</localVars></interface>{}</pou>"#,
        var("a", "BOOL"),
        var("b", "BOOL"),
        cfc_body(&chart)
    ));
    let (code, lines) = check_text("odd.xml", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("odd.xml:11:1: error[E3012]") && errors[0].contains("selector"),
        "{lines:?}"
    );
}

/// An operator box numbered after the output that reads its result: CODESYS would write the
/// result of the previous cycle; ladderc computes it where it is read and says so, one W1448 at
/// the box naming the reader (the standard is silent: IEC 61131-3 has no CFC).
#[test]
fn an_operator_numbered_after_its_reader_is_one_warning() {
    let chart = [
        input(1, 2, 10, "a"),
        input(3, 4, 11, "b"),
        block(5, 3, 10, "AND", "", &[("In1", 2), ("In2", 4)], &["Out1"]),
        wire(6, 5, ""),
        output(7, 0, 10, 6, "c"),
    ]
    .concat();
    let src = project(&format!(
        r#"<pou name="Main" pouType="program"><interface><localVars>{}{}{}</localVars></interface>{}</pou>"#,
        r#"<variable name="a"><type><BOOL/></type><initialValue><simpleValue value="TRUE"/></initialValue></variable>"#,
        r#"<variable name="b"><type><BOOL/></type><initialValue><simpleValue value="TRUE"/></initialValue></variable>"#,
        var("c", "BOOL"),
        cfc_body(&chart)
    ));
    let (code, lines) = check_text("late.xml", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    let w: Vec<_> = lines.iter().filter(|l| l.contains("W1448")).collect();
    assert_eq!(w.len(), 1, "{lines:?}");
    assert!(
        w[0].starts_with("late.xml:12:1: warning[W1448]: CFC element localId 5 does not run exactly at its executionOrderId")
            && w[0].contains("localId 7 reads its result before it runs"),
        "{lines:?}"
    );
    let (trace, _) = run_text("late.xml", &src, 1, "m.c");
    assert_eq!(column(&trace, "m.c"), [1.0], "{trace}");
}
