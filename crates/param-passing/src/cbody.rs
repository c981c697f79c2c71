//! Checks of a template's C body before any C compiler sees it.
//!
//! Input: the body text with its file span, the names the head declares (abbreviations, `FuncNum`, template
//! locals) and the symbols the runtime offers. Output: diagnostics pointing into the template file for
//! unbalanced delimiters, unterminated comments/strings, names the head does not declare, and breaches of
//! paper A's rules (no `static`/global storage, no call of another embedded function).
//! Invariant: the token scanner never fails; every byte of the body belongs to exactly one token or gap.

use crate::template::{is_abbreviation, is_reserved_name, CText, C_KEYWORDS};
use diagnostics::{code, Diagnostic, Diagnostics, Span};
use std::collections::BTreeSet;

/// Names every body may use besides its own declarations: fixed-width C types (the first nine) and a few
/// math functions.
pub const C_BASICS: &[&str] = &[
    "uint8_t", "int8_t", "uint16_t", "int16_t", "uint32_t", "int32_t", "uint64_t", "int64_t",
    "size_t", "fabs", "sqrt", "floor", "ceil", "fmod", "fmin", "fmax",
];

/// The kind of a body token.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tok {
    /// An identifier or keyword.
    Ident,
    /// A number literal.
    Number,
    /// A string or character literal.
    Str,
    /// A punctuation byte.
    Punct(u8),
}

/// The deepest nesting of `(`, `[` and `{` a body may have (E4008 beyond; C99's translation limit for
/// parentheses is 63).
pub const MAX_BRACKET_DEPTH: usize = 63;

/// The most elements an array a body declares may have, all dimensions together (E4208 beyond).
pub const MAX_LOCAL_ARRAY: u64 = 4096;

/// Whether `toks`, starting at the `[` after a declared name, are `[N]` groups of decimal sizes whose
/// product is at most [`MAX_LOCAL_ARRAY`].
fn array_size_ok(toks: &[Token], text: &str) -> bool {
    let mut product: u64 = 1;
    let mut k = 0;
    while toks.get(k).is_some_and(|t| t.kind == Tok::Punct(b'[')) {
        let (Some(n), Some(close)) = (toks.get(k + 1), toks.get(k + 2)) else {
            return false;
        };
        if n.kind != Tok::Number || close.kind != Tok::Punct(b']') {
            return false;
        }
        let digits = text[n.start..n.end].trim_end_matches(['u', 'U', 'l', 'L']);
        let Ok(size) = digits.parse::<u64>() else {
            return false;
        };
        product = product.saturating_mul(size);
        if product > MAX_LOCAL_ARRAY {
            return false;
        }
        k += 3;
    }
    true
}

/// A token of a template body: its kind and byte range.
#[derive(Debug, Clone, Copy)]
pub struct Token {
    /// Its kind.
    pub kind: Tok,
    /// Its first byte in the body.
    pub start: usize,
    /// One past its last byte.
    pub end: usize,
}

/// A lexical problem (unterminated comment, string or char literal), at a byte range of the body.
pub struct LexError {
    /// The first byte of the problem.
    pub start: usize,
    /// One past its last byte.
    pub end: usize,
    /// What is unterminated.
    pub what: &'static str,
}

