//! ErrorID values of the motion library (PLCopen `ErrorID : WORD`, vendor-defined).
//!
//! Input: none. Output: [`ErrorId`], the one table of codes reported by every block's
//! `ErrorID` output and by `MC_ReadAxisError.AxisErrorID`. Invariant: the numeric values are
//! stable (the C ABI and compiled PLC programs see them); the README's table lists them all.

/// Every error a block or an axis can report. `ErrorId::None` (0) means no error.
#[repr(u16)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum ErrorId {
    #[default]
    /// No error (0).
    None = 0,
    /// The axis index does not name an axis of the engine.
    InvalidAxis = 1,
    /// The group index does not name a group of the engine.
    InvalidGroup = 2,
    /// The cam table reference or CamTableID is unknown.
    InvalidCamTable = 3,
    /// Motion command on an axis that is not powered (state Disabled).
    AxisDisabled = 10,
    /// Command rejected because the axis is in ErrorStop.
    AxisErrorStop = 11,
    /// Motion command rejected because the axis is Stopping.
    AxisStopping = 12,
    /// Command rejected because the axis is Homing.
    AxisHoming = 13,
    /// MC_Home needs the axis in Standstill.
    NotStandstill = 14,
    /// MC_GearOut / MC_CamOut on an axis that is not in SynchronizedMotion (or not by that kind).
    NotSynchronized = 15,
    /// Single-axis command on an axis owned by an enabled group.
    AxisInGroup = 16,
    /// MC_Reset while the axis still brakes after the error.
    AxisStillMoving = 17,
    /// MC_Reset cannot clear the error: the drive still reports a fault.
    DriveFaultActive = 18,
    /// Velocity input is not finite, zero or negative where a positive value is needed.
    InvalidVelocity = 20,
    /// Acceleration input is not finite or not > 0.
    InvalidAcceleration = 21,
    /// Deceleration input is not finite or not > 0.
    InvalidDeceleration = 22,
    /// Jerk input is not finite or negative.
    InvalidJerk = 23,
    /// Position or distance input is not finite.
    InvalidPosition = 24,
    /// Direction not allowed here (e.g. mcShortestWay for MC_MoveVelocity) or unknown.
    InvalidDirection = 25,
    /// BufferMode value unknown or not allowed for this block.
    InvalidBufferMode = 26,
    /// The target lies outside the enabled software position limits.
    TargetBeyondSoftwareLimit = 27,
    /// Gear ratio invalid (denominator 0 or not finite).
    InvalidRatio = 28,
    /// The planned path (a time-optimal overshoot, braking from the current velocity) leaves
    /// the enabled software position limits.
    PathBeyondSoftwareLimit = 29,
    /// Override factor out of range: VelFactor negative or not finite, AccFactor or JerkFactor outside [0, 1] (0 = 1).
    InvalidOverride = 30,
    /// The profile planner found no profile for these inputs.
    PlanningFailed = 31,
    /// ExecutionMode, StartMode or another enumerated input is out of range.
    InvalidMode = 32,
    /// MC_CamIn: the cam law, for a master within its axis limits, needs more than the slave's velocity, acceleration or jerk limit, or the slave's motion relative to the law at coupling does not fit in what the law leaves.
    CamBeyondSlaveLimits = 33,
    /// MC_GearIn: the ratio times the master's axis limits (velocity, acceleration, jerk) leaves none of the slave's limits: a master within its own limits could drive the slave past them.
    GearBeyondSlaveLimits = 34,
    /// The axis's (or group's) command queue is full: the command is rejected, nothing is dropped.
    QueueFull = 40,
    /// Group motion or group command on a group in GroupDisabled.
    GroupDisabled = 50,
    /// Command rejected because the group is in GroupErrorStop.
    GroupErrorStop = 51,
    /// Motion command rejected because the group is GroupStopping.
    GroupStopping = 52,
    /// Command rejected because the group is GroupHoming.
    GroupHoming = 53,
    /// Axes can be added or removed only in GroupDisabled.
    GroupNotDisabled = 54,
    /// IdentInGroup out of range (0..16) or already used.
    InvalidIdentInGroup = 55,
    /// The axis already belongs to a group.
    AxisAlreadyInGroup = 56,
    /// The axis is not in this group.
    AxisNotInGroup = 57,
    /// MC_GroupEnable needs at least one axis, every axis powered and in Standstill.
    GroupAxesNotReady = 58,
    /// TransitionMode unknown or not supported (TMStartVelocity, TMConstantVelocity), or a negative TransitionParameter.
    InvalidTransitionMode = 59,
    /// The circle is not defined (collinear points, end point off the circle, zero radius).
    InvalidCircle = 60,
    /// CoordSystem other than ACS/MCS (0, 1) is not supported.
    InvalidCoordSystem = 61,
    /// MC_GroupDisable while the group is moving.
    GroupMoving = 62,
    /// A position array names an axis identity that is not in the group.
    InvalidPositionArray = 63,
    // ---- axis errors (AxisErrorID; they put the axis into ErrorStop) ----
    /// Set position reached the positive software limit.
    SoftwareLimitPositive = 100,
    /// Set position reached the negative software limit.
    SoftwareLimitNegative = 101,
    /// |set position - actual position| exceeded the configured following-error limit.
    FollowingError = 102,
    /// The drive reported a fault (see the drive's own code).
    DriveFault = 103,
    /// The drive lost its enable while powered.
    DriveDisabled = 104,
    /// Homing failed in the drive.
    HomingFailed = 105,
    /// An axis of the group went to ErrorStop (group error).
    GroupAxisError = 106,
    /// Error set from outside (tests, `Engine::raise_axis_error`).
    ExternalError = 107,
}

