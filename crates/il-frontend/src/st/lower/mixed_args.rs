//! Calls that give their first arguments by position and the rest by name:
//! `Integrate(t, p0 := ps, v0 := vs)`, `Roots.SolveCub(ADR(c), rootCount := n)`.
//!
//! IEC 61131-3 ed. 3 (6.6.1.4.2) makes a call either formal or non-formal, and CODESYS compilers up
//! to V3.4.10 refused the mix (C0042 "Either all or none formal parameter have to be denoted").
//! TwinCAT 3 and later CODESYS compilers accept positional arguments followed by formal ones: their
//! static analysis only flags it (Beckhoff TE1200 SA0107 "Missing formal parameters", whose
//! example `F_Sample(TRUE, bIn2 := FALSE)` compiles). ladderc accepts what they accept, with one
//! W1422 per POU (the text is not portable), and keeps E3106 for a positional argument after a
//! formal one, which no vendor accepts.
//!
//! Input: a call's callee and arguments. Output: the arguments with the leading positional ones
//! named after the callee's parameters in declaration order (VAR_INPUT and VAR_IN_OUT, the order
//! a non-formal call binds); `None` when the call is not such a mix or its callee's parameters are
//! unknown (then the call is lowered as written and E3106 reports it).

use super::super::ast::{Arg, ArgDir, Place};
use super::PouLowering;
use crate::ast::{PouKind, TypeRef, VarKind};
use diagnostics::{code, Diagnostic, Diagnostics, Severity};

impl PouLowering<'_> {
    /// `args` with the positional arguments before the first formal one named (see the module
    /// documentation), or `None`.
    pub(super) fn name_positional_args(
        &mut self,
        callee: &Place,
        args: &[Arg],
        diags: &mut Diagnostics,
    ) -> Option<Vec<Arg>> {
        let first_formal = args.iter().position(|a| a.name.is_some())?;
        if first_formal == 0 || args[first_formal..].iter().any(|a| a.name.is_none()) {
            return None;
        }
        let params = self.parameter_order(callee)?;
        if first_formal > params.len() {
            return None;
        }
        let mut named = args.to_vec();
        for (a, p) in named.iter_mut().zip(&params) {
            if a.name.is_none() {
                if !matches!(a.dir, ArgDir::Input) {
                    return None;
                }
                a.name = Some(crate::ast::Ident::new(p.clone(), a.span));
            }
        }
        if !self.mixed_args_reported {
            self.mixed_args_reported = true;
            diags.push(
                Diagnostic::new(
                    code::W1422,
                    Severity::Warning,
                    "positional arguments followed by formal ones in one call: IEC 61131-3 makes a call either formal or non-formal (its other uses in this POU are not reported)",
                )
                .at(args[0].span.to(args[first_formal].span))
                .with_primary_label("positional, then formal")
                .with_hint("compiled as TwinCAT does, the positional ones bound in declaration order; name every argument for another IEC compiler"),
            );
        }
        Some(named)
    }

    /// The parameters a non-formal call of `callee` binds, in order: a function's, a program's or
    /// a function block instance's VAR_INPUT and VAR_IN_OUT, a method's inputs (`inst.M`,
    /// `PRG.M`), a standard function's inputs.
    fn parameter_order(&self, callee: &Place) -> Option<Vec<String>> {
        let of_pou = |name: &str| {
            self.decls.pou(name).map(|p| {
                p.params()
                    .filter(|v| matches!(v.1, VarKind::Input | VarKind::InOut))
                    .map(|v| v.0.clone())
                    .collect::<Vec<_>>()
            })
        };
        if let Some(name) = callee.name() {
            if self.env().var_type(name).is_none() {
                if let Some(p) = self.decls.pou(&name.name) {
                    if matches!(p.kind, PouKind::Function | PouKind::Program) {
                        return of_pou(&name.name);
                    }
                }
                let f = crate::sema::stdlib::function(&name.name)?;
                return (!f.extensible).then(|| f.params.iter().map(|p| p.name.to_string()).collect());
            }
        }
        if let Some(TypeRef::Named(t)) = self.env().place_type(callee) {
            if self.decls.pou(&t.name).is_some_and(|p| p.kind == PouKind::FunctionBlock) {
                return of_pou(&t.name);
            }
        }
        // `inst.M(...)`, `PRG.M(...)`: a method of the instance's block or of the program
        let (super::super::ast::Accessor::Field(m), rest) = callee.accessors.split_last()? else {
            return None;
        };
        let prefix = Place {
            base: callee.base.clone(),
            accessors: rest.to_vec(),
            span: callee.span,
        };
        let owner = match self.env().place_type(&prefix) {
            Some(TypeRef::Named(t)) => t.key(),
            _ => prefix.name()?.key(),
        };
        let sig = self
            .decls
            .methods
            .get(&owner)?
            .iter()
            .find(|s| s.name.eq_ignore_ascii_case(&m.name))?;
        Some(sig.inputs.clone())
    }
}
