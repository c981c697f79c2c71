//! Round 20 of unseen projects (issue #13): forms that the round's real programs use, run end to
//! end through `ladderc run`:
//! - a method called through an interface that is a function block's output (`d.itf.Get()`,
//!   trofimich/TwinCAT.OpenFramework; before: a false E1015 "`itf` is an output of FB instance
//!   `d`");
//! - standard functions of constants in a declaration's constant expression (`SQRT(4.0)`,
//!   `MAX(3, 7, 5)`, `REAL_TO_INT(2.5)`, `TO_REAL(LOG(-1))`, TwinCAT's way to write NaN; before:
//!   E0011 "unexpected literal `-1` (hint: expected a name)");
//! - TwinCAT's `XSIZEOF` (before: E1003, an unknown function);
//! - an open input of a standard function box (Beremiz's LD `MOVE` with no wire at `IN`, and the
//!   ST Beremiz generates for it, `MOVE(EN := go, ENO => ok)`: legsano/FactoryIO-OpenPLCEditor's
//!   Pick_and_Place_XYZ) takes 0 as IEC 61131-3 and matiec give it (before: E3013, E1020);
//! - OpenPLC Editor v4: an array variable exported as `<derived name="ARRAY [0..4999] OF INT"/>`
//!   (VBlackie/PLC_FIFO_Optimization; before: E3013), and a v4 project folder (`project.json`,
//!   `pous/**.st`) read with its tasks, instances and globals (before: E9001);
//! - a TwinCAT solution given as its `.sln` or `.tsproj` (before: the `.sln` read as IL, 227-332
//!   errors on real solutions; the `.tsproj` E3002), and MSBuild's `%28`/`%29` escapes in a
//!   `.plcproj`'s paths (Beckhoff's XTS_Base: `XTS %28Do Not Edit%29\...`; before: E1079, 25 files
//!   missing);
//! - an element of an `ARRAY [*]` given to an ANY input: one located E1068 (before: the compiler
//!   overflowed its stack and aborted, exit 134), and the element copied first runs;
//! - a POU's constant named above its declaration (`ARRAY[0..TABLESIZE - 1]`, `TON := (PT :=
//!   DELAY)` above `VAR CONSTANT`: KimRo's Tc3_CRC, Roald87's SimRelay; before: E0022, E1025);
//! - `SHL(1, 1)` in a constant, `[N(7)]` with a named repeat count, TwinCAT's `BIT`, `r REF= 0;`,
//!   `bExecute;` (W1431), and a call chain on a variable of a library's block type (one E1003 for
//!   the type; before: E0349 "is no method", the type never named);
//! - an unknown function's call is one E1019 (before: also a W1001 "result never used" with IL's
//!   hint, even in ST: 52 in round 20's OpenPLC files), and `TON` called as an IL operator says
//!   it is a block type;
//! - a FUNCTION written inside a PROGRAM's body (Bentusi/STVM's test files): one E0106 per
//!   nested POU, its text skipped (before: one error per line, 2,362 in one file);
//! - corpus: FraBenni/FactoryIO-PLC's Fischertechnik test-bed cell (MIT), its ST export and its
//!   Beremiz XML, which run to the same trace.

mod common;
use common::{check_text, column, run_stimulated_files, run_text, run_traced};

/// `d.itf.Get()` runs the method of the instance that `d` put in its output `itf`, and writing
/// the output itself from outside stays E1015.
#[test]
fn a_method_is_called_through_an_interface_output_of_a_block() {
    let src = "INTERFACE I_Get
METHOD Get : INT
END_METHOD
END_INTERFACE

FUNCTION_BLOCK Impl IMPLEMENTS I_Get
VAR_INPUT k : INT := 3; END_VAR
METHOD Get : INT
Get := k * 2;
END_METHOD
END_FUNCTION_BLOCK

FUNCTION_BLOCK Holder
VAR_OUTPUT itf : I_Get; END_VAR
VAR inner : Impl; END_VAR
inner.k := inner.k + 1;
itf := inner;
END_FUNCTION_BLOCK

PROGRAM main
VAR d : Holder; v : INT; before : INT; END_VAR
IF d.itf <> 0 THEN
  before := 99;
END_IF
d();
IF d.itf <> 0 THEN
  v := d.itf.Get();
END_IF
END_PROGRAM
";
    let (trace, stderr) = run_text("itf_out.st", src, 3, "main.v,main.before");
    assert_eq!(column(&trace, "main.v"), [8.0, 10.0, 12.0], "{stderr}");
    assert_eq!(column(&trace, "main.before"), [0.0, 99.0, 99.0]);
    let (code, lines) = check_text(
        "itf_write.st",
        &src.replace("  v := d.itf.Get();", "  d.itf := 0;"),
    );
    assert_eq!(code, Some(1));
    assert!(
        lines.iter().any(|l| l
            .starts_with("itf_write.st:27:3: error[E1015]: `itf` is an output of FB instance `d`")),
        "{lines:?}"
    );
}

