//! TwinCAT 3 source files (issue #13): `.TcPOU`, `.TcDUT`, `.TcGVL`, `.TcIO` and `.TcTTO` objects,
//! read as ST in place, and a `.plcproj` project (or a folder holding one) standing for the files it
//! lists, run end to end through `ladderc run`. The fixtures under `fixtures/twincat/` are written for
//! these tests: a project with a DUT, a `qualified_only` GVL, a GVL of constants used in an array
//! bound, an enumeration with its base type after it used with dotted values (`E_Mode.Full`), a task
//! of 20 ms, a visualisation task, a function block with a method and an action, and
//! MAIN; a GVL of `AT %I*`/`%Q*` I/O links and a PERSISTENT list with a program using them; a POU
//! with an LD network body; two programs without a task file.
//!
//! Record of the public projects (README "TwinCAT 3 projects"), issue #13's inheritance round, the
//! 70 `.plcproj` files of today's snapshots run 50 scans before and after, side by side:
//!
//! | | run | rejected | projects with E0303 | with E0336 | with E0330 |
//! |---|---|---|---|---|---|
//! | before (EXTENDS, IMPLEMENTS, INTERFACE: E0303) | 23 | 47 | 17 | 0 | 0 |
//! | after (inheritance compiled) | 23 | 47 | 8 (PROPERTY, METHOD of a PROGRAM) | 5 | 4 (TcUnit's FB_TestSuite as base) |
//!
//! (Inheritance itself: `tests/tests/oop_inherit_run.rs`, which runs one pair of blocks as `.TcPOU`
//! and `.TcIO` files.)

mod common;
use common::{assert_ok, column, diagnostic_heads, ladderc, run_traced, run_traced_files};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/twincat")
        .join(rel)
}

const WATCH: &str =
    "MAIN.fbCounter.nCount,MAIN.nScaled,GVL.stData.nTotal,GVL.stData.bHigh,MAIN.aSeen[3],MAIN.eMode";

/// The trace of the fixture project's MAIN: the counter counts to GVL.nLimit (5) and is reset by its
/// action `ResetCount` (then GVL.stData.bHigh is set); the method `Scaled` gives 10 x the count;
/// `aSeen : ARRAY[1..cSeen]` takes its bound from GVL_Const's constant (another file); `eMode`, of
/// the enumeration `E_Mode` written with its base type after it (`(Counting := 0, Full := 10) INT`),
/// starts as `E_Mode.Counting` and becomes `E_Mode.Full` (values qualified with a dot) once bHigh.
fn assert_project_trace(trace: &str, cycle_ms: f64) {
    assert_eq!(
        column(trace, "MAIN.fbCounter.nCount"),
        [1.0, 2.0, 3.0, 4.0, 0.0, 1.0, 2.0]
    );
    assert_eq!(
        column(trace, "MAIN.eMode"),
        [0.0, 0.0, 0.0, 0.0, 10.0, 10.0, 10.0]
    );
    assert_eq!(
        column(trace, "MAIN.aSeen[3]"),
        column(trace, "MAIN.fbCounter.nCount")
    );
    assert_eq!(
        column(trace, "MAIN.nScaled"),
        [10.0, 20.0, 30.0, 40.0, 0.0, 10.0, 20.0]
    );
    assert_eq!(
        column(trace, "GVL.stData.nTotal"),
        [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]
    );
    assert_eq!(
        column(trace, "GVL.stData.bHigh"),
        [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0]
    );
    let times: Vec<f64> = (0..7).map(|k| k as f64 * cycle_ms).collect();
    assert_eq!(column(trace, "time_ms"), times);
}

#[test]
fn a_project_folder_runs_with_its_methods_actions_dut_qualified_gvl_and_task_period() {
    let (trace, stderr) = run_traced(&fixture("project"), 7, WATCH);
    // the task file's CycleTime of 20000 us is the scan cycle (the visualisation task, which calls
    // a library program, is left out)
    assert_project_trace(&trace, 20.0);
    assert!(!stderr.contains("error"), "{stderr}");
}

#[test]
fn the_plcproj_file_reads_the_files_it_lists_as_the_folder_does() {
    let (trace, _) = run_traced(&fixture("project/Demo.plcproj"), 7, WATCH);
    assert_project_trace(&trace, 20.0);
}

