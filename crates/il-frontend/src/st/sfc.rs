//! Textual Sequential Function Chart (IEC 61131-3 ed. 2 §2.6, ed. 3 §6.7) in the body of an ST POU.
//!
//! Input: the file text and the byte range of a POU body written as `INITIAL_STEP`/`STEP`/`TRANSITION`/
//! `ACTION` elements (the form OpenPLC Editor and Beremiz write into their `.st` files). Output: a
//! [`TextChart`] (steps with their action associations, transitions between steps, action bodies), every
//! name and text with its byte range in the file, and located diagnostics for charts that cannot run.
//! Invariants: the reader does not lower anything: conditions and action bodies stay text ranges (ST or
//! IL), to be lowered by the same SFC lowering as a PLCopen XML `<SFC>` body; step indexes in
//! transitions point into [`TextChart::steps`]; a transition naming an unknown step is left out.

use super::lexer::{lex, Tok, Token};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic};
use std::ops::Range;

/// A chart read from text.
#[derive(Debug, Clone, Default)]
pub struct TextChart {
    /// The steps in text order.
    pub steps: Vec<TextStep>,
    /// The transitions in text order (their priority among transitions leaving the same step).
    pub transitions: Vec<TextTransition>,
    /// The `ACTION name: ... END_ACTION` elements in text order.
    pub actions: Vec<TextAction>,
}

/// `STEP name: associations END_STEP` (or `INITIAL_STEP`).
#[derive(Debug, Clone)]
pub struct TextStep {
    /// The step's name as written.
    pub name: String,
    /// Byte range of the name.
    pub name_range: Range<usize>,
    /// `INITIAL_STEP`: active at the first scan.
    pub initial: bool,
    /// The action associations, in text order.
    pub associations: Vec<TextAssociation>,
}

/// `action(qualifier, time, indicator ...)` inside a step.
#[derive(Debug, Clone)]
pub struct TextAssociation {
    /// The action's (or BOOL variable's) name.
    pub action: String,
    /// Byte range of the whole association (name to `)`).
    pub range: Range<usize>,
    /// The qualifier as written, upper-cased (`N` when none is written).
    pub qualifier: String,
    /// Byte range of the qualifier (the action name when none is written).
    pub qualifier_range: Range<usize>,
    /// Byte range of the duration (`T#5s` or a TIME variable) of a timed qualifier.
    pub time: Option<Range<usize>>,
    /// Byte ranges of the indicator variables after the qualifier (and duration):
    /// `act(N, ind)` (IEC 61131-3 ed. 2 B.1.6 `action_association`).
    pub indicators: Vec<Range<usize>>,
}

/// How a transition's condition is written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum TextCondition {
    /// `:= expression;`: the expression's byte range (without `:=` and `;`).
    Expression(Range<usize>),
    /// `: instructions`: IL instructions leaving the condition in the current result (their range).
    Instructions(Range<usize>),
}

/// `TRANSITION [name] [(PRIORITY := n)] FROM steps TO steps condition END_TRANSITION`.
#[derive(Debug, Clone)]
pub struct TextTransition {
    /// The optional name.
    pub name: Option<String>,
    /// Byte range of the `TRANSITION` keyword.
    pub range: Range<usize>,
    /// `(PRIORITY := n)` when written.
    pub priority: Option<u32>,
    /// Predecessor steps (indexes into [`TextChart::steps`]).
    pub from: Vec<usize>,
    /// Successor steps.
    pub to: Vec<usize>,
    /// The condition.
    pub cond: TextCondition,
}

/// `ACTION name: body END_ACTION`.
#[derive(Debug, Clone)]
pub struct TextAction {
    /// The action's name as written.
    pub name: String,
    /// Byte range of the name.
    pub name_range: Range<usize>,
    /// Byte range of the body (ST statements or IL instructions).
    pub body: Range<usize>,
}

/// Whether `q` (upper-case) is an action qualifier that takes a duration.
pub fn timed_qualifier(q: &str) -> bool {
    matches!(q, "L" | "D" | "SD" | "DS" | "SL")
}

