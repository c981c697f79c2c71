//! Issue #13, round 17 (helper `stlang`): the ST / CODESYS / TwinCAT language items the last closing
//! note left, each through `ladderc run` on fixtures written here
//! (`tests/tests/fixtures/lang_left_r17/`, see its README for the public projects they reproduce):
//! - **Methods exported one file each** (a CODESYS 3 export script: `Block.st` holds the
//!   FUNCTION_BLOCK, `Block.Method.st` each method, `END_METHOD` and `END_FUNCTION_BLOCK` often
//!   missing; kevin00156/codesys_template_public, greenforge-labs/codescribe): a method file is
//!   joined to the block its name names when that block is among the given files, and runs as if its
//!   text stood inside the block; a property file (`PROPERTY P : T GET ... END_GET END_PROPERTY`)
//!   too. Before: one E1063 per file ("a METHOD outside any FUNCTION_BLOCK"). E1063 stays when no
//!   block of that name is given; a method written both in its block and in a file of its own is
//!   one E1066.
//! - **VAR_STAT** (CODESYS "VAR_STAT"; TwinCAT accepts it too): the static variables of a
//!   FUNCTION_BLOCK, FUNCTION or PROGRAM, one copy shared by every instance and every call, kept
//!   between calls and initialised once; the block's methods see them. They are global variables
//!   `__STAT_<POU>_<NAME>` (the name `--watch` takes). Before: E0011 and E0007 at each declaration,
//!   E0015 at the next block. In a PROPERTY accessor: one E1067 (read as VAR; a METHOD's compiles
//!   since round 18).
//! - **VAR_INST initial values computed from the instance** (TwinCAT): `nSeed : INT :=
//!   THIS^.nBase * 10;`, `pSelf : POINTER TO FB_X := THIS;`, and an instance with one input given
//!   `(ipList := THIS^.fbList)` (fisothemes/TwinCat-Dynamic-Collections' `_Values` accessor): computed
//!   once per instance when it is initialised, before its FB_init, as TwinCAT initialises
//!   declarations. `THIS` alone is the instance's address (`ADR(THIS^)`) anywhere in a block's code.
//!   Before: E0001 at the `^`, E0305 "a reference cannot have the initial value `THIS`".
//! - **A FUNCTION input of type ANY** (`ANY_NUM`, `ANY_INT`, `ANY_REAL`, `ANY_BIT`; CODESYS "ANY
//!   and ANY_<type>"): the function reads the argument's `.diSize` and `.TypeClass` (compared with
//!   `__SYSTEM.TYPE_CLASS.TYPE_INT` ...), calls pass any variable, element or field of the family,
//!   formally or by position. The input read as a value, a literal argument and an argument
//!   outside the family are E1068 (`.pValue` compiles since round 18; before it, a pointer to an unknown type was left: it needs pointer
//!   indexing and casts). Before: E1003 "unknown type `ANY`".

mod common;
use common::{check_files, column, run_stimulated_files, run_traced_files};
use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/lang_left_r17")
        .join(name)
}

// ------------------------------------------------------------------ 1. methods one file each

fn sequencer_files() -> Vec<PathBuf> {
    [
        "Sequencer.st",
        "Sequencer.Advance.st",
        "Sequencer.Raise.st",
        "Sequencer.Reset.st",
        "Sequencer.Busy.st",
        "Valve.st",
        "Valve.Open.st",
        "PLC_PRG.st",
    ]
    .iter()
    .map(|f| fixture(&format!("methods/{f}")))
    .collect()
}

