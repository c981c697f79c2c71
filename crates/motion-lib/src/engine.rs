//! The interpolation engine: axes, their command buffers and the fixed-cycle step.
//!
//! Input: axis configurations (at setup), commands from the blocks (between cycles) and
//! [`Engine::step`] once per cycle. Output: per axis a set point (position, velocity,
//! acceleration) each cycle, the PLCopen state, and the status of every command.
//! Invariants: deterministic (same calls, same set points); `step` allocates nothing
//! (flat arrays sized at setup; queues reserved at their depth); an axis error always
//! ends in ErrorStop with every buffered command failed and the queue empty.

use crate::axis::{AxisConfig, AxisKind, ConfigError, Drive, HomingStatus};
use crate::buffer::{BufferMode, Direction, Queue};
use crate::cmd::{CmdId, CmdStatus, CmdTable};
use crate::error::ErrorId;
use crate::fsm::{check_axis, AxisCmd, AxisState, GroupState};
use crate::group::GroupRt;
use crate::profile::{Limits, Profile, State};
use crate::sync::{CamTable, SyncParams};

/// Engine settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EngineConfig {
    /// Cycle time in seconds (default 1 ms).
    pub cycle: f64,
    /// Commands each axis and each group can buffer besides the active one.
    pub queue_depth: usize,
}

impl Default for EngineConfig {
    fn default() -> Self {
        EngineConfig {
            cycle: 0.001,
            queue_depth: 8,
        }
    }
}

/// Dynamics inputs of a move (PLCopen Velocity, Acceleration, Deceleration, Jerk).
/// Jerk 0 means "the axis's jerk limit".
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Dynamics {
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
}

/// Source of a master's value for gearing and camming.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum MasterSource {
    #[default]
    /// mcSetValue (0): the master's set point of this cycle (its successor starting within the
    /// cycle included).
    SetValue,
    /// mcActualValue (1): the master's actual position and velocity as its drive reports them.
    ActualValue,
}

/// A single-axis command.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AxisCommand {
    /// MC_MoveAbsolute: to `position` (u); on a modulo axis the way `direction` says.
    MoveAbsolute {
        /// Target position, u.
        position: f64,
        /// Way round a modulo axis (ignored on a linear axis).
        direction: Direction,
    },
    /// MC_MoveRelative: `distance` added to the set position when the command becomes active.
    MoveRelative {
        /// Distance, u (signed).
        distance: f64,
    },
    /// MC_MoveAdditive: `distance` added to the last commanded target.
    MoveAdditive {
        /// Distance, u (signed).
        distance: f64,
    },
    /// `dynamics.velocity` is the speed; the sign comes from `direction` (a negative
    /// velocity reverses it).
    MoveVelocity {
        /// Positive, Negative or Current (Shortest is refused with ErrorID 25).
        direction: Direction,
    },
    /// MC_Halt: brake to standstill with the given deceleration and jerk (DiscreteMotion, then
    /// Standstill).
    Halt,
    /// MC_Stop: abort everything and brake (Stopping; held until the block releases it).
    Stop,
    /// MC_Home: run the drive's homing (Homing); the set position becomes `position`.
    Home {
        /// Position after homing, u.
        position: f64,
    },
    /// MC_GearIn: follow `master` at numerator/denominator after a catch-up profile.
    GearIn {
        /// Index of the master axis.
        master: usize,
        /// Ratio numerator (slave/master).
        numerator: f64,
        /// Ratio denominator (non-zero; else ErrorID 28).
        denominator: f64,
        /// Set or actual value of the master.
        source: MasterSource,
    },
    /// MC_GearOut: decouple; the slave keeps its current velocity (ContinuousMotion).
    GearOut,
    /// MC_CamIn: follow `master` through a cam table after a catch-up profile.
    CamIn {
        /// Index of the master axis.
        master: usize,
        /// The cam law: table, offsets, scalings, periodic/absolute flags.
        params: SyncParams,
    },
    /// MC_CamOut: decouple; the slave keeps its current velocity (ContinuousMotion).
    CamOut,
}

impl AxisCommand {
    fn class(&self) -> AxisCmd {
        match self {
            AxisCommand::MoveAbsolute { .. }
            | AxisCommand::MoveRelative { .. }
            | AxisCommand::MoveAdditive { .. }
            | AxisCommand::Halt => AxisCmd::Discrete,
            AxisCommand::MoveVelocity { .. } => AxisCmd::Continuous,
            AxisCommand::Stop => AxisCmd::Stop,
            AxisCommand::Home { .. } => AxisCmd::Home,
            AxisCommand::GearIn { .. } | AxisCommand::CamIn { .. } => AxisCmd::Synchronized,
            AxisCommand::GearOut | AxisCommand::CamOut => AxisCmd::SyncOut,
        }
    }
}

/// What the axis is doing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub(crate) enum Kind {
    #[default]
    Idle,
    Position,
    Velocity,
    Halt,
    Stop,
    Home,
    Gear,
    Cam,
    /// Set point written by the axis's group.
    Group,
    /// Error braking (no command).
    Brake,
}

/// A resolved command waiting in an axis queue (or running).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Pending {
    pub id: CmdId,
    pub kind: Kind,
    /// Raw target position (Position), signed velocity (Velocity), home position (Home).
    pub target: f64,
    /// Commanded speed magnitude (for blending).
    pub speed: f64,
    pub lim: Limits,
    pub buffer: BufferMode,
    /// Signed velocity at the end of the move (set by a blending successor).
    pub end_v: f64,
    pub sync: SyncParams,
    /// MC_MoveRelative: the distance, counted from the set position when the command
    /// becomes active (`target` holds the prediction from the predecessor's target).
    pub relative: Option<f64>,
}

/// The running motion of an axis. `repr(C)`: the fields read every cycle come first,
/// next to the profile's sampling cursor (see [`AxisRt`]).
#[derive(Clone, Copy, Debug)]
#[repr(C)]
pub(crate) struct Active {
    pub kind: Kind,
    /// VelFactor 0: the move brakes to standstill on its way and waits for a factor > 0.
    pub paused: bool,
    /// Release given (InVelocity / InGear / InSync reached).
    pub released: bool,
    pub t: f64,
    pub prof: Profile,
    pub id: Option<CmdId>,
    pub target: f64,
    pub speed: f64,
    /// Limits the profile was planned with (the command's limits scaled by the
    /// AccFactor and JerkFactor override).
    pub lim: Limits,
    /// The command's own limits (before the override).
    pub base: Limits,
    pub end_v: f64,
    pub sync: SyncParams,
    /// Velocity-change tail run after `prof` (see [`plan_to`]).
    pub tail: Option<Profile>,
    /// A velocity move braked to stop at a software limit: the error raised when it stands.
    pub limit_stop: Option<ErrorId>,
}

impl Active {
    pub(crate) fn idle(at: State) -> Active {
        Active {
            kind: Kind::Idle,
            id: None,
            prof: standing(at.p),
            t: 0.0,
            target: at.p,
            speed: 0.0,
            lim: UNIT,
            base: UNIT,
            paused: false,
            released: true,
            end_v: 0.0,
            sync: SyncParams::default(),
            tail: None,
            limit_stop: None,
        }
    }
}

/// Profile::position, standing still when the start already is the target.
pub(crate) fn plan_position(
    start: State,
    target: f64,
    end_v: f64,
    lim: &Limits,
) -> Result<Profile, crate::profile::PlanError> {
    if start.p == target && start.v == end_v && start.a == 0.0 && end_v == 0.0 {
        return Ok(standing(target));
    }
    Profile::position(start, target, end_v, lim)
}

/// A positioning plan ending at `end_v`: when |end_v| exceeds the move's velocity limit
/// (BlendingNext/High towards a faster successor) the move cruises at its own limit and
/// a velocity-change tail at the end reaches `end_v` exactly at `target`.
pub(crate) fn plan_to(
    start: State,
    target: f64,
    end_v: f64,
    lim: &Limits,
) -> Result<(Profile, Option<Profile>), crate::profile::PlanError> {
    if end_v.abs() <= lim.vmax {
        return plan_position(start, target, end_v, lim).map(|p| (p, None));
    }
    let mut fast = *lim;
    fast.vmax = end_v.abs();
    let cruise = lim.vmax * end_v.signum();
    let probe = Profile::velocity(
        State {
            p: 0.0,
            v: cruise,
            a: 0.0,
        },
        end_v,
        &fast,
    )?;
    let d_tail = probe.end().p;
    let split = target - d_tail;
    // Room for the tail in the direction of travel: else one profile with the raised limit.
    if (split - start.p) * end_v.signum() > 0.0 {
        if let Ok(main) = Profile::position(start, split, cruise, lim) {
            let tail = Profile::velocity(
                State {
                    p: split,
                    v: cruise,
                    a: 0.0,
                },
                end_v,
                &fast,
            )?;
            return Ok((main, Some(tail)));
        }
    }
    Profile::position(start, target, end_v, &fast).map(|p| (p, None))
}

