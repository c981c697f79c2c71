//! The ABI's constants, emitted as `#define` by cbindgen: BufferMode, Direction, TransitionMode and
//! the other enumerations' values, and the PLCopen ErrorIDs (`MC_ERR_*`) of the blocks' `ErrorID`.
//!
//! Input: none. Output: `pub const` items. Invariants: there is one `MC_ERR_*` per
//! [`crate::error::ErrorId`], named after it and equal to its code (the test below).

/// BufferMode mcAborting: starts at once from the current state; the running and every buffered
/// command get CommandAborted.
pub const MC_ABORTING: u8 = 0;
/// BufferMode mcBuffered: starts when the predecessor finished (Done; InVelocity, InGear, InSync
/// for continuous ones).
pub const MC_BUFFERED: u8 = 1;
/// BufferMode mcBlendingLow: no stop between the moves; the junction speed is the lower of the two
/// velocities.
pub const MC_BLENDING_LOW: u8 = 2;
/// BufferMode mcBlendingPrevious: no stop between the moves; the junction speed is the
/// predecessor's velocity.
pub const MC_BLENDING_PREVIOUS: u8 = 3;
/// BufferMode mcBlendingNext: no stop between the moves; the junction speed is the successor's
/// velocity.
pub const MC_BLENDING_NEXT: u8 = 4;
/// BufferMode mcBlendingHigh: no stop between the moves; the junction speed is the higher of the
/// two velocities.
pub const MC_BLENDING_HIGH: u8 = 5;
/// Direction mcPositiveDirection: modulo targets reached moving forward; MC_MoveVelocity forward.
pub const MC_POSITIVE_DIRECTION: u8 = 0;
/// Direction mcShortestWay: the shorter way round a modulo axis (MC_MoveVelocity refuses it:
/// ErrorID 25).
pub const MC_SHORTEST_WAY: u8 = 1;
/// Direction mcNegativeDirection: modulo targets reached moving backward; MC_MoveVelocity backward.
pub const MC_NEGATIVE_DIRECTION: u8 = 2;
/// Direction mcCurrentDirection: keeps the direction the axis moves in (forward from rest).
pub const MC_CURRENT_DIRECTION: u8 = 3;
/// TransitionMode TMNone: no transition curve; at a real corner the path stops (junction speed 0).
pub const MC_TM_NONE: u8 = 0;
/// TransitionMode TMCornerDistance: a clothoid blend leaving the path TransitionParameter (u)
/// before the corner.
pub const MC_TM_CORNER_DISTANCE: u8 = 3;
/// TransitionMode TMMaxCornerDeviation: the same blend, passing at most TransitionParameter (u)
/// from the corner.
pub const MC_TM_MAX_CORNER_DEVIATION: u8 = 4;
/// MC_CIRC_MODE BORDER (AuxPoint on the arc).
pub const MC_CIRC_BORDER: u8 = 0;
/// MC_CIRC_MODE CENTER (AuxPoint the centre, X/Y plane).
pub const MC_CIRC_CENTER: u8 = 1;
/// MC_CIRC_MODE RADIUS (AuxPoint the plane's normal, its length the radius).
pub const MC_CIRC_RADIUS: u8 = 2;
/// MC_CIRC_PATHCHOICE clockwise.
pub const MC_CLOCKWISE: u8 = 0;
/// MC_CIRC_PATHCHOICE counter-clockwise.
pub const MC_COUNTER_CLOCKWISE: u8 = 1;
/// ErrorID 0: no error.
pub const MC_ERR_NONE: u16 = 0;
/// ErrorID 1: The axis index does not name an axis of the engine.
pub const MC_ERR_INVALID_AXIS: u16 = 1;
/// ErrorID 2: The group index does not name a group of the engine.
pub const MC_ERR_INVALID_GROUP: u16 = 2;
/// ErrorID 3: The cam table reference or CamTableID is unknown.
pub const MC_ERR_INVALID_CAM_TABLE: u16 = 3;
/// ErrorID 10: Motion command on an axis that is not powered (state Disabled).
pub const MC_ERR_AXIS_DISABLED: u16 = 10;
/// ErrorID 11: Command rejected because the axis is in ErrorStop.
pub const MC_ERR_AXIS_ERROR_STOP: u16 = 11;
/// ErrorID 12: Motion command rejected because the axis is Stopping.
pub const MC_ERR_AXIS_STOPPING: u16 = 12;
/// ErrorID 13: Command rejected because the axis is Homing.
pub const MC_ERR_AXIS_HOMING: u16 = 13;
/// ErrorID 14: MC_Home needs the axis in Standstill.
pub const MC_ERR_NOT_STANDSTILL: u16 = 14;
/// ErrorID 15: MC_GearOut / MC_CamOut on an axis that is not in SynchronizedMotion (or not by that kind).
pub const MC_ERR_NOT_SYNCHRONIZED: u16 = 15;
/// ErrorID 16: Single-axis command on an axis owned by an enabled group.
pub const MC_ERR_AXIS_IN_GROUP: u16 = 16;
/// ErrorID 17: MC_Reset while the axis still brakes after the error.
pub const MC_ERR_AXIS_STILL_MOVING: u16 = 17;
/// ErrorID 18: MC_Reset cannot clear the error: the drive still reports a fault.
pub const MC_ERR_DRIVE_FAULT_ACTIVE: u16 = 18;
/// ErrorID 20: Velocity input is not finite, zero or negative where a positive value is needed.
pub const MC_ERR_INVALID_VELOCITY: u16 = 20;
/// ErrorID 21: Acceleration input is not finite or not > 0.
pub const MC_ERR_INVALID_ACCELERATION: u16 = 21;
/// ErrorID 22: Deceleration input is not finite or not > 0.
pub const MC_ERR_INVALID_DECELERATION: u16 = 22;
/// ErrorID 23: Jerk input is not finite or negative.
pub const MC_ERR_INVALID_JERK: u16 = 23;
/// ErrorID 24: Position or distance input is not finite.
pub const MC_ERR_INVALID_POSITION: u16 = 24;
/// ErrorID 25: Direction not allowed here (e.g. mcShortestWay for MC_MoveVelocity) or unknown.
pub const MC_ERR_INVALID_DIRECTION: u16 = 25;
/// ErrorID 26: BufferMode value unknown or not allowed for this block.
pub const MC_ERR_INVALID_BUFFER_MODE: u16 = 26;
/// ErrorID 27: The target lies outside the enabled software position limits.
pub const MC_ERR_TARGET_BEYOND_SOFTWARE_LIMIT: u16 = 27;
/// ErrorID 28: Gear ratio invalid (denominator 0 or not finite).
pub const MC_ERR_INVALID_RATIO: u16 = 28;
/// ErrorID 29: The planned path (a time-optimal overshoot, braking from the current velocity) leaves the enabled software position limits.
pub const MC_ERR_PATH_BEYOND_SOFTWARE_LIMIT: u16 = 29;
/// ErrorID 30: Override factor out of range: VelFactor negative or not finite, AccFactor or JerkFactor outside [0, 1] (0 = 1).
pub const MC_ERR_INVALID_OVERRIDE: u16 = 30;
/// ErrorID 31: The profile planner found no profile for these inputs.
pub const MC_ERR_PLANNING_FAILED: u16 = 31;
/// ErrorID 32: ExecutionMode, StartMode or another enumerated input is out of range.
pub const MC_ERR_INVALID_MODE: u16 = 32;
/// ErrorID 33: MC_CamIn: the cam law, for a master within its axis limits, needs more than the slave's velocity, acceleration or jerk limit, or the slave's motion relative to the law at coupling does not fit in what the law leaves.
pub const MC_ERR_CAM_BEYOND_SLAVE_LIMITS: u16 = 33;
/// ErrorID 34: MC_GearIn: the ratio times the master's axis limits (velocity, acceleration, jerk) leaves none of the slave's limits: a master within its own limits could drive the slave past them.
pub const MC_ERR_GEAR_BEYOND_SLAVE_LIMITS: u16 = 34;
/// ErrorID 40: The axis's (or group's) command queue is full: the command is rejected, nothing is dropped.
pub const MC_ERR_QUEUE_FULL: u16 = 40;
/// ErrorID 50: Group motion or group command on a group in GroupDisabled.
pub const MC_ERR_GROUP_DISABLED: u16 = 50;
/// ErrorID 51: Command rejected because the group is in GroupErrorStop.
pub const MC_ERR_GROUP_ERROR_STOP: u16 = 51;
/// ErrorID 52: Motion command rejected because the group is GroupStopping.
pub const MC_ERR_GROUP_STOPPING: u16 = 52;
/// ErrorID 53: Command rejected because the group is GroupHoming.
pub const MC_ERR_GROUP_HOMING: u16 = 53;
/// ErrorID 54: Axes can be added or removed only in GroupDisabled.
pub const MC_ERR_GROUP_NOT_DISABLED: u16 = 54;
/// ErrorID 55: IdentInGroup out of range (0..16) or already used.
pub const MC_ERR_INVALID_IDENT_IN_GROUP: u16 = 55;
/// ErrorID 56: The axis already belongs to a group.
pub const MC_ERR_AXIS_ALREADY_IN_GROUP: u16 = 56;
/// ErrorID 57: The axis is not in this group.
pub const MC_ERR_AXIS_NOT_IN_GROUP: u16 = 57;
/// ErrorID 58: MC_GroupEnable needs at least one axis, every axis powered and in Standstill.
pub const MC_ERR_GROUP_AXES_NOT_READY: u16 = 58;
/// ErrorID 59: TransitionMode unknown or not supported (TMStartVelocity, TMConstantVelocity), or a negative TransitionParameter.
pub const MC_ERR_INVALID_TRANSITION_MODE: u16 = 59;
/// ErrorID 60: The circle is not defined (collinear points, end point off the circle, zero radius).
pub const MC_ERR_INVALID_CIRCLE: u16 = 60;
/// ErrorID 61: CoordSystem other than ACS/MCS (0, 1) is not supported.
pub const MC_ERR_INVALID_COORD_SYSTEM: u16 = 61;
/// ErrorID 62: MC_GroupDisable while the group is moving.
pub const MC_ERR_GROUP_MOVING: u16 = 62;
/// ErrorID 63: A position array names an axis identity that is not in the group.
pub const MC_ERR_INVALID_POSITION_ARRAY: u16 = 63;
/// ErrorID 100: Set position reached the positive software limit.
pub const MC_ERR_SOFTWARE_LIMIT_POSITIVE: u16 = 100;
/// ErrorID 101: Set position reached the negative software limit.
pub const MC_ERR_SOFTWARE_LIMIT_NEGATIVE: u16 = 101;
/// ErrorID 102: |set position - actual position| exceeded the configured following-error limit.
pub const MC_ERR_FOLLOWING_ERROR: u16 = 102;
/// ErrorID 103: The drive reported a fault (see the drive's own code).
pub const MC_ERR_DRIVE_FAULT: u16 = 103;
/// ErrorID 104: The drive lost its enable while powered.
pub const MC_ERR_DRIVE_DISABLED: u16 = 104;
/// ErrorID 105: Homing failed in the drive.
pub const MC_ERR_HOMING_FAILED: u16 = 105;
/// ErrorID 106: An axis of the group went to ErrorStop (group error).
pub const MC_ERR_GROUP_AXIS_ERROR: u16 = 106;
/// ErrorID 107: Error set from outside (tests, `Engine::raise_axis_error`).
pub const MC_ERR_EXTERNAL_ERROR: u16 = 107;

