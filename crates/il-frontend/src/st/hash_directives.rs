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
//! file not compiled).
//!
//! Invariants: sections nest; inside a section not compiled no define changes; a `#if` /
//! `#elif` compiles none of its sections (no branch chosen by guess). Names are case-sensitive as
//! in C. A directive is only recognised at the start of a line (after blanks).

use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics, Severity};
use std::collections::HashSet;

const DIRECTIVES: &[&str] = &[
    "define", "undef", "ifdef", "ifndef", "if", "elif", "else", "endif", "include",
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
    let mut lines = Vec::new();
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
        let word = &rest[..end];
        DIRECTIVES
            .contains(&word)
            .then(|| (lead, word, rest[end..].trim()))
    }
    if !lines.iter().any(|(_, l)| directive(l).is_some()) {
        return None;
    }
    let mut text = src.to_string();
    let blank = |text: &mut String, start: usize, line: &str| {
        let b: String = line
            .chars()
            .map(|c| if matches!(c, '\n' | '\r') { c } else { ' ' })
            .collect();
        text.replace_range(start..start + line.len(), &b);
    };
    let mut defines: HashSet<String> = HashSet::new();
    let mut noted: HashSet<String> = HashSet::new();
    let mut stack: Vec<Open> = Vec::new();
    for (start, line) in lines {
        let on = stack.last().is_none_or(|o| o.on);
        let Some((lead, word, arg)) = directive(line) else {
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
            "include" if on => diags.push(error(
                "`#include` of the B&R preprocessor is not read".into(),
                "give the included file to ladderc as an input of its own",
            )),
            _ => {}
        }
        blank(&mut text, start, line);
    }
    for o in stack {
        diags.push(
            Diagnostic::error(code::E1058, "`#ifdef` without its `#endif`")
                .at(Span::new(file, o.at.0, o.at.1))
                .with_primary_label("opened here")
                .with_hint("close the section with `#endif`; everything after it is read as if the section ended at the end of the text"),
        );
    }
    Some(text)
}
