//! SFC charts end to end: PLCopen XML with an SFC body, lowered, compiled to C, run cycle by cycle by
//! `ladderc run`; the traces are checked at the exact cycle each step or action changes.

mod common;

use std::collections::HashMap;
use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/sfc")
        .join(name)
}

/// Runs `file` for `cycles` scans of 10 ms with `stimulus`; returns the trace text.
fn run(file: &Path, cycles: u32, stimulus: &str, watch: &[&str]) -> String {
    common::run_with_stimulus(file, cycles, stimulus, watch)
}

/// The trace as columns: name -> one value per cycle.
fn columns(trace: &str) -> HashMap<String, Vec<String>> {
    let mut lines = trace.lines();
    let names: Vec<String> = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_string)
        .collect();
    let mut cols: HashMap<String, Vec<String>> =
        names.iter().map(|n| (n.clone(), vec![])).collect();
    for l in lines {
        for (n, v) in names.iter().zip(l.split(',')) {
            cols.get_mut(n).unwrap().push(v.to_string());
        }
    }
    cols
}

/// The cycles at which a BOOL column is 1.
fn on(cols: &HashMap<String, Vec<String>>, name: &str) -> Vec<usize> {
    cols[name]
        .iter()
        .enumerate()
        .filter(|(_, v)| v.as_str() == "1")
        .map(|(i, _)| i)
        .collect()
}

const STEPS: &[&str] = &[
    "main.__sfc_X_Init",
    "main.__sfc_X_Choose",
    "main.__sfc_X_A",
    "main.__sfc_X_B",
    "main.__sfc_X_C",
    "main.__sfc_X_P1",
    "main.__sfc_X_P2",
    "main.__sfc_X_P1b",
];

#[test]
fn explicit_priority_beats_the_drawing_order_at_a_selection_divergence() {
    // a, b and c are all TRUE when Choose is active: C has priority="1", so it wins over A (left-most).
    let t = run(
        &fixture("sequence.xml"),
        6,
        "1,main.go,1\n1,main.a,1\n1,main.b,1\n1,main.c,1\n",
        STEPS,
    );
    let c = columns(&t);
    assert_eq!(on(&c, "main.__sfc_X_Init"), [0]);
    assert_eq!(on(&c, "main.__sfc_X_Choose"), [1]);
    assert_eq!(on(&c, "main.__sfc_X_C"), [2, 3, 4, 5]);
    assert!(on(&c, "main.__sfc_X_A").is_empty() && on(&c, "main.__sfc_X_B").is_empty());
    insta::assert_snapshot!(t);
}

#[test]
fn left_most_transition_wins_then_simultaneous_branches_join() {
    // c FALSE: A (x=10) wins over B (x=200). A's transition is TRUE, but the evolution is one step per
    // scan: P1 and P2 start together one scan later. `join` is TRUE all along, yet the convergence
    // waits until P1b and P2 are both active (p1done at cycle 6), then everything returns to Init.
    let t = run(
        &fixture("sequence.xml"),
        10,
        "1,main.go,1\n1,main.a,1\n1,main.b,1\n1,main.join,1\n6,main.p1done,1\n7,main.go,0\n",
        STEPS,
    );
    let c = columns(&t);
    assert_eq!(on(&c, "main.__sfc_X_Choose"), [1]);
    assert_eq!(on(&c, "main.__sfc_X_A"), [2]);
    assert!(on(&c, "main.__sfc_X_B").is_empty());
    assert_eq!(on(&c, "main.__sfc_X_P1"), [3, 4, 5]);
    assert_eq!(on(&c, "main.__sfc_X_P1b"), [6]);
    assert_eq!(on(&c, "main.__sfc_X_P2"), [3, 4, 5, 6]);
    assert_eq!(on(&c, "main.__sfc_X_Init"), [0, 7, 8, 9]);
    insta::assert_snapshot!(t);
}

