//! The fixed-cycle step: each axis's set point advanced by one cycle, the drive exchange, and the
//! events that end, buffer or fail commands.
//!
//! Input: [`Engine::step`] once per cycle. Output: set points, states and command statuses.
//! Invariant: allocates nothing; deterministic.

use super::*;

impl Engine {
    /// Advances every axis and group by one cycle.
    pub fn step(&mut self) {
        let dt = self.cfg.cycle;
        self.cycles += 1;
        self.step_groups(dt);
        self.events.clear();
        self.synced.clear();
        for (i, ax) in self.axes.iter_mut().enumerate() {
            let a = &mut ax.active;
            match a.kind {
                Kind::Idle => {
                    ax.set.v = 0.0;
                    ax.set.a = 0.0;
                }
                Kind::Group => {}
                Kind::Gear | Kind::Cam => {
                    self.synced.push(i as u32);
                    continue;
                }
                Kind::Home => {
                    self.events.push(i as u32);
                }
                _ => {
                    a.t += dt;
                    ax.set = a.prof.at_next(a.t);
                    if a.kind == Kind::Velocity
                        && ax.cfg.sw_limits_enabled
                        && ax.cfg.period().is_none()
                        && ax.set.v != 0.0
                    {
                        guard_limit(&ax.cfg, a, ax.set, ax.origin, dt, &mut self.cmds);
                    }
                    if a.t >= a.prof.duration() && !a.released && !a.paused {
                        self.events.push(i as u32);
                    } else if a.kind == Kind::Velocity && a.released && !self.queues[i].is_empty() {
                        // InVelocity was shown (at least one scan): the successor takes over.
                        self.events.push(i as u32);
                    }
                }
            }
            if !ax.has_drive {
                ax.act_p = ax.set.p;
                ax.act_v = ax.set.v;
                if ax.cfg.sw_limits_enabled && ax.state != AxisState::ErrorStop {
                    let u = ax.set.p + ax.origin;
                    if ax.cfg.period().is_none()
                        && ((u > ax.cfg.sw_limit_pos && ax.set.v > 0.0)
                            || (u < ax.cfg.sw_limit_neg && ax.set.v < 0.0))
                    {
                        self.events.push(i as u32);
                    }
                }
            }
        }
        // Events of simulated axes first: a master whose profile ended (its successor
        // starting within the cycle) has its final set point before its slaves follow it.
        for k in 0..self.events.len() {
            let i = self.events[k] as usize;
            if !self.axes[i].has_drive {
                self.axis_event(i);
            }
        }
        for k in 0..self.synced.len() {
            let i = self.synced[k] as usize;
            self.step_sync(i, dt);
        }
        // Over the drives (a compact vector), not over the axes' large records.
        for i in 0..self.drives.len() {
            if self.drives[i].is_some() {
                self.exchange_drive(i);
            }
        }
        for k in 0..self.events.len() {
            let i = self.events[k] as usize;
            if self.axes[i].has_drive {
                self.axis_event(i);
            }
        }
    }

    pub(super) fn exchange_drive(&mut self, i: usize) {
        let s = self.axes[i].set;
        let powered = self.axes[i].powered;
        let Some(d) = self.drives[i].as_mut() else {
            return;
        };
        if powered {
            d.write(s.p, s.v, s.a);
        }
        let (p, v, en, fault) = (
            d.actual_position(),
            d.actual_velocity(),
            d.enabled(),
            d.fault(),
        );
        let ax = &mut self.axes[i];
        ax.act_p = p;
        ax.act_v = v;
        if !powered {
            ax.set.p = p;
        }
        if let Some(code) = fault {
            if ax.state != AxisState::ErrorStop {
                ax.drive_code = code;
                let _ = self.raise_axis_error(i, ErrorId::DriveFault);
            }
            return;
        }
        if ax.power_req && ax.powered && !en {
            let _ = self.raise_axis_error(i, ErrorId::DriveDisabled);
            return;
        }
        if ax.power_req && !ax.powered {
            self.poll_power(i);
        }
        let ax = &self.axes[i];
        if ax.cfg.following_error_limit > 0.0
            && ax.powered
            && (s.p - p).abs() > ax.cfg.following_error_limit
        {
            let _ = self.raise_axis_error(i, ErrorId::FollowingError);
            return;
        }
        self.check_limits(i);
    }

