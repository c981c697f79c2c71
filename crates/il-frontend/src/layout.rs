//! The layout pass between lexer and grammar: decides which line ends matter and repairs unclosed blocks.
//!
//! Input: the raw tokens of [`crate::lexer`]. Output: the [`Tok`] stream the grammar reads, with byte
//! positions (local to the text; diagnostics add `base`), plus the lexical diagnostics.
//! Invariants:
//! - IL is line-oriented: in instruction lists a line end is one [`Tok::Eol`] (blank and comment-only lines
//!   collapse); inside declarations (`VAR`..`END_VAR`, `TYPE`, `CONFIGURATION`) line ends are blanks.
//! - Inside the argument list of a call (`CAL f(` / `LIMIT(`), a line end next to `(`, `,` or `)` is a blank,
//!   so arguments may span lines; a deferred operator's `(` (`AND(` at the start of an instruction) keeps
//!   line ends, its nested list is line-oriented. An operator word whose `(` is followed (over line ends
//!   and comments) by `name :=` or `name =>` is the formal call of the standard function of that name
//!   (`MOD(` + `IN1 := a, IN2 := b`): it is passed on as an identifier and its list as call arguments.
//! - A `;` in an instruction list is the non-standard end-of-line comment: reported, skipped to line end.
//! - A block left open (missing `END_VAR`, `END_PROGRAM`, `)` of a deferred operator) is reported once and
//!   closed with a zero-width synthetic token, so the grammar sees a well-nested stream and one mistake
//!   does not cascade into the rest of the file.
//! - Lexer errors are reported here and passed on as [`Tok::Error`], which the grammar recovers from
//!   without reporting again.
//! - The commonest lines (`LD x`, `ADD 5`, `JMPC l`, `l:` alone on their line) pass as one token each
//!   ([`Tok::SimpleLine`] ...); where several follow one another at the start of an instruction line,
//!   they are scanned without the lexer and pass as one [`Tok::Lines`] run (at most 256 lines). Either
//!   way the grammar builds the same statements and diagnostics as of the tokens one by one.

use crate::ast::Condition;
use crate::lexer::{LexError, LineTok, RawToken, TimeValue, Tok, Word};
use diagnostics::{code, Diagnostic, FileId, Span};
use logos::Logos;
use std::collections::VecDeque;

/// A token with its local byte range.
pub type Spanned = (usize, Tok, usize);

/// An open block, innermost last.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Frame {
    /// A POU opened by `PROGRAM`/`FUNCTION`/`FUNCTION_BLOCK` at this position.
    Pou(Word, usize, usize),
    /// A `VAR*` block opened at this position.
    Var(usize, usize),
    Type(usize, usize),
    Struct(usize, usize),
    Config(usize, usize),
    Resource(usize, usize),
    /// `AND(` ... `)`: line ends matter inside.
    Deferred(usize, usize),
    /// A call's argument list: line ends next to separators are blanks.
    Args,
}

impl Frame {
    fn is_decl(self) -> bool {
        matches!(
            self,
            Frame::Var(..)
                | Frame::Type(..)
                | Frame::Struct(..)
                | Frame::Config(..)
                | Frame::Resource(..)
        )
    }
}

/// What the last emitted token was, as far as layout decisions care.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Last {
    Start,
    Eol,
    Colon,
    LParen,
    Comma,
    Deferrable,
    /// `.`: a keyword after it names a field (`r.Type`).
    Dot,
    Other,
}

/// The layout pass as an iterator of `(start, token, end)` for the grammar (see the module header).
pub struct Layout<'s> {
    src: &'s str,
    lex: logos::Lexer<'s, RawToken>,
    file: FileId,
    base: usize,
    /// The lexical problems found so far (unterminated comments and strings, bad literals, `$` escapes).
    pub diags: Vec<Diagnostic>,
    out: VecDeque<Spanned>,
    stack: Vec<Frame>,
    pending_eol: Option<usize>,
    prev: Last,
    prev2: Last,
    start: Option<Tok>,
    finished: bool,
    /// The last token emitted ends a declaration or opens a `VAR` block: a new declaration may start.
    decl_start: bool,
    /// The last token emitted is a `VAR*` keyword or one of its qualifiers (`CONSTANT`, `RETAIN`):
    /// `PERSISTENT` there is the CODESYS / TwinCAT qualifier, read as `RETAIN` (W1424).
    var_head: bool,
    /// An unterminated comment swallowed the rest of the file: blocks it leaves open are not reported.
    swallowed: bool,
    /// Upper-case names declared outside the text (a PLCopen XML POU's interface): a keyword among them
    /// is read as that variable's name (its reserved name is E1031 at the declaration, once).
    declared: Vec<String>,
    /// `[` opened in declarations and not closed yet: `+ - * /` there are constant-expression
    /// operators (`ARRAY[0..N-1]`); anywhere else they stay unexpected characters.
    decl_brackets: u32,
    /// After `:=` in declarations, up to the `;`: an initial value, which may be a constant
    /// expression (`c : INT := N * 2;`).
    decl_init: bool,
    /// `(` opened in declarations by a string length and not closed yet (`STRING(N * 2)`, CODESYS):
    /// `+ - * /` there are constant-expression operators too.
    decl_parens: u32,
    /// The end of the last token emitted that is not a line end: where a missing `;` belongs.
    last_end: usize,
    /// `[` opened in instruction lists and not closed yet (subscripts of operands), capped at
    /// [`MAX_SUBSCRIPT_NESTING`].
    code_brackets: usize,
    /// E0200 for subscripts nested too deeply was reported (once per text).
    deep_subscript_reported: bool,
    /// Runs of plain lines pass on as one [`Tok::Lines`] ([`Layout::line_run`]); off, each line
    /// passes on as its own line token and line end (the tests compare the two).
    line_runs: bool,
    /// The members of the innermost `STRUCT` read so far that have a relative location
    /// (`x AT %B0 : WORD;`, [`Layout::relative_location`]): their first bit, their bits (`None`
    /// for a type whose size the layout does not know) and the location's local byte range.
    relative: Vec<(u64, Option<u64>, usize, usize)>,
    /// The last token emitted is an `END_STRUCT` that closed a structure: its end (where the
    /// declaration's `;` belongs when a name follows, [`Layout::missing_struct_semi`]).
    end_struct_at: Option<usize>,
}

/// The most lines one [`Tok::Lines`] carries (its list is 64 bytes a line).
const MAX_RUN: usize = 256;

/// The deepest nesting of subscripts in an instruction list (`a[b[c[i]]]`: 3) accepted in IL; the
/// same as PLCopen XML variables' (`ladder_compiler::values::MAX_INDEX_DEPTH`). Real programs nest a
/// few levels; the semantic checks walk subscripts recursively.
pub const MAX_SUBSCRIPT_NESTING: usize = 64;

impl<'s> Layout<'s> {
    /// `start` is [`Tok::UnitStart`] or [`Tok::BodyStart`]: which grammar entry to use.
    pub fn new(file: FileId, src: &'s str, base: usize, start: Tok) -> Self {
        Layout {
            src,
            lex: RawToken::lexer(src),
            file,
            base,
            diags: Vec::new(),
            out: VecDeque::new(),
            relative: Vec::new(),
            stack: Vec::new(),
            pending_eol: None,
            prev: Last::Start,
            prev2: Last::Start,
            start: Some(start),
            finished: false,
            decl_start: false,
            var_head: false,
            swallowed: false,
            declared: Vec::new(),
            decl_brackets: 0,
            decl_init: false,
            decl_parens: 0,
            last_end: 0,
            code_brackets: 0,
            deep_subscript_reported: false,
            line_runs: true,
            end_struct_at: None,
        }
    }

    /// Each plain line passes on as its own line token and line end, never in a [`Tok::Lines`] run.
    pub fn without_line_runs(mut self) -> Self {
        self.line_runs = false;
        self
    }

    /// Names declared outside the text (upper case): a keyword among them reads as a name.
    pub fn with_declared(mut self, declared: Vec<String>) -> Self {
        self.declared = declared;
        self
    }

    fn span(&self, start: usize, end: usize) -> Span {
        Span::new(self.file, self.base + start, self.base + end)
    }

    fn in_decl(&self) -> bool {
        self.stack.last().is_some_and(|f| f.is_decl())
    }

