//! The IL lexer: source text in, tokens with byte ranges out (a logos state machine plus value decoding).
//!
//! Input: UTF-8 source. Output: [`RawToken`]s (newlines and `(* *)` comments included, blanks skipped) with
//! their byte ranges; [`crate::layout`] turns them into the parser's [`Tok`] stream.
//! Invariants: every word goes through ONE keyword table ([`classify`]), case-insensitively; a word that
//! spells an IL operator (`LD`, `IN`, `S1`, ...) is still usable as a name, the grammar decides by
//! position. Literal values are decoded here; an invalid literal becomes [`LexError`] with a reason.

use crate::ast::{AddressSize, Area};
use crate::literal;
use logos::{FilterResult, Logos};

/// Why the lexer could not make a token of some text.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum LexError {
    /// A character that starts no token.
    #[default]
    UnexpectedChar,
    /// `(*` without its closing `*)` before the end of the file.
    UnterminatedComment,
    /// A `'` or `"` string without its closing quote on the same line.
    UnterminatedString,
    /// A numeric, duration or date literal with no valid value; the reason.
    BadLiteral(String),
    /// `%` not followed by `I`, `Q` or `M` and a location.
    BadAddress(String),
}

/// A problem inside an otherwise usable token (an invalid `$` escape): byte range and reason.
pub type LexWarning = (std::ops::Range<usize>, String);

/// Decoded value of a `T#`/`D#`/`TOD#`/`DT#` literal; `long` is the `L` form (`LTIME#`, `LDT#` ...).
#[derive(Debug, Clone, PartialEq)]
pub enum TimeValue {
    /// `T#1s`, `LTIME#5ns`: nanoseconds (sign applied); `true` for `LTIME`.
    Duration(i128, bool),
    /// `D#2001-04-09`: days since 1970-01-01; `true` for `LDATE`.
    Date(i64, bool),
    /// `TOD#11:36:15.2`: nanoseconds since midnight; `true` for `LTOD`.
    TimeOfDay(i64, bool),
    /// `DT#2001-04-09-11:36:15`: nanoseconds since 1970-01-01T00:00:00; `true` for `LDT`.
    DateAndTime(i128, bool),
}

/// The tokens of the logos state machine.
#[derive(Logos, Debug, Clone, PartialEq)]
#[logos(error = LexError)]
#[logos(extras = Vec<LexWarning>)]
#[logos(skip r"[ \t\f\u{FEFF}]+")]
pub enum RawToken {
    /// A line end (IL instructions are line-delimited): `\n`, `\r\n` or a lone `\r` (old Mac OS), the
    /// line ends diagnostics count ([`diagnostics::line_starts`]).
    #[regex(r"\r\n|\r|\n")]
    Newline,
    /// A `(* *)` comment; `true` when it spans lines: then it ends the line like a newline does.
    #[token("(*", block_comment)]
    #[token("/*", slash_block_comment)]
    Comment(bool),
    /// `// ...` to the end of the line (skipped; an extension most tools accept).
    #[regex(r"//[^\r\n]*", logos::skip, allow_greedy = true)]
    LineComment,
    /// A word: identifier or keyword, classified later by [`classify`]. A word with letters beyond
    /// ASCII (`Motor_ä`, CODESYS 3 accepts them) is one word too: the layout reports it once (E1089).
    #[regex(r"[A-Za-z_\p{L}][A-Za-z0-9_\p{L}\p{N}]*")]
    Word,
    /// `INT#`, `BOOL#`, `Color#` (a typed literal or enum value follows) or a whole `T#1s`, `D#...`.
    #[regex(r"[A-Za-z_][A-Za-z0-9_]*#", prefixed)]
    Prefixed(Option<TimeValue>),
    /// `12`, `-3`, `1_000`, `16#FF`: the value, sign applied.
    #[regex(r"[+-]?[0-9][0-9_]*", |l| literal::decimal_int(l.slice()).map_err(LexError::BadLiteral))]
    #[regex(r"[0-9]+#[0-9A-Za-z_]*", |l| literal::based_int(l.slice()).map_err(LexError::BadLiteral))]
    Int(i128),
    /// `2.5`, `-1.0E3`: the value.
    #[regex(r"[+-]?[0-9][0-9_]*\.[0-9][0-9_]*([eE][+-]?[0-9]+)?", |l| literal::real(l.slice()).map_err(LexError::BadLiteral))]
    #[regex(r"[+-]?[0-9][0-9_]*[eE][+-]?[0-9]+", |l| literal::real(l.slice()).map_err(LexError::BadLiteral))]
    Real(f64),
    /// `'text'` (`false`) or `"wide"` (`true`) with escapes decoded.
    #[token("'", |l| string(l, false))]
    #[token("\"", |l| string(l, true))]
    Str((bool, String)),
    /// `%IX0.1`: area, size and the dotted location numbers.
    #[regex(r"%[A-Za-z0-9_.*]*", address)]
    Address((Area, AddressSize, Vec<u32>)),
    /// `(`
    #[token("(")]
    LParen,
    /// `)`
    #[token(")")]
    RParen,
    /// `[`
    #[token("[")]
    LBracket,
    /// `]`
    #[token("]")]
    RBracket,
    /// `,`
    #[token(",")]
    Comma,
    /// `:`
    #[token(":")]
    Colon,
    /// `;`
    #[token(";")]
    Semi,
    /// `:=` (assignment, input parameter).
    #[token(":=")]
    Assign,
    /// `=>` (output parameter).
    #[token("=>")]
    Arrow,
    /// `..` (a range, `1..10`).
    #[token("..")]
    DotDot,
    /// `.` (field access, `inst.Q`).
    #[token(".")]
    Dot,
    /// `+ - * /` written alone (a sign before a digit belongs to the number): an operator of a
    /// constant expression in a declaration (`ARRAY[0..N-1]`); anywhere else the layout reports it.
    #[token("+", |_| b'+')]
    #[token("-", |_| b'-')]
    #[token("*", |_| b'*')]
    #[token("/", |_| b'/')]
    Op(u8),
    /// `&`: the short form of `AND`.
    #[token("&")]
    Amp,
    /// `&N`: the short form of `ANDN`.
    #[regex("&[Nn]")]
    AmpN,
}

