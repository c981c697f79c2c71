//! SIMATIC AX projects (`apax.yml`) as inputs: their preprocessor symbols, and a project folder
//! standing for its sources.
//!
//! Input: the command line's paths and the [`Session`] (the file system when allowed). Output: the
//! paths with each folder that holds an `apax.yml` replaced by the `.st` files under its `src/`
//! (sorted, at most [`MAX_FILES`], at most [`MAX_DEPTH`] folders down: AX's ST compiler reads the
//! sources there), and the preprocessor symbols of the `apax.yml` of every such folder and of the
//! nearest `apax.yml` above each `.st` input (at most [`MAX_UP`] folders up), as defines for
//! `{::ifdef NAME}` ... `{::elseif NAME}` (`il_frontend::st::ProjectDefines`); one note W1452 per
//! `apax.yml` that lists symbols, at its key, naming them.
//!
//! Which keys: the list `DEFINED_PREPROCESSOR_SYMBOLS` (block `- NAME` items or a flow `[A, B]`),
//! the project variable Siemens' own sample (simatic-ax/ae-demo-rack) sets for its build's
//! `{::ifdef}` variants; a symbol commented out (`# - NAME`) is not defined. Nothing else of the
//! file is read (no other variable, no `APAX_BUILD_ARGS`, no `scripts`).
//!
//! Invariants: never panics; only IEC 61131-3 identifiers become symbols; each `apax.yml` is read
//! once; nothing is written.

use crate::pipeline::Session;
use diagnostics::{code, Diagnostic, Diagnostics, Severity, Span};
use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// At most this many `.st` files are read from one project's `src/` (a bound against hostile folders).
pub const MAX_FILES: usize = 10_000;

/// How many folders down `src/` is searched.
pub const MAX_DEPTH: usize = 16;

/// How many folders up from a `.st` input its `apax.yml` is looked for.
pub const MAX_UP: usize = 16;

/// The key of the list of symbols.
const SYMBOLS_KEY: &str = "DEFINED_PREPROCESSOR_SYMBOLS";

/// `paths` with each SIMATIC AX project folder replaced by its sources; the symbols of the
/// projects' `apax.yml` files go to `defines` (name, empty value).
pub fn expand(
    session: &mut Session,
    paths: &[PathBuf],
    defines: &mut Vec<(String, String)>,
    diags: &mut Diagnostics,
) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut read: HashSet<PathBuf> = HashSet::new();
    for p in paths {
        if !session.disk {
            out.push(p.clone());
            continue;
        }
        let project = if p.is_dir() && p.join("apax.yml").is_file() {
            let files =
                crate::folder_walk::files_under(&p.join("src"), MAX_DEPTH, MAX_FILES, |f| {
                    crate::twincat::has_extension(f, "st")
                });
            if files.is_empty() {
                // nothing under src/: the folder is reported as an input as before
                out.push(p.clone());
            } else {
                out.extend(files);
            }
            Some(p.join("apax.yml"))
        } else {
            out.push(p.clone());
            let st = p
                .extension()
                .and_then(|x| x.to_str())
                .is_some_and(|x| x.eq_ignore_ascii_case("st"));
            if st {
                nearest_apax(p)
            } else {
                None
            }
        };
        if let Some(yml) = project {
            if read.insert(yml.clone()) {
                symbols_of(session, &yml, defines, diags);
            }
        }
    }
    out
}

/// The nearest `apax.yml` in the folder of `file` or above it.
fn nearest_apax(file: &Path) -> Option<PathBuf> {
    let abs = std::fs::canonicalize(file).ok()?;
    abs.ancestors()
        .skip(1)
        .take(MAX_UP)
        .map(|d| d.join("apax.yml"))
        .find(|y| y.is_file())
}

