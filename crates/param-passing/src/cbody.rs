//! Checks of a template's C body before any C compiler sees it.
//!
//! Input: the body text with its file span, the names the head declares (abbreviations, `FuncNum`, template
//! locals) and the symbols the runtime offers. Output: diagnostics pointing into the template file for
//! unbalanced delimiters, unterminated comments/strings, names the head does not declare, and breaches of
//! paper A's rules (no `static`/global storage, no call of another embedded function).
//! Invariant: the token scanner never fails; every byte of the body belongs to exactly one token or gap.

use crate::template::{CText, C_KEYWORDS};
use diagnostics::{code, Diagnostic, Diagnostics, Span};
use std::collections::BTreeSet;

/// Names every body may use besides its own declarations: fixed-width C types (the first nine) and a few
/// math functions.
pub const C_BASICS: &[&str] = &[
    "uint8_t", "int8_t", "uint16_t", "int16_t", "uint32_t", "int32_t", "uint64_t", "int64_t",
    "size_t", "fabs", "sqrt", "floor", "ceil", "fmod", "fmin", "fmax",
];

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tok {
    Ident,
    Number,
    Str,
    Punct(u8),
}

#[derive(Debug, Clone, Copy)]
pub struct Token {
    pub kind: Tok,
    pub start: usize,
    pub end: usize,
}

/// A lexical problem (unterminated comment, string or char literal), at a byte range of the body.
pub struct LexError {
    pub start: usize,
    pub end: usize,
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
            while i < b.len() && b[i] != b'\n' {
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
            while i < b.len() && b[i] != b'\n' {
                if b[i] == b'\\' {
                    i += 2;
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
            let width = src[i..].chars().next().map_or(1, char::len_utf8);
            out.push(Token {
                kind: Tok::Punct(if width == 1 { c } else { b'?' }),
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
pub fn check(body: &CText, scope: &Scope<'_>, block: &str, diags: &mut Diagnostics) -> bool {
    let before = diags.error_count();
    let at = |s: usize, e: usize| -> Span {
        if body.verbatim {
            Span::new(
                body.span.file,
                body.span.start as usize + s,
                body.span.start as usize + e,
            )
        } else {
            body.span
        }
    };
    let (toks, errs) = tokens(&body.text);
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
    // Delimiter balance.
    let mut stack: Vec<(u8, usize, usize)> = Vec::new();
    for t in &toks {
        if let Tok::Punct(p) = t.kind {
            match p {
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
        ) || C_BASICS[..9].contains(&name)
            || (scope.runtime.contains(name)
                && (name.ends_with("_t")
                    || name.chars().next().is_some_and(|c| c.is_ascii_uppercase())))
    };
    let mut body_locals: BTreeSet<&str> = BTreeSet::new();
    for (k, t) in toks.iter().enumerate() {
        if t.kind != Tok::Ident {
            continue;
        }
        let mut j = k;
        while j > 0 && toks[j - 1].kind == Tok::Punct(b'*') {
            j -= 1;
        }
        if j > 0
            && toks[j - 1].kind == Tok::Ident
            && is_type(&body.text[toks[j - 1].start..toks[j - 1].end])
        {
            body_locals.insert(&body.text[t.start..t.end]);
        }
    }
    let mut reported = BTreeSet::new();
    for (k, t) in toks.iter().enumerate() {
        if t.kind != Tok::Ident {
            continue;
        }
        let name = &body.text[t.start..t.end];
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
        if C_KEYWORDS.contains(&name) || C_BASICS.contains(&name) {
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