/// Skips a possibly nested `(* ... *)` comment; reports whether it spanned a line break.
fn block_comment(lex: &mut logos::Lexer<RawToken>) -> FilterResult<bool, LexError> {
    let (n, end) = comment_rest(lex.remainder());
    lex.bump(n);
    match end {
        CommentEnd::Closed { newline: true } => FilterResult::Emit(true),
        // a token the layout drops (a logos skip would recurse once per comment in debug builds)
        CommentEnd::Closed { newline: false } => FilterResult::Emit(false),
        CommentEnd::Unterminated => FilterResult::Error(LexError::UnterminatedComment),
    }
}

/// Skips a possibly nested `/* ... */` comment (IEC 61131-3 ed. 3); reports whether it spanned a
/// line break.
fn slash_block_comment(lex: &mut logos::Lexer<RawToken>) -> FilterResult<bool, LexError> {
    let (n, end) = slash_comment_rest(lex.remainder());
    lex.bump(n);
    match end {
        CommentEnd::Closed { newline } => FilterResult::Emit(newline),
        CommentEnd::Unterminated => FilterResult::Error(LexError::UnterminatedComment),
    }
}

/// Scans a string body after its opening quote, decoding `$` escapes (invalid ones go to `extras`).
fn string(lex: &mut logos::Lexer<RawToken>, wide: bool) -> Result<(bool, String), LexError> {
    let body_start = lex.span().end;
    let (n, value) = string_rest(lex.remainder(), wide, body_start, &mut lex.extras);
    lex.bump(n);
    value
}

/// `%IX0.1`, `%QW3`, `%MD10`, `%i0.0`, `%I*`.
fn address(lex: &mut logos::Lexer<RawToken>) -> Result<(Area, AddressSize, Vec<u32>), LexError> {
    direct_address(lex.slice())
}

/// `INT#`, `T#1h`, `DATE#2001-04-09` ...: see [`prefixed_rest`].
fn prefixed(lex: &mut logos::Lexer<RawToken>) -> Result<Option<TimeValue>, LexError> {
    let (n, value) = prefixed_rest(lex.slice(), lex.remainder());
    lex.bump(n);
    value
}

// ---------------------------------------------------------------- scanners shared with the ST lexer
// They work on text (the token's slice, the rest of the source after it) and say how many bytes of the
// rest the token takes, so each logos lexer only bumps.

/// How a `(* ... *)` comment ended.
pub(crate) enum CommentEnd {
    Closed { newline: bool },
    Unterminated,
}

/// The rest of a possibly nested `(* ... *)` comment after its opening: bytes it takes, how it ended.
///
/// One exception: OpenPLC Editor appends the C source of its debugger to the `.st` files it
/// generates, one line per comment, `(*DBG:<C text>*)`, where the C text holds `*)` and `(*` of its
/// own (`return (void *)&((__IEC_BOOL_t *) ptr)->value;`). Such a comment ends at the `*)` that ends
/// its line.
pub(crate) fn comment_rest(rest: &str) -> (usize, CommentEnd) {
    if rest.starts_with("DBG:") {
        let line = rest.find(['\n', '\r']).unwrap_or(rest.len());
        let text = rest[..line].trim_end();
        if text.ends_with("*)") {
            return (text.len(), CommentEnd::Closed { newline: false });
        }
    }
    nested_comment(rest.as_bytes(), b'(', b')')
}

/// The length of a `(* ... *)` comment's rest after its opening when it is read without nesting (it
/// ends at the first `*)`, as IEC 61131-3 edition 2 and matiec read comments), or `None` when no `*)`
/// follows. The ST lexer falls back to it for a comment that nesting leaves unclosed.
pub(crate) fn flat_comment_len(rest: &str) -> Option<usize> {
    rest.find("*)").map(|k| k + 2)
}

/// The rest of a possibly nested `/* ... */` comment after its opening (IEC 61131-3 ed. 3, Table 3,
/// features 2b and 3b): bytes it takes, how it ended.
pub(crate) fn slash_comment_rest(rest: &str) -> (usize, CommentEnd) {
    nested_comment(rest.as_bytes(), b'/', b'/')
}

/// A nested comment opened by `open *` and closed by `* close`, after its opening.
fn nested_comment(rest: &[u8], open: u8, close: u8) -> (usize, CommentEnd) {
    let mut depth = 1usize;
    let mut i = 0;
    let mut newline = false;
    while i < rest.len() {
        match (rest[i], rest.get(i + 1)) {
            (c, Some(b'*')) if c == open => {
                depth += 1;
                i += 2;
            }
            (b'*', Some(&c)) if c == close => {
                depth -= 1;
                i += 2;
                if depth == 0 {
                    return (i, CommentEnd::Closed { newline });
                }
            }
            (b'\n' | b'\r', _) => {
                newline = true;
                i += 1;
            }
            _ => i += 1,
        }
    }
    (rest.len(), CommentEnd::Unterminated)
}

/// A string body after its opening quote (`body_start` is its offset in the source): bytes it takes
/// (closing quote included) and its decoded value; invalid `$` escapes are pushed to `warnings`.
pub(crate) fn string_rest(
    rest: &str,
    wide: bool,
    body_start: usize,
    warnings: &mut Vec<LexWarning>,
) -> (usize, Result<(bool, String), LexError>) {
    let quote = if wide { b'"' } else { b'\'' };
    let bytes = rest.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'$' if i + 1 < bytes.len() && !matches!(bytes[i + 1], b'\n' | b'\r') => {
                // Skip the escaped character (may be multi-byte UTF-8).
                let ch_len = rest[i + 1..].chars().next().map_or(1, char::len_utf8);
                i += 1 + ch_len;
            }
            b'\n' | b'\r' => {
                // a string written over several lines (TwinCAT projects hold them: an HTTP
                // header in a declaration): still an error (IEC 61131-3 writes a line break in a
                // string as `$N`), but the token ends at its closing quote, so that the rest of
                // the file is read as written, when that quote ends the declaration or statement
                if let Some(end) = closed_on_a_later_line(&rest[i..], quote) {
                    return (i + end, Err(LexError::UnterminatedString));
                }
                break;
            }
            c if c == quote => {
                let (value, errors) = literal::unescape(&rest[..i], wide);
                for (s, e, why) in errors {
                    warnings.push((body_start + s..body_start + e, why));
                }
                return (i + 1, Ok((wide, value)));
            }
            _ => i += 1,
        }
    }
    (i, Err(LexError::UnterminatedString))
}

