//! Versioned JSON diagnostics and feedback on long work (issues #15.3, #11.6): every JSON line carries the
//! schema version and validates against `crates/diagnostics/schema/diagnostics-1.schema.json`; the last
//! line is the summary record; `run` prints a one-line summary; XML inputs give every diagnostic its POU,
//! network and localId; no progress bar without a terminal, one on a terminal.

mod common;

use common::{assert_ok, ladderc, write_file};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Output;

fn root() -> PathBuf {
    common::repo_root()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn validator() -> jsonschema::Validator {
    let text =
        std::fs::read_to_string(root().join("crates/diagnostics/schema/diagnostics-1.schema.json"))
            .unwrap();
    let schema: Value = serde_json::from_str(&text).unwrap();
    jsonschema::validator_for(&schema).expect("the schema is a valid JSON Schema")
}

/// Every line of standard error, each validated against the schema; the last one is the summary.
fn json_lines(out: &Output) -> Vec<Value> {
    let v = validator();
    let err = stderr(out);
    let lines: Vec<Value> = err
        .lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("not JSON ({e}): {l}")))
        .collect();
    for l in &lines {
        let errors: Vec<String> = v.iter_errors(l).map(|e| e.to_string()).collect();
        assert!(errors.is_empty(), "{l}: {errors:?}");
        assert_eq!(l["schema"], "ladderc-diagnostic/1");
    }
    let last = lines.last().unwrap_or_else(|| panic!("no output: {err}"));
    assert_eq!(last["kind"], "summary", "{err}");
    assert_eq!(
        lines.iter().filter(|l| l["kind"] == "summary").count(),
        1,
        "{err}"
    );
    lines
}

fn json(args: &[&str], cwd: &Path) -> Output {
    ladderc()
        .current_dir(cwd)
        .args(["--message-format", "json"])
        .args(args)
        .output()
        .unwrap()
}

const LD_GHOST: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="main" pouType="program">
      <interface><localVars>
        <variable name="lamp"><type><BOOL/></type></variable>
        <variable name="start"><type><BOOL/></type></variable>
      </localVars></interface>
      <body><LD>
        <leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter="none"/></leftPowerRail>
        <contact localId="2"><position x="20" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>start</variable></contact>
        <coil localId="3"><position x="60" y="0"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>lamp</variable></coil>
        <leftPowerRail localId="11"><position x="0" y="100"/><connectionPointOut formalParameter="none"/></leftPowerRail>
        <contact localId="12"><position x="20" y="100"/><connectionPointIn><connection refLocalId="11"/></connectionPointIn><connectionPointOut/><variable>ghost</variable></contact>
        <coil localId="13"><position x="60" y="100"/><connectionPointIn><connection refLocalId="12"/></connectionPointIn><connectionPointOut/><variable>lamp</variable></coil>
      </LD></body>
    </pou>
    <pou name="calc" pouType="program">
      <interface><localVars><variable name="n"><type><INT/></type></variable><variable name="t"><type><derived name="TON"/></type></variable></localVars></interface>
      <body><ST><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml">n := n + phantom;
t(IN := TRUE, NOPE := T#1s);</xhtml:p></ST></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="c"><resource name="r">
    <task name="t" interval="T#10ms" priority="1"><pouInstance name="i" typeName="main"/><pouInstance name="j" typeName="calc"/></task>
  </resource></configuration></configurations></instances>
</project>
"#;

#[test]
fn semantic_errors_in_xml_name_their_pou_network_and_local_id() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "ghost.xml", LD_GHOST);
    let out = json(&["check", "ghost.xml"], dir.path());
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    let lines = json_lines(&out);
    let diags: Vec<&Value> = lines.iter().filter(|l| l["kind"] == "diagnostic").collect();
    let ghost = diags
        .iter()
        .find(|d| d["message"].as_str().unwrap().contains("ghost"))
        .unwrap_or_else(|| panic!("{lines:?}"));
    assert_eq!(ghost["code"], "E1001");
    assert_eq!(ghost["pou"], "main");
    assert_eq!(ghost["network"], "2", "the second rung");
    assert_eq!(ghost["local_id"], "12");
    let phantom = diags
        .iter()
        .find(|d| d["message"].as_str().unwrap().contains("phantom"))
        .unwrap_or_else(|| panic!("{lines:?}"));
    assert_eq!(phantom["code"], "E1001");
    assert_eq!(phantom["pou"], "calc");
    let nope = diags
        .iter()
        .find(|d| d["message"].as_str().unwrap().contains("NOPE"))
        .unwrap_or_else(|| panic!("{lines:?}"));
    assert_eq!(nope["code"], "E1011");
    assert_eq!(nope["pou"], "calc");
    // every diagnostic with a span in the XML file has its POU
    for d in &diags {
        assert!(d["pou"].is_string(), "{d}");
    }
    let summary = lines.last().unwrap();
    let errors = diags.iter().filter(|d| d["severity"] == "error").count();
    assert_eq!(summary["errors"], errors);
    assert_eq!(summary["warnings"], diags.len() - errors);
    assert_eq!(summary["files"], Value::Array(vec![]));
    // The short rendering shows the same context.
    let short = ladderc()
        .current_dir(dir.path())
        .args(["--message-format", "short", "check", "ghost.xml"])
        .output()
        .unwrap();
    assert!(
        stderr(&short).contains("[POU `main`, network 2, localId 12]"),
        "{}",
        stderr(&short)
    );
}

