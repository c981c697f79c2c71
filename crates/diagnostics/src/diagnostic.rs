//! The diagnostic value: code, severity, one-line message, primary span, secondary labels, hint, notes.

use crate::codes::Code;
use crate::span::Span;
use serde::Serialize;

/// How bad a diagnostic is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// Stops the build (exit 1).
    Error,
    /// Reported; the build goes on.
    Warning,
    /// Information (a detected language, an ignored pragma).
    Note,
}

/// A secondary location with a short message ("first jump here").
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Label {
    /// Where.
    pub span: Span,
    /// What is there.
    pub message: String,
}

/// Where in a PLCopen XML project a diagnostic points, in the engineer's terms.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct XmlContext {
    /// The POU (`<pou name>`).
    pub pou: Option<String>,
    /// The element's `localId`.
    pub local_id: Option<String>,
    /// The network (rung) of a ladder or FBD body.
    pub network: Option<String>,
}

/// One finding: a stable code, where, what, and how to fix it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Diagnostic {
    /// The stable code (`E1001`); `ladderc explain CODE` explains it.
    pub code: Code,
    /// Error, warning or note.
    pub severity: Severity,
    /// One line, no trailing period.
    pub message: String,
    /// The primary location; `None` only for diagnostics about no file (usage, I/O).
    pub span: Option<Span>,
    /// Message for the primary label (shown under the excerpt); may be empty.
    pub primary_label: String,
    /// Secondary locations.
    pub labels: Vec<Label>,
    /// How to fix it (one line).
    pub hint: Option<String>,
    /// Further lines of context.
    pub notes: Vec<String>,
    /// Where in a PLCopen XML project (POU, network, localId).
    pub xml: Option<XmlContext>,
}

impl Diagnostic {
    /// An error without a location.
    pub fn error(code: Code, message: impl Into<String>) -> Self {
        Self::new(code, Severity::Error, message)
    }
    /// A warning without a location.
    pub fn warning(code: Code, message: impl Into<String>) -> Self {
        Self::new(code, Severity::Warning, message)
    }
    /// A diagnostic of any severity, without a location.
    pub fn new(code: Code, severity: Severity, message: impl Into<String>) -> Self {
        Diagnostic {
            code,
            severity,
            message: clip(message.into()),
            span: None,
            primary_label: String::new(),
            labels: Vec::new(),
            hint: None,
            notes: Vec::new(),
            xml: None,
        }
    }
    /// Located at `span`.
    pub fn at(mut self, span: Span) -> Self {
        self.span = Some(span);
        self
    }
    /// With the message under the primary excerpt.
    pub fn with_primary_label(mut self, message: impl Into<String>) -> Self {
        self.primary_label = message.into();
        self
    }
    /// With a secondary location.
    pub fn with_label(mut self, span: Span, message: impl Into<String>) -> Self {
        if self.labels.len() >= MAX_LABELS {
            // a loop of 20,000 blocks labelled each one: 4.8 MB for one diagnostic
            if !self.notes.iter().any(|n| n == LABELS_LEFT_OUT) {
                self.notes.push(LABELS_LEFT_OUT.to_string());
            }
            return self;
        }
        self.labels.push(Label {
            span,
            message: clip(message.into()),
        });
        self
    }
    /// With the hint.
    pub fn with_hint(mut self, hint: impl Into<String>) -> Self {
        self.hint = Some(clip(hint.into()));
        self
    }
    /// With one more note.
    pub fn with_note(mut self, note: impl Into<String>) -> Self {
        self.notes.push(clip(note.into()));
        self
    }
    /// With its PLCopen XML context.
    pub fn with_xml(mut self, xml: XmlContext) -> Self {
        self.xml = Some(xml);
        self
    }
}

/// The most secondary labels of one diagnostic; further ones are left out and a note says so.
pub const MAX_LABELS: usize = 64;

const LABELS_LEFT_OUT: &str = "further places are left out (at most 64 labels per diagnostic)";

/// The most characters of a message, label, hint or note; longer text (a message that quotes a
/// 300 KB `<expression>`) is cut there and ends with `…`, so one diagnostic stays a few kilobytes.
pub const MAX_TEXT_CHARS: usize = 1000;

fn clip(mut s: String) -> String {
    // A text of at most MAX_TEXT_CHARS bytes has at most as many characters: nothing to count (the
    // common case; counting the characters of every message cost 7 % of an ST fuzz step).
    if s.len() <= MAX_TEXT_CHARS {
        return s;
    }
    if let Some((cut, _)) = s.char_indices().nth(MAX_TEXT_CHARS) {
        s.truncate(cut);
        s.push('…');
    }
    s
}
