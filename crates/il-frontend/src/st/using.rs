//! `USING Siemens.Simatic.S71500.Tasks;`: a namespace import (IEC 61131-3 ed. 3 namespaces, as
//! SIMATIC AX, CODESYS and other ed. 3 workbenches write them) in `.st` text.
//!
//! Input: the file's text and tokens. Output: the text with each `USING` directive blanked, one
//! W1421 note per directive naming a namespace no file of the project declares (a vendor library's;
//! a namespace the project declares is read, `qualifiers`, and its directive blanked silently), or
//! `None` when there is none. The directive brings nothing in, and a block, type or task kind that
//! only the namespace declares is then reported where it is used (E1003, E1019 ...), naming it. Before, the
//! directive made the file look like IL (W0001, E0007 for its `;`).
//! Invariant: positions unchanged (the directive becomes blanks), so every span stays where the user
//! wrote it.
//!
//! A task declared by its kind, `TASK Main : ProgramCycle;` (SIMATIC AX: the kind is a type of
//! the `Siemens.Simatic.S71500.Tasks` namespace; also written with it,
//! `TASK Main : Siemens.Simatic.S71500.Tasks.ProgramCycle;`; with its parameters as an initial value,
//! `TASK T : CyclicInterrupt := (CycleTime := T#500ms);`), is one E1048 naming the kind ([`typed_tasks`]):
//! IEC 61131-3 declares a task by its schedule. The declaration and the `WITH Main` of the program
//! instances it runs are blanked, so the instances are not reported again. A directive is `USING` + a name (dotted parts) [`, name` ...] + `;`, at the start of the
//! text, after a `;` or after a POU header's name: `USING` names nothing else in ST.

use super::file::{is_word, word};
use super::lexer::{Tok, Token};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics, Severity};

/// See the module documentation.
pub(super) fn namespace_imports(
    file: FileId,
    src: &str,
    toks: &[Token],
    diags: &mut Diagnostics,
) -> Option<String> {
    let mut out: Option<String> = None;
    let mut k = 0;
    while k < toks.len() {
        if !is_word(src, &toks[k], "USING") || !starts_statement(src, toks, k) {
            k += 1;
            continue;
        }
        // the names: `a.b.c` [`, d.e`]
        let mut j = k + 1;
        let mut names = Vec::new();
        while let Some(first) = toks.get(j).filter(|t| t.tok == Tok::Ident) {
            let mut name = word(src, first).to_string();
            j += 1;
            while toks.get(j).is_some_and(|t| t.tok == Tok::Dot)
                && toks.get(j + 1).is_some_and(|t| t.tok == Tok::Ident)
            {
                name.push('.');
                name.push_str(word(src, &toks[j + 1]));
                j += 2;
            }
            names.push(name);
            if toks.get(j).is_some_and(|t| t.tok == Tok::Comma) {
                j += 1;
                continue;
            }
            break;
        }
        if names.is_empty() || !toks.get(j).is_some_and(|t| t.tok == Tok::Semi) {
            k += 1;
            continue;
        }
        let range = toks[k].range.start..toks[j].range.end;
        // a namespace this file declares (`NAMESPACE Lib ... END_NAMESPACE`): its names are the
        // file's, reached plain or `Lib.`-qualified (`qualifiers`): nothing to report
        let declared = |n: &String| {
            (0..toks.len()).any(|k| {
                if !is_word(src, &toks[k], "NAMESPACE") {
                    return false;
                }
                // `NAMESPACE Factory.Motion`: its dotted name
                let mut name = String::new();
                let mut j = k + 1;
                while let Some(t) = toks.get(j).filter(|t| t.tok == Tok::Ident) {
                    name.push_str(word(src, t));
                    if toks.get(j + 1).is_some_and(|d| d.tok == Tok::Dot) {
                        name.push('.');
                        j += 2;
                    } else {
                        break;
                    }
                }
                name.eq_ignore_ascii_case(n)
            })
        };
        // (or another file of the project does: one project, `qualifiers::set_project_namespaces`)
        let declared = |n: &String| {
            declared(n) || super::qualifiers::is_project_namespace(&n.to_ascii_uppercase())
        };
        if names.iter().all(declared) {
            let text = out.get_or_insert_with(|| src.to_string());
            text.replace_range(range.clone(), &" ".repeat(range.len()));
            k = j + 1;
            continue;
        }
        diags.push(
            Diagnostic::new(
                code::W1421,
                Severity::Warning,
                format!(
                    "`USING {}`: no file of the project declares this namespace (a library's); the directive is ignored",
                    names.join(", ")
                ),
            )
            .at(Span::new(file, range.start, range.end))
            .with_primary_label("ignored")
            .with_hint("a block, type or task kind that only this namespace declares (a vendor library's) is reported where it is used; declare it in the project's files, or leave it out"),
        );
        let text = out.get_or_insert_with(|| src.to_string());
        text.replace_range(range.clone(), &" ".repeat(range.len()));
        k = j + 1;
    }
    out
}

