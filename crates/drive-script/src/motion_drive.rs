//! [`MotionLibDrive`]: the script's [`Drive`] on a motion-lib axis, commanded through PLCopen function blocks.
//!
//! Input: the interpreter's drive commands (moves, jog, homing, settings, outputs) and one [`tick`] per
//! main-loop cycle. Output: the readings the interpreter snapshots, taken with `MC_ReadActualPosition`,
//! `MC_ReadActualVelocity` and `MC_ReadStatus` on a one-axis [`Engine`] with a simulated drive.
//! Invariants:
//! * every motion command is a PLCopen block call made at once (rising Execute, BufferMode Aborting), so a
//!   command that starts motion makes `motion_state()` non-standstill immediately (the engine activates an
//!   Aborting command in the call);
//! * the engine steps exactly once per [`tick`], then every block is called again (falling Execute: the
//!   motion goes on, finished commands are released) and the readings are refreshed;
//! * each block type has two instances used in turn, because a PLCopen block ignores a rising Execute while
//!   Busy: a new command of the same kind takes the free instance and aborts the other one's command;
//! * a refused command (e.g. `Velocity = 0` then a move) leaves the axis as it was and makes `motion_state()`
//!   report `Fault` until the next accepted command; no method panics for any argument;
//! * a positioning command the engine cannot plan from the moving axis's state (`PlanningFailed`) is
//!   deferred, reported as moving, and given again after every engine step (see [`tick`]).
//!
//! Units: the axis unit is one pulse, so positions are pulses, velocities pulses/s, accelerations
//! pulses/s²; the axis config's limits cap the script's settings (the engine uses the smaller value).
//!
//! [`tick`]: MotionLibDrive::tick

use crate::drive::{CycleDrive, Drive, MotionState};
use motion_lib::axis::{AxisConfig, ConfigError};
use motion_lib::blocks::{
    McHalt, McHome, McMoveAbsolute, McMoveAdditive, McMoveRelative, McMoveVelocity, McPower,
    McReadActualPosition, McReadActualVelocity, McReadStatus, McReset, McSetPosition,
};
use motion_lib::buffer::Direction;
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::error::ErrorId;
use motion_lib::fsm::AxisState;
use motion_lib::profile::Limits;

/// The Execute-type blocks the adapter calls, seen uniformly.
trait ExecBlock: Default {
    fn set_execute(&mut self, on: bool);
    fn call_on(&mut self, eng: &mut Engine, axis: usize);
    fn is_busy(&self) -> bool;
    fn failure(&self) -> Option<ErrorId>;
}

macro_rules! exec_block {
    ($($t:ty),*) => {$(
        impl ExecBlock for $t {
            fn set_execute(&mut self, on: bool) {
                self.execute = on;
            }
            fn call_on(&mut self, eng: &mut Engine, axis: usize) {
                self.call(eng, axis);
            }
            fn is_busy(&self) -> bool {
                self.busy
            }
            fn failure(&self) -> Option<ErrorId> {
                self.error.then_some(self.error_id)
            }
        }
    )*};
}

exec_block!(
    McMoveRelative,
    McMoveAdditive,
    McMoveAbsolute,
    McMoveVelocity,
    McHalt,
    McHome
);

/// Two instances of one block type (see the module invariants).
#[derive(Debug, Default, Clone, Copy)]
struct Pair<B>([B; 2]);

impl<B: ExecBlock> Pair<B> {
    /// Calls both instances with Execute FALSE: statuses are tracked, finished commands released.
    fn refresh(&mut self, eng: &mut Engine, axis: usize) {
        for b in &mut self.0 {
            b.set_execute(false);
            b.call_on(eng, axis);
        }
    }

    fn any_busy(&self) -> bool {
        self.0.iter().any(|b| b.is_busy())
    }

    /// A rising Execute on a free instance after `setup` wrote its inputs.
    fn issue(
        &mut self,
        eng: &mut Engine,
        axis: usize,
        setup: impl FnOnce(&mut B),
    ) -> Result<(), ErrorId> {
        // All commands abort their predecessor, so at most one instance is still Busy after a refresh.
        let b = match self.0.iter().position(|b| !b.is_busy()) {
            Some(i) => &mut self.0[i],
            None => return Err(ErrorId::QueueFull),
        };
        setup(b);
        b.set_execute(true);
        b.call_on(eng, axis);
        match b.failure() {
            Some(e) => Err(e),
            None => Ok(()),
        }
    }
}

