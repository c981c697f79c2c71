//! Round 26 of unseen projects (issue #13), B&R Automation Studio libraries, run end to end
//! through `ladderc`:
//! - an input or output of a `.fun` block named with a keyword, an elementary type or a standard
//!   block (`Type`, `Configuration`, `string`, `type`: B&R's own libraries Acp10_MC, MpAlarmX,
//!   sys_lib, AsArSdm) is declared, set in a formal call `blk(Type := 3)` and read as `blk.Type`;
//!   a stub no file implements is the one note W0021 (before: E1031 at each, the project stopped);
//! - a `.fun` function or block whose `.st` implementation has no statement is one block, the
//!   function's result the type's initial value (before: E1002 "declared twice", or E0354);
//! - a library folder's action file, called by name in the library's function block, is that
//!   block's action and runs on its instance (before: E1060 and W1431 at the call);
//! - B&R's zero initializer repeated in an array initializer, `3((0))`, is three elements of the
//!   type's initial value (before: E0011);
//! - one stray `END_IF` in a CASE branch is one E0100 (before: E0100, E0105 and E0100 for the next
//!   label).

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

/// A library block `Pick` declared in a `.fun` file with inputs `Type`, `Configuration` and
/// output `string`, implemented in a `.st` file, is called as `p(Type := 3, Configuration := 40)`
/// and read as `p.Type`, `p.Configuration`, `p.string` (and as `Type` in its own statements); the stub `VendorCore` (inputs
/// `Configuration`, `type`) that no file implements is W0021 only.
#[test]
fn fun_parameters_named_with_keywords_are_declared_and_used() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write_in(
        root,
        "Libraries/KwLib/KwLib.fun",
        "FUNCTION_BLOCK Pick\n\tVAR_INPUT\n\t\tEnable : BOOL;\n\t\tType : USINT;\n\t\tConfiguration : INT;\n\tEND_VAR\n\tVAR_OUTPUT\n\t\tstring : INT;\n\t\tDone : BOOL;\n\tEND_VAR\nEND_FUNCTION_BLOCK\n\nFUNCTION_BLOCK VendorCore\n\tVAR_INPUT\n\t\tConfiguration : UDINT;\n\t\ttype : USINT;\n\tEND_VAR\n\tVAR_OUTPUT\n\t\tActive : BOOL;\n\tEND_VAR\nEND_FUNCTION_BLOCK\n",
    );
    write_in(
        root,
        "Libraries/KwLib/Pick.st",
        "FUNCTION_BLOCK Pick\n\tDone := Enable AND Type = 3;\nEND_FUNCTION_BLOCK\n",
    );
    write_in(
        root,
        "Prog/Variables.var",
        "VAR\n\tp : Pick;\n\tn : INT;\n\tt : USINT;\n\td : BOOL;\nEND_VAR\n",
    );
    write_in(
        root,
        "Prog/Main.st",
        "PROGRAM _CYCLIC\n\tp(Enable := TRUE, Type := 3, Configuration := 40);\n\tn := p.Configuration + 1 + p.string;\n\tt := p.Type;\n\td := p.Done;\nEND_PROGRAM\n",
    );
    let (code, out, err) = in_dir(
        root,
        &[
            "run",
            "--lang",
            "st",
            "Libraries/KwLib/KwLib.fun",
            "Libraries/KwLib/Pick.st",
            "Prog/Variables.var",
            "Prog/Main.st",
            "--cycles",
            "2",
            "--watch",
            "Prog.n,Prog.t,Prog.d",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("E1031"), "{err}");
    assert!(
        err.contains("W0021") && err.contains("`VendorCore`"),
        "{err}"
    );
    assert_eq!(column(&out, "Prog.n"), vec![41.0, 41.0]);
    assert_eq!(column(&out, "Prog.t"), vec![3.0, 3.0]);
    assert_eq!(column(&out, "Prog.d"), vec![1.0, 1.0]);
    // a block with statements still may not name its input with a keyword
    let (code, lines) = check_text(
        "fb.st",
        "FUNCTION_BLOCK FB\nVAR_INPUT Type : INT; END_VAR\nVAR_OUTPUT q : INT; END_VAR\nq := 1;\nEND_FUNCTION_BLOCK\n",
    );
    assert_eq!(code, Some(1));
    assert!(
        lines.iter().any(|l| l.contains("fb.st:2:11: error[E1031]")),
        "{lines:?}"
    );
}

