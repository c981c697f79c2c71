//! Round 33: instances, interfaces and in-outs (issue #13).
//!
//! - an ANY input of a FUNCTION_BLOCK (`Arg : ANY;`, Beckhoff Infosys "ANY and `ANY_<type>`":
//!   inputs of type ANY in functions, methods and, from TwinCAT 3.1 build 4026, function blocks;
//!   CODESYS "Data Type: ANY" likewise) has `Arg.diSize`, `Arg.TypeClass` and `Arg.pValue` as a
//!   function's has; the address is given for the call only and is NULL after it (before: E1003
//!   unknown type `ANY`, and E1068 where a METHOD passed its own ANY input on to it;
//!   AAG_TF6281_Explicit_Messaging);
//! - a located variable given to a FUNCTION_BLOCK's VAR_IN_OUT (IEC 61131-3 ed. 3, 6.5.5: a
//!   directly represented variable is a variable; 6.6.1.2.2: a VAR_IN_OUT takes a variable) is
//!   copied in before the call and the block's writes back into the process image when it
//!   returns (before: E2005 "this argument for an IN_OUT parameter"; MECTsrl/mect_apps' form).

mod common;
use common::{column, run_text};

/// A block that describes what its ANY input was given, and a block whose METHOD passes its own
/// ANY input on to such a block.
const ANY_INPUT_OF_A_BLOCK: &str = "FUNCTION_BLOCK FB_Probe
VAR_INPUT
  Arg : ANY;
END_VAR
VAR_OUTPUT
  size : DINT;
  class : INT;
  b0, b1, b2 : BYTE;
END_VAR
size := Arg.diSize;
IF Arg.TypeClass = __SYSTEM.TYPE_CLASS.TYPE_INT THEN
  class := 1;
ELSIF Arg.TypeClass = __SYSTEM.TYPE_CLASS.TYPE_REAL THEN
  class := 2;
ELSIF Arg.TypeClass = __SYSTEM.TYPE_CLASS.TYPE_STRING THEN
  class := 3;
ELSE
  class := 0;
END_IF
b0 := Arg.pValue[0];
b1 := Arg.pValue[1];
b2 := Arg.pValue[2];
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB_Client
VAR
  probe : FB_Probe;
END_VAR
METHOD Measure : DINT
VAR_INPUT
  Sym : ANY;
END_VAR
probe(Arg := Sym);
Measure := probe.size * 10 + probe.class;
END_METHOD
END_FUNCTION_BLOCK

PROGRAM main
VAR
  probe : FB_Probe;
  client : FB_Client;
  i : INT := 258;
  r : REAL := 1.0;
  s : STRING := 'Hi';
  intSize, realSize, strSize, viaMethod, viaMethodStr, tempSize : DINT;
  intClass, realClass, strClass : INT;
  i0, i1, s0, s2, afterB0 : BYTE;
  afterSize : DINT;
END_VAR
VAR_TEMP
  t : LINT;
END_VAR
probe(Arg := i);
intSize := probe.size; intClass := probe.class; i0 := probe.b0; i1 := probe.b1;
probe(Arg := r);
realSize := probe.size; realClass := probe.class;
probe(Arg := s);
strSize := probe.size; strClass := probe.class; s0 := probe.b0; s2 := probe.b2;
probe();
afterSize := probe.size; afterB0 := probe.b0;
viaMethod := client.Measure(Sym := i);
viaMethodStr := client.Measure(Sym := s);
t := 5;
probe(Arg := t);
tempSize := probe.size;
i := i + 1;
END_PROGRAM
";

/// An FB's ANY input read through `.diSize`, `.TypeClass` and `.pValue` for an INT (258, then
/// 259: its bytes 2|1, then 3|1), a REAL and a STRING (ladderc's `IEC_STRING`, 258 bytes: the
/// 2-byte length, then 'H' = 72), a VAR_TEMP (LINT, 8 bytes), and through a METHOD that passes its
/// own ANY input on (size * 10 + class: 21 for the INT, 2583 for the STRING). A call that does not
/// give the input keeps the last size (as any input) but its `.pValue` is NULL (read 0, reported
/// at the end of the run). Before: E1003 unknown type `ANY` at the input, E1068 at the method's
/// call.
#[test]
fn any_input_of_a_function_block_describes_its_argument() {
    let watch = "main.intSize,main.intClass,main.i0,main.i1,main.realSize,main.realClass,\
                 main.strSize,main.strClass,main.s0,main.s2,main.afterSize,main.afterB0,\
                 main.viaMethod,main.viaMethodStr,main.tempSize";
    let (trace, stderr) = run_text("probe.st", ANY_INPUT_OF_A_BLOCK, 2, watch);
    let col = |n: &str| column(&trace, n);
    assert_eq!(col("main.intSize"), [2.0, 2.0], "{trace}");
    assert_eq!(col("main.intClass"), [1.0, 1.0], "{trace}");
    assert_eq!(col("main.i0"), [2.0, 3.0], "{trace}");
    assert_eq!(col("main.i1"), [1.0, 1.0], "{trace}");
    assert_eq!(col("main.realSize"), [4.0, 4.0], "{trace}");
    assert_eq!(col("main.realClass"), [2.0, 2.0], "{trace}");
    assert_eq!(col("main.strSize"), [258.0, 258.0], "{trace}");
    assert_eq!(col("main.strClass"), [3.0, 3.0], "{trace}");
    assert_eq!(col("main.s0"), [2.0, 2.0], "{trace}");
    assert_eq!(col("main.s2"), [72.0, 72.0], "{trace}");
    assert_eq!(col("main.afterSize"), [258.0, 258.0], "{trace}");
    assert_eq!(col("main.afterB0"), [0.0, 0.0], "{trace}");
    assert_eq!(col("main.viaMethod"), [21.0, 21.0], "{trace}");
    assert_eq!(col("main.viaMethodStr"), [2583.0, 2583.0], "{trace}");
    assert_eq!(col("main.tempSize"), [8.0, 8.0], "{trace}");
    assert!(
        stderr.contains("NULL reference dereferenced (first: Arg.pValue[0] in FB_Probe"),
        "{stderr}"
    );
}

/// A bit (`%QX4.3`) and a word (`%MW10`) of the process image given to a block's VAR_IN_OUTs:
/// the block's writes are in the process image when the call returns, in the same scan (the
/// count 1, 2, 3; the lamp toggling). Before: E2005 "the C backend does not support this
/// argument for an IN_OUT parameter".
#[test]
fn located_variables_given_to_a_blocks_in_outs_are_written_back() {
    let src = "VAR_GLOBAL
    lamp AT %QX4.3 : BOOL;
    count AT %MW10 : INT;
END_VAR
FUNCTION_BLOCK FB_Step
VAR_IN_OUT
    flag : BOOL;
    n : INT;
END_VAR
    n := n + 1;
    flag := NOT flag;
END_FUNCTION_BLOCK
PROGRAM Main
VAR
    step : FB_Step;
    seenCount : INT;
    seenLamp : BOOL;
END_VAR
    step(flag := lamp, n := count);
    seenCount := count;
    seenLamp := lamp;
END_PROGRAM
";
    let (trace, _) = run_text(
        "located.st",
        src,
        3,
        "Main.seenCount,Main.seenLamp,count,lamp",
    );
    assert_eq!(column(&trace, "Main.seenCount"), [1.0, 2.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "count"), [1.0, 2.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "Main.seenLamp"), [1.0, 0.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "lamp"), [1.0, 0.0, 1.0], "{trace}");
}
