//! Round 31 of issue #13: TwinCAT leftovers of rounds 29 and 30, end to end.
//! - Tc2_MC2's AXIS_REF members through a `REFERENCE TO AXIS_REF` or `POINTER TO AXIS_REF`
//!   (TC_XboxController's `FB_Xbox_*_NC` blocks: `Axis.PlcToNc.Override`, `Axis.NcToPlc.ActPos`)
//!   read the axis the reference is bound to; `PlcToNc.Override` (Infosys, Tc2_MC2 >
//!   PLCTONC_AXIS_REF: `Override : UDINT`, "velocity override", 1000000 = 100 %) is the NC's
//!   velocity override, written and read back; an unbound reference (Infosys, "REFERENCE":
//!   "TwinCAT initializes references (with 0)", `__ISVALIDREF`) is never dereferenced: its
//!   members read 0 / FALSE, a write into it is dropped (before: E1021 "AXIS_REF has no field
//!   `PlcToNc`" with the hint "fields of AXIS_REF: AxisNo", 17 in TC_XboxController);
//! - a TwinCAT CFC box whose instance is `SUPER^` (Beckhoff's TF8040 templates) calls the base
//!   block's body, as `SUPER^()` in ST (Infosys, TC3 PLC, "SUPER") (before: E0326 "box
//!   `FB_BA_View` does not name its instance or program (`SUPER^`)", 59 in TF8040 Templates).

mod common;
use common::{
    cfc::{cfc_input, cfc_output, cfc_pin, cfc_wire},
    column, in_dir, write_in,
};

/// Runs `file` in `dir` for `cycles` 10 ms scans with the sanitizers, tracing `watch`: the trace.
fn run_in(dir: &std::path::Path, file: &str, cycles: u32, watch: &str) -> String {
    let (code, trace, stderr) = in_dir(
        dir,
        &[
            "run",
            file,
            "--cycles",
            &cycles.to_string(),
            "--cycle-ms",
            "10",
            "--sanitize",
            "--trace",
            "-",
            "--watch",
            watch,
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        !stderr.contains("Sanitizer") && !stderr.contains("runtime error"),
        "{stderr}"
    );
    trace
}

/// The axes file of one axis `A1` linked to `MAIN.ax` (100 units/s, 1000 units/s²).
const ONE_AXIS: &str = r#"{ "axes": [ { "name": "A1", "link": "MAIN.ax", "velocity": 100.0, "acceleration": 1000.0, "deceleration": 1000.0 } ] }"#;

/// TC_XboxController's pattern: a jog block holds `Axis : REFERENCE TO AXIS_REF`, moves it with
/// MC_MoveVelocity at 10 units/s, remembers `Axis.PlcToNc.Override` before writing its own and
/// reads `Axis.NcToPlc.ActPos`. From the 5th scan it writes 500000 (50 %): the axis slows from
/// 0.1 to 0.05 units a scan (jerk-limited, within a few scans), the override reads back 500000
/// in the block and in MAIN (`ax.PlcToNc.Override`), from the scan it is written, and the
/// value the block remembers is 1000000 (100 %, the NC's start value) up to then. A second
/// instance whose reference is never bound reads 0 for every member and its write of 250000 is
/// dropped (no NULL dereference under the sanitizers). Before: E1021 "AXIS_REF has no field
/// `NcToPlc`" / `PlcToNc` with the hint "fields of AXIS_REF: AxisNo".
#[test]
fn an_axis_through_a_reference_moves_and_reads_back_its_override() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "jog.st",
        "FUNCTION_BLOCK FB_Jog
VAR_INPUT
    Axis : REFERENCE TO AXIS_REF;
    nOverride : UDINT;
END_VAR
VAR_OUTPUT
    fPos : LREAL;
    bMoving : BOOL;
    nOverrideNow : UDINT;
    nOverrideBefore : UDINT;
END_VAR
VAR
    power : MC_Power;
    move : MC_MoveVelocity;
END_VAR
nOverrideBefore := Axis.PlcToNc.Override;
IF __ISVALIDREF(Axis) THEN
    power(Axis := Axis, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);
    move(Axis := Axis, Execute := TRUE, Velocity := 10.0, Direction := MC_Positive_Direction);
END_IF
Axis.PlcToNc.Override := nOverride;
nOverrideNow := Axis.PlcToNc.Override;
fPos := Axis.NcToPlc.ActPos;
bMoving := Axis.Status.Moving;
END_FUNCTION_BLOCK

PROGRAM MAIN
VAR
    ax : AXIS_REF;
    jog : FB_Jog;
    unbound : FB_Jog;
    scan : INT;
    nOverride : UDINT;
END_VAR
scan := scan + 1;
IF scan < 5 THEN
    jog(Axis := ax, nOverride := 1000000);
ELSE
    jog(Axis := ax, nOverride := 500000);
END_IF
unbound(nOverride := 250000);
nOverride := ax.PlcToNc.Override;
END_PROGRAM
",
    );
    write_in(dir.path(), "jog.axes.json", ONE_AXIS);
    let t = run_in(
        dir.path(),
        "jog.st",
        14,
        "MAIN.jog.fPos,MAIN.jog.bMoving,MAIN.jog.nOverrideNow,MAIN.jog.nOverrideBefore,\
         MAIN.nOverride,MAIN.unbound.fPos,MAIN.unbound.bMoving,MAIN.unbound.nOverrideNow,\
         MAIN.unbound.nOverrideBefore",
    );
    let pos = column(&t, "MAIN.jog.fPos");
    assert_eq!(pos[0], 0.0, "{t}");
    // full speed, 10 units/s: 0.1 a scan once accelerated
    assert!((pos[3] - pos[2] - 0.1).abs() < 1e-9, "{pos:?}");
    // at 50 %: 0.05 a scan once the override's transition is over
    for k in 9..14 {
        assert!(
            (pos[k] - pos[k - 1] - 0.05).abs() < 1e-9,
            "scan {k}: {pos:?}"
        );
    }
    assert_eq!(column(&t, "MAIN.jog.bMoving")[1..], [1.0; 13]);
    let mut now = vec![1_000_000.0; 4];
    now.extend([500_000.0; 10]);
    assert_eq!(column(&t, "MAIN.jog.nOverrideNow"), now);
    assert_eq!(column(&t, "MAIN.nOverride"), now);
    let mut before = vec![1_000_000.0; 5];
    before.extend([500_000.0; 9]);
    assert_eq!(column(&t, "MAIN.jog.nOverrideBefore"), before);
    for unbound in [
        "MAIN.unbound.fPos",
        "MAIN.unbound.bMoving",
        "MAIN.unbound.nOverrideNow",
        "MAIN.unbound.nOverrideBefore",
    ] {
        assert_eq!(column(&t, unbound), [0.0; 14], "{unbound}: {t}");
    }
}