/// A move planned under the override.
pub(crate) struct Overridden {
    pub prof: Profile,
    pub tail: Option<Profile>,
    pub lim: Limits,
    pub paused: bool,
}

/// Plans a Position, Velocity or Halt move (`base` its own limits, `target` its raw
/// target or signed velocity, `end_v` its end velocity) from `now` under the axis's
/// override: velocity limit * VelFactor (at most the axis's limit), acceleration and
/// deceleration * AccFactor, jerk * JerkFactor (0 = unlimited stays 0). VelFactor 0
/// brakes a Position or Velocity move to standstill (`paused`).
pub(crate) fn overridden(
    ax: &AxisRt,
    kind: Kind,
    base: &Limits,
    now: State,
    target: f64,
    end_v: f64,
) -> Result<Overridden, ErrorId> {
    let mut lim = Limits {
        vmax: base.vmax,
        amax: base.amax * ax.acc_factor,
        dmax: base.dmax * ax.acc_factor,
        jmax: base.jmax * ax.jerk_factor,
    };
    // A move that starts while the axis accelerates: with the block's (lower) jerk the
    // velocity would pass the axis's limit before the acceleration is gone. The block's
    // jerk is then raised to the axis's own (the limits are physics, the block's a wish).
    let al = ax.cfg.limits;
    if lim.jmax > 0.0 && (al.jmax == 0.0 || al.jmax > lim.jmax) {
        let peak = (now.v + now.a * now.a.abs() / (2.0 * lim.jmax)).abs();
        if peak > al.vmax {
            lim.jmax = al.jmax;
        }
    }
    let paused = ax.vel_factor == 0.0 && kind != Kind::Halt;
    if !paused && kind != Kind::Halt {
        lim.vmax = (base.vmax * ax.vel_factor).min(base.vmax.max(ax.cfg.limits.vmax));
    }
    let planned = if paused || kind == Kind::Halt {
        Profile::velocity(now, 0.0, &lim).map(|p| (p, None))
    } else if kind == Kind::Position {
        plan_to(now, target, end_v, &lim)
    } else {
        let v = (target * ax.vel_factor).clamp(-lim.vmax, lim.vmax);
        Profile::velocity(now, v, &lim).map(|p| (p, None))
    };
    let (prof, tail) = planned.map_err(|_| ErrorId::PlanningFailed)?;
    Ok(Overridden {
        prof,
        tail,
        lim,
        paused,
    })
}

/// A zero-length profile standing at `p`.
pub(crate) fn standing(p: f64) -> Profile {
    let at = State { p, v: 0.0, a: 0.0 };
    match Profile::velocity(at, 0.0, &UNIT) {
        Ok(prof) => prof,
        // Only a non-finite position fails: stand at 0 instead.
        Err(_) => {
            Profile::velocity(State::default(), 0.0, &UNIT).unwrap_or_else(|_| unreachable!())
        }
    }
}

/// Lowest and highest position a profile (and its tail) passes: its phase boundaries and
/// the instants within a phase where the velocity is 0.
pub(crate) fn position_range(prof: &Profile, tail: Option<&Profile>) -> (f64, f64) {
    let mut lo = prof.start().p.min(prof.end().p);
    let mut hi = prof.start().p.max(prof.end().p);
    for pr in std::iter::once(prof).chain(tail) {
        for (st, ph) in pr.phase_starts().iter().zip(pr.phases()) {
            let mut see = |t: f64| {
                if t >= 0.0 && t <= ph.duration {
                    let p = st.integrate(t, ph.jerk).p;
                    lo = lo.min(p);
                    hi = hi.max(p);
                }
            };
            see(0.0);
            see(ph.duration);
            // v + a t + j t^2 / 2 = 0
            let (a2, b, c) = (ph.jerk / 2.0, st.a, st.v);
            if a2.abs() > 1e-300 {
                let disc = b * b - 4.0 * a2 * c;
                if disc >= 0.0 {
                    let r = disc.sqrt();
                    see((-b + r) / (2.0 * a2));
                    see((-b - r) / (2.0 * a2));
                }
            } else if b.abs() > 1e-300 {
                see(-c / b);
            }
        }
        lo = lo.min(pr.end().p);
        hi = hi.max(pr.end().p);
    }
    (lo, hi)
}

const UNIT: Limits = Limits {
    vmax: 1.0,
    amax: 1.0,
    dmax: 1.0,
    jmax: 0.0,
};

/// Runtime of one axis (flat, no heap). `repr(C)`, hot fields first: a moving axis's
/// cycle (`Engine::step`) reads and writes `set`, `act_p`, `act_v`, `has_drive`, the
/// start of `active` (kind, flags, time, the profile's cursor and duration) and `cfg`'s
/// software-limit switch, a few adjacent cache lines of this large record.
#[derive(Clone, Debug)]
#[repr(C)]
pub(crate) struct AxisRt {
    /// Set point in raw (unwrapped) units.
    pub set: State,
    pub act_p: f64,
    pub act_v: f64,
    pub has_drive: bool,
    pub state: AxisState,
    pub active: Active,
    pub cfg: AxisConfig,
    /// User position = raw + origin (then wrapped on modulo axes).
    pub origin: f64,
    pub power_req: bool,
    pub powered: bool,
    pub axis_error: ErrorId,
    pub drive_code: u16,
    /// MC_SetOverride VelFactor (>= 0).
    pub vel_factor: f64,
    /// MC_SetOverride AccFactor (acceleration and deceleration) and JerkFactor, (0, 1].
    pub acc_factor: f64,
    pub jerk_factor: f64,
    pub group: Option<u16>,
    pub stop_owner: Option<CmdId>,
}

/// The motion engine.
pub struct Engine {
    pub(crate) cfg: EngineConfig,
    pub(crate) axes: Vec<AxisRt>,
    pub(crate) drives: Vec<Option<Box<dyn Drive>>>,
    pub(crate) queues: Vec<Queue<Pending>>,
    pub(crate) groups: Vec<GroupRt>,
    pub(crate) cmds: CmdTable,
    pub(crate) cams: Vec<CamTable>,
    pub(crate) events: Vec<u32>,
    pub(crate) synced: Vec<u32>,
    pub(crate) cycles: u64,
    /// Per axis: MC_Stop inputs capped to the axis limits (README "MC_Stop").
    pub(crate) stop_caps: Vec<StopCaps>,
}

/// An MC_Stop whose Deceleration or Jerk exceeded the axis's limit and was capped to it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StopReduction {
    /// The MC_Stop command.
    pub cmd: CmdId,
    /// The Deceleration input the block asked for (u/s²).
    pub deceleration_requested: f64,
    /// The deceleration the stop runs with: the request capped to the axis's limit (u/s²).
    pub deceleration_reached: f64,
    /// The Jerk input the block asked for (u/s³; 0 = the axis's jerk limit).
    pub jerk_requested: f64,
    /// The jerk the stop runs with (u/s³; equal to the request when only the deceleration was capped).
    pub jerk_reached: f64,
}

/// The capped stops of one axis: the first [`crate::group::REDUCTIONS_KEPT`] kept, all
/// counted, and the engine cycle of the last one.
#[derive(Clone, Debug, Default)]
pub(crate) struct StopCaps {
    kept: Vec<StopReduction>,
    count: usize,
    /// The last capped stop and `Engine::cycles` when it was given (its first cycle is the
    /// next).
    last: Option<(u64, StopReduction)>,
}

fn finite(x: f64) -> bool {
    x.is_finite()
}

impl Engine {
    /// An engine with no axes.
    pub fn new(cfg: EngineConfig) -> Result<Engine, ConfigError> {
        if !(cfg.cycle.is_finite() && cfg.cycle > 0.0) {
            return Err(ConfigError::InvalidEngineConfig);
        }
        Ok(Engine {
            cfg,
            axes: Vec::new(),
            drives: Vec::new(),
            queues: Vec::new(),
            groups: Vec::new(),
            cmds: CmdTable::with_capacity(64),
            cams: Vec::new(),
            events: Vec::new(),
            synced: Vec::new(),
            cycles: 0,
            stop_caps: Vec::new(),
        })
    }

    /// The engine's configuration.
    pub fn config(&self) -> &EngineConfig {
        &self.cfg
    }

