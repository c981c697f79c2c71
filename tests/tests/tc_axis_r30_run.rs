//! Round 30 of unseen TwinCAT projects (issue #13): Tc2_MC2 axes (`AXIS_REF`), end to end.
//! - an `AXIS_REF` that the .tsproj links to an NC axis but no body reads yet (a System Manager
//!   automation that links the axis before the logic is written) is that axis (before: E1057
//!   "links `MAIN.axisRef`, which is no AXIS_REF of the program");
//! - an `AXIS_REF` declared as a function block's `VAR_OUTPUT` (Beckhoff's XTS sample `Mover`:
//!   "left as output so the link can be made directly") is an axis of each instance, linked by
//!   its path and read from outside (`movers[i].AxisReference.Status.Moving`) (before: E1021
//!   "AXIS_REF has no field Status", E1057 for every link);
//! - Tc2_MC2's AXIS_REF members `PlcToNc` and `NcToPlc` / `Status` read whole are one E1042 each
//!   (Infosys, Tc2_MC2 > Data types > AXIS_REF: PlcToNc, NcToPlc, ADS, Status) (before: E1021
//!   "AXIS_REF has no field NcToPlc" with the false hint "fields of AXIS_REF: AxisNo");
//! - MC_Halt's `Options` (Infosys, Tc2_MC2 MC_Halt: `Options : ST_MoveOptions`) is E1041 in a
//!   METHOD nothing calls as in a body (before: E1011 "MC_Halt has no parameter Options" in the
//!   METHOD).

mod common;
use common::{column, in_dir, write_in};

/// A TwinCAT solution: `Cell.tsproj` with the NC axes `X` (Id 1) and `Y` (Id 2), `X` linked to
/// `MAIN.axisRef` and `Y` to `MAIN.axisY`, and the PLC project `Cell/Cell.plcproj` holding
/// `main` as `POUs/MAIN.TcPOU`.
fn cell_solution(dir: &std::path::Path, main: &str) {
    let axis = |id: u32, name: &str| {
        format!(
            r#"        <Axis Id="{id}" CreateSymbols="true" AxisType="1">
          <Name>{name}</Name>
          <AxisPara>
            <Dynamic Acceleration="1000" Deceleration="1000" Jerk="0"/>
            <Velo RefSearch="5" RefSync="2" SlowManual="10" FastManual="50" Maximum="100"/>
          </AxisPara>
        </Axis>
"#
        )
    };
    let link = |axis: &str, var: &str| {
        format!(
            r#"      <OwnerB Name="TINC^NC-Task 1 SAF^Axes^{axis}">
        <Link VarA="PlcTask Inputs^{var}.NcToPlc" VarB="Outputs^ToPlc"/>
        <Link VarA="PlcTask Outputs^{var}.PlcToNc" VarB="Inputs^FromPlc"/>
      </OwnerB>
"#
        )
    };
    write_in(
        dir,
        "Cell.tsproj",
        &format!(
            r##"<?xml version="1.0"?>
<TcSmProject TcSmVersion="1.0" TcVersion="3.1.4026.18">
  <Project ProjectGUID="{{00000000-0000-0000-0000-0000000000a1}}" TargetNetId="127.0.0.1.1.1">
    <System>
      <Tasks>
        <Task Id="3" Priority="20" CycleTime="100000" AmsPort="350">
          <Name>PlcTask</Name>
        </Task>
      </Tasks>
    </System>
    <Motion>
      <NC>
        <SafTask Priority="4" CycleTime="20000" AmsPort="501" IoAtBegin="true">
          <Name>NC-Task 1 SAF</Name>
        </SafTask>
{}{}      </NC>
    </Motion>
    <Plc>
      <Project GUID="{{00000000-0000-0000-0000-0000000000a2}}" Name="Cell" PrjFilePath="Cell\Cell.plcproj" TmcFilePath="Cell\Cell.tmc" AmsPort="851">
        <Instance Id="#x08502000" TcSmClass="TComPlcObjDef">
          <Name>Cell Instance</Name>
        </Instance>
      </Project>
    </Plc>
  </Project>
  <Mappings>
    <OwnerA Name="TIPC^Cell^Cell Instance">
{}{}    </OwnerA>
  </Mappings>
</TcSmProject>
"##,
            axis(1, "X"),
            axis(2, "Y"),
            link("X", "MAIN.axisRef"),
            link("Y", "MAIN.axisY"),
        ),
    );
    write_in(
        dir,
        "Cell/Cell.plcproj",
        r#"<?xml version="1.0" encoding="utf-8"?>
<Project DefaultTargets="Build" xmlns="http://schemas.microsoft.com/developer/msbuild/2003">
  <PropertyGroup>
    <Name>Cell</Name>
  </PropertyGroup>
  <ItemGroup>
    <Compile Include="POUs\MAIN.TcPOU">
      <SubType>Code</SubType>
    </Compile>
  </ItemGroup>
  <ItemGroup>
    <PlaceholderReference Include="Tc2_MC2">
      <DefaultResolution>Tc2_MC2, * (Beckhoff Automation GmbH)</DefaultResolution>
      <Namespace>Tc2_MC2</Namespace>
    </PlaceholderReference>
  </ItemGroup>
</Project>
"#,
    );
    write_in(dir, "Cell/POUs/MAIN.TcPOU", main);
}

