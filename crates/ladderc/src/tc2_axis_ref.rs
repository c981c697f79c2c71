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
//!
//! An element of a one-dimensional `ARRAY [l..u] OF AXIS_REF` (`GVL.axisRefs[i].NcToPlc.ActPos`,
//! any index) reads the same members: the hidden blocks are arrays of the same bounds, each
//! element called on its axis at the start of the body (unrolled, so at most
//! [`MAX_ARRAY_AXES`] elements; a larger array's members stay unknown, E1021).

use diagnostics::{code, Diagnostic, Diagnostics};
use il_frontend::ast::{
    Accessor, ArgDir, ArrayDim, CallArgs, Condition, FormalArg, Ident, IlStmt, InstrKind,
    Instruction, Literal, LiteralKind, Op, Operand, Pou, TypeRef, VarDecl, VarRef,
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
    // Infosys, ST_AxisStatus: `InTargetPosition` "axis is in target position (position window)",
    // `InPositionArea` "axis is in the position range". The simulated drive follows its set
    // point exactly, so an axis that stands with no motion (PLCopen Standstill) stands at the end
    // of its last move; one in motion is not (yet) there.
    ("INTARGETPOSITION", "Standstill"),
    ("INPOSITIONAREA", "Standstill"),
    // ST_AxisStatus `HomingBusy` ("homing is running"), `CoupledMode` ("the axis is a coupled
    // slave"): MC_Home running, synchronized motion (MC_GearIn, MC_CamIn)
    ("HOMINGBUSY", "Homing"),
    ("COUPLEDMODE", "SynchronizedMotion"),
];

/// ST_AxisStatus / NCTOPLC_AXIS_REF members computed in the body's prologue from the hidden
/// blocks (BOOL, BOOL, BOOL, BOOL, UDINT, DWORD): see [`computed`].
const COMPUTED: &[(&str, &str)] = &[
    ("OPERATIONAL", "BOOL"),
    ("CONTROLLOOPCLOSED", "BOOL"),
    ("POSITIVEDIRECTION", "BOOL"),
    ("NEGATIVEDIRECTION", "BOOL"),
    ("COUPLESTATE", "UDINT"),
    ("STATEDWORD", "DWORD"),
];

/// The ST_AxisStatus names of [`STATUS`]'s entries, as Tc2_MC2 spells them.
const STATUS_NAMES: &[&str] = &[
    "Error",
    "ErrorID",
    "ErrorStop",
    "Disabled",
    "Stopping",
    "StandStill",
    "DiscreteMotion",
    "ContinuousMotion",
    "SynchronizedMotion",
    "Homing",
    "InTargetPosition",
    "InPositionArea",
    "HomingBusy",
    "CoupledMode",
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
        Some("STATUS") => STATUS_NAMES
            .iter()
            .map(|n| pair(n, "BOOL"))
            .filter(|(n, _)| n != "ErrorID")
            .chain([
                pair("ErrorID", "UDINT"),
                pair("Moving", "BOOL"),
                pair("NotMoving", "BOOL"),
                pair("HasJob", "BOOL"),
                pair("Homed", "BOOL"),
                pair("Operational", "BOOL"),
                pair("ControlLoopClosed", "BOOL"),
                pair("PositiveDirection", "BOOL"),
                pair("NegativeDirection", "BOOL"),
            ])
            .collect(),
        Some("NCTOPLC") => [
            "ActPos",
            "SetPos",
            "ActVelo",
            "SetVelo",
            "PosDiff",
            "ActTorque",
            "SetTorque",
        ]
        .iter()
        .map(|n| pair(n, "LREAL"))
        .chain([
            pair("ErrorCode", "UDINT"),
            pair("CoupleState", "UDINT"),
            pair("AxisId", "UDINT"),
            pair("StateDWord", "DWORD"),
        ])
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

/// The most elements of an `ARRAY OF AXIS_REF` whose members are read (the hidden blocks are
/// called element by element, unrolled).
pub const MAX_ARRAY_AXES: i128 = 64;

/// The one-dimensional `ARRAY [l..u] OF AXIS_REF` variables of `vars` (of at most
/// [`MAX_ARRAY_AXES`] elements), with their bounds.
pub fn axis_ref_arrays<'a>(vars: impl Iterator<Item = &'a VarDecl>) -> Vec<(Ident, ArrayDim)> {
    vars.filter_map(|v| match &v.ty {
        TypeRef::Array { dims, element, .. }
            if matches!(element.as_ref(), TypeRef::Named(t) if t.is("AXIS_REF")) =>
        {
            match dims.as_slice() {
                [d] if d.upper >= d.lower && d.upper - d.lower < MAX_ARRAY_AXES => {
                    Some((v.name.clone(), d.clone()))
                }
                _ => None,
            }
        }
        _ => None,
    })
    .collect()
}