/// `Twice` (a FUNCTION : INT) and `Idle` (a FUNCTION_BLOCK) declared in `MyLib.fun` and
/// implemented by `.st` files with no statement (a comment only, as Automation Studio's wizard
/// writes them) are one block each: `Twice(n)` is 0, `Idle` runs and does nothing.
#[test]
fn fun_block_with_an_empty_implementation_is_one_block() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write_in(
        root,
        "Libraries/MyLib/MyLib.fun",
        "FUNCTION Twice : INT\n\tVAR_INPUT\n\t\tv : INT;\n\tEND_VAR\nEND_FUNCTION\nFUNCTION_BLOCK Idle\n\tVAR_INPUT\n\t\tx : BOOL;\n\tEND_VAR\n\tVAR_OUTPUT\n\t\ty : INT;\n\tEND_VAR\nEND_FUNCTION_BLOCK\n",
    );
    write_in(
        root,
        "Libraries/MyLib/Twice.st",
        "FUNCTION Twice\n\t(* not written yet *)\nEND_FUNCTION\n",
    );
    write_in(
        root,
        "Libraries/MyLib/Idle.st",
        "FUNCTION_BLOCK Idle\n\nEND_FUNCTION_BLOCK\n",
    );
    write_in(
        root,
        "Prog/Variables.var",
        "VAR\n\tn : INT;\n\tr : INT;\n\ti : Idle;\n\tk : INT;\nEND_VAR\n",
    );
    write_in(
        root,
        "Prog/Main.st",
        "PROGRAM _CYCLIC\n\tn := n + 1;\n\tr := Twice(n) + n;\n\ti(x := TRUE);\n\tk := i.y + 5;\nEND_PROGRAM\n",
    );
    let (code, out, err) = in_dir(
        root,
        &[
            "run",
            "--lang",
            "st",
            "Libraries/MyLib/MyLib.fun",
            "Libraries/MyLib/Twice.st",
            "Libraries/MyLib/Idle.st",
            "Prog/Variables.var",
            "Prog/Main.st",
            "--cycles",
            "3",
            "--watch",
            "Prog.r,Prog.k",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("E1002") && !err.contains("E0354"), "{err}");
    assert_eq!(err.matches("W0019").count(), 2, "{err}");
    assert_eq!(column(&out, "Prog.r"), vec![1.0, 2.0, 3.0]);
    assert_eq!(column(&out, "Prog.k"), vec![5.0, 5.0, 5.0]);
}

