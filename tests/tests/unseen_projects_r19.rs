//! Round 19 of issue #13: real public programs never seen before, run as a new user would. The
//! four files here are bundled (`tests/corpus/`, MIT and Apache-2.0, `ATTRIBUTION.md`); the
//! constructs of the other projects of the round are reproduced in texts of our own
//! (`codesys_st_forms_run.rs`, `additional_blocks_run.rs`, `twincat_graphical_run.rs`,
//! `twincat_files.rs`).
//!
//! | program | before this round | now |
//! |---|---|---|
//! | jasonleecode/OpenPLC `tools/traffic.st` | runs | runs (phases checked) |
//! | kaz19610303/OpenPLC_test_bench `Spresense_Blink.st` | runs | runs (blink period checked) |
//! | LilKiddy007/twincat3-plc-motion-control `src/main.st` | runs with an axes file | the same (steps and velocities checked) |
//! | justkuchkorov/tcs `PLC_PRG.st` | one E1003 `PID_FIXCYCLE` | one E1003 that names CODESYS's Util library |

mod common;
use common::{column, ladderc, repo_root};

use std::path::PathBuf;

fn file(name: &str) -> PathBuf {
    let p = repo_root().join("tests/corpus").join(name);
    assert!(p.is_file(), "{} is missing", p.display());
    p
}

/// The cycles where column `name` changes, with the new value (the first row included).
fn changes(trace: &str, name: &str) -> Vec<(usize, f64)> {
    let mut out: Vec<(usize, f64)> = Vec::new();
    for (k, v) in column(trace, name).into_iter().enumerate() {
        if out.last().is_none_or(|(_, last)| *last != v) {
            out.push((k, v));
        }
    }
    out
}

fn run(path: &std::path::Path, args: &[&str]) -> String {
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(path)
        .args(["--sanitize", "--trace", "-"])
        .args(args)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("error["), "{stderr}");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// A traffic light of one TON restarted per phase (10 ms scans): NS green 20 s, yellow 3 s, all
/// red 2 s, EW green 20 s, yellow 3 s, all red 2 s; each restart takes the scan that resets the
/// timer, and a phase's lamps light in the scan after its state is set.
#[test]
fn jasonleecode_traffic_light_runs_its_six_phases() {
    let trace = run(
        &file("jasonleecode_OpenPLC_traffic.st"),
        &[
            "--cycles",
            "5010",
            "--watch",
            "TrafficLight.State,TrafficLight.EW_G",
        ],
    );
    assert_eq!(
        changes(&trace, "TrafficLight.State"),
        [
            (0, 1.0),
            (2000, 2.0),
            (2301, 3.0),
            (2502, 4.0),
            (4503, 5.0),
            (4804, 6.0),
            (5005, 1.0)
        ]
    );
    assert_eq!(
        changes(&trace, "TrafficLight.EW_G"),
        [(0, 0.0), (2503, 1.0), (4504, 0.0)]
    );
}

/// OpenPLC Editor's TON/TOF blinker (20 ms task, EN/ENO chained): the LED toggles every 26 scans.
#[test]
fn kaz19610303_blinker_toggles_every_520_ms() {
    let trace = run(
        &file("kaz19610303_OpenPLC_test_bench_Spresense_Blink.st"),
        &[
            "--cycles",
            "200",
            "--cycle-ms",
            "20",
            "--watch",
            "instance0.blink_led",
        ],
    );
    let toggles: Vec<usize> = changes(&trace, "instance0.blink_led")
        .into_iter()
        .skip(1)
        .map(|(k, _)| k)
        .collect();
    assert_eq!(toggles, [25, 51, 77, 103, 129, 155, 181]);
}

