//! User libraries given as source projects (issue #13): `ladderc run App.plcproj --lib
//! MotionMath.plcproj --lib Helpers.plcproj`. The fixtures under `fixtures/user_library/` are
//! written for these tests: an application project `App` referencing the library `MotionMath`
//! under the namespace `MoMath` (`<PlaceholderReference>`), which references the library
//! `Helpers` under `Hlp`; `MotionMath` holds a function block with FB_init arguments (`Ramp`), a
//! `qualified_only` list of constants, an enumeration, a function counting with a BYTE (W1436), a
//! program with its own task (a library's tasks do not run); `BadLib` holds an error.
//!
//! Struckig (stefanbesler/struckig, GPL-3, not copied here) is the real library these forms come
//! from: `otg : Struckig.Otg(cycletime := 0.001, dofs := 6) := (...)` in its examples.

mod common;
use common::{column, diagnostic_heads};

use std::path::{Path, PathBuf};

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/user_library")
}

/// `ladderc --message-format short ARGS` in the fixtures folder: exit code, stdout, stderr.
fn ladderc_in_fixtures(args: &[&str]) -> (Option<i32>, String, String) {
    common::in_dir(&fixtures(), args)
}

const APP_RUN: &[&str] = &[
    "run",
    "App/App.plcproj",
    "--lib",
    "MotionMath/MotionMath.plcproj",
    "--lib",
    "Helpers/Helpers.plcproj",
    "--cycles",
    "5",
    "--sanitize",
    "--trace",
    "-",
    "--watch",
    "MAIN.ramp.Value,MAIN.ramp._cycletime,MAIN.state,MAIN.held.Value,MAIN.mean,MAIN.turn,MAIN.samples[1]",
];

/// The application runs with its library's block, type, constants and function, named with the
/// namespace of its reference (`MoMath.Ramp`, `MoMath.Constants.TwoPi`) and unqualified (`held :
/// Ramp`); the library's own reference (`Hlp.Clamp`) resolves among the `--lib` projects.
#[test]
fn application_runs_with_its_libraries() {
    let (code, trace, stderr) = ladderc_in_fixtures(APP_RUN);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("Sanitizer"), "{stderr}");
    // FB_init's argument (cycletime := 0.01) and the initial values (Rate := 50.0, Target := 2.0)
    // of the qualified type `MoMath.Ramp(...) := (...)`: 0.5 a cycle, clamped by Hlp.Clamp
    assert_eq!(column(&trace, "MAIN.ramp._cycletime"), [0.01; 5]);
    assert_eq!(column(&trace, "MAIN.ramp.Value"), [0.5, 1.0, 1.5, 2.0, 2.0]);
    // MoMath.RampState: Rising (1), then Reached (2)
    assert_eq!(column(&trace, "MAIN.state"), [1.0, 1.0, 1.0, 2.0, 2.0]);
    // `held := ramp;` in cycle 2 (W1437): a copy, not a second name of the same instance
    assert_eq!(column(&trace, "MAIN.held.Value"), [0.0, 1.0, 1.0, 1.0, 1.0]);
    // MoMath.Average over MoMath.Constants.Window (a BYTE, 4) samples, counted with a BYTE
    assert_eq!(column(&trace, "MAIN.mean"), [2.0; 5]);
    assert_eq!(column(&trace, "MAIN.turn"), [std::f64::consts::TAU; 5]);
    // an array initialiser's constant expression (`2.0 * 1.5`)
    assert_eq!(column(&trace, "MAIN.samples[1]"), [3.0; 5]);
    // the library's program and task do not run: its variable is no column of the program
    assert!(!trace.contains("LibSelfTest"), "{trace}");
    let heads = diagnostic_heads(stderr.as_bytes(), &fixtures(), true);
    assert_eq!(
        heads,
        [
            "MotionMath/POUs/Average.TcPOU:16:15: warning[W1436]: BYTE counted as the unsigned integer USINT: IEC 61131-3 gives bit strings no arithmetic (its other uses in this POU are not reported)",
            "App/POUs/MAIN.TcPOU:20:3: warning[W1437]: a function block instance copied whole: IEC 61131-3 defines no assignment of instances (its other uses in this POU are not reported)",
        ]
    );
}

/// Without `--lib`, the library's namespace is unknown: E1032, whose hint names `--lib`.
#[test]
fn without_the_library_its_namespace_is_unknown() {
    let (code, _, stderr) = ladderc_in_fixtures(&["check", "App/App.plcproj"]);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("App/POUs/MAIN.TcPOU:6:10: error[E1032]: `MoMath` is neither a variable nor a library ladderc provides"),
        "{stderr}"
    );
    assert!(
        stderr.contains("give its source project with --lib"),
        "{stderr}"
    );
}

/// A library the project references only through another library, given alone: E1077 (the
/// project does not reference it).
#[test]
fn a_library_no_project_references_is_an_error() {
    let (code, _, stderr) = ladderc_in_fixtures(&[
        "check",
        "App/App.plcproj",
        "--lib",
        "Helpers/Helpers.plcproj",
    ]);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("error[E1077]: --lib Helpers/Helpers.plcproj: no input project references the library `Helpers`"),
        "{stderr}"
    );
    assert!(stderr.contains("the projects reference MoMath"), "{stderr}");
}

/// Without a project among the inputs, a `--lib` library's names are available under its default
/// namespace and unqualified; a folder holding one project stands for it.
#[test]
fn a_library_for_st_inputs_under_its_default_namespace() {
    let (code, trace, stderr) = ladderc_in_fixtures(&[
        "run",
        "uses_helpers.st",
        "--lib",
        "Helpers",
        "--cycles",
        "1",
        "--sanitize",
        "--trace",
        "-",
    ]);
    assert_eq!(code, Some(0), "{stderr}");
    // Helpers.Clamp(7.5, 0, 5) + Clamp(-1, 0, 5)
    assert_eq!(column(&trace, "main.y"), [5.0]);
}

/// An error inside a library is reported at the library's file.
#[test]
fn errors_in_a_library_name_its_file() {
    let (code, _, stderr) =
        ladderc_in_fixtures(&["check", "uses_bad.st", "--lib", "BadLib/BadLib.plcproj"]);
    assert_eq!(code, Some(1), "{stderr}");
    let heads = diagnostic_heads(stderr.as_bytes(), &fixtures(), false);
    assert_eq!(
        heads,
        ["BadLib/POUs/Broken.TcPOU:10:34: error[E1001]: undeclared name `undeclaredName`"]
    );
}

/// `--lib` naming no TwinCAT project: E1078 (exit 1); a path that cannot be read: E9001 (exit 2).
#[test]
fn lib_paths_that_are_no_projects() {
    let (code, _, stderr) =
        ladderc_in_fixtures(&["check", "uses_helpers.st", "--lib", "uses_bad.st"]);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("error[E1078]: --lib uses_bad.st is no TwinCAT PLC project"),
        "{stderr}"
    );
    let (code, _, stderr) = ladderc_in_fixtures(&["check", "uses_helpers.st", "--lib", "."]);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("error[E1078]: --lib .: the folder holds 4 TwinCAT PLC projects, not one"),
        "{stderr}"
    );
    let (code, _, stderr) = ladderc_in_fixtures(&[
        "check",
        "uses_helpers.st",
        "--lib",
        "missing/Missing.plcproj",
    ]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("error[E9001]: cannot read missing/Missing.plcproj"),
        "{stderr}"
    );
}