/// Where a `Homing` command is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum HomingPhase {
    Idle,
    /// Running to the reference mark (method ≠ 0) or halting (method 0 while moving).
    Approach,
    /// `MC_Home` given; Done marks the axis homed.
    Reference,
}

/// A positioning command of the script, kept to be given again (see [`MotionLibDrive::tick`]).
#[derive(Debug, Clone, Copy, PartialEq)]
enum PositionMove {
    /// `MC_MoveRelative` (from the set position).
    Relative(f64),
    /// `MC_MoveAdditive` (from the running target).
    Additive(f64),
    /// `MC_MoveAbsolute`.
    Absolute(f64),
}

/// Default axis limits of the adapter (pulses): well above the script defaults (10 000 p/s,
/// 100 000 p/s²) so that the script's settings decide, with a jerk limit giving 10 ms ramps of the
/// acceleration at 1 000 000 p/s².
pub const DEFAULT_LIMITS: Limits = Limits {
    vmax: 1_000_000.0,
    amax: 10_000_000.0,
    dmax: 10_000_000.0,
    jmax: 100_000_000.0,
};

/// A drive-script [`Drive`] on axis 0 of a motion-lib [`Engine`] (simulated drive: actual = set point).
pub struct MotionLibDrive {
    engine: Engine,
    axis: usize,
    cycle_ms: u32,
    time_ms: u32,
    power: McPower,
    relative: Pair<McMoveRelative>,
    additive: Pair<McMoveAdditive>,
    absolute: Pair<McMoveAbsolute>,
    velocity_fb: Pair<McMoveVelocity>,
    halt: Pair<McHalt>,
    home_fb: Pair<McHome>,
    set_position_fb: McSetPosition,
    reset_fb: McReset,
    read_position: McReadActualPosition,
    read_velocity: McReadActualVelocity,
    read_status: McReadStatus,
    set_acceleration: f64,
    velocity: f64,
    acceleration: f64,
    deceleration: f64,
    jog_velocity: f64,
    homing: HomingPhase,
    homed: bool,
    command_error: Option<ErrorId>,
    /// A positioning command motion-lib could not plan from the moving axis's state, given again each tick.
    deferred: Option<PositionMove>,
    /// Position of the reference mark that homing methods ≠ 0 run to, in the axis's current coordinates
    /// (pulses, default 0). `MC_Home` then makes that point position 0.
    pub reference_mark: f64,
    /// Bit n = `DI_n`; tests and the debugger write it.
    pub inputs: u32,
    outputs: u32,
    /// mA per pulse/s² of set acceleration (motion-lib has no current reading: the simulated motor's
    /// torque constant and inertia together).
    pub current_per_accel: f64,
}

impl std::fmt::Debug for MotionLibDrive {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MotionLibDrive")
            .field("time_ms", &self.time_ms)
            .field("state", &self.axis_state())
            .field("position", &self.read_position.position)
            .field("velocity", &self.read_velocity.velocity)
            .field("homing", &self.homing)
            .field("command_error", &self.command_error)
            .field("deferred", &self.deferred)
            .finish()
    }
}

impl MotionLibDrive {
    /// A powered axis at position 0 with [`DEFAULT_LIMITS`], stepping every `cycle_ms` milliseconds
    /// (0 is taken as 1).
    pub fn new(cycle_ms: u32) -> MotionLibDrive {
        let cfg = AxisConfig {
            limits: DEFAULT_LIMITS,
            ..AxisConfig::default()
        };
        match MotionLibDrive::with_axis(cycle_ms, cfg) {
            Ok(d) => d,
            // DEFAULT_LIMITS and a positive cycle always validate.
            Err(_) => unreachable!("the default axis configuration is valid"),
        }
    }

