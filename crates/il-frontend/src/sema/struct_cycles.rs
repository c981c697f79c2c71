//! Structures that contain themselves by value (`TYPE S : STRUCT next : S; END_STRUCT`, directly or
//! through other structures and arrays): such a type has no finite size.
//!
//! Input: the resolved user types of the [`Model`]. Output: one E0343 at the field that closes
//! each cycle, whose type becomes [`Type::Error`] (so no later walk, the C backend's included,
//! recurses without bound). Invariants: a reference (`REF_TO S`) breaks a cycle (it holds an
//! address); each structure and each field is walked once, so the check is linear.

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
    /// One depth-first walk over all the types (linear in types and fields: a project of 100,000
    /// nested structures is checked in one pass); a field leading back to a structure still on the
    /// walk's path closes a cycle.
    pub(super) fn check_struct_cycles(&mut self) {
        #[derive(Clone, Copy, PartialEq)]
        enum Mark {
            New,
            OnPath,
            Done,
        }
        let n = self.model.types.len();
        let mut mark = vec![Mark::New; n];
        for root in 0..n {
            if mark[root] != Mark::New {
                continue;
            }
            mark[root] = Mark::OnPath;
            let mut stack: Vec<(usize, usize)> = vec![(root, 0)];
            while let Some(&(ty, k)) = stack.last() {
                let field = match &self.model.types[ty].def {
                    UserTypeDef::Struct { fields } => fields.get(k),
                    _ => None,
                };
                let Some(f) = field else {
                    mark[ty] = Mark::Done;
                    stack.pop();
                    continue;
                };
                if let Some(l) = stack.last_mut() {
                    l.1 += 1;
                }
                let Some(next) = held_struct(&f.ty).map(|id| id.0 as usize) else {
                    continue;
                };
                if next >= n {
                    continue;
                }
                match mark[next] {
                    Mark::New => {
                        mark[next] = Mark::OnPath;
                        stack.push((next, 0));
                    }
                    Mark::Done => {}
                    Mark::OnPath => {
                        let (field, span) = (f.name.clone(), f.span);
                        let name = self.model.types[next].name.clone();
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
                    }
                }
            }
        }
    }
}