    /// Adds an axis with a simulated drive; returns its index.
    pub fn add_axis(&mut self, cfg: AxisConfig) -> Result<usize, ConfigError> {
        cfg.validate()?;
        self.axes.push(AxisRt {
            cfg,
            state: AxisState::Disabled,
            set: State::default(),
            act_p: 0.0,
            act_v: 0.0,
            origin: 0.0,
            power_req: false,
            powered: false,
            axis_error: ErrorId::None,
            drive_code: 0,
            vel_factor: 1.0,
            acc_factor: 1.0,
            jerk_factor: 1.0,
            group: None,
            stop_owner: None,
            active: Active::idle(State::default()),
            has_drive: false,
        });
        self.drives.push(None);
        self.queues.push(Queue::new(self.cfg.queue_depth));
        self.stop_caps.push(StopCaps::default());
        let n = self.axes.len();
        self.events.reserve(3 * n);
        self.synced.reserve(n);
        Ok(self.axes.len() - 1)
    }

    /// Adds an axis driven by a real drive.
    pub fn add_axis_with_drive(
        &mut self,
        cfg: AxisConfig,
        drive: Box<dyn Drive>,
    ) -> Result<usize, ConfigError> {
        let i = self.add_axis(cfg)?;
        let p = drive.actual_position();
        self.axes[i].set.p = p;
        self.axes[i].act_p = p;
        self.axes[i].has_drive = true;
        self.drives[i] = Some(drive);
        Ok(i)
    }

    /// Replaces an axis's configuration (allowed while Disabled or Standstill).
    pub fn configure_axis(&mut self, axis: usize, cfg: AxisConfig) -> Result<(), ErrorId> {
        cfg.validate().map_err(|_| ErrorId::InvalidMode)?;
        let ax = self.axes.get_mut(axis).ok_or(ErrorId::InvalidAxis)?;
        if !matches!(ax.state, AxisState::Disabled | AxisState::Standstill) {
            return Err(ErrorId::NotStandstill);
        }
        ax.cfg = cfg;
        Ok(())
    }

    /// Number of axes.
    pub fn axis_count(&self) -> usize {
        self.axes.len()
    }

    /// Cycles stepped so far.
    pub fn cycles(&self) -> u64 {
        self.cycles
    }

    /// Engine time in seconds (cycles * cycle time).
    pub fn time(&self) -> f64 {
        self.cycles as f64 * self.cfg.cycle
    }

    pub(crate) fn axis(&self, axis: usize) -> Result<&AxisRt, ErrorId> {
        self.axes.get(axis).ok_or(ErrorId::InvalidAxis)
    }

    // ------------------------------------------------------------------ reads

    /// PLCopen state of the axis.
    pub fn axis_state(&self, axis: usize) -> Result<AxisState, ErrorId> {
        Ok(self.axis(axis)?.state)
    }

    fn to_user(ax: &AxisRt, raw: f64) -> f64 {
        let p = raw + ax.origin;
        match ax.cfg.kind {
            AxisKind::Linear => p,
            AxisKind::Modulo { period } => p.rem_euclid(period),
        }
    }

    /// Set position in user units (wrapped on modulo axes).
    pub fn set_position_of(&self, axis: usize) -> Result<f64, ErrorId> {
        let ax = self.axis(axis)?;
        Ok(Self::to_user(ax, ax.set.p))
    }

    /// Set velocity (includes the override).
    pub fn set_velocity_of(&self, axis: usize) -> Result<f64, ErrorId> {
        Ok(self.axis(axis)?.set.v)
    }

    /// Set acceleration.
    pub fn set_acceleration_of(&self, axis: usize) -> Result<f64, ErrorId> {
        Ok(self.axis(axis)?.set.a)
    }

    /// Actual position in user units.
    pub fn actual_position(&self, axis: usize) -> Result<f64, ErrorId> {
        let ax = self.axis(axis)?;
        Ok(Self::to_user(ax, ax.act_p))
    }

    /// Actual velocity.
    pub fn actual_velocity(&self, axis: usize) -> Result<f64, ErrorId> {
        Ok(self.axis(axis)?.act_v)
    }

    /// The axis error (AxisErrorID), `ErrorId::None` when the axis has none.
    pub fn axis_error(&self, axis: usize) -> Result<ErrorId, ErrorId> {
        Ok(self.axis(axis)?.axis_error)
    }

    /// The drive's own fault code of the last drive fault.
    pub fn drive_fault_code(&self, axis: usize) -> Result<u16, ErrorId> {
        Ok(self.axis(axis)?.drive_code)
    }

    /// MC_Power.Status: the drive is enabled.
    pub fn power_status(&self, axis: usize) -> Result<bool, ErrorId> {
        Ok(self.axis(axis)?.powered)
    }

    /// Number of commands waiting in the axis's buffer (not counting the active one).
    pub fn queued(&self, axis: usize) -> Result<usize, ErrorId> {
        self.axis(axis)?;
        Ok(self.queues[axis].len())
    }

    /// Group the axis belongs to.
    pub fn group_of(&self, axis: usize) -> Result<Option<usize>, ErrorId> {
        Ok(self.axis(axis)?.group.map(usize::from))
    }

    // --------------------------------------------------------------- commands

    /// Status of a command.
    pub fn status(&self, id: CmdId) -> CmdStatus {
        self.cmds.status(id)
    }

    /// InVelocity / InGear / InSync of a command (on the set value).
    pub fn in_target(&self, id: CmdId) -> bool {
        self.cmds.in_target(id)
    }

    /// EndOfProfile of a CamIn command.
    pub fn end_of_profile(&self, id: CmdId) -> bool {
        self.cmds.end_of_profile(id)
    }

    /// Forgets a finished command (its block has read the final status).
    pub fn release(&mut self, id: CmdId) {
        if self.cmds.status(id).is_final() {
            self.cmds.release(id);
        }
    }

    /// MC_Stop's Execute fell after Done: the axis leaves Stopping for Standstill.
    pub fn release_stop(&mut self, axis: usize, id: CmdId) {
        if let Some(ax) = self.axes.get_mut(axis) {
            if ax.stop_owner == Some(id) && ax.active.kind != Kind::Stop {
                ax.stop_owner = None;
                if ax.state == AxisState::Stopping {
                    ax.state = AxisState::Standstill;
                }
            }
        }
    }

    /// MC_Power: switches the drive on or off. Returns MC_Power.Status.
    pub fn power(&mut self, axis: usize, enable: bool) -> Result<bool, ErrorId> {
        self.axis(axis)?;
        let ax = &mut self.axes[axis];
        if enable == ax.power_req {
            self.poll_power(axis);
            return Ok(self.axes[axis].powered);
        }
        ax.power_req = enable;
        if let Some(d) = self.drives[axis].as_mut() {
            d.set_enable(enable);
        }
        if !enable {
            self.abort_all(axis, CmdStatus::Aborted);
            let ax = &mut self.axes[axis];
            ax.powered = false;
            ax.set.v = 0.0;
            ax.set.a = 0.0;
            ax.set.p = ax.act_p;
            ax.active = Active::idle(ax.set);
            ax.stop_owner = None;
            if ax.state != AxisState::ErrorStop {
                ax.state = AxisState::Disabled;
            }
            if let Some(g) = ax.group {
                self.group_axis_fault(g as usize);
            }
        }
        self.poll_power(axis);
        Ok(self.axes[axis].powered)
    }

    /// Reads the drive's enable feedback; Disabled -> Standstill once enabled.
    fn poll_power(&mut self, axis: usize) {
        let ax = &mut self.axes[axis];
        if ax.power_req {
            let en = match self.drives[axis].as_ref() {
                Some(d) => d.enabled(),
                None => true,
            };
            if en && !ax.powered {
                ax.powered = true;
                ax.set = State {
                    p: ax.act_p,
                    v: 0.0,
                    a: 0.0,
                };
                ax.active = Active::idle(ax.set);
            }
            if en && ax.state == AxisState::Disabled {
                ax.state = AxisState::Standstill;
            }
        }
    }

    /// MC_Reset: ErrorStop -> Standstill (powered) or Disabled. In other states nothing
    /// happens (Done).
    pub fn reset(&mut self, axis: usize) -> Result<(), ErrorId> {
        self.axis(axis)?;
        if self.axes[axis].state != AxisState::ErrorStop {
            return Ok(());
        }
        if self.axes[axis].active.kind == Kind::Brake
            || (self.axes[axis].active.kind == Kind::Group)
        {
            return Err(ErrorId::AxisStillMoving);
        }
        if let Some(d) = self.drives[axis].as_mut() {
            d.reset_fault();
            if d.fault().is_some() {
                return Err(ErrorId::DriveFaultActive);
            }
        }
        let ax = &mut self.axes[axis];
        ax.axis_error = ErrorId::None;
        ax.drive_code = 0;
        ax.state = if ax.powered {
            AxisState::Standstill
        } else {
            AxisState::Disabled
        };
        Ok(())
    }