/// Whether `q` (upper-case) is an IEC action qualifier, or one of [`VENDOR_QUALIFIERS`].
pub fn is_qualifier(q: &str) -> bool {
    matches!(q, "N" | "R" | "S" | "P" | "P0" | "P1")
        || timed_qualifier(q)
        || VENDOR_QUALIFIERS.contains(&q)
}

/// How ladderc writes CODESYS's step actions (TwinCAT 3 and CODESYS V3 charts: a step's entry action,
/// step action and exit action) as textual SFC associations: `__ENTRY` runs once when the step
/// becomes active, `__ACTIVE` in every scan it is active (without the final scan of `N`), `__EXIT`
/// once when it is left; no IEC name (two underscores), so no IEC chart writes them by chance.
pub const VENDOR_QUALIFIERS: [&str; 3] = ["__ENTRY", "__ACTIVE", "__EXIT"];

fn word_is(src: &str, t: &Token, w: &str) -> bool {
    matches!(t.tok, Tok::Ident | Tok::Kw(_))
        && src
            .get(t.range.clone())
            .unwrap_or("")
            .eq_ignore_ascii_case(w)
}

/// A name and its byte range.
type Named = (String, Range<usize>);

struct Reader<'s> {
    file: FileId,
    text: &'s str,
    base: usize,
    toks: Vec<Token>,
    i: usize,
    diags: Vec<Diagnostic>,
}

