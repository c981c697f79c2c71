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
//! generation with arbitrary target states", RSS 2021): closed-form fast paths
//! (`velocity`: cruise at vmax, short rest-to-rest moves) and otherwise the enumeration
//! of every profile family (`kernel`, adapted from rsruckig). See `README_profile.md`.

mod jsonl;
mod kernel;
pub mod line;
// The planners' results written once into a slot (safe code).
mod slot;
mod velocity;

pub use jsonl::plan_jsonl;

use thiserror::Error;

/// Most phases a profile can hold: 2 brake phases + 7 profile phases.
pub const MAX_PHASES: usize = 9;

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
    /// Largest |velocity|, u/s (finite, > 0).
    pub vmax: f64,
    /// Largest acceleration in the direction of travel, u/s² (finite, > 0).
    pub amax: f64,
    /// Largest deceleration against the direction of travel, u/s² (finite, > 0).
    pub dmax: f64,
    /// Largest |jerk|, u/s³ (0 or infinite: no jerk limit, trapezoidal profiles).
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
        if self.is_valid() {
            Ok(())
        } else {
            Err(PlanError::InvalidLimits)
        }
    }

    /// [`Limits::validate`] as a bool (comparisons are false for NaN). Floating-point
    /// arithmetic, no branches: one sum of [`zero_if_finite`] tells whether all three are
    /// finite.
    #[inline(always)]
    pub(crate) fn is_valid(&self) -> bool {
        let (v, a, d) = (self.vmax, self.amax, self.dmax);
        (zero_if_finite(v) + zero_if_finite(a) + zero_if_finite(d) == 0.0)
            & (v > 0.0)
            & (a > 0.0)
            & (d > 0.0)
            & (self.jmax >= 0.0)
    }
}

/// Kinematic state of one axis: position, velocity, acceleration.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct State {
    /// Position, u.
    pub p: f64,
    /// Velocity, u/s.
    pub v: f64,
    /// Acceleration, u/s².
    pub a: f64,
}

impl State {
    /// The state after `t` seconds of constant `jerk` from `self`.
    #[inline]
    pub fn integrate(&self, t: f64, jerk: f64) -> State {
        State {
            p: self.p + t * (self.v + t * (0.5 * self.a + t * jerk * (1.0 / 6.0))),
            v: self.v + t * (self.a + 0.5 * t * jerk),
            a: self.a + t * jerk,
        }
    }
}

/// One phase of a profile: `duration` seconds of constant `jerk`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Phase {
    /// Length of the phase, s (>= 0).
    pub duration: f64,
    /// Constant jerk during the phase, u/s³ (signed).
    pub jerk: f64,
}

/// Why a profile could not be planned.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum PlanError {
    /// A limit is not finite and positive (`jmax`: negative or NaN); see [`Limits::validate`].
    #[error("invalid limits: vmax, amax and dmax must be finite and > 0, jmax >= 0 (0 or infinite = trapezoidal)")]
    InvalidLimits,
    /// The start position, velocity or acceleration is not finite.
    #[error("invalid start state: position, velocity and acceleration must be finite")]
    InvalidState,
    #[error("invalid target: the position must be finite and the velocity finite with |v| <= vmax ({vmax})")]
    /// The target position is not finite, or the target velocity is not finite or above `vmax`.
    InvalidTarget {
        /// The velocity limit the target velocity was checked against, u/s.
        vmax: f64,
    },
    #[error("requested duration {requested} s is shorter than the minimal duration {minimal} s")]
    /// [`Profile::with_duration`] was asked for less than the time-optimal duration.
    DurationTooShort {
        /// The duration asked for, s.
        requested: f64,
        /// The shortest duration the limits allow, s.
        minimal: f64,
    },
    #[error(
        "no profile reaches the target in exactly {requested} s (minimal duration {minimal} s)"
    )]
    /// [`Profile::with_duration`]: no profile takes exactly that long (a blocked interval).
    DurationUnreachable {
        /// The duration asked for, s.
        requested: f64,
        /// The shortest duration the limits allow, s.
        minimal: f64,
    },
    /// A straight line in N axes could not be planned (the message says why).
    #[error("line: {0}")]
    Line(String),
    /// No profile family gave a valid profile (a numerical failure of the planner).
    #[error("no valid profile found (numerical failure) for start {start:?}, target p = {target_p}, v = {target_v}")]
    NoSolution {
        /// The start state given to the planner.
        start: State,
        /// The target position, u.
        target_p: f64,
        /// The target velocity, u/s.
        target_v: f64,
    },
}

