//! ST inside LD/FBD bodies, for [`super`]: the ST expressions TwinCAT and CODESYS write where a
//! variable is read (a contact's `<variable>`, an input variable's `<expression>`) and the ST
//! statements of CODESYS EXECUTE boxes, lowered by the ST front end (`il_frontend::st`) through one
//! [`PouLowering`] per body (labels and temporaries `_STX_...`, so they never clash with an ST body's).
//!
//! Input: the graph and its nodes. Output: IL statements (per network for the expressions, a
//! [`Action::Execute`] for a box) and hidden variables `__expr_<localId>` declared in the body.
//! Invariants: every diagnostic of the ST front end is located at the element (POU, network,
//! localId); text that is neither an operand nor an ST expression is left to the caller (E3011).

use super::{
    bool_ty, sanitize, shown, simple, Action, BodyLowering, InPin, Kind, NetLowering, Operand, Val,
    ValId,
};
use crate::context::{Ctx, Where};
use crate::graph::{self, Graph};
use crate::values;
use diagnostics::{code, Diagnostic};
use il_frontend::ast::{IlStmt, Op};
use il_frontend::st::{self, PouLowering};

impl BodyLowering<'_> {
    /// The ST expressions written where a variable is read (a contact's `<variable>`, an input
    /// variable's `<expression>`: `NOT Stop`, `A AND C`, `T1 > T#7s OR T1 > T#8s`, as TwinCAT and
    /// CODESYS export them): each is lowered by the ST front end into a hidden `__expr_<localId>`
    /// the node then reads, computed at the start of its network (the code per network is returned).
    /// Text that is neither an operand nor an ST expression is left to [`NetLowering::parse_var`]
    /// (E3011).
    pub(super) fn expressions(&mut self, ctx: &mut Ctx, g: &Graph) -> Vec<Vec<IlStmt>> {
        self.exprs.clear();
        let mut pre = vec![Vec::new(); g.networks.len()];
        for (n, net) in g.networks.iter().enumerate() {
            for &i in net {
                let node = &g.nodes[i];
                let (text, span, contact) = match &node.kind {
                    Kind::Contact { var, var_span, .. } => (var, *var_span, true),
                    Kind::InVar {
                        expr, expr_span, ..
                    } => (expr, *expr_span, false),
                    _ => continue,
                };
                if text.trim().is_empty() || values::operand(text, span).is_some() {
                    continue;
                }
                let mut local = diagnostics::Diagnostics::new();
                let Some(e) = st::parse_expression(ctx.file, text, span.start as usize, &mut local)
                else {
                    continue; // not ST either: E3011 when the node is built
                };
                if local.has_errors() {
                    continue;
                }
                let decls = crate::st_body::declarations(self.index);
                let pou_ast = self.pou_ast;
                let low = self
                    .st
                    .get_or_insert_with(|| PouLowering::new(decls, pou_ast).with_prefix("_STX_"));
                let ty = if contact {
                    Some(bool_ty(span))
                } else {
                    low.expression_type(&e)
                };
                let mut code = if contact {
                    low.condition(&e, &mut local)
                } else {
                    low.expression(&e, &mut local)
                };
                let at = Where {
                    pou: self.pou.clone(),
                    network: Some(n + 1),
                    local_id: Some(node.id.to_string()),
                };
                let failed = local.has_errors();
                for d in local {
                    let d = if d.xml.is_none() {
                        d.with_xml(at.xml())
                    } else {
                        d
                    };
                    ctx.report(d);
                }
                let Some(ty) = ty.filter(|_| !failed) else {
                    if !failed {
                        ctx.report(
                            Diagnostic::error(
                                code::E3011,
                                format!("the type of `{}` cannot be told", shown(text)),
                            )
                            .at(span)
                            .with_hint("write a variable here, or convert the expression to a type (`INT_TO_REAL(...)`)")
                            .with_xml(at.xml()),
                        );
                    }
                    self.exprs.insert(i, None);
                    continue;
                };
                let name = format!("__expr_{}", sanitize(&node.id));
                self.declare_hidden(&name, ty, self.body_span);
                let Some(var) = values::var_ref(&name, span) else {
                    continue;
                };
                code.push(simple(Op::St, false, Some(Operand::Var(var.clone())), span));
                pre[n].extend(code);
                self.exprs.insert(i, Some(Operand::Var(var)));
            }
        }
        pre
    }
}

