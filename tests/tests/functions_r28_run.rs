//! Round 28 of issue #13: functions and calls, run end to end through `ladderc run`:
//! - a FUNCTION's VAR_IN_OUT given by position is bound to the caller's variable, so a function
//!   passes its own in-out on to another function (`EvtFull(Handle)`, log-lib), and so does a
//!   block's or a method's in-out; the callee's writes reach the original variable (before: E2005
//!   "a missing or located IN_OUT argument": the first argument went through IL's current result);
//! - a non-formal call may list all the parameters of the definition, inputs, in-outs and outputs
//!   in declaration order (IEC 61131-3 ed. 3, 6.6.1.4.2; SIMATIC AX writes `F(a, b, out)`): for a
//!   function and a function block instance the outputs so given are written (before: E1020
//!   "takes 1 inputs (the current result is the first), 3 given" for a function, "an output of a
//!   block is not passed positionally" for a block; too many arguments for a block stay E1020);
//! - a user function given another number of positional arguments is one E1020 in ST's words
//!   (before: IL's "the current result is the first");
//! - `LOWER_BOUND(x.a, 1)` with `x` of a type nothing declares is the type's E1003 alone, in ST,
//!   in a TwinCAT `.TcPOU` and in PLCopen XML (before: an E1070 for the bound, and no E1003);
//! - a property and a literal given to two VAR_IN_OUTs of one call: one E0338 and one E1088, each
//!   at its argument (the lowering reads the property rewrite's mark, not its message);
//! - a call of a FUNCTION declared twice (SIMATIC AX overloads) is not checked against the one
//!   declaration kept: the E1002 is the one error (before: an E1012 for the other overload's
//!   argument type besides).

mod common;
use common::{check_text, column, run_text};

const HANDLE: &str = "TYPE H : STRUCT a : INT; b : INT; END_STRUCT; END_TYPE
FUNCTION Bump : BOOL
VAR_IN_OUT h : H; END_VAR
h.a := h.a + 1;
Bump := TRUE;
END_FUNCTION
FUNCTION_BLOCK Adder
VAR_IN_OUT h : H; END_VAR
h.b := h.b + 100;
END_FUNCTION_BLOCK
";

/// A function passes its VAR_IN_OUT on to another function, by position and by name, and is
/// itself called by position: both callee writes reach the program's variable each scan.
#[test]
fn a_function_passes_its_in_out_on() {
    let src = format!(
        "{HANDLE}FUNCTION Outer : BOOL
VAR_IN_OUT hh : H; END_VAR
Outer := Bump(hh);
Bump(h := hh);
hh.b := hh.b + 10;
END_FUNCTION
PROGRAM P
VAR x : H; r : BOOL; a : INT; b : INT; END_VAR
r := Outer(x);
a := x.a;
b := x.b;
END_PROGRAM
"
    );
    let (trace, stderr) = run_text("pass.st", &src, 2, "P.a,P.b,P.r");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "P.a"), vec![2.0, 4.0], "{trace}");
    assert_eq!(column(&trace, "P.b"), vec![10.0, 20.0], "{trace}");
    assert_eq!(column(&trace, "P.r"), vec![1.0, 1.0], "{trace}");
}

/// A block's in-out passed on to a function's in-out (by position and by name) and to another
/// block's in-out; a method's in-out passed on to a function's in-out.
#[test]
fn a_block_or_method_passes_its_in_out_on() {
    let src = format!(
        "{HANDLE}FUNCTION_BLOCK Blk
METHOD M : BOOL
VAR_IN_OUT mh : H; END_VAR
M := Bump(mh);
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Outer
VAR_IN_OUT hh : H; END_VAR
VAR fb : Adder; m : Blk; r : BOOL; END_VAR
r := Bump(hh);
Bump(h := hh);
fb(hh);
fb(h := hh);
m.M(hh);
END_FUNCTION_BLOCK
PROGRAM P
VAR x : H; o : Outer; a : INT; b : INT; END_VAR
o(x);
a := x.a;
b := x.b;
END_PROGRAM
"
    );
    let (trace, stderr) = run_text("pass_fb.st", &src, 2, "P.a,P.b");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "P.a"), vec![3.0, 6.0], "{trace}");
    assert_eq!(column(&trace, "P.b"), vec![200.0, 400.0], "{trace}");
}

