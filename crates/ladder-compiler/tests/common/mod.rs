//! Test helpers: compile a file, render short diagnostics.
#![allow(dead_code)]

use diagnostics::{render_short, Diagnostics, SourceMap};
use ladder_compiler::ast::CompilationUnit;

/// The shared corpus: `../../../shared/corpus` from the crate (the repository's sibling `shared/`), or
/// the nearest ancestor's `shared/corpus` (worktrees live deeper than the main checkout).
pub fn corpus_dir() -> std::path::PathBuf {
    let here = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    here.ancestors()
        .map(|a| a.join("shared/corpus"))
        .find(|p| p.is_dir())
        .unwrap_or_else(|| here.join("../../../shared/corpus"))
}

pub fn corpus(name: &str) -> String {
    let path = corpus_dir().join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

pub fn fixture(name: &str) -> String {
    let path = format!("{}/tests/fixtures/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// Compiles `xml` named `name`; returns the unit and the short diagnostics, one per line.
pub fn compile(name: &str, xml: &str) -> (CompilationUnit, String) {
    let mut map = SourceMap::new();
    let file = map.add(name, xml);
    let mut diags = Diagnostics::new();
    let unit = ladder_compiler::compile_xml(file, xml, &mut diags);
    let text: String = diags
        .into_sorted()
        .iter()
        .map(|d| render_short(&map, d) + "\n")
        .collect();
    (unit, text)
}

/// The emitted IL of a unit.
pub fn dump_unit(u: &CompilationUnit) -> String {
    ladder_compiler::emit_il(u)
}
