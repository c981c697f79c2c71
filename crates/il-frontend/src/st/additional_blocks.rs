//! The "additional function blocks" of Beremiz and OpenPLC Editor: HYSTERESIS, INTEGRAL,
//! DERIVATIVE, RAMP and PID (IEC 61131-3 ed. 2, Annex F), SEMA (edition 1's semaphore) and RTC
//! (edition 1's real-time clock, on the scan clock), which
//! those editors offer beside the standard blocks and real OpenPLC projects instantiate
//! (`pid0 : PID;`, a `<block typeName="INTEGRAL">`).
//!
//! Input: the parsed units of a project. Output: the names of the blocks it uses without declaring
//! them ([`wanted`]), and the ST text of just those blocks and the blocks they call
//! ([`source_for`], from `additional_blocks.st`, written for ladderc from the standard's
//! algorithms), which the caller reads as one more ST file. Invariants: a project that declares a
//! POU or type of one of these names keeps its own (that block is never added); the text keeps
//! every line of `additional_blocks.st` (blocks left out are blanked), so a position in it is the
//! file's own; a TIME counts in seconds inside these blocks, as in the runtimes they come from.

use crate::ast::{CompilationUnit, LibraryElement, TypeDef, TypeRef};
use diagnostics::Span;
use std::collections::{HashMap, HashSet};

/// The blocks' ST source.
pub const SOURCE: &str = include_str!("additional_blocks.st");

/// The name the text is read under (diagnostics, tools).
pub const FILE_NAME: &str = "<ladderc>/additional_blocks.st";

/// Each block with the blocks of this file it instantiates.
const BLOCKS: &[(&str, &[&str])] = &[
    ("HYSTERESIS", &[]),
    ("INTEGRAL", &[]),
    ("DERIVATIVE", &[]),
    ("RAMP", &[]),
    ("PID", &["INTEGRAL", "DERIVATIVE"]),
    ("SEMA", &[]),
    ("RTC", &[]),
];

/// Whether `name` (any case) is one of the additional blocks.
pub fn is_additional(name: &str) -> bool {
    BLOCKS.iter().any(|(n, _)| n.eq_ignore_ascii_case(name))
}

/// The additional blocks `units` use as a type (of a variable, a structure field, an array's
/// elements, a function's result) and declare nowhere, each with its first use, then the blocks
/// those call that the units do not declare either (no use of their own); upper case, in
/// the file's order. Empty for nearly every project.
pub fn wanted(units: &[CompilationUnit]) -> Vec<(&'static str, Option<Span>)> {
    let mut declared: HashSet<String> = HashSet::new();
    let mut used: HashMap<String, Span> = HashMap::new();
    let mut use_type = |ty: &TypeRef| {
        let mut t = ty;
        while let TypeRef::Array { element, .. } = t {
            t = element;
        }
        if let TypeRef::Named(n) = t {
            if is_additional(&n.name) {
                used.entry(n.name.to_ascii_uppercase()).or_insert(n.span);
            }
        }
    };
    for item in units.iter().flat_map(|u| u.items.iter()) {
        match item {
            LibraryElement::Pou(p) => {
                declared.insert(p.name.name.to_ascii_uppercase());
                if let Some(r) = &p.return_type {
                    use_type(r);
                }
            }
            LibraryElement::DataTypes(types) => {
                for d in types {
                    declared.insert(d.name.name.to_ascii_uppercase());
                    if let TypeDef::Struct { fields } = &d.def {
                        fields.iter().for_each(|f| use_type(&f.ty));
                    }
                }
            }
            _ => {}
        }
        for v in item.var_blocks().iter().flat_map(|b| b.vars.iter()) {
            use_type(&v.ty);
        }
    }
    let mut out: Vec<(&'static str, Option<Span>)> = Vec::new();
    for (name, calls) in BLOCKS {
        if used.contains_key(*name) {
            for n in std::iter::once(name).chain(calls.iter()) {
                if !declared.contains(*n) && !out.iter().any(|(o, _)| o == n) {
                    out.push((n, used.get(*n).copied()));
                }
            }
        }
    }
    out.sort_by_key(|(n, _)| BLOCKS.iter().position(|(b, _)| b == n));
    out
}

/// The blocks' declarations (parsed once): their interfaces, for a reader that must know a block's
/// pins before the project's units exist (PLCopen XML's block boxes).
pub fn declarations() -> &'static [crate::ast::Pou] {
    static POUS: std::sync::OnceLock<Vec<crate::ast::Pou>> = std::sync::OnceLock::new();
    POUS.get_or_init(|| {
        let mut diags = diagnostics::Diagnostics::new();
        // (a file id of its own: no span of these declarations is ever reported)
        let (unit, _, _) = super::file::parse_text(
            diagnostics::FileId(u32::MAX),
            SOURCE,
            "additional_blocks",
            super::file::Lang::St,
            &mut diags,
        );
        unit.items
            .into_iter()
            .filter_map(|i| match i {
                LibraryElement::Pou(p) => Some(p),
                _ => None,
            })
            .collect()
    })
}

