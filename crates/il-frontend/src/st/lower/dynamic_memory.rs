//! `__NEW` and `__DELETE` (CODESYS, TwinCAT: instances and variables created at run time on the
//! controller's heap, `p := __NEW(FB_Item);`, `__DELETE(p);`) are refused.
//!
//! Decision (issue #13): ladderc has no heap by design. A reference or pointer holds the address
//! of a named variable, which is what makes its checks possible: `ADR` is taken only of variables,
//! elements and fields, `MEMCPY` is bounded by the object its pointer points into, a NULL
//! dereference is reported by name. A heap would give the run addresses that no declaration
//! names, and memory that a cycle's timing would depend on (allocation, fragmentation), which a
//! PLC scan should not.
//!
//! Input: one ST statement about to be lowered. Output: one E0351 at the first `__NEW` /
//! `__DELETE` call of a file (a library built on the heap uses them everywhere: the others are not
//! reported), each statement holding one dropped (its type argument is no variable, so no E1001
//! follows, and no unused result either). Invariant: a statement without them is untouched.

use super::super::ast::{Expr, ExprKind, Place, PlaceBase, Stmt, StmtKind};
use super::PouLowering;
use crate::Span;
use diagnostics::{code, Diagnostic, Diagnostics};

fn is_dynamic(name: &str) -> bool {
    name.eq_ignore_ascii_case("__NEW") || name.eq_ignore_ascii_case("__DELETE")
}

fn in_expr(e: &Expr, out: &mut Vec<(String, Span)>) {
    let mut todo = vec![e];
    while let Some(e) = todo.pop() {
        match &e.kind {
            ExprKind::Unary { operand, .. } => todo.push(operand),
            ExprKind::Binary { left, right, .. } => {
                todo.push(right);
                todo.push(left);
            }
            ExprKind::Call { name, args } => {
                if is_dynamic(&name.name) {
                    out.push((name.name.to_ascii_uppercase(), e.span));
                } else {
                    todo.extend(args.iter().rev().map(|a| &a.value));
                }
            }
            ExprKind::Place(p) => in_place(p, &mut todo),
            _ => {}
        }
    }
}

fn in_place<'e>(p: &'e Place, todo: &mut Vec<&'e Expr>) {
    for a in p.accessors.iter().rev() {
        match a {
            super::super::ast::Accessor::Index(ix) => todo.extend(ix.iter().rev()),
            super::super::ast::Accessor::Call { args, .. } => {
                todo.extend(args.iter().rev().map(|a| &a.value))
            }
            _ => {}
        }
    }
}

/// The `__NEW` / `__DELETE` calls statement `s` evaluates itself, in source order.
fn calls_in(s: &Stmt) -> Vec<(String, Span)> {
    let mut out = Vec::new();
    match &s.kind {
        StmtKind::Assign { target, value } => {
            let mut todo = Vec::new();
            in_place(target, &mut todo);
            todo.push(value);
            for e in todo {
                in_expr(e, &mut out);
            }
        }
        StmtKind::Call { callee, args } => match &callee.base {
            PlaceBase::Name(n) if callee.accessors.is_empty() && is_dynamic(&n.name) => {
                out.push((n.name.to_ascii_uppercase(), s.span));
            }
            _ => args.iter().for_each(|a| in_expr(&a.value, &mut out)),
        },
        StmtKind::If { branches, .. } => branches.iter().for_each(|b| in_expr(&b.cond, &mut out)),
        StmtKind::Case { selector, .. } => in_expr(selector, &mut out),
        StmtKind::For { from, to, by, .. } => {
            in_expr(from, &mut out);
            in_expr(to, &mut out);
            if let Some(b) = by {
                in_expr(b, &mut out);
            }
        }
        StmtKind::While { cond, .. } => in_expr(cond, &mut out),
        StmtKind::Repeat { until, .. } => in_expr(until, &mut out),
        _ => {}
    }
    out
}

impl PouLowering<'_> {
    /// Reports each `__NEW` / `__DELETE` of `s` (E0351) and says whether there was one (the
    /// statement is then dropped).
    pub(super) fn refuse_dynamic_memory(&mut self, s: &Stmt, diags: &mut Diagnostics) -> bool {
        let found = calls_in(s);
        let first_in_file = |span: &Span| {
            self.decls
                .heap_reported
                .lock()
                .map(|mut files| files.insert(span.file))
                .unwrap_or(true)
        };
        if let Some((name, span)) = found.first().filter(|(_, span)| first_in_file(span)) {
            let hint = if name == "__NEW" {
                "declare the instance or variable (`VAR item : FB_Item; END_VAR`) and take its address (`p := ADR(item);`); for a number of them, an ARRAY of instances used as a pool"
            } else {
                "nothing to free: ladderc's pointers point to declared variables; set the pointer to 0 (`p := 0;`) when it no longer points to one"
            };
            diags.push(
                Diagnostic::error(
                    code::E0351,
                    format!("`{name}`: ladderc has no dynamic memory (no heap) to create or free variables at run time (its other uses in this file are not reported)"),
                )
                .at(*span)
                .with_primary_label("dynamic memory")
                .with_hint(hint),
            );
        }
        !found.is_empty()
    }
}
