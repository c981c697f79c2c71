//! The C ABI of the motion library: the ONLY `unsafe` code of the project.
//!
//! Input: calls from C (generated C of compiled IL programs, or hand-written C): an
//! engine handle, axis/group indices ([`McIndex`]) and per block a `#[repr(C)]` struct holding the
//! PLCopen inputs (written by C), outputs (written here) and `_internal` state (edge
//! detection and the command handle; C zero-initialises it and never touches it).
//! Output: the same block semantics as [`crate::blocks`] and [`crate::group_blocks`]
//! (each call converts the C struct to the Rust block, calls it, writes the outputs back), and a
//! [`McStatus`] from every call: `MC_OK`, or a negative `MC_STATUS_*` code.
//! Invariants: every pointer is checked for null before use, and the engine handle for its tag
//! (`MC_STATUS_NULL_HANDLE`, `MC_STATUS_BAD_HANDLE`, `MC_STATUS_NULL_ARGUMENT`); a bad axis or group index gives
//! `MC_STATUS_BAD_INDEX` (and the block's Error/ErrorID); a bad enumeration value (BufferMode, Direction, ...)
//! sets Error with its ErrorID instead of being trusted; every entry catches panics: a panic never
//! unwinds into C nor aborts the controller, it returns `MC_STATUS_PANIC` and poisons the engine. The
//! header include/motion_lib.h is generated from this file by cbindgen (test `ffi_header`).
//!
//! Versions: `MC_ABI_VERSION` in the header and `mc_abi_version()` in the library must agree;
//! `mc_sizeof("MC_MoveAbsolute_C")` gives each struct's size as the library sees it, to compare with
//! the C compiler's `sizeof`.
//!
//! Threads: an engine is not thread-safe. All calls on one engine (block calls and `mc_engine_step`)
//! are made by one thread at a time: normally the PLC scan task, which each cycle first calls the
//! blocks (they queue commands and read outputs) and then `mc_engine_step` (which advances the set
//! values; a command given in scan k takes effect in step k, its outputs show in scan k + 1). An
//! engine may move to another thread between calls; different engines are independent and may run
//! on different threads at once. Drives (Rust `Drive` implementations) are `Send`.
//!
//! Lifetime: `mc_engine_create` returns an owned engine; free it with
//! `mc_engine_destroy`. Block structs are owned by C (static or stack memory).
#![deny(unsafe_op_in_unsafe_fn)]
#![allow(
    non_snake_case,
    non_camel_case_types,
    clippy::field_reassign_with_default
)]
// Safety contract of every function taking pointers: `engine` is NULL or a live handle from
// `mc_engine_create`; `fb`/`config`/`index` are NULL or point to a valid, writable struct of the
// declared type; arrays hold the stated number of elements. NULL pointers give an error status.

use crate::axis::{AxisConfig, AxisKind};
use crate::blocks::*;
use crate::buffer::{BufferMode, Direction, TransitionMode};
use crate::cmd::CmdId;
use crate::engine::{Engine, EngineConfig, MasterSource};
use crate::error::ErrorId;
use crate::group_blocks::*;
use crate::path::CircMode;
use crate::profile::Limits;
use crate::sync::CamTable;

/// Version of this C ABI (`MC_ABI_VERSION` in the header). It changes whenever a function signature, a
/// struct layout or a status code changes; compare it with [`mc_abi_version`] at start-up.
pub const MC_ABI_VERSION: u32 = 2;

/// Index of an axis, an axes group or a cam table: the one index type of the ABI.
pub type McIndex = u32;

/// Status returned by every call: `MC_OK` (0) or a negative `MC_STATUS_*` code (the PLCopen ErrorIDs,
/// `MC_ERR_*`, stay in the blocks' `ErrorID` outputs).
pub type McStatus = i32;
/// The call did its work.
pub const MC_OK: McStatus = 0;
/// The engine handle is NULL.
pub const MC_STATUS_NULL_HANDLE: McStatus = -1;
/// The engine handle does not point to a live engine (wrong pointer, or already destroyed).
pub const MC_STATUS_BAD_HANDLE: McStatus = -2;
/// A block, configuration, output or array pointer is NULL.
pub const MC_STATUS_NULL_ARGUMENT: McStatus = -3;
/// An axis, group or cam-table index does not exist (the block's Error/ErrorID are also set).
pub const MC_STATUS_BAD_INDEX: McStatus = -4;
/// A configuration is invalid (limits, cycle time, cam table).
pub const MC_STATUS_BAD_CONFIG: McStatus = -5;
/// The library panicked (a bug). The engine is poisoned: every later call on it returns this code, and
/// the controller must bring the machine to its own safe stop (drive-level STO/SS1).
pub const MC_STATUS_PANIC: McStatus = -6;

/// Tag of a live engine; cleared when it is destroyed.
const MAGIC: u64 = 0x4d43_454e_4749_4e45; // "MCENGINE"

