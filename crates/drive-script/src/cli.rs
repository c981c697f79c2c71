//! Library side of the `ladderc drive` subcommands: `build`, `run` and the interactive `debug`.
//!
//! Input: paths and options (the CLI's parsed arguments), a command reader for `debug`, writers for normal
//! output and for diagnostics. Output: files (image, CSV trace), text, and an exit code (0 success, 1 the
//! script or image was rejected, 2 a file could not be read or written). Invariants: every failure is
//! reported as a rendered diagnostic on `err` (E6xxx for scripts/images, E9001/E9002 for files); nothing
//! panics on bad input; the debugger reads commands until `quit` or end of input.

use crate::compiler::{compile, DebugInfo};
use crate::debugger::{Location, Phase};
use crate::drive::{CycleDrive, SimDrive};
use crate::image::{decode, encode, MAGIC};
use crate::interpreter::{CycleResult, Interpreter};
use crate::limits::*;
use crate::motion_drive::MotionLibDrive;
use crate::program::Program;
use diagnostics::{code, render, Diagnostic, MessageFormat, SourceMap};
use std::io::{BufRead, Write};
use std::path::{Path, PathBuf};

/// Exit codes.
pub const EXIT_OK: i32 = 0;
/// The script or image was rejected: E6xxx diagnostics were written to the error writer.
pub const EXIT_REJECTED: i32 = 1;
/// A file could not be read or written (E9001, E9002).
pub const EXIT_IO: i32 = 2;

/// `ladderc drive build SCRIPT -o IMAGE`.
#[derive(Debug, Clone)]
pub struct BuildArgs {
    /// The script to compile.
    pub script: PathBuf,
    /// Where the binary image is written (`-o`).
    pub output: PathBuf,
    /// How diagnostics are printed (human text or JSON lines).
    pub format: MessageFormat,
}

/// `ladderc drive run SCRIPT --cycles N [--trace FILE.csv] [--cycle-ms MS] [--inputs BITS]`.
#[derive(Debug, Clone)]
pub struct RunArgs {
    /// A script, or an image built by `build` (recognised by its magic bytes).
    pub script: PathBuf,
    /// Main-loop cycles to simulate (`--cycles N`); one interpreter slice and one drive tick each.
    pub cycles: u64,
    /// CSV trace file, one row per cycle (`--trace`); none when absent.
    pub trace: Option<PathBuf>,
    /// Simulated main-loop period (default 1 ms).
    pub cycle_ms: u32,
    /// Digital inputs of the simulated drive (bit n = DI_n).
    pub inputs: u32,
    /// How diagnostics are printed (human text or JSON lines).
    pub format: MessageFormat,
}

impl RunArgs {
    /// Arguments for `cycles` cycles of `script` with the defaults: 1 ms cycle, all inputs low, no trace,
    /// human diagnostics.
    pub fn new(script: impl Into<PathBuf>, cycles: u64) -> RunArgs {
        RunArgs {
            script: script.into(),
            cycles,
            trace: None,
            cycle_ms: 1,
            inputs: 0,
            format: MessageFormat::Human,
        }
    }
}

/// Which simulated drive `run` and `debug` use (`--drive motion-lib|sim`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DriveKind {
    /// A motion-lib axis commanded by PLCopen blocks ([`MotionLibDrive`]): jerk-limited profiles. Default.
    #[default]
    MotionLib,
    /// The crate's own trapezoidal simulation ([`SimDrive`]).
    Sim,
}

impl DriveKind {
    /// Parses the `--drive` option value: `motion-lib` (also `motionlib`, `axis`) or `sim`.
    pub fn parse(s: &str) -> Option<DriveKind> {
        match s.to_ascii_lowercase().as_str() {
            "motion-lib" | "motionlib" | "motion_lib" | "axis" => Some(DriveKind::MotionLib),
            "sim" | "simdrive" => Some(DriveKind::Sim),
            _ => None,
        }
    }

    /// A fresh drive of this kind with a `cycle_ms` main-loop period.
    pub fn make(self, cycle_ms: u32) -> Box<dyn CycleDrive> {
        match self {
            DriveKind::MotionLib => Box::new(MotionLibDrive::new(cycle_ms)),
            DriveKind::Sim => Box::new(SimDrive::new(cycle_ms)),
        }
    }
}

