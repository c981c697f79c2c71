//! Generic POU headers (`FUNCTION Pick<T : ANY_INT> : T`, RuSTy's extension), handled before the
//! parser: IEC 61131-3 has generic types (`ANY_INT`, `ANY_REAL` ...) for its standard functions
//! only; a user POU's header names no type parameters (ed. 3, 6.6.2.2: `FUNCTION name : type`).
//!
//! Input: the file's text and tokens. Output: the text with each generic POU blanked, from its
//! keyword to its `END_...` (positions unchanged), and one E1085 per such POU at its name and type
//! parameter list. Invariants: every span stays where the user wrote it; nothing of a generic POU
//! reaches the parser (before: E0100 at `<`, its declarations read as statements, W1426 and E0106,
//! and a misleading E0354 or E1020 at its calls); its calls are not reported again (the checks'
//! errors at them are dropped by the caller, `ladderc`'s pipeline).

use super::file::{blank, is_word, word};
use super::lexer::{Tok, Token};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};

/// The most tokens a type parameter list may hold (`<T : ANY_INT, U : ANY_REAL>`): a `<` further
/// from its `>` is no such list.
const MAX_PARAMETER_TOKENS: usize = 64;

/// `None`: no generic POU in the text.
pub(super) fn generic_headers(
    file: FileId,
    src: &str,
    toks: &[Token],
    diags: &mut Diagnostics,
) -> Option<String> {
    let mut text: Option<String> = None;
    let mut k = 0;
    while k + 2 < toks.len() {
        let keyword = &toks[k];
        let kind = ["FUNCTION", "FUNCTION_BLOCK"]
            .into_iter()
            .find(|w| is_word(src, keyword, w));
        let (Some(kind), Some(name), Some(open)) = (kind, toks.get(k + 1), toks.get(k + 2)) else {
            k += 1;
            continue;
        };
        if name.tok != Tok::Ident || open.tok != Tok::Lt {
            k += 1;
            continue;
        }
        // the list's `>`, close by and before any `:=` or `;` (no comparison of a statement)
        let close = toks[k + 3..]
            .iter()
            .take(MAX_PARAMETER_TOKENS)
            .take_while(|t| !matches!(t.tok, Tok::Semi | Tok::Assign | Tok::Eof))
            .position(|t| t.tok == Tok::Gt)
            .map(|p| k + 3 + p);
        let Some(close) = close else {
            k += 1;
            continue;
        };
        let end_word = format!("END_{kind}");
        let end = toks[close..]
            .iter()
            .position(|t| is_word(src, t, &end_word))
            .map_or(toks.len() - 1, |p| close + p);
        let pou = word(src, name);
        let parameters = src
            .get(open.range.start..toks[close].range.end)
            .unwrap_or("<>");
        diags.push(
            Diagnostic::error(
                code::E1085,
                format!(
                    "`{pou}{parameters}`: a generic {} (RuSTy) is not IEC 61131-3; ladderc does not compile it",
                    kind.to_ascii_lowercase().replace('_', " ")
                ),
            )
            .at(Span::new(file, name.range.start, toks[close].range.end))
            .with_primary_label("type parameters")
            .with_hint(format!(
                "IEC 61131-3 has generic types only for its standard functions: write one {kind} per type the program uses (`{pou}_INT`, `{pou}_REAL`); its calls are not reported"
            )),
        );
        let t = text.get_or_insert_with(|| src.to_string());
        blank(t, keyword.range.start..toks[end].range.end);
        k = end + 1;
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::st::lexer::lex;

    /// A generic function is one E1085 at its name and parameters, and blanked whole; a
    /// comparison `a < b` in a body is no parameter list.
    #[test]
    fn a_generic_header_is_one_error_and_the_pou_is_blanked() {
        let src = "FUNCTION Pick<T : ANY_INT> : T\nVAR_INPUT a : T; END_VAR\nPick := a;\nEND_FUNCTION\nPROGRAM P\nVAR x : INT; END_VAR\nIF x < 3 THEN x := 1; END_IF;\nEND_PROGRAM\n";
        let (toks, _) = lex(src);
        let mut diags = Diagnostics::new();
        let text = generic_headers(FileId(0), src, &toks, &mut diags).unwrap_or_default();
        assert_eq!(diags.iter().count(), 1);
        assert_eq!(text.len(), src.len());
        assert!(text.trim_start().starts_with("PROGRAM P"), "{text}");
        assert!(text.contains("IF x < 3 THEN"));
        let src = "PROGRAM P\nVAR x : INT; END_VAR\nIF x < 3 THEN x := 1; END_IF;\nEND_PROGRAM\n";
        let (toks, _) = lex(src);
        assert!(generic_headers(FileId(0), src, &toks, &mut diags).is_none());
    }
}
