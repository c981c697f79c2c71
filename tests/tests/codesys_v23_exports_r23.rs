//! Round 23 of unseen projects (issue #13): CODESYS V2.3 text exports (`.EXP`, "Project > Export")
//! and the detection of a text's language, run end to end through `ladderc`:
//! - the exports of objects that hold no code (a visualisation, the PLC configuration, the alarm
//!   configuration, the workspace, a library reference) are skipped with one note W1442 each, and
//!   the task configuration (`RESOURCE` / `TASK main (PRIORITY := 1, INTERVAL := T#20ms);` /
//!   `PLC_PRG();` / `END_TASK` / `END_RESOURCE`) is read as the project's tasks: its period is the
//!   scan cycle (before: each file read as IL, one E0011 per line, up to 195 in a project);
//! - an array's initial value without brackets (`:= 1, 2, 2(5)`, `:= 3(7)`), the form of
//!   CODESYS V2.3 and TwinCAT 2, means what it means in brackets (before: E0011);
//! - `ACTION name:` ... `END_ACTION` after a POU's `END_FUNCTION_BLOCK` (how V2.3 exports a POU's
//!   actions) is an action of that POU (before: E0307, and the rest of a whole-project export
//!   dropped);
//! - a text that holds only declarations (a GVL `VAR_GLOBAL` list, a `TYPE` export, a `NAMESPACE`
//!   holding a TYPE) is detected as ST, so `POINTER TO` reads (before: detected as IL, E0011 at
//!   `TO`; E1019 "unknown function `NAMESPACE`");
//! - a line of stray text before a POU in a `.st` file whose last word is `function` is one error
//!   at the stray text, and the FUNCTION after it is read as ST (before: the function read as IL,
//!   7 errors for one cause);
//! - a POU whose body V2.3 exported in CFC (`_CFC_BODY` then `_ELEMENT` records; also `_LD_BODY`,
//!   `_FBD_BODY`) is one E0321 at that line, the body skipped up to `END_FUNCTION_BLOCK` (before:
//!   about 50 E0011, each record line read as IL).

mod common;
use common::*;

const PLC_PRG_EXP: &str = "(* @NESTEDCOMMENTS := 'Yes' *)
(* @PATH := '' *)
(* @OBJECTFLAGS := '0, 8' *)
PROGRAM PLC_PRG
VAR
    n : INT;
END_VAR
(* @END_DECLARATION := '0' *)
n := n + 1;
END_PROGRAM
";

const TASKS_EXP: &str = "
RESOURCE

TASK main (PRIORITY := 1, INTERVAL := T#20ms);
PLC_PRG();
{Additional_info : 1,0,0,0,1,4294967295}
END_TASK

END_RESOURCE
";

/// The non-code exports are skipped with one note each, and the task configuration's 20 ms task
/// runs PLC_PRG: the trace's time advances 20 ms a cycle.
#[test]
fn non_code_exports_are_skipped_and_the_task_configuration_is_read() {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "PLC_PRG.EXP", PLC_PRG_EXP);
    write_in(dir.path(), "TASKS.EXP", TASKS_EXP);
    write_in(
        dir.path(),
        "VISU.EXP",
        "(* @PATH := '' *)\n\nVISUALISATION panel _VISU_TYPES : 1,1\n_BG_BMP : ''\n_TEXT : 12\n\
         _VISUGROUP : 0\n_POS : 10,10,200,100,105,55\n_VARIABLES : 'PLC_PRG.n','',''\n_END_ELEM\n\
         END_VISUALISATION\n",
    );
    write_in(
        dir.path(),
        "PLC_CONFIG.EXP",
        "\nPLC_CONFIGURATION\n_GLOBAL\n_VERSION: 3\n_END_GLOBAL\n_MODULE: '3S'\n_IECIN: %IB0\n\
         _END_MODULE\nPLC_END\n",
    );
    write_in(
        dir.path(),
        "STDLIB.EXP",
        "LIBRARY\nSTANDARD.LIB 4.10.05 11:14:46\nNumOfPOUs: 1\nTON: 0\nNumOfGVLs: 0\nEND_LIBRARY\n",
    );
    write_in(
        dir.path(),
        "ALARMS.EXP",
        "\n_ALARMCONFIG\n_ALARMCONFIGNEXTTEXTID : 10002\n_ALARMCLASSLIST : 1\n_END_ALARMCONFIG\n",
    );
    write_in(
        dir.path(),
        "WORKSPACE.EXP",
        "\n_WORKSPACE\n_GLOBALVISUALSETTINGS\n_END_GLOBALVISUALSETTINGS\n_END_WORKSPACE\n",
    );
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "PLC_PRG.EXP",
            "TASKS.EXP",
            "VISU.EXP",
            "PLC_CONFIG.EXP",
            "STDLIB.EXP",
            "ALARMS.EXP",
            "WORKSPACE.EXP",
            "--cycles",
            "3",
            "--trace",
            "-",
            "--watch",
            "PLC_PRG.n",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("E0011"), "{stderr}");
    assert_eq!(stderr.matches("note[W1442]").count(), 5, "{stderr}");
    for what in [
        "VISU.EXP:3:1: note[W1442]: a visualisation (`panel`)",
        "PLC_CONFIG.EXP:2:1: note[W1442]: the PLC configuration",
        "STDLIB.EXP:1:1: note[W1442]: a library reference (`STANDARD.LIB`)",
        "ALARMS.EXP:2:1: note[W1442]: the alarm configuration",
        "WORKSPACE.EXP:2:1: note[W1442]: the workspace options",
    ] {
        assert!(stderr.contains(what), "{what}: {stderr}");
    }
    assert_eq!(column(&trace, "PLC_PRG.n"), [1.0, 2.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "time_ms"), [0.0, 20.0, 40.0], "{trace}");
}

