//! PLCopen Part 4 function blocks (axes groups), called once per PLC scan.
//!
//! Input: each block's inputs (public fields), the engine and the group index. Output:
//! the PLCopen outputs. Invariants: the output rules of [`crate::blocks`] (shared
//! [`ExecCore`] / [`ImmediateCore`]); positions are arrays indexed by IdentInGroup.

use crate::blocks::{outputs_from_core, ExecCore, ImmediateCore, StopCore};
use crate::buffer::{BufferMode, TransitionMode};
use crate::engine::Engine;
use crate::error::ErrorId;
use crate::fsm::GroupState;
use crate::group::{GroupMotion, PathInputs};
use crate::path::{CircMode, Vecn, MAX_AXES};

macro_rules! immediate_block {
    ($(#[$m:meta])* $name:ident { $($(#[$fm:meta])* $f:ident : $t:ty),* $(,)? } |$s:ident, $eng:ident, $g:ident| $body:expr) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, Default, PartialEq)]
        pub struct $name {
            /// Execute: its rising edge carries out the command within this call; Done or Error
            /// then show while Execute stays TRUE (for one call if it already fell).
            pub execute: bool,
            $($(#[$fm])* pub $f: $t,)*
            /// Done: the command finished successfully: the group command was carried out.
            pub done: bool,
            /// Busy: always FALSE after the call: the command completes within the call.
            pub busy: bool,
            /// Error: the command was refused or failed; ErrorID says why.
            pub error: bool,
            /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the
            /// README's ErrorID table); 0 (None) while there is no error.
            pub error_id: ErrorId,
            #[doc(hidden)]
            pub core: ImmediateCore,
        }
        impl $name {
            /// One call (one PLC scan) on group `$g`: on a rising Execute carries out the
            /// group command at once and shows Done or Error.
            pub fn call(&mut self, $eng: &mut Engine, $g: usize) {
                let $s = *self;
                self.core.cycle(self.execute, || $body);
                outputs_from_core!(@final self);
            }
        }
    };
}

immediate_block!(
    /// MC_AddAxisToGroup (only in GroupDisabled).
    McAddAxisToGroup {
        /// Axis: index of the axis to add (unknown: ErrorID 1 InvalidAxis; already in a group:
        /// ErrorID 56).
        axis: usize,
        /// IdentInGroup: the axis's identity in the group, 0..15 (X, Y, Z, A, ...;
        /// `path::IDENT_NAMES`); out of range or already used gives ErrorID 55.
        ident_in_group: usize,
    }
    |s, eng, g| eng.add_axis_to_group(g, s.axis, s.ident_in_group)
);
immediate_block!(
    /// MC_RemoveAxisFromGroup (by IdentInGroup; only in GroupDisabled).
    McRemoveAxisFromGroup {
        /// IdentInGroup: identity (0..15) of the axis to remove; an identity with no axis gives
        /// ErrorID 57 AxisNotInGroup.
        ident_in_group: usize,
    }
    |s, eng, g| eng.remove_axis_from_group(g, s.ident_in_group)
);
immediate_block!(
    /// MC_UngroupAllAxes.
    McUngroupAllAxes {}
    |_s, eng, g| eng.ungroup_all(g)
);
immediate_block!(
    /// MC_GroupEnable.
    McGroupEnable {}
    |_s, eng, g| eng.group_enable(g)
);
immediate_block!(
    /// MC_GroupDisable.
    McGroupDisable {}
    |_s, eng, g| eng.group_disable(g)
);
immediate_block!(
    /// MC_GroupReset.
    McGroupReset {}
    |_s, eng, g| eng.group_reset(g)
);

macro_rules! motion_block {
    ($(#[$m:meta])* $name:ident { $($(#[$fm:meta])* $f:ident : $t:ty),* $(,)? } |$s:ident| $motion:expr) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, Default, PartialEq)]
        pub struct $name {
            /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and
            /// issues the command; a rising edge while Busy is ignored. Its falling edge never
            /// stops a motion, it only resets Done, Error, ErrorID and CommandAborted.
            pub execute: bool,
            $($(#[$fm])* pub $f: $t,)*
            /// Velocity: largest path speed, u/s; finite and > 0 (else ErrorID 20); further
            /// limited by the axes' limits projected onto the path.
            pub velocity: f64,
            /// Acceleration: path acceleration, u/s², finite and > 0 (else ErrorID 21); further
            /// limited by the axes' limits.
            pub acceleration: f64,
            /// Deceleration: path deceleration, u/s², finite and > 0 (else ErrorID 22); further
            /// limited by the axes' limits.
            pub deceleration: f64,
            /// Jerk: path jerk, u/s³, finite and >= 0 (else ErrorID 23); 0 = the axes' jerk limit.
            pub jerk: f64,
            /// 0 ACS, 1 MCS (both the axes' own coordinates here).
            pub coord_system: u8,
            /// BufferMode: when the command starts relative to the one running: Aborting (0, at
            /// once), Buffered (1, after the predecessor finished) or
            /// BlendingLow/Previous/Next/High (2..5, without stopping at the junction); another
            /// value gives ErrorID 26 InvalidBufferMode.
            pub buffer_mode: BufferMode,
            /// TransitionMode: the curve joining this move to its predecessor under a blending
            /// BufferMode: TMNone (0, through the corner), TMCornerDistance (3) or
            /// TMMaxCornerDeviation (4); TMStartVelocity (1), TMConstantVelocity (2) and values
            /// above 4 give ErrorID 59 InvalidTransitionMode.
            pub transition_mode: TransitionMode,
            /// TransitionParameter: for TMCornerDistance the corner distance d, for
            /// TMMaxCornerDeviation the largest distance e the path may pass from the corner, in u
            /// (>= 0, else ErrorID 59); capped at half of either line.
            pub transition_parameter: f64,
            /// Done: the end point was reached (set value).
            pub done: bool,
            /// Busy: the command was accepted and has not finished (queued in the buffer or
            /// running).
            pub busy: bool,
            /// Active: this block's command controls the axis now (a buffered one is Busy but not
            /// yet Active).
            pub active: bool,
            /// CommandAborted: another command (an Aborting block, MC_Stop, power-off or an axis
            /// error) took over before this one finished.
            pub command_aborted: bool,
            /// Error: the command was refused or failed; ErrorID says why.
            pub error: bool,
            /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the
            /// README's ErrorID table); 0 (None) while there is no error.
            pub error_id: ErrorId,
            #[doc(hidden)]
            pub core: ExecCore,
        }
        impl $name {
            /// One call (one PLC scan) on `group`: on a rising Execute submits the path move
            /// with BufferMode and TransitionMode (refused with ErrorID 61 for a CoordSystem
            /// above 1); writes the outputs from the command's status.
            pub fn call(&mut self, eng: &mut Engine, group: usize) {
                let $s = *self;
                let motion = $motion;
                let inputs = PathInputs {
                    velocity: $s.velocity,
                    acceleration: $s.acceleration,
                    deceleration: $s.deceleration,
                    jerk: $s.jerk,
                    buffer: $s.buffer_mode,
                    transition: $s.transition_mode,
                    transition_parameter: $s.transition_parameter,
                };
                let cs = $s.coord_system;
                self.core.cycle(
                    eng,
                    self.execute,
                    |e| {
                        if cs > 1 {
                            return Err(ErrorId::InvalidCoordSystem);
                        }
                        e.submit_group(group, motion, inputs)
                    },
                    None,
                );
                outputs_from_core!(self);
            }
        }
    };
}

motion_block!(
    /// MC_MoveLinearAbsolute.
    McMoveLinearAbsolute {
        /// Position: end point per identity (IdentInGroup: X, Y, Z, ...), in u; entries of
        /// identities with no axis in the group are ignored.
        position: Vecn,
    }
    |s| GroupMotion::LinearAbsolute { position: s.position }
);
motion_block!(
    /// MC_MoveLinearRelative.
    McMoveLinearRelative {
        /// Distance per identity, in u, added to the group's last commanded point; entries of
        /// absent identities are ignored.
        distance: Vecn,
    }
    |s| GroupMotion::LinearRelative { distance: s.distance }
);
motion_block!(
    /// MC_MoveDirectAbsolute (each axis on its own profile; Velocity etc. cap each axis).
    McMoveDirectAbsolute {
        /// Position: end point per identity, in u; each axis moves there on its own profile (absent
        /// identities ignored).
        position: Vecn,
    }
    |s| GroupMotion::DirectAbsolute { position: s.position }
);
motion_block!(
    /// MC_MoveCircularAbsolute (CircMode BORDER, CENTER or RADIUS, see [`CircMode`];
    /// PathChoice: false = clockwise, true = counter-clockwise, CENTER and RADIUS only).
    McMoveCircularAbsolute {
        /// CircMode: how AuxPoint defines the circle: Border, Center or Radius (see [`CircMode`]).
        circ_mode: CircMode,
        /// AuxPoint: per identity, in u: BORDER a point on the arc between start and end, CENTER
        /// the centre (X/Y plane), RADIUS the normal vector of the circle's plane, its length the
        /// radius.
        aux_point: Vecn,
        /// EndPoint: end point of the arc per identity (X/Y/Z on the arc, other axes linear), in u.
        end_point: Vecn,
        /// PathChoice (CENTER and RADIUS): FALSE clockwise, TRUE counter-clockwise (about +Z, or
        /// seen from the tip of the RADIUS normal). Ignored for BORDER.
        path_choice_ccw: bool,
    }
    |s| GroupMotion::Circular {
        mode: s.circ_mode,
        aux: s.aux_point,
        end: s.end_point,
        ccw: s.path_choice_ccw,
        relative: false,
    }
);
motion_block!(
    /// MC_MoveCircularRelative (AuxPoint and EndPoint relative to the start point; in
    /// RADIUS mode AuxPoint is the plane's normal vector either way).
    McMoveCircularRelative {
        /// CircMode: how AuxPoint defines the circle: Border, Center or Radius (see [`CircMode`]).
        circ_mode: CircMode,
        /// AuxPoint per identity, in u, relative to the start point: BORDER a point on the arc,
        /// CENTER the centre (X/Y plane); RADIUS the normal vector of the circle's plane (never
        /// relative), its length the radius.
        aux_point: Vecn,
        /// EndPoint: end of the arc relative to the start point, per identity, in u.
        end_point: Vecn,
        /// PathChoice (CENTER and RADIUS): FALSE clockwise, TRUE counter-clockwise (about +Z, or
        /// seen from the tip of the RADIUS normal). Ignored for BORDER.
        path_choice_ccw: bool,
    }
    |s| GroupMotion::Circular {
        mode: s.circ_mode,
        aux: s.aux_point,
        end: s.end_point,
        ccw: s.path_choice_ccw,
        relative: true,
    }
);

/// MC_GroupHome (Position by identity: the set positions after homing on the spot).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McGroupHome {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub execute: bool,
    /// Position per identity (IdentInGroup), in u: each axis's set position after homing (simulated
    /// drives home on the spot).
    pub position: Vecn,
    /// BufferMode: not used, group homing always starts at once (the C call still refuses an
    /// unknown value with ErrorID 26); it needs GroupStandby.
    pub buffer_mode: BufferMode,
    /// Done: every axis of the group homed; the group is back in GroupStandby.
    pub done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub busy: bool,
    /// Active: this block's command controls the axis now (a buffered one is Busy but not yet
    /// Active).
    pub active: bool,
    /// CommandAborted: another command (an Aborting block, MC_Stop, power-off or an axis error)
    /// took over before this one finished.
    pub command_aborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: ExecCore,
}

impl McGroupHome {
    /// One call (one PLC scan) on `group`: on a rising Execute homes every axis of the group (from
    /// GroupStandby; GroupHoming, then GroupStandby).
    pub fn call(&mut self, eng: &mut Engine, group: usize) {
        let pos = self.position;
        self.core
            .cycle(eng, self.execute, |e| e.group_home(group, pos), None);
        outputs_from_core!(self);
    }
}

/// Path inputs of MC_GroupHalt and MC_GroupStop: brake with `deceleration` and `jerk`.
fn braking(deceleration: f64, jerk: f64) -> PathInputs {
    PathInputs {
        velocity: 1.0,
        acceleration: deceleration,
        deceleration,
        jerk,
        ..PathInputs::default()
    }
}

/// MC_GroupHalt.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McGroupHalt {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub execute: bool,
    /// Deceleration: path braking rate in u/s², finite and > 0 (else ErrorID 22).
    pub deceleration: f64,
    /// Jerk of the path braking in u/s³ (>= 0; 0 = the axes' jerk limit).
    pub jerk: f64,
    /// BufferMode: Aborting (0) brakes at once; Buffered (1) brakes after the running move ended
    /// (which is then at rest); unknown: ErrorID 26.
    pub buffer_mode: BufferMode,
    /// Done: the group reached path velocity 0 (GroupStandby).
    pub done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub busy: bool,
    /// Active: this block's command controls the axis now (a buffered one is Busy but not yet
    /// Active).
    pub active: bool,
    /// CommandAborted: another command (an Aborting block, MC_Stop, power-off or an axis error)
    /// took over before this one finished.
    pub command_aborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: ExecCore,
}

impl McGroupHalt {
    /// One call (one PLC scan) on `group`: on a rising Execute brakes the path to velocity 0 with
    /// Deceleration and Jerk (GroupMoving until it stands, then GroupStandby).
    pub fn call(&mut self, eng: &mut Engine, group: usize) {
        let inputs = PathInputs {
            buffer: self.buffer_mode,
            ..braking(self.deceleration, self.jerk)
        };
        self.core.cycle(
            eng,
            self.execute,
            |e| e.submit_group(group, GroupMotion::Halt, inputs),
            None,
        );
        outputs_from_core!(self);
    }
}

/// MC_GroupStop: the group stays GroupStopping while Execute is TRUE after Done.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McGroupStop {
    /// Execute: its rising edge starts braking, aborting every command of the group (also from
    /// Standstill); while Execute stays TRUE after Done the group stays GroupStopping and refuses
    /// motion commands; its falling edge releases it.
    pub execute: bool,
    /// Deceleration: path braking rate in u/s², finite and > 0 (else ErrorID 22).
    pub deceleration: f64,
    /// Jerk of the path braking in u/s³ (>= 0; 0 = the axes' jerk limit).
    pub jerk: f64,
    /// Done: the group reached path velocity 0; it stays GroupStopping (motion commands refused)
    /// while Execute is TRUE.
    pub done: bool,
    /// Busy: the group is still braking.
    pub busy: bool,
    /// CommandAborted: the stop was ended by an axis error or a disable before it finished.
    pub command_aborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: StopCore,
}

impl McGroupStop {
    /// One call (one PLC scan) on `group`: on a rising Execute aborts every group command and
    /// brakes the path (GroupStopping); holds GroupStopping while Execute stays TRUE after Done.
    pub fn call(&mut self, eng: &mut Engine, group: usize) {
        let inputs = braking(self.deceleration, self.jerk);
        self.core.cycle(
            eng,
            self.execute,
            |e| e.submit_group(group, GroupMotion::Stop, inputs),
            |e, id| e.release_group_stop(group, id),
        );
        outputs_from_core!(@final self);
        self.command_aborted = self.core.command_aborted;
    }
}

/// MC_GroupReadActualPosition / Velocity and MC_GroupReadStatus share these outputs.
fn enable_outputs(
    enable: bool,
    ok: Result<(), ErrorId>,
    valid: &mut bool,
    busy: &mut bool,
    error: &mut bool,
    id: &mut ErrorId,
) {
    *valid = enable && ok.is_ok();
    *busy = enable && ok.is_ok();
    *error = enable && ok.is_err();
    *id = if enable {
        ok.err().unwrap_or_default()
    } else {
        ErrorId::None
    };
}

/// MC_GroupReadActualPosition (set positions; the simulated drives follow exactly).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McGroupReadActualPosition {
    /// Enable: while TRUE the block works and its outputs are refreshed every call; FALSE resets
    /// the outputs.
    pub enable: bool,
    /// CoordSystem: kept for the PLCopen interface; positions are always the axes' own coordinates
    /// (ACS = MCS here).
    pub coord_system: u8,
    /// Valid: the value outputs are valid (Enable TRUE and no error).
    pub valid: bool,
    /// Busy: TRUE while Enable is TRUE and the values are valid.
    pub busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    /// Position per identity, in u (the set positions; the simulated drives follow them exactly);
    /// zeros for absent identities.
    pub position: Vecn,
}

impl McGroupReadActualPosition {
    /// One call (one PLC scan) on `group`: while Enable is TRUE reads the position of every
    /// identity.
    pub fn call(&mut self, eng: &mut Engine, group: usize) {
        let r = eng.group_position(group);
        self.position = *r.as_ref().unwrap_or(&[0.0; MAX_AXES]);
        enable_outputs(
            self.enable,
            r.map(|_| ()),
            &mut self.valid,
            &mut self.busy,
            &mut self.error,
            &mut self.error_id,
        );
    }
}

/// MC_GroupReadActualVelocity (per identity, plus the path velocity).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McGroupReadActualVelocity {
    /// Enable: while TRUE the block works and its outputs are refreshed every call; FALSE resets
    /// the outputs.
    pub enable: bool,
    /// CoordSystem: kept for the PLCopen interface; velocities are always in the axes' own
    /// coordinates (ACS = MCS here).
    pub coord_system: u8,
    /// Valid: the value outputs are valid (Enable TRUE and no error).
    pub valid: bool,
    /// Busy: TRUE while Enable is TRUE and the values are valid.
    pub busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    /// Velocity per identity, in u/s; zeros for absent identities.
    pub velocity: Vecn,
    /// PathVelocity: the speed along the path, u/s (>= 0).
    pub path_velocity: f64,
}

impl McGroupReadActualVelocity {
    /// One call (one PLC scan) on `group`: while Enable is TRUE reads the velocity of every
    /// identity and the path velocity.
    pub fn call(&mut self, eng: &mut Engine, group: usize) {
        let r = eng.group_velocity(group);
        let (v, pv) = *r.as_ref().unwrap_or(&([0.0; MAX_AXES], 0.0));
        self.velocity = v;
        self.path_velocity = pv;
        enable_outputs(
            self.enable,
            r.map(|_| ()),
            &mut self.valid,
            &mut self.busy,
            &mut self.error,
            &mut self.error_id,
        );
    }
}

/// MC_GroupReadStatus.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McGroupReadStatus {
    /// Enable: while TRUE the block works and its outputs are refreshed every call; FALSE resets
    /// the outputs.
    pub enable: bool,
    /// Valid: the value outputs are valid (Enable TRUE and no error).
    pub valid: bool,
    /// Busy: TRUE while Enable is TRUE and the state is valid.
    pub busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    /// GroupMoving: a group motion (line, circle, direct move, halt) runs.
    pub group_moving: bool,
    /// GroupHoming: MC_GroupHome runs.
    pub group_homing: bool,
    /// GroupErrorStop: the group is in GroupErrorStop (an axis of it failed; leave it with
    /// MC_GroupReset).
    pub group_error_stop: bool,
    /// GroupStandby: the group is enabled and stands still with no command.
    pub group_standby: bool,
    /// GroupStopping: MC_GroupStop brakes or holds the group.
    pub group_stopping: bool,
    /// GroupDisabled: the group is not enabled (axes may be added or removed).
    pub group_disabled: bool,
}

impl McGroupReadStatus {
    /// One call (one PLC scan) on `group`: while Enable is TRUE sets exactly one of the state
    /// outputs (the group's PLCopen state).
    pub fn call(&mut self, eng: &mut Engine, group: usize) {
        let r = eng.group_state(group);
        let st = if self.enable { r.ok() } else { None };
        self.group_moving = st == Some(GroupState::GroupMoving);
        self.group_homing = st == Some(GroupState::GroupHoming);
        self.group_error_stop = st == Some(GroupState::GroupErrorStop);
        self.group_standby = st == Some(GroupState::GroupStandby);
        self.group_stopping = st == Some(GroupState::GroupStopping);
        self.group_disabled = st == Some(GroupState::GroupDisabled);
        enable_outputs(
            self.enable,
            r.map(|_| ()),
            &mut self.valid,
            &mut self.busy,
            &mut self.error,
            &mut self.error_id,
        );
    }
}
