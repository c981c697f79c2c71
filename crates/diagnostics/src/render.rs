//! The three renderings: human (codespan-reporting excerpt), short (one line), JSON lines.

use crate::diagnostic::{Diagnostic, Severity};
use crate::source::{SourceFile, SourceMap};
use codespan_reporting::diagnostic as cs;
use codespan_reporting::files;
use codespan_reporting::term;
use serde::Serialize;
use std::sync::atomic::{AtomicUsize, Ordering};

/// How diagnostics are printed (`--message-format`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MessageFormat {
    /// Source excerpts with labels, hints and notes.
    Human,
    /// One line each: `file:line:col: error[CODE]: message`.
    Short,
    /// JSON lines ([`JSON_SCHEMA`]).
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

/// How many diagnostics per file the human and short renderings show by default; the rest are
/// counted in one line. Change it with [`set_max_per_file`] (`ladderc --max-diagnostics N`).
pub const DEFAULT_MAX_PER_FILE: usize = 50;

/// How many diagnostics per file JSON lines shows by default (the summary record's `errors` and
/// `warnings` count them all). 1,000 records of a few hundred bytes keep the output of any input to
/// a few hundred kilobytes per file; [`set_max_per_file`] changes it too.
pub const DEFAULT_MAX_PER_FILE_JSON: usize = 1000;

static MAX_PER_FILE: AtomicUsize = AtomicUsize::new(DEFAULT_MAX_PER_FILE);
static MAX_PER_FILE_JSON: AtomicUsize = AtomicUsize::new(DEFAULT_MAX_PER_FILE_JSON);

/// Sets how many diagnostics per file every rendering shows (0: no limit).
pub fn set_max_per_file(n: usize) {
    let n = if n == 0 { usize::MAX } else { n };
    MAX_PER_FILE.store(n, Ordering::Relaxed);
    MAX_PER_FILE_JSON.store(n, Ordering::Relaxed);
}

/// The current per-file limit of the human and short renderings.
pub fn max_per_file() -> usize {
    MAX_PER_FILE.load(Ordering::Relaxed)
}

/// The current per-file limit of JSON lines.
pub fn max_per_file_json() -> usize {
    MAX_PER_FILE_JSON.load(Ordering::Relaxed)
}

/// Characters of a long source line shown before the first label on it.
const CONTEXT_BEFORE: usize = 40;
/// Characters of a source line shown at most; longer lines are clipped around the label with `…`.
const MAX_LINE_CHARS: usize = 160;

/// One clipped source line of an excerpt.
struct ExcerptLine {
    /// Where the line starts in the excerpt text, and where its copied content starts (after `…`).
    start: usize,
    content: usize,
    /// The copied window of the real text.
    real: std::ops::Range<usize>,
    /// The real 1-based line number, and the characters of the real line before the window.
    number: usize,
    skipped_chars: usize,
}

/// The lines of one file that a diagnostic's labels touch, each clipped to a window around its
/// first label: what codespan-reporting renders instead of the whole file. Building it costs time
/// proportional to the windows (and to finding the line: a binary search in the file's line index).
struct Excerpt {
    name: String,
    text: String,
    lines: Vec<ExcerptLine>,
}

impl Excerpt {
    /// `anchors`: the real byte offsets where labels start (on character boundaries).
    fn new(f: &SourceFile, anchors: &[usize]) -> Excerpt {
        let starts = f.line_starts();
        let text = &f.text;
        let mut by_line: Vec<(usize, usize)> = anchors
            .iter()
            .map(|&a| {
                let line = match starts.binary_search(&a) {
                    Ok(l) => l,
                    Err(l) => l - 1,
                };
                (line, a)
            })
            .collect();
        by_line.sort_unstable();
        by_line.dedup_by_key(|(l, _)| *l);
        // codespan-reporting shows the one line between two labelled lines (and `·` for a longer gap)
        let gaps: Vec<(usize, usize)> = by_line
            .windows(2)
            .filter(|w| w[1].0 == w[0].0 + 2)
            .map(|w| (w[0].0 + 1, starts[w[0].0 + 1]))
            .collect();
        by_line.extend(gaps);
        by_line.sort_unstable();
        let mut out = Excerpt {
            name: f.name.clone(),
            text: String::new(),
            lines: Vec::new(),
        };
        for (line, anchor) in by_line {
            let line_start = starts[line];
            let mut line_end = starts.get(line + 1).map_or(text.len(), |&n| n - 1);
            if text[line_start..line_end].ends_with('\r') {
                line_end -= 1;
            }
            let anchor = anchor.clamp(line_start, line_end);
            let short = text[line_start..line_end]
                .char_indices()
                .nth(MAX_LINE_CHARS)
                .is_none();
            let ws = if short {
                line_start
            } else {
                text[line_start..anchor]
                    .char_indices()
                    .rev()
                    .take(CONTEXT_BEFORE)
                    .last()
                    .map_or(anchor, |(i, _)| line_start + i)
            };
            let we = text[ws..line_end]
                .char_indices()
                .nth(MAX_LINE_CHARS)
                .map_or(line_end, |(i, _)| ws + i);
            let start = out.text.len();
            if ws > line_start {
                out.text.push('…');
            }
            let content = out.text.len();
            out.text.push_str(&text[ws..we]);
            if we < line_end {
                out.text.push('…');
            }
            out.text.push('\n');
            out.lines.push(ExcerptLine {
                start,
                content,
                real: ws..we,
                number: line + 1,
                skipped_chars: text[line_start..ws].chars().count(),
            });
        }
        out
    }

