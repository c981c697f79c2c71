//! Version-control conflict markers left in a source file (`<<<<<<< HEAD` ... `=======` ...
//! `>>>>>>> branch`, with git's `|||||||` base section in the diff3 style).
//!
//! Input: a source text (ST, or IL read through the same entry). Output: `None` when it holds no
//! conflict (a `<<<<<<<` line closed by a `>>>>>>>` line); otherwise one E1039 per outermost
//! conflict, located at its `<<<<<<<` line with labels at its `=======` and `>>>>>>>` lines, and the
//! text with the marker lines and the other sides blanked (spaces for each byte but line ends, so
//! positions do not move): the lines of the first side ("ours") stay, so that the rest of the file
//! is still checked without one error per `<` of the markers.
//!
//! Invariants: a marker is a line that starts with seven `<`, `|`, `=` or `>` followed by a blank or
//! the line's end; `=======`, `|||||||` and `>>>>>>>` lines are markers only inside an open
//! conflict; conflicts may nest (a file merged twice); a `<<<<<<<` never closed is not a conflict.

use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};
use std::ops::Range;

#[derive(Clone, Copy, PartialEq)]
enum Marker {
    Ours,
    Base,
    Theirs,
    End,
}

fn marker(line: &str) -> Option<Marker> {
    let (m, rest) = [
        ("<<<<<<<", Marker::Ours),
        ("|||||||", Marker::Base),
        ("=======", Marker::Theirs),
        (">>>>>>>", Marker::End),
    ]
    .into_iter()
    .find_map(|(p, m)| line.strip_prefix(p).map(|rest| (m, rest)))?;
    rest.chars()
        .next()
        .is_none_or(|c| c.is_whitespace())
        .then_some(m)
}

/// One open conflict: its `<<<<<<<` line, the section being read, its other marker lines.
struct Open {
    opener: Range<usize>,
    section: Marker,
    others: Vec<Range<usize>>,
}

/// Blanks the conflict markers and the sides after the first (see the module header); `None`
/// when `src` holds no closed conflict.
pub(super) fn conflict_markers(file: FileId, src: &str, diags: &mut Diagnostics) -> Option<String> {
    if !src.contains(">>>>>>>") || !src.contains("<<<<<<<") {
        return None;
    }
    let mut stack: Vec<Open> = Vec::new();
    let mut blanked: Vec<Range<usize>> = Vec::new();
    let mut found: Vec<Diagnostic> = Vec::new();
    let mut at = 0usize;
    for line in src.split_inclusive('\n') {
        let range = at..at + line.trim_end_matches(['\n', '\r']).len();
        at += line.len();
        let m = marker(line);
        match m {
            Some(Marker::Ours) => stack.push(Open {
                opener: range.clone(),
                section: Marker::Ours,
                others: Vec::new(),
            }),
            Some(k @ (Marker::Base | Marker::Theirs)) if !stack.is_empty() => {
                let top = stack.last_mut().expect("not empty");
                top.section = k;
                top.others.push(range.clone());
            }
            Some(Marker::End) if !stack.is_empty() => {
                let mut open = stack.pop().expect("not empty");
                open.others.push(range.clone());
                if stack.is_empty() {
                    found.push(conflict_diagnostic(file, &open));
                }
            }
            _ => {
                // a line of a side that is not the first is not read
                if stack.iter().any(|o| o.section != Marker::Ours) {
                    blanked.push(range);
                }
                continue;
            }
        }
        blanked.push(range);
    }
    if found.is_empty() {
        return None;
    }
    let mut text = src.to_string();
    for r in blanked {
        super::file::blank(&mut text, r);
    }
    for d in found {
        diags.push(d);
    }
    Some(text)
}

fn conflict_diagnostic(file: FileId, open: &Open) -> Diagnostic {
    let mut d = Diagnostic::error(
        code::E1039,
        "unresolved merge conflict: the file still holds version-control conflict markers",
    )
    .at(Span::new(file, open.opener.start, open.opener.end))
    .with_primary_label("the conflict starts here");
    for r in &open.others {
        d = d.with_label(Span::new(file, r.start, r.end), "conflict marker");
    }
    d.with_hint("keep the lines of one side, delete the other side and the `<<<<<<<`, `=======` and `>>>>>>>` lines; ladderc checks the rest of the file with the first side's lines")
}
