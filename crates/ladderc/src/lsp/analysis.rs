//! What the language server knows about one document: its diagnostics and its semantic model.
//!
//! Input: the document's path and text (the editor's buffer, which may be unsaved), the project around it
//! (the axes file `<stem>.axes.json` beside it, a `templates/` folder of the workspace root).
//! Output: the diagnostics of `ladderc check` for the document (the whole pipeline to C, in memory), and a
//! semantic model of the document (with the PLCopen block interfaces and the axes declared before it) for
//! hover, go to definition, document symbols and completion.
//! Invariants: nothing is written to disk; every offset handed out lies inside the document's text.

use crate::pipeline::{self, Options, Session};
use diagnostics::{Diagnostic, FileId, SourceMap, Span};
use il_frontend::ast::{PouKind, VarKind};
use il_frontend::sema::model::{FbType, Model, NameRef, Type, Variable};
use param_passing::library::Library;
use param_passing::template::Direction;
use std::path::{Path, PathBuf};

/// One analysed document.
pub struct Analysis {
    /// The document's path.
    pub path: PathBuf,
    /// The document's text (the editor's buffer).
    pub text: String,
    /// The document's diagnostics (those located in other files, or nowhere, are kept too: the server shows
    /// them at the start of the document).
    pub diagnostics: Vec<(Option<Span>, Diagnostic)>,
    map: SourceMap,
    file: Option<FileId>,
    model: Model,
    library: Library,
}

/// The project options for a document: the templates folder of the workspace root, if there is one.
pub fn options(root: Option<&Path>) -> Options {
    let templates = root
        .map(|r| r.join("templates"))
        .filter(|t| t.is_dir() && t.read_dir().is_ok());
    Options {
        profile: None,
        strategy: param_passing::lower::Strategy::Template,
        templates,
        axes: None,
        cycle_ms: None,
        lang: None,
        compile_templates: true,
        libraries: Vec::new(),
    }
}

/// Analyses `text` as the content of `path`.
pub fn analyze(path: &Path, text: &str, root: Option<&Path>) -> Analysis {
    let opts = options(root);
    let paths = vec![path.to_path_buf()];
    // Diagnostics: the whole pipeline, as `ladderc check` runs it, on the buffer's text.
    let mut check = Session::new();
    check.overlay.insert(path.to_path_buf(), text.to_string());
    let _ = check.compile(&paths, &opts);
    let doc_file = check
        .map
        .files()
        .find(|(_, f)| Path::new(&f.name) == path)
        .map(|(id, _)| id);
    let diagnostics = check
        .diags
        .into_sorted()
        .into_iter()
        .map(|d| {
            let span = d.span.filter(|s| Some(s.file) == doc_file);
            (span, d)
        })
        .collect();
    // Navigation: the document's model, with the block interfaces and axes declared before it.
    let mut s = Session::new();
    s.overlay.insert(path.to_path_buf(), text.to_string());
    let mut quiet = diagnostics::Diagnostics::new();
    let library = Library::builtin(&mut s.map, &mut quiet);
    let mut units = Vec::new();
    let pre = param_passing::prelude::before_lowering(&library);
    let f = s.map.add("<PLCopen blocks>", pre.clone());
    units.push(il_frontend::parse(f, &pre, &mut quiet));
    let mut cfg = None;
    if let Some(axes) = pipeline::default_axes_path(path).filter(|p| p.is_file()) {
        if let Ok(t) = std::fs::read_to_string(&axes) {
            let f = s.map.add(axes.display().to_string(), t);
            cfg = crate::axes::AxisConfig::parse(&s.map, f, &mut quiet);
        }
    }
    // as `ladderc check` reads them: the Tc2_MC2 blocks ladderc builds, the AXIS_REFs linked to
    // the axes (a GVL's `Axis1` named like an axis is that axis, declared once)
    let mut user = s.load(&paths);
    let mut cfg = cfg.unwrap_or_default();
    cfg.tc2_tables = crate::tc2_blocks::add(&mut user, &mut s.map, &mut quiet);
    crate::axis_links::link(&mut user, &mut cfg, &mut quiet);
    let il = cfg.globals_il();
    let f = s.map.add("<axis configuration>", il.clone());
    units.push(il_frontend::parse(f, &il, &mut quiet));
    units.extend(user);
    let file = s
        .map
        .files()
        .find(|(_, f)| Path::new(&f.name) == path)
        .map(|(id, _)| id);
    let model = {
        let _twincat = il_frontend::sema::TwinCatFiles::set(s.twincat_files.iter().copied());
        let _codesys = il_frontend::sema::CodesysFiles::set(s.codesys_files.iter().copied());
        il_frontend::sema::analyze(&units, &mut quiet)
    };
    Analysis {
        path: path.to_path_buf(),
        text: text.to_string(),
        diagnostics,
        map: s.map,
        file,
        model,
        library,
    }
}

