//! Round 28 of unseen projects (issue #13): vendor forms of CODESYS, TwinCAT and SIMATIC AX
//! programs, run end to end through `ladderc run`:
//! - `s[i]` of a STRING in a file written for CODESYS or TwinCAT (a `.TcPOU`, a CODESYS V2.3
//!   `.EXP`, CODESYS's PLCopen XML) is the BYTE at offset i, 0 the first (of a WSTRING the WORD),
//!   read and written: a 0 written ends the string, a code written at LEN(s) appends it, an offset
//!   past the declared length is the run-time string index error, the string unchanged (before:
//!   E1006 "cannot store CHAR into BYTE", E1050 "character 0 is outside 1..20"); a `.st` file
//!   keeps edition 3's CHAR from 1.
//! - CODESYS's pointer-sized `__XINT`, `__UXINT`, `__XWORD` (TwinCAT's `XINT`, `UXINT`, `XWORD`)
//!   are LINT, ULINT and LWORD, the 64-bit target's widths (before: E1003 unknown type).
//! - a STRUCT field's relative location (`x AT %B0 : DWORD;`, `b AT %X4.1 : BOOL;`, IEC 61131-3
//!   ed. 3 Table 11, SIMATIC AX's I/O layouts) is read, the field plain (before: E0006 "the area
//!   must be I, Q or M" per field); two fields sharing bits are one E0006 at the second.
//! - CODESYS SoftMotion's `AXIS_REF_SM3` members `fActPosition`, `fSetPosition`,
//!   `fActVelocity`, `fSetVelocity`, `nAxisState` read from the simulated axis (before: E1021
//!   "AXIS_REF has no field fActPosition"); another member is one E1021 naming it.
//! - Tc2_MC2's `AXIS_REF` members in an array of structures whose bound is a qualified constant
//!   of a global variable list (`axes : ARRAY [1..GVL.nMax] OF ST_Ctl`, ISIS's DrivePLC) are read
//!   in a METHOD of the POU, also where the METHOD is checked on its own (before: E1021 "AXIS_REF
//!   has no field NcToPlc").

mod common;
use common::{check_text, column, in_dir, run_text, text_column, write_in};

/// A TwinCAT 3 object of one program MAIN with `decl` (its VAR block's lines) and `body` (ST).
fn tc_pou(decl: &str, body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1">
  <POU Name="MAIN" Id="{{00000000-0000-0000-0000-000000000004}}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
{decl}
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[{body}]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
"#
    )
}

/// TwinCAT: `sText[0]` of 'ABC' is the BYTE 16#41; `sText[1] := 0` cuts the string after its
/// first character (LEN 1); `sText[1] := 66` then appends 'B' at LEN(s) (the TF6701 sample's
/// `sPayload[nLen] := 0` idiom, the other way); `sText[3]` past the end reads 0.
#[test]
fn a_twincat_string_index_is_the_byte_at_an_offset_from_0() {
    let src = tc_pou(
        "    sText  : STRING(20) := 'ABC';
    nFirst : BYTE;
    nLen, nLen2 : INT;
    nPast : BYTE;
    sAfter : STRING(20);",
        "nFirst := sText[0];
sText[1] := 0;
nLen := LEN(sText);
sText[1] := 66;
nLen2 := LEN(sText);
nPast := sText[3];
sAfter := sText;
",
    );
    let (trace, _) = run_text(
        "MAIN.TcPOU",
        &src,
        1,
        "MAIN.nFirst,MAIN.nLen,MAIN.nLen2,MAIN.nPast,MAIN.sAfter",
    );
    assert_eq!(column(&trace, "MAIN.nFirst"), [65.0]);
    assert_eq!(column(&trace, "MAIN.nLen"), [1.0]);
    assert_eq!(column(&trace, "MAIN.nLen2"), [2.0]);
    assert_eq!(column(&trace, "MAIN.nPast"), [0.0]);
    assert_eq!(text_column(&trace, "MAIN.sAfter"), ["\"AB\""]);
}

