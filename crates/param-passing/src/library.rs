//! The block library: the built-in templates (`templates/*.xml` of the repository, compiled in) plus a user
//! directory (`--templates DIR`), whose files replace built-ins of the same block name.
//!
//! Input: template files. Output: a [`Library`] of validated templates, looked up case-insensitively by block
//! name; every problem is a diagnostic in the template file. Invariant: block names are unique in a library;
//! a template of the user directory is in the library only if its body passed the checks of [`crate::cbody`]
//! and its function compiled alone ([`crate::ccheck`]).

use crate::cbody::{self, Scope};
use crate::template::{self, Template};
use diagnostics::{code, Diagnostic, Diagnostics, FileId, SourceMap};
use std::cell::OnceCell;
use std::collections::BTreeSet;
use std::path::Path;

/// The built-in templates: (file name, text).
pub const BUILTIN: &[(&str, &str)] = &[
    (
        "MC_AddAxisToGroup.xml",
        include_str!("../../../templates/MC_AddAxisToGroup.xml"),
    ),
    (
        "MC_GearIn.xml",
        include_str!("../../../templates/MC_GearIn.xml"),
    ),
    (
        "MC_GearOut.xml",
        include_str!("../../../templates/MC_GearOut.xml"),
    ),
    (
        "MC_GroupDisable.xml",
        include_str!("../../../templates/MC_GroupDisable.xml"),
    ),
    (
        "MC_GroupEnable.xml",
        include_str!("../../../templates/MC_GroupEnable.xml"),
    ),
    (
        "MC_GroupHalt.xml",
        include_str!("../../../templates/MC_GroupHalt.xml"),
    ),
    (
        "MC_GroupHome.xml",
        include_str!("../../../templates/MC_GroupHome.xml"),
    ),
    (
        "MC_GroupReadActualPosition.xml",
        include_str!("../../../templates/MC_GroupReadActualPosition.xml"),
    ),
    (
        "MC_GroupReadActualVelocity.xml",
        include_str!("../../../templates/MC_GroupReadActualVelocity.xml"),
    ),
    (
        "MC_GroupReadStatus.xml",
        include_str!("../../../templates/MC_GroupReadStatus.xml"),
    ),
    (
        "MC_GroupReset.xml",
        include_str!("../../../templates/MC_GroupReset.xml"),
    ),
    (
        "MC_GroupStop.xml",
        include_str!("../../../templates/MC_GroupStop.xml"),
    ),
    (
        "MC_Halt.xml",
        include_str!("../../../templates/MC_Halt.xml"),
    ),
    (
        "MC_Home.xml",
        include_str!("../../../templates/MC_Home.xml"),
    ),
    (
        "MC_MoveAbsolute.xml",
        include_str!("../../../templates/MC_MoveAbsolute.xml"),
    ),
    (
        "MC_MoveAdditive.xml",
        include_str!("../../../templates/MC_MoveAdditive.xml"),
    ),
    (
        "MC_MoveCircularAbsolute.xml",
        include_str!("../../../templates/MC_MoveCircularAbsolute.xml"),
    ),
    (
        "MC_MoveCircularRelative.xml",
        include_str!("../../../templates/MC_MoveCircularRelative.xml"),
    ),
    (
        "MC_MoveDirectAbsolute.xml",
        include_str!("../../../templates/MC_MoveDirectAbsolute.xml"),
    ),
    (
        "MC_MoveLinearAbsolute.xml",
        include_str!("../../../templates/MC_MoveLinearAbsolute.xml"),
    ),
    (
        "MC_MoveLinearRelative.xml",
        include_str!("../../../templates/MC_MoveLinearRelative.xml"),
    ),
    (
        "MC_MoveRelative.xml",
        include_str!("../../../templates/MC_MoveRelative.xml"),
    ),
    (
        "MC_MoveVelocity.xml",
        include_str!("../../../templates/MC_MoveVelocity.xml"),
    ),
    (
        "MC_Power.xml",
        include_str!("../../../templates/MC_Power.xml"),
    ),
    (
        "MC_ReadActualPosition.xml",
        include_str!("../../../templates/MC_ReadActualPosition.xml"),
    ),
    (
        "MC_ReadActualVelocity.xml",
        include_str!("../../../templates/MC_ReadActualVelocity.xml"),
    ),
    (
        "MC_ReadAxisError.xml",
        include_str!("../../../templates/MC_ReadAxisError.xml"),
    ),
    (
        "MC_ReadStatus.xml",
        include_str!("../../../templates/MC_ReadStatus.xml"),
    ),
    (
        "MC_RemoveAxisFromGroup.xml",
        include_str!("../../../templates/MC_RemoveAxisFromGroup.xml"),
    ),
    (
        "MC_Reset.xml",
        include_str!("../../../templates/MC_Reset.xml"),
    ),
    (
        "MC_SetOverride.xml",
        include_str!("../../../templates/MC_SetOverride.xml"),
    ),
    (
        "MC_SetPosition.xml",
        include_str!("../../../templates/MC_SetPosition.xml"),
    ),
    (
        "MC_Stop.xml",
        include_str!("../../../templates/MC_Stop.xml"),
    ),
    (
        "MC_UngroupAllAxes.xml",
        include_str!("../../../templates/MC_UngroupAllAxes.xml"),
    ),
];

