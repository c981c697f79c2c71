//! Siemens SCL (TIA Portal) in a `.st` file: one error that names the dialect instead of one per
//! line (a TIA Portal source reads locals as `#name` and data blocks as `"DB".member`, neither of
//! which is IEC 61131-3 Structured Text).
//!
//! Input: the file's text and its ST tokens and lexer problems. Output: E0023 at the first SCL mark,
//! or nothing. Invariants: only constructs that are invalid IEC 61131-3 ST count as marks (a `#`
//! that starts a name; a double-quoted literal followed by `.` and a name; a double-quoted literal
//! right after a block keyword, `FUNCTION_BLOCK "Counter"`), so a valid ST file is never reported.

use super::lexer::{Problem, Tok, Token};
use crate::FileId;
use diagnostics::{code, Diagnostic, Span};

/// The block keywords of an S7-SCL source, whose name may be quoted (`FUNCTION_BLOCK "Counter"`).
const SCL_BLOCKS: [&str; 5] = [
    "FUNCTION_BLOCK",
    "FUNCTION",
    "ORGANIZATION_BLOCK",
    "DATA_BLOCK",
    "TYPE",
];

/// E0023 when the text shows SCL's `#local`, `"DataBlock".member` or a quoted block name.
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
    // `FUNCTION_BLOCK "Counter"`, `ORGANIZATION_BLOCK "Main"`: S7-SCL and TIA Portal sources name
    // a block in double quotes (a symbol), which no IEC 61131-3 POU header allows (round 33: before,
    // E0307 inside the header, or E1095 naming 4CONTROL at the block's SCL `CONST` section)
    let block_name = toks.windows(2).find_map(|w| match (&w[0].tok, &w[1].tok) {
        (Tok::Ident | Tok::Kw(_), Tok::Str(true, _))
            if SCL_BLOCKS.iter().any(|b| {
                src.get(w[0].range.clone())
                    .is_some_and(|x| x.eq_ignore_ascii_case(b))
            }) =>
        {
            Some((
                w[0].range.start,
                w[1].range.end,
                "SCL's block header with a quoted name",
            ))
        }
        _ => None,
    });
    let (start, end, what) = [hash, quoted, block_name]
        .into_iter()
        .flatten()
        .min_by_key(|m| m.0)?;
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
