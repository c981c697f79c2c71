//! CODESYS and TwinCAT forms of Structured Text found in unseen projects (issue #13, round 19:
//! trofimich/TwinCAT.OpenFramework's Core library, purushothaman2310/IEC61131-OOPS-TwiCAT), run end
//! to end through `ladderc run`:
//! - jump labels and `JMP name;` in ST (W1426 once per POU; before: E0106 "expected `:=` or `(`
//!   after `START`");
//! - `__TRY ... __CATCH(exc) ... __FINALLY ... __ENDTRY` (W1427: ladderc raises no exception, the
//!   catch never runs; before: three E0106/E0104 calling `__TRY` a variable), with
//!   `__SYSTEM.ExceptionCode` for the variable;
//! - a pointer or reference declared `:= 0` (CODESYS's null address; before: E0305);
//! - a method that calls itself: one E0106 that says so (before: "action ... calls itself");
//! - `SUPER^` as a value, and `THIS^` of an ABSTRACT block given to an interface (before: E0108,
//!   E0340).

mod common;
use common::{check_text, column, run_text};

/// A label before a statement and `JMP` back to it (a loop), `JMP` out of a FOR loop and over
/// statements: the values CODESYS gives; one W1426 per POU.
#[test]
fn jumps_and_labels_in_st_run_as_codesys_runs_them() {
    let src = "PROGRAM main
VAR i : INT; n : INT; k : INT; last : INT; skipped : INT; END_VAR
i := 0;
n := 0;
START:
i := i + 1;
n := n + i;
IF i < 3 THEN
    JMP START;
END_IF
FOR k := 1 TO 10 DO
    IF k = 4 THEN
        JMP done;
    END_IF;
END_FOR;
skipped := 99;
done:
last := k;
END_PROGRAM
";
    let (trace, stderr) = run_text("jumps.st", src, 2, "main.i,main.n,main.last,main.skipped");
    assert_eq!(column(&trace, "main.i"), [3.0, 3.0]);
    assert_eq!(column(&trace, "main.n"), [6.0, 6.0]);
    assert_eq!(column(&trace, "main.last"), [4.0, 4.0]);
    assert_eq!(column(&trace, "main.skipped"), [0.0, 0.0]);
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("warning[")).collect();
    assert_eq!(warnings.len(), 1, "{stderr}");
    assert!(
        warnings[0].contains("jumps.st:5:1: warning[W1426]: `main` jumps in Structured Text"),
        "{stderr}"
    );
}