/// B1 (bstiffler582/TcSysManAutomation): MAIN declares `axisRef : AXIS_REF;` and no body reads
/// it yet, while the .tsproj links the NC axis `X` to it (the System Manager links an axis to a
/// declared AXIS_REF before the logic is written). The link is valid: the project runs, and the
/// other axis `Y`, linked to `MAIN.axisY` that the body moves, moves at 10 units/s (0.1 a
/// 10 ms scan once accelerated). Before: exit 1, E1057 "axis `X` links `MAIN.axisRef`, which is
/// no AXIS_REF of the program"; and the `.plcproj` given relative to the working folder
/// (`Cell/Cell.plcproj`) found no .tsproj above it (E1056 for `MAIN.axisY`).
#[test]
fn an_axis_ref_the_tsproj_links_but_no_body_reads_yet_is_that_axis() {
    let dir = tempfile::tempdir().unwrap();
    cell_solution(
        dir.path(),
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4026.18">
  <POU Name="MAIN" Id="{00000000-0000-0000-0000-0000000000a3}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
	axisRef : AXIS_REF;
	axisY : AXIS_REF;
	power : MC_Power;
	move : MC_MoveVelocity;
	fPosY : LREAL;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[power(Axis := axisY, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);
move(Axis := axisY, Execute := TRUE, Velocity := 10.0, Direction := MC_Positive_Direction);
fPosY := axisY.NcToPlc.ActPos;
]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
"#,
    );
    let (code, _, stderr) = in_dir(dir.path(), &["check", "Cell/Cell.plcproj"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        !stderr.contains("E1057") && !stderr.contains("E1056"),
        "{stderr}"
    );
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "Cell/Cell.plcproj",
            "--cycles",
            "6",
            "--cycle-ms",
            "10",
            "--trace",
            "-",
            "--watch",
            "MAIN.fPosY",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    let pos = column(&trace, "MAIN.fPosY");
    assert_eq!(pos.len(), 6, "{trace}");
    // standing at 0.0 in the first scan, then moving forward at 10 units/s (0.1 per scan)
    assert_eq!(pos[0], 0.0, "{trace}");
    for k in 2..6 {
        assert!(
            (pos[k] - pos[k - 1] - 0.1).abs() < 1e-9,
            "cycle {k}: {pos:?}"
        );
    }
}

/// B7 (nijaz123/XTS_AO, Beckhoff's XTS sample `Mover`): `AxisReference : AXIS_REF` declared as
/// FB_Mover's VAR_OUTPUT is an axis of each instance, linked by the axes file's `"link"`
/// (`MAIN.one.AxisReference`, `MAIN.movers[2].AxisReference`), powered inside the block and
/// moved and read from outside. Only `movers[2]`'s axis moves: `movers[i].AxisReference.Status.
/// Moving` (i = 2) is TRUE from the first move and its `NcToPlc.ActPos` grows 0.1 a scan at
/// 10 units/s; `movers[1]`'s and `one`'s stand at 0.0. Before: exit 1, E1021 "AXIS_REF has no
/// field `Status`" (hint: "fields of AXIS_REF: AxisNo") and E1057 for each of the three links.
#[test]
fn an_axis_ref_that_is_a_function_blocks_output_is_an_axis_of_each_instance() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "mover.st",
        "FUNCTION_BLOCK FB_Mover
VAR_OUTPUT
    AxisReference : AXIS_REF;
    bMoving : BOOL;
END_VAR
VAR
    power : MC_Power;
END_VAR
power(Axis := AxisReference, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);
bMoving := AxisReference.Status.Moving;
END_FUNCTION_BLOCK

PROGRAM MAIN
VAR
    one : FB_Mover;
    movers : ARRAY[1..2] OF FB_Mover;
    move : MC_MoveVelocity;
    i : INT := 2;
    bMoving1, bMoving2, bMovingOne, bInside2 : BOOL;
    fPos2, fPosOne : LREAL;
END_VAR
one();
movers[1]();
movers[2]();
move(Axis := movers[2].AxisReference, Execute := TRUE, Velocity := 10.0,
     Direction := MC_Positive_Direction);
movers[i].AxisReference.ReadStatus();
bMoving2 := movers[i].AxisReference.Status.Moving;
bMoving1 := movers[1].AxisReference.Status.Moving;
bMovingOne := one.AxisReference.Status.Moving;
bInside2 := movers[2].bMoving;
fPos2 := movers[2].AxisReference.NcToPlc.ActPos;
fPosOne := one.AxisReference.NcToPlc.ActPos;
END_PROGRAM
",
    );
    write_in(
        dir.path(),
        "mover.axes.json",
        r#"{ "axes": [
  { "name": "A1", "link": "MAIN.one.AxisReference", "velocity": 100.0, "acceleration": 1000.0, "deceleration": 1000.0 },
  { "name": "A2", "link": "MAIN.movers[1].AxisReference", "velocity": 100.0, "acceleration": 1000.0, "deceleration": 1000.0 },
  { "name": "A3", "link": "MAIN.movers[2].AxisReference", "velocity": 100.0, "acceleration": 1000.0, "deceleration": 1000.0 } ] }"#,
    );
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "mover.st",
            "--cycles",
            "6",
            "--cycle-ms",
            "10",
            "--trace",
            "-",
            "--watch",
            "MAIN.bMoving1,MAIN.bMoving2,MAIN.bMovingOne,MAIN.bInside2,MAIN.fPos2,MAIN.fPosOne",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(
        column(&trace, "MAIN.bMoving2"),
        [0.0, 1.0, 1.0, 1.0, 1.0, 1.0]
    );
    // (the block reads its axis's status at the start of its call, before MAIN's move)
    assert_eq!(
        column(&trace, "MAIN.bInside2"),
        [0.0, 1.0, 1.0, 1.0, 1.0, 1.0]
    );
    assert_eq!(column(&trace, "MAIN.bMoving1"), [0.0; 6]);
    assert_eq!(column(&trace, "MAIN.bMovingOne"), [0.0; 6]);
    assert_eq!(column(&trace, "MAIN.fPosOne"), [0.0; 6]);
    let pos = column(&trace, "MAIN.fPos2");
    assert_eq!(pos[0], 0.0, "{trace}");
    for k in 2..6 {
        assert!(
            (pos[k] - pos[k - 1] - 0.1).abs() < 1e-9,
            "cycle {k}: {pos:?}"
        );
    }
}

