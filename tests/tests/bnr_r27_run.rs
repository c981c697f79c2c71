//! Round 27 of unseen projects (issue #13), B&R Automation Studio projects, run end to end through
//! `ladderc`:
//! - a system library's data type with a field of a block its `.fun` file only declares (a stub,
//!   W0021: `runtime.typ`'s `SFCActionType`, `AC : SFCActionControl`) is as unavailable as the
//!   stub: nothing when no code uses it, one E1003 naming the stub where the user's code does
//!   (before: one E1003 per such field inside the vendor's file, the project stopped);
//! - a program folder with `ANSIC.prg` (a program in C, its code not given) keeps its `.var`
//!   declarations to itself, W0022, as an `IEC.prg` folder does (before: read as global variables,
//!   E1002 between two such programs);
//! - a program folder named like a library function block (`Logical/Blink/` beside the block
//!   `Blink`) is a program traced as `Blink`, and the block stays a type (before: E1002);
//! - a program's own `Mixing` hiding the global `MIXING` of a `.var` file (two variables in
//!   case-sensitive Automation Studio): W1450 at each use spelled as the global (before: silent);
//! - a variable named `this` in a B&R program is read as `this.x` (before: E0104/E0100 at each
//!   read);
//! - a structure field named `Type` set in a structure initializer, `(Name := 'calc', Type := 2)`
//!   (before: a cascade of five parse errors);
//! - a parenthesised string literal as an initial value, `[('ab')]`, `:= ('ab')` (before: E0011);
//! - B&R's zero initializer as an element of an array of structures, `[(0)]`, `2(0)`: the type's
//!   initial value (before: E1025).

mod common;
use common::{column, in_dir, run_text, write_in};

/// `StubLib.fun` declares the block `StubFb` without statements (a system library's stub) and
/// `StubLib.typ` two structures with a field of it, one through the other: unused, they are no
/// error and the program runs; a program that declares a variable of one gets one E1003 there,
/// naming the stub.
#[test]
fn types_made_of_stub_blocks_are_unavailable_only_where_used() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write_in(
        root,
        "Libraries/StubLib/StubLib.fun",
        "FUNCTION_BLOCK StubFb\n\tVAR_INPUT\n\t\tGo : BOOL;\n\tEND_VAR\nEND_FUNCTION_BLOCK\n",
    );
    write_in(
        root,
        "Libraries/StubLib/StubLib.typ",
        "TYPE\n\tUsesStub : STRUCT\n\t\tflag : BOOL;\n\t\tctl : StubFb;\n\tEND_STRUCT;\n\tUsesUses : STRUCT\n\t\tinner : ARRAY[0..1] OF UsesStub;\n\tEND_STRUCT;\n\tPlain : STRUCT\n\t\tk : INT := 4;\n\tEND_STRUCT;\nEND_TYPE\n",
    );
    write_in(root, "Main/IEC.prg", "<Program SubType=\"IEC\"/>\n");
    write_in(
        root,
        "Main/Main.var",
        "VAR\n\tn : INT;\n\tp : Plain;\nEND_VAR\n",
    );
    write_in(
        root,
        "Main/Main.st",
        "PROGRAM _CYCLIC\n\tn := n + p.k;\nEND_PROGRAM\n",
    );
    let args = [
        "run",
        "--lang",
        "st",
        "Libraries/StubLib/StubLib.fun",
        "Libraries/StubLib/StubLib.typ",
        "Main/Main.var",
        "Main/Main.st",
        "--cycles",
        "3",
        "--watch",
        "Main.n",
    ];
    let (code, out, err) = in_dir(root, &args);
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("E1003"), "{err}");
    assert!(err.contains("W0021"), "{err}");
    assert_eq!(column(&out, "Main.n"), vec![4.0, 8.0, 12.0]);
    // used: one E1003 at the use, naming the stub
    write_in(
        root,
        "Main/Main.var",
        "VAR\n\tn : INT;\n\tp : Plain;\n\th : UsesUses;\nEND_VAR\n",
    );
    let (code, _, err) = in_dir(root, &args);
    assert_eq!(code, Some(1), "{err}");
    assert_eq!(err.matches("error[").count(), 1, "{err}");
    assert!(
        err.contains("error[E1003]: `UsesUses` is made of `StubFb`, a block StubLib.fun declares without statements"),
        "{err}"
    );
    assert!(err.contains("Main/Main.var:4:6"), "{err}");
}

