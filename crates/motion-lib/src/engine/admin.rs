//! Axis administration between cycles: releasing commands, power, reset and raised errors,
//! MC_SetPosition, the override factors and cam tables.
//!
//! Input: the administrative blocks' calls. Output: the axis's state and queue changed at once.
//! Invariant: an error always ends in ErrorStop with every buffered command failed.

use super::*;

impl Engine {
    /// Forgets a finished command (its block has read the final status).
    pub fn release(&mut self, id: CmdId) {
        if self.cmds.status(id).is_final() {
            self.cmds.release(id);
        }
    }

    /// MC_Stop's Execute fell after Done: the axis leaves Stopping for Standstill.
    pub fn release_stop(&mut self, axis: usize, id: CmdId) {
        if let Some(ax) = self.axes.get_mut(axis) {
            if ax.stop_owner == Some(id) && ax.active.kind != Kind::Stop {
                ax.stop_owner = None;
                if ax.state == AxisState::Stopping {
                    ax.state = AxisState::Standstill;
                }
            }
        }
    }

    /// MC_Power: switches the drive on or off. Returns MC_Power.Status.
    pub fn power(&mut self, axis: usize, enable: bool) -> Result<bool, ErrorId> {
        self.axis(axis)?;
        let ax = &mut self.axes[axis];
        if enable == ax.power_req {
            self.poll_power(axis);
            return Ok(self.axes[axis].powered);
        }
        ax.power_req = enable;
        if let Some(d) = self.drives[axis].as_mut() {
            d.set_enable(enable);
        }
        if !enable {
            self.abort_all(axis, CmdStatus::Aborted);
            let ax = &mut self.axes[axis];
            ax.powered = false;
            ax.set.v = 0.0;
            ax.set.a = 0.0;
            ax.set.p = ax.act_p;
            ax.active = Active::idle(ax.set);
            ax.stop_owner = None;
            if ax.state != AxisState::ErrorStop {
                ax.state = AxisState::Disabled;
            }
            if let Some(g) = ax.group {
                self.group_axis_fault(g as usize);
            }
        }
        self.poll_power(axis);
        Ok(self.axes[axis].powered)
    }

    /// Reads the drive's enable feedback; Disabled -> Standstill once enabled.
    pub(super) fn poll_power(&mut self, axis: usize) {
        let ax = &mut self.axes[axis];
        if ax.power_req {
            let en = match self.drives[axis].as_ref() {
                Some(d) => d.enabled(),
                None => true,
            };
            if en && !ax.powered {
                ax.powered = true;
                ax.set = State {
                    p: ax.act_p,
                    v: 0.0,
                    a: 0.0,
                };
                ax.active = Active::idle(ax.set);
            }
            if en && ax.state == AxisState::Disabled {
                ax.state = AxisState::Standstill;
            }
        }
    }

    /// MC_Reset: ErrorStop -> Standstill (powered) or Disabled. In other states nothing
    /// happens (Done).
    pub fn reset(&mut self, axis: usize) -> Result<(), ErrorId> {
        self.axis(axis)?;
        if self.axes[axis].state != AxisState::ErrorStop {
            return Ok(());
        }
        if self.axes[axis].active.kind == Kind::Brake
            || (self.axes[axis].active.kind == Kind::Group)
        {
            return Err(ErrorId::AxisStillMoving);
        }
        if let Some(d) = self.drives[axis].as_mut() {
            d.reset_fault();
            if d.fault().is_some() {
                return Err(ErrorId::DriveFaultActive);
            }
        }
        let ax = &mut self.axes[axis];
        ax.axis_error = ErrorId::None;
        ax.drive_code = 0;
        ax.state = if ax.powered {
            AxisState::Standstill
        } else {
            AxisState::Disabled
        };
        Ok(())
    }

    /// Puts the axis into ErrorStop with `error` (AxisErrorID): the active and every
    /// buffered command fail with that error, the queue is cleared and the axis brakes
    /// with its own deceleration and jerk limits.
    pub fn raise_axis_error(&mut self, axis: usize, error: ErrorId) -> Result<(), ErrorId> {
        self.axis(axis)?;
        if self.axes[axis].state == AxisState::ErrorStop {
            return Ok(());
        }
        self.abort_all(axis, CmdStatus::Error(error));
        let ax = &mut self.axes[axis];
        ax.state = AxisState::ErrorStop;
        ax.axis_error = error;
        ax.stop_owner = None;
        if ax.active.kind == Kind::Group {
            // The group brakes along its path (it drives this axis's set point).
            let g = ax.group.map(usize::from);
            if let Some(g) = g {
                self.group_axis_fault(g);
            }
            return Ok(());
        }
        if ax.powered {
            let lim = ax.cfg.limits;
            let start = ax.set;
            ax.active = Active::idle(start);
            if start.v == 0.0 && start.a == 0.0 {
                // At rest already (a velocity move stopped at a limit): nothing to brake.
                return Ok(());
            }
            if let Ok(p) = Profile::velocity(start, 0.0, &lim) {
                ax.active.prof = p;
                ax.active.kind = Kind::Brake;
                ax.active.released = false;
            }
        }
        Ok(())
    }

