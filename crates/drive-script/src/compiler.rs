//! Compiler: script text to a [`Program`] (Motion pool + Event pool) with debug line information.
//!
//! Input: one file of a [`SourceMap`]. Output: [`Compiled`] or every diagnostic found (E6xxx codes, each with
//! a span, so with line and column). Steps: lex, cut the token stream into `S:: ... ;` statements, classify
//! each statement (PARAM, INIT, MOTION n, EVENT n, IF, THEN, `name = value`), parse it, then check the
//! cross-references (NextMotionID, Jump and Loop targets). Invariant: a returned program satisfies every
//! invariant listed in [`crate::program`]; errors never panic and recovery resumes at the next statement.

use crate::lexer::{lex, Tok, Token};
use crate::limits::*;
use crate::program::*;
use diagnostics::{code, Diagnostic, Diagnostics, FileId, SourceMap, Span};

/// Source positions of one Event, indexed like the Event pool.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct EventLines {
    /// The `S:: EVENT e;` statement.
    pub event: Span,
    /// The `S:: IF ...;` statement (where a before-IF stop is shown).
    pub if_stmt: Span,
    /// The `S:: THEN ...;` statement (where a before-THEN stop is shown).
    pub then_stmt: Span,
}

/// Debug information kept on the PC side (not in the image).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct DebugInfo {
    /// The source file the spans point into.
    pub file: FileId,
    /// Source positions of every Event, indexed like the Event pool.
    pub events: Vec<EventLines>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
/// A compiled script: the program for the image and the PC-side line information of the debugger.
pub struct Compiled {
    /// The Motion and Event pools with the Param and Init values.
    pub program: Program,
    /// Where each Event came from in the source.
    pub debug: DebugInfo,
}

/// Compiles one registered file.
pub fn compile(map: &SourceMap, file: FileId) -> Result<Compiled, Diagnostics> {
    let text = &map.get(file).text;
    let mut c = Compiler {
        file,
        diags: Diagnostics::new(),
        program: Program::default(),
        debug: DebugInfo {
            file,
            events: Vec::new(),
        },
        block: Block::None,
        open_event: None,
        motion_span: None,
        motion_targets: Vec::new(),
        event_targets: Vec::new(),
        text_len: text.len(),
        skipping: Skip::No,
    };
    let toks = lex(text);
    for stmt in split_statements(&toks, file, &mut c.diags) {
        c.statement(&stmt);
    }
    c.finish();
    if c.diags.has_errors() {
        Err(c.diags)
    } else {
        Ok(Compiled {
            program: c.program,
            debug: c.debug,
        })
    }
}

/// Convenience: registers `text` as `name` in a new source map and compiles it.
pub fn compile_str(name: &str, text: &str) -> (SourceMap, Result<Compiled, Diagnostics>) {
    let mut map = SourceMap::new();
    let f = map.add(name, text.strip_prefix('\u{feff}').unwrap_or(text));
    let r = compile(&map, f);
    (map, r)
}

/// One `S:: body ;` statement: `whole` covers `S::` to `;` (or to the last token if `;` is missing).
struct Stmt<'t> {
    whole: Span,
    body: &'t [Token],
}

fn split_statements<'t>(toks: &'t [Token], file: FileId, diags: &mut Diagnostics) -> Vec<Stmt<'t>> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < toks.len() {
        let t = &toks[i];
        if t.tok != Tok::Start {
            let what = describe(&t.tok);
            diags.push(
                Diagnostic::error(code::E6001, format!("expected `S::`, found {what}"))
                    .at(Span::new(file, t.start, t.end))
                    .with_primary_label("every statement starts with `S::`")
                    .with_hint("write the statement as `S:: ... ;`"),
            );
            // Skip to the next statement start.
            while i < toks.len() && toks[i].tok != Tok::Start {
                i += 1;
            }
            continue;
        }
        let begin = i;
        i += 1;
        let body_start = i;
        while i < toks.len() && toks[i].tok != Tok::Semi && toks[i].tok != Tok::Start {
            i += 1;
        }
        let body = &toks[body_start..i];
        let last = body.last().unwrap_or(&toks[begin]);
        if i < toks.len() && toks[i].tok == Tok::Semi {
            out.push(Stmt {
                whole: Span::new(file, toks[begin].start, toks[i].end),
                body,
            });
            i += 1;
        } else {
            diags.push(
                Diagnostic::error(code::E6002, "statement is not terminated by `;`")
                    .at(Span::new(file, last.end, last.end))
                    .with_primary_label("expected `;` here")
                    .with_label(
                        Span::new(file, toks[begin].start, toks[begin].end),
                        "statement starts here",
                    )
                    .with_hint("end every statement with `;`"),
            );
            out.push(Stmt {
                whole: Span::new(file, toks[begin].start, last.end),
                body,
            });
        }
    }
    out
}

fn describe(t: &Tok) -> String {
    match t {
        Tok::Start => "`S::`".into(),
        Tok::Semi => "`;`".into(),
        Tok::Ident(s) => format!("`{s}`"),
        Tok::Int(..) => "a number".into(),
        Tok::Bad(c) => format!("unexpected character `{c}`"),
        other => format!("`{}`", tok_text(other)),
    }
}

