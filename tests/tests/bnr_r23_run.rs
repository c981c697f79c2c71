//! Round 23 of unseen projects (issue #13), B&R Automation Studio forms and keyword names, run end
//! to end through `ladderc`:
//! - `pb ACCESS ADR(data[i]);`, B&R's binding of a dynamic variable (`REFERENCE TO`, B&R help
//!   "Dynamic variables": `Tptr ACCESS ADR(Ts);`): the reference refers to the variable, as
//!   `pb REF= data[i]` does; `pt ACCESS (ADR(pt) + 1);` moves it by a byte, as a pointer (before:
//!   E0106 "expected `:=` or `(` after `pb`, found name `ACCESS`", one per statement, 103 in
//!   tkucic/brOscatLib);
//! - `c : Cfg := (0);`, the zero initializer of B&R's generated declarations (a structure, an FB
//!   instance, an array): the type's initial value (before: E0011 "unexpected `;`");
//! - a B&R program folder's actions file (`Actions.st`: `ACTION Advance : ... END_ACTION`): the
//!   folder program's actions, `Advance;` in `_CYCLIC` runs it (before: E0307 for the file, E1001
//!   and W1431 for each call); a file of actions with no program to belong to is one E1060;
//! - a variable named with a block keyword (`Configuration : INT;`, case-sensitive B&R accepts it)
//!   is one E1031 (before: E1031 plus three E0008 "missing `END_...`");
//! - a keyword as a structure field (`s.Continue := FALSE;`, a B&R mapp field): the field, declared
//!   so in the STRUCT (before: E0100, E3101 "CONTINUE outside a loop" and E0104 for one field);
//! - B&R's redundancy pragmas (`{REDUND_ERROR}` before each block of a library's `.fun`): one
//!   informational note per file (before: W0300 "holds code that does not run" for each, 1132 in
//!   one project).

mod common;

use common::{check_text, column, in_dir, run_text, write_in};

/// `ref ACCESS ADR(x)` binds the reference to `x` (reads and writes go to it); `ref ACCESS (ADR(ref)
/// + 1)` moves it to the next byte of the same variable.
#[test]
fn bnr_access_binds_a_reference() {
    let src = "PROGRAM main
VAR
    data : ARRAY[0..3] OF BYTE := [16#11, 16#22, 16#33, 16#44];
    pb : REFERENCE TO BYTE;
    pw : REFERENCE TO BYTE;
    sum : UINT;
    walk : UINT;
    i : INT;
END_VAR
sum := 0;
walk := 0;
FOR i := 0 TO 3 DO
    pb ACCESS ADR(data[i]);
    sum := sum + BYTE_TO_UINT(pb);
END_FOR;
pw ACCESS ADR(data);
FOR i := 0 TO 3 DO
    walk := walk * 2 + BYTE_TO_UINT(pw);
    pw ACCESS (ADR(pw) + 1);
END_FOR;
pb := 16#55;
END_PROGRAM
";
    let (trace, stderr) = run_text("access.st", src, 1, "main.sum,main.walk,main.data[3]");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "main.sum"), vec![170.0]);
    // ((0x11 * 2 + 0x22) * 2 + 0x33) * 2 + 0x44
    assert_eq!(column(&trace, "main.walk"), vec![442.0]);
    // the last binding was data[3]: the write reached it
    assert_eq!(column(&trace, "main.data[3]"), vec![85.0]);
}

/// `:= (0)` of a structure, an FB instance and an array starts them as their type's initial value
/// (a field's declared initial value stays); `m := (0);` in a body stays an assignment.
#[test]
fn bnr_zero_initializer() {
    let src = "TYPE Cfg : STRUCT
    a : INT;
    b : REAL;
    c : INT := 7;
END_STRUCT;
END_TYPE
FUNCTION_BLOCK FB
VAR_INPUT
    k : INT;
END_VAR
VAR_OUTPUT
    q : INT;
END_VAR
q := k + 1;
END_FUNCTION_BLOCK
PROGRAM main
VAR
    c : Cfg := (0);
    f : FB := (0);
    arr : ARRAY[0..2] OF INT := (0);
    n : INT;
    m : INT := 3;
END_VAR
n := c.a + 1 + c.c;
f(k := n);
m := (0);
arr[1] := f.q + arr[0];
END_PROGRAM
";
    let (trace, stderr) = run_text("zero.st", src, 1, "main.n,main.m,main.arr[1],main.c.b");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "main.n"), vec![8.0]);
    assert_eq!(column(&trace, "main.m"), vec![0.0]);
    assert_eq!(column(&trace, "main.arr[1]"), vec![9.0]);
    assert_eq!(column(&trace, "main.c.b"), vec![0.0]);
}

