//! Helpers shared by the end-to-end tests: the binary, the corpus, exit-status checks; the
//! builders of TwinCAT CFC charts in [`cfc`].
#![allow(dead_code)]

pub mod cfc;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The `ladderc` binary under test: this package's `ladderc-e2e` (the ladderc command line), run with
/// `argv[0] = ladderc` so that its usage and help texts name `ladderc`.
pub fn ladderc() -> Command {
    #[allow(unused_mut)]
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_ladderc-e2e"));
    #[cfg(unix)]
    std::os::unix::process::CommandExt::arg0(&mut cmd, "ladderc");
    cmd
}

/// The repository's root directory (the workspace).
pub fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the tests package lies in the repository")
        .to_path_buf()
}

/// A corpus file the test requires (see the `test-corpus` crate): the bundled copy or the file in
/// `$LADDERC_CORPUS`. Panics when it is neither; a test over a GPL file calls [`corpus_file`] instead.
pub fn corpus(name: &str) -> PathBuf {
    test_corpus::path(name)
}

/// A corpus file, or `None` after printing a skip line when it is not bundled and `LADDERC_CORPUS` is
/// unset (the test then returns and passes). Panics when `LADDERC_CORPUS` is set and lacks the file.
pub fn corpus_file(name: &str) -> Option<PathBuf> {
    test_corpus::file(name)
}

/// Asserts that a run exited with 0, showing its standard error otherwise.
pub fn assert_ok(out: &Output) {
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// `ladderc build --report json --strategy STRATEGY -o OUT SRC`: the report, each block's object size
/// checked to be over `min_object_bytes` (it depends on the C compiler) and then left out.
pub fn block_report(
    src: &Path,
    out_dir: &Path,
    strategy: &str,
    min_object_bytes: u64,
) -> serde_json::Value {
    let out = ladderc()
        .args(["build", "--report", "json", "--strategy", strategy, "-o"])
        .arg(out_dir)
        .arg(src)
        .output()
        .unwrap();
    assert_ok(&out);
    let mut v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for b in v["blocks"].as_array_mut().unwrap() {
        let size = b["object_bytes"].as_u64().expect("cc and nm are available");
        assert!(size > min_object_bytes, "{b}");
        b.as_object_mut().unwrap().remove("object_bytes");
    }
    // the whole program's code size depends on the C compiler too: checked, then left out
    let size = v.as_object_mut().unwrap().remove("code_size").unwrap();
    for k in [
        "program_code_bytes",
        "runtime_code_bytes",
        "executable_bytes",
    ] {
        assert!(size[k].as_u64().is_some_and(|n| n > 0), "{k}: {size}");
    }
    v
}

/// Runs `src` (written to `dir/name`) for one scan under the sanitizers, asserting exit 0 and no
/// undefined behaviour, and returns the traced values by column with the run's stderr.
pub fn run_one_scan(
    dir: &Path,
    name: &str,
    src: &str,
) -> (std::collections::BTreeMap<String, String>, String) {
    let file = dir.join(name);
    std::fs::write(&file, src).unwrap();
    let trace = dir.join(format!("{name}.csv"));
    let out = ladderc()
        .arg("run")
        .arg(&file)
        .args(["--cycles", "1", "--sanitize", "--trace"])
        .arg(&trace)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{stderr}\n{src}");
    assert!(
        !stderr.contains("runtime error") && !stderr.contains("Sanitizer"),
        "undefined behaviour: {stderr}"
    );
    let text = std::fs::read_to_string(&trace).unwrap();
    let mut lines = text.lines();
    let head = split_csv(lines.next().unwrap());
    let row = split_csv(lines.next().unwrap());
    (head.into_iter().zip(row).collect(), stderr)
}

/// A CSV row of a trace: strings are quoted and keep their quotes; a doubled quote inside is one.
pub fn split_csv(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                cur.push('"');
                chars.next();
            }
            '"' => {
                quoted = !quoted;
                cur.push('"');
            }
            ',' if !quoted => out.push(std::mem::take(&mut cur)),
            c => cur.push(c),
        }
    }
    out.push(cur);
    out
}

