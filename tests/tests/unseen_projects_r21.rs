//! Round 21 of unseen projects (issue #13): forms that real programs use, run end to end through
//! `ladderc run`:
//! - a literal beside a subrange value in an operation (`n * 5`, `m + 10`, `n > 7` with `n :
//!   UINT(1..4)`) is a value of the subrange's base type, as IEC 61131-3 types the operation (before:
//!   a false E1017 "literal 5 does not fit UINT (1..4)"); a result stored back into the subrange
//!   that falls outside it is saturated to the nearer bound with the runtime's range flag;
//! - CODESYS's and TwinCAT's `TIME()`, the time since the controller started (before: E1019
//!   "unknown function `TIME`"): the scan clock, as the timers read it;
//! - a data type with named values whose values are constant expressions of the values before
//!   them (IEC 61131-3 ed. 3, Table 11's own `White := Red OR Green OR Blue`; KrystianOlszowy's
//!   test.st; before: E0011 "unexpected `Red`, expected a number");
//! - an index that mixes integer types (`a[i - lb]` of an INT and a DINT), as the index of an
//!   `ARRAY [*]` in-out always does (`Park[i]` with `i : INT`: TomF777's CarPark3D; before: a false
//!   E1006 "cannot store DINT into INT");
//! - a TwinCAT PROPERTY whose declaration ends in a `//` comment (`PROPERTY P_Free : INT // number
//!   of free places`, TomF777's CarPark3D; before: E0100 "this PROPERTY cannot be read", the
//!   `GET` that ladderc writes after the declaration landed inside the comment);
//! - `{attribute 'hide'}` among a METHOD's `VAR_INST` declarations (CHALET_Base; before: E0001
//!   "unexpected character `{`", the declarations after it lost);
//! - `TO_TIME(0)`, `UDINT_TO_TIME(1000)`, `TIME_TO_DINT(T#1S500MS)` in a constant (before:
//!   E0022 "computed at run time");
//! - `[N(FALSE)]`, a named repeat count of a BOOL or a string (Mem1; before: E0011);
//! - a TwinCAT PROGRAM with an ACTION written before a METHOD (ISIS DrivePLC; before: E1019
//!   "unknown function" at each call of the method);
//! - a program's action named as a global of a `qualified_only` list (`AXES();` beside
//!   `GVL.axes`), an enumeration named as such a global (`MachineMode.Auto` beside
//!   `GVL.machineMode`), and a method called through a list (`GVL.fbA.SignalEnable(...)`)
//!   (SWTest, ISIS; before: E1018, E1021, E1011);
//! - a PLCopen block call that leaves out a required input another call of the instance binds
//!   (`rst(Axis := ax);` then `rst(Axis := ax, Execute := go);`; before: E4023 at the first);
//! - `check Demo.sln` from the solution's own folder (before: the `.sln` read as ST, 44 errors),
//!   and a solution whose PLC project is missing: one E1079 at the `PrjFilePath` that names it
//!   (robinruys/NLR_internship; before: an unlocated E9001 about the folder, exit 2);
//! - `run` of inputs with no PROGRAM (a CODESYS export of one function block): W1441 says that
//!   nothing runs (before: empty cycles, exit 0, silently);
//! - an array indexed by a value of an enumeration without `{attribute 'strict'}` (ISIS:
//!   `arr[E_P.B]`; before: E1021 with a hint to convert with REAL_TO_DINT): its number, W1439;
//! - diagnostics of invalid inputs: a FOR without `:=` is one error (before: four, msftrncs's
//!   test.st), a library-qualified name is never shown by its internal spelling (`__o_Bar`,
//!   `__3_EventLogger_FB_TcAlarm`), and W1003's hint for an ST function is ST;
//! - several PLCopen XML files given together (CODESYS exports one object per file): a program
//!   in one calls a function block of another, in ST and as an FBD box, and uses its structure
//!   type (before: E3009 "type `FB_Count` is not defined in this project");
//! - Tc2_MC2's `MC_HomingMode.MC_Direct` (older Tc2_MC2 versions' name of the mode that sets the
//!   position without a movement; ggekchyan's 3D-Scanner; before: E1001 "undeclared name
//!   `MC_HomingMode`");
//! - edition 3's `VAR PUBLIC` (W0304, the word ignored) and `CLASS ... END_CLASS` (one E1076 per
//!   class; simatic-ax; before: W0001 "instructions outside any POU" and E0011s with IL advice),
//!   also `VAR RETAIN PUBLIC`, `VAR CONSTANT PRIVATE`;
//! - a PLCopen block's input left out of a call keeps the value the last call gave it, and
//!   `rst.Execute` reads it, in both parameter-passing methods (before: FALSE, so MC_Reset's Done
//!   fell in the next call without Execute; the traced Execute was always 0);
//! - `RETURN (cond);` and `RETURN(b := e);` (CODESYS conditional return, fisothemes'
//!   FsControllerToolbox; before: E0104 "missing `;`");
//! - `Foo;` of a name nothing declares is E1001 (before: only W1431, the statement silently
//!   dropped; mgmike1011's B&R action calls);
//! - corpus: efranceschetti/festo-codesys-mcp's two CODESYS V3.5 SP21 exports (MIT), a program and
//!   the state-machine block it calls, one object per file: given together, they run.

mod common;
use common::{column, ladderc, rejected_heads, run_stimulated_files, run_text, run_traced_files};

