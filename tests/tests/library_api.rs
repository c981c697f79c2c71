//! The library API (`ladderc::Project`) end to end, without the file system: sources, the axes file, the
//! target profile and templates given in memory; diagnostics, the lowered IL, the C files and the report
//! read as values. The C it returns is then built and run (an explicit, separate step) to show it is the
//! program. Files that exist on disk under the same or the default paths are never read, and no stage writes
//! a file.

use ladderc::diagnostics::{code, Severity};
use ladderc::{Options, Project};
use std::path::{Path, PathBuf};

const BLINK: &str = "PROGRAM blink\nVAR\n    lamp : BOOL;\n    n : INT;\nEND_VAR\n    LD lamp\n    STN lamp\n    LD n\n    ADD 1\n    ST n\nEND_PROGRAM\n";

const MOVE: &str = "PROGRAM main\nVAR\n    power : MC_Power;\n    move : MC_MoveAbsolute;\n    powered : BOOL;\n    done : BOOL;\nEND_VAR\n    CAL power(Axis := X1, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE, Status => powered)\n    CAL move(Axis := X1, Execute := powered, Position := 100.0, Velocity := 50.0, Acceleration := 200.0,\n             Deceleration := 200.0, Jerk := 2000.0, Done => done)\nEND_PROGRAM\n";

const AXES: &str = r#"{ "cycle_ms": 2, "axes": [ { "name": "X1", "velocity": 200, "acceleration": 1000, "deceleration": 1000, "jerk": 10000 } ] }"#;

/// Every file under `dir` (relative path, bytes), sorted.
fn tree(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                let bytes = std::fs::read(&p).unwrap();
                out.push((p.strip_prefix(dir).unwrap().to_path_buf(), bytes));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn il_in_memory_to_c_that_builds_and_runs() {
    // The path exists nowhere: it names the source and gives its language.
    let checked = Project::from_sources([("no/such/dir/blink.il", BLINK)], Options::default())
        .check()
        .expect("blink checks");
    assert!(
        checked.diagnostics().is_empty(),
        "{:?}",
        checked.diagnostics()
    );
    assert_eq!(checked.units().len(), 1);
    let lowered = checked.lower().expect("blink lowers");
    let il = lowered.il();
    assert!(
        il.contains("PROGRAM blink") && il.contains("STN lamp"),
        "{il}"
    );
    let generated = lowered.generate().expect("blink generates C");
    let c_files: Vec<&str> = generated.c_files().map(|(n, _)| n).collect();
    assert!(c_files.contains(&"program.c"), "{c_files:?}");
    assert!(generated.headers().any(|(n, _)| n == "ladderc_config.h"));
    assert!(!generated.uses_motion());
    assert_eq!(generated.cycle_ms(), 10.0);
    let report: serde_json::Value = serde_json::from_str(&generated.report()).unwrap();
    assert_eq!(report["blocks"], serde_json::json!([]));
    assert!(report["code_size"]["executable_bytes"].is_null());

    // Building and running are explicit steps of the caller.
    let dir = tempfile::tempdir().unwrap();
    let exe = c_backend::build(generated.program(), dir.path()).expect("the C builds");
    let out = c_backend::run(
        &exe,
        &c_backend::RunOptions {
            cycles: 4,
            watch: vec!["blink.lamp".into(), "blink.n".into()],
            ..Default::default()
        },
    )
    .unwrap();
    assert!(out.success(), "{}", out.stderr);
    let rows: Vec<Vec<&str>> = out
        .stdout
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 4, "{}", out.stdout);
    // lamp toggles every scan, n counts the scans
    for (k, row) in rows.iter().enumerate() {
        let lamp = if k % 2 == 0 { "1" } else { "0" };
        assert_eq!(&row[2..], &[lamp, &(k + 1).to_string()], "{}", out.stdout);
    }
}

#[test]
fn an_undeclared_variable_is_a_diagnostic_value_at_its_line() {
    let src =
        "PROGRAM p\nVAR\n    a : INT;\nEND_VAR\n    LD a\n    ADD ghost\n    ST a\nEND_PROGRAM\n";
    let failed = Project::from_sources([("p.il", src)], Options::default())
        .compile()
        .expect_err("ghost is undeclared");
    let errors: Vec<_> = failed.errors().collect();
    assert_eq!(errors.len(), 1, "{}", failed);
    assert_eq!(errors[0].code, code::E1001);
    assert!(errors[0].message.contains("ghost"), "{}", errors[0].message);
    assert_eq!(failed.line_col(errors[0]), Some((6, 9)));
    let short = failed.to_string();
    assert!(short.starts_with("p.il:6:9: error[E1001]"), "{short}");
    // The README's example.
    let failed = Project::from_sources(
        [("p.il", "PROGRAM p\n    LD ghost\nEND_PROGRAM\n")],
        Options::default(),
    )
    .compile()
    .unwrap_err();
    let e = failed.errors().next().unwrap();
    assert_eq!((e.code.0, failed.line_col(e)), ("E1001", Some((2, 8))));
    // The stage stops: no lowered program or C comes out of a program with errors.
    let parsed = Project::from_sources([("p.il", src)], Options::default())
        .parse()
        .expect("it parses");
    assert!(parsed.check().is_err());
}

