//! The typed, in-memory pipeline API: sources and options in; diagnostics, the lowered IL, the C files and
//! the block report out.
//!
//! Input: sources as `(path, text)` pairs and [`Options`]; the axes file, the target profile and the user
//! templates may be given in memory too ([`Project::with_file`]). Output: one value per stage, each
//! holding every diagnostic reported so far:
//!
//! ```text
//! Project --parse()--> ParsedProject --check()--> CheckedProject --lower()--> LoweredProject
//!         --generate()--> GeneratedProject
//! ```
//!
//! A stage that reports an error returns [`Failed`] (the sources and the diagnostics, as values) instead of
//! the next stage. Invariants: a project made by [`Project::from_sources`] reads no file and no standard
//! input (a path that is not given is an E9001 error) unless [`Project::with_disk_fallback`] is set;
//! no stage writes a file or starts a process, unless [`Options::compile_templates`] asks for the
//! templates' C check. Building and running the generated C are separate, explicit steps
//! ([`GeneratedProject::write_to`], [`c_backend::build_with`]).

use crate::pipeline::{self, Options, Session};
use diagnostics::{Diagnostic, MessageFormat, SourceMap};
use il_frontend::ast::CompilationUnit;
use std::path::{Path, PathBuf};

/// A project before any stage ran: its sources, the other files it may read, its options.
///
/// ```
/// use ladderc::{Options, Project};
///
/// let project = Project::from_sources(
///     [("lamp.il", "PROGRAM lamp\nVAR\n  lit : BOOL;\nEND_VAR\n  LD TRUE\n  ST lit\nEND_PROGRAM\n")],
///     Options::default(),
/// );
/// let generated = project.compile().expect("no errors");
/// assert!(generated.c_file("program.c").is_some());
/// ```
pub struct Project {
    session: Session,
    inputs: Vec<PathBuf>,
    options: Options,
}

/// The parsed sources ([`Project::parse`]).
pub struct ParsedProject {
    session: Session,
    inputs: Vec<PathBuf>,
    options: Options,
    parsed: pipeline::Parsed,
}

/// A program that passed the semantic checks ([`ParsedProject::check`]).
pub struct CheckedProject {
    session: Session,
    options: Options,
    checked: pipeline::Checked,
}

/// A program whose PLCopen block calls are lowered to IL by parameter passing ([`CheckedProject::lower`]).
///
/// ```
/// use ladderc::{Options, Project};
///
/// let lowered = Project::from_sources(
///     [("count.il", "PROGRAM count\nVAR\n  n : INT;\nEND_VAR\n  LD n\n  ADD 1\n  ST n\nEND_PROGRAM\n")],
///     Options::default(),
/// )
/// .check()?
/// .lower()?;
/// assert!(lowered.il().contains("ADD 1"));
/// # Ok::<(), ladderc::Failed>(())
/// ```
pub struct LoweredProject {
    session: Session,
    lowered: pipeline::Lowered,
}

/// The C project of a program ([`LoweredProject::generate`]): sources, headers, the runtime and a Makefile,
/// all as text.
pub struct GeneratedProject {
    session: Session,
    lowered: pipeline::Lowered,
    program: c_backend::CProgram,
}

/// A stage stopped on errors: the sources read and every diagnostic (sorted by file and position).
///
/// ```
/// use ladderc::{Options, Project};
///
/// let failed = Project::from_sources([("missing.il", "PROGRAM p\n  LD x\nEND_PROGRAM\n")], Options::default())
///     .with_disk_fallback(false)
///     .check()
///     .expect_err("x is undeclared");
/// let e = failed.errors().next().unwrap();
/// assert_eq!(e.code, ladderc::diagnostics::code::E1001);
/// assert_eq!(failed.line_col(e), Some((2, 6)));
/// ```
pub struct Failed {
    /// Every text the stages read (to render the diagnostics' excerpts).
    pub sources: SourceMap,
    /// Every diagnostic, sorted; at least one is an error.
    pub diagnostics: Vec<Diagnostic>,
}

