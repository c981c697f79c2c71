//! The blocks of a graphical body, for [`super`]: a function, function block, operator or motion block
//! box ([`NetLowering::build_block`]), its pins typed against the block's declaration, its EN/ENO, and
//! the result type of an overloaded or literal-typed function; a box named after an action of the POU
//! or of an FB instance (CODESYS), which becomes `CAL Act` / `CAL inst.Act` behind its EN.
//!
//! Input: one block node of the network being lowered and the values of its input wires. Output: the
//! block's [`Action`] and the values of its outputs in the network's value table. Invariants: every
//! diagnostic is located at the block (POU, network, localId); a block that cannot be typed is
//! reported once and gives no action.

use super::*;

impl NetLowering<'_, '_> {
    pub(super) fn build_block(&mut self, ctx: &mut Ctx, i: usize) {
        let g = self.g;
        let node = &g.nodes[i];
        let span = node.span;
        let Kind::Block(b) = &node.kind else {
            return;
        };
        let graph::Block {
            type_name,
            type_span,
            instance,
            inputs,
            outputs,
            code,
        } = &**b;
        if let Some(code) = code {
            self.build_execute(ctx, i, code, inputs, outputs);
            return;
        }
        if type_name.is_empty() {
            let d = self.diag(ctx, code::E3013, i, span, "block without a typeName".into());
            ctx.report(d);
            self.poisoned.insert(i);
            return;
        }
        let Some(bt) = self.block_type(type_name) else {
            if let Some(callee) = self.action_box(type_name, *type_span, instance.as_ref()) {
                self.build_action_call(ctx, i, callee, inputs, outputs);
                return;
            }
            if self
                .pou
                .index
                .missing_types
                .contains(&type_name.to_ascii_uppercase())
            {
                // the instance's type is missing from the file: E3009 named it with every use
                self.poisoned.insert(i);
                return;
            }
            let is_program = self
                .pou
                .index
                .pous
                .contains_key(&type_name.to_ascii_uppercase());
            let d = if is_program {
                self.diag(
                    ctx,
                    code::E3012,
                    i,
                    *type_span,
                    format!("program `{type_name}` cannot be called as a block"),
                )
            } else {
                self.diag(
                    ctx,
                    code::E3007,
                    i,
                    *type_span,
                    format!("unknown block type `{type_name}`"),
                )
                .with_hint("not a standard function or function block, not MC_*, not a POU of this project")
            };
            ctx.report(d);
            self.poisoned.insert(i);
            return;
        };
        // Inputs.
        let mut en = None;
        let mut args: Vec<(Ident, ValId)> = Vec::new();
        let mut unconnected: Vec<&InPin> = Vec::new();
        for pin in inputs {
            let v = self.input_val(ctx, &pin.wires, i);
            let v = match (v, &bt) {
                // an open input of a standard function takes its type's initial value, 0 or FALSE
                // (IEC 61131-3 ed. 3, 6.6.1.2: an input a call leaves out; matiec compiles
                // Beremiz's open `MOVE.IN` so), with a warning
                (None, BlockType::StdFn(_))
                    if pin.wires.is_empty() && !pin.name.eq_ignore_ascii_case("EN") =>
                {
                    let bool_pin = matches!(
                        Self::pin_type(&bt, &pin.name, pin.span),
                        Some(Some(t)) if type_text(&Ty::Known(t.clone())) == "BOOL"
                    );
                    let d = Diagnostic::warning(
                        code::W3005,
                        format!(
                            "input `{}` of function {type_name} is not connected: it takes {}",
                            pin.name,
                            if bool_pin { "FALSE" } else { "0" }
                        ),
                    )
                    .at(pin.span)
                    .with_xml(self.at(i).xml())
                    .with_hint("connect the input, or wire the constant it should have");
                    ctx.report(d);
                    Some(if bool_pin {
                        self.val(Val::Const(false), pin.span)
                    } else {
                        self.val(
                            Val::Leaf {
                                op: Operand::literal(Literal {
                                    kind: LiteralKind::Int(0),
                                    type_prefix: None,
                                    span: pin.span,
                                }),
                                neg: false,
                            },
                            pin.span,
                        )
                    })
                }
                (v, _) => v,
            };
            let Some(mut v) = v else {
                if !pin.wires.is_empty() {
                    // Fed only by elements that could not be lowered (already reported); the
                    // box's own instance is still checked (its E3016 is a cause of its own)
                    if matches!(
                        bt,
                        BlockType::UserFb(_) | BlockType::StdFb(_) | BlockType::Motion
                    ) {
                        let _ = self.fb_instance(ctx, i, span, type_name, instance.as_ref());
                    }
                    self.poisoned.insert(i);
                    return;
                }
                if !pin.name.eq_ignore_ascii_case("EN") {
                    unconnected.push(pin);
                }
                continue;
            };
            if pin.negated {
                v = self.val(Val::Not(v), pin.span);
            }
            if pin.edge != Edge::None {
                let name = format!("__trig_{}_{}", sanitize(&node.id), sanitize(&pin.name));
                v = self.trig(name, pin.edge == Edge::Falling, v, pin.span);
            }
            if pin.name.eq_ignore_ascii_case("EN") {
                self.check_bool(ctx, i, v, pin.span, format_args!("EN input"));
                en = Some(v);
                continue;
            }
            // CODESYS/TwinCAT `RS.SET` is IEC `RS.S` (a user block of that name keeps its pins)
            let pin_name: &str = match &bt {
                BlockType::StdFb(_) => {
                    catalogue::vendor_pin_alias(type_name, &pin.name).unwrap_or(&pin.name)
                }
                _ => &pin.name,
            };
            match Self::pin_type(&bt, pin_name, pin.span) {
                None => {
                    let d = self.diag(
                        ctx,
                        code::E3018,
                        i,
                        pin.span,
                        format!("{type_name} has no input `{}`", pin.name),
                    );
                    ctx.report(d);
                    continue;
                }
                Some(Some(expected)) => {
                    let to = Ty::Known(expected);
                    // `0` and `1` are BOOL literals too (IEC 61131-3, boolean literals)
                    if type_text(&to) == "BOOL" {
                        let bit = match &self.vals[v] {
                            Val::Leaf {
                                op: Operand::Literal(l),
                                neg: false,
                            } => match **l {
                                Literal {
                                    kind: LiteralKind::Int(n @ (0 | 1)),
                                    type_prefix: None,
                                    ..
                                } => Some(n),
                                _ => None,
                            },
                            _ => None,
                        };
                        if let Some(n) = bit {
                            let b = n == 1;
                            v = self.val(Val::Const(b), self.spans[v]);
                        }
                    }
                    let from = self.ty(v);
                    if let (Some(f), Some(t)) = (family_of(&from), family_of(&to)) {
                        if !catalogue::compatible(f, t) {
                            let d = self.diag(
                                ctx,
                                code::E3008,
                                i,
                                pin.span,
                                format!(
                                    "input `{}` of {type_name} is {}, but is driven by {}",
                                    pin.name,
                                    type_text(&to),
                                    type_text(&from)
                                ),
                            )
                            .with_hint(if type_text(&to) == "BOOL" {
                                "compare the value first (`GT`, `NE`, ...) to get a BOOL"
                            } else {
                                "insert a conversion block (`INT_TO_REAL`, ...) before this input"
                            });
                            ctx.report(d);
                        }
                    }
                }
                Some(None) => {}
            }
            args.push((Ident::new(pin_name, pin.span), v));
        }
        let eno = match en {
            Some(e) => e,
            None => self.val(Val::Const(true), span),
        };
        match bt {
            BlockType::UserFb(_) | BlockType::StdFb(_) | BlockType::Motion => {
                let Some(inst) = self.fb_instance(ctx, i, span, type_name, instance.as_ref())
                else {
                    return;
                };
                self.push_action(Action::Fb {
                    inst: inst.clone(),
                    args: args.clone(),
                    en,
                    // EN is the call's `EN :=` for standard and user blocks alike, so a box whose
                    // EN is FALSE leaves the instance's ENO FALSE (IEC 61131-3 ed. 2 2.5.1.2, ed. 3
                    // 6.6.1.6: EN FALSE, the body is not executed and ENO is FALSE; matiec's FB bodies
                    // start `if (!EN) { ENO = FALSE; return; }`), as the same call in ST does: a
                    // contact on `inst.ENO` then reads FALSE (before round 30: TRUE from the last
                    // call that ran, `tests/tests/ld_r30_run.rs`)
                    en_arg: matches!(bt, BlockType::StdFb(_) | BlockType::UserFb(_)),
                    span,
                });
                for out in outputs {
                    let key = out.name.to_ascii_uppercase();
                    let v = if key == "ENO" && matches!(bt, BlockType::UserFb(_)) {
                        // a user block's ENO pin is its instance's ENO after the call: FALSE
                        // when EN is FALSE, else TRUE unless the body wrote `ENO := FALSE` (IEC
                        // 61131-3 ed. 3 6.6.1.6, ed. 2 2.5.1.2: ENO is an output of the block;
                        // matiec's FB bodies set ENO TRUE then run the body, and Beremiz reads
                        // the pin as `inst.ENO`). Before round 31 it was EN
                        // (`tests/tests/ld_r31_run.rs`)
                        self.val(
                            Val::Leaf {
                                op: field_operand(&inst, "ENO", span),
                                neg: false,
                            },
                            span,
                        )
                    } else if key == "ENO" {
                        eno
                    } else if let Some((_, v)) = args.iter().find(|(n, _)| n.is(&out.name)) {
                        // The output side of an in-out pin carries the connected variable.
                        *v
                    } else {
                        self.val(
                            Val::Leaf {
                                op: field_operand(&inst, &out.name, span),
                                neg: false,
                            },
                            span,
                        )
                    };
                    let v = if out.negated {
                        self.val(Val::Not(v), span)
                    } else {
                        v
                    };
                    self.pin_vals.insert((i, key), v);
                }
            }
            BlockType::UserFn(_) | BlockType::StdFn(_) => {
                if let Some(pin) = unconnected.first() {
                    let d = self.diag(
                        ctx,
                        code::E3013,
                        i,
                        pin.span,
                        format!(
                            "input `{}` of function {type_name} is not connected",
                            pin.name
                        ),
                    );
                    ctx.report(d);
                    self.poisoned.insert(i);
                    return;
                }
                let (form, result_ty) = match &bt {
                    BlockType::UserFn(sig) => (FuncForm::Formal, sig.ret.clone()),
                    BlockType::StdFn(f) => {
                        let form = match f.operator {
                            Some(op) => FuncForm::Operator(op),
                            None => FuncForm::NonFormal,
                        };
                        let ty = match f.rule {
                            ResultRule::Fixed(t) => Some(named_type(t, span)),
                            ResultRule::SameAsInputs => self
                                .common_type(&args, f.selectors, span)
                                .map(|t| self.literal_result_type(i, &args, f.selectors, t)),
                        };
                        (form, ty)
                    }
                    _ => (FuncForm::Formal, None),
                };
                let arity_ok = match &form {
                    FuncForm::Operator(OperatorBlock::Compare(_)) => args.len() >= 2,
                    FuncForm::Operator(OperatorBlock::Not | OperatorBlock::Move) => args.len() == 1,
                    FuncForm::Operator(_) => args.len() >= 2,
                    _ => true,
                };
                if !arity_ok {
                    let d = self.diag(
                        ctx,
                        code::E3012,
                        i,
                        span,
                        format!("{type_name} with {} inputs is not supported", args.len()),
                    );
                    ctx.report(d);
                    self.poisoned.insert(i);
                    return;
                }
                let Some(result_ty) = result_ty else {
                    // inputs that are undeclared names: that is the error, not the type
                    let mut undeclared = false;
                    for (_, v) in &args {
                        // a negated input (`negated="true"`) is the variable under its NOT
                        let v = match &self.vals[*v] {
                            Val::Not(inner) => *inner,
                            _ => *v,
                        };
                        if let Val::Leaf {
                            op: Operand::Var(r),
                            ..
                        } = &self.vals[v]
                        {
                            // (a hidden name, `__loop_<localId>` of a loop of wires, is no
                            // user's: E3017 below says what is missing)
                            if self.pou.var_type(r).is_none() && !r.base.name.starts_with("__") {
                                undeclared = true;
                                let d = self
                                    .diag(
                                        ctx,
                                        code::E1001,
                                        i,
                                        r.base.span,
                                        format!("undeclared name `{}`", r.base.name),
                                    )
                                    .with_hint(format!(
                                        "declare `{}` in a VAR block of `{}` (or VAR_EXTERNAL for a global)",
                                        r.base.name, self.pou.pou
                                    ));
                                ctx.report(d);
                            }
                        }
                    }
                    if undeclared {
                        self.poisoned.insert(i);
                        return;
                    }
                    let d = self.diag(
                        ctx,
                        code::E3017,
                        i,
                        span,
                        format!(
                            "cannot tell the result type of {type_name}: no input has a known type"
                        ),
                    );
                    ctx.report(d);
                    self.poisoned.insert(i);
                    return;
                };
                // With EN, a skipped call passes on the initial value of its result type: a
                // function has no memory (IEC 61131-3 2.5.1: the same inputs give the same result),
                // as matiec and Schneider's EN/ENO rule give it, and as ladderc's ST calls with EN
                // do. A variable wired straight to the result is not written at all (see
                // `NetLowering::en_results`). The result and that never-written initial value get
                // their own hidden variables.
                let (result, initial) = if en.is_none() && self.feedback_sources.contains(&i) {
                    // read back by an earlier box of a loop of wires (`lower_feedback`): kept
                    let name = self.feedback_var(i);
                    self.pou.declare_hidden(&name, result_ty.clone(), span);
                    (var_operand(&name, span), None)
                } else if en.is_some() {
                    let name = format!("__out_{}", sanitize(&node.id));
                    self.pou.declare_hidden(&name, result_ty.clone(), span);
                    let init = format!("__init_{}", sanitize(&node.id));
                    self.pou.declare_hidden(&init, result_ty.clone(), span);
                    (var_operand(&name, span), Some(var_operand(&init, span)))
                } else {
                    (self.alloc_temp(&result_ty), None)
                };
                // A user function's ENO pin: the ENO its body leaves (TRUE unless it writes
                // `ENO := FALSE`; FALSE when EN is FALSE), stored by the call as Beremiz generates
                // it (`F42_OUT := F(EN := .., ENO => F42_ENO, ..)`); it also guards the writes of
                // the result (see `NetLowering::en_results`). A standard function's ENO is its EN.
                let eno_out = match bt {
                    BlockType::UserFn(_)
                        if en.is_some()
                            || outputs.iter().any(|o| o.name.eq_ignore_ascii_case("ENO")) =>
                    {
                        let name = format!("__eno_{}", sanitize(&node.id));
                        self.pou.declare_hidden(&name, bool_ty(span), span);
                        Some(var_operand(&name, span))
                    }
                    _ => None,
                };
                let eno = match &eno_out {
                    Some(op) => self.val(
                        Val::Leaf {
                            op: op.clone(),
                            neg: false,
                        },
                        span,
                    ),
                    None => eno,
                };
                self.push_action(Action::Func {
                    name: Ident::new(&**type_name, *type_span),
                    form,
                    args,
                    en,
                    result: result.clone(),
                    initial,
                    eno: eno_out,
                    skip_label: format!("__skip_{}", sanitize(&node.id)),
                    span,
                });
                let rv = self.val(
                    Val::Leaf {
                        op: result,
                        neg: false,
                    },
                    span,
                );
                for out in outputs {
                    let key = out.name.to_ascii_uppercase();
                    let v = if key == "ENO" { eno } else { rv };
                    let v = if out.negated {
                        self.val(Val::Not(v), span)
                    } else {
                        v
                    };
                    if key != "ENO" && en.is_some() {
                        self.en_results.insert(v, eno);
                    }
                    self.pin_vals.insert((i, key), v);
                }
                if outputs.is_empty() {
                    if en.is_some() {
                        self.en_results.insert(rv, eno);
                    }
                    self.pin_vals.insert((i, String::new()), rv);
                }
            }
        }
    }

