//! The three renderings: human (codespan-reporting excerpt), short (one line), JSON lines.

use crate::diagnostic::{Diagnostic, Severity};
use crate::source::SourceMap;
use codespan_reporting::diagnostic as cs;
use codespan_reporting::files::SimpleFiles;
use codespan_reporting::term;
use serde::Serialize;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MessageFormat {
    Human,
    Short,
    Json,
}

fn severity_word(s: Severity) -> &'static str {
    match s {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Note => "note",
    }
}

fn xml_context_text(d: &Diagnostic) -> Option<String> {
    let x = d.xml.as_ref()?;
    let mut parts = Vec::new();
    if let Some(p) = &x.pou {
        parts.push(format!("POU `{p}`"));
    }
    if let Some(n) = &x.network {
        parts.push(format!("network {n}"));
    }
    if let Some(l) = &x.local_id {
        parts.push(format!("localId {l}"));
    }
    (!parts.is_empty()).then(|| parts.join(", "))
}

/// Human rendering: header, source excerpt with labels, hint and notes.
pub fn render_human(map: &SourceMap, diags: &[Diagnostic]) -> String {
    let mut files = SimpleFiles::new();
    let ids: Vec<usize> = map
        .files()
        .map(|(_, f)| files.add(f.name.clone(), f.text.clone()))
        .collect();
    let config = term::Config::default();
    let mut out = String::new();
    for d in diags {
        let mut labels = Vec::new();
        if let Some(span) = d.span {
            labels.push(
                cs::Label::primary(ids[span.file.0 as usize], span.range())
                    .with_message(d.primary_label.clone()),
            );
        }
        for l in &d.labels {
            labels.push(
                cs::Label::secondary(ids[l.span.file.0 as usize], l.span.range())
                    .with_message(l.message.clone()),
            );
        }
        let mut notes = Vec::new();
        if let Some(ctx) = xml_context_text(d) {
            notes.push(format!("in {ctx}"));
        }
        if let Some(h) = hint_of(d) {
            notes.push(format!("hint: {h}"));
        }
        notes.extend(d.notes.iter().map(|n| format!("note: {n}")));
        let sev = match d.severity {
            Severity::Error => cs::Severity::Error,
            Severity::Warning => cs::Severity::Warning,
            Severity::Note => cs::Severity::Note,
        };
        let diag = cs::Diagnostic::new(sev)
            .with_code(d.code.0)
            .with_message(d.message.clone())
            .with_labels(labels)
            .with_notes(notes);
        // Spans come from our own source map, so emitting cannot fail on a missing file.
        let _ = term::emit_to_string(&mut out, &config, &files, &diag);
    }
    out
}

/// The diagnostic's own hint, else a pointer to its code's explanation (causes, an example, how to
/// fix): every rendered diagnostic tells the user where to go next.
pub fn hint_of(d: &Diagnostic) -> Option<std::borrow::Cow<'_, str>> {
    Some(match &d.hint {
        Some(h) => std::borrow::Cow::Borrowed(h.as_str()),
        None => std::borrow::Cow::Owned(format!(
            "`ladderc explain {}` shows causes and fixes",
            d.code
        )),
    })
}

/// One line per diagnostic: `file:line:col: error[CODE]: message`; the hint follows after ` (hint: ...)`.
pub fn render_short(map: &SourceMap, d: &Diagnostic) -> String {
    let loc = match d.span {
        Some(span) => {
            let f = map.get(span.file);
            let (line, col) = f.line_col(span.start as usize);
            format!("{}:{line}:{col}: ", f.name)
        }
        None => String::new(),
    };
    let ctx = xml_context_text(d)
        .map(|c| format!(" [{c}]"))
        .unwrap_or_default();
    let hint = hint_of(d)
        .map(|h| format!(" (hint: {h})"))
        .unwrap_or_default();
    format!(
        "{loc}{}[{}]: {}{ctx}{hint}",
        severity_word(d.severity),
        d.code,
        d.message
    )
}

#[derive(Serialize)]
struct JsonLabel<'a> {
    path: &'a str,
    line: usize,
    column: usize,
    end_line: usize,
    end_column: usize,
    byte_start: u32,
    byte_end: u32,
    message: &'a str,
}

/// The schema version carried by every JSON line (`"schema"`): the document is
/// `crates/diagnostics/schema/diagnostics-1.schema.json`. A change that removes or retypes a field bumps it.
pub const JSON_SCHEMA: &str = "ladderc-diagnostic/1";

