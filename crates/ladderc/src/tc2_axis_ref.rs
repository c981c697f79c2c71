//! Beckhoff Tc2_MC2's `AXIS_REF` members read from ladderc's simulated axis.
//!
//! Input: one POU's variables and body (IL, before the semantic checks). Output: the body with
//! `Axis.ReadStatus()` (and `Axis();`, a call of the AXIS_REF block itself) a call of a hidden MC_ReadStatus instance, `Axis.Status.<field>` and
//! `Axis.NcToPlc.<field>` reads of hidden MC_ReadStatus / MC_ReadActualPosition /
//! MC_ReadActualVelocity instances that the body calls first in every scan; `Axis.PlcToNc.
//! Override` the axes' table `__TC2_OVERRIDE` by `AxisNo`, a store into it also a hidden
//! MC_SetOverride call; one located E1042 per member with no counterpart (a `Status.` /
//! `NcToPlc.` field ladderc has no value for, `PlcToNc` with another member, `ADS`, `NcToPlc` /
//! `Status` read whole), a store into one left out (`no_store`). Invariants: only variables the
//! POU declares as `AXIS_REF`, as a `REFERENCE TO` / `POINTER TO` / `REF_TO AXIS_REF` (or as
//! structures, or function block instances with an `AXIS_REF` output, holding one:
//! [`axis_holders`]) are touched; the hidden names start with `__TC2_` (a user cannot write them);
//! an axis behind a reference is read only while the reference is bound (no NULL is
//! dereferenced: `Used::guarded`); its members read 0 / FALSE until it is first bound.
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
    Accessor, ArgDir, ArrayDim, CallArgs, CompilationUnit, Condition, FormalArg, Ident, IlStmt,
    InstrKind, Instruction, LibraryElement, Literal, LiteralKind, Op, Operand, Pou, PouKind,
    TypeRef, VarDecl, VarKind, VarRef,
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
    // SoftMotion's AXIS_REF_SM3.nAxisState, an SMC_AXIS_STATE (INT values)
    ("NAXISSTATE", "INT"),
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
/// completion: after `Axis.` (`group` None) `ReadStatus`, `Status`, `NcToPlc`, `PlcToNc` (its
/// `Override`); after
/// `Axis.Status.` the ST_AxisStatus fields; after `Axis.NcToPlc.` the positions and velocities.
pub fn members(group: Option<&str>) -> Vec<(String, String)> {
    let pair = |n: &str, t: &str| (n.to_string(), t.to_string());
    match group.map(|g| g.to_ascii_uppercase()).as_deref() {
        None => vec![
            pair("ReadStatus", "method (Tc2_MC2): refreshes Status"),
            pair("Status", "ST_AxisStatus (Tc2_MC2)"),
            pair("NcToPlc", "NCTOPLC_AXIS_REF (Tc2_MC2)"),
            pair("PlcToNc", "PLCTONC_AXIS_REF (Tc2_MC2)"),
        ],
        Some("PLCTONC") => vec![pair("Override", "UDINT")],
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

/// One step from a variable to the `AXIS_REF` inside it: a field of a structure, or an element
/// of a one-dimensional array (its bounds).
#[derive(Clone, Debug)]
pub enum Step {
    /// `.name`
    Field(Ident),
    /// `[i]`
    Index(ArrayDim),
    /// `^`: the axis behind a `REFERENCE TO AXIS_REF` (dereferenced where it is used, the ST
    /// lowering writes the `^`), a `POINTER TO AXIS_REF` or a `REF_TO AXIS_REF`; always the
    /// path's last step.
    Deref,
}

/// Where an `AXIS_REF` sits: a variable (`Axis`), an element of an array (`axisRefs[i]`), a field
/// of a structure (`AxisController.Axis`), or any nesting of these (`GVL.axes[i].Axis`).
#[derive(Clone, Debug)]
pub struct AxisPath {
    /// The variable.
    pub root: Ident,
    /// The fields and indexes from the variable to the axis.
    pub steps: Vec<Step>,
}

impl AxisPath {
    /// The path without its indexes, upper case, parts joined by `__` (a user's name has no
    /// `__`, so two paths never share a key): `AXIS`, `AXES__AXIS`.
    fn key(&self) -> String {
        let mut k = self.root.key();
        for s in &self.steps {
            if let Step::Field(f) = s {
                k.push_str("__");
                k.push_str(&f.key());
            }
        }
        k
    }
    /// The bounds of the path's indexes, in order.
    fn dims(&self) -> Vec<ArrayDim> {
        self.steps
            .iter()
            .filter_map(|s| match s {
                Step::Index(d) => Some(d.clone()),
                Step::Field(_) | Step::Deref => None,
            })
            .collect()
    }
    /// The axis sits behind a reference or pointer (which may be unbound).
    fn through_reference(&self) -> bool {
        matches!(self.steps.last(), Some(Step::Deref))
    }
    /// `v`'s indexes and the accessors after the axis, when `v` goes through this path (one
    /// operand per index: the arrays read are one-dimensional; another count is the semantic
    /// checks' error, on the user's names).
    fn matches(&self, v: &VarRef) -> Option<(Vec<Operand>, Vec<Accessor>)> {
        if v.base.key() != self.root.key() || v.accessors.len() < self.steps.len() {
            return None;
        }
        let mut index = Vec::new();
        for (s, a) in self.steps.iter().zip(v.accessors.iter()) {
            match (s, a) {
                (Step::Field(f), Accessor::Field(g)) if f.key() == g.key() => {}
                (Step::Index(_), Accessor::Index(ix)) if ix.len() == 1 => index.push(ix[0].clone()),
                (Step::Deref, Accessor::Deref(_)) => {}
                _ => return None,
            }
        }
        Some((index, v.accessors[self.steps.len()..].to_vec()))
    }
    /// The axis itself with the indexes `index` (`GVL.axes[i].Axis`), then `field` when given.
    fn reference(&self, index: &[Operand], field: Option<&str>, at: Span) -> VarRef {
        let mut ix = index.iter();
        let mut accessors: Vec<Accessor> = self
            .steps
            .iter()
            .map(|s| match s {
                Step::Field(f) => Accessor::Field(Ident::new(f.name.clone(), at)),
                Step::Index(_) => Accessor::Index(ix.next().cloned().into_iter().collect()),
                Step::Deref => Accessor::Deref(at),
            })
            .collect();
        accessors.extend(field.map(|f| Accessor::Field(Ident::new(f, at))));
        VarRef {
            base: Ident::new(self.root.name.clone(), self.root.span),
            accessors: accessors.into(),
            span: at,
        }
    }
}

/// The most elements of an `ARRAY OF AXIS_REF` (or of arrays of structures holding one) whose
/// members are read (the hidden blocks are called element by element, unrolled).
pub const MAX_ARRAY_AXES: i128 = 64;

/// The fields of the declared structures, by type key (as `tc2_mc2`'s `declared_types` gives them).
pub type Structs = std::collections::HashMap<String, std::collections::HashMap<String, TypeRef>>;

/// The types whose instances may hold an `AXIS_REF` another POU reads: the declared structures
/// (`structs`) and the function blocks of `units` with their `VAR_OUTPUT`s (readable from
/// outside, IEC 61131-3 ed. 3, 6.5.2.2: `GVL.Mover[i].AxisReference.Status.Moving` of Beckhoff's
/// XTS sample, whose `Mover` block declares its axis as an output "so the link can be made
/// directly"; [`crate::axis_links`] links it as any instance).
pub fn axis_holders(units: &[CompilationUnit], structs: &Structs) -> Structs {
    let mut out = structs.clone();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        let LibraryElement::Pou(p) = item else {
            continue;
        };
        if p.kind != PouKind::FunctionBlock || out.contains_key(&p.name.key()) {
            continue;
        }
        let outputs: std::collections::HashMap<String, TypeRef> = p
            .var_blocks
            .iter()
            .filter(|b| b.kind == VarKind::Output)
            .flat_map(|b| b.vars.iter())
            .map(|v| (v.name.key(), v.ty.clone()))
            .collect();
        if !outputs.is_empty() {
            out.insert(p.name.key(), outputs);
        }
    }
    out
}

/// The `AXIS_REF`s inside `vars`: each variable of that type, each one-dimensional array of them,
/// each field of a declared structure, nested up to four steps deep, with at most
/// [`MAX_ARRAY_AXES`] axes a path (sorted by field name where a structure holds several).
pub fn axis_paths<'a>(vars: impl Iterator<Item = &'a VarDecl>, structs: &Structs) -> Vec<AxisPath> {
    fn walk(
        ty: &TypeRef,
        steps: &mut Vec<Step>,
        count: i128,
        structs: &Structs,
        out: &mut Vec<Vec<Step>>,
    ) {
        if steps.len() > 4 {
            return;
        }
        match ty {
            TypeRef::Named(t) if t.is("AXIS_REF") => out.push(steps.clone()),
            // `Axis : REFERENCE TO AXIS_REF` (TC_XboxController's `FB_Xbox_*_NC`), `POINTER TO
            // AXIS_REF`, `REF_TO AXIS_REF`: the axis it refers to, read where it is bound
            TypeRef::Ref { target, .. } if matches!(&**target, TypeRef::Named(t) if t.is("AXIS_REF")) =>
            {
                steps.push(Step::Deref);
                out.push(steps.clone());
                steps.pop();
            }
            TypeRef::Named(t) => {
                let Some(fields) = structs.get(&t.key()) else {
                    return;
                };
                let mut names: Vec<&String> = fields.keys().collect();
                names.sort();
                for n in names {
                    steps.push(Step::Field(Ident::new(n.clone(), t.span)));
                    walk(&fields[n], steps, count, structs, out);
                    steps.pop();
                }
            }
            TypeRef::Array { dims, element, .. } => match dims.as_slice() {
                [d] if d.upper >= d.lower
                    && (d.upper - d.lower + 1).saturating_mul(count) <= MAX_ARRAY_AXES =>
                {
                    steps.push(Step::Index(d.clone()));
                    walk(
                        element,
                        steps,
                        count * (d.upper - d.lower + 1),
                        structs,
                        out,
                    );
                    steps.pop();
                }
                _ => {}
            },
            _ => {}
        }
    }
    let mut paths = Vec::new();
    for v in vars {
        let mut found = Vec::new();
        walk(&v.ty, &mut Vec::new(), 1, structs, &mut found);
        paths.extend(found.into_iter().map(|steps| AxisPath {
            root: v.name.clone(),
            steps,
        }));
    }
    paths
}

