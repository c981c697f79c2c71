//! CODESYS's and TwinCAT's FB_init arguments in an instance declaration: `fb : FB_X(nSize := 4);`
//! (or `fbTest : FB_Test(fbPrep);`) passes the arguments to the extra inputs of the block's
//! `FB_init` method, which those systems run once before the first cycle ([`super::fb_init`] runs
//! it so).
//!
//! Input: the text of an `.st` file (or a TwinCAT or CODESYS object read as one) and its tokens.
//! Output: the text with each argument list blanked (so the IL declaration reader declares the
//! instance as if they were not there), and the arguments of each declaration, read as the
//! arguments of an ST call (so positional and named arguments and any expression are allowed), to
//! be matched with the block's FB_init inputs once every file is read. Only declarations inside
//! `VAR...END_VAR` blocks and `STRUCT...END_STRUCT` fields are looked at (`name : Type(` where `Type` is no elementary type:
//! `STRING(20)`, `INT(0..10)` are lengths and subranges). Invariant: positions unchanged; the
//! spans of the arguments are positions in the file.

use super::ast::{Arg, StmtKind};
use super::file::{blank, is_word, word};
use super::lexer::{Tok, Token};
use crate::sema::Elementary;
use crate::{FileId, Span};
use diagnostics::Diagnostics;

const VAR_KEYWORDS: &[&str] = &[
    "VAR",
    "VAR_INPUT",
    "VAR_OUTPUT",
    "VAR_IN_OUT",
    "VAR_GLOBAL",
    "VAR_TEMP",
    "VAR_STAT",
    "VAR_INST",
    "VAR_EXTERNAL",
];

/// The FB_init arguments of one instance declaration (`fb : FB_X(nSize := 4)`).
#[derive(Debug, Clone)]
pub struct DeclArgs {
    /// The span of the type's name in the declaration: the key that finds the declaration
    /// (its `TypeRef::Named` ident, or the element type of an `ARRAY ... OF FB_X(...)`).
    pub ty: Span,
    /// The type's name as written.
    pub ty_name: String,
    /// The arguments, as in a call.
    pub args: Vec<Arg>,
    /// From `(` to `)` (for a list per element, from `[` to `]`).
    pub span: Span,
    /// An array's arguments element by element (`ARRAY[0..1] OF FB_X[(a := 1), (a := 2)]`,
    /// CODESYS): each list with its span, `(` to `)`; empty for one list `FB_X(...)`.
    pub elements: Vec<(Vec<Arg>, Span)>,
    /// The declaration is in a METHOD of a block whose EXTENDS chain is broken (set by
    /// [`super::inherit`], which compiles such a block without its methods): no instance takes
    /// the arguments, which is the missing base's error, not this declaration's.
    pub in_uncompiled_method: bool,
}

/// See the module documentation; `None` when the text has no such declaration.
pub(super) fn fb_init_arguments(
    file: FileId,
    src: &str,
    toks: &[Token],
    diags: &mut Diagnostics,
    found: &mut Vec<DeclArgs>,
) -> Option<String> {
    let mut in_vars = false;
    let mut text: Option<String> = None;
    let mut k = 0;
    while k < toks.len() {
        let t = &toks[k];
        // (a STRUCT's fields too: `fb : FB_X(1, 2);` as a field, initialised with each
        // instance of the structure, as TwinCAT and CODESYS do)
        if VAR_KEYWORDS.iter().any(|w| is_word(src, t, w)) || is_word(src, t, "STRUCT") {
            in_vars = true;
        } else if is_word(src, t, "END_VAR") || is_word(src, t, "END_STRUCT") {
            in_vars = false;
        }
        // `ARRAY [..] OF FB_X[(a := 1), (a := 2)]`: a list per element (CODESYS)
        let per_element = in_vars
            && is_word(src, t, "OF")
            && toks.get(k + 1).is_some_and(|n| n.tok == Tok::Ident)
            && toks.get(k + 2).is_some_and(|n| n.tok == Tok::LBracket)
            && toks.get(k + 3).is_some_and(|n| n.tok == Tok::LParen);
        if per_element {
            k = element_lists(file, src, toks, k + 1, diags, found, &mut text);
            continue;
        }
        // `name : FB_X(`, or the element type of `ARRAY [..] OF FB_X(`; the type may be
        // qualified by its library's namespace (`otg : Struckig.Otg(dofs := 6)`): `k` then
        // moves to the token before the type's own name
        let starts = in_vars && (t.tok == Tok::Colon || is_word(src, t, "OF"));
        let mut name_at = k + 1;
        while starts
            && toks.get(name_at).is_some_and(|n| n.tok == Tok::Ident)
            && toks.get(name_at + 1).is_some_and(|n| n.tok == Tok::Dot)
            && toks.get(name_at + 2).is_some_and(|n| n.tok == Tok::Ident)
        {
            name_at += 2;
        }
        let declares = starts
            && toks.get(name_at).is_some_and(|n| n.tok == Tok::Ident)
            && toks.get(name_at + 1).is_some_and(|n| n.tok == Tok::LParen);
        if !declares {
            k += 1;
            continue;
        }
        k = name_at - 1;
        let ty = word(src, &toks[k + 1]);
        let upper = ty.to_ascii_uppercase();
        if Elementary::from_name(&upper).is_some() || upper == "STRING" || upper == "WSTRING" {
            k += 1;
            continue;
        }
        // the argument list, up to its closing parenthesis (or the end of the declaration)
        let open = k + 2;
        let close = group_close(toks, open, false);
        let end = toks
            .get(close)
            .filter(|c| c.tok == Tok::RParen)
            .map_or(toks[close.min(toks.len()) - 1].range.end, |c| c.range.end);
        let start = toks[open].range.start;
        let ty_range = toks[k + 1].range.clone();
        // `FB_X(args)` read as a call statement, in place
        let call = format!("{};", src.get(ty_range.start..end).unwrap_or(""));
        let mut local = Diagnostics::new();
        let stmts = super::parse_statements(file, &call, ty_range.start, &mut local);
        let args = match stmts.into_iter().next().map(|s| s.kind) {
            Some(StmtKind::Call { args, .. }) => args,
            _ => Vec::new(),
        };
        diags.extend(local);
        found.push(DeclArgs {
            ty: Span::new(file, ty_range.start, ty_range.end),
            ty_name: ty.to_string(),
            args,
            span: Span::new(file, start, end),
            elements: Vec::new(),
            in_uncompiled_method: false,
        });
        blank(text.get_or_insert_with(|| src.to_string()), start..end);
        k = close + 1;
    }
    text
}

