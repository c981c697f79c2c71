//! Jerk-limited (S-curve) motion along a straight line, in the PMAC's terms.
//!
//! Input: a line (start, end), per-axis limits (velocity, acceleration, deceleration, jerk).
//! Output: the path limits after projection onto the line ([`PathLimits`]), the time-optimal rest-to-rest
//! profile ([`RestToRest`]: peak speed, acceleration ramp, deceleration ramp, cruise), the PMAC parameters that
//! reproduce it (`TS`, `TA`, `TD`, `F`), and the PMAC's normalised S ramp ([`s_ramp`]) used to rebuild motion.
//! Invariants: a ramp of duration `T` with S-curve time `ts` (T >= 2 ts) has constant jerk for `ts`, constant
//! acceleration for `T - 2 ts`, constant jerk for `ts`, and is antisymmetric about its middle, so a blend centred
//! on a corner passes through the corner. With `TS = a/j`, `TA = v/a + a/j` (v >= a^2/j) or
//! `TS = TA/2 = sqrt(v/j)` (v < a^2/j) the PMAC ramp has exactly acceleration `a` and jerk `j`.

/// Path limits on one line: speed, acceleration, deceleration, jerk (user units, seconds).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathLimits {
    /// Path speed limit.
    pub velocity: f64,
    /// Path acceleration limit.
    pub acceleration: f64,
    /// Path deceleration limit.
    pub deceleration: f64,
    /// Path jerk limit.
    pub jerk: f64,
}

/// Length of `delta` and the path limits such that no axis exceeds its own limit: for each limit,
/// `min over moving axes k of limit_k / |u_k|` with `u = delta / |delta|`. `None` if the line has zero length.
pub fn project(
    delta: &[f64],
    velocity: &[f64],
    acceleration: &[f64],
    deceleration: &[f64],
    jerk: &[f64],
) -> Option<(f64, PathLimits)> {
    let length = delta.iter().map(|d| d * d).sum::<f64>().sqrt();
    if !(length > 0.0 && length.is_finite()) {
        return None;
    }
    let mut lim = PathLimits {
        velocity: f64::INFINITY,
        acceleration: f64::INFINITY,
        deceleration: f64::INFINITY,
        jerk: f64::INFINITY,
    };
    for (k, d) in delta.iter().enumerate() {
        let u = d.abs() / length;
        if u == 0.0 {
            continue;
        }
        lim.velocity = lim.velocity.min(velocity[k] / u);
        lim.acceleration = lim.acceleration.min(acceleration[k] / u);
        lim.deceleration = lim.deceleration.min(deceleration[k] / u);
        lim.jerk = lim.jerk.min(jerk[k] / u);
    }
    Some((length, lim))
}

/// The per-axis limit that gives `path_limit` on the line `delta` after projection: `path_limit * max |u_k|`.
/// Use it when a planner gives path limits (PLCopen MC_MoveLinear* velocity is along the path) and the move
/// is to be written as a [`crate::LinearMove`], whose limits are per axis. `None` for a zero-length line.
pub fn axis_limit_for_path(delta: &[f64], path_limit: f64) -> Option<f64> {
    let length = delta.iter().map(|d| d * d).sum::<f64>().sqrt();
    if !(length > 0.0 && length.is_finite()) {
        return None;
    }
    let dominant = delta.iter().map(|d| d.abs()).fold(0.0, f64::max) / length;
    Some(path_limit * dominant)
}

/// A speed change of `dv` from or to rest, as the PMAC times it: total time `time` (TA or TD) with S-curve
/// time `ts`, reaching `peak_acceleration`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ramp {
    /// The ramp time (TA or TD), seconds.
    pub time: f64,
    /// The S-curve time at each end (TS), seconds.
    pub ts: f64,
    /// The acceleration reached.
    pub peak_acceleration: f64,
}

/// The fastest ramp for a speed change `dv` with acceleration limit `a` and jerk limit `j`.
pub fn ramp(dv: f64, a: f64, j: f64) -> Ramp {
    let dv = dv.abs();
    if dv >= a * a / j {
        Ramp {
            time: dv / a + a / j,
            ts: a / j,
            peak_acceleration: a,
        }
    } else {
        let ts = (dv / j).sqrt();
        Ramp {
            time: 2.0 * ts,
            ts,
            peak_acceleration: (dv * j).sqrt(),
        }
    }
}