/// The `AXIS_REF` variables a POU reads: its own and the project's global ones.
pub struct Axes {
    /// The variables.
    pub names: Vec<Ident>,
    /// The arrays of axes ([`axis_ref_arrays`]).
    pub arrays: Vec<(Ident, ArrayDim)>,
    /// (global variable list, variable), upper case: `GVL_Axes.Axis1` names `Axis1`.
    pub lists: Vec<(String, String)>,
    /// Set when a body reads an axis's calibration (`Status.Homed`, `NcToPlc.StateDWord`): the
    /// `__TC2_HOMED` table is needed.
    pub homed_read: std::cell::Cell<bool>,
    /// Set once the note on the torque a simulated axis has none of (W1429) was given.
    pub torque_noted: std::cell::Cell<bool>,
}

/// The axes whose members a body reads: scalars and arrays (each once).
#[derive(Default)]
struct Used {
    scalars: Vec<Ident>,
    arrays: Vec<(Ident, ArrayDim)>,
    /// The axes (upper case) whose `NcToPlc.ErrorCode` is read.
    error_codes: Vec<String>,
    /// The axes (upper case) with a [`COMPUTED`] member read.
    computed: Vec<String>,
    /// `Status.Homed` or `NcToPlc.StateDWord` is read.
    homed: bool,
    /// Where a torque (`NcToPlc.ActTorque`, `SetTorque`) is first read.
    torque: Option<Span>,
}

impl Used {
    fn note(&mut self, a: &Ident, dim: Option<&ArrayDim>) {
        match dim {
            None => {
                if !self.scalars.iter().any(|u| u.key() == a.key()) {
                    self.scalars.push(a.clone());
                }
            }
            Some(d) => {
                if !self.arrays.iter().any(|(u, _)| u.key() == a.key()) {
                    self.arrays.push((a.clone(), d.clone()));
                }
            }
        }
    }
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
    fn find_array(&self, v: &VarRef) -> Option<&(Ident, ArrayDim)> {
        self.arrays.iter().find(|(a, _)| a.key() == v.base.key())
    }
}

