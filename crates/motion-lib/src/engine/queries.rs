//! What the engine tells about its axes and commands: counts, states, set and actual values, and
//! the status of each command. Read-only; any thread that owns the engine may ask between cycles.

use super::*;

impl Engine {
    /// Number of axes.
    pub fn axis_count(&self) -> usize {
        self.axes.len()
    }

    /// Cycles stepped so far.
    pub fn cycles(&self) -> u64 {
        self.cycles
    }

    /// Engine time in seconds (cycles * cycle time).
    pub fn time(&self) -> f64 {
        self.cycles as f64 * self.cfg.cycle
    }

    /// PLCopen state of the axis.
    pub fn axis_state(&self, axis: usize) -> Result<AxisState, ErrorId> {
        Ok(self.axis(axis)?.state)
    }

    pub(super) fn to_user(ax: &AxisRt, raw: f64) -> f64 {
        let p = raw + ax.origin;
        match ax.cfg.kind {
            AxisKind::Linear => p,
            AxisKind::Modulo { period } => p.rem_euclid(period),
        }
    }

    /// Set position in user units (wrapped on modulo axes).
    pub fn set_position_of(&self, axis: usize) -> Result<f64, ErrorId> {
        let ax = self.axis(axis)?;
        Ok(Self::to_user(ax, ax.set.p))
    }

    /// Set velocity (includes the override).
    pub fn set_velocity_of(&self, axis: usize) -> Result<f64, ErrorId> {
        Ok(self.axis(axis)?.set.v)
    }

    /// Set acceleration.
    pub fn set_acceleration_of(&self, axis: usize) -> Result<f64, ErrorId> {
        Ok(self.axis(axis)?.set.a)
    }

    /// Actual position in user units.
    pub fn actual_position(&self, axis: usize) -> Result<f64, ErrorId> {
        let ax = self.axis(axis)?;
        Ok(Self::to_user(ax, ax.act_p))
    }

    /// Actual velocity.
    pub fn actual_velocity(&self, axis: usize) -> Result<f64, ErrorId> {
        Ok(self.axis(axis)?.act_v)
    }

    /// The axis error (AxisErrorID), `ErrorId::None` when the axis has none.
    pub fn axis_error(&self, axis: usize) -> Result<ErrorId, ErrorId> {
        Ok(self.axis(axis)?.axis_error)
    }

    /// The drive's own fault code of the last drive fault.
    pub fn drive_fault_code(&self, axis: usize) -> Result<u16, ErrorId> {
        Ok(self.axis(axis)?.drive_code)
    }

    /// MC_Power.Status: the drive is enabled.
    pub fn power_status(&self, axis: usize) -> Result<bool, ErrorId> {
        Ok(self.axis(axis)?.powered)
    }

    /// Number of commands waiting in the axis's buffer (not counting the active one).
    pub fn queued(&self, axis: usize) -> Result<usize, ErrorId> {
        self.axis(axis)?;
        Ok(self.queues[axis].len())
    }

    /// Group the axis belongs to.
    pub fn group_of(&self, axis: usize) -> Result<Option<usize>, ErrorId> {
        Ok(self.axis(axis)?.group.map(usize::from))
    }

    /// Status of a command.
    pub fn status(&self, id: CmdId) -> CmdStatus {
        self.cmds.status(id)
    }

    /// InVelocity / InGear / InSync of a command (on the set value).
    pub fn in_target(&self, id: CmdId) -> bool {
        self.cmds.in_target(id)
    }

    /// EndOfProfile of a CamIn command.
    pub fn end_of_profile(&self, id: CmdId) -> bool {
        self.cmds.end_of_profile(id)
    }
}
