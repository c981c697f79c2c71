//! Round 26 of unseen projects (issue #13), more gaps real projects met, run end to end through
//! `ladderc run`:
//! - a `VAR_EXTERNAL` block inside a METHOD (edition 3's grammar lets a method declare
//!   `external_var_decls` as a function does; SIMATIC AX state classes read their globals so)
//!   reads and writes the global, in a FUNCTION_BLOCK's and a CLASS's method (before: E0303 "this
//!   variable block is not supported in a method"); one naming a variable of the block is one
//!   E0303 that says so;
//! - a PLCopen XML initial value `<simpleValue value="ADR(x)"/>` (CODESYS's export of `p :
//!   POINTER TO INT := ADR(x);`) makes the pointer start at `x`, for a local, a structure's field
//!   and a global pointer, as the ST declaration does (before: E3011 "is not a literal, a
//!   constant name or an integer constant expression"); `ADR('State')` of a literal is one E0305,
//!   as in ST (before: that E3011);
//! - the actions of a POU whose body is instruction list (an `ACTIONS ... END_ACTIONS` block, or
//!   CODESYS V2.3's bare `ACTION Name: ... END_ACTION` after the POU), each written in IL or ST,
//!   run where the IL body calls them (`CAL Act`, `CALC Act`) and through an instance from other
//!   POUs (`inst.Act();`), an ST action calling an IL one and the other way round (before: E0304
//!   "supported only right after a POU whose body is ST" for the block, E1060 "outside any POU"
//!   for the bare actions).

mod common;
use common::{check_text, column, run_text};

/// A method's `VAR_EXTERNAL` names the global itself: the method increments it and returns it,
/// and the program sees the new value; a second method of the same block may declare it too.
#[test]
fn a_method_reads_and_writes_a_global_through_var_external() {
    let src = "VAR_GLOBAL
  gCount : INT := 5;
  gLimit : INT := 7;
END_VAR
FUNCTION_BLOCK FB_Step
VAR_OUTPUT
  last : INT;
  full : BOOL;
END_VAR
METHOD Bump : INT
VAR_EXTERNAL
  gCount : INT;
END_VAR
gCount := gCount + 1;
Bump := gCount;
END_METHOD
METHOD IsFull : BOOL
VAR_EXTERNAL
  gCount : INT;
  gLimit : INT;
END_VAR
IsFull := gCount >= gLimit;
END_METHOD
last := THIS^.Bump();
full := IsFull();
END_FUNCTION_BLOCK
PROGRAM Main
VAR
  s : FB_Step;
  seen : INT;
END_VAR
s();
seen := gCount;
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "step.st",
        src,
        3,
        "gCount,Main.s.last,Main.s.full,Main.seen",
    );
    assert_eq!(column(&trace, "gCount"), [6.0, 7.0, 8.0], "{stderr}");
    assert_eq!(column(&trace, "Main.s.last"), [6.0, 7.0, 8.0]);
    assert_eq!(column(&trace, "Main.s.full"), [0.0, 1.0, 1.0]);
    assert_eq!(column(&trace, "Main.seen"), [6.0, 7.0, 8.0]);
    assert!(!stderr.contains("error"), "{stderr}");
}

/// The SIMATIC AX form: a CLASS's method declares the global sensor it reads (`VAR_EXTERNAL
/// resetError : BOOL; END_VAR`) and sets a field of the object from it.
#[test]
fn a_class_method_reads_a_global_through_var_external() {
    let src = "VAR_GLOBAL
  resetError : BOOL;
  cycles : INT;
END_VAR
CLASS ErrorState
VAR PUBLIC
  canGoNext : BOOL;
END_VAR
METHOD PUBLIC ExecuteJob
VAR_EXTERNAL
  resetError : BOOL;
  cycles : INT;
END_VAR
cycles := cycles + 1;
IF resetError THEN
  canGoNext := TRUE;
END_IF;
END_METHOD
END_CLASS
PROGRAM Main
VAR
  st : ErrorState;
  next : BOOL;
END_VAR
IF cycles = 2 THEN resetError := TRUE; END_IF;
st.ExecuteJob();
next := st.canGoNext;
END_PROGRAM
";
    let (trace, stderr) = run_text("states.st", src, 4, "cycles,Main.next");
    assert_eq!(column(&trace, "cycles"), [1.0, 2.0, 3.0, 4.0], "{stderr}");
    assert_eq!(column(&trace, "Main.next"), [0.0, 0.0, 1.0, 1.0]);
}

/// A method's `VAR_EXTERNAL` with the name of one of the block's own variables would make the
/// name mean two variables: one E0303 at the name, saying so.
#[test]
fn a_method_external_named_as_a_block_variable_is_one_error() {
    let src = "VAR_GLOBAL
  n : INT;
END_VAR
FUNCTION_BLOCK FB_A
VAR
  n : INT;
END_VAR
METHOD M
VAR_EXTERNAL
  n : INT;
END_VAR
n := 1;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : FB_A; END_VAR
a.M();
END_PROGRAM
";
    let (code, diags) = check_text("clash.st", src);
    assert_eq!(code, Some(1), "{diags:?}");
    let errors: Vec<_> = diags.iter().filter(|d| d.contains("error")).collect();
    assert_eq!(errors.len(), 1, "{diags:?}");
    assert!(
        errors[0].contains("E0303")
            && errors[0].contains("has the name of a variable of the block"),
        "{diags:?}"
    );
}

