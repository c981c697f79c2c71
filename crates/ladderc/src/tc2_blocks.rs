//! Beckhoff Tc2_MC2 blocks that ladderc builds from its PLCopen blocks: `MC_MoveModulo`, `MC_Jog`,
//! and Tc2_MC2's `MC_Home` with its `HomingMode`.
//!
//! Input: the user's parsed units. Output: when a variable of the program has a Tc2_MC2 block
//! type that ladderc builds (and the program does not declare a POU of that name), one unit with
//! the block written in ST on top of ladderc's own blocks; the axis configuration marked so that
//! its globals include the per-axis tables the block reads (`__TC2_MODULO`, `__TC2_ACC`,
//! `__TC2_DEC`, indexed by `AxisNo`). Invariants: the block's text is fixed (nothing of the user's
//! input enters it; `tc2_blocks/*.st`); the blocks only command motion through ladderc's PLCopen
//! blocks (MC_MoveRelative, MC_MoveAbsolute, MC_MoveAdditive, MC_MoveVelocity, MC_Halt), so every
//! axis limit holds as for any other move.
//!
//! MC_MoveModulo, per Infosys (Tc2_MC2 > Motion > MC_MoveModulo): a positioning to a modulo
//! position of the axis; the modulo period is the axis's `modulo_period` in the axes file (an
//! axis without one refuses the command with ErrorID 24 InvalidPosition). Started from
//! standstill, `MC_Positive_Direction` turns forward to the position, `MC_Negative_Direction`
//! backward, `MC_Shortest_Way` the shorter way (`MC_Current_Direction` forward); a Position of
//! one period or more adds that many full turns (450 deg forward from 90 deg: one turn; 90 deg
//! from exactly 90 deg: no motion). Started while the axis moves, the direction is kept (MC_MoveModulo
//! cannot reverse it) and the target is the first one ahead at which the axis can stop with the
//! block's deceleration (v^2 / 2d; with a jerk limit the motion library still keeps every limit
//! and plans the stop, which may then pass the target and come back). Acceleration and
//! Deceleration left out or 0 take the axis's configured limits. With `MC_Aborting` the distance
//! is computed from the set position when the command is issued; a position within 1e-9 periods
//! of the target counts as the target (the rounding of a full turn is no distance). With
//! `MC_Buffered` or a blending mode the command waits in the axis's queue and its target is
//! computed from where the queue ends (Infosys: "the same applies to a start with the BufferMode
//! MC_Buffered", the rule of a start from standstill): the modulo position is the motion
//! library's MC_MoveAbsolute on the modulo axis with the block's Direction and BufferMode, which
//! measures from the last commanded target, and the full turns of a Position of one period or
//! more follow as an MC_MoveAdditive blended onto it (MC_BlendingLow, same direction, so the axis
//! does not stop between them); Done comes with the last of them. Queued full turns with
//! `MC_Shortest_Way` or `MC_Current_Direction` are refused with ErrorID 25 (InvalidDirection):
//! which way is shorter, or current, is only known where the queue ends (Beckhoff's TC3 MC3
//! MC_MoveModulo likewise requires a direction other than ShortestDistance for additional turns).
//!
//! MC_Jog, per Infosys (Tc2_MC2 > Motion > MC_Jog, E_JogMode): a rising edge of `JogForward` (which
//! wins over a simultaneous `JogBackwards`) or `JogBackwards` starts a jog, and no edge is taken
//! until it has ended. MC_JOGMODE_STANDARD_SLOW / _FAST move while the key is held at the axis's
//! manual velocity (axes file `jog_velocity_slow` / `jog_velocity_fast`, by default 10 % / 50 % of
//! `velocity`) with the axis's acceleration and deceleration, the block's inputs unused;
//! MC_JOGMODE_CONTINOUS moves while the key is held with the block's Velocity, Acceleration,
//! Deceleration and Jerk (0: the axis's); releasing the key halts the axis (MC_Halt), and Done
//! rises once it stands. MC_JOGMODE_INCHING moves `Position` per edge (MC_MoveRelative).
//! MC_JOGMODE_INCHING_MODULO (Infosys, E_JogMode: "axis moves for a certain relative distance -
//! stop position is rounded to the distance value") moves per edge to the whole multiple of
//! `Position` nearest to one step ahead of the axis's actual position (on a modulo axis its
//! position within the period), a tie going ahead: a step of between a half and one and a half
//! `Position`, always in the jog's direction; a `Position` of 0 is ErrorID 24 (InvalidPosition).
//! Any other mode is refused with ErrorID 32 (InvalidMode).
//!
//! MC_Home, per Infosys (Tc2_MC2 > Motion > MC_Home, MC_HomingMode): when the program passes a
//! Tc2_MC2 pin (`HomingMode`, `bCalibrationCam`) or reads an axis's calibration (`Status.Homed`,
//! `NcToPlc.StateDWord`, a `MC_HomingMode` value), every `MC_Home` instance is the Tc2_MC2 block
//! (`__TC2_MC_HOME`, `tc2_blocks/MC_Home.st`), built on the PLCopen MC_Home and MC_SetPosition:
//! `MC_DefaultHoming` homes on the spot (the simulated drive has no reference cam; PLCopen MC_Home
//! in the motion library) to `Position`, or to the NC's calibration value 0 for
//! `DEFAULT_HOME_POSITION` (1E+308, the input's default); `MC_AbsoluteHoming` sets the position
//! to `Position` (on the spot, from standstill), `MC_RelativeHoming` shifts it by `Position`
//! (MC_SetPosition, `Relative := TRUE`); both refuse `DEFAULT_HOME_POSITION` with ErrorID 24;
//! `MC_ForceCalibration` marks the axis homed and `MC_ResetCalibration` not homed, without
//! motion, Done at once; another value is ErrorID 32 (`ErrorID` is UDINT, as Tc2_MC2's). The axis is homed (`Status.Homed`, the
//! table `__TC2_HOMED` by `AxisNo`) when a homing ends, not homed at the start of the run and
//! from the start of a default homing on.

