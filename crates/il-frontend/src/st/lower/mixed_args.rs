//! Calls that give some arguments by position and others by name:
//! `Integrate(t, p0 := ps, v0 := vs)`, `BubbleSort(data := ADR(d), n, sorted := ADR(ix))`.
//!
//! IEC 61131-3 ed. 3 (6.6.1.4.2) makes a call either formal or non-formal; CODESYS compilers up to
//! V3.4.10 refused the mix (C0042 "Either all or none formal parameter have to be denoted"), and
//! Beckhoff's "Object Function" page still says TwinCAT 3 does. The TwinCAT 3 compiler accepts it in
//! practice: stefanbesler/struckig, a library built with it, mixes them in 47 calls, and Beckhoff's
//! static analysis only flags the mix (TE1200 SA0107 "Missing formal parameters", whose example
//! `F_Sample(TRUE, bIn2 := FALSE)` compiles). The argument at position k binds the k-th parameter
//! (VAR_INPUT and VAR_IN_OUT in declaration order, as in a non-formal call). ladderc accepts it so,
//! with one W1422 per POU (another IEC compiler refuses the text).
//!
//! Input: a call's callee and arguments. Output: the arguments with the positional ones named;
//! `None` when the call does not mix them, its callee's parameters are unknown, a position is past
//! the last parameter or names a parameter also given by name (then the call is lowered as written
//! and E3106 reports it).

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
        let first_positional = args.iter().position(|a| a.name.is_none())?;
        let params = self.parameter_order(callee)?;
        let mut named = args.to_vec();
        for (k, a) in named.iter_mut().enumerate() {
            if a.name.is_some() {
                continue;
            }
            let p = params.get(k)?;
            // the parameter is given by name too: left to E3106
            if args.iter().any(|b| {
                b.name
                    .as_ref()
                    .is_some_and(|n| n.name.eq_ignore_ascii_case(p))
            }) || !matches!(a.dir, ArgDir::Input)
            {
                return None;
            }
            a.name = Some(crate::ast::Ident::new(p.clone(), a.span));
        }
        let at = args[first_formal.min(first_positional)]
            .span
            .to(args[first_formal.max(first_positional)].span);
        if !self.mixed_args_reported {
            self.mixed_args_reported = true;
            diags.push(
                Diagnostic::new(
                    code::W1422,
                    Severity::Warning,
                    "positional and formal arguments mixed in one call: IEC 61131-3 makes a call either formal or non-formal (its other uses in this POU are not reported)",
                )
                .at(at)
                .with_primary_label("positional and formal arguments")
                .with_hint("compiled as TwinCAT does: the argument at position k binds the k-th parameter; name every argument for another IEC compiler"),
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
                return (!f.extensible)
                    .then(|| f.params.iter().map(|p| p.name.to_string()).collect());
            }
        }
        if let Some(TypeRef::Named(t)) = self.env().place_type(callee) {
            if self
                .decls
                .pou(&t.name)
                .is_some_and(|p| p.kind == PouKind::FunctionBlock)
            {
                return of_pou(&t.name);
            }
        }
        // `inst.M(...)`, `PRG.M(...)`: a method of the instance's block or of the program
        self.method_called(callee).map(|(_, sig)| sig.inputs)
    }

    /// The method a call `inst.M(...)` / `PRG.M(...)` names: the type holding it (the block, or
    /// the program) and its signature.
    pub(super) fn method_called(
        &self,
        callee: &Place,
    ) -> Option<(TypeRef, super::super::types::MethodSig)> {
        let (super::super::ast::Accessor::Field(m), rest) = callee.accessors.split_last()? else {
            return None;
        };
        let prefix = Place {
            base: callee.base.clone(),
            accessors: rest.to_vec(),
            span: callee.span,
        };
        let owner = match self.env().place_type(&prefix) {
            Some(TypeRef::Named(t)) => t,
            _ => prefix.name()?.clone(),
        };
        let sig = self
            .decls
            .methods
            .get(&owner.key())?
            .iter()
            .find(|s| s.name.eq_ignore_ascii_case(&m.name))?;
        Some((TypeRef::Named(owner), sig.clone()))
    }
}
