//! Edition 3's functions and blocks that ladderc refused before round 25 of issue #13, run end to
//! end:
//! - the LTIME timers of Table 46, `TON_LTIME`, `TOF_LTIME`, `TP_LTIME` (PT and ET of type LTIME),
//!   under CODESYS's (Standard64) and TwinCAT's (Tc2_Standard) names `LTON`, `LTOF`, `LTP` too, and
//!   `TON_TIME` ... as the TIME timers (before: E1003 "unknown type `TON_LTIME`", E1003 for `LTON`);
//!   a TIME timer given an LTIME PT is E1012 with a hint naming the LTIME timer (before: the hint
//!   named only LTIME_TO_TIME).
//! - the functions with outputs of Table 36, `SPLIT_DATE`, `SPLIT_TOD`, `SPLIT_LTOD`, `SPLIT_DT`,
//!   `SPLIT_LDT`, in ST and IL, into integer variables of any width that holds the part, with EN and
//!   ENO (before: E1019 "unknown function `SPLIT_DT`"); a call without formal outputs or without IN
//!   is E1062, a part into a variable too narrow for it (a YEAR into SINT) or not an integer is
//!   E1012; and the long forms of Table 36's `CONCAT_TOD` and `CONCAT_DT`, `CONCAT_LTOD` and
//!   `CONCAT_LDT`, which give back what SPLIT_LTOD and SPLIT_LDT split (before: E1019).
//! - the endianness conversions, `TO_BIG_ENDIAN`, `TO_LITTLE_ENDIAN`, `FROM_BIG_ENDIAN`,
//!   `FROM_LITTLE_ENDIAN`, on every width of ANY_INT, ANY_BIT and ANY_REAL, on values whose bytes
//!   all differ (before: E1019 "unknown function `TO_BIG_ENDIAN`"); a STRING or TIME is E1004.

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
    let ton_et = ms(&[
        "0ms", "10ms", "20ms", "25ms", "0ms", "0ms", "0ms", "0ms", "0ms",
    ]);
    let tp_q = ["1", "1", "1", "0", "0", "0", "0", "0", "0"];
    let tp_et = ms(&[
        "0ms", "10ms", "20ms", "25ms", "0ms", "0ms", "0ms", "0ms", "0ms",
    ]);
    let tof_q = ["1", "1", "1", "1", "1", "1", "1", "0", "0"];
    let tof_et = ms(&[
        "0ms", "0ms", "0ms", "0ms", "0ms", "10ms", "20ms", "25ms", "25ms",
    ]);
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
    assert_eq!(
        trace,
        "cycle,time_ms,main.q,main.ltp\n0,0,0,1.5\n1,10,0,3\n"
    );
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

/// Every SPLIT function on values whose parts all differ, into outputs of every integer width that
/// holds them: a DT on a leap day one second before the next day (and, two seconds later, the next
/// day), an LDT before 1970 (negative nanoseconds), a DATE, a TOD and an LTOD whose sub-millisecond
/// digits are cut (not rounded), a part left out.
#[test]
fn the_split_functions_give_every_part() {
    let src = "PROGRAM main\nVAR\n  dt1 : DT := DT#2024-02-29-23:59:58.123;\n  \
               ldt1 : LDT := LDT#1969-12-31-01:02:03.456789;\n  \
               y : INT; mo : USINT; d : SINT; h : DINT; mi : LINT; s : UINT; ms : UDINT;\n  \
               y2, mo2, d2, h2, mi2, s2, ms2 : INT;\n  dy : ULINT; dm, dd : INT;\n  \
               th, tm, ts, tms : INT;\n  lh, lms : INT;\nEND_VAR\n  \
               SPLIT_DT(IN := dt1, YEAR => y, MONTH => mo, DAY => d, HOUR => h, MINUTE => mi, SECOND => s, MILLISECOND => ms);\n  \
               SPLIT_LDT(IN := ldt1, YEAR => y2, MONTH => mo2, DAY => d2, HOUR => h2, MINUTE => mi2, SECOND => s2, MILLISECOND => ms2);\n  \
               SPLIT_DATE(IN := D#2000-03-01, YEAR => dy, MONTH => dm, DAY => dd);\n  \
               SPLIT_TOD(IN := TOD#07:08:09.010, HOUR => th, MINUTE => tm, SECOND => ts, MILLISECOND => tms);\n  \
               SPLIT_LTOD(IN := LTOD#22:00:00.999999, HOUR => lh, MILLISECOND => lms);\n  \
               dt1 := ADD_DT_TIME(dt1, T#2s);\nEND_PROGRAM\n";
    let watch = "main.y,main.mo,main.d,main.h,main.mi,main.s,main.ms,main.y2,main.mo2,main.d2,main.h2,main.mi2,main.s2,main.ms2,main.dy,main.dm,main.dd,main.th,main.tm,main.ts,main.tms,main.lh,main.lms";
    let (trace, _) = run_text("split.st", src, 2, watch);
    assert_eq!(
        trace,
        format!(
            "cycle,time_ms,{}\n\
             0,0,2024,2,29,23,59,58,123,1969,12,31,1,2,3,456,2000,3,1,7,8,9,10,22,999\n\
             1,10,2024,3,1,0,0,0,123,1969,12,31,1,2,3,456,2000,3,1,7,8,9,10,22,999\n",
            watch
        )
    );
}

