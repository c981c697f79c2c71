//! The VAR_IN_OUT parameters of a function block's methods (CODESYS and TwinCAT methods take them,
//! IEC 61131-3 ed. 3 6.6.1.2.2 gives methods the same parameter kinds as functions).
//!
//! A method's in-out `x` is the block's hidden VAR_IN_OUT `__M_<M>_X` (see
//! [`crate::st::file::add_method_vars`]). A call from outside the block (`inst.M(x := v)`) binds it
//! as any call of the instance binds an in-out: by reference. A call inside the block (`M(x := v)`,
//! from its body or another of its methods) is inlined ([`crate::actions::inline_calls`]); there the
//! in-out is not bound at run time: the inlined copy of the method names the argument itself.
//!
//! Input: the call's in-out arguments (ST places). Output: `CAL M(__M_M_X := v)`, whose formal
//! arguments [`bind_in_outs`] substitutes into the copy of the method's statements.
//! Invariants: an argument's index expressions are computed once, before the method runs (a
//! temporary holds each one that is not a literal), so the copy reads and writes the element the
//! call named, as a reference would; an argument that is not a variable is E0353, except for a
//! `VAR_IN_OUT CONSTANT` (CODESYS: read-only, takes any value), which reads a temporary holding it.

use super::super::ast::{Accessor as SAccessor, Arg, Expr, ExprKind, Place, PlaceBase};
use super::super::infer::named;
use super::super::types::MethodSig;
use super::{simple, var_operand, PouLowering};
use crate::ast::{
    Accessor, ArgDir, CallArgs, FormalArg, Ident, IlStmt, InstrKind, Op, Operand, VarRef,
};
use diagnostics::{code, Diagnostic, Diagnostics};

impl PouLowering<'_> {
    /// The formal arguments binding the in-outs of the own method `sig` in one call (their index
    /// temporaries computed into `out`); an argument that is not a variable is E0353 and left out.
    pub(super) fn method_in_out_args(
        &mut self,
        sig: &MethodSig,
        args: &[(String, &Arg)],
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) -> Vec<FormalArg> {
        let mut bound = Vec::new();
        for (param, a) in args {
            let constant = sig
                .constant_in_outs
                .iter()
                .find(|(n, _)| n.eq_ignore_ascii_case(param));
            let place = match (&a.value.kind, constant) {
                (ExprKind::Place(p), _) => Some(self.frozen_indexes(p, out, diags)),
                // `VAR_IN_OUT CONSTANT` takes a value (CODESYS): it is read from a temporary
                (_, Some((_, ty))) => {
                    self.lit_hint = Some(ty.clone());
                    self.value(&a.value, out, diags);
                    let t = self.temp(ty.clone(), a.value.span);
                    out.push(simple(Op::St, false, Some(var_operand(&t)), a.value.span));
                    Some(Place {
                        base: PlaceBase::Name(t),
                        accessors: Vec::new(),
                        span: a.value.span,
                    })
                }
                _ => None,
            };
            let operand = place.and_then(|p| self.place_operand(&p, out, diags));
            let Some(Operand::Var(v)) = operand else {
                diags.push(
                    Diagnostic::error(
                        code::E0353,
                        format!(
                            "VAR_IN_OUT `{param}` of method `{}` needs a variable",
                            sig.name
                        ),
                    )
                    .at(a.value.span)
                    .with_primary_label("not a variable")
                    .with_hint(format!(
                        "an in-out is passed by reference: store the value in a variable and pass that (`{param} := v`)"
                    )),
                );
                self.poisoned = true;
                continue;
            };
            bound.push(FormalArg {
                name: Ident::new(crate::actions::method_var(&sig.name, param), a.span),
                dir: ArgDir::Input,
                span: a.span,
                value: Operand::Var(v),
            });
        }
        bound
    }

    /// `p` with each index that is not a literal replaced by a temporary holding its value now
    /// (`a[i + 1]` -> `t := i + 1;` and `a[t]`): the element is chosen when the method is called,
    /// even if the method changes `i`.
    fn frozen_indexes(
        &mut self,
        p: &Place,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) -> Place {
        let mut p = p.clone();
        for a in p.accessors.iter_mut() {
            let SAccessor::Index(ix) = a else {
                continue;
            };
            for e in ix.iter_mut() {
                if matches!(e.kind, ExprKind::Literal(_)) {
                    continue;
                }
                let ty = self.temp_type(e, Some(&named("DINT", e.span)));
                self.lit_hint = Some(ty.clone());
                self.value(e, out, diags);
                let t = self.temp(ty, e.span);
                out.push(simple(Op::St, false, Some(var_operand(&t)), e.span));
                *e = Expr {
                    kind: ExprKind::Place(Place {
                        base: PlaceBase::Name(t),
                        accessors: Vec::new(),
                        span: e.span,
                    }),
                    span: e.span,
                };
            }
        }
        self.types.get_mut().clear();
        p
    }
}

