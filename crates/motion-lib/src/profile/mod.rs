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
        velocity::position_simple(start, target_p, target_v, lim)
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
    pub fn with_duration(
        start: State,
        target_p: f64,
        target_v: f64,
        lim: &Limits,
        t: f64,
    ) -> Result<Profile, PlanError> {
        let fastest = Profile::position(start, target_p, target_v, lim)?;
        let minimal = fastest.duration();
        if t.is_nan() || t < minimal * (1.0 - 1e-12) - 1e-12 {
            return Err(PlanError::DurationTooShort {
                requested: t,
                minimal,
            });
        }
        if t <= minimal * (1.0 + 1e-12) + 1e-12 {
            return Ok(fastest);
        }
        velocity::with_duration_simple(start, target_p, target_v, lim, t).ok_or(
            PlanError::DurationUnreachable {
                requested: t,
                minimal,
            },
        )
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
        if t <= 0.0 {
            return self.starts[0];
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
        self.starts[0]
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
