//! ST parser (skeleton).

use super::ast::{Expr, Stmt};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};

pub fn statements(file: FileId, src: &str, base: usize, diags: &mut Diagnostics) -> Vec<Stmt> {
    if !src.trim().is_empty() {
        diags.push(Diagnostic::error(code::E0100, "ST parser not available yet").at(Span::new(file, base, base + src.len())));
    }
    Vec::new()
}

pub fn expression(file: FileId, src: &str, base: usize, diags: &mut Diagnostics) -> Option<Expr> {
    diags.push(Diagnostic::error(code::E0100, "ST parser not available yet").at(Span::new(file, base, base + src.len())));
    None
}