/// Operations on a subrange value take its base type: the literals beside it are not checked
/// against the range, the results are exact, and a result stored back into the subrange that
/// leaves it is saturated (the range flag reported), while a literal stored straight into it is
/// still checked (E1017).
#[test]
fn a_literal_beside_a_subrange_value_takes_the_base_type() {
    let src = "TYPE TIdx : UINT(1..4); END_TYPE
PROGRAM Main
VAR
  n : UINT(1..4) := 2;
  m : TIdx := 3;
  k : UINT;
  h : UINT;
  b : BOOL;
  j : INT(-5..5);
  s : UINT(1..4) := 1;
  lo : INT(-5..5) := 0;
END_VAR
k := n * 5;
h := 10 + m;
b := n > 7 OR m < 0;
j := MAX(j, 3) - 7;
n := n + 1;
IF n >= 4 THEN n := 1; END_IF;
s := s * 3;
lo := lo - 4;
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "sub.st",
        src,
        3,
        "Main.n,Main.k,Main.h,Main.b,Main.j,Main.s,Main.lo",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.n,Main.k,Main.h,Main.b,Main.j,Main.s,Main.lo\n\
         0,0,3,10,13,0,-4,3,-4\n\
         1,10,1,15,13,0,-4,4,-5\n\
         2,20,2,5,13,0,-4,4,-5\n"
    );
    // s := 3 * 3 = 9 and lo := -4 - 4 = -8 leave their ranges: saturated to 4 and -5, reported
    assert!(
        stderr.contains("runtime: conversion out of range or value outside a subrange (saturated)"),
        "{stderr}"
    );
    let heads = rejected_heads(
        "direct.st",
        "PROGRAM Main\nVAR\n  n : UINT(1..4);\nEND_VAR\nn := 5;\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        ["direct.st:5:6: error[E1017]: literal 5 does not fit UINT (1..4)"]
    );
}

