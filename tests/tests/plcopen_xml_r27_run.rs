//! Round 27 of unseen projects (issue #13), PLCopen XML: what CODESYS V3 exports need, run end to
//! end through `ladderc run`:
//! - a box output written as `<connectionPointOut><expression>state</expression>` (CODESYS V3.5 LD:
//!   the output assigned to a variable; PLCopen TC6: `connectionPointOut` holds an optional
//!   `expression`) writes that variable, as an `<outVariable>` would (before: dropped silently, exit
//!   0); the same for an input written as `<connectionPointIn><expression>n</expression>` (TC6:
//!   either wires or one expression), on a box pin or on an element's own input (before: the
//!   input read as unwired); an expression beside a wire, or on a power rail, is W1449 (not read);
//! - a member of a global list given as a text file (`Glob.st`, `Glob.a`) into a box input of an
//!   LD/FBD body (before: E1001 `Glob` at the box, the list known only to direct connections).
//! - a CODESYS UNION in the project's vendor data (`.../plcopenxml/union`) is a type (before: E3009).
//! - `REFERENCE TO Lib.T` in XML is E3009 naming the missing `Lib.T` (before: E3012 "not supported").
//! - elements of another schema in a graphical body (`<rung>`) are one E3012 with their count, a
//!   reused localId one E3014 with its number of uses (before: one error per element, per repeat).
//! - a CODESYS V2.3 `.EXP` export gets no W0302 language note (before: one per file).
//! - IL `CAL f(...)` of a user FUNCTION runs (before: E2005 from the C backend); `CALC f` of a
//!   function is a front-end E1018 (before: E2005).

mod common;
use common::{column, run_stimulated_files, run_traced_files};

/// A PLCopen XML project of one program `Prg` (instance `P`, 10 ms task) with `vars` (the
/// `<localVars>` variables) and `body` (the children of its `<body>`), CODESYS V3.5 style.
fn project(vars: &str, body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP20" creationDateTime="2026-01-01T00:00:00" />
  <contentHeader name="t.project"><coordinateInfo><fbd><scaling x="1" y="1" /></fbd><ld><scaling x="1" y="1" /></ld><sfc><scaling x="1" y="1" /></sfc></coordinateInfo></contentHeader>
  <types><dataTypes /><pous>
    <pou name="Prg" pouType="program">
      <interface><localVars>{vars}</localVars></interface>
      <body>{body}</body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="C"><resource name="R"><task name="T" interval="PT0.01S" priority="1"><pouInstance name="P" typeName="Prg" /></task></resource></configuration></configurations></instances>
</project>
"#
    )
}

/// Writes `files` (name, text) to a temporary folder and runs them together with `stimulus`.
fn run_files(files: &[(&str, &str)], cycles: u32, stimulus: &str, watch: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let paths: Vec<std::path::PathBuf> = files
        .iter()
        .map(|(name, text)| {
            let p = dir.path().join(name);
            std::fs::write(&p, text).unwrap();
            p
        })
        .collect();
    run_stimulated_files(&paths, &["--cycle-ms", "10"], cycles, stimulus, watch).0
}

/// CODESYS V3.5 LD: a contact on `btn` enables a MOVE of 3 whose OUT is assigned to `state`
/// through the output point's `<expression>`, and its ENO a second MOVE of a string into `txt`.
/// Both are written once `btn` is TRUE (before: both outputs were dropped, `state` stayed 0).
#[test]
fn a_box_output_point_expression_writes_its_variable() {
    let vars = r#"<variable name="btn"><type><BOOL /></type></variable>
        <variable name="state"><type><SINT /></type></variable>
        <variable name="txt"><type><string length="20" /></type></variable>"#;
    let body = r#"<LD>
        <leftPowerRail localId="0"><position x="0" y="0" /><connectionPointOut formalParameter="none" /></leftPowerRail>
        <contact localId="5" negated="false" storage="none" edge="none"><position x="0" y="0" /><connectionPointIn><connection refLocalId="0" /></connectionPointIn><connectionPointOut /><variable>btn</variable></contact>
        <inVariable localId="6"><position x="0" y="0" /><connectionPointOut /><expression>3</expression></inVariable>
        <block localId="4" typeName="MOVE"><position x="0" y="0" />
          <inputVariables>
            <variable formalParameter="EN"><connectionPointIn><connection refLocalId="5" /></connectionPointIn></variable>
            <variable formalParameter="IN"><connectionPointIn><connection refLocalId="6" /></connectionPointIn></variable>
          </inputVariables><inOutVariables />
          <outputVariables>
            <variable formalParameter="ENO"><connectionPointOut /></variable>
            <variable formalParameter="OUT"><connectionPointOut><expression>state</expression></connectionPointOut></variable>
          </outputVariables>
        </block>
        <inVariable localId="7"><position x="0" y="0" /><connectionPointOut /><expression>'Stopped'</expression></inVariable>
        <block localId="3" typeName="MOVE"><position x="0" y="0" />
          <inputVariables>
            <variable formalParameter="EN"><connectionPointIn><connection refLocalId="4" formalParameter="ENO" /></connectionPointIn></variable>
            <variable formalParameter="IN"><connectionPointIn><connection refLocalId="7" /></connectionPointIn></variable>
          </inputVariables><inOutVariables />
          <outputVariables>
            <variable formalParameter="ENO"><connectionPointOut /></variable>
            <variable formalParameter="OUT"><connectionPointOut><expression>txt</expression></connectionPointOut></variable>
          </outputVariables>
        </block>
      </LD>"#;
    let trace = run_files(
        &[("ld.xml", &project(vars, body))],
        4,
        "2,P.btn,1\n",
        "P.state,P.txt",
    );
    assert_eq!(column(&trace, "P.state"), [0.0, 0.0, 3.0, 3.0], "{trace}");
    let rows: Vec<&str> = trace.lines().collect();
    assert!(rows[2].ends_with(",\"\""), "{trace}");
    assert!(rows[3].ends_with(",\"Stopped\""), "{trace}");
}

