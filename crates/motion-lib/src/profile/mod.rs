//! Time-optimal jerk-limited motion profiles (the mathematics, with no PLC interface).
//!
//! Input: a start [`State`] (position, velocity, acceleration: anywhere, even beyond the
//! limits), a target (position and velocity, or velocity alone) and [`Limits`].
//! Output: a [`Profile`], i.e. the start state and at most [`MAX_PHASES`] phases of
//! piecewise-constant jerk, followed after [`Profile::duration`] by an endless
//! constant-velocity continuation at the target velocity.
//!
//! Invariants of every profile returned by a planner here:
//! - position, velocity and acceleration are continuous (jerk-limited profiles; a
//!   trapezoidal profile, `jmax` = 0 or infinite, has piecewise-constant acceleration);
//! - |jerk| <= jmax, acceleration in [-dmax, amax] (mirrored for a move in the negative
//!   direction) and |v| <= vmax, except while braking a start state that is already
//!   beyond a limit back inside it (then the limit is approached monotonically);
//! - the end state is the target (to 1e-8 relative), with acceleration 0.
//!
//! The planners follow ruckig (Berscheid & Kröger, "Jerk-limited real-time trajectory
//! generation with arbitrary target states", RSS 2021): see `README_profile.md`.

mod jsonl;
mod kernel;
pub mod line;
mod velocity;

pub use jsonl::plan_jsonl;

use thiserror::Error;

/// Most phases a profile can hold: 2 brake phases + 7 profile phases + slack.
pub const MAX_PHASES: usize = 12;

/// Kinematic limits of one axis (or of the path of a straight line).
///
/// `amax` applies while accelerating in the direction of travel, `dmax` while
/// decelerating (ruckig's `max_acceleration = amax`, `min_acceleration = -dmax` for a
/// move in the positive direction; mirrored for the negative direction).
///
/// `jmax = 0` or `jmax = f64::INFINITY` means "no jerk limit": the profile is then
/// trapezoidal (acceleration steps between `amax`, 0 and `-dmax`), and the start
/// acceleration is ignored.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Limits {
    pub vmax: f64,
    pub amax: f64,
    pub dmax: f64,
    pub jmax: f64,
}

impl Limits {
    /// True when there is no jerk limit (`jmax` is 0 or infinite): trapezoidal profiles.
    pub fn is_trapezoidal(&self) -> bool {
        self.jmax == 0.0 || self.jmax.is_infinite()
    }

    /// Checks that the limits are usable: `vmax`, `amax`, `dmax` finite and > 0, `jmax`
    /// >= 0 (0 or +infinity meaning trapezoidal) and not NaN.
    pub fn validate(&self) -> Result<(), PlanError> {
        let pos = |x: f64| x.is_finite() && x > 0.0;
        if pos(self.vmax)
            && pos(self.amax)
            && pos(self.dmax)
            && !self.jmax.is_nan()
            && self.jmax >= 0.0
        {
            Ok(())
        } else {
            Err(PlanError::InvalidLimits)
        }
    }
}

/// Kinematic state of one axis: position, velocity, acceleration.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct State {
    pub p: f64,
    pub v: f64,
    pub a: f64,
}

impl State {
    /// The state after `t` seconds of constant `jerk` from `self`.
    #[inline]
    pub fn integrate(&self, t: f64, jerk: f64) -> State {
        State {
            p: self.p + t * (self.v + t * (self.a / 2.0 + t * jerk / 6.0)),
            v: self.v + t * (self.a + t * jerk / 2.0),
            a: self.a + t * jerk,
        }
    }
}

/// One phase of a profile: `duration` seconds of constant `jerk`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Phase {
    pub duration: f64,
    pub jerk: f64,
}

