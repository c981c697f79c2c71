//! TwinCAT's and CODESYS's generic constants (`VAR_GENERIC CONSTANT`), read for the parse of one
//! text: the block's declarations as a `VAR CONSTANT` block, an instance's values noted on its type.
//!
//! Beckhoff Infosys, TC3 PLC "Generic constant variables - VAR_GENERIC CONSTANT" (TwinCAT 3.1 Build
//! 4026; CODESYS online help "VAR_GENERIC CONSTANT" likewise): a function block declares
//! `VAR_GENERIC CONSTANT maxlen : UDINT := 1; END_VAR` and uses `maxlen` in its array bounds and
//! string lengths; each instance gives its own value in angle brackets after the block's name
//! (`fbPou : FB_Pou<100>;`, `FB_Pou<(2 * cconst)>`, `FB_Pou<100, 1000>`, `ARRAY[0..5] OF
//! FB_Pou<100>`, `EXTENDS FB_Pou<1000>`), so every instance is a block of its own size. "The
//! initial value is only needed for compile checks. At runtime, the value is overwritten."
//!
//! Input: a file's text and its tokens. Output: the text with each `VAR_GENERIC` keyword read as
//! `VAR` (so the block's constants are `VAR CONSTANT` with their initial value and the block's
//! declarations and body are read as such; an `EXTENDS` or `IMPLEMENTS` clause that TwinCAT writes
//! after this block, `END_VAR IMPLEMENTS I_Trace`, is then read as the block's clause by
//! [`super::file`]'s scan) and each `<...>` after a block's name in a declaration (after `:`, `OF`
//! or `EXTENDS`) blanked, or `None` when the text has neither; [`generic_instances`] lists the
//! instances' `<...>` so that [`name_generic_instances`] writes them into the parsed types
//! (`FB_Pou<100>`), which [`super::generic_blocks`] turns into blocks of their own. Invariant:
//! positions unchanged (replaced bytes become blanks), so every span stays where the user wrote it.
//! Still not compiled: a block that extends a generic block with values (`EXTENDS FB_Pou<1000>`):
//! one located E1081, the base read with its initial values.

use super::file::{is_word, word};
use super::lexer::{Tok, Token};
use diagnostics::{code, Diagnostic, Diagnostics};

