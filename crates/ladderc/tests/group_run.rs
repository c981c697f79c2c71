//! PLCopen Part 4 (axes group) blocks end to end: a 3-axis group of the axis file, MC_GroupEnable and paper
//! B's three MC_MoveLinearAbsolute blocks (Aborting, BlendingLow, BlendingHigh), through both parameter-passing
//! methods; array parameters (Position, the read blocks' Position/Velocity outputs), the report, `--emit il`,
//! and the legality checks before code generation.

use std::path::{Path, PathBuf};
use std::process::Command;

fn ladderc() -> Command {
    Command::new(env!("CARGO_BIN_EXE_ladderc"))
}

/// Paper B's experiment: three straight lines on a 3-axis group, velocities 40, 55, 70 mm/s, acceleration
/// and deceleration 5 mm/s², jerk 2 mm/s³; block 2 starts (is buffered) as soon as block 1 is busy, block 3
/// as soon as block 2 is. The read blocks report the path velocity, positions and velocities by identity.
const LINES: &str = "PROGRAM lines
VAR
    pw1 : MC_Power;
    pw2 : MC_Power;
    pw3 : MC_Power;
    en : MC_GroupEnable;
    mv1 : MC_MoveLinearAbsolute;
    mv2 : MC_MoveLinearAbsolute;
    mv3 : MC_MoveLinearAbsolute;
    rv : MC_GroupReadActualVelocity;
    rp : MC_GroupReadActualPosition;
    rs : MC_GroupReadStatus;
    p1 : ARRAY [0..5] OF LREAL := [1600.0, 1200.0, 800.0];
    p2 : ARRAY [0..5] OF LREAL := [2200.0, 3800.0, 5000.0];
    p3 : ARRAY [0..5] OF LREAL := [4500.0, 4200.0, 4800.0];
    s1 : BOOL;
    s2 : BOOL;
    s3 : BOOL;
    powered : BOOL;
    enabled : BOOL;
    go2 : BOOL;
    go3 : BOOL;
    done1 : BOOL;
    done2 : BOOL;
    done3 : BOOL;
    err : BOOL;
    pv : LREAL;
    vel : ARRAY [0..5] OF LREAL;
    pos : ARRAY [0..5] OF LREAL;
    moving : BOOL;
END_VAR
    CAL pw1(Axis := A1, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE, Status => s1)
    CAL pw2(Axis := A2, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE, Status => s2)
    CAL pw3(Axis := A3, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE, Status => s3)
    LD s1
    AND s2
    AND s3
    ST powered
    CAL en(AxesGroup := G1, Execute := powered, Done => enabled)
    CAL mv1(AxesGroup := G1, Execute := enabled, Position := p1, Velocity := 40.0, Acceleration := 5.0,
            Deceleration := 5.0, Jerk := 2.0, BufferMode := mcAborting, Done => done1, Error => err)
    LD mv1.Busy
    S go2
    CAL mv2(AxesGroup := G1, Execute := go2, Position := p2, Velocity := 55.0, Acceleration := 5.0,
            Deceleration := 5.0, Jerk := 2.0, BufferMode := mcBlendingLow, Done => done2)
    LD mv2.Busy
    S go3
    CAL mv3(AxesGroup := G1, Execute := go3, Position := p3, Velocity := 70.0, Acceleration := 5.0,
            Deceleration := 5.0, Jerk := 2.0, BufferMode := mcBlendingHigh, Done => done3)
    CAL rv(AxesGroup := G1, Enable := TRUE, Velocity => vel, PathVelocity => pv)
    CAL rp(AxesGroup := G1, Enable := TRUE, Position => pos)
    CAL rs(AxesGroup := G1, Enable := TRUE, GroupMoving => moving)
END_PROGRAM
";