/// Constants initialised by standard functions of constants take the functions' values (the
/// conversion rounds halves to even), NaN included; a call of something else is one E0022 that
/// says what a constant expression may call.
#[test]
fn standard_functions_of_constants_initialise_constants() {
    let src = "VAR_GLOBAL CONSTANT
  NAN_L : LREAL := LOG(-1);
  NAN_R : REAL := TO_REAL(LOG(-1));
  TWO : LREAL := SQRT(4.0);
  BIG : INT := MAX(3, 7, 5);
  R : INT := REAL_TO_INT(2.5);
  N : DINT := LIMIT(0, 12, 10) * 2;
  LEN : INT := MIN(4, 9);
  T : DINT := TRUNC(-2.7);
END_VAR
PROGRAM main
VAR x : LREAL; y : INT; z : DINT; is_nan : BOOL; a : ARRAY[1..LEN] OF INT; t1 : DINT; END_VAR
x := TWO;
y := BIG * 10 + R;
z := N;
t1 := T;
is_nan := NAN_L <> NAN_L AND NAN_R <> NAN_R;
a[LEN] := 5;
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "const_calls.st",
        src,
        1,
        "main.x,main.y,main.z,main.t1,main.is_nan,main.a[4]",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "main.x"), [2.0]);
    assert_eq!(column(&trace, "main.y"), [72.0]);
    assert_eq!(column(&trace, "main.z"), [20.0]);
    assert_eq!(column(&trace, "main.t1"), [-2.0]);
    assert_eq!(column(&trace, "main.is_nan"), [1.0]);
    assert_eq!(column(&trace, "main.a[4]"), [5.0]);

    let (code, lines) = check_text(
        "const_bad.st",
        "VAR_GLOBAL CONSTANT\n  K : INT := MY_F(2);\n  J : INT := REAL_TO_INT(1.0E10);\nEND_VAR\n\
         PROGRAM main\nVAR x : INT; END_VAR\nx := K + J;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 2, "{lines:?}");
    assert!(
        errors[0].starts_with("const_bad.st:2:14: error[E0022]")
            && errors[0].contains("`MY_F(...)` is a call"),
        "{lines:?}"
    );
    assert!(
        errors[1].starts_with("const_bad.st:3:14: error[E0022]")
            && errors[1].contains("out of INT's range"),
        "{lines:?}"
    );
}

/// TwinCAT's `XSIZEOF` measures as `SIZEOF` does.
#[test]
fn xsizeof_measures_as_sizeof() {
    let src = "TYPE ST_A : STRUCT x : DINT; y : LREAL; END_STRUCT; END_TYPE
PROGRAM main
VAR n : UDINT; m : UDINT; a : ST_A; END_VAR
n := XSIZEOF(a) * 2;
m := SIZEOF(ST_A);
END_PROGRAM
";
    let (trace, stderr) = run_text("xsizeof.st", src, 1, "main.n,main.m");
    assert_eq!(column(&trace, "main.m"), [16.0], "{stderr}");
    assert_eq!(column(&trace, "main.n"), [32.0]);
}

