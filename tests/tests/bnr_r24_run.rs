//! Round 24 of unseen projects (issue #13), B&R Automation Studio's everyday idioms, run end to end
//! through `ladderc run` / `ladderc check`:
//! - `ADR('text')` / `ADR("text")` of a string literal is the address of a hidden copy of the
//!   literal that lives for the whole run, bounded as every pointer (before: E0305, the one error
//!   of five B&R projects, hiding all their others); a write through it never changes the
//!   literal's next use.
//! - a B&R block declared in a `.fun` file and implemented in a `.st` file calls the FB members of
//!   its variables (`ax.Delay(...)`, `ax` a VAR_IN_OUT of a structure holding a TON) (before:
//!   E1032 "`ax` is neither a variable nor a library", which also hid the E1003 of a member type
//!   no file declares).
//! - an ST body whose `IF` / `ELSIF` / `WHILE` conditions continue on lines starting with
//!   `AND (` is ST (before: enough such lines made it "instruction list" (W0303), then a cascade of
//!   IL errors, 78 per B&R library).
//! - B&R's preprocessor lines `#define`, `#ifdef`, `#ifndef`, `#else`, `#endif` compile the branch
//!   whose name is (not) defined (before: E0023 "this file is Siemens SCL", the rest of the file
//!   not compiled); `#include` / `#if` are one located E1058.
//! - a B&R program folder (`IEC.prg`) whose code is not among the inputs (written in B&R's LD):
//!   its own `.var` / `.typ` declarations are not compiled, one note W0022 (before: read as global,
//!   two such programs' `Variables.var` were E1002 duplicates).

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

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

/// The structure type in a `.typ`, the block's declaration in a `.fun` (a VAR_IN_OUT and a VAR of
/// it), its body in a `.st`: `loc.Delay(...)` and `ax.Delay(...)` run the TON members. The 50 ms
/// delay is done after its fifth 10 ms cycle, the 20 ms one after two more; `Done` is written
/// through the VAR_IN_OUT into the program's variable. A member type no file declares is then
/// named where it is (E1003), not hidden behind an E1032 of the body.
#[test]
fn a_split_block_calls_the_fb_members_of_its_variables() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_in(
        d,
        "Ax.typ",
        "TYPE\n  Axis_typ : STRUCT\n    Delay : TON;\n    Done : BOOL;\n  END_STRUCT;\nEND_TYPE\n",
    );
    write_in(
        d,
        "Ax.fun",
        "FUNCTION_BLOCK AxFB\n  VAR_IN_OUT\n    ax : Axis_typ;\n  END_VAR\n  VAR\n    loc : Axis_typ;\n  END_VAR\nEND_FUNCTION_BLOCK\n",
    );
    write_in(
        d,
        "AxFB.st",
        "FUNCTION_BLOCK AxFB\n  loc.Delay(IN := TRUE, PT := T#50ms);\n  ax.Delay(IN := loc.Delay.Q, PT := T#20ms);\n  ax.Done := ax.Delay.Q;\nEND_FUNCTION_BLOCK\n",
    );
    write_in(
        d,
        "Main.st",
        "PROGRAM Main\nVAR\n  a : Axis_typ;\n  f : AxFB;\nEND_VAR\nf(ax := a);\nEND_PROGRAM\n",
    );
    let files = ["Ax.typ", "Ax.fun", "AxFB.st", "Main.st"];
    let mut args = vec!["run"];
    args.extend(files);
    args.extend([
        "--cycles",
        "10",
        "--trace",
        "-",
        "--watch",
        "Main.a.Done,Main.a.Delay.ET",
    ]);
    let (code, trace, stderr) = in_dir(d, &args);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("E1032"), "{stderr}");
    let done = column(&trace, "Main.a.Done");
    let first = done.iter().position(|&v| v == 1.0);
    // loc.Delay.Q from cycle 5 (ET 50 ms), ax.Delay.Q two 10 ms cycles later (cycle 7)
    assert_eq!(first, Some(7), "{trace}");
    // a member type of another library: its E1003, at the member, is what is reported
    write_in(
        d,
        "Ax.typ",
        "TYPE\n  Axis_typ : STRUCT\n    Delay : TON;\n    Done : BOOL;\n    Pid : LCRTempPID;\n  END_STRUCT;\nEND_TYPE\n",
    );
    let mut args = vec!["check"];
    args.extend(files);
    let (code, _, stderr) = in_dir(d, &args);
    assert_eq!(code, Some(1), "{stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].starts_with("Ax.typ:5:11: error[E1003]: unknown type `LCRTempPID`"),
        "{stderr}"
    );
}

