//! ST statements and expressions to IL instructions.
//!
//! Input: [`super::ast`] statements or expressions of one POU, the POU's declarations and the
//! program's [`Declarations`]. Output: `Vec<IlStmt>` and the VAR_TEMP temporaries they use.
//! Invariants:
//! - an expression is lowered where the current result (CR) is free: its code starts with a load (or
//!   with the code of temporaries, then a load), and leaves the value in the CR; a right operand that
//!   is not a plain operand becomes a deferred operator `ADD( ... )`, whose nested list has its own CR;
//!   call arguments and array indices that are not plain operands are computed first into typed
//!   temporaries `_ST_T<n>` (IEC evaluates both sides of AND/OR: no short-circuit; CODESYS's
//!   `AND_THEN`/`OR_ELSE` are computed first into BOOL temporaries, see `lower/short_circuit.rs`);
//! - control flow becomes `JMP`/`JMPC`/`JMPCN` to labels `_ST_<WHAT><n>` unique in the POU;
//! - every instruction carries the span of the ST construct it comes from;
//! - a statement whose text had a syntax error (already reported) produces no code.

use super::ast::*;
use super::infer::{named, Env, Ty, TypeCache};
use super::types::Declarations;
use crate::ast::{
    self as il, CallArgs, Condition, FormalArg, Ident, IlStmt, InstrKind, Instruction, Literal,
    LiteralKind, Op, Operand, Pou, PouKind, TypeRef, VarBlock, VarDecl, VarKind, VarRef,
};
use crate::sema::stdlib::{self, ParamTy, Ret};
use crate::Span;
use diagnostics::{code, Diagnostic, Diagnostics};
use std::cell::RefCell;
use std::collections::HashMap;

mod call_chain;
mod case_labels;
mod dynamic_memory;
mod for_control;
pub(crate) mod global_ns;
pub(crate) use global_ns::{GLOBAL_NS, GLOBAL_NS_SEEN};
mod memory;
pub(super) mod method_flow;
pub use method_flow::{method_call_expr, METHOD_CALL};
pub(crate) mod method_in_out;
mod mixed_args;
mod own_name;
mod short_circuit;
mod void_result;

/// What the hidden labels and temporaries of `pou`'s lowering start with: `_ST_`, but `_ST_INIT_`
/// and `_ST_EXIT_` in a B&R program's `PROGRAM _INIT` and `_EXIT`, which ladderc joins with the
/// folder's `_CYCLIC` into one POU (`ladderc`'s `br_programs`): a loop in both parts is no label
/// or temporary defined twice (before round 25: E1010 `_ST_FOR1` defined twice).
fn hidden_prefix(pou: &Pou) -> &'static str {
    match pou.kind {
        PouKind::Program if pou.name.name.eq_ignore_ascii_case("_INIT") => "_ST_INIT_",
        PouKind::Program if pou.name.name.eq_ignore_ascii_case("_EXIT") => "_ST_EXIT_",
        _ => "_ST_",
    }
}

/// Labels of the innermost loop, for EXIT and CONTINUE.
struct LoopLabels {
    exit: Ident,
    cont: Ident,
}

/// The lowering state of one POU: shared by every ST snippet lowered into that POU, so labels and
/// temporaries stay unique.
pub struct PouLowering<'d> {
    decls: &'d Declarations,
    pou: Ident,
    kind: PouKind,
    ret: Option<TypeRef>,
    vars: HashMap<String, TypeRef>,
    temps: Vec<VarDecl>,
    next_label: u32,
    /// Whether a jump or label in ST was reported in this POU (W1426, once).
    st_jump_noted: bool,
    /// What the names of labels and temporaries start with (`_ST_`; see [`Self::with_prefix`]).
    prefix: &'static str,
    loops: Vec<LoopLabels>,
    /// Set when an expression contained a syntax error (reported by the parser).
    poisoned: bool,
    /// Results of methods called on a property's value (`a.Child.Depth()`, `call_chain`): the
    /// text the parser reads the result by (`A.CHILD.__M_DEPTH`) and the temporary holding it.
    property_results: Vec<(String, Ident)>,
    /// The type an untyped literal loaded first by the next [`Self::value`] should get (`LD REAL#2.0`
    /// where the context is REAL), so IL sema does not default it to DINT/LREAL.
    lit_hint: Option<TypeRef>,
    /// The POU's actions (CODESYS: a program's or FB's `<actions>` with ST bodies), by upper-case
    /// name: a call statement `Act();` lowers the action's statements in its place.
    actions: HashMap<String, std::rc::Rc<Vec<Stmt>>>,
    /// The POU's actions already in IL (PLCopen XML actions written in IL, LD or FBD), by upper-case
    /// name: a call statement `Act();` puts a copy of them in its place
    /// ([`crate::actions::instantiate`]).
    il_actions: HashMap<String, std::rc::Rc<Vec<IlStmt>>>,
    /// Actions being inlined (a call of one inside itself is reported, not expanded forever).
    inlining: Vec<String>,
    /// The methods of the function block being lowered (or of the block of the method being
    /// lowered), by upper-case name: `M(...)` inside the block is a call of its own method.
    methods: HashMap<String, super::types::MethodSig>,
    /// Whether some function block of the program has a PROPERTY (its uses are rewritten into
    /// calls of its accessors before a statement is lowered: `property::rewrite`).
    properties: bool,
    /// Some FUNCTION of the project has an ANY input (`any_inputs`): its calls and uses are
    /// rewritten before they are lowered.
    any_inputs: bool,
    /// How many times in a row the ANY-input rewrite has rewritten the statement being lowered
    /// (bounded: a rewrite that never settles is one E1068, not an endless recursion).
    any_passes: u8,
    /// Some POU of the project has a variable-length in-out (`varlen`): its calls and uses are
    /// rewritten.
    varlen: bool,
    /// Types of the subexpressions of the trees being lowered (so lowering a chain of n operators
    /// types each node once, not n times). Cleared by every public entry point and after lowering a
    /// tree built here, so no entry outlives the node it describes.
    types: RefCell<TypeCache>,
    /// Nesting of deferred operators' lists being lowered (`AND( ...`): 0 where jumps may stand.
    nested: u32,
    /// While set, a `REFERENCE TO` variable stands for itself, not for the variable it refers to
    /// (`r REF= x`, `__ISVALIDREF(r)`, see [`super::refs`]).
    raw_refs: bool,
    /// Whether the POU or the program declares a `REFERENCE TO` anywhere: only then are accesses
    /// looked at for the `^` they leave out.
    reference_to: bool,
    /// Whether W1422 (positional then formal arguments) was reported for this POU.
    mixed_args_reported: bool,
    /// Set while the arguments of a call whose callee is not known are lowered: their mix of
    /// formal and non-formal arguments is no E3106 (the callee's own error says what is wrong).
    unknown_callee: bool,
    /// Set while the arguments of a call are lowered: the callee's `VAR_IN_OUT CONSTANT`
    /// parameters (upper case), which take a value that is not a variable through a temporary.
    constant_in_outs: Vec<String>,
    /// Set with [`Self::constant_in_outs`]: the callee's name and its other VAR_IN_OUT parameters
    /// (upper case), which need a variable (E1088).
    plain_in_outs: (String, Vec<String>),
    /// Set while a call statement's function call is lowered: its value is not used (a FUNCTION
    /// without result type may stand there, nowhere else: E0354).
    result_dropped: bool,
    /// Set once a FUNCTION without result type assigning its own name has been reported
    /// (`void_result`: one E0354 per function).
    missing_result_reported: bool,
    /// A METHOD's `REFERENCE TO` variables (VAR, VAR_TEMP; upper-case) that start again at each
    /// call: `p REF= block.Pmin` into one is call-scoped (see `refs::REF_ASSIGN_CALL`), so it may
    /// refer to the method's VAR_IN_OUT, and sema keeps no reference through it (E0305).
    pub(super) per_call_refs: std::collections::HashSet<String>,
    /// Set while the value of an assignment to one of [`Self::per_call_refs`] is lowered.
    per_call_target: bool,
    /// The hidden variables holding the text of a string literal whose address is taken
    /// (`ADR('text')`, B&R Automation Studio's idiom): one per place in the text, for the whole
    /// run (see [`Self::take_literal_copies`]).
    literal_copies: Vec<VarDecl>,
}

fn instr(kind: InstrKind, span: Span) -> IlStmt {
    IlStmt::Instr(Instruction { kind, span })
}

fn simple(op: Op, negate: bool, operand: Option<Operand>, span: Span) -> IlStmt {
    instr(
        InstrKind::Simple {
            op,
            negate,
            operand,
        },
        span,
    )
}

fn ld(o: Operand, span: Span) -> IlStmt {
    simple(Op::Ld, false, Some(o), span)
}

/// IL's deferred operation `op( operand ... )` spanning `span`: `body` runs on a current result
/// loaded from `operand`, and `op` then combines the current result before with the one `body`
/// leaves.
fn deferred(op: Op, operand: Operand, body: Vec<IlStmt>, span: Span) -> IlStmt {
    instr(
        InstrKind::Deferred {
            op,
            negate: false,
            operand: Some(Box::new(operand)),
            body,
            close: span,
        },
        span,
    )
}

fn jump(cond: Condition, label: &Ident, span: Span) -> IlStmt {
    instr(
        InstrKind::Jump {
            cond,
            label: label.clone(),
        },
        span,
    )
}

fn int_lit(v: i128, span: Span) -> Operand {
    Operand::literal(Literal {
        kind: LiteralKind::Int(v),
        type_prefix: None,
        span,
    })
}

/// `e`, an untyped literal, as a literal of the elementary type `t` (`UINT#256`).
fn prefixed_literal(e: &Expr, t: &TypeRef) -> Option<Operand> {
    let (ExprKind::Literal(l), TypeRef::Named(n)) = (&e.kind, t) else {
        return None;
    };
    let mut l = l.clone();
    l.type_prefix = Some(Ident::new(n.name.clone(), l.span));
    Some(Operand::literal(l))
}

fn var_operand(name: &Ident) -> Operand {
    Operand::Var(VarRef {
        base: name.clone(),
        accessors: Default::default(),
        span: name.span,
    })
}

fn binop(op: BinaryOp) -> Option<Op> {
    Some(match op {
        BinaryOp::Or => Op::Or,
        BinaryOp::Xor => Op::Xor,
        BinaryOp::And => Op::And,
        BinaryOp::Eq => Op::Eq,
        BinaryOp::Ne => Op::Ne,
        BinaryOp::Lt => Op::Lt,
        BinaryOp::Gt => Op::Gt,
        BinaryOp::Le => Op::Le,
        BinaryOp::Ge => Op::Ge,
        BinaryOp::Add => Op::Add,
        BinaryOp::Sub => Op::Sub,
        BinaryOp::Mul => Op::Mul,
        BinaryOp::Div => Op::Div,
        BinaryOp::Mod => Op::Mod,
        // (`value` computes these into temporaries before it gets here: see `short_circuit`)
        BinaryOp::AndThen => Op::And,
        BinaryOp::OrElse => Op::Or,
        BinaryOp::Power => return None,
    })
}

/// How a call in ST resolves.
enum Callee {
    /// A user FUNCTION with its parameters (name, kind, type).
    UserFunction(Vec<(String, VarKind, TypeRef)>),
    Standard(&'static stdlib::StdFunction),
    /// Conversions, time arithmetic, unknown names: called as written, sema checks.
    Other,
}

/// The statements of an action a call statement names.
enum ActionBody {
    /// Written in ST: lowered where it is called.
    St(std::rc::Rc<Vec<Stmt>>),
    /// Already IL (an IL, LD or FBD action): copied where it is called.
    Il(std::rc::Rc<Vec<IlStmt>>),
}

impl<'d> PouLowering<'d> {
    /// The lowering state for `pou`: its declared variables are known, the other names come from `decls`.
    pub fn new(decls: &'d Declarations, pou: &Pou) -> Self {
        let mut vars = HashMap::new();
        for b in &pou.var_blocks {
            for v in &b.vars {
                vars.insert(v.name.key(), v.ty.clone());
            }
        }
        PouLowering {
            decls,
            pou: pou.name.clone(),
            kind: pou.kind,
            ret: pou.return_type.clone(),
            vars,
            temps: Vec::new(),
            next_label: 0,
            st_jump_noted: false,
            prefix: hidden_prefix(pou),
            loops: Vec::new(),
            poisoned: false,
            property_results: Vec::new(),
            lit_hint: None,
            actions: HashMap::new(),
            il_actions: HashMap::new(),
            inlining: Vec::new(),
            methods: decls
                .methods
                .get(&pou.name.key())
                .into_iter()
                .flatten()
                .map(|m| (m.name.to_ascii_uppercase(), m.clone()))
                .collect(),
            properties: decls
                .methods
                .values()
                .flatten()
                .any(|m| super::property::is_accessor(&m.name)),
            any_inputs: super::any_inputs::in_project(decls),
            any_passes: 0,
            varlen: super::varlen::in_project(decls),
            types: RefCell::new(TypeCache::new()),
            nested: 0,
            raw_refs: false,
            mixed_args_reported: false,
            unknown_callee: false,
            constant_in_outs: Vec::new(),
            plain_in_outs: (String::new(), Vec::new()),
            result_dropped: false,
            missing_result_reported: false,
            per_call_refs: Default::default(),
            per_call_target: false,
            literal_copies: Vec::new(),
            reference_to: decls.has_reference_to()
                || pou.var_blocks.iter().any(|b| {
                    b.vars
                        .iter()
                        .any(|v| super::refs::holds_reference_to(&v.ty))
                }),
        }
    }

    /// The POU's actions (name, parsed statements): a call statement `Act();` of one (with no
    /// arguments, where no variable or POU has that name) is lowered as the action's statements.
    pub fn set_actions(&mut self, actions: Vec<(Ident, Vec<Stmt>)>) {
        self.actions = actions
            .into_iter()
            .map(|(n, s)| (n.key(), std::rc::Rc::new(s)))
            .collect();
    }

    /// The POU's actions already lowered to IL (name, statements): a call statement `Act();` of one
    /// (as for [`Self::set_actions`]) is a copy of its statements, with labels of its own.
    pub fn set_il_actions(&mut self, actions: Vec<(Ident, Vec<IlStmt>)>) {
        self.il_actions = actions
            .into_iter()
            .map(|(n, s)| (n.key(), std::rc::Rc::new(s)))
            .collect();
    }

    /// Names labels and temporaries `<prefix><WHAT><n>` and `<prefix>T<n>` instead of `_ST_...`, so a
    /// second lowering of the same POU (ST expressions inside an LD/FBD body) never clashes with the
    /// first.
    pub fn with_prefix(mut self, prefix: &'static str) -> Self {
        self.prefix = prefix;
        self
    }

    /// The type of the value [`Self::expression`] leaves in the current result: the declared type,
    /// DINT / LREAL for an untyped literal, `None` when it cannot be told here.
    pub fn expression_type(&self, e: &Expr) -> Option<TypeRef> {
        self.types.borrow_mut().clear();
        let t = match self.ty(e) {
            Ty::Known(t) => Some(t),
            Ty::IntLit => Some(named("DINT", e.span)),
            Ty::RealLit => Some(named("LREAL", e.span)),
            Ty::Unknown => None,
        };
        self.types.borrow_mut().clear();
        t
    }

