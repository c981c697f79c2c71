//! TwinCAT object-oriented code found in public projects (issue #13, round 29), end to end:
//! - a FUNCTION_BLOCK whose body is SFC and that EXTENDS / IMPLEMENTS another runs its chart with
//!   its base's variables and methods, and is called through its interface (TwinCAT lets any
//!   block extend another whatever its body's language, Infosys "Extending a function block";
//!   before: E0015 "declarations after instructions" at the clause, and in x-PPU a cascade of
//!   E0303/E0108); `SUPER^()` of a chart base is one located E0303;
//! - `ADR` of a METHOD's own VAR kept in another VAR of the method (CODESYS and TwinCAT keep a
//!   method's variables on the stack for the call; before: E0305), W1444 when the pointer is
//!   stored into the instance;
//! - a method's VAR given to the ANY inputs of another method of the block (TcUnit-style
//!   `AssertEquals(expected, result)`; Infosys "ANY and ANY_<type>": the argument is passed as a
//!   pointer for the call; before: E0305);
//! - a global `ARRAY OF` an interface initialised with instances in a GVL, from another list, from
//!   the same list, with `0` elements (Infosys "Interface"; before: E0336).

mod common;
use common::{column, run_stimulated, run_stimulated_files, write_in};

/// A TwinCAT `.TcPOU` holding function block `FB_Seq` (`header` its first line) whose body is the
/// chart Idle (initial) -> `bGo` -> Run (action `aCount`, N) -> `NOT bGo` -> back to Idle, with
/// method `Count` (the runs counted so far).
fn sfc_block(header: &str) -> String {
    let attr = |guid: &str, value: &str| {
        format!(
            "<o><v n=\"AttributeId\">{{{guid}}}</v><o n=\"Value\" t=\"StringValue\"><v n=\"Value\">\"{value}\"</v><v n=\"DefaultValue\">\"\"</v></o></o>"
        )
    };
    let initial = |v: bool| {
        format!(
            "<o><v n=\"AttributeId\">{{6844a48e-46c2-4cc8-a185-a478f3b99cc0}}</v><o n=\"Value\" t=\"BoolValue\"><v n=\"Value\">\"{}\"</v><v n=\"DefaultValue\">\"FALSE\"</v></o></o>",
            if v { "TRUE" } else { "FALSE" }
        )
    };
    let name = "38391c6d-6d4a-42f8-8ee7-9f45e5adafa8";
    let step = |n: &str, init: bool, action: Option<&str>| {
        let assoc = action.map_or("<l2 n=\"InnerList\" />".to_string(), |a| {
            format!(
                "<l2 n=\"InnerList\" cet=\"SFCActionAssociation\"><o><l2 n=\"Attributes\" cet=\"SFCAttribute\">{}{}</l2></o></l2>",
                attr(name, a),
                attr("e174fc0d-80b0-4a9e-a530-ca239c249a50", "N")
            )
        });
        format!(
            "<o t=\"SFCStep\"><n n=\"EmbeddedMainAction\" /><n n=\"EmbeddedEntryAction\" /><n n=\"EmbeddedExitAction\" /><o n=\"ElementList\" t=\"SFCElementList\">{assoc}</o><l2 n=\"Attributes\" cet=\"SFCAttribute\">{}{}</l2></o>",
            attr(name, n),
            initial(init)
        )
    };
    let transition = |c: &str| {
        format!(
            "<o t=\"SFCTransition\"><n n=\"EmbeddedTransition\" /><l2 n=\"Attributes\" cet=\"SFCAttribute\">{}</l2></o>",
            attr(name, c)
        )
    };
    let jump = format!(
        "<o t=\"SFCJump\"><l2 n=\"Attributes\" cet=\"SFCAttribute\">{}</l2></o>",
        attr(name, "Idle")
    );
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  <POU Name=\"FB_Seq\" Id=\"{{00000000-0000-4000-8000-000000000001}}\" SpecialFunc=\"None\">\n    <Declaration><![CDATA[{header}\nVAR_INPUT\n\tbGo : BOOL;\nEND_VAR\nVAR_OUTPUT\n\tnRun : INT;\nEND_VAR\n]]></Declaration>\n    <Implementation>\n      <SFC><XmlArchive><Data><o xml:space=\"preserve\" t=\"SFCImplementationObject\"><o n=\"Root\" t=\"SFCSegment\"><o n=\"ElementList\" t=\"SFCElementList\"><l2 n=\"InnerList\">{}{}{}{}{}</l2></o></o></o></Data></XmlArchive></SFC>\n    </Implementation>\n    <Action Name=\"aCount\" Id=\"{{00000000-0000-4000-8000-000000000002}}\">\n      <Implementation>\n        <ST><![CDATA[nRun := nRun + 1;\nnBase := nBase + 10;]]></ST>\n      </Implementation>\n    </Action>\n    <Method Name=\"Count\" Id=\"{{00000000-0000-4000-8000-000000000003}}\">\n      <Declaration><![CDATA[METHOD Count : INT\n]]></Declaration>\n      <Implementation>\n        <ST><![CDATA[Count := nRun + Offset();]]></ST>\n      </Implementation>\n    </Method>\n  </POU>\n</TcPlcObject>\n",
        step("Idle", true, None),
        transition("bGo"),
        step("Run", false, Some("aCount")),
        transition("NOT bGo"),
        jump
    )
}

