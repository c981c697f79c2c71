//! PLCopen Part 1 function blocks (single axis), called once per PLC scan.
//!
//! Input: each block's PLCopen inputs (public fields), the engine and the axis index.
//! Output: the PLCopen outputs (public fields) after `call`. Invariants (Part 1 Table 2):
//! Execute-type blocks latch their inputs on the rising edge of Execute; Busy, Done,
//! Error and CommandAborted are mutually exclusive; Done, Error, ErrorID and
//! CommandAborted reset on the falling edge of Execute, but a final output that appears
//! after Execute fell is shown for one call; a falling Execute never stops a motion;
//! InVelocity/InGear/InSync follow the set value.

use crate::buffer::{BufferMode, Direction};
use crate::cmd::{CmdId, CmdStatus};
use crate::engine::{AxisCommand, Dynamics, Engine, MasterSource};
use crate::error::ErrorId;
use crate::fsm::AxisState;
use crate::sync::SyncParams;

/// ContinuousUpdate callback: re-sends the block's inputs for a Busy command.
pub type UpdateFn<'a> = Option<&'a mut dyn FnMut(&mut Engine, CmdId)>;

/// The common output logic of Execute-type blocks.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ExecCore {
    #[doc(hidden)]
    pub prev_execute: bool,
    #[doc(hidden)]
    pub cmd: Option<CmdId>,
    pub done: bool,
    pub busy: bool,
    pub active: bool,
    pub command_aborted: bool,
    pub error: bool,
    pub error_id: ErrorId,
    /// InVelocity / InGear / InSync (on the set value).
    pub in_target: bool,
    /// EndOfProfile (cams).
    pub end_of_profile: bool,
}

impl ExecCore {
    /// One call: `issue` gives the command on a rising edge while not Busy; `update`
    /// re-sends the inputs while Busy (ContinuousUpdate). Returns the command handle.
    pub fn cycle(
        &mut self,
        eng: &mut Engine,
        execute: bool,
        issue: impl FnOnce(&mut Engine) -> Result<CmdId, ErrorId>,
        update: UpdateFn<'_>,
    ) {
        let was_final = self.done || self.error || self.command_aborted;
        let rising = execute && !self.prev_execute;
        self.prev_execute = execute;
        if rising && !self.busy {
            self.done = false;
            self.error = false;
            self.command_aborted = false;
            self.error_id = ErrorId::None;
            self.in_target = false;
            match issue(eng) {
                Ok(id) => {
                    self.cmd = Some(id);
                    self.busy = true;
                }
                Err(e) => {
                    self.error = true;
                    self.error_id = e;
                }
            }
        } else if let (Some(id), Some(u)) = (self.cmd, update) {
            if execute {
                u(eng, id);
            }
        }
        self.track(eng, true);
        if !execute && was_final && !rising {
            self.done = false;
            self.error = false;
            self.command_aborted = false;
            self.error_id = ErrorId::None;
        }
    }

    /// One call of a single-axis command block: `cmd` is submitted to `axis` on a rising
    /// edge; with `continuous_update` a Busy command gets the inputs again every call.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn axis_cycle(
        &mut self,
        eng: &mut Engine,
        execute: bool,
        axis: usize,
        cmd: AxisCommand,
        d: Dynamics,
        bm: BufferMode,
        continuous_update: bool,
    ) {
        let mut upd = |e: &mut Engine, id: CmdId| {
            let _ = e.update(axis, id, cmd, d);
        };
        let update: UpdateFn<'_> = if continuous_update {
            Some(&mut upd)
        } else {
            None
        };
        self.cycle(eng, execute, |e| e.submit(axis, cmd, d, bm), update);
    }

    /// Reads the command's status into the outputs.
    fn track(&mut self, eng: &mut Engine, release: bool) {
        let Some(id) = self.cmd else {
            self.busy = false;
            self.active = false;
            return;
        };
        self.end_of_profile = eng.end_of_profile(id);
        match eng.status(id) {
            CmdStatus::Queued => {
                self.busy = true;
                self.active = false;
            }
            CmdStatus::Active => {
                self.busy = true;
                self.active = true;
                self.in_target = eng.in_target(id);
            }
            st => {
                self.busy = false;
                self.active = false;
                self.in_target = false;
                match st {
                    CmdStatus::Done => self.done = true,
                    CmdStatus::Error(e) => {
                        self.error = true;
                        self.error_id = e;
                    }
                    _ => self.command_aborted = true,
                }
                if release {
                    eng.release(id);
                    self.cmd = None;
                }
            }
        }
    }
}

