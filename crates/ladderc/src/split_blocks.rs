//! Blocks declared in one file and implemented in another (B&R Automation Studio: a library's
//! `.fun` file holds each FUNCTION_BLOCK's declaration blocks, a `.st` file repeats
//! `FUNCTION_BLOCK Name ... END_FUNCTION_BLOCK` around its statements only).
//!
//! Input: the parsed units and the ST bodies not yet compiled. Output: each such pair made one
//! POU, the implementation's, with the declaration's blocks before its own (and the declaration's
//! result type for a FUNCTION); the declaration removed with its empty body; one note W0019 at the
//! implementation. A block of a `.fun` file that no file implements (B&R's system libraries:
//! `operator.fun` declares ADD, `standard.fun` TON) is not compiled, one note W0021 per file:
//! ladderc's own blocks stand for the standard names, a use of another is reported where it is
//! made. Invariants: only pairs of one kind, in two files, where exactly one has no statement (no
//! IL instruction and an ST body without a token) are joined, or where the one without statements
//! is in a `.fun` file and the other, also without statements, is not (an implementation left
//! empty); every other duplicate stays the checks' E1002, but for `.fun` stubs of one name none
//! of which has statements (all skipped); no `.fun` declaration alone becomes an empty block. Runs
//! before the bodies are compiled, so the statements are lowered knowing the declarations.

use diagnostics::{code, Diagnostic, Diagnostics, Severity};
use il_frontend::ast::{CompilationUnit, LibraryElement, PouKind, TypeRef, VarKind};
use il_frontend::st::file::PendingBody;
use std::collections::HashMap;

/// A parameter of a block ladderc provides (its PLCopen templates): name, direction (VAR_INPUT,
/// VAR_OUTPUT or VAR_IN_OUT), type, whether a call must give it.
pub struct ProvidedParam {
    /// The parameter's name.
    pub name: String,
    /// VAR_INPUT, VAR_OUTPUT or VAR_IN_OUT.
    pub kind: VarKind,
    /// Its IEC type (`AXIS_REF`, `LREAL`; `ARRAY` for an array).
    pub ty: String,
    /// Whether a call must give it.
    pub required: bool,
}