/// One access path of a configuration's `VAR_ACCESS` block (IEC 61131-3 2.7.1 / 6.8.2; PLCopen XML's
/// `<accessVars>`): the name by which the outside reaches a variable of the running program. It is
/// a name of the run's watch table: a trace column (`--watch NAME`, a structured one as
/// `NAME.field`) and, when READ_WRITE, a stimulus target.
///
/// ```
/// use ladderc::{AccessDirection, Options, Project};
///
/// let st = "PROGRAM p\nVAR\n  n : INT;\nEND_VAR\n  n := n + 1;\nEND_PROGRAM\n\
///           CONFIGURATION c\nVAR_ACCESS\n  count : res.inst.n : INT READ_WRITE;\nEND_VAR\n\
///           RESOURCE res ON PLC\n  TASK t (INTERVAL := T#10ms, PRIORITY := 1);\n\
///           PROGRAM inst WITH t : p;\nEND_RESOURCE\nEND_CONFIGURATION\n";
/// let generated = Project::from_sources([("cell.st", st)], Options::default()).compile()?;
/// let paths = generated.access_paths();
/// assert_eq!(paths[0].name, "count");
/// assert_eq!(paths[0].path, "res.inst.n");
/// assert_eq!(paths[0].type_name, "INT");
/// assert_eq!(paths[0].direction, AccessDirection::ReadWrite);
/// # Ok::<(), ladderc::Failed>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AccessPath {
    /// The configuration that declares it.
    pub configuration: String,
    /// The access name, as declared (the trace and stimulus name).
    pub name: String,
    /// The path as written: `resource.program.{fb.}variable`, `program.variable`, a global
    /// (`resource.g`, `g`) or a direct address (`resource.%IX1.1`).
    pub path: String,
    /// The declared type's name, as written.
    pub type_name: String,
    /// READ_ONLY (the standard's default when no direction is written) or READ_WRITE.
    pub direction: AccessDirection,
}

/// Whether the outside may write through an access path.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AccessDirection {
    /// `READ_ONLY`, or no direction written: a stimulus row for it is refused.
    ReadOnly,
    /// `READ_WRITE`: a stimulus row sets the variable.
    ReadWrite,
}

/// The access paths of every configuration of `units`, in source order.
fn access_paths(units: &[CompilationUnit], map: &SourceMap) -> Vec<AccessPath> {
    use il_frontend::ast::LibraryElement;
    let mut out = Vec::new();
    for unit in units {
        for item in &unit.items {
            let LibraryElement::Configuration(c) = item else {
                continue;
            };
            for a in &c.access {
                let mut parts: Vec<String> = a.path.iter().map(|i| i.name.clone()).collect();
                if let Some(addr) = &a.address {
                    let text = &map.get(addr.span.file).text;
                    let (s, e) = (addr.span.start as usize, addr.span.end as usize);
                    parts.push(text.get(s..e).unwrap_or_default().trim().to_string());
                }
                out.push(AccessPath {
                    configuration: c.name.name.clone(),
                    name: a.name.name.clone(),
                    path: parts.join("."),
                    type_name: a.type_name.name.clone(),
                    direction: if a.read_only {
                        AccessDirection::ReadOnly
                    } else {
                        AccessDirection::ReadWrite
                    },
                });
            }
        }
    }
    out
}

impl Project {
    /// A project of in-memory sources `(path, text)`, compiled in the given order. The paths name the
    /// sources in diagnostics and choose their language (`.il`, `.st`, `.xml`; others by content); they
    /// need not exist. Nothing is read from the file system.
    pub fn from_sources<I, P, T>(sources: I, options: Options) -> Project
    where
        I: IntoIterator<Item = (P, T)>,
        P: Into<PathBuf>,
        T: Into<String>,
    {
        let mut session = Session::in_memory();
        let mut inputs = Vec::new();
        for (p, t) in sources {
            let p = p.into();
            session.overlay.insert(p.clone(), t.into());
            inputs.push(p);
        }
        Project {
            session,
            inputs,
            options,
        }
    }

    /// A project of source files on disk (`-`: standard input), read as the command line reads them: every
    /// file not given with [`Project::with_file`] comes from the file system.
    pub fn from_paths(
        paths: impl IntoIterator<Item = impl Into<PathBuf>>,
        options: Options,
    ) -> Project {
        Project {
            session: Session::new(),
            inputs: paths.into_iter().map(Into::into).collect(),
            options,
        }
    }

