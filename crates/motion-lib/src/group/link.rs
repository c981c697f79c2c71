//! Blending: a buffered group move linked to its predecessor, with the junction speed at the
//! corner lowered until every axis stays within its limits (the lowering is reported).
//!
//! Input: the running move and the next pending one. Output: the junction speed and the blend
//! geometry. Invariant: no axis exceeds its velocity, acceleration or jerk limit through a corner.

use super::*;

impl Engine {
    /// A blending successor joins the group's last move.
    pub(super) fn group_link(&mut self, g: usize, next: &mut GPending) {
        if !next.inputs.buffer.is_blending() || next.kind != GKind::Path {
            return;
        }
        let n = self.groups[g].n();
        let gr = &self.groups[g];
        // Predecessor: the queue's back, else the active move.
        // Predecessor: the queue's back (its geometry from its original start corner: its
        // own predecessor may since have been shortened by a corner blend), else the
        // active move.
        let (pred_target, pred_speed, pred_kind, pred_is_active, pred_geom, pred_circle) =
            match gr.queue.back() {
                Some(b) => (
                    b.target,
                    b.speed,
                    b.kind,
                    false,
                    self.geometry_for(g, &b.start_corner, &b.target, &b.motion),
                    matches!(b.motion, GroupMotion::Circular { .. }),
                ),
                None => match &gr.active {
                    Some(a) => (
                        a.target,
                        a.speed,
                        a.kind,
                        true,
                        a.geom,
                        matches!(a.geom, Geometry::Arc { .. }),
                    ),
                    None => return,
                },
            };
        if pred_kind != GKind::Path {
            return;
        }
        let gr = &self.groups[g];
        // Where the predecessor's own line really starts (after its corner blend) and at
        // what path state: it has `room` to reach the junction speed.
        let (room_start, room, room_inputs) = match gr.queue.back() {
            Some(b) => {
                let start = match &b.prefix {
                    Some((Geometry::Blend { end, .. }, _)) => *end,
                    _ => b.start_corner,
                };
                let q = &gr.queue;
                let v0 = if q.len() >= 2 {
                    q.iter().nth(q.len() - 2).map_or(0.0, |p| p.end_v)
                } else {
                    gr.active.as_ref().map_or(0.0, |a| a.end_v)
                };
                (
                    State {
                        p: 0.0,
                        v: v0,
                        a: 0.0,
                    },
                    dist(&start, &b.target),
                    b.inputs,
                )
            }
            None => {
                let a = gr.active.as_ref().map(|a| {
                    let s_now = if a.t < a.prefix_end {
                        a.prof.start()
                    } else {
                        a.prof.at(a.t - a.prefix_end)
                    };
                    (s_now, a.geom.len() - s_now.p, a.lim)
                });
                match a {
                    Some((st, room, lim)) => (
                        State { p: 0.0, ..st },
                        room,
                        PathInputs {
                            velocity: lim.vmax,
                            acceleration: lim.amax,
                            deceleration: lim.dmax,
                            jerk: lim.jmax,
                            ..PathInputs::default()
                        },
                    ),
                    None => return,
                }
            }
        };
        let next_geom = self.geometry_for(g, &pred_target, &next.target, &next.motion);
        let (_, u1) = pred_geom.tangents(n);
        let (u2, _) = next_geom.tangents(n);
        let requested = next.inputs.buffer.junction_speed(pred_speed, next.speed);
        let mut vj = requested;
        let mut reason = ReductionReason::Velocity;
        // Corner blend.
        let mut new_pred_target = pred_target;
        let cos = (0..n).map(|i| u1[i] * u2[i]).sum::<f64>();
        // (A circle's geometry is known for sure only from where it starts: a circular
        // move on either side is a circle junction.)
        let lines = matches!(pred_geom, Geometry::Line { .. })
            && matches!(next_geom, Geometry::Line { .. })
            && !pred_circle
            && !matches!(next.motion, GroupMotion::Circular { .. });
        let tangent = cos >= 1.0 - 1e-12;
        if vj > 0.0 && lines {
            // Never above an axis's velocity limit projected onto either line.
            let free = PathInputs {
                velocity: f64::MAX,
                acceleration: f64::MAX,
                deceleration: f64::MAX,
                jerk: 0.0,
                ..PathInputs::default()
            };
            for u in [&u1, &u2] {
                if let Ok(l) = self.path_lims(g, u, &free) {
                    vj = vj.min(l.vmax);
                }
            }
        }
        if vj > 0.0 && !lines {
            vj = 0.0;
            reason = ReductionReason::Arc;
        } else if vj > 0.0 && !tangent {
            if next.inputs.transition == TransitionMode::None
                || next.inputs.transition_parameter <= 0.0
            {
                vj = 0.0;
                reason = ReductionReason::Corner;
            } else {
                let mut d = corner_distance(
                    next.inputs.transition,
                    next.inputs.transition_parameter,
                    cos,
                )
                .min(room / 2.0)
                .min(next_geom.len() / 2.0);
                if pred_is_active {
                    if let Some(a) = &gr.active {
                        let s_now = a.prof.at(a.t - a.prefix_end).p;
                        let remaining = pred_geom.len() - s_now;
                        // Leave room to reach the junction speed before the blend.
                        d = d.min(remaining * 0.5);
                    }
                }
                match Geometry::corner_blend(&pred_target, &u1, &u2, d, n) {
                    Some(blend) if d > 1e-9 => {
                        let vb = self.blend_speed(g, &blend);
                        if vb < vj {
                            vj = vb;
                            reason = ReductionReason::Blend;
                        }
                        if vj > 0.0 {
                            next.prefix = Some((blend, vj));
                            if let Geometry::Blend { start, .. } = blend {
                                new_pred_target = start;
                            }
                        }
                    }
                    _ => {
                        vj = 0.0;
                        reason = ReductionReason::NoBlend;
                    }
                }
            }
        }
        if vj > 0.0 {
            // The predecessor must reach vj on the room it has left (after the blend's cut).
            let cut = dist(&pred_target, &new_pred_target);
            let lim = self.path_lims(g, &u1, &room_inputs).ok();
            if let Some(lim) = lim {
                let r = reachable(room_start, room - cut, vj, &lim);
                if r < vj {
                    vj = r;
                    reason = ReductionReason::Distance;
                    match next.prefix.as_mut() {
                        Some(pre) if vj > 0.0 => pre.1 = vj,
                        _ => {
                            next.prefix = None;
                            new_pred_target = pred_target;
                        }
                    }
                }
            }
        }
        if vj > 0.0 {
            next.pred_dir = u1;
        }
        if vj < requested {
            next.reduced = Some((requested, vj));
            let gr = &mut self.groups[g];
            gr.reduction_count += 1;
            if gr.reductions.len() < REDUCTIONS_KEPT {
                gr.reductions.push(Reduction {
                    block: next.seq,
                    cmd: next.id,
                    corner: pred_target,
                    requested,
                    reached: vj,
                    reason,
                });
            }
        }
        let gr = &mut self.groups[g];
        if pred_is_active {
            if let Some(a) = gr.active.as_mut() {
                // Re-plan the running move to end at the junction (speed vj). While the
                // move still runs its own corner blend, its main part has not started:
                // re-plan that from its start state.
                let in_prefix = a.t < a.prefix_end;
                let s_now = if in_prefix {
                    a.prof.start()
                } else {
                    a.prof.at(a.t - a.prefix_end)
                };
                let new_len = a.geom.len() - dist(&pred_target, &new_pred_target);
                if let Ok((p, tail)) = crate::engine::plan_to(s_now, new_len, vj, &a.lim) {
                    a.prof = p;
                    a.tail = tail;
                    if !in_prefix {
                        a.t = a.prefix_end;
                    }
                    a.end_v = vj;
                    a.target = new_pred_target;
                } else {
                    next.prefix = None;
                }
            }
        } else if let Some(b) = gr.queue.back_mut() {
            b.end_v = vj;
            b.target = new_pred_target;
        }
    }

