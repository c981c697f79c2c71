//! Constructs of the sixth acceptance run of issue #13 (2026-12-03, branch `lang`): the CODESYS
//! PLCopen exports of the "Pick and Place Unit" (PPU and xPPU scenarios) of
//! `KamilRosiak/IEC_61131_3_Clone_Detection`, whose function blocks keep their sequences in actions
//! whose body is an SFC chart (before, W3401 named them and every call was E1019 or E1011). Each
//! test is a minimal reproduction written here (`tests/fixtures/unseen/codesys_sfc_actions.xml`,
//! `codesys_action_boxes.xml`), run through `ladderc run` (C compiled with the sanitizers) or
//! `ladderc check`:
//! - an action whose body is an SFC chart runs one scan of its chart per call, from the POU's ST
//!   body (`Sequence();`), through an instance (`fb2.Sequence(Start := go);`) and from IL
//!   (`CALC Blink`); its steps, step times and action qualifiers (S, R, N, P, with the final scan of
//!   an action body) behave as the same chart as a function block's body, and its state is the
//!   POU's, in hidden variables named after the action (`__sfc_Blink__X_Dark`);
//! - an LD or FBD box named after an action (`Tick`, `ctr.Inc`, `Blink`) calls it when powered
//!   (before, E3007 "unknown block type"); its ENO is its EN.

mod common;
use common::{check_text, run_stimulated, unseen_fixture};
use std::path::Path;

/// [`run_stimulated`], asserting also that no action was left uncompiled (W3401).
fn run(file: &Path, cycles: u32, stimulus: &str, watch: &str) -> (String, String) {
    let (trace, stderr) = run_stimulated(file, cycles, stimulus, watch);
    assert!(!stderr.contains("W3401"), "{stderr}");
    (trace, stderr)
}

/// The end of the `<action>` (a POU's action with an SFC body) that starts at `start`: after the
/// `</action>` that follows its chart (the chart's action blocks hold `<action>` elements too).
fn action_end(src: &str, start: usize) -> usize {
    let chart_end = src[start..].find("</SFC>").unwrap() + start;
    src[chart_end..].find("</action>").unwrap() + chart_end + "</action>".len()
}

/// The columns `names` of a trace, one row per cycle (`cycle,time_ms` left out).
fn columns(trace: &str, names: &[&str]) -> Vec<Vec<String>> {
    let mut lines = trace.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let ks: Vec<usize> = names
        .iter()
        .map(|n| {
            header
                .iter()
                .position(|h| h == n)
                .unwrap_or_else(|| panic!("no column {n} in {header:?}"))
        })
        .collect();
    lines
        .map(|l| {
            let cells: Vec<&str> = l.split(',').collect();
            ks.iter().map(|&k| cells[k].to_string()).collect()
        })
        .collect()
}

