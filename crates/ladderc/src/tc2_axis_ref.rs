//! Beckhoff Tc2_MC2's `AXIS_REF` members read from ladderc's simulated axis.
//!
//! Input: one POU's variables and body (IL, before the semantic checks). Output: the body with
//! `Axis.ReadStatus()` a call of a hidden MC_ReadStatus instance, `Axis.Status.<field>` and
//! `Axis.NcToPlc.<field>` reads of hidden MC_ReadStatus / MC_ReadActualPosition /
//! MC_ReadActualVelocity instances that the body calls first in every scan; one located E1042
//! per member with no counterpart. Invariants: only variables the POU declares as `AXIS_REF` are
//! touched; the hidden names start with `__TC2_` (a user cannot write them).
//!
//! Per Infosys (Tc2_MC2 > AXIS_REF, ST_AxisStatus, NCTOPLC_AXIS_REF): `NcToPlc` is updated by the
//! NC every cycle, `Status` by `ReadStatus()`. Here both are refreshed at the start of the POU's
//! body, and `Status` again where `ReadStatus()` is called. ST_AxisStatus's `Moving` is "the axis
//! moves" (here: discrete, continuous, synchronized motion, homing or stopping), `NotMoving` its
//! negation; the simulated drive's actual values equal its set values, so `ActPos`/`SetPos` and
//! `ActVelo`/`SetVelo` read the same.

use diagnostics::{code, Diagnostic, Diagnostics};
use il_frontend::ast::{
    Accessor, ArgDir, CallArgs, Condition, FormalArg, Ident, IlStmt, InstrKind, Instruction,
    Literal, LiteralKind, Op, Operand, Pou, TypeRef, VarDecl, VarRef,
};
use il_frontend::Span;

/// ST_AxisStatus fields and the MC_ReadStatus output each reads.
const STATUS: &[(&str, &str)] = &[
    ("ERROR", "Error"),
    ("ERRORID", "ErrorID"),
    ("ERRORSTOP", "ErrorStop"),
    ("DISABLED", "Disabled"),
    ("STOPPING", "Stopping"),
    ("STANDSTILL", "Standstill"),
    ("DISCRETEMOTION", "DiscreteMotion"),
    ("CONTINUOUSMOTION", "ContinuousMotion"),
    ("SYNCHRONIZEDMOTION", "SynchronizedMotion"),
    ("HOMING", "Homing"),
];

/// The MC_ReadStatus outputs whose OR is `Moving`.
const MOVING: &[&str] = &[
    "DiscreteMotion",
    "ContinuousMotion",
    "SynchronizedMotion",
    "Homing",
    "Stopping",
];

/// NCTOPLC_AXIS_REF fields: (field, reads position (true) or velocity).
const NC_TO_PLC: &[(&str, bool)] = &[
    ("ACTPOS", true),
    ("SETPOS", true),
    ("ACTVELO", false),
    ("SETVELO", false),
];

/// The members of a Tc2_MC2 `AXIS_REF` ladderc reads, as (name, type) for the language server's
/// completion: after `Axis.` (`group` None) `ReadStatus`, `Status`, `NcToPlc`; after
/// `Axis.Status.` the ST_AxisStatus fields; after `Axis.NcToPlc.` the positions and velocities.
pub fn members(group: Option<&str>) -> Vec<(String, String)> {
    let pair = |n: &str, t: &str| (n.to_string(), t.to_string());
    match group.map(|g| g.to_ascii_uppercase()).as_deref() {
        None => vec![
            pair("ReadStatus", "method (Tc2_MC2): refreshes Status"),
            pair("Status", "ST_AxisStatus (Tc2_MC2)"),
            pair("NcToPlc", "NCTOPLC_AXIS_REF (Tc2_MC2)"),
        ],
        Some("STATUS") => STATUS
            .iter()
            .map(|(_, o)| pair(if *o == "Standstill" { "StandStill" } else { o }, "BOOL"))
            .filter(|(n, _)| n != "ErrorID")
            .chain([
                pair("ErrorID", "UDINT"),
                pair("Moving", "BOOL"),
                pair("NotMoving", "BOOL"),
            ])
            .collect(),
        Some("NCTOPLC") => ["ActPos", "SetPos", "ActVelo", "SetVelo"]
            .iter()
            .map(|n| pair(n, "LREAL"))
            .collect(),
        _ => Vec::new(),
    }
}

/// The `AXIS_REF` variables of `vars`.
pub fn axis_refs<'a>(vars: impl Iterator<Item = &'a VarDecl>) -> Vec<Ident> {
    vars.filter(|v| matches!(&v.ty, TypeRef::Named(t) if t.is("AXIS_REF")))
        .map(|v| v.name.clone())
        .collect()
}

