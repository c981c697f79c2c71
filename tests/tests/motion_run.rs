//! Programs with PLCopen motion blocks end to end: axis configuration, both parameter-passing methods,
//! the motion runtime linked into the generated C (strict warnings, sanitizers), axis trace columns.

mod common;
use common::ladderc;

use std::path::{Path, PathBuf};
use std::process::Command;

const MOVE: &str = "PROGRAM move
VAR
    pw : MC_Power;
    mv : MC_MoveAbsolute;
    go : BOOL;
    powered : BOOL;
    done : BOOL;
    busy : BOOL;
    aborted : BOOL;
END_VAR
    CAL pw(Axis := X1, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE, Status => powered)
    LD powered
    ST go
    CAL mv(Axis := X1, Execute := go, Position := 100.0, Velocity := 50.0, Acceleration := 200.0,
           Deceleration := 200.0, Done => done, Busy => busy, CommandAborted => aborted)
END_PROGRAM
";

const AXES: &str = r#"{ "cycle_ms": 10, "queue_depth": 8,
  "axes": [ { "name": "X1", "unit": "mm", "velocity": 100, "acceleration": 500, "deceleration": 500 } ] }
"#;

const WATCH: &str = "move.go,move.powered,move.done,move.busy,move.aborted,move.mv.Active,\
                     axis.X1.position,axis.X1.velocity,axis.X1.acceleration";

/// A project directory with `move.il` and `move.axes.json` (found by default beside the program).
fn project() -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("move.il");
    std::fs::write(&src, MOVE).unwrap();
    std::fs::write(dir.path().join("move.axes.json"), AXES).unwrap();
    (dir, src)
}

fn run_trace(src: &Path, extra: &[&str]) -> String {
    let trace = src.with_file_name(format!("trace{}.csv", extra.join("_").replace('-', "")));
    let out = ladderc()
        .arg("run")
        .arg(src)
        .args(["--cycles", "300", "--watch", WATCH, "--trace"])
        .arg(&trace)
        .args(extra)
        .output()
        .unwrap();
    common::assert_ok(&out);
    std::fs::read_to_string(&trace).unwrap()
}

/// Column `name` of a CSV trace, per row.
fn column(trace: &str, name: &str) -> Vec<f64> {
    let mut lines = trace.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let i = header.iter().position(|h| *h == name).unwrap();
    lines
        .map(|l| l.split(',').nth(i).unwrap().parse::<f64>().unwrap())
        .collect()
}

#[test]
fn both_methods_give_identical_traces_cycle_by_cycle_including_axis_positions() {
    let (_dir, src) = project();
    let il = run_trace(&src, &["--strategy", "il"]);
    let template = run_trace(&src, &["--strategy", "template"]);
    assert_eq!(il.lines().count(), 301);
    for (k, (a, b)) in il.lines().zip(template.lines()).enumerate() {
        assert_eq!(a, b, "the traces differ at row {k}");
    }
    // the sanitizers find nothing with either method and the trace stays the same
    for s in ["il", "template"] {
        let san = run_trace(&src, &["--strategy", s, "--sanitize"]);
        assert_eq!(san, il, "--strategy {s} --sanitize");
    }
}

#[test]
fn move_absolute_reaches_done_at_the_target_within_the_limits() {
    let (_dir, src) = project();
    let t = run_trace(&src, &["--strategy", "template"]);
    let pos = column(&t, "axis.X1.position");
    let vel = column(&t, "axis.X1.velocity");
    let done = column(&t, "move.done");
    let busy = column(&t, "move.busy");
    let first_done = done.iter().position(|&d| d == 1.0).expect("Done rises");
    // 100 mm at 50 mm/s with 200 mm/s² ramps: 0.25 s + 1.75 s + 0.25 s = 2.25 s = 225 cycles of 10 ms
    assert!(
        (224..=227).contains(&first_done),
        "Done at cycle {first_done}"
    );
    assert_eq!(pos[first_done], 100.0);
    assert!(done[first_done..].iter().all(|&d| d == 1.0));
    assert!(busy[..first_done].iter().all(|&b| b == 1.0) && busy[first_done] == 0.0);
    assert!(vel.iter().all(|&v| (0.0..=50.0 + 1e-9).contains(&v)));
    assert!(pos.windows(2).all(|w| w[1] >= w[0]), "monotonic move");
    assert!(column(&t, "axis.X1.acceleration")
        .iter()
        .all(|a| a.abs() <= 200.0 + 1e-9));
}