/// The parameter templates a program can call, by block name: the built-ins and the user's.
///
/// The built-ins are read on first use: [`Library::builtin`] registers their files in the source map
/// (so file ids do not depend on whether a program uses a block), and their XML is parsed only when a
/// lookup names a built-in block, when every template is asked for, or when a template is added.
#[derive(Debug, Default, Clone)]
pub struct Library {
    /// The built-ins not read yet: their file ids, indexes into [`BUILTIN`] and block names (each
    /// block's name is its file's stem, test `builtin_block_names_are_their_file_stems`; kept here so
    /// that a lookup compares names without stripping the file name each time: `ladderc build` looks
    /// up the type of every variable, 40,000 lookups for 10,000 generated rungs).
    pending: Vec<(FileId, usize, &'static str)>,
    /// Every template once the pending built-ins are read (they come first, in [`BUILTIN`] order).
    templates: OnceCell<Vec<Template>>,
}

impl Library {
    /// An empty library.
    pub fn new() -> Self {
        Self::default()
    }
    /// Loads the built-in templates.
    /// Their files are added to `map` now; their XML is read on first use (a built-in template
    /// reports no diagnostics: `diags` is kept for the signature).
    pub fn builtin(map: &mut SourceMap, diags: &mut Diagnostics) -> Self {
        let _ = diags;
        let pending = BUILTIN
            .iter()
            .enumerate()
            .map(|(k, (name, text))| {
                (
                    map.add(format!("templates/{name}"), *text),
                    k,
                    Self::pending_block(k),
                )
            })
            .collect();
        Library {
            pending,
            templates: OnceCell::new(),
        }
    }

    /// Every template, the pending built-ins read first.
    fn all(&self) -> &Vec<Template> {
        self.templates.get_or_init(|| {
            let mut quiet = Diagnostics::new();
            let out: Vec<Template> = self
                .pending
                .iter()
                .filter_map(|&(file, k, _)| template::load(file, BUILTIN[k].1, &mut quiet))
                .collect();
            debug_assert!(quiet.is_empty(), "a built-in template reported diagnostics");
            out
        })
    }

    /// [`Library::all`], to change.
    fn all_mut(&mut self) -> &mut Vec<Template> {
        self.all();
        self.pending.clear();
        self.templates.get_mut().expect("read just above")
    }

    /// The block name of a pending built-in (its file's stem).
    fn pending_block(k: usize) -> &'static str {
        BUILTIN[k].0.strip_suffix(".xml").unwrap_or(BUILTIN[k].0)
    }
    /// Loads every `*.xml` of `dir` (sorted by name); they replace built-ins of the same block name. Each is
    /// checked in full, its function compiled alone with the C compiler ([`Library::add_user_texts`]).
    pub fn add_dir(&mut self, dir: &Path, map: &mut SourceMap, diags: &mut Diagnostics) {
        self.add_dir_with(dir, true, map, diags);
    }

