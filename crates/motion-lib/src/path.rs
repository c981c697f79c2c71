//! Path geometry of group moves: straight lines, circular arcs and corner blends.
//!
//! Input: points in up to [`MAX_AXES`] coordinates (index = identity in the group).
//! Output: a [`Geometry`] parametrised by its arc length s: position, first and second
//! derivative with respect to s (so axis velocity = d1 * ds/dt, acceleration =
//! d1 * d2s/dt2 + d2 * (ds/dt)^2). Invariants: |d1| = 1 on lines, arcs and blends (closed
//! form); blends have zero curvature at both ends; nothing allocates.

/// Most axes in a group (X, Y, Z, A, B, C, U, V, W and 7 more).
pub const MAX_AXES: usize = 16;

/// Names of the identities in a group (IdentInGroup 0..16).
pub const IDENT_NAMES: [&str; MAX_AXES] = [
    "X", "Y", "Z", "A", "B", "C", "U", "V", "W", "P", "Q", "R", "E", "F", "G", "H",
];

/// A point or vector over the group's axes.
pub type Vecn = [f64; MAX_AXES];

/// One path piece (fixed size, no heap: the blend carries its arc-length table inline).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Geometry {
    /// A straight line: position(s) = `start + s * unit`, s in [0, len].
    Line {
        /// Start point per identity, u.
        start: Vecn,
        /// Unit direction of travel (|unit| = 1).
        unit: Vecn,
        /// Length of the line, u (>= 0).
        len: f64,
    },
    /// Arc in the X/Y/Z sub-space (identities 0..3), the other axes move linearly
    /// (helix) from `start` by `delta`.
    Arc {
        /// Centre of the circle in X/Y/Z, u (CENTER mode: Z = 0, Z moves with `delta`).
        center: [f64; 3],
        /// Unit vector from the centre to the start point.
        e1: [f64; 3],
        /// Unit vector in the circle's plane, 90 degrees from `e1` in the direction of travel.
        e2: [f64; 3],
        /// Radius, u (> 0).
        r: f64,
        /// Angle turned from start to end, radians (in (0, 2 pi]).
        angle: f64,
        /// Start of the linear part per identity (the circle's axes 0).
        start: Vecn,
        /// Linear travel of the other axes over the whole arc (the circle's axes 0).
        delta: Vecn,
        /// Path length of the helix, u: sqrt((r angle)^2 + |delta|^2).
        len: f64,
    },
    /// Corner blend: a symmetric pair of clothoids (Euler spirals) from `start` (on the first
    /// line, heading `u1`) to the point at the same distance after the corner (heading
    /// `u2`). The curvature grows linearly from 0 to its peak at the middle and back to 0,
    /// so the axis acceleration is 0 at both ends (no step) and the jerk stays finite.
    /// The tangent is exact at every s (closed form); the position integrates it with a
    /// fixed Gauss-Legendre rule.
    Blend {
        /// Where the blend leaves the first line, per identity, u.
        start: Vecn,
        /// Where the blend joins the second line, per identity, u.
        end: Vecn,
        /// Unit direction of the first line (the tangent at `start`).
        u1: Vecn,
        /// Unit normal towards the inside of the corner, first half.
        w1: Vecn,
        /// Unit direction of the second line (the tangent at `end`).
        u2: Vecn,
        /// Unit normal towards the inside of the corner seen backwards from `end`.
        w2: Vecn,
        /// Half the deflection angle (the tangent turns by `half` over each half).
        half: f64,
        /// Length of each half.
        l: f64,
        /// Path length of the blend, u (2 l).
        len: f64,
    },
}

fn norm(v: &Vecn) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn sub(a: &Vecn, b: &Vecn) -> Vecn {
    let mut r = [0.0; MAX_AXES];
    for i in 0..MAX_AXES {
        r[i] = a[i] - b[i];
    }
    r
}

