//! A text whose language is detected from its content (a `.txt` file, no extension, standard
//! input) but that holds no program in any language ladderc reads: a Modbus register list kept
//! beside a CODESYS project (`0 - SPV_DAC` under `//` banners).
//!
//! The detection (`il_frontend::st::file::detect`, note W0302) reads a text that is neither PLCopen
//! XML nor Structured Text as instruction list; a text none of whose lines is an IL instruction
//! then gave two errors a line (36 for a 37-line register list, issue #13's round 34). IEC
//! 61131-3 (ed. 3, 7.2) writes an IL instruction as an optional label `name:`, an operator and
//! its operand, one per line; a POU, variable or type block starts with its keyword.
//!
//! Input: the text of a file whose language was detected as IL. Output: `None` when some line
//! (outside comments) starts with an IL operator, a keyword of IEC 61131-3 (`FUNCTION_BLOCK`,
//! `VAR`, `TYPE` ...) or a label, or when it holds a rung drawn in text (the IL/ST reader's one E1091
//! says more); else the one E1107 at the first line that is no comment.
//! Invariant: one pass over the text, no recursion.

use diagnostics::{code, Diagnostic, FileId, Span};
use il_frontend::lexer::{classify, Word};

/// The lines of `src` that hold text outside comments (`(* ... *)`, `// ...`): each line's start
/// (its first non-blank byte) and its text outside comments, trimmed.
fn code_lines(src: &str) -> Vec<(usize, String)> {
    let mut lines = Vec::new();
    let mut in_comment = false;
    let mut start = 0;
    for line in src.split_inclusive('\n') {
        let mut text = String::new();
        let bytes = line.as_bytes();
        let mut k = 0;
        while k < bytes.len() {
            if in_comment {
                if line[k..].starts_with("*)") {
                    in_comment = false;
                    k += 2;
                } else {
                    k += 1;
                }
                continue;
            }
            if line[k..].starts_with("(*") {
                in_comment = true;
                k += 2;
                continue;
            }
            if line[k..].starts_with("//") {
                break;
            }
            let Some(c) = line[k..].chars().next() else {
                break;
            };
            text.push(c);
            k += c.len_utf8();
        }
        let trimmed = text.trim();
        if !trimmed.is_empty() {
            let offset = line.len() - line.trim_start().len();
            lines.push((start + offset, trimmed.to_string()));
        }
        start += line.len();
    }
    lines
}

/// Whether the line `text` (comments removed, trimmed) starts as an IL instruction or an IEC
/// 61131-3 block does: an operator or keyword, or a label `name:` (not `name :=`).
fn starts_program_text(text: &str) -> bool {
    let word: String = text
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect();
    if word.is_empty() || word.starts_with(|c: char| c.is_ascii_digit()) {
        return false;
    }
    let rest = text[word.len()..].trim_start();
    if rest.starts_with(':') && !rest.starts_with(":=") {
        return true;
    }
    !matches!(
        classify(&word),
        Word::Ident | Word::True | Word::False | Word::REdge | Word::FEdge
    )
}

/// The one E1107 when the text `src` of `file` (its language detected as IL) holds no line of a
/// program (see the module documentation); `None` otherwise.
pub fn check(file: FileId, src: &str) -> Option<Diagnostic> {
    // a rung drawn in text is the one E1091 of the IL/ST reader (`diag_r31_run.rs`), which says more
    if il_frontend::st::holds_text_ladder(src) {
        return None;
    }
    let lines = code_lines(src);
    if lines.iter().any(|(_, t)| starts_program_text(t)) {
        return None;
    }
    let (at, _) = lines.first()?;
    let line = src.get(*at..).and_then(|r| r.lines().next()).unwrap_or("");
    let end = at + line.trim_end().len();
    Some(
        Diagnostic::error(
            code::E1107,
            "this file holds no program in any language ladderc reads (no IL instruction, no POU or declaration)",
        )
        .at(Span::new(file, *at, end))
        .with_primary_label(format!(
            "not IEC 61131-3 source ({} line{} of text, not compiled)",
            lines.len(),
            if lines.len() == 1 { "" } else { "s" }
        ))
        .with_hint("give the program's source (.st, .il or PLCopen .xml) instead of this file; a note kept beside a project belongs in a comment `(* ... *)`"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_register_list_is_no_program_but_instructions_and_labels_are() {
        let list = "// HOLDING\n0 - SPV_DAC\n1 - SPV_W4\n(* x *)\n";
        let d = check(FileId::default(), list).expect("one error");
        assert_eq!(d.code, code::E1107);
        assert!(check(FileId::default(), "LD a\nST b\n").is_none());
        assert!(check(FileId::default(), "start: x\n").is_none());
        assert!(check(FileId::default(), "(* only a comment *)\n").is_none());
    }
}