/// Three axes (jerk limit 5 mm/s³ so that the blocks' 2 mm/s³ rules) in group G1 as X, Y, Z.
const AXES: &str = r#"{ "cycle_ms": 10, "queue_depth": 8,
  "axes": [
    { "name": "A1", "unit": "mm", "velocity": 100, "acceleration": 10, "deceleration": 10, "jerk": 5 },
    { "name": "A2", "unit": "mm", "velocity": 100, "acceleration": 10, "deceleration": 10, "jerk": 5 },
    { "name": "A3", "unit": "mm", "velocity": 100, "acceleration": 10, "deceleration": 10, "jerk": 5 } ],
  "groups": [ { "name": "G1", "axes": [ { "axis": "A1", "identity": "X" },
                                        { "axis": "A2", "identity": "Y" },
                                        { "axis": "A3", "identity": "Z" } ] } ] }
"#;

const WATCH: &str = "lines.powered,lines.enabled,lines.go2,lines.go3,lines.done1,lines.done2,lines.done3,\
                     lines.err,lines.mv1.Busy,lines.mv1.Active,lines.mv2.Active,lines.mv3.Active,\
                     lines.mv1.CommandAborted,lines.pv,lines.moving,lines.pos[0],lines.pos[1],lines.pos[2],\
                     lines.vel[0],lines.vel[1],lines.vel[2],\
                     axis.A1.position,axis.A2.position,axis.A3.position,\
                     axis.A1.velocity,axis.A2.velocity,axis.A3.velocity,\
                     axis.A1.acceleration,axis.A2.acceleration,axis.A3.acceleration";

/// Cycles of 10 ms: block 3 ends at about 191 s.
const CYCLES: &str = "19300";

fn project(program: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("lines.il");
    std::fs::write(&src, program).unwrap();
    std::fs::write(dir.path().join("lines.axes.json"), AXES).unwrap();
    (dir, src)
}

fn run_trace(src: &Path, cycles: &str, extra: &[&str]) -> String {
    let trace = src.with_file_name(format!("trace{}.csv", extra.join("_").replace('-', "")));
    let out = ladderc()
        .arg("run")
        .arg(src)
        .args(["--cycles", cycles, "--watch", WATCH, "--trace"])
        .arg(&trace)
        .args(extra)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    std::fs::read_to_string(&trace).unwrap()
}

fn column(trace: &str, name: &str) -> Vec<f64> {
    let mut lines = trace.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let i = header
        .iter()
        .position(|h| *h == name)
        .unwrap_or_else(|| panic!("no column {name}"));
    lines
        .map(|l| l.split(',').nth(i).unwrap().parse::<f64>().unwrap())
        .collect()
}

fn first_rise(v: &[f64]) -> usize {
    v.iter().position(|&x| x == 1.0).expect("the signal rises")
}

