//! Issue #13, ninth round (helper `lang10`): the gaps left from earlier rounds, each through
//! `ladderc run`/`check` (or the library API) on small inputs written here:
//! - **Beremiz project folders** (`tests/tests/fixtures/beremiz/mixer/`: `plc.xml`, `beremiz.xml` and
//!   confnodes `c_code@c_ext`, `py_ext_0@py_ext`, `modbus_0@modbus`, `mqtt_0@mqtt`): `ladderc run DIR`
//!   and `DIR/plc.xml` declare the confnodes' variables as configuration globals (the C extension's and
//!   the Python file's `<variables>` with their initial values, the MQTT client's `MQTT_STATUS_3`), and
//!   each confnode whose code or field bus does not run is one located W0320. Before: the program's
//!   VAR_EXTERNALs were E1022 ("no global variable").

mod common;
use common::{column, ladderc, run_stimulated};
use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    common::repo_root()
        .join("tests/tests/fixtures/beremiz")
        .join(name)
}

/// `ladderc check PATH` (short format): exit code and the error and warning lines, with `strip` left
/// out of the paths.
fn check_path(path: &Path, strip: &Path) -> (Option<i32>, Vec<String>) {
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(path)
        .output()
        .unwrap();
    let prefix = format!("{}/", strip.display());
    let lines = String::from_utf8_lossy(&out.stderr)
        .lines()
        .filter(|l| l.contains("error[") || l.contains("warning["))
        .map(|l| l.replace(&prefix, ""))
        .map(|l| l.split_once(" (hint").map_or(l.clone(), |(h, _)| h.to_string()))
        .collect();
    (out.status.code(), lines)
}

/// Copies the fixture folder `name` into a fresh temporary folder.
fn copy_fixture(name: &str) -> tempfile::TempDir {
    fn copy(from: &Path, to: &Path) {
        std::fs::create_dir_all(to).unwrap();
        for e in std::fs::read_dir(from).unwrap() {
            let e = e.unwrap();
            let target = to.join(e.file_name());
            if e.file_type().unwrap().is_dir() {
                copy(&e.path(), &target);
            } else {
                std::fs::copy(e.path(), target).unwrap();
            }
        }
    }
    let dir = tempfile::tempdir().unwrap();
    copy(&fixture(name), &dir.path().join(name));
    dir
}

#[test]
fn a_beremiz_folder_runs_with_the_globals_of_its_confnodes() {
    // Setpoint (c_ext, initial 21), Pulses (py_ext), MQTT_STATUS_3 (the MQTT client on channel 3)
    let (trace, stderr) = run_stimulated(
        &fixture("mixer"),
        6,
        "2,Pulses,5\n4,MQTT_STATUS_3,1\n",
        "plant.total,%QW0.0.0,Setpoint,Pulses,MQTT_STATUS_3",
    );
    assert_eq!(column(&trace, "Setpoint"), [21.0; 6]);
    assert_eq!(column(&trace, "plant.total"), [0.0, 0.0, 5.0, 10.0, 15.0, 20.0]);
    assert_eq!(column(&trace, "%QW0.0.0"), [42.0, 42.0, 42.0, 42.0, 43.0, 43.0]);
    // one located W0320 per confnode whose code or field bus does not run, nothing else
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("warning[")).collect();
    assert_eq!(warnings.len(), 4, "{stderr}");
    for (file, what) in [
        ("modbus_0@modbus/confnode.xml:2:1", "confnode `modbus_0` (modbus) does not run"),
        ("c_code@c_ext/cfile.xml:10:3", "the C code of confnode `c_code` (c_ext) does not run"),
        (
            "py_ext_0@py_ext/pyfile.xml:10:3",
            "the Python code of confnode `py_ext_0` (py_ext) does not run",
        ),
        ("mqtt_0@mqtt/confnode.xml:2:1", "confnode `mqtt_0` (mqtt) does not run"),
    ] {
        assert!(
            warnings
                .iter()
                .any(|w| w.contains(file) && w.contains("warning[W0320]") && w.contains(what)),
            "{file}: {stderr}"
        );
    }
}

#[test]
fn the_plc_xml_of_a_beremiz_folder_reads_the_folder_and_alone_it_does_not() {
    let dir = copy_fixture("mixer");
    let plc = dir.path().join("mixer/plc.xml");
    let (code, lines) = check_path(&plc, dir.path());
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 4, "{lines:?}");
    assert!(lines.iter().all(|l| l.contains("warning[W0320]")), "{lines:?}");
    // without beremiz.xml the file is a plain PLCopen project: its externals name no global
    std::fs::remove_file(dir.path().join("mixer/beremiz.xml")).unwrap();
    let (code, lines) = check_path(&plc, dir.path());
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        lines,
        [
            "mixer/plc.xml:17:29: error[E1022]: no global variable `Setpoint` [POU `mixer`]",
            "mixer/plc.xml:18:29: error[E1022]: no global variable `Pulses` [POU `mixer`]",
            "mixer/plc.xml:19:29: error[E1022]: no global variable `MQTT_STATUS_3` [POU `mixer`]",
        ]
    );
}

#[test]
fn a_confnode_variable_that_cannot_be_read_is_one_located_error() {
    // the parse stage stops at it: one error, in the confnode's file
    let dir = copy_fixture("mixer");
    let cfile = dir.path().join("mixer/c_code@c_ext/cfile.xml");
    let text = std::fs::read_to_string(&cfile).unwrap().replace(
        r#"<variable name="Setpoint" type="INT" initial="21"/>"#,
        r#"<variable name="Setpoint" type="" initial="21"/>"#,
    );
    std::fs::write(&cfile, text).unwrap();
    let (code, lines) = check_path(&dir.path().join("mixer"), dir.path());
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(
        errors,
        [
            "mixer/c_code@c_ext/cfile.xml:8:37: error[E0320]: confnode variable `Setpoint` has no valid type (``); it is not declared",
        ]
    );
}