fn tok_text(t: &Tok) -> &'static str {
    match t {
        Tok::Eq => "=",
        Tok::Ne => "<>",
        Tok::Lt => "<",
        Tok::Le => "<=",
        Tok::Gt => ">",
        Tok::Ge => ">=",
        Tok::Plus => "+",
        Tok::Minus => "-",
        Tok::Star => "*",
        Tok::Slash => "/",
        Tok::Percent => "%",
        Tok::Amp => "&",
        Tok::Pipe => "|",
        Tok::Caret => "^",
        Tok::Tilde => "~",
        Tok::LParen => "(",
        Tok::RParen => ")",
        Tok::Comma => ",",
        Tok::Semi => ";",
        Tok::Start => "S::",
        Tok::Ident(_) | Tok::Int(..) | Tok::Bad(_) => "?",
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Block {
    None,
    Param,
    Init,
    Motion,
}

struct OpenEvent {
    span: Span,
    has_if: bool,
    has_then: bool,
}

struct Compiler {
    file: FileId,
    diags: Diagnostics,
    program: Program,
    debug: DebugInfo,
    block: Block,
    open_event: Option<OpenEvent>,
    motion_span: Option<Span>,
    /// (target Motion, span) of every NextMotionID.
    motion_targets: Vec<(usize, Span)>,
    /// (Motion, target Event, span) of every Jump and Loop.
    event_targets: Vec<(usize, usize, Span)>,
    text_len: usize,
    /// After a rejected MOTION (or EVENT) header, its statements are skipped up to the next header, so one
    /// mistake gives one diagnostic rather than a cascade.
    skipping: Skip,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Skip {
    No,
    Motion,
    Event,
}

type PResult<T> = Result<T, Box<Diagnostic>>;

/// A named thing the language knows, after case-insensitive lookup.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Name {
    Read(Source, i32),
    Const(i32),
    Write(ActionKind, u8),
    /// Readable register written by an action too (`MD`, `DO`, `MathError`).
    ReadWrite(Source, i32, ActionKind, u8),
    Stop,
    Loop,
    NextMotionId,
    Jump,
    Setting(&'static str),
    ReadOnlyIndexed(Source, i32),
    OutOfRange(&'static str, u64, usize),
    Keyword,
    Unknown,
}

fn indexed(name: &str, prefix: &str) -> Option<Option<u64>> {
    let rest = name.get(..prefix.len())?;
    if !rest.eq_ignore_ascii_case(prefix) {
        return None;
    }
    let digits = &name[prefix.len()..];
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    Some(digits.parse::<u64>().ok())
}

fn lookup(name: &str) -> Name {
    let lower = name.to_ascii_lowercase();
    let simple = match lower.as_str() {
        "high" | "true" => Some(Name::Const(1)),
        "low" | "false" => Some(Name::Const(0)),
        "actualposition" => Some(Name::Read(Source::ActualPosition, 0)),
        "actualvelocity" => Some(Name::Read(Source::ActualVelocity, 0)),
        "actualcurrent" => Some(Name::Read(Source::ActualCurrent, 0)),
        "motionstate" => Some(Name::Read(Source::MotionState, 0)),
        "motiondone" => Some(Name::Read(Source::MotionDone, 0)),
        "homed" => Some(Name::Read(Source::Homed, 0)),
        "matherror" => Some(Name::ReadWrite(
            Source::MathError,
            0,
            ActionKind::WriteMathError,
            0,
        )),
        "velocity" => Some(Name::Write(ActionKind::SetVelocity, 0)),
        "acceleration" => Some(Name::Write(ActionKind::SetAcceleration, 0)),
        "deceleration" => Some(Name::Write(ActionKind::SetDeceleration, 0)),
        "jogvelocity" => Some(Name::Write(ActionKind::SetJogVelocity, 0)),
        "setposition" => Some(Name::Write(ActionKind::SetPosition, 0)),
        "velocitymove" => Some(Name::Write(ActionKind::VelocityMove, 0)),
        "relativetargetposition" | "relativemove" => Some(Name::Write(ActionKind::RelativeMove, 0)),
        "absolutetargetposition" | "absolutemove" => Some(Name::Write(ActionKind::AbsoluteMove, 0)),
        "jog" => Some(Name::Write(ActionKind::Jog, 0)),
        "homing" => Some(Name::Write(ActionKind::Homing, 0)),
        "stop" => Some(Name::Stop),
        "loop" => Some(Name::Loop),
        "nextmotionid" => Some(Name::NextMotionId),
        "jump" => Some(Name::Jump),
        "eventspercycle" => Some(Name::Setting("EventsPerCycle")),
        "if" | "then" | "and" | "or" | "not" | "motion" | "event" | "param" | "init" => {
            Some(Name::Keyword)
        }
        _ => None,
    };
    if let Some(n) = simple {
        return n;
    }
    // Longest prefixes first: `MD` before a hypothetical `M`, `TimerDone_` before `T`.
    let table: [(&str, &'static str, usize); 6] = [
        ("TimerDone_", "timer", TIMERS),
        ("TimerSet_", "timer", TIMERS),
        ("DI_", "digital input", DIGITAL_INPUTS),
        ("DO_", "digital output", DIGITAL_OUTPUTS),
        ("MD", "memory word", MEMORY_WORDS),
        ("P", "parameter", PARAMS),
    ];
    for (prefix, what, limit) in table {
        if let Some(n) = indexed(name, prefix) {
            let Some(n) = n.filter(|n| (*n as usize) < limit && *n < 256) else {
                return Name::OutOfRange(what, n.unwrap_or(u64::MAX), limit);
            };
            let i = n as i32;
            return match prefix {
                "TimerDone_" => Name::Read(Source::TimerDone, i),
                "TimerSet_" => Name::Write(ActionKind::TimerSet, n as u8),
                "DI_" => Name::ReadOnlyIndexed(Source::DigitalIn, i),
                "DO_" => Name::ReadWrite(Source::DigitalOut, i, ActionKind::WriteOutput, n as u8),
                "MD" => Name::ReadWrite(Source::Mem, i, ActionKind::WriteMem, n as u8),
                _ => Name::ReadOnlyIndexed(Source::Param, i),
            };
        }
    }
    Name::Unknown
}

/// Cursor over one statement's tokens.
struct Cursor<'t> {
    toks: &'t [Token],
    pos: usize,
    file: FileId,
    /// Span of the statement (for "missing X at end" errors).
    whole: Span,
    /// Parsing an IF (OR/NOT are E6009 there) rather than a THEN.
    in_if: bool,
}

impl<'t> Cursor<'t> {
    fn peek(&self) -> Option<&'t Token> {
        self.toks.get(self.pos)
    }
    fn next(&mut self) -> Option<&'t Token> {
        let t = self.toks.get(self.pos);
        self.pos += 1;
        t
    }
    fn at_end(&self) -> bool {
        self.pos >= self.toks.len()
    }
    fn span(&self, t: &Token) -> Span {
        Span::new(self.file, t.start, t.end)
    }
    /// Where the next token is, or the statement's `;` when at the end.
    fn here(&self) -> Span {
        match self.peek() {
            Some(t) => self.span(t),
            None => Span::new(
                self.file,
                self.whole.end as usize - 1,
                self.whole.end as usize,
            ),
        }
    }
    fn peek_keyword(&self, kw: &str) -> bool {
        matches!(self.peek(), Some(Token { tok: Tok::Ident(s), .. }) if s.eq_ignore_ascii_case(kw))
    }
    fn syntax(&self, msg: impl Into<String>, label: impl Into<String>) -> Box<Diagnostic> {
        Box::new(
            Diagnostic::error(code::E6010, msg)
                .at(self.here())
                .with_primary_label(label),
        )
    }
    fn found(&self) -> String {
        match self.peek() {
            Some(t) => describe(&t.tok),
            None => "`;`".into(),
        }
    }
    fn expect(&mut self, tok: Tok, what: &str) -> PResult<&'t Token> {
        if self.peek().map(|t| &t.tok) == Some(&tok) {
            Ok(self.next().expect("peeked"))
        } else {
            Err(self.syntax(
                format!("expected {what}, found {}", self.found()),
                format!("expected {what}"),
            ))
        }
    }
    fn expect_end(&mut self) -> PResult<()> {
        if self.at_end() {
            Ok(())
        } else {
            Err(self.syntax(
                format!("expected `;`, found {}", self.found()),
                "unexpected text before `;`",
            ))
        }
    }
    /// A non-negative integer literal (block and target numbers).
    fn number(&mut self, what: &str) -> PResult<(u64, Span)> {
        match self.peek() {
            Some(
                t @ Token {
                    tok: Tok::Int(v, _),
                    ..
                },
            ) => {
                let span = self.span(t);
                self.pos += 1;
                match v {
                    Some(v) => Ok((*v, span)),
                    None => Err(Box::new(
                        Diagnostic::error(code::E6014, format!("{what} is not a valid number"))
                            .at(span)
                            .with_primary_label("not a number in range"),
                    )),
                }
            }
            _ => Err(self.syntax(
                format!("expected {what}, found {}", self.found()),
                format!("expected {what}"),
            )),
        }
    }
    /// A signed 32-bit literal: decimal in i32 range, or hex up to 0xFFFFFFFF (taken as the bit pattern).
    fn literal(&mut self) -> PResult<i32> {
        let neg = if self.peek().map(|t| &t.tok) == Some(&Tok::Minus) {
            self.pos += 1;
            true
        } else {
            false
        };
        let t = match self.peek() {
            Some(
                t @ Token {
                    tok: Tok::Int(..), ..
                },
            ) => t,
            _ => {
                return Err(self.syntax(
                    format!("expected an integer literal, found {}", self.found()),
                    "expected an integer",
                ))
            }
        };
        self.pos += 1;
        literal_value(t, neg, self.file)
    }
}

