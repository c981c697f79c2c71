//! What `build -o DIR` does to the user's folder (manifest, no deletion, no file replaced by a folder,
//! `-o .`), the motion library ladderc carries (no environment variable, no source tree), depfiles driven
//! through GNU make, and byte-identical outputs from different folders.

mod common;
use common::{assert_ok, ladderc};

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const MOVE: &str = "PROGRAM main
VAR
    power : MC_Power;
    move : MC_MoveAbsolute;
    powered : BOOL;
    at_100 : BOOL;
END_VAR
    CAL power(Axis := X1, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE, Status => powered)
    CAL move(Axis := X1, Execute := powered, Position := 100.0, Velocity := 50.0, Acceleration := 200.0,
             Deceleration := 200.0, Jerk := 2000.0, Done => at_100)
END_PROGRAM
";

const AXES: &str = r#"{ "cycle_ms": 10, "axes": [ { "name": "X1", "unit": "mm", "velocity": 100,
  "acceleration": 500, "deceleration": 500 } ] }
"#;

/// A folder with `move.il` and `move.axes.json`.
fn project() -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("move.il");
    std::fs::write(&src, MOVE).unwrap();
    std::fs::write(dir.path().join("move.axes.json"), AXES).unwrap();
    (dir, src)
}

/// `ladderc` with every `LADDERC_*` variable removed, run in `cwd`.
fn clean_ladderc(cwd: &Path) -> Command {
    let mut c = ladderc();
    for (k, _) in std::env::vars_os() {
        if k.to_string_lossy().starts_with("LADDERC_") {
            c.env_remove(k);
        }
    }
    c.current_dir(cwd);
    c
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Every file under `dir` (relative path -> bytes), sorted.
fn tree(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                let rel = p.strip_prefix(dir).unwrap().display().to_string();
                out.push((rel, std::fs::read(&p).unwrap()));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn the_users_own_files_stay_unchanged_and_rebuilding_into_the_same_folder_works() {
    let (dir, src) = project();
    let out = dir.path().join("fwproj");
    std::fs::create_dir(&out).unwrap();
    let user = b"int user_main(void) { return 42; }\n";
    std::fs::write(out.join("main_fw.c"), user).unwrap();
    for _ in 0..2 {
        let o = clean_ladderc(dir.path())
            .arg("build")
            .arg(&src)
            .arg("-o")
            .arg(&out)
            .output()
            .unwrap();
        assert_ok(&o);
        assert_eq!(std::fs::read(out.join("main_fw.c")).unwrap(), user);
        assert!(out.join("program.c").is_file() && out.join(".ladderc-manifest").is_file());
    }
    // the manifest lists what ladderc wrote, with its SHA-256, and not the user's file
    let manifest = std::fs::read_to_string(out.join(".ladderc-manifest")).unwrap();
    assert!(!manifest.contains("main_fw.c"), "{manifest}");
    let program_c = std::fs::read(out.join("program.c")).unwrap();
    assert!(manifest.contains(&format!(
        "{}  program.c\n",
        ladderc::output::sha256_hex(&program_c)
    )));
    // a file the user changed since is refused, listed, and nothing is written
    std::fs::write(out.join("Makefile"), "# mine now\n").unwrap();
    let before = tree(&out);
    let o = clean_ladderc(dir.path())
        .args(["--message-format", "short", "build"])
        .arg(&src)
        .arg("-o")
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("E9101") && stderr(&o).contains("Makefile"));
    assert_eq!(tree(&out), before);
}

#[test]
fn an_output_path_that_is_a_regular_file_is_refused_and_left_alone() {
    let (dir, src) = project();
    let out = dir.path().join("fwproj");
    std::fs::write(&out, "my notes\n").unwrap();
    let o = clean_ladderc(dir.path())
        .arg("build")
        .arg(&src)
        .arg("-o")
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("E9100"), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "my notes\n");
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(names.len(), 3, "no staging files are left");
}

#[test]
fn build_into_the_current_folder_then_make_and_run_with_the_carried_library() {
    let (dir, _) = project();
    let o = clean_ladderc(dir.path())
        .args(["build", "move.il", "-o", "."])
        .output()
        .unwrap();
    assert_ok(&o);
    for f in [
        "program.c",
        "Makefile",
        "libmotion_lib.a",
        "motion_lib.h",
        "move.il",
    ] {
        assert!(dir.path().join(f).is_file(), "{f}");
    }
    assert_eq!(
        std::fs::read_to_string(dir.path().join("move.il")).unwrap(),
        MOVE
    );
    // the project links the release library on the host with its own Makefile
    let make = Command::new("make")
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(make.status.success(), "{}", stderr(&make));
    let exe = dir.path().join("program");
    let size = std::fs::metadata(&exe).unwrap().len();
    // stripped, unused sections dropped (a debug, unstripped library gives several MB)
    assert!(size < 1_000_000, "executable of {size} bytes");
    let run = Command::new(&exe)
        .args(["--cycles", "300", "--watch", "main.at_100,axis.X1.position"])
        .output()
        .unwrap();
    assert!(run.status.success(), "{}", stderr(&run));
    let last = String::from_utf8(run.stdout).unwrap();
    assert!(last.lines().last().unwrap().ends_with(",1,100"), "{last}");
    // rebuilding into `.` replaces only ladderc's files (the executable `make` wrote is not touched)
    let o = clean_ladderc(dir.path())
        .args(["build", "move.il", "-o", "."])
        .output()
        .unwrap();
    assert_ok(&o);
    assert_eq!(std::fs::metadata(&exe).unwrap().len(), size);
}

