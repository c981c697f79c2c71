//! Textual SFC (IEC 61131-3 2.6 `INITIAL_STEP`/`STEP`/`TRANSITION`/`ACTION` in an ST body, as OpenPLC
//! Editor and Beremiz write it) end to end through `ladderc run`: each chart is also written as PLCopen XML,
//! and the XML SFC path is the oracle: the traces must be identical, cycle by cycle. Broken charts get
//! located diagnostics.

mod common;
use common::text_column;

use std::path::{Path, PathBuf};
use std::process::Output;

fn fixture(dir: &str, name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures")
        .join(dir)
        .join(name)
}

/// Runs `file` for `cycles` scans of 10 ms with `stimulus`; returns the trace text.
fn run(file: &Path, cycles: u32, stimulus: &str, watch: &[&str]) -> String {
    common::run_with_stimulus(file, cycles, stimulus, watch)
}

/// The textual chart and its XML twin give the same trace; returns it.
fn same_as_xml(st: &str, xml: &Path, cycles: u32, stimulus: &str, watch: &[&str]) -> String {
    let t = run(&fixture("st_sfc", st), cycles, stimulus, watch);
    let x = run(xml, cycles, stimulus, watch);
    assert_eq!(t, x, "{st}: textual SFC and PLCopen XML SFC traces differ");
    t
}

fn on(trace: &str, name: &str) -> Vec<usize> {
    text_column(trace, name)
        .iter()
        .enumerate()
        .filter(|(_, v)| v.as_str() == "1")
        .map(|(i, _)| i)
        .collect()
}

#[test]
fn traffic_light_with_timed_transitions() {
    let watch = [
        "main.__sfc_X_Red",
        "main.__sfc_X_Green",
        "main.__sfc_X_Yellow",
        "main.__sfc_T_Red",
        "main.red",
        "main.green",
        "main.yellow",
        "main.cycles",
    ];
    let t = same_as_xml(
        "traffic.st",
        &fixture("st_sfc", "traffic.xml"),
        30,
        "",
        &watch,
    );
    // Red 50 ms (cycles 0..4), Green 40 ms (5..8), Yellow 20 ms (9, 10), Red again from 11.
    assert_eq!(on(&t, "main.red")[..6], [0, 1, 2, 3, 4, 11]);
    assert_eq!(on(&t, "main.green")[..4], [5, 6, 7, 8]);
    assert_eq!(on(&t, "main.yellow")[..2], [9, 10]);
    // P: once per Green phase.
    assert_eq!(text_column(&t, "main.cycles")[5], "1");
    assert_eq!(text_column(&t, "main.cycles")[29], "3");
}