/// `ladderc run FILE` for `cycles` scans of 10 ms with `stimulus` (rows `cycle,variable,value` after the
/// header), tracing the `watch` columns; returns the trace text. Panics when the run fails.
pub fn run_with_stimulus(file: &Path, cycles: u32, stimulus: &str, watch: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, format!("cycle,variable,value\n{stimulus}")).unwrap();
    let trace = dir.path().join("trace.csv");
    let out = ladderc()
        .arg("run")
        .arg(file)
        .args(["--cycles", &cycles.to_string(), "--cycle-ms", "10"])
        .arg("--stimulus")
        .arg(&stim)
        .arg("--trace")
        .arg(&trace)
        .args(["--watch", &watch.join(",")])
        .output()
        .unwrap();
    assert_ok(&out);
    std::fs::read_to_string(&trace).unwrap()
}

/// `ladderc run FILE` (10 ms scans, C built with the sanitizers) with `stimulus` rows
/// (`cycle,variable,value` after the header), tracing `watch` to standard output: the trace and
/// standard error; asserts exit 0 and no sanitizer report.
pub fn run_stimulated(file: &Path, cycles: u32, stimulus: &str, watch: &str) -> (String, String) {
    run_stimulated_files(&[file], &["--cycle-ms", "10"], cycles, stimulus, watch)
}

/// `ladderc run FILES EXTRA --cycles N --sanitize --stimulus S --trace - --watch W` (the cycle
/// time is the project's unless `extra` gives one): the trace and standard error; asserts exit 0
/// and no sanitizer report.
pub fn run_stimulated_files<P: AsRef<std::ffi::OsStr> + std::fmt::Debug>(
    files: &[P],
    extra: &[&str],
    cycles: u32,
    stimulus: &str,
    watch: &str,
) -> (String, String) {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, format!("cycle,variable,value\n{stimulus}")).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .args(files)
        .args(extra)
        .args(["--cycles", &cycles.to_string(), "--sanitize", "--stimulus"])
        .arg(&stim)
        .args(["--trace", "-", "--watch", watch])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{files:?}: {stderr}");
    assert!(!stderr.contains("Sanitizer"), "{stderr}");
    (String::from_utf8_lossy(&out.stdout).into_owned(), stderr)
}

/// `ladderc check` of the files (name, text) written together to a temporary folder: exit code
/// and the error lines up to their hints, with the folder left out.
pub fn check_files(files: &[(&str, &str)]) -> (Option<i32>, Vec<String>) {
    let dir = tempfile::tempdir().unwrap();
    let paths: Vec<PathBuf> = files
        .iter()
        .map(|(name, src)| {
            let p = dir.path().join(name);
            std::fs::write(&p, src).unwrap();
            p
        })
        .collect();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .args(&paths)
        .output()
        .unwrap();
    let lines = diagnostic_heads(&out.stderr, dir.path(), false);
    (out.status.code(), lines)
}

/// A copy of the folder `from` (and everything under it) in a new temporary folder.
pub fn copy_of_folder(from: &Path) -> tempfile::TempDir {
    fn copy(from: &Path, to: &Path) {
        std::fs::create_dir_all(to).unwrap();
        for e in std::fs::read_dir(from).unwrap() {
            let e = e.unwrap();
            let target = to.join(e.file_name());
            if e.path().is_dir() {
                copy(&e.path(), &target);
            } else {
                std::fs::copy(e.path(), target).unwrap();
            }
        }
    }
    let dir = tempfile::tempdir().unwrap();
    copy(from, dir.path());
    dir
}

