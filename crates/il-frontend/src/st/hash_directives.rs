//! B&R Automation Studio's preprocessor lines in ST (`#define`, `#ifdef` ... `#else` ... `#endif`),
//! as K5/straton documents the same directives ("Conditional compiling": `#ifdef CONDITION` ...
//! `#else` ... `#endif`, each alone on its line, the condition a name set by `#define`).
//!
//! Input: an ST text. Output: `None` when no line starts with a directive; otherwise the text with
//! every directive line, and every section whose condition is false, blanked (spaces for each
//! byte but line ends, so positions do not move), and the diagnostics: E1058 for a directive
//! ladderc does not read (`#include`, `#if`, `#elif`) and for a `#else`/`#endif` without its
//! `#ifdef` or a `#ifdef` never closed; a W1419 note the first time a condition asks for a name
//! that nothing in the text defines (before: E0023 "this file is Siemens SCL", the rest of the
//! file not compiled). Softing 4CONTROL's `#import "file.gvl"` (MECT's TPAC panels) is blanked
//! too (also written `#IMPORT`: directive words are case-insensitive), with one note W1458 per
//! file: the imported globals are those of the inputs. Its block of constants `CONST ...
//! END_CONST` is one E1095 and the file is not compiled ([`four_control_constants`]); so is its
//! resource file, a `RESOURCE` without its `CONFIGURATION`, one E1094
//! ([`four_control_resource`]).
//!
//! Invariants: sections nest; inside a section not compiled no define changes; a `#if` /
//! `#elif` compiles none of its sections (no branch chosen by guess). Names are case-sensitive as
//! in C. A directive is only recognised at the start of a line (after blanks), and never inside a
//! comment or a string (comments have no meaning, IEC 61131-3 ed. 3 6.1.5: a `#ifdef` line inside
//! `(* ... *)` is text of the comment).

use crate::lexer::{self, CommentEnd};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics, Severity};
use std::collections::HashSet;

const DIRECTIVES: &[&str] = &[
    "define", "undef", "ifdef", "ifndef", "if", "elif", "else", "endif", "include", "import",
];

/// One open `#ifdef`: whether its current section is compiled, whether an earlier section was,
/// whether the text around it is, and where it opened.
struct Open {
    on: bool,
    taken: bool,
    outer: bool,
    at: (usize, usize),
}