    /// Gives another file in memory: the axes file (`--axes`, or `<first input stem>.axes.json` beside the
    /// first input), the target profile ([`Options::profile`]), a template `DIR/NAME.xml` of
    /// [`Options::templates`]. It replaces a file of the same path on disk.
    ///
    /// ```
    /// use ladderc::{Options, Project};
    ///
    /// let il = "PROGRAM main\nVAR\n  power : MC_Power;\n  powered : BOOL;\nEND_VAR\n\
    ///           CAL power(Axis := X1, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE, Status => powered)\n\
    ///           END_PROGRAM\n";
    /// let axes = r#"{ "cycle_ms": 2, "axes": [ { "name": "X1", "velocity": 200, "acceleration": 1000,
    ///                 "deceleration": 1000, "jerk": 10000 } ] }"#;
    /// let generated = Project::from_sources([("cell/main.il", il)], Options::default())
    ///     .with_file("cell/main.axes.json", axes)
    ///     .compile()?;
    /// assert_eq!(generated.cycle_ms(), 2.0);
    /// assert!(generated.uses_motion());
    /// assert!(generated.files().any(|(name, _)| name == "motion_lib.h"));
    /// # Ok::<(), ladderc::Failed>(())
    /// ```
    pub fn with_file(mut self, path: impl Into<PathBuf>, text: impl Into<String>) -> Project {
        self.session.overlay.insert(path.into(), text.into());
        self
    }

    /// Whether files that are not given in memory are read from the file system, and `-` from standard
    /// input (the default of [`Project::from_paths`]; [`Project::from_sources`] reads nothing).
    pub fn with_disk_fallback(mut self, yes: bool) -> Project {
        self.session.disk = yes;
        self
    }

    /// Reads and parses every source, the target profile and the user templates.
    pub fn parse(mut self) -> Result<ParsedProject, Failed> {
        match self.session.parse(&self.inputs, &self.options) {
            Some(parsed) => Ok(ParsedProject {
                session: self.session,
                inputs: self.inputs,
                options: self.options,
                parsed,
            }),
            None => Err(Failed::from(self.session)),
        }
    }

    /// [`Project::parse`], then [`ParsedProject::check`].
    pub fn check(self) -> Result<CheckedProject, Failed> {
        self.parse()?.check()
    }

    /// Every stage to the C project: what `ladderc check` runs. The semantic model it keeps
    /// ([`GeneratedProject::lowered`]) has no name table ([`Session::name_table`]): nothing on the way
    /// to C reads it (run the stages one by one, [`Project::check`], for a model with it).
    pub fn compile(mut self) -> Result<GeneratedProject, Failed> {
        self.session.name_table = false;
        self.check()?.lower()?.generate()
    }
}

impl ParsedProject {
    /// The user's units as parsed (PLCopen XML already lowered to IL), in input order.
    pub fn units(&self) -> &[CompilationUnit] {
        &self.parsed.units
    }

    /// The semantic checks, with the PLCopen block interfaces and the axes file when the program uses blocks.
    pub fn check(mut self) -> Result<CheckedProject, Failed> {
        match self.session.check(self.parsed, &self.inputs, &self.options) {
            Some(checked) => Ok(CheckedProject {
                session: self.session,
                options: self.options,
                checked,
            }),
            None => Err(Failed::from(self.session)),
        }
    }
}

impl CheckedProject {
    /// The user's units as parsed.
    pub fn units(&self) -> &[CompilationUnit] {
        self.checked.units()
    }

    /// The semantic model of the checked program (types, symbols, the current result of each instruction).
    pub fn model(&self) -> &il_frontend::sema::Model {
        &self.checked.model
    }

    /// The access paths (`VAR_ACCESS`) of the program's configurations, as declared; the C
    /// generation checks each against the variable it names (E0308).
    pub fn access_paths(&self) -> Vec<AccessPath> {
        access_paths(self.units(), &self.session.map)
    }

    /// Lowers the PLCopen block calls by [`Options::strategy`].
    pub fn lower(mut self) -> Result<LoweredProject, Failed> {
        match self.session.lower_checked(self.checked, &self.options) {
            Some(lowered) => Ok(LoweredProject {
                session: self.session,
                lowered,
            }),
            None => Err(Failed::from(self.session)),
        }
    }
}

impl LoweredProject {
    /// The user's units after block lowering.
    pub fn units(&self) -> &[CompilationUnit] {
        self.lowered.units()
    }