#[test]
fn real_failing_runs_validate_against_the_schema() {
    let dir = tempfile::tempdir().unwrap();
    write_file(
        dir.path(),
        "bad.il",
        "PROGRAM main\nVAR x : INT; END_VAR\n    LD y\n    ST x\n    JMP nowhere\nEND_PROGRAM\n",
    );
    write_file(
        dir.path(),
        "bad.st",
        "PROGRAM main\nVAR x : INT; END_VAR\n  x := ;\n  y := 1;\nEND_PROGRAM\n",
    );
    write_file(dir.path(), "ghost.xml", LD_GHOST);
    write_file(
        dir.path(),
        "broken.xml",
        "<project><types><pous><pou name=\"a\"",
    );
    for (args, exit) in [
        (vec!["check", "bad.il"], 1),
        (vec!["build", "bad.st", "--emit", "il"], 1),
        (vec!["run", "ghost.xml"], 1),
        (vec!["check", "broken.xml"], 1),
        (vec!["check", "missing.il"], 2),
        (vec!["run", "bad.il", "--cycels", "2"], 2),
        (vec!["build", "bad.il"], 2),
    ] {
        let out = json(&args, dir.path());
        assert_eq!(out.status.code(), Some(exit), "{args:?}: {}", stderr(&out));
        let lines = json_lines(&out);
        let errors = lines.iter().filter(|l| l["severity"] == "error").count();
        assert!(errors > 0, "{args:?}");
        assert_eq!(lines.last().unwrap()["errors"], errors, "{args:?}");
    }
}

