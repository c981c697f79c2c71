//! Command-line conventions (issue #11.5, #13.7): exit 2 for every I/O error, a closed standard output ends
//! quietly with the requested files written, `check` takes the project options and runs every check of
//! `build`, usage errors as JSON, help text and exit codes in `--help`, and the README's synopsis.

mod common;

use common::{assert_ok, ladderc, write_file};
use std::path::{Path, PathBuf};
use std::process::{Output, Stdio};

fn root() -> PathBuf {
    common::repo_root()
}

const COUNTER: &str =
    "PROGRAM main\nVAR n : INT; END_VAR\n    LD n\n    ADD 1\n    ST n\nEND_PROGRAM\n";

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn every_io_error_exits_2() {
    let dir = tempfile::tempdir().unwrap();
    let prog = write_file(dir.path(), "prog.il", COUNTER);
    let prog = prog.to_str().unwrap();
    let missing = dir.path().join("missing");
    let missing = missing.to_str().unwrap();
    let file_as_dir = write_file(dir.path(), "plain", "x");
    let under_file = format!("{}/out.csv", file_as_dir.display());
    let motion = root().join("examples/motion/move.il");
    let motion = motion.to_str().unwrap();
    let cases: Vec<Vec<&str>> = vec![
        vec!["check", missing],
        vec!["build", missing, "-o", "unused"],
        vec!["build", prog, "--emit", "il", "--axes", missing],
        vec!["check", prog, "--profile", missing],
        vec!["check", prog, "--templates", missing],
        vec!["run", prog, "--stimulus", missing],
        vec!["run", missing],
        vec!["run", prog, "--trace", &under_file],
        vec!["build", motion, "--pmac", &under_file, "-o", "unused"],
        vec!["run", motion, "--cycles", "5", "--plot", &under_file],
        vec!["run", motion, "--cycles", "5", "--pmac-pvt", &under_file],
    ];
    for args in cases {
        let out = ladderc()
            .current_dir(dir.path())
            .args(&args)
            .output()
            .unwrap();
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            ["E9001", "E9002", "E7005"]
                .iter()
                .any(|c| err.contains(&format!("error[{c}]"))),
            "{args:?}: {err}"
        );
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
    assert!(!dir.path().join("unused").exists());
}

/// Runs `args` with standard output closed before the program writes to it.
fn with_closed_stdout(args: &[&str], cwd: &Path) -> Output {
    let mut child = ladderc()
        .args(args)
        .current_dir(cwd)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    child.wait_with_output().unwrap()
}

#[test]
fn a_closed_pipe_ends_quietly_and_the_requested_files_are_written() {
    let dir = tempfile::tempdir().unwrap();
    let motion = root().join("examples/motion/move.il");
    let svg = dir.path().join("move.svg");
    let pmc = dir.path().join("move.pmc");
    // The trace goes to standard output (no --trace): 2200 rows, far more than a pipe holds.
    let out = with_closed_stdout(
        &[
            "run",
            motion.to_str().unwrap(),
            "--cycles",
            "2200",
            "--plot",
            svg.to_str().unwrap(),
            "--pmac",
            pmc.to_str().unwrap(),
        ],
        dir.path(),
    );
    assert_ok(&out);
    let err = stderr(&out);
    assert!(!err.contains("panicked") && !err.contains("error"), "{err}");
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
    assert!(!std::fs::read_to_string(&pmc).unwrap().is_empty());

    for args in [
        vec!["explain"],
        vec!["explain", "E1001"],
        vec!["build", motion.to_str().unwrap(), "--emit", "il"],
    ] {
        let out = with_closed_stdout(&args, dir.path());
        assert_ok(&out);
        assert_eq!(stderr(&out), "", "{args:?}");
    }
}

