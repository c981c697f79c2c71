//! Argument parsing (clap) and dispatch to the library crates.
//!
//! Input: the command line. Output: the commands' results on standard output, diagnostics (and, for `check`,
//! `build` and `run`, the final summary) on standard error, and the exit code: 0 success, 1 diagnostics or a
//! failed run, 2 usage and I/O errors (a usage error is diagnostic E9200, in JSON under
//! `--message-format json`). Invariant: a closed standard output ends the command quietly ([`crate::stdio`]).

use crate::project::{CheckedProject, Failed, GeneratedProject, Project};
use crate::{output, pipeline, stdio, summary};
use clap::{Parser, Subcommand, ValueEnum};
use diagnostics::{render, Diagnostic, MessageFormat, Severity, SourceMap};
use param_passing::lower::Strategy;
use std::path::PathBuf;

/// The command line.
#[derive(Parser, Debug)]
#[command(
    name = "ladderc",
    version,
    about = "IEC 61131-3 ladder (PLCopen XML) and IL to C, with PLCopen motion",
    after_help = EXIT_CODES_HELP
)]
pub struct Cli {
    /// How diagnostics are printed on stderr.
    #[arg(long, value_enum, default_value_t = Format::Human, global = true)]
    pub message_format: Format,
    /// At most N diagnostics per file (0: all); by default 50 in the human and short formats, 1000 in
    /// JSON lines (whose summary record counts them all).
    #[arg(long, value_name = "N", global = true)]
    pub max_diagnostics: Option<usize>,
    /// The command.
    #[command(subcommand)]
    pub command: Command,
}

/// The exit codes, shown by `--help`.
pub const EXIT_CODES_HELP: &str = "Exit codes:\n  0  success\n  1  diagnostics (errors in the sources), or the program run failed\n  2  usage error (E9200) or I/O error (a file that cannot be read or written)";

