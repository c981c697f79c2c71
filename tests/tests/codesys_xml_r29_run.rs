//! Round 29 of unseen projects (issue #13): CODESYS V3's "Export PLCopenXML" files, run end to end
//! through `ladderc run`:
//! - the visualisation task's `<pouInstance name="VisuElems.Visu_Prg" typeName=""/>` (every export of
//!   a project with a visualisation) is left out with one W1447 naming it, and a task that ran only
//!   it is left out too; the other programs run (before: E3013 "program instance needs a `name` and
//!   a `typeName`", nothing ran). An instance `name="PLC_PRG" typeName=""` still runs PLC_PRG.
//! - CODESYS's `BIT` (`<derived name="BIT"/>`, a structure's one-bit member) is read as BOOL, as in
//!   ST text (before: E3009 "type `BIT` is not defined in this project").
//! - a VAR_IN_OUT `ARRAY[*] OF T`, which the export writes as an input `<pointer>` with the vendor
//!   attributes `variable_length_array` and `variable_length_array_original_scope="Inout"`, is the
//!   variable-length array it was declared as: `LOWER_BOUND`, `UPPER_BOUND` and indexing give the
//!   caller's array, in a function and in a function block's METHOD (before: two E1070
//!   "`LOWER_BOUND` takes a declared array").
//! - a METHOD (and a PROPERTY) of a PROGRAM in the program's vendor data is compiled, called inside
//!   it and as `PRG.M(x)` from another program (before: E0303 "methods are compiled for function
//!   blocks only").
//! - a function called only from an action (or a method) of a program is used, so compiled
//!   (before: W3004 "skipped", then E1019 "unknown function" at the action's call).
//! - a file that is not well-formed XML in its attributes (`@_name="x"`, `name=x`) is one E3001 at
//!   the first fault (before: W3001 and one E3013 per POU, nothing saying the XML is malformed).

mod common;
use common::{check_text, column, run_text};

/// A CODESYS V3.5 export of `data_types` (`<dataType>` elements), `pous` (`<pou>` elements) and
/// `tasks` (`<task>` elements of the resource `Application`).
fn codesys_export(data_types: &str, pous: &str, tasks: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="CODESYS Development GmbH" productName="CODESYS" productVersion="CODESYS V3.5 SP16" creationDateTime="2026-01-01T00:00:00" />
  <contentHeader name="r29.project" modificationDateTime="2026-01-01T00:00:00">
    <coordinateInfo><fbd><scaling x="1" y="1" /></fbd><ld><scaling x="1" y="1" /></ld><sfc><scaling x="1" y="1" /></sfc></coordinateInfo>
  </contentHeader>
  <types>
    <dataTypes>{data_types}</dataTypes>
    <pous>{pous}</pous>
  </types>
  <instances>
    <configurations>
      <configuration name="Device">
        <resource name="Application">{tasks}</resource>
      </configuration>
    </configurations>
  </instances>
</project>
"#
    )
}

/// The main task running PLC_PRG every 10 ms (every scan of `ladderc run`), as CODESYS writes it
/// (`typeName=""`).
const MAIN_TASK: &str = r#"
          <task name="MainTask" interval="PT0.01S" priority="1">
            <pouInstance name="PLC_PRG" typeName="" />
          </task>"#;

/// An ST POU of `kind` with `vars` (its `<localVars>` content) and `body`.
fn st_pou(name: &str, kind: &str, vars: &str, body: &str) -> String {
    format!(
        r#"
      <pou name="{name}" pouType="{kind}">
        <interface><localVars>{vars}</localVars></interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">{body}</xhtml></ST></body>
      </pou>"#
    )
}

/// The counter PLC_PRG: `n` counts the program's executions.
fn counter() -> String {
    st_pou(
        "PLC_PRG",
        "program",
        r#"<variable name="n"><type><INT /></type></variable>"#,
        "n := n + 1;",
    )
}

