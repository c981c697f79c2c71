//! The declared type of an input of a method called through an instance (`inst.M(mode := IDLE)`,
//! `inst.M(IDLE)`): the context that types a bare enumerated value passed to it, as for the input
//! of a function block (see `enum_by_context`).
//!
//! Input: the callee place `inst.M` and the argument's name or position. Output: the type of the
//! method's hidden input `__M_<M>_<input>` of the block (`crate::actions::method_var`), or `None`
//! when the callee is no method of a known block. Invariants: never reports; sema checks the call.

use super::super::ast::{Accessor, Place};
use super::super::infer::Env;
use super::PouLowering;
use crate::ast::{Ident, TypeRef};

impl PouLowering<'_> {
    /// The type of input `name` (or the `k`-th input when `name` is empty) of the method `callee`
    /// names, `inst.M`.
    pub(super) fn method_input_type(
        &self,
        env: &Env,
        callee: &Place,
        name: &Ident,
        k: usize,
    ) -> Option<TypeRef> {
        let (Accessor::Field(m), prefix) = callee.accessors.split_last()? else {
            return None;
        };
        let block = env.place_type(&Place {
            base: callee.base.clone(),
            accessors: prefix.to_vec(),
            span: callee.span,
        })?;
        let TypeRef::Named(b) = env.resolve(&block) else {
            return None;
        };
        let sig = self
            .decls
            .methods
            .get(&b.key())?
            .iter()
            .find(|s| m.is(&s.name))?;
        let input = if name.name.is_empty() {
            sig.inputs.get(k)?.clone()
        } else {
            name.name.clone()
        };
        let hidden = Ident::new(crate::actions::method_var(&sig.name, &input), name.span);
        env.member(&block, &hidden)
    }
}
