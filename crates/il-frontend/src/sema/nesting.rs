//! The containment depth of structured types and function blocks: a struct field of a struct type, an
//! FB instance inside an FB, and so on through names (`s0 : STRUCT a : s1; END_STRUCT; s1 : ...`).
//!
//! Input: the declared model (struct fields, POU variables). Output: one E0214 at the outermost type or
//! FB of a chain longer than [`MAX_CONTAINMENT`]. Invariants: the depths are computed once each with an
//! explicit stack (no recursion, linear in the declarations); a cycle (reported elsewhere as a recursive
//! type) counts 0 here. The C generation and the initial values walk types recursively: this cap is what
//! bounds their depth.

use super::model::{FbType, Type, UserTypeDef};
use super::Analyzer;
use crate::ast::VarKind;
use diagnostics::code;
use std::collections::HashMap;

/// The deepest chain of structs in structs and FB instances in FBs a program may declare.
pub const MAX_CONTAINMENT: usize = 64;

#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum Key {
    Struct(u32),
    Fb(u32),
}

impl Analyzer<'_> {
    /// The structured types a struct or FB contains directly (through arrays too).
    fn contained(&self, k: Key) -> Vec<Key> {
        let key = |ty: &Type| {
            let mut t = ty;
            while let Type::Array { element, .. } = t {
                t = element;
            }
            match t {
                Type::Struct(id) => Some(Key::Struct(id.0)),
                Type::Fb(FbType::User(id)) => Some(Key::Fb(id.0)),
                _ => None,
            }
        };
        match k {
            Key::Struct(i) => match &self.model.types[i as usize].def {
                UserTypeDef::Struct { fields } => {
                    fields.iter().filter_map(|f| key(&f.ty)).collect()
                }
                _ => Vec::new(),
            },
            Key::Fb(i) => self.model.pous[i as usize]
                .vars
                .iter()
                .filter(|v| !matches!(v.kind, VarKind::InOut | VarKind::External))
                .filter_map(|v| key(&v.ty))
                .collect(),
        }
    }

    /// Reports E0214 once, at the first struct or FB (in declaration order) whose containment chain is
    /// longer than [`MAX_CONTAINMENT`].
    pub(crate) fn check_containment(&mut self) {
        let mut depth: HashMap<Key, usize> = HashMap::new();
        let roots: Vec<Key> = (0..self.model.types.len() as u32)
            .filter(|&i| matches!(self.model.types[i as usize].def, UserTypeDef::Struct { .. }))
            .map(Key::Struct)
            .chain((0..self.model.pous.len() as u32).map(Key::Fb))
            .collect();
        for root in roots {
            if depth.contains_key(&root) {
                continue;
            }
            // Post-order with an explicit stack: a key's depth is 1 + the deepest it contains.
            let mut stack = vec![(root, false)];
            while let Some((k, expanded)) = stack.pop() {
                if expanded {
                    let d = 1 + self
                        .contained(k)
                        .iter()
                        .map(|c| depth.get(c).copied().unwrap_or(0))
                        .max()
                        .unwrap_or(0);
                    depth.insert(k, d);
                    continue;
                }
                if depth.contains_key(&k) {
                    continue;
                }
                depth.insert(k, 0); // open: a cycle back to it counts 0
                stack.push((k, true));
                for c in self.contained(k) {
                    if !depth.contains_key(&c) {
                        stack.push((c, false));
                    }
                }
            }
            let d = depth[&root];
            if d > MAX_CONTAINMENT {
                let (what, name, span) = match root {
                    Key::Struct(i) => {
                        let t = &self.model.types[i as usize];
                        ("structure", t.name.clone(), t.span)
                    }
                    Key::Fb(i) => {
                        let p = &self.model.pous[i as usize];
                        let what = match p.kind {
                            crate::ast::PouKind::Program => "program",
                            crate::ast::PouKind::Function => "function",
                            _ => "function block",
                        };
                        (what, p.name.clone(), p.span)
                    }
                };
                self.error(
                    code::E0214,
                    span,
                    format!(
                        "{what} `{name}` contains structures or FB instances {d} levels deep (at most {MAX_CONTAINMENT})"
                    ),
                )
                .label("the chain of contained types starts here")
                .hint("flatten the data: fewer levels of structures in structures, or FB instances in FBs");
                return;
            }
        }
    }
}