/// A rest-to-rest move: accelerate to `peak_velocity`, cruise, decelerate; time-optimal for the limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RestToRest {
    /// The path length.
    pub length: f64,
    /// The speed reached.
    pub peak_velocity: f64,
    /// The ramp from rest.
    pub accel: Ramp,
    /// The ramp to rest.
    pub decel: Ramp,
}

impl RestToRest {
    /// Plans the time-optimal move of `length` (> 0) under `lim`: the peak speed is the limit if the ramps fit,
    /// otherwise the largest speed whose two ramps cover exactly `length` (no cruise).
    pub fn plan(length: f64, lim: &PathLimits) -> RestToRest {
        let make = |v: f64| RestToRest {
            length,
            peak_velocity: v,
            accel: ramp(v, lim.acceleration, lim.jerk),
            decel: ramp(v, lim.deceleration, lim.jerk),
        };
        let full = make(lim.velocity);
        if full.ramp_distance() <= length {
            return full;
        }
        // ramp_distance(v) = v (Ta(v) + Td(v)) / 2 increases with v: bisect.
        let (mut lo, mut hi) = (0.0, lim.velocity);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if make(mid).ramp_distance() <= length {
                lo = mid;
            } else {
                hi = mid;
            }
            if hi - lo <= 1e-15 * lim.velocity {
                break;
            }
        }
        make(lo)
    }
    /// Distance covered by the two ramps (each covers speed times half its time).
    pub fn ramp_distance(&self) -> f64 {
        self.peak_velocity * (self.accel.time + self.decel.time) / 2.0
    }
    /// The time at `peak_velocity` between the ramps.
    pub fn cruise_time(&self) -> f64 {
        ((self.length - self.ramp_distance()) / self.peak_velocity).max(0.0)
    }
    /// Total duration: `length / v + (Ta + Td) / 2`.
    pub fn duration(&self) -> f64 {
        self.accel.time + self.cruise_time() + self.decel.time
    }
    /// Path acceleration at `t`.
    pub fn acceleration(&self, t: f64) -> f64 {
        let v = self.peak_velocity;
        let td = self.decel.time;
        let stop = self.duration();
        v * (s_ramp_acc(self.accel.time, self.accel.ts, t)
            - s_ramp_acc(td, self.decel.ts, t - (stop - td)))
    }
    /// Path position and speed at `t` (clamped to the move).
    pub fn eval(&self, t: f64) -> (f64, f64) {
        let v = self.peak_velocity;
        let ta = self.accel.time;
        let td = self.decel.time;
        let stop = self.duration();
        let t = t.clamp(0.0, stop);
        // Speed = v * S_acc(t) - v * S_dec(t - (stop - td)); position by the ramps' integrals.
        let (ua, ia) = s_ramp(ta, self.accel.ts, t);
        let (ud, id) = s_ramp(td, self.decel.ts, t - (stop - td));
        (v * (ia - id), v * (ua - ud))
    }
}

/// The PMAC's normalised S ramp from 0 to 1 over `time` with S-curve time `ts` (if `time < 2 ts`, `2 ts` is
/// used), at `x` seconds after its start: (value, integral of the value from the start). Before the start both
/// are 0; after the end the value is 1 and the integral `time/2 + (x - time)`.
pub fn s_ramp(time: f64, ts: f64, x: f64) -> (f64, f64) {
    let ts = ts.max(0.0);
    let time = time.max(2.0 * ts);
    if x <= 0.0 {
        return (0.0, 0.0);
    }
    if time <= 0.0 {
        return (1.0, x);
    }
    if x >= time {
        return (1.0, time / 2.0 + (x - time));
    }
    let rising = |y: f64| -> (f64, f64) {
        // First half: y <= time / 2.
        if ts <= 0.0 {
            let peak = 1.0 / time;
            return (peak * y, peak * y * y / 2.0);
        }
        let peak = 1.0 / (time - ts);
        let k = peak / ts;
        if y <= ts {
            (k * y * y / 2.0, k * y * y * y / 6.0)
        } else {
            let z = y - ts;
            (
                k * ts * ts / 2.0 + peak * z,
                k * ts * ts * ts / 6.0 + k * ts * ts / 2.0 * z + peak * z * z / 2.0,
            )
        }
    };
    if x <= time / 2.0 {
        rising(x)
    } else {
        // Antisymmetry: value(x) = 1 - value(time - x); integral over [x, time] of value = (time - x) - I(time - x).
        let y = time - x;
        let (vy, iy) = rising(y);
        (1.0 - vy, time / 2.0 - (y - iy))
    }
}