/// Splits C text into tokens, skipping white space, comments and preprocessor-free text.
pub fn tokens(src: &str) -> (Vec<Token>, Vec<LexError>) {
    let b = src.as_bytes();
    let mut out = Vec::new();
    let mut errs = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c.is_ascii_whitespace() {
            i += 1;
        } else if c == b'/' && b.get(i + 1) == Some(&b'/') {
            // A C compiler ends a line at LF, CR LF or a lone CR.
            while i < b.len() && b[i] != b'\n' && b[i] != b'\r' {
                i += 1;
            }
        } else if c == b'/' && b.get(i + 1) == Some(&b'*') {
            match src[i + 2..].find("*/") {
                Some(k) => i = i + 2 + k + 2,
                None => {
                    errs.push(LexError {
                        start: i,
                        end: i + 2,
                        what: "comment is not closed",
                    });
                    i = b.len();
                }
            }
        } else if c.is_ascii_alphabetic() || c == b'_' {
            let s = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
            out.push(Token {
                kind: Tok::Ident,
                start: s,
                end: i,
            });
        } else if c.is_ascii_digit() || (c == b'.' && b.get(i + 1).is_some_and(u8::is_ascii_digit))
        {
            let s = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'.' || b[i] == b'_') {
                // exponent signs: 1e-5
                if (b[i] == b'e' || b[i] == b'E') && matches!(b.get(i + 1), Some(b'+' | b'-')) {
                    i += 1;
                }
                i += 1;
            }
            out.push(Token {
                kind: Tok::Number,
                start: s,
                end: i,
            });
        } else if c == b'"' || c == b'\'' {
            let s = i;
            i += 1;
            let mut closed = false;
            while i < b.len() && b[i] != b'\n' && b[i] != b'\r' {
                if b[i] == b'\\' {
                    i += 1;
                    if let Some(ch) = src.get(i..).and_then(|r| r.chars().next()) {
                        if ch != '\n' && ch != '\r' {
                            i += ch.len_utf8();
                        }
                    }
                    continue;
                }
                if b[i] == c {
                    closed = true;
                    i += 1;
                    break;
                }
                i += 1;
            }
            if closed {
                out.push(Token {
                    kind: Tok::Str,
                    start: s,
                    end: i,
                });
            } else {
                errs.push(LexError {
                    start: s,
                    end: i.min(b.len()),
                    what: if c == b'"' {
                        "string literal is not closed"
                    } else {
                        "character literal is not closed"
                    },
                });
            }
        } else {
            let width = src
                .get(i..)
                .and_then(|r| r.chars().next())
                .map_or(1, char::len_utf8);
            out.push(Token {
                kind: Tok::Punct(if width == 1 { c } else { 0 }),
                start: i,
                end: i + width,
            });
            i += width;
        }
    }
    (out, errs)
}

/// What a body may refer to.
pub struct Scope<'a> {
    /// Names the generated head declares (abbreviations with their instance suffix removed, `FuncNum`, locals).
    pub declared: BTreeSet<String>,
    /// Runtime symbols (functions, types, constants) of the motion library's C header.
    pub runtime: &'a BTreeSet<String>,
    /// Names of every embedded function (FUNC targets): a body must not call them.
    pub embedded_functions: &'a BTreeSet<String>,
}

