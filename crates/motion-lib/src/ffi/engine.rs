//! The engine's C calls: create, destroy and step an engine, add axes, groups and cam tables, read
//! and force axis and group state, and read the reductions the engine made to keep within the axis
//! limits (junctions of blended group paths, stops whose deceleration or jerk was raised).
//!
//! Input: an engine handle (NULL or from `mc_engine_create`) and indices. Output: a status, a state
//! code or a value (NaN or 0 for a bad handle or index). Invariants: the module contract of
//! [`crate::ffi`] (null and tag checks, panics caught, the engine poisoned by a panic).

use super::*;

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