use diagnostics::Diagnostics;
use il_frontend::ast::{
    Accessor, CallArgs, CompilationUnit, Ident, IlStmt, InstrKind, LibraryElement, Operand,
    TypeRef, VarRef,
};

/// A type a block needs: (name, ST text).
type Needs = Option<(&'static str, &'static str)>;

/// The blocks ladderc builds: (name, ST text, the enumeration type it needs).
const BLOCKS: &[(&str, &str, Needs)] = &[
    ("MC_MoveModulo", MOVE_MODULO, None),
    ("MC_Jog", JOG, Some(("E_JogMode", JOG_MODE))),
];

/// Infosys, Tc2_MC2 > Data types > E_JogMode (numbered from 0, as TwinCAT numbers an enumeration).
const JOG_MODE: &str = "TYPE E_JogMode :
(
    MC_JOGMODE_STANDARD_SLOW,
    MC_JOGMODE_STANDARD_FAST,
    MC_JOGMODE_CONTINOUS,
    MC_JOGMODE_INCHING,
    MC_JOGMODE_INCHING_MODULO
);
END_TYPE
";

/// MC_Jog in ST (the module header says what it does).
const JOG: &str = include_str!("tc2_blocks/MC_Jog.st");

/// Infosys, Tc2_MC2 > Data types > MC_HomingMode; `MC_Direct`, the name older Tc2_MC2 versions
/// give the mode that sets the position to `Position` without a movement, is MC_AbsoluteHoming's
/// number.
const HOMING_MODE: &str = "TYPE MC_HomingMode :
(
    MC_DefaultHoming,
    MC_AbsoluteHoming,
    MC_RelativeHoming,
    MC_ForceCalibration,
    MC_ResetCalibration,
    MC_Direct := 1
);
END_TYPE
";

/// Tc2_MC2's global constant: MC_Home's `Position` that means the configured calibration value.
const DEFAULT_HOME_POSITION: &str = "VAR_GLOBAL CONSTANT
    DEFAULT_HOME_POSITION : LREAL := 1.0E308;
END_VAR
";

/// Tc2_MC2's MC_Home in ST (the module header says what it does).
const HOME: &str = include_str!("tc2_blocks/MC_Home.st");

/// The name the Tc2_MC2 MC_Home is given (the PLCopen MC_Home keeps its name).
pub const TC2_HOME: &str = "__TC2_MC_HOME";

/// MC_MoveModulo in ST (the module header says what it does).
const MOVE_MODULO: &str = include_str!("tc2_blocks/MC_MoveModulo.st");

/// The names of the blocks ladderc builds.
pub fn names() -> impl Iterator<Item = &'static str> {
    BLOCKS.iter().map(|(n, _, _)| *n)
}