fn dot3(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn unit3(a: [f64; 3]) -> Option<[f64; 3]> {
    let n = dot3(&a, &a).sqrt();
    if n > 1e-12 {
        Some([a[0] / n, a[1] / n, a[2] / n])
    } else {
        None
    }
}

fn xyz(v: &Vecn) -> [f64; 3] {
    [v[0], v[1], v[2]]
}

/// How a circle is given (PLCopen MC_CIRC_MODE; C values 0, 1, 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum CircMode {
    /// AuxPoint is a point on the arc between start and end.
    #[default]
    Border,
    /// AuxPoint is the centre (in the X/Y plane; Z moves linearly).
    Center,
    /// AuxPoint (X, Y, Z) is a vector, not a point: the normal of the circle's plane
    /// (through the start point), its length the radius. PathChoice is the direction
    /// of rotation seen from the tip of the normal (counter-clockwise = right-hand rule
    /// about it); of the two arcs of that radius and direction the shorter one (at most
    /// 180 degrees) is taken. The part of EndPoint - StartPoint along the normal is
    /// travelled linearly (a helix). In MC_MoveCircularRelative too AuxPoint is this
    /// vector (it is not offset by the start point).
    Radius,
}

impl CircMode {
    /// From the C value (0 BORDER, 1 CENTER, 2 RADIUS).
    pub fn from_u8(v: u8) -> Option<CircMode> {
        match v {
            0 => Some(CircMode::Border),
            1 => Some(CircMode::Center),
            2 => Some(CircMode::Radius),
            _ => None,
        }
    }
}

impl Geometry {
    /// A straight line from `a` to `b`.
    pub fn line(a: &Vecn, b: &Vecn) -> Geometry {
        let d = sub(b, a);
        let len = norm(&d);
        let mut unit = [0.0; MAX_AXES];
        if len > 0.0 {
            for i in 0..MAX_AXES {
                unit[i] = d[i] / len;
            }
        }
        Geometry::Line {
            start: *a,
            unit,
            len,
        }
    }

    /// A circular arc from `a` to `b` (`aux` per [`CircMode`]); `ccw` is the PathChoice
    /// for centre mode (about +Z) and radius mode (about the normal `aux`). None when
    /// the circle is undefined.
    pub fn arc(a: &Vecn, aux: &Vecn, b: &Vecn, mode: CircMode, ccw: bool) -> Option<Geometry> {
        let (s, e) = (xyz(a), xyz(b));
        let (center, e1, e2, r, angle) = match mode {
            CircMode::Border => {
                let m = xyz(aux);
                let u = [m[0] - s[0], m[1] - s[1], m[2] - s[2]];
                let w = [e[0] - s[0], e[1] - s[1], e[2] - s[2]];
                let n = cross(&u, &w);
                let nn = dot3(&n, &n);
                if nn < 1e-18 * dot3(&u, &u).max(1.0) * dot3(&w, &w).max(1.0) {
                    return None;
                }
                // Circumcentre of s, m, e.
                let uu = dot3(&u, &u);
                let ww = dot3(&w, &w);
                let t1 = cross(&n, &u);
                let t2 = cross(&w, &n);
                let c = [
                    s[0] + (ww * t1[0] + uu * t2[0]) / (2.0 * nn),
                    s[1] + (ww * t1[1] + uu * t2[1]) / (2.0 * nn),
                    s[2] + (ww * t1[2] + uu * t2[2]) / (2.0 * nn),
                ];
                let rs = [s[0] - c[0], s[1] - c[1], s[2] - c[2]];
                let r = dot3(&rs, &rs).sqrt();
                let e1 = unit3(rs)?;
                let nu = unit3(n)?;
                let e2 = cross(&nu, &e1);
                let re = [e[0] - c[0], e[1] - c[1], e[2] - c[2]];
                let mut ang = dot3(&re, &e2).atan2(dot3(&re, &e1));
                if ang <= 0.0 {
                    ang += 2.0 * std::f64::consts::PI;
                }
                (c, e1, e2, r, ang)
            }
            CircMode::Center => {
                let c = [aux[0], aux[1], s[2]];
                let rs = [s[0] - c[0], s[1] - c[1], 0.0];
                let re = [e[0] - c[0], e[1] - c[1], 0.0];
                let r = dot3(&rs, &rs).sqrt();
                let r2 = dot3(&re, &re).sqrt();
                if r < 1e-12 || (r - r2).abs() > 1e-6 * r.max(1.0) {
                    return None;
                }
                let e1 = unit3(rs)?;
                let nz = if ccw {
                    [0.0, 0.0, 1.0]
                } else {
                    [0.0, 0.0, -1.0]
                };
                let e2 = cross(&nz, &e1);
                let mut ang = dot3(&re, &e2).atan2(dot3(&re, &e1));
                if ang <= 1e-12 {
                    ang += 2.0 * std::f64::consts::PI;
                }
                (c, e1, e2, r, ang)
            }
            CircMode::Radius => return Self::arc_by_radius(a, aux, b, ccw),
        };
        let mut start = *a;
        let mut delta = sub(b, a);
        let circle_axes = if mode == CircMode::Center { 2 } else { 3 };
        for i in 0..circle_axes {
            start[i] = 0.0;
            delta[i] = 0.0;
        }
        let center = if mode == CircMode::Center {
            [center[0], center[1], 0.0]
        } else {
            center
        };
        Some(Self::helix(center, e1, e2, r, angle, start, delta))
    }

