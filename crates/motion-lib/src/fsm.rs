//! The PLCopen state machines: single axis (Part 1 fig. 2) and axes group (Part 4).
//!
//! Input: the current state and the class of a command. Output: whether the command is
//! legal there (else the documented [`ErrorId`]) and the state it leads to.
//! Invariant: these tables are the only place that decides legality; the engine applies
//! the transitions they return.

use crate::error::ErrorId;

/// Single-axis states (PLCopen Part 1, fig. 2).
#[repr(u8)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum AxisState {
    #[default]
    /// Not powered (MC_Power.Enable FALSE); the start state. Motion commands are refused (ErrorID 10).
    Disabled = 0,
    /// Powered, no motion command; every motion command and MC_Home may start here.
    Standstill = 1,
    /// MC_Home runs; back to Standstill when it ends.
    Homing = 2,
    /// A positioning move (MoveAbsolute, MoveRelative, MoveAdditive) or MC_Halt runs; Standstill
    /// when it ends.
    DiscreteMotion = 3,
    /// MC_MoveVelocity runs (never ends by itself), or a slave runs on after MC_GearOut /
    /// MC_CamOut.
    ContinuousMotion = 4,
    /// A geared or cammed slave (MC_GearIn, MC_CamIn), or a member of a moving axes group.
    SynchronizedMotion = 5,
    /// MC_Stop brakes the axis or holds it (while its Execute is TRUE); motion commands are refused
    /// (ErrorID 12).
    Stopping = 6,
    /// An axis error: the axis brakes with its own limits and refuses commands (ErrorID 11) until
    /// MC_Reset.
    ErrorStop = 7,
}

/// Axes-group states (PLCopen Part 4).
#[repr(u8)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum GroupState {
    #[default]
    /// The group is not enabled (the start state); axes are added and removed only here.
    GroupDisabled = 0,
    /// Enabled, no group motion; its axes refuse single-axis motion (ErrorID 16).
    GroupStandby = 1,
    /// A group move (line, circle, direct move, halt) runs; the axes are in SynchronizedMotion.
    GroupMoving = 2,
    /// MC_GroupHome runs; GroupStandby when every axis homed.
    GroupHoming = 3,
    /// MC_GroupStop brakes or holds the group; motion commands are refused (ErrorID 52).
    GroupStopping = 4,
    /// An axis of the group failed or lost power: the path brakes; MC_GroupReset returns to
    /// GroupStandby.
    GroupErrorStop = 5,
}

/// Classes of single-axis commands, as the state diagram sees them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AxisCmd {
    /// MoveAbsolute, MoveRelative, MoveAdditive, Halt: -> DiscreteMotion.
    Discrete,
    /// MoveVelocity: -> ContinuousMotion.
    Continuous,
    /// GearIn, CamIn: -> SynchronizedMotion.
    Synchronized,
    /// GearOut, CamOut: SynchronizedMotion -> ContinuousMotion.
    SyncOut,
    /// Home: Standstill -> Homing.
    Home,
    /// Stop: -> Stopping.
    Stop,
}

impl AxisCmd {
    /// The state a legal command of this class leads to.
    pub fn target(self) -> AxisState {
        match self {
            AxisCmd::Discrete => AxisState::DiscreteMotion,
            AxisCmd::Continuous | AxisCmd::SyncOut => AxisState::ContinuousMotion,
            AxisCmd::Synchronized => AxisState::SynchronizedMotion,
            AxisCmd::Home => AxisState::Homing,
            AxisCmd::Stop => AxisState::Stopping,
        }
    }
}