/// The `AXIS_REF` variables a POU reads: its own and the project's global ones.
pub struct Axes {
    /// The variables.
    pub names: Vec<Ident>,
    /// (global variable list, variable), upper case: `GVL_Axes.Axis1` names `Axis1`.
    pub lists: Vec<(String, String)>,
}

impl Axes {
    /// `GVL_Axes.Axis1...` -> `Axis1...` when the list holds that axis.
    fn unqualify(&self, v: &mut VarRef) {
        let Some(Accessor::Field(f)) = v.accessors.first() else {
            return;
        };
        let pair = (v.base.key(), f.key());
        if self.lists.contains(&pair) {
            v.base = f.clone();
            let rest: Vec<Accessor> = v.accessors[1..].to_vec();
            v.accessors = rest.into();
        }
    }
    fn find(&self, v: &VarRef) -> Option<&Ident> {
        self.names.iter().find(|a| a.key() == v.base.key())
    }
}

/// Reads the Tc2_MC2 members of the POU's `AXIS_REF` variables and of the project's global ones
/// (see the module header).
pub fn read_members(p: &mut Pou, globals: &Axes, diags: &mut Diagnostics) {
    let mut names = axis_refs(p.var_blocks.iter().flat_map(|b| b.vars.iter()));
    names.extend(globals.names.iter().cloned());
    let axes = Axes {
        names,
        lists: globals.lists.clone(),
    };
    let axes = &axes;
    let mut used: Vec<Ident> = Vec::new();
    rewrite(&mut p.body, axes, &mut used, diags);
    if used.is_empty() {
        return;
    }
    let mut hidden = Vec::new();
    let mut prologue = Vec::new();
    for axis in &used {
        let at = axis.span;
        for (suffix, block) in [
            ("STATUS", "MC_ReadStatus"),
            ("POS", "MC_ReadActualPosition"),
            ("VELO", "MC_ReadActualVelocity"),
        ] {
            hidden.push(VarDecl {
                name: Ident::new(hidden_name(axis, suffix), at),
                location: None,
                ty: TypeRef::Named(Ident::new(block, at)),
                init: None,
                edge: None,
                span: at,
            });
            prologue.push(call(axis, suffix));
        }
        for flag in ["MOVING", "NOTMOVING"] {
            hidden.push(VarDecl {
                name: Ident::new(hidden_name(axis, flag), at),
                location: None,
                ty: TypeRef::Named(Ident::new("BOOL", at)),
                init: None,
                edge: None,
                span: at,
            });
        }
        prologue.extend(moving(axis));
    }
    crate::block_temps::add_hidden_vars(p, hidden);
    p.body.splice(0..0, prologue);
}

fn hidden_name(axis: &Ident, what: &str) -> String {
    format!("__TC2_{}_{what}", axis.key())
}

fn var(name: String, field: Option<&str>, at: Span) -> VarRef {
    let accessors: Vec<Accessor> = field
        .map(|f| Accessor::Field(Ident::new(f, at)))
        .into_iter()
        .collect();
    VarRef {
        base: Ident::new(name, at),
        accessors: accessors.into(),
        span: at,
    }
}

fn instr(kind: InstrKind, at: Span) -> IlStmt {
    IlStmt::Instr(Instruction { kind, span: at })
}

/// `CAL __TC2_<AXIS>_<suffix>(Axis := <axis>, Enable := TRUE)`.
fn call(axis: &Ident, suffix: &str) -> IlStmt {
    let at = axis.span;
    let arg = |name: &str, value: Operand| FormalArg {
        name: Ident::new(name, at),
        dir: ArgDir::Input,
        value,
        span: at,
    };
    let args = vec![
        arg("Axis", Operand::Var(var(axis.name.clone(), None, at))),
        arg(
            "Enable",
            Operand::literal(Literal {
                kind: LiteralKind::Bool(true),
                type_prefix: None,
                span: at,
            }),
        ),
    ];
    instr(
        InstrKind::Call {
            cond: Condition::Always,
            instance: Box::new(var(hidden_name(axis, suffix), None, at)),
            args: CallArgs::Formal(args),
        },
        at,
    )
}

/// `LD status.DiscreteMotion OR ... ST __TC2_<AXIS>_MOVING STN __TC2_<AXIS>_NOTMOVING`.
fn moving(axis: &Ident) -> Vec<IlStmt> {
    let at = axis.span;
    let simple = |op: Op, v: VarRef| {
        instr(
            InstrKind::Simple {
                op,
                negate: false,
                operand: Some(Operand::Var(v)),
            },
            at,
        )
    };
    let mut out = Vec::new();
    for (k, f) in MOVING.iter().enumerate() {
        let op = if k == 0 { Op::Ld } else { Op::Or };
        out.push(simple(op, var(hidden_name(axis, "STATUS"), Some(f), at)));
    }
    out.push(simple(Op::St, var(hidden_name(axis, "MOVING"), None, at)));
    out.push(instr(
        InstrKind::Simple {
            op: Op::St,
            negate: true,
            operand: Some(Operand::Var(var(hidden_name(axis, "NOTMOVING"), None, at))),
        },
        at,
    ));
    out
}

