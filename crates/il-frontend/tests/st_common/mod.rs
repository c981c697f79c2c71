//! Test helpers for the ST front end: declarations written in IL, bodies in ST.

#![allow(dead_code)]

use diagnostics::{Diagnostics, SourceMap};
use il_frontend::ast::{CompilationUnit, LibraryElement};
use il_frontend::st;

/// Compiles `decls` (IL text: TYPEs and POUs with empty bodies) where the POU named `pou` gets the ST
/// `body`; returns the printed IL of that POU, and the rendered diagnostics of parsing, lowering and
/// IL sema over the whole unit.
pub fn compile(decls: &str, pou: &str, body: &str) -> (String, String) {
    let mut sm = SourceMap::new();
    let src = format!("{decls}\n(*ST*)\n{body}");
    let file = sm.add("test.st", src.clone());
    let mut diags = Diagnostics::new();
    let mut unit = il_frontend::parse(file, decls, &mut diags);
    let base = decls.len() + "\n(*ST*)\n".len();
    let d = st::Declarations::from_units(std::slice::from_ref(&unit));
    let mut printed = String::new();
    for item in &mut unit.items {
        if let LibraryElement::Pou(p) = item {
            if p.name.is(pou) {
                let (il, temps) = st::compile_body(file, body, base, &d, p, p.span, &mut diags);
                p.body = il;
                if let Some(t) = temps {
                    p.var_blocks.push(t);
                }
                printed = il_frontend::print::unit(&CompilationUnit {
                    items: vec![LibraryElement::Pou(p.clone())],
                    ..Default::default()
                });
            }
        }
    }
    let _ = il_frontend::sema::analyze(std::slice::from_ref(&unit), &mut diags);
    (printed, render(&sm, diags))
}

pub fn render(sm: &SourceMap, diags: Diagnostics) -> String {
    let mut out = String::new();
    for d in diags.into_sorted() {
        out.push_str(&diagnostics::render_short(sm, &d));
        out.push('\n');
    }
    out
}