    /// Makes a variable the POU will have (but `pou.var_blocks` did not list when [`Self::new`] ran)
    /// visible to the lowering, e.g. SFC step flags.
    pub fn declare(&mut self, name: &str, ty: TypeRef) {
        self.vars.insert(name.to_ascii_uppercase(), ty);
    }

    /// A label no other snippet of this POU uses: `_ST_<WHAT><n>`.
    pub fn fresh_label(&mut self, what: &str, span: Span) -> Ident {
        self.next_label += 1;
        Ident::new(format!("{}{what}{}", self.prefix, self.next_label), span)
    }

    /// Lowers a statement list.
    pub fn statements(&mut self, stmts: &[Stmt], diags: &mut Diagnostics) -> Vec<IlStmt> {
        let mut out = Vec::new();
        self.types.get_mut().clear();
        // `Prog.Act();` inside `Prog`: `Act();` (own_name)
        let stmts = self.own_names_dropped(stmts);
        self.stmt_list(&stmts, &mut out, diags);
        self.types.get_mut().clear();
        out
    }

    /// The action a call statement names: `Act();` without arguments, where `Act` is an action of
    /// the POU and no variable, POU or function result has that name.
    fn action_of(&self, callee: &Place, args: &[Arg]) -> Option<(String, ActionBody)> {
        if (self.actions.is_empty() && self.il_actions.is_empty())
            || !args.is_empty()
            || !callee.accessors.is_empty()
        {
            return None;
        }
        let PlaceBase::Name(n) = &callee.base else {
            return None;
        };
        let body = match self.actions.get(&n.key()) {
            Some(b) => ActionBody::St(b.clone()),
            None => ActionBody::Il(self.il_actions.get(&n.key())?.clone()),
        };
        // the POU's own variables and the POUs hide the action; a global does not (the action
        // is the POU's own name: a TwinCAT program's action `AXES` beside a `qualified_only`
        // list's `axes`)
        let own = self.vars.contains_key(&n.key())
            || (self.kind == PouKind::Function && n.is(&self.pou.name));
        if own || self.decls.pou(&n.name).is_some() {
            return None;
        }
        Some((n.key(), body))
    }

    /// The method of the block a call statement names: `M(...)` (or `THIS^.M(...)`), where `M` is
    /// a method of the block and no variable of the POU has that name.
    fn method_of(&self, callee: &Place) -> Option<&super::types::MethodSig> {
        let PlaceBase::Name(n) = &callee.base else {
            return None;
        };
        if !callee.accessors.is_empty() || self.callable_var(n) {
            return None;
        }
        self.methods.get(&n.key())
    }

    /// A call of the block's own method `M(args)`: the inputs are stored into the method's hidden
    /// inputs, `CAL M` runs it (replaced by a copy of the method's statements once every method is
    /// lowered: [`crate::actions::inline_calls`]), then the outputs (`v => x`) are read back.
    fn method_call(
        &mut self,
        sig: &super::types::MethodSig,
        args: &[Arg],
        span: Span,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) {
        let place = |name: String, span: Span| Place {
            base: PlaceBase::Name(Ident::new(name, span)),
            accessors: Vec::new(),
            span,
        };
        let mut before = Vec::new();
        let mut after = Vec::new();
        let mut in_outs = Vec::new();
        // the REFERENCE TO inputs bound for this call: reset to NULL when it returns
        let mut bound_refs = Vec::new();
        let mut positional = sig.inputs.iter();
        // positional arguments after the inputs bind the outputs in order (IEC 61131-3 ed. 3,
        // 6.6.1.4.2: a non-formal call gives every parameter of the definition in order; as a
        // call from outside the block does, `crate::actions`)
        let mut positional_outputs = sig.outputs.iter();
        let bound: Vec<Arg>;
        let args = if args.iter().filter(|a| a.name.is_none()).count() > sig.inputs.len()
            && args
                .iter()
                .all(|a| a.name.is_none() && a.dir == ArgDir::Input)
        {
            let mut k = 0;
            bound = args
                .iter()
                .map(|a| {
                    k += 1;
                    if k <= sig.inputs.len() {
                        return a.clone();
                    }
                    match (positional_outputs.next(), &a.value.kind) {
                        (Some(o), ExprKind::Place(_)) => Arg {
                            name: Some(Ident::new(o.clone(), a.span)),
                            dir: ArgDir::Output { negated: false },
                            value: a.value.clone(),
                            span: a.span,
                        },
                        _ => a.clone(),
                    }
                })
                .collect();
            &bound[..]
        } else {
            args
        };
        for a in args {
            let (param, list) = match (&a.dir, &a.name) {
                (ArgDir::Input, Some(n)) => {
                    (sig.inputs.iter().find(|i| n.is(i)).cloned(), &sig.inputs)
                }
                (ArgDir::Input, None) => (positional.next().cloned(), &sig.inputs),
                (ArgDir::Output { .. }, Some(n)) => {
                    (sig.outputs.iter().find(|o| n.is(o)).cloned(), &sig.outputs)
                }
                (ArgDir::Output { .. }, None) => (None, &sig.outputs),
            };
            let Some(param) = param else {
                // (a call of a dropped overload: its E1084 is the one error)
                if sig.overloaded {
                    continue;
                }
                let what = match &a.name {
                    Some(n) => format!("method `{}` has no parameter `{}`", sig.name, n.name),
                    None => format!("method `{}` takes {} input(s)", sig.name, sig.inputs.len()),
                };
                diags.push(
                    Diagnostic::error(code::E1011, what)
                        .at(a.span)
                        .with_primary_label("no such parameter")
                        .with_hint(format!("parameters of `{}`: {}", sig.name, list.join(", "))),
                );
                continue;
            };
            let hidden = place(crate::actions::method_var(&sig.name, &param), a.span);
            match a.dir {
                ArgDir::Input if sig.in_outs.iter().any(|i| i.eq_ignore_ascii_case(&param)) => {
                    in_outs.push((param, a));
                }
                // a REFERENCE TO input refers to the argument for this call (`q REF= v`, call-
                // scoped: see `refs::REF_ASSIGN_CALL`); any other input takes its value
                ArgDir::Input => before.push(Stmt {
                    kind: StmtKind::Assign {
                        value: match self
                            .vars
                            .get(&crate::actions::method_var(&sig.name, &param))
                        {
                            Some(TypeRef::Ref {
                                kind: il::RefKind::Reference,
                                ..
                            }) if matches!(a.value.kind, ExprKind::Place(_)) => Expr {
                                kind: ExprKind::Call {
                                    name: {
                                        bound_refs.push(Ident::new(
                                            crate::actions::method_var(&sig.name, &param),
                                            a.span,
                                        ));
                                        Ident::new(super::refs::REF_ASSIGN_CALL, a.span)
                                    },
                                    args: vec![Arg {
                                        name: None,
                                        dir: ArgDir::Input,
                                        value: a.value.clone(),
                                        span: a.span,
                                    }],
                                },
                                span: a.span,
                            },
                            // the address of an argument given to an ANY input (`In__PVALUE :=
                            // ADR(x)`, `super::any_inputs`): made for this call (call-scoped, as
                            // an `ARRAY [*]` argument's), so that `x` may be a variable that
                            // lives for the call (a method's VAR, a VAR_TEMP; TwinCAT passes an
                            // ANY argument as a pointer read during the call, Infosys "ANY and
                            // ANY_<type>"); reset to NULL when the call returns
                            _ if super::any_inputs::is_address_input(&param) => {
                                match super::any_inputs::address_for_one_call(&a.value) {
                                    Some(value) => {
                                        bound_refs.push(Ident::new(
                                            crate::actions::method_var(&sig.name, &param),
                                            a.span,
                                        ));
                                        value
                                    }
                                    None => a.value.clone(),
                                }
                            }
                            _ => a.value.clone(),
                        },
                        target: hidden,
                    },
                    span: a.span,
                }),
                ArgDir::Output { negated } => {
                    let ExprKind::Place(target) = &a.value.kind else {
                        continue;
                    };
                    let read = Expr {
                        kind: ExprKind::Place(hidden),
                        span: a.span,
                    };
                    let value = if negated {
                        Expr {
                            kind: ExprKind::Unary {
                                op: UnaryOp::Not,
                                operand: Box::new(read),
                            },
                            span: a.span,
                        }
                    } else {
                        read
                    };
                    after.push(Stmt {
                        kind: StmtKind::Assign {
                            target: target.clone(),
                            value,
                        },
                        span: a.span,
                    });
                }
            }
        }
        // the value inputs the call leaves out start again at their initial values (the
        // never-written `__MD_<M>_<X>` of `crate::actions::method_input_default`)
        let given: Vec<String> = before
            .iter()
            .filter_map(|s| match &s.kind {
                StmtKind::Assign { target, .. } => target.name().map(|n| n.key()),
                _ => None,
            })
            .collect();
        for input in &sig.inputs {
            let hidden = crate::actions::method_var(&sig.name, input);
            let default = crate::actions::method_input_default(&sig.name, input);
            let resets = self
                .vars
                .get(&default)
                .is_some_and(|t| self.decls.resets_per_call(t));
            if given.contains(&hidden) || !resets || super::fb_init::is_special_method(&sig.name) {
                continue;
            }
            before.push(Stmt {
                kind: StmtKind::Assign {
                    target: place(hidden, span),
                    value: Expr {
                        kind: ExprKind::Place(place(default, span)),
                        span,
                    },
                },
                span,
            });
        }
        self.stmt_list(&before, out, diags);
        let bound = self.method_in_out_args(sig, &in_outs, out, diags);
        out.push(instr(
            InstrKind::Call {
                cond: Condition::Always,
                instance: Box::new(VarRef {
                    base: Ident::new(sig.name.clone(), span),
                    accessors: Default::default(),
                    span,
                }),
                args: if bound.is_empty() {
                    CallArgs::None
                } else {
                    CallArgs::Formal(bound)
                },
            },
            span,
        ));
        for hidden in &bound_refs {
            out.push(ld(Operand::reference(None, span), span));
            out.push(simple(Op::St, false, Some(var_operand(hidden)), span));
        }
        self.stmt_list(&after, out, diags);
        self.types.get_mut().clear();
    }

    /// Lowers an expression: the instructions leave its value in the current result.
    pub fn expression(&mut self, e: &Expr, diags: &mut Diagnostics) -> Vec<IlStmt> {
        let mut out = Vec::new();
        self.poisoned = false;
        self.types.get_mut().clear();
        let own = self.own_names_dropped_expr(e);
        self.value(own.as_ref().unwrap_or(e), &mut out, diags);
        self.types.get_mut().clear();
        out
    }

    /// Lowers a condition (a BOOL expression): the instructions leave it in the current result.
    /// A condition whose type is known and not BOOL is reported (E3105) and becomes `LD FALSE`.
    pub fn condition(&mut self, e: &Expr, diags: &mut Diagnostics) -> Vec<IlStmt> {
        let mut out = Vec::new();
        self.poisoned = false;
        self.types.get_mut().clear();
        let own = self.own_names_dropped_expr(e);
        let e = own.as_ref().unwrap_or(e);
        let reads_property =
            self.properties && super::property::reads_any(&self.env(), &self.methods, e);
        if reads_property || call_chain::expr_has_chain(e) {
            // `m_ptrPanelMgr^.Start` (a PROPERTY), `stack.Get(1).Ready` as an SFC transition's
            // condition: the statement rewrites (getter calls, call chains) need a statement, so
            // the condition is `T := e;` lowered as any statement, then `LD T`
            let span = e.span;
            let t = self.temp(named("BOOL", span), span);
            let assign = Stmt {
                kind: StmtKind::Assign {
                    target: Place {
                        base: PlaceBase::Name(t.clone()),
                        accessors: Vec::new(),
                        span,
                    },
                    value: e.clone(),
                },
                span,
            };
            self.stmt(&assign, &mut out, diags);
            out.push(ld(var_operand(&t), span));
        } else {
            self.cond_value(e, "condition", &mut out, diags);
        }
        self.types.get_mut().clear();
        out
    }

    /// The temporaries declared so far.
    pub fn temporaries(&self) -> &[VarDecl] {
        &self.temps
    }

    /// The `VAR_TEMP` block holding the temporaries (none when no temporary was needed).
    pub fn finish(self, span: Span) -> Option<VarBlock> {
        (!self.temps.is_empty()).then_some(VarBlock {
            access: None,
            name: None,
            kind: VarKind::Temp,
            constant: false,
            retain: false,
            vars: self.temps,
            span,
        })
    }

    /// The hidden variables holding the literals whose address the statements take
    /// (`ADR('text')`): a block named [`super::var_stat::MARK`], so that
    /// [`super::var_stat::hoist`] makes each a global variable with an address for the whole run
    /// (a pointer stored from it stays valid, also in a FUNCTION); `None` when there are none.
    pub fn take_literal_copies(&mut self, span: Span) -> Option<VarBlock> {
        (!self.literal_copies.is_empty()).then(|| VarBlock {
            access: None,
            name: Some(Ident::new(super::var_stat::MARK, span)),
            kind: VarKind::Local,
            constant: false,
            retain: false,
            vars: std::mem::take(&mut self.literal_copies),
            span,
        })
    }

    /// `ADR('text')` / `ADR("text")`: the hidden variable (a STRING / WSTRING of the literal's
    /// length) holding the literal, given the literal again right before the address is taken,
    /// so that a write through an address taken before never changes what the literal means here.
    /// `None` for another literal (a number has no address: E0305 stays).
    pub(super) fn literal_copy(&mut self, e: &Expr, out: &mut Vec<IlStmt>) -> Option<il::VarRef> {
        let ExprKind::Literal(l) = &e.kind else {
            return None;
        };
        let LiteralKind::String { wide, value } = &l.kind else {
            return None;
        };
        let span = e.span;
        let name = Ident::new(format!("__ADRLIT_{}_{}", span.file.0, span.start), span);
        if !self.vars.contains_key(&name.key()) {
            let length = (value.chars().count() as u32).max(1);
            let ty = TypeRef::String {
                wide: *wide,
                length: Some(length),
                span,
            };
            self.literal_copies
                .push(VarDecl::new(name.clone(), ty.clone(), span));
            self.vars.insert(name.key(), ty);
        }
        out.push(ld(Operand::literal(l.clone()), span));
        out.push(simple(Op::St, false, Some(var_operand(&name)), span));
        Some(VarRef {
            base: name,
            accessors: Default::default(),
            span,
        })
    }

    // ------------------------------------------------------------ helpers

    fn env(&self) -> Env<'_> {
        Env {
            decls: self.decls,
            vars: &self.vars,
            pou_name: &self.pou,
            pou_kind: self.kind,
            pou_ret: self.ret.as_ref(),
        }
    }

    fn ty(&self, e: &Expr) -> Ty {
        self.env().expr_cached(e, &mut self.types.borrow_mut())
    }