/// methods/: `Sequencer.st` calls `Advance(iBy := 1)` while xExecute; at step 3 it calls
/// `Raise(iErrorID := 42, iNextStep := 1)`, which sets the error, remembers the step to go back to
/// and parks the sequence at 999; `Reset()` (cycle 4, with xExecute FALSE) goes back to step 1. The
/// property `Busy` (its own file) reads step > 0 and no error. `Valve` has no body of its own (all
/// its code is in `Valve.Open.st`): each scan opens it once more.
#[test]
fn methods_exported_one_file_each_run_in_their_block() {
    let (trace, _) = run_stimulated_files(
        &sequencer_files(),
        &[],
        7,
        "4,PLC_PRG.xClear,1\n4,PLC_PRG.xRun,0\n5,PLC_PRG.xClear,0\n",
        "PLC_PRG.seq.iStep,PLC_PRG.seq.xError,PLC_PRG.seq.iErrorID,PLC_PRG.xBusy,PLC_PRG.iOpened",
    );
    assert_eq!(
        column(&trace, "PLC_PRG.seq.iStep"),
        [1., 2., 999., 999., 1., 1., 1.]
    );
    assert_eq!(
        column(&trace, "PLC_PRG.seq.xError"),
        [0., 0., 1., 1., 0., 0., 0.]
    );
    assert_eq!(
        column(&trace, "PLC_PRG.seq.iErrorID"),
        [0., 0., 42., 42., 0., 0., 0.]
    );
    assert_eq!(
        column(&trace, "PLC_PRG.xBusy"),
        [1., 1., 0., 0., 1., 1., 1.]
    );
    assert_eq!(
        column(&trace, "PLC_PRG.iOpened"),
        [1., 2., 3., 4., 5., 6., 7.]
    );
}

/// A block that EXTENDS one whose methods are files of their own inherits them (the base's method
/// runs on the derived instance), and an error inside a method file is located in that file.
#[test]
fn an_exported_method_is_inherited_and_its_errors_point_into_its_file() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    let files = [
        write(
            "Tank.st",
            "FUNCTION_BLOCK Tank\nVAR\n    rLevel : REAL;\nEND_VAR\n",
        ),
        write(
            "Tank.Fill.st",
            "METHOD Fill\nVAR_INPUT\n    rBy : REAL;\nEND_VAR\nrLevel := rLevel + rBy;\n",
        ),
        write(
            "BigTank.st",
            "FUNCTION_BLOCK BigTank EXTENDS Tank\nVAR_OUTPUT seen : REAL; END_VAR\n\
             Fill(rBy := 1.5);\nseen := rLevel;\nEND_FUNCTION_BLOCK\n",
        ),
        write(
            "main.st",
            "PROGRAM main\nVAR b : BigTank; END_VAR\nb();\nEND_PROGRAM\n",
        ),
    ];
    let refs: Vec<&Path> = files.iter().map(|p| p.as_path()).collect();
    let (trace, _) = run_traced_files(&refs, 3, "main.b.seen");
    assert_eq!(column(&trace, "main.b.seen"), [1.5, 3., 4.5]);
    let (code, errors) = check_files(&[
        (
            "Tank.st",
            "FUNCTION_BLOCK Tank\nVAR\n    rLevel : REAL;\nEND_VAR\nFill();\n",
        ),
        (
            "Tank.Fill.st",
            "METHOD Fill\nrLevel := rLevel + 1.0;\nundeclared := 1;\n",
        ),
    ]);
    assert_eq!(code, Some(1));
    assert_eq!(
        errors,
        ["Tank.Fill.st:3:1: error[E1001]: undeclared name `undeclared`"]
    );
}

/// Without its block among the given files (given alone, or its name naming no block), a method
/// file stays one E1063 at its header; a method both inside its block and in a file of its own is
/// one E1066 at the file's copy, which is not compiled.
#[test]
fn a_method_file_without_its_block_or_written_twice_is_one_located_error() {
    let (code, errors) =
        check_files(&[("Motor.Start.st", "METHOD Start : BOOL\nStart := TRUE;\n")]);
    assert_eq!(code, Some(1));
    assert_eq!(
        errors,
        ["Motor.Start.st:1:1: error[E1063]: a METHOD outside any FUNCTION_BLOCK"]
    );
    let block = "FUNCTION_BLOCK Motor\nVAR on : BOOL; END_VAR\nMETHOD Start : BOOL\non := TRUE;\n\
                 END_METHOD\nEND_FUNCTION_BLOCK\n";
    let (code, errors) = check_files(&[
        ("Motor.st", block),
        ("Pump.Start.st", "METHOD Start : BOOL\nStart := TRUE;\n"),
        ("Motor.Start.st", "METHOD Start : BOOL\non := FALSE;\n"),
    ]);
    assert_eq!(code, Some(1));
    assert_eq!(
        errors,
        [
            "Pump.Start.st:1:1: error[E1063]: a METHOD outside any FUNCTION_BLOCK",
            "Motor.Start.st:1:8: error[E1066]: `Start` of `Motor` is written twice: in the block and in a file of its own",
        ]
    );
}