fn literal_value(t: &Token, neg: bool, file: FileId) -> PResult<i32> {
    let span = Span::new(file, t.start, t.end);
    let Tok::Int(v, hex) = t.tok else {
        unreachable!("literal_value called on a non-integer token")
    };
    let value = v.and_then(|v| {
        if neg {
            (v <= 1 << 31).then(|| (v as i64).wrapping_neg() as i32)
        } else if v <= i32::MAX as u64 {
            Some(v as i32)
        } else if hex && v <= u32::MAX as u64 {
            Some(v as u32 as i32)
        } else {
            None
        }
    });
    value.ok_or_else(|| {
        Box::new(
            Diagnostic::error(code::E6014, "integer literal does not fit in 32 bits")
                .at(span)
                .with_primary_label("out of range")
                .with_hint(
                    "values are 32-bit signed: -2147483648 ..= 2147483647 (hex up to 0xFFFFFFFF)",
                ),
        )
    })
}

impl Compiler {
    fn err(&mut self, d: Diagnostic) {
        self.diags.push(d);
    }

    fn statement(&mut self, stmt: &Stmt<'_>) {
        let mut cur = Cursor {
            toks: stmt.body,
            pos: 0,
            file: self.file,
            whole: stmt.whole,
            in_if: false,
        };
        let header = match cur.peek() {
            Some(Token {
                tok: Tok::Ident(w), ..
            }) => {
                if w.eq_ignore_ascii_case("motion") {
                    Some(Skip::Motion)
                } else if w.eq_ignore_ascii_case("event") {
                    Some(Skip::Event)
                } else {
                    None
                }
            }
            _ => None,
        };
        match (self.skipping, header) {
            (Skip::Motion, Some(Skip::Motion)) | (Skip::Event, Some(_)) => self.skipping = Skip::No,
            (Skip::No, _) => {}
            _ => return,
        }
        if let Err(d) = self.statement_inner(&mut cur, stmt.whole) {
            if let Some(h) = header {
                self.skipping = h;
                // The Event before a rejected header is still checked for completeness.
                self.close_event();
            }
            self.err(*d);
        }
    }

