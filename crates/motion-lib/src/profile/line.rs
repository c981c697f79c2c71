//! Straight-line planning for N axes.
//!
//! Input: start and end positions of N axes and each axis's [`Limits`]. Output: a
//! [`Line`]: a 1-D [`Profile`] of the path length s (0 to the line's length) and the
//! unit direction that maps s to axis positions (`start + s * unit`).
//! Invariant: the path limits are the minimum over axes of `axis limit / |unit_i|`
//! (axes not moving do not limit the path), so no axis ever exceeds its own limits.
//! An axis with `jmax` 0 or infinite does not limit the path jerk; when every axis is
//! trapezoidal, the path profile is trapezoidal.

use super::{Limits, PlanError, Profile, State};

/// Axes whose geometry is stored inline (no allocation).
const INLINE_AXES: usize = 6;

/// Start positions then unit direction: inline for up to [`INLINE_AXES`] axes.
#[derive(Clone, Debug, PartialEq)]
enum Geometry {
    Inline(usize, [f64; 2 * INLINE_AXES]),
    Heap(Vec<f64>),
}

impl Geometry {
    #[inline]
    fn zeroed(n: usize) -> Geometry {
        if n <= INLINE_AXES {
            Geometry::Inline(2 * n, [0.0; 2 * INLINE_AXES])
        } else {
            Geometry::Heap(vec![0.0; 2 * n])
        }
    }

    #[inline]
    fn as_slice(&self) -> &[f64] {
        match self {
            Geometry::Inline(len, data) => &data[..*len],
            Geometry::Heap(v) => v,
        }
    }

    #[inline]
    fn as_mut_slice(&mut self) -> &mut [f64] {
        match self {
            Geometry::Inline(len, data) => &mut data[..*len],
            Geometry::Heap(v) => v,
        }
    }
}

/// A planned straight line: path profile plus geometry.
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    geometry: Geometry,
    length: f64,
    limits: Limits,
    profile: Profile,
}

/// The path limits of a line with direction `unit` (a unit vector) through axes `axes`.
#[inline]
pub fn path_limits(unit: &[f64], axes: &[Limits]) -> Result<Limits, PlanError> {
    if unit.len() != axes.len() {
        return Err(PlanError::Line(format!(
            "{} direction components but {} axis limits",
            unit.len(),
            axes.len()
        )));
    }
    let mut l = Limits {
        vmax: f64::INFINITY,
        amax: f64::INFINITY,
        dmax: f64::INFINITY,
        jmax: f64::INFINITY,
    };
    let mut valid = true;
    for (u, ax) in unit.iter().zip(axes) {
        valid &= ax.is_valid();
        let u = u.abs();
        if u > 0.0 {
            // Plain comparisons: no NaN can reach here once the limits are valid.
            let inv = 1.0 / u;
            let (v, a, d) = (ax.vmax * inv, ax.amax * inv, ax.dmax * inv);
            if v < l.vmax {
                l.vmax = v;
            }
            if a < l.amax {
                l.amax = a;
            }
            if d < l.dmax {
                l.dmax = d;
            }
            if !ax.is_trapezoidal() && ax.jmax * inv < l.jmax {
                l.jmax = ax.jmax * inv;
            }
        }
    }
    if !valid {
        return Err(PlanError::InvalidLimits);
    }
    if !l.vmax.is_finite() {
        // No axis moves: any finite limits will do.
        l = Limits {
            vmax: 1.0,
            amax: 1.0,
            dmax: 1.0,
            jmax: 1.0,
        };
    }
    Ok(l)
}