    /// Aborts the active and every queued command of the axis with `status`.
    pub(super) fn abort_all(&mut self, axis: usize, status: CmdStatus) {
        let ax = &mut self.axes[axis];
        if let Some(id) = ax.active.id.take() {
            self.cmds.set(id, status);
            self.cmds.set_in_target(id, false);
        }
        let cmds = &mut self.cmds;
        self.queues[axis].drain_with(|p| cmds.set(p.id, status));
    }

    /// MC_SetPosition: shifts the axis coordinate so that the set position becomes
    /// `position` (or moves by `position` when `relative`). Motion continues unchanged.
    pub fn set_position(
        &mut self,
        axis: usize,
        position: f64,
        relative: bool,
    ) -> Result<(), ErrorId> {
        self.axis(axis)?;
        if !finite(position) {
            return Err(ErrorId::InvalidPosition);
        }
        let ax = &mut self.axes[axis];
        if matches!(ax.state, AxisState::Homing | AxisState::ErrorStop) {
            return Err(check_state_err(ax.state));
        }
        if relative {
            ax.origin += position;
        } else {
            ax.origin = position - ax.set.p;
        }
        Ok(())
    }

    /// MC_SetOverride with VelFactor only (AccFactor and JerkFactor unchanged); see
    /// [`Engine::set_override_factors`].
    pub fn set_override(&mut self, axis: usize, factor: f64) -> Result<(), ErrorId> {
        let ax = self.axis(axis)?;
        let (acc, jerk) = (ax.acc_factor, ax.jerk_factor);
        self.set_override_factors(axis, factor, acc, jerk)
    }

    /// MC_SetOverride with all three factors: VelFactor (>= 0) scales the velocity limit
    /// (capped by the axis's limit; 0 brakes the move to standstill on its way, where it
    /// waits), AccFactor the acceleration and deceleration limits, JerkFactor the jerk
    /// limit of the running and of every later positioning, velocity and halt move (not
    /// MC_Stop, error braking, gearing, camming or group moves). AccFactor and JerkFactor
    /// must be in (0, 1]; 0 stands for 1 (the value of a zero-initialised block). A
    /// change re-plans the running move from its current position, velocity and
    /// acceleration, so the set point stays continuous and within the limits in force.
    pub fn set_override_factors(
        &mut self,
        axis: usize,
        vel: f64,
        acc: f64,
        jerk: f64,
    ) -> Result<(), ErrorId> {
        self.axis(axis)?;
        let factor = |f: f64| -> Result<f64, ErrorId> {
            if f == 0.0 {
                Ok(1.0)
            } else if finite(f) && f > 0.0 && f <= 1.0 {
                Ok(f)
            } else {
                Err(ErrorId::InvalidOverride)
            }
        };
        let (acc, jerk) = (factor(acc)?, factor(jerk)?);
        if !(finite(vel) && vel >= 0.0) {
            return Err(ErrorId::InvalidOverride);
        }
        let ax = &mut self.axes[axis];
        if ax.vel_factor != vel || ax.acc_factor != acc || ax.jerk_factor != jerk {
            ax.vel_factor = vel;
            ax.acc_factor = acc;
            ax.jerk_factor = jerk;
            self.replan_override(axis);
        }
        Ok(())
    }

    /// The override factors in effect: (VelFactor, AccFactor, JerkFactor).
    pub fn override_factors(&self, axis: usize) -> Result<(f64, f64, f64), ErrorId> {
        let ax = self.axis(axis)?;
        Ok((ax.vel_factor, ax.acc_factor, ax.jerk_factor))
    }

    /// Re-plans the running move under the new override from its current state. A
    /// MoveVelocity that was InVelocity drops it until it reaches a new velocity (an
    /// AccFactor or JerkFactor change alone keeps it).
    pub(super) fn replan_override(&mut self, axis: usize) {
        let ax = &self.axes[axis];
        let a = ax.active;
        let running = match a.kind {
            Kind::Velocity => true,
            Kind::Position | Kind::Halt => !a.released,
            _ => false,
        };
        if !running {
            return;
        }
        if let Ok(o) = overridden(ax, a.kind, &a.base, ax.set, a.target, a.end_v) {
            let ax = &mut self.axes[axis];
            ax.active.prof = o.prof;
            ax.active.tail = o.tail;
            ax.active.t = 0.0;
            ax.active.lim = o.lim;
            ax.active.paused = o.paused;
            if a.kind == Kind::Velocity && a.released && o.prof.duration() > 0.0 {
                ax.active.released = false;
                if let Some(id) = a.id {
                    self.cmds.set_in_target(id, false);
                }
            }
        }
    }

    /// Registers a cam table; returns its CamTableID.
    pub fn add_cam_table(&mut self, table: CamTable) -> usize {
        self.cams.push(table);
        self.cams.len() - 1
    }

    /// Checks a CamTableID.
    pub fn cam_table(&self, id: usize) -> Result<&CamTable, ErrorId> {
        self.cams.get(id).ok_or(ErrorId::InvalidCamTable)
    }
}
