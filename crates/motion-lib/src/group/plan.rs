//! A group motion command checked and planned: the path limits along its direction (reduced to
//! every axis's, each reduction reported), arcs slowed by their curvature, the software limits
//! along the path, and its place in the group's buffer.
//!
//! Input: [`GroupMotion`] with its [`PathInputs`]. Output: a command id or the ErrorID that
//! refuses it. Invariant: no planned path exceeds an axis's limits or leaves its software limits.

use super::*;

impl Engine {
    pub(super) fn path_lims(
        &self,
        g: usize,
        unit: &Vecn,
        inp: &PathInputs,
    ) -> Result<Limits, ErrorId> {
        let gr = &self.groups[g];
        // Fixed arrays: this runs inside the cycle on an error brake, so no allocation.
        let mut us = [0.0; MAX_AXES];
        let mut ls = [Limits::default(); MAX_AXES];
        let mut k = 0;
        for (i, a) in gr.axes.iter().enumerate() {
            if let Some(a) = a {
                us[k] = unit[i];
                ls[k] = self.axes[*a as usize].cfg.limits;
                k += 1;
            }
        }
        let mut l = path_limits(&us[..k], &ls[..k]).map_err(|_| ErrorId::PlanningFailed)?;
        let pos = |x: f64| x.is_finite() && x > 0.0;
        if !pos(inp.velocity) {
            return Err(ErrorId::InvalidVelocity);
        }
        if !pos(inp.acceleration) {
            return Err(ErrorId::InvalidAcceleration);
        }
        if !pos(inp.deceleration) {
            return Err(ErrorId::InvalidDeceleration);
        }
        if !(inp.jerk.is_finite() && inp.jerk >= 0.0) {
            return Err(ErrorId::InvalidJerk);
        }
        l.vmax = l.vmax.min(inp.velocity);
        l.amax = l.amax.min(inp.acceleration);
        l.dmax = l.dmax.min(inp.deceleration);
        if inp.jerk > 0.0 {
            l.jmax = if l.jmax.is_infinite() || l.jmax == 0.0 {
                inp.jerk
            } else {
                l.jmax.min(inp.jerk)
            };
        }
        if l.jmax.is_infinite() {
            l.jmax = 0.0;
        }
        Ok(l)
    }

    /// The move `p` ends at rest instead of at its junction speed: its successor starts
    /// from rest (reported as a reduction to 0).
    pub(super) fn note_dropped_junction(&mut self, g: usize, p: &GPending) {
        let gr = &mut self.groups[g];
        gr.drop_junction = true;
        gr.reduction_count += 1;
        if let Some(nx) = gr.queue.front() {
            if gr.reductions.len() < REDUCTIONS_KEPT {
                gr.reductions.push(Reduction {
                    block: nx.seq,
                    cmd: nx.id,
                    corner: p.target,
                    requested: p.end_v,
                    reached: 0.0,
                    reason: ReductionReason::Distance,
                });
            }
        }
    }

    /// A move or brake that starts while the path accelerates: with the block's (lower)
    /// jerk the speed would pass the axes' velocity limit on direction `u` before the
    /// acceleration is gone; the jerk is then raised to the axes' own, projected.
    pub(super) fn raise_jerk(&self, g: usize, u: &Vecn, s: State, lim: &mut Limits) {
        if lim.jmax <= 0.0 || s.a == 0.0 {
            return;
        }
        let free = PathInputs {
            velocity: f64::MAX,
            acceleration: f64::MAX,
            deceleration: f64::MAX,
            jerk: 0.0,
            ..PathInputs::default()
        };
        let Ok(axes) = self.path_lims(g, u, &free) else {
            return;
        };
        let peak = (s.v + s.a * s.a.abs() / (2.0 * lim.jmax)).abs();
        if peak > axes.vmax && (axes.jmax == 0.0 || axes.jmax > lim.jmax) {
            lim.jmax = axes.jmax;
        }
    }