/// The error lines (short format) of `ladderc check FILE` in `dir`, with exit 1.
fn errors_of(dir: &std::path::Path, file: &str) -> Vec<String> {
    let (code, _, stderr) = in_dir(dir, &["check", file]);
    assert_eq!(code, Some(1), "{stderr}");
    stderr
        .lines()
        .filter(|l| l.contains("error[") || l.contains("warning["))
        .map(|l| l.split_once(" (hint").map_or(l, |(h, _)| h).to_string())
        .collect()
}

/// B2 (zhaoshutao/HEPSPLC `LeftTopLin.NcToPlc`, TC_XboxController `Axis.PlcToNc.Override`):
/// Tc2_MC2's AXIS_REF members that ladderc's simulated axis has no value for are one E1042 each,
/// at the member: `NcToPlc` and `Status` read whole, `PlcToNc.AxisModeRequest` read and written; the
/// store is left out (no follow-on W1001). `NcToPlc.ActPos` next to them stays accepted (and, since
/// round 31, `PlcToNc.Override`: `tc_r31_run.rs`; here `PlcToNc.AxisModeRequest`). Before:
/// E1021 "AXIS_REF has no field `NcToPlc`" / `PlcToNc`, with the false hint "fields of AXIS_REF:
/// AxisNo".
#[test]
fn tc2_axis_ref_members_without_a_counterpart_are_e1042_not_unknown_fields() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "whole.st",
        "PROGRAM MAIN
