//! Gaps found on real projects (issue #13), each closed end to end through `ladderc run`: actions
//! called from other POUs, global variable lists sharing member names, trace columns of qualified
//! globals and `--trace -`, SFC indicator variables, overlapping CASE labels, integer division of
//! integer literals, and names the standard reserves.

mod common;
use common::{check_text, ladderc, run_traced as run};

use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/real_gaps")
        .join(name)
}

// ------------------------------------------------------------------ 1. actions called from outside

#[test]
fn actions_of_fb_instances_run_once_per_call_from_st_and_il() {
    // main calls c.Reset() in cycle 2 (n = 3), after c(step := 2): the count drops to 0 and the next
    // call adds 2 again; cs[2].Bump() twice a cycle (the second with step := 7 passed as in a call of
    // the instance) adds 100 and counts 1 each time: the body never runs for cs[2]; il_side's
    // CALC d.Reset resets d once its count reaches 3
    let (trace, _) = run(
        &fixture("actions.st"),
        5,
        "main.c.count,main.cs[2].count,main.cs[2].calls,main.cs[2].step,il_side.d.count",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,main.c.count,main.cs[2].count,main.cs[2].calls,main.cs[2].step,il_side.d.count\n\
         0,0,2,200,2,7,1\n\
         1,10,4,400,4,7,2\n\
         2,20,0,600,6,7,0\n\
         3,30,2,800,8,7,1\n\
         4,40,4,1000,10,7,2\n"
    );
}

#[test]
fn codesys_fb_actions_run_from_st_and_il_bodies() {
    // FB_Tank adds rIn to rLevel; its ST action Drain halves rLevel. PLC_PRG drains every second
    // cycle; PRG_IL calls the instance with 8.0 and then `CAL fbTank.Drain(rIn := 0.0)`.
    let (trace, stderr) = run(
        &fixture("fb_actions.xml"),
        4,
        "PLC_PRG.fbTank.rLevel,PRG_IL.fbTank.rLevel,PRG_IL.fbTank.rIn",
    );
    assert!(!stderr.contains("W3401"), "{stderr}");
    assert_eq!(
        trace,
        "cycle,time_ms,PLC_PRG.fbTank.rLevel,PRG_IL.fbTank.rLevel,PRG_IL.fbTank.rIn\n\
         0,0,4,4,0\n\
         1,10,4,6,0\n\
         2,20,8,7,0\n\
         3,30,6,7.5,0\n"
    );
}

#[test]
fn il_ld_and_fbd_actions_of_a_codesys_export_run_where_they_are_called() {
    // FB_Counter's ST body calls its IL action Inc (RETC when step = 0: leaves the action, not the
    // body) and its LD action Edge (rising-edge contact, a detector of the action's own); PLC_PRG
    // calls the FBD action fb.Scale() from outside (scaled = total * 10) with step 0 in cycle 2;
    // PRG_IL (IL body) calls `CAL fb2.Inc(step := 5)` (only the action runs: fb2.n stays 0) and its
    // own LD action Blink with `CALC Blink` once k > 2. Its SFC action (an empty chart, never
    // called) compiles too since actions with SFC bodies do (`unseen_projects_r6.rs`).
    let (trace, stderr) = run(
        &fixture("il_ld_fbd_actions.xml"),
        4,
        "PLC_PRG.fb.n,PLC_PRG.fb.total,PLC_PRG.fb.lamp,PLC_PRG.fb.rises,PLC_PRG.fb.scaled,\
         PRG_IL.fb2.total,PRG_IL.fb2.n,PRG_IL.k,PRG_IL.led",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,PLC_PRG.fb.n,PLC_PRG.fb.total,PLC_PRG.fb.lamp,PLC_PRG.fb.rises,\
         PLC_PRG.fb.scaled,PRG_IL.fb2.total,PRG_IL.fb2.n,PRG_IL.k,PRG_IL.led\n\
         0,0,1,2,1,1,20,5,0,1,0\n\
         1,10,2,4,0,1,40,10,0,2,0\n\
         2,20,3,4,1,2,40,15,0,3,1\n\
         3,30,4,6,0,2,60,20,0,4,0\n"
    );
    assert!(!stderr.contains("W3401"), "{stderr}");
}