/// A program folder's actions file: `Advance;` in `_CYCLIC` (and in `_INIT`) runs the action with
/// the folder's variables; the actions file alone is one E1060.
#[test]
fn bnr_program_folder_actions_file() {
    let dir = tempfile::tempdir().unwrap();
    let w = |n: &str, t: &str| write_in(dir.path(), n, t);
    w(
        "Logical/Counter/Variables.var",
        "VAR\n    count : INT;\n    step : INT := 2;\n    inits : INT;\nEND_VAR\n",
    );
    w(
        "Logical/Counter/Main.st",
        "PROGRAM _INIT\n    Reset;\nEND_PROGRAM\n\nPROGRAM _CYCLIC\n    IF count < 100 THEN\n        Advance;\n    END_IF;\nEND_PROGRAM\n",
    );
    w(
        "Logical/Counter/Actions.st",
        "ACTION Advance :\n    count := count + step;\nEND_ACTION\n\nACTION Reset :\n    count := 10;\n    inits := inits + 1;\nEND_ACTION\n",
    );
    let (code, stdout, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "--lang",
            "st",
            "Logical/Counter/Variables.var",
            "Logical/Counter/Main.st",
            "Logical/Counter/Actions.st",
            "--cycles",
            "3",
            "--sanitize",
            "--watch",
            "Counter.count,Counter.inits",
            "--trace",
            "-",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        !stderr.contains("W1431") && !stderr.contains("error"),
        "{stderr}"
    );
    assert_eq!(column(&stdout, "Counter.count"), vec![12.0, 14.0, 16.0]);
    assert_eq!(column(&stdout, "Counter.inits"), vec![1.0, 1.0, 1.0]);
    let (code, _, stderr) = in_dir(
        dir.path(),
        &["check", "--lang", "st", "Logical/Counter/Actions.st"],
    );
    assert_eq!(code, Some(1), "{stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(
        errors,
        vec!["Logical/Counter/Actions.st:1:1: error[E1060]: action `Advance` outside any POU: no program or block it belongs to (hint: give the B&R program folder's `_CYCLIC` file on the same command line, or put the actions in an `ACTIONS ... END_ACTIONS` block right after their POU)"],
        "{stderr}"
    );
}

/// A variable named with a block keyword (`Configuration`, `Type`) is one E1031 at its name; the
/// other POUs are read as written.
#[test]
fn keyword_variable_is_one_error() {
    for kw in ["Configuration", "Type", "Function", "Struct"] {
        let src = format!(
            "FUNCTION_BLOCK Axis
VAR_INPUT
    Enable : BOOL;
    {kw} : INT;
    Speed : REAL;
END_VAR
VAR_OUTPUT
    Done : BOOL;
END_VAR
Done := Enable AND Speed > 0.0;
END_FUNCTION_BLOCK

PROGRAM main
VAR
    ax : Axis;
END_VAR
ax(Enable := TRUE, Speed := 1.5);
END_PROGRAM
"
        );
        let (code, lines) = check_text("kw.st", &src);
        assert_eq!(code, Some(1));
        assert_eq!(
            lines,
            vec![format!("kw.st:4:5: error[E1031]: `{kw}` is reserved in IEC 61131-3 (a keyword): it cannot name a variable (hint: rename the variable, for example `x{kw}`)")]
        );
    }
}

/// A keyword as a structure field's name (`Continue`, `case`, `Exit`): declared in the STRUCT and
/// written and read after `.`; a field the structure lacks is one E1021.
#[test]
fn keyword_as_field_name() {
    let src = "TYPE Seq : STRUCT
    Step : INT;
    Continue : BOOL;
    case : INT;
    Exit : BOOL;
END_STRUCT;
END_TYPE
PROGRAM main
VAR
    s : Seq;
    n : INT;
END_VAR
s.Continue := n > 2;
s.case := n * 2;
s.Exit := s.Continue AND s.case > 4;
n := n + 1;
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "field.st",
        src,
        4,
        "main.s.Continue,main.s.case,main.s.Exit",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "main.s.Continue"), vec![0.0, 0.0, 0.0, 1.0]);
    assert_eq!(column(&trace, "main.s.case"), vec![0.0, 2.0, 4.0, 6.0]);
    assert_eq!(column(&trace, "main.s.Exit"), vec![0.0, 0.0, 0.0, 1.0]);
    let (code, lines) = check_text(
        "nofield.st",
        "TYPE Seq : STRUCT\n    Step : INT;\nEND_STRUCT;\nEND_TYPE\n\nPROGRAM main\nVAR\n    s : Seq;\n    n : INT;\nEND_VAR\ns.Continue := FALSE;\nn := n + 1;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        vec!["nofield.st:11:3: error[E1021]: Seq has no field `Continue` (hint: fields of Seq: Step)"]
    );
}

/// B&R's redundancy pragmas in a library's `.fun` file: one informational note for the file, no
/// W0300, and the blocks compile.
#[test]
fn bnr_redundancy_pragmas_one_note() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "Lib.fun",
        "{REDUND_ERROR} FUNCTION Twice : INT\n\tVAR_INPUT\n\t\tx : INT; {REDUND_UNREPLICABLE}\n\tEND_VAR\nEND_FUNCTION\n\n{REDUND_ERROR} {REDUND_UNREPLICABLE} FUNCTION Thrice : INT\n\tVAR_INPUT\n\t\tx : INT;\n\tEND_VAR\nEND_FUNCTION\n",
    );
    write_in(
        dir.path(),
        "Lib.st",
        "FUNCTION Twice\n\tTwice := 2 * x;\nEND_FUNCTION\n\nFUNCTION Thrice\n\tThrice := 3 * x;\nEND_FUNCTION\n",
    );
    write_in(
        dir.path(),
        "Main.st",
        "PROGRAM main\nVAR\n\ty : INT;\nEND_VAR\ny := Twice(4) + Thrice(1);\nEND_PROGRAM\n",
    );
    let (code, stdout, stderr) = in_dir(
        dir.path(),
        &[
            "run", "--lang", "st", "Lib.fun", "Lib.st", "Main.st", "--cycles", "1", "--watch",
            "main.y", "--trace", "-",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&stdout, "main.y"), vec![11.0]);
    assert!(!stderr.contains("W0300"), "{stderr}");
    let notes: Vec<&str> = stderr.lines().filter(|l| l.contains("W0301")).collect();
    assert_eq!(notes.len(), 1, "{stderr}");
    assert!(
        notes[0].starts_with("Lib.fun:1:1: note[W0301]: pragma `{REDUND_ERROR}` is informational"),
        "{stderr}"
    );
}
