//! Beremiz project folders as inputs: `ladderc check|build|run DIR` (a folder holding `plc.xml`) or
//! `DIR/plc.xml` beside a `beremiz.xml` (a bare `plc.xml` is `DIR` = the current folder: the same
//! project whichever way the path is spelled).
//!
//! Input: an input path and the [`Session`] (its overlay and, when allowed, the file system). Output:
//! the path of the project's `plc.xml`, and, once it is compiled, the globals its confnodes declare
//! (`ladder_compiler::beremiz`) added to its first configuration, each confnode file read into the
//! source map so that diagnostics point into it. Invariants: every confnode whose code or field bus does
//! not run gets one located W0320 (never dropped silently); the walk of the folder is bounded in depth
//! and never follows more than [`MAX_CONFNODES`] confnodes; nothing is written.

use crate::pipeline::Session;
use diagnostics::{code, Diagnostic, FileId, Span};
use il_frontend::ast::{CompilationUnit, VarDecl};
use ladder_compiler::beremiz;
use std::path::{Path, PathBuf};

/// How deep confnodes are looked for (Beremiz nests them: Modbus server, memory area; EtherCAT
/// master, slave).
const MAX_DEPTH: usize = 8;

/// At most this many confnodes are read in one project (a bound against hostile folders).
pub const MAX_CONFNODES: usize = 1000;

/// The `plc.xml` to read for input `p`, and the Beremiz project folder when `p` is one (a folder
/// holding `plc.xml`) or is the `plc.xml` of one (beside a `beremiz.xml`).
pub fn resolve(session: &Session, p: &Path) -> (PathBuf, Option<PathBuf>) {
    let plc = p.join("plc.xml");
    if session.disk && p.is_dir() && session.file_exists(&plc) {
        return (plc, Some(p.to_path_buf()));
    }
    if !session.disk && session.overlay.contains_key(&plc) {
        return (plc, Some(p.to_path_buf()));
    }
    if p.file_name().is_some_and(|n| n == "plc.xml") {
        let dir = p.parent().unwrap_or(Path::new(""));
        if session.file_exists(&dir.join("beremiz.xml")) {
            return (p.to_path_buf(), Some(dir.to_path_buf()));
        }
    }
    (p.to_path_buf(), None)
}

/// Reads the confnodes of the project folder `dir` and adds the globals they declare to `unit` (the
/// compiled `plc.xml`).
pub fn add_confnodes(session: &mut Session, dir: &Path, unit: &mut CompilationUnit) {
    let mut globals = Vec::new();
    let mut count = 0;
    walk(session, dir, &[], 0, &mut count, &mut globals);
    beremiz::add_globals(unit, globals);
}

/// The sub-folders `NAME@TYPE` of `dir` (on disk and in the overlay), sorted by name.
fn confnode_dirs(session: &Session, dir: &Path) -> Vec<PathBuf> {
    let mut found: Vec<PathBuf> = Vec::new();
    if session.disk {
        // a bare `plc.xml` is in the current folder: its parent is the empty path, which the file
        // system does not list; the confnodes keep the spelling of `dir` (`py_ext_0@py_ext/...`)
        let listed = if dir.as_os_str().is_empty() {
            Path::new(".")
        } else {
            dir
        };
        if let Ok(entries) = std::fs::read_dir(listed) {
            found.extend(
                entries
                    .filter_map(|e| e.ok())
                    .filter(|e| e.file_type().is_ok_and(|t| t.is_dir()))
                    .map(|e| dir.join(e.file_name())),
            );
        }
    }
    for key in session.overlay.keys() {
        if let Ok(rest) = key.strip_prefix(dir) {
            let mut comps = rest.components();
            if let (Some(first), Some(_)) = (comps.next(), comps.next()) {
                found.push(dir.join(first.as_os_str()));
            }
        }
    }
    found.retain(|d| {
        d.file_name()
            .and_then(|n| n.to_str())
            .is_some_and(|n| n.contains('@'))
    });
    found.sort();
    found.dedup();
    found
}