/// See the module documentation.
pub fn hash_directives(file: FileId, src: &str, diags: &mut Diagnostics) -> Option<String> {
    let mut lines: Vec<(usize, &str)> = Vec::new();
    let mut pos = 0;
    for line in src.split_inclusive('\n') {
        lines.push((pos, line));
        pos += line.len();
    }
    fn directive(line: &str) -> Option<(usize, &str, &str)> {
        let lead = line.len() - line.trim_start().len();
        let rest = line.trim_start().strip_prefix('#')?;
        let end = rest
            .find(|c: char| !c.is_ascii_alphabetic())
            .unwrap_or(rest.len());
        // directive words are case-insensitive as IEC 61131-3 keywords are (4CONTROL writes
        // `#IMPORT` in its configuration and resource files, `#import` in POUs); B&R's and
        // K5's `#ifdef` family is written in lower case, which this keeps
        let word = DIRECTIVES
            .iter()
            .copied()
            .find(|d| d.eq_ignore_ascii_case(&rest[..end]))
            .unwrap_or(&rest[..end]);
        DIRECTIVES
            .contains(&word)
            .then(|| (lead, word, rest[end..].trim()))
    }
    if !lines.iter().any(|(_, l)| directive(l).is_some()) {
        return None;
    }
    // a line whose `#` is inside a comment or a string is never a directive
    let quiet = quiet_ranges(src);
    fn outside<'a>(
        quiet: &[std::ops::Range<usize>],
        start: usize,
        line: &'a str,
    ) -> Option<(usize, &'a str, &'a str)> {
        directive(line).filter(|(lead, _, _)| {
            let at = start + lead;
            !quiet.iter().any(|r| r.start < at && at < r.end)
        })
    }
    if !lines
        .iter()
        .any(|&(start, l)| outside(&quiet, start, l).is_some())
    {
        return None;
    }
    let mut text = src.to_string();
    let blank = |text: &mut String, start: usize, line: &str| {
        // One space per byte, so that a character beyond ASCII keeps its width in bytes and
        // every later position (and the line's end) stays where it was.
        let b: String = line
            .chars()
            .flat_map(|c| {
                let keep = matches!(c, '\n' | '\r');
                std::iter::repeat_n(
                    if keep { c } else { ' ' },
                    if keep { 1 } else { c.len_utf8() },
                )
            })
            .collect();
        text.replace_range(start..start + line.len(), &b);
    };
    let mut defines: HashSet<String> = HashSet::new();
    let mut noted: HashSet<String> = HashSet::new();
    let mut stack: Vec<Open> = Vec::new();
    let mut imported = false;
    for &(start, line) in &lines {
        let on = stack.last().is_none_or(|o| o.on);
        let Some((lead, word, arg)) = outside(&quiet, start, line) else {
            if !on {
                blank(&mut text, start, line);
            }
            continue;
        };
        let at = Span::new(file, start + lead, start + line.trim_end().len());
        let name = arg
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .next()
            .unwrap_or("")
            .to_string();
        let error = |msg: String, hint: &str| {
            Diagnostic::error(code::E1058, msg)
                .at(at)
                .with_primary_label("B&R preprocessor directive")
                .with_hint(hint)
        };
        match word {
            "define" if on => {
                defines.insert(name);
            }
            "undef" if on => {
                defines.remove(&name);
            }
            "ifdef" | "ifndef" => {
                let defined = defines.contains(&name);
                if on && !defined && !name.is_empty() && noted.insert(name.clone()) {
                    diags.push(
                        Diagnostic::new(
                            code::W1419,
                            Severity::Note,
                            format!("`{name}` is defined nowhere in this file: `#{word} {name}` reads it as not defined"),
                        )
                        .at(at)
                        .with_hint("add `#define NAME` before it to compile the other branch (a project's or a build configuration's defines are not read)"),
                    );
                }
                let cond = defined == (word == "ifdef");
                stack.push(Open {
                    on: on && cond,
                    taken: cond,
                    outer: on,
                    at: (at.start as usize, at.end as usize),
                });
            }
            "if" | "elif" => {
                if on || stack.last().is_some_and(|o| o.outer) {
                    diags.push(error(
                        format!("`#{word}` of the B&R preprocessor: ladderc evaluates `#ifdef` and `#ifndef` only; no section of it is compiled"),
                        "write the condition as `#ifdef NAME` over a `#define NAME`",
                    ));
                }
                if word == "if" {
                    stack.push(Open {
                        on: false,
                        taken: true,
                        outer: on,
                        at: (at.start as usize, at.end as usize),
                    });
                } else if let Some(o) = stack.last_mut() {
                    o.on = false;
                    o.taken = true;
                }
            }
            "else" => match stack.last_mut() {
                Some(o) => {
                    o.on = o.outer && !o.taken;
                    o.taken = true;
                }
                None => diags.push(error(
                    "`#else` without its `#ifdef`".into(),
                    "open the section with `#ifdef NAME` or delete the line",
                )),
            },
            "endif" if stack.pop().is_none() => {
                diags.push(error(
                    "`#endif` without its `#ifdef`".into(),
                    "open the section with `#ifdef NAME` or delete the line",
                ));
            }
            // `#import "Crosstable.gvl"` after a POU's header: Softing 4CONTROL / ATCMcontrol
            // (MECT's TPAC panels) makes a resource's global variable file known to the POU;
            // ladderc knows every input's globals, so the line is read as nothing, with one note
            // per file naming what to give (before round 32: E0023 "Siemens SCL", the file not
            // compiled)
            "import" if on && !imported => {
                imported = true;
                diags.push(
                    Diagnostic::new(
                        code::W1458,
                        Severity::Note,
                        format!("`#import {arg}` (4CONTROL / ATCMcontrol) is read as nothing: the imported file is compiled only when it is an input"),
                    )
                    .at(at)
                    .with_primary_label("4CONTROL import directive")
                    .with_hint("give the imported file (its VAR_GLOBAL blocks) to ladderc as an input of its own"),
                );
            }
            "include" if on => diags.push(error(
                "`#include` of the B&R preprocessor is not read".into(),
                "give the included file to ladderc as an input of its own",
            )),
            _ => {}
        }
        blank(&mut text, start, line);
    }
    // An unclosed `#ifdef` says nothing certain about the text after it: compile that text as if
    // the directive were not there (its E1058 alone, not a missing `END_VAR` of a blanked block).
    if let Some(first) = stack.first().map(|o| o.at.1) {
        for &(start, line) in lines.iter().filter(|(start, _)| *start >= first) {
            if outside(&quiet, start, line).is_none() {
                text.replace_range(start..start + line.len(), line);
            }
        }
    }
    for o in stack {
        diags.push(
            Diagnostic::error(code::E1058, "`#ifdef` without its `#endif`")
                .at(Span::new(file, o.at.0, o.at.1))
                .with_primary_label("opened here")
                .with_hint("close the section with `#endif`; the text after it is compiled as if the line were not there"),
        );
    }
    Some(text)
}