#[test]
fn group_enable_and_three_linear_moves_give_identical_traces_with_both_methods() {
    let (_dir, src) = project(LINES);
    let il = run_trace(&src, CYCLES, &["--strategy", "il"]);
    let template = run_trace(&src, CYCLES, &["--strategy", "template"]);
    assert_eq!(il.lines().count(), 19301);
    for (k, (a, b)) in il.lines().zip(template.lines()).enumerate() {
        assert_eq!(a, b, "the traces differ at row {k}");
    }

    // What the run shows (paper B): the group is enabled once the axes are powered; block 1 (Aborting)
    // ends at the junction velocity min(40, 55) = 40 (BlendingLow of block 2), block 2 at max(55, 70) = 70
    // (BlendingHigh of block 3), block 3 stops at C.
    let t = &il;
    let enabled = first_rise(&column(t, "lines.enabled"));
    let (d1, d2, d3) = (
        first_rise(&column(t, "lines.done1")),
        first_rise(&column(t, "lines.done2")),
        first_rise(&column(t, "lines.done3")),
    );
    assert!(
        enabled < d1 && d1 < d2 && d2 < d3,
        "{enabled} {d1} {d2} {d3}"
    );
    assert!(column(t, "lines.err").iter().all(|&e| e == 0.0));
    assert!(column(t, "lines.mv1.CommandAborted")
        .iter()
        .all(|&e| e == 0.0));
    let pv = column(t, "lines.pv");
    assert!((pv[d1] - 40.0).abs() < 1e-6, "junction A: {}", pv[d1]);
    assert!((pv[d2] - 70.0).abs() < 1e-6, "junction B: {}", pv[d2]);
    assert!(pv.iter().all(|&v| v <= 70.0 + 1e-6));
    // the blocks' Active outputs hand over at the junctions
    let act2 = column(t, "lines.mv2.Active");
    assert_eq!(act2[d1 - 1], 0.0);
    assert_eq!(act2[d1 + 1], 1.0);
    // at the end every axis stands at C, the group no longer moves, the read block gives C by identity
    let last = il.lines().count() - 2;
    for (axis, target) in [("A1", 4500.0), ("A2", 4200.0), ("A3", 4800.0)] {
        let p = column(t, &format!("axis.{axis}.position"));
        assert!((p[last] - target).abs() < 1e-9, "{axis}: {}", p[last]);
        assert_eq!(column(t, &format!("axis.{axis}.velocity"))[last], 0.0);
    }
    assert_eq!(column(t, "lines.moving")[last], 0.0);
    assert_eq!(column(t, "lines.moving")[d1], 1.0);
    for (k, target) in [(0, 4500.0), (1, 4200.0), (2, 4800.0)] {
        let p = column(t, &format!("lines.pos[{k}]"));
        assert!((p[last] - target).abs() < 1e-9, "pos[{k}]: {}", p[last]);
    }
    // block 1 is a straight line: the velocity components keep the direction (1600, 1200, 800)
    let mid = (enabled + d1) / 2;
    let (vx, vy, vz) = (
        column(t, "lines.vel[0]")[mid],
        column(t, "lines.vel[1]")[mid],
        column(t, "lines.vel[2]")[mid],
    );
    assert!((vx / vz - 2.0).abs() < 1e-9 && (vy / vz - 1.5).abs() < 1e-9);
    assert!(((vx * vx + vy * vy + vz * vz).sqrt() - pv[mid]).abs() < 1e-9);
}

#[test]
fn group_blocks_run_sanitizer_clean_with_both_methods() {
    let (_dir, src) = project(LINES);
    let plain = run_trace(&src, "7000", &["--strategy", "il"]);
    for s in ["il", "template"] {
        let san = run_trace(&src, "7000", &["--strategy", s, "--sanitize"]);
        assert_eq!(san, plain, "--strategy {s} --sanitize");
    }
}

#[test]
fn built_group_projects_compile_warning_free_with_their_makefile() {
    let (dir, src) = project(LINES);
    for s in ["il", "template"] {
        let out_dir = dir.path().join(format!("out-{s}"));
        let out = ladderc()
            .args(["build", "--strategy", s, "-o"])
            .arg(&out_dir)
            .arg(&src)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
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
    }
}

const ONE_LINE: &str = "PROGRAM lines
VAR
    mv : MC_MoveLinearAbsolute;
    target : ARRAY [0..5] OF LREAL := [100.0, 50.0, 25.0];
    go : BOOL;
    done : BOOL;
END_VAR
    CAL mv(AxesGroup := G1, Execute := go, Position := target, Velocity := 40.0, Acceleration := 5.0,
           Deceleration := 5.0, BufferMode := mcBlendingLow, Done => done)
END_PROGRAM
";