    fn statement_inner(&mut self, cur: &mut Cursor<'_>, whole: Span) -> PResult<()> {
        let Some(first) = cur.peek() else {
            return Err(Box::new(
                Diagnostic::error(code::E6010, "empty statement")
                    .at(whole)
                    .with_primary_label("nothing between `S::` and `;`"),
            ));
        };
        let first_span = cur.span(first);
        let word = match &first.tok {
            Tok::Ident(s) => s.to_ascii_lowercase(),
            _ => {
                return Err(cur.syntax(
                    format!("expected an instruction, found {}", cur.found()),
                    "expected PARAM, INIT, MOTION, EVENT, IF, THEN or `name = value`",
                ))
            }
        };
        match word.as_str() {
            "param" | "init" => {
                cur.next();
                cur.expect_end()?;
                let b = if word == "param" {
                    Block::Param
                } else {
                    Block::Init
                };
                if self.block >= b {
                    return Err(Box::new(
                        Diagnostic::error(
                            code::E6011,
                            format!("`{}` block is out of place", word.to_ascii_uppercase()),
                        )
                        .at(first_span)
                        .with_primary_label("blocks come in the order PARAM, INIT, MOTION")
                        .with_hint("write each of PARAM and INIT once, before the first MOTION"),
                    ));
                }
                self.block = b;
                Ok(())
            }
            "motion" => {
                cur.next();
                let (n, nspan) = cur.number("a Motion number")?;
                cur.expect_end()?;
                self.close_event();
                self.close_motion();
                let expected = self.program.motions.len();
                if n as usize != expected || n > u16::MAX as u64 {
                    return Err(Box::new(
                        Diagnostic::error(
                            code::E6012,
                            format!("Motion {n} is out of sequence: expected Motion {expected}"),
                        )
                        .at(nspan)
                        .with_primary_label(format!("expected {expected}"))
                        .with_hint("number Motions 0, 1, 2, ... in the order they are written"),
                    ));
                }
                if expected >= MAX_MOTIONS {
                    return Err(Box::new(
                        Diagnostic::error(
                            code::E6008,
                            format!("too many Motions: the Motion pool holds {MAX_MOTIONS}"),
                        )
                        .at(whole)
                        .with_primary_label(format!("Motion {n} does not fit")),
                    ));
                }
                self.block = Block::Motion;
                self.program.motions.push(Motion {
                    first_event: self.program.events.len() as u16,
                    event_count: 0,
                });
                self.motion_span = Some(whole);
                Ok(())
            }
            "event" => {
                cur.next();
                let (n, nspan) = cur.number("an Event number")?;
                cur.expect_end()?;
                self.close_event();
                let Some(motion) = self.program.motions.last_mut() else {
                    return Err(Box::new(
                        Diagnostic::error(code::E6011, "Event outside a Motion block")
                            .at(first_span)
                            .with_primary_label("no `S:: MOTION n;` before this Event")
                            .with_hint("start a Motion block with `S:: MOTION 0;`"),
                    ));
                };
                let expected = motion.event_count as usize;
                if n as usize != expected {
                    return Err(Box::new(
                        Diagnostic::error(
                            code::E6012,
                            format!("Event {n} is out of sequence: expected Event {expected}"),
                        )
                        .at(nspan)
                        .with_primary_label(format!("expected {expected}"))
                        .with_hint("number the Events of each Motion 0, 1, 2, ... in order"),
                    ));
                }
                if self.program.events.len() >= MAX_EVENTS {
                    return Err(Box::new(
                        Diagnostic::error(
                            code::E6008,
                            format!("too many Events: the Event pool holds {MAX_EVENTS}"),
                        )
                        .at(whole)
                        .with_primary_label(format!("Event {n} does not fit")),
                    ));
                }
                motion.event_count += 1;
                self.program.events.push(Event::default());
                self.debug.events.push(EventLines {
                    event: whole,
                    ..Default::default()
                });
                self.open_event = Some(OpenEvent {
                    span: whole,
                    has_if: false,
                    has_then: false,
                });
                Ok(())
            }
            "if" | "then" => {
                let is_if = word == "if";
                cur.next();
                let Some(open) = self.open_event.as_mut() else {
                    return Err(Box::new(
                        Diagnostic::error(
                            code::E6011,
                            format!("{} outside an Event", word.to_ascii_uppercase()),
                        )
                        .at(first_span)
                        .with_primary_label("no `S:: EVENT n;` before this statement")
                        .with_hint("start an Event with `S:: EVENT n;` inside a Motion block"),
                    ));
                };
                if is_if && (open.has_if || open.has_then) {
                    let msg = if open.has_then {
                        "IF after THEN: an Event is one IF followed by one THEN"
                    } else {
                        "second IF in one Event: an Event has exactly one IF"
                    };
                    return Err(Box::new(
                        Diagnostic::error(code::E6005, msg)
                            .at(first_span)
                            .with_label(open.span, "in this Event")
                            .with_hint("start a new Event with `S:: EVENT n;` or join the conditions with AND"),
                    ));
                }
                if !is_if && (open.has_then || !open.has_if) {
                    let msg = if open.has_then {
                        "second THEN in one Event: an Event has exactly one THEN"
                    } else {
                        "THEN without IF: an Event is one IF followed by one THEN"
                    };
                    // Mark it so the end-of-Event check does not report the same Event again.
                    open.has_if = true;
                    open.has_then = true;
                    return Err(Box::new(
                        Diagnostic::error(code::E6005, msg)
                            .at(first_span)
                            .with_label(open.span, "in this Event")
                            .with_hint("write `S:: IF condition;` before `S:: THEN action;` (use `S:: IF TRUE;` for always)"),
                    ));
                }
                if is_if {
                    open.has_if = true;
                } else {
                    open.has_then = true;
                }
                let idx = self.program.events.len() - 1;
                let motion = self.program.motions.len() - 1;
                cur.in_if = is_if;
                if is_if {
                    self.debug.events[idx].if_stmt = whole;
                    let conds = self.conditions(cur)?;
                    let ev = &mut self.program.events[idx];
                    for (i, c) in conds.iter().enumerate() {
                        ev.conditions[i] = *c;
                    }
                    ev.cond_count = conds.len() as u8;
                } else {
                    self.debug.events[idx].then_stmt = whole;
                    let acts = self.actions(cur, motion)?;
                    let ev = &mut self.program.events[idx];
                    for (i, a) in acts.iter().enumerate() {
                        ev.actions[i] = *a;
                    }
                    ev.act_count = acts.len() as u8;
                }
                Ok(())
            }
            _ => self.assignment_statement(cur, first_span),
        }
    }

