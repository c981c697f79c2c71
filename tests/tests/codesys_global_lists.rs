//! CODESYS/TwinCAT global variable lists used without `VAR_EXTERNAL` (issue #13): a tc6_0200 export
//! whose POUs (ST program, ST function block, LD program) read and write the resource's `globalVars`
//! lists directly runs through `ladderc run`, with one note W1410 per POU and global; a local name
//! shadows a global; a CONSTANT global stays read-only; a name that is neither is still E1001. The
//! same holds for the configuration globals of a `.st` file.

mod common;
use common::ladderc;

use std::path::{Path, PathBuf};

fn fixture() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/codesys/tc6_0200_global_lists.xml")
}

#[test]
fn codesys_global_lists_without_var_external_run() {
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture())
        .args(["--cycles", "4", "--sanitize", "--trace"])
        .arg(&trace)
        .args([
            "--watch",
            "GVL.iCount,GVL.xLamp,GVL.xMotor,PRG_MAIN.iCount,GVL.fbPulse.ET",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    // FB_Count counts the global iCount up to the CONSTANT GC_MAX = 3; PRG_MAIN's own iCount (-1)
    // shadows the global, so the TP pulse starts at once (IN := xStart AND iCount < 0) and lasts
    // 20 ms; PRG_LD's contact on the global xLamp drives the global coil xMotor in the same cycle.
    let text = std::fs::read_to_string(&trace).unwrap();
    assert_eq!(
        text,
        "cycle,time_ms,GVL.iCount,GVL.xLamp,GVL.xMotor,PRG_MAIN.iCount,GVL.fbPulse.ET\n\
         0,0,1,1,1,-1,T#0ms\n\
         1,10,2,1,1,-1,T#10ms\n\
         2,20,3,0,0,-1,T#20ms\n\
         3,30,3,0,0,-1,T#20ms\n"
    );
    let notes: Vec<&str> = stderr
        .lines()
        .filter(|l| l.contains("note[W1410]"))
        .collect();
    // FB_Count: iCount, GC_MAX; PRG_MAIN: xStart, fbPulse, xLamp (not iCount: it is local);
    // PRG_LD: xLamp, xMotor
    assert_eq!(notes.len(), 7, "{stderr}");
    for (pou, name) in [
        ("function block `FB_Count`", "iCount"),
        ("function block `FB_Count`", "GC_MAX"),
        ("program `PRG_MAIN`", "xStart"),
        ("program `PRG_MAIN`", "fbPulse"),
        ("program `PRG_MAIN`", "xLamp"),
        ("program `PRG_LD`", "xLamp"),
        ("program `PRG_LD`", "xMotor"),
    ] {
        let msg = format!("global `{name}` is used in {pou} without a VAR_EXTERNAL declaration");
        assert!(notes.iter().any(|n| n.contains(&msg)), "{msg}: {stderr}");
    }
    assert!(
        !notes
            .iter()
            .any(|n| n.contains("`iCount` is used in program")),
        "{stderr}"
    );
    // located in the file, with the declaration IEC 61131-3 wants in the hint
    let f = fixture().display().to_string();
    assert!(
        notes.iter().all(|n| n.starts_with(&format!("{f}:"))),
        "{stderr}"
    );
    assert!(
        stderr.contains("needs `VAR_EXTERNAL CONSTANT GC_MAX : INT; END_VAR`"),
        "{stderr}"
    );
}

fn check_st(src: &str) -> (Option<i32>, String) {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("p.st");
    std::fs::write(&f, src).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run", "--cycles", "3"])
        .arg(&f)
        .output()
        .unwrap();
    // the trace (standard output) after the diagnostics
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stderr),
        String::from_utf8_lossy(&out.stdout)
    );
    (
        out.status.code(),
        text.replace(&f.display().to_string(), "p.st"),
    )
}

const CONFIG: &str = "CONFIGURATION cfg\n  VAR_GLOBAL\n    speed : INT := 1;\n  END_VAR\n  \
    VAR_GLOBAL CONSTANT\n    TOP : INT := 100;\n  END_VAR\n  RESOURCE r ON PLC\n    \
    TASK t(INTERVAL := T#10ms, PRIORITY := 1);\n    PROGRAM inst WITH t : main;\n  END_RESOURCE\n\
    END_CONFIGURATION\n";

#[test]
fn st_configuration_globals_without_var_external_run_and_keep_their_rules() {
    // reads and writes of a configuration global, the constant read
    let (code, err) = check_st(&format!(
        "PROGRAM main\nVAR\n  gap : INT;\nEND_VAR\n  speed := speed * 2;\n  gap := TOP - speed;\nEND_PROGRAM\n{CONFIG}"
    ));
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("p.st:5:12: note[W1410]: global `speed`"),
        "{err}"
    );
    assert!(
        err.contains("p.st:6:10: note[W1410]: global `TOP`"),
        "{err}"
    );
    // speed doubles every cycle from 1; gap = 100 - speed
    assert!(err.contains("2,20,8,100,92"), "{err}");

    // a CONSTANT global is not writable, declared or not
    let (code, err) = check_st(&format!("PROGRAM main\n  TOP := 5;\nEND_PROGRAM\n{CONFIG}"));
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("p.st:2:3: error["), "{err}");

    // a name that is no global is still undeclared
    let (code, err) = check_st(&format!(
        "PROGRAM main\n  sped := 1;\nEND_PROGRAM\n{CONFIG}"
    ));
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("p.st:2:3: error[E1001]: undeclared name `sped`"),
        "{err}"
    );

    // a declared VAR_EXTERNAL gives no note
    let (code, err) = check_st(&format!(
        "PROGRAM main\nVAR_EXTERNAL\n  speed : INT;\nEND_VAR\n  speed := speed + 1;\nEND_PROGRAM\n{CONFIG}"
    ));
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("W1410"), "{err}");
}