/// Cylinder's body calls its SFC action `Sequence` every scan; PLC_PRG calls `fb(Start := go)` and
/// `fb2.Sequence(Start := go)` (only the action runs, with the input passed first). Init -> Move
/// when Start (a condition wired from an input variable, as CODESYS exports it); Move sets Extend
/// (S) and runs the ST action CountUp (N); Move -> Hold after 30 ms of Move.T; Hold resets Extend (R)
/// and drives Done (N); Hold -> Init when Start falls.
#[test]
fn an_sfc_action_runs_one_scan_of_its_chart_per_call_from_the_body_and_through_an_instance() {
    let (trace, _) = run(
        &unseen_fixture("codesys_sfc_actions.xml"),
        11,
        "2,PLC_PRG.go,TRUE\n8,PLC_PRG.go,FALSE\n",
        "PLC_PRG.fb.__sfc_Sequence__X_Move,PLC_PRG.fb.__sfc_Sequence__T_Move,PLC_PRG.fb.Extend,\
         PLC_PRG.fb.Count,PLC_PRG.fb.Done,PLC_PRG.fb2.Extend,PLC_PRG.fb2.Count,PLC_PRG.fb2.Done",
    );
    // Move is entered in cycle 2 (Start), Extend is set and CountUp runs from that scan; Move.T
    // reaches 30 ms in cycle 5, where Hold resets Extend, drives Done and CountUp runs its final
    // scan (Count 4); Start falls in cycle 8 and Hold is left (Done FALSE)
    assert_eq!(
        trace,
        "cycle,time_ms,PLC_PRG.fb.__sfc_Sequence__X_Move,PLC_PRG.fb.__sfc_Sequence__T_Move,\
         PLC_PRG.fb.Extend,PLC_PRG.fb.Count,PLC_PRG.fb.Done,PLC_PRG.fb2.Extend,PLC_PRG.fb2.Count,\
         PLC_PRG.fb2.Done\n\
         0,0,0,T#0ms,0,0,0,0,0,0\n\
         1,10,0,T#0ms,0,0,0,0,0,0\n\
         2,20,1,T#0ms,1,1,0,1,1,0\n\
         3,30,1,T#10ms,1,2,0,1,2,0\n\
         4,40,1,T#20ms,1,3,0,1,3,0\n\
         5,50,0,T#30ms,0,4,1,0,4,1\n\
         6,60,0,T#30ms,0,4,1,0,4,1\n\
         7,70,0,T#30ms,0,4,1,0,4,1\n\
         8,80,0,T#30ms,0,4,0,0,4,0\n\
         9,90,0,T#30ms,0,4,0,0,4,0\n\
         10,100,0,T#30ms,0,4,0,0,4,0\n"
    );
}

/// The same chart as the body of a function block (`Cylinder` with `<SFC>` as its body, called as
/// `fb(Start := go)`) and as an action called every scan behave alike, cycle by cycle.
#[test]
fn an_sfc_action_behaves_as_the_same_chart_as_a_function_block_body() {
    let src = std::fs::read_to_string(unseen_fixture("codesys_sfc_actions.xml")).unwrap();
    let start = src.find("<SFC>").unwrap();
    let end = src.find("</SFC>").unwrap() + "</SFC>".len();
    let chart = &src[start..end];
    let action_start = src.find("<action name=\"Sequence\">").unwrap();
    let action_end = action_end(&src, action_start);
    let body =
        "<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">Sequence();</xhtml></ST></body>";
    let as_body = format!("{}{}", &src[..action_start], &src[action_end..])
        .replacen(body, &format!("<body>{chart}</body>"), 1)
        .replace("fb2.Sequence(Start := go);", "fb2(Start := go);");
    assert!(as_body.contains("<body><SFC>") && !as_body.contains("Sequence"));
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("as_body.xml");
    std::fs::write(&file, as_body).unwrap();
    let stimulus =
        "1,PLC_PRG.go,TRUE\n3,PLC_PRG.go,FALSE\n6,PLC_PRG.go,TRUE\n13,PLC_PRG.go,FALSE\n";
    let outputs = "PLC_PRG.fb.Extend,PLC_PRG.fb.Count,PLC_PRG.fb.Done,PLC_PRG.fb2.Extend,\
                   PLC_PRG.fb2.Count,PLC_PRG.fb2.Done";
    let names: Vec<&str> = outputs.split(',').map(str::trim).collect();
    let (as_action, _) = run(
        &unseen_fixture("codesys_sfc_actions.xml"),
        16,
        stimulus,
        outputs,
    );
    let (as_body, _) = run(&file, 16, stimulus, outputs);
    let a = columns(&as_action, &names);
    assert_eq!(a, columns(&as_body, &names));
    // the chart did evolve: Extend was set and reset, Done came and went, Count counted
    assert!(a.iter().any(|r| r[0] == "1") && a.last().unwrap()[0] == "0");
    assert!(a.iter().any(|r| r[2] == "1"));
    assert_ne!(a.last().unwrap()[1], "0");
}