/// A planned motion: the start state, phases of constant jerk, then constant velocity.
///
/// Equality compares the plan (start, phases, their start states, end), not the
/// sampling cursor.
#[derive(Clone, Copy, Debug)]
#[repr(C)]
pub struct Profile {
    /// The piece last sampled by [`Profile::at_next`] (first, with the total duration:
    /// the cycle's sampling touches one cache line of the profile).
    cursor: Cursor,
    /// Total duration.
    total: f64,
    count: usize,
    /// Time at the end of each phase.
    ends: [f64; MAX_PHASES],
    /// State at the start of each phase. For a trapezoidal phase `starts[i].a` is the
    /// phase's constant acceleration.
    starts: [State; MAX_PHASES],
    phases: [Phase; MAX_PHASES],
    start: State,
    /// State at the end of the last phase.
    last: State,
}

/// One piece of a profile for sampling: times `[lo, hi)`, the state at `lo` and the
/// jerk. Only ever copied from the profile's own phases (or its constant-velocity end),
/// so it is valid for every copy of the profile; an empty interval means "look up".
#[derive(Clone, Copy, Debug, Default)]
#[repr(C)]
struct Cursor {
    lo: f64,
    hi: f64,
    at: State,
    jerk: f64,
}

impl PartialEq for Profile {
    fn eq(&self, o: &Profile) -> bool {
        let n = self.count;
        n == o.count
            && self.total == o.total
            && self.start == o.start
            && self.last == o.last
            && self.phases[..n] == o.phases[..n]
            && self.starts[..n] == o.starts[..n]
            && self.ends[..n] == o.ends[..n]
    }
}

impl Profile {
    /// An empty profile standing at `start` (duration 0).
    #[inline]
    pub(crate) fn new(start: State) -> Profile {
        Profile {
            cursor: Cursor::default(),
            total: 0.0,
            count: 0,
            ends: [0.0; MAX_PHASES],
            starts: [State::default(); MAX_PHASES],
            phases: [Phase::default(); MAX_PHASES],
            start,
            last: start,
        }
    }

    /// [`Profile::at`] for a caller that samples forward in time (one interpolation
    /// cycle after the other): the piece containing `t` is kept in the profile's cursor,
    /// so that a sample inside the same piece reads one cache line and does no search.
    /// Gives the same state as `at(t)`.
    #[inline]
    pub(crate) fn at_next(&mut self, t: f64) -> State {
        let c = &self.cursor;
        if t >= c.lo && t < c.hi {
            return c.at.integrate(t - c.lo, c.jerk);
        }
        self.at_and_seek(t)
    }

    /// The slow path of [`Profile::at_next`]: `at(t)`, and the cursor moved to the piece
    /// containing `t` (a phase, or the constant-velocity continuation after the end).
    #[inline(never)]
    fn at_and_seek(&mut self, t: f64) -> State {
        let s = self.at(t);
        if t >= self.total {
            let e = self.end();
            self.cursor = Cursor {
                lo: self.total,
                hi: f64::INFINITY,
                at: State {
                    p: e.p,
                    v: e.v,
                    a: 0.0,
                },
                jerk: 0.0,
            };
        } else if t >= 0.0 {
            let i = self.phase_index(t);
            self.cursor = Cursor {
                lo: if i == 0 { 0.0 } else { self.ends[i - 1] },
                hi: self.ends[i],
                at: self.starts[i],
                jerk: self.phases[i].jerk,
            };
        }
        s
    }

    /// Index of the phase containing `t` (0 <= `t` < duration).
    #[inline]
    fn phase_index(&self, t: f64) -> usize {
        let n = self.count;
        let mut i = 0;
        while i + 1 < n && t >= self.ends[i] {
            i += 1;
        }
        i
    }

    /// The profile of `items` = (duration, jerk) from `start` (or (duration,
    /// acceleration) when `trapezoidal`); items of zero or negative duration are skipped.
    /// `snap` = (k, v): the state before item k is snapped to velocity v, acceleration 0
    /// (the start of a cruise, removing rounding).
    #[inline(always)]
    pub(crate) fn build(
        start: State,
        items: &[(f64, f64)],
        trapezoidal: bool,
        snap: Option<(usize, f64)>,
    ) -> Profile {
        let mut prof = Profile::new(start);
        prof.fill(start, items, trapezoidal, snap);
        prof
    }