    fn emit(&mut self, start: usize, tok: Tok, end: usize) {
        let last = match &tok {
            Tok::Eol | Tok::UnitStart | Tok::BodyStart => Last::Eol,
            Tok::Colon => Last::Colon,
            Tok::LParen => Last::LParen,
            Tok::Comma => Last::Comma,
            Tok::Amp | Tok::AmpN => Last::Deferrable,
            Tok::Word(w) if w.is_simple_op() => Last::Deferrable,
            Tok::Dot => Last::Dot,
            _ => Last::Other,
        };
        if !matches!(tok, Tok::Eol | Tok::UnitStart | Tok::BodyStart) {
            self.last_end = end;
        }
        // a VAR block's keyword (`VAR`, `VAR_INPUT`, ..., `CONSTANT`, `RETAIN`, `NON_RETAIN`)
        self.var_head = matches!(
            tok,
            Tok::Word(
                Word::Var
                    | Word::VarInput
                    | Word::VarOutput
                    | Word::VarInOut
                    | Word::VarTemp
                    | Word::VarGlobal
                    | Word::VarExternal
                    | Word::Constant
                    | Word::Retain
                    | Word::NonRetain
            )
        );
        self.decl_start = self.var_head || matches!(tok, Tok::Semi | Tok::Word(Word::Struct));
        if !matches!(tok, Tok::Word(Word::EndStruct)) {
            self.end_struct_at = None;
        }
        self.prev2 = self.prev;
        self.prev = last;
        self.out.push_back((start, tok, end));
    }

    /// Emits a pending line end before `next`, unless it is a blank (see module doc).
    fn resolve_eol(&mut self, next: Option<&Tok>) {
        let Some(pos) = self.pending_eol.take() else {
            return;
        };
        if matches!(self.prev, Last::Start | Last::Eol) {
            return;
        }
        if self.stack.last() == Some(&Frame::Args) {
            if matches!(self.prev, Last::LParen | Last::Comma)
                || matches!(next, Some(Tok::RParen | Tok::Comma))
            {
                return;
            }
            // The argument list was not closed on this line: it is over.
            while self.stack.last() == Some(&Frame::Args) {
                self.stack.pop();
            }
        }
        self.emit(pos, Tok::Eol, pos + 1);
    }

    fn ensure_eol(&mut self, at: usize) {
        if !matches!(self.prev, Last::Start | Last::Eol) {
            self.emit(at, Tok::Eol, at);
        }
    }

    /// Closes the innermost frame with synthetic tokens at `at`, reporting what was missing.
    fn close_top(&mut self, at: usize) {
        let Some(frame) = self.stack.pop() else {
            return;
        };
        let before = self.diags.len();
        self.close_frame(frame, at);
        if self.swallowed {
            self.diags.truncate(before);
        }
    }

    fn close_frame(&mut self, frame: Frame, at: usize) {
        let here = self.span(at, at);
        let missing = |what: &str, open: Span, opened: &str| {
            Diagnostic::error(code::E0008, format!("missing `{what}`"))
                .at(here)
                .with_primary_label(format!("`{what}` expected before this"))
                .with_label(open, format!("{opened} opened here"))
                .with_hint(format!("close the block with `{what}`"))
        };
        match frame {
            Frame::Pou(kind, s, e) => {
                let end = kind.pou_end().unwrap_or(Word::EndProgram);
                self.ensure_eol(at);
                let d = missing(
                    end.spelling(),
                    self.span(s, e),
                    &format!("`{}`", kind.spelling()),
                );
                self.diags.push(d);
                self.emit(at, Tok::Word(end), at);
            }
            Frame::Var(s, e) => {
                let d = missing("END_VAR", self.span(s, e), "the declaration block");
                self.diags.push(d);
                self.emit(at, Tok::Word(Word::EndVar), at);
            }
            Frame::Type(s, e) => {
                let d = missing("END_TYPE", self.span(s, e), "`TYPE`");
                self.diags.push(d);
                self.emit(at, Tok::Word(Word::EndType), at);
            }
            Frame::Struct(s, e) => {
                let d = missing("END_STRUCT", self.span(s, e), "`STRUCT`");
                self.diags.push(d);
                self.emit(at, Tok::Word(Word::EndStruct), at);
                self.emit(at, Tok::Semi, at);
            }
            Frame::Config(s, e) => {
                let d = missing("END_CONFIGURATION", self.span(s, e), "`CONFIGURATION`");
                self.diags.push(d);
                self.emit(at, Tok::Word(Word::EndConfiguration), at);
            }
            Frame::Resource(s, e) => {
                let d = missing("END_RESOURCE", self.span(s, e), "`RESOURCE`");
                self.diags.push(d);
                self.emit(at, Tok::Word(Word::EndResource), at);
            }
            Frame::Deferred(s, e) => {
                self.ensure_eol(at);
                self.diags.push(
                    Diagnostic::error(code::E0009, "missing `)` of a deferred operator")
                        .at(here)
                        .with_primary_label("`)` expected on a line before this")
                        .with_label(self.span(s, e), "parenthesis opened here")
                        .with_hint("close the nested instruction list with `)` on its own line"),
                );
                self.emit(at, Tok::RParen, at);
                self.emit(at, Tok::Eol, at);
            }
            Frame::Args => {}
        }
    }

    /// Closes frames down to (not including) the innermost one that `keep` accepts; returns whether found.
    fn close_until(&mut self, at: usize, keep: impl Fn(&Frame) -> bool) -> bool {
        if !self.stack.iter().any(&keep) {
            return false;
        }
        while let Some(top) = self.stack.last() {
            if keep(top) {
                return true;
            }
            self.close_top(at);
        }
        false
    }

    fn in_configuration(&self) -> bool {
        self.stack
            .iter()
            .any(|f| matches!(f, Frame::Config(..) | Frame::Resource(..)))
    }

    /// Block structure bookkeeping for one token; may emit synthetic tokens before it.
    fn structure(&mut self, s: usize, tok: &Tok, e: usize) {
        if matches!(tok, Tok::Word(Word::Ident)) && self.in_decl() {
            if let Some(at) = self.end_struct_at.take() {
                self.missing_struct_semi(at, s, e);
            }
        }
        let decl = self.in_decl();
        match tok {
            Tok::Word(w) => match w {
                Word::VarAccess | Word::VarConfig => {}
                Word::Var
                | Word::VarInput
                | Word::VarOutput
                | Word::VarInOut
                | Word::VarTemp
                | Word::VarGlobal
                | Word::VarExternal => {
                    if matches!(self.stack.last(), Some(Frame::Var(..))) {
                        self.close_top(s);
                    }
                    self.drop_parens();
                    self.stack.push(Frame::Var(s, e));
                }
                Word::EndVar => {
                    if matches!(self.stack.last(), Some(Frame::Var(..))) && !self.decl_start {
                        self.missing_decl_semi("END_VAR");
                    }
                    self.close_until(s, |f| matches!(f, Frame::Var(..)));
                    if matches!(self.stack.last(), Some(Frame::Var(..))) {
                        self.stack.pop();
                    }
                }
                Word::Type if !self.in_configuration() => {
                    self.close_all(s);
                    self.stack.push(Frame::Type(s, e));
                }
                Word::EndType if self.close_until(s, |f| matches!(f, Frame::Type(..))) => {
                    if let Some(Frame::Type(_, te)) = self.stack.pop() {
                        self.missing_type_semi(te, s, e);
                    }
                }
                Word::Struct if decl => {
                    self.relative.clear();
                    self.stack.push(Frame::Struct(s, e));
                }
                Word::EndStruct => {
                    self.overlapping_locations();
                    if matches!(self.stack.last(), Some(Frame::Struct(..))) && !self.decl_start {
                        self.missing_decl_semi("END_STRUCT");
                    }
                    if matches!(self.stack.last(), Some(Frame::Struct(..))) {
                        self.stack.pop();
                        self.end_struct_at = Some(e);
                    }
                }
                // a variable named `Configuration` (TwinCAT, W1418; elsewhere E1031 in sema) is
                // in a declaration or after an operator, never where a configuration starts
                Word::Configuration if !decl && matches!(self.prev, Last::Start | Last::Eol) => {
                    self.close_all(s);
                    self.stack.push(Frame::Config(s, e));
                }
                Word::EndConfiguration
                    if self.close_until(s, |f| matches!(f, Frame::Config(..))) =>
                {
                    self.stack.pop();
                }
                Word::Resource if self.in_configuration() => {
                    self.close_until(s, |f| matches!(f, Frame::Config(..)));
                    self.stack.push(Frame::Resource(s, e));
                }
                Word::EndResource if self.close_until(s, |f| matches!(f, Frame::Resource(..))) => {
                    self.stack.pop();
                }
                Word::Program | Word::Function | Word::FunctionBlock
                    if !self.in_configuration() =>
                {
                    self.close_all(s);
                    self.stack.push(Frame::Pou(*w, s, e));
                }
                _ => {}
            },
            Tok::LParen if !decl => {
                let deferred = self.prev == Last::Deferrable
                    && matches!(self.prev2, Last::Start | Last::Eol | Last::Colon);
                self.stack.push(if deferred {
                    Frame::Deferred(s, e)
                } else {
                    Frame::Args
                });
            }
            Tok::RParen if !decl => {
                if matches!(self.stack.last(), Some(Frame::Args | Frame::Deferred(..))) {
                    self.stack.pop();
                }
            }
            _ => {}
        }
    }