    /// A new temporary of type `ty`, declared in the POU's VAR_TEMP block.
    fn temp(&mut self, ty: TypeRef, span: Span) -> Ident {
        let name = Ident::new(format!("{}T{}", self.prefix, self.temps.len() + 1), span);
        self.temps.push(VarDecl::new(name.clone(), ty, span));
        self.vars
            .insert(name.key(), self.temps[self.temps.len() - 1].ty.clone());
        name
    }

    /// The type to declare a temporary holding `e`: its own type, else the context's `hint`,
    /// else DINT / LREAL for untyped literals.
    fn temp_type(&self, e: &Expr, hint: Option<&TypeRef>) -> TypeRef {
        match (self.ty(e), hint) {
            (Ty::Known(t), _) => t,
            (_, Some(h)) => h.clone(),
            (Ty::RealLit, None) => named("LREAL", e.span),
            _ => named("DINT", e.span),
        }
    }

    /// Reports a condition whose type is known and not BOOL (E3105); returns whether it is fine.
    fn check_bool(&self, e: &Expr, what: &str, diags: &mut Diagnostics) -> bool {
        let env = self.env();
        if let Ty::Known(t) = self.ty(e) {
            let is_bool = env
                .elementary(&t)
                .is_some_and(|x| x == crate::sema::model::Elementary::Bool);
            if !is_bool && env.elementary(&t).is_some() {
                diags.push(
                    Diagnostic::error(
                        code::E3105,
                        format!(
                            "the {what} must be BOOL, but this expression is {}",
                            type_text(&t)
                        ),
                    )
                    .at(e.span)
                    .with_primary_label("not a BOOL")
                    .with_hint("compare the value, e.g. `x <> 0`"),
                );
                return false;
            }
        }
        true
    }

    /// The code of an IF/ELSIF/WHILE/UNTIL condition. A condition that is known not to be BOOL is
    /// reported in ST terms (E3105) and replaced by `LD FALSE`, so the conditional jump does not
    /// report the same mistake again in IL terms.
    fn cond_value(&mut self, e: &Expr, what: &str, out: &mut Vec<IlStmt>, diags: &mut Diagnostics) {
        if self.check_bool(e, what, diags) {
            self.value(e, out, diags);
        } else {
            let f = Operand::literal(Literal {
                kind: LiteralKind::Bool(false),
                type_prefix: None,
                span: e.span,
            });
            out.push(ld(f, e.span));
        }
    }

    // ------------------------------------------------------------ statements

    fn stmt_list(&mut self, stmts: &[Stmt], out: &mut Vec<IlStmt>, diags: &mut Diagnostics) {
        for s in stmts {
            self.stmt(s, out, diags);
        }
    }

    /// A loop's `body` (WHILE, REPEAT, FOR), where EXIT jumps to `exit` and CONTINUE to `cont`.
    fn loop_body(
        &mut self,
        body: &[Stmt],
        exit: &Ident,
        cont: &Ident,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) {
        self.loops.push(LoopLabels {
            exit: exit.clone(),
            cont: cont.clone(),
        });
        self.stmt_list(body, out, diags);
        self.loops.pop();
    }

    fn stmt(&mut self, s: &Stmt, out: &mut Vec<IlStmt>, diags: &mut Diagnostics) {
        // (no type cached for a node of another statement: see `infer::NodeKey`)
        self.types.get_mut().clear();
        if !self.stmt_rewritten(s, out, diags) {
            self.stmt_lowered(s, out, diags);
        }
    }
    /// Lowers the calls a rewrite hoisted out of a statement, then the statement `rest` reading
    /// their results.
    fn lower_hoisted(
        &mut self,
        calls: &[Stmt],
        rest: &Stmt,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) {
        for c in calls {
            self.stmt(c, out, diags);
        }
        self.stmt(rest, out, diags);
        self.types.get_mut().clear();
    }

    /// Lowers the statements a rewrite gave for one statement, with the temporaries it declared.
    fn lower_rewritten(
        &mut self,
        stmts: &[Stmt],
        temps: Vec<VarDecl>,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) {
        for t in temps {
            self.vars.insert(t.name.key(), t.ty.clone());
            self.temps.push(t);
        }
        for c in stmts {
            self.stmt(c, out, diags);
        }
        self.types.get_mut().clear();
    }

    /// Lowers `s` when a rewrite applies to it (property accessors, method calls hoisted out of
    /// it, interface variables) and says whether one did. Kept out of [`Self::stmt`]'s frame:
    /// statements nest (IF in IF ...), and the rewrites' statements would be on the stack at
    /// every level of the nesting (the E0108 limit must lower without overflowing a 2 MB stack).
    #[inline(never)]
    fn stmt_rewritten(&mut self, s: &Stmt, out: &mut Vec<IlStmt>, diags: &mut Diagnostics) -> bool {
        if self.refuse_dynamic_memory(s, diags) {
            // `p := __NEW(FB_Item);`: one E0351 each, the statement dropped (dynamic_memory)
            return true;
        }
        let passes = std::mem::take(&mut self.any_passes);
        let type_of = |e: &Expr| self.expression_type(e);
        let any = if self.any_inputs {
            super::any_inputs::rewrite(&self.env(), &type_of, s, diags)
        } else {
            None
        };
        match any {
            // a rewrite that does not settle (an `ARRAY [*]` element given to an ANY input)
            Some(Some(_)) if passes >= 4 => {
                diags.push(
                    Diagnostic::error(
                        code::E1068,
                        "an argument of an ANY input that ladderc cannot pass here",
                    )
                    .at(s.span)
                    .with_primary_label("not compiled")
                    .with_hint(
                        "copy the value into a variable of its type first, and pass that variable",
                    ),
                );
                self.poisoned = true;
                return true;
            }
            // `F(In := x)` of a function's ANY input `In`, `In.diSize` in it (any_inputs)
            Some(Some(s)) => {
                self.any_passes = passes + 1;
                self.stmt(&s, out, diags);
                return true;
            }
            // (reported; the statement is dropped)
            Some(None) => return true,
            None => {}
        }
        let varlen = if self.varlen {
            super::varlen::rewrite(&self.env(), &type_of, s, diags)
        } else {
            None
        };
        match varlen {
            // `F(xs := arr)` of an `ARRAY [*]` in-out, `xs[i]`, `UPPER_BOUND(xs, 1)` (varlen);
            // the type cache is keyed by node address: cleared around the new tree's life
            Some(Some(s)) => {
                self.types.get_mut().clear();
                self.stmt(&s, out, diags);
                self.types.get_mut().clear();
                return true;
            }
            // (reported; the statement is dropped)
            Some(None) => return true,
            None => {}
        }
        if let Some(s) = self.read_property_results(s) {
            // the statement after `a.Child.Depth();`: reads the result kept below
            self.stmt(&s, out, diags);
            return true;
        }
        if let Some(calls) = self.call_on_property(s) {
            // `a.Child.Depth(...)` (the parser put it before its statement): the property's
            // value first, then the call on it, its result kept (call_chain)
            for c in &calls {
                self.stmt(c, out, diags);
            }
            self.types.get_mut().clear();
            return true;
        }
        if call_chain::stmt_has_chain(s) {
            // `x := stack.Get(1).Pop();`: the chain's calls first, each result in a temporary
            // (call_chain), then the statement on the temporaries with every other rewrite
            if let Some((calls, rest)) = self.hoist_method_calls(s, diags) {
                self.lower_hoisted(&calls, &rest, out, diags);
                return true;
            }
        }
        if self.properties {
            let rewritten = super::property::rewrite(&self.env(), &self.methods, s, diags);
            if let Some((calls, rest)) = rewritten {
                // `x := inst.P + 1;`: the getter runs first, the statement reads its result;
                // `inst.P := v;` calls the setter
                self.lower_hoisted(&calls, &rest, out, diags);
                return true;
            }
        }
        {
            if let Some((calls, rest)) = self.hoist_method_calls(s, diags) {
                // `x := M(a) + 1;` inside the block: the call runs first, the statement reads the
                // result `__M_M` (as `inst.M(a)` from outside, see the parser)
                self.lower_hoisted(&calls, &rest, out, diags);
                return true;
            }
        }
        let first = self.temps.len();
        if let Some((stmts, temps)) = super::base_view::rewrite(&self.env(), s, first) {
            // `r.M()` through a reference to a base: a CASE on the instance's class (base_view)
            self.lower_rewritten(&stmts, temps, out, diags);
            return true;
        }
        let first = self.temps.len();
        let rewritten = super::interface_vars::rewrite(&self.env(), s, first, diags);
        if let Some((stmts, temps)) = rewritten {
            // `itf := inst;`, `itf.M();`, `itf <> 0`: the hidden tag and references of the
            // interface variable (see interface_vars); `F(shape := inst)` passes a temporary
            self.lower_rewritten(&stmts, temps, out, diags);
            return true;
        }
        false
    }