    /// [`Profile::build`] in place: `self` must be `Profile::new(start)` (entries past the
    /// phase count stay zero, so that equal plans compare equal), `start` passed again.
    #[inline(always)]
    fn fill(
        &mut self,
        start: State,
        items: &[(f64, f64)],
        trapezoidal: bool,
        snap: Option<(usize, f64)>,
    ) {
        // The running state is kept in scalar locals (registers), starting from the `start`
        // argument: the profile is only written, never read back. (Reading `self.start`
        // right after `Profile::new` stored it is a load spanning two stores, which cannot
        // be forwarded and stalls the whole integration until the stores reach the cache.)
        let (mut p, mut v, mut a) = (start.p, start.v, start.a);
        let mut total = 0.0;
        let mut n = 0;
        for (k, &(duration, x)) in items.iter().enumerate() {
            if let Some((ks, vs)) = snap {
                if ks == k {
                    v = vs;
                    a = 0.0;
                }
            }
            if duration.is_nan() || duration <= 0.0 || n == MAX_PHASES {
                continue;
            }
            let jerk = if trapezoidal {
                a = x;
                0.0
            } else {
                x
            };
            self.phases[n] = Phase { duration, jerk };
            self.starts[n] = State { p, v, a };
            let t = duration;
            p += t * (v + t * (0.5 * a + t * jerk * (1.0 / 6.0)));
            v += t * (a + 0.5 * t * jerk);
            a = if trapezoidal { 0.0 } else { a + t * jerk };
            total += duration;
            self.ends[n] = total;
            n += 1;
        }
        self.count = n;
        self.last = State { p, v, a };
        self.total = total;
    }

    /// A fast path's profile: seven jerk phases to the target (`target_p`, `target_v`,
    /// acceleration 0), the fourth a cruise at velocity `fast.v_peak` from
    /// `start.p + fast.d_cruise` to `target_p - fast.d_decel`. Built as one value, the
    /// seven phases in the first seven slots (so that it is written straight into its
    /// destination, without zeroing it first); `true` when every phase has a positive
    /// duration, else the empty ones must be removed with [`Profile::compact`].
    ///
    /// No phase start waits for more than one integration step: the states at the start
    /// and the end of the cruise and at the end are known, the phase after each of the
    /// start and the cruise's end is integrated forward from it, the phase before the
    /// cruise and the last phase backward from the state they reach (the profile of a
    /// sampled cycle is the same to rounding; the end state is the target exactly). One
    /// chain of seven integrations made the plan wait about 50 cycles for it. The phase
    /// end times are summed in order.
    #[inline(always)]
    fn fast(start: State, fast: &velocity::Fast, target_p: f64, target_v: f64) -> (Profile, bool) {
        let items = &fast.items;
        let kept = items.map(|(d, _)| if d > 0.0 { d } else { 0.0 });
        let jerk = items.map(|(_, j)| j);
        let cruise = State {
            p: start.p + fast.d_cruise,
            v: fast.v_peak,
            a: 0.0,
        };
        let decel = State {
            p: target_p - fast.d_decel,
            v: fast.v_peak,
            a: 0.0,
        };
        let end = State {
            p: target_p,
            v: target_v,
            a: 0.0,
        };
        let e0 = kept[0];
        let e1 = e0 + kept[1];
        let e2 = e1 + kept[2];
        let e3 = e2 + kept[3];
        let e4 = e3 + kept[4];
        let e5 = e4 + kept[5];
        let e6 = e5 + kept[6];
        let ph = |k: usize| Phase {
            duration: kept[k],
            jerk: jerk[k],
        };
        let all = (kept[0] > 0.0)
            & (kept[1] > 0.0)
            & (kept[2] > 0.0)
            & (kept[3] > 0.0)
            & (kept[4] > 0.0)
            & (kept[5] > 0.0)
            & (kept[6] > 0.0);
        let none = State::default();
        let prof = Profile {
            cursor: Cursor::default(),
            total: e6,
            count: 7,
            ends: [e0, e1, e2, e3, e4, e5, e6, 0.0, 0.0],
            starts: [
                start,
                start.integrate(kept[0], jerk[0]),
                cruise.integrate(-kept[2], jerk[2]),
                cruise,
                decel,
                decel.integrate(kept[4], jerk[4]),
                end.integrate(-kept[6], jerk[6]),
                none,
                none,
            ],
            phases: [
                ph(0),
                ph(1),
                ph(2),
                ph(3),
                ph(4),
                ph(5),
                ph(6),
                Phase::default(),
                Phase::default(),
            ],
            start,
            last: end,
        };
        (prof, all)
    }

    /// Removes the phases of zero duration (moving the others down, clearing the slots
    /// freed): the profile [`Profile::fast`] leaves when not every phase is needed.
    #[inline(never)]
    fn compact(&mut self) {
        let count = self.count;
        let mut n = 0;
        for k in 0..count {
            if self.phases[k].duration > 0.0 {
                self.phases[n] = self.phases[k];
                self.starts[n] = self.starts[k];
                self.ends[n] = self.ends[k];
                n += 1;
            }
        }
        for k in n..count {
            self.phases[k] = Phase::default();
            self.starts[k] = State::default();
            self.ends[k] = 0.0;
        }
        self.count = n;
    }

