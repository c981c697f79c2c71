//! The axis's command buffer: updating a queued command, linking a buffered move to its
//! predecessor (the junction velocity of a blend), and activating the next command.
//!
//! Input: pending commands in the queue. Output: the active profile of each axis.
//! Invariant: a blended junction never exceeds the limits of either move.

use super::*;

impl Engine {
    /// ContinuousUpdate: new inputs for a command that is still Busy.
    pub fn update(
        &mut self,
        axis: usize,
        id: CmdId,
        cmd: AxisCommand,
        dynamics: Dynamics,
    ) -> Result<(), ErrorId> {
        self.axis(axis)?;
        let st = self.cmds.status(id);
        if self.axes[axis].active.id == Some(id) && st == CmdStatus::Active {
            let buffer = BufferMode::Aborting;
            let mut p = self.resolve(axis, &cmd, &dynamics, buffer, id, None)?;
            if matches!(
                cmd,
                AxisCommand::MoveAdditive { .. } | AxisCommand::MoveRelative { .. }
            ) {
                // The target of a relative move does not move with the axis.
                return Ok(());
            }
            let cur = &self.axes[axis].active;
            if cur.kind == p.kind && cur.target == p.target && cur.base == p.lim {
                // Inputs unchanged: keep the running profile.
                return Ok(());
            }
            p.end_v = cur.end_v;
            let released = cur.released;
            self.activate(axis, p, 0.0)?;
            if p.kind == Kind::Velocity && released {
                self.cmds.set_in_target(id, false);
            }
        } else if st == CmdStatus::Queued {
            let p = {
                let q = self.queues[axis].iter().find(|p| p.id == id).copied();
                match q {
                    Some(q) => {
                        let mut n = self.resolve(axis, &cmd, &dynamics, q.buffer, id, None)?;
                        n.end_v = q.end_v;
                        n
                    }
                    None => return Ok(()),
                }
            };
            for q in self.queues[axis].iter_mut() {
                if q.id == id {
                    *q = p;
                }
            }
        }
        Ok(())
    }

    /// A blending successor joins the last command: set its end velocity.
    pub(super) fn link_successor(&mut self, axis: usize, next: &Pending) {
        if !next.buffer.is_blending() {
            return;
        }
        let (pred_kind, pred_target, pred_speed, pred_from) = match self.queues[axis].back() {
            Some(b) => (b.kind, b.target, b.speed, None),
            None => {
                let a = &self.axes[axis].active;
                (a.kind, a.target, a.speed, Some(self.axes[axis].set))
            }
        };
        if pred_kind != Kind::Position {
            return;
        }
        // Direction of the predecessor at its end and of the successor at its start.
        let start_p = match pred_from {
            Some(_) => self.axes[axis].active.prof.start().p,
            None => {
                let q = &self.queues[axis];
                if q.len() >= 2 {
                    q.iter()
                        .nth(q.len() - 2)
                        .map(|p| p.target)
                        .unwrap_or(pred_target)
                } else {
                    self.axes[axis].active.target
                }
            }
        };
        let d1 = (pred_target - start_p).signum();
        let d2 = match next.kind {
            Kind::Position => (next.target - pred_target).signum(),
            Kind::Velocity => next.target.signum(),
            _ => 0.0,
        };
        let vj = if d1 != 0.0 && d1 == d2 {
            d1 * next.buffer.junction_speed(pred_speed, next.speed)
        } else {
            0.0
        };
        match pred_from {
            None => {
                if let Some(b) = self.queues[axis].back_mut() {
                    b.end_v = vj;
                }
            }
            Some(now) => {
                let a = &mut self.axes[axis].active;
                if a.paused {
                    // Held by VelFactor 0: the resumed plan ends at vj.
                    a.end_v = vj;
                    return;
                }
                if let Ok((p, tail)) = plan_to(now, a.target, vj, &a.lim) {
                    a.prof = p;
                    a.tail = tail;
                    a.t = 0.0;
                    a.end_v = vj;
                }
            }
        }
    }