/// Opaque engine handle (C sees `McEngine *` only): the axes, groups, cam tables and command
/// buffers of one motion controller. Made by `mc_engine_create`, freed by `mc_engine_destroy`; a
/// tag marks it live, and a panic inside a call poisons it.
pub struct McEngine {
    magic: u64,
    poisoned: bool,
    engine: Engine,
}

/// Axis configuration (C view of [`AxisConfig`]). `ModuloPeriod` 0 = linear axis.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_AxisConfig_C {
    /// VelocityLimit: largest |velocity| of the axis, u/s (> 0).
    pub VelocityLimit: f64,
    /// AccelerationLimit: largest acceleration (speeding up), u/s² (> 0).
    pub AccelerationLimit: f64,
    /// DecelerationLimit: largest deceleration (slowing down), u/s² (> 0).
    pub DecelerationLimit: f64,
    /// 0 = no jerk limit.
    pub JerkLimit: f64,
    /// SwLimitPositive: upper software position limit, u (checked when SwLimitsEnabled).
    pub SwLimitPositive: f64,
    /// SwLimitNegative: lower software position limit, u (checked when SwLimitsEnabled; below
    /// SwLimitPositive).
    pub SwLimitNegative: f64,
    /// SwLimitsEnabled: check the software limits (linear axes): targets beyond them are refused
    /// (ErrorID 27, 29), velocity moves stop at them (ErrorID 100, 101).
    pub SwLimitsEnabled: bool,
    /// ModuloPeriod: > 0 makes a modulo (rotary) axis whose positions are reported in [0, period),
    /// u; 0 = linear axis.
    pub ModuloPeriod: f64,
    /// 0 = not checked.
    pub FollowingErrorLimit: f64,
}

/// The ABI version the library was built with ([`MC_ABI_VERSION`]). Call it once at start-up and
/// refuse to run when it differs from the header's `MC_ABI_VERSION`. No handle, any thread.
#[no_mangle]
pub extern "C" fn mc_abi_version() -> u32 {
    MC_ABI_VERSION
}

/// `sizeof` of the named ABI struct as the library sees it (e.g. `"MC_MoveAbsolute_C"`), 0 for an unknown
/// name or NULL. Compare with the C compiler's `sizeof` to detect a header that does not match the library.
/// No handle, any thread; never panics into C (a panic returns 0).
/// # Safety
/// `name` is NULL or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn mc_sizeof(name: *const std::ffi::c_char) -> usize {
    if name.is_null() {
        return 0;
    }
    // SAFETY: a non-null name is a NUL-terminated string (caller contract).
    let name = unsafe { std::ffi::CStr::from_ptr(name) };
    std::panic::catch_unwind(|| struct_size(name.to_bytes())).unwrap_or(0)
}

/// Runs one ABI call: a panic becomes [`MC_STATUS_PANIC`] and poisons the engine; `Err(code)` is returned as
/// the code.
fn guard(engine: *mut McEngine, f: impl FnOnce() -> Result<(), McStatus>) -> McStatus {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)) {
        Ok(Ok(())) => MC_OK,
        Ok(Err(code)) => code,
        Err(_) => {
            // SAFETY: a non-null handle that passed the checks of `eng` points to a live McEngine (caller
            // contract); the panicked call's borrows ended with the unwinding.
            if !engine.is_null() && unsafe { std::ptr::addr_of!((*engine).magic).read() } == MAGIC {
                // SAFETY: as above, a live engine; nothing else borrows it now.
                unsafe { (*engine).poisoned = true };
            }
            MC_STATUS_PANIC
        }
    }
}

/// The engine behind a handle, or the status that says why not.
/// # Safety
/// `engine` is NULL or a pointer to a live McEngine (the magic check catches some misuse, not all).
unsafe fn eng<'a>(engine: *mut McEngine) -> Result<&'a mut Engine, McStatus> {
    if engine.is_null() {
        return Err(MC_STATUS_NULL_HANDLE);
    }
    // SAFETY: a non-null handle points to readable memory of a McEngine's size (caller contract); only
    // the tag is read before the handle is trusted.
    if unsafe { std::ptr::addr_of!((*engine).magic).read() } != MAGIC {
        return Err(MC_STATUS_BAD_HANDLE);
    }
    // SAFETY: the tag says this is a live engine (caller contract: not aliased during the call).
    let h = unsafe { &mut *engine };
    if h.poisoned {
        return Err(MC_STATUS_PANIC);
    }
    Ok(&mut h.engine)
}

fn axis_ok(e: &Engine, axis: McIndex) -> Result<(), McStatus> {
    e.axis_state(axis as usize)
        .map(|_| ())
        .map_err(|_| MC_STATUS_BAD_INDEX)
}