/// Is `cmd` legal in `state`? The error says why not.
pub fn check_axis(state: AxisState, cmd: AxisCmd) -> Result<AxisState, ErrorId> {
    use AxisState::*;
    let err = match (state, cmd) {
        (ErrorStop, _) => Some(ErrorId::AxisErrorStop),
        (Disabled, _) => Some(ErrorId::AxisDisabled),
        (Stopping, AxisCmd::Stop) => None,
        (Stopping, _) => Some(ErrorId::AxisStopping),
        (Homing, AxisCmd::Stop) => None,
        (Homing, _) => Some(ErrorId::AxisHoming),
        (Standstill, AxisCmd::Home) => None,
        (_, AxisCmd::Home) => Some(ErrorId::NotStandstill),
        (SynchronizedMotion, AxisCmd::SyncOut) => None,
        (_, AxisCmd::SyncOut) => Some(ErrorId::NotSynchronized),
        (Standstill | DiscreteMotion | ContinuousMotion | SynchronizedMotion, _) => None,
    };
    match err {
        Some(e) => Err(e),
        None => Ok(cmd.target()),
    }
}

/// Classes of group commands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GroupCmd {
    /// MC_GroupEnable.
    Enable,
    /// MC_GroupDisable.
    Disable,
    /// MC_AddAxisToGroup, MC_RemoveAxisFromGroup.
    Configure,
    /// MC_UngroupAllAxes.
    Ungroup,
    /// Group motion (MoveLinear*, MoveCircular*, MoveDirect*, GroupHalt).
    Motion,
    /// MC_GroupStop.
    Stop,
    /// MC_GroupReset.
    Reset,
    /// MC_GroupHome: GroupStandby -> GroupHoming.
    Home,
}

/// Is `cmd` legal in `state`? Returns the resulting state.
pub fn check_group(state: GroupState, cmd: GroupCmd) -> Result<GroupState, ErrorId> {
    use GroupState::*;
    match (cmd, state) {
        (GroupCmd::Configure, GroupDisabled) => Ok(GroupDisabled),
        (GroupCmd::Configure, _) => Err(ErrorId::GroupNotDisabled),
        (GroupCmd::Ungroup, GroupMoving | GroupHoming | GroupStopping) => Err(ErrorId::GroupMoving),
        (GroupCmd::Ungroup, _) => Ok(GroupDisabled),
        (GroupCmd::Enable, GroupDisabled | GroupStandby) => Ok(GroupStandby),
        (GroupCmd::Enable, GroupErrorStop) => Err(ErrorId::GroupErrorStop),
        (GroupCmd::Enable, _) => Ok(state),
        (GroupCmd::Disable, GroupMoving | GroupHoming | GroupStopping) => Err(ErrorId::GroupMoving),
        (GroupCmd::Disable, _) => Ok(GroupDisabled),
        (GroupCmd::Motion, GroupStandby | GroupMoving) => Ok(GroupMoving),
        (GroupCmd::Motion, GroupDisabled) => Err(ErrorId::GroupDisabled),
        (GroupCmd::Motion, GroupErrorStop) => Err(ErrorId::GroupErrorStop),
        (GroupCmd::Motion, GroupStopping) => Err(ErrorId::GroupStopping),
        (GroupCmd::Motion, GroupHoming) => Err(ErrorId::GroupHoming),
        (GroupCmd::Stop, GroupStandby | GroupMoving | GroupHoming | GroupStopping) => {
            Ok(GroupStopping)
        }
        (GroupCmd::Stop, GroupDisabled) => Err(ErrorId::GroupDisabled),
        (GroupCmd::Stop, GroupErrorStop) => Err(ErrorId::GroupErrorStop),
        (GroupCmd::Home, GroupStandby) => Ok(GroupHoming),
        (GroupCmd::Home, GroupDisabled) => Err(ErrorId::GroupDisabled),
        (GroupCmd::Home, GroupErrorStop) => Err(ErrorId::GroupErrorStop),
        (GroupCmd::Home, GroupStopping) => Err(ErrorId::GroupStopping),
        (GroupCmd::Home, GroupHoming) => Err(ErrorId::GroupHoming),
        (GroupCmd::Home, GroupMoving) => Err(ErrorId::GroupMoving),
        (GroupCmd::Reset, GroupErrorStop) => Ok(GroupStandby),
        (GroupCmd::Reset, _) => Ok(state),
    }
}
