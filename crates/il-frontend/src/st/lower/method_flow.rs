//! Method calls inside expressions: `x := M(a) + 1;` (the block's own method), `IF p.Check(v)
//! THEN` (an instance's method, hoisted by the parser), and the places where a call cannot simply
//! run before its statement: an ELSIF, WHILE or UNTIL condition, the right operand of AND_THEN /
//! OR_ELSE, and a second call of the same method in one statement (stefanbesler/struckig writes all
//! of them).
//!
//! Input: one ST statement about to be lowered. Output: call statements to run first, and the
//! statement reading temporaries that hold the results; or the statement rewritten so that every
//! call stands where it can run first:
//! - `IF a THEN .. ELSIF M() THEN .. END_IF` -> `IF a THEN .. ELSE IF M() THEN .. END_IF END_IF`;
//! - `WHILE c(M()) DO body END_WHILE` -> `WHILE TRUE DO IF NOT c THEN EXIT; END_IF; body END_WHILE`;
//! - `REPEAT body UNTIL c(M()) END_REPEAT` -> `REPEAT body UNTIL t END_REPEAT` with `t := c` in
//!   the loop's setup, which runs before each test, also after a CONTINUE of the body (before
//!   issue #13's round on call chains a CONTINUE there was E0108);
//! - `a AND_THEN M()` -> `t := a; IF t THEN t := M(); END_IF` before the statement, which reads `t`
//!   (`OR_ELSE`: `IF NOT t`).
//!
//! Invariants: each call runs exactly once where the source evaluates it, in source order among
//! the method calls of the statement, and never when a short-circuit operator or an earlier branch
//! decides first; each call's result is copied into a temporary of its own right after the call,
//! so two calls of one method in one statement each give their own result (an interface's method,
//! whose result type is not known here, is read in place).

use super::super::ast::{
    Accessor, Arg, BinaryOp, CondBranch, Expr, ExprKind, Place, PlaceBase, Stmt, StmtKind, UnaryOp,
};
use super::super::infer::named;
use super::{place_exprs, PouLowering};
use crate::ast::{Ident, LiteralKind, PouKind, TypeRef};
use crate::Span;
use diagnostics::{code, Diagnostic, Diagnostics};

/// The name of the function call the parser writes for an instance's method call it cannot run
/// before its statement (`inst.M(a)` in an ELSIF condition, after AND_THEN, or a second call of
/// `inst.M` in one statement): its first argument is the place `inst.M`, the others are the call's.
/// Two leading underscores: no IEC identifier can be it.
pub const METHOD_CALL: &str = "__METHOD_CALL";

/// The expression of an instance's method call the parser leaves in place (see [`METHOD_CALL`]).
pub fn method_call_expr(callee: Place, args: Vec<Arg>, span: Span) -> Expr {
    let mut all = vec![Arg {
        name: None,
        dir: super::super::ast::ArgDir::Input,
        span: callee.span,
        value: Expr {
            span: callee.span,
            kind: ExprKind::Place(callee),
        },
    }];
    all.extend(args);
    Expr {
        kind: ExprKind::Call {
            name: Ident::new(METHOD_CALL, span),
            args: all,
        },
        span,
    }
}

fn place_expr(p: Place) -> Expr {
    Expr {
        span: p.span,
        kind: ExprKind::Place(p),
    }
}

fn name_place(n: Ident) -> Place {
    Place {
        span: n.span,
        base: PlaceBase::Name(n),
        accessors: Vec::new(),
    }
}

fn assign(target: Place, value: Expr, span: Span) -> Stmt {
    Stmt {
        kind: StmtKind::Assign { target, value },
        span,
    }
}

fn bool_lit(v: bool, span: Span) -> Expr {
    Expr::literal(LiteralKind::Bool(v), span)
}

/// The text key of a place made of names, fields and dereferences (`Svc^.PtrMgr^.Start`),
/// upper-case; the same as [`field_key`] for a place without `^`.
pub(super) fn deref_key(p: &Place) -> Option<String> {
    let PlaceBase::Name(n) = &p.base else {
        return None;
    };
    let mut k = n.key();
    for a in &p.accessors {
        match a {
            Accessor::Field(f) => {
                k.push('.');
                k.push_str(&f.key());
            }
            Accessor::Deref(_) => k.push('^'),
            _ => return None,
        }
    }
    Some(k)
}

/// The text key of a place made of names and fields only (`Roots.PolyEval`), upper-case.
pub(super) fn field_key(p: &Place) -> Option<String> {
    let PlaceBase::Name(n) = &p.base else {
        return None;
    };
    let mut k = n.key();
    for a in &p.accessors {
        let Accessor::Field(f) = a else {
            return None;
        };
        k.push('.');
        k.push_str(&f.key());
    }
    Some(k)
}