fn group_ok(e: &Engine, group: McIndex) -> Result<(), McStatus> {
    e.group_state(group as usize)
        .map(|_| ())
        .map_err(|_| MC_STATUS_BAD_INDEX)
}

/// Creates an engine with cycle time `cycle_seconds` (e.g. 0.001; finite and > 0) and
/// per-axis/group
/// buffer depth `queue_depth` (commands buffered besides the active one; a full buffer refuses a
/// command with ErrorID 40). Returns the owned handle, or NULL on a bad configuration (or a panic).
/// Free it with `mc_engine_destroy`. The handle may be used from one thread at a time.
#[no_mangle]
pub extern "C" fn mc_engine_create(cycle_seconds: f64, queue_depth: u32) -> *mut McEngine {
    let made = std::panic::catch_unwind(|| {
        Engine::new(EngineConfig {
            cycle: cycle_seconds,
            queue_depth: queue_depth as usize,
        })
    });
    match made {
        Ok(Ok(engine)) => Box::into_raw(Box::new(McEngine {
            magic: MAGIC,
            poisoned: false,
            engine,
        })),
        _ => std::ptr::null_mut(),
    }
}

/// Destroys an engine created by `mc_engine_create` and frees its memory (also a poisoned one).
/// Returns `MC_OK`; NULL gives `MC_STATUS_NULL_HANDLE` and a pointer without a live engine's tag
/// `MC_STATUS_BAD_HANDLE` (both do nothing). No call on `engine` may run at the same time or
/// follow.
/// # Safety
/// `engine` is NULL or a live handle, destroyed once.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_destroy(engine: *mut McEngine) -> McStatus {
    if engine.is_null() {
        return MC_STATUS_NULL_HANDLE;
    }
    // SAFETY: a non-null handle points to readable memory of a McEngine's size (caller contract).
    if unsafe { std::ptr::addr_of!((*engine).magic).read() } != MAGIC {
        return MC_STATUS_BAD_HANDLE;
    }
    // SAFETY: the tag says this is a live engine; clear it so a later call on the freed block fails the
    // check while the memory is not reused.
    unsafe { std::ptr::addr_of_mut!((*engine).magic).write(0) };
    // SAFETY: the pointer came from Box::into_raw in mc_engine_create and is destroyed once (caller
    // contract; the cleared magic makes a second destroy of a not yet reused block fail the check).
    let boxed = unsafe { Box::from_raw(engine) };
    let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(move || drop(boxed)));
    MC_OK
}

/// Advances the engine by one cycle: every axis and group moves its set point on by the cycle time,
/// drives are written and read, command statuses advance. Call it once per cycle after the block
/// calls of the scan (a command given in scan k takes effect in this step; its outputs show in scan
/// k + 1). Returns `MC_OK`, `MC_STATUS_NULL_HANDLE`, `MC_STATUS_BAD_HANDLE` or `MC_STATUS_PANIC`.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`, used by no other thread during the
/// call.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_step(engine: *mut McEngine) -> McStatus {
    guard(engine, || {
        unsafe { eng(engine) }?.step();
        Ok(())
    })
}

/// Test hook for the panic path: panics inside the call's guard, so it returns `MC_STATUS_PANIC` and the
/// engine is poisoned (every later call on it returns `MC_STATUS_PANIC`; `mc_engine_destroy` still frees it).
/// Never call it on a controller that drives a machine. A NULL or dead handle gives
/// `MC_STATUS_NULL_HANDLE` / `MC_STATUS_BAD_HANDLE` instead.
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`, used by no other thread during the
/// call.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_selftest_panic(engine: *mut McEngine) -> McStatus {
    guard(engine, || {
        let _ = unsafe { eng(engine) }?;
        panic!("mc_engine_selftest_panic: a deliberate panic of the motion library's test hook");
    })
}

/// Cycles stepped so far by `mc_engine_step` (0 for a NULL, invalid or poisoned handle).
/// # Safety
/// `engine` is NULL or a live handle from `mc_engine_create`, used by no other thread during the
/// call.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_cycles(engine: *mut McEngine) -> u64 {
    unsafe { eng(engine) }.map_or(0, |e| e.cycles())
}

/// Adds an axis with a simulated drive (actual values = set point), configured by `*config`, and
/// writes its index (0, 1, ... in the order of creation) to the out-parameter `*index`. The axis
/// starts Disabled. Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` / `MC_STATUS_BAD_HANDLE` for `engine`,
/// `MC_STATUS_NULL_ARGUMENT` for a NULL `config` or `index`, `MC_STATUS_BAD_CONFIG` for limits that
/// are not finite and positive (jerk >= 0), software limits not ordered, a bad modulo period or
/// following-error limit (then `*index` is not written), `MC_STATUS_PANIC`.
/// # Safety
/// `engine` is NULL or a live handle; `config` is NULL or points to a readable `MC_AxisConfig_C`;
/// `index` is NULL or points to a writable `McIndex`; no other thread uses `engine` meanwhile.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_add_axis(
    engine: *mut McEngine,
    config: *const MC_AxisConfig_C,
    index: *mut McIndex,
) -> McStatus {
    guard(engine, || {
        let e = unsafe { eng(engine) }?;
        // SAFETY: a non-null config points to a readable MC_AxisConfig_C (caller contract).
        let c = unsafe { config.as_ref() }.ok_or(MC_STATUS_NULL_ARGUMENT)?;
        // SAFETY: a non-null index points to a writable McIndex (caller contract).
        let out = unsafe { index.as_mut() }.ok_or(MC_STATUS_NULL_ARGUMENT)?;
        let cfg = AxisConfig {
            limits: Limits {
                vmax: c.VelocityLimit,
                amax: c.AccelerationLimit,
                dmax: c.DecelerationLimit,
                jmax: c.JerkLimit,
            },
            sw_limit_pos: c.SwLimitPositive,
            sw_limit_neg: c.SwLimitNegative,
            sw_limits_enabled: c.SwLimitsEnabled,
            kind: if c.ModuloPeriod != 0.0 {
                AxisKind::Modulo {
                    period: c.ModuloPeriod,
                }
            } else {
                AxisKind::Linear
            },
            following_error_limit: c.FollowingErrorLimit,
        };
        let i = e.add_axis(cfg).map_err(|_| MC_STATUS_BAD_CONFIG)?;
        *out = McIndex::try_from(i).map_err(|_| MC_STATUS_BAD_CONFIG)?;
        Ok(())
    })
}