/// The most lines a string written over several lines may take to be read to its closing quote.
const MAX_STRING_LINES: usize = 64;

/// Where a string that reaches a line end (`rest` starts at that line end) is closed on a later
/// line: the bytes to its closing quote, included, when the next unescaped `quote` comes within
/// [`MAX_STRING_LINES`] lines, with no `;` before it, and only blanks and then a `;` after it (the
/// end of the declaration or statement: `s : STRING := 'a<line break>b';`). `None` otherwise: an
/// unclosed string then ends at its line, as before (a quote forgotten on one line is not read
/// into the next statement).
fn closed_on_a_later_line(rest: &str, quote: u8) -> Option<usize> {
    let bytes = rest.as_bytes();
    let mut lines = 0;
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'$' => i += 2,
            b'\n' => {
                lines += 1;
                if lines > MAX_STRING_LINES {
                    return None;
                }
                i += 1;
            }
            b';' => return None,
            c if c == quote => {
                let after = rest[i + 1..].trim_start_matches([' ', '\t']);
                return after.starts_with(';').then_some(i + 1);
            }
            _ => i += 1,
        }
    }
    None
}

/// A direct address `%IX0.1`, `%QW3`, `%MD10`, `%i0.0`, `%I*` (the whole token's text).
pub fn direct_address(text: &str) -> Result<(Area, AddressSize, Vec<u32>), LexError> {
    let bad = |why: &str| LexError::BadAddress(format!("`{text}` {why}"));
    let mut chars = text[1..].chars().peekable();
    let area = match chars.next().map(|c| c.to_ascii_uppercase()) {
        Some('I') => Area::Input,
        Some('Q') => Area::Output,
        Some('M') => Area::Memory,
        _ => return Err(bad("is not a direct address: the area must be I, Q or M")),
    };
    let size = match chars.peek().map(|c| c.to_ascii_uppercase()) {
        Some('X') => Some(AddressSize::Bit),
        Some('B') => Some(AddressSize::Byte),
        Some('W') => Some(AddressSize::Word),
        Some('D') => Some(AddressSize::DWord),
        Some('L') => Some(AddressSize::LWord),
        _ => None,
    };
    if size.is_some() {
        chars.next();
    } else if let Some(&c) = chars.peek().filter(|c| c.is_ascii_alphabetic()) {
        // `%IR3.0` (an OWEN/CODESYS V2.3 target's REAL area): the location is fine, the size
        // letter is not one of IEC 61131-3's (ed. 3, 6.5.5, Table 16: X, B, W, D, L)
        return Err(bad(&format!(
            "has the size letter `{c}`, which is not one of X, B, W, D, L (IEC 61131-3 sizes: bit, byte, word, double word, long word)"
        )));
    }
    let size = size.unwrap_or(AddressSize::Bit);
    let rest: String = chars.collect();
    if rest == "*" {
        return Ok((area, size, Vec::new()));
    }
    let mut path = Vec::new();
    for part in rest.split('.') {
        if part.is_empty() || !part.bytes().all(|b| b.is_ascii_digit()) {
            return Err(bad(
                "is not a valid location: expected numbers separated by dots (e.g. %IX0.1)",
            ));
        }
        path.push(
            part.parse::<u32>()
                .map_err(|_| bad("has a location number that is too large"))?,
        );
    }
    Ok((area, size, path))
}

/// A `PREFIX#` token (`INT#`, `T#`, `DATE#` ...) and the source after it: the date/time families are
/// decoded right away (their bodies contain `:` `-` `.` that are other tokens elsewhere), other prefixes
/// stay prefixes (`None`). Returns the bytes of `rest` the literal's body takes. In a duration a `.`
/// belongs to the literal only before a digit (`T#1.5s`), so `T#1s..T#2s` and `T#1s.` end at the `s`.
pub(crate) fn prefixed_rest(
    prefix: &str,
    rest: &str,
) -> (usize, Result<Option<TimeValue>, LexError>) {
    let prefix = prefix.trim_end_matches('#').to_ascii_uppercase();
    let (fam, long) = match prefix.as_str() {
        "T" | "TIME" => (Fam::Dur, false),
        "LT" | "LTIME" => (Fam::Dur, true),
        "D" | "DATE" => (Fam::Date, false),
        "LD" | "LDATE" => (Fam::Date, true),
        "TOD" | "TIME_OF_DAY" => (Fam::Tod, false),
        "LTOD" | "LTIME_OF_DAY" => (Fam::Tod, true),
        "DT" | "DATE_AND_TIME" => (Fam::Dt, false),
        "LDT" | "LDATE_AND_TIME" => (Fam::Dt, true),
        _ => return (0, Ok(None)),
    };
    // `T# 30000ms`: blanks between `#` and the value (matiec reads `T#` as a token of its own, and
    // OpenPLC Editor projects carry such literals): skipped when a value follows on the same line
    let blanks = rest.len() - rest.trim_start_matches([' ', '\t']).len();
    let skip = match rest.as_bytes().get(blanks) {
        Some(c) if blanks > 0 && (c.is_ascii_digit() || matches!(c, b'+' | b'-')) => blanks,
        _ => 0,
    };
    let (n, value) = prefixed_body(fam, long, &rest[skip..]);
    (skip + n, value)
}