    /// `name = literal` in the PARAM or INIT block.
    fn assignment_statement(&mut self, cur: &mut Cursor<'_>, first_span: Span) -> PResult<()> {
        let Some(Token {
            tok: Tok::Ident(name),
            ..
        }) = cur.next()
        else {
            unreachable!("caller checked the identifier")
        };
        let looked = lookup(name);
        match looked {
            Name::Unknown => return Err(unknown_name(name, first_span)),
            Name::OutOfRange(what, n, limit) => {
                return Err(out_of_range(what, n, limit, first_span))
            }
            _ => {}
        }
        if self.block == Block::Motion || self.block == Block::None {
            let msg = if self.block == Block::Motion {
                format!("`{name} = ...` outside a THEN statement")
            } else {
                format!("`{name} = ...` before a PARAM or INIT block")
            };
            return Err(Box::new(
                Diagnostic::error(code::E6011, msg)
                    .at(first_span)
                    .with_primary_label("misplaced statement")
                    .with_hint(if self.block == Block::Motion {
                        "inside a Motion, write actions in `S:: THEN ...;`"
                    } else {
                        "start with `S:: PARAM;` (P0..P15) or `S:: INIT;` (MD0..MD49 and settings)"
                    }),
            ));
        }
        cur.expect(Tok::Eq, "`=`")?;
        let value = cur.literal()?;
        cur.expect_end()?;
        match (self.block, looked) {
            (Block::Param, Name::ReadOnlyIndexed(Source::Param, i)) => {
                self.program.params[i as usize] = value;
            }
            (Block::Init, Name::ReadWrite(Source::Mem, i, _, _)) => {
                self.program.init[i as usize] = value;
            }
            (Block::Init, Name::Write(kind, _))
                if matches!(
                    kind,
                    ActionKind::SetVelocity
                        | ActionKind::SetAcceleration
                        | ActionKind::SetDeceleration
                        | ActionKind::SetJogVelocity
                ) =>
            {
                let s = &mut self.program.settings;
                match kind {
                    ActionKind::SetVelocity => s.velocity = value,
                    ActionKind::SetAcceleration => s.acceleration = value,
                    ActionKind::SetDeceleration => s.deceleration = value,
                    _ => s.jog_velocity = value,
                }
            }
            (Block::Init, Name::Setting(_)) => {
                if value < 1 || value > MAX_EVENTS_PER_CYCLE as i32 {
                    return Err(Box::new(
                        Diagnostic::error(
                            code::E6014,
                            format!("EventsPerCycle must be 1..={MAX_EVENTS_PER_CYCLE}, found {value}"),
                        )
                        .at(first_span)
                        .with_primary_label("out of range"),
                    ));
                }
                self.program.settings.events_per_cycle = value as u16;
            }
            (Block::Param, _) => {
                return Err(Box::new(
                    Diagnostic::error(code::E6011, format!("`{name}` cannot be set in the PARAM block"))
                        .at(first_span)
                        .with_primary_label("the PARAM block sets P0..P15 only"),
                ))
            }
            _ => {
                return Err(Box::new(
                    Diagnostic::error(code::E6011, format!("`{name}` cannot be set in the INIT block"))
                        .at(first_span)
                        .with_primary_label(
                            "INIT sets MD0..MD49, Velocity, Acceleration, Deceleration, JogVelocity, EventsPerCycle",
                        ),
                ))
            }
        }
        Ok(())
    }