/// `--message-format`.
#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
pub enum Format {
    /// Source excerpts with labels, hints and notes.
    Human,
    /// One line per diagnostic: `file:line:col: error[CODE]: message` (IDE problem matchers).
    Short,
    /// JSON lines (schema `ladderc-diagnostic/1`), then a summary record.
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

/// What a program is made of: the sources and every file that changes how they compile. Shared by
/// `check`, `build` and `run`, so that `check` checks exactly what `build` builds.
#[derive(clap::Args, Debug, Clone)]
pub struct ProjectArgs {
    /// Input files: IL (`.il`), Structured Text (`.st`), PLCopen TC6 XML projects (`.xml`), TwinCAT 3
    /// objects (`.TcPOU`, `.TcDUT`, `.TcGVL`, `.TcIO`, `.TcTTO`) and projects (`.plcproj`, or a
    /// folder holding one); a Beremiz project folder; other names by their content; `-` reads
    /// standard input.
    #[arg(required = true)]
    pub inputs: Vec<PathBuf>,
    /// Read every input in this language, whatever its name.
    #[arg(long, value_enum)]
    pub lang: Option<LangArg>,
    /// Target profile (memory model): a JSON file, or a built-in name: `openplc` (OpenPLC's areas,
    /// one image per size: `%QX0.0` apart from `%QW0`) or `default`; the default profile when absent.
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
    /// A user library given as its TwinCAT source project (`.plcproj`, or a folder holding one),
    /// for the library references of the inputs' projects (`Struckig.Otg`); repeatable.
    #[arg(long = "lib", value_name = "PLCPROJ")]
    pub libraries: Vec<PathBuf>,
}

/// The arguments of `build` and `run`: the project and the PMAC output.
#[derive(clap::Args, Debug, Clone)]
pub struct CompileArgs {
    /// The project.
    #[command(flatten)]
    pub project: ProjectArgs,
    /// Also write a PMAC motion program of the program's constant MC_MoveAbsolute/MC_MoveRelative moves.
    #[arg(long)]
    pub pmac: Option<PathBuf>,
    /// PMAC dialect of `--pmac`: `turbo` or `power`.
    #[arg(long, default_value = "turbo")]
    pub pmac_dialect: String,
}

/// `--lang`.
#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
pub enum LangArg {
    /// Instruction list.
    Il,
    /// Structured Text (POU bodies may be IL, detected per POU).
    St,
    /// PLCopen TC6 XML.
    Xml,
}

impl From<LangArg> for pipeline::Lang {
    fn from(l: LangArg) -> Self {
        match l {
            LangArg::Il => pipeline::Lang::Il,
            LangArg::St => pipeline::Lang::St,
            LangArg::Xml => pipeline::Lang::Xml,
        }
    }
}

/// `--strategy`.
#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
pub enum StrategyArg {
    /// IL-instruction method: TM transfers + one FUNC of a static-library function.
    Il,
    /// Parameter-template method: one FUNC of a function synthesised from the template.
    Template,
    /// Per block: IL when it fits the TM area and is called at 3 or more sites, template otherwise.
    Auto,
}

/// `build --emit`.
#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
pub enum Emit {
    /// The C project (default): written to the output directory.
    C,
    /// The lowered IL, printed on standard output.
    Il,
}

/// `build --report`.
#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
pub enum ReportFormat {
    /// One JSON object with a `blocks` array.
    Json,
}

/// The commands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Check sources: every check that `build` runs (parsing, semantics, block calls, the target
    /// profile, C generation), in memory; writes nothing.
    Check {
        /// The project.
        #[command(flatten)]
        project: ProjectArgs,
    },
    /// Compile to a C project (sources, header, runtime, Makefile) in a directory.
    Build {
        /// The project and the PMAC output.
        #[command(flatten)]
        compile: CompileArgs,
        /// Output directory: ladderc writes only its own files there (see `.ladderc-manifest`).
        #[arg(short = 'o', long = "output")]
        output: Option<PathBuf>,
        /// Also write a make-syntax depfile: every output depends on every input read.
        #[arg(long)]
        depfile: Option<PathBuf>,
        /// What to produce: the C project (`c`, into `-o DIR`) or the lowered IL on standard output (`il`).
        #[arg(long, value_enum, default_value_t = Emit::C)]
        emit: Emit,
        /// Print a report on standard output: per PLCopen block type its method, calls, TM bytes,
        /// IL instructions and generated C bytes (paper A's comparison).
        #[arg(long, value_enum)]
        report: Option<ReportFormat>,
    },
    /// Build with the system C compiler and run scan cycles.
    Run {
        /// The project and the PMAC output.
        #[command(flatten)]
        compile: CompileArgs,
        /// Number of scan cycles.
        #[arg(long, default_value_t = 10)]
        cycles: u64,
        /// Cycle time in milliseconds (default: the axis configuration's `cycle_ms`, else the
        /// TwinCAT tasks' cycle time, else 10).
        #[arg(long)]
        cycle_ms: Option<f64>,
        /// CSV rows `cycle,variable,value`, applied before that cycle.
        #[arg(long)]
        stimulus: Option<PathBuf>,
        /// CSV trace: `cycle,time_ms,VAR...`, one row per cycle after the cycle; `-` (or no
        /// `--trace`) writes it to standard output.
        #[arg(long)]
        trace: Option<PathBuf>,
        /// Variables to trace (`main.count`, `inst.count`, `%QX0.1`, `main.grid[1,0]`),
        /// comma-separated (a subscript list's commas, and a name in double quotes, stay in one name).
        #[arg(long)]
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
    /// Serve the language server protocol on standard input/output (for editors: diagnostics, hover,
    /// go to definition, document symbols, completion of IL, ST and PLCopen XML).
    Lsp,
    /// Print the explanation of a diagnostic code (e.g. `ladderc explain E1001`), or list every code.
    Explain {
        /// The code; omit it to list all codes with their titles.
        code: Option<String>,
    },
}

/// `ladderc motion ...`.
#[derive(Subcommand, Debug)]
pub enum MotionCommand {
    /// Plan jerk-limited profiles for problems in the oracle's JSON-lines format; prints each problem back
    /// with its time-optimal `duration` and `phases` ([duration, jerk] pairs).
    Plan {
        /// JSON lines, one problem each (the ruckig oracle's format).
        file: PathBuf,
    },
}

/// `ladderc drive ...`.
#[derive(Subcommand, Debug)]
pub enum DriveCommand {
    /// Compile a drive script into its binary image (Motion and Event pools).
    Build {
        /// The drive script source.
        script: PathBuf,
        /// The image file to write.
        #[arg(short = 'o', long = "output")]
        output: PathBuf,
    },
    /// Run a script (or an image) on the simulated drive.
    Run {
        /// A drive script source, or an image written by `drive build`.
        script: PathBuf,
        /// Main-loop cycles to run.
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
        /// The drive script source.
        script: PathBuf,
        /// The drive: a motion-lib axis or the simple simulation.
        #[arg(long, value_enum, default_value_t = DriveArg::MotionLib)]
        drive: DriveArg,
    },
}

/// `drive --drive`.
#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
pub enum DriveArg {
    /// A motion-lib axis: jerk-limited profiles through the PLCopen blocks.
    MotionLib,
    /// The simple simulated drive.
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

/// Exit code: success.
pub const EXIT_OK: i32 = 0;
/// Exit code: diagnostics with errors, or a failed program run.
pub const EXIT_DIAGNOSTICS: i32 = 1;
/// Exit code: a usage or I/O error.
pub const EXIT_USAGE: i32 = 2;

/// Parses the process's arguments, runs the command and prints; returns the exit code.
pub fn main() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => return usage_error(&e, requested_format(std::env::args_os())),
    };
    if let Some(n) = cli.max_diagnostics {
        diagnostics::set_max_per_file(n);
    }
    let format = cli.message_format;
    let pipeline_command = matches!(
        cli.command,
        Command::Check { .. } | Command::Build { .. } | Command::Run { .. }
    );
    let code = dispatch(cli);
    if pipeline_command {
        summary::finish(format);
    }
    code
}