/// Adds an empty axes group (GroupDisabled) and writes its index to the out-parameter `*index`.
/// Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` / `MC_STATUS_BAD_HANDLE` for `engine`,
/// `MC_STATUS_NULL_ARGUMENT` for a NULL `index`, `MC_STATUS_PANIC`.
/// # Safety
/// `engine` is NULL or a live handle; `index` is NULL or points to a writable `McIndex`; no other
/// thread uses `engine` meanwhile.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_add_group(
    engine: *mut McEngine,
    index: *mut McIndex,
) -> McStatus {
    guard(engine, || {
        let e = unsafe { eng(engine) }?;
        // SAFETY: a non-null index points to a writable McIndex (caller contract).
        let out = unsafe { index.as_mut() }.ok_or(MC_STATUS_NULL_ARGUMENT)?;
        *out = McIndex::try_from(e.add_group()).map_err(|_| MC_STATUS_BAD_CONFIG)?;
        Ok(())
    })
}

/// Registers a cam table of `n` points (`master[i]`, `slave[i]`, in u; master strictly increasing,
/// at least 2 points, all finite; slave values between points by cubic Hermite interpolation) and
/// writes its CamTable reference for MC_CamTableSelect to the out-parameter `*table`. The arrays
/// are
/// copied. Returns `MC_OK`; `MC_STATUS_NULL_HANDLE` / `MC_STATUS_BAD_HANDLE` for `engine`,
/// `MC_STATUS_NULL_ARGUMENT` for a NULL array or `table`, `MC_STATUS_BAD_CONFIG` for a table that
/// breaks those rules (`*table` not written), `MC_STATUS_PANIC`.
/// # Safety
/// `engine` is NULL or a live handle; `master` and `slave` are NULL or hold `n` readable doubles
/// each; `table` is NULL or points to a writable `McIndex`; no other thread uses `engine`
/// meanwhile.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_add_cam_table(
    engine: *mut McEngine,
    master: *const f64,
    slave: *const f64,
    n: u32,
    table: *mut McIndex,
) -> McStatus {
    guard(engine, || {
        let e = unsafe { eng(engine) }?;
        if master.is_null() || slave.is_null() {
            return Err(MC_STATUS_NULL_ARGUMENT);
        }
        // SAFETY: a non-null table points to a writable McIndex (caller contract).
        let out = unsafe { table.as_mut() }.ok_or(MC_STATUS_NULL_ARGUMENT)?;
        // SAFETY: both arrays hold n readable doubles (caller contract).
        let (m, s) = unsafe {
            (
                std::slice::from_raw_parts(master, n as usize),
                std::slice::from_raw_parts(slave, n as usize),
            )
        };
        let pts: Vec<(f64, f64)> = m.iter().copied().zip(s.iter().copied()).collect();
        let t = CamTable::new(&pts).map_err(|_| MC_STATUS_BAD_CONFIG)?;
        *out = McIndex::try_from(e.add_cam_table(t)).map_err(|_| MC_STATUS_BAD_CONFIG)?;
        Ok(())
    })
}

