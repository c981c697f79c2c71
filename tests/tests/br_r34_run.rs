//! Round 34 (issue #13), B&R Automation Studio projects, run end to end through `ladderc`:
//! - B1: a program folder's `Types.typ` is private to its program (the folder's `IEC.prg` lists it
//!   `Private="true"`, "Local data types"): two programs may each declare their own
//!   `InternalType` and `MachineStateEnum`, with other fields and values (before: E1002 per clash
//!   and a cascade of E1021 "has no field" and E1001 "is not a value of" in the other programs);
//! - B2: a program folder's `Variables.var` is private too: a program's `i : INT` is not typed by
//!   another program's `i : REAL`, whatever the order of the files (before: E1006 "cannot store
//!   REAL into INT" at `i := 7;` when the other program's file came later);
//! - B5: a structure of a `.typ` file whose fields differ in case only (B&R's own
//!   `acp10_mc.typ`: `TargetPosition` and `targetPosition`), which case-sensitive Automation
//!   Studio compiles: W1463 at the later field, E1105 at a use spelled as it (before: E1002, the
//!   project stopped even when no program used the type).

mod common;
use common::{column, in_dir, write_in};

const IEC_PRG: &str = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Program SubType=\"IEC\" xmlns=\"http://br-automation.co.at/AS/Program\">\n  <Files>\n    <File Description=\"Init, cyclic, exit code\">Main.st</File>\n    <File Description=\"Local data types\" Private=\"true\">Types.typ</File>\n    <File Description=\"Local variables\" Private=\"true\">Variables.var</File>\n  </Files>\n</Program>\n";

/// `run --lang st FILES --cycles N --watch WATCH` in `root`.
fn run_in(
    root: &std::path::Path,
    files: &[&str],
    cycles: &str,
    watch: &str,
) -> (Option<i32>, String, String) {
    let mut args = vec!["run", "--lang", "st"];
    args.extend_from_slice(files);
    args.extend_from_slice(&["--cycles", cycles, "--watch", watch]);
    in_dir(root, &args)
}