fn kind_word(k: VarKind) -> &'static str {
    match k {
        VarKind::Local => "VAR",
        VarKind::Input => "VAR_INPUT",
        VarKind::Output => "VAR_OUTPUT",
        VarKind::InOut => "VAR_IN_OUT",
        VarKind::Temp => "VAR_TEMP",
        VarKind::Global => "VAR_GLOBAL",
        VarKind::External => "VAR_EXTERNAL",
    }
}

fn pou_word(k: PouKind) -> &'static str {
    match k {
        PouKind::Program => "PROGRAM",
        PouKind::FunctionBlock => "FUNCTION_BLOCK",
        PouKind::Function => "FUNCTION",
    }
}

/// A variable that a name or declaration at the cursor stands for.
pub struct Target<'a> {
    /// The variable.
    pub var: &'a Variable,
    /// The POU that declares it (None: a global).
    pub pou: Option<usize>,
}

impl Analysis {
    fn in_doc(&self, s: &Span, offset: usize) -> bool {
        Some(s.file) == self.file && s.start as usize <= offset && offset <= s.end as usize
    }

    /// The POU (index into the model) whose text contains `offset`.
    fn pou_at(&self, offset: usize) -> Option<usize> {
        self.model
            .pous
            .iter()
            .position(|p| self.in_doc(&p.span, offset))
    }

