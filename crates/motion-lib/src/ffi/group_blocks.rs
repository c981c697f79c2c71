//! The axes-group blocks of Part 4 in C: grouping (MC_AddAxisToGroup, MC_RemoveAxisFromGroup,
//! MC_UngroupAllAxes), administration (MC_GroupEnable/Disable/Reset/Stop/Home/Halt, MC_GroupRead*)
//! and path motion (MC_MoveLinear*, MC_MoveDirectAbsolute, MC_MoveCircular*).
//!
//! Input: per block a `#[repr(C)]` struct and the group index. Output: the block's outputs, as
//! [`crate::group_blocks`] computes them, and a status. Invariants: the module contract of
//! [`crate::ffi`].

use super::*;

/// C view of `McAddAxisToGroup` (MC_AddAxisToGroup).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_AddAxisToGroup_C {
    /// Execute: its rising edge carries out the command within this call; Done or Error then show
    /// while Execute stays TRUE (for one call if it already fell).
    pub Execute: bool,
    /// The axis to add (its index in the engine; unknown: ErrorID 1 InvalidAxis).
    pub Axis: u32,
    /// IdentInGroup: the axis's identity in the group, 0..15 (X, Y, Z, A, ...;
    /// `path::IDENT_NAMES`); out of range or already used gives ErrorID 55.
    pub IdentInGroup: u32,
    /// Done: the axis was added to the group (only in GroupDisabled).
    pub Done: bool,
    /// Busy: always FALSE after the call: the command completes within the call.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_AddAxisToGroup_C { done: Done });

