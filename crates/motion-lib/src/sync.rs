//! Synchronized motion: electronic gearing and camming (MC_GearIn, MC_CamIn).
//!
//! Input: a master axis, a ratio or a [`CamTable`] (a C2 cubic spline), and the slave's state
//! when coupling.
//! Output: each cycle the slave set point = coupling law of the master value + a
//! catch-up profile that takes the slave from its own state onto the law (jerk-limited
//! with the slave's limits); InGear/InSync when the catch-up has ended.
//! Invariants: the slave set point is continuous in position and velocity at coupling;
//! a cam table's master positions are strictly increasing; evaluation allocates nothing.

use crate::cmd::CmdStatus;
use crate::engine::{plan_position, Engine, Kind, MasterSource};
use crate::error::ErrorId;
use crate::profile::{Limits, Profile, State};

/// A cam profile: slave position as a function of the master position, a cubic spline
/// through the points (twice continuously differentiable, so that the slave's velocity and
/// acceleration never step; README "Camming"). Two splines are kept: the natural one
/// (second derivative 0 at both ends, continued by straight lines beyond the table) for a
/// single-shot cam, and the periodic one (first and second derivatives equal at both ends,
/// the slave rising by the table's rise every period) for a periodic cam.
#[derive(Clone, Debug, PartialEq)]
pub struct CamTable {
    master: Vec<f64>,
    slave: Vec<f64>,
    /// Second derivatives at the points: natural spline.
    m2_single: Vec<f64>,
    /// Second derivatives at the points: periodic spline.
    m2_periodic: Vec<f64>,
    /// max |f'|, max |f''|, max |f'''| over the table: natural, periodic.
    bounds: [[f64; 3]; 2],
}

/// Solves a tridiagonal system (sub `a`, diagonal `b`, super `c`, right side `r`), Thomas.
fn tridiagonal(a: &[f64], b: &[f64], c: &[f64], r: &[f64]) -> Vec<f64> {
    let n = b.len();
    let mut cp = vec![0.0; n];
    let mut x = vec![0.0; n];
    if n == 0 {
        return x;
    }
    cp[0] = c[0] / b[0];
    x[0] = r[0] / b[0];
    for i in 1..n {
        let m = b[i] - a[i] * cp[i - 1];
        cp[i] = c[i] / m;
        x[i] = (r[i] - a[i] * x[i - 1]) / m;
    }
    for i in (0..n - 1).rev() {
        x[i] -= cp[i] * x[i + 1];
    }
    x
}

/// Solves a cyclic tridiagonal system (row i: a[i] x[i-1] + b[i] x[i] + c[i] x[i+1] = r[i],
/// indices mod n), by Sherman-Morrison for n >= 3.
fn cyclic(a: &[f64], b: &[f64], c: &[f64], r: &[f64]) -> Vec<f64> {
    let n = b.len();
    match n {
        1 => vec![r[0] / (a[0] + b[0] + c[0])],
        2 => {
            // b0 x0 + (a0 + c0) x1 = r0; (a1 + c1) x0 + b1 x1 = r1.
            let (p, q) = (a[0] + c[0], a[1] + c[1]);
            let det = b[0] * b[1] - p * q;
            vec![
                (r[0] * b[1] - p * r[1]) / det,
                (b[0] * r[1] - q * r[0]) / det,
            ]
        }
        _ => {
            let (alpha, beta) = (c[n - 1], a[0]);
            let gamma = -b[0];
            let mut bb = b.to_vec();
            bb[0] = b[0] - gamma;
            bb[n - 1] = b[n - 1] - alpha * beta / gamma;
            let x = tridiagonal(a, &bb, c, r);
            let mut u = vec![0.0; n];
            u[0] = gamma;
            u[n - 1] = alpha;
            let z = tridiagonal(a, &bb, c, &u);
            let f = (x[0] + beta * x[n - 1] / gamma) / (1.0 + z[0] + beta * z[n - 1] / gamma);
            x.iter().zip(&z).map(|(x, z)| x - f * z).collect()
        }
    }
}

