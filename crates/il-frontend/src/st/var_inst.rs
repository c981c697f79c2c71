//! `VAR_INST` (TwinCAT, Beckhoff Infosys "VAR_INST": "method variables stored in the function block
//! instance") outside a method or a property's accessor: one located E0348 each, the block then
//! read as a `VAR` block.
//!
//! Input: a file's text and tokens. Output: the text with each such `VAR_INST` keyword replaced by
//! `VAR` of the same length (so every span stays where it was), or `None` when there is none. The
//! `VAR_INST` blocks of methods and accessors are left for [`super::file`] and
//! [`super::property`], which keep their variables in the instance (`PendingMethod::inst`).
//! Invariants: a keyword belongs to the nearest `METHOD`, `PROPERTY`, `FUNCTION_BLOCK`, `FUNCTION`
//! or `PROGRAM` keyword before it (after an `END_METHOD` or `END_PROPERTY`, to none); only one
//! belonging to a `METHOD` or `PROPERTY` is a member's.

use super::file::word;
use super::lexer::{Tok, Token};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};

/// See the module documentation.
pub fn var_inst_outside_methods(
    file: FileId,
    src: &str,
    toks: &[Token],
    diags: &mut Diagnostics,
) -> Option<String> {
    let mut out: Option<String> = None;
    let mut owner: Option<String> = None;
    for t in toks {
        if !matches!(t.tok, Tok::Ident | Tok::Kw(_)) {
            continue;
        }
        let w = word(src, t).to_ascii_uppercase();
        match w.as_str() {
            "METHOD" | "PROPERTY" | "FUNCTION_BLOCK" | "FUNCTION" | "PROGRAM" => owner = Some(w),
            "END_METHOD" | "END_PROPERTY" => owner = None,
            "VAR_INST" if !matches!(owner.as_deref(), Some("METHOD" | "PROPERTY")) => {
                let what = match owner.as_deref() {
                    Some("FUNCTION_BLOCK") => "a FUNCTION_BLOCK's own declarations",
                    Some("FUNCTION") => "a FUNCTION",
                    Some("PROGRAM") => "a PROGRAM",
                    _ => "this place",
                };
                diags.push(
                    Diagnostic::error(
                        code::E0348,
                        format!("VAR_INST in {what}: only a METHOD declares VAR_INST"),
                    )
                    .at(Span::new(file, t.range.start, t.range.end))
                    .with_primary_label("not in a method")
                    .with_hint("declare the variables in VAR (a block's VAR keeps its values between calls), or move them into a METHOD of a function block"),
                );
                out.get_or_insert_with(|| src.to_string())
                    .replace_range(t.range.clone(), "VAR     ");
            }
            _ => {}
        }
    }
    out
}