/// Acceleration of the normalised S ramp (derivative of `s_ramp`'s value).
pub fn s_ramp_acc(time: f64, ts: f64, x: f64) -> f64 {
    let time = time.max(2.0 * ts);
    if x <= 0.0 || x >= time || time <= 0.0 {
        return 0.0;
    }
    let y = x.min(time - x);
    if ts <= 0.0 {
        return 1.0 / time;
    }
    let peak = 1.0 / (time - ts);
    if y <= ts {
        peak * y / ts
    } else {
        peak
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn projection_uses_the_dominant_axis() {
        let (len, lim) = project(
            &[1600.0, 1200.0, 800.0],
            &[40.0; 3],
            &[5.0; 3],
            &[5.0; 3],
            &[2.0; 3],
        )
        .unwrap();
        assert!((len - 4_640_000f64.sqrt()).abs() < 1e-9);
        assert!((lim.velocity - 40.0 * len / 1600.0).abs() < 1e-9);
        assert!((lim.jerk - 2.0 * len / 1600.0).abs() < 1e-9);
        assert!(project(&[0.0, 0.0], &[1.0; 2], &[1.0; 2], &[1.0; 2], &[1.0; 2]).is_none());
    }

    #[test]
    fn path_limits_round_trip_through_axis_limits() {
        let delta = [600.0, 2600.0, 4200.0];
        let axis = axis_limit_for_path(&delta, 55.0).unwrap();
        let (_, lim) = project(&delta, &[axis; 3], &[axis; 3], &[axis; 3], &[axis; 3]).unwrap();
        assert!((lim.velocity - 55.0).abs() < 1e-12);
        assert!(axis_limit_for_path(&[0.0, 0.0], 1.0).is_none());
    }

    #[test]
    fn ramp_matches_pmac_formulas() {
        let r = ramp(40.0, 5.0, 2.0);
        assert!((r.ts - 2.5).abs() < 1e-12 && (r.time - 10.5).abs() < 1e-12);
        let r = ramp(8.0, 5.0, 2.0); // 8 < 25/2: no constant-acceleration phase
        assert!((r.ts - 2.0).abs() < 1e-12 && (r.time - 4.0).abs() < 1e-12);
        assert!((r.peak_acceleration - 4.0).abs() < 1e-12);
    }

    #[test]
    fn s_ramp_is_continuous_and_reaches_one() {
        let (t, ts) = (10.5, 2.5);
        let mut prev = s_ramp(t, ts, 0.0);
        let n = 10_000;
        let mut integral = 0.0;
        for i in 1..=n {
            let x = t * i as f64 / n as f64;
            let cur = s_ramp(t, ts, x);
            assert!((cur.0 - prev.0).abs() < 1e-3, "jump at {x}");
            integral += 0.5 * (cur.0 + prev.0) * t / n as f64;
            assert!((cur.1 - integral).abs() < 1e-6, "integral at {x}");
            prev = cur;
        }
        assert!((prev.0 - 1.0).abs() < 1e-12 && (prev.1 - t / 2.0).abs() < 1e-12);
    }

    #[test]
    fn short_move_does_not_cruise() {
        let lim = PathLimits {
            velocity: 40.0,
            acceleration: 5.0,
            deceleration: 5.0,
            jerk: 2.0,
        };
        let m = RestToRest::plan(100.0, &lim);
        assert!(m.peak_velocity < 40.0);
        assert!(m.cruise_time() < 1e-9);
        let (p, v) = m.eval(m.duration());
        assert!((p - 100.0).abs() < 1e-9 && v.abs() < 1e-12);
    }
}
