//! Closed-form time-optimal velocity changes (MoveVelocity, Halt, Stop), and the fast
//! path of position profiles that cruise at vmax.
//!
//! Input: a start velocity/acceleration, a target velocity (reached with acceleration 0),
//! acceleration bounds `[-a_lo, a_hi]` and a jerk bound. Output: at most 3 phases of
//! constant jerk (or of constant acceleration when the profile is trapezoidal).
//! Invariant: the change is time-optimal for a free end position (ruckig's third-order
//! velocity interface with target acceleration 0), acceleration never leaves
//! `[-a_lo, a_hi]` except to come back from a start acceleration beyond it.

use super::{zero_if_finite, Limits, Profile, State};

/// One velocity change: three pieces (duration, jerk; or duration, acceleration when
/// trapezoidal), some possibly of zero duration, with the distance covered.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Change {
    pub t: [f64; 3],
    pub x: [f64; 3],
    pub dist: f64,
}

/// Time-optimal change from (`v0`, `a0`) to (`vt`, 0) with a in `[-a_lo, a_hi]`, |jerk| <= `j`
/// (`j` infinite: trapezoidal, `a0` ignored). Closed form, scalars only.
#[inline(always)]
pub(crate) fn change(v0: f64, a0: f64, vt: f64, a_hi: f64, a_lo: f64, j: f64) -> Change {
    change_with(v0, a0, vt, a_hi, a_lo, j, [1.0 / j, 1.0 / a_hi, 1.0 / a_lo])
}

/// [`change`] with `inv` = [1 / `j`, 1 / `a_hi`, 1 / `a_lo`] precomputed (off the
/// critical path of the square root).
#[inline(always)]
pub(crate) fn change_with(
    v0: f64,
    a0: f64,
    vt: f64,
    a_hi: f64,
    a_lo: f64,
    j: f64,
    inv: [f64; 3],
) -> Change {
    let inv_j = inv[0];
    if j.is_infinite() {
        let (t, acc) = if vt > v0 {
            ((vt - v0) / a_hi, a_hi)
        } else if vt < v0 {
            ((v0 - vt) / a_lo, -a_lo)
        } else {
            (0.0, 0.0)
        };
        return Change {
            t: [t, 0.0, 0.0],
            x: [acc, 0.0, 0.0],
            dist: 0.5 * (v0 + vt) * t,
        };
    }
    let v_zero = v0 + 0.5 * a0 * a0.abs() * inv_j;
    let (s, v0m, a0m, vtm, hi, inv_hi) = if vt >= v_zero {
        (1.0, v0, a0, vt, a_hi, inv[1])
    } else {
        (-1.0, -v0, -a0, -vt, a_lo, inv[2])
    };
    // Upward change in the mirrored frame: jerk j1 to the peak acceleration `ap`, hold
    // it for t2, jerk -j back to 0.
    let (t1, j1, t2, ap) = if a0m > hi {
        let vz = v0m + 0.5 * a0m * a0m * inv_j;
        ((a0m - hi) * inv_j, -j, ((vtm - vz) * inv_hi).max(0.0), hi)
    } else {
        let ap = (j * (vtm - v0m) + 0.5 * a0m * a0m).max(0.0).sqrt();
        if ap <= hi {
            ((ap - a0m).max(0.0) * inv_j, j, 0.0, ap)
        } else {
            let t2 = ((vtm - v0m - (hi * hi - 0.5 * a0m * a0m) * inv_j) * inv_hi).max(0.0);
            ((hi - a0m) * inv_j, j, t2, hi)
        }
    };
    let t3 = ap * inv_j;
    // Distance in the mirrored frame, piece by piece.
    const SIXTH: f64 = 1.0 / 6.0;
    let d1 = t1 * (v0m + t1 * (0.5 * a0m + t1 * j1 * SIXTH));
    let v1 = v0m + t1 * (a0m + 0.5 * t1 * j1);
    let d2 = t2 * (v1 + 0.5 * ap * t2);
    let v2 = v1 + ap * t2;
    let d3 = t3 * (v2 + t3 * (0.5 * ap - t3 * j * SIXTH));
    Change {
        t: [t1, t2, t3],
        x: [s * j1, 0.0, -s * j],
        dist: s * (d1 + d2 + d3),
    }
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
    let items = [0, 1, 2].map(|i| (c.t[i], dir * c.x[i]));
    Profile::build(cur, &items, j.is_infinite(), None)
}