/// The base (ST) of `FB_Seq`: a variable the chart's action writes and a method the chart's
/// method calls; the interface `FB_Seq` implements; a program calling the block and its method
/// through the interface.
const BASE_AND_MAIN: &str = "INTERFACE I_Count\nMETHOD Count : INT\nEND_METHOD\nEND_INTERFACE\n\n\
FUNCTION_BLOCK FB_Base\nVAR\n  nBase : INT;\nEND_VAR\nMETHOD Offset : INT\nOffset := 1000;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\n\
PROGRAM MAIN\nVAR\n  go : BOOL;\n  seq : FB_Seq;\n  itf : I_Count;\n  n, base, counted : INT;\nEND_VAR\n\
seq(bGo := go);\nn := seq.nRun;\nbase := seq.nBase;\nitf := seq;\ncounted := itf.Count();\nEND_PROGRAM\n\n\
CONFIGURATION C\nRESOURCE R ON PLC\nTASK T(INTERVAL := T#10ms, PRIORITY := 1);\nPROGRAM P WITH T : MAIN;\nEND_RESOURCE\nEND_CONFIGURATION\n";

/// `FUNCTION_BLOCK FB_Seq EXTENDS FB_Base IMPLEMENTS I_Count` with an SFC body (a TwinCAT
/// `.TcPOU`, x-PPU's `ControlPrimitiveBase` / `LinearSequence` form): the chart runs, its action
/// writes the base's `nBase`, its method calls the base's method `Offset`, and the block is
/// called through the interface. `go` rises at scan 2 and falls at scan 5; the chart runs in
/// TwinCAT's processing order (round 34: the actions first, the transition check last, Beckhoff
/// infosys "Processing Order in SFC"): Run becomes active at the end of scan 2 (its N action runs
/// from scan 3) and is left at the end of scan 5 (N runs once more in scan 6, its final scan), so
/// `nRun` counts 1, 2, 3, 4 in scans 3..6 then stays 4 (before: in scans 2..5). Before: two E0015 "declarations after instructions" at the
/// clause, nothing compiled.
#[test]
fn a_chart_block_that_extends_and_implements_runs_with_its_base() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "FB_Seq.TcPOU",
        &sfc_block("FUNCTION_BLOCK FB_Seq EXTENDS FB_Base IMPLEMENTS I_Count"),
    );
    write_in(dir.path(), "main.st", BASE_AND_MAIN);
    let (trace, _) = run_stimulated_files(
        &[dir.path().join("FB_Seq.TcPOU"), dir.path().join("main.st")],
        &["--cycle-ms", "10"],
        9,
        "2,P.go,1\n5,P.go,0\n",
        "P.n,P.base,P.counted",
    );
    let n = column(&trace, "P.n");
    // TwinCAT's processing order (round 34): the count from the scan after `go`'s
    assert_eq!(n, [0., 0., 0., 1., 2., 3., 4., 4., 4.], "{trace}");
    let base: Vec<f64> = n.iter().map(|v| v * 10.).collect();
    assert_eq!(column(&trace, "P.base"), base);
    let counted: Vec<f64> = n.iter().map(|v| v + 1000.).collect();
    assert_eq!(column(&trace, "P.counted"), counted);
}

