//! Straight-line planning for N axes.
//!
//! Input: start and end positions of N axes and each axis's [`Limits`]. Output: a
//! [`Line`]: a 1-D [`Profile`] of the path length s (0 to the line's length) and the
//! unit direction that maps s to axis positions (`start + s * unit`).
//! Invariant: the path limits are the minimum over axes of `axis limit / |unit_i|`
//! (axes not moving do not limit the path), so no axis ever exceeds its own limits.
//! An axis with `jmax` 0 or infinite does not limit the path jerk; when every axis is
//! trapezoidal, the path profile is trapezoidal.

use super::{slot, Limits, PlanError, Profile, State};

/// Axes whose geometry is stored inline (no allocation).
const INLINE_AXES: usize = 6;

/// Start positions then unit direction: inline for up to [`INLINE_AXES`] axes.
#[derive(Clone, Debug, PartialEq)]
enum Geometry {
    Inline(usize, [f64; 2 * INLINE_AXES]),
    Heap(Vec<f64>),
}

impl Geometry {
    #[inline(always)]
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
        slot::in_place(|out| {
            let n = start.len();
            let r = out.write(Ok(Line {
                geometry: Geometry::zeroed(n),
                length: 0.0,
                limits: Limits::default(),
                profile: Profile::new(State::default()),
            }));
            let planned = match r {
                Ok(line) => line.plan_here(start, end, axes),
                Err(_) => Ok(()),
            };
            if let Err(e) = planned {
                *r = Err(e);
            }
            r
        })
    }

    /// [`Line::plan`] in place: `self` holds a zeroed geometry of `start.len()` axes and
    /// `Profile::new(State::default())`.
    #[inline(always)]
    fn plan_here(&mut self, start: &[f64], end: &[f64], axes: &[Limits]) -> Result<(), PlanError> {
        let n = start.len();
        if end.len() != n {
            return Err(PlanError::Line(format!(
                "start has {n} axes but end has {}",
                end.len()
            )));
        }
        let non_finite = || PlanError::Line("non-finite coordinate".into());
        if axes.len() != n {
            if start.iter().chain(end).any(|x| !x.is_finite()) {
                return Err(non_finite());
            }
            return Err(PlanError::Line(format!(
                "{n} direction components but {} axis limits",
                axes.len()
            )));
        }
        let g = self.geometry.as_mut_slice();
        let (g0, gd) = g.split_at_mut(n);
        // One pass over the axes, without branches: the coordinates, their differences
        // and the path limits, min over moving axes of limit_i / |u_i| = limit_i * length /
        // |d_i| (the reciprocals 1 / |d_i| do not wait for the square root of the length;
        // an axis that does not move has 1 / |d_i| = infinity and does not limit).
        let mut sq = 0.0;
        let (mut finite, mut valid) = (true, true);
        let (mut v, mut a, mut d, mut j) =
            (f64::INFINITY, f64::INFINITY, f64::INFINITY, f64::INFINITY);
        for ((((x0, di), ax), &xa), &xb) in g0
            .iter_mut()
            .zip(gd.iter_mut())
            .zip(axes)
            .zip(start)
            .zip(end)
        {
            finite &= xa.is_finite() & xb.is_finite();
            valid &= ax.is_valid();
            *x0 = xa;
            *di = xb - xa;
            sq += *di * *di;
            let r = 1.0 / di.abs();
            let (vi, ai, dd) = (ax.vmax * r, ax.amax * r, ax.dmax * r);
            // An axis without jerk limit (jmax 0 or infinite) does not limit the path jerk.
            let ji = if ax.is_trapezoidal() {
                f64::INFINITY
            } else {
                ax.jmax * r
            };
            v = if vi < v { vi } else { v };
            a = if ai < a { ai } else { a };
            d = if dd < d { dd } else { d };
            j = if ji < j { ji } else { j };
        }
        if !finite {
            return Err(non_finite());
        }
        if !valid {
            return Err(PlanError::InvalidLimits);
        }
        let length = sq.sqrt();
        let inv = if length > 0.0 { 1.0 / length } else { 0.0 };
        for d in gd.iter_mut() {
            *d *= inv;
        }
        self.length = length;
        let rest = State::default();
        if !(length.is_finite() && v.is_finite()) {
            // No axis moves, or a coordinate difference overflows: the general path.
            self.limits = path_limits(gd, axes)?;
            self.profile = Profile::position(rest, length, 0.0, &self.limits)?;
            return Ok(());
        }
        self.limits = Limits {
            vmax: v * length,
            amax: a * length,
            dmax: d * length,
            jmax: j * length,
        };
        // The common case is built in the profile itself.
        match Profile::position_fast(rest, length, 0.0, &self.limits) {
            Some(fast) => self.profile.fill_fast(rest, &fast),
            None => self.profile = Profile::position(rest, length, 0.0, &self.limits)?,
        }
        Ok(())
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