#[test]
fn object_files_given_one_by_one_run_without_a_task_file() {
    let files = [
        fixture("project/POUs/MAIN.TcPOU"),
        fixture("project/POUs/FB_Counter.TcPOU"),
        fixture("project/GVLs/GVL.TcGVL"),
        fixture("project/GVLs/GVL_Const.TcGVL"),
        fixture("project/DUTs/ST_Data.TcDUT"),
        fixture("project/DUTs/E_Mode.TcDUT"),
    ];
    let refs: Vec<&Path> = files.iter().map(PathBuf::as_path).collect();
    let (trace, _) = run_traced_files(&refs, 7, WATCH);
    // no task file: the one PROGRAM runs at ladderc's default cycle of 10 ms
    assert_project_trace(&trace, 10.0);
}

/// `ladderc --message-format short check FILES`: exit code and the error lines (up to the hint), the
/// folder `strip` left out of their paths.
fn check(files: &[PathBuf], strip: &Path) -> (Option<i32>, Vec<String>) {
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .args(files)
        .output()
        .unwrap();
    (
        out.status.code(),
        diagnostic_heads(&out.stderr, strip, false),
    )
}

#[test]
fn a_graphical_body_is_one_located_error() {
    let dir = fixture("graphical");
    let (code, heads) = check(&[dir.join("P_Ladder.TcPOU")], &dir);
    assert_eq!(code, Some(1));
    assert_eq!(
        heads,
        ["P_Ladder.TcPOU:11:7: error[E0325]: TwinCAT LD/FBD body of `P_Ladder`: its archive has no \
          network list (`<o t=\"NWLImplementationObject\">` with `<l2 n=\"NetworkList\">`)"]
    );
}

#[test]
fn two_programs_without_a_task_file_or_main_are_one_located_error_and_one_alone_runs() {
    let dir = fixture("two_programs");
    let (code, heads) = check(&[dir.join("P_Fill.TcPOU"), dir.join("P_Drain.TcPOU")], &dir);
    assert_eq!(code, Some(1));
    assert_eq!(
        heads,
        ["P_Fill.TcPOU:4:35: error[E0322]: 2 TwinCAT programs (P_Fill, P_Drain) and no task file: \
          which one runs is not said"]
    );
    let (trace, _) = run_traced(&dir.join("P_Fill.TcPOU"), 3, "P_Fill.nLevel");
    assert_eq!(column(&trace, "P_Fill.nLevel"), [1.0, 2.0, 3.0]);
}

/// The same two programs listed by a library's project (`<Company>`, `<Released>`, `<Title>`, as
/// TwinCAT writes a project saved as a library): a library has no task, so `check` passes with one
/// note (W1434) and `run` calls both programs each cycle; the project without those properties is
/// E0322 again.
#[test]
fn a_library_project_with_several_programs_and_no_task_checks_with_one_note() {
    let dir = fixture("library");
    let project = dir.join("Tank_Library.plcproj");
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&project)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let prefix = format!("{}/", dir.join("..").join("two_programs").display());
    let heads: Vec<String> = stderr
        .lines()
        .map(|l| l.replace(&prefix, ""))
        .map(|l| {
            l.split_once(" (hint")
                .map_or(l.clone(), |(h, _)| h.to_string())
        })
        .collect();
    assert_eq!(
        heads,
        [
            "P_Fill.TcPOU:4:35: note[W1434]: `Tank_Library.plcproj` is a library's project: its 2 \
          programs (P_Fill, P_Drain) are compiled, and no task says which runs"
        ],
        "{stderr}"
    );
    let (trace, _) = run_traced(&project, 3, "P_Fill.nLevel,P_Drain.nLevel");
    assert_eq!(column(&trace, "P_Fill.nLevel"), [1.0, 2.0, 3.0]);
    assert_eq!(column(&trace, "P_Drain.nLevel"), [1.0, 2.0, 3.0]);
    // an application's project (no library properties): which program runs is not said
    let plain = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(&project)
        .unwrap()
        .replace("<Company>ladderc tests</Company>", "")
        .replace("<Released>false</Released>", "")
        .replace("<Title>Tank library</Title>", "")
        .replace("..\\two_programs\\", "");
    for f in ["P_Fill.TcPOU", "P_Drain.TcPOU"] {
        std::fs::copy(fixture("two_programs").join(f), plain.path().join(f)).unwrap();
    }
    let app = plain.path().join("Tank.plcproj");
    std::fs::write(&app, text).unwrap();
    let (code, heads) = check(&[app], plain.path());
    assert_eq!(code, Some(1));
    assert_eq!(
        heads,
        ["P_Fill.TcPOU:4:35: error[E0322]: 2 TwinCAT programs (P_Fill, P_Drain) and no task file: \
          which one runs is not said"]
    );
}

