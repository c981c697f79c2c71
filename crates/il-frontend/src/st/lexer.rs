//! The ST lexer: source text in, [`Token`]s with byte ranges out (a logos state machine).
//!
//! Input: UTF-8 text. Output: tokens (blanks, line ends, `(* *)` and `/* */` nested comments, `//` comments and
//! `{ }` pragmas skipped) and lexing problems, each with its byte range in `src`.
//! Invariants: keywords are recognised case-insensitively by ONE table ([`keyword`]); number literals
//! carry no sign (`a-1` is `a`, `-`, `1`; the parser folds `-1`); literal values are decoded by
//! [`crate::literal`], exactly as the IL lexer does; an invalid literal becomes an error token.

use crate::ast::{AddressSize, Area};
use crate::lexer::{self, LexError, TimeValue};
use crate::literal;
use logos::{FilterResult, Logos};
use std::ops::Range;

#[derive(Logos, Debug, Clone, PartialEq)]
#[logos(error = LexError)]
#[logos(extras = Vec<(Range<usize>, String)>)]
#[logos(skip r"[ \t\r\n\f\u{FEFF}]+")]
enum Raw {
    #[token("(*", block_comment)]
    #[token("/*", slash_block_comment)]
    Comment,
    #[token("{", pragma)]
    Pragma,
    // Comments and pragmas are tokens that `lex` drops, not logos skips: logos restarts after a
    // skip by a call that debug builds do not turn into a loop, so a long run of comments would
    // overflow the stack.
    #[regex(r"//[^\r\n]*", allow_greedy = true)]
    LineComment,
    // letters beyond ASCII are read into the word (reported once per name: E1089)
    #[regex(r"[A-Za-z_\p{L}][A-Za-z0-9_\p{L}\p{N}]*")]
    Word,
    #[regex(r"[A-Za-z_][A-Za-z0-9_]*#", prefixed)]
    Prefixed(Option<TimeValue>),
    #[regex(r"[0-9][0-9_]*", |l| literal::decimal_int(l.slice()).map_err(LexError::BadLiteral))]
    #[regex(r"[0-9]+#[0-9A-Za-z_]*", |l| literal::based_int(l.slice()).map_err(LexError::BadLiteral))]
    Int(i128),
    #[regex(r"[0-9][0-9_]*\.[0-9][0-9_]*([eE][+-]?[0-9]+)?", |l| literal::real(l.slice()).map_err(LexError::BadLiteral))]
    #[regex(r"[0-9][0-9_]*[eE][+-]?[0-9]+", |l| literal::real(l.slice()).map_err(LexError::BadLiteral))]
    Real(f64),
    #[token("'", |l| string(l, false))]
    #[token("\"", |l| string(l, true))]
    Str((bool, String)),
    #[regex(r"%[A-Za-z0-9_.*]*", address)]
    Address((Area, AddressSize, Vec<u32>)),
    #[token("(")]
    LParen,
    #[token(")")]
    RParen,
    #[token("[")]
    LBracket,
    #[token("]")]
    RBracket,
    #[token(",")]
    Comma,
    #[token(";")]
    Semi,
    #[token(":")]
    Colon,
    #[token(":=")]
    Assign,
    #[token("?=")]
    AttemptAssign,
    #[token("=>")]
    Arrow,
    #[token("..")]
    DotDot,
    #[token(".")]
    Dot,
    #[token("&")]
    Amp,
    #[token("+")]
    Plus,
    #[token("-")]
    Minus,
    #[token("*")]
    Star,
    #[token("**")]
    Power,
    #[token("/")]
    Slash,
    #[token("<")]
    Lt,
    #[token(">")]
    Gt,
    #[token("<=")]
    Le,
    #[token(">=")]
    Ge,
    #[token("=")]
    Eq,
    #[token("<>")]
    Ne,
    #[token("^")]
    Caret,
}

/// ST keywords (reserved: never names).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
pub enum Kw {
    /// `IF`: opens a conditional.
    If,
    /// `THEN`: ends an IF/ELSIF condition.
    Then,
    /// `ELSIF`: another condition of an IF.
    Elsif,
    /// `ELSE`: the default branch of IF or CASE.
    Else,
    /// `END_IF`: closes an IF.
    EndIf,
    /// `CASE`: opens a selection.
    Case,
    /// `OF`: ends the CASE selector.
    Of,
    /// `END_CASE`: closes a CASE.
    EndCase,
    /// `FOR`: opens a counted loop.
    For,
    /// `TO`: the end value of a FOR.
    To,
    /// `BY`: the step of a FOR.
    By,
    /// `DO`: starts a FOR or WHILE body.
    Do,
    /// `END_FOR`: closes a FOR.
    EndFor,
    /// `WHILE`: opens a pre-tested loop.
    While,
    /// `END_WHILE`: closes a WHILE.
    EndWhile,
    /// `REPEAT`: opens a post-tested loop.
    Repeat,
    /// `UNTIL`: the end condition of a REPEAT.
    Until,
    /// `END_REPEAT`: closes a REPEAT.
    EndRepeat,
    /// `EXIT`: leaves the innermost loop.
    Exit,
    /// `CONTINUE`: next iteration of the innermost loop (edition 3).
    Continue,
    /// `RETURN`: leaves the POU.
    Return,
    /// `AND`: Boolean/bitwise AND operator.
    And,
    /// `OR`: Boolean/bitwise OR operator.
    Or,
    /// `XOR`: exclusive OR operator.
    Xor,
    /// `NOT`: complement operator.
    Not,
    /// `MOD`: remainder operator.
    Mod,
    /// `TRUE`: Boolean literal.
    True,
    /// `FALSE`: Boolean literal.
    False,
}