/// Reads the Tc2_MC2 members of the POU's `AXIS_REF` variables and of the project's global ones
/// (see the module header).
pub fn read_members(p: &mut Pou, globals: &Axes, diags: &mut Diagnostics) {
    let own = p.var_blocks.iter().flat_map(|b| b.vars.iter());
    let mut names = axis_refs(own.clone());
    names.extend(globals.names.iter().cloned());
    let mut arrays = axis_ref_arrays(own);
    arrays.extend(globals.arrays.iter().cloned());
    let axes = Axes {
        names,
        arrays,
        lists: globals.lists.clone(),
        homed_read: Default::default(),
        torque_noted: Default::default(),
    };
    let axes = &axes;
    let mut used = Used::default();
    rewrite(&mut p.body, axes, &mut used, diags);
    if used.homed {
        globals.homed_read.set(true);
    }
    if let Some(at) = used.torque.filter(|_| !globals.torque_noted.get()) {
        globals.torque_noted.set(true);
        diags.push(
            Diagnostic::new(
                code::W1429,
                diagnostics::Severity::Note,
                "a simulated axis has no drive torque: `NcToPlc.ActTorque` and `SetTorque` read 0.0",
            )
            .at(at)
            .with_hint("ladderc's drive follows its set point without a load; the run has no torque to report"),
        );
    }
    if used.scalars.is_empty() && used.arrays.is_empty() {
        return;
    }
    let mut hidden = Vec::new();
    let mut prologue = Vec::new();
    let axes_used = used
        .scalars
        .iter()
        .map(|a| (a, None))
        .chain(used.arrays.iter().map(|(a, d)| (a, Some(d))));
    for (axis, dim) in axes_used {
        let at = axis.span;
        let ty = |name: &str| {
            let one = TypeRef::Named(Ident::new(name, at));
            match dim {
                None => one,
                Some(d) => TypeRef::Array {
                    dims: vec![d.clone()],
                    element: Box::new(one),
                    span: at,
                },
            }
        };
        // the elements, in order (a scalar axis: one, without an index)
        let elements: Vec<Option<Vec<Operand>>> = match dim {
            None => vec![None],
            Some(d) => (d.lower..=d.upper)
                .map(|k| {
                    Some(vec![Operand::literal(Literal {
                        kind: LiteralKind::Int(k),
                        type_prefix: None,
                        span: at,
                    })])
                })
                .collect(),
        };
        for (suffix, block) in [
            ("STATUS", "MC_ReadStatus"),
            ("POS", "MC_ReadActualPosition"),
            ("VELO", "MC_ReadActualVelocity"),
        ] {
            hidden.push(VarDecl {
                name: Ident::new(hidden_name(axis, suffix), at),
                location: None,
                ty: ty(block),
                init: None,
                edge: None,
                span: at,
            });
            prologue.extend(elements.iter().map(|ix| call(axis, suffix, ix.clone())));
        }
        for flag in ["MOVING", "NOTMOVING"] {
            hidden.push(VarDecl {
                name: Ident::new(hidden_name(axis, flag), at),
                location: None,
                ty: ty("BOOL"),
                init: None,
                edge: None,
                span: at,
            });
        }
        for ix in &elements {
            prologue.extend(moving(axis, ix.clone()));
        }
        if used.computed.contains(&axis.key()) {
            for (name, ty_name) in COMPUTED {
                hidden.push(VarDecl {
                    name: Ident::new(hidden_name(axis, name), at),
                    location: None,
                    ty: ty(ty_name),
                    init: None,
                    edge: None,
                    span: at,
                });
            }
            for ix in &elements {
                prologue.extend(computed(axis, ix.clone()));
            }
        }
        if used.error_codes.contains(&axis.key()) {
            hidden.push(VarDecl {
                name: Ident::new(hidden_name(axis, "AXERR"), at),
                location: None,
                ty: ty("MC_ReadAxisError"),
                init: None,
                edge: None,
                span: at,
            });
            hidden.push(VarDecl {
                name: Ident::new(hidden_name(axis, "ERRORCODE"), at),
                location: None,
                ty: ty("UDINT"),
                init: None,
                edge: None,
                span: at,
            });
            for ix in &elements {
                prologue.extend(error_code(axis, ix.clone()));
            }
        }
    }
    crate::block_temps::add_hidden_vars(p, hidden);
    p.body.splice(0..0, prologue);
}

fn hidden_name(axis: &Ident, what: &str) -> String {
    format!("__TC2_{}_{what}", axis.key())
}

/// `name[index].field`, each part when given.
fn indexed(name: String, index: Option<Vec<Operand>>, field: Option<&str>, at: Span) -> VarRef {
    let accessors: Vec<Accessor> = index
        .map(Accessor::Index)
        .into_iter()
        .chain(field.map(|f| Accessor::Field(Ident::new(f, at))))
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

/// The formal input argument `name := value` of a generated call, at `at`.
pub(crate) fn input_arg(name: &str, value: Operand, at: Span) -> FormalArg {
    FormalArg {
        name: Ident::new(name, at),
        dir: ArgDir::Input,
        value,
        span: at,
    }
}

/// `CAL __TC2_<AXIS>_<suffix>(Axis := <axis>, Enable := TRUE)`; of an array of axes, of the
/// element `index` (`CAL __TC2_<AXIS>_<suffix>[i](Axis := <axis>[i], ...)`).
fn call(axis: &Ident, suffix: &str, index: Option<Vec<Operand>>) -> IlStmt {
    let at = axis.span;
    let arg = |name: &str, value: Operand| input_arg(name, value, at);
    let args = vec![
        arg(
            "Axis",
            Operand::Var(indexed(axis.name.clone(), index.clone(), None, at)),
        ),
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
            instance: Box::new(indexed(hidden_name(axis, suffix), index, None, at)),
            args: CallArgs::Formal(args),
        },
        at,
    )
}

