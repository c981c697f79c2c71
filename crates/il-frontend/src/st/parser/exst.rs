//! ExST's assignment as an expression inside conditions (CODESYS and TwinCAT: "assignment as an
//! expression", its value is the value assigned): `ELSIF b := (i = 1) THEN`, `ELSIF (x := F()) > 0
//! THEN`, `UNTIL (n := n + 1) >= 10`, `WHILE (c := c - 1) > 0 DO`, `IF (x := F()) > 0 THEN`.
//!
//! Input: the parser at a condition. Output: the condition, reading the assigned variable where the
//! assignment stood, and the assignments (the "setup") that must run right before each evaluation of
//! the condition. Where they go:
//! - in a statement's own expressions (IF's first condition, CASE selector, FOR bounds, the
//!   right-hand side of an assignment, call arguments): before the statement, as the method calls of
//!   [`super::Parser::method_call_expr`] are (the statement evaluates them once);
//! - an ELSIF condition: `IF a THEN .. ELSIF (x := F()) > 0 THEN .. END_IF` is read as `IF a THEN ..
//!   ELSE x := F(); IF x > 0 THEN .. END_IF END_IF`, so the assignment runs exactly when the
//!   conditions before are FALSE, as IEC 61131-3 evaluates an ELSIF condition (7.3.3.3.2);
//! - an UNTIL condition: [`StmtKind::Repeat::setup`], run before each test of the condition, after
//!   the body and also after a CONTINUE (which goes to the test);
//! - a WHILE condition: `WHILE TRUE DO setup; IF NOT cond THEN EXIT; END_IF; body END_WHILE` (a
//!   CONTINUE goes back to the test, so the assignment runs again).
//!
//! Invariants: each assignment runs exactly once per evaluation of its condition; it runs before the
//! rest of the condition is read (the operands left of it that read the same variable see the new
//! value: write the assignment first); an assignment in the right operand of AND_THEN / OR_ELSE
//! (which runs only sometimes) or in an SFC transition condition (no statement to run it in) is
//! E1052, once, at the assignment.

use super::super::ast::*;
use super::Parser;
use crate::ast::{Literal, LiteralKind};
use crate::Span;
use diagnostics::{code, Diagnostic};

impl Parser<'_, '_> {
    /// The `)` of the parenthesis opened at `here`; E0100 when something else stands there.
    pub(super) fn close_paren(&mut self, here: Span) {
        if self.at(&super::Tok::RParen) {
            self.bump();
        } else {
            let found = self.describe_current();
            self.push_error(
                Diagnostic::error(code::E0100, format!("expected `)`, found {found}"))
                    .at(self.cur_span())
                    .with_label(here, "this `(` is not closed")
                    .with_hint("close the parenthesis"),
            );
        }
    }

    /// `(place := value)` after its `(` (`here`): the assignment goes into the hoisted statements,
    /// the expression reads `place`.
    pub(super) fn paren_assignment(&mut self, here: Span) -> Expr {
        let Some(target) = self.place() else {
            return self.error_expr(here);
        };
        self.bump(); // `:=` (checked by `at_condition_assignment`)
        let value = self.expr();
        self.close_paren(here);
        let span = here.to(self.span(self.prev_end(), self.prev_end()));
        if self.short_operand > 0 || self.no_assign {
            let what = if self.no_assign {
                "a transition condition"
            } else {
                "the right operand of AND_THEN or OR_ELSE"
            };
            self.push_error(
                Diagnostic::error(
                    code::E1052,
                    format!("an assignment in {what} is not supported"),
                )
                .at(target.span.to(value.span))
                .with_primary_label("ExST assignment as an expression")
                .with_hint(if self.no_assign {
                    "assign the variable in an action or the step's code and test it in the transition"
                } else {
                    "assign the variable in a statement before, or nest IFs instead of AND_THEN/OR_ELSE"
                }),
            );
            return self.error_expr(span);
        }
        let read = Expr {
            span,
            kind: ExprKind::Place(target.clone()),
        };
        self.hoisted.push(Stmt {
            span: target.span.to(value.span),
            kind: StmtKind::Assign { target, value },
        });
        read
    }

