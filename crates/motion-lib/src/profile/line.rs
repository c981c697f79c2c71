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
    fn zeroed(n: usize) -> Geometry {
        if n <= INLINE_AXES {
            Geometry::Inline(2 * n, [0.0; 2 * INLINE_AXES])
        } else {
            Geometry::Heap(vec![0.0; 2 * n])
        }
    }

    fn as_slice(&self) -> &[f64] {
        match self {
            Geometry::Inline(len, data) => &data[..*len],
            Geometry::Heap(v) => v,
        }
    }

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
        // Built in place: the profile is planned into the line that is returned (no copy).
        let mut line = Line {
            geometry: Geometry::zeroed(n),
            length: 0.0,
            limits: Limits::default(),
            profile: Profile::new(State::default()),
        };
        let g = line.geometry.as_mut_slice();
        g[..n].copy_from_slice(start);
        for ((d, a), b) in g[n..].iter_mut().zip(start).zip(end) {
            *d = b - a;
        }
        let length = g[n..].iter().map(|d| d * d).sum::<f64>().sqrt();
        let inv = if length > 0.0 { 1.0 / length } else { 0.0 };
        for d in &mut g[n..] {
            *d *= inv;
        }
        line.limits = path_limits(&g[n..], axes)?;
        line.length = length;
        line.profile.plan_position(length, 0.0, &line.limits)?;
        Ok(line)
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