/// `ladderc drive debug SCRIPT`.
#[derive(Debug, Clone)]
pub struct DebugArgs {
    /// A script, or an image built by `build` (without line information then).
    pub script: PathBuf,
    /// How diagnostics of loading are printed.
    pub format: MessageFormat,
}

struct Loaded {
    program: Program,
    /// Source and line information when loaded from a script (not from an image).
    source: Option<(SourceMap, DebugInfo)>,
}

fn report(err: &mut dyn Write, map: &SourceMap, diags: &[Diagnostic], format: MessageFormat) {
    let _ = err.write_all(render(map, diags, format).as_bytes());
}

fn load(path: &Path, format: MessageFormat, err: &mut dyn Write) -> Result<Loaded, i32> {
    let bytes = match std::fs::read(path) {
        Ok(b) => b,
        Err(e) => {
            let d = Diagnostic::error(
                code::E9001,
                format!("cannot read `{}`: {e}", path.display()),
            );
            report(err, &SourceMap::new(), &[d], format);
            return Err(EXIT_IO);
        }
    };
    if bytes.starts_with(&MAGIC) {
        return match decode(&bytes) {
            Ok(program) => Ok(Loaded {
                program,
                source: None,
            }),
            Err(e) => {
                let d = e
                    .to_diagnostic()
                    .with_note(format!("in image `{}`", path.display()));
                report(err, &SourceMap::new(), &[d], format);
                Err(EXIT_REJECTED)
            }
        };
    }
    let text = match String::from_utf8(bytes) {
        Ok(t) => t,
        Err(_) => {
            let d = Diagnostic::error(
                code::E9001,
                format!("cannot read `{}`: not UTF-8 text", path.display()),
            );
            report(err, &SourceMap::new(), &[d], format);
            return Err(EXIT_IO);
        }
    };
    let mut map = SourceMap::new();
    let file = map.add(
        path.display().to_string(),
        text.strip_prefix('\u{feff}').unwrap_or(&text),
    );
    match compile(&map, file) {
        Ok(c) => Ok(Loaded {
            program: c.program,
            source: Some((map, c.debug)),
        }),
        Err(diags) => {
            report(err, &map, &diags.into_sorted(), format);
            Err(EXIT_REJECTED)
        }
    }
}

/// Compiles a script and writes its image. Prints a one-line summary on `out`.
pub fn build(args: &BuildArgs, out: &mut dyn Write, err: &mut dyn Write) -> i32 {
    let loaded = match load(&args.script, args.format, err) {
        Ok(l) => l,
        Err(code) => return code,
    };
    let bytes = encode(&loaded.program);
    if let Err(e) = std::fs::write(&args.output, &bytes) {
        let d = Diagnostic::error(
            code::E9002,
            format!("cannot write `{}`: {e}", args.output.display()),
        );
        report(err, &SourceMap::new(), &[d], args.format);
        return EXIT_IO;
    }
    let p = &loaded.program;
    let _ = writeln!(
        out,
        "{}: {} Motions, {} Events, {} bytes (Motion pool {}/{MAX_MOTIONS}, Event pool {}/{MAX_EVENTS})",
        args.output.display(),
        p.motions.len(),
        p.events.len(),
        bytes.len(),
        p.motions.len(),
        p.events.len()
    );
    EXIT_OK
}

const TRACE_MD: usize = 8;

/// Runs a script (or image) on a motion-lib axis ([`DriveKind::MotionLib`]) for `cycles` main-loop cycles;
/// optionally writes a CSV trace with one row per cycle:
/// `cycle,time_ms,motion,event,phase,position,velocity,current,di,do,md0..md7`.
pub fn run(args: &RunArgs, out: &mut dyn Write, err: &mut dyn Write) -> i32 {
    run_with_drive(args, DriveKind::MotionLib, out, err)
}