    /// Lowers `s` itself (no rewrite applies to it).
    fn stmt_lowered(&mut self, s: &Stmt, out: &mut Vec<IlStmt>, diags: &mut Diagnostics) {
        let span = s.span;
        match &s.kind {
            StmtKind::Call { callee, args } if self.method_of(callee).is_some() => {
                let sig = self
                    .method_of(callee)
                    .expect("checked by the guard")
                    .clone();
                self.method_call(&sig, args, span, out, diags);
            }
            StmtKind::Empty => {}
            // `x;` (W1431): nothing to run, but a name nothing declares is an error: loaded (the
            // load does nothing), so that sema reports it as any use of an undeclared name (one
            // E1001 per POU at its first use), with every other error of the project
            StmtKind::Named(p) => {
                if let PlaceBase::Name(n) = &p.base {
                    let key = n.key();
                    let known = self.env().var_type(n).is_some()
                        || self.decls.global_lists.contains_key(&key)
                        || self.decls.pou(&n.name).is_some()
                        || self.decls.types.contains_key(&key)
                        || self.actions.contains_key(&key)
                        || self.il_actions.contains_key(&key)
                        || self.env().place_type(p).is_some();
                    if !known {
                        out.push(ld(var_operand(n), n.span));
                    }
                }
            }
            StmtKind::Assign { target, value } if is_ref_assign(value) => {
                self.poisoned = false;
                let mut code = Vec::new();
                self.raw_refs = true;
                let place = self.place_operand(target, &mut code, diags);
                self.raw_refs = false;
                self.per_call_target = target.accessors.is_empty()
                    && target
                        .name()
                        .is_some_and(|n| self.per_call_refs.contains(&n.key()));
                let value = self.reference(value, None, &mut code, diags);
                self.per_call_target = false;
                if let (Some(p), Some(v), false) = (place, value, self.poisoned) {
                    code.push(ld(v, span));
                    code.push(simple(Op::St, false, Some(p), span));
                    out.extend(code);
                }
            }
            // `r ACCESS e` (B&R): the reference itself takes the address `e` computes
            StmtKind::Assign { target, value } if is_access_assign(value) => {
                self.poisoned = false;
                let mut code = Vec::new();
                self.raw_refs = true;
                let place = self.place_operand(target, &mut code, diags);
                self.raw_refs = false;
                if let ExprKind::Call { args, .. } = &value.kind {
                    if let Some(a) = args.first() {
                        self.value(&a.value, &mut code, diags);
                    }
                }
                if let (Some(p), false) = (place, self.poisoned) {
                    code.push(simple(Op::St, false, Some(p), span));
                    out.extend(code);
                }
            }
            StmtKind::Assign { target, value }
                if self.assigns_missing_result(target, value, span, diags) => {}
            StmtKind::Assign { target, value } => {
                self.poisoned = false;
                let mut code = Vec::new();
                let place = self.place_operand(target, &mut code, diags);
                self.lit_hint = match self.ty(value) {
                    Ty::Known(_) => None,
                    _ => self.env().place_type(target),
                };
                let target_type = self.env().place_type(target);
                self.shadowed_enum_value(value, target_type.as_ref(), diags);
                self.value(value, &mut code, diags);
                if let (Some(p), false) = (place, self.poisoned) {
                    code.push(simple(Op::St, false, Some(p), span));
                    out.extend(code);
                }
            }
            StmtKind::Call { callee, args } if self.action_of(callee, args).is_some() => {
                let (key, body) = self.action_of(callee, args).expect("checked by the guard");
                if self.inlining.contains(&key) {
                    diags.push(
                        Diagnostic::error(
                            code::E0106,
                            format!(
                                "action `{key}` calls itself (directly or through another action)"
                            ),
                        )
                        .at(span)
                        .with_primary_label("recursive action call")
                        .with_hint(
                            "actions are inlined where they are called; they cannot recurse",
                        ),
                    );
                } else {
                    match body {
                        ActionBody::St(body) => {
                            self.inlining.push(key);
                            let body = self.own_names_dropped(&body);
                            self.stmt_list(&body, out, diags);
                            self.inlining.pop();
                        }
                        ActionBody::Il(body) => {
                            self.next_label += 1;
                            let tag = format!("{}A{}_", self.prefix, self.next_label);
                            out.extend(crate::actions::instantiate(&body, &tag, span));
                        }
                    }
                }
            }
            StmtKind::Call { callee, args } => {
                self.poisoned = false;
                let mut code = Vec::new();
                self.call_statement(callee, args, span, &mut code, diags);
                if !self.poisoned {
                    out.extend(code);
                }
            }
            StmtKind::If {
                branches,
                else_body,
            } => {
                let end = self.fresh_label("END_IF", span);
                for (k, b) in branches.iter().enumerate() {
                    let last = k + 1 == branches.len() && else_body.is_none();
                    let next = if last {
                        end.clone()
                    } else {
                        self.fresh_label("ELSE", b.span)
                    };
                    self.poisoned = false;
                    self.cond_value(&b.cond, "IF condition", out, diags);
                    out.push(jump(Condition::IfFalse, &next, b.cond.span));
                    self.stmt_list(&b.body, out, diags);
                    if !last {
                        if !ends_with_transfer(out) {
                            out.push(jump(Condition::Always, &end, b.span));
                        }
                        out.push(IlStmt::Label(next));
                    }
                }
                if let Some(e) = else_body {
                    self.stmt_list(e, out, diags);
                }
                out.push(IlStmt::Label(end));
            }
            StmtKind::Case {
                selector,
                arms,
                else_body,
            } => self.case(selector, arms, else_body.as_deref(), span, out, diags),
            StmtKind::For {
                control,
                element,
                from,
                to,
                by,
                body,
            } => self.for_loop(
                (control, element.as_ref()),
                from,
                to,
                by.as_ref(),
                body,
                span,
                out,
                diags,
            ),
            StmtKind::While { cond, body } => {
                let test = self.fresh_label("WHILE", span);
                let end = self.fresh_label("END_WHILE", span);
                out.push(IlStmt::Label(test.clone()));
                self.poisoned = false;
                self.cond_value(cond, "WHILE condition", out, diags);
                out.push(jump(Condition::IfFalse, &end, cond.span));
                self.loop_body(body, &end, &test, out, diags);
                if !ends_with_transfer(out) {
                    // the jump back is located at `WHILE cond` (the loop guard of `ladderc run`
                    // reports a loop that never ends there)
                    let head = Span::new(span.file, span.start as usize, cond.span.end as usize);
                    let head = if cond.span.end >= span.start {
                        head
                    } else {
                        span
                    };
                    out.push(jump(Condition::Always, &test, head));
                }
                out.push(IlStmt::Label(end));
            }
            StmtKind::Repeat { body, setup, until } => {
                let top = self.fresh_label("REPEAT", span);
                let cont = self.fresh_label("UNTIL", until.span);
                let end = self.fresh_label("END_REPEAT", span);
                out.push(IlStmt::Label(top.clone()));
                self.loop_body(body, &end, &cont, out, diags);
                out.push(IlStmt::Label(cont));
                // the condition's ExST assignments, before each test (also after a CONTINUE)
                self.stmt_list(setup, out, diags);
                self.poisoned = false;
                self.cond_value(until, "UNTIL condition", out, diags);
                out.push(jump(Condition::IfFalse, &top, until.span));
                out.push(IlStmt::Label(end));
            }
            StmtKind::Exit | StmtKind::Continue => {
                let exit = matches!(s.kind, StmtKind::Exit);
                match self.loops.last() {
                    Some(l) => {
                        let target = if exit { &l.exit } else { &l.cont };
                        out.push(jump(Condition::Always, target, span));
                    }
                    None => diags.push(
                        Diagnostic::error(
                            code::E3101,
                            format!("{} outside a loop", if exit { "EXIT" } else { "CONTINUE" }),
                        )
                        .at(span)
                        .with_primary_label("not inside FOR, WHILE or REPEAT")
                        .with_hint("use RETURN to leave the POU, or an IF to skip statements"),
                    ),
                }
            }
            StmtKind::Return => out.push(instr(
                InstrKind::Return {
                    cond: Condition::Always,
                },
                span,
            )),
            // the label and the jump keep the user's name (the generated ones start with `_ST_`):
            // a jump to a label the body does not have, or a label written twice, is the IL's
            // E1009 / E1010 at the name
            StmtKind::Label(_) | StmtKind::Jump(_) if !self.st_jump_noted => {
                self.st_jump_noted = true;
                diags.push(
                    Diagnostic::warning(
                        code::W1426,
                        format!(
                            "`{}` jumps in Structured Text (CODESYS and TwinCAT): IEC 61131-3 has jumps in IL, LD and FBD only (the POU's other jumps and labels are not reported)",
                            self.pou.name
                        ),
                    )
                    .at(span)
                    .with_primary_label("a jump or its label")
                    .with_hint("compiled as CODESYS does: `JMP name;` goes on at `name:` of the same body; for another IEC compiler write the logic with IF, CASE and the loops"),
                );
                self.stmt_lowered(s, out, diags);
            }
            StmtKind::Label(l) => out.push(IlStmt::Label(l.clone())),
            StmtKind::Jump(l) => out.push(jump(Condition::Always, l, span)),
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn case(
        &mut self,
        selector: &Expr,
        arms: &[CaseArm],
        else_body: Option<&[Stmt]>,
        span: Span,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) {
        self.poisoned = false;
        let mut code = Vec::new();
        let sel = match self.pure_operand(selector) {
            Some(o) => o,
            None => {
                let ty = self.temp_type(selector, None);
                self.value(selector, &mut code, diags);
                let t = self.temp(ty, selector.span);
                code.push(simple(Op::St, false, Some(var_operand(&t)), selector.span));
                var_operand(&t)
            }
        };
        if self.poisoned {
            return;
        }
        out.extend(code);
        // a bare enumerated value as a label is typed by the selector (`CASE state OF IDLE:` with
        // `IDLE` also a value of another enumeration), as the right side of `state = IDLE` is
        let sel_ty = self.ty(selector).known().cloned();
        let hint = sel_ty.as_ref();
        let end = self.fresh_label("END_CASE", span);
        let mut targets = Vec::new();
        let mut seen = LabelSet::default();
        for arm in arms {
            let target = self.fresh_label("CASE", arm.span);
            for label in &arm.labels {
                let key = match label {
                    CaseLabel::Value(v) => self
                        .case_value(v, hint, &mut Diagnostics::new())
                        .and_then(|o| label_key(&o, &o)),
                    CaseLabel::Range(lo, hi) => {
                        let mut quiet = Diagnostics::new();
                        match (
                            self.case_value(lo, hint, &mut quiet),
                            self.case_value(hi, hint, &mut quiet),
                        ) {
                            (Some(l), Some(h)) => label_key(&l, &h),
                            _ => None,
                        }
                    }
                };
                let at = match label {
                    CaseLabel::Value(v) => v.span,
                    CaseLabel::Range(lo, hi) => lo.span.to(hi.span),
                };
                if let Some(k) = key {
                    if let Some(first) = seen.first_overlap(&k) {
                        diags.push(
                            Diagnostic::warning(
                                code::W3140,
                                "this CASE label overlaps an earlier one: the earlier label wins",
                            )
                            .at(at)
                            .with_primary_label("never chosen for the values it shares")
                            .with_label(first, "earlier label with the same value")
                            .with_hint("remove the value from one of the labels (IEC 61131-3 requires distinct labels)"),
                        );
                    }
                    seen.insert(k, at);
                }
                match label {
                    CaseLabel::Value(v) => {
                        let Some(v) = self.case_label(v, hint, out, diags) else {
                            continue;
                        };
                        out.push(ld(sel.clone(), v.span()));
                        out.push(simple(Op::Eq, false, Some(v.clone()), v.span()));
                    }
                    CaseLabel::Range(lo, hi) => {
                        let (Some(lo), Some(hi)) = (
                            self.case_label(lo, hint, out, diags),
                            self.case_label(hi, hint, out, diags),
                        ) else {
                            continue;
                        };
                        let at = lo.span().to(hi.span());
                        out.push(ld(sel.clone(), at));
                        out.push(simple(Op::Ge, false, Some(lo), at));
                        out.push(deferred(
                            Op::And,
                            sel.clone(),
                            vec![simple(Op::Le, false, Some(hi), at)],
                            at,
                        ));
                    }
                }
                out.push(jump(Condition::IfTrue, &target, arm.span));
            }
            targets.push(target);
        }
        let else_label = else_body.map(|_| self.fresh_label("CASE_ELSE", span));
        out.push(jump(
            Condition::Always,
            else_label.as_ref().unwrap_or(&end),
            span,
        ));
        for (arm, target) in arms.iter().zip(targets) {
            out.push(IlStmt::Label(target));
            self.stmt_list(&arm.body, out, diags);
            if !ends_with_transfer(out) {
                out.push(jump(Condition::Always, &end, arm.span));
            }
        }
        if let (Some(l), Some(body)) = (else_label, else_body) {
            out.push(IlStmt::Label(l));
            self.stmt_list(body, out, diags);
        }
        out.push(IlStmt::Label(end));
    }

    /// A CASE label as compared: [`Self::case_value`], or a constant expression of named constants,
    /// literals and arithmetic (`ST_RUN + ST_ERR:`; edition 3: Case_List_Elem is a Subrange or a
    /// Constant_Expr; CODESYS documents it) computed into a temporary of the label's type before
    /// the comparison (its names are checked by sema as any operand: a variable is accepted as
    /// CODESYS accepts it only where constant; ladderc does not tell them apart here).
    fn case_label(
        &mut self,
        e: &Expr,
        hint: Option<&TypeRef>,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) -> Option<Operand> {
        fn constant_shape(e: &Expr) -> bool {
            match &e.kind {
                ExprKind::Literal(_) | ExprKind::EnumValue { .. } => true,
                ExprKind::Place(p) => {
                    matches!(p.base, PlaceBase::Name(_))
                        && p.accessors.iter().all(|a| matches!(a, Accessor::Field(_)))
                }
                ExprKind::Unary { op, operand } => {
                    matches!(op, UnaryOp::Neg | UnaryOp::Plus) && constant_shape(operand)
                }
                ExprKind::Binary { op, left, right } => {
                    matches!(
                        op,
                        BinaryOp::Add
                            | BinaryOp::Sub
                            | BinaryOp::Mul
                            | BinaryOp::Div
                            | BinaryOp::Mod
                    ) && constant_shape(left)
                        && constant_shape(right)
                }
                _ => false,
            }
        }
        if matches!(e.kind, ExprKind::Binary { .. } | ExprKind::Unary { .. })
            && constant_shape(e)
            && self.value_of_enumeration(e, hint).is_none()
            && self.pure_operand(e).is_none()
        {
            let ty = self.temp_type(e, hint);
            self.value(e, out, diags);
            let t = self.temp(ty, e.span);
            out.push(simple(Op::St, false, Some(var_operand(&t)), e.span));
            return Some(var_operand(&t));
        }
        self.case_value(e, hint, diags)
    }

    /// A CASE label: a literal, an enumerated value or a constant (a plain operand); `hint` is the
    /// selector's type. A bare name of a value of the selector's enumeration is that value, also
    /// where a variable has the same name (`case_labels`).
    fn case_value(
        &mut self,
        e: &Expr,
        hint: Option<&TypeRef>,
        diags: &mut Diagnostics,
    ) -> Option<Operand> {
        if matches!(e.kind, ExprKind::Error) {
            return None;
        }
        let o = self
            .value_of_enumeration(e, hint)
            .or_else(|| self.pure_operand(e));
        if o.is_none() {
            diags.push(
                Diagnostic::error(code::E3104, "a CASE label must be a literal, an enumerated value or a constant")
                    .at(e.span)
                    .with_primary_label("computed value")
                    .with_hint("write the values (`1, 2:`), a range (`3..5:`) or enumerated values (`Color#red:`)"),
            );
        }
        o
    }

    #[allow(clippy::too_many_arguments)]
    fn for_loop(
        &mut self,
        (control, element): (&Ident, Option<&Place>),
        from: &Expr,
        to: &Expr,
        by: Option<&Expr>,
        body: &[Stmt],
        span: Span,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) {
        self.poisoned = false;
        let mut code = Vec::new();
        // an element or member (`Offset[1]`): its indices evaluated once, here (`for_control`)
        let (cty, i, written) = match element {
            Some(p) => {
                let (t, o) = self.for_control_element(p, &mut code, diags);
                let Some(o) = o else { return };
                (t, o, p.span)
            }
            None => (
                self.env().var_type(control),
                var_operand(control),
                control.span,
            ),
        };
        let env = self.env();
        if let Some(t) = &cty {
            // a bit string counts as its unsigned integer (CODESYS, TwinCAT; W1436 from sema at
            // its first arithmetic in the POU)
            let int = env.elementary(t).is_some_and(|e| {
                e.is_integer()
                    || matches!(
                        e,
                        crate::sema::model::Elementary::Byte
                            | crate::sema::model::Elementary::Word
                            | crate::sema::model::Elementary::Dword
                            | crate::sema::model::Elementary::Lword
                    )
            });
            // an enumeration without {attribute 'strict'} counts as its integer (CODESYS,
            // TwinCAT; `FOR e := E.a TO E.b`), as `e := E.a + 1` does in sema's loose_enum
            if !int && !env.loose_enum(t) {
                let text = match element {
                    Some(p) => for_control::place_text(p),
                    None => control.name.clone(),
                };
                diags.push(
                    Diagnostic::error(
                        code::E3100,
                        format!(
                            "the FOR control variable `{text}` must be an integer variable, but it is {}",
                            type_text(t)
                        ),
                    )
                    .at(written)
                    .with_primary_label("control variable")
                    .with_hint("declare it as INT, DINT, SINT, LINT or an unsigned integer"),
                );
                return;
            }
        }
        let mut writes = Vec::new();
        let shown = match element {
            None => {
                writes_of_control(control, body, &mut writes);
                control.name.clone()
            }
            Some(p) => {
                for_control::writes_of_element(p, body, &mut writes);
                for_control::place_text(p)
            }
        };
        for at in writes {
            diags.push(
                Diagnostic::warning(
                    code::W3141,
                    format!("the FOR control variable `{shown}` is changed inside its loop"),
                )
                .at(at)
                .with_primary_label("written inside the loop")
                .with_label(written, "control variable of this FOR")
                .with_hint("IEC 61131-3 forbids it and the loop may never end: count with another variable, or leave with EXIT"),
            );
        }
        let cty = cty.unwrap_or_else(|| named("DINT", control.span));
        let cty_is_bits = env.elementary(&cty).is_some_and(|e| {
            matches!(
                e,
                crate::sema::model::Elementary::Byte
                    | crate::sema::model::Elementary::Word
                    | crate::sema::model::Elementary::Dword
                    | crate::sema::model::Elementary::Lword
            )
        });
        // Bounds are evaluated once, before the first test.
        self.value(from, &mut code, diags);
        code.push(simple(Op::St, false, Some(i.clone()), from.span));
        let limit = match literal_value(to) {
            Some(_) => self.pure_operand(to).unwrap_or_else(|| int_lit(0, to.span)),
            None => {
                self.value(to, &mut code, diags);
                let t = self.temp(cty.clone(), to.span);
                code.push(simple(Op::St, false, Some(var_operand(&t)), to.span));
                var_operand(&t)
            }
        };
        let (step, sign) = match by {
            None => (int_lit(1, span), Some(1)),
            Some(b) => match literal_value(b) {
                Some(v) => {
                    if v == 0 {
                        diags.push(
                            Diagnostic::error(
                                code::E3100,
                                "FOR loop step is 0: the loop would never end",
                            )
                            .at(b.span)
                            .with_primary_label("BY 0")
                            .with_hint(
                                "use a positive step to count up, a negative one to count down",
                            ),
                        );
                        return;
                    }
                    (
                        self.pure_operand(b).unwrap_or_else(|| int_lit(1, b.span)),
                        Some(v.signum()),
                    )
                }
                None => {
                    self.value(b, &mut code, diags);
                    let t = self.temp(cty.clone(), b.span);
                    code.push(simple(Op::St, false, Some(var_operand(&t)), b.span));
                    (var_operand(&t), None)
                }
            },
        };
        if self.poisoned {
            return;
        }
        out.extend(code);
        let test = self.fresh_label("FOR", span);
        let cont = self.fresh_label("NEXT", span);
        let end = self.fresh_label("END_FOR", span);
        out.push(IlStmt::Label(test.clone()));
        let at = span;
        match sign {
            Some(s) => {
                out.push(ld(i.clone(), at));
                out.push(simple(
                    if s > 0 { Op::Gt } else { Op::Lt },
                    false,
                    Some(limit.clone()),
                    at,
                ));
            }
            None => {
                // (step >= 0 AND i > limit) OR (step < 0 AND i < limit)
                out.push(ld(step.clone(), at));
                out.push(simple(Op::Ge, false, Some(int_lit(0, at)), at));
                out.push(deferred(
                    Op::And,
                    i.clone(),
                    vec![simple(Op::Gt, false, Some(limit.clone()), at)],
                    at,
                ));
                out.push(deferred(
                    Op::Or,
                    step.clone(),
                    vec![
                        simple(Op::Lt, false, Some(int_lit(0, at)), at),
                        deferred(
                            Op::And,
                            i.clone(),
                            vec![simple(Op::Lt, false, Some(limit.clone()), at)],
                            at,
                        ),
                    ],
                    at,
                ));
            }
        }
        out.push(jump(Condition::IfTrue, &end, at));
        self.loop_body(body, &end, &cont, out, diags);
        out.push(IlStmt::Label(cont));
        // a bit-string counter's step is reported (W1436) at the counter
        let bit_counter = cty_is_bits;
        let bspan = by.map_or(if bit_counter { written } else { span }, |b| b.span);
        out.push(ld(i.clone(), bspan));
        out.push(simple(Op::Add, false, Some(step), bspan));
        out.push(simple(Op::St, false, Some(i), bspan));
        out.push(jump(Condition::Always, &test, span));
        out.push(IlStmt::Label(end));
    }

    fn call_statement(
        &mut self,
        callee: &Place,
        args: &[Arg],
        span: Span,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) {
        let named;
        let args = match self.name_positional_args(callee, args, diags) {
            Some(n) => {
                named = n;
                &named[..]
            }
            None => args,
        };
        // A plain name that is not a variable but a function: a function call whose result is dropped.
        if let Some(name) = callee.name() {
            if self.env().var_type(name).is_none() || self.function_beside_global(name) {
                if self
                    .decls
                    .pou(&name.name)
                    .is_some_and(|p| p.kind == PouKind::Program)
                {
                    // `P(in := x);` (CODESYS, TwinCAT): the program's one instance runs, as
                    // `CAL P(in := x)` (sema checks that it has one)
                    let ty = TypeRef::Named(name.clone());
                    let args = self.call_args(args, |env, n, _| env.member(&ty, n), out, diags);
                    out.push(instr(
                        InstrKind::Call {
                            cond: Condition::Always,
                            instance: Box::new(VarRef {
                                base: name.clone(),
                                accessors: Default::default(),
                                span: name.span,
                            }),
                            args,
                        },
                        span,
                    ));
                    return;
                }
                let e = Expr {
                    kind: ExprKind::Call {
                        name: name.clone(),
                        args: args.to_vec(),
                    },
                    span,
                };
                self.result_dropped = true;
                // (its value stays the current result, unused: no W1001, see `dropped_results`)
                super::dropped_results::record(span);
                self.value(&e, out, diags);
                self.result_dropped = false;
                // `e` is dropped here: forget the types keyed by its nodes' addresses.
                self.types.get_mut().clear();
                return;
            }
        }
        let Some(Operand::Var(instance)) = self.place_operand(callee, out, diags) else {
            diags.push(
                Diagnostic::error(
                    code::E3103,
                    "only a function block instance or a function can be called",
                )
                .at(callee.span)
                .with_primary_label("not callable"),
            );
            return;
        };
        let fb_ty = self.env().place_type(callee);
        // `inst.M(x := v)`: M's inputs are the block's hidden `__M_M_X` (a REFERENCE TO input
        // then refers to `v`, as a block's own does)
        let method = fb_ty
            .is_none()
            .then(|| self.method_called(callee))
            .flatten();
        self.unknown_callee = fb_ty.is_none() && method.is_none();
        if let Some(TypeRef::Named(t)) = fb_ty.as_ref().map(|t| self.env().resolve(t)) {
            self.callee_in_outs(&t.name);
        }
        let args = self.call_args(
            args,
            |env, name, k| match (&fb_ty, &method) {
                (Some(t), _) => env.member(t, name),
                (None, Some((owner, sig))) => {
                    let param = match name.name.as_str() {
                        "" => sig.inputs.get(k)?.as_str(),
                        n => n,
                    };
                    let hidden = crate::actions::method_var(&sig.name, param);
                    env.member(owner, &Ident::new(hidden, name.span))
                }
                (None, None) => None,
            },
            out,
            diags,
        );
        // the ANY inputs' addresses the call was given (`super::any_inputs`: call-scoped) are
        // reset to NULL when it returns: `.pValue` is valid while the call runs
        let any_addresses: Vec<String> = match fb_ty.as_ref().map(|t| self.env().resolve(t)) {
            Some(TypeRef::Named(t)) => self
                .decls
                .pou(&t.name)
                .filter(|p| p.kind == PouKind::FunctionBlock)
                .map(|p| {
                    p.vars
                        .iter()
                        .filter(|(n, k, _)| {
                            *k == crate::ast::VarKind::Input
                                && super::any_inputs::is_block_address_input(n)
                        })
                        .map(|(n, _, _)| n.clone())
                        .collect()
                })
                .unwrap_or_default(),
            _ => Vec::new(),
        };
        let reset: Vec<VarRef> = any_addresses
            .into_iter()
            .map(|n| {
                let mut v = instance.clone();
                v.accessors.push(il::Accessor::Field(Ident::new(n, span)));
                v
            })
            .collect();
        out.push(instr(
            InstrKind::Call {
                cond: Condition::Always,
                instance: Box::new(instance),
                args,
            },
            span,
        ));
        for v in reset {
            out.push(ld(Operand::reference(None, span), span));
            out.push(simple(Op::St, false, Some(Operand::Var(v)), span));
        }
    }

    /// Arguments of a call as IL operands (inputs that are not plain operands go through temporaries,
    /// computed into `out` first). `param_ty` gives the declared type of a named input.
    /// Notes the VAR_IN_OUT parameters of the user POU `name` for the next [`Self::call_args`].
    fn callee_in_outs(&mut self, name: &str) {
        let Some(p) = self.decls.pou(name) else {
            return;
        };
        let constant = p.constant_in_outs.clone();
        let plain = p
            .vars
            .iter()
            .filter(|v| v.1 == crate::ast::VarKind::InOut)
            .map(|v| v.0.to_ascii_uppercase())
            .filter(|n| !constant.contains(n))
            .collect();
        self.plain_in_outs = (p.name.clone(), plain);
        self.constant_in_outs = constant;
    }

    fn call_args(
        &mut self,
        args: &[Arg],
        param_ty: impl Fn(&Env, &Ident, usize) -> Option<TypeRef>,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) -> CallArgs {
        let unknown_callee = std::mem::take(&mut self.unknown_callee);
        let constant_in_outs = std::mem::take(&mut self.constant_in_outs);
        let (callee, plain_in_outs) = std::mem::take(&mut self.plain_in_outs);
        if args.is_empty() {
            return CallArgs::None;
        }
        let formal = args.iter().any(|a| a.name.is_some());
        if formal && args.iter().any(|a| a.name.is_none()) && unknown_callee {
            // `F_Unknown(hr, nOut => n)`, `fbMissing.Send(sUri := s, 0)`: the named arguments
            // only; the unknown function or type is the one error (E1019, E1003)
            let named: Vec<Arg> = args.iter().filter(|a| a.name.is_some()).cloned().collect();
            return self.call_args(&named, param_ty, out, diags);
        }
        if formal && args.iter().any(|a| a.name.is_none()) {
            let bad = args
                .iter()
                .find(|a| a.name.is_none())
                .map_or(args[0].span, |a| a.span);
            diags.push(
                Diagnostic::error(
                    code::E3106,
                    "formal and non-formal arguments are mixed in one call",
                )
                .at(bad)
                .with_primary_label("argument without a name")
                .with_hint("name every argument (`IN := x, PT := T#1s`) or none (`x, T#1s`)"),
            );
            self.poisoned = true;
            return CallArgs::None;
        }
        if !formal {
            let mut ops = Vec::new();
            for (k, a) in args.iter().enumerate() {
                let hint = param_ty(&self.env(), &Ident::new("", a.span), k);
                ops.push(self.operand(&a.value, hint.as_ref(), out, diags));
            }
            return CallArgs::NonFormal(ops);
        }
        let mut fargs = Vec::new();
        for (k, a) in args.iter().enumerate() {
            let Some(name) = &a.name else { continue };
            let value = match a.dir {
                // `VAR_IN_OUT CONSTANT` given a value that is not a variable (CODESYS, TwinCAT:
                // `fb(sTopic := 'abc')`): the value is stored in a temporary, which is passed
                ArgDir::Input
                    if !matches!(a.value.kind, ExprKind::Place(_))
                        && constant_in_outs.contains(&name.key()) =>
                {
                    match param_ty(&self.env(), name, k) {
                        Some(ty) => {
                            self.lit_hint = Some(ty.clone());
                            self.value(&a.value, out, diags);
                            let t = self.temp(ty, a.value.span);
                            out.push(simple(Op::St, false, Some(var_operand(&t)), a.value.span));
                            var_operand(&t)
                        }
                        None => self.operand(&a.value, None, out, diags),
                    }
                }
                // a plain VAR_IN_OUT is passed by reference: it needs a variable (IEC 61131-3
                // 6.6.1.2.2; CODESYS, TwinCAT: "a constant cannot be passed")
                ArgDir::Input
                    if !matches!(a.value.kind, ExprKind::Place(_))
                        && plain_in_outs.contains(&name.key()) =>
                {
                    // an argument already reported: a property given there (the property
                    // rewrite's E0338 left `ExprKind::Error`), or an argument with an error of its
                    // own, such as `Unknown(x)^`'s E1019: one cause, one error
                    let within = |s: Option<Span>| {
                        s.is_some_and(|s| {
                            s.file == a.value.span.file
                                && s.start >= a.value.span.start
                                && s.end <= a.value.span.end
                        })
                    };
                    if matches!(a.value.kind, ExprKind::Error)
                        || diags
                            .iter()
                            .any(|d| d.severity == diagnostics::Severity::Error && within(d.span))
                    {
                        self.poisoned = true;
                        continue;
                    }
                    diags.push(
                        Diagnostic::error(
                            code::E1088,
                            format!("VAR_IN_OUT `{}` of `{callee}` needs a variable", name.name),
                        )
                        .at(a.value.span)
                        .with_primary_label("not a variable")
                        .with_hint(format!(
                            "an in-out is passed by reference: store the value in a variable and pass that (`{} := v`), or declare the parameter `VAR_IN_OUT CONSTANT`",
                            name.name
                        )),
                    );
                    self.poisoned = true;
                    continue;
                }
                ArgDir::Input => {
                    let hint = param_ty(&self.env(), name, k);
                    self.operand(&a.value, hint.as_ref(), out, diags)
                }
                ArgDir::Output { .. } => match &a.value.kind {
                    ExprKind::Place(p) => match self.place_operand(p, out, diags) {
                        Some(o) => o,
                        None => continue,
                    },
                    // `Q =>` with nothing after it: the output is not read.
                    _ => continue,
                },
            };
            fargs.push(FormalArg {
                name: name.clone(),
                dir: match a.dir {
                    ArgDir::Input => il::ArgDir::Input,
                    ArgDir::Output { negated } => il::ArgDir::Output { negated },
                },
                value,
                span: a.span,
            });
        }
        CallArgs::Formal(fargs)
    }

    // ------------------------------------------------------------ expressions

    /// A plain IL operand for `e` if it needs no code: a literal, an enumerated value, an address, or
    /// a variable whose indices are themselves plain operands.
    /// A bare name that is no variable but a value of the enumeration the context expects
    /// (`c := XXXX;` with `c : enum_type00`, where other enumerations also declare `XXXX`): the
    /// qualified value `enum_type00#XXXX`. IEC 61131-3 asks for the type prefix only where the
    /// context does not determine the value.
    fn enum_by_context(&self, e: &Expr, hint: Option<&TypeRef>) -> Option<Operand> {
        let ExprKind::Place(Place {
            base: PlaceBase::Name(value),
            ..
        }) = &e.kind
        else {
            return None;
        };
        if self.env().var_type(value).is_some() {
            return None;
        }
        self.value_of_enumeration(e, hint)
    }

    /// W1430 when `e` is a bare name that is a variable (of another type) and also a value of the
    /// enumeration `hint` (`Position := SEL_MANUAL;` with an input `Sel_Manual : BOOL`): IEC 61131-3
    /// names ignore case, the variable is read (as matiec reads it; sema then reports the type), and
    /// the note says why.
    fn shadowed_enum_value(&self, e: &Expr, hint: Option<&TypeRef>, diags: &mut Diagnostics) {
        let ExprKind::Place(Place {
            base: PlaceBase::Name(value),
            accessors,
            ..
        }) = &e.kind
        else {
            return;
        };
        let (true, Some(var_type), Some(hint)) =
            (accessors.is_empty(), self.env().var_type(value), hint)
        else {
            return;
        };
        let TypeRef::Named(t) = self.env().resolve(hint) else {
            return;
        };
        let Some(decl) = self.decls.type_decl(&t.name) else {
            return;
        };
        let crate::ast::TypeDef::Enum { values, .. } = &decl.def else {
            return;
        };
        let same_type = matches!(self.env().resolve(&var_type), TypeRef::Named(v) if v.is(&t.name));
        let Some(declared) = values.iter().find(|v| v.name.is(&value.name)) else {
            return;
        };
        if same_type {
            return;
        }
        let (ty, val) = (&decl.name.name, &declared.name.name);
        diags.push(
            Diagnostic::warning(
                code::W1430,
                format!(
                    "`{}` is a variable here, not the value {ty}#{val} the assignment expects",
                    value.name
                ),
            )
            .at(value.span)
            .with_primary_label("the variable is read")
            .with_hint(format!(
                "IEC 61131-3 names ignore case, and a variable hides an enumeration's value of the same name: write {ty}#{val} for the value, or rename the variable"
            )),
        );
    }

    /// The reference operand `e` stands for, if it is one: `REF(x)` / `ADR(x)` / `r REF= x`'s `x`,
    /// `NULL`, `0` where a `POINTER TO` is expected, or a variable passed where a `REFERENCE TO`
    /// is expected (`hint`). Index code of `x` goes to `out`.
    fn reference(
        &mut self,
        e: &Expr,
        hint: Option<&TypeRef>,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) -> Option<Operand> {
        // the context's type matters only for a literal `0` and for a variable where a `REFERENCE
        // TO` may be expected (resolved only then: this runs for every operand)
        let needs_context = match &e.kind {
            ExprKind::Literal(Literal {
                kind: LiteralKind::Int(0),
                type_prefix: None,
                ..
            }) => true,
            ExprKind::Place(_) => self.reference_to,
            _ => false,
        };
        if let ExprKind::Call { name, args } = &e.kind {
            if name.is(super::base_view::RAW_REF) {
                // the reference a base view reads through, itself (base_view's dispatch)
                if let [Arg {
                    value:
                        Expr {
                            kind: ExprKind::Place(p),
                            ..
                        },
                    ..
                }] = &args[..]
                {
                    self.raw_refs = true;
                    let o = self.place_operand(p, out, diags);
                    self.raw_refs = false;
                    return o;
                }
            }
        }
        let expected = hint
            .filter(|_| needs_context)
            .map(|h| self.env().resolve(h));
        let place = match (&e.kind, &expected) {
            (ExprKind::Call { name, args }, _)
                if super::refs::is_address_of(name)
                    || name.is(super::refs::REF_ASSIGN)
                    || name.is(super::refs::REF_ASSIGN_CALL) =>
            {
                match &args[..] {
                    [Arg {
                        name: None,
                        value:
                            Expr {
                                kind: ExprKind::Place(p),
                                ..
                            },
                        ..
                    }] => p,
                    // `REF(THIS)`, `ADR(THIS)`: THIS is no variable of its own but the instance's
                    // reference (IEC 61131-3 ed. 3 6.6.5.6) or pointer (CODESYS, TwinCAT), which
                    // the parser reads as `ADR(THIS^)`: the instance's address, as `THIS` alone
                    [Arg {
                        name: None, value, ..
                    }] if super::refs::is_address_of(name) && bare_this(value).is_some() => {
                        bare_this(value)?
                    }
                    // `r REF= 0;` (TwinCAT): the reference refers to nothing (`__ISVALIDREF(r)`
                    // is FALSE), as a pointer set to 0
                    [Arg {
                        name: None,
                        value:
                            Expr {
                                kind:
                                    ExprKind::Literal(crate::ast::Literal {
                                        kind: LiteralKind::Int(0),
                                        type_prefix: None,
                                        ..
                                    }),
                                ..
                            },
                        ..
                    }] if name.is(super::refs::REF_ASSIGN)
                        || name.is(super::refs::REF_ASSIGN_CALL) =>
                    {
                        return Some(Operand::reference(None, e.span));
                    }
                    [Arg {
                        name: None,
                        value:
                            text @ Expr {
                                kind:
                                    ExprKind::Literal(Literal {
                                        kind: LiteralKind::String { .. },
                                        ..
                                    }),
                                ..
                            },
                        ..
                    }] if name.is("ADR") => {
                        // `ADR('text')` (B&R Automation Studio, CODESYS): the address of a
                        // hidden copy of the literal
                        let of = self.literal_copy(text, out)?;
                        return Some(Operand::reference(Some(of), e.span));
                    }
                    [Arg {
                        name: None,
                        value:
                            Expr {
                                kind: ExprKind::Literal(_),
                                span: lit,
                            },
                        ..
                    }] => {
                        // `ADR(16#FF)`: a number has no address
                        diags.push(
                            Diagnostic::error(
                                code::E0305,
                                format!("`{}` of a literal: a reference must refer to a variable", name.name),
                            )
                            .at(*lit)
                            .with_primary_label("a literal")
                            .with_hint("declare a variable (or VAR CONSTANT) holding the value and take its address"),
                        );
                        self.poisoned = true;
                        return Some(Operand::reference(None, e.span));
                    }
                    _ => {
                        diags.push(
                            Diagnostic::error(
                                code::E3103,
                                format!("`{}` takes one variable", name.name),
                            )
                            .at(e.span)
                            .with_primary_label("not one variable")
                            .with_hint("write `REF(x)` or `ADR(x)` of a variable, an array element or a structure field"),
                        );
                        self.poisoned = true;
                        return Some(Operand::reference(None, e.span));
                    }
                }
            }
            (
                ExprKind::Literal(Literal {
                    kind: LiteralKind::Int(0),
                    type_prefix: None,
                    ..
                }),
                Some(TypeRef::Ref { .. }),
            ) => {
                // `p := 0` (CODESYS, TwinCAT): NULL
                return Some(Operand::reference(None, e.span));
            }
            (
                ExprKind::Place(p),
                Some(TypeRef::Ref {
                    kind: il::RefKind::Reference,
                    ..
                }),
            ) if !(p.accessors.is_empty() && p.name().is_some_and(|n| n.is("NULL"))) => p,
            _ => return None,
        };
        // (`st::varlen`'s address of an array passed to a function's or method's ARRAY [*])
        // (and a `REFERENCE TO` input of the block's own method bound for one call)
        let call_scoped = self.per_call_target
            || matches!(&e.kind, ExprKind::Call { name, .. }
            if name.is(super::varlen::CALL_ADDRESS) || name.is(super::refs::REF_ASSIGN_CALL));
        match self.place_operand(place, out, diags)? {
            Operand::Var(v) => Some(Operand::Ref(Box::new(il::RefOperand {
                of: Some(v),
                span: e.span,
                call_scoped,
                address_of: matches!(&e.kind, ExprKind::Call { name, .. } if name.is("ADR")),
            }))),
            other => {
                diags.push(
                    Diagnostic::error(code::E0305, "a reference must refer to a variable")
                        .at(other.span())
                        .with_primary_label("no variable")
                        .with_hint("refer to a variable, an array element or a structure field (a direct address has no reference)"),
                );
                self.poisoned = true;
                None
            }
        }
    }

    fn pure_operand(&self, e: &Expr) -> Option<Operand> {
        match &e.kind {
            ExprKind::Literal(l) => Some(Operand::literal(l.clone())),
            ExprKind::EnumValue { type_name, value } => Some(Operand::enum_value(
                type_name.clone(),
                value.clone(),
                e.span,
            )),
            ExprKind::Place(p) => self.pure_place(p),
            _ => None,
        }
    }

    fn pure_place(&self, p: &Place) -> Option<Operand> {
        if let Some((t, v)) = self.env().qualified_enum_value(p) {
            return Some(Operand::enum_value(t, v, p.span));
        }
        let base = match &p.base {
            PlaceBase::Address(a) if p.accessors.is_empty() => {
                return Some(Operand::Address(a.clone()))
            }
            PlaceBase::Address(_) => return None,
            PlaceBase::Name(n) => n.clone(),
        };
        if p.accessors.is_empty() && base.is("NULL") && self.env().var_type(&base).is_none() {
            return Some(Operand::reference(None, p.span));
        }
        let derefs = self.implicit_derefs_of(p);
        Self::accessed_variable(base, p, &derefs, |a| match a {
            Accessor::Index(ix) => Some(il::Accessor::Index(
                ix.iter()
                    .map(|e| self.pure_operand(e))
                    .collect::<Option<Vec<_>>>()?,
            )),
            _ => None,
        })
    }

    /// The positions among `p`'s accessors (its length: after the last) where a `REFERENCE TO`
    /// leaves its `^` out; none unless the program declares a `REFERENCE TO`.
    fn implicit_derefs_of(&self, p: &Place) -> Vec<usize> {
        if self.reference_to {
            self.env().implicit_derefs(p, self.raw_refs)
        } else {
            Vec::new()
        }
    }

    /// The operand for a place; index expressions that are not plain operands are computed into
    /// temporaries first (code goes to `out`, where the current result must be free).
    fn place_operand(
        &mut self,
        p: &Place,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) -> Option<Operand> {
        if let Some(o) = self.pure_place(p) {
            return Some(o);
        }
        let base = match &p.base {
            PlaceBase::Name(n) => n.clone(),
            PlaceBase::Address(a) => {
                diags.push(
                    Diagnostic::error(code::E3100, "a direct address has no fields or elements")
                        .at(a.span)
                        .with_primary_label("direct address"),
                );
                self.poisoned = true;
                // The address itself stands in (the body is poisoned): a `None` here sent
                // `operand` back to `value`, which asked `operand` again, without end.
                return Some(Operand::Address(a.clone()));
            }
        };
        let derefs = self.implicit_derefs_of(p);
        Self::accessed_variable(base, p, &derefs, |a| match a {
            Accessor::Index(ix) => {
                let mut ops = Vec::new();
                for e in ix {
                    ops.push(self.operand(e, Some(&named("DINT", e.span)), out, diags));
                }
                Some(il::Accessor::Index(ops))
            }
            // every chain is taken apart before its statement is lowered (call_chain); one
            // left here stands where no statement could run its calls first
            Accessor::Call { span, .. } => {
                diags.push(
                    Diagnostic::error(
                        code::E0349,
                        "a method's result cannot be accessed here",
                    )
                    .at(*span)
                    .with_hint("call the method in a statement before, store its result in a variable and access that"),
                );
                self.poisoned = true;
                None
            }
            _ => None,
        })
    }

    /// The variable `base` with the accessors of place `p` (its fields and `^` as written), a `^`
    /// inserted before each accessor whose position is among `derefs` (its length: after the
    /// last), where a `REFERENCE TO` leaves it out ([`Self::implicit_derefs_of`]); `computed`
    /// lowers the accessors that need it, an index (`[i + 1]`) and a method's result (`.M()`), in
    /// order: `None` when it gives none.
    fn accessed_variable(
        base: Ident,
        p: &Place,
        derefs: &[usize],
        mut computed: impl FnMut(&Accessor) -> Option<il::Accessor>,
    ) -> Option<Operand> {
        let mut accessors = Vec::new();
        for (k, a) in p.accessors.iter().enumerate() {
            if derefs.contains(&k) {
                accessors.push(il::Accessor::Deref(p.span));
            }
            accessors.push(match a {
                Accessor::Field(f) => il::Accessor::Field(f.clone()),
                Accessor::Deref(s) => il::Accessor::Deref(*s),
                Accessor::Index(_) | Accessor::Call { .. } => computed(a)?,
            });
        }
        if derefs.contains(&p.accessors.len()) {
            accessors.push(il::Accessor::Deref(p.span));
        }
        Some(Operand::Var(VarRef {
            base,
            accessors: accessors.into(),
            span: p.span,
        }))
    }

    /// An operand holding the value of `e`: the plain operand, or a temporary computed into `out`
    /// (where the current result must be free). `hint` types a temporary for an untyped literal.
    fn operand(
        &mut self,
        e: &Expr,
        hint: Option<&TypeRef>,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) -> Operand {
        if let Some(o) = self.reference(e, hint, out, diags) {
            return o;
        }
        if let Some(o) = self.enum_by_context(e, hint) {
            return o;
        }
        if let ExprKind::Place(p) = &e.kind {
            if let Some(o) = self.place_operand(p, out, diags) {
                return o;
            }
        }
        if let Some(o) = self.pure_operand(e) {
            return o;
        }
        let ty = self.temp_type(e, hint);
        self.lit_hint = Some(ty.clone());
        self.value(e, out, diags);
        let t = self.temp(ty, e.span);
        out.push(simple(Op::St, false, Some(var_operand(&t)), e.span));
        var_operand(&t)
    }

    /// Code that leaves the value of `e` in the current result; `out` must be at a point where the
    /// current result is free.
    fn value(&mut self, e: &Expr, out: &mut Vec<IlStmt>, diags: &mut Diagnostics) {
        if self.nested == 0 {
            if let Some(plain) = self.short_circuits(e, out, diags) {
                self.value(&plain, out, diags);
                self.types.get_mut().clear();
                return;
            }
        }
        let hint = self.lit_hint.take();
        // IEC 61131-3: integer literals are ANY_INT, so a division of them is an integer division
        // (`7 / 2` is 3), even where the context is REAL: computed as LINT, then converted.
        let real_context = hint
            .as_ref()
            .and_then(|h| self.env().elementary(h))
            .filter(|x| x.is_real());
        if let Some(real) = real_context {
            if matches!(self.ty(e), Ty::IntLit) && divides_integers(e) {
                self.lit_hint = Some(named("LINT", e.span));
                self.value(e, out, diags);
                out.push(instr(
                    InstrKind::FunctionCall {
                        name: Ident::new(format!("LINT_TO_{}", real.name()), e.span),
                        args: Box::new(CallArgs::None),
                    },
                    e.span,
                ));
                return;
            }
        }
        if matches!(e.kind, ExprKind::Literal(_)) {
            // `p := 0` for a POINTER TO: NULL
            if let Some(o) = self.reference(e, hint.as_ref(), out, diags) {
                out.push(ld(o, e.span));
                return;
            }
        }
        match &e.kind {
            ExprKind::Error => {
                self.poisoned = true;
            }
            ExprKind::Literal(l) if l.type_prefix.is_none() && hint.is_some() => {
                let mut l = l.clone();
                if let (LiteralKind::Int(_) | LiteralKind::Real(_), Some(TypeRef::Named(t))) =
                    (&l.kind, &hint)
                {
                    // The prefix is the elementary type (a subrange or alias `Level` gives its
                    // base `INT#`: a derived type name is no literal prefix).
                    let numeric = self
                        .env()
                        .elementary(&TypeRef::Named(t.clone()))
                        .filter(|x| {
                            x.is_numeric() && (x.is_real() || matches!(l.kind, LiteralKind::Int(_)))
                        });
                    if let Some(x) = numeric {
                        l.type_prefix = Some(Ident::new(x.name(), l.span));
                    }
                }
                out.push(ld(Operand::literal(l), e.span));
            }
            ExprKind::Literal(_) | ExprKind::EnumValue { .. } | ExprKind::Place(_) => {
                let o = self.operand(e, hint.as_ref(), out, diags);
                out.push(ld(o, e.span));
            }
            ExprKind::Unary { op, operand } => match op {
                UnaryOp::Plus => {
                    self.lit_hint = hint;
                    self.value(operand, out, diags)
                }
                UnaryOp::Not => {
                    if let Some(o) = self.pure_operand(operand) {
                        out.push(simple(Op::Ld, true, Some(o), e.span));
                    } else {
                        self.value(operand, out, diags);
                        out.push(simple(Op::Not, false, None, e.span));
                    }
                }
                UnaryOp::Neg => {
                    self.lit_hint = hint;
                    self.value(operand, out, diags);
                    let real = match self.ty(operand) {
                        Ty::RealLit => true,
                        Ty::Known(t) => self.env().elementary(&t).is_some_and(|x| x.is_real()),
                        _ => false,
                    };
                    let minus_one = Operand::literal(Literal {
                        kind: if real {
                            LiteralKind::Real(-1.0)
                        } else {
                            LiteralKind::Int(-1)
                        },
                        type_prefix: None,
                        span: e.span,
                    });
                    out.push(simple(Op::Mul, false, Some(minus_one), e.span));
                }
            },
            ExprKind::Binary { .. } => self.binary_chain(e, hint, out, diags),
            ExprKind::Call { name, args } => {
                self.function_call(name, args, hint, e.span, out, diags)
            }
        }
    }

    /// A binary operation: its left operands are a chain as long as the source line (`a + b + c ...`
    /// parses as `((a + b) + c) ...`), so the chain is walked with a loop: down the left operands
    /// (computing each level's literal hints and, for `**`, its exponent), then the innermost left
    /// operand, then each level's operator back up. Right operands nest only as deep as the parser
    /// allows (parentheses, calls and unary operators are capped there).
    fn binary_chain(
        &mut self,
        top: &Expr,
        mut hint: Option<TypeRef>,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) {
        enum Then<'e> {
            Apply(Op, &'e Expr, Option<TypeRef>, Span),
            Expt(Operand, Span),
            /// `b + 256` (b : USINT): the literal in the type that holds it (`UINT#256`)
            Literal(Op, Operand, Span),
        }
        let mut pending = Vec::new();
        let mut e = top;
        while let ExprKind::Binary { op, left, right } = &e.kind {
            let (left, right) = if *op == BinaryOp::Mul && self.number_times_duration(left, right) {
                (right, left)
            } else {
                (left, right)
            };
            match binop(*op) {
                Some(il_op) => {
                    let (lt, rt) = (self.ty(left), self.ty(right));
                    let cmp = matches!(il_op, Op::Eq | Op::Ne | Op::Lt | Op::Gt | Op::Le | Op::Ge);
                    let ctx = if cmp { None } else { hint };
                    // a literal beside a typed operand takes its type, or the smallest type
                    // that type widens to and that holds it (`256 * b`, b : USINT: UINT#256)
                    let env = self.env();
                    let beside = |t: &TypeRef, lit: &Expr| {
                        env.literal_widened(t, lit).unwrap_or_else(|| t.clone())
                    };
                    let right_hint = match rt {
                        Ty::Known(_) => None,
                        _ => lt.known().map(|t| beside(t, right)).or(ctx.clone()),
                    };
                    let widened = lt
                        .known()
                        .and_then(|t| env.literal_widened(t, right))
                        .and_then(|t| prefixed_literal(right, &t));
                    hint = match lt {
                        Ty::Known(_) => None,
                        _ => rt.known().map(|t| beside(t, left)).or(ctx),
                    };
                    pending.push(match widened {
                        Some(o) => Then::Literal(il_op, o, e.span),
                        None => Then::Apply(il_op, right, right_hint, e.span),
                    });
                }
                None => {
                    // a ** b: EXPT with the current result as IN1 (ANY_REAL).
                    let exp = self.operand(right, None, out, diags);
                    hint = match self.ty(left) {
                        Ty::Known(_) => None,
                        _ => Some(hint.unwrap_or_else(|| named("LREAL", left.span))),
                    };
                    pending.push(Then::Expt(exp, e.span));
                }
            }
            e = left;
        }
        self.lit_hint = hint;
        self.value(e, out, diags);
        for then in pending.into_iter().rev() {
            match then {
                Then::Apply(op, right, right_hint, span) => {
                    self.apply(op, right, right_hint, span, out, diags)
                }
                Then::Literal(op, o, span) => out.push(simple(op, false, Some(o), span)),
                Then::Expt(exp, span) => out.push(instr(
                    InstrKind::FunctionCall {
                        name: Ident::new("EXPT", span),
                        args: Box::new(CallArgs::NonFormal(vec![exp])),
                    },
                    span,
                )),
            }
        }
    }

    /// `LOWER_BOUND(arr, dim)` / `UPPER_BOUND(arr, dim)` (IEC 61131-3 edition 3, the bounds of an
    /// array, DINT): `arr` a declared array (a variable, a field, an element of an array of arrays),
    /// `dim` an integer literal from 1 to its number of dimensions. The bounds are known when
    /// compiling, so the call is that DINT constant. Anything else is one E1070 (the call reads 0).
    fn array_bound(
        &mut self,
        name: &Ident,
        args: &[Arg],
        span: Span,
        diags: &mut Diagnostics,
    ) -> Operand {
        let upper = name.is("UPPER_BOUND");
        let dims = match args {
            [Arg {
                name: None,
                value:
                    Expr {
                        kind: ExprKind::Place(p),
                        ..
                    },
                ..
            }, Arg {
                name: None,
                value: dim,
                ..
            }] => {
                let env = self.env();
                if env.of_unknown_type(p) {
                    // (`pos.v` with `pos` of a type nothing declares: that type's error says it)
                    self.poisoned = true;
                    return int_lit(0, span);
                }
                match env.place_type(p).map(|t| env.resolve(&t)) {
                    Some(TypeRef::Array { dims, .. }) => {
                        if let ExprKind::Literal(Literal {
                            kind: LiteralKind::Int(k),
                            ..
                        }) = &dim.kind
                        {
                            if *k >= 1 && *k <= dims.len() as i128 {
                                let d = &dims[(*k - 1) as usize];
                                if d.is_variable() {
                                    // a misplaced `ARRAY [*]` (sema's E1072): its bounds are
                                    // no number, and nothing more is said here
                                    self.poisoned = true;
                                    return int_lit(0, span);
                                }
                                return Operand::literal(Literal {
                                    kind: LiteralKind::Int(if upper { d.upper } else { d.lower }),
                                    type_prefix: Some(Ident::new("DINT", span)),
                                    span,
                                });
                            }
                        }
                        Some(dims.len())
                    }
                    _ => None,
                }
            }
            _ => None,
        };
        let message = match dims {
            Some(n) => format!(
                "`{}`: the dimension must be an integer literal from 1 to {n}",
                name.name
            ),
            None => format!(
                "`{}` takes a declared array and the number of one of its dimensions",
                name.name
            ),
        };
        diags.push(
            Diagnostic::error(code::E1070, message)
                .at(span)
                .with_primary_label("not an array and a dimension")
                .with_hint(format!(
                    "write `{}(arr, 1)` for the first dimension of `arr`",
                    name.name
                )),
        );
        self.poisoned = true;
        int_lit(0, span)
    }

    /// `2 * tCycle`: a number times a duration, both plain operands (a literal, a variable).
    /// IEC 61131-3 defines MUL_TIME as TIME * ANY_NUM only; CODESYS and TwinCAT also accept the
    /// number first, and real projects write it (`PT := 2 * tCycletime`). Multiplication
    /// commutes and plain operands have no side effects, so it is lowered as `tCycle * 2`.
    fn number_times_duration(&self, left: &Expr, right: &Expr) -> bool {
        let env = self.env();
        let duration = |t: &Ty| {
            t.known()
                .and_then(|t| env.elementary(t))
                .is_some_and(|e| e.is_duration())
        };
        let number = |t: &Ty| match t {
            Ty::IntLit | Ty::RealLit => true,
            Ty::Known(t) => env.elementary(t).is_some_and(|e| e.is_numeric()),
            Ty::Unknown => false,
        };
        duration(&self.ty(right))
            && number(&self.ty(left))
            && self.pure_operand(left).is_some()
            && self.pure_operand(right).is_some()
    }

    /// `OP right` applied to the current result: a plain operand directly, anything else as a
    /// deferred operator whose nested list computes `right`.
    fn apply(
        &mut self,
        op: Op,
        right: &Expr,
        hint: Option<TypeRef>,
        span: Span,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) {
        if matches!(right.kind, ExprKind::Literal(_)) {
            // `p <> 0` for a POINTER TO: NULL
            if let Some(o) = self.reference(right, hint.as_ref(), out, diags) {
                out.push(simple(op, false, Some(o), span));
                return;
            }
        }
        if let Some(o) = self
            .enum_by_context(right, hint.as_ref())
            .or_else(|| self.pure_operand(right))
        {
            out.push(simple(op, false, Some(o), span));
            return;
        }
        let mut body = Vec::new();
        self.lit_hint = hint;
        self.nested += 1;
        self.value(right, &mut body, diags);
        self.nested -= 1;
        // `ADD( x` ...: the nested list's first load goes on the opening line.
        let operand = match body.first() {
            Some(IlStmt::Instr(Instruction {
                kind:
                    InstrKind::Simple {
                        op: Op::Ld,
                        negate: false,
                        operand: Some(_),
                    },
                ..
            })) => match &mut body.remove(0) {
                IlStmt::Instr(Instruction {
                    kind: InstrKind::Simple { operand, .. },
                    ..
                }) => operand.take(),
                _ => None,
            },
            _ => None,
        };
        out.push(instr(
            InstrKind::Deferred {
                op,
                negate: false,
                operand: operand.map(Box::new),
                body,
                close: right.span,
            },
            span,
        ));
    }

    /// Whether `e` is an array or a structure (a value IL does not load into the current result).
    fn is_aggregate(&self, e: &Expr) -> bool {
        let env = self.env();
        match self.ty(e).known().map(|t| env.resolve(t)) {
            Some(TypeRef::Array { .. }) => true,
            Some(TypeRef::Named(n)) => self
                .decls
                .type_decl(&n.name)
                .is_some_and(|d| matches!(d.def, crate::ast::TypeDef::Struct { .. })),
            _ => false,
        }
    }

    fn resolve_callee(&self, name: &Ident) -> Callee {
        if let Some(p) = self.decls.pou(&name.name) {
            if p.kind == PouKind::Function {
                return Callee::UserFunction(p.params().cloned().collect());
            }
        }
        match stdlib::function(&name.name) {
            Some(f) => Callee::Standard(f),
            None => Callee::Other,
        }
    }

    /// A formal call of a standard function that leaves inputs out (`MOVE(EN := go, ENO => ok)`,
    /// as Beremiz writes an LD `MOVE` whose `IN` pin is open): the arguments with each input left
    /// out given its type's initial value, `0` (`FALSE` for a BOOL input), the untyped literal
    /// taking the call's type (IEC 61131-3 ed. 3, 6.6.1.2; matiec compiles it so). `None` when
    /// nothing is left out, or the call is not formal.
    fn omitted_standard_inputs(&self, name: &Ident, args: &[Arg]) -> Option<Vec<Arg>> {
        if self.decls.pou(&name.name).is_some() || args.is_empty() {
            return None;
        }
        let f = stdlib::function(&name.name)?;
        if f.extensible || args.iter().any(|a| a.name.is_none()) {
            return None;
        }
        // a name that is no input of the function: its own error, nothing added here
        if args.iter().any(|a| {
            a.name
                .as_ref()
                .is_some_and(|n| !n.is("EN") && !n.is("ENO") && f.param_index(&n.name).is_none())
        }) {
            return None;
        }
        // (an input given under a vendor's name, `LEFT(STR := s, SIZE := 3)`, counts as given)
        let given: Vec<usize> = args
            .iter()
            .filter_map(|a| a.name.as_ref().and_then(|n| f.param_index(&n.name)))
            .collect();
        let missing: Vec<&stdlib::Param> = f
            .params
            .iter()
            .enumerate()
            .filter(|(k, _)| !given.contains(k))
            .map(|(_, p)| p)
            .collect();
        if missing.is_empty() {
            return None;
        }
        let at = name.span;
        let mut with = args.to_vec();
        with.extend(missing.into_iter().map(|p| Arg {
            name: Some(Ident::new(p.name, at)),
            dir: ArgDir::Input,
            value: Expr::literal(
                if matches!(p.ty, ParamTy::Fixed(crate::sema::Elementary::Bool)) {
                    LiteralKind::Bool(false)
                } else {
                    LiteralKind::Int(0)
                },
                at,
            ),
            span: at,
        }));
        Some(with)
    }

    fn function_call(
        &mut self,
        name: &Ident,
        args: &[Arg],
        context: Option<TypeRef>,
        span: Span,
        out: &mut Vec<IlStmt>,
        diags: &mut Diagnostics,
    ) {
        let dropped = std::mem::take(&mut self.result_dropped);
        // CODESYS/TwinCAT dynamic memory (`__NEW(BYTE)`: a type name for argument): the call is
        // lowered without its arguments, so that one E0351 is all that is said of it
        let args: &[Arg] =
            if (name.is("__NEW") || name.is("__DELETE")) && self.decls.pou(&name.name).is_none() {
                &[]
            } else {
                args
            };
        if !dropped
            && self
                .decls
                .pou(&name.name)
                .is_some_and(|p| p.kind == PouKind::Function && p.ret.is_none())
            && self.env().var_type(name).is_none()
        {
            // (a body that assigns the function's name has its own E0354, which says it all)
            if self.decls.assigns_missing_result.contains(&name.key()) {
                self.poisoned = true;
                return;
            }
            diags.push(
                Diagnostic::error(
                    code::E0354,
                    format!("function `{}` returns no value", name.name),
                )
                .at(span)
                .with_primary_label("its value is used here")
                .with_hint(format!(
                    "call it as a statement (`{}(...);`) and read what it writes to its VAR_IN_OUT or VAR_OUTPUT parameters, or give it a result type (`FUNCTION {} : LREAL`)",
                    name.name, name.name
                )),
            );
            self.poisoned = true;
            return;
        }
        let with_names;
        let callee = Place {
            base: PlaceBase::Name(name.clone()),
            accessors: Vec::new(),
            span: name.span,
        };
        let args = match self.name_positional_args(&callee, args, diags) {
            Some(n) => {
                with_names = n;
                &with_names[..]
            }
            None => args,
        };
        let with_defaults;
        let args = match self.omitted_standard_inputs(name, args) {
            Some(a) => {
                with_defaults = a;
                &with_defaults[..]
            }
            None => args,
        };
        let call = Expr {
            kind: ExprKind::Call {
                name: name.clone(),
                args: args.to_vec(),
            },
            span,
        };
        if let Some(o) = self.reference(&call, None, out, diags) {
            out.push(ld(o, span));
            return;
        }
        if self.decls.pou(&name.name).is_none() && self.memory_call(name, args, span, out, diags) {
            return;
        }
        if (name.is("SIZEOF") || name.is("XSIZEOF")) && self.decls.pou(&name.name).is_none() {
            // `SIZEOF(x)`, `SIZEOF(arr[1])`, `SIZEOF(T)` (CODESYS, TwinCAT; TwinCAT's XSIZEOF is
            // the same size, typed for the platform): one operand, a variable (its accesses
            // lowered as any place's) or a type name (sema tells them apart)
            if let [Arg {
                name: None,
                value:
                    Expr {
                        kind: ExprKind::Place(p),
                        ..
                    },
                ..
            }] = args
            {
                let of = match p.name() {
                    Some(n) if p.accessors.is_empty() => Some(il::VarRef {
                        base: n.clone(),
                        accessors: Default::default(),
                        span: p.span,
                    }),
                    _ => match self.place_operand(p, out, diags) {
                        Some(Operand::Var(v)) => Some(v),
                        _ => None,
                    },
                };
                if let Some(of) = of {
                    out.push(ld(
                        Operand::SizeOf(Box::new(il::SizeOfOperand { of, span })),
                        span,
                    ));
                    return;
                }
            }
            // `SIZEOF(STRING(255))`: the type STRING of that length; every STRING (WSTRING) of
            // ladderc has one size whatever its length (README, memory model)
            if let [Arg {
                name: None,
                value:
                    Expr {
                        kind:
                            ExprKind::Call {
                                name: ty,
                                args: len,
                            },
                        ..
                    },
                ..
            }] = args
            {
                if (ty.is("STRING") || ty.is("WSTRING")) && len.len() == 1 {
                    let of = il::VarRef {
                        base: ty.clone(),
                        accessors: Default::default(),
                        span: ty.span,
                    };
                    out.push(ld(
                        Operand::SizeOf(Box::new(il::SizeOfOperand { of, span })),
                        span,
                    ));
                    return;
                }
            }
            diags.push(
                Diagnostic::error(code::E1034, "`SIZEOF` takes one variable or one type name")
                    .at(span)
                    .with_primary_label("not one variable or type")
                    .with_hint(
                        "write `SIZEOF(x)`, `SIZEOF(a[1])`, `SIZEOF(st.field)` or `SIZEOF(INT)`",
                    ),
            );
            self.poisoned = true;
            out.push(ld(int_lit(0, span), span));
            return;
        }
        if (name.is("LOWER_BOUND") || name.is("UPPER_BOUND"))
            && self.decls.pou(&name.name).is_none()
        {
            let v = self.array_bound(name, args, span, diags);
            out.push(ld(v, span));
            return;
        }
        if name.is(super::refs::IS_VALID_REF) {
            // `__ISVALIDREF(r)`: `r <> NULL`, `r` the reference itself
            let [Arg {
                name: None,
                value:
                    Expr {
                        kind: ExprKind::Place(p),
                        ..
                    },
                ..
            }] = args
            else {
                diags.push(
                    Diagnostic::error(code::E3103, "`__ISVALIDREF` takes one reference variable")
                        .at(span)
                        .with_primary_label("called here")
                        .with_hint("write `__ISVALIDREF(r)` with `r` a REFERENCE TO, REF_TO or POINTER TO variable"),
                );
                self.poisoned = true;
                return;
            };
            self.raw_refs = true;
            let r = self.place_operand(p, out, diags);
            self.raw_refs = false;
            if let Some(r) = r {
                out.push(ld(r, span));
                let null = Operand::reference(None, span);
                out.push(simple(Op::Ne, false, Some(null), span));
            }
            return;
        }
        if let Some(t) = self
            .env()
            .var_type(name)
            .filter(|_| !self.function_beside_global(name))
        {
            let fb = self.env().is_fb_type(&t);
            diags.push(
                Diagnostic::error(
                    code::E3103,
                    if fb {
                        format!("function block instance `{}` cannot be called inside an expression", name.name)
                    } else {
                        format!("`{}` is a variable, not a function", name.name)
                    },
                )
                .at(span)
                .with_primary_label("called here")
                .with_hint(if fb {
                    "call the instance as a statement (`inst(...);`), then read its outputs (`inst.Q`)"
                } else {
                    "remove the parentheses to read the variable"
                }),
            );
            self.poisoned = true;
            return;
        }
        let callee = self.resolve_callee(name);
        // `TRUNC` takes its integer type from its context (`i := TRUNC(r)`, `INT_TO_WORD(TRUNC(r))`,
        // `TRUNC(r) * 2` into an INT): edition 3's `TRUNC_INT`; without an integer context DINT
        let typed_trunc = name
            .name
            .eq_ignore_ascii_case("TRUNC")
            .then(|| context.as_ref().and_then(|c| self.env().elementary(c)))
            .flatten()
            .filter(|e| e.is_integer())
            .map(|e| Ident::new(format!("TRUNC_{}", e.name()), name.span));
        let name = typed_trunc.as_ref().unwrap_or(name);
        let has_output = args.iter().any(|a| matches!(a.dir, ArgDir::Output { .. }));
        let ordered = if has_output {
            None
        } else {
            positional(&callee, args)
        };
        // A formal call whose first input is an array or a structure stays formal: in the operator
        // form that value would have to travel through the current result.
        let formal = args.iter().any(|a| a.name.is_some());
        let ordered = ordered
            .filter(|list| !formal || list.first().is_none_or(|a| !self.is_aggregate(&a.value)));
        // A generic standard function whose result is its inputs' type (LIMIT, MAX, SEL, ...) and
        // none of whose generic inputs is typed takes the type of its context (IEC 61131-3: untyped
        // literals take their type from the context), so `r := MAX(1.0, 0.5 ** 2.0)` is REAL.
        let fname = name;
        let hint_of =
            |env: &Env, callee: &Callee, k: usize, name: Option<&Ident>, args: &[&Arg]| {
                param_hint(env, callee, k, name, args).or_else(|| match callee {
                    // a typed conversion's input (`INT_TO_WORD(TRUNC(r))`, `INT_TO_WORD(5)`)
                    Callee::Other if k == 0 => stdlib::conversion(&fname.name)
                        .and_then(|c| c.from)
                        .and_then(|t| t.elementary())
                        .map(|e| named(e.name(), fname.span)),
                    Callee::Standard(f) if matches!(f.result, Ret::T) => {
                        let idx = match name {
                            Some(n) => f.param_index(&n.name)?,
                            None => k,
                        };
                        matches!(f.param_ty(idx)?, ParamTy::T(_))
                            .then(|| context.clone())
                            .flatten()
                    }
                    _ => None,
                })
            };
        match ordered {
            Some(list) if !list.is_empty() => {
                let mut ops = Vec::new();
                for k in 1..list.len() {
                    let hint = hint_of(&self.env(), &callee, k, None, &list);
                    ops.push(self.operand(&list[k].value, hint.as_ref(), out, diags));
                }
                let first = hint_of(&self.env(), &callee, 0, None, &list);
                // a first input `REFERENCE TO T` given a variable: its address (as any other input)
                if let Some(o) = self.reference(&list[0].value, first.as_ref(), out, diags) {
                    out.push(ld(o, list[0].value.span));
                } else {
                    self.lit_hint =
                        first.filter(|_| !matches!(self.ty(&list[0].value), Ty::Known(_)));
                    self.value(&list[0].value, out, diags);
                }
                out.push(instr(
                    InstrKind::FunctionCall {
                        name: name.clone(),
                        args: Box::new(if ops.is_empty() {
                            CallArgs::None
                        } else {
                            CallArgs::NonFormal(ops)
                        }),
                    },
                    span,
                ));
            }
            _ => {
                let all: Vec<&Arg> = args.iter().collect();
                let callee2 = self.resolve_callee(name);
                self.unknown_callee =
                    matches!(callee2, Callee::Other) && self.decls.pou(&name.name).is_none();
                self.callee_in_outs(&name.name);
                let args = match self.call_args(
                    args,
                    |env, n, k| hint_of(env, &callee2, k, Some(n), &all),
                    out,
                    diags,
                ) {
                    // `f()`: a call without arguments reads no current result (an empty formal
                    // list; the operator form would take the current result as the first input).
                    CallArgs::None => CallArgs::Formal(Vec::new()),
                    a => a,
                };
                out.push(instr(
                    InstrKind::FunctionCall {
                        name: name.clone(),
                        args: Box::new(args),
                    },
                    span,
                ));
            }
        }
    }
}

/// The arguments in parameter order when the call can use the IL operator form: all non-formal, or
/// formal inputs of a known signature, every input given (then the first goes into the current result).
fn positional<'a>(callee: &Callee, args: &'a [Arg]) -> Option<Vec<&'a Arg>> {
    if args.iter().all(|a| a.name.is_none()) {
        return Some(args.iter().collect());
    }
    let names: Vec<String> = match callee {
        Callee::Standard(f) if !f.extensible => {
            f.params.iter().map(|p| p.name.to_string()).collect()
        }
        Callee::UserFunction(ps) => ps
            .iter()
            .filter(|p| p.1 == VarKind::Input)
            .map(|p| p.0.clone())
            .collect(),
        _ => return None,
    };
    let mut v = Vec::new();
    for n in &names {
        v.push(
            args.iter()
                .find(|a| a.name.as_ref().is_some_and(|x| x.is(n)))?,
        );
    }
    (v.len() == args.len()).then_some(v)
}

