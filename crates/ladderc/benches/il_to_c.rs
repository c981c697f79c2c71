//! `cargo bench -p ladderc --bench il_to_c`: IL-to-C compile speed and peak memory (issue #2).
//!
//! Input: programs from `il_frontend::testgen::generate` (the benchmark's generator): the 100,000-line
//! program (50 POUs of 2,000 body lines) and single POUs of 250,000, 500,000 and 1,000,000 lines (the
//! "no size limits" check). Output: a table of median wall and CPU time of parse + sema + C generation,
//! per stage, and the peak resident memory of each job, with the ratios against matiec's iec2c anchor
//! stated in the issue (8.2 s, 164 MB; goals: at least 50x faster, under 100 MB peak).
//! `LADDERC_BENCH_DUMP=<file>` also writes the generated program (to time `ladderc build` on it).
//! Invariants: every job runs in its own child process (see `common`), so its peak memory is its own;
//! the compiled program must produce no error diagnostic, and the bench fails if it does.

mod common;

use c_backend::{Options, TargetProfile};
use common::{median, num, report, run_child, Stopwatch};
use diagnostics::{Diagnostics, FileId};

/// matiec's iec2c on a program of this shape, as stated in issue #2 (this machine class).
const ANCHOR_SECONDS: f64 = 8.2;
const ANCHOR_MB: f64 = 164.0;

/// A job: `il:<body lines per POU>:<POUs>:<timed runs>`.
fn job(lines: usize, pous: usize, runs: usize) -> String {
    format!("il:{lines}:{pous}:{runs}")
}

fn main() {
    if let Some(job) = common::child_job() {
        child(&job);
        return;
    }
    println!("IL to C (parse + sema + C generation), release build");
    println!("{}", common::machine_line());
    let main_job = run_child(&job(2_000, 50, 9));
    print_main(&main_job);

    println!();
    println!("No size limits: one POU of N IL lines (memory must grow in proportion to the input)");
    println!(
        "{:>10} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10} {:>12}",
        "IL lines", "IL MB", "C MB", "wall s", "CPU s", "peak MB", "work MB", "work B/line"
    );
    for lines in [250_000usize, 500_000, 1_000_000] {
        let r = run_child(&job(lines, 1, 3));
        let work = num(&r, "peak_kib") - num(&r, "baseline_kib");
        println!(
            "{:>10} {:>10.1} {:>10.1} {:>10.3} {:>10.3} {:>10.1} {:>10.1} {:>12.0}",
            lines,
            num(&r, "il_bytes") / 1e6,
            num(&r, "c_bytes") / 1e6,
            num(&r, "wall_total"),
            num(&r, "cpu_total"),
            num(&r, "peak_kib") / 1024.0,
            work / 1024.0,
            work * 1024.0 / lines as f64,
        );
    }
}

fn print_main(r: &std::collections::BTreeMap<String, String>) {
    let wall = num(r, "wall_total");
    let cpu = num(r, "cpu_total");
    let peak_mb = num(r, "peak_kib") / 1024.0;
    println!(
        "program: {} POUs x {} body lines = {} IL lines in {} source lines, {:.1} MB of IL -> {:.1} MB of C, median of {} runs",
        r["pous"],
        r["lines"],
        num(r, "pous") * num(r, "lines"),
        r["source_lines"],
        num(r, "il_bytes") / 1e6,
        num(r, "c_bytes") / 1e6,
        r["runs"],
    );
    println!("{:<28} {:>10} {:>10}", "stage", "wall ms", "CPU ms");
    for stage in ["parse", "sema", "generate", "total"] {
        println!(
            "{:<28} {:>10.1} {:>10.1}",
            stage,
            num(r, &format!("wall_{stage}")) * 1e3,
            num(r, &format!("cpu_{stage}")) * 1e3
        );
        if stage == "parse" {
            println!(
                "{:<28} {:>10.1} {:>10.1}",
                "  of which lex + layout",
                num(r, "wall_lex") * 1e3,
                num(r, "cpu_lex") * 1e3
            );
        }
    }
    println!();
    println!(
        "{:<28} {:>12} {:>12} {:>12} {:>8}",
        "", "matiec iec2c", "ladderc", "ratio", "goal"
    );
    println!(
        "{:<28} {:>12.2} {:>12.3} {:>11.0}x {:>8}",
        "time, s (wall median)",
        ANCHOR_SECONDS,
        wall,
        ANCHOR_SECONDS / wall,
        ">= 50x"
    );
    println!(
        "{:<28} {:>12.2} {:>12.3} {:>11.0}x {:>8}",
        "time, s (CPU median)",
        ANCHOR_SECONDS,
        cpu,
        ANCHOR_SECONDS / cpu,
        ">= 50x"
    );
    println!(
        "{:<28} {:>12.0} {:>12.1} {:>11.1}x {:>8}",
        "peak memory, MB (VmHWM)",
        ANCHOR_MB,
        peak_mb,
        ANCHOR_MB / peak_mb,
        "< 100"
    );
    println!(
        "(matiec's figures are the issue's anchor: matiec is not packaged in this machine's registries, so it was not rerun here)"
    );
}