    /// [`Library::add_dir`]; `compile_c`: whether each template's function is also compiled alone with the
    /// C compiler (which starts `$CC`).
    pub fn add_dir_with(
        &mut self,
        dir: &Path,
        compile_c: bool,
        map: &mut SourceMap,
        diags: &mut Diagnostics,
    ) {
        let entries = match std::fs::read_dir(dir) {
            Ok(e) => e,
            Err(e) => {
                diags.push(
                    Diagnostic::error(
                        code::E9001,
                        format!("cannot read the template directory {}: {e}", dir.display()),
                    )
                    .with_hint("pass an existing directory of template files to --templates"),
                );
                return;
            }
        };
        let mut paths: Vec<_> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x.eq_ignore_ascii_case("xml")))
            .collect();
        paths.sort();
        let mut files = Vec::new();
        for p in paths {
            match std::fs::read_to_string(&p) {
                Ok(text) => files.push((p.display().to_string(), text)),
                Err(e) => diags.push(
                    Diagnostic::error(code::E9001, format!("cannot read {}: {e}", p.display()))
                        .with_hint("template files must be readable UTF-8"),
                ),
            }
        }
        self.add_user_texts(&files, compile_c, map, diags);
    }

    /// Adds user templates given as `(file name, text)`, in that order; they replace built-ins (and earlier
    /// ones) of the same block name. A user template is checked in full before it is used: its schema, its
    /// body's tokens and names, then (when `compile_c`) its function compiled alone with `$CC`. A template
    /// that fails is dropped (its diagnostics stop the build).
    pub fn add_user_texts(
        &mut self,
        files: &[(String, String)],
        compile_c: bool,
        map: &mut SourceMap,
        diags: &mut Diagnostics,
    ) {
        let mut added = Vec::new();
        for (name, text) in files {
            if let Some(block) = self.add_text(map, name, text, diags) {
                added.push(block);
            }
        }
        let runtime = runtime_symbol_set();
        let templates = self.all_mut();
        let embedded: BTreeSet<String> = templates.iter().map(|t| t.block.clone()).collect();
        for block in added {
            let Some(k) = templates.iter().position(|t| t.block == block) else {
                continue;
            };
            let t = &templates[k];
            let clean = cbody::check(
                &t.body,
                &Self::scope(t, runtime, &embedded),
                &t.block,
                diags,
            ) && (!compile_c || crate::ccheck::compile(t, diags));
            if !clean {
                templates.remove(k);
            }
        }
    }

    /// What the body of `t` may refer to.
    fn scope<'a>(
        t: &Template,
        runtime: &'a BTreeSet<String>,
        embedded: &'a BTreeSet<String>,
    ) -> Scope<'a> {
        let mut declared: BTreeSet<String> = t.params.iter().map(|p| p.abbr.clone()).collect();
        declared.insert("FuncNum".into());
        declared.extend(t.locals.iter().map(|l| l.name.clone()));
        Scope {
            declared,
            runtime,
            embedded_functions: embedded,
        }
    }
    /// Adds one template file's text (replacing a template of the same block name); returns the block name.
    /// Only the schema is checked here; [`Library::add_dir`] also checks the body and compiles it.
    pub fn add_text(
        &mut self,
        map: &mut SourceMap,
        name: &str,
        text: &str,
        diags: &mut Diagnostics,
    ) -> Option<String> {
        let file = map.add(name, text);
        let t = template::load(file, text, diags)?;
        let templates = self.all_mut();
        templates.retain(|old| !old.block.eq_ignore_ascii_case(&t.block));
        let block = t.block.clone();
        templates.push(t);
        Some(block)
    }
    /// The template of `block` (case-insensitive). Reads the built-ins only when `block` is one of
    /// their names.
    pub fn get(&self, block: &str) -> Option<&Template> {
        if self.templates.get().is_none()
            && !self
                .pending
                .iter()
                .any(|&(_, _, name)| name.eq_ignore_ascii_case(block))
        {
            return None;
        }
        self.all()
            .iter()
            .find(|t| t.block.eq_ignore_ascii_case(block))
    }
    /// Every template.
    pub fn templates(&self) -> &[Template] {
        self.all()
    }
    /// Checks every body against its head and the runtime symbols (see [`crate::cbody`]).
    pub fn check_bodies(&self, runtime: &BTreeSet<String>, diags: &mut Diagnostics) -> bool {
        let embedded: BTreeSet<String> = self.all().iter().map(|t| t.block.clone()).collect();
        let mut clean = true;
        for t in self.all() {
            clean &= cbody::check(
                &t.body,
                &Self::scope(t, runtime, &embedded),
                &t.block,
                diags,
            );
        }
        clean
    }

    /// Compiles every template's function alone (see [`crate::ccheck`]); the test of the built-in templates.
    pub fn compile_all(&self, diags: &mut Diagnostics) -> bool {
        let mut clean = true;
        for t in self.all() {
            clean &= crate::ccheck::compile(t, diags);
        }
        clean
    }
}