/// PLCopen state of axis `axis` (0 Disabled, 1 Standstill, 2 Homing, 3 DiscreteMotion,
/// 4 ContinuousMotion, 5 SynchronizedMotion, 6 Stopping, 7 ErrorStop), or a negative status:
/// `MC_STATUS_NULL_HANDLE`, `MC_STATUS_BAD_HANDLE`, `MC_STATUS_PANIC` (poisoned engine),
/// `MC_STATUS_BAD_INDEX`.
/// # Safety
/// `engine` is NULL or a live handle, used by no other thread during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_state(engine: *mut McEngine, axis: McIndex) -> i32 {
    match unsafe { eng(engine) } {
        Ok(e) => e
            .axis_state(axis as usize)
            .map_or(MC_STATUS_BAD_INDEX, |s| s as i32),
        Err(code) => code,
    }
}

/// One set value of an axis, NaN for a NULL, invalid or poisoned handle or a bad index.
unsafe fn set_value(
    engine: *mut McEngine,
    axis: McIndex,
    get: impl Fn(&Engine, usize) -> Result<f64, ErrorId>,
) -> f64 {
    match unsafe { eng(engine) } {
        Ok(e) => get(e, axis as usize).unwrap_or(f64::NAN),
        Err(_) => f64::NAN,
    }
}

/// Set position of axis `axis` after the last `mc_engine_step`, in user units (modulo axes: in
/// [0, period)); NaN for a NULL, dead or poisoned handle or a bad index.
/// # Safety
/// `engine` is NULL or a live handle, used by no other thread during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_set_position(engine: *mut McEngine, axis: McIndex) -> f64 {
    unsafe { set_value(engine, axis, Engine::set_position_of) }
}

/// Set velocity of axis `axis` after the last `mc_engine_step`, in u/s (override included); NaN for
/// a NULL, dead or poisoned handle or a bad index.
/// # Safety
/// `engine` is NULL or a live handle, used by no other thread during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_set_velocity(engine: *mut McEngine, axis: McIndex) -> f64 {
    unsafe { set_value(engine, axis, Engine::set_velocity_of) }
}

/// Set acceleration of axis `axis` after the last `mc_engine_step`, in u/s²; NaN for a NULL, dead
/// or
/// poisoned handle or a bad index.
/// # Safety
/// `engine` is NULL or a live handle, used by no other thread during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_set_acceleration(engine: *mut McEngine, axis: McIndex) -> f64 {
    unsafe { set_value(engine, axis, Engine::set_acceleration_of) }
}

/// State of axes group `group` (0 GroupDisabled, 1 GroupStandby, 2 GroupMoving, 3 GroupHoming,
/// 4 GroupStopping, 5 GroupErrorStop), or a negative status: `MC_STATUS_NULL_HANDLE`,
/// `MC_STATUS_BAD_HANDLE`, `MC_STATUS_PANIC` (poisoned engine), `MC_STATUS_BAD_INDEX`.
/// # Safety
/// `engine` is NULL or a live handle, used by no other thread during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_state(engine: *mut McEngine, group: McIndex) -> i32 {
    match unsafe { eng(engine) } {
        Ok(e) => e
            .group_state(group as usize)
            .map_or(MC_STATUS_BAD_INDEX, |s| s as i32),
        Err(code) => code,
    }
}

/// Junction speed the BufferMode asked for at a lowered junction the group's path passed in
/// the last cycle (the limits did not allow it); 0 in every other cycle, for a bad index and for a
/// NULL, invalid or poisoned handle. In path units per second (u/s).
/// # Safety
/// `engine` is NULL or a live handle, used by no other thread during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_junction_requested(engine: *mut McEngine, group: McIndex) -> f64 {
    unsafe { eng(engine) }
        .ok()
        .and_then(|e| e.group_junction_now(group as usize).ok())
        .map_or(0.0, |j| j.0)
}

/// Junction speed planned and reached at that lowered junction (see
/// `mc_group_junction_requested`), u/s; 0 otherwise.
/// # Safety
/// `engine` is NULL or a live handle, used by no other thread during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_junction_reached(engine: *mut McEngine, group: McIndex) -> f64 {
    unsafe { eng(engine) }
        .ok()
        .and_then(|e| e.group_junction_now(group as usize).ok())
        .map_or(0.0, |j| j.1)
}

/// How many junction speeds of the group were lowered so far (0 for a bad index and for a NULL,
/// invalid or poisoned handle).
/// # Safety
/// `engine` is NULL or a live handle, used by no other thread during the call.
#[no_mangle]
pub unsafe extern "C" fn mc_group_reduction_count(engine: *mut McEngine, group: McIndex) -> u32 {
    unsafe { eng(engine) }
        .ok()
        .and_then(|e| e.group_reductions(group as usize).ok())
        .map_or(0, |r| r.1 as u32)
}

