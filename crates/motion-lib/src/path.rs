//! Path geometry of group moves: straight lines, circular arcs and corner blends.
//!
//! Input: points in up to [`MAX_AXES`] coordinates (index = identity in the group).
//! Output: a [`Geometry`] parametrised by its arc length s: position, first and second
//! derivative with respect to s (so axis velocity = d1 * ds/dt, acceleration =
//! d1 * d2s/dt2 + d2 * (ds/dt)^2). Invariants: |d1| = 1 on lines, arcs and (to the table's
//! accuracy) blends; nothing allocates.

/// Most axes in a group (X, Y, Z, A, B, C, U, V, W and 7 more).
pub const MAX_AXES: usize = 16;

/// Names of the identities in a group (IdentInGroup 0..16).
pub const IDENT_NAMES: [&str; MAX_AXES] = [
    "X", "Y", "Z", "A", "B", "C", "U", "V", "W", "P", "Q", "R", "E", "F", "G", "H",
];

/// A point or vector over the group's axes.
pub type Vecn = [f64; MAX_AXES];

const TABLE: usize = 32;

/// One path piece (fixed size, no heap: the blend carries its arc-length table inline).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Geometry {
    Line {
        start: Vecn,
        unit: Vecn,
        len: f64,
    },
    /// Arc in the X/Y/Z sub-space (identities 0..3), the other axes move linearly
    /// (helix) from `start` by `delta`.
    Arc {
        center: [f64; 3],
        e1: [f64; 3],
        e2: [f64; 3],
        r: f64,
        angle: f64,
        start: Vecn,
        delta: Vecn,
        len: f64,
    },
    /// Quadratic Bezier corner blend p0 -> (control p1) -> p2, with an arc-length table.
    Blend {
        p0: Vecn,
        p1: Vecn,
        p2: Vecn,
        len: f64,
        table: [f64; TABLE + 1],
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

    /// The corner blend from `p0` through control `p1` to `p2`.
    pub fn blend(p0: &Vecn, p1: &Vecn, p2: &Vecn) -> Geometry {
        let mut table = [0.0; TABLE + 1];
        let mut prev = *p0;
        for (k, slot) in table.iter_mut().enumerate().skip(1) {
            let p = bezier(p0, p1, p2, k as f64 / TABLE as f64);
            let mut acc = 0.0;
            // Sub-sample each table step for accuracy.
            let mut q = prev;
            for j in 1..=8 {
                let u = (k as f64 - 1.0 + j as f64 / 8.0) / TABLE as f64;
                let r = bezier(p0, p1, p2, u);
                acc += norm(&sub(&r, &q));
                q = r;
            }
            *slot = acc;
            prev = p;
        }
        for k in 1..=TABLE {
            table[k] += table[k - 1];
        }
        Geometry::Blend {
            p0: *p0,
            p1: *p1,
            p2: *p2,
            len: table[TABLE],
            table,
        }
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
                p0,
                p1,
                p2,
                len,
                table,
            } => {
                let sc = s.clamp(0.0, *len);
                let k = table.partition_point(|&x| x <= sc).clamp(1, TABLE);
                let (a, b) = (table[k - 1], table[k]);
                let f = if b > a { (sc - a) / (b - a) } else { 0.0 };
                let u = ((k - 1) as f64 + f) / TABLE as f64;
                let p = bezier(p0, p1, p2, u);
                let mut b1 = [0.0; MAX_AXES];
                let mut b2 = [0.0; MAX_AXES];
                for i in 0..n {
                    b1[i] = 2.0 * (1.0 - u) * (p1[i] - p0[i]) + 2.0 * u * (p2[i] - p1[i]);
                    b2[i] = 2.0 * (p2[i] - 2.0 * p1[i] + p0[i]);
                }
                let n1 = norm(&b1).max(1e-12);
                let dd: f64 = (0..n).map(|i| b1[i] * b2[i]).sum();
                let extra = s - sc;
                for i in 0..n {
                    d1[i] = b1[i] / n1;
                    d2[i] = if extra == 0.0 {
                        (b2[i] * n1 * n1 - b1[i] * dd) / (n1 * n1 * n1 * n1)
                    } else {
                        0.0
                    };
                    pos[i] = p[i] + extra * d1[i];
                }
            }
        }
    }

    /// Largest curvature (1/radius) along the piece (sampled).
    pub fn max_curvature(&self, n: usize) -> f64 {
        match self {
            Geometry::Line { .. } => 0.0,
            Geometry::Arc { r, angle, len, .. } => {
                if *len > 0.0 {
                    r * (angle / len) * (angle / len)
                } else {
                    0.0
                }
            }
            Geometry::Blend { len, .. } => {
                let (mut p, mut d1, mut d2) = ([0.0; MAX_AXES], [0.0; MAX_AXES], [0.0; MAX_AXES]);
                let mut k: f64 = 0.0;
                for j in 0..=TABLE {
                    self.eval(len * j as f64 / TABLE as f64, n, &mut p, &mut d1, &mut d2);
                    k = k.max(norm(&d2));
                }
                k
            }
        }
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

fn bezier(p0: &Vecn, p1: &Vecn, p2: &Vecn, u: f64) -> Vecn {
    let mut r = [0.0; MAX_AXES];
    let (a, b, c) = ((1.0 - u) * (1.0 - u), 2.0 * u * (1.0 - u), u * u);
    for i in 0..MAX_AXES {
        r[i] = a * p0[i] + b * p1[i] + c * p2[i];
    }
    r
}
