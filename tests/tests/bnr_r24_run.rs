//! Round 24 of unseen projects (issue #13), B&R Automation Studio's everyday idioms, run end to end
//! through `ladderc run` / `ladderc check`:
//! - `ADR('text')` / `ADR("text")` of a string literal is the address of a hidden copy of the
//!   literal that lives for the whole run, bounded as every pointer (before: E0305, the one error
//!   of five B&R projects, hiding all their others); a write through it never changes the
//!   literal's next use.

mod common;
use common::{column, run_text};

/// `MEMCPY(ADR(buf), ADR('abc'), 5)` copies the literal (its 2-byte length and 3 characters), a
/// function reads the literal's first character through a `POINTER TO BYTE` and its length through
/// a `POINTER TO STRING`, a FUNCTION keeps the address of its own literals and a FUNCTION_BLOCK's
/// method stores one in the instance for later cycles. A write through `p := ADR('hello')` changes
/// what `p^` reads, but the next cycle's `ADR('hello')` gives `'hello'` again.
#[test]
fn the_address_of_a_string_literal_reads_the_literal() {
    let src = "FUNCTION FirstCode : INT
VAR_INPUT
  p : POINTER TO BYTE;
END_VAR
(* ladderc's STRING: a 2-byte length, then the characters *)
FirstCode := BYTE_TO_INT(p[2]);
END_FUNCTION

FUNCTION TextLen : INT
VAR_INPUT
  ps : POINTER TO STRING;
END_VAR
TextLen := LEN(ps^);
END_FUNCTION

FUNCTION Greeting : INT
VAR
  p : POINTER TO STRING;
  w : POINTER TO WSTRING;
END_VAR
p := ADR('greetings');
w := ADR(\"wide\");
Greeting := LEN(p^) * 10 + LEN(w^);
END_FUNCTION

FUNCTION_BLOCK Keeper
VAR_OUTPUT
  size : INT;
END_VAR
VAR
  p : POINTER TO STRING;
END_VAR
METHOD Keep
p := ADR('kept pointer');
END_METHOD
IF p = 0 THEN
  THIS^.Keep();
END_IF
size := LEN(p^);
END_FUNCTION_BLOCK

PROGRAM Main
VAR
  buf : STRING[10];
  p : POINTER TO STRING;
  copied, first, before, after, wlen, greet : INT;
  k : Keeper;
END_VAR
MEMCPY(ADR(buf), ADR('abc'), 5);
copied := LEN(buf);
first := FirstCode(ADR('A'));
p := ADR('hello');
before := LEN(p^);
p^ := 'hi';
after := LEN(p^);
wlen := TextLen(ADR('four'));
greet := Greeting();
k();
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "literals.st",
        src,
        3,
        "Main.copied,Main.first,Main.before,Main.after,Main.wlen,Main.greet,Main.k.size",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "Main.copied"), vec![3.0; 3], "{trace}");
    assert_eq!(column(&trace, "Main.first"), vec![65.0; 3], "{trace}");
    // each cycle `ADR('hello')` is 'hello' again, although the cycle before wrote 'hi' through it
    assert_eq!(column(&trace, "Main.before"), vec![5.0; 3], "{trace}");
    assert_eq!(column(&trace, "Main.after"), vec![2.0; 3], "{trace}");
    assert_eq!(column(&trace, "Main.wlen"), vec![4.0; 3], "{trace}");
    assert_eq!(column(&trace, "Main.greet"), vec![94.0; 3], "{trace}");
    // the pointer the method stored in cycle 0 still reads the literal in the later cycles
    assert_eq!(column(&trace, "Main.k.size"), vec![12.0; 3], "{trace}");
}
