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

mod admin;
mod commands;
mod cycle;
mod queries;
mod queue;

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

    pub(crate) fn axis(&self, axis: usize) -> Result<&AxisRt, ErrorId> {
        self.axes.get(axis).ok_or(ErrorId::InvalidAxis)
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
