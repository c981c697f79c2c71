//! The group's part of each cycle: path set points written to the axes, homing, stops,
//! faults of member axes and the end of each move.
//!
//! Input: [`Engine::step`]. Output: the axes' set points along the path and the group's state.
//! Invariant: allocates nothing; an axis fault puts the group into GroupErrorStop.

use super::*;

impl Engine {
    /// An axis of the group failed (or lost power): GroupErrorStop, buffered moves fail,
    /// the path brakes.
    pub(crate) fn group_axis_fault(&mut self, g: usize) {
        if self.groups[g].state == GroupState::GroupErrorStop
            || self.groups[g].state == GroupState::GroupDisabled
        {
            return;
        }
        self.group_abort_all(g, CmdStatus::Error(ErrorId::GroupAxisError));
        self.groups[g].error = ErrorId::GroupAxisError;
        self.groups[g].state = GroupState::GroupErrorStop;
        self.groups[g].stop_owner = None;
        if self.groups[g].active.is_some() {
            // Brake along the path with the axes' deceleration.
            let inputs = PathInputs {
                velocity: f64::MAX,
                acceleration: f64::MAX,
                deceleration: f64::MAX,
                jerk: 0.0,
                ..PathInputs::default()
            };
            let id = self.cmds.alloc(CmdStatus::Queued);
            let p = GPending {
                id,
                kind: GKind::Brake,
                motion: GroupMotion::Halt,
                target: ZERO,
                inputs,
                speed: 0.0,
                end_v: 0.0,
                prefix: None,
                start_v: None,
                start_corner: ZERO,
                seq: 0,
                reduced: None,
                pred_dir: ZERO,
            };
            if self.group_activate(g, p, 0.0).is_err() {
                self.finish_group(g);
            }
            if let Some(a) = self.groups[g].active.as_mut() {
                a.id = None;
            }
            self.cmds.set(id, CmdStatus::Done);
            self.cmds.release(id);
        }
    }

    /// MC_GroupHome: homes every axis of the group (simulated drives: on the spot, the
    /// set positions become `position` by identity); GroupStandby -> GroupHoming ->
    /// GroupStandby when every drive reports its homing done.
    pub fn group_home(&mut self, g: usize, position: Vecn) -> Result<CmdId, ErrorId> {
        let gr = self.grp(g)?;
        let st = check_group(gr.state, GroupCmd::Home)?;
        let n = gr.n();
        if position[..n].iter().any(|x| !x.is_finite()) {
            return Err(ErrorId::InvalidPosition);
        }
        let now = self.raw_now(g);
        let id = self.cmds.alloc(CmdStatus::Active);
        let members = self.groups[g].axes;
        for a in members.iter().flatten() {
            let a = *a as usize;
            let ax = &mut self.axes[a];
            ax.active = Active {
                kind: Kind::Group,
                ..Active::idle(ax.set)
            };
            ax.state = AxisState::Homing;
            if let Some(d) = self.drives[a].as_mut() {
                d.start_homing();
            }
        }
        let gr = &mut self.groups[g];
        gr.active = Some(GActive {
            kind: GKind::Home,
            id: Some(id),
            geom: Geometry::line(&now, &now),
            prof: standing(0.0),
            t: 0.0,
            prefix: None,
            prefix_end: 0.0,
            target: position,
            speed: 0.0,
            lim: Limits::default(),
            end_v: 0.0,
            direct: None,
            tail: None,
        });
        gr.state = st;
        Ok(id)
    }

    /// One cycle of a group homing: poll the drives.
    pub(super) fn step_group_home(&mut self, g: usize, a: GActive) {
        let members = self.groups[g].axes;
        let mut all = true;
        let mut failed = None;
        for ax in members.iter().flatten() {
            let ax = *ax as usize;
            let st = match self.drives[ax].as_mut() {
                Some(d) => d.homing_status(),
                None => crate::axis::HomingStatus::Done,
            };
            match st {
                crate::axis::HomingStatus::Busy => all = false,
                crate::axis::HomingStatus::Failed => failed = Some(ax),
                crate::axis::HomingStatus::Done => {}
            }
        }
        let id = a.id;
        let target = a.target;
        self.groups[g].active = Some(a);
        if let Some(ax) = failed {
            let _ = self.raise_axis_error(ax, ErrorId::HomingFailed);
            return;
        }
        if !all {
            return;
        }
        for (i, ax) in members.iter().enumerate() {
            if let Some(ax) = ax {
                let ax = &mut self.axes[*ax as usize];
                ax.origin = target[i] - ax.set.p;
            }
        }
        if let Some(id) = id {
            self.cmds.set(id, CmdStatus::Done);
        }
        self.finish_group(g);
        self.groups[g].state = GroupState::GroupStandby;
    }

    /// MC_GroupStop's Execute fell after Done: GroupStopping -> GroupStandby.
    pub fn release_group_stop(&mut self, g: usize, id: CmdId) {
        if let Some(gr) = self.groups.get_mut(g) {
            let running = gr.active.as_ref().is_some_and(|a| a.kind == GKind::Stop);
            if gr.stop_owner == Some(id) && !running {
                gr.stop_owner = None;
                if gr.state == GroupState::GroupStopping {
                    gr.state = GroupState::GroupStandby;
                }
            }
        }
    }

    /// The group's motion ended: axes stand still.
    pub(super) fn finish_group(&mut self, g: usize) {
        self.groups[g].active = None;
        for a in self.groups[g].axes.iter().flatten() {
            let ax = &mut self.axes[*a as usize];
            ax.set.v = 0.0;
            ax.set.a = 0.0;
            ax.active = Active::idle(ax.set);
            if matches!(ax.state, AxisState::SynchronizedMotion | AxisState::Homing) {
                ax.state = AxisState::Standstill;
            }
        }
    }