impl CamTable {
    /// A table through `points` (master, slave); master strictly increasing, at least 2.
    pub fn new(points: &[(f64, f64)]) -> Result<CamTable, ErrorId> {
        if points.len() < 2
            || points.iter().any(|(m, s)| !m.is_finite() || !s.is_finite())
            || points.windows(2).any(|w| w[1].0 <= w[0].0)
        {
            return Err(ErrorId::InvalidCamTable);
        }
        let master: Vec<f64> = points.iter().map(|p| p.0).collect();
        let slave: Vec<f64> = points.iter().map(|p| p.1).collect();
        let n = master.len();
        let h: Vec<f64> = (0..n - 1).map(|i| master[i + 1] - master[i]).collect();
        let d: Vec<f64> = (0..n - 1)
            .map(|i| (slave[i + 1] - slave[i]) / h[i])
            .collect();
        // Natural spline: M_0 = M_{n-1} = 0, interior rows
        // h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1} = 6 (d_i - d_{i-1}).
        let mut m2_single = vec![0.0; n];
        if n > 2 {
            let k = n - 2;
            let a: Vec<f64> = (1..=k)
                .map(|i| if i == 1 { 0.0 } else { h[i - 1] })
                .collect();
            let b: Vec<f64> = (1..=k).map(|i| 2.0 * (h[i - 1] + h[i])).collect();
            let c: Vec<f64> = (1..=k).map(|i| if i == k { 0.0 } else { h[i] }).collect();
            let r: Vec<f64> = (1..=k).map(|i| 6.0 * (d[i] - d[i - 1])).collect();
            let x = tridiagonal(&a, &b, &c, &r);
            m2_single[1..=k].copy_from_slice(&x);
        }
        // Periodic spline: unknowns M_0 .. M_{n-2}, M_{n-1} = M_0; segment indices cyclic.
        let s = n - 1;
        let prev = |i: usize| (i + s - 1) % s;
        let a: Vec<f64> = (0..s).map(|i| h[prev(i)]).collect();
        let b: Vec<f64> = (0..s).map(|i| 2.0 * (h[prev(i)] + h[i])).collect();
        let c: Vec<f64> = (0..s).map(|i| h[i]).collect();
        let r: Vec<f64> = (0..s).map(|i| 6.0 * (d[i] - d[prev(i)])).collect();
        let mut m2_periodic = cyclic(&a, &b, &c, &r);
        m2_periodic.push(m2_periodic[0]);
        if m2_single.iter().chain(&m2_periodic).any(|x| !x.is_finite()) {
            return Err(ErrorId::InvalidCamTable);
        }
        let mut t = CamTable {
            master,
            slave,
            m2_single,
            m2_periodic,
            bounds: [[0.0; 3]; 2],
        };
        t.bounds = [t.derivative_bounds(false), t.derivative_bounds(true)];
        Ok(t)
    }

    /// First and last master position.
    pub fn master_range(&self) -> (f64, f64) {
        (self.master[0], self.master[self.master.len() - 1])
    }

    /// Slave rise over the table (last - first slave position).
    pub fn slave_rise(&self) -> f64 {
        self.slave[self.slave.len() - 1] - self.slave[0]
    }

    /// max |f'|, max |f''|, max |f'''| of the law (natural or periodic spline) over every
    /// master position (beyond a single-shot table the law is a straight line).
    pub fn bounds(&self, periodic: bool) -> [f64; 3] {
        self.bounds[periodic as usize]
    }

    fn derivative_bounds(&self, periodic: bool) -> [f64; 3] {
        let m2 = if periodic {
            &self.m2_periodic
        } else {
            &self.m2_single
        };
        let mut b = [0.0f64; 3];
        for i in 0..self.master.len() - 1 {
            let h = self.master[i + 1] - self.master[i];
            let (x0, x1) = (self.master[i], self.master[i + 1]);
            let mut d1 = |x: f64| {
                let (_, d, _) = self.segment(m2, i, x);
                b[0] = b[0].max(d.abs());
            };
            d1(x0);
            d1(x1);
            // f' is quadratic on the segment: its extremum where f'' = 0.
            if m2[i] * m2[i + 1] < 0.0 {
                let u = m2[i] / (m2[i] - m2[i + 1]);
                d1(x0 + u * h);
            }
            b[1] = b[1].max(m2[i].abs()).max(m2[i + 1].abs());
            b[2] = b[2].max(((m2[i + 1] - m2[i]) / h).abs());
        }
        b
    }

