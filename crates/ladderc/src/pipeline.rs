//! The compilation pipeline behind `check`, `build` and `run`.
//!
//! Input: source paths (`.xml` PLCopen projects, `.il` IL, `.st` Structured Text, others by content;
//! `-` standard input) and options. Output: the source map, the
//! diagnostics, and (when there are no errors) the lowered IL units and the C project.
//! Stages: read -> parse (IL) or read + lower ladder (XML) -> semantic checks against the PLCopen block
//! prelude -> parameter passing (block calls by the chosen strategy) -> semantic model of the lowered
//! program -> C. Invariant: a stage runs only when the ones before it reported no error.

use crate::axes::AxisConfig;
use diagnostics::{code, Diagnostic, Diagnostics, SourceMap};
use il_frontend::ast::CompilationUnit;
use param_passing::library::Library;
use param_passing::lower::{self, Strategy, TmWindow};
use std::path::{Path, PathBuf};

pub struct Options {
    pub profile: Option<PathBuf>,
    pub strategy: Strategy,
    pub templates: Option<PathBuf>,
    /// The axis configuration; `None`: `<first input stem>.axes.json` beside the first input, if present.
    pub axes: Option<PathBuf>,
    /// The scan cycle `run` uses (`--cycle-ms`), when given; checked against the configuration's.
    pub cycle_ms: Option<f64>,
    /// The source language of every input (`--lang`); `None`: by extension, else from the content.
    pub lang: Option<Lang>,
}

pub use il_frontend::st::file::Lang;

/// The language of an input: `forced`, else by extension (`.il`, `.st`, `.xml`), else from the
/// content. The flag says whether it was detected from the content.
pub fn input_lang(path: &Path, text: &str, forced: Option<Lang>) -> (Lang, bool) {
    if let Some(l) = forced {
        return (l, false);
    }
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("xml") => (Lang::Xml, false),
        Some("il") => (Lang::Il, false),
        Some("st") => (Lang::St, false),
        _ => (il_frontend::st::file::detect(text), true),
    }
}

/// The name diagnostics give standard input (`-` as an input).
pub const STDIN_NAME: &str = "<stdin>";

/// Whether an input path means standard input.
pub fn is_stdin(p: &Path) -> bool {
    p.as_os_str() == "-"
}

/// The motion library's C header, copied into generated projects that use motion blocks.
pub const MOTION_HEADER: &str = include_str!("../../motion-lib/include/motion_lib.h");

/// The scan cycle when neither `--cycle-ms` nor the axis configuration gives one.
pub const DEFAULT_CYCLE_MS: f64 = 10.0;

pub struct Session {
    pub map: SourceMap,
    pub diags: Diagnostics,
    /// Source texts that replace the files of the same path (an editor's unsaved buffers): `load` reads
    /// these instead of the disk.
    pub overlay: std::collections::HashMap<PathBuf, String>,
}

/// What a successful front half produced.
pub struct Lowered {
    /// The user's units as parsed, when block lowering changed them (otherwise they are [`Lowered::units`]:
    /// one copy of the program is kept, whatever its size).
    source_copy: Option<Vec<CompilationUnit>>,
    /// Units to compile: the post-lowering prelude (when blocks are used), then the user's units.
    pub all_units: Vec<CompilationUnit>,
    /// Where the user's units start in `all_units`.
    user_start: usize,
    pub lowering: lower::Lowered,
    pub library: Library,
    pub profile: c_backend::TargetProfile,
    /// Whether the program uses PLCopen blocks (then the motion runtime is linked).
    pub uses_blocks: bool,
    /// The axis configuration (the default, empty one when there is no file).
    pub axes: AxisConfig,
    /// The scan cycle = the motion engine's cycle.
    pub cycle_ms: f64,
    /// The semantic model of `all_units`: after [`Session::lower`], when nothing was lowered (the
    /// checked program is the compiled one, so it is analysed once); after [`Session::compile`], always
    /// (the model the C was generated from).
    pub model: Option<il_frontend::sema::Model>,
}