/// A task without INTERVAL (free-wheeling) is one note W1443 at its name, and its programs run.
#[test]
fn a_task_without_interval_is_one_note() {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "PLC_PRG.EXP", PLC_PRG_EXP);
    write_in(
        dir.path(),
        "TASKS.EXP",
        "RESOURCE\nTASK free (PRIORITY := 1);\nPLC_PRG();\nEND_TASK\nEND_RESOURCE\n",
    );
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "PLC_PRG.EXP",
            "TASKS.EXP",
            "--cycles",
            "2",
            "--trace",
            "-",
            "--watch",
            "PLC_PRG.n",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stderr.contains("TASKS.EXP:2:6: note[W1443]"), "{stderr}");
    assert_eq!(column(&trace, "PLC_PRG.n"), [1.0, 2.0], "{trace}");
}

/// A whole-project export: a POU, its action after END_FUNCTION_BLOCK, a visualisation, the task
/// configuration and the workspace in one file; the code is read, the rest skipped.
#[test]
fn a_whole_project_export_reads_its_code_and_tasks() {
    let src = "(* @NESTEDCOMMENTS := 'Yes' *)
FUNCTION_BLOCK FB_Step
VAR_OUTPUT
    nStep : INT := 1;
END_VAR
(* @END_DECLARATION := '0' *)
IF nStep > 3 THEN
    nStep := 1;
END_IF
END_FUNCTION_BLOCK
ACTION\tacNext:
nStep := nStep + 1;
END_ACTION

(* @NESTEDCOMMENTS := 'Yes' *)
PROGRAM PLC_PRG
VAR
    fb : FB_Step;
    s : INT;
END_VAR
(* @END_DECLARATION := '0' *)
fb.acNext();
fb();
s := fb.nStep;
END_PROGRAM

(* @PATH := '' *)
VISUALISATION graf _VISU_TYPES : 1,1
_VISUGROUP : 0
_END_ELEM
END_VISUALISATION

RESOURCE
TASK main (PRIORITY := 1, INTERVAL := T#5ms);
PLC_PRG();
END_TASK
END_RESOURCE

_WORKSPACE
_END_WORKSPACE
";
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "PROJECT.EXP", src);
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "PROJECT.EXP",
            "--cycles",
            "4",
            "--trace",
            "-",
            "--watch",
            "PLC_PRG.s",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(stderr.matches("note[W1442]").count(), 2, "{stderr}");
    assert_eq!(column(&trace, "PLC_PRG.s"), [2.0, 3.0, 1.0, 2.0], "{trace}");
    assert_eq!(column(&trace, "time_ms"), [0.0, 5.0, 10.0, 15.0], "{trace}");
}

/// V2.3's action after END_FUNCTION_BLOCK in an object's export: FB_Step's action (before: E0307).
#[test]
fn an_action_after_end_function_block_is_the_blocks() {
    let src = "FUNCTION_BLOCK FB_Step
VAR_OUTPUT
    nStep : INT := 1;
END_VAR
IF nStep > 3 THEN
    nStep := 1;
END_IF
END_FUNCTION_BLOCK
ACTION acNext:
nStep := nStep + 1;
END_ACTION
ACTION acReset:
nStep := 1;
END_ACTION

PROGRAM PLC_PRG
VAR
    fb : FB_Step;
    s : INT;
END_VAR
fb.acNext();
fb.acNext();
IF fb.nStep = 3 THEN fb.acReset(); END_IF
s := fb.nStep;
END_PROGRAM
";
    let (trace, _) = run_text("ACT.EXP", src, 2, "PLC_PRG.s");
    // 1 -> 2 -> 3 -> reset 1; then 1 -> 2 -> 3 -> 1
    assert_eq!(column(&trace, "PLC_PRG.s"), [1.0, 1.0], "{trace}");
}