    /// The access paths (`VAR_ACCESS`) of the program's configurations, as declared.
    pub fn access_paths(&self) -> Vec<AccessPath> {
        access_paths(self.lowered.source_units(), &self.session.map)
    }

    /// The lowered program as IL text: what `ladderc build --emit il` prints.
    pub fn il(&self) -> String {
        self.units().iter().map(il_frontend::print::unit).collect()
    }

    /// The whole pipeline state: the lowering's per-block figures, the templates, profile and axes.
    pub fn lowered(&self) -> &pipeline::Lowered {
        &self.lowered
    }

    /// A PMAC motion program of the program's constant axis and group moves (`--pmac`); `None` when
    /// it has errors, which are added to this project's diagnostics.
    pub fn pmac_program(&mut self, dialect: pmac_backend::model::Dialect) -> Option<String> {
        pmac_program(&self.lowered, &mut self.session, dialect)
    }

    /// Generates the C project.
    pub fn generate(mut self) -> Result<GeneratedProject, Failed> {
        match self.session.generate(&mut self.lowered) {
            Some(program) => Ok(GeneratedProject {
                session: self.session,
                lowered: self.lowered,
                program,
            }),
            None => Err(Failed::from(self.session)),
        }
    }
}

fn pmac_program(
    l: &pipeline::Lowered,
    s: &mut Session,
    dialect: pmac_backend::model::Dialect,
) -> Option<String> {
    crate::pmac_out::program(l.source_units(), &l.axes, dialect, &mut s.diags)
}

impl GeneratedProject {
    /// Every generated file `(relative path, text)`: the C sources, the headers, the runtime and the
    /// Makefile. A program that uses PLCopen blocks also links the motion library
    /// ([`crate::motion_link::library`]), which is not generated text.
    pub fn files(&self) -> impl Iterator<Item = (&str, &str)> {
        self.program
            .files
            .iter()
            .map(|(p, t)| (p.as_str(), t.as_str()))
    }

    /// The access paths (`VAR_ACCESS`) of the program's configurations: each names a variable of the
    /// generated program (checked), and is a name of its watch table ([`AccessPath`]).
    pub fn access_paths(&self) -> Vec<AccessPath> {
        access_paths(self.lowered.source_units(), &self.session.map)
    }

    /// The C sources (`*.c`).
    pub fn c_files(&self) -> impl Iterator<Item = (&str, &str)> {
        self.files().filter(|(p, _)| p.ends_with(".c"))
    }

    /// The C headers (`*.h`).
    pub fn headers(&self) -> impl Iterator<Item = (&str, &str)> {
        self.files().filter(|(p, _)| p.ends_with(".h"))
    }

    /// The text of one generated file by relative path (`program.c`, `ladderc_config.h`, `Makefile` ...).
    pub fn c_file(&self, path: &str) -> Option<&str> {
        self.program.file(path)
    }

    /// The C project as the backend returns it (with its linker arguments), for
    /// [`c_backend::build_with`].
    pub fn program(&self) -> &c_backend::CProgram {
        &self.program
    }

    /// Moves the C project's files (name, text) out, leaving the program without files: for a caller
    /// that writes them and needs no copy.
    pub fn take_files(&mut self) -> Vec<(String, String)> {
        std::mem::take(&mut self.program.files)
    }

    /// The lowered program the C was generated from.
    pub fn lowered(&self) -> &pipeline::Lowered {
        &self.lowered
    }

    /// The scan cycle in ms (the axes file's `cycle_ms`, [`Options::cycle_ms`], else the TwinCAT
    /// tasks' cycle time, else 10).
    pub fn cycle_ms(&self) -> f64 {
        self.lowered.cycle_ms
    }

    /// Whether the program uses PLCopen blocks (and so links the motion library).
    pub fn uses_motion(&self) -> bool {
        self.lowered.uses_blocks
    }

    /// The block report of `build --report json` (per PLCopen block type: method, calls, TM bytes, IL
    /// instructions, C bytes) without the figures that need a C compiler (`object_bytes` and `code_size`
    /// are `null`): no process is started.
    pub fn report(&self) -> String {
        crate::report::json_with(&self.lowered, &self.program, &[], false)
    }