/// Calls MC_AddAxisToGroup once (one PLC scan) on axes group `group` of `engine`: reads the inputs
/// from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_AddAxisToGroup_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_add_axis_to_group(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_AddAxisToGroup_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McAddAxisToGroup {
            execute: c.Execute,
            axis: c.Axis as usize,
            ident_in_group: c.IdentInGroup as usize,
            ..Default::default()
        };
        run_immediate(c, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McRemoveAxisFromGroup` (MC_RemoveAxisFromGroup).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_RemoveAxisFromGroup_C {
    /// Execute: its rising edge carries out the command within this call; Done or Error then show
    /// while Execute stays TRUE (for one call if it already fell).
    pub Execute: bool,
    /// IdentInGroup: identity (0..15) of the axis to remove; an identity with no axis gives ErrorID
    /// 57 AxisNotInGroup.
    pub IdentInGroup: u32,
    /// Done: the axis was removed from the group (only in GroupDisabled).
    pub Done: bool,
    /// Busy: always FALSE after the call: the command completes within the call.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_RemoveAxisFromGroup_C { done: Done });

/// Calls MC_RemoveAxisFromGroup once (one PLC scan) on axes group `group` of `engine`: reads the
/// inputs from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_RemoveAxisFromGroup_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_remove_axis_from_group(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_RemoveAxisFromGroup_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McRemoveAxisFromGroup {
            execute: c.Execute,
            ident_in_group: c.IdentInGroup as usize,
            ..Default::default()
        };
        run_immediate(c, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McUngroupAllAxes` (MC_UngroupAllAxes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_UngroupAllAxes_C {
    /// Execute: its rising edge carries out the command within this call; Done or Error then show
    /// while Execute stays TRUE (for one call if it already fell).
    pub Execute: bool,
    /// Done: every axis left the group; the group is GroupDisabled.
    pub Done: bool,
    /// Busy: always FALSE after the call: the command completes within the call.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_UngroupAllAxes_C { done: Done });

/// Calls MC_UngroupAllAxes once (one PLC scan) on axes group `group` of `engine`: reads the inputs
/// from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_UngroupAllAxes_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_ungroup_all_axes(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_UngroupAllAxes_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McUngroupAllAxes {
            execute: c.Execute,
            ..Default::default()
        };
        run_immediate(c, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McGroupEnable` (MC_GroupEnable).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupEnable_C {
    /// Execute: its rising edge carries out the command within this call; Done or Error then show
    /// while Execute stays TRUE (for one call if it already fell).
    pub Execute: bool,
    /// Done: the group went to GroupStandby (every axis powered and in Standstill).
    pub Done: bool,
    /// Busy: always FALSE after the call: the command completes within the call.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_GroupEnable_C { done: Done });

/// Calls MC_GroupEnable once (one PLC scan) on axes group `group` of `engine`: reads the inputs
/// from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_GroupEnable_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_enable(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_GroupEnable_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McGroupEnable {
            execute: c.Execute,
            ..Default::default()
        };
        run_immediate(c, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McGroupDisable` (MC_GroupDisable).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupDisable_C {
    /// Execute: its rising edge carries out the command within this call; Done or Error then show
    /// while Execute stays TRUE (for one call if it already fell).
    pub Execute: bool,
    /// Done: the group went to GroupDisabled.
    pub Done: bool,
    /// Busy: always FALSE after the call: the command completes within the call.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_GroupDisable_C { done: Done });

/// Calls MC_GroupDisable once (one PLC scan) on axes group `group` of `engine`: reads the inputs
/// from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_GroupDisable_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_disable(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_GroupDisable_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McGroupDisable {
            execute: c.Execute,
            ..Default::default()
        };
        run_immediate(c, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McGroupReset` (MC_GroupReset).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupReset_C {
    /// Execute: its rising edge carries out the command within this call; Done or Error then show
    /// while Execute stays TRUE (for one call if it already fell).
    pub Execute: bool,
    /// Done: the group left GroupErrorStop for GroupStandby (or was not in an error).
    pub Done: bool,
    /// Busy: always FALSE after the call: the command completes within the call.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_GroupReset_C { done: Done });

/// Calls MC_GroupReset once (one PLC scan) on axes group `group` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_GroupReset_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_reset(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_GroupReset_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McGroupReset {
            execute: c.Execute,
            ..Default::default()
        };
        run_immediate(c, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McGroupStop` (MC_GroupStop).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupStop_C {
    /// Execute: its rising edge starts braking, aborting every command of the group (also from
    /// Standstill); while Execute stays TRUE after Done the group stays GroupStopping and refuses
    /// motion commands; its falling edge releases it.
    pub Execute: bool,
    /// Deceleration: path braking rate in u/s², finite and > 0 (else ErrorID 22).
    pub Deceleration: f64,
    /// Jerk of the path braking in u/s³ (>= 0; 0 = the axes' jerk limit).
    pub Jerk: f64,
    /// Done: the group reached path velocity 0; it stays GroupStopping (motion commands refused)
    /// while Execute is TRUE.
    pub Done: bool,
    /// Busy: the group is still braking.
    pub Busy: bool,
    /// CommandAborted: the stop was ended by an axis error or a disable before it finished.
    pub CommandAborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_GroupStop_C {
    done: Done,
    command_aborted: CommandAborted
});

/// Calls MC_GroupStop once (one PLC scan) on axes group `group` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_GroupStop_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_stop(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_GroupStop_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McGroupStop {
            execute: c.Execute,
            deceleration: c.Deceleration,
            jerk: c.Jerk,
            ..Default::default()
        };
        run_stop(c, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McGroupHome` (MC_GroupHome).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupHome_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// Position per identity (IdentInGroup), in u: each axis's set position after homing (simulated
    /// drives home on the spot).
    pub Position: [f64; 16],
    /// BufferMode: not used, group homing always starts at once (an unknown value is still refused
    /// with ErrorID 26); it needs GroupStandby.
    pub BufferMode: u8,
    /// Done: every axis of the group homed; the group is back in GroupStandby.
    pub Done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub Busy: bool,
    /// Active: this block's command controls the axis now (a buffered one is Busy but not yet
    /// Active).
    pub Active: bool,
    /// CommandAborted: another command (an Aborting block, MC_Stop, power-off or an axis error)
    /// took over before this one finished.
    pub CommandAborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_GroupHome_C);

/// Calls MC_GroupHome once (one PLC scan) on axes group `group` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_GroupHome_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_home(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_GroupHome_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = McGroupHome {
            execute: c.Execute,
            position: c.Position,
            buffer_mode: enum_in(BufferMode::from_u8(c.BufferMode), &mut bad),
            ..Default::default()
        };
        run_exec(c, bad, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McGroupHalt` (MC_GroupHalt).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupHalt_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// Deceleration: path braking rate in u/s², finite and > 0 (else ErrorID 22).
    pub Deceleration: f64,
    /// Jerk of the path braking in u/s³ (>= 0; 0 = the axes' jerk limit).
    pub Jerk: f64,
    /// BufferMode: Aborting (0) brakes at once; Buffered (1) brakes after the running move ended
    /// (which is then at rest); unknown: ErrorID 26.
    pub BufferMode: u8,
    /// Done: the group reached path velocity 0 (GroupStandby).
    pub Done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub Busy: bool,
    /// Active: this block's command controls the axis now (a buffered one is Busy but not yet
    /// Active).
    pub Active: bool,
    /// CommandAborted: another command (an Aborting block, MC_Stop, power-off or an axis error)
    /// took over before this one finished.
    pub CommandAborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_GroupHalt_C);

/// Calls MC_GroupHalt once (one PLC scan) on axes group `group` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_GroupHalt_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_halt(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_GroupHalt_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = McGroupHalt {
            execute: c.Execute,
            deceleration: c.Deceleration,
            jerk: c.Jerk,
            buffer_mode: enum_in(BufferMode::from_u8(c.BufferMode), &mut bad),
            ..Default::default()
        };
        run_exec(c, bad, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McMoveLinearAbsolute` (MC_MoveLinearAbsolute).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveLinearAbsolute_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// Position: end point per identity (IdentInGroup: X, Y, Z, ...), in u; entries of identities
    /// with no axis in the group are ignored.
    pub Position: [f64; 16],
    /// Velocity: largest path speed, u/s; finite and > 0 (else ErrorID 20); further limited by the
    /// axes' limits projected onto the path.
    pub Velocity: f64,
    /// Acceleration: path acceleration, u/s², finite and > 0 (else ErrorID 21); further limited by
    /// the axes' limits.
    pub Acceleration: f64,
    /// Deceleration: path deceleration, u/s², finite and > 0 (else ErrorID 22); further limited by
    /// the axes' limits.
    pub Deceleration: f64,
    /// Jerk: path jerk, u/s³, finite and >= 0 (else ErrorID 23); 0 = the axes' jerk limit.
    pub Jerk: f64,
    /// CoordSystem: 0 ACS or 1 MCS (both are the axes' own coordinates in this library); another
    /// value gives ErrorID 61 InvalidCoordSystem.
    pub CoordSystem: u8,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub BufferMode: u8,
    /// TransitionMode: the curve joining this move to its predecessor under a blending BufferMode:
    /// TMNone (0, through the corner), TMCornerDistance (3) or TMMaxCornerDeviation (4);
    /// TMStartVelocity (1), TMConstantVelocity (2) and values above 4 give ErrorID 59
    /// InvalidTransitionMode.
    pub TransitionMode: u8,
    /// TransitionParameter: for TMCornerDistance the corner distance d, for TMMaxCornerDeviation
    /// the largest distance e the path may pass from the corner, in u (>= 0, else ErrorID 59);
    /// capped at half of either line.
    pub TransitionParameter: f64,
    /// Done: the end point was reached (set value).
    pub Done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub Busy: bool,
    /// Active: this block's command controls the axis now (a buffered one is Busy but not yet
    /// Active).
    pub Active: bool,
    /// CommandAborted: another command (an Aborting block, MC_Stop, power-off or an axis error)
    /// took over before this one finished.
    pub CommandAborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_MoveLinearAbsolute_C);

/// Calls MC_MoveLinearAbsolute once (one PLC scan) on axes group `group` of `engine`: reads the
/// inputs from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_MoveLinearAbsolute_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_move_linear_absolute(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_MoveLinearAbsolute_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = path_block!(
            McMoveLinearAbsolute,
            c,
            bad {
                execute: c.Execute,
                position: c.Position,
            }
        );
        run_exec(c, bad, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McMoveLinearRelative` (MC_MoveLinearRelative).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveLinearRelative_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// Distance per identity, in u, added to the group's last commanded point; entries of absent
    /// identities are ignored.
    pub Distance: [f64; 16],
    /// Velocity: largest path speed, u/s; finite and > 0 (else ErrorID 20); further limited by the
    /// axes' limits projected onto the path.
    pub Velocity: f64,
    /// Acceleration: path acceleration, u/s², finite and > 0 (else ErrorID 21); further limited by
    /// the axes' limits.
    pub Acceleration: f64,
    /// Deceleration: path deceleration, u/s², finite and > 0 (else ErrorID 22); further limited by
    /// the axes' limits.
    pub Deceleration: f64,
    /// Jerk: path jerk, u/s³, finite and >= 0 (else ErrorID 23); 0 = the axes' jerk limit.
    pub Jerk: f64,
    /// CoordSystem: 0 ACS or 1 MCS (both are the axes' own coordinates in this library); another
    /// value gives ErrorID 61 InvalidCoordSystem.
    pub CoordSystem: u8,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub BufferMode: u8,
    /// TransitionMode: the curve joining this move to its predecessor under a blending BufferMode:
    /// TMNone (0, through the corner), TMCornerDistance (3) or TMMaxCornerDeviation (4);
    /// TMStartVelocity (1), TMConstantVelocity (2) and values above 4 give ErrorID 59
    /// InvalidTransitionMode.
    pub TransitionMode: u8,
    /// TransitionParameter: for TMCornerDistance the corner distance d, for TMMaxCornerDeviation
    /// the largest distance e the path may pass from the corner, in u (>= 0, else ErrorID 59);
    /// capped at half of either line.
    pub TransitionParameter: f64,
    /// Done: the end point was reached (set value).
    pub Done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub Busy: bool,
    /// Active: this block's command controls the axis now (a buffered one is Busy but not yet
    /// Active).
    pub Active: bool,
    /// CommandAborted: another command (an Aborting block, MC_Stop, power-off or an axis error)
    /// took over before this one finished.
    pub CommandAborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_MoveLinearRelative_C);

/// Calls MC_MoveLinearRelative once (one PLC scan) on axes group `group` of `engine`: reads the
/// inputs from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_MoveLinearRelative_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_move_linear_relative(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_MoveLinearRelative_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = path_block!(
            McMoveLinearRelative,
            c,
            bad {
                execute: c.Execute,
                distance: c.Distance,
            }
        );
        run_exec(c, bad, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McMoveDirectAbsolute` (MC_MoveDirectAbsolute).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveDirectAbsolute_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// Position: end point per identity, in u; each axis moves there on its own profile (absent
    /// identities ignored).
    pub Position: [f64; 16],
    /// Velocity: largest speed of each axis, u/s (finite and > 0, else ErrorID 20; capped per axis
    /// by its limit).
    pub Velocity: f64,
    /// Acceleration of each axis, u/s² (finite and > 0, else ErrorID 21; capped per axis by its
    /// limit).
    pub Acceleration: f64,
    /// Deceleration of each axis, u/s² (finite and > 0, else ErrorID 22; capped per axis by its
    /// limit).
    pub Deceleration: f64,
    /// Jerk of each axis, u/s³ (finite and >= 0, else ErrorID 23; 0 = each axis's own limit; capped
    /// per axis).
    pub Jerk: f64,
    /// CoordSystem: 0 ACS or 1 MCS (both are the axes' own coordinates in this library); another
    /// value gives ErrorID 61 InvalidCoordSystem.
    pub CoordSystem: u8,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub BufferMode: u8,
    /// TransitionMode: the curve joining this move to its predecessor under a blending BufferMode:
    /// TMNone (0, through the corner), TMCornerDistance (3) or TMMaxCornerDeviation (4);
    /// TMStartVelocity (1), TMConstantVelocity (2) and values above 4 give ErrorID 59
    /// InvalidTransitionMode.
    pub TransitionMode: u8,
    /// TransitionParameter: for TMCornerDistance the corner distance d, for TMMaxCornerDeviation
    /// the largest distance e the path may pass from the corner, in u (>= 0, else ErrorID 59);
    /// capped at half of either line.
    pub TransitionParameter: f64,
    /// Done: every axis reached its end point (set value).
    pub Done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub Busy: bool,
    /// Active: this block's command controls the axis now (a buffered one is Busy but not yet
    /// Active).
    pub Active: bool,
    /// CommandAborted: another command (an Aborting block, MC_Stop, power-off or an axis error)
    /// took over before this one finished.
    pub CommandAborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_MoveDirectAbsolute_C);

/// Calls MC_MoveDirectAbsolute once (one PLC scan) on axes group `group` of `engine`: reads the
/// inputs from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_MoveDirectAbsolute_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_move_direct_absolute(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_MoveDirectAbsolute_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = path_block!(
            McMoveDirectAbsolute,
            c,
            bad {
                execute: c.Execute,
                position: c.Position,
            }
        );
        run_exec(c, bad, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McMoveCircularAbsolute` (MC_MoveCircularAbsolute).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveCircularAbsolute_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// CircMode: how AuxPoint defines the circle: BORDER (0), CENTER (1) or RADIUS (2); another
    /// value gives ErrorID 60 InvalidCircle.
    pub CircMode: u8,
    /// AuxPoint: per identity, in u: BORDER a point on the arc between start and end, CENTER the
    /// centre (X/Y plane), RADIUS the normal vector of the circle's plane, its length the radius.
    pub AuxPoint: [f64; 16],
    /// EndPoint: end point of the arc per identity (X/Y/Z on the arc, other axes linear), in u.
    pub EndPoint: [f64; 16],
    /// PathChoice (CENTER and RADIUS): MC_CLOCKWISE (0) or MC_COUNTER_CLOCKWISE (1); another value
    /// gives ErrorID 25 InvalidDirection. Ignored for BORDER.
    pub PathChoice: u8,
    /// Velocity: largest path speed, u/s; finite and > 0 (else ErrorID 20); further limited by the
    /// axes' limits projected onto the path.
    pub Velocity: f64,
    /// Acceleration: path acceleration, u/s², finite and > 0 (else ErrorID 21); further limited by
    /// the axes' limits.
    pub Acceleration: f64,
    /// Deceleration: path deceleration, u/s², finite and > 0 (else ErrorID 22); further limited by
    /// the axes' limits.
    pub Deceleration: f64,
    /// Jerk: path jerk, u/s³, finite and >= 0 (else ErrorID 23); 0 = the axes' jerk limit.
    pub Jerk: f64,
    /// CoordSystem: 0 ACS or 1 MCS (both are the axes' own coordinates in this library); another
    /// value gives ErrorID 61 InvalidCoordSystem.
    pub CoordSystem: u8,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub BufferMode: u8,
    /// TransitionMode: the curve joining this move to its predecessor under a blending BufferMode:
    /// TMNone (0, through the corner), TMCornerDistance (3) or TMMaxCornerDeviation (4);
    /// TMStartVelocity (1), TMConstantVelocity (2) and values above 4 give ErrorID 59
    /// InvalidTransitionMode.
    pub TransitionMode: u8,
    /// TransitionParameter: for TMCornerDistance the corner distance d, for TMMaxCornerDeviation
    /// the largest distance e the path may pass from the corner, in u (>= 0, else ErrorID 59);
    /// capped at half of either line.
    pub TransitionParameter: f64,
    /// Done: the end point of the arc was reached (set value).
    pub Done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub Busy: bool,
    /// Active: this block's command controls the axis now (a buffered one is Busy but not yet
    /// Active).
    pub Active: bool,
    /// CommandAborted: another command (an Aborting block, MC_Stop, power-off or an axis error)
    /// took over before this one finished.
    pub CommandAborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_MoveCircularAbsolute_C);

/// Calls MC_MoveCircularAbsolute once (one PLC scan) on axes group `group` of `engine`: reads the
/// inputs from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_MoveCircularAbsolute_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_move_circular_absolute(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_MoveCircularAbsolute_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = circular_block!(McMoveCircularAbsolute, c, bad);
        run_exec(c, bad, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McMoveCircularRelative` (MC_MoveCircularRelative).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveCircularRelative_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// CircMode: how AuxPoint defines the circle: BORDER (0), CENTER (1) or RADIUS (2); another
    /// value gives ErrorID 60 InvalidCircle.
    pub CircMode: u8,
    /// AuxPoint per identity, in u, relative to the start point: BORDER a point on the arc, CENTER
    /// the centre (X/Y plane); RADIUS the normal vector of the circle's plane (never relative), its
    /// length the radius.
    pub AuxPoint: [f64; 16],
    /// EndPoint: end of the arc relative to the start point, per identity, in u.
    pub EndPoint: [f64; 16],
    /// PathChoice (CENTER and RADIUS): MC_CLOCKWISE (0) or MC_COUNTER_CLOCKWISE (1); another value
    /// gives ErrorID 25 InvalidDirection. Ignored for BORDER.
    pub PathChoice: u8,
    /// Velocity: largest path speed, u/s; finite and > 0 (else ErrorID 20); further limited by the
    /// axes' limits projected onto the path.
    pub Velocity: f64,
    /// Acceleration: path acceleration, u/s², finite and > 0 (else ErrorID 21); further limited by
    /// the axes' limits.
    pub Acceleration: f64,
    /// Deceleration: path deceleration, u/s², finite and > 0 (else ErrorID 22); further limited by
    /// the axes' limits.
    pub Deceleration: f64,
    /// Jerk: path jerk, u/s³, finite and >= 0 (else ErrorID 23); 0 = the axes' jerk limit.
    pub Jerk: f64,
    /// CoordSystem: 0 ACS or 1 MCS (both are the axes' own coordinates in this library); another
    /// value gives ErrorID 61 InvalidCoordSystem.
    pub CoordSystem: u8,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub BufferMode: u8,
    /// TransitionMode: the curve joining this move to its predecessor under a blending BufferMode:
    /// TMNone (0, through the corner), TMCornerDistance (3) or TMMaxCornerDeviation (4);
    /// TMStartVelocity (1), TMConstantVelocity (2) and values above 4 give ErrorID 59
    /// InvalidTransitionMode.
    pub TransitionMode: u8,
    /// TransitionParameter: for TMCornerDistance the corner distance d, for TMMaxCornerDeviation
    /// the largest distance e the path may pass from the corner, in u (>= 0, else ErrorID 59);
    /// capped at half of either line.
    pub TransitionParameter: f64,
    /// Done: the end point of the arc was reached (set value).
    pub Done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub Busy: bool,
    /// Active: this block's command controls the axis now (a buffered one is Busy but not yet
    /// Active).
    pub Active: bool,
    /// CommandAborted: another command (an Aborting block, MC_Stop, power-off or an axis error)
    /// took over before this one finished.
    pub CommandAborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_MoveCircularRelative_C);

/// Calls MC_MoveCircularRelative once (one PLC scan) on axes group `group` of `engine`: reads the
/// inputs from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_MoveCircularRelative_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_move_circular_relative(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_MoveCircularRelative_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = circular_block!(McMoveCircularRelative, c, bad);
        run_exec(c, bad, b, |b| b.call(e, group as usize));
        group_ok(e, group)
    })
}

/// C view of `McGroupReadActualPosition` (MC_GroupReadActualPosition).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupReadActualPosition_C {
    /// Enable: while TRUE the block works and its outputs are refreshed every call; FALSE resets
    /// the outputs.
    pub Enable: bool,
    /// CoordSystem: kept for the PLCopen interface; positions are always the axes' own coordinates
    /// (ACS = MCS here).
    pub CoordSystem: u8,
    /// Valid: the value outputs are valid (Enable TRUE and no error).
    pub Valid: bool,
    /// Busy: TRUE while Enable is TRUE and the values are valid.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Position per identity, in u (the set positions; the simulated drives follow them exactly);
    /// zeros for absent identities.
    pub Position: [f64; 16],
}

/// Calls MC_GroupReadActualPosition once (one PLC scan) on axes group `group` of `engine`: reads
/// the inputs from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_GroupReadActualPosition_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_read_actual_position(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_GroupReadActualPosition_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut b = McGroupReadActualPosition {
            enable: c.Enable,
            coord_system: c.CoordSystem,
            ..Default::default()
        };
        b.call(e, group as usize);

        c.Valid = b.valid;
        c.Busy = b.busy;
        c.Error = b.error;
        c.ErrorID = b.error_id.code();
        c.Position = b.position;
        group_ok(e, group)
    })
}

/// C view of `McGroupReadActualVelocity` (MC_GroupReadActualVelocity).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupReadActualVelocity_C {
    /// Enable: while TRUE the block works and its outputs are refreshed every call; FALSE resets
    /// the outputs.
    pub Enable: bool,
    /// CoordSystem: kept for the PLCopen interface; velocities are always in the axes' own
    /// coordinates (ACS = MCS here).
    pub CoordSystem: u8,
    /// Valid: the value outputs are valid (Enable TRUE and no error).
    pub Valid: bool,
    /// Busy: TRUE while Enable is TRUE and the values are valid.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Velocity per identity, in u/s; zeros for absent identities.
    pub Velocity: [f64; 16],
    /// PathVelocity: the speed along the path, u/s (>= 0).
    pub PathVelocity: f64,
}

/// Calls MC_GroupReadActualVelocity once (one PLC scan) on axes group `group` of `engine`: reads
/// the inputs from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_GroupReadActualVelocity_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_read_actual_velocity(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_GroupReadActualVelocity_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut b = McGroupReadActualVelocity {
            enable: c.Enable,
            coord_system: c.CoordSystem,
            ..Default::default()
        };
        b.call(e, group as usize);

        c.Valid = b.valid;
        c.Busy = b.busy;
        c.Error = b.error;
        c.ErrorID = b.error_id.code();
        c.Velocity = b.velocity;
        c.PathVelocity = b.path_velocity;
        group_ok(e, group)
    })
}

/// C view of `McGroupReadStatus` (MC_GroupReadStatus).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupReadStatus_C {
    /// Enable: while TRUE the block works and its outputs are refreshed every call; FALSE resets
    /// the outputs.
    pub Enable: bool,
    /// Valid: the value outputs are valid (Enable TRUE and no error).
    pub Valid: bool,
    /// Busy: TRUE while Enable is TRUE and the state is valid.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// GroupMoving: a group motion (line, circle, direct move, halt) runs.
    pub GroupMoving: bool,
    /// GroupHoming: MC_GroupHome runs.
    pub GroupHoming: bool,
    /// GroupErrorStop: the group is in GroupErrorStop (an axis of it failed; leave it with
    /// MC_GroupReset).
    pub GroupErrorStop: bool,
    /// GroupStandby: the group is enabled and stands still with no command.
    pub GroupStandby: bool,
    /// GroupStopping: MC_GroupStop brakes or holds the group.
    pub GroupStopping: bool,
    /// GroupDisabled: the group is not enabled (axes may be added or removed).
    pub GroupDisabled: bool,
}

/// Calls MC_GroupReadStatus once (one PLC scan) on axes group `group` of `engine`: reads the inputs
/// from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `group` is not a group of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_GroupReadStatus_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_read_status(
    engine: *mut McEngine,
    group: McIndex,
    fb: *mut MC_GroupReadStatus_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut b = McGroupReadStatus {
            enable: c.Enable,
            ..Default::default()
        };
        b.call(e, group as usize);

        c.Valid = b.valid;
        c.Busy = b.busy;
        c.Error = b.error;
        c.ErrorID = b.error_id.code();
        c.GroupMoving = b.group_moving;
        c.GroupHoming = b.group_homing;
        c.GroupErrorStop = b.group_error_stop;
        c.GroupStandby = b.group_standby;
        c.GroupStopping = b.group_stopping;
        c.GroupDisabled = b.group_disabled;
        group_ok(e, group)
    })
}
