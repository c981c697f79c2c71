//! The single-axis PLCopen blocks of Part 1 in C: administrative (MC_Power, MC_Reset, MC_Read*,
//! MC_SetPosition, MC_SetOverride) and motion (MC_Home, MC_Stop, MC_Halt, MC_Move*).
//!
//! Input: per block a `#[repr(C)]` struct (inputs written by C, outputs and `_internal` written
//! here) and the axis index. Output: the block's outputs, as [`crate::blocks`] computes them, and a
//! status. Invariants: the module contract of [`crate::ffi`]; each function only maps its own
//! input fields, the frame (pointer checks, edge detection, write-back) is the shared plumbing.

use super::*;

/// C view of `McPower` (MC_Power).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_Power_C {
    /// Enable: TRUE powers the axis (Disabled to Standstill); FALSE disables it: every command is
    /// aborted and the axis goes to Disabled (an axis in ErrorStop stays there until MC_Reset).
    pub Enable: bool,
    /// EnablePositive: PLCopen input kept for the interface; the drive interface has no direction
    /// enable, so it has no effect.
    pub EnablePositive: bool,
    /// EnableNegative: PLCopen input kept for the interface; the drive interface has no direction
    /// enable, so it has no effect.
    pub EnableNegative: bool,
    /// Status: the axis is powered (the drive is enabled; the axis left Disabled).
    pub Status: bool,
    /// Valid: Status is valid (Enable TRUE and no error).
    pub Valid: bool,
    /// Error: the power command failed (e.g. an unknown axis); ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
}

/// Calls MC_Power once (one PLC scan) on axis `axis` of `engine`: reads the inputs from `*fb`, runs
/// the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_Power_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_power(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_Power_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut b = McPower {
            enable: c.Enable,
            enable_positive: c.EnablePositive,
            enable_negative: c.EnableNegative,
            ..Default::default()
        };
        b.call(e, axis as usize);

        c.Status = b.status;
        c.Valid = b.valid;
        c.Error = b.error;
        c.ErrorID = b.error_id.code();
        axis_ok(e, axis)
    })
}

/// C view of `McHome` (MC_Home).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_Home_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// Position: the axis's position after homing, in u (a simulated drive homes on the spot: the
    /// set position becomes Position).
    pub Position: f64,
    /// BufferMode: not used, homing always starts at once (an unknown value is still refused with
    /// ErrorID 26); it needs Standstill (ErrorID 14 NotStandstill while the axis moves).
    pub BufferMode: u8,
    /// Done: homing finished; the axis is back in Standstill at Position.
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

block_c!(MC_Home_C);

/// Calls MC_Home once (one PLC scan) on axis `axis` of `engine`: reads the inputs from `*fb`, runs
/// the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_Home_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_home(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_Home_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = McHome {
            execute: c.Execute,
            position: c.Position,
            buffer_mode: enum_in(BufferMode::from_u8(c.BufferMode), &mut bad),
            ..Default::default()
        };
        run_exec(c, bad, b, |b| b.call(e, axis as usize));
        axis_ok(e, axis)
    })
}

/// C view of `McStop` (MC_Stop).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_Stop_C {
    /// Execute: its rising edge starts braking, aborting every command of the axis (also from
    /// Standstill); while Execute stays TRUE after Done the axis stays Stopping and refuses motion
    /// commands; its falling edge releases it.
    pub Execute: bool,
    /// Deceleration: braking rate in u/s², finite and > 0 (else ErrorID 22); capped by the axis's
    /// deceleration limit and never scaled by the override.
    pub Deceleration: f64,
    /// Jerk of the braking in u/s³ (>= 0; 0 = the axis's jerk limit, a larger value is capped to
    /// it).
    pub Jerk: f64,
    /// Done: the axis reached velocity 0; it stays Stopping (motion commands refused) while Execute
    /// is TRUE.
    pub Done: bool,
    /// Busy: the axis is still braking.
    pub Busy: bool,
    /// CommandAborted: the stop was ended by power-off or an axis error before it finished.
    pub CommandAborted: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_Stop_C {
    done: Done,
    command_aborted: CommandAborted
});

