//! `cargo bench -p ladderc --bench il_to_c`: IL-to-C compile speed and peak memory (issues #2, #16).
//!
//! Input: programs from `il_frontend::testgen::generate` (the benchmark's generator): the 100,000-line
//! program (50 POUs of 2,000 body lines) and single POUs of 250,000, 500,000 and 1,000,000 lines (the
//! "no size limits" check). `MATIEC_BIN=<iec2c>` (built by `scripts/build-matiec.sh`; its `lib/` from
//! `MATIEC_LIB`, else `lib/` of the build tree beside the binary, else `$MATIEC_SRC/lib`) also runs the
//! anchor. Output: a table of median wall and CPU time of parse + sema + C generation in memory, per
//! stage, and the peak resident memory of each job; with `MATIEC_BIN`, paired interleaved runs of
//! `iec2c` and `ladderc build` (both as processes, timed by GNU time) on the same program file, their
//! medians and ratios (goals: at least 20x iec2c -O2 in CPU, at most 600 B per line of peak memory, the
//! 1,000,000-line POU under 1 s). Without `MATIEC_BIN` it says that the anchor was not run.
//! `LADDERC_BENCH_DUMP=<file>` also writes the generated program (to time `ladderc build` on it).
//! Invariants: every job runs in its own child process (see `common`), so its peak memory is its own;
//! the compiled program must produce no error diagnostic, and the bench fails if it does.
#![forbid(unsafe_code)]

mod common;

use c_backend::{Options, TargetProfile};
use common::{median, num, report, run_child, Stopwatch};
use diagnostics::{Diagnostics, FileId};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Pairs of (iec2c, ladderc build) runs for the anchor (`LADDERC_BENCH_PAIRS` changes it).
const PAIRS: usize = 5;

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

    println!();
    anchor();
}

/// matiec's iec2c and `ladderc build`, side by side on the 100,000-line program (see the header).
fn anchor() {
    let Some(iec2c) = std::env::var_os("MATIEC_BIN").map(PathBuf::from) else {
        println!(
            "matiec anchor: not run (set MATIEC_BIN to an iec2c built by scripts/build-matiec.sh); no ratio is claimed"
        );
        return;
    };
    let Some(lib) = matiec_lib(&iec2c) else {
        println!("matiec anchor: not run (matiec's lib/ not found: set MATIEC_LIB or MATIEC_SRC)");
        return;
    };
    if !Path::new("/usr/bin/time").is_file() {
        println!(
            "matiec anchor: not run (GNU time, /usr/bin/time, is needed for CPU and peak RSS)"
        );
        return;
    }
    let pairs = std::env::var("LADDERC_BENCH_PAIRS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(PAIRS);
    let dir = tempfile::tempdir().expect("a temporary directory");
    let prog = dir.path().join("program.il");
    let src = il_frontend::testgen::generate(2_000, 50);
    std::fs::write(&prog, &src).expect("writing the program");
    let lines = src.lines().count();
    let out = |name: &str| {
        let d = dir.path().join(name);
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).expect("an output folder");
        d
    };
    let iec2c_run = || {
        let o = out("iec2c");
        let mut c = Command::new(&iec2c);
        c.arg("-I").arg(&lib).arg("-T").arg(&o).arg(&prog);
        timed(c, dir.path())
    };
    let ladderc_run = || {
        let o = out("ladderc");
        let mut c = Command::new(env!("CARGO_BIN_EXE_ladderc"));
        c.arg("build").arg(&prog).arg("-o").arg(&o);
        timed(c, dir.path())
    };
    // Warm-up (page cache; both must accept the program), not counted.
    iec2c_run();
    ladderc_run();
    println!(
        "matiec anchor, side by side: {} and `ladderc build` on the same {lines}-line program, {pairs} interleaved pairs",
        iec2c.display()
    );
    println!("{}", common::machine_line());
    let (mut m, mut l) = (Vec::new(), Vec::new());
    for i in 0..pairs {
        if i % 2 == 0 {
            m.push(iec2c_run());
            l.push(ladderc_run());
        } else {
            l.push(ladderc_run());
            m.push(iec2c_run());
        }
    }
    let med = |v: &[[f64; 3]], k: usize| median(v.iter().map(|r| r[k]).collect());
    println!(
        "{:<24} {:>12} {:>12} {:>10} {:>10}",
        "median", "iec2c", "ladderc", "ratio", "goal"
    );
    let (mc, lc) = (med(&m, 0), med(&l, 0));
    println!(
        "{:<24} {:>12.3} {:>12.3} {:>9.1}x {:>10}",
        "CPU s (user+sys)",
        mc,
        lc,
        mc / lc,
        ">= 20x"
    );
    let (mw, lw) = (med(&m, 1), med(&l, 1));
    println!(
        "{:<24} {:>12.3} {:>12.3} {:>9.1}x",
        "wall s",
        mw,
        lw,
        mw / lw
    );
    let (mr, lr) = (med(&m, 2), med(&l, 2));
    println!(
        "{:<24} {:>12.1} {:>12.1} {:>9.2}x",
        "peak RSS MB",
        mr / 1024.0,
        lr / 1024.0,
        mr / lr
    );
    println!(
        "{:<24} {:>12.0} {:>12.0} {:>10} {:>10}",
        "peak RSS B per line",
        mr * 1024.0 / lines as f64,
        lr * 1024.0 / lines as f64,
        "",
        "<= 600"
    );
    let ratios: Vec<String> = m
        .iter()
        .zip(&l)
        .map(|(a, b)| format!("{:.1}", a[0] / b[0]))
        .collect();
    println!("CPU ratio per pair: {}", ratios.join(" "));
}