/// Why a profile could not be planned.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum PlanError {
    #[error("invalid limits: vmax, amax and dmax must be finite and > 0, jmax >= 0 (0 or infinite = trapezoidal)")]
    InvalidLimits,
    #[error("invalid start state: position, velocity and acceleration must be finite")]
    InvalidState,
    #[error("invalid target: the position must be finite and the velocity finite with |v| <= vmax ({vmax})")]
    InvalidTarget { vmax: f64 },
    #[error("requested duration {requested} s is shorter than the minimal duration {minimal} s")]
    DurationTooShort { requested: f64, minimal: f64 },
    #[error(
        "no profile reaches the target in exactly {requested} s (minimal duration {minimal} s)"
    )]
    DurationUnreachable { requested: f64, minimal: f64 },
    #[error("line: {0}")]
    Line(String),
    #[error("no valid profile found (numerical failure) for start {start:?}, target p = {target_p}, v = {target_v}")]
    NoSolution {
        start: State,
        target_p: f64,
        target_v: f64,
    },
}

/// A planned motion: the start state, phases of constant jerk, then constant velocity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Profile {
    start: State,
    count: usize,
    phases: [Phase; MAX_PHASES],
    /// State at the start of each phase; `starts[count]` is the end state. For a
    /// trapezoidal phase `starts[i].a` is the phase's constant acceleration.
    starts: [State; MAX_PHASES + 1],
    /// Time at the end of each phase.
    ends: [f64; MAX_PHASES],
}

impl Profile {
    /// An empty profile standing at `start` (duration 0).
    pub(crate) fn new(start: State) -> Profile {
        Profile {
            start,
            count: 0,
            phases: [Phase::default(); MAX_PHASES],
            starts: [start; MAX_PHASES + 1],
            ends: [0.0; MAX_PHASES],
        }
    }

    /// Appends a phase of constant jerk (phases of zero or negative duration are skipped).
    pub(crate) fn push_jerk(&mut self, duration: f64, jerk: f64) {
        if duration > 0.0 && self.count < MAX_PHASES {
            let i = self.count;
            let s = self.starts[i];
            self.phases[i] = Phase { duration, jerk };
            self.starts[i + 1] = s.integrate(duration, jerk);
            self.ends[i] = self.duration() + duration;
            self.count += 1;
        }
    }

    /// Appends a trapezoidal phase of constant acceleration `accel` (jerk 0).
    pub(crate) fn push_accel(&mut self, duration: f64, accel: f64) {
        if duration > 0.0 && self.count < MAX_PHASES {
            self.starts[self.count].a = accel;
            self.push_jerk(duration, 0.0);
            self.starts[self.count].a = 0.0;
        }
    }

    /// Time-optimal profile from `start` to position `target_p` with velocity `target_v`
    /// and acceleration 0.
    pub fn position(
        start: State,
        target_p: f64,
        target_v: f64,
        lim: &Limits,
    ) -> Result<Profile, PlanError> {
        check_inputs(&start, target_p, target_v, lim)?;
        if let Some(prof) = velocity::position_cruising(start, target_p, target_v, lim) {
            return Ok(prof);
        }
        let sol = Solved::new(start, target_p, target_v, lim).ok_or(PlanError::NoSolution {
            start,
            target_p,
            target_v,
        })?;
        Ok(sol.build(&sol.block.p_min))
    }

    /// Time-optimal profile from `start` to velocity `target_v` with acceleration 0
    /// (MoveVelocity; Halt/Stop with `target_v = 0`). The position is free.
    pub fn velocity(start: State, target_v: f64, lim: &Limits) -> Result<Profile, PlanError> {
        check_inputs(&start, 0.0, target_v, lim)?;
        let mut prof = Profile::new(start);
        velocity::push_velocity_change(&mut prof, target_v, lim, 1.0);
        Ok(prof)
    }

