//! Round 34 (issue #13), two false warnings found on real TwinCAT projects:
//! - W1001 ("this result is never used", IL hint "store it (ST x)") on an ST call statement of a
//!   FUNCTION, `Simulatie_invoer();`: CODESYS and TwinCAT run the function for its side effects and
//!   drop its result (normal ST); the warning now stays for IL, where an unused current result is a
//!   slip;
//! - W1411 (a write of the block's own input inside it) in FB_init, `THIS^.src := src;`: the
//!   documented TwinCAT/CODESYS way to give an instance its initial inputs (Beckhoff Infosys
//!   "Methods FB_init, FB_reinit and FB_exit"; CODESYS "Method: FB_Init, FB_Reinit, FB_Exit"),
//!   run once before the first call; other methods writing an input keep it.

mod common;

use common::{check_text, column, run_text};

/// A function with a side effect (its VAR_IN_OUT) called as ST statements, its result dropped,
/// each followed by an assignment of a literal.
const ST_CALLS: &str = "\
FUNCTION Step : BOOL
VAR_IN_OUT n : INT; END_VAR
n := n + 1;
Step := TRUE;
END_FUNCTION

FUNCTION Twice : INT
VAR_INPUT v : INT; END_VAR
Twice := v * 2;
END_FUNCTION

PROGRAM P
VAR c : INT; done : BOOL := TRUE; k : INT; END_VAR
Step(c);
done := FALSE;
Twice(v := 3);
k := 7;
Step(n := c);
IF c > 4 THEN
    k := Twice(c);
END_IF
END_PROGRAM
";

/// `Step(c);` and `Twice(v := 3);` are ST call statements whose result is dropped: no warning.
/// Before round 34: W1001 at each call, "replaced here before any use" on the literal of the next
/// statement (`FALSE`, `7`), with the IL hint "store it (ST x)".
#[test]
fn st_function_call_statement_gives_no_w1001() {
    let (code, lines) = check_text("calls.st", ST_CALLS);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(lines.is_empty(), "{lines:?}");
}

/// The same program runs the calls each cycle: `c` counts 2 a cycle (two calls of `Step`), `done`
/// is FALSE from the first cycle, `k` is 7, then `Twice(c)` once `c > 4`.
#[test]
fn st_function_call_statement_runs_its_side_effects() {
    let (trace, stderr) = run_text("calls.st", ST_CALLS, 4, "P.c,P.done,P.k");
    assert!(!stderr.contains("W1001"), "{stderr}");
    assert_eq!(column(&trace, "P.c"), vec![2.0, 4.0, 6.0, 8.0]);
    assert_eq!(column(&trace, "P.done"), vec![0.0; 4]);
    assert_eq!(column(&trace, "P.k"), vec![7.0, 7.0, 12.0, 16.0]);
}

/// In IL a result computed and replaced before any use is still W1001, at the instruction that
/// computed it (unchanged by round 34).
#[test]
fn il_unused_result_keeps_w1001() {
    let src = "\
PROGRAM P
VAR x : INT; END_VAR
    LD 1
    ADD 2
    LD 3
    ST x
END_PROGRAM
";
    let (code, lines) = check_text("unused.il", src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("unused.il:4:5: warning[W1001]") && lines[0].contains("never used"),
        "{lines:?}"
    );
}

/// A block whose FB_init stores its extra input into the block's own input, and a method that
/// writes the same input at run time.
const FB_INIT: &str = "\
FUNCTION_BLOCK FB_Use
VAR_INPUT
    src : INT;
END_VAR
VAR_OUTPUT
    y : INT;
END_VAR
y := src * 2;
METHOD FB_init : BOOL
VAR_INPUT
    bInitRetains : BOOL;
    bInCopyCode : BOOL;
    src : INT;
END_VAR
THIS^.src := src;
END_METHOD
METHOD FB_reinit : BOOL
THIS^.src := 0;
END_METHOD
END_FUNCTION_BLOCK

PROGRAM P
VAR
    u : FB_Use(src := 21);
    r : INT;
END_VAR
u();
r := u.y;
END_PROGRAM
";

/// FB_init (and FB_reinit) writing the block's own input: no W1411 (before round 34: W1411 at
/// `THIS^.src := src;`), and the instance starts with the declaration's argument (r = 42).
#[test]
fn fb_init_writing_own_input_gives_no_w1411_and_runs() {
    let (code, lines) = check_text("init.st", FB_INIT);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(!lines.iter().any(|l| l.contains("W1411")), "{lines:?}");
    let (trace, stderr) = run_text("init.st", FB_INIT, 2, "P.r,P.u.src");
    assert!(!stderr.contains("W1411"), "{stderr}");
    assert_eq!(column(&trace, "P.r"), vec![42.0, 42.0]);
    assert_eq!(column(&trace, "P.u.src"), vec![21.0, 21.0]);
}

/// A method other than FB_init writing the block's input keeps its W1411, at the write, once;
/// the write takes effect (the block's own copy).
#[test]
fn other_method_writing_own_input_keeps_w1411() {
    let src = FB_INIT
        .replace(
            "END_FUNCTION_BLOCK",
            "METHOD SetSrc\nVAR_INPUT v : INT; END_VAR\nsrc := v;\nEND_METHOD\nEND_FUNCTION_BLOCK",
        )
        .replace("u();\n", "u();\nu.SetSrc(v := 5);\n");
    let (code, lines) = check_text("other.st", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    let w: Vec<_> = lines.iter().filter(|l| l.contains("W1411")).collect();
    assert_eq!(w.len(), 1, "{lines:?}");
    assert!(
        w[0].starts_with("other.st:22:1: warning[W1411]") && w[0].contains("`src` is an input"),
        "{lines:?}"
    );
    let (trace, _) = run_text("other.st", &src, 3, "P.r");
    // cycle 1 runs with 21 (then SetSrc writes 5), the next ones with 5
    assert_eq!(column(&trace, "P.r"), vec![42.0, 10.0, 10.0]);
}
