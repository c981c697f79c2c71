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
    /// Done: the command finished successfully; stays TRUE while Execute is TRUE (one call if
    /// Execute is already FALSE).
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
        if rising && self.busy {
            // Busy is as of the last call: the command may have ended since, in the engine's
            // step (finished, or aborted by another block, as MC_Halt aborts MC_MoveVelocity).
            // The block is then not Busy, and the rising edge issues the new command.
            self.track(eng, true);
        }
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
    /// Enable: TRUE powers the axis (Disabled to Standstill); FALSE disables it: every command is
    /// aborted and the axis goes to Disabled (an axis in ErrorStop stays there until MC_Reset).
    pub enable: bool,
    /// EnablePositive: PLCopen input kept for the interface; the drive interface has no direction
    /// enable, so it has no effect.
    pub enable_positive: bool,
    /// EnableNegative: PLCopen input kept for the interface; the drive interface has no direction
    /// enable, so it has no effect.
    pub enable_negative: bool,
    /// Status: the axis is powered (the drive is enabled; the axis left Disabled).
    pub status: bool,
    /// Valid: Status is valid (Enable TRUE and no error).
    pub valid: bool,
    /// Error: the power command failed (e.g. an unknown axis); ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
}

impl McPower {
    /// One call (one PLC scan) on `axis`: powers the axis on or off as Enable says and writes
    /// Status, Valid, Error and ErrorID.
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
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub execute: bool,
    /// ContinuousUpdate: while TRUE and the block Busy, inputs changed since the last call re-plan
    /// the running command from its current position, velocity and acceleration.
    pub continuous_update: bool,
    /// Position: target position in user units (u); on a modulo axis taken modulo the period and
    /// reached the way Direction says.
    pub position: f64,
    /// Velocity: largest speed of the move in u/s; finite and non-zero (its magnitude is used, else
    /// ErrorID 20 InvalidVelocity); above the axis's velocity limit it is capped to it.
    pub velocity: f64,
    /// Acceleration: u/s², finite and > 0 (else ErrorID 21 InvalidAcceleration); capped by the
    /// axis's acceleration limit.
    pub acceleration: f64,
    /// Deceleration: u/s², finite and > 0 (else ErrorID 22 InvalidDeceleration); capped by the
    /// axis's deceleration limit.
    pub deceleration: f64,
    /// Jerk: u/s³, finite and >= 0 (else ErrorID 23 InvalidJerk); 0 means the axis's jerk limit, a
    /// larger value is capped to it.
    pub jerk: f64,
    /// Direction (modulo axes only): positive (0), shortest way (1), negative (2) or current
    /// direction (3); ignored on a linear axis; another value gives ErrorID 25 InvalidDirection.
    pub direction: Direction,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub buffer_mode: BufferMode,
    /// Done: the command finished successfully; stays TRUE while Execute is TRUE (one call if
    /// Execute is already FALSE).
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

impl McMoveAbsolute {
    /// One call (one PLC scan) on `axis`: on a rising Execute submits the move to Position with
    /// BufferMode; with ContinuousUpdate re-plans it while Busy; writes the outputs from the
    /// command's status.
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
            /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and
            /// issues the command; a rising edge while Busy is ignored. Its falling edge never
            /// stops a motion, it only resets Done, Error, ErrorID and CommandAborted.
            pub execute: bool,
            /// ContinuousUpdate: part of the PLCopen interface but not acted on by these blocks:
            /// Distance is latched at the rising edge.
            pub continuous_update: bool,
            /// Distance in u: MC_MoveRelative adds it to the set position when the command becomes
            /// active, MC_MoveAdditive to the last commanded target.
            pub distance: f64,
            /// Velocity: largest speed of the move in u/s; finite and non-zero (its magnitude is
            /// used, else ErrorID 20 InvalidVelocity); above the axis's velocity limit it is capped
            /// to it.
            pub velocity: f64,
            /// Acceleration: u/s², finite and > 0 (else ErrorID 21 InvalidAcceleration); capped by
            /// the axis's acceleration limit.
            pub acceleration: f64,
            /// Deceleration: u/s², finite and > 0 (else ErrorID 22 InvalidDeceleration); capped by
            /// the axis's deceleration limit.
            pub deceleration: f64,
            /// Jerk: u/s³, finite and >= 0 (else ErrorID 23 InvalidJerk); 0 means the axis's jerk
            /// limit, a larger value is capped to it.
            pub jerk: f64,
            /// BufferMode: when the command starts relative to the one running: Aborting (0, at
            /// once), Buffered (1, after the predecessor finished) or
            /// BlendingLow/Previous/Next/High (2..5, without stopping at the junction); another
            /// value gives ErrorID 26 InvalidBufferMode.
            pub buffer_mode: BufferMode,
            /// Done: the target was reached (set value).
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
            /// One call (one PLC scan) on `axis`: on a rising Execute submits the move by
            /// Distance with BufferMode; writes the outputs from the command's status.
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
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Error, ErrorID and CommandAborted.
    pub execute: bool,
    /// ContinuousUpdate: while TRUE and the block Busy, inputs changed since the last call re-plan
    /// the running command from its current position, velocity and acceleration.
    pub continuous_update: bool,
    /// Velocity: target speed in u/s, finite and non-zero (else ErrorID 20); its sign times
    /// Direction gives the direction of travel; capped by the axis's velocity limit.
    pub velocity: f64,
    /// Acceleration: u/s², finite and > 0 (else ErrorID 21 InvalidAcceleration); capped by the
    /// axis's acceleration limit.
    pub acceleration: f64,
    /// Deceleration: u/s², finite and > 0 (else ErrorID 22 InvalidDeceleration); capped by the
    /// axis's deceleration limit.
    pub deceleration: f64,
    /// Jerk: u/s³, finite and >= 0 (else ErrorID 23 InvalidJerk); 0 means the axis's jerk limit, a
    /// larger value is capped to it.
    pub jerk: f64,
    /// Direction: positive (0), negative (2) or current (3, the sign of the set velocity); shortest
    /// way (1) or another value gives ErrorID 25 InvalidDirection. A negative Velocity reverses it.
    pub direction: Direction,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub buffer_mode: BufferMode,
    /// InVelocity: the set velocity reached the commanded Velocity (while Active); a Buffered
    /// successor starts after it was shown for one scan.
    pub in_velocity: bool,
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

impl McMoveVelocity {
    /// One call (one PLC scan) on `axis`: on a rising Execute submits the velocity move; with
    /// ContinuousUpdate re-plans it while Busy; InVelocity follows the set velocity.
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
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub execute: bool,
    /// Deceleration: braking rate in u/s², finite and > 0 (else ErrorID 22); capped by the axis's
    /// deceleration limit.
    pub deceleration: f64,
    /// Jerk of the braking in u/s³ (>= 0; 0 = the axis's jerk limit).
    pub jerk: f64,
    /// BufferMode: Aborting (0) brakes at once; Buffered (1) halts after the running move ended;
    /// unknown: ErrorID 26.
    pub buffer_mode: BufferMode,
    /// Done: the axis reached velocity 0 (Standstill); unlike MC_Stop it takes further commands at
    /// any time.
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

impl McHalt {
    /// One call (one PLC scan) on `axis`: on a rising Execute submits a controlled stop to velocity
    /// 0 (the axis stays in DiscreteMotion until it stands, then Standstill).
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
    /// Done: the command finished successfully; stays TRUE while Execute is TRUE (one call if
    /// Execute is already FALSE).
    pub done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub busy: bool,
    /// CommandAborted: another command (an Aborting block, MC_Stop, power-off or an axis error)
    /// took over before this one finished.
    pub command_aborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
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
    /// Execute: its rising edge starts braking, aborting every command of the axis (also from
    /// Standstill); while Execute stays TRUE after Done the axis stays Stopping and refuses motion
    /// commands; its falling edge releases it.
    pub execute: bool,
    /// Deceleration: braking rate in u/s², finite and > 0 (else ErrorID 22); capped by the axis's
    /// deceleration limit and never scaled by the override.
    pub deceleration: f64,
    /// Jerk of the braking in u/s³ (>= 0; 0 = the axis's jerk limit, a larger value is capped to
    /// it).
    pub jerk: f64,
    /// Done: the axis reached velocity 0; it stays Stopping (motion commands refused) while Execute
    /// is TRUE.
    pub done: bool,
    /// Busy: the axis is still braking.
    pub busy: bool,
    /// CommandAborted: the stop was ended by power-off or an axis error before it finished.
    pub command_aborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: StopCore,
}

impl McStop {
    /// One call (one PLC scan) on `axis`: on a rising Execute aborts every command of the axis and
    /// brakes it (state Stopping); holds the axis in Stopping while Execute stays TRUE after Done.
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
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub execute: bool,
    /// Position: the axis's position after homing, in u (a simulated drive homes on the spot: the
    /// set position becomes Position).
    pub position: f64,
    /// BufferMode: not used, homing always starts at once (the C call still refuses an unknown
    /// value with ErrorID 26); it needs Standstill (ErrorID 14 NotStandstill while the axis moves).
    pub buffer_mode: BufferMode,
    /// Done: homing finished; the axis is back in Standstill at Position.
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

impl McHome {
    /// One call (one PLC scan) on `axis`: on a rising Execute submits homing (from Standstill;
    /// state Homing until the drive reports the end).
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
    /// Done: the command finished successfully; stays TRUE while Execute is TRUE (one call if
    /// Execute is already FALSE).
    pub done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
}

impl ImmediateCore {
    /// One call: on a rising Execute runs `run` at once and shows Done or Error (with its
    /// ErrorID); they reset on the falling edge of Execute (or one call later when Execute
    /// fell before they appeared). Busy is always FALSE after the call.
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
    /// Execute: its rising edge carries out the command within this call; Done or Error then show
    /// while Execute stays TRUE (for one call if it already fell).
    pub execute: bool,
    /// Done: the reset was carried out: the axis left ErrorStop (to Standstill if powered), or it
    /// was not in ErrorStop and nothing was done.
    pub done: bool,
    /// Busy: always FALSE after the call: the reset completes within the call.
    pub busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: ImmediateCore,
}

impl McReset {
    /// One call (one PLC scan) on `axis`: on a rising Execute takes the axis out of ErrorStop (to
    /// Standstill if powered, else Disabled); refused (ErrorID 17 or 18) while it still brakes or
    /// the drive still reports a fault.
    pub fn call(&mut self, eng: &mut Engine, axis: usize) {
        self.core.cycle(self.execute, || eng.reset(axis));
        outputs_from_core!(@final self);
    }
}

/// MC_SetPosition (ExecutionMode immediate).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct McSetPosition {
    /// Execute: its rising edge carries out the command within this call; Done or Error then show
    /// while Execute stays TRUE (for one call if it already fell).
    pub execute: bool,
    /// Position: the new set position in u (Relative FALSE) or the shift added to it (Relative
    /// TRUE); finite, else ErrorID 24 InvalidPosition. Refused while Homing or in ErrorStop.
    pub position: f64,
    /// Relative: FALSE = Position becomes the axis's set position; TRUE = Position is added to it
    /// (a shift of the coordinate origin, no motion).
    pub relative: bool,
    /// Done: the coordinate shift was applied (immediately, within the call).
    pub done: bool,
    /// Busy: always FALSE after the call: the shift completes within the call.
    pub busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    #[doc(hidden)]
    pub core: ImmediateCore,
}

impl McSetPosition {
    /// One call (one PLC scan) on `axis`: on a rising Execute shifts the axis's coordinates so that
    /// its set position becomes Position (or moves by Position when Relative); no motion.
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
    /// Enable: while TRUE the factors are written every call; when it falls the outputs reset and
    /// the last factors stay in force.
    pub enable: bool,
    /// VelFactor: scale of the velocity limit of the running and later moves, >= 0 (0 brakes the
    /// move to standstill until it rises again); the axis's velocity limit still caps it.
    pub vel_factor: f64,
    /// AccFactor: scale of the acceleration and deceleration limits, in (0, 1]; 0 stands for 1; out
    /// of range gives ErrorID 30 InvalidOverride.
    pub acc_factor: f64,
    /// JerkFactor: scale of the jerk limit, in (0, 1]; 0 stands for 1; out of range gives ErrorID
    /// 30 InvalidOverride.
    pub jerk_factor: f64,
    /// Enabled: the factors were accepted and are written every call while Enable is TRUE.
    pub enabled: bool,
    /// Busy: TRUE while Enable is TRUE and the factors are accepted.
    pub busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
}

impl McSetOverride {
    /// One call (one PLC scan) on `axis`: while Enable is TRUE writes the three factors (each
    /// change re-plans the running move within the scaled limits).
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
    /// Enable: while TRUE the block works and its outputs are refreshed every call; FALSE resets
    /// the outputs.
    pub enable: bool,
    /// Valid: the value outputs are valid (Enable TRUE and no error).
    pub valid: bool,
    /// Busy: TRUE while Enable is TRUE and the value is valid.
    pub busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    /// Position: the actual position reported by the drive, in u (modulo axes: in [0, period)); 0
    /// while not Valid.
    pub position: f64,
}

impl McReadActualPosition {
    /// One call (one PLC scan) on `axis`: while Enable is TRUE reads the actual position into
    /// Position.
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
    /// Enable: while TRUE the block works and its outputs are refreshed every call; FALSE resets
    /// the outputs.
    pub enable: bool,
    /// Valid: the value outputs are valid (Enable TRUE and no error).
    pub valid: bool,
    /// Busy: TRUE while Enable is TRUE and the value is valid.
    pub busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    /// Velocity: the actual velocity reported by the drive, in u/s; 0 while not Valid.
    pub velocity: f64,
}

impl McReadActualVelocity {
    /// One call (one PLC scan) on `axis`: while Enable is TRUE reads the actual velocity into
    /// Velocity.
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
    /// ErrorStop: the axis is in ErrorStop (an axis error; leave it with MC_Reset).
    pub error_stop: bool,
    /// Disabled: the axis is not powered.
    pub disabled: bool,
    /// Stopping: MC_Stop brakes or holds the axis (motion commands are refused).
    pub stopping: bool,
    /// Homing: MC_Home is running.
    pub homing: bool,
    /// Standstill: the axis is powered and holds its position with no command.
    pub standstill: bool,
    /// DiscreteMotion: a positioning move or MC_Halt runs (MoveAbsolute/Relative/Additive, Halt).
    pub discrete_motion: bool,
    /// ContinuousMotion: MC_MoveVelocity runs (or the slave runs on after MC_GearOut/MC_CamOut).
    pub continuous_motion: bool,
    /// SynchronizedMotion: the axis is a geared or cammed slave, or moves as part of an axes group.
    pub synchronized_motion: bool,
}

impl McReadStatus {
    /// One call (one PLC scan) on `axis`: while Enable is TRUE sets exactly one of the state
    /// outputs (the axis's PLCopen state).
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
    /// Enable: while TRUE the block works and its outputs are refreshed every call; FALSE resets
    /// the outputs.
    pub enable: bool,
    /// Valid: the value outputs are valid (Enable TRUE and no error).
    pub valid: bool,
    /// Busy: TRUE while Enable is TRUE and AxisErrorID is valid.
    pub busy: bool,
    /// Error: the read itself failed (e.g. an unknown axis); ErrorID says why (the axis error is
    /// AxisErrorID).
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    /// AxisErrorID: the axis error that put the axis into ErrorStop (100 and above, e.g. 102
    /// FollowingError); 0 (None) when there is none.
    pub axis_error_id: ErrorId,
}

impl McReadAxisError {
    /// One call (one PLC scan) on `axis`: while Enable is TRUE reads the axis's error into
    /// AxisErrorID.
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
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Error, ErrorID and CommandAborted.
    pub execute: bool,
    /// ContinuousUpdate: part of the PLCopen interface but not acted on by this block: the ratio is
    /// latched at the rising edge.
    pub continuous_update: bool,
    /// RatioNumerator: numerator of the gear ratio slave/master (finite; negative reverses the
    /// slave).
    pub ratio_numerator: f64,
    /// RatioDenominator: denominator of the gear ratio; finite and non-zero, else ErrorID 28
    /// InvalidRatio.
    pub ratio_denominator: f64,
    /// MasterValueSource: the master value followed: its set value (0, mcSetValue, the default) or
    /// its actual value (1, mcActualValue); another value gives ErrorID 32 InvalidMode.
    pub master_value_source: MasterSource,
    /// Acceleration of the catch-up profile that brings the slave onto ratio * master, u/s² (> 0;
    /// capped by the slave's limits less the master's share).
    pub acceleration: f64,
    /// Deceleration of the catch-up profile, u/s² (> 0).
    pub deceleration: f64,
    /// Jerk of the catch-up profile, u/s³ (>= 0; 0 = the slave's jerk limit).
    pub jerk: f64,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub buffer_mode: BufferMode,
    /// InGear: the slave's catch-up profile ended and it follows ratio * master (on the set value,
    /// while Active).
    pub in_gear: bool,
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

impl McGearIn {
    /// One call (one PLC scan): on a rising Execute couples `slave` to `master` with the gear ratio
    /// (state SynchronizedMotion); InGear once the catch-up ended.
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
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error and ErrorID.
    pub execute: bool,
    /// Done: the slave was decoupled; it runs on at its current velocity (ContinuousMotion).
    pub done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
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
    /// Execute: its rising edge carries out the command within this call; Done or Error then show
    /// while Execute stays TRUE (for one call if it already fell).
    pub execute: bool,
    /// The CAM_REF: index returned by `Engine::add_cam_table`.
    pub cam_table: usize,
    /// Periodic: PLCopen input kept for the interface; the cam's periodicity is MC_CamIn's Periodic
    /// input here.
    pub periodic: bool,
    /// MasterAbsolute: PLCopen input kept for the interface; MC_CamIn's MasterAbsolute input is
    /// used.
    pub master_absolute: bool,
    /// SlaveAbsolute: PLCopen input kept for the interface; MC_CamIn's SlaveAbsolute input is used.
    pub slave_absolute: bool,
    /// Done: the table and both axes exist; CamTableID is valid.
    pub done: bool,
    /// Busy: always FALSE after the call: the command completes within the call.
    pub busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table); 0 (None) while there is no error.
    pub error_id: ErrorId,
    /// CamTableID: the checked table, to be given to MC_CamIn; set when Done.
    pub cam_table_id: usize,
    #[doc(hidden)]
    pub core: ImmediateCore,
}

impl McCamTableSelect {
    /// One call (one PLC scan) for `master` and `slave`: on a rising Execute checks that both axes
    /// and the cam table exist and gives its CamTableID.
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
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Error, ErrorID and CommandAborted.
    pub execute: bool,
    /// ContinuousUpdate: part of the PLCopen interface but not acted on by this block: the inputs
    /// are latched at the rising edge.
    pub continuous_update: bool,
    /// MasterOffset: subtracted from the master position before the table look-up, in u (table x =
    /// (master - MasterOffset) * MasterScaling).
    pub master_offset: f64,
    /// SlaveOffset: added to the table's slave value, in u (slave = SlaveScaling * y +
    /// SlaveOffset).
    pub slave_offset: f64,
    /// MasterScaling: factor on the master position before the table look-up; 0 stands for 1.
    pub master_scaling: f64,
    /// SlaveScaling: factor on the table's slave value; 0 stands for 1.
    pub slave_scaling: f64,
    /// MasterValueSource: the master value followed: its set value (0, mcSetValue, the default) or
    /// its actual value (1, mcActualValue); another value gives ErrorID 32 InvalidMode.
    pub master_value_source: MasterSource,
    /// CamTableID: the table to follow, as returned by MC_CamTableSelect (unknown: ErrorID 3
    /// InvalidCamTable).
    pub cam_table_id: usize,
    /// Periodic: TRUE repeats the table (each period the slave advances by the table's rise and
    /// EndOfProfile pulses); FALSE continues the law beyond the table's master range along its end
    /// tangents (a straight line, so the velocity never steps; end the table flat to dwell).
    pub periodic: bool,
    /// MasterAbsolute: TRUE looks the table up with the master's absolute position; FALSE with the
    /// distance the master travelled since coupling.
    pub master_absolute: bool,
    /// SlaveAbsolute: TRUE the table gives the slave's absolute position; FALSE a position relative
    /// to where the slave was at coupling.
    pub slave_absolute: bool,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub buffer_mode: BufferMode,
    /// InSync: the slave's catch-up profile ended and it follows the cam law (on the set value,
    /// while Active).
    pub in_sync: bool,
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
    /// EndOfProfile: TRUE in the cycle the master passes the end of the table (Periodic: each
    /// period boundary), while Active.
    pub end_of_profile: bool,
    #[doc(hidden)]
    pub core: ExecCore,
}

impl McCamIn {
    /// One call (one PLC scan): on a rising Execute couples `slave` to `master` through the cam
    /// table CamTableID (state SynchronizedMotion); InSync once the catch-up ended.
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