    /// Time-optimal profile from `start` to position `target_p` with velocity `target_v`
    /// and acceleration 0.
    #[inline]
    pub fn position(
        start: State,
        target_p: f64,
        target_v: f64,
        lim: &Limits,
    ) -> Result<Profile, PlanError> {
        slot::in_place(|out| Self::position_into(out, start, target_p, target_v, lim))
    }

    /// [`Profile::position`] written once into `out`, a slot the caller keeps and may reuse
    /// from plan to plan (its previous value is dropped); returns the result in the slot.
    /// This is the form for hot loops: the 552-byte result is not copied after it is built.
    #[inline(always)]
    pub fn position_into<'a>(
        out: &'a mut Option<Result<Profile, PlanError>>,
        start: State,
        target_p: f64,
        target_v: f64,
        lim: &Limits,
    ) -> &'a mut Result<Profile, PlanError> {
        if let Err(e) = check_inputs(&start, target_p, target_v, lim) {
            return out.insert(Err(e));
        }
        match velocity::fast_path(start, target_p, target_v, lim) {
            Some(fast) => {
                let (prof, all) = Profile::fast(start, &fast, target_p, target_v);
                let r = out.insert(Ok(prof));
                if !all {
                    if let Ok(p) = r {
                        p.compact();
                    }
                }
                r
            }
            None => out.insert(Self::position_kernel(start, target_p, target_v, lim)),
        }
    }

    /// The kernel's enumeration of every profile family (no fast path applies). Kept out
    /// of [`Profile::position`]: its large locals would otherwise make the fast path's
    /// stack frame about 4 KiB, where the copy of the result into the caller's slot then
    /// suffers 4 KiB aliasing between loads and stores.
    #[inline(never)]
    fn position_kernel(
        start: State,
        target_p: f64,
        target_v: f64,
        lim: &Limits,
    ) -> Result<Profile, PlanError> {
        let mut block = kernel::Block::default();
        match Solved::new(start, target_p, target_v, lim, 0.0, &mut block) {
            Some(sol) => Ok(sol.build(&block.p_min)),
            None => Self::position_relative(start, target_p, target_v, lim).or_else(|_| {
                Self::position_after_zero_acceleration(start, target_p, target_v, lim)
            }),
        }
    }

    /// Fallback for a start far from the origin (|p| around 1e11 and beyond with long moves,
    /// `tests/data/ruckig-unseen.jsonl`'s `decades` kind): the kernel's root checks lose the
    /// digits they need in absolute positions (and the fast paths are not tried), so the same
    /// problem is solved with the start at 0 and the phases are replayed from the real start.
    #[inline(never)]
    fn position_relative(
        start: State,
        target_p: f64,
        target_v: f64,
        lim: &Limits,
    ) -> Result<Profile, PlanError> {
        let no_solution = PlanError::NoSolution {
            start,
            target_p,
            target_v,
        };
        if start.p == 0.0 {
            return Err(no_solution);
        }
        let rel = State { p: 0.0, ..start };
        let dist = target_p - start.p;
        // The end position to 16 ulps of the largest term of the kernel's integration, or
        // 1e-8 if coarser: beyond a scale of about 1e6 ruckig's absolute 1e-8 is finer than
        // the rounding of that sum.
        let p_tol = 16.0 * f64::EPSILON;
        let mut block = kernel::Block::default();
        let tolerant = Solved::new(rel, dist, target_v, lim, p_tol, &mut block)
            .map(|sol| sol.build(&block.p_min));
        // (With the start at 0 this fallback is not taken again.)
        let prof = match tolerant {
            Some(prof) => prof,
            None => Self::position(rel, dist, target_v, lim).map_err(|_| no_solution.clone())?,
        };
        let n = prof.phases().len();
        let mut items = [(0.0, 0.0); MAX_PHASES];
        for (k, ph) in prof.phases().iter().enumerate() {
            items[k] = (ph.duration, ph.jerk);
        }
        Ok(Profile::build(start, &items[..n], false, None))
    }

    /// Fallback for the rare start states where the kernel finds no profile (inherited from
    /// ruckig's numerics, e.g. the last cycles of a braking ramp): ramp the acceleration to zero
    /// at full jerk, then plan from there. The result is valid and within the limits, but may be
    /// slightly slower than the time optimum.
    fn position_after_zero_acceleration(
        start: State,
        target_p: f64,
        target_v: f64,
        lim: &Limits,
    ) -> Result<Profile, PlanError> {
        let no_solution = PlanError::NoSolution {
            start,
            target_p,
            target_v,
        };
        if start.a == 0.0 || lim.is_trapezoidal() {
            return Err(no_solution);
        }
        let t0 = start.a.abs() / lim.jmax;
        let jerk = -start.a.signum() * lim.jmax;
        let mut mid = start.integrate(t0, jerk);
        mid.a = 0.0;
        // `amax` bounds the acceleration towards the target as seen from the start. When the
        // ramp carries the axis past the target, the rest is a move the other way, whose
        // `amax` would bound the opposite sign: swap the two so that the bounds stay those of
        // the problem (else the rest may brake at up to `amax` where `dmax` applies).
        let forward = target_p >= start.p;
        let sub = if (target_p >= mid.p) == forward {
            *lim
        } else {
            Limits {
                amax: lim.dmax,
                dmax: lim.amax,
                ..*lim
            }
        };
        let rest =
            Self::position(mid, target_p, target_v, &sub).map_err(|_| no_solution.clone())?;
        if rest.phases().len() + 1 > MAX_PHASES {
            return Err(no_solution);
        }
        let mut items = [(0.0, 0.0); MAX_PHASES];
        items[0] = (t0, jerk);
        for (k, ph) in rest.phases().iter().enumerate() {
            items[k + 1] = (ph.duration, ph.jerk);
        }
        Ok(Profile::build(
            start,
            &items[..rest.phases().len() + 1],
            false,
            None,
        ))
    }

    /// Time-optimal profile from `start` to velocity `target_v` with acceleration 0
    /// (MoveVelocity; Halt/Stop with `target_v = 0`). The position is free.
    pub fn velocity(start: State, target_v: f64, lim: &Limits) -> Result<Profile, PlanError> {
        check_inputs(&start, 0.0, target_v, lim)?;
        Ok(velocity::velocity_change(start, target_v, lim))
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
        let mut block = kernel::Block::default();
        let sol = Solved::new(start, target_p, target_v, lim, 0.0, &mut block).ok_or(
            PlanError::NoSolution {
                start,
                target_p,
                target_v,
            },
        )?;
        let fastest = match velocity::fast_path(start, target_p, target_v, lim) {
            Some(fast) => {
                let (mut prof, all) = Profile::fast(start, &fast, target_p, target_v);
                if !all {
                    prof.compact();
                }
                prof
            }
            None => sol.build(&block.p_min),
        };
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
        for iv in [block.a, block.b].into_iter().flatten() {
            if (t_profile - iv.right).abs() <= eps {
                return Ok(sol.build(&iv.profile));
            }
        }
        if block.is_blocked(t_profile) || !t.is_finite() {
            return Err(unreachable);
        }
        sol.with_duration(t_profile)
            .map(|k| sol.build(&k))
            .ok_or(unreachable)
    }

    /// Total duration of the phases (s).
    #[inline]
    pub fn duration(&self) -> f64 {
        self.total
    }

    /// The state at time `t`: `t < 0` clamps to the start; after [`Profile::duration`]
    /// the motion continues at the final velocity with acceleration 0.
    #[inline]
    pub fn at(&self, t: f64) -> State {
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
        let i = self.phase_index(t);
        let t0 = if i == 0 { 0.0 } else { self.ends[i - 1] };
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
        let e = self.last;
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
}

