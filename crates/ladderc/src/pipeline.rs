//! The compilation pipeline behind `check`, `build` and `run`.
//!
//! Input: source paths (`.xml` PLCopen projects, anything else IL) and options. Output: the source map, the
//! diagnostics, and (when there are no errors) the lowered IL units and the C project.
//! Stages: read -> parse (IL) or read + lower ladder (XML) -> semantic checks against the PLCopen block
//! prelude -> parameter passing (block calls by the chosen strategy) -> semantic model of the lowered
//! program -> C. Invariant: a stage runs only when the ones before it reported no error.

use diagnostics::{code, Diagnostic, Diagnostics, SourceMap};
use il_frontend::ast::CompilationUnit;
use param_passing::library::Library;
use param_passing::lower::{self, Strategy, TmWindow};
use std::path::{Path, PathBuf};

pub struct Options {
    pub profile: Option<PathBuf>,
    pub strategy: Strategy,
    pub templates: Option<PathBuf>,
}

pub struct Session {
    pub map: SourceMap,
    pub diags: Diagnostics,
}

/// What a successful front half produced.
pub struct Lowered {
    /// The user's units after block lowering (without the prelude).
    pub units: Vec<CompilationUnit>,
    /// Units to compile: the post-lowering prelude (when blocks are used) and the user's units.
    pub all_units: Vec<CompilationUnit>,
    pub lowering: lower::Lowered,
    pub library: Library,
    pub profile: c_backend::TargetProfile,
}

impl Session {
    pub fn new() -> Self {
        Session {
            map: SourceMap::new(),
            diags: Diagnostics::new(),
        }
    }

    /// Reads and parses every input (IL or PLCopen XML).
    pub fn load(&mut self, paths: &[PathBuf]) -> Vec<CompilationUnit> {
        let mut units = Vec::new();
        for p in paths {
            let text = match std::fs::read(p) {
                Ok(bytes) => match String::from_utf8(bytes) {
                    Ok(t) => t,
                    Err(_) => {
                        self.diags.push(
                            Diagnostic::error(
                                code::E9001,
                                format!("{} is not valid UTF-8", p.display()),
                            )
                            .with_hint("save the file as UTF-8"),
                        );
                        continue;
                    }
                },
                Err(e) => {
                    self.diags.push(
                        Diagnostic::error(code::E9001, format!("cannot read {}: {e}", p.display()))
                            .with_hint("check the path and its permissions"),
                    );
                    continue;
                }
            };
            let name = p.display().to_string();
            let is_xml = p.extension().is_some_and(|e| e.eq_ignore_ascii_case("xml"));
            // A UTF-8 byte-order mark is dropped: positions count from the first character after it.
            let text = match text.strip_prefix('\u{feff}') {
                Some(rest) => rest.to_string(),
                None => text,
            };
            let file = self.map.add(name, text);
            let src = self.map.get(file).text.clone();
            if is_xml {
                units.push(ladder_compiler::compile_xml(file, &src, &mut self.diags));
            } else {
                let stem = p.file_stem().and_then(|s| s.to_str()).unwrap_or("main");
                let implicit = if is_iec_identifier(stem) {
                    stem
                } else {
                    il_frontend::DEFAULT_IMPLICIT_PROGRAM
                };
                units.push(il_frontend::parse_named(
                    file,
                    &src,
                    implicit,
                    &mut self.diags,
                ));
            }
        }
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
            library.add_dir(dir, &mut self.map, &mut self.diags);
            library.check_bodies(&param_passing::library::runtime_symbols(), &mut self.diags);
        }
        let user = self.load(paths);
        if self.diags.has_errors() {
            return None;
        }
        let uses_blocks = uses_library_blocks(&user, &library);
        // Check the user's program (with the block interfaces when it uses blocks).
        let mut checked = Vec::new();
        if uses_blocks {
            let pre = param_passing::prelude::before_lowering(&library);
            let f = self.map.add("<PLCopen blocks>", pre.clone());
            checked.push(il_frontend::parse(f, &pre, &mut self.diags));
        }
        checked.extend(user.iter().cloned());
        il_frontend::sema::analyze(&checked, &mut self.diags);
        if self.diags.has_errors() {
            return None;
        }
        let window = TmWindow {
            offset: profile.tm_offset,
            bytes: profile.tm_bytes,
            element_addressing: profile.address_unit == c_backend::AddressUnit::Element,
        };
        let lowering = if uses_blocks {
            lower::lower(&user, &library, opts.strategy, &window, &mut self.diags)
        } else {
            lower::Lowered {
                units: user,
                ..Default::default()
            }
        };
        if self.diags.has_errors() {
            return None;
        }
        let mut all_units = Vec::new();
        if uses_blocks {
            let post = param_passing::prelude::after_lowering(&library);
            let f = self.map.add("<PLCopen block instances>", post.clone());
            all_units.push(il_frontend::parse(f, &post, &mut self.diags));
        }
        all_units.extend(lowering.units.iter().cloned());
        Some(Lowered {
            units: lowering.units.clone(),
            all_units,
            lowering,
            library,
            profile,
        })
    }

    /// The whole pipeline to a C project.
    pub fn compile(
        &mut self,
        paths: &[PathBuf],
        opts: &Options,
    ) -> Option<(Lowered, c_backend::CProgram)> {
        let lowered = self.lower(paths, opts)?;
        let model = il_frontend::sema::analyze(&lowered.all_units, &mut self.diags);
        if self.diags.has_errors() {
            return None;
        }
        let embedded = embedded_functions(&lowered);
        let copts = c_backend::Options { embedded };
        let program = c_backend::generate(
            &lowered.all_units,
            &model,
            &lowered.profile,
            &copts,
            &mut self.diags,
        )?;
        Some((lowered, program))
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
