//! Round 28 of unseen projects (issue #13): declarations and initial values as CODESYS and
//! TwinCAT write them ("Variable Initialization": any ST expression, with constants, other
//! variables or functions), run end to end through `ladderc run`:
//! - a global initialised from another global (`rAlpha : REAL := GVL.rPi;`) or by a call given an
//!   array element (`n : UDINT := TO_UDINT(LIMIT(1, aPrio[2], 16));`): assigned once before the
//!   first cycle, in the order of the text, with W1433 (before: E1025, or E0011 at `[`);
//! - a field of a structured initial value that reads a variable (`(stCfg := gCfg, aSeq :=
//!   aLocal)`) or calls a function (`(uStamp := F_Pack(2020, 10))`, formal arguments too), or is
//!   `THIS^` (`(iParent := THIS^)`): the field is assigned when the instance is initialised, the
//!   other fields keep their constant values (before: E1025, E0011, or E0001 at `^`);
//! - a method's local pointer initialised from the block's pointer (`pCopy : POINTER TO INT :=
//!   pHead;`): assigned at each call (before: E0305);
//! - an implicit enumeration with its base type after the values (`e : (A := 1, B := 2) UDINT :=
//!   1;`, CODESYS; before: E0011);
//! - `SIZEOF(POINTER TO T)`, `SIZEOF(REFERENCE TO T)`: 8, a pointer of ladderc's 64-bit target
//!   (before: E0100 at `TO`);
//! - an enumeration's typed literal qualified by its namespace (`Plant.Valve#Open`, SIMATIC AX;
//!   before: E0100 and a cascading E0104);
//! - computed fields side by side, first or last among constant ones, each leave the declaration
//!   with their own comma (before: `(x := 6, y := a, z := b)` left `(x := 6, )`, an E0011);
//! - a global read by a global list's computed initial value is no W1410 note about ladderc's
//!   hidden `__FBINIT_ALL` program.

mod common;
use common::{check_text, column, run_text};

/// A global list's value read from another global of an earlier list, and one computed by a call
/// whose argument is an element of a global array: both are set before the first cycle.
#[test]
fn a_global_is_initialised_from_another_global_and_a_call() {
    let src = "VAR_GLOBAL
    gBase : REAL := 1.25;
    gLimits : ARRAY[1..3] OF INT := [5, 30, 12];
END_VAR
VAR_GLOBAL
    gTwice : REAL := gBase * 2.0;
    gLevel : UDINT := TO_UDINT(LIMIT(0, gLimits[3], 20));
END_VAR
PROGRAM Main
VAR
    r : REAL;
    n : UDINT;
END_VAR
r := gTwice;
n := gLevel;
END_PROGRAM
";
    let (trace, stderr) = run_text("globals.st", src, 1, "Main.r,Main.n");
    assert_eq!(column(&trace, "Main.r"), vec![2.5], "{stderr}");
    assert_eq!(column(&trace, "Main.n"), vec![12.0], "{stderr}");
    // one portability warning for the file's global lists
    assert_eq!(stderr.matches("W1433").count(), 1, "{stderr}");
}

/// An instance's structured initial value whose fields read a global structure and an array of
/// the program: the instance's inputs hold them at its first call; a constant field next to them
/// keeps its value.
#[test]
fn structured_initial_value_fields_read_variables() {
    let src = "TYPE ST_Limits :
STRUCT
    nLow : INT;
    nHigh : INT;
END_STRUCT
END_TYPE
VAR_GLOBAL
    gLimits : ST_Limits := (nLow := 3, nHigh := 40);
END_VAR
FUNCTION_BLOCK FB_Span
VAR_INPUT
    stLim : ST_Limits;
    aSteps : ARRAY[0..1] OF INT;
    nExtra : INT;
END_VAR
VAR_OUTPUT
    nSum : INT;
END_VAR
nSum := stLim.nHigh - stLim.nLow + aSteps[1] + nExtra;
END_FUNCTION_BLOCK
PROGRAM Main
VAR
    aOwn : ARRAY[0..1] OF INT := [100, 200];
    fbSpan : FB_Span := (stLim := gLimits, nExtra := 1000, aSteps := aOwn);
    n : INT;
END_VAR
fbSpan();
n := fbSpan.nSum;
END_PROGRAM
";
    let (trace, stderr) = run_text("fields.st", src, 1, "Main.n");
    assert_eq!(column(&trace, "Main.n"), vec![1237.0], "{stderr}");
}