/// Reads the symbols of `yml` into `defines`, with the W1452 note.
fn symbols_of(
    session: &mut Session,
    yml: &Path,
    defines: &mut Vec<(String, String)>,
    diags: &mut Diagnostics,
) {
    let Ok(text) = std::fs::read_to_string(yml) else {
        return;
    };
    let Some((at, names)) = preprocessor_symbols(&text) else {
        return;
    };
    let file = session.map.add_file(yml.display().to_string(), &text);
    let listed = if names.is_empty() {
        "no symbol".to_string()
    } else {
        names
            .iter()
            .map(|n| format!("`{n}`"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    diags.push(
        Diagnostic::new(
            code::W1452,
            Severity::Note,
            format!("the SIMATIC AX project defines {listed} for `{{::ifdef}}` (`{SYMBOLS_KEY}` of its apax.yml)"),
        )
        .at(Span::new(file, at.0, at.1))
        .with_primary_label("preprocessor symbols read here")
        .with_hint("ladderc reads this list only; a symbol set another way (a build argument, a script) is not defined: add it here or `{define NAME}` in the source"),
    );
    defines.extend(names.into_iter().map(|n| (n, String::new())));
}

/// The key's position and the symbols listed under `DEFINED_PREPROCESSOR_SYMBOLS` in an
/// `apax.yml` text; `None` when the key is not there. Only identifiers are kept.
pub fn preprocessor_symbols(text: &str) -> Option<((usize, usize), Vec<String>)> {
    let mut pos = 0;
    let mut found: Option<((usize, usize), usize)> = None;
    let mut names = Vec::new();
    for line in text.split_inclusive('\n') {
        let start = pos;
        pos += line.len();
        let content = strip_comment(line.trim_end());
        let trimmed = content.trim_start();
        let indent = content.len() - trimmed.len();
        if trimmed.is_empty() {
            continue;
        }
        match found {
            None => {
                let Some(rest) = trimmed.strip_prefix(SYMBOLS_KEY) else {
                    continue;
                };
                let Some(rest) = rest.trim_start().strip_prefix(':') else {
                    continue;
                };
                let at = (start + indent, start + indent + SYMBOLS_KEY.len());
                let rest = rest.trim();
                if let Some(flow) = rest.strip_prefix('[') {
                    let flow = flow.strip_suffix(']').unwrap_or(flow);
                    names.extend(flow.split(',').filter_map(symbol));
                    return Some((at, names));
                }
                if !rest.is_empty() {
                    names.extend(symbol(rest));
                    return Some((at, names));
                }
                found = Some((at, indent));
            }
            Some((_, key_indent)) => {
                // a block list: `- NAME` items, indented as the key or more
                match trimmed.strip_prefix('-') {
                    Some(item) if indent >= key_indent => names.extend(symbol(item)),
                    _ => break,
                }
            }
        }
    }
    found.map(|(at, _)| (at, names))
}

/// A line without its YAML comment (`#` at its start or after a blank, outside quotes).
fn strip_comment(line: &str) -> &str {
    let mut quote: Option<char> = None;
    let mut prev = ' ';
    for (i, c) in line.char_indices() {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if c == '"' || c == '\'' => quote = Some(c),
            None if c == '#' && prev.is_whitespace() => return &line[..i],
            None => {}
        }
        prev = c;
    }
    line
}

/// One symbol of the list (quotes dropped), when it is an identifier.
fn symbol(item: &str) -> Option<String> {
    let s = item.trim().trim_matches(|c| c == '"' || c == '\'').trim();
    crate::openplc_v4::is_name(s).then(|| s.to_string())
}

#[cfg(test)]
mod tests {
    use super::preprocessor_symbols;

    #[test]
    fn block_and_flow_lists_commented_items_left_out() {
        let text = "variables:\n  A: 1\n  DEFINED_PREPROCESSOR_SYMBOLS:\n    - SPEED # on\n    # - POS\n    - \"Two\"\n  APAX_BUILD_ARGS:\n    - --debug\n";
        let (at, names) = preprocessor_symbols(text).unwrap();
        assert_eq!(&text[at.0..at.1], "DEFINED_PREPROCESSOR_SYMBOLS");
        assert_eq!(names, ["SPEED", "Two"]);
        let (_, names) =
            preprocessor_symbols("v:\n  DEFINED_PREPROCESSOR_SYMBOLS: [A, 'B', 1x]\n").unwrap();
        assert_eq!(names, ["A", "B"]);
        assert!(preprocessor_symbols("variables:\n  X: 1\n").is_none());
    }
}
