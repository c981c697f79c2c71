//! The scan harness of a built program: options, stimulus errors, listing, default watch list, Makefile.

mod support;
use std::process::Command;
use support::*;

const SRC: &str = "PROGRAM main
VAR
  count : INT;
  flag : BOOL;
  t : TIME;
  r : REAL;
  s : STRING[8];
END_VAR
  LD count
  ADD 1
  ST count
END_PROGRAM
";

fn exec(b: &Built, args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(&b.exe)
        .args(args)
        .current_dir(b.dir.path())
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn bad_stimulus_rows_stop_with_file_line_and_status_2() {
    let b = build_src(SRC);
    let cases = [
        (
            "0,main.count,40000\n",
            "s.csv:1: expected an integer in the range of INT: `40000`",
        ),
        (
            "# comment\n\n0,main.nope,1\n",
            "s.csv:3: unknown variable `main.nope`",
        ),
        (
            "x,main.count,1\n",
            "s.csv:1: the cycle `x` is not a non-negative integer",
        ),
        (
            "0,main.flag,yes\n",
            "s.csv:1: expected TRUE, FALSE, 1 or 0 for a BOOL: `yes`",
        ),
        (
            "0,main.t,150\n",
            "s.csv:1: expected a duration like T#1s500ms: `150`",
        ),
        (
            "0,main.r,1.5.2\n",
            "s.csv:1: expected a number for a REAL: `1.5.2`",
        ),
        ("0,main.count\n", "s.csv:1: expected `cycle,variable,value`"),
        (
            "0,%IX999.0,1\n",
            "s.csv:1: address outside the area's size in the target profile: `%IX999.0`",
        ),
    ];
    for (stim, message) in cases {
        std::fs::write(b.dir.path().join("s.csv"), stim).unwrap();
        let (status, stdout, stderr) = exec(&b, &["--cycles", "2", "--stimulus", "s.csv"]);
        assert_eq!(status, Some(2), "{stim:?}: {stderr}");
        assert!(stderr.contains(message), "{stim:?}: {stderr}");
        assert!(stdout.is_empty(), "no trace after a bad stimulus");
    }
}

#[test]
fn good_stimulus_with_header_comments_crlf_and_unordered_rows() {
    let b = build_src(SRC);
    std::fs::write(
        b.dir.path().join("s.csv"),
        "cycle,variable,value\r\n# set late first\r\n2,main.count,100\r\n0,MAIN.COUNT,16#10\r\n1,main.s,'a,b'\r\n",
    )
    .unwrap();
    let (status, stdout, stderr) = exec(
        &b,
        &[
            "--cycles",
            "3",
            "--stimulus",
            "s.csv",
            "--watch",
            "main.count, main.s",
        ],
    );
    assert_eq!(status, Some(0), "{stderr}");
    assert_eq!(
        stdout,
        "cycle,time_ms,main.count,main.s\n0,0,17,\"\"\n1,10,18,\"a,b\"\n2,20,101,\"a,b\"\n"
    );
}

#[test]
fn list_and_default_watch_show_every_variable() {
    let b = build_src(SRC);
    let (status, stdout, _) = exec(&b, &["--list"]);
    assert_eq!(status, Some(0));
    assert_eq!(
        stdout,
        "main.count : INT\nmain.flag : BOOL\nmain.t : TIME\nmain.r : REAL\nmain.s : STRING\n"
    );
    let (status, stdout, _) = exec(&b, &["--cycles", "1"]);
    assert_eq!(status, Some(0));
    assert_eq!(
        stdout,
        "cycle,time_ms,main.count,main.flag,main.t,main.r,main.s\n0,0,1,0,T#0ms,0,\"\"\n"
    );
}

#[test]
fn bad_options_are_usage_errors() {
    let b = build_src(SRC);
    for args in [
        &["--cycles", "-1"][..],
        &["--cycle-ms", "0"],
        &["--cycle-ms", "abc"],
        &["--bogus", "1"],
        &["--watch", "nope"],
        &["--cycles"],
        &["--stimulus", "/nonexistent/file.csv"],
    ] {
        let (status, _, stderr) = exec(&b, args);
        assert_eq!(status, Some(2), "{args:?}");
        assert!(!stderr.is_empty(), "{args:?}");
    }
}

#[test]
fn the_makefile_builds_the_same_program() {
    if Command::new("make").arg("--version").output().is_err() {
        eprintln!("make not installed: skipped");
        return;
    }
    let (units, model, map) = frontend(SRC);
    let p = generate_with(
        &units,
        &model,
        &map,
        &Default::default(),
        &Default::default(),
    );
    let dir = tempfile::tempdir().unwrap();
    c_backend::toolchain::write_files(&p, dir.path()).unwrap();
    let out = Command::new("make")
        .arg("CFLAGS=-O2 -Wall -Wextra -Werror")
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let run = Command::new(dir.path().join("program"))
        .args(["--cycles", "2", "--watch", "main.count"])
        .output()
        .unwrap();
    assert_eq!(
        String::from_utf8_lossy(&run.stdout),
        "cycle,time_ms,main.count\n0,0,1\n1,10,2\n"
    );
}

#[test]
fn the_pipeline_builds_a_bare_il_file_as_program_main() {
    let mut map = diagnostics::SourceMap::new();
    let mut diags = diagnostics::Diagnostics::new();
    let dir = tempfile::tempdir().unwrap();
    let inputs = vec![(
        "bare.il".to_string(),
        "VAR\n  count : INT;\nEND_VAR\n  LD count\n  ADD 2\n  ST count\n".to_string(),
    )];
    let exe = c_backend::build_il(
        &mut map,
        &inputs,
        &Default::default(),
        &Default::default(),
        dir.path(),
        &strict(),
        &mut diags,
    )
    .unwrap()
    .expect("builds");
    assert!(!diags.has_errors());
    let out = c_backend::run(
        &exe,
        &c_backend::RunOptions {
            cycles: 2,
            watch: vec!["main.count".into()],
            ..Default::default()
        },
    )
    .unwrap();
    assert_eq!(out.stdout, "cycle,time_ms,main.count\n0,0,2\n1,10,4\n");
    // errors stop the pipeline before any C is written
    let mut diags = diagnostics::Diagnostics::new();
    let bad = vec![(
        "bad.il".to_string(),
        "PROGRAM p\n  LD nope\nEND_PROGRAM\n".to_string(),
    )];
    let r = c_backend::build_il(
        &mut map,
        &bad,
        &Default::default(),
        &Default::default(),
        &dir.path().join("bad"),
        &strict(),
        &mut diags,
    )
    .unwrap();
    assert!(r.is_none() && diags.has_errors());
    assert!(!dir.path().join("bad").exists());
}

#[test]
fn a_program_without_variables_or_programs_still_builds_and_runs() {
    let b = build_src("FUNCTION_BLOCK unused\nVAR_INPUT\n  x : BOOL;\nEND_VAR\nVAR_OUTPUT\n  y : BOOL;\nEND_VAR\n  LD x\n  ST y\nEND_FUNCTION_BLOCK\n");
    let (status, stdout, _) = exec(&b, &["--cycles", "2", "--watch", "%QX0.0"]);
    assert_eq!(status, Some(0));
    assert_eq!(stdout, "cycle,time_ms,%QX0.0\n0,0,0\n1,10,0\n");
    let (_, list, _) = exec(&b, &["--list"]);
    assert_eq!(list, "");
}
