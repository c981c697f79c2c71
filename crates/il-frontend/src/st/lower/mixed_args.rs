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

use super::super::ast::{Arg, ArgDir, ExprKind, Place};
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
        if args.iter().all(|a| a.name.is_none()) {
            return self.positional_outputs_named(callee, args, diags);
        }
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

    /// A non-formal call that gives the outputs too: `Split(x, lo, hi)` with `Split`'s VAR_INPUT
    /// `x` and VAR_OUTPUTs `lo`, `hi` (IEC 61131-3 ed. 3, 6.6.1.4.2: a non-formal call lists the
    /// parameters of the definition in their order; SIMATIC AX writes it). With as many arguments
    /// as the function's or block's inputs, in-outs and outputs together, each argument is named
    /// after its parameter, the outputs' `=>` (a variable receives the output). With as many as
    /// the inputs and in-outs, the call is left as it is (the outputs are not read). A user
    /// function given another number of arguments is one E1020 here, in ST's words (sema's speaks
    /// of IL's current result). `None`: the call is lowered as written.
    fn positional_outputs_named(
        &mut self,
        callee: &Place,
        args: &[Arg],
        diags: &mut Diagnostics,
    ) -> Option<Vec<Arg>> {
        let (params, function) = self.definition_order(callee)?;
        let inputs: Vec<&String> = params
            .iter()
            .filter(|p| p.1 != VarKind::Output)
            .map(|p| &p.0)
            .collect();
        let outputs = params.len() - inputs.len();
        // (`F()` is a formal call giving no argument: its inputs keep their initial values)
        if args.is_empty() {
            return None;
        }
        if args.len() == inputs.len() {
            // a function's VAR_IN_OUT given by position is bound to its variable: the call is
            // made formal (`F(h)` as `F(io := h)`), the operator form would pass the first
            // argument through the current result, a copy
            if !function || !params.iter().any(|p| p.1 == VarKind::InOut) {
                return None;
            }
            let params: Vec<&(String, VarKind)> =
                params.iter().filter(|p| p.1 != VarKind::Output).collect();
            let mut named = args.to_vec();
            for (a, (p, _)) in named.iter_mut().zip(params) {
                a.name = Some(crate::ast::Ident::new(p.clone(), a.span));
            }
            return Some(named);
        }
        if args.len() != params.len() || outputs == 0 {
            if !function {
                return None;
            }
            let name = callee.name().map_or(String::new(), |n| n.name.clone());
            let list =
                |v: Vec<&String>| v.iter().map(|s| s.as_str()).collect::<Vec<_>>().join(", ");
            let hint = if inputs.is_empty() && outputs == 0 {
                format!("{name} has no parameters: call it without arguments (`{name}()`)")
            } else if outputs == 0 && args.len() < inputs.len() {
                // (TwinCAT projects leave out trailing inputs that have initial values, guanda's
                // `WStrConcat("a", b)` of 9: IEC 61131-3 ed. 2, 2.5.1.1, and ed. 3, 6.6.1.4.2,
                // let only a formal call leave inputs out, and no Beckhoff or CODESYS page found
                // says otherwise, so the error stays and says how to write it)
                format!(
                    "give its inputs in order: {}; or name the ones given (`{name}({} := ...)`): a formal call leaves the others at their initial values",
                    list(inputs.clone()),
                    inputs[..args.len()]
                        .iter()
                        .map(|s| s.as_str())
                        .collect::<Vec<_>>()
                        .join(" := ..., ")
                )
            } else if outputs == 0 {
                format!("give its inputs in order: {}", list(inputs.clone()))
            } else {
                format!(
                    "give its inputs in order ({}), or all its parameters in order ({})",
                    list(inputs.clone()),
                    list(params.iter().map(|p| &p.0).collect())
                )
            };
            let also = if outputs == 0 {
                String::new()
            } else {
                format!(" (or {} with its outputs)", params.len())
            };
            diags.push(
                Diagnostic::error(
                    code::E1020,
                    format!(
                        "{name} takes {} inputs{also}, {} given",
                        inputs.len(),
                        args.len()
                    ),
                )
                .at(args
                    .first()
                    .map_or(callee.span, |a| a.span.to(args[args.len() - 1].span)))
                .with_primary_label("wrong number of arguments")
                .with_hint(hint),
            );
            self.poisoned = true;
            return None;
        }
        let mut named = args.to_vec();
        for (a, (p, kind)) in named.iter_mut().zip(&params) {
            if *kind == VarKind::Output {
                if !matches!(a.value.kind, ExprKind::Place(_)) {
                    // (an output needs a variable to receive it: as written, sema says so)
                    return None;
                }
                a.dir = ArgDir::Output { negated: false };
            }
            a.name = Some(crate::ast::Ident::new(p.clone(), a.span));
        }
        Some(named)
    }

    /// The parameters of `callee`'s definition in their order, each with its kind, and whether
    /// `callee` is a user FUNCTION: a function's or a function block instance's (a method binds
    /// its positional outputs itself, `Action::method_outputs`).
    fn definition_order(&self, callee: &Place) -> Option<(Vec<(String, VarKind)>, bool)> {
        // (a method's hidden inputs are the method's, not the block's)
        let of_pou = |p: &super::super::types::PouInterface| {
            p.params()
                .filter(|v| {
                    !v.0.to_ascii_uppercase()
                        .starts_with(crate::actions::METHOD_PREFIX)
                })
                .map(|v| (v.0.clone(), v.1))
                .collect::<Vec<_>>()
        };
        if let Some(name) = callee.name() {
            if self.env().var_type(name).is_none() || self.function_beside_global(name) {
                let p = self.decls.pou(&name.name)?;
                return (p.kind == PouKind::Function).then(|| (of_pou(p), true));
            }
        }
        if let Some(TypeRef::Named(t)) = self.env().place_type(callee) {
            let p = self.decls.pou(&t.name)?;
            return (p.kind == PouKind::FunctionBlock).then(|| (of_pou(p), false));
        }
        None
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