/// Reads `path` into the source map, when it exists, decoded as `plc.xml` is: a byte that is not
/// UTF-8 (a Windows-1252 `´` in a C comment of `cfile.xml`) makes the file read as Windows-1252
/// with note W0305 at that byte, as for any input (round 32, before: one E9001 without a place
/// and exit 2; `tests/tests/fbd_r32_run.rs`).
fn read(session: &mut Session, path: &Path) -> Option<FileId> {
    if !session.file_exists(path) {
        return None;
    }
    session.read_decoded(path)
}

fn walk(
    session: &mut Session,
    dir: &Path,
    location: &[u32],
    depth: usize,
    count: &mut usize,
    globals: &mut Vec<VarDecl>,
) {
    if depth >= MAX_DEPTH {
        return;
    }
    // Beremiz orders the confnodes by IEC channel (`IECSortedChildren`)
    let mut nodes = Vec::new();
    for sub in confnode_dirs(session, dir) {
        *count += 1;
        if *count > MAX_CONFNODES {
            return;
        }
        let folder = sub
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or_default()
            .to_string();
        let (folder_name, kind) = folder.split_once('@').unwrap_or((&folder, ""));
        let base = read(session, &sub.join("baseconfnode.xml"));
        let params = base.and_then(|f| beremiz::base_params(&session.map.get(f).text));
        let name = params
            .as_ref()
            .map(|(n, _)| n.clone())
            .filter(|n| !n.is_empty())
            .unwrap_or_else(|| folder_name.to_string());
        let channel = params.and_then(|(_, c)| c).unwrap_or(0);
        nodes.push((channel, sub.clone(), name, kind.to_string(), base));
    }
    nodes.sort_by(|a, b| (a.0, &a.1).cmp(&(b.0, &b.1)));
    for (channel, sub, name, kind, base) in nodes {
        let mut loc = location.to_vec();
        loc.push(channel);
        let loc_text = loc
            .iter()
            .map(|c| c.to_string())
            .collect::<Vec<_>>()
            .join(".");
        let code_file = [("cfile.xml", "C"), ("pyfile.xml", "Python")]
            .into_iter()
            .find_map(|(f, lang)| read(session, &sub.join(f)).map(|id| (id, lang)));
        if let Some((file, lang)) = code_file {
            let read = {
                let Session { map, diags, .. } = &mut *session;
                beremiz::code_file(file, &map.get(file).text, diags)
            };
            if let Some((span, section)) = read.code {
                session.diags.push(
                    Diagnostic::warning(
                        code::W0320,
                        format!(
                            "the {lang} code of confnode `{name}` ({kind}) does not run: ladderc \
                             compiles only the IEC 61131-3 program ({section} is skipped); its \
                             variables are plain globals"
                        ),
                    )
                    .at(span)
                    .with_hint(
                        "write the behaviour in ST in plc.xml, or drive the variables with --stimulus",
                    ),
                );
            }
            globals.extend(read.globals);
        } else if depth == 0 {
            let at = read(session, &sub.join("confnode.xml"))
                .and_then(|f| beremiz::root_tag(f, &session.map.get(f).text))
                .map(|(_, s)| s)
                .or_else(|| base.map(|f| Span::new(f, 0, 0)));
            if kind == "mqtt" {
                let status = format!("MQTT_STATUS_{}", loc_text.replace('.', "_"));
                let span = base.map(|f| Span::new(f, 0, 0)).or(at);
                if let Some(span) = span {
                    globals.push(beremiz::implicit_global(&status, "INT", span));
                }
            }
            let mut d = Diagnostic::warning(
                code::W0320,
                format!(
                    "confnode `{name}` ({kind}) does not run: ladderc has no field bus or runtime \
                     extension; the located variables on its channel (`%I*{loc_text}.*`, \
                     `%Q*{loc_text}.*`) are plain process-image addresses"
                ),
            )
            .with_hint("set its inputs with --stimulus and read its outputs with --watch");
            if let Some(at) = at {
                d = d.at(at);
            }
            session.diags.push(d);
        }
        walk(session, &sub, &loc, depth + 1, count, globals);
    }
}
