//! CODESYS V2.3's text exports (`.EXP`, "Project > Export"): the sections that hold no code
//! (visualisations, the PLC and alarm configurations, the workspace, library references) blanked
//! with one note W1442 each, the task configuration (`RESOURCE` ... `END_RESOURCE`) read as
//! the project's tasks (W1443 for a task without INTERVAL), and the symbolic names of the PLC
//! configuration read as global variables at their addresses ([`crate::codesys_v23_io`]). The rest of the file (POUs, types,
//! variable lists) keeps its place, so every diagnostic keeps the file's own line and column.

use diagnostics::{code, Diagnostic, FileId, Severity, Span};
use ladder_compiler::twincat::TcTask;

/// What [`read`] found in an export.
pub struct Export {
    /// The text with the non-code sections and the task configuration blanked (line breaks kept).
    pub text: String,
    /// One note per section skipped, and per task without a cycle time.
    pub notes: Vec<Diagnostic>,
    /// The tasks of the task configuration.
    pub tasks: Vec<TcTask>,
    /// The global variables the PLC configuration's symbolic names declare (its channels and
    /// bits), located at the names in the section.
    pub io_globals: Option<il_frontend::ast::VarBlock>,
}

/// The sections' first words, their last words and what they are.
const SECTIONS: &[(&str, &str, &str)] = &[
    ("VISUALISATION", "END_VISUALISATION", "a visualisation"),
    ("PLC_CONFIGURATION", "PLC_END", "the PLC configuration"),
    (
        "_ALARMCONFIG",
        "_END_ALARMCONFIG",
        "the alarm configuration",
    ),
    ("_WORKSPACE", "_END_WORKSPACE", "the workspace options"),
    ("LIBRARY", "END_LIBRARY", "a library reference"),
    ("RESOURCE", "END_RESOURCE", "the task configuration"),
    // a macro (menu name and batch commands, `MacroCmd: 'project build'`), exported by "Export
    // multiple" beside the POUs
    ("MACRO", "END_MACRO", "a macro"),
];

/// The first word of a line (the line trimmed), and the rest.
fn first_word(line: &str) -> (&str, &str) {
    let t = line.trim_start();
    let end = t
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(t.len());
    (&t[..end], &t[end..])
}

/// The lines of `text` with their byte offsets (the line without its line break).
pub(crate) fn lines(text: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut at = 0;
    for l in text.split_inclusive('\n') {
        out.push((at, l.trim_end_matches(['\n', '\r'])));
        at += l.len();
    }
    out
}