/// B1: the programs `Stamper` and `Pusher` each declare in their own `Types.typ` an
/// `InternalType` (other fields), a `MachineStateEnum` (other values, `IDLE` in both) and an
/// alike `MachineStateType` whose field is of the program's own enumeration (the trap of keeping
/// one copy of alike types). Both run with their own types, in either order of the files; each
/// program's bare `IDLE` is its own enumeration's value. Before: E1002 "`InternalType` is declared
/// twice" (and for `MachineStateEnum`), then E1021 "InternalType has no field `Ready`" and E1001
/// at the other program's values.
#[test]
fn private_types_of_one_name_are_each_programs_own() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    let state_type = "\tMachineStateType : STRUCT\n\t\tActualState : MachineStateEnum;\n\t\tNextState : MachineStateEnum;\n\tEND_STRUCT;\n";
    write_in(root, "Logical/Stamper/IEC.prg", IEC_PRG);
    write_in(
        root,
        "Logical/Stamper/Types.typ",
        &format!("TYPE\n{state_type}\tMachineStateEnum :\n\t\t(\n\t\tIDLE,\n\t\tSTAMPING\n\t\t);\n\tInternalType : STRUCT\n\t\tCount : INT;\n\tEND_STRUCT;\nEND_TYPE\n"),
    );
    write_in(
        root,
        "Logical/Stamper/Variables.var",
        "VAR\n\tInternal : InternalType;\n\tMachine : MachineStateType;\n\tisStamping : BOOL;\nEND_VAR\n",
    );
    write_in(
        root,
        "Logical/Stamper/Main.st",
        "PROGRAM _CYCLIC\n\tInternal.Count := Internal.Count + 1;\n\tCASE Machine.ActualState OF\n\t\tIDLE: Machine.NextState := STAMPING;\n\t\tSTAMPING: Machine.NextState := IDLE;\n\tEND_CASE;\n\tMachine.ActualState := Machine.NextState;\n\tisStamping := Machine.ActualState = STAMPING;\nEND_PROGRAM\n",
    );
    write_in(root, "Logical/Pusher/IEC.prg", IEC_PRG);
    write_in(
        root,
        "Logical/Pusher/Types.typ",
        &format!("TYPE\n\tInternalType : STRUCT\n\t\tReady : BOOL;\n\t\tOffset : REAL;\n\tEND_STRUCT;\n\tMachineStateEnum :\n\t\t(\n\t\tWAITING,\n\t\tPUSHING,\n\t\tIDLE\n\t\t);\n{state_type}END_TYPE\n"),
    );
    write_in(
        root,
        "Logical/Pusher/Variables.var",
        "VAR\n\tInternal : InternalType;\n\tMachine : MachineStateType;\n\tstep : INT;\nEND_VAR\n",
    );
    write_in(
        root,
        "Logical/Pusher/Main.st",
        "PROGRAM _CYCLIC\n\tInternal.Ready := NOT Internal.Ready;\n\tInternal.Offset := Internal.Offset + 0.5;\n\tCASE Machine.ActualState OF\n\t\tWAITING: Machine.NextState := PUSHING; step := 1;\n\t\tPUSHING: Machine.NextState := IDLE; step := 2;\n\t\tIDLE: Machine.NextState := WAITING; step := 3;\n\tEND_CASE;\n\tMachine.ActualState := Machine.NextState;\nEND_PROGRAM\n",
    );
    let stamper = [
        "Logical/Stamper/Main.st",
        "Logical/Stamper/Types.typ",
        "Logical/Stamper/Variables.var",
    ];
    let pusher = [
        "Logical/Pusher/Main.st",
        "Logical/Pusher/Types.typ",
        "Logical/Pusher/Variables.var",
    ];
    let watch = "Stamper.Internal.Count,Stamper.isStamping,Pusher.Internal.Ready,Pusher.Internal.Offset,Pusher.step";
    for files in [[stamper, pusher].concat(), [pusher, stamper].concat()] {
        let (code, out, err) = run_in(root, &files, "4", watch);
        assert_eq!(code, Some(0), "{err}");
        assert!(!err.contains("error["), "{err}");
        assert_eq!(
            column(&out, "Stamper.Internal.Count"),
            vec![1.0, 2.0, 3.0, 4.0]
        );
        assert_eq!(column(&out, "Stamper.isStamping"), vec![1.0, 0.0, 1.0, 0.0]);
        assert_eq!(
            column(&out, "Pusher.Internal.Ready"),
            vec![1.0, 0.0, 1.0, 0.0]
        );
        assert_eq!(
            column(&out, "Pusher.Internal.Offset"),
            vec![0.5, 1.0, 1.5, 2.0]
        );
        assert_eq!(column(&out, "Pusher.step"), vec![1.0, 2.0, 3.0, 1.0]);
    }
}

/// B2: `ProgA`'s `i : INT` and `ProgB`'s `i : REAL`, each in its folder's `Variables.var`: both
/// orders of the files check clean and run alike, `ProgA.x = i / 2 = 3` (INT division) and
/// `ProgB.i = 7.5`. Before: given ProgA then ProgB, E1006 "cannot store REAL into INT" at ProgA's
/// `i := 7;` (Main.st:2:2), the other order clean.
#[test]
fn same_local_name_in_two_programs_keeps_each_type() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write_in(root, "Logical/ProgA/IEC.prg", IEC_PRG);
    write_in(
        root,
        "Logical/ProgA/Variables.var",
        "VAR\n\ti : INT;\n\tx : INT;\nEND_VAR\n",
    );
    write_in(
        root,
        "Logical/ProgA/Main.st",
        "PROGRAM _CYCLIC\n\ti := 7;\n\tx := i / 2;\nEND_PROGRAM\n",
    );
    write_in(root, "Logical/ProgB/IEC.prg", IEC_PRG);
    write_in(
        root,
        "Logical/ProgB/Variables.var",
        "VAR\n\ti : REAL;\nEND_VAR\n",
    );
    write_in(
        root,
        "Logical/ProgB/Main.st",
        "PROGRAM _INIT\n\ti := 0.5;\nEND_PROGRAM\nPROGRAM _CYCLIC\n\ti := i + 7.0;\nEND_PROGRAM\n",
    );
    let a = ["Logical/ProgA/Main.st", "Logical/ProgA/Variables.var"];
    let b = ["Logical/ProgB/Main.st", "Logical/ProgB/Variables.var"];
    for files in [[a, b].concat(), [b, a].concat()] {
        let (code, out, err) = run_in(root, &files, "2", "ProgA.i,ProgA.x,ProgB.i");
        assert_eq!(code, Some(0), "{err}");
        assert!(!err.contains("error["), "{err}");
        assert_eq!(column(&out, "ProgA.i"), vec![7.0, 7.0]);
        assert_eq!(column(&out, "ProgA.x"), vec![3.0, 3.0]);
        assert_eq!(column(&out, "ProgB.i"), vec![7.5, 14.5]);
    }
}

