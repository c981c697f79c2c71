//! Round 26 of unseen projects (issue #13), initial values: what real programs need, run end to
//! end through `ladderc run`:
//! - `ADR()` in a global function block instance's structured initial value (`g : FB_Lamp :=
//!   (pL := ADR(x), n := 7);` in VAR_GLOBAL, TwinCAT's way to hand pointers to a GVL's instances)
//!   makes the pointer start at the global, also qualified by its list (`ADR(GVL_IO.bLamp)`),
//!   through an instance's output and from a plain global pointer (before: the `ADR` element
//!   silently dropped, the pointer NULL, the run ending "NULL reference dereferenced"); nested
//!   instance initializers keep their addresses too (before: silently dropped); where no address
//!   is taken (a located variable; until round 27 an element of an array's initial value) one
//!   E0305 (before: silent);
//! - a structure type's field initialised with a structure of a type declared below it (ST, and
//!   PLCopen XML `<dataTypes>` as OSCAT exports them) runs (before: E1025 at every member);
//! - a PLCopen XML `simpleValue` holding an integer constant expression (`((1024 * 1024) * 30)`,
//!   `(BLOCK * 2)`, as CODESYS exports a declaration's expression) is computed (before: E3011);
//! - an ST initial value that is a constant expression in parentheses (`x : UINT := (N * 2);`)
//!   runs (before: E0011);
//! - CODESYS V2.3's array initial value without brackets inside a structure's initializer
//!   (`items := (a := 11, b := 12), (a := 13, b := 14)`) is the array (before: E0011 at `(`).

mod common;
use common::{column, rejected_heads, run_text, run_traced_files};

/// The repro of the sweep: the global instance `g` gets `pL := ADR(x)` and writes `x` through it
/// from the first cycle, as the program-local instance `l` does; `h` without the element keeps
/// NULL (its guard skips the write).
#[test]
fn a_global_instance_initializer_takes_the_address_of_a_global() {
    let src = "FUNCTION_BLOCK FB_Lamp
VAR_INPUT
  pL : POINTER TO BOOL;
  n : INT;
END_VAR
VAR_OUTPUT
  m : INT;
END_VAR
IF pL <> 0 THEN pL^ := TRUE; END_IF
m := n;
END_FUNCTION_BLOCK
VAR_GLOBAL
  x : BOOL;
  g : FB_Lamp := (pL := ADR(x), n := 7);
  h : FB_Lamp := (n := 5);
END_VAR
PROGRAM Main
VAR
  y : BOOL;
  l : FB_Lamp := (pL := ADR(y), n := 3);
END_VAR
g();
h();
l();
END_PROGRAM
";
    let (trace, stderr) = run_text("lamps.st", src, 2, "x,g.m,h.m,Main.y,Main.l.m");
    assert_eq!(column(&trace, "x"), [1.0, 1.0], "{stderr}");
    assert_eq!(column(&trace, "g.m"), [7.0, 7.0]);
    assert_eq!(column(&trace, "h.m"), [5.0, 5.0]);
    assert_eq!(column(&trace, "Main.y"), [1.0, 1.0]);
    assert_eq!(column(&trace, "Main.l.m"), [3.0, 3.0]);
    assert!(!stderr.contains("error"), "{stderr}");
}