impl PouLowering<'_> {
    /// Whether `n` names one of the block's methods (and no variable).
    pub(super) fn is_method(&self, n: &Ident) -> bool {
        self.methods.contains_key(&n.key()) && !self.callable_var(n)
    }

    /// Whether `n` is a variable that a call could name: one that is no data, a function block
    /// instance. A method's local variable named like one of the block's methods (`Hash : DWORD`
    /// beside `THIS^.Hash(Key)`, fisothemes/TwinCat-Dynamic-Collections) cannot be called, so a
    /// call of that name is the method's (before: E3103).
    pub(super) fn callable_var(&self, n: &Ident) -> bool {
        let Some(ty) = self.vars.get(&n.key()) else {
            return false;
        };
        let env = self.env();
        match env.resolve(ty) {
            TypeRef::Named(t) => env.decls.pou(&t.name).is_some(),
            _ => false,
        }
    }

    /// Whether a call `n(...)` names the project's FUNCTION `n` although a global variable has
    /// the name too: a global of a `{attribute 'qualified_only'}` list (TwinCAT, CODESYS: its
    /// variables are named `GVL.x` only, so `StartUp()` beside `GVL.startUp` is the function;
    /// before: E3103 / E2005). A variable of the POU's own, or a global block instance, keeps
    /// the name.
    pub(super) fn function_beside_global(&self, n: &Ident) -> bool {
        if self.vars.contains_key(&n.key()) {
            return false;
        }
        let env = self.env();
        env.decls
            .pou(&n.name)
            .is_some_and(|p| p.kind == PouKind::Function)
            && env.var_type(n).is_some_and(|t| !env.is_fb_type(&t))
    }

    /// The span of the first method call inside `e` (an own method's, or [`METHOD_CALL`]), left
    /// to right. Without recursion: it looks at every statement's expressions, and a line's chain
    /// of 1,000 operators (the parser's cap, E0109) must not overflow the stack.
    pub(super) fn first_method_call(&self, e: &Expr) -> Option<Span> {
        let mut todo = vec![e];
        while let Some(e) = todo.pop() {
            match &e.kind {
                ExprKind::Unary { operand, .. } => todo.push(operand),
                ExprKind::Binary { left, right, .. } => {
                    todo.push(right);
                    todo.push(left);
                }
                ExprKind::Call { name, args } => {
                    if self.is_method(name) || name.is(METHOD_CALL) {
                        return Some(e.span);
                    }
                    todo.extend(args.iter().rev().map(|a| &a.value));
                }
                ExprKind::Place(p) => {
                    if super::call_chain::is_chain(p) {
                        return Some(p.span);
                    }
                    for a in p.accessors.iter().rev() {
                        if let Accessor::Index(ix) = a {
                            todo.extend(ix.iter().rev());
                        }
                    }
                }
                _ => {}
            }
        }
        None
    }

    /// The method calls inside the expressions `s` evaluates, as call statements to run first,
    /// and `s` reading their results; or `s` rewritten so that they can (see the module
    /// documentation). `None` when `s` holds no method call.
    pub(super) fn hoist_method_calls(
        &mut self,
        s: &Stmt,
        diags: &mut Diagnostics,
    ) -> Option<(Vec<Stmt>, Stmt)> {
        let has = |e: &Expr| self.first_method_call(e).is_some();
        let place_has = |p: &Place| {
            super::call_chain::is_chain(p)
                || p.accessors
                    .iter()
                    .any(|a| matches!(a, Accessor::Index(ix) if ix.iter().any(has)))
        };
        let any = match &s.kind {
            StmtKind::Assign { target, value } => place_has(target) || has(value),
            StmtKind::Call { callee, args } => {
                place_has(callee) || args.iter().any(|a| has(&a.value))
            }
            StmtKind::If { branches, .. } => branches.iter().any(|b| has(&b.cond)),
            StmtKind::Case { selector, .. } => has(selector),
            StmtKind::For { from, to, by, .. } => {
                has(from) || has(to) || by.as_ref().is_some_and(has)
            }
            StmtKind::While { cond, .. } => has(cond),
            StmtKind::Repeat { until, .. } => has(until),
            _ => false,
        };
        if !any {
            return None;
        }
        if let Some(rewritten) = self.calls_made_eager(s) {
            return Some((Vec::new(), rewritten));
        }
        let mut calls = Vec::new();
        let mut rest = s.clone();
        self.keep_earlier_results(&mut rest, &mut calls);
        // `cell.Units[2].Cmd.Move(1, 2).Go();` with `cell` declared nowhere: read as `cell :=
        // cell;`, so that sema reports the undeclared name once (E1001), not a call of it
        if let StmtKind::Call { callee, .. } = &rest.kind {
            if let Some(n) = super::call_chain::is_chain(callee)
                .then(|| self.undeclared_root(callee))
                .flatten()
            {
                let root = Place {
                    span: n.span,
                    base: PlaceBase::Name(n),
                    accessors: Vec::new(),
                };
                rest.kind = StmtKind::Assign {
                    value: Expr {
                        span: root.span,
                        kind: ExprKind::Place(root.clone()),
                    },
                    target: root,
                };
                return Some((calls, rest));
            }
        }
        // a chain in the place written or called: its calls first (`list.Item(2).Value := 5;`)
        if let StmtKind::Assign { target: p, .. } | StmtKind::Call { callee: p, .. } =
            &mut rest.kind
        {
            if super::call_chain::is_chain(p) && !self.unchain(p, &mut calls, diags) {
                let span = rest.span;
                return Some((
                    calls,
                    Stmt {
                        kind: StmtKind::Empty,
                        span,
                    },
                ));
            }
        }
        let mut eager: Vec<&mut Expr> = Vec::new();
        match &mut rest.kind {
            StmtKind::Assign { target, value } => {
                place_exprs(target, &mut eager);
                eager.push(value);
            }
            StmtKind::Call { callee, args } => {
                place_exprs(callee, &mut eager);
                eager.extend(args.iter_mut().map(|a| &mut a.value));
            }
            StmtKind::If { branches, .. } => eager.push(&mut branches[0].cond),
            StmtKind::Case { selector, .. } => eager.push(selector),
            StmtKind::For { from, to, by, .. } => {
                eager.push(from);
                eager.push(to);
                eager.extend(by.as_mut());
            }
            _ => {}
        }
        for e in eager {
            self.hoist_in(e, &mut calls, diags);
        }
        Some((calls, rest))
    }

    /// `s` rewritten when a method call stands in a condition evaluated later than the statement
    /// starts (ELSIF, WHILE, UNTIL); `None` when none does.
    fn calls_made_eager(&mut self, s: &Stmt) -> Option<Stmt> {
        let span = s.span;
        match &s.kind {
            StmtKind::If {
                branches,
                else_body,
            } => {
                let k = branches
                    .iter()
                    .skip(1)
                    .position(|b| self.first_method_call(&b.cond).is_some())?
                    + 1;
                // `ELSIF c THEN` as `ELSE IF c THEN`: c is evaluated where the ELSIF would be
                let inner = Stmt {
                    kind: StmtKind::If {
                        branches: branches[k..].to_vec(),
                        else_body: else_body.clone(),
                    },
                    span: branches[k].span,
                };
                Some(Stmt {
                    kind: StmtKind::If {
                        branches: branches[..k].to_vec(),
                        else_body: Some(vec![inner]),
                    },
                    span,
                })
            }
            StmtKind::While { cond, body } => {
                self.first_method_call(cond)?;
                let c = cond.span;
                let test = Stmt {
                    kind: StmtKind::If {
                        branches: vec![CondBranch {
                            cond: Expr {
                                kind: ExprKind::Unary {
                                    op: UnaryOp::Not,
                                    operand: Box::new(cond.clone()),
                                },
                                span: c,
                            },
                            body: vec![Stmt {
                                kind: StmtKind::Exit,
                                span: c,
                            }],
                            span: c,
                        }],
                        else_body: None,
                    },
                    span: c,
                };
                let mut inner = vec![test];
                inner.extend(body.iter().cloned());
                Some(Stmt {
                    kind: StmtKind::While {
                        cond: bool_lit(true, c),
                        body: inner,
                    },
                    span,
                })
            }
            StmtKind::Repeat { body, until, setup } => {
                self.first_method_call(until)?;
                // the test computed into a temporary by the loop's setup, which runs before each
                // test, also after a CONTINUE: IEC 61131-3 ed. 3 (7.3.3.4.10) and CODESYS's
                // CONTINUE go on with the next iteration, whose REPEAT test comes first
                let c = until.span;
                let t = self.temp(named("BOOL", c), c);
                let mut setup = setup.clone();
                setup.push(assign(name_place(t.clone()), until.clone(), c));
                Some(Stmt {
                    kind: StmtKind::Repeat {
                        body: body.clone(),
                        setup,
                        until: place_expr(name_place(t)),
                    },
                    span,
                })
            }
            _ => None,
        }
    }

    /// A statement that reads an instance's method result `inst.__M_M` (its call hoisted by the
    /// parser) and calls `inst.M` again later ([`METHOD_CALL`]): the result read is copied into a
    /// temporary first, before the second call overwrites it.
    fn keep_earlier_results(&mut self, s: &mut Stmt, calls: &mut Vec<Stmt>) {
        let mut again = Vec::new();
        walk_stmt_exprs(s, &mut |e| collect_method_callees(e, &mut again));
        // (a program's own method named through the program, `Prog.M(1) + Prog.M(2)`: the
        // parser hoisted the first call and reads `__M_M`, the second is `M(2)`, see own_name)
        if self.kind == PouKind::Program {
            walk_stmt_exprs(s, &mut |e| {
                each_expr(e, &mut |x| {
                    if let ExprKind::Call { name, .. } = &x.kind {
                        if self.is_method(name) && !again.contains(&name.key()) {
                            again.push(name.key());
                        }
                    }
                })
            });
        }
        for key in again {
            let result_key = match key.rsplit_once('.') {
                Some((prefix, method)) => format!(
                    "{prefix}.{}",
                    crate::actions::method_result(method).to_ascii_uppercase()
                ),
                None => crate::actions::method_result(&key),
            };
            let mut found: Option<Place> = None;
            walk_stmt_exprs(s, &mut |e| find_place(e, &result_key, &mut found));
            let Some(read) = found else {
                continue;
            };
            let Some(ty) = self.env().place_type(&read) else {
                continue;
            };
            let t = self.temp(ty, read.span);
            calls.push(assign(
                name_place(t.clone()),
                place_expr(read.clone()),
                read.span,
            ));
            walk_stmt_exprs(s, &mut |e| {
                replace_place(e, &result_key, &t);
            });
        }
    }

    /// Replaces the method calls inside `e` (arguments first) by temporaries holding their
    /// results, the calls and copies appended to `calls` in evaluation order.
    pub(super) fn hoist_in(
        &mut self,
        e: &mut Expr,
        calls: &mut Vec<Stmt>,
        diags: &mut Diagnostics,
    ) {
        let span = e.span;
        match &mut e.kind {
            ExprKind::Unary { operand, .. } => self.hoist_in(operand, calls, diags),
            ExprKind::Binary {
                op: op @ (BinaryOp::AndThen | BinaryOp::OrElse),
                left,
                right,
            } => {
                let and_then = *op == BinaryOp::AndThen;
                self.hoist_in(left, calls, diags);
                if self.first_method_call(right).is_none() {
                    return;
                }
                // the right operand runs only when the left does not decide: behind an IF
                let t = self.temp(named("BOOL", span), span);
                calls.push(assign(name_place(t.clone()), (**left).clone(), left.span));
                let test = place_expr(name_place(t.clone()));
                let cond = if and_then {
                    test
                } else {
                    Expr {
                        kind: ExprKind::Unary {
                            op: UnaryOp::Not,
                            operand: Box::new(test),
                        },
                        span,
                    }
                };
                calls.push(Stmt {
                    kind: StmtKind::If {
                        branches: vec![CondBranch {
                            cond,
                            body: vec![assign(
                                name_place(t.clone()),
                                (**right).clone(),
                                right.span,
                            )],
                            span,
                        }],
                        else_body: None,
                    },
                    span,
                });
                e.kind = ExprKind::Place(name_place(t));
            }
            ExprKind::Binary { left, right, .. } => {
                self.hoist_in(left, calls, diags);
                self.hoist_in(right, calls, diags);
            }
            ExprKind::Call { name, args } => {
                let instance_call = name.is(METHOD_CALL);
                if instance_call {
                    // `stack.Get(1).Pop()`: the calls before the last one first
                    if let Some(ExprKind::Place(p)) = args.first_mut().map(|a| &mut a.value.kind) {
                        if super::call_chain::is_chain(p) && !self.unchain(p, calls, diags) {
                            e.kind = ExprKind::Error;
                            return;
                        }
                    }
                }
                let skip = usize::from(instance_call);
                for a in args.iter_mut().skip(skip) {
                    self.hoist_in(&mut a.value, calls, diags);
                }
                let (callee, result, args) = if instance_call {
                    let mut args = std::mem::take(args);
                    let first = args.remove(0);
                    let ExprKind::Place(callee) = &first.value.kind else {
                        e.kind = ExprKind::Error;
                        return;
                    };
                    let mut result = callee.clone();
                    if let Some(Accessor::Field(m)) = result.accessors.last_mut() {
                        *m = Ident::new(crate::actions::method_result(&m.name), m.span);
                    }
                    (callee.clone(), result, args)
                } else {
                    if !self.is_method(name) {
                        return;
                    }
                    let sig = self.methods[&name.key()].clone();
                    // (a call of a dropped overload, `sig.overloaded`: its E1084 is the one error)
                    if !sig.returns && sig.overloaded {
                        e.kind = ExprKind::Error;
                        return;
                    }
                    if !sig.returns {
                        diags.push(
                            Diagnostic::error(
                                code::E1011,
                                format!("method `{}` returns no value", name.name),
                            )
                            .at(span)
                            .with_hint("call it as a statement, or give the method a result type (`METHOD M : INT`) and assign it"),
                        );
                        e.kind = ExprKind::Error;
                        return;
                    }
                    let result = name_place(Ident::new(
                        crate::actions::method_result(&sig.name),
                        name.span,
                    ));
                    (name_place(name.clone()), result, std::mem::take(args))
                };
                calls.push(Stmt {
                    kind: StmtKind::Call { callee, args },
                    span,
                });
                // the result is copied at once: a later call of the method overwrites it (an
                // interface's method, whose result type the lowering does not see, is read in place)
                match self.env().place_type(&result) {
                    Some(ty) => {
                        let t = self.temp(ty, span);
                        calls.push(assign(name_place(t.clone()), place_expr(result), span));
                        e.kind = ExprKind::Place(name_place(t));
                    }
                    None => e.kind = ExprKind::Place(result),
                }
            }
            ExprKind::Place(p) => {
                if super::call_chain::is_chain(p) && !self.unchain(p, calls, diags) {
                    e.kind = ExprKind::Error;
                    return;
                }
                let mut inner = Vec::new();
                place_exprs(p, &mut inner);
                for x in inner {
                    self.hoist_in(x, calls, diags);
                }
            }
            _ => {}
        }
    }
}

