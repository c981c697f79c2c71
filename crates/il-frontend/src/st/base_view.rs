//! A derived function block instance where its base is expected (IEC 61131-3 edition 3, 6.6.5
//! "a derived function block instance can be used wherever an instance of its base is allowed";
//! CODESYS, Beckhoff Infosys "Object Orientated Programming": a `REFERENCE TO`, `POINTER TO` or
//! VAR_IN_OUT of the base takes any derived instance, and a method called through it runs the
//! derived block's override).
//!
//! Representation: ladderc flattens a derived block (see [`super::inherit`]): its variables are its
//! bases' (root first, in declaration order, every section) then its own, and the hidden variables
//! of methods come after all of them. So the base's declared variables are a prefix of every
//! derived block's layout, and a reference to a derived instance, read as a reference to its base
//! (a *base view*), reaches the base part of it. Each block of a family (a block that is extended,
//! or that extends another) gets one more variable, first of all, before the root's own:
//! the class `__CLASS_<len>_<ROOT>..._<len>_<BLOCK>` (`UINT`, initial value a number per block, the
//! chain of names read by sema: [`class_chain`]); through a base view it tells which block the
//! instance really is.
//!
//! Input: the flattened units (`super::inherit::flatten` declares the class variables and converts
//! the VAR_IN_OUTs) and the ST statements being lowered (`rewrite`). Output: the class variables;
//! each `VAR_IN_OUT x : B` of a block `B` that has derived blocks becomes `VAR_INPUT x : REFERENCE
//! TO B` (CODESYS passes a VAR_IN_OUT by reference: the same calls, `fb(x := d)`, also from IL
//! bodies, and the same uses of `x` compile, now also with a derived `d`); sema lets a reference to a derived block be stored where a reference to its base is
//! expected (`REFERENCE TO B`, `POINTER TO B := ADR(d)`, `REF_TO B`, `r REF= d`). Through a base view
//! (a place that dereferences a reference, `r.M()`, `p^.M()`, `io.M()`), a method call `v.M(args)`
//! and a call of the block `v(args)` are a CASE on the class: for each derived block `D`, the view
//! is stored in a hidden `__VIEW_<n> : REF_TO D` (the one downcast sema allows) and
//! `__VIEW_<n>^.M(args)` runs `D`'s version, its result copied into the hidden `__VR_<pos>_<M>`
//! that the statement reading `v.M()` (the parser's `v.__M_M`) reads instead; ELSE the base's own.
//! Invariants: only the base's declared variables are ever accessed through a base view (a
//! method's hidden inputs and results lie elsewhere in a derived block, so every method call
//! through a view dispatches before its arguments are stored); the generated C views the derived
//! struct through the base's, so the C backend declares the structs of a family
//! `__may_alias__` (GCC, Clang: no type-based alias assumption between them); the views take the
//! reference itself (`p` of `p^`), never the address of a NULL dereference's scratch object; a
//! NULL view reads class 0 and calls the base's version, which the NULL dereference check
//! reports.

use super::ast::{Accessor, Arg, ArgDir, CaseArm, CaseLabel, Expr, ExprKind, Place, PlaceBase};
use super::ast::{Stmt, StmtKind};
use super::infer::Env;
use crate::ast::{Ident, LiteralKind, RefKind, TypeRef, VarDecl};
use crate::Span;
use std::collections::HashMap;

/// The start of a class variable's name.
pub const CLASS_PREFIX: &str = "__CLASS";
/// The hidden function whose argument, a reference, is read as itself (no implicit `^`).
pub const RAW_REF: &str = "__RAWREF";
/// The start of the hidden references a dispatch views the instance through.
pub const VIEW_PREFIX: &str = "__VIEW_";

/// The class variable of the block whose chain of bases is `chain` (root first, the block last).
pub fn class_var(chain: &[String]) -> String {
    let mut s = CLASS_PREFIX.to_string();
    for n in chain {
        let n = n.to_ascii_uppercase();
        s.push_str(&format!("_{}_{n}", n.len()));
    }
    s
}

/// Whether `name` is one of the hidden views of a dispatch (`__VIEW_<n>`, or inside a method
/// `__M_<METHOD>_VIEW_<n>` once the method's temporaries are renamed).
pub fn is_view_name(name: &str) -> bool {
    name.starts_with(VIEW_PREFIX) || (name.starts_with("__") && name.contains("_VIEW_"))
}