    /// An arc of radius `r` turning `angle` from `center + r e1` towards `e2`, plus the
    /// linear motion `delta` from `start` (the arc's axes zero in both).
    fn helix(
        center: [f64; 3],
        e1: [f64; 3],
        e2: [f64; 3],
        r: f64,
        angle: f64,
        start: Vecn,
        delta: Vecn,
    ) -> Geometry {
        let arc_len = r * angle;
        let len = (arc_len * arc_len + norm(&delta).powi(2)).sqrt();
        Geometry::Arc {
            center,
            e1,
            e2,
            r,
            angle,
            start,
            delta,
            len,
        }
    }

    /// CircMode RADIUS (see [`CircMode::Radius`]): the shorter arc of radius |n| in the
    /// plane through `a` normal to `n` (X/Y/Z of `aux`), turning about `n` (ccw) or
    /// about -n (clockwise) from `a` to `b`. None when n is zero, the chord in the plane
    /// is zero or longer than the diameter.
    fn arc_by_radius(a: &Vecn, aux: &Vecn, b: &Vecn, ccw: bool) -> Option<Geometry> {
        let n = xyz(aux);
        let r = dot3(&n, &n).sqrt();
        let nu = unit3(n)?;
        let axis = if ccw { nu } else { [-nu[0], -nu[1], -nu[2]] };
        let (s, e) = (xyz(a), xyz(b));
        let w = [e[0] - s[0], e[1] - s[1], e[2] - s[2]];
        let along = dot3(&w, &nu);
        let wp = [
            w[0] - along * nu[0],
            w[1] - along * nu[1],
            w[2] - along * nu[2],
        ];
        let chord = dot3(&wp, &wp).sqrt();
        if chord < 1e-12 * r.max(1.0) || chord > 2.0 * r * (1.0 + 1e-12) {
            return None;
        }
        // The centre lies left of the chord seen from the tip of the rotation axis.
        let h = (r * r - chord * chord / 4.0).max(0.0).sqrt();
        let left = unit3(cross(&axis, &wp))?;
        let c = [
            s[0] + wp[0] / 2.0 + h * left[0],
            s[1] + wp[1] / 2.0 + h * left[1],
            s[2] + wp[2] / 2.0 + h * left[2],
        ];
        let rs = [s[0] - c[0], s[1] - c[1], s[2] - c[2]];
        let e1 = unit3(rs)?;
        let e2 = cross(&axis, &e1);
        let re = [
            s[0] + wp[0] - c[0],
            s[1] + wp[1] - c[1],
            s[2] + wp[2] - c[2],
        ];
        let angle = dot3(&re, &e2).atan2(dot3(&re, &e1));
        if angle <= 0.0 {
            return None;
        }
        let mut start = *a;
        let mut delta = sub(b, a);
        for i in 0..3 {
            start[i] = 0.0;
            delta[i] = along * nu[i];
        }
        Some(Self::helix(c, e1, e2, r, angle, start, delta))
    }