/// [`run`] on the chosen drive (`ladderc drive run ... --drive sim`).
pub fn run_with_drive(
    args: &RunArgs,
    kind: DriveKind,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> i32 {
    let loaded = match load(&args.script, args.format, err) {
        Ok(l) => l,
        Err(code) => return code,
    };
    let mut interp = match Interpreter::new(loaded.program) {
        Ok(i) => i,
        Err(m) => {
            let d = Diagnostic::error(code::E6023, format!("malformed program: {m}"));
            report(err, &SourceMap::new(), &[d], args.format);
            return EXIT_REJECTED;
        }
    };
    let mut drive = kind.make(args.cycle_ms);
    drive.set_inputs(args.inputs);
    let mut trace = String::new();
    if args.trace.is_some() {
        trace.push_str("cycle,time_ms,motion,event,phase,position,velocity,current,di,do");
        for i in 0..TRACE_MD {
            trace.push_str(&format!(",md{i}"));
        }
        trace.push('\n');
    }
    for n in 0..args.cycles {
        interp.cycle(drive.as_mut());
        drive.tick();
        if args.trace.is_some() {
            let at = interp.location();
            trace.push_str(&format!(
                "{n},{},{},{},{},{},{},{},{},{}",
                drive.now_ms(),
                at.motion,
                at.event,
                if at.phase == Phase::BeforeIf {
                    "IF"
                } else {
                    "THEN"
                },
                drive.actual_position(),
                drive.actual_velocity(),
                drive.actual_current(),
                drive.digital_inputs(),
                drive.digital_outputs()
            ));
            for v in &interp.memory_words()[..TRACE_MD] {
                trace.push_str(&format!(",{v}"));
            }
            trace.push('\n');
        }
    }
    if let Some(path) = &args.trace {
        if let Err(e) = std::fs::write(path, trace) {
            let d = Diagnostic::error(
                code::E9002,
                format!("cannot write `{}`: {e}", path.display()),
            );
            report(err, &SourceMap::new(), &[d], args.format);
            return EXIT_IO;
        }
    }
    let _ = writeln!(
        out,
        "{} cycles ({} ms): at {}; position {}, velocity {}, DO 0x{:04X}; {} Events evaluated",
        args.cycles,
        drive.now_ms(),
        interp.location(),
        drive.actual_position(),
        drive.actual_velocity(),
        drive.digital_outputs(),
        interp.events_evaluated()
    );
    EXIT_OK
}

/// Default and maximum cycles for `run`, `step` and `pause` in the debugger.
pub const DEBUG_RUN_CYCLES: u64 = 10_000;

/// A debugging session: interpreter, simulated drive and (when loaded from source) line information.
pub struct DebugSession {
    /// The interpreter being debugged (breakpoints, stop state, registers).
    pub interp: Interpreter,
    /// The simulated drive it commands, ticked once per cycle.
    pub drive: Box<dyn CycleDrive>,
    /// Main-loop cycles run so far in this session.
    pub cycles: u64,
    source: Option<(SourceMap, DebugInfo)>,
    /// Names printed after every stop (`watch NAME`).
    watches: Vec<String>,
}

impl DebugSession {
    /// A session on a motion-lib axis with a 1 ms cycle.
    pub fn new(
        program: Program,
        source: Option<(SourceMap, DebugInfo)>,
    ) -> Result<DebugSession, String> {
        DebugSession::with_drive(program, source, DriveKind::MotionLib)
    }

    /// A session on the chosen drive with a 1 ms cycle.
    pub fn with_drive(
        program: Program,
        source: Option<(SourceMap, DebugInfo)>,
        kind: DriveKind,
    ) -> Result<DebugSession, String> {
        Ok(DebugSession {
            interp: Interpreter::new(program)?,
            drive: kind.make(1),
            cycles: 0,
            source,
            watches: Vec::new(),
        })
    }

    /// Runs main-loop cycles (the drive ticks after each) until the interpreter stops or `max` cycles pass.
    pub fn run_cycles(&mut self, max: u64) -> Option<Location> {
        for _ in 0..max {
            if let CycleResult::Stopped(at) = self.interp.cycle(self.drive.as_mut()) {
                return Some(at);
            }
            self.drive.tick();
            self.cycles += 1;
        }
        None
    }

    /// `Motion m Event e before IF (line n: text)`.
    pub fn describe(&self, at: Location) -> String {
        let mut s = at.to_string();
        if let Some((map, debug)) = &self.source {
            let idx = self
                .interp
                .program()
                .motions
                .get(at.motion as usize)
                .map(|m| m.first_event as usize + at.event as usize);
            if let Some(lines) = idx.and_then(|i| debug.events.get(i)) {
                let span = match at.phase {
                    Phase::BeforeIf => lines.if_stmt,
                    Phase::BeforeThen => lines.then_stmt,
                };
                let f = map.get(debug.file);
                let (line, _) = f.line_col(span.start as usize);
                let text = f.text.get(span.range()).unwrap_or("").replace('\n', " ");
                s.push_str(&format!(" (line {line}: {text})"));
            }
        }
        s
    }

    /// Executes one debugger command line; returns false on `quit`.
    pub fn command(&mut self, line: &str, out: &mut dyn Write) -> bool {
        let words: Vec<&str> = line
            .split(|c: char| c.is_whitespace() || c == '=')
            .filter(|w| !w.is_empty())
            .collect();
        let Some(cmd) = words.first() else {
            return true;
        };
        let r = match cmd.to_ascii_lowercase().as_str() {
            "quit" | "q" | "exit" => return false,
            "help" | "h" | "?" => Ok(HELP.to_string()),
            "break" | "b" => self.cmd_break(&words[1..]),
            "delete" | "d" => self.cmd_number(&words[1..]).and_then(|n| {
                self.interp
                    .delete_breakpoint(n)
                    .map(|_| format!("deleted breakpoint {n}"))
                    .map_err(|e| e.to_string())
            }),
            "enable" | "disable" => {
                let on = cmd.eq_ignore_ascii_case("enable");
                self.cmd_number(&words[1..]).and_then(|n| {
                    self.interp
                        .enable_breakpoint(n, on)
                        .map(|_| {
                            format!("breakpoint {n} {}", if on { "enabled" } else { "disabled" })
                        })
                        .map_err(|e| e.to_string())
                })
            }
            "list" | "info" | "l" => Ok(self.list()),
            "run" | "r" | "continue" | "c" => self.cmd_cycles(&words[1..]).map(|max| {
                self.interp.resume();
                self.after_run(max)
            }),
            "step" | "s" => {
                self.interp.step();
                Ok(self.after_run(DEBUG_RUN_CYCLES))
            }
            "pause" => {
                if self.interp.is_stopped() {
                    Ok(format!(
                        "already stopped at {}",
                        self.describe(self.interp.location())
                    ))
                } else {
                    self.interp.pause();
                    Ok(self.after_run(DEBUG_RUN_CYCLES))
                }
            }
            "print" | "p" => self.cmd_print(&words[1..]),
            "watch" | "w" => match words.get(1) {
                None => Ok(self.watch_lines()),
                Some(name) => self.cmd_print(&words[1..2]).map(|now| {
                    if !self.watches.iter().any(|w| w.eq_ignore_ascii_case(name)) {
                        self.watches.push(name.to_string());
                    }
                    format!("watching {name}: {now}")
                }),
            },
            "unwatch" => match words.get(1) {
                Some(name) => {
                    let before = self.watches.len();
                    self.watches.retain(|w| !w.eq_ignore_ascii_case(name));
                    if self.watches.len() < before {
                        Ok(format!("no longer watching {name}"))
                    } else {
                        Err(format!("`{name}` is not watched"))
                    }
                }
                None => Err("usage: unwatch NAME".into()),
            },
            "set" => self.cmd_set(&words[1..]),
            other => Err(format!("unknown command `{other}` (type `help`)")),
        };
        let _ = match r {
            Ok(text) => writeln!(out, "{text}"),
            Err(text) => writeln!(out, "error: {text}"),
        };
        true
    }

    fn watch_lines(&self) -> String {
        self.watches
            .iter()
            .map(|w| format!("  {}", self.cmd_print(&[w.as_str()]).unwrap_or_else(|e| e)))
            .collect::<Vec<_>>()
            .join("\n")
    }

    fn after_run(&mut self, max: u64) -> String {
        let mut s = self.after_run_inner(max);
        if !self.watches.is_empty() {
            s.push('\n');
            s.push_str(&self.watch_lines());
        }
        s
    }

    fn after_run_inner(&mut self, max: u64) -> String {
        let before = self.cycles;
        match self.run_cycles(max) {
            Some(at) => format!(
                "stopped at {} after {} cycles",
                self.describe(at),
                self.cycles - before
            ),
            None => format!(
                "ran {max} cycles without stopping; next: {}",
                self.describe(self.interp.location())
            ),
        }
    }

    fn cmd_number(&self, args: &[&str]) -> Result<usize, String> {
        args.first()
            .and_then(|a| a.parse().ok())
            .ok_or_else(|| "expected a breakpoint number".to_string())
    }

    fn cmd_cycles(&self, args: &[&str]) -> Result<u64, String> {
        match args.first() {
            None => Ok(DEBUG_RUN_CYCLES),
            Some(a) => a
                .parse()
                .map_err(|_| format!("expected a number of cycles, found `{a}`")),
        }
    }

    fn cmd_break(&mut self, args: &[&str]) -> Result<String, String> {
        let usage = "usage: break MOTION EVENT [if|then]";
        let motion: u16 = args.first().and_then(|a| a.parse().ok()).ok_or(usage)?;
        let event: u16 = args.get(1).and_then(|a| a.parse().ok()).ok_or(usage)?;
        let phase = match args.get(2).map(|a| a.to_ascii_lowercase()).as_deref() {
            None | Some("if") => Phase::BeforeIf,
            Some("then") => Phase::BeforeThen,
            Some(_) => return Err(usage.into()),
        };
        let at = Location {
            motion,
            event,
            phase,
        };
        let n = self.interp.add_breakpoint(at).map_err(|e| e.to_string())?;
        Ok(format!("breakpoint {n} at {}", self.describe(at)))
    }

    fn list(&self) -> String {
        let mut s = String::new();
        for (n, b) in self.interp.breakpoints().list().iter().enumerate() {
            match b {
                Some(b) => s.push_str(&format!(
                    "{n}: {}{}\n",
                    self.describe(b.at),
                    if b.enabled { "" } else { " [disabled]" }
                )),
                None => s.push_str(&format!("{n}: -\n")),
            }
        }
        s.push_str(&format!(
            "step: {}",
            if self.interp.breakpoints().temp_armed() {
                "armed"
            } else {
                "-"
            }
        ));
        s
    }

    fn cmd_print(&self, args: &[&str]) -> Result<String, String> {
        let Some(name) = args.first() else {
            return Err("usage: print NAME (MDn, Pn, DI_n, DO_n, ActualPosition, ActualVelocity, ActualCurrent, where, md, params)".into());
        };
        let lower = name.to_ascii_lowercase();
        let i = &self.interp;
        let d = &self.drive;
        let text = match lower.as_str() {
            "where" => format!(
                "{} at {} (cycle {}, {} ms)",
                if i.is_stopped() { "stopped" } else { "running" },
                self.describe(i.location()),
                self.cycles,
                d.now_ms()
            ),
            "md" => join_words("MD", i.memory_words()),
            "params" | "p" => join_words("P", i.params()),
            "actualposition" | "position" | "pos" => {
                format!("ActualPosition = {}", d.actual_position())
            }
            "actualvelocity" | "velocity" => format!("ActualVelocity = {}", d.actual_velocity()),
            "actualcurrent" | "current" => format!("ActualCurrent = {}", d.actual_current()),
            "matherror" => format!("MathError = {}", i.math_error() as i32),
            _ => match register(&lower) {
                Some(Register::Md(n)) => format!("MD{n} = {}", i.memory(n).unwrap_or(0)),
                Some(Register::P(n)) => format!("P{n} = {}", i.param(n).unwrap_or(0)),
                Some(Register::Di(n)) => format!("DI_{n} = {}", (d.digital_inputs() >> n) & 1),
                Some(Register::Do(n)) => format!("DO_{n} = {}", (d.digital_outputs() >> n) & 1),
                None => return Err(format!("cannot print `{name}`")),
            },
        };
        Ok(text)
    }

    fn cmd_set(&mut self, args: &[&str]) -> Result<String, String> {
        let usage = "usage: set NAME = VALUE (MDn, Pn, DI_n, DO_n)";
        let (Some(name), Some(value)) = (args.first(), args.get(1)) else {
            return Err(usage.into());
        };
        let v = parse_value(value).ok_or_else(|| format!("`{value}` is not a 32-bit integer"))?;
        match register(&name.to_ascii_lowercase()) {
            Some(Register::Md(n)) => {
                self.interp.set_memory(n, v);
                Ok(format!("MD{n} = {v}"))
            }
            Some(Register::P(n)) => {
                self.interp.set_param(n, v);
                Ok(format!("P{n} = {v}"))
            }
            Some(Register::Di(n)) => {
                self.drive.set_input_bit(n as u8, v != 0);
                Ok(format!("DI_{n} = {}", (v != 0) as i32))
            }
            Some(Register::Do(n)) => {
                self.drive.set_digital_output(n as u8, v != 0);
                Ok(format!("DO_{n} = {}", (v != 0) as i32))
            }
            None => Err(format!("cannot set `{name}`; {usage}")),
        }
    }
}

enum Register {
    Md(usize),
    P(usize),
    Di(usize),
    Do(usize),
}

fn register(lower: &str) -> Option<Register> {
    let idx = |rest: &str, limit: usize| rest.parse::<usize>().ok().filter(|n| *n < limit);
    if let Some(r) = lower.strip_prefix("md") {
        idx(r, MEMORY_WORDS).map(Register::Md)
    } else if let Some(r) = lower.strip_prefix("di_") {
        idx(r, DIGITAL_INPUTS).map(Register::Di)
    } else if let Some(r) = lower.strip_prefix("do_") {
        idx(r, DIGITAL_OUTPUTS).map(Register::Do)
    } else if let Some(r) = lower.strip_prefix('p') {
        idx(r, PARAMS).map(Register::P)
    } else {
        None
    }
}

fn parse_value(s: &str) -> Option<i32> {
    match s.to_ascii_lowercase().as_str() {
        "high" | "true" => return Some(1),
        "low" | "false" => return Some(0),
        _ => {}
    }
    if let Some(h) = s.strip_prefix("0x").or_else(|| s.strip_prefix("0X")) {
        return u32::from_str_radix(h, 16).ok().map(|v| v as i32);
    }
    s.parse().ok()
}

fn join_words(prefix: &str, words: &[i32]) -> String {
    words
        .iter()
        .enumerate()
        .map(|(i, v)| format!("{prefix}{i}={v}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// The debugger's `help` text: every command with its arguments.
pub const HELP: &str = "\
commands (names are case-insensitive):
  break M E [if|then]   breakpoint before the IF (default) or the THEN of Event E of Motion M (4 at most)
  delete N              remove breakpoint N      enable N / disable N   switch breakpoint N
  list                  show the breakpoint list (4 user entries + the single-step entry)
  run [CYCLES]          resume and run up to CYCLES main-loop cycles (default 10000) or to a breakpoint
  step                  run the current IF or THEN and stop at the next point
  pause                 stop at the next point reached
  print NAME            MDn, Pn, DI_n, DO_n, ActualPosition, ActualVelocity, ActualCurrent, MathError,
                        where, md (all MD words), params (all parameters)
  set NAME = VALUE      write MDn, Pn, DI_n (simulated input) or DO_n; VALUE: integer, 0x hex, HIGH, LOW
  watch NAME            print NAME after every run, step and pause (`watch` alone: print them now)
  unwatch NAME          stop watching NAME
  help                  this text
  quit                  leave the debugger";

/// The interactive debugger on a motion-lib axis: reads command lines from `input` until `quit` or end of
/// input; writes a `(ds) ` prompt and each answer to `out`.
pub fn debug(
    args: &DebugArgs,
    input: &mut dyn BufRead,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> i32 {
    debug_with_drive(args, DriveKind::MotionLib, input, out, err)
}

/// [`debug`] on the chosen drive (`ladderc drive debug SCRIPT --drive sim`).
pub fn debug_with_drive(
    args: &DebugArgs,
    kind: DriveKind,
    input: &mut dyn BufRead,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> i32 {
    let loaded = match load(&args.script, args.format, err) {
        Ok(l) => l,
        Err(code) => return code,
    };
    let p = &loaded.program;
    let _ = writeln!(
        out,
        "drive-script debugger: {} Motions, {} Events; nothing has run yet, next: {}. Type `help`.",
        p.motions.len(),
        p.events.len(),
        Location::START
    );
    let mut session = match DebugSession::with_drive(loaded.program, loaded.source, kind) {
        Ok(s) => s,
        Err(m) => {
            let d = Diagnostic::error(code::E6023, format!("malformed program: {m}"));
            report(err, &SourceMap::new(), &[d], args.format);
            return EXIT_REJECTED;
        }
    };
    let mut line = String::new();
    loop {
        let _ = write!(out, "(ds) ");
        let _ = out.flush();
        line.clear();
        match input.read_line(&mut line) {
            Ok(0) | Err(_) => {
                let _ = writeln!(out);
                return EXIT_OK;
            }
            Ok(_) => {}
        }
        if !session.command(&line, out) {
            return EXIT_OK;
        }
    }
}