/// FBD with every pin written as an expression: `n := n + 2` by an ADD box whose inputs and output
/// are `<expression>`s, a GT of the expression `n * 10` against 35 into `big`, and an
/// `<outVariable>` whose own input is the expression `n + 100` (before: the inputs were read as
/// unwired, E-less: the ADD of nothing).
#[test]
fn input_point_expressions_are_read_into_their_pins() {
    let vars = r#"<variable name="n"><type><INT /></type></variable>
        <variable name="m"><type><INT /></type></variable>
        <variable name="big"><type><BOOL /></type></variable>"#;
    let body = r#"<FBD>
        <block localId="1" typeName="ADD"><position x="0" y="0" />
          <inputVariables>
            <variable formalParameter="IN1"><connectionPointIn><expression>n</expression></connectionPointIn></variable>
            <variable formalParameter="IN2"><connectionPointIn><expression>2</expression></connectionPointIn></variable>
          </inputVariables><inOutVariables />
          <outputVariables>
            <variable formalParameter="OUT"><connectionPointOut><expression>n</expression></connectionPointOut></variable>
          </outputVariables>
        </block>
        <block localId="2" typeName="GT"><position x="0" y="100" />
          <inputVariables>
            <variable formalParameter="IN1"><connectionPointIn><expression>n * 10</expression></connectionPointIn></variable>
            <variable formalParameter="IN2"><connectionPointIn><expression>35</expression></connectionPointIn></variable>
          </inputVariables><inOutVariables />
          <outputVariables>
            <variable formalParameter="OUT"><connectionPointOut><expression>big</expression></connectionPointOut></variable>
          </outputVariables>
        </block>
        <outVariable localId="3"><position x="0" y="200" /><connectionPointIn><expression>n + 100</expression></connectionPointIn><expression>m</expression></outVariable>
      </FBD>"#;
    let trace = run_files(&[("fbd.xml", &project(vars, body))], 3, "", "P.n,P.m,P.big");
    assert_eq!(column(&trace, "P.n"), [2.0, 4.0, 6.0], "{trace}");
    assert_eq!(column(&trace, "P.m"), [102.0, 104.0, 106.0], "{trace}");
    assert_eq!(column(&trace, "P.big"), [0.0, 1.0, 1.0], "{trace}");
}