/// Lamp (IL body) calls its SFC action Blink with `CALC Blink` while `enable`: Dark -> Lit after
/// 20 ms, Lit -> Dark after 10 ms; Lit drives `light` (N) and runs the IL action CountFlash once
/// per entry (P). While not called, the chart stands still (Dark.T keeps its value, then measures
/// the time since the step was entered, as a step's TON does).
#[test]
fn an_sfc_action_called_from_il_runs_only_when_called() {
    let (trace, _) = run(
        &unseen_fixture("codesys_sfc_actions.xml"),
        16,
        "1,Lamp.enable,TRUE\n9,Lamp.enable,FALSE\n12,Lamp.enable,TRUE\n",
        "Lamp.enable,Lamp.light,Lamp.flashes,Lamp.__sfc_Blink__X_Dark,Lamp.__sfc_Blink__T_Dark",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Lamp.enable,Lamp.light,Lamp.flashes,Lamp.__sfc_Blink__X_Dark,Lamp.__sfc_Blink__T_Dark\n\
         0,0,0,0,0,1,T#0ms\n\
         1,10,1,0,0,1,T#0ms\n\
         2,20,1,0,0,1,T#10ms\n\
         3,30,1,1,1,0,T#20ms\n\
         4,40,1,0,1,1,T#0ms\n\
         5,50,1,0,1,1,T#10ms\n\
         6,60,1,1,2,0,T#20ms\n\
         7,70,1,0,2,1,T#0ms\n\
         8,80,1,0,2,1,T#10ms\n\
         9,90,0,0,2,1,T#10ms\n\
         10,100,0,0,2,1,T#10ms\n\
         11,110,0,0,2,1,T#10ms\n\
         12,120,1,1,3,0,T#50ms\n\
         13,130,1,0,3,1,T#0ms\n\
         14,140,1,0,3,1,T#10ms\n\
         15,150,1,1,4,0,T#20ms\n"
    );
}

/// Two SFC actions of one POU with the same step names keep separate state: Blink (20 ms dark,
/// 10 ms lit) and a copy Slow (40 ms dark, 10 ms lit) driving another variable.
#[test]
fn two_sfc_actions_with_the_same_step_names_keep_separate_state() {
    let src = std::fs::read_to_string(unseen_fixture("codesys_sfc_actions.xml")).unwrap();
    let start = src.find("<action name=\"Blink\">").unwrap();
    let end = action_end(&src, start);
    let slow = src[start..end]
        .replace("name=\"Blink\"", "name=\"Slow\"")
        .replace("T#20ms", "T#40ms")
        .replace(
            "<reference name=\"light\" />",
            "<reference name=\"slowLight\" />",
        )
        .replace(
            "<reference name=\"CountFlash\" />",
            "<reference name=\"light\" />",
        );
    let src = format!("{}\n{slow}{}", &src[..end], &src[end..])
        .replace(
            "<variable name=\"flashes\">",
            "<variable name=\"slowLight\"><type><BOOL /></type></variable>\n<variable name=\"flashes\">",
        )
        .replace("CALC Blink", "CALC Blink\nLD enable\nCALC Slow");
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("two.xml");
    std::fs::write(&file, src).unwrap();
    let (trace, _) = run(
        &file,
        12,
        "0,Lamp.enable,TRUE\n",
        "Lamp.__sfc_Blink__X_Lit,Lamp.__sfc_Slow__X_Lit,Lamp.slowLight,Lamp.flashes",
    );
    let rows = columns(
        &trace,
        &[
            "Lamp.__sfc_Blink__X_Lit",
            "Lamp.__sfc_Slow__X_Lit",
            "Lamp.slowLight",
            "Lamp.flashes",
        ],
    );
    let lit = |k: usize| -> Vec<usize> {
        rows.iter()
            .enumerate()
            .filter(|(_, r)| r[k] == "1")
            .map(|(c, _)| c)
            .collect()
    };
    // Blink is lit every third scan from cycle 2, Slow every fifth from cycle 4
    assert_eq!(lit(0), vec![2, 5, 8, 11], "{trace}");
    assert_eq!(lit(1), vec![4, 9], "{trace}");
    assert_eq!(lit(2), vec![4, 9], "{trace}");
    assert_eq!(rows.last().unwrap()[3], "4", "{trace}");
}

