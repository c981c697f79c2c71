//! Argument parsing (clap) and dispatch to the library crates.

use clap::{Parser, Subcommand, ValueEnum};
use diagnostics::{render, Diagnostic, MessageFormat, SourceMap};
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

#[derive(Subcommand, Debug)]
pub enum Command {
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
    },
    /// Interactive breakpoint debugger (commands from standard input; `help` lists them).
    Debug { script: PathBuf },
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
    match cli.command {
        Command::Explain { code } => explain(code.as_deref()),
        Command::Drive(cmd) => drive(cmd, cli.message_format.into()),
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
        } => cli::run(
            &cli::RunArgs {
                script,
                cycles,
                trace,
                cycle_ms,
                inputs,
                format,
            },
            &mut out,
            &mut err,
        ),
        DriveCommand::Debug { script } => {
            let stdin = std::io::stdin();
            cli::debug(
                &cli::DebugArgs { script, format },
                &mut stdin.lock(),
                &mut out,
                &mut err,
            )
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
#[allow(dead_code)]
pub fn emit(map: &SourceMap, diags: &[Diagnostic], format: Format) {
    eprint!("{}", render(map, diags, format.into()));
}
