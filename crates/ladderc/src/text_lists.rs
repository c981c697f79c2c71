//! CODESYS global variable list objects exported as text: a file `GVL.txt` (or `GVL.st`) that
//! holds only `VAR_GLOBAL` blocks (with or without `{attribute 'qualified_only'}`) is the list
//! `GVL`, so the project's `GVL.nJoints` resolves in bodies (bounds: `il_frontend`'s `list_bounds`).
//!
//! Input: the units read from text files, each with its file's stem. Output: the `VAR_GLOBAL`
//! blocks of each such unit named after the stem. Invariants: only a unit whose items are all
//! global variable lists is named, and only when no POU, type or variable of any unit, and no
//! other list, already has the name (it then stays unnamed, as before: its members are used
//! unqualified); an unnamed list's members stay reachable without the qualifier. A stem of the form
//! `global (GVL)` (a CODESYS project exported object by object as `NAME (KIND).st`) names `global`
//! ([`object_name`]).

use il_frontend::ast::{CompilationUnit, Ident, LibraryElement, TypeDecl};
use std::collections::HashSet;

/// The object's name in a file stem: `global` for `global (GVL)`, `PLC_PRG` for `PLC_PRG (PRG)`
/// (CODESYS objects exported one per file as `NAME (KIND).st`, KIND the object's kind as CODESYS
/// abbreviates it: GVL, PRG, FB, FUN, DUT, ITF, METH, PROP, ACT); any other stem as it is.
pub fn object_name(stem: &str) -> &str {
    const KINDS: &[&str] = &[
        "GVL", "PRG", "FB", "FUN", "DUT", "ITF", "METH", "PROP", "ACT",
    ];
    let Some(open) = stem.rfind(" (") else {
        return stem;
    };
    let kind = &stem[open + 2..];
    match kind.strip_suffix(')') {
        Some(k) if KINDS.iter().any(|x| x.eq_ignore_ascii_case(k)) => stem[..open].trim_end(),
        _ => stem,
    }
}

/// Names the global lists of the units `lists` gives (unit index, file stem); see the module
/// documentation.
pub fn name_text_lists(units: &mut [CompilationUnit], lists: &[(usize, String)]) {
    if lists.is_empty() {
        return;
    }
    let mut taken: HashSet<String> = HashSet::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        match item {
            LibraryElement::Pou(p) => {
                taken.insert(p.name.key());
            }
            LibraryElement::DataTypes(types) => {
                taken.extend(types.iter().map(|t: &TypeDecl| t.name.key()));
            }
            LibraryElement::GlobalVars(b) => {
                taken.extend(b.name.iter().map(Ident::key));
                taken.extend(b.vars.iter().map(|v| v.name.key()));
            }
            LibraryElement::Configuration(c) => {
                taken.insert(c.name.key());
            }
            LibraryElement::Action(_) => {}
        }
    }
    for (k, stem) in lists {
        let Some(unit) = units.get_mut(*k) else {
            continue;
        };
        let only_lists = !unit.items.is_empty()
            && unit
                .items
                .iter()
                .all(|i| matches!(i, LibraryElement::GlobalVars(b) if b.name.is_none()));
        if !only_lists || !taken.insert(stem.to_ascii_uppercase()) {
            continue;
        }
        for item in &mut unit.items {
            if let LibraryElement::GlobalVars(block) = item {
                block.name = Some(Ident::new(stem.clone(), block.span));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::object_name;

    #[test]
    fn object_names_of_exported_stems() {
        assert_eq!(object_name("global (GVL)"), "global");
        assert_eq!(object_name("PLC_PRG (PRG)"), "PLC_PRG");
        assert_eq!(object_name("GVL"), "GVL");
        assert_eq!(object_name("notes (draft)"), "notes (draft)");
    }
}