/// `ValveLib`'s block `Valve` calls `ACT_Drive;` (an action file of the library's folder): the
/// action runs on the instance, `q` follows `cmd`; an action file no block calls stays E1060.
#[test]
fn a_library_action_called_by_its_block_runs() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write_in(
        root,
        "Libraries/ValveLib/ValveLib.fun",
        "FUNCTION_BLOCK Valve\n\tVAR_INPUT\n\t\tcmd : BOOL;\n\tEND_VAR\n\tVAR_OUTPUT\n\t\tout : BOOL;\n\t\tcount : INT;\n\tEND_VAR\nEND_FUNCTION_BLOCK\n",
    );
    write_in(
        root,
        "Libraries/ValveLib/Valve.st",
        "FUNCTION_BLOCK Valve\n\tACT_Drive;\n\tACT_Count;\nEND_FUNCTION_BLOCK\n",
    );
    write_in(
        root,
        "Libraries/ValveLib/ACT_Drive.st",
        "ACTION ACT_Drive:\n\tout := cmd;\nEND_ACTION\n",
    );
    write_in(
        root,
        "Libraries/ValveLib/ACT_Count.st",
        "ACTION ACT_Count:\n\tIF out THEN\n\t\tcount := count + 1;\n\tEND_IF\nEND_ACTION\n",
    );
    write_in(
        root,
        "Prog/Variables.var",
        "VAR\n\tv : Valve;\n\tn : INT;\n\tq : BOOL;\n\tc : INT;\nEND_VAR\n",
    );
    write_in(
        root,
        "Prog/Main.st",
        "PROGRAM _CYCLIC\n\tv(cmd := n > 1);\n\tn := n + 1;\n\tq := v.out;\n\tc := v.count;\nEND_PROGRAM\n",
    );
    let files = [
        "Libraries/ValveLib/ValveLib.fun",
        "Libraries/ValveLib/Valve.st",
        "Libraries/ValveLib/ACT_Drive.st",
        "Libraries/ValveLib/ACT_Count.st",
        "Prog/Variables.var",
        "Prog/Main.st",
    ];
    let mut args = vec!["run", "--lang", "st"];
    args.extend(files);
    args.extend(["--cycles", "4", "--watch", "Prog.q,Prog.c"]);
    let (code, out, err) = in_dir(root, &args);
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("E1060") && !err.contains("W1431"), "{err}");
    assert_eq!(column(&out, "Prog.q"), vec![0.0, 0.0, 1.0, 1.0]);
    assert_eq!(column(&out, "Prog.c"), vec![0.0, 0.0, 1.0, 2.0]);
    // an action of the library that no block calls has no owner
    write_in(
        root,
        "Libraries/ValveLib/ACT_Unused.st",
        "ACTION ACT_Unused:\n\tout := FALSE;\nEND_ACTION\n",
    );
    let mut args = vec!["check", "--lang", "st", "Libraries/ValveLib/ACT_Unused.st"];
    args.extend(files);
    let (code, _, err) = in_dir(root, &args);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("ACT_Unused.st:1:1: error[E1060]"), "{err}");
}

/// `Slots : ARRAY[0..3] OF Slot := [(Start := TOD#06:00:00, Len := 5), 3((0))]` (as B&R's mapp
/// types write it): element 0 as written, elements 1 to 3 the type's initial values (`Len := 2`).
#[test]
fn a_repeated_zero_structure_initializer_is_the_initial_value() {
    let src = "TYPE
  Slot : STRUCT
    Start : TOD;
    Len : UINT := 2;
  END_STRUCT;
  Plan : STRUCT
    Name : STRING[20];
    Slots : ARRAY[0..3] OF Slot := [(Start := TOD#06:00:00, Len := 5), 3((0))];
  END_STRUCT;
END_TYPE
PROGRAM Main
VAR
  p : Plan;
  q : ARRAY[0..2] OF Slot := [3((0))];
  n : UINT;
END_VAR
n := p.Slots[0].Len * 100 + p.Slots[1].Len * 10 + p.Slots[3].Len + q[2].Len * 1000;
END_PROGRAM
";
    let (trace, stderr) = run_text("zero.st", src, 1, "Main.n");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "Main.n"), vec![2522.0]);
}

/// One `END_IF` too many in branch 0 of a CASE is one E0100 at it; the next label `10:` and the
/// `END_CASE` are read as the CASE's.
#[test]
fn a_stray_end_if_in_a_case_branch_is_one_error() {
    let (code, lines) = check_text(
        "stray.st",
        "PROGRAM P
VAR state : INT; a, b : BOOL; END_VAR
CASE state OF
  0:
    IF a THEN
      state := 10;
    END_IF
    END_IF
  10:
    b := TRUE;
    state := 0;
END_CASE
END_PROGRAM
",
    );
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("stray.st:8:5: error[E0100]") && lines[0].contains("`END_IF`"),
        "{lines:?}"
    );
}