/// Reads `text` as a CODESYS V2.3 export; `None` when it has no such section (a section starts at
/// a line whose first word is one of `SECTIONS`, `RESOURCE` alone on its line: IEC 61131-3's
/// has a name and sits inside a CONFIGURATION).
pub fn read(file: FileId, text: &str) -> Option<Export> {
    let ls = lines(text);
    let mut out = Export {
        text: String::new(),
        notes: Vec::new(),
        tasks: Vec::new(),
        io_globals: None,
    };
    let mut blanked: Vec<std::ops::Range<usize>> = Vec::new();
    let mut k = 0;
    while k < ls.len() {
        let (at, line) = ls[k];
        let (w, rest) = first_word(line);
        if let Some(form) = graphical_body(w, rest) {
            // a POU's body in a graphical form (`_CFC_BODY` then `_ELEMENT` records): one error,
            // the body blanked up to the POU's (or action's) end
            let start = at + (line.len() - line.trim_start().len());
            let mut j = k + 1;
            while j < ls.len()
                && !matches!(
                    first_word(ls[j].1).0,
                    "END_FUNCTION_BLOCK" | "END_PROGRAM" | "END_FUNCTION" | "END_ACTION"
                )
            {
                j += 1;
            }
            let stop = ls.get(j).map_or(text.len(), |(a, _)| *a);
            out.notes.push(
                Diagnostic::error(
                    code::E0321,
                    format!("a body in {form} exported by CODESYS V2.3 (`{w}`): ladderc reads the ST and IL bodies of a text export"),
                )
                .at(Span::new(file, start, start + w.len()))
                .with_primary_label("graphical body")
                .with_hint("export the project as PLCopen XML (Project > Export PLCopenXML), whose LD, FBD and SFC bodies ladderc reads, or write the body in ST"),
            );
            blanked.push(start..stop);
            k = j;
            continue;
        }
        let Some(&(_, end, what)) = SECTIONS.iter().find(|(s, _, _)| *s == w) else {
            k += 1;
            continue;
        };
        // `RESOURCE`, `LIBRARY` and `MACRO` alone on their line (IEC 61131-3's RESOURCE has a
        // name; a variable named `macro` is no section)
        if matches!(w, "RESOURCE" | "LIBRARY" | "MACRO") && !rest.trim().is_empty() {
            k += 1;
            continue;
        }
        let start = at + (line.len() - line.trim_start().len());
        let mut j = k + 1;
        while j < ls.len() && first_word(ls[j].1).0 != end {
            j += 1;
        }
        let stop = ls.get(j).map_or(text.len(), |(a, l)| a + l.len());
        if w == "RESOURCE" {
            out.tasks
                .extend(tasks(file, &ls[k..j.min(ls.len())], &mut out.notes));
            if out.tasks.is_empty() {
                out.notes.push(skipped(file, start, line.trim(), what));
            }
        } else {
            // `VISUALISATION panel _VISU_TYPES : 1,1`: the object's name
            let name = rest
                .split_whitespace()
                .next()
                .filter(|n| w == "VISUALISATION" && !n.is_empty());
            // `MacroName: 'BuildAll'`: the macro's name
            let macro_name = (w == "MACRO")
                .then(|| {
                    ls[k + 1..j.min(ls.len())].iter().find_map(|(_, l)| {
                        let v = l.trim().strip_prefix("MacroName:")?.trim();
                        Some(v.trim_matches('\'').to_string())
                    })
                })
                .flatten();
            let shown = match name {
                Some(n) => format!("{what} (`{n}`)"),
                None if macro_name.is_some() => {
                    format!("{what} (`{}`)", macro_name.unwrap_or_default())
                }
                None if w == "LIBRARY" => {
                    let lib = ls
                        .get(k + 1)
                        .and_then(|(_, l)| l.split_whitespace().next())
                        .unwrap_or("");
                    format!("{what} (`{lib}`)")
                }
                None => what.to_string(),
            };
            if w == "PLC_CONFIGURATION" {
                let section = &ls[k..j.min(ls.len())];
                let names = crate::codesys_v23_io::symbolic_names(file, section, &mut out.notes);
                if let Some(block) = names {
                    out.notes
                        .push(io_read(file, start, line.trim(), block.vars.len()));
                    out.io_globals = Some(block);
                    blanked.push(start..stop);
                    k = j + 1;
                    continue;
                }
            }
            out.notes.push(skipped(file, start, line.trim(), &shown));
        }
        blanked.push(start..stop);
        k = j + 1;
    }
    if blanked.is_empty() {
        return None;
    }
    let mut t = text.to_string();
    for r in blanked {
        il_frontend::st::file::blank(&mut t, r);
    }
    out.text = t;
    Some(out)
}

/// The graphical language of a V2.3 body's first line (`_CFC_BODY`, `_LD_BODY`, `_FBD_BODY`,
/// alone on its line).
fn graphical_body(word: &str, rest: &str) -> Option<&'static str> {
    if !rest.trim().is_empty() {
        return None;
    }
    Some(match word {
        "_CFC_BODY" => "CFC",
        "_LD_BODY" => "LD",
        "_FBD_BODY" => "FBD",
        "_SFC_BODY" => "SFC",
        _ => return None,
    })
}

/// Whether `text` holds nothing but blanks and `(* *)` comments (the export's `(* @PATH := '' *)`
/// headers).
pub fn no_code(text: &str) -> bool {
    let mut rest = text.trim_start();
    while let Some(after) = rest.strip_prefix("(*") {
        match after.find("*)") {
            Some(k) => rest = after[k + 2..].trim_start(),
            None => return true,
        }
    }
    rest.is_empty()
}