/// THE keyword table (case-insensitive); `None` for a name.
pub fn keyword(word: &str) -> Option<Kw> {
    let mut buf = [0u8; 12];
    if word.len() > buf.len() {
        return None;
    }
    let up = &mut buf[..word.len()];
    up.copy_from_slice(word.as_bytes());
    up.make_ascii_uppercase();
    use Kw::*;
    Some(match &*up {
        b"IF" => If,
        b"THEN" => Then,
        b"ELSIF" => Elsif,
        b"ELSE" => Else,
        b"END_IF" => EndIf,
        b"CASE" => Case,
        b"OF" => Of,
        b"END_CASE" => EndCase,
        b"FOR" => For,
        b"TO" => To,
        b"BY" => By,
        b"DO" => Do,
        b"END_FOR" => EndFor,
        b"WHILE" => While,
        b"END_WHILE" => EndWhile,
        b"REPEAT" => Repeat,
        b"UNTIL" => Until,
        b"END_REPEAT" => EndRepeat,
        b"EXIT" => Exit,
        b"CONTINUE" => Continue,
        b"RETURN" => Return,
        b"AND" => And,
        b"OR" => Or,
        b"XOR" => Xor,
        b"NOT" => Not,
        b"MOD" => Mod,
        b"TRUE" => True,
        b"FALSE" => False,
        _ => return None,
    })
}

impl Kw {
    /// The keyword upper case, as the standard writes it (for messages).
    pub fn spelling(self) -> &'static str {
        use Kw::*;
        match self {
            If => "IF",
            Then => "THEN",
            Elsif => "ELSIF",
            Else => "ELSE",
            EndIf => "END_IF",
            Case => "CASE",
            Of => "OF",
            EndCase => "END_CASE",
            For => "FOR",
            To => "TO",
            By => "BY",
            Do => "DO",
            EndFor => "END_FOR",
            While => "WHILE",
            EndWhile => "END_WHILE",
            Repeat => "REPEAT",
            Until => "UNTIL",
            EndRepeat => "END_REPEAT",
            Exit => "EXIT",
            Continue => "CONTINUE",
            Return => "RETURN",
            And => "AND",
            Or => "OR",
            Xor => "XOR",
            Not => "NOT",
            Mod => "MOD",
            True => "TRUE",
            False => "FALSE",
        }
    }
}

/// The parser's tokens.
#[derive(Debug, Clone, PartialEq)]
pub enum Tok {
    /// A name (any word that is not a keyword); the text is the token's range.
    Ident,
    /// A keyword (see [`Kw`]).
    Kw(Kw),
    /// An integer literal `12`, `16#FF` (no sign: the parser folds `-`).
    Int(i128),
    /// A real literal `2.5`, `1.0E3`.
    Real(f64),
    /// A `T#`/`D#`/`TOD#`/`DT#` literal, decoded.
    Time(TimeValue),
    /// A string literal: wide flag (`"..."`) and decoded characters.
    Str(bool, String),
    /// `INT#`, `Color#`: a typed literal or enum value follows; the name is the text without `#`.
    TypePrefix,
    /// A direct address `%IX0.1`: area, size, location numbers.
    Address(Area, AddressSize, Vec<u32>),
    /// `(`: opens a call's arguments or a parenthesised expression.
    LParen,
    /// `)`
    RParen,
    /// `[`: opens array subscripts.
    LBracket,
    /// `]`
    RBracket,
    /// `,`: separates arguments, subscripts and CASE labels.
    Comma,
    /// `;`: ends a statement.
    Semi,
    /// `:`: ends a CASE label list.
    Colon,
    /// `:=` (assignment, input argument).
    Assign,
    /// `?=` (IEC 61131-3 ed. 3 assignment attempt).
    AttemptAssign,
    /// `=>` (output argument).
    Arrow,
    /// `..` (a CASE range).
    DotDot,
    /// `.` (field access).
    Dot,
    /// `&` (AND).
    Amp,
    /// `+`: addition or unary plus.
    Plus,
    /// `-`: subtraction or negation.
    Minus,
    /// `*`: multiplication.
    Star,
    /// `**`: exponentiation.
    Power,
    /// `/`: division.
    Slash,
    /// `<`
    Lt,
    /// `>`
    Gt,
    /// `<=`
    Le,
    /// `>=`
    Ge,
    /// `=`: equality (assignment is `:=`).
    Eq,
    /// `<>`: inequality.
    Ne,
    /// `^` (pointer dereference: not supported, the parser reports E0108).
    Caret,
    /// Text the lexer could not read (reported as a [`Problem`]).
    Error,
    /// End of the text (zero-width, always last).
    Eof,
}