fn dynamics(velocity: f64, acceleration: f64, deceleration: f64, jerk: f64) -> Dynamics {
    Dynamics {
        velocity,
        acceleration,
        deceleration,
        jerk,
    }
}

/// MC_Power (Enable-type).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McPower {
    pub enable: bool,
    pub enable_positive: bool,
    pub enable_negative: bool,
    pub status: bool,
    pub valid: bool,
    pub error: bool,
    pub error_id: ErrorId,
}

impl McPower {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        match eng.power(axis, self.enable) {
            Ok(st) => {
                self.status = st;
                self.error = false;
                self.error_id = ErrorId::None;
                self.valid = self.enable;
            }
            Err(e) => {
                self.status = false;
                self.valid = false;
                self.error = true;
                self.error_id = e;
            }
        }
    }
}

/// Copies a block's PLCopen outputs from its core: `(self)` Done, Busy, Active,
/// CommandAborted, Error, ErrorID; `(self, in_x)` the same with InVelocity / InGear /
/// InSync (`in_x`, on the set value while Active) instead of Done; `(@final self)` Done,
/// Busy, Error, ErrorID (blocks without Active and CommandAborted).
macro_rules! outputs_from_core {
    (@final $s:ident) => {
        $s.done = $s.core.done;
        $s.busy = $s.core.busy;
        $s.error = $s.core.error;
        $s.error_id = $s.core.error_id;
    };
    (@motion $s:ident) => {
        $s.busy = $s.core.busy;
        $s.active = $s.core.active;
        $s.command_aborted = $s.core.command_aborted;
        $s.error = $s.core.error;
        $s.error_id = $s.core.error_id;
    };
    ($s:ident) => {
        $s.done = $s.core.done;
        outputs_from_core!(@motion $s);
    };
    ($s:ident, $in_target:ident) => {
        $s.$in_target = $s.core.in_target && $s.core.active;
        outputs_from_core!(@motion $s);
    };
}
pub(crate) use outputs_from_core;

/// MC_MoveAbsolute.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McMoveAbsolute {
    pub execute: bool,
    pub continuous_update: bool,
    pub position: f64,
    pub velocity: f64,
    pub acceleration: f64,
    pub deceleration: f64,
    pub jerk: f64,
    pub direction: Direction,
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

impl McMoveAbsolute {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        let cmd = AxisCommand::MoveAbsolute {
            position: self.position,
            direction: self.direction,
        };
        let d = dynamics(
            self.velocity,
            self.acceleration,
            self.deceleration,
            self.jerk,
        );
        let (x, bm, cu) = (self.execute, self.buffer_mode, self.continuous_update);
        self.core.axis_cycle(eng, x, axis, cmd, d, bm, cu);
        outputs_from_core!(self);
    }
}