/// Checks a body; returns whether it is clean (no errors added).
///
/// Beyond balance and names, the checks make the body's tokens the compiler's tokens: no trigraph (E4202),
/// no line splice or `\` outside a literal (E4203), no `#`/`%:` (E4201: no preprocessor directive can
/// appear), no digraph (E4205: `<%` would open a brace the balance check does not see), no character
/// outside C's punctuators, ASCII identifiers and literals (E4204: `$` would join identifiers).
pub fn check(body: &CText, scope: &Scope<'_>, block: &str, diags: &mut Diagnostics) -> bool {
    let before = diags.error_count();
    let at = |s: usize, e: usize| -> Span { body.span_of(s, e) };
    let text = body.text.as_str();
    let raw = text.as_bytes();
    // Phase 1 and 2 of C translation, which happen before tokens exist: trigraphs and line splices.
    for (i, w) in raw.windows(3).enumerate() {
        if w[0] == b'?' && w[1] == b'?' && b"=/'()!<>-".contains(&w[2]) {
            diags.push(
                Diagnostic::error(
                    code::E4202,
                    format!("the body of template `{block}` contains the trigraph `??{}`", w[2] as char),
                )
                .at(at(i, i + 3))
                .with_hint("write the character itself (C99 replaces `??=` by `#`, `??/` by `\\` ...); in a string, write `?\\?`"),
            );
        }
    }
    for (i, &c) in raw.iter().enumerate() {
        if c != b'\\' {
            continue;
        }
        let rest = &raw[i + 1..];
        let blanks = rest
            .iter()
            .take_while(|b| matches!(b, b' ' | b'\t' | b'\x0c' | b'\x0b'))
            .count();
        if matches!(rest.get(blanks), Some(b'\n' | b'\r')) {
            diags.push(
                Diagnostic::error(
                    code::E4203,
                    format!("the body of template `{block}` splices lines with `\\` at the end of a line"),
                )
                .at(at(i, i + 1))
                .with_hint("join the lines yourself: a splice can hide a directive or split a name"),
            );
        }
    }
    let (toks, errs) = tokens(text);
    for e in errs {
        diags.push(
            Diagnostic::error(
                code::E4008,
                format!("syntax error in the body of template `{block}`: {}", e.what),
            )
            .at(at(e.start, e.end))
            .with_hint("close it; the body is C99 code"),
        );
    }
    // Punctuators: only C's, and no preprocessing ones.
    let line_start = |pos: usize| -> bool {
        // Only white space and comments since the end of the previous token on this line.
        let k = toks.partition_point(|t| t.start < pos);
        k == 0 || text[toks[k - 1].end..pos].contains(['\n', '\r'])
    };
    for (k, t) in toks.iter().enumerate() {
        let Tok::Punct(p) = t.kind else { continue };
        let next = toks
            .get(k + 1)
            .filter(|n| n.start == t.end)
            .and_then(|n| match n.kind {
                Tok::Punct(q) => Some(q),
                _ => None,
            });
        // The pair's end is the next token's end (it may be a multi-byte character: found by the fuzzer).
        let pair_end = toks
            .get(k + 1)
            .filter(|n| n.start == t.end && next.is_some())
            .map_or(t.end, |n| n.end);
        let bad = |code, msg: String, hint: &str| {
            Diagnostic::error(code, msg)
                .at(at(t.start, pair_end))
                .with_hint(hint.to_string())
        };
        match (p, next) {
            (b'#', _) | (b'%', Some(b':')) => {
                let what = if line_start(t.start) {
                    "a preprocessor directive"
                } else {
                    "a `#` operator"
                };
                diags.push(bad(
                    code::E4201,
                    format!("the body of template `{block}` contains {what}"),
                    "bodies are plain C statements: no #include, #define, #if or #pragma (the head and the motion library's header provide every name)",
                ));
            }
            (b'<', Some(b':' | b'%')) | (b':', Some(b'>')) | (b'%', Some(b'>')) => {
                diags.push(bad(
                    code::E4205,
                    format!("the body of template `{block}` contains a digraph"),
                    "write [ ] { } instead of <: :> <% %>",
                ));
            }
            (
                b'{' | b'}' | b'[' | b']' | b'(' | b')' | b'<' | b'>' | b'.' | b',' | b';' | b':'
                | b'?' | b'!' | b'~' | b'+' | b'-' | b'*' | b'/' | b'%' | b'&' | b'|' | b'^' | b'=',
                _,
            ) => {}
            (b'\\', _) => diags.push(
                Diagnostic::error(
                    code::E4203,
                    format!("the body of template `{block}` has `\\` outside a literal"),
                )
                .at(at(t.start, t.end))
                .with_hint("universal character names and splices are not allowed in a body"),
            ),
            _ => {
                let ch = text[t.start..t.end].chars().next().unwrap_or('?');
                diags.push(
                    Diagnostic::error(
                        code::E4204,
                        format!("the body of template `{block}` contains the character {:?} outside a literal or comment", ch),
                    )
                    .at(at(t.start, t.end))
                    .with_hint("names are ASCII letters, digits and `_` (no `$`); other characters belong in strings or comments"),
                );
            }
        }
    }
    // Delimiter balance, and depth: C compilers recurse per level (100,000 `{` kept gcc busy for
    // minutes in the load-time check).
    let mut stack: Vec<(u8, usize, usize)> = Vec::new();
    for t in &toks {
        if let Tok::Punct(p) = t.kind {
            match p {
                b'(' | b'[' | b'{' if stack.len() >= MAX_BRACKET_DEPTH => {
                    diags.push(
                        Diagnostic::error(
                            code::E4008,
                            format!("the body of template `{block}` nests brackets deeper than {MAX_BRACKET_DEPTH} levels"),
                        )
                        .at(at(t.start, t.end))
                        .with_hint("C99 guarantees 63 levels of parentheses and 127 of blocks; keep the body flat"),
                    );
                    stack.clear();
                    break;
                }
                b'(' | b'[' | b'{' => stack.push((p, t.start, t.end)),
                b')' | b']' | b'}' => {
                    let want = match p {
                        b')' => b'(',
                        b']' => b'[',
                        _ => b'{',
                    };
                    match stack.pop() {
                        Some((open, _, _)) if open == want => {}
                        Some((open, s, e)) => {
                            diags.push(
                                Diagnostic::error(
                                    code::E4008,
                                    format!(
                                        "syntax error in the body of template `{block}`: `{}` closes `{}`",
                                        p as char, open as char
                                    ),
                                )
                                .at(at(t.start, t.end))
                                .with_label(at(s, e), "opened here")
                                .with_hint("balance the brackets of the body"),
                            );
                            stack.clear();
                        }
                        None => diags.push(
                            Diagnostic::error(
                                code::E4008,
                                format!("syntax error in the body of template `{block}`: unmatched `{}`", p as char),
                            )
                            .at(at(t.start, t.end))
                            .with_hint("remove it or add the opening bracket"),
                        ),
                    }
                }
                _ => {}
            }
        }
    }
    for (open, s, e) in stack {
        diags.push(
            Diagnostic::error(
                code::E4008,
                format!(
                    "syntax error in the body of template `{block}`: `{}` is never closed",
                    open as char
                ),
            )
            .at(at(s, e))
            .with_hint("add the closing bracket"),
        );
    }
    // Names. A name right after a type name (optionally behind `*`s) is a declaration of a body local.
    let is_type = |name: &str| {
        matches!(
            name,
            "int"
                | "char"
                | "double"
                | "float"
                | "long"
                | "short"
                | "unsigned"
                | "signed"
                | "_Bool"
                | "bool"
                | "void"
        ) || C_BASICS[..9].contains(&name)
            || (scope.runtime.contains(name)
                && (name.ends_with("_t")
                    || name.chars().next().is_some_and(|c| c.is_ascii_uppercase())))
    };
    let mut body_locals: BTreeSet<&str> = BTreeSet::new();
    for (k, t) in toks.iter().enumerate() {
        if t.kind == Tok::Punct(b'*') && toks.get(k + 1).is_some_and(|n| n.kind == Tok::Punct(b')'))
        {
            diags.push(
                Diagnostic::error(code::E4208, format!("the body of template `{block}` casts to a pointer type"))
                    .at(at(t.start, t.end))
                    .with_hint("embedded C reaches memory only through its parameters and the motion library (paper A); take `&local` where the library asks for a pointer"),
            );
        }
        if t.kind != Tok::Ident {
            continue;
        }
        let mut j = k;
        while j > 0 && toks[j - 1].kind == Tok::Punct(b'*') {
            j -= 1;
        }
        if j > 0
            && toks[j - 1].kind == Tok::Ident
            && is_type(&text[toks[j - 1].start..toks[j - 1].end])
        {
            let name = &text[t.start..t.end];
            if j < k {
                diags.push(
                    Diagnostic::error(code::E4208, format!("the body of template `{block}` declares the pointer `{name}`"))
                        .at(at(toks[j].start, t.end))
                        .with_hint("embedded C keeps no pointers (paper A); use a value, or `&local` in a library call"),
                );
            } else if toks.get(k + 1).is_some_and(|n| n.kind == Tok::Punct(b'(')) {
                diags.push(
                    Diagnostic::error(
                        code::E4208,
                        format!("the body of template `{block}` declares the function `{name}`"),
                    )
                    .at(at(t.start, t.end))
                    .with_hint(
                        "a body is the statements of one function; it declares no functions",
                    ),
                );
            } else if toks.get(k + 1).is_some_and(|n| n.kind == Tok::Punct(b'['))
                && !array_size_ok(&toks[k + 1..], text)
            {
                diags.push(
                    Diagnostic::error(
                        code::E4208,
                        format!("the body of template `{block}` declares the array `{name}` larger than {MAX_LOCAL_ARRAY} elements or of no constant size"),
                    )
                    .at(at(t.start, t.end))
                    .with_hint(format!("a body's arrays live on the stack of the scan: give each a decimal size, at most {MAX_LOCAL_ARRAY} elements in all")),
                );
            } else if !is_abbreviation(name)
                || is_reserved_name(name)
                || scope.declared.contains(name)
            {
                diags.push(
                    Diagnostic::error(code::E4206, format!("the body of template `{block}` declares `{name}`, which does not follow the abbreviation rules"))
                        .at(at(t.start, t.end))
                        .with_hint("a body local is 1 to 24 ASCII letters and digits, starting with a letter, and is none of the head's names, a C keyword or a motion-library name"),
                );
            }
            body_locals.insert(name);
        }
    }
    let mut reported = BTreeSet::new();
    for (k, t) in toks.iter().enumerate() {
        if t.kind != Tok::Ident {
            continue;
        }
        let name = &text[t.start..t.end];
        // A member after `.` or `->` is not a free name.
        if k > 0 {
            let prev = toks[k - 1];
            if prev.kind == Tok::Punct(b'.')
                || (prev.kind == Tok::Punct(b'>') && k > 1 && toks[k - 2].kind == Tok::Punct(b'-'))
            {
                continue;
            }
        }
        if name == "static" || name == "extern" {
            diags.push(
                Diagnostic::error(code::E4010, format!("the body of template `{block}` declares `{name}` storage"))
                    .at(at(t.start, t.end))
                    .with_hint("embedded C keeps no globals (paper A): state lives in the controller's shared memory or the motion engine"),
            );
            continue;
        }
        if name == "_Pragma" {
            diags.push(
                Diagnostic::error(
                    code::E4201,
                    format!("the body of template `{block}` contains the `_Pragma` operator"),
                )
                .at(at(t.start, t.end))
                .with_hint("bodies hold no preprocessor directives or pragmas"),
            );
            continue;
        }
        if name == "typedef" {
            diags.push(
                Diagnostic::error(
                    code::E4208,
                    format!("the body of template `{block}` defines a type"),
                )
                .at(at(t.start, t.end))
                .with_hint("use the fixed-width C types and the motion library's structs"),
            );
            continue;
        }
        if C_KEYWORDS.contains(&name)
            || C_BASICS.contains(&name)
            || matches!(name, "bool" | "true" | "false")
        {
            continue;
        }
        let called = toks.get(k + 1).is_some_and(|n| n.kind == Tok::Punct(b'('));
        if called && scope.embedded_functions.contains(name) {
            diags.push(
                Diagnostic::error(
                    code::E4010,
                    format!("the body of template `{block}` calls the embedded function `{name}`"),
                )
                .at(at(t.start, t.end))
                .with_hint("no embedded C function calls another (paper A); call the motion library instead"),
            );
            continue;
        }
        if scope.declared.contains(name)
            || scope.runtime.contains(name)
            || body_locals.contains(name)
        {
            continue;
        }
        if reported.insert(name.to_string()) {
            diags.push(
                Diagnostic::error(code::E4007, format!("the body of template `{block}` uses `{name}`, which the head does not declare"))
                    .at(at(t.start, t.end))
                    .with_hint("use a parameter abbreviation, `FuncNum`, a <local> of the template, or a motion library symbol"),
            );
        }
    }
    diags.error_count() == before
}