/// A PLCopen project (tc6_0200) whose type section is `types`.
fn plcopen(types: &str, globals: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP16" creationDateTime="2026-01-01T00:00:00" />
  <contentHeader name="r26" modificationDateTime="2026-01-01T00:00:00">
    <coordinateInfo><fbd><scaling x="1" y="1" /></fbd><ld><scaling x="1" y="1" /></ld><sfc><scaling x="1" y="1" /></sfc></coordinateInfo>
  </contentHeader>
  <types>
{types}
  </types>
  <instances>
    <configurations>
      <configuration name="Cfg">
        <resource name="Res">
          <task name="MainTask" interval="PT0.01S" priority="1"><pouInstance name="PLC_PRG" typeName="PLC_PRG" /></task>
        </resource>
        <globalVars>
{globals}
        </globalVars>
      </configuration>
    </configurations>
  </instances>
</project>
"#
    )
}

/// CODESYS exports `pA : POINTER TO INT := ADR(a);` as `<simpleValue value="ADR(a)"/>`: the
/// pointer starts at `a` (a local), a structure's field at a global (`adr( gTotal )`, any case
/// and blanks), and a global pointer at another global; each writes its target from the first
/// cycle.
#[test]
fn a_plcopen_initial_value_adr_of_a_variable() {
    let src = plcopen(
        r#"    <dataTypes>
      <dataType name="ST_Target">
        <baseType><struct>
          <variable name="pCount"><type><pointer><baseType><INT /></baseType></pointer></type></variable>
          <variable name="step"><type><INT /></type></variable>
        </struct></baseType>
      </dataType>
    </dataTypes>
    <pous>
      <pou name="PLC_PRG" pouType="program">
        <interface>
          <localVars>
            <variable name="a"><type><INT /></type><initialValue><simpleValue value="10" /></initialValue></variable>
            <variable name="pA">
              <type><pointer><baseType><INT /></baseType></pointer></type>
              <initialValue><simpleValue value="ADR(a)" /></initialValue>
            </variable>
            <variable name="target">
              <type><derived name="ST_Target" /></type>
              <initialValue><structValue>
                <value member="pCount"><simpleValue value="adr( gTotal )" /></value>
                <value member="step"><simpleValue value="5" /></value>
              </structValue></initialValue>
            </variable>
          </localVars>
          <externalVars>
            <variable name="gP"><type><pointer><baseType><INT /></baseType></pointer></type></variable>
          </externalVars>
        </interface>
        <body>
          <ST><xhtml xmlns="http://www.w3.org/1999/xhtml">pA^ := pA^ + 1;
target.pCount^ := target.pCount^ + target.step;
gP^ := gP^ + 100;</xhtml></ST>
        </body>
      </pou>
    </pous>"#,
        r#"          <variable name="gTotal"><type><INT /></type></variable>
          <variable name="gOther"><type><INT /></type></variable>
          <variable name="gP">
            <type><pointer><baseType><INT /></baseType></pointer></type>
            <initialValue><simpleValue value="ADR(gOther)" /></initialValue>
          </variable>"#,
    );
    let (trace, stderr) = run_text("adr.xml", &src, 2, "PLC_PRG.a,gTotal,gOther");
    assert_eq!(column(&trace, "PLC_PRG.a"), [11.0, 12.0], "{stderr}");
    assert_eq!(column(&trace, "gTotal"), [5.0, 10.0]);
    assert_eq!(column(&trace, "gOther"), [100.0, 200.0]);
    assert!(!stderr.contains("error"), "{stderr}");
}

/// An IL program with an `ACTIONS` block: `CAL Bump` runs the IL action, `CAL Twice` the ST one,
/// in the order the body calls them.
#[test]
fn an_il_program_runs_its_actions_block() {
    let src = "PROGRAM Main
VAR
  n : INT;
  m : INT;
END_VAR
  LD n
  ADD 1
  ST n
  CAL Bump
  CAL Twice
END_PROGRAM
ACTIONS
ACTION Bump:
  LD m
  ADD 10
  ST m
END_ACTION
ACTION Twice:
  m := m * 2;
END_ACTION
END_ACTIONS
";
    let (trace, stderr) = run_text("il_actions.st", src, 2, "Main.n,Main.m");
    assert_eq!(column(&trace, "Main.n"), [1.0, 2.0], "{stderr}");
    assert_eq!(column(&trace, "Main.m"), [20.0, 60.0]);
    assert!(!stderr.contains("error"), "{stderr}");
}

