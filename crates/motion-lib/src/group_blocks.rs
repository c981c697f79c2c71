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
    ($(#[$m:meta])* $name:ident { $($f:ident : $t:ty),* } |$s:ident, $eng:ident, $g:ident| $body:expr) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, Default, PartialEq)]
        pub struct $name {
            pub execute: bool,
            $(pub $f: $t,)*
            pub done: bool,
            pub busy: bool,
            pub error: bool,
            pub error_id: ErrorId,
            #[doc(hidden)]
            pub core: ImmediateCore,
        }
        impl $name {
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
    McAddAxisToGroup { axis: usize, ident_in_group: usize }
    |s, eng, g| eng.add_axis_to_group(g, s.axis, s.ident_in_group)
);
immediate_block!(
    /// MC_RemoveAxisFromGroup (by IdentInGroup; only in GroupDisabled).
    McRemoveAxisFromGroup { ident_in_group: usize }
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
    ($(#[$m:meta])* $name:ident { $($f:ident : $t:ty),* } |$s:ident| $motion:expr) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, Default, PartialEq)]
        pub struct $name {
            pub execute: bool,
            $(pub $f: $t,)*
            pub velocity: f64,
            pub acceleration: f64,
            pub deceleration: f64,
            pub jerk: f64,
            /// 0 ACS, 1 MCS (both the axes' own coordinates here).
            pub coord_system: u8,
            pub buffer_mode: BufferMode,
            pub transition_mode: TransitionMode,
            pub transition_parameter: f64,
            pub done: bool,
            pub busy: bool,
            pub active: bool,
            pub command_aborted: bool,
            pub error: bool,
            pub error_id: ErrorId,
            #[doc(hidden)]
            pub core: ExecCore,
        }
        impl $name {
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
    McMoveLinearAbsolute { position: Vecn }
    |s| GroupMotion::LinearAbsolute { position: s.position }
);
motion_block!(
    /// MC_MoveLinearRelative.
    McMoveLinearRelative { distance: Vecn }
    |s| GroupMotion::LinearRelative { distance: s.distance }
);
motion_block!(
    /// MC_MoveDirectAbsolute (each axis on its own profile; Velocity etc. cap each axis).
    McMoveDirectAbsolute { position: Vecn }
    |s| GroupMotion::DirectAbsolute { position: s.position }
);
motion_block!(
    /// MC_MoveCircularAbsolute (CircMode BORDER, CENTER or RADIUS, see [`CircMode`];
    /// PathChoice: false = clockwise, true = counter-clockwise, CENTER and RADIUS only).
    McMoveCircularAbsolute { circ_mode: CircMode, aux_point: Vecn, end_point: Vecn, path_choice_ccw: bool }
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
    McMoveCircularRelative { circ_mode: CircMode, aux_point: Vecn, end_point: Vecn, path_choice_ccw: bool }
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
    pub execute: bool,
    pub position: Vecn,
    pub buffer_mode: BufferMode,
    pub done: bool,
    pub busy: bool,
    pub active: bool,
    pub command_aborted: bool,
    pub error: bool,
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: ExecCore,
}

impl McGroupHome {
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
    pub execute: bool,
    pub deceleration: f64,
    pub jerk: f64,
    pub buffer_mode: BufferMode,
    pub done: bool,
    pub busy: bool,
    pub active: bool,
    pub command_aborted: bool,
    pub error: bool,
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: ExecCore,
}

impl McGroupHalt {
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
    pub execute: bool,
    pub deceleration: f64,
    pub jerk: f64,
    pub done: bool,
    pub busy: bool,
    pub command_aborted: bool,
    pub error: bool,
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: StopCore,
}

impl McGroupStop {
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
    pub enable: bool,
    pub coord_system: u8,
    pub valid: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
    pub position: Vecn,
}

impl McGroupReadActualPosition {
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
    pub enable: bool,
    pub coord_system: u8,
    pub valid: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
    pub velocity: Vecn,
    pub path_velocity: f64,
}

impl McGroupReadActualVelocity {
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
    pub enable: bool,
    pub valid: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
    pub group_moving: bool,
    pub group_homing: bool,
    pub group_error_stop: bool,
    pub group_standby: bool,
    pub group_stopping: bool,
    pub group_disabled: bool,
}

impl McGroupReadStatus {
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
