//! TwinCAT's and CODESYS's generic constants (`VAR_GENERIC CONSTANT`), which ladderc does not
//! compile: one located E1081 per declaration block and per instance that gives the constants.
//!
//! Beckhoff Infosys, TC3 PLC "Generic constant variables - VAR_GENERIC CONSTANT" (TwinCAT 3.1 Build
//! 4026; CODESYS online help "VAR_GENERIC CONSTANT" likewise): a function block declares
//! `VAR_GENERIC CONSTANT maxlen : UDINT := 1; END_VAR` and uses `maxlen` in its array bounds and
//! string lengths; each instance gives its own value in angle brackets after the block's name
//! (`fbPou : FB_Pou<100>;`, `FB_Pou<(2 * cconst)>`, `ARRAY[0..5] OF FB_Pou<100>`, `EXTENDS
//! FB_Pou<1000>`), so every instance is a block of its own size. "The initial value is only needed
//! for compile checks. At runtime, the value is overwritten."
//!
//! Input: a file's text and its tokens. Output: the text with each `VAR_GENERIC` keyword read as
//! `VAR` (so the block's constants are `VAR CONSTANT` with their initial value and the block's
//! declarations and body are read as such, with no cascade of parse errors; an `EXTENDS` or
//! `IMPLEMENTS` clause that TwinCAT writes after this block, `END_VAR IMPLEMENTS I_Trace`, is then
//! read as the block's clause by [`super::file`]'s scan) and each `<...>` after
//! a block's name in a declaration (after `:`, `OF` or `EXTENDS`) blanked; one E1081 for each of
//! them, or `None` when the text has neither. Invariant: positions unchanged (replaced bytes become
//! blanks), so every span stays where the user wrote it; the E1081 keep the run from starting, as the
//! sizes compiled (the initial values) are not the instances' own.

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
            diags.push(
                Diagnostic::error(
                    code::E1081,
                    "generic constants (`VAR_GENERIC CONSTANT`, TwinCAT 3.1.4026 and CODESYS) are not supported",
                )
                .at(span(file, t))
                .with_primary_label("the block's generic constants")
                .with_hint("declare the sizes as constants (VAR CONSTANT or a global constant list) and write one function block per size; ladderc reads these constants with their initial values"),
            );
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
        let block = word(src, &toks[k - 1]);
        diags.push(
            Diagnostic::error(
                code::E1081,
                format!(
                    "`{block}<...>` gives generic constants (`VAR_GENERIC CONSTANT`), which ladderc does not support"
                ),
            )
            .at(crate::Span::new(file, t.range.start, toks[close].range.end))
            .with_primary_label("the instance's generic constants")
            .with_hint(format!(
                "write a function block of this size and declare the instance with it; ladderc reads this instance as a plain `{block}`"
            )),
        );
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

fn span(file: crate::FileId, t: &Token) -> crate::Span {
    crate::Span::new(file, t.range.start, t.range.end)
}

/// The `>` that closes the `<` at `open` (parentheses nest inside: `<(a > b)>` has none at its
/// level), `None` when a `;`, `:=` or the end of the declaration's line of tokens comes first.
fn closing_angle(toks: &[Token], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (j, t) in toks.iter().enumerate().skip(open + 1) {
        match t.tok {
            Tok::LParen | Tok::LBracket => depth += 1,
            Tok::RParen | Tok::RBracket => depth = depth.checked_sub(1)?,
            Tok::Gt if depth == 0 => return Some(j),
            Tok::Semi | Tok::Assign => return None,
            Tok::Kw(_) if depth == 0 => return None,
            _ => {}
        }
    }
    None
}