impl NetLowering<'_, '_> {
    /// A CODESYS EXECUTE box: its ST statements (lowered by the ST front end, errors located at the
    /// box) run when EN is TRUE (always without EN); ENO is EN.
    pub(super) fn build_execute(
        &mut self,
        ctx: &mut Ctx,
        i: usize,
        text: &crate::il_body::EmbeddedText,
        inputs: &[InPin],
        outputs: &[graph::OutPin],
    ) {
        let node = &self.g.nodes[i];
        let span = node.span;
        let Some(en) = self.only_en(ctx, i, inputs, |pin| {
            (
                format!("EXECUTE has no input `{pin}`"),
                "an EXECUTE box takes only EN (and gives ENO); its ST statements read the variables themselves",
            )
        }) else {
            return;
        };
        let mut local = diagnostics::Diagnostics::new();
        // `&gt;=` is `>` and padding: join the operator again
        let mut src = text.text.clone();
        crate::st_body::join_split_operators(&mut src, text.base, ctx.xml);
        let stmts = st::parse_statements(ctx.file, &src, text.base, &mut local);
        let decls = crate::st_body::declarations(self.pou.index);
        let pou_ast = self.pou.pou_ast;
        // `Act();` calls an action of the POU: `CAL Act`, which the caller inlines
        let actions: Vec<(il_frontend::ast::Ident, Vec<IlStmt>)> = if self.pou.calls_actions {
            self.pou
                .index
                .pous
                .get(&self.pou.pou.to_ascii_uppercase())
                .map(|sig| sig.actions.as_slice())
                .unwrap_or_default()
                .iter()
                .map(|a| {
                    let name = il_frontend::ast::Ident::new(a.as_str(), span);
                    let call = IlStmt::Instr(il_frontend::ast::Instruction {
                        kind: il_frontend::ast::InstrKind::Call {
                            cond: il_frontend::ast::Condition::Always,
                            instance: Box::new(il_frontend::ast::VarRef {
                                base: name.clone(),
                                accessors: Default::default(),
                                span,
                            }),
                            args: il_frontend::ast::CallArgs::None,
                        },
                        span,
                    });
                    (name, vec![call])
                })
                .collect()
        } else {
            Vec::new()
        };
        let low = self
            .pou
            .st
            .get_or_insert_with(|| PouLowering::new(decls, pou_ast).with_prefix("_STX_"));
        if !actions.is_empty() {
            low.set_il_actions(actions);
        }
        let code = low.statements(&stmts, &mut local);
        let failed = local.has_errors();
        let at = self.at(i).xml();
        for d in local {
            let d = if d.xml.is_none() {
                d.with_xml(at.clone())
            } else {
                d
            };
            ctx.report(d);
        }
        if failed {
            self.poisoned.insert(i);
            return;
        }
        self.push_action(Action::Execute {
            code,
            en,
            skip_label: format!("__skip_{}", sanitize(&node.id)),
            span,
        });
        self.eno_outputs(i, en, outputs);
    }

    /// The EN of a box that takes only EN (an EXECUTE box, an action call): `Some(None)` without
    /// EN, `None` when a wired input failed to lower (the box is poisoned). Any other input gets
    /// E3018 with the message and hint `other` gives for its name.
    pub(super) fn only_en(
        &mut self,
        ctx: &mut Ctx,
        i: usize,
        inputs: &[InPin],
        other: impl Fn(&str) -> (String, &'static str),
    ) -> Option<Option<ValId>> {
        let mut en = None;
        for pin in inputs {
            let Some(v) = self.input_val(ctx, &pin.wires, i) else {
                if !pin.wires.is_empty() {
                    self.poisoned.insert(i);
                    return None;
                }
                continue;
            };
            if !pin.name.eq_ignore_ascii_case("EN") {
                let (msg, hint) = other(&pin.name);
                let d = self
                    .diag(ctx, code::E3018, i, pin.span, msg)
                    .with_hint(hint);
                ctx.report(d);
                continue;
            }
            let v = if pin.negated {
                self.val(Val::Not(v), pin.span)
            } else {
                v
            };
            self.check_bool(ctx, i, v, pin.span, format_args!("EN input"));
            en = Some(v);
        }
        Some(en)
    }

    /// The outputs of a box whose ENO is its EN (an EXECUTE box, an action call): every output
    /// pin, and the box's power flow when it has none, is EN (TRUE without EN).
    pub(super) fn eno_outputs(&mut self, i: usize, en: Option<ValId>, outputs: &[graph::OutPin]) {
        let span = self.g.nodes[i].span;
        let eno = en.unwrap_or_else(|| self.val(Val::Const(true), span));
        for out in outputs {
            let v = if out.negated {
                self.val(Val::Not(eno), span)
            } else {
                eno
            };
            self.pin_vals.insert((i, out.name.to_ascii_uppercase()), v);
        }
        if outputs.is_empty() {
            self.pin_vals.insert((i, String::new()), eno);
        }
    }
}
