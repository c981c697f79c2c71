//! The control variable of a FOR loop that is an array element or a structure member
//! (`FOR Offset[1] := 0 TO n DO`, TcUnit's FB_TestSuite; `FOR st.i := 1 TO 3 DO`).
//!
//! IEC 61131-3 ed. 3 (7.3.3.4.2) writes `FOR Control_Variable := ...` with an identifier; the
//! CODESYS and Beckhoff help write `<counter>`, "a variable", and TwinCAT compiles TcUnit, whose
//! FB_TestSuite counts in `Offset[1]`, `Offset[2]`, `Offset[3]` (a Beckhoff-supported library):
//! the vendors accept an element or member, so ladderc compiles it. Neither documents when the
//! element's index is evaluated; ladderc chooses the element once, when the loop starts: each
//! index that is not a literal is evaluated into a temporary before the start value is assigned,
//! as the bounds are (the standard evaluates the bounds once and treats the control variable as
//! one variable for the whole loop, which the body must not change). A dereference in the control
//! (`p^.i`) follows the pointer at each access.
//!
//! Input: the control place. Output: its type (as written) and the operand the loop tests and
//! increments, with the index code in `out`. Invariants: the index expressions run exactly once
//! per execution of the FOR statement, before its start value.

use super::super::ast::{Accessor, Expr, ExprKind, Place, PlaceBase, Stmt, StmtKind};
use super::{named, simple, var_operand, PouLowering};
use crate::ast::{Op, Operand, TypeRef};
use crate::Span;
use diagnostics::Diagnostics;

impl PouLowering<'_> {
    /// The type of the control place `p` and its operand, its indices evaluated once into `out`.
    pub(super) fn for_control_element(
        &mut self,
        p: &Place,
        out: &mut Vec<crate::ast::IlStmt>,
        diags: &mut Diagnostics,
    ) -> (Option<TypeRef>, Option<Operand>) {
        let ty = self.env().place_type(p);
        let mut fixed = p.clone();
        for acc in fixed.accessors.iter_mut() {
            let Accessor::Index(ix) = acc else { continue };
            for e in ix.iter_mut() {
                if matches!(e.kind, ExprKind::Literal(_)) {
                    continue;
                }
                let dint = named("DINT", e.span);
                self.lit_hint = Some(dint.clone());
                self.value(e, out, diags);
                let t = self.temp(dint, e.span);
                out.push(simple(Op::St, false, Some(var_operand(&t)), e.span));
                *e = Expr {
                    span: e.span,
                    kind: ExprKind::Place(Place {
                        base: PlaceBase::Name(t),
                        accessors: Vec::new(),
                        span: e.span,
                    }),
                };
            }
        }
        let operand = self.place_operand(&fixed, out, diags);
        (ty, operand)
    }
}

/// `p` as written for a message: `Offset[1]`, `st.i`, `a[..]` (an index that is no literal).
pub(super) fn place_text(p: &Place) -> String {
    let mut s = match &p.base {
        PlaceBase::Name(n) => n.name.clone(),
        PlaceBase::Address(_) => "%..".into(),
    };
    for a in &p.accessors {
        match a {
            Accessor::Field(f) => {
                s.push('.');
                s.push_str(&f.name);
            }
            Accessor::Index(ix) => {
                let parts: Vec<String> = ix
                    .iter()
                    .map(|e| match &e.kind {
                        ExprKind::Literal(crate::ast::Literal {
                            kind: crate::ast::LiteralKind::Int(v),
                            ..
                        }) => v.to_string(),
                        _ => "..".into(),
                    })
                    .collect();
                s.push_str(&format!("[{}]", parts.join(", ")));
            }
            Accessor::Deref(_) => s.push('^'),
            Accessor::Call { .. } => s.push_str("(..)"),
        }
    }
    s
}

/// Where `body` assigns the control element `p` itself (W3141), at any depth of IF, CASE and
/// loops: the same text with literal indices only (`Offset[1]`, `st.i`); an element with a
/// computed index is not compared (its index may differ at run time).
pub(super) fn writes_of_element(p: &Place, body: &[Stmt], found: &mut Vec<Span>) {
    let text = place_text(p);
    if text.contains("..") {
        return;
    }
    let key = text.to_ascii_uppercase();
    let same = |q: &Place| place_text(q).to_ascii_uppercase() == key;
    for s in body {
        match &s.kind {
            StmtKind::Assign { target, .. } if same(target) => found.push(target.span),
            StmtKind::If {
                branches,
                else_body,
            } => {
                for b in branches {
                    writes_of_element(p, &b.body, found);
                }
                writes_of_element(p, else_body.as_deref().unwrap_or_default(), found);
            }
            StmtKind::Case {
                arms, else_body, ..
            } => {
                for a in arms {
                    writes_of_element(p, &a.body, found);
                }
                writes_of_element(p, else_body.as_deref().unwrap_or_default(), found);
            }
            StmtKind::For {
                element: Some(inner),
                ..
            } if same(inner) => found.push(inner.span),
            StmtKind::For { body, .. }
            | StmtKind::While { body, .. }
            | StmtKind::Repeat { body, .. } => writes_of_element(p, body, found),
            _ => {}
        }
    }
}