impl Lowered {
    /// The user's units after block lowering (without the prelude).
    pub fn units(&self) -> &[CompilationUnit] {
        &self.all_units[self.user_start..]
    }
    /// The user's units as parsed, before block lowering.
    pub fn source_units(&self) -> &[CompilationUnit] {
        self.source_copy.as_deref().unwrap_or(self.units())
    }
}

impl Default for Session {
    fn default() -> Self {
        Self::new()
    }
}

impl Session {
    /// An empty session: no sources, no diagnostics.
    pub fn new() -> Self {
        Session {
            map: SourceMap::new(),
            diags: Diagnostics::new(),
            overlay: std::collections::HashMap::new(),
        }
    }

    /// Reads and parses every input (IL, ST or PLCopen XML; `-` is standard input, read once).
    pub fn load(&mut self, paths: &[PathBuf]) -> Vec<CompilationUnit> {
        self.load_as(paths, None)
    }

    /// [`Session::load`] with every input read in `lang` when it is given.
    pub fn load_as(&mut self, paths: &[PathBuf], lang: Option<Lang>) -> Vec<CompilationUnit> {
        let mut units = Vec::new();
        let mut pending = Vec::new();
        let mut stdin_read = false;
        for p in paths {
            let stdin = is_stdin(p);
            let shown = if stdin {
                STDIN_NAME.to_string()
            } else {
                p.display().to_string()
            };
            let bytes = if stdin {
                if stdin_read {
                    self.diags.push(
                        Diagnostic::error(code::E9001, "`-` (standard input) is given twice")
                            .with_hint("standard input can be read once: give `-` once"),
                    );
                    continue;
                }
                stdin_read = true;
                let mut b = Vec::new();
                std::io::Read::read_to_end(&mut std::io::stdin(), &mut b).map(|_| b)
            } else if let Some(t) = self.overlay.get(p) {
                Ok(t.clone().into_bytes())
            } else {
                std::fs::read(p)
            };
            let text = match bytes {
                Ok(bytes) => match String::from_utf8(bytes) {
                    Ok(t) => t,
                    Err(_) => {
                        self.diags.push(
                            Diagnostic::error(code::E9001, format!("{shown} is not valid UTF-8"))
                                .with_hint("save the file as UTF-8"),
                        );
                        continue;
                    }
                },
                Err(e) => {
                    self.diags.push(
                        Diagnostic::error(code::E9001, format!("cannot read {shown}: {e}"))
                            .with_hint("check the path and its permissions"),
                    );
                    continue;
                }
            };
            // A UTF-8 byte-order mark is dropped: positions count from the first character after it.
            let text = match text.strip_prefix('\u{feff}') {
                Some(rest) => rest.to_string(),
                None => text,
            };
            let (file_lang, detected) = if stdin {
                (
                    lang.unwrap_or_else(|| il_frontend::st::file::detect(&text)),
                    lang.is_none(),
                )
            } else {
                input_lang(p, &text, lang)
            };
            let file = self.map.add(shown, text);
            // Borrowed from the source map (a field apart from the diagnostics): the text is held once.
            let src = &self.map.get(file).text;
            if detected {
                self.diags.push(
                    Diagnostic::new(
                        code::W0302,
                        diagnostics::Severity::Note,
                        format!("read as {} (detected from the content)", file_lang.name()),
                    )
                    .at(diagnostics::Span::new(file, 0, 0))
                    .with_hint(
                        "name the file .il, .st or .xml, or pass --lang il|st|xml, to choose",
                    ),
                );
            }
            if file_lang == Lang::Xml {
                units.push(ladder_compiler::compile_xml(file, src, &mut self.diags));
            } else {
                let stem = if stdin {
                    None
                } else {
                    p.file_stem().and_then(|s| s.to_str())
                };
                let implicit = match stem {
                    Some(stem) if is_iec_identifier(stem) => stem,
                    _ => il_frontend::DEFAULT_IMPLICIT_PROGRAM,
                };
                let (unit, bodies) = il_frontend::st::file::parse_text(
                    file,
                    src,
                    implicit,
                    file_lang,
                    &mut self.diags,
                );
                units.push(unit);
                pending.extend(bodies);
            }
        }
        il_frontend::st::file::compile_pending(&mut units, &pending, &mut self.diags);
        units
    }

