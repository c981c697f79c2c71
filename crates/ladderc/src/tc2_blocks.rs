//! Beckhoff Tc2_MC2 blocks that ladderc builds from its PLCopen blocks: `MC_MoveModulo`, `MC_Jog`.
//!
//! Input: the user's parsed units. Output: when a variable of the program has a Tc2_MC2 block
//! type that ladderc builds (and the program does not declare a POU of that name), one unit with
//! the block written in ST on top of ladderc's own blocks; the axis configuration marked so that
//! its globals include the per-axis tables the block reads (`__TC2_MODULO`, `__TC2_ACC`,
//! `__TC2_DEC`, indexed by `AxisNo`). Invariants: the block's text is fixed (nothing of the user's
//! input enters it); the block only commands motion through MC_MoveRelative, so every axis limit
//! holds as for any other move.
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
//! Deceleration left out or 0 take the axis's configured limits. The distance is computed from
//! the set position when the command is issued, so with `MC_Buffered` it is measured from where
//! the axis is then, not from the end of the move before. A position within 1e-9 periods of the
//! target counts as the target (the rounding of a full turn is no distance).
//!
//! MC_Jog, per Infosys (Tc2_MC2 > Motion > MC_Jog, E_JogMode): a rising edge of `JogForward` (which
//! wins over a simultaneous `JogBackwards`) or `JogBackwards` starts a jog, and no edge is taken
//! until it has ended. MC_JOGMODE_STANDARD_SLOW / _FAST move while the key is held at the axis's
//! manual velocity (axes file `jog_velocity_slow` / `jog_velocity_fast`, by default 10 % / 50 % of
//! `velocity`) with the axis's acceleration and deceleration, the block's inputs unused;
//! MC_JOGMODE_CONTINOUS moves while the key is held with the block's Velocity, Acceleration,
//! Deceleration and Jerk (0: the axis's); releasing the key halts the axis (MC_Halt), and Done
//! rises once it stands. MC_JOGMODE_INCHING moves `Position` per edge (MC_MoveRelative).
//! MC_JOGMODE_INCHING_MODULO is refused (Error, ErrorID 32 InvalidMode): ladderc does not round
//! the stop position.

use diagnostics::Diagnostics;
use il_frontend::ast::{CompilationUnit, LibraryElement, TypeRef};

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

const JOG: &str = "FUNCTION_BLOCK MC_Jog
VAR_IN_OUT
    Axis : AXIS_REF;
END_VAR
VAR_INPUT
    JogForward : BOOL;
    JogBackwards : BOOL;
    Mode : E_JogMode;
    Position : LREAL;
    Velocity : LREAL;
    Acceleration : LREAL;
    Deceleration : LREAL;
    Jerk : LREAL;
END_VAR
VAR_OUTPUT
    Done : BOOL;
    Busy : BOOL;
    Active : BOOL;
    CommandAborted : BOOL;
    Error : BOOL;
    ErrorID : WORD;
END_VAR
VAR
    fbVel : MC_MoveVelocity;
    fbHalt : MC_Halt;
    fbStep : MC_MoveRelative;
    bFwdLast : BOOL;
    bBwdLast : BOOL;
    bFwdEdge : BOOL;
    bBwdEdge : BOOL;
    bHeld : BOOL;
    bGoVel : BOOL;
    bGoHalt : BOOL;
    bGoStep : BOOL;
    nDir : INT;
    nKind : INT;
    nAxis : UDINT;
    nRefused : WORD;
    eDir : MC_Direction;
    fVel : LREAL;
    fAcc : LREAL;
    fDec : LREAL;
    fDist : LREAL;
END_VAR
bFwdEdge := JogForward AND NOT bFwdLast;
bBwdEdge := JogBackwards AND NOT bBwdLast;
bFwdLast := JogForward;
bBwdLast := JogBackwards;
IF NOT JogForward AND NOT JogBackwards AND nDir = 0 THEN
    nRefused := 0;
