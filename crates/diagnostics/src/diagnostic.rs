//! The diagnostic value: code, severity, one-line message, primary span, secondary labels, hint, notes.

use crate::codes::Code;
use crate::span::Span;
use serde::Serialize;

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Error,
    Warning,
    Note,
}

/// A secondary location with a short message ("first jump here").
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Label {
    pub span: Span,
    pub message: String,
}

/// Where in a PLCopen XML project a diagnostic points, in the engineer's terms.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct XmlContext {
    pub pou: Option<String>,
    pub local_id: Option<String>,
    pub network: Option<String>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Diagnostic {
    pub code: Code,
    pub severity: Severity,
    /// One line, no trailing period.
    pub message: String,
    /// The primary location; `None` only for diagnostics about no file (usage, I/O).
    pub span: Option<Span>,
    /// Message for the primary label (shown under the excerpt); may be empty.
    pub primary_label: String,
    pub labels: Vec<Label>,
    pub hint: Option<String>,
    pub notes: Vec<String>,
    pub xml: Option<XmlContext>,
}

impl Diagnostic {
    pub fn error(code: Code, message: impl Into<String>) -> Self {
        Self::new(code, Severity::Error, message)
    }
    pub fn warning(code: Code, message: impl Into<String>) -> Self {
        Self::new(code, Severity::Warning, message)
    }
    pub fn new(code: Code, severity: Severity, message: impl Into<String>) -> Self {
        Diagnostic {
            code,
            severity,
            message: message.into(),
            span: None,
            primary_label: String::new(),
            labels: Vec::new(),
            hint: None,
            notes: Vec::new(),
            xml: None,
        }
    }
    pub fn at(mut self, span: Span) -> Self {
        self.span = Some(span);
        self
    }
    pub fn with_primary_label(mut self, message: impl Into<String>) -> Self {
        self.primary_label = message.into();
        self
    }
    pub fn with_label(mut self, span: Span, message: impl Into<String>) -> Self {
        self.labels.push(Label {
            span,
            message: message.into(),
        });
        self
    }
    pub fn with_hint(mut self, hint: impl Into<String>) -> Self {
        self.hint = Some(hint.into());
        self
    }
    pub fn with_note(mut self, note: impl Into<String>) -> Self {
        self.notes.push(note.into());
        self
    }
    pub fn with_xml(mut self, xml: XmlContext) -> Self {
        self.xml = Some(xml);
        self
    }
}