// ------------------------------------------------------------------ 2. VAR_STAT

/// var_stat.st: two FB_Station instances draw tickets from one counter (`nNextTicket`, a static of
/// the block, initialised once to 100, incremented by the block's method `Take`): A gets 101, B
/// 102, then 103 and 104 ...; the first-scan flag kept in VAR_STAT is TRUE for the very first
/// call of any instance only (stA in cycle 0). `aLast` is shared too. F_Total's static `dTotal`
/// sums over every call while its VAR `dCall` starts again at each call: 2, then 2 + 3 = 5 in
/// the first scan, 10 and 15 after.
#[test]
fn var_stat_is_one_copy_for_every_instance_and_call() {
    let (trace, _) = common::run_traced(
        &fixture("var_stat.st"),
        3,
        "Main.stA.nTicket,Main.stB.nTicket,Main.stA.xFirst,Main.stB.xFirst,Main.dSum,\
         __STAT_FB_STATION_ALAST[0],__STAT_FB_STATION_ALAST[1],__STAT_F_TOTAL_DTOTAL",
    );
    assert_eq!(column(&trace, "Main.stA.nTicket"), [101., 103., 105.]);
    assert_eq!(column(&trace, "Main.stB.nTicket"), [102., 104., 106.]);
    assert_eq!(column(&trace, "Main.stA.xFirst"), [1., 0., 0.]);
    assert_eq!(column(&trace, "Main.stB.xFirst"), [0., 0., 0.]);
    assert_eq!(
        column(&trace, "__STAT_FB_STATION_ALAST[0]"),
        [101., 103., 105.]
    );
    assert_eq!(
        column(&trace, "__STAT_FB_STATION_ALAST[1]"),
        [102., 104., 106.]
    );
    assert_eq!(column(&trace, "Main.dSum"), [5., 10., 15.]);
    assert_eq!(column(&trace, "__STAT_F_TOTAL_DTOTAL"), [5., 10., 15.]);
}

/// A VAR_STAT block of a PROPERTY accessor is one E1067 at its keyword; nothing else is reported
/// (the block is read as VAR). A METHOD's VAR_STAT compiles since round 18
/// (`tests/tests/lang_left_r18.rs`).
#[test]
fn var_stat_in_a_property_accessor_is_one_e1067() {
    let (code, errors) = check_files(&[(
        "counter.st",
        "FUNCTION_BLOCK Counter\nVAR\n    n : INT;\nEND_VAR\nPROPERTY Calls : INT\nGET\nVAR_STAT\n    nCalls : INT;\nEND_VAR\n\
         nCalls := nCalls + 1;\nCalls := nCalls;\nEND_GET\nEND_PROPERTY\nEND_FUNCTION_BLOCK\n",
    )]);
    assert_eq!(code, Some(1));
    assert_eq!(
        errors,
        ["counter.st:7:1: error[E1067]: VAR_STAT in a PROPERTY accessor is not supported"]
    );
}

// ------------------------------------------------------------------ 3. VAR_INST := THIS ...

/// var_inst_this.st: `Next`'s `nSeed := THIS^.nBase * 10` is computed when each instance is
/// initialised (a: nBase 7 -> 70; b, declared `(nBase := 2)` -> 20), before the body first adds 1
/// to nBase, then counts up by one per call; `pSelf := THIS` points at the calling instance, whose
/// nVisits it counts. `_Values`' VAR_INST view gets `ipList := THIS^.fbList` once and reads the
/// list's count through the interface (1, 2, 3 as fbList counts its calls).
#[test]
fn var_inst_initial_values_from_this_are_computed_once_per_instance() {
    let (trace, _) = common::run_traced(
        &fixture("var_inst_this.st"),
        3,
        "Main.ra,Main.rb,Main.ca,Main.a.nVisits,Main.b.nVisits",
    );
    assert_eq!(column(&trace, "Main.ra"), [71., 72., 73.]);
    assert_eq!(column(&trace, "Main.rb"), [21., 22., 23.]);
    assert_eq!(column(&trace, "Main.ca"), [1., 2., 3.]);
    assert_eq!(column(&trace, "Main.a.nVisits"), [1., 2., 3.]);
    assert_eq!(column(&trace, "Main.b.nVisits"), [1., 2., 3.]);
}