    /// Profile reaching the same target as [`Profile::position`] at exactly time `t`
    /// (`t` >= the minimal duration), for synchronising axes and blending.
    ///
    /// Some durations above the minimum are impossible (ruckig's blocked intervals, e.g.
    /// a start velocity towards the target that cannot be slowed down enough without
    /// reversing): they give [`PlanError::DurationUnreachable`].
    pub fn with_duration(
        start: State,
        target_p: f64,
        target_v: f64,
        lim: &Limits,
        t: f64,
    ) -> Result<Profile, PlanError> {
        check_inputs(&start, target_p, target_v, lim)?;
        let sol = Solved::new(start, target_p, target_v, lim).ok_or(PlanError::NoSolution {
            start,
            target_p,
            target_v,
        })?;
        let fastest = velocity::position_cruising(start, target_p, target_v, lim)
            .unwrap_or_else(|| sol.build(&sol.block.p_min));
        let minimal = fastest.duration();
        let eps = 1e-12 * minimal.max(1.0);
        if t.is_nan() || t < minimal - eps {
            return Err(PlanError::DurationTooShort {
                requested: t,
                minimal,
            });
        }
        if t <= minimal + eps {
            return Ok(fastest);
        }
        let unreachable = PlanError::DurationUnreachable {
            requested: t,
            minimal,
        };
        let t_profile = t - sol.brake.duration;
        for iv in [sol.block.a, sol.block.b].into_iter().flatten() {
            if (t_profile - iv.right).abs() <= eps {
                return Ok(sol.build(&iv.profile));
            }
        }
        if sol.block.is_blocked(t_profile) || !t.is_finite() {
            return Err(unreachable);
        }
        sol.with_duration(t_profile)
            .map(|k| sol.build(&k))
            .ok_or(unreachable)
    }

    /// Total duration of the phases (s).
    #[inline]
    pub fn duration(&self) -> f64 {
        if self.count == 0 {
            0.0
        } else {
            self.ends[self.count - 1]
        }
    }

    /// The state at time `t`: `t < 0` clamps to the start; after [`Profile::duration`]
    /// the motion continues at the final velocity with acceleration 0.
    #[inline]
    pub fn at(&self, t: f64) -> State {
        let n = self.count;
        if t >= self.duration() {
            let e = self.end();
            let dt = t - self.duration();
            return State {
                p: e.p + e.v * dt,
                v: e.v,
                a: 0.0,
            };
        }
        if t < 0.0 {
            return self.start;
        }
        let mut i = 0;
        while i + 1 < n && t >= self.ends[i] {
            i += 1;
        }
        let t0 = self.ends[i] - self.phases[i].duration;
        self.starts[i].integrate(t - t0, self.phases[i].jerk)
    }

    /// The phases (constant jerk each).
    pub fn phases(&self) -> &[Phase] {
        &self.phases[..self.count]
    }

    /// The state at the start of each phase (for a trapezoidal phase, `a` is the
    /// phase's constant acceleration).
    pub fn phase_starts(&self) -> &[State] {
        &self.starts[..self.count]
    }

    /// The start state.
    pub fn start(&self) -> State {
        self.start
    }

    /// The end state (acceleration 0).
    pub fn end(&self) -> State {
        let e = self.starts[self.count];
        State {
            p: e.p,
            v: e.v,
            a: 0.0,
        }
    }
}

thread_local! {
    static STEP1: std::cell::RefCell<kernel::pos3::PositionThirdOrderStep1> =
        std::cell::RefCell::new(kernel::pos3::PositionThirdOrderStep1::default());
}

/// A position problem solved by the kernel in a frame where the move goes towards +p
/// (so that `amax` bounds the acceleration in the direction of travel, `dmax` the
/// deceleration): brake pre-phase and step-1 block.
struct Solved {
    start: State,
    /// +1 or -1: the frame's direction.
    s: f64,
    trapezoidal: bool,
    /// Frame limits: v in [-vmax, vmax], a in [a_min, a_max], |j| <= jmax.
    vmax: f64,
    a_max: f64,
    a_min: f64,
    jmax: f64,
    /// Frame target.
    pf: f64,
    vf: f64,
    brake: kernel::brake::BrakeProfile,
    /// State after the brake pre-phase (frame).
    after_brake: (f64, f64, f64),
    block: kernel::Block,
}

