//! Round 26 of unseen projects (issue #13), TwinCAT: what real projects need, run end to end
//! through `ladderc run`:
//! - a TwinCAT SFC POU whose SFC settings say "use defaults" (every chart TwinCAT creates) runs
//!   with the flags TwinCAT saves with it, the project's settings copied into the POU (before:
//!   E0321, its message broken by runs of 18 blanks);
//! - `Axis();`, a call of a Tc2_MC2 `AXIS_REF` (a function block there), refreshes the axis's
//!   status as `Axis.ReadStatus()` does (before: E1018 "`Axis` is AXIS_REF, not an FB instance").

mod common;
use common::{ladderc, run_traced_files};
use std::path::Path;

/// `ladderc run` of `file` for `cycles` scans of 10 ms with `stimulus`, watching `watch`: the
/// trace, after asserting exit 0.
fn run(file: &Path, cycles: u32, stimulus: &str, watch: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, format!("cycle,variable,value\n{stimulus}")).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(file)
        .args([
            "--cycles",
            &cycles.to_string(),
            "--cycle-ms",
            "10",
            "--stimulus",
        ])
        .arg(&stim)
        .args(["--trace", "-", "--watch", watch])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("E0321"), "{stderr}");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The SFC fixture of `twincat_sfc_run.rs` (its settings enable SFCReset) saved with "use
/// defaults" ticked runs as it does unticked: TwinCAT copies the project's SFC settings into each
/// SFC object and saves them with it, so the flags saved beside `UseDefaults` are the ones in
/// force (here SFCReset resets the chart to its initial step).
#[test]
fn an_sfc_pou_whose_settings_use_the_defaults_runs_with_the_flags_saved_with_it() {
    let fixture =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/twincat_sfc/MAIN.TcPOU");
    let src = std::fs::read_to_string(&fixture).unwrap();
    let unticked = r#"<v n="UseDefaults">false</v>"#;
    assert!(src.contains(unticked));
    let dir = tempfile::tempdir().unwrap();
    let defaults = dir.path().join("MAIN.TcPOU");
    std::fs::write(
        &defaults,
        src.replace(unticked, r#"<v n="UseDefaults">true</v>"#),
    )
    .unwrap();
    let watch = "MAIN.nLevel,MAIN.__sfc_X_Idle,MAIN.__sfc_X_Fill,MAIN.__sfc_X_Drain";
    let stimulus = "2,MAIN.bStart,1\n3,MAIN.bStart,0\n5,MAIN.SFCReset,1\n6,MAIN.SFCReset,0\n";
    let with_defaults = run(&defaults, 10, stimulus, watch);
    assert_eq!(with_defaults, run(&fixture, 10, stimulus, watch));
    let fill = common::column(&with_defaults, "MAIN.__sfc_X_Fill");
    let idle = common::column(&with_defaults, "MAIN.__sfc_X_Idle");
    // bStart enters Fill; SFCReset (a flag the saved settings enable) brings the chart back to Idle
    assert_eq!(fill[2], 1.0, "{with_defaults}");
    assert_eq!((idle[5], fill[5]), (1.0, 0.0), "{with_defaults}");
}

/// `Axis();` where `Axis.ReadStatus();` stood: the same run, status and NC values read from the
/// simulated axis (TwinCAT's AXIS_REF is a function block; ladderc refreshes its Status at the
/// call as `ReadStatus()` does, its NcToPlc at the start of every scan as the NC does).
#[test]
fn a_call_of_an_axis_ref_refreshes_its_status_as_read_status_does() {
    let dir = tempfile::tempdir().unwrap();
    let program = |call: &str| {
        format!(
            "PROGRAM MAIN\nVAR\n  Axis : AXIS_REF;\n  fbPower : MC_Power;\n  fbMove : MC_MoveAbsolute;\n\
             \x20 bMoving, bStill : BOOL;\n  p : LREAL;\nEND_VAR\n\
             fbPower(Axis := Axis, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);\n\
             fbMove(Axis := Axis, Execute := fbPower.Status, Position := 10.0, Velocity := 100.0);\n\
             {call}\nbMoving := Axis.Status.Moving;\nbStill := Axis.Status.StandStill;\n\
             p := Axis.NcToPlc.ActPos;\nEND_PROGRAM\n"
        )
    };
    let axes =
        "{ \"cycle_ms\": 10, \"axes\": [ { \"name\": \"X1\", \"unit\": \"mm\", \"velocity\": 100, \
                \"acceleration\": 3000, \"deceleration\": 3000 } ] }";
    let mut traces = Vec::new();
    for (name, call) in [("called", "Axis();"), ("read", "Axis.ReadStatus();")] {
        let src = dir.path().join(format!("{name}.st"));
        std::fs::write(&src, program(call)).unwrap();
        std::fs::write(dir.path().join(format!("{name}.axes.json")), axes).unwrap();
        let (trace, stderr) = run_traced_files(&[&src], 30, "MAIN.bMoving,MAIN.bStill,MAIN.p");
        assert!(!stderr.contains("error"), "{stderr}");
        traces.push(trace);
    }
    assert_eq!(traces[0], traces[1]);
    let moving = common::column(&traces[0], "MAIN.bMoving");
    let still = common::column(&traces[0], "MAIN.bStill");
    assert!(moving.contains(&1.0) && still[29] == 1.0, "{}", traces[0]);
}
