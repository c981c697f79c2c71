//! Beckhoff Tc2_MC2's `MC_Power.Override` as ladderc's MC_SetOverride.
//!
//! Input: one MC_Power call's instance, its `Axis` operand and its `Override` operand (IL,
//! before the semantic checks). Output: the hidden variables and the IL that follow the call:
//! the override limited to 0..100 % and divided by 100, written as the VelFactor of a hidden
//! MC_SetOverride instance called with `Enable := TRUE` on the same axis. Invariants: the hidden
//! names start with `__TC2_OVR_` (a user cannot write them); nothing else of the call changes.
//!
//! Per Infosys (Tc2_MC2 > MC_Power): "Override: velocity override in % for all movement commands
//! (0 <= Override <= 100.0)", written whenever MC_Power is called. ladderc's MC_SetOverride scales
//! the velocity limit of the running and of every later positioning, velocity and halt move, and
//! re-plans a running move from its current position, velocity and acceleration within the
//! axis's acceleration and jerk limits (motion-lib, `Engine::set_override_factors`), so a changed
//! override is a jerk-limited transition; 0 % brakes the move to standstill, where it waits until
//! the override rises again. An override outside 0..100 % is limited to that range (the axis's
//! velocity limit is never exceeded either way).

use il_frontend::ast::{
    CallArgs, Condition, Ident, IlStmt, InstrKind, Instruction, Literal, LiteralKind, Op, Operand,
    TypeRef, VarDecl, VarRef,
};
use il_frontend::Span;

fn hidden(instance: &VarRef, suffix: &str) -> String {
    format!("__TC2_OVR_{}{suffix}", instance.base.key())
}

fn instr(kind: InstrKind, at: Span) -> IlStmt {
    IlStmt::Instr(Instruction { kind, span: at })
}

fn var(name: &str, at: Span) -> VarRef {
    VarRef {
        base: Ident::new(name, at),
        accessors: Vec::new().into(),
        span: at,
    }
}

fn real(v: f64, at: Span) -> Operand {
    Operand::literal(Literal {
        kind: LiteralKind::Real(v),
        type_prefix: None,
        span: at,
    })
}

fn simple(op: Op, o: Operand, at: Span) -> IlStmt {
    instr(
        InstrKind::Simple {
            op,
            negate: false,
            operand: Some(o),
        },
        at,
    )
}

fn function(name: &str, arg: Operand, at: Span) -> IlStmt {
    instr(
        InstrKind::FunctionCall {
            name: Ident::new(name, at),
            args: Box::new(CallArgs::NonFormal(vec![arg])),
        },
        at,
    )
}

/// The hidden variables and the IL that give `axis` the override `value` (percent) after the
/// MC_Power call of `instance` (see the module header). `declared` is the instance variable's
/// type: for an element of an array of MC_Power (`fbPower[i](..., Override := f)`) the hidden
/// MC_SetOverride is an array of the same bounds, called at the same index, so each axis keeps
/// its own override block.
pub fn set_override(
    instance: &VarRef,
    declared: Option<&TypeRef>,
    axis: &Operand,
    value: Operand,
) -> (Vec<VarDecl>, Vec<IlStmt>) {
    let at = instance.span;
    let block = hidden(instance, "");
    let factor = hidden(instance, "_FACTOR");
    let decl = |name: &str, ty: &str| VarDecl {
        name: Ident::new(name, at),
        location: None,
        ty: TypeRef::Named(Ident::new(ty, at)),
        init: None,
        edge: None,
        span: at,
    };
    let mut block_decl = decl(&block, "MC_SetOverride");
    let mut called = var(&block, at);
    if let (false, Some(TypeRef::Array { dims, span, .. })) =
        (instance.accessors.is_empty(), declared)
    {
        block_decl.ty = TypeRef::Array {
            dims: dims.clone(),
            element: Box::new(TypeRef::Named(Ident::new("MC_SetOverride", at))),
            span: *span,
        };
        called.accessors = instance.accessors.clone();
    }
    let decls = vec![block_decl, decl(&factor, "LREAL")];
    // an integer literal (`Override := 50`) is the LREAL it stands for
    let value = match &value {
        Operand::Literal(l) => match l.kind {
            LiteralKind::Int(i) => real(i as f64, l.span),
            _ => value,
        },
        _ => value,
    };
    let f = || Operand::Var(var(&factor, at));
    let arg = |name: &str, value: Operand| crate::tc2_axis_ref::input_arg(name, value, at);
    let code = vec![
        simple(Op::Ld, value, at),
        simple(Op::St, f(), at),
        simple(Op::Ld, f(), at),
        function("MAX", real(0.0, at), at),
        function("MIN", real(100.0, at), at),
        simple(Op::Div, real(100.0, at), at),
        simple(Op::St, f(), at),
        instr(
            InstrKind::Call {
                cond: Condition::Always,
                instance: Box::new(called),
                args: CallArgs::Formal(vec![
                    arg("Axis", axis.clone()),
                    arg(
                        "Enable",
                        Operand::literal(Literal {
                            kind: LiteralKind::Bool(true),
                            type_prefix: None,
                            span: at,
                        }),
                    ),
                    arg("VelFactor", f()),
                ]),
            },
            at,
        ),
    ];
    (decls, code)
}

/// The hidden LREAL (initial value 100.0) that holds `instance.Override` as the program writes it
/// (`fbPower.Override := nPct;`, an input written before the call, IEC 61131-3 6.6.1.2): its
/// name, and its declaration.
pub fn written_field(instance: &Ident) -> (String, VarDecl) {
    let at = instance.span;
    let name = format!("__TC2_OVR_{}_FIELD", instance.key());
    let decl = VarDecl {
        name: Ident::new(&name, at),
        location: None,
        ty: TypeRef::Named(Ident::new("LREAL", at)),
        init: Some(il_frontend::ast::Initializer::Value(real(100.0, at))),
        edge: None,
        span: at,
    };
    (name, decl)
}

/// The IL that stores `value` (the `Override` argument of a call) into the hidden field `field`
/// ([`written_field`]), so that `fbPower.Override` reads the value the last call gave: `LD value;
/// ST field` (an integer literal as the LREAL it stands for).
pub fn store_field(value: Operand, field: &str, at: Span) -> Vec<IlStmt> {
    let value = match &value {
        Operand::Literal(l) => match l.kind {
            LiteralKind::Int(i) => real(i as f64, l.span),
            _ => value,
        },
        _ => value,
    };
    vec![
        simple(Op::Ld, value, at),
        simple(Op::St, Operand::Var(var(field, at)), at),
    ]
}