/// The chain of block names (upper-case, root first) a class variable's name encodes; `None` when
/// `name` is no class variable.
pub fn class_chain(name: &str) -> Option<Vec<String>> {
    let mut rest = name.strip_prefix(CLASS_PREFIX)?;
    let mut out = Vec::new();
    while !rest.is_empty() {
        rest = rest.strip_prefix('_')?;
        let digits = rest.find('_')?;
        let len: usize = rest[..digits].parse().ok()?;
        rest = &rest[digits + 1..];
        out.push(rest.get(..len)?.to_ascii_uppercase());
        rest = &rest[len..];
    }
    (!out.is_empty()).then_some(out)
}

/// The derived blocks of each block that has some (upper-case key), each with its class number.
pub type Derived = HashMap<String, Vec<(Ident, u32)>>;

/// Whether a statement's place `p` reads through a reference (a base view): an explicit `^`, or a
/// `REFERENCE TO` (a converted VAR_IN_OUT included) the lowering dereferences.
fn is_view(env: &Env<'_>, p: &Place) -> bool {
    p.accessors.iter().any(|a| matches!(a, Accessor::Deref(_)))
        || !env.implicit_derefs(p, false).is_empty()
}

fn field(p: &Place, name: &str, span: Span) -> Place {
    let mut q = p.clone();
    q.accessors.push(Accessor::Field(Ident::new(name, span)));
    q
}

fn name_place(name: &str, span: Span) -> Place {
    Place {
        base: PlaceBase::Name(Ident::new(name, span)),
        accessors: Vec::new(),
        span,
    }
}

fn place_expr(p: Place, span: Span) -> Expr {
    Expr {
        kind: ExprKind::Place(p),
        span,
    }
}

fn assign(target: Place, value: Expr, span: Span) -> Stmt {
    Stmt {
        kind: StmtKind::Assign { target, value },
        span,
    }
}

/// The hidden variable holding the result of method `m` called through the view at `at`.
fn result_var(at: Span, m: &str) -> String {
    format!("__VR_{}_{}", at.start, m.to_ascii_uppercase())
}

/// The base view a statement's callee `callee` calls through: the view, the block it is typed with,
/// the method called (`None`: the block's body), when the block has derived blocks.
fn view_call(env: &Env<'_>, callee: &Place) -> Option<(Place, Ident, Option<Ident>)> {
    // a view the dispatch made has the exact type of the instance
    if matches!(&callee.base, PlaceBase::Name(n) if n.name.starts_with(VIEW_PREFIX)) {
        return None;
    }
    let block = |p: &Place| -> Option<Ident> {
        let TypeRef::Named(n) = env.resolve(&env.place_type(p)?) else {
            return None;
        };
        let pou = env.decls.pou(&n.name)?;
        (pou.kind == crate::ast::PouKind::FunctionBlock && env.decls.derived.contains_key(&n.key()))
            .then(|| Ident::new(&pou.name, n.span))
    };
    if let Some((Accessor::Field(m), prefix)) = callee.accessors.split_last() {
        let view = Place {
            base: callee.base.clone(),
            accessors: prefix.to_vec(),
            span: callee.span,
        };
        if let Some(b) = block(&view) {
            let is_method = env
                .decls
                .methods
                .get(&b.key())
                .is_some_and(|ms| ms.iter().any(|s| s.name.eq_ignore_ascii_case(&m.name)));
            if is_method && is_view(env, &view) {
                return Some((view, b, Some(m.clone())));
            }
            return None;
        }
    }
    let b = block(callee)?;
    is_view(env, callee).then(|| (callee.clone(), b, None))
}