/// The date/time family of a `PREFIX#` literal.
#[derive(Clone, Copy)]
enum Fam {
    Dur,
    Date,
    Tod,
    Dt,
}

/// The body of a date/time literal at the start of `rest`: its length and value.
fn prefixed_body(fam: Fam, long: bool, rest: &str) -> (usize, Result<Option<TimeValue>, LexError>) {
    let bytes = rest.as_bytes();
    // `_` between two digits (`TOD#10:43:47.260_001`: IEC 61131-3's `integer ::= digit {['_']
    // digit}` in every number of a date and time)
    let digit_separator = |i: usize, c: u8| {
        c == b'_'
            && i > 0
            && bytes[i - 1].is_ascii_digit()
            && bytes.get(i + 1).is_some_and(u8::is_ascii_digit)
    };
    let allowed = |i: usize, c: u8| match fam {
        Fam::Dur => {
            c.is_ascii_alphanumeric()
                || c == b'_'
                || (c == b'.' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit))
                || (i == 0 && (c == b'-' || c == b'+'))
        }
        Fam::Date => c.is_ascii_digit() || c == b'-' || digit_separator(i, c),
        Fam::Tod => c.is_ascii_digit() || c == b':' || c == b'.' || digit_separator(i, c),
        Fam::Dt => {
            c.is_ascii_digit() || c == b'-' || c == b':' || c == b'.' || digit_separator(i, c)
        }
    };
    let n = bytes
        .iter()
        .enumerate()
        .take_while(|&(i, &c)| allowed(i, c))
        .count();
    let body = &rest[..n];
    let plain;
    let dated = if matches!(fam, Fam::Dur) || !body.contains('_') {
        body
    } else {
        plain = body.replace('_', "");
        plain.as_str()
    };
    let value = match fam {
        Fam::Dur => literal::duration(body).map(|v| TimeValue::Duration(v, long)),
        Fam::Date => literal::date(dated).map(|v| TimeValue::Date(v, long)),
        Fam::Tod => literal::time_of_day(dated).map(|v| TimeValue::TimeOfDay(v, long)),
        Fam::Dt => literal::date_and_time(dated).map(|v| TimeValue::DateAndTime(v, long)),
    };
    (n, value.map(Some).map_err(LexError::BadLiteral))
}

/// The class of a word: a plain identifier or one of the keywords. Classified by [`classify`] only.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Word {
    /// Any word that is not a keyword: a variable, type, POU or label name.
    Ident,
    // IL operators: also usable as names (`IN := x`, `tmr.PT`, a variable named `R1`).
    /// `LD`: load the operand into the current result.
    Ld,
    /// `LDN`: load the negated operand.
    Ldn,
    /// `ST`: store the current result.
    St,
    /// `STN`: store the negated current result.
    Stn,
    /// `S`: set the operand if the current result is TRUE (a set coil).
    S,
    /// `R`: reset the operand if the current result is TRUE (a reset coil).
    R,
    /// `AND`: AND the operand into the current result (a series contact).
    And,
    /// `ANDN`: AND NOT (a normally closed series contact).
    Andn,
    /// `OR`: OR the operand into the current result (a parallel branch).
    Or,
    /// `ORN`: OR NOT.
    Orn,
    /// `XOR`: exclusive OR.
    Xor,
    /// `XORN`: exclusive OR with the negated operand.
    Xorn,
    /// `NOT`: invert the current result.
    Not,
    /// `ADD`: addition.
    Add,
    /// `SUB`: subtraction.
    Sub,
    /// `MUL`: multiplication.
    Mul,
    /// `DIV`: division.
    Div,
    /// `MOD`: remainder.
    Mod,
    /// `GT`: greater than.
    Gt,
    /// `GE`: greater or equal.
    Ge,
    /// `EQ`: equal.
    Eq,
    /// `NE`: not equal.
    Ne,
    /// `LE`: less or equal.
    Le,
    /// `LT`: less than.
    Lt,
    /// `JMP`: jump to a label.
    Jmp,
    /// `JMPC`: jump if the current result is TRUE.
    Jmpc,
    /// `JMPCN`: jump if the current result is FALSE (also spelled `JMPNC`).
    Jmpcn,
    /// `CAL`: call an FB instance.
    Cal,
    /// `CALC`: call if the current result is TRUE.
    Calc,
    /// `CALCN`: call if the current result is FALSE (also spelled `CALNC`).
    Calcn,
    /// `RET`: return from the POU.
    Ret,
    /// `RETC`: return if the current result is TRUE.
    Retc,
    /// `RETCN`: return if the current result is FALSE (also spelled `RETNC`).
    Retcn,
    /// `S1`: set input of an SR instance.
    S1,
    /// `R1`: reset input of an RS instance.
    R1,
    /// `CLK`: clock input of R_TRIG/F_TRIG.
    Clk,
    /// `CU`: count-up input of a counter.
    Cu,
    /// `CD`: count-down input of a counter.
    Cd,
    /// `PV`: preset value of a counter.
    Pv,
    /// `IN`: input of a timer.
    In,
    /// `PT`: preset time of a timer.
    Pt,
    /// The `FUNC Name()` embedded-C extension.
    Func,
    // Reserved words: never names.
    /// `PROGRAM` (reserved): opens a program POU.
    Program,
    /// `END_PROGRAM` (reserved): closes a program.
    EndProgram,
    /// `FUNCTION` (reserved): opens a function.
    Function,
    /// `END_FUNCTION` (reserved): closes a function.
    EndFunction,
    /// `FUNCTION_BLOCK` (reserved): opens a function block.
    FunctionBlock,
    /// `END_FUNCTION_BLOCK` (reserved): closes a function block.
    EndFunctionBlock,
    /// `VAR` (reserved): local variable block.
    Var,
    /// `VAR_INPUT` (reserved): input parameter block.
    VarInput,
    /// `VAR_OUTPUT` (reserved): output parameter block.
    VarOutput,
    /// `VAR_IN_OUT` (reserved): in-out (by reference) parameter block.
    VarInOut,
    /// `VAR_TEMP` (reserved): temporary variable block.
    VarTemp,
    /// `VAR_GLOBAL` (reserved): global variable block.
    VarGlobal,
    /// `VAR_EXTERNAL` (reserved): block referencing globals.
    VarExternal,
    /// `VAR_ACCESS` (reserved): access path block (reserved so it is never a name; the grammar does not
    /// accept it).
    VarAccess,
    /// `VAR_CONFIG` (reserved): instance-specific initialisation block (reserved so it is never a name; the
    /// grammar does not accept it).
    VarConfig,
    /// `END_VAR` (reserved): closes a variable block.
    EndVar,
    /// `CONSTANT` (reserved): read-only qualifier of a variable block.
    Constant,
    /// `RETAIN` (reserved): retentive qualifier.
    Retain,
    /// `NON_RETAIN` (reserved): non-retentive qualifier.
    NonRetain,
    /// `AT` (reserved): introduces a direct address location.
    At,
    /// `TYPE` (reserved): opens a data type block.
    Type,
    /// `END_TYPE` (reserved): closes a data type block.
    EndType,
    /// `STRUCT` (reserved): opens a structure type.
    Struct,
    /// `END_STRUCT` (reserved): closes a structure type.
    EndStruct,
    /// `ARRAY` (reserved): array type.
    Array,
    /// `OF` (reserved): element type of an array.
    Of,
    /// `STRING` (reserved): byte string type.
    String,
    /// `WSTRING` (reserved): wide (UTF-16) string type.
    WString,
    /// `CONFIGURATION` (reserved): opens a configuration.
    Configuration,
    /// `END_CONFIGURATION` (reserved): closes a configuration.
    EndConfiguration,
    /// `RESOURCE` (reserved): opens a resource.
    Resource,
    /// `END_RESOURCE` (reserved): closes a resource.
    EndResource,
    /// `ON` (reserved): the PLC of a resource (`RESOURCE r ON PLC`).
    On,
    /// `TASK` (reserved): a task declaration.
    Task,
    /// `WITH` (reserved): the task of a program instance (`PROGRAM p WITH t : T`).
    With,
    /// `TRUE` (reserved): Boolean literal.
    True,
    /// `FALSE` (reserved): Boolean literal.
    False,
    /// `R_EDGE` (reserved): rising-edge input qualifier.
    REdge,
    /// `F_EDGE` (reserved): falling-edge input qualifier.
    FEdge,
}