/// PLC_PRG's LD body: contact `run` powers a box `Tick` (its own ST action: ticks + 1) whose ENO
/// drives the coil `ticked`; contact `count` powers `ctr.Inc` (an action of the instance ctr);
/// the left rail powers `Blink`, its own SFC action (Dark 20 ms, Lit 10 ms driving `light`).
#[test]
fn ld_boxes_named_after_actions_call_them_when_powered() {
    let (trace, stderr) = run(
        &unseen_fixture("codesys_action_boxes.xml"),
        8,
        "1,PLC_PRG.run,TRUE\n4,PLC_PRG.run,FALSE\n2,PLC_PRG.count,TRUE\n5,PLC_PRG.count,FALSE\n",
        "PLC_PRG.run,PLC_PRG.ticks,PLC_PRG.ticked,PLC_PRG.count,PLC_PRG.ctr.n,PLC_PRG.light",
    );
    assert!(!stderr.contains("E3007"), "{stderr}");
    assert_eq!(
        trace,
        "cycle,time_ms,PLC_PRG.run,PLC_PRG.ticks,PLC_PRG.ticked,PLC_PRG.count,PLC_PRG.ctr.n,PLC_PRG.light\n\
         0,0,0,0,0,0,0,0\n\
         1,10,1,1,1,0,0,0\n\
         2,20,1,2,1,1,1,1\n\
         3,30,1,3,1,1,2,0\n\
         4,40,0,3,0,1,3,0\n\
         5,50,0,3,0,0,3,1\n\
         6,60,0,3,0,0,3,0\n\
         7,70,0,3,0,0,3,0\n"
    );
}

/// An action box wired to an input other than EN is one E3018 at the pin, located in the POU,
/// network and localId; a box named after nothing stays E3007.
#[test]
fn an_action_box_with_another_input_is_one_located_error() {
    let src = std::fs::read_to_string(unseen_fixture("codesys_action_boxes.xml")).unwrap();
    let wrong = src.replacen(
        "<variable formalParameter=\"EN\"><connectionPointIn><connection refLocalId=\"21\" />",
        "<variable formalParameter=\"Step\"><connectionPointIn><connection refLocalId=\"21\" />",
        1,
    );
    let (code, lines) = check_text("boxes.xml", &wrong);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("boxes.xml:101:17:")
            && errors[0].contains(
                "error[E3018]: the call of action `ctr.Inc` has no input `Step` [POU `PLC_PRG`, network 2, localId 22]"
            ),
        "{lines:?}"
    );
    let unknown = src.replacen("typeName=\"ctr.Inc\"", "typeName=\"ctr.Dec\"", 1);
    let (code, lines) = check_text("boxes.xml", &unknown);
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines.len() == 1 && lines[0].contains("error[E3007]: unknown block type `ctr.Dec`"),
        "{lines:?}"
    );
}