/// The visualisation task of a CODESYS export beside the main task: the visualisation's program is
/// left out with one W1447 at its name (and its task with it), and PLC_PRG (instance
/// `typeName=""`) runs every scan: n = 1, 2, 3 ... Before, the instance was E3013 and nothing ran.
#[test]
fn the_visualisation_task_of_a_codesys_export_is_left_out_and_the_programs_run() {
    let tasks = format!(
        r#"{MAIN_TASK}
          <task name="VISU_TASK" interval="PT0.2S" priority="31">
            <pouInstance name="VisuElems.Visu_Prg" typeName="" />
          </task>"#
    );
    let src = codesys_export("", &counter(), &tasks);
    let (code, lines) = check_text("visu.xml", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    let visu: Vec<&String> = lines.iter().filter(|l| l.contains("W1447")).collect();
    assert_eq!(visu.len(), 1, "{lines:?}");
    assert!(
        visu[0].starts_with("visu.xml:23:32: warning[W1447]")
            && visu[0].contains("`VisuElems.Visu_Prg`")
            && visu[0].contains("`VISU_TASK`")
            && visu[0].contains("library `VisuElems`"),
        "{lines:?}"
    );
    assert!(!lines.iter().any(|l| l.contains("error[")), "{lines:?}");
    let (trace, _) = run_text("visu.xml", &src, 5, "PLC_PRG.n");
    assert_eq!(column(&trace, "PLC_PRG.n"), vec![1.0, 2.0, 3.0, 4.0, 5.0]);
}

/// A qualified instance name that is not a library program's call (it has a type of its own) is
/// still one E3013, which now says that the name is not an identifier (before: "needs a `name` and
/// a `typeName`", though both were there).
#[test]
fn a_qualified_program_instance_with_a_type_is_one_e3013_naming_it() {
    let tasks = r#"
          <task name="MainTask" interval="PT0.01S" priority="1">
            <pouInstance name="My.Main" typeName="PLC_PRG" />
          </task>"#;
    let src = codesys_export("", &counter(), tasks);
    let (code, lines) = check_text("qualified.xml", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("qualified.xml:20:32: error[E3013]")
            && errors[0].contains("`My.Main` is not an IEC 61131-3 identifier"),
        "{lines:?}"
    );
}

/// CODESYS's `BIT` members of a structure (`<derived name="BIT"/>`, CODESYS online help, compiler
/// error C0203: BIT only in structures and function blocks) hold TRUE and FALSE like BOOL: b1
/// set, b0 left FALSE, and a BIT member counted as an INT through BOOL_TO_INT. Before: E3009
/// "type `BIT` is not defined in this project".
#[test]
fn a_codesys_bit_member_of_a_structure_is_read_as_bool() {
    let types = r#"
      <dataType name="dtBits">
        <baseType><struct>
          <variable name="b0"><type><derived name="BIT" /></type></variable>
          <variable name="b1"><type><derived name="BIT" /></type></variable>
        </struct></baseType>
      </dataType>"#;
    let pou = st_pou(
        "PLC_PRG",
        "program",
        r#"<variable name="s"><type><derived name="dtBits" /></type></variable>
          <variable name="x"><type><BOOL /></type></variable>
          <variable name="y"><type><BOOL /></type></variable>
          <variable name="k"><type><INT /></type></variable>"#,
        "s.b1 := NOT s.b1; x := s.b1; y := s.b0; k := k + BOOL_TO_INT(s.b1);",
    );
    let src = codesys_export(types, &pou, MAIN_TASK);
    let (trace, _) = run_text("bits.xml", &src, 4, "PLC_PRG.x,PLC_PRG.y,PLC_PRG.k");
    assert_eq!(column(&trace, "PLC_PRG.x"), vec![1.0, 0.0, 1.0, 0.0]);
    assert_eq!(column(&trace, "PLC_PRG.y"), vec![0.0; 4]);
    assert_eq!(column(&trace, "PLC_PRG.k"), vec![1.0, 1.0, 2.0, 2.0]);
}

/// The function `SumAll` as CODESYS exports `VAR_IN_OUT Values : ARRAY[*] OF INT` (CODESYS online
/// help, "Data Type: ARRAY OF", arrays of variable length, only in VAR_IN_OUT; IEC 61131-3 ed. 3,
/// 6.5.3): an input `<pointer>` to INT with the vendor attributes giving the declaration. `limit`
/// is a plain input after it (its place among the parameters kept).
const SUM_ALL: &str = r#"
      <pou name="SumAll" pouType="function">
        <interface>
          <returnType><INT /></returnType>
          <inputVars>
            <variable name="Values">
              <type><pointer><baseType><INT /></baseType></pointer></type>
              <addData>
                <data name="http://www.3s-software.com/plcopenxml/attributes" handleUnknown="implementation">
                  <Attributes>
                    <Attribute Name="variable_length_array_original_scope" Value="Inout" />
                    <Attribute Name="variable_length_array" Value="ARRAY[*] OF INT" />
                    <Attribute Name="Dimensions" Value="1" />
                  </Attributes>
                </data>
              </addData>
            </variable>
            <variable name="limit"><type><DINT /></type></variable>
          </inputVars>
          <outputVars><variable name="first"><type><DINT /></type></variable></outputVars>
          <localVars><variable name="i"><type><DINT /></type></variable></localVars>
        </interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">SumAll := 0;
first := LOWER_BOUND(Values, 1);
FOR i := LOWER_BOUND(Values, 1) TO MIN(UPPER_BOUND(Values, 1), limit) DO
  SumAll := SumAll + Values[i];
END_FOR;
Values[first] := Values[first] + 1;</xhtml></ST></body>
      </pou>"#;

/// CODESYS's export of an `ARRAY[*]` VAR_IN_OUT is read as that parameter: `SumAll(a, 99)` over
/// `a : ARRAY[1..3]` = [1, 2, 3] sums 6 and gives the lower bound 1; over `b : ARRAY[5..6]` =
/// [10, 20] with limit 5 it sums only b[5] = 10 and gives 5; the write `Values[first]` reaches the
/// caller's array (a[1] grows by one each scan, so the sum does too). Before: two E1070,
/// "`LOWER_BOUND` takes a declared array".
#[test]
fn a_codesys_variable_length_in_out_is_the_callers_array() {
    let main = st_pou(
        "PLC_PRG",
        "program",
        r#"<variable name="a"><type><array><dimension lower="1" upper="3" /><baseType><INT /></baseType></array></type>
            <initialValue><arrayValue><value><simpleValue value="1" /></value><value><simpleValue value="2" /></value><value><simpleValue value="3" /></value></arrayValue></initialValue></variable>
          <variable name="b"><type><array><dimension lower="5" upper="6" /><baseType><INT /></baseType></array></type>
            <initialValue><arrayValue><value><simpleValue value="10" /></value><value><simpleValue value="20" /></value></arrayValue></initialValue></variable>
          <variable name="sa"><type><INT /></type></variable>
          <variable name="sb"><type><INT /></type></variable>
          <variable name="fa"><type><DINT /></type></variable>
          <variable name="fb"><type><DINT /></type></variable>"#,
        "sa := SumAll(a, 99, first =&gt; fa); sb := SumAll(Values := b, limit := 5, first =&gt; fb);",
    );
    let src = codesys_export("", &format!("{SUM_ALL}{main}"), MAIN_TASK);
    let (code, lines) = check_text("vla.xml", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    let (trace, _) = run_text(
        "vla.xml",
        &src,
        3,
        "PLC_PRG.sa,PLC_PRG.fa,PLC_PRG.sb,PLC_PRG.fb",
    );
    assert_eq!(column(&trace, "PLC_PRG.sa"), vec![6.0, 7.0, 8.0]);
    assert_eq!(column(&trace, "PLC_PRG.fa"), vec![1.0; 3]);
    assert_eq!(column(&trace, "PLC_PRG.sb"), vec![10.0, 11.0, 12.0]);
    assert_eq!(column(&trace, "PLC_PRG.fb"), vec![5.0; 3]);
}

/// The same encoding in a METHOD of a function block (its `<interface>` in the block's vendor
/// data): `st.Sum(a)` over `a : ARRAY[0..2]` = [4, 5, 6] sums 15, and the method's
/// `Values[UPPER_BOUND(Values, 1)]` is a[2] = 6. Without the method's split, E1072 "a
/// variable-length array is allowed only as a VAR_IN_OUT".
#[test]
fn a_codesys_variable_length_in_out_of_a_method_is_the_callers_array() {
    let pous = r#"
      <pou name="FB_Stats" pouType="functionBlock">
        <interface><outputVars><variable name="last"><type><INT /></type></variable></outputVars></interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml"></xhtml></ST></body>
        <addData>
          <data name="http://www.3s-software.com/plcopenxml/method" handleUnknown="implementation">
            <Method name="Sum" ObjectId="00000000-0000-0000-0000-000000000001">
              <interface>
                <returnType><INT /></returnType>
                <inputVars>
                  <variable name="Values">
                    <type><pointer><baseType><INT /></baseType></pointer></type>
                    <addData>
                      <data name="http://www.3s-software.com/plcopenxml/attributes" handleUnknown="implementation">
                        <Attributes>
                          <Attribute Name="variable_length_array_original_scope" Value="Inout" />
                          <Attribute Name="variable_length_array" Value="ARRAY[*] OF INT" />
                          <Attribute Name="Dimensions" Value="1" />
                        </Attributes>
                      </data>
                    </addData>
                  </variable>
                </inputVars>
                <localVars><variable name="i"><type><DINT /></type></variable></localVars>
              </interface>
              <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">Sum := 0;
FOR i := LOWER_BOUND(Values, 1) TO UPPER_BOUND(Values, 1) DO Sum := Sum + Values[i]; END_FOR;
last := Values[UPPER_BOUND(Values, 1)];</xhtml></ST></body>
              <addData />
            </Method>
          </data>
        </addData>
      </pou>
      <pou name="PLC_PRG" pouType="program">
        <interface><localVars>
          <variable name="st"><type><derived name="FB_Stats" /></type></variable>
          <variable name="a"><type><array><dimension lower="0" upper="2" /><baseType><INT /></baseType></array></type>
            <initialValue><arrayValue><value><simpleValue value="4" /></value><value><simpleValue value="5" /></value><value><simpleValue value="6" /></value></arrayValue></initialValue></variable>
          <variable name="s"><type><INT /></type></variable>
          <variable name="l"><type><INT /></type></variable>
        </localVars></interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">s := st.Sum(a); l := st.last;</xhtml></ST></body>
      </pou>"#;
    let src = codesys_export("", pous, MAIN_TASK);
    let (trace, _) = run_text("vla_method.xml", &src, 2, "PLC_PRG.s,PLC_PRG.l");
    assert_eq!(column(&trace, "PLC_PRG.s"), vec![15.0; 2]);
    assert_eq!(column(&trace, "PLC_PRG.l"), vec![6.0; 2]);
}

/// A METHOD and a PROPERTY of a PROGRAM in CODESYS's vendor data (CODESYS help, object "Method":
/// inserted below a function block or a program): `Add2` called inside PLC_PRG counts n = 1, 2,
/// 3; the program `Other` calls `PLC_PRG.Add2(100, n_other)` and reads the property
/// `PLC_PRG.Count` (its Get returns n). Before: E0303 "methods are compiled for function blocks
/// only" (and the same for the property).
#[test]
fn a_method_and_a_property_of_a_codesys_program_are_compiled() {
    let main = r#"
      <pou name="PLC_PRG" pouType="program">
        <interface><localVars><variable name="n"><type><INT /></type></variable></localVars></interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := Add2(n, 1);</xhtml></ST></body>
        <addData>
          <data name="http://www.3s-software.com/plcopenxml/method" handleUnknown="implementation">
            <Method name="Add2" ObjectId="00000000-0000-0000-0000-000000000001">
              <interface>
                <returnType><INT /></returnType>
                <inputVars>
                  <variable name="a"><type><INT /></type></variable>
                  <variable name="b"><type><INT /></type></variable>
                </inputVars>
              </interface>
              <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">Add2 := a + b;</xhtml></ST></body>
              <addData />
            </Method>
          </data>
          <data name="http://www.3s-software.com/plcopenxml/property" handleUnknown="implementation">
            <Property name="Count" ObjectId="00000000-0000-0000-0000-000000000002">
              <interface><returnType><INT /></returnType></interface>
              <GetAccessor>
                <interface />
                <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">Count := n;</xhtml></ST></body>
                <addData />
              </GetAccessor>
            </Property>
          </data>
        </addData>
      </pou>"#;
    let other = st_pou(
        "Other",
        "program",
        r#"<variable name="m"><type><INT /></type></variable>
          <variable name="c"><type><INT /></type></variable>"#,
        "m := PLC_PRG.Add2(100, c); c := PLC_PRG.Count;",
    );
    let tasks = r#"
          <task name="MainTask" interval="PT0.01S" priority="1">
            <pouInstance name="PLC_PRG" typeName="" />
            <pouInstance name="Other" typeName="" />
          </task>"#;
    let src = codesys_export("", &format!("{main}{other}"), tasks);
    let (code, lines) = check_text("method.xml", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    let (trace, _) = run_text("method.xml", &src, 3, "PLC_PRG.n,Other.m,Other.c");
    assert_eq!(column(&trace, "PLC_PRG.n"), vec![1.0, 2.0, 3.0]);
    // c is read after m is computed: the count of the scan before
    assert_eq!(column(&trace, "Other.m"), vec![100.0, 101.0, 102.0]);
    assert_eq!(column(&trace, "Other.c"), vec![1.0, 2.0, 3.0]);
}

/// A file whose attributes are written `@_name="..."` (a JavaScript XML library's object dump, as
/// spirithere/plc-emulator saves its projects) is not well-formed XML (XML 1.0, 2.3 NameStartChar;
/// a processor reports such a fatal error, 1.2): one E3001 at the first `@`, naming the attribute,
/// and nothing else. Before: W3001 "no PLCopen namespace" and one E3013 "POU without a valid
/// `name`" per POU and per configuration.
#[test]
fn an_attribute_name_starting_with_at_is_one_xml_error_at_it() {
    let src = r#"<?xml version="1.0" encoding="utf-8"?>
<project @_xmlns="http://www.plcopen.org/xml/tc6_0201">
  <types>
    <pous>
      <pou @_name="Main" @_pouType="program">
        <body><ST><xhtml>x := TRUE;</xhtml></ST></body>
      </pou>
    </pous>
  </types>
</project>
"#;
    let (code, lines) = check_text("at.xml", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("at.xml:2:10: error[E3001]")
            && lines[0].contains("not well-formed")
            && lines[0].contains("`@_xmlns`"),
        "{lines:?}"
    );
}

/// An unquoted attribute value (`name=Other`, XML 1.0, 3.1 [10] AttValue) after well-formed
/// elements: one E3001 at the value, saying it is not in quotes; the POU read before it is no
/// error of its own. Before: one E3013 "POU without a valid `name`".
#[test]
fn an_unquoted_attribute_value_is_one_xml_error_at_it() {
    let src = codesys_export(
        "",
        &format!(
            "{}{}",
            counter(),
            r#"
      <pou name=Other pouType="program">
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">y := TRUE;</xhtml></ST></body>
      </pou>"#
        ),
        MAIN_TASK,
    );
    let (code, lines) = check_text("unquoted.xml", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("unquoted.xml:14:17: error[E3001]")
            && errors[0].contains("attribute `name` is not in quotes"),
        "{lines:?}"
    );
}

/// A function called only from an action of the program (CODESYS's speed tests call their
/// functions from an action `Measure`) is used: compiled, and the action's call runs, d = 2 * n.
/// Before: W3004 "not used by any program instance and is skipped", then E1019 "unknown function
/// `Twice`" at the action's call (the search for used POUs read the POU's body only).
#[test]
fn a_function_called_only_from_an_action_is_compiled() {
    let twice = r#"
      <pou name="Twice" pouType="function">
        <interface><returnType><INT /></returnType><inputVars><variable name="x"><type><INT /></type></variable></inputVars></interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">Twice := 2 * x;</xhtml></ST></body>
      </pou>"#;
    let main = r#"
      <pou name="PLC_PRG" pouType="program">
        <interface><localVars>
          <variable name="n"><type><INT /></type></variable>
          <variable name="d"><type><INT /></type></variable>
        </localVars></interface>
        <actions>
          <action name="Measure">
            <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">d := Twice(n);</xhtml></ST></body>
          </action>
        </actions>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := n + 1; Measure();</xhtml></ST></body>
      </pou>"#;
    let src = codesys_export("", &format!("{twice}{main}"), MAIN_TASK);
    let (code, lines) = check_text("action.xml", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(!lines.iter().any(|l| l.contains("W3004")), "{lines:?}");
    let (trace, _) = run_text("action.xml", &src, 3, "PLC_PRG.d");
    assert_eq!(column(&trace, "PLC_PRG.d"), vec![2.0, 4.0, 6.0]);
}