/// An INTERFACE that extends an unknown interface is one located E0330 (before: accepted
/// silently, its missing methods unchecked); TwinCAT's `__SYSTEM.IQueryInterface` stays known
/// (also as `_SYSTEM.`, as purushothaman2310's project writes it), and a method through such an
/// interface runs.
#[test]
fn an_interface_extending_an_unknown_interface_is_one_error() {
    let (code, lines) = check_text(
        "itf_ext.st",
        "INTERFACE I_A EXTENDS I_Missing\nMETHOD Get : INT\nEND_METHOD\nEND_INTERFACE\n\
         PROGRAM main\nVAR x : INT; END_VAR\nx := 1;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with(
            "itf_ext.st:1:23: error[E0330]: `I_A` EXTENDS `I_Missing`, which names no INTERFACE"
        ),
        "{lines:?}"
    );
    let src = "INTERFACE I_A EXTENDS __SYSTEM.IQueryInterface
METHOD Get : INT
END_METHOD
END_INTERFACE
INTERFACE I_B EXTENDS _SYSTEM.IQueryInterface
END_INTERFACE
FUNCTION_BLOCK B IMPLEMENTS I_A
METHOD Get : INT
Get := 4;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM main
VAR x : INT; b : B; i : I_A; END_VAR
i := b;
x := i.Get();
END_PROGRAM
";
    let (trace, stderr) = run_text("itf_system.st", src, 1, "main.x");
    assert_eq!(column(&trace, "main.x"), [4.0], "{stderr}");
}

/// Beremiz's LD `MOVE` whose `IN` has no wire moves 0 (warning W3005 at the pin, located with the
/// POU and localId), and the ST form Beremiz generates for it, with a user function's input left
/// out taking its declared initial value beside it.
#[test]
fn an_open_input_of_a_standard_function_takes_zero() {
    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="x" productName="x" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="p"><coordinateInfo><fbd><scaling x="10" y="10"/></fbd><ld><scaling x="10" y="10"/></ld><sfc><scaling x="10" y="10"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="main" pouType="program">
      <interface><localVars>
        <variable name="go"><type><BOOL/></type><initialValue><simpleValue value="TRUE"/></initialValue></variable>
        <variable name="spz"><type><INT/></type><initialValue><simpleValue value="7"/></initialValue></variable>
      </localVars></interface>
      <body><FBD>
        <inVariable localId="1" height="20" width="40"><position x="10" y="10"/>
          <connectionPointOut><relPosition x="40" y="10"/></connectionPointOut><expression>go</expression></inVariable>
        <block localId="2" typeName="MOVE" height="60" width="60"><position x="100" y="10"/>
          <inputVariables>
            <variable formalParameter="EN"><connectionPointIn><relPosition x="0" y="30"/><connection refLocalId="1"/></connectionPointIn></variable>
            <variable formalParameter="IN"><connectionPointIn><relPosition x="0" y="50"/></connectionPointIn></variable>
          </inputVariables>
          <inOutVariables/>
          <outputVariables>
            <variable formalParameter="ENO"><connectionPointOut><relPosition x="60" y="30"/></connectionPointOut></variable>
            <variable formalParameter="OUT"><connectionPointOut><relPosition x="60" y="50"/></connectionPointOut></variable>
          </outputVariables>
        </block>
        <outVariable localId="3" height="20" width="40"><position x="200" y="30"/>
          <connectionPointIn><relPosition x="0" y="10"/><connection refLocalId="2" formalParameter="OUT"/></connectionPointIn><expression>spz</expression></outVariable>
      </FBD></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="c"><resource name="r"><task name="t" interval="T#10ms" priority="0"><pouInstance name="p" typeName="main"/></task></resource></configuration></configurations></instances>
</project>
"#;
    let (trace, stderr) = run_text("move_open_in.xml", xml, 1, "p.spz");
    assert_eq!(column(&trace, "p.spz"), [0.0], "{stderr}");
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("warning[")).collect();
    assert_eq!(warnings.len(), 1, "{stderr}");
    assert!(
        warnings[0].contains(
            "move_open_in.xml:17:13: warning[W3005]: input `IN` of function MOVE is not connected: it takes 0 [POU `main`, network 1, localId 2]"
        ),
        "{stderr}"
    );

    let st = "FUNCTION ADD1 : INT
  VAR_INPUT a : INT; b : INT := 5; END_VAR
  ADD1 := a + b;
END_FUNCTION

