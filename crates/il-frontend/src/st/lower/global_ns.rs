//! The global namespace operator of CODESYS and TwinCAT: `.x`, `.GVL.x`.
//!
//! CODESYS ("Operator: Global Namespace") and Beckhoff Infosys ("Global namespace"): "an instance
//! path that starts with a dot . always opens a global namespace. So, if there is a local variable
//! with the same name `<varname>` as a global variable, `.<varname>` is used to address the global
//! variable". The parser reads `.x` as a place whose base is `x` marked by [`GLOBAL_NS`].
//!
//! Input: a marked place. Output: the place qualified by the global variable list that declares
//! `x` (`GVL.x`, which reaches the global even where a local hides `x`), `.GVL.x` as `GVL.x`, or
//! the bare `x` when no named list or two declare it (a global of an unnamed list or a CONFIGURATION,
//! or an undeclared name, reported as any).

use super::super::ast::{Accessor, Place, PlaceBase};
use super::super::types::Declarations;
use crate::ast::Ident;
use std::sync::atomic::AtomicBool;

/// The prefix of the base name the parser gives `.x` (no identifier of a source starts so).
pub(crate) const GLOBAL_NS: &str = "__GLOBAL_NS.";

/// Set once the parser has read a `.x` (the lowering then looks for the marked places).
pub(crate) static GLOBAL_NS_SEEN: AtomicBool = AtomicBool::new(false);

/// Whether `p` is a `.x` place.
pub(super) fn is_marked(p: &Place) -> bool {
    matches!(&p.base, PlaceBase::Name(n) if n.name.starts_with(GLOBAL_NS))
}

/// `p` (a `.x` place) resolved in the global namespace (see the module documentation).
pub(super) fn resolve(p: &mut Place, decls: &Declarations) {
    let PlaceBase::Name(n) = &p.base else { return };
    let Some(name) = n.name.strip_prefix(GLOBAL_NS) else {
        return;
    };
    let name = Ident::new(name, n.span);
    let key = name.key();
    p.base = PlaceBase::Name(name.clone());
    if decls.global_lists.contains_key(&key) {
        return;
    }
    let lists: Vec<&String> = decls
        .global_lists
        .iter()
        .filter(|(_, members)| members.contains_key(&key))
        .map(|(list, _)| list)
        .collect();
    // (two lists declaring `x`: the bare name, ambiguous as any unqualified use, E1030)
    if let [list] = lists.as_slice() {
        p.base = PlaceBase::Name(Ident::new(list.as_str(), name.span));
        p.accessors.insert(0, Accessor::Field(name));
    }
}