/// `SUPER^()` in a block that extends a chart block (itself derived from `FB_Base`) runs one scan
/// of the base's chart per call (Beckhoff Infosys "SUPER": `SUPER^()` calls the base's body;
/// round 31): `FB_Child`, whose body is `SUPER^(); k := k + 1;`, counts as `FB_Seq` itself does,
/// its chart's action writing the inherited `nBase`, and the child's own body runs every scan.
/// Before round 31: one E0303 "SUPER^() runs the body of `FB_Seq`, which is SFC: not supported"
/// (and before round 29 x-PPU got 15 E0303 calling its body "instruction list" plus 15 E0108).
#[test]
fn super_call_of_a_chart_base_runs_its_chart() {
    let child = "FUNCTION_BLOCK FB_Child EXTENDS FB_Seq\nVAR_OUTPUT\n  k : INT;\nEND_VAR\nSUPER^();\nk := k + 1;\nEND_FUNCTION_BLOCK\n";
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "FB_Seq.TcPOU",
        &sfc_block("FUNCTION_BLOCK FB_Seq EXTENDS FB_Base IMPLEMENTS I_Count"),
    );
    write_in(
        dir.path(),
        "main.st",
        &BASE_AND_MAIN
            .replace("seq : FB_Seq", "seq : FB_Child;\n  steps : INT")
            .replace("n := seq.nRun;", "n := seq.nRun;\nsteps := seq.k;"),
    );
    write_in(dir.path(), "child.st", child);
    let (trace, _) = run_stimulated_files(
        &[
            dir.path().join("FB_Seq.TcPOU"),
            dir.path().join("main.st"),
            dir.path().join("child.st"),
        ],
        &["--cycle-ms", "10"],
        9,
        "2,P.go,1\n5,P.go,0\n",
        "P.n,P.base,P.steps",
    );
    let n = column(&trace, "P.n");
    // TwinCAT's processing order (round 34): the count from the scan after `go`'s
    assert_eq!(n, [0., 0., 0., 1., 2., 3., 4., 4., 4.], "{trace}");
    let base: Vec<f64> = n.iter().map(|v| v * 10.).collect();
    assert_eq!(column(&trace, "P.base"), base);
    assert_eq!(
        column(&trace, "P.steps"),
        [1., 2., 3., 4., 5., 6., 7., 8., 9.]
    );
}

/// `ADR` of a METHOD's own VAR (an array) kept in a pointer that is another VAR of the method, and
/// read through it (rozicdejan/TC3-mqtt-example's `pBaseAddr := ADR(sPayloadPub)`): the method's
/// variables live for its call as a FUNCTION's do (CODESYS and TwinCAT keep both on the stack).
/// The same for a program's VAR_TEMP. Before: E0305 "a VAR_TEMP variable lives for one call".
#[test]
fn address_of_a_method_variable_kept_in_the_method_runs() {
    let src = "FUNCTION_BLOCK FB_Buf\nVAR_INPUT\n  k : BYTE;\nEND_VAR\n\
METHOD Fill : INT\nVAR\n  aBytes : ARRAY[0..3] OF BYTE := [1, 2, 3, 4];\n  pByte : POINTER TO BYTE;\n  i : INT;\nEND_VAR\n\
aBytes[3] := k;\npByte := ADR(aBytes);\nFOR i := 0 TO 3 DO\n  Fill := Fill * 10 + pByte^;\n  pByte := pByte + 1;\nEND_FOR\nEND_METHOD\nEND_FUNCTION_BLOCK\n\n\
PROGRAM Main\nVAR\n  b : FB_Buf;\n  n, m : INT;\n  k : BYTE;\nEND_VAR\nVAR_TEMP\n  t : INT;\n  pt : POINTER TO INT;\nEND_VAR\n\
b.k := k;\nn := b.Fill();\nt := n + 1;\npt := ADR(t);\nm := pt^;\nEND_PROGRAM\n\n\
CONFIGURATION C\nRESOURCE R ON PLC\nTASK T(INTERVAL := T#10ms, PRIORITY := 1);\nPROGRAM P WITH T : Main;\nEND_RESOURCE\nEND_CONFIGURATION\n";
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "adr.st", src);
    let (trace, stderr) = run_stimulated(&dir.path().join("adr.st"), 4, "2,P.k,7\n", "P.n,P.m");
    assert!(!stderr.contains("W1444"), "{stderr}");
    assert_eq!(column(&trace, "P.n"), [1230., 1230., 1237., 1237.]);
    assert_eq!(column(&trace, "P.m"), [1231., 1231., 1238., 1238.]);
}