/// Calls MC_Stop once (one PLC scan) on axis `axis` of `engine`: reads the inputs from `*fb`, runs
/// the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_Stop_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_stop(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_Stop_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McStop {
            execute: c.Execute,
            deceleration: c.Deceleration,
            jerk: c.Jerk,
            ..Default::default()
        };
        run_stop(c, b, |b| b.call(e, axis as usize));
        axis_ok(e, axis)
    })
}

/// C view of `McHalt` (MC_Halt).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_Halt_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// Deceleration: braking rate in u/s², finite and > 0 (else ErrorID 22); capped by the axis's
    /// deceleration limit.
    pub Deceleration: f64,
    /// Jerk of the braking in u/s³ (>= 0; 0 = the axis's jerk limit).
    pub Jerk: f64,
    /// BufferMode: Aborting (0) brakes at once; Buffered (1) halts after the running move ended;
    /// unknown: ErrorID 26.
    pub BufferMode: u8,
    /// Done: the axis reached velocity 0 (Standstill); unlike MC_Stop it takes further commands at
    /// any time.
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

block_c!(MC_Halt_C);

/// Calls MC_Halt once (one PLC scan) on axis `axis` of `engine`: reads the inputs from `*fb`, runs
/// the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_Halt_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_halt(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_Halt_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = McHalt {
            execute: c.Execute,
            deceleration: c.Deceleration,
            jerk: c.Jerk,
            buffer_mode: enum_in(BufferMode::from_u8(c.BufferMode), &mut bad),
            ..Default::default()
        };
        run_exec(c, bad, b, |b| b.call(e, axis as usize));
        axis_ok(e, axis)
    })
}

/// C view of `McMoveAbsolute` (MC_MoveAbsolute).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveAbsolute_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// ContinuousUpdate: while TRUE and the block Busy, inputs changed since the last call re-plan
    /// the running command from its current position, velocity and acceleration.
    pub ContinuousUpdate: bool,
    /// Position: target position in user units (u); on a modulo axis taken modulo the period and
    /// reached the way Direction says.
    pub Position: f64,
    /// Velocity: largest speed of the move in u/s; finite and non-zero (its magnitude is used, else
    /// ErrorID 20 InvalidVelocity); above the axis's velocity limit it is capped to it.
    pub Velocity: f64,
    /// Acceleration: u/s², finite and > 0 (else ErrorID 21 InvalidAcceleration); capped by the
    /// axis's acceleration limit.
    pub Acceleration: f64,
    /// Deceleration: u/s², finite and > 0 (else ErrorID 22 InvalidDeceleration); capped by the
    /// axis's deceleration limit.
    pub Deceleration: f64,
    /// Jerk: u/s³, finite and >= 0 (else ErrorID 23 InvalidJerk); 0 means the axis's jerk limit, a
    /// larger value is capped to it.
    pub Jerk: f64,
    /// Direction (modulo axes only): positive (0), shortest way (1), negative (2) or current
    /// direction (3); ignored on a linear axis; another value gives ErrorID 25 InvalidDirection.
    pub Direction: u8,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub BufferMode: u8,
    /// Done: the command finished successfully; stays TRUE while Execute is TRUE (one call if
    /// Execute is already FALSE).
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

block_c!(MC_MoveAbsolute_C);

/// Calls MC_MoveAbsolute once (one PLC scan) on axis `axis` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_MoveAbsolute_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_move_absolute(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_MoveAbsolute_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = move_block!(
            McMoveAbsolute,
            c {
                execute: c.Execute,
                continuous_update: c.ContinuousUpdate,
                position: c.Position,
                direction: enum_in(Direction::from_u8(c.Direction), &mut bad),
                buffer_mode: enum_in(BufferMode::from_u8(c.BufferMode), &mut bad),
            }
        );
        run_exec(c, bad, b, |b| b.call(e, axis as usize));
        axis_ok(e, axis)
    })
}