fn declares_type(units: &[CompilationUnit], name: &str) -> bool {
    fn uses(t: &TypeRef, name: &str) -> bool {
        match t {
            TypeRef::Named(n) => n.is(name),
            TypeRef::Array { element, .. } => uses(element, name),
            _ => false,
        }
    }
    let mut declared = false;
    let mut used = false;
    for item in units.iter().flat_map(|u| u.items.iter()) {
        match item {
            LibraryElement::DataTypes(ts) => declared |= ts.iter().any(|t| t.name.is(name)),
            LibraryElement::Pou(p) => {
                declared |= p.name.is(name);
                used |= p
                    .var_blocks
                    .iter()
                    .flat_map(|b| b.vars.iter())
                    .any(|v| uses(&v.ty, name));
            }
            LibraryElement::GlobalVars(b) => used |= b.vars.iter().any(|v| uses(&v.ty, name)),
            _ => {}
        }
    }
    used && !declared
}

/// Does the program declare a type or POU named `name`?
fn declared(units: &[CompilationUnit], name: &str) -> bool {
    units
        .iter()
        .flat_map(|u| u.items.iter())
        .any(|item| match item {
            LibraryElement::DataTypes(ts) => ts.iter().any(|t| t.name.is(name)),
            LibraryElement::Pou(p) => p.name.is(name),
            _ => false,
        })
}

/// Adds the blocks the program uses (see the module header); true when one was added.
pub fn add(
    units: &mut Vec<CompilationUnit>,
    map: &mut diagnostics::SourceMap,
    diags: &mut Diagnostics,
) -> bool {
    let mut added = false;
    for (name, text, ty) in BLOCKS {
        if !declares_type(units, name) {
            continue;
        }
        // the enumeration the block needs, unless the program declares one of that name
        let text = match ty {
            Some((ty, ty_text)) if !declared(units, ty) => format!("{ty_text}{text}"),
            _ => text.to_string(),
        };
        let file = map.add(format!("<Tc2_MC2 {name}>"), text.clone());
        let (unit, pending, _) = il_frontend::st::file::parse_text(
            file,
            &text,
            name,
            il_frontend::st::file::Lang::St,
            diags,
        );
        let mut one = vec![unit];
        il_frontend::st::file::compile_pending(&mut one, &pending, diags);
        units.splice(0..0, one);
        added = true;
    }
    added | add_home(units, map, diags)
}

/// Whether the program reads a Tc2_MC2 homing pin or an axis's calibration (module header).
fn reads_calibration(units: &[CompilationUnit]) -> bool {
    const NAMES: &[&str] = &[
        "HOMINGMODE",
        "BCALIBRATIONCAM",
        "HOMED",
        "STATEDWORD",
        "MC_DEFAULTHOMING",
        "MC_ABSOLUTEHOMING",
        "MC_RELATIVEHOMING",
        "MC_FORCECALIBRATION",
        "MC_RESETCALIBRATION",
        "MC_DIRECT",
    ];
    fn var(v: &VarRef) -> bool {
        NAMES.contains(&v.base.key().as_str())
            || v.accessors.iter().any(|a| match a {
                Accessor::Field(f) => NAMES.contains(&f.key().as_str()),
                Accessor::Index(ops) => ops.iter().any(operand),
                Accessor::Deref(_) => false,
            })
    }
    fn operand(o: &Operand) -> bool {
        matches!(o, Operand::Var(v) if var(v))
    }
    fn args(a: &CallArgs) -> bool {
        match a {
            CallArgs::Formal(list) => list
                .iter()
                .any(|a| NAMES.contains(&a.name.key().as_str()) || operand(&a.value)),
            CallArgs::NonFormal(ops) => ops.iter().any(operand),
            CallArgs::None => false,
        }
    }
    fn body(b: &[IlStmt]) -> bool {
        b.iter().any(|s| {
            let IlStmt::Instr(i) = s else { return false };
            match &i.kind {
                InstrKind::Simple {
                    operand: Some(o), ..
                } => operand(o),
                InstrKind::Deferred {
                    operand: o,
                    body: b,
                    ..
                } => o.as_ref().is_some_and(|o| operand(o)) || body(b),
                InstrKind::Call {
                    instance, args: a, ..
                } => var(instance) || args(a),
                InstrKind::FunctionCall { args: a, .. } => args(a),
                _ => false,
            }
        })
    }
    units
        .iter()
        .flat_map(|u| u.items.iter())
        .any(|item| match item {
            LibraryElement::Pou(p) => body(&p.body),
            LibraryElement::Action(a) => body(&a.body),
            _ => false,
        })
}