/// B&R code splits long conditions over lines, each continuation starting with `AND (...)`; such
/// lines outnumber the statements here, and the body is still read (and run) as ST: `state`
/// follows `ready`, which the program sets from its second cycle.
#[test]
fn conditions_continued_on_and_lines_stay_structured_text() {
    let src = "PROGRAM Main
VAR
  ready, running, enabled, fault : BOOL;
  state, n : INT;
END_VAR
n := n + 1;
ready := n >= 2;
IF (ready = FALSE)
  AND (running = FALSE)
  AND (enabled = FALSE)
  AND (fault = FALSE)
THEN
  state := 1;
ELSIF (ready = TRUE)
  AND (running = FALSE)
  AND (enabled = FALSE)
  AND (fault = FALSE)
THEN
  state := 2;
END_IF;
WHILE (n < 0)
  AND (running = FALSE)
  AND (enabled = FALSE)
  AND (fault = FALSE)
DO
  n := 0;
END_WHILE;
END_PROGRAM
";
    let (trace, stderr) = run_text("leading_and.st", src, 3, "Main.state");
    assert!(!stderr.contains("W0303"), "{stderr}");
    assert_eq!(column(&trace, "Main.state"), vec![1.0, 2.0, 2.0], "{trace}");
}

/// `#ifdef SIMULATION` with no `#define SIMULATION` takes the `#else` branch (note W1419 says
/// the name is defined nowhere); `#define FAST` makes `#ifdef FAST` compile, `#ifndef FAST` not.
/// An `#include` line is one E1058 at the line, not an SCL diagnosis of the whole file.
#[test]
fn bnr_preprocessor_lines_choose_their_branch() {
    let src = "#define FAST
PROGRAM Main
VAR
  mode, speed : INT;
END_VAR
#ifdef SIMULATION
  mode := 1;
#else
  mode := 2;
#endif
#ifdef FAST
  speed := 10;
#endif
#ifndef FAST
  speed := 1;
#endif
END_PROGRAM
";
    let (trace, stderr) = run_text("pre.st", src, 2, "Main.mode,Main.speed");
    assert!(stderr.contains("W1419"), "{stderr}");
    assert!(!stderr.contains("E0023"), "{stderr}");
    assert_eq!(column(&trace, "Main.mode"), vec![2.0, 2.0], "{trace}");
    assert_eq!(column(&trace, "Main.speed"), vec![10.0, 10.0], "{trace}");
    let (code, lines) = check_text(
        "inc.st",
        "PROGRAM Main\nVAR\n  x : INT;\nEND_VAR\n#include \"config.h\"\nx := 1;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("inc.st:5:1: error[E1058]"),
        "{lines:?}"
    );
}

/// Two program folders whose code is LD (`Main.ld`, not read) declare the same private variable
/// and type; a third folder's ST program runs with the package's `Global.var`. Before: E1002 for
/// the second `state` and `Mode`.
#[test]
fn a_program_folder_without_its_code_keeps_its_declarations_to_itself() {
    let dir = tempfile::tempdir().unwrap();
    let w = |n: &str, t: &str| write_in(dir.path(), n, t);
    let prg = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Program SubType=\"IEC\" xmlns=\"http://br-automation.co.at/AS/Program\">\n  <Files>\n    <File Description=\"Init, cyclic, exit code\">Main.ld</File>\n    <File Description=\"Local data types\" Private=\"true\">Types.typ</File>\n    <File Description=\"Local variables\" Private=\"true\">Variables.var</File>\n  </Files>\n</Program>\n";
    for folder in ["Detect", "Move"] {
        w(&format!("Logical/Cell/{folder}/IEC.prg"), prg);
        w(
            &format!("Logical/Cell/{folder}/Variables.var"),
            "VAR\n    state : Mode;\nEND_VAR\n",
        );
        w(
            &format!("Logical/Cell/{folder}/Types.typ"),
            "TYPE\n    Mode : (IDLE, BUSY);\nEND_TYPE\n",
        );
    }
    w("Logical/Global.var", "VAR\n    ticks : INT;\nEND_VAR\n");
    w(
        "Logical/Cell/Counter/Main.st",
        "PROGRAM _CYCLIC\n    ticks := ticks + 1;\nEND_PROGRAM\n",
    );
    let mut args = vec!["run", "--lang", "st", "Logical/Global.var"];
    let files = [
        "Logical/Cell/Detect/Variables.var",
        "Logical/Cell/Detect/Types.typ",
        "Logical/Cell/Move/Variables.var",
        "Logical/Cell/Move/Types.typ",
        "Logical/Cell/Counter/Main.st",
    ];
    args.extend(files);
    args.extend(["--cycles", "3", "--watch", "Global.ticks", "--trace", "-"]);
    let (code, stdout, stderr) = in_dir(dir.path(), &args);
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&stdout, "Global.ticks"), vec![1.0, 2.0, 3.0]);
    // the dropped files' "read as global" notes are withdrawn; Global.var keeps its own
    assert_eq!(stderr.matches("W0018").count(), 1, "{stderr}");
    let notes: Vec<&str> = stderr.lines().filter(|l| l.contains("W0022")).collect();
    assert_eq!(notes.len(), 2, "{stderr}");
    assert!(
        notes[0].starts_with(
            "Logical/Cell/Detect/Variables.var:1:1: note[W0022]: B&R program `Detect`"
        ),
        "{stderr}"
    );
}