/// The identifiers a C header declares at file scope: macro names (`#define NAME`), typedef names, struct
/// tags and function names. Comments, `#include` lines, parameter names and members are not declarations;
/// `#ifdef __cplusplus` blocks are skipped.
pub fn header_symbols(header: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut code = String::with_capacity(header.len());
    let mut skip_depth = 0usize;
    for line in header.lines() {
        let t = line.trim_start();
        if let Some(d) = t.strip_prefix('#') {
            let d = d.trim_start();
            if skip_depth > 0 {
                if d.starts_with("if") {
                    skip_depth += 1;
                } else if d.starts_with("endif") {
                    skip_depth -= 1;
                }
            } else if d.starts_with("ifdef __cplusplus") {
                skip_depth = 1;
            } else if let Some(rest) = d.strip_prefix("define") {
                let name: String = rest
                    .trim_start()
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                if !name.is_empty() && !name.ends_with("_H") {
                    out.insert(name);
                }
            }
            code.push('\n');
            continue;
        }
        if skip_depth == 0 {
            code.push_str(line);
        }
        code.push('\n');
    }
    let (toks, _) = cbody::tokens(&code);
    let text = |t: &cbody::Token| &code[t.start..t.end];
    let (mut braces, mut parens) = (0usize, 0usize);
    let mut in_typedef = false;
    for (k, t) in toks.iter().enumerate() {
        match t.kind {
            cbody::Tok::Punct(b'{') => braces += 1,
            cbody::Tok::Punct(b'}') => braces = braces.saturating_sub(1),
            cbody::Tok::Punct(b'(') => parens += 1,
            cbody::Tok::Punct(b')') => parens = parens.saturating_sub(1),
            cbody::Tok::Punct(b';') if braces == 0 && parens == 0 => {
                if in_typedef && k > 0 && toks[k - 1].kind == cbody::Tok::Ident {
                    out.insert(text(&toks[k - 1]).to_string());
                }
                in_typedef = false;
            }
            cbody::Tok::Ident if braces == 0 && parens == 0 => {
                let name = text(t);
                if name == "typedef" {
                    in_typedef = true;
                } else if (k > 0 && text(&toks[k - 1]) == "struct")
                    || (toks
                        .get(k + 1)
                        .is_some_and(|n| n.kind == cbody::Tok::Punct(b'('))
                        && !crate::template::C_KEYWORDS.contains(&name))
                {
                    // A struct tag, or a function's name.
                    out.insert(name.to_string());
                }
            }
            _ => {}
        }
    }
    out
}

/// The complete struct types of the motion library's header (`MC_MoveAbsolute_C` ...): with the
/// fixed-width scalar types, the only C types a template `<local>` may have.
pub fn header_struct_types() -> &'static BTreeSet<String> {
    static TYPES: std::sync::OnceLock<BTreeSet<String>> = std::sync::OnceLock::new();
    TYPES.get_or_init(|| {
        let mut out = BTreeSet::new();
        for line in MOTION_HEADER.lines() {
            if let Some(rest) = line.strip_prefix("typedef struct ") {
                if let Some(name) = rest.strip_suffix(" {") {
                    out.insert(name.trim().to_string());
                }
            }
        }
        out
    })
}

/// [`runtime_symbols`], computed once.
pub fn runtime_symbol_set() -> &'static BTreeSet<String> {
    static SET: std::sync::OnceLock<BTreeSet<String>> = std::sync::OnceLock::new();
    SET.get_or_init(runtime_symbols)
}

/// The symbols template bodies may use: the motion library header's declarations and the runtime's
/// engine accessor.
pub fn runtime_symbols() -> BTreeSet<String> {
    let mut s = header_symbols(MOTION_HEADER);
    s.insert("ladderc_motion_engine".into());
    s
}

/// The motion library's C header (generated by cbindgen, committed in crates/motion-lib/include).
pub const MOTION_HEADER: &str = include_str!("../../motion-lib/include/motion_lib.h");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_symbols_are_declarations_only() {
        let s = runtime_symbols();
        for name in [
            "mc_move_absolute",
            "MC_MoveAbsolute_C",
            "McEngine",
            "MC_ABORTING",
            "ladderc_motion_engine",
        ] {
            assert!(s.contains(name), "{name}");
        }
        // Included headers, directive words, parameter names and members are not symbols a body may use.
        for name in [
            "stdlib",
            "include",
            "define",
            "ifndef",
            "system",
            "engine",
            "Execute",
            "MOTION_LIB_H",
            "extern",
        ] {
            assert!(!s.contains(name), "{name}");
        }
        assert!(header_struct_types().contains("MC_MoveAbsolute_C"));
        assert!(!header_struct_types().contains("McEngine"));
    }
}