/// One figure of the capped MC_Stop that started on the axis in the last cycle; 0 in every
/// other cycle, for a bad index and for a NULL, invalid or poisoned handle.
unsafe fn stop_now(
    engine: *mut McEngine,
    axis: McIndex,
    pick: fn(&crate::engine::StopReduction) -> f64,
) -> f64 {
    unsafe { eng(engine) }
        .ok()
        .and_then(|e| e.stop_reduction_now(axis as usize).ok().flatten())
        .map_or(0.0, |r| pick(&r))
}

/// Deceleration an MC_Stop asked for when the axis limit capped it (in the stop's first
/// cycle; 0 otherwise, see `stop_now`).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_stop_decel_requested(engine: *mut McEngine, axis: McIndex) -> f64 {
    unsafe { stop_now(engine, axis, |r| r.deceleration_requested) }
}

/// Deceleration that capped MC_Stop runs with (see `mc_axis_stop_decel_requested`).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_stop_decel_reached(engine: *mut McEngine, axis: McIndex) -> f64 {
    unsafe { stop_now(engine, axis, |r| r.deceleration_reached) }
}

/// Jerk that capped MC_Stop asked for (0: the axis's; see `mc_axis_stop_decel_requested`).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_stop_jerk_requested(engine: *mut McEngine, axis: McIndex) -> f64 {
    unsafe { stop_now(engine, axis, |r| r.jerk_requested) }
}

/// Jerk that capped MC_Stop runs with (see `mc_axis_stop_decel_requested`).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_stop_jerk_reached(engine: *mut McEngine, axis: McIndex) -> f64 {
    unsafe { stop_now(engine, axis, |r| r.jerk_reached) }
}

/// How many MC_Stop commands of the axis were capped to its limits so far (0 for a bad index).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_stop_reduction_count(engine: *mut McEngine, axis: McIndex) -> u32 {
    unsafe { eng(engine) }
        .ok()
        .and_then(|e| e.stop_reductions(axis as usize).ok())
        .map_or(0, |r| r.1 as u32)
}

fn master_source(x: u8) -> Result<MasterSource, ErrorId> {
    match x {
        0 => Ok(MasterSource::SetValue),
        1 => Ok(MasterSource::ActualValue),
        _ => Err(ErrorId::InvalidMode),
    }
}

fn circ_mode(x: u8) -> Result<CircMode, ErrorId> {
    CircMode::from_u8(x).ok_or(ErrorId::InvalidCircle)
}

fn path_choice(x: u8) -> Result<bool, ErrorId> {
    match x {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(ErrorId::InvalidDirection),
    }
}

fn pack(prev_execute: bool, cmd: Option<CmdId>) -> [u64; 2] {
    match cmd {
        Some(c) => [
            u64::from(prev_execute) | 2,
            (u64::from(c.index) << 32) | u64::from(c.gen),
        ],
        None => [u64::from(prev_execute), 0],
    }
}

fn unpack(raw: [u64; 2]) -> (bool, Option<CmdId>) {
    let cmd = (raw[0] & 2 != 0).then_some(CmdId {
        index: (raw[1] >> 32) as u32,
        gen: raw[1] as u32,
    });
    (raw[0] & 1 != 0, cmd)
}

fn err(code: u16) -> ErrorId {
    ErrorId::from_code(code)
}

// ------------------------------------------------------------ shared block plumbing
//
// Every block function below has the same frame: check the two pointers, build the Rust
// block from the C inputs (an out-of-range enumeration is kept in `bad` and refuses the
// rising edge with its ErrorID), rebuild the block's core from the C outputs and
// `_internal`, call the Rust block, write the outputs and `_internal` back. The frame is
// shared here; each extern function keeps only its own input fields.

/// The engine and the block struct behind the two pointers, or the status that says why not.
/// # Safety
/// The module contract: `engine` is NULL or a live handle, `fb` NULL or a valid,
/// writable struct of its type, not aliased during the call.
unsafe fn args<'a, T>(
    engine: *mut McEngine,
    fb: *mut T,
) -> Result<(&'a mut Engine, &'a mut T), McStatus> {
    // SAFETY: a non-null handle points to a McEngine (caller contract); `eng` checks it.
    let e = unsafe { eng(engine) }?;
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let c = unsafe { fb.as_mut() }.ok_or(MC_STATUS_NULL_ARGUMENT)?;
    Ok((e, c))
}

/// An enumerated C input: its value, or the default with the first bad value's ErrorID
/// kept in `bad`.
fn enum_in<T: Default>(r: Result<T, ErrorId>, bad: &mut Option<ErrorId>) -> T {
    r.unwrap_or_else(|id| {
        bad.get_or_insert(id);
        T::default()
    })
}

/// Rust blocks reachable through their output core (`core` field of type `K`).
trait HasCore<K> {
    fn core(&mut self) -> &mut K;
}

macro_rules! has_core {
    ($k:ty: $($t:ty),*) => {
        $(impl HasCore<$k> for $t {
            fn core(&mut self) -> &mut $k {
                &mut self.core
            }
        })*
    };
}