/// `--message-format` as written on a command line that clap rejected (human when absent or unreadable).
pub fn requested_format(args: impl IntoIterator<Item = std::ffi::OsString>) -> Format {
    let args: Vec<String> = args
        .into_iter()
        .map(|a| a.to_string_lossy().into_owned())
        .collect();
    let mut format = Format::Human;
    for (i, a) in args.iter().enumerate() {
        let value = match a.strip_prefix("--message-format") {
            Some("") => args.get(i + 1).map(String::as_str),
            Some(v) => v.strip_prefix('='),
            None => None,
        };
        if let Some(v) = value {
            if let Ok(f) = Format::from_str(v, true) {
                format = f;
            }
        }
    }
    format
}

/// Prints a clap error: help and version on standard output (exit 0); a usage error as E9200 under
/// `--message-format json` (with the summary record), clap's own text otherwise (exit 2).
fn usage_error(e: &clap::Error, format: Format) -> i32 {
    use clap::error::ErrorKind;
    if !e.use_stderr() {
        let _ = stdio::out(&e.render().to_string());
        return EXIT_OK;
    }
    if format != Format::Json {
        stdio::err(&e.render().to_string());
        return EXIT_USAGE;
    }
    let text = e.render().to_string();
    let mut lines = text.lines().filter(|l| !l.trim().is_empty());
    let first = lines.next().unwrap_or("invalid command line");
    let message = first.strip_prefix("error: ").unwrap_or(first).to_string();
    let mut d = Diagnostic::error(diagnostics::code::E9200, message).with_hint(
        if e.kind() == ErrorKind::MissingRequiredArgument {
            "add the missing argument; `ladderc help` lists every command and option"
        } else {
            "`ladderc help` (or `ladderc SUBCOMMAND --help`) lists every command and option"
        },
    );
    for l in lines {
        let l = l.trim();
        if !l.starts_with("For more information") {
            d = d.with_note(l.to_string());
        }
    }
    emit(&SourceMap::new(), &[d], format);
    summary::finish(format);
    EXIT_USAGE
}