END_IF
(* a new jog only while none runs; JogForward first *)
IF nDir = 0 AND (bFwdEdge OR bBwdEdge) THEN
    IF bFwdEdge THEN
        nDir := 1;
        eDir := MC_Positive_Direction;
    ELSE
        nDir := -1;
        eDir := MC_Negative_Direction;
    END_IF
    nAxis := Axis.AxisNo;
    fVel := Velocity;
    fAcc := Acceleration;
    IF fAcc <= 0.0 THEN
        fAcc := __TC2_ACC[nAxis];
    END_IF
    fDec := Deceleration;
    IF fDec <= 0.0 THEN
        fDec := __TC2_DEC[nAxis];
    END_IF
    nRefused := 0;
    Done := FALSE;
    CommandAborted := FALSE;
    IF Mode = MC_JOGMODE_STANDARD_SLOW OR Mode = MC_JOGMODE_STANDARD_FAST THEN
        nKind := 1;
        IF Mode = MC_JOGMODE_STANDARD_SLOW THEN
            fVel := __TC2_JOGSLOW[nAxis];
        ELSE
            fVel := __TC2_JOGFAST[nAxis];
        END_IF
        fAcc := __TC2_ACC[nAxis];
        fDec := __TC2_DEC[nAxis];
    ELSIF Mode = MC_JOGMODE_CONTINOUS THEN
        nKind := 1;
    ELSIF Mode = MC_JOGMODE_INCHING THEN
        nKind := 2;
        fDist := Position;
        IF nDir < 0 THEN
            fDist := -Position;
        END_IF
    ELSE
        nKind := 0;
        nDir := 0;
        nRefused := 32;
    END_IF
END_IF
bHeld := (nDir = 1 AND JogForward) OR (nDir = -1 AND JogBackwards);
bGoVel := nKind = 1 AND nDir <> 0 AND bHeld;
bGoHalt := nKind = 1 AND nDir <> 0 AND NOT bHeld;
bGoStep := nKind = 2 AND nDir <> 0;
fbVel(Axis := Axis, Execute := bGoVel, Velocity := fVel, Acceleration := fAcc, Deceleration := fDec,
      Jerk := Jerk, Direction := eDir);
fbHalt(Axis := Axis, Execute := bGoHalt, Deceleration := fDec, Jerk := Jerk);
fbStep(Axis := Axis, Execute := bGoStep, Distance := fDist, Velocity := fVel, Acceleration := fAcc,
       Deceleration := fDec, Jerk := Jerk);
Active := fbVel.Active OR fbHalt.Active OR fbStep.Active;
Error := fbVel.Error OR fbHalt.Error OR fbStep.Error OR nRefused <> 0;
IF nRefused <> 0 THEN
    ErrorID := nRefused;
ELSIF fbVel.Error THEN
    ErrorID := fbVel.ErrorID;
ELSIF fbHalt.Error THEN
    ErrorID := fbHalt.ErrorID;
ELSE
    ErrorID := fbStep.ErrorID;
END_IF
(* the end of a jog: stopped after the key was released, or the step done *)
IF nKind = 1 AND (fbHalt.Done OR fbHalt.Error OR fbVel.Error OR fbHalt.CommandAborted) THEN
    Done := fbHalt.Done;
    CommandAborted := fbHalt.CommandAborted;
    nDir := 0;
    nKind := 0;
ELSIF nKind = 2 AND (fbStep.Done OR fbStep.Error OR fbStep.CommandAborted) THEN
    Done := fbStep.Done;
    CommandAborted := fbStep.CommandAborted;
    nDir := 0;
    nKind := 0;
END_IF
Busy := nDir <> 0;
END_FUNCTION_BLOCK
";

const MOVE_MODULO: &str = "FUNCTION_BLOCK MC_MoveModulo
VAR_IN_OUT
    Axis : AXIS_REF;
END_VAR
VAR_INPUT
    Execute : BOOL;
    Position : LREAL;
    Velocity : LREAL;
    Acceleration : LREAL;
    Deceleration : LREAL;
    Jerk : LREAL;
    Direction : MC_Direction;
    BufferMode : MC_BufferMode;