/// A CODESYS global list exported as the text file `Glob.st` (only `VAR_GLOBAL`, `qualified_only`)
/// and an FBD body that moves `Glob.a` through a MOVE box into `c`, and `Glob.a * 2.0` through an
/// ADD's input into `d`: both run (before: E1001 `Glob` at the box).
#[test]
fn a_text_global_list_member_feeds_a_box_input() {
    let gvl = "{attribute 'qualified_only'}\nVAR_GLOBAL\n  a : REAL := 2.5;\nEND_VAR\n";
    let vars = r#"<variable name="c"><type><REAL /></type></variable>
        <variable name="d"><type><REAL /></type></variable>"#;
    let body = r#"<FBD>
        <inVariable localId="1"><position x="0" y="0" /><connectionPointOut /><expression>Glob.a</expression></inVariable>
        <block localId="2" typeName="MOVE"><position x="0" y="0" />
          <inputVariables><variable formalParameter="IN"><connectionPointIn><connection refLocalId="1" /></connectionPointIn></variable></inputVariables>
          <inOutVariables />
          <outputVariables><variable formalParameter="OUT"><connectionPointOut /></variable></outputVariables>
        </block>
        <outVariable localId="3"><position x="0" y="0" /><connectionPointIn><connection refLocalId="2" formalParameter="OUT" /></connectionPointIn><expression>c</expression></outVariable>
        <block localId="4" typeName="ADD"><position x="0" y="50" />
          <inputVariables>
            <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="1" /></connectionPointIn></variable>
            <variable formalParameter="IN2"><connectionPointIn><expression>Glob.a</expression></connectionPointIn></variable>
          </inputVariables><inOutVariables />
          <outputVariables><variable formalParameter="OUT"><connectionPointOut><expression>d</expression></connectionPointOut></variable></outputVariables>
        </block>
      </FBD>"#;
    let dir = tempfile::tempdir().unwrap();
    let g = dir.path().join("Glob.st");
    let x = dir.path().join("prg.xml");
    std::fs::write(&g, gvl).unwrap();
    std::fs::write(&x, project(vars, body)).unwrap();
    let (trace, _) = run_traced_files(&[&g, &x], 1, "P.c,P.d");
    assert_eq!(column(&trace, "P.c"), [2.5], "{trace}");
    assert_eq!(column(&trace, "P.d"), [5.0], "{trace}");
}

/// A CODESYS V3 UNION exported in the project's vendor data (`.../plcopenxml/union`): a DWORD
/// overlaid by two WORDs; the high word of 16#12345678 is 16#1234, as the same type in ST gives
/// (before: E3009 `U_Bits` is not defined, and W3002 for the block).
#[test]
fn a_union_in_the_project_vendor_data_is_a_type() {
    let vars = r#"<variable name="bits"><type><derived name="U_Bits" /></type></variable>
        <variable name="hi"><type><WORD /></type></variable>"#;
    let body = r#"<ST><xhtml xmlns="http://www.w3.org/1999/xhtml">bits.d := 16#12345678;
hi := bits.w[1];</xhtml></ST>"#;
    let union = r#"<addData>
    <data name="http://www.3s-software.com/plcopenxml/union" handleUnknown="implementation">
      <union name="U_Bits">
        <variable name="d"><type><DWORD /></type></variable>
        <variable name="w"><type><array><dimension lower="0" upper="1" /><baseType><WORD /></baseType></array></type></variable>
      </union>
    </data>
  </addData>
</project>"#;
    let xml = project(vars, body).replace("</project>", union);
    let dir = tempfile::tempdir().unwrap();
    let x = dir.path().join("u.xml");
    std::fs::write(&x, xml).unwrap();
    let (trace, stderr) = run_traced_files(&[&x], 1, "P.hi");
    assert_eq!(column(&trace, "P.hi"), [4660.0], "{trace}");
    assert!(!stderr.contains("W3002"), "{stderr}");
}

/// `REFERENCE TO LibMotion.AXIS_GROUP_REF` (CODESYS writes a reference to a library's type so) names
/// one type: the missing library type is the one error, by its name (before: E3012 "a reference or
/// pointer names one type").
#[test]
fn a_reference_to_a_library_type_names_the_missing_type() {
    let vars = r#"<variable name="grp"><type><derived name="REFERENCE TO LibMotion.AXIS_GROUP_REF" /></type></variable>
        <variable name="n"><type><INT /></type></variable>"#;
    let body = r#"<ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := 1;</xhtml></ST>"#;
    let (code, lines) = common::check_text("r.xml", &project(vars, body));
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].contains("error[E3009]: type `LibMotion.AXIS_GROUP_REF` is not defined"),
        "{lines:?}"
    );
}