    /// The front half: load, check, lower block calls. `None` when errors were reported.
    pub fn lower(&mut self, paths: &[PathBuf], opts: &Options) -> Option<Lowered> {
        let profile = match &opts.profile {
            Some(p) => c_backend::TargetProfile::load_or_report(p, &mut self.diags)?,
            None => c_backend::TargetProfile::default(),
        };
        let mut library = Library::builtin(&mut self.map, &mut self.diags);
        if let Some(dir) = &opts.templates {
            // Checks every user template in full (body tokens and names, its function compiled alone).
            library.add_dir(dir, &mut self.map, &mut self.diags);
        }
        let user = self.load_as(paths, opts.lang);
        if self.diags.has_errors() {
            return None;
        }
        let axes = self.axis_config(paths, opts.axes.as_deref())?;
        let uses_blocks = uses_library_blocks(&user, &library);
        let cycle_ms = match (axes.cycle_ms, opts.cycle_ms) {
            (Some(a), Some(c)) if (a - c).abs() > 1e-9 * a.abs().max(1.0) => {
                self.diags.push(
                    Diagnostic::error(
                        code::E5053,
                        format!(
                            "--cycle-ms {c} differs from the axis configuration's cycle_ms {a}"
                        ),
                    )
                    .with_hint(
                        "leave out --cycle-ms, or make both equal: the engine steps once per scan",
                    ),
                );
                return None;
            }
            (Some(a), _) => a,
            (None, Some(c)) => c,
            (None, None) => DEFAULT_CYCLE_MS,
        };
        // Check the user's program (with the block interfaces and the axes when it uses blocks).
        let mut checked = Vec::new();
        let axes_il = axes.globals_il();
        if uses_blocks {
            let pre = param_passing::prelude::before_lowering(&library);
            let f = self.map.add("<PLCopen blocks>", pre.clone());
            checked.push(il_frontend::parse(f, &pre, &mut self.diags));
            let f = self.map.add("<axis configuration>", axes_il.clone());
            checked.push(il_frontend::parse(f, &axes_il, &mut self.diags));
        }
        // Without blocks the checked program is the compiled one: no copy.
        let user = if uses_blocks {
            checked.extend(user.iter().cloned());
            user
        } else {
            checked.extend(user);
            Vec::new()
        };
        let checked_model = il_frontend::sema::analyze(&checked, &mut self.diags);
        if self.diags.has_errors() {
            if uses_blocks && opts.axes.is_none() && axes.axes.is_empty() && axes.groups.is_empty()
            {
                self.hint_axes_file(paths);
            }
            return None;
        }
        let window = TmWindow {
            offset: profile.tm_offset,
            bytes: profile.tm_bytes,
            element_addressing: profile.address_unit == c_backend::AddressUnit::Element,
        };
        let mut lowering = if uses_blocks {
            lower::lower(&user, &library, opts.strategy, &window, &mut self.diags)
        } else {
            lower::Lowered::default()
        };
        if self.diags.has_errors() {
            return None;
        }
        // The model is valid only for the very units it was computed from (it keys instructions by
        // identity): without block lowering those are `checked`, which is then compiled as it is.
        let user_start = if uses_blocks { 2 } else { 0 };
        let all_units = if uses_blocks {
            let mut all_units = Vec::new();
            let post = param_passing::prelude::after_lowering(&library);
            let f = self.map.add("<PLCopen block instances>", post.clone());
            all_units.push(il_frontend::parse(f, &post, &mut self.diags));
            let f = self.map.add("<axis configuration>", axes_il.clone());
            all_units.push(il_frontend::parse(f, &axes_il, &mut self.diags));
            all_units.append(&mut lowering.units);
            all_units
        } else {
            checked
        };
        Some(Lowered {
            source_copy: uses_blocks.then_some(user),
            all_units,
            user_start,
            lowering,
            library,
            profile,
            uses_blocks,
            axes,
            cycle_ms,
            model: (!uses_blocks).then_some(checked_model),
        })
    }