    /// The corner blend at `corner` between a line arriving with unit direction `u1` and
    /// one leaving with `u2`, starting and ending `d` from the corner. None when the lines
    /// are parallel (no corner) or reverse (no blend can turn by 180 degrees).
    pub fn corner_blend(corner: &Vecn, u1: &Vecn, u2: &Vecn, d: f64, n: usize) -> Option<Geometry> {
        let c: f64 = (0..n).map(|i| u1[i] * u2[i]).sum::<f64>().clamp(-1.0, 1.0);
        let alpha = c.acos();
        let usable = d > 0.0 && alpha > 1e-9 && alpha <= std::f64::consts::PI - 1e-6;
        if !usable {
            return None;
        }
        let half = alpha / 2.0;
        let mut w1 = [0.0; MAX_AXES];
        let mut w2 = [0.0; MAX_AXES];
        for i in 0..n {
            w1[i] = u2[i] - c * u1[i];
            w2[i] = c * u2[i] - u1[i];
        }
        let (n1, n2) = (norm(&w1), norm(&w2));
        if n1 < 1e-12 || n2 < 1e-12 {
            return None;
        }
        for i in 0..n {
            w1[i] /= n1;
            w2[i] /= n2;
        }
        let (fx, fy) = fresnel(half, 1.0);
        let l = d / (fx + fy * half.tan());
        let mut start = *corner;
        let mut end = *corner;
        for i in 0..n {
            start[i] -= u1[i] * d;
            end[i] += u2[i] * d;
        }
        Some(Geometry::Blend {
            start,
            end,
            u1: *u1,
            w1,
            u2: *u2,
            w2,
            half,
            l,
            len: 2.0 * l,
        })
    }

    /// Corner distance of the blend of [`Geometry::corner_blend`] whose midpoint, its
    /// closest point to the corner, is `e` away from the corner (deflection `alpha`).
    pub fn blend_distance_for_deviation(e: f64, alpha: f64) -> f64 {
        let half = alpha / 2.0;
        let (fx, fy) = fresnel(half, 1.0);
        if fy <= 0.0 {
            return 0.0;
        }
        let l = e * half.cos() / fy;
        l * (fx + fy * half.tan())
    }

    /// Upper bounds, per axis, of |d1|, |d2| and |d3| (derivatives by arc length) over the
    /// piece: at constant path speed v an axis moves at v |d1|, accelerates at v^2 |d2| and
    /// jerks at v^3 |d3|. Blends only (lines: d1 = unit, d2 = d3 = 0).
    pub fn blend_bounds(&self, n: usize) -> Option<(Vecn, Vecn, Vecn)> {
        let Geometry::Blend {
            u1,
            w1,
            u2,
            w2,
            half,
            l,
            ..
        } = self
        else {
            return None;
        };
        // theta(s) = half (s / l)^2 on each half: theta' <= 2 half / l, theta'' = 2 half / l^2.
        let k1 = 2.0 * half / l;
        let k2 = 2.0 * half / (l * l);
        let (mut b1, mut b2, mut b3) = ([0.0; MAX_AXES], [0.0; MAX_AXES], [0.0; MAX_AXES]);
        for i in 0..n {
            let mut t_max: f64 = 0.0;
            let mut n_max: f64 = 0.0;
            // First half: tangent cos th u1 + sin th w1, normal -sin th u1 + cos th w1;
            // second half: tangent cos th u2 - sin th w2, normal sin th u2 + cos th w2.
            t_max = t_max
                .max(max_abs_cos(u1[i], w1[i], *half))
                .max(max_abs_cos(u2[i], -w2[i], *half));
            n_max = n_max
                .max(max_abs_cos(w1[i], -u1[i], *half))
                .max(max_abs_cos(w2[i], u2[i], *half));
            b1[i] = t_max;
            b2[i] = k1 * n_max;
            b3[i] = k2 * n_max + k1 * k1 * t_max;
        }
        Some((b1, b2, b3))
    }

    /// Arc length.
    pub fn len(&self) -> f64 {
        match self {
            Geometry::Line { len, .. }
            | Geometry::Arc { len, .. }
            | Geometry::Blend { len, .. } => *len,
        }
    }