/// Joins the declaration-only and implementation-only halves of each block (see the module
/// header). `provided` gives the interface of a block ladderc provides by that name (its PLCopen
/// templates), to tell a vendor's block of the same name (B&R's Acp10_MC `MC_Power`, `Axis :
/// UDINT`) from the standard one.
pub fn join(
    units: &mut [CompilationUnit],
    pending: &mut Vec<PendingBody>,
    is_fun: impl Fn(diagnostics::FileId) -> bool,
    provided: impl Fn(&str) -> Option<Vec<ProvidedParam>>,
    file_name: impl Fn(diagnostics::FileId) -> String,
    diags: &mut Diagnostics,
) -> Vec<(String, diagnostics::FileId)> {
    // (unit, item) of every function block and function, by upper-case name
    let mut by_name: HashMap<String, Vec<(usize, usize)>> = HashMap::new();
    for (u, unit) in units.iter().enumerate() {
        for (i, item) in unit.items.iter().enumerate() {
            if let LibraryElement::Pou(p) = item {
                if matches!(p.kind, PouKind::FunctionBlock | PouKind::Function) {
                    by_name.entry(p.name.key()).or_default().push((u, i));
                }
            }
        }
    }
    let mut removals: Vec<(usize, usize)> = Vec::new();
    let mut names: Vec<&String> = by_name.keys().collect();
    names.sort();
    for name in names {
        let [a, b] = by_name[name][..] else { continue };
        let (Some(pa), Some(pb)) = (pou(units, a), pou(units, b)) else {
            continue;
        };
        if pa.kind != pb.kind || pa.name.span.file == pb.name.span.file {
            continue;
        }
        let (ea, eb) = (no_statement(pa, pending), no_statement(pb, pending));
        let (fa, fb) = (is_fun(pa.name.span.file), is_fun(pb.name.span.file));
        let (decl, imp) = match (ea, eb) {
            (true, false) => (a, b),
            (false, true) => (b, a),
            // a `.fun` declaration and an implementation without statements in a `.st` file
            // (Automation Studio's "Add function" writes one so; an empty statement list is a
            // body, IEC 61131-3 ed. 3 7.3.1): one block, doing nothing (before round 26: E1002)
            (true, true) if fa && !fb => (a, b),
            (true, true) if fb && !fa => (b, a),
            _ => continue,
        };
        let Some(d) = pou(units, decl).cloned() else {
            continue;
        };
        let LibraryElement::Pou(p) = &mut units[imp.0].items[imp.1] else {
            continue;
        };
        let mut blocks = d.var_blocks.clone();
        blocks.append(&mut p.var_blocks);
        p.var_blocks = blocks;
        if p.return_type.is_none() {
            p.return_type = d.return_type.clone();
        }
        diags.push(
            Diagnostic::new(
                code::W0019,
                Severity::Note,
                format!(
                    "`{}` is declared in one file and implemented in this one: read as one block",
                    p.name.name
                ),
            )
            .at(p.name.span)
            .with_primary_label("the statements")
            .with_label(d.name.span, "the declarations")
            .with_hint("as B&R Automation Studio keeps a library's blocks (`.fun` and `.st`); for another IEC compiler write one FUNCTION_BLOCK"),
        );
        pending.retain(|b| {
            !(b.file == d.name.span.file && b.name_start == d.name.span.start as usize)
        });
        removals.push(decl);
    }
    // a `.fun` declaration no file implements: a block of a library the B&R system provides
    // (`operator`, `standard`, `AsIecCon`: ADD, TON, INT_TO_REAL ... declared without statements),
    // not compiled (an empty body would stand silently for the block: a TON that never times, an
    // ADD that gives 0); ladderc's own standard functions and blocks stand for the standard names,
    // a use of any other is an unknown function or type at that use; one note W0021 per file.
    // Two such stubs of one name (B&R's `runtime.fun` `r_trig` and `standard.fun` `R_TRIG`: one
    // standard block, B&R's names being case-sensitive) are both stubs, not a duplicate (before
    // round 25: W1446 and E1002)
    let mut skipped: Vec<(diagnostics::FileId, diagnostics::Span, Vec<String>)> = Vec::new();
    for (u, unit) in units.iter().enumerate() {
        for (i, item) in unit.items.iter().enumerate() {
            let LibraryElement::Pou(p) = item else {
                continue;
            };
            if !matches!(p.kind, PouKind::FunctionBlock | PouKind::Function)
                || !is_fun(p.name.span.file)
                || removals.contains(&(u, i))
                || !no_statement(p, pending)
                || !by_name.get(&p.name.key()).is_some_and(|v| {
                    v.iter().all(|&at| {
                        pou(units, at).is_some_and(|q| {
                            q.kind == p.kind && is_fun(q.name.span.file) && no_statement(q, pending)
                        })
                    })
                })
            {
                continue;
            }
            // a vendor's block named like one ladderc provides, with another interface (B&R's
            // Acp10_MC `MC_Power` takes `Axis : UDINT`, an address, PLCopen's `Axis : AXIS_REF`
            // in-out): not ladderc's block; its uses are one error at the first instance (before
            // round 26: E1006, E1033 ... at each call, ladderc's block meeting the vendor's calls)
            if let Some((theirs, ours)) = provided(&p.name.name).and_then(|q| difference(p, &q)) {
                if let Some(at) = first_instance(units, &p.name.key(), &is_fun) {
                    diags.push(
                        Diagnostic::new(
                            code::E1003,
                            Severity::Error,
                            format!(
                                "`{}` of {} ({theirs}) is B&R's, not PLCopen's ({ours}): not provided",
                                p.name.name,
                                file_name(p.name.span.file)
                            ),
                        )
                        .at(at)
                        .with_primary_label("an instance of the vendor's block")
                        .with_label(p.name.span, "declared here, without statements")
                        .with_hint("ladderc provides PLCopen's block of that name, whose parameters differ; give the vendor library's source, or write the program with PLCopen's interface"),
                    );
                    // (kept: the calls are checked against the vendor's interface, no cascade)
                    continue;
                }
            }
            match skipped.iter_mut().find(|(f, _, _)| *f == p.name.span.file) {
                Some((_, _, names)) => names.push(p.name.name.clone()),
                None => skipped.push((p.name.span.file, p.name.span, vec![p.name.name.clone()])),
            }
            pending.retain(|b| {
                !(b.file == p.name.span.file && b.name_start == p.name.span.start as usize)
            });
            removals.push((u, i));
        }
    }
    let stubs: Vec<(String, diagnostics::FileId)> = skipped
        .iter()
        .flat_map(|(f, _, names)| names.iter().map(|n| (n.clone(), *f)))
        .collect();
    for (_, at, names) in skipped {
        let shown: Vec<String> = names.iter().take(8).map(|n| format!("`{n}`")).collect();
        let more = if names.len() > 8 {
            format!(" and {} more", names.len() - 8)
        } else {
            String::new()
        };
        diags.push(
            Diagnostic::new(
                code::W0021,
                Severity::Note,
                format!(
                    "this `.fun` file declares {} block(s) that no file implements ({}{more}): a library the B&R system provides, not compiled",
                    names.len(),
                    shown.join(", ")
                ),
            )
            .at(at)
            .with_primary_label("declared without statements")
            .with_hint("ladderc's own standard functions and blocks (ADD, TON, INT_TO_REAL ...) stand for the standard names; a call of any other is reported where it is made (give the library's source if you have it)"),
        );
    }
    // from the back, so the other indexes stay valid
    removals.sort();
    removals.dedup();
    for (u, i) in removals.into_iter().rev() {
        units[u].items.remove(i);
    }
    stubs
}