/// `TIME()` is the scan clock: an elapsed time measured with it counts the 10 ms scans, in a
/// PROGRAM and in a FUNCTION; given an input it is one E1020 that says to call it without.
#[test]
fn time_without_inputs_is_the_scan_clock() {
    let src = "FUNCTION Since : TIME
VAR_INPUT t0 : TIME; END_VAR
Since := TIME() - t0;
END_FUNCTION
PROGRAM Main
VAR
  t0 : TIME;
  el : TIME;
  f : TIME;
  started : BOOL;
END_VAR
IF NOT started THEN t0 := TIME(); started := TRUE; END_IF;
el := TIME() - t0;
f := Since(t0 := T#5ms);
END_PROGRAM
";
    let (trace, _) = run_text("clock.st", src, 4, "Main.el,Main.f");
    assert_eq!(
        trace,
        "cycle,time_ms,Main.el,Main.f\n0,0,T#0ms,T#-5ms\n1,10,T#10ms,T#5ms\n2,20,T#20ms,T#15ms\n3,30,T#30ms,T#25ms\n"
    );
    let heads = rejected_heads(
        "arg.st",
        "PROGRAM Main\nVAR t : TIME; END_VAR\nt := TIME(T#1s);\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        ["arg.st:3:6: error[E1020]: TIME takes 0 inputs, 1 given"]
    );
}

/// The standard's own example of named values given by expressions: `White` is the OR of the three
/// colours, `Black` their AND, `Cyan` an XOR; the values are numbered as computed, and a value that
/// names something that is no constant is one E0022.
#[test]
fn named_values_may_be_expressions_of_the_values_before() {
    let src = "TYPE Colors : DWORD (Red := 16#00FF0000, Green := 16#0000FF00, Blue := 16#000000FF,
    White := Red OR Green OR Blue, Black := Red AND Green AND Blue, Cyan := White XOR Red,
    Next) := Green;
END_TYPE
PROGRAM Main
VAR
  c : Colors := Colors#White;
  k : Colors;
  white : DINT;
  black : DINT;
  cyan : DINT;
  next : DINT;
  green : BOOL;
END_VAR
white := TO_DINT(c);
black := TO_DINT(Colors#Black);
cyan := TO_DINT(Colors#Cyan);
next := TO_DINT(Colors#Next);
green := k = Colors#Green;
END_PROGRAM
";
    let (trace, _) = run_text(
        "colors.st",
        src,
        1,
        "Main.white,Main.black,Main.cyan,Main.next,Main.green",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.white,Main.black,Main.cyan,Main.next,Main.green\n0,0,16777215,0,65535,65536,1\n"
    );
    let heads = rejected_heads(
        "bad.st",
        "TYPE T : INT (A := 1, B := A OR x) := A;\nEND_TYPE\nPROGRAM Main\nVAR v : T; END_VAR\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        ["bad.st:1:28: error[E0022]: constant expression `A OR x`: `x` names no constant with a value in the files given"]
    );
}

/// An index computed from an INT and a DINT is a DINT (the wider type), in a declared array, a
/// pointer and an `ARRAY [*]` in-out indexed by an INT variable.
#[test]
fn an_index_of_mixed_integer_types_takes_the_wider_type() {
    let src = "FUNCTION_BLOCK FB_Park
VAR_IN_OUT Park : ARRAY[*] OF INT; END_VAR
VAR_OUTPUT v : INT; END_VAR
VAR i : INT := 2; END_VAR
v := Park[i];
END_FUNCTION_BLOCK
PROGRAM Main
VAR
  a : ARRAY[0..3] OF INT := [1, 2, 3, 4];
  lot : ARRAY[1..2] OF INT := [5, 6];
  p : POINTER TO INT;
  i : INT := 2;
  lb : DINT := 1;
  x : INT;
  y : INT;
  fb : FB_Park;
END_VAR
p := ADR(a);
x := a[i - lb] + p[i + lb];
fb(Park := lot);
y := fb.v;
END_PROGRAM
";
    let (trace, _) = run_text("index.st", src, 1, "Main.x,Main.y");
    assert_eq!(trace, "cycle,time_ms,Main.x,Main.y\n0,0,6,6\n");
}

/// A TwinCAT property's declaration that ends in a `//` comment: the accessor is read, and
/// `park.P_Free` gives 10 - 3.
#[test]
fn a_property_declaration_may_end_in_a_line_comment() {
    let dir = tempfile::tempdir().unwrap();
    let fb = dir.path().join("FB_Park.TcPOU");
    std::fs::write(
        &fb,
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4022.18">
  <POU Name="FB_Park" Id="{11111111-1111-1111-1111-111111111111}" SpecialFunc="None">
    <Declaration><![CDATA[FUNCTION_BLOCK FB_Park
VAR
	Used : INT := 3;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[]]></ST>
    </Implementation>
    <Property Name="P_Free" Id="{22222222-2222-2222-2222-222222222222}">
      <Declaration><![CDATA[PROPERTY P_Free : INT // number of free places (* not closed here]]></Declaration>
      <Get Name="Get" Id="{33333333-3333-3333-3333-333333333333}">
        <Declaration><![CDATA[VAR // none
END_VAR
]]></Declaration>
        <Implementation>
          <ST><![CDATA[P_Free := 10 - Used; // 'quoted' text]]></ST>
        </Implementation>
      </Get>
    </Property>
  </POU>
</TcPlcObject>"#,
    )
    .unwrap();
    let main = dir.path().join("MAIN.TcPOU");
    std::fs::write(
        &main,
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4022.18">
  <POU Name="MAIN" Id="{44444444-4444-4444-4444-444444444444}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
	park : FB_Park;
	free : INT;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[free := park.P_Free; // read the property]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>"#,
    )
    .unwrap();
    let (trace, _) = run_traced_files(&[&fb, &main], 1, "MAIN.free");
    assert_eq!(trace, "cycle,time_ms,MAIN.free\n0,0,7\n");
}

/// `{attribute 'hide'}` above a METHOD's VAR_INST variable: a note, and the variable is kept in
/// the instance (the method counts 1, 2).
#[test]
fn a_pragma_among_a_methods_declarations_is_a_note() {
    let src = "FUNCTION_BLOCK FB_A
METHOD M : INT
VAR_INST
\t{attribute 'hide'}
\tk : INT;
END_VAR
k := k + 1;
M := k;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : FB_A; r : INT; END_VAR
r := a.M();
END_PROGRAM
";
    let (trace, stderr) = run_text("hide.st", src, 2, "Main.r");
    assert_eq!(trace, "cycle,time_ms,Main.r\n0,0,1\n1,10,2\n");
    assert!(
        stderr.contains("hide.st:4:2: note[W0301]: pragma `{attribute 'hide'}` is informational"),
        "{stderr}"
    );
}

/// Conversions to and from TIME in constants count milliseconds, as at run time; a real number
/// to TIME is rounded to whole milliseconds, halves to even (round 34, Beckhoff infosys
/// "REAL/LREAL_TO_<type>": `REAL_TO_TIME(2.5)` is `T#2ms`, before `T#2500us`).
#[test]
fn time_conversions_are_computed_in_constants() {
    let src = "VAR_GLOBAL CONSTANT
\tcMinTime : TIME := TO_TIME(0);
\tcMinL : LTIME := TO_LTIME(2);
\tcT : TIME := UDINT_TO_TIME(1000);
\tcR : TIME := REAL_TO_TIME(2.5);
\tcMs : DINT := TIME_TO_DINT(T#1S500MS);
\tcSec : REAL := TIME_TO_REAL(T#250MS) / 1000.0;
END_VAR
PROGRAM Main
VAR same : BOOL; END_VAR
same := cT = UDINT_TO_TIME(1000) AND cR = REAL_TO_TIME(2.5) AND cMs = TIME_TO_DINT(T#1S500MS);
END_PROGRAM
";
    let (trace, _) = run_text(
        "consts.st",
        src,
        1,
        "cMinTime,cMinL,cT,cR,cMs,cSec,Main.same",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,cMinTime,cMinL,cT,cR,cMs,cSec,Main.same\n0,0,T#0ms,T#2ms,T#1000ms,T#2ms,1500,0.25,1\n"
    );
}

/// `[N(TRUE)]` and `[N('ab')]` repeat a BOOL and a string N times, N a named constant.
#[test]
fn a_named_repeat_count_repeats_a_bool_or_a_string() {
    let src = "PROGRAM Main
VAR CONSTANT
  N : INT := 3;
END_VAR
VAR
  a : ARRAY [1..N] OF BOOL := [N(TRUE)];
  s : ARRAY [1..N] OF STRING(4) := [N('ab')];
  b : ARRAY [1..4] OF BOOL := [N(FALSE), TRUE];
  c : INT;
END_VAR
c := BOOL_TO_INT(a[1]) + BOOL_TO_INT(a[3]) + LEN(s[3]) + BOOL_TO_INT(b[4]) * 10 + BOOL_TO_INT(b[3]) * 100;
END_PROGRAM
";
    let (trace, _) = run_text("repeat.st", src, 1, "Main.c");
    assert_eq!(trace, "cycle,time_ms,Main.c\n0,0,14\n");
}

/// A TwinCAT PROGRAM whose ACTION comes before its METHOD: the action and the program's body
/// both call the method (n counts 1 + 2 a cycle).
#[test]
fn a_programs_action_may_come_before_its_method() {
    let dir = tempfile::tempdir().unwrap();
    let main = dir.path().join("MAIN.TcPOU");
    std::fs::write(
        &main,
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4022.12">
  <POU Name="MAIN" Id="{00000000-0000-0000-0000-000000000001}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
	n : INT;
END_VAR]]></Declaration>
    <Implementation>
      <ST><![CDATA[DOIT();
Bump(2);]]></ST>
    </Implementation>
    <Action Name="DOIT" Id="{00000000-0000-0000-0000-000000000002}">
      <Implementation>
        <ST><![CDATA[Bump(1);]]></ST>
      </Implementation>
    </Action>
    <Method Name="Bump" Id="{00000000-0000-0000-0000-000000000003}">
      <Declaration><![CDATA[METHOD Bump : BOOL
VAR_INPUT
	d : INT;
END_VAR]]></Declaration>
      <Implementation>
        <ST><![CDATA[n := n + d;]]></ST>
      </Implementation>
    </Method>
  </POU>
</TcPlcObject>"#,
    )
    .unwrap();
    let (trace, _) = run_traced_files(&[&main], 2, "MAIN.n");
    assert_eq!(trace, "cycle,time_ms,MAIN.n\n0,0,3\n1,10,6\n");
}

/// Names a `qualified_only` list shares with a program's action and with an enumeration: the
/// action runs (`AXES();`), the enumerated value is read (`MachineMode.Auto`), and a method is
/// called through the list (`GVL.fbA.SignalEnable(...)`).
#[test]
fn names_of_a_qualified_only_list_leave_actions_enumerations_and_methods_alone() {
    let dir = tempfile::tempdir().unwrap();
    let gvl = dir.path().join("GVL.st");
    std::fs::write(
        &gvl,
        "{attribute 'qualified_only'}\nVAR_GLOBAL\n  axes : ARRAY [1..2] OF INT;\n  fbA : FB_Sig;\n  machineMode : MachineMode;\nEND_VAR\n",
    )
    .unwrap();
    let main = dir.path().join("main.st");
    std::fs::write(
        &main,
        "FUNCTION_BLOCK FB_Sig
VAR_OUTPUT bOut : BOOL; END_VAR
METHOD SignalEnable : BOOL
VAR_INPUT bEn : BOOL; END_VAR
bOut := bEn;
SignalEnable := TRUE;
END_METHOD
END_FUNCTION_BLOCK
TYPE MachineMode : (Manual, Auto); END_TYPE
PROGRAM Main
VAR n : INT; ok : BOOL; END_VAR
AXES();
GVL.axes[1] := n;
GVL.fbA.SignalEnable(bEn := n > 1);
GVL.machineMode := MachineMode.Auto;
ok := GVL.fbA.bOut AND GVL.machineMode = MachineMode.Auto;
END_PROGRAM
ACTIONS
ACTION AXES:
n := n + 1;
END_ACTION
END_ACTIONS
",
    )
    .unwrap();
    let (trace, _) = run_traced_files(&[&gvl, &main], 2, "GVL.axes[1],Main.ok");
    assert_eq!(
        trace,
        "cycle,time_ms,GVL.axes[1],Main.ok\n0,0,1,0\n1,10,2,1\n"
    );
}

/// A required input (MC_Reset's `Execute`) left out of one call of an instance and bound in
/// another: the input keeps its value between calls, so the project checks; left out of every
/// call it is E4023 at each.
#[test]
fn a_required_input_may_be_bound_by_another_call_of_the_instance() {
    let dir = tempfile::tempdir().unwrap();
    axes_file(dir.path(), "reset");
    let src = |second: &str| {
        format!(
            "PROGRAM MAIN\nVAR\n    ax : AXIS_REF;\n    rst : MC_Reset;\n    go : BOOL;\n    st : INT;\nEND_VAR\n\
             rst(Axis := ax);\nCASE st OF\n0: {second}\n   IF rst.Done THEN st := 1; END_IF\nEND_CASE\nEND_PROGRAM\n"
        )
    };
    let check = |text: String| {
        let f = dir.path().join("reset.st");
        std::fs::write(&f, text).unwrap();
        let out = ladderc()
            .args(["--message-format", "short", "check"])
            .arg(&f)
            .output()
            .unwrap();
        let stderr =
            String::from_utf8_lossy(&out.stderr).replace(&format!("{}/", dir.path().display()), "");
        (out.status.code(), stderr)
    };
    let (code, stderr) = check(src("rst(Axis := ax, Execute := go);"));
    assert_eq!((code, stderr.as_str()), (Some(0), ""));
    let (code, stderr) = check(src("rst(Axis := ax);"));
    assert_eq!(code, Some(1), "{stderr}");
    let heads: Vec<&str> = stderr
        .lines()
        .map(|l| l.split(" (hint").next().unwrap())
        .collect();
    assert_eq!(
        heads,
        [
            "reset.st:8:1: error[E4023]: required input `Execute` of `MC_Reset` (instance `rst`) is not bound",
            "reset.st:10:4: error[E4023]: required input `Execute` of `MC_Reset` (instance `rst`) is not bound",
        ]
    );
}

/// A solution given by its bare name from its own folder reads its PLC project; a solution whose
/// PLC project is not there is one located E1079 naming it (exit 1), for the `.sln` and the
/// `.tsproj`.
#[test]
fn a_solution_is_read_from_its_own_folder_and_a_missing_plc_project_is_located() {
    let dir = tempfile::tempdir().unwrap();
    let sln = "\nMicrosoft Visual Studio Solution File, Format Version 12.00\n\
               Project(\"{B1E792BE-AA5F-4E3C-8C82-674BF9C0715B}\") = \"Demo\", \"Demo.tsproj\", \"{47B55B41-E449-41DF-B79A-0A3C932F2E52}\"\nEndProject\n";
    let tsproj = "<?xml version=\"1.0\"?>\n<TcSmProject TcSmVersion=\"1.0\" TcVersion=\"3.1.4022.30\">\n\t<Project>\n\t\t<Plc>\n\t\t\t<Project Name=\"PLC\" PrjFilePath=\"PLC\\PLC.plcproj\" AmsPort=\"851\"/>\n\t\t</Plc>\n\t</Project>\n</TcSmProject>\n";
    std::fs::write(dir.path().join("Demo.sln"), sln).unwrap();
    std::fs::write(dir.path().join("Demo.tsproj"), tsproj).unwrap();
    let check = |input: &str| {
        let out = ladderc()
            .current_dir(dir.path())
            .args(["--message-format", "short", "check", input])
            .output()
            .unwrap();
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    for input in ["Demo.sln", "Demo.tsproj"] {
        let (code, stderr) = check(input);
        assert_eq!(code, Some(1), "{stderr}");
        assert_eq!(
            stderr.lines().map(|l| l.split(" (hint").next().unwrap()).collect::<Vec<_>>(),
            ["Demo.tsproj:5:37: error[E1079]: the solution lists PLC\\PLC.plcproj, which is not there"],
            "{input}"
        );
    }
    std::fs::create_dir(dir.path().join("PLC")).unwrap();
    std::fs::write(
        dir.path().join("PLC/PLC.plcproj"),
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Project xmlns=\"http://schemas.microsoft.com/developer/msbuild/2003\">\n  <ItemGroup>\n    <Compile Include=\"MAIN.TcPOU\"><SubType>Code</SubType></Compile>\n  </ItemGroup>\n</Project>\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("PLC/MAIN.TcPOU"),
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  <POU Name=\"MAIN\" Id=\"{576e9352-28e5-424b-9181-de377b879873}\" SpecialFunc=\"None\">\n    <Declaration><![CDATA[PROGRAM MAIN\nVAR\n\tn : INT;\nEND_VAR\n]]></Declaration>\n    <Implementation>\n      <ST><![CDATA[n := n + 1;]]></ST>\n    </Implementation>\n  </POU>\n</TcPlcObject>\n",
    )
    .unwrap();
    for input in ["Demo.sln", "Demo.tsproj"] {
        let out = ladderc()
            .current_dir(dir.path())
            .args(["run", input, "--cycles", "2", "--trace", "-"])
            .output()
            .unwrap();
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert_eq!(
            String::from_utf8_lossy(&out.stdout),
            "cycle,time_ms,MAIN.n\n0,0,1\n1,10,2\n"
        );
    }
}

/// `run` of a file of function blocks only: the cycles run, and W1441 at the first POU says that
/// no program calls them; with a program beside them, no W1441.
#[test]
fn run_without_a_program_says_nothing_runs() {
    let fb = "FUNCTION_BLOCK FB_Count\nVAR_INPUT bIn : BOOL; END_VAR\nVAR_OUTPUT nCount : INT; END_VAR\nIF bIn THEN nCount := nCount + 1; END_IF\nEND_FUNCTION_BLOCK\n";
    let (trace, stderr) = run_text("fb.st", fb, 2, "");
    assert_eq!(trace, "cycle,time_ms\n0,0\n1,10\n");
    assert!(
        stderr.contains("fb.st:1:1: warning[W1441]: nothing to run: the inputs declare no PROGRAM (1 function block(s) and function(s)"),
        "{stderr}"
    );
    let with_program =
        format!("{fb}PROGRAM Main\nVAR c : FB_Count; END_VAR\nc(bIn := TRUE);\nEND_PROGRAM\n");
    let (trace, stderr) = run_text("both.st", &with_program, 2, "Main.c.nCount");
    assert_eq!(trace, "cycle,time_ms,Main.c.nCount\n0,0,1\n1,10,2\n");
    assert!(!stderr.contains("W1441"), "{stderr}");
}

/// An enumeration without `{attribute 'strict'}` indexes an array by its number (W1439); a
/// strict one and a REAL are E1021, each with the conversion to write.
#[test]
fn a_loose_enumeration_indexes_an_array_by_its_number() {
    let src = "TYPE E_P : (A := 1, B := 2, C := 3); END_TYPE
PROGRAM Main
VAR arr : ARRAY[1..3] OF LREAL; x : LREAL; END_VAR
arr[E_P.B] := 5.0;
x := arr[E_P.C] + arr[E_P.B];
END_PROGRAM
";
    let (trace, stderr) = run_text("index.st", src, 1, "Main.arr[2],Main.x");
    assert_eq!(trace, "cycle,time_ms,Main.arr[2],Main.x\n0,0,5,5\n");
    assert!(stderr.contains("index.st:4:5: warning[W1439]"), "{stderr}");
    // a strict enumeration indexes too: {attribute 'strict'} forbids arithmetic and storing
    // other values (Infosys), not indexing (ISIS's `fParameters[eRWParameter.EnableLimitPos]`);
    // a REAL index stays an error
    let strict = "{attribute 'strict'}\nTYPE E_S : (X := 1, Y := 2); END_TYPE\nPROGRAM Main\nVAR arr : ARRAY[1..3] OF INT; v : INT; END_VAR\narr[E_S.Y] := 5;\nv := arr[E_S.Y] + 1;\nEND_PROGRAM\n";
    let (trace, stderr) = run_text("strict.st", strict, 1, "Main.arr[2],Main.v");
    assert_eq!(trace, "cycle,time_ms,Main.arr[2],Main.v\n0,0,5,6\n");
    assert!(
        stderr.contains("strict.st:5:5: warning[W1439]")
            && stderr.contains("also under {attribute 'strict'}"),
        "{stderr}"
    );
    let heads = rejected_heads(
        "real.st",
        "PROGRAM Main\nVAR arr : ARRAY[1..3] OF INT; r : REAL := 1.0; END_VAR\narr[r] := 1;\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        ["real.st:3:5: error[E1021]: an array index must be an integer, not REAL"]
    );
    let (_, lines) = common::check_text(
        "real.st",
        "PROGRAM Main\nVAR arr : ARRAY[1..3] OF INT; r : REAL := 1.0; END_VAR\narr[r] := 1;\nEND_PROGRAM\n",
    );
    assert!(
        lines[0].ends_with("(hint: convert the index: REAL_TO_DINT(...))"),
        "{lines:?}"
    );
}

/// Invalid inputs get one diagnostic per cause, in the user's words: a FOR without `:=`, a
/// library-qualified call where a CASE label belongs, a library-qualified type in a call chain,
/// and an ST function that never sets its result.
#[test]
fn invalid_inputs_get_one_diagnostic_in_the_users_words() {
    let for_src = "PROGRAM p\nVAR\n  i : USINT;\n  n : USINT;\nEND_VAR\nIF TRUE THEN\n  FOR i TO 5 DO\n    n := n + 1;\n  END_FOR;\nEND_IF;\nEND_PROGRAM\n";
    assert_eq!(
        rejected_heads("for.st", for_src),
        ["for.st:7:9: error[E0100]: expected `:=` after the FOR control variable, found `TO`"]
    );
    let case_src =
        "PROGRAM p\nVAR i : INT; END_VAR\nCASE i OF\n  Foo.Bar();\nEND_CASE;\nEND_PROGRAM\n";
    assert_eq!(
        rejected_heads("case.st", case_src),
        [
            "case.st:4:3: error[E1032]: `Foo` is neither a variable nor a library ladderc provides",
            "case.st:4:3: error[E0100]: expected a CASE label such as `1:`, `2, 3:` or `4..6:`, found a library-qualified name",
        ]
    );
    let chain_src = "FUNCTION_BLOCK FB_X\nVAR\n    fbAlarm : Tc3_EventLogger.FB_TcAlarm;\nEND_VAR\nMETHOD M : BOOL\nfbAlarm.ipArguments.Clear().AddString(1);\nEND_METHOD\nEND_FUNCTION_BLOCK\nPROGRAM MAIN\nVAR x : FB_X; END_VAR\nx.M();\nEND_PROGRAM\n";
    assert_eq!(
        rejected_heads("chain.st", chain_src),
        ["chain.st:3:15: error[E1032]: `Tc3_EventLogger` is neither a variable nor a library ladderc provides"]
    );
    let pack_src = "FUNCTION Pack : BOOL\nVAR_INPUT\n  b : BOOL;\nEND_VAR\nVAR_IN_OUT\n  w : WORD;\nEND_VAR\n  w.0 := b;\nEND_FUNCTION\n\nPROGRAM p\nVAR\n  w : WORD;\nEND_VAR\n  Pack(b := TRUE, w := w);\nEND_PROGRAM\n";
    let (code, lines) = common::check_text("pack.st", pack_src);
    assert_eq!(code, Some(0));
    assert_eq!(
        lines,
        ["pack.st:1:10: warning[W1003]: function `Pack` never sets its result (hint: assign the result: `Pack := ...;` in ST, `ST Pack` in IL (it is 0/FALSE/empty otherwise))"]
    );
}

/// Two PLCopen XML exports given together are one project: the program of one file calls the
/// function block of the other (an ST call and an FBD box) and declares a variable of its
/// structure type.
#[test]
fn plcopen_files_given_together_see_each_others_pous_and_types() {
    let dir = tempfile::tempdir().unwrap();
    let head = |name: &str| {
        format!(
            r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP21" creationDateTime="2025-01-01T00:00:00" />
  <contentHeader name="{name}"><coordinateInfo><fbd><scaling x="1" y="1" /></fbd><ld><scaling x="1" y="1" /></ld><sfc><scaling x="1" y="1" /></sfc></coordinateInfo></contentHeader>
"#
        )
    };
    let fb = format!(
        r#"{}  <types><dataTypes>
    <dataType name="ST_Total"><baseType><struct>
      <variable name="n"><type><INT /></type></variable>
      <variable name="busy"><type><BOOL /></type></variable>
    </struct></baseType></dataType>
  </dataTypes><pous>
    <pou name="FB_Count" pouType="functionBlock">
      <interface>
        <inputVars><variable name="bIn"><type><BOOL /></type></variable></inputVars>
        <outputVars><variable name="nCount"><type><INT /></type></variable></outputVars>
      </interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">IF bIn THEN nCount := nCount + 1; END_IF</xhtml></ST></body>
    </pou>
  </pous></types>
  <instances><configurations /></instances>
</project>
"#,
        head("FB_Count")
    );
    let prg = format!(
        r#"{}  <types><dataTypes /><pous>
    <pou name="PRG_Main" pouType="program">
      <interface>
        <localVars>
          <variable name="fbC"><type><derived name="FB_Count" /></type></variable>
          <variable name="fbD"><type><derived name="FB_Count" /></type></variable>
          <variable name="go"><type><BOOL /></type><initialValue><simpleValue value="TRUE" /></initialValue></variable>
          <variable name="boxed"><type><INT /></type></variable>
          <variable name="total"><type><derived name="ST_Total" /></type></variable>
        </localVars>
      </interface>
      <body><FBD>
        <inVariable localId="1" height="20" width="40"><position x="10" y="10"/>
          <connectionPointOut><relPosition x="40" y="10"/></connectionPointOut><expression>go</expression></inVariable>
        <block localId="2" typeName="FB_Count" instanceName="fbD" height="60" width="60"><position x="100" y="10"/>
          <inputVariables>
            <variable formalParameter="bIn"><connectionPointIn><relPosition x="0" y="30"/><connection refLocalId="1"/></connectionPointIn></variable>
          </inputVariables>
          <inOutVariables/>
          <outputVariables>
            <variable formalParameter="nCount"><connectionPointOut><relPosition x="60" y="30"/></connectionPointOut></variable>
          </outputVariables>
        </block>
        <outVariable localId="3" height="20" width="40"><position x="200" y="30"/>
          <connectionPointIn><relPosition x="0" y="10"/><connection refLocalId="2" formalParameter="nCount"/></connectionPointIn><expression>boxed</expression></outVariable>
      </FBD></body>
      <addData><data name="http://www.3s-software.com/plcopenxml/pouinstance" handleUnknown="discard"/></addData>
    </pou>
    <pou name="PRG_Sum" pouType="program">
      <interface>
        <externalVars />
      </interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">PRG_Main.fbC(bIn := TRUE);
PRG_Main.total.n := PRG_Main.fbC.nCount * 10;
PRG_Main.total.busy := PRG_Main.total.n &gt; 15;</xhtml></ST></body>
    </pou>
  </pous></types>
  <instances><configurations /></instances>
</project>
"#,
        head("PRG_Main")
    );
    let fb_file = dir.path().join("fb.xml");
    let prg_file = dir.path().join("prg.xml");
    std::fs::write(&fb_file, fb).unwrap();
    std::fs::write(&prg_file, prg).unwrap();
    let (trace, stderr) = run_traced_files(
        &[&fb_file, &prg_file],
        2,
        "PRG_Main.boxed,PRG_Main.fbC.nCount,PRG_Main.total.n,PRG_Main.total.busy",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,PRG_Main.boxed,PRG_Main.fbC.nCount,PRG_Main.total.n,PRG_Main.total.busy\n0,0,1,1,10,0\n1,10,2,2,20,1\n",
        "{stderr}"
    );
}

/// `HomingMode := MC_HomingMode.MC_Direct` of the Tc2_MC2 MC_Home: the position is set to
/// `Position` on the spot, the axis homed, Done in the next cycle.
#[test]
fn tc2_mc_direct_sets_the_position_without_a_movement() {
    let dir = tempfile::tempdir().unwrap();
    axes_file(dir.path(), "home");
    let f = dir.path().join("home.st");
    std::fs::write(
        &f,
        "PROGRAM MAIN
VAR
    ax : AXIS_REF;
    pw : MC_Power;
    hm : MC_Home;
    go : BOOL;
    done : BOOL;
    homed : BOOL;
END_VAR
pw(Axis := ax, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);
go := pw.Status;
hm(Axis := ax, Execute := go, Position := 5.0, HomingMode := MC_HomingMode.MC_Direct);
done := hm.Done;
homed := ax.Status.Homed;
END_PROGRAM
",
    )
    .unwrap();
    let (trace, _) = run_traced_files(
        &[&f],
        3,
        "MAIN.done,MAIN.homed,axis.X.position,MAIN.hm.Error",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,MAIN.done,MAIN.homed,axis.X.position,MAIN.hm.Error\n0,0,0,0,5,0\n1,10,1,1,5,0\n2,20,1,1,5,0\n"
    );
}

/// `VAR PUBLIC` in a function block is its VAR (a variable named `public` stays one), and an
/// edition-3 CLASS is compiled (round 26: before, W0304 at the word, one E1076 per class; the
/// classes themselves are tested in `classes_run.rs`).
#[test]
fn var_public_is_read_and_a_class_is_compiled() {
    let src = "FUNCTION_BLOCK fb
VAR PUBLIC
  x : BOOL;
END_VAR
VAR
  public : INT;
END_VAR
  x := NOT x;
  public := public + 1;
END_FUNCTION_BLOCK
PROGRAM p
VAR f : fb; END_VAR
  f();
END_PROGRAM
";
    let (trace, stderr) = run_text("public.st", src, 2, "p.f.x,p.f.public");
    assert_eq!(trace, "cycle,time_ms,p.f.x,p.f.public\n0,0,1,1\n1,10,0,2\n");
    assert!(!stderr.contains("W0304"), "{stderr}");
    let class_src = "CLASS Valve
  VAR PUBLIC
    bIsOpen : BOOL;
  END_VAR
  METHOD Open
    bIsOpen := TRUE;
  END_METHOD
END_CLASS

CLASS OutputValve EXTENDS Valve
  VAR PUBLIC
    drain : BOOL;
  END_VAR
END_CLASS

PROGRAM p
VAR
  n : INT;
END_VAR
  n := n + 1;
END_PROGRAM
";
    let (trace, stderr) = run_text("class.st", class_src, 2, "p.n");
    assert_eq!(trace, "cycle,time_ms,p.n\n0,0,1\n1,10,2\n", "{stderr}");
}

/// `VAR RETAIN PUBLIC` and `VAR CONSTANT PRIVATE`: the blocks read with their qualifiers, the
/// specifier kept (round 26: before, ignored with W0304; `classes_run.rs` tests what it does).
#[test]
fn an_access_specifier_after_the_blocks_qualifiers_is_kept() {
    let src = "FUNCTION_BLOCK fb
VAR RETAIN PUBLIC
  n : INT;
END_VAR
VAR CONSTANT PRIVATE
  step : INT := 5;
END_VAR
  n := n + step;
END_FUNCTION_BLOCK
PROGRAM p
VAR f : fb; END_VAR
  f();
END_PROGRAM
";
    let (trace, stderr) = run_text("retain_public.st", src, 2, "p.f.n");
    assert_eq!(trace, "cycle,time_ms,p.f.n\n0,0,5\n1,10,10\n");
    assert!(!stderr.contains("W0304"), "{stderr}");
}

/// MC_Reset called with `Execute := TRUE` once and then without Execute: Execute stays TRUE in
/// the instance, so Done stays TRUE (PLCopen: Done is kept while Execute is TRUE), with the IL
/// method and with the template method.
#[test]
fn an_input_left_out_of_a_block_call_keeps_its_last_value() {
    let dir = tempfile::tempdir().unwrap();
    axes_file(dir.path(), "keep");
    let f = dir.path().join("keep.st");
    std::fs::write(
        &f,
        "PROGRAM MAIN
VAR
    ax : AXIS_REF;
    rst : MC_Reset;
    n : INT;
END_VAR
n := n + 1;
IF n = 3 THEN rst(Axis := ax, Execute := TRUE); ELSE rst(Axis := ax); END_IF
END_PROGRAM
",
    )
    .unwrap();
    let expected = "cycle,time_ms,MAIN.n,MAIN.rst.Execute,MAIN.rst.Done\n0,0,1,0,0\n1,10,2,0,0\n2,20,3,1,1\n3,30,4,1,1\n4,40,5,1,1\n";
    for strategy in ["il", "template"] {
        let out = ladderc()
            .args(["--message-format", "short", "run"])
            .arg(&f)
            .args([
                "--strategy",
                strategy,
                "--cycles",
                "5",
                "--sanitize",
                "--trace",
                "-",
            ])
            .args(["--watch", "MAIN.n,MAIN.rst.Execute,MAIN.rst.Done"])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{strategy}: {stderr}");
        assert_eq!(String::from_utf8_lossy(&out.stdout), expected, "{strategy}");
    }
}

/// `RETURN (cond);` leaves the block when `cond` holds; `RETURN(b := e);` assigns `b` first and
/// tests it.
#[test]
fn a_conditional_return_leaves_when_its_condition_holds() {
    let src = "FUNCTION_BLOCK FB_R
VAR_INPUT go : BOOL; END_VAR
VAR_OUTPUT n : INT; m : INT; END_VAR
VAR bInit : BOOL := TRUE; t : INT; END_VAR
IF bInit THEN
  t := t + 1;
  RETURN(bInit := t <= 2);
END_IF
RETURN (NOT go);
n := n + 1;
RETURN(n > 3);
m := m + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR f : FB_R; g : BOOL; END_VAR
f(go := g);
g := NOT g;
END_PROGRAM
";
    let (trace, _) = run_text("ret.st", src, 10, "Main.f.t,Main.f.n,Main.f.m");
    assert_eq!(
        column(&trace, "Main.f.t"),
        [1.0, 2.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0]
    );
    assert_eq!(
        column(&trace, "Main.f.n"),
        [0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0]
    );
    assert_eq!(
        column(&trace, "Main.f.m"),
        [0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 3.0]
    );
}

/// A name alone as a statement: a declared one is W1431 and does nothing; one nothing declares
/// is E1001.
#[test]
fn a_name_alone_must_be_declared() {
    let src = "PROGRAM Main\nVAR b : BOOL; n : INT; END_VAR\nb;\nFoo;\nn := n + 1;\nEND_PROGRAM\n";
    let (code, lines) = common::check_text("named.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split(" (hint").next().unwrap())
        .collect();
    assert_eq!(
        heads,
        [
            "named.st:3:1: warning[W1431]: `b;` has no effect: it names a value and does nothing with it",
            "named.st:4:1: error[E1001]: undeclared name `Foo`",
            "named.st:4:1: warning[W1431]: `Foo;` has no effect: it names a value and does nothing with it",
        ]
    );
}

/// efranceschetti/festo-codesys-mcp (MIT, `tests/corpus/efranceschetti_festo-codesys-mcp_*.xml`): CODESYS's export of PRG_Main and, in another
/// file, of the FB_StateMachine it calls. Given together they run: the start button (cycle 2)
/// moves the machine to WORKING (state 10, busy) and, the TON watchdog's 5 s later, to ERROR
/// (state 99, error 100, not busy). The repository's test tool writes `creationDateTime="<NORMALIZED>"`
/// into both files, which XML 1.0 makes not well-formed (`<` in an attribute value, 2.3 [10]; CODESYS
/// writes a date there): since round 29 each file as it is is one E3001 at that `<`, and the run is
/// of copies with a date in its place.
#[test]
fn festo_exports_of_one_object_each_run_together() {
    let dir = tempfile::tempdir().unwrap();
    let files = ["prg-cyclic", "fb-state-machine"].map(|f| {
        let original = common::repo_root().join(format!(
            "tests/corpus/efranceschetti_festo-codesys-mcp_{f}.xml"
        ));
        let (code, lines) =
            common::check_files(&[("export.xml", &std::fs::read_to_string(&original).unwrap())]);
        assert_eq!(code, Some(1), "{lines:?}");
        let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
        assert_eq!(errors.len(), 1, "{lines:?}");
        assert!(
            errors[0].contains("export.xml:3:105: error[E3001]")
                && errors[0].contains("`<` in the value of attribute `creationDateTime`"),
            "{lines:?}"
        );
        let text = std::fs::read_to_string(&original)
            .unwrap()
            .replace("<NORMALIZED>", "2025-01-01T00:00:00");
        let copy = dir.path().join(format!("{f}.xml"));
        std::fs::write(&copy, text).unwrap();
        copy
    });
    let watch = "PRG_Main.fbWorker.nState,PRG_Main.fbWorker.bBusy,PRG_Main.fbWorker.bErr,PRG_Main.fbWorker.nErrId";
    let (trace, _) = run_stimulated_files(
        &files,
        &["--cycle-ms", "10"],
        510,
        "2,PRG_Main.bStart,TRUE\n",
        watch,
    );
    let state = column(&trace, "PRG_Main.fbWorker.nState");
    let busy = column(&trace, "PRG_Main.fbWorker.bBusy");
    let err = column(&trace, "PRG_Main.fbWorker.bErr");
    assert_eq!(state[..3], [0.0, 0.0, 10.0]);
    assert_eq!(busy[..4], [0.0, 0.0, 0.0, 1.0]);
    // the watchdog runs from cycle 3 (state 10): Q after 5 s, at cycle 503
    let first_error = state.iter().position(|s| *s == 99.0).unwrap();
    assert_eq!(first_error, 503, "{:?}", &state[498..506]);
    assert_eq!(err[first_error + 1], 1.0);
    assert_eq!(busy[first_error + 1], 0.0);
    assert_eq!(
        column(&trace, "PRG_Main.fbWorker.nErrId")[first_error],
        100.0
    );
}

/// An axes file `<stem>.axes.json` in `dir`: one axis X (mm, 100 mm/s, 1000 mm/s²) linked to
/// `MAIN.ax`, for the source `<stem>.st` beside it.
fn axes_file(dir: &std::path::Path, stem: &str) {
    std::fs::write(
        dir.join(format!("{stem}.axes.json")),
        r#"{ "cycle_ms": 10, "axes": [ { "name": "X", "unit": "mm", "velocity": 100, "acceleration": 1000, "deceleration": 1000, "jerk": 0, "link": "MAIN.ax" } ] }"#,
    )
    .unwrap();
}