#[test]
fn built_projects_compile_warning_free_with_their_makefile_and_bundle_the_library() {
    let (dir, src) = project();
    for s in ["il", "template"] {
        let out_dir = dir.path().join(format!("out-{s}"));
        let out = ladderc()
            .args(["build", "--strategy", s, "-o"])
            .arg(&out_dir)
            .arg(&src)
            .output()
            .unwrap();
        common::assert_ok(&out);
        assert!(out_dir.join("libmotion_lib.a").is_file());
        assert!(out_dir.join("motion_lib.h").is_file());
        let make = Command::new("make")
            .arg("CFLAGS=-O1 -Wall -Wextra -Werror -pedantic")
            .current_dir(&out_dir)
            .output()
            .unwrap();
        assert!(
            make.status.success(),
            "{}{}",
            String::from_utf8_lossy(&make.stdout),
            String::from_utf8_lossy(&make.stderr)
        );
        let run = Command::new(out_dir.join("program"))
            .args(["--cycles", "300", "--watch", WATCH])
            .output()
            .unwrap();
        assert!(run.status.success());
        let trace = String::from_utf8(run.stdout).unwrap();
        // without --cycle-ms the harness runs at the engine's cycle (10 ms from move.axes.json)
        assert_eq!(column(&trace, "time_ms")[1], 10.0);
        assert_eq!(column(&trace, "axis.X1.position")[299], 100.0, "{s}");
        let config = std::fs::read_to_string(out_dir.join("ladderc_config.h")).unwrap();
        assert!(config.contains("#define LADDERC_DEFAULT_CYCLE_NS 10000000\n#endif"));
    }
}

const ONE_MOVE: &str = "PROGRAM one
VAR
    mv : MC_MoveAbsolute;
    go : BOOL;
    done : BOOL;
END_VAR
    CAL mv(Axis := X1, Execute := go, Position := 100.0, Velocity := 50.0, Acceleration := 200.0,
           Deceleration := 200.0, Done => done)
END_PROGRAM
";

fn emit_il(strategy: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("one.il");
    std::fs::write(&src, ONE_MOVE).unwrap();
    std::fs::write(dir.path().join("one.axes.json"), AXES).unwrap();
    let out = ladderc()
        .args(["build", "--emit", "il", "--strategy", strategy])
        .arg(&src)
        .output()
        .unwrap();
    common::assert_ok(&out);
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn emit_il_shows_three_parts_for_the_il_method() {
    insta::assert_snapshot!(emit_il("il"));
}

#[test]
fn emit_il_shows_one_func_for_the_template_method() {
    let il = emit_il("template");
    assert_eq!(il.matches("FUNC ").count(), 1, "{il}");
    insta::assert_snapshot!(il);
}

fn json_errors(args: &[&str], env: Option<(&str, &str)>) -> (Option<i32>, String) {
    let mut cmd = ladderc();
    cmd.args(["--message-format", "json"]).args(args);
    if let Some((k, v)) = env {
        cmd.env(k, v);
    }
    let out = cmd.output().unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_bad_axis_file_is_a_diagnostic_at_its_line_and_column() {
    let (dir, src) = project();
    let axes = dir.path().join("bad.json");
    std::fs::write(
        &axes,
        "{\n  \"axes\": [ { \"name\": \"X1\", \"velocity\": \"fast\" } ]\n}\n",
    )
    .unwrap();
    let (code, err) = json_errors(
        &[
            "build",
            "--emit",
            "il",
            "--axes",
            axes.to_str().unwrap(),
            src.to_str().unwrap(),
        ],
        None,
    );
    assert_eq!(code, Some(1), "{err}");
    let d: serde_json::Value = serde_json::from_str(err.lines().next().unwrap()).unwrap();
    assert_eq!(d["code"], "E5050", "{err}");
    assert!(err.contains("\"line\":2"), "{err}");
}

#[test]
fn a_scan_cycle_other_than_the_motion_cycle_is_refused() {
    let (_dir, src) = project();
    let (code, err) = json_errors(&["run", src.to_str().unwrap(), "--cycle-ms", "1"], None);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("E5053"), "{err}");
}

#[test]
fn an_unknown_axis_name_is_reported_before_code_generation() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("move.il");
    std::fs::write(
        &src,
        MOVE.replace("Axis := X1, Execute", "Axis := X2, Execute"),
    )
    .unwrap();
    std::fs::write(dir.path().join("move.axes.json"), AXES).unwrap();
    let (code, err) = json_errors(&["build", "--emit", "il", src.to_str().unwrap()], None);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("X2"), "{err}");
}

#[test]
fn a_missing_motion_library_is_e9050() {
    let (dir, src) = project();
    let missing = dir.path().join("nope.a");
    let (code, err) = json_errors(
        &["run", src.to_str().unwrap()],
        Some(("LADDERC_MOTION_LIB", missing.to_str().unwrap())),
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("E9050"), "{err}");
}