/// A file in another schema (`<rung>` elements in an LD body: PLCopen TC6 LD has none) is one E3012
/// with the count, and a right rail whose localId every rung repeats is one E3014 with the number
/// of uses (before: one error per rung, per repeat).
#[test]
fn foreign_elements_and_a_reused_local_id_are_one_error_each() {
    let vars = r#"<variable name="a"><type><BOOL /></type></variable>
        <variable name="q"><type><BOOL /></type></variable>"#;
    let rungs: String = (0..5)
        .map(|k| format!(r#"<rung id="{k}"><contact variable="a"/><coil variable="q"/></rung>"#))
        .collect();
    let rails: String = (0..4)
        .map(|_| r#"<rightPowerRail localId="2147483646"><position x="0" y="0" /><connectionPointIn /></rightPowerRail>"#)
        .collect();
    let body = format!("<LD>{rungs}{rails}</LD>");
    let (code, lines) = common::check_text("rungs.xml", &project(vars, &body));
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 2, "{lines:?}");
    assert!(
        errors[0].contains(
            "error[E3012]: element <rung> is not supported in a graphical body (5 elements)"
        ),
        "{lines:?}"
    );
    assert!(
        errors[1].contains("error[E3014]: localId 2147483646 is used 4 times"),
        "{lines:?}"
    );
}

/// A CODESYS V2.3 text export (`.EXP`, a documented input) runs without the W0302 note "read as
/// Structured Text ... name the file .il, .st or .xml" (before: one note per `.EXP` file, 45 on one
/// project).
#[test]
fn a_codesys_v23_export_gets_no_language_note() {
    let dir = tempfile::tempdir().unwrap();
    common::write_in(
        dir.path(),
        "PLC_PRG.EXP",
        "(* @NESTEDCOMMENTS := 'Yes' *)\n(* @PATH := '' *)\n(* @OBJECTFLAGS := '0, 8' *)\n\
         (* @SYMFILEFLAGS := '2048' *)\nPROGRAM PLC_PRG\nVAR\n\tn : INT;\nEND_VAR\n\
         (* @END_DECLARATION := '0' *)\nn := n + 1;\nEND_PROGRAM\n",
    );
    let (code, trace, stderr) = common::in_dir(
        dir.path(),
        &[
            "run",
            "PLC_PRG.EXP",
            "--cycles",
            "2",
            "--trace",
            "-",
            "--watch",
            "PLC_PRG.n",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&trace, "PLC_PRG.n"), [1.0, 2.0], "{trace}");
    assert!(!stderr.contains("W0302"), "{stderr}");
}

/// IL `CAL Twice(v := n)` of a user FUNCTION runs as the function call it is (IEC 61131-3 draft
/// Annex F; ladderc already ran `CAL SPLIT_TOD(...)`): its result is the current result, `r` = 6
/// (before: E2005 "the C backend cannot resolve `Twice`"). A conditional `CALC` of a function is
/// a front-end E1018 at the name, alone (before: E2005).
#[test]
fn cal_of_a_user_function_runs_and_calc_of_one_is_a_front_end_error() {
    let il = "FUNCTION Twice : INT\nVAR_INPUT v : INT; END_VAR\nLD v\nMUL 2\nST Twice\nEND_FUNCTION\n\n\
              PROGRAM main\nVAR n : INT := 3; r : INT; END_VAR\nCAL Twice(v := n)\nST r\nEND_PROGRAM\n";
    let (trace, _) = common::run_text("cal.il", il, 1, "main.r");
    assert_eq!(column(&trace, "main.r"), [6.0], "{trace}");
    let calc = il.replace("CAL Twice", "LD TRUE\nCALC Twice");
    let (code, lines) = common::check_text("calc.il", &calc);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("calc.il:11:6: error[E1018]: `Twice` is a function: a conditional CAL (CALC, CALCN) calls a function block instance"),
        "{lines:?}"
    );
}

/// An expression on a point that also has a wire (TC6: either, not both) is W1449 at the
/// expression and the wire is what the pin reads; the run goes on.
#[test]
fn an_expression_beside_a_wire_is_a_warning() {
    let vars = r#"<variable name="n"><type><INT /></type></variable>
        <variable name="m"><type><INT /></type></variable>"#;
    let body = r#"<FBD>
        <inVariable localId="1"><position x="0" y="0" /><connectionPointOut /><expression>7</expression></inVariable>
        <block localId="2" typeName="MOVE"><position x="0" y="0" />
          <inputVariables><variable formalParameter="IN"><connectionPointIn><connection refLocalId="1" /><expression>n</expression></connectionPointIn></variable></inputVariables>
          <inOutVariables />
          <outputVariables><variable formalParameter="OUT"><connectionPointOut><expression>m</expression></connectionPointOut></variable></outputVariables>
        </block>
      </FBD>"#;
    let dir = tempfile::tempdir().unwrap();
    let x = dir.path().join("w.xml");
    std::fs::write(&x, project(vars, body)).unwrap();
    let (trace, stderr) = run_traced_files(&[&x], 1, "P.m");
    assert_eq!(column(&trace, "P.m"), [7.0], "{trace}");
    assert!(
        stderr.contains("warning[W1449]: expression `n` on a connection point is not read: the pin has wires too"),
        "{stderr}"
    );
}
