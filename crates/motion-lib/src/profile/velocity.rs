//! Closed-form velocity changes and the "change, cruise, change" family of profiles.
//!
//! Input: a start velocity/acceleration, a target velocity (reached with acceleration 0),
//! acceleration bounds `[-a_lo, a_hi]` and a jerk bound. Output: at most 3 phases of
//! constant jerk (or of constant acceleration when the profile is trapezoidal).
//! Invariant: the change is time-optimal for a free end position (ruckig's third-order
//! velocity interface with target acceleration 0), acceleration never leaves
//! `[-a_lo, a_hi]` except to come back from a start acceleration beyond it.

use super::{Limits, PlanError, Profile, State};

/// A phase in the planning frame: duration, and jerk (or acceleration when trapezoidal).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Piece {
    pub t: f64,
    pub x: f64,
}

/// Up to 3 pieces of one velocity change, plus its duration and distance.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Change {
    pub pieces: [Piece; 3],
    pub n: usize,
    pub time: f64,
    pub dist: f64,
    /// Velocity and acceleration reached (the target velocity, acceleration 0).
    pub v_end: f64,
}

impl Change {
    fn push(&mut self, t: f64, x: f64) {
        if t > 0.0 {
            self.pieces[self.n] = Piece { t, x };
            self.n += 1;
        }
    }
}

/// Time-optimal change from (`v0`, `a0`) to (`vt`, 0) with a in `[-a_lo, a_hi]`, |jerk| <= `j`
/// (`j` infinite: trapezoidal, `a0` ignored).
pub(crate) fn change(v0: f64, a0: f64, vt: f64, a_hi: f64, a_lo: f64, j: f64) -> Change {
    let mut c = Change::default();
    if j.is_infinite() {
        if vt > v0 {
            c.push((vt - v0) / a_hi, a_hi);
        } else if vt < v0 {
            c.push((v0 - vt) / a_lo, -a_lo);
        }
        let dv = vt - v0;
        c.time = c.pieces[..c.n].iter().map(|p| p.t).sum();
        c.dist = if c.n == 0 {
            0.0
        } else {
            (v0 + dv / 2.0) * c.time
        };
        c.v_end = vt;
        return c;
    }
    let v_zero = v0 + a0 * a0.abs() / (2.0 * j);
    let (s, v0m, a0m, vtm, hi) = if vt >= v_zero {
        (1.0, v0, a0, vt, a_hi)
    } else {
        (-1.0, -v0, -a0, -vt, a_lo)
    };
    // Upward change in the mirrored frame.
    if a0m > hi {
        let vz = v0m + a0m * a0m / (2.0 * j);
        c.push((a0m - hi) / j, -s * j);
        c.push(((vtm - vz) / hi).max(0.0), 0.0);
        c.push(hi / j, -s * j);
    } else {
        let ap = (j * (vtm - v0m) + a0m * a0m / 2.0).max(0.0).sqrt();
        if ap <= hi {
            c.push((ap - a0m).max(0.0) / j, s * j);
            c.push(ap / j, -s * j);
        } else {
            c.push((hi - a0m) / j, s * j);
            c.push(
                ((vtm - v0m - (2.0 * hi * hi - a0m * a0m) / (2.0 * j)) / hi).max(0.0),
                0.0,
            );
            c.push(hi / j, -s * j);
        }
    }
    let mut st = State {
        p: 0.0,
        v: v0,
        a: a0,
    };
    for p in &c.pieces[..c.n] {
        st = st.integrate(p.t, p.x);
        c.time += p.t;
    }
    c.dist = st.p;
    c.v_end = vt;
    c
}

/// Jerk bound used by the planners: infinite for trapezoidal limits.
pub(crate) fn jerk_bound(lim: &Limits) -> f64 {
    if lim.is_trapezoidal() {
        f64::INFINITY
    } else {
        lim.jmax
    }
}

/// Appends the pieces (planned in a frame mirrored by `s` = ±1) to `prof`.
pub(crate) fn push_pieces(prof: &mut Profile, pieces: &[Piece], s: f64, trapezoidal: bool) {
    for p in pieces {
        if trapezoidal {
            prof.push_accel(p.t, s * p.x);
        } else {
            prof.push_jerk(p.t, s * p.x);
        }
    }
}

/// Appends the time-optimal velocity change from the profile's current end to `vt`.
/// The travel direction is that of `vt` (or of the current velocity when `vt` = 0):
/// `amax` bounds the acceleration in that direction, `dmax` the deceleration.
pub(crate) fn push_velocity_change(prof: &mut Profile, vt: f64, lim: &Limits, _hint: f64) {
    let cur = prof.starts[prof.count];
    let dir = if vt != 0.0 {
        vt.signum()
    } else if cur.v != 0.0 {
        cur.v.signum()
    } else {
        1.0
    };
    let j = jerk_bound(lim);
    let a0 = if j.is_infinite() { 0.0 } else { cur.a };
    let c = change(dir * cur.v, dir * a0, dir * vt, lim.amax, lim.dmax, j);
    push_pieces(prof, &c.pieces[..c.n], dir, j.is_infinite());
}