    /// A motion program without an axes file: every undeclared name (E1001) may be an axis or group that
    /// the missing file would declare, so its hint says where the file was looked for.
    fn hint_axes_file(&mut self, paths: &[PathBuf]) {
        let looked = paths
            .first()
            .and_then(|p| default_axes_path(p))
            .map(|p| format!("`{}`", p.display()))
            .unwrap_or_else(|| "`<input stem>.axes.json`".into());
        let list = std::mem::take(&mut self.diags).into_vec();
        self.diags.extend(list.into_iter().map(|mut d| {
            if d.code == code::E1001 {
                let axes = format!(
                    "if it is an axis or axes group, declare it in an axes file: none was found \
                     (looked for {looked}); pass `--axes FILE.json` (crates/ladderc/AXES.md)"
                );
                d.hint = Some(match d.hint.take() {
                    Some(h) => format!("{h}; {axes}"),
                    None => axes,
                });
            }
            d
        }));
    }

    /// The axis configuration: `explicit`, else `<stem>.axes.json` beside the first input when it
    /// exists, else the empty default. `None`: it could not be read or had errors.
    fn axis_config(&mut self, paths: &[PathBuf], explicit: Option<&Path>) -> Option<AxisConfig> {
        let path = match explicit {
            Some(p) => p.to_path_buf(),
            None => match paths
                .first()
                .filter(|p| !is_stdin(p))
                .and_then(|p| default_axes_path(p))
            {
                Some(p) if p.is_file() => p,
                _ => return Some(AxisConfig::default()),
            },
        };
        let text = match std::fs::read_to_string(&path) {
            Ok(t) => t,
            Err(e) => {
                self.diags.push(
                    Diagnostic::error(code::E9001, format!("cannot read {}: {e}", path.display()))
                        .with_hint("check the --axes path"),
                );
                return None;
            }
        };
        let text = text.strip_prefix('\u{feff}').unwrap_or(&text).to_string();
        let f = self.map.add(path.display().to_string(), text);
        AxisConfig::parse(&self.map, f, &mut self.diags)
    }

    /// The whole pipeline to a C project.
    pub fn compile(
        &mut self,
        paths: &[PathBuf],
        opts: &Options,
    ) -> Option<(Lowered, c_backend::CProgram)> {
        let mut lowered = self.lower(paths, opts)?;
        let model = match lowered.model.take() {
            Some(m) => m,
            None => {
                // The lowered program: its warnings were given on the user's program already; an error
                // here would be a lowering bug, and is reported.
                let mut second = Diagnostics::new();
                let m = il_frontend::sema::analyze(&lowered.all_units, &mut second);
                self.diags.extend(
                    second
                        .into_iter()
                        .filter(|d| d.severity == diagnostics::Severity::Error),
                );
                m
            }
        };
        if self.diags.has_errors() {
            return None;
        }
        let embedded = embedded_functions(&lowered);
        let copts = c_backend::Options { embedded };
        let ext = c_backend::Extensions {
            motion: lowered
                .uses_blocks
                .then(|| lowered.axes.runtime(lowered.cycle_ms, MOTION_HEADER)),
            methods: lowered
                .lowering
                .synthesized
                .iter()
                .map(pou_method)
                .collect(),
        };
        let program = c_backend::generate_with(
            &lowered.all_units,
            &model,
            &lowered.profile,
            &copts,
            &ext,
            &mut self.diags,
        )?;
        lowered.model = Some(model);
        Some((lowered, program))
    }
}