/// `CONCAT_LTOD` and `CONCAT_LDT` build the long forms from the parts `SPLIT_LTOD` and `SPLIT_LDT`
/// give; an invalid part (a 13th month) gives 0 and the range flag (reported at the end of the
/// run), as `CONCAT_DT`'s.
#[test]
fn concat_ltod_and_concat_ldt_join_the_parts() {
    let src = "PROGRAM main\nVAR\n  t : LTOD;\n  l, bad : LDT;\n  y, mo, d, h, mi, s, ms : INT;\nEND_VAR\n  \
               SPLIT_LDT(IN := LDT#2024-02-29-13:14:15.678, YEAR => y, MONTH => mo, DAY => d, HOUR => h, MINUTE => mi, SECOND => s, MILLISECOND => ms);\n  \
               l := CONCAT_LDT(y, mo, d, h, mi, s, ms);\n  \
               t := CONCAT_LTOD(HOUR := h, MINUTE := mi, SECOND := s, MILLISECOND := ms);\n  \
               bad := CONCAT_LDT(2024, 13, 1, 0, 0, 0, 0);\nEND_PROGRAM\n";
    let (trace, stderr) = run_text("concat.st", src, 1, "main.l,main.t,main.bad");
    assert_eq!(
        trace,
        "cycle,time_ms,main.l,main.t,main.bad\n0,0,LDT#2024-02-29-13:14:15.678,LTOD#13:14:15.678,LDT#1970-01-01-00:00:00\n"
    );
    assert!(
        stderr.contains("runtime: conversion out of range"),
        "{stderr}"
    );
}

/// In IL (a formal call of the function, and `CAL`), and with EN: FALSE leaves the outputs as they
/// were and ENO FALSE, TRUE splits.
#[test]
fn split_runs_in_il_and_with_en() {
    let il = "PROGRAM main\nVAR\n  d : INT := 5;\n  m : INT;\n  e : BOOL;\n  ok : BOOL := TRUE;\n  h : INT;\nEND_VAR\n  \
              SPLIT_DATE(EN := e, IN := D#2001-02-03, DAY => d, MONTH => m, ENO => ok)\n  \
              CAL SPLIT_TOD(IN := TOD#13:14:15, HOUR => h)\n  \
              LD TRUE\n  ST e\nEND_PROGRAM\n";
    let (trace, _) = run_text("split.il", il, 2, "main.d,main.m,main.ok,main.h");
    assert_eq!(
        trace,
        "cycle,time_ms,main.d,main.m,main.ok,main.h\n0,0,5,0,0,13\n1,10,3,2,1,13\n"
    );
}

/// A SPLIT call without formal outputs or without IN is one E1062 each; a part into a variable
/// that cannot hold it, or that is no integer, is E1012; an IN of another type is E1012.
#[test]
fn bad_split_calls_are_located_errors() {
    let src = "PROGRAM main\nVAR\n  y : SINT;\n  m : INT;\n  r : REAL;\n  d : DATE;\nEND_VAR\n  \
               SPLIT_DATE(d, m, m, m);\n  \
               SPLIT_DATE(YEAR => m);\n  \
               SPLIT_DATE(IN := d, YEAR => y, MONTH => r, DAY => m);\n  \
               SPLIT_DATE(IN := T#1s, DAY => m);\nEND_PROGRAM\n";
    let heads = common::rejected_heads("bad.st", src);
    assert_eq!(
        heads,
        [
            "bad.st:8:3: error[E1062]: SPLIT_DATE gives its parts as outputs: it needs a formal call",
            "bad.st:9:3: error[E1062]: SPLIT_DATE without its input IN",
            "bad.st:10:31: error[E1012]: output YEAR of SPLIT_DATE (1677..2262) cannot be stored into SINT",
            "bad.st:10:43: error[E1012]: output MONTH of SPLIT_DATE (1..12) cannot be stored into REAL",
            "bad.st:11:20: error[E1012]: IN of SPLIT_DATE is DATE, not TIME",
        ]
    );
}