/// `Split(x, c, l, h)`: a function's input, in-out and two outputs by position, in a statement
/// and in an expression; a block instance's input and output by position (`f(7, q)`, the block's
/// method's input is not one of its parameters).
#[test]
fn outputs_given_by_position_are_written() {
    let src = "FUNCTION Split : BOOL
VAR_INPUT a : INT; END_VAR
VAR_IN_OUT n : INT; END_VAR
VAR_OUTPUT lo : INT; hi : INT; END_VAR
lo := a MOD 10;
hi := a / 10;
n := n + 1;
Split := TRUE;
END_FUNCTION
FUNCTION_BLOCK Twice
VAR_INPUT a : INT; END_VAR
VAR_OUTPUT q : INT; END_VAR
q := a * 2;
METHOD Scale : INT
VAR_INPUT k : INT; END_VAR
Scale := q * k;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Five
VAR_OUTPUT o : INT; END_VAR
o := 5;
END_FUNCTION_BLOCK
PROGRAM P
VAR x : INT := 42; c : INT; l : INT; h : INT; l2 : INT; h2 : INT; r : BOOL;
  f : Twice; q : INT; five : Five; v : INT; END_VAR
r := Split(x, c, l, h);
Split(x + 1, c, l2, h2);
f(7, q);
five(v);
END_PROGRAM
";
    let (trace, stderr) = run_text("outs.st", src, 2, "P.l,P.h,P.l2,P.h2,P.c,P.r,P.q,P.v");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "P.l"), vec![2.0, 2.0], "{trace}");
    assert_eq!(column(&trace, "P.h"), vec![4.0, 4.0], "{trace}");
    assert_eq!(column(&trace, "P.l2"), vec![3.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "P.h2"), vec![4.0, 4.0], "{trace}");
    assert_eq!(column(&trace, "P.c"), vec![2.0, 4.0], "{trace}");
    assert_eq!(column(&trace, "P.r"), vec![1.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "P.q"), vec![14.0, 14.0], "{trace}");
    assert_eq!(column(&trace, "P.v"), vec![5.0, 5.0], "{trace}");
}

/// A user function given neither its inputs nor all its parameters by position: one E1020 at the
/// arguments, in ST's words (no "current result", which is IL's), naming both lists.
#[test]
fn a_wrong_number_of_positional_arguments_is_said_in_st_words() {
    let src = "FUNCTION Split : BOOL
VAR_INPUT a : INT; END_VAR
VAR_OUTPUT lo : INT; hi : INT; END_VAR
lo := a; hi := a;
Split := TRUE;
END_FUNCTION
PROGRAM P
VAR x : INT; l : INT; r : BOOL; END_VAR
r := Split(x, l);
END_PROGRAM
";
    let (code, lines) = check_text("arity.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains(
            "arity.st:9:12: error[E1020]: Split takes 1 inputs (or 3 with its outputs), 2 given"
        ) && lines[0].contains("a, lo, hi")
            && !lines[0].contains("current result"),
        "{lines:?}"
    );
}

/// `LOWER_BOUND(x.a, 1)` with `x : Missing` (unqualified, declared nowhere): the type's E1003 is
/// the one error.
#[test]
fn bounds_of_an_unknown_types_field_are_the_types_error() {
    let src = "PROGRAM P
VAR x : Missing; n : DINT; END_VAR
n := LOWER_BOUND(x.a, 1);
n := UPPER_BOUND(x.a, 1);
END_PROGRAM
";
    let (code, lines) = check_text("unknown.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("unknown.st:2:9: error[E1003]: unknown type `Missing`"),
        "{lines:?}"
    );
}

