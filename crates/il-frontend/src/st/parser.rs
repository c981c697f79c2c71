//! The ST parser: tokens in, [`super::ast`] statements or one expression out (recursive descent).
//!
//! Input: the text, its file and byte base. Output: the statements that could be read, and
//! diagnostics E0100-E0139 in ST terms with hints.
//! Invariants: expressions follow the IEC precedence (edition 2 table 55): `( )`, function call, `**`,
//! unary `-`/`+`/`NOT`, `* / MOD`, `+ -`, `< > <= >=`, `= <>`, `AND &`, `XOR`, `OR`; binary operators are
//! left-associative. Recovery: a bad statement is reported once and skipped up to its `;` (or the next
//! statement or block keyword), so the next statement is still read; a block left open is reported at
//! its opening keyword. The `;` after `END_IF`, `END_CASE`, `END_FOR`, `END_WHILE`, `END_REPEAT` may be
//! left out, as CODESYS allows. Every loop consumes a token or returns, so the parser always terminates; the
//! nesting depth is bounded so hostile input cannot overflow the stack.

use super::ast::*;
use super::lexer::{lex, Kw, Problem, Tok, Token};
use crate::ast::{DirectAddress, Ident, Literal, LiteralKind};
use crate::lexer::TimeValue;
use crate::{FileId, Span};
use diagnostics::{code, Code, Diagnostic, Diagnostics};

mod exst;

/// Deeper nesting of blocks or parentheses than this is reported (E0108) instead of recursing
/// (each level costs the parser and the lowering about 12 KB of stack in a debug build: 128 levels
/// stay within a 2 MB thread, as an IDE embedding the library may give).
const MAX_DEPTH: usize = 128;
/// The most places one chained assignment `a := b := ... := e;` writes (ExST).
const MAX_ASSIGN_CHAIN: usize = 64;
/// The most tokens a place may span for the chained-assignment lookahead.
const MAX_PLACE_LOOKAHEAD: usize = 256;
/// The most tokens looked at for a call chain (`)` then `.`) ahead of a statement or call.
const MAX_CHAIN_LOOKAHEAD: usize = 4096;

/// More operations than this in one expression (operators, function calls and array indexes, in its
/// parentheses and call arguments too) is E0109. The C of a long expression is linear (about one line per
/// operation), but C compilers are not: `cc -O2` spends 15 s on one function of 10,000 DINT divisions,
/// over 4 minutes on 100,000 mixed operators and over 2 minutes on 90,000 nested `ABS` calls.
pub const MAX_EXPRESSION_OPERATIONS: usize = 1000;

/// Parses a statement list (a POU body, an action or transition body). `base` is the byte offset of `src`
/// in file `file`; errors are reported, the statements read are returned.
pub fn statements(file: FileId, src: &str, base: usize, diags: &mut Diagnostics) -> Vec<Stmt> {
    statements_in(file, src, base, false, false, diags)
}

/// [`statements`] of a function block's body or method; `this_dot`: `THIS.x` and `THIS.M(...)`
/// (IEC 61131-3 edition 3, Annex A: `Symbolic_Variable : ( 'THIS' '.' )? ...`) are read as
/// `THIS^.x`, `THIS^.M(...)` (CODESYS, TwinCAT). Only where the block declares no variable `THIS`.
/// `this_declared`: the POU declares a variable named `THIS`, so `this` alone is that variable,
/// not the instance's address.
pub fn statements_in(
    file: FileId,
    src: &str,
    base: usize,
    this_dot: bool,
    this_declared: bool,
    diags: &mut Diagnostics,
) -> Vec<Stmt> {
    let mut local = Diagnostics::new();
    let mut p = Parser::new(file, src, base, &mut local);
    p.this_dot = this_dot;
    p.this_declared = this_declared;
    // a statement list ends where its POU's, method's or action's body ends (`END_PROGRAM`, the
    // end of a TwinCAT `<ST>` element): "found the end of the body" (not "of text")
    p.eof_text = "the end of the body";
    let mut list = p.statement_list();
    while !p.at(&Tok::Eof) {
        // A stray block keyword at the top level (`END_IF` without `IF` ...).
        let t = p.describe_current();
        p.error_here(
            code::E0100,
            format!("{t} without a matching opening statement"),
            "remove it, or add the statement that it closes",
        );
        p.bump();
        list.extend(p.statement_list());
    }
    // A comment that is never closed takes the rest of the text: what is missing after its
    // opening (`END_CASE`, `END_IF` ...) follows from it and is not reported again.
    let unclosed = local
        .iter()
        .filter(|d| d.code == code::E0102 && d.message.starts_with("comment or pragma"))
        .filter_map(|d| d.span.map(|s| s.start))
        .min();
    match unclosed {
        Some(at) => diags.extend(
            local
                .into_vec()
                .into_iter()
                .filter(|d| d.code == code::E0102 || d.span.is_none_or(|s| s.start < at)),
        ),
        None => diags.extend(local),
    }
    list
}

/// Parses one expression (an inline transition condition, `Level > 10 AND NOT Alarm`); `None` when there is
/// none or it cannot be read (reported, E0107).
pub fn expression(file: FileId, src: &str, base: usize, diags: &mut Diagnostics) -> Option<Expr> {
    let mut p = Parser::new(file, src, base, diags);
    // (no statement runs before a transition condition: an assignment in it is E1052)
    p.no_assign = true;
    if p.at(&Tok::Eof) {
        p.error_here(
            code::E0107,
            "expected an expression, found nothing",
            "write a BOOL expression such as `Level > 10 AND NOT Alarm`",
        );
        return None;
    }
    let e = p.expr();
    if p.at(&Tok::Semi) {
        p.bump();
    }
    if !p.at(&Tok::Eof) {
        let t = p.describe_current();
        p.error_here(
            code::E0107,
            format!("unexpected {t} after the end of the expression"),
            "an expression alone is expected here (no statements, no `:=`)",
        );
        return None;
    }
    (!matches!(e.kind, ExprKind::Error)).then_some(e)
}

struct Parser<'s, 'd> {
    file: FileId,
    src: &'s str,
    base: usize,
    toks: Vec<Token>,
    pos: usize,
    depth: usize,
    /// Nesting of [`Parser::expr`] calls: 0 outside any expression.
    expr_level: usize,
    /// Operations read in the outermost expression so far.
    operations: usize,
    /// Start of the outermost expression (for E0109's label).
    expr_start: usize,
    /// Method calls read in the expressions of the statement being parsed (`r := c.Add(1);`):
    /// put before it as call statements, the expression reading the method's result
    /// (`c.__M_ADD`, see `crate::actions::method_result`).
    hoisted: Vec<Stmt>,
    /// Inside a condition evaluated again and again or only sometimes (WHILE, UNTIL, ELSIF): a
    /// method call there cannot be put before the statement.
    no_hoist: usize,
    /// Inside the right operand of AND_THEN / OR_ELSE (for E0108's message, and E1052).
    short_operand: usize,
    /// Reading an expression alone (an SFC transition condition): no statement can run an ExST
    /// assignment `(x := e)` before it (E1052).
    no_assign: bool,
    /// Whether W0324 (AND_THEN / OR_ELSE) was reported for this text.
    short_circuit_noted: bool,
    /// Whether W1427 (`__TRY`) was reported for this text.
    try_noted: bool,
    /// `THIS.x` is `THIS^.x` (edition 3's spelling; see [`statements_in`]).
    this_dot: bool,
    /// The POU declares a variable named `THIS`: `this` alone reads it (see [`statements_in`]).
    this_declared: bool,
    /// How the end of the text is described in "found ..." (`end of text`; in a body, `the end of
    /// the body`).
    eof_text: &'static str,
    /// The last error reported (code, span): the same error at the same place again (an unclosed
    /// `(` or IF per level after E0108 "nested too deeply") is not repeated.
    last_error: Option<(Code, Span)>,
    /// The token that starts the statements of the last CASE branch read (after its `:`): a
    /// statement begins there (`0: Bump;`, see [`Parser::starts_statement`]).
    arm_start: usize,
    diags: &'d mut Diagnostics,
}

/// Keywords that end a statement list (the enclosing construct decides whether it is its own).
fn ends_list(t: &Tok) -> bool {
    use Kw::*;
    matches!(
        t,
        Tok::Eof | Tok::Kw(EndIf | Elsif | Else | EndCase | EndFor | EndWhile | Until | EndRepeat)
    )
}

/// Keywords that start a statement: where recovery stops skipping.
fn starts_statement(t: &Tok) -> bool {
    use Kw::*;
    matches!(
        t,
        Tok::Kw(If | Case | For | While | Repeat | Exit | Continue | Return)
    )
}

impl<'s, 'd> Parser<'s, 'd> {
    fn new(file: FileId, src: &'s str, base: usize, diags: &'d mut Diagnostics) -> Self {
        let (toks, problems) = lex(src);
        let mut p = Parser {
            file,
            src,
            base,
            toks,
            pos: 0,
            depth: 0,
            expr_level: 0,
            operations: 0,
            expr_start: 0,
            hoisted: Vec::new(),
            no_hoist: 0,
            short_operand: 0,
            no_assign: false,
            short_circuit_noted: false,
            try_noted: false,
            this_dot: false,
            this_declared: false,
            eof_text: "end of text",
            last_error: None,
            arm_start: usize::MAX,
            diags,
        };
        for pr in problems {
            p.lex_problem(pr);
        }
        p
    }

