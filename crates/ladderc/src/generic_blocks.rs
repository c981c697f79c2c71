//! The project's blocks with generic constants (`VAR_GENERIC CONSTANT`), built once per set of
//! values its instances give (`fb : FB_Buf<10>;`), as TwinCAT 3.1.4026 and CODESYS compile them.
//!
//! Input: the session, the texts of the files that declare such blocks (noted while the files
//! were read), every unit parsed and the bodies pending. Output: the instances' types renamed
//! (`FB_Buf__10`, see `il_frontend::st::generic_blocks`), and for each set of values one unit
//! more: the block's file parsed again as a file of its own (`FILE<FB_Buf__10>`, the same text),
//! its generic constants taking the instance's values (so the arrays they bound have the
//! instance's sizes), of which only that block, renamed, and its bodies are kept. Invariants: the
//! copy's diagnostics are placed in the block's own file (`Diagnostics::read_as`: the same bytes),
//! so an error only the values cause points at its place there and one the file gives anyway is
//! said once; the unit is a TwinCAT or CODESYS file when the block's file is; at most 8 rounds of
//! blocks built inside blocks built.

use crate::pipeline::Session;
use diagnostics::{Diagnostics, FileId};
use il_frontend::ast::{CompilationUnit, LibraryElement};
use il_frontend::st::file::{Lang, PendingBody};

/// A file that declares a block with generic constants: its id, the index of its unit, its text
/// as parsed and its implicit program's name.
pub struct GenericText {
    /// The file.
    pub file: FileId,
    /// The index of its unit.
    pub unit: usize,
    /// Its text as parsed (a TwinCAT object's declarations and bodies).
    pub text: String,
    /// The name of its implicit program (see `parse_text`).
    pub implicit: String,
}

/// Whether `text` may declare generic constants (worth noting as a [`GenericText`]).
pub fn declares_generic_constants(text: &str) -> bool {
    text.as_bytes()
        .windows(11)
        .any(|w| w.eq_ignore_ascii_case(b"VAR_GENERIC"))
}

/// See the module documentation. `names` are the names every file declares (known to the
/// qualifiers of the texts parsed again), `twincat_units` marks the units of TwinCAT objects.
pub fn build(
    session: &mut Session,
    texts: &[GenericText],
    names: &std::collections::HashSet<String>,
    units: &mut Vec<CompilationUnit>,
    pending: &mut Vec<PendingBody>,
    twincat_units: &mut Vec<bool>,
) {
    if texts.is_empty() {
        return;
    }
    let known: il_frontend::parser::Constants = units
        .iter()
        .flat_map(|u| il_frontend::parser::global_integer_constants(u, &Diagnostics::new()))
        .collect();
    let mut blocks = Vec::new();
    let mut origin = Vec::new();
    for (k, t) in texts.iter().enumerate() {
        for b in il_frontend::st::generic_blocks::generic_blocks(t.file, &t.text, &known) {
            blocks.push(b);
            origin.push(k);
        }
    }
    // (a block built may hold instances of generic blocks in turn: a few rounds, each renaming
    // the instances of the units built in the one before)
    let mut done: Vec<String> = Vec::new();
    let mut from = 0;
    for _ in 0..8 {
        let to = units.len();
        let built = il_frontend::st::generic_blocks::specialise_instances(
            &mut units[from..to],
            pending,
            &blocks,
            &known,
            &mut session.diags,
        );
        from = to;
        for s in built {
            if done.iter().any(|d| d.eq_ignore_ascii_case(&s.name)) {
                continue;
            }
            done.push(s.name.clone());
            let (Some(block), Some(t)) = (
                blocks.get(s.block),
                origin.get(s.block).and_then(|&k| texts.get(k)),
            ) else {
                continue;
            };
            build_one(
                session,
                block,
                t,
                &s,
                &known,
                names,
                units,
                pending,
                twincat_units,
            );
        }
        if units.len() == from {
            break;
        }
    }
}

/// Parses `t` again as a file of its own with `block`'s generic constants at `s`'s values, and
/// adds the block (renamed `s.name`) and its bodies.
#[allow(clippy::too_many_arguments)]
fn build_one(
    session: &mut Session,
    block: &il_frontend::st::generic_blocks::GenericBlock,
    t: &GenericText,
    s: &il_frontend::st::generic_blocks::Specialisation,
    known: &il_frontend::parser::Constants,
    names: &std::collections::HashSet<String>,
    units: &mut Vec<CompilationUnit>,
    pending: &mut Vec<PendingBody>,
    twincat_units: &mut Vec<bool>,
) {
    let file_name = format!("{}<{}>", session.map.get(t.file).name, s.name);
    let file = session.map.add_file_owned(file_name, t.text.clone());
    // its diagnostics are the block's file's (equal ones said once)
    session.diags.read_as(file, t.file);
    let mut local = Diagnostics::new();
    let (unit, bodies, _) = il_frontend::parser::with_other_files_constants(known.clone(), || {
        il_frontend::st::with_other_files_names(names.clone(), || {
            il_frontend::st::generic_blocks::with_instance_values(block, &s.values, || {
                il_frontend::st::file::parse_text(file, &t.text, &t.implicit, Lang::St, &mut local)
            })
        })
    });
    session.diags.extend(local);
    // only the block: its file's other objects are built with that file
    let Some(mut pou) = unit.items.into_iter().find(|i| {
        matches!(i, LibraryElement::Pou(p) if p.name.span.start as usize == block.name_range.start)
    }) else {
        return;
    };
    let LibraryElement::Pou(p) = &mut pou else {
        return;
    };
    p.name.name = s.name.clone();
    let name_start = block.name_range.start;
    pending.extend(bodies.into_iter().filter(|b| b.name_start == name_start));
    if session.twincat_files.contains(&t.file) {
        session.twincat_files.push(file);
    }
    if session.codesys_files.contains(&t.file) {
        session.codesys_files.push(file);
    }
    let twincat = twincat_units.get(t.unit).copied().unwrap_or(false);
    units.push(CompilationUnit {
        items: vec![pou],
        ..CompilationUnit::default()
    });
    if twincat {
        twincat_units.resize(units.len() - 1, false);
        twincat_units.push(true);
    }
}