/// E1095 at the first `CONST` line of a file whose `END_CONST` follows: Softing 4CONTROL's block of
/// constants (`CONST this : INT := 48; END_CONST` after a POU's header), which IEC 61131-3 writes
/// `VAR CONSTANT ... END_VAR`. The file is not compiled (one error for the dialect, not one per
/// declaration read as a statement). A `CONST` inside a comment or a string is no block.
pub fn four_control_constants(file: FileId, src: &str) -> Option<Diagnostic> {
    let quiet = quiet_ranges(src);
    let mut pos = 0;
    let mut open: Option<(usize, usize)> = None;
    for line in src.split_inclusive('\n') {
        let lead = line.len() - line.trim_start().len();
        let at = pos + lead;
        pos += line.len();
        if quiet.iter().any(|r| r.start <= at && at < r.end) {
            continue;
        }
        let first = line
            .trim_start()
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .next()
            .unwrap_or("");
        if open.is_none() && first.eq_ignore_ascii_case("CONST") {
            open = Some((at, at + first.len()));
        } else if first.eq_ignore_ascii_case("END_CONST") {
            if let Some((start, end)) = open {
                return Some(
                    Diagnostic::error(
                        code::E1095,
                        "`CONST ... END_CONST` is a block of constants of 4CONTROL / ATCMcontrol, not IEC 61131-3: this file is not compiled",
                    )
                    .at(Span::new(file, start, end))
                    .with_primary_label("4CONTROL block of constants")
                    .with_hint("write the block as `VAR CONSTANT ... END_VAR` (IEC 61131-3 ed. 3, 6.5.2), the same declarations inside"),
                );
            }
        }
    }
    None
}

/// E1094 at `RESOURCE name` when it is the first word of the text: a resource standing without
/// its `CONFIGURATION`, as Softing 4CONTROL / ATCMcontrol keeps one in a resource file (`.res`,
/// imported by the configuration file's `#IMPORT "Resource1.res"`), its tasks set by 4CONTROL's
/// `EVENT` and `AUTOSTART` (a task not autostarted runs once a program starts it with
/// `StartLocalTask`). IEC 61131-3 ed. 2 2.7.1 (ed. 3 6.8.1) declares a resource inside a
/// configuration only; ladderc does not guess the 4CONTROL schedule, so the file is not compiled
/// (one error naming the construct; before round 33: E0023 "Siemens SCL" at `#IMPORT`, or a
/// syntax error at `RESOURCE`).
pub fn four_control_resource(file: FileId, src: &str) -> Option<Diagnostic> {
    let quiet = quiet_ranges(src);
    let mut words = Vec::new();
    let mut i = 0;
    let b = src.as_bytes();
    while i < b.len() && words.len() < 2 {
        if let Some(r) = quiet.iter().find(|r| r.start == i) {
            i = r.end;
            continue;
        }
        let c = b[i];
        if c.is_ascii_alphabetic() || c == b'_' {
            let start = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
            words.push(start..i);
        } else if c.is_ascii_whitespace() {
            i += 1;
        } else {
            break;
        }
    }
    let [kw, name] = words.as_slice() else {
        return None;
    };
    if !src[kw.clone()].eq_ignore_ascii_case("RESOURCE") {
        return None;
    }
    let name_text = &src[name.clone()];
    Some(
        Diagnostic::error(
            code::E1094,
            format!("`RESOURCE {name_text}` stands without its CONFIGURATION (a 4CONTROL / ATCMcontrol resource file): this file is not compiled"),
        )
        .at(Span::new(file, kw.start, name.end))
        .with_primary_label("resource outside a configuration")
        .with_hint("IEC 61131-3 declares a RESOURCE inside `CONFIGURATION c ... END_CONFIGURATION`, its tasks set by INTERVAL, SINGLE and PRIORITY (4CONTROL's EVENT and AUTOSTART are not read): write the configuration so, or leave this file out and every program runs once per cycle"),
    )
}

/// The byte ranges of the comments (`(* *)` and `/* */` nested as the ST lexer reads them, `//` to
/// the end of the line) and string literals of an ST text, each from its opening to its end.
fn quiet_ranges(src: &str) -> Vec<std::ops::Range<usize>> {
    let b = src.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let rest = &src[i..];
        let len = if let Some(body) = rest.strip_prefix("(*") {
            match lexer::comment_rest(body) {
                (n, CommentEnd::Closed { .. }) => 2 + n,
                (n, CommentEnd::Unterminated) => 2 + lexer::flat_comment_len(body).unwrap_or(n),
            }
        } else if let Some(body) = rest.strip_prefix("/*") {
            2 + lexer::slash_comment_rest(body).0
        } else if rest.starts_with("//") {
            rest.find('\n').unwrap_or(rest.len())
        } else if b[i] == b'\'' || b[i] == b'"' {
            // a string ends at its own quote (`$'` is an escaped quote) or, unclosed, at the line's end
            let q = b[i];
            let mut k = 1;
            while k < rest.len() && b[i + k] != q && b[i + k] != b'\n' {
                k += if b[i + k] == b'$' { 2 } else { 1 };
            }
            (k + 1).min(rest.len())
        } else {
            0
        };
        if len > 0 {
            out.push(i..i + len);
            i += len;
        } else {
            i += rest.chars().next().map_or(1, char::len_utf8);
        }
    }
    out
}