    /// Arc path limits ("Arc speed" in the README). The tangent turns, so every axis's
    /// limits bound the path. With a = min over the axes of min(amax, dmax) and j the
    /// lowest axis jerk limit, on an arc of curvature k (largest |d2|) and largest |d3| = m:
    /// an axis accelerates at most |a_t| + k v^2 and jerks at most
    /// |j_t| + 3 k v |a_t| + m v^3 (a_t, j_t the path's tangential acceleration and jerk).
    /// The budget is split: the tangential acceleration and the turn get a / 2 each
    /// (v <= sqrt(a / (2 k))); the tangential jerk j / 2, the turn's own jerk j / 4
    /// (v <= cbrt(j / (4 m))), the cross term j / 4 (|a_t| <= j / (12 k v)). Returns the
    /// path speed the arc allows (the lowest of those caps and the axes' velocity limits).
    pub(super) fn arc_limits(&self, g: usize, geo: &Geometry, lim: &mut Limits) -> f64 {
        let n = self.groups[g].n();
        let mut vmax = f64::INFINITY;
        let mut amin = f64::INFINITY;
        let mut jmin = f64::INFINITY;
        for a in self.groups[g].axes.iter().flatten() {
            let l = self.axes[*a as usize].cfg.limits;
            vmax = vmax.min(l.vmax);
            amin = amin.min(l.amax).min(l.dmax);
            if l.jmax > 0.0 {
                jmin = jmin.min(l.jmax);
            }
        }
        let half = amin.min(lim.amax).min(lim.dmax) / 2.0;
        let k = geo.max_curvature(n);
        let m = geo.max_d3();
        let v_turn = if k > 0.0 {
            (half / k).sqrt()
        } else {
            f64::INFINITY
        };
        let mut v_arc = vmax.min(v_turn);
        lim.amax = lim.amax.min(half);
        lim.dmax = lim.dmax.min(half);
        if jmin.is_finite() {
            if m > 0.0 {
                v_arc = v_arc.min((jmin / (4.0 * m)).cbrt());
            }
            if k > 0.0 && v_arc > 0.0 {
                let a_cross = jmin / (12.0 * k * v_arc);
                lim.amax = lim.amax.min(a_cross);
                lim.dmax = lim.dmax.min(a_cross);
            }
            lim.jmax = if lim.jmax > 0.0 {
                lim.jmax.min(jmin / 2.0)
            } else {
                jmin / 2.0
            };
        }
        lim.vmax = lim.vmax.min(v_arc);
        v_arc
    }

    /// Software limits of the group's axes against a path piece between arc lengths
    /// `s0 <= s1` (the geometry over [0, len] and, at activation, the planned profile's
    /// overshoot): ErrorID 27 when the end point of an axis lies outside its range, 29 when
    /// the path leaves it (an arc's bulge, an overshoot). As for single axes, an axis that
    /// starts beyond a limit may move back, never further out.
    pub(super) fn group_sw_check(
        &self,
        g: usize,
        geo: &Geometry,
        s0: f64,
        s1: f64,
    ) -> Result<(), ErrorId> {
        let gr = &self.groups[g];
        let n = gr.n();
        let on = |a: &u32| {
            let c = &self.axes[*a as usize].cfg;
            c.sw_limits_enabled && c.period().is_none()
        };
        if !gr.axes.iter().flatten().any(on) {
            return Ok(());
        }
        let (mut start, mut end, mut d1, mut d2) = (ZERO, ZERO, ZERO, ZERO);
        geo.eval(0.0, n, &mut start, &mut d1, &mut d2);
        geo.eval(geo.len(), n, &mut end, &mut d1, &mut d2);
        let (lo, hi) = geo.axis_range(n, s0.min(0.0), s1.max(geo.len()));
        for (i, a) in gr.axes.iter().enumerate().take(n) {
            let Some(a) = a.filter(on) else {
                continue;
            };
            let ax = &self.axes[a as usize];
            let (o, c) = (ax.origin, &ax.cfg);
            let e = end[i] + o;
            if e > c.sw_limit_pos || e < c.sw_limit_neg {
                return Err(ErrorId::TargetBeyondSoftwareLimit);
            }
            let top = c.sw_limit_pos.max(start[i] + o);
            let bottom = c.sw_limit_neg.min(start[i] + o);
            let eps = 1e-12 * (1.0 + top.abs().max(bottom.abs()));
            if hi[i] + o > top + eps || lo[i] + o < bottom - eps {
                return Err(ErrorId::PathBeyondSoftwareLimit);
            }
        }
        Ok(())
    }