/// C view of `McMoveRelative` (MC_MoveRelative).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveRelative_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// ContinuousUpdate: part of the PLCopen interface but not acted on by this block: Distance is
    /// latched at the rising edge.
    pub ContinuousUpdate: bool,
    /// Distance in u, added to the set position when the command becomes active (at the rising edge
    /// when Aborting or on an idle axis, else at the end of its predecessor).
    pub Distance: f64,
    /// Velocity: largest speed of the move in u/s; finite and non-zero (its magnitude is used, else
    /// ErrorID 20 InvalidVelocity); above the axis's velocity limit it is capped to it.
    pub Velocity: f64,
    /// Acceleration: u/s², finite and > 0 (else ErrorID 21 InvalidAcceleration); capped by the
    /// axis's acceleration limit.
    pub Acceleration: f64,
    /// Deceleration: u/s², finite and > 0 (else ErrorID 22 InvalidDeceleration); capped by the
    /// axis's deceleration limit.
    pub Deceleration: f64,
    /// Jerk: u/s³, finite and >= 0 (else ErrorID 23 InvalidJerk); 0 means the axis's jerk limit, a
    /// larger value is capped to it.
    pub Jerk: f64,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub BufferMode: u8,
    /// Done: the command finished successfully; stays TRUE while Execute is TRUE (one call if
    /// Execute is already FALSE).
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

block_c!(MC_MoveRelative_C);

/// Calls MC_MoveRelative once (one PLC scan) on axis `axis` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_MoveRelative_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_move_relative(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_MoveRelative_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = move_block!(
            McMoveRelative,
            c {
                execute: c.Execute,
                continuous_update: c.ContinuousUpdate,
                distance: c.Distance,
                buffer_mode: enum_in(BufferMode::from_u8(c.BufferMode), &mut bad),
            }
        );
        run_exec(c, bad, b, |b| b.call(e, axis as usize));
        axis_ok(e, axis)
    })
}

/// C view of `McMoveAdditive` (MC_MoveAdditive).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveAdditive_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Done, Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// ContinuousUpdate: part of the PLCopen interface but not acted on by this block: Distance is
    /// latched at the rising edge.
    pub ContinuousUpdate: bool,
    /// Distance in u, added to the last commanded target (the running or last buffered command's).
    pub Distance: f64,
    /// Velocity: largest speed of the move in u/s; finite and non-zero (its magnitude is used, else
    /// ErrorID 20 InvalidVelocity); above the axis's velocity limit it is capped to it.
    pub Velocity: f64,
    /// Acceleration: u/s², finite and > 0 (else ErrorID 21 InvalidAcceleration); capped by the
    /// axis's acceleration limit.
    pub Acceleration: f64,
    /// Deceleration: u/s², finite and > 0 (else ErrorID 22 InvalidDeceleration); capped by the
    /// axis's deceleration limit.
    pub Deceleration: f64,
    /// Jerk: u/s³, finite and >= 0 (else ErrorID 23 InvalidJerk); 0 means the axis's jerk limit, a
    /// larger value is capped to it.
    pub Jerk: f64,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub BufferMode: u8,
    /// Done: the command finished successfully; stays TRUE while Execute is TRUE (one call if
    /// Execute is already FALSE).
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

block_c!(MC_MoveAdditive_C);

/// Calls MC_MoveAdditive once (one PLC scan) on axis `axis` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_MoveAdditive_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_move_additive(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_MoveAdditive_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = move_block!(
            McMoveAdditive,
            c {
                execute: c.Execute,
                continuous_update: c.ContinuousUpdate,
                distance: c.Distance,
                buffer_mode: enum_in(BufferMode::from_u8(c.BufferMode), &mut bad),
            }
        );
        run_exec(c, bad, b, |b| b.call(e, axis as usize));
        axis_ok(e, axis)
    })
}