#[test]
fn the_running_programs_messages_are_json_records_too() {
    let dir = tempfile::tempdir().unwrap();
    write_file(
        dir.path(),
        "div.il",
        "PROGRAM main\nVAR d : INT; q : INT; END_VAR\n    LD 10\n    DIV d\n    ST q\nEND_PROGRAM\n",
    );
    write_file(
        dir.path(),
        "bad.csv",
        "cycle,variable,value\n1,main.nosuch,3\n",
    );
    let out = json(&["run", "div.il", "--cycles", "2"], dir.path());
    assert_ok(&out);
    let lines = json_lines(&out);
    assert_eq!(lines[0]["code"], "W9200", "{lines:?}");
    assert!(lines[0]["message"]
        .as_str()
        .unwrap()
        .contains("division by zero"));
    assert_eq!(lines.last().unwrap()["warnings"], 1);
    assert_eq!(lines.last().unwrap()["run"]["cycles"], 2);

    let out = json(
        &["run", "div.il", "--cycles", "2", "--stimulus", "bad.csv"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(1));
    let lines = json_lines(&out);
    assert_eq!(lines[0]["code"], "E9201", "{lines:?}");
    assert!(lines[0]["message"].as_str().unwrap().contains("nosuch"));
    assert_eq!(lines.last().unwrap()["errors"], 1);
    assert!(
        lines.last().unwrap().get("run").is_none(),
        "a failed run has no run figures"
    );
}

#[test]
fn run_prints_a_one_line_summary_and_a_json_summary_record() {
    let dir = tempfile::tempdir().unwrap();
    let counter = root().join("examples/counter");
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .arg("run")
        .arg(counter.join("counter.il"))
        .args(["--cycles", "25", "--stimulus"])
        .arg(counter.join("stimulus.csv"))
        .arg("--trace")
        .arg(&trace)
        .output()
        .unwrap();
    assert_ok(&out);
    let err = stderr(&out);
    let line = err
        .lines()
        .find(|l| l.starts_with("ran 25 cycles: 0.25 s simulated in "))
        .unwrap_or_else(|| panic!("{err}"));
    assert!(line.contains(" s ("), "{line}");
    assert!(line.contains("x real time"), "{line}");
    assert!(
        line.ends_with(&format!("; wrote {}", trace.display())),
        "{line}"
    );
    assert!(
        !err.contains('\r'),
        "no progress bar without a terminal: {err:?}"
    );

    let motion = root().join("examples/motion/move.il");
    let svg = dir.path().join("m.svg");
    let out = ladderc()
        .args(["--message-format", "json", "run"])
        .arg(&motion)
        .args(["--cycles", "300", "--watch", "axis.X1.position", "--trace"])
        .arg(&trace)
        .arg("--plot")
        .arg(&svg)
        .output()
        .unwrap();
    assert_ok(&out);
    let lines = json_lines(&out);
    let s = lines.last().unwrap();
    assert_eq!(s["errors"], 0);
    assert_eq!(s["run"]["cycles"], 300);
    assert_eq!(
        s["run"]["simulated_s"], 0.6,
        "2 ms cycles from move.axes.json"
    );
    assert!(s["run"]["wall_s"].as_f64().unwrap() > 0.0);
    assert_eq!(
        s["files"],
        serde_json::json!([svg.display().to_string(), trace.display().to_string()]),
        "in the order written: the trace is moved into place last"
    );
    // build reports its directory.
    let out_dir = dir.path().join("proj");
    let out = ladderc()
        .args(["--message-format", "json", "build"])
        .arg(counter.join("counter.il"))
        .arg("-o")
        .arg(&out_dir)
        .output()
        .unwrap();
    assert_ok(&out);
    let lines = json_lines(&out);
    assert_eq!(
        lines.last().unwrap()["files"],
        serde_json::json!([out_dir.display().to_string()])
    );
}

/// A program that runs for a while: many cycles of a loop.
const SLOW: &str = "PROGRAM main\nVAR i : DINT; acc : DINT; END_VAR\n    LD 0\n    ST i\nloop:\n    LD acc\n    ADD i\n    ST acc\n    LD i\n    ADD 1\n    ST i\n    LT 2000\n    JMPC loop\nEND_PROGRAM\n";

#[test]
fn a_progress_bar_is_drawn_on_a_terminal_only() {
    let dir = tempfile::tempdir().unwrap();
    let prog = write_file(dir.path(), "slow.il", SLOW);
    let trace = dir.path().join("t.csv");
    let args = format!(
        "{} run {} --cycles 200000 --watch main.acc --trace {}",
        env!("CARGO_BIN_EXE_ladderc-e2e"),
        prog.display(),
        trace.display()
    );
    // `script` gives the command a pseudo-terminal; the bar appears after LADDERC_PROGRESS_AFTER_MS.
    if std::process::Command::new("script")
        .arg("--version")
        .output()
        .is_err()
    {
        println!("skipped: `script` (util-linux) is not installed");
        return;
    }
    let out = std::process::Command::new("script")
        .args(["-qec", &args, "/dev/null"])
        .env("LADDERC_PROGRESS_AFTER_MS", "0")
        .stdin(std::process::Stdio::null())
        .output()
        .unwrap();
    let screen = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{screen}");
    assert!(screen.contains("/200000 cycles"), "{screen}");
    assert!(screen.contains("ran 200000 cycles"), "{screen}");
    // The same run without a terminal: no bar.
    let out = ladderc()
        .arg("run")
        .arg(&prog)
        .args(["--cycles", "200000", "--watch", "main.acc", "--trace"])
        .arg(&trace)
        .env("LADDERC_PROGRESS_AFTER_MS", "0")
        .output()
        .unwrap();
    assert_ok(&out);
    let err = stderr(&out);
    assert!(!err.contains("cycles (") && !err.contains('\r'), "{err:?}");
    assert_eq!(err.lines().count(), 1, "{err}");
}