impl Reader<'_> {
    fn peek(&self) -> &Token {
        &self.toks[self.i.min(self.toks.len() - 1)]
    }
    fn is(&self, w: &str) -> bool {
        word_is(self.text, self.peek(), w)
    }
    fn at_eof(&self) -> bool {
        self.peek().tok == Tok::Eof
    }
    fn bump(&mut self) -> Token {
        let t = self.peek().clone();
        if !self.at_eof() {
            self.i += 1;
        }
        t
    }
    fn range(&self, t: &Token) -> Range<usize> {
        t.range.start + self.base..t.range.end + self.base
    }
    fn span(&self, r: &Range<usize>) -> Span {
        Span::new(self.file, r.start, r.end)
    }
    fn text_of(&self, t: &Token) -> String {
        self.text.get(t.range.clone()).unwrap_or("").to_string()
    }
    fn error(&mut self, at: Range<usize>, msg: String, label: &str) {
        self.error_code(code::E0302, at, msg, label);
    }
    fn error_code(&mut self, c: diagnostics::Code, at: Range<usize>, msg: String, label: &str) {
        let d = Diagnostic::error(c, msg)
            .at(self.span(&at))
            .with_primary_label(label.to_string());
        self.diags.push(d);
    }
    /// A name; reports and returns `None` when the next token is not one.
    fn name(&mut self, what: &str) -> Option<(String, Range<usize>)> {
        if self.peek().tok == Tok::Ident {
            let t = self.bump();
            return Some((self.text_of(&t), self.range(&t)));
        }
        let t = self.peek().clone();
        let r = self.range(&t);
        self.error(r, format!("textual SFC: expected {what}"), "expected here");
        None
    }
    /// Skips to just after the word `end` (or to the end of the text); the range of the skipped text.
    fn skip_to(&mut self, end: &str) -> Range<usize> {
        let start = self.peek().range.start + self.base;
        while !self.at_eof() && !self.is(end) {
            self.bump();
        }
        let stop = self.peek().range.start + self.base;
        if self.at_eof() {
            let r = self.range(&self.peek().clone());
            self.error(
                r,
                format!("textual SFC: `{end}` is missing"),
                "the text ends here",
            );
        } else {
            self.bump();
        }
        start..stop
    }
    /// `name` or `(name, name ...)`.
    fn step_list(&mut self) -> Vec<(String, Range<usize>)> {
        let mut out = Vec::new();
        if self.peek().tok == Tok::LParen {
            self.bump();
            loop {
                if let Some(n) = self.name("a step name") {
                    out.push(n);
                }
                match self.peek().tok {
                    Tok::Comma => {
                        self.bump();
                    }
                    Tok::RParen => {
                        self.bump();
                        break;
                    }
                    _ => {
                        let r = self.range(&self.peek().clone());
                        self.error(
                            r,
                            "textual SFC: expected `,` or `)` in a step list".into(),
                            "here",
                        );
                        break;
                    }
                }
            }
        } else if let Some(n) = self.name("a step name") {
            out.push(n);
        }
        out
    }
    /// Whether the step body from the current token up to `END_STEP` holds statements (a CODESYS
    /// V2.3 step's embedded action: `STEP s: n := n + 1; END_STEP`) rather than action
    /// associations (`act(N); flag(S);`). Statements: anything that is not `name [(args)] [;]`, or
    /// `(args)` holding `:=` / `=>` (a call's parameters). In a V2.3 export (`v23`) an element is an
    /// association only with a qualifier as its first argument (`fb();` is a call there).
    fn step_holds_code(&self, v23: bool) -> bool {
        let last = self.toks.len() - 1;
        let tok = |j: usize| &self.toks[j.min(last)];
        let mut j = self.i;
        loop {
            let t = tok(j);
            if t.tok == Tok::Eof || word_is(self.text, t, "END_STEP") {
                return false;
            }
            if t.tok != Tok::Ident {
                return true;
            }
            j += 1;
            let mut qualified = false;
            if tok(j).tok == Tok::LParen {
                j += 1;
                let first = j;
                let mut first_end: Option<usize> = None;
                let mut depth = 0usize;
                loop {
                    match tok(j).tok {
                        Tok::Eof => return false,
                        Tok::Assign | Tok::Arrow => return true,
                        Tok::LParen => depth += 1,
                        Tok::RParen if depth == 0 => break,
                        Tok::RParen => depth -= 1,
                        Tok::Comma if depth == 0 => {
                            first_end.get_or_insert(j);
                        }
                        _ => {}
                    }
                    j += 1;
                }
                let end = first_end.unwrap_or(j);
                if end > first {
                    let from = tok(first).range.start;
                    let to = tok(end - 1).range.end;
                    let q = self.text.get(from..to).unwrap_or("").trim();
                    qualified = is_qualifier(&q.to_ascii_uppercase());
                }
                j += 1;
            }
            if v23 && !qualified {
                return true;
            }
            match tok(j).tok {
                Tok::Semi => j += 1,
                Tok::Ident | Tok::Eof => {}
                _ if word_is(self.text, tok(j), "END_STEP") => {}
                _ => return true,
            }
        }
    }
    fn association(&mut self) -> Option<TextAssociation> {
        let (action, name_range) = self.name("an action name or `END_STEP`")?;
        let mut a = TextAssociation {
            action,
            range: name_range.clone(),
            qualifier: "N".into(),
            qualifier_range: name_range.clone(),
            time: None,
            indicators: Vec::new(),
        };
        if self.peek().tok == Tok::LParen {
            self.bump();
            // the arguments, split at top-level commas
            let mut args: Vec<Range<usize>> = Vec::new();
            let mut depth = 0usize;
            let mut start: Option<usize> = None;
            let mut end = 0usize;
            loop {
                let t = self.peek().clone();
                match t.tok {
                    Tok::Eof => break,
                    Tok::LParen => depth += 1,
                    Tok::RParen if depth == 0 => {
                        self.bump();
                        a.range.end = t.range.end + self.base;
                        break;
                    }
                    Tok::RParen => depth -= 1,
                    Tok::Comma if depth == 0 => {
                        if let Some(s) = start.take() {
                            args.push(s..end);
                        }
                        self.bump();
                        continue;
                    }
                    _ => {}
                }
                start.get_or_insert(t.range.start + self.base);
                end = t.range.end + self.base;
                self.bump();
            }
            if let Some(s) = start {
                args.push(s..end);
            }
            let src_of = |r: &Range<usize>| {
                self.text
                    .get(r.start - self.base..r.end - self.base)
                    .unwrap_or("")
                    .trim()
                    .to_ascii_uppercase()
            };
            let mut rest = 0;
            if let Some(q) = args.first() {
                let qs = src_of(q);
                rest = 1;
                if is_qualifier(&qs) {
                    a.qualifier = qs.clone();
                    a.qualifier_range = q.clone();
                    if timed_qualifier(&qs) {
                        match args.get(1) {
                            Some(t) => {
                                a.time = Some(t.clone());
                                rest = 2;
                            }
                            None => {
                                let r = q.clone();
                                self.error_code(
                                    code::E3123,
                                    r,
                                    format!("textual SFC: qualifier {qs} needs a duration (`{qs}, T#1s`)"),
                                    "no duration",
                                );
                            }
                        }
                    }
                } else {
                    let r = q.clone();
                    self.error_code(
                        code::E3123,
                        r,
                        format!("textual SFC: `{qs}` is not an action qualifier (N R S P P0 P1 L D SD DS SL)"),
                        "unknown qualifier",
                    );
                }
            }
            a.indicators = args.get(rest..).unwrap_or_default().to_vec();
        }
        if self.peek().tok == Tok::Semi {
            self.bump();
        }
        Some(a)
    }
}