    /// The highest constant path speed on a corner blend at which every axis keeps its
    /// velocity, acceleration and jerk limits: min over axes of vmax / max|d1|,
    /// sqrt(a / max|d2|), cbrt(j / max|d3|) (derivatives by arc length, bounded in closed
    /// form by [`Geometry::blend_bounds`]). The block's Acceleration and Jerk bound the
    /// path's tangential motion; on the blend the path speed is constant and the axes
    /// carry the turn.
    pub(super) fn blend_speed(&self, g: usize, blend: &Geometry) -> f64 {
        let n = self.groups[g].n();
        let Some((b1, b2, b3)) = blend.blend_bounds(n) else {
            return 0.0;
        };
        let mut v = f64::INFINITY;
        for (i, a) in self.groups[g].axes.iter().enumerate() {
            let Some(a) = a else { continue };
            let l = self.axes[*a as usize].cfg.limits;
            if b1[i] > 0.0 {
                v = v.min(l.vmax / b1[i]);
            }
            if b2[i] > 0.0 {
                v = v.min((l.amax.min(l.dmax) / b2[i]).sqrt());
            }
            if b3[i] > 0.0 && l.jmax > 0.0 && l.jmax.is_finite() {
                v = v.min((l.jmax / b3[i]).cbrt());
            }
        }
        // Rounding margin: the bounds are met with 1e-9 to spare.
        v * (1.0 - 1e-9)
    }
}
