//! Call chains (CODESYS, TwinCAT): a method's result used at once, as the libraries write it:
//! `x := stack.Get(i).Pop();`, `list.Item(2).Value := 5;`, `n := node.Next()^.Value;`,
//! `Get(1).Value` inside the block itself.
//!
//! Input: a place holding an [`Accessor::Call`] (the parser puts one where `(args)` after a name
//! is followed by `.`, `^` or `[`). Output: the calls, as statements to run before the statement
//! that holds the place, and the place rewritten onto temporaries that hold the results:
//! `stack.Get(i).Pop` -> `stack.Get(i); T1 REF= stack.__M_GET;` and `T1.Pop`.
//!
//! Invariants: each call of the chain runs exactly once, left to right, its arguments (and the
//! indexes before it) evaluated just before it; a `REFERENCE TO` result is bound (`REF=`), never
//! copied, so a write through the chain reaches the referenced instance; a `POINTER TO`, a
//! structure or an interface result is copied into its temporary right after the call, so a second
//! call of the same method later in the statement cannot change what the chain reads. A call that
//! is no method (nor the block's own method) is one E0349 at the call, the statement dropped; when
//! the instance's type (an array's element type too) is declared nowhere, that is the error
//! instead (E1003 at its declaration).

use super::super::ast::{Accessor, Arg, Expr, ExprKind, Place, PlaceBase, Stmt, StmtKind};
use super::super::refs::REF_ASSIGN;
use super::{place_exprs, PouLowering};
use crate::ast::{Ident, RefKind, TypeRef};
use crate::Span;
use diagnostics::{code, Diagnostic, Diagnostics};

/// Whether `p` holds a call in its accessors (`a.Get(1).x`).
pub(super) fn is_chain(p: &Place) -> bool {
    p.accessors
        .iter()
        .any(|a| matches!(a, Accessor::Call { .. }))
}

fn name_place(n: Ident) -> Place {
    Place {
        span: n.span,
        base: PlaceBase::Name(n),
        accessors: Vec::new(),
    }
}