    /// The result type of a generic function whose inputs are all untyped literals (`fallback`: DINT
    /// or LREAL) takes the type of the variable its output is wired to, as IEC 61131-3 types a literal
    /// by its context: `5` into MOVE into an INT (or a subrange of INT) is INT, not DINT.
    pub(super) fn literal_result_type(
        &self,
        block: usize,
        args: &[(Ident, ValId)],
        skip: usize,
        fallback: TypeRef,
    ) -> TypeRef {
        let tys: Vec<Ty> = args.iter().skip(skip).map(|(_, v)| self.ty(*v)).collect();
        if tys.iter().any(|t| !matches!(t, Ty::WeakInt | Ty::WeakReal)) {
            return fallback;
        }
        let real = tys.iter().any(|t| matches!(t, Ty::WeakReal));
        // the variables the output reaches, directly or through the data inputs of further generic
        // functions (`SEL(G, 9, 10)` into `SEL(G2, _, 8)` into an INT: INT)
        let mut stack = vec![block];
        let mut seen = HashSet::default();
        while let Some(b) = stack.pop() {
            if !seen.insert(b) {
                continue;
            }
            for (ni, n) in self.g.nodes.iter().enumerate() {
                match &n.kind {
                    Kind::OutVar {
                        expr, expr_span, ..
                    }
                    | Kind::InOutVar {
                        expr, expr_span, ..
                    } => {
                        if !n.input.iter().any(|w| w.from == b) {
                            continue;
                        }
                        let Some(op) = values::operand(expr, *expr_span) else {
                            continue;
                        };
                        if let Ty::Known(t) = self.operand_ty(&op) {
                            let dest_real =
                                matches!(&t, TypeRef::Named(n) if n.is("REAL") || n.is("LREAL"));
                            if !real || dest_real {
                                return t;
                            }
                        }
                    }
                    Kind::Block(blk) => {
                        let (type_name, inputs) = (&blk.type_name, &blk.inputs);
                        let Some(f) = catalogue::std_function(type_name) else {
                            continue;
                        };
                        let generic = matches!(f.rule, ResultRule::SameAsInputs);
                        let feeds_data = inputs
                            .iter()
                            .skip(f.selectors)
                            .any(|p| p.wires.iter().any(|w| w.from == b));
                        if generic && feeds_data {
                            stack.push(ni);
                        }
                    }
                    _ => {}
                }
            }
        }
        fallback
    }