has_core!(ExecCore: McHome, McHalt, McMoveAbsolute, McMoveRelative, McMoveAdditive,
    McMoveVelocity, McGearIn, McSyncOut, McCamIn, McGroupHome, McGroupHalt,
    McMoveLinearAbsolute, McMoveLinearRelative, McMoveDirectAbsolute,
    McMoveCircularAbsolute, McMoveCircularRelative);
has_core!(ImmediateCore: McReset, McSetPosition, McCamTableSelect, McAddAxisToGroup,
    McRemoveAxisFromGroup, McUngroupAllAxes, McGroupEnable, McGroupDisable, McGroupReset);
has_core!(StopCore: McStop, McGroupStop);

/// The status outputs and private state of a C block (outputs it lacks are None).
struct StatusC<'a> {
    execute: bool,
    done: Option<&'a mut bool>,
    /// InVelocity / InGear / InSync.
    in_target: Option<&'a mut bool>,
    active: Option<&'a mut bool>,
    command_aborted: Option<&'a mut bool>,
    end_of_profile: Option<&'a mut bool>,
    busy: &'a mut bool,
    error: &'a mut bool,
    error_id: &'a mut u16,
    internal: &'a mut [u64; 2],
}

/// C block structs, seen through their status outputs.
trait BlockC {
    fn status(&mut self) -> StatusC<'_>;
}

/// `BlockC` for a C struct with Execute, Busy, Error, ErrorID and `_internal`, plus the
/// named optional outputs (`done: Done`, `in_target: InVelocity`, ...); without a list:
/// Done, Active and CommandAborted (the positioning blocks).
macro_rules! block_c {
    ($t:ty) => {
        block_c!($t { done: Done, active: Active, command_aborted: CommandAborted });
    };
    ($t:ty { $($f:ident : $cf:ident),* }) => {
        impl BlockC for $t {
            fn status(&mut self) -> StatusC<'_> {
                #[allow(unused_mut)]
                let mut s = StatusC {
                    execute: self.Execute,
                    done: None,
                    in_target: None,
                    active: None,
                    command_aborted: None,
                    end_of_profile: None,
                    busy: &mut self.Busy,
                    error: &mut self.Error,
                    error_id: &mut self.ErrorID,
                    internal: &mut self._internal,
                };
                $(s.$f = Some(&mut self.$cf);)*
                s
            }
        }
    };
}

fn flag(f: &Option<&mut bool>) -> bool {
    f.as_ref().is_some_and(|x| **x)
}

fn put(f: Option<&mut bool>, v: bool) {
    if let Some(f) = f {
        *f = v;
    }
}

/// One call of an Execute-type block ([`ExecCore`]) from C; returns the block.
fn run_exec<B: HasCore<ExecCore>>(
    c: &mut impl BlockC,
    bad: Option<ErrorId>,
    mut b: B,
    call: impl FnOnce(&mut B),
) -> B {
    let s = c.status();
    let (prev_execute, cmd) = unpack(*s.internal);
    let core = ExecCore {
        prev_execute,
        cmd,
        done: flag(&s.done),
        busy: *s.busy,
        active: flag(&s.active),
        command_aborted: flag(&s.command_aborted),
        error: *s.error,
        error_id: err(*s.error_id),
        in_target: flag(&s.in_target),
        end_of_profile: flag(&s.end_of_profile),
    };
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if s.execute && !prev_execute && !core.busy {
            for f in [
                s.done,
                s.in_target,
                s.active,
                s.command_aborted,
                s.end_of_profile,
            ] {
                put(f, false);
            }
            *s.busy = false;
            *s.error = true;
            *s.error_id = id.code();
            *s.internal = pack(true, cmd);
            return b;
        }
    }
    *b.core() = core;
    call(&mut b);
    let k = *b.core();
    put(s.done, k.done);
    put(s.in_target, k.in_target && k.active);
    put(s.active, k.active);
    put(s.command_aborted, k.command_aborted);
    put(s.end_of_profile, k.end_of_profile && k.active);
    *s.busy = k.busy;
    *s.error = k.error;
    *s.error_id = k.error_id.code();
    *s.internal = pack(k.prev_execute, k.cmd);
    b
}

/// One call of an immediate block ([`ImmediateCore`]) from C; returns the block.
fn run_immediate<B: HasCore<ImmediateCore>>(
    c: &mut impl BlockC,
    mut b: B,
    call: impl FnOnce(&mut B),
) -> B {
    let s = c.status();
    *b.core() = ImmediateCore {
        prev_execute: s.internal[0] & 1 != 0,
        done: flag(&s.done),
        busy: *s.busy,
        error: *s.error,
        error_id: err(*s.error_id),
    };
    call(&mut b);
    let k = *b.core();
    put(s.done, k.done);
    *s.busy = k.busy;
    *s.error = k.error;
    *s.error_id = k.error_id.code();
    *s.internal = [u64::from(k.prev_execute), 0];
    b
}

