//! PLCopen Part 4 (axes group) blocks end to end: a 3-axis group of the axis file, MC_GroupEnable and paper
//! B's three MC_MoveLinearAbsolute blocks (Aborting, BlendingLow, BlendingHigh), through both parameter-passing
//! methods; array parameters (Position, the read blocks' Position/Velocity outputs), the report, `--emit il`,
//! and the legality checks before code generation.

mod common;
use common::ladderc;

use std::path::{Path, PathBuf};
use std::process::Command;

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
    grs : MC_GroupReadStatus;
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
    CAL grs(AxesGroup := G1, Enable := TRUE, GroupMoving => moving)
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

/// Cycles of 10 ms: block 3 ends at about 218.3 s (the TMNone corners are passed at rest).
const CYCLES: &str = "22000";

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
    common::assert_ok(&out);
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
    assert_eq!(il.lines().count(), 22001);
    for (k, (a, b)) in il.lines().zip(template.lines()).enumerate() {
        assert_eq!(a, b, "the traces differ at row {k}");
    }

    // What the run shows (paper B): the group is enabled once the axes are powered; block 1 (Aborting)
    // would end at the junction velocity min(40, 55) = 40 (BlendingLow of block 2), block 2 at
    // max(55, 70) = 70 (BlendingHigh of block 3), but at these TMNone corners no speed keeps the axis
    // limits: both are passed at rest (and reported), block 3 stops at C.
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
    assert!(pv[d1].abs() < 1e-9, "junction A: {}", pv[d1]);
    assert!(pv[d2].abs() < 1e-9, "junction B: {}", pv[d2]);
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
        common::assert_ok(&out);
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
        let v = common::block_report(&src, &dir.path().join("out"), s, 50);
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
    // AxesGroup is a VAR_IN_OUT: an unconnected one is E1033 for every block (CODESYS's C0039),
    // reported once and before the motion lowering's E4023 would be
    let err = check_errors(&ONE_LINE.replace("AxesGroup := G1, ", ""));
    assert!(
        err.contains("lines.il:8:5: error[E1033]: VAR_IN_OUT `AxesGroup` of MC_MoveLinearAbsolute is not connected")
            && err.matches("error[").count() == 1,
        "{err}"
    );
}