    fn lex_problem(&mut self, pr: Problem) {
        let (code, range, msg, hint) = match pr {
            Problem::Pragma(r) => {
                let span = self.span(r.start, r.end);
                let text = self.src.get(r).unwrap_or("{}");
                // (`{attribute 'call_after_init'}` is applied: `super::fb_init`)
                if !super::fb_init::is_call_after_init(text) {
                    self.diags.push(super::lexer::pragma_diagnostic(text, span));
                }
                return;
            }
            Problem::NoSeconds(r) => {
                let span = self.span(r.start, r.end);
                let text = self.src[r].to_string();
                self.diags
                    .push(super::lexer::no_seconds_diagnostic(span, &text));
                return;
            }
            Problem::TrailingPoint(r) => {
                let span = self.span(r.start, r.end);
                let text = self.src[r].to_string();
                self.diags
                    .push(super::lexer::trailing_point_diagnostic(span, &text));
                return;
            }
            Problem::FlatComment(r) => {
                let whole = self.span(r.start, r.end);
                self.diags
                    .push(super::lexer::flat_comment_diagnostic(whole));
                return;
            }
            Problem::NonAsciiName(r) => {
                let span = self.span(r.start, r.end);
                let name = self.src[r].to_string();
                self.diags
                    .push(super::lexer::non_ascii_name_diagnostic(span, &name));
                return;
            }
            Problem::UnexpectedChar(r) => {
                let c = self.src[r.clone()].chars().next().unwrap_or(' ');
                (
                    code::E0101,
                    r,
                    format!("`{c}` cannot start anything in Structured Text"),
                    "remove the character; strings are written between quotes ('text'), comments as (* ... *)".to_string(),
                )
            }
            Problem::UnterminatedComment(r) => (
                code::E0102,
                // the opener: `(*`, `/*` or `{` (whatever follows may be a multi-byte character)
                r.start..r.start
                    + if self.src[r.start..].starts_with("(*") || self.src[r.start..].starts_with("/*") {
                        2
                    } else {
                        1
                    },
                "comment or pragma is never closed".to_string(),
                "close `(*` with `*)` (comments nest: every `(*` needs its own `*)`) and `{` with `}`".to_string(),
            ),
            Problem::UnterminatedString(r) => (
                code::E0102,
                r,
                "string literal is not closed on its line".to_string(),
                "end the string with the quote it started with; write a quote inside as $' or $\"".to_string(),
            ),
            Problem::BadLiteral(r, why) => (
                code::E0103,
                r,
                format!("invalid literal: {why}"),
                "see the literal forms: 16#FF, 2#1010, 1.5E3, T#1h2m3s, D#2024-01-31, TOD#12:00:00".to_string(),
            ),
            Problem::DoubledQuote(r) => {
                let q = &self.src[r.start..r.start + 1];
                (
                    code::E0103,
                    r,
                    format!("invalid escape in string: `{q}{q}` ends the string and starts another"),
                    format!("IEC 61131-3 writes the quote inside a string as `${q}` (`'it$'s'`)"),
                )
            }
            Problem::BadEscape(r, why) => (
                code::E0103,
                r,
                format!("invalid escape in string: {why}"),
                "escapes are $$, $', $\", $L, $N, $P, $R, $T and $ followed by two hex digits".to_string(),
            ),
        };
        let span = self.span(range.start, range.end);
        self.diags
            .push(Diagnostic::error(code, msg).at(span).with_hint(hint));
    }

    // ------------------------------------------------------------ token helpers