/// `s` with its calls through base views dispatched (see the module documentation), and the
/// hidden variables to declare; `None` when it has none. `first` numbers the views (the caller's
/// temporaries so far).
pub(super) fn rewrite(env: &Env<'_>, s: &Stmt, first: usize) -> Option<(Vec<Stmt>, Vec<VarDecl>)> {
    if env.decls.derived.is_empty() {
        return None;
    }
    let mut temps = Vec::new();
    if let StmtKind::Call { callee, args } = &s.kind {
        if let Some((view, base, method)) = view_call(env, callee) {
            return Some(dispatch(
                env,
                &view,
                &base,
                method.as_ref(),
                args,
                s.span,
                first,
            ));
        }
    }
    // the statement after a call through a view reads its result (`x := v.__M_M`)
    let mut s2 = s.clone();
    let mut changed = false;
    let mut visit = |e: &mut Expr| results_in(env, e, &mut temps, &mut changed);
    match &mut s2.kind {
        StmtKind::Assign { value, .. } => visit(value),
        StmtKind::Call { args, .. } => args.iter_mut().for_each(|a| visit(&mut a.value)),
        StmtKind::If { branches, .. } => {
            if let Some(b) = branches.first_mut() {
                visit(&mut b.cond);
            }
        }
        StmtKind::Case { selector, .. } => visit(selector),
        StmtKind::For { from, to, by, .. } => {
            visit(from);
            visit(to);
            if let Some(b) = by {
                visit(b);
            }
        }
        _ => {}
    }
    changed.then(|| (vec![s2], temps))
}

/// Replaces in `e` each read of a method's result through a base view (`v.__M_M`) by its hidden
/// result variable.
fn results_in(env: &Env<'_>, e: &mut Expr, temps: &mut Vec<VarDecl>, changed: &mut bool) {
    match &mut e.kind {
        ExprKind::Unary { operand, .. } => results_in(env, operand, temps, changed),
        ExprKind::Binary { left, right, .. } => {
            results_in(env, left, temps, changed);
            results_in(env, right, temps, changed);
        }
        ExprKind::Call { args, .. } => {
            for a in args.iter_mut() {
                results_in(env, &mut a.value, temps, changed);
            }
        }
        ExprKind::Place(p) => {
            let Some((Accessor::Field(f), _)) = p.accessors.split_last() else {
                return;
            };
            let Some(m) = f.name.strip_prefix(crate::actions::METHOD_PREFIX) else {
                return;
            };
            let (m, fspan) = (m.to_string(), f.span);
            // the parser's `v.__M_M` replaces the method's name: the call's callee is `v.M`
            let mut callee = p.clone();
            if let Some(last) = callee.accessors.last_mut() {
                *last = Accessor::Field(Ident::new(&m, fspan));
            }
            let Some((view, base, Some(_))) = view_call(env, &callee) else {
                return;
            };
            let name = result_var(view.span, &m);
            if env.var_type(&Ident::new(&name, e.span)).is_none()
                && !temps.iter().any(|t| t.name.is(&name))
            {
                let Some(ty) = result_type(env, &base, &m) else {
                    return;
                };
                temps.push(VarDecl::new(Ident::new(&name, e.span), ty, e.span));
            }
            *p = name_place(&name, p.span);
            *changed = true;
        }
        _ => {}
    }
}

/// The type of method `m`'s result in block `base` (its hidden `__M_M`).
fn result_type(env: &Env<'_>, base: &Ident, m: &str) -> Option<TypeRef> {
    let hidden = crate::actions::method_result(m);
    env.decls
        .pou(&base.name)?
        .vars
        .iter()
        .find(|v| v.0.eq_ignore_ascii_case(&hidden))
        .map(|v| v.2.clone())
}

