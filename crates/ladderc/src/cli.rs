//! Argument parsing (clap) and dispatch to the library crates.

use crate::{output, pipeline};
use clap::{Parser, Subcommand, ValueEnum};
use diagnostics::{render, Diagnostic, MessageFormat, SourceMap};
use param_passing::lower::Strategy;
use std::path::PathBuf;

#[derive(Parser, Debug)]
#[command(
    name = "ladderc",
    version,
    about = "IEC 61131-3 ladder (PLCopen XML) and IL to C, with PLCopen motion"
)]
pub struct Cli {
    /// How diagnostics are printed on stderr.
    #[arg(long, value_enum, default_value_t = Format::Human, global = true)]
    pub message_format: Format,
    /// At most N diagnostics per file in the human and short formats (0: all); JSON shows all.
    #[arg(long, value_name = "N", default_value_t = diagnostics::DEFAULT_MAX_PER_FILE, global = true)]
    pub max_diagnostics: usize,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
pub enum Format {
    Human,
    Short,
    Json,
}

impl From<Format> for MessageFormat {
    fn from(f: Format) -> Self {
        match f {
            Format::Human => MessageFormat::Human,
            Format::Short => MessageFormat::Short,
            Format::Json => MessageFormat::Json,
        }
    }
}

#[derive(clap::Args, Debug, Clone)]
pub struct CompileArgs {
    /// Input files: IL sources, or PLCopen TC6 XML projects (`.xml`).
    #[arg(required = true)]
    pub inputs: Vec<PathBuf>,
    /// Target profile (memory model) as JSON; the default profile when absent.
    #[arg(long)]
    pub profile: Option<PathBuf>,
    /// How PLCopen block calls are lowered (paper A).
    #[arg(long, value_enum, default_value_t = StrategyArg::Template)]
    pub strategy: StrategyArg,
    /// A directory of extra parameter templates (`*.xml`); they replace built-ins of the same name.
    #[arg(long)]
    pub templates: Option<PathBuf>,
    /// Axis configuration (JSON, see crates/ladderc/AXES.md); default: `<first input stem>.axes.json`
    /// beside the first input, when it exists.
    #[arg(long)]
    pub axes: Option<PathBuf>,
    /// Also write a PMAC motion program of the program's constant MC_MoveAbsolute/MC_MoveRelative moves.
    #[arg(long)]
    pub pmac: Option<PathBuf>,
    /// PMAC dialect of `--pmac`: `turbo` or `power`.
    #[arg(long, default_value = "turbo")]
    pub pmac_dialect: String,
}

#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
pub enum StrategyArg {
    /// IL-instruction method: TM transfers + one FUNC of a static-library function.
    Il,
    /// Parameter-template method: one FUNC of a function synthesised from the template.
    Template,
    /// Per block: IL when it fits the TM area and is called at 3 or more sites, template otherwise.
    Auto,
}

#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
pub enum Emit {
    /// The C project (default): written to the output directory.
    C,
    /// The lowered IL, printed on standard output.
    Il,
}

#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
pub enum ReportFormat {
    Json,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Check sources: parse and run the semantic checks, print diagnostics.
    Check {
        #[arg(required = true)]
        inputs: Vec<PathBuf>,
    },
    /// Compile to a C project (sources, header, runtime, Makefile) in a directory.
    Build {
        #[command(flatten)]
        compile: CompileArgs,
        /// Output directory (replaced atomically).
        #[arg(short = 'o', long = "output")]
        output: Option<PathBuf>,
        #[arg(long, value_enum, default_value_t = Emit::C)]
        emit: Emit,
        /// Print a report on standard output: per PLCopen block type its method, calls, TM bytes,
        /// IL instructions and generated C bytes (paper A's comparison).
        #[arg(long, value_enum)]
        report: Option<ReportFormat>,
    },
    /// Build with the system C compiler and run scan cycles.
    Run {
        #[command(flatten)]
        compile: CompileArgs,
        /// Number of scan cycles.
        #[arg(long, default_value_t = 10)]
        cycles: u64,
        /// Cycle time in milliseconds (default: the axis configuration's `cycle_ms`, else 10).
        #[arg(long)]
        cycle_ms: Option<f64>,
        /// CSV rows `cycle,variable,value`, applied before that cycle.
        #[arg(long)]
        stimulus: Option<PathBuf>,
        /// CSV trace: `cycle,time_ms,VAR...`, one row per cycle after the cycle.
        #[arg(long)]
        trace: Option<PathBuf>,
        /// Variables to trace (`main.count`, `inst.count`, `%QX0.1`), comma-separated.
        #[arg(long, value_delimiter = ',')]
        watch: Vec<String>,
        /// Build with -fsanitize=address,undefined.
        #[arg(long)]
        sanitize: bool,
        /// Draw position and velocity of every axis over time into this SVG file (block starts and
        /// ends marked from watched `.busy` / `.done` columns).
        #[arg(long)]
        plot: Option<PathBuf>,
        /// Write the run's motion (every axis's traced set position, velocity, acceleration) as a PMAC
        /// PVT rotary-buffer script (dialect: --pmac-dialect).
        #[arg(long)]
        pmac_pvt: Option<PathBuf>,
        /// PVT segment time in ms for --pmac-pvt (a whole number of cycles).
        #[arg(long, default_value_t = 10.0)]
        pvt_ms: f64,
    },
    /// Motion planning tools.
    #[command(subcommand)]
    Motion(MotionCommand),
    /// Drive scripts (paper C): compile, run on a simulated drive, debug.
    #[command(subcommand)]
    Drive(DriveCommand),
    /// Print the explanation of a diagnostic code (e.g. `ladderc explain E1001`), or list every code.
    Explain {
        /// The code; omit it to list all codes with their titles.
        code: Option<String>,
    },
}

#[derive(Subcommand, Debug)]
pub enum MotionCommand {
    /// Plan jerk-limited profiles for problems in the oracle's JSON-lines format; prints each problem back
    /// with its time-optimal `duration` and `phases` ([duration, jerk] pairs).
    Plan { file: PathBuf },
}

#[derive(Subcommand, Debug)]
pub enum DriveCommand {
    /// Compile a drive script into its binary image (Motion and Event pools).
    Build {
        script: PathBuf,
        #[arg(short = 'o', long = "output")]
        output: PathBuf,
    },
    /// Run a script (or an image) on the simulated drive.
    Run {
        script: PathBuf,
        #[arg(long, default_value_t = 1000)]
        cycles: u64,
        /// CSV trace, one row per main-loop cycle.
        #[arg(long)]
        trace: Option<PathBuf>,
        /// Main-loop period in milliseconds.
        #[arg(long, default_value_t = 1)]
        cycle_ms: u32,
        /// Digital inputs of the simulated drive (bit n = DI_n).
        #[arg(long, default_value_t = 0)]
        inputs: u32,
        /// The drive: a motion-lib axis (jerk-limited, PLCopen blocks) or the simple simulation.
        #[arg(long, value_enum, default_value_t = DriveArg::MotionLib)]
        drive: DriveArg,
    },
    /// Interactive breakpoint debugger (commands from standard input; `help` lists them).
    Debug {
        script: PathBuf,
        #[arg(long, value_enum, default_value_t = DriveArg::MotionLib)]
        drive: DriveArg,
    },
}

#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
pub enum DriveArg {
    MotionLib,
    Sim,
}

impl From<DriveArg> for drive_script::cli::DriveKind {
    fn from(d: DriveArg) -> Self {
        match d {
            DriveArg::MotionLib => drive_script::cli::DriveKind::MotionLib,
            DriveArg::Sim => drive_script::cli::DriveKind::Sim,
        }
    }
}

/// Exit codes.
pub const EXIT_OK: i32 = 0;
pub const EXIT_DIAGNOSTICS: i32 = 1;
pub const EXIT_USAGE: i32 = 2;

pub fn main() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let _ = e.print();
            return if e.use_stderr() { EXIT_USAGE } else { EXIT_OK };
        }
    };
    diagnostics::set_max_per_file(cli.max_diagnostics);
    match cli.command {
        Command::Explain { code } => explain(code.as_deref()),
        Command::Drive(cmd) => drive(cmd, cli.message_format.into()),
        Command::Motion(MotionCommand::Plan { file }) => motion_plan(&file),
        Command::Check { inputs } => check(&inputs, cli.message_format),
        Command::Build {
            compile,
            output,
            emit,
            report,
        } => build(
            &compile,
            output.as_deref(),
            emit,
            report,
            cli.message_format,
        ),
        Command::Run {
            compile,
            cycles,
            cycle_ms,
            stimulus,
            trace,
            watch,
            sanitize,
            plot,
            pmac_pvt,
            pvt_ms,
        } => {
            let run = c_backend::RunOptions {
                cycles,
                cycle_ms: cycle_ms.unwrap_or(pipeline::DEFAULT_CYCLE_MS),
                stimulus,
                trace,
                watch,
            };
            let pvt = pmac_pvt.map(|p| (p, pvt_ms));
            run_program(
                &compile,
                cycle_ms,
                run,
                sanitize,
                (plot, pvt),
                cli.message_format,
            )
        }
    }
}