    /// Position, d/ds and d2/ds2 at arc length `s` (lines and arcs extrapolate beyond
    /// their ends; blends continue along their end tangent).
    pub fn eval(&self, s: f64, n: usize, pos: &mut Vecn, d1: &mut Vecn, d2: &mut Vecn) {
        match self {
            Geometry::Line { start, unit, .. } => {
                for i in 0..n {
                    pos[i] = start[i] + s * unit[i];
                    d1[i] = unit[i];
                    d2[i] = 0.0;
                }
            }
            Geometry::Arc {
                center,
                e1,
                e2,
                r,
                angle,
                start,
                delta,
                len,
            } => {
                let k = if *len > 0.0 { angle / len } else { 0.0 };
                let phi = k * s;
                let (sn, cs) = phi.sin_cos();
                for i in 0..n {
                    if i < 3 {
                        pos[i] = center[i]
                            + r * (cs * e1[i] + sn * e2[i])
                            + start[i]
                            + delta[i] * s / len;
                        d1[i] = r * k * (-sn * e1[i] + cs * e2[i]) + delta[i] / len;
                        d2[i] = -r * k * k * (cs * e1[i] + sn * e2[i]);
                    } else {
                        pos[i] = start[i] + delta[i] * s / len;
                        d1[i] = delta[i] / len;
                        d2[i] = 0.0;
                    }
                }
            }
            Geometry::Blend {
                start,
                end,
                u1,
                w1,
                u2,
                w2,
                half,
                l,
                len,
            } => {
                let sc = s.clamp(0.0, *len);
                let extra = s - sc;
                // First half from `start`; second half mirrored from `end`.
                let (second, sig) = if sc <= *l {
                    (false, sc)
                } else {
                    (true, len - sc)
                };
                let th = half * (sig / l) * (sig / l);
                let dth = 2.0 * half * sig / (l * l);
                let (sn, cs) = th.sin_cos();
                let (x, y) = fresnel(*half, sig / l);
                for i in 0..n {
                    if !second {
                        pos[i] = start[i] + l * (x * u1[i] + y * w1[i]);
                        d1[i] = cs * u1[i] + sn * w1[i];
                        d2[i] = dth * (-sn * u1[i] + cs * w1[i]);
                    } else {
                        pos[i] = end[i] - l * (x * u2[i] - y * w2[i]);
                        d1[i] = cs * u2[i] - sn * w2[i];
                        d2[i] = dth * (sn * u2[i] + cs * w2[i]);
                    }
                    if extra != 0.0 {
                        d2[i] = 0.0;
                    }
                    pos[i] += extra * d1[i];
                }
            }
        }
    }

    /// Largest curvature (1/radius) along the piece (sampled).
    pub fn max_curvature(&self, _n: usize) -> f64 {
        match self {
            Geometry::Line { .. } => 0.0,
            Geometry::Arc { r, angle, len, .. } => {
                if *len > 0.0 {
                    r * (angle / len) * (angle / len)
                } else {
                    0.0
                }
            }
            Geometry::Blend { half, l, .. } => 2.0 * half / l,
        }
    }

    /// Largest |d3 p / ds3| of any axis along the piece (the rate at which the curvature
    /// vector turns): r k^3 on an arc (k = angle / len), 0 on a line. Blends: see
    /// [`Geometry::blend_bounds`].
    pub fn max_d3(&self) -> f64 {
        match self {
            Geometry::Arc { r, angle, len, .. } if *len > 0.0 => {
                let k = angle / len;
                r * k * k * k
            }
            _ => 0.0,
        }
    }