    /// Puts the axis into ErrorStop with `error` (AxisErrorID): the active and every
    /// buffered command fail with that error, the queue is cleared and the axis brakes
    /// with its own deceleration and jerk limits.
    pub fn raise_axis_error(&mut self, axis: usize, error: ErrorId) -> Result<(), ErrorId> {
        self.axis(axis)?;
        if self.axes[axis].state == AxisState::ErrorStop {
            return Ok(());
        }
        self.abort_all(axis, CmdStatus::Error(error));
        let ax = &mut self.axes[axis];
        ax.state = AxisState::ErrorStop;
        ax.axis_error = error;
        ax.stop_owner = None;
        if ax.active.kind == Kind::Group {
            // The group brakes along its path (it drives this axis's set point).
            let g = ax.group.map(usize::from);
            if let Some(g) = g {
                self.group_axis_fault(g);
            }
            return Ok(());
        }
        if ax.powered {
            let lim = ax.cfg.limits;
            let start = ax.set;
            ax.active = Active::idle(start);
            if start.v == 0.0 && start.a == 0.0 {
                // At rest already (a velocity move stopped at a limit): nothing to brake.
                return Ok(());
            }
            if let Ok(p) = Profile::velocity(start, 0.0, &lim) {
                ax.active.prof = p;
                ax.active.kind = Kind::Brake;
                ax.active.released = false;
            }
        }
        Ok(())
    }

    /// Aborts the active and every queued command of the axis with `status`.
    fn abort_all(&mut self, axis: usize, status: CmdStatus) {
        let ax = &mut self.axes[axis];
        if let Some(id) = ax.active.id.take() {
            self.cmds.set(id, status);
            self.cmds.set_in_target(id, false);
        }
        let cmds = &mut self.cmds;
        self.queues[axis].drain_with(|p| cmds.set(p.id, status));
    }

    /// MC_SetPosition: shifts the axis coordinate so that the set position becomes
    /// `position` (or moves by `position` when `relative`). Motion continues unchanged.
    pub fn set_position(
        &mut self,
        axis: usize,
        position: f64,
        relative: bool,
    ) -> Result<(), ErrorId> {
        self.axis(axis)?;
        if !finite(position) {
            return Err(ErrorId::InvalidPosition);
        }
        let ax = &mut self.axes[axis];
        if matches!(ax.state, AxisState::Homing | AxisState::ErrorStop) {
            return Err(check_state_err(ax.state));
        }
        if relative {
            ax.origin += position;
        } else {
            ax.origin = position - ax.set.p;
        }
        Ok(())
    }

    /// MC_SetOverride with VelFactor only (AccFactor and JerkFactor unchanged); see
    /// [`Engine::set_override_factors`].
    pub fn set_override(&mut self, axis: usize, factor: f64) -> Result<(), ErrorId> {
        let ax = self.axis(axis)?;
        let (acc, jerk) = (ax.acc_factor, ax.jerk_factor);
        self.set_override_factors(axis, factor, acc, jerk)
    }

    /// MC_SetOverride with all three factors: VelFactor (>= 0) scales the velocity limit
    /// (capped by the axis's limit; 0 brakes the move to standstill on its way, where it
    /// waits), AccFactor the acceleration and deceleration limits, JerkFactor the jerk
    /// limit of the running and of every later positioning, velocity and halt move (not
    /// MC_Stop, error braking, gearing, camming or group moves). AccFactor and JerkFactor
    /// must be in (0, 1]; 0 stands for 1 (the value of a zero-initialised block). A
    /// change re-plans the running move from its current position, velocity and
    /// acceleration, so the set point stays continuous and within the limits in force.
    pub fn set_override_factors(
        &mut self,
        axis: usize,
        vel: f64,
        acc: f64,
        jerk: f64,
    ) -> Result<(), ErrorId> {
        self.axis(axis)?;
        let factor = |f: f64| -> Result<f64, ErrorId> {
            if f == 0.0 {
                Ok(1.0)
            } else if finite(f) && f > 0.0 && f <= 1.0 {
                Ok(f)
            } else {
                Err(ErrorId::InvalidOverride)
            }
        };
        let (acc, jerk) = (factor(acc)?, factor(jerk)?);
        if !(finite(vel) && vel >= 0.0) {
            return Err(ErrorId::InvalidOverride);
        }
        let ax = &mut self.axes[axis];
        if ax.vel_factor != vel || ax.acc_factor != acc || ax.jerk_factor != jerk {
            ax.vel_factor = vel;
            ax.acc_factor = acc;
            ax.jerk_factor = jerk;
            self.replan_override(axis);
        }
        Ok(())
    }

    /// The override factors in effect: (VelFactor, AccFactor, JerkFactor).
    pub fn override_factors(&self, axis: usize) -> Result<(f64, f64, f64), ErrorId> {
        let ax = self.axis(axis)?;
        Ok((ax.vel_factor, ax.acc_factor, ax.jerk_factor))
    }

    /// Re-plans the running move under the new override from its current state. A
    /// MoveVelocity that was InVelocity drops it until it reaches a new velocity (an
    /// AccFactor or JerkFactor change alone keeps it).
    fn replan_override(&mut self, axis: usize) {
        let ax = &self.axes[axis];
        let a = ax.active;
        let running = match a.kind {
            Kind::Velocity => true,
            Kind::Position | Kind::Halt => !a.released,
            _ => false,
        };
        if !running {
            return;
        }
        if let Ok(o) = overridden(ax, a.kind, &a.base, ax.set, a.target, a.end_v) {
            let ax = &mut self.axes[axis];
            ax.active.prof = o.prof;
            ax.active.tail = o.tail;
            ax.active.t = 0.0;
            ax.active.lim = o.lim;
            ax.active.paused = o.paused;
            if a.kind == Kind::Velocity && a.released && o.prof.duration() > 0.0 {
                ax.active.released = false;
                if let Some(id) = a.id {
                    self.cmds.set_in_target(id, false);
                }
            }
        }
    }

    /// Registers a cam table; returns its CamTableID.
    pub fn add_cam_table(&mut self, table: CamTable) -> usize {
        self.cams.push(table);
        self.cams.len() - 1
    }

    /// Checks a CamTableID.
    pub fn cam_table(&self, id: usize) -> Result<&CamTable, ErrorId> {
        self.cams.get(id).ok_or(ErrorId::InvalidCamTable)
    }

    /// Effective limits of a move on `axis` from the block's dynamics inputs.
    fn move_limits(cfg: &AxisConfig, d: &Dynamics, need_velocity: bool) -> Result<Limits, ErrorId> {
        let al = cfg.limits;
        if need_velocity && !(finite(d.velocity) && d.velocity != 0.0) {
            return Err(ErrorId::InvalidVelocity);
        }
        if !(finite(d.acceleration) && d.acceleration > 0.0) {
            return Err(ErrorId::InvalidAcceleration);
        }
        if !(finite(d.deceleration) && d.deceleration > 0.0) {
            return Err(ErrorId::InvalidDeceleration);
        }
        if !(finite(d.jerk) && d.jerk >= 0.0) {
            return Err(ErrorId::InvalidJerk);
        }
        let jerk = if d.jerk == 0.0 {
            al.jmax
        } else if al.jmax == 0.0 || al.jmax.is_infinite() {
            d.jerk
        } else {
            d.jerk.min(al.jmax)
        };
        let vmax = if need_velocity {
            d.velocity.abs().min(al.vmax)
        } else {
            al.vmax
        };
        Ok(Limits {
            vmax,
            amax: d.acceleration.min(al.amax),
            dmax: d.deceleration.min(al.dmax),
            jmax: jerk,
        })
    }

    /// Raw position the next command in the buffer starts from, and its direction.
    fn last_commanded(&self, axis: usize) -> (f64, f64) {
        let ax = &self.axes[axis];
        if let Some(p) = self.queues[axis].back() {
            match p.kind {
                Kind::Position => return (p.target, 0.0),
                Kind::Velocity => return (ax.set.p, p.target.signum()),
                _ => {}
            }
        }
        match ax.active.kind {
            Kind::Position => (ax.active.target, 0.0),
            _ => (ax.set.p, ax.set.v.signum()),
        }
    }

