//! CODESYS/TwinCAT qualified access to global variable lists, `GVL.var` (issue #13): a tc6_0200 export
//! with a list in its device configuration (`<globalVars name="GVL_Main">`, whose CONSTANT and plain
//! sections are split in the vendor's `mixedattrsvarlist` data, as CODESYS writes it) and a list
//! exported on its own in the project's `addData` (`GVL_IO`) runs through `ladderc run`: ST, IL, LD and
//! FBD bodies read and write `GVL_Main.iCount`, call `GVL_Main.fbTimer(...)` and read
//! `GVL_Main.fbTimer.Q`; a local of the same name does not hide the qualified global. An unknown list
//! or member, a list used as a variable and a write to a CONSTANT member are located errors.

mod common;
use common::ladderc;

use std::path::{Path, PathBuf};

fn fixture() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/codesys/tc6_0200_qualified_gvl.xml")
}

#[test]
fn qualified_global_list_members_run_in_st_il_ld_and_fbd() {
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture())
        .args(["--cycles", "6", "--sanitize", "--trace"])
        .arg(&trace)
        .args([
            "--watch",
            "GVL_Main.iCount,PRG_ST.iCount,GVL_IO.iLevel,GVL_IO.iPlus,GVL_Main.fbTimer.ET,GVL_Main.xDone,GVL_IO.xLamp",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("error"), "{stderr}");
    // PRG_ST counts GVL_Main.iCount up to the CONSTANT GVL_Main.iLimit = 3 while GVL_IO.xStart
    // (its own local iCount stays 100); the timer starts when the limit is reached (cycle 2) and is
    // done after 20 ms; PRG_IL writes 10 x iCount into GVL_IO.iLevel, PRG_FBD adds 5 to it, PRG_LD's
    // contact on GVL_Main.xDone drives the coil GVL_IO.xLamp.
    let text = std::fs::read_to_string(&trace).unwrap();
    assert_eq!(
        text,
        "cycle,time_ms,GVL_Main.iCount,PRG_ST.iCount,GVL_IO.iLevel,GVL_IO.iPlus,GVL_Main.fbTimer.ET,GVL_Main.xDone,GVL_IO.xLamp\n\
         0,0,1,100,10,15,T#0ms,0,0\n\
         1,10,2,100,20,25,T#0ms,0,0\n\
         2,20,3,100,30,35,T#0ms,0,0\n\
         3,30,3,100,30,35,T#10ms,0,0\n\
         4,40,3,100,30,35,T#20ms,1,1\n\
         5,50,3,100,30,35,T#20ms,1,1\n"
    );
}

/// `check` of the fixture with `from` (a unique text of it) replaced by `to`: exit code and the
/// error lines, with the temporary path replaced by `q.xml`.
fn check_variant(from: &str, to: &str) -> (Option<i32>, Vec<String>) {
    let src = std::fs::read_to_string(fixture()).unwrap();
    assert_eq!(src.matches(from).count(), 1, "{from}");
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("q.xml");
    std::fs::write(&f, src.replace(from, to)).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&f)
        .output()
        .unwrap();
    let errors = String::from_utf8_lossy(&out.stderr)
        .lines()
        .filter(|l| l.contains("error["))
        .map(|l| l.replace(&f.display().to_string(), "q.xml"))
        .collect();
    (out.status.code(), errors)
}

#[test]
fn unknown_lists_and_members_are_located_errors() {
    let cases = [
        // an unknown member, in ST, located at the member
        (
            ">iCount := 100;",
            ">GVL_Main.iCnt := 1;",
            "q.xml:17:68: error[E1001]: global variable list `GVL_Main` has no variable `iCnt` \
             [POU `PRG_ST`] (hint: GVL_Main declares: iLimit, iCount, xDone, fbTimer)",
        ),
        // an unknown list, with the near list name suggested
        (
            ">iCount := 100;",
            ">GVL_Mian.iCount := 1;",
            "q.xml:17:59: error[E1001]: undeclared name `GVL_Mian` [POU `PRG_ST`] \
             (hint: did you mean `GVL_Main`? otherwise declare `GVL_Mian` in a VAR block)",
        ),
        // the list itself is not a variable
        (
            ">iCount := 100;",
            ">GVL_Main := 1;",
            "q.xml:17:59: error[E1001]: `GVL_Main` is a global variable list, not a variable \
             [POU `PRG_ST`] (hint: name one of its variables: GVL_Main.<variable>)",
        ),
        // the CONSTANT section of a mixed list stays read-only
        (
            ">iCount := 100;",
            ">GVL_Main.iLimit := 4;",
            "q.xml:17:59: error[E1014]: `GVL_Main.iLimit` is a constant [POU `PRG_ST`] \
             (hint: write another variable, or drop CONSTANT from its declaration)",
        ),
        // IL operand
        (
            ">LD GVL_Main.iCount",
            ">LD GVL_Main.iCounter",
            "q.xml:28:71: error[E1001]: global variable list `GVL_Main` has no variable `iCounter` \
             [POU `PRG_IL`] (hint: GVL_Main declares: iLimit, iCount, xDone, fbTimer)",
        ),
        // LD contact, located at the element
        (
            "<variable>GVL_Main.xDone<",
            "<variable>GVL_Main.xDn<",
            "q.xml:40:47: error[E1001]: global variable list `GVL_Main` has no variable `xDn` \
             [POU `PRG_LD`, network 1, localId 2] (hint: GVL_Main declares: iLimit, iCount, xDone, fbTimer)",
        ),
        // FBD output variable
        (
            "<expression>GVL_IO.iPlus<",
            "<expression>GVL_IO.iPlusOne<",
            "q.xml:63:",
        ),
    ];
    for (from, to, want) in cases {
        let (code, errors) = check_variant(from, to);
        assert_eq!(code, Some(1), "{to}: {errors:?}");
        assert_eq!(errors.len(), 1, "{to}: {errors:?}");
        assert!(errors[0].starts_with(want), "{to}: {errors:?}");
    }
}

#[test]
fn without_the_mixed_sections_the_whole_list_would_be_constant() {
    // the same export without CODESYS's mixedattrsvarlist data: the outer list says constant="true"
    // for all its members, so the writes to GVL_Main.iCount are errors (the sections are what make
    // the fixture valid)
    let src = std::fs::read_to_string(fixture()).unwrap();
    let start = src
        .find("<data name=\"http://www.3s-software.com/plcopenxml/mixedattrsvarlist\"")
        .unwrap();
    let end = src[start..].find("</data>").unwrap() + start + "</data>".len();
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("q.xml");
    std::fs::write(&f, format!("{}{}", &src[..start], &src[end..])).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&f)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("error[E1014]: `GVL_Main.iCount` is a constant"),
        "{stderr}"
    );
}