    /// A powered axis with this configuration (limits in pulses); refused configurations give the
    /// motion library's error (E5001..E5005).
    pub fn with_axis(cycle_ms: u32, cfg: AxisConfig) -> Result<MotionLibDrive, ConfigError> {
        let cycle_ms = cycle_ms.max(1);
        let mut engine = Engine::new(EngineConfig {
            cycle: cycle_ms as f64 / 1000.0,
            ..EngineConfig::default()
        })?;
        let axis = engine.add_axis(cfg)?;
        let mut d = MotionLibDrive {
            engine,
            axis,
            cycle_ms,
            time_ms: 0,
            power: McPower {
                enable: true,
                ..McPower::default()
            },
            relative: Pair::default(),
            additive: Pair::default(),
            absolute: Pair::default(),
            velocity_fb: Pair::default(),
            halt: Pair::default(),
            home_fb: Pair::default(),
            set_position_fb: McSetPosition::default(),
            reset_fb: McReset::default(),
            read_position: McReadActualPosition {
                enable: true,
                ..Default::default()
            },
            read_velocity: McReadActualVelocity {
                enable: true,
                ..Default::default()
            },
            read_status: McReadStatus {
                enable: true,
                ..Default::default()
            },
            set_acceleration: 0.0,
            velocity: 10_000.0,
            acceleration: 100_000.0,
            deceleration: 100_000.0,
            jog_velocity: 5_000.0,
            homing: HomingPhase::Idle,
            homed: false,
            command_error: None,
            deferred: None,
            reference_mark: 0.0,
            inputs: 0,
            outputs: 0,
            current_per_accel: 0.01,
        };
        d.power.call(&mut d.engine, d.axis);
        d.read();
        Ok(d)
    }

    /// The motion engine (read-only: limits, set points, the axis state).
    pub fn engine(&self) -> &Engine {
        &self.engine
    }

    /// The motion engine, mutable: for tests and tools (e.g. `raise_axis_error` to simulate a drive fault).
    /// Commands given here bypass the adapter's blocks; the adapter sees their effect on the axis state.
    pub fn engine_mut(&mut self) -> &mut Engine {
        &mut self.engine
    }

    /// The axis index in [`Self::engine`].
    pub fn axis(&self) -> usize {
        self.axis
    }

    /// The PLCopen state of the axis (from `MC_ReadStatus`, as of the last command or tick).
    pub fn axis_state(&self) -> AxisState {
        let s = &self.read_status;
        if s.error_stop {
            AxisState::ErrorStop
        } else if s.disabled {
            AxisState::Disabled
        } else if s.stopping {
            AxisState::Stopping
        } else if s.homing {
            AxisState::Homing
        } else if s.discrete_motion {
            AxisState::DiscreteMotion
        } else if s.continuous_motion {
            AxisState::ContinuousMotion
        } else if s.synchronized_motion {
            AxisState::SynchronizedMotion
        } else {
            AxisState::Standstill
        }
    }

    /// The error of the last refused command (cleared by the next accepted one).
    pub fn command_error(&self) -> Option<ErrorId> {
        self.command_error
    }

    /// Exact actual position (pulses, `MC_ReadActualPosition`).
    pub fn position(&self) -> f64 {
        self.read_position.position
    }

    /// Exact actual velocity (pulses/s, `MC_ReadActualVelocity`).
    pub fn velocity(&self) -> f64 {
        self.read_velocity.velocity
    }

    /// Advances one main-loop cycle: one engine step, then every block is called and the readings
    /// refreshed; a homing sequence moves on when its phase has finished; a deferred positioning command
    /// is given again.
    ///
    /// Deferred commands: motion-lib's profile kernel finds no solution from a few states at the very end
    /// of a braking ramp (velocity and deceleration both just about to reach 0; the engine answers
    /// `PlanningFailed`). A positioning command refused that way while the axis moves is kept, reported as
    /// moving, and given again after each engine step until it is accepted (at the latest at standstill,
    /// a few cycles later); its target is the same (an additive move still adds to the running target).
    pub fn tick(&mut self) {
        self.time_ms = self.time_ms.wrapping_add(self.cycle_ms);
        self.engine.step();
        self.power.call(&mut self.engine, self.axis);
        self.refresh();
        self.read();
        if let Some(m) = self.deferred.take() {
            let r = self.position_move(m);
            self.outcome(r);
        }
        if self.homing == HomingPhase::Approach {
            match self.axis_state() {
                AxisState::Standstill => {
                    self.homing = HomingPhase::Reference;
                    let r = self
                        .home_fb
                        .issue(&mut self.engine, self.axis, |b| b.position = 0.0);
                    self.outcome(r);
                }
                AxisState::DiscreteMotion => {}
                // Aborted by an axis error or anything unexpected: the sequence ends unhomed.
                _ => self.homing = HomingPhase::Idle,
            }
        }
        self.read();
    }