    fn conditions(&mut self, cur: &mut Cursor<'_>) -> PResult<Vec<Condition>> {
        let mut out = Vec::new();
        loop {
            if cur.peek_keyword("not") {
                return Err(and_only(cur.here(), "NOT"));
            }
            let start = cur.here();
            let c = condition(cur)?;
            if out.len() == MAX_CONDITIONS {
                return Err(Box::new(
                    Diagnostic::error(
                        code::E6008,
                        format!("too many conditions: an IF holds at most {MAX_CONDITIONS}"),
                    )
                    .at(start)
                    .with_primary_label("this condition does not fit")
                    .with_hint("compute part of the test into an MD word in an earlier Event"),
                ));
            }
            out.push(c);
            if cur.at_end() {
                return Ok(out);
            }
            if cur.peek_keyword("and") {
                cur.next();
                continue;
            }
            if cur.peek_keyword("or") {
                return Err(and_only(cur.here(), "OR"));
            }
            return Err(cur.syntax(
                format!("expected AND or `;`, found {}", cur.found()),
                "expected AND or `;`",
            ));
        }
    }

    fn actions(&mut self, cur: &mut Cursor<'_>, motion: usize) -> PResult<Vec<Action>> {
        let mut out = Vec::new();
        loop {
            let start = cur.here();
            let a = self.action(cur, motion)?;
            if out.len() == MAX_ACTIONS {
                return Err(Box::new(
                    Diagnostic::error(
                        code::E6008,
                        format!("too many actions: a THEN holds at most {MAX_ACTIONS}"),
                    )
                    .at(start)
                    .with_primary_label("this action does not fit")
                    .with_hint(
                        "move the remaining actions to a following Event with `S:: IF TRUE;`",
                    ),
                ));
            }
            out.push(a);
            if cur.at_end() {
                return Ok(out);
            }
            if cur.peek_keyword("and") {
                cur.next();
                continue;
            }
            for word in ["or", "xor", "not"] {
                if cur.peek_keyword(word) {
                    return Err(keyword_operator(cur.here(), word));
                }
            }
            return Err(cur.syntax(
                format!("expected AND or `;`, found {}", cur.found()),
                "actions are joined with AND",
            ));
        }
    }

    fn action(&mut self, cur: &mut Cursor<'_>, motion: usize) -> PResult<Action> {
        let t = match cur.peek() {
            Some(
                t @ Token {
                    tok: Tok::Ident(_), ..
                },
            ) => t,
            _ => {
                return Err(cur.syntax(
                    format!("expected an action, found {}", cur.found()),
                    "expected an action such as `DO_0=HIGH`",
                ))
            }
        };
        let Tok::Ident(name) = &t.tok else {
            unreachable!()
        };
        let span = cur.span(t);
        cur.next();
        let name_kind = lookup(name);
        let (kind, index) = match name_kind {
            Name::Stop => {
                return Ok(Action {
                    kind: ActionKind::Stop,
                    ..Default::default()
                })
            }
            Name::Loop => {
                cur.expect(Tok::LParen, "`(` after Loop")?;
                let reg = match cur.next() {
                    Some(
                        r @ Token {
                            tok: Tok::Ident(n), ..
                        },
                    ) => match lookup(n) {
                        Name::ReadWrite(Source::Mem, i, _, _) => i as u8,
                        Name::OutOfRange(what, n, limit) => {
                            return Err(out_of_range(what, n, limit, cur.span(r)))
                        }
                        _ => {
                            return Err(Box::new(
                                Diagnostic::error(
                                    code::E6013,
                                    format!("Loop counts down an MD word, not `{n}`"),
                                )
                                .at(cur.span(r))
                                .with_primary_label("expected MD0..MD49"),
                            ))
                        }
                    },
                    _ => {
                        cur.pos -= 1;
                        return Err(cur.syntax("expected an MD word in Loop(...)", "expected MDn"));
                    }
                };
                cur.expect(Tok::RParen, "`)`")?;
                cur.expect(Tok::Eq, "`=`")?;
                let (target, tspan) = cur.number("a target Event number")?;
                self.event_targets.push((motion, target as usize, tspan));
                return Ok(Action {
                    kind: ActionKind::Loop,
                    index: reg,
                    value: Value::konst(target.min(i32::MAX as u64) as i32),
                });
            }
            Name::NextMotionId | Name::Jump => {
                cur.expect(Tok::Eq, "`=`")?;
                let (target, tspan) = cur.number(if name_kind == Name::Jump {
                    "a target Event number"
                } else {
                    "a target Motion number"
                })?;
                let kind = if name_kind == Name::Jump {
                    self.event_targets.push((motion, target as usize, tspan));
                    ActionKind::Jump
                } else {
                    self.motion_targets.push((target as usize, tspan));
                    ActionKind::NextMotion
                };
                return Ok(Action {
                    kind,
                    index: target.min(255) as u8,
                    value: Value::default(),
                });
            }
            Name::Write(kind, i) | Name::ReadWrite(_, _, kind, i) => (kind, i),
            Name::OutOfRange(what, n, limit) => return Err(out_of_range(what, n, limit, span)),
            Name::Unknown | Name::Keyword => return Err(unknown_name(name, span)),
            Name::Read(..) | Name::ReadOnlyIndexed(..) | Name::Const(_) | Name::Setting(_) => {
                let why = match name_kind {
                    Name::ReadOnlyIndexed(Source::Param, _) => {
                        "parameters are read-only in a script (the PC or the debugger writes them)"
                    }
                    Name::ReadOnlyIndexed(..) => "digital inputs are read-only",
                    Name::Setting(_) => "EventsPerCycle is set in the INIT block only",
                    Name::Const(_) => "a constant cannot be assigned",
                    _ => "drive readings are read-only",
                };
                return Err(Box::new(
                    Diagnostic::error(
                        code::E6013,
                        format!("`{name}` cannot be written by an action"),
                    )
                    .at(span)
                    .with_primary_label("not writable")
                    .with_hint(why),
                ));
            }
        };
        cur.expect(Tok::Eq, "`=`")?;
        let value = value(cur)?;
        Ok(Action { kind, index, value })
    }