/// [`SOURCE`] with only the blocks named in `wanted` (upper case): every other byte of the file
/// that belongs to another block becomes a space (line breaks kept), the comments before a block
/// that is left out included.
pub fn source_for(wanted: &[&str]) -> String {
    let mut out = String::with_capacity(SOURCE.len());
    let mut keep = true;
    // each block runs from its `FUNCTION_BLOCK` line (with the comment lines just before it) to
    // its `END_FUNCTION_BLOCK` line: decided line by line, looking ahead for a comment's block
    let lines: Vec<&str> = SOURCE.split_inclusive('\n').collect();
    for (i, line) in lines.iter().enumerate() {
        let trimmed = line.trim_start();
        if trimmed.starts_with("(*") && !trimmed.contains("ladderc's built-in copy") {
            // a block's comment: kept with the block that follows it
            let next = lines[i..]
                .iter()
                .find_map(|l| l.trim_start().strip_prefix("FUNCTION_BLOCK "));
            if let Some(name) = next {
                keep = wanted.iter().any(|w| w.eq_ignore_ascii_case(name.trim()));
            }
        } else if let Some(name) = trimmed.strip_prefix("FUNCTION_BLOCK ") {
            keep = wanted.iter().any(|w| w.eq_ignore_ascii_case(name.trim()));
        }
        if keep {
            out.push_str(line);
        } else {
            out.extend(line.chars().map(|c| if c == '\n' { '\n' } else { ' ' }));
        }
        if trimmed.starts_with("END_FUNCTION_BLOCK") {
            keep = true;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_block_left_out_is_blanked_line_for_line() {
        let text = source_for(&["SEMA"]);
        assert_eq!(text.lines().count(), SOURCE.lines().count());
        assert!(text.contains("FUNCTION_BLOCK SEMA"));
        assert!(!text.contains("FUNCTION_BLOCK PID"));
        assert!(!text.contains("bumpless"));
        assert!(text.contains("ladderc's built-in copy"));
        let all = source_for(&[
            "HYSTERESIS",
            "INTEGRAL",
            "DERIVATIVE",
            "RAMP",
            "PID",
            "SEMA",
            "RTC",
        ]);
        assert_eq!(all, SOURCE);
    }

    #[test]
    fn every_block_is_declared_with_its_pins() {
        let names: Vec<String> = declarations().iter().map(|p| p.name.name.clone()).collect();
        assert_eq!(
            names,
            [
                "HYSTERESIS",
                "INTEGRAL",
                "DERIVATIVE",
                "RAMP",
                "PID",
                "SEMA",
                "RTC"
            ]
        );
        assert!(BLOCKS.iter().all(|(n, _)| names.iter().any(|m| m == n)));
        let pid = &declarations()[4];
        let inputs: usize = pid
            .var_blocks
            .iter()
            .filter(|b| b.kind == crate::ast::VarKind::Input)
            .map(|b| b.vars.len())
            .sum();
        assert_eq!(inputs, 8);
    }
}