PROGRAM main
  VAR go : BOOL := TRUE; out1 : INT := 7; eno1 : BOOL; r : INT; lim : INT := 9; END_VAR
  out1 := MOVE(EN := go, ENO => eno1);
  r := ADD1(a := 1);
  lim := LIMIT(MN := 2, IN := lim);
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "move_missing_in.st",
        st,
        1,
        "main.out1,main.eno1,main.r,main.lim",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "main.out1"), [0.0]);
    assert_eq!(column(&trace, "main.eno1"), [1.0]);
    assert_eq!(column(&trace, "main.r"), [6.0]);
    // MX left out is 0: LIMIT(2, 9, 0) = MIN(MAX(9, 2), 0) = 0
    assert_eq!(column(&trace, "main.lim"), [0.0]);
}

/// `<derived name="ARRAY [0..4] OF INT"/>`, as OpenPLC Editor v4 exports an array variable of an
/// ST POU, is the array (a FIFO filled cycle by cycle reads back what it stored).
#[test]
fn an_array_written_as_a_derived_name_is_the_array() {
    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="Unknown" productName="Unnamed" productVersion="1" creationDateTime="2026-02-02T14:07:16"/>
  <contentHeader name="Unnamed"><coordinateInfo><fbd><scaling x="10" y="10"/></fbd><ld><scaling x="10" y="10"/></ld><sfc><scaling x="10" y="10"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="main" pouType="program">
      <interface><localVars>
        <variable name="Buffer"><type><derived name="ARRAY [0..4] OF INT"/></type></variable>
        <variable name="Grid"><type><derived name="ARRAY[1..2, 0..1] OF BOOL"/></type></variable>
        <variable name="n"><type><INT/></type></variable>
        <variable name="back"><type><INT/></type></variable>
        <variable name="corner"><type><BOOL/></type></variable>
      </localVars></interface>
      <body><ST><xhtml:p><![CDATA[Buffer[n] := n * 10; back := Buffer[n]; Grid[2, 1] := TRUE; corner := Grid[2, 1] AND NOT Grid[1, 0]; n := n + 1; IF n > 4 THEN n := 0; END_IF;]]></xhtml:p></ST></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="Config0"><resource name="Res0"><task name="task0" interval="T#10ms" priority="0"><pouInstance name="instance0" typeName="main"/></task></resource></configuration></configurations></instances>
</project>
"#;
    let (trace, stderr) = run_text(
        "v4_array.xml",
        xml,
        6,
        "instance0.back,instance0.Buffer[4],instance0.corner",
    );
    assert_eq!(
        column(&trace, "instance0.back"),
        [0.0, 10.0, 20.0, 30.0, 40.0, 0.0],
        "{stderr}"
    );
    assert_eq!(
        column(&trace, "instance0.Buffer[4]"),
        [0.0, 0.0, 0.0, 0.0, 40.0, 40.0]
    );
    assert_eq!(column(&trace, "instance0.corner"), [1.0; 6]);
}

