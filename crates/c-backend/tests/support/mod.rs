//! End-to-end test support: IL source -> AST -> sema model -> C -> executable (cc with -Wall -Wextra
//! -Werror and the address/undefined sanitizers) -> run with a stimulus -> trace rows.
#![allow(dead_code)]

use c_backend::{BuildOptions, CProgram, Options, RunOptions, TargetProfile};
use diagnostics::{render_short, Diagnostics, SourceMap};
use il_frontend::ast::CompilationUnit;
use il_frontend::sema::{analyze, Model};
use std::path::PathBuf;

/// Parses and analyses; panics on front-end errors.
pub fn frontend(src: &str) -> (Vec<CompilationUnit>, Model, SourceMap) {
    frontend_with(src, |_, _| {})
}

/// Like [`frontend`], letting the test add elements (configurations) to the parsed unit.
pub fn frontend_with(
    src: &str,
    edit: impl FnOnce(&mut CompilationUnit, diagnostics::FileId),
) -> (Vec<CompilationUnit>, Model, SourceMap) {
    let mut map = SourceMap::new();
    let file = map.add("test.il", src.to_string());
    let mut diags = Diagnostics::new();
    let mut unit = il_frontend::parse(file, src, &mut diags);
    edit(&mut unit, file);
    let units = vec![unit];
    let model = analyze(&units, &mut diags);
    let list = diags.into_sorted();
    let errors: Vec<String> = list
        .iter()
        .filter(|d| d.severity == diagnostics::Severity::Error)
        .map(|d| render_short(&map, d))
        .collect();
    assert!(
        errors.is_empty(),
        "front-end errors:\n{}",
        errors.join("\n")
    );
    (units, model, map)
}

/// Generates C; panics with the rendered diagnostics on failure.
pub fn generate_with(
    units: &[CompilationUnit],
    model: &Model,
    map: &SourceMap,
    profile: &TargetProfile,
    opts: &Options,
) -> CProgram {
    let mut diags = Diagnostics::new();
    match c_backend::generate(units, model, profile, opts, &mut diags) {
        Some(p) => p,
        None => panic!(
            "generation failed:\n{}",
            diags
                .iter()
                .map(|d| render_short(map, d))
                .collect::<Vec<_>>()
                .join("\n")
        ),
    }
}

/// Generation diagnostics (short form) for a source expected to fail.
pub fn generate_errors(src: &str, profile: &TargetProfile, opts: &Options) -> Vec<String> {
    let (units, model, map) = frontend(src);
    let mut diags = Diagnostics::new();
    let r = c_backend::generate(&units, &model, profile, opts, &mut diags);
    assert!(r.is_none(), "generation unexpectedly succeeded");
    diags
        .into_sorted()
        .iter()
        .map(|d| render_short(&map, d))
        .collect()
}

/// Strict flags: warnings are errors, sanitizers on.
pub fn strict() -> BuildOptions {
    BuildOptions {
        cc: None,
        extra_flags: [
            "-Wall",
            "-Wextra",
            "-Werror",
            "-pedantic",
            "-g",
            "-O0",
            "-fsanitize=address,undefined",
            "-fno-sanitize-recover=all",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect(),
    }
}

pub struct Built {
    pub dir: tempfile::TempDir,
    pub exe: PathBuf,
    pub program: CProgram,
}

pub fn build_program(program: CProgram) -> Built {
    let dir = tempfile::tempdir().expect("temp dir");
    let exe = match c_backend::build_with(&program, dir.path(), &strict()) {
        Ok(e) => e,
        Err(e) => panic!(
            "{e}\n--- program.c ---\n{}",
            program.file("program.c").unwrap_or("")
        ),
    };
    Built { dir, exe, program }
}

/// Source -> built executable (default profile, no embedded functions).
pub fn build_src(src: &str) -> Built {
    let (units, model, map) = frontend(src);
    let p = generate_with(
        &units,
        &model,
        &map,
        &TargetProfile::default(),
        &Options::default(),
    );
    build_program(p)
}

/// Runs with a stimulus text; returns the trace as rows of fields (header first).
pub fn run(
    b: &Built,
    cycles: u64,
    cycle_ms: f64,
    stimulus: &str,
    watch: &[&str],
) -> Vec<Vec<String>> {
    let stim = b.dir.path().join("stimulus.csv");
    std::fs::write(&stim, stimulus).unwrap();
    let trace = b.dir.path().join("trace.csv");
    let out = c_backend::run(
        &b.exe,
        &RunOptions {
            cycles,
            cycle_ms,
            stimulus: Some(stim),
            trace: Some(trace.clone()),
            watch: watch.iter().map(|s| s.to_string()).collect(),
        },
    )
    .expect("run");
    assert!(
        out.success(),
        "program failed: {:?}\n{}",
        out.status,
        out.stderr
    );
    assert!(
        !out.stderr.contains("runtime error"),
        "sanitizer report:\n{}",
        out.stderr
    );
    let text = std::fs::read_to_string(trace).unwrap();
    text.lines()
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

/// The column of a watched variable (values only, one per cycle).
pub fn column(rows: &[Vec<String>], name: &str) -> Vec<String> {
    let i = rows[0]
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {:?}", rows[0]));
    rows[1..].iter().map(|r| r[i].clone()).collect()
}

/// A corpus file (see the `test-corpus` crate): bundled, or in `$LADDERC_CORPUS`; `None` after printing
/// a skip line when it is neither.
pub fn corpus(rel: &str) -> Option<PathBuf> {
    test_corpus::file(rel)
}
