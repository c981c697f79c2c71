//! The C backend: IEC 61131-3 IL (parsed and analysed) to a standalone C99 program.
//!
//! Input: the parsed [`CompilationUnit`]s, the sema [`Model`], a [`TargetProfile`] (memory model) and
//! [`Options`] (embedded C functions from the parameter-passing stage). Output: a [`CProgram`] (the files of
//! a C project: generated program, runtime, harness, Makefile), or `None` with E2xxx diagnostics.
//! [`build`] writes the files and compiles them with the system C compiler; [`run`] executes the result.
//! Invariants: the generated C compiles with `cc -std=c99 -Wall -Wextra -Werror`, has no undefined
//! behaviour for any input values (wrapping integer arithmetic, defined division by zero), contains no
//! user text except inside octal-escaped string literals, and is generated in time linear in the input.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

/// `format!` into a `String` that starts with room for a typical C expression or statement (64
/// bytes): `format!` sizes its buffer from the literal pieces only, so a short template such as
/// `"{lv} = {value};"` regrows its string two or three times. Used on the per-instruction paths.
macro_rules! cfmt {
    ($($arg:tt)*) => {{
        let mut s = String::with_capacity(64);
        let _ = std::fmt::Write::write_fmt(&mut s, format_args!($($arg)*));
        s
    }};
}

/// Concatenates `parts` into one `String` allocated once at its final length. The per-instruction C
/// expressions are fixed pieces around operands; `format!` (and [`cfmt!`]) walk a format template and
/// cost about 1,000 instructions for such an expression, this a tenth of that.
pub(crate) fn cat(parts: &[&str]) -> String {
    let mut s = String::with_capacity(parts.iter().map(|p| p.len()).sum());
    for p in parts {
        s.push_str(p);
    }
    s
}

mod budget;
pub mod ctypes;
mod emit;
pub use emit::config_header;
pub mod extensions;
pub mod mangle;
pub mod motion;
pub mod pipeline;
pub mod profile;
pub mod runtime;
pub mod toolchain;

pub use extensions::{Extensions, MethodFeedback, MethodLocal, PouMethod};
pub use pipeline::{build_il, compile_il};
pub use profile::{
    AddressUnit, BitNumbering, ByteOrder, Located, ProfileError, SfcActionControl, TargetProfile,
    TimeNumberUnit,
};
pub use toolchain::{
    build, build_with, run, watch_names, BuildError, BuildOptions, RunOptions, RunOutput,
};

use diagnostics::Diagnostics;
use il_frontend::ast::CompilationUnit;
use il_frontend::sema::Model;

/// An embedded C function called by `FUNC Name()` (supplied by the parameter-passing stage).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EmbeddedFunction {
    /// The C name (a plain identifier); `FUNC` matches it case-insensitively.
    pub name: String,
    /// A complete C99 translation-unit fragment defining `void <name>(void)`; it may use the runtime
    /// (`ladderc_rt.h` is included before it), e.g. `LADDERC_TM` for the TM area.
    pub c_source: String,
}

/// Generator options.
#[derive(Debug, Clone, Default)]
pub struct Options {
    /// Static-library functions (the IL method of paper A) put into `embedded.c`.
    pub embedded: Vec<EmbeddedFunction>,
    /// The sources' lines, so that a run-time error names the line of its first site (`temps[i] in
    /// Main at main.st:12`); empty: the sites name the access and the POU only.
    pub lines: SourceLines,
}

/// The file name, the text and the line starts of each source file, by [`diagnostics::FileId`]:
/// what the generator needs to name a site in the generated C (its line, and an expression the
/// lowering replaced by a temporary as the user wrote it). Only the file's name is kept (not its
/// folders), so the C does not depend on where the project lies.
#[derive(Debug, Clone, Default)]
pub struct SourceLines {
    files: Vec<SourceText>,
}

#[derive(Debug, Clone)]
struct SourceText {
    name: String,
    text: String,
    starts: Vec<usize>,
}