/// A program's `.var` variable `PACK_ML` and its action `Pack_ML` (two names in case-sensitive
/// Automation Studio; one under IEC 61131-3): the variable stays global as before round 34, so
/// the action still runs and counts it (with the variables made the program's own, this was a
/// new E1002 "`Pack_ML` is declared twice: as a variable and as an action").
#[test]
fn variable_named_like_the_programs_action_in_another_case_still_runs() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write_in(root, "Logical/Line/IEC.prg", IEC_PRG);
    write_in(
        root,
        "Logical/Line/Variables.var",
        "VAR\n\tPACK_ML : INT;\n\tcalls : INT;\nEND_VAR\n",
    );
    write_in(
        root,
        "Logical/Line/Action.st",
        "ACTION Pack_ML:\n\tPACK_ML := PACK_ML + 10;\nEND_ACTION\n",
    );
    write_in(
        root,
        "Logical/Line/Main.st",
        "PROGRAM _CYCLIC\n\tPack_ML;\n\tcalls := calls + 1;\nEND_PROGRAM\n",
    );
    let (code, out, err) = run_in(
        root,
        &[
            "Logical/Line/Variables.var",
            "Logical/Line/Action.st",
            "Logical/Line/Main.st",
        ],
        "3",
        "Line.calls",
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("error["), "{err}");
    assert_eq!(column(&out, "Line.calls"), vec![1.0, 2.0, 3.0]);
}

/// B5: a library `.typ` structure with `TargetPosition` and `targetPosition` (as B&R's
/// `acp10_mc.typ` has): one W1463 at the later field (MyLib.typ:4:3), and a program using the
/// kept spelling runs (a B-R-Tetris-like project, whose only error this was). A use spelled as
/// the field taken out is one E1105 at it (Main.st:3:4). Before: E1002 "`targetPosition` is
/// declared twice" at MyLib.typ:4:3, exit 1, with or without a use.
#[test]
fn library_structure_fields_differing_in_case_only() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    write_in(
        root,
        "Logical/Libraries/MyLib/MyLib.typ",
        "TYPE\n\tJogInternalType : STRUCT\n\t\tTargetPosition : DINT;\n\t\ttargetPosition : DINT;\n\t\tVelocity : REAL;\n\tEND_STRUCT;\nEND_TYPE\n",
    );
    write_in(root, "Logical/Game/IEC.prg", IEC_PRG);
    write_in(
        root,
        "Logical/Game/Variables.var",
        "VAR\n\tjog : JogInternalType;\n\tn : DINT;\nEND_VAR\n",
    );
    write_in(
        root,
        "Logical/Game/Main.st",
        "PROGRAM _CYCLIC\n\tjog.TargetPosition := jog.TargetPosition + 5;\n\tn := jog.TargetPosition;\nEND_PROGRAM\n",
    );
    let files = [
        "Logical/Libraries/MyLib/MyLib.typ",
        "Logical/Game/Main.st",
        "Logical/Game/Variables.var",
    ];
    let (code, out, err) = run_in(root, &files, "3", "Game.n");
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("error["), "{err}");
    assert_eq!(err.matches("warning[W1463]").count(), 1, "{err}");
    assert!(
        err.contains("Logical/Libraries/MyLib/MyLib.typ:4:3: warning[W1463]: field `targetPosition` of `JogInternalType` differs from its field `TargetPosition` in case only"),
        "{err}"
    );
    assert_eq!(column(&out, "Game.n"), vec![5.0, 10.0, 15.0]);
    // a use spelled as the field taken out: one error, at it
    write_in(
        root,
        "Logical/Game/Main.st",
        "PROGRAM _CYCLIC\n\tn := n + 1;\n\tjog.targetPosition := n;\nEND_PROGRAM\n",
    );
    let (code, _, err) = run_in(root, &files, "3", "Game.n");
    assert_eq!(code, Some(1), "{err}");
    assert_eq!(err.matches("error[").count(), 1, "{err}");
    assert!(
        err.contains("Logical/Game/Main.st:3:6: error[E1105]: `targetPosition` is the field of `JogInternalType` that differs from `TargetPosition` in case only"),
        "{err}"
    );
}