fn drive(cmd: DriveCommand, format: MessageFormat) -> i32 {
    use drive_script::cli;
    let (mut out, mut err) = (std::io::stdout(), std::io::stderr());
    match cmd {
        DriveCommand::Build { script, output } => cli::build(
            &cli::BuildArgs {
                script,
                output,
                format,
            },
            &mut out,
            &mut err,
        ),
        DriveCommand::Run {
            script,
            cycles,
            trace,
            cycle_ms,
            inputs,
            drive,
        } => cli::run_with_drive(
            &cli::RunArgs {
                script,
                cycles,
                trace,
                cycle_ms,
                inputs,
                format,
            },
            drive.into(),
            &mut out,
            &mut err,
        ),
        DriveCommand::Debug { script, drive } => {
            let stdin = std::io::stdin();
            cli::debug_with_drive(
                &cli::DebugArgs { script, format },
                drive.into(),
                &mut stdin.lock(),
                &mut out,
                &mut err,
            )
        }
    }
}

fn options(c: &CompileArgs) -> pipeline::Options {
    pipeline::Options {
        axes: c.axes.clone(),
        cycle_ms: None,
        profile: c.profile.clone(),
        strategy: match c.strategy {
            StrategyArg::Il => Strategy::Il,
            StrategyArg::Template => Strategy::Template,
            StrategyArg::Auto => Strategy::Auto,
        },
        templates: c.templates.clone(),
    }
}