/// The type a step is of for the ST lowering of the chart's conditions and actions: a structure of
/// `X : BOOL` (active) and `T : TIME` (elapsed since it became active), so `Step.X` and `Step.T`
/// type-check (IEC 61131-3 ed. 3 8.3.2, ed. 2 2.6.2; CODESYS's and TwinCAT's `SFCStepType`,
/// Beckhoff Infosys "Implicit variables": `<stepname>.x`, `<stepname>.t`); also `_X : BOOL` and
/// `_T : TIME`, CODESYS's and TwinCAT's `<stepname>._x` ("the activation status for the next
/// cycle", copied to `.x` at the start of a cycle; written to force a step) and `<stepname>._t`
/// (CODESYS SFC "Implicit Variables"; Beckhoff Infosys "Implicit variables"), which ladderc reads
/// as the same flag and time: its chart decides the steps of the next cycle before the actions run
/// (README "SFC"). The SFC lowering then renames all four to the chart's hidden variables.
pub const STEP_TYPE: &str = "__SFC_STEP";

/// The fields of [`STEP_TYPE`] (name, type): IEC's `X` and `T`, CODESYS's and TwinCAT's `_X` and
/// `_T`.
pub const STEP_FIELDS: [(&str, &str); 4] =
    [("X", "BOOL"), ("T", "TIME"), ("_X", "BOOL"), ("_T", "TIME")];

/// The declaration of [`STEP_TYPE`], at `span`.
pub fn step_type(span: Span) -> crate::ast::TypeDecl {
    use crate::ast::{Ident, TypeDecl, TypeDef, TypeRef, VarDecl};
    let field = |n: &str, t: &str| {
        VarDecl::new(
            Ident::new(n, span),
            TypeRef::Named(Ident::new(t, span)),
            span,
        )
    };
    TypeDecl {
        name: Ident::new(STEP_TYPE, span),
        def: TypeDef::Struct {
            fields: STEP_FIELDS.iter().map(|(n, t)| field(n, t)).collect(),
        },
        union: false,
        span,
    }
}

/// The names of the steps of the chart `body` (a POU's body text in textual SFC), in text order:
/// the steps whose flags the POU's own actions may read. A chart that cannot be read gives the
/// steps read (its diagnostics are reported where the chart is lowered).
pub fn step_names(file: FileId, body: &str) -> Vec<String> {
    read(file, body, 0..body.len())
        .0
        .steps
        .into_iter()
        .map(|s| s.name)
        .collect()
}

