//! Straight-line planning for N axes.
//!
//! Input: start and end positions of N axes and each axis's [`Limits`]. Output: a
//! [`Line`]: a 1-D [`Profile`] of the path length s (0 to the line's length) and the
//! unit direction that maps s to axis positions (`start + s * unit`).
//! Invariant: the path limits are the minimum over axes of `axis limit / |unit_i|`
//! (axes not moving do not limit the path), so no axis ever exceeds its own limits.
//! An axis with `jmax` 0 or infinite does not limit the path jerk; when every axis is
//! trapezoidal, the path profile is trapezoidal.

use super::{slot, velocity, zero_if_finite, Limits, PlanError, Profile, State};

/// Axes whose geometry is stored inline (no allocation).
const INLINE_AXES: usize = 6;

/// Start positions then unit direction: inline for up to [`INLINE_AXES`] axes.
#[derive(Clone, Debug, PartialEq)]
enum Geometry {
    Inline(usize, [f64; 2 * INLINE_AXES]),
    Heap(Vec<f64>),
}

impl Geometry {
    /// The geometry of `n` axes: `inline`'s first 2n values, or `heap` beyond
    /// [`INLINE_AXES`] axes.
    #[inline(always)]
    fn new(n: usize, inline: [f64; 2 * INLINE_AXES], heap: Vec<f64>) -> Geometry {
        if n <= INLINE_AXES {
            Geometry::Inline(2 * n, inline)
        } else {
            Geometry::Heap(heap)
        }
    }