/// A ladder network (PLCopen XML): MC_Power on X1 and Y1 (the second enabled by the first's Status),
/// MC_GroupEnable of G1 when both are powered, then MC_MoveLinearAbsolute to the array variable `Target`.
/// Several blocks of one network once shared their lowered instructions' spans, which mixed their types
/// with the IL method (the second MC_Power then powered X1 again and the group refused to enable).
const LADDER: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="ladderc" productName="tests" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="lgroup"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="lgroup" pouType="program">
      <interface><localVars>
        <variable name="Powered"><type><BOOL/></type></variable>
        <variable name="Enabled"><type><BOOL/></type></variable>
        <variable name="Done"><type><BOOL/></type></variable>
        <variable name="Target"><type><array><dimension lower="0" upper="5"/><baseType><LREAL/></baseType></array></type>
          <initialValue><arrayValue><value><simpleValue value="100.0"/></value><value><simpleValue value="50.0"/></value></arrayValue></initialValue></variable>
        <variable name="pw1"><type><derived name="MC_Power"/></type></variable>
        <variable name="pw2"><type><derived name="MC_Power"/></type></variable>
        <variable name="en"><type><derived name="MC_GroupEnable"/></type></variable>
        <variable name="mv"><type><derived name="MC_MoveLinearAbsolute"/></type></variable>
      </localVars></interface>
      <body><LD>
        <leftPowerRail localId="1" executionOrderId="1"><position x="10" y="50"/>
          <connectionPointOut formalParameter=""/></leftPowerRail>
        <inVariable localId="2" executionOrderId="2"><position x="40" y="90"/><expression>X1</expression></inVariable>
        <inVariable localId="20" executionOrderId="2"><position x="40" y="90"/><expression>Y1</expression></inVariable>
        <block localId="3" typeName="MC_Power" instanceName="pw1" executionOrderId="3"><position x="100" y="50"/>
          <inputVariables>
            <variable formalParameter="Enable"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
          </inputVariables>
          <inOutVariables>
            <variable formalParameter="Axis"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
          </inOutVariables>
          <outputVariables>
            <variable formalParameter="Status"><connectionPointOut/></variable>
          </outputVariables>
        </block>
        <block localId="21" typeName="MC_Power" instanceName="pw2" executionOrderId="4"><position x="200" y="50"/>
          <inputVariables>
            <variable formalParameter="Enable"><connectionPointIn><connection refLocalId="3" formalParameter="Status"/></connectionPointIn></variable>
          </inputVariables>
          <inOutVariables>
            <variable formalParameter="Axis"><connectionPointIn><connection refLocalId="20"/></connectionPointIn></variable>
          </inOutVariables>
          <outputVariables>
            <variable formalParameter="Status"><connectionPointOut/></variable>
          </outputVariables>
        </block>
        <coil localId="4" executionOrderId="5"><position x="300" y="50"/>
          <connectionPointIn><connection refLocalId="21" formalParameter="Status"/></connectionPointIn>
          <variable>Powered</variable></coil>
        <contact localId="5" executionOrderId="6"><position x="40" y="150"/>
          <connectionPointIn><connection refLocalId="1"/></connectionPointIn>
          <variable>Powered</variable></contact>
        <inVariable localId="6" executionOrderId="7"><position x="40" y="190"/><expression>G1</expression></inVariable>
        <block localId="7" typeName="MC_GroupEnable" instanceName="en" executionOrderId="8"><position x="100" y="150"/>
          <inputVariables>
            <variable formalParameter="Execute"><connectionPointIn><connection refLocalId="5"/></connectionPointIn></variable>
          </inputVariables>
          <inOutVariables>
            <variable formalParameter="AxesGroup"><connectionPointIn><connection refLocalId="6"/></connectionPointIn></variable>
          </inOutVariables>
          <outputVariables>
            <variable formalParameter="Done"><connectionPointOut/></variable>
          </outputVariables>
        </block>
        <coil localId="8" executionOrderId="9"><position x="200" y="150"/>
          <connectionPointIn><connection refLocalId="7" formalParameter="Done"/></connectionPointIn>
          <variable>Enabled</variable></coil>
        <contact localId="9" executionOrderId="10"><position x="40" y="250"/>
          <connectionPointIn><connection refLocalId="1"/></connectionPointIn>
          <variable>Enabled</variable></contact>
        <inVariable localId="10" executionOrderId="11"><position x="40" y="290"/><expression>Target</expression></inVariable>
        <inVariable localId="11" executionOrderId="12"><position x="40" y="310"/><expression>20.0</expression></inVariable>
        <inVariable localId="12" executionOrderId="13"><position x="40" y="330"/><expression>100.0</expression></inVariable>
        <inVariable localId="13" executionOrderId="14"><position x="40" y="350"/><expression>mcBlendingLow</expression></inVariable>
        <block localId="14" typeName="MC_MoveLinearAbsolute" instanceName="mv" executionOrderId="15"><position x="100" y="250"/>
          <inputVariables>
            <variable formalParameter="Execute"><connectionPointIn><connection refLocalId="9"/></connectionPointIn></variable>
            <variable formalParameter="Position"><connectionPointIn><connection refLocalId="10"/></connectionPointIn></variable>
            <variable formalParameter="Velocity"><connectionPointIn><connection refLocalId="11"/></connectionPointIn></variable>
            <variable formalParameter="Acceleration"><connectionPointIn><connection refLocalId="12"/></connectionPointIn></variable>
            <variable formalParameter="Deceleration"><connectionPointIn><connection refLocalId="12"/></connectionPointIn></variable>
            <variable formalParameter="BufferMode"><connectionPointIn><connection refLocalId="13"/></connectionPointIn></variable>
          </inputVariables>
          <inOutVariables>
            <variable formalParameter="AxesGroup"><connectionPointIn><connection refLocalId="6"/></connectionPointIn></variable>
          </inOutVariables>
          <outputVariables>
            <variable formalParameter="Done"><connectionPointOut/></variable>
          </outputVariables>
        </block>
        <coil localId="15" executionOrderId="16"><position x="200" y="250"/>
          <connectionPointIn><connection refLocalId="14" formalParameter="Done"/></connectionPointIn>
          <variable>Done</variable></coil>
      </LD></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#;