    fn close_event(&mut self) {
        if let Some(open) = self.open_event.take() {
            let missing = match (open.has_if, open.has_then) {
                (true, true) => return,
                (false, false) => "has neither IF nor THEN",
                (false, true) => "has no IF",
                (true, false) => "has no THEN",
            };
            let m = self.program.motions.len().saturating_sub(1);
            let e = self
                .program
                .motions
                .last()
                .map(|m| (m.event_count as usize).saturating_sub(1))
                .unwrap_or(0);
            self.err(
                Diagnostic::error(code::E6005, format!("Event {e} of Motion {m} {missing}"))
                    .at(open.span)
                    .with_primary_label("incomplete Event")
                    .with_hint("an Event is `S:: IF condition;` followed by `S:: THEN action;`"),
            );
        }
    }

    fn close_motion(&mut self) {
        if let (Some(m), Some(span)) = (self.program.motions.last(), self.motion_span) {
            if m.event_count == 0 {
                let n = self.program.motions.len() - 1;
                self.err(
                    Diagnostic::error(code::E6015, format!("Motion {n} has no Event"))
                        .at(span)
                        .with_primary_label("empty Motion")
                        .with_hint("add `S:: EVENT 0;` with an IF and a THEN"),
                );
            }
        }
    }

    fn finish(&mut self) {
        self.close_event();
        self.close_motion();
        if self.program.motions.is_empty() {
            let end = self.text_len;
            self.err(
                Diagnostic::error(code::E6015, "the script has no Motion block")
                    .at(Span::new(self.file, end, end))
                    .with_primary_label("end of script")
                    .with_hint("the interpreter starts at `S:: MOTION 0;` Event 0"),
            );
        }
        let motions = self.program.motions.clone();
        for (target, span) in std::mem::take(&mut self.motion_targets) {
            if target >= motions.len() {
                self.err(
                    Diagnostic::error(
                        code::E6006,
                        format!("NextMotionID {target}: there is no Motion {target}"),
                    )
                    .at(span)
                    .with_primary_label("no such Motion")
                    .with_note(format!(
                        "the script defines Motions 0..={}",
                        motions.len().saturating_sub(1)
                    )),
                );
            }
        }
        for (motion, target, span) in std::mem::take(&mut self.event_targets) {
            let count = motions
                .get(motion)
                .map(|m| m.event_count as usize)
                .unwrap_or(0);
            if target >= count {
                self.err(
                    Diagnostic::error(
                        code::E6007,
                        format!("jump to Event {target}: Motion {motion} has no Event {target}"),
                    )
                    .at(span)
                    .with_primary_label("no such Event in this Motion")
                    .with_note(format!(
                        "Motion {motion} has Events 0..={}",
                        count.saturating_sub(1)
                    )),
                );
            }
        }
    }
}

fn and_only(span: Span, word: &str) -> Box<Diagnostic> {
    Box::new(
        Diagnostic::error(
            code::E6009,
            format!("`{word}` in a condition: conditions combine with AND only"),
        )
        .at(span)
        .with_primary_label(format!("`{word}` is not allowed in IF"))
        .with_hint(if word == "OR" {
            "write one Event per alternative (same THEN), or use `|` to OR bits into one value"
        } else {
            "invert the comparison instead (`DI_0 = LOW` rather than `NOT DI_0`), or use `~` on a value"
        }),
    )
}

/// `OR`/`XOR`/`NOT` used as an operator in a THEN value.
fn keyword_operator(span: Span, word: &str) -> Box<Diagnostic> {
    let upper = word.to_ascii_uppercase();
    let symbol = match upper.as_str() {
        "OR" => "|",
        "XOR" => "^",
        _ => "~",
    };
    Box::new(
        Diagnostic::error(
            code::E6010,
            format!("`{upper}` is not an operator in a value: write `{symbol}`"),
        )
        .at(span)
        .with_primary_label(format!("use `{symbol}`"))
        .with_hint(
            "in values the bitwise operators are `&`, `|`, `^`, `~`; the keyword AND joins actions",
        ),
    )
}

fn unknown_name(name: &str, span: Span) -> Box<Diagnostic> {
    Box::new(
        Diagnostic::error(code::E6003, format!("unknown instruction or name `{name}`"))
            .at(span)
            .with_primary_label("not part of the drive script language")
            .with_hint(
                "see the instruction list in the drive-script README (names are case-insensitive)",
            ),
    )
}