#[test]
fn action_qualifiers_switch_at_the_exact_cycle() {
    // 10 ms scans. go at cycle 1 activates S1 (cycles 1..7); next at cycle 8 moves to S2, which leaves
    // by `S2.T >= T#40ms` at cycle 12 (activated at 80 ms, 120 ms is 40 ms later) back to S0.
    let watch = [
        "main.__sfc_X_S0",
        "main.__sfc_X_S1",
        "main.__sfc_X_S2",
        "main.__sfc_T_S1",
        "main.idle",
        "main.n_out",
        "main.stored",
        "main.limited",
        "main.delayed",
        "main.sd_out",
        "main.ds_out",
        "main.sl_out",
        "main.p_count",
        "main.p1_count",
        "main.p0_count",
        "main.n_runs",
        "main.s1_t",
    ];
    let t = run(
        &fixture("actions.xml"),
        15,
        "1,main.go,1\n2,main.go,0\n8,main.next,1\n9,main.next,0\n",
        &watch,
    );
    let c = columns(&t);
    assert_eq!(on(&c, "main.__sfc_X_S1"), [1, 2, 3, 4, 5, 6, 7]);
    assert_eq!(on(&c, "main.__sfc_X_S2"), [8, 9, 10, 11]);
    assert_eq!(on(&c, "main.__sfc_X_S0"), [0, 12, 13, 14]);
    // N on a BOOL variable: exactly while S0 / S1 is active.
    assert_eq!(on(&c, "main.idle"), [0, 12, 13, 14]);
    assert_eq!(on(&c, "main.n_out"), [1, 2, 3, 4, 5, 6, 7]);
    // S stays set after S1 until R in S2.
    assert_eq!(on(&c, "main.stored"), [1, 2, 3, 4, 5, 6, 7]);
    // L T#30ms: TRUE for 30 ms from activation (10, 20, 30 ms), FALSE from 40 ms.
    assert_eq!(on(&c, "main.limited"), [1, 2, 3]);
    // D T#20ms: TRUE from 20 ms after activation while the step stays active.
    assert_eq!(on(&c, "main.delayed"), [3, 4, 5, 6, 7]);
    // SD / DS T#20ms: on 20 ms after activation, stored past S1's end until R in S0 (cycle 12).
    assert_eq!(on(&c, "main.sd_out"), (3..=11).collect::<Vec<_>>());
    assert_eq!(on(&c, "main.ds_out"), (3..=11).collect::<Vec<_>>());
    // SL T#30ms: stored and limited to 30 ms.
    assert_eq!(on(&c, "main.sl_out"), [1, 2, 3]);
    // P, P1 and P0 run exactly once (on activation, on activation, on deactivation): no final scan.
    assert_eq!(c["main.p_count"][1], "1");
    assert_eq!(c["main.p_count"][14], "1");
    assert_eq!(c["main.p1_count"][1], "1");
    assert_eq!(c["main.p1_count"][14], "1");
    assert_eq!(c["main.p0_count"][7], "0");
    assert_eq!(c["main.p0_count"][8], "1");
    assert_eq!(c["main.p0_count"][14], "1");
    // N body: 7 active scans plus the final scan at cycle 8; it reads S1.T each time.
    assert_eq!(c["main.n_runs"][7], "7");
    assert_eq!(c["main.n_runs"][8], "8");
    assert_eq!(c["main.n_runs"][14], "8");
    assert_eq!(c["main.s1_t"][1], "T#0ms");
    assert_eq!(c["main.s1_t"][7], "T#60ms");
    assert_eq!(c["main.s1_t"][8], "T#70ms");
    // Step.T keeps its value after the step is left.
    assert_eq!(c["main.__sfc_T_S1"][14], "T#70ms");
    insta::assert_snapshot!(t);
}