/// The `AXIS_REF`s a POU reads: its own and the project's global ones.
pub struct Axes {
    /// Where they sit ([`axis_paths`]).
    pub paths: Vec<AxisPath>,
    /// (global variable list, variable), upper case: `GVL_Axes.Axis1` names `Axis1`.
    pub lists: Vec<(String, String)>,
    /// Set when a body reads an axis's calibration (`Status.Homed`, `NcToPlc.StateDWord`): the
    /// `__TC2_HOMED` table is needed.
    pub homed_read: std::cell::Cell<bool>,
    /// Set once the note on the torque a simulated axis has none of (W1429) was given.
    pub torque_noted: std::cell::Cell<bool>,
}

/// The axes whose members a body reads (each once).
#[derive(Default)]
struct Used {
    paths: Vec<AxisPath>,
    /// The axes (path keys) whose `NcToPlc.ErrorCode` is read.
    error_codes: Vec<String>,
    /// The axes (path keys) with a [`COMPUTED`] member read.
    computed: Vec<String>,
    /// `Status.Homed` or `NcToPlc.StateDWord` is read.
    homed: bool,
    /// Where a torque (`NcToPlc.ActTorque`, `SetTorque`) is first read.
    torque: Option<Span>,
    /// The axes (path keys) whose `PlcToNc.Override` is read or written.
    overrides: Vec<String>,
    /// The labels made so far (`__TC2_<AXIS>_UNBOUND<n>`, see [`guarded`]).
    labels: usize,
}