/// One call of MC_Stop / MC_GroupStop ([`StopCore`]) from C.
fn run_stop<B: HasCore<StopCore>>(c: &mut impl BlockC, mut b: B, call: impl FnOnce(&mut B)) {
    let s = c.status();
    let (prev_execute, cmd) = unpack(*s.internal);
    *b.core() = StopCore {
        prev_execute,
        cmd,
        done: flag(&s.done),
        busy: *s.busy,
        command_aborted: flag(&s.command_aborted),
        error: *s.error,
        error_id: err(*s.error_id),
    };
    call(&mut b);
    let k = *b.core();
    put(s.done, k.done);
    put(s.command_aborted, k.command_aborted);
    *s.busy = k.busy;
    *s.error = k.error;
    *s.error_id = k.error_id.code();
    *s.internal = pack(k.prev_execute, k.cmd);
}

/// A single-axis move block from its C struct: Velocity, Acceleration, Deceleration,
/// Jerk and the block's own fields.
macro_rules! move_block {
    ($t:ident, $c:ident { $($f:ident : $v:expr),* $(,)? }) => {
        $t {
            $($f: $v,)*
            velocity: $c.Velocity,
            acceleration: $c.Acceleration,
            deceleration: $c.Deceleration,
            jerk: $c.Jerk,
            ..Default::default()
        }
    };
}

/// MC_MoveCircularAbsolute / Relative from its C struct.
macro_rules! circular_block {
    ($t:ident, $c:ident, $bad:ident) => {
        path_block!(
            $t,
            $c,
            $bad {
                execute: $c.Execute,
                circ_mode: enum_in(circ_mode($c.CircMode), &mut $bad),
                aux_point: $c.AuxPoint,
                end_point: $c.EndPoint,
                path_choice_ccw: enum_in(path_choice($c.PathChoice), &mut $bad),
            }
        )
    };
}

/// A Part 4 path block from its C struct: the block's own fields, then the path
/// dynamics, CoordSystem, BufferMode, TransitionMode and TransitionParameter.
macro_rules! path_block {
    ($t:ident, $c:ident, $bad:ident { $($f:ident : $v:expr),* $(,)? }) => {
        $t {
            $($f: $v,)*
            velocity: $c.Velocity,
            acceleration: $c.Acceleration,
            deceleration: $c.Deceleration,
            jerk: $c.Jerk,
            coord_system: $c.CoordSystem,
            buffer_mode: enum_in(BufferMode::from_u8($c.BufferMode), &mut $bad),
            transition_mode: enum_in(TransitionMode::from_u8($c.TransitionMode), &mut $bad),
            transition_parameter: $c.TransitionParameter,
            ..Default::default()
        }
    };
}

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

// ---- constants (emitted as #define by cbindgen) ----

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

/// `sizeof` of the ABI structs by name (see [`mc_sizeof`]); every `#[repr(C)]` struct of this module is
/// listed (test `ffi_c::struct_sizes_match_the_header` checks the list against the header).
fn struct_size(name: &[u8]) -> usize {
    macro_rules! sizes {
        ($($t:ident),* $(,)?) => {
            match name {
                $(n if n == stringify!($t).as_bytes() => std::mem::size_of::<$t>(),)*
                _ => 0,
            }
        };
    }
    sizes!(
        MC_AxisConfig_C,
        MC_Power_C,
        MC_Home_C,
        MC_Stop_C,
        MC_Halt_C,
        MC_MoveAbsolute_C,
        MC_MoveRelative_C,
        MC_MoveAdditive_C,
        MC_MoveVelocity_C,
        MC_Reset_C,
        MC_ReadActualPosition_C,
        MC_ReadActualVelocity_C,
        MC_ReadStatus_C,
        MC_ReadAxisError_C,
        MC_SetPosition_C,
        MC_SetOverride_C,
        MC_GearIn_C,
        MC_GearOut_C,
        MC_CamOut_C,
        MC_CamTableSelect_C,
        MC_CamIn_C,
        MC_AddAxisToGroup_C,
        MC_RemoveAxisFromGroup_C,
        MC_UngroupAllAxes_C,
        MC_GroupEnable_C,
        MC_GroupDisable_C,
        MC_GroupReset_C,
        MC_GroupStop_C,
        MC_GroupHome_C,
        MC_GroupHalt_C,
        MC_MoveLinearAbsolute_C,
        MC_MoveLinearRelative_C,
        MC_MoveDirectAbsolute_C,
        MC_MoveCircularAbsolute_C,
        MC_MoveCircularRelative_C,
        MC_GroupReadActualPosition_C,
        MC_GroupReadActualVelocity_C,
        MC_GroupReadStatus_C
    )
}