/// A token and its byte range in the lexed text.
#[derive(Debug, Clone, PartialEq)]
pub struct Token {
    /// The token kind, with its decoded value for literals.
    pub tok: Tok,
    /// Its byte range in the lexed text.
    pub range: Range<usize>,
}

/// What went wrong where (byte range in the lexed text).
#[derive(Debug, Clone, PartialEq)]
pub enum Problem {
    /// A character that starts no token.
    UnexpectedChar(Range<usize>),
    /// A name with letters beyond ASCII (`Мотор`): read as a name, reported (E1089).
    NonAsciiName(Range<usize>),
    /// `(*` or `{` never closed.
    UnterminatedComment(Range<usize>),
    /// A string without its closing quote.
    UnterminatedString(Range<usize>),
    /// A literal or direct address with no valid value, and why.
    BadLiteral(Range<usize>, String),
    /// An invalid `$` escape inside a string (the string is still usable).
    BadEscape(Range<usize>, String),
    /// A `{ ... }` or `{{ ... }}` pragma (skipped; reported by [`pragma_diagnostic`]).
    Pragma(Range<usize>),
    /// A `(* ... *)` comment holding a `(*` without its own `*)`: nesting leaves it unclosed, so it
    /// ends at its first `*)` (IEC 61131-3 edition 2, matiec); warning W0015.
    FlatComment(Range<usize>),
    /// Two string literals with nothing between them (`'it''s'`): a quote written doubled, as SQL
    /// and STruCpp read it, where IEC 61131-3 writes `$'` (`$"` in a WSTRING). The range is the two
    /// quotes; the literals are read as one string holding the quote, so nothing else follows.
    DoubledQuote(Range<usize>),
    /// A time-of-day or date-and-time literal without seconds (`TOD#12:00`): read as `:00`, as
    /// CODESYS reads it; warning W1445 (IEC 61131-3 requires the seconds).
    NoSeconds(Range<usize>),
    /// A decimal literal ending in its point (`10.`, CODESYS V2.3): read as the REAL `10.0`, as
    /// CODESYS compiles it; warning W1459 (IEC 61131-3 requires a digit after the point).
    TrailingPoint(Range<usize>),
}