fn rewrite(body: &mut [IlStmt], axes: &Axes, used: &mut Vec<Ident>, diags: &mut Diagnostics) {
    for s in body {
        let IlStmt::Instr(i) = s else { continue };
        let mut replace = None;
        match &mut i.kind {
            InstrKind::Simple {
                operand: Some(o), ..
            } => operand(o, axes, used, diags),
            InstrKind::Deferred {
                operand: o, body, ..
            } => {
                if let Some(o) = o {
                    operand(o, axes, used, diags);
                }
                rewrite(body, axes, used, diags);
            }
            InstrKind::Call { instance, args, .. } => {
                axes.unqualify(instance);
                let axis = axes.find(instance);
                match (axis, instance.accessors.as_slice()) {
                    (Some(a), [Accessor::Field(m)]) if m.key() == "READSTATUS" => {
                        note_used(a, used);
                        replace = Some(call(a, "STATUS"));
                    }
                    _ => {
                        let _ = member(instance, axes, used, diags);
                        if let CallArgs::Formal(list) = args {
                            list.iter_mut()
                                .for_each(|a| operand(&mut a.value, axes, used, diags));
                        }
                    }
                }
            }
            InstrKind::FunctionCall { args, .. } => match &mut **args {
                CallArgs::Formal(list) => list
                    .iter_mut()
                    .for_each(|a| operand(&mut a.value, axes, used, diags)),
                CallArgs::NonFormal(ops) => {
                    ops.iter_mut().for_each(|o| operand(o, axes, used, diags))
                }
                CallArgs::None => {}
            },
            _ => {}
        }
        if let Some(r) = replace {
            *s = r;
        }
    }
}

fn note_used(a: &Ident, used: &mut Vec<Ident>) {
    if !used.iter().any(|u| u.key() == a.key()) {
        used.push(a.clone());
    }
}

fn operand(o: &mut Operand, axes: &Axes, used: &mut Vec<Ident>, diags: &mut Diagnostics) {
    if let Operand::Var(v) = o {
        if let Some(kind) = member(v, axes, used, diags) {
            // reported: the literal (FALSE for a status flag, 0 for an NC value) stops a second report
            *o = Operand::literal(Literal {
                kind,
                type_prefix: None,
                span: v.span,
            });
        }
    }
}

/// `Axis.Status.Moving` -> `__TC2_AXIS_MOVING` ...; a member without a counterpart is one E1042,
/// and the literal that stands for it is returned.
fn member(
    v: &mut VarRef,
    axes: &Axes,
    used: &mut Vec<Ident>,
    diags: &mut Diagnostics,
) -> Option<LiteralKind> {
    let mut q = v.clone();
    axes.unqualify(&mut q);
    let axis = axes.find(&q)?.clone();
    let axis = &axis;
    let [Accessor::Field(group), Accessor::Field(f), ..] = q.accessors.as_slice() else {
        return None;
    };
    let (group, field) = (group.key(), f.key());
    let (name, out): (String, Option<&str>) = match group.as_str() {
        "STATUS" => match field.as_str() {
            "MOVING" | "NOTMOVING" => (hidden_name(axis, &field), None),
            _ => match STATUS.iter().find(|(k, _)| *k == field) {
                Some((_, o)) => (hidden_name(axis, "STATUS"), Some(o)),
                None => {
                    diags.push(e1042(&format!("Status.{}", f.name), f.span));
                    return Some(LiteralKind::Bool(false));
                }
            },
        },
        "NCTOPLC" => match NC_TO_PLC.iter().find(|(k, _)| *k == field) {
            Some((_, true)) => (hidden_name(axis, "POS"), Some("Position")),
            Some((_, false)) => (hidden_name(axis, "VELO"), Some("Velocity")),
            None => {
                diags.push(e1042(&format!("NcToPlc.{}", f.name), f.span));
                return Some(LiteralKind::Int(0));
            }
        },
        _ => return None,
    };
    if q.accessors.len() > 2 {
        return None;
    }
    note_used(axis, used);
    let at = v.span;
    *v = var(name, out, at);
    None
}

fn e1042(member: &str, span: Span) -> Diagnostic {
    Diagnostic::error(
        code::E1042,
        format!("AXIS_REF's `{member}` has no counterpart in ladderc's simulated axis"),
    )
    .at(span)
    .with_hint(
        "ladderc reads Status.Error, ErrorID, ErrorStop, Disabled, Stopping, StandStill, DiscreteMotion, \
         ContinuousMotion, SynchronizedMotion, Homing, Moving, NotMoving and NcToPlc.ActPos, SetPos, ActVelo, SetVelo",
    )
}