    fn span(&self, start: usize, end: usize) -> Span {
        Span::new(self.file, self.base + start, self.base + end.max(start))
    }
    fn cur(&self) -> &Token {
        &self.toks[self.pos.min(self.toks.len() - 1)]
    }
    fn peek(&self) -> &Tok {
        &self.cur().tok
    }
    fn peek_at(&self, n: usize) -> &Tok {
        &self.toks[(self.pos + n).min(self.toks.len() - 1)].tok
    }
    fn at(&self, t: &Tok) -> bool {
        self.peek() == t
    }
    fn at_kw(&self, k: Kw) -> bool {
        self.at(&Tok::Kw(k))
    }
    fn bump(&mut self) -> Token {
        let t = self.cur().clone();
        if self.pos < self.toks.len() - 1 {
            self.pos += 1;
        }
        t
    }
    fn cur_span(&self) -> Span {
        let r = &self.cur().range;
        self.span(r.start, r.end)
    }
    /// The end of the previous token (where a missing `;` belongs).
    fn prev_end(&self) -> usize {
        if self.pos == 0 {
            0
        } else {
            self.toks[self.pos - 1].range.end
        }
    }
    fn text(&self, t: &Token) -> &'s str {
        &self.src[t.range.clone()]
    }
    fn ident(&self, t: &Token) -> Ident {
        Ident::new(self.text(t), self.span(t.range.start, t.range.end))
    }
    fn describe_current(&self) -> String {
        let t = self.cur();
        match &t.tok {
            Tok::Eof => self.eof_text.into(),
            // `Lib.Name` of a library ladderc does not provide reaches the parser as `__b_Name`
            // (`super::qualifiers`, E1032): no identifier can be written so
            Tok::Ident if self.text(t).starts_with("__") => "a library-qualified name".into(),
            Tok::Ident => format!("name `{}`", self.text(t)),
            Tok::Kw(k) => format!("`{}`", k.spelling()),
            Tok::Int(_) | Tok::Real(_) | Tok::Time(_) | Tok::Str(..) => {
                format!("literal `{}`", self.text(t))
            }
            Tok::Error => "invalid text".into(),
            _ => format!("`{}`", self.text(t)),
        }
    }
    fn error_at(
        &mut self,
        code: Code,
        span: Span,
        msg: impl Into<String>,
        hint: impl Into<String>,
    ) {
        self.push_error(Diagnostic::error(code, msg).at(span).with_hint(hint));
    }
    /// Reports `d` unless the last error had the same code at the same place.
    fn push_error(&mut self, d: Diagnostic) {
        if let Some(span) = d.span {
            if self.last_error == Some((d.code, span)) {
                return;
            }
            self.last_error = Some((d.code, span));
        }
        self.diags.push(d);
    }
    fn error_here(&mut self, code: Code, msg: impl Into<String>, hint: impl Into<String>) {
        // An error token was already reported by the lexer: one diagnostic per mistake.
        if self.at(&Tok::Error) {
            return;
        }
        let span = self.cur_span();
        self.error_at(code, span, msg, hint);
    }
    /// Consumes `k` or reports "expected `k`"; returns whether it was there.
    fn expect_kw(&mut self, k: Kw, context: &str) -> bool {
        if self.at_kw(k) {
            self.bump();
            return true;
        }
        let found = self.describe_current();
        self.error_here(
            code::E0100,
            format!("expected `{}` {context}, found {found}", k.spelling()),
            format!("write `{}` here", k.spelling()),
        );
        false
    }
    /// Skips to the end of the bad statement: past its `;`, or up to a statement or block keyword.
    fn sync(&mut self) {
        loop {
            let t = self.peek();
            if *t == Tok::Semi {
                self.bump();
                return;
            }
            if ends_list(t) || starts_statement(t) {
                return;
            }
            self.bump();
        }
    }

    // ------------------------------------------------------------ statements

    fn statement_list(&mut self) -> Vec<Stmt> {
        let mut out = Vec::new();
        while !ends_list(self.peek()) && self.try_word().is_none_or(|w| w == "__TRY") {
            self.statement_into(&mut out);
        }
        out
    }

    /// The word of TwinCAT's exception handling here (`__TRY`, `__CATCH`, `__FINALLY`,
    /// `__ENDTRY`, upper case), if any.
    fn try_word(&self) -> Option<&'static str> {
        if !matches!(self.peek(), Tok::Ident) {
            return None;
        }
        let w = self.text(self.cur());
        ["__TRY", "__CATCH", "__FINALLY", "__ENDTRY"]
            .into_iter()
            .find(|k| w.eq_ignore_ascii_case(k))
    }

    /// `__TRY s __CATCH(exc) c __FINALLY f __ENDTRY` (TwinCAT 3.1.4024): read as `IF TRUE THEN s f
    /// ELSE c f END_IF`: ladderc's runtime raises no exception (a division by zero gives 0 and is
    /// reported while the program runs), so the `__CATCH` statements are checked and never run
    /// (W1427, once per text). The current token is `__TRY`.
    fn try_stmt(&mut self) -> Option<StmtKind> {
        let t = self.cur().clone();
        let try_span = self.span(t.range.start, t.range.end);
        self.bump();
        let mut body = self.statement_list();
        let mut catch = Vec::new();
        let mut finally = Vec::new();
        if self.try_word() == Some("__CATCH") {
            self.bump();
            // `(exc)`: the variable that would receive the exception code (never written)
            if self.at(&Tok::LParen) {
                self.bump();
                if matches!(self.peek(), Tok::Ident) {
                    self.bump();
                }
                if self.at(&Tok::RParen) {
                    self.bump();
                } else {
                    let found = self.describe_current();
                    self.error_here(
                        code::E0100,
                        format!("expected `)` after the exception variable, found {found}"),
                        "write `__CATCH(exc)` with one variable",
                    );
                }
            }
            catch = self.statement_list();
        }
        if self.try_word() == Some("__FINALLY") {
            self.bump();
            finally = self.statement_list();
        }
        if self.try_word() != Some("__ENDTRY") {
            let found = self.describe_current();
            self.error_here(
                code::E0100,
                format!("expected `__ENDTRY`, found {found}"),
                "close the block: `__TRY ... __CATCH(exc) ... __FINALLY ... __ENDTRY`",
            );
            return None;
        }
        self.bump();
        if !self.try_noted {
            self.try_noted = true;
            self.diags.push(
                Diagnostic::warning(
                    code::W1427,
                    "`__TRY` (TwinCAT exception handling): ladderc's runtime raises no exception, so the `__CATCH` statements never run (the text's other such blocks are not reported)",
                )
                .at(try_span)
                .with_primary_label("its statements run, then the __FINALLY ones")
                .with_hint("a division by zero gives 0, a conversion out of range saturates, an index out of bounds stops the run, each reported while the program runs; test the divisor (or the index) before the operation to handle it in the program"),
            );
        }
        body.extend(finally.iter().cloned());
        catch.extend(finally);
        let cond = Expr {
            kind: ExprKind::Literal(Literal {
                kind: LiteralKind::Bool(true),
                type_prefix: None,
                span: try_span,
            }),
            span: try_span,
        };
        Some(StmtKind::If {
            branches: vec![CondBranch {
                cond,
                body,
                span: try_span,
            }],
            else_body: Some(catch),
        })
    }

    /// Parses one statement into `out`, after the method calls its expressions hold.
    fn statement_into(&mut self, out: &mut Vec<Stmt>) {
        let outer = std::mem::take(&mut self.hoisted);
        // a call chain (`x := a.M() + s.Get(1).Pop();`) is taken apart by the lowering: the
        // statement's other method calls stay in place too, so that all run in source order
        let chained = self.chain_ahead();
        let outer_no_hoist = std::mem::replace(&mut self.no_hoist, usize::from(chained));
        let s = self.statement();
        self.no_hoist = outer_no_hoist;
        let calls = std::mem::replace(&mut self.hoisted, outer);
        if let Some(s) = s {
            out.extend(calls);
            out.push(s);
        }
    }

    /// Whether the statement starting here holds a call chain (`)` followed by `.`, `^` or `[`)
    /// before its first `;` outside parentheses (looking at most [`MAX_CHAIN_LOOKAHEAD`] tokens).
    fn chain_ahead(&self) -> bool {
        let mut depth = 0usize;
        for i in 0..MAX_CHAIN_LOOKAHEAD {
            match self.peek_at(i) {
                Tok::LParen => depth += 1,
                Tok::RParen => {
                    depth = depth.saturating_sub(1);
                    if matches!(self.peek_at(i + 1), Tok::Dot | Tok::Caret | Tok::LBracket) {
                        return true;
                    }
                }
                Tok::Semi if depth == 0 => return false,
                Tok::Eof => return false,
                _ => {}
            }
        }
        false
    }

    /// Whether the `(` at `self.peek_at(at)` opens a call whose `)` is followed by `.`, `^` or `[`
    /// (a call chain: `stack.Get(1).Pop()`, `Next()^.Value`).
    fn call_then_access(&self, at: usize) -> bool {
        if *self.peek_at(at) != Tok::LParen {
            return false;
        }
        let mut depth = 0usize;
        let mut i = at;
        while i < at + MAX_CHAIN_LOOKAHEAD {
            match self.peek_at(i) {
                Tok::LParen => depth += 1,
                Tok::RParen => {
                    depth -= 1;
                    if depth == 0 {
                        return matches!(
                            self.peek_at(i + 1),
                            Tok::Dot | Tok::Caret | Tok::LBracket
                        );
                    }
                }
                Tok::Semi | Tok::Eof => return false,
                _ => {}
            }
            i += 1;
        }
        false
    }

    /// A statement list that stops also before a CASE label (`5:`, `1, 2:`, `3..4:`, `red:`).
    fn case_arm_body(&mut self) -> Vec<Stmt> {
        let mut out = Vec::new();
        loop {
            while !ends_list(self.peek()) && !self.looks_like_case_label() {
                self.statement_into(&mut out);
            }
            if !self.stray_closer_in_case() {
                return out;
            }
            // one E0100 for a closer that closes nothing in the branch (`END_IF` once too often),
            // skipped: the CASE goes on (before round 26: also E0105 "CASE is not closed" and an
            // E0100 for the next label)
            let t = self.describe_current();
            self.error_here(
                code::E0100,
                format!("{t} without a matching opening statement"),
                "remove it, or add the statement that it closes",
            );
            self.bump();
            if self.at(&Tok::Semi) {
                self.bump();
            }
        }
    }

    /// Whether the current token closes a statement that is not open in a CASE branch (`END_IF`,
    /// `END_FOR`, `END_WHILE`, `END_REPEAT`) and the CASE plainly goes on after it (a label or
    /// `END_CASE` follows): a stray closer, not the end of an enclosing statement.
    fn stray_closer_in_case(&self) -> bool {
        use Kw::*;
        if !matches!(self.peek(), Tok::Kw(EndIf | EndFor | EndWhile | EndRepeat)) {
            return false;
        }
        let next = if *self.peek_at(1) == Tok::Semi { 2 } else { 1 };
        matches!(self.peek_at(next), Tok::Kw(EndCase)) || self.looks_like_case_label_at(next)
    }

    fn looks_like_case_label(&self) -> bool {
        self.looks_like_case_label_at(0)
    }

    fn looks_like_case_label_at(&self, from: usize) -> bool {
        let mut i = from;
        if matches!(self.peek_at(0), Tok::Minus | Tok::Plus) {
            i += 1;
        }
        match self.peek_at(i) {
            Tok::Int(_) | Tok::Kw(Kw::True | Kw::False) => return true,
            Tok::TypePrefix => return true,
            // `'0':` on a CHAR selector (edition 3: a CHAR literal is written `'0'`)
            Tok::Str(..) => {
                return matches!(self.peek_at(i + 1), Tok::Colon | Tok::Comma | Tok::DotDot)
            }
            Tok::Ident => {}
            Tok::LParen => return self.constant_expression_label_at(i),
            _ => return false,
        }
        let first = i;
        i += 1;
        while *self.peek_at(i) == Tok::Dot && *self.peek_at(i + 1) == Tok::Ident {
            i += 2;
        }
        matches!(self.peek_at(i), Tok::Colon | Tok::Comma | Tok::DotDot)
            || self.constant_expression_label_at(first)
    }

    /// Whether the tokens from `from` are a constant expression ending at a CASE label's `:`
    /// (`ST_RUN + ST_ERR:`, `(N * 2) + 1:`; edition 3: Case_List_Elem is a Subrange or a
    /// Constant_Expr): names, numbers, arithmetic and parentheses only, then `:` before any `;`,
    /// `:=` or keyword (a statement never holds a lone `:`).
    fn constant_expression_label_at(&self, from: usize) -> bool {
        let mut depth = 0usize;
        let mut operator = false;
        for i in from..from + 64 {
            match self.peek_at(i) {
                Tok::Ident | Tok::Int(_) | Tok::Real(_) | Tok::TypePrefix | Tok::Dot => {}
                Tok::Plus | Tok::Minus | Tok::Star | Tok::Slash | Tok::Kw(Kw::Mod) => {
                    operator = true
                }
                Tok::LParen => depth += 1,
                Tok::RParen if depth > 0 => depth -= 1,
                Tok::Comma | Tok::DotDot if depth == 0 => {}
                Tok::Colon => return depth == 0 && operator,
                _ => return false,
            }
        }
        false
    }

    fn statement(&mut self) -> Option<Stmt> {
        let start = self.cur().range.start;
        if self.depth > MAX_DEPTH {
            self.error_here(
                code::E0108,
                "statements are nested too deeply",
                "split the logic into functions or function blocks",
            );
            while !self.at(&Tok::Eof) {
                self.bump();
            }
            return None;
        }
        let kind = match self.peek().clone() {
            Tok::Semi => {
                self.bump();
                return Some(Stmt {
                    kind: StmtKind::Empty,
                    span: self.span(start, self.prev_end()),
                });
            }
            Tok::Kw(Kw::If) => self.if_stmt(),
            Tok::Kw(Kw::Case) => self.case_stmt(),
            Tok::Kw(Kw::For) => self.for_stmt(),
            Tok::Kw(Kw::While) => self.while_stmt(),
            Tok::Kw(Kw::Repeat) => self.repeat_stmt(),
            Tok::Kw(Kw::Exit) => {
                self.bump();
                Some(StmtKind::Exit)
            }
            Tok::Kw(Kw::Continue) => {
                self.bump();
                Some(StmtKind::Continue)
            }
            Tok::Kw(Kw::Return) => {
                self.bump();
                if self.at(&Tok::LParen) {
                    // `RETURN (xIsDone);` (CODESYS, TwinCAT: a conditional return), also with an
                    // ExST assignment, `RETURN(bInit := fT <= 0);`: `IF cond THEN RETURN; END_IF`
                    let cond = self.expr();
                    let span = self.span(start, self.prev_end());
                    return_if(cond, span)
                } else {
                    Some(StmtKind::Return)
                }
            }
            Tok::Ident if self.try_word() == Some("__TRY") => self.try_stmt(),
            // `FUNCTION Add : INT ... END_FUNCTION` written inside another POU's body (some
            // simulators' dialects): one error, the nested text skipped to its end
            Tok::Ident
                if matches!(self.peek_at(1), Tok::Ident)
                    && ["FUNCTION", "FUNCTION_BLOCK", "PROGRAM"]
                        .iter()
                        .any(|k| self.text(self.cur()).eq_ignore_ascii_case(k)) =>
            {
                return self.nested_pou(start);
            }
            // `VAR_TEMP k : REAL; END_VAR` written among the statements: one error, the block
            // skipped to its END_VAR (before: one error per declaration line, one at END_VAR and
            // a false W1426 for `k : REAL;` read as a jump label)
            Tok::Ident
                if !matches!(
                    self.peek_at(1),
                    Tok::Assign | Tok::LParen | Tok::Dot | Tok::LBracket | Tok::Caret | Tok::Colon
                ) && is_var_keyword(self.text(self.cur())) =>
            {
                return self.decl_block_in_body(start);
            }
            // `START:` (a jump label, CODESYS and TwinCAT): a statement of its own, no `;`
            Tok::Ident if matches!(self.peek_at(1), Tok::Colon) => {
                let label = self.ident(self.cur());
                self.bump();
                self.bump();
                return Some(Stmt {
                    kind: StmtKind::Label(label),
                    span: self.span(start, self.prev_end()),
                });
            }
            // `JMP START;` (CODESYS and TwinCAT)
            Tok::Ident
                if self.text(self.cur()).eq_ignore_ascii_case("JMP")
                    && matches!(self.peek_at(1), Tok::Ident) =>
            {
                self.bump();
                let label = self.ident(self.cur());
                self.bump();
                Some(StmtKind::Jump(label))
            }
            Tok::Ident | Tok::Address(..) => self.assign_or_call(),
            // `.x := ...;`, `.GVL.x := ...;` (CODESYS, TwinCAT: the global namespace operator)
            Tok::Dot if matches!(self.peek_at(1), Tok::Ident) => self.assign_or_call(),
            Tok::Error => {
                self.sync();
                return None;
            }
            // `1:` / `1, 2:` / `1..3:` where a statement should be: the labels of a CASE whose
            // `CASE x OF` line is missing. One error; the labels and their statements up to the
            // `END_CASE` are skipped (each label would be one more error, END_CASE another)
            Tok::Int(_) | Tok::TypePrefix
                if matches!(self.peek_at(1), Tok::Colon | Tok::Comma | Tok::DotDot) =>
            {
                self.error_here(
                    code::E0100,
                    "a CASE label outside a CASE statement",
                    "write `CASE <selector> OF` before the first label",
                );
                while !matches!(self.peek(), Tok::Eof | Tok::Kw(Kw::EndCase)) {
                    self.bump();
                }
                if self.at(&Tok::Kw(Kw::EndCase)) {
                    self.bump();
                    if self.at(&Tok::Semi) {
                        self.bump();
                    }
                }
                return None;
            }
            _ => {
                let found = self.describe_current();
                self.error_here(
                    code::E0100,
                    format!("expected a statement, found {found}"),
                    "a statement is an assignment `x := ...;`, a call `inst(...);`, IF, CASE, FOR, WHILE, REPEAT, EXIT or RETURN",
                );
                self.bump();
                self.sync();
                return None;
            }
        };
        let Some(kind) = kind else {
            self.sync();
            return None;
        };
        let block = matches!(
            kind,
            StmtKind::If { .. }
                | StmtKind::Case { .. }
                | StmtKind::For { .. }
                | StmtKind::While { .. }
                | StmtKind::Repeat { .. }
        );
        if self.at(&Tok::Semi) {
            self.bump();
        } else if self.at(&Tok::Error) {
            // The lexer reported the bad text: the statement is dropped with it.
            self.sync();
            return None;
        } else if !block {
            // `END_IF` without `;` is accepted (CODESYS and Beremiz accept it too).
            let at = self.prev_end();
            let found = self.describe_current();
            self.error_at(
                code::E0104,
                self.span(at, at),
                format!("missing `;` after the statement (found {found})"),
                "every ST statement ends with `;` (also `END_IF;`, `END_FOR;` ...)",
            );
            // what follows is no statement (`RETURN TRUE;`): skipped with this one error
            if !ends_list(self.peek())
                && !starts_statement(self.peek())
                && !matches!(self.peek(), Tok::Ident | Tok::Address(..))
            {
                self.sync();
            }
        }
        Some(Stmt {
            kind,
            span: self.span(start, self.prev_end()),
        })
    }

    /// A POU declared inside a body, its keyword the current token: one E0106 at the keyword,
    /// then every token up to its `END_...` (or the end of the text) skipped; an empty statement.
    fn decl_block_in_body(&mut self, start: usize) -> Option<Stmt> {
        let kw = self.text(self.cur()).to_ascii_uppercase();
        self.error_here(
            code::E0106,
            format!("a declaration block `{kw} ... END_VAR` after the statements"),
            "IEC 61131-3 writes a POU's declarations before its body (CODESYS and TwinCAT too): move the block before the first statement",
        );
        while !self.at(&Tok::Eof) {
            let t = self.bump();
            if self.text(&t).eq_ignore_ascii_case("END_VAR") {
                break;
            }
        }
        if self.at(&Tok::Semi) {
            self.bump();
        }
        Some(Stmt {
            kind: StmtKind::Empty,
            span: self.span(start, self.prev_end()),
        })
    }

    fn nested_pou(&mut self, start: usize) -> Option<Stmt> {
        let kw = self.text(self.cur()).to_ascii_uppercase();
        let name = self
            .text(&self.toks[(self.pos + 1).min(self.toks.len() - 1)])
            .to_string();
        self.error_here(
            code::E0106,
            format!("{kw} `{name}` is declared inside another POU's body"),
            "IEC 61131-3 declares POUs one after the other: close the POU before it (its END_PROGRAM, END_FUNCTION_BLOCK or END_FUNCTION), or move this one after that end",
        );
        let end = format!("END_{kw}");
        while !self.at(&Tok::Eof) {
            let t = self.bump();
            if self.text(&t).eq_ignore_ascii_case(&end) {
                break;
            }
        }
        if self.at(&Tok::Semi) {
            self.bump();
        }
        Some(Stmt {
            kind: StmtKind::Empty,
            span: self.span(start, self.prev_end()),
        })
    }

    /// Whether the tokens from the current one are a place followed by `:=` (the `b :=` of
    /// `a := b := e;`); looks at most [`MAX_PLACE_LOOKAHEAD`] tokens ahead.
    fn at_place_then_assign(&self) -> bool {
        if !matches!(self.peek(), Tok::Ident | Tok::Address(..)) {
            return false;
        }
        let mut depth = 0usize;
        for i in 1..MAX_PLACE_LOOKAHEAD {
            match self.peek_at(i) {
                Tok::Assign if depth == 0 => return true,
                Tok::LBracket => depth += 1,
                Tok::RBracket if depth > 0 => depth -= 1,
                Tok::Dot | Tok::Caret | Tok::Ident | Tok::Int(_) => {}
                Tok::Semi | Tok::Eof | Tok::Assign => return false,
                _ if depth > 0 => {}
                _ => return false,
            }
        }
        false
    }

    /// Whether the current token is the `S` or `R` of an ExST set or reset assignment (`S=`, `R=`).
    fn at_set_reset(&self) -> bool {
        self.set_reset_at(0).is_some()
    }

    /// `Some(true)` for `S=`, `Some(false)` for `R=` at `n` tokens from the current one.
    fn set_reset_at(&self, n: usize) -> Option<bool> {
        let k = (self.pos + n).min(self.toks.len() - 1);
        let t = &self.toks[k];
        if t.tok != Tok::Ident || *self.peek_at(n + 1) != Tok::Eq {
            return None;
        }
        let text = self.text(t);
        if text.eq_ignore_ascii_case("S") {
            Some(true)
        } else if text.eq_ignore_ascii_case("R") {
            Some(false)
        } else {
            None
        }
    }

    /// Whether the tokens from the current one are a place followed by `S=` or `R=` (the `b R=`
    /// of `a S= b R= c;`); looks at most [`MAX_PLACE_LOOKAHEAD`] tokens ahead.
    fn at_place_then_set_reset(&self) -> bool {
        if !matches!(self.peek(), Tok::Ident | Tok::Address(..)) {
            return false;
        }
        let mut depth = 0usize;
        for i in 1..MAX_PLACE_LOOKAHEAD {
            match self.peek_at(i) {
                Tok::Ident if depth == 0 && self.set_reset_at(i).is_some() => return true,
                Tok::LBracket => depth += 1,
                Tok::RBracket if depth > 0 => depth -= 1,
                Tok::Dot | Tok::Caret | Tok::Int(_) => {}
                Tok::Ident if depth == 0 && matches!(self.peek_at(i - 1), Tok::Dot) => {}
                Tok::Semi | Tok::Eof => return false,
                _ if depth > 0 => {}
                _ => return false,
            }
        }
        false
    }

    /// `a S= b R= c;` from its `S`/`R` (CODESYS and TwinCAT ExST, Infosys "ExST assignment S=" /
    /// "R="): every place of the chain takes the operand at the end of the line, which is
    /// evaluated once: a place after `S=` becomes TRUE when it is TRUE, one after `R=` FALSE;
    /// when it is FALSE nothing is written. Read as `IF c THEN b := FALSE; a := TRUE; END_IF`
    /// (the innermost assignment first, as `a := b := e` is read).
    fn set_reset_assign(&mut self, target: Place) -> Option<StmtKind> {
        let mut chain = Vec::new();
        let mut place = target;
        loop {
            let set = self.set_reset_at(0)?;
            self.bump();
            self.bump();
            chain.push((place, set));
            if chain.len() >= MAX_ASSIGN_CHAIN || !self.at_place_then_set_reset() {
                break;
            }
            place = self.place()?;
        }
        let cond = self.expr();
        if matches!(cond.kind, ExprKind::Error) {
            return None;
        }
        let start = chain.first().map_or(cond.span, |(p, _)| p.span);
        let span = start.to(cond.span);
        let body = chain
            .into_iter()
            .rev()
            .map(|(target, set)| {
                let value = Expr {
                    kind: ExprKind::Literal(Literal {
                        kind: LiteralKind::Bool(set),
                        type_prefix: None,
                        span: target.span,
                    }),
                    span: target.span,
                };
                Stmt {
                    span: target.span.to(cond.span),
                    kind: StmtKind::Assign { target, value },
                }
            })
            .collect();
        Some(StmtKind::If {
            branches: vec![CondBranch { cond, body, span }],
            else_body: None,
        })
    }

    /// `x := e`, `inst(...)`, `F(...)`; anything else that starts with a name is reported here.
    fn assign_or_call(&mut self) -> Option<StmtKind> {
        let target = self.place()?;
        match self.peek() {
            Tok::Assign => {
                self.bump();
                // `a := b := e;`: ExST's assignment as an expression (CODESYS, TwinCAT: "int_var1 and
                // int_var2 receive the value of int_var3 + 9"), read as `b := e; a := b;`
                let mut chain = vec![target];
                while chain.len() < MAX_ASSIGN_CHAIN && self.at_place_then_assign() {
                    let place = self.place()?;
                    self.bump();
                    chain.push(place);
                }
                let mut value = self.expr();
                if matches!(value.kind, ExprKind::Error) {
                    return None;
                }
                let mut target = chain.pop()?;
                while let Some(outer) = chain.pop() {
                    let span = target.span.to(value.span);
                    let read = Expr {
                        span: target.span,
                        kind: ExprKind::Place(target.clone()),
                    };
                    self.hoisted.push(Stmt {
                        kind: StmtKind::Assign { target, value },
                        span,
                    });
                    (target, value) = (outer, read);
                }
                Some(StmtKind::Assign { target, value })
            }
            // `r ?= e;` (IEC 61131-3 ed. 3, 6.6.6.7 assignment attempt; SIMATIC AX): `r`, an
            // interface or a reference to a class or block, takes `e` when the instance `e`
            // holds fits, else NULL (`super::interface_vars::ATTEMPT`)
            Tok::AttemptAssign => {
                let op = self.bump();
                let value = self.expr();
                if matches!(value.kind, ExprKind::Error) {
                    return None;
                }
                let span = self.span(op.range.start, self.prev_end());
                Some(reference_assign(
                    target,
                    super::interface_vars::ATTEMPT,
                    value,
                    span,
                ))
            }
            Tok::LParen => {
                let args = self.args()?;
                Some(StmtKind::Call {
                    callee: target,
                    args,
                })
            }
            // `x S= c;`, `x R= c;`, `a S= b R= c;` (CODESYS, TwinCAT ExST set and reset
            // assignments)
            Tok::Ident if self.at_set_reset() => self.set_reset_assign(target),
            // `r REF= x` (CODESYS, TwinCAT): `r`, a REFERENCE TO, now refers to `x` (lowered by
            // `PouLowering`, see `super::refs::REF_ASSIGN`)
            Tok::Ident if self.ident(self.cur()).is("REF") && *self.peek_at(1) == Tok::Eq => {
                let op = self.bump();
                self.bump();
                let value = self.expr();
                if matches!(value.kind, ExprKind::Error) {
                    return None;
                }
                let span = self.span(op.range.start, self.prev_end());
                Some(reference_assign(
                    target,
                    super::refs::REF_ASSIGN,
                    value,
                    span,
                ))
            }
            // `r ACCESS ADR(x)` (B&R Automation Studio's dynamic variables): `r`, a REFERENCE TO,
            // now refers to the address given: `r REF= x` for `ADR(x)`, else the address itself
            // (`r ACCESS (ADR(r) + 1)`, see `super::refs::ACCESS_ASSIGN`)
            Tok::Ident
                if self.ident(self.cur()).is("ACCESS")
                    && !matches!(self.peek_at(1), Tok::Semi | Tok::Eof) =>
            {
                let op = self.bump();
                let value = self.expr();
                if matches!(value.kind, ExprKind::Error) {
                    return None;
                }
                let span = self.span(op.range.start, self.prev_end());
                let (callee, value) = match &value.kind {
                    ExprKind::Call { name, args }
                        if (name.is("ADR") || name.is("REF"))
                            && args.len() == 1
                            && args[0].name.is_none()
                            && matches!(args[0].value.kind, ExprKind::Place(_)) =>
                    {
                        (super::refs::REF_ASSIGN, args[0].value.clone())
                    }
                    _ => (super::refs::ACCESS_ASSIGN, value),
                };
                Some(reference_assign(target, callee, value, span))
            }
            Tok::Eq => {
                self.error_here(
                    code::E0106,
                    "`=` compares; it does not assign",
                    "assign with `:=` (`x := 1;`)",
                );
                None
            }
            // a name an error was just reported at, read again as a statement when recovery found
            // nothing else before the end of the text (a file cut off in `IF (a AN`): no second error
            Tok::Eof
                if self
                    .last_error
                    .is_some_and(|(_, span)| span.start == target.span.start) =>
            {
                None
            }
            // `bExecute;` (CODESYS, TwinCAT: "the code has no effect", C0139): a warning, the
            // statement does nothing (only where a statement begins: after `;`, a keyword or at
            // the start; `x : T;` read as statements after an error stays an error)
            Tok::Semi if self.starts_statement(&target) => {
                self.diags.push(
                    Diagnostic::warning(
                        code::W1431,
                        format!("`{};` has no effect: it names a value and does nothing with it", self.place_text(&target)),
                    )
                    .at(target.span)
                    .with_primary_label("no assignment, no call")
                    .with_hint("assign it (`y := x;`), call it (`inst();`), or delete the statement (CODESYS and TwinCAT compile it with the same message)"),
                );
                Some(StmtKind::Named(target))
            }
            _ => {
                let found = self.describe_current();
                self.error_here(
                    code::E0106,
                    format!("expected `:=` or `(` after `{}`, found {found}", self.place_text(&target)),
                    "a statement that starts with a name is an assignment `x := ...;` or a call `inst(...);`",
                );
                None
            }
        }
    }

    /// Whether `p` begins where a statement begins: the first token, one after `;` or a keyword
    /// (`THEN`, `ELSE`, `DO`, `END_IF` ...), or the first of a CASE branch's statements (after the
    /// `:` of its labels: IEC 61131-3 ed. 3 7.3.3.3.3, `case_element: case_list ':' stmt_list`).
    fn starts_statement(&self, p: &Place) -> bool {
        let start = (p.span.start as usize).saturating_sub(self.base);
        let Some(k) = self.toks.iter().position(|t| t.range.start == start) else {
            return false;
        };
        k == 0 || k == self.arm_start || matches!(self.toks[k - 1].tok, Tok::Semi | Tok::Kw(_))
    }

    fn place_text(&self, p: &Place) -> &'s str {
        let s = (p.span.start as usize).saturating_sub(self.base);
        let e = (p.span.end as usize).saturating_sub(self.base);
        self.src.get(s..e).unwrap_or("")
    }

    fn block_open(&mut self) -> Option<(Token, Span)> {
        let t = self.bump();
        let span = self.span(t.range.start, t.range.end);
        if self.depth > MAX_DEPTH {
            return None;
        }
        Some((t, span))
    }

    /// Reports a block that is not closed by `end` (at its opening keyword) unless `end` is next.
    fn close_block(&mut self, end: Kw, open: Span, what: &str) -> bool {
        if self.at_kw(end) {
            self.bump();
            return true;
        }
        let found = self.describe_current();
        self.push_error(
            Diagnostic::error(
                code::E0105,
                format!(
                    "{what} is not closed: expected `{}`, found {found}",
                    end.spelling()
                ),
            )
            .at(self.cur_span())
            .with_label(open, format!("this {what} needs `{}`", end.spelling()))
            .with_hint(format!("close the block with `{};`", end.spelling())),
        );
        false
    }

    fn nested<T>(&mut self, f: impl FnOnce(&mut Self) -> T) -> T {
        self.depth += 1;
        let r = f(self);
        self.depth -= 1;
        r
    }

    fn if_stmt(&mut self) -> Option<StmtKind> {
        let (_, open) = self.block_open()?;
        let mut branches = Vec::new();
        let mut else_body = None;
        let mut bstart = open;
        let mut first = true;
        // the ExST assignments of each ELSIF condition (`exst::nest_elsif`)
        let mut setups: Vec<Vec<Stmt>> = Vec::new();
        loop {
            // (an ELSIF condition is evaluated only when the ones before are FALSE)
            let cond = if first {
                // `IF b := (i = 1) THEN` (ExST): `b := (i = 1);` runs before the IF, which tests `b`
                self.assigned_condition()
            } else {
                // (its assignments run only when the conditions before are FALSE: `exst`)
                let (cond, setup) = self.late_condition();
                setups.push(setup);
                cond
            };
            if first {
                setups.push(Vec::new());
            }
            first = false;
            if !self.expect_kw(Kw::Then, "after the IF condition") {
                // Garbage before a THEN on the same statement is skipped; without THEN the body
                // starts right here (`IF a x := 1;` keeps `x := 1`).
                let mut k = 0;
                loop {
                    match self.peek_at(k) {
                        Tok::Kw(Kw::Then) => {
                            for _ in 0..=k {
                                self.bump();
                            }
                            break;
                        }
                        t if *t == Tok::Semi || ends_list(t) => break,
                        _ => k += 1,
                    }
                }
            }
            let body = self.nested(|p| p.statement_list());
            branches.push(CondBranch {
                cond,
                body,
                span: bstart.to(self.span(self.prev_end(), self.prev_end())),
            });
            if self.at_kw(Kw::Elsif) {
                bstart = self.cur_span();
                self.bump();
                continue;
            }
            if self.at_kw(Kw::Else) {
                self.bump();
                else_body = Some(self.nested(|p| p.statement_list()));
            }
            break;
        }
        self.close_block(Kw::EndIf, open, "IF");
        let (branches, else_body) =
            exst::nest_elsif(branches.into_iter().zip(setups).collect(), else_body);
        Some(StmtKind::If {
            branches,
            else_body,
        })
    }

    fn case_stmt(&mut self) -> Option<StmtKind> {
        let (_, open) = self.block_open()?;
        let selector = self.expr();
        self.expect_kw(Kw::Of, "after the CASE selector");
        let mut arms = Vec::new();
        let mut else_body = None;
        loop {
            if self.at_kw(Kw::Else) {
                self.bump();
                else_body = Some(self.nested(|p| p.statement_list()));
                break;
            }
            if ends_list(self.peek()) {
                break;
            }
            if !self.looks_like_case_label() {
                let found = self.describe_current();
                self.error_here(
                    code::E0100,
                    format!(
                        "expected a CASE label such as `1:`, `2, 3:` or `4..6:`, found {found}"
                    ),
                    "each branch of CASE starts with its values and `:`",
                );
                self.bump();
                self.sync();
                continue;
            }
            let astart = self.cur_span();
            let mut labels = Vec::new();
            loop {
                let lo = self.binary(5);
                if self.at(&Tok::DotDot) {
                    self.bump();
                    let hi = self.binary(5);
                    labels.push(CaseLabel::Range(lo, hi));
                } else {
                    labels.push(CaseLabel::Value(lo));
                }
                if self.at(&Tok::Comma) {
                    self.bump();
                    continue;
                }
                break;
            }
            if self.at(&Tok::Colon) {
                self.bump();
            } else {
                let found = self.describe_current();
                self.error_here(
                    code::E0100,
                    format!("expected `:` after the CASE label, found {found}"),
                    "write the branch as `1, 2: statements`",
                );
                self.sync();
            }
            self.arm_start = self.pos;
            let body = self.nested(|p| p.case_arm_body());
            arms.push(CaseArm {
                labels,
                body,
                span: astart.to(self.span(self.prev_end(), self.prev_end())),
            });
        }
        self.close_block(Kw::EndCase, open, "CASE");
        Some(StmtKind::Case {
            selector,
            arms,
            else_body,
        })
    }

    fn for_stmt(&mut self) -> Option<StmtKind> {
        let (_, open) = self.block_open()?;
        if !self.at(&Tok::Ident) {
            let found = self.describe_current();
            self.error_here(
                code::E0100,
                format!("expected the control variable after FOR, found {found}"),
                "write `FOR i := 1 TO 10 DO ... END_FOR;`",
            );
            return None;
        }
        // `FOR Offset[1] := ...`, `FOR st.i := ...` (CODESYS, TwinCAT): an element or member
        // counts (see `lower::for_control`)
        let (control, element) = if matches!(self.peek_at(1), Tok::LBracket | Tok::Dot | Tok::Caret)
        {
            let p = self.place()?;
            let PlaceBase::Name(n) = &p.base else {
                return None;
            };
            (n.clone(), Some(p))
        } else {
            let t = self.bump();
            (self.ident(&t), None)
        };
        if !self.at(&Tok::Assign) {
            let found = self.describe_current();
            self.error_here(
                code::E0100,
                format!("expected `:=` after the FOR control variable, found {found}"),
                "write `FOR i := 1 TO 10 DO ... END_FOR;`",
            );
            return self.abandoned_for(open);
        }
        self.bump();
        let from = self.expr();
        if !self.expect_kw(Kw::To, "after the FOR start value") {
            return self.abandoned_for(open);
        }
        let to = self.expr();
        let by = if self.at_kw(Kw::By) {
            self.bump();
            Some(self.expr())
        } else {
            None
        };
        if !self.expect_kw(Kw::Do, "before the FOR loop body") {
            return None;
        }
        let body = self.nested(|p| p.statement_list());
        self.close_block(Kw::EndFor, open, "FOR");
        Some(StmtKind::For {
            control,
            element,
            from,
            to,
            by,
            body,
        })
    }

    /// A FOR whose header is wrong (already reported): the rest of the header is skipped up to its
    /// `DO`, the body read (its own errors reported) up to `END_FOR`, so that the loop's end is no
    /// second error; an empty statement. Without a `DO` before the next `;`, nothing more is read.
    fn abandoned_for(&mut self, open: Span) -> Option<StmtKind> {
        while !self.at_kw(Kw::Do)
            && !self.at_kw(Kw::EndFor)
            && !matches!(self.peek(), Tok::Semi | Tok::Eof)
        {
            self.bump();
        }
        if !self.at_kw(Kw::Do) {
            return None;
        }
        self.bump();
        let _ = self.nested(|p| p.statement_list());
        self.close_block(Kw::EndFor, open, "FOR");
        Some(StmtKind::Empty)
    }

    /// Whether a condition starts with a well-formed place and `:=` (`b :=`, `st.x :=`, `a[i] :=`,
    /// `p^ :=`); stricter than [`Self::at_place_then_assign`], so that `IF a x := 5;` (THEN
    /// missing) still recovers at `x`.
    fn at_condition_assignment(&self) -> bool {
        if !matches!(self.peek(), Tok::Ident) {
            return false;
        }
        let mut i = 1;
        while i < MAX_PLACE_LOOKAHEAD {
            match self.peek_at(i) {
                Tok::Assign => return true,
                Tok::Dot if *self.peek_at(i + 1) == Tok::Ident => i += 2,
                Tok::Caret => i += 1,
                Tok::LBracket => {
                    let mut depth = 0usize;
                    while i < MAX_PLACE_LOOKAHEAD {
                        match self.peek_at(i) {
                            Tok::LBracket => depth += 1,
                            Tok::RBracket => {
                                depth -= 1;
                                if depth == 0 {
                                    break;
                                }
                            }
                            Tok::Semi | Tok::Eof | Tok::Assign => return false,
                            _ => {}
                        }
                        i += 1;
                    }
                    i += 1;
                }
                _ => return false,
            }
        }
        false
    }

    /// `b := e` at the start of a condition, as CODESYS/TwinCAT ExST allow it ("assignment as an
    /// expression": its value is the value assigned): the place and the value; `None` (nothing read)
    /// when the condition is no assignment.
    fn condition_assignment(&mut self) -> Option<(Place, Expr)> {
        if !self.at_condition_assignment() {
            return None;
        }
        let target = self.place()?;
        self.bump();
        let value = self.expr();
        Some((target, value))
    }

    fn while_stmt(&mut self) -> Option<StmtKind> {
        let (_, open) = self.block_open()?;
        let (cond, setup) = self.late_condition();
        if !self.expect_kw(Kw::Do, "after the WHILE condition") {
            return None;
        }
        let body = self.nested(|p| p.statement_list());
        self.close_block(Kw::EndWhile, open, "WHILE");
        if !setup.is_empty() {
            // `WHILE b := e DO`, `WHILE (c := c - 1) > 0 DO` (ExST): the assignment runs at each test
            return Some(exst::while_with_setup(cond, setup, body));
        }
        Some(StmtKind::While { cond, body })
    }

    fn repeat_stmt(&mut self) -> Option<StmtKind> {
        let (_, open) = self.block_open()?;
        let body = self.nested(|p| p.statement_list());
        if !self.at_kw(Kw::Until) {
            self.close_block(Kw::Until, open, "REPEAT");
            return Some(StmtKind::Repeat {
                body,
                setup: Vec::new(),
                until: Expr {
                    kind: ExprKind::Error,
                    span: open,
                },
            });
        }
        self.bump();
        // `UNTIL (n := n + 1) >= 10` (ExST): the assignment runs before each test (`exst`)
        let (until, setup) = self.late_condition();
        self.close_block(Kw::EndRepeat, open, "REPEAT");
        Some(StmtKind::Repeat { body, setup, until })
    }

    // ------------------------------------------------------------ places and calls

    /// `inst.M(args)` inside an expression: a call of method `M` (edition 3). The call becomes a
    /// statement before the current one, and the expression reads the method's result
    /// `inst.__M_M`. Where the statement cannot run it first (a WHILE, UNTIL or ELSIF condition,
    /// the right operand of AND_THEN / OR_ELSE), or when the statement calls the same method of
    /// the same instance twice (both would read one result), the call stays in the expression
    /// ([`super::lower::method_call_expr`]) and the lowering places it.
    fn method_call_expr(&mut self, callee: Place, m: Ident) -> Expr {
        let here = callee.span;
        let Some(args) = self.args() else {
            return self.error_expr(here);
        };
        let span = here.to(self.span(self.prev_end(), self.prev_end()));
        let text = |p: &Place| {
            self.src
                .get(p.span.start as usize - self.base..p.span.end as usize - self.base)
                .map(|t| t.to_ascii_uppercase().replace(' ', ""))
        };
        let twice = self.hoisted.iter().any(
            |s| matches!(&s.kind, StmtKind::Call { callee: c, .. } if text(c) == text(&callee)),
        );
        let chain = callee
            .accessors
            .iter()
            .any(|a| matches!(a, Accessor::Call { .. }));
        if self.no_hoist > 0 || twice || chain {
            // left in the expression: the lowering runs it where the source evaluates it
            // (`super::lower::method_flow`)
            return super::lower::method_call_expr(callee, args, span);
        }
        let mut result = callee.clone();
        if let Some(last) = result.accessors.last_mut() {
            *last = Accessor::Field(Ident::new(crate::actions::method_result(&m.name), m.span));
        }
        self.hoisted.push(Stmt {
            kind: StmtKind::Call { callee, args },
            span,
        });
        Expr {
            kind: ExprKind::Place(result),
            span,
        }
    }

    /// `x`, `a.b[i, j].c`, `%QX0.1`.
    fn place(&mut self) -> Option<Place> {
        let t = self.bump();
        let start = t.range.start;
        let base = match t.tok {
            // `THIS^.x`, `THIS^.M(...)` inside a function block or its method (CODESYS, TwinCAT):
            // the block's own variable or method, as `x` and `M(...)`
            Tok::Ident
                if self.ident(&t).is("THIS")
                    && *self.peek() == Tok::Caret
                    && *self.peek_at(1) == Tok::Dot
                    && *self.peek_at(2) == Tok::Ident =>
            {
                self.bump();
                self.bump();
                let f = self.bump();
                PlaceBase::Name(self.ident(&f))
            }
            // `THIS.x`, `THIS.M(...)`: edition 3's spelling of the same
            Tok::Ident
                if self.this_dot
                    && self.ident(&t).is("THIS")
                    && *self.peek() == Tok::Dot
                    && *self.peek_at(1) == Tok::Ident =>
            {
                self.bump();
                let f = self.bump();
                PlaceBase::Name(self.ident(&f))
            }
            // `.x`, `.GVL.x`: the global namespace operator (CODESYS "Operator: Global Namespace",
            // Beckhoff Infosys "Global namespace": "an instance path that starts with a dot .
            // always opens a global namespace"); the lowering resolves the marked name
            // (`crate::st::lower::global_ns`)
            Tok::Dot if *self.peek() == Tok::Ident => {
                let f = self.bump();
                let id = self.ident(&f);
                crate::st::lower::GLOBAL_NS_SEEN.store(true, std::sync::atomic::Ordering::Relaxed);
                PlaceBase::Name(Ident::new(
                    format!("{}{}", crate::st::lower::GLOBAL_NS, id.name),
                    self.span(start, f.range.end),
                ))
            }
            Tok::Ident => PlaceBase::Name(self.ident(&t)),
            Tok::Address(area, size, path) => PlaceBase::Address(DirectAddress {
                area,
                size,
                path,
                span: self.span(t.range.start, t.range.end),
            }),
            _ => return None,
        };
        let mut accessors = Vec::new();
        loop {
            match self.peek() {
                Tok::Dot => {
                    self.bump();
                    match self.peek() {
                        Tok::Ident => {
                            let f = self.bump();
                            accessors.push(Accessor::Field(self.ident(&f)));
                        }
                        // `s.Continue`, `cmd.Type` (B&R, CODESYS before edition 3): a keyword after
                        // `.` can only be a field's name
                        Tok::Kw(_) => {
                            let f = self.bump();
                            accessors.push(Accessor::Field(self.ident(&f)));
                        }
                        // `x.3`: a partial access (3rd edition), kept as the field `3` (see
                        // `ast::partial_access`; `x.%X3` comes as an identifier from the lexer)
                        Tok::Int(_) => {
                            let f = self.bump();
                            accessors.push(Accessor::Field(self.ident(&f)));
                        }
                        _ => {
                            let found = self.describe_current();
                            self.error_here(
                                code::E0100,
                                format!("expected a field name after `.`, found {found}"),
                                "write `instance.output` or `structure.field`",
                            );
                            return None;
                        }
                    }
                }
                Tok::LBracket => {
                    let t = self.bump();
                    self.count_operation(t.range.start, t.range.end);
                    let mut idx = vec![self.expr()];
                    while self.at(&Tok::Comma) {
                        self.bump();
                        idx.push(self.expr());
                    }
                    if !self.at(&Tok::RBracket) {
                        let found = self.describe_current();
                        self.error_here(
                            code::E0100,
                            format!("expected `]` after the array index, found {found}"),
                            "write the element as `a[i]` or `m[i, j]`",
                        );
                        return None;
                    }
                    self.bump();
                    accessors.push(Accessor::Index(idx));
                }
                Tok::Caret => {
                    // (in a block that EXTENDS another, `SUPER^` is rewritten before parsing:
                    // `super::inherit`)
                    if accessors.is_empty() && matches!(&base, PlaceBase::Name(n) if n.is("SUPER"))
                    {
                        self.error_here(
                            code::E0108,
                            "`SUPER^` in a POU that extends no function block",
                            "SUPER^ reaches the base of a block declared `FUNCTION_BLOCK Name EXTENDS Base`; use THIS^ (or nothing) for the block's own methods and variables",
                        );
                        return None;
                    }
                    let t = self.bump();
                    let derefs = accessors
                        .iter()
                        .filter(|a| matches!(a, Accessor::Deref(_)))
                        .count();
                    if derefs == crate::parser::MAX_TYPE_NESTING {
                        // as deep as references may nest (`st::refs`): bounds the generated C,
                        // which nests one call per `^`
                        self.error_at(
                            code::E0108,
                            self.span(t.range.start, t.range.end),
                            format!(
                                "more than {} `^` in one access",
                                crate::parser::MAX_TYPE_NESTING
                            ),
                            "references nest at most that deep: follow them in several statements",
                        );
                        return None;
                    }
                    accessors.push(Accessor::Deref(self.span(t.range.start, t.range.end)));
                }
                // `stack.Get(1).Pop`, `Get(1).Value`, `Next()^.x`: a call chain (CODESYS, TwinCAT)
                Tok::LParen
                    if matches!(accessors.last(), None | Some(Accessor::Field(_)))
                        && matches!(base, PlaceBase::Name(_))
                        && self.call_then_access(0) =>
                {
                    let open = self.cur().range.start;
                    let args = self.args()?;
                    let span = self.span(open, self.prev_end());
                    accessors.push(Accessor::Call { args, span });
                }
                _ => break,
            }
        }
        Some(Place {
            base,
            accessors,
            span: self.span(start, self.prev_end()),
        })
    }

    /// A call whose arguments are not read (`__NEW(POINTER TO T, n)`): its text up to the
    /// matching `)` is skipped, the call kept without arguments.
    fn skipped_call(&mut self, name: Ident, here: Span) -> Expr {
        let mut depth = 0usize;
        loop {
            match self.peek() {
                Tok::LParen => depth += 1,
                Tok::RParen => {
                    depth = depth.saturating_sub(1);
                    if depth == 0 {
                        self.bump();
                        break;
                    }
                }
                Tok::Semi | Tok::Eof => break,
                _ => {}
            }
            self.bump();
        }
        Expr {
            kind: ExprKind::Call {
                name,
                args: Vec::new(),
            },
            span: here.to(self.span(self.prev_end(), self.prev_end())),
        }
    }

    /// Whether the tokens from `n` on are `POINTER TO` or `REFERENCE TO` (a type, not a value).
    fn at_pointer_type(&self, n: usize) -> bool {
        let t = &self.toks[(self.pos + n).min(self.toks.len() - 1)];
        *self.peek_at(n + 1) == Tok::Kw(Kw::To)
            && t.tok == Tok::Ident
            && ["POINTER", "REFERENCE"]
                .iter()
                .any(|w| self.text(t).eq_ignore_ascii_case(w))
    }

    /// `SIZEOF(POINTER TO T)`, `SIZEOF(REFERENCE TO T)` (CODESYS, TwinCAT: SIZEOF's operand may be
    /// a data type): the size of an address, whatever `T`; read as `SIZEOF(LWORD)`, the 8 bytes of
    /// a pointer on ladderc's 64-bit target (its generated C's `sizeof(void *)`). `name` is read,
    /// the current token is `(`.
    fn sizeof_pointer_type(&mut self, name: Ident, here: Span) -> Expr {
        let open = self.bump();
        let at = self.cur().range.clone();
        let mut depth = 0usize;
        loop {
            match self.peek() {
                Tok::LParen | Tok::LBracket => depth += 1,
                Tok::RBracket => depth = depth.saturating_sub(1),
                Tok::RParen if depth == 0 => break,
                Tok::RParen => depth -= 1,
                Tok::Semi | Tok::Eof => break,
                _ => {}
            }
            self.bump();
        }
        let ty_span = self.span(at.start, self.prev_end().max(open.range.end));
        if self.at(&Tok::RParen) {
            self.bump();
        } else {
            let found = self.describe_current();
            self.error_here(
                code::E0100,
                format!("expected `)` after SIZEOF's type, found {found}"),
                "write `SIZEOF(POINTER TO INT)`",
            );
            return self.error_expr(here);
        }
        let value = Expr {
            kind: ExprKind::Place(Place {
                base: PlaceBase::Name(Ident::new("LWORD", ty_span)),
                accessors: Vec::new(),
                span: ty_span,
            }),
            span: ty_span,
        };
        Expr {
            kind: ExprKind::Call {
                name,
                args: vec![Arg {
                    name: None,
                    dir: ArgDir::Input,
                    value,
                    span: ty_span,
                }],
            },
            span: here.to(self.span(self.prev_end(), self.prev_end())),
        }
    }

    /// `( args )` after a call target.
    fn args(&mut self) -> Option<Vec<Arg>> {
        let open = self.bump();
        let mut args = Vec::new();
        if self.at(&Tok::RParen) {
            self.bump();
            return Some(args);
        }
        loop {
            let start = self.cur().range.start;
            let negated = self.at_kw(Kw::Not)
                && *self.peek_at(1) == Tok::Ident
                && *self.peek_at(2) == Tok::Arrow;
            if negated {
                self.bump();
            }
            // a keyword before `:=` or `=>` names a parameter (`blk(Type := 2)`: B&R's libraries
            // name inputs so, Automation Studio reserving only the upper-case words)
            if matches!(self.peek(), Tok::Ident | Tok::Kw(_))
                && matches!(self.peek_at(1), Tok::Assign | Tok::Arrow)
            {
                let n = self.bump();
                let name = self.ident(&n);
                let out = self.bump().tok == Tok::Arrow;
                if out {
                    let value = if self.at(&Tok::Ident) || matches!(self.peek(), Tok::Address(..)) {
                        let p = self.place()?;
                        Expr {
                            span: p.span,
                            kind: ExprKind::Place(p),
                        }
                    } else if self.at(&Tok::Comma) || self.at(&Tok::RParen) {
                        // `Q =>` with nothing: the output is not used.
                        let s = self.span(self.prev_end(), self.prev_end());
                        Expr {
                            kind: ExprKind::Error,
                            span: s,
                        }
                    } else {
                        let found = self.describe_current();
                        self.error_here(
                            code::E0100,
                            format!("expected a variable after `=>`, found {found}"),
                            "an output is stored into a variable: `Q => done`",
                        );
                        return None;
                    };
                    args.push(Arg {
                        name: Some(name),
                        dir: ArgDir::Output { negated },
                        value,
                        span: self.span(start, self.prev_end()),
                    });
                } else if self.at(&Tok::Comma) || self.at(&Tok::RParen) {
                    // `IN :=` with nothing (TwinCAT and CODESYS accept it, as their editors write
                    // an unconnected input): the input is left out of the call, so it keeps its
                    // value in a block's instance and takes its initial value in a function's
                    // call, as IEC 61131-3 ed. 3 (6.6.1.4.2) has an unassigned input do
                } else {
                    let value = self.expr();
                    args.push(Arg {
                        name: Some(name),
                        dir: ArgDir::Input,
                        value,
                        span: self.span(start, self.prev_end()),
                    });
                }
            } else {
                let value = self.expr();
                args.push(Arg {
                    name: None,
                    dir: ArgDir::Input,
                    value,
                    span: self.span(start, self.prev_end()),
                });
            }
            match self.peek() {
                Tok::Comma => {
                    self.bump();
                    if !args.is_empty() && self.at(&Tok::RParen) {
                        // `fb(a := x, q => y, )`, `f(a, b, )`: a comma after the last argument,
                        // formal or not, as TwinCAT accepts it (its editor leaves one after a
                        // removed pin; Beckhoff's own samples write `ADSLOGSTR(t, 'm', 'a',)`)
                        self.bump();
                        return Some(args);
                    }
                }
                Tok::RParen => {
                    self.bump();
                    return Some(args);
                }
                _ => {
                    let found = self.describe_current();
                    let open_span = self.span(open.range.start, open.range.end);
                    self.diags.push(
                        Diagnostic::error(
                            code::E0100,
                            format!("expected `,` or `)` in the argument list, found {found}"),
                        )
                        .at(self.cur_span())
                        .with_label(open_span, "the argument list starts here")
                        .with_hint("separate arguments with `,` and close the list with `)`"),
                    );
                    return None;
                }
            }
        }
    }

    // ------------------------------------------------------------ expressions

    fn error_expr(&self, span: Span) -> Expr {
        Expr {
            kind: ExprKind::Error,
            span,
        }
    }

    pub(crate) fn expr(&mut self) -> Expr {
        if self.depth > MAX_DEPTH {
            let s = self.cur_span();
            self.error_here(
                code::E0108,
                "expression is nested too deeply",
                "split it into several assignments",
            );
            while !self.at(&Tok::Eof) {
                self.bump();
            }
            return self.error_expr(s);
        }
        if self.expr_level == 0 {
            self.operations = 0;
            self.expr_start = self.cur().range.start;
        }
        self.expr_level += 1;
        self.depth += 1;
        let e = self.binary(0);
        self.depth -= 1;
        self.expr_level -= 1;
        e
    }

    /// Counts the operation whose token (operator, function name, `[`) was just read at `start..end`;
    /// E0109 once per expression when it is one more than [`MAX_EXPRESSION_OPERATIONS`]. Outside an
    /// expression (the index of an assignment's target) nothing is counted: its index expressions count
    /// for themselves.
    fn count_operation(&mut self, start: usize, end: usize) {
        if self.expr_level == 0 {
            return;
        }
        self.operations += 1;
        if self.operations != MAX_EXPRESSION_OPERATIONS + 1 {
            return;
        }
        let first = self.span(self.expr_start, self.expr_start);
        self.diags.push(
            Diagnostic::error(
                code::E0109,
                format!(
                    "expression with more than {MAX_EXPRESSION_OPERATIONS} operations (operators, calls, indexes)"
                ),
            )
            .at(self.span(start, end))
            .with_primary_label(format!("operation {}", MAX_EXPRESSION_OPERATIONS + 1))
            .with_label(first, "the expression starts here")
            .with_hint(
                "split it into several assignments through temporary variables (C compilers slow down on one very long expression)",
            ),
        );
    }

    /// Binary operator of the current token with its precedence level (0 = OR ... 6 = MOD).
    fn binop(&self) -> Option<(BinaryOp, u8)> {
        Some(match self.peek() {
            Tok::Kw(Kw::Or) => (BinaryOp::Or, 0),
            Tok::Kw(Kw::Xor) => (BinaryOp::Xor, 1),
            Tok::Kw(Kw::And) | Tok::Amp => (BinaryOp::And, 2),
            Tok::Eq => (BinaryOp::Eq, 3),
            Tok::Ne => (BinaryOp::Ne, 3),
            Tok::Lt => (BinaryOp::Lt, 4),
            Tok::Gt => (BinaryOp::Gt, 4),
            Tok::Le => (BinaryOp::Le, 4),
            Tok::Ge => (BinaryOp::Ge, 4),
            Tok::Plus => (BinaryOp::Add, 5),
            Tok::Minus => (BinaryOp::Sub, 5),
            Tok::Star => (BinaryOp::Mul, 6),
            Tok::Slash => (BinaryOp::Div, 6),
            Tok::Kw(Kw::Mod) => (BinaryOp::Mod, 6),
            // CODESYS's short-circuit operators, at the precedence of AND and OR (W0324 in `binary`)
            Tok::Ident if self.text(self.cur()).eq_ignore_ascii_case("AND_THEN") => {
                (BinaryOp::AndThen, 2)
            }
            Tok::Ident if self.text(self.cur()).eq_ignore_ascii_case("OR_ELSE") => {
                (BinaryOp::OrElse, 0)
            }
            _ => return None,
        })
    }

    /// Operators of level `min` and above (precedence climbing, left-associative).
    fn binary(&mut self, min: u8) -> Expr {
        let mut left = self.unary();
        while let Some((op, level)) = self.binop() {
            if level < min {
                break;
            }
            let t = self.bump();
            self.count_operation(t.range.start, t.range.end);
            let short = matches!(op, BinaryOp::AndThen | BinaryOp::OrElse);
            if short && !self.short_circuit_noted {
                // once per text: a CODESYS project uses them everywhere
                self.short_circuit_noted = true;
                let (word, plain) = if op == BinaryOp::AndThen {
                    ("AND_THEN", "AND")
                } else {
                    ("OR_ELSE", "OR")
                };
                let span = self.span(t.range.start, t.range.end);
                self.diags.push(
                    Diagnostic::warning(
                        code::W0324,
                        format!("`{word}` is CODESYS's short-circuit {plain}, not IEC 61131-3 (its other uses in this text are not reported)"),
                    )
                    .at(span)
                    .with_primary_label("the right operand runs only when the left does not decide")
                    .with_hint(format!("compiled as CODESYS does; for another IEC compiler nest IFs instead (where the right operand may always be evaluated, write {plain})")),
                );
            }
            // a method call in the right operand runs only sometimes: it cannot be put before the
            // statement (E0108 in `method_call_expr`)
            self.no_hoist += usize::from(short);
            self.short_operand += usize::from(short);
            let right = self.binary(level + 1);
            self.no_hoist -= usize::from(short);
            self.short_operand -= usize::from(short);
            let span = left.span.to(right.span);
            left = Expr {
                kind: ExprKind::Binary {
                    op,
                    left: Box::new(left),
                    right: Box::new(right),
                },
                span,
            };
        }
        left
    }

    fn unary(&mut self) -> Expr {
        let op = match self.peek() {
            Tok::Minus => UnaryOp::Neg,
            Tok::Plus => UnaryOp::Plus,
            Tok::Kw(Kw::Not) => UnaryOp::Not,
            _ => return self.power(),
        };
        let t = self.bump();
        self.count_operation(t.range.start, t.range.end);
        let start = self.span(t.range.start, t.range.end);
        if self.depth > MAX_DEPTH {
            return self.expr();
        }
        self.depth += 1;
        let operand = self.unary();
        self.depth -= 1;
        let span = start.to(operand.span);
        // `-5`, `-1.5`, `-T#1s`: one negative literal.
        if op != UnaryOp::Not {
            if let ExprKind::Literal(l) = &operand.kind {
                let neg = op == UnaryOp::Neg;
                let kind = match &l.kind {
                    LiteralKind::Int(v) => Some(LiteralKind::Int(if neg { -v } else { *v })),
                    LiteralKind::Real(v) => Some(LiteralKind::Real(if neg { -v } else { *v })),
                    LiteralKind::Duration(v) => {
                        Some(LiteralKind::Duration(if neg { -v } else { *v }))
                    }
                    _ => None,
                };
                if let (Some(kind), None) = (kind, &l.type_prefix) {
                    return Expr {
                        kind: ExprKind::Literal(Literal {
                            kind,
                            type_prefix: None,
                            span,
                        }),
                        span,
                    };
                }
            }
        }
        Expr {
            kind: ExprKind::Unary {
                op,
                operand: Box::new(operand),
            },
            span,
        }
    }

    fn power(&mut self) -> Expr {
        let mut left = self.primary();
        while self.at(&Tok::Power) {
            let t = self.bump();
            self.count_operation(t.range.start, t.range.end);
            // `2 ** -1` is accepted: the exponent may carry a sign.
            let right = if matches!(self.peek(), Tok::Minus | Tok::Plus) {
                self.unary()
            } else {
                self.primary()
            };
            let span = left.span.to(right.span);
            left = Expr {
                kind: ExprKind::Binary {
                    op: BinaryOp::Power,
                    left: Box::new(left),
                    right: Box::new(right),
                },
                span,
            };
        }
        left
    }

    fn literal(&self, kind: LiteralKind, prefix: Option<Ident>, t: &Token, end: usize) -> Expr {
        let span = self.span(t.range.start, end);
        Expr {
            kind: ExprKind::Literal(Literal {
                kind,
                type_prefix: prefix,
                span,
            }),
            span,
        }
    }

    fn primary(&mut self) -> Expr {
        let t = self.cur().clone();
        let here = self.span(t.range.start, t.range.end);
        match t.tok.clone() {
            Tok::Int(v) => {
                self.bump();
                self.literal(LiteralKind::Int(v), None, &t, t.range.end)
            }
            Tok::Real(v) => {
                self.bump();
                self.literal(LiteralKind::Real(v), None, &t, t.range.end)
            }
            Tok::Kw(Kw::True) | Tok::Kw(Kw::False) => {
                self.bump();
                self.literal(
                    LiteralKind::Bool(t.tok == Tok::Kw(Kw::True)),
                    None,
                    &t,
                    t.range.end,
                )
            }
            Tok::Str(wide, value) => {
                self.bump();
                self.literal(LiteralKind::String { wide, value }, None, &t, t.range.end)
            }
            Tok::Time(tv) => {
                self.bump();
                let hash = self.text(&t).find('#').unwrap_or(0) + t.range.start;
                let long = |name: &str| Some(Ident::new(name, self.span(t.range.start, hash)));
                let (kind, prefix) = match tv {
                    TimeValue::Duration(v, lg) => (
                        LiteralKind::Duration(v),
                        lg.then(|| long("LTIME")).flatten(),
                    ),
                    TimeValue::Date(v, lg) => {
                        (LiteralKind::Date(v), lg.then(|| long("LDATE")).flatten())
                    }
                    TimeValue::TimeOfDay(v, lg) => (
                        LiteralKind::TimeOfDay(v),
                        lg.then(|| long("LTOD")).flatten(),
                    ),
                    TimeValue::DateAndTime(v, lg) => (
                        LiteralKind::DateAndTime(v),
                        lg.then(|| long("LDT")).flatten(),
                    ),
                };
                self.literal(kind, prefix, &t, t.range.end)
            }
            Tok::TypePrefix => self.typed_literal(),
            Tok::LParen => {
                self.bump();
                // `(x := e)`: ExST's assignment as an expression (see `exst`)
                if self.at_condition_assignment() {
                    return self.paren_assignment(here);
                }
                let mut inner = self.expr();
                self.close_paren(here);
                inner.span = here.to(self.span(self.prev_end(), self.prev_end()));
                inner
            }
            // `THIS` alone (not `THIS^`): the instance's address, `ADR(THIS^)` (CODESYS, TwinCAT:
            // `pSelf := THIS;`, `pSelf : POINTER TO FB_X := THIS;` in a method's VAR_INST)
            // (`this.x` where `THIS.x` is no block's own variable, a program's: a variable named
            // `this`, B&R Automation Studio's ST having no THIS; round 27, before: E0104/E0100
            // at each read)
            // (a POU's own variable named `this`, IEC 61131-3 ed. 2 code where THIS is no
            // keyword, 4CONTROL's `this : INT := 48;`: that variable; round 32, before: E1021
            // "`^` cannot follow it" at each use)
            Tok::Ident
                if self.ident(&t).is("THIS")
                    && !self.this_declared
                    && *self.peek_at(1) != Tok::Caret
                    && *self.peek_at(1) != Tok::Dot =>
            {
                self.bump();
                let this = Expr {
                    kind: ExprKind::Place(Place {
                        base: PlaceBase::Name(self.ident(&t)),
                        accessors: vec![Accessor::Deref(here)],
                        span: here,
                    }),
                    span: here,
                };
                Expr {
                    kind: ExprKind::Call {
                        name: Ident::new("ADR", here),
                        args: vec![Arg {
                            name: None,
                            dir: ArgDir::Input,
                            value: this,
                            span: here,
                        }],
                    },
                    span: here,
                }
            }
            // `XOR(a, b)`, `MOD(x, 2)`, `AND(a, b, c)`: the standard functions named like operators,
            // in functional form.
            Tok::Kw(Kw::Xor | Kw::Mod | Kw::And | Kw::Or) | Tok::Ident
                if *self.peek_at(1) == Tok::LParen
                    && !(t.tok == Tok::Ident && self.call_then_access(1)) =>
            {
                let n = self.bump();
                self.count_operation(n.range.start, n.range.end);
                let name = self.ident(&n);
                if name.is("__NEW") {
                    // `__NEW(POINTER TO T, n)` (CODESYS, TwinCAT): its first argument is a type,
                    // no expression; the lowering refuses the call (E0351, `lower::dynamic_memory`)
                    return self.skipped_call(name, here);
                }
                if (name.is("SIZEOF") || name.is("XSIZEOF")) && self.at_pointer_type(1) {
                    return self.sizeof_pointer_type(name, here);
                }
                match self.args() {
                    Some(args) => Expr {
                        kind: ExprKind::Call { name, args },
                        span: here.to(self.span(self.prev_end(), self.prev_end())),
                    },
                    None => self.error_expr(here),
                }
            }
            Tok::Ident | Tok::Address(..) | Tok::Dot
                if t.tok != Tok::Dot || matches!(self.peek_at(1), Tok::Ident) =>
            {
                match self.place() {
                    Some(p) => {
                        if self.at(&Tok::LParen) {
                            if let Some(Accessor::Field(m)) = p.accessors.last() {
                                return self.method_call_expr(p.clone(), m.clone());
                            }
                            // `THIS^.M(...)`: a call of the block's own method `M(...)`
                            if let (PlaceBase::Name(name), true) = (&p.base, p.accessors.is_empty())
                            {
                                let name = name.clone();
                                return match self.args() {
                                    Some(args) => Expr {
                                        kind: ExprKind::Call { name, args },
                                        span: here.to(self.span(self.prev_end(), self.prev_end())),
                                    },
                                    None => self.error_expr(here),
                                };
                            }
                            self.error_here(
                            code::E0108,
                            "only a function name can be called inside an expression",
                            "call the function block as a statement (`inst(...);`) and read its output (`inst.Q`)",
                        );
                            return self.error_expr(p.span);
                        }
                        Expr {
                            span: p.span,
                            kind: ExprKind::Place(p),
                        }
                    }
                    None => self.error_expr(here),
                }
            }
            Tok::Error => {
                self.bump();
                self.error_expr(here)
            }
            _ => {
                let found = self.describe_current();
                self.error_here(
                    code::E0107,
                    format!("expected an expression, found {found}"),
                    "an expression is a variable, a literal, a function call or a combination with operators",
                );
                self.error_expr(here)
            }
        }
    }

    /// `INT#5`, `REAL#-1.5`, `BOOL#TRUE`, `STRING#'x'`, `Color#red`.
    fn typed_literal(&mut self) -> Expr {
        let p = self.bump();
        let name = &self.src[p.range.start..p.range.end - 1];
        let prefix = Ident::new(name, self.span(p.range.start, p.range.end - 1));
        let neg = if self.at(&Tok::Minus) {
            self.bump();
            true
        } else {
            if self.at(&Tok::Plus) {
                self.bump();
            }
            false
        };
        let t = self.cur().clone();
        let kind = match t.tok.clone() {
            Tok::Int(v) => LiteralKind::Int(if neg { -v } else { v }),
            Tok::Real(v) => LiteralKind::Real(if neg { -v } else { v }),
            Tok::Kw(Kw::True) => LiteralKind::Bool(true),
            Tok::Kw(Kw::False) => LiteralKind::Bool(false),
            Tok::Str(wide, value) => LiteralKind::String { wide, value },
            Tok::Ident if !neg => {
                self.bump();
                let value = self.ident(&t);
                return Expr {
                    kind: ExprKind::EnumValue {
                        type_name: prefix,
                        value,
                    },
                    span: self.span(p.range.start, t.range.end),
                };
            }
            _ => {
                let found = self.describe_current();
                self.error_here(
                    code::E0103,
                    format!("expected a value after `{name}#`, found {found}"),
                    "a typed literal is written `INT#5`, `REAL#1.5`, `BOOL#TRUE`; an enumerated value `Color#red`",
                );
                return self.error_expr(self.span(p.range.start, p.range.end));
            }
        };
        self.bump();
        self.literal(kind, Some(prefix), &p, t.range.end)
    }
}