    #[inline]
    fn as_slice(&self) -> &[f64] {
        match self {
            Geometry::Inline(len, data) => &data[..*len],
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

/// One pass over the axes of a line, without branches: the start coordinates and the
/// coordinate differences written to the geometry, and the path limits, min over moving
/// axes of limit_i / |u_i| = limit_i * length / |d_i| (still to be multiplied by the
/// length: the reciprocals 1 / |d_i| do not wait for its square root; an axis that does
/// not move has 1 / |d_i| = infinity and does not limit).
struct AxisPass {
    /// Sum of the squared differences (not finite when a coordinate is not).
    sq: f64,
    /// Every axis's limits valid.
    valid: bool,
    v: f64,
    a: f64,
    d: f64,
    j: f64,
}

impl AxisPass {
    #[inline(always)]
    fn run(
        g0: &mut [f64],
        gd: &mut [f64],
        start: &[f64],
        end: &[f64],
        axes: &[Limits],
    ) -> AxisPass {
        let mut p = AxisPass {
            sq: 0.0,
            valid: true,
            v: f64::INFINITY,
            a: f64::INFINITY,
            d: f64::INFINITY,
            j: f64::INFINITY,
        };
        for ((((x0, di), ax), &xa), &xb) in g0
            .iter_mut()
            .zip(gd.iter_mut())
            .zip(axes)
            .zip(start)
            .zip(end)
        {
            p.valid &= ax.is_valid();
            let dx = xb - xa;
            *x0 = xa;
            *di = dx;
            p.sq += dx * dx;
            let r = 1.0 / dx.abs();
            let (vi, ai, dd) = (ax.vmax * r, ax.amax * r, ax.dmax * r);
            // An axis without jerk limit (jmax 0 or infinite) does not limit the path jerk
            // (infinite jmax: jmax * r is infinite; valid limits have jmax >= 0).
            let ji = if ax.jmax > 0.0 {
                ax.jmax * r
            } else {
                f64::INFINITY
            };
            p.v = if vi < p.v { vi } else { p.v };
            p.a = if ai < p.a { ai } else { p.a };
            p.d = if dd < p.d { dd } else { p.d };
            p.j = if ji < p.j { ji } else { p.j };
        }
        p
    }
}

impl Line {
    /// Time-optimal rest-to-rest straight line from `start` to `end`.
    #[inline]
    pub fn plan(start: &[f64], end: &[f64], axes: &[Limits]) -> Result<Line, PlanError> {
        slot::in_place(|out| Line::plan_into(out, start, end, axes))
    }

    /// [`Line::plan`] written once into `out`, a slot the caller keeps and may reuse from plan
    /// to plan (its previous value is dropped); returns the result in the slot. The line is
    /// written once,
    /// as one value (geometry, limits and the fast path's profile computed before), so
    /// that it goes straight into the slot, without zeroing it first.
    #[inline(always)]
    pub fn plan_into<'a>(
        out: &'a mut Option<Result<Line, PlanError>>,
        start: &[f64],
        end: &[f64],
        axes: &[Limits],
    ) -> &'a mut Result<Line, PlanError> {
        let n = start.len();
        if end.len() != n {
            return out.insert(Err(PlanError::Line(format!(
                "start has {n} axes but end has {}",
                end.len()
            ))));
        }
        let non_finite = || PlanError::Line("non-finite coordinate".into());
        if axes.len() != n {
            if start.iter().chain(end).any(|x| !x.is_finite()) {
                return out.insert(Err(non_finite()));
            }
            return out.insert(Err(PlanError::Line(format!(
                "{n} direction components but {} axis limits",
                axes.len()
            ))));
        }
        // Start positions then unit direction: inline for up to INLINE_AXES axes.
        let mut inline = [0.0; 2 * INLINE_AXES];
        let mut heap = if n > INLINE_AXES {
            vec![0.0; 2 * n]
        } else {
            Vec::new()
        };
        let g: &mut [f64] = if n > INLINE_AXES {
            &mut heap
        } else {
            &mut inline[..2 * n]
        };
        let (g0, gd) = g.split_at_mut(n);
        // The common axis counts get a pass of constant length (unrolled, no loop).
        let pass = match n {
            2 => AxisPass::run(
                &mut g0[..2],
                &mut gd[..2],
                &start[..2],
                &end[..2],
                &axes[..2],
            ),
            3 => AxisPass::run(
                &mut g0[..3],
                &mut gd[..3],
                &start[..3],
                &end[..3],
                &axes[..3],
            ),
            _ => AxisPass::run(g0, gd, start, end, axes),
        };
        let AxisPass {
            sq,
            valid,
            v,
            a,
            d,
            j,
        } = pass;
        // A non-finite coordinate makes its difference, and so the length, infinite or
        // NaN: the coordinates are only looked at then (or when the limits are invalid:
        // a non-finite coordinate is reported first).
        let coords_finite = || start.iter().chain(end).all(|x| x.is_finite());
        if !valid {
            return out.insert(Err(if coords_finite() {
                PlanError::InvalidLimits
            } else {
                non_finite()
            }));
        }
        let length = sq.sqrt();
        let inv = if length > 0.0 { 1.0 / length } else { 0.0 };
        for d in gd.iter_mut() {
            *d *= inv;
        }
        let rest = State::default();
        if zero_if_finite(length) + zero_if_finite(v) != 0.0 {
            if !coords_finite() {
                return out.insert(Err(non_finite()));
            }
            // No axis moves, or a coordinate difference overflows: the general path.
            let planned = path_limits(gd, axes).and_then(|limits| {
                Profile::position(rest, length, 0.0, &limits).map(|p| (limits, p))
            });
            let geometry = Geometry::new(n, inline, heap);
            return out.insert(planned.map(|(limits, profile)| Line {
                geometry,
                length,
                limits,
                profile,
            }));
        }
        let limits = Limits {
            vmax: v * length,
            amax: a * length,
            dmax: d * length,
            jmax: j * length,
        };
        let geometry = Geometry::new(n, inline, heap);
        // The common case, planned on the unit path (s = 0 to 1, limits per unit of s)
        // and scaled by the length: the same times (to rounding) and positions `length`
        // times as large, but the plan does not wait for the square root of the length.
        // The unit limits are valid here (positive: min over moving axes of valid limits
        // / |d_i|, v finite, so a and d too; j infinite when no axis limits the jerk, and
        // the fast path is then not taken): no input check. The scaled limits must be
        // finite too (else the general path reports it).
        let unit = Limits {
            vmax: v,
            amax: a,
            dmax: d,
            jmax: j,
        };
        let finite =
            zero_if_finite(limits.vmax) + zero_if_finite(limits.amax) + zero_if_finite(limits.dmax)
                == 0.0;
        match velocity::fast_path(rest, 1.0, 0.0, &unit) {
            Some(fast) if finite => {
                let (profile, all) = Profile::fast(rest, &fast.scaled(length), length, 0.0);
                let r = out.insert(Ok(Line {
                    geometry,
                    length,
                    limits,
                    profile,
                }));
                if !all {
                    if let Ok(line) = r {
                        line.profile.compact();
                    }
                }
                r
            }
            _ => out.insert(
                Profile::position(rest, length, 0.0, &limits).map(|profile| Line {
                    geometry,
                    length,
                    limits,
                    profile,
                }),
            ),
        }
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

#[cfg(test)]
mod tests {
    use super::*;

    const AX: Limits = Limits {
        vmax: 10.0,
        amax: 20.0,
        dmax: 30.0,
        jmax: 100.0,
    };

    /// Every axis count (the unrolled 2 and 3 and the general pass) gives the same line as
    /// the per-axis definition: path limits min over moving axes of limit / |u_i|, unit
    /// direction, length, and the rest-to-rest profile of the path with those limits.
    #[test]
    fn every_axis_count_plans_the_path_problem() {
        for n in 1..=8 {
            let start: Vec<f64> = (0..n).map(|i| i as f64 - 2.0).collect();
            // Axis 1 does not move (when there is one): it must not limit the path.
            let end: Vec<f64> = (0..n)
                .map(|i| {
                    if i == 1 {
                        start[i]
                    } else {
                        start[i] + 3.0 * (i as f64 + 1.0)
                    }
                })
                .collect();
            let axes: Vec<Limits> = (0..n)
                .map(|i| Limits {
                    vmax: AX.vmax * (1.0 + i as f64),
                    jmax: if i == 2 { 0.0 } else { AX.jmax },
                    ..AX
                })
                .collect();
            let line = Line::plan(&start, &end, &axes).unwrap();
            let d: Vec<f64> = start.iter().zip(&end).map(|(a, b)| b - a).collect();
            let len = d.iter().map(|x| x * x).sum::<f64>().sqrt();
            let unit: Vec<f64> = d.iter().map(|x| x / len).collect();
            let want = path_limits(&unit, &axes).unwrap();
            let got = line.limits();
            for (g, w) in [
                (got.vmax, want.vmax),
                (got.amax, want.amax),
                (got.dmax, want.dmax),
                (got.jmax, want.jmax),
            ] {
                assert!((g - w).abs() <= 1e-12 * w, "n {n}: {got:?} vs {want:?}");
            }
            assert_eq!(line.length(), len);
            assert_eq!(line.start(), &start[..]);
            for (u, w) in line.unit().iter().zip(&unit) {
                assert!((u - w).abs() <= 1e-15, "n {n}");
            }
            let prof = Profile::position(State::default(), len, 0.0, &want).unwrap();
            let rel = (line.duration() - prof.duration()).abs() / prof.duration();
            assert!(
                rel <= 1e-12,
                "n {n}: {} vs {}",
                line.duration(),
                prof.duration()
            );
            let e = line.profile().end();
            assert!(
                (e.p - len).abs() <= 1e-9 * len && e.v.abs() <= 1e-9,
                "n {n}: {e:?}"
            );
        }
    }

    /// Bad input gives its error: lengths first, then non-finite coordinates, then
    /// the axis count, then invalid limits; for the unrolled counts as for the others.
    #[test]
    fn bad_lines_give_their_errors() {
        for n in [2, 3, 5] {
            let start = vec![0.0; n];
            let end = vec![1.0; n];
            let axes = vec![AX; n];
            let msg = |r: Result<Line, PlanError>| match r {
                Err(PlanError::Line(m)) => m,
                other => panic!("{other:?}"),
            };
            assert!(msg(Line::plan(&start, &end[1..], &axes)).contains("start has"));
            for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                let mut bad = end.clone();
                bad[n - 1] = x;
                assert!(msg(Line::plan(&start, &bad, &axes)).contains("non-finite"));
                assert!(msg(Line::plan(&bad, &end, &axes)).contains("non-finite"));
                assert!(msg(Line::plan(&bad, &end, &axes[1..])).contains("non-finite"));
                let mut lim = axes.clone();
                lim[n - 1].amax = x;
                assert_eq!(
                    Line::plan(&start, &end, &lim).unwrap_err(),
                    PlanError::InvalidLimits
                );
            }
            assert!(msg(Line::plan(&start, &end, &axes[1..])).contains("direction components"));
            // A line that does not move is planned (duration 0).
            assert_eq!(Line::plan(&start, &start, &axes).unwrap().duration(), 0.0);
        }
    }
}