#[test]
fn report_json_gives_per_block_method_tm_bytes_instructions_and_c_bytes() {
    let (dir, src) = project();
    let mut reports = Vec::new();
    for s in ["il", "template"] {
        // object sizes depend on the C compiler: checked, then left out of the snapshot
        let v = common::block_report(&src, &dir.path().join(format!("out-{s}")), s, 100);
        reports.push(v);
    }
    let block = |r: &serde_json::Value, name: &str| {
        r["blocks"]
            .as_array()
            .unwrap()
            .iter()
            .find(|b| b["block"] == name)
            .cloned()
            .unwrap()
    };
    let (il, tpl) = (
        block(&reports[0], "MC_MoveAbsolute"),
        block(&reports[1], "MC_MoveAbsolute"),
    );
    assert_eq!(il["method"], "il");
    assert_eq!(tpl["method"], "template");
    assert_eq!(il["calls"], 1);
    // IL method: every parameter has a TM slot (4 B axis index + 6 LREAL... see --emit il), one FUNC
    assert!(il["tm_bytes"].as_u64().unwrap() > 33);
    assert_eq!(tpl["tm_bytes"], 0);
    assert!(il["il_instructions"].as_u64().unwrap() > 30);
    assert_eq!(tpl["il_instructions"], 1);
    assert!(il["c_bytes"].as_u64().unwrap() > 500);
    assert!(tpl["c_bytes"].as_u64().unwrap() > 500);
    insta::assert_snapshot!(format!(
        "{}\n{}",
        serde_json::to_string_pretty(&reports[0]).unwrap(),
        serde_json::to_string_pretty(&reports[1]).unwrap()
    ));
}

#[test]
fn run_plot_draws_position_and_velocity_of_each_axis() {
    let (dir, src) = project();
    let svg = dir.path().join("move.svg");
    let out = ladderc()
        .arg("run")
        .arg(&src)
        .args([
            "--cycles",
            "250",
            "--watch",
            "move.busy,move.done",
            "--plot",
        ])
        .arg(&svg)
        .output()
        .unwrap();
    common::assert_ok(&out);
    // the axis columns were added to the watch list for the plot
    let header = String::from_utf8(out.stdout).unwrap();
    assert!(
        header.starts_with("cycle,time_ms,move.busy,move.done,axis.X1.position,axis.X1.velocity\n")
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg"));
    assert!(text.contains("X1.position") && text.contains("X1.velocity"));
    assert!(
        text.matches("<polyline").count() >= 4,
        "two axis lines and the block markers"
    );
}

/// Drops the TM views (only the IL method has them) from a trace.
fn without_tm_views(trace: &str) -> Vec<Vec<String>> {
    let rows: Vec<Vec<String>> = trace
        .lines()
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    let keep: Vec<usize> = (0..rows[0].len())
        .filter(|&i| !rows[0][i].contains("TM__"))
        .collect();
    rows.iter()
        .map(|r| keep.iter().map(|&i| r[i].clone()).collect())
        .collect()
}

#[test]
fn differential_two_axes_calc_negated_outputs_buffered_halt_every_variable() {
    // every variable of the program (block instances included) and both axes, 400 cycles of 5 ms
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/motion/two_axes.il");
    let dir = tempfile::tempdir().unwrap();
    let mut traces = Vec::new();
    for s in ["il", "template"] {
        let trace = dir.path().join(format!("{s}.csv"));
        let out = ladderc()
            .arg("run")
            .arg(&src)
            .args(["--cycles", "400", "--strategy", s, "--trace"])
            .arg(&trace)
            .output()
            .unwrap();
        common::assert_ok(&out);
        traces.push(without_tm_views(&std::fs::read_to_string(&trace).unwrap()));
    }
    let (il, tpl) = (&traces[0], &traces[1]);
    assert_eq!(il[0], tpl[0], "same columns");
    assert!(il[0].iter().any(|c| c == "axis.Y1.velocity"));
    assert!(il[0].iter().any(|c| c == "two_axes.notdone"));
    assert_eq!(il.len(), 401);
    for k in 0..il.len() {
        assert_eq!(il[k], tpl[k], "row {k} differs");
    }
    // the halt stopped Y1 (its velocity ends at 0) after MC_MoveVelocity had moved it
    let h = &il[0];
    let col = |name: &str| h.iter().position(|c| c == name).unwrap();
    assert_eq!(il[400][col("axis.Y1.velocity")], "0");
    assert_eq!(il[400][col("two_axes.halted")], "1");
    assert!(il[400][col("axis.Y1.position")].parse::<f64>().unwrap() > 5.0);
    // NOT Done => notdone: notdone is the negation of a.Done on every row
    for r in &il[1..] {
        assert_ne!(r[col("two_axes.notdone")], r[col("two_axes.a.Done")]);
    }
}

#[test]
fn groups_of_the_axis_file_are_created_at_init_and_declared_as_globals() {
    let (dir, src) = project();
    let axes = dir.path().join("group.json");
    std::fs::write(
        &axes,
        r#"{ "cycle_ms": 10, "axes": [
            { "name": "X1", "velocity": 100, "acceleration": 500, "deceleration": 500 },
            { "name": "Y9", "velocity": 100, "acceleration": 500, "deceleration": 500 } ],
          "groups": [ { "name": "G1", "axes": [ { "axis": "X1", "identity": "X" }, { "axis": "Y9", "identity": "Y" } ] } ] }"#,
    )
    .unwrap();
    let out = ladderc()
        .arg("run")
        .arg(&src)
        .arg("--axes")
        .arg(&axes)
        .args([
            "--cycles",
            "2",
            "--watch",
            "X1.AxisNo,Y9.AxisNo,G1.GroupNo,axis.Y9.position",
        ])
        .output()
        .unwrap();
    common::assert_ok(&out);
    assert_eq!(
        String::from_utf8(out.stdout).unwrap(),
        "cycle,time_ms,X1.AxisNo,Y9.AxisNo,G1.GroupNo,axis.Y9.position\n0,0,0,1,0,0\n1,10,0,1,0,0\n"
    );
}