/// Function calls inside a structured initial value, positional (with TRUE) and formal.
#[test]
fn structured_initial_value_fields_call_functions() {
    let src = "FUNCTION F_Stamp : UDINT
VAR_INPUT
    nMajor : UINT;
    nMinor : UINT;
END_VAR
F_Stamp := UINT_TO_UDINT(nMajor) * 100 + UINT_TO_UDINT(nMinor);
END_FUNCTION
FUNCTION F_Bits : WORD
VAR_INPUT
    a : BOOL;
    b : BOOL;
END_VAR
F_Bits := SEL(a, 0, 4) OR SEL(b, 0, 8);
END_FUNCTION
FUNCTION_BLOCK FB_Tag
VAR_INPUT
    uStamp : UDINT;
    uOther : UDINT;
    wBits : WORD;
END_VAR
END_FUNCTION_BLOCK
PROGRAM Main
VAR
    fbTag : FB_Tag := (uStamp := F_Stamp(3, 7), wBits := F_Bits(TRUE, FALSE),
                       uOther := F_Stamp(nMinor := 9, nMajor := 1));
    u : UDINT;
    o : UDINT;
    w : WORD;
END_VAR
u := fbTag.uStamp;
o := fbTag.uOther;
w := fbTag.wBits;
END_PROGRAM
";
    let (trace, stderr) = run_text("calls.st", src, 1, "Main.u,Main.o,Main.w");
    assert_eq!(column(&trace, "Main.u"), vec![307.0], "{stderr}");
    assert_eq!(column(&trace, "Main.o"), vec![109.0], "{stderr}");
    assert_eq!(column(&trace, "Main.w"), vec![4.0], "{stderr}");
}

/// `(iOwner := THIS^)`: the inner instance's interface input is the enclosing instance.
#[test]
fn this_in_a_structured_initial_value_is_the_instance() {
    let src = "INTERFACE I_Owner
METHOD Code : INT
END_METHOD
END_INTERFACE
FUNCTION_BLOCK FB_Part
VAR_INPUT
    iOwner : I_Owner;
END_VAR
VAR_OUTPUT
    nCode : INT;
END_VAR
IF iOwner <> 0 THEN
    nCode := iOwner.Code();
END_IF
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_Whole IMPLEMENTS I_Owner
VAR
    fbPart : FB_Part := (iOwner := THIS^);
END_VAR
VAR_OUTPUT
    nGot : INT;
END_VAR
fbPart();
nGot := fbPart.nCode;
METHOD Code : INT
Code := 77;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR
    fbW : FB_Whole;
    n : INT;
END_VAR
fbW();
n := fbW.nGot;
END_PROGRAM
";
    let (trace, stderr) = run_text("this.st", src, 1, "Main.n");
    assert_eq!(column(&trace, "Main.n"), vec![77.0], "{stderr}");
}

/// A method's local pointer starts as the block's pointer, at each call.
#[test]
fn a_method_pointer_is_initialised_from_the_block_pointer() {
    let src = "FUNCTION_BLOCK FB_Ring
VAR
    aVals : ARRAY[0..2] OF INT := [5, 6, 7];
    pCur : POINTER TO INT;
END_VAR
VAR_INPUT
    k : INT;
END_VAR
VAR_OUTPUT
    nRead : INT;
END_VAR
pCur := ADR(aVals[k]);
nRead := M_Read();
METHOD M_Read : INT
VAR
    pLocal : POINTER TO INT := pCur;
END_VAR
M_Read := pLocal^;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR
    fb : FB_Ring;
    n : INT;
    c : INT;
END_VAR
fb(k := c);
n := fb.nRead;
c := c + 1;
END_PROGRAM
";
    let (trace, stderr) = run_text("ptr.st", src, 3, "Main.n");
    assert_eq!(column(&trace, "Main.n"), vec![5.0, 6.0, 7.0], "{stderr}");
}

/// `eStep : (eWait := 1, eGo := 2) UDINT := 1;`: the implicit enumeration, its base type after
/// the values.
#[test]
fn an_implicit_enumeration_takes_a_base_type_after_its_values() {
    let src = "PROGRAM Main
VAR
    eStep : (eWait := 1, eGo := 2, eStop := 3) UDINT := 1;
    n : UDINT;
END_VAR
n := eStep;
IF eStep = eWait THEN
    eStep := eGo;
END_IF
END_PROGRAM
";
    let (trace, stderr) = run_text("enum.st", src, 2, "Main.n");
    assert_eq!(column(&trace, "Main.n"), vec![1.0, 2.0], "{stderr}");
}