    /// Position, first and second derivative of segment `i` at `x`.
    fn segment(&self, m2: &[f64], i: usize, x: f64) -> (f64, f64, f64) {
        let (x0, x1) = (self.master[i], self.master[i + 1]);
        let (y0, y1) = (self.slave[i], self.slave[i + 1]);
        let (a, b) = (m2[i], m2[i + 1]);
        let h = x1 - x0;
        let (l, r) = (x1 - x, x - x0);
        let p = a * l * l * l / (6.0 * h)
            + b * r * r * r / (6.0 * h)
            + (y0 / h - a * h / 6.0) * l
            + (y1 / h - b * h / 6.0) * r;
        let dp = -a * l * l / (2.0 * h) + b * r * r / (2.0 * h) + (y1 - y0) / h - (b - a) * h / 6.0;
        let ddp = (a * l + b * r) / h;
        (p, dp, ddp)
    }

    /// Slave position and its first and second derivatives by the master position at `x`.
    /// `periodic`: the periodic spline, `x` taken within the table (clamped); otherwise the
    /// natural spline, continued beyond the table by its end tangents (f'' = 0 there).
    pub fn eval(&self, x: f64, periodic: bool) -> (f64, f64, f64) {
        let (x0, x1) = self.master_range();
        let n = self.master.len();
        if periodic {
            let x = x.clamp(x0, x1);
            return self.segment(&self.m2_periodic, self.index(x), x);
        }
        let m2 = &self.m2_single;
        if x < x0 {
            let (p, d, _) = self.segment(m2, 0, x0);
            return (p + d * (x - x0), d, 0.0);
        }
        if x > x1 {
            let (p, d, _) = self.segment(m2, n - 2, x1);
            return (p + d * (x - x1), d, 0.0);
        }
        self.segment(m2, self.index(x), x)
    }

    fn index(&self, x: f64) -> usize {
        match self.master.partition_point(|&m| m <= x) {
            0 => 0,
            k => (k - 1).min(self.master.len() - 2),
        }
    }
}

/// Coupling law of a synchronized motion (inputs of MC_GearIn / MC_CamIn) plus its
/// runtime anchors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SyncParams {
    /// Index of the master axis.
    pub master: usize,
    /// MasterValueSource: the master's set value or actual value.
    pub source: MasterSource,
    /// Gear ratio (numerator / denominator).
    pub ratio: f64,
    /// CamTableID.
    pub table: usize,
    /// Periodic: TRUE repeats the table (each period the slave advances by the table's rise and
    /// EndOfProfile pulses); FALSE continues the law beyond the table's master range along its end
    /// tangents (a straight line, so the velocity never steps; end the table flat to dwell).
    pub periodic: bool,
    /// MasterAbsolute: TRUE looks the table up with the master's absolute position; FALSE with the
    /// distance the master travelled since coupling.
    pub master_absolute: bool,
    /// SlaveAbsolute: TRUE the table gives the slave's absolute position; FALSE a position relative
    /// to where the slave was at coupling.
    pub slave_absolute: bool,
    /// MasterOffset: subtracted from the master position before the table look-up, in u (table x =
    /// (master - MasterOffset) * MasterScaling).
    pub master_offset: f64,
    /// SlaveOffset: added to the table's slave value, in u (slave = SlaveScaling * y +
    /// SlaveOffset).
    pub slave_offset: f64,
    /// MasterScaling: factor on the master position before the table look-up (finite, non-zero).
    pub master_scaling: f64,
    /// SlaveScaling: factor on the table's slave value (finite).
    pub slave_scaling: f64,
    /// Master raw position at coupling.
    pub(crate) m0: f64,
    /// Slave raw position at coupling.
    pub(crate) s0: f64,
    /// Last period index (EndOfProfile pulses).
    pub(crate) period: i64,
}

impl Default for SyncParams {
    fn default() -> Self {
        SyncParams {
            master: 0,
            source: MasterSource::SetValue,
            ratio: 1.0,
            table: 0,
            periodic: true,
            master_absolute: true,
            slave_absolute: true,
            master_offset: 0.0,
            slave_offset: 0.0,
            master_scaling: 1.0,
            slave_scaling: 1.0,
            m0: 0.0,
            s0: 0.0,
            period: 0,
        }
    }
}