fn dispatch(cli: Cli) -> i32 {
    match cli.command {
        Command::Lsp => crate::lsp::run(),
        Command::Explain { code } => explain(code.as_deref()),
        Command::Drive(cmd) => drive(cmd, cli.message_format.into()),
        Command::Motion(MotionCommand::Plan { file }) => motion_plan(&file),
        Command::Check { project } => check(&project, cli.message_format),
        Command::Build {
            compile,
            output,
            depfile,
            emit,
            report,
        } => build(
            &compile,
            (output.as_deref(), depfile.as_deref()),
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
                watch: watch
                    .iter()
                    .flat_map(|w| c_backend::watch_names(w))
                    .collect(),
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

fn options(c: &ProjectArgs) -> pipeline::Options {
    pipeline::Options {
        axes: c.axes.clone(),
        cycle_ms: None,
        lang: c.lang.map(Into::into),
        profile: c.profile.clone(),
        strategy: match c.strategy {
            StrategyArg::Il => Strategy::Il,
            StrategyArg::Template => Strategy::Template,
            StrategyArg::Auto => Strategy::Auto,
        },
        templates: c.templates.clone(),
        compile_templates: true,
        libraries: c.libraries.clone(),
    }
}

/// The project of `c`: its inputs read from disk, with the options of the command line.
fn project(c: &ProjectArgs, opts: pipeline::Options) -> Project {
    Project::from_paths(c.inputs.iter().cloned(), opts)
}

/// Prints a project's diagnostics (sorted, with `extra` ones); the exit code for them: 0 without errors, 2
/// when a file could not be read or written (an I/O error), 1 otherwise.
fn finish(map: &SourceMap, diags: &[Diagnostic], extra: Vec<Diagnostic>, format: Format) -> i32 {
    let mut all = diagnostics::Diagnostics::new();
    all.extend(diags.iter().cloned());
    all.extend(extra);
    let diags = all.into_sorted();
    emit(map, &diags, format);
    exit_code(&diags)
}

/// Prints the diagnostics of a failed stage; the exit code for them.
fn finish_failed(f: &Failed, format: Format) -> i32 {
    finish(&f.sources, &f.diagnostics, Vec::new(), format)
}

/// The codes of I/O errors (a file that cannot be read or written; E7005: a PMAC file or connection):
/// they exit with 2.
const IO_CODES: [diagnostics::Code; 3] = [
    diagnostics::code::E9001,
    diagnostics::code::E9002,
    diagnostics::code::E7005,
];

fn exit_code(diags: &[Diagnostic]) -> i32 {
    let errors = diags.iter().filter(|d| d.severity == Severity::Error);
    let mut code = EXIT_OK;
    for d in errors {
        if IO_CODES.contains(&d.code) {
            return EXIT_USAGE;
        }
        code = EXIT_DIAGNOSTICS;
    }
    code
}

fn io_error(message: String, hint: &str, format: Format) -> i32 {
    let d = Diagnostic::error(diagnostics::code::E9002, message).with_hint(hint);
    emit(&SourceMap::new(), &[d], format);
    EXIT_USAGE
}

/// `check`: the whole pipeline to C in memory (the same checks as `build`), nothing written.
fn check(p: &ProjectArgs, format: Format) -> i32 {
    match project(p, options(p)).compile() {
        Ok(g) => finish(g.sources(), g.diagnostics(), Vec::new(), format),
        Err(f) => finish_failed(&f, format),
    }
}

fn build(
    c: &CompileArgs,
    (output, depfile): (Option<&std::path::Path>, Option<&std::path::Path>),
    emit_kind: Emit,
    report: Option<ReportFormat>,
    format: Format,
) -> i32 {
    match emit_kind {
        Emit::Il if report.is_some() => usage(
            "`--report` describes a C build: use it with `-o DIR`, not `--emit il`",
            format,
        ),
        Emit::Il if depfile.is_some() => usage(
            "`--depfile` describes a C build: use it with `-o DIR`, not `--emit il`",
            format,
        ),
        Emit::Il => {
            let lowered = match project(&c.project, options(&c.project))
                .check()
                .and_then(CheckedProject::lower)
            {
                Ok(l) => l,
                Err(f) => return finish_failed(&f, format),
            };
            let code = finish(lowered.sources(), lowered.diagnostics(), Vec::new(), format);
            for u in lowered.units() {
                if let Err(e) = stdio::out(&il_frontend::print::unit(u)) {
                    return stdout_error(e, format);
                }
            }
            code
        }
        Emit::C => {
            let Some(dir) = output else {
                return usage("`build` needs `-o DIR` (or `--emit il`)", format);
            };
            let mut g = match project(&c.project, options(&c.project)).compile() {
                Ok(g) => g,
                Err(f) => return finish_failed(&f, format),
            };
            let mut extra = Vec::new();
            let pmac = pmac_text(c, &mut g, &mut extra);
            let code = finish(g.sources(), g.diagnostics(), extra, format);
            let program = g.program();
            if let Err(code) = write_pmac(c, pmac, code, format) {
                return code;
            }
            let mut extra = Vec::new();
            if let Err(code) = add_staticlib(program, &mut extra, format) {
                return code;
            }
            if report == Some(ReportFormat::Json) {
                let text = g.report_measured(&extra) + "\n";
                if let Err(e) = stdio::out(&text) {
                    return stdout_error(e, format);
                }
            }
            // The C texts are moved, not copied, into the files to write.
            let mut files: Vec<(String, Vec<u8>)> = g
                .take_files()
                .into_iter()
                .map(|(p, c)| (p, c.into_bytes()))
                .collect();
            files.extend(extra);
            if let Err(d) = output::write_build(
                dir,
                &files,
                depfile,
                &crate::depfile::inputs(&c.project.inputs, &options(&c.project)),
            ) {
                emit(&SourceMap::new(), &[*d], format);
                return EXIT_USAGE;
            }
            summary::wrote(dir);
            // The process ends now: the syntax trees, the semantic model and the file texts (a few
            // hundred thousand allocations for a large program) are left to the operating system
            // instead of being freed one by one.
            std::mem::forget((g, files));
            code
        }
    }
}

/// The PMAC program of `--pmac` (its diagnostics into the project; a bad dialect into `extra`).
fn pmac_text(
    c: &CompileArgs,
    g: &mut GeneratedProject,
    extra: &mut Vec<Diagnostic>,
) -> Option<String> {
    c.pmac.as_ref()?;
    let dialect = match c.pmac_dialect.parse() {
        Ok(d) => d,
        Err(e) => {
            extra.push(
                Diagnostic::error(diagnostics::code::E9002, format!("--pmac-dialect: {e}"))
                    .with_hint("use turbo or power"),
            );
            return None;
        }
    };
    g.pmac_program(dialect)
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
    })?;
    summary::wrote(path);
    Ok(())
}

/// A usage error found after parsing (E9200, exit 2).
fn usage(message: &str, format: Format) -> i32 {
    let d = Diagnostic::error(diagnostics::code::E9200, message)
        .with_hint("`ladderc help` lists every command and option");
    emit(&SourceMap::new(), &[d], format);
    EXIT_USAGE
}

/// Standard output failed for another reason than a closed pipe (a closed pipe is no error).
fn stdout_error(e: std::io::Error, format: Format) -> i32 {
    io_error(
        format!("cannot write to standard output: {e}"),
        "check where standard output is redirected (a full disk?)",
        format,
    )
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
    match crate::motion_link::library() {
        Ok(bytes) => {
            files.push((lib.to_string(), bytes.into_owned()));
            Ok(())
        }
        Err(d) => {
            emit(&SourceMap::new(), &[*d], format);
            Err(EXIT_USAGE)
        }
    }
}

/// W1441 at the first POU when the inputs declare no PROGRAM and no CONFIGURATION: the cycles
/// `run` runs do nothing. Inputs that declare no POU at all (a placeholder holding only comments,
/// only types or only global variables) get it too, at the start of the first input file read.
fn nothing_to_run(
    lowered: &pipeline::Lowered,
    sources: &SourceMap,
    inputs: &[PathBuf],
) -> Option<Diagnostic> {
    let model = lowered.model.as_ref()?;
    if !model.configurations.is_empty()
        || model
            .pous
            .iter()
            .any(|p| p.kind == il_frontend::ast::PouKind::Program)
    {
        return None;
    }
    let (at, what, label) = match model.pous.first() {
        Some(first) => (
            first.span,
            format!(
                "{} function block(s) and function(s), which run only when a program calls them",
                model.pous.len()
            ),
            "a POU no program calls",
        ),
        None => {
            let (file, _) = sources
                .files()
                .find(|(_, f)| inputs.iter().any(|p| p.display().to_string() == f.name))?;
            (
                diagnostics::Span::new(file, 0, 0),
                "no POU at all".to_string(),
                "this input declares no POU",
            )
        }
    };
    Some(
        Diagnostic::warning(
            diagnostics::code::W1441,
            format!("nothing to run: the inputs declare no PROGRAM ({what})"),
        )
        .at(at)
        .with_primary_label(label)
        .with_hint("give the file of the program that uses them as well, or write a PROGRAM that calls them"),
    )
}

/// W1457, once per task with programs: its INTERVAL is longer than the scan cycle, so its
/// programs run only in the cycles in which the interval has elapsed (one of every k), and leave
/// their variables unchanged in the others; `run` would otherwise say nothing of it.
fn slower_tasks(lowered: &pipeline::Lowered) -> Vec<Diagnostic> {
    let Some(model) = lowered.model.as_ref() else {
        return Vec::new();
    };
    let cycle_ns = lowered.cycle_ms * 1e6;
    let mut out = Vec::new();
    for r in model.configurations.iter().flat_map(|c| c.resources.iter()) {
        for (k, t) in r.tasks.iter().enumerate() {
            let Some(iv) = t.interval_ns.filter(|_| t.single.is_none()) else {
                continue;
            };
            let ratio = iv as f64 / cycle_ns;
            if ratio <= 1.0 + 1e-9 || !r.programs.iter().any(|p| p.task == Some(k)) {
                continue;
            }
            let every = if (ratio - ratio.round()).abs() < 1e-9 {
                format!("one cycle of every {}", ratio.round())
            } else {
                format!("about one cycle of every {ratio:.2}")
            };
            let interval_ms = iv as f64 / 1e6;
            let ms = |v: f64| format!("{}", (v * 1e6).round() / 1e6);
            out.push(
                Diagnostic::new(
                    diagnostics::code::W1457,
                    diagnostics::Severity::Note,
                    format!(
                        "task `{}` has INTERVAL {} ms, longer than the scan cycle of {} ms: its programs run in {every}, and keep their values in the others",
                        t.name,
                        ms(interval_ms),
                        ms(lowered.cycle_ms)
                    ),
                )
                .at(t.span)
                .with_primary_label("runs when its interval has elapsed")
                .with_hint(format!(
                    "pass --cycle-ms {} to scan at the task's interval (`ladderc explain W1457`)",
                    ms(interval_ms)
                )),
            );
        }
    }
    out
}

fn run_program(
    c: &CompileArgs,
    cycle_ms: Option<f64>,
    mut run: c_backend::RunOptions,
    sanitize: bool,
    (plot, pvt): (Option<PathBuf>, Option<(PathBuf, f64)>),
    format: Format,
) -> i32 {
    let mut opts = options(&c.project);
    opts.cycle_ms = cycle_ms;
    if let Some(stimulus) = &run.stimulus {
        if let Err(e) = std::fs::File::open(stimulus) {
            let d = Diagnostic::error(
                diagnostics::code::E9001,
                format!("cannot read {}: {e}", stimulus.display()),
            )
            .with_hint("check the --stimulus path and its permissions");
            emit(&SourceMap::new(), &[d], format);
            return EXIT_USAGE;
        }
    }
    let mut g = match project(&c.project, opts).compile() {
        Ok(g) => g,
        Err(f) => return finish_failed(&f, format),
    };
    let mut extra = Vec::new();
    let pmac = pmac_text(c, &mut g, &mut extra);
    extra.extend(nothing_to_run(g.lowered(), g.sources(), &c.project.inputs));
    extra.extend(slower_tasks(g.lowered()));
    let code = finish(g.sources(), g.diagnostics(), extra, format);
    let (lowered, program) = (g.lowered(), g.program());
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
        for g in &lowered.axes.groups {
            for sig in ["junction_requested", "junction_reached"] {
                let col = format!("group.{}.{sig}", g.name);
                if !run.watch.iter().any(|w| w.eq_ignore_ascii_case(&col)) {
                    run.watch.push(col);
                }
            }
        }
    }
    let mut extra = Vec::new();
    if let Err(code) = add_staticlib(program, &mut extra, format) {
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
    bopts.extra_flags.push(crate::loop_guard::c_flag());
    let exe = match c_backend::build_with(program, work.path(), &bopts) {
        Ok(e) => e,
        Err(e) => {
            return io_error(
                format!("building the generated C failed: {e}"),
                "this is a bug in ladderc if the C compiler works; please report it",
                format,
            )
        }
    };
    // `--trace -`: the trace goes to standard output, as it does without `--trace`.
    if run.trace.as_deref() == Some(std::path::Path::new("-")) {
        run.trace = None;
    }
    // The trace is written beside its destination and moved into place only when the run succeeded.
    let final_trace = run.trace.clone();
    if let Some(t) = &final_trace {
        let staging = pipeline::staging_path(t);
        // Created here so that an unwritable destination is an I/O error (exit 2) before the run.
        if let Err(e) = std::fs::File::create(&staging) {
            return io_error(
                format!("cannot write {}: {e}", t.display()),
                "check that the trace's directory exists and can be written",
                format,
            );
        }
        run.trace = Some(staging);
    }
    let timed = match crate::progress::run(&exe, &run, work.path()) {
        Ok(o) => o,
        Err(e) => {
            return io_error(
                format!("running the program failed: {e}"),
                "check the stimulus and trace paths",
                format,
            )
        }
    };
    let mut out = timed.output;
    let stuck = crate::loop_guard::take(&mut out.stderr, g.sources());
    if out.success() {
        summary::set_run(summary::run_figures(run.cycles, run.cycle_ms, timed.wall));
    }
    // A closed standard output (`| head`) is no reason to skip the files asked for.
    let stdout_failed = stdio::out(&out.stdout).err();
    match &stuck {
        // the loop guard's E1061 says why the run failed: no E9201 beside it
        Some(d) => {
            if !out.stderr.trim().is_empty() {
                program_stderr(&out, format);
            }
            emit(g.sources(), std::slice::from_ref(d), format);
        }
        None => program_stderr(&out, format),
    }
    // The trace, read once for the junction summary, the plot and the PVT program.
    let text = match (out.success(), &run.trace) {
        (false, _) => String::new(),
        (true, Some(t)) => std::fs::read_to_string(t).unwrap_or_default(),
        (true, None) => out.stdout.clone(),
    };
    if out.success() {
        let unit = lowered
            .axes
            .axes
            .first()
            .and_then(|a| a.unit.clone())
            .unwrap_or_else(|| "unit".into());
        for line in junction_summary(&text, &unit) {
            stdio::err(&format!("{line}\n"));
        }
        for line in stop_summary(&text, &unit) {
            stdio::err(&format!("{line}\n"));
        }
    }
    if let (true, Some(svg)) = (out.success(), &plot) {
        let unit = lowered
            .axes
            .axes
            .first()
            .and_then(|a| a.unit.clone())
            .unwrap_or_else(|| "unit".into());
        if let Err(e) = crate::plot::svg(&text, svg, &unit) {
            return io_error(
                format!("cannot plot into {}: {e}", svg.display()),
                "the program needs configured axes (--axes) for a plot",
                format,
            );
        }
        summary::wrote(svg);
    }
    if let (true, Some((path, segment_ms))) = (out.success(), &pvt) {
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
            let code = exit_code(std::slice::from_ref(&*d));
            emit(&SourceMap::new(), &[*d], format);
            if let Some(tmp) = &run.trace {
                let _ = std::fs::remove_file(tmp);
            }
            return code;
        }
        summary::wrote(path);
    }
    if let Some(e) = stdout_failed {
        if let Some(tmp) = &run.trace {
            let _ = std::fs::remove_file(tmp);
        }
        return stdout_error(e, format);
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
            summary::wrote(dst);
            EXIT_OK
        }
        (true, _, _) => EXIT_OK,
        (false, _, tmp) => {
            if let Some(tmp) = tmp {
                let _ = std::fs::remove_file(tmp);
            }
            // `--watch P1.n` of instances `P1` in two configurations: the harness refused the
            // ambiguous name (listing the qualified ones), a usage error
            if out
                .stderr
                .lines()
                .any(|l| l.starts_with("error: --watch: `") && l.contains("` is ambiguous: "))
            {
                return EXIT_USAGE;
            }
            EXIT_DIAGNOSTICS
        }
    }
}