/// The address of a method's variable stored into a variable of the instance outlives the call:
/// W1444 at the target, naming the variable as written and the block; `REF` of it stays E0305
/// (IEC 61131-3 ed. 3, 6.4.4.10).
#[test]
fn address_of_a_method_variable_kept_in_the_instance_is_w1444() {
    let src = "FUNCTION_BLOCK FB_Buf\nVAR\n  pKeep : POINTER TO INT;\n  rKeep : REF_TO INT;\nEND_VAR\n\
METHOD Keep : BOOL\nVAR\n  n : INT;\nEND_VAR\npKeep := ADR(n);\nrKeep := REF(n);\nEND_METHOD\nEND_FUNCTION_BLOCK\n";
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "keep.st", src);
    let (code, _, stderr) = common::in_dir(dir.path(), &["check", "keep.st"]);
    assert_eq!(code, Some(1), "{stderr}");
    let heads: Vec<&str> = stderr
        .lines()
        .filter(|l| l.contains("error[") || l.contains("warning["))
        .map(|l| l.split(" (hint:").next().unwrap_or(l))
        .collect();
    assert_eq!(
        heads,
        [
            "keep.st:10:1: warning[W1444]: `pKeep` keeps the address of a VAR_TEMP (or a method's variable) of `FB_Buf`, which lives for one call",
            "keep.st:11:10: error[E0305]: a reference to `N` is not allowed: a VAR_TEMP variable lives for one call (IEC 61131-3, 6.4.4.10)",
        ]
    );
}

/// A method's VAR given to the ANY inputs of another method of the block (TcUnit-style assert,
/// Beckhoff-USA-Community/TwinCAT_AzureDevOps's `AssertEquals(testExpected, testResult, ...)`):
/// the argument's address is passed for the call only, so it may live for the call. `Same`
/// compares sizes and every byte; scan by scan with `x`, `y` stimulated. Before: E0305 at each
/// argument.
#[test]
fn method_variables_given_to_a_method_s_any_inputs_run() {
    let src = "FUNCTION_BLOCK FB_Test\nVAR_OUTPUT\n  bOk : BOOL;\n  nSize : DINT;\nEND_VAR\n\
METHOD PROTECTED Same : BOOL\nVAR_INPUT\n  a : ANY;\n  b : ANY;\nEND_VAR\nVAR\n  i : DINT;\nEND_VAR\n\
nSize := a.diSize;\nSame := a.diSize = b.diSize;\nIF Same THEN\n  FOR i := 0 TO a.diSize - 1 DO\n    IF a.pValue[i] <> b.pValue[i] THEN\n      Same := FALSE;\n    END_IF\n  END_FOR\nEND_IF\nEND_METHOD\n\
METHOD Run : BOOL\nVAR_INPUT\n  x, y : DINT;\nEND_VAR\nVAR\n  exp : DINT;\n  res : DINT;\nEND_VAR\nVAR_TEMP\n  t : DINT;\nEND_VAR\n\
exp := x;\nres := y;\nt := y;\nbOk := Same(exp, res) AND Same(res, t);\nRun := bOk;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\n\
PROGRAM Main\nVAR\n  t : FB_Test;\n  ok : BOOL;\n  x, y : DINT;\n  size : DINT;\nEND_VAR\nok := t.Run(x := x, y := y);\nsize := t.nSize;\nEND_PROGRAM\n\n\
CONFIGURATION C\nRESOURCE R ON PLC\nTASK T(INTERVAL := T#10ms, PRIORITY := 1);\nPROGRAM P WITH T : Main;\nEND_RESOURCE\nEND_CONFIGURATION\n";
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "any.st", src);
    let (trace, _) = run_stimulated(
        &dir.path().join("any.st"),
        5,
        "1,P.x,70000\n2,P.y,70000\n3,P.y,70256\n4,P.x,70256\n",
        "P.ok,P.size",
    );
    assert_eq!(column(&trace, "P.ok"), [1., 0., 1., 0., 1.]);
    assert_eq!(column(&trace, "P.size"), [4., 4., 4., 4., 4.]);
}

/// A TwinCAT object file.
fn tc(kind: &str, name: &str, id: u32, declaration: &str, body: Option<&str>) -> String {
    let body = body.map_or(String::new(), |b| {
        format!("    <Implementation>\n      <ST><![CDATA[{b}]]></ST>\n    </Implementation>\n")
    });
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  <{kind} Name=\"{name}\" Id=\"{{00000000-0000-4000-8000-{id:012}}}\">\n    <Declaration><![CDATA[{declaration}]]></Declaration>\n{body}  </{kind}>\n</TcPlcObject>\n"
    )
}