impl SyncParams {
    pub(crate) fn gear(master: usize, ratio: f64, source: MasterSource) -> SyncParams {
        SyncParams {
            master,
            ratio,
            source,
            ..SyncParams::default()
        }
    }

    /// Checks the cam inputs.
    pub fn validate(&self) -> Result<(), ErrorId> {
        let ok = |x: f64| x.is_finite();
        if ok(self.master_offset)
            && ok(self.slave_offset)
            && ok(self.master_scaling)
            && ok(self.slave_scaling)
            && self.master_scaling != 0.0
        {
            Ok(())
        } else {
            Err(ErrorId::InvalidRatio)
        }
    }
}

impl Engine {
    fn master_state(&self, sp: &SyncParams) -> State {
        let m = &self.axes[sp.master];
        match sp.source {
            MasterSource::SetValue => m.set,
            MasterSource::ActualValue => State {
                p: m.act_p,
                v: m.act_v,
                a: 0.0,
            },
        }
    }

    /// Cam law: (slave raw set point: position, velocity and acceleration by the chain
    /// rule, period index, end reached).
    fn cam_law(&self, slave: usize, sp: &SyncParams, m: &State) -> (State, i64, bool) {
        let table = &self.cams[sp.table];
        let mx = &self.axes[sp.master];
        let mrel = if sp.master_absolute {
            m.p + mx.origin
        } else {
            m.p - sp.m0
        };
        let x = (mrel - sp.master_offset) * sp.master_scaling;
        let (x0, x1) = table.master_range();
        let len = x1 - x0;
        let (xw, k, end) = if sp.periodic {
            let k = ((x - x0) / len).floor();
            (x - k * len, k as i64, false)
        } else {
            (x, 0, x >= x1)
        };
        let (y, d1, d2) = table.eval(xw, sp.periodic);
        let rise = if sp.periodic {
            table.slave_rise() * k as f64
        } else {
            0.0
        };
        let user = sp.slave_scaling * (y + rise) + sp.slave_offset;
        let raw = if sp.slave_absolute {
            user - self.axes[slave].origin
        } else {
            user + sp.s0
        };
        // s(t) = ss f(ms (m(t) - off)): s' = ss ms f' m', s'' = ss (ms^2 f'' m'^2 + ms f' m'').
        let (ms, ss) = (sp.master_scaling, sp.slave_scaling);
        let v = ss * ms * d1 * m.v;
        let a = ss * (ms * ms * d2 * m.v * m.v + ms * d1 * m.a);
        (State { p: raw, v, a }, k, end)
    }

    /// What the cam law can take of the slave's limits, for a master moving within its own
    /// axis limits (V, A = max(amax, dmax), J): |v| <= |ss ms| F1 V,
    /// |a| <= |ss| (ms^2 F2 V^2 + |ms| F1 A), |j| <= |ss| (|ms|^3 F3 V^3 + 3 ms^2 F2 V A + |ms| F1 J),
    /// F1..F3 the bounds of the table's first three derivatives. Returns the limits left to
    /// the catch-up profile; ErrorID 33 when the law alone needs all of one of the slave's
    /// limits (README "Camming").
    pub(crate) fn cam_remaining(&self, slave: usize, sp: &SyncParams) -> Result<Limits, ErrorId> {
        let f = self.cams[sp.table].bounds(sp.periodic);
        let (ms, ss) = (sp.master_scaling.abs(), sp.slave_scaling.abs());
        self.law_remaining(slave, sp.master, f, ms, ss)
            .ok_or(ErrorId::CamBeyondSlaveLimits)
    }

    /// What a gear leaves of the slave's limits: a gear is the linear law f(x) = ratio x
    /// (F1 = |ratio|, F2 = F3 = 0), so the slave keeps |ratio| V, |ratio| A and |ratio| J of
    /// the master's axis limits for the coupling and the rest for its catch-up. ErrorID 34
    /// when nothing is left of one of them (README "Gearing").
    pub(crate) fn gear_remaining(&self, slave: usize, sp: &SyncParams) -> Result<Limits, ErrorId> {
        self.law_remaining(slave, sp.master, [sp.ratio.abs(), 0.0, 0.0], 1.0, 1.0)
            .ok_or(ErrorId::GearBeyondSlaveLimits)
    }