/// houqicheng/SWTestBeckhoff's GVL_General: an instance in one list whose pointer inputs start at
/// a structure's field of another list (`ADR(GVL_Machine.HWOutput.Lamp02)`), at an instance's
/// output of a third (`ADR(GVL_Sig.sig.bOut)`) and at a global declared below it (`ADR(tDelay)`);
/// a plain global pointer, a structure's pointer field and a program's pointer to a global start
/// there too.
#[test]
fn global_addresses_across_lists_fields_and_outputs() {
    let dir = tempfile::tempdir().unwrap();
    let main = dir.path().join("Main.st");
    std::fs::write(
        &main,
        "TYPE ST_Out : STRUCT Lamp01 : BOOL; Lamp02 : BOOL; END_STRUCT; END_TYPE
TYPE ST_Links : STRUCT p : POINTER TO BOOL; n : INT := 4; END_STRUCT; END_TYPE
FUNCTION_BLOCK FB_Sig
VAR_OUTPUT bOut : BOOL; END_VAR
bOut := TRUE;
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_Lamp
VAR_INPUT pLamp, pStop : POINTER TO BOOL; pTime : POINTER TO TIME; END_VAR
VAR_OUTPUT t : TIME; stop : BOOL; END_VAR
pLamp^ := TRUE;
stop := pStop^;
t := pTime^;
END_FUNCTION_BLOCK
VAR_GLOBAL
  fbLamp : FB_Lamp := (pLamp := ADR(GVL_Machine.HWOutput.Lamp02),
                       pStop := ADR(GVL_Sig.sig.bOut), pTime := ADR(tDelay));
  tDelay : TIME := T#1S;
  pDirect : POINTER TO BOOL := ADR(GVL_Machine.HWOutput.Lamp01);
  links : ST_Links := (p := ADR(GVL_Machine.HWOutput.Lamp01));
END_VAR
PROGRAM Main
VAR
  q : POINTER TO TIME := ADR(tDelay);
  t2 : TIME;
  b1, b2 : BOOL;
  n : INT;
END_VAR
GVL_Sig.sig();
fbLamp();
t2 := q^;
b1 := pDirect^;
b2 := links.p^;
n := links.n;
END_PROGRAM
",
    )
    .unwrap();
    let machine = dir.path().join("GVL_Machine.st");
    std::fs::write(
        &machine,
        "VAR_GLOBAL\n  HWOutput : ST_Out := (Lamp01 := TRUE);\nEND_VAR\n",
    )
    .unwrap();
    let sig = dir.path().join("GVL_Sig.st");
    std::fs::write(&sig, "VAR_GLOBAL\n  sig : FB_Sig;\nEND_VAR\n").unwrap();
    let (trace, stderr) = run_traced_files(
        &[&main, &machine, &sig],
        2,
        "GVL_Machine.HWOutput.Lamp02,fbLamp.stop,fbLamp.t,Main.t2,Main.b1,Main.b2,Main.n",
    );
    assert_eq!(
        column(&trace, "GVL_Machine.HWOutput.Lamp02"),
        [1.0, 1.0],
        "{stderr}"
    );
    assert_eq!(column(&trace, "fbLamp.stop"), [1.0, 1.0]);
    assert!(trace.contains(",T#1000ms,T#1000ms,1,1,4\n"), "{trace}");
    assert!(!stderr.contains("error"), "{stderr}");
}

/// An address inside a nested instance initializer (`o : FB_Outer := (inner := (pL := ADR(y)))`)
/// is kept, in a program and in a global list (before: silently dropped in both).
#[test]
fn a_nested_instance_initializer_keeps_its_address() {
    let src = "FUNCTION_BLOCK FB_Lamp
VAR_INPUT pL : POINTER TO BOOL; END_VAR
pL^ := TRUE;
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_Outer
VAR_INPUT inner : FB_Lamp; n : INT; END_VAR
inner();
END_FUNCTION_BLOCK
VAR_GLOBAL
  gx : BOOL;
  go : FB_Outer := (inner := (pL := ADR(gx)), n := 2);
END_VAR
PROGRAM Main
VAR
  y : BOOL;
  o : FB_Outer := (n := 1, inner := (pL := ADR(y)));
END_VAR
o();
go();
END_PROGRAM
";
    let (trace, stderr) = run_text("nested.st", src, 1, "Main.y,gx,Main.o.n,go.n");
    assert_eq!(column(&trace, "Main.y"), [1.0], "{stderr}");
    assert_eq!(column(&trace, "gx"), [1.0]);
    assert_eq!(column(&trace, "Main.o.n"), [1.0]);
    assert_eq!(column(&trace, "go.n"), [2.0]);
}