/// Lexes `src`; the token list always ends with [`Tok::Eof`].
pub fn lex(src: &str) -> (Vec<Token>, Vec<Problem>) {
    let mut out = Vec::new();
    let mut problems = Vec::new();
    let mut lx = Raw::lexer(src);
    while let Some(r) = lx.next() {
        let range = lx.span();
        let tok = match r {
            Ok(Raw::Word) if !lx.slice().is_ascii() => {
                problems.push(Problem::NonAsciiName(range.clone()));
                Tok::Ident
            }
            Ok(Raw::Word) => match keyword(lx.slice()) {
                Some(k) => Tok::Kw(k),
                None => Tok::Ident,
            },
            Ok(Raw::Prefixed(Some(t))) => {
                if matches!(t, TimeValue::TimeOfDay(..) | TimeValue::DateAndTime(..))
                    && literal::lacks_seconds(&src[range.clone()])
                {
                    problems.push(Problem::NoSeconds(range.clone()));
                }
                Tok::Time(t)
            }
            Ok(Raw::Prefixed(None)) => Tok::TypePrefix,
            // `10.`: the REAL 10.0 (W1459, see `trailing_point`)
            Ok(Raw::Int(v)) if trailing_point(src, &range, out.last()) => {
                lx.bump(1);
                let range = range.start..range.end + 1;
                problems.push(Problem::TrailingPoint(range.clone()));
                out.push(Token {
                    tok: Tok::Real(v as f64),
                    range,
                });
                continue;
            }
            Ok(Raw::Int(v)) => Tok::Int(v),
            Ok(Raw::Real(v)) => Tok::Real(v),
            Ok(Raw::Str((w, s))) => match out.last() {
                // `'it''s'`: one string holding a quote, and E0103 at the doubled quote
                Some(Token {
                    tok: Tok::Str(pw, ps),
                    range: pr,
                }) if *pw == w && pr.end == range.start => {
                    let merged = format!("{ps}{}{s}", if w { '"' } else { '\'' });
                    let start = pr.start;
                    out.pop();
                    problems.push(Problem::DoubledQuote(range.start - 1..range.start + 1));
                    out.push(Token {
                        tok: Tok::Str(w, merged),
                        range: start..range.end,
                    });
                    continue;
                }
                _ => Tok::Str(w, s),
            },
            Ok(Raw::Address((a, s, p))) => Tok::Address(a, s, p),
            Ok(Raw::LParen) => Tok::LParen,
            Ok(Raw::RParen) => Tok::RParen,
            Ok(Raw::LBracket) => Tok::LBracket,
            Ok(Raw::RBracket) => Tok::RBracket,
            Ok(Raw::Comma) => Tok::Comma,
            Ok(Raw::Semi) => Tok::Semi,
            Ok(Raw::Colon) => Tok::Colon,
            Ok(Raw::Assign) => Tok::Assign,
            Ok(Raw::AttemptAssign) => Tok::AttemptAssign,
            Ok(Raw::Arrow) => Tok::Arrow,
            Ok(Raw::DotDot) => Tok::DotDot,
            Ok(Raw::Dot) => Tok::Dot,
            Ok(Raw::Amp) => Tok::Amp,
            Ok(Raw::Plus) => Tok::Plus,
            Ok(Raw::Minus) => Tok::Minus,
            Ok(Raw::Star) => Tok::Star,
            Ok(Raw::Power) => Tok::Power,
            Ok(Raw::Slash) => Tok::Slash,
            Ok(Raw::Lt) => Tok::Lt,
            Ok(Raw::Gt) => Tok::Gt,
            Ok(Raw::Le) => Tok::Le,
            Ok(Raw::Ge) => Tok::Ge,
            Ok(Raw::Eq) => Tok::Eq,
            Ok(Raw::Ne) => Tok::Ne,
            Ok(Raw::Caret) => Tok::Caret,
            Ok(Raw::Pragma) => {
                problems.push(Problem::Pragma(range));
                continue;
            }
            Ok(Raw::Comment) => {
                // a `(*` comment that nesting leaves unclosed inside its own text was closed by
                // its first `*)` (see `block_comment`)
                let text = &src[range.clone()];
                if let Some(inner) = text.strip_prefix("(*") {
                    if inner.contains("(*")
                        && matches!(
                            lexer::comment_rest(inner).1,
                            lexer::CommentEnd::Unterminated
                        )
                    {
                        problems.push(Problem::FlatComment(range));
                    }
                }
                continue;
            }
            Ok(Raw::LineComment) => continue,
            // `x.%X3`, `x.%B1`: a partial access after a dot (3rd edition), an identifier for the parser
            Err(LexError::BadAddress(_))
                if src[..range.start].ends_with('.')
                    && !src[..range.start].ends_with("..")
                    && crate::ast::partial_access(lx.slice()).is_some() =>
            {
                Tok::Ident
            }
            // `16#D013THEN`: a based literal run into the keyword after it (TwinCAT compiles it:
            // the literal ends at its last digit, as the longest-match rule of IEC 61131-3's
            // token grammar reads it). Only a keyword tail splits: `16#FG` stays E0103.
            Err(LexError::BadLiteral(_)) if based_then_keyword(lx.slice()).is_some() => {
                let (digits, k) = based_then_keyword(lx.slice()).expect("checked");
                let v = literal::based_int(&lx.slice()[..digits]).expect("checked");
                out.push(Token {
                    tok: Tok::Int(v),
                    range: range.start..range.start + digits,
                });
                out.push(Token {
                    tok: Tok::Kw(k),
                    range: range.start + digits..range.end,
                });
                continue;
            }
            // `register^.%Xpin` (RuSTy): a partial access whose bit is a variable
            Err(LexError::BadAddress(_))
                if src[..range.start].ends_with('.') && partial_by_variable(lx.slice()) =>
            {
                problems.push(Problem::BadLiteral(
                    range.clone(),
                    format!(
                        "`{}` names its part by a variable: a partial access takes a number (`x.%X3`), as IEC 61131-3 writes it",
                        lx.slice()
                    ),
                ));
                Tok::Error
            }
            Err(e) => {
                problems.push(match e {
                    LexError::UnexpectedChar => Problem::UnexpectedChar(range.clone()),
                    LexError::UnterminatedComment => Problem::UnterminatedComment(range.clone()),
                    LexError::UnterminatedString => Problem::UnterminatedString(range.clone()),
                    LexError::BadLiteral(why) | LexError::BadAddress(why) => {
                        Problem::BadLiteral(range.clone(), why)
                    }
                });
                Tok::Error
            }
        };
        out.push(Token { tok, range });
    }
    for (range, why) in std::mem::take(&mut lx.extras) {
        problems.push(Problem::BadEscape(range, why));
    }
    out.push(Token {
        tok: Tok::Eof,
        range: src.len()..src.len(),
    });
    (out, problems)
}

/// `%Xpin`, `%Bk`: a partial access's size letter followed by a name (RuSTy accepts a variable
/// there; IEC 61131-3 a number).
fn partial_by_variable(text: &str) -> bool {
    let mut c = text.chars();
    c.next() == Some('%')
        && matches!(
            c.next(),
            Some('X' | 'x' | 'B' | 'b' | 'W' | 'w' | 'D' | 'd' | 'L' | 'l')
        )
        && c.next()
            .is_some_and(|ch| ch.is_ascii_alphabetic() || ch == '_')
}

/// For a based literal whose letters run into a keyword (`16#D013THEN`, `2#1010AND`): the length
/// of the literal (up to its last digit, which must leave at least one) and the keyword.
fn based_then_keyword(text: &str) -> Option<(usize, Kw)> {
    let (base, digits) = text.split_once('#')?;
    let radix = match base {
        "2" => 2,
        "8" => 8,
        "16" => 16,
        _ => return None,
    };
    let end = digits
        .char_indices()
        .find(|&(_, c)| c != '_' && !c.is_digit(radix))?
        .0;
    if end == 0 || digits[..end].ends_with('_') {
        return None;
    }
    let k = keyword(&digits[end..])?;
    let len = base.len() + 1 + end;
    literal::based_int(&text[..len]).ok()?;
    Some((len, k))
}

