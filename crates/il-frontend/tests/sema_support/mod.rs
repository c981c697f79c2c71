//! Test support for the sema tests: parse and analyse source text, render the diagnostics of both stages
//! (human form, sorted) for snapshots.
#![allow(dead_code)]

use diagnostics::{render_human, Diagnostics, FileId, SourceMap};
use il_frontend::ast::CompilationUnit;
use il_frontend::sema::{analyze, Model};

/// Analyses one source text; returns the model and the rendered diagnostics of parser and sema.
pub fn analyze_src(src: &str) -> (Model, String) {
    let mut map = SourceMap::new();
    let file = map.add("test.il", src.to_string());
    let mut diags = Diagnostics::new();
    let unit = il_frontend::parse(file, src, &mut diags);
    let model = analyze(&[unit], &mut diags);
    let list = diags.into_sorted();
    (model, render_human(&map, &list))
}

/// Source and diagnostics together, for snapshots.
pub fn check(src: &str) -> String {
    let (_, diags) = analyze_src(src);
    format!(
        "{src}\n---- diagnostics ----\n{}",
        if diags.is_empty() {
            "(none)\n".into()
        } else {
            diags
        }
    )
}

/// The codes of the diagnostics, sorted by position.
pub fn codes(src: &str) -> Vec<String> {
    let mut map = SourceMap::new();
    let file = map.add("test.il", src.to_string());
    let mut diags = Diagnostics::new();
    let unit = il_frontend::parse(file, src, &mut diags);
    analyze(&[unit], &mut diags);
    diags
        .into_sorted()
        .into_iter()
        .map(|d| d.code.0.to_string())
        .collect()
}

/// Parses one file of a multi-file test.
pub fn read(file: FileId, src: &str, diags: &mut Diagnostics) -> CompilationUnit {
    il_frontend::parse(file, src, diags)
}