    /// The slave's limits less what a coupling law with derivative bounds `f` (F1..F3) and
    /// scalings `ms`, `ss` needs for a master within its axis limits; `None` when one of them
    /// is used up (see [`Engine::cam_remaining`]).
    fn law_remaining(
        &self,
        slave: usize,
        master: usize,
        [f1, f2, f3]: [f64; 3],
        ms: f64,
        ss: f64,
    ) -> Option<Limits> {
        let ml = self.axes[master].cfg.limits;
        let sl = self.axes[slave].cfg.limits;
        let (v, a) = (ml.vmax, ml.amax.max(ml.dmax));
        let j = if ml.jmax > 0.0 {
            ml.jmax
        } else {
            f64::INFINITY
        };
        let sv = ss * ms * f1 * v;
        let sa = ss * (ms * ms * f2 * v * v + ms * f1 * a);
        // 0 * inf (a straight law under a master without a jerk limit) is no jerk.
        let fj = if f1 == 0.0 { 0.0 } else { ms * f1 * j };
        let sj = ss * (ms * ms * ms * f3 * v * v * v + 3.0 * ms * ms * f2 * v * a + fj);
        let rem = Limits {
            vmax: sl.vmax - sv,
            amax: sl.amax.min(sl.dmax) - sa,
            dmax: sl.amax.min(sl.dmax) - sa,
            jmax: if sl.jmax > 0.0 { sl.jmax - sj } else { 0.0 },
        };
        let ok = |x: f64| x.is_finite() && x > 0.0;
        (ok(rem.vmax) && ok(rem.amax) && (sl.jmax == 0.0 || ok(rem.jmax))).then_some(rem)
    }

    /// Plans the coupling of a cam: the catch-up profile from the slave's state onto the
    /// law, within what the law leaves of the slave's limits. ErrorID 33 when the slave's
    /// velocity or acceleration relative to the law does not fit in that (README
    /// "Camming"); the caller refuses the command before anything changes.
    pub(crate) fn plan_cam(
        &self,
        axis: usize,
        sync: &SyncParams,
    ) -> Result<(SyncParams, Profile, Limits), ErrorId> {
        let mut sp = *sync;
        let m = self.master_state(&sp);
        let s = self.axes[axis].set;
        sp.m0 = m.p;
        sp.s0 = s.p;
        let lim = self.cam_remaining(axis, &sp)?;
        let (c, k, _) = self.cam_law(axis, &sp, &m);
        sp.period = k;
        let jerk_free = lim.jmax == 0.0;
        let e = State {
            p: s.p - c.p,
            v: s.v - c.v,
            // Without a jerk limit the acceleration may step.
            a: if jerk_free { 0.0 } else { s.a - c.a },
        };
        // The catch-up must start within its limits and, while its acceleration goes to
        // 0, not carry its velocity past them.
        let peak = if jerk_free {
            e.v.abs()
        } else {
            (e.v + e.a * e.a.abs() / (2.0 * lim.jmax)).abs()
        };
        let tol = 1e-12;
        if e.v.abs() > lim.vmax * (1.0 + tol)
            || e.a.abs() > lim.amax * (1.0 + tol)
            || peak > lim.vmax * (1.0 + tol)
        {
            return Err(ErrorId::CamBeyondSlaveLimits);
        }
        let prof = plan_position(e, 0.0, 0.0, &lim).map_err(|_| ErrorId::PlanningFailed)?;
        Ok((sp, prof, lim))
    }