impl PouLowering<'_> {
    /// The type name of `callee`'s instance (`uut` of `uut.M`) when no declaration of the project
    /// and no standard block has it (sema reports it E1003).
    fn undeclared_block_type(&self, callee: &Place) -> Option<Ident> {
        // (`uut.M()`, and deeper: `fbAlarm.ipArguments.Clear()` with `fbAlarm` of a library's
        // block ladderc does not have; `Alarm[i].ipArguments.Clear()` with `Alarm : ARRAY[1..5]
        // OF FB_TcAlarm`: the element's type, through the indexes)
        let PlaceBase::Name(n) = &callee.base else {
            return None;
        };
        let mut ty = self.env().var_type(n)?;
        let mut rest = callee.accessors.as_slice();
        while let [Accessor::Index(ix), tail @ ..] = rest {
            match ty {
                TypeRef::Array { dims, element, .. } if dims.len() == ix.len() => ty = *element,
                _ => return None,
            }
            rest = tail;
        }
        let ([Accessor::Field(_), ..], TypeRef::Named(t)) = (rest, ty) else {
            return None;
        };
        let known = crate::sema::model::Elementary::from_name(&t.name.to_ascii_uppercase())
            .is_some()
            || self.decls.type_decl(&t.name).is_some()
            || self.decls.pou(&t.name).is_some()
            || crate::sema::model::StdFb::from_name(&t.name).is_some();
        (!known).then_some(t)
    }

    /// The name `callee` when it is a plain name that nothing declares: no POU, variable,
    /// global list, type, action, method of the block, standard function or conversion.
    fn unknown_function(&self, callee: &Place) -> Option<Ident> {
        let (PlaceBase::Name(n), []) = (&callee.base, callee.accessors.as_slice()) else {
            return None;
        };
        let key = n.key();
        let known = n.name.starts_with("__")
            || self.env().var_type(n).is_some()
            || self.decls.global_lists.contains_key(&key)
            || self.decls.pou(&n.name).is_some()
            || self.decls.types.contains_key(&key)
            || self.actions.contains_key(&key)
            || self.il_actions.contains_key(&key)
            || self.methods.contains_key(&key)
            || crate::sema::stdlib::function(&n.name).is_some()
            || crate::sema::stdlib::conversion(&n.name).is_some();
        (!known).then(|| n.clone())
    }

    /// The name `p` starts with (`cell` of `cell.Units[1].Home()`) when it names nothing: no
    /// variable, global, global list, POU, type or action (a call right after it, `Get(1).x`, is
    /// the block's own method or a function, and is left alone).
    pub(super) fn undeclared_root(&self, p: &Place) -> Option<Ident> {
        let (PlaceBase::Name(n), [Accessor::Field(_) | Accessor::Index(_), ..]) =
            (&p.base, p.accessors.as_slice())
        else {
            return None;
        };
        let key = n.key();
        let known = n.name.starts_with("__")
            || self.env().var_type(n).is_some()
            || self.decls.global_lists.contains_key(&key)
            || self.decls.pou(&n.name).is_some()
            || self.decls.types.contains_key(&key)
            || self.actions.contains_key(&key)
            || self.il_actions.contains_key(&key)
            || self.methods.contains_key(&key);
        (!known).then(|| n.clone())
    }

    /// Replaces every call inside `p` (left to right) by a temporary holding its result; the
    /// calls and the bindings go to `calls`. `false` (after one E0349) when a call is no method
    /// call or its result cannot be accessed.
    pub(super) fn unchain(
        &mut self,
        p: &mut Place,
        calls: &mut Vec<Stmt>,
        diags: &mut Diagnostics,
    ) -> bool {
        if let Some(n) = self.undeclared_root(p) {
            // `ip.Movers[1].Cmd.Home().Done` with `ip` declared nowhere: nothing is known of the
            // chain; the place is read as the name alone, so that sema reports the undeclared name
            // (E1001, once per POU at its first use) and nothing else
            *p = name_place(n);
            return true;
        }
        while let Some(k) = p
            .accessors
            .iter()
            .position(|a| matches!(a, Accessor::Call { .. }))
        {
            let rest = p.accessors.split_off(k + 1);
            let Some(Accessor::Call { mut args, span }) = p.accessors.pop() else {
                return false;
            };
            let mut callee = Place {
                base: p.base.clone(),
                accessors: std::mem::take(&mut p.accessors),
                span: Span {
                    end: span.start,
                    ..p.span
                },
            };
            // the indexes before the call and its arguments, in source order
            let mut inner = Vec::new();
            place_exprs(&mut callee, &mut inner);
            for e in inner {
                self.hoist_in(e, calls, diags);
            }
            for a in args.iter_mut() {
                self.hoist_in(&mut a.value, calls, diags);
            }
            let call_span = callee.span.to(span);
            // `a.Child.Kid()` with `PROPERTY Child`: the property's value in a temporary first
            self.property_holder(&mut callee, calls);
            let Some(result) = self.chain_result(&callee) else {
                if let Some(t) = self.undeclared_block_type(&callee) {
                    // `uut.DoSomething(...).Finish()` with `uut : SomeFunctionBlock` declared
                    // nowhere: the missing type is the cause (sema's E1003 at the declaration,
                    // once), not the chain
                    // (a library-qualified type, `Lib.T`, written `__b_T`: E1032 named the
                    // library already)
                    let here = Some(t.span);
                    if !t.name.starts_with("__")
                        && !diags
                            .iter()
                            .any(|d| d.code == code::E1003 && d.span == here)
                    {
                        diags.push(
                            Diagnostic::error(code::E1003, format!("unknown type `{}`", t.name))
                                .at(t.span)
                                .with_primary_label("no such type")
                                .with_hint("declare it in a TYPE block or as a FUNCTION_BLOCK, or use an elementary type"),
                        );
                    }
                    return false;
                }
                if let PlaceBase::Name(n) = &callee.base {
                    // `cell.A().x` with `cell` declared nowhere reads as a library's function
                    // `Lib.A` (`__ll_A`, `super::super::qualifiers`): E1032 named `cell` already
                    if n.name.starts_with("__")
                        && callee.accessors.is_empty()
                        && diags.iter().any(|d| d.code == code::E1032)
                    {
                        return false;
                    }
                }
                if let Some(n) = self.unknown_function(&callee) {
                    // `AsAxisRef(axis)^` with `AsAxisRef` declared nowhere (a vendor library's
                    // function): the missing function is the cause, named once (as sema's E1019
                    // of a plain call), not the access of its result
                    let message = format!("unknown function `{}`", n.name);
                    if !diags
                        .iter()
                        .any(|d| d.code == code::E1019 && d.message == message)
                    {
                        diags.push(
                            Diagnostic::error(code::E1019, message)
                                .at(n.span)
                                .with_primary_label("no such function")
                                .with_hint("use an IEC standard function, a conversion X_TO_Y, or declare the FUNCTION (its other calls are not reported)"),
                        );
                    }
                    return false;
                }
                diags.push(
                    Diagnostic::error(
                        code::E0349,
                        format!(
                            "`{}` is no method: its result cannot be accessed",
                            super::for_control::place_text(&callee)
                        ),
                    )
                    .at(call_span)
                    .with_primary_label("called inside an access")
                    .with_hint("only a METHOD's result can be used at once (`stack.Get(1).Value`); call anything else as a statement and read its outputs"),
                );
                return false;
            };
            let ty = self
                .declared_type(&result)
                .or_else(|| self.through_interface(&callee).flatten());
            // `a.M().x`, `a.M()[1]`, `a.M()^` where `M` returns an INT: nothing to access
            if let Some(e) = ty.as_ref().and_then(|t| self.env().elementary(t)) {
                diags.push(
                    Diagnostic::error(
                        code::E0349,
                        format!(
                            "`{}` returns {}: its result has nothing the rest of the access can reach",
                            super::for_control::place_text(&callee),
                            e.name()
                        ),
                    )
                    .at(call_span)
                    .with_primary_label("called inside an access")
                    .with_hint("use the result as a value (`x := a.M();`), or give the method a result type with fields, elements or a reference"),
                );
                return false;
            }
            calls.push(Stmt {
                kind: StmtKind::Call { callee, args },
                span: call_span,
            });
            let read = Expr {
                span: call_span,
                kind: ExprKind::Place(result.clone()),
            };
            let base = match ty {
                // bound, not copied: the rest of the chain reaches the instance itself
                Some(
                    ty @ TypeRef::Ref {
                        kind: RefKind::Reference,
                        ..
                    },
                ) => {
                    let t = self.temp(ty, call_span);
                    let bind = Expr {
                        span: call_span,
                        kind: ExprKind::Call {
                            name: Ident::new(REF_ASSIGN, call_span),
                            args: vec![Arg {
                                name: None,
                                dir: super::super::ast::ArgDir::Input,
                                span: call_span,
                                value: read,
                            }],
                        },
                    };
                    calls.push(assign(name_place(t.clone()), bind, call_span));
                    name_place(t)
                }
                // a function block returned by value is the method's own result variable
                Some(ty) if self.is_block(&ty) => result,
                Some(ty) => {
                    let t = self.temp(ty, call_span);
                    calls.push(assign(name_place(t.clone()), read, call_span));
                    name_place(t)
                }
                // through an interface: its result is read where the call left it
                None => result,
            };
            p.base = base.base;
            p.accessors = base.accessors;
            p.accessors.extend(rest);
        }
        true
    }

    /// The variable holding the result of the method `callee` names (`inst.__M_GET` for
    /// `inst.Get`, `__M_GET` for the block's own `Get`); `None` when `callee` names no method.
    fn chain_result(&self, callee: &Place) -> Option<Place> {
        let mut result = callee.clone();
        match result.accessors.last_mut() {
            Some(Accessor::Field(m)) => {
                *m = Ident::new(crate::actions::method_result(&m.name), m.span);
                // a method of the instance's block, or of the interface it holds
                let env = self.env();
                let known =
                    env.place_type(&result).is_some() || self.through_interface(callee).is_some();
                known.then_some(result)
            }
            None => {
                let PlaceBase::Name(n) = &callee.base else {
                    return None;
                };
                if !self.is_method(n) {
                    return None;
                }
                let sig = &self.methods[&n.key()];
                sig.returns.then(|| {
                    name_place(Ident::new(crate::actions::method_result(&sig.name), n.span))
                })
            }
            _ => None,
        }
    }

    /// When the block `callee` (`a.Child.Kid`) calls a method of is a PROPERTY's value
    /// (`a.Child`, or what a POINTER TO property points to, `a.PtrChild^.Kid`), that value goes
    /// into a temporary first (`T REF= a.Child;` for a `REFERENCE
    /// TO`, `T := a.Child;` otherwise; the property's getter runs there) and `callee` becomes
    /// `T.Kid`.
    pub(super) fn property_holder(&mut self, callee: &mut Place, calls: &mut Vec<Stmt>) {
        if self.own_property_holder(callee, calls) {
            return;
        }
        let n = callee.accessors.len();
        if n < 2 {
            return;
        }
        // `a.Child.Kid`, or `a.PtrChild^.Kid` with `PROPERTY PtrChild : POINTER TO ...` (TwinCAT:
        // `m_ptrServices^.PtrProcessManager^.RequestAbort()`): `at` is the property's accessor
        let at = match &callee.accessors[n - 2] {
            Accessor::Deref(_) if n >= 3 => n - 3,
            _ => n - 2,
        };
        let Accessor::Field(prop) = &callee.accessors[at] else {
            return;
        };
        let prefix = Place {
            base: callee.base.clone(),
            accessors: callee.accessors[..at].to_vec(),
            span: callee.span,
        };
        let env = self.env();
        let Some(holder_type) = env.place_type(&prefix) else {
            return;
        };
        if env.member(&holder_type, prop).is_some() {
            return; // a variable, no property
        }
        let result = Ident::new(
            crate::actions::method_result(&super::super::property::getter(&prop.name)),
            prop.span,
        );
        // (an interface's property returning an interface: no field of the interface's hidden
        // structure, its type is the accessor's: `ifut.executor.Run()`)
        let Some(ty) = env.member(&holder_type, &result).or_else(|| {
            super::super::interface_vars::interface_result_type(
                &env,
                &holder_type,
                &super::super::property::getter(&prop.name),
            )
        }) else {
            return;
        };
        if at + 3 == n && !matches!(env.resolve(&ty), TypeRef::Ref { .. }) {
            return; // `P^.Kid` of a property that is no pointer
        }
        let holder = Place {
            base: callee.base.clone(),
            accessors: callee.accessors[..=at].to_vec(),
            span: callee.span,
        };
        let span = holder.span;
        let read = Expr {
            span,
            kind: ExprKind::Place(holder),
        };
        let value = if matches!(
            ty,
            TypeRef::Ref {
                kind: RefKind::Reference,
                ..
            }
        ) {
            Expr {
                span,
                kind: ExprKind::Call {
                    name: Ident::new(REF_ASSIGN, span),
                    args: vec![Arg {
                        name: None,
                        dir: super::super::ast::ArgDir::Input,
                        span,
                        value: read,
                    }],
                },
            }
        } else {
            read
        };
        let t = self.temp(ty, span);
        calls.push(assign(name_place(t.clone()), value, span));
        let rest = callee.accessors[at + 1..].to_vec();
        callee.base = PlaceBase::Name(t);
        callee.accessors = rest;
    }

    /// `P_Log.M_Add('x')` (or `P^.Kid`) inside the block that declares or inherits the PROPERTY
    /// `P_Log`, where no variable has that name: as `inst.P_Log.M_Add` from outside
    /// ([`Self::property_holder`]), the property's value into a temporary first (its getter runs
    /// there) and `callee` becomes `T.M_Add`. Beckhoff infosys "Property"
    /// (infosys.beckhoff.com/content/1033/tc3_plc_intro/2530307467.html): inside the block a
    /// property is named without a prefix, as `THIS^.P_Log` is. Whether it did so.
    fn own_property_holder(&mut self, callee: &mut Place, calls: &mut Vec<Stmt>) -> bool {
        let PlaceBase::Name(prop) = &callee.base else {
            return false;
        };
        let get = super::super::property::getter(&prop.name);
        let deref = matches!(callee.accessors.first(), Some(Accessor::Deref(_)));
        if callee.accessors.len() <= usize::from(deref)
            || !self.methods.contains_key(&get)
            || self.env().vars.contains_key(&prop.key())
        {
            return false;
        }
        let result = Ident::new(crate::actions::method_result(&get), prop.span);
        let Some(ty) = self.env().var_type(&result) else {
            return false;
        };
        let env = self.env();
        let resolved = env.resolve(&ty);
        let through = match resolved {
            TypeRef::Ref { .. } => true,
            // a block instance or an interface reference: its method is called on it
            TypeRef::Named(_) => !deref,
            _ => false,
        };
        if !through {
            return false;
        }
        let span = prop.span;
        let holder = name_place(prop.clone());
        let read = Expr {
            span,
            kind: ExprKind::Place(holder),
        };
        let value = if matches!(
            ty,
            TypeRef::Ref {
                kind: RefKind::Reference,
                ..
            }
        ) {
            Expr {
                span,
                kind: ExprKind::Call {
                    name: Ident::new(REF_ASSIGN, span),
                    args: vec![Arg {
                        name: None,
                        dir: super::super::ast::ArgDir::Input,
                        span,
                        value: read,
                    }],
                },
            }
        } else {
            read
        };
        let t = self.temp(ty, span);
        calls.push(assign(name_place(t.clone()), value, span));
        // (`T^.Kid` when a `^` follows the property: `T` holds the pointer)
        callee.base = PlaceBase::Name(t);
        true
    }

    /// `a.Child.Depth(args);` as the parser puts it before the statement reading its result
    /// `a.Child.__M_DEPTH`, where `Child` is a PROPERTY: the property's value into a temporary,
    /// the call on it, and its result copied into another, which [`Self::read_property_results`]
    /// gives the next statement (so the getter and the method run once each). `None` for any
    /// other statement.
    pub(super) fn call_on_property(&mut self, s: &Stmt) -> Option<Vec<Stmt>> {
        let StmtKind::Call { callee, args } = &s.kind else {
            return None;
        };
        if is_chain(callee) || callee.accessors.is_empty() {
            return None;
        }
        let key = super::method_flow::deref_key(callee)?;
        let mut calls = Vec::new();
        let mut on = callee.clone();
        self.property_holder(&mut on, &mut calls);
        if calls.is_empty() {
            return None;
        }
        let result = self.chain_result(&on)?;
        calls.push(Stmt {
            kind: StmtKind::Call {
                callee: on,
                args: args.clone(),
            },
            span: s.span,
        });
        if let Some(ty) = self.declared_type(&result) {
            let (prefix, method) = key.rsplit_once('.')?;
            let read_key = format!(
                "{prefix}.{}",
                crate::actions::method_result(method).to_ascii_uppercase()
            );
            let t = self.temp(ty, s.span);
            calls.push(assign(
                name_place(t.clone()),
                Expr {
                    span: s.span,
                    kind: ExprKind::Place(result),
                },
                s.span,
            ));
            self.property_results.retain(|(k, _)| *k != read_key);
            self.property_results.push((read_key, t));
        }
        Some(calls)
    }

    /// `s` reading the results [`Self::call_on_property`] kept, from their temporaries (each
    /// used once); `None` when it reads none.
    pub(super) fn read_property_results(&mut self, s: &Stmt) -> Option<Stmt> {
        if self.property_results.is_empty() {
            return None;
        }
        let mut out = s.clone();
        let mut used = Vec::new();
        for (key, t) in &self.property_results {
            let mut hit = false;
            super::method_flow::walk_stmt_exprs(&mut out, &mut |e| {
                hit |= super::method_flow::replace_place(e, key, t);
            });
            if hit {
                used.push(key.clone());
            }
        }
        if used.is_empty() {
            return None;
        }
        self.property_results.retain(|(k, _)| !used.contains(k));
        Some(out)
    }

    /// The type `p` is declared with, a `REFERENCE TO` kept as such (`place_type` reads it as
    /// the type it refers to).
    fn declared_type(&self, p: &Place) -> Option<TypeRef> {
        let env = self.env();
        match p.accessors.split_last() {
            None => match &p.base {
                PlaceBase::Name(n) => env.var_type(n),
                PlaceBase::Address(_) => None,
            },
            Some((Accessor::Field(f), prefix)) => {
                let holder = Place {
                    base: p.base.clone(),
                    accessors: prefix.to_vec(),
                    span: p.span,
                };
                env.member(&env.place_type(&holder)?, f)
            }
            Some(_) => env.place_type(p),
        }
    }

    /// Whether `callee` (`itf.M`) is a method of the interface its prefix holds: `Some` with the
    /// result's interface type when the result is an interface (`METHOD Next : I_Node`).
    fn through_interface(&self, callee: &Place) -> Option<Option<TypeRef>> {
        let Some((Accessor::Field(m), prefix)) = callee.accessors.split_last() else {
            return None;
        };
        let holder = Place {
            base: callee.base.clone(),
            accessors: prefix.to_vec(),
            span: callee.span,
        };
        let env = self.env();
        let Some(TypeRef::Named(n)) = env.place_type(&holder).map(|t| env.resolve(&t)) else {
            return None;
        };
        let i = env.decls.interfaces.get(&n.key())?;
        if !i
            .methods
            .iter()
            .any(|x| x.name.eq_ignore_ascii_case(&m.name))
        {
            return None;
        }
        Some(
            i.interface_results
                .iter()
                .find(|(k, _)| k.eq_ignore_ascii_case(&m.name))
                .map(|(_, t)| t.clone()),
        )
    }

    /// Whether `ty` is a function block type.
    fn is_block(&self, ty: &TypeRef) -> bool {
        let env = self.env();
        matches!(env.resolve(ty), TypeRef::Named(n) if env.decls.pou(&n.name).is_some())
    }
}

