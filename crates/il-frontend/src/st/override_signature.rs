//! A derived block's method that overrides a base's method with another signature (SIMATIC AX's
//! overloading across inheritance).
//!
//! Input: the versions of each method along one chain of `EXTENDS` (root first), as
//! [`super::inherit`] collects them, and the names of the chain's levels. Output: the same versions
//! less every one whose signature (result, inputs, outputs, in-outs: names and types) differs from
//! the version it would override, each dropped one reported by one E1084 at its name; and, for
//! each method that lost a version, the widest access of its versions: the derived block's copy of
//! the kept version gets it and calls treat it as overloaded (a call that fits the dropped version,
//! also from outside when only the dropped one is PUBLIC, reports nothing more, as for two METHODs
//! of one name in one class).
//! Invariants: the root's version of a method is always kept; a base's PRIVATE method is not
//! overridden (IEC 61131-3 ed. 3, 6.6.5: it is invisible to the derived block), so a derived
//! method of its name replaces it whatever its signature; `FB_init`, `FB_reinit` and `FB_exit` are
//! not overrides (every level's FB_init runs with its own inputs, `super::fb_init`) and are left
//! alone.
//!
//! IEC 61131-3 ed. 3, 6.6.5.5 (OVERRIDE): an overriding method has the signature of the method it
//! overrides; CODESYS and TwinCAT refuse another one. SIMATIC AX reads a derived method of a base's
//! name with other parameters as an overload: `THIS.Init(a)` in the derived `Init(a, b)` calls the
//! base's `Init(a)` (before round 31: no diagnostic for the override, and that call was E0106
//! "calls itself"). ladderc compiles no overloads (E1084): the base's version is kept.

use super::file::PendingMethod;
use crate::ast::{Access, Ident, MemberAccess};
use crate::FileId;
use diagnostics::{code, Diagnostic, Diagnostics};
use std::collections::HashMap;

/// One version of a method: its level in the chain (0 = the root), the method, its file.
pub type Version<'a> = (usize, &'a PendingMethod, FileId);

/// Drops from `versions` each derived version whose signature differs from the version it
/// overrides (one E1084 each, into `diags`); `levels`: the name of each level of the chain.
/// Returns, for the key of each method that lost a version, the widest access of its versions
/// (`None`: PUBLIC).
pub fn keep_base_signatures(
    versions: &mut HashMap<String, Vec<Version<'_>>>,
    levels: &[&Ident],
    diags: &mut Diagnostics,
) -> HashMap<String, Option<MemberAccess>> {
    let mut dropped = HashMap::new();
    for (key, list) in versions.iter_mut() {
        if super::fb_init::is_special_method(key) {
            continue;
        }
        let mut kept: Vec<Version<'_>> = Vec::with_capacity(list.len());
        for &(j, m, file) in list.iter() {
            let overridden = kept
                .last()
                .filter(|(_, b, _)| !is_private(b))
                .map(|&(i, b, _)| (i, b));
            match overridden {
                Some((i, b)) if !same_signature(b, m) => {
                    diags.push(mismatch(m, levels.get(j), b, levels.get(i)));
                    let widest = dropped
                        .entry(key.clone())
                        .or_insert_with(|| b.access.clone());
                    if rank(&m.access) > rank(widest) {
                        *widest = m.access.clone();
                    }
                }
                _ => kept.push((j, m, file)),
            }
        }
        *list = kept;
    }
    dropped
}

/// Whether `base` and `m` have one signature: equal, or equal but for types that one of them
/// writes with a library qualifier the other leaves out (`i : Resi4MPM.ParameterSet` against the
/// base's `i : ParameterSet`, the library given as another input or missing: `qualifiers` wrote
/// the qualified one `__si4MPM_ParameterSet`, and a missing library is its own E1032). Before
/// round 32 such a pair was E1084.
fn same_signature(base: &PendingMethod, m: &PendingMethod) -> bool {
    let (a, b) = (
        super::inherit::signature(base),
        super::inherit::signature(m),
    );
    if a == b {
        return true;
    }
    let words = |s: &str| {
        s.split([' ', ':', '[', ']', ','])
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    let (a, b) = (words(&a), words(&b));
    a.len() == b.len()
        && a.iter()
            .zip(&b)
            .all(|(x, y)| x == y || qualified(x, y) || qualified(y, x))
}

/// Whether `q` is `t` written with a library qualifier (`__<qualifier less its first two
/// characters>_<t>`, upper case, as `qualifiers` writes `Lib.T`).
fn qualified(q: &str, t: &str) -> bool {
    !t.is_empty()
        && !t.starts_with("__")
        && q.len() > t.len() + 3
        && q.starts_with("__")
        && q.ends_with(t)
        && q.as_bytes()[q.len() - t.len() - 1] == b'_'
}

/// How widely an access lets a method be called: PUBLIC (`None`) 2, PROTECTED 1, PRIVATE 0.
fn rank(access: &Option<MemberAccess>) -> u8 {
    match access.as_ref().map(|a| a.access) {
        None => 2,
        Some(Access::Private) => 0,
        Some(_) => 1,
    }
}

/// Whether a method is `METHOD PRIVATE`.
fn is_private(m: &PendingMethod) -> bool {
    m.access
        .as_ref()
        .is_some_and(|a| matches!(a.access, Access::Private))
}

/// The E1084 at derived method `m` (of block `owner`) that differs from `base` (of `base_owner`).
fn mismatch(
    m: &PendingMethod,
    owner: Option<&&Ident>,
    base: &PendingMethod,
    base_owner: Option<&&Ident>,
) -> Diagnostic {
    let name = |o: Option<&&Ident>| o.map_or(String::new(), |i| i.name.clone());
    Diagnostic::error(
        code::E1084,
        format!(
            "METHOD `{}` of `{}` overrides `{}.{}` with another signature: `{}`, the base's is `{}`",
            m.name.name,
            name(owner),
            name(base_owner),
            base.name.name,
            super::inherit::shown(m),
            super::inherit::shown(base),
        ),
    )
    .at(m.name.span)
    .with_primary_label("another signature than the base method's")
    .with_label(base.name.span, "the base method")
    .with_hint(
        "IEC 61131-3 ed. 3 (6.6.5.5): an overriding method keeps the signature of the method it \
         overrides; SIMATIC AX overloads methods by their parameters, ladderc does not: give it the \
         base's inputs and outputs, or rename it (the base's method is the one compiled and called)",
    )
}