/// The type a temporary for argument `k` (or the named input) of a call should get.
fn param_hint(
    env: &Env,
    callee: &Callee,
    k: usize,
    name: Option<&Ident>,
    args: &[&Arg],
) -> Option<TypeRef> {
    match callee {
        Callee::UserFunction(ps) => match name {
            Some(n) => ps.iter().find(|p| n.is(&p.0)).map(|p| p.2.clone()),
            None => ps
                .iter()
                .filter(|p| p.1 == VarKind::Input)
                .nth(k)
                .map(|p| p.2.clone()),
        },
        Callee::Standard(f) => {
            let idx = match name {
                Some(n) => f.param_index(&n.name)?,
                None => k,
            };
            match f.param_ty(idx)? {
                ParamTy::Fixed(e) => Some(named(e.name(), args[0].span)),
                ParamTy::Own(_) => None,
                ParamTy::T(_) => {
                    // The generic type: the first typed argument among the T inputs.
                    args.iter().enumerate().find_map(|(i, a)| {
                        let ai = match &a.name {
                            Some(n) => f.param_index(&n.name)?,
                            None => i,
                        };
                        matches!(f.param_ty(ai), Some(ParamTy::T(_)))
                            .then(|| env.expr(&a.value).known().cloned())
                            .flatten()
                    })
                }
            }
        }
        Callee::Other => None,
    }
}