/// The program's standard error: as it is, or under JSON one diagnostic per line (W9200 after a
/// successful run, E9201 after a failed one), so that every line stays a JSON record.
fn program_stderr(out: &c_backend::RunOutput, format: Format) {
    if format != Format::Json {
        stdio::err(&out.stderr);
        return;
    }
    let diags: Vec<Diagnostic> = out
        .stderr
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            if out.success() {
                Diagnostic::warning(diagnostics::code::W9200, l.trim())
            } else {
                Diagnostic::error(diagnostics::code::E9201, l.trim())
            }
        })
        .collect();
    let failed_silently = !out.success() && diags.is_empty();
    emit(&SourceMap::new(), &diags, format);
    if failed_silently {
        let status = match out.status {
            Some(c) => format!("exit status {c}"),
            None => "a signal".to_string(),
        };
        let d = Diagnostic::error(
            diagnostics::code::E9201,
            format!("the program run failed ({status})"),
        );
        emit(&SourceMap::new(), &[d], format);
    }
}

/// The run summary's lines about lowered junction speeds, read from the trace's
/// `group.<name>.junction_requested|junction_reached` columns (non-zero only in the cycle the
/// path passes such a junction): the group, the block that starts there (the watched
/// `<block>.Active` column that turns TRUE in that row or the next; else the block whose `Done`
/// rises there), the cycle, the speed requested and reached. Empty when the trace has no such columns or nothing was lowered.
pub fn junction_summary(trace: &str, unit: &str) -> Vec<String> {
    let mut lines = trace.lines();
    let Some(header) = lines.next() else {
        return Vec::new();
    };
    let cols: Vec<&str> = header.split(',').collect();
    let groups: Vec<(&str, usize, Option<usize>)> = cols
        .iter()
        .enumerate()
        .filter_map(|(k, c)| {
            let group = c
                .strip_prefix("group.")?
                .strip_suffix(".junction_requested")?;
            let reached = cols
                .iter()
                .position(|x| *x == format!("group.{group}.junction_reached"));
            Some((group, k, reached))
        })
        .collect();
    if groups.is_empty() {
        return Vec::new();
    }
    let active: Vec<(usize, &str)> = cols
        .iter()
        .enumerate()
        .filter_map(|(k, c)| c.strip_suffix(".Active").map(|b| (k, b)))
        .collect();
    let done: Vec<(usize, &str)> = cols
        .iter()
        .enumerate()
        .filter_map(|(k, c)| c.strip_suffix(".Done").map(|b| (k, b)))
        .collect();
    // Only the columns read below are kept, one row after another (a full trace has many more).
    let mut kept: Vec<usize> = vec![0];
    for (_, k, reached) in &groups {
        kept.push(*k);
        kept.extend(reached);
    }
    kept.extend(active.iter().chain(&done).map(|(k, _)| *k));
    kept.sort_unstable();
    kept.dedup();
    let slot = |k: usize| kept.binary_search(&k).ok();
    let stride = kept.len();
    let mut rows: Vec<&str> = Vec::new();
    for line in lines {
        let start = rows.len();
        rows.resize(start + stride, "");
        let mut next = 0;
        for (k, field) in line.split(',').enumerate() {
            if k == kept[next] {
                rows[start + next] = field;
                next += 1;
                if next == stride {
                    break;
                }
            }
        }
    }
    let row_count = rows.len() / stride;
    let field = |r: usize, k: usize| slot(k).map(|s| rows[r * stride + s]);
    let num = |r: usize, k: usize| field(r, k).and_then(|x| x.parse::<f64>().ok());
    let is_true = |r: usize, k: usize| field(r, k).is_some_and(|x| x == "1" || x == "TRUE");
    let rises = |r: usize, k: usize| {
        (r..(r + 2).min(row_count)).any(|x| is_true(x, k) && (x == 0 || !is_true(x - 1, k)))
    };
    let mut out = Vec::new();
    for (group, k, reached_col) in groups {
        for r in 0..row_count {
            let Some(req) = num(r, k).filter(|v| *v > 0.0) else {
                continue;
            };
            let reached = reached_col.and_then(|j| num(r, j)).unwrap_or(0.0);
            let block = active
                .iter()
                .find(|(j, _)| rises(r, *j))
                .map(|(_, b)| format!(" before {b}"))
                .or_else(|| {
                    // without Active columns: the block whose Done rises there ends at it
                    done.iter()
                        .find(|(j, _)| rises(r, *j))
                        .map(|(_, b)| format!(" after {b}"))
                })
                .unwrap_or_default();
            let cycle = field(r, 0).unwrap_or("?");
            out.push(format!(
                "motion: group {group}: junction{block} at cycle {cycle}: requested {req} {unit}/s, reached {reached:.6} {unit}/s (lowered to keep the axis limits: a junction, or an arc's path speed; motion-lib README, \"Junction speeds\")"
            ));
        }
    }
    out
}