#[test]
fn ld_fbd_and_il_conditions_and_actions_run_with_the_final_scan() {
    // A contact network wired to the first transition, an FBD named transition `Done` (count >= 3),
    // an LD action `Run` gated by its own `Run.Q`, an IL action `Count`.
    let t = run(
        &fixture("languages.xml"),
        9,
        "0,main.enable,1\n2,main.start,1\n3,main.start,0\n",
        &[
            "main.__sfc_X_Idle",
            "main.__sfc_X_Work",
            "main.motor",
            "main.count",
        ],
    );
    let c = columns(&t);
    assert_eq!(on(&c, "main.__sfc_X_Work"), [2, 3, 4]);
    // Run's final scan (cycle 5) sees Run.Q = FALSE, so the motor goes off with the step.
    assert_eq!(on(&c, "main.motor"), [2, 3, 4]);
    // Count runs while Work is active and once more in its final scan: 3 then 4.
    assert_eq!(c["main.count"][4], "3");
    assert_eq!(c["main.count"][5], "4");
    assert_eq!(c["main.count"][8], "4");
    insta::assert_snapshot!(t);
}

#[test]
fn corpus_01_runs_and_counter_sfc_tracks_counter_il_as_the_standard_says() {
    // The whole Beremiz "first steps" project (LD, FBD, ST, IL and SFC counters) runs. Its task is
    // T#100ms, so one scan per 100 ms cycle.
    let Some(file) = common::corpus_file("01_beremiz_first_steps.xml") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let p = "plc_task_instance";
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        format!("cycle,variable,value\n4,{p}.Reset,1\n6,{p}.Reset,0\n"),
    )
    .unwrap();
    let trace = dir.path().join("trace.csv");
    let watch: Vec<String> = [
        "Reset",
        "CounterIL0.OUT",
        "CounterSFC0.OUT",
        "CounterST0.OUT",
    ]
    .iter()
    .map(|v| format!("{p}.{v}"))
    .collect();
    let out = common::ladderc()
        .arg("run")
        .arg(&file)
        .args(["--cycles", "10", "--cycle-ms", "100", "--stimulus"])
        .arg(&stim)
        .arg("--trace")
        .arg(&trace)
        .args(["--watch", &watch.join(",")])
        .output()
        .unwrap();
    common::assert_ok(&out);
    let t = std::fs::read_to_string(&trace).unwrap();
    let c = columns(&t);
    let il = &c[&format!("{p}.CounterIL0.OUT")];
    let sfc = &c[&format!("{p}.CounterSFC0.OUT")];
    let st = &c[&format!("{p}.CounterST0.OUT")];
    // ST and IL are the same program.
    assert_eq!(il, st);
    // While Reset stays FALSE from the start, the chart (Start -> Count, Count's N actions) counts
    // exactly like the IL: the first scan fires Start -> Count and runs Count's actions.
    assert_eq!(&il[..4], ["1", "2", "3", "4"]);
    assert_eq!(&sfc[..4], &il[..4]);
    // Reset rises at cycle 4: IL loads ResetCounterValue (17). The chart leaves Count for Start (a
    // step without actions): Count's actions run once more, their final scan, so Cnt + 1 = 5.
    assert_eq!((il[4].as_str(), sfc[4].as_str()), ("17", "5"));
    // Cycle 5: Start -> ResetCounter, whose actions load 17.
    assert_eq!((il[5].as_str(), sfc[5].as_str()), ("17", "17"));
    // Reset falls at cycle 6: IL counts on (18); the chart goes ResetCounter -> Start (final scan of
    // ResetCounter: 17 again), then Start -> Count at cycle 7: one scan is spent in Start, so from
    // then on the chart is one count behind.
    assert_eq!((il[6].as_str(), sfc[6].as_str()), ("18", "17"));
    for k in 7..10 {
        let (i, s): (i32, i32) = (il[k].parse().unwrap(), sfc[k].parse().unwrap());
        assert_eq!(s, i - 1, "cycle {k}");
    }
    insta::assert_snapshot!(t);
}