/// CODESYS V2.3's export: an IL function block followed by its bare actions (`ACTION Reset:`, IL,
/// calling `Note`, ST); the body runs `Reset` conditionally (`CALC Reset`), the program runs it
/// through an instance (`d.Reset();`).
#[test]
fn an_il_block_runs_its_bare_actions_from_its_body_and_through_an_instance() {
    let src = "(* @NESTEDCOMMENTS := 'Yes' *)
(* @PATH := '' *)
(* @OBJECTFLAGS := '0, 8' *)
FUNCTION_BLOCK FB_Counter
VAR_INPUT
  step : INT := 1;
END_VAR
VAR_OUTPUT
  count : INT;
  resets : INT;
END_VAR
(* @END_DECLARATION := '0' *)
LD count
ADD step
ST count
LD count
GT 5
CALC Reset
END_FUNCTION_BLOCK
ACTION\tReset:
LD 0
ST count
CAL Note
END_ACTION

ACTION\tNote:
resets := resets + 1;
END_ACTION


(* @NESTEDCOMMENTS := 'Yes' *)
(* @PATH := '' *)
(* @OBJECTFLAGS := '0, 8' *)
PROGRAM PLC_PRG
VAR
  c : FB_Counter;
  d : FB_Counter;
  cycle : INT;
END_VAR
(* @END_DECLARATION := '0' *)
c(step := 2);
d();
cycle := cycle + 1;
IF cycle = 2 THEN
  d.Reset();
END_IF;
END_PROGRAM
";
    let watch = "PLC_PRG.c.count,PLC_PRG.c.resets,PLC_PRG.d.count,PLC_PRG.d.resets";
    let (trace, stderr) = run_text("COUNTER.EXP", src, 5, watch);
    assert_eq!(
        column(&trace, "PLC_PRG.c.count"),
        [2.0, 4.0, 0.0, 2.0, 4.0],
        "{stderr}"
    );
    assert_eq!(
        column(&trace, "PLC_PRG.c.resets"),
        [0.0, 0.0, 1.0, 1.0, 1.0]
    );
    assert_eq!(column(&trace, "PLC_PRG.d.count"), [1.0, 0.0, 1.0, 2.0, 3.0]);
    assert_eq!(
        column(&trace, "PLC_PRG.d.resets"),
        [0.0, 1.0, 1.0, 1.0, 1.0]
    );
    assert!(!stderr.contains("error"), "{stderr}");
}

/// A bare action after an IL program, in a `.st` file: `CAL Main.Bump` (the program's own name,
/// CODESYS) and `CAL Bump` both run it.
#[test]
fn an_il_program_runs_a_bare_action_also_by_its_qualified_name() {
    let src = "PROGRAM Main
VAR
  m : INT;
END_VAR
  CAL Bump
  CAL Main.Bump
END_PROGRAM

ACTION Bump:
  LD m
  ADD 10
  ST m
END_ACTION
";
    let (trace, stderr) = run_text("il_bare.st", src, 2, "Main.m");
    assert_eq!(column(&trace, "Main.m"), [20.0, 40.0], "{stderr}");
    assert!(!stderr.contains("error"), "{stderr}");
}

/// An IL action that calls itself through another is E0106 at the call, once (no cascade).
#[test]
fn an_il_action_recursion_is_one_error_per_call() {
    let src = "PROGRAM Main
VAR
  m : INT;
END_VAR
  CAL A
END_PROGRAM
ACTION A:
  CAL B
END_ACTION
ACTION B:
  CAL A
END_ACTION
";
    let (code, diags) = check_text("il_rec.st", src);
    assert_eq!(code, Some(1), "{diags:?}");
    let errors: Vec<_> = diags.iter().filter(|d| d.contains("error")).collect();
    assert!(
        !errors.is_empty() && errors.iter().all(|d| d.contains("E0106")),
        "{diags:?}"
    );
    assert!(errors.len() <= 2, "{diags:?}");
}

/// `ADR('State')` (the address of a string literal, in CODESYS's MQTT export) is not a
/// variable's address: one E0305 saying so, as the ST declaration gets (before: E3011 "is not a
/// literal, a constant name or an integer constant expression").
#[test]
fn a_plcopen_initial_value_adr_of_a_literal_is_one_e0305() {
    let src = plcopen(
        r#"    <pous>
      <pou name="PLC_PRG" pouType="program">
        <interface>
          <localVars>
            <variable name="pS">
              <type><pointer><baseType><string /></baseType></pointer></type>
              <initialValue><simpleValue value="ADR('State')" /></initialValue>
            </variable>
          </localVars>
        </interface>
        <body>
          <ST><xhtml xmlns="http://www.w3.org/1999/xhtml">;</xhtml></ST>
        </body>
      </pou>
    </pous>"#,
        "",
    );
    let (code, diags) = check_text("lit.xml", &src);
    assert_eq!(code, Some(1), "{diags:?}");
    let errors: Vec<_> = diags.iter().filter(|d| d.contains("error")).collect();
    assert_eq!(errors.len(), 1, "{diags:?}");
    assert!(
        errors[0].contains("E0305") && errors[0].contains("ADR('State')"),
        "{diags:?}"
    );
}
