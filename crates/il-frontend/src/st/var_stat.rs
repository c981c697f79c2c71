//! `VAR_STAT` (CODESYS, online help "VAR_STAT": static variables): variables of a FUNCTION_BLOCK,
//! FUNCTION or PROGRAM of which there is one copy, shared by every instance and every call, kept
//! from call to call and initialised once, when the application starts.
//!
//! Input: a file's text and tokens ([`mark`], before the declarations are parsed), then the parsed
//! units once every body is lowered ([`hoist`]). Output: [`mark`] gives the text with each `VAR_STAT`
//! keyword of a POU replaced by `VAR` of the same length (so every span stays where it was) and the
//! keywords' offsets; the caller names those blocks [`MARK`] after parsing ([`name_blocks`]), so
//! that the body is typed and lowered with them as the POU's own variables. [`hoist`] then moves
//! each marked block's variables out of the POU into a global variable `__STAT_<POU>_<NAME>` (one
//! per program, the same for every instance and call) and renames their uses in the POU's body
//! and in its methods and actions.
//! A METHOD's `VAR_STAT` ([`name_method_blocks`]) is one copy per method shared by every instance
//! of the block (CODESYS "VAR_STAT": static variables of a method are shared by all instances),
//! the global `__STAT_<BLOCK>___M_<METHOD>_<NAME>`.
//! Invariants: a `VAR_STAT` inside a PROPERTY accessor is one E1067 (read as VAR, a variable of
//! the call); outside any POU the keyword is left to the parser. A marked block is never left in a POU after
//! [`hoist`]; its variables keep their types and initial values.

use super::file::word;
use super::lexer::{Tok, Token};
use crate::ast::{CompilationUnit, Ident, LibraryElement, VarBlock, VarKind};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};

/// The name a POU's `VAR_STAT` block carries between the parse and [`hoist`] (a POU's own blocks
/// have no list name otherwise).
pub const MARK: &str = "VAR_STAT";

/// The global variable that holds POU `pou`'s static variable `name`.
pub fn global_name(pou: &str, name: &str) -> String {
    format!(
        "__STAT_{}_{}",
        pou.to_ascii_uppercase(),
        name.to_ascii_uppercase()
    )
}

/// See the module documentation: the text with the POUs' `VAR_STAT` keywords read as `VAR`, and
/// their offsets; `None` when the text has none.
pub fn mark(
    file: FileId,
    src: &str,
    toks: &[Token],
    diags: &mut Diagnostics,
) -> Option<(String, Vec<usize>)> {
    let mut out: Option<(String, Vec<usize>)> = None;
    let mut owner: Option<String> = None;
    for t in toks {
        if !matches!(t.tok, Tok::Ident | Tok::Kw(_)) {
            continue;
        }
        let w = word(src, t).to_ascii_uppercase();
        match w.as_str() {
            "METHOD" | "PROPERTY" | "FUNCTION_BLOCK" | "FUNCTION" | "PROGRAM" => owner = Some(w),
            "END_METHOD" | "END_PROPERTY" => owner = Some("FUNCTION_BLOCK".into()),
            "END_FUNCTION_BLOCK" | "END_FUNCTION" | "END_PROGRAM" => owner = None,
            "VAR_STAT" if owner.is_some() => {
                let o = out.get_or_insert_with(|| (src.to_string(), Vec::new()));
                o.0.replace_range(t.range.clone(), "VAR     ");
                if owner.as_deref() == Some("PROPERTY") {
                    diags.push(
                        Diagnostic::error(
                            code::E1067,
                            "VAR_STAT in a PROPERTY accessor is not supported",
                        )
                        .at(Span::new(file, t.range.start, t.range.end))
                        .with_primary_label("static variables of an accessor")
                        .with_hint("declare the variables in the block's own VAR_STAT (one copy shared by every instance), or in the accessor's VAR_INST (one copy per instance, TwinCAT)"),
                    );
                } else {
                    o.1.push(t.range.start);
                }
            }
            _ => {}
        }
    }
    out
}

/// Names [`MARK`] the POU blocks of `unit` (in `file`) whose keyword is at one of `at`.
pub fn name_blocks(unit: &mut CompilationUnit, file: FileId, at: &[usize]) {
    for item in &mut unit.items {
        let LibraryElement::Pou(p) = item else {
            continue;
        };
        for b in &mut p.var_blocks {
            if b.span.file == file && at.contains(&(b.span.start as usize)) {
                b.name = Some(Ident::new(MARK, b.span));
            }
        }
    }
}

/// Names [`MARK`] the blocks of method `m` whose keyword is at one of `at` (a METHOD's `VAR_STAT`:
/// its variables join the block's marked variables as `__M_<METHOD>_<NAME>`, so [`hoist`] makes
/// them one global per method, shared by every instance).
pub fn name_method_blocks(m: &mut super::file::PendingMethod, at: &[usize]) {
    for b in &mut m.blocks {
        if at.contains(&(b.span.start as usize)) {
            b.name = Some(Ident::new(MARK, b.span));
        }
    }
}

/// See the module documentation: the marked blocks moved out of their POUs into global variables,
/// their uses renamed.
pub fn hoist(units: &mut [CompilationUnit]) {
    for unit in units.iter_mut() {
        let mut globals = Vec::new();
        let mut renamed: Vec<(String, crate::rename::Renames)> = Vec::new();
        for item in unit.items.iter_mut() {
            let LibraryElement::Pou(p) = item else {
                continue;
            };
            let is_mark = |b: &VarBlock| b.name.as_ref().is_some_and(|n| n.name == MARK);
            if !p.var_blocks.iter().any(is_mark) {
                continue;
            }
            let mut renames = crate::rename::Renames::default();
            let (stat, own): (Vec<VarBlock>, Vec<VarBlock>) = std::mem::take(&mut p.var_blocks)
                .into_iter()
                .partition(is_mark);
            p.var_blocks = own;
            for mut b in stat {
                for v in &mut b.vars {
                    let g = global_name(&p.name.name, &v.name.name);
                    renames.bases.insert(v.name.key(), g.clone());
                    v.name = Ident::new(g, v.name.span);
                }
                b.name = None;
                b.kind = VarKind::Global;
                globals.push(b);
            }
            renames.apply(&mut p.body);
            renamed.push((p.name.key(), renames));
        }
        if renamed.is_empty() {
            continue;
        }
        for item in unit.items.iter_mut() {
            if let LibraryElement::Action(a) = item {
                if let Some((_, r)) = renamed.iter().find(|(k, _)| *k == a.pou.key()) {
                    r.apply(&mut a.body);
                }
            }
        }
        unit.items
            .extend(globals.into_iter().map(LibraryElement::GlobalVars));
    }
}
