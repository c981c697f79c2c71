//! Diagnostics shared by every ladderc stage.
//!
//! Input: spans into files registered in a [`SourceMap`], stable [`Code`]s (one explanation file each under
//! `explanations/`), messages and hints produced by the stages.
//! Output: three renderings of a [`Diagnostic`] list: human (source excerpt with labels and a hint), short
//! (`file:line:col: error[CODE]: message`, one line, for IDE problem matchers) and JSON lines (each with
//! `"schema": "ladderc-diagnostic/1"`, [`JSON_SCHEMA`]; the document is `schema/diagnostics-1.schema.json`),
//! plus the final [`Summary`] record ([`render_summary_json`]).
//! Invariants: a span always refers to a file of the source map and lies on UTF-8 boundaries of its text;
//! line and column are 1-based, columns count characters (not bytes).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod codes;
mod diagnostic;
mod render;
mod source;
mod span;

pub use codes::{all as all_codes, explain, lookup, Code, CodeInfo};
pub use diagnostic::{Diagnostic, Label, Severity, XmlContext};
pub use render::{
    hint_of, max_per_file, max_per_file_json, render, render_human, render_json_line, render_short,
    render_summary_json, set_max_per_file, MessageFormat, RunSummary, Summary,
    DEFAULT_MAX_PER_FILE, JSON_SCHEMA,
};
pub use source::{line_starts, FileEncoding, SourceFile, SourceMap};
pub use span::{FileId, Span};

/// All codes as constants (`diagnostics::code::E0001`), generated from `explanations/`.
pub mod code {
    pub use crate::codes::generated::*;
}

/// A sink that stages push diagnostics into; keeps the count of errors so a stage can stop before codegen.
/// A diagnostic equal to one already pushed (same code, severity, place and message: a text read
/// twice by two stages) is left out, so the user reads each once.
#[derive(Default, Clone)]
pub struct Diagnostics {
    list: Vec<Diagnostic>,
    /// The hashes of the diagnostics pushed (code, severity, place, message).
    seen: std::collections::HashSet<u64>,
    /// Where diagnostics of some files are shown instead (boxed: the sink is returned in `Err`s).
    places: Box<Places>,
}

/// Files and pieces of files whose diagnostics are shown elsewhere.
#[derive(Default, Clone)]
struct Places {
    /// Files that are copies of another, byte for byte (a block with generic constants built once
    /// per set of values): their diagnostics are placed in the original ([`Diagnostics::read_as`]).
    copies: std::collections::HashMap<FileId, FileId>,
    /// Pieces of a file's text written elsewhere in it than they stand in the file
    /// ([`Diagnostics::read_moved`]), sorted by where they were written.
    moved: std::collections::HashMap<FileId, Vec<MovedText>>,
}

/// A piece of text that a reader wrote at one place of a file's text as compiled (`at`, `len`
/// bytes) but that stands at another place of the same file (`from`): a TwinCAT chart's condition
/// taken from its `<Transition>` object. Pieces of one `group` (one condition) are one text: a
/// span from one of them to another is moved as a whole.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MovedText {
    /// Where the piece was written in the text as compiled.
    pub at: u32,
    /// Its length in bytes.
    pub len: u32,
    /// Where it stands in the file.
    pub from: u32,
    /// The text it belongs to: spans across pieces of different groups are not moved.
    pub group: u32,
}

/// The list alone (the hashes are bookkeeping): two sinks that hold the same diagnostics print the
/// same.
impl std::fmt::Debug for Diagnostics {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Diagnostics")
            .field("list", &self.list)
            .finish()
    }
}