    /// The result type of a generic function: the first input with a known type, else the literal kind.
    pub(super) fn common_type(
        &self,
        args: &[(Ident, ValId)],
        skip: usize,
        span: Span,
    ) -> Option<TypeRef> {
        let tys: Vec<Ty> = args.iter().skip(skip).map(|(_, v)| self.ty(*v)).collect();
        if let Some(Ty::Known(t)) = tys.iter().find(|t| matches!(t, Ty::Known(_))) {
            return Some(t.clone());
        }
        if tys.iter().any(|t| matches!(t, Ty::WeakReal)) {
            return Some(TypeRef::Named(Ident::new("LREAL", span)));
        }
        if tys.iter().any(|t| matches!(t, Ty::WeakInt)) {
            return Some(TypeRef::Named(Ident::new("DINT", span)));
        }
        None
    }

    /// The action a box calls: CODESYS draws the call of an action in LD and FBD as a box named
    /// after it. `Act` is an action of this POU; `inst.Act` (or a box of type `Act` with instance
    /// `inst`) an action of the function block instance `inst`. `None` when the name is no action.
    fn action_box(
        &self,
        type_name: &str,
        type_span: Span,
        instance: Option<&(std::borrow::Cow<'_, str>, Span)>,
    ) -> Option<VarRef> {
        if !self.pou.calls_actions {
            return None;
        }
        let index = self.pou.index;
        let has = |pou: &str, action: &str| {
            index
                .pous
                .get(&pou.to_ascii_uppercase())
                .is_some_and(|s| s.actions.iter().any(|a| a.eq_ignore_ascii_case(action)))
        };
        let instance_has = |inst: &VarRef, action: &str| match self.pou.var_type(inst) {
            Some(TypeRef::Named(fb)) => has(&fb.name, action),
            _ => false,
        };
        let callee = values::var_ref(type_name, type_span)?;
        match callee.accessors.as_slice() {
            [] => {
                if let Some((inst, inst_span)) = instance {
                    let mut r = values::var_ref(inst, *inst_span)?;
                    if !instance_has(&r, type_name) {
                        return None;
                    }
                    r.accessors
                        .push(Accessor::Field(Ident::new(type_name, type_span)));
                    return Some(r);
                }
                has(&self.pou.pou, type_name).then_some(callee)
            }
            [.., Accessor::Field(action)] => {
                let mut inst = callee.clone();
                inst.accessors.pop();
                instance_has(&inst, &action.name).then_some(callee)
            }
            _ => None,
        }
    }

    /// A box that calls an action (see [`Self::action_box`]): the action runs where the box sits
    /// when its EN is TRUE (always without EN); ENO, or the box's one output, is EN. A box has no
    /// other input (E3018).
    fn build_action_call(
        &mut self,
        ctx: &mut Ctx,
        i: usize,
        callee: VarRef,
        inputs: &[InPin],
        outputs: &[graph::OutPin],
    ) {
        let node = &self.g.nodes[i];
        let span = node.span;
        let Some(en) = self.only_en(ctx, i, inputs, |pin| {
            (
                format!(
                    "the call of action `{}` has no input `{pin}`",
                    shown_callee(&callee)
                ),
                "an action box takes only EN (and gives ENO); set the block's inputs before the call",
            )
        }) else {
            return;
        };
        let call = IlStmt::Instr(Instruction {
            kind: InstrKind::Call {
                cond: Condition::Always,
                instance: Box::new(callee),
                args: CallArgs::None,
            },
            span,
        });
        self.push_action(Action::Execute {
            code: vec![call],
            en,
            skip_label: format!("__skip_{}", sanitize(&node.id)),
            span,
        });
        self.eno_outputs(i, en, outputs);
    }
}

/// `Act` or `inst.Act`, as the engineer wrote it.
fn shown_callee(r: &VarRef) -> String {
    let mut s = r.base.name.clone();
    for a in r.accessors.iter() {
        if let Accessor::Field(f) = a {
            s.push('.');
            s.push_str(&f.name);
        }
    }
    s
}

impl NetLowering<'_, '_> {
    /// The declared instance a function block box `i` calls, or `None` after its E3016 (no
    /// `instanceName`, or one the POU does not declare as a function block); the box is poisoned
    /// then. Checked also for a box whose inputs could not be lowered, so that each box's own
    /// error comes out in the same run as its inputs' (before issue #13's round 31 a second box
    /// fed by the first's output showed its E3016 only after the first was fixed).
    pub(super) fn fb_instance(
        &mut self,
        ctx: &mut Ctx,
        i: usize,
        span: Span,
        type_name: &str,
        instance: Option<&(graph::Text<'_>, Span)>,
    ) -> Option<VarRef> {
        let Some((inst_name, inst_span)) = instance else {
            let d = self.diag(
                ctx,
                code::E3016,
                i,
                span,
                format!("function block {type_name} has no instance name"),
            );
            ctx.report(d);
            self.poisoned.insert(i);
            return None;
        };
        match values::var_ref(inst_name, *inst_span) {
            Some(r)
                if self
                    .pou
                    .var_type(&r)
                    .is_some_and(|t| self.pou.is_fb_type(&t)) =>
            {
                Some(r)
            }
            _ => {
                let d = self
                    .diag(
                        ctx,
                        code::E3016,
                        i,
                        *inst_span,
                        format!(
                            "instance `{inst_name}` of {type_name} is not declared in `{}`",
                            self.pou.pou
                        ),
                    )
                    .with_hint(format!(
                        "declare `{inst_name} : {type_name};` in the POU's variables"
                    ));
                ctx.report(d);
                self.poisoned.insert(i);
                None
            }
        }
    }
}