/// The run summary's lines about MC_Stop commands capped to the axis limits, read from the trace's
/// `axis.<name>.stop_decel_requested|stop_decel_reached|stop_jerk_requested|stop_jerk_reached` columns
/// (non-zero only in the stop's first cycle): the axis, the MC_Stop block (the watched `<block>.Busy`
/// column that rises in that row or the one before), the cycle, the deceleration and jerk requested and
/// reached. Empty when the trace has no such columns or no stop was capped.
pub fn stop_summary(trace: &str, unit: &str) -> Vec<String> {
    let mut lines = trace.lines();
    let Some(header) = lines.next() else {
        return Vec::new();
    };
    let cols: Vec<&str> = header.split(',').collect();
    let find = |name: String| cols.iter().position(|c| *c == name);
    let axes: Vec<(&str, [Option<usize>; 4])> = cols
        .iter()
        .filter_map(|c| {
            let axis = c
                .strip_prefix("axis.")?
                .strip_suffix(".stop_decel_requested")?;
            let k = |s: &str| find(format!("axis.{axis}.{s}"));
            Some((
                axis,
                [
                    k("stop_decel_requested"),
                    k("stop_decel_reached"),
                    k("stop_jerk_requested"),
                    k("stop_jerk_reached"),
                ],
            ))
        })
        .collect();
    if axes.is_empty() {
        return Vec::new();
    }
    let busy: Vec<(usize, &str)> = cols
        .iter()
        .enumerate()
        .filter_map(|(k, c)| c.strip_suffix(".Busy").map(|b| (k, b)))
        .collect();
    // The rows are streamed: only the columns read here are kept, and only the last three rows (a
    // full trace has a hundred and more columns and hundreds of thousands of rows).
    let mut kept: Vec<usize> = vec![0];
    kept.extend(axes.iter().flat_map(|(_, k)| k.iter().flatten().copied()));
    kept.extend(busy.iter().map(|(k, _)| *k));
    kept.sort_unstable();
    kept.dedup();
    let slot = |k: usize| kept.binary_search(&k).ok();
    let mut window: [Vec<&str>; 3] = Default::default();
    let mut per_axis: Vec<Vec<String>> = vec![Vec::new(); axes.len()];
    for (r, line) in lines.enumerate() {
        window.rotate_left(1);
        let row = &mut window[2];
        row.clear();
        row.resize(kept.len(), "");
        let mut next = 0;
        for (k, field) in line.split(',').enumerate() {
            if k == kept[next] {
                row[next] = field;
                next += 1;
                if next == kept.len() {
                    break;
                }
            }
        }
        // `back` rows before this one (0, 1 or 2), if it exists
        let get = |back: usize, k: usize| {
            (back <= r)
                .then(|| slot(k).map(|s| window[2 - back][s]))
                .flatten()
        };
        let num = |k: Option<usize>| {
            k.and_then(|k| get(0, k))
                .and_then(|x| x.parse::<f64>().ok())
                .unwrap_or(0.0)
        };
        let is_true = |back: usize, k: usize| get(back, k).is_some_and(|x| x == "1" || x == "TRUE");
        for ((axis, k), out) in axes.iter().zip(per_axis.iter_mut()) {
            let req = num(k[0]);
            if req <= 0.0 {
                continue;
            }
            // The block's Busy rises in the scan that gave the stop: this row or the one before.
            let rises = |back: usize, j: usize| {
                back <= r && is_true(back, j) && (back == r || !is_true(back + 1, j))
            };
            let block = busy
                .iter()
                .find(|(j, _)| rises(1, *j) || rises(0, *j))
                .map(|(_, b)| format!(" {b}"))
                .unwrap_or_default();
            let cycle = get(0, 0).unwrap_or("?");
            let (jr, jg) = (num(k[2]), num(k[3]));
            let jerk = if jr == 0.0 {
                format!("jerk the axis's {jg} {unit}/s^3")
            } else {
                format!("jerk requested {jr} {unit}/s^3, reached {jg} {unit}/s^3")
            };
            out.push(format!(
                "motion: axis {axis}: MC_Stop{block} at cycle {cycle}: deceleration requested {req} {unit}/s^2, reached {} {unit}/s^2; {jerk} (capped to the axis limits; motion-lib README, \"MC_Stop\")",
                num(k[1])
            ));
        }
    }
    per_axis.concat()
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
        Ok(out) => match stdio::out(&out) {
            Ok(()) => EXIT_OK,
            Err(e) => stdout_error(e, Format::Human),
        },
        Err(e) => {
            eprintln!("{}: error[E9003]: {e}", file.display());
            EXIT_DIAGNOSTICS
        }
    }
}

fn explain(code: Option<&str>) -> i32 {
    match code {
        None => {
            let list: String = diagnostics::all_codes()
                .iter()
                .map(|c| format!("{}  {}\n", c.code, c.title))
                .collect();
            match stdio::out(&list) {
                Ok(()) => EXIT_OK,
                Err(e) => stdout_error(e, Format::Human),
            }
        }
        Some(code) => {
            match diagnostics::explain(code) {
                Some(text) => match stdio::out(text) {
                    Ok(()) => EXIT_OK,
                    Err(e) => stdout_error(e, Format::Human),
                },
                None => {
                    eprintln!("error: unknown diagnostic code `{code}` (run `ladderc explain` for the list)");
                    EXIT_USAGE
                }
            }
        }
    }
}

/// Prints diagnostics in the chosen format on stderr (and counts them for the summary). Diagnostics whose
/// span lies in a PLCopen XML file and that carry no XML context get it from the file
/// ([`ladder_compiler::locate`]).
pub fn emit(map: &SourceMap, diags: &[Diagnostic], format: Format) {
    summary::count(diags);
    let located = crate::xml_context::annotate(map, diags);
    stdio::err(&render(map, &located, format.into()));
}
