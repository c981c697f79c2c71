//! Synchronized motion: electronic gearing and camming (MC_GearIn, MC_CamIn).
//!
//! Input: a master axis, a ratio or a [`CamTable`], and the slave's state when coupling.
//! Output: each cycle the slave set point = coupling law of the master value + a
//! catch-up profile that takes the slave from its own state onto the law (jerk-limited
//! with the slave's limits); InGear/InSync when the catch-up has ended.
//! Invariants: the slave set point is continuous in position and velocity at coupling;
//! a cam table's master positions are strictly increasing; evaluation allocates nothing.

use crate::cmd::CmdStatus;
use crate::engine::{Engine, Kind, MasterSource};
use crate::error::ErrorId;
use crate::profile::{Profile, State};

/// A cam profile: slave position as a function of the master position (cubic Hermite
/// through the points, slopes by finite differences).
#[derive(Clone, Debug, PartialEq)]
pub struct CamTable {
    master: Vec<f64>,
    slave: Vec<f64>,
    slope: Vec<f64>,
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
        let sec = |i: usize| (slave[i + 1] - slave[i]) / (master[i + 1] - master[i]);
        let slope = (0..n)
            .map(|i| {
                if i == 0 {
                    sec(0)
                } else if i == n - 1 {
                    sec(n - 2)
                } else {
                    0.5 * (sec(i - 1) + sec(i))
                }
            })
            .collect();
        Ok(CamTable {
            master,
            slave,
            slope,
        })
    }

    /// First and last master position.
    pub fn master_range(&self) -> (f64, f64) {
        (self.master[0], self.master[self.master.len() - 1])
    }

    /// Slave rise over the table (last - first slave position).
    pub fn slave_rise(&self) -> f64 {
        self.slave[self.slave.len() - 1] - self.slave[0]
    }

    /// Slave position and dslave/dmaster at master position `x` (clamped to the range).
    pub fn eval(&self, x: f64) -> (f64, f64) {
        let (x0, x1) = self.master_range();
        let x = x.clamp(x0, x1);
        let i = match self.master.partition_point(|&m| m <= x) {
            0 => 0,
            k => (k - 1).min(self.master.len() - 2),
        };
        let h = self.master[i + 1] - self.master[i];
        let t = (x - self.master[i]) / h;
        let (p0, p1) = (self.slave[i], self.slave[i + 1]);
        let (m0, m1) = (self.slope[i] * h, self.slope[i + 1] * h);
        let t2 = t * t;
        let t3 = t2 * t;
        let p = (2.0 * t3 - 3.0 * t2 + 1.0) * p0
            + (t3 - 2.0 * t2 + t) * m0
            + (-2.0 * t3 + 3.0 * t2) * p1
            + (t3 - t2) * m1;
        let dp = ((6.0 * t2 - 6.0 * t) * p0
            + (3.0 * t2 - 4.0 * t + 1.0) * m0
            + (-6.0 * t2 + 6.0 * t) * p1
            + (3.0 * t2 - 2.0 * t) * m1)
            / h;
        (p, dp)
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
    /// EndOfProfile pulses); FALSE holds the table's ends beyond its master range.
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

    /// Cam law: (slave raw position, slave velocity, period index, end reached).
    fn cam_law(&self, slave: usize, sp: &SyncParams, m: &State) -> (f64, f64, i64, bool) {
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
        let (y, dy) = table.eval(xw);
        let rise = if sp.periodic {
            table.slave_rise() * k as f64
        } else {
            0.0
        };
        let dy = if !sp.periodic && (x >= x1 || x <= x0) {
            0.0
        } else {
            dy
        };
        let user = sp.slave_scaling * (y + rise) + sp.slave_offset;
        let raw = if sp.slave_absolute {
            user - self.axes[slave].origin
        } else {
            user + sp.s0
        };
        let v = sp.slave_scaling * dy * sp.master_scaling * m.v;
        (raw, v, k, end)
    }

    /// Couples the slave: plans the catch-up profile.
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
                // gets the slave's limits less the master's axis limits times |ratio|
                // (at least a twentieth of the slave's, README "Gearing").
                let ml = self.axes[sp.master].cfg.limits;
                let sl = self.axes[axis].cfg.limits;
                let k = sp.ratio.abs();
                let share = |own: f64, slave: f64, master: f64| {
                    own.min((slave - k * master).max(slave / 20.0))
                };
                lim.vmax = share(lim.vmax, sl.vmax, ml.vmax);
                lim.amax = share(lim.amax, sl.amax.min(sl.dmax), ml.amax.max(ml.dmax));
                lim.dmax = share(lim.dmax, sl.amax.min(sl.dmax), ml.amax.max(ml.dmax));
                // The slave's velocity overshoot while the catch-up removes its
                // acceleration error.
                let ea = s.a - sp.ratio * m.a;
                let peak = |j: f64| (s.v + ea * ea.abs() / (2.0 * j)).abs();
                if sl.jmax == 0.0 && lim.jmax > 0.0 && peak(lim.jmax) > sl.vmax {
                    // No jerk limit on the slave: the block's would overshoot; none then.
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
                let (c, cv, k, _) = self.cam_law(axis, &sp, &m);
                sp.period = k;
                let e = State {
                    p: s.p - c,
                    v: s.v - cv,
                    a: s.a,
                };
                crate::engine::plan_position(e, 0.0, 0.0, &lim)
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
                let (c, cv, k, end) = self.cam_law(axis, &sp, &m);
                if let Some(id) = id {
                    let pulse = if sp.periodic { k != sp.period } else { end };
                    self.cmds.set_end_of_profile(id, pulse);
                }
                self.axes[axis].active.sync.period = k;
                State {
                    p: c + b.p,
                    v: cv + b.v,
                    a: b.a,
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
