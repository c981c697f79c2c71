//! `cargo bench -p ladderc --bench ladder_to_c`: PLCopen XML ladder to C, speed and peak memory (issue #4).
//!
//! Input: projects from `ladder_compiler::testgen::generate(rungs)` (the benchmark's generator: contacts,
//! parallel coils, TON timers, GT/LT compare blocks) with 1,000 to 10,000 rungs. Output: a table of the
//! median wall and CPU time of XML reading + ladder lowering (`compile_xml`), sema and C generation, the
//! peak resident memory of each job, and the end-to-end wall time of `ladderc build project.xml -o DIR`
//! (process start, file I/O, the CLI's whole pipeline). Goal (#16; #4 asked for 1 s): 10,000 rungs from XML
//! to C through `ladderc build` in at most 0.25 s.
//! Invariants: every job runs in its own child process (see `common`); the project must compile without
//! an error diagnostic, and the bench fails if it does not.
#![forbid(unsafe_code)]

mod common;

use c_backend::{Options, TargetProfile};
use common::{median, num, report, run_child, Stopwatch};
use diagnostics::{Diagnostics, FileId};
use std::process::Command;
use std::time::Instant;

/// Issue #16's budget for 10,000 rungs through `ladderc build`.
const GOAL_SECONDS: f64 = 0.25;
const RUNS: usize = 7;

fn main() {
    if let Some(job) = common::child_job() {
        let rungs = job
            .strip_prefix("ld:")
            .and_then(|n| n.parse().ok())
            .unwrap_or_else(|| panic!("unknown job {job}"));
        child(rungs);
        return;
    }
    println!("Ladder (PLCopen TC6 XML) to C: compile_xml + sema + C generation, release build");
    println!("{}", common::machine_line());
    println!(
        "{:>7} {:>7} {:>7} | {:>9} {:>9} {:>9} {:>9} {:>9} | {:>8} | {:>9}",
        "rungs",
        "XML MB",
        "C MB",
        "xml->IL",
        "sema",
        "C gen",
        "total",
        "total",
        "peak",
        "CLI build"
    );
    println!(
        "{:>7} {:>7} {:>7} | {:>9} {:>9} {:>9} {:>9} {:>9} | {:>8} | {:>9}",
        "", "", "", "CPU ms", "CPU ms", "CPU ms", "wall ms", "CPU ms", "MB", "wall ms"
    );
    let mut headline = None;
    for rungs in [1_000usize, 2_000, 5_000, 10_000] {
        let r = run_child(&format!("ld:{rungs}"));
        let cli = cli_build_seconds(rungs);
        println!(
            "{:>7} {:>7.1} {:>7.1} | {:>9.1} {:>9.1} {:>9.1} {:>9.1} {:>9.1} | {:>8.1} | {:>9.1}",
            rungs,
            num(&r, "xml_bytes") / 1e6,
            num(&r, "c_bytes") / 1e6,
            num(&r, "cpu_xml") * 1e3,
            num(&r, "cpu_sema") * 1e3,
            num(&r, "cpu_generate") * 1e3,
            num(&r, "wall_total") * 1e3,
            num(&r, "cpu_total") * 1e3,
            num(&r, "peak_kib") / 1024.0,
            cli * 1e3,
        );
        headline = Some((r, cli));
    }
    let (r, cli) = headline.expect("the 10,000-rung job ran");
    println!();
    let total = num(&r, "wall_total");
    println!(
        "10,000 rungs: {:.3} s wall / {:.3} s CPU (median of {}), {:.3} s through `ladderc build` (median of 3); peak {:.1} MB",
        total,
        num(&r, "cpu_total"),
        r["runs"],
        cli,
        num(&r, "peak_kib") / 1024.0,
    );
    println!(
        "goal: at most {GOAL_SECONDS} s through `ladderc build` -> {} ({:.2}x the budget; in memory: wall {:.2}x, CPU {:.2}x)",
        if cli <= GOAL_SECONDS {
            "met"
        } else {
            "NOT met"
        },
        cli / GOAL_SECONDS,
        total / GOAL_SECONDS,
        num(&r, "cpu_total") / GOAL_SECONDS,
    );
}

/// Median wall time of `ladderc build project.xml -o DIR` (the release CLI next to this bench).
fn cli_build_seconds(rungs: usize) -> f64 {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let xml = dir.path().join("project.xml");
    std::fs::write(&xml, ladder_compiler::testgen::generate(rungs)).expect("writing the project");
    let mut times = Vec::new();
    for i in 0..3 {
        let out = dir.path().join(format!("c{i}"));
        let t = Instant::now();
        let status = Command::new(env!("CARGO_BIN_EXE_ladderc"))
            .arg("build")
            .arg(&xml)
            .arg("-o")
            .arg(&out)
            .output()
            .expect("running ladderc");
        times.push(t.elapsed().as_secs_f64());
        assert!(
            status.status.success(),
            "ladderc build failed: {}",
            String::from_utf8_lossy(&status.stderr)
        );
    }
    median(times)
}

/// The measuring child: generates the project, compiles it [`RUNS`] times, reports medians and the
/// peak resident memory after the first compilation.
fn child(rungs: usize) {
    let baseline = common::status_kib("VmHWM");
    let xml = ladder_compiler::testgen::generate(rungs);
    let mut times: [Vec<f64>; 8] = Default::default();
    let mut peak = 0;
    let mut c_bytes = 0;
    let runs = common::runs(RUNS);
    for run in 0..runs {
        let (t, c) = compile(&xml);
        c_bytes = c;
        if run == 0 {
            peak = common::status_kib("VmHWM");
        }
        for (i, v) in t.iter().enumerate() {
            times[i].push(*v);
        }
    }
    report("rungs", rungs);
    report("runs", runs);
    report("xml_bytes", xml.len());
    report("c_bytes", c_bytes);
    report("baseline_kib", baseline);
    report("peak_kib", peak);
    for (i, name) in ["xml", "sema", "generate", "total"].iter().enumerate() {
        report(&format!("wall_{name}"), median(times[2 * i].clone()));
        report(&format!("cpu_{name}"), median(times[2 * i + 1].clone()));
    }
}

/// XML -> IL tree -> sema -> C; returns (wall, CPU) pairs for the three stages and the total, and the
/// size of the C project.
fn compile(xml: &str) -> ([f64; 8], usize) {
    let mut diags = Diagnostics::new();
    let all = Stopwatch::start();
    let sw = Stopwatch::start();
    let unit = ladder_compiler::compile_xml(FileId(0), xml, &mut diags);
    let lower = sw.lap();
    let sw = Stopwatch::start();
    let units = [unit];
    let model = il_frontend::sema::analyze(&units, &mut diags);
    let sema = sw.lap();
    let sw = Stopwatch::start();
    let program = c_backend::generate(
        &units,
        &model,
        &TargetProfile::default(),
        &Options::default(),
        &mut diags,
    );
    let generate = sw.lap();
    let total = all.lap();
    if diags.has_errors() {
        let first: Vec<String> = diags.iter().take(5).map(|d| format!("{d:?}")).collect();
        panic!("the generated project has errors: {first:#?}");
    }
    let program = program.expect("C generation succeeds without errors");
    let c_bytes = program.files.iter().map(|(_, c)| c.len()).sum();
    std::hint::black_box(&program);
    (
        [
            lower.0, lower.1, sema.0, sema.1, generate.0, generate.1, total.0, total.1,
        ],
        c_bytes,
    )
}