    /// Calls every Execute-type block with Execute FALSE (tracking and releasing) and notes a finished
    /// homing.
    fn refresh(&mut self) {
        let (e, a) = (&mut self.engine, self.axis);
        self.relative.refresh(e, a);
        self.additive.refresh(e, a);
        self.absolute.refresh(e, a);
        self.velocity_fb.refresh(e, a);
        self.halt.refresh(e, a);
        self.home_fb.refresh(e, a);
        if self.home_fb.0.iter().any(|b| b.done) {
            self.homed = true;
        }
        if self.homing == HomingPhase::Reference && !self.home_fb.any_busy() {
            // Done, failed or aborted.
            self.homing = HomingPhase::Idle;
        }
    }

    /// Calls the read blocks.
    fn read(&mut self) {
        let (e, a) = (&mut self.engine, self.axis);
        self.read_position.call(e, a);
        self.read_velocity.call(e, a);
        self.read_status.call(e, a);
        self.set_acceleration = e.set_acceleration_of(a).unwrap_or(0.0);
    }

    fn outcome(&mut self, r: Result<(), ErrorId>) {
        match r {
            Ok(()) => self.command_error = None,
            Err(e) => {
                self.command_error = Some(e);
                if self.homing != HomingPhase::Idle {
                    self.homing = HomingPhase::Idle;
                }
            }
        }
    }

    /// Common frame of a script command: refresh, cancel a homing sequence and a deferred command, run,
    /// record, read.
    fn command(&mut self, run: impl FnOnce(&mut MotionLibDrive) -> Result<(), ErrorId>) {
        self.refresh();
        self.read();
        self.homing = HomingPhase::Idle;
        self.deferred = None;
        let r = run(self);
        self.outcome(r);
        self.read();
    }

    fn moving(&self) -> bool {
        !matches!(
            self.axis_state(),
            AxisState::Standstill | AxisState::Disabled | AxisState::ErrorStop
        )
    }

    /// `MC_Halt` when the axis moves; nothing at standstill or while `MC_Home` runs (homing on the spot
    /// ends at the next engine step).
    fn halt_now(&mut self) -> Result<(), ErrorId> {
        if !self.moving() || self.axis_state() == AxisState::Homing {
            return Ok(());
        }
        let dec = self.deceleration;
        self.halt
            .issue(&mut self.engine, self.axis, |b| b.deceleration = dec)
    }

    fn move_velocity(&mut self, signed: f64) -> Result<(), ErrorId> {
        if signed == 0.0 {
            return self.halt_now();
        }
        let (acc, dec) = (self.acceleration, self.deceleration);
        self.velocity_fb.issue(&mut self.engine, self.axis, |b| {
            b.velocity = signed.abs();
            b.acceleration = acc;
            b.deceleration = dec;
            b.direction = if signed < 0.0 {
                Direction::Negative
            } else {
                Direction::Positive
            };
        })
    }

    /// A script positioning command at the profile velocity; deferred when it cannot be planned from the
    /// moving axis's state (see [`Self::tick`]).
    fn position_move(&mut self, m: PositionMove) -> Result<(), ErrorId> {
        let (v, acc, dec) = (self.velocity, self.acceleration, self.deceleration);
        let (e, a) = (&mut self.engine, self.axis);
        let r = match m {
            PositionMove::Absolute(target) => self.move_absolute(target, v),
            PositionMove::Relative(distance) => self.relative.issue(e, a, |b| {
                b.distance = distance;
                b.velocity = v;
                b.acceleration = acc;
                b.deceleration = dec;
            }),
            PositionMove::Additive(distance) => self.additive.issue(e, a, |b| {
                b.distance = distance;
                b.velocity = v;
                b.acceleration = acc;
                b.deceleration = dec;
            }),
        };
        if r == Err(ErrorId::PlanningFailed) && self.moving() {
            self.deferred = Some(m);
            return Ok(());
        }
        r
    }

    fn move_absolute(&mut self, target: f64, velocity: f64) -> Result<(), ErrorId> {
        let (acc, dec) = (self.acceleration, self.deceleration);
        self.absolute.issue(&mut self.engine, self.axis, |b| {
            b.position = target;
            b.velocity = velocity;
            b.acceleration = acc;
            b.deceleration = dec;
            b.direction = Direction::Shortest;
        })
    }
}

fn to_i32(x: f64) -> i32 {
    if x.is_nan() {
        return 0;
    }
    x.round().clamp(i32::MIN as f64, i32::MAX as f64) as i32
}