const SEQ: &[&str] = &[
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
fn divergence_convergence_and_priority_match_the_xml_chart() {
    let xml = fixture("sfc", "sequence.xml");
    // PRIORITY := 1 wins over the text order.
    let t = same_as_xml(
        "sequence.st",
        &xml,
        6,
        "1,main.go,1\n1,main.a,1\n1,main.b,1\n1,main.c,1\n",
        SEQ,
    );
    assert_eq!(on(&t, "main.__sfc_X_C"), [2, 3, 4, 5]);
    // FROM A TO (P1, P2) and FROM (P1b, P2) TO Init.
    let t = same_as_xml(
        "sequence.st",
        &xml,
        10,
        "1,main.go,1\n1,main.a,1\n1,main.b,1\n1,main.join,1\n6,main.p1done,1\n7,main.go,0\n",
        SEQ,
    );
    assert_eq!(on(&t, "main.__sfc_X_P2"), [3, 4, 5, 6]);
    assert_eq!(on(&t, "main.__sfc_X_P1b"), [6]);
    assert_eq!(on(&t, "main.__sfc_X_Init"), [0, 7, 8, 9]);
    // the selection divergence's other branch, and back.
    same_as_xml(
        "sequence.st",
        &xml,
        10,
        "1,main.go,1\n1,main.b,1\n4,main.back,1\n",
        SEQ,
    );
}

#[test]
fn action_qualifiers_match_the_xml_chart() {
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
    let t = same_as_xml(
        "actions.st",
        &fixture("sfc", "actions.xml"),
        15,
        "1,main.go,1\n2,main.go,0\n8,main.next,1\n9,main.next,0\n",
        &watch,
    );
    assert_eq!(on(&t, "main.stored"), [1, 2, 3, 4, 5, 6, 7]);
    assert_eq!(on(&t, "main.limited"), [1, 2, 3]);
    assert_eq!(on(&t, "main.delayed"), [3, 4, 5, 6, 7]);
    assert_eq!(text_column(&t, "main.p_count")[14], "1");
    assert_eq!(text_column(&t, "main.p0_count")[8], "1");
    assert_eq!(text_column(&t, "main.s1_t")[8], "T#70ms");
}

/// `ladderc check` of `text`: the errors as (code, line, column).
fn check(text: &str) -> (Output, Vec<(String, u64, u64)>) {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("chart.st");
    std::fs::write(&p, text).unwrap();
    let o = common::ladderc()
        .arg("check")
        .arg(&p)
        .args(["--message-format", "json"])
        .output()
        .unwrap();
    let errs = String::from_utf8_lossy(&o.stdout)
        .lines()
        .chain(String::from_utf8_lossy(&o.stderr).lines())
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .filter(|v| v["severity"] == "error")
        .map(|v| {
            (
                v["code"].as_str().unwrap().to_string(),
                v["line"].as_u64().unwrap(),
                v["column"].as_u64().unwrap(),
            )
        })
        .collect();
    (o, errs)
}

fn chart(first: &str, to: &str, second: &str) -> String {
    format!(
        "PROGRAM P\n  VAR x : BOOL; END_VAR\n  {first} A:\n  END_STEP\n  TRANSITION FROM A TO {to} := x; END_TRANSITION\n  {second} B: END_STEP\n  TRANSITION FROM B TO A := NOT x; END_TRANSITION\nEND_PROGRAM\n"
    )
}

#[test]
fn broken_charts_get_located_errors() {
    let (o, e) = check(&chart("INITIAL_STEP", "B", "STEP"));
    assert_eq!(o.status.code(), Some(0), "{e:?}");
    // an unknown step in a transition
    let (_, e) = check(&chart("INITIAL_STEP", "Bx", "STEP"));
    assert_eq!(e, [("E3120".to_string(), 5, 24)]);
    // no initial step
    let (_, e) = check(&chart("STEP", "B", "STEP"));
    assert_eq!(e, [("E3124".to_string(), 3, 8)]);
    // two initial steps
    let (_, e) = check(&chart("INITIAL_STEP", "B", "INITIAL_STEP"));
    assert_eq!(e, [("E3128".to_string(), 6, 16)]);
    // a timed qualifier without its duration; an ST error in a condition, located in the file
    let (_, e) = check(
        "PROGRAM P\n  VAR x : BOOL; END_VAR\n  INITIAL_STEP A:\n    x(L);\n  END_STEP\n  TRANSITION FROM A TO A := x + ; END_TRANSITION\nEND_PROGRAM\n",
    );
    assert_eq!(e, [("E3123".to_string(), 4, 7)]);
    let (_, e) = check(
        "PROGRAM P\n  VAR x : BOOL; END_VAR\n  INITIAL_STEP A:\n    x(N);\n  END_STEP\n  TRANSITION FROM A TO A := x + ; END_TRANSITION\nEND_PROGRAM\n",
    );
    assert_eq!(e, [("E0107".to_string(), 6, 33)]);
}

#[test]
fn a_function_block_chart_keeps_its_steps_per_instance_and_a_function_chart_is_refused() {
    let fb = "FUNCTION_BLOCK Blink\n  VAR_OUTPUT q : BOOL; END_VAR\n  INITIAL_STEP Off: END_STEP\n  TRANSITION FROM Off TO On := Off.T >= T#20ms; END_TRANSITION\n  STEP On: q(N); END_STEP\n  TRANSITION FROM On TO Off := On.T >= T#20ms; END_TRANSITION\nEND_FUNCTION_BLOCK\n";
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("blink.st");
    std::fs::write(
        &p,
        format!("{fb}PROGRAM Main\n  VAR b : Blink; out : BOOL; END_VAR\n  b();\n  out := b.q;\nEND_PROGRAM\n"),
    )
    .unwrap();
    let t = run(&p, 10, "", &["main.out"]);
    assert_eq!(on(&t, "main.out"), [2, 3, 6, 7]);
    let (_, e) = check("FUNCTION F : BOOL\n  INITIAL_STEP A: END_STEP\n  TRANSITION FROM A TO A := TRUE; END_TRANSITION\nEND_FUNCTION\n");
    assert_eq!(e, [("E3125".to_string(), 1, 10)]);
}
