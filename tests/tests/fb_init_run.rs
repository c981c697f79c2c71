//! CODESYS's and TwinCAT's FB_init (issue #13), run end to end through `ladderc run` on files
//! written for these tests (`fixtures/fb_init/`): every instance's FB_init runs once before the
//! first cycle, with `bInitRetains = TRUE, bInCopyCode = FALSE` (a cold start) and the arguments
//! of its declaration (`fb : FB_X(nId := 1)`, positional or named); instances in a global list, a
//! program, an array, and inside another block (inner first); for a derived block its bases'
//! FB_init first; `THIS^.x` inside FB_init is the block's `x` where an input has the same name.
//! FB_exit and FB_reinit are never called (note W0345). Arguments that go nowhere are one E0329
//! each; a huge array of such instances is E0345. METHODs and PROPERTYs of a PROGRAM run on its one
//! instance, called inside it or as `PRG.M(x)` from another POU (also of another TwinCAT object).
//! `{attribute 'call_after_init'}` methods run after FB_init and the structured initial values.

mod common;
use common::{check_text, column, rejected_heads, run_traced, run_traced_files};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/fb_init")
        .join(rel)
}

/// `instances.st`: the global `gCounter` first (id 1), then MAIN's `fbMain` (2), `fbPair`'s inner
/// `fbLeft` (3) and `fbRight` (4) before `fbPair` itself (5), then the three array elements (id 0):
/// the log reads 1 2 3 4 5 0 0 0 before the first cycle and never changes.
#[test]
fn every_instance_runs_its_fb_init_once_before_the_first_cycle() {
    let (trace, stderr) = run_traced(
        &fixture("instances.st"),
        3,
        "nLog,gCounter.nValue,gCounter.nInits,MAIN.fbMain.nValue,MAIN.fbMain.nInits,\
         MAIN.fbMain.nId,MAIN.fbMain.bRetains,MAIN.fbMain.bCopy,MAIN.fbMain.nStepSeen,MAIN.nFirst,\
         MAIN.fbPair.nSum,MAIN.fbPair.fbLeft.nValue,MAIN.fbPair.fbRight.nValue,\
         MAIN.fbPair.fbRight.nId,MAIN.aCounters[1].nInits,MAIN.aCounters[3].nInits,\
         MAIN.aCounters[2].nValue",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "nLog"), [12345000.0; 3]);
    // the global instance: nStart := 100, then one step per cycle
    assert_eq!(column(&trace, "gCounter.nValue"), [101.0, 102.0, 103.0]);
    assert_eq!(column(&trace, "gCounter.nInits"), [1.0; 3]);
    // named arguments in another order than FB_init's inputs; THIS^.nId is the block's nId
    assert_eq!(column(&trace, "MAIN.fbMain.nId"), [2.0; 3]);
    assert_eq!(column(&trace, "MAIN.nFirst"), [7.0; 3]);
    assert_eq!(column(&trace, "MAIN.fbMain.nValue"), [9.0, 11.0, 13.0]);
    assert_eq!(column(&trace, "MAIN.fbMain.nInits"), [1.0; 3]);
    // a cold start, after the initial values (bCopy starts TRUE, nStep := 1)
    assert_eq!(column(&trace, "MAIN.fbMain.bRetains"), [1.0; 3]);
    assert_eq!(column(&trace, "MAIN.fbMain.bCopy"), [0.0; 3]);
    assert_eq!(column(&trace, "MAIN.fbMain.nStepSeen"), [1.0; 3]);
    // the inner instances (positional arguments for fbRight) before the outer block's FB_init
    assert_eq!(column(&trace, "MAIN.fbPair.nSum"), [70.0; 3]);
    assert_eq!(
        column(&trace, "MAIN.fbPair.fbLeft.nValue"),
        [31.0, 32.0, 33.0]
    );
    assert_eq!(
        column(&trace, "MAIN.fbPair.fbRight.nValue"),
        [41.0, 42.0, 43.0]
    );
    assert_eq!(column(&trace, "MAIN.fbPair.fbRight.nId"), [4.0; 3]);
    // every element of the array, without arguments
    assert_eq!(column(&trace, "MAIN.aCounters[1].nInits"), [1.0; 3]);
    assert_eq!(column(&trace, "MAIN.aCounters[3].nInits"), [1.0; 3]);
    assert_eq!(column(&trace, "MAIN.aCounters[2].nValue"), [1.0, 2.0, 3.0]);
}

