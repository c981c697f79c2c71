//! The synchronised-motion blocks of Part 1 in C: MC_GearIn, MC_GearOut, MC_CamTableSelect, MC_CamIn
//! and MC_CamOut (a master and a slave axis).
//!
//! Input: per block a `#[repr(C)]` struct and the master/slave indices. Output: the block's outputs,
//! as [`crate::blocks`] computes them, and a status. Invariants: the module contract of
//! [`crate::ffi`]; gearing and camming never drive the slave past its own limits (ErrorIDs 33, 34).

use super::*;

/// C view of `McGearIn` (MC_GearIn).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GearIn_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// ContinuousUpdate: part of the PLCopen interface but not acted on by this block: the ratio is
    /// latched at the rising edge.
    pub ContinuousUpdate: bool,
    /// RatioNumerator: numerator of the gear ratio slave/master (finite; negative reverses the
    /// slave).
    pub RatioNumerator: f64,
    /// RatioDenominator: denominator of the gear ratio; finite and non-zero, else ErrorID 28
    /// InvalidRatio.
    pub RatioDenominator: f64,
    /// MasterValueSource: the master value followed: its set value (0, mcSetValue, the default) or
    /// its actual value (1, mcActualValue); another value gives ErrorID 32 InvalidMode.
    pub MasterValueSource: u8,
    /// Acceleration of the catch-up profile that brings the slave onto ratio * master, u/s² (> 0;
    /// capped by the slave's limits less the master's share).
    pub Acceleration: f64,
    /// Deceleration of the catch-up profile, u/s² (> 0).
    pub Deceleration: f64,
    /// Jerk of the catch-up profile, u/s³ (>= 0; 0 = the slave's jerk limit).
    pub Jerk: f64,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub BufferMode: u8,
    /// InGear: the slave's catch-up profile ended and it follows ratio * master (on the set value,
    /// while Active).
    pub InGear: bool,
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

block_c!(MC_GearIn_C {
    in_target: InGear,
    active: Active,
    command_aborted: CommandAborted
});

/// Calls MC_GearIn once (one PLC scan) on master axis `master` and slave axis `slave` of `engine`:
/// reads the inputs from `*fb`, runs the block and writes its outputs and `_internal` back to
/// `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `master` or `slave` is not an axis of the engine (the outputs are
/// still written: the block reports the bad index through Error/ErrorID when it acts);
/// `MC_STATUS_PANIC` after a panic (the engine is poisoned). PLCopen errors of the block itself are
/// in `fb->ErrorID`, not in the status. Call it from the one thread that drives `engine` (normally
/// the PLC scan task), once per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_GearIn_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_gear_in(
    engine: *mut McEngine,
    master: McIndex,
    slave: McIndex,
    fb: *mut MC_GearIn_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = McGearIn {
            execute: c.Execute,
            continuous_update: c.ContinuousUpdate,
            ratio_numerator: c.RatioNumerator,
            ratio_denominator: c.RatioDenominator,
            master_value_source: enum_in(master_source(c.MasterValueSource), &mut bad),
            acceleration: c.Acceleration,
            deceleration: c.Deceleration,
            jerk: c.Jerk,
            buffer_mode: enum_in(BufferMode::from_u8(c.BufferMode), &mut bad),
            ..Default::default()
        };
        run_exec(c, bad, b, |b| b.call(e, master as usize, slave as usize));
        axis_ok(e, master)?;
        axis_ok(e, slave)
    })
}

/// C view of `McSyncOut` (MC_GearOut).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GearOut_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error and ErrorID.
    pub Execute: bool,
    /// Done: the slave was decoupled; it runs on at its current velocity (ContinuousMotion).
    pub Done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_GearOut_C { done: Done });

/// Calls MC_GearOut once (one PLC scan) on slave axis `slave` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `slave` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_GearOut_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_gear_out(
    engine: *mut McEngine,
    slave: McIndex,
    fb: *mut MC_GearOut_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McSyncOut {
            execute: c.Execute,
            ..Default::default()
        };
        run_exec(c, None, b, |b| b.call_gear_out(e, slave as usize));
        axis_ok(e, slave)
    })
}

/// C view of `McSyncOut` (MC_CamOut).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_CamOut_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error and ErrorID.
    pub Execute: bool,
    /// Done: the slave was decoupled; it runs on at its current velocity (ContinuousMotion).
    pub Done: bool,
    /// Busy: the command was accepted and has not finished (queued in the buffer or running).
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_CamOut_C { done: Done });

/// Calls MC_CamOut once (one PLC scan) on slave axis `slave` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `slave` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_CamOut_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_cam_out(
    engine: *mut McEngine,
    slave: McIndex,
    fb: *mut MC_CamOut_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McSyncOut {
            execute: c.Execute,
            ..Default::default()
        };
        run_exec(c, None, b, |b| b.call_cam_out(e, slave as usize));
        axis_ok(e, slave)
    })
}

/// C view of `McCamTableSelect` (MC_CamTableSelect).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_CamTableSelect_C {
    /// Execute: its rising edge carries out the command within this call; Done or Error then show
    /// while Execute stays TRUE (for one call if it already fell).
    pub Execute: bool,
    /// CamTable: the CAM_REF, the index `mc_engine_add_cam_table` (Rust: `Engine::add_cam_table`)
    /// returned.
    pub CamTable: u32,
    /// Periodic: PLCopen input kept for the interface; the cam's periodicity is MC_CamIn's Periodic
    /// input here.
    pub Periodic: bool,
    /// MasterAbsolute: PLCopen input kept for the interface; MC_CamIn's MasterAbsolute input is
    /// used.
    pub MasterAbsolute: bool,
    /// SlaveAbsolute: PLCopen input kept for the interface; MC_CamIn's SlaveAbsolute input is used.
    pub SlaveAbsolute: bool,
    /// Done: the table and both axes exist; CamTableID is valid.
    pub Done: bool,
    /// Busy: always FALSE after the call: the command completes within the call.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// CamTableID: the checked table, to be given to MC_CamIn; set when Done.
    pub CamTableID: u32,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_CamTableSelect_C { done: Done });