impl Used {
    fn note(&mut self, a: &AxisPath) {
        if !self.paths.iter().any(|u| u.key() == a.key()) {
            self.paths.push(a.clone());
        }
    }
    /// `stmts`, run only while the reference or pointer the axis sits behind is bound: `LD Axis
    /// NE NULL JMPCN skip ... skip:` (Infosys, "REFERENCE": "TwinCAT initializes references
    /// (with 0)", and `__ISVALIDREF` tells whether one refers to a variable). An unbound
    /// reference's members then read what they last read (0 / FALSE until it is first bound),
    /// and no NULL is dereferenced. Of an axis not behind a reference: `stmts` as they are.
    fn guarded(&mut self, axis: &AxisPath, index: &[Operand], stmts: Vec<IlStmt>) -> Vec<IlStmt> {
        if !axis.through_reference() || stmts.is_empty() {
            return stmts;
        }
        let at = axis.root.span;
        self.labels += 1;
        let label = Ident::new(
            format!("{}_UNBOUND{}", hidden_name(axis, ""), self.labels),
            at,
        );
        let mut reference = axis.reference(index, None, at);
        let mut accessors = reference.accessors.to_vec();
        accessors.pop(); // the `^` (the path's last step)
        reference.accessors = accessors.into();
        let null = Operand::Ref(Box::new(il_frontend::ast::RefOperand {
            of: None,
            span: at,
            call_scoped: false,
            address_of: false,
        }));
        let mut out = vec![
            var_instr(Op::Ld, reference, at),
            instr(
                InstrKind::Simple {
                    op: Op::Ne,
                    negate: false,
                    operand: Some(null),
                },
                at,
            ),
            instr(
                InstrKind::Jump {
                    cond: Condition::IfFalse,
                    label: label.clone(),
                },
                at,
            ),
        ];
        out.extend(stmts);
        out.push(IlStmt::Label(label));
        out
    }
}

/// Beckhoff's scale of `PlcToNc.Override` (UDINT): 1000000 is 100 % (the factor 1.0).
const OVERRIDE_FULL: f64 = 1_000_000.0;