/// C view of `McMoveVelocity` (MC_MoveVelocity).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveVelocity_C {
    /// Execute: its rising edge (FALSE to TRUE between two calls) latches the inputs and issues the
    /// command; a rising edge while Busy is ignored. Its falling edge never stops a motion, it only
    /// resets Error, ErrorID and CommandAborted.
    pub Execute: bool,
    /// ContinuousUpdate: while TRUE and the block Busy, inputs changed since the last call re-plan
    /// the running command from its current position, velocity and acceleration.
    pub ContinuousUpdate: bool,
    /// Velocity: target speed in u/s, finite and non-zero (else ErrorID 20); its sign times
    /// Direction gives the direction of travel; capped by the axis's velocity limit.
    pub Velocity: f64,
    /// Acceleration: u/s², finite and > 0 (else ErrorID 21 InvalidAcceleration); capped by the
    /// axis's acceleration limit.
    pub Acceleration: f64,
    /// Deceleration: u/s², finite and > 0 (else ErrorID 22 InvalidDeceleration); capped by the
    /// axis's deceleration limit.
    pub Deceleration: f64,
    /// Jerk: u/s³, finite and >= 0 (else ErrorID 23 InvalidJerk); 0 means the axis's jerk limit, a
    /// larger value is capped to it.
    pub Jerk: f64,
    /// Direction: positive (0), negative (2) or current (3, the sign of the set velocity); shortest
    /// way (1) or another value gives ErrorID 25 InvalidDirection. A negative Velocity reverses it.
    pub Direction: u8,
    /// BufferMode: when the command starts relative to the one running: Aborting (0, at once),
    /// Buffered (1, after the predecessor finished) or BlendingLow/Previous/Next/High (2..5,
    /// without stopping at the junction); another value gives ErrorID 26 InvalidBufferMode.
    pub BufferMode: u8,
    /// InVelocity: the set velocity reached the commanded Velocity (while Active); a Buffered
    /// successor starts after it was shown for one scan.
    pub InVelocity: bool,
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

block_c!(MC_MoveVelocity_C {
    in_target: InVelocity,
    active: Active,
    command_aborted: CommandAborted
});

/// Calls MC_MoveVelocity once (one PLC scan) on axis `axis` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_MoveVelocity_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_move_velocity(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_MoveVelocity_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut bad = None;
        let b = move_block!(
            McMoveVelocity,
            c {
                execute: c.Execute,
                continuous_update: c.ContinuousUpdate,
                direction: enum_in(Direction::from_u8(c.Direction), &mut bad),
                buffer_mode: enum_in(BufferMode::from_u8(c.BufferMode), &mut bad),
            }
        );
        run_exec(c, bad, b, |b| b.call(e, axis as usize));
        axis_ok(e, axis)
    })
}

/// C view of `McReset` (MC_Reset).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_Reset_C {
    /// Execute: its rising edge carries out the command within this call; Done or Error then show
    /// while Execute stays TRUE (for one call if it already fell).
    pub Execute: bool,
    /// Done: the reset was carried out: the axis left ErrorStop (to Standstill if powered), or it
    /// was not in ErrorStop and nothing was done.
    pub Done: bool,
    /// Busy: always FALSE after the call: the reset completes within the call.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_Reset_C { done: Done });

/// Calls MC_Reset once (one PLC scan) on axis `axis` of `engine`: reads the inputs from `*fb`, runs
/// the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_Reset_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_reset(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_Reset_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McReset {
            execute: c.Execute,
            ..Default::default()
        };
        run_immediate(c, b, |b| b.call(e, axis as usize));
        axis_ok(e, axis)
    })
}

/// C view of `McReadActualPosition` (MC_ReadActualPosition).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_ReadActualPosition_C {
    /// Enable: while TRUE the block works and its outputs are refreshed every call; FALSE resets
    /// the outputs.
    pub Enable: bool,
    /// Valid: the value outputs are valid (Enable TRUE and no error).
    pub Valid: bool,
    /// Busy: TRUE while Enable is TRUE and the value is valid.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Position: the actual position reported by the drive, in u (modulo axes: in [0, period)); 0
    /// while not Valid.
    pub Position: f64,
}

/// Calls MC_ReadActualPosition once (one PLC scan) on axis `axis` of `engine`: reads the inputs
/// from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_ReadActualPosition_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_read_actual_position(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_ReadActualPosition_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut b = McReadActualPosition {
            enable: c.Enable,
            ..Default::default()
        };
        b.call(e, axis as usize);

        c.Valid = b.valid;
        c.Busy = b.busy;
        c.Error = b.error;
        c.ErrorID = b.error_id.code();
        c.Position = b.position;
        axis_ok(e, axis)
    })
}

