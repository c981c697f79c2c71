//! Round 28 (issue #13): the type of a variable given to a VAR_IN_OUT. ladderc passes an in-out by
//! address (IEC 61131-3 ed. 3, 6.6.1.2.2: the in-out's argument is a variable of the in-out's
//! type; CODESYS and TwinCAT refuse another type), so a variable of another size would let the C
//! write the wrong number of bytes:
//! - an elementary variable given to an in-out of another elementary type (an INT to a REAL, a
//!   WORD to a DWORD, a BOOL to a BYTE, an INT to an enumeration) is one E1012 at the argument, by
//!   name or by position, of a block, a function, a method and IL's `CAL` (before: compiled, the
//!   C wrote a REAL through a pointer to the two-byte INT, which read 0 after `r := r + 1.5`;
//!   widening pairs such as WORD to DWORD wrote four bytes over two);
//! - the uses IEC 61131-3 allows still run: a subrange and an alias given to an in-out of their
//!   integer type, an enumeration to an in-out of its own type, `ARRAY [*]`, an array of other
//!   bounds but the same size, a derived instance to an in-out of its base;
//! - an array of another size or a structure of another type (even of the same size) is E1012
//!   (unchanged: no conversion between them);
//! - a `VAR_IN_OUT CONSTANT` given a variable of another type too (a variable is passed by address);
//! - the same for a PLCopen XML block's in-out pin (FBD/LD box), said at the variable wired to it;
//! - a STRING[10] given to an in-out STRING (CODESYS and TwinCAT accept it; their manuals say the
//!   lengths "should" be equal): every string is stored with the runtime's whole capacity, so the
//!   callee never writes past the caller's variable, and after the call the variable is cut back
//!   to its own ten characters (before: it kept the callee's 50 characters);
//! - a `REF_TO INT` given `REF(real_var)` and a `REFERENCE TO LREAL` bound to an INT stay W1425
//!   (pointers convert in CODESYS and TwinCAT) and are safe: a write through them that would leave
//!   the variable is dropped and reported at the end of the run (run under AddressSanitizer).

mod common;
use common::{check_text, column, run_text};

/// A PLCopen XML FBD program: two instances of a block with `VAR_IN_OUT r : REAL`, the first's
/// box given the variable `i`, the second's `x` (a REAL).
const BOXES: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="box"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Acc" pouType="functionBlock">
      <interface><inOutVars><variable name="r"><type><REAL/></type></variable></inOutVars></interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">r := r + 1.5;</xhtml></ST></body>
    </pou>
    <pou name="Main" pouType="program">
      <interface><localVars>
        <variable name="i"><type><INT/></type></variable>
        <variable name="x"><type><REAL/></type></variable>
        <variable name="a"><type><derived name="Acc"/></type></variable>
        <variable name="b"><type><derived name="Acc"/></type></variable>
      </localVars></interface>
      <body><FBD>
        <inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>i</expression></inVariable>
        <block localId="2" typeName="Acc" instanceName="a"><position x="50" y="0"/>
          <inputVariables/>
          <inOutVariables><variable formalParameter="r"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/></variable></inOutVariables>
          <outputVariables/>
        </block>
        <inVariable localId="3"><position x="0" y="50"/><connectionPointOut/><expression>x</expression></inVariable>
        <block localId="4" typeName="Acc" instanceName="b"><position x="50" y="50"/>
          <inputVariables/>
          <inOutVariables><variable formalParameter="r"><connectionPointIn><connection refLocalId="3"/></connectionPointIn><connectionPointOut/></variable></inOutVariables>
          <outputVariables/>
        </block>
      </FBD></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#;

/// The repro of the sweep: an INT given to a block's and a method's `VAR_IN_OUT r : REAL` by
/// name (and to the method's by position). One E1012 each, at the argument, exit 1 (before:
/// compiled; the C wrote the REAL's four bytes over the two-byte INT).
#[test]
fn an_int_given_to_a_real_in_out_is_one_error_per_call() {
    let src = "FUNCTION_BLOCK FB
METHOD Bump
VAR_IN_OUT r : REAL; END_VAR
r := r + 1.5;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB2
VAR_IN_OUT r : REAL; END_VAR
r := r + 1.5;
END_FUNCTION_BLOCK
PROGRAM Main
VAR f : FB; g : FB2; i : INT := 2; j : INT := 2; x : REAL; END_VAR
f.Bump(r := i);
g(r := j);
f.Bump(r := x);
g(r := x);
f.Bump(j);
END_PROGRAM
";
    let (code, lines) = check_text("io.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        lines,
        vec![
            "io.st:13:13: error[E1012]: in-out Bump.r of FB is REAL, not INT (hint: an in-out \
             passes the variable itself, so its type must be REAL: declare it REAL, or copy it \
             through a variable of type REAL before and after the call)",
            "io.st:14:8: error[E1012]: in-out r of FB2 is REAL, not INT (hint: an in-out passes \
             the variable itself, so its type must be REAL: declare it REAL, or copy it through a \
             variable of type REAL before and after the call)",
            "io.st:17:8: error[E1012]: in-out Bump.r of FB is REAL, not INT (hint: an in-out \
             passes the variable itself, so its type must be REAL: declare it REAL, or copy it \
             through a variable of type REAL before and after the call)",
        ]
    );
}