#[test]
fn run_links_the_carried_library_without_environment_from_another_folder() {
    let (dir, _) = project();
    let o = clean_ladderc(dir.path())
        .args([
            "run",
            "move.il",
            "--cycles",
            "300",
            "--watch",
            "main.at_100,axis.X1.position",
        ])
        .output()
        .unwrap();
    assert_ok(&o);
    let trace = String::from_utf8(o.stdout).unwrap();
    assert!(trace.lines().last().unwrap().ends_with(",1,100"), "{trace}");
}

/// `make` in `dir`: whether it ran the build recipe (its output names ladderc's command).
fn make_rebuilt(dir: &Path) -> bool {
    let o = Command::new("make").current_dir(dir).output().unwrap();
    assert!(
        o.status.success(),
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        stderr(&o)
    );
    String::from_utf8_lossy(&o.stdout).contains("--depfile")
}

#[test]
fn make_rebuilds_after_a_change_to_each_kind_of_input_and_not_otherwise() {
    let (dir, _) = project();
    let root = common::repo_root();
    std::fs::copy(
        root.join("crates/c-backend/profiles/default.json"),
        dir.path().join("my profile.json"),
    )
    .unwrap();
    let tpl = dir.path().join("tpl");
    std::fs::create_dir(&tpl).unwrap();
    std::fs::copy(
        root.join("templates/MC_MoveAbsolute.xml"),
        tpl.join("MC_MoveAbsolute.xml"),
    )
    .unwrap();
    std::fs::rename(
        dir.path().join("move.axes.json"),
        dir.path().join("axes.json"),
    )
    .unwrap();
    let exe = PathBuf::from(env!("CARGO_BIN_EXE_ladderc-e2e"));
    std::fs::write(
        dir.path().join("Makefile"),
        format!(
            "proj/program.c:\n\t{} build move.il --axes axes.json --profile 'my profile.json' \
             --templates tpl -o proj --depfile proj.d\n\n-include proj.d\n",
            exe.display()
        ),
    )
    .unwrap();
    assert!(make_rebuilt(dir.path()), "first build");
    let dep = std::fs::read_to_string(dir.path().join("proj.d")).unwrap();
    for input in [
        "move.il",
        "axes.json",
        "my\\ profile.json",
        "tpl/MC_MoveAbsolute.xml",
    ] {
        assert!(dep.contains(input), "{input} in {dep}");
    }
    assert!(!make_rebuilt(dir.path()), "up to date");
    for input in [
        "move.il",
        "axes.json",
        "my profile.json",
        "tpl/MC_MoveAbsolute.xml",
    ] {
        let f = std::fs::File::options()
            .append(true)
            .open(dir.path().join(input))
            .unwrap();
        f.set_modified(std::time::SystemTime::now()).unwrap();
        drop(f);
        assert!(make_rebuilt(dir.path()), "after touching {input}");
        assert!(!make_rebuilt(dir.path()), "up to date after {input}");
    }
}

#[test]
fn identical_inputs_give_byte_identical_outputs_from_different_folders() {
    let a = tempfile::tempdir().unwrap();
    let b = tempfile::tempdir().unwrap();
    let b_deep = b.path().join("a longer/path");
    let mut outputs = Vec::new();
    for (root, absolute) in [(a.path().to_path_buf(), false), (b_deep, true)] {
        std::fs::create_dir_all(&root).unwrap();
        std::fs::write(root.join("move.il"), MOVE).unwrap();
        std::fs::write(root.join("move.axes.json"), AXES).unwrap();
        // one build names its input relative to the folder, the other by its absolute path
        let input = if absolute {
            root.join("move.il")
        } else {
            PathBuf::from("move.il")
        };
        let o = clean_ladderc(&root)
            .args(["build", "--report", "json", "-o", "out"])
            .arg(&input)
            .output()
            .unwrap();
        assert_ok(&o);
        outputs.push((tree(&root.join("out")), o.stdout));
    }
    let (ta, ra) = &outputs[0];
    let (tb, rb) = &outputs[1];
    assert_eq!(
        ta.iter().map(|(p, _)| p).collect::<Vec<_>>(),
        tb.iter().map(|(p, _)| p).collect::<Vec<_>>()
    );
    for ((p, x), (_, y)) in ta.iter().zip(tb) {
        assert!(x == y, "{p} differs between the two folders");
        let text = String::from_utf8_lossy(x);
        for root in [a.path(), b.path()] {
            assert!(
                !text.contains(&*root.to_string_lossy()),
                "{p} names the folder it was built in"
            );
        }
    }
    assert_eq!(
        String::from_utf8_lossy(ra),
        String::from_utf8_lossy(rb),
        "the report"
    );
}

#[test]
fn report_json_gives_the_programs_own_code_size_beside_the_executables() {
    let (dir, src) = project();
    let o = clean_ladderc(dir.path())
        .args(["build", "--report", "json", "-o", "out"])
        .arg(&src)
        .output()
        .unwrap();
    assert_ok(&o);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let size = &v["code_size"];
    let n = |k: &str| size[k].as_u64().unwrap_or_else(|| panic!("{k}: {size}"));
    // the program's own code: two template functions and the scan of one POU
    assert!(
        n("program_code_bytes") > 100 && n("program_code_bytes") < 8192,
        "{size}"
    );
    assert!(n("runtime_code_bytes") > n("program_code_bytes"), "{size}");
    // the executable carries the motion library: larger than the two, and what `make` links
    assert!(n("executable_bytes") > n("runtime_code_bytes"), "{size}");
    let make = Command::new("make")
        .current_dir(dir.path().join("out"))
        .output()
        .unwrap();
    assert!(make.status.success(), "{}", stderr(&make));
    let built = std::fs::metadata(dir.path().join("out/program"))
        .unwrap()
        .len();
    assert_eq!(
        n("executable_bytes"),
        built,
        "the Makefile builds what was measured"
    );
}
