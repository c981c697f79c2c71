//! Text outside every POU of a Structured Text file that declares POUs: a description written as
//! bare text (PC WORX exports each POU's description between `(*@KEY@:DESCRIPTION*)` and
//! `(*@KEY@:END_DESCRIPTION*)`, OSCAT for PC WORX), which IEC 61131-3 allows only in comments
//! (ed. 3, 6.1.5 and Annex B.0: a file is made of POU, type, configuration and global declarations).
//!
//! Input: the file's text and the byte ranges of the tokens outside every block
//! ([`super::file`]'s scan). Output: one E0307 at the first line of the text; the caller blanks the
//! text, so the IL parser does not read it as an implicit program (an `.il` file's form) and the
//! POUs around it are read whole. Invariant: one error per file, whatever the length of the text.

use super::file::trim_span;
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic};
use std::ops::Range;

/// `TYPE`, `FUNCTION`, `VAR_INPUT` ... (upper-case): a word that opens a block outside any POU.
/// After a word of stray text on the same line (`this function adds one`, `an external var of
/// type byte`) it is one more word of that text, not the start of a block that would swallow the
/// POU after it.
pub(super) fn is_block_keyword(w: &str) -> bool {
    super::file::is_var_keyword(w)
        || matches!(
            w,
            "TYPE"
                | "CONFIGURATION"
                | "RESOURCE"
                | "ACTIONS"
                | "ACTION"
                | "INTERFACE"
                | "PROGRAM"
                | "FUNCTION"
                | "FUNCTION_BLOCK"
                | "CLASS"
        )
}

/// The one E0307 for the text outside POUs whose words are `stray` (from `first` to `last`),
/// located at the text's first line.
pub(super) fn text_outside_pous(
    file: FileId,
    src: &str,
    stray: &[Range<usize>],
    first: &Range<usize>,
    last: &Range<usize>,
) -> Diagnostic {
    let line_end = src
        .get(first.start..)
        .and_then(|rest| rest.find('\n'))
        .map_or(src.len(), |k| first.start + k);
    let first_line_end = stray
        .iter()
        .filter(|r| r.end <= line_end)
        .map(|r| r.end)
        .max()
        .unwrap_or(first.end);
    let lines = src
        .get(first.start..last.end)
        .map_or(1, |t| t.lines().count());
    Diagnostic::error(
        code::E0307,
        "text outside any POU: a Structured Text file holds other text only in comments",
    )
    .at(trim_span(src, Span::new(file, first.start, first_line_end)))
    .with_primary_label(format!(
        "not compiled (the text outside POUs spans {lines} line{})",
        if lines == 1 { "" } else { "s" }
    ))
    .with_hint("put a description in a comment `(* ... *)`; the POUs before and after it are read")
}