impl Solved {
    fn new(start: State, target_p: f64, target_v: f64, lim: &Limits) -> Option<Solved> {
        let s = if target_p >= start.p { 1.0 } else { -1.0 };
        let trapezoidal = lim.is_trapezoidal();
        let (p0, v0, a0) = (s * start.p, s * start.v, s * start.a);
        let (pf, vf) = (s * target_p, s * target_v);
        let (vmax, a_max, a_min, jmax) = (lim.vmax, lim.amax, -lim.dmax, lim.jmax);
        let mut brake = kernel::brake::BrakeProfile::new();
        let (mut ps, mut vs, mut as_) = (p0, v0, a0);
        let mut input = kernel::kprofile::Profile::default();
        let mut block = kernel::Block::default();
        let found = if trapezoidal {
            brake.get_second_order_position_brake_trajectory(v0, vmax, -vmax, a_max, a_min);
            brake.finalize_second_order(&mut ps, &mut vs, &mut as_);
            as_ = 0.0;
            input.set_boundary(ps, vs, 0.0, pf, vf, 0.0);
            kernel::pos2::PositionSecondOrderStep1::new(ps, vs, pf, vf, vmax, -vmax, a_max, a_min)
                .get_profile(&input, &mut block)
        } else {
            brake.get_position_brake_trajectory(v0, a0, vmax, -vmax, a_max, a_min, jmax);
            brake.finalize(&mut ps, &mut vs, &mut as_);
            input.set_boundary(ps, vs, as_, pf, vf, 0.0);
            // The solver's candidate buffer is reused per thread (no re-zeroing).
            STEP1.with(|cell| {
                let mut step1 = cell.borrow_mut();
                step1.reset(ps, vs, as_, pf, vf, 0.0, vmax, -vmax, a_max, a_min, jmax);
                step1.get_profile(&input, &mut block)
            })
        };
        found.then_some(Solved {
            start,
            s,
            trapezoidal,
            vmax,
            a_max,
            a_min,
            jmax,
            pf,
            vf,
            brake,
            after_brake: (ps, vs, as_),
            block,
        })
    }

    /// Step 2: a kernel profile of duration `tf` (after the brake pre-phase).
    fn with_duration(&self, tf: f64) -> Option<kernel::kprofile::Profile> {
        let (ps, vs, as_) = self.after_brake;
        let mut k = kernel::kprofile::Profile::default();
        k.set_boundary(ps, vs, as_, self.pf, self.vf, 0.0);
        let found = if self.trapezoidal {
            kernel::pos2_duration::PositionSecondOrderStep2::new(
                tf, ps, vs, self.pf, self.vf, self.vmax, -self.vmax, self.a_max, self.a_min,
            )
            .get_profile(&mut k)
        } else {
            kernel::pos3_duration::PositionThirdOrderStep2::new(
                tf, ps, vs, as_, self.pf, self.vf, 0.0, self.vmax, -self.vmax, self.a_max,
                self.a_min, self.jmax,
            )
            .get_profile(&mut k)
        };
        found.then_some(k)
    }

    /// The public profile: brake pre-phase then the kernel profile `k`, mirrored back.
    fn build(&self, k: &kernel::kprofile::Profile) -> Profile {
        let s = self.s;
        let mut prof = Profile::new(self.start);
        if self.trapezoidal {
            prof.push_accel(self.brake.t[0], s * self.brake.a[0]);
            for i in 0..7 {
                prof.push_accel(k.t[i], s * k.a[i]);
            }
        } else {
            for i in 0..2 {
                prof.push_jerk(self.brake.t[i], s * self.brake.j[i]);
            }
            for i in 0..7 {
                prof.push_jerk(k.t[i], s * k.j[i]);
            }
        }
        prof
    }
}

fn check_inputs(
    start: &State,
    target_p: f64,
    target_v: f64,
    lim: &Limits,
) -> Result<(), PlanError> {
    lim.validate()?;
    if !(start.p.is_finite() && start.v.is_finite() && start.a.is_finite()) {
        return Err(PlanError::InvalidState);
    }
    if !(target_p.is_finite() && target_v.is_finite() && target_v.abs() <= lim.vmax) {
        return Err(PlanError::InvalidTarget { vmax: lim.vmax });
    }
    Ok(())
}