/// `<stem>.axes.json` beside `input`.
pub fn default_axes_path(input: &Path) -> Option<PathBuf> {
    let stem = input.file_stem()?.to_str()?;
    Some(input.with_file_name(format!("{stem}.axes.json")))
}

/// A template-method function for the C backend.
fn pou_method(s: &lower::Synthesized) -> c_backend::PouMethod {
    use param_passing::template::TypeClass;
    c_backend::PouMethod {
        name: s.name.clone(),
        pou: s.pou.clone(),
        func_num: s.func_num,
        head: s
            .head
            .iter()
            .map(|h| c_backend::MethodLocal {
                c_type: h.c_type.to_string(),
                local: h.local.clone(),
                boolean: h.class == TypeClass::Bool,
                source: h.source.clone(),
            })
            .collect(),
        locals: s.locals.clone(),
        body: s.body.clone(),
        tail: s
            .tail
            .iter()
            .map(|f| c_backend::MethodFeedback {
                target: f.target.clone(),
                local: f.local.clone(),
                c_type: s
                    .head
                    .iter()
                    .find(|h| h.local == f.local)
                    .map_or("uint8_t", |h| h.c_type)
                    .to_string(),
                boolean: f.class == TypeClass::Bool,
                negated: f.negated,
            })
            .collect(),
        span: s.call_span,
    }
}

/// The static-library functions of the IL method as embedded C for the backend.
fn embedded_functions(l: &Lowered) -> Vec<c_backend::EmbeddedFunction> {
    let mut out = Vec::new();
    if l.lowering.static_functions.is_empty() {
        return out;
    }
    let used: Vec<&str> = l
        .lowering
        .static_functions
        .keys()
        .map(String::as_str)
        .collect();
    let pairs: Vec<_> = used
        .iter()
        .filter_map(|b| {
            l.library
                .get(b)
                .map(|t| (t, &l.lowering.static_functions[*b]))
        })
        .collect();
    let lib = param_passing::static_lib::library_c(pairs, &used);
    for (i, b) in used.iter().enumerate() {
        out.push(c_backend::EmbeddedFunction {
            name: b.to_string(),
            c_source: if i == 0 { lib.clone() } else { String::new() },
        });
    }
    out
}

fn uses_library_blocks(units: &[CompilationUnit], lib: &Library) -> bool {
    use il_frontend::ast::{LibraryElement, TypeRef};
    units.iter().flat_map(|u| u.items.iter()).any(|item| {
        let blocks: Vec<&il_frontend::ast::VarBlock> = match item {
            LibraryElement::Pou(p) => p.var_blocks.iter().collect(),
            LibraryElement::GlobalVars(b) => vec![b],
            LibraryElement::Configuration(c) => c.globals.iter().chain(c.resources.iter().flat_map(|r| r.globals.iter())).collect(),
            LibraryElement::DataTypes(_) => vec![],
        };
        blocks.iter().flat_map(|b| b.vars.iter()).any(|v| {
            matches!(&v.ty, TypeRef::Named(t) if lib.get(&t.name).is_some() || t.is("AXIS_REF") || t.is("AXES_GROUP_REF"))
        })
    })
}

fn is_iec_identifier(s: &str) -> bool {
    let mut c = s.chars();
    matches!(c.next(), Some(ch) if ch.is_ascii_alphabetic() || ch == '_')
        && c.all(|ch| ch.is_ascii_alphanumeric() || ch == '_')
        && !s.contains("__")
}

/// The file name for a trace written next to `path` while the program runs (renamed on success).
pub fn staging_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "out".into());
    path.with_file_name(format!(".{name}.partial"))
}
