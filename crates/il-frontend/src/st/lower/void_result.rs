//! A FUNCTION declared without a result type whose body assigns the function's name:
//! `FUNCTION Inv` (ST) or a PLCopen `<pou pouType="function">` without `<returnType>`, then
//! `Inv := 0 - v;`.
//!
//! IEC 61131-3 ed. 3 (6.6.2.2) makes a function's result the variable named after the function, of
//! the result type declared after its name; Beckhoff's "Object Function" page (TwinCAT 3: `FUNCTION
//! <function> : <data type>`, "The output variable of a function is the function name") says the
//! same. ladderc compiles a function without a result type, as TwinCAT does (E0018 is no longer
//! reported), as one returning no value, so such a function has no variable of its own name: the
//! assignment has nothing to write. Most often the result type was lost on the way (an exporter
//! that dropped `<returnType>`). Before issue #13's round 31 the body gave one to three back-end
//! E2005 per assignment ("current result of unknown type", "cannot resolve `Inv`").
//!
//! Input: an assignment statement of the POU being lowered. Output: `true` when the assignment is
//! to the name of a FUNCTION without result type (which has no variable of that name), then one
//! E0354 for the POU at its first such assignment; the assignment is not lowered. Invariants: one
//! error per function however many assignments name it; nothing changes for other POUs, for
//! functions with a result type, or when a variable of the function has the function's name.

use super::super::ast::{Expr, Place};
use super::{PouLowering, Ty};
use crate::ast::{PouKind, TypeRef};
use diagnostics::{code, Diagnostic, Diagnostics, Span};

impl PouLowering<'_> {
    /// Whether `target := value` assigns the result of a FUNCTION without result type (see the
    /// module documentation); reports it the first time.
    pub(super) fn assigns_missing_result(
        &mut self,
        target: &Place,
        value: &Expr,
        span: Span,
        diags: &mut Diagnostics,
    ) -> bool {
        if self.kind != PouKind::Function || self.ret.is_some() {
            return false;
        }
        let Some(name) = target.name() else {
            return false;
        };
        if !name.is(&self.pou.name) || self.env().var_type(name).is_some() {
            return false;
        }
        if self.missing_result_reported {
            return true;
        }
        self.missing_result_reported = true;
        // the type of the value assigned, when it is a named type, else an example
        let example = match self.ty(value) {
            Ty::Known(TypeRef::Named(t)) => t.name,
            _ => "INT".to_string(),
        };
        let pou = self.pou.name.clone();
        diags.push(
            Diagnostic::error(
                code::E0354,
                format!(
                    "function `{pou}` is declared without a result type, so `{pou} := ...` has nothing to assign to"
                ),
            )
            .at(span)
            .with_primary_label(format!("`{pou}` is no variable: the function returns no value"))
            .with_hint(format!(
                "declare its result type: `FUNCTION {pou} : {example}` in ST, `<returnType><{example}/></returnType>` in its PLCopen <interface>"
            )),
        );
        true
    }
}