/// Skips a possibly nested `(* ... *)` comment; one that nesting leaves unclosed but a `*)` follows
/// ends at that first `*)` (not nested, as matiec reads it: `lex` reports it, W0015).
fn block_comment(lex: &mut logos::Lexer<Raw>) -> FilterResult<(), LexError> {
    let (n, end) = lexer::comment_rest(lex.remainder());
    match end {
        lexer::CommentEnd::Closed { .. } => {
            lex.bump(n);
            FilterResult::Emit(())
        }
        lexer::CommentEnd::Unterminated => match lexer::flat_comment_len(lex.remainder()) {
            Some(m) => {
                lex.bump(m);
                FilterResult::Emit(())
            }
            None => {
                lex.bump(n);
                FilterResult::Error(LexError::UnterminatedComment)
            }
        },
    }
}

/// Skips a possibly nested `/* ... */` comment (IEC 61131-3 ed. 3, Table 3).
fn slash_block_comment(lex: &mut logos::Lexer<Raw>) -> FilterResult<(), LexError> {
    let (n, end) = lexer::slash_comment_rest(lex.remainder());
    lex.bump(n);
    match end {
        lexer::CommentEnd::Closed { .. } => FilterResult::Emit(()),
        lexer::CommentEnd::Unterminated => FilterResult::Error(LexError::UnterminatedComment),
    }
}

/// Skips a `{ ... }` pragma (CODESYS attributes, Beremiz annotations and C code): braces nest, so
/// `{{ ... }}` and C blocks `{ if (x) { y(); } }` end at their own closing brace.
fn pragma(lex: &mut logos::Lexer<Raw>) -> Result<(), LexError> {
    match pragma_len(lex.remainder()) {
        Some(n) => {
            lex.bump(n);
            Ok(())
        }
        None => {
            lex.bump(lex.remainder().len());
            Err(LexError::UnterminatedComment)
        }
    }
}

/// The length of a pragma's rest after its opening `{` (up to and including the matching `}`), or
/// `None` when it is never closed. Braces inside C string or character literals are not counted.
///
/// An attribute or other informational pragma (`{attribute 'strict'}`) does not nest: the CODESYS
/// help gives its syntax as `{attribute '<name>' ...}` with no braces inside, and it ends at its first
/// `}`. So a project whose `{attribute 'qualified only'` lacks its `}` (SeanyCash/TwinCAT_CNC) reads
/// up to the next pragma's `}` as one informational pragma instead of swallowing the whole file.
pub fn pragma_len(rest: &str) -> Option<usize> {
    // the pragma's first 40 characters tell its kind (a character may be several bytes)
    let head = rest
        .char_indices()
        .nth(40)
        .map_or(rest, |(i, _)| &rest[..i]);
    if !rest.starts_with('{') && pragma_kind(&format!("{{{head}")) == PragmaKind::Informational {
        return rest.find('}').map(|i| i + 1);
    }
    let mut depth = 1usize;
    let mut quote: Option<u8> = None;
    let b = rest.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        match quote {
            Some(q) => {
                if c == b'\\' {
                    i += 1;
                } else if c == q {
                    quote = None;
                }
            }
            None => match c {
                b'"' => quote = Some(c),
                b'{' => depth += 1,
                b'}' => {
                    depth -= 1;
                    if depth == 0 {
                        return Some(i + 1);
                    }
                }
                _ => {}
            },
        }
        i += 1;
    }
    None
}

/// What a pragma is: informational (an attribute, a message, a region, conditional-compilation text
/// that IEC leaves to the implementation) or code (Beremiz `{ C code }` / `{{ C code }}`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PragmaKind {
    /// Attributes, messages, regions, TwinCAT's `{flow}` / `{noflow}` / `{analysis ...}`, an empty
    /// `{}`: ignored, with note W0301.
    Informational,
    /// Beremiz embedded C (`{ C code }`, `{{ ... }}`): not compiled, warning W0300.
    Code,
}