/// Where no address is taken the initial value is refused, one located E0305 each: a located
/// global, an unknown name. Before: silently NULL. (The elements of an array's initial value, in a
/// global list and in a program, were refused too until round 27, which starts them:
/// `misc_r27_run.rs`; none is reported here.)
#[test]
fn an_address_that_cannot_start_is_one_e0305() {
    assert_eq!(
        rejected_heads(
            "links.st",
            "TYPE ST_Links : STRUCT p : POINTER TO BOOL; END_STRUCT; END_TYPE
VAR_GLOBAL
  lamp AT %QX0.0 : BOOL;
  x : BOOL;
  pL : POINTER TO BOOL := ADR(lamp);
  arr : ARRAY[0..1] OF ST_Links := [(p := ADR(x)), (p := ADR(x))];
  l2 : ST_Links := (p := ADR(nosuch));
END_VAR
PROGRAM Main
VAR
  y : BOOL;
  arr2 : ARRAY[0..1] OF ST_Links := [(p := ADR(y)), (p := ADR(y))];
END_VAR
y := pL^;
END_PROGRAM
"
        ),
        [
            "links.st:5:27: error[E0305]: `pL` cannot start as `ADR(lamp)`: a located variable lives in the process image, which has no address",
            "links.st:7:26: error[E0305]: `l2.p` cannot start as `ADR(nosuch)`: `nosuch` is no global variable",
        ]
    );
}

/// A structure's field initialised with a structure of a type declared below it, in ST: the
/// later type's fields are known (before: E1025 "DAY_DATA has no field or input `DAY`"), also
/// as an array of it.
#[test]
fn a_field_initialised_with_a_type_declared_below_in_st() {
    let src = "TYPE CFG : STRUCT
  START : DAY_DATA := (DAY := 24, MONTH := 12);
  HOLIDAYS : ARRAY[1..2] OF DAY_DATA := [(DAY := 1, MONTH := 1), (DAY := 25, MONTH := 12)];
END_STRUCT; END_TYPE
TYPE DAY_DATA : STRUCT DAY : SINT; MONTH : SINT; END_STRUCT; END_TYPE
PROGRAM Main
VAR c : CFG; n, h : INT; END_VAR
n := SINT_TO_INT(c.START.DAY) * 100 + SINT_TO_INT(c.START.MONTH);
h := SINT_TO_INT(c.HOLIDAYS[2].DAY);
END_PROGRAM
";
    let (trace, stderr) = run_text("days.st", src, 1, "Main.n,Main.h");
    assert_eq!(column(&trace, "Main.n"), [2412.0], "{stderr}");
    assert_eq!(column(&trace, "Main.h"), [25.0]);
}

/// The PLCopen XML head and tail around `types` (data types and POUs) with one program PLC_PRG
/// in a task.
fn plcopen(types: &str) -> String {
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
      </configuration>
    </configurations>
  </instances>
</project>
"#
    )
}

/// OSCAT's export: a structure type's member initialised with a `structValue` of a type declared
/// later in `<dataTypes>` (before: E1025 at every member of the value).
#[test]
fn a_plcopen_member_initialised_with_a_type_declared_later() {
    let src = plcopen(
        r#"    <dataTypes>
      <dataType name="SETTINGS">
        <baseType><struct>
          <variable name="FIRST">
            <type><derived name="DATE_PARTS" /></type>
            <initialValue>
              <structValue>
                <value member="DD"><simpleValue value="31" /></value>
                <value member="MM"><simpleValue value="10" /></value>
              </structValue>
            </initialValue>
          </variable>
        </struct></baseType>
      </dataType>
      <dataType name="DATE_PARTS">
        <baseType><struct>
          <variable name="DD"><type><SINT /></type></variable>
          <variable name="MM"><type><SINT /></type></variable>
        </struct></baseType>
      </dataType>
    </dataTypes>
    <pous>
      <pou name="PLC_PRG" pouType="program">
        <interface>
          <localVars>
            <variable name="s"><type><derived name="SETTINGS" /></type></variable>
            <variable name="n"><type><INT /></type></variable>
          </localVars>
        </interface>
        <body>
          <ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := SINT_TO_INT(s.FIRST.DD) * 100 + SINT_TO_INT(s.FIRST.MM);</xhtml></ST>
        </body>
      </pou>
    </pous>"#,
    );
    let (trace, stderr) = run_text("settings.xml", &src, 1, "PLC_PRG.n");
    assert_eq!(column(&trace, "PLC_PRG.n"), [3110.0], "{stderr}");
}