/// The override written into the axis (`Axis.PlcToNc.Override := x`, `x` the current result,
/// of the element `index`): `ST __TC2_<AXIS>_OVR`, then, while the axis is bound, the per-axis
/// table `__TC2_OVERRIDE[AxisNo]` (what every POU reads back) and the hidden MC_SetOverride with
/// `VelFactor := OVR / 1000000` (the NC's velocity override, applied to the running and later
/// moves, as Tc2_MC2's MC_Power.Override is: [`crate::tc2_override`]).
fn override_written(axis: &AxisPath, index: &[Operand], at: Span, used: &mut Used) -> Vec<IlStmt> {
    let ovr = || hidden(axis, "OVR", index, None, at);
    let velf = || hidden(axis, "VELF", index, None, at);
    let table = override_table(axis, index, at);
    let body = vec![
        var_instr(Op::Ld, ovr(), at),
        var_instr(Op::St, table, at),
        instr(
            InstrKind::FunctionCall {
                name: Ident::new("UDINT_TO_LREAL", at),
                args: Box::new(CallArgs::None),
            },
            at,
        ),
        instr(
            InstrKind::Simple {
                op: Op::Div,
                negate: false,
                operand: Some(Operand::literal(Literal {
                    kind: LiteralKind::Real(OVERRIDE_FULL),
                    type_prefix: None,
                    span: at,
                })),
            },
            at,
        ),
        var_instr(Op::St, velf(), at),
        instr(
            InstrKind::Call {
                cond: Condition::Always,
                instance: Box::new(hidden(axis, "SETOVR", index, None, at)),
                args: CallArgs::Formal(vec![
                    input_arg("Axis", Operand::Var(axis.reference(index, None, at)), at),
                    input_arg(
                        "Enable",
                        Operand::literal(Literal {
                            kind: LiteralKind::Bool(true),
                            type_prefix: None,
                            span: at,
                        }),
                        at,
                    ),
                    input_arg("VelFactor", Operand::Var(velf()), at),
                ]),
            },
            at,
        ),
    ];
    let mut out = vec![var_instr(Op::St, ovr(), at)];
    out.extend(used.guarded(axis, index, body));
    out
}

/// `__TC2_OVERRIDE[<axis>.AxisNo]`: the override last written into the axis, by any POU (the
/// axes' table, 100 % at the start as the NC's override is), read where it is written.
fn override_table(axis: &AxisPath, index: &[Operand], at: Span) -> VarRef {
    let axis_no = axis.reference(index, Some("AxisNo"), at);
    VarRef {
        base: Ident::new("__TC2_OVERRIDE", at),
        accessors: vec![Accessor::Index(vec![Operand::Var(axis_no)])].into(),
        span: at,
    }
}

/// The prologue of `PlcToNc.Override` of an axis behind a reference (of the element `index`):
/// `__TC2_<AXIS>_NO` is the axis's `AxisNo` while the reference is bound, else
/// `__TC2_NO_AXIS`, the table's last entry, which nothing writes (an unbound reference's
/// override reads 0).
fn override_read(axis: &AxisPath, index: &[Operand], used: &mut Used) -> Vec<IlStmt> {
    let at = axis.root.span;
    let no = || hidden(axis, "NO", index, None, at);
    let none = VarRef {
        base: Ident::new("__TC2_NO_AXIS", at),
        accessors: Vec::new().into(),
        span: at,
    };
    let mut out = vec![var_instr(Op::Ld, none, at), var_instr(Op::St, no(), at)];
    let bound = vec![
        var_instr(Op::Ld, axis.reference(index, Some("AxisNo"), at), at),
        var_instr(Op::St, no(), at),
    ];
    out.extend(used.guarded(axis, index, bound));
    out
}