/// MC_MoveRelative and MC_MoveAdditive: the same inputs, a different command.
macro_rules! distance_block {
    ($(#[$m:meta])* $name:ident => $cmd:ident) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, Default, PartialEq)]
        pub struct $name {
            pub execute: bool,
            pub continuous_update: bool,
            pub distance: f64,
            pub velocity: f64,
            pub acceleration: f64,
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

        impl $name {
            pub fn call(&mut self, eng: &mut Engine, axis: usize) {
                let cmd = AxisCommand::$cmd {
                    distance: self.distance,
                };
                let d = dynamics(
                    self.velocity,
                    self.acceleration,
                    self.deceleration,
                    self.jerk,
                );
                let (x, bm) = (self.execute, self.buffer_mode);
                self.core.axis_cycle(eng, x, axis, cmd, d, bm, false);
                outputs_from_core!(self);
            }
        }
    };
}

distance_block!(
    /// MC_MoveRelative (Distance added to the set position when the command becomes active:
    /// at the rising Execute when Aborting or idle, else at the end of its predecessor).
    McMoveRelative => MoveRelative
);
distance_block!(
    /// MC_MoveAdditive (Distance added to the last commanded target).
    McMoveAdditive => MoveAdditive
);

/// MC_MoveVelocity.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McMoveVelocity {
    pub execute: bool,
    pub continuous_update: bool,
    pub velocity: f64,
    pub acceleration: f64,
    pub deceleration: f64,
    pub jerk: f64,
    pub direction: Direction,
    pub buffer_mode: BufferMode,
    pub in_velocity: bool,
    pub busy: bool,
    pub active: bool,
    pub command_aborted: bool,
    pub error: bool,
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: ExecCore,
}

impl McMoveVelocity {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        let cmd = AxisCommand::MoveVelocity {
            direction: self.direction,
        };
        let d = dynamics(
            self.velocity,
            self.acceleration,
            self.deceleration,
            self.jerk,
        );
        let (x, bm, cu) = (self.execute, self.buffer_mode, self.continuous_update);
        self.core.axis_cycle(eng, x, axis, cmd, d, bm, cu);
        outputs_from_core!(self, in_velocity);
    }
}

/// MC_Halt.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McHalt {
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

impl McHalt {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        let d = dynamics(0.0, self.deceleration, self.deceleration, self.jerk);
        let (x, bm) = (self.execute, self.buffer_mode);
        self.core
            .axis_cycle(eng, x, axis, AxisCommand::Halt, d, bm, false);
        outputs_from_core!(self);
    }
}

/// The output logic of MC_Stop and MC_GroupStop: as [`ExecCore`], but after Done the
/// command holds (the axis or group stays Stopping) while Execute is TRUE; it is released
/// when Execute falls, or by the next rising edge.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StopCore {
    #[doc(hidden)]
    pub prev_execute: bool,
    #[doc(hidden)]
    pub cmd: Option<CmdId>,
    pub done: bool,
    pub busy: bool,
    pub command_aborted: bool,
    pub error: bool,
    pub error_id: ErrorId,
}

impl StopCore {
    /// One call: `issue` gives the stop on a rising edge while not Busy; `release` ends
    /// the holding of a finished stop (the engine's `release_stop` of the axis or group).
    pub fn cycle(
        &mut self,
        eng: &mut Engine,
        execute: bool,
        issue: impl FnOnce(&mut Engine) -> Result<CmdId, ErrorId>,
        release: impl Fn(&mut Engine, CmdId),
    ) {
        let was_final = self.done || self.error || self.command_aborted;
        let rising = execute && !self.prev_execute;
        self.prev_execute = execute;
        if rising && !self.busy {
            if let Some(old) = self.cmd.take() {
                release(eng, old);
                eng.release(old);
            }
            self.done = false;
            self.error = false;
            self.command_aborted = false;
            self.error_id = ErrorId::None;
            match issue(eng) {
                Ok(id) => {
                    self.cmd = Some(id);
                    self.busy = true;
                }
                Err(e) => {
                    self.error = true;
                    self.error_id = e;
                }
            }
        }
        if let Some(id) = self.cmd {
            match eng.status(id) {
                CmdStatus::Queued | CmdStatus::Active => self.busy = true,
                CmdStatus::Done => {
                    self.busy = false;
                    self.done = true;
                    if !execute {
                        release(eng, id);
                        eng.release(id);
                        self.cmd = None;
                    }
                }
                st => {
                    self.busy = false;
                    if let CmdStatus::Error(e) = st {
                        self.error = true;
                        self.error_id = e;
                    } else {
                        self.command_aborted = true;
                    }
                    eng.release(id);
                    self.cmd = None;
                }
            }
        }
        if !execute && was_final && !rising {
            self.done = false;
            self.error = false;
            self.command_aborted = false;
            self.error_id = ErrorId::None;
        }
    }
}