fn skipped(file: FileId, start: usize, line: &str, what: &str) -> Diagnostic {
    let first = line.split_whitespace().next().unwrap_or(line);
    Diagnostic::new(
        code::W1442,
        Severity::Note,
        format!("{what} exported by CODESYS V2.3: no code, skipped"),
    )
    .at(Span::new(file, start, start + first.len()))
    .with_primary_label("skipped up to its end")
    .with_hint("nothing to fix (`ladderc explain W1442`); give only the code objects' files to silence this note")
}

/// W1442 for a PLC configuration whose symbolic names were read: `n` global variables.
fn io_read(file: FileId, start: usize, line: &str, n: usize) -> Diagnostic {
    let first = line.split_whitespace().next().unwrap_or(line);
    Diagnostic::new(
        code::W1442,
        Severity::Note,
        format!(
            "the PLC configuration exported by CODESYS V2.3: its {n} symbolic name(s) declared as global variables at their addresses, the rest (modules, parameters) skipped"
        ),
    )
    .at(Span::new(file, start, start + first.len()))
    .with_primary_label("symbolic names read up to its end")
    .with_hint("nothing to fix (`ladderc explain W1442`): a channel's type follows from its address (%IX BOOL, %IB BYTE, %IW WORD, %ID DWORD)")
}

/// The tasks of a task configuration's lines (`RESOURCE` up to `END_RESOURCE`): `TASK name
/// (PRIORITY := 1, INTERVAL := T#20ms);`, then one program call a line (`PLC_PRG();`), then
/// `END_TASK`; the pragmas (`{Additional_info ...}`, `{event_task ...}`) are not read.
fn tasks(file: FileId, ls: &[(usize, &str)], notes: &mut Vec<Diagnostic>) -> Vec<TcTask> {
    let mut out: Vec<TcTask> = Vec::new();
    let mut open = false;
    for &(at, line) in ls {
        let (w, rest) = first_word(line);
        let indent = line.len() - line.trim_start().len();
        if w.eq_ignore_ascii_case("TASK") {
            let rest_trim = rest.trim_start();
            let name_at = at + indent + w.len() + (rest.len() - rest_trim.len());
            let (name, params) = first_word(rest_trim);
            if name.is_empty() {
                continue;
            }
            let upper = params.to_ascii_uppercase();
            let value = |key: &str| -> Option<String> {
                let k = upper.find(key)?;
                let after = params[k + key.len()..].trim_start().strip_prefix(":=")?;
                let v = after
                    .trim_start()
                    .split([',', ')', ';'])
                    .next()?
                    .trim()
                    .to_string();
                Some(v)
            };
            let cycle_us = value("INTERVAL").and_then(|v| {
                let body = v.split_once('#').map_or(v.as_str(), |(_, b)| b);
                il_frontend::literal::duration(body)
                    .ok()
                    .and_then(|ns| u64::try_from(ns / 1000).ok())
                    .filter(|&us| us > 0)
            });
            let priority = value("PRIORITY").and_then(|v| v.parse().ok());
            if cycle_us.is_none() {
                notes.push(
                    Diagnostic::new(
                        code::W1443,
                        Severity::Note,
                        format!(
                            "task `{name}` has no INTERVAL (a free-wheeling or event task): its \
                             programs run every cycle of 10 ms"
                        ),
                    )
                    .at(Span::new(file, name_at, name_at + name.len()))
                    .with_primary_label("no cycle time")
                    .with_hint(
                        "pass --cycle-ms to choose the scan cycle (`ladderc explain W1443`)",
                    ),
                );
            }
            out.push(TcTask {
                name: name.to_string(),
                span: (name_at, name_at + name.len()),
                cycle_us,
                priority,
                programs: Vec::new(),
            });
            open = true;
        } else if w.eq_ignore_ascii_case("END_TASK") {
            open = false;
        } else if open && !w.is_empty() && rest.trim_start().starts_with('(') {
            // `PLC_PRG();`: a program call
            let s = at + indent;
            if let Some(t) = out.last_mut() {
                t.programs.push((w.to_string(), (s, s + w.len())));
            }
        }
    }
    out
}