/// On this (little-endian) host, TO_BIG_ENDIAN and FROM_BIG_ENDIAN reverse the bytes of every
/// type wider than a byte and the LITTLE ones keep them; the generated C orders bytes in memory
/// (no host assumption), so a round trip gives the value back on any host. REAL and LREAL: the
/// bytes of 1.0 reversed (0x0000803F and 0x000000000000F03F as numbers); an untyped literal takes
/// the type of the variable it is stored into.
#[test]
fn the_endianness_conversions_order_the_bytes() {
    let src = "PROGRAM main\nVAR\n  \
               w : WORD := 16#1234; i : INT := -2; d : DWORD := 16#11223344; di : DINT := 16#01020304;\n  \
               l : LWORD := 16#0102030405060708; li : LINT := -2; u : UINT := 16#00FF; ud : UDINT := 1;\n  \
               r : REAL := 1.0; lr : LREAL := 1.0; b : BYTE := 16#AB; si : SINT := -5;\n  \
               wb, wl, wfb, wfl, wlit : WORD; ib : INT; db, dl, dfb : DWORD; dib, dlit : DINT; lb : LWORD; lib : LINT;\n  \
               ub : UINT; udb : UDINT; rb, rr : REAL; lrb, lrr : LREAL; bb : BYTE; sib : SINT; x : BOOL;\n\
               END_VAR\n  \
               wb := TO_BIG_ENDIAN(w);\n  wl := TO_LITTLE_ENDIAN(w);\n  \
               wfb := FROM_BIG_ENDIAN(wb);\n  wfl := FROM_LITTLE_ENDIAN(w);\n  \
               wlit := TO_BIG_ENDIAN(16#1234);\n  dlit := TO_BIG_ENDIAN(16#1234);\n  \
               ib := TO_BIG_ENDIAN(i);\n  db := TO_BIG_ENDIAN(d);\n  dl := TO_LITTLE_ENDIAN(d);\n  \
               dfb := FROM_BIG_ENDIAN(TO_BIG_ENDIAN(d));\n  dib := FROM_BIG_ENDIAN(di);\n  \
               lb := TO_BIG_ENDIAN(l);\n  lib := TO_BIG_ENDIAN(li);\n  ub := TO_BIG_ENDIAN(u);\n  \
               udb := FROM_BIG_ENDIAN(ud);\n  rb := TO_BIG_ENDIAN(r);\n  rr := FROM_BIG_ENDIAN(rb);\n  \
               lrb := TO_BIG_ENDIAN(lr);\n  lrr := FROM_BIG_ENDIAN(lrb);\n  \
               bb := TO_BIG_ENDIAN(b);\n  sib := FROM_BIG_ENDIAN(si);\n  x := TO_BIG_ENDIAN(TRUE);\n\
               END_PROGRAM\n";
    let want = [
        ("wb", "13330"), // 16#3412
        ("wl", "4660"),  // 16#1234
        ("wfb", "4660"),
        ("wfl", "4660"),
        ("wlit", "13330"),
        ("dlit", "873594880"), // 16#34120000
        ("ib", "-257"),        // 16#FFFE -> 16#FEFF
        ("db", "1144201745"),  // 16#44332211
        ("dl", "287454020"),   // 16#11223344
        ("dfb", "287454020"),
        ("dib", "67305985"),           // 16#04030201
        ("lb", "578437695752307201"),  // 16#0807060504030201
        ("lib", "-72057594037927937"), // 16#FEFFFFFFFFFFFFFF
        ("ub", "65280"),               // 16#FF00
        ("udb", "16777216"),           // 16#01000000
        ("rb", "4.6006e-41"),
        ("rr", "1"),
        ("lrb", "3.03865194161742e-319"),
        ("lrr", "1"),
        ("bb", "171"),
        ("sib", "-5"),
        ("x", "1"),
    ];
    let watch: Vec<String> = want.iter().map(|(n, _)| format!("main.{n}")).collect();
    let (trace, _) = run_text("endian.st", src, 1, &watch.join(","));
    let row: Vec<String> = common::split_csv(trace.lines().nth(1).unwrap());
    for (k, (n, v)) in want.iter().enumerate() {
        assert_eq!(row[k + 2], *v, "{n}\n{trace}");
    }
}

/// In IL, on the current result (`LD w` then `TO_BIG_ENDIAN`), and formally with EN FALSE (the
/// result is 0, ENO FALSE).
#[test]
fn the_endianness_conversions_run_in_il() {
    let il = "PROGRAM main\nVAR\n  w : WORD := 16#ABCD;\n  a, c : WORD;\n  ok : BOOL := TRUE;\nEND_VAR\n  \
              LD w\n  TO_BIG_ENDIAN\n  ST a\n  \
              TO_LITTLE_ENDIAN(EN := FALSE, IN := w, ENO => ok)\n  ST c\nEND_PROGRAM\n";
    let (trace, _) = run_text("endian.il", il, 1, "main.a,main.c,main.ok");
    // 16#CDAB
    assert_eq!(
        trace,
        "cycle,time_ms,main.a,main.c,main.ok\n0,0,52651,0,0\n"
    );
}

/// A value of another kind (a STRING, a TIME) is E1004 naming the classes the conversions take.
#[test]
fn the_endianness_conversions_refuse_other_types() {
    let src = "PROGRAM main\nVAR\n  w : WORD;\n  s : STRING;\n  t : TIME;\nEND_VAR\n  \
               w := TO_BIG_ENDIAN(s);\n  t := FROM_LITTLE_ENDIAN(t);\nEND_PROGRAM\n";
    assert_eq!(
        common::rejected_heads("types.st", src),
        [
            "types.st:7:8: error[E1004]: TO_BIG_ENDIAN is not defined for STRING",
            "types.st:8:8: error[E1004]: FROM_LITTLE_ENDIAN is not defined for TIME",
        ]
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