/// C view of `McReadActualVelocity` (MC_ReadActualVelocity).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_ReadActualVelocity_C {
    /// Enable: while TRUE the block works and its outputs are refreshed every call; FALSE resets
    /// the outputs.
    pub Enable: bool,
    /// Valid: the value outputs are valid (Enable TRUE and no error).
    pub Valid: bool,
    /// Busy: TRUE while Enable is TRUE and the value is valid.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Velocity: the actual velocity reported by the drive, in u/s; 0 while not Valid.
    pub Velocity: f64,
}

/// Calls MC_ReadActualVelocity once (one PLC scan) on axis `axis` of `engine`: reads the inputs
/// from `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_ReadActualVelocity_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_read_actual_velocity(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_ReadActualVelocity_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut b = McReadActualVelocity {
            enable: c.Enable,
            ..Default::default()
        };
        b.call(e, axis as usize);

        c.Valid = b.valid;
        c.Busy = b.busy;
        c.Error = b.error;
        c.ErrorID = b.error_id.code();
        c.Velocity = b.velocity;
        axis_ok(e, axis)
    })
}

/// C view of `McReadStatus` (MC_ReadStatus).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_ReadStatus_C {
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
    /// ErrorStop: the axis is in ErrorStop (an axis error; leave it with MC_Reset).
    pub ErrorStop: bool,
    /// Disabled: the axis is not powered.
    pub Disabled: bool,
    /// Stopping: MC_Stop brakes or holds the axis (motion commands are refused).
    pub Stopping: bool,
    /// Homing: MC_Home is running.
    pub Homing: bool,
    /// Standstill: the axis is powered and holds its position with no command.
    pub Standstill: bool,
    /// DiscreteMotion: a positioning move or MC_Halt runs (MoveAbsolute/Relative/Additive, Halt).
    pub DiscreteMotion: bool,
    /// ContinuousMotion: MC_MoveVelocity runs (or the slave runs on after MC_GearOut/MC_CamOut).
    pub ContinuousMotion: bool,
    /// SynchronizedMotion: the axis is a geared or cammed slave, or moves as part of an axes group.
    pub SynchronizedMotion: bool,
}

/// Calls MC_ReadStatus once (one PLC scan) on axis `axis` of `engine`: reads the inputs from `*fb`,
/// runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_ReadStatus_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_read_status(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_ReadStatus_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut b = McReadStatus {
            enable: c.Enable,
            ..Default::default()
        };
        b.call(e, axis as usize);

        c.Valid = b.valid;
        c.Busy = b.busy;
        c.Error = b.error;
        c.ErrorID = b.error_id.code();
        c.ErrorStop = b.error_stop;
        c.Disabled = b.disabled;
        c.Stopping = b.stopping;
        c.Homing = b.homing;
        c.Standstill = b.standstill;
        c.DiscreteMotion = b.discrete_motion;
        c.ContinuousMotion = b.continuous_motion;
        c.SynchronizedMotion = b.synchronized_motion;
        axis_ok(e, axis)
    })
}

/// C view of `McReadAxisError` (MC_ReadAxisError).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_ReadAxisError_C {
    /// Enable: while TRUE the block works and its outputs are refreshed every call; FALSE resets
    /// the outputs.
    pub Enable: bool,
    /// Valid: the value outputs are valid (Enable TRUE and no error).
    pub Valid: bool,
    /// Busy: TRUE while Enable is TRUE and AxisErrorID is valid.
    pub Busy: bool,
    /// Error: the read itself failed (e.g. an unknown axis); ErrorID says why (the axis error is
    /// AxisErrorID).
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// AxisErrorID: the axis error that put the axis into ErrorStop (100 and above, e.g. 102
    /// FollowingError); 0 (None) when there is none.
    pub AxisErrorID: u16,
}

/// Calls MC_ReadAxisError once (one PLC scan) on axis `axis` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_ReadAxisError_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_read_axis_error(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_ReadAxisError_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut b = McReadAxisError {
            enable: c.Enable,
            ..Default::default()
        };
        b.call(e, axis as usize);

        c.Valid = b.valid;
        c.Busy = b.busy;
        c.Error = b.error;
        c.ErrorID = b.error_id.code();
        c.AxisErrorID = b.axis_error_id.code();
        axis_ok(e, axis)
    })
}