    /// `END_PROGRAM` & co.: closes what is open inside the POU; a mismatched keyword is reported and
    /// replaced by the right one. Returns the token to emit.
    fn pou_end(&mut self, s: usize, w: Word, e: usize) -> Tok {
        if !self.close_until(s, |f| matches!(f, Frame::Pou(..))) {
            return Tok::Word(w);
        }
        let Some(Frame::Pou(kind, ps, pe)) = self.stack.pop() else {
            return Tok::Word(w);
        };
        let want = kind.pou_end().unwrap_or(w);
        if want != w {
            self.diags.push(
                Diagnostic::error(
                    code::E0010,
                    format!("`{}` closes a {}", w.spelling(), kind.spelling()),
                )
                .at(self.span(s, e))
                .with_primary_label(format!("expected `{}`", want.spelling()))
                .with_label(self.span(ps, pe), "opened here")
                .with_hint(format!("write `{}`", want.spelling())),
            );
        }
        Tok::Word(want)
    }

    /// `END_TYPE` right after a type declaration without its `;` (`END_STRUCT END_TYPE`,
    /// `(Off, On) END_TYPE`, `T : INT END_TYPE`), as CODESYS and TwinCAT write it: IEC 61131-3's
    /// grammar ends every type declaration with `;`, so W0013 says so, and a synthetic `;` lets the
    /// declaration stand. `te` is the end of `TYPE`; an empty block (`TYPE END_TYPE`) gets nothing.
    fn missing_type_semi(&mut self, te: usize, s: usize, e: usize) {
        if self.decl_start || self.src.get(te..s).is_none_or(|t| t.trim().is_empty()) {
            return;
        }
        self.diags.push(
            Diagnostic::warning(
                code::W0013,
                "the last type declaration before `END_TYPE` has no `;`",
            )
            .at(self.span(s, e))
            .with_primary_label("`;` expected before this")
            .with_hint(
                "IEC 61131-3 ends each type declaration with `;` (`END_STRUCT;`); CODESYS accepts it without, and so does ladderc",
            ),
        );
        self.emit(s, Tok::Semi, s);
    }

    /// `END_VAR` or `END_STRUCT` (`keyword`) right after a declaration without its `;` (`b : BOOL
    /// END_VAR`): IEC 61131-3, CODESYS and TwinCAT all require it. One E0011 where the `;` belongs,
    /// with the declaration completed in the hint; a synthetic `;` lets the block close as written
    /// (no further error).
    fn missing_decl_semi(&mut self, keyword: &str) {
        let at = self.last_end;
        let line_start = self.src[..at].rfind('\n').map_or(0, |i| i + 1);
        let decl = self.src[line_start..at].trim();
        let shown = if decl.chars().count() > 60 || decl.is_empty() {
            "the declaration".to_string()
        } else {
            format!("`{decl}`")
        };
        let fix = if shown.starts_with('`') {
            format!(" (`{decl};`)")
        } else {
            String::new()
        };
        self.diags.push(
            Diagnostic::error(
                code::E0011,
                format!("missing `;` after {shown} before `{keyword}`"),
            )
            .at(self.span(at, at))
            .with_primary_label("`;` expected here")
            .with_hint(format!(
                "end each declaration with `;`{fix}: IEC 61131-3, CODESYS and TwinCAT require it, also before `{keyword}`"
            )),
        );
        self.emit(at, Tok::Semi, at);
    }

    /// `END_STRUCT` (ending at `at`) then the name of the next declaration (`s..e`) without the
    /// `;` between (`END_STRUCT` / `Pts : ARRAY [0..3] OF P2;`): IEC 61131-3 ends each type and
    /// variable declaration with `;` (ed. 3, B.1.3), CODESYS and TwinCAT too. One E0011 where the
    /// `;` belongs, and a synthetic `;` so that the name starts the next declaration, as the hint
    /// says (before: read as one more field of the closed structure, a second error at `END_TYPE`).
    fn missing_struct_semi(&mut self, at: usize, s: usize, e: usize) {
        let name = self.src.get(s..e).unwrap_or("").to_string();
        self.diags.push(
            Diagnostic::error(
                code::E0011,
                format!("missing `;` after `END_STRUCT` before `{name}`"),
            )
            .at(self.span(at, at))
            .with_primary_label("`;` expected here")
            .with_hint(
                "end each declaration with `;` (`END_STRUCT;`): IEC 61131-3, CODESYS and TwinCAT require it",
            ),
        );
        self.emit(at, Tok::Semi, at);
    }

    fn close_all(&mut self, at: usize) {
        while !self.stack.is_empty() {
            self.close_top(at);
        }
    }

    fn drop_parens(&mut self) {
        while matches!(self.stack.last(), Some(Frame::Args)) {
            self.stack.pop();
        }
    }

    fn report_lex_error(&mut self, err: LexError, s: usize, e: usize) {
        let text = &self.src[s..e];
        let d = match err {
            LexError::UnexpectedChar => {
                let in_decl = self.stack.last().is_some_and(|f| f.is_decl());
                let hint = match text {
                    // an initial value or a bound written as an expression (`c : INT := b + 1;`,
                    // in IL and ST files alike: their declarations are read here)
                    "=" | "<" | ">" | "+" | "-" | "*" | "/" | "<>" | "<=" | ">=" if in_decl => {
                        "an initial value in a declaration is a literal or an integer constant expression (+ - * / MOD, parentheses, integer constants); write the value, or assign it in the body"
                    }
                    "=" | "<" | ">" | "+" | "-" | "*" | "/" | "<>" | "<=" | ">=" => {
                        "IL has no infix operators: use EQ, NE, LT, LE, GT, GE, ADD, SUB, MUL or DIV"
                    }
                    "{" | "}" => "comments are written (* ... *)",
                    _ => "remove it, or put it in a (* comment *)",
                };
                Diagnostic::error(code::E0001, format!("unexpected character `{text}`"))
                    .at(self.span(s, e))
                    .with_hint(hint)
            }
            LexError::UnterminatedComment => {
                Diagnostic::error(code::E0002, "comment is not closed")
                    .at(self.span(s, s + 2))
                    .with_primary_label("this comment runs to the end of the file")
                    .with_hint(if self.src[s..].starts_with("/*") {
                        "close it with `*/`"
                    } else {
                        "close it with `*)`"
                    })
            }
            LexError::UnterminatedString => {
                Diagnostic::error(code::E0003, "string is not closed on its line")
                    .at(self.span(s, e))
                    .with_hint(format!(
                        "close it with `{}`; write a line break inside a string as $N",
                        &text[..1]
                    ))
            }
            LexError::BadLiteral(why) => {
                Diagnostic::error(code::E0005, format!("invalid literal: {why}"))
                    .at(self.span(s, e))
                    .with_hint("see the literal forms in `ladderc explain E0005`")
            }
            LexError::BadAddress(why) => Diagnostic::error(
                code::E0006,
                format!("invalid direct address: {why}"),
            )
            .at(self.span(s, e))
            .with_hint(
                "write %I, %Q or %M, an optional size X, B, W, D or L, and a location like 0.1",
            ),
        };
        self.diags.push(d);
    }

    /// `VAR_GLOBAL PERSISTENT`, `VAR RETAIN PERSISTENT` (CODESYS V2.3, TwinCAT): the vendors'
    /// qualifier for values kept over a download and a cold start, which IEC 61131-3 does not have.
    /// A `ladderc run` has neither, so it is read as `RETAIN` (which keeps values over a warm
    /// restart), with one note.
    fn persistent_read_as_retain(&mut self, s: usize, e: usize) -> Tok {
        self.diags.push(
            Diagnostic::new(
                code::W1424,
                diagnostics::Severity::Note,
                "`PERSISTENT` (CODESYS, TwinCAT) is read as `RETAIN`",
            )
            .at(self.span(s, e))
            .with_hint(
                "a run has no download or restart: the variables keep their values from scan to scan either way",
            ),
        );
        Tok::Word(Word::Retain)
    }

    /// The text after byte `e` goes on with `:` (not `:=`), blanks skipped.
    fn colon_follows(&self, e: usize) -> bool {
        let rest = self.src[e..].trim_start_matches([' ', '\t']);
        rest.starts_with(':') && !rest.starts_with(":=")
    }

