//! Siemens STL (STEP 7 "AWL", the statement list of S7-200 MicroWIN and S7-300/400 sources) read as
//! instruction list: one error that names the dialect instead of one per line.
//!
//! STL looks like IEC 61131-3 IL (`LD I0.0`) but is not IL: its blocks are `ORGANIZATION_BLOCK` /
//! `DATA_BLOCK` ... `BEGIN` ... with `NETWORK` / `TITLE =` lines, it assigns with `=`, and its logic
//! operations are `A`, `AN`, `O`, `ON`, `X`, `XN` (IEC 61131-3 ed. 2, 3.2, Table 52: `ST`, `AND`,
//! `ANDN`, `OR`, `ORN`, `XOR`, `XORN`; no `=` operator, no ORGANIZATION_BLOCK, no BEGIN).
//!
//! Input: the text of a file read as IL whose IL parse reported errors. Output: E0023 at the first
//! STL mark, or nothing. Invariants: a mark is a line that is not valid IEC IL; the text is taken for
//! STL only on a STEP 7 block keyword (`ORGANIZATION_BLOCK`, `DATA_BLOCK`) or on marks of two kinds
//! (a lone `A x` could be a call of a user function `A`), so an IL file with a typing slip is never
//! reported as STL; one pass over the lines, no allocation per line.

use crate::FileId;
use diagnostics::{code, Diagnostic, Span};

/// What a line shows of STL.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mark {
    /// `ORGANIZATION_BLOCK` or `DATA_BLOCK`: decisive alone.
    Block,
    /// `NETWORK` or `Network 3`.
    Network,
    /// `TITLE =` (a block's or network's title).
    Title,
    /// `BEGIN` (the code part of a block).
    Begin,
    /// `= Q0.0` (STL's assignment).
    Assign,
    /// `A`, `AN`, `O`, `ON`, `X`, `XN` with an operand or `(`.
    Logic,
}

impl Mark {
    /// The label at the mark: what it is in STL, and what IEC IL writes instead.
    fn label(self) -> &'static str {
        match self {
            Mark::Block => "a STEP 7 block: IEC 61131-3 has no such POU",
            Mark::Network => "an STL network heading",
            Mark::Title => "an STL title line",
            Mark::Begin => "`BEGIN` opens an STL block's code",
            Mark::Assign => "STL's assignment `=` (IEC 61131-3 IL writes `ST`)",
            Mark::Logic => {
                "an STL logic operation (IEC 61131-3 IL writes AND, ANDN, OR, ORN, XOR, XORN)"
            }
        }
    }
}

/// E0023 when the text is Siemens STL (see the module header for the marks).
pub(super) fn siemens_stl(file: FileId, src: &str) -> Option<Diagnostic> {
    let mut first: Option<(usize, usize, Mark)> = None;
    let mut kinds: Vec<Mark> = Vec::new();
    let mut decisive = false;
    let mut line_start = 0;
    for line in src.split_inclusive('\n') {
        let at = line_start;
        line_start += line.len();
        let Some((start, end, mark)) = line_mark(line) else {
            continue;
        };
        if first.is_none() {
            first = Some((at + start, at + end, mark));
        }
        if !kinds.contains(&mark) {
            kinds.push(mark);
        }
        decisive |= mark == Mark::Block;
        if decisive || kinds.len() >= 2 {
            break;
        }
    }
    let (start, end, mark) = first?;
    if !(decisive || kinds.len() >= 2) {
        return None;
    }
    Some(
        Diagnostic::error(
            code::E0023,
            "this file is Siemens STL (STEP 7 / MicroWIN AWL), not IEC 61131-3 instruction list: it is not compiled",
        )
        .at(Span::new(file, start, end))
        .with_primary_label(mark.label())
        .with_hint(
            "port it to IEC 61131-3 IL or ST: a PROGRAM with declared variables, AND/ANDN/OR/ORN/ST for A/AN/O/ON/=, \
             %IX0.0 / %QX0.0 for I0.0 / Q0.0, and TON instances for the timers",
        ),
    )
}

/// The STL mark of one line (its byte range in the line), if any.
fn line_mark(line: &str) -> Option<(usize, usize, Mark)> {
    let body = line.split("//").next().unwrap_or("");
    let trimmed = body.trim_start();
    let start = body.len() - trimmed.len();
    let trimmed = trimmed.trim_end();
    if trimmed.is_empty() {
        return None;
    }
    if let Some(rest) = trimmed.strip_prefix('=') {
        // `= Q0.0`, not `=>` or `==`
        let operand = rest.trim_start();
        return (rest.starts_with([' ', '\t'])
            && operand
                .chars()
                .next()
                .is_some_and(|c| c.is_ascii_alphanumeric() || c == '#' || c == '"'))
        .then_some((start, start + 1, Mark::Assign));
    }
    let word_len = trimmed
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(trimmed.len());
    let word = &trimmed[..word_len];
    let rest = &trimmed[word_len..];
    let after = rest.trim_start();
    let mark = if word.eq_ignore_ascii_case("ORGANIZATION_BLOCK")
        || word.eq_ignore_ascii_case("DATA_BLOCK")
    {
        Mark::Block
    } else if word.eq_ignore_ascii_case("NETWORK")
        && (after.is_empty() || after.bytes().all(|b| b.is_ascii_digit()))
    {
        Mark::Network
    } else if word.eq_ignore_ascii_case("TITLE") && after.starts_with('=') {
        Mark::Title
    } else if word.eq_ignore_ascii_case("BEGIN") && after.is_empty() {
        Mark::Begin
    } else if ["A", "AN", "O", "ON", "X", "XN"]
        .iter()
        .any(|op| word.eq_ignore_ascii_case(op))
        && (rest.starts_with([' ', '\t']) && !after.is_empty() && !after.starts_with(':')
            || rest.starts_with('('))
    {
        Mark::Logic
    } else {
        return None;
    };
    Some((start, start + word_len, mark))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn marks(src: &str) -> Option<(u32, u32)> {
        siemens_stl(FileId(0), src).and_then(|d| d.span.map(|s| (s.start, s.end)))
    }

    #[test]
    fn an_organization_block_is_decisive() {
        assert_eq!(marks("ORGANIZATION_BLOCK MAIN:OB1\nBEGIN\n"), Some((0, 18)));
    }

    #[test]
    fn a_network_and_an_assignment_are_stl() {
        assert_eq!(marks("Network 1\nLD I0.0\n= Q0.0\n"), Some((0, 7)));
    }

    #[test]
    fn one_kind_of_mark_alone_is_not_enough() {
        assert_eq!(marks("LD x\nA y\nA z\n"), None);
        assert_eq!(marks("LD x\nST y\n"), None);
        // an IL label `A:` and an ST-like `=>` are no marks
        assert_eq!(marks("A: LD x\nCAL f(q => y)\nNETWORK\n"), None);
    }
}