/// A data type of a B&R library dropped with the stubs it is made of (see [`drop_stub_types`]).
pub struct StubType {
    /// The type's name, upper case.
    pub key: String,
    /// The type's name as declared.
    pub name: String,
    /// The stub block it is made of (directly or through another such type).
    pub stub: String,
    /// The file name of the `.fun` file declaring the stub.
    pub stub_file: String,
    /// Where the stub is declared.
    pub stub_at: diagnostics::Span,
}

/// The data types declared in the folder of a `.fun` file whose blocks are stubs (`stubs`, from
/// [`join`]: B&R's system library `runtime`, whose `runtime.typ` declares `SFCActionType` with a
/// field `AC : SFCActionControl`, a block `runtime.fun` only declares) that are made of such a
/// stub (a field, an array element, an alias; or of another such type): as unavailable as the
/// stub, so not compiled either (before round 27: one E1003 per field in the vendor's file, though
/// no user code named the type). A use of one is the checks' E1003 where it is made, which
/// [`name_stub_types`] words to name the stub.
pub fn drop_stub_types(
    units: &mut [CompilationUnit],
    stubs: &[(String, diagnostics::FileId)],
    folder: impl Fn(diagnostics::FileId) -> std::path::PathBuf,
    file_name: impl Fn(diagnostics::FileId) -> String,
) -> Vec<StubType> {
    if stubs.is_empty() {
        return Vec::new();
    }
    let lib_dirs: Vec<std::path::PathBuf> = stubs.iter().map(|(_, f)| folder(*f)).collect();
    // the stub each unavailable name stands for: (key, stub name, stub file)
    let mut gone: HashMap<String, (String, diagnostics::FileId)> = stubs
        .iter()
        .map(|(n, f)| (n.to_ascii_uppercase(), (n.clone(), *f)))
        .collect();
    fn named(t: &TypeRef) -> Option<&il_frontend::ast::Ident> {
        match t {
            TypeRef::Named(i) => Some(i),
            TypeRef::Array { element, .. } => named(element),
            _ => None,
        }
    }
    let mut dropped: Vec<StubType> = Vec::new();
    // until no more: a type made of a dropped type is dropped too
    loop {
        let mut more = false;
        for unit in units.iter_mut() {
            for item in unit.items.iter_mut() {
                let LibraryElement::DataTypes(types) = item else {
                    continue;
                };
                types.retain(|t| {
                    if !lib_dirs.contains(&folder(t.name.span.file)) {
                        return true;
                    }
                    let made_of: Vec<&TypeRef> = match &t.def {
                        il_frontend::ast::TypeDef::Alias { ty, .. } => vec![ty],
                        il_frontend::ast::TypeDef::Struct { fields } => {
                            fields.iter().map(|f| &f.ty).collect()
                        }
                        il_frontend::ast::TypeDef::Enum { .. } => Vec::new(),
                    };
                    let Some((stub, file)) = made_of
                        .iter()
                        .filter_map(|ty| named(ty))
                        .find_map(|n| gone.get(&n.key()).cloned())
                    else {
                        return true;
                    };
                    dropped.push(StubType {
                        key: t.name.key(),
                        name: t.name.name.clone(),
                        stub: stub.clone(),
                        stub_file: file_name(file),
                        stub_at: t.name.span,
                    });
                    gone.insert(t.name.key(), (stub, file));
                    more = true;
                    false
                });
            }
        }
        if !more {
            break;
        }
    }
    dropped
}

