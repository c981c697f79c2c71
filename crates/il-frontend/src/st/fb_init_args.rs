//! CODESYS's and TwinCAT's FB_init arguments in an instance declaration: `fb : FB_X(nSize := 4);`
//! (or `fbTest : FB_Test(fbPrep);`) passes the arguments to the extra inputs of the block's
//! `FB_init` method, which those systems run once before the first cycle. ladderc does not run
//! FB_init methods, so each such declaration is one E0329 naming it.
//!
//! Input: the text of an `.st` file (or a TwinCAT or CODESYS object read as one) and its tokens.
//! Output: the text with each argument list blanked (so the instance is declared, the rest of the
//! file is checked, and no E0011 cascade follows), and one diagnostic per declaration. Only
//! declarations inside `VAR...END_VAR` blocks are looked at (`name : Type(` where `Type` is no
//! elementary type: `STRING(20)`, `INT(0..10)` are lengths and subranges). Invariant: positions
//! unchanged.

use super::file::{blank, is_word, word};
use super::lexer::{Tok, Token};
use crate::sema::Elementary;
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};

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

/// See the module documentation; `None` when the text has no such declaration.
pub(super) fn fb_init_arguments(
    file: FileId,
    src: &str,
    toks: &[Token],
    diags: &mut Diagnostics,
) -> Option<String> {
    let mut in_vars = false;
    let mut text: Option<String> = None;
    let mut k = 0;
    while k < toks.len() {
        let t = &toks[k];
        if VAR_KEYWORDS.iter().any(|w| is_word(src, t, w)) {
            in_vars = true;
        } else if is_word(src, t, "END_VAR") {
            in_vars = false;
        }
        let declares = in_vars
            && t.tok == Tok::Colon
            && toks.get(k + 1).is_some_and(|n| n.tok == Tok::Ident)
            && toks.get(k + 2).is_some_and(|n| n.tok == Tok::LParen);
        if !declares {
            k += 1;
            continue;
        }
        let ty = word(src, &toks[k + 1]);
        let upper = ty.to_ascii_uppercase();
        if Elementary::from_name(&upper).is_some() || upper == "STRING" || upper == "WSTRING" {
            k += 1;
            continue;
        }
        // the argument list, up to its closing parenthesis (or the end of the declaration)
        let open = k + 2;
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
                _ => {}
            }
            close += 1;
        }
        let end = toks
            .get(close)
            .filter(|c| c.tok == Tok::RParen)
            .map_or(toks[close.min(toks.len()) - 1].range.end, |c| c.range.end);
        let start = toks[open].range.start;
        let name_span = Span::new(file, toks[k + 1].range.start, toks[k + 1].range.end);
        diags.push(
            Diagnostic::error(
                code::E0329,
                format!("`{ty}(...)` in a declaration passes arguments to `{ty}`'s FB_init method (CODESYS, TwinCAT), which ladderc does not run"),
            )
            .at(Span::new(file, start, end))
            .with_primary_label("FB_init arguments")
            .with_label(name_span, "instance type")
            .with_hint(format!(
                "give the instance's inputs initial values instead (`: {ty} := (input := value);`, IEC 61131-3 edition 3), or set them in the first cycle"
            )),
        );
        blank(text.get_or_insert_with(|| src.to_string()), start..end);
        k = close + 1;
    }
    text
}