/// `CAL __TC2_<AXIS>_AXERR(...)`, `LD __TC2_<AXIS>_AXERR.AxisErrorID WORD_TO_UDINT ST
/// __TC2_<AXIS>_ERRORCODE` (of the element `index` of an array of axes): Tc2_MC2's
/// `NcToPlc.ErrorCode` (UDINT, 0 while the axis has no error) read as the simulated axis's error
/// (MC_ReadAxisError's AxisErrorID, ladderc's ErrorID numbers).
fn error_code(axis: &Ident, index: Option<Vec<Operand>>) -> Vec<IlStmt> {
    let at = axis.span;
    let simple = |op: Op, v: VarRef| var_instr(op, v, at);
    vec![
        call(axis, "AXERR", index.clone()),
        simple(
            Op::Ld,
            indexed(
                hidden_name(axis, "AXERR"),
                index.clone(),
                Some("AxisErrorID"),
                at,
            ),
        ),
        instr(
            InstrKind::FunctionCall {
                name: Ident::new("WORD_TO_UDINT", at),
                args: Box::new(CallArgs::None),
            },
            at,
        ),
        simple(
            Op::St,
            indexed(hidden_name(axis, "ERRORCODE"), index, None, at),
        ),
    ]
}

/// `LD status.DiscreteMotion OR ... ST __TC2_<AXIS>_MOVING STN __TC2_<AXIS>_NOTMOVING` (of
/// the element `index` of an array of axes).
fn moving(axis: &Ident, index: Option<Vec<Operand>>) -> Vec<IlStmt> {
    let at = axis.span;
    let simple = |op: Op, v: VarRef| var_instr(op, v, at);
    let mut out = Vec::new();
    for (k, f) in MOVING.iter().enumerate() {
        let op = if k == 0 { Op::Ld } else { Op::Or };
        let status = indexed(hidden_name(axis, "STATUS"), index.clone(), Some(f), at);
        out.push(simple(op, status));
    }
    let flag = |name: &str| indexed(hidden_name(axis, name), index.clone(), None, at);
    out.push(simple(Op::St, flag("MOVING")));
    out.push(instr(
        InstrKind::Simple {
            op: Op::St,
            negate: true,
            operand: Some(Operand::Var(flag("NOTMOVING"))),
        },
        at,
    ));
    out
}

