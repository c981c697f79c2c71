//! CODESYS's short-circuit operators `AND_THEN` and `OR_ELSE` (W0324) in ST expressions.
//!
//! Input: an expression about to be lowered at a point where the current result is free and jumps
//! may stand (not inside a deferred operator's list). Output: for each `a AND_THEN b` (`a OR_ELSE
//! b`), the code computing it into a BOOL temporary `t` is appended to the code, and the expression
//! reads `t` in its place:
//!
//! ```text
//!     <a>  ST t  JMPCN skip  <b>  ST t  skip:        (OR_ELSE: JMPC)
//! ```
//!
//! Invariants: the right operand's code (its function calls, its array indexes and the
//! short-circuit operations inside it) runs only when the left one does not decide, so a guarded
//! index or call is never evaluated; the left operand runs first. The operations are computed
//! before the rest of their expression (as call arguments are), so in `f(x) + g(a AND_THEN b)`
//! `a` and `b` are evaluated before `f(x)`.

use super::super::ast::{Accessor, BinaryOp, Expr, ExprKind, Place, PlaceBase};
use super::{jump, named, simple, var_operand, PouLowering};
use crate::ast::{Condition, IlStmt, Op};
use diagnostics::Diagnostics;

/// Whether `e` holds an `AND_THEN` or `OR_ELSE` (walks left operands iteratively: a source line's
/// chain of operators is as long as the line).
fn has_short_circuit(mut e: &Expr) -> bool {
    loop {
        match &e.kind {
            ExprKind::Binary { op, left, right } => {
                if matches!(op, BinaryOp::AndThen | BinaryOp::OrElse) || has_short_circuit(right) {
                    return true;
                }
                e = left;
            }
            ExprKind::Unary { operand, .. } => e = operand,
            ExprKind::Call { args, .. } => return args.iter().any(|a| has_short_circuit(&a.value)),
            ExprKind::Place(p) => return place_has(p),
            _ => return false,
        }
    }
}

fn place_has(p: &Place) -> bool {
    p.accessors.iter().any(|a| match a {
        Accessor::Index(ix) => ix.iter().any(has_short_circuit),
        Accessor::Call { args, .. } => args.iter().any(|a| has_short_circuit(&a.value)),
        Accessor::Field(_) | Accessor::Deref(_) => false,
    })
}

impl PouLowering<'_> {
    /// `e` with each `AND_THEN`/`OR_ELSE` replaced by a BOOL temporary whose code goes to `out`
    /// (see the module documentation); `None` when `e` has none.
    pub(super) fn short_circuits(
        &mut self,
        e: &Expr,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) -> Option<Expr> {
        if !has_short_circuit(e) {
            return None;
        }
        let hint = self.lit_hint.take();
        let mut plain = e.clone();
        self.replace(&mut plain, out, diags);
        // the type cache may hold the replaced nodes' addresses
        self.types.get_mut().clear();
        self.lit_hint = hint;
        Some(plain)
    }

    fn replace(&mut self, e: &mut Expr, out: &mut Vec<IlStmt>, diags: &mut Diagnostics) {
        match &mut e.kind {
            ExprKind::Binary {
                op: op @ (BinaryOp::AndThen | BinaryOp::OrElse),
                left,
                right,
            } => {
                let and_then = *op == BinaryOp::AndThen;
                let span = e.span;
                let what = format!("operand of {}", op.spelling());
                let both_bool =
                    self.check_bool(left, &what, diags) & self.check_bool(right, &what, diags);
                if !both_bool {
                    e.kind = ExprKind::Error;
                    self.poisoned = true;
                    return;
                }
                let t = self.temp(named("BOOL", span), span);
                let skip = self.fresh_label(if and_then { "ANDTHEN" } else { "ORELSE" }, span);
                // each operand is lowered by `value`, which computes the operations inside it the
                // same way (the right operand's after the jump)
                self.lit_hint = Some(named("BOOL", left.span));
                self.value(left, out, diags);
                out.push(simple(Op::St, false, Some(var_operand(&t)), span));
                let cond = if and_then {
                    Condition::IfFalse
                } else {
                    Condition::IfTrue
                };
                out.push(jump(cond, &skip, span));
                self.lit_hint = Some(named("BOOL", right.span));
                self.value(right, out, diags);
                out.push(simple(Op::St, false, Some(var_operand(&t)), span));
                out.push(IlStmt::Label(skip));
                e.kind = ExprKind::Place(Place {
                    base: PlaceBase::Name(t),
                    accessors: Vec::new(),
                    span,
                });
            }
            ExprKind::Binary { left, right, .. } => {
                // (recursive: the parser caps an expression at 1,000 operations, E0109)
                for x in [left, right] {
                    if has_short_circuit(x) {
                        self.replace(x, out, diags);
                    }
                }
            }
            ExprKind::Unary { operand, .. } => self.replace(operand, out, diags),
            ExprKind::Call { args, .. } => {
                for a in args.iter_mut() {
                    if has_short_circuit(&a.value) {
                        self.replace(&mut a.value, out, diags);
                    }
                }
            }
            ExprKind::Place(p) => {
                for a in p.accessors.iter_mut() {
                    if let Accessor::Index(ix) = a {
                        for x in ix.iter_mut() {
                            if has_short_circuit(x) {
                                self.replace(x, out, diags);
                            }
                        }
                    }
                }
            }
            _ => {}
        }
    }
}