    fn convert(&self, raw: RawToken, s: usize, e: usize) -> Tok {
        match raw {
            RawToken::Word => {
                let text = &self.src[s..e];
                // `TYPE T : UNION ... END_UNION` (CODESYS, TwinCAT) is read as a structure, the
                // grammar's TypeDecl marks it a union; elsewhere UNION stays a name
                let top = self.stack.last();
                if text.eq_ignore_ascii_case("UNION")
                    && matches!(top, Some(Frame::Type(..)))
                    && !matches!(self.prev, Last::LParen | Last::Comma)
                {
                    return Tok::Word(Word::Struct);
                }
                if text.eq_ignore_ascii_case("END_UNION") && matches!(top, Some(Frame::Struct(..)))
                {
                    return Tok::Word(Word::EndStruct);
                }
                // `CLASS Name ... END_CLASS` (IEC 61131-3 ed. 3, 6.6.5) is read as a function
                // block without a body (`st::classes` checks what a class may not hold): CLASS
                // at the start of a line outside any declaration, END_CLASS inside a POU;
                // elsewhere (`Class : INT;`, `r.Class`) either stays a name
                if text.eq_ignore_ascii_case("CLASS")
                    && !top.is_some_and(|f| f.is_decl())
                    && (matches!(self.prev, Last::Start | Last::Eol) || self.pending_eol.is_some())
                    && !self.colon_follows(e)
                {
                    return Tok::Word(Word::FunctionBlock);
                }
                if text.eq_ignore_ascii_case("END_CLASS")
                    && self.stack.iter().any(|f| matches!(f, Frame::Pou(..)))
                {
                    return Tok::Word(Word::EndFunctionBlock);
                }
                match crate::lexer::classify(text) {
                    w if !w.is_name()
                        && !self.declared.is_empty()
                        && self.declared.iter().any(|d| d.eq_ignore_ascii_case(text)) =>
                    {
                        Tok::Word(Word::Ident)
                    }
                    // a structure's field named by a keyword (`Type : INT;` in a STRUCT, read
                    // `r.Type`), as the ST reader takes it (B&R's library types use such names)
                    w if !w.is_name()
                        && (self.prev == Last::Dot
                            || (self.decl_start
                                && matches!(top, Some(Frame::Struct(..)))
                                && self.colon_follows(e))) =>
                    {
                        Tok::Word(Word::Ident)
                    }
                    // `R_Edge : R_TRIG;`: an edge qualifier stands only after an input's type,
                    // so at the start of a declaration, before `:`, it is the variable's name
                    // (accepted in a TwinCAT object, W1451; E1031 elsewhere: sema)
                    Word::REdge | Word::FEdge
                        if self.decl_start
                            && matches!(top, Some(Frame::Var(..)))
                            && self.colon_follows(e) =>
                    {
                        Tok::Word(Word::Ident)
                    }
                    w => Tok::Word(w),
                }
            }
            RawToken::Prefixed(None) => Tok::TypePrefix,
            RawToken::Prefixed(Some(t)) => Tok::Time(t),
            RawToken::Int(v) => Tok::Int(v),
            RawToken::Real(v) => Tok::Real(v),
            RawToken::Str((wide, v)) => Tok::Str(wide, v),
            RawToken::Address((a, sz, p)) => Tok::Address(a, sz, p),
            RawToken::LParen => Tok::LParen,
            RawToken::RParen => Tok::RParen,
            RawToken::LBracket => Tok::LBracket,
            RawToken::RBracket => Tok::RBracket,
            RawToken::Comma => Tok::Comma,
            RawToken::Colon => Tok::Colon,
            RawToken::Semi => Tok::Semi,
            RawToken::Assign => Tok::Assign,
            RawToken::Arrow => Tok::Arrow,
            RawToken::DotDot => Tok::DotDot,
            RawToken::Dot => Tok::Dot,
            RawToken::Op(b'+') => Tok::Plus,
            RawToken::Op(b'-') => Tok::Minus,
            RawToken::Op(b'*') => Tok::Star,
            RawToken::Op(_) => Tok::Slash,
            RawToken::Amp => Tok::Amp,
            RawToken::AmpN => Tok::AmpN,
            // Newlines and comments are handled before conversion.
            RawToken::Newline | RawToken::Comment(_) | RawToken::LineComment => Tok::Eol,
        }
    }

    /// Reads raw tokens until at least one output token is queued (or the input is exhausted).
    fn fill(&mut self) {
        if let Some(start) = self.start.take() {
            self.emit(0, start, 0);
            return;
        }
        while self.out.is_empty() && !self.finished {
            if self.line_runs && self.line_run() {
                return;
            }
            let next = self.lex.next();
            for (range, why) in std::mem::take(&mut self.lex.extras) {
                self.diags.push(
                    Diagnostic::error(code::E0004, format!("invalid string escape: {why}"))
                        .at(self.span(range.start, range.end))
                        .with_hint("write a dollar sign as `$$`"),
                );
            }
            let range = self.lex.span();
            let (s, e) = (range.start, range.end);
            let tok = match next {
                None => {
                    self.finish();
                    return;
                }
                Some(Ok(RawToken::Comment(false))) => continue,
                Some(Ok(RawToken::Newline | RawToken::Comment(true))) => {
                    if !self.in_decl() && self.pending_eol.is_none() {
                        self.pending_eol = Some(s);
                    }
                    continue;
                }
                Some(Ok(RawToken::Semi)) if !self.in_decl() => {
                    self.semicolon_comment(s);
                    continue;
                }
                // `LD w.3`, `ST w.%X0`: a partial access (3rd edition) is a field named `3` or `%X0`
                // (see `ast::partial_access`)
                Some(Ok(RawToken::Int(_)) | Err(LexError::BadAddress(_)))
                    if self.src[..s].ends_with('.')
                        && !self.src[..s].ends_with("..")
                        && crate::ast::partial_access(&self.src[s..e]).is_some() =>
                {
                    Tok::Word(Word::Ident)
                }
                Some(Ok(RawToken::Op(_)))
                    if !(self.in_decl()
                        && (self.decl_brackets > 0 || self.decl_init || self.decl_parens > 0)) =>
                {
                    self.report_lex_error(LexError::UnexpectedChar, s, e);
                    Tok::Error
                }
                Some(Ok(RawToken::LBracket))
                    if !self.in_decl() && self.code_brackets >= MAX_SUBSCRIPT_NESTING =>
                {
                    self.skip_too_deep_subscript(s, e);
                    continue;
                }
                Some(Ok(raw)) => {
                    match raw {
                        RawToken::LBracket if self.in_decl() => self.decl_brackets += 1,
                        RawToken::LBracket => self.code_brackets += 1,
                        RawToken::RBracket => {
                            self.decl_brackets = self.decl_brackets.saturating_sub(1);
                            if !self.in_decl() {
                                self.code_brackets = self.code_brackets.saturating_sub(1);
                            }
                        }
                        RawToken::Assign if self.in_decl() => self.decl_init = true,
                        RawToken::LParen
                            if self.in_decl()
                                && (self.decl_parens > 0
                                    || after_string_keyword(&self.src[..s])) =>
                        {
                            self.decl_parens += 1
                        }
                        RawToken::RParen if self.in_decl() => {
                            self.decl_parens = self.decl_parens.saturating_sub(1)
                        }
                        RawToken::Semi => {
                            self.decl_brackets = 0;
                            self.decl_init = false;
                            self.decl_parens = 0;
                        }
                        _ => {}
                    }
                    if matches!(
                        raw,
                        RawToken::Prefixed(Some(
                            TimeValue::TimeOfDay(..) | TimeValue::DateAndTime(..)
                        ))
                    ) && crate::literal::lacks_seconds(&self.src[s..e])
                    {
                        let d = crate::st::lexer::no_seconds_diagnostic(
                            self.span(s, e),
                            &self.src[s..e],
                        );
                        self.diags.push(d);
                    }
                    if matches!(raw, RawToken::Word) && !self.src[s..e].is_ascii() {
                        let d = crate::st::lexer::non_ascii_name_diagnostic(
                            self.span(s, e),
                            &self.src[s..e],
                        );
                        self.diags.push(d);
                    }
                    if matches!(raw, RawToken::Word)
                        && self.var_head
                        && self.src[s..e].eq_ignore_ascii_case("PERSISTENT")
                    {
                        self.persistent_read_as_retain(s, e)
                    } else {
                        self.convert(raw, s, e)
                    }
                }
                Some(Err(err)) => {
                    self.swallowed |= err == LexError::UnterminatedComment;
                    let skip_line = err == LexError::UnexpectedChar && !self.in_decl();
                    self.report_lex_error(err, s, e);
                    if skip_line {
                        // an IL line with a character that starts nothing (`# note: área`, a
                        // dialect's comment): one error for the line, the rest of it skipped
                        let rest = &self.src[e..];
                        let end = rest.find(['\n', '\r']).unwrap_or(rest.len());
                        self.lex.bump(end);
                    }
                    Tok::Error
                }
            };
            self.resolve_eol(Some(&tok));
            if let Tok::Word(w @ (Word::VarAccess | Word::VarConfig)) = tok {
                self.skip_unsupported_block(w, s, e);
                continue;
            }
            let mut closed = false;
            if let Tok::Word(w) = tok {
                if w != Word::Ident && w.is_name() && self.instruction_in_declarations() {
                    self.close_top(s);
                    closed = true;
                }
            }
            // `MOD(` + `IN1 := ...`: the formal call of the standard function that shares the
            // operator's name (IEC 61131-3 IL formal function call), not a deferred operator.
            let tok = match tok {
                Tok::Word(w) if w.is_simple_op() && self.formal_call_follows() => {
                    Tok::Word(Word::Ident)
                }
                other => other,
            };
            let tok =
                match tok {
                    Tok::Word(
                        w @ (Word::EndProgram | Word::EndFunction | Word::EndFunctionBlock),
                    ) if !self.in_configuration() => self.pou_end(s, w, e),
                    other => {
                        self.structure(s, &other, e);
                        other
                    }
                };
            if let Tok::Word(w) = tok {
                if !closed && self.line_token(s, e, w) {
                    continue;
                }
            }
            if matches!(tok, Tok::Word(Word::At))
                && matches!(self.stack.last(), Some(Frame::Struct(..)))
                && self.relative_location(e)
            {
                continue;
            }
            self.emit(s, tok, e);
        }
    }