/// `SIZEOF(POINTER TO T)` and `SIZEOF(REFERENCE TO T)`: the 8 bytes of an address.
#[test]
fn sizeof_takes_a_pointer_type() {
    let src = "PROGRAM Main
VAR
    a : UDINT;
    b : UDINT;
    c : UDINT;
END_VAR
a := SIZEOF(POINTER TO BYTE);
b := SIZEOF(POINTER TO STRING(40)) * 3;
c := SIZEOF(REFERENCE TO LREAL);
END_PROGRAM
";
    let (trace, stderr) = run_text("size.st", src, 1, "Main.a,Main.b,Main.c");
    assert_eq!(column(&trace, "Main.a"), vec![8.0], "{stderr}");
    assert_eq!(column(&trace, "Main.b"), vec![24.0], "{stderr}");
    assert_eq!(column(&trace, "Main.c"), vec![8.0], "{stderr}");
}

/// `Plant.Valve#Open`: the enumeration `Valve` of `NAMESPACE Plant`, its value `Open`.
#[test]
fn a_namespace_qualified_enumeration_literal_is_read() {
    let src = "NAMESPACE Plant
    TYPE Valve : (Closed, Opening, Open); END_TYPE
END_NAMESPACE
PROGRAM Main
VAR
    v : Plant.Valve;
    isOpen : BOOL;
    n : INT;
END_VAR
IF NOT isOpen THEN
    v := Plant.Valve#Open;
END_IF
isOpen := v = Plant.Valve#Open;
n := SEL(isOpen, 0, 1);
END_PROGRAM
";
    let (code, lines) = check_text("ax.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    let (trace, stderr) = run_text("ax.st", src, 1, "Main.n");
    assert_eq!(column(&trace, "Main.n"), vec![1.0], "{stderr}");
}

/// Computed fields side by side, first, last and between constant ones: each leaves with its own
/// comma (before: `(x := 6, y := a, z := b)` left `(x := 6, )`, an E0011 "unexpected `)`" that
/// hid a real project's other errors). s1 = (1, 2, 30, 40), s2 = (10, 1, 30, 2),
/// s3 = (1, 20, 2, 1), s4 = (10, 20, 1, 2), read as w*1000 + x*100 + y + z.
#[test]
fn computed_fields_side_by_side_keep_the_constant_ones() {
    let src = "TYPE ST4 : STRUCT
    w : INT;
    x : INT;
    y : INT;
    z : INT;
END_STRUCT;
END_TYPE

PROGRAM Main
VAR
    a : INT := 1;
    b : INT := 2;
    s1 : ST4 := (w := a, x := b, y := 30, z := 40);
    s2 : ST4 := (w := 10, x := a, y := 30, z := b);
    s3 : ST4 := (w := a, x := 20, y := b, z := a);
    s4 : ST4 := (w := 10, x := 20, y := a, z := b);
    n1, n2, n3, n4 : INT;
END_VAR
n1 := s1.w * 1000 + s1.x * 100 + s1.y + s1.z;
n2 := s2.w * 1000 + s2.x * 100 + s2.y + s2.z;
n3 := s3.w * 1000 + s3.x * 100 + s3.y + s3.z;
n4 := s4.w * 1000 + s4.x * 100 + s4.y + s4.z;
END_PROGRAM
";
    let (trace, stderr) = run_text("mix.st", src, 1, "Main.n1,Main.n2,Main.n3,Main.n4");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "Main.n1"), vec![1270.0], "{trace}");
    assert_eq!(column(&trace, "Main.n2"), vec![10132.0], "{trace}");
    assert_eq!(column(&trace, "Main.n3"), vec![3003.0], "{trace}");
    assert_eq!(column(&trace, "Main.n4"), vec![12003.0], "{trace}");
}

/// A global list's initial value reading another global (`b : INT := a + 1;`) is W1433 once, and
/// no W1410 note about a program named `__FBINIT_ALL` (the hidden program ladderc makes for
/// such values, in which the user cannot declare a VAR_EXTERNAL); b is 8.
#[test]
fn a_global_read_by_a_computed_initial_value_is_no_w1410() {
    let src = "CONFIGURATION Cfg
VAR_GLOBAL
  a : INT := 7;
  b : INT := a + 1;
END_VAR
RESOURCE Res ON PLC
  TASK T(INTERVAL := T#10ms, PRIORITY := 1);
  PROGRAM P WITH T : Main;
END_RESOURCE
END_CONFIGURATION

PROGRAM Main
VAR_EXTERNAL
  b : INT;
END_VAR
VAR
  n : INT;
END_VAR
n := b;
END_PROGRAM
";
    let (trace, stderr) = run_text("glob.st", src, 1, "P.n");
    assert!(!stderr.contains("__FBINIT"), "{stderr}");
    assert!(!stderr.contains("W1410"), "{stderr}");
    assert_eq!(column(&trace, "P.n"), vec![8.0], "{trace}");
}