#[test]
fn an_il_action_that_calls_itself_is_one_located_error() {
    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <types><pous>
    <pou name="P" pouType="program">
      <interface><localVars><variable name="x"><type><INT /></type></variable></localVars></interface>
      <actions><action name="Loop"><body><IL><xhtml xmlns="http://www.w3.org/1999/xhtml">LD x
ADD 1
ST x
CAL Loop</xhtml></IL></body></action></actions>
      <body><IL><xhtml xmlns="http://www.w3.org/1999/xhtml">CAL Loop</xhtml></IL></body>
    </pou>
  </pous></types>
</project>"#;
    let (code, lines) = check_text("loop.xml", xml);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("loop.xml:9:1: error[E0106]: action `Loop` calls itself"),
        "{lines:?}"
    );
}

#[test]
fn an_action_calling_an_action_of_another_instance_runs_it_once() {
    // main calls p.Press() once a cycle; Press counts and calls l.Switch() on Panel's Lamp, which
    // toggles `lit`; the Lamp's body (p's own call l()) counts n once a cycle
    let (trace, _) = run(
        &fixture("action_chain.st"),
        3,
        "main.p.presses,main.p.l.lit,main.p.l.n",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,main.p.presses,main.p.l.lit,main.p.l.n\n\
         0,0,1,1,1\n\
         1,10,2,0,2\n\
         2,20,3,1,3\n"
    );
}

#[test]
fn an_action_of_a_program_runs_on_its_one_instance_when_called_from_another_program() {
    // programs run in source order, each as its one implicit instance: Other calls
    // PLC_PRG.Reset() when n is a multiple of 3, IlSide `CALC PLC_PRG.Reset` when k = 5; the action
    // runs at once on PLC_PRG's state (count back to 0, resets counted)
    let (trace, _) = run(
        &fixture("program_actions.st"),
        6,
        "PLC_PRG.count,PLC_PRG.resets,Other.n,IlSide.k",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,PLC_PRG.count,PLC_PRG.resets,Other.n,IlSide.k\n\
         0,0,1,0,1,1\n\
         1,10,2,0,2,2\n\
         2,20,0,1,3,3\n\
         3,30,1,1,4,4\n\
         4,40,0,2,5,5\n\
         5,50,0,3,6,6\n"
    );
}

#[test]
fn a_program_action_call_is_a_located_error_when_the_program_has_several_instances() {
    let src = "PROGRAM counter\nVAR n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n\
               ACTIONS\nACTION Reset:\nn := 0;\nEND_ACTION\nEND_ACTIONS\n\
               PROGRAM other\ncounter.Reset();\nEND_PROGRAM\n\
               CONFIGURATION Cfg\nRESOURCE Res ON PLC\nTASK Main(INTERVAL := T#10ms, PRIORITY := 1);\n";
    let tail = "PROGRAM O WITH Main : other;\nEND_RESOURCE\nEND_CONFIGURATION\n";
    // (a program that the configuration does not instantiate has, since issue #13's eleventh
    // round, an instance of its own that only such calls run: `tests/tests/lang_left_r11.rs`)
    let instances = "PROGRAM A WITH Main : counter;\nPROGRAM B WITH Main : counter;\n";
    let (code, lines) = check_text("p.st", &format!("{src}{instances}{tail}"));
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        lines,
        vec![
            "p.st:11:1: error[E3135]: action `Reset` of program `counter` cannot be called \
             here: program `counter` has 2 instances (`A`, `B`): the call does not say which one \
             (hint: call it from `counter` itself (`Reset();`), or give the program one instance)"
        ]
    );
    // with one instance the call runs on it (named by the instance in the trace): A counts, O
    // resets it in its second cycle (A runs first: declared first in the task)
    let one = format!("{src}PROGRAM A WITH Main : counter;\n{tail}").replace(
        "PROGRAM other\ncounter.Reset();",
        "PROGRAM other\nVAR m : INT; END_VAR\nm := m + 1;\nIF m = 2 THEN counter.Reset(); END_IF",
    );
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("one.st");
    std::fs::write(&f, one).unwrap();
    let (trace, _) = run(&f, 4, "A.n,O.m");
    assert_eq!(
        trace,
        "cycle,time_ms,A.n,O.m\n0,0,1,1\n1,10,0,2\n2,20,1,3\n3,30,2,4\n"
    );
}