/// Planning frame of a position problem: mirrored so that the move is in +p.
struct Frame {
    s: f64,
    v0: f64,
    a0: f64,
    dist: f64,
    vt: f64,
    j: f64,
}

impl Frame {
    fn new(start: State, target_p: f64, target_v: f64, lim: &Limits) -> Frame {
        let s = if target_p > start.p || (target_p == start.p && target_v + start.v >= 0.0) {
            1.0
        } else {
            -1.0
        };
        let j = jerk_bound(lim);
        Frame {
            s,
            v0: s * start.v,
            a0: if j.is_infinite() { 0.0 } else { s * start.a },
            dist: s * (target_p - start.p),
            vt: s * target_v,
            j,
        }
    }

    fn halves(&self, vp: f64, lim: &Limits) -> (Change, Change) {
        (
            change(self.v0, self.a0, vp, lim.amax, lim.dmax, self.j),
            change(vp, 0.0, self.vt, lim.amax, lim.dmax, self.j),
        )
    }

    fn build(&self, start: State, c1: &Change, cruise: f64, vp: f64, c2: &Change) -> Profile {
        let mut prof = Profile::new(start);
        let trap = self.j.is_infinite();
        push_pieces(&mut prof, &c1.pieces[..c1.n], self.s, trap);
        if cruise > 0.0 {
            if trap {
                prof.push_accel(cruise, 0.0);
            } else {
                // Snap the acceleration to exactly 0 at the cruise velocity.
                let i = prof.count;
                prof.starts[i].a = 0.0;
                prof.starts[i].v = self.s * vp;
                prof.push_jerk(cruise, 0.0);
            }
        }
        push_pieces(&mut prof, &c2.pieces[..c2.n], self.s, trap);
        prof
    }
}

/// A valid (not always time-optimal) profile: velocity change to a peak velocity `vp`,
/// cruise, velocity change to the target velocity; `vp` found by bisection.
pub(crate) fn position_simple(
    start: State,
    target_p: f64,
    target_v: f64,
    lim: &Limits,
) -> Result<Profile, PlanError> {
    let f = Frame::new(start, target_p, target_v, lim);
    let (c1, c2) = f.halves(lim.vmax, lim);
    let d = c1.dist + c2.dist;
    if d <= f.dist {
        let cruise = (f.dist - d) / lim.vmax;
        return Ok(f.build(start, &c1, cruise, lim.vmax, &c2));
    }
    let (mut lo, mut hi) = (-lim.vmax, lim.vmax);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        let (a, b) = f.halves(mid, lim);
        if a.dist + b.dist > f.dist {
            hi = mid;
        } else {
            lo = mid;
        }
        if hi - lo <= 1e-15 * lim.vmax {
            break;
        }
    }
    let (a, b) = f.halves(lo, lim);
    let rest = f.dist - a.dist - b.dist;
    if lo.abs() > 0.0 && rest / lo >= 0.0 {
        return Ok(f.build(start, &a, rest / lo, lo, &b));
    }
    Err(PlanError::NoSolution {
        start,
        target_p,
        target_v,
    })
}

/// A profile of duration exactly `t` from the same family, with a lower peak velocity.
pub(crate) fn with_duration_simple(
    start: State,
    target_p: f64,
    target_v: f64,
    lim: &Limits,
    t: f64,
) -> Option<Profile> {
    let f = Frame::new(start, target_p, target_v, lim);
    // Total time with peak velocity vp (None when the distance is overshot).
    let total = |vp: f64| -> Option<(f64, Change, Change, f64)> {
        let (a, b) = f.halves(vp, lim);
        let rest = f.dist - a.dist - b.dist;
        if vp <= 0.0 || rest < -1e-12 * f.dist.abs().max(1.0) {
            return None;
        }
        let cruise = rest.max(0.0) / vp;
        Some((a.time + b.time + cruise, a, b, cruise))
    };
    let mut hi = lim.vmax;
    let mut lo = 0.0;
    // Find the fastest feasible vp (largest) by bisection on feasibility.
    if total(hi).is_none() {
        let (mut l, mut h) = (0.0, lim.vmax);
        for _ in 0..200 {
            let m = 0.5 * (l + h);
            if total(m).is_some() {
                l = m;
            } else {
                h = m;
            }
        }
        hi = l;
    }
    let (t_hi, ..) = total(hi)?;
    if t_hi > t {
        return None;
    }
    for _ in 0..200 {
        let m = 0.5 * (lo + hi);
        match total(m) {
            Some((tm, ..)) if tm <= t => hi = m,
            _ => lo = m,
        }
        if hi - lo <= 1e-15 * lim.vmax {
            break;
        }
    }
    let (tt, a, b, cruise) = total(hi)?;
    let cruise = cruise + (t - tt).max(0.0) * 0.0;
    if (tt - t).abs() > 1e-9 * t.max(1.0) {
        return None;
    }
    Some(f.build(start, &a, cruise, hi, &b))
}