    /// After `AT` (ending at `e`) in a `STRUCT`: a relative location of the member (IEC 61131-3
    /// ed. 3, 6.4.4.2 and Table 11, "structure with relative location of elements": `x AT %B0 :
    /// WORD;`, `b AT %X4.1 : BOOL;`, as SIMATIC AX's I/O layouts write them), the member's byte
    /// (and bit) offset in the structure. Each member is its own variable here: without the
    /// keyword OVERLAP members do not share bits, so the values read and written are those of the
    /// same structure without the locations. The `AT` and the location are skipped (`true`); the
    /// location is kept for [`Layout::overlapping_locations`].
    fn relative_location(&mut self, e: usize) -> bool {
        let rest = &self.src[e..];
        let blanks = rest.len() - rest.trim_start().len();
        let text = &rest[blanks..];
        let Some(loc) = text.strip_prefix('%') else {
            return false;
        };
        let size = match loc.bytes().next().map(|b| b.to_ascii_uppercase()) {
            Some(b @ (b'X' | b'B' | b'W' | b'D' | b'L')) => b,
            _ => return false,
        };
        let digits = |t: &str| t.bytes().take_while(u8::is_ascii_digit).count();
        let body = &loc[1..];
        let n = digits(body);
        if n == 0 {
            return false;
        }
        let Ok(byte) = body[..n].parse::<u64>() else {
            return false;
        };
        let mut len = 2 + n;
        let mut bit = 0;
        if let Some(after) = body[n..].strip_prefix('.') {
            let m = digits(after);
            if m == 0 || size != b'X' {
                return false;
            }
            bit = after[..m].parse::<u64>().unwrap_or(8);
            if bit > 7 {
                return false;
            }
            len += 1 + m;
        }
        if text[len..]
            .bytes()
            .next()
            .is_some_and(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'.')
        {
            return false;
        }
        // the member's type, when it is elementary: its width in bits
        let after = text[len..].trim_start();
        let ty = after.strip_prefix(':').map(str::trim_start).unwrap_or("");
        let name_len = ty
            .bytes()
            .take_while(|b| b.is_ascii_alphanumeric() || *b == b'_')
            .count();
        let bits = elementary_bits(&ty[..name_len]);
        let at = e + blanks;
        self.relative.push((byte * 8 + bit, bits, at, at + len));
        self.lex.bump(blanks + len);
        true
    }

    /// At `END_STRUCT`: E0006 for a member whose relative location shares bits with an earlier
    /// member's (IEC 61131-3 ed. 3: only a structure declared `OVERLAP` may overlap its members).
    fn overlapping_locations(&mut self) {
        let members = std::mem::take(&mut self.relative);
        for (k, &(start, bits, s, e)) in members.iter().enumerate() {
            let Some(bits) = bits else { continue };
            let clash = members[..k]
                .iter()
                .find(|&&(o, ob, _, _)| ob.is_some_and(|ob| start < o + ob && o < start + bits));
            if let Some(&(_, _, os, oe)) = clash {
                let d = Diagnostic::error(
                    code::E0006,
                    format!(
                        "relative location `{}` overlaps the member at `{}`",
                        &self.src[s..e],
                        &self.src[os..oe]
                    ),
                )
                .at(self.span(s, e))
                .with_hint(
                    "members of a STRUCT without OVERLAP do not share bytes (IEC 61131-3 ed. 3, Table 11); move the member past the other one's bytes",
                );
                self.diags.push(d);
            }
        }
    }

    /// At a word `w` (at `s..e`) that starts an instruction line: when the line is `LD x`,
    /// `ADD 5`, `JMPC done` (an operator word and a plain name or an integer literal) or `done:`, passes
    /// its two tokens on as one ([`Tok::SimpleLine`], [`Tok::SimpleIntLine`], [`Tok::JumpLine`],
    /// [`Tok::LabelLine`]) and returns `true`; nothing is emitted otherwise. The grammar builds the
    /// same statement of it as of the two tokens; the layout state after it is the one after the two
    /// (see [`Layout::emit`]). The line's end (blanks before it) must follow: anything else on the
    /// line (an accessor, a second operand, a comment) keeps the tokens apart.
    fn line_token(&mut self, s: usize, e: usize, w: Word) -> bool {
        // (a name with letters beyond ASCII goes the long way, which reports it: E1089)
        if !matches!(self.prev, Last::Start | Last::Eol)
            || !self.src[s..e].is_ascii()
            || self.in_decl()
            || self.stack.last() == Some(&Frame::Args)
        {
            return false;
        }
        let op = crate::parser::simple_op(w);
        let jump = match w {
            Word::Jmp => Some(Condition::Always),
            Word::Jmpc => Some(Condition::IfTrue),
            Word::Jmpcn => Some(Condition::IfFalse),
            _ => None,
        };
        if op.is_none() && jump.is_none() && w != Word::Ident {
            return false;
        }
        let mut ahead = self.lex.clone();
        let next = ahead.next();
        if !ahead.extras.is_empty() {
            return false;
        }
        let second = ahead.span();
        let name = matches!(next, Some(Ok(RawToken::Word)))
            && ahead.slice().is_ascii()
            && crate::lexer::classify(ahead.slice()) == Word::Ident;
        let (tok, end, prev2, prev) = match (next, op, jump) {
            (Some(Ok(RawToken::Word)), Some(op), _) if name => (
                Tok::SimpleLine(op, second.start, second.end),
                second.end,
                Last::Deferrable,
                Last::Other,
            ),
            (Some(Ok(RawToken::Int(v))), Some(op), _) => (
                Tok::SimpleIntLine(op, v, second.start, second.end),
                second.end,
                Last::Deferrable,
                Last::Other,
            ),
            (Some(Ok(RawToken::Word)), _, Some(c)) if name => (
                Tok::JumpLine(c, second.start, second.end),
                second.end,
                Last::Other,
                Last::Other,
            ),
            (Some(Ok(RawToken::Colon)), None, None) => {
                (Tok::LabelLine(s, e), second.end, Last::Other, Last::Colon)
            }
            _ => return false,
        };
        let rest = ahead.remainder().as_bytes();
        let blanks = rest
            .iter()
            .take_while(|b| matches!(b, b' ' | b'\t'))
            .count();
        if !matches!(rest.get(blanks), Some(b'\n' | b'\r')) {
            return false;
        }
        self.lex = ahead;
        self.emit(s, tok, end);
        self.prev2 = prev2;
        self.prev = prev;
        true
    }