/// Whether the code ends with an unconditional jump or return (code after it would be unreachable).
fn ends_with_transfer(out: &[IlStmt]) -> bool {
    matches!(
        out.last(),
        Some(IlStmt::Instr(Instruction {
            kind: InstrKind::Jump {
                cond: Condition::Always,
                ..
            } | InstrKind::Return {
                cond: Condition::Always
            },
            ..
        }))
    )
}

/// The integer value of a literal (also `-5`), for FOR bounds and steps.
fn literal_value(e: &Expr) -> Option<i128> {
    match &e.kind {
        ExprKind::Literal(Literal {
            kind: LiteralKind::Int(v),
            ..
        }) => Some(*v),
        _ => None,
    }
}

/// How a type reads in a message.
fn type_text(t: &TypeRef) -> String {
    match t {
        TypeRef::Named(n) => n.name.clone(),
        TypeRef::String { wide: false, .. } => "STRING".into(),
        TypeRef::String { wide: true, .. } => "WSTRING".into(),
        TypeRef::Array { .. } => "an array".into(),
        TypeRef::Subrange { base, .. } => format!("a subrange of {}", base.name),
        TypeRef::Enum { .. } => "an enumeration".into(),
        TypeRef::Ref { kind, .. } => format!("a reference ({})", kind.keyword()),
    }
}

