//! Test helpers: compile a file, render short diagnostics.
#![allow(dead_code)]

use diagnostics::{render_short, Diagnostics, SourceMap};
use ladder_compiler::ast::CompilationUnit;

/// The text of a corpus file (see the `test-corpus` crate): bundled, or read from `$LADDERC_CORPUS`;
/// `None` after a skip line when it is neither.
pub fn corpus(name: &str) -> Option<String> {
    test_corpus::read(name)
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