/// `ladderc --message-format short check FILE`: exit code and standard error.
pub fn check_stderr(file: &Path) -> (Option<i32>, String) {
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(file)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// `ladderc build FILE -o DIR`, then the generated Makefile run with `CFLAGS=cflags`; panics
/// (with the compiler's messages) when either fails. Gives the folder (removed when dropped)
/// and the generated `program.c`.
pub fn build_and_make(file: &Path, cflags: &str) -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let out_dir = dir.path().join("out");
    let out = ladderc()
        .arg("build")
        .arg(file)
        .arg("-o")
        .arg(&out_dir)
        .output()
        .unwrap();
    assert_ok(&out);
    let c = std::fs::read_to_string(out_dir.join("program.c")).unwrap();
    let built = Command::new("make")
        .args(["-s", &format!("CFLAGS={cflags}")])
        .current_dir(&out_dir)
        .output()
        .unwrap();
    assert!(
        built.status.success(),
        "{file:?}: {}",
        String::from_utf8_lossy(&built.stderr)
    );
    (dir, c)
}

/// The numeric column `name` of a trace (CSV text with a header row), one value per cycle. Panics when
/// the column is missing or a value is not a number.
pub fn column(trace: &str, name: &str) -> Vec<f64> {
    let mut lines = trace.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header
        .iter()
        .position(|h| *h == name)
        .unwrap_or_else(|| panic!("no column {name}"));
    lines
        .map(|l| l.split(',').nth(k).unwrap().parse::<f64>().unwrap())
        .collect()
}

/// The text column `name` of a trace (CSV text with a header row), one value per cycle, as written
/// (TIME, TOD and DT values as literals, `T#1500ms`). Panics when the column is missing.
pub fn text_column(trace: &str, name: &str) -> Vec<String> {
    let mut lines = trace.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header
        .iter()
        .position(|h| *h == name)
        .unwrap_or_else(|| panic!("no column {name} in {trace}"));
    lines
        .map(|l| l.split(',').nth(k).unwrap().to_string())
        .collect()
}

/// The cycles at which the numeric column `name` of a trace changes, with its new value (the first
/// row included).
pub fn changes(trace: &str, name: &str) -> Vec<(usize, f64)> {
    let col = column(trace, name);
    let mut out = vec![(0, col[0])];
    for (k, w) in col.windows(2).enumerate() {
        if w[0] != w[1] {
            out.push((k + 1, w[1]));
        }
    }
    out
}

/// `text` written as `plc.xml` in a fresh folder and run there as [`run_with_stimulus`] does.
pub fn run_xml_with_stimulus(text: &str, cycles: u32, stimulus: &str, watch: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("plc.xml");
    std::fs::write(&file, text).unwrap();
    run_with_stimulus(&file, cycles, stimulus, watch)
}

/// A PLCopen TC6 project: `fbs` (whole `<pou>` elements), then program `main` with the local
/// variables `vars` (`name:TYPE` pairs, TYPE elementary or a block type) and `body` (an `<LD>` or
/// `<FBD>` element), run as instance `m` by a 10 ms task.
pub fn plcopen_program(fbs: &str, vars: &[(&str, &str)], body: &str) -> String {
    let vars: String = vars
        .iter()
        .map(|(n, t)| {
            let ty = if t.chars().all(|c| c.is_ascii_uppercase()) {
                format!("<{t}/>")
            } else {
                format!("<derived name=\"{t}\"/>")
            };
            format!("<variable name=\"{n}\"><type>{ty}</type></variable>\n")
        })
        .collect();
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
<fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
<contentHeader name="t"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
<types><dataTypes/><pous>
{fbs}
<pou name="main" pouType="program">
<interface><localVars>
{vars}</localVars></interface>
<body>
{body}
</body>
</pou>
</pous></types>
<instances><configurations><configuration name="c"><resource name="r">
<task name="t" priority="0" interval="T#10ms"><pouInstance name="m" typeName="main"/></task>
</resource></configuration></configurations></instances>
</project>
"#
    )
}