/// An ST expression in an FBD input variable (and an SFC condition, as the PPU's charts write
/// them) may read an internal variable of an FB instance (`NOT sw.DI_Switch`; CODESYS and
/// TwinCAT allow it, W1412), typed from the block's declaration (before, E3011 "the type of ...
/// cannot be told").
#[test]
fn an_expression_reading_an_internal_variable_of_an_instance_runs() {
    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP19" creationDateTime="2024-01-01T00:00:00" />
  <contentHeader name="Internal" modificationDateTime="2024-01-01T00:00:00"><coordinateInfo><fbd><scaling x="1" y="1" /></fbd><ld><scaling x="1" y="1" /></ld><sfc><scaling x="1" y="1" /></sfc></coordinateInfo></contentHeader>
  <types><dataTypes /><pous>
    <pou name="MicroSwitch" pouType="functionBlock">
      <interface><inputVars><variable name="press"><type><BOOL /></type></variable></inputVars>
        <localVars><variable name="DI_Switch"><type><BOOL /></type></variable><variable name="count"><type><INT /></type></variable></localVars></interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">DI_Switch := press; count := count + 1;</xhtml></ST></body>
    </pou>
    <pou name="PLC_PRG" pouType="program">
      <interface><localVars>
        <variable name="go"><type><BOOL /></type></variable>
        <variable name="y"><type><BOOL /></type></variable>
        <variable name="n"><type><INT /></type></variable>
        <variable name="sw"><type><derived name="MicroSwitch" /></type></variable>
      </localVars></interface>
      <body><FBD>
        <inVariable localId="1"><position x="0" y="0" /><connectionPointOut /><expression>go</expression></inVariable>
        <block localId="2" typeName="MicroSwitch" instanceName="sw"><position x="0" y="0" />
          <inputVariables><variable formalParameter="press"><connectionPointIn><connection refLocalId="1" /></connectionPointIn></variable></inputVariables>
          <inOutVariables /><outputVariables /></block>
        <inVariable localId="3"><position x="0" y="100" /><connectionPointOut /><expression>NOT sw.DI_Switch</expression></inVariable>
        <outVariable localId="4"><position x="0" y="100" /><connectionPointIn><connection refLocalId="3" /></connectionPointIn><expression>y</expression></outVariable>
        <inVariable localId="5"><position x="0" y="200" /><connectionPointOut /><expression>sw.count * 2</expression></inVariable>
        <outVariable localId="6"><position x="0" y="200" /><connectionPointIn><connection refLocalId="5" /></connectionPointIn><expression>n</expression></outVariable>
      </FBD></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="Device"><resource name="Application">
    <task name="MainTask" interval="PT0.01S" priority="1"><pouInstance name="PLC_PRG" typeName="" /></task>
  </resource></configuration></configurations></instances>
</project>"#;
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("internal.xml");
    std::fs::write(&file, xml).unwrap();
    // the expressions are evaluated at the start of their network, after sw ran in network 1:
    // y is NOT go (DI_Switch follows go), n is twice the calls of sw
    let (trace, stderr) = run(
        &file,
        4,
        "1,PLC_PRG.go,TRUE\n3,PLC_PRG.go,FALSE\n",
        "PLC_PRG.go,PLC_PRG.y,PLC_PRG.n",
    );
    assert!(
        stderr.contains("W1412") && !stderr.contains("E3011"),
        "{stderr}"
    );
    assert_eq!(
        trace,
        "cycle,time_ms,PLC_PRG.go,PLC_PRG.y,PLC_PRG.n\n0,0,0,1,2\n1,10,1,0,4\n2,20,1,0,6\n3,30,0,1,8\n"
    );
}

/// An action block may name an action of a function block instance (`ctr.Inc`, as the PPU's
/// conveyors name `Motor.ACT_Stop`; before, E3122 "not an IEC identifier"): it is called while the
/// chart's action is executed, here once per entry of step Lit (qualifier P).
#[test]
fn an_action_block_calls_an_action_of_an_instance() {
    let src = std::fs::read_to_string(unseen_fixture("codesys_action_boxes.xml")).unwrap();
    let src = src.replacen(
        "<reference name=\"light\" /><connectionPointOut /></action>",
        "<reference name=\"light\" /><connectionPointOut /></action>\n\
         <action localId=\"0\" qualifier=\"P\" duration=\"\" indicator=\"\"><relPosition x=\"0\" y=\"0\" />\
         <reference name=\"ctr.Inc\" /><connectionPointOut /></action>",
        1,
    );
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("call.xml");
    std::fs::write(&file, src).unwrap();
    let (trace, _) = run(&file, 9, "", "PLC_PRG.light,PLC_PRG.ctr.n");
    assert_eq!(
        trace,
        "cycle,time_ms,PLC_PRG.light,PLC_PRG.ctr.n\n0,0,0,0\n1,10,0,0\n2,20,1,1\n3,30,0,1\n\
         4,40,0,1\n5,50,1,2\n6,60,0,2\n7,70,0,2\n8,80,1,3\n"
    );
    // an instance without that action is still E3122, at the reference
    let (code, lines) = check_text(
        "call.xml",
        &std::fs::read_to_string(&file)
            .unwrap()
            .replace("\"ctr.Inc\" />", "\"ctr.Dec\" />"),
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines.len() == 1
            && lines[0].contains("error[E3122]: step `Lit` names action `ctr.Dec`")
            && lines[0].contains("[POU `PLC_PRG`, localId 4]"),
        "{lines:?}"
    );
}