/// An OpenPLC Editor v4 project folder runs: its POU files under `pous/`, its task (T#50ms: the
/// program runs every fifth 10 ms cycle), its instance name and its global variable; an entry that
/// could carry text of its own (an initial value with `;`) is one E1074 and is left out; data
/// types declared in the JSON are named by W1440.
#[test]
fn an_openplc_editor_v4_project_folder_runs() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path().join("garage");
    std::fs::create_dir_all(root.join("pous/programs")).unwrap();
    std::fs::create_dir_all(root.join("pous/function-blocks")).unwrap();
    std::fs::write(
        root.join("project.json"),
        r#"{"meta":{"name":"garage","type":"plc-project"},"data":{"dataTypes":[],"pous":[],
        "configuration":{"resource":{"tasks":[{"name":"task0","triggering":"Cyclic","interval":"T#50ms","priority":1}],
        "instances":[{"name":"instance0","task":"task0","program":"main"}],
        "globalVariables":[{"name":"step","type":{"definition":"base-type","value":"INT"},"location":"","initialValue":"3"}]}}}}"#,
    )
    .unwrap();
    std::fs::write(
        root.join("pous/programs/main.st"),
        "PROGRAM main\nVAR_EXTERNAL step : INT; END_VAR\nVAR c : Counter; count : INT AT %QW0; END_VAR\n\
         c(inc := step);\ncount := c.n;\nEND_PROGRAM\n",
    )
    .unwrap();
    std::fs::write(
        root.join("pous/function-blocks/Counter.st"),
        "FUNCTION_BLOCK Counter\nVAR_INPUT inc : INT; END_VAR\nVAR_OUTPUT n : INT; END_VAR\n\
         n := n + inc;\nEND_FUNCTION_BLOCK\n",
    )
    .unwrap();
    let (trace, stderr) = run_traced(&root, 11, "instance0.count,step");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(
        column(&trace, "instance0.count"),
        [3.0, 3.0, 3.0, 3.0, 3.0, 6.0, 6.0, 6.0, 6.0, 6.0, 9.0]
    );
    assert_eq!(column(&trace, "step"), [3.0; 11]);

    std::fs::write(
        root.join("project.json"),
        r#"{"meta":{"name":"garage","type":"plc-project"},"data":{"dataTypes":[{"name":"E_Door","derivation":{"type":"enumerated","values":["OPEN","SHUT"]}}],"pous":[],
        "configuration":{"resource":{"tasks":[],"instances":[],
        "globalVariables":[{"name":"step","type":{"definition":"base-type","value":"INT"},"location":"","initialValue":"3; END_VAR"}]}}}}"#,
    )
    .unwrap();
    let out = common::ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&root)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert!(
        errors[0].contains("error[E1074]")
            && errors[0].contains("the initial value `3; END_VAR` of `step` is not read"),
        "{stderr}"
    );
    assert!(
        stderr.contains("warning[W1440]")
            && stderr.contains("the data types it declares are not read (E_Door)"),
        "{stderr}"
    );
    // the variable left out: `step` is then undeclared where the program names it
    assert!(
        errors.iter().skip(1).all(|e| e.contains("step")),
        "{stderr}"
    );

    // a graphical POU of the folder (declarations, JSON, then `END_PROGRAM`, as yaseralie's
    // `main.ld`): one E1073 at the JSON (before: 7,649 errors, one per JSON line); since round
    // 24 an FBD body (`"rung": {...}`), a ladder body's rungs being read (openplc_v4_ld_run.rs)
    std::fs::remove_file(root.join("pous/programs/main.st")).unwrap();
    std::fs::write(
        root.join("pous/programs/main.fbd"),
        "PROGRAM main\nVAR\n\tLED1 : bool AT %QX100.0;\nEND_VAR\n\n{\n  \"name\": \"main\",\n  \
         \"rung\": {\n      \"comment\": \"\",\n      \"nodes\": []\n  }\n}\nEND_PROGRAM",
    )
    .unwrap();
    let out = common::ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&root)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert!(
        errors.iter().filter(|e| e.contains("E1073")).count() == 1
            && errors
                .iter()
                .all(|e| e.contains("E1073") || e.contains("E1074")),
        "{stderr}"
    );
    assert!(
        errors
            .iter()
            .any(|e| e.contains("main.fbd:6:1: error[E1073]")),
        "{stderr}"
    );
    // (no note that the file was "read as IL": it was not read)
    assert!(!stderr.contains("W0302"), "{stderr}");
}

