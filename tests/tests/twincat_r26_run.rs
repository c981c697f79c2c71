//! Round 26 of unseen projects (issue #13), TwinCAT: what real projects need, run end to end
//! through `ladderc run`:
//! - a TwinCAT SFC POU whose SFC settings say "use defaults" (every chart TwinCAT creates) runs
//!   with the flags TwinCAT saves with it, the project's settings copied into the POU (before:
//!   E0321, its message broken by runs of 18 blanks);
//! - `Axis();`, a call of a Tc2_MC2 `AXIS_REF` (a function block there), refreshes the axis's
//!   status as `Axis.ReadStatus()` does (before: E1018 "`Axis` is AXIS_REF, not an FB instance");
//! - `Configuration` and `Resource` name variables of TwinCAT objects, with W1418 as `ON` does
//!   (before: E1031; TwinCAT has no textual configuration and does not reserve them);
//! - a `--lib` library's own `PROGRAM MAIN` (every library made from TwinCAT's template keeps one)
//!   is shadowed by the application's `MAIN` (before: E1002 "`MAIN` is declared twice").

mod common;
use common::{check_text, column, in_dir, ladderc, run_traced_files, write_in};
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
    let fill = column(&with_defaults, "MAIN.__sfc_X_Fill");
    let idle = column(&with_defaults, "MAIN.__sfc_X_Idle");
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
    let moving = column(&traces[0], "MAIN.bMoving");
    let still = column(&traces[0], "MAIN.bStill");
    assert!(moving.contains(&1.0) && still[29] == 1.0, "{}", traces[0]);
}

/// A TwinCAT object holding one POU: `kind` `POU`, `DUT` ..., its declaration and ST body.
fn tc_pou(name: &str, declaration: &str, body: &str) -> String {
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4024.12\">\n\
         \x20 <POU Name=\"{name}\" Id=\"{{00000000-0000-0000-0000-000000000001}}\" SpecialFunc=\"None\">\n\
         \x20   <Declaration><![CDATA[{declaration}]]></Declaration>\n\
         \x20   <Implementation>\n      <ST><![CDATA[{body}]]></ST>\n    </Implementation>\n\
         \x20 </POU>\n</TcPlcObject>\n"
    )
}

/// A function block whose inputs are named `Configuration` and `Resource` (a real project's
/// `Configuration : ST_ConveyorConfig`): called with them as formal parameters, read in its body,
/// one W1418 at each declaration; in a plain `.st` file the name stays E1031.
#[test]
fn configuration_and_resource_name_variables_of_twincat_objects() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "FB_Sum.TcPOU",
        &tc_pou(
            "FB_Sum",
            "FUNCTION_BLOCK FB_Sum\nVAR_INPUT\n  Configuration : INT;\n  Resource : INT;\nEND_VAR\nVAR_OUTPUT\n  total : INT;\nEND_VAR\n",
            "total := Configuration * 10 + Resource;",
        ),
    );
    write_in(
        dir.path(),
        "MAIN.TcPOU",
        &tc_pou(
            "MAIN",
            "PROGRAM MAIN\nVAR\n  s : FB_Sum;\n  r : INT;\nEND_VAR\n",
            "s(Configuration := 4, Resource := 2);\nr := s.total;",
        ),
    );
    let (code, stdout, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "FB_Sum.TcPOU",
            "MAIN.TcPOU",
            "--cycles",
            "2",
            "--trace",
            "-",
            "--watch",
            "MAIN.r",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&stdout, "MAIN.r"), vec![42.0, 42.0], "{stdout}");
    let w1418: Vec<&str> = stderr.lines().filter(|l| l.contains("W1418")).collect();
    assert_eq!(w1418.len(), 2, "{stderr}");
    assert!(
        w1418[0].contains("FB_Sum.TcPOU:6:3") && w1418[0].contains("`Configuration`"),
        "{stderr}"
    );
    assert!(
        w1418[1].contains("FB_Sum.TcPOU:7:3") && w1418[1].contains("`Resource`"),
        "{stderr}"
    );
    let (code, diags) = check_text(
        "plain.st",
        "PROGRAM Main\nVAR\n  Resource : INT;\nEND_VAR\nResource := 1;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert!(diags[0].contains("E1031"), "{diags:?}");
}

/// An application and a `--lib` library project that both have a `PROGRAM MAIN` (the library's is
/// the empty one of TwinCAT's template): the application's runs, the library's block is used.
#[test]
fn a_library_program_is_shadowed_by_the_application_pou_of_its_name() {
    let dir = tempfile::tempdir().unwrap();
    let project = |name: &str, files: &[&str], reference: &str| {
        let compile: String = files
            .iter()
            .map(|f| {
                format!("    <Compile Include=\"POUs\\{f}\"><SubType>Code</SubType></Compile>\n")
            })
            .collect();
        format!(
            "<Project DefaultTargets=\"Build\" xmlns=\"http://schemas.microsoft.com/developer/msbuild/2003\">\n\
             \x20 <PropertyGroup>\n    <Name>{name}</Name>\n    <Title>{name}</Title>\n  </PropertyGroup>\n\
             \x20 <ItemGroup>\n{compile}  </ItemGroup>\n  <ItemGroup>\n{reference}  </ItemGroup>\n</Project>\n"
        )
    };
    write_in(
        dir.path(),
        "Lib/Halves.plcproj",
        &project("Halves", &["FB_Half.TcPOU", "MAIN.TcPOU"], ""),
    );
    write_in(
        dir.path(),
        "Lib/POUs/FB_Half.TcPOU",
        &tc_pou(
            "FB_Half",
            "FUNCTION_BLOCK FB_Half\nVAR_INPUT i : INT; END_VAR\nVAR_OUTPUT o : INT; END_VAR\n",
            "o := i / 2;",
        ),
    );
    write_in(
        dir.path(),
        "Lib/POUs/MAIN.TcPOU",
        &tc_pou(
            "MAIN",
            "PROGRAM MAIN\nVAR\n  unused : INT;\nEND_VAR\n",
            "unused := 1;",
        ),
    );
    write_in(
        dir.path(),
        "App/App.plcproj",
        &project(
            "App",
            &["MAIN.TcPOU"],
            "    <PlaceholderReference Include=\"Halves\">\n      <DefaultResolution>Halves, * (Me)</DefaultResolution>\n      <Namespace>Halves</Namespace>\n    </PlaceholderReference>\n",
        ),
    );
    write_in(
        dir.path(),
        "App/POUs/MAIN.TcPOU",
        &tc_pou(
            "MAIN",
            "PROGRAM MAIN\nVAR\n  h : FB_Half;\n  r : INT;\nEND_VAR\n",
            "h(i := 84);\nr := h.o;",
        ),
    );
    let (code, stdout, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "App/App.plcproj",
            "--lib",
            "Lib/Halves.plcproj",
            "--cycles",
            "1",
            "--trace",
            "-",
            "--watch",
            "MAIN.r",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&stdout, "MAIN.r"), vec![42.0], "{stdout}");
    assert!(!stdout.contains("unused"), "{stdout}");
}