    /// Writes the set points of the group's axes from the running path move at its time.
    pub(super) fn write_path_setpoints(&mut self, g: usize) {
        let n = self.groups[g].n();
        let Some(a) = self.groups[g].active.as_ref() else {
            return;
        };
        if a.direct.is_some() {
            return;
        }
        let (geo, s) = Self::path_state(a);
        let (mut pos, mut d1, mut d2) = self.groups[g].scratch;
        geo.eval(s.p, n, &mut pos, &mut d1, &mut d2);
        for i in 0..n {
            if let Some(ax) = self.groups[g].axes[i] {
                if self.axes[ax as usize].active.kind != Kind::Group {
                    continue;
                }
                self.axes[ax as usize].set = State {
                    p: pos[i],
                    v: d1[i] * s.v,
                    a: d1[i] * s.a + d2[i] * s.v * s.v,
                };
            }
        }
        self.groups[g].scratch = (pos, d1, d2);
    }

    /// One cycle of every group with a running move.
    pub(crate) fn step_groups(&mut self, dt: f64) {
        for g in 0..self.groups.len() {
            self.groups[g].junction_now = self.groups[g].arc_now.take().unwrap_or((0.0, 0.0));
            let Some(mut a) = self.groups[g].active.take() else {
                continue;
            };
            if a.kind == GKind::Home {
                self.step_group_home(g, a);
                continue;
            }
            let n = self.groups[g].n();
            a.t += dt;
            let (mut pos, mut d1, mut d2) = self.groups[g].scratch;
            let ended;
            if let Some(profs) = &a.direct {
                let mut done = true;
                for i in 0..n {
                    if let Some(ax) = self.groups[g].axes[i] {
                        if self.axes[ax as usize].active.kind != Kind::Group {
                            continue;
                        }
                        let s = profs[i].at(a.t);
                        self.axes[ax as usize].set = s;
                        done &= a.t >= profs[i].duration();
                    }
                }
                ended = done;
            } else {
                if let Some(tail) = a.tail {
                    if a.t >= a.prefix_end + a.prof.duration() {
                        // Main part done: the velocity-change tail follows at once.
                        a.prefix_end += a.prof.duration();
                        a.prof = tail;
                        a.tail = None;
                    }
                }
                let (geo, s) = Self::path_state(&a);
                geo.eval(s.p, n, &mut pos, &mut d1, &mut d2);
                for i in 0..n {
                    if let Some(ax) = self.groups[g].axes[i] {
                        if self.axes[ax as usize].active.kind != Kind::Group {
                            continue;
                        }
                        self.axes[ax as usize].set = State {
                            p: pos[i],
                            v: d1[i] * s.v,
                            a: d1[i] * s.a + d2[i] * s.v * s.v,
                        };
                    }
                }
                ended = a.t >= a.prefix_end + a.prof.duration() && a.tail.is_none();
            }
            self.groups[g].scratch = (pos, d1, d2);
            let kind = a.kind;
            let id = a.id;
            let leftover = a.t - a.prefix_end - a.prof.duration();
            let end_v = a.end_v;
            self.groups[g].active = Some(a);
            if !ended {
                continue;
            }
            if let Some(id) = id {
                self.cmds.set(id, CmdStatus::Done);
            }
            if matches!(kind, GKind::Path | GKind::Direct) {
                // Land exactly on the commanded end point.
                let target = self.groups[g].active.as_ref().map(|a| a.target);
                if let Some(target) = target {
                    for (i, t) in target.iter().enumerate().take(n) {
                        if let Some(ax) = self.groups[g].axes[i] {
                            if self.axes[ax as usize].active.kind != Kind::Group {
                                continue;
                            }
                            // At a junction (end_v > 0) the successor starts from the
                            // end point, not from the profile extrapolated past it.
                            let s = &mut self.axes[ax as usize].set;
                            s.p = *t;
                            s.v = d1[i] * end_v;
                            s.a = 0.0;
                        }
                    }
                }
            }
            match kind {
                GKind::Stop | GKind::Brake => {
                    self.finish_group(g);
                    if kind == GKind::Brake {
                        self.groups[g].state = GroupState::GroupErrorStop;
                    }
                }
                _ => {
                    // Next buffered move starts from the junction.
                    let mut started = false;
                    while let Some(mut p) = self.groups[g].queue.pop() {
                        if std::mem::take(&mut self.groups[g].drop_junction) {
                            p.prefix = None;
                            p.start_v = None;
                        }
                        let t0 = if end_v > 0.0 { leftover.max(0.0) } else { 0.0 };
                        if end_v > 0.0 {
                            p.start_v = Some(end_v);
                        }
                        match self.group_activate(g, p, t0) {
                            Ok(()) => {
                                let arc = self.groups[g].arc_now.take();
                                if let Some(r) = p.reduced.or(arc) {
                                    self.groups[g].junction_now = r;
                                }
                                if t0 > 0.0 {
                                    // The successor already ran `t0` of this cycle.
                                    self.write_path_setpoints(g);
                                }
                                started = true;
                                break;
                            }
                            Err(e) => {
                                // Its successor cannot join it: it starts from rest.
                                self.groups[g].drop_junction = true;
                                self.cmds.set(p.id, CmdStatus::Error(e));
                            }
                        }
                    }
                    if !started {
                        self.finish_group(g);
                        if self.groups[g].state == GroupState::GroupMoving {
                            self.groups[g].state = GroupState::GroupStandby;
                        }
                    }
                }
            }
        }
    }
}