#[test]
fn st_conditions_and_actions_read_step_flags_and_times() {
    let watch = [
        "main.__sfc_X_Idle",
        "main.__sfc_X_Fill",
        "main.__sfc_X_Drain",
        "main.level",
        "main.pump",
        "main.fills",
    ];
    // Filling by one per scan reaches 5 at cycle 5: Drain from cycle 6. At cycle 6 Fill's inline
    // action runs its final scan (level 6, pump := Fill.X = FALSE), then Drain's action (level 5).
    let t = run(
        &fixture("st_chart.xml"),
        14,
        "1,main.start,1\n2,main.start,0\n",
        &watch,
    );
    let c = columns(&t);
    assert_eq!(on(&c, "main.__sfc_X_Fill"), [1, 2, 3, 4, 5]);
    assert_eq!(on(&c, "main.__sfc_X_Drain"), [6, 7, 8, 9, 10, 11]);
    assert_eq!(on(&c, "main.__sfc_X_Idle"), [0, 12, 13]);
    assert_eq!(on(&c, "main.pump"), [1, 2, 3, 4, 5]);
    let level: Vec<&str> = c["main.level"].iter().map(String::as_str).collect();
    assert_eq!(
        level,
        ["0", "1", "2", "3", "4", "5", "5", "4", "3", "2", "1", "0", "0", "0"]
    );
    // P1: once per activation.
    assert_eq!(c["main.fills"][13], "1");
    insta::assert_snapshot!("st_chart_level", t);

    // From level -10, `Fill.T >= T#100ms` ends the filling: Fill is active from 10 ms, so at the
    // 110 ms scan (cycle 11).
    let t = run(
        &fixture("st_chart.xml"),
        14,
        "0,main.level,-10\n1,main.start,1\n2,main.start,0\n",
        &watch,
    );
    let c = columns(&t);
    assert_eq!(on(&c, "main.__sfc_X_Fill"), (1..=10).collect::<Vec<_>>());
    assert_eq!(on(&c, "main.__sfc_X_Drain"), [11]);
    assert_eq!(on(&c, "main.__sfc_X_Idle"), [0, 12, 13]);
    insta::assert_snapshot!("st_chart_time", t);
}

#[test]
fn a_step_looping_on_itself_restarts_its_time() {
    // Loop -> (Loop.T >= T#30ms) -> jump Loop: re-entered every 30 ms, its T restarts at 0 each time.
    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <types><dataTypes/><pous>
    <pou name="Blink" pouType="program">
      <interface><localVars><variable name="laps"><type><INT/></type></variable></localVars></interface>
      <body><SFC>
        <step localId="1" name="Loop" initialStep="true"/>
        <transition localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
          <condition><inline name=""><IL><xhtml:p><![CDATA[LD Loop.T
GE T#30ms]]></xhtml:p></IL></inline></condition></transition>
        <jumpStep localId="3" targetName="Loop"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></jumpStep>
        <actionBlock localId="4"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
          <action localId="0" qualifier="P1"><inline><IL><xhtml:p><![CDATA[LD laps
ADD 1
ST laps]]></xhtml:p></IL></inline></action></actionBlock>
      </SFC></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="Cfg"><resource name="Res">
    <task name="Main" interval="T#10ms" priority="0"><pouInstance name="main" typeName="Blink"/></task>
  </resource></configuration></configurations></instances>
</project>"#;
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("blink.xml");
    std::fs::write(&file, xml).unwrap();
    let t = run(
        &file,
        8,
        "",
        &["main.__sfc_X_Loop", "main.__sfc_T_Loop", "main.laps"],
    );
    let c = columns(&t);
    let times: Vec<&str> = c["main.__sfc_T_Loop"].iter().map(String::as_str).collect();
    assert_eq!(
        times,
        ["T#0ms", "T#10ms", "T#20ms", "T#0ms", "T#10ms", "T#20ms", "T#0ms", "T#10ms"]
    );
    assert_eq!(on(&c, "main.__sfc_X_Loop"), (0..8).collect::<Vec<_>>());
    // Documented: the step flag never falls, so its P1 action (a rising edge of Loop.X, as in the
    // standard's ACTION_CONTROL) runs only on the first activation.
    assert_eq!(c["main.laps"][7], "1");
    insta::assert_snapshot!(t);
}
