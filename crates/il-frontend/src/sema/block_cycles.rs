//! Function blocks and classes that contain an instance of themselves by value (`CLASS Node VAR
//! next : Node; END_VAR`, directly or through other blocks, structures and arrays): such a block
//! has no finite size (IEC 61131-3 ed. 3, 6.6.5, 6.6.6).
//!
//! Input: the declared model (structure fields, block variables), after
//! [`Analyzer::check_struct_cycles`] cut the cycles made of structures only. Output: one E1080 at
//! the variable that closes each cycle, naming the chain; that variable's type becomes
//! [`Type::Error`] (so no later walk, the C backend's included, recurses without bound).
//! Invariants: a VAR_IN_OUT, a VAR_EXTERNAL, a VAR_TEMP (a C local of the call, a method's locals
//! included) and a reference break a cycle; each type and each variable is walked once (linear).

use super::model::{FbType, Type, UserTypeDef};
use super::Analyzer;
use crate::ast::VarKind;
use diagnostics::code;

#[derive(Clone, Copy, PartialEq, Eq)]
enum Node {
    Struct(usize),
    Block(usize),
}

/// The structure or block a value of type `t` holds (through arrays), if any.
fn held(t: &Type) -> Option<Node> {
    match t {
        Type::Struct(id) => Some(Node::Struct(id.0 as usize)),
        Type::Fb(FbType::User(id)) => Some(Node::Block(id.0 as usize)),
        Type::Array { element, .. } => held(element),
        _ => None,
    }
}

impl Analyzer<'_> {
    /// The `k`th member of `n` that holds its value inside `n`: its name, span and type.
    fn member(&self, n: Node, k: usize) -> Option<(&str, diagnostics::Span, &Type)> {
        match n {
            Node::Struct(i) => match &self.model.types[i].def {
                UserTypeDef::Struct { fields } => {
                    fields.get(k).map(|f| (f.name.as_str(), f.span, &f.ty))
                }
                _ => None,
            },
            Node::Block(i) => self.model.pous[i].vars.get(k).map(|v| {
                let by_value =
                    !matches!(v.kind, VarKind::InOut | VarKind::External | VarKind::Temp);
                let ty = if by_value { &v.ty } else { &Type::Error };
                (v.name.as_str(), v.span, ty)
            }),
        }
    }

    fn node_name(&self, n: Node) -> &str {
        match n {
            Node::Struct(i) => &self.model.types[i].name,
            Node::Block(i) => &self.model.pous[i].name,
        }
    }

    /// Reports and cuts every block that contains itself (see the module documentation): one
    /// depth-first walk over the structures and blocks; a member leading back to a node still on
    /// the walk's path closes a cycle.
    pub(super) fn check_block_cycles(&mut self) {
        let (nt, np) = (self.model.types.len(), self.model.pous.len());
        let index = |n: Node| match n {
            Node::Struct(i) => i,
            Node::Block(i) => nt + i,
        };
        // 0: new, 1: on the path, 2: done
        let mut mark = vec![0u8; nt + np];
        let roots = (0..np).map(Node::Block);
        for root in roots {
            if mark[index(root)] != 0 {
                continue;
            }
            mark[index(root)] = 1;
            // (node, next member to look at)
            let mut stack: Vec<(Node, usize)> = vec![(root, 0)];
            while let Some(&(n, k)) = stack.last() {
                let Some((_, _, ty)) = self.member(n, k) else {
                    mark[index(n)] = 2;
                    stack.pop();
                    continue;
                };
                if let Some(l) = stack.last_mut() {
                    l.1 += 1;
                }
                let Some(next) = held(ty) else {
                    continue;
                };
                let in_range = match next {
                    Node::Struct(i) => i < nt,
                    Node::Block(i) => i < np,
                };
                if !in_range {
                    continue;
                }
                match mark[index(next)] {
                    0 => {
                        mark[index(next)] = 1;
                        stack.push((next, 0));
                    }
                    1 => self.report_block_cycle(&stack, next),
                    _ => {}
                }
            }
        }
    }

    /// E1080 for the cycle from `target` (on `path`) to the member just walked, which is cut.
    fn report_block_cycle(&mut self, path: &[(Node, usize)], target: Node) {
        let Some(from) = path.iter().position(|&(n, _)| n == target) else {
            return;
        };
        let mut chain = Vec::new();
        for &(n, k) in &path[from..] {
            if let Some((name, _, _)) = self.member(n, k - 1) {
                chain.push(format!("`{}.{}`", self.node_name(n), name));
            }
        }
        let Some(&(last, k)) = path.last() else {
            return;
        };
        let Some((_, span, _)) = self.member(last, k - 1) else {
            return;
        };
        let (what, name) = match target {
            Node::Block(i) if self.model.pous[i].class => ("class", self.node_name(target)),
            Node::Block(_) => ("function block", self.node_name(target)),
            Node::Struct(_) => ("structure", self.node_name(target)),
        };
        let message = format!(
            "{what} `{name}` contains an instance of itself (through {})",
            chain.join(" -> ")
        );
        self.error(code::E1080, span, message)
            .label("an instance held inside itself")
            .hint("hold the other instance through a reference (`REF_TO`, `POINTER TO`) or pass it as a VAR_IN_OUT");
        match last {
            Node::Block(i) => self.model.pous[i].vars[k - 1].ty = Type::Error,
            Node::Struct(i) => {
                if let UserTypeDef::Struct { fields } = &mut self.model.types[i].def {
                    fields[k - 1].ty = Type::Error;
                }
            }
        }
    }
}