impl Line {
    /// Time-optimal rest-to-rest straight line from `start` to `end`.
    #[inline]
    pub fn plan(start: &[f64], end: &[f64], axes: &[Limits]) -> Result<Line, PlanError> {
        if start.len() != end.len() {
            return Err(PlanError::Line(format!(
                "start has {} axes but end has {}",
                start.len(),
                end.len()
            )));
        }
        if start.iter().chain(end).any(|x| !x.is_finite()) {
            return Err(PlanError::Line("non-finite coordinate".into()));
        }
        let n = start.len();
        if axes.len() != n {
            return Err(PlanError::Line(format!(
                "{n} direction components but {} axis limits",
                axes.len()
            )));
        }
        let mut geometry = Geometry::zeroed(n);
        let g = geometry.as_mut_slice();
        let (g0, gd) = g.split_at_mut(n);
        let mut sq = 0.0;
        // One pass (no library copy call for a few coordinates).
        for (((x0, d), a), b) in g0.iter_mut().zip(gd.iter_mut()).zip(start).zip(end) {
            *x0 = *a;
            *d = b - a;
            sq += *d * *d;
        }
        let length = sq.sqrt();
        // The path limits, min over moving axes of limit_i / |u_i| = limit_i * length / |d_i|:
        // the reciprocals 1 / |d_i| do not wait for the square root.
        let (mut v, mut a, mut d, mut j) =
            (f64::INFINITY, f64::INFINITY, f64::INFINITY, f64::INFINITY);
        let mut valid = true;
        for (di, ax) in g[n..].iter().zip(axes) {
            valid &= ax.is_valid();
            let di = di.abs();
            if di > 0.0 {
                let r = 1.0 / di;
                v = v.min(ax.vmax * r);
                a = a.min(ax.amax * r);
                d = d.min(ax.dmax * r);
                if !ax.is_trapezoidal() {
                    j = j.min(ax.jmax * r);
                }
            }
        }
        if !valid {
            return Err(PlanError::InvalidLimits);
        }
        let inv = if length > 0.0 { 1.0 / length } else { 0.0 };
        for d in &mut g[n..] {
            *d *= inv;
        }
        if !(length.is_finite() && v.is_finite()) {
            // No axis moves, or a coordinate difference overflows: the general path.
            let limits = path_limits(&g[n..], axes)?;
            let profile = Profile::position(State::default(), length, 0.0, &limits)?;
            return Ok(Line {
                geometry,
                length,
                limits,
                profile,
            });
        }
        let limits = Limits {
            vmax: v * length,
            amax: a * length,
            dmax: d * length,
            jmax: j * length,
        };
        let rest = State::default();
        // The common case is built in the returned value itself.
        if let Some(fast) = Profile::position_fast(rest, length, 0.0, &limits) {
            return Ok(Line {
                geometry,
                length,
                limits,
                profile: Profile::fast(rest, &fast),
            });
        }
        let profile = Profile::position(rest, length, 0.0, &limits)?;
        Ok(Line {
            geometry,
            length,
            limits,
            profile,
        })
    }

    /// Duration of the line (s).
    pub fn duration(&self) -> f64 {
        self.profile.duration()
    }

    /// Length of the line.
    pub fn length(&self) -> f64 {
        self.length
    }

    /// The path limits used.
    pub fn limits(&self) -> &Limits {
        &self.limits
    }

    /// The 1-D profile of the path length.
    pub fn profile(&self) -> &Profile {
        &self.profile
    }

    /// Unit direction of the line.
    pub fn unit(&self) -> &[f64] {
        let g = self.geometry.as_slice();
        &g[g.len() / 2..]
    }

    /// Start positions of the axes.
    pub fn start(&self) -> &[f64] {
        let g = self.geometry.as_slice();
        &g[..g.len() / 2]
    }

    /// Path state at `t`, and the axis positions written to `positions`
    /// (its length must be the number of axes; extra entries are left alone).
    pub fn at(&self, t: f64, positions: &mut [f64]) -> State {
        let s = self.profile.at(t);
        let p = s.p.min(self.length);
        for ((out, x0), u) in positions.iter_mut().zip(self.start()).zip(self.unit()) {
            *out = x0 + p * u;
        }
        s
    }
}