/// The operands `MC_HomingMode.<value>` of `body` (CODESYS's and TwinCAT's way to name an
/// enumerated value) made the enumerated value `MC_HomingMode#<value>`.
fn qualified_modes(body: &mut [IlStmt]) {
    fn operand(o: &mut Operand) {
        let Operand::Var(v) = o else { return };
        let [Accessor::Field(value)] = &v.accessors[..] else {
            return;
        };
        if v.base.is("MC_HomingMode") {
            *o = Operand::enum_value(v.base.clone(), value.clone(), v.span);
        }
    }
    fn args(a: &mut CallArgs) {
        match a {
            CallArgs::Formal(list) => list.iter_mut().for_each(|a| operand(&mut a.value)),
            CallArgs::NonFormal(ops) => ops.iter_mut().for_each(operand),
            CallArgs::None => {}
        }
    }
    for s in body {
        let IlStmt::Instr(i) = s else { continue };
        match &mut i.kind {
            InstrKind::Simple {
                operand: Some(o), ..
            } => operand(o),
            InstrKind::Deferred {
                operand: o,
                body: b,
                ..
            } => {
                if let Some(o) = o {
                    operand(o);
                }
                qualified_modes(b);
            }
            InstrKind::Call { args: a, .. } => args(a),
            InstrKind::FunctionCall { args: a, .. } => args(a),
            _ => {}
        }
    }
}

/// `MC_Home` (or `Tc2_MC2.MC_Home`) as a type, also as an array's element.
fn home_type(t: &mut TypeRef) -> Option<&mut Ident> {
    match t {
        TypeRef::Named(n) if n.is("MC_Home") || n.key().ends_with(".MC_HOME") => Some(n),
        TypeRef::Array { element, .. } => home_type(element),
        _ => None,
    }
}

/// Tc2_MC2's MC_Home (module header): the `MC_Home` instances retyped, the block, its
/// enumeration and `DEFAULT_HOME_POSITION` added, when the program reads a Tc2_MC2 homing pin or an
/// axis's calibration. True when the program reads one (the `__TC2_HOMED` table is then needed).
fn add_home(
    units: &mut Vec<CompilationUnit>,
    map: &mut diagnostics::SourceMap,
    diags: &mut Diagnostics,
) -> bool {
    if !reads_calibration(units) {
        return false;
    }
    if declared(units, "MC_Home") {
        return true;
    }
    let mut retyped = false;
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        let blocks: Vec<&mut il_frontend::ast::VarBlock> = match item {
            LibraryElement::Pou(p) => p.var_blocks.iter_mut().collect(),
            LibraryElement::GlobalVars(b) => vec![b],
            _ => Vec::new(),
        };
        for v in blocks.into_iter().flat_map(|b| b.vars.iter_mut()) {
            if let Some(n) = home_type(&mut v.ty) {
                *n = Ident::new(TC2_HOME, n.span);
                retyped = true;
            }
        }
    }
    let mut text = String::new();
    if !declared(units, "MC_HomingMode") {
        text.push_str(HOMING_MODE);
        // `MC_HomingMode.MC_Direct`, read as a variable before the type was added: its value
        for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
            match item {
                LibraryElement::Pou(p) => qualified_modes(&mut p.body),
                LibraryElement::Action(a) => qualified_modes(&mut a.body),
                _ => {}
            }
        }
    }
    if retyped {
        text.push_str(HOME);
    }
    let constant_declared = units.iter().flat_map(|u| u.items.iter()).any(|i| {
        matches!(i, LibraryElement::GlobalVars(b)
            if b.vars.iter().any(|v| v.name.is("DEFAULT_HOME_POSITION")))
    });
    if !constant_declared {
        text.push_str(DEFAULT_HOME_POSITION);
    }
    if !text.is_empty() {
        let file = map.add("<Tc2_MC2 MC_Home>", text.clone());
        let (unit, pending, _) = il_frontend::st::file::parse_text(
            file,
            &text,
            "MC_Home",
            il_frontend::st::file::Lang::St,
            diags,
        );
        let mut one = vec![unit];
        il_frontend::st::file::compile_pending(&mut one, &pending, diags);
        units.splice(0..0, one);
    }
    true
}