fn pou(name: &str, decl: &str, body: &str, members: &str) -> String {
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  \
         <POU Name=\"{name}\" Id=\"{{1}}\" SpecialFunc=\"None\">\n    \
         <Declaration><![CDATA[{decl}]]></Declaration>\n    <Implementation>\n      \
         <ST><![CDATA[{body}]]></ST>\n    </Implementation>\n{members}  </POU>\n</TcPlcObject>\n"
    )
}

#[test]
fn diagnostics_point_into_the_twincat_file_and_a_task_naming_no_program_is_located() {
    let dir = tempfile::tempdir().unwrap();
    let main = dir.path().join("MAIN.TcPOU");
    std::fs::write(
        &main,
        pou(
            "MAIN",
            "PROGRAM MAIN\nVAR\n\tn : INT;\nEND_VAR\n",
            "n := n + 1;\nm := n;",
            "",
        ),
    )
    .unwrap();
    let fb = dir.path().join("FB_Prop.TcPOU");
    std::fs::write(
        &fb,
        pou(
            "FB_Prop",
            "FUNCTION_BLOCK FB_Prop\nVAR\n\tx : INT;\nEND_VAR\n",
            "x := x + 1;\nValue := 3;",
            "    <Property Name=\"Value\" Id=\"{2}\">\n      \
             <Declaration><![CDATA[PROPERTY Value : INT]]></Declaration>\n      \
             <Get Name=\"Get\" Id=\"{3}\">\n        <Declaration><![CDATA[VAR\nEND_VAR\n]]></Declaration>\n        \
             <Implementation>\n          <ST><![CDATA[Value := x;]]></ST>\n        </Implementation>\n      \
             </Get>\n    </Property>\n",
        ),
    )
    .unwrap();
    let task = dir.path().join("PlcTask.TcTTO");
    std::fs::write(
        &task,
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  \
         <Task Name=\"PlcTask\" Id=\"{4}\">\n    <CycleTime>10000</CycleTime>\n    \
         <Priority>20</Priority>\n    <PouCall>\n      <Name>P_Missing</Name>\n    </PouCall>\n  \
         </Task>\n</TcPlcObject>\n",
    )
    .unwrap();
    let (code, heads) = check(&[fb, task], dir.path());
    assert_eq!(code, Some(1));
    assert_eq!(
        heads,
        [
            // (the property is compiled; written without a Set accessor in the body's second line)
            "FB_Prop.TcPOU:11:1: error[E0337]: property `Value` has no Set accessor: it cannot be \
             written",
            "PlcTask.TcTTO:7:13: error[E0322]: task `PlcTask` calls `P_Missing`, which no file \
             given declares as a PROGRAM",
        ]
    );
    // a name error in the ST body: the line and column of the .TcPOU file
    let (code, heads) = check(&[main], dir.path());
    assert_eq!(code, Some(1));
    assert_eq!(
        heads,
        ["MAIN.TcPOU:11:1: error[E1001]: undeclared name `m`"]
    );
}

#[test]
fn io_links_are_plain_variables_set_by_the_stimulus_and_persistent_is_retain() {
    let dir = fixture("io");
    let tmp = tempfile::tempdir().unwrap();
    let stim = tmp.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n1,GVL_IO.bStart,1\n3,GVL_IO.bStart,0\n4,GVL_IO.bStart,1\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(dir.join("GVL_IO.TcGVL"))
        .arg(dir.join("P_Io.TcPOU"))
        .args(["--cycles", "6", "--sanitize", "--stimulus"])
        .arg(&stim)
        .args(["--trace", "-", "--watch", "GVL_IO.nStarts,GVL_IO.nLamp"])
        .output()
        .unwrap();
    assert_ok(&out);
    let trace = String::from_utf8_lossy(&out.stdout);
    // each rising edge of the input counts in the PERSISTENT list; the output is 10 x the count
    assert_eq!(
        column(&trace, "GVL_IO.nStarts"),
        [0.0, 1.0, 1.0, 1.0, 2.0, 2.0]
    );
    assert_eq!(
        column(&trace, "GVL_IO.nLamp"),
        [0.0, 10.0, 10.0, 10.0, 20.0, 20.0]
    );
    let notes: Vec<String> = String::from_utf8_lossy(&out.stderr)
        .lines()
        .filter(|l| l.contains("W0322"))
        .map(|l| l.replace(&format!("{}/", dir.display()), ""))
        .map(|l| {
            l.split_once(" (hint")
                .map_or(l.clone(), |(h, _)| h.to_string())
        })
        .collect();
    assert_eq!(
        notes,
        [
            "GVL_IO.TcGVL:6:9: note[W0322]: 2 `AT %I*`/`%Q*`/`%M*` declaration(s) read as plain \
          variables: TwinCAT links them to I/O in the system configuration (.tsproj), which \
          ladderc does not read"
        ]
    );
}