/// Calls `f` on each expression `s` evaluates before its body (the ones [`PouLowering::hoist_method_calls`]
/// hoists from).
pub(super) fn walk_stmt_exprs(s: &mut Stmt, f: &mut dyn FnMut(&mut Expr)) {
    match &mut s.kind {
        StmtKind::Assign { target, value } => {
            let mut v = Vec::new();
            place_exprs(target, &mut v);
            v.into_iter().for_each(&mut *f);
            f(value);
        }
        StmtKind::Call { args, .. } => args.iter_mut().for_each(|a| f(&mut a.value)),
        StmtKind::If { branches, .. } => f(&mut branches[0].cond),
        StmtKind::Case { selector, .. } => f(selector),
        StmtKind::For { from, to, by, .. } => {
            f(from);
            f(to);
            if let Some(b) = by {
                f(b);
            }
        }
        _ => {}
    }
}

/// Every sub-expression of `e`, `e` first.
fn each_expr(e: &mut Expr, f: &mut dyn FnMut(&mut Expr)) {
    f(e);
    match &mut e.kind {
        ExprKind::Unary { operand, .. } => each_expr(operand, f),
        ExprKind::Binary { left, right, .. } => {
            each_expr(left, f);
            each_expr(right, f);
        }
        ExprKind::Call { args, .. } => args.iter_mut().for_each(|a| each_expr(&mut a.value, f)),
        ExprKind::Place(p) => {
            let mut v = Vec::new();
            place_exprs(p, &mut v);
            for x in v {
                each_expr(x, f);
            }
        }
        _ => {}
    }
}

