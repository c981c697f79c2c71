//! A ladder diagram drawn in text (ASCII art) given as IL or ST: one error that says so instead of
//! one "unexpected character" per `|`, `+` and `-` of the drawing.
//!
//! IEC 61131-3 draws LD in its figures with semigraphic characters (ed. 2, 4.2 and ed. 3, 8.2:
//! power rails `|`, links `---`, contacts `--| |--` / `--|/|--`, coils `--( )--`, `--(S)--`), and some
//! tools and test suites store rungs that way (`+--[ ]--+--( )--`). Such a drawing is no textual
//! language: ladderc reads LD only as PLCopen TC6 XML `<LD>` bodies.
//!
//! Input: the text of a file read as IL or ST whose parse (IL) or lexer (ST) reported errors.
//! Output: E1091 at the first line of the drawing, or nothing. Invariants: the text is taken for a
//! drawing only when, outside comments, a line holds a drawn contact or coil (an opening `[`, `(`
//! or `|` right after a `-`, at most three characters (` `, `/`, `S`, `R`, `P`, `N`) and its
//! closing character followed by `-`, for a coil also by the line's end), which no IL or ST
//! statement holds; a drawing inside a `(* comment *)` or after `//` is never reported; one pass
//! over the text.

use crate::FileId;
use diagnostics::{code, Diagnostic, Span};

/// E1091 when the text holds a ladder rung drawn in text (see the module header).
pub(super) fn text_ladder(file: FileId, src: &str) -> Option<Diagnostic> {
    let code = without_comments(src.as_bytes());
    let mut first_drawing: Option<(usize, usize)> = None;
    let mut drawn = false;
    let mut line_start = 0;
    for line in code.split_inclusive(|&b| b == b'\n') {
        let at = line_start;
        line_start += line.len();
        let Some(start) = line.iter().position(|b| !b.is_ascii_whitespace()) else {
            continue;
        };
        let end = line
            .iter()
            .rposition(|b| !b.is_ascii_whitespace())
            .map_or(start + 1, |e| e + 1);
        drawn = holds_element(line);
        if first_drawing.is_none()
            && (drawn || matches!(line[start], b'|' | b'+') || contains(line, b"--"))
        {
            first_drawing = Some((at + start, at + end));
        }
        if drawn {
            break;
        }
    }
    let (start, end) = first_drawing.filter(|_| drawn)?;
    Some(
        Diagnostic::error(
            code::E1091,
            "this file is a ladder diagram drawn in text (ASCII art), not instruction list or structured text: it is not compiled",
        )
        .at(Span::new(file, start, end))
        .with_primary_label("the drawing starts here")
        .with_hint(
            "ladderc reads ladder diagrams as PLCopen TC6 XML (`<LD>` bodies): export the rungs from the LD editor as \
             PLCopen XML, or write them as IL or ST (`%QX0 := %IX0 OR %IX1;`)",
        ),
    )
}

/// The text with every comment (`(* ... *)`, nested, and `// ...` to the line's end) replaced by
/// spaces, newlines kept: same length, same offsets.
fn without_comments(src: &[u8]) -> Vec<u8> {
    let mut out = src.to_vec();
    let mut depth = 0usize;
    let mut line_comment = false;
    let mut i = 0;
    while i < src.len() {
        let b = src[i];
        let next = src.get(i + 1).copied();
        if line_comment {
            if b == b'\n' {
                line_comment = false;
            } else {
                out[i] = b' ';
            }
            i += 1;
            continue;
        }
        if b == b'(' && next == Some(b'*') {
            depth += 1;
            out[i] = b' ';
            out[i + 1] = b' ';
            i += 2;
            continue;
        }
        if depth > 0 {
            if b == b'*' && next == Some(b')') {
                depth -= 1;
                out[i] = b' ';
                out[i + 1] = b' ';
                i += 2;
                continue;
            }
            if b != b'\n' {
                out[i] = b' ';
            }
            i += 1;
            continue;
        }
        if b == b'/' && next == Some(b'/') {
            line_comment = true;
            continue;
        }
        i += 1;
    }
    out
}

/// Whether the line holds a drawn contact (`-[ ]-`, `-[/]-`, `-| |-`) or coil (`-( )-`, `-(S)`).
fn holds_element(line: &[u8]) -> bool {
    (1..line.len()).any(|i| {
        if line[i - 1] != b'-' {
            return false;
        }
        let close = match line[i] {
            b'[' => b']',
            b'(' => b')',
            b'|' => b'|',
            _ => return false,
        };
        let Some(len) = line[i + 1..].iter().take(4).position(|&b| b == close) else {
            return false;
        };
        let inside = &line[i + 1..i + 1 + len];
        if !inside.iter().all(|b| {
            matches!(
                b.to_ascii_uppercase(),
                b' ' | b'/' | b'S' | b'R' | b'P' | b'N'
            )
        }) {
            return false;
        }
        match line.get(i + 2 + len) {
            Some(b'-') => true,
            None | Some(b'\r' | b'\n' | b' ' | b'\t' | b'|') => close == b')',
            _ => false,
        }
    })
}

fn contains(line: &[u8], what: &[u8]) -> bool {
    line.windows(what.len()).any(|w| w == what)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(src: &str) -> Option<(u32, u32)> {
        text_ladder(FileId(0), src).and_then(|d| d.span.map(|s| (s.start, s.end)))
    }

    #[test]
    fn a_drawn_rung_is_reported_at_its_first_line() {
        let src = "(* rung --[ ]-- *)\n| a   q\n+--[ ]--+--( )--\n|\n";
        assert_eq!(at(src), Some((19, 26)));
        // the IEC form of a contact, and a set coil at the line's end
        assert!(at("|--| |----(S)\n").is_some());
        assert!(at("|--|/|--( )\n").is_some());
    }

    #[test]
    fn il_and_st_and_comments_are_no_drawing() {
        assert_eq!(at("LD a\nOR( b\nAND c\n)\nST q\n"), None);
        assert_eq!(at("q := a - (b) - c;\nx := y[ 1]-z;\n"), None);
        assert_eq!(at("(* --[ ]--( )-- *)\nLD a | b\n// --[/]--( )\n"), None);
        assert_eq!(at("| a\n+-----+\n"), None);
    }
}