    /// Lowest and highest coordinate of every axis (raw units, by identity) on the piece
    /// between arc lengths `s0 <= s1` (lines extrapolate beyond their ends). Arcs: exact,
    /// from the ends and the angles where an axis's coordinate
    /// `A cos(phi) + B sin(phi) + C phi + D` has a zero derivative; `s0`, `s1` are clamped
    /// to the arc.
    pub fn axis_range(&self, n: usize, s0: f64, s1: f64) -> (Vecn, Vecn) {
        let (mut lo, mut hi) = ([f64::INFINITY; MAX_AXES], [f64::NEG_INFINITY; MAX_AXES]);
        let (mut p, mut d1, mut d2) = ([0.0; MAX_AXES], [0.0; MAX_AXES], [0.0; MAX_AXES]);
        let mut see = |s: f64, lo: &mut Vecn, hi: &mut Vecn| {
            self.eval(s, n, &mut p, &mut d1, &mut d2);
            for i in 0..n {
                lo[i] = lo[i].min(p[i]);
                hi[i] = hi[i].max(p[i]);
            }
        };
        match self {
            Geometry::Arc {
                e1,
                e2,
                r,
                angle,
                delta,
                len,
                ..
            } if *len > 0.0 && *angle > 0.0 => {
                let (a, b) = (s0.clamp(0.0, *len), s1.clamp(0.0, *len));
                see(a, &mut lo, &mut hi);
                see(b, &mut lo, &mut hi);
                let k = angle / len;
                for i in 0..n.min(3) {
                    // x_i(phi) = r (cos phi e1 + sin phi e2) + delta phi / angle + const.
                    let (ca, cb, cc) = (r * e1[i], r * e2[i], delta[i] / angle);
                    let rr = (ca * ca + cb * cb).sqrt();
                    if rr <= 0.0 || cc.abs() > rr {
                        continue;
                    }
                    // -ca sin phi + cb cos phi + cc = 0, i.e. rr cos(phi + th) = -cc.
                    let th = ca.atan2(cb);
                    let base = (-cc / rr).clamp(-1.0, 1.0).acos();
                    let tau = std::f64::consts::TAU;
                    for root in [base - th, -base - th] {
                        let mut phi = root.rem_euclid(tau);
                        while phi <= b * k {
                            if phi >= a * k {
                                let mut q = [0.0; MAX_AXES];
                                let (mut g1, mut g2) = ([0.0; MAX_AXES], [0.0; MAX_AXES]);
                                self.eval(phi / k, n, &mut q, &mut g1, &mut g2);
                                lo[i] = lo[i].min(q[i]);
                                hi[i] = hi[i].max(q[i]);
                            }
                            phi += tau;
                        }
                    }
                }
            }
            _ => {
                see(s0, &mut lo, &mut hi);
                see(s1, &mut lo, &mut hi);
                if let Geometry::Blend { len, .. } = self {
                    // Sampled (a blend's deviation from its chord is small and convex).
                    for j in 1..16 {
                        let s = (j as f64 / 16.0 * len).clamp(s0, s1);
                        see(s, &mut lo, &mut hi);
                    }
                }
            }
        }
        (lo, hi)
    }

    /// Unit tangent at the start and at the end.
    pub fn tangents(&self, n: usize) -> (Vecn, Vecn) {
        let (mut p, mut a, mut b, mut d2) = (
            [0.0; MAX_AXES],
            [0.0; MAX_AXES],
            [0.0; MAX_AXES],
            [0.0; MAX_AXES],
        );
        self.eval(0.0, n, &mut p, &mut a, &mut d2);
        self.eval(self.len(), n, &mut p, &mut b, &mut d2);
        (a, b)
    }
}

/// max over theta in [0, half] of |a cos theta + b sin theta| (half <= pi/2).
fn max_abs_cos(a: f64, b: f64, half: f64) -> f64 {
    let f = |t: f64| (a * t.cos() + b * t.sin()).abs();
    let mut m = f(0.0).max(f(half));
    // Stationary point: tan theta = b / a.
    let t = b.atan2(a);
    for t in [t, t + std::f64::consts::PI, t - std::f64::consts::PI] {
        if (0.0..=half).contains(&t) {
            m = m.max(f(t));
        }
    }
    m
}

/// (int_0^x cos(beta t^2) dt, int_0^x sin(beta t^2) dt) for 0 <= x <= 1, beta <= pi/2:
/// 16-point Gauss-Legendre (the integrand is smooth; error below 1e-15).
fn fresnel(beta: f64, x: f64) -> (f64, f64) {
    const XS: [f64; 8] = [
        0.095_012_509_837_637_44,
        0.281_603_550_779_258_9,
        0.458_016_777_657_227_4,
        0.617_876_244_402_643_7,
        0.755_404_408_355_003,
        0.865_631_202_387_831_7,
        0.944_575_023_073_232_6,
        0.989_400_934_991_649_9,
    ];
    const WS: [f64; 8] = [
        0.189_450_610_455_068_5,
        0.182_603_415_044_923_6,
        0.169_156_519_395_002_5,
        0.149_595_988_816_576_7,
        0.124_628_971_255_533_9,
        0.095_158_511_682_492_78,
        0.062_253_523_938_647_89,
        0.027_152_459_411_754_09,
    ];
    let h = x / 2.0;
    let (mut c, mut s) = (0.0, 0.0);
    for k in 0..8 {
        for t in [h * (1.0 - XS[k]), h * (1.0 + XS[k])] {
            let (sn, cs) = (beta * t * t).sin_cos();
            c += WS[k] * cs;
            s += WS[k] * sn;
        }
    }
    (c * h, s * h)
}
