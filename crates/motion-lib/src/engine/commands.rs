//! A motion command from a block, checked and planned: the limits it may use (reduced to the
//! axis's, with the reduction reported), its path against the software limits, and its place
//! in the axis's buffer.
//!
//! Input: [`AxisCommand`]s with their dynamics and BufferMode. Output: a command id, or the
//! PLCopen ErrorID that refuses it. Invariant: a planned path never leaves the software limits
//! nor exceeds the axis's limits.

use super::*;

impl Engine {
    /// Effective limits of a move on `axis` from the block's dynamics inputs.
    pub(super) fn move_limits(
        cfg: &AxisConfig,
        d: &Dynamics,
        need_velocity: bool,
    ) -> Result<Limits, ErrorId> {
        let al = cfg.limits;
        if need_velocity && !(finite(d.velocity) && d.velocity != 0.0) {
            return Err(ErrorId::InvalidVelocity);
        }
        if !(finite(d.acceleration) && d.acceleration > 0.0) {
            return Err(ErrorId::InvalidAcceleration);
        }
        if !(finite(d.deceleration) && d.deceleration > 0.0) {
            return Err(ErrorId::InvalidDeceleration);
        }
        if !(finite(d.jerk) && d.jerk >= 0.0) {
            return Err(ErrorId::InvalidJerk);
        }
        let jerk = if d.jerk == 0.0 {
            al.jmax
        } else if al.jmax == 0.0 || al.jmax.is_infinite() {
            d.jerk
        } else {
            d.jerk.min(al.jmax)
        };
        let vmax = if need_velocity {
            d.velocity.abs().min(al.vmax)
        } else {
            al.vmax
        };
        Ok(Limits {
            vmax,
            amax: d.acceleration.min(al.amax),
            dmax: d.deceleration.min(al.dmax),
            jmax: jerk,
        })
    }

    /// Raw position the next command in the buffer starts from, and its direction.
    pub(super) fn last_commanded(&self, axis: usize) -> (f64, f64) {
        let ax = &self.axes[axis];
        if let Some(p) = self.queues[axis].back() {
            match p.kind {
                Kind::Position => return (p.target, 0.0),
                Kind::Velocity => return (ax.set.p, p.target.signum()),
                _ => {}
            }
        }
        match ax.active.kind {
            Kind::Position => (ax.active.target, 0.0),
            _ => (ax.set.p, ax.set.v.signum()),
        }
    }

    /// Refuses a planned positioning whose path leaves the software limits further than
    /// where it starts (a move from beyond a limit back into the range is allowed).
    pub(super) fn check_path(
        ax: &AxisRt,
        prof: &Profile,
        tail: Option<&Profile>,
    ) -> Result<(), ErrorId> {
        if !ax.cfg.sw_limits_enabled || ax.cfg.period().is_some() {
            return Ok(());
        }
        let (lo, hi) = position_range(prof, tail);
        let start = prof.start().p + ax.origin;
        let top = ax.cfg.sw_limit_pos.max(start);
        let bottom = ax.cfg.sw_limit_neg.min(start);
        let eps = 1e-12 * (1.0 + top.abs().max(bottom.abs()));
        if hi + ax.origin > top + eps || lo + ax.origin < bottom - eps {
            return Err(ErrorId::PathBeyondSoftwareLimit);
        }
        Ok(())
    }

    pub(super) fn check_target(ax: &AxisRt, raw: f64) -> Result<(), ErrorId> {
        if ax.cfg.sw_limits_enabled && ax.cfg.period().is_none() {
            let u = raw + ax.origin;
            if u > ax.cfg.sw_limit_pos || u < ax.cfg.sw_limit_neg {
                return Err(ErrorId::TargetBeyondSoftwareLimit);
            }
        }
        Ok(())
    }