/// TwinCAT: an offset past the declared length (a computed 25 of a STRING(20)) reads 0, its write
/// is dropped and reported once at the end of the run as a string index out of range (offsets
/// 0..20); the string is unchanged.
#[test]
fn a_twincat_string_offset_past_its_length_is_a_run_time_error() {
    let src = tc_pou(
        "    sText : STRING(20) := 'ABC';
    i : INT := 25;
    nRead : BYTE := 7;",
        "nRead := sText[i];
sText[i] := 65;
",
    );
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "MAIN.TcPOU", &src);
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "MAIN.TcPOU",
            "--cycles",
            "1",
            "--trace",
            "-",
            "--watch",
            "MAIN.nRead,MAIN.sText",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&trace, "MAIN.nRead"), [0.0]);
    assert_eq!(text_column(&trace, "MAIN.sText"), ["\"ABC\""]);
    assert!(
        stderr.contains("string index out of range") && stderr.contains("index 25 outside 0..20"),
        "{stderr}"
    );
}

/// A CODESYS V2.3 export (`.EXP`): `s[0]` is the first byte, `s[2] := 0` ends the string after
/// two characters; a WSTRING's `w[1]` is the WORD of its second character.
#[test]
fn a_codesys_export_string_index_is_a_byte_and_a_wstring_index_a_word() {
    let src = "(* @NESTEDCOMMENTS := 'Yes' *)
(* @PATH := '' *)
PROGRAM PLC_PRG
VAR
\ts : STRING(10) := 'xyz';
\tw : WSTRING(10) := \"AB\";
\tb : BYTE;
\tn : INT;
\tc : WORD;
END_VAR
(* @END_DECLARATION := '0' *)
b := s[0];
s[2] := 0;
n := LEN(s);
c := w[1];
END_PROGRAM
";
    let (trace, _) = run_text("prg.EXP", src, 1, "PLC_PRG.b,PLC_PRG.n,PLC_PRG.c");
    assert_eq!(column(&trace, "PLC_PRG.b"), [120.0]);
    assert_eq!(column(&trace, "PLC_PRG.n"), [2.0]);
    assert_eq!(column(&trace, "PLC_PRG.c"), [66.0]);
}

/// A CODESYS PLCopen XML project (`productName="CODESYS"`): `s[0]` is a BYTE, 16#61 of 'abc'.
#[test]
fn a_codesys_xml_string_index_is_a_byte() {
    let src = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP20" creationDateTime="2026-01-01T00:00:00" />
  <contentHeader name="t.project"><coordinateInfo><fbd><scaling x="1" y="1" /></fbd><ld><scaling x="1" y="1" /></ld><sfc><scaling x="1" y="1" /></sfc></coordinateInfo></contentHeader>
  <types><dataTypes /><pous>
    <pou name="Prg" pouType="program">
      <interface><localVars>
        <variable name="s"><type><string length="20" /></type><initialValue><simpleValue value="'abc'" /></initialValue></variable>
        <variable name="b"><type><BYTE /></type></variable>
      </localVars></interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">b := s[0];</xhtml></ST></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="C"><resource name="R"><task name="T" interval="PT0.01S" priority="1"><pouInstance name="P" typeName="Prg" /></task></resource></configuration></configurations></instances>
</project>
"#;
    let (trace, _) = run_text("prj.xml", src, 1, "P.b");
    assert_eq!(column(&trace, "P.b"), [97.0]);
}

/// A plain `.st` file keeps edition 3's `s[i]`: the i-th CHAR, 1 the first.
#[test]
fn an_iec_st_string_index_stays_the_character_from_1() {
    let src = "PROGRAM Main
VAR s : STRING(10) := 'xyz'; c : CHAR; n : BYTE; END_VAR
c := s[1];
n := CHAR_TO_BYTE(c);
END_PROGRAM
";
    let (trace, _) = run_text("main.st", src, 1, "Main.n");
    assert_eq!(column(&trace, "Main.n"), [120.0]);
}

/// CODESYS's pointer-sized integers hold 64-bit values: `__UXINT` 2^32 + 1, `__XINT` -2^40,
/// `__XWORD` 16#1_0000_0000 shifted; TwinCAT's `UXINT` is the same type.
#[test]
fn codesys_pointer_sized_integers_are_64_bit() {
    let src = "PROGRAM Main
VAR
  u : __UXINT := 4294967296;
  x : __XINT;
  w : __XWORD := 16#100000000;
  t : UXINT;
  hi : UDINT;
END_VAR
u := u + 1;
x := -1099511627776;
t := u * 2;
hi := LWORD_TO_UDINT(SHR(w, 32));
END_PROGRAM
";
    let (trace, _) = run_text("main.st", src, 1, "Main.u,Main.x,Main.t,Main.hi");
    assert_eq!(column(&trace, "Main.u"), [4294967297.0]);
    assert_eq!(column(&trace, "Main.x"), [-1099511627776.0]);
    assert_eq!(column(&trace, "Main.t"), [8589934594.0]);
    assert_eq!(column(&trace, "Main.hi"), [1.0]);
}