const LADDER_AXES: &str = r#"{ "cycle_ms": 10,
  "axes": [ { "name": "X1", "unit": "mm", "velocity": 100, "acceleration": 500, "deceleration": 500 },
            { "name": "Y1", "unit": "mm", "velocity": 100, "acceleration": 500, "deceleration": 500 } ],
  "groups": [ { "name": "G1", "axes": [ { "axis": "X1", "identity": "X" }, { "axis": "Y1", "identity": "Y" } ] } ] }
"#;

#[test]
fn a_ladder_network_with_group_blocks_runs_identically_with_both_methods() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("lgroup.xml");
    std::fs::write(&src, LADDER).unwrap();
    std::fs::write(dir.path().join("lgroup.axes.json"), LADDER_AXES).unwrap();
    let mut traces = Vec::new();
    for s in ["il", "template"] {
        let trace = dir.path().join(format!("{s}.csv"));
        let out = ladderc()
            .arg("run")
            .arg(&src)
            .args([
                "--strategy",
                s,
                "--cycles",
                "700",
                "--watch",
                "lgroup.Powered,lgroup.Enabled,lgroup.Done,lgroup.en.ErrorID,axis.X1.position,axis.Y1.position",
                "--trace",
            ])
            .arg(&trace)
            .output()
            .unwrap();
        common::assert_ok(&out);
        traces.push(std::fs::read_to_string(&trace).unwrap());
    }
    assert_eq!(traces[0], traces[1]);
    let t = &traces[0];
    assert_eq!(column(t, "lgroup.Enabled")[1], 1.0, "the group is enabled");
    assert!(column(t, "lgroup.en.ErrorID").iter().all(|&e| e == 0.0));
    let done = first_rise(&column(t, "lgroup.Done"));
    assert_eq!(column(t, "axis.X1.position")[done], 100.0);
    assert_eq!(column(t, "axis.Y1.position")[done], 50.0);
}

/// Every Part 4 block in one sequence, each started by the previous one's Done: the group G1 starts empty
/// (axes file), MC_AddAxisToGroup adds X1 and Y1, MC_GroupEnable, MC_GroupHome at 0, a relative line by
/// (10, 10), a clockwise arc about the centre (10, 0) to (20, 0), a relative arc through (+5, +5) to
/// (+10, 0), a direct move to (0, 5), a line to (40, 40), MC_GroupHalt, MC_GroupStop, MC_GroupReset,
/// MC_GroupDisable (once in standby), MC_RemoveAxisFromGroup, MC_UngroupAllAxes; the read blocks run
/// every scan. `errors` collects every ErrorID.
const ALL_BLOCKS: &str = r#"PROGRAM allg
VAR
    pw1 : MC_Power;
    pw2 : MC_Power;
    add1 : MC_AddAxisToGroup;
    add2 : MC_AddAxisToGroup;
    en : MC_GroupEnable;
    home : MC_GroupHome;
    rel : MC_MoveLinearRelative;
    circ : MC_MoveCircularAbsolute;
    crel : MC_MoveCircularRelative;
    direct : MC_MoveDirectAbsolute;
    lin : MC_MoveLinearAbsolute;
    halt : MC_GroupHalt;
    stop : MC_GroupStop;
    reset : MC_GroupReset;
    dis : MC_GroupDisable;
    rem : MC_RemoveAxisFromGroup;
    ung : MC_UngroupAllAxes;
    rp : MC_GroupReadActualPosition;
    rv : MC_GroupReadActualVelocity;
    grs : MC_GroupReadStatus;
    zero : ARRAY [0..5] OF LREAL;
    dist : ARRAY [0..5] OF LREAL := [10.0, 10.0];
    centre : ARRAY [0..5] OF LREAL := [10.0, 0.0];
    cend : ARRAY [0..5] OF LREAL := [20.0, 0.0];
    aux : ARRAY [0..5] OF LREAL := [5.0, 5.0];
    rend : ARRAY [0..5] OF LREAL := [10.0, 0.0];
    dpos : ARRAY [0..5] OF LREAL := [0.0, 5.0];
    lpos : ARRAY [0..5] OF LREAL := [40.0, 40.0];
    pos : ARRAY [0..5] OF LREAL;
    vel : ARRAY [0..5] OF LREAL;
    pv : LREAL;
    powered : BOOL;
    stopped : BOOL;
    go_stop : BOOL;
    go_dis : BOOL;
    standby : BOOL;
    disabled : BOOL;
    errors : WORD;
