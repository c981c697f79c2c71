//! Axis configuration and drives.
//!
//! Input: an [`AxisConfig`] per axis (limits, software limits, linear or modulo) and
//! optionally a [`Drive`] (a real drive); without one the axis has a simulated drive whose
//! actual values follow the set point exactly. Output: validated configurations.
//! Invariant: a configuration accepted by [`AxisConfig::validate`] has finite positive
//! vmax/amax/dmax, jmax >= 0 (0 = no jerk limit), a positive finite modulo period, and
//! software limits with negative < positive.

use crate::profile::Limits;

/// Linear axis, or a modulo (rotary) axis whose position is reported in `[0, period)`.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum AxisKind {
    #[default]
    /// Positions are plain numbers in user units; software limits apply.
    Linear,
    /// A rotary axis: positions are reported in `[0, period)`; MoveAbsolute's Direction picks the
    /// way round.
    Modulo {
        /// Length of one turn in user units (finite, > 0).
        period: f64,
    },
}

/// Configuration of one axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AxisConfig {
    /// Velocity, acceleration, deceleration and jerk limits of the axis (jmax 0 = none).
    pub limits: Limits,
    /// Positive software position limit (checked when `sw_limits_enabled`).
    pub sw_limit_pos: f64,
    /// Negative software position limit (checked when `sw_limits_enabled`).
    pub sw_limit_neg: f64,
    /// SwLimitsEnabled: check the software limits (linear axes): targets beyond them are refused
    /// (ErrorID 27, 29), velocity moves stop at them (ErrorID 100, 101).
    pub sw_limits_enabled: bool,
    /// Linear axis or modulo axis with its period.
    pub kind: AxisKind,
    /// Largest allowed |set - actual| position difference (0 = not checked).
    pub following_error_limit: f64,
}

impl Default for AxisConfig {
    fn default() -> Self {
        AxisConfig {
            limits: Limits {
                vmax: 1000.0,
                amax: 10000.0,
                dmax: 10000.0,
                jmax: 100000.0,
            },
            sw_limit_pos: 0.0,
            sw_limit_neg: 0.0,
            sw_limits_enabled: false,
            kind: AxisKind::Linear,
            following_error_limit: 0.0,
        }
    }
}

/// Why an axis configuration was refused (each maps to an E5xxx diagnostic code).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ConfigError {
    /// E5001: vmax, amax, dmax must be finite and > 0, jmax >= 0.
    InvalidLimits,
    /// E5002: software limits not finite or negative >= positive.
    InvalidSoftwareLimits,
    /// E5003: modulo period not finite or <= 0.
    InvalidModuloPeriod,
    /// E5004: following-error limit negative or not finite.
    InvalidFollowingErrorLimit,
    /// E5005: too many axes in the engine or a cycle time that is not finite and > 0.
    InvalidEngineConfig,
}

impl ConfigError {
    /// The E5xxx diagnostic code that explains this error (`ladderc explain E5001`).
    pub fn code(self) -> &'static str {
        match self {
            ConfigError::InvalidLimits => "E5001",
            ConfigError::InvalidSoftwareLimits => "E5002",
            ConfigError::InvalidModuloPeriod => "E5003",
            ConfigError::InvalidFollowingErrorLimit => "E5004",
            ConfigError::InvalidEngineConfig => "E5005",
        }
    }
}

impl std::fmt::Display for ConfigError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let m = match self {
            ConfigError::InvalidLimits => {
                "axis limits: vmax, amax, dmax must be finite and > 0, jmax >= 0"
            }
            ConfigError::InvalidSoftwareLimits => {
                "software limits must be finite with negative < positive"
            }
            ConfigError::InvalidModuloPeriod => "modulo period must be finite and > 0",
            ConfigError::InvalidFollowingErrorLimit => {
                "following-error limit must be finite and >= 0"
            }
            ConfigError::InvalidEngineConfig => "engine: cycle time must be finite and > 0",
        };
        write!(f, "{}: {m}", self.code())
    }
}

impl std::error::Error for ConfigError {}

impl AxisConfig {
    /// Checks the configuration.
    pub fn validate(&self) -> Result<(), ConfigError> {
        let l = &self.limits;
        let pos = |x: f64| x.is_finite() && x > 0.0;
        if !(pos(l.vmax) && pos(l.amax) && pos(l.dmax) && !l.jmax.is_nan() && l.jmax >= 0.0) {
            return Err(ConfigError::InvalidLimits);
        }
        if self.sw_limits_enabled
            && !(self.sw_limit_neg.is_finite()
                && self.sw_limit_pos.is_finite()
                && self.sw_limit_neg < self.sw_limit_pos)
        {
            return Err(ConfigError::InvalidSoftwareLimits);
        }
        if let AxisKind::Modulo { period } = self.kind {
            if !pos(period) {
                return Err(ConfigError::InvalidModuloPeriod);
            }
        }
        if !(self.following_error_limit.is_finite() && self.following_error_limit >= 0.0) {
            return Err(ConfigError::InvalidFollowingErrorLimit);
        }
        Ok(())
    }

    /// The modulo period, if the axis is a modulo axis.
    pub fn period(&self) -> Option<f64> {
        match self.kind {
            AxisKind::Linear => None,
            AxisKind::Modulo { period } => Some(period),
        }
    }
}

/// Result of polling a drive's homing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HomingStatus {
    /// The drive is still homing (the axis stays in Homing).
    Busy,
    /// Homing finished; the drive's actual position (drive units) at the reference.
    Done,
    /// Homing failed: the axis goes to ErrorStop with ErrorID 105 (HomingFailed).
    Failed,
}

/// A real drive. The engine calls [`Drive::write`] once per cycle with the set point and
/// reads back the actual values. Positions are the engine's internal (unwrapped) units.
pub trait Drive: Send {
    /// Enables or disables the power stage.
    fn set_enable(&mut self, on: bool);
    /// True when the power stage is enabled (MC_Power.Status).
    fn enabled(&self) -> bool;
    /// Writes the cycle's set point (position, velocity, acceleration).
    fn write(&mut self, p: f64, v: f64, a: f64);
    /// Actual position.
    fn actual_position(&self) -> f64;
    /// Actual velocity.
    fn actual_velocity(&self) -> f64;
    /// A fault code when the drive is in fault (the axis goes to ErrorStop).
    fn fault(&self) -> Option<u16> {
        None
    }
    /// Tries to clear a drive fault (MC_Reset).
    fn reset_fault(&mut self) {}
    /// Starts the drive's homing procedure.
    fn start_homing(&mut self) {}
    /// Polls the homing procedure (default: immediately done, i.e. homing on the spot).
    fn homing_status(&mut self) -> HomingStatus {
        HomingStatus::Done
    }
}