impl SourceLines {
    /// The lines of every file of `map`.
    pub fn of(map: &diagnostics::SourceMap) -> Self {
        SourceLines {
            files: map
                .files()
                .map(|(_, f)| SourceText {
                    name: std::path::Path::new(&f.name)
                        .file_name()
                        .map(|n| n.to_string_lossy().into_owned())
                        .unwrap_or_else(|| f.name.clone()),
                    text: f.text.clone(),
                    starts: f.line_starts().to_vec(),
                })
                .collect(),
        }
    }

    /// `file:line` of the start of `span` (1-based line), when its file is known.
    pub fn locate(&self, span: diagnostics::Span) -> Option<String> {
        let f = self.files.get(span.file.0 as usize)?;
        let at = span.start as usize;
        let line = match f.starts.binary_search(&at) {
            Ok(l) => l,
            Err(l) => l.checked_sub(1)?,
        };
        Some(format!("{}:{}", f.name, line + 1))
    }

    /// The text of `span` when it is a short piece of one line (at most 60 bytes), as written.
    pub fn text(&self, span: diagnostics::Span) -> Option<&str> {
        let f = self.files.get(span.file.0 as usize)?;
        let t = f.text.get(span.range())?.trim();
        (!t.is_empty() && t.len() <= 60 && !t.contains(['\n', '\r'])).then_some(t)
    }
}

/// The generated C project: `(relative path, contents)` pairs.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct CProgram {
    /// Every generated file `(relative path, text)`: sources, headers, the runtime, the Makefile.
    pub files: Vec<(String, String)>,
    /// Linker arguments after the sources (e.g. `libmotion_lib.a -lpthread -ldl -lm`), relative to the
    /// project directory; files named here are not generated text and are put there by the caller.
    pub link: Vec<String>,
}

impl CProgram {
    /// The contents of a file by relative path.
    pub fn file(&self, path: &str) -> Option<&str> {
        self.files
            .iter()
            .find(|(p, _)| p == path)
            .map(|(_, c)| c.as_str())
    }
    /// The C sources to compile (all `.c` files).
    pub fn sources(&self) -> impl Iterator<Item = &str> {
        self.files
            .iter()
            .map(|(p, _)| p.as_str())
            .filter(|p| p.ends_with(".c"))
    }
}

/// The name of the executable [`build`] produces (and the Makefile's target).
pub const EXECUTABLE: &str = "program";

/// Generates the C project. Returns `None` when an error was reported (E2xxx; existing errors in `diags`
/// from earlier stages also stop generation, since the model may then be incomplete).
pub fn generate(
    units: &[CompilationUnit],
    model: &Model,
    profile: &TargetProfile,
    opts: &Options,
    diags: &mut Diagnostics,
) -> Option<CProgram> {
    generate_with(units, model, profile, opts, &Extensions::default(), diags)
}

/// [`generate`] with the motion runtime and template-method functions.
pub fn generate_with(
    units: &[CompilationUnit],
    model: &Model,
    profile: &TargetProfile,
    opts: &Options,
    ext: &Extensions,
    diags: &mut Diagnostics,
) -> Option<CProgram> {
    if diags.has_errors() {
        return None;
    }
    if let Err(e) = profile.validate() {
        diags.push(diagnostics::Diagnostic::error(
            diagnostics::code::E2003,
            e.to_string(),
        ));
        return None;
    }
    if !budget::check(model, profile, diags) {
        return None;
    }
    let before = diags.error_count();
    let files = emit::generate(units, model, profile, opts, ext, diags);
    if diags.error_count() > before {
        return None;
    }
    let mut program = CProgram {
        files,
        link: Vec::new(),
    };
    program.files.extend(runtime::files());
    if let Some(m) = &ext.motion {
        if let Some((_, h)) = program
            .files
            .iter_mut()
            .find(|(p, _)| p == "ladderc_config.h")
        {
            if let Some(end) = h.rfind("#endif") {
                h.insert_str(end, &m.config_define());
            }
        }
        program.files.extend(m.files());
        program.link = motion::link_args(motion::STATICLIB);
    }
    program
        .files
        .push(("Makefile".into(), toolchain::makefile(&program)));
    Some(program)
}
