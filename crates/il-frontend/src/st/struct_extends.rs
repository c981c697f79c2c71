//! Structures that extend others (CODESYS, TwinCAT: `TYPE ST_B EXTENDS ST_A : STRUCT ... END_STRUCT
//! END_TYPE`, Beckhoff Infosys "Structure": "the structure ST_B has all the components of ST_A,
//! then its own").
//!
//! Input: a file's text and tokens ([`hide_bases`]), then every parsed unit ([`flatten`]).
//! Output: `EXTENDS ST_A :` `STRUCT` is read as `: STRUCT __B : ST_A;` (the same length and line
//! breaks: every span after it stays in place), and each structure whose first field is that
//! hidden `__B` gets the fields of its base (flattened first, a base declared anywhere in the
//! program) in its place. Invariants: a chain of bases that loops, or a base that is no structure,
//! leaves the hidden field as it is (sema then reports its type, or the structure containing
//! itself, E0343, at the base's name); nothing else of the text changes.

use super::file::word;
use super::lexer::{Tok, Token};
use crate::ast::{CompilationUnit, LibraryElement, TypeDef, TypeRef, VarDecl};
use std::collections::{HashMap, HashSet};

/// The hidden first field standing for the base of a structure.
const BASE_FIELD: &str = "__B";

/// The text with each `TYPE X EXTENDS Y : STRUCT` read as `TYPE X : STRUCT __B : Y;`; `None` when
/// the text has none.
pub fn hide_bases(src: &str, toks: &[Token]) -> Option<String> {
    let mut out: Option<String> = None;
    let is = |k: usize, w: &str| {
        toks.get(k).is_some_and(|t| {
            matches!(t.tok, Tok::Ident | Tok::Kw(_)) && word(src, t).eq_ignore_ascii_case(w)
        })
    };
    for k in 0..toks.len() {
        // TYPE name EXTENDS base : STRUCT
        if !(is(k, "TYPE") && is(k + 2, "EXTENDS")) {
            continue;
        }
        let (Some(base), Some(colon)) = (toks.get(k + 3), toks.get(k + 4)) else {
            continue;
        };
        if base.tok != Tok::Ident || colon.tok != Tok::Colon || !is(k + 5, "STRUCT") {
            continue;
        }
        let start = toks[k + 2].range.start;
        let end = toks[k + 5].range.end;
        let Some(old) = src.get(start..end) else {
            continue;
        };
        let breaks: String = old.chars().filter(|c| matches!(c, '\n' | '\r')).collect();
        let name = word(src, base);
        let mut new = format!(":{breaks}STRUCT {BASE_FIELD}:{name};");
        if new.len() > old.len() {
            continue;
        }
        new.push_str(&" ".repeat(old.len() - new.len()));
        out.get_or_insert_with(|| src.to_string())
            .replace_range(start..end, &new);
    }
    out
}

/// Replaces the hidden base field of each structure by its base's fields (see the module
/// documentation).
pub fn flatten(units: &mut [CompilationUnit]) {
    let mut structs: HashMap<String, Vec<VarDecl>> = HashMap::new();
    let mut any = false;
    for item in units.iter().flat_map(|u| u.items.iter()) {
        if let LibraryElement::DataTypes(ts) = item {
            for t in ts {
                if let TypeDef::Struct { fields } = &t.def {
                    any |= fields.first().is_some_and(|f| f.name.is(BASE_FIELD));
                    structs
                        .entry(t.name.key())
                        .or_insert_with(|| fields.clone());
                }
            }
        }
    }
    if !any {
        return;
    }
    let mut done: HashMap<String, Vec<VarDecl>> = HashMap::new();
    let keys: Vec<String> = structs.keys().cloned().collect();
    for k in keys {
        resolve(&k, &structs, &mut done, &mut HashSet::new());
    }
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        if let LibraryElement::DataTypes(ts) = item {
            for t in ts {
                if let TypeDef::Struct { fields } = &mut t.def {
                    if let Some(f) = done.get(&t.name.key()) {
                        *fields = f.clone();
                    }
                }
            }
        }
    }
}

/// The fields of structure `key` with its bases' in place of the hidden field (left when the
/// chain loops or its base is no structure).
fn resolve(
    key: &str,
    structs: &HashMap<String, Vec<VarDecl>>,
    done: &mut HashMap<String, Vec<VarDecl>>,
    visiting: &mut HashSet<String>,
) -> Vec<VarDecl> {
    if let Some(f) = done.get(key) {
        return f.clone();
    }
    let Some(fields) = structs.get(key) else {
        return Vec::new();
    };
    let mut out = fields.clone();
    if let Some(TypeRef::Named(base)) = fields
        .first()
        .filter(|f| f.name.is(BASE_FIELD))
        .map(|f| &f.ty)
    {
        let bkey = base.key();
        if structs.contains_key(&bkey) && visiting.insert(key.to_string()) {
            let mut all = resolve(&bkey, structs, done, visiting);
            visiting.remove(key);
            if !all.iter().any(|f| f.name.is(BASE_FIELD)) {
                all.extend(fields.iter().skip(1).cloned());
                out = all;
            }
        }
    }
    done.insert(key.to_string(), out.clone());
    out
}