/// CODESYS ends the branches of an alternative branch with steps and jumps and merges them with a
/// selection convergence followed by a transition (the xPPU's sorting conveyors; before, E3128
/// "<selectionConvergence> cannot precede a transition"): the transition leaves whichever branch's
/// step is active; a branch ending in a jump never reaches it.
#[test]
fn a_transition_after_a_convergence_of_branch_end_steps_leaves_the_active_one() {
    let (trace, _) = run(
        &unseen_fixture("codesys_branch_ends.xml"),
        15,
        "1,Sorter.light,TRUE\n2,Sorter.light,FALSE\n3,Sorter.done,TRUE\n4,Sorter.done,FALSE\n\
         6,Sorter.metal,TRUE\n7,Sorter.metal,FALSE\n8,Sorter.done,TRUE\n9,Sorter.done,FALSE\n\
         11,Sorter.reject,TRUE\n12,Sorter.reject,FALSE\n13,Sorter.done,TRUE\n",
        "Sorter.__sfc_X_Wait,Sorter.toRamp1,Sorter.toRamp2,Sorter.pushing",
    );
    // light: Ramp1 (cycles 1-2), done: Push (3); metal: Ramp2 (6-7), done: Push (8); reject jumps
    // back to Wait (11), and done in cycle 13 finds no branch step active
    assert_eq!(
        trace,
        "cycle,time_ms,Sorter.__sfc_X_Wait,Sorter.toRamp1,Sorter.toRamp2,Sorter.pushing\n\
         0,0,1,0,0,0\n1,10,0,1,0,0\n2,20,0,1,0,0\n3,30,0,0,0,1\n4,40,1,0,0,0\n5,50,1,0,0,0\n\
         6,60,0,0,1,0\n7,70,0,0,1,0\n8,80,0,0,0,1\n9,90,1,0,0,0\n10,100,1,0,0,0\n11,110,1,0,0,0\n\
         12,120,1,0,0,0\n13,130,1,0,0,0\n14,140,1,0,0,0\n"
    );
}

/// CODESYS keeps a step's entry action, step action and exit action in the step's vendor data
/// (`addData/data[.../sfc/element]`, attributes by GUID; before, ignored under W3002, so the PPU's
/// charts ran without them). Run (go): entry Enter (2), step action Tick (3) while active, exit
/// Leave (1) when left, without a final scan of Tick: `log` reads 2, 3, 3, 3, 1. Sub: entry
/// `table.Motor.ACT_Turn` and exit `table.Motor.ACT_Stop` (actions of an instance inside an
/// instance), step action ACT_Sub, an action whose body is a chart (A -> B -> A, B's step action
/// Flip), run while Sub is active. Other calls `t2.Motor.ACT_Turn();` from ST.
#[test]
fn codesys_entry_step_and_exit_actions_of_steps_run() {
    let (trace, stderr) = run(
        &unseen_fixture("codesys_step_actions.xml"),
        8,
        "1,PPU.go,TRUE\n4,PPU.go,FALSE\n",
        "PPU.__sfc_X_Run,PPU.log,PPU.__sfc_X_Sub,PPU.flips,PPU.__sfc_ACT_Sub__X_B,\
         PPU.table.Motor.turns,PPU.table.Motor.stops,Other.t2.Motor.turns",
    );
    assert!(!stderr.contains("W3002"), "{stderr}");
    assert_eq!(
        trace,
        "cycle,time_ms,PPU.__sfc_X_Run,PPU.log,PPU.__sfc_X_Sub,PPU.flips,PPU.__sfc_ACT_Sub__X_B,\
         PPU.table.Motor.turns,PPU.table.Motor.stops,Other.t2.Motor.turns\n\
         0,0,0,0,0,0,0,0,0,1\n\
         1,10,1,23,0,0,0,0,0,2\n\
         2,20,1,233,0,0,0,0,0,3\n\
         3,30,1,2333,0,0,0,0,0,4\n\
         4,40,0,23331,1,1,1,1,0,5\n\
         5,50,0,23331,1,1,0,1,0,6\n\
         6,60,0,23331,0,1,0,1,1,7\n\
         7,70,0,23331,0,1,0,1,1,8\n"
    );
    // a step action naming nothing is one E3122 at its attribute, located at the step
    let src = std::fs::read_to_string(unseen_fixture("codesys_step_actions.xml")).unwrap();
    let (code, lines) = check_text(
        "steps.xml",
        &src.replacen(">Tick</attribute>", ">Tock</attribute>", 1),
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines.len() == 1
            && lines[0].contains(
                "error[E3122]: step `Run` names action `Tock`, which is neither an action of the POU nor a BOOL variable [POU `PPU`, localId 3]"
            ),
        "{lines:?}"
    );
}

