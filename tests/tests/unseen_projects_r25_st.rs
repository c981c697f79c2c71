//! Round 25 of unseen projects (issue #13), ExST and qualified names in ST bodies, run end to end
//! through `ladderc run` / `ladderc check`:
//! - the ExST set and reset assignments `x S= c;`, `x R= c;` and their chains `a S= b R= c;`
//!   (CODESYS, TwinCAT: every place of the chain takes the operand at the end of the line; `S=`
//!   writes TRUE and `R=` FALSE when it is TRUE, nothing when it is FALSE; before: E0106);
//! - a PROGRAM's own PROPERTY named through the program, `Prg.Prop := v;` / `x := Prg.Prop;`
//!   inside the program, its actions and methods, runs the program's own accessors (before:
//!   E3135 "calls its own action" naming the hidden `__SET_PROP`), and E3135 for a property of a
//!   program with two instances names the property and its accessor, never `__GET_`/`__SET_`;
//! - a member or method chain on an undeclared name (`cell.Units[1].Cmd.Home().Done`) is the one
//!   E1001 of that name in its POU, at its first use (before: one E0349 "is no method" per use,
//!   the name never reported).

mod common;
use common::{check_text, column, run_text};

/// `motor S= start;` sets, `motor R= stop;` resets, `lamp S= motor R= stop;` resets `motor` and
/// sets `lamp` when `stop` is TRUE, and nothing changes while the operand is FALSE. In `x S= x R=
/// c;` the innermost assignment runs first (as `a := b := e` is read), so `x` ends TRUE.
#[test]
fn set_and_reset_assignments_run_as_codesys_documents_them() {
    let src = "PROGRAM Main
VAR
    n : INT;
    start, stop : BOOL;
    motor, lamp, x : BOOL;
END_VAR
n := n + 1;
start := n = 2 OR n = 5;
stop := n = 4;
motor S= start;
motor R= stop;
lamp S= motor R= stop;
x S= x R= start;
END_PROGRAM
";
    let (trace, stderr) = run_text("latch.st", src, 6, "Main.motor,Main.lamp,Main.x");
    assert_eq!(
        column(&trace, "Main.motor"),
        [0.0, 1.0, 1.0, 0.0, 1.0, 1.0],
        "{stderr}"
    );
    assert_eq!(column(&trace, "Main.lamp"), [0.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
    assert_eq!(column(&trace, "Main.x"), [0.0, 1.0, 1.0, 1.0, 1.0, 1.0]);
}

/// The operand of a chain is evaluated once (Infosys: "all assignments refer to the operand at the
/// end of the code line"): a function with a side effect runs once per line, and a set/reset of
/// elements, members and a function's result all work.
#[test]
fn a_set_reset_chain_evaluates_its_operand_once() {
    let src = "FUNCTION Count : BOOL
VAR_INPUT
    inp : BOOL;
END_VAR
VAR_IN_OUT
    calls : INT;
END_VAR
calls := calls + 1;
Count := inp;
END_FUNCTION
TYPE ST_Flags : STRUCT
    a, b : BOOL;
END_STRUCT
END_TYPE
PROGRAM Main
VAR
    n, calls : INT;
    f : ST_Flags;
    arr : ARRAY[1..2] OF BOOL;
END_VAR
n := n + 1;
arr[1] S= f.a R= Count(inp := n = 2, calls := calls);
f.b R= arr[2] S= n >= 3;
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "chain.st",
        src,
        3,
        "Main.calls,Main.arr[1],Main.f.a,Main.arr[2],Main.f.b",
    );
    assert_eq!(column(&trace, "Main.calls"), [1.0, 2.0, 3.0], "{stderr}");
    assert_eq!(column(&trace, "Main.arr[1]"), [0.0, 1.0, 1.0]);
    assert_eq!(column(&trace, "Main.f.a"), [0.0, 0.0, 0.0]);
    assert_eq!(column(&trace, "Main.arr[2]"), [0.0, 0.0, 1.0]);
    assert_eq!(column(&trace, "Main.f.b"), [0.0, 0.0, 0.0]);
}

/// `Lights.Level := ...` and `Lights.Level` inside program `Lights`, in one of its actions and in
/// one of its methods: the program's own Set and Get accessors, as TwinCAT runs them; another
/// program reads the same property through the program's one instance.
#[test]
fn a_program_names_its_own_property_through_its_name() {
    let src = "PROGRAM Lights
VAR
    nLevel : INT;
    shown : INT;
    doubled : INT;
END_VAR
Bump();
shown := Lights.Level;
doubled := Twice();

METHOD Twice : INT
Twice := Lights.Level * 2;
END_METHOD

PROPERTY Level : INT
GET
    Level := nLevel;
END_GET
SET
    nLevel := Level;
END_SET
END_PROPERTY
END_PROGRAM
ACTIONS Lights
ACTION Bump:
Lights.Level := Lights.Level + 1;
END_ACTION
END_ACTIONS
PROGRAM Other
VAR
    seen : INT;
END_VAR
seen := Lights.Level;
END_PROGRAM
CONFIGURATION C
RESOURCE R ON PLC
TASK t(INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM p1 WITH t : Lights;
PROGRAM p2 WITH t : Other;
END_RESOURCE
END_CONFIGURATION
";
    let (trace, stderr) = run_text("lights.st", src, 3, "p1.shown,p1.doubled,p2.seen");
    assert_eq!(column(&trace, "p1.shown"), [1.0, 2.0, 3.0], "{stderr}");
    assert_eq!(column(&trace, "p1.doubled"), [2.0, 4.0, 6.0]);
    assert_eq!(column(&trace, "p2.seen"), [1.0, 2.0, 3.0]);
}

/// Directly in the program's body, as the round's repro writes it: `Lights.Level := nLevel + 1;`
/// then `shown := Lights.Level;`.
#[test]
fn a_program_writes_and_reads_its_own_property_in_its_body() {
    let src = "PROGRAM Lights
VAR
    nLevel : INT;
    shown : INT;
END_VAR
Lights.Level := nLevel + 1;
shown := Lights.Level;

PROPERTY Level : INT
GET
    Level := nLevel;
END_GET
SET
    nLevel := Level;
END_SET
END_PROPERTY
END_PROGRAM
";
    let (trace, stderr) = run_text("own.st", src, 3, "Lights.shown");
    assert_eq!(column(&trace, "Lights.shown"), [1.0, 2.0, 3.0], "{stderr}");
}

/// A property of a program instantiated twice, used as `Lights.Level` from another program: E3135
/// names the property and the accessor, with a hint in source terms, never the hidden
/// `__GET_LEVEL` / `__SET_LEVEL`.
#[test]
fn e3135_for_a_property_never_shows_the_hidden_accessor_names() {
    let src = "PROGRAM Lights
VAR
    nLevel : INT;
END_VAR
nLevel := nLevel + 1;
PROPERTY Level : INT
GET
    Level := nLevel;
END_GET
SET
    nLevel := Level;
END_SET
END_PROPERTY
END_PROGRAM
PROGRAM Other
VAR
    seen : INT;
END_VAR
seen := Lights.Level;
Lights.Level := 3;
END_PROGRAM
CONFIGURATION C
RESOURCE R ON PLC
TASK t(INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM p1 WITH t : Lights;
PROGRAM p3 WITH t : Lights;
PROGRAM p2 WITH t : Other;
END_RESOURCE
END_CONFIGURATION
";
    let (code, lines) = check_text("twice.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(lines[0].starts_with("twice.st:19:9: error[E3135]: the Get accessor of property"));
    assert!(lines[1].starts_with("twice.st:20:1: error[E3135]: the Set accessor of property"));
    for l in &lines {
        assert!(!l.contains("__"), "{l}");
        assert!(l.contains("instances (`p1`, `p3`)"), "{l}");
    }
}

/// `cell` declared nowhere, used in method chains in IF conditions, as a written place and as a
/// called chain: one E1001 `undeclared name cell` at its first use, nothing else (no E0349 per
/// chain, no E1019 "unknown function").
#[test]
fn a_chain_on_an_undeclared_name_is_one_e1001() {
    let src = "PROGRAM Main
VAR
    n : INT;
END_VAR
IF cell.Units[1].Cmd.Home().Done THEN
    n := n + 1;
END_IF
IF cell.Units[2].Cmd.Move(10, 20).Done THEN
    n := n + 2;
END_IF
cell.Units[2].Cmd.Move(10, 20).Go();
cell.Units[1] := n;
cell.Units[3].Cmd.Stop().Done := TRUE;
END_PROGRAM
";
    let (code, lines) = check_text("cell.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        lines,
        ["cell.st:5:4: error[E1001]: undeclared name `cell` (hint: declare `cell` in a VAR block (or VAR_EXTERNAL for a global))"],
        "{lines:?}"
    );
}

/// The called chain first (`cell.A().Go();` as the POU's first use of `cell`): the E1001 is at it.
#[test]
fn a_called_chain_on_an_undeclared_name_is_its_e1001() {
    let src = "PROGRAM Main
VAR
    n : INT;
END_VAR
n := n + 1;
cell.Units[2].Cmd.Move(10, 20).Go();
IF cell.Units[1].Cmd.Home().Done THEN
    n := n + 1;
END_IF
END_PROGRAM
";
    let (code, lines) = check_text("first.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("first.st:6:1: error[E1001]: undeclared name `cell`"),
        "{lines:?}"
    );
}