/// Prints the session's diagnostics; the exit code for them (0 when there is no error).
fn finish(s: pipeline::Session, format: Format) -> i32 {
    let has_errors = s.diags.has_errors();
    emit(&s.map, &s.diags.into_sorted(), format);
    if has_errors {
        EXIT_DIAGNOSTICS
    } else {
        EXIT_OK
    }
}

fn io_error(message: String, hint: &str, format: Format) -> i32 {
    let d = Diagnostic::error(diagnostics::code::E9002, message).with_hint(hint);
    emit(&SourceMap::new(), &[d], format);
    EXIT_USAGE
}

fn check(inputs: &[PathBuf], format: Format) -> i32 {
    let mut s = pipeline::Session::new();
    let c = CompileArgs {
        inputs: inputs.to_vec(),
        profile: None,
        strategy: StrategyArg::Template,
        templates: None,
        axes: None,
        pmac: None,
        pmac_dialect: "turbo".into(),
    };
    let _ = s.lower(inputs, &options(&c));
    finish(s, format)
}

fn build(
    c: &CompileArgs,
    output: Option<&std::path::Path>,
    emit_kind: Emit,
    report: Option<ReportFormat>,
    format: Format,
) -> i32 {
    let mut s = pipeline::Session::new();
    match emit_kind {
        Emit::Il if report.is_some() => {
            eprintln!(
                "error: `--report` describes a C build: use it with `-o DIR`, not `--emit il`"
            );
            EXIT_USAGE
        }
        Emit::Il => {
            let lowered = s.lower(&c.inputs, &options(c));
            let code = finish(s, format);
            if let Some(l) = lowered {
                for u in l.units() {
                    print!("{}", il_frontend::print::unit(u));
                }
            }
            code
        }
        Emit::C => {
            let Some(dir) = output else {
                eprintln!("error: `build` needs `-o DIR` (or `--emit il`)");
                return EXIT_USAGE;
            };
            let compiled = s.compile(&c.inputs, &options(c));
            let pmac = compiled.as_ref().and_then(|(l, _)| pmac_text(c, l, &mut s));
            let code = finish(s, format);
            let Some((lowered, program)) = compiled else {
                return code;
            };
            if let Err(code) = write_pmac(c, pmac, code, format) {
                return code;
            }
            if report == Some(ReportFormat::Json) {
                println!("{}", crate::report::json(&lowered, &program));
            }
            let mut files: Vec<(String, Vec<u8>)> = program
                .files
                .iter()
                .map(|(p, c)| (p.clone(), c.clone().into_bytes()))
                .collect();
            if let Err(code) = add_staticlib(&program, &mut files, format) {
                return code;
            }
            if let Err(e) = output::write_dir_atomically(dir, &files) {
                return io_error(
                    format!("cannot write {}: {e}", dir.display()),
                    "check that the directory can be written",
                    format,
                );
            }
            code
        }
    }
}

