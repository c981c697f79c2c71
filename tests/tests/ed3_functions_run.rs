//! Edition 3's functions and blocks that ladderc refused before round 25 of issue #13, run end to
//! end:
//! - the LTIME timers of Table 46, `TON_LTIME`, `TOF_LTIME`, `TP_LTIME` (PT and ET of type LTIME),
//!   under CODESYS's (Standard64) and TwinCAT's (Tc2_Standard) names `LTON`, `LTOF`, `LTP` too, and
//!   `TON_TIME` ... as the TIME timers (before: E1003 "unknown type `TON_LTIME`", E1003 for `LTON`);
//!   a TIME timer given an LTIME PT is E1012 with a hint naming the LTIME timer (before: the hint
//!   named only LTIME_TO_TIME).

mod common;
use common::{check_text, run_text};

/// The three timers on TIME, their LTIME forms under the standard's and the vendors' names, driven
/// by the same IN (TRUE for four 10 ms cycles, then FALSE) and PT (25 ms): Q and ET are cycle by
/// cycle the TIME timers' (TON: Q from 30 ms, ET held at PT; TP: a 25 ms pulse; TOF: Q held 25 ms
/// after IN falls), and an LTIME PT finer than a millisecond (20.5 ms) is kept to the microsecond.
#[test]
fn the_ltime_timers_run_as_the_time_timers() {
    let src = "PROGRAM main\nVAR\n  go : BOOL;\n  n : INT;\n  \
               t1 : TON; t2 : TON_LTIME; t3 : LTON; t4 : TON_TIME; t5 : LTON;\n  \
               p1 : TP; p2 : TP_LTIME; p3 : LTP;\n  f1 : TOF; f2 : TOF_LTIME; f3 : LTOF;\n  \
               e2 : LTIME; q3 : BOOL;\nEND_VAR\n  \
               go := n < 4;\n  n := n + 1;\n  \
               t1(IN := go, PT := T#25ms);\n  t2(IN := go, PT := LTIME#25ms, ET => e2);\n  \
               t3(IN := go, PT := LTIME#25ms, Q => q3);\n  t4(IN := go, PT := T#25ms);\n  \
               t5(IN := go, PT := LTIME#20ms500us);\n  \
               p1(IN := go, PT := T#25ms);\n  p2(IN := go, PT := LTIME#25ms);\n  p3(IN := go, PT := LTIME#25ms);\n  \
               f1(IN := go, PT := T#25ms);\n  f2(IN := go, PT := LTIME#25ms);\n  f3(IN := go, PT := LTIME#25ms);\n\
               END_PROGRAM\n";
    let mut watch = Vec::new();
    for fb in ["t1", "t2", "t3", "t4", "p1", "p2", "p3", "f1", "f2", "f3"] {
        watch.push(format!("main.{fb}.Q"));
        watch.push(format!("main.{fb}.ET"));
    }
    watch.extend(["main.e2", "main.q3", "main.t5.Q", "main.t5.ET"].map(String::from));
    let (trace, _) = run_text("ltimers.st", src, 9, &watch.join(","));
    let col = |name: &str| -> Vec<String> {
        let mut lines = trace.lines();
        let head = common::split_csv(lines.next().unwrap());
        let i = head.iter().position(|h| h == name).unwrap();
        lines.map(|l| common::split_csv(l)[i].clone()).collect()
    };
    let ms = |v: &[&str]| -> Vec<String> { v.iter().map(|s| format!("T#{s}")).collect() };
    let ton_q = ["0", "0", "0", "1", "0", "0", "0", "0", "0"];
    let ton_et = ms(&["0ms", "10ms", "20ms", "25ms", "0ms", "0ms", "0ms", "0ms", "0ms"]);
    let tp_q = ["1", "1", "1", "0", "0", "0", "0", "0", "0"];
    let tp_et = ms(&["0ms", "10ms", "20ms", "25ms", "0ms", "0ms", "0ms", "0ms", "0ms"]);
    let tof_q = ["1", "1", "1", "1", "1", "1", "1", "0", "0"];
    let tof_et = ms(&["0ms", "0ms", "0ms", "0ms", "0ms", "10ms", "20ms", "25ms", "25ms"]);
    for (fbs, q, et) in [
        (["t1", "t2", "t3", "t4"].as_slice(), &ton_q, &ton_et),
        (["p1", "p2", "p3"].as_slice(), &tp_q, &tp_et),
        (["f1", "f2", "f3"].as_slice(), &tof_q, &tof_et),
    ] {
        for fb in fbs {
            assert_eq!(col(&format!("main.{fb}.Q")), q, "{fb}.Q\n{trace}");
            assert_eq!(col(&format!("main.{fb}.ET")), *et, "{fb}.ET\n{trace}");
        }
    }
    assert_eq!(col("main.e2"), ton_et);
    assert_eq!(col("main.q3"), ton_q);
    assert_eq!(col("main.t5.Q"), ton_q);
    assert_eq!(
        col("main.t5.ET"),
        ms(&["0ms", "10ms", "20ms", "20500us", "0ms", "0ms", "0ms", "0ms", "0ms"])
    );
}