    /// Refuses a planned positioning whose path leaves the software limits further than
    /// where it starts (a move from beyond a limit back into the range is allowed).
    fn check_path(ax: &AxisRt, prof: &Profile, tail: Option<&Profile>) -> Result<(), ErrorId> {
        if !ax.cfg.sw_limits_enabled || ax.cfg.period().is_some() {
            return Ok(());
        }
        let (lo, hi) = position_range(prof, tail);
        let start = prof.start().p + ax.origin;
        let top = ax.cfg.sw_limit_pos.max(start);
        let bottom = ax.cfg.sw_limit_neg.min(start);
        let eps = 1e-12 * (1.0 + top.abs().max(bottom.abs()));
        if hi + ax.origin > top + eps || lo + ax.origin < bottom - eps {
            return Err(ErrorId::PathBeyondSoftwareLimit);
        }
        Ok(())
    }

    fn check_target(ax: &AxisRt, raw: f64) -> Result<(), ErrorId> {
        if ax.cfg.sw_limits_enabled && ax.cfg.period().is_none() {
            let u = raw + ax.origin;
            if u > ax.cfg.sw_limit_pos || u < ax.cfg.sw_limit_neg {
                return Err(ErrorId::TargetBeyondSoftwareLimit);
            }
        }
        Ok(())
    }

    /// Resolves a command into a [`Pending`] (targets in raw units).
    fn resolve(
        &self,
        axis: usize,
        cmd: &AxisCommand,
        d: &Dynamics,
        buffer: BufferMode,
        id: CmdId,
        additive_base: Option<f64>,
    ) -> Result<Pending, ErrorId> {
        let ax = &self.axes[axis];
        let aborting = buffer == BufferMode::Aborting;
        let (from, dir_hint) = if aborting {
            (ax.set.p, ax.set.v.signum())
        } else {
            self.last_commanded(axis)
        };
        let mut p = Pending {
            id,
            kind: Kind::Position,
            target: 0.0,
            speed: d.velocity.abs(),
            lim: Limits::default(),
            buffer,
            end_v: 0.0,
            sync: SyncParams::default(),
            relative: None,
        };
        match *cmd {
            AxisCommand::MoveAbsolute {
                position,
                direction,
            } => {
                if !finite(position) {
                    return Err(ErrorId::InvalidPosition);
                }
                p.lim = Self::move_limits(&ax.cfg, d, true)?;
                p.target = match ax.cfg.period() {
                    None => position - ax.origin,
                    Some(period) => {
                        let cur = (from + ax.origin).rem_euclid(period);
                        let goal = position.rem_euclid(period);
                        let fwd = (goal - cur).rem_euclid(period);
                        let back = if fwd == 0.0 { 0.0 } else { fwd - period };
                        let delta = match direction {
                            Direction::Positive => fwd,
                            Direction::Negative => back,
                            Direction::Shortest => {
                                if fwd <= -back {
                                    fwd
                                } else {
                                    back
                                }
                            }
                            Direction::Current => {
                                let s = if aborting {
                                    ax.set.v.signum()
                                } else {
                                    dir_hint
                                };
                                if s < 0.0 {
                                    back
                                } else {
                                    fwd
                                }
                            }
                        };
                        from + delta
                    }
                };
            }
            AxisCommand::MoveRelative { distance } => {
                if !finite(distance) {
                    return Err(ErrorId::InvalidPosition);
                }
                p.lim = Self::move_limits(&ax.cfg, d, true)?;
                // From the set position when it becomes active: now (Aborting or idle),
                // else predicted from the predecessor's target and re-based at activation.
                p.target = from + distance;
                p.relative = Some(distance);
            }
            AxisCommand::MoveAdditive { distance } => {
                if !finite(distance) {
                    return Err(ErrorId::InvalidPosition);
                }
                p.lim = Self::move_limits(&ax.cfg, d, true)?;
                let base = additive_base.unwrap_or_else(|| self.last_commanded(axis).0);
                p.target = base + distance;
            }
            AxisCommand::MoveVelocity { direction } => {
                p.lim = Self::move_limits(&ax.cfg, d, true)?;
                let sign = match direction {
                    Direction::Positive => 1.0,
                    Direction::Negative => -1.0,
                    Direction::Current => {
                        if ax.set.v < 0.0 {
                            -1.0
                        } else {
                            1.0
                        }
                    }
                    Direction::Shortest => return Err(ErrorId::InvalidDirection),
                };
                p.kind = Kind::Velocity;
                p.target = sign * d.velocity.signum() * p.lim.vmax;
                if ax.cfg.sw_limits_enabled && ax.cfg.period().is_none() {
                    // At (or past) a limit, a velocity move further out is refused. "At":
                    // within 1e-9 relative, where the brake to the limit leaves the axis
                    // (it stops there to rounding).
                    let u = ax.set.p + ax.origin;
                    let (hi, lo) = (ax.cfg.sw_limit_pos, ax.cfg.sw_limit_neg);
                    let eps = |l: f64| 1e-9 * l.abs().max(1.0);
                    if (p.target > 0.0 && u >= hi - eps(hi))
                        || (p.target < 0.0 && u <= lo + eps(lo))
                    {
                        return Err(ErrorId::TargetBeyondSoftwareLimit);
                    }
                }
            }
            AxisCommand::Halt | AxisCommand::Stop => {
                if !(finite(d.deceleration) && d.deceleration > 0.0) {
                    return Err(ErrorId::InvalidDeceleration);
                }
                if !(finite(d.jerk) && d.jerk >= 0.0) {
                    return Err(ErrorId::InvalidJerk);
                }
                let dd = Dynamics {
                    velocity: ax.cfg.limits.vmax,
                    acceleration: d.deceleration,
                    deceleration: d.deceleration,
                    jerk: d.jerk,
                };
                p.lim = Self::move_limits(&ax.cfg, &dd, false)?;
                p.lim.amax = p.lim.amax.max(p.lim.dmax);
                p.kind = if matches!(cmd, AxisCommand::Halt) {
                    Kind::Halt
                } else {
                    Kind::Stop
                };
                p.speed = 0.0;
            }
            AxisCommand::Home { position } => {
                if !finite(position) {
                    return Err(ErrorId::InvalidPosition);
                }
                p.kind = Kind::Home;
                p.target = position;
                p.speed = 0.0;
            }
            AxisCommand::GearIn {
                master,
                numerator,
                denominator,
                source,
            } => {
                self.axis(master)?;
                if master == axis {
                    return Err(ErrorId::InvalidAxis);
                }
                if !(finite(numerator) && finite(denominator) && denominator != 0.0) {
                    return Err(ErrorId::InvalidRatio);
                }
                let dd = Dynamics {
                    velocity: ax.cfg.limits.vmax,
                    ..*d
                };
                p.lim = Self::move_limits(&ax.cfg, &dd, false)?;
                p.kind = Kind::Gear;
                p.sync = SyncParams::gear(master, numerator / denominator, source);
                self.gear_remaining(axis, &p.sync)?;
                p.speed = 0.0;
            }
            AxisCommand::CamIn { master, params } => {
                self.axis(master)?;
                if master == axis {
                    return Err(ErrorId::InvalidAxis);
                }
                self.cam_table(params.table)?;
                params.validate()?;
                let dd = Dynamics {
                    velocity: ax.cfg.limits.vmax,
                    acceleration: ax.cfg.limits.amax,
                    deceleration: ax.cfg.limits.dmax,
                    jerk: 0.0,
                };
                p.lim = Self::move_limits(&ax.cfg, &dd, false)?;
                p.kind = Kind::Cam;
                p.sync = SyncParams { master, ..params };
                self.cam_remaining(axis, &p.sync)?;
                p.speed = 0.0;
            }
            AxisCommand::GearOut | AxisCommand::CamOut => {}
        }
        if matches!(p.kind, Kind::Position | Kind::Velocity) {
            // The junction speeds of blending use the speed the move can have.
            p.speed = p.lim.vmax;
        }
        if p.kind == Kind::Position {
            Self::check_target(ax, p.target)?;
        }
        Ok(p)
    }