fn rewrite(body: &mut [IlStmt], axes: &Axes, used: &mut Used, diags: &mut Diagnostics) {
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
                let array = axes.find_array(instance);
                match (axis, array, instance.accessors.as_slice()) {
                    (Some(a), _, [Accessor::Field(m)]) if m.key() == "READSTATUS" => {
                        used.note(a, None);
                        replace = Some(call(a, "STATUS", None));
                    }
                    // `axisRefs[i].ReadStatus()`
                    (None, Some((a, d)), [Accessor::Index(ix), Accessor::Field(m)])
                        if m.key() == "READSTATUS" && ix.len() == 1 =>
                    {
                        used.note(a, Some(d));
                        replace = Some(call(a, "STATUS", Some(ix.clone())));
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

fn operand(o: &mut Operand, axes: &Axes, used: &mut Used, diags: &mut Diagnostics) {
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
    used: &mut Used,
    diags: &mut Diagnostics,
) -> Option<LiteralKind> {
    let mut q = v.clone();
    axes.unqualify(&mut q);
    // a scalar axis (`Axis.Status.Error`) or an element of an array of axes
    // (`axisRefs[i].Status.Error`): the axis, its bounds and index, the members after it
    let (axis, dim, index, rest) = match (axes.find(&q), axes.find_array(&q)) {
        (Some(a), _) => (a.clone(), None, None, q.accessors.to_vec()),
        // one index (the arrays read are one-dimensional; another count is the semantic
        // checks' error, on the user's names)
        (None, Some((a, d))) => match q.accessors.split_first() {
            Some((Accessor::Index(ix), rest)) if ix.len() == 1 => {
                (a.clone(), Some(d.clone()), Some(ix.clone()), rest.to_vec())
            }
            _ => return None,
        },
        (None, None) => return None,
    };
    let axis = &axis;
    let [Accessor::Field(group), Accessor::Field(f), ..] = rest.as_slice() else {
        return None;
    };
    let (group, field) = (group.key(), f.key());
    // `Axis.NcToPlc.StateDWord.1`: a bit of the computed state word
    let bit = match rest.get(2) {
        Some(Accessor::Field(b))
            if group == "NCTOPLC"
                && field == "STATEDWORD"
                && il_frontend::ast::partial_access(&b.name).is_some() =>
        {
            Some(Accessor::Field(b.clone()))
        }
        _ => None,
    };
    let (name, out): (String, Option<&str>) = match group.as_str() {
        // tables by `AxisNo`: the calibration flag, the NC axis's Id
        "STATUS" | "NCTOPLC"
            if (group == "STATUS" && field == "HOMED")
                || (group == "NCTOPLC" && field == "AXISID") =>
        {
            let table = if field == "HOMED" {
                "__TC2_HOMED"
            } else {
                "__TC2_AXISID"
            };
            if rest.len() > 2 {
                return None;
            }
            used.homed = true;
            used.note(axis, dim.as_ref());
            let at = v.span;
            let axis_no = {
                let mut r = indexed(axis.name.clone(), index, Some("AxisNo"), at);
                r.base.span = axis.span;
                r
            };
            *v = VarRef {
                base: Ident::new(table, at),
                accessors: vec![Accessor::Index(vec![Operand::Var(axis_no)])].into(),
                span: at,
            };
            return None;
        }
        "STATUS" | "NCTOPLC" if COMPUTED.iter().any(|(c, _)| *c == field) => {
            if !used.computed.contains(&axis.key()) {
                used.computed.push(axis.key());
            }
            // the state word's prologue reads the calibration table
            used.homed = true;
            (hidden_name(axis, &field), None)
        }
        "STATUS" => match field.as_str() {
            "MOVING" | "NOTMOVING" => (hidden_name(axis, &field), None),
            "HASJOB" => (hidden_name(axis, "MOVING"), None),
            _ => match STATUS.iter().find(|(k, _)| *k == field) {
                Some((_, o)) => (hidden_name(axis, "STATUS"), Some(o)),
                None => {
                    diags.push(e1042(&format!("Status.{}", f.name), f.span));
                    return Some(LiteralKind::Bool(false));
                }
            },
        },
        // the simulated drive follows its set point exactly: no following error
        "NCTOPLC" if field == "POSDIFF" => return Some(LiteralKind::Real(0.0)),
        "NCTOPLC" if field == "ACTTORQUE" || field == "SETTORQUE" => {
            used.torque.get_or_insert(f.span);
            return Some(LiteralKind::Real(0.0));
        }
        "NCTOPLC" if field == "ERRORCODE" => {
            if !used.error_codes.contains(&axis.key()) {
                used.error_codes.push(axis.key());
            }
            (hidden_name(axis, "ERRORCODE"), None)
        }
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
    if rest.len() > 2 + usize::from(bit.is_some()) {
        return None;
    }
    used.note(axis, dim.as_ref());
    let at = v.span;
    *v = indexed(name, index, out, at);
    if let Some(b) = bit {
        let mut acc = v.accessors.to_vec();
        acc.push(b);
        v.accessors = acc.into();
    }
    None
}

/// The prologue of the [`COMPUTED`] members of one axis (of the element `index` of an array of
/// axes), from the hidden MC_ReadStatus and MC_ReadActualVelocity and the calibration table:
/// `Operational` (powered, no error), `ControlLoopClosed` (powered), `PositiveDirection` /
/// `NegativeDirection` (the sign of the velocity), `CoupleState` (3 "slave" in synchronized
/// motion, else 0 "single axis": ladderc's status does not tell a master), `StateDWord`
/// (NCTOPLC_AXIS_REF_STATE's bits: 0 Operational, 1 Homed, 2 NotMoving, 3 InPositionArea,
/// 4 InTargetPosition, 8 HasJob, 9 PositiveDirection, 10 NegativeDirection, 11 HomingBusy,
/// 19 ContinuousMotion, 20 ControlLoopClosed, 31 Error; the others 0).
fn computed(axis: &Ident, index: Option<Vec<Operand>>) -> Vec<IlStmt> {
    let at = axis.span;
    let hidden = |name: &str, field: Option<&str>| {
        indexed(hidden_name(axis, name), index.clone(), field, at)
    };
    let status = |f: &str| hidden("STATUS", Some(f));
    let op = |op: Op, negate: bool, v: VarRef| {
        instr(
            InstrKind::Simple {
                op,
                negate,
                operand: Some(Operand::Var(v)),
            },
            at,
        )
    };
    let lit = |op: Op, kind: LiteralKind| {
        instr(
            InstrKind::Simple {
                op,
                negate: false,
                operand: Some(Operand::literal(Literal {
                    kind,
                    type_prefix: None,
                    span: at,
                })),
            },
            at,
        )
    };
    let word = hidden("STATEDWORD", None);
    let bit = |n: u32| {
        let mut w = word.clone();
        let mut acc = w.accessors.to_vec();
        acc.push(Accessor::Field(Ident::new(n.to_string(), at)));
        w.accessors = acc.into();
        op(Op::St, false, w)
    };
    let homed = VarRef {
        base: Ident::new("__TC2_HOMED", at),
        accessors: vec![Accessor::Index(vec![Operand::Var(indexed(
            axis.name.clone(),
            index.clone(),
            Some("AxisNo"),
            at,
        ))])]
        .into(),
        span: at,
    };
    vec![
        op(Op::Ld, true, status("Disabled")),
        op(Op::And, true, status("Error")),
        op(Op::St, false, hidden("OPERATIONAL", None)),
        op(Op::Ld, true, status("Disabled")),
        op(Op::St, false, hidden("CONTROLLOOPCLOSED", None)),
        op(Op::Ld, false, hidden("VELO", Some("Velocity"))),
        lit(Op::Gt, LiteralKind::Real(0.0)),
        op(Op::St, false, hidden("POSITIVEDIRECTION", None)),
        op(Op::Ld, false, hidden("VELO", Some("Velocity"))),
        lit(Op::Lt, LiteralKind::Real(0.0)),
        op(Op::St, false, hidden("NEGATIVEDIRECTION", None)),
        op(Op::Ld, false, status("SynchronizedMotion")),
        instr(
            InstrKind::FunctionCall {
                name: Ident::new("BOOL_TO_UDINT", at),
                args: Box::new(CallArgs::None),
            },
            at,
        ),
        lit(Op::Mul, LiteralKind::Int(3)),
        op(Op::St, false, hidden("COUPLESTATE", None)),
        op(Op::Ld, false, hidden("OPERATIONAL", None)),
        bit(0),
        op(Op::Ld, false, homed),
        bit(1),
        op(Op::Ld, false, hidden("NOTMOVING", None)),
        bit(2),
        op(Op::Ld, false, status("Standstill")),
        bit(3),
        bit(4),
        op(Op::Ld, false, hidden("MOVING", None)),
        bit(8),
        op(Op::Ld, false, hidden("POSITIVEDIRECTION", None)),
        bit(9),
        op(Op::Ld, false, hidden("NEGATIVEDIRECTION", None)),
        bit(10),
        op(Op::Ld, false, status("Homing")),
        bit(11),
        op(Op::Ld, false, status("ContinuousMotion")),
        bit(19),
        op(Op::Ld, false, hidden("CONTROLLOOPCLOSED", None)),
        bit(20),
        op(Op::Ld, false, status("Error")),
        bit(31),
    ]
}

fn e1042(member: &str, span: Span) -> Diagnostic {
    Diagnostic::error(
        code::E1042,
        format!("AXIS_REF's `{member}` has no counterpart in ladderc's simulated axis"),
    )
    .at(span)
    .with_hint(
        "ladderc reads Status.Error, ErrorID, ErrorStop, Disabled, Stopping, StandStill, DiscreteMotion, \
         ContinuousMotion, SynchronizedMotion, Homing, HomingBusy, CoupledMode, InTargetPosition, \
         InPositionArea, Moving, NotMoving, HasJob, Homed, Operational, ControlLoopClosed, \
         PositiveDirection, NegativeDirection and NcToPlc.ActPos, SetPos, ActVelo, SetVelo, PosDiff, \
         ActTorque, SetTorque, ErrorCode, CoupleState, AxisId, StateDWord",
    )
}

/// `op v` (`LD v`, `ST v`, ...): a simple IL instruction on a variable, at `at`.
fn var_instr(op: Op, v: VarRef, at: il_frontend::Span) -> IlStmt {
    instr(
        InstrKind::Simple {
            op,
            negate: false,
            operand: Some(Operand::Var(v)),
        },
        at,
    )
}