fn assign(target: Place, value: Expr, span: Span) -> Stmt {
    Stmt {
        kind: StmtKind::Assign { target, value },
        span,
    }
}

/// Whether expression `e` holds a call chain anywhere (in a place, an index, an argument).
pub(super) fn expr_has_chain(e: &Expr) -> bool {
    let mut todo = vec![e];
    while let Some(e) = todo.pop() {
        match &e.kind {
            ExprKind::Unary { operand, .. } => todo.push(operand),
            ExprKind::Binary { left, right, .. } => {
                todo.push(left);
                todo.push(right);
            }
            ExprKind::Call { args, .. } => todo.extend(args.iter().map(|a| &a.value)),
            ExprKind::Place(p) => {
                if is_chain(p) {
                    return true;
                }
                for a in &p.accessors {
                    if let Accessor::Index(ix) = a {
                        todo.extend(ix.iter());
                    }
                }
            }
            _ => {}
        }
    }
    false
}

/// Whether statement `s` holds a call chain in what it evaluates itself (not in the statements
/// it nests): its target or callee, its value, arguments, conditions, selector or bounds.
pub(super) fn stmt_has_chain(s: &Stmt) -> bool {
    match &s.kind {
        StmtKind::Assign { target, value } => is_chain(target) || expr_has_chain(value),
        StmtKind::Call { callee, args } => {
            is_chain(callee) || args.iter().any(|a| expr_has_chain(&a.value))
        }
        StmtKind::If { branches, .. } => branches.iter().any(|b| expr_has_chain(&b.cond)),
        StmtKind::Case { selector, .. } => expr_has_chain(selector),
        StmtKind::For { from, to, by, .. } => {
            expr_has_chain(from) || expr_has_chain(to) || by.as_ref().is_some_and(expr_has_chain)
        }
        StmtKind::While { cond, .. } => expr_has_chain(cond),
        StmtKind::Repeat { until, .. } => expr_has_chain(until),
        _ => false,
    }
}
