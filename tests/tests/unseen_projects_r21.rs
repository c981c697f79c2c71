//! Round 21 of unseen projects (issue #13): forms that real programs use, run end to end through
//! `ladderc run`:
//! - a literal beside a subrange value in an operation (`n * 5`, `m + 10`, `n > 7` with `n :
//!   UINT(1..4)`) is a value of the subrange's base type, as IEC 61131-3 types the operation (before:
//!   a false E1017 "literal 5 does not fit UINT (1..4)"); a result stored back into the subrange
//!   that falls outside it is saturated to the nearer bound with the runtime's range flag;
//! - CODESYS's and TwinCAT's `TIME()`, the time since the controller started (before: E1019
//!   "unknown function `TIME`"): the scan clock, as the timers read it;
//! - a data type with named values whose values are constant expressions of the values before
//!   them (IEC 61131-3 ed. 3, Table 11's own `White := Red OR Green OR Blue`; KrystianOlszowy's
//!   test.st; before: E0011 "unexpected `Red`, expected a number").

mod common;
use common::{rejected_heads, run_text};

/// Operations on a subrange value take its base type: the literals beside it are not checked
/// against the range, the results are exact, and a result stored back into the subrange that
/// leaves it is saturated (the range flag reported), while a literal stored straight into it is
/// still checked (E1017).
#[test]
fn a_literal_beside_a_subrange_value_takes_the_base_type() {
    let src = "TYPE TIdx : UINT(1..4); END_TYPE
PROGRAM Main
VAR
  n : UINT(1..4) := 2;
  m : TIdx := 3;
  k : UINT;
  h : UINT;
  b : BOOL;
  j : INT(-5..5);
  s : UINT(1..4) := 1;
  lo : INT(-5..5) := 0;
END_VAR
k := n * 5;
h := 10 + m;
b := n > 7 OR m < 0;
j := MAX(j, 3) - 7;
n := n + 1;
IF n >= 4 THEN n := 1; END_IF;
s := s * 3;
lo := lo - 4;
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "sub.st",
        src,
        3,
        "Main.n,Main.k,Main.h,Main.b,Main.j,Main.s,Main.lo",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.n,Main.k,Main.h,Main.b,Main.j,Main.s,Main.lo\n\
         0,0,3,10,13,0,-4,3,-4\n\
         1,10,1,15,13,0,-4,4,-5\n\
         2,20,2,5,13,0,-4,4,-5\n"
    );
    // s := 3 * 3 = 9 and lo := -4 - 4 = -8 leave their ranges: saturated to 4 and -5, reported
    assert!(
        stderr.contains("runtime: conversion out of range or value outside a subrange (saturated)"),
        "{stderr}"
    );
    let heads = rejected_heads(
        "direct.st",
        "PROGRAM Main\nVAR\n  n : UINT(1..4);\nEND_VAR\nn := 5;\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        ["direct.st:5:6: error[E1017]: literal 5 does not fit UINT (1..4)"]
    );
}

/// `TIME()` is the scan clock: an elapsed time measured with it counts the 10 ms scans, in a
/// PROGRAM and in a FUNCTION; given an input it is one E1020 that says to call it without.
#[test]
fn time_without_inputs_is_the_scan_clock() {
    let src = "FUNCTION Since : TIME
VAR_INPUT t0 : TIME; END_VAR
Since := TIME() - t0;
END_FUNCTION
PROGRAM Main
VAR
  t0 : TIME;
  el : TIME;
  f : TIME;
  started : BOOL;
END_VAR
IF NOT started THEN t0 := TIME(); started := TRUE; END_IF;
el := TIME() - t0;
f := Since(t0 := T#5ms);
END_PROGRAM
";
    let (trace, _) = run_text("clock.st", src, 4, "Main.el,Main.f");
    assert_eq!(
        trace,
        "cycle,time_ms,Main.el,Main.f\n0,0,T#0ms,T#-5ms\n1,10,T#10ms,T#5ms\n2,20,T#20ms,T#15ms\n3,30,T#30ms,T#25ms\n"
    );
    let heads = rejected_heads(
        "arg.st",
        "PROGRAM Main\nVAR t : TIME; END_VAR\nt := TIME(T#1s);\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        ["arg.st:3:6: error[E1020]: TIME takes 0 inputs, 1 given"]
    );
}

/// The standard's own example of named values given by expressions: `White` is the OR of the three
/// colours, `Black` their AND, `Cyan` an XOR; the values are numbered as computed, and a value that
/// names something that is no constant is one E0022.
#[test]
fn named_values_may_be_expressions_of_the_values_before() {
    let src = "TYPE Colors : DWORD (Red := 16#00FF0000, Green := 16#0000FF00, Blue := 16#000000FF,
    White := Red OR Green OR Blue, Black := Red AND Green AND Blue, Cyan := White XOR Red,
    Next) := Green;
END_TYPE
PROGRAM Main
VAR
  c : Colors := Colors#White;
  k : Colors;
  white : DINT;
  black : DINT;
  cyan : DINT;
  next : DINT;
  green : BOOL;
END_VAR
white := TO_DINT(c);
black := TO_DINT(Colors#Black);
cyan := TO_DINT(Colors#Cyan);
next := TO_DINT(Colors#Next);
green := k = Colors#Green;
END_PROGRAM
";
    let (trace, _) = run_text(
        "colors.st",
        src,
        1,
        "Main.white,Main.black,Main.cyan,Main.next,Main.green",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.white,Main.black,Main.cyan,Main.next,Main.green\n0,0,16777215,0,65535,65536,1\n"
    );
    let heads = rejected_heads(
        "bad.st",
        "TYPE T : INT (A := 1, B := A OR x) := A;\nEND_TYPE\nPROGRAM Main\nVAR v : T; END_VAR\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        ["bad.st:1:28: error[E0022]: constant expression `A OR x`: `x` is not an integer constant declared before"]
    );
}
