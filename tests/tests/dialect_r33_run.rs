//! Round 33, dialect leftovers (issue #13), end to end through `ladderc run` / `ladderc check`:
//! - Softing 4CONTROL / ATCMcontrol: `#IMPORT "file"` in capitals is the same directive as
//!   `#import` (before: E0023 "this file is Siemens SCL"); its resource file (`RESOURCE r` without
//!   a CONFIGURATION) is one E1094 naming the construct (before: E0023 "Siemens SCL" at its
//!   `#IMPORT`);
//! - SIMATIC AX: the `DEFINED_PREPROCESSOR_SYMBOLS` of a project's `apax.yml` choose the
//!   `{::ifdef}` sections, given the project folder or its `.st` files (before: never defined,
//!   W1419), one note W1452;
//! - SFC: CODESYS's and TwinCAT's `Step._x` and `Step._t` (CODESYS SFC help "Implicit Variables",
//!   Beckhoff Infosys "Implicit variables") beside IEC's `Step.X` and `Step.T` (IEC 61131-3 ed. 2
//!   2.6.2), in a textual chart and a TwinCAT `.TcPOU` chart, `_x` written to force a step; an
//!   unknown step flag is one E1021 at the field naming the step (before: E1001 "undeclared name"
//!   at the step).

mod common;
use common::{check_files, column, in_dir, ladderc, run_stimulated, write_in};

use std::path::Path;

const COUNTER_P: &str = "PROGRAM Counter_P
#IMPORT \"Resource1.gvl\"
VAR
    n : INT;
END_VAR
    n := n + 1;
    total := total + 2;
END_PROGRAM
";

const RESOURCE1_GVL: &str = "VAR_GLOBAL
    total : INT;
END_VAR
";

const RESOURCE1_RES: &str = "(*[[
]]*)
RESOURCE Resource1
    #IMPORT \"Resource1.gvl\"
        TASK Fast (INTERVAL:=T#100ms, PRIORITY:=4, AUTOSTART:=TRUE);
        TASK Slow (EVENT:='4,12', PRIORITY:=0, AUTOSTART:=FALSE);
        PROGRAM Counter WITH Fast: Counter_P;
END_RESOURCE
";

/// 4CONTROL writes its import directive in capitals in configuration and resource files (and some
/// POUs): `#IMPORT "Resource1.gvl"` is read as `#import` (blanked, one W1458 note), and the program
/// runs with the global file given beside it. Before: E0023 "this file is Siemens SCL ...:
/// `#IMPORT` is SCL's prefix of a local variable", the file not compiled.
#[test]
fn four_control_import_in_capitals_is_the_import_directive() {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "Counter_P.st", COUNTER_P);
    write_in(dir.path(), "Resource1.gvl", RESOURCE1_GVL);
    let paths = [
        dir.path().join("Counter_P.st"),
        dir.path().join("Resource1.gvl"),
    ];
    let (trace, stderr) =
        common::run_stimulated_files(&paths, &["--cycle-ms", "10"], 3, "", "Counter_P.n");
    assert_eq!(column(&trace, "Counter_P.n"), [1.0, 2.0, 3.0]);
    assert!(!stderr.contains("E0023"), "{stderr}");
    assert!(stderr.contains("Counter_P.st:2:1: note[W1458]"), "{stderr}");
}

/// A 4CONTROL resource file (`Resource1.res`: `RESOURCE Resource1` with no CONFIGURATION around
/// it, `#IMPORT` lines, tasks with 4CONTROL's EVENT and AUTOSTART) is one E1094 at `RESOURCE
/// Resource1` naming 4CONTROL, and nothing else of the file is reported (no W1458 for its
/// `#IMPORT`s, no E0020 for AUTOSTART). IEC 61131-3 ed. 2 2.7.1 declares a resource inside a
/// configuration only. Before: E0023 "this file is Siemens SCL" at `#IMPORT`.
#[test]
fn four_control_resource_file_is_one_error_naming_it() {
    let (code, lines) = check_files(&[
        ("Counter_P.st", COUNTER_P),
        ("Resource1.gvl", RESOURCE1_GVL),
        ("Resource1.res", RESOURCE1_RES),
    ]);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:#?}");
    assert!(
        lines[0].starts_with("Resource1.res:3:1: error[E1094]")
            && lines[0].contains("`RESOURCE Resource1`")
            && lines[0].contains("4CONTROL")
            && lines[0].contains("CONFIGURATION"),
        "{lines:#?}"
    );
    // and the note of its `#IMPORT` is not given: the file is not compiled
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "Resource1.res", RESOURCE1_RES);
    let (_, _, stderr) = in_dir(dir.path(), &["check", "Resource1.res"]);
    assert!(!stderr.contains("W1458"), "{stderr}");
    assert!(!stderr.contains("E0023"), "{stderr}");
}

