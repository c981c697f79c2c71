//! Structures that contain themselves by value (`TYPE S : STRUCT next : S; END_STRUCT`, directly or
//! through other structures and arrays): such a type has no finite size.
//!
//! Input: the resolved user types of the [`Model`]. Output: one E0343 at the field that closes
//! each cycle, whose type becomes [`Type::Error`] (so no later walk, the C backend's included,
//! recurses without bound). Invariants: a reference (`REF_TO S`) breaks a cycle (it holds an
//! address); each structure is walked at most once per start, so the check is finite.

use super::model::*;
use super::Analyzer;
use diagnostics::code;

/// The structure a field of type `t` holds by value (through arrays), if any.
fn held_struct(t: &Type) -> Option<TypeId> {
    match t {
        Type::Struct(id) => Some(*id),
        Type::Array { element, .. } => held_struct(element),
        _ => None,
    }
}

impl Analyzer<'_> {
    /// Reports and cuts every structure that contains itself (see the module documentation).
    pub(super) fn check_struct_cycles(&mut self) {
        for start in 0..self.model.types.len() {
            // depth-first from `start`: a path back to it is a cycle
            let mut stack: Vec<(usize, usize)> = vec![(start, 0)];
            let mut seen = vec![false; self.model.types.len()];
            while let Some(&(ty, k)) = stack.last() {
                let UserTypeDef::Struct { fields } = &self.model.types[ty].def else {
                    stack.pop();
                    continue;
                };
                let Some(f) = fields.get(k) else {
                    stack.pop();
                    continue;
                };
                if let Some(l) = stack.last_mut() {
                    l.1 += 1;
                }
                let Some(next) = held_struct(&f.ty).map(|id| id.0 as usize) else {
                    continue;
                };
                if next == start {
                    let (field, span) = (f.name.clone(), f.span);
                    let name = self.model.types[start].name.clone();
                    self.error(
                        code::E0343,
                        span,
                        format!("structure `{name}` contains itself (through field `{field}`)"),
                    )
                    .label("a value of the structure inside itself")
                    .hint("hold the inner one through a reference (`REF_TO`, `POINTER TO`) or drop the field");
                    if let UserTypeDef::Struct { fields } = &mut self.model.types[ty].def {
                        fields[k].ty = Type::Error;
                    }
                    break;
                }
                if next < seen.len() && !seen[next] {
                    seen[next] = true;
                    stack.push((next, 0));
                }
            }
        }
    }
}