// ------------------------------------------------------------------ 3. trace columns, `--trace -`

#[test]
fn trace_dash_writes_the_csv_to_standard_output_and_no_file() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(fixture("actions.st"), dir.path().join("a.st")).unwrap();
    let out = ladderc()
        .current_dir(dir.path())
        .args([
            "run", "a.st", "--cycles", "2", "--trace", "-", "--watch", "main.n",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "cycle,time_ms,main.n\n0,0,1\n1,10,2\n"
    );
    assert!(
        !dir.path().join("-").exists(),
        "a file named `-` was written"
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("ran 2 cycles"), "{stderr}");
    assert!(!stderr.contains("wrote"), "{stderr}");
}

// ------------------------------------------------------------------ 2. lists sharing member names

#[test]
fn two_global_lists_with_the_same_member_names_run_qualified() {
    // GVL_A and GVL_B (resource lists) both declare iSpeed and xOn, GVL_C (a project list) iSpeed:
    // three variables, each counted on its own; the trace names them by list, with and without
    // --watch
    let file = fixture("shared_gvl.xml");
    let (trace, _) = run(
        &file,
        3,
        "GVL_A.iSpeed,GVL_B.iSpeed,GVL_C.iSpeed,GVL_A.xOn,GVL_B.xOn,PRG_IL.iSum",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,GVL_A.iSpeed,GVL_B.iSpeed,GVL_C.iSpeed,GVL_A.xOn,GVL_B.xOn,PRG_IL.iSum\n\
         0,0,1,110,111,0,1,109\n\
         1,10,2,120,122,1,0,118\n\
         2,20,3,130,133,1,0,127\n"
    );
    let out = ladderc()
        .arg("run")
        .arg(&file)
        .args(["--cycles", "1", "--trace", "-"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(
        String::from_utf8_lossy(&out.stdout).lines().next(),
        Some(
            "cycle,time_ms,GVL_C.iSpeed,GVL_A.iSpeed,GVL_A.xOn,GVL_B.iSpeed,GVL_B.xOn,PRG_IL.iSum"
        )
    );
}

#[test]
fn an_unqualified_use_of_a_shared_list_member_is_one_located_error_naming_the_lists() {
    let src = std::fs::read_to_string(fixture("shared_gvl.xml")).unwrap();
    let cases = [
        (
            "GVL_A.iSpeed := GVL_A.iSpeed + 1;",
            "iSpeed := 1;",
            "q.xml:12:63: error[E1030]: `iSpeed` is declared by the global variable lists `GVL_C`, \
             `GVL_A` and `GVL_B` [POU `PLC_PRG`] (hint: write GVL_C.iSpeed (or the other list's name))",
        ),
        (
            "SUB GVL_A.iSpeed",
            "SUB xOn",
            "q.xml:21:5: error[E1030]: `xOn` is declared by the global variable lists `GVL_A` and \
             `GVL_B` [POU `PRG_IL`] (hint: write GVL_A.xOn (or the other list's name))",
        ),
    ];
    for (from, to, want) in cases {
        assert_eq!(src.matches(from).count(), 1, "{from}");
        let (code, lines) = check_text("q.xml", &src.replace(from, to));
        let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
        assert_eq!(code, Some(1), "{lines:?}");
        assert_eq!(errors, vec![want], "{lines:?}");
    }
}

// ------------------------------------------------------------------ 4. SFC indicator variables

#[test]
fn textual_sfc_indicator_variables_are_set_by_the_action_never_by_the_chart() {
    // IEC 61131-3: an indicator variable shows the action's completion, set by the action's own
    // logic. Run is active in cycles 2-4 and 6-8; Tick(N, done) sets `done` once n >= 30 (cycle 4)
    // and nothing resets it; the boolean action valve(L, T#20ms, draining) never writes its
    // indicator `draining`, which stays FALSE. Driven from Q, `done` would be 0,0,1,1,0,0,1,1,0.
    let (trace, _) = run(
        &fixture("indicators.st"),
        9,
        "Fill.n,Fill.__sfc_X_Run,Fill.done,Fill.valve,Fill.draining",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Fill.n,Fill.__sfc_X_Run,Fill.done,Fill.valve,Fill.draining\n\
         0,0,1,0,0,0,0\n\
         1,10,2,0,0,0,0\n\
         2,20,13,1,0,1,0\n\
         3,30,23,1,0,1,0\n\
         4,40,33,1,1,0,0\n\
         5,50,44,0,1,0,0\n\
         6,60,55,1,1,1,0\n\
         7,70,65,1,1,1,0\n\
         8,80,75,1,1,0,0\n"
    );
}

#[test]
fn plcopen_action_indicator_attribute_is_checked_and_left_to_the_action() {
    // tests/fixtures/sfc/actions.xml with an indicator on two associations: `lim_on` on the L T#30ms
    // boolean action `limited`, `pulse_on` on the P action `Pulse` (active for one scan)
    let src = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/sfc/actions.xml"),
    )
    .unwrap();
    let edits = [
        (
            "<variable name=\"go\"><type><BOOL/></type></variable>",
            "<variable name=\"go\"><type><BOOL/></type></variable>\
             <variable name=\"lim_on\"><type><BOOL/></type></variable>\
             <variable name=\"pulse_on\"><type><BOOL/></type></variable>",
        ),
        (
            "qualifier=\"L\" duration=\"T#30ms\">",
            "qualifier=\"L\" duration=\"T#30ms\" indicator=\"lim_on\">",
        ),
        (
            "qualifier=\"P\"><relPosition x=\"0\" y=\"0\"/><reference name=\"Pulse\"/>",
            "qualifier=\"P\" indicator=\"pulse_on\"><relPosition x=\"0\" y=\"0\"/><reference name=\"Pulse\"/>",
        ),
    ];
    let mut text = src.clone();
    for (from, to) in edits {
        assert_eq!(text.matches(from).count(), 1, "{from}");
        text = text.replace(from, to);
    }
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("ind.xml");
    std::fs::write(&f, &text).unwrap();
    let trace = common::run_with_stimulus(
        &f,
        6,
        "1,main.go,1\n2,main.go,0\n",
        &[
            "main.limited",
            "main.lim_on",
            "main.pulse_on",
            "main.p_count",
        ],
    );
    // the actions are active (limited is TRUE for 30 ms) but no action body writes its
    // indicator: the chart does not drive them
    assert_eq!(
        common::column(&trace, "main.limited"),
        [0.0, 1.0, 1.0, 1.0, 0.0, 0.0]
    );
    assert_eq!(common::column(&trace, "main.lim_on"), [0.0; 6]);
    assert_eq!(common::column(&trace, "main.pulse_on"), [0.0; 6]);
    // an indicator that is not a BOOL variable is a located error
    let (code, lines) = check_text(
        "bad.xml",
        &text.replace("indicator=\"lim_on\"", "indicator=\"p_count\""),
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines.iter().any(|l| l.contains("error[E3122]: indicator `p_count` of an action of step `S1` is not a declared BOOL variable")),
        "{lines:?}"
    );
}

// ------------------------------------------------------------------ 5. overlapping CASE labels

#[test]
fn overlapping_case_labels_warn_with_both_locations_and_the_first_label_wins() {
    let file = fixture("case_overlap.st");
    // x counts 1, 2, ...: 2 is in `1..3` (a = 10), not `2:` (20); 6 is in `5..6` (40), not `6..9`;
    // c = green matches `red, green` (b = 1), not `Color#green` (2)
    let (trace, _) = run(&file, 8, "main.x,main.a,main.b");
    assert_eq!(
        trace,
        "cycle,time_ms,main.x,main.a,main.b\n\
         0,0,1,10,1\n\
         1,10,2,10,1\n\
         2,20,3,10,1\n\
         3,30,4,40,1\n\
         4,40,5,40,1\n\
         5,50,6,40,1\n\
         6,60,7,60,1\n\
         7,70,8,60,1\n"
    );
    let out = ladderc()
        .args(["--message-format", "json", "check"])
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    // (line, column) of each W3140 and of its second location
    let found: Vec<((u64, u64), (u64, u64))> = String::from_utf8_lossy(&out.stderr)
        .lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap())
        .filter(|d| d["code"] == "W3140")
        .map(|d| {
            let at = |v: &serde_json::Value| {
                (v["line"].as_u64().unwrap(), v["column"].as_u64().unwrap())
            };
            let labels = d["labels"].as_array().unwrap();
            let other = labels
                .iter()
                .find(|l| l["line"] != d["line"] || l["column"] != d["column"])
                .unwrap();
            (at(&d), at(other))
        })
        .collect();
    assert_eq!(
        found,
        vec![((7, 3), (6, 3)), ((9, 3), (8, 6)), ((16, 3), (15, 8))],
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

// ------------------------------------------------------------------ 6. integer literals divide as integers

#[test]
fn integer_literals_divide_as_integers_even_into_a_real() {
    // ST: `r := 7 / 2` is 3 (was 3.5), a REAL literal makes it a real division, `1.5 + 7 / 2` is
    // 4.5, `-7 / 2` truncates toward zero, MOD stays integer
    let (st, _) = run(
        &fixture("int_division.st"),
        1,
        "main.r,main.q,main.m,main.l,main.x,main.i",
    );
    assert_eq!(
        st,
        "cycle,time_ms,main.r,main.q,main.m,main.l,main.x,main.i\n0,0,3,3.5,4.5,-3,3,3\n"
    );
    // IL: `LD 7` / `DIV 2` / `ST r` likewise
    let (il, _) = run(
        &fixture("int_division.il"),
        1,
        "main.r,main.q,main.l,main.i,main.s",
    );
    assert_eq!(
        il,
        "cycle,time_ms,main.r,main.q,main.l,main.i,main.s\n0,0,3,3.5,-3,3,1\n"
    );
}

// ------------------------------------------------------------------ 7. reserved names

#[test]
fn reserved_names_are_one_located_error_and_the_names_real_projects_use_run() {
    // what the standard reserves and matiec rejects: one error at the declaration, in ST and IL
    for (name, why) in [
        ("TON", "a standard function block"),
        ("TIME", "an elementary data type"),
        ("STRING", "an elementary data type"),
        ("IF", "a keyword"),
        ("MOD", "a keyword"),
        ("TRUE", "a keyword"),
    ] {
        let want = format!(
            "error[E1031]: `{name}` is reserved in IEC 61131-3 ({why}): it cannot name a variable \
             (hint: rename the variable, for example `x{name}`)"
        );
        let st = format!(
            "PROGRAM main\nVAR {name} : BOOL; y : BOOL; END_VAR\ny := NOT y;\nEND_PROGRAM\n"
        );
        let (code, lines) = check_text("r.st", &st);
        assert_eq!(code, Some(1), "{name}: {lines:?}");
        assert_eq!(lines, vec![format!("r.st:2:5: {want}")], "{name}");
        let il = format!(
            "PROGRAM main\nVAR {name} : BOOL; y : BOOL; END_VAR\nLD y\nSTN y\nEND_PROGRAM\n"
        );
        let (code, lines) = check_text("r.il", &il);
        assert_eq!(code, Some(1), "{name}: {lines:?}");
        assert_eq!(lines, vec![format!("r.il:2:5: {want}")], "{name}");
    }
    // a keyword used in the ST body too: still the one error at the declaration, no cascade
    let (code, lines) = check_text(
        "k.st",
        "PROGRAM main\nVAR IF : BOOL; y : BOOL; END_VAR\ny := IF;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(lines[0].starts_with("k.st:2:5: error[E1031]"), "{lines:?}");
    // ... and used in IL or ST bodies (read, written, as an operand of AND): the keywords the lexer
    // reads as keywords, including the VAR-block qualifiers, give the one E1031 at the declaration,
    // never a syntax error at each use (ON, WITH and TASK name variables, with W1418:
    // tests/tests/lang_left_r12.rs)
    for name in [
        "OF",
        "BY",
        "DO",
        "TO",
        "AT",
        "TRUE",
        "FALSE",
        "RETAIN",
        "CONSTANT",
        "NON_RETAIN",
    ] {
        let want = format!("error[E1031]: `{name}` is reserved in IEC 61131-3 (a keyword)");
        let il = format!(
            "PROGRAM main\nVAR\n  {name} : BOOL;\n  x : BOOL;\nEND_VAR\nLD {name}\nST x\nANDN {name}\nST {name}\nEND_PROGRAM\n"
        );
        let (code, lines) = check_text("u.il", &il);
        assert_eq!(code, Some(1), "{name}: {lines:?}");
        assert_eq!(lines.len(), 1, "{name}: {lines:?}");
        assert!(
            lines[0].starts_with(&format!("u.il:3:3: {want}")),
            "{lines:?}"
        );
        let st = format!(
            "PROGRAM main\nVAR\n  {name} : BOOL;\n  x : BOOL;\nEND_VAR\n{name} := TRUE;\nx := {name} AND x;\nEND_PROGRAM\n"
        );
        let (code, lines) = check_text("u.st", &st);
        assert_eq!(code, Some(1), "{name}: {lines:?}");
        assert_eq!(lines.len(), 1, "{name}: {lines:?}");
        assert!(
            lines[0].starts_with(&format!("u.st:3:3: {want}")),
            "{lines:?}"
        );
    }
    // accepted: IL operator names (Beremiz's traffic light names variables S and R), standard
    // block parameters (IN, Q, PT, CU) and standard function names (a CODESYS project's LEN)
    let (out, _) = run(
        &fixture("accepted_names.st"),
        3,
        "main.S,main.R,main.IN,main.Q,main.PT,main.LEN,main.LD",
    );
    assert_eq!(
        out,
        "cycle,time_ms,main.S,main.R,main.IN,main.Q,main.PT,main.LEN,main.LD\n\
         0,0,1,0,1,1,T#10ms,1,1\n\
         1,10,0,1,0,0,T#20ms,2,0\n\
         2,20,1,0,1,1,T#30ms,3,1\n"
    );
}

// ------------------------------------------------------------------ BCD conversions

#[test]
fn bcd_conversions_have_the_standard_widths_and_documented_results() {
    // IEC 61131-3 (3rd ed., BCD conversions): the typed forms USINT_TO_BCD_BYTE, UINT_TO_BCD_WORD,
    // UDINT_TO_BCD_DWORD, ULINT_TO_BCD_LWORD and back (*_BCD_TO_*), the overloaded BCD_TO_INT and
    // INT_TO_BCD (WORD: the width of an INT). Documented results (crates/c-backend/README.md): an
    // invalid digit (16#12A4), a negative value, and a value with more digits than the bit string
    // holds give 0 (and the range flag the run reports)
    let (trace, stderr) = run(
        &fixture("bcd.st"),
        1,
        "main.b,main.w,main.d,main.l,main.us,main.ui,main.ud,main.ul,main.i,main.bad,main.neg,\
         main.big,main.ov",
    );
    assert_eq!(
        trace,
        format!(
            "cycle,time_ms,main.b,main.w,main.d,main.l,main.us,main.ui,main.ud,main.ul,main.i,\
             main.bad,main.neg,main.big,main.ov\n0,0,{},{},{},{},99,9876,12345678,1234567890123456,\
             321,0,0,0,0\n",
            0x45, 0x1234, 0x1234_5678, 0x1234_5678_9012_3456u64
        )
    );
    assert!(stderr.contains("conversion out of range"), "{stderr}");
    // INT_TO_BCD gives a WORD: stored into a BYTE it is the one error of any WORD into a BYTE
    let (code, lines) = check_text(
        "n.st",
        "PROGRAM main\nVAR b : BYTE; END_VAR\nb := INT_TO_BCD(12);\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("n.st:3:1: error[E1006]: cannot store WORD into BYTE"),
        "{lines:?}"
    );
}

// ------------------------------------------------------------------ methods (edition 3)

#[test]
fn methods_of_a_function_block_run_from_statements_and_expressions() {
    // Counter's body adds step; its method Add (VAR_INPUT n, VAR tmp, result INT) adds n * step,
    // returns the new value, or -1 through RETURN when n * step = 0; Reset sets value to 0.
    // main: r := c.Add(10) * 2 (the call runs before the statement reads its result), IF
    // c.Add(0) < 0 counts z (Add returned early), c.Reset() in cycle 3 (k = 3)
    let (trace, _) = run(
        &fixture("methods.st"),
        4,
        "main.c.value,main.k,main.r,main.z",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,main.c.value,main.k,main.r,main.z\n\
         0,0,11,1,22,1\n\
         1,10,22,2,44,2\n\
         2,20,0,3,66,3\n\
         3,30,11,4,22,4\n"
    );
}

#[test]
fn method_calls_that_cannot_run_before_their_statement_are_one_located_error_each() {
    let fb = "FUNCTION_BLOCK Counter\nVAR_OUTPUT value : INT; END_VAR\n\
              METHOD Add : INT\nVAR_INPUT n : INT; END_VAR\nvalue := value + n;\nAdd := value;\nEND_METHOD\n\
              METHOD Clear\nvalue := 0;\nEND_METHOD\n\
              END_FUNCTION_BLOCK\n";
    for (stmt, want) in [
        // (`c.Add(1) + c.Add(2)` and `WHILE c.Add(1) < 5` were E0108: they run since Struckig's
        // round, `tests/tests/struckig_constructs_run.rs`)
        (
            "r := c.Clear();",
            "m.st:14:8: error[E1011]: method `CLEAR` of Counter returns no value",
        ),
        (
            "r := c.Sub(1);",
            "m.st:14:8: error[E1011]: Counter has no input or output `Sub` (hint: parameters of Counter: value)",
        ),
    ] {
        let src = format!("{fb}PROGRAM main\nVAR c : Counter; r : INT; END_VAR\n{stmt}\nEND_PROGRAM\n");
        let (code, lines) = check_text("m.st", &src);
        assert_eq!(code, Some(1), "{stmt}: {lines:?}");
        assert_eq!(lines.len(), 1, "{stmt}: {lines:?}");
        assert!(lines[0].starts_with(want), "{stmt}: {lines:?}");
    }
}

#[test]
fn codesys_methods_in_vendor_data_run_and_a_property_without_accessors_is_one_located_error() {
    // FB_Axis adds rVelocity every call; its method M_MoveBy (CODESYS: addData .../method, with
    // returnType, inputVars, outputVars and a localVars rLimit initialised to 100.0 at each call)
    // moves by rDistance unless the target passes rLimit (then FALSE through RETURN, rTarget
    // still set); M_Home zeroes the position (in cycle 2). PRG_IL calls `CAL fbAxis.M_MoveBy(5.0)`
    // only: its instance's body never runs.
    let (trace, _) = run(
        &fixture("xml_methods.xml"),
        5,
        "PLC_PRG.fbAxis.rPosition,PLC_PRG.xOk,PLC_PRG.rLast,PRG_IL.fbAxis.rPosition",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,PLC_PRG.fbAxis.rPosition,PLC_PRG.xOk,PLC_PRG.rLast,PRG_IL.fbAxis.rPosition\n\
         0,0,41,1,41,5\n\
         1,10,82,1,82,10\n\
         2,20,0,0,123,15\n\
         3,30,41,1,41,20\n\
         4,40,82,1,82,25\n"
    );
    let src = std::fs::read_to_string(fixture("xml_methods.xml")).unwrap().replace(
        "<data name=\"http://www.3s-software.com/plcopenxml/method\" handleUnknown=\"implementation\">\n            <Method name=\"M_Home\"",
        "<data name=\"http://www.3s-software.com/plcopenxml/property\" handleUnknown=\"implementation\">\n            <Property name=\"P_Home\"",
    ).replace("</Method>\n          </data>\n        </addData>", "</Property>\n          </data>\n        </addData>");
    let (code, lines) = check_text("p.xml", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        lines.iter().filter(|l| l.contains("error[")).count(),
        1,
        "{lines:?}"
    );
    assert!(
        lines.iter().any(|l| l.starts_with(
            "p.xml:42:13: error[E0303]: `FB_Axis`: PROPERTY `P_Home` is not compiled: the property has no Get or Set accessor"
        )),
        "{lines:?}"
    );
}