/// The checks' E1003 `unknown type `T`` for a type [`drop_stub_types`] dropped, worded to name the
/// stub it is made of (one error where the user's code uses it, as for the stub itself).
pub fn name_stub_types(dropped: &[StubType], diags: &mut Diagnostics) {
    if dropped.is_empty() {
        return;
    }
    let which = |d: &Diagnostic| -> Option<&StubType> {
        if d.code != code::E1003 {
            return None;
        }
        let name = d
            .message
            .strip_prefix("unknown type `")?
            .strip_suffix('`')?;
        dropped.iter().find(|t| t.key == name.to_ascii_uppercase())
    };
    let mut worded = Vec::new();
    diags.retain(|d| match which(d) {
        Some(t) => {
            let mut e = d.clone();
            e.message = format!(
                "`{}` is made of `{}`, a block {} declares without statements (not compiled, W0021): not available",
                t.name, t.stub, t.stub_file
            );
            e.labels.push(diagnostics::Label {
                span: t.stub_at,
                message: "the type, not compiled".to_string(),
            });
            e.hint = Some("a block of a B&R system library ladderc does not provide; give the library's source if you have it, or do without the type".to_string());
            worded.push(e);
            false
        }
        None => true,
    });
    diags.extend(worded);
}

/// The first difference between the stub `p`'s parameters and those of ladderc's block: (the
/// stub's text, ladderc's text); `None` when every parameter of the stub is ladderc's (name,
/// direction, type) and the stub leaves out none that a call must give.
fn difference(p: &il_frontend::ast::Pou, ours: &[ProvidedParam]) -> Option<(String, String)> {
    let kw = |k: VarKind| match k {
        VarKind::Input => "VAR_INPUT ",
        VarKind::Output => "VAR_OUTPUT ",
        _ => "VAR_IN_OUT ",
    };
    let mut theirs = Vec::new();
    for b in &p.var_blocks {
        if !matches!(b.kind, VarKind::Input | VarKind::Output | VarKind::InOut) {
            continue;
        }
        for v in &b.vars {
            let ty = match &v.ty {
                TypeRef::Named(t) => t.name.to_ascii_uppercase(),
                TypeRef::String { wide: false, .. } => "STRING".to_string(),
                TypeRef::String { wide: true, .. } => "WSTRING".to_string(),
                TypeRef::Array { .. } => "ARRAY".to_string(),
                _ => "?".to_string(),
            };
            let Some(q) = ours.iter().find(|q| v.name.is(&q.name)) else {
                return Some((
                    format!("{} : {ty}", v.name.name),
                    format!("no `{}`", v.name.name),
                ));
            };
            if q.kind != b.kind || !q.ty.eq_ignore_ascii_case(&ty) {
                let (a, o) = if q.kind != b.kind {
                    (kw(b.kind), kw(q.kind))
                } else {
                    ("", "")
                };
                return Some((
                    format!("{a}{} : {ty}", v.name.name),
                    format!("{o}{} : {}", q.name, q.ty),
                ));
            }
            theirs.push(v.name.key());
        }
    }
    ours.iter()
        .find(|q| q.required && !theirs.contains(&q.name.to_ascii_uppercase()))
        .map(|q| {
            (
                format!("no `{}`", q.name),
                format!("{}{} : {}", kw(q.kind), q.name, q.ty),
            )
        })
}

/// The type name of the first instance of the block `key` (upper case) declared outside `.fun`
/// files: a variable of that type or of an array of it.
fn first_instance(
    units: &[CompilationUnit],
    key: &str,
    is_fun: impl Fn(diagnostics::FileId) -> bool,
) -> Option<diagnostics::Span> {
    fn named(t: &TypeRef) -> Option<&il_frontend::ast::Ident> {
        match t {
            TypeRef::Named(i) => Some(i),
            TypeRef::Array { element, .. } => named(element),
            _ => None,
        }
    }
    units
        .iter()
        .flat_map(|u| u.items.iter())
        .flat_map(|item| item.var_blocks())
        .flat_map(|b| b.vars.iter())
        .filter_map(|v| named(&v.ty))
        .find(|t| t.key() == key && !is_fun(t.span.file))
        .map(|t| t.span)
}

fn pou(units: &[CompilationUnit], (u, i): (usize, usize)) -> Option<&il_frontend::ast::Pou> {
    match units.get(u)?.items.get(i)? {
        LibraryElement::Pou(p) => Some(p),
        _ => None,
    }
}

/// Whether `p` has no statement: no IL instruction, and no token in its ST body (if it has one).
fn no_statement(p: &il_frontend::ast::Pou, pending: &[PendingBody]) -> bool {
    let body = pending
        .iter()
        .find(|b| b.file == p.name.span.file && b.name_start == p.name.span.start as usize);
    p.body.is_empty()
        && body.is_none_or(|b| {
            b.actions.is_empty()
                && b.methods.is_empty()
                && b.oop.is_none()
                && il_frontend::st::lexer::lex(&b.text)
                    .0
                    .iter()
                    .all(|t| t.tok == il_frontend::st::lexer::Tok::Eof)
        })
}