#[test]
fn report_with_emit_il_is_a_usage_error() {
    let (_dir, src) = project();
    let out = ladderc()
        .args(["build", "--emit", "il", "--report", "json"])
        .arg(&src)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--report"));
}

#[test]
fn a_ladder_program_with_motion_blocks_runs_identically_with_both_methods() {
    // tests/motion/ladder_move.axes.json is found beside the XML by default
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/motion/ladder_move.xml");
    let dir = tempfile::tempdir().unwrap();
    let mut traces = Vec::new();
    for s in ["il", "template"] {
        let trace = dir.path().join(format!("{s}.csv"));
        let out = ladderc()
            .arg("run")
            .arg(&src)
            .args(["--cycles", "260", "--strategy", s, "--sanitize", "--trace"])
            .arg(&trace)
            .args([
                "--watch",
                "lmove.Powered,lmove.Done,axis.X1.position,axis.X1.velocity",
            ])
            .output()
            .unwrap();
        common::assert_ok(&out);
        traces.push(std::fs::read_to_string(&trace).unwrap());
    }
    assert_eq!(traces[0], traces[1]);
    let done = column(&traces[0], "lmove.Done");
    let k = done.iter().position(|&d| d == 1.0).expect("Done rises");
    assert_eq!(column(&traces[0], "axis.X1.position")[k], 100.0);
}

#[test]
fn pmac_program_of_the_constant_moves_with_a_warning_for_the_computed_one() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/motion/pmac_moves.il");
    let dir = tempfile::tempdir().unwrap();
    let mut texts = Vec::new();
    for dialect in ["turbo", "power"] {
        let pmc = dir.path().join(format!("{dialect}.pmc"));
        let out = ladderc()
            .args(["--message-format", "short", "build", "-o"])
            .arg(dir.path().join(format!("out-{dialect}")))
            .arg(&src)
            .arg("--pmac")
            .arg(&pmc)
            .args(["--pmac-dialect", dialect])
            .output()
            .unwrap();
        common::assert_ok(&out);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("warning[W5050]") && err.contains(":16:"),
            "{err}"
        );
        texts.push(std::fs::read_to_string(&pmc).unwrap());
    }
    // X1 to 100 (its own jerk 1000), Y1 to 50 (no jerk limit: TS0), X1 back by 20 (the axis's jerk 5000)
    insta::assert_snapshot!(texts.join("\n----\n"));
}

#[test]
fn blocks_inside_a_function_block_and_global_instances_work_with_both_methods() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/motion/fb_and_global.il");
    let dir = tempfile::tempdir().unwrap();
    let mut traces = Vec::new();
    for s in ["il", "template"] {
        let trace = dir.path().join(format!("{s}.csv"));
        let out = ladderc()
            .arg("run")
            .arg(&src)
            .args(["--cycles", "150", "--strategy", s, "--trace"])
            .arg(&trace)
            .args([
                "--watch",
                "fb_and_global.d,gdone,axis.X1.position,axis.Y1.position",
            ])
            .output()
            .unwrap();
        common::assert_ok(&out);
        traces.push(std::fs::read_to_string(&trace).unwrap());
    }
    assert_eq!(traces[0], traces[1]);
    assert!(traces[0].ends_with("149,1490,1,1,20,-5\n"), "{}", traces[0]);
}