    /// [`GeneratedProject::report`] with the object and program code sizes measured by compiling the C
    /// (starts `$CC` and `nm` in a temporary folder), as `build --report json` prints it.
    pub fn report_measured(&self, extra: &[(String, Vec<u8>)]) -> String {
        crate::report::json(&self.lowered, &self.program, extra)
    }

    /// A PMAC motion program of the program's constant axis and group moves (see
    /// [`LoweredProject::pmac_program`]).
    pub fn pmac_program(&mut self, dialect: pmac_backend::model::Dialect) -> Option<String> {
        pmac_program(&self.lowered, &mut self.session, dialect)
    }

    /// Writes the generated files into `dir` (created when missing), as they are: an explicit file-system
    /// step (`ladderc build -o` also keeps a manifest and never replaces a user's file; see
    /// [`crate::output`]).
    pub fn write_to(&self, dir: &Path) -> Result<(), c_backend::BuildError> {
        c_backend::toolchain::write_files(&self.program, dir)
    }
}

/// The diagnostics of a stage, shared by every stage's value.
macro_rules! diagnostics_access {
    ($($t:ty),*) => {$(
        impl $t {
            /// Every diagnostic reported so far (warnings and notes: a stage value has no errors), in the
            /// order they were reported.
            pub fn diagnostics(&self) -> &[Diagnostic] {
                self.session.diags.as_slice()
            }
            /// Every text read so far, by file id (for the diagnostics' spans).
            pub fn sources(&self) -> &SourceMap {
                &self.session.map
            }
            /// The sources and the diagnostics (sorted), e.g. to render them.
            pub fn into_diagnostics(self) -> (SourceMap, Vec<Diagnostic>) {
                (self.session.map, self.session.diags.into_sorted())
            }
        }
        impl std::fmt::Debug for $t {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.debug_struct(stringify!($t))
                    .field("files", &self.session.map.files().count())
                    .field("diagnostics", &self.session.diags.len())
                    .finish_non_exhaustive()
            }
        }
    )*};
}
diagnostics_access!(
    Project,
    ParsedProject,
    CheckedProject,
    LoweredProject,
    GeneratedProject
);

impl From<Session> for Failed {
    fn from(s: Session) -> Failed {
        Failed {
            sources: s.map,
            diagnostics: s.diags.into_sorted(),
        }
    }
}

impl Failed {
    /// The error diagnostics.
    pub fn errors(&self) -> impl Iterator<Item = &Diagnostic> {
        self.diagnostics
            .iter()
            .filter(|d| d.severity == diagnostics::Severity::Error)
    }

    /// The 1-based line and column where `d` starts; `None` when it has no location.
    pub fn line_col(&self, d: &Diagnostic) -> Option<(usize, usize)> {
        line_col(&self.sources, d)
    }

    /// The diagnostics as `ladderc` prints them in `format` (XML diagnostics with their POU, network and
    /// localId).
    pub fn render(&self, format: MessageFormat) -> String {
        render(&self.sources, &self.diagnostics, format)
    }
}

/// The 1-based line and column where `d` starts in `map`; `None` when it has no location.
pub fn line_col(map: &SourceMap, d: &Diagnostic) -> Option<(usize, usize)> {
    let span = d.span?;
    let (line, col) = map.get(span.file).line_col(span.start as usize);
    Some((line, col))
}

/// `diags` as `ladderc` prints them in `format` (XML diagnostics with their POU, network and localId).
pub fn render(map: &SourceMap, diags: &[Diagnostic], format: MessageFormat) -> String {
    let mut located = crate::xml_context::annotate(map, diags);
    // no generated name of a method's variable in what the user reads (`Take.o`)
    let hidden = |d: &Diagnostic| {
        std::iter::once(&d.message)
            .chain(Some(&d.primary_label))
            .chain(d.labels.iter().map(|l| &l.message))
            .chain(d.hint.as_ref())
            .chain(d.notes.iter())
            .any(|t| t.contains("__M"))
    };
    if located.iter().any(hidden) {
        located
            .to_mut()
            .iter_mut()
            .for_each(il_frontend::actions::show_user_names);
    }
    diagnostics::render(map, &located, format)
}

impl std::fmt::Display for Failed {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.render(MessageFormat::Short).trim_end())
    }
}

impl std::fmt::Debug for Failed {
    /// The diagnostics in the short format (not the sources).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Failed:\n{self}")
    }
}

impl std::error::Error for Failed {}