/// See the module documentation.
pub(super) fn generic_constants(
    file: crate::FileId,
    src: &str,
    toks: &[Token],
    diags: &mut Diagnostics,
) -> Option<String> {
    let mut edits: Vec<(std::ops::Range<usize>, &'static str)> = Vec::new();
    for (k, t) in toks.iter().enumerate() {
        // `VAR_GENERIC CONSTANT`: read as `VAR CONSTANT`
        if is_word(src, t, "VAR_GENERIC") {
            edits.push((t.range.clone(), "VAR"));
            continue;
        }
        // `FB_X<10>` in a declaration: the instance's generic constants
        if t.tok != Tok::Lt || k < 2 || toks[k - 1].tok != Tok::Ident {
            continue;
        }
        let before = &toks[k - 2];
        let declares = before.tok == Tok::Colon
            || is_word(src, before, "OF")
            || is_word(src, before, "EXTENDS");
        if !declares {
            continue;
        }
        let Some(close) = closing_angle(toks, k) else {
            continue;
        };
        if is_word(src, before, "EXTENDS") {
            let block = word(src, &toks[k - 1]);
            diags.push(
                Diagnostic::error(
                    code::E1081,
                    format!(
                        "`EXTENDS {block}<...>`: a block derived from a generic block with its own values is not supported"
                    ),
                )
                .at(crate::Span::new(file, t.range.start, toks[close].range.end))
                .with_primary_label("the base's generic constants")
                .with_hint(format!(
                    "declare an instance `{block}<...>` inside the block instead of extending it; ladderc reads this base as a plain `{block}` with its initial values"
                )),
            );
        }
        edits.push((t.range.start..toks[close].range.end, ""));
    }
    if edits.is_empty() {
        return None;
    }
    let mut bytes = src.as_bytes().to_vec();
    for (range, keep) in edits {
        let Some(slice) = bytes.get_mut(range) else {
            continue;
        };
        // (token ranges start and end on character boundaries: all blanks stay UTF-8)
        slice.fill(b' ');
        let n = keep.len().min(slice.len());
        slice[..n].copy_from_slice(&keep.as_bytes()[..n]);
    }
    String::from_utf8(bytes).ok()
}

/// The instances' generic values of a text (`fb : FB_X<10>;`, `ARRAY[1..2] OF FB_X<(N * 2)>`):
/// the range from the block's name to the closing `>`, and the name and values as written
/// (`FB_X<10>`).
pub(super) fn generic_instances(
    src: &str,
    toks: &[Token],
) -> Vec<(std::ops::Range<usize>, String)> {
    let mut found = Vec::new();
    for (k, t) in toks.iter().enumerate() {
        if t.tok != Tok::Lt || k < 2 || toks[k - 1].tok != Tok::Ident {
            continue;
        }
        let before = &toks[k - 2];
        if !(before.tok == Tok::Colon || is_word(src, before, "OF")) {
            continue;
        }
        let Some(close) = closing_angle(toks, k) else {
            continue;
        };
        let name = &toks[k - 1];
        let range = name.range.start..toks[close].range.end;
        let values = src.get(t.range.end..toks[close].range.start).unwrap_or("");
        found.push((range, format!("{}<{}>", word(src, name), values.trim())));
    }
    found
}

/// Writes the instances' generic values (`instances`, of [`generic_instances`]) into the types
/// of `unit`'s and `pending`'s declarations that name a block at the same place: the type's name
/// becomes `FB_X<10>` and its span reaches the `>`, for [`super::generic_blocks`].
pub(super) fn name_generic_instances(
    instances: &[(std::ops::Range<usize>, String)],
    unit: &mut crate::ast::CompilationUnit,
    pending: &mut [super::file::PendingBody],
) {
    if instances.is_empty() {
        return;
    }
    each_declared_type(
        std::slice::from_mut(unit),
        pending,
        &mut |ty: &mut crate::ast::TypeRef| name_type(instances, ty),
    );
}

/// Calls `f` on the type of every variable and field `units` and `pending` declare: POU variables,
/// global lists, configurations and their resources, structure fields and aliases, and the
/// variables of the METHODs left to the ST front end (enumerations hold no types).
pub(super) fn each_declared_type(
    units: &mut [crate::ast::CompilationUnit],
    pending: &mut [super::file::PendingBody],
    f: &mut impl FnMut(&mut crate::ast::TypeRef),
) {
    use crate::ast::{LibraryElement, TypeDef};
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        match item {
            LibraryElement::Pou(p) => p
                .var_blocks
                .iter_mut()
                .flat_map(|b| b.vars.iter_mut())
                .for_each(|v| f(&mut v.ty)),
            LibraryElement::GlobalVars(b) => b.vars.iter_mut().for_each(|v| f(&mut v.ty)),
            LibraryElement::Configuration(c) => c
                .globals
                .iter_mut()
                .chain(c.resources.iter_mut().flat_map(|r| r.globals.iter_mut()))
                .flat_map(|b| b.vars.iter_mut())
                .for_each(|v| f(&mut v.ty)),
            LibraryElement::DataTypes(types) => {
                for t in types {
                    match &mut t.def {
                        TypeDef::Struct { fields } => fields.iter_mut().for_each(|v| f(&mut v.ty)),
                        TypeDef::Alias { ty, .. } => f(ty),
                        TypeDef::Enum { .. } => {}
                    }
                }
            }
            LibraryElement::Action(_) => {}
        }
    }
    for m in pending.iter_mut().flat_map(|b| b.methods.iter_mut()) {
        m.blocks
            .iter_mut()
            .flat_map(|b| b.vars.iter_mut())
            .for_each(|v| f(&mut v.ty));
    }
}

fn name_type(instances: &[(std::ops::Range<usize>, String)], ty: &mut crate::ast::TypeRef) {
    use crate::ast::TypeRef;
    match ty {
        TypeRef::Named(id) => {
            if let Some((range, written)) = instances
                .iter()
                .find(|(r, _)| r.start == id.span.start as usize)
            {
                id.name = written.clone();
                id.span = crate::Span::new(id.span.file, range.start, range.end);
            }
        }
        TypeRef::Array { element, .. } => name_type(instances, element),
        TypeRef::Ref { target, .. } => name_type(instances, target),
        TypeRef::String { .. } | TypeRef::Subrange { .. } | TypeRef::Enum { .. } => {}
    }
}

/// The `>` that closes the `<` at `open` (parentheses nest inside: `<(a > b)>` has none at its
/// level), `None` when a `;`, a `:=` outside parentheses or the end of the declaration's line of
/// tokens comes first.
fn closing_angle(toks: &[Token], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (j, t) in toks.iter().enumerate().skip(open + 1) {
        match t.tok {
            Tok::LParen | Tok::LBracket => depth += 1,
            Tok::RParen | Tok::RBracket => depth = depth.checked_sub(1)?,
            Tok::Gt if depth == 0 => return Some(j),
            Tok::Semi => return None,
            // (`FB_X<(N := 10)>`: a value by name, inside parentheses)
            Tok::Assign if depth == 0 => return None,
            Tok::Kw(_) if depth == 0 => return None,
            _ => {}
        }
    }
    None
}
