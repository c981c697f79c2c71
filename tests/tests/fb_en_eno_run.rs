//! EN and ENO on function block instances (issue #13), through `ladderc run`, cycle by cycle: the ST
//! call `t1(EN := x, IN := ..., PT := ..., ENO => ok)` and the read `t1.ENO`, the IL
//! `CAL c1(EN := ..., ...)`, and the LD form (a TON box with its EN pin wired in a rung and ENO driving
//! a coil, how real LD exports call timers and counters). IEC 61131-3: with EN FALSE the instance's
//! body is not executed and ENO is FALSE; its outputs keep their values (a timer's ET freezes, a
//! counter misses the edges). Before, the ST/IL forms generated C that did not compile (`no member
//! named EN`) and `t1.ENO` was E1011.

mod common;
use common::ladderc;

use std::path::Path;

/// EN is TRUE in cycles 0-1, FALSE in 2-3, TRUE again from 4.
const STIMULUS: &str = "cycle,variable,value\n0,main.en_in,1\n2,main.en_in,0\n4,main.en_in,1\n";

fn run(file: &Path, cycles: &str, watch: &str) -> String {
    let dir = file.parent().unwrap();
    let stim = dir.join("stim.csv");
    std::fs::write(&stim, STIMULUS).unwrap();
    let trace = dir.join("t.csv");
    let out = ladderc()
        .arg("run")
        .arg(file)
        .args(["--cycles", cycles, "--sanitize", "--stimulus"])
        .arg(&stim)
        .arg("--trace")
        .arg(&trace)
        .args(["--watch", watch])
        .output()
        .unwrap();
    common::assert_ok(&out);
    std::fs::read_to_string(&trace).unwrap()
}

#[test]
fn st_timer_with_en_freezes_and_eno_follows_en() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("t.st");
    std::fs::write(
        &file,
        "PROGRAM main\nVAR\n  en_in : BOOL;\n  go : BOOL := TRUE;\n  t1 : TON;\n  q : BOOL;\n  \
         ok : BOOL;\n  eno2 : BOOL;\n  e : TIME;\nEND_VAR\n  \
         t1(EN := en_in, IN := go, PT := T#30ms, Q => q, ET => e, ENO => ok);\n  \
         eno2 := t1.ENO;\nEND_PROGRAM\n",
    )
    .unwrap();
    // cycles 2-3: not executed, ET frozen at 10 ms, ENO FALSE; cycle 4: executed again, the timer
    // (started at 0 ms, IN still TRUE) has elapsed: Q TRUE, ET = PT
    assert_eq!(
        run(
            &file,
            "6",
            "main.en_in,main.t1.ET,main.t1.Q,main.q,main.e,main.ok,main.eno2"
        ),
        "cycle,time_ms,main.en_in,main.t1.ET,main.t1.Q,main.q,main.e,main.ok,main.eno2\n\
         0,0,1,T#0ms,0,0,T#0ms,1,1\n\
         1,10,1,T#10ms,0,0,T#10ms,1,1\n\
         2,20,0,T#10ms,0,0,T#10ms,0,0\n\
         3,30,0,T#10ms,0,0,T#10ms,0,0\n\
         4,40,1,T#30ms,1,1,T#30ms,1,1\n\
         5,50,1,T#30ms,1,1,T#30ms,1,1\n"
    );
}

#[test]
fn il_counter_with_en_misses_the_edges_while_disabled() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("c.il");
    std::fs::write(
        &file,
        "PROGRAM main\nVAR\n  en_in : BOOL;\n  pulse : BOOL;\n  c1 : CTU;\n  cv : INT;\n  \
         eno : BOOL;\n  was : BOOL;\nEND_VAR\n    \
         CAL c1(EN := en_in, CU := pulse, PV := 3, CV => cv, ENO => eno)\n    \
         LD c1.ENO\n    ST was\n    LDN pulse\n    ST pulse\nEND_PROGRAM\n",
    )
    .unwrap();
    // pulse (shown after the cycle) rises before cycles 1, 3, 5, 7; the rise seen in cycle 3 is
    // missed (EN FALSE, the edge memory is not updated either), so CV counts in 1, 5 and 7 only
    assert_eq!(
        run(
            &file,
            "8",
            "main.en_in,main.pulse,main.cv,main.eno,main.was"
        ),
        "cycle,time_ms,main.en_in,main.pulse,main.cv,main.eno,main.was\n\
         0,0,1,1,0,1,1\n\
         1,10,1,0,1,1,1\n\
         2,20,0,1,1,0,0\n\
         3,30,0,0,1,0,0\n\
         4,40,1,1,1,1,1\n\
         5,50,1,0,2,1,1\n\
         6,60,1,1,2,1,1\n\
         7,70,1,0,3,1,1\n"
    );
}

#[test]
fn ld_timer_box_with_en_and_eno_pins() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/en_eno/ld_ton_en.xml");
    let dir = tempfile::tempdir().unwrap();
    let copy = dir.path().join("ld_ton_en.xml");
    std::fs::copy(&file, &copy).unwrap();
    // the rung: en_in -> TON t1 (IN := go, PT := T#30ms), ENO -> coil ok, Q -> coil q, ET -> e; a
    // second rung reads t1.ENO into last_eno
    assert_eq!(
        run(
            &copy,
            "6",
            "main.en_in,main.t1.ET,main.t1.Q,main.ok,main.q,main.e,main.last_eno"
        ),
        "cycle,time_ms,main.en_in,main.t1.ET,main.t1.Q,main.ok,main.q,main.e,main.last_eno\n\
         0,0,1,T#0ms,0,1,0,T#0ms,1\n\
         1,10,1,T#10ms,0,1,0,T#10ms,1\n\
         2,20,0,T#10ms,0,0,0,T#10ms,0\n\
         3,30,0,T#10ms,0,0,0,T#10ms,0\n\
         4,40,1,T#30ms,1,1,1,T#30ms,1\n\
         5,50,1,T#30ms,1,1,1,T#30ms,1\n"
    );
}

#[test]
fn user_fb_with_en_is_skipped_and_its_eno_is_kept() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("u.st");
    let src =
        "FUNCTION_BLOCK Cnt\nVAR_OUTPUT n : INT; END_VAR\n  n := n + 1;\nEND_FUNCTION_BLOCK\n\
               PROGRAM main\nVAR\n  en_in : BOOL;\n  f : Cnt;\n  n : INT;\nEND_VAR\n  \
               f(EN := en_in, n => n);\nEND_PROGRAM\n";
    std::fs::write(&file, src).unwrap();
    assert_eq!(
        run(&file, "6", "main.en_in,main.n"),
        "cycle,time_ms,main.en_in,main.n\n0,0,1,1\n1,10,1,2\n2,20,0,2\n3,30,0,2\n4,40,1,3\n5,50,1,4\n"
    );
    // the instance keeps its ENO (issue #13, acceptance run 3): `ENO => ok` is TRUE when the body
    // ran, FALSE when EN was FALSE
    std::fs::write(
        &file,
        src.replace("n => n);", "n => n, ENO => ok);")
            .replace("  n : INT;\n", "  n : INT;\n  ok : BOOL;\n"),
    )
    .unwrap();
    assert_eq!(
        run(&file, "6", "main.en_in,main.n,main.ok"),
        "cycle,time_ms,main.en_in,main.n,main.ok\n0,0,1,1,1\n1,10,1,2,1\n2,20,0,2,0\n3,30,0,2,0\n\
         4,40,1,3,1\n5,50,1,4,1\n"
    );
}