#[test]
fn a_pipe_into_head_prints_no_panic() {
    let counter = root().join("examples/counter/counter.il");
    let script = format!(
        "{} run {} --cycles 100000 | head -1; exit ${{PIPESTATUS[0]}}",
        env!("CARGO_BIN_EXE_ladderc-e2e"),
        counter.display()
    );
    let out = std::process::Command::new("bash")
        .args(["-c", &script])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert_eq!(String::from_utf8_lossy(&out.stdout).lines().count(), 1);
    assert!(!stderr(&out).contains("panicked"), "{}", stderr(&out));
}

#[test]
fn check_takes_the_axes_file_and_says_where_it_looked_for_one() {
    let dir = tempfile::tempdir().unwrap();
    let motion = root().join("examples/motion");
    let prog = write_file(
        dir.path(),
        "prog.il",
        &std::fs::read_to_string(motion.join("move.il")).unwrap(),
    );
    // No axes file beside the copy: X1 is undeclared, and the hint names the file looked for.
    let out = ladderc()
        .args(["--message-format", "json", "check"])
        .arg(&prog)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let first: serde_json::Value =
        serde_json::from_str(stderr(&out).lines().next().unwrap()).unwrap();
    assert_eq!(first["code"], "E1001");
    assert!(first["message"].as_str().unwrap().contains("X1"));
    let hint = first["hint"].as_str().unwrap();
    assert!(
        hint.contains("axes file") && hint.contains("prog.axes.json") && hint.contains("--axes"),
        "{hint}"
    );
    // With --axes it checks.
    let out = ladderc()
        .arg("check")
        .arg(&prog)
        .arg("--axes")
        .arg(motion.join("move.axes.json"))
        .output()
        .unwrap();
    assert_ok(&out);
}

#[test]
fn check_rejects_what_build_rejects() {
    let dir = tempfile::tempdir().unwrap();
    // A DINT at a hierarchical word address: it parses and checks, but the C backend refuses it
    // (E2002: the address's slot holds 2 bytes).
    let prog = write_file(
        dir.path(),
        "prog.il",
        "PROGRAM main\nVAR q AT %QW0.0.0.0 : DINT; END_VAR\n    LD 1\n    ST q\nEND_PROGRAM\n",
    );
    let build = ladderc()
        .arg("build")
        .arg(&prog)
        .arg("-o")
        .arg(dir.path().join("out"))
        .output()
        .unwrap();
    assert_eq!(build.status.code(), Some(1));
    assert!(stderr(&build).contains("E2002"), "{}", stderr(&build));
    let check = ladderc().arg("check").arg(&prog).output().unwrap();
    assert_eq!(check.status.code(), Some(1));
    assert!(stderr(&check).contains("E2002"), "{}", stderr(&check));
    // check writes nothing.
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, vec![std::ffi::OsString::from("prog.il")]);
    // --profile changes what check accepts, as it does for build: a profile without %Q bytes.
    let profile: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(root().join("crates/c-backend/profiles/default.json")).unwrap(),
    )
    .unwrap();
    let mut small = profile.clone();
    small["output_bytes"] = 1.into();
    let small = write_file(dir.path(), "small.json", &small.to_string());
    let prog2 = write_file(
        dir.path(),
        "wide.il",
        "PROGRAM main\nVAR q AT %QW4 : INT; END_VAR\n    LD 1\n    ST q\nEND_PROGRAM\n",
    );
    assert_ok(&ladderc().arg("check").arg(&prog2).output().unwrap());
    let out = ladderc()
        .arg("check")
        .arg(&prog2)
        .arg("--profile")
        .arg(&small)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(stderr(&out).contains("E2001"), "{}", stderr(&out));
}