/// Whether `text` is a B&R redundancy pragma (`{REDUND_ERROR}`): [`pragma_kind`] reads it as
/// informational, and a file reports only its first.
pub fn is_redundancy_pragma(text: &str) -> bool {
    let inner = text.trim_start_matches('{').trim_end_matches('}').trim();
    inner.len() > 7
        && inner
            .get(..7)
            .is_some_and(|head| head.eq_ignore_ascii_case("REDUND_"))
        && inner.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Whether `text` (a pragma with its braces) is a description or attribute of its declaration:
/// `{ key:"text" }` or `{key=value}`, one key (dotted parts allowed) and one value (a quoted
/// string, or a word, number or reference without blanks): CODESYS-based editors' descriptions
/// (`{ DE:"Heater relay" }`, `{G:"EEPROM_Parameters"}`), SIMATIC AX's attributes
/// (`{s7.extern=ReadWrite}`) and AX Code's links from a declaration to its documentation page
/// (`{axcode:docs-v0:@simatic-ax/conversion:TRUNC.md}`: a package and a Markdown file, round 30).
/// IEC 61131-3 ed. 3 (6.2) leaves pragmas to the implementation, and CODESYS reads a pragma it
/// cannot interpret as a comment; such a pair is metadata, no code (Beremiz's C code has
/// statements: `;`, parentheses, blanks).
pub fn is_metadata_pragma(text: &str) -> bool {
    if text.starts_with("{{") {
        return false;
    }
    let inner = text.trim_start_matches('{').trim_end_matches('}').trim();
    let key_len = inner
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '.'))
        .unwrap_or(inner.len());
    let key = &inner[..key_len];
    if key.is_empty()
        || !key.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        || key.ends_with('.')
    {
        return false;
    }
    let rest = inner[key_len..].trim_start();
    let Some(value) = rest.strip_prefix([':', '=']) else {
        return false;
    };
    let value = value.trim();
    let quoted = |q: char| {
        value.len() >= 2
            && value.starts_with(q)
            && value.ends_with(q)
            && !value[1..value.len() - 1].contains(q)
    };
    quoted('"')
        || quoted('\'')
        || (!value.is_empty()
            && value.chars().all(|c| {
                c.is_ascii_alphanumeric()
                    || matches!(c, '_' | '.' | '#' | '-' | '+' | ':' | '@' | '/')
            }))
}

/// The message prefix of the note of a description or attribute pragma ([`is_metadata_pragma`]):
/// [`collapse_metadata_notes`] finds them by it.
const METADATA_NOTE: &str = "description or attribute pragma";

/// One note per file for its description and attribute pragmas ([`is_metadata_pragma`]; a
/// CODESYS-based global list has one per variable): the first kept, its message naming how many
/// others the file has.
pub fn collapse_metadata_notes(diags: &mut diagnostics::Diagnostics) {
    use std::collections::HashMap;
    let is_meta = |d: &diagnostics::Diagnostic| {
        d.code == diagnostics::code::W0301 && d.message.starts_with(METADATA_NOTE)
    };
    // per file: the first (by position) and the count of the others
    let mut first: HashMap<crate::FileId, (diagnostics::Diagnostic, usize)> = HashMap::new();
    for d in diags.iter().filter(|d| is_meta(d)) {
        let Some(span) = d.span else { continue };
        match first.get_mut(&span.file) {
            Some((kept, n)) => {
                *n += 1;
                if kept.span.is_some_and(|k| span.start < k.start) {
                    *kept = d.clone();
                }
            }
            None => {
                first.insert(span.file, (d.clone(), 0));
            }
        }
    }
    if first.values().all(|(_, n)| *n == 0) {
        return;
    }
    diags.retain(|d| !is_meta(d) || d.span.is_some_and(|s| first[&s.file].1 == 0));
    let mut kept: Vec<_> = first.into_values().filter(|(_, n)| *n > 0).collect();
    kept.sort_by_key(|(d, _)| d.span.map(|s| (s.file, s.start)));
    for (mut d, n) in kept {
        // (in the message: a diagnostic equal to one already pushed is not pushed again)
        d.message = if n == 1 {
            format!("{} (and the file's other one)", d.message)
        } else {
            format!("{} (and the file's {n} others)", d.message)
        };
        diags.push(d);
    }
}

/// Classifies the full text of a pragma (with its braces).
pub fn pragma_kind(text: &str) -> PragmaKind {
    let inner = text
        .trim_start_matches('{')
        .trim_end_matches('}')
        .trim_start();
    let word: String = inner
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect::<String>()
        .to_ascii_lowercase();
    const INFO: &[&str] = &[
        "attribute",
        "warning",
        "error",
        "info",
        "text",
        "library",
        "region",
        "endregion",
        "messageguid",
        "bitmap",
        "flag",
        "author",
        "version",
        "description",
        "implicit",
        // TwinCAT / CODESYS: flow control of online monitoring, static-analysis switches
        "flow",
        "noflow",
        "analysis",
    ];
    // B&R Automation Studio's redundancy pragmas (`{REDUND_OK}`, `{REDUND_ERROR}`,
    // `{REDUND_UNREPLICABLE}` before a library's blocks and inputs): for its redundant controllers
    let redund = word.starts_with("redund_") && inner.trim_end().len() == word.len();
    if !text.starts_with("{{")
        && (inner.trim().is_empty()
            || INFO.contains(&word.as_str())
            || redund
            || is_metadata_pragma(text))
    {
        PragmaKind::Informational
    } else {
        PragmaKind::Code
    }
}

