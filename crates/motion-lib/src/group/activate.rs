//! Activating the next group command: its profile planned from the group's state along the path,
//! and every buffered command failed when the group must stop.
//!
//! Input: a pending group command. Output: the group's active move.

use super::*;

impl Engine {
    pub(super) fn group_abort_all(&mut self, g: usize, status: CmdStatus) {
        let gr = &mut self.groups[g];
        gr.drop_junction = false;
        if let Some(a) = gr.active.as_mut() {
            if let Some(id) = a.id.take() {
                self.cmds.set(id, status);
            }
        }
        let cmds = &mut self.cmds;
        gr.queue.drain_with(|p| cmds.set(p.id, status));
    }

    /// Current path state of the running group move (s, ds/dt, d2s/dt2) and its geometry.
    pub(super) fn path_state(a: &GActive) -> (Geometry, State) {
        if a.t < a.prefix_end {
            if let Some((geo, v)) = a.prefix {
                return (
                    geo,
                    State {
                        p: v * a.t,
                        v,
                        a: 0.0,
                    },
                );
            }
        }
        (a.geom, a.prof.at(a.t - a.prefix_end))
    }

    pub(super) fn group_activate(&mut self, g: usize, p: GPending, t0: f64) -> Result<(), ErrorId> {
        let n = self.groups[g].n();
        let now = self.raw_now(g);
        // Current axis velocities/accelerations by identity.
        let mut vel = ZERO;
        let mut acc = ZERO;
        for (i, a) in self.groups[g].axes.iter().enumerate() {
            if let Some(a) = a {
                vel[i] = self.axes[*a as usize].set.v;
                acc[i] = self.axes[*a as usize].set.a;
            }
        }
        let running = self.groups[g]
            .active
            .as_ref()
            .map(|a| (Self::path_state(a), a.lim));
        let mut tail = None;
        let mut end_v = p.end_v;
        // A brake that starts on a corner blend finishes the blend at its constant speed
        // (its curvature takes the whole acceleration budget) and brakes on the line after it.
        let in_blend = self.groups[g].active.as_ref().and_then(|a| match a.prefix {
            Some((b @ Geometry::Blend { end, u2, .. }, v)) if a.t < a.prefix_end => {
                Some((b, v, a.t, a.prefix_end, end, u2))
            }
            _ => None,
        });
        let mut keep_prefix = None;
        // An arc whose path speed its curvature lowered: (requested, reached, start).
        let mut arc_cut = None;
        let (geom, prof, lim, direct, prefix_end) = match p.kind {
            GKind::Halt | GKind::Stop | GKind::Brake if in_blend.is_some() => {
                let Some((b, v, t, pe, end, u2)) = in_blend else {
                    return Err(ErrorId::PlanningFailed);
                };
                let mut i2 = p.inputs;
                i2.velocity = f64::MAX;
                i2.acceleration = p.inputs.deceleration;
                let mut lim = self.path_lims(g, &u2, &i2)?;
                lim.amax = lim.amax.max(lim.dmax);
                lim.vmax = lim.vmax.max(v);
                let s0 = State { p: 0.0, v, a: 0.0 };
                let prof = Profile::velocity(s0, 0.0, &lim).map_err(|_| ErrorId::PlanningFailed)?;
                let mut far = end;
                let l = prof.end().p.max(1e-9);
                for i in 0..n {
                    far[i] += u2[i] * l;
                }
                keep_prefix = Some(((b, v), t));
                (Geometry::line(&end, &far), prof, lim, None, pe)
            }
            GKind::Halt | GKind::Stop | GKind::Brake
                if self.groups[g]
                    .active
                    .as_ref()
                    .is_some_and(|a| a.direct.is_some()) =>
            {
                // A MoveDirectAbsolute (or its brake) runs: each axis brakes on its own
                // profile with the block's deceleration and jerk capped by its limits.
                let mut profs = Box::new([standing(0.0); MAX_AXES]);
                for i in 0..n {
                    if let Some(a) = self.groups[g].axes[i] {
                        let al = self.axes[a as usize].cfg.limits;
                        let st = State {
                            p: now[i],
                            v: vel[i],
                            a: acc[i],
                        };
                        let mut l = Limits {
                            vmax: al.vmax.max(st.v.abs()),
                            amax: al.amax.max(al.dmax).max(st.a.abs()),
                            dmax: al.dmax.min(p.inputs.deceleration),
                            jmax: if p.inputs.jerk > 0.0 && al.jmax > 0.0 {
                                p.inputs.jerk.min(al.jmax)
                            } else if p.inputs.jerk > 0.0 {
                                p.inputs.jerk
                            } else {
                                al.jmax
                            },
                        };
                        if l.jmax > 0.0 && (al.jmax == 0.0 || al.jmax > l.jmax) {
                            let peak = (st.v + st.a * st.a.abs() / (2.0 * l.jmax)).abs();
                            if peak > al.vmax {
                                l.jmax = al.jmax;
                            }
                        }
                        profs[i] =
                            Profile::velocity(st, 0.0, &l).map_err(|_| ErrorId::PlanningFailed)?;
                    }
                }
                let geo = Geometry::line(&now, &now);
                (geo, standing(0.0), Limits::default(), Some(profs), 0.0)
            }
            GKind::Home | GKind::Halt | GKind::Stop | GKind::Brake => {
                let ((geo, s), _) = running.unwrap_or((
                    (Geometry::line(&now, &now), State::default()),
                    Limits::default(),
                ));
                let mut i2 = p.inputs;
                i2.velocity = f64::MAX;
                i2.acceleration = p.inputs.deceleration;
                let (u, _) = geo.tangents(n);
                let mut lim = self.path_lims(g, &u, &i2)?;
                if let Geometry::Arc { .. } = geo {
                    // Braking on an arc: the arc's limits (the turn keeps its share); the
                    // arc's own jerk when the halt's lower one would carry the speed
                    // past the arc's.
                    let mut arc = lim;
                    arc.jmax = 0.0;
                    let v_arc = self.arc_limits(g, &geo, &mut arc);
                    lim.dmax = lim.dmax.min(arc.dmax);
                    lim.jmax = if lim.jmax > 0.0 && arc.jmax > 0.0 {
                        lim.jmax.min(arc.jmax)
                    } else {
                        arc.jmax
                    };
                    let peak = s.v + s.a * s.a.abs() / (2.0 * lim.jmax.max(1e-300));
                    if lim.jmax > 0.0 && peak > v_arc {
                        lim.jmax = arc.jmax;
                    }
                    lim.amax = lim.dmax.max(s.a.abs());
                    lim.vmax = v_arc.max(s.v.abs());
                } else {
                    lim.amax = lim.amax.max(lim.dmax);
                    lim.vmax = lim.vmax.max(s.v.abs());
                    self.raise_jerk(g, &u, s, &mut lim);
                }
                let prof = Profile::velocity(s, 0.0, &lim).map_err(|_| ErrorId::PlanningFailed)?;
                (geo, prof, lim, None, 0.0)
            }
            GKind::Path => {
                let start = match &p.prefix {
                    Some((geo, _)) => {
                        let (mut q, mut d1, mut d2) = (ZERO, ZERO, ZERO);
                        geo.eval(geo.len(), n, &mut q, &mut d1, &mut d2);
                        q
                    }
                    None => now,
                };
                let geo = self.geometry_for(g, &start, &p.target, &p.motion);
                if matches!(p.motion, GroupMotion::Circular { .. })
                    && !matches!(geo, Geometry::Arc { .. })
                {
                    // A buffered circle whose start (its predecessor's end) does not
                    // define it: refused when it would start, never run as a line.
                    return Err(ErrorId::InvalidCircle);
                }
                let (u, _) = geo.tangents(n);
                let mut lim = self.path_lims(g, &u, &p.inputs)?;
                if let Geometry::Arc { .. } = geo {
                    let requested = lim.vmax;
                    let reached = self.arc_limits(g, &geo, &mut lim);
                    if reached < requested {
                        arc_cut = Some((requested, reached, start));
                    }
                }
                let (v0, a0, pe) = match &p.prefix {
                    Some((b, v)) => (*v, 0.0, if *v > 0.0 { b.len() / v } else { 0.0 }),
                    None if p.start_v.is_some() => (p.start_v.unwrap_or(0.0), 0.0, 0.0),
                    None => {
                        // Aborting: the current axis velocity projected onto the path.
                        let v0: f64 = (0..n).map(|i| vel[i] * u[i]).sum();
                        let a0: f64 = (0..n).map(|i| acc[i] * u[i]).sum();
                        (v0, a0, 0.0)
                    }
                };
                let s0 = State {
                    p: 0.0,
                    v: v0,
                    a: a0,
                };
                self.raise_jerk(g, &u, s0, &mut lim);
                let (_, u_end) = geo.tangents(n);
                let arrives_as_planned = self.groups[g].queue.front().is_none_or(|nx| {
                    let dot: f64 = (0..n).map(|i| nx.pred_dir[i] * u_end[i]).sum();
                    nx.pred_dir == ZERO || dot >= 1.0 - 1e-9
                });
                let mut p = p;
                if p.end_v > 0.0 && !arrives_as_planned {
                    // The junction (and its blend) was planned for another direction.
                    self.note_dropped_junction(g, &p);
                    p.end_v = 0.0;
                    end_v = 0.0;
                }
                let planned = match crate::engine::plan_to(s0, geo.len(), p.end_v, &lim) {
                    Err(_) if p.end_v > 0.0 => {
                        // The junction speed cannot be planned from here: stop at the
                        // junction instead (reported), the successor starts from rest.
                        let r = crate::engine::plan_to(s0, geo.len(), 0.0, &lim);
                        if r.is_ok() {
                            self.note_dropped_junction(g, &p);
                            end_v = 0.0;
                        }
                        r
                    }
                    r => r,
                };
                let (prof, t) = planned.map_err(|_| ErrorId::PlanningFailed)?;
                let (lo, hi) = crate::engine::position_range(&prof, t.as_ref());
                self.group_sw_check(g, &geo, lo, hi)?;
                tail = t;
                (geo, prof, lim, None, pe)
            }
            GKind::Direct => {
                let mut profs = Box::new([standing(0.0); MAX_AXES]);
                let mut longest: f64 = 0.0;
                for i in 0..n {
                    if let Some(a) = self.groups[g].axes[i] {
                        let al = self.axes[a as usize].cfg.limits;
                        // The block's inputs capped by the axis's limits (Jerk 0: the
                        // axis's own), as a single-axis move.
                        let mut l = Limits {
                            vmax: al.vmax.min(p.inputs.velocity),
                            amax: al.amax.min(p.inputs.acceleration),
                            dmax: al.dmax.min(p.inputs.deceleration),
                            jmax: if p.inputs.jerk > 0.0 && al.jmax > 0.0 {
                                p.inputs.jerk.min(al.jmax)
                            } else if p.inputs.jerk > 0.0 {
                                p.inputs.jerk
                            } else {
                                al.jmax
                            },
                        };
                        let st = State {
                            p: now[i],
                            v: vel[i],
                            a: acc[i],
                        };
                        // Started while the axis accelerates: the block's lower jerk would
                        // carry the velocity past the axis's limit; the axis's jerk then.
                        if l.jmax > 0.0 && (al.jmax == 0.0 || al.jmax > l.jmax) {
                            let peak = (st.v + st.a * st.a.abs() / (2.0 * l.jmax)).abs();
                            if peak > al.vmax {
                                l.jmax = al.jmax;
                            }
                        }
                        profs[i] = crate::engine::plan_position(st, p.target[i], 0.0, &l)
                            .map_err(|_| ErrorId::PlanningFailed)?;
                        let ax = &self.axes[a as usize];
                        if ax.cfg.sw_limits_enabled && ax.cfg.period().is_none() {
                            // Each axis's own path (an overshoot) within its range.
                            let (lo, hi) = crate::engine::position_range(&profs[i], None);
                            let (o, c) = (ax.origin, &ax.cfg);
                            let top = c.sw_limit_pos.max(st.p + o);
                            let bottom = c.sw_limit_neg.min(st.p + o);
                            let eps = 1e-12 * (1.0 + top.abs().max(bottom.abs()));
                            if hi + o > top + eps || lo + o < bottom - eps {
                                return Err(ErrorId::PathBeyondSoftwareLimit);
                            }
                        }
                        longest = longest.max(profs[i].duration());
                    }
                }
                let geo = Geometry::line(&now, &p.target);
                let prof = Profile::velocity(
                    State::default(),
                    0.0,
                    &Limits {
                        vmax: 1.0,
                        amax: 1.0,
                        dmax: 1.0,
                        jmax: 0.0,
                    },
                )
                .map_err(|_| ErrorId::PlanningFailed)?;
                let _ = longest;
                (geo, prof, Limits::default(), Some(profs), 0.0)
            }
        };
        let gr = &mut self.groups[g];
        gr.active = Some(GActive {
            kind: p.kind,
            id: Some(p.id),
            geom,
            prof,
            t: keep_prefix.map_or(t0, |k| k.1),
            prefix: keep_prefix.map_or(p.prefix, |k| Some(k.0)),
            prefix_end,
            target: p.target,
            speed: p.speed,
            lim,
            end_v,
            direct,
            tail,
        });
        if let Some((requested, reached, corner)) = arc_cut {
            gr.reduction_count += 1;
            if gr.reductions.len() < REDUCTIONS_KEPT {
                gr.reductions.push(Reduction {
                    block: p.seq,
                    cmd: p.id,
                    corner,
                    requested,
                    reached,
                    reason: ReductionReason::ArcSpeed,
                });
            }
            gr.arc_now = Some((requested, reached));
        }
        gr.state = if p.kind == GKind::Stop {
            gr.stop_owner = Some(p.id);
            GroupState::GroupStopping
        } else if p.kind == GKind::Brake {
            GroupState::GroupErrorStop
        } else {
            GroupState::GroupMoving
        };
        self.cmds.set(p.id, CmdStatus::Active);
        for a in self.groups[g].axes.iter().flatten() {
            let ax = &mut self.axes[*a as usize];
            if ax.state == AxisState::Disabled {
                continue;
            }
            ax.active = Active {
                kind: Kind::Group,
                ..Active::idle(ax.set)
            };
            if ax.state != AxisState::ErrorStop {
                ax.state = AxisState::SynchronizedMotion;
            }
        }
        Ok(())
    }
}