/// MC_Stop. The axis stays Stopping while Execute is TRUE after Done.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McStop {
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

impl McStop {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        let d = dynamics(0.0, self.deceleration, self.deceleration, self.jerk);
        self.core.cycle(
            eng,
            self.execute,
            |e| e.submit(axis, AxisCommand::Stop, d, BufferMode::Aborting),
            |e, id| e.release_stop(axis, id),
        );
        outputs_from_core!(@final self);
        self.command_aborted = self.core.command_aborted;
    }
}

/// MC_Home (homing on the spot with a simulated drive: Position becomes the set position).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McHome {
    pub execute: bool,
    pub position: f64,
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

impl McHome {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        let cmd = AxisCommand::Home {
            position: self.position,
        };
        self.core.cycle(
            eng,
            self.execute,
            |e| e.submit(axis, cmd, Dynamics::default(), BufferMode::Aborting),
            None,
        );
        outputs_from_core!(self);
    }
}

/// Runs an immediate (one-call) command with Execute semantics: Done/Error shown while
/// Execute is TRUE and for at least one call after it falls.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ImmediateCore {
    #[doc(hidden)]
    pub prev_execute: bool,
    pub done: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
}

impl ImmediateCore {
    pub fn cycle(&mut self, execute: bool, run: impl FnOnce() -> Result<(), ErrorId>) {
        let was_final = self.done || self.error;
        let rising = execute && !self.prev_execute;
        self.prev_execute = execute;
        if rising {
            self.busy = false;
            match run() {
                Ok(()) => {
                    self.done = true;
                    self.error = false;
                    self.error_id = ErrorId::None;
                }
                Err(e) => {
                    self.done = false;
                    self.error = true;
                    self.error_id = e;
                }
            }
        } else if !execute && was_final {
            self.done = false;
            self.error = false;
            self.error_id = ErrorId::None;
        }
    }
}

/// MC_Reset.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McReset {
    pub execute: bool,
    pub done: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: ImmediateCore,
}

impl McReset {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        self.core.cycle(self.execute, || eng.reset(axis));
        outputs_from_core!(@final self);
    }
}

/// MC_SetPosition (ExecutionMode immediate).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McSetPosition {
    pub execute: bool,
    pub position: f64,
    pub relative: bool,
    pub done: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: ImmediateCore,
}

impl McSetPosition {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        let (p, r) = (self.position, self.relative);
        self.core
            .cycle(self.execute, || eng.set_position(axis, p, r));
        outputs_from_core!(@final self);
    }
}

/// MC_SetOverride (Enable-type): while Enable is TRUE the factors are written every call
/// (VelFactor >= 0, AccFactor and JerkFactor in (0, 1], 0 = 1; each re-plans
/// the running move; see [`Engine::set_override_factors`]). The last factors stay in
/// force after Enable falls.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McSetOverride {
    pub enable: bool,
    pub vel_factor: f64,
    pub acc_factor: f64,
    pub jerk_factor: f64,
    pub enabled: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
}

impl McSetOverride {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        if !self.enable {
            self.enabled = false;
            self.busy = false;
            self.error = false;
            self.error_id = ErrorId::None;
            return;
        }
        match eng.set_override_factors(axis, self.vel_factor, self.acc_factor, self.jerk_factor) {
            Ok(()) => {
                self.enabled = true;
                self.busy = true;
                self.error = false;
                self.error_id = ErrorId::None;
            }
            Err(e) => {
                self.enabled = false;
                self.busy = false;
                self.error = true;
                self.error_id = e;
            }
        }
    }
}

