//! The warnings users expect of outputs, through `ladderc run` and `build`: W3400 when a ladder POU
//! drives one variable from plain coils of two networks (the later rung wins every scan; set/reset
//! coils in different rungs are normal and not reported), W1400 when two located variables share
//! output bits (`%QW0` and `%QX0.3`, the same `%QX2.0` twice, `%QB1` inside `%QW0`); and `0`/`1` as
//! BOOL literals on block inputs (found in a real OpenPLC project while testing these).

mod common;
use common::ladderc;

use std::path::Path;

fn json_lines(stderr: &[u8]) -> Vec<serde_json::Value> {
    String::from_utf8_lossy(stderr)
        .lines()
        .filter(|l| l.starts_with('{'))
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

#[test]
fn two_rungs_driving_one_coil_warn_with_pou_network_and_local_id() {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, "0,%IX0.0,1\n1,%IX0.0,0\n1,%IX0.1,1\n2,%IX0.0,1\n").unwrap();
    let trace = dir.path().join("t.csv");
    let fixture = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/double_coil.xml");
    let out = ladderc()
        .args(["--message-format", "json", "run"])
        .arg(&fixture)
        .args(["--cycles", "3", "--sanitize", "--stimulus"])
        .arg(&stim)
        .arg("--trace")
        .arg(&trace)
        .args(["--watch", "main.motor,main.latch"])
        .output()
        .unwrap();
    common::assert_ok(&out);
    // start alone (cycle 0) does not reach the motor: the jog rung overrides it, as W3400 says
    assert_eq!(
        std::fs::read_to_string(&trace).unwrap(),
        "cycle,time_ms,main.motor,main.latch\n0,0,0,0\n1,10,1,1\n2,20,1,0\n"
    );
    let diags = json_lines(&out.stderr);
    let w3400: Vec<_> = diags.iter().filter(|d| d["code"] == "W3400").collect();
    assert_eq!(w3400.len(), 1, "{diags:?}");
    let d = w3400[0];
    assert_eq!(d["severity"], "warning");
    assert_eq!(d["pou"], "main");
    assert_eq!(d["network"], "2");
    assert_eq!(d["local_id"], "22");
    assert_eq!(d["line"], 26);
    assert_eq!(d["labels"][0]["line"], 21);
    assert!(
        d["message"]
            .as_str()
            .unwrap()
            .contains("`motor` is written by network 1 (localId 12) and again by network 2"),
        "{d}"
    );
    // the located output overlap of the same file
    let w1400: Vec<_> = diags.iter().filter(|d| d["code"] == "W1400").collect();
    assert_eq!(w1400.len(), 1, "{diags:?}");
    assert_eq!(w1400[0]["pou"], "main");
    assert_eq!(w1400[0]["line"], 14);
    assert_eq!(w1400[0]["labels"][0]["line"], 12);
}

#[test]
fn located_outputs_sharing_bits_warn_once_per_pair() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("ov.il");
    std::fs::write(
        &src,
        "VAR_GLOBAL
  panel AT %QW0 : WORD;
  lamp AT %QX0.3 : BOOL;
  other AT %QX1.0 : BOOL;
  free AT %QX2.0 : BOOL;
  same AT %QX2.0 : BOOL;
  apart AT %QX2.1 : BOOL;
  word2 AT %QW2 : WORD;
  inp AT %IX0.3 : BOOL;
  inw AT %IW0 : WORD;
END_VAR
PROGRAM main
VAR_EXTERNAL
  panel : WORD;
  lamp : BOOL;
END_VAR
VAR
  tail AT %QB1 : BYTE;
END_VAR
  LD TRUE
  ST lamp
END_PROGRAM
",
    )
    .unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(&src)
        .args(["--cycles", "1", "--trace"])
        .arg(&trace)
        .args(["--watch", "%QW0,%QX0.3"])
        .output()
        .unwrap();
    common::assert_ok(&out);
    // lamp's bit 3 shows in the word: both names are one output
    assert_eq!(
        std::fs::read_to_string(&trace).unwrap(),
        "cycle,time_ms,%QW0,%QX0.3\n0,0,8,1\n"
    );
    let err = String::from_utf8_lossy(&out.stderr);
    let mut w: Vec<&str> = err.lines().filter(|l| l.contains("W1400")).collect();
    w.sort();
    // %QW2 is bytes 4..6 (element addressing): it overlaps nothing; inputs are not outputs
    assert_eq!(
        w,
        [
            "ov.il:18:11: warning[W1400]: `main.tail` at %QB1 shares output bits with `panel` at %QW0 [POU `main`]",
            "ov.il:3:11: warning[W1400]: `lamp` at %QX0.3 shares output bits with `panel` at %QW0",
            "ov.il:4:12: warning[W1400]: `other` at %QX1.0 shares output bits with `panel` at %QW0",
            "ov.il:6:11: warning[W1400]: `same` at %QX2.0 shares output bits with `free` at %QX2.0",
        ]
        .map(|s| {
            // two sizes: apart in OpenPLC's and matiec's memory, which a profile models
            let apart = if s.contains("%QW0") {
                " (OpenPLC and matiec keep one image per size, where they are apart: `--profile openplc`)"
            } else {
                ""
            };
            format!(
                "{}{s} (hint: give each output its own address; writing one changes the other{apart})",
                src.parent().unwrap().display().to_string() + "/"
            )
        }),
        "{err}"
    );
}

/// `0` and `1` wired to BOOL block inputs are BOOL literals (IEC 61131-3 boolean literals; OpenPLC
/// Editor projects write them, e.g. a CTUD with LD wired to `0`): the project runs instead of E3008.
#[test]
fn zero_and_one_drive_bool_block_inputs() {
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.csv");
    let fixture =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/bool_literal_inputs.xml");
    let out = ladderc()
        .arg("run")
        .arg(&fixture)
        .args(["--cycles", "4", "--sanitize", "--trace"])
        .arg(&trace)
        .args(["--watch", "main.done,main.count"])
        .output()
        .unwrap();
    common::assert_ok(&out);
    // TON(IN := 1, PT := T#20ms) is done at 20 ms; CTU(CU := 1, R := 0) counts the first edge once
    assert_eq!(
        std::fs::read_to_string(&trace).unwrap(),
        "cycle,time_ms,main.done,main.count\n0,0,0,1\n1,10,0,1\n2,20,1,1\n3,30,1,1\n"
    );
}
