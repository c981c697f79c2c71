//! Beckhoff Tc2_MC2 blocks that ladderc builds from its PLCopen blocks: `MC_MoveModulo`.
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

use diagnostics::Diagnostics;
use il_frontend::ast::{CompilationUnit, LibraryElement, TypeRef};

/// The blocks ladderc builds: (name, ST text).
const BLOCKS: &[(&str, &str)] = &[("MC_MoveModulo", MOVE_MODULO)];

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

/// The names of the blocks ladderc builds, for the language server's completion.
pub fn names() -> impl Iterator<Item = &'static str> {
    BLOCKS.iter().map(|(n, _)| *n)
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

/// Adds the blocks the program uses (see the module header); true when one was added.
pub fn add(
    units: &mut Vec<CompilationUnit>,
    map: &mut diagnostics::SourceMap,
    diags: &mut Diagnostics,
) -> bool {
    let mut added = false;
    for (name, text) in BLOCKS {
        if !declares_type(units, name) {
            continue;
        }
        let file = map.add(format!("<Tc2_MC2 {name}>"), text.to_string());
        let (unit, pending, _) = il_frontend::st::file::parse_text(
            file,
            text,
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