/// A fast path's profile: seven phases (duration, jerk), the fourth a cruise (possibly
/// empty), with the state at the start of the cruise.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Fast {
    /// The phases.
    pub items: [(f64, f64); 7],
    /// Signed velocity of the cruise.
    pub v_peak: f64,
    /// Signed distance from the start to the start of the cruise.
    pub d_cruise: f64,
    /// Signed distance from the end of the cruise to the target.
    pub d_decel: f64,
}

impl Fast {
    /// The same profile with positions (and so velocities, accelerations, jerks) scaled
    /// by `k`, times unchanged: the profile of the target `k` times as far under limits
    /// `k` times as high.
    #[inline(always)]
    pub(crate) fn scaled(&self, k: f64) -> Fast {
        Fast {
            items: self.items.map(|(t, j)| (t, j * k)),
            v_peak: self.v_peak * k,
            d_cruise: self.d_cruise * k,
            d_decel: self.d_decel * k,
        }
    }
}

/// Fast paths of [`Profile::position`]. None when the problem needs the kernel's
/// enumeration of every profile family.
#[inline(always)]
pub(crate) fn fast_path(start: State, target_p: f64, target_v: f64, lim: &Limits) -> Option<Fast> {
    if lim.is_trapezoidal() {
        return None;
    }
    if start.v == 0.0 && start.a == 0.0 && target_v == 0.0 {
        return rest_to_rest(start, target_p, lim);
    }
    position_cruising(start, target_p, target_v, lim)
}

/// Rest-to-rest move (v = a = 0 at both ends), in closed form: accelerate to a peak
/// velocity `vp`, cruise, decelerate. Each ramp from rest to `vp` is triangular (jerk
/// `j` for `sqrt(vp/j)`, then `-j` as long) when `vp <= a^2/j`, else trapezoidal (`a/j`
/// at full jerk, `vp/a - a/j` at acceleration `a`, `a/j` back), and covers
/// `vp/2 x its duration`. With room to cruise, `vp = vmax`. Otherwise the distance
/// `D(vp)` of the two ramps is increasing in `vp` and has closed-form inverses when both
/// ramps are triangular (`D = 2 j t^3` with `t = sqrt(vp/j)`: one cube root) or both
/// trapezoidal (a quadratic in `vp`); the mixed case (`amax != dmax`, a quartic) is left
/// to the kernel. No loops, no iterations: a handful of divisions and at most one root.
#[inline(always)]
fn rest_to_rest(start: State, target_p: f64, lim: &Limits) -> Option<Fast> {
    let s = if target_p >= start.p { 1.0 } else { -1.0 };
    let dist = s * (target_p - start.p);
    let (vm, am, dm, j) = (lim.vmax, lim.amax, lim.dmax, lim.jmax);
    // The four divisions are independent of each other (issued back to back); everything
    // after them is multiplications, one comparison and at most one root.
    let (inv_j, inv_am, inv_dm, inv_vm) = (1.0 / j, 1.0 / am, 1.0 / dm, 1.0 / vm);
    let sj = s * j;
    // Ramp from rest to vmax with acceleration limit `a`: (jerk time, constant-acceleration
    // time, distance).
    let ramp = |a: f64, inv_a: f64| -> (f64, f64, f64) {
        if vm * j > a * a {
            let t1 = a * inv_j;
            let t2 = vm * inv_a - t1;
            (t1, t2, 0.5 * vm * (2.0 * t1 + t2))
        } else {
            let t1 = (vm * inv_j).sqrt();
            (t1, 0.0, vm * t1)
        }
    };
    let (ta1, ta2, da) = ramp(am, inv_am);
    let (td1, td2, dd) = ramp(dm, inv_dm);
    let cruise = (dist - da - dd) * inv_vm;
    let (ta1, ta2, td1, td2, vp, cruise) = if cruise >= 0.0 {
        (ta1, ta2, td1, td2, vm, cruise)
    } else {
        let a_lo = am.min(dm);
        let a_hi = am.max(dm);
        // Both triangular while vp = j t^2 <= a_lo^2 / j, i.e. dist <= 2 a_lo^3 / j^2.
        let t_lo = a_lo * inv_j;
        if dist <= 2.0 * j * t_lo * t_lo * t_lo {
            let t = (0.5 * dist * inv_j).cbrt();
            (t, 0.0, t, 0.0, j * t * t, 0.0)
        } else {
            // Both trapezoidal: (1/am + 1/dm)/2 vp^2 + (am + dm)/(2j) vp - dist = 0.
            let qa = 0.5 * (inv_am + inv_dm);
            let qb = 0.5 * (am + dm) * inv_j;
            let vp = 2.0 * dist / (qb + (qb * qb + 4.0 * qa * dist).sqrt());
            if !(vp * j >= a_hi * a_hi && vp <= vm) {
                return None;
            }
            let (t1a, t1d) = (am * inv_j, dm * inv_j);
            (t1a, vp * inv_am - t1a, t1d, vp * inv_dm - t1d, vp, 0.0)
        }
    };
    if !(vp > 0.0 && zero_if_finite(vp) == 0.0) {
        return None;
    }
    let items = [
        (ta1, sj),
        (ta2, 0.0),
        (ta1, -sj),
        (cruise, 0.0),
        (td1, -sj),
        (td2, 0.0),
        (td1, sj),
    ];
    // Each ramp is point-symmetric about its middle: it covers vp/2 x its duration
    // 2 t1 + t2.
    Some(Fast {
        items,
        v_peak: s * vp,
        d_cruise: s * (0.5 * vp * (2.0 * ta1 + ta2)),
        d_decel: s * (0.5 * vp * (2.0 * td1 + td2)),
    })
}