/// Reads the textual SFC in `src[body]`. Diagnostics (E0302 for text that is not textual SFC, E3123 for a
/// bad qualifier or missing duration, E3120 for
/// a transition naming an unknown step, E3124 without an initial step, E3128 for a second initial step,
/// E3131 for a step name used twice) are located in `file`.
pub fn read(file: FileId, src: &str, body: Range<usize>) -> (TextChart, Vec<Diagnostic>) {
    let text = src.get(body.clone()).unwrap_or("");
    let (toks, _) = lex(text);
    let mut r = Reader {
        file,
        text,
        base: body.start,
        toks,
        i: 0,
        diags: Vec::new(),
    };
    let mut chart = TextChart::default();
    // a CODESYS V2.3 export (its `(* @SFCMAXTIME := '' *)` after every step, its
    // `(* @END_DECLARATION := '0' *)`): a step's body is its embedded action's statements
    let v23 = text.contains("@SFCMAXTIME") || src.contains("@END_DECLARATION");
    // (transition, names) resolved once every step is known
    let mut pending: Vec<(Vec<Named>, Vec<Named>)> = Vec::new();
    while !r.at_eof() {
        if r.is("INITIAL_STEP") || r.is("STEP") {
            let initial = r.is("INITIAL_STEP");
            r.bump();
            let Some((name, name_range)) = r.name("a step name") else {
                r.skip_to("END_STEP");
                continue;
            };
            if r.peek().tok == Tok::Colon {
                r.bump();
            }
            let mut associations = Vec::new();
            if r.step_holds_code(v23) {
                // the step's embedded action (CODESYS V2.3): an action named as the step, run
                // while the step is active, as CODESYS runs a step action (`__ACTIVE`)
                let code = r.skip_to("END_STEP");
                chart.actions.push(TextAction {
                    name: name.clone(),
                    name_range: name_range.clone(),
                    body: code,
                });
                associations.push(TextAssociation {
                    action: name.clone(),
                    range: name_range.clone(),
                    qualifier: "__ACTIVE".into(),
                    qualifier_range: name_range.clone(),
                    time: None,
                    indicators: Vec::new(),
                });
                chart.steps.push(TextStep {
                    name,
                    name_range,
                    initial,
                    associations,
                });
                continue;
            }
            while !r.at_eof() && !r.is("END_STEP") {
                match r.association() {
                    Some(a) => associations.push(a),
                    None => {
                        r.skip_to("END_STEP");
                        break;
                    }
                }
            }
            if r.is("END_STEP") {
                r.bump();
            }
            chart.steps.push(TextStep {
                name,
                name_range,
                initial,
                associations,
            });
        } else if r.is("TRANSITION") {
            let kw = r.bump();
            let range = r.range(&kw);
            let mut name = None;
            if r.peek().tok == Tok::Ident && !r.is("FROM") {
                let t = r.bump();
                name = Some(r.text_of(&t));
            }
            let mut priority = None;
            if r.peek().tok == Tok::LParen {
                r.bump();
                if r.is("PRIORITY") {
                    r.bump();
                    if r.peek().tok == Tok::Assign {
                        r.bump();
                    }
                    if let Tok::Int(n) = r.peek().tok {
                        priority = u32::try_from(n).ok();
                        r.bump();
                    }
                }
                while !r.at_eof() && r.peek().tok != Tok::RParen {
                    r.bump();
                }
                r.bump();
            }
            if !r.is("FROM") {
                let t = r.peek().clone();
                let at = r.range(&t);
                r.error(
                    at,
                    "textual SFC: expected `FROM` in a transition".into(),
                    "expected `FROM`",
                );
                r.skip_to("END_TRANSITION");
                continue;
            }
            r.bump();
            let from = r.step_list();
            if !r.is("TO") {
                let t = r.peek().clone();
                let at = r.range(&t);
                r.error(
                    at,
                    "textual SFC: expected `TO` in a transition".into(),
                    "expected `TO`",
                );
                r.skip_to("END_TRANSITION");
                continue;
            }
            r.bump();
            let to = r.step_list();
            let cond = match r.peek().tok {
                Tok::Assign => {
                    r.bump();
                    let mut whole = r.skip_to("END_TRANSITION");
                    let t = &text[whole.start - body.start..whole.end - body.start];
                    let trimmed = t.trim_end();
                    whole.end = whole.start + trimmed.len();
                    if trimmed.ends_with(';') {
                        whole.end -= 1;
                    }
                    TextCondition::Expression(whole)
                }
                Tok::Colon => {
                    r.bump();
                    TextCondition::Instructions(r.skip_to("END_TRANSITION"))
                }
                _ => {
                    let t = r.peek().clone();
                    let at = r.range(&t);
                    r.error(
                        at,
                        "textual SFC: expected the transition's condition (`:= expression;` or `: instructions`)".into(),
                        "expected `:=` or `:`",
                    );
                    r.skip_to("END_TRANSITION");
                    continue;
                }
            };
            chart.transitions.push(TextTransition {
                name,
                range,
                priority,
                from: Vec::new(),
                to: Vec::new(),
                cond,
            });
            pending.push((from, to));
        } else if r.is("ACTION") {
            r.bump();
            let Some((name, name_range)) = r.name("an action name") else {
                r.skip_to("END_ACTION");
                continue;
            };
            if r.peek().tok == Tok::Colon {
                r.bump();
            }
            let body = r.skip_to("END_ACTION");
            chart.actions.push(TextAction {
                name,
                name_range,
                body,
            });
        } else {
            let t = r.bump();
            let at = r.range(&t);
            r.error(
                at,
                "textual SFC: expected `STEP`, `INITIAL_STEP`, `TRANSITION` or `ACTION`".into(),
                "not part of a chart",
            );
            // resynchronise at the next element
            while !r.at_eof()
                && !["INITIAL_STEP", "STEP", "TRANSITION", "ACTION"]
                    .iter()
                    .any(|w| r.is(w))
            {
                r.bump();
            }
        }
    }
    let mut diags = std::mem::take(&mut r.diags);
    let span = |rg: &Range<usize>| Span::new(file, rg.start, rg.end);
    // step names: unique
    for (k, s) in chart.steps.iter().enumerate() {
        if chart.steps[..k]
            .iter()
            .any(|o| o.name.eq_ignore_ascii_case(&s.name))
        {
            diags.push(
                Diagnostic::error(code::E3131, format!("step name `{}` is used twice", s.name))
                    .at(span(&s.name_range))
                    .with_primary_label("second step with this name"),
            );
        }
    }
    let initials: Vec<&TextStep> = chart.steps.iter().filter(|s| s.initial).collect();
    if initials.is_empty() {
        let at = chart
            .steps
            .first()
            .map_or(body.start..body.start, |s| s.name_range.clone());
        diags.push(
            Diagnostic::error(
                code::E3124,
                "the chart has no INITIAL_STEP: no step would ever become active",
            )
            .at(span(&at))
            .with_primary_label("first step of the chart")
            .with_hint("write the first step of the sequence as `INITIAL_STEP name: ... END_STEP`"),
        );
    }
    let find = |n: &str| {
        chart
            .steps
            .iter()
            .position(|s| s.name.eq_ignore_ascii_case(n))
    };
    let mut resolved = Vec::new();
    for (from, to) in &pending {
        let mut ok = true;
        let mut idx = |list: &[(String, Range<usize>)], side: &str| -> Vec<usize> {
            let mut out = Vec::new();
            for (n, rg) in list {
                match find(n) {
                    Some(k) => out.push(k),
                    None => {
                        ok = false;
                        diags.push(
                            Diagnostic::error(
                                code::E3120,
                                format!("transition {side} step `{n}`, which the chart does not declare"),
                            )
                            .at(span(rg))
                            .with_primary_label("unknown step"),
                        );
                    }
                }
            }
            out
        };
        let f = idx(from, "from");
        let t = idx(to, "to");
        resolved.push((f, t, ok));
    }
    let mut keep = Vec::new();
    for (mut tr, (f, t, ok)) in chart.transitions.into_iter().zip(resolved) {
        if ok {
            tr.from = f;
            tr.to = t;
            keep.push(tr);
        }
    }
    chart.transitions = keep;
    // A body may hold several SFC networks (IEC 61131-3: `sequential_function_chart ::= sfc_network
    // {sfc_network}`, as the Annex F gravel example does), each with exactly one initial step: a
    // second initial step is an error only in a network that already has one, i.e. among steps
    // that transitions link.
    let mut root: Vec<usize> = (0..chart.steps.len()).collect();
    fn net_of(root: &mut [usize], mut i: usize) -> usize {
        while root[i] != i {
            root[i] = root[root[i]];
            i = root[i];
        }
        i
    }
    for tr in &chart.transitions {
        let mut linked = tr.from.iter().chain(tr.to.iter());
        if let Some(&first) = linked.next() {
            for &k in linked {
                let (a, b) = (net_of(&mut root, first), net_of(&mut root, k));
                root[a] = b;
            }
        }
    }
    let mut first_initial: std::collections::HashMap<usize, usize> = Default::default();
    for (k, s) in chart.steps.iter().enumerate() {
        if !s.initial {
            continue;
        }
        let net = net_of(&mut root, k);
        match first_initial.get(&net) {
            None => {
                first_initial.insert(net, k);
            }
            Some(&first) => diags.push(
                Diagnostic::error(
                    code::E3128,
                    format!(
                        "a second INITIAL_STEP `{}` in the network of `{}` (steps linked by transitions): each SFC network has exactly one",
                        s.name, chart.steps[first].name
                    ),
                )
                .at(span(&s.name_range))
                .with_primary_label("second initial step"),
            ),
        }
    }
    (chart, diags)
}