/// THE keyword table: every word of the source is classified here, case-insensitively.
pub fn classify(word: &str) -> Word {
    let mut buf = [0u8; 20];
    if word.len() > buf.len() {
        return Word::Ident;
    }
    // upper-cased byte by byte into the buffer (a word is a few bytes: no call to copy them first)
    for (d, s) in buf.iter_mut().zip(word.as_bytes()) {
        *d = s.to_ascii_uppercase();
    }
    let up = &buf[..word.len()];
    use Word::*;
    match up {
        b"LD" => Ld,
        b"LDN" => Ldn,
        b"ST" => St,
        b"STN" => Stn,
        b"S" => S,
        b"R" => R,
        b"AND" => And,
        b"ANDN" => Andn,
        b"OR" => Or,
        b"ORN" => Orn,
        b"XOR" => Xor,
        b"XORN" => Xorn,
        b"NOT" => Not,
        b"ADD" => Add,
        b"SUB" => Sub,
        b"MUL" => Mul,
        b"DIV" => Div,
        b"MOD" => Mod,
        b"GT" => Gt,
        b"GE" => Ge,
        b"EQ" => Eq,
        b"NE" => Ne,
        b"LE" => Le,
        b"LT" => Lt,
        b"JMP" => Jmp,
        b"JMPC" => Jmpc,
        b"JMPCN" | b"JMPNC" => Jmpcn,
        b"CAL" => Cal,
        b"CALC" => Calc,
        b"CALCN" | b"CALNC" => Calcn,
        b"RET" => Ret,
        b"RETC" => Retc,
        b"RETCN" | b"RETNC" => Retcn,
        b"S1" => S1,
        b"R1" => R1,
        b"CLK" => Clk,
        b"CU" => Cu,
        b"CD" => Cd,
        b"PV" => Pv,
        b"IN" => In,
        b"PT" => Pt,
        b"FUNC" => Func,
        b"PROGRAM" => Program,
        b"END_PROGRAM" => EndProgram,
        b"FUNCTION" => Function,
        b"END_FUNCTION" => EndFunction,
        b"FUNCTION_BLOCK" => FunctionBlock,
        b"END_FUNCTION_BLOCK" => EndFunctionBlock,
        b"VAR" => Var,
        b"VAR_INPUT" => VarInput,
        b"VAR_OUTPUT" => VarOutput,
        b"VAR_IN_OUT" => VarInOut,
        b"VAR_TEMP" => VarTemp,
        b"VAR_GLOBAL" => VarGlobal,
        b"VAR_EXTERNAL" => VarExternal,
        b"VAR_ACCESS" => VarAccess,
        b"VAR_CONFIG" => VarConfig,
        b"END_VAR" => EndVar,
        b"CONSTANT" => Constant,
        b"RETAIN" => Retain,
        b"NON_RETAIN" => NonRetain,
        b"AT" => At,
        b"TYPE" => Type,
        b"END_TYPE" => EndType,
        b"STRUCT" => Struct,
        b"END_STRUCT" => EndStruct,
        b"ARRAY" => Array,
        b"OF" => Of,
        b"STRING" => String,
        b"WSTRING" => WString,
        b"CONFIGURATION" => Configuration,
        b"END_CONFIGURATION" => EndConfiguration,
        b"RESOURCE" => Resource,
        b"END_RESOURCE" => EndResource,
        b"ON" => On,
        b"TASK" => Task,
        b"WITH" => With,
        b"TRUE" => True,
        b"FALSE" => False,
        b"R_EDGE" => REdge,
        b"F_EDGE" => FEdge,
        _ => Ident,
    }
}