#[test]
fn a_task_calling_a_program_whose_file_failed_is_not_reported_again() {
    let dir = tempfile::tempdir().unwrap();
    let main = dir.path().join("MAIN.TcPOU");
    std::fs::write(
        &main,
        std::fs::read_to_string(fixture("graphical/P_Ladder.TcPOU"))
            .unwrap()
            .replace("P_Ladder", "MAIN"),
    )
    .unwrap();
    let (code, heads) = check(&[main, fixture("project/PlcTask.TcTTO")], dir.path());
    assert_eq!(code, Some(1));
    assert_eq!(heads.len(), 1, "{heads:?}");
    assert!(
        heads[0].starts_with("MAIN.TcPOU:11:7: error[E0325]"),
        "{heads:?}"
    );
}

#[test]
fn dotted_enumerated_values_and_base_types_run_in_st_files_too() {
    let dir = tempfile::tempdir().unwrap();
    let st = dir.path().join("states.st");
    std::fs::write(
        &st,
        "TYPE E_State :\n(\n\tIdle := 0,\n\tBusy := 10,\n\tDone\n) INT;\nEND_TYPE\n\
         PROGRAM MAIN\nVAR\n\teState : E_State := E_State.Busy;\n\tn : INT;\nEND_VAR\n\
         CASE eState OF\nE_State.Busy: n := n + 1; IF n >= 2 THEN eState := E_State.Done; END_IF\n\
         E_State.Done: n := 100;\nEND_CASE\nEND_PROGRAM\n",
    )
    .unwrap();
    let (trace, _) = run_traced(&st, 4, "MAIN.eState,MAIN.n");
    assert_eq!(column(&trace, "MAIN.eState"), [10.0, 11.0, 11.0, 11.0]);
    assert_eq!(column(&trace, "MAIN.n"), [1.0, 2.0, 100.0, 100.0]);
}

/// A project written on Windows names `POUs\MAIN.TcPOU` while the file on disk is `pous/Main.tcpou`
/// (Windows names ignore case): it is found and runs. A listed file that is not there at all
/// (koreacomp5/real_press_plc's `Axis04_Set_Work_End_Speed.TcPOU`, was E9001 without a location
/// and exit 2) is one E1079 at its `Include` in the project, exit 1, and the rest is checked.
#[test]
fn listed_files_are_found_whatever_their_case_and_a_missing_one_is_located() {
    let dir = common::copy_of_folder(&fixture("project"));
    let root = dir.path();
    std::fs::rename(root.join("POUs"), root.join("pous")).unwrap();
    std::fs::rename(root.join("pous/MAIN.TcPOU"), root.join("pous/Main.tcpou")).unwrap();
    let (trace, _) = run_traced(&root.join("Demo.plcproj"), 7, WATCH);
    assert_project_trace(&trace, 20.0);

    let project = root.join("Demo.plcproj");
    let text = std::fs::read_to_string(&project).unwrap().replace(
        "    <Compile Include=\"VisuTask.TcTTO\">",
        "    <Compile Include=\"POUs\\Gone.TcPOU\" />\n    <Compile Include=\"VisuTask.TcTTO\">",
    );
    std::fs::write(&project, text).unwrap();
    let (code, stderr) = common::check_stderr(&project);
    assert_eq!(code, Some(1), "{stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error")).collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    let shown = format!(
        "{}:29:23: error[E1079]: the project lists ",
        project.display()
    );
    assert!(errors[0].starts_with(&shown), "{stderr}");
    assert!(
        errors[0].contains("Gone.TcPOU, which is not there"),
        "{stderr}"
    );
}

/// A truncated `.TcPOU` (round 19) is one E3001 at its root, not also E3002 "expected a PLCopen
/// <project>", which a TwinCAT file is not.
#[test]
fn a_truncated_object_file_is_one_e3001() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("MAIN.TcPOU");
    std::fs::write(
        &path,
        "<?xml version=\"1.0\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  <POU Name=\"MAIN\">\n    \
         <Declaration><![CDATA[PROGRAM MAIN\nVAR n : INT; END_VAR\n]]></Declaration>\n  </POU>\n",
    )
    .unwrap();
    let (code, heads) = check(&[path], dir.path());
    assert_eq!(code, Some(1));
    assert_eq!(
        heads,
        ["MAIN.TcPOU:2:1: error[E3001]: the XML file is not well-formed: element <TcPlcObject> is \
          never closed"]
    );
}
