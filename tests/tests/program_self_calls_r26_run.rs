//! Round 26 of issue #13: a PROGRAM naming its own actions and methods through its own name,
//! inside itself, run end to end through `ladderc run`:
//! - `Prog.Act();` in `Prog`'s body or one of its actions is the call `Act();`: the action runs at
//!   once on the program's state (CODESYS, "Object: Action": the program's name is optional in the
//!   program's own implementation; a CODESYS V2.3 export writes it; before: E3135 "calls its own
//!   action through its name");
//! - the same for the program's METHODs: `Prog.M(x)`, `Prog.M(d := 1)`, `y := Prog.M(2) + 1`, an
//!   output `Prog.M(x := 3, r => q)`, in an ELSIF condition, twice in one statement, from the body,
//!   an action or another method, in `.st` files and TwinCAT `.TcPOU` (before: E3135);
//! - `CAL Prog.Act` in an IL body or IL action of a PLCopen XML program (before: E3135);
//! - a program instantiated twice by its configuration calls its own action through its name on
//!   the running instance (before: E3135); from another program that call stays E3135, and a
//!   program calling itself (`Prog();`) stays E3135, as does an IL call passing arguments to its
//!   own action through its name.

mod common;
use common::{check_text, run_text, run_traced_files};

/// A CODESYS V2.3 export: `Pump.Bump();` in `Pump`'s body and in its action `Twice` runs `Bump`
/// at once on Pump's state (tick: +10 from the body, +2 x 10 through `Twice`; `Pump.Twice();`
/// from the body too).
#[test]
fn a_v23_program_calls_its_own_action_through_its_name() {
    let src = "(* @NESTEDCOMMENTS := 'Yes' *)
(* @PATH := '' *)
(* @OBJECTFLAGS := '0, 8' *)
PROGRAM Pump
VAR
\tcount : INT;
\ttick : INT;
END_VAR
(* @END_DECLARATION := '0' *)
count := count + 1;
Pump.Bump();
Pump.Twice();
END_PROGRAM
ACTION\tBump:
tick := tick + 10;
END_ACTION
ACTION\tTwice:
Pump.Bump();
Bump();
END_ACTION
";
    let (trace, _) = run_text("pump.EXP", src, 3, "Pump.count,Pump.tick");
    assert_eq!(
        trace,
        "cycle,time_ms,Pump.count,Pump.tick\n0,0,1,30\n1,10,2,60\n2,20,3,90\n"
    );
}

/// A program's methods and actions through its own name in a `.st` file: positional and formal
/// inputs, a result inside an expression, an output, an ELSIF condition, two calls of one method
/// in one statement (each its own result), and calls from an action and from a method.
#[test]
fn a_program_calls_its_own_methods_through_its_name() {
    let src = "PROGRAM Main
VAR
  n, a, y, z, q, w, m : INT;
END_VAR
n := n + 1;
Main.Bump();
Main.Add(5);
Main.Add(d := 100);
y := Main.Twice(n) + 1;
IF n > 1 THEN
  z := 2;
ELSIF Main.Twice(n) > 0 THEN
  z := 1;
END_IF;
Main.Out(x := 3, r => q);
w := Main.Twice(1) + Main.Twice(2);
m := Main.Quad(n);
METHOD Add
VAR_INPUT d : INT; END_VAR
a := a + d;
END_METHOD
METHOD Twice : INT
VAR_INPUT v : INT; END_VAR
Twice := 2 * v;
END_METHOD
METHOD Quad : INT
VAR_INPUT v : INT; END_VAR
Quad := Main.Twice(Main.Twice(v));
END_METHOD
METHOD Out
VAR_INPUT x : INT; END_VAR
VAR_OUTPUT r : INT; END_VAR
r := x * 7;
END_METHOD
END_PROGRAM
ACTIONS
ACTION Bump:
  a := a + 1;
  Main.Add(1000);
END_ACTION
END_ACTIONS
";
    let (trace, _) = run_text(
        "main.st",
        src,
        2,
        "Main.a,Main.y,Main.z,Main.q,Main.w,Main.m",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.a,Main.y,Main.z,Main.q,Main.w,Main.m\n\
         0,0,1106,3,1,21,6,4\n\
         1,10,2212,5,2,21,6,8\n"
    );
}

/// A TwinCAT program: `MAIN.DoIt();` and `r := MAIN.Bump(2) * 10;` in its body, `MAIN.Bump(d :=
/// 1);` in its action (n grows by 3 a cycle; r is 10 times n after the second call).
#[test]
fn a_twincat_program_calls_its_own_action_and_method_through_its_name() {
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
	r : INT;
END_VAR]]></Declaration>
    <Implementation>
      <ST><![CDATA[MAIN.DoIt();
r := MAIN.Bump(2) * 10;]]></ST>
    </Implementation>
    <Action Name="DoIt" Id="{00000000-0000-0000-0000-000000000002}">
      <Implementation>
        <ST><![CDATA[MAIN.Bump(d := 1);]]></ST>
      </Implementation>
    </Action>
    <Method Name="Bump" Id="{00000000-0000-0000-0000-000000000003}">
      <Declaration><![CDATA[METHOD Bump : INT
VAR_INPUT
	d : INT;
END_VAR]]></Declaration>
      <Implementation>
        <ST><![CDATA[n := n + d;
Bump := n;]]></ST>
      </Implementation>
    </Method>
  </POU>