VAR
    ax : AXIS_REF;
    n : DINT;
    f : LREAL;
    o : UDINT;
    b : BOOL;
END_VAR
n := SIZEOF(ax.NcToPlc);
f := ax.NcToPlc.ActPos;
o := ax.PlcToNc.AxisModeRequest;
ax.PlcToNc.AxisModeRequest := 5;
b := TRUE;
b := ax.Status;
END_PROGRAM
",
    );
    write_in(
        dir.path(),
        "whole.axes.json",
        r#"{ "axes": [ { "name": "ax", "velocity": 100.0, "acceleration": 1000.0, "deceleration": 1000.0 } ] }"#,
    );
    let lines = errors_of(dir.path(), "whole.st");
    assert_eq!(
        lines,
        [
            "whole.st:9:16: error[E1042]: AXIS_REF's `NcToPlc` has no counterpart in ladderc's simulated axis",
            "whole.st:11:9: error[E1042]: AXIS_REF's `PlcToNc.AxisModeRequest` has no counterpart in ladderc's simulated axis",
            "whole.st:12:4: error[E1042]: AXIS_REF's `PlcToNc.AxisModeRequest` has no counterpart in ladderc's simulated axis",
            "whole.st:14:9: error[E1042]: AXIS_REF's `Status` has no counterpart in ladderc's simulated axis",
        ],
    );
    let (_, _, stderr) = in_dir(dir.path(), &["check", "whole.st"]);
    assert!(stderr.contains("read its members one by one"), "{stderr}");
    assert!(!stderr.contains("fields of AXIS_REF: AxisNo"), "{stderr}");
}

/// B10 (TC_XboxController `FB_Xbox_1D_Joystick_NC`, METHOD `Jog`): Tc2_MC2's MC_Halt has an
/// `Options : ST_MoveOptions` input that ladderc's axis has no counterpart for: E1041, in a
/// METHOD nothing calls (checked on its own) as in the block's body, one each, at the pin.
/// Before: the METHOD's call was E1011 "MC_Halt has no parameter `Options`", with a hint listing
/// MC_Halt's pins without it.
#[test]
fn mc_halt_options_is_e1041_in_a_method_as_in_a_body() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "jog.st",
        "TYPE ST_Opt :
STRUCT
    x : BOOL;
END_STRUCT;
END_TYPE

FUNCTION_BLOCK FB_Jog
VAR_IN_OUT
    Ax : AXIS_REF;
END_VAR
VAR
    fbHalt : MC_Halt;
    fbHalt2 : MC_Halt;
    o : ST_Opt;
END_VAR
METHOD Jog
VAR_INPUT
    Axis : REFERENCE TO AXIS_REF;
    opt : ST_Opt;
END_VAR
fbHalt(Axis := Axis, Execute := TRUE, Options := opt);
END_METHOD
fbHalt2(Axis := Ax, Execute := TRUE, Options := o);
END_FUNCTION_BLOCK
",
    );
    let lines = errors_of(dir.path(), "jog.st");
    assert_eq!(
        lines,
        [
            "jog.st:21:39: error[E1041]: Tc2_MC2's `Options` of MC_Halt has no counterpart in ladderc's simulated axis",
            "jog.st:23:38: error[E1041]: Tc2_MC2's `Options` of MC_Halt has no counterpart in ladderc's simulated axis",
        ],
    );
}