/// Whether an expression of integer literals holds an integer division (`/` or `MOD`) and no `**`
/// (whose operand must be real). Walked with a stack: chains can be long.
fn divides_integers(e: &Expr) -> bool {
    let mut stack = vec![e];
    let mut divides = false;
    while let Some(e) = stack.pop() {
        match &e.kind {
            ExprKind::Binary { op, left, right } => {
                match op {
                    BinaryOp::Div | BinaryOp::Mod => divides = true,
                    BinaryOp::Power => return false,
                    _ => {}
                }
                stack.push(left);
                stack.push(right);
            }
            ExprKind::Unary { operand, .. } => stack.push(operand),
            ExprKind::Literal(_) => {}
            // a value whose type the lowering does not know (`Axis.NcToPlc.ActPos`, read by
            // the Tc2_MC2 pass): not a literal, so no integer division is forced on it
            _ => return false,
        }
    }
    divides
}

/// Where `body` writes the FOR control variable `control` (W3141): an assignment to the variable
/// itself (not to a field or element of it) and a nested FOR that counts with it, at any depth.
fn writes_of_control(control: &Ident, body: &[Stmt], found: &mut Vec<Span>) {
    let is_control = |id: &Ident| id.name.eq_ignore_ascii_case(&control.name);
    for s in body {
        match &s.kind {
            StmtKind::Assign { target, .. } => {
                if let PlaceBase::Name(id) = &target.base {
                    if target.accessors.is_empty() && is_control(id) {
                        found.push(target.span);
                    }
                }
            }
            StmtKind::If {
                branches,
                else_body,
            } => {
                for b in branches {
                    writes_of_control(control, &b.body, found);
                }
                writes_of_control(control, else_body.as_deref().unwrap_or_default(), found);
            }
            StmtKind::Case {
                arms, else_body, ..
            } => {
                for a in arms {
                    writes_of_control(control, &a.body, found);
                }
                writes_of_control(control, else_body.as_deref().unwrap_or_default(), found);
            }
            StmtKind::For {
                control: inner,
                body,
                ..
            } => {
                if is_control(inner) {
                    // the inner loop reports the writes in its own body
                    found.push(inner.span);
                } else {
                    writes_of_control(control, body, found);
                }
            }
            StmtKind::While { body, .. } | StmtKind::Repeat { body, .. } => {
                writes_of_control(control, body, found);
            }
            _ => {}
        }
    }
}