/// `FB_X[(args), (args) ...]` from the type's name at `ty` (an array's element type): the lists
/// read as calls of `FB_X`, one [`DeclArgs`] pushed to `found`, the bracketed text blanked.
/// Returns the index of the token after the `]` (or where reading stopped).
fn element_lists(
    file: FileId,
    src: &str,
    toks: &[Token],
    ty: usize,
    diags: &mut Diagnostics,
    found: &mut Vec<DeclArgs>,
    text: &mut Option<String>,
) -> usize {
    let ty_range = toks[ty].range.clone();
    let open = ty + 1;
    let mut elements = Vec::new();
    let mut k = open + 1;
    let mut end = toks[open].range.end;
    while toks.get(k).is_some_and(|t| t.tok == Tok::LParen) {
        let close = group_close(toks, k, true);
        let Some(c) = toks.get(close).filter(|c| c.tok == Tok::RParen) else {
            break;
        };
        // `(args)` read as the call `FB_X(args)`, the arguments' spans in the file
        let pad = " ".repeat(toks[k].range.start - ty_range.end);
        let call = format!(
            "{}{pad}{};",
            &src[ty_range.clone()],
            src.get(toks[k].range.start..c.range.end).unwrap_or("")
        );
        let mut local = Diagnostics::new();
        let stmts = super::parse_statements(file, &call, ty_range.start, &mut local);
        diags.extend(local);
        let args = match stmts.into_iter().next().map(|s| s.kind) {
            Some(StmtKind::Call { args, .. }) => args,
            _ => Vec::new(),
        };
        elements.push((args, Span::new(file, toks[k].range.start, c.range.end)));
        end = c.range.end;
        k = close + 1;
        if toks.get(k).is_some_and(|t| t.tok == Tok::Comma) {
            k += 1;
        }
    }
    if let Some(c) = toks.get(k).filter(|t| t.tok == Tok::RBracket) {
        end = c.range.end;
        k += 1;
    }
    let start = toks[open].range.start;
    found.push(DeclArgs {
        ty: Span::new(file, ty_range.start, ty_range.end),
        ty_name: src[ty_range].to_string(),
        args: Vec::new(),
        span: Span::new(file, start, end),
        elements,
        in_uncompiled_method: false,
    });
    blank(text.get_or_insert_with(|| src.to_string()), start..end);
    k
}

/// The index of the `)` closing the parenthesis at `open`, or of the token that ends the declaration
/// first (`;`, and the end of the text when `eof_stops`), or the token count.
fn group_close(toks: &[Token], open: usize, eof_stops: bool) -> usize {
    let mut depth = 0usize;
    let mut close = open;
    while close < toks.len() {
        match toks[close].tok {
            Tok::LParen => depth += 1,
            Tok::RParen => {
                depth -= 1;
                if depth == 0 {
                    break;
                }
            }
            Tok::Semi => break,
            Tok::Eof if eof_stops => break,
            _ => {}
        }
        close += 1;
    }
    close
}