    /// At the start of an instruction line of a POU's body, of a nested list (`AND(` .. `)`) or
    /// outside any block (a bare instruction list; no declaration block or argument list open, no
    /// keyword declared as a name outside the text): passes the plain
    /// lines from here on as one [`Tok::Lines`] and returns `true` (`false`, nothing consumed, when the
    /// first line is not plain). A plain line ([`plain_line`]) is one [`Layout::line_token`] passes
    /// on as one token, written with ASCII names, decimal digits, spaces and tabs only, and ended by
    /// `\n` or `\r\n`; blank lines between are skipped. The run stands for that line token and a
    /// [`Tok::Eol`] per line: a line end pending before it is resolved first, and the layout state
    /// after it is the one after a line end. Anything else (a comment, an accessor, a literal of
    /// another form, a `(`) ends the run and goes the general way, token by token.
    fn line_run(&mut self) -> bool {
        if !(matches!(self.prev, Last::Start | Last::Eol) || self.pending_eol.is_some())
            || !matches!(
                self.stack.last(),
                None | Some(Frame::Pou(..) | Frame::Deferred(..))
            )
            || !self.declared.is_empty()
        {
            return false;
        }
        let at = self.lex.span().end;
        let mut end = at;
        let mut lines = Vec::new();
        while lines.len() < MAX_RUN {
            // blank lines are skipped between the lines of a run only: before its first line the
            // lexer takes them (a failed look past many blank lines is not repeated line by line)
            let Some((s, line, e, next)) = plain_line(self.src, end, !lines.is_empty()) else {
                break;
            };
            if lines.is_empty() {
                lines.reserve(32);
            }
            lines.push((s, line, e));
            end = next;
        }
        let Some(&(start, ..)) = lines.first() else {
            return false;
        };
        self.lex.bump(end - at);
        self.resolve_eol(None);
        self.emit(start, Tok::Lines(lines), end);
        // as after the last line's `Eol`
        self.prev2 = Last::Other;
        self.prev = Last::Eol;
        true
    }

    /// A `[` past [`MAX_SUBSCRIPT_NESTING`] open subscripts in an instruction list: reported once
    /// per file (E0200), and skipped with everything up to its matching `]` (or the line's end), so
    /// the grammar sees an operand nested [`MAX_SUBSCRIPT_NESTING`] deep and no later stage (the
    /// semantic checks walk subscripts recursively) sees unbounded nesting.
    fn skip_too_deep_subscript(&mut self, s: usize, e: usize) {
        if !self.deep_subscript_reported {
            self.deep_subscript_reported = true;
            self.diags.push(
                Diagnostic::error(
                    code::E0200,
                    format!("subscripts are nested more than {MAX_SUBSCRIPT_NESTING} deep"),
                )
                .at(self.span(s, e))
                .with_primary_label(format!(
                    "level {}: skipped up to its `]`",
                    MAX_SUBSCRIPT_NESTING + 1
                ))
                .with_hint("compute inner subscripts into variables first (`LD i ... ST k`) and index with those"),
            );
        }
        let mut open = 1usize;
        loop {
            let mut ahead = self.lex.clone();
            match ahead.next() {
                None | Some(Ok(RawToken::Newline)) => break,
                Some(Ok(RawToken::LBracket)) => open += 1,
                Some(Ok(RawToken::RBracket)) => open -= 1,
                _ => {}
            }
            self.lex = ahead;
            if open == 0 {
                break;
            }
        }
        self.lex.extras.clear();
    }

    /// `VAR_ACCESS` / `VAR_CONFIG` ... `END_VAR`: reported once, skipped whole.
    fn skip_unsupported_block(&mut self, w: Word, s: usize, e: usize) {
        self.diags.push(
            Diagnostic::error(
                code::E0019,
                format!("`{}` blocks are not supported", w.spelling()),
            )
            .at(self.span(s, e))
            .with_primary_label("this block is skipped up to its END_VAR")
            .with_hint("remove the block; declare the variables in VAR_GLOBAL or VAR_EXTERNAL"),
        );
        while let Some(t) = self.lex.next() {
            if t == Ok(RawToken::Word) && crate::lexer::classify(self.lex.slice()) == Word::EndVar {
                break;
            }
        }
        self.lex.extras.clear();
    }

    /// At the start of a declaration in a `VAR` block, an IL operator not followed by `:`, `,` or `AT`
    /// starts an instruction: the block lacks its `END_VAR`.
    fn instruction_in_declarations(&self) -> bool {
        if !self.decl_start || !matches!(self.stack.last(), Some(Frame::Var(..))) {
            return false;
        }
        let mut ahead = self.lex.clone();
        match ahead.next() {
            Some(Ok(RawToken::Colon | RawToken::Comma)) | None => false,
            Some(Ok(RawToken::Word)) => crate::lexer::classify(ahead.slice()) != Word::At,
            _ => true,
        }
    }

    /// At an instruction's start, after an operator word: `(`, then (over line ends and comments) a
    /// name and `:=` or `=>`, so the word names a function called with formal arguments.
    fn formal_call_follows(&self) -> bool {
        if self.in_decl() || !matches!(self.prev, Last::Start | Last::Eol | Last::Colon) {
            return false;
        }
        // The usual case, without lexing ahead: past the blanks the lexer skips, the next character
        // cannot start `(` (`(*` opens a comment). A BOM or `/` (a skipped `//` comment) may hide one:
        // those take the full look-ahead.
        let rest = self.lex.remainder().as_bytes();
        let blanks = rest
            .iter()
            .take_while(|b| matches!(b, b' ' | b'\t' | 0x0c))
            .count();
        match rest.get(blanks) {
            Some(b'(') if rest.get(blanks + 1) != Some(&b'*') => {}
            Some(0xEF | b'/') => {}
            _ => return false,
        }
        let mut ahead = self.lex.clone();
        if ahead.next() != Some(Ok(RawToken::LParen)) {
            return false;
        }
        let name = loop {
            match ahead.next() {
                Some(Ok(RawToken::Newline | RawToken::Comment(_))) => continue,
                other => break other,
            }
        };
        name == Some(Ok(RawToken::Word))
            && matches!(ahead.next(), Some(Ok(RawToken::Assign | RawToken::Arrow)))
    }

    /// `; text` in an instruction list: reported, skipped to the end of the line. A `;` right after
    /// a block's closing keyword (`END_TYPE;`, `END_PROGRAM;`, common in hand-written ST) is no
    /// comment: it is reported as what it is, and only it is skipped.
    fn semicolon_comment(&mut self, s: usize) {
        let before = self.src[..s].trim_end();
        // (the character before the word may take several bytes: `�END_TYPE;`)
        let word_start = before
            .char_indices()
            .rev()
            .find(|&(_, c)| !(c.is_ascii_alphanumeric() || c == '_'))
            .map_or(0, |(i, c)| i + c.len_utf8());
        let word = &before[word_start..];
        const BLOCK_ENDS: &[&str] = &[
            "END_VAR",
            "END_TYPE",
            "END_STRUCT",
            "END_UNION",
            "END_PROGRAM",
            "END_FUNCTION",
            "END_FUNCTION_BLOCK",
            "END_CONFIGURATION",
            "END_RESOURCE",
            "END_ACTION",
            "END_ACTIONS",
            "END_METHOD",
            "END_PROPERTY",
            "END_INTERFACE",
        ];
        if BLOCK_ENDS.iter().any(|k| k.eq_ignore_ascii_case(word)) {
            let shown = word.to_ascii_uppercase();
            self.diags.push(
                Diagnostic::error(code::E0011, format!("unexpected `;` after `{shown}`"))
                    .at(self.span(s, s + 1))
                    .with_primary_label("no `;` here")
                    .with_hint(format!(
                        "remove the `;`: IEC 61131-3 ends a block with `{shown}` alone"
                    )),
            );
            return;
        }
        let rest = self.lex.remainder();
        let n = rest.find(['\n', '\r']).unwrap_or(rest.len());
        self.lex.bump(n);
        let end = s + 1 + rest[..n].trim_end().len();
        self.diags.push(
            Diagnostic::error(code::E0007, "`;` comments are not IEC 61131-3; use (* *)")
                .at(self.span(s, end))
                .with_primary_label("end-of-line comment of another dialect")
                .with_hint("write the comment as (* ... *); the rest of the line was skipped"),
        );
    }

    fn finish(&mut self) {
        self.finished = true;
        let end = self.src.len();
        self.resolve_eol(None);
        if !self.in_decl() {
            self.ensure_eol(end);
        }
        self.close_all(end);
        self.ensure_eol(end);
    }
}

