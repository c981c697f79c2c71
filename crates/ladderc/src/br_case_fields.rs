//! B&R Automation Studio structures whose fields differ in letter case only (B&R's own motion
//! library `acp10_mc.typ`: `TargetPosition : DINT;` and `targetPosition : DINT;` in one STRUCT).
//!
//! Automation Studio tells names apart by their case (its IEC compiler is case-sensitive: B&R
//! ships and compiles this very declaration; no B&R help page on it was found in the reference
//! search), so the two are two fields there; IEC 61131-3 (ed. 2 2.1.2, ed. 3 6.1.2) ignores case,
//! so ladderc can keep only one of them.
//!
//! Input: the parsed units (before the bodies are compiled) and the source map. Output: in each
//! structure declared in a `.typ` file, a field spelled as an earlier field of the same structure
//! in another case is taken out (the first one stays), with one warning W1463 at it; each use, in
//! an `.st` file, of a member spelled exactly as a field taken out (`.targetPosition`) is one
//! E1105 there: ladderc would read it as the kept field, which the controller does not. A use
//! spelled as the kept field, and a structure no program uses, are fine (round 34, before: E1002
//! "declared twice" in the vendor's file, the project stopped). Invariants: only `.typ` files
//! (B&R's type declarations) are concerned; elsewhere two such fields stay E1002 (CODESYS,
//! TwinCAT and the standard ignore case); a spelling that another structure or block of the
//! project declares as its own member is not reported at its uses (ladderc cannot tell whose
//! member a use is before the bodies are typed).

use diagnostics::{code, Diagnostic, Diagnostics, Severity, SourceMap, Span};
use il_frontend::ast::{CompilationUnit, Ident, LibraryElement, TypeDef};
use std::path::Path;

/// A field taken out: its spelling and place, the kept field's spelling and the structure's name.
struct Dropped {
    field: Ident,
    kept: String,
    structure: String,
}

/// Takes out the case-only twins of structure fields in `.typ` files (see the module header).
pub fn keep_first_of_case_twins(
    units: &mut [CompilationUnit],
    map: &SourceMap,
    diags: &mut Diagnostics,
) {
    let is_typ = |file: diagnostics::FileId| {
        Path::new(&map.get(file).name)
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("typ"))
    };
    let mut dropped: Vec<Dropped> = Vec::new();
    for unit in units.iter_mut() {
        for item in &mut unit.items {
            let LibraryElement::DataTypes(types) = item else {
                continue;
            };
            for t in types.iter_mut() {
                if !is_typ(t.name.span.file) {
                    continue;
                }
                let TypeDef::Struct { fields } = &mut t.def else {
                    continue;
                };
                let mut kept: Vec<&str> = Vec::new();
                let mut out = Vec::new();
                for (k, f) in fields.iter().enumerate() {
                    match kept
                        .iter()
                        .find(|n| n.eq_ignore_ascii_case(&f.name.name) && **n != f.name.name)
                    {
                        Some(first) => {
                            dropped.push(Dropped {
                                field: f.name.clone(),
                                kept: first.to_string(),
                                structure: t.name.name.clone(),
                            });
                            out.push(k);
                        }
                        None => kept.push(&f.name.name),
                    }
                }
                for &k in out.iter().rev() {
                    fields.remove(k);
                }
            }
        }
    }
    if dropped.is_empty() {
        return;
    }
    for d in &dropped {
        diags.push(
            Diagnostic::new(
                code::W1463,
                Severity::Warning,
                format!(
                    "field `{}` of `{}` differs from its field `{}` in case only: one field under IEC 61131-3, two in case-sensitive B&R Automation Studio",
                    d.field.name, d.structure, d.kept
                ),
            )
            .at(d.field.span)
            .with_primary_label("not compiled: ladderc keeps the first")
            .with_hint(format!(
                "a use spelled `{}` is an error (E1105); `{}` is read as written (`ladderc explain W1463`)",
                d.field.name, d.kept
            )),
        );
    }
    // the members the project declares elsewhere, spelled exactly (their uses are theirs)
    let mut declared: std::collections::HashSet<&str> = std::collections::HashSet::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        match item {
            LibraryElement::DataTypes(types) => {
                for t in types {
                    if let TypeDef::Struct { fields } = &t.def {
                        declared.extend(fields.iter().map(|f| f.name.name.as_str()));
                    }
                }
            }
            LibraryElement::Pou(p) => {
                declared.extend(
                    p.var_blocks
                        .iter()
                        .flat_map(|b| b.vars.iter())
                        .map(|v| v.name.name.as_str()),
                );
            }
            _ => {}
        }
    }
    use il_frontend::st::lexer::{lex, Tok};
    let files: Vec<diagnostics::FileId> = map
        .files()
        .filter(|(_, f)| {
            Path::new(&f.name)
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("st"))
        })
        .map(|(id, _)| id)
        .collect();
    for file in files {
        let src = map.get(file).text.as_str();
        let toks = lex(src).0;
        for (k, t) in toks.iter().enumerate().skip(1) {
            if t.tok != Tok::Ident || toks[k - 1].tok != Tok::Dot {
                continue;
            }
            let Some(word) = src.get(t.range.clone()) else {
                continue;
            };
            let Some(d) = dropped
                .iter()
                .find(|d| d.field.name == word && !declared.contains(word))
            else {
                continue;
            };
            let span = Span {
                file,
                start: t.range.start as u32,
                end: t.range.end as u32,
            };
            diags.push(
                Diagnostic::new(
                    code::E1105,
                    Severity::Error,
                    format!(
                        "`{word}` is the field of `{}` that differs from `{}` in case only: ladderc cannot tell the two apart",
                        d.structure, d.kept
                    ),
                )
                .at(span)
                .with_primary_label("read as this spelling in B&R Automation Studio")
                .with_label(d.field.span, "declared here, beside its case-only twin")
                .with_hint(format!(
                    "IEC 61131-3 ignores case: rename one of the two fields of `{}` to use it (`ladderc explain E1105`)",
                    d.structure
                )),
            );
        }
    }
}