#[test]
fn motion_with_the_axes_file_in_memory() {
    let generated = Project::from_sources([("cell/main.il", MOVE)], Options::default())
        .with_file("cell/main.axes.json", AXES)
        .compile()
        .unwrap_or_else(|f| panic!("{f}"));
    assert!(generated.uses_motion());
    assert_eq!(generated.cycle_ms(), 2.0);
    assert!(generated.headers().any(|(n, _)| n == "motion_lib.h"));
    let report: serde_json::Value = serde_json::from_str(&generated.report()).unwrap();
    let blocks: Vec<&str> = report["blocks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b["block"].as_str().unwrap())
        .collect();
    assert_eq!(blocks, ["MC_MoveAbsolute", "MC_Power"]);
    assert!(report["blocks"][0]["c_bytes"].as_u64().unwrap() > 0);

    // Without its axes file, X1 is undeclared.
    let failed = Project::from_sources([("cell/main.il", MOVE)], Options::default())
        .compile()
        .expect_err("X1 needs the axes file");
    assert!(failed.errors().all(|d| d.code == code::E1001), "{failed}");
}

#[test]
fn the_profile_and_templates_are_read_from_memory() {
    let opts = Options {
        profile: Some("target.json".into()),
        ..Default::default()
    };
    let bad = Project::from_sources([("blink.il", BLINK)], opts.clone())
        .with_file("target.json", "{ not json")
        .compile()
        .expect_err("a bad profile");
    assert_eq!(bad.errors().next().unwrap().code, code::E2003, "{bad}");
    // A profile that is named but not given is an I/O error, whatever the disk holds.
    let missing = Project::from_sources([("blink.il", BLINK)], opts)
        .compile()
        .expect_err("no profile given");
    let e = missing.errors().next().unwrap();
    assert_eq!(e.code, code::E9001);
    assert!(e.message.contains("not given in memory"), "{}", e.message);

    // A template of the templates folder given in memory is loaded and checked (here: its schema).
    let opts = Options {
        templates: Some("tpl".into()),
        ..Default::default()
    };
    let failed = Project::from_sources([("blink.il", BLINK)], opts)
        .with_file("tpl/MC_Bad.xml", "<template")
        .compile()
        .expect_err("a broken template");
    assert!(
        failed
            .diagnostics
            .iter()
            .any(|d| d.severity == Severity::Error
                && d.span
                    .is_some_and(|s| failed.sources.get(s.file).name == "tpl/MC_Bad.xml")),
        "{failed}"
    );
}

/// Files on disk under the paths the pipeline would look at are not read, and nothing is written: the current
/// directory holds decoys (a source of the same name, the default axes file) and stays as it was.
#[test]
fn the_api_neither_reads_nor_writes_the_file_system() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    std::fs::write(root.join("main.il"), "this is not IL and must not be read").unwrap();
    std::fs::write(root.join("main.axes.json"), AXES).unwrap();
    std::fs::write(root.join("profile.json"), "{}").unwrap();
    let before = tree(root);
    let main = root.join("main.il");

    // The in-memory text wins over the file of the same path.
    let generated = Project::from_sources([(main.clone(), BLINK)], Options::default())
        .compile()
        .unwrap_or_else(|f| panic!("{f}"));
    assert!(generated.c_file("program.c").unwrap().contains("blink"));
    // The default axes file beside the input exists on disk, but is not read: X1 stays undeclared.
    let failed = Project::from_sources([(main.clone(), MOVE)], Options::default())
        .compile()
        .expect_err("the disk's axes file is not read");
    assert!(failed.errors().any(|d| d.code == code::E1001), "{failed}");
    // An explicit axes path on disk is not read either.
    let opts = Options {
        axes: Some(root.join("main.axes.json")),
        ..Default::default()
    };
    let failed = Project::from_sources([(main.clone(), MOVE)], opts)
        .compile()
        .expect_err("the disk's axes file is not read");
    let e = failed.errors().next().unwrap();
    assert_eq!(e.code, code::E9001, "{failed}");
    assert!(e.message.contains("not given in memory"), "{failed}");
    // Standard input is not read.
    let opts = Options {
        lang: Some(ladderc::Lang::Il),
        ..Default::default()
    };
    let failed = Project::from_paths(["-"], opts)
        .with_disk_fallback(false)
        .parse()
        .expect_err("standard input is not read");
    assert_eq!(failed.errors().next().unwrap().code, code::E9001);
    // The report without measurements and the PMAC program are values too.
    let mut motion = Project::from_sources([(main.clone(), MOVE)], Options::default())
        .with_file(root.join("main.axes.json"), AXES)
        .compile()
        .unwrap_or_else(|f| panic!("{f}"));
    let _ = motion.report();
    let pmac = motion
        .pmac_program(pmac_backend::model::Dialect::Turbo)
        .expect("a PMAC program");
    assert!(pmac.contains("X"), "{pmac}");

    assert_eq!(tree(root), before, "the API wrote or changed a file");

    // With the disk fallback asked for, the file beside the input is the axes file.
    let generated = Project::from_sources([(main, MOVE)], Options::default())
        .with_disk_fallback(true)
        .compile()
        .unwrap_or_else(|f| panic!("{f}"));
    assert_eq!(generated.cycle_ms(), 2.0);
    assert_eq!(tree(root), before);
}