/// Fast path of [`Profile::position`]: when the start is inside the limits and the
/// distance leaves room for a cruise at vmax, the time-optimal profile is the
/// time-optimal change to vmax, the cruise, and the time-optimal change to the target
/// velocity (ruckig's velocity-limited profile families). Returns the phases
/// (duration, jerk), the cruise being the fourth, at velocity `sign(target_p - start.p)
/// * vmax`. None otherwise (the kernel then enumerates every family).
#[inline(always)]
pub(crate) fn position_cruising(
    start: State,
    target_p: f64,
    target_v: f64,
    lim: &Limits,
) -> Option<Fast> {
    let s = if target_p >= start.p { 1.0 } else { -1.0 };
    let (v0, a0, vf, j) = (s * start.v, s * start.a, s * target_v, lim.jmax);
    let inv_j = 1.0 / j;
    let v_zero = v0 + 0.5 * a0 * a0.abs() * inv_j;
    if v0.abs() > lim.vmax
        || a0 > lim.amax
        || a0 < -lim.dmax
        || v_zero.abs() > lim.vmax
        || vf.abs() > lim.vmax
    {
        return None;
    }
    let inv = [inv_j, 1.0 / lim.amax, 1.0 / lim.dmax];
    let inv_vmax = 1.0 / lim.vmax;
    let c1 = change_with(v0, a0, lim.vmax, lim.amax, lim.dmax, j, inv);
    let c2 = change_with(lim.vmax, 0.0, vf, lim.amax, lim.dmax, j, inv);
    let cruise = (s * (target_p - start.p) - c1.dist - c2.dist) * inv_vmax;
    if cruise.is_nan() || cruise <= 0.0 {
        return None;
    }
    let items = [
        (c1.t[0], s * c1.x[0]),
        (c1.t[1], s * c1.x[1]),
        (c1.t[2], s * c1.x[2]),
        (cruise, 0.0),
        (c2.t[0], s * c2.x[0]),
        (c2.t[1], s * c2.x[1]),
        (c2.t[2], s * c2.x[2]),
    ];
    Some(Fast {
        items,
        v_peak: s * lim.vmax,
        d_cruise: s * c1.dist,
        d_decel: s * c2.dist,
    })
}