/// `view.M(args)` (or `view(args)`) through a base view of `base`: a CASE on the class variable
/// that calls the version of the block the instance is, through a downcast view.
fn dispatch(
    env: &Env<'_>,
    view: &Place,
    base: &Ident,
    method: Option<&Ident>,
    args: &[Arg],
    span: Span,
    first: usize,
) -> (Vec<Stmt>, Vec<VarDecl>) {
    let mut temps = Vec::new();
    let class = env
        .decls
        .pou(&base.name)
        .and_then(|p| p.vars.first())
        .map(|v| v.0.clone())
        .unwrap_or_default();
    // the result: copied out of the instance called into a variable of the caller
    let result = method.and_then(|m| {
        let ty = result_type(env, base, &m.name)?;
        let name = result_var(view.span, &m.name);
        // a `REFERENCE TO` result is bound, not copied (`METHOD Get : REFERENCE TO FB_Item`)
        let bound = matches!(
            ty,
            TypeRef::Ref {
                kind: RefKind::Reference,
                ..
            }
        );
        if env.var_type(&Ident::new(&name, span)).is_none() {
            temps.push(VarDecl::new(Ident::new(&name, span), ty, span));
        }
        Some((name, crate::actions::method_result(&m.name), bound))
    });
    let call_on = |target: &Place| -> Vec<Stmt> {
        let callee = match method {
            Some(m) => field(target, &m.name, m.span),
            None => target.clone(),
        };
        let mut body = vec![Stmt {
            kind: StmtKind::Call {
                callee,
                args: args.to_vec(),
            },
            span,
        }];
        if let Some((r, hidden, bound)) = &result {
            let read = place_expr(field(target, hidden, span), span);
            let value = if *bound {
                Expr {
                    span,
                    kind: ExprKind::Call {
                        name: Ident::new(super::refs::REF_ASSIGN, span),
                        args: vec![Arg {
                            name: None,
                            dir: super::ast::ArgDir::Input,
                            span,
                            value: read,
                        }],
                    },
                }
            } else {
                read
            };
            body.push(assign(name_place(r, span), value, span));
        }
        body
    };
    let mut arms = Vec::new();
    let derived = env
        .decls
        .derived
        .get(&base.key())
        .cloned()
        .unwrap_or_default();
    for (k, (d, id)) in derived.iter().enumerate() {
        let v = format!("{VIEW_PREFIX}{}", first + k + 1);
        temps.push(VarDecl::new(
            Ident::new(&v, span),
            TypeRef::Ref {
                kind: RefKind::RefTo,
                target: Box::new(TypeRef::Named(d.clone())),
                span,
            },
            span,
        ));
        let reference = reference_to(env, view, span);
        let mut deref = name_place(&v, span);
        deref.accessors.push(Accessor::Deref(span));
        let mut body = vec![assign(name_place(&v, span), reference, span)];
        body.extend(call_on(&deref));
        arms.push((*id, body));
    }
    // ELSE: the base itself (also a NULL view: class 0), through a view of its own type
    let mut else_body = Vec::new();
    let own = arms.len();
    {
        let v = format!("{VIEW_PREFIX}{}", first + own + 1);
        temps.push(VarDecl::new(
            Ident::new(&v, span),
            TypeRef::Ref {
                kind: RefKind::RefTo,
                target: Box::new(TypeRef::Named(base.clone())),
                span,
            },
            span,
        ));
        let mut deref = name_place(&v, span);
        deref.accessors.push(Accessor::Deref(span));
        else_body.push(assign(
            name_place(&v, span),
            reference_to(env, view, span),
            span,
        ));
        else_body.extend(call_on(&deref));
    }
    let arms = arms
        .into_iter()
        .map(|(id, body)| CaseArm {
            labels: vec![CaseLabel::Value(Expr::literal(
                LiteralKind::Int(id.into()),
                span,
            ))],
            body,
            span,
        })
        .collect();
    let stmt = Stmt {
        kind: StmtKind::Case {
            selector: place_expr(field(view, &class, span), span),
            arms,
            else_body: Some(else_body),
        },
        span,
    };
    (vec![stmt], temps)
}

/// The reference `view` reads through: `p` for `p^`, the `REFERENCE TO` (or converted
/// VAR_IN_OUT) `r` itself for `r` (no dereference: a NULL view stays NULL, and the C compiler never
/// sees the base's NULL scratch object read as a derived one); `REF(view)` for any other view.
fn reference_to(env: &Env<'_>, view: &Place, span: Span) -> Expr {
    let n = view.accessors.len();
    if let Some(Accessor::Deref(_)) = view.accessors.last() {
        let mut p = view.clone();
        p.accessors.pop();
        if !env.implicit_derefs(&p, false).contains(&(n - 1)) {
            return place_expr(p, span);
        }
    }
    let (name, arg) = if env.implicit_derefs(view, false).contains(&n) {
        (RAW_REF, view.clone())
    } else {
        ("REF", view.clone())
    };
    Expr {
        kind: ExprKind::Call {
            name: Ident::new(name, span),
            args: vec![Arg {
                name: None,
                dir: ArgDir::Input,
                value: place_expr(arg, span),
                span,
            }],
        },
        span,
    }
}