</TcPlcObject>"#,
    )
    .unwrap();
    let (trace, _) = run_traced_files(&[&main], 2, "MAIN.n,MAIN.r");
    assert_eq!(trace, "cycle,time_ms,MAIN.n,MAIN.r\n0,0,3,30\n1,10,6,60\n");
}

/// PLCopen XML: `CAL P.Inc` and `CAL P.Add` (an ST action) in P's IL body, `CAL P.Inc` in its IL
/// action `Both`, and `Q.Inc();` in Q's ST body run the actions in place.
#[test]
fn a_plcopen_program_calls_its_own_actions_through_its_name_in_il_and_st() {
    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <types><pous>
    <pou name="P" pouType="program">
      <interface><localVars><variable name="x"><type><INT /></type></variable><variable name="k"><type><INT /></type></variable></localVars></interface>
      <actions><action name="Inc"><body><IL><xhtml xmlns="http://www.w3.org/1999/xhtml">LD x
ADD 1
ST x</xhtml></IL></body></action>
      <action name="Add"><body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">k := k + 100;</xhtml></ST></body></action>
      <action name="Both"><body><IL><xhtml xmlns="http://www.w3.org/1999/xhtml">CAL P.Inc
CAL Inc</xhtml></IL></body></action></actions>
      <body><IL><xhtml xmlns="http://www.w3.org/1999/xhtml">CAL P.Inc
CAL P.Add
CAL P.Both</xhtml></IL></body>
    </pou>
    <pou name="Q" pouType="program">
      <interface><localVars><variable name="x"><type><INT /></type></variable></localVars></interface>
      <actions><action name="Inc"><body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">x := x + 1;</xhtml></ST></body></action></actions>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">Q.Inc();
Q.Inc();</xhtml></ST></body>
    </pou>
  </pous></types>
</project>
"#;
    let (trace, _) = run_text("own.xml", xml, 2, "P.x,P.k,Q.x");
    assert_eq!(
        trace,
        "cycle,time_ms,P.x,P.k,Q.x\n0,0,3,100,2\n1,10,6,200,4\n"
    );
}

/// A program that the configuration instantiates twice calls its own action through its name:
/// each instance runs it on its own state (A adds 1 a cycle, B 5).
#[test]
fn each_instance_of_a_program_runs_its_own_action_called_through_its_name() {
    let src = "PROGRAM Main
VAR_INPUT step : INT; END_VAR
VAR n : INT; END_VAR
Main.Bump();
END_PROGRAM
ACTIONS
ACTION Bump:
n := n + step;
END_ACTION
END_ACTIONS
CONFIGURATION Cfg
RESOURCE Res ON PLC
TASK T(INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM A WITH T : Main(step := 1);
PROGRAM B WITH T : Main(step := 5);
END_RESOURCE
END_CONFIGURATION
";
    let (trace, _) = run_text("cfg.st", src, 2, "A.n,B.n");
    assert_eq!(trace, "cycle,time_ms,A.n,B.n\n0,0,1,5\n1,10,2,10\n");
}

/// What stays E3135: a program calling itself (`Main();` inside Main), another program calling
/// the action of a program instantiated twice, and an IL call passing arguments to the program's
/// own action through its name (`CAL P.Inc(k := 1)`: `CAL Inc(k := 1)` is no call of it either).
#[test]
fn a_program_calling_itself_and_an_ambiguous_instance_stay_e3135() {
    let (code, lines) = check_text(
        "self.st",
        "PROGRAM Main
VAR n : INT; END_VAR
n := n + 1;
Main();
END_PROGRAM
",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("self.st:4:1: error[E3135]: program `Main` cannot be called here"),
        "{lines:?}"
    );
    let (code, lines) = check_text(
        "two.st",
        "PROGRAM Main
VAR n : INT; END_VAR
Main.Bump();
END_PROGRAM
ACTIONS
ACTION Bump:
n := n + 1;
END_ACTION
END_ACTIONS
PROGRAM Other
Main.Bump();
END_PROGRAM
CONFIGURATION Cfg
RESOURCE Res ON PLC
TASK T(INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM A WITH T : Main;
PROGRAM B WITH T : Main;
PROGRAM O WITH T : Other;
END_RESOURCE
END_CONFIGURATION
",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("two.st:11:1: error[E3135]: action `Bump` of program `Main`"),
        "{lines:?}"
    );
    let (code, lines) = check_text(
        "args.xml",
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <types><pous>
    <pou name="P" pouType="program">
      <interface><localVars><variable name="k"><type><INT /></type></variable></localVars></interface>
      <actions><action name="Inc"><body><IL><xhtml xmlns="http://www.w3.org/1999/xhtml">LD k
ADD 1
ST k</xhtml></IL></body></action></actions>
      <body><IL><xhtml xmlns="http://www.w3.org/1999/xhtml">CAL P.Inc(k := 1)</xhtml></IL></body>
    </pou>
  </pous></types>
</project>
"#,
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("error[E3135]: action `Inc` of program `P` cannot be called here: `P` passes arguments to its own action through its name"),
        "{lines:?}"
    );
}