#[cfg(test)]
mod tests {
    use super::*;

    const CHART: &str = "
  INITIAL_STEP Start:
  END_STEP
  TRANSITION FROM Start TO (A, B)
    := go;
  END_TRANSITION
  STEP A:
    Lamp(N);
    Motor(L, T#5s);
  END_STEP
  STEP B:
    Pulse(P1);
  END_STEP
  TRANSITION t2 (PRIORITY := 2) FROM (A, B) TO Start : LD A.T
    GE T#2s
  END_TRANSITION
  ACTION Pulse:
    n := n + 1;
  END_ACTION
";

    fn read_all(src: &str) -> (TextChart, Vec<Diagnostic>) {
        read(FileId(0), src, 0..src.len())
    }

    #[test]
    fn reads_steps_transitions_actions() {
        let (c, d) = read_all(CHART);
        assert!(d.is_empty(), "{d:?}");
        let names: Vec<&str> = c.steps.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, ["Start", "A", "B"]);
        assert!(c.steps[0].initial && !c.steps[1].initial);
        let a = &c.steps[1].associations;
        assert_eq!(
            (a[0].action.as_str(), a[0].qualifier.as_str()),
            ("Lamp", "N")
        );
        assert_eq!(a[1].qualifier, "L");
        assert_eq!(&CHART[a[1].time.clone().unwrap()], "T#5s");
        assert_eq!(c.steps[2].associations[0].qualifier, "P1");
        assert_eq!(
            (c.transitions[0].from.clone(), c.transitions[0].to.clone()),
            (vec![0], vec![1, 2])
        );
        let TextCondition::Expression(e) = &c.transitions[0].cond else {
            panic!()
        };
        assert_eq!(&CHART[e.clone()], "go");
        assert_eq!(c.transitions[1].priority, Some(2));
        assert_eq!(c.transitions[1].name.as_deref(), Some("t2"));
        let TextCondition::Instructions(i) = &c.transitions[1].cond else {
            panic!()
        };
        assert_eq!(CHART[i.clone()].trim(), "LD A.T\n    GE T#2s");
        assert_eq!(c.actions[0].name, "Pulse");
        assert_eq!(CHART[c.actions[0].body.clone()].trim(), "n := n + 1;");
    }