    /// The variable used or declared at `offset`.
    pub fn target(&self, offset: usize) -> Option<Target<'_>> {
        let pou = self.pou_at(offset);
        // A use in a body.
        for (span, r) in self.model.names.iter() {
            if !self.in_doc(span, offset) {
                continue;
            }
            match r {
                NameRef::Var(i) => {
                    let p = pou?;
                    return Some(Target {
                        var: self.model.pous[p].vars.get(*i)?,
                        pou: Some(p),
                    });
                }
                NameRef::Global(_) => {
                    let name = &self.text.get(span.range())?;
                    return self
                        .model
                        .globals
                        .iter()
                        .chain(self.config_globals())
                        .find(|g| g.is(name))
                        .map(|var| Target { var, pou: None });
                }
                _ => {}
            }
        }
        // A declaration.
        if let Some(p) = pou {
            if let Some(var) = self.model.pous[p]
                .vars
                .iter()
                .find(|v| self.in_doc(&v.span, offset))
            {
                return Some(Target { var, pou: Some(p) });
            }
        }
        self.model
            .globals
            .iter()
            .chain(self.config_globals())
            .find(|v| self.in_doc(&v.span, offset))
            .map(|var| Target { var, pou: None })
    }

    fn config_globals(&self) -> impl Iterator<Item = &Variable> {
        self.model
            .configurations
            .iter()
            .flat_map(|c| c.resources.iter().flat_map(|r| r.globals.iter()))
    }

    /// The name of a type as the user writes it.
    pub fn type_name(&self, ty: &Type) -> String {
        self.model.type_name(ty)
    }

    /// Markdown for the variable at `offset`: its type, where it is declared, and for an FB instance the
    /// block's interface (a PLCopen block's inputs with their types and defaults).
    pub fn hover(&self, offset: usize) -> Option<String> {
        let t = self.target(offset)?;
        let v = t.var;
        let mut s = format!("**{}** : `{}`", v.name, self.type_name(&v.ty));
        let owner = match t.pou {
            Some(p) => format!(
                "{} of {} {}",
                kind_word(v.kind),
                pou_word(self.model.pous[p].kind),
                self.model.pous[p].name
            ),
            None => "VAR_GLOBAL".to_string(),
        };
        s.push_str(&format!("\n\n{owner}"));
        if v.constant {
            s.push_str(" CONSTANT");
        }
        if let Some(init) = &v.init {
            s.push_str(&format!(", initial value `{init:?}`"));
        }
        if let Some(loc) = &v.location {
            s.push_str(&format!(", at `{loc:?}`"));
        }
        let (line, _) = self.line_col(v.span);
        s.push_str(&format!(", declared on line {}", line + 1));
        if let Some(sig) = self.signature(&v.ty) {
            s.push_str("\n\n");
            s.push_str(&sig);
        }
        Some(s)
    }

    fn line_col(&self, span: Span) -> (u32, u32) {
        let text = &self.map.get(span.file).text;
        super::text::position(text, span.start as usize)
    }

    /// The interface of an FB type: a PLCopen block's template parameters, or a user FB's inputs and outputs.
    pub fn signature(&self, ty: &Type) -> Option<String> {
        let Type::Fb(fb) = ty else { return None };
        let name = self.type_name(ty);
        if let Some(t) = self.library.get(&name) {
            let mut s = format!("PLCopen block `{}`:", t.block);
            for p in &t.params {
                let dir = match p.direction {
                    Direction::Input => "input",
                    Direction::Output => "output",
                    Direction::InOut => "in-out",
                    Direction::State => continue,
                };
                s.push_str(&format!("\n- `{}` : `{}` ({dir}", p.name, p.iec_type));
                if p.required {
                    s.push_str(", required");
                }
                if let Some(d) = &p.default {
                    s.push_str(&format!(", default `{d}`"));
                }
                s.push(')');
            }
            for (pin, ty) in crate::tc2_mc2::tc2_pins(&t.block) {
                s.push_str(&format!("\n- `{pin}` : `{ty}` (input, Beckhoff Tc2_MC2)"));
            }
            return Some(s);
        }
        if let FbType::User(id) = fb {
            let pou = self.model.pous.get(id.0 as usize)?;
            let mut s = format!("FUNCTION_BLOCK `{}`:", pou.name);
            for v in pou
                .vars
                .iter()
                .filter(|v| matches!(v.kind, VarKind::Input | VarKind::Output | VarKind::InOut))
            {
                s.push_str(&format!(
                    "\n- `{}` : `{}` ({})",
                    v.name,
                    self.type_name(&v.ty),
                    kind_word(v.kind)
                ));
            }
            return Some(s);
        }
        Some(format!("standard function block `{name}`"))
    }

    /// Where the variable at `offset` is declared: the file's path and the declaration's span.
    pub fn definition(&self, offset: usize) -> Option<(PathBuf, Span)> {
        let t = self.target(offset)?;
        let f = self.map.get(t.var.span.file);
        if f.name.starts_with('<') {
            return None; // declared by the block prelude or the axes: no file to open
        }
        Some((PathBuf::from(&f.name), t.var.span))
    }

    /// The text of a span in its own file.
    pub fn file_text(&self, span: Span) -> &str {
        &self.map.get(span.file).text
    }

    /// The document's POUs with their variables: (name, kind, span, variables).
    pub fn symbols(&self) -> Vec<(String, PouKind, Span, Vec<&Variable>)> {
        self.model
            .pous
            .iter()
            .filter(|p| Some(p.span.file) == self.file)
            // (not the hidden program that runs the FB_init methods: no text of the file)
            .filter(|p| {
                !p.name
                    .eq_ignore_ascii_case(il_frontend::st::fb_init::PROGRAM)
            })
            .map(|p| (p.name.clone(), p.kind, p.span, p.vars.iter().collect()))
            .collect()
    }

    /// Completion at `offset`: (label, detail) pairs. After `inst.`, the members of `inst`'s FB type; in
    /// `CAL inst(` of a PLCopen block, its inputs as `Name :=`; otherwise the variables in scope.
    pub fn completion(&self, offset: usize) -> Vec<(String, String)> {
        let offset = offset.min(self.text.len());
        let line_start = self.text[..offset].rfind(['\n', '\r']).map_or(0, |i| i + 1);
        let line = &self.text[line_start..offset];
        let pou = self.pou_at(offset);
        let scope: Vec<&Variable> = pou
            .map(|p| self.model.pous[p].vars.iter().collect())
            .unwrap_or_default();
        let var_named = |n: &str| {
            scope
                .iter()
                .copied()
                .chain(self.model.globals.iter())
                .chain(self.config_globals())
                .find(|v| v.is(n))
        };
        // `inst.` + partial member
        let trimmed = line.trim_end_matches(|c: char| c.is_ascii_alphanumeric() || c == '_');
        if let Some(before_dot) = trimmed.strip_suffix('.') {
            let inst = last_word(before_dot);
            if let Some(v) = var_named(inst) {
                if self.type_name(&v.ty).eq_ignore_ascii_case("AXIS_REF") {
                    return crate::tc2_axis_ref::members(None);
                }
                return self.members(&v.ty, true);
            }
            // `Axis.Status.`, `GVL_Axes.Axis1.NcToPlc.`: a Tc2_MC2 AXIS_REF's member groups
            let chain: Vec<&str> = before_dot
                .rsplit(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '.'))
                .next()
                .unwrap_or("")
                .split('.')
                .collect();
            if let [.., axis, group] = chain.as_slice() {
                if var_named(axis)
                    .is_some_and(|v| self.type_name(&v.ty).eq_ignore_ascii_case("AXIS_REF"))
                {
                    return crate::tc2_axis_ref::members(Some(group));
                }
            }
            if let [_, axis] = chain.as_slice() {
                // `GVL_Axes.Axis1.`: a variable of a global variable list
                if let Some(v) = var_named(axis) {
                    if self.type_name(&v.ty).eq_ignore_ascii_case("AXIS_REF") {
                        return crate::tc2_axis_ref::members(None);
                    }
                }
            }
            return Vec::new();
        }
        // ST `inst(` ... not yet closed: the block's inputs as `Name :=`
        if let Some(paren) = line.rfind('(') {
            if !line[paren..].contains(')') {
                let inst = last_word(line[..paren].trim_end());
                if let Some(v) = var_named(inst).filter(|v| matches!(v.ty, Type::Fb(_))) {
                    return self
                        .members(&v.ty, false)
                        .into_iter()
                        .map(|(l, d)| (format!("{l} :="), d))
                        .collect();
                }
            }
        }
        // `CAL inst(` ... not yet closed
        let upper = line.to_ascii_uppercase();
        if let Some(cal) = upper.rfind("CAL ") {
            let after = &line[cal + 4..];
            if let Some(paren) = after.find('(') {
                if !after[paren..].contains(')') {
                    let inst = after[..paren].trim();
                    if let Some(v) = var_named(inst) {
                        return self
                            .members(&v.ty, false)
                            .into_iter()
                            .map(|(l, d)| (format!("{l} :="), d))
                            .collect();
                    }
                }
            }
        }
        scope
            .iter()
            .copied()
            .chain(self.model.globals.iter())
            .chain(self.config_globals())
            // (not the hidden variables ladderc adds, `__TC2_ACC` ...: no user can write them)
            .filter(|v| !v.name.starts_with("__"))
            .map(|v| (v.name.clone(), self.type_name(&v.ty)))
            .collect()
    }

    /// Members of an FB type: inputs (and outputs when `outputs`), as (name, type).
    fn members(&self, ty: &Type, outputs: bool) -> Vec<(String, String)> {
        let Type::Fb(fb) = ty else { return Vec::new() };
        let name = self.type_name(ty);
        if let Some(t) = self.library.get(&name) {
            let mut out: Vec<(String, String)> = t
                .params
                .iter()
                .filter(|p| match p.direction {
                    Direction::Input | Direction::InOut => true,
                    Direction::Output => outputs,
                    Direction::State => false,
                })
                .map(|p| (p.name.clone(), p.iec_type.clone()))
                .collect();
            // the Tc2_MC2 spellings `ladderc check` reads (`Enable_Positive`, `Override`)
            out.extend(
                crate::tc2_mc2::tc2_pins(&t.block)
                    .map(|(pin, ty)| (pin.to_string(), format!("{ty} (Tc2_MC2)"))),
            );
            return out;
        }
        if let FbType::User(id) = fb {
            if let Some(pou) = self.model.pous.get(id.0 as usize) {
                return pou
                    .vars
                    .iter()
                    .filter(|v| match v.kind {
                        VarKind::Input | VarKind::InOut => true,
                        VarKind::Output => outputs,
                        _ => false,
                    })
                    .map(|v| (v.name.clone(), self.type_name(&v.ty)))
                    .collect();
            }
        }
        Vec::new()
    }
}

/// The identifier that ends `text` (`fb` of `x := fb`), empty when none does.
fn last_word(text: &str) -> &str {
    let word = |c: char| c.is_ascii_alphanumeric() || c == '_';
    // the word's characters are ASCII, so its length in bytes is its length in characters
    let len = text.chars().rev().take_while(|&c| word(c)).count();
    &text[text.len() - len..]
}