/// The diagnostic of a pragma at `span` whose text is `text`: W0300 (its code does not run) for code
/// pragmas, a W0301 note for informational ones.
pub fn pragma_diagnostic(text: &str, span: crate::Span) -> diagnostics::Diagnostic {
    use diagnostics::{code, Diagnostic, Severity};
    let shown = short_text(text);
    match pragma_kind(text) {
        PragmaKind::Informational if text[1..].contains('{') => {
            // An attribute whose `}` is missing runs into the next pragma (see [`pragma_len`]).
            let first = text[1..].find('{').map_or(text, |i| text[..=i].trim_end());
            Diagnostic::warning(
                code::W1420,
                format!(
                    "pragma `{}` is not closed before the next `{{`: both are read as one informational pragma",
                    short_text(first)
                ),
            )
            .at(span)
            .with_hint("close the pragma with `}` (`{attribute 'qualified_only'}`); ladderc reads neither attribute either way")
        }
        PragmaKind::Informational if is_metadata_pragma(text) => Diagnostic::new(
            code::W0301,
            Severity::Note,
            format!("{METADATA_NOTE} `{shown}` is ignored"),
        )
        .at(span)
        .with_hint("a `{ key:\"text\" }` or `{key=value}` pragma describes its declaration (an editor's description, an export attribute, a link to its documentation); it changes nothing in the compiled program"),
        PragmaKind::Informational => Diagnostic::new(
            code::W0301,
            Severity::Note,
            format!("pragma `{shown}` is informational and is ignored"),
        )
        .at(span)
        .with_hint("of the attributes ladderc reads only 'to_string', 'strict' and 'call_after_init'; this pragma changes nothing in the compiled program"),
        PragmaKind::Code => Diagnostic::warning(
            code::W0300,
            format!("pragma `{shown}` holds code that does not run"),
        )
        .at(span)
        .with_primary_label("this code is not compiled")
        .with_hint(
            "ladderc compiles no C or other code from pragmas; write the behaviour in ST (e.g. assign the output) or call a FUNCTION",
        ),
    }
}

/// Warning W0015 for a `(*` comment read without nesting (see [`Problem::FlatComment`]): at its
/// opening, with a label at the `*)` that closes it. `whole` is the whole comment.
pub fn flat_comment_diagnostic(whole: crate::Span) -> diagnostics::Diagnostic {
    use diagnostics::{code, Diagnostic};
    let (start, end) = (whole.start as usize, whole.end as usize);
    let open = crate::Span::new(whole.file, start, (start + 2).min(end));
    let close = crate::Span::new(whole.file, end.saturating_sub(2).max(start), end);
    Diagnostic::warning(
        code::W0015,
        "this comment holds a `(*` without its own `*)`: it ends at the first `*)`, not nested",
    )
    .at(open)
    .with_primary_label("comment opened here")
    .with_label(close, "closed here (what follows is compiled)")
    .with_hint("IEC 61131-3 edition 2 and matiec end a comment at its first `*)`, edition 3 may nest comments; close each `(*` with its own `*)` if the text after this `*)` belongs to the comment")
}

/// A decimal integer literal at `range` followed by a point that ends the number (`10.;`,
/// `10. * x`, `10.)`): CODESYS V2.3 compiles it as the REAL `10.0` (its exports hold `x / 10.;`),
/// where IEC 61131-3's `real_literal` needs a digit after the point. Not when a digit, a second
/// point (`1..10`), a letter or `_` follows the point, nor after a `.` (`w.1`, a bit access), nor for
/// a based literal (`16#FF`).
fn trailing_point(src: &str, range: &Range<usize>, before: Option<&Token>) -> bool {
    let Some(digits) = src.get(range.clone()) else {
        return false;
    };
    let Some(rest) = src.get(range.end..).and_then(|r| r.strip_prefix('.')) else {
        return false;
    };
    let ends = rest
        .chars()
        .next()
        .is_none_or(|c| !(c.is_alphanumeric() || c == '_' || c == '.' || c == '%'));
    ends && digits.bytes().all(|b| b.is_ascii_digit() || b == b'_')
        && !before.is_some_and(|t| t.tok == Tok::Dot)
}

/// W1459 for a REAL literal ending in its point (`10.`) at `span`, read as `10.0`.
pub fn trailing_point_diagnostic(span: crate::Span, text: &str) -> diagnostics::Diagnostic {
    use diagnostics::{code, Diagnostic};
    Diagnostic::warning(
        code::W1459,
        format!("`{text}` has no digit after its point: read as the REAL `{text}0`, as CODESYS reads it"),
    )
    .at(span)
    .with_hint(format!("IEC 61131-3 requires a digit after the point: write `{text}0`"))
}

/// W1445 for a time-of-day or date-and-time literal without seconds (`TOD#12:00`) at `span`: the
/// same warning in ST, IL and PLCopen XML initial values.
pub fn no_seconds_diagnostic(span: crate::Span, text: &str) -> diagnostics::Diagnostic {
    use diagnostics::{code, Diagnostic};
    Diagnostic::warning(
        code::W1445,
        format!("`{text}` has no seconds: read as `:00`, as CODESYS reads it"),
    )
    .at(span)
    .with_hint("IEC 61131-3 requires the seconds (`TOD#12:00:00`, `DT#1970-01-01-00:00:00`); add `:00` to silence this warning")
}

/// E1089 for a name with letters beyond ASCII (`Мотор`, `Motor_ä`): IEC 61131-3 names are letters,
/// digits and `_` of ISO 646; CODESYS 3 accepts international letters. The name is read as a name
/// (its other uses report nothing more) and [`diagnostics::Diagnostics`] keeps one E1089 per name
/// and file.
pub fn non_ascii_name_diagnostic(span: crate::Span, name: &str) -> diagnostics::Diagnostic {
    use diagnostics::{code, Diagnostic};
    Diagnostic::error(
        code::E1089,
        format!("the name `{name}` has letters beyond ASCII: not supported"),
    )
    .at(span)
    .with_hint("IEC 61131-3 names are ASCII letters, digits and `_` (CODESYS 3 also accepts international letters): rename it, e.g. `Motor` for `Мотор` (reported once per name and file)")
}