fn build(program: &str, args: &[&str]) -> (bool, String, String) {
    let (dir, _src) = project(program);
    let out = ladderc()
        .arg("build")
        .args(args)
        .arg("lines.il")
        .current_dir(dir.path())
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn emit_il(strategy: &str) -> String {
    let (ok, out, err) = build(ONE_LINE, &["--emit", "il", "--strategy", strategy]);
    assert!(ok, "{err}");
    out
}

#[test]
fn emit_il_of_move_linear_absolute_with_the_il_method_moves_each_array_element() {
    let il = emit_il("il");
    assert_eq!(il.matches("FUNC ").count(), 1, "{il}");
    // the six elements of Position go to six consecutive LREAL slots of the TM area
    for k in 0..6 {
        assert!(
            il.contains(&format!("LD target[{k}]")),
            "element {k}:\n{il}"
        );
    }
    insta::assert_snapshot!(il);
}

#[test]
fn emit_il_of_move_linear_absolute_with_the_template_method_is_one_func() {
    let il = emit_il("template");
    assert_eq!(il.matches("FUNC ").count(), 1, "{il}");
    assert!(!il.contains("TM__"), "{il}");
    insta::assert_snapshot!(il);
}

#[test]
fn report_json_lists_the_group_blocks_with_their_tm_bytes() {
    let mut reports = Vec::new();
    for s in ["il", "template"] {
        let (dir, src) = project(LINES);
        let out = ladderc()
            .args(["build", "--report", "json", "--strategy", s, "-o"])
            .arg(dir.path().join("out"))
            .arg(&src)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let mut v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        for b in v["blocks"].as_array_mut().unwrap() {
            let size = b["object_bytes"].as_u64().expect("cc and nm are available");
            assert!(size > 50, "{b}");
            b.as_object_mut().unwrap().remove("object_bytes");
        }
        reports.push(v);
    }
    let block = |r: &serde_json::Value, name: &str| {
        r["blocks"]
            .as_array()
            .unwrap()
            .iter()
            .find(|b| b["block"] == name)
            .cloned()
            .unwrap_or_else(|| panic!("{name} in {r}"))
    };
    // AXES_GROUP_REF 4 + 6 LREAL positions 48 + Velocity .. Jerk, TransitionParameter 40 + two state
    // words 16 + ErrorID 2 + Execute, CoordSystem, BufferMode, TransitionMode 4 + five BOOL outputs 5
    let il = block(&reports[0], "MC_MoveLinearAbsolute");
    assert_eq!(il["tm_bytes"], 4 + 48 + 40 + 16 + 2 + 4 + 5);
    assert_eq!(il["calls"], 3);
    assert_eq!(il["method"], "il");
    let tpl = block(&reports[1], "MC_MoveLinearAbsolute");
    assert_eq!(tpl["tm_bytes"], 0);
    assert_eq!(tpl["il_instructions"], 3);
    // AXES_GROUP_REF 4 + two state words 16 + ErrorID 2 + Execute 1 + three BOOL outputs 3
    assert_eq!(block(&reports[0], "MC_GroupEnable")["tm_bytes"], 26);
    insta::assert_snapshot!(format!(
        "{}\n{}",
        serde_json::to_string_pretty(&reports[0]).unwrap(),
        serde_json::to_string_pretty(&reports[1]).unwrap()
    ));
}

fn check_errors(program: &str) -> String {
    let (ok, _, err) = build(
        program,
        &[
            "--emit",
            "il",
            "--message-format",
            "short",
            "--strategy",
            "il",
        ],
    );
    assert!(!ok, "{err}");
    err
}

#[test]
fn a_wrong_reference_type_an_unknown_group_and_a_single_value_for_an_array_are_reported() {
    let err = check_errors(
        &ONE_LINE
            .replace("go : BOOL;", "go : BOOL;\n    en : MC_GroupEnable;")
            .replace(
                "END_PROGRAM",
                "    CAL en(AxesGroup := A1, Execute := go)\n    CAL en(AxesGroup := G7, Execute := go)\n    \
                 CAL mv(AxesGroup := G1, Execute := go, Position := 3.0, Velocity := 1.0, Acceleration := 1.0, \
                 Deceleration := 1.0)\nEND_PROGRAM",
            ),
    );
    insta::assert_snapshot!(err);
    assert!(err.contains("AxesGroup of MC_GroupEnable is AXES_GROUP_REF, not AXIS_REF"));
    assert!(err.contains("`G7`"), "{err}");
    assert!(err.contains("ARRAY [0..5] OF LREAL"), "{err}");
}

#[test]
fn a_missing_required_group_input_is_reported_before_code_generation() {
    let err = check_errors(&ONE_LINE.replace("Position := target, ", ""));
    assert!(
        err.contains("E4023")
            && err.contains("required input `Position` of `MC_MoveLinearAbsolute`"),
        "{err}"
    );
    let err = check_errors(&ONE_LINE.replace("AxesGroup := G1, ", ""));
    assert!(
        err.contains("E4023") && err.contains("`AxesGroup`"),
        "{err}"
    );
}
