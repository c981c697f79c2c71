//! Every redistributable real project of `tests/corpus/` (see its ATTRIBUTION.md) through the
//! `ladderc` binary: programs run a few cycles (C compiled with sanitizers and executed), files that
//! need what the export does not contain (vendor library types, POINTER TO) or that are not valid
//! IEC 61131-3 are rejected with exit 1, every error located (`file:line:col: error[CODE]`), and
//! naming what is missing. `.st` files are Structured Text (issue #13.1): they run too, and the
//! TwinCAT math library checks with one located E1019 per IronPLC intrinsic it calls.

mod common;
use common::ladderc;

use std::path::PathBuf;

/// `tests/corpus` of the workspace: the folder beside the `Cargo.lock` above this crate.
fn corpus_dir() -> PathBuf {
    let here = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let root = here
        .ancestors()
        .find(|a| a.join("Cargo.lock").is_file())
        .expect("the workspace root (Cargo.lock) above CARGO_MANIFEST_DIR");
    root.join("tests/corpus")
}

fn file(name: &str) -> PathBuf {
    let p = corpus_dir().join(name);
    assert!(p.is_file(), "{} is missing", p.display());
    p
}

/// Runs a project for `cycles` cycles; returns the trace.
fn runs(name: &str, cycles: u32) -> String {
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .arg("run")
        .arg(file(name))
        .args(["--cycles", &cycles.to_string(), "--sanitize", "--trace"])
        .arg(&trace)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{name}: {err}");
    assert!(!err.contains("runtime error"), "{name}: {err}");
    let text = std::fs::read_to_string(&trace).unwrap();
    assert_eq!(text.lines().count(), cycles as usize + 1, "{name}: {text}");
    text
}

/// Checks a file that must be rejected: exit 1, every error line located in the file itself, each
/// code among `codes`; returns the error lines.
fn rejected(name: &str, codes: &[&str]) -> Vec<String> {
    let out = ladderc()
        .args([
            "--message-format",
            "short",
            "--max-diagnostics",
            "0",
            "check",
        ])
        .arg(file(name))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(1), "{name}: {err}");
    let errors: Vec<String> = err
        .lines()
        .filter(|l| l.contains(": error["))
        .map(str::to_string)
        .collect();
    assert!(!errors.is_empty(), "{name}: {err}");
    let prefix = format!("{}:", file(name).display());
    for e in &errors {
        let rest = e
            .strip_prefix(&prefix)
            .unwrap_or_else(|| panic!("{name}: not located in the file: {e}"));
        let mut parts = rest.splitn(3, ':');
        let line: u32 = parts.next().unwrap().parse().expect("a line number");
        let col: u32 = parts.next().unwrap().parse().expect("a column number");
        assert!(line > 0 && col > 0, "{e}");
        assert!(
            codes.iter().any(|c| e.contains(&format!("error[{c}]"))),
            "{name}: unexpected code: {e}"
        );
    }
    errors
}

#[test]
fn openplc_dancing_lights_ld_runs() {
    let t = runs("godardhi0_dancinglights_plc.xml", 5);
    assert!(t.starts_with("cycle,time_ms,"), "{t}");
}

#[test]
fn idaholab_spemmcra_ld_runs() {
    runs("idaholab_SPEMMCRA_plc.xml", 5);
}

#[test]
fn codesys_s7rtt_st_motion_runs() {
    runs("feecat_S7RTT.xml", 3);
}

#[test]
fn wago_e_cockpit_export_runs() {
    let t = runs("AandIF_e-COCKPIT_python_scripting_plc.xml", 3);
    assert_eq!(t, "cycle,time_ms,PLC_PRG.i\n0,0,1\n1,10,2\n2,20,3\n");
}

#[test]
fn codesys_home_automation_export_names_its_vendor_libraries() {
    let errors = rejected(
        "MichielVanwelsenaere_HomeAutomation_CoDeSys3_PLCopen.xml",
        &["E3009", "E3012"],
    );
    let all = errors.join("\n");
    // the CODESYS-specific parts that are read now: no error about them any more
    for gone in ["interval", "typeName", "array dimension", "<derived> type"] {
        assert!(!all.contains(gone), "{gone}: {all}");
    }
    // what the export genuinely lacks: library types, named as the file names them, and POINTER TO
    for lib in [
        "`JSONVAR`",
        "`MQTT.QoS`",
        "`WagoAppDALI.",
        "`SysCom.SysComSettings`",
        "type <pointer>",
    ] {
        assert!(all.contains(lib), "{lib}: {all}");
    }
    // Standard.TON is the IEC timer, not a missing library type
    assert!(!all.contains("Standard.TON"), "{all}");
}

#[test]
fn il_parser_test1_is_rejected_for_its_set_without_operand() {
    let e = rejected("hiperiondev_il_parser_test1.il", &["E1016"]);
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(
        e[0].contains("test1.il:24:1: error[E1016]: S without operand"),
        "{e:?}"
    );
}

#[test]
fn il_parser_test2_is_rejected_for_its_semicolon_comments() {
    let e = rejected("hiperiondev_il_parser_test2.il", &["E0007"]);
    assert!(
        e.iter()
            .all(|l| l.contains("`;` comments are not IEC 61131-3")),
        "{e:?}"
    );
}

/// The ST text files: each is a program (or, for Tc2_Math, a library) that should run or check once
/// `.st` files are read as Structured Text.
fn st_runs(name: &str) {
    runs(name, 3);
}

#[test]
fn st_spemmcra_plc() {
    st_runs("idaholab_SPEMMCRA_plc.st");
}

#[test]
fn st_spemmcra_dnp3_microgrid() {
    st_runs("idaholab_SPEMMCRA_DNP3_Microgrid.st");
}

#[test]
fn st_ironplc_getting_started() {
    st_runs("ironplc_getting_started.st");
}

#[test]
fn st_ironplc_quickstart_timer() {
    st_runs("ironplc_quickstart_timer.st");
}

#[test]
fn st_ironplc_quickstart_helloworld() {
    st_runs("ironplc_quickstart_helloworld.st");
}

#[test]
fn st_ironplc_motor() {
    st_runs("ironplc_motor.st");
}

#[test]
fn st_ironplc_tc2_math_library() {
    rejected("ironplc_Tc2_Math.st", &["E1019"]);
}