END_VAR
VAR_OUTPUT
    Done : BOOL;
    Busy : BOOL;
    Active : BOOL;
    CommandAborted : BOOL;
    Error : BOOL;
    ErrorID : WORD;
END_VAR
VAR
    fbMove : MC_MoveRelative;
    fbPos : MC_ReadActualPosition;
    fbVel : MC_ReadActualVelocity;
    bLast : BOOL;
    bStart : BOOL;
    bGo : BOOL;
    nRefused : WORD;
    nAxis : UDINT;
    nTurns : DINT;
    fPeriod : LREAL;
    fAcc : LREAL;
    fDec : LREAL;
    fTurns : LREAL;
    fGoal : LREAL;
    fFwd : LREAL;
    fBack : LREAL;
    fVel : LREAL;
    fStop : LREAL;
    fDist : LREAL;
END_VAR
fbPos(Axis := Axis, Enable := TRUE);
fbVel(Axis := Axis, Enable := TRUE);
bStart := Execute AND NOT bLast;
bLast := Execute;
IF NOT Execute THEN
    nRefused := 0;
END_IF
IF bStart THEN
    nAxis := Axis.AxisNo;
    fPeriod := __TC2_MODULO[nAxis];
    fAcc := Acceleration;
    IF fAcc <= 0.0 THEN
        fAcc := __TC2_ACC[nAxis];
    END_IF
    fDec := Deceleration;
    IF fDec <= 0.0 THEN
        fDec := __TC2_DEC[nAxis];
    END_IF
    nRefused := 0;
    IF fPeriod <= 0.0 THEN
        nRefused := 24;
    ELSIF Direction > MC_Current_Direction THEN
        nRefused := 25;
    ELSE
        nTurns := LREAL_TO_DINT(Position / fPeriod);
        IF DINT_TO_LREAL(nTurns) > Position / fPeriod THEN
            nTurns := nTurns - 1;
        END_IF
        fTurns := DINT_TO_LREAL(nTurns);
        fGoal := Position - fTurns * fPeriod;
        fFwd := fGoal - fbPos.Position;
        IF fFwd < 0.0 THEN
            fFwd := fFwd + fPeriod;
        END_IF
        IF fFwd >= fPeriod THEN
            fFwd := fFwd - fPeriod;
        END_IF
        (* the rounding of a full turn (89.99999999999994 for 90) is no distance *)
        IF fFwd < fPeriod * 1.0E-9 OR fFwd > fPeriod * (1.0 - 1.0E-9) THEN
            fFwd := 0.0;
        END_IF
        IF fFwd = 0.0 THEN
            fBack := 0.0;
        ELSE
            fBack := fFwd - fPeriod;
        END_IF
        fVel := fbVel.Velocity;
        IF fVel = 0.0 THEN
            IF Direction = MC_Negative_Direction OR (Direction = MC_Shortest_Way AND -fBack < fFwd) THEN
                fDist := fBack - fTurns * fPeriod;
            ELSE
                fDist := fFwd + fTurns * fPeriod;
            END_IF
        ELSE
            fStop := fVel * fVel / (2.0 * fDec);
            IF fVel > 0.0 THEN
                fDist := fFwd;
                WHILE fDist < fStop DO
                    fDist := fDist + fPeriod;
                END_WHILE
            ELSE
                fDist := fBack;
                WHILE -fDist < fStop DO
                    fDist := fDist - fPeriod;
                END_WHILE
            END_IF
        END_IF
    END_IF
END_IF
bGo := Execute AND nRefused = 0;
fbMove(Axis := Axis, Execute := bGo, Distance := fDist, Velocity := Velocity,
       Acceleration := fAcc, Deceleration := fDec, Jerk := Jerk, BufferMode := BufferMode);
Done := fbMove.Done;
Busy := fbMove.Busy;
Active := fbMove.Active;
CommandAborted := fbMove.CommandAborted;
Error := fbMove.Error OR nRefused <> 0;
IF nRefused <> 0 THEN
    ErrorID := nRefused;
ELSE
    ErrorID := fbMove.ErrorID;
END_IF
END_FUNCTION_BLOCK
";

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
    added
}