/// The measuring child: generates the program, compiles it `runs` times, reports stage times (medians)
/// and the peak resident memory after the first compilation.
fn child(job: &str) {
    let parts: Vec<usize> = job
        .strip_prefix("il:")
        .unwrap_or_else(|| panic!("unknown job {job}"))
        .split(':')
        .map(|p| p.parse().expect("a number in the job name"))
        .collect();
    let [lines, pous, runs] = parts[..] else {
        panic!("job {job} needs lines:pous:runs")
    };
    let runs = common::runs(runs);
    let baseline = common::status_kib("VmHWM");
    let src = il_frontend::testgen::generate(lines, pous);
    // `LADDERC_BENCH_DUMP=<file>`: also write the program, e.g. to time `ladderc build` on it.
    if let Ok(path) = std::env::var("LADDERC_BENCH_DUMP") {
        std::fs::write(&path, &src).unwrap_or_else(|e| panic!("writing {path}: {e}"));
    }
    // Lexing and layout alone (the token stream the grammar reads), to split the parse stage.
    let mut tokens = Vec::new();
    let mut tokens_count = 0;
    for _ in 0..runs {
        let sw = Stopwatch::start();
        let layout = il_frontend::layout::Layout::new(
            FileId(0),
            &src,
            0,
            il_frontend::lexer::Tok::UnitStart,
        );
        tokens_count = std::hint::black_box(layout.count());
        tokens.push(sw.lap());
    }
    let mut times: [Vec<f64>; 8] = Default::default();
    let mut peak = 0;
    let mut c_bytes = 0;
    for run in 0..runs {
        let t = compile(&src);
        c_bytes = t.c_bytes;
        if run == 0 {
            peak = common::status_kib("VmHWM");
        }
        for (i, v) in t.stages.iter().enumerate() {
            times[i].push(*v);
        }
    }
    report("lines", lines);
    report("pous", pous);
    report("runs", runs);
    report("source_lines", src.lines().count());
    report("il_bytes", src.len());
    report("c_bytes", c_bytes);
    report("baseline_kib", baseline);
    report("peak_kib", peak);
    report("peak_after_all_runs_kib", common::status_kib("VmHWM"));
    report("tokens", tokens_count);
    report("wall_lex", median(tokens.iter().map(|t| t.0).collect()));
    report("cpu_lex", median(tokens.iter().map(|t| t.1).collect()));
    let names = ["parse", "sema", "generate", "total"];
    for (i, name) in names.iter().enumerate() {
        report(&format!("wall_{name}"), median(times[2 * i].clone()));
        report(&format!("cpu_{name}"), median(times[2 * i + 1].clone()));
    }
}

struct Timing {
    /// wall, CPU for parse, sema, generate, total (seconds).
    stages: [f64; 8],
    c_bytes: usize,
}

fn compile(src: &str) -> Timing {
    let mut diags = Diagnostics::new();
    let all = Stopwatch::start();
    let sw = Stopwatch::start();
    let unit = il_frontend::parse(FileId(0), src, &mut diags);
    let parse = sw.lap();
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
        panic!("the generated program has errors: {first:#?}");
    }
    let program = program.expect("C generation succeeds without errors");
    let c_bytes = program.files.iter().map(|(_, c)| c.len()).sum();
    std::hint::black_box(&program);
    Timing {
        stages: [
            parse.0, parse.1, sema.0, sema.1, generate.0, generate.1, total.0, total.1,
        ],
        c_bytes,
    }
}