/// A TwinCAT MAIN written as text (MC_Power, MC_MoveVelocity, MC_Halt, MC_Stop on one axis): with
/// a one-axis file it moves +300 deg/s for 5 s, -300 for 5 s, +1000 for 7 s, then counts a cycle.
#[test]
fn lilkiddy007_motion_sequence_runs_its_steps() {
    let dir = tempfile::tempdir().unwrap();
    let main = dir.path().join("main.st");
    std::fs::copy(
        file("LilKiddy007_twincat3-plc-motion-control_main.st"),
        &main,
    )
    .unwrap();
    std::fs::write(
        dir.path().join("main.axes.json"),
        r#"{"cycle_ms":10,"axes":[{"name":"Axis","unit":"deg","counts_per_unit":1,"velocity":2000,
           "acceleration":10000,"deceleration":10000,"jerk":0,"modulo_period":0,
           "following_error_limit":0}]}"#,
    )
    .unwrap();
    let trace = run(
        &main,
        &[
            "--cycles",
            "1710",
            "--watch",
            "MAIN.Step,MAIN.Cyclecount,axis.Axis.velocity",
        ],
    );
    assert_eq!(
        changes(&trace, "MAIN.Step"),
        [(0, 0.0), (501, 1.0), (1003, 2.0), (1705, 0.0)]
    );
    assert_eq!(changes(&trace, "MAIN.Cyclecount"), [(0, 0.0), (1705, 1.0)]);
    let v = column(&trace, "axis.Axis.velocity");
    assert_eq!((v[300], v[800], v[1400]), (300.0, -300.0, 1000.0));
}

/// A CODESYS PLC_PRG using Util's PID_FIXCYCLE: one located E1003 naming the library, exit 1.
#[test]
fn justkuchkorov_util_pid_is_one_error_naming_its_library() {
    one_error(
        &file("justkuchkorov_tcs_PLC_PRG.st"),
        "justkuchkorov_tcs_PLC_PRG.st:23:25: error[E1003]: unknown type `PID_FIXCYCLE` (hint: `PID_FIXCYCLE` is a block of CODESYS's Util library",
    );
}

/// `ladderc check FILE` exits 1 with one error line, which holds `want`.
fn one_error(path: &std::path::Path, want: &str) {
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(path)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(errors[0].contains(want), "{stderr}");
}

/// OpenPLC Editor v4 (yaseralie/OpenPLC_Arduino, round 19): a `.fbd` POU (a `.ld` one runs since
/// round 24: openplc_v4_ld_run.rs) is declarations then JSON
/// graphics: one located E1073 (before: 7,649 errors, one per JSON line), exit 1; its project
/// folder (`project.json`, no plc.xml) is one E9001 that says so and names the generated XML
/// (before: "Is a directory (os error 21)", "check the permissions"), exit 2.
#[test]
fn an_openplc_editor_v4_json_body_and_project_folder_are_one_diagnostic_each() {
    let dir = tempfile::tempdir().unwrap();
    let programs = dir.path().join("pous/programs");
    std::fs::create_dir_all(&programs).unwrap();
    std::fs::write(
        dir.path().join("project.json"),
        "{ \"type\": \"plc-project\" }\n",
    )
    .unwrap();
    // (an FBD body, `"rung": {...}`; a ladder body's `"rungs"` are read since round 24:
    // openplc_v4_ld_run.rs)
    let ld = programs.join("main.fbd");
    std::fs::write(
        &ld,
        "PROGRAM main\nVAR\n\tLED1 : bool AT %QX0.0;\nEND_VAR\n\n{\n  \"name\": \"main\",\n  \
         \"rung\": {\n      \"comment\": \"\",\n      \"nodes\": [],\n      \"edges\": []\n    \
         }\n}\n",
    )
    .unwrap();
    one_error(
        &ld,
        "main.fbd:6:1: error[E1073]: an OpenPLC Editor v4 graphical body",
    );
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(dir.path())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.contains("is a folder that holds no project ladderc reads")
            && stderr.contains("OpenPLC Editor v4 project (project.json)")
            && !stderr.contains("permissions"),
        "{stderr}"
    );
}