    /// Gives a motion command to a group. Returns its handle or the ErrorID.
    pub fn submit_group(
        &mut self,
        g: usize,
        motion: GroupMotion,
        inputs: PathInputs,
    ) -> Result<CmdId, ErrorId> {
        let gr = self.grp(g)?;
        let class = match motion {
            GroupMotion::Stop => GroupCmd::Stop,
            _ => GroupCmd::Motion,
        };
        check_group(gr.state, class)?;
        if (inputs.buffer.is_blending() || inputs.transition != TransitionMode::None)
            && !(inputs.transition_parameter.is_finite() && inputs.transition_parameter >= 0.0)
        {
            return Err(ErrorId::InvalidTransitionMode);
        }
        let n = gr.n();
        let origin =
            |eng: &Engine, i: usize| gr.axes[i].map_or(0.0, |a| eng.axes[a as usize].origin);
        let mut buffer = inputs.buffer;
        let kind = match motion {
            GroupMotion::Stop => {
                buffer = BufferMode::Aborting;
                GKind::Stop
            }
            GroupMotion::Halt => GKind::Halt,
            GroupMotion::DirectAbsolute { .. } => GKind::Direct,
            _ => GKind::Path,
        };
        let from = if buffer == BufferMode::Aborting {
            self.raw_now(g)
        } else {
            self.group_last_target(g)
        };
        let check = |v: &Vecn| -> Result<(), ErrorId> {
            if v[..n].iter().all(|x| x.is_finite()) {
                Ok(())
            } else {
                Err(ErrorId::InvalidPosition)
            }
        };
        let mut target = from;
        match motion {
            GroupMotion::LinearAbsolute { position } | GroupMotion::DirectAbsolute { position } => {
                check(&position)?;
                for i in 0..n {
                    if gr.axes[i].is_some() {
                        target[i] = position[i] - origin(self, i);
                    }
                }
            }
            GroupMotion::LinearRelative { distance } => {
                check(&distance)?;
                for i in 0..n {
                    if gr.axes[i].is_some() {
                        target[i] = from[i] + distance[i];
                    }
                }
            }
            GroupMotion::Circular {
                end,
                aux,
                relative,
                mode,
                ccw,
            } => {
                check(&end)?;
                check(&aux)?;
                let mut e = from;
                // RADIUS: AuxPoint is the plane's normal vector, taken as given.
                let mut x = if mode == CircMode::Radius { aux } else { from };
                for i in 0..n {
                    if gr.axes[i].is_some() {
                        e[i] = if relative {
                            from[i] + end[i]
                        } else {
                            end[i] - origin(self, i)
                        };
                        x[i] = if mode == CircMode::Radius {
                            aux[i]
                        } else if relative {
                            from[i] + aux[i]
                        } else {
                            aux[i] - origin(self, i)
                        };
                    }
                }
                Geometry::arc(&from, &x, &e, mode, ccw).ok_or(ErrorId::InvalidCircle)?;
                target = e;
            }
            GroupMotion::Halt | GroupMotion::Stop => {}
        }
        // Validate the dynamics against the move's direction.
        let geom = self.geometry_for(g, &from, &target, &motion);
        if kind == GKind::Path {
            // The path (end point, an arc's bulge) within the software limits, before any
            // motion; buffered moves again when they start (from where they really start).
            self.group_sw_check(g, &geom, 0.0, geom.len())?;
        } else if kind == GKind::Direct {
            self.group_sw_check(g, &Geometry::line(&target, &target), 0.0, 0.0)?;
        }
        let (t0, _) = geom.tangents(n);
        let lim = match kind {
            GKind::Halt | GKind::Stop => {
                let mut i2 = inputs;
                i2.velocity = f64::MAX;
                i2.acceleration = inputs.deceleration;
                self.path_lims(g, &t0, &i2)?
            }
            _ => self.path_lims(g, &t0, &inputs)?,
        };
        let _ = lim;
        let gr = &self.groups[g];
        let idle = gr.active.is_none();
        if buffer != BufferMode::Aborting && !idle && gr.queue.len() >= gr.queue.depth() {
            return Err(ErrorId::QueueFull);
        }
        let id = self.cmds.alloc(CmdStatus::Queued);
        let seq = if matches!(kind, GKind::Path | GKind::Direct) {
            self.groups[g].seq = self.groups[g].seq.wrapping_add(1);
            self.groups[g].seq
        } else {
            0
        };
        let p = GPending {
            id,
            kind,
            motion,
            target,
            inputs: PathInputs { buffer, ..inputs },
            speed: inputs.velocity.abs(),
            end_v: 0.0,
            prefix: None,
            start_v: None,
            start_corner: from,
            seq,
            reduced: None,
            pred_dir: ZERO,
        };
        if buffer == BufferMode::Aborting || idle {
            self.group_abort_all(g, CmdStatus::Aborted);
            if kind == GKind::Path && self.group_turns(g, &from, &target, &motion) {
                // The path turns away from the current motion: a velocity or acceleration
                // step would break the axis limits, so the group first brakes along its
                // path (the command is Active meanwhile) and starts from there.
                self.group_brake_then(g, p);
            } else if let Err(e) = self.group_activate(g, p, 0.0) {
                // Refused as it starts (e.g. its overshoot leaves the software limits): the
                // running move, already aborted, brakes along its path.
                if let Some(lim) = self.groups[g].active.as_ref().map(|a| a.lim) {
                    // With the running move's own deceleration: it stops before the end
                    // it was planned to.
                    let halt = GPending {
                        kind: GKind::Halt,
                        motion: GroupMotion::Halt,
                        speed: 0.0,
                        seq: 0,
                        inputs: PathInputs {
                            deceleration: if lim.dmax > 0.0 {
                                lim.dmax
                            } else {
                                p.inputs.deceleration
                            },
                            jerk: lim.jmax,
                            ..p.inputs
                        },
                        ..p
                    };
                    if self.group_activate(g, halt, 0.0).is_ok() {
                        if let Some(a) = self.groups[g].active.as_mut() {
                            a.id = None;
                        }
                    }
                }
                self.cmds.set(id, CmdStatus::Error(e));
            }
        } else {
            let mut p = p;
            self.group_link(g, &mut p);
            if let Err((e, p)) = self.groups[g].queue.push(p) {
                self.cmds.set(p.id, CmdStatus::Error(e));
            }
        }
        Ok(id)
    }