/// Enable-type read outputs.
fn read_outputs<T: Default>(
    enable: bool,
    r: Result<T, ErrorId>,
    valid: &mut bool,
    busy: &mut bool,
    error: &mut bool,
    error_id: &mut ErrorId,
) -> T {
    if !enable {
        *valid = false;
        *busy = false;
        *error = false;
        *error_id = ErrorId::None;
        return T::default();
    }
    match r {
        Ok(v) => {
            *valid = true;
            *busy = true;
            *error = false;
            *error_id = ErrorId::None;
            v
        }
        Err(e) => {
            *valid = false;
            *busy = false;
            *error = true;
            *error_id = e;
            T::default()
        }
    }
}

/// MC_ReadActualPosition.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McReadActualPosition {
    pub enable: bool,
    pub valid: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
    pub position: f64,
}

impl McReadActualPosition {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        self.position = read_outputs(
            self.enable,
            eng.actual_position(axis),
            &mut self.valid,
            &mut self.busy,
            &mut self.error,
            &mut self.error_id,
        );
    }
}

/// MC_ReadActualVelocity.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McReadActualVelocity {
    pub enable: bool,
    pub valid: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
    pub velocity: f64,
}

impl McReadActualVelocity {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        self.velocity = read_outputs(
            self.enable,
            eng.actual_velocity(axis),
            &mut self.valid,
            &mut self.busy,
            &mut self.error,
            &mut self.error_id,
        );
    }
}

/// MC_ReadStatus.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McReadStatus {
    pub enable: bool,
    pub valid: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
    pub error_stop: bool,
    pub disabled: bool,
    pub stopping: bool,
    pub homing: bool,
    pub standstill: bool,
    pub discrete_motion: bool,
    pub continuous_motion: bool,
    pub synchronized_motion: bool,
}

impl McReadStatus {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        let st: Option<AxisState> = read_outputs(
            self.enable,
            eng.axis_state(axis).map(Some),
            &mut self.valid,
            &mut self.busy,
            &mut self.error,
            &mut self.error_id,
        );
        self.error_stop = st == Some(AxisState::ErrorStop);
        self.disabled = st == Some(AxisState::Disabled);
        self.stopping = st == Some(AxisState::Stopping);
        self.homing = st == Some(AxisState::Homing);
        self.standstill = st == Some(AxisState::Standstill);
        self.discrete_motion = st == Some(AxisState::DiscreteMotion);
        self.continuous_motion = st == Some(AxisState::ContinuousMotion);
        self.synchronized_motion = st == Some(AxisState::SynchronizedMotion);
    }
}

/// MC_ReadAxisError.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McReadAxisError {
    pub enable: bool,
    pub valid: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
    pub axis_error_id: ErrorId,
}

impl McReadAxisError {
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        self.axis_error_id = read_outputs(
            self.enable,
            eng.axis_error(axis),
            &mut self.valid,
            &mut self.busy,
            &mut self.error,
            &mut self.error_id,
        );
    }
}

/// MC_GearIn (Master given as an axis index).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McGearIn {
    pub execute: bool,
    pub continuous_update: bool,
    pub ratio_numerator: f64,
    pub ratio_denominator: f64,
    pub master_value_source: MasterSource,
    pub acceleration: f64,
    pub deceleration: f64,
    pub jerk: f64,
    pub buffer_mode: BufferMode,
    pub in_gear: bool,
    pub busy: bool,
    pub active: bool,
    pub command_aborted: bool,
    pub error: bool,
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: ExecCore,
}

impl McGearIn {
    pub fn call(&mut self, eng: &mut Engine, master: usize, slave: usize) {
        let cmd = AxisCommand::GearIn {
            master,
            numerator: self.ratio_numerator,
            denominator: self.ratio_denominator,
            source: self.master_value_source,
        };
        let d = dynamics(0.0, self.acceleration, self.deceleration, self.jerk);
        let (x, bm) = (self.execute, self.buffer_mode);
        self.core.axis_cycle(eng, x, slave, cmd, d, bm, false);
        outputs_from_core!(self, in_gear);
    }
}