    /// Couples a geared slave: plans the catch-up profile.
    pub(crate) fn start_sync(&mut self, axis: usize) {
        let mut sp = self.axes[axis].active.sync;
        let m = self.master_state(&sp);
        let s = self.axes[axis].set;
        sp.m0 = m.p;
        sp.s0 = s.p;
        let mut lim = self.axes[axis].active.lim;
        let prof = match self.axes[axis].active.kind {
            Kind::Gear => {
                // The slave moves by the catch-up profile plus ratio * master: the profile
                // gets the slave's limits less the master's axis limits times |ratio|, which
                // MC_GearIn checked to be positive (ErrorID 34, README "Gearing").
                let ml = self.axes[sp.master].cfg.limits;
                let sl = self.axes[axis].cfg.limits;
                let k = sp.ratio.abs();
                let share = |own: f64, slave: f64, master: f64| {
                    own.min((slave - k * master).max(slave * 1e-9))
                };
                lim.vmax = share(lim.vmax, sl.vmax, ml.vmax);
                lim.amax = share(lim.amax, sl.amax.min(sl.dmax), ml.amax.max(ml.dmax));
                lim.dmax = share(lim.dmax, sl.amax.min(sl.dmax), ml.amax.max(ml.dmax));
                // The slave's velocity overshoot while the catch-up removes its
                // acceleration error.
                let ea = s.a - sp.ratio * m.a;
                let peak = |j: f64| (s.v + ea * ea.abs() / (2.0 * j)).abs();
                if sl.jmax == 0.0 && lim.jmax > 0.0 && peak(lim.jmax) > lim.vmax {
                    // No jerk limit on the slave: the block's would carry the catch-up past
                    // its share of the velocity limit (the master takes the rest); none then.
                    lim.jmax = 0.0;
                }
                if sl.jmax > 0.0 {
                    let jm = if ml.jmax > 0.0 { ml.jmax } else { 0.0 };
                    let j = if lim.jmax > 0.0 { lim.jmax } else { sl.jmax };
                    lim.jmax = share(j, sl.jmax, jm);
                    // Coupled while the slave accelerates: a jerk that low would carry
                    // its velocity past its limit; then the slave's jerk less the master's
                    // share, or the slave's own (as for a halt).
                    if peak(lim.jmax) > sl.vmax {
                        let less = sl.jmax - k * jm;
                        lim.jmax = if less > lim.jmax && peak(less) <= sl.vmax {
                            less
                        } else {
                            sl.jmax
                        };
                    }
                }
                let e = State {
                    p: 0.0,
                    v: s.v - sp.ratio * m.v,
                    // Without a jerk limit the acceleration may step.
                    a: if lim.jmax > 0.0 {
                        s.a - sp.ratio * m.a
                    } else {
                        0.0
                    },
                };
                Profile::velocity(e, 0.0, &lim)
            }
            _ => {
                // Cams are planned by `plan_cam` when activated.
                return;
            }
        };
        let a = &mut self.axes[axis].active;
        a.sync = sp;
        a.t = 0.0;
        match prof {
            Ok(p) => a.prof = p,
            Err(_) => {
                let id = a.id;
                if let Some(id) = id {
                    self.cmds.set(id, CmdStatus::Error(ErrorId::PlanningFailed));
                }
                let _ = self.raise_axis_error(axis, ErrorId::PlanningFailed);
            }
        }
    }

    /// One cycle of a slave.
    pub(crate) fn step_sync(&mut self, axis: usize, dt: f64) {
        let sp = self.axes[axis].active.sync;
        let m = self.master_state(&sp);
        let kind = self.axes[axis].active.kind;
        let a = &mut self.axes[axis].active;
        a.t += dt;
        let b = a.prof.at(a.t);
        let synced_now = a.t >= a.prof.duration();
        let id = a.id;
        let set = match kind {
            Kind::Gear => State {
                p: sp.s0 + b.p + sp.ratio * (m.p - sp.m0),
                v: b.v + sp.ratio * m.v,
                a: b.a + sp.ratio * m.a,
            },
            _ => {
                let (c, k, end) = self.cam_law(axis, &sp, &m);
                if let Some(id) = id {
                    let pulse = if sp.periodic { k != sp.period } else { end };
                    self.cmds.set_end_of_profile(id, pulse);
                }
                self.axes[axis].active.sync.period = k;
                State {
                    p: c.p + b.p,
                    v: c.v + b.v,
                    a: c.a + b.a,
                }
            }
        };
        self.axes[axis].set = set;
        let a = &mut self.axes[axis].active;
        if synced_now && !a.released {
            a.released = true;
            if let Some(id) = id {
                self.cmds.set_in_target(id, true);
            }
            if !self.queues[axis].is_empty() {
                if let Some(id) = id {
                    self.cmds.set(id, CmdStatus::Aborted);
                    self.cmds.set_in_target(id, false);
                }
                self.axes[axis].active.id = None;
                self.start_next(axis, 0.0);
            }
        }
        self.check_limits(axis);
    }
}