#[cfg(test)]
mod tests {
    use crate::error::ErrorId;

    /// `InvalidCamTable` -> `MC_ERR_INVALID_CAM_TABLE`.
    fn constant_name(e: ErrorId) -> String {
        let mut name = String::from("MC_ERR");
        for ch in format!("{e:?}").chars() {
            if ch.is_ascii_uppercase() {
                name.push('_');
            }
            name.push(ch.to_ascii_uppercase());
        }
        name
    }

    #[test]
    fn every_error_id_has_its_constant_with_its_code() {
        // The constants as cbindgen reads them: `pub const MC_ERR_X: u16 = N;` lines of this file.
        let consts: Vec<(&str, u16)> = include_str!("constants.rs")
            .lines()
            .filter_map(|l| l.strip_prefix("pub const MC_ERR_"))
            .filter_map(|l| {
                let (name, value) = l.split_once(": u16 = ")?;
                Some((name, value.trim_end_matches(';').parse().ok()?))
            })
            .collect();
        assert_eq!(consts.len(), ErrorId::ALL.len(), "one MC_ERR_* per ErrorId");
        for &e in ErrorId::ALL {
            let name = constant_name(e);
            let value = consts
                .iter()
                .find(|(n, _)| format!("MC_ERR_{n}") == name)
                .map(|(_, v)| *v);
            assert_eq!(value, Some(e.code()), "{name} for {e:?}");
        }
    }
}
