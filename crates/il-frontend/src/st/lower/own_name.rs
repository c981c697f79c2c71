//! A program's own actions and methods named through the program's name, inside the program:
//! `Prog.Act();`, `Prog.M(x := 1);`, `y := Prog.M(2);` in `Prog`'s body, actions or methods.
//!
//! CODESYS ("Object: Action": `<program name>.<action name>`, the program's name optional in the
//! program's own implementation) and TwinCAT accept the qualified name there: it is the same call
//! as `Act();` / `M(x := 1)`, on the running instance's state, at once (before issue #13's round
//! 26 it was E3135).
//!
//! Input: the statements of a PROGRAM (or of one of its actions or methods) about to be lowered.
//! Output: the same statements with the prefix `Prog.` dropped from every place that names one of
//! the program's actions or methods, or the hidden result `__M_<M>` the parser reads a method
//! call's result by (`Prog.__M_M`, see `Parser::method_call_expr`); a method call the parser left
//! in its expression ([`super::method_flow::METHOD_CALL`]) becomes the call `M(args)` the lowering
//! places as any call of the block's own method. A program calling itself (`Prog();`) is left
//! alone (E3135, `sema::program_calls`), as are the program's variables read through its name
//! (`Prog.x`, W1413) and its properties (`property`).
//!
//! Invariants: nothing changes when the POU is no PROGRAM, or when a variable of the POU has the
//! program's name; the walk uses explicit stacks (a long line's chain of operators nests deep).

use super::super::ast::{Accessor, Expr, ExprKind, Place, PlaceBase, Stmt, StmtKind};
use super::method_flow::METHOD_CALL;
use super::PouLowering;
use crate::ast::PouKind;
use std::borrow::Cow;

impl PouLowering<'_> {
    /// `stmts` with the program's own name dropped before its actions and methods (see the module
    /// documentation); borrowed unchanged when nothing names one so.
    /// Also resolves the global namespace operator's places (`.x`, [`super::global_ns`]).
    pub(super) fn own_names_dropped<'s>(&self, stmts: &'s [Stmt]) -> Cow<'s, [Stmt]> {
        let own = self.own_prefix_possible();
        let global = global_ns_seen();
        if !own && !global {
            return Cow::Borrowed(stmts);
        }
        let mut v = stmts.to_vec();
        let mut hit = false;
        walk(&mut v, &mut |p| {
            if global && super::global_ns::is_marked(p) {
                hit = true;
                super::global_ns::resolve(p, self.decls);
            }
            if own && self.is_own_member(p) {
                hit = true;
                drop_base(p);
            }
        });
        if hit {
            Cow::Owned(v)
        } else {
            Cow::Borrowed(stmts)
        }
    }

    /// [`Self::own_names_dropped`] for one expression.
    pub(super) fn own_names_dropped_expr(&self, e: &Expr) -> Option<Expr> {
        let own = self.own_prefix_possible();
        let global = global_ns_seen();
        if !own && !global {
            return None;
        }
        let mut e = e.clone();
        let mut hit = false;
        walk_expr(&mut e, &mut |p| {
            if global && super::global_ns::is_marked(p) {
                hit = true;
                super::global_ns::resolve(p, self.decls);
            }
            if own && self.is_own_member(p) {
                hit = true;
                drop_base(p);
            }
        });
        hit.then_some(e)
    }

    /// Whether the POU is a program that no variable of its own hides the name of.
    fn own_prefix_possible(&self) -> bool {
        self.kind == PouKind::Program
            && !self.vars.contains_key(&self.pou.key())
            && !(self.actions.is_empty() && self.il_actions.is_empty() && self.methods.is_empty())
    }

    /// `Prog.Act...`, `Prog.M...` or `Prog.__M_M...` where `Prog` is the program being lowered.
    fn is_own_member(&self, p: &Place) -> bool {
        let (PlaceBase::Name(n), Some(Accessor::Field(f))) = (&p.base, p.accessors.first()) else {
            return false;
        };
        if !n.is(&self.pou.name) {
            return false;
        }
        let k = f.key();
        if self.vars.contains_key(&k) {
            // a method's hidden result (`Prog.__M_M`, the parser's read of `Prog.M(2)`)
            return k.starts_with(crate::actions::METHOD_PREFIX)
                && self
                    .methods
                    .contains_key(&k[crate::actions::METHOD_PREFIX.len()..]);
        }
        self.actions.contains_key(&k)
            || self.il_actions.contains_key(&k)
            || self.methods.contains_key(&k)
    }
}

fn global_ns_seen() -> bool {
    super::GLOBAL_NS_SEEN.load(std::sync::atomic::Ordering::Relaxed)
}