fn out_of_range(what: &str, n: u64, limit: usize, span: Span) -> Box<Diagnostic> {
    let shown = if n == u64::MAX {
        "too large".to_string()
    } else {
        n.to_string()
    };
    Box::new(
        Diagnostic::error(
            code::E6004,
            format!(
                "{what} index {shown} is out of range: valid indices are 0..={}",
                limit - 1
            ),
        )
        .at(span)
        .with_primary_label("index out of range"),
    )
}

fn compare_of(t: &Tok) -> Option<Compare> {
    Some(match t {
        Tok::Eq => Compare::Eq,
        Tok::Ne => Compare::Ne,
        Tok::Lt => Compare::Lt,
        Tok::Le => Compare::Le,
        Tok::Gt => Compare::Gt,
        Tok::Ge => Compare::Ge,
        _ => return None,
    })
}

fn arith_of(t: &Tok) -> Option<ArithOp> {
    Some(match t {
        Tok::Plus => ArithOp::Add,
        Tok::Minus => ArithOp::Sub,
        Tok::Star => ArithOp::Mul,
        Tok::Slash => ArithOp::Div,
        Tok::Percent => ArithOp::Rem,
        Tok::Amp => ArithOp::And,
        Tok::Pipe => ArithOp::Or,
        Tok::Caret => ArithOp::Xor,
        _ => return None,
    })
}

/// `value [cmp value]`; a lone value means `value <> 0`.
fn condition(cur: &mut Cursor<'_>) -> PResult<Condition> {
    let lhs = value(cur)?;
    match cur.peek().and_then(|t| compare_of(&t.tok)) {
        Some(cmp) => {
            cur.next();
            let rhs = value(cur)?;
            Ok(Condition { lhs, cmp, rhs })
        }
        None => Ok(Condition {
            lhs,
            cmp: Compare::Ne,
            rhs: Value::konst(0),
        }),
    }
}

/// `operand [op operand]`, `-operand` (0 - x) or `~operand` (x ^ -1): at most one operator.
fn value(cur: &mut Cursor<'_>) -> PResult<Value> {
    let unary = match cur.peek().map(|t| &t.tok) {
        Some(Tok::Tilde) => Some(ArithOp::Xor),
        Some(Tok::Minus)
            if !matches!(
                cur.toks.get(cur.pos + 1).map(|t| &t.tok),
                Some(Tok::Int(..))
            ) =>
        {
            Some(ArithOp::Sub)
        }
        _ => None,
    };
    let v = if let Some(op) = unary {
        cur.next();
        let x = operand(cur)?;
        if op == ArithOp::Xor {
            Value {
                a: x,
                op,
                b: Operand::konst(-1),
            }
        } else {
            Value {
                a: Operand::konst(0),
                op,
                b: x,
            }
        }
    } else {
        let a = operand(cur)?;
        match cur.peek().and_then(|t| arith_of(&t.tok)) {
            Some(op) => {
                cur.next();
                let b = operand(cur)?;
                Value { a, op, b }
            }
            None => Value::of(a),
        }
    };
    if let Some(t) = cur.peek() {
        if arith_of(&t.tok).is_some() {
            return Err(Box::new(
                Diagnostic::error(code::E6010, "more than one operator in a value")
                    .at(cur.span(t))
                    .with_primary_label("second operator")
                    .with_hint("a value is `a`, `a op b`, `-a` or `~a`: store intermediate results in an MD word with an earlier action"),
            ));
        }
        if matches!(t.tok, Tok::LParen) {
            return Err(cur.syntax("parentheses are not allowed in a value", "unexpected `(`"));
        }
    }
    Ok(v)
}

fn operand(cur: &mut Cursor<'_>) -> PResult<Operand> {
    let Some(t) = cur.peek() else {
        return Err(cur.syntax("expected a value, found `;`", "expected a value"));
    };
    let span = cur.span(t);
    match &t.tok {
        Tok::Int(..) | Tok::Minus => Ok(Operand::konst(cur.literal()?)),
        Tok::Ident(name) => {
            cur.next();
            match lookup(name) {
                Name::Const(v) => Ok(Operand::konst(v)),
                Name::Read(source, i)
                | Name::ReadOnlyIndexed(source, i)
                | Name::ReadWrite(source, i, _, _) => Ok(Operand { source, arg: i }),
                Name::OutOfRange(what, n, limit) => Err(out_of_range(what, n, limit, span)),
                Name::Write(..) | Name::NextMotionId | Name::Jump | Name::Setting(_) => {
                    Err(Box::new(
                        Diagnostic::error(code::E6013, format!("`{name}` can be written but not read"))
                            .at(span)
                            .with_primary_label("not readable")
                            .with_hint("readable drive values: ActualPosition, ActualVelocity, ActualCurrent, MotionState, MotionDone, Homed, TimerDone_n"),
                    ))
                }
                Name::Keyword
                    if name.eq_ignore_ascii_case("or") || name.eq_ignore_ascii_case("not") =>
                {
                    if cur.in_if {
                        Err(and_only(span, &name.to_ascii_uppercase()))
                    } else {
                        Err(keyword_operator(span, name))
                    }
                }
                Name::Stop | Name::Loop | Name::Keyword | Name::Unknown => Err(unknown_name(name, span)),
            }
        }
        _ => Err(cur.syntax(
            format!("expected a value, found {}", cur.found()),
            "expected a value",
        )),
    }
}
