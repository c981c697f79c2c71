//! Issue #13, ninth round (helper `lang10`): the gaps left from earlier rounds, each through
//! `ladderc run`/`check` (or the library API) on small inputs written here:
//! - **Beremiz project folders** (`tests/tests/fixtures/beremiz/mixer/`: `plc.xml`, `beremiz.xml` and
//!   confnodes `c_code@c_ext`, `py_ext_0@py_ext`, `modbus_0@modbus`, `mqtt_0@mqtt`): `ladderc run DIR`
//!   and `DIR/plc.xml` declare the confnodes' variables as configuration globals (the C extension's and
//!   the Python file's `<variables>` with their initial values, the MQTT client's `MQTT_STATUS_3`), and
//!   each confnode whose code or field bus does not run is one located W0320. Before: the program's
//!   VAR_EXTERNALs were E1022 ("no global variable").
//! - **CODESYS V2.3 object files** (`tests/tests/fixtures/codesys_v2/`: `Tank.pou.xml` with an
//!   action, `PLC_PRG.pou.xml`, `Globals.gvl.xml` in ISO-8859-1, `Tank_State.dut.xml`; the layout of
//!   CODESYS V2.3's version-control export, as in flhofer/IEC_61131-3_TestLib): the `<interface>` and
//!   `<st><body>` texts are read as ST in place, so diagnostics keep the file's lines and columns; a
//!   graphical body is one E0321. Before: E3002 "root element is <pou>".
//! - **A PLCopen file of one POU** (`tests/tests/fixtures/plcopen_pou/ramp.cfc`: root `<pou
//!   xmlns="http://www.plcopen.org/xml/tc6_0201">`, as RuSTy's and Bachmann's CFC files, with the
//!   interface written as text in `<addData><data><textDeclaration><content>`): read as the project
//!   of that POU, the text declarations located in the file. Before: E3002, and the declarations
//!   were not read.
//! - **A missing `;`** after a STRUCT's last field, before `END_VAR`, or between two declarations:
//!   no public CODESYS or TwinCAT source or document shows a vendor accepting it (the W0013 case,
//!   `END_STRUCT END_TYPE`, is the one they do accept), so it stays an error, now one E0011 where
//!   the `;` belongs, with the declaration completed in the hint. Before: the error was at the next
//!   token (`END_STRUCT`, the next name), and a missing `;` before `END_STRUCT` also gave a second
//!   error at `END_TYPE`.
//! - **Access paths in the library API**: `CheckedProject::access_paths`, `LoweredProject::…` and
//!   `GeneratedProject::access_paths` give each `VAR_ACCESS` entry (ST/IL configurations and PLCopen
//!   XML `<accessVars>`) with its configuration, name, path, type and direction; the generated
//!   program, built and run through `c_backend`, traces and sets the variables by those names.
//!   Before: they were only entries of the command line's watch table.