/// The PMAC program of `--pmac` (diagnostics into the session).
fn pmac_text(c: &CompileArgs, l: &pipeline::Lowered, s: &mut pipeline::Session) -> Option<String> {
    c.pmac.as_ref()?;
    let dialect = match c.pmac_dialect.parse() {
        Ok(d) => d,
        Err(e) => {
            s.diags.push(
                Diagnostic::error(diagnostics::code::E9002, format!("--pmac-dialect: {e}"))
                    .with_hint("use turbo or power"),
            );
            return None;
        }
    };
    crate::pmac_out::program(l.source_units(), &l.axes, dialect, &mut s.diags)
}

/// Writes the `--pmac` file. `Err`: the exit code (the session had errors, or writing failed).
fn write_pmac(c: &CompileArgs, text: Option<String>, code: i32, format: Format) -> Result<(), i32> {
    let Some(path) = &c.pmac else {
        return Ok(());
    };
    if code != EXIT_OK {
        return Err(code);
    }
    let Some(text) = text else {
        return Err(EXIT_DIAGNOSTICS);
    };
    std::fs::write(path, text).map_err(|e| {
        io_error(
            format!("cannot write {}: {e}", path.display()),
            "check that the directory can be written",
            format,
        )
    })
}

/// Adds the motion library to the project's files when the program links it (so that the project
/// builds on its own with `make`). `Err`: the exit code after reporting E9050 or an I/O error.
fn add_staticlib(
    program: &c_backend::CProgram,
    files: &mut Vec<(String, Vec<u8>)>,
    format: Format,
) -> Result<(), i32> {
    let lib = c_backend::motion::STATICLIB;
    if !program.link.iter().any(|l| l == lib) {
        return Ok(());
    }
    let path = match crate::motion_link::find() {
        Ok(p) => p,
        Err(d) => {
            emit(&SourceMap::new(), &[*d], format);
            return Err(EXIT_USAGE);
        }
    };
    match std::fs::read(&path) {
        Ok(bytes) => {
            files.push((lib.to_string(), bytes));
            Ok(())
        }
        Err(e) => Err(io_error(
            format!("cannot read {}: {e}", path.display()),
            "check LADDERC_MOTION_LIB",
            format,
        )),
    }
}