fn collect_method_callees(e: &mut Expr, out: &mut Vec<String>) {
    each_expr(e, &mut |x| {
        if let ExprKind::Call { name, args } = &x.kind {
            if name.is(METHOD_CALL) {
                if let Some(ExprKind::Place(p)) = args.first().map(|a| &a.value.kind) {
                    if let Some(k) = field_key(p) {
                        if !out.contains(&k) {
                            out.push(k);
                        }
                    }
                }
            }
        }
    });
}

fn find_place(e: &mut Expr, key: &str, found: &mut Option<Place>) {
    each_expr(e, &mut |x| {
        if let ExprKind::Place(p) = &x.kind {
            if found.is_none() && field_key(p).as_deref() == Some(key) {
                *found = Some(p.clone());
            }
        }
    });
}

/// Replaces each read of the place `key` in `e` by `t`; whether there was one.
pub(super) fn replace_place(e: &mut Expr, key: &str, t: &Ident) -> bool {
    let mut hit = false;
    each_expr(e, &mut |x| {
        if let ExprKind::Place(p) = &x.kind {
            if deref_key(p).as_deref() == Some(key) {
                x.kind = ExprKind::Place(name_place(Ident::new(t.name.clone(), p.span)));
                hit = true;
            }
        }
    });
    hit
}