/// A pragma's text on one line, at most 60 characters (cut at a character boundary).
fn short_text(text: &str) -> String {
    let one: String = text.split_whitespace().collect::<Vec<_>>().join(" ");
    if one.chars().count() > 60 {
        let cut: String = one.chars().take(57).collect();
        format!("{cut}...")
    } else {
        one
    }
}

/// Scans a string body after its opening quote, decoding `$` escapes (invalid ones go to `extras`).
fn string(lex: &mut logos::Lexer<Raw>, wide: bool) -> Result<(bool, String), LexError> {
    let body_start = lex.span().end;
    let (n, value) = lexer::string_rest(lex.remainder(), wide, body_start, &mut lex.extras);
    lex.bump(n);
    value
}

/// `%IX0.1`, `%QW3`, `%MD10`, `%I*`.
fn address(lex: &mut logos::Lexer<Raw>) -> Result<(Area, AddressSize, Vec<u32>), LexError> {
    lexer::direct_address(lex.slice())
}

/// `INT#`, `T#1h`, `DATE#2001-04-09` ...: the date/time families are decoded right away (their bodies
/// contain `:` `-` `.`); other prefixes stay prefixes.
fn prefixed(lex: &mut logos::Lexer<Raw>) -> Result<Option<TimeValue>, LexError> {
    let (n, value) = lexer::prefixed_rest(lex.slice(), lex.remainder());
    lex.bump(n);
    value
}

#[cfg(test)]
mod tests {
    use super::*;

    fn toks(src: &str) -> Vec<Tok> {
        lex(src).0.into_iter().map(|t| t.tok).collect()
    }

    #[test]
    fn a_number_ending_in_its_point_is_a_real() {
        use Tok::*;
        assert_eq!(toks("x / 10.;"), vec![Ident, Slash, Real(10.0), Semi, Eof]);
        assert_eq!(lex("10.").1, vec![Problem::TrailingPoint(0..3)]);
        // a range, a bit, a field, a real with digits: unchanged
        assert_eq!(toks("1..5"), vec![Int(1), DotDot, Int(5), Eof]);
        assert_eq!(toks("w.1.x"), vec![Ident, Dot, Int(1), Dot, Ident, Eof]);
        assert_eq!(toks("1.5"), vec![Real(1.5), Eof]);
        assert_eq!(toks("16#F."), vec![Int(15), Dot, Eof]);
    }

    #[test]
    fn operators_and_signless_numbers() {
        use Tok::*;
        assert_eq!(
            toks("a-1**2<=b<>c>=d&e=>f"),
            vec![
                Ident,
                Minus,
                Int(1),
                Power,
                Int(2),
                Le,
                Ident,
                Ne,
                Ident,
                Ge,
                Ident,
                Amp,
                Ident,
                Arrow,
                Ident,
                Eof
            ]
        );
        assert_eq!(toks("1..5"), vec![Int(1), DotDot, Int(5), Eof]);
        assert_eq!(toks("16#FF 2.5e3"), vec![Int(255), Real(2500.0), Eof]);
    }

    #[test]
    fn keywords_are_case_insensitive_and_comments_nest() {
        assert_eq!(
            toks("if (* a (* b *) *) Then // x\n end_IF {attribute 'x'}"),
            vec![
                Tok::Kw(Kw::If),
                Tok::Kw(Kw::Then),
                Tok::Kw(Kw::EndIf),
                Tok::Eof
            ]
        );
        let (_, p) = lex("x (* open");
        assert!(matches!(p[0], Problem::UnterminatedComment(_)));
    }

    #[test]
    fn literals() {
        use Tok::*;
        let s = literal::NS_PER_S;
        assert_eq!(
            toks("T#1s500ms INT#5 'a$'b'"),
            vec![
                Time(TimeValue::Duration(s + s / 2, false)),
                TypePrefix,
                Int(5),
                Str(false, "a'b".into()),
                Eof
            ]
        );
        let (t, p) = lex("2#102 ?");
        assert_eq!(t[0].tok, Error);
        assert!(matches!(p[0], Problem::BadLiteral(..)));
        assert!(matches!(p[1], Problem::UnexpectedChar(_)));
    }

    #[test]
    fn doubled_quote_is_one_string_and_a_problem() {
        let (t, p) = lex("s := 'it''s' + \"a\"\"b\";");
        assert_eq!(t[2].tok, Tok::Str(false, "it's".into()));
        assert_eq!(t[2].range, 5..12);
        assert_eq!(t[4].tok, Tok::Str(true, "a\"b".into()));
        assert_eq!(p.len(), 2);
        assert!(matches!(&p[0], Problem::DoubledQuote(r) if *r == (8..10)));
        // a space between two literals: two strings, no problem
        let (t, p) = lex("'a' 'b'");
        assert_eq!(t.len(), 3);
        assert!(p.is_empty());
    }
}