impl Word {
    /// IL operator words (and `FUNC`) may also be used as names.
    pub fn is_name(self) -> bool {
        (self as u8) <= (Word::Func as u8)
    }
    /// Operators that take a parenthesised deferred operand: `AND(`, `ADD(`, `GT(` ...
    pub fn is_deferrable(self) -> bool {
        use Word::*;
        matches!(
            self,
            And | Andn
                | Or
                | Orn
                | Xor
                | Xorn
                | Add
                | Sub
                | Mul
                | Div
                | Mod
                | Gt
                | Ge
                | Eq
                | Ne
                | Le
                | Lt
        )
    }
    /// The simple operators `LD` ... `LT` (a `(` after one at the start of an instruction opens a
    /// nested list; only [`Word::is_deferrable`] ones may, the parser reports the others).
    pub fn is_simple_op(self) -> bool {
        (Word::Ld as u8..=Word::Lt as u8).contains(&(self as u8))
    }
    /// The `END_*` keyword that closes a POU opened by this keyword.
    pub fn pou_end(self) -> Option<Word> {
        match self {
            Word::Program => Some(Word::EndProgram),
            Word::Function => Some(Word::EndFunction),
            Word::FunctionBlock => Some(Word::EndFunctionBlock),
            _ => None,
        }
    }
    /// The canonical upper-case spelling (for messages).
    pub fn spelling(self) -> &'static str {
        use Word::*;
        match self {
            Ident => "identifier",
            Ld => "LD",
            Ldn => "LDN",
            St => "ST",
            Stn => "STN",
            S => "S",
            R => "R",
            And => "AND",
            Andn => "ANDN",
            Or => "OR",
            Orn => "ORN",
            Xor => "XOR",
            Xorn => "XORN",
            Not => "NOT",
            Add => "ADD",
            Sub => "SUB",
            Mul => "MUL",
            Div => "DIV",
            Mod => "MOD",
            Gt => "GT",
            Ge => "GE",
            Eq => "EQ",
            Ne => "NE",
            Le => "LE",
            Lt => "LT",
            Jmp => "JMP",
            Jmpc => "JMPC",
            Jmpcn => "JMPCN",
            Cal => "CAL",
            Calc => "CALC",
            Calcn => "CALCN",
            Ret => "RET",
            Retc => "RETC",
            Retcn => "RETCN",
            S1 => "S1",
            R1 => "R1",
            Clk => "CLK",
            Cu => "CU",
            Cd => "CD",
            Pv => "PV",
            In => "IN",
            Pt => "PT",
            Func => "FUNC",
            Program => "PROGRAM",
            EndProgram => "END_PROGRAM",
            Function => "FUNCTION",
            EndFunction => "END_FUNCTION",
            FunctionBlock => "FUNCTION_BLOCK",
            EndFunctionBlock => "END_FUNCTION_BLOCK",
            Var => "VAR",
            VarInput => "VAR_INPUT",
            VarOutput => "VAR_OUTPUT",
            VarInOut => "VAR_IN_OUT",
            VarTemp => "VAR_TEMP",
            VarGlobal => "VAR_GLOBAL",
            VarExternal => "VAR_EXTERNAL",
            VarAccess => "VAR_ACCESS",
            VarConfig => "VAR_CONFIG",
            EndVar => "END_VAR",
            Constant => "CONSTANT",
            Retain => "RETAIN",
            NonRetain => "NON_RETAIN",
            At => "AT",
            Type => "TYPE",
            EndType => "END_TYPE",
            Struct => "STRUCT",
            EndStruct => "END_STRUCT",
            Array => "ARRAY",
            Of => "OF",
            String => "STRING",
            WString => "WSTRING",
            Configuration => "CONFIGURATION",
            EndConfiguration => "END_CONFIGURATION",
            Resource => "RESOURCE",
            EndResource => "END_RESOURCE",
            On => "ON",
            Task => "TASK",
            With => "WITH",
            True => "TRUE",
            False => "FALSE",
            REdge => "R_EDGE",
            FEdge => "F_EDGE",
        }
    }
}

/// The parser's tokens (what [`crate::layout`] hands to the grammar).
#[derive(Debug, Clone, PartialEq)]
pub enum Tok {
    /// Synthetic first token: parse a whole compilation unit.
    UnitStart,
    /// Synthetic first token: parse an instruction list alone.
    BodyStart,
    /// End of an IL line (consecutive line ends collapse into one).
    Eol,
    /// A word, identifier or keyword (see [`Word`]).
    Word(Word),
    /// `&` and `&N` (AND, AND NOT).
    Amp,
    /// See [`Tok::Amp`].
    AmpN,
    /// An integer literal, sign applied.
    Int(i128),
    /// A real literal.
    Real(f64),
    /// A duration, date, time-of-day or date-and-time literal, decoded.
    Time(TimeValue),
    /// A string literal: wide flag (`"..."`) and decoded characters.
    Str(bool, String),
    /// `INT#`, `Color#`: the name is the token text without `#`.
    TypePrefix,
    /// A direct address `%IX0.1`: area, size, location numbers.
    Address(Area, AddressSize, Vec<u32>),
    /// `(`: parameter list or nested instruction list.
    LParen,
    /// `)`
    RParen,
    /// `[`
    LBracket,
    /// `]`
    RBracket,
    /// `,`
    Comma,
    /// `:`
    Colon,
    /// `;`
    Semi,
    /// `:=`
    Assign,
    /// `+` in a bound of a declaration (`ARRAY[0..N + 1]`, `STRING[N+1]`).
    Plus,
    /// `-` in a bound of a declaration (`ARRAY[0..N - 1]`).
    Minus,
    /// `*` in a bound of a declaration (`ARRAY[1..2*N]`).
    Star,
    /// `/` in a bound of a declaration (`ARRAY[0..N/2]`).
    Slash,
    /// `=>`
    Arrow,
    /// `..`
    DotDot,
    /// `.`
    Dot,
    /// Text the lexer could not make a token of (already reported).
    Error,
    /// A whole simple instruction line, `LD x`: an operator word (one of `LD` .. `LT`, see
    /// [`Word::is_simple_op`], as the grammar reads it: operator, `N` modifier, word) at the start of
    /// an instruction line and a plain name, its operand, with the name's local byte range. The layout
    /// pass passes the two tokens on as one when a line end follows the name (the commonest IL line);
    /// the grammar builds what it builds of the two.
    SimpleLine((crate::ast::Op, bool, Word), usize, usize),
    /// `ADD 5`: as [`Tok::SimpleLine`], with an integer literal (sign applied) as the operand, and the
    /// literal's local byte range.
    SimpleIntLine((crate::ast::Op, bool, Word), i128, usize, usize),
    /// `JMPC done`: a jump word (`JMP`, `JMPC`, `JMPCN`), as its condition, and a plain name as the
    /// label, with the name's local byte range, followed by the line's end.
    JumpLine(crate::ast::Condition, usize, usize),
    /// `done:` alone on its line: a plain name at the start of an instruction line and `:`, followed
    /// by the line's end; the name's local byte range.
    LabelLine(usize, usize),
    /// A run of consecutive plain lines of an instruction list (see
    /// [`crate::layout::Layout`]'s line runs), each with its line end: what the layout pass would
    /// have passed on as one line token ([`LineTok`], with that token's local byte range) and an
    /// [`Tok::Eol`] per line. The grammar adds to the list what it builds of those tokens.
    Lines(Vec<(usize, LineTok, usize)>),
}