    #[test]
    fn broken_charts_are_located() {
        let src = "STEP a: END_STEP STEP b: END_STEP TRANSITION FROM a TO c := x; END_TRANSITION";
        let (c, d) = read_all(src);
        let codes: Vec<(String, usize)> = d
            .iter()
            .map(|d| (d.code.to_string(), d.span.map_or(0, |s| s.start as usize)))
            .collect();
        assert_eq!(
            codes,
            [
                ("E3124".to_string(), 5),
                ("E3120".to_string(), src.find(" c ").unwrap() + 1)
            ]
        );
        assert!(c.transitions.is_empty());
        // two networks, one initial step each: valid
        let src = "INITIAL_STEP a: END_STEP INITIAL_STEP b: END_STEP";
        let (_, d) = read_all(src);
        assert!(d.is_empty(), "{d:?}");
        // one network (a transition links the steps) with two initial steps
        let src = "INITIAL_STEP a: END_STEP INITIAL_STEP b: END_STEP STEP c: END_STEP \
                   TRANSITION FROM c TO (a, b) := x; END_TRANSITION";
        let (_, d) = read_all(src);
        assert_eq!(d.len(), 1);
        assert_eq!(d[0].code.to_string(), "E3128");
        assert_eq!(
            d[0].span.map(|s| s.start as usize),
            src.find(" b:").map(|i| i + 1)
        );
    }
}