impl Solved {
    /// Solves the problem; the step-1 result goes to `block`. `p_tol`: the kernel's relative
    /// tolerance of the end position (0: ruckig's absolute 1e-8; see `kprofile::Profile::p_tol`).
    fn new(
        start: State,
        target_p: f64,
        target_v: f64,
        lim: &Limits,
        p_tol: f64,
        block: &mut kernel::Block,
    ) -> Option<Solved> {
        let s = if target_p >= start.p { 1.0 } else { -1.0 };
        let trapezoidal = lim.is_trapezoidal();
        let (p0, v0, a0) = (s * start.p, s * start.v, s * start.a);
        let (pf, vf) = (s * target_p, s * target_v);
        let (vmax, a_max, a_min, jmax) = (lim.vmax, lim.amax, -lim.dmax, lim.jmax);
        let mut brake = kernel::brake::BrakeProfile::new();
        let (mut ps, mut vs, mut as_) = (p0, v0, a0);
        let mut input = kernel::kprofile::Profile {
            p_tol,
            ..Default::default()
        };
        let found = if trapezoidal {
            brake.get_second_order_position_brake_trajectory(v0, vmax, -vmax, a_max, a_min);
            brake.finalize_second_order(&mut ps, &mut vs, &mut as_);
            as_ = 0.0;
            input.set_boundary(ps, vs, 0.0, pf, vf, 0.0);
            kernel::pos2::PositionSecondOrderStep1::new(ps, vs, pf, vf, vmax, -vmax, a_max, a_min)
                .get_profile(&input, block)
        } else {
            brake.get_position_brake_trajectory(v0, a0, vmax, -vmax, a_max, a_min, jmax);
            brake.finalize(&mut ps, &mut vs, &mut as_);
            input.set_boundary(ps, vs, as_, pf, vf, 0.0);
            // The solver's candidate buffer is reused per thread (no re-zeroing).
            STEP1.with(|cell| {
                let mut step1 = cell.borrow_mut();
                step1.reset(ps, vs, as_, pf, vf, 0.0, vmax, -vmax, a_max, a_min, jmax);
                step1.get_profile(&input, block)
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

    #[inline]
    /// The public profile: brake pre-phase then the kernel profile `k`, mirrored back.
    fn build(&self, k: &kernel::kprofile::Profile) -> Profile {
        let mut prof = Profile::new(self.start);
        self.build_into(k, &mut prof);
        prof
    }

    /// [`Solved::build`] in place: `out` must be `Profile::new(self.start)`.
    #[inline]
    fn build_into(&self, k: &kernel::kprofile::Profile, out: &mut Profile) {
        let s = self.s;
        let b = &self.brake;
        let mut items = [(0.0, 0.0); MAX_PHASES];
        if self.trapezoidal {
            items[0] = (b.t[0], s * b.a[0]);
            items[1] = (0.0, 0.0);
            for i in 0..7 {
                items[2 + i] = (k.t[i], s * k.a[i]);
            }
        } else {
            items[0] = (b.t[0], s * b.j[0]);
            items[1] = (b.t[1], s * b.j[1]);
            for i in 0..7 {
                items[2 + i] = (k.t[i], s * k.j[i]);
            }
        }
        out.fill(self.start, &items, self.trapezoidal, None);
    }
}

/// `x - x`: 0 for a finite `x`, NaN for an infinite or NaN one (a sum of these is 0
/// exactly when every term is finite: one comparison, no branch per value).
#[inline(always)]
#[allow(clippy::eq_op)]
pub(crate) fn zero_if_finite(x: f64) -> f64 {
    x - x
}

#[inline(always)]
fn check_inputs(
    start: &State,
    target_p: f64,
    target_v: f64,
    lim: &Limits,
) -> Result<(), PlanError> {
    // One test for the valid case (see `Limits::is_valid`; |target_v| <= vmax is false
    // for a NaN or infinite target_v once vmax is finite), then which error.
    let (p, v, a) = (start.p, start.v, start.a);
    let finite_state = zero_if_finite(p) + zero_if_finite(v) + zero_if_finite(a) == 0.0;
    let finite_target = zero_if_finite(target_p) == 0.0;
    if lim.is_valid() & finite_state & finite_target & (target_v.abs() <= lim.vmax) {
        return Ok(());
    }
    lim.validate()?;
    if !finite_state {
        return Err(PlanError::InvalidState);
    }
    Err(PlanError::InvalidTarget { vmax: lim.vmax })
}

#[cfg(test)]
mod cursor_tests {
    use super::*;

    /// `at_next` (the engine's per-cycle sampling through the cursor) gives `at`'s state
    /// for forward cycles, backward jumps, times past the end and before the start, on
    /// a profile and on copies of it taken mid-way (the cursor travels with the copy).
    #[test]
    fn at_next_equals_at() {
        let lim = Limits {
            vmax: 40.0,
            amax: 300.0,
            dmax: 500.0,
            jmax: 4000.0,
        };
        let starts = [
            State::default(),
            State {
                p: 3.0,
                v: -20.0,
                a: 100.0,
            },
            State {
                p: -1.0,
                v: 35.0,
                a: -200.0,
            },
        ];
        let mut other = Profile::position(State::default(), -7.0, 0.0, &lim).unwrap();
        for (k, start) in starts.iter().enumerate() {
            for target in [0.05, 2.0, 60.0, -30.0] {
                let mut prof = Profile::position(*start, target, 0.0, &lim).unwrap();
                let d = prof.duration();
                let mut times: Vec<f64> = (0..2000).map(|i| i as f64 * d * 1.3 / 1999.0).collect();
                times.extend([0.3 * d, -1.0, 0.9 * d, 2.0 * d, 0.0, d, 0.5 * d]);
                for (i, &t) in times.iter().enumerate() {
                    let want = prof.at(t);
                    let got = prof.at_next(t);
                    assert_eq!(got, want, "start {k} target {target} t {t}");
                    if i % 97 == 0 {
                        // Replace the profile by a copy of another one sampled elsewhere.
                        std::mem::swap(&mut prof, &mut other);
                        assert_eq!(prof.at_next(t), prof.at(t));
                        std::mem::swap(&mut prof, &mut other);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod fallback_tests {
    use super::*;

    /// The zero-acceleration fallback ramps a0 = 13777.9 to 0 at full jerk, which carries the
    /// axis past the target (285 ahead, moving at 9318 towards it). The rest is then a move
    /// the other way, but the bounds stay those of the problem: acceleration within
    /// [-dmax, amax] = [-46596.9, 352671.8] (before, the rest braked at up to -115,522).
    #[test]
    fn the_zero_acceleration_fallback_keeps_the_problems_acceleration_bounds() {
        let lim = Limits {
            vmax: 50114.6192,
            amax: 352671.798,
            dmax: 46596.8768,
            jmax: 185930.911,
        };
        let start = State {
            p: 326225.245,
            v: 9318.1428,
            a: 13777.9233,
        };
        let (p1, v1) = (326510.475, -45179.1836);
        let prof = Profile::position_after_zero_acceleration(start, p1, v1, &lim).unwrap();
        let d = prof.duration();
        let tol = 1e-9 * lim.amax;
        for s in prof.phase_starts().iter().chain([&prof.at(d)]) {
            assert!(s.a <= lim.amax + tol && s.a >= -lim.dmax - tol, "{s:?}");
        }
        let end = prof.at(d);
        assert!(
            (end.p - p1).abs() < 1e-6 && (end.v - v1).abs() < 1e-6,
            "{end:?}"
        );
        // The fallback is not time-optimal (ruckig 0.19.4: 2.5167 s), but close.
        assert!(d > 2.5167134 && d < 2.7, "{d}");
    }
}

#[cfg(test)]
mod check_tests {
    use super::*;

    /// The branch-free input check gives the error of the first bad input class (limits,
    /// then start state, then target) for every field set to +-infinity or NaN, and
    /// accepts the valid problem (jmax infinite or 0 included).
    #[test]
    fn every_non_finite_input_gives_its_error() {
        let good = Limits {
            vmax: 2.0,
            amax: 3.0,
            dmax: 4.0,
            jmax: 5.0,
        };
        let st = State {
            p: 1.0,
            v: 0.5,
            a: -0.5,
        };
        assert_eq!(check_inputs(&st, 3.0, 1.0, &good), Ok(()));
        for jmax in [0.0, f64::INFINITY] {
            assert_eq!(
                check_inputs(&st, 3.0, 1.0, &Limits { jmax, ..good }),
                Ok(())
            );
        }
        for x in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
            for lim in [
                Limits { vmax: x, ..good },
                Limits { amax: x, ..good },
                Limits { dmax: x, ..good },
            ] {
                // A bad start and target too: the limits' error comes first.
                let bad_start = State { p: x, ..st };
                assert_eq!(
                    check_inputs(&bad_start, x, x, &lim),
                    Err(PlanError::InvalidLimits)
                );
            }
            // jmax: +infinity is valid (no jerk limit), -infinity and NaN are not.
            if x != f64::INFINITY {
                let lim = Limits { jmax: x, ..good };
                assert_eq!(
                    check_inputs(&st, 3.0, 1.0, &lim),
                    Err(PlanError::InvalidLimits)
                );
            }
            for bad in [
                State { p: x, ..st },
                State { v: x, ..st },
                State { a: x, ..st },
            ] {
                assert_eq!(
                    check_inputs(&bad, x, x, &good),
                    Err(PlanError::InvalidState)
                );
            }
            for (p1, v1) in [(x, 1.0), (3.0, x)] {
                assert_eq!(
                    check_inputs(&st, p1, v1, &good),
                    Err(PlanError::InvalidTarget { vmax: 2.0 })
                );
            }
        }
        assert_eq!(
            check_inputs(&st, 3.0, -2.5, &good),
            Err(PlanError::InvalidTarget { vmax: 2.0 })
        );
        assert_eq!(
            check_inputs(&st, 3.0, 0.0, &Limits { vmax: 0.0, ..good }),
            Err(PlanError::InvalidLimits)
        );
    }
}

#[cfg(test)]
mod fast_fill_tests {
    use super::*;

    /// A fast path's profile, whose phase starts are anchored at the start, the cruise's
    /// two ends and the target: it ends exactly at the target, and each phase integrated
    /// over its duration reaches the next phase's start (to rounding), for rest-to-rest
    /// moves (cruising or not) and moves that cruise from a moving start.
    #[test]
    fn fast_profiles_end_at_the_target_and_are_continuous() {
        let lim = Limits {
            vmax: 40.0,
            amax: 300.0,
            dmax: 500.0,
            jmax: 4000.0,
        };
        let sym = Limits { dmax: 300.0, ..lim };
        let mut cases = vec![];
        for (p0, p1) in [(0.0, 100.0), (3.0, -250.0), (1e4, 1e4 + 0.01), (-7.0, -5.0)] {
            cases.push((
                State {
                    p: p0,
                    v: 0.0,
                    a: 0.0,
                },
                p1,
                0.0,
                sym,
            ));
        }
        cases.push((
            State {
                p: 0.0,
                v: 0.0,
                a: 0.0,
            },
            500.0,
            0.0,
            lim,
        ));
        cases.push((
            State {
                p: 2.0,
                v: 12.0,
                a: 100.0,
            },
            300.0,
            20.0,
            lim,
        ));
        cases.push((
            State {
                p: -2.0,
                v: 39.0,
                a: -250.0,
            },
            -400.0,
            -5.0,
            lim,
        ));
        cases.push((
            State {
                p: 5.0,
                v: -30.0,
                a: 0.0,
            },
            900.0,
            40.0,
            lim,
        ));
        for (start, p1, v1, lim) in cases {
            let fast = velocity::fast_path(start, p1, v1, &lim);
            assert!(fast.is_some(), "{start:?} -> {p1}: no fast path");
            let prof = Profile::position(start, p1, v1, &lim).unwrap();
            assert_eq!(
                prof.end(),
                State {
                    p: p1,
                    v: v1,
                    a: 0.0
                },
                "{start:?} -> {p1}"
            );
            let (ph, st) = (prof.phases(), prof.phase_starts());
            assert_eq!(st[0], start);
            let scale = p1.abs().max(start.p.abs()).max(1.0);
            for i in 0..ph.len() {
                let reached = st[i].integrate(ph[i].duration, ph[i].jerk);
                let next = if i + 1 < ph.len() {
                    st[i + 1]
                } else {
                    prof.end()
                };
                assert!(
                    (reached.p - next.p).abs() <= 1e-12 * scale
                        && (reached.v - next.v).abs() <= 1e-9 * lim.vmax
                        && (reached.a - next.a).abs() <= 1e-9 * lim.amax,
                    "{start:?} -> {p1}: phase {i} reaches {reached:?}, next {next:?}"
                );
            }
        }
    }

    /// The phases of zero duration of a fast path's profile are removed: the others are
    /// those of the generic build from the same items (durations and jerks exactly,
    /// phase starts to rounding), and the freed slots are cleared (so that equal plans
    /// compare equal and print alike).
    #[test]
    fn empty_phases_are_removed_and_their_slots_cleared() {
        let lim = Limits {
            vmax: 40.0,
            amax: 300.0,
            dmax: 300.0,
            jmax: 4000.0,
        };
        // Short rest-to-rest moves (triangular ramps, no cruise: 4 phases), one with
        // trapezoidal ramps and no cruise (6), and a cruise from a start at vmax (4).
        let cases = [
            (State::default(), 0.01, 0.0),
            (
                State {
                    p: 1.0,
                    ..State::default()
                },
                -2.0,
                0.0,
            ),
            (State::default(), 6.0, 0.0),
            (
                State {
                    p: 0.0,
                    v: 40.0,
                    a: 0.0,
                },
                300.0,
                0.0,
            ),
        ];
        for (start, p1, v1) in cases {
            let fast = velocity::fast_path(start, p1, v1, &lim).expect("fast path");
            let prof = Profile::position(start, p1, v1, &lim).unwrap();
            let n = prof.phases().len();
            assert!(n < 7, "{start:?} -> {p1}: {n} phases");
            let items: Vec<(f64, f64)> = fast.items.to_vec();
            let generic = Profile::build(start, &items, false, None);
            assert_eq!(prof.phases(), generic.phases(), "{start:?} -> {p1}");
            for (a, b) in prof.phase_starts().iter().zip(generic.phase_starts()) {
                assert!(
                    (a.p - b.p).abs() <= 1e-12 * (1.0 + p1.abs())
                        && (a.v - b.v).abs() <= 1e-12 * lim.vmax
                        && (a.a - b.a).abs() <= 1e-12 * lim.amax,
                    "{a:?} vs {b:?}"
                );
            }
            assert!(prof.ends[..n]
                .iter()
                .zip(&generic.ends[..n])
                .all(|(a, b)| a == b));
            assert!(prof.phases[n..].iter().all(|ph| *ph == Phase::default()));
            assert!(prof.starts[n..].iter().all(|st| *st == State::default()));
            assert!(prof.ends[n..].iter().all(|e| *e == 0.0));
        }
    }
}