/// A jump to a label the body lacks is IL's E1009 at the name, a label written twice E1010.
#[test]
fn a_missing_or_doubled_label_is_one_located_error() {
    let (code, lines) = check_text(
        "bad.st",
        "PROGRAM main\nVAR i : INT; END_VAR\nJMP nowhere;\ni := 1;\nhere:\ni := 2;\nhere:\ni := 3;\n\
         END_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 2, "{lines:?}");
    assert!(
        errors[0].starts_with("bad.st:3:5: error[E1009]: no label `nowhere` in `main`"),
        "{lines:?}"
    );
    assert!(
        errors[1].starts_with("bad.st:7:1: error[E1010]: label `here` is defined twice"),
        "{lines:?}"
    );
}

/// `__TRY` (TwinCAT): its statements run, then `__FINALLY`'s; `__CATCH`'s are checked and never
/// run (a division by zero gives 0 in ladderc); the exception variable is a
/// `__SYSTEM.ExceptionCode`.
#[test]
fn twincat_try_runs_its_statements_and_finally_never_the_catch() {
    let src = "PROGRAM main
VAR
    a : DINT := 10;
    b : DINT := 0;
    q : DINT;
    caught : INT;
    finished : INT;
    exc : __SYSTEM.ExceptionCode;
END_VAR
__TRY
    q := a / b;
    b := 5;
__CATCH(exc)
    caught := caught + 1;
__FINALLY
    finished := finished + 1;
__ENDTRY
END_PROGRAM
";
    let (trace, stderr) = run_text("try.st", src, 2, "main.q,main.b,main.caught,main.finished");
    assert_eq!(column(&trace, "main.q"), [0.0, 2.0]);
    assert_eq!(column(&trace, "main.caught"), [0.0, 0.0]);
    assert_eq!(column(&trace, "main.finished"), [1.0, 2.0]);
    assert!(stderr.contains("try.st:10:1: warning[W1427]"), "{stderr}");
    assert!(!stderr.contains("error["), "{stderr}");
    // the catch statements are checked: an error there is reported
    let (code, lines) = check_text(
        "try_bad.st",
        "PROGRAM main\nVAR q : INT; END_VAR\n__TRY\nq := 1;\n__CATCH(e)\nq := nosuch;\n__ENDTRY\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("try_bad.st:6:6: error[E1001]: undeclared name `nosuch`")),
        "{lines:?}"
    );
}

/// `p : POINTER TO INT := 0;` and an optional `REFERENCE TO` input `:= 0`: unbound, as NULL; a
/// call that leaves the reference out refers to nothing (not to the previous call's variable).
#[test]
fn a_pointer_or_reference_declared_zero_starts_unbound() {
    let src = "FUNCTION_BLOCK FB_Log
METHOD TryLog : BOOL
VAR_INPUT
    code : DINT;
    counter : REFERENCE TO ULINT := 0;
END_VAR
IF __ISVALIDREF(counter) THEN
    counter := counter + 1;
END_IF
TryLog := TRUE;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM main
VAR
    l : FB_Log;
    m : ULINT;
    ok : BOOL;
    p : POINTER TO INT := 0;
    q : POINTER TO INT := 16#0;
    unset : BOOL;
END_VAR
ok := l.TryLog(code := 2, counter := m);
(* left out, the reference refers to nothing: m is not counted again *)
ok := l.TryLog(code := 1);
unset := p = 0 AND q = 0;
END_PROGRAM
";
    let (trace, stderr) = run_text("zero.st", src, 2, "main.m,main.unset");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "main.m"), [1.0, 2.0]);
    assert_eq!(column(&trace, "main.unset"), [1.0, 1.0]);
}

/// A method calling itself is one E0106 that names the method and says why.
#[test]
fn a_recursive_method_is_one_error_that_names_the_method() {
    let (code, lines) = check_text(
        "rec.st",
        "FUNCTION_BLOCK FB_Count\nVAR_OUTPUT total : DINT; END_VAR\nMETHOD AddDown\n\
         VAR_INPUT n : DINT; END_VAR\nIF n <= 0 THEN\n    RETURN;\nEND_IF\n\
         total := total + n;\nAddDown(n - 1);\nEND_METHOD\nEND_FUNCTION_BLOCK\n\
         PROGRAM main\nVAR c : FB_Count; END_VAR\nc.AddDown(4);\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "rec.st:9:1: error[E0106]: method `AddDown` calls itself (directly or through another \
             method): ladderc does not compile recursive methods"
        ),
        "{lines:?}"
    );
}

/// `SUPER^` as a value (`itf := SUPER^;`, purushothaman2310/IEC61131-OOPS-TwiCAT; before: E0108
/// "in a POU that extends no function block"): the instance itself, an interface call through it
/// dispatching on the instance.
#[test]
fn super_as_a_value_is_the_instance_seen_as_its_base() {
    let src = "INTERFACE I_Get
METHOD Get : DINT
END_METHOD
END_INTERFACE
FUNCTION_BLOCK FB_Base IMPLEMENTS I_Get
VAR
    n : DINT := 7;
END_VAR
METHOD Get : DINT
Get := n;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_Derived EXTENDS FB_Base
METHOD Through : DINT
VAR
    itf : I_Get;
END_VAR
itf := SUPER^;
Through := itf.Get() + 100;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM main
VAR
    d : FB_Derived;
    r : DINT;
END_VAR
r := d.Through();
END_PROGRAM
";
    let (trace, stderr) = run_text("super_value.st", src, 1, "main.r");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "main.r"), [107.0]);
}