/// `Prog.Act.rest` -> `Act.rest`.
fn drop_base(p: &mut Place) {
    if let Some(Accessor::Field(f)) = p.accessors.first() {
        p.base = PlaceBase::Name(f.clone());
        p.accessors.remove(0);
    }
}

/// Calls `f` on every place of `stmts` (targets, callees, reads, in nested statements too); a
/// [`METHOD_CALL`] whose place `f` leaves without accessors becomes the plain call `M(args)`.
fn walk(stmts: &mut [Stmt], f: &mut dyn FnMut(&mut Place)) {
    let mut todo: Vec<&mut Stmt> = stmts.iter_mut().collect();
    let mut exprs: Vec<&mut Expr> = Vec::new();
    let mut places: Vec<&mut Place> = Vec::new();
    while let Some(s) = todo.pop() {
        match &mut s.kind {
            StmtKind::Assign { target, value } => {
                places.push(target);
                exprs.push(value);
            }
            StmtKind::Call { callee, args } => {
                places.push(callee);
                exprs.extend(args.iter_mut().map(|a| &mut a.value));
            }
            StmtKind::If {
                branches,
                else_body,
            } => {
                for b in branches.iter_mut() {
                    exprs.push(&mut b.cond);
                    todo.extend(b.body.iter_mut());
                }
                todo.extend(else_body.iter_mut().flatten());
            }
            StmtKind::Case {
                selector,
                arms,
                else_body,
            } => {
                exprs.push(selector);
                for a in arms.iter_mut() {
                    todo.extend(a.body.iter_mut());
                }
                todo.extend(else_body.iter_mut().flatten());
            }
            StmtKind::For {
                element,
                from,
                to,
                by,
                body,
                ..
            } => {
                places.extend(element.iter_mut());
                exprs.push(from);
                exprs.push(to);
                exprs.extend(by.iter_mut());
                todo.extend(body.iter_mut());
            }
            StmtKind::While { cond, body } => {
                exprs.push(cond);
                todo.extend(body.iter_mut());
            }
            StmtKind::Repeat { body, setup, until } => {
                todo.extend(body.iter_mut());
                todo.extend(setup.iter_mut());
                exprs.push(until);
            }
            StmtKind::Named(p) => places.push(p),
            StmtKind::Exit
            | StmtKind::Continue
            | StmtKind::Return
            | StmtKind::Empty
            | StmtKind::Label(_)
            | StmtKind::Jump(_) => {}
        }
        parts(&mut exprs, &mut places, f);
    }
}

/// [`walk`] for one expression.
fn walk_expr(e: &mut Expr, f: &mut dyn FnMut(&mut Place)) {
    parts(&mut vec![e], &mut Vec::new(), f);
}

/// `f` on every place of `exprs` and `places` and of the expressions inside them.
fn parts<'a>(
    exprs: &mut Vec<&'a mut Expr>,
    places: &mut Vec<&'a mut Place>,
    f: &mut dyn FnMut(&mut Place),
) {
    loop {
        if let Some(p) = places.pop() {
            f(p);
            for a in p.accessors.iter_mut() {
                match a {
                    Accessor::Index(ix) => exprs.extend(ix.iter_mut()),
                    Accessor::Call { args, .. } => {
                        exprs.extend(args.iter_mut().map(|a| &mut a.value))
                    }
                    Accessor::Field(_) | Accessor::Deref(_) => {}
                }
            }
            continue;
        }
        let Some(e) = exprs.pop() else { break };
        method_call_in_place(e, f);
        match &mut e.kind {
            ExprKind::Place(p) => places.push(p),
            ExprKind::Unary { operand, .. } => exprs.push(operand),
            ExprKind::Binary { left, right, .. } => {
                exprs.push(left);
                exprs.push(right);
            }
            ExprKind::Call { args, .. } => exprs.extend(args.iter_mut().map(|a| &mut a.value)),
            ExprKind::Literal(_) | ExprKind::EnumValue { .. } | ExprKind::Error => {}
        }
    }
}

/// `__METHOD_CALL(Prog.M, args)`: `f` on the place `Prog.M`; when that leaves the name `M` alone,
/// the expression becomes the call `M(args)` (the block's own method).
fn method_call_in_place(e: &mut Expr, f: &mut dyn FnMut(&mut Place)) {
    let ExprKind::Call { name, args } = &mut e.kind else {
        return;
    };
    if !name.is(METHOD_CALL) {
        return;
    }
    let Some(ExprKind::Place(p)) = args.first_mut().map(|a| &mut a.value.kind) else {
        return;
    };
    f(p);
    if !p.accessors.is_empty() {
        return;
    }
    let PlaceBase::Name(m) = &p.base else {
        return;
    };
    let m = m.clone();
    args.remove(0);
    *name = m;
}