    /// Gives a command to an axis (a block's rising Execute). Returns its handle, or the
    /// ErrorID when the command is illegal in the axis state, its inputs are invalid or
    /// the buffer is full.
    pub fn submit(
        &mut self,
        axis: usize,
        cmd: AxisCommand,
        dynamics: Dynamics,
        buffer: BufferMode,
    ) -> Result<CmdId, ErrorId> {
        let ax = self.axis(axis)?;
        if let Some(g) = ax.group {
            if self.groups[g as usize].state != GroupState::GroupDisabled {
                return Err(ErrorId::AxisInGroup);
            }
        }
        check_axis(ax.state, cmd.class())?;
        match cmd {
            AxisCommand::GearOut => return self.sync_out(axis, Kind::Gear),
            AxisCommand::CamOut => return self.sync_out(axis, Kind::Cam),
            _ => {}
        }
        let buffer = match cmd {
            AxisCommand::Stop | AxisCommand::Home { .. } => BufferMode::Aborting,
            _ => buffer,
        };
        // Check the inputs before allocating a handle.
        let probe = CmdId { index: 0, gen: 0 };
        let pending = self.resolve(axis, &cmd, &dynamics, buffer, probe, None)?;
        let idle = self.axes[axis].active.kind == Kind::Idle;
        if buffer != BufferMode::Aborting
            && !idle
            && self.queues[axis].len() >= self.queues[axis].depth()
        {
            return Err(ErrorId::QueueFull);
        }
        if (buffer == BufferMode::Aborting || idle) && pending.kind == Kind::Position {
            // The path from the current state (a time-optimal overshoot, braking from the
            // current velocity) must stay within the software limits: refused before any
            // motion, and before anything running is aborted.
            let ax = &self.axes[axis];
            if ax.cfg.sw_limits_enabled {
                let o = overridden(
                    ax,
                    Kind::Position,
                    &pending.lim,
                    ax.set,
                    pending.target,
                    0.0,
                )?;
                Self::check_path(ax, &o.prof, o.tail.as_ref())?;
            }
        }
        if (buffer == BufferMode::Aborting || idle) && pending.kind == Kind::Cam {
            // The coupling must fit the slave's limits: refused before anything running
            // is aborted (README "Camming").
            self.plan_cam(axis, &pending.sync)?;
        }
        let id = self.cmds.alloc(CmdStatus::Queued);
        let pending = Pending { id, ..pending };
        if buffer == BufferMode::Aborting || idle {
            self.abort_all(axis, CmdStatus::Aborted);
            if let Err(e) = self.activate(axis, pending, 0.0) {
                self.cmds.set(id, CmdStatus::Error(e));
            } else if pending.kind == Kind::Stop {
                self.note_stop_cap(axis, id, &dynamics, &pending.lim);
            }
        } else {
            self.link_successor(axis, &pending);
            if let Err((e, p)) = self.queues[axis].push(pending) {
                self.cmds.set(p.id, CmdStatus::Error(e));
            }
        }
        Ok(id)
    }

    /// Records an MC_Stop whose Deceleration or Jerk the axis limits capped.
    fn note_stop_cap(&mut self, axis: usize, cmd: CmdId, d: &Dynamics, lim: &Limits) {
        let dec_capped = d.deceleration > lim.dmax;
        let jerk_capped = d.jerk > 0.0 && lim.jmax > 0.0 && d.jerk > lim.jmax;
        if !(dec_capped || jerk_capped) {
            return;
        }
        let r = StopReduction {
            cmd,
            deceleration_requested: d.deceleration,
            deceleration_reached: lim.dmax,
            jerk_requested: d.jerk,
            jerk_reached: lim.jmax,
        };
        let c = &mut self.stop_caps[axis];
        if c.kept.len() < crate::group::REDUCTIONS_KEPT {
            c.kept.push(r);
        }
        c.count += 1;
        c.last = Some((self.cycles, r));
    }

    /// The MC_Stop commands of an axis whose Deceleration or Jerk was capped to the axis
    /// limits (the first `REDUCTIONS_KEPT`), and how many there were in all.
    pub fn stop_reductions(&self, axis: usize) -> Result<(&[StopReduction], usize), ErrorId> {
        self.axis(axis)?;
        let c = &self.stop_caps[axis];
        Ok((&c.kept, c.count))
    }

    /// The capped MC_Stop that started in the last cycle (the cycle after the scan that gave
    /// it), if any: what the trace columns `axis.<A>.stop_*` show.
    pub fn stop_reduction_now(&self, axis: usize) -> Result<Option<StopReduction>, ErrorId> {
        self.axis(axis)?;
        let c = &self.stop_caps[axis];
        Ok(c.last.filter(|(k, _)| k + 1 == self.cycles).map(|(_, r)| r))
    }

    /// ContinuousUpdate: new inputs for a command that is still Busy.
    pub fn update(
        &mut self,
        axis: usize,
        id: CmdId,
        cmd: AxisCommand,
        dynamics: Dynamics,
    ) -> Result<(), ErrorId> {
        self.axis(axis)?;
        let st = self.cmds.status(id);
        if self.axes[axis].active.id == Some(id) && st == CmdStatus::Active {
            let buffer = BufferMode::Aborting;
            let mut p = self.resolve(axis, &cmd, &dynamics, buffer, id, None)?;
            if matches!(
                cmd,
                AxisCommand::MoveAdditive { .. } | AxisCommand::MoveRelative { .. }
            ) {
                // The target of a relative move does not move with the axis.
                return Ok(());
            }
            let cur = &self.axes[axis].active;
            if cur.kind == p.kind && cur.target == p.target && cur.base == p.lim {
                // Inputs unchanged: keep the running profile.
                return Ok(());
            }
            p.end_v = cur.end_v;
            let released = cur.released;
            self.activate(axis, p, 0.0)?;
            if p.kind == Kind::Velocity && released {
                self.cmds.set_in_target(id, false);
            }
        } else if st == CmdStatus::Queued {
            let p = {
                let q = self.queues[axis].iter().find(|p| p.id == id).copied();
                match q {
                    Some(q) => {
                        let mut n = self.resolve(axis, &cmd, &dynamics, q.buffer, id, None)?;
                        n.end_v = q.end_v;
                        n
                    }
                    None => return Ok(()),
                }
            };
            for q in self.queues[axis].iter_mut() {
                if q.id == id {
                    *q = p;
                }
            }
        }
        Ok(())
    }

    /// A blending successor joins the last command: set its end velocity.
    fn link_successor(&mut self, axis: usize, next: &Pending) {
        if !next.buffer.is_blending() {
            return;
        }
        let (pred_kind, pred_target, pred_speed, pred_from) = match self.queues[axis].back() {
            Some(b) => (b.kind, b.target, b.speed, None),
            None => {
                let a = &self.axes[axis].active;
                (a.kind, a.target, a.speed, Some(self.axes[axis].set))
            }
        };
        if pred_kind != Kind::Position {
            return;
        }
        // Direction of the predecessor at its end and of the successor at its start.
        let start_p = match pred_from {
            Some(_) => self.axes[axis].active.prof.start().p,
            None => {
                let q = &self.queues[axis];
                if q.len() >= 2 {
                    q.iter()
                        .nth(q.len() - 2)
                        .map(|p| p.target)
                        .unwrap_or(pred_target)
                } else {
                    self.axes[axis].active.target
                }
            }
        };
        let d1 = (pred_target - start_p).signum();
        let d2 = match next.kind {
            Kind::Position => (next.target - pred_target).signum(),
            Kind::Velocity => next.target.signum(),
            _ => 0.0,
        };
        let vj = if d1 != 0.0 && d1 == d2 {
            d1 * next.buffer.junction_speed(pred_speed, next.speed)
        } else {
            0.0
        };
        match pred_from {
            None => {
                if let Some(b) = self.queues[axis].back_mut() {
                    b.end_v = vj;
                }
            }
            Some(now) => {
                let a = &mut self.axes[axis].active;
                if a.paused {
                    // Held by VelFactor 0: the resumed plan ends at vj.
                    a.end_v = vj;
                    return;
                }
                if let Ok((p, tail)) = plan_to(now, a.target, vj, &a.lim) {
                    a.prof = p;
                    a.tail = tail;
                    a.t = 0.0;
                    a.end_v = vj;
                }
            }
        }
    }