/// Two program folders whose code is C (`ANSIC.prg`, no `.c` file given) declare `count` each in
/// their `Variables.var`: each is private to its program (two W0022 notes), and the ST program
/// beside them runs with its own `count`.
#[test]
fn ansic_program_folders_keep_their_variables() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    for p in ["CProgA", "CProgB"] {
        write_in(
            root,
            &format!("{p}/ANSIC.prg"),
            "<Program SubType=\"ANSIC\"/>\n",
        );
        write_in(
            root,
            &format!("{p}/Variables.var"),
            "VAR\n\tcount : UDINT;\n\tbusy : BOOL;\nEND_VAR\n",
        );
    }
    write_in(root, "StProg/IEC.prg", "<Program SubType=\"IEC\"/>\n");
    write_in(
        root,
        "StProg/Variables.var",
        "VAR\n\tcount : INT;\nEND_VAR\n",
    );
    write_in(
        root,
        "StProg/Main.st",
        "PROGRAM _CYCLIC\n\tcount := count + 1;\nEND_PROGRAM\n",
    );
    let (code, out, err) = in_dir(
        root,
        &[
            "run",
            "--lang",
            "st",
            "CProgA/Variables.var",
            "CProgB/Variables.var",
            "StProg/Variables.var",
            "StProg/Main.st",
            "--cycles",
            "3",
            "--watch",
            "StProg.count",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(err.matches("note[W0022]").count(), 2, "{err}");
    assert!(!err.contains("W0018") && !err.contains("E1002"), "{err}");
    assert_eq!(column(&out, "StProg.count"), vec![1.0, 2.0, 3.0]);
}

/// The library block `Toggle` (declared in a `.fun` file, implemented in a `.st` one) and the
/// program folder `Toggle` that declares an instance of it: the program runs, traced as
/// `Toggle.lamp`.
#[test]
fn program_folder_named_like_a_library_block() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write_in(
        root,
        "Libraries/Lamps/Lamps.fun",
        "FUNCTION_BLOCK Toggle\n\tVAR_INPUT\n\t\ton : BOOL;\n\tEND_VAR\n\tVAR_OUTPUT\n\t\tq : BOOL;\n\tEND_VAR\nEND_FUNCTION_BLOCK\n",
    );
    write_in(
        root,
        "Libraries/Lamps/Toggle.st",
        "FUNCTION_BLOCK Toggle\n\tIF on THEN\n\t\tq := NOT q;\n\tEND_IF\nEND_FUNCTION_BLOCK\n",
    );
    write_in(root, "Toggle/IEC.prg", "<Program SubType=\"IEC\"/>\n");
    write_in(
        root,
        "Toggle/Variables.var",
        "VAR\n\tt : Toggle;\n\tlamp : BOOL;\nEND_VAR\n",
    );
    write_in(
        root,
        "Toggle/Main.st",
        "PROGRAM _CYCLIC\n\tt(on := TRUE);\n\tlamp := t.q;\nEND_PROGRAM\n",
    );
    let (code, out, err) = in_dir(
        root,
        &[
            "run",
            "--lang",
            "st",
            "Libraries/Lamps/Lamps.fun",
            "Libraries/Lamps/Toggle.st",
            "Toggle/Variables.var",
            "Toggle/Main.st",
            "--cycles",
            "4",
            "--watch",
            "Toggle.lamp",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("E1002"), "{err}");
    assert!(err.contains("B&R program `Toggle` (its folder)"), "{err}");
    assert_eq!(column(&out, "Toggle.lamp"), vec![1.0, 0.0, 1.0, 0.0]);
}

/// A program's own `Mixing` (its folder's `.var`) and the global `MIXING` (a `.var` file outside
/// any program folder): read as IEC reads them (one name, the program's), with W1450 at the use
/// spelled as the global (in the program's part and in its actions file), and none at the uses
/// spelled as the program's variable.
#[test]
fn case_shadowed_global_is_warned_at_its_use() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write_in(root, "Global.var", "VAR\n\tSTIRRING : BOOL;\nEND_VAR\n");
    write_in(root, "Tank/IEC.prg", "<Program SubType=\"IEC\"/>\n");
    write_in(
        root,
        "Tank/Variables.var",
        "VAR\n\tStirring : BOOL;\n\tsteps : INT;\nEND_VAR\n",
    );
    write_in(
        root,
        "Tank/Main.st",
        "PROGRAM _CYCLIC\n\tStirring := STIRRING OR TRUE;\n\tIF Stirring THEN\n\t\tsteps := steps + 1;\n\tEND_IF\n\tCount;\nEND_PROGRAM\n",
    );
    write_in(
        root,
        "Tank/Actions.st",
        "ACTION Count:\n\tIF STIRRING THEN\n\t\tsteps := steps + 10;\n\tEND_IF\nEND_ACTION\n",
    );
    let (code, out, err) = in_dir(
        root,
        &[
            "run",
            "--lang",
            "st",
            "Global.var",
            "Tank/Variables.var",
            "Tank/Main.st",
            "Tank/Actions.st",
            "--cycles",
            "2",
            "--watch",
            "Tank.steps",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(err.matches("warning[W1450]").count(), 2, "{err}");
    assert!(
        err.contains("warning[W1450]: `STIRRING` here is the program's own `Stirring`"),
        "{err}"
    );
    assert!(err.contains("Tank/Main.st:2:14"), "{err}");
    assert!(err.contains("Tank/Actions.st:2:5"), "{err}");
    assert_eq!(column(&out, "Tank.steps"), vec![11.0, 22.0]);
}

/// A variable named `this` (a `REFERENCE TO` a structure) in a B&R program, set with `ACCESS` and
/// read as `this.count` in expressions and conditions: the program runs.
#[test]
fn variable_named_this_in_a_program() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write_in(root, "Ctl/IEC.prg", "<Program SubType=\"IEC\"/>\n");
    write_in(
        root,
        "Ctl/Ctl.typ",
        "TYPE\n\tcell_typ : STRUCT\n\t\tcount : INT;\n\t\tfull : BOOL;\n\tEND_STRUCT;\nEND_TYPE\n",
    );
    write_in(
        root,
        "Ctl/Ctl.var",
        "VAR\n\tthis : REFERENCE TO cell_typ;\n\tcells : ARRAY[0..1] OF cell_typ;\nEND_VAR\n",
    );
    write_in(
        root,
        "Ctl/Main.st",
        "PROGRAM _CYCLIC\n\tthis ACCESS ADR(cells[1]);\n\tthis.count := this.count + 2;\n\tIF this.count > 4 THEN\n\t\tthis.full := TRUE;\n\tEND_IF\nEND_PROGRAM\n",
    );
    let (code, out, err) = in_dir(
        root,
        &[
            "run",
            "--lang",
            "st",
            "Ctl/Ctl.typ",
            "Ctl/Ctl.var",
            "Ctl/Main.st",
            "--cycles",
            "3",
            "--watch",
            "Ctl.cells[1].count,Ctl.cells[1].full",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(column(&out, "Ctl.cells[1].count"), vec![2.0, 4.0, 6.0]);
    assert_eq!(column(&out, "Ctl.cells[1].full"), vec![0.0, 0.0, 1.0]);
}

/// A structure with a field named `Type`, set in the structure initializer of a `.var`
/// declaration and of a field of another type: the values are the initial ones.
#[test]
fn field_named_type_in_a_structure_initializer() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write_in(root, "P/IEC.prg", "<Program SubType=\"IEC\"/>\n");
    write_in(
        root,
        "P/P.typ",
        "TYPE\n\tCase_typ : STRUCT\n\t\tName : STRING[12];\n\t\tType : USINT;\n\t\tLevel : INT;\n\tEND_STRUCT;\n\tSuite_typ : STRUCT\n\t\tfirst : Case_typ := (Type := 7, Level := 1);\n\tEND_STRUCT;\nEND_TYPE\n",
    );
    write_in(
        root,
        "P/P.var",
        "VAR\n\tc : Case_typ := (Name := 'calc', Type := 2, Level := 5);\n\ts : Suite_typ;\n\tn : INT;\nEND_VAR\n",
    );
    write_in(
        root,
        "P/Main.st",
        "PROGRAM _CYCLIC\n\tn := c.Type * 100 + c.Level * 10 + s.first.Type;\nEND_PROGRAM\n",
    );
    let (code, out, err) = in_dir(
        root,
        &[
            "run",
            "--lang",
            "st",
            "P/P.typ",
            "P/P.var",
            "P/Main.st",
            "--cycles",
            "1",
            "--watch",
            "P.n",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(column(&out, "P.n"), vec![257.0]);
}

/// `('ab')` as an array element's and a variable's initial value: the string.
#[test]
fn parenthesised_string_literal_as_initial_value() {
    let (out, err) = run_text(
        "paren_init.st",
        "PROGRAM Main\nVAR\n\ta : ARRAY[0..1] OF STRING[5] := [('abc'), 'd'];\n\ts : STRING[5] := ('wxyz');\n\tw : WSTRING[5] := (\"uv\");\n\tn : INT;\nEND_VAR\nn := LEN(a[0]) * 100 + LEN(a[1]) * 10 + LEN(s) + LEN(w) * 1000;\nEND_PROGRAM\n",
        1,
        "Main.n",
    );
    assert!(!err.contains("error"), "{err}");
    assert_eq!(column(&out, "Main.n"), vec![2314.0]);
}

/// `[(0)]` and `2(0)` among the elements of arrays of structures: each such element is the
/// structure type's initial value (its field `Id` keeps 7), the others as written.
#[test]
fn zero_initializer_elements_of_arrays_of_structures() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write_in(
        root,
        "Global.typ",
        "TYPE\n\tRec_typ : STRUCT\n\t\tId : INT := 7;\n\t\tNote : STRING[10];\n\tEND_STRUCT;\nEND_TYPE\n",
    );
    write_in(
        root,
        "Global.var",
        "VAR\n\trecs : ARRAY[0..3] OF Rec_typ := [(Id := 1),2(0),(Note := 'last')];\n\tmore : ARRAY[0..2] OF Rec_typ := [(0)];\n\tints : ARRAY[0..1] OF INT := [(0), 3];\nEND_VAR\n",
    );
    write_in(root, "P/IEC.prg", "<Program SubType=\"IEC\"/>\n");
    write_in(
        root,
        "P/P.var",
        "VAR\n\tn : INT;\n\tm : INT;\n\tl : INT;\nEND_VAR\n",
    );
    write_in(
        root,
        "P/Main.st",
        "PROGRAM _CYCLIC\n\tn := recs[0].Id + recs[1].Id + recs[2].Id + recs[3].Id;\n\tm := more[0].Id + more[2].Id + ints[0] + ints[1];\n\tl := LEN(recs[3].Note);\nEND_PROGRAM\n",
    );
    let (code, out, err) = in_dir(
        root,
        &[
            "run",
            "--lang",
            "st",
            "Global.typ",
            "Global.var",
            "P/P.var",
            "P/Main.st",
            "--cycles",
            "1",
            "--watch",
            "P.n,P.m,P.l",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(column(&out, "P.n"), vec![22.0]);
    assert_eq!(column(&out, "P.m"), vec![17.0]);
    assert_eq!(column(&out, "P.l"), vec![4.0]);
}