fn run_program(
    c: &CompileArgs,
    cycle_ms: Option<f64>,
    mut run: c_backend::RunOptions,
    sanitize: bool,
    (plot, pvt): (Option<PathBuf>, Option<(PathBuf, f64)>),
    format: Format,
) -> i32 {
    let mut s = pipeline::Session::new();
    let mut opts = options(c);
    opts.cycle_ms = cycle_ms;
    let compiled = s.compile(&c.inputs, &opts);
    let pmac = compiled.as_ref().and_then(|(l, _)| pmac_text(c, l, &mut s));
    let code = finish(s, format);
    let Some((lowered, program)) = compiled else {
        return code;
    };
    if let Err(code) = write_pmac(c, pmac, code, format) {
        return code;
    }
    run.cycle_ms = lowered.cycle_ms;
    if (plot.is_some() || pvt.is_some()) && !run.watch.is_empty() {
        let signals: &[&str] = if pvt.is_some() {
            &["position", "velocity", "acceleration"]
        } else {
            &["position", "velocity"]
        };
        for a in &lowered.axes.axes {
            for sig in signals {
                let col = format!("axis.{}.{sig}", a.name);
                if !run.watch.iter().any(|w| w.eq_ignore_ascii_case(&col)) {
                    run.watch.push(col);
                }
            }
        }
    }
    let mut extra = Vec::new();
    if let Err(code) = add_staticlib(&program, &mut extra, format) {
        return code;
    }
    let work = match tempfile::Builder::new().prefix("ladderc-run-").tempdir() {
        Ok(w) => w,
        Err(e) => {
            return io_error(
                format!("cannot create a build directory: {e}"),
                "check TMPDIR",
                format,
            )
        }
    };
    for (name, bytes) in &extra {
        if let Err(e) = std::fs::write(work.path().join(name), bytes) {
            return io_error(
                format!("cannot write the build directory: {e}"),
                "check TMPDIR",
                format,
            );
        }
    }
    let mut bopts = c_backend::BuildOptions::default();
    if sanitize {
        bopts.extra_flags = vec![
            "-fsanitize=address,undefined".into(),
            "-fno-sanitize-recover=all".into(),
            "-g".into(),
        ];
    }
    let exe = match c_backend::build_with(&program, work.path(), &bopts) {
        Ok(e) => e,
        Err(e) => {
            return io_error(
                format!("building the generated C failed: {e}"),
                "this is a bug in ladderc if the C compiler works; please report it",
                format,
            )
        }
    };
    // The trace is written beside its destination and moved into place only when the run succeeded.
    let final_trace = run.trace.clone();
    if let Some(t) = &final_trace {
        run.trace = Some(pipeline::staging_path(t));
    }
    let out = match c_backend::run(&exe, &run) {
        Ok(o) => o,
        Err(e) => {
            return io_error(
                format!("running the program failed: {e}"),
                "check the stimulus and trace paths",
                format,
            )
        }
    };
    print!("{}", out.stdout);
    eprint!("{}", out.stderr);
    if let (true, Some(svg)) = (out.success(), &plot) {
        let text = match &run.trace {
            Some(t) => std::fs::read_to_string(t).unwrap_or_default(),
            None => out.stdout.clone(),
        };
        if let Err(e) = crate::plot::svg(&text, svg) {
            return io_error(
                format!("cannot plot into {}: {e}", svg.display()),
                "the program needs configured axes (--axes) for a plot",
                format,
            );
        }
    }
    if let (true, Some((path, segment_ms))) = (out.success(), &pvt) {
        let text = match &run.trace {
            Some(t) => std::fs::read_to_string(t).unwrap_or_default(),
            None => out.stdout.clone(),
        };
        let dialect = match c.pmac_dialect.parse() {
            Ok(d) => d,
            Err(e) => {
                let d = Diagnostic::error(diagnostics::code::E9002, format!("--pmac-dialect: {e}"))
                    .with_hint("use turbo or power");
                emit(&SourceMap::new(), &[d], format);
                if let Some(tmp) = &run.trace {
                    let _ = std::fs::remove_file(tmp);
                }
                return EXIT_DIAGNOSTICS;
            }
        };
        if let Err(d) = crate::pmac_out::write_pvt(
            &text,
            &lowered.axes,
            lowered.cycle_ms,
            dialect,
            *segment_ms,
            path,
        ) {
            emit(&SourceMap::new(), &[*d], format);
            if let Some(tmp) = &run.trace {
                let _ = std::fs::remove_file(tmp);
            }
            return EXIT_DIAGNOSTICS;
        }
    }
    match (out.success(), &final_trace, &run.trace) {
        (true, Some(dst), Some(tmp)) => {
            if let Err(e) = std::fs::rename(tmp, dst) {
                let _ = std::fs::remove_file(tmp);
                return io_error(
                    format!("cannot write {}: {e}", dst.display()),
                    "check that the directory can be written",
                    format,
                );
            }
            EXIT_OK
        }
        (true, _, _) => EXIT_OK,
        (false, _, tmp) => {
            if let Some(tmp) = tmp {
                let _ = std::fs::remove_file(tmp);
            }
            EXIT_DIAGNOSTICS
        }
    }
}

fn motion_plan(file: &std::path::Path) -> i32 {
    let text = match std::fs::read_to_string(file) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("error[E9001]: cannot read {}: {e}", file.display());
            return EXIT_USAGE;
        }
    };
    match motion_lib::profile::plan_jsonl(&text) {
        Ok(out) => {
            print!("{out}");
            EXIT_OK
        }
        Err(e) => {
            eprintln!("{}: error[E9003]: {e}", file.display());
            EXIT_DIAGNOSTICS
        }
    }
}

fn explain(code: Option<&str>) -> i32 {
    match code {
        None => {
            for c in diagnostics::all_codes() {
                println!("{}  {}", c.code, c.title);
            }
            EXIT_OK
        }
        Some(code) => {
            match diagnostics::explain(code) {
                Some(text) => {
                    print!("{text}");
                    EXIT_OK
                }
                None => {
                    eprintln!("error: unknown diagnostic code `{code}` (run `ladderc explain` for the list)");
                    EXIT_USAGE
                }
            }
        }
    }
}

/// Prints diagnostics in the chosen format on stderr.
pub fn emit(map: &SourceMap, diags: &[Diagnostic], format: Format) {
    eprint!("{}", render(map, diags, format.into()));
}