/// The plain line at `pos` of `src` (after blank lines, spaces and tabs only, when `past_blank_lines`),
/// if it is one: the
/// local byte range and kind of the line token [`Layout::line_token`] passes on for it, and the
/// position after the line's end. Plain: blanks, then an operator word (`LD` .. `LT`, see
/// [`crate::parser::simple_op`]) and a name or a decimal integer (digits only), or a jump word
/// (`JMP`, `JMPC`, `JMPCN`) and a name, or a name and `:`; then blanks and `\n` or `\r\n`. Names are
/// `[A-Za-z_][A-Za-z0-9_]*` and not keywords ([`crate::lexer::classify`] gives [`Word::Ident`]); an
/// operator word and its operand are separated by blanks. Anything else is `None`.
fn plain_line(
    src: &str,
    pos: usize,
    past_blank_lines: bool,
) -> Option<(usize, LineTok, usize, usize)> {
    let b = src.as_bytes();
    let blanks = |mut i: usize| {
        while matches!(b.get(i), Some(b' ' | b'\t')) {
            i += 1;
        }
        i
    };
    let line_end = |i: usize| match (b.get(i), b.get(i + 1)) {
        (Some(b'\n'), _) => Some(i + 1),
        (Some(b'\r'), Some(b'\n')) => Some(i + 2),
        _ => None,
    };
    let word = |i: usize| {
        if !matches!(b.get(i), Some(c) if c.is_ascii_alphabetic() || *c == b'_') {
            return None;
        }
        let mut j = i + 1;
        while matches!(b.get(j), Some(c) if c.is_ascii_alphanumeric() || *c == b'_') {
            j += 1;
        }
        Some(j)
    };
    let mut i = blanks(pos);
    while let Some(next) = line_end(i).filter(|_| past_blank_lines) {
        i = blanks(next);
    }
    let ws = i;
    let we = word(ws)?;
    let w = crate::lexer::classify(&src[ws..we]);
    let j = blanks(we);
    let (line, e) = if b.get(j) == Some(&b':') {
        if w != Word::Ident {
            return None;
        }
        (LineTok::Label(ws, we), j + 1)
    } else if j == we {
        // no operand (`NOT`), or the word goes on (`x.y`, `INT#5`, `f(`)
        return None;
    } else if b.get(j).is_some_and(u8::is_ascii_digit) {
        let op = crate::parser::simple_op(w)?;
        let mut ne = j;
        while b.get(ne).is_some_and(u8::is_ascii_digit) {
            ne += 1;
        }
        let v = crate::literal::decimal_int(&src[j..ne]).ok()?;
        (LineTok::SimpleInt(op, v, j, ne), ne)
    } else {
        let ne = word(j)?;
        if crate::lexer::classify(&src[j..ne]) != Word::Ident {
            return None;
        }
        let line = match (crate::parser::simple_op(w), w) {
            (Some(op), _) => LineTok::Simple(op, j, ne),
            (None, Word::Jmp) => LineTok::Jump(Condition::Always, j, ne),
            (None, Word::Jmpc) => LineTok::Jump(Condition::IfTrue, j, ne),
            (None, Word::Jmpcn) => LineTok::Jump(Condition::IfFalse, j, ne),
            _ => return None,
        };
        (line, ne)
    };
    let next = line_end(blanks(e))?;
    Some((ws, line, e, next))
}

impl Iterator for Layout<'_> {
    type Item = Result<Spanned, ()>;
    fn next(&mut self) -> Option<Self::Item> {
        if self.out.is_empty() {
            self.fill();
        }
        self.out.pop_front().map(Ok)
    }
}

/// Whether `before` (the text up to a `(`) ends with the keyword `STRING` or `WSTRING`: the `(`
/// opens a string length (`STRING(80)`, CODESYS).
fn after_string_keyword(before: &str) -> bool {
    let before = before.trim_end();
    let word_start = before
        .bytes()
        .rposition(|b| !(b.is_ascii_alphanumeric() || b == b'_'))
        .map_or(0, |i| i + 1);
    let word = &before[word_start..];
    word.eq_ignore_ascii_case("STRING")
        || word.eq_ignore_ascii_case("WSTRING")
        // a subrange's bounds (`INT(cMin..cMax - 1)`): an elementary integer type's name
        || crate::sema::Elementary::from_name(&word.to_ascii_uppercase())
            .is_some_and(|e| e.is_integer())
}