/// MC_GearOut / MC_CamOut.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McSyncOut {
    pub execute: bool,
    pub done: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: ExecCore,
}

/// MC_GearOut.
pub type McGearOut = McSyncOut;
/// MC_CamOut.
pub type McCamOut = McSyncOut;

impl McSyncOut {
    fn run(&mut self, eng: &mut Engine, slave: usize, cmd: AxisCommand) {
        self.core.cycle(
            eng,
            self.execute,
            |e| e.submit(slave, cmd, Dynamics::default(), BufferMode::Aborting),
            None,
        );
        outputs_from_core!(@final self);
    }

    /// Call as MC_GearOut.
    pub fn call_gear_out(&mut self, eng: &mut Engine, slave: usize) {
        self.run(eng, slave, AxisCommand::GearOut);
    }

    /// Call as MC_CamOut.
    pub fn call_cam_out(&mut self, eng: &mut Engine, slave: usize) {
        self.run(eng, slave, AxisCommand::CamOut);
    }
}

/// MC_CamTableSelect: checks a registered cam table and returns its CamTableID.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McCamTableSelect {
    pub execute: bool,
    /// The CAM_REF: index returned by `Engine::add_cam_table`.
    pub cam_table: usize,
    pub periodic: bool,
    pub master_absolute: bool,
    pub slave_absolute: bool,
    pub done: bool,
    pub busy: bool,
    pub error: bool,
    pub error_id: ErrorId,
    pub cam_table_id: usize,
    #[doc(hidden)]
    pub core: ImmediateCore,
}

impl McCamTableSelect {
    pub fn call(&mut self, eng: &mut Engine, master: usize, slave: usize) {
        let t = self.cam_table;
        self.core.cycle(self.execute, || {
            eng.axis_state(master)?;
            eng.axis_state(slave)?;
            eng.cam_table(t).map(|_| ())
        });
        if self.core.done {
            self.cam_table_id = t;
        }
        outputs_from_core!(@final self);
    }
}

/// MC_CamIn.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McCamIn {
    pub execute: bool,
    pub continuous_update: bool,
    pub master_offset: f64,
    pub slave_offset: f64,
    pub master_scaling: f64,
    pub slave_scaling: f64,
    pub master_value_source: MasterSource,
    pub cam_table_id: usize,
    pub periodic: bool,
    pub master_absolute: bool,
    pub slave_absolute: bool,
    pub buffer_mode: BufferMode,
    pub in_sync: bool,
    pub busy: bool,
    pub active: bool,
    pub command_aborted: bool,
    pub error: bool,
    pub error_id: ErrorId,
    pub end_of_profile: bool,
    #[doc(hidden)]
    pub core: ExecCore,
}

impl McCamIn {
    pub fn call(&mut self, eng: &mut Engine, master: usize, slave: usize) {
        let params = SyncParams {
            master,
            source: self.master_value_source,
            table: self.cam_table_id,
            periodic: self.periodic,
            master_absolute: self.master_absolute,
            slave_absolute: self.slave_absolute,
            master_offset: self.master_offset,
            slave_offset: self.slave_offset,
            master_scaling: if self.master_scaling == 0.0 {
                1.0
            } else {
                self.master_scaling
            },
            slave_scaling: if self.slave_scaling == 0.0 {
                1.0
            } else {
                self.slave_scaling
            },
            ..SyncParams::default()
        };
        let cmd = AxisCommand::CamIn { master, params };
        let (x, bm) = (self.execute, self.buffer_mode);
        self.core
            .axis_cycle(eng, x, slave, cmd, Dynamics::default(), bm, false);
        self.end_of_profile = self.core.end_of_profile && self.core.active;
        outputs_from_core!(self, in_sync);
    }
}