/// `extends.st`, under a configuration: FB_Mid inherits FB_Base's FB_init (trace 1); FB_Top runs
/// FB_Base's then its own (trace 13); FB_Base's version got `nAxis` (7) before FB_Top's read it.
#[test]
fn a_derived_blocks_bases_run_their_fb_init_first() {
    let (trace, stderr) = run_traced(
        &fixture("extends.st"),
        2,
        "cell1.fbMid.nTrace,cell1.fbMid.nAxis,cell1.fbTop.nTrace,cell1.fbTop.nAxis,\
         cell1.fbTop.nGear,cell1.fbTop.nCalls",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "cell1.fbMid.nTrace"), [1.0, 1.0]);
    assert_eq!(column(&trace, "cell1.fbMid.nAxis"), [4.0, 4.0]);
    assert_eq!(column(&trace, "cell1.fbTop.nTrace"), [13.0, 13.0]);
    assert_eq!(column(&trace, "cell1.fbTop.nAxis"), [7.0, 7.0]);
    assert_eq!(column(&trace, "cell1.fbTop.nGear"), [21.0, 21.0]);
    assert_eq!(column(&trace, "cell1.fbTop.nCalls"), [1.0, 2.0]);
    // the program instantiated twice: its instances' FB_init is not run, one E0347
    let src = std::fs::read_to_string(fixture("extends.st"))
        .unwrap()
        .replace(
            "PROGRAM cell1 WITH Fast : Cell;",
            "PROGRAM cell1 WITH Fast : Cell; PROGRAM cell2 WITH Fast : Cell;",
        );
    assert_eq!(
        rejected_heads("two.st", &src),
        ["two.st:58:49: error[E0347]: program `Cell` has 2 instances (`cell1`, `cell2`): the FB_init of the instances it declares is not run"]
    );
}

/// TwinCAT objects: the `<Method Name="FB_init">` of a `.TcPOU` runs with the declaration's
/// argument (the valve stops at 30); its FB_exit is never called, which a note says; MAIN calls
/// the method of a program of another object file (`PRG_Counter.Bump(nBy := 2)`).
#[test]
fn twincat_fb_init_runs_and_fb_exit_is_a_note() {
    let files = [
        fixture("twincat/FB_Valve.TcPOU"),
        fixture("twincat/MAIN.TcPOU"),
        fixture("twincat/PRG_Counter.TcPOU"),
    ];
    let files: Vec<&Path> = files.iter().map(PathBuf::as_path).collect();
    let (trace, stderr) = run_traced_files(
        &files,
        4,
        "MAIN.fbValve.nPosition,MAIN.fbValve.nMax,MAIN.nBumped,PRG_Counter.nCount",
    );
    assert_eq!(column(&trace, "MAIN.nBumped"), [2.0, 4.0, 6.0, 8.0]);
    assert_eq!(column(&trace, "PRG_Counter.nCount"), [2.0, 4.0, 6.0, 8.0]);
    assert_eq!(column(&trace, "MAIN.fbValve.nMax"), [30.0; 4]);
    assert_eq!(
        column(&trace, "MAIN.fbValve.nPosition"),
        [10.0, 20.0, 30.0, 30.0]
    );
    let notes: Vec<&str> = stderr.lines().filter(|l| l.contains("[W0345]")).collect();
    assert_eq!(notes.len(), 1, "{stderr}");
    assert!(
        notes[0].contains("FB_Valve.TcPOU:35:")
            && notes[0].contains("`FB_Valve.FB_exit` is never called in a simulation"),
        "{stderr}"
    );
}