/// A TwinCAT project given as its solution (`.sln`), its system project (`.tsproj`) or its
/// `.plcproj` whose `<Compile>` paths MSBuild escapes (`%28` is `(`) runs its MAIN.
#[test]
fn a_twincat_solution_and_escaped_project_paths_are_read() {
    let pou = |name: &str, decl: &str, body: &str| {
        format!(
            "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4024.12\">\n\
             <POU Name=\"{name}\" Id=\"{{11111111-1111-1111-1111-111111111111}}\" SpecialFunc=\"None\">\n\
             <Declaration><![CDATA[{decl}]]></Declaration>\n<Implementation><ST><![CDATA[{body}]]></ST></Implementation>\n\
             </POU>\n</TcPlcObject>\n"
        )
    };
    let dir = tempfile::tempdir().unwrap();
    let plc = dir.path().join("Demo/PLC");
    std::fs::create_dir_all(plc.join("Lib (Do Not Edit)")).unwrap();
    std::fs::write(
        dir.path().join("Demo.sln"),
        "\nMicrosoft Visual Studio Solution File, Format Version 12.00\n# Visual Studio Version 17\n\
         VisualStudioVersion = 17.0.0.0\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("Demo/Demo.tsproj"),
        "<?xml version=\"1.0\"?>\n<TcSmProject TcSmVersion=\"1.0\"><Project><Plc>\
         <Project Name=\"PLC\" PrjFilePath=\"PLC\\PLC.plcproj\"/></Plc></Project></TcSmProject>\n",
    )
    .unwrap();
    std::fs::write(
        plc.join("PLC.plcproj"),
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Project DefaultTargets=\"Build\" \
         xmlns=\"http://schemas.microsoft.com/developer/msbuild/2003\">\n<PropertyGroup><Name>PLC</Name></PropertyGroup>\n\
         <ItemGroup>\n<Compile Include=\"Lib %28Do Not Edit%29\\FB_Count.TcPOU\"/>\n\
         <Compile Include=\"MAIN.TcPOU\"/>\n</ItemGroup>\n</Project>\n",
    )
    .unwrap();
    std::fs::write(
        plc.join("Lib (Do Not Edit)/FB_Count.TcPOU"),
        pou(
            "FB_Count",
            "FUNCTION_BLOCK FB_Count\nVAR_OUTPUT n : INT; END_VAR\n",
            "n := n + 1;",
        ),
    )
    .unwrap();
    std::fs::write(
        plc.join("MAIN.TcPOU"),
        pou(
            "MAIN",
            "PROGRAM MAIN\nVAR c : FB_Count; k : INT; END_VAR\n",
            "c();\nk := c.n * 2;",
        ),
    )
    .unwrap();
    for input in [
        dir.path().join("Demo.sln"),
        dir.path().join("Demo/Demo.tsproj"),
        plc.join("PLC.plcproj"),
    ] {
        let (trace, stderr) = run_traced(&input, 3, "MAIN.k");
        assert_eq!(
            column(&trace, "MAIN.k"),
            [2.0, 4.0, 6.0],
            "{input:?}: {stderr}"
        );
        assert!(!stderr.contains("error["), "{stderr}");
    }
}

/// `Take(Arr[0])` with `Arr : ARRAY [*] OF REAL` and `Take`'s input ANY is one E1068 at the
/// argument (before: an endless rewrite, the compiler's stack overflowed); copied into a REAL
/// first, the call runs and `A.diSize` is the REAL's 4 bytes.
#[test]
fn an_element_of_a_variable_length_array_given_to_any_is_one_error() {
    let src = "FUNCTION Take : DINT
VAR_INPUT A : ANY; END_VAR
Take := A.diSize;
END_FUNCTION

FUNCTION UseIt : DINT
VAR_IN_OUT Arr : ARRAY[*] OF REAL; END_VAR
UseIt := Take(Arr[0]);
END_FUNCTION

PROGRAM main
VAR xs : ARRAY[0..2] OF REAL; n : DINT; END_VAR
n := UseIt(xs);
END_PROGRAM
";
    let (code, lines) = check_text("any_vla.st", src);
    assert_eq!(code, Some(1));
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with(
            "any_vla.st:8:15: error[E1068]: an element of the `ARRAY [*]` `Arr` given to the ANY input `A` of `Take`"
        ),
        "{lines:?}"
    );
    let fixed = src
        .replace(
            "VAR_IN_OUT Arr : ARRAY[*] OF REAL; END_VAR",
            "VAR_IN_OUT Arr : ARRAY[*] OF REAL; END_VAR\nVAR tmp : REAL; END_VAR",
        )
        .replace(
            "UseIt := Take(Arr[0]);",
            "tmp := Arr[0];\nUseIt := Take(tmp);",
        );
    let (trace, stderr) = run_text("any_vla_fixed.st", &fixed, 1, "main.n");
    assert_eq!(column(&trace, "main.n"), [4.0], "{stderr}");
}

