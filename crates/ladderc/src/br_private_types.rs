//! B&R Automation Studio programs' private data types: a `.typ` file in a program folder (one
//! holding `IEC.prg` or `ANSIC.prg`; the `IEC.prg` lists it as `<File Description="Local data
//! types" Private="true">Types.typ</File>`) declares types that only that program sees, so two
//! programs may each declare their own `InternalType` or `MachineStateEnum` with other fields or
//! values (as B&R's program template does).
//!
//! Input: the parsed units once each program folder's `.var` blocks are its parts' own
//! ([`crate::br_programs::own_variables`]), before the bodies are compiled. Output: each
//! private type whose name another declaration of the project also takes (another program's
//! private type, or a global one) is renamed `Program.Name` (the program named after its folder,
//! as the program is), and every type name in the folder's own declarations (its `.typ` types,
//! its parts' VAR blocks) that names it follows. A global type of that name keeps its name and
//! is what the other programs see. Invariants: only names in declarations are renamed (the
//! statements name a type rarely: a typed literal `InternalType#X` there still names the global
//! one, or is an unknown type); a folder that declares one name twice keeps both (the checks'
//! E1002); nothing outside program folders changes. Before round 34: one namespace of types, one
//! E1002 per clash and a cascade of E1021/E1001 in the other programs (round 25 kept one copy of
//! a type declared alike in several folders, which is wrong when its fields name a type each
//! program declares otherwise: each program now has its own copy). In the statements, an
//! enumerated value of another program's private enumeration is not seen (sema's
//! `private_to_another_program`), so a value several programs' enumerations declare is the
//! program's own.

use il_frontend::ast::{CompilationUnit, Ident, LibraryElement, TypeDef, TypeRef};
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};

/// Gives each program its own private types where their names clash (see the module header).
pub fn scope_private_types(units: &mut [CompilationUnit], map: &diagnostics::SourceMap) {
    let mut folders_of: HashMap<diagnostics::FileId, PathBuf> = HashMap::new();
    let mut dir_of = |file: diagnostics::FileId| -> PathBuf {
        folders_of
            .entry(file)
            .or_insert_with(|| {
                let name = Path::new(&map.get(file).name);
                let path = std::fs::canonicalize(name).unwrap_or_else(|_| name.to_path_buf());
                path.parent().unwrap_or(Path::new("")).to_path_buf()
            })
            .clone()
    };
    let is_typ = |file: diagnostics::FileId| {
        Path::new(&map.get(file).name)
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("typ"))
    };
    let mut program_folder: HashMap<PathBuf, bool> = HashMap::new();
    // by upper-case name: the folder of each declaration (None: not private)
    let mut by_name: BTreeMap<String, Vec<Option<PathBuf>>> = BTreeMap::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        let names: Vec<&Ident> = match item {
            LibraryElement::DataTypes(types) => types.iter().map(|t| &t.name).collect(),
            LibraryElement::Pou(p) => vec![&p.name],
            _ => continue,
        };
        for n in names {
            let private = matches!(item, LibraryElement::DataTypes(_)) && is_typ(n.span.file);
            let folder = private.then(|| dir_of(n.span.file)).filter(|d| {
                *program_folder
                    .entry(d.clone())
                    .or_insert_with(|| crate::br_programs::is_program_folder(d))
            });
            by_name.entry(n.key()).or_default().push(folder);
        }
    }
    // by folder: upper-case name -> new name
    let mut renames: BTreeMap<PathBuf, HashMap<String, String>> = BTreeMap::new();
    for (key, seen) in &by_name {
        if seen.len() < 2 {
            continue;
        }
        for dir in seen.iter().flatten() {
            if seen.iter().filter(|d| d.as_ref() == Some(dir)).count() > 1 {
                continue;
            }
            let folder = dir
                .file_name()
                .and_then(|n| n.to_str())
                .unwrap_or("BRProgram");
            let program = il_frontend::implicit_program_name(folder);
            renames
                .entry(dir.clone())
                .or_default()
                .insert(key.clone(), format!("{program}.{key}"));
        }
    }
    if renames.is_empty() {
        return;
    }
    for unit in units.iter_mut() {
        for item in &mut unit.items {
            match item {
                LibraryElement::DataTypes(types) => {
                    for t in types.iter_mut() {
                        if !is_typ(t.name.span.file) {
                            continue;
                        }
                        let Some(names) = renames.get(&dir_of(t.name.span.file)) else {
                            continue;
                        };
                        if let Some(new) = names.get(&t.name.key()) {
                            // the name as written, after the program's
                            let shown = new
                                .split_once('.')
                                .map(|(p, _)| format!("{p}.{}", t.name.name))
                                .unwrap_or_else(|| new.clone());
                            t.name = Ident::new(&shown, t.name.span);
                        }
                        match &mut t.def {
                            TypeDef::Alias { ty, .. } => rename(ty, names),
                            TypeDef::Struct { fields } => {
                                fields.iter_mut().for_each(|f| rename(&mut f.ty, names))
                            }
                            TypeDef::Enum { .. } => {}
                        }
                    }
                }
                LibraryElement::Pou(p) => {
                    let Some(names) = renames.get(&dir_of(p.name.span.file)) else {
                        continue;
                    };
                    for v in p.var_blocks.iter_mut().flat_map(|b| b.vars.iter_mut()) {
                        rename(&mut v.ty, names);
                    }
                }
                _ => {}
            }
        }
    }
}

/// `ty` with each type name of `names` (upper case -> new name) renamed.
fn rename(ty: &mut TypeRef, names: &HashMap<String, String>) {
    match ty {
        TypeRef::Named(id) => {
            if let Some(new) = names.get(&id.key()) {
                let shown = new
                    .split_once('.')
                    .map(|(p, _)| format!("{p}.{}", id.name))
                    .unwrap_or_else(|| new.clone());
                *id = Ident::new(&shown, id.span);
            }
        }
        TypeRef::Array { element, .. } => rename(element, names),
        TypeRef::Ref { target, .. } => rename(target, names),
        TypeRef::String { .. } | TypeRef::Subrange { .. } | TypeRef::Enum { .. } => {}
    }
}