    /// Resolves a command into a [`Pending`] (targets in raw units).
    pub(super) fn resolve(
        &self,
        axis: usize,
        cmd: &AxisCommand,
        d: &Dynamics,
        buffer: BufferMode,
        id: CmdId,
        additive_base: Option<f64>,
    ) -> Result<Pending, ErrorId> {
        let ax = &self.axes[axis];
        let aborting = buffer == BufferMode::Aborting;
        let (from, dir_hint) = if aborting {
            (ax.set.p, ax.set.v.signum())
        } else {
            self.last_commanded(axis)
        };
        let mut p = Pending {
            id,
            kind: Kind::Position,
            target: 0.0,
            speed: d.velocity.abs(),
            lim: Limits::default(),
            buffer,
            end_v: 0.0,
            sync: SyncParams::default(),
            relative: None,
        };
        match *cmd {
            AxisCommand::MoveAbsolute {
                position,
                direction,
            } => {
                if !finite(position) {
                    return Err(ErrorId::InvalidPosition);
                }
                p.lim = Self::move_limits(&ax.cfg, d, true)?;
                p.target = match ax.cfg.period() {
                    None => position - ax.origin,
                    Some(period) => {
                        let cur = (from + ax.origin).rem_euclid(period);
                        let goal = position.rem_euclid(period);
                        let fwd = (goal - cur).rem_euclid(period);
                        let back = if fwd == 0.0 { 0.0 } else { fwd - period };
                        let delta = match direction {
                            Direction::Positive => fwd,
                            Direction::Negative => back,
                            Direction::Shortest => {
                                if fwd <= -back {
                                    fwd
                                } else {
                                    back
                                }
                            }
                            Direction::Current => {
                                let s = if aborting {
                                    ax.set.v.signum()
                                } else {
                                    dir_hint
                                };
                                if s < 0.0 {
                                    back
                                } else {
                                    fwd
                                }
                            }
                        };
                        from + delta
                    }
                };
            }
            AxisCommand::MoveRelative { distance } => {
                if !finite(distance) {
                    return Err(ErrorId::InvalidPosition);
                }
                p.lim = Self::move_limits(&ax.cfg, d, true)?;
                // From the set position when it becomes active: now (Aborting or idle),
                // else predicted from the predecessor's target and re-based at activation.
                p.target = from + distance;
                p.relative = Some(distance);
            }
            AxisCommand::MoveAdditive { distance } => {
                if !finite(distance) {
                    return Err(ErrorId::InvalidPosition);
                }
                p.lim = Self::move_limits(&ax.cfg, d, true)?;
                let base = additive_base.unwrap_or_else(|| self.last_commanded(axis).0);
                p.target = base + distance;
            }
            AxisCommand::MoveVelocity { direction } => {
                p.lim = Self::move_limits(&ax.cfg, d, true)?;
                let sign = match direction {
                    Direction::Positive => 1.0,
                    Direction::Negative => -1.0,
                    Direction::Current => {
                        if ax.set.v < 0.0 {
                            -1.0
                        } else {
                            1.0
                        }
                    }
                    Direction::Shortest => return Err(ErrorId::InvalidDirection),
                };
                p.kind = Kind::Velocity;
                p.target = sign * d.velocity.signum() * p.lim.vmax;
                if ax.cfg.sw_limits_enabled && ax.cfg.period().is_none() {
                    // At (or past) a limit, a velocity move further out is refused. "At":
                    // within 1e-9 relative, where the brake to the limit leaves the axis
                    // (it stops there to rounding).
                    let u = ax.set.p + ax.origin;
                    let (hi, lo) = (ax.cfg.sw_limit_pos, ax.cfg.sw_limit_neg);
                    let eps = |l: f64| 1e-9 * l.abs().max(1.0);
                    if (p.target > 0.0 && u >= hi - eps(hi))
                        || (p.target < 0.0 && u <= lo + eps(lo))
                    {
                        return Err(ErrorId::TargetBeyondSoftwareLimit);
                    }
                }
            }
            AxisCommand::Halt | AxisCommand::Stop => {
                if !(finite(d.deceleration) && d.deceleration > 0.0) {
                    return Err(ErrorId::InvalidDeceleration);
                }
                if !(finite(d.jerk) && d.jerk >= 0.0) {
                    return Err(ErrorId::InvalidJerk);
                }
                let dd = Dynamics {
                    velocity: ax.cfg.limits.vmax,
                    acceleration: d.deceleration,
                    deceleration: d.deceleration,
                    jerk: d.jerk,
                };
                p.lim = Self::move_limits(&ax.cfg, &dd, false)?;
                p.lim.amax = p.lim.amax.max(p.lim.dmax);
                p.kind = if matches!(cmd, AxisCommand::Halt) {
                    Kind::Halt
                } else {
                    Kind::Stop
                };
                p.speed = 0.0;
            }
            AxisCommand::Home { position } => {
                if !finite(position) {
                    return Err(ErrorId::InvalidPosition);
                }
                p.kind = Kind::Home;
                p.target = position;
                p.speed = 0.0;
            }
            AxisCommand::GearIn {
                master,
                numerator,
                denominator,
                source,
            } => {
                self.axis(master)?;
                if master == axis {
                    return Err(ErrorId::InvalidAxis);
                }
                if !(finite(numerator) && finite(denominator) && denominator != 0.0) {
                    return Err(ErrorId::InvalidRatio);
                }
                let dd = Dynamics {
                    velocity: ax.cfg.limits.vmax,
                    ..*d
                };
                p.lim = Self::move_limits(&ax.cfg, &dd, false)?;
                p.kind = Kind::Gear;
                p.sync = SyncParams::gear(master, numerator / denominator, source);
                self.gear_remaining(axis, &p.sync)?;
                p.speed = 0.0;
            }
            AxisCommand::CamIn { master, params } => {
                self.axis(master)?;
                if master == axis {
                    return Err(ErrorId::InvalidAxis);
                }
                self.cam_table(params.table)?;
                params.validate()?;
                let dd = Dynamics {
                    velocity: ax.cfg.limits.vmax,
                    acceleration: ax.cfg.limits.amax,
                    deceleration: ax.cfg.limits.dmax,
                    jerk: 0.0,
                };
                p.lim = Self::move_limits(&ax.cfg, &dd, false)?;
                p.kind = Kind::Cam;
                p.sync = SyncParams { master, ..params };
                self.cam_remaining(axis, &p.sync)?;
                p.speed = 0.0;
            }
            AxisCommand::GearOut | AxisCommand::CamOut => {}
        }
        if matches!(p.kind, Kind::Position | Kind::Velocity) {
            // The junction speeds of blending use the speed the move can have.
            p.speed = p.lim.vmax;
        }
        if p.kind == Kind::Position {
            Self::check_target(ax, p.target)?;
        }
        Ok(p)
    }