/// The same members through a `POINTER TO AXIS_REF` (`p^.NcToPlc.ActPos`, `p^.Status.Moving`,
/// `p^.PlcToNc.Override`, `p^.ReadStatus()`): 0 / FALSE while the pointer is 0, the axis's values
/// from the scan after `p := ADR(ax)` (the members are read at the start of the body, as the NC
/// writes NcToPlc before the PLC task), and no NULL dereference. Before: E1021 "AXIS_REF has no
/// field `NcToPlc`".
#[test]
fn an_axis_through_a_pointer_reads_zero_until_the_pointer_is_set() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "ptr.st",
        "PROGRAM MAIN
VAR
    ax : AXIS_REF;
    p : POINTER TO AXIS_REF;
    power : MC_Power;
    move : MC_MoveVelocity;
    fPos : LREAL;
    bMoving : BOOL;
    nOverride : UDINT;
    scan : INT;
END_VAR
scan := scan + 1;
IF scan = 3 THEN
    p := ADR(ax);
END_IF
power(Axis := ax, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);
move(Axis := ax, Execute := TRUE, Velocity := 10.0, Direction := MC_Positive_Direction);
p^.ReadStatus();
fPos := p^.NcToPlc.ActPos;
bMoving := p^.Status.Moving;
nOverride := p^.PlcToNc.Override;
END_PROGRAM
",
    );
    write_in(dir.path(), "ptr.axes.json", ONE_AXIS);
    let t = run_in(
        dir.path(),
        "ptr.st",
        6,
        "MAIN.fPos,MAIN.bMoving,MAIN.nOverride",
    );
    let pos = column(&t, "MAIN.fPos");
    assert_eq!(pos[..3], [0.0; 3], "{t}");
    assert!(pos[3] > 0.2 && (pos[4] - pos[3] - 0.1).abs() < 1e-9, "{t}");
    assert_eq!(column(&t, "MAIN.bMoving"), [0.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
    assert_eq!(column(&t, "MAIN.nOverride"), [0.0, 0.0, 0.0, 1e6, 1e6, 1e6]);
}

// ---- CFC ----

/// A function block box: its input pins `inputs` (name, pin id), its output pins `outputs`
/// (name, pin id), `type_name` and `instance`, at `x, y`.
fn cfc_fb_box(
    type_name: &str,
    instance: &str,
    inputs: &[(&str, u32)],
    outputs: &[(&str, u32)],
    x: u32,
    y: u32,
) -> String {
    let ins: String = inputs.iter().map(|(_, id)| cfc_pin(*id)).collect();
    let outs: String = outputs.iter().map(|(_, id)| cfc_pin(*id)).collect();
    let texts: String = inputs
        .iter()
        .chain(outputs.iter())
        .map(|(n, _)| *n)
        .chain([type_name, instance])
        .map(|t| format!(r#"<o><v n="Text">"{t}"</v></o>"#))
        .collect();
    format!(
        r#"<o t="CFCBoxElement"><o n="Inputs" t="CFCItemList"><l2 n="InnerList" cet="CFCInputPin">{ins}</l2></o><o n="Outputs" t="CFCItemList"><l2 n="InnerList" cet="CFCOutputPin">{outs}</l2></o><o n="Texts" t="CFCItemList"><l2 n="InnerList" cet="CFCText">{texts}</l2></o><v n="Bounds">"{x}, {y}, 0, 0"</v><v n="EnEno">false</v><v n="KindOfCall" t="KindOfCall">FunctionBlock</v></o>"#
    )
}

/// A `.TcPOU` whose declaration is `decl` and whose body is a CFC chart of `elements`.
fn cfc_pou(name: &str, decl: &str, elements: &[String]) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4024.12">
  <POU Name="{name}" Id="{{31313131-0000-0000-0000-000000000001}}" SpecialFunc="None">
    <Declaration><![CDATA[{decl}]]></Declaration>
    <Implementation>
      <CFC>
        <XmlArchive>
          <Data>
            <o xml:space="preserve" t="CFCImplementationObject">
              <o n="Items" t="CFCItemList">
                <l2 n="InnerList">
{}
                </l2>
              </o>
              <v n="UseExplicitExecutionOrder">false</v>
            </o>
          </Data>
        </XmlArchive>
      </CFC>
    </Implementation>
  </POU>
</TcPlcObject>
"#,
        elements.concat()
    )
}

/// A `.TcPOU` of `decl` with the ST body `body`.
fn st_pou(name: &str, decl: &str, body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4024.12">
  <POU Name="{name}" Id="{{31313131-0000-0000-0000-000000000002}}" SpecialFunc="None">
    <Declaration><![CDATA[{decl}]]></Declaration>
    <Implementation>
      <ST><![CDATA[{body}]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
"#
    )
}

/// TF8040's templates: a derived block's CFC chart holds a box of its base's type whose instance
/// is `SUPER^`, its input `nStep` wired from the derived block's `nInc` and its output `nCount`
/// wired to `nSeen`. The box calls the base's body (`nCount := nCount + nStep`) once a scan, on
/// the derived instance's own variables: `d.nCount` counts 3, 6, 9 ... and `d.nSeen` reads the
/// count after the call. Before: E0326 "box `FB_Base` does not name its instance or program
/// (`SUPER^`)" and nothing ran.
#[test]
fn a_cfc_box_on_super_runs_the_base_blocks_body() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "FB_Base.TcPOU",
        &st_pou(
            "FB_Base",
            "FUNCTION_BLOCK FB_Base
VAR_INPUT
    nStep : INT;
END_VAR
VAR_OUTPUT
    nCount : INT;
END_VAR
",
            "nCount := nCount + nStep;",
        ),
    );
    write_in(
        dir.path(),
        "FB_Derived.TcPOU",
        &cfc_pou(
            "FB_Derived",
            "FUNCTION_BLOCK FB_Derived EXTENDS FB_Base
VAR_INPUT
    nInc : INT;
END_VAR
VAR_OUTPUT
    nSeen : INT;
END_VAR
",
            &[
                cfc_input("nInc", 10, 1, 1),
                cfc_fb_box(
                    "FB_Base",
                    "SUPER^",
                    &[("nStep", 11)],
                    &[("nCount", 12)],
                    5,
                    1,
                ),
                cfc_output("nSeen", 13, 10, 1),
                cfc_wire(10, 11),
                cfc_wire(12, 13),
            ],
        ),
    );
    write_in(
        dir.path(),
        "MAIN.TcPOU",
        &st_pou(
            "MAIN",
            "PROGRAM MAIN
VAR
    d : FB_Derived;
END_VAR
",
            "d(nInc := 3);",
        ),
    );
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "FB_Base.TcPOU",
            "FB_Derived.TcPOU",
            "MAIN.TcPOU",
            "--cycles",
            "4",
            "--sanitize",
            "--trace",
            "-",
            "--watch",
            "MAIN.d.nCount,MAIN.d.nSeen",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("E0326"), "{stderr}");
    assert_eq!(column(&trace, "MAIN.d.nCount"), [3.0, 6.0, 9.0, 12.0]);
    assert_eq!(column(&trace, "MAIN.d.nSeen"), [3.0, 6.0, 9.0, 12.0]);
}