    /// Makes `p` the active command of the axis, starting from the current set point
    /// advanced by `t0` seconds into its profile.
    pub(super) fn activate(&mut self, axis: usize, mut p: Pending, t0: f64) -> Result<(), ErrorId> {
        let start = self.axes[axis].set;
        if let Some(d) = p.relative {
            p.target = start.p + d;
            Self::check_target(&self.axes[axis], p.target)?;
        }
        let mut lim = p.lim;
        let mut tail = None;
        let mut paused = false;
        let prof = match p.kind {
            Kind::Position | Kind::Velocity | Kind::Halt => {
                let ax = &self.axes[axis];
                overridden(ax, p.kind, &p.lim, start, p.target, p.end_v).map(|o| {
                    (lim, tail, paused) = (o.lim, o.tail, o.paused);
                    o.prof
                })
            }
            Kind::Stop => {
                // Not overridden; the jerk raised as for a halt (see `overridden`).
                let al = self.axes[axis].cfg.limits;
                if lim.jmax > 0.0 && (al.jmax == 0.0 || al.jmax > lim.jmax) {
                    let peak = (start.v + start.a * start.a.abs() / (2.0 * lim.jmax)).abs();
                    if peak > al.vmax {
                        lim.jmax = al.jmax;
                    }
                }
                lim.vmax = lim.vmax.max(start.v.abs());
                Profile::velocity(start, 0.0, &lim).map_err(|_| ErrorId::PlanningFailed)
            }
            Kind::Gear | Kind::Cam => Ok(self.axes[axis].active.prof),
            _ => Ok(Active::idle(start).prof),
        }
        .map_err(|_| ErrorId::PlanningFailed)?;
        if p.kind == Kind::Position {
            Self::check_path(&self.axes[axis], &prof, tail.as_ref())?;
        }
        let cam = if p.kind == Kind::Cam {
            Some(self.plan_cam(axis, &p.sync)?)
        } else {
            None
        };
        let ax = &mut self.axes[axis];
        let class = match p.kind {
            Kind::Position | Kind::Halt => AxisState::DiscreteMotion,
            Kind::Velocity => AxisState::ContinuousMotion,
            Kind::Stop => AxisState::Stopping,
            Kind::Home => AxisState::Homing,
            Kind::Gear | Kind::Cam => AxisState::SynchronizedMotion,
            _ => ax.state,
        };
        ax.state = class;
        ax.active = Active {
            kind: p.kind,
            id: Some(p.id),
            prof,
            t: t0,
            target: p.target,
            speed: p.speed,
            lim,
            base: p.lim,
            paused,
            released: false,
            end_v: p.end_v,
            sync: p.sync,
            tail,
            limit_stop: None,
        };
        if p.kind == Kind::Stop {
            ax.stop_owner = Some(p.id);
        }
        self.cmds.set(p.id, CmdStatus::Active);
        match p.kind {
            Kind::Home => {
                if let Some(d) = self.drives[axis].as_mut() {
                    d.start_homing();
                }
            }
            Kind::Gear => {
                self.start_sync(axis);
            }
            Kind::Cam => {
                if let Some((sync, prof, lim)) = cam {
                    // The catch-up starts from the state it was planned from (as gearing).
                    let a = &mut self.axes[axis].active;
                    (a.sync, a.prof, a.lim, a.t) = (sync, prof, lim, 0.0);
                }
            }
            _ => {
                let a = &self.axes[axis].active;
                if t0 > 0.0 {
                    let s = a.prof.at(t0);
                    self.axes[axis].set = s;
                }
            }
        }
        Ok(())
    }

    /// GearOut / CamOut: the slave keeps its current velocity (ContinuousMotion).
    pub(super) fn sync_out(&mut self, axis: usize, kind: Kind) -> Result<CmdId, ErrorId> {
        if self.axes[axis].active.kind != kind {
            return Err(ErrorId::NotSynchronized);
        }
        self.abort_all(axis, CmdStatus::Aborted);
        let ax = &mut self.axes[axis];
        let start = ax.set;
        let mut lim = ax.cfg.limits;
        lim.vmax = lim.vmax.max(start.v.abs());
        let prof = Profile::velocity(start, start.v, &lim).map_err(|_| ErrorId::PlanningFailed)?;
        ax.active = Active {
            kind: Kind::Velocity,
            id: None,
            prof,
            t: 0.0,
            target: start.v,
            speed: start.v.abs(),
            lim,
            base: lim,
            paused: false,
            released: true,
            end_v: 0.0,
            sync: SyncParams::default(),
            tail: None,
            limit_stop: None,
        };
        ax.state = AxisState::ContinuousMotion;
        let id = self.cmds.alloc(CmdStatus::Done);
        Ok(id)
    }

    pub(super) fn junction_after(&self, axis: usize, p: &Pending, n: &Pending) -> f64 {
        if p.kind != Kind::Position || !n.buffer.is_blending() {
            return 0.0;
        }
        let from = self.axes[axis].set.p;
        let d1 = (p.target - from).signum();
        let d2 = match n.kind {
            Kind::Position => (n.target - p.target).signum(),
            Kind::Velocity => n.target.signum(),
            _ => 0.0,
        };
        if d1 != 0.0 && d1 == d2 {
            d1 * n.buffer.junction_speed(p.speed, n.speed)
        } else {
            0.0
        }
    }

    /// Starts the next buffered command, if any.
    pub(crate) fn start_next(&mut self, axis: usize, t0: f64) {
        while let Some(p) = self.queues[axis].pop() {
            // Its own successor may blend with it: compute its end velocity.
            let mut p = p;
            if let Some(n) = self.queues[axis].front().copied() {
                p.end_v = self.junction_after(axis, &p, &n);
            }
            match self.activate(axis, p, t0) {
                Ok(()) => {
                    let a = &self.axes[axis].active;
                    if matches!(a.kind, Kind::Position | Kind::Halt)
                        && a.t >= a.prof.duration()
                        && a.tail.is_none()
                        && !a.paused
                    {
                        // Already over within this cycle (a halt at rest, a zero move): end
                        // it now, so that its successor runs the rest of this cycle.
                        self.axis_event(axis);
                    }
                    return;
                }
                Err(e) => {
                    // Only the active block failed: the next buffered block starts.
                    self.cmds.set(p.id, CmdStatus::Error(e));
                }
            }
        }
        let ax = &mut self.axes[axis];
        if ax.active.kind == Kind::Idle && ax.state != AxisState::ErrorStop {
            if ax.set.v != 0.0 || ax.set.a != 0.0 {
                // Left at a junction speed with no successor running (it failed): brake
                // to rest within the axis's limits instead of stopping at once.
                let lim = ax.cfg.limits;
                if let Ok(p) = Profile::velocity(ax.set, 0.0, &lim) {
                    let at = ax.set;
                    ax.active = Active::idle(at);
                    ax.active.kind = Kind::Halt;
                    ax.active.prof = p;
                    ax.active.released = false;
                    ax.state = AxisState::DiscreteMotion;
                    return;
                }
            }
            ax.state = AxisState::Standstill;
            ax.set.v = 0.0;
            ax.set.a = 0.0;
        }
    }
}