/// CODESYS exports a declaration's constant expression as the `simpleValue` text, fully
/// parenthesised: `(BLOCK * 2)` over a constant of the POU, `((1024 * 1024) * 30)` (before:
/// E3011 "is not a literal or a constant name").
#[test]
fn a_plcopen_simple_value_that_is_a_constant_expression() {
    let src = plcopen(
        r#"    <dataTypes />
    <pous>
      <pou name="PLC_PRG" pouType="program">
        <interface>
          <localVars constant="true">
            <variable name="BLOCK">
              <type><UINT /></type>
              <initialValue><simpleValue value="64" /></initialValue>
            </variable>
            <variable name="TWO_BLOCKS">
              <type><UINT /></type>
              <initialValue><simpleValue value="(BLOCK * 2)" /></initialValue>
            </variable>
          </localVars>
          <localVars>
            <variable name="maxBytes">
              <type><UDINT /></type>
              <initialValue><simpleValue value="((1024 * 1024) * 30) - 1" /></initialValue>
            </variable>
            <variable name="n"><type><UDINT /></type></variable>
          </localVars>
        </interface>
        <body>
          <ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := maxBytes + TWO_BLOCKS;</xhtml></ST>
        </body>
      </pou>
    </pous>"#,
    );
    let (trace, stderr) = run_text("sizes.xml", &src, 1, "PLC_PRG.n");
    assert_eq!(column(&trace, "PLC_PRG.n"), [31_457_407.0], "{stderr}");
}

/// `x : UINT := (N * 2);` and `((1024 * 1024) * 30)` in ST: a parenthesised constant expression
/// (before: E0011 "unexpected `;`"); a parenthesised literal, and an instance's parameter list
/// `(PT := T#20MS)` beside them, are read as before.
#[test]
fn an_st_initial_value_in_parentheses() {
    let src = "PROGRAM Main
VAR CONSTANT
  N : UINT := 50;
  TWICE : UINT := (N * 2);
END_VAR
VAR
  big : UDINT := ((1024 * 1024) * 30);
  five : INT := (5);
  neg : INT := -(N * 2);
  tmr : TON := (PT := T#20MS);
  total : UDINT;
END_VAR
tmr(IN := TRUE);
total := big + TWICE + INT_TO_UDINT(five);
END_PROGRAM
";
    let (trace, stderr) = run_text("paren.st", src, 3, "Main.total,Main.neg,Main.tmr.Q");
    assert_eq!(column(&trace, "Main.total"), [31_457_385.0; 3], "{stderr}");
    assert_eq!(column(&trace, "Main.neg"), [-100.0; 3]);
    assert_eq!(column(&trace, "Main.tmr.Q"), [0.0, 0.0, 1.0]);
}

/// CODESYS V2.3 writes an array field's initial value without brackets inside a structure's
/// initializer too (cha1n3aw's PRMDATA_SAMPLE.EXP): `items := (a := 11, b := 12), (a := 13, b :=
/// 14)` is the array of the two (before: E0011 "unexpected `(`"); numbers so too.
#[test]
fn a_v23_bracketless_array_inside_a_structure_initializer() {
    let src = "TYPE Item_ts :
STRUCT
\ta : INT;
\tb : INT;
END_STRUCT
END_TYPE
TYPE Group_ts :
STRUCT
\tid : INT;
\titems : ARRAY [1..2] OF Item_ts;
\tcodes : ARRAY [0..2] OF INT;
END_STRUCT
END_TYPE
PROGRAM Cfg
VAR CONSTANT
\tgroups : ARRAY [1..2] OF Group_ts :=
\t\t(
\t\t\tid := 1,
\t\t\titems := (a := 11, b := 12), (a := 13, b := 14),
\t\t\tcodes := 7, 8, 9
\t\t),
\t\t(
\t\t\tid := 2,
\t\t\titems := (a := 21, b := 22), (a := 23, b := 24)
\t\t);
END_VAR
VAR
\ts, c : INT;
END_VAR
s := groups[2].items[2].b + groups[1].items[1].a + groups[2].id;
c := groups[1].codes[2];
END_PROGRAM
";
    let (trace, stderr) = run_text("groups.EXP", src, 1, "Cfg.s,Cfg.c");
    assert_eq!(column(&trace, "Cfg.s"), [37.0], "{stderr}");
    assert_eq!(column(&trace, "Cfg.c"), [9.0]);
}