    /// The excerpt line holding real offset `b`, if any.
    fn line_of(&self, f: &SourceFile, b: usize) -> Option<usize> {
        let starts = f.line_starts();
        let real_line = match starts.binary_search(&b) {
            Ok(l) => l,
            Err(l) => l - 1,
        } + 1;
        self.lines.iter().position(|l| l.number == real_line)
    }

    /// A real byte range, as a range of the excerpt (clipped to the window of its start's line).
    fn map(&self, f: &SourceFile, r: std::ops::Range<usize>) -> std::ops::Range<usize> {
        let Some(i) = self.line_of(f, r.start) else {
            return 0..0;
        };
        let l = &self.lines[i];
        let clip = |b: usize| l.content + b.clamp(l.real.start, l.real.end) - l.real.start;
        let (s, e) = (clip(r.start), clip(r.end.max(r.start)));
        if r.end > l.real.end && e == s {
            // a label that starts past the window: mark the window's end
            return s..s;
        }
        s..e
    }
}

/// The excerpts of one diagnostic, as codespan-reporting's file provider (real line numbers and
/// columns).
struct Excerpts(Vec<Excerpt>);

impl<'a> files::Files<'a> for Excerpts {
    type FileId = usize;
    type Name = &'a str;
    type Source = &'a str;
    fn name(&'a self, id: usize) -> Result<&'a str, files::Error> {
        Ok(&self.get(id)?.name)
    }
    fn source(&'a self, id: usize) -> Result<&'a str, files::Error> {
        Ok(&self.get(id)?.text)
    }
    /// Line indices are the real ones (0-based), so gaps between excerpt lines show as gaps.
    fn line_index(&'a self, id: usize, byte_index: usize) -> Result<usize, files::Error> {
        let x = self.get(id)?;
        let k = x
            .lines
            .partition_point(|l| l.start <= byte_index)
            .saturating_sub(1);
        Ok(x.lines.get(k).map_or(0, |l| l.number - 1))
    }
    fn column_number(
        &'a self,
        id: usize,
        line_index: usize,
        byte_index: usize,
    ) -> Result<usize, files::Error> {
        let x = self.get(id)?;
        let Some(l) = x.line(line_index) else {
            return Ok(1);
        };
        let b = byte_index.clamp(l.content, l.content + l.real.len());
        Ok(l.skipped_chars + x.text[l.content..b].chars().count() + 1)
    }
    fn line_range(
        &'a self,
        id: usize,
        line_index: usize,
    ) -> Result<std::ops::Range<usize>, files::Error> {
        let x = self.get(id)?;
        let Some(k) = x.lines.iter().position(|l| l.number == line_index + 1) else {
            // a line outside the excerpt: shown empty
            return Ok(x.text.len()..x.text.len());
        };
        let end = x.lines.get(k + 1).map_or(x.text.len(), |n| n.start);
        Ok(x.lines[k].start..end)
    }
}

impl Excerpt {
    /// The excerpt line of real 0-based line `index`.
    fn line(&self, index: usize) -> Option<&ExcerptLine> {
        let k = self
            .lines
            .binary_search_by_key(&(index + 1), |l| l.number)
            .ok()?;
        self.lines.get(k)
    }
}

impl Excerpts {
    fn get(&self, id: usize) -> Result<&Excerpt, files::Error> {
        self.0.get(id).ok_or(files::Error::FileMissing)
    }
}

/// The diagnostics to show (at most [`max_per_file`] per file of their primary span, in order) and,
/// per file, how many were left out. Errors come first: a file's errors take the room before its
/// warnings and notes, so that a rejected file always shows why (51 warnings and one error show the
/// error and 49 warnings), and the order of what is shown stays the order given.
fn limited<'d>(
    map: &SourceMap,
    diags: &'d [Diagnostic],
    max: usize,
) -> (Vec<&'d Diagnostic>, Vec<String>) {
    // index 0: no span; file i + 1
    let file = |d: &Diagnostic| d.span.map_or(0, |s| s.file.0 as usize + 1);
    let mut errors: Vec<usize> = Vec::new();
    for d in diags.iter().filter(|d| d.severity == Severity::Error) {
        let k = file(d);
        if errors.len() <= k {
            errors.resize(k + 1, 0);
        }
        errors[k] += 1;
    }
    let mut shown_errors: Vec<usize> = Vec::new();
    let mut shown_others: Vec<usize> = Vec::new();
    let mut left: Vec<usize> = Vec::new();
    let mut keep = Vec::new();
    for d in diags {
        let k = file(d);
        if left.len() <= k {
            shown_errors.resize(k + 1, 0);
            shown_others.resize(k + 1, 0);
            left.resize(k + 1, 0);
        }
        let room = if d.severity == Severity::Error {
            shown_errors[k] < max
        } else {
            let errors = errors.get(k).copied().unwrap_or(0);
            shown_others[k] < max.saturating_sub(errors)
        };
        if room {
            if d.severity == Severity::Error {
                shown_errors[k] += 1;
            } else {
                shown_others[k] += 1;
            }
            keep.push(d);
        } else {
            left[k] += 1;
        }
    }
    let mut tail = Vec::new();
    for (k, &n) in left.iter().enumerate().filter(|(_, &n)| n > 0) {
        let place = if k == 0 {
            String::from("without a location")
        } else {
            format!("in {}", map.get(crate::FileId(k as u32 - 1)).name)
        };
        tail.push(format!(
            "note: {n} more diagnostic{} {place} not shown (at most {max} per file; change with --max-diagnostics N, 0 for all)",
            if n == 1 { "" } else { "s" }
        ));
    }
    (keep, tail)
}

/// Human rendering: header, source excerpt with labels, hint and notes. At most [`max_per_file`]
/// diagnostics per file, then one line counting the rest; long lines are clipped around the label.
/// Work and output are proportional to what is shown, not to the size of the files.
pub fn render_human(map: &SourceMap, diags: &[Diagnostic]) -> String {
    let config = term::Config::default();
    let mut out = String::new();
    let (keep, tail) = limited(map, diags, max_per_file());
    for d in keep {
        // every span of the diagnostic, primary first, grouped by file into excerpts
        let mut spans: Vec<(crate::Span, bool, &str)> = Vec::new();
        if let Some(span) = d.span {
            spans.push((span, true, &d.primary_label));
        }
        spans.extend(d.labels.iter().map(|l| (l.span, false, l.message.as_str())));
        let mut file_ids: Vec<crate::FileId> = spans.iter().map(|s| s.0.file).collect();
        file_ids.sort_unstable_by_key(|f| f.0);
        file_ids.dedup();
        let excerpts = Excerpts(
            file_ids
                .iter()
                .map(|&id| {
                    let f = map.get(id);
                    let anchors: Vec<usize> = spans
                        .iter()
                        .filter(|s| s.0.file == id)
                        .map(|s| f.floor_char_boundary(s.0.start as usize))
                        .collect();
                    Excerpt::new(f, &anchors)
                })
                .collect(),
        );
        let labels = spans
            .iter()
            .map(|&(span, primary, msg)| {
                let xi = file_ids.iter().position(|f| *f == span.file).unwrap_or(0);
                let f = map.get(span.file);
                let r = f.floor_char_boundary(span.start as usize)
                    ..f.floor_char_boundary(span.end as usize);
                let r = excerpts.0[xi].map(f, r);
                let l = if primary {
                    cs::Label::primary(xi, r)
                } else {
                    cs::Label::secondary(xi, r)
                };
                l.with_message(msg.to_string())
            })
            .collect();
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
        let _ = term::emit_to_string(&mut out, &config, &excerpts, &diag);
    }
    for t in tail {
        out.push_str(&t);
        out.push('\n');
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
        byte_start: f.file_offset(span.start),
        byte_end: f.file_offset(span.end),
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

/// Renders a list in the chosen format; every format ends each diagnostic with a newline. Human and
/// short show at most [`max_per_file`] diagnostics per file (then one line counting the rest); JSON
/// lines at most [`max_per_file_json`] (a JSON stream has no room for the counting line: the summary
/// record counts them all).
pub fn render(map: &SourceMap, diags: &[Diagnostic], format: MessageFormat) -> String {
    match format {
        MessageFormat::Human => render_human(map, diags),
        MessageFormat::Short => {
            let (keep, tail) = limited(map, diags, max_per_file());
            let mut out: String = keep.iter().map(|d| render_short(map, d) + "\n").collect();
            for t in tail {
                out.push_str(&t);
                out.push('\n');
            }
            out
        }
        MessageFormat::Json => limited(map, diags, max_per_file_json())
            .0
            .into_iter()
            .map(|d| render_json_line(map, d) + "\n")
            .collect(),
    }
}

/// What a `run` did, for the summary: cycles, simulated and wall time, their ratio.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct RunSummary {
    /// The scan cycles run.
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
    /// Error diagnostics reported.
    pub errors: usize,
    /// Warning diagnostics reported.
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
