//! TwinCAT 3 project forms found by round 25 of unseen projects (issue #13), each run through
//! `ladderc run` on a copy of the fixture project (`fixtures/twincat/project`) or the LD blinker
//! (`fixtures/twincat_graphical/blink`):
//! - an object the `.plcproj` excludes from the build (`<ExcludeFromBuild>true</ExcludeFromBuild>`
//!   under its `<Compile>` item, CODESYS "Properties: Build": not compiled) is not read (before: a
//!   notes page excluded so was read as IL, 446 errors on one real project);
//! - the visualisation task of TwinCAT 3.1.4022 (`VISU_TASK` calling `VISU_PRG`, which the
//!   visualisation manager generates) is left out as `VisuElems.Visu_Prg` is (before: E0322);
//! - an LD comparison box saved by TwinCAT 3.1.4022 with its long call type (`Greater`, `Equal`
//!   beside the box type `>`, `=`) is the comparison (before: E0325 "call type `Greater`, which
//!   ladderc does not read").

mod common;
use common::{column, run_stimulated_files, run_traced};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures")
        .join(rel)
}

const WATCH: &str = "MAIN.fbCounter.nCount,MAIN.eMode";

/// The fixture project's counter (to 5, then reset), as `twincat_files.rs` checks it in full.
fn assert_counts(trace: &str) {
    assert_eq!(
        column(trace, "MAIN.fbCounter.nCount"),
        [1.0, 2.0, 3.0, 4.0, 0.0, 1.0, 2.0]
    );
}

/// A copy of the fixture project whose `.plcproj` also lists `POUs\Notes.TcPOU`, a POU whose body
/// is prose (not ST, not IL), with `extra` inside its `<Compile>` item.
fn project_with_notes(extra: &str) -> tempfile::TempDir {
    let dir = common::copy_of_folder(&fixture("twincat/project"));
    let root = dir.path();
    common::write_in(
        root,
        "POUs/Notes.TcPOU",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  \
         <POU Name=\"Notes\" Id=\"{9}\" SpecialFunc=\"None\">\n    \
         <Declaration><![CDATA[PROGRAM Notes\n]]></Declaration>\n    <Implementation>\n      \
         <ST><![CDATA[belt speed 30 Hz = 164 mm/s, check with the supplier / before commissioning]]></ST>\n    \
         </Implementation>\n  </POU>\n</TcPlcObject>\n",
    );
    let project = root.join("Demo.plcproj");
    let text = std::fs::read_to_string(&project).unwrap().replace(
        "    <Compile Include=\"VisuTask.TcTTO\">",
        &format!(
            "    <Compile Include=\"POUs\\Notes.TcPOU\">\n      <SubType>Code</SubType>\n{extra}    \
             </Compile>\n    <Compile Include=\"VisuTask.TcTTO\">"
        ),
    );
    std::fs::write(&project, text).unwrap();
    dir
}

/// The notes page excluded from the build is not compiled: the project runs as without it, given as
/// its `.plcproj` or as its folder. Listed without the flag, the same page is read (and rejected),
/// so the flag is what leaves it out.
#[test]
fn an_object_excluded_from_the_build_is_not_read() {
    let dir = project_with_notes("      <ExcludeFromBuild>true</ExcludeFromBuild>\n");
    let (trace, stderr) = run_traced(&dir.path().join("Demo.plcproj"), 7, WATCH);
    assert_counts(&trace);
    assert!(!stderr.contains("Notes"), "{stderr}");
    let (trace, _) = run_traced(dir.path(), 7, WATCH);
    assert_counts(&trace);

    let dir = project_with_notes("");
    let (code, stderr) = common::check_stderr(&dir.path().join("Demo.plcproj"));
    assert_eq!(code, Some(1), "{stderr}");
    assert!(stderr.contains("Notes.TcPOU"), "{stderr}");
}

/// TwinCAT 3.1.4022's visualisation task calls `VISU_PRG`, a program no file declares (the
/// visualisation manager generates it): the task is left out and MAIN runs on its own task's
/// 20 ms. Another task calling an undeclared program is still E0322.
#[test]
fn the_visualisation_task_of_tc_4022_is_left_out() {
    let dir = common::copy_of_folder(&fixture("twincat/project"));
    let visu = dir.path().join("VisuTask.TcTTO");
    let text = std::fs::read_to_string(&visu)
        .unwrap()
        .replace("VisuElems.Visu_Prg", "VISU_PRG");
    std::fs::write(&visu, &text).unwrap();
    let (trace, stderr) = run_traced(&dir.path().join("Demo.plcproj"), 7, WATCH);
    assert_counts(&trace);
    // PlcTask's 20 ms (the visualisation task's 50 ms would make the scan 10 ms)
    assert_eq!(column(&trace, "time_ms")[1], 20.0, "{stderr}");

    std::fs::write(&visu, text.replace("VISU_TASK", "HMI_TASK")).unwrap();
    let (code, stderr) = common::check_stderr(&dir.path().join("Demo.plcproj"));
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("task `HMI_TASK` calls `VISU_PRG`, which no file given declares"),
        "{stderr}"
    );
}

/// The blinker's network 6 (`GE`, call type `Ge`) saved as 3.1.4022 does: box type `>` with call
/// type `Greater`, and `=` with `Equal`. Each runs with the trace of the same box in the short
/// form (`GT`/`Gt`, `EQ`/`Eq`), and the two comparisons give different traces (the box is read as
/// what it says, not as any comparison).
#[test]
fn long_comparison_call_types_of_tc_4022_are_the_comparisons() {
    let main = std::fs::read_to_string(fixture("twincat_graphical/blink/MAIN.TcPOU")).unwrap();
    assert_eq!(main.matches("<v n=\"BoxType\">\"GE\"</v>").count(), 1);
    let watch = "MAIN.nCount,MAIN.bDone";
    let trace_of = |box_type: &str, call: &str| {
        let dir = tempfile::tempdir().unwrap();
        let text = main
            .replace(
                "<v n=\"BoxType\">\"GE\"</v>",
                &format!("<v n=\"BoxType\">\"{box_type}\"</v>"),
            )
            .replace(
                "<v n=\"CallType\" t=\"Operator\">Ge</v>",
                &format!("<v n=\"CallType\" t=\"Operator\">{call}</v>"),
            );
        let file = dir.path().join("MAIN.TcPOU");
        std::fs::write(&file, text).unwrap();
        let fb = fixture("twincat_graphical/blink/FB_Blink.TcPOU");
        // the motor started at cycle 2: the counter counts the blinker's edges
        let stimulus = "2,MAIN.bStart,1\n4,MAIN.bStart,0\n";
        let files = [file.as_path(), fb.as_path()];
        run_stimulated_files(&files, &["--cycle-ms", "10"], 50, stimulus, watch).0
    };
    let greater = trace_of("&gt;", "Greater");
    assert_eq!(greater, trace_of("GT", "Gt"));
    let equal = trace_of("=", "Equal");
    assert_eq!(equal, trace_of("EQ", "Eq"));
    assert_ne!(greater, equal);
}