/// The VAR_INST initial value is computed before the block's FB_init (TwinCAT initialises the
/// declarations first): FB_init sets nBase to 100 after `n := THIS^.nBase` took 7; an instance in
/// an array is initialised the same way.
#[test]
fn var_inst_initial_values_are_computed_before_fb_init() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("fbi.st");
    std::fs::write(
        &f,
        "FUNCTION_BLOCK FB_A\nVAR nBase : INT := 7; END_VAR\nMETHOD FB_init : BOOL\n\
         VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; END_VAR\nnBase := 100;\nEND_METHOD\n\
         METHOD Seed : INT\nVAR_INST n : INT := THIS^.nBase; END_VAR\nSeed := n;\nEND_METHOD\n\
         END_FUNCTION_BLOCK\nPROGRAM main\nVAR a : FB_A; arr : ARRAY[0..1] OF FB_A; r, r1 : INT; END_VAR\n\
         r := a.Seed();\nr1 := arr[1].Seed();\nEND_PROGRAM\n",
    )
    .unwrap();
    let (trace, _) = common::run_traced(&f, 1, "main.r,main.r1,main.a.nBase");
    assert_eq!(column(&trace, "main.r"), [7.]);
    assert_eq!(column(&trace, "main.r1"), [7.]);
    assert_eq!(column(&trace, "main.a.nBase"), [100.]);
}

// ------------------------------------------------------------------ 4. ANY inputs

/// any_input.st: F_Describe sees each argument's class and size: INT i (2 bytes) 1002, LREAL r
/// (8) 2008, ARRAY[0..9] OF BYTE (10) 3010, STRING 4000, an element `buf[2]` (a BYTE) 9001; each
/// plus its nTag * 10000, given formally, in another order or by position. F_Bytes (ANY_NUM):
/// 8 + 2.
#[test]
fn an_any_input_sees_the_size_and_class_of_its_argument() {
    let (trace, _) = common::run_traced(
        &fixture("any_input.st"),
        1,
        "Main.nInt,Main.nReal,Main.nArr,Main.nStr,Main.nPos,Main.nBytes",
    );
    assert_eq!(column(&trace, "Main.nInt"), [11002.]);
    assert_eq!(column(&trace, "Main.nReal"), [22008.]);
    assert_eq!(column(&trace, "Main.nArr"), [33010.]);
    assert_eq!(column(&trace, "Main.nStr"), [44000.]);
    assert_eq!(column(&trace, "Main.nPos"), [59001.]);
    assert_eq!(column(&trace, "Main.nBytes"), [10.]);
}

/// What an ANY input does not compile is one E1068 each: the input read as a value (kevin00156's
/// Clear hands `ADR(In)` and `SIZEOF(In)` to SysMemSet; `.pValue` compiles since round 18,
/// `tests/tests/lang_left_r18.rs`), once per input of the
/// function however often it is used; a BOOL given to an ANY_NUM input; an expression given to an
/// ANY input.
#[test]
fn what_an_any_input_does_not_compile_is_one_e1068_each() {
    let (code, errors) = check_files(&[(
        "any_bad.st",
        "FUNCTION Clear : BOOL\nVAR_INPUT\n    In : ANY;\nEND_VAR\nMEMSET(In.pValue, 0, In.diSize);\n\
         Clear := SIZEOF(In) > 0;\nEND_FUNCTION\nFUNCTION F_Num : DINT\nVAR_INPUT v : ANY_NUM; END_VAR\n\
         F_Num := v.diSize;\nEND_FUNCTION\nPROGRAM Main\nVAR x : INT; b : BOOL; r : DINT; END_VAR\n\
         b := Clear(x);\nr := F_Num(b);\nr := F_Num(3 + x);\nEND_PROGRAM\n",
    )]);
    assert_eq!(code, Some(1));
    assert_eq!(
        errors,
        [
            "any_bad.st:6:17: error[E1068]: `In` of `Clear` is an ANY input: it is read through `.diSize`, `.TypeClass` and `.pValue`, not as a value",
            "any_bad.st:15:12: error[E1068]: the input `v` of `F_Num` is ANY_NUM: `BOOL` is not one of its types",
            "any_bad.st:16:12: error[E1068]: the ANY input `v` of `F_Num` takes a variable",
        ]
    );
}