/// The diagnostic lines of `stderr` (short format) that are errors, and warnings too with
/// `with_warnings`, each up to its hint, with the folder `strip` left out of their paths.
pub fn diagnostic_heads(stderr: &[u8], strip: &Path, with_warnings: bool) -> Vec<String> {
    let prefix = format!("{}/", strip.display());
    String::from_utf8_lossy(stderr)
        .lines()
        .filter(|l| l.contains("error[") || (with_warnings && l.contains("warning[")))
        .map(|l| l.replace(&prefix, ""))
        .map(|l| {
            l.split_once(" (hint")
                .map_or(l.clone(), |(h, _)| h.to_string())
        })
        .collect()
}

/// [`check_text`] of a text that must be rejected (exit 1): each diagnostic line up to its hint
/// (`file:line:col: error[CODE]: message`).
pub fn rejected_heads(name: &str, src: &str) -> Vec<String> {
    let (code, lines) = check_text(name, src);
    assert_eq!(code, Some(1), "{lines:?}");
    lines
        .iter()
        .map(|l| l.split_once(" (hint").unwrap().0.to_string())
        .collect()
}

/// `ladderc run FILE --cycles N --sanitize --watch WATCH --trace -`: the trace (standard output)
/// and standard error; asserts exit 0.
pub fn run_traced(file: &Path, cycles: u32, watch: &str) -> (String, String) {
    run_traced_files(&[file], cycles, watch)
}

/// [`run_traced`] of several files compiled together (a project split over files).
pub fn run_traced_files(files: &[&Path], cycles: u32, watch: &str) -> (String, String) {
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .args(files)
        .args([
            "--cycles",
            &cycles.to_string(),
            "--sanitize",
            "--trace",
            "-",
        ])
        .args(["--watch", watch])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{files:?}: {stderr}");
    assert!(!stderr.contains("Sanitizer"), "{stderr}");
    (String::from_utf8_lossy(&out.stdout).into_owned(), stderr)
}

/// [`run_traced`] of `src` written to a temporary `name`.
pub fn run_text(name: &str, src: &str, cycles: u32, watch: &str) -> (String, String) {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join(name);
    std::fs::write(&file, src).unwrap();
    run_traced(&file, cycles, watch)
}

/// `ladderc check` of `src` written to `dir/name`: exit code and the diagnostic lines (short
/// format), with the temporary folder left out.
pub fn check_text(name: &str, src: &str) -> (Option<i32>, Vec<String>) {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join(name);
    std::fs::write(&f, src).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&f)
        .output()
        .unwrap();
    let prefix = format!("{}/", dir.path().display());
    let lines = String::from_utf8_lossy(&out.stderr)
        .lines()
        .filter(|l| l.contains("error[") || l.contains("warning["))
        .map(|l| l.replace(&prefix, ""))
        .collect();
    (out.status.code(), lines)
}

/// Writes `text` to `dir/name` (its folder exists) and returns its path.
pub fn write_file(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// The path of `name` among the unseen projects' fixtures (`tests/tests/fixtures/unseen/`).
pub fn unseen_fixture(name: &str) -> PathBuf {
    repo_root().join("tests/tests/fixtures/unseen").join(name)
}

/// `ladderc --message-format short ARGS` run in `dir`: exit code, stdout, stderr.
#[allow(dead_code)]
pub fn in_dir(dir: &Path, args: &[&str]) -> (Option<i32>, String, String) {
    let out = ladderc()
        .current_dir(dir)
        .args(["--message-format", "short"])
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Writes `text` to `dir/name`, creating the folders of `name` (`Logical/Conveyor/Main.st`).
#[allow(dead_code)]
pub fn write_in(dir: &Path, name: &str, text: &str) {
    let p = dir.join(name);
    std::fs::create_dir_all(p.parent().unwrap()).unwrap();
    std::fs::write(p, text).unwrap();
}