/// Global interface variables initialised with instances in GVLs (RafalRjm/Maszyna's
/// `GVL_LogowanieBledow`): an `ARRAY OF I_Log` from nested instances of another list, a plain
/// `I_Log` from an instance of the same list, an array with a `0` element (unassigned). They are
/// assigned once before the first cycle: MAIN reads 11, 22 and 33 from scan 0. Before: E0336 for
/// each, "only `:= 0` or `:= instance` of a POU's own variable".
#[test]
fn global_interface_variables_start_with_their_instances() {
    let dir = tempfile::tempdir().unwrap();
    let files = [
        (
            "I_Log.TcIO",
            tc("Itf", "I_Log", 1, "INTERFACE I_Log\n", None).replace(
                "  </Itf>",
                "    <Method Name=\"Code\" Id=\"{00000000-0000-4000-8000-000000000002}\">\n      <Declaration><![CDATA[METHOD Code : INT\n]]></Declaration>\n    </Method>\n  </Itf>",
            ),
        ),
        (
            "FB_Part.TcPOU",
            tc("POU", "FB_Part", 3, "FUNCTION_BLOCK FB_Part IMPLEMENTS I_Log\nVAR_INPUT\n\tnCode : INT;\nEND_VAR\n", Some("")).replace(
                "  </POU>",
                "    <Method Name=\"Code\" Id=\"{00000000-0000-4000-8000-000000000004}\">\n      <Declaration><![CDATA[METHOD Code : INT\n]]></Declaration>\n      <Implementation>\n        <ST><![CDATA[Code := nCode;]]></ST>\n      </Implementation>\n    </Method>\n  </POU>",
            ),
        ),
        (
            "FB_Cyl.TcPOU",
            tc("POU", "FB_Cyl", 5, "FUNCTION_BLOCK FB_Cyl\nVAR\n\tfbLog : FB_Part;\nEND_VAR\n", Some("")),
        ),
        (
            "GVL_Dev.TcGVL",
            tc("GVL", "GVL_Dev", 6, "{attribute 'qualified_only'}\nVAR_GLOBAL\n\tfbCyl1 : FB_Cyl;\n\tfbCyl2 : FB_Cyl;\nEND_VAR\n", None),
        ),
        (
            "GVL_Log.TcGVL",
            tc("GVL", "GVL_Log", 7, "{attribute 'qualified_only'}\nVAR_GLOBAL\n\taItf : ARRAY[1..2] OF I_Log := [GVL_Dev.fbCyl1.fbLog, GVL_Dev.fbCyl2.fbLog];\n\tfbP : FB_Part := (nCode := 33);\n\titfP : I_Log := fbP;\n\taMixed : ARRAY[0..1] OF I_Log := [0, fbP];\nEND_VAR\n", None),
        ),
        (
            "MAIN.TcPOU",
            tc("POU", "MAIN", 8, "PROGRAM MAIN\nVAR\n\tn1, n2, n3, n4 : INT;\n\tbEmpty : BOOL;\nEND_VAR\n", Some("IF GVL_Dev.fbCyl1.fbLog.nCode = 0 THEN\n\tGVL_Dev.fbCyl1.fbLog.nCode := 11;\n\tGVL_Dev.fbCyl2.fbLog.nCode := 22;\nEND_IF\nn1 := GVL_Log.aItf[1].Code();\nn2 := GVL_Log.aItf[2].Code();\nn3 := GVL_Log.itfP.Code();\nn4 := GVL_Log.aMixed[1].Code();\nbEmpty := GVL_Log.aMixed[0] = 0;")),
        ),
    ];
    for (name, text) in &files {
        write_in(dir.path(), name, text);
    }
    let paths: Vec<_> = files.iter().map(|(n, _)| dir.path().join(n)).collect();
    let (trace, stderr) = run_stimulated_files(
        &paths,
        &["--cycle-ms", "10"],
        3,
        "",
        "MAIN.n1,MAIN.n2,MAIN.n3,MAIN.n4,MAIN.bEmpty",
    );
    assert!(!stderr.contains("E0336"), "{stderr}");
    assert_eq!(column(&trace, "MAIN.n1"), [11., 11., 11.]);
    assert_eq!(column(&trace, "MAIN.n2"), [22., 22., 22.]);
    assert_eq!(column(&trace, "MAIN.n3"), [33., 33., 33.]);
    assert_eq!(column(&trace, "MAIN.n4"), [33., 33., 33.]);
    assert_eq!(column(&trace, "MAIN.bEmpty"), [1., 1., 1.]);
}