    /// Rare per-axis work: a profile ended, homing progressed, a limit was hit.
    pub(super) fn axis_event(&mut self, i: usize) {
        {
            let ax = &self.axes[i];
            if ax.cfg.sw_limits_enabled && !ax.has_drive {
                self.check_limits(i);
            }
        }
        let a = self.axes[i].active;
        match a.kind {
            Kind::Home => {
                let st = match self.drives[i].as_mut() {
                    Some(d) => d.homing_status(),
                    None => HomingStatus::Done,
                };
                match st {
                    HomingStatus::Busy => {}
                    HomingStatus::Done => {
                        let ax = &mut self.axes[i];
                        ax.origin = a.target - ax.set.p;
                        ax.active = Active::idle(ax.set);
                        ax.state = AxisState::Standstill;
                        if let Some(id) = a.id {
                            self.cmds.set(id, CmdStatus::Done);
                        }
                        self.start_next(i, 0.0);
                    }
                    HomingStatus::Failed => {
                        let _ = self.raise_axis_error(i, ErrorId::HomingFailed);
                    }
                }
            }
            Kind::Velocity if a.released && !a.paused && !self.queues[i].is_empty() => {
                if let Some(id) = a.id {
                    self.cmds.set(id, CmdStatus::Aborted);
                    self.cmds.set_in_target(id, false);
                }
                // It starts from this cycle's set point.
                self.start_next(i, 0.0);
            }
            Kind::Velocity if a.released && !a.paused => {}
            Kind::Position | Kind::Halt | Kind::Velocity | Kind::Stop | Kind::Brake => {
                if a.released || a.paused || a.t < a.prof.duration() {
                    return;
                }
                if let Some(tail) = a.tail {
                    // Main part done: continue with the velocity-change tail.
                    let ax = &mut self.axes[i];
                    ax.active.t -= a.prof.duration();
                    ax.active.prof = tail;
                    ax.active.tail = None;
                    ax.set = tail.at(ax.active.t);
                    return;
                }
                let leftover = a.t - a.prof.duration();
                match a.kind {
                    Kind::Velocity => {
                        self.axes[i].active.released = true;
                        if let Some(id) = a.id {
                            self.cmds.set_in_target(id, true);
                        }
                    }
                    Kind::Stop => {
                        let ax = &mut self.axes[i];
                        let end = a.prof.end();
                        ax.set = State {
                            p: end.p,
                            v: 0.0,
                            a: 0.0,
                        };
                        ax.active = Active::idle(ax.set);
                        if let Some(id) = a.id {
                            self.cmds.set(id, CmdStatus::Done);
                        }
                    }
                    Kind::Brake => {
                        let ax = &mut self.axes[i];
                        let end = a.prof.end();
                        ax.set = State {
                            p: end.p,
                            v: 0.0,
                            a: 0.0,
                        };
                        ax.active = Active::idle(ax.set);
                    }
                    _ if a.limit_stop.is_some() => {
                        // A velocity move stopped at a software limit: the axis error.
                        let ax = &mut self.axes[i];
                        // At rest at the limit (the profile's end, rounding aside).
                        ax.set = State {
                            p: a.prof.end().p,
                            v: 0.0,
                            a: 0.0,
                        };
                        ax.active = Active::idle(ax.set);
                        ax.active.id = a.id;
                        if let Some(e) = a.limit_stop {
                            let _ = self.raise_axis_error(i, e);
                        }
                    }
                    _ => {
                        let end = a.prof.end();
                        let ax = &mut self.axes[i];
                        ax.set = end;
                        if let Some(id) = a.id {
                            self.cmds.set(id, CmdStatus::Done);
                        }
                        ax.active = Active::idle(ax.set);
                        ax.active.released = true;
                        if self.queues[i].is_empty() && a.end_v == 0.0 {
                            ax.state = AxisState::Standstill;
                            ax.set.v = 0.0;
                        } else {
                            // The successor starts from the junction state.
                            ax.set = State {
                                p: end.p,
                                v: a.end_v,
                                a: 0.0,
                            };
                            self.start_next(i, leftover);
                        }
                    }
                }
            }
            _ => {}
        }
    }

    /// Checks after the sync pass (software limits of slaves).
    pub(crate) fn check_limits(&mut self, i: usize) {
        let ax = &self.axes[i];
        if !ax.has_drive {
            let s = ax.set;
            let ax = &mut self.axes[i];
            ax.act_p = s.p;
            ax.act_v = s.v;
        }
        let ax = &self.axes[i];
        if ax.cfg.sw_limits_enabled && ax.state != AxisState::ErrorStop && ax.cfg.period().is_none()
        {
            // Only motion further out is an error: an axis standing beyond a limit (after
            // an error brake) can be reset and moved back into the range.
            let u = ax.set.p + ax.origin;
            if u > ax.cfg.sw_limit_pos && ax.set.v > 0.0 {
                let _ = self.raise_axis_error(i, ErrorId::SoftwareLimitPositive);
            } else if u < ax.cfg.sw_limit_neg && ax.set.v < 0.0 {
                let _ = self.raise_axis_error(i, ErrorId::SoftwareLimitNegative);
            }
        }
    }
}