/// A wider type is no excuse: a WORD given to a DWORD in-out and a BOOL to a BYTE in-out, by
/// name and by position, of a block and of a function (in a function, by position too), are one
/// E1012 each (before: the widening that inputs allow let them through, and the C wrote four
/// bytes over the WORD's two).
#[test]
fn a_narrower_variable_given_to_a_wider_in_out_is_an_error_by_name_and_by_position() {
    let src = "FUNCTION_BLOCK FB
VAR_IN_OUT a : DWORD; b : BYTE; END_VAR
a := 16#FFFFFFFF; b := 16#FF;
END_FUNCTION_BLOCK
FUNCTION Fill : INT
VAR_IN_OUT a : DWORD; END_VAR
a := 16#FFFFFFFF; Fill := 1;
END_FUNCTION
PROGRAM Main
VAR f : FB; w : WORD; x : BOOL; n : INT; END_VAR
f(a := w, b := x);
f(w, x);
n := Fill(a := w);
END_PROGRAM
";
    let (code, lines) = check_text("wide.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split(" (hint").next().unwrap())
        .collect();
    assert_eq!(
        heads,
        vec![
            "wide.st:11:8: error[E1012]: in-out a of FB is DWORD, not WORD",
            "wide.st:11:16: error[E1012]: in-out b of FB is BYTE, not BOOL",
            "wide.st:12:3: error[E1012]: in-out a of FB is DWORD, not WORD",
            "wide.st:12:6: error[E1012]: in-out b of FB is BYTE, not BOOL",
            "wide.st:13:16: error[E1012]: in-out a of Fill is DWORD, not WORD",
        ]
    );
}

/// IL: `CAL f(r := i)` of an INT to a REAL in-out, and a function called with the current result
/// (an INT) as its DINT in-out, are one E1012 each (before: compiled).
#[test]
fn il_cal_and_a_function_operator_check_their_in_outs() {
    let src = "FUNCTION_BLOCK FB
VAR_IN_OUT r : REAL; END_VAR
LD r
ADD 1.5
ST r
END_FUNCTION_BLOCK
FUNCTION Inc : DINT
VAR_IN_OUT d : DINT; END_VAR
LD d
ADD 1
ST d
ST Inc
END_FUNCTION
PROGRAM Main
VAR f : FB; i : INT; x : REAL; k : DINT; END_VAR
CAL f(r := i)
CAL f(r := x)
LD i
Inc
ST k
END_PROGRAM
";
    let (code, lines) = check_text("io.il", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split(" (hint").next().unwrap())
        .collect();
    assert_eq!(
        heads,
        vec![
            "io.il:16:12: error[E1012]: in-out r of FB is REAL, not INT",
            "io.il:19:1: error[E1012]: in-out d of Inc is DINT, not INT",
        ]
    );
}

/// An enumeration is stored as a DINT: an INT given to an in-out of the enumeration, or the
/// enumeration to an INT in-out, is E1012 (before: the C wrote four bytes over the INT's two);
/// the enumeration given to a DINT in-out passes (its number, W1439 as for values).
#[test]
fn an_enumeration_and_an_int_in_out_do_not_mix() {
    let src = "TYPE Color : (red, green, blue); END_TYPE
FUNCTION_BLOCK FB
VAR_IN_OUT a : Color; b : INT; c : DINT; END_VAR
a := blue;
END_FUNCTION_BLOCK
PROGRAM Main
VAR f : FB; x : INT; e : Color; d : DINT; END_VAR
f(a := x, b := e, c := e);
END_PROGRAM
";
    let (code, lines) = check_text("enum.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split(" (hint").next().unwrap())
        .filter(|l| l.contains("error["))
        .collect();
    assert_eq!(
        heads,
        vec![
            "enum.st:8:8: error[E1012]: in-out a of FB is Color, not INT",
            "enum.st:8:16: error[E1012]: in-out b of FB is INT, not Color",
        ]
    );
}

/// What IEC 61131-3 allows still runs (under AddressSanitizer): a subrange and an alias of INT
/// given to an INT in-out, an enumeration to an in-out of its own type, an array to `ARRAY [*]`
/// and to an in-out of other bounds but the same size, a derived instance to an in-out of its
/// base (the derived block's body runs).
#[test]
fn the_allowed_in_out_arguments_still_run() {
    let src = "TYPE Small : INT (0..100); END_TYPE
TYPE MyInt : INT; END_TYPE
TYPE Color : (red, green, blue); END_TYPE
FUNCTION_BLOCK FB_Base
VAR_OUTPUT n : INT; END_VAR
n := n + 1;
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_Derived EXTENDS FB_Base
n := n + 10;
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_Use
VAR_IN_OUT b : FB_Base; END_VAR
b();
END_FUNCTION_BLOCK
FUNCTION Bump : INT
VAR_IN_OUT v : INT; END_VAR
v := v + 1; Bump := v;
END_FUNCTION
FUNCTION SumAll : DINT
VAR_IN_OUT a : ARRAY[*] OF INT; END_VAR
VAR i : DINT; END_VAR
FOR i := LOWER_BOUND(a, 1) TO UPPER_BOUND(a, 1) DO SumAll := SumAll + a[i]; END_FOR
END_FUNCTION
FUNCTION Last : INT
VAR_IN_OUT a : ARRAY[0..2] OF INT; END_VAR
a[2] := a[2] + 100; Last := a[2];
END_FUNCTION
FUNCTION_BLOCK FB_Next
VAR_IN_OUT c : Color; END_VAR
IF c = blue THEN c := red; ELSE c := blue; END_IF
END_FUNCTION_BLOCK
PROGRAM Main
VAR s : Small := 5; m : MyInt := 10; d : FB_Derived; u : FB_Use;
  arr : ARRAY[1..3] OF INT := [1, 2, 3]; total : DINT; c : Color := green; nx : FB_Next;
  k : INT; END_VAR
k := Bump(v := s);
k := Bump(v := m);
total := SumAll(arr);
k := Last(a := arr);
u(b := d);
nx(c := c);
END_PROGRAM
";
    let (trace, _) = run_text(
        "allowed.st",
        src,
        2,
        "Main.s,Main.m,Main.total,Main.arr[3],Main.c,Main.d.n",
    );
    assert_eq!(column(&trace, "Main.s"), vec![6.0, 7.0]);
    assert_eq!(column(&trace, "Main.m"), vec![11.0, 12.0]);
    assert_eq!(column(&trace, "Main.total"), vec![6.0, 106.0]);
    assert_eq!(column(&trace, "Main.arr[3]"), vec![103.0, 203.0]);
    // green -> blue -> red (the enumeration's numbers 2, 0)
    assert_eq!(column(&trace, "Main.c"), vec![2.0, 0.0]);
    assert_eq!(column(&trace, "Main.d.n"), vec![10.0, 20.0]);
}

/// An array of another size (`ARRAY[0..3]` to an in-out `ARRAY[0..9]`: the callee would write
/// six elements past it) and a structure of another type of the same size are one E1012 each.
#[test]
fn an_array_of_another_size_or_another_structure_is_an_error() {
    let src =
        "TYPE S1 : STRUCT x : INT; y : INT; END_STRUCT; S2 : STRUCT p : DINT; END_STRUCT; END_TYPE
FUNCTION_BLOCK FB
VAR_IN_OUT a : ARRAY[0..9] OF INT; s : S1; END_VAR
VAR i : INT; END_VAR
FOR i := 0 TO 9 DO a[i] := i; END_FOR
s.x := 5;
END_FUNCTION_BLOCK
PROGRAM Main
VAR f : FB; small : ARRAY[0..3] OF INT; other : S2; END_VAR
f(a := small, s := other);
END_PROGRAM
";
    let (code, lines) = check_text("sizes.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split(" (hint").next().unwrap())
        .collect();
    assert_eq!(
        heads,
        vec![
            "sizes.st:10:8: error[E1012]: a of FB is ARRAY [0..9] OF INT, not ARRAY [0..3] OF INT",
            "sizes.st:10:20: error[E1012]: s of FB is S1, not S2",
        ]
    );
}

/// A STRING[10] given to a block's, a function's and a method's `VAR_IN_OUT s : STRING` whose
/// callee writes 50 characters: accepted (CODESYS, TwinCAT), run under AddressSanitizer, and the
/// variable holds its own ten characters after the call; the callee itself saw the 50 (before:
/// the STRING[10] variable held 50 characters).
#[test]
fn a_shorter_string_given_to_an_in_out_string_keeps_its_length() {
    let src = "FUNCTION_BLOCK FB
VAR_IN_OUT s : STRING; END_VAR
VAR_OUTPUT seen : INT; END_VAR
s := 'abcdefghijabcdefghijabcdefghijabcdefghijabcdefghij';
seen := LEN(s);
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_M
METHOD Put : INT
VAR_IN_OUT s : STRING; END_VAR
s := 'ABCDEFGHIJKLMNOPQRSTUVWXYZ';
Put := LEN(s);
END_METHOD
END_FUNCTION_BLOCK
FUNCTION Fill : INT
VAR_IN_OUT s : STRING[40]; END_VAR
s := '0123456789012345678901234567890123456789';
Fill := LEN(s);
END_FUNCTION
PROGRAM Main
VAR f : FB; g : FB_M; a : STRING[10]; b : STRING[10]; c : STRING[5]; wide : STRING[80];
  la, lb, lc, lw, seen, put, filled : INT; END_VAR
f(s := a);
seen := f.seen;
put := g.Put(s := b);
filled := Fill(s := c);
f(s := wide);
la := LEN(a); lb := LEN(b); lc := LEN(c); lw := LEN(wide);
END_PROGRAM
";
    let (trace, _) = run_text(
        "str.st",
        src,
        1,
        "Main.a,Main.b,Main.c,Main.la,Main.lb,Main.lc,Main.lw,Main.seen,Main.put,Main.filled",
    );
    let last = trace.lines().last().unwrap();
    assert!(
        last.contains("\"abcdefghij\",\"ABCDEFGHIJ\",\"01234\",10,10,5,50,50,26,40"),
        "{trace}"
    );
}

/// `REF_TO INT` given `REF(real_var)`, `REF_TO LREAL` given `REF(int_var)` and a `REFERENCE TO
/// LREAL` bound to an INT: W1425 (pointers convert in CODESYS and TwinCAT; IEC 61131-3 keeps
/// them typed), and safe: a write of an LREAL through them into the INT would leave the variable,
/// it is dropped and reported at the end of the run (AddressSanitizer finds nothing); the INT's
/// neighbours keep their values.
#[test]
fn a_reference_to_another_type_warns_and_never_writes_past_its_variable() {
    let src = "PROGRAM Main
VAR r : REAL := 1.5; i : INT := 1; j : INT := 2; k : INT := 3;
  p : REF_TO INT; w : REF_TO LREAL; q : REFERENCE TO LREAL; END_VAR
p := REF(r);
w := REF(i);
w^ := 1.0;
q REF= j;
q := 2.0;
END_PROGRAM
";
    let (code, lines) = check_text("refs.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(
        lines.len() == 1 && lines[0].starts_with("refs.st:4:1: warning[W1425]"),
        "{lines:?}"
    );
    let (trace, stderr) = run_text("refs.st", src, 1, "Main.i,Main.j,Main.k");
    assert_eq!(column(&trace, "Main.i"), vec![1.0]);
    assert_eq!(column(&trace, "Main.j"), vec![2.0]);
    assert_eq!(column(&trace, "Main.k"), vec![3.0]);
    assert!(
        stderr.contains("runtime: pointer outside its variable dereferenced"),
        "{stderr}"
    );
}

/// A PLCopen XML box: the INT `i` wired to the REAL in-out pin `r` is one E1012 at the variable's
/// element, naming the network (before: compiled); with `i` declared REAL both boxes run.
#[test]
fn a_box_in_out_pin_checks_the_type_of_its_variable() {
    let (code, lines) = check_text("box.xml", BOXES);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "box.xml:18:89: error[E1012]: in-out r of Acc is REAL, not INT [POU `Main`, network 1, localId 1]"
        ),
        "{lines:?}"
    );
    let fixed = BOXES.replace(
        "<variable name=\"i\"><type><INT/></type>",
        "<variable name=\"i\"><type><REAL/></type>",
    );
    let (trace, _) = run_text("box.xml", &fixed, 2, "Main.i,Main.x");
    assert_eq!(column(&trace, "Main.i"), vec![1.5, 3.0]);
    assert_eq!(column(&trace, "Main.x"), vec![1.5, 3.0]);
}

/// A `VAR_IN_OUT CONSTANT r : LREAL` given an INT variable: a variable is passed by address there
/// too (a literal or expression goes through a temporary), so it is E1012 as well (before:
/// compiled, the callee read eight bytes from the two-byte INT); the literal still runs.
#[test]
fn a_constant_in_out_takes_a_variable_of_its_type_or_a_value() {
    let src = "FUNCTION Twice : LREAL
VAR_IN_OUT CONSTANT r : LREAL; END_VAR
Twice := r * 2.0;
END_FUNCTION
PROGRAM Main
VAR i : INT := 3; y : LREAL; END_VAR
y := Twice(r := i);
END_PROGRAM
";
    let (code, lines) = check_text("ioc.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split(" (hint").next().unwrap())
        .collect();
    assert_eq!(
        heads,
        vec!["ioc.st:7:17: error[E1012]: in-out r of Twice is LREAL, not INT"]
    );
    let fixed = src.replace("Twice(r := i)", "Twice(r := 3.5)");
    let (trace, _) = run_text("ioc.st", &fixed, 1, "Main.y");
    assert_eq!(column(&trace, "Main.y"), vec![7.0]);
}