/// Calls MC_CamTableSelect once (one PLC scan) on master axis `master` and slave axis `slave` of
/// `engine`: reads the inputs from `*fb`, runs the block and writes its outputs and `_internal`
/// back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `master` or `slave` is not an axis of the engine (the outputs are
/// still written: the block reports the bad index through Error/ErrorID when it acts);
/// `MC_STATUS_PANIC` after a panic (the engine is poisoned). PLCopen errors of the block itself are
/// in `fb->ErrorID`, not in the status. Call it from the one thread that drives `engine` (normally
/// the PLC scan task), once per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_CamTableSelect_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_cam_table_select(
    engine: *mut McEngine,
    master: McIndex,
    slave: McIndex,
    fb: *mut MC_CamTableSelect_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McCamTableSelect {
            execute: c.Execute,
            cam_table: c.CamTable as usize,
            periodic: c.Periodic,
            master_absolute: c.MasterAbsolute,
            slave_absolute: c.SlaveAbsolute,
            cam_table_id: c.CamTableID as usize,
            ..Default::default()
        };
        let b = run_immediate(c, b, |b| b.call(e, master as usize, slave as usize));
        c.CamTableID = b.cam_table_id as u32;
        axis_ok(e, master)?;
        axis_ok(e, slave)
    })
}

/// C view of `McCamIn` (MC_CamIn).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_CamIn_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// ContinuousUpdate: part of the PLCopen interface but not acted on by this block: the inputs
    /// are latched at the rising edge.
    pub ContinuousUpdate: bool,
    /// MasterOffset: subtracted from the master position before the table look-up, in u (table x =
    /// (master - MasterOffset) * MasterScaling).
    pub MasterOffset: f64,
    /// SlaveOffset: added to the table's slave value, in u (slave = SlaveScaling * y +
    /// SlaveOffset).
    pub SlaveOffset: f64,
    /// MasterScaling: factor on the master position before the table look-up; 0 stands for 1.
    pub MasterScaling: f64,
    /// SlaveScaling: factor on the table's slave value; 0 stands for 1.
    pub SlaveScaling: f64,
    /// MasterValueSource: the master value followed: its set value (0, mcSetValue, the default) or
    /// its actual value (1, mcActualValue); another value gives ErrorID 32 InvalidMode.
    pub MasterValueSource: u8,
    /// CamTableID: the table to follow, as returned by MC_CamTableSelect (unknown: ErrorID 3
    /// InvalidCamTable).
    pub CamTableID: u32,
    /// Periodic: TRUE repeats the table (each period the slave advances by the table's rise and
    /// EndOfProfile pulses); FALSE continues the law beyond the table's master range along its end
    /// tangents (a straight line, so the velocity never steps; end the table flat to dwell).
    pub Periodic: bool,
    /// MasterAbsolute: TRUE looks the table up with the master's absolute position; FALSE with the
    /// distance the master travelled since coupling.
    pub MasterAbsolute: bool,
    /// SlaveAbsolute: TRUE the table gives the slave's absolute position; FALSE a position relative
    /// to where the slave was at coupling.
    pub SlaveAbsolute: bool,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub BufferMode: u8,
    /// InSync: the slave's catch-up profile ended and it follows the cam law (on the set value,
    /// while Active).
    pub InSync: bool,
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
    /// EndOfProfile: TRUE in the cycle the master passes the end of the table (Periodic: each
    /// period boundary), while Active.
    pub EndOfProfile: bool,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_CamIn_C {
    in_target: InSync,
    active: Active,
    command_aborted: CommandAborted,
    end_of_profile: EndOfProfile
});

/// Calls MC_CamIn once (one PLC scan) on master axis `master` and slave axis `slave` of `engine`:
/// reads the inputs from `*fb`, runs the block and writes its outputs and `_internal` back to
/// `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `master` or `slave` is not an axis of the engine (the outputs are
/// still written: the block reports the bad index through Error/ErrorID when it acts);
/// `MC_STATUS_PANIC` after a panic (the engine is poisoned). PLCopen errors of the block itself are
/// in `fb->ErrorID`, not in the status. Call it from the one thread that drives `engine` (normally
/// the PLC scan task), once per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_CamIn_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_cam_in(
    engine: *mut McEngine,
    master: McIndex,
    slave: McIndex,
    fb: *mut MC_CamIn_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = McCamIn {
            execute: c.Execute,
            continuous_update: c.ContinuousUpdate,
            master_offset: c.MasterOffset,
            slave_offset: c.SlaveOffset,
            master_scaling: c.MasterScaling,
            slave_scaling: c.SlaveScaling,
            master_value_source: enum_in(master_source(c.MasterValueSource), &mut bad),
            cam_table_id: c.CamTableID as usize,
            periodic: c.Periodic,
            master_absolute: c.MasterAbsolute,
            slave_absolute: c.SlaveAbsolute,
            buffer_mode: enum_in(BufferMode::from_u8(c.BufferMode), &mut bad),
            ..Default::default()
        };
        run_exec(c, bad, b, |b| b.call(e, master as usize, slave as usize));
        axis_ok(e, master)?;
        axis_ok(e, slave)
    })
}