mod common;
use common::{column, ladderc, run_stimulated};
use ladderc::{AccessDirection, AccessPath, Options, Project};
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
    let lines = common::diagnostic_heads(&out.stderr, strip, true);
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
    assert_eq!(
        column(&trace, "plant.total"),
        [0.0, 0.0, 5.0, 10.0, 15.0, 20.0]
    );
    assert_eq!(
        column(&trace, "%QW0.0.0"),
        [42.0, 42.0, 42.0, 42.0, 43.0, 43.0]
    );
    // one located W0320 per confnode whose code or field bus does not run, nothing else
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("warning[")).collect();
    assert_eq!(warnings.len(), 4, "{stderr}");
    for (file, what) in [
        (
            "modbus_0@modbus/confnode.xml:2:1",
            "confnode `modbus_0` (modbus) does not run",
        ),
        (
            "c_code@c_ext/cfile.xml:10:3",
            "the C code of confnode `c_code` (c_ext) does not run",
        ),
        (
            "py_ext_0@py_ext/pyfile.xml:10:3",
            "the Python code of confnode `py_ext_0` (py_ext) does not run",
        ),
        (
            "mqtt_0@mqtt/confnode.xml:2:1",
            "confnode `mqtt_0` (mqtt) does not run",
        ),
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
    assert!(
        lines.iter().all(|l| l.contains("warning[W0320]")),
        "{lines:?}"
    );
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

fn codesys_v2_files(dir: &Path) -> Vec<PathBuf> {
    [
        "Tank.pou.xml",
        "PLC_PRG.pou.xml",
        "Globals.gvl.xml",
        "Tank_State.dut.xml",
    ]
    .iter()
    .map(|f| dir.join(f))
    .collect()
}

#[test]
fn codesys_v2_object_files_run_together() {
    let dir = common::repo_root().join("tests/tests/fixtures/codesys_v2");
    let files = codesys_v2_files(&dir);
    let files: Vec<&Path> = files.iter().map(PathBuf::as_path).collect();
    let (trace, stderr) = common::run_traced_files(
        &files,
        6,
        "PLC_PRG.cycles,PLC_PRG.t.Level,PLC_PRG.t.Full,PLC_PRG.state",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    // Tank fills by 3 per scan; at 12 (>= Max_Level of the GVL) its action Drain empties it, and
    // PLC_PRG sets the enumeration of the DUT
    assert_eq!(
        column(&trace, "PLC_PRG.t.Level"),
        [3.0, 6.0, 9.0, 0.0, 3.0, 6.0]
    );
    assert_eq!(
        column(&trace, "PLC_PRG.state"),
        [0.0, 0.0, 0.0, 1.0, 1.0, 1.0]
    );
}

#[test]
fn codesys_v2_object_files_keep_their_lines_and_a_graphical_body_is_one_error() {
    let src = common::repo_root().join("tests/tests/fixtures/codesys_v2");
    let dir = tempfile::tempdir().unwrap();
    for f in codesys_v2_files(&src) {
        std::fs::copy(&f, dir.path().join(f.file_name().unwrap())).unwrap();
    }
    let check = |dir: &Path| {
        let out = ladderc()
            .args(["--message-format", "short", "check"])
            .args(codesys_v2_files(dir))
            .output()
            .unwrap();
        let prefix = format!("{}/", dir.display());
        let lines: Vec<String> = String::from_utf8_lossy(&out.stderr)
            .lines()
            .filter(|l| l.contains("error["))
            .map(|l| l.replace(&prefix, ""))
            .map(|l| l.split_once(" (hint").unwrap().0.to_string())
            .collect();
        (out.status.code(), lines)
    };
    // a misspelt name in the body: located in the XML file (line 18, after three tabs and `<![CDATA[`)
    let prg = dir.path().join("PLC_PRG.pou.xml");
    let text = std::fs::read_to_string(&prg).unwrap();
    std::fs::write(
        &prg,
        text.replace("cycles := cycles + 1;", "cycles := cycels + 1;"),
    )
    .unwrap();
    assert_eq!(
        check(dir.path()),
        (
            Some(1),
            vec![
                "PLC_PRG.pou.xml:18:23: error[E1001]: undeclared name `cycels` [POU `PLC_PRG`]"
                    .to_string()
            ]
        )
    );
    // a CFC body (CODESYS's own form, not PLCopen): one E0321 at the element
    let tank = dir.path().join("Tank.pou.xml");
    let bytes = std::fs::read(&tank).unwrap();
    let text = String::from_utf8(bytes).unwrap();
    let text = text
        .replacen("\t<st>\n", "\t<cfc>\n", 1)
        .replacen("\t</st>\n", "\t</cfc>\n", 1);
    std::fs::write(&tank, text).unwrap();
    assert_eq!(
        check(dir.path()),
        (
            Some(1),
            vec!["Tank.pou.xml:20:2: error[E0321]: CODESYS V2.3 object file: the body of `Tank` is <cfc>, which ladderc cannot read in this format (it reads <st> and <il> bodies) [POU `Tank`]".to_string()]
        )
    );
}

#[test]
fn a_plcopen_file_of_one_pou_with_text_declarations_runs() {
    let file = common::repo_root().join("tests/tests/fixtures/plcopen_pou/ramp.cfc");
    let (trace, stderr) = common::run_traced(&file, 3, "ramp.level");
    assert_eq!(column(&trace, "ramp.level"), [2.0, 4.0, 6.0]);
    // the content tells the language (a note), and nothing is ignored silently
    assert!(
        stderr.contains("note[W0302]: read as PLCopen XML"),
        "{stderr}"
    );
    assert!(!stderr.contains("warning["), "{stderr}");
    // an error in the text declaration is located in the file
    let text = std::fs::read_to_string(&file)
        .unwrap()
        .replace("    step : DINT := 2;", "    step : DINT := 2");
    let heads = common::rejected_heads("ramp.xml", &text);
    assert_eq!(
        heads[0],
        "ramp.xml:11:21: error[E0011]: missing `;` after `step : DINT := 2` before `level` [POU `ramp`]"
    );
}

#[test]
fn a_missing_semicolon_in_declarations_is_one_error_where_it_belongs() {
    let last_field = "TYPE r :\nSTRUCT\n    a : INT;\n    b : BOOL\nEND_STRUCT;\nEND_TYPE\n\
                      PROGRAM main\nVAR x : r; END_VAR\nx.a := 1;\nEND_PROGRAM\n";
    assert_eq!(
        common::rejected_heads("last_field.st", last_field),
        ["last_field.st:4:13: error[E0011]: missing `;` after `b : BOOL` before `END_STRUCT`"]
    );
    let between = "PROGRAM main\nVAR\n    a : INT := 3 (* start *)\n    b : BOOL;\nEND_VAR\n\
                   LD a\nST a\nEND_PROGRAM\n";
    assert_eq!(
        common::rejected_heads("between.il", between),
        ["between.il:3:17: error[E0011]: missing `;` after `a : INT := 3` before `b`"]
    );
    let (_, lines) = common::check_text(
        "before_end_var.st",
        "FUNCTION_BLOCK fb\nVAR_INPUT\n    s : STRING := 'x'\nEND_VAR\nEND_FUNCTION_BLOCK\n",
    );
    assert_eq!(
        lines,
        ["before_end_var.st:3:22: error[E0011]: missing `;` after `s : STRING := 'x'` before `END_VAR` \
          (hint: end each declaration with `;` (`s : STRING := 'x';`): IEC 61131-3, CODESYS and \
          TwinCAT require it, also before `END_VAR`)"]
    );
}

const ACCESS_ST: &str = "PROGRAM tank\nVAR\n  inflow : INT;\n  level : INT;\nEND_VAR\n\
  level := level + inflow;\nEND_PROGRAM\n\
CONFIGURATION plant\nVAR_GLOBAL\n  alarm : BOOL;\nEND_VAR\n\
VAR_ACCESS\n  fill : cpu.t1.inflow : INT READ_WRITE;\n  shown : t1.level : INT;\n\
  siren : alarm : BOOL READ_ONLY;\n  pump : cpu.%QX0.1 : BOOL;\nEND_VAR\n\
RESOURCE cpu ON PLC\n  TASK cyc (INTERVAL := T#10ms, PRIORITY := 1);\n  PROGRAM t1 WITH cyc : tank;\n\
END_RESOURCE\nEND_CONFIGURATION\n";

fn access(configuration: &str, name: &str, path: &str, ty: &str, rw: bool) -> AccessPath {
    AccessPath {
        configuration: configuration.to_string(),
        name: name.to_string(),
        path: path.to_string(),
        type_name: ty.to_string(),
        direction: if rw {
            AccessDirection::ReadWrite
        } else {
            AccessDirection::ReadOnly
        },
    }
}

#[test]
fn access_paths_are_in_the_library_api_and_name_the_running_variables() {
    let checked = Project::from_sources([("plant/cell.st", ACCESS_ST)], Options::default())
        .check()
        .expect("checks");
    let expected = vec![
        access("plant", "fill", "cpu.t1.inflow", "INT", true),
        access("plant", "shown", "t1.level", "INT", false),
        access("plant", "siren", "alarm", "BOOL", false),
        access("plant", "pump", "cpu.%QX0.1", "BOOL", false),
    ];
    assert_eq!(checked.access_paths(), expected);
    let lowered = checked.lower().expect("lowers");
    assert_eq!(lowered.access_paths(), expected);
    let generated = lowered.generate().expect("generates");
    assert_eq!(generated.access_paths(), expected);

    // the names are the running program's: set `fill` (READ_WRITE), trace `shown`
    let dir = tempfile::tempdir().unwrap();
    let exe = c_backend::build(generated.program(), dir.path()).expect("the C builds");
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, "cycle,variable,value\n1,fill,4\n").unwrap();
    let out = c_backend::run(
        &exe,
        &c_backend::RunOptions {
            cycles: 3,
            stimulus: Some(stim),
            watch: vec!["shown".into(), "fill".into()],
            ..Default::default()
        },
    )
    .unwrap();
    assert!(out.success(), "{}", out.stderr);
    assert_eq!(column(&out.stdout, "shown"), [0.0, 4.0, 8.0]);
    assert_eq!(column(&out.stdout, "fill"), [0.0, 4.0, 4.0]);

    // PLCopen XML `<accessVars>`: the same values (no direction written is READ_ONLY)
    let xml = std::fs::read_to_string(
        common::repo_root().join("tests/tests/fixtures/unseen/var_access_tc6.xml"),
    )
    .unwrap();
    let generated = Project::from_sources([("tank.xml", xml.as_str())], Options::default())
        .compile()
        .expect("compiles");
    let paths = generated.access_paths();
    let names: Vec<(&str, &str, AccessDirection)> = paths
        .iter()
        .map(|a| (a.name.as_str(), a.path.as_str(), a.direction))
        .collect();
    assert_eq!(
        names,
        [
            ("fill_rate", "cpu.t1.inflow", AccessDirection::ReadWrite),
            ("tank_level", "cpu.t1.level", AccessDirection::ReadOnly),
            ("tank_high", "t1.high", AccessDirection::ReadOnly),
        ]
    );
}

#[test]
fn a_beremiz_folder_in_memory_through_the_library_api() {
    let dir = fixture("mixer");
    let read = |rel: &str| std::fs::read_to_string(dir.join(rel)).unwrap();
    let checked = Project::from_sources([("mem/plc.xml", read("plc.xml"))], Options::default())
        .with_file("mem/beremiz.xml", read("beremiz.xml"))
        .with_file(
            "mem/c_code@c_ext/baseconfnode.xml",
            read("c_code@c_ext/baseconfnode.xml"),
        )
        .with_file("mem/c_code@c_ext/cfile.xml", read("c_code@c_ext/cfile.xml"))
        .with_file(
            "mem/py_ext_0@py_ext/baseconfnode.xml",
            read("py_ext_0@py_ext/baseconfnode.xml"),
        )
        .with_file(
            "mem/py_ext_0@py_ext/pyfile.xml",
            read("py_ext_0@py_ext/pyfile.xml"),
        )
        .with_file(
            "mem/mqtt_0@mqtt/baseconfnode.xml",
            read("mqtt_0@mqtt/baseconfnode.xml"),
        )
        .check()
        .expect("the confnodes' globals are declared");
    let w0320 = checked
        .diagnostics()
        .iter()
        .filter(|d| d.code.0 == "W0320")
        .count();
    // the C code, the Python code and the MQTT client (the Modbus confnode was not given)
    assert_eq!(w0320, 3, "{:?}", checked.diagnostics());
}