#[test]
fn usage_errors_are_json_diagnostics_under_json_message_format() {
    for args in [
        vec!["--message-format", "json", "run", "x.il", "--cycels", "3"],
        vec!["--message-format=json", "check"],
        vec![
            "run",
            "x.il",
            "--message-format",
            "json",
            "--cycles",
            "many",
        ],
        vec!["--message-format", "json", "frobnicate"],
    ] {
        let out = ladderc().args(&args).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = stderr(&out);
        let lines: Vec<serde_json::Value> = err
            .lines()
            .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}")))
            .collect();
        assert_eq!(lines.len(), 2, "{err}");
        assert_eq!(lines[0]["code"], "E9200", "{err}");
        assert_eq!(lines[0]["severity"], "error");
        assert!(!lines[0]["message"].as_str().unwrap().is_empty());
        assert_eq!(lines[1]["kind"], "summary");
        assert_eq!(lines[1]["errors"], 1);
    }
    // Without JSON it is clap's text; help is not an error.
    let out = ladderc().args(["run", "--cycels"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("--cycels"));
    let out = ladderc()
        .args(["--message-format", "json", "--help"])
        .output()
        .unwrap();
    assert_ok(&out);
}

#[test]
fn help_has_the_exit_codes_and_every_argument_has_help_text() {
    let out = ladderc().arg("--help").output().unwrap();
    assert_ok(&out);
    let help = String::from_utf8_lossy(&out.stdout);
    assert!(help.contains("Exit codes:"), "{help}");
    assert!(help.contains("2  usage error"), "{help}");

    use clap::CommandFactory;
    fn walk(cmd: &clap::Command, path: &str, missing: &mut Vec<String>) {
        for a in cmd.get_arguments() {
            let id = a.get_id().as_str();
            if matches!(id, "help" | "version") {
                continue;
            }
            if a.get_help().is_none() {
                missing.push(format!("{path} {id}"));
            }
            // Flags (`--sanitize`) have the values true/false, which need no help.
            let values = if a.get_action().takes_values() {
                a.get_possible_values()
            } else {
                Vec::new()
            };
            for v in values {
                if !v.is_hide_set() && v.get_help().is_none() {
                    missing.push(format!("{path} {id}={}", v.get_name()));
                }
            }
        }
        for s in cmd.get_subcommands() {
            if s.get_name() == "help" {
                continue;
            }
            if s.get_about().is_none() {
                missing.push(format!("{path} {}", s.get_name()));
            }
            walk(s, &format!("{path} {}", s.get_name()), missing);
        }
    }
    let mut missing = Vec::new();
    walk(&ladderc::cli::Cli::command(), "ladderc", &mut missing);
    assert!(missing.is_empty(), "without help text: {missing:?}");
}

#[test]
fn the_readme_synopsis_lists_every_option() {
    use clap::CommandFactory;
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let start = readme.find("## Command line").unwrap();
    let section = &readme[start..];
    let section = &section[..section[3..].find("\n## ").map_or(section.len(), |e| e + 3)];
    fn walk(cmd: &clap::Command, path: &str, out: &mut Vec<(String, String)>) {
        for a in cmd.get_arguments() {
            if let Some(long) = a.get_long() {
                if !matches!(long, "help" | "version") {
                    out.push((path.to_string(), format!("--{long}")));
                }
            }
        }
        for s in cmd.get_subcommands() {
            walk(s, &format!("{path} {}", s.get_name()), out);
        }
    }
    let mut options = Vec::new();
    walk(&ladderc::cli::Cli::command(), "ladderc", &mut options);
    let absent: Vec<_> = options
        .iter()
        .filter(|(_, o)| {
            !section.match_indices(o.as_str()).any(|(i, _)| {
                !section[i + o.len()..].starts_with(|c: char| c == '-' || c.is_ascii_alphanumeric())
            })
        })
        .collect();
    assert!(
        absent.is_empty(),
        "not in the README's Command line section: {absent:?}"
    );
    for sub in [
        "check",
        "build",
        "run",
        "explain",
        "motion plan",
        "drive build",
        "drive run",
        "drive debug",
    ] {
        assert!(section.contains(&format!("ladderc {sub}")), "{sub}");
    }
}