/// C view of `McSetPosition` (MC_SetPosition).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_SetPosition_C {
    /// Execute: its rising edge carries out the command within this call; Done or Error then show
    /// while Execute stays TRUE (for one call if it already fell).
    pub Execute: bool,
    /// Position: the new set position in u (Relative FALSE) or the shift added to it (Relative
    /// TRUE); finite, else ErrorID 24 InvalidPosition. Refused while Homing or in ErrorStop.
    pub Position: f64,
    /// Relative: FALSE = Position becomes the axis's set position; TRUE = Position is added to it
    /// (a shift of the coordinate origin, no motion).
    pub Relative: bool,
    /// Done: the coordinate shift was applied (immediately, within the call).
    pub Done: bool,
    /// Busy: always FALSE after the call: the shift completes within the call.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

block_c!(MC_SetPosition_C { done: Done });

/// Calls MC_SetPosition once (one PLC scan) on axis `axis` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_SetPosition_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_set_position(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_SetPosition_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let b = McSetPosition {
            execute: c.Execute,
            position: c.Position,
            relative: c.Relative,
            ..Default::default()
        };
        run_immediate(c, b, |b| b.call(e, axis as usize));
        axis_ok(e, axis)
    })
}

/// C view of `McSetOverride` (MC_SetOverride).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_SetOverride_C {
    /// Enable: while TRUE the factors are written every call; when it falls the outputs reset and
    /// the last factors stay in force.
    pub Enable: bool,
    /// VelFactor: scale of the velocity limit of the running and later moves, >= 0 (0 brakes the
    /// move to standstill until it rises again); the axis's velocity limit still caps it.
    pub VelFactor: f64,
    /// AccFactor: scale of the acceleration and deceleration limits, in (0, 1]; 0 stands for 1; out
    /// of range gives ErrorID 30 InvalidOverride.
    pub AccFactor: f64,
    /// JerkFactor: scale of the jerk limit, in (0, 1]; 0 stands for 1; out of range gives ErrorID
    /// 30 InvalidOverride.
    pub JerkFactor: f64,
    /// Enabled: the factors were accepted and are written every call while Enable is TRUE.
    pub Enabled: bool,
    /// Busy: TRUE while Enable is TRUE and the factors are accepted.
    pub Busy: bool,
    /// Error: the command was refused or failed; ErrorID says why.
    pub Error: bool,
    /// ErrorID: why Error is TRUE (1..99 block errors, 100 and above axis errors; the README's
    /// ErrorID table, `MC_ERR_*`); 0 (MC_ERR_NONE) while there is no error.
    pub ErrorID: u16,
}

/// Calls MC_SetOverride once (one PLC scan) on axis `axis` of `engine`: reads the inputs from
/// `*fb`, runs the block and writes its outputs and `_internal` back to `*fb`.
///
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` or `MC_STATUS_BAD_HANDLE` for a NULL or dead `engine`
/// and `MC_STATUS_NULL_ARGUMENT` for a NULL `fb` (then nothing is read or written);
/// `MC_STATUS_BAD_INDEX` when `axis` is not an axis of the engine (the outputs are still written:
/// the block reports the bad index through Error/ErrorID when it acts); `MC_STATUS_PANIC` after a
/// panic (the engine is poisoned). PLCopen errors of the block itself are in `fb->ErrorID`, not in
/// the status. Call it from the one thread that drives `engine` (normally the PLC scan task), once
/// per scan and before `mc_engine_step`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`; `fb` is NULL or points to a valid,
/// writable `MC_SetOverride_C` that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_set_override(
    engine: *mut McEngine,
    axis: McIndex,
    fb: *mut MC_SetOverride_C,
) -> McStatus {
    guard(engine, || {
        let (e, c) = unsafe { args(engine, fb) }?;
        let mut b = McSetOverride {
            enable: c.Enable,
            vel_factor: c.VelFactor,
            acc_factor: c.AccFactor,
            jerk_factor: c.JerkFactor,
            ..Default::default()
        };
        b.call(e, axis as usize);

        c.Enabled = b.enabled;
        c.Busy = b.busy;
        c.Error = b.error;
        c.ErrorID = b.error_id.code();
        axis_ok(e, axis)
    })
}