/// A bound and an instance's initial value name constants the POU declares below them: CODESYS
/// and TwinCAT resolve them by name, so does ladderc; a name that is no constant anywhere stays
/// E0022.
#[test]
fn constants_declared_below_their_use_in_a_pou_are_known() {
    let src = "FUNCTION_BLOCK FB_Table
VAR
    table   : ARRAY[0..TABLESIZE - 1] OF UINT;
    delayOn : TON := (PT := DELAY);
    i       : UINT;
    last    : UINT;
END_VAR
VAR CONSTANT
    TABLESIZE : UINT := 4;
    DELAY     : TIME := T#30MS;
END_VAR
FOR i := 0 TO TABLESIZE - 1 DO
    table[i] := i * 10;
END_FOR
last := table[TABLESIZE - 1];
delayOn(IN := TRUE);
END_FUNCTION_BLOCK
PROGRAM main
VAR t : FB_Table; done : BOOL; last : UINT; END_VAR
t();
done := t.delayOn.Q;
last := t.last;
END_PROGRAM
";
    let (trace, stderr) = run_text("const_later.st", src, 5, "main.last,main.done");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "main.last"), [30.0; 5]);
    assert_eq!(column(&trace, "main.done"), [0.0, 0.0, 0.0, 1.0, 1.0]);
    let (code, lines) = check_text(
        "const_none.st",
        &src.replace("TABLESIZE - 1] OF", "TABLESIZ - 1] OF"),
    );
    assert_eq!(code, Some(1));
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("const_none.st:3:24: error[E0022]") && l.contains("`TABLESIZ`")),
        "{lines:?}"
    );
}