/// The axis `v` writes or reads the override of (`Axis.PlcToNc.Override`), and its indexes.
fn override_of<'a>(v: &VarRef, axes: &'a Axes) -> Option<(&'a AxisPath, Vec<Operand>)> {
    let mut q = v.clone();
    axes.unqualify(&mut q);
    let (axis, index, rest) = axes.find(&q)?;
    match rest.as_slice() {
        [Accessor::Field(g), Accessor::Field(f)]
            if g.key() == "PLCTONC" && f.key() == "OVERRIDE" =>
        {
            Some((axis, index))
        }
        _ => None,
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
    /// The axis `v` goes through, its indexes and the accessors after it.
    fn find(&self, v: &VarRef) -> Option<(&AxisPath, Vec<Operand>, Vec<Accessor>)> {
        self.paths
            .iter()
            .find_map(|p| p.matches(v).map(|(ix, rest)| (p, ix, rest)))
    }
}

/// Reads the Tc2_MC2 members of the POU's `AXIS_REF`s and of the project's global ones (see the
/// module header).
pub fn read_members(p: &mut Pou, globals: &Axes, structs: &Structs, diags: &mut Diagnostics) {
    let own = p.var_blocks.iter().flat_map(|b| b.vars.iter());
    let mut paths = axis_paths(own, structs);
    // a POU's own variable hides a global of the same name
    paths.extend(
        globals
            .paths
            .iter()
            .filter(|g| !paths.iter().any(|o| o.root.key() == g.root.key()))
            .cloned()
            .collect::<Vec<_>>(),
    );
    let axes = Axes {
        paths,
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
    if used.paths.is_empty() {
        return;
    }
    let mut hidden = Vec::new();
    let mut prologue = Vec::new();
    let paths = used.paths.clone();
    for axis in &paths {
        let at = axis.root.span;
        let dims = axis.dims();
        let ty = |name: &str| {
            let one = TypeRef::Named(Ident::new(name, at));
            if dims.is_empty() {
                one
            } else {
                TypeRef::Array {
                    dims: dims.clone(),
                    element: Box::new(one),
                    span: at,
                }
            }
        };
        // the elements, in order (an axis outside arrays: one, without an index)
        let elements = elements(&dims, at);
        let mut decl = |what: &str, ty: TypeRef| {
            hidden.push(VarDecl {
                name: Ident::new(hidden_name(axis, what), at),
                location: None,
                ty,
                init: None,
                edge: None,
                span: at,
            })
        };
        for (suffix, block) in [
            ("STATUS", "MC_ReadStatus"),
            ("POS", "MC_ReadActualPosition"),
            ("VELO", "MC_ReadActualVelocity"),
        ] {
            decl(suffix, ty(block));
            for ix in &elements {
                prologue.extend(used.guarded(axis, ix, vec![call(axis, suffix, ix)]));
            }
        }
        for flag in ["MOVING", "NOTMOVING"] {
            decl(flag, ty("BOOL"));
        }
        for ix in &elements {
            prologue.extend(moving(axis, ix));
        }
        if used.computed.contains(&axis.key()) {
            for (name, ty_name) in COMPUTED {
                decl(name, ty(ty_name));
            }
            for ix in &elements {
                let c = computed(axis, ix);
                prologue.extend(used.guarded(axis, ix, c));
            }
        }
        if used.error_codes.contains(&axis.key()) {
            decl("AXERR", ty("MC_ReadAxisError"));
            decl("ERRORCODE", ty("UDINT"));
            for ix in &elements {
                let e = error_code(axis, ix);
                prologue.extend(used.guarded(axis, ix, e));
            }
        }
        if used.overrides.contains(&axis.key()) {
            decl("OVR", ty("UDINT"));
            decl("VELF", ty("LREAL"));
            decl("SETOVR", ty("MC_SetOverride"));
            if axis.through_reference() {
                decl("NO", ty("UDINT"));
                for ix in &elements {
                    let o = override_read(axis, ix, &mut used);
                    prologue.extend(o);
                }
            }
        }
    }
    // (read again for the METHODs checked on their own: the variables declared then are kept)
    let declared: std::collections::HashSet<String> = p
        .var_blocks
        .iter()
        .flat_map(|b| b.vars.iter().map(|v| v.name.key()))
        .collect();
    hidden.retain(|h| !declared.contains(&h.name.key()));
    if !hidden.is_empty() {
        crate::block_temps::add_hidden_vars(p, hidden);
    }
    p.body.splice(0..0, prologue);
}

/// Every index combination of `dims` in order, as literal operands (no dims: one, empty).
fn elements(dims: &[ArrayDim], at: Span) -> Vec<Vec<Operand>> {
    let mut out: Vec<Vec<Operand>> = vec![Vec::new()];
    for d in dims {
        out = out
            .into_iter()
            .flat_map(|prefix| {
                (d.lower..=d.upper).map(move |k| {
                    let mut ix = prefix.clone();
                    ix.push(Operand::literal(Literal {
                        kind: LiteralKind::Int(k),
                        type_prefix: None,
                        span: at,
                    }));
                    ix
                })
            })
            .collect();
    }
    out
}

fn hidden_name(axis: &AxisPath, what: &str) -> String {
    format!("__TC2_{}_{what}", axis.key())
}

/// The hidden variable `what` of `axis` at the indexes `index` (one index of all of them:
/// the hidden arrays have the path's dimensions), then `field` when given.
fn hidden(axis: &AxisPath, what: &str, index: &[Operand], field: Option<&str>, at: Span) -> VarRef {
    let index = (!index.is_empty()).then(|| index.to_vec());
    indexed(hidden_name(axis, what), index, field, at)
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

/// `CAL __TC2_<AXIS>_<suffix>(Axis := <axis>, Enable := TRUE)`; of an axis inside arrays, of
/// the element `index` (`CAL __TC2_<AXES__AXIS>_<suffix>[i](Axis := axes[i].Axis, ...)`).
fn call(axis: &AxisPath, suffix: &str, index: &[Operand]) -> IlStmt {
    let at = axis.root.span;
    let arg = |name: &str, value: Operand| input_arg(name, value, at);
    let args = vec![
        arg("Axis", Operand::Var(axis.reference(index, None, at))),
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
            instance: Box::new(hidden(axis, suffix, index, None, at)),
            args: CallArgs::Formal(args),
        },
        at,
    )
}

/// `CAL __TC2_<AXIS>_AXERR(...)`, `LD __TC2_<AXIS>_AXERR.AxisErrorID WORD_TO_UDINT ST
/// __TC2_<AXIS>_ERRORCODE` (of the element `index`): Tc2_MC2's `NcToPlc.ErrorCode` (UDINT, 0
/// while the axis has no error) read as the simulated axis's error (MC_ReadAxisError's
/// AxisErrorID, ladderc's ErrorID numbers).
fn error_code(axis: &AxisPath, index: &[Operand]) -> Vec<IlStmt> {
    let at = axis.root.span;
    let simple = |op: Op, v: VarRef| var_instr(op, v, at);
    vec![
        call(axis, "AXERR", index),
        simple(
            Op::Ld,
            hidden(axis, "AXERR", index, Some("AxisErrorID"), at),
        ),
        instr(
            InstrKind::FunctionCall {
                name: Ident::new("WORD_TO_UDINT", at),
                args: Box::new(CallArgs::None),
            },
            at,
        ),
        simple(Op::St, hidden(axis, "ERRORCODE", index, None, at)),
    ]
}

/// `LD status.DiscreteMotion OR ... ST __TC2_<AXIS>_MOVING STN __TC2_<AXIS>_NOTMOVING` (of
/// the element `index`).
fn moving(axis: &AxisPath, index: &[Operand]) -> Vec<IlStmt> {
    let at = axis.root.span;
    let simple = |op: Op, v: VarRef| var_instr(op, v, at);
    let mut out = Vec::new();
    for (k, f) in MOVING.iter().enumerate() {
        let op = if k == 0 { Op::Ld } else { Op::Or };
        out.push(simple(op, hidden(axis, "STATUS", index, Some(f), at)));
    }
    let flag = |name: &str| hidden(axis, name, index, None, at);
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

fn rewrite(body: &mut Vec<IlStmt>, axes: &Axes, used: &mut Used, diags: &mut Diagnostics) {
    // the stores into a member without a counterpart (`Axis.PlcToNc.Override := x;`, E1042
    // reported): left out, as a store leaves the current result as it is
    let mut dropped = Vec::new();
    let mut at = Vec::new();
    // statements that stand for one (`ST Axis.PlcToNc.Override`, `Axis.ReadStatus()` through a
    // reference), by index
    let mut replaced: Vec<(usize, Vec<IlStmt>)> = Vec::new();
    for (k, s) in body.iter_mut().enumerate() {
        let IlStmt::Instr(i) = s else { continue };
        let mut replace = None;
        match &mut i.kind {
            // `Axis.PlcToNc.Override := x;` (TC_XboxController's jog blocks, through a
            // `REFERENCE TO AXIS_REF`): the NC's velocity override
            InstrKind::Simple {
                op: Op::St,
                negate: false,
                operand: Some(Operand::Var(v)),
            } if override_of(v, axes).is_some() => {
                if let Some((a, ix)) = override_of(v, axes) {
                    used.note(a);
                    if !used.overrides.contains(&a.key()) {
                        used.overrides.push(a.key());
                    }
                    used.homed = true;
                    let code = override_written(a, &ix, i.span, used);
                    replaced.push((k, code));
                }
            }
            InstrKind::Simple {
                op,
                operand: Some(o),
                ..
            } => {
                let was_var = matches!(o, Operand::Var(_));
                operand(o, axes, used, diags);
                if was_var && !matches!(o, Operand::Var(_)) && matches!(op, Op::St | Op::S | Op::R)
                {
                    dropped.push(k);
                    at.push(i.span);
                }
            }
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
                match axes.find(instance) {
                    // `Axis.ReadStatus()`, `axisRefs[i].ReadStatus()`, `s.Axis.ReadStatus()`
                    Some((a, ix, rest)) if matches!(rest.as_slice(), [Accessor::Field(m)] if m.key() == "READSTATUS") =>
                    {
                        used.note(a);
                        replace = Some(used.guarded(a, &ix, vec![call(a, "STATUS", &ix)]));
                    }
                    // `Axis();`: AXIS_REF is a FUNCTION_BLOCK of Tc2_MC2 (its ReadStatus an
                    // action of it), and a call of the instance refreshes its status as
                    // `Axis.ReadStatus()` does (before: E1018 "AXIS_REF, not an FB instance")
                    Some((a, ix, rest))
                        if rest.is_empty()
                            && match args {
                                CallArgs::None => true,
                                CallArgs::Formal(l) => l.is_empty(),
                                CallArgs::NonFormal(l) => l.is_empty(),
                            } =>
                    {
                        used.note(a);
                        replace = Some(used.guarded(a, &ix, vec![call(a, "STATUS", &ix)]));
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
            replaced.push((k, r));
        }
    }
    for (k, span) in dropped.into_iter().zip(at) {
        body[k] = no_store(span);
    }
    // (from the last, so that the earlier indexes stay)
    for (k, code) in replaced.into_iter().rev() {
        body.splice(k..k + 1, code);
    }
}

/// What stands for a store left out after its error (E1041, E1042): a label of its own, which
/// ends the current result's life as the store would, so that the value stored gets no follow-on
/// "this result is never used" (W1001). Only a program with errors holds one: it is never compiled.
pub(crate) fn no_store(at: Span) -> IlStmt {
    IlStmt::Label(Ident::new(
        format!("__TC2_NO_STORE_{}_{}", at.file.0, at.start),
        at,
    ))
}

fn operand(o: &mut Operand, axes: &Axes, used: &mut Used, diags: &mut Diagnostics) {
    match o {
        Operand::Var(v) => {
            if let Some(kind) = member(v, axes, used, diags) {
                // reported: the literal (FALSE for a status flag, 0 for an NC value) stops a
                // second report
                *o = Operand::literal(Literal {
                    kind,
                    type_prefix: None,
                    span: v.span,
                });
            }
        }
        // `SIZEOF(Axis.NcToPlc.ActPos)`: the size of the value the member reads; a member
        // without a counterpart (E1042 reported, `SIZEOF(Axis.NcToPlc)`) is 0
        Operand::SizeOf(s) => {
            let without = member(&mut s.of, axes, used, diags).is_some();
            let span = s.span;
            if without {
                *o = Operand::literal(Literal {
                    kind: LiteralKind::Int(0),
                    type_prefix: None,
                    span,
                });
            }
        }
        // `ADR(Axis.NcToPlc.ActPos)`: the address of the hidden block's output that the member
        // reads, refreshed at the start of every scan as the NC refreshes the member (before:
        // E1021 "AXIS_REF has no field NcToPlc"); a member without a counterpart (E1042
        // reported) is NULL
        Operand::Ref(r) => {
            if let Some(v) = &mut r.of {
                if member(v, axes, used, diags).is_some() {
                    r.of = None;
                }
            }
        }
        _ => {}
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
    // the axis (`Axis`, `axisRefs[i]`, `GVL.axes[i].Axis`), its indexes, the members after it
    let (axis, index, rest) = axes.find(&q)?;
    // `PlcToNc.Override` read: the override last written into the axis (see [`override_read`])
    if override_of(&q, axes).is_some() {
        used.note(axis);
        if !used.overrides.contains(&axis.key()) {
            used.overrides.push(axis.key());
        }
        used.homed = true;
        let at = v.span;
        *v = if axis.through_reference() {
            let no = hidden(axis, "NO", &index, None, at);
            VarRef {
                base: Ident::new("__TC2_OVERRIDE", at),
                accessors: vec![Accessor::Index(vec![Operand::Var(no)])].into(),
                span: at,
            }
        } else {
            override_table(axis, &index, at)
        };
        return None;
    }
    // Tc2_MC2's AXIS_REF is `PlcToNc` (PLCTONC_AXIS_REF), `NcToPlc` (NCTOPLC_AXIS_REF), `ADS`
    // (ST_AdsAddress) and `Status` (ST_AxisStatus) (Infosys, Tc2_MC2 > Data types > AXIS_REF):
    // the simulated axis has no value for `PlcToNc` (the PLC's requests to the NC: override,
    // control word ...) and `ADS`, nor for `NcToPlc` / `Status` read whole (the structure's
    // other members, its layout); each is one E1042, not E1021 "AXIS_REF has no field"
    if let Some(Accessor::Field(g)) = rest.first() {
        let k = g.key();
        let whole = rest.len() == 1 && (k == "NCTOPLC" || k == "STATUS");
        if k == "PLCTONC" || k == "ADS" || whole {
            let written: Vec<&str> = rest
                .iter()
                .map_while(|a| match a {
                    Accessor::Field(f) => Some(f.name.as_str()),
                    _ => None,
                })
                .collect();
            let mut d = e1042(&written.join("."), g.span);
            if whole {
                let example = if k == "STATUS" {
                    "`Status.Moving`, `Status.Error`"
                } else {
                    "`NcToPlc.ActPos`, `NcToPlc.ActVelo`"
                };
                d = d.with_hint(format!(
                    "ladderc's simulated axis has no `{}` structure to read whole: read its \
                     members one by one ({example} ...; see `ladderc explain E1042`)",
                    g.name
                ));
            }
            diags.push(d);
            return Some(LiteralKind::Int(0));
        }
    }
    // CODESYS SoftMotion's AXIS_REF_SM3 (ladderc's AXIS_REF, `tc2_mc2::sm3_axis_type`): its
    // members `fActPosition`, `fSetPosition`, `fActVelocity`, `fSetVelocity` (LREAL) and
    // `nAxisState` (SMC_AXIS_STATE), read from the simulated axis as NcToPlc's are; another
    // member stays unknown (sema's E1021 names it)
    if let [Accessor::Field(f)] = rest.as_slice() {
        let (name, out) = match f.key().as_str() {
            "FACTPOSITION" | "FSETPOSITION" => (hidden_name(axis, "POS"), Some("Position")),
            "FACTVELOCITY" | "FSETVELOCITY" => (hidden_name(axis, "VELO"), Some("Velocity")),
            "NAXISSTATE" => {
                if !used.computed.contains(&axis.key()) {
                    used.computed.push(axis.key());
                }
                used.homed = true;
                (hidden_name(axis, "NAXISSTATE"), None)
            }
            _ => return None,
        };
        used.note(axis);
        let at = v.span;
        let index = (!index.is_empty()).then_some(index);
        *v = indexed(name, index, out, at);
        return None;
    }
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
            used.note(axis);
            let at = v.span;
            let axis_no = axis.reference(&index, Some("AxisNo"), at);
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
    used.note(axis);
    let at = v.span;
    let index = (!index.is_empty()).then_some(index);
    *v = indexed(name, index, out, at);
    if let Some(b) = bit {
        let mut acc = v.accessors.to_vec();
        acc.push(b);
        v.accessors = acc.into();
    }
    None
}

/// The prologue of the [`COMPUTED`] members of one axis (of the element `index`), from the hidden MC_ReadStatus and MC_ReadActualVelocity and the calibration table:
/// `Operational` (powered, no error), `ControlLoopClosed` (powered), `PositiveDirection` /
/// `NegativeDirection` (the sign of the velocity), `CoupleState` (3 "slave" in synchronized
/// motion, else 0 "single axis": ladderc's status does not tell a master), `StateDWord`
/// (NCTOPLC_AXIS_REF_STATE's bits: 0 Operational, 1 Homed, 2 NotMoving, 3 InPositionArea,
/// 4 InTargetPosition, 8 HasJob, 9 PositiveDirection, 10 NegativeDirection, 11 HomingBusy,
/// 19 ContinuousMotion, 20 ControlLoopClosed, 31 Error; the others 0).
fn computed(axis: &AxisPath, index: &[Operand]) -> Vec<IlStmt> {
    let at = axis.root.span;
    let hidden = |name: &str, field: Option<&str>| hidden(axis, name, index, field, at);
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
        accessors: vec![Accessor::Index(vec![Operand::Var(axis.reference(
            index,
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
    .into_iter()
    .chain(axis_state(axis, index))
    .collect()
}

/// SoftMotion's `nAxisState` (SMC_AXIS_STATE, helpme-codesys.com SM3_Basic > SMC_AXIS_STATE:
/// power_off 0, errorstop 1, stopping 2, standstill 3, discrete_motion 4, continuous_motion 5,
/// synchronized_motion 6, homing 7) of one axis (of the element `index`), from the hidden
/// MC_ReadStatus: the PLCopen states are exclusive, so the sum of each flag times its number.
fn axis_state(axis: &AxisPath, index: &[Operand]) -> Vec<IlStmt> {
    let at = axis.root.span;
    let state = hidden(axis, "NAXISSTATE", index, None, at);
    let mut code = vec![instr(
        InstrKind::Simple {
            op: Op::Ld,
            negate: false,
            operand: Some(Operand::literal(Literal {
                kind: LiteralKind::Int(0),
                type_prefix: None,
                span: at,
            })),
        },
        at,
    )];
    code.push(var_instr(Op::St, state.clone(), at));
    for (flag, n) in [
        ("ErrorStop", 1),
        ("Stopping", 2),
        ("Standstill", 3),
        ("DiscreteMotion", 4),
        ("ContinuousMotion", 5),
        ("SynchronizedMotion", 6),
        ("Homing", 7),
    ] {
        code.push(var_instr(
            Op::Ld,
            hidden(axis, "STATUS", index, Some(flag), at),
            at,
        ));
        code.push(instr(
            InstrKind::FunctionCall {
                name: Ident::new("BOOL_TO_INT", at),
                args: Box::new(CallArgs::None),
            },
            at,
        ));
        code.push(instr(
            InstrKind::Simple {
                op: Op::Mul,
                negate: false,
                operand: Some(Operand::literal(Literal {
                    kind: LiteralKind::Int(n),
                    type_prefix: None,
                    span: at,
                })),
            },
            at,
        ));
        code.push(var_instr(Op::Add, state.clone(), at));
        code.push(var_instr(Op::St, state.clone(), at));
    }
    code
}

fn e1042(member: &str, span: Span) -> Diagnostic {
    Diagnostic::error(
        code::E1042,
        format!("AXIS_REF's `{member}` has no counterpart in ladderc's simulated axis"),
    )
    .at(span)
    .with_hint(
        "ladderc reads PlcToNc.Override, Status.Error, ErrorID, ErrorStop, Disabled, Stopping, StandStill, DiscreteMotion, \
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