    /// A condition that may begin with an ExST assignment `b := e` (IF, WHILE, ELSIF, UNTIL): the
    /// assignment is hoisted to run before the test ([`Parser::hoisted`]), and the condition reads
    /// `b`; otherwise the expression itself.
    pub(super) fn assigned_condition(&mut self) -> Expr {
        match self.condition_assignment() {
            Some((target, value)) => {
                let read = Expr {
                    span: target.span,
                    kind: ExprKind::Place(target.clone()),
                };
                self.hoisted.push(Stmt {
                    span: target.span.to(value.span),
                    kind: StmtKind::Assign { target, value },
                });
                read
            }
            None => self.expr(),
        }
    }

    /// A condition evaluated only sometimes or again and again (ELSIF, UNTIL, WHILE): the
    /// condition and the assignments to run before each evaluation of it (`b := e` at its start,
    /// `(x := e)` inside). A method call there stays E0108 ([`Parser::method_call_expr`]).
    pub(super) fn late_condition(&mut self) -> (Expr, Vec<Stmt>) {
        let outer = std::mem::take(&mut self.hoisted);
        self.no_hoist += 1;
        let cond = self.assigned_condition();
        self.no_hoist -= 1;
        let setup = std::mem::replace(&mut self.hoisted, outer);
        (cond, setup)
    }
}

/// The branches of an IF (each with the setup of its condition; the first's is empty, it runs
/// before the IF) and its ELSE: from the first ELSIF whose condition has a setup on, the branches
/// become an IF nested in the ELSE, after the setup.
pub(super) fn nest_elsif(
    mut branches: Vec<(CondBranch, Vec<Stmt>)>,
    else_body: Option<Vec<Stmt>>,
) -> (Vec<CondBranch>, Option<Vec<Stmt>>) {
    let Some(k) = branches
        .iter()
        .skip(1)
        .position(|(_, setup)| !setup.is_empty())
        .map(|k| k + 1)
    else {
        return (branches.into_iter().map(|(b, _)| b).collect(), else_body);
    };
    let mut tail = branches.split_off(k);
    let setup = std::mem::take(&mut tail[0].1);
    let start = tail[0].0.span;
    let (inner, inner_else) = nest_elsif(tail, else_body);
    let end = inner_else
        .as_ref()
        .and_then(|e| e.last())
        .map_or(inner[inner.len() - 1].span, |s| s.span);
    let mut outer_else = setup;
    outer_else.push(Stmt {
        span: start.to(end),
        kind: StmtKind::If {
            branches: inner,
            else_body: inner_else,
        },
    });
    (
        branches.into_iter().map(|(b, _)| b).collect(),
        Some(outer_else),
    )
}

/// `WHILE cond DO body END_WHILE` whose condition has a `setup`: `WHILE TRUE DO setup; IF NOT cond
/// THEN EXIT; END_IF; body END_WHILE`.
pub(super) fn while_with_setup(cond: Expr, setup: Vec<Stmt>, mut body: Vec<Stmt>) -> StmtKind {
    let span = setup.first().map_or(cond.span, |s| s.span).to(cond.span);
    let exit = Stmt {
        span,
        kind: StmtKind::If {
            branches: vec![CondBranch {
                cond: Expr {
                    span: cond.span,
                    kind: ExprKind::Unary {
                        op: UnaryOp::Not,
                        operand: Box::new(cond.clone()),
                    },
                },
                body: vec![Stmt {
                    span,
                    kind: StmtKind::Exit,
                }],
                span,
            }],
            else_body: None,
        },
    };
    let n = setup.len();
    body.splice(0..0, setup.into_iter().chain([exit]));
    debug_assert!(body.len() > n);
    let always = Expr {
        span: cond.span,
        kind: ExprKind::Literal(Literal {
            kind: LiteralKind::Bool(true),
            type_prefix: None,
            span: cond.span,
        }),
    };
    StmtKind::While { cond: always, body }
}