/// Forms of CODESYS and TwinCAT programs of round 20, each as those compilers take it.
#[test]
fn codesys_forms_of_round_20_run() {
    let src = "VAR_GLOBAL CONSTANT
    N          : INT := 3;
    CHUNK_END  : DWORD := SHL(1, 4) + SHR(16#8, 3);
END_VAR
TYPE ST_Buttons :
STRUCT
    Start : BIT;
    Back  : BIT;
END_STRUCT;
END_TYPE
FUNCTION_BLOCK FB_Holder
VAR
    target : INT;
    r : REFERENCE TO INT;
    valid_before : BOOL;
END_VAR
VAR_OUTPUT invalid_after : BOOL; END_VAR
r REF= target;
valid_before := __ISVALIDREF(r);
r REF= 0;
invalid_after := valid_before AND NOT __ISVALIDREF(r);
END_FUNCTION_BLOCK
PROGRAM main
VAR
    a : ARRAY[1..N] OF INT := [N(7)];
    d : DWORD;
    b : ST_Buttons;
    n : INT;
    h : FB_Holder;
    ok : BOOL;
    sum : INT;
    bit : INT;
END_VAR
d := CHUNK_END;
b.Start := TRUE;
IF b.Start AND NOT b.Back THEN
    n := n + 1;
END_IF
h();
ok;
ok := h.invalid_after;
sum := a[1] + a[2] + a[3];
bit := sum;
END_PROGRAM
";
    let (trace, stderr) = run_text("forms20.st", src, 2, "main.d,main.n,main.ok,main.sum");
    assert_eq!(column(&trace, "main.d"), [17.0, 17.0], "{stderr}");
    assert_eq!(column(&trace, "main.n"), [1.0, 2.0]);
    assert_eq!(column(&trace, "main.ok"), [1.0, 1.0]);
    assert_eq!(column(&trace, "main.sum"), [21.0, 21.0]);
    let warnings: Vec<&str> = stderr
        .lines()
        .filter(|l| l.contains("warning[W1431]"))
        .collect();
    assert_eq!(warnings.len(), 1, "{stderr}");
    assert!(
        warnings[0].contains("forms20.st:40:1: warning[W1431]: `ok;` has no effect"),
        "{stderr}"
    );

    // a declaration written among the statements stays an error, not a statement "with no effect"
    let (code, lines) = check_text(
        "stray.st",
        "PROGRAM main\nVAR a : INT; END_VAR\na := 1;\nb : MyType;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert!(!lines.iter().any(|l| l.contains("W1431")), "{lines:?}");
    assert!(
        lines.iter().any(|l| l.starts_with("stray.st:4:")),
        "{lines:?}"
    );

    let (code, lines) = check_text(
        "chain.st",
        "PROGRAM main\nVAR\n    fbAlarm : FB_TcAlarm;\nEND_VAR\n\
         fbAlarm.ipArguments.Clear().AddString('Alice');\nfbAlarm.Raise(0);\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("chain.st:3:15: error[E1003]: unknown type `FB_TcAlarm`"),
        "{lines:?}"
    );
}

/// `PRINT('hello');` (a runtime's function ladderc does not have) is one E1019 and nothing more;
/// `TON T1, T#5s` in IL names TON a function block type with the way to call one.
#[test]
fn an_unknown_function_is_one_error_and_a_block_type_is_named_so() {
    let (code, lines) = check_text(
        "print.st",
        "PROGRAM main\nVAR\n  x : INT;\nEND_VAR\n  PRINT('hello');\n  x := x + 1;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("print.st:5:3: error[E1019]: unknown function `PRINT`"),
        "{lines:?}"
    );
    let (code, lines) = check_text(
        "ton.il",
        "PROGRAM main\nVAR\n  run : BOOL;\n  pump : BOOL;\n  T1 : TON;\nEND_VAR\n  LD   run\n  TON  T1, T#5s\n  ST   pump\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    let e: Vec<&String> = lines.iter().filter(|l| l.contains("E1019")).collect();
    assert_eq!(e.len(), 1, "{lines:?}");
    assert!(
        e[0].starts_with(
            "ton.il:8:3: error[E1019]: `TON` is a function block type, not a function"
        ) && e[0].contains("`CAL T1(...)` in IL"),
        "{lines:?}"
    );
    assert!(!lines.iter().any(|l| l.contains("W1001")), "{lines:?}");
}

/// FraBenni/FactoryIO-PLC's test-bed cell (MIT, `tests/corpus/FraBenni_FactoryIO-PLC_FT_con01.*`):
/// its ST export and its Beremiz PLCopen XML give the same trace, cycle by cycle (50 ms scans):
/// the start sensor (active low) starts the conveyor (`%QX0.4` low: on), the end sensor marks the
/// part in transit, and 1 s (TON) later the robot moves forward and the conveyor stops.
#[test]
fn frabenni_test_bed_cell_runs_the_same_from_st_and_xml() {
    let stimulus = "1,%IX0.5,FALSE\n2,%IX0.5,TRUE\n5,%IX0.4,FALSE\n6,%IX0.4,TRUE\n";
    let watch = "%MD1,%MD3,%MD4,%QX0.2,%QX0.4";
    let traces: Vec<String> = ["st", "xml"]
        .iter()
        .map(|ext| {
            let file = common::repo_root().join(format!(
                "tests/corpus/FraBenni_FactoryIO-PLC_FT_con01.{ext}"
            ));
            run_stimulated_files(&[file], &["--cycle-ms", "50"], 28, stimulus, watch).0
        })
        .collect();
    assert_eq!(traces[0], traces[1]);
    let t = &traces[0];
    // the conveyor runs from cycle 1 (C1_working), the part is in transit from cycle 5
    assert_eq!(column(t, "%MD1")[1], 1.0);
    assert_eq!(column(t, "%QX0.4")[..2], [1.0, 0.0]);
    assert_eq!(column(t, "%MD3")[4..6], [0.0, 1.0]);
    // TON 1000 ms from cycle 5 (250 ms): done at cycle 25 (1,250 ms)
    assert_eq!(column(t, "%MD4")[24..26], [0.0, 1.0]);
    assert_eq!(column(t, "%QX0.2")[24..26], [1.0, 0.0]);
    assert_eq!(column(t, "%MD1")[25], 0.0);
    assert_eq!(column(t, "%QX0.4")[25..27], [0.0, 1.0]);
}

/// A FUNCTION written inside a PROGRAM's body is one E0106 naming it, and nothing more of it.
#[test]
fn a_pou_declared_inside_a_body_is_one_error() {
    let (code, lines) = check_text(
        "nested.st",
        "PROGRAM main\nVAR\n    r : INT;\nEND_VAR\n\nFUNCTION Add : INT\nVAR_INPUT\n    a : INT;\n    b : INT;\nEND_VAR\n\
         \x20   Add := a + b;\nEND_FUNCTION\n\n    r := 3;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "nested.st:6:1: error[E0106]: FUNCTION `Add` is declared inside another POU's body"
        ),
        "{lines:?}"
    );
}