    /// True when the group moves (or accelerates) across the start direction of the new
    /// path from `from` to `target`.
    pub(super) fn group_turns(
        &self,
        g: usize,
        from: &Vecn,
        target: &Vecn,
        motion: &GroupMotion,
    ) -> bool {
        if self.groups[g].active.is_none() {
            return false;
        }
        let n = self.groups[g].n();
        let geo = self.geometry_for(g, from, target, motion);
        let (u, _) = geo.tangents(n);
        let mut vel = ZERO;
        let mut acc = ZERO;
        for (i, a) in self.groups[g].axes.iter().enumerate() {
            if let Some(a) = a {
                vel[i] = self.axes[*a as usize].set.v;
                acc[i] = self.axes[*a as usize].set.a;
            }
        }
        let lateral = |x: &Vecn| {
            let along: f64 = (0..n).map(|i| x[i] * u[i]).sum();
            (0..n)
                .map(|i| (x[i] - along * u[i]).powi(2))
                .sum::<f64>()
                .sqrt()
        };
        let moving = vel[..n].iter().chain(&acc[..n]).any(|x| *x != 0.0);
        let arc = matches!(geo, Geometry::Arc { .. });
        moving && (arc || lateral(&vel) > 1e-12 || lateral(&acc) > 1e-12)
    }

    /// Brakes the running path to rest with `p`'s deceleration, then starts `p`.
    pub(super) fn group_brake_then(&mut self, g: usize, mut p: GPending) {
        let halt = GPending {
            id: p.id,
            kind: GKind::Halt,
            motion: GroupMotion::Halt,
            target: ZERO,
            inputs: p.inputs,
            speed: 0.0,
            end_v: 0.0,
            prefix: None,
            start_v: None,
            start_corner: ZERO,
            seq: 0,
            reduced: None,
            pred_dir: ZERO,
        };
        if let Err(e) = self.group_activate(g, halt, 0.0) {
            self.cmds.set(p.id, CmdStatus::Error(e));
            return;
        }
        let n = self.groups[g].n();
        if let Some(a) = self.groups[g].active.as_mut() {
            a.id = None;
            // The move starts where the brake ends.
            let (mut q, mut d1, mut d2) = (ZERO, ZERO, ZERO);
            a.geom.eval(a.prof.end().p, n, &mut q, &mut d1, &mut d2);
            if let Some(profs) = &a.direct {
                for i in 0..n {
                    q[i] = profs[i].end().p;
                }
            }
            for (i, ax) in self.groups[g].axes.iter().enumerate() {
                if ax.is_some() {
                    p.start_corner[i] = q[i];
                }
            }
        }
        self.cmds.set(p.id, CmdStatus::Active);
        if let Err((e, p)) = self.groups[g].queue.push(p) {
            self.cmds.set(p.id, CmdStatus::Error(e));
        }
    }

    pub(super) fn geometry_for(
        &self,
        g: usize,
        from: &Vecn,
        target: &Vecn,
        motion: &GroupMotion,
    ) -> Geometry {
        let n = self.groups[g].n();
        if let GroupMotion::Circular {
            aux,
            relative,
            mode,
            ccw,
            ..
        } = motion
        {
            let mut x = if *mode == CircMode::Radius {
                *aux
            } else {
                *from
            };
            for i in 0..n {
                if let Some(a) = self.groups[g].axes[i] {
                    x[i] = if *mode == CircMode::Radius {
                        aux[i]
                    } else if *relative {
                        from[i] + aux[i]
                    } else {
                        aux[i] - self.axes[a as usize].origin
                    };
                }
            }
            if let Some(geo) = Geometry::arc(from, &x, target, *mode, *ccw) {
                return geo;
            }
        }
        Geometry::line(from, target)
    }
}
