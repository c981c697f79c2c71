//! One span per IL instruction: IL sema and the C backend key what they know about an instruction by
//! its span, so two instructions lowered from one ST construct must not share one.
//!
//! Input: the instructions' preferred spans (the ST construct they come from) and the token boundaries
//! of the ST text (every span endpoint of its syntax tree: always UTF-8 boundaries). Output: a span per
//! instruction, unique within the POU: the preferred one when free, else the widest free sub-span of it
//! between token boundaries, else a free empty span at the nearest boundary.
//! Invariants: spans only ever start and end on boundaries the syntax tree had, so they render safely.

use super::ast::{Accessor, Arg, CaseLabel, Expr, ExprKind, Place, PlaceBase, Stmt, StmtKind};
use crate::ast::{IlStmt, InstrKind};
use crate::Span;
use std::collections::{BTreeSet, HashSet};

#[derive(Default)]
pub struct SpanAlloc {
    used: HashSet<Span>,
    bounds: BTreeSet<(u32, u32)>,
}

impl SpanAlloc {
    fn add(&mut self, s: Span) {
        self.bounds.insert((s.file.0, s.start));
        self.bounds.insert((s.file.0, s.end));
    }

    /// Marks a span as taken (an instruction not lowered here, e.g. by the SFC lowering).
    pub fn reserve(&mut self, s: Span) {
        self.used.insert(s);
    }

    /// A free span for an instruction that would like `want`.
    pub fn unique(&mut self, want: Span) -> Span {
        self.add(want);
        if self.used.insert(want) {
            return want;
        }
        let f = want.file.0;
        let pts: Vec<u32> = self
            .bounds
            .range((f, want.start)..=(f, want.end))
            .map(|p| p.1)
            .collect();
        for i in 0..pts.len() {
            for j in (i..pts.len()).rev() {
                let s = Span {
                    file: want.file,
                    start: pts[i],
                    end: pts[j],
                };
                if self.used.insert(s) {
                    return s;
                }
            }
        }
        // Every sub-span is taken: an empty span at the nearest free boundary.
        let before = self.bounds.range(..(f, want.start)).rev().map(|p| p.1);
        let after = self.bounds.range((f, want.end)..).map(|p| p.1);
        let mut cands: Vec<u32> = before
            .take(64)
            .chain(after.take(64))
            .filter(|_| true)
            .collect();
        cands.sort_by_key(|k| k.abs_diff(want.start));
        for k in cands {
            let s = Span {
                file: want.file,
                start: k,
                end: k,
            };
            if self.used.insert(s) {
                return s;
            }
        }
        want
    }

    /// Gives every instruction of `code` (nested lists too) a span of its own.
    pub fn uniquify(&mut self, code: &mut [IlStmt]) {
        for s in code {
            if let IlStmt::Instr(i) = s {
                i.span = self.unique(i.span);
                if let InstrKind::Deferred { body, .. } = &mut i.kind {
                    self.uniquify(body);
                }
            }
        }
    }

    pub fn stmts(&mut self, stmts: &[Stmt]) {
        for s in stmts {
            self.stmt(s);
        }
    }

    fn stmt(&mut self, s: &Stmt) {
        self.add(s.span);
        match &s.kind {
            StmtKind::Assign { target, value } => {
                self.place(target);
                self.expr(value);
            }
            StmtKind::Call { callee, args } => {
                self.place(callee);
                self.args(args);
            }
            StmtKind::If {
                branches,
                else_body,
            } => {
                for b in branches {
                    self.add(b.span);
                    self.expr(&b.cond);
                    self.stmts(&b.body);
                }
                if let Some(e) = else_body {
                    self.stmts(e);
                }
            }
            StmtKind::Case {
                selector,
                arms,
                else_body,
            } => {
                self.expr(selector);
                for a in arms {
                    self.add(a.span);
                    for l in &a.labels {
                        match l {
                            CaseLabel::Value(v) => self.expr(v),
                            CaseLabel::Range(a, b) => {
                                self.expr(a);
                                self.expr(b);
                            }
                        }
                    }
                    self.stmts(&a.body);
                }
                if let Some(e) = else_body {
                    self.stmts(e);
                }
            }
            StmtKind::For {
                control,
                from,
                to,
                by,
                body,
            } => {
                self.add(control.span);
                self.expr(from);
                self.expr(to);
                if let Some(b) = by {
                    self.expr(b);
                }
                self.stmts(body);
            }
            StmtKind::While { cond, body } => {
                self.expr(cond);
                self.stmts(body);
            }
            StmtKind::Repeat { body, until } => {
                self.stmts(body);
                self.expr(until);
            }
            StmtKind::Exit | StmtKind::Continue | StmtKind::Return | StmtKind::Empty => {}
        }
    }

    fn args(&mut self, args: &[Arg]) {
        for a in args {
            self.add(a.span);
            if let Some(n) = &a.name {
                self.add(n.span);
            }
            self.expr(&a.value);
        }
    }

    fn place(&mut self, p: &Place) {
        self.add(p.span);
        match &p.base {
            PlaceBase::Name(n) => self.add(n.span),
            PlaceBase::Address(a) => self.add(a.span),
        }
        for a in &p.accessors {
            match a {
                Accessor::Field(f) => self.add(f.span),
                Accessor::Index(ix) => ix.iter().for_each(|e| self.expr(e)),
            }
        }
    }

    pub fn expr(&mut self, e: &Expr) {
        self.add(e.span);
        match &e.kind {
            ExprKind::Place(p) => self.place(p),
            ExprKind::Unary { operand, .. } => self.expr(operand),
            ExprKind::Binary { left, right, .. } => {
                self.expr(left);
                self.expr(right);
            }
            ExprKind::Call { name, args } => {
                self.add(name.span);
                self.args(args);
            }
            ExprKind::Literal(_) | ExprKind::EnumValue { .. } | ExprKind::Error => {}
        }
    }
}