    /// Makes `p` the active command of the axis, starting from the current set point
    /// advanced by `t0` seconds into its profile.
    fn activate(&mut self, axis: usize, mut p: Pending, t0: f64) -> Result<(), ErrorId> {
        let start = self.axes[axis].set;
        if let Some(d) = p.relative {
            p.target = start.p + d;
            Self::check_target(&self.axes[axis], p.target)?;
        }
        let mut lim = p.lim;
        let mut tail = None;
        let mut paused = false;
        let prof = match p.kind {
            Kind::Position | Kind::Velocity | Kind::Halt => {
                let ax = &self.axes[axis];
                overridden(ax, p.kind, &p.lim, start, p.target, p.end_v).map(|o| {
                    (lim, tail, paused) = (o.lim, o.tail, o.paused);
                    o.prof
                })
            }
            Kind::Stop => {
                // Not overridden; the jerk raised as for a halt (see `overridden`).
                let al = self.axes[axis].cfg.limits;
                if lim.jmax > 0.0 && (al.jmax == 0.0 || al.jmax > lim.jmax) {
                    let peak = (start.v + start.a * start.a.abs() / (2.0 * lim.jmax)).abs();
                    if peak > al.vmax {
                        lim.jmax = al.jmax;
                    }
                }
                lim.vmax = lim.vmax.max(start.v.abs());
                Profile::velocity(start, 0.0, &lim).map_err(|_| ErrorId::PlanningFailed)
            }
            Kind::Gear | Kind::Cam => Ok(self.axes[axis].active.prof),
            _ => Ok(Active::idle(start).prof),
        }
        .map_err(|_| ErrorId::PlanningFailed)?;
        if p.kind == Kind::Position {
            Self::check_path(&self.axes[axis], &prof, tail.as_ref())?;
        }
        let cam = if p.kind == Kind::Cam {
            Some(self.plan_cam(axis, &p.sync)?)
        } else {
            None
        };
        let ax = &mut self.axes[axis];
        let class = match p.kind {
            Kind::Position | Kind::Halt => AxisState::DiscreteMotion,
            Kind::Velocity => AxisState::ContinuousMotion,
            Kind::Stop => AxisState::Stopping,
            Kind::Home => AxisState::Homing,
            Kind::Gear | Kind::Cam => AxisState::SynchronizedMotion,
            _ => ax.state,
        };
        ax.state = class;
        ax.active = Active {
            kind: p.kind,
            id: Some(p.id),
            prof,
            t: t0,
            target: p.target,
            speed: p.speed,
            lim,
            base: p.lim,
            paused,
            released: false,
            end_v: p.end_v,
            sync: p.sync,
            tail,
            limit_stop: None,
        };
        if p.kind == Kind::Stop {
            ax.stop_owner = Some(p.id);
        }
        self.cmds.set(p.id, CmdStatus::Active);
        match p.kind {
            Kind::Home => {
                if let Some(d) = self.drives[axis].as_mut() {
                    d.start_homing();
                }
            }
            Kind::Gear => {
                self.start_sync(axis);
            }
            Kind::Cam => {
                if let Some((sync, prof, lim)) = cam {
                    // The catch-up starts from the state it was planned from (as gearing).
                    let a = &mut self.axes[axis].active;
                    (a.sync, a.prof, a.lim, a.t) = (sync, prof, lim, 0.0);
                }
            }
            _ => {
                let a = &self.axes[axis].active;
                if t0 > 0.0 {
                    let s = a.prof.at(t0);
                    self.axes[axis].set = s;
                }
            }
        }
        Ok(())
    }

    /// GearOut / CamOut: the slave keeps its current velocity (ContinuousMotion).
    fn sync_out(&mut self, axis: usize, kind: Kind) -> Result<CmdId, ErrorId> {
        if self.axes[axis].active.kind != kind {
            return Err(ErrorId::NotSynchronized);
        }
        self.abort_all(axis, CmdStatus::Aborted);
        let ax = &mut self.axes[axis];
        let start = ax.set;
        let mut lim = ax.cfg.limits;
        lim.vmax = lim.vmax.max(start.v.abs());
        let prof = Profile::velocity(start, start.v, &lim).map_err(|_| ErrorId::PlanningFailed)?;
        ax.active = Active {
            kind: Kind::Velocity,
            id: None,
            prof,
            t: 0.0,
            target: start.v,
            speed: start.v.abs(),
            lim,
            base: lim,
            paused: false,
            released: true,
            end_v: 0.0,
            sync: SyncParams::default(),
            tail: None,
            limit_stop: None,
        };
        ax.state = AxisState::ContinuousMotion;
        let id = self.cmds.alloc(CmdStatus::Done);
        Ok(id)
    }

    // ------------------------------------------------------------------- step

    /// Advances every axis and group by one cycle.
    pub fn step(&mut self) {
        let dt = self.cfg.cycle;
        self.cycles += 1;
        self.step_groups(dt);
        self.events.clear();
        self.synced.clear();
        for (i, ax) in self.axes.iter_mut().enumerate() {
            let a = &mut ax.active;
            match a.kind {
                Kind::Idle => {
                    ax.set.v = 0.0;
                    ax.set.a = 0.0;
                }
                Kind::Group => {}
                Kind::Gear | Kind::Cam => {
                    self.synced.push(i as u32);
                    continue;
                }
                Kind::Home => {
                    self.events.push(i as u32);
                }
                _ => {
                    a.t += dt;
                    ax.set = a.prof.at_next(a.t);
                    if a.kind == Kind::Velocity
                        && ax.cfg.sw_limits_enabled
                        && ax.cfg.period().is_none()
                        && ax.set.v != 0.0
                    {
                        guard_limit(&ax.cfg, a, ax.set, ax.origin, dt, &mut self.cmds);
                    }
                    if a.t >= a.prof.duration() && !a.released && !a.paused {
                        self.events.push(i as u32);
                    } else if a.kind == Kind::Velocity && a.released && !self.queues[i].is_empty() {
                        // InVelocity was shown (at least one scan): the successor takes over.
                        self.events.push(i as u32);
                    }
                }
            }
            if !ax.has_drive {
                ax.act_p = ax.set.p;
                ax.act_v = ax.set.v;
                if ax.cfg.sw_limits_enabled && ax.state != AxisState::ErrorStop {
                    let u = ax.set.p + ax.origin;
                    if ax.cfg.period().is_none()
                        && ((u > ax.cfg.sw_limit_pos && ax.set.v > 0.0)
                            || (u < ax.cfg.sw_limit_neg && ax.set.v < 0.0))
                    {
                        self.events.push(i as u32);
                    }
                }
            }
        }
        // Events of simulated axes first: a master whose profile ended (its successor
        // starting within the cycle) has its final set point before its slaves follow it.
        for k in 0..self.events.len() {
            let i = self.events[k] as usize;
            if !self.axes[i].has_drive {
                self.axis_event(i);
            }
        }
        for k in 0..self.synced.len() {
            let i = self.synced[k] as usize;
            self.step_sync(i, dt);
        }
        // Over the drives (a compact vector), not over the axes' large records.
        for i in 0..self.drives.len() {
            if self.drives[i].is_some() {
                self.exchange_drive(i);
            }
        }
        for k in 0..self.events.len() {
            let i = self.events[k] as usize;
            if self.axes[i].has_drive {
                self.axis_event(i);
            }
        }
    }

    /// Checks after the sync pass (software limits of slaves).
    pub(crate) fn check_limits(&mut self, i: usize) {
        let ax = &self.axes[i];
        if !ax.has_drive {
            let s = ax.set;
            let ax = &mut self.axes[i];
            ax.act_p = s.p;
            ax.act_v = s.v;
        }
        let ax = &self.axes[i];
        if ax.cfg.sw_limits_enabled && ax.state != AxisState::ErrorStop && ax.cfg.period().is_none()
        {
            // Only motion further out is an error: an axis standing beyond a limit (after
            // an error brake) can be reset and moved back into the range.
            let u = ax.set.p + ax.origin;
            if u > ax.cfg.sw_limit_pos && ax.set.v > 0.0 {
                let _ = self.raise_axis_error(i, ErrorId::SoftwareLimitPositive);
            } else if u < ax.cfg.sw_limit_neg && ax.set.v < 0.0 {
                let _ = self.raise_axis_error(i, ErrorId::SoftwareLimitNegative);
            }
        }
    }

    fn exchange_drive(&mut self, i: usize) {
        let s = self.axes[i].set;
        let powered = self.axes[i].powered;
        let Some(d) = self.drives[i].as_mut() else {
            return;
        };
        if powered {
            d.write(s.p, s.v, s.a);
        }
        let (p, v, en, fault) = (
            d.actual_position(),
            d.actual_velocity(),
            d.enabled(),
            d.fault(),
        );
        let ax = &mut self.axes[i];
        ax.act_p = p;
        ax.act_v = v;
        if !powered {
            ax.set.p = p;
        }
        if let Some(code) = fault {
            if ax.state != AxisState::ErrorStop {
                ax.drive_code = code;
                let _ = self.raise_axis_error(i, ErrorId::DriveFault);
            }
            return;
        }
        if ax.power_req && ax.powered && !en {
            let _ = self.raise_axis_error(i, ErrorId::DriveDisabled);
            return;
        }
        if ax.power_req && !ax.powered {
            self.poll_power(i);
        }
        let ax = &self.axes[i];
        if ax.cfg.following_error_limit > 0.0
            && ax.powered
            && (s.p - p).abs() > ax.cfg.following_error_limit
        {
            let _ = self.raise_axis_error(i, ErrorId::FollowingError);
            return;
        }
        self.check_limits(i);
    }