END_VAR
    CAL pw1(Axis := X1, Enable := TRUE)
    CAL pw2(Axis := Y1, Enable := TRUE)
    LD pw1.Status
    AND pw2.Status
    ST powered
    CAL add1(AxesGroup := G1, Axis := X1, Execute := powered, IdentInGroup := 0)
    CAL add2(AxesGroup := G1, Axis := Y1, Execute := add1.Done, IdentInGroup := 1)
    CAL en(AxesGroup := G1, Execute := add2.Done)
    CAL home(AxesGroup := G1, Execute := en.Done, Position := zero)
    CAL rel(AxesGroup := G1, Execute := home.Done, Distance := dist, Velocity := 20.0, Acceleration := 100.0, Deceleration := 100.0)
    CAL circ(AxesGroup := G1, Execute := rel.Done, CircMode := mcCenter, AuxPoint := centre, EndPoint := cend,
             PathChoice := mcClockwise, Velocity := 20.0, Acceleration := 100.0, Deceleration := 100.0)
    CAL crel(AxesGroup := G1, Execute := circ.Done, CircMode := mcBorder, AuxPoint := aux, EndPoint := rend,
             PathChoice := mcClockwise, Velocity := 20.0, Acceleration := 100.0, Deceleration := 100.0)
    CAL direct(AxesGroup := G1, Execute := crel.Done, Position := dpos, Velocity := 20.0, Acceleration := 100.0, Deceleration := 100.0)
    CAL lin(AxesGroup := G1, Execute := direct.Done, Position := lpos, Velocity := 20.0, Acceleration := 100.0,
            Deceleration := 100.0, Jerk := 1000.0)
    CAL halt(AxesGroup := G1, Execute := lin.Done, Deceleration := 100.0)
    LD halt.Done
    ANDN stopped
    ST go_stop
    CAL stop(AxesGroup := G1, Execute := go_stop, Deceleration := 100.0)
    LD stop.Done
    S stopped
    CAL reset(AxesGroup := G1, Execute := stopped)
    LD reset.Done
    AND standby
    ST go_dis
    CAL dis(AxesGroup := G1, Execute := go_dis)
    CAL rem(AxesGroup := G1, Execute := dis.Done, IdentInGroup := 1)
    CAL ung(AxesGroup := G1, Execute := rem.Done)
    CAL rp(AxesGroup := G1, Enable := TRUE, Position => pos)
    CAL rv(AxesGroup := G1, Enable := TRUE, Velocity => vel, PathVelocity => pv)
    CAL grs(AxesGroup := G1, Enable := TRUE, GroupStandby => standby, GroupDisabled => disabled)
    LD add1.ErrorID
    OR add2.ErrorID
    OR en.ErrorID
    OR home.ErrorID
    OR rel.ErrorID
    OR circ.ErrorID
    OR crel.ErrorID
    OR direct.ErrorID
    OR lin.ErrorID
    OR halt.ErrorID
    OR stop.ErrorID
    OR reset.ErrorID
    OR dis.ErrorID
    OR rem.ErrorID
    OR ung.ErrorID
    OR errors
    ST errors