/// One line of a [`Tok::Lines`] run: the line token the layout pass passes on for it otherwise.
#[derive(Debug, Clone, PartialEq)]
pub enum LineTok {
    /// As [`Tok::SimpleLine`].
    Simple((crate::ast::Op, bool, Word), usize, usize),
    /// As [`Tok::SimpleIntLine`].
    SimpleInt((crate::ast::Op, bool, Word), i128, usize, usize),
    /// As [`Tok::JumpLine`].
    Jump(crate::ast::Condition, usize, usize),
    /// As [`Tok::LabelLine`].
    Label(usize, usize),
}

impl LineTok {
    /// The line token it stands for.
    pub fn into_tok(self) -> Tok {
        match self {
            LineTok::Simple(op, l, r) => Tok::SimpleLine(op, l, r),
            LineTok::SimpleInt(op, v, l, r) => Tok::SimpleIntLine(op, v, l, r),
            LineTok::Jump(c, l, r) => Tok::JumpLine(c, l, r),
            LineTok::Label(l, r) => Tok::LabelLine(l, r),
        }
    }
}

impl Tok {
    /// How the token reads in a message: "`LD`", "end of line", "integer literal".
    pub fn describe(&self, text: &str) -> String {
        match self {
            Tok::UnitStart | Tok::BodyStart => "start of file".into(),
            Tok::Eol => "end of line".into(),
            Tok::Word(_)
            | Tok::Amp
            | Tok::AmpN
            | Tok::SimpleLine(..)
            | Tok::SimpleIntLine(..)
            | Tok::JumpLine(..)
            | Tok::LabelLine(..)
            | Tok::Lines(..) => format!("`{text}`"),
            Tok::Int(_) | Tok::Real(_) | Tok::Time(_) | Tok::Str(..) => {
                format!("literal `{text}`")
            }
            Tok::TypePrefix => format!("`{text}`"),
            Tok::Address(..) => format!("address `{text}`"),
            Tok::Error => "invalid text".into(),
            _ if text.is_empty() => "end of file".into(),
            _ => format!("`{text}`"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lex(src: &str) -> Vec<Result<RawToken, LexError>> {
        RawToken::lexer(src).collect()
    }

    /// The grammar moves tokens inside its symbols (the largest symbol is lalrpop's error record,
    /// which holds a token): the line tokens (`SimpleIntLine` with its `i128`) fit in the size the
    /// literal tokens already had.
    #[test]
    fn tokens_stay_small() {
        assert_eq!(std::mem::size_of::<Tok>(), 48);
    }

    #[test]
    fn keyword_table_is_case_insensitive_and_keeps_names_usable() {
        assert_eq!(classify("ld"), Word::Ld);
        assert_eq!(classify("JmpNC"), Word::Jmpcn);
        assert_eq!(classify("end_function_block"), Word::EndFunctionBlock);
        assert_eq!(classify("In"), Word::In);
        assert_eq!(classify("x_1"), Word::Ident);
        assert_eq!(classify("a_very_long_identifier_name"), Word::Ident);
        assert!(Word::In.is_name() && Word::Func.is_name() && Word::S.is_name());
        assert!(!Word::Program.is_name() && !Word::True.is_name());
    }

    #[test]
    fn comments_and_newlines() {
        use RawToken::*;
        assert_eq!(
            lex("LD x (* a (* nested *) b *)\n// line\nST y"),
            vec![
                Ok(Word),
                Ok(Word),
                Ok(Comment(false)),
                Ok(Newline),
                Ok(Newline),
                Ok(Word),
                Ok(Word)
            ]
        );
        assert_eq!(
            lex("a (* x\n y *) b"),
            vec![Ok(Word), Ok(Comment(true)), Ok(Word)]
        );
        assert_eq!(
            lex("a (* open"),
            vec![Ok(Word), Err(LexError::UnterminatedComment)]
        );
    }

    #[test]
    fn numbers() {
        use RawToken::*;
        assert_eq!(
            lex("1_000 -12 +3"),
            vec![Ok(Int(1000)), Ok(Int(-12)), Ok(Int(3))]
        );
        assert_eq!(
            lex("2#1010 8#17 16#a5 16#FF_FF"),
            vec![Ok(Int(10)), Ok(Int(15)), Ok(Int(0xa5)), Ok(Int(0xffff))]
        );
        assert_eq!(
            lex("23.6 -12e-5 1.5E3 -12e6"),
            vec![
                Ok(Real(23.6)),
                Ok(Real(-12e-5)),
                Ok(Real(1.5e3)),
                Ok(Real(-12e6))
            ]
        );
        assert_eq!(lex("0..127"), vec![Ok(Int(0)), Ok(DotDot), Ok(Int(127))]);
        assert!(matches!(lex("2#102")[0], Err(LexError::BadLiteral(_))));
    }

    #[test]
    fn typed_and_time_literals() {
        use RawToken::*;
        let s = literal::NS_PER_S;
        assert_eq!(lex("INT#5"), vec![Ok(Prefixed(None)), Ok(Int(5))]);
        assert_eq!(lex("REAL#1.5"), vec![Ok(Prefixed(None)), Ok(Real(1.5))]);
        assert_eq!(lex("BOOL#TRUE"), vec![Ok(Prefixed(None)), Ok(Word)]);
        assert_eq!(lex("UINT#16#a5"), vec![Ok(Prefixed(None)), Ok(Int(0xa5))]);
        assert_eq!(
            lex("T#1h2m3.5s"),
            vec![Ok(Prefixed(Some(TimeValue::Duration(
                3723 * s + s / 2,
                false
            ))))]
        );
        assert_eq!(
            lex("TIME#1h_15m_30s_60ms"),
            vec![Ok(Prefixed(Some(TimeValue::Duration(
                4530 * s + 60_000_000,
                false
            ))))]
        );
        assert_eq!(
            lex("t#-5s"),
            vec![Ok(Prefixed(Some(TimeValue::Duration(-5 * s, false))))]
        );
        // blanks after `#` (matiec, OpenPLC Editor projects), not a line end
        assert_eq!(
            lex("T# 30ms"),
            vec![Ok(Prefixed(Some(TimeValue::Duration(30_000_000, false))))]
        );
        assert!(matches!(lex("T#\n30ms")[0], Err(LexError::BadLiteral(_))));
        assert_eq!(
            lex("LTIME#1ns"),
            vec![Ok(Prefixed(Some(TimeValue::Duration(1, true))))]
        );
        assert_eq!(
            lex("D#2001-04-09 DATE#1970-01-02"),
            vec![
                Ok(Prefixed(Some(TimeValue::Date(11_421, false)))),
                Ok(Prefixed(Some(TimeValue::Date(1, false))))
            ]
        );
        assert_eq!(
            lex("TOD#11:36:15.20 TIME_OF_DAY#00:00:01"),
            vec![
                Ok(Prefixed(Some(TimeValue::TimeOfDay(
                    41_775_200_000_000,
                    false
                )))),
                Ok(Prefixed(Some(TimeValue::TimeOfDay(1_000_000_000, false))))
            ]
        );
        assert_eq!(
            lex("DT#1970-01-02-00:00:01 DATE_AND_TIME#2001-04-09-11:36:15.20"),
            vec![
                Ok(Prefixed(Some(TimeValue::DateAndTime(
                    literal::NS_PER_DAY + s,
                    false
                )))),
                Ok(Prefixed(Some(TimeValue::DateAndTime(
                    11_421 * literal::NS_PER_DAY + 41_775_200_000_000,
                    false
                ))))
            ]
        );
        // `DT` without `#` is a plain word (a formal argument name in the corpus).
        assert_eq!(lex("DT:=1"), vec![Ok(Word), Ok(Assign), Ok(Int(1))]);
        assert!(matches!(lex("T#5x")[0], Err(LexError::BadLiteral(_))));
    }

    #[test]
    fn strings() {
        use RawToken::*;
        assert_eq!(
            lex(r#"'a$'b$$' "x$"y" 'it' ''"#),
            vec![
                Ok(Str((false, "a'b$".into()))),
                Ok(Str((true, "x\"y".into()))),
                Ok(Str((false, "it".into()))),
                Ok(Str((false, "".into())))
            ]
        );
        assert_eq!(
            lex("'$N$L$P$R$T$41'"),
            vec![Ok(Str((false, "\n\n\u{c}\r\tA".into())))]
        );
        assert_eq!(
            lex("'open\nLD"),
            vec![Err(LexError::UnterminatedString), Ok(Newline), Ok(Word)]
        );
        let mut l = RawToken::lexer("'a$qb'");
        assert_eq!(l.next(), Some(Ok(Str((false, "a$qb".into())))));
        assert_eq!(l.extras.len(), 1);
        assert_eq!(l.extras[0].0, 2..4);
    }

    #[test]
    fn addresses() {
        use AddressSize::*;
        use RawToken::*;
        assert_eq!(
            lex("%IX0.1 %QW3 %MD10 %i0.0 %md4.23 %I*"),
            vec![
                Ok(Address((Area::Input, Bit, vec![0, 1]))),
                Ok(Address((Area::Output, AddressSize::Word, vec![3]))),
                Ok(Address((Area::Memory, DWord, vec![10]))),
                Ok(Address((Area::Input, Bit, vec![0, 0]))),
                Ok(Address((Area::Memory, DWord, vec![4, 23]))),
                Ok(Address((Area::Input, Bit, vec![]))),
            ]
        );
        assert!(matches!(lex("%Z1")[0], Err(LexError::BadAddress(_))));
        assert!(matches!(lex("%IX")[0], Err(LexError::BadAddress(_))));
    }

    #[test]
    fn punctuation() {
        use RawToken::*;
        assert_eq!(
            lex("( ) [ ] , : ; := => .. . & &N"),
            vec![
                Ok(LParen),
                Ok(RParen),
                Ok(LBracket),
                Ok(RBracket),
                Ok(Comma),
                Ok(Colon),
                Ok(Semi),
                Ok(Assign),
                Ok(Arrow),
                Ok(DotDot),
                Ok(Dot),
                Ok(Amp),
                Ok(AmpN)
            ]
        );
        assert_eq!(lex("?"), vec![Err(LexError::UnexpectedChar)]);
    }
}