/// `:= 3(7)` and `:= 1, 2, 2(5)` without brackets: N = [7, 7, 7], M = [1, 2, 5, 5].
#[test]
fn array_initial_values_without_brackets() {
    let src = "PROGRAM PLC_PRG
VAR
\tN : ARRAY [1..3] OF INT := 3(7);
\tM : ARRAY [1..4] OF USINT := 1, 2, 2(5);
\tK : ARRAY [0..2] OF BOOL := FALSE, TRUE, TRUE;
\ts : INT;
END_VAR
s := N[1] + N[3] + USINT_TO_INT(M[1] * 10 + M[2] + M[4]) + BOOL_TO_INT(K[2]) * 100;
END_PROGRAM
";
    let (trace, _) = run_text("arr_init.st", src, 1, "PLC_PRG.s");
    assert_eq!(
        column(&trace, "PLC_PRG.s"),
        [7.0 + 7.0 + 17.0 + 100.0],
        "{trace}"
    );
}

/// A GVL export and a TYPE export (declarations only) are ST: `POINTER TO` reads, the program of
/// another file uses them.
#[test]
fn declarations_only_exports_are_st() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "GLOBALS.EXP",
        "VAR_GLOBAL\n\tlamp : BOOL;\n\tpLamp : POINTER TO BOOL;\nEND_VAR\n",
    );
    write_in(
        dir.path(),
        "TYPES.EXP",
        "TYPE ST_Ref :\nSTRUCT\n    pb : POINTER TO BYTE;\n    n  : INT;\nEND_STRUCT\nEND_TYPE\n",
    );
    write_in(
        dir.path(),
        "prg.st",
        "PROGRAM PLC_PRG
VAR
\tn : INT;
\tr : ST_Ref;
END_VAR
pLamp := ADR(lamp);
pLamp^ := TRUE;
r.n := 4;
n := BOOL_TO_INT(lamp) + r.n;
END_PROGRAM
",
    );
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "GLOBALS.EXP",
            "TYPES.EXP",
            "prg.st",
            "--cycles",
            "1",
            "--trace",
            "-",
            "--watch",
            "PLC_PRG.n",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    // read as ST without the W0302 note: an `.EXP` file is a documented input (round 27)
    assert!(!stderr.contains("W0302"), "{stderr}");
    assert_eq!(column(&trace, "PLC_PRG.n"), [5.0], "{trace}");
}

/// A declarations-only NAMESPACE file (`.txt`) is ST: it checks clean (before: IL, E1019
/// "unknown function `NAMESPACE`").
#[test]
fn a_namespace_of_declarations_is_st() {
    let (code, lines) = check_text(
        "dut.txt",
        "NAMESPACE Plant\nTYPE Pump : STRUCT\n    running : BOOL;\n    speed : INT;\nEND_STRUCT;\nEND_TYPE\nEND_NAMESPACE\n",
    );
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(lines.is_empty(), "{lines:?}");
}

/// Stray text ending in `function` before `FUNCTION Twice`: one error at the stray text, and
/// the function and the program after it read as ST (since round 29 that error is E0307 "text
/// outside any POU" at the text's first line, `st_diagnostics_r29_run.rs`; before: E0011 at `of`,
/// the text read as an IL instruction).
#[test]
fn stray_text_before_a_pou_is_one_error() {
    let src = "version 1.3 of this function

FUNCTION Twice : INT
VAR_INPUT
    x : INT;
END_VAR
Twice := x * 2;
END_FUNCTION

PROGRAM main
VAR n : INT; END_VAR
n := Twice(4);
END_PROGRAM
";
    let (code, lines) = check_text("prose.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("prose.st:1:1: error[E0307]: text outside any POU"),
        "{lines:?}"
    );
}

/// A function block whose body is CFC in a V2.3 export: one E0321 at `_CFC_BODY` (line 9), which
/// names the form and says to export PLCopen XML; the declarations before it are read (no other
/// error), and a program of another export beside it still checks.
#[test]
fn a_graphical_body_in_an_export_is_one_error() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "ALARM.EXP",
        "(* @NESTEDCOMMENTS := 'Yes' *)
(* @PATH := '' *)
FUNCTION_BLOCK Alarm
VAR_INPUT Status : BOOL; END_VAR
VAR_OUTPUT Out : BOOL; END_VAR
VAR T : TON; END_VAR
(* @END_DECLARATION := '0' *)

_CFC_BODY
_ELEMENT
_ID: 8
_MACROID: -1
_POS: 22, 3
_TYPE: _INPUT
_TEXT: Status AND NOT Out
_NEGATE: 0
_CONNECTOR: 
_END
_ELEMENT
_ID: 6
_TYPE: _BOX
_INSTANCENAME: T
_TYPENAME: TON
_END
END_FUNCTION_BLOCK
",
    );
    write_in(dir.path(), "PLC_PRG.EXP", PLC_PRG_EXP);
    let (code, _, stderr) = in_dir(dir.path(), &["check", "ALARM.EXP", "PLC_PRG.EXP"]);
    assert_eq!(code, Some(1), "{stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].starts_with("ALARM.EXP:9:1: error[E0321]"),
        "{stderr}"
    );
    assert!(errors[0].contains("CFC"), "{stderr}");
}