/// The width in bits of an elementary type named `name` (a structure member's, for its relative
/// location); `None` for another type.
fn elementary_bits(name: &str) -> Option<u64> {
    let n = name.to_ascii_uppercase();
    Some(match n.as_str() {
        "BOOL" => 1,
        "BYTE" | "SINT" | "USINT" | "CHAR" => 8,
        "WORD" | "INT" | "UINT" | "WCHAR" => 16,
        "DWORD" | "DINT" | "UDINT" | "REAL" => 32,
        "LWORD" | "LINT" | "ULINT" | "LREAL" => 64,
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The token stream in a compact notation: words by spelling, `;` for Eol.
    /// A run of lines ([`Tok::Lines`]) reads as its lines' tokens, each with a line end: the same
    /// notation with and without runs (asserted).
    fn stream(src: &str) -> (String, Vec<String>) {
        let render = |mut l: Layout| {
            let mut out = Vec::new();
            for t in l.by_ref() {
                let (s, tok, e) = t.unwrap();
                out.push(match tok {
                    Tok::UnitStart => continue,
                    Tok::Eol => "/".to_string(),
                    Tok::Word(w) if s == e => format!("<{}>", w.spelling()),
                    Tok::RParen if s == e => "<)>".to_string(),
                    Tok::Lines(lines) => lines
                        .iter()
                        .map(|(l, _, r)| format!("{} /", &src[*l..*r]))
                        .collect::<Vec<_>>()
                        .join(" "),
                    _ => src[s..e].to_string(),
                });
            }
            (
                out.join(" "),
                l.diags
                    .iter()
                    .map(|d| format!("{} {}", d.code, d.message))
                    .collect::<Vec<_>>(),
            )
        };
        let runs = render(Layout::new(FileId(0), src, 0, Tok::UnitStart));
        let apart = render(Layout::new(FileId(0), src, 0, Tok::UnitStart).without_line_runs());
        assert_eq!(runs, apart, "with and without runs of lines");
        runs
    }

    /// The plain lines of a POU's body, of a nested list and outside any POU pass as runs (blank
    /// lines skipped, each line's token as [`Layout::line_token`] makes it); a line that is not plain,
    /// declarations (`y :` there is no label) and a text with a keyword declared as a name outside
    /// it do not.
    #[test]
    fn plain_lines_pass_as_runs() {
        let src = "PROGRAM p\nVAR\n  y :\n  INT;\nEND_VAR\n  LD x\n  ADD 5\r\n\n l:\n  JMPC l\n  LD x.y\n  ST z\nAND( a\n OR b\n)\nEND_PROGRAM\nLD q\n";
        let runs = |l: Layout| -> Vec<Vec<String>> {
            l.filter_map(|t| match t {
                Ok((_, Tok::Lines(lines), _)) => Some(
                    lines
                        .iter()
                        .map(|(s, line, e)| format!("{} {line:?}", &src[*s..*e]))
                        .collect(),
                ),
                _ => None,
            })
            .collect()
        };
        let at = |t: &str| src.find(t).unwrap();
        let op = |w: Word| crate::parser::simple_op(w).unwrap();
        let simple = |w: Word, name: &str| LineTok::Simple(op(w), at(name), at(name) + 1);
        assert_eq!(
            runs(Layout::new(FileId(0), src, 0, Tok::UnitStart)),
            vec![
                vec![
                    format!("LD x {:?}", simple(Word::Ld, "x\n  ADD")),
                    format!(
                        "ADD 5 {:?}",
                        LineTok::SimpleInt(op(Word::Add), 5, at("5"), at("5") + 1)
                    ),
                    format!("l: {:?}", LineTok::Label(at("l:"), at("l:") + 1)),
                    format!(
                        "JMPC l {:?}",
                        LineTok::Jump(Condition::IfTrue, at("l\n  LD"), at("l\n  LD") + 1)
                    ),
                ],
                vec![format!("ST z {:?}", simple(Word::St, "z\n"))],
                vec![format!("OR b {:?}", simple(Word::Or, "b\n"))],
                vec![format!("LD q {:?}", simple(Word::Ld, "q\n"))],
            ]
        );
        let declared =
            Layout::new(FileId(0), src, 0, Tok::UnitStart).with_declared(vec!["ON".into()]);
        assert!(runs(declared).is_empty());
        assert!(
            runs(Layout::new(FileId(0), src, 0, Tok::UnitStart).without_line_runs()).is_empty()
        );
    }

    #[test]
    fn line_ends_collapse_and_comments_vanish() {
        let (s, d) = stream("\n\nLD a (* c *)\n\n(* only *)\n  ST b");
        assert_eq!(s, "LD a / ST b /");
        assert!(d.is_empty());
    }

    #[test]
    fn declarations_ignore_line_ends() {
        let (s, _) = stream("PROGRAM p\nVAR\n a :\n INT;\nEND_VAR\nLD a\nEND_PROGRAM\n");
        assert_eq!(
            s,
            "PROGRAM p / VAR a : INT ; END_VAR / LD a / END_PROGRAM /"
        );
    }

    #[test]
    fn call_arguments_span_lines_but_deferred_lists_do_not() {
        let (s, _) = stream("CAL f(\n a := 1,\n b => c\n)\nAND( x\nOR y\n)\n");
        assert_eq!(s, "CAL f ( a := 1 , b => c ) / AND ( x / OR y / ) /");
        let (s, _) = stream("CAL f(a := 1\nLD x\n");
        assert_eq!(s, "CAL f ( a := 1 / LD x /");
    }

    #[test]
    fn semicolon_comment_is_reported_and_skipped() {
        let (s, d) = stream("LD a ; it's a comment\nST b");
        assert_eq!(s, "LD a / ST b /");
        assert_eq!(d, vec!["E0007 `;` comments are not IEC 61131-3; use (* *)"]);
        let (s, d) = stream("VAR a : INT; END_VAR");
        assert_eq!(s, "VAR a : INT ; END_VAR /");
        assert!(d.is_empty());
    }

    /// A `;` comment after a word that follows a character of several bytes (found by
    /// `fuzz_inprocess`: `MC_Move\u{fffd}Absolute ;` sliced inside the character and panicked).
    #[test]
    fn semicolon_comment_after_a_multibyte_character_is_reported() {
        for src in [
            "LD a\u{fffd}b ; note\nST c",
            "LD \u{e9}; note\nST c",
            "\u{20ac}END_TYPE; x",
        ] {
            let (_, d) = stream(src);
            // (an unexpected character, `\u{fffd}`, takes the rest of its line: one E0001)
            assert!(
                d.iter().any(|m| m.starts_with("E0007")
                    || m.starts_with("E0011")
                    || m.starts_with("E0001")),
                "{src:?}: {d:?}"
            );
        }
    }

    #[test]
    fn unclosed_blocks_are_closed_and_reported_once() {
        let (s, d) = stream("PROGRAM p\nVAR a : INT;\nLD a\nAND( b\nOR c\n");
        assert_eq!(
            s,
            "PROGRAM p / VAR a : INT ; <END_VAR> LD a / AND ( b / OR c / <)> / <END_PROGRAM> /"
        );
        assert_eq!(
            d,
            vec![
                "E0008 missing `END_VAR`",
                "E0009 missing `)` of a deferred operator",
                "E0008 missing `END_PROGRAM`"
            ]
        );
        let (s, d) = stream("PROGRAM p\nAND( b\nOR c\nPROGRAM q\nEND_PROGRAM");
        assert_eq!(
            s,
            "PROGRAM p / AND ( b / OR c / <)> / <END_PROGRAM> PROGRAM q / END_PROGRAM /"
        );
        assert_eq!(
            d,
            vec![
                "E0009 missing `)` of a deferred operator",
                "E0008 missing `END_PROGRAM`"
            ]
        );
    }

    #[test]
    fn mismatched_pou_end_is_replaced() {
        let (s, d) = stream("FUNCTION_BLOCK f\nEND_FUNCTION\n");
        assert_eq!(s, "FUNCTION_BLOCK f / END_FUNCTION /");
        assert_eq!(d, vec!["E0010 `END_FUNCTION` closes a FUNCTION_BLOCK"]);
    }

    #[test]
    fn lexer_errors_become_error_tokens() {
        let (s, d) = stream("LD 2#12\nST ?");
        assert_eq!(s, "LD 2#12 / ST ? /");
        assert_eq!(
            d,
            vec![
                "E0005 invalid literal: `2` is not a base-2 digit",
                "E0001 unexpected character `?`"
            ]
        );
    }

    /// `LD x`, `ADD 5`, `JMPC l` and `l:` followed by the line's end: one token each (without runs), with the
    /// operator and the second token's range; any other line keeps its tokens (an accessor, another
    /// literal, a comment, a label before an instruction, a keyword as the name, declarations, call
    /// arguments, the end of the text right after the name).
    #[test]
    fn simple_jump_and_label_lines_pass_as_one_token() {
        let lines = |src: &str| -> Vec<String> {
            Layout::new(FileId(0), src, 0, Tok::UnitStart)
                .without_line_runs()
                .filter_map(|t| t.ok())
                .filter_map(|(s, tok, e)| {
                    let (what, ns, ne) = match tok {
                        Tok::SimpleLine((op, negated, w), ns, ne) => {
                            (format!("{op:?}{negated} {}", w.spelling()), ns, ne)
                        }
                        Tok::SimpleIntLine((op, negated, w), v, ns, ne) => {
                            (format!("{op:?}{negated} {} {v}", w.spelling()), ns, ne)
                        }
                        Tok::JumpLine(c, ns, ne) => (format!("{c:?}"), ns, ne),
                        Tok::LabelLine(ns, ne) => ("label".to_string(), ns, ne),
                        _ => return None,
                    };
                    assert!(s <= ns && ne <= e, "{src:?}");
                    Some(format!("{what} [{}] [{}]", &src[ns..ne], &src[s..e]))
                })
                .collect()
        };
        assert_eq!(
            lines("LD a\n  ANDN b_1 \t\r\nst Q\rLT c\nADD 16#1F\nSUB -7\nJMPCN l2\nl2:\nJMPNC x\n"),
            [
                "Ldfalse LD [a] [LD a]",
                "Andtrue ANDN [b_1] [ANDN b_1]",
                "Stfalse ST [Q] [st Q]",
                "Ltfalse LT [c] [LT c]",
                "Addfalse ADD 31 [16#1F] [ADD 16#1F]",
                "Subfalse SUB -7 [-7] [SUB -7]",
                "IfFalse [l2] [JMPCN l2]",
                "label [l2] [l2:]",
                "IfFalse [x] [JMPNC x]",
            ]
        );
        for src in [
            "LD a.b\n",
            "LD a[1]\n",
            "LD a (* c *)\n",
            "LD a // c\n",
            "LD 5.0\n",
            "LD INT#5\n",
            "LD TRUE\n",
            "LD IN\n",
            "ADD a, b\n",
            "ADD 1, 2\n",
            "l1: LD a\n",
            "l1: (* c *)\n",
            "IN:\n",
            "CAL f\n",
            "JMP LD\n",
            "JMP l1 l2\n",
            "VAR\nLD : BOOL;\nEND_VAR\n",
            "VAR\nx :\nBOOL;\nEND_VAR\n",
            "CAL f(\nLD a\n)\n",
            "LD a",
        ] {
            assert_eq!(lines(src), Vec::<String>::new(), "{src:?}");
        }
        // The line after such a line: the layout state is the one after its two tokens.
        let (s, d) = stream("LD a\nAND( b\nOR 1\n)\nl:\nST d\nJMP l\n");
        assert_eq!(s, "LD a / AND ( b / OR 1 / ) / l: / ST d / JMP l /");
        assert!(d.is_empty());
    }

    /// An operator word followed by a formal argument list is passed on as a name (a function call),
    /// also with blanks or a BOM before `(`; `(*` opens a comment and a bare operand is an operand.
    #[test]
    fn formal_call_look_ahead_sees_past_blanks_only() {
        let word_of_mod = |src: &str| {
            Layout::new(FileId(0), src, 0, Tok::UnitStart)
                .without_line_runs()
                .filter_map(|t| t.ok())
                .find_map(|(s, tok, e)| match tok {
                    Tok::Word(w) if &src[s..e] == "MOD" => Some(w),
                    Tok::SimpleLine((_, _, w), ..) if src[s..e].starts_with("MOD") => Some(w),
                    _ => None,
                })
        };
        for src in [
            "MOD(IN1 := a, IN2 := b)\n",
            "MOD \t\u{c}(IN1 := a, IN2 := b)\r\n",
            "MOD (\n IN1 := a, IN2 := b)\n",
            "MOD\u{feff}(IN1 => a)\n",
        ] {
            assert_eq!(word_of_mod(src), Some(Word::Ident), "{src:?}");
        }
        for src in [
            "MOD b\n",
            "MOD (* c *) b\n",
            "MOD // c\n",
            "MOD(\n LD b\n)\n",
            // a lone \r ends the line (old Mac OS line ends)
            "MOD \t\r(IN1 := a, IN2 := b)\n",
            "MOD",
        ] {
            assert_eq!(word_of_mod(src), Some(Word::Mod), "{src:?}");
        }
    }
}