impl Drive for MotionLibDrive {
    fn actual_position(&self) -> i32 {
        to_i32(self.read_position.position)
    }
    fn actual_velocity(&self) -> i32 {
        to_i32(self.read_velocity.velocity)
    }
    fn actual_current(&self) -> i32 {
        to_i32(self.set_acceleration * self.current_per_accel)
    }
    fn digital_inputs(&self) -> u32 {
        self.inputs
    }
    fn digital_outputs(&self) -> u32 {
        self.outputs
    }
    fn set_digital_output(&mut self, index: u8, high: bool) {
        if index < 32 {
            if high {
                self.outputs |= 1 << index;
            } else {
                self.outputs &= !(1 << index);
            }
        }
    }
    fn motion_state(&self) -> MotionState {
        if self.command_error.is_some() {
            return MotionState::Fault;
        }
        match self.axis_state() {
            AxisState::ErrorStop | AxisState::Disabled => MotionState::Fault,
            _ if self.homing != HomingPhase::Idle => MotionState::Homing,
            _ if self.deferred.is_some() => MotionState::Moving,
            AxisState::Homing => MotionState::Homing,
            AxisState::Standstill => MotionState::Standstill,
            _ => MotionState::Moving,
        }
    }
    fn homed(&self) -> bool {
        self.homed
    }
    fn now_ms(&self) -> u32 {
        self.time_ms
    }
    fn set_velocity(&mut self, v: i32) {
        self.velocity = (v as f64).abs();
    }
    fn set_acceleration(&mut self, a: i32) {
        self.acceleration = (a as f64).abs();
    }
    fn set_deceleration(&mut self, d: i32) {
        self.deceleration = (d as f64).abs();
    }
    fn set_jog_velocity(&mut self, v: i32) {
        self.jog_velocity = (v as f64).abs();
    }
    fn set_position(&mut self, p: i32) {
        self.command(|d| {
            d.set_position_fb.execute = false;
            d.set_position_fb.call(&mut d.engine, d.axis);
            d.set_position_fb.position = p as f64;
            d.set_position_fb.relative = false;
            d.set_position_fb.execute = true;
            d.set_position_fb.call(&mut d.engine, d.axis);
            match d.set_position_fb.error {
                true => Err(d.set_position_fb.error_id),
                false => Ok(()),
            }
        });
    }
    fn velocity_move(&mut self, v: i32) {
        self.command(|d| d.move_velocity(v as f64));
    }
    fn relative_move(&mut self, distance: i32) {
        // From the running target when a positioning move is active (MC_MoveAdditive), else from the
        // set position (MC_MoveRelative).
        let was_homing = self.homing != HomingPhase::Idle;
        self.command(|d| {
            // Block statuses are fresh here (`command` refreshed them).
            let running_move = !was_homing
                && d.axis_state() == AxisState::DiscreteMotion
                && (d.relative.any_busy() || d.additive.any_busy() || d.absolute.any_busy());
            let distance = distance as f64;
            d.position_move(if running_move {
                PositionMove::Additive(distance)
            } else {
                PositionMove::Relative(distance)
            })
        });
    }
    fn absolute_move(&mut self, target: i32) {
        self.command(|d| d.position_move(PositionMove::Absolute(target as f64)));
    }
    fn jog(&mut self, direction: i32) {
        self.command(|d| d.move_velocity(direction.signum() as f64 * d.jog_velocity));
    }
    fn home(&mut self, method: i32) {
        self.command(|d| {
            d.homed = false;
            if method != 0 {
                let (mark, v) = (d.reference_mark, d.jog_velocity);
                d.move_absolute(mark, v)?;
                d.homing = HomingPhase::Approach;
            } else if d.moving() {
                d.halt_now()?;
                d.homing = HomingPhase::Approach;
            } else {
                d.home_fb
                    .issue(&mut d.engine, d.axis, |b| b.position = 0.0)?;
                d.homing = HomingPhase::Reference;
            }
            Ok(())
        });
    }
    fn stop(&mut self) {
        self.command(|d| {
            if d.axis_state() == AxisState::ErrorStop {
                // Stop acknowledges an axis error.
                d.reset_fb.execute = false;
                d.reset_fb.call(&mut d.engine, d.axis);
                d.reset_fb.execute = true;
                d.reset_fb.call(&mut d.engine, d.axis);
                return match d.reset_fb.error {
                    true => Err(d.reset_fb.error_id),
                    false => Ok(()),
                };
            }
            d.halt_now()
        });
    }
}

impl CycleDrive for MotionLibDrive {
    fn tick(&mut self) {
        MotionLibDrive::tick(self);
    }
    fn set_inputs(&mut self, bits: u32) {
        self.inputs = bits;
    }
}