impl ErrorId {
    /// The WORD value of the error.
    pub fn code(self) -> u16 {
        self as u16
    }

    /// True unless this is [`ErrorId::None`].
    pub fn is_error(self) -> bool {
        self != ErrorId::None
    }

    /// All errors, in code order (for the README table and tests).
    pub const ALL: &'static [ErrorId] = &[
        ErrorId::None,
        ErrorId::InvalidAxis,
        ErrorId::InvalidGroup,
        ErrorId::InvalidCamTable,
        ErrorId::AxisDisabled,
        ErrorId::AxisErrorStop,
        ErrorId::AxisStopping,
        ErrorId::AxisHoming,
        ErrorId::NotStandstill,
        ErrorId::NotSynchronized,
        ErrorId::AxisInGroup,
        ErrorId::AxisStillMoving,
        ErrorId::DriveFaultActive,
        ErrorId::InvalidVelocity,
        ErrorId::InvalidAcceleration,
        ErrorId::InvalidDeceleration,
        ErrorId::InvalidJerk,
        ErrorId::InvalidPosition,
        ErrorId::InvalidDirection,
        ErrorId::InvalidBufferMode,
        ErrorId::TargetBeyondSoftwareLimit,
        ErrorId::InvalidRatio,
        ErrorId::PathBeyondSoftwareLimit,
        ErrorId::InvalidOverride,
        ErrorId::PlanningFailed,
        ErrorId::InvalidMode,
        ErrorId::CamBeyondSlaveLimits,
        ErrorId::GearBeyondSlaveLimits,
        ErrorId::QueueFull,
        ErrorId::GroupDisabled,
        ErrorId::GroupErrorStop,
        ErrorId::GroupStopping,
        ErrorId::GroupHoming,
        ErrorId::GroupNotDisabled,
        ErrorId::InvalidIdentInGroup,
        ErrorId::AxisAlreadyInGroup,
        ErrorId::AxisNotInGroup,
        ErrorId::GroupAxesNotReady,
        ErrorId::InvalidTransitionMode,
        ErrorId::InvalidCircle,
        ErrorId::InvalidCoordSystem,
        ErrorId::GroupMoving,
        ErrorId::InvalidPositionArray,
        ErrorId::SoftwareLimitPositive,
        ErrorId::SoftwareLimitNegative,
        ErrorId::FollowingError,
        ErrorId::DriveFault,
        ErrorId::DriveDisabled,
        ErrorId::HomingFailed,
        ErrorId::GroupAxisError,
        ErrorId::ExternalError,
    ];
}

impl ErrorId {
    /// The error with WORD value `code` (unknown values map to `ExternalError`).
    pub fn from_code(code: u16) -> ErrorId {
        ErrorId::ALL
            .iter()
            .copied()
            .find(|e| e.code() == code)
            .unwrap_or(ErrorId::ExternalError)
    }
}