/// What a CASE label selects, for the overlap warning W3140: an integer range, or an enumerated
/// value by name (`red`, `Color#red`).
enum LabelKey {
    Ints(i128, i128),
    Enum(String),
}

/// The labels of one CASE seen so far, for W3140: single values and enumerated values are looked
/// up in logarithmic or constant time; ranges are compared one by one, up to [`MAX_CASE_RANGES`]
/// of them (a generated CASE of thousands of ranges is not compared quadratically).
#[derive(Default)]
struct LabelSet {
    singles: std::collections::BTreeMap<i128, Span>,
    ranges: Vec<(i128, i128, Span)>,
    enums: HashMap<String, Span>,
}

/// How many ranges of one CASE are compared with the labels after them.
const MAX_CASE_RANGES: usize = 1024;

impl LabelSet {
    /// The earliest-seen label among those that share a value with `k` (the first found).
    fn first_overlap(&self, k: &LabelKey) -> Option<Span> {
        match k {
            LabelKey::Enum(n) => self.enums.get(n).copied(),
            LabelKey::Ints(lo, hi) => self
                .ranges
                .iter()
                .find(|(a, b, _)| a <= hi && lo <= b)
                .map(|r| r.2)
                .or_else(|| self.singles.range(*lo..=*hi).next().map(|(_, s)| *s)),
        }
    }
    fn insert(&mut self, k: LabelKey, at: Span) {
        match k {
            LabelKey::Enum(n) => {
                self.enums.entry(n).or_insert(at);
            }
            LabelKey::Ints(lo, hi) if lo == hi => {
                self.singles.entry(lo).or_insert(at);
            }
            LabelKey::Ints(lo, hi) => {
                if self.ranges.len() < MAX_CASE_RANGES {
                    self.ranges.push((lo, hi, at));
                }
            }
        }
    }
}

/// The key of a label `lo..hi` (`lo` = `hi` for a single value); `None` for what is not an integer
/// literal or an enumerated value (a constant's value is not known here).
fn label_key(lo: &Operand, hi: &Operand) -> Option<LabelKey> {
    let int = |o: &Operand| match o {
        Operand::Literal(l) => match l.kind {
            LiteralKind::Int(v) => Some(v),
            _ => None,
        },
        _ => None,
    };
    let name = |o: &Operand| match o {
        Operand::EnumValue(e) => Some(e.value.key()),
        Operand::Var(v) if v.accessors.is_empty() => Some(v.base.key()),
        _ => None,
    };
    match (int(lo), int(hi)) {
        (Some(a), Some(b)) => Some(LabelKey::Ints(a.min(b), a.max(b))),
        _ => {
            let (a, b) = (name(lo)?, name(hi)?);
            (a == b).then_some(LabelKey::Enum(a))
        }
    }
}

/// The index expressions of a place (`a[i, M(2)].b`), for [`PouLowering::hoist_method_calls`].
fn place_exprs<'p>(p: &'p mut Place, out: &mut Vec<&'p mut Expr>) {
    for a in p.accessors.iter_mut() {
        if let Accessor::Index(ix) = a {
            out.extend(ix.iter_mut());
        }
    }
}

/// Whether an assignment's value is B&R's `ACCESS e` (see [`super::refs::ACCESS_ASSIGN`]).
fn is_access_assign(value: &Expr) -> bool {
    matches!(&value.kind, ExprKind::Call { name, .. } if name.is(super::refs::ACCESS_ASSIGN))
}

/// Whether an assignment's value is `REF= x` (see [`super::refs::REF_ASSIGN`]).
fn is_ref_assign(value: &Expr) -> bool {
    matches!(&value.kind, ExprKind::Call { name, .. }
        if name.is(super::refs::REF_ASSIGN) || name.is(super::refs::REF_ASSIGN_CALL))
}

/// The place `THIS^` when `e` is the parser's reading of a bare `THIS` (`ADR(THIS^)`).
fn bare_this(e: &Expr) -> Option<&Place> {
    let ExprKind::Call { name, args } = &e.kind else {
        return None;
    };
    let [Arg {
        name: None,
        value: Expr {
            kind: ExprKind::Place(p),
            ..
        },
        ..
    }] = &args[..]
    else {
        return None;
    };
    (name.is("ADR")
        && matches!(&p.base, PlaceBase::Name(n) if n.is("THIS"))
        && matches!(p.accessors[..], [Accessor::Deref(_)]))
    .then_some(p)
}