END_PROGRAM
"#;

const ALL_AXES: &str = r#"{ "cycle_ms": 10, "queue_depth": 4,
  "axes": [ { "name": "X1", "unit": "mm", "velocity": 100, "acceleration": 1000, "deceleration": 1000 },
            { "name": "Y1", "unit": "mm", "velocity": 100, "acceleration": 1000, "deceleration": 1000 } ],
  "groups": [ { "name": "G1", "axes": [] } ] }
"#;

const ALL_DONES: [&str; 14] = [
    "add2", "en", "home", "rel", "circ", "crel", "direct", "lin", "halt", "stop", "reset", "dis",
    "rem", "ung",
];

fn all_blocks_project() -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("allg.il");
    std::fs::write(&src, ALL_BLOCKS).unwrap();
    std::fs::write(dir.path().join("allg.axes.json"), ALL_AXES).unwrap();
    (dir, src)
}

#[test]
fn every_group_block_runs_in_sequence_identically_with_both_methods() {
    let (dir, src) = all_blocks_project();
    let mut watch: Vec<String> = ALL_DONES.iter().map(|b| format!("allg.{b}.Done")).collect();
    watch.extend(
        [
            "allg.errors",
            "allg.standby",
            "allg.disabled",
            "allg.pos[0]",
            "allg.pos[1]",
            "allg.vel[0]",
            "allg.pv",
            "axis.X1.position",
            "axis.Y1.position",
        ]
        .map(String::from),
    );
    let mut traces = Vec::new();
    for s in ["il", "template"] {
        let trace = dir.path().join(format!("{s}.csv"));
        let out = ladderc()
            .arg("run")
            .arg(&src)
            .args([
                "--strategy",
                s,
                "--cycles",
                "900",
                "--watch",
                &watch.join(","),
                "--trace",
            ])
            .arg(&trace)
            .output()
            .unwrap();
        common::assert_ok(&out);
        traces.push(std::fs::read_to_string(&trace).unwrap());
    }
    for (k, (a, b)) in traces[0].lines().zip(traces[1].lines()).enumerate() {
        assert_eq!(a, b, "the traces differ at row {k}");
    }
    let t = &traces[0];
    assert!(
        column(t, "allg.errors").iter().all(|&e| e == 0.0),
        "no block failed"
    );
    // each block completes, in order
    let dones: Vec<usize> = ALL_DONES
        .iter()
        .map(|b| first_rise(&column(t, &format!("allg.{b}.Done"))))
        .collect();
    assert!(dones.windows(2).all(|w| w[0] <= w[1]), "{dones:?}");
    let (x, y) = (column(t, "axis.X1.position"), column(t, "axis.Y1.position"));
    let at = |b: &str| dones[ALL_DONES.iter().position(|n| *n == b).unwrap()];
    for (block, ex, ey) in [
        ("rel", 10.0, 10.0),
        ("circ", 20.0, 0.0),
        ("crel", 30.0, 0.0),
        ("direct", 0.0, 5.0),
        ("lin", 40.0, 40.0),
    ] {
        // Done shows in the scan after the target was reached (the next block then starts at once)
        let k = at(block) - 1;
        assert!(
            (x[k] - ex).abs() < 1e-6 && (y[k] - ey).abs() < 1e-6,
            "{block}: ({}, {})",
            x[k],
            y[k]
        );
    }
    // on the arc about (10, 0) the distance to the centre stays 10
    for k in at("rel") - 1..at("circ") {
        let r = ((x[k] - 10.0).powi(2) + y[k].powi(2)).sqrt();
        assert!((r - 10.0).abs() < 1e-6, "cycle {k}: radius {r}");
    }
    // the read block reports the positions by identity (one scan behind the engine step)
    let px = column(t, "allg.pos[0]");
    assert_eq!(px[at("lin")], 40.0);
    // standby after the stop, disabled after MC_GroupDisable, for good after MC_UngroupAllAxes
    let disabled = column(t, "allg.disabled");
    assert_eq!(column(t, "allg.standby")[at("dis") - 1], 1.0);
    assert!(disabled[at("ung")..].iter().all(|&d| d == 1.0));
    assert!(disabled[at("en")..at("dis")].iter().all(|&d| d == 0.0));
}