/// Whether token `k` begins a declaration or statement: the first token, after `;` or an `END_`
/// word, or after
/// a POU header's name (`PROGRAM p USING ns;`).
fn starts_statement(src: &str, toks: &[Token], k: usize) -> bool {
    if k == 0 {
        return true;
    }
    // (or after the end of a declaration: `END_NAMESPACE USING Lib;`, `END_FUNCTION`)
    if toks[k - 1].tok == Tok::Semi
        || word(src, &toks[k - 1])
            .get(..4)
            .is_some_and(|w| w.eq_ignore_ascii_case("END_"))
    {
        return true;
    }
    k >= 2
        && toks[k - 1].tok == Tok::Ident
        && [
            "PROGRAM",
            "FUNCTION_BLOCK",
            "FUNCTION",
            "NAMESPACE",
            "CONFIGURATION",
        ]
        .iter()
        .any(|w| is_word(src, &toks[k - 2], w))
}

/// See the module documentation: `TASK name : Kind;` in a CONFIGURATION or RESOURCE.
pub(super) fn typed_tasks(
    file: FileId,
    src: &str,
    toks: &[Token],
    diags: &mut Diagnostics,
) -> Option<String> {
    let mut out: Option<String> = None;
    let mut names = Vec::new();
    let mut k = 0;
    while k + 4 < toks.len() {
        // `TASK name : Kind;`, the kind bare or with its namespace
        // (`Siemens.Simatic.S71500.Tasks.ProgramCycle`, as SIMATIC AX's templates write it)
        let header = is_word(src, &toks[k], "TASK")
            && toks[k + 1].tok == Tok::Ident
            && toks[k + 2].tok == Tok::Colon
            && toks[k + 3].tok == Tok::Ident;
        let Some(semi) = header.then(|| qualified_name_end(toks, k + 3)).flatten() else {
            k += 1;
            continue;
        };
        let task = word(src, &toks[k + 1]);
        // the kind's name alone (its dotted parts), not the parameters after it
        let mut kind_end = k + 3;
        while toks.get(kind_end + 1).is_some_and(|t| t.tok == Tok::Dot)
            && toks.get(kind_end + 2).is_some_and(|t| t.tok == Tok::Ident)
        {
            kind_end += 2;
        }
        let kind_range = toks[k + 3].range.start..toks[kind_end].range.end;
        let kind = &src[kind_range.clone()];
        diags.push(
            Diagnostic::error(
                code::E1048,
                format!("task `{task}` is declared by its kind `{kind}`, not by a schedule"),
            )
            .at(Span::new(file, kind_range.start, kind_range.end))
            .with_primary_label("a task kind of a library (SIMATIC AX's `ProgramCycle`, `Startup` ...)")
            .with_hint("IEC 61131-3 declares a task by its schedule: `TASK name (INTERVAL := T#10ms, PRIORITY := 1);` (cyclic) or `(SINGLE := trigger, PRIORITY := 1)`; the programs it runs are not compiled into a task"),
        );
        names.push(task.to_ascii_uppercase());
        let range = toks[k].range.start..toks[semi].range.end;
        let text = out.get_or_insert_with(|| src.to_string());
        text.replace_range(range.clone(), &" ".repeat(range.len()));
        k = semi + 1;
    }
    if names.is_empty() {
        return None;
    }
    // `PROGRAM P WITH Main : T;` -> `PROGRAM P           : T;`
    let text = out.as_mut().expect("a task was blanked");
    for j in 0..toks.len().saturating_sub(1) {
        if is_word(src, &toks[j], "WITH")
            && toks[j + 1].tok == Tok::Ident
            && names.contains(&word(src, &toks[j + 1]).to_ascii_uppercase())
        {
            let range = toks[j].range.start..toks[j + 1].range.end;
            text.replace_range(range.clone(), &" ".repeat(range.len()));
        }
    }
    out
}

/// The index of the `;` that ends the name `a.b.c` whose first part is `toks[first]`, or `None`
/// when the parts are not followed by `;`. Each step moves past one `.` and one name: bounded by
/// the tokens. The kind may carry its parameters as an initial value, as SIMATIC AX writes a
/// cyclic-interrupt task: `TASK T : CyclicInterrupt := (CycleTime := T#500ms, EventPriority :=
/// USINT#13);` (round 31: before, a bare E0011 at the `:`); the parenthesised list is skipped
/// to its matching `)`, one token a step.
fn qualified_name_end(toks: &[Token], first: usize) -> Option<usize> {
    let mut j = first + 1;
    while toks.get(j).is_some_and(|t| t.tok == Tok::Dot)
        && toks.get(j + 1).is_some_and(|t| t.tok == Tok::Ident)
    {
        j += 2;
    }
    if toks.get(j).is_some_and(|t| t.tok == Tok::Assign)
        && toks.get(j + 1).is_some_and(|t| t.tok == Tok::LParen)
    {
        let mut depth = 0usize;
        let mut k = j + 1;
        loop {
            match toks.get(k).map(|t| &t.tok) {
                Some(Tok::LParen) => depth += 1,
                Some(Tok::RParen) => {
                    depth = depth.saturating_sub(1);
                    if depth == 0 {
                        break;
                    }
                }
                // (a `;` or the end inside the list: not a task declaration of this form)
                Some(Tok::Semi) | None => return None,
                Some(_) => {}
            }
            k += 1;
        }
        j = k + 1;
    }
    toks.get(j).is_some_and(|t| t.tok == Tok::Semi).then_some(j)
}