/// `RETURN (cond);`: `IF cond THEN RETURN; END_IF` spanning `span`.
fn return_if(cond: Expr, span: Span) -> Option<StmtKind> {
    Some(StmtKind::If {
        branches: vec![CondBranch {
            cond,
            body: vec![Stmt {
                kind: StmtKind::Return,
                span,
            }],
            span,
        }],
        else_body: None,
    })
}

/// `target REF= value` (or B&R's `ACCESS`) as the assignment of the hidden call `callee(value)`
/// that the lowering reads (`super::refs`).
fn reference_assign(target: Place, callee: &str, value: Expr, span: Span) -> StmtKind {
    let arg = Arg {
        name: None,
        dir: ArgDir::Input,
        span: value.span,
        value,
    };
    StmtKind::Assign {
        target,
        value: Expr {
            kind: ExprKind::Call {
                name: Ident::new(callee, span),
                args: vec![arg],
            },
            span,
        },
    }
}

/// Whether `word` opens a block of variable declarations (`VAR`, `VAR_TEMP`, `VAR_INPUT`, ...).
fn is_var_keyword(word: &str) -> bool {
    [
        "VAR",
        "VAR_TEMP",
        "VAR_INPUT",
        "VAR_OUTPUT",
        "VAR_IN_OUT",
        "VAR_STAT",
        "VAR_INST",
        "VAR_EXTERNAL",
        "VAR_GLOBAL",
    ]
    .iter()
    .any(|k| word.eq_ignore_ascii_case(k))
}