/// Whether `args` are the in-out bindings of an own method's call (see the module documentation):
/// formal inputs named after the method's hidden variables (`__M_<M>_X`).
pub(crate) fn is_in_out_binding(method: &str, args: &CallArgs) -> bool {
    let CallArgs::Formal(list) = args else {
        return false;
    };
    let prefix = crate::actions::method_var(method, "");
    !list.is_empty()
        && list.iter().all(|a| {
            a.dir == ArgDir::Input
                && a.name.name.starts_with(&prefix)
                && matches!(a.value, Operand::Var(_))
        })
}

/// Replaces, in the copy `stmts` of a method's statements, each use of a bound in-out
/// (`__M_M_X.f[1]`) by the argument with the use's accessors after it (`v.f[1]`).
pub(crate) fn bind_in_outs(stmts: &mut [IlStmt], args: &CallArgs) {
    let CallArgs::Formal(list) = args else {
        return;
    };
    let map: Vec<(String, &VarRef)> = list
        .iter()
        .filter_map(|a| match &a.value {
            Operand::Var(v) => Some((a.name.key(), v)),
            _ => None,
        })
        .collect();
    if !map.is_empty() {
        stmts_in(stmts, &map);
    }
}

fn stmts_in(stmts: &mut [IlStmt], map: &[(String, &VarRef)]) {
    for s in stmts {
        let IlStmt::Instr(i) = s else {
            continue;
        };
        match &mut i.kind {
            InstrKind::Simple { operand, .. } => {
                if let Some(o) = operand {
                    operand_in(o, map);
                }
            }
            InstrKind::Deferred { operand, body, .. } => {
                if let Some(o) = operand {
                    operand_in(o, map);
                }
                stmts_in(body, map);
            }
            InstrKind::Call { instance, args, .. } => {
                var_in(instance, map);
                args_in(args, map);
            }
            InstrKind::FunctionCall { args, .. } => args_in(args, map),
            InstrKind::FbInput { instance, .. } => var_in(instance, map),
            InstrKind::Jump { .. } | InstrKind::Return { .. } | InstrKind::EmbeddedC { .. } => {}
        }
    }
}

fn args_in(a: &mut CallArgs, map: &[(String, &VarRef)]) {
    match a {
        CallArgs::None => {}
        CallArgs::NonFormal(ops) => ops.iter_mut().for_each(|o| operand_in(o, map)),
        CallArgs::Formal(f) => f.iter_mut().for_each(|a| operand_in(&mut a.value, map)),
    }
}

fn operand_in(o: &mut Operand, map: &[(String, &VarRef)]) {
    match o {
        Operand::Var(v) => var_in(v, map),
        Operand::Ref(r) => {
            if let Some(v) = r.of.as_mut() {
                var_in(v, map);
            }
        }
        _ => {}
    }
}

fn var_in(v: &mut VarRef, map: &[(String, &VarRef)]) {
    for a in v.accessors.iter_mut() {
        if let Accessor::Index(ix) = a {
            ix.iter_mut().for_each(|o| operand_in(o, map));
        }
    }
    let key = v.base.key();
    if let Some((_, arg)) = map.iter().find(|(k, _)| *k == key) {
        let mut accessors: Vec<Accessor> = arg.accessors.to_vec();
        accessors.extend(v.accessors.iter().cloned());
        v.base = arg.base.clone();
        v.accessors = accessors.into();
    }
}