    /// Gives a command to an axis (a block's rising Execute). Returns its handle, or the
    /// ErrorID when the command is illegal in the axis state, its inputs are invalid or
    /// the buffer is full.
    pub fn submit(
        &mut self,
        axis: usize,
        cmd: AxisCommand,
        dynamics: Dynamics,
        buffer: BufferMode,
    ) -> Result<CmdId, ErrorId> {
        let ax = self.axis(axis)?;
        if let Some(g) = ax.group {
            if self.groups[g as usize].state != GroupState::GroupDisabled {
                return Err(ErrorId::AxisInGroup);
            }
        }
        check_axis(ax.state, cmd.class())?;
        match cmd {
            AxisCommand::GearOut => return self.sync_out(axis, Kind::Gear),
            AxisCommand::CamOut => return self.sync_out(axis, Kind::Cam),
            _ => {}
        }
        let buffer = match cmd {
            AxisCommand::Stop | AxisCommand::Home { .. } => BufferMode::Aborting,
            _ => buffer,
        };
        // Check the inputs before allocating a handle.
        let probe = CmdId { index: 0, gen: 0 };
        let pending = self.resolve(axis, &cmd, &dynamics, buffer, probe, None)?;
        let idle = self.axes[axis].active.kind == Kind::Idle;
        if buffer != BufferMode::Aborting
            && !idle
            && self.queues[axis].len() >= self.queues[axis].depth()
        {
            return Err(ErrorId::QueueFull);
        }
        if (buffer == BufferMode::Aborting || idle) && pending.kind == Kind::Position {
            // The path from the current state (a time-optimal overshoot, braking from the
            // current velocity) must stay within the software limits: refused before any
            // motion, and before anything running is aborted.
            let ax = &self.axes[axis];
            if ax.cfg.sw_limits_enabled {
                let o = overridden(
                    ax,
                    Kind::Position,
                    &pending.lim,
                    ax.set,
                    pending.target,
                    0.0,
                )?;
                Self::check_path(ax, &o.prof, o.tail.as_ref())?;
            }
        }
        if (buffer == BufferMode::Aborting || idle) && pending.kind == Kind::Cam {
            // The coupling must fit the slave's limits: refused before anything running
            // is aborted (README "Camming").
            self.plan_cam(axis, &pending.sync)?;
        }
        let id = self.cmds.alloc(CmdStatus::Queued);
        let pending = Pending { id, ..pending };
        if buffer == BufferMode::Aborting || idle {
            self.abort_all(axis, CmdStatus::Aborted);
            if let Err(e) = self.activate(axis, pending, 0.0) {
                self.cmds.set(id, CmdStatus::Error(e));
            } else if pending.kind == Kind::Stop {
                self.note_stop_cap(axis, id, &dynamics, &pending.lim);
            }
        } else {
            self.link_successor(axis, &pending);
            if let Err((e, p)) = self.queues[axis].push(pending) {
                self.cmds.set(p.id, CmdStatus::Error(e));
            }
        }
        Ok(id)
    }

    /// Records an MC_Stop whose Deceleration or Jerk the axis limits capped.
    pub(super) fn note_stop_cap(&mut self, axis: usize, cmd: CmdId, d: &Dynamics, lim: &Limits) {
        let dec_capped = d.deceleration > lim.dmax;
        let jerk_capped = d.jerk > 0.0 && lim.jmax > 0.0 && d.jerk > lim.jmax;
        if !(dec_capped || jerk_capped) {
            return;
        }
        let r = StopReduction {
            cmd,
            deceleration_requested: d.deceleration,
            deceleration_reached: lim.dmax,
            jerk_requested: d.jerk,
            jerk_reached: lim.jmax,
        };
        let c = &mut self.stop_caps[axis];
        if c.kept.len() < crate::group::REDUCTIONS_KEPT {
            c.kept.push(r);
        }
        c.count += 1;
        c.last = Some((self.cycles, r));
    }

    /// The MC_Stop commands of an axis whose Deceleration or Jerk was capped to the axis
    /// limits (the first `REDUCTIONS_KEPT`), and how many there were in all.
    pub fn stop_reductions(&self, axis: usize) -> Result<(&[StopReduction], usize), ErrorId> {
        self.axis(axis)?;
        let c = &self.stop_caps[axis];
        Ok((&c.kept, c.count))
    }

    /// The capped MC_Stop that started in the last cycle (the cycle after the scan that gave
    /// it), if any: what the trace columns `axis.<A>.stop_*` show.
    pub fn stop_reduction_now(&self, axis: usize) -> Result<Option<StopReduction>, ErrorId> {
        self.axis(axis)?;
        let c = &self.stop_caps[axis];
        Ok(c.last.filter(|(k, _)| k + 1 == self.cycles).map(|(_, r)| r))
    }
}