/// A property given to one VAR_IN_OUT and a literal to another of the same call: the property's
/// E0338 and the literal's E1088, one each (neither hides nor repeats the other).
#[test]
fn a_property_and_a_literal_given_to_in_outs_are_one_error_each() {
    let src = "FUNCTION_BLOCK Box
VAR v : INT; END_VAR
PROPERTY Val : INT
GET
Val := v;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
FUNCTION_BLOCK Both
VAR_IN_OUT x : INT; y : INT; END_VAR
x := y;
END_FUNCTION_BLOCK
PROGRAM P
VAR b : Box; t : Both; END_VAR
t(x := b.Val, y := 5);
END_PROGRAM
";
    let (code, lines) = check_text("prop.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(lines[0].contains("prop.st:15:8: error[E0338]"), "{lines:?}");
    assert!(
        lines[1].contains("prop.st:15:20: error[E1088]"),
        "{lines:?}"
    );
}

/// The same in a TwinCAT `.TcPOU` and in a PLCopen XML POU: the unknown type is the one error
/// (E1003 in the `.TcPOU`, the XML reader's E3009), not the bounds of its field.
#[test]
fn bounds_of_an_unknown_types_field_in_twincat_and_xml() {
    let tc = r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4024.12">
  <POU Name="MAIN" Id="{6f1f5a52-0000-4000-8000-000000000001}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
  x : ST_Missing;
  n : DINT;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[n := UPPER_BOUND(x.aValues, 1);]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
"#;
    let (code, lines) = check_text("MAIN.TcPOU", tc);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("error[E1003]: unknown type `ST_Missing`"),
        "{lines:?}"
    );
    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP16" creationDateTime="2026-01-01T00:00:00" />
  <contentHeader name="r28" modificationDateTime="2026-01-01T00:00:00">
    <coordinateInfo><fbd><scaling x="1" y="1" /></fbd><ld><scaling x="1" y="1" /></ld><sfc><scaling x="1" y="1" /></sfc></coordinateInfo>
  </contentHeader>
  <types>
    <dataTypes />
    <pous>
      <pou name="PLC_PRG" pouType="program">
        <interface>
          <localVars>
            <variable name="x"><type><derived name="ST_Missing" /></type></variable>
            <variable name="n"><type><DINT /></type></variable>
          </localVars>
        </interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := LOWER_BOUND(x.aValues, 1);</xhtml></ST></body>
      </pou>
    </pous>
  </types>
  <instances>
    <configurations>
      <configuration name="Cfg">
        <resource name="Res">
          <task name="MainTask" interval="PT0.01S" priority="1"><pouInstance name="PLC_PRG" typeName="PLC_PRG" /></task>
        </resource>
      </configuration>
    </configurations>
  </instances>
</project>
"#;
    let (code, lines) = check_text("bounds.xml", xml);
    assert_eq!(code, Some(1));
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(errors[0].contains("ST_Missing"), "{lines:?}");
}

/// Two FUNCTIONs of one name (SIMATIC AX overloads `CountDigits(LINT)` and `CountDigits(ULINT)`;
/// IEC 61131-3 gives user functions no overloading): the E1002 is the one error, the call of the
/// ULINT is not also checked against the LINT declaration kept (before: E1012 besides).
#[test]
fn a_call_of_a_function_declared_twice_is_the_e1002_alone() {
    let src = "FUNCTION Digits : INT
VAR_INPUT value : LINT; END_VAR
Digits := 1;
END_FUNCTION
FUNCTION Digits : INT
VAR_INPUT value : ULINT; END_VAR
Digits := 2;
END_FUNCTION
PROGRAM P
VAR u : ULINT; n : INT; END_VAR
n := Digits(u);
END_PROGRAM
";
    let (code, lines) = check_text("overload.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("overload.st:5:10: error[E1002]: `Digits` is declared twice"),
        "{lines:?}"
    );
}