/// An EXECUTE box of an FBD action may call the POU's other actions (`Reset_Variables();`, an ST
/// action of an ST body; `Sort();`, an FBD action), as the PPU's conveyors do (before, E1019
/// "unknown function"): Conv's ST body calls its FBD action Auto every scan.
#[test]
fn an_execute_box_in_an_fbd_action_calls_other_actions() {
    let execute = |id: u32, code: &str| {
        format!(
            r#"<block localId="{id}" typeName="EXECUTE"><position x="0" y="0" /><inputVariables /><inOutVariables /><outputVariables />
              <addData><data name="http://www.3s-software.com/plcopenxml/stcode" handleUnknown="implementation"><STCode xmlns="">{code}</STCode></data></addData></block>"#
        )
    };
    let xml = format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP19" creationDateTime="2024-01-01T00:00:00" />
  <contentHeader name="Execute" modificationDateTime="2024-01-01T00:00:00"><coordinateInfo><fbd><scaling x="1" y="1" /></fbd><ld><scaling x="1" y="1" /></ld><sfc><scaling x="1" y="1" /></sfc></coordinateInfo></contentHeader>
  <types><dataTypes /><pous>
    <pou name="Conv" pouType="program">
      <interface><localVars>
        <variable name="n"><type><INT /></type></variable>
        <variable name="m"><type><INT /></type></variable>
        <variable name="k"><type><INT /></type></variable>
      </localVars></interface>
      <actions>
        <action name="Reset_Variables"><body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := n + 1;</xhtml></ST></body></action>
        <action name="Sort"><body><FBD>{sort}</FBD></body></action>
        <action name="Auto"><body><FBD>{auto}</FBD></body></action>
      </actions>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">Auto();</xhtml></ST></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="Device"><resource name="Application">
    <task name="MainTask" interval="PT0.01S" priority="1"><pouInstance name="Conv" typeName="" /></task>
  </resource></configuration></configurations></instances>
</project>"#,
        sort = execute(1, "k := k + 100;"),
        auto = execute(2, "Reset_Variables();\nm := m + 10;\nSort();"),
    );
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("execute.xml");
    std::fs::write(&file, &xml).unwrap();
    let (trace, _) = run(&file, 3, "", "Conv.n,Conv.m,Conv.k");
    assert_eq!(
        trace,
        "cycle,time_ms,Conv.n,Conv.m,Conv.k\n0,0,1,10,100\n1,10,2,20,200\n2,20,3,30,300\n"
    );
    // an error in the ST action is reported once, whether the body or an action calls it
    let (code, lines) = check_text(
        "execute.xml",
        &xml.replace("n := n + 1;", "n := n + undeclared;")
            .replace("Auto();", "Auto(); Reset_Variables();"),
    );
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert!(
        errors.len() == 1 && errors[0].contains("error[E1001]: undeclared name `undeclared`"),
        "{lines:?}"
    );
}

/// A step name with two underscores in a row (the xPPU's `Move_Forwards__Pos3`; CODESYS accepts
/// it, IEC 61131-3 does not) is one E3131 at the name; the transitions around the step are not
/// reported again (before, also E3128 "transition without a following step" and E3120).
#[test]
fn a_step_name_that_is_no_identifier_is_one_located_error() {
    let src = std::fs::read_to_string(unseen_fixture("codesys_branch_ends.xml")).unwrap();
    let (code, lines) = check_text(
        "steps.xml",
        &src.replacen("name=\"Ramp1\"", "name=\"Ramp__1\"", 1),
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines.len() == 1
            && lines[0].starts_with("steps.xml:42:38:")
            && lines[0].contains(
                "error[E3131]: step name `Ramp__1` is not an IEC identifier [POU `Sorter`, localId 12]"
            ),
        "{lines:?}"
    );
}