const AX_MAIN: &str = "PROGRAM Main
VAR
    variant : INT;
END_VAR
    {::ifdef SPEED_DRIVE}
    variant := 1;
    {::elseif POSITION_DRIVE}
    variant := 2;
    {::else}
    variant := 3;
    {::endif}
END_PROGRAM
";

const AX_CONFIGURATION: &str = "CONFIGURATION Plc
    TASK Main (INTERVAL := T#10ms, PRIORITY := 1);
    PROGRAM P1 WITH Main : Main;
END_CONFIGURATION
";

/// An `apax.yml` whose `variables` list `DEFINED_PREPROCESSOR_SYMBOLS` (as Siemens' sample
/// simatic-ax/ae-demo-rack does; a commented item is not defined).
fn apax_yml(symbols: &str) -> String {
    format!(
        "name: \"demo\"\nversion: 1.0.0\ntype: app\ntargets:\n  - \"1500\"\nvariables:\n  IP_ADDRESS: \"192.168.0.1\"\n  DEFINED_PREPROCESSOR_SYMBOLS:\n{symbols}  APAX_BUILD_ARGS:\n    - --debug\n"
    )
}

/// `ladderc run ARG` in `dir` for 2 scans: the trace's `P1.variant` column and standard error.
fn variant(dir: &Path, arg: &[&str]) -> (Vec<f64>, String) {
    let out = ladderc()
        .current_dir(dir)
        .args(["--message-format", "short", "run"])
        .args(arg)
        .args(["--cycles", "2", "--trace", "-", "--watch", "P1.variant"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    (
        column(&String::from_utf8_lossy(&out.stdout), "P1.variant"),
        stderr,
    )
}

/// SIMATIC AX's build defines the symbols its `apax.yml` lists under `DEFINED_PREPROCESSOR_SYMBOLS`:
/// given the project folder (its `src/` files are the inputs) or its `.st` files, ladderc defines
/// them too, so `{::ifdef SPEED_DRIVE}` compiles its section (variant 1), with one W1452 note at
/// the key naming the symbols; with the item commented out, the `{::else}` section (variant 3).
/// Before: the symbols were never defined (W1419), variant 3 whatever the `apax.yml` said, and a
/// project folder was E9001.
#[test]
fn apax_yml_symbols_choose_the_ifdef_section() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_in(
        d,
        "apax.yml",
        &apax_yml("    - SPEED_DRIVE\n    # - POSITION_DRIVE\n"),
    );
    write_in(d, "src/Main.st", AX_MAIN);
    write_in(d, "src/configuration.st", AX_CONFIGURATION);
    // the project folder
    let (v, stderr) = variant(d, &["."]);
    assert_eq!(v, [1.0, 1.0], "{stderr}");
    assert!(
        stderr.contains("apax.yml:8:3: note[W1452]") && stderr.contains("`SPEED_DRIVE`"),
        "{stderr}"
    );
    assert!(!stderr.contains("POSITION_DRIVE`,"), "{stderr}");
    assert!(!stderr.contains("W1419"), "{stderr}");
    // its .st files, given from another folder
    let (v, _) = variant(d.join("src").as_path(), &["Main.st", "configuration.st"]);
    assert_eq!(v, [1.0, 1.0]);
    // no symbol listed: the {::else} section
    write_in(d, "apax.yml", &apax_yml("    # - SPEED_DRIVE\n"));
    let (v, stderr) = variant(d, &["."]);
    assert_eq!(v, [3.0, 3.0], "{stderr}");
    assert!(stderr.contains("W1419"), "{stderr}");
}

/// CODESYS's and TwinCAT's step flags `Fill._x` (the activation status for the next cycle) and
/// `Fill._t` (an internal copy of the elapsed time) in a textual chart: read in the transition
/// (`Fill._t >= T#20ms` leaves Fill after 20 ms) and in the step's action; `Fill._x := TRUE`
/// written by Idle's action (`force`) activates Fill from the next scan, as CODESYS's forcing of a
/// step does. Before: E1001 "undeclared name `Fill`" (only `.X`/`.T` were the step's flags).
#[test]
fn textual_chart_reads_and_forces_underscore_step_flags() {
    let src = "PROGRAM Main
VAR
  force : BOOL;
  n : INT;
  el : TIME;
  busy : BOOL;
END_VAR
INITIAL_STEP Idle:
  Watch(N);
END_STEP
TRANSITION FROM Idle TO Fill := FALSE;
END_TRANSITION
STEP Fill:
  Count(N);
END_STEP
TRANSITION FROM Fill TO Idle := Fill._t >= T#20ms;
END_TRANSITION
ACTION Watch:
  IF force THEN
    Fill._x := TRUE;
    Idle._x := FALSE;
  END_IF;
END_ACTION
ACTION Count:
  n := n + 1;
  el := Fill._t;
  busy := Fill._x;
END_ACTION
END_PROGRAM
";
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "main.st", src);
    let (t, _) = run_stimulated(
        &dir.path().join("main.st"),
        7,
        "1,Main.force,1\n2,Main.force,0\n",
        "Main.n,Main.el,Main.busy,Main.__sfc_X_Idle,Main.__sfc_X_Fill",
    );
    // forced in scan 1, Fill active from scan 2 to 3, left in scan 4 (its time 20 ms)
    assert_eq!(
        column(&t, "Main.__sfc_X_Fill"),
        [0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0]
    );
    assert_eq!(
        column(&t, "Main.__sfc_X_Idle"),
        [1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0]
    );
    assert_eq!(column(&t, "Main.n"), [0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0]);
    assert_eq!(column(&t, "Main.busy"), [0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0]);
}

/// A TwinCAT `.TcPOU` chart (the fixture of `twincat_sfc_run.rs`) whose transition object
/// `T_Full` reads `Fill._t >= T#30ms` instead of the level: Fill is left after 30 ms, before the
/// level reaches 50. Before: E1001 "undeclared name `Fill`" in the transition.
#[test]
fn twincat_chart_reads_underscore_step_time() {
    let fixture =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/twincat_sfc/MAIN.TcPOU");
    let text = std::fs::read_to_string(fixture).unwrap();
    let changed = text.replace("nLevel >= 50]]>", "Fill._t >= T#30ms]]>");
    assert_ne!(changed, text);
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "MAIN.TcPOU", &changed);
    let (t, _) = run_stimulated(
        &dir.path().join("MAIN.TcPOU"),
        9,
        "2,MAIN.bStart,1\n3,MAIN.bStart,0\n",
        "MAIN.nLevel,MAIN.nExit,MAIN.__sfc_X_Fill,MAIN.__sfc_X_Drain",
    );
    let fill = column(&t, "MAIN.__sfc_X_Fill");
    let first = fill.iter().position(|&v| v == 1.0).unwrap();
    let left = first + fill[first..].iter().position(|&v| v == 0.0).unwrap();
    // active 4 scans (TwinCAT's processing order since round 34: `Fill._x` set by the transition
    // check at the end of the scan at 20 ms, its actions from 30 ms, `_t` 0..30 ms, left by the
    // check of the scan that reads 30 ms; before: 3 scans); the level is 40 then (aFill ran in
    // that scan before the check), short of the 50 the fixture's own condition waits for
    assert_eq!(left - first, 4, "{t}");
    assert_eq!(column(&t, "MAIN.__sfc_X_Drain")[left], 1.0, "{t}");
    assert_eq!(column(&t, "MAIN.nLevel")[left - 1], 30.0, "{t}");
    assert_eq!(column(&t, "MAIN.nLevel")[left], 40.0, "{t}");
}

/// An unknown flag of a step (`Fill.Foo`) is one E1021 at the field, naming the step and the
/// flags a step has, in a transition and in an action. Before: E1001 "undeclared name `Fill`" at
/// the step (which the chart declares).
#[test]
fn unknown_step_flag_is_one_error_at_the_field() {
    let src = "PROGRAM Main
VAR
  go : BOOL;
  n : INT;
END_VAR
INITIAL_STEP Idle:
END_STEP
TRANSITION FROM Idle TO Fill := go;
END_TRANSITION
STEP Fill:
  Count(N);
END_STEP
TRANSITION FROM Fill TO Idle := Fill.Foo;
END_TRANSITION
ACTION Count:
  n := n + 1;
  go := Idle.Bar;
END_ACTION
END_PROGRAM
";
    let (code, lines) = check_files(&[("main.st", src)]);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 2, "{lines:#?}");
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("main.st:13:38: error[E1021]")
                && l.contains("step `Fill` has no flag `Foo`")),
        "{lines:#?}"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("main.st:17:14: error[E1021]")
                && l.contains("step `Idle` has no flag `Bar`")),
        "{lines:#?}"
    );
}