/// matiec's `lib/` folder (iec2c -I): `MATIEC_LIB`, `build/lib` beside the binary, `$MATIEC_SRC/lib`.
fn matiec_lib(iec2c: &Path) -> Option<PathBuf> {
    let candidates = [
        std::env::var_os("MATIEC_LIB").map(PathBuf::from),
        iec2c.parent().map(|d| d.join("build/lib")),
        std::env::var_os("MATIEC_SRC").map(|s| PathBuf::from(s).join("lib")),
    ];
    candidates
        .into_iter()
        .flatten()
        .find(|d| d.join("ieclib.txt").is_file())
}

/// Runs `cmd` under GNU time: [CPU seconds (user + sys), wall seconds, peak RSS KiB]. Panics when the
/// command fails (both compilers must accept the program).
fn timed(cmd: Command, dir: &Path) -> [f64; 3] {
    let times = dir.join("time");
    let program = cmd.get_program().to_owned();
    let args: Vec<_> = cmd.get_args().map(|a| a.to_owned()).collect();
    let out = Command::new("/usr/bin/time")
        .arg("-f")
        .arg("%U %S %e %M")
        .arg("-o")
        .arg(&times)
        .arg(&program)
        .args(&args)
        .output()
        .expect("running /usr/bin/time");
    assert!(
        out.status.success(),
        "{} failed on the program: {}",
        program.to_string_lossy(),
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&times).expect("GNU time's output");
    let v: Vec<f64> = text
        .lines()
        .last()
        .unwrap_or_default()
        .split_whitespace()
        .filter_map(|x| x.parse().ok())
        .collect();
    assert_eq!(v.len(), 4, "GNU time's output: {text}");
    [v[0] + v[1], v[2], v[3]]
}

fn print_main(r: &std::collections::BTreeMap<String, String>) {
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
    println!(
        "{:<28} {:>10.1} MB, {:.0} B per IL line (in memory; the anchor below measures whole processes)",
        "peak memory (VmHWM)",
        num(r, "peak_kib") / 1024.0,
        num(r, "peak_kib") * 1024.0 / (num(r, "pous") * num(r, "lines")),
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