    /// Rare per-axis work: a profile ended, homing progressed, a limit was hit.
    fn axis_event(&mut self, i: usize) {
        {
            let ax = &self.axes[i];
            if ax.cfg.sw_limits_enabled && !ax.has_drive {
                self.check_limits(i);
            }
        }
        let a = self.axes[i].active;
        match a.kind {
            Kind::Home => {
                let st = match self.drives[i].as_mut() {
                    Some(d) => d.homing_status(),
                    None => HomingStatus::Done,
                };
                match st {
                    HomingStatus::Busy => {}
                    HomingStatus::Done => {
                        let ax = &mut self.axes[i];
                        ax.origin = a.target - ax.set.p;
                        ax.active = Active::idle(ax.set);
                        ax.state = AxisState::Standstill;
                        if let Some(id) = a.id {
                            self.cmds.set(id, CmdStatus::Done);
                        }
                        self.start_next(i, 0.0);
                    }
                    HomingStatus::Failed => {
                        let _ = self.raise_axis_error(i, ErrorId::HomingFailed);
                    }
                }
            }
            Kind::Velocity if a.released && !a.paused && !self.queues[i].is_empty() => {
                if let Some(id) = a.id {
                    self.cmds.set(id, CmdStatus::Aborted);
                    self.cmds.set_in_target(id, false);
                }
                // It starts from this cycle's set point.
                self.start_next(i, 0.0);
            }
            Kind::Velocity if a.released && !a.paused => {}
            Kind::Position | Kind::Halt | Kind::Velocity | Kind::Stop | Kind::Brake => {
                if a.released || a.paused || a.t < a.prof.duration() {
                    return;
                }
                if let Some(tail) = a.tail {
                    // Main part done: continue with the velocity-change tail.
                    let ax = &mut self.axes[i];
                    ax.active.t -= a.prof.duration();
                    ax.active.prof = tail;
                    ax.active.tail = None;
                    ax.set = tail.at(ax.active.t);
                    return;
                }
                let leftover = a.t - a.prof.duration();
                match a.kind {
                    Kind::Velocity => {
                        self.axes[i].active.released = true;
                        if let Some(id) = a.id {
                            self.cmds.set_in_target(id, true);
                        }
                    }
                    Kind::Stop => {
                        let ax = &mut self.axes[i];
                        let end = a.prof.end();
                        ax.set = State {
                            p: end.p,
                            v: 0.0,
                            a: 0.0,
                        };
                        ax.active = Active::idle(ax.set);
                        if let Some(id) = a.id {
                            self.cmds.set(id, CmdStatus::Done);
                        }
                    }
                    Kind::Brake => {
                        let ax = &mut self.axes[i];
                        let end = a.prof.end();
                        ax.set = State {
                            p: end.p,
                            v: 0.0,
                            a: 0.0,
                        };
                        ax.active = Active::idle(ax.set);
                    }
                    _ if a.limit_stop.is_some() => {
                        // A velocity move stopped at a software limit: the axis error.
                        let ax = &mut self.axes[i];
                        // At rest at the limit (the profile's end, rounding aside).
                        ax.set = State {
                            p: a.prof.end().p,
                            v: 0.0,
                            a: 0.0,
                        };
                        ax.active = Active::idle(ax.set);
                        ax.active.id = a.id;
                        if let Some(e) = a.limit_stop {
                            let _ = self.raise_axis_error(i, e);
                        }
                    }
                    _ => {
                        let end = a.prof.end();
                        let ax = &mut self.axes[i];
                        ax.set = end;
                        if let Some(id) = a.id {
                            self.cmds.set(id, CmdStatus::Done);
                        }
                        ax.active = Active::idle(ax.set);
                        ax.active.released = true;
                        if self.queues[i].is_empty() && a.end_v == 0.0 {
                            ax.state = AxisState::Standstill;
                            ax.set.v = 0.0;
                        } else {
                            // The successor starts from the junction state.
                            ax.set = State {
                                p: end.p,
                                v: a.end_v,
                                a: 0.0,
                            };
                            self.start_next(i, leftover);
                        }
                    }
                }
            }
            _ => {}
        }
    }

    /// Starts the next buffered command, if any.
    pub(crate) fn start_next(&mut self, axis: usize, t0: f64) {
        while let Some(p) = self.queues[axis].pop() {
            // Its own successor may blend with it: compute its end velocity.
            let mut p = p;
            if let Some(n) = self.queues[axis].front().copied() {
                p.end_v = self.junction_after(axis, &p, &n);
            }
            match self.activate(axis, p, t0) {
                Ok(()) => {
                    let a = &self.axes[axis].active;
                    if matches!(a.kind, Kind::Position | Kind::Halt)
                        && a.t >= a.prof.duration()
                        && a.tail.is_none()
                        && !a.paused
                    {
                        // Already over within this cycle (a halt at rest, a zero move): end
                        // it now, so that its successor runs the rest of this cycle.
                        self.axis_event(axis);
                    }
                    return;
                }
                Err(e) => {
                    // Only the active block failed: the next buffered block starts.
                    self.cmds.set(p.id, CmdStatus::Error(e));
                }
            }
        }
        let ax = &mut self.axes[axis];
        if ax.active.kind == Kind::Idle && ax.state != AxisState::ErrorStop {
            if ax.set.v != 0.0 || ax.set.a != 0.0 {
                // Left at a junction speed with no successor running (it failed): brake
                // to rest within the axis's limits instead of stopping at once.
                let lim = ax.cfg.limits;
                if let Ok(p) = Profile::velocity(ax.set, 0.0, &lim) {
                    let at = ax.set;
                    ax.active = Active::idle(at);
                    ax.active.kind = Kind::Halt;
                    ax.active.prof = p;
                    ax.active.released = false;
                    ax.state = AxisState::DiscreteMotion;
                    return;
                }
            }
            ax.state = AxisState::Standstill;
            ax.set.v = 0.0;
            ax.set.a = 0.0;
        }
    }

    fn junction_after(&self, axis: usize, p: &Pending, n: &Pending) -> f64 {
        if p.kind != Kind::Position || !n.buffer.is_blending() {
            return 0.0;
        }
        let from = self.axes[axis].set.p;
        let d1 = (p.target - from).signum();
        let d2 = match n.kind {
            Kind::Position => (n.target - p.target).signum(),
            Kind::Velocity => n.target.signum(),
            _ => 0.0,
        };
        if d1 != 0.0 && d1 == d2 {
            d1 * n.buffer.junction_speed(p.speed, n.speed)
        } else {
            0.0
        }
    }
}

/// A velocity move on an axis with software limits: when stopping from the next cycle's
/// state (with the axis's own deceleration and jerk) would pass the limit ahead, it brakes
/// now on a positioning profile that stops exactly at the limit.
fn guard_limit(
    cfg: &AxisConfig,
    a: &mut Active,
    now: State,
    origin: f64,
    dt: f64,
    cmds: &mut CmdTable,
) {
    let dir = now.v.signum();
    let limit = if dir > 0.0 {
        cfg.sw_limit_pos
    } else {
        cfg.sw_limit_neg
    } - origin;
    let mut l = cfg.limits;
    l.vmax = l.vmax.max(now.v.abs()).max(a.lim.vmax);
    let next = a.prof.at(a.t + dt);
    let Ok(stop) = Profile::velocity(next, 0.0, &l) else {
        return;
    };
    if (stop.end().p - limit) * dir <= 0.0 {
        return;
    }
    if let Ok(p) = Profile::position(now, limit, 0.0, &l) {
        a.kind = Kind::Position;
        a.prof = p;
        a.t = 0.0;
        a.tail = None;
        a.target = limit;
        a.end_v = 0.0;
        a.released = false;
        a.limit_stop = Some(if dir > 0.0 {
            ErrorId::SoftwareLimitPositive
        } else {
            ErrorId::SoftwareLimitNegative
        });
        if let Some(id) = a.id {
            cmds.set_in_target(id, false);
        }
    }
}

fn check_state_err(s: AxisState) -> ErrorId {
    match s {
        AxisState::Homing => ErrorId::AxisHoming,
        AxisState::ErrorStop => ErrorId::AxisErrorStop,
        AxisState::Disabled => ErrorId::AxisDisabled,
        AxisState::Stopping => ErrorId::AxisStopping,
        _ => ErrorId::None,
    }
}
