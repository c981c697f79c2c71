//! Feedback loops drawn with wires only, for [`super`]: a function box's output wired back to an
//! input evaluated before it (an `AND` whose `OUT` feeds its own `IN1`, an `OR`/`AND` latch), with
//! no variable and no function block instance on the loop.
//!
//! IEC 61131-3 ed. 2 (2003) 4.1.3 "Evaluation of networks", feedback paths (ed. 3 keeps the rules):
//! explicit loops (wires only) may appear in FBD; the order of execution of the elements of such a
//! loop is the implementation's to choose; the feedback value is the one of the previous evaluation
//! of its element, its initial value at the first evaluation. Beremiz's PLCGenerator compiles the
//! loop through a temporary that keeps the previous value; Beckhoff's and CODESYS' CFC let the user
//! choose the loop's first element ("Set Start of Feedback", infosys tc3_plc_intro 11981157515).
//!
//! ladderc's choice: the loop is cut at the box that comes first in the network's order (data flow,
//! ties broken top to bottom, then left to right: [`Node::order_key`](crate::graph::Node)); its input
//! wired from a function box of the loop reads that box's result from the end of the previous
//! evaluation, kept in the hidden variable `__loop_<localId>` (initially the type's default: FALSE,
//! 0); the box stores its result there when it runs. A box with EN keeps its result in
//! `__out_<localId>` already, which the input reads. `tests/tests/fbd_r32_run.rs`.
//!
//! Input: one strongly connected component of a network's dependencies. Output: the (reader, source)
//! pair to cut, or `None` (E3010 then: a loop through elements that hold no value, like connectors
//! between contacts). Invariants: only a wire from a function box's result (not its ENO) into a box
//! is cut; the choice depends on the graph only, not on the order of the component.

use super::*;

impl NetLowering<'_, '_> {
    /// Whether node `s` is a function box (a standard or user function, an operator: no instance)
    /// whose result can be kept from one evaluation to the next.
    fn is_function_box(&self, s: usize) -> bool {
        match &self.g.nodes[s].kind {
            Kind::Block(b) => {
                b.instance.is_none()
                    && b.code.is_none()
                    && matches!(
                        self.block_type(&b.type_name),
                        Some(BlockType::StdFn(_) | BlockType::UserFn(_))
                    )
            }
            _ => false,
        }
    }

    /// The wire of a loop made of wires only to cut: into the box of `comp` that comes first in the
    /// network's order, from a function box of `comp` (its result, not its ENO).
    pub(super) fn feedback_cut(
        &self,
        comp: &[usize],
        deps: &HashMap<usize, Vec<usize>>,
    ) -> Option<(usize, usize)> {
        let g = self.g;
        let set: HashSet<usize> = comp.iter().copied().collect();
        let mut readers: Vec<usize> = comp
            .iter()
            .copied()
            .filter(|&t| matches!(g.nodes[t].kind, Kind::Block(_)))
            .collect();
        readers.sort_by_key(|&t| g.nodes[t].order_key());
        for t in readers {
            let mut sources: Vec<usize> = deps
                .get(&t)
                .map(Vec::as_slice)
                .unwrap_or(&[])
                .iter()
                .copied()
                .filter(|s| set.contains(s) && self.is_function_box(*s))
                .filter(|&s| {
                    // every wire from `s` into `t` carries the result, none the ENO
                    g.nodes[t].wires().filter(|w| w.from == s).all(|w| {
                        !w.pin
                            .as_deref()
                            .is_some_and(|p| p.trim().eq_ignore_ascii_case("ENO"))
                    })
                })
                .collect();
            sources.sort_by_key(|&s| g.nodes[s].order_key());
            if let Some(&s) = sources.first() {
                return Some((t, s));
            }
        }
        None
    }

    /// The hidden variable that keeps the result of function box `s` from one evaluation to the next:
    /// `__out_<localId>` for a box with EN (its result is kept there anyway), else `__loop_<localId>`.
    pub(super) fn feedback_var(&self, s: usize) -> String {
        let node = &self.g.nodes[s];
        let with_en = match &node.kind {
            Kind::Block(b) => b
                .inputs
                .iter()
                .any(|p| p.name.eq_ignore_ascii_case("EN") && !p.wires.is_empty()),
            _ => false,
        };
        if with_en {
            format!("__out_{}", sanitize(&node.id))
        } else {
            format!("__loop_{}", sanitize(&node.id))
        }
    }

    /// The result type of function box `s`, known before it is built: a fixed result type (`GT`:
    /// BOOL, a user function's), else the declared type of a variable wired to one of its inputs,
    /// else of a variable its result is written to; `None` when none tells.
    fn feedback_type(&self, s: usize) -> Option<TypeRef> {
        let g = self.g;
        let node = &g.nodes[s];
        let Kind::Block(b) = &node.kind else {
            return None;
        };
        match self.block_type(&b.type_name)? {
            BlockType::StdFn(f) => {
                if let ResultRule::Fixed(t) = f.rule {
                    return Some(named_type(t, node.span));
                }
            }
            BlockType::UserFn(sig) => return sig.ret.clone(),
            _ => return None,
        }
        let var_of = |i: usize| -> Option<TypeRef> {
            let (expr, span) = match &g.nodes[i].kind {
                Kind::InVar {
                    expr, expr_span, ..
                }
                | Kind::OutVar {
                    expr, expr_span, ..
                }
                | Kind::InOutVar {
                    expr, expr_span, ..
                } => (expr, *expr_span),
                _ => return None,
            };
            self.pou.var_type(&values::var_ref(expr, span)?)
        };
        let from_inputs = b
            .inputs
            .iter()
            .filter(|p| !p.name.eq_ignore_ascii_case("EN"))
            .flat_map(|p| p.wires.iter())
            .find_map(|w| var_of(w.from));
        from_inputs.or_else(|| {
            g.nodes
                .iter()
                .enumerate()
                .filter(|(_, n)| n.wires().any(|w| w.from == s))
                .find_map(|(i, _)| var_of(i))
        })
    }

    /// What a cut wire from function box `src` (not built yet) carries: the box's result at the end
    /// of its previous evaluation, negated when its output pin is.
    pub(super) fn feedback_read(&mut self, src: usize, w: &Wire) -> Option<ValId> {
        let g = self.g;
        let Kind::Block(b) = &g.nodes[src].kind else {
            return None;
        };
        let out = match &w.pin {
            Some(p) => b
                .outputs
                .iter()
                .find(|o| o.name.eq_ignore_ascii_case(p.trim())),
            None => b
                .outputs
                .iter()
                .find(|o| !o.name.eq_ignore_ascii_case("ENO")),
        };
        let negated = out.is_some_and(|o| o.negated);
        let name = self.feedback_var(src);
        if let Some(ty) = self.feedback_type(src) {
            // known before the box is built, so the boxes reading it are typed (a `NOT` fed by
            // its own output has no other input to take its type from)
            self.pou.declare_hidden(&name, ty, g.nodes[src].span);
        }
        let op = var_operand(&name, w.span);
        let v = self.val(Val::Leaf { op, neg: false }, g.nodes[src].span);
        Some(if negated {
            self.val(Val::Not(v), g.nodes[src].span)
        } else {
            v
        })
    }
}