impl Diagnostics {
    /// An empty list.
    pub fn new() -> Self {
        Self::default()
    }
    /// Adds one, unless an equal one is there (E1089, a name with letters beyond ASCII: one per
    /// name and file, at its first use).
    pub fn push(&mut self, mut d: Diagnostic) {
        use std::hash::{Hash, Hasher};
        if !self.places.moved.is_empty() {
            if let Some(sp) = d.span.as_mut() {
                *sp = self.where_written(*sp);
            }
            for l in &mut d.labels {
                l.span = self.where_written(l.span);
            }
        }
        if !self.places.copies.is_empty() {
            let original = |sp: &mut Span| {
                if let Some(f) = self.places.copies.get(&sp.file) {
                    sp.file = *f;
                }
            };
            if let Some(sp) = d.span.as_mut() {
                original(sp);
            }
            d.labels.iter_mut().for_each(|l| original(&mut l.span));
        }
        let mut h = std::collections::hash_map::DefaultHasher::new();
        if d.code.0 == "E1089" {
            (d.code, d.span.map(|s| s.file), &d.message).hash(&mut h);
        } else {
            (d.code, d.severity, d.span, &d.message).hash(&mut h);
        }
        if self.seen.insert(h.finish()) {
            self.list.push(d);
        }
    }
    /// From now on, places the diagnostics of `copy` (a file whose text is `original`'s, byte for
    /// byte, read again) in `original`, where one equal to a diagnostic of `original` is left out.
    pub fn read_as(&mut self, copy: FileId, original: FileId) {
        self.places.copies.insert(copy, original);
    }
    /// From now on, places a diagnostic whose span lies in pieces of `file`'s text that were written
    /// elsewhere than they stand (`pieces`, sorted by [`MovedText::at`]) where they stand in the file.
    pub fn read_moved(&mut self, file: FileId, mut pieces: Vec<MovedText>) {
        if pieces.is_empty() {
            return;
        }
        pieces.sort_by_key(|p| p.at);
        self.places.moved.insert(file, pieces);
    }
    /// `span` where its text stands in the file: moved when it starts and ends inside pieces of
    /// one group of [`Diagnostics::read_moved`], else as it is.
    fn where_written(&self, span: Span) -> Span {
        let Some(pieces) = self.places.moved.get(&span.file) else {
            return span;
        };
        // the piece holding byte `pos` (`end`: the piece the span's last byte is in)
        let piece = |pos: u32, end: bool| {
            let k = pieces.partition_point(|p| p.at <= pos.saturating_sub(u32::from(end)));
            let p = pieces.get(k.checked_sub(1)?)?;
            let inside = if end {
                pos > p.at && pos <= p.at + p.len
            } else {
                pos >= p.at && pos < p.at + p.len
            };
            inside.then_some(*p)
        };
        let (Some(a), Some(b)) = (piece(span.start, false), piece(span.end, !span.is_empty()))
        else {
            return span;
        };
        let (start, end) = (a.from + (span.start - a.at), b.from + (span.end - b.at));
        if a.group != b.group || end < start {
            return span;
        }
        Span { start, end, ..span }
    }
    /// Adds several (each as [`Diagnostics::push`]).
    pub fn extend(&mut self, ds: impl IntoIterator<Item = Diagnostic>) {
        for d in ds {
            self.push(d);
        }
    }
    /// Whether one is an error.
    pub fn has_errors(&self) -> bool {
        self.list.iter().any(|d| d.severity == Severity::Error)
    }
    /// How many are warnings.
    pub fn warning_count(&self) -> usize {
        self.list
            .iter()
            .filter(|d| d.severity == Severity::Warning)
            .count()
    }
    /// How many are errors.
    pub fn error_count(&self) -> usize {
        self.list
            .iter()
            .filter(|d| d.severity == Severity::Error)
            .count()
    }
    /// The diagnostics in the order they were reported.
    pub fn as_slice(&self) -> &[Diagnostic] {
        &self.list
    }
    /// The diagnostics, in the order they were reported.
    pub fn iter(&self) -> std::slice::Iter<'_, Diagnostic> {
        self.list.iter()
    }
    /// Keeps only those for which `keep` is true (a later stage withdrawing a note an earlier one
    /// made: a file it did not compile after all).
    pub fn retain(&mut self, keep: impl FnMut(&Diagnostic) -> bool) {
        self.list.retain(keep);
    }
    /// The diagnostics reported from the `from`-th on, to be completed where an earlier stage knows
    /// more than the one that reported them (a qualifier the parser did not see).
    pub fn since_mut(&mut self, from: usize) -> &mut [Diagnostic] {
        let from = from.min(self.list.len());
        &mut self.list[from..]
    }
    /// Changes each in place (a later stage completing an earlier one's message: how many uses an
    /// unknown type has). The duplicate check keeps the text they were added with.
    pub fn update(&mut self, f: impl FnMut(&mut Diagnostic)) {
        self.list.iter_mut().for_each(f);
    }
    /// How many there are.
    pub fn len(&self) -> usize {
        self.list.len()
    }
    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }
    /// Sorted by file, then position, then code: stable output for IDEs and snapshots.
    pub fn into_sorted(mut self) -> Vec<Diagnostic> {
        self.list.sort_by(|a, b| {
            let ka = a.span.map(|s| (s.file.0, s.start, s.end));
            let kb = b.span.map(|s| (s.file.0, s.start, s.end));
            ka.cmp(&kb).then_with(|| a.code.0.cmp(b.code.0))
        });
        self.list
    }
    /// The diagnostics, in the order they were reported.
    pub fn into_vec(self) -> Vec<Diagnostic> {
        self.list
    }
}

impl IntoIterator for Diagnostics {
    type Item = Diagnostic;
    type IntoIter = std::vec::IntoIter<Diagnostic>;
    fn into_iter(self) -> Self::IntoIter {
        self.list.into_iter()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_equal_diagnostic_is_kept_once_and_a_different_one_is_not_lost() {
        let at = |s: usize| Span::new(FileId(0), s, s + 2);
        let d = |s: usize, m: &str| Diagnostic::error(code::E0100, m).at(at(s));
        let mut ds = Diagnostics::new();
        ds.push(d(4, "expected `)`"));
        ds.extend([d(4, "expected `)`"), d(4, "expected `)`")]);
        // another place, another message, another severity: kept
        ds.push(d(9, "expected `)`"));
        ds.push(d(4, "expected `,`"));
        ds.push(Diagnostic::warning(code::E0100, "expected `)`").at(at(4)));
        assert_eq!(ds.len(), 4);
        assert_eq!(ds.error_count(), 3);
        // a list taken out and pushed again keeps them all
        let again: Vec<Diagnostic> = std::mem::take(&mut ds).into_vec();
        ds.extend(again);
        assert_eq!(ds.len(), 4);
    }
}