#[derive(Serialize)]
struct JsonDiagnostic<'a> {
    schema: &'static str,
    /// `"diagnostic"` (the summary record has `"summary"`).
    kind: &'static str,
    code: &'a str,
    severity: &'a str,
    message: &'a str,
    path: Option<&'a str>,
    line: Option<usize>,
    column: Option<usize>,
    end_line: Option<usize>,
    end_column: Option<usize>,
    byte_start: Option<u32>,
    byte_end: Option<u32>,
    labels: Vec<JsonLabel<'a>>,
    hint: Option<std::borrow::Cow<'a, str>>,
    notes: &'a [String],
    pou: Option<&'a str>,
    local_id: Option<&'a str>,
    network: Option<&'a str>,
}

fn json_label<'a>(map: &'a SourceMap, span: crate::Span, message: &'a str) -> JsonLabel<'a> {
    let f = map.get(span.file);
    let (line, column) = f.line_col(span.start as usize);
    let (end_line, end_column) = f.line_col(span.end as usize);
    JsonLabel {
        path: &f.name,
        line,
        column,
        end_line,
        end_column,
        byte_start: span.start,
        byte_end: span.end,
        message,
    }
}

/// One JSON object (no newline) with path, 1-based line/column, byte range, code, severity, message, labels, notes.
pub fn render_json_line(map: &SourceMap, d: &Diagnostic) -> String {
    let primary = d.span.map(|s| json_label(map, s, &d.primary_label));
    let labels = d
        .labels
        .iter()
        .map(|l| json_label(map, l.span, &l.message))
        .collect();
    let j = JsonDiagnostic {
        schema: JSON_SCHEMA,
        kind: "diagnostic",
        code: d.code.0,
        severity: severity_word(d.severity),
        message: &d.message,
        path: primary.as_ref().map(|p| p.path),
        line: primary.as_ref().map(|p| p.line),
        column: primary.as_ref().map(|p| p.column),
        end_line: primary.as_ref().map(|p| p.end_line),
        end_column: primary.as_ref().map(|p| p.end_column),
        byte_start: primary.as_ref().map(|p| p.byte_start),
        byte_end: primary.as_ref().map(|p| p.byte_end),
        labels,
        hint: hint_of(d),
        notes: &d.notes,
        pou: d.xml.as_ref().and_then(|x| x.pou.as_deref()),
        local_id: d.xml.as_ref().and_then(|x| x.local_id.as_deref()),
        network: d.xml.as_ref().and_then(|x| x.network.as_deref()),
    };
    serde_json::to_string(&j).expect("diagnostic serialises")
}

/// Renders a list in the chosen format; every format ends each diagnostic with a newline.
pub fn render(map: &SourceMap, diags: &[Diagnostic], format: MessageFormat) -> String {
    match format {
        MessageFormat::Human => render_human(map, diags),
        MessageFormat::Short => diags.iter().map(|d| render_short(map, d) + "\n").collect(),
        MessageFormat::Json => diags
            .iter()
            .map(|d| render_json_line(map, d) + "\n")
            .collect(),
    }
}

/// What a `run` did, for the summary: cycles, simulated and wall time, their ratio.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct RunSummary {
    pub cycles: u64,
    /// `cycles` times the scan cycle, in seconds.
    pub simulated_s: f64,
    /// Wall time of the program's run, in seconds.
    pub wall_s: f64,
    /// `simulated_s / wall_s` (how many times faster than real time); `null` when too fast to measure.
    pub real_time_factor: Option<f64>,
}

/// The last JSON line of a command: how many errors and warnings it reported, the files it wrote.
#[derive(Debug, Clone, Serialize, PartialEq, Default)]
pub struct Summary {
    pub errors: usize,
    pub warnings: usize,
    /// Paths as given on the command line, in the order they were written.
    pub files: Vec<String>,
    /// Only for `run`, when the program ran.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub run: Option<RunSummary>,
}

#[derive(Serialize)]
struct JsonSummary<'a> {
    schema: &'static str,
    kind: &'static str,
    #[serde(flatten)]
    summary: &'a Summary,
}

/// The summary record as one JSON object (no newline).
pub fn render_summary_json(s: &Summary) -> String {
    serde_json::to_string(&JsonSummary {
        schema: JSON_SCHEMA,
        kind: "summary",
        summary: s,
    })
    .expect("summary serialises")
}