/// An ABSTRACT block giving `THIS^` to an interface its base implements (trofimich's
/// `_AutoDisposeRegistrar : AutoDisposeRegistrar(THIS^);` in `FUNCTION_BLOCK ABSTRACT Exception
/// EXTENDS Object`; before: E0340 "does not implement"): no instance is of the abstract block, and
/// the derived block's copy gives the derived instance, whose method the registrar calls.
#[test]
fn this_of_an_abstract_block_given_to_an_interface_is_the_derived_instance() {
    let src = "INTERFACE I_Obj
METHOD Id : DINT
END_METHOD
END_INTERFACE
FUNCTION_BLOCK Registrar
VAR
    count : DINT;
END_VAR
METHOD FB_init : BOOL
VAR_INPUT
    bInitRetains : BOOL;
    bInCopyCode : BOOL;
    obj : I_Obj;
END_VAR
IF obj <> 0 THEN
    count := obj.Id();
END_IF
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Base IMPLEMENTS I_Obj
METHOD Id : DINT
Id := 42;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK ABSTRACT Middle EXTENDS Base
VAR
    reg : Registrar(THIS^);
END_VAR
END_FUNCTION_BLOCK
FUNCTION_BLOCK Leaf EXTENDS Middle
METHOD Id : DINT
Id := 43;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM main
VAR
    d : Leaf;
    n : DINT;
END_VAR
d();
n := d.reg.count;
END_PROGRAM
";
    let (trace, stderr) = run_text("abstract.st", src, 1, "main.n");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "main.n"), [43.0]);
}

/// A method's value input that a call leaves out takes its initial value again (a method's
/// variables start again at each call: IEC 61131-3 ed. 3, 6.6.1.2; CODESYS, TwinCAT; before, it
/// kept the previous call's value), from outside the block, inside it, and on a program's method.
#[test]
fn a_method_input_left_out_takes_its_initial_value_at_each_call() {
    let src = "FUNCTION_BLOCK FB
METHOD M : INT
VAR_INPUT a : INT := 5; b : BOOL := TRUE; END_VAR
VAR k : INT := 3; END_VAR
k := k + 1;
M := a * 10 + k;
IF b THEN M := M + 1000; END_IF;
END_METHOD
METHOD Inner : INT
Inner := M(a := 2, b := FALSE) + M();
END_METHOD
END_FUNCTION_BLOCK
PROGRAM PRG
METHOD PM : INT
VAR_INPUT q : INT := 3; END_VAR
PM := q;
END_METHOD
END_PROGRAM
PROGRAM main
VAR f : FB; r1 : INT; r2 : INT; r3 : INT; r4 : INT; r5 : INT; END_VAR
r1 := f.M(a := 7);
r2 := f.M();
r3 := f.Inner();
r4 := PRG.PM(q := 9);
r5 := PRG.PM();
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "defaults.st",
        src,
        2,
        "main.r1,main.r2,main.r3,main.r4,main.r5",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    // no warning about the hidden defaults the calls pass (only W1413 for `PRG.PM`)
    assert!(!stderr.contains("__MD_"), "{stderr}");
    assert_eq!(column(&trace, "main.r1"), [1074.0, 1074.0]);
    assert_eq!(column(&trace, "main.r2"), [1054.0, 1054.0]);
    assert_eq!(column(&trace, "main.r3"), [24.0 + 1054.0, 24.0 + 1054.0]);
    assert_eq!(column(&trace, "main.r4"), [9.0, 9.0]);
    assert_eq!(column(&trace, "main.r5"), [3.0, 3.0]);
}
