//! Small builders for the IL statements the SFC lowering emits, the hidden declarations it needs, and
//! the renaming pass that maps chart names (`Step.X`, `Step.T`, `Action.Q`, `Action.A`, a sub-body's
//! hidden variables and labels) to the hidden variables of the POU.
//!
//! Input: names and spans. Output: `ast::IlStmt`s and `ast::VarDecl`s (built with `VarDecl::new`).
//! Invariants: hidden names start with `__`, which IEC identifiers cannot, so they never clash with
//! user names; a name is declared once.

use il_frontend::ast::{
    Accessor, ArgDir, CallArgs, Condition, FormalArg, Ident, IlStmt, Initializer, InstrKind,
    Instruction, Literal, LiteralKind, Op, Operand, TypeRef, VarDecl, VarRef,
};
use il_frontend::Span;

pub use il_frontend::rename::Renames;
use std::collections::HashSet;

/// The variable `name` as an operand.
pub fn var(name: &str, span: Span) -> Operand {
    Operand::Var(var_ref(name, span))
}

/// The variable `name` as a variable access.
pub fn var_ref(name: &str, span: Span) -> VarRef {
    VarRef {
        base: Ident::new(name, span),
        accessors: Default::default(),
        span,
    }
}

/// `base.f` as an operand (`Step.X`).
pub fn field(base: &str, f: &str, span: Span) -> Operand {
    Operand::Var(VarRef {
        base: Ident::new(base, span),
        accessors: vec![Accessor::Field(Ident::new(f, span))].into(),
        span,
    })
}

/// The BOOL literal `b`.
pub fn lit_bool(b: bool, span: Span) -> Operand {
    Operand::literal(Literal {
        kind: LiteralKind::Bool(b),
        type_prefix: None,
        span,
    })
}

/// The duration literal of `ns` nanoseconds.
pub fn lit_time(ns: i128, span: Span) -> Operand {
    Operand::literal(Literal {
        kind: LiteralKind::Duration(ns),
        type_prefix: None,
        span,
    })
}

/// An IL simple instruction (`LD`, `ST`, `ANDN` ...) with its `N` modifier.
pub fn simple(op: Op, negate: bool, operand: Option<Operand>, span: Span) -> IlStmt {
    IlStmt::Instr(Instruction {
        kind: InstrKind::Simple {
            op,
            negate,
            operand,
        },
        span,
    })
}

/// `op operand` (`LD x`), spanning the operand.
pub fn op(op: Op, operand: Operand) -> IlStmt {
    let span = operand.span();
    simple(op, false, Some(operand), span)
}

/// `opN operand` (`LDN x`, `ANDN x`), spanning the operand.
pub fn opn(op: Op, operand: Operand) -> IlStmt {
    let span = operand.span();
    simple(op, true, Some(operand), span)
}

/// `OR( first ... )`: the operator applied to the value of a nested list.
pub fn deferred(o: Op, body: Vec<IlStmt>, span: Span) -> IlStmt {
    IlStmt::Instr(Instruction {
        kind: InstrKind::Deferred {
            op: o,
            negate: false,
            operand: None,
            body,
            close: span,
        },
        span,
    })
}

/// `CAL inst(a := x, ...)`.
pub fn call(inst: &str, args: Vec<(&str, Operand)>, span: Span) -> IlStmt {
    IlStmt::Instr(Instruction {
        kind: InstrKind::Call {
            cond: Condition::Always,
            instance: Box::new(var_ref(inst, span)),
            args: CallArgs::Formal(
                args.into_iter()
                    .map(|(n, v)| FormalArg {
                        name: Ident::new(n, span),
                        dir: ArgDir::Input,
                        value: v,
                        span,
                    })
                    .collect(),
            ),
        },
        span,
    })
}

/// `SEL a, b` with the current result as selector.
pub fn sel(a: Operand, b: Operand, span: Span) -> IlStmt {
    IlStmt::Instr(Instruction {
        kind: InstrKind::FunctionCall {
            name: Ident::new("SEL", span),
            args: Box::new(CallArgs::NonFormal(vec![a, b])),
        },
        span,
    })
}

/// `JMPCN label`.
pub fn jump_if_false(label: &str, span: Span) -> IlStmt {
    IlStmt::Instr(Instruction {
        kind: InstrKind::Jump {
            cond: Condition::IfFalse,
            label: Ident::new(label, span),
        },
        span,
    })
}

/// `label:`.
pub fn label(name: &str, span: Span) -> IlStmt {
    IlStmt::Label(Ident::new(name, span))
}

/// The type named `name` (`BOOL`, `TON`).
pub fn named_type(name: &str, span: Span) -> TypeRef {
    TypeRef::Named(Ident::new(name, span))
}

/// The hidden declarations of the chart, in declaration order.
#[derive(Default)]
pub struct Hidden {
    /// The declarations, in the order they were first declared.
    pub vars: Vec<VarDecl>,
    names: HashSet<String>,
}

impl Hidden {
    /// Declares `name : ty := init` unless that name (case-insensitive) is declared already.
    pub fn declare(&mut self, name: &str, ty: &str, init: Option<Operand>, span: Span) {
        if self.names.insert(name.to_ascii_uppercase()) {
            let mut d = VarDecl::new(Ident::new(name, span), named_type(ty, span), span);
            if let Some(i) = init {
                d = d.with_init(Initializer::Value(i));
            }
            self.vars.push(d);
        }
    }
    /// Adds a ready declaration unless its name is declared already.
    pub fn push(&mut self, d: VarDecl) {
        if self.names.insert(d.name.key()) {
            self.vars.push(d);
        }
    }
}
