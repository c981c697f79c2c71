//! Closed-form time-optimal velocity changes (MoveVelocity, Halt, Stop), and the fast
//! path of position profiles that cruise at vmax.
//!
//! Input: a start velocity/acceleration, a target velocity (reached with acceleration 0),
//! acceleration bounds `[-a_lo, a_hi]` and a jerk bound. Output: at most 3 phases of
//! constant jerk (or of constant acceleration when the profile is trapezoidal).
//! Invariant: the change is time-optimal for a free end position (ruckig's third-order
//! velocity interface with target acceleration 0), acceleration never leaves
//! `[-a_lo, a_hi]` except to come back from a start acceleration beyond it.

use super::{Limits, Profile, State};

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
    #[inline]
    fn push(&mut self, t: f64, x: f64) {
        if t > 0.0 {
            self.pieces[self.n] = Piece { t, x };
            self.n += 1;
        }
    }
}

/// Time-optimal change from (`v0`, `a0`) to (`vt`, 0) with a in `[-a_lo, a_hi]`, |jerk| <= `j`
/// (`j` infinite: trapezoidal, `a0` ignored).
#[inline]
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

/// The time-optimal velocity change from `cur` to `vt` (acceleration 0).
/// The travel direction is that of `vt` (or of the current velocity when `vt` = 0):
/// `amax` bounds the acceleration in that direction, `dmax` the deceleration.
pub(crate) fn velocity_change(cur: State, vt: f64, lim: &Limits) -> Profile {
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
    let mut items = [(0.0, 0.0); 3];
    for (it, p) in items.iter_mut().zip(&c.pieces[..c.n]) {
        *it = (p.t, dir * p.x);
    }
    Profile::build(cur, &items[..c.n], j.is_infinite(), None)
}

/// Fast path of [`Profile::position`]: when the start is inside the limits and the
/// distance leaves room for a cruise at vmax, the time-optimal profile is the
/// time-optimal change to vmax, the cruise, and the time-optimal change to the target
/// velocity (ruckig's velocity-limited profile families). None otherwise (the kernel
/// then enumerates every family).
#[inline]
pub(crate) fn position_cruising(
    start: State,
    target_p: f64,
    target_v: f64,
    lim: &Limits,
) -> Option<Profile> {
    if lim.is_trapezoidal() {
        return None;
    }
    let s = if target_p >= start.p { 1.0 } else { -1.0 };
    let (v0, a0, vf, j) = (s * start.v, s * start.a, s * target_v, lim.jmax);
    let v_zero = v0 + a0 * a0.abs() / (2.0 * j);
    if v0.abs() > lim.vmax
        || a0 > lim.amax
        || a0 < -lim.dmax
        || v_zero.abs() > lim.vmax
        || vf.abs() > lim.vmax
    {
        return None;
    }
    let c1 = change(v0, a0, lim.vmax, lim.amax, lim.dmax, j);
    let c2 = change(lim.vmax, 0.0, vf, lim.amax, lim.dmax, j);
    let cruise = (s * (target_p - start.p) - c1.dist - c2.dist) / lim.vmax;
    if cruise.is_nan() || cruise <= 0.0 {
        return None;
    }
    let mut items = [(0.0, 0.0); 7];
    for (it, p) in items.iter_mut().zip(&c1.pieces[..c1.n]) {
        *it = (p.t, s * p.x);
    }
    items[c1.n] = (cruise, 0.0);
    for (it, p) in items[c1.n + 1..].iter_mut().zip(&c2.pieces[..c2.n]) {
        *it = (p.t, s * p.x);
    }
    // Snap to exactly vmax, acceleration 0, for the cruise.
    let n = c1.n + 1 + c2.n;
    Some(Profile::build(
        start,
        &items[..n],
        false,
        Some((c1.n, s * lim.vmax)),
    ))
}