/// SIMATIC AX: a structure whose fields give their relative locations (a DWORD at byte 0, a BYTE
/// at 4, a BOOL at bit 5.0) is used as a plain one: 16#1234, 3 and TRUE read back.
#[test]
fn struct_fields_at_relative_locations_run() {
    let src = "TYPE CtrlCh : STRUCT
    loadValue   AT %B0 : DWORD;
    controlByte AT %B4 : BYTE;
    enable      AT %X5.0 : BOOL;
    spare       AT %X5.1 : BOOL;
END_STRUCT;
END_TYPE

PROGRAM Main
    VAR c : CtrlCh; v : DWORD; b : BYTE; e : BOOL; END_VAR
    c.loadValue := 16#1234;
    c.controlByte := 3;
    c.enable := TRUE;
    v := c.loadValue;
    b := c.controlByte;
    e := c.enable AND NOT c.spare;
END_PROGRAM
";
    let (trace, _) = run_text("ax.st", src, 1, "Main.v,Main.b,Main.e");
    assert_eq!(column(&trace, "Main.v"), [4660.0]);
    assert_eq!(column(&trace, "Main.b"), [3.0]);
    assert_eq!(column(&trace, "Main.e"), [1.0]);
}

/// Two fields whose relative locations share bytes (a WORD at byte 2 inside a DWORD at byte 0)
/// are one E0006 at the second location.
#[test]
fn overlapping_relative_locations_are_one_error() {
    let (code, lines) = check_text(
        "ax.st",
        "TYPE T : STRUCT
    a AT %B0 : DWORD;
    b AT %B2 : WORD;
    c AT %B4 : BYTE;
END_STRUCT;
END_TYPE
PROGRAM Main
VAR t1 : T; END_VAR
t1.c := 1;
END_PROGRAM
",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "ax.st:3:10: error[E0006]: relative location `%B2` overlaps the member at `%B0`"
        ),
        "{lines:?}"
    );
}

/// CODESYS SoftMotion: an `AXIS_REF_SM3` powered and moved to 50 mm: `nAxisState` is 0
/// (power_off) before the power, 3 (standstill) powered, 4 (discrete_motion) while it moves and 3
/// again at the end; `fActPosition` and `fSetPosition` follow the simulated position,
/// `fActVelocity` is positive while it moves.
#[test]
fn sm3_axis_members_read_the_simulated_axis() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "sm3.st",
        "PROGRAM Main
VAR
  X1 : AXIS_REF_SM3;
  power : MC_Power;
  move : MC_MoveAbsolute;
  go : BOOL;
  scans, state : INT;
  pos, setPos, velo : LREAL;
END_VAR
scans := scans + 1;
power(Axis := X1, Enable := scans > 2, bRegulatorOn := TRUE, bDriveStart := TRUE);
go := scans > 5;
move(Axis := X1, Execute := go, Position := 50.0, Velocity := 100.0,
     Acceleration := 1000.0, Deceleration := 1000.0);
state := X1.nAxisState;
pos := X1.fActPosition;
setPos := X1.fSetPosition;
velo := X1.fActVelocity;
END_PROGRAM
",
    );
    write_in(
        dir.path(),
        "sm3.axes.json",
        r#"{ "cycle_ms": 10, "axes": [ { "name": "X1", "unit": "mm", "velocity": 250, "acceleration": 1000, "deceleration": 1000 } ] }"#,
    );
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "sm3.st",
            "--cycles",
            "100",
            "--trace",
            "-",
            "--watch",
            "Main.state,Main.pos,Main.setPos,Main.velo,axis.X1.position",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    let state = column(&trace, "Main.state");
    assert_eq!(state[0], 0.0, "{state:?}");
    assert!(state.contains(&3.0) && state.contains(&4.0), "{state:?}");
    assert_eq!(state[99], 3.0, "{state:?}");
    let pos = column(&trace, "Main.pos");
    let axis = column(&trace, "axis.X1.position");
    assert!((pos[99] - 50.0).abs() < 1e-9, "{pos:?}");
    // read at the start of the scan: the position of the scan before
    assert_eq!(&pos[1..], &axis[..99]);
    assert_eq!(column(&trace, "Main.setPos"), pos);
    assert!(column(&trace, "Main.velo").iter().any(|&v| v > 0.0));
}