/// An FBD block `LTON` of a PLCopen XML project (CODESYS's name; the LD/FBD catalogue knows the
/// LTIME timers under every name sema does): its LTIME pins are wired as such.
#[test]
fn an_fbd_lton_block_runs() {
    let (trace, _) = run_text("ltimer.xml", LTON_FBD, 4, "main.E,main.DONE");
    assert_eq!(
        trace,
        "cycle,time_ms,main.E,main.DONE\n0,0,T#0ms,0\n1,10,T#10ms,0\n2,20,T#15ms,1\n3,30,T#15ms,1\n"
    );
}

/// `LTON`, `LTOF`, `LTP` are a vendor library's names, not the standard's: a variable may be named
/// so, and a project's own `LTON` block is used without W1446 (an `LTP : REAL` counter, a user
/// `LTON` that copies IN to Q).
#[test]
fn the_vendor_timer_names_stay_free_for_the_project() {
    let src = "FUNCTION_BLOCK LTON\nVAR_INPUT IN : BOOL; END_VAR\nVAR_OUTPUT Q : BOOL; END_VAR\n  \
               Q := NOT IN;\nEND_FUNCTION_BLOCK\n\
               PROGRAM main\nVAR\n  t1 : LTON;\n  q : BOOL;\n  ltp : REAL;\nEND_VAR\n  \
               ltp := ltp + 1.5;\n  t1(IN := TRUE, Q => q);\nEND_PROGRAM\n";
    let (code, lines) = check_text("own.st", src);
    assert_eq!((code, lines.clone()), (Some(0), vec![]), "{lines:?}");
    let (trace, _) = run_text("own.st", src, 2, "main.q,main.ltp");
    assert_eq!(trace, "cycle,time_ms,main.q,main.ltp\n0,0,0,1.5\n1,10,0,3\n");
}

/// A TIME timer given an LTIME PT: one E1012 whose hint names the LTIME timer of its family.
#[test]
fn an_ltime_pt_on_a_time_timer_names_the_ltime_timer() {
    let src = "PROGRAM main\nVAR\n  t1 : TOF;\n  x : LTIME := LTIME#1s;\nEND_VAR\n  \
               t1(IN := TRUE, PT := x);\nEND_PROGRAM\n";
    let (code, lines) = check_text("pt.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        ["pt.st:6:24: error[E1012]: PT of TOF is TIME, not LTIME (hint: declare the instance TOF_LTIME (edition 3's timer on LTIME), or convert explicitly with LTIME_TO_TIME)"]
    );
}

const LTON_FBD: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="ladderc" productName="tests" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="ltimers"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="main" pouType="program">
      <interface><localVars>
        <variable name="GO"><type><BOOL/></type><initialValue><simpleValue value="TRUE"/></initialValue></variable>
        <variable name="DONE"><type><BOOL/></type></variable>
        <variable name="E"><type><LTIME/></type></variable>
        <variable name="T1"><type><derived name="LTON"/></type></variable>
      </localVars></interface>
      <body><FBD>
        <block localId="40" typeName="LTON" instanceName="T1"><position x="0" y="0"/>
          <inputVariables>
            <variable formalParameter="IN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
            <variable formalParameter="PT"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></variable>
          </inputVariables>
          <inOutVariables/>
          <outputVariables>
            <variable formalParameter="Q"><connectionPointOut/></variable>
            <variable formalParameter="ET"><connectionPointOut/></variable>
          </outputVariables>
        </block>
        <outVariable localId="41"><position x="60" y="0"/><connectionPointIn><connection refLocalId="40" formalParameter="ET"/></connectionPointIn><expression>E</expression></outVariable>
        <outVariable localId="42"><position x="60" y="40"/><connectionPointIn><connection refLocalId="40" formalParameter="Q"/></connectionPointIn><expression>DONE</expression></outVariable>
        <inVariable localId="1"><position x="400" y="30"/><connectionPointOut/><expression>GO</expression></inVariable>
        <inVariable localId="3"><position x="400" y="90"/><connectionPointOut/><expression>LTIME#15ms</expression></inVariable>
      </FBD></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#;