#[test]
fn report_json_gives_the_figures_of_every_group_block_for_both_methods() {
    let (dir, src) = all_blocks_project();
    let mut table =
        String::from("block | IL: TM bytes, IL instructions, C bytes | template: TM bytes, IL instructions, C bytes\n");
    let mut rows: std::collections::BTreeMap<String, Vec<String>> = Default::default();
    for s in ["il", "template"] {
        let out = ladderc()
            .args(["build", "--report", "json", "--strategy", s, "-o"])
            .arg(dir.path().join(format!("out-{s}")))
            .arg(&src)
            .output()
            .unwrap();
        common::assert_ok(&out);
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        for b in v["blocks"].as_array().unwrap() {
            assert_eq!(b["method"], s);
            assert!(b["object_bytes"].as_u64().is_some_and(|n| n > 0), "{b}");
            rows.entry(b["block"].as_str().unwrap().to_string())
                .or_default()
                .push(format!(
                    "{}, {}, {}",
                    b["tm_bytes"], b["il_instructions"], b["c_bytes"]
                ));
        }
    }
    // 17 group blocks and MC_Power
    assert_eq!(rows.len(), 18, "{rows:?}");
    for (block, r) in &rows {
        table.push_str(&format!("{block} | {} | {}\n", r[0], r[1]));
    }
    insta::assert_snapshot!(table);
}

#[test]
fn a_user_template_with_a_bad_array_declaration_is_reported_in_its_file() {
    let (dir, _src) = project(ONE_LINE);
    let tpl = dir.path().join("vendor");
    std::fs::create_dir(&tpl).unwrap();
    std::fs::write(
        tpl.join("MC_MoveLinearAbsolute.xml"),
        r#"<blockTemplate name="MC_MoveLinearAbsolute" funcNum="42">
  <parameters>
    <param name="AxesGroup" abbr="AxG" direction="inout" class="struct" type="AXES_GROUP_REF" required="true"/>
    <param name="Position" abbr="Pos" direction="input" class="array" element="lreal" type="LREAL" length="32"/>
  </parameters>
  <body><![CDATA[ (void)AxG; (void)Pos; ]]></body>
</blockTemplate>
"#,
    )
    .unwrap();
    let (ok, _, err) = build(
        ONE_LINE,
        &[
            "--emit",
            "il",
            "--message-format",
            "short",
            "--templates",
            tpl.to_str().unwrap(),
        ],
    );
    assert!(!ok);
    let file = tpl.join("MC_MoveLinearAbsolute.xml");
    // line 4 of the user's file, at the `length` attribute
    let at = format!("{}:4:", file.display());
    let line = err
        .lines()
        .find(|l| l.starts_with(&at))
        .unwrap_or_else(|| panic!("{err}"));
    assert!(
        line.contains("error[E4102]: array `Position`: length `32` is not a number from 1 to 16"),
        "{line}"
    );
    let column: usize = line[at.len()..].split(':').next().unwrap().parse().unwrap();
    let text = std::fs::read_to_string(&file).unwrap();
    assert!(text.lines().nth(3).unwrap()[column - 1..].starts_with("length="));
}