/// An `AXIS_REF_SM3` member ladderc does not simulate is one E1021 naming it.
#[test]
fn an_sm3_axis_member_without_a_counterpart_is_one_error() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "sm3.st",
        "PROGRAM Main
VAR X1 : AXIS_REF_SM3; a, b : LREAL; END_VAR
a := X1.fActPosition;
b := X1.fActTorque;
END_PROGRAM
",
    );
    write_in(
        dir.path(),
        "sm3.axes.json",
        r#"{ "cycle_ms": 10, "axes": [ { "name": "X1", "unit": "mm", "velocity": 250, "acceleration": 1000, "deceleration": 1000 } ] }"#,
    );
    let (code, _, stderr) = in_dir(dir.path(), &["check", "sm3.st"]);
    assert_eq!(code, Some(1), "{stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].starts_with("sm3.st:4:9: error[E1021]") && errors[0].contains("`fActTorque`"),
        "{stderr}"
    );
}

/// TwinCAT: a program's METHOD reads `GVL.axes[i].Axis.NcToPlc.AxisId` of an array of structures
/// whose bound is the list's constant (ISIS's DrivePLC): the NC axis's Id, 1 and 2, so the check
/// it makes passes and `nWrong` stays 0.
#[test]
fn a_method_reads_the_nc_members_of_axes_in_structures() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "ST_Ctl.TcDUT",
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1">
  <DUT Name="ST_Ctl" Id="{00000000-0000-0000-0000-000000000011}">
    <Declaration><![CDATA[TYPE ST_Ctl :
STRUCT
    fPos : LREAL;
    Axis : AXIS_REF;
END_STRUCT
END_TYPE
]]></Declaration>
  </DUT>
</TcPlcObject>
"#,
    );
    write_in(
        dir.path(),
        "GVL.TcGVL",
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1">
  <GVL Name="GVL" Id="{00000000-0000-0000-0000-000000000012}">
    <Declaration><![CDATA[VAR_GLOBAL
    axes : ARRAY [1..GVL.nMax] OF ST_Ctl;
END_VAR
VAR_GLOBAL CONSTANT
    nMax : UINT := 2;
END_VAR
]]></Declaration>
  </GVL>
</TcPlcObject>
"#,
    );
    write_in(
        dir.path(),
        "MAIN.TcPOU",
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1">
  <POU Name="MAIN" Id="{00000000-0000-0000-0000-000000000013}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
    nWrong : INT;
    fPos : LREAL;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[fPos := GVL.axes[2].Axis.NcToPlc.ActPos;
Check();
]]></ST>
    </Implementation>
    <Method Name="Check" Id="{00000000-0000-0000-0000-000000000014}">
      <Declaration><![CDATA[METHOD Check : BOOL
VAR
    i : UINT;
END_VAR
]]></Declaration>
      <Implementation>
        <ST><![CDATA[FOR i := 1 TO GVL.nMax DO
    IF GVL.axes[i].Axis.NcToPlc.AxisId <> UINT_TO_UDINT(i) THEN
        nWrong := nWrong + 1;
    END_IF
END_FOR
]]></ST>
      </Implementation>
    </Method>
  </POU>
</TcPlcObject>
"#,
    );
    write_in(
        dir.path(),
        "axes.json",
        r#"{ "cycle_ms": 10, "axes": [
  { "name": "A1", "unit": "mm", "velocity": 250, "acceleration": 1000, "deceleration": 1000, "link": "GVL.axes[1].Axis" },
  { "name": "A2", "unit": "mm", "velocity": 250, "acceleration": 1000, "deceleration": 1000, "link": "GVL.axes[2].Axis" } ] }"#,
    );
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "MAIN.TcPOU",
            "GVL.TcGVL",
            "ST_Ctl.TcDUT",
            "--axes",
            "axes.json",
            "--cycles",
            "3",
            "--trace",
            "-",
            "--watch",
            "MAIN.nWrong,MAIN.fPos",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&trace, "MAIN.nWrong"), [0.0, 0.0, 0.0]);
    assert_eq!(column(&trace, "MAIN.fPos"), [0.0, 0.0, 0.0]);
}
