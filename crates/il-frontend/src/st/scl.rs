//! Siemens SCL (TIA Portal) in a `.st` file: one error that names the dialect instead of one per
//! line (a TIA Portal source reads locals as `#name` and data blocks as `"DB".member`, neither of
//! which is IEC 61131-3 Structured Text).
//!
//! Input: the file's text and its ST tokens and lexer problems. Output: E0023 at the first SCL mark,
//! or nothing. Invariants: only constructs that are invalid IEC 61131-3 ST count as marks (a `#`
//! that starts a name; a double-quoted literal followed by `.` and a name), so a valid ST file is
//! never reported.

use super::lexer::{Problem, Tok, Token};
use crate::FileId;
use diagnostics::{code, Diagnostic, Span};

/// E0023 when the text shows SCL's `#local` or `"DataBlock".member`.
pub(super) fn siemens_scl(
    file: FileId,
    src: &str,
    toks: &[Token],
    problems: &[Problem],
) -> Option<Diagnostic> {
    let hash = problems.iter().find_map(|p| match p {
        Problem::UnexpectedChar(r)
            if src.as_bytes().get(r.start) == Some(&b'#')
                && src[r.end..]
                    .chars()
                    .next()
                    .is_some_and(|c| c.is_ascii_alphabetic() || c == '_') =>
        {
            let end = r.end
                + src[r.end..]
                    .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                    .unwrap_or(src.len() - r.end);
            Some((r.start, end, "SCL's prefix of a local variable"))
        }
        _ => None,
    });
    let quoted = toks
        .windows(3)
        .find_map(|w| match (&w[0].tok, &w[1].tok, &w[2].tok) {
            (Tok::Str(true, _), Tok::Dot, Tok::Ident) => Some((
                w[0].range.start,
                w[2].range.end,
                "SCL's access to a member of a data block",
            )),
            _ => None,
        });
    let (start, end, what) = match (hash, quoted) {
        (Some(a), Some(b)) => {
            if a.0 <= b.0 {
                a
            } else {
                b
            }
        }
        (Some(a), None) | (None, Some(a)) => a,
        (None, None) => return None,
    };
    Some(
        Diagnostic::error(
            code::E0023,
            format!(
                "this file is Siemens SCL (TIA Portal), not IEC 61131-3 Structured Text: `{}` is {what}",
                &src[start..end]
            ),
        )
        .at(Span::new(file, start, end))
        .with_primary_label("SCL, not ST")
        .with_hint("write IEC 61131-3 ST: locals without `#`, data blocks as global variables (VAR_GLOBAL) or instances; the rest of the file is not compiled"),
    )
}

/// E0023 when the text is a SIMOTION ST unit: `UNIT Name;` first, then its `INTERFACE` or
/// `IMPLEMENTATION` section (SIMOTION ST, Siemens's motion controllers: `USES`, `ARRAY[..]`
/// dynamic arrays, none of it IEC 61131-3). At the `UNIT` line; the rest is not compiled.
pub(super) fn simotion_unit(file: FileId, src: &str, toks: &[Token]) -> Option<Diagnostic> {
    let word = |t: &Token, w: &str| {
        src.get(t.range.clone())
            .is_some_and(|x| x.eq_ignore_ascii_case(w))
    };
    let [unit, name, semi, ..] = toks else {
        return None;
    };
    let header = word(unit, "UNIT") && name.tok == Tok::Ident && semi.tok == Tok::Semi;
    let sections = toks[3..]
        .iter()
        .any(|t| word(t, "IMPLEMENTATION") || word(t, "INTERFACE"));
    if !(header && sections) {
        return None;
    }
    Some(
        Diagnostic::error(
            code::E0023,
            format!(
                "this file is a SIMOTION ST unit (`UNIT {}`), not IEC 61131-3 Structured Text",
                &src[name.range.clone()]
            ),
        )
        .at(Span::new(file, unit.range.start, semi.range.end))
        .with_primary_label("SIMOTION ST, not IEC 61131-3")
        .with_hint("write the unit's POUs as IEC 61131-3 ST: the FUNCTIONs and FUNCTION_BLOCKs of its IMPLEMENTATION without UNIT, INTERFACE, USES and IMPLEMENTATION, arrays with their bounds (`ARRAY[0..9] OF LREAL`, not `ARRAY[..]`); the rest of the file is not compiled"),
    )
}