/// `program_methods.st`: PRG_Tank drains itself through its own method `Drain(1)`; PRG_Pump
/// fills it through `PRG_Tank.Fill(nAmount := 30)` (the result is the room left) and, once full,
/// lowers its limit through the property `PRG_Tank.Limit := 50` (read back as `nSeen`).
#[test]
fn methods_and_properties_of_a_program_run_on_its_one_instance() {
    let (trace, stderr) = run_traced(
        &fixture("program_methods.st"),
        6,
        "PRG_Tank.nLevel,PRG_Tank.nFills,PRG_Tank.nLimit,PRG_Pump.nRoom,PRG_Pump.nSeen",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(
        column(&trace, "PRG_Tank.nLevel"),
        [30.0, 59.0, 88.0, 100.0, 50.0, 50.0]
    );
    assert_eq!(
        column(&trace, "PRG_Tank.nFills"),
        [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
    );
    assert_eq!(
        column(&trace, "PRG_Pump.nRoom"),
        [70.0, 41.0, 12.0, 0.0, 0.0, 0.0]
    );
    assert_eq!(
        column(&trace, "PRG_Tank.nLimit"),
        [100.0, 100.0, 100.0, 50.0, 50.0, 50.0]
    );
    assert_eq!(
        column(&trace, "PRG_Pump.nSeen"),
        [100.0, 100.0, 100.0, 100.0, 50.0, 50.0]
    );
}

/// `after_init.st`: FB_init sets a default setpoint; the declaration's structured initial value
/// (`:= (nSetpoint := 180)`) is set again after FB_init; then the call_after_init method runs and
/// finds it (180; 20 where the declaration gives none); order 1 then 2, once each.
#[test]
fn call_after_init_methods_run_after_fb_init_and_the_initial_values() {
    let (trace, stderr) = run_traced(
        &fixture("after_init.st"),
        2,
        "MAIN.fbOven.nSetpoint,MAIN.fbOven.nChecked,MAIN.fbOven.nOrder,MAIN.fbOven.nDefaults,\
         MAIN.fbRoom.nSetpoint,MAIN.fbRoom.nChecked,MAIN.fbRoom.nOrder",
    );
    assert!(
        !stderr.contains("error") && !stderr.contains("W0301"),
        "{stderr}"
    );
    assert_eq!(column(&trace, "MAIN.fbOven.nSetpoint"), [180.0; 2]);
    assert_eq!(column(&trace, "MAIN.fbOven.nChecked"), [180.0; 2]);
    assert_eq!(column(&trace, "MAIN.fbOven.nOrder"), [12.0; 2]);
    assert_eq!(column(&trace, "MAIN.fbOven.nDefaults"), [1.0; 2]);
    assert_eq!(column(&trace, "MAIN.fbRoom.nSetpoint"), [20.0; 2]);
    assert_eq!(column(&trace, "MAIN.fbRoom.nChecked"), [20.0; 2]);
    assert_eq!(column(&trace, "MAIN.fbRoom.nOrder"), [12.0; 2]);
}

/// A call_after_init method with an input is E0346; one marked in a block without the attribute
/// is W0346 and not called.
#[test]
fn a_call_after_init_method_with_inputs_or_alone_is_located() {
    let with_input = "{attribute 'call_after_init'}\nFUNCTION_BLOCK FB_A\nVAR n : INT; END_VAR\n\
{attribute 'call_after_init'}\nMETHOD Prepare\nVAR_INPUT k : INT; END_VAR\nn := k;\nEND_METHOD\n\
END_FUNCTION_BLOCK\nPROGRAM Main\nVAR a : FB_A; END_VAR\nEND_PROGRAM\n";
    assert_eq!(
        rejected_heads("ai.st", with_input),
        ["ai.st:5:8: error[E0346]: method `Prepare` of `FB_A` is marked call_after_init but has inputs"]
    );
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("alone.st");
    std::fs::write(
        &f,
        "FUNCTION_BLOCK FB_A\nVAR n : INT; END_VAR\n{attribute 'call_after_init'}\nMETHOD Prepare\n\
n := 5;\nEND_METHOD\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR a : FB_A; END_VAR\nEND_PROGRAM\n",
    )
    .unwrap();
    let (trace, stderr) = run_traced(&f, 1, "Main.a.n");
    assert_eq!(column(&trace, "Main.a.n"), [0.0]);
    assert!(
        stderr.contains("alone.st:4:8: warning[W0346]: method `Prepare` is marked call_after_init, but `FB_A` is not"),
        "{stderr}"
    );
}

/// An instance in a structure's field, in an array field of a structure, in an array of
/// structures: each runs its FB_init once. FB_init arguments on a structure are E0329.
#[test]
fn instances_inside_structures_are_initialised() {
    let src = "FUNCTION_BLOCK FB_X\nVAR nInits : INT; END_VAR\nMETHOD FB_init : BOOL\n\
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; END_VAR\nnInits := nInits + 1;\nEND_METHOD\n\
END_FUNCTION_BLOCK\nTYPE ST_Axis : STRUCT\n  n : INT;\n  fb : FB_X;\n  more : ARRAY[0..1] OF FB_X;\n\
END_STRUCT; END_TYPE\nPROGRAM Main\nVAR s : ST_Axis; a : ARRAY[1..2] OF ST_Axis; END_VAR\nEND_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("structs.st");
    std::fs::write(&f, src).unwrap();
    let watch = "Main.s.fb.nInits,Main.s.more[0].nInits,Main.s.more[1].nInits,Main.a[1].fb.nInits,\
                 Main.a[2].fb.nInits,Main.a[2].more[0].nInits,Main.a[2].more[1].nInits";
    let (trace, _) = run_traced(&f, 2, watch);
    for name in watch.split(',') {
        assert_eq!(column(&trace, name), [1.0, 1.0], "{name}");
    }
    assert_eq!(
        rejected_heads(
            "bad.st",
            "TYPE ST_A : STRUCT n : INT; END_STRUCT; END_TYPE\nPROGRAM Main\nVAR bad : ST_A(3); END_VAR\nEND_PROGRAM\n"
        ),
        ["bad.st:3:15: error[E0329]: `ST_A` is a structure: FB_init arguments go to function block instances"]
    );
}

const FB_X: &str = "FUNCTION_BLOCK FB_X\nVAR a : INT; END_VAR\nMETHOD FB_init : BOOL\n\
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; nSize : INT; END_VAR\na := nSize;\nEND_METHOD\n\
END_FUNCTION_BLOCK\nFUNCTION_BLOCK FB_Plain\nVAR a : INT; END_VAR\nEND_FUNCTION_BLOCK\n";

/// Each argument list, or argument, with no FB_init input to go to is one E0329 at it: a name
/// FB_init does not have, one positional argument too many, a block without FB_init (also a
/// standard block); an array of more than 4096 instances to initialise is E0345. (An array's
/// arguments, `w` here, go to each element since the round on call chains: `oop_chains_run.rs`.)
/// The instances without such problems still compile (checked by the run below).
#[test]
fn arguments_that_go_nowhere_are_one_e0329_each() {
    let src = format!(
        "{FB_X}PROGRAM Main\nVAR\n  x : FB_X(nSiz := 5);\n  y : FB_X(1, 2);\n  z : FB_Plain(3);\n  \
         w : ARRAY[1..2] OF FB_X(4);\n  t : TON(1);\n  big : ARRAY[1..5000] OF FB_X;\n  \
         ok : FB_X(nSize := 6);\nEND_VAR\nEND_PROGRAM\n"
    );
    assert_eq!(
        rejected_heads("args.st", &src),
        [
            "args.st:13:12: error[E0329]: argument `nSiz`: the FB_init method of `FB_X` has no such input",
            "args.st:14:15: error[E0329]: the FB_init method of `FB_X` takes 1 argument(s) in a declaration",
            "args.st:15:15: error[E0329]: `FB_Plain` has no FB_init method to take these arguments",
            "args.st:17:10: error[E0329]: `TON` has no FB_init method to take these arguments",
            "args.st:18:3: error[E0345]: `big` holds 5000 instances of `FB_X` whose FB_init ladderc would run one by one",
        ]
    );
    // the one right declaration alone runs
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("ok.st");
    std::fs::write(
        &f,
        format!("{FB_X}PROGRAM Main\nVAR ok : FB_X(nSize := 6); END_VAR\nEND_PROGRAM\n"),
    )
    .unwrap();
    let (trace, _) = run_traced(&f, 1, "Main.ok.a");
    assert_eq!(column(&trace, "Main.ok.a"), [6.0]);
    // `PROGRAM INTERNAL Main` (TwinCAT, fisothemes/TwinCat-Dynamic-Collections): the modifier is
    // W0304, the program compiles and its instance is initialised
    std::fs::write(
        &f,
        format!("{FB_X}PROGRAM INTERNAL Main\nVAR ok : FB_X(nSize := 8); END_VAR\nEND_PROGRAM\n"),
    )
    .unwrap();
    let (trace, stderr) = run_traced(&f, 1, "Main.ok.a");
    assert_eq!(column(&trace, "Main.ok.a"), [8.0]);
    assert!(
        stderr.contains("warning[W0304]: `PROGRAM INTERNAL` of `Main`: the modifier is ignored"),
        "{stderr}"
    );
    // a block without FB_init and without arguments is untouched
    let (code, lines) = check_text(
        "plain.st",
        &format!("{FB_X}PROGRAM Main\nVAR p : FB_Plain; END_VAR\nEND_PROGRAM\n"),
    );
    assert_eq!(code, Some(0), "{lines:?}");
}
