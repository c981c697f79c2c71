//! The C ABI of the motion library: the ONLY `unsafe` code of the project.
//!
//! Input: calls from C (generated C of compiled IL programs, or hand-written C): an
//! engine handle, axis/group indices and per block a `#[repr(C)]` struct holding the
//! PLCopen inputs (written by C), outputs (written here) and `_internal` state (edge
//! detection and the command handle; C zero-initialises it and never touches it).
//! Output: the same block semantics as [`crate::blocks`] and [`crate::group_blocks`]
//! (each call converts the C struct to the Rust block, calls it, writes the outputs back).
//! Invariants: every pointer is checked for null before use; a bad enumeration value
//! (BufferMode, Direction, ...) sets Error with its ErrorID instead of being trusted;
//! no call panics across the boundary. The header include/motion_lib.h is generated from
//! this file by cbindgen (test `ffi_header`).
//!
//! Lifetime: `mc_engine_create` returns an owned engine; free it with
//! `mc_engine_destroy`. Block structs are owned by C (static or stack memory).
#![allow(
    non_snake_case,
    non_camel_case_types,
    clippy::field_reassign_with_default
)]
// Safety contract of every function taking pointers: `engine` is NULL or a live handle from
// `mc_engine_create`; `fb`/`config` are NULL or point to a valid, writable struct of the
// declared type; arrays hold the stated number of elements. NULL pointers are ignored.

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

/// Opaque engine handle.
pub struct McEngine {
    engine: Engine,
}

/// Axis configuration (C view of [`AxisConfig`]). `ModuloPeriod` 0 = linear axis.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_AxisConfig_C {
    pub VelocityLimit: f64,
    pub AccelerationLimit: f64,
    pub DecelerationLimit: f64,
    /// 0 = no jerk limit.
    pub JerkLimit: f64,
    pub SwLimitPositive: f64,
    pub SwLimitNegative: f64,
    pub SwLimitsEnabled: bool,
    pub ModuloPeriod: f64,
    /// 0 = not checked.
    pub FollowingErrorLimit: f64,
}

/// Creates an engine with cycle time `cycle_seconds` (e.g. 0.001) and per-axis/group
/// buffer depth `queue_depth`. Returns NULL on a bad configuration.
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_create(cycle_seconds: f64, queue_depth: u32) -> *mut McEngine {
    match Engine::new(EngineConfig {
        cycle: cycle_seconds,
        queue_depth: queue_depth as usize,
    }) {
        Ok(engine) => Box::into_raw(Box::new(McEngine { engine })),
        Err(_) => std::ptr::null_mut(),
    }
}

/// Destroys an engine created by `mc_engine_create` (NULL is ignored).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_destroy(engine: *mut McEngine) {
    if !engine.is_null() {
        // SAFETY: the pointer came from Box::into_raw in mc_engine_create and is
        // destroyed once (caller contract).
        drop(unsafe { Box::from_raw(engine) });
    }
}

unsafe fn eng<'a>(engine: *mut McEngine) -> Option<&'a mut Engine> {
    // SAFETY: a non-null handle points to a live McEngine (caller contract).
    unsafe { engine.as_mut() }.map(|e| &mut e.engine)
}

/// Advances the engine by one cycle.
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_step(engine: *mut McEngine) {
    if let Some(e) = unsafe { eng(engine) } {
        e.step();
    }
}

/// Cycles stepped so far (0 for NULL).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_cycles(engine: *mut McEngine) -> u64 {
    unsafe { eng(engine) }.map_or(0, |e| e.cycles())
}

/// Adds an axis with a simulated drive. Returns its index, or -1 on a bad configuration.
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_add_axis(
    engine: *mut McEngine,
    config: *const MC_AxisConfig_C,
) -> i32 {
    let Some(e) = (unsafe { eng(engine) }) else {
        return -1;
    };
    // SAFETY: a non-null config points to a readable MC_AxisConfig_C (caller contract).
    let Some(c) = (unsafe { config.as_ref() }) else {
        return -1;
    };
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
    e.add_axis(cfg).map_or(-1, |i| i as i32)
}

/// Adds an empty axes group. Returns its index (-1 for NULL).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_add_group(engine: *mut McEngine) -> i32 {
    unsafe { eng(engine) }.map_or(-1, |e| e.add_group() as i32)
}

/// Registers a cam table of `n` points (master strictly increasing). Returns its
/// CamTable reference for MC_CamTableSelect, or -1.
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_engine_add_cam_table(
    engine: *mut McEngine,
    master: *const f64,
    slave: *const f64,
    n: u32,
) -> i32 {
    let Some(e) = (unsafe { eng(engine) }) else {
        return -1;
    };
    if master.is_null() || slave.is_null() {
        return -1;
    }
    // SAFETY: both arrays hold n readable doubles (caller contract).
    let (m, s) = unsafe {
        (
            std::slice::from_raw_parts(master, n as usize),
            std::slice::from_raw_parts(slave, n as usize),
        )
    };
    let pts: Vec<(f64, f64)> = m.iter().copied().zip(s.iter().copied()).collect();
    match CamTable::new(&pts) {
        Ok(t) => e.add_cam_table(t) as i32,
        Err(_) => -1,
    }
}

/// PLCopen state of an axis (0 Disabled .. 7 ErrorStop), -1 for a bad index.
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_state(engine: *mut McEngine, axis: u32) -> i32 {
    unsafe { eng(engine) }
        .and_then(|e| e.axis_state(axis as usize).ok())
        .map_or(-1, |s| s as i32)
}

/// Set position of an axis (user units; 0 for a bad index).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_set_position(engine: *mut McEngine, axis: u32) -> f64 {
    unsafe { eng(engine) }
        .and_then(|e| e.set_position_of(axis as usize).ok())
        .unwrap_or(0.0)
}

/// Set velocity of an axis (user units per second, override included; 0 for a bad index).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_set_velocity(engine: *mut McEngine, axis: u32) -> f64 {
    unsafe { eng(engine) }
        .and_then(|e| e.set_velocity_of(axis as usize).ok())
        .unwrap_or(0.0)
}

/// Set acceleration of an axis (user units per second squared; 0 for a bad index).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_axis_set_acceleration(engine: *mut McEngine, axis: u32) -> f64 {
    unsafe { eng(engine) }
        .and_then(|e| e.set_acceleration_of(axis as usize).ok())
        .unwrap_or(0.0)
}

/// State of a group (0 GroupDisabled .. 5 GroupErrorStop), -1 for a bad index.
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_group_state(engine: *mut McEngine, group: u32) -> i32 {
    unsafe { eng(engine) }
        .and_then(|e| e.group_state(group as usize).ok())
        .map_or(-1, |s| s as i32)
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

/// C view of `McPower` (MC_Power).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_Power_C {
    pub Enable: bool,
    pub EnablePositive: bool,
    pub EnableNegative: bool,
    pub Status: bool,
    pub Valid: bool,
    pub Error: bool,
    pub ErrorID: u16,
}

/// Calls MC_Power once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_power(engine: *mut McEngine, axis: u32, fb: *mut MC_Power_C) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McPower::default();
    b.enable = c.Enable;
    b.enable_positive = c.EnablePositive;
    b.enable_negative = c.EnableNegative;
    b.status = c.Status;
    b.valid = c.Valid;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.call(e, axis as usize);
    c.Status = b.status;
    c.Valid = b.valid;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
}

/// C view of `McHome` (MC_Home).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_Home_C {
    pub Execute: bool,
    pub Position: f64,
    pub BufferMode: u8,
    pub Done: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_Home once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_home(engine: *mut McEngine, axis: u32, fb: *mut MC_Home_C) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McHome::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.position = c.Position;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.done = c.Done;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Done = false;
            c.Active = false;
            c.CommandAborted = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, axis as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McStop` (MC_Stop).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_Stop_C {
    pub Execute: bool,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub Done: bool,
    pub Busy: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_Stop once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_stop(engine: *mut McEngine, axis: u32, fb: *mut MC_Stop_C) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McStop::default();
    b.execute = c.Execute;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.done = c.Done;
    b.busy = c.Busy;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.prev_execute = prev;
    b.cmd = cmd;
    b.call(e, axis as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.prev_execute, b.cmd);
}

/// C view of `McHalt` (MC_Halt).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_Halt_C {
    pub Execute: bool,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub BufferMode: u8,
    pub Done: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_Halt once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_halt(engine: *mut McEngine, axis: u32, fb: *mut MC_Halt_C) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McHalt::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.done = c.Done;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Done = false;
            c.Active = false;
            c.CommandAborted = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, axis as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McMoveAbsolute` (MC_MoveAbsolute).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveAbsolute_C {
    pub Execute: bool,
    pub ContinuousUpdate: bool,
    pub Position: f64,
    pub Velocity: f64,
    pub Acceleration: f64,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub Direction: u8,
    pub BufferMode: u8,
    pub Done: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_MoveAbsolute once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_move_absolute(
    engine: *mut McEngine,
    axis: u32,
    fb: *mut MC_MoveAbsolute_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McMoveAbsolute::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.continuous_update = c.ContinuousUpdate;
    b.position = c.Position;
    b.velocity = c.Velocity;
    b.acceleration = c.Acceleration;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.direction = Direction::from_u8(c.Direction).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.done = c.Done;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Done = false;
            c.Active = false;
            c.CommandAborted = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, axis as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McMoveRelative` (MC_MoveRelative).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveRelative_C {
    pub Execute: bool,
    pub ContinuousUpdate: bool,
    pub Distance: f64,
    pub Velocity: f64,
    pub Acceleration: f64,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub BufferMode: u8,
    pub Done: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_MoveRelative once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_move_relative(
    engine: *mut McEngine,
    axis: u32,
    fb: *mut MC_MoveRelative_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McMoveRelative::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.continuous_update = c.ContinuousUpdate;
    b.distance = c.Distance;
    b.velocity = c.Velocity;
    b.acceleration = c.Acceleration;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.done = c.Done;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Done = false;
            c.Active = false;
            c.CommandAborted = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, axis as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McMoveAdditive` (MC_MoveAdditive).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveAdditive_C {
    pub Execute: bool,
    pub ContinuousUpdate: bool,
    pub Distance: f64,
    pub Velocity: f64,
    pub Acceleration: f64,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub BufferMode: u8,
    pub Done: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_MoveAdditive once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_move_additive(
    engine: *mut McEngine,
    axis: u32,
    fb: *mut MC_MoveAdditive_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McMoveAdditive::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.continuous_update = c.ContinuousUpdate;
    b.distance = c.Distance;
    b.velocity = c.Velocity;
    b.acceleration = c.Acceleration;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.done = c.Done;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Done = false;
            c.Active = false;
            c.CommandAborted = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, axis as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McMoveVelocity` (MC_MoveVelocity).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveVelocity_C {
    pub Execute: bool,
    pub ContinuousUpdate: bool,
    pub Velocity: f64,
    pub Acceleration: f64,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub Direction: u8,
    pub BufferMode: u8,
    pub InVelocity: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_MoveVelocity once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_move_velocity(
    engine: *mut McEngine,
    axis: u32,
    fb: *mut MC_MoveVelocity_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McMoveVelocity::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.continuous_update = c.ContinuousUpdate;
    b.velocity = c.Velocity;
    b.acceleration = c.Acceleration;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.direction = Direction::from_u8(c.Direction).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.in_velocity = c.InVelocity;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.core.in_target = c.InVelocity;
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Active = false;
            c.CommandAborted = false;
            c.InVelocity = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, axis as usize);
    c.InVelocity = b.in_velocity;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McReset` (MC_Reset).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_Reset_C {
    pub Execute: bool,
    pub Done: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_Reset once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_reset(engine: *mut McEngine, axis: u32, fb: *mut MC_Reset_C) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McReset::default();
    b.execute = c.Execute;
    b.done = c.Done;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.core.prev_execute = c._internal[0] & 1 != 0;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.call(e, axis as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = [u64::from(b.core.prev_execute), 0];
}

/// C view of `McReadActualPosition` (MC_ReadActualPosition).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_ReadActualPosition_C {
    pub Enable: bool,
    pub Valid: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    pub Position: f64,
}

/// Calls MC_ReadActualPosition once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_read_actual_position(
    engine: *mut McEngine,
    axis: u32,
    fb: *mut MC_ReadActualPosition_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McReadActualPosition::default();
    b.enable = c.Enable;
    b.valid = c.Valid;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.position = c.Position;
    b.call(e, axis as usize);
    c.Valid = b.valid;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c.Position = b.position;
}

/// C view of `McReadActualVelocity` (MC_ReadActualVelocity).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_ReadActualVelocity_C {
    pub Enable: bool,
    pub Valid: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    pub Velocity: f64,
}

/// Calls MC_ReadActualVelocity once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_read_actual_velocity(
    engine: *mut McEngine,
    axis: u32,
    fb: *mut MC_ReadActualVelocity_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McReadActualVelocity::default();
    b.enable = c.Enable;
    b.valid = c.Valid;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.velocity = c.Velocity;
    b.call(e, axis as usize);
    c.Valid = b.valid;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c.Velocity = b.velocity;
}

/// C view of `McReadStatus` (MC_ReadStatus).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_ReadStatus_C {
    pub Enable: bool,
    pub Valid: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    pub ErrorStop: bool,
    pub Disabled: bool,
    pub Stopping: bool,
    pub Homing: bool,
    pub Standstill: bool,
    pub DiscreteMotion: bool,
    pub ContinuousMotion: bool,
    pub SynchronizedMotion: bool,
}

/// Calls MC_ReadStatus once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_read_status(
    engine: *mut McEngine,
    axis: u32,
    fb: *mut MC_ReadStatus_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McReadStatus::default();
    b.enable = c.Enable;
    b.valid = c.Valid;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.error_stop = c.ErrorStop;
    b.disabled = c.Disabled;
    b.stopping = c.Stopping;
    b.homing = c.Homing;
    b.standstill = c.Standstill;
    b.discrete_motion = c.DiscreteMotion;
    b.continuous_motion = c.ContinuousMotion;
    b.synchronized_motion = c.SynchronizedMotion;
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
}

/// C view of `McReadAxisError` (MC_ReadAxisError).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_ReadAxisError_C {
    pub Enable: bool,
    pub Valid: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    pub AxisErrorID: u16,
}

/// Calls MC_ReadAxisError once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_read_axis_error(
    engine: *mut McEngine,
    axis: u32,
    fb: *mut MC_ReadAxisError_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McReadAxisError::default();
    b.enable = c.Enable;
    b.valid = c.Valid;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.axis_error_id = err(c.AxisErrorID);
    b.call(e, axis as usize);
    c.Valid = b.valid;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c.AxisErrorID = b.axis_error_id.code();
}

/// C view of `McSetPosition` (MC_SetPosition).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_SetPosition_C {
    pub Execute: bool,
    pub Position: f64,
    pub Relative: bool,
    pub Done: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_SetPosition once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_set_position(
    engine: *mut McEngine,
    axis: u32,
    fb: *mut MC_SetPosition_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McSetPosition::default();
    b.execute = c.Execute;
    b.position = c.Position;
    b.relative = c.Relative;
    b.done = c.Done;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.core.prev_execute = c._internal[0] & 1 != 0;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.call(e, axis as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = [u64::from(b.core.prev_execute), 0];
}

/// C view of `McSetOverride` (MC_SetOverride).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_SetOverride_C {
    pub Enable: bool,
    pub VelFactor: f64,
    pub AccFactor: f64,
    pub JerkFactor: f64,
    pub Enabled: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
}

/// Calls MC_SetOverride once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_set_override(
    engine: *mut McEngine,
    axis: u32,
    fb: *mut MC_SetOverride_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McSetOverride::default();
    b.enable = c.Enable;
    b.vel_factor = c.VelFactor;
    b.acc_factor = c.AccFactor;
    b.jerk_factor = c.JerkFactor;
    b.enabled = c.Enabled;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.call(e, axis as usize);
    c.Enabled = b.enabled;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
}

/// C view of `McGearIn` (MC_GearIn).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GearIn_C {
    pub Execute: bool,
    pub ContinuousUpdate: bool,
    pub RatioNumerator: f64,
    pub RatioDenominator: f64,
    pub MasterValueSource: u8,
    pub Acceleration: f64,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub BufferMode: u8,
    pub InGear: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_GearIn once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_gear_in(
    engine: *mut McEngine,
    master: u32,
    slave: u32,
    fb: *mut MC_GearIn_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McGearIn::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.continuous_update = c.ContinuousUpdate;
    b.ratio_numerator = c.RatioNumerator;
    b.ratio_denominator = c.RatioDenominator;
    b.master_value_source = master_source(c.MasterValueSource).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.acceleration = c.Acceleration;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.in_gear = c.InGear;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.core.in_target = c.InGear;
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Active = false;
            c.CommandAborted = false;
            c.InGear = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, master as usize, slave as usize);
    c.InGear = b.in_gear;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McSyncOut` (MC_GearOut).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GearOut_C {
    pub Execute: bool,
    pub Done: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_GearOut once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_gear_out(engine: *mut McEngine, slave: u32, fb: *mut MC_GearOut_C) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McSyncOut::default();
    b.execute = c.Execute;
    b.done = c.Done;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.call_gear_out(e, slave as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McSyncOut` (MC_CamOut).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_CamOut_C {
    pub Execute: bool,
    pub Done: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_CamOut once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_cam_out(engine: *mut McEngine, slave: u32, fb: *mut MC_CamOut_C) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McSyncOut::default();
    b.execute = c.Execute;
    b.done = c.Done;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.call_cam_out(e, slave as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McCamTableSelect` (MC_CamTableSelect).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_CamTableSelect_C {
    pub Execute: bool,
    pub CamTable: u32,
    pub Periodic: bool,
    pub MasterAbsolute: bool,
    pub SlaveAbsolute: bool,
    pub Done: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    pub CamTableID: u32,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_CamTableSelect once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_cam_table_select(
    engine: *mut McEngine,
    master: u32,
    slave: u32,
    fb: *mut MC_CamTableSelect_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McCamTableSelect::default();
    b.execute = c.Execute;
    b.cam_table = c.CamTable as usize;
    b.periodic = c.Periodic;
    b.master_absolute = c.MasterAbsolute;
    b.slave_absolute = c.SlaveAbsolute;
    b.done = c.Done;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.cam_table_id = c.CamTableID as usize;
    b.core.prev_execute = c._internal[0] & 1 != 0;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.call(e, master as usize, slave as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c.CamTableID = b.cam_table_id as u32;
    c._internal = [u64::from(b.core.prev_execute), 0];
}

/// C view of `McCamIn` (MC_CamIn).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_CamIn_C {
    pub Execute: bool,
    pub ContinuousUpdate: bool,
    pub MasterOffset: f64,
    pub SlaveOffset: f64,
    pub MasterScaling: f64,
    pub SlaveScaling: f64,
    pub MasterValueSource: u8,
    pub CamTableID: u32,
    pub Periodic: bool,
    pub MasterAbsolute: bool,
    pub SlaveAbsolute: bool,
    pub BufferMode: u8,
    pub InSync: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    pub EndOfProfile: bool,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_CamIn once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_cam_in(
    engine: *mut McEngine,
    master: u32,
    slave: u32,
    fb: *mut MC_CamIn_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McCamIn::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.continuous_update = c.ContinuousUpdate;
    b.master_offset = c.MasterOffset;
    b.slave_offset = c.SlaveOffset;
    b.master_scaling = c.MasterScaling;
    b.slave_scaling = c.SlaveScaling;
    b.master_value_source = master_source(c.MasterValueSource).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.cam_table_id = c.CamTableID as usize;
    b.periodic = c.Periodic;
    b.master_absolute = c.MasterAbsolute;
    b.slave_absolute = c.SlaveAbsolute;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.in_sync = c.InSync;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.end_of_profile = c.EndOfProfile;
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.core.in_target = c.InSync;
    b.core.end_of_profile = c.EndOfProfile;
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Active = false;
            c.CommandAborted = false;
            c.InSync = false;
            c.EndOfProfile = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, master as usize, slave as usize);
    c.InSync = b.in_sync;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c.EndOfProfile = b.end_of_profile;
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McAddAxisToGroup` (MC_AddAxisToGroup).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_AddAxisToGroup_C {
    pub Execute: bool,
    pub Axis: u32,
    pub IdentInGroup: u32,
    pub Done: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_AddAxisToGroup once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_add_axis_to_group(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_AddAxisToGroup_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McAddAxisToGroup::default();
    b.execute = c.Execute;
    b.axis = c.Axis as usize;
    b.ident_in_group = c.IdentInGroup as usize;
    b.done = c.Done;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.core.prev_execute = c._internal[0] & 1 != 0;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = [u64::from(b.core.prev_execute), 0];
}

/// C view of `McRemoveAxisFromGroup` (MC_RemoveAxisFromGroup).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_RemoveAxisFromGroup_C {
    pub Execute: bool,
    pub IdentInGroup: u32,
    pub Done: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_RemoveAxisFromGroup once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_remove_axis_from_group(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_RemoveAxisFromGroup_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McRemoveAxisFromGroup::default();
    b.execute = c.Execute;
    b.ident_in_group = c.IdentInGroup as usize;
    b.done = c.Done;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.core.prev_execute = c._internal[0] & 1 != 0;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = [u64::from(b.core.prev_execute), 0];
}

/// C view of `McUngroupAllAxes` (MC_UngroupAllAxes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_UngroupAllAxes_C {
    pub Execute: bool,
    pub Done: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_UngroupAllAxes once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_ungroup_all_axes(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_UngroupAllAxes_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McUngroupAllAxes::default();
    b.execute = c.Execute;
    b.done = c.Done;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.core.prev_execute = c._internal[0] & 1 != 0;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = [u64::from(b.core.prev_execute), 0];
}

/// C view of `McGroupEnable` (MC_GroupEnable).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupEnable_C {
    pub Execute: bool,
    pub Done: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_GroupEnable once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_group_enable(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_GroupEnable_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McGroupEnable::default();
    b.execute = c.Execute;
    b.done = c.Done;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.core.prev_execute = c._internal[0] & 1 != 0;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = [u64::from(b.core.prev_execute), 0];
}

/// C view of `McGroupDisable` (MC_GroupDisable).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupDisable_C {
    pub Execute: bool,
    pub Done: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_GroupDisable once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_group_disable(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_GroupDisable_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McGroupDisable::default();
    b.execute = c.Execute;
    b.done = c.Done;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.core.prev_execute = c._internal[0] & 1 != 0;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = [u64::from(b.core.prev_execute), 0];
}

/// C view of `McGroupReset` (MC_GroupReset).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupReset_C {
    pub Execute: bool,
    pub Done: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_GroupReset once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_group_reset(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_GroupReset_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McGroupReset::default();
    b.execute = c.Execute;
    b.done = c.Done;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.core.prev_execute = c._internal[0] & 1 != 0;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = [u64::from(b.core.prev_execute), 0];
}

/// C view of `McGroupStop` (MC_GroupStop).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupStop_C {
    pub Execute: bool,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub Done: bool,
    pub Busy: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_GroupStop once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_group_stop(engine: *mut McEngine, group: u32, fb: *mut MC_GroupStop_C) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McGroupStop::default();
    b.execute = c.Execute;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.done = c.Done;
    b.busy = c.Busy;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.prev_execute = prev;
    b.cmd = cmd;
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.prev_execute, b.cmd);
}

/// C view of `McGroupHome` (MC_GroupHome).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupHome_C {
    pub Execute: bool,
    pub Position: [f64; 16],
    pub BufferMode: u8,
    pub Done: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_GroupHome once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_group_home(engine: *mut McEngine, group: u32, fb: *mut MC_GroupHome_C) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McGroupHome::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.position = c.Position;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.done = c.Done;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Done = false;
            c.Active = false;
            c.CommandAborted = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McGroupHalt` (MC_GroupHalt).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupHalt_C {
    pub Execute: bool,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub BufferMode: u8,
    pub Done: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_GroupHalt once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_group_halt(engine: *mut McEngine, group: u32, fb: *mut MC_GroupHalt_C) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McGroupHalt::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.done = c.Done;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Done = false;
            c.Active = false;
            c.CommandAborted = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McMoveLinearAbsolute` (MC_MoveLinearAbsolute).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveLinearAbsolute_C {
    pub Execute: bool,
    pub Position: [f64; 16],
    pub Velocity: f64,
    pub Acceleration: f64,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub CoordSystem: u8,
    pub BufferMode: u8,
    pub TransitionMode: u8,
    pub TransitionParameter: f64,
    pub Done: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_MoveLinearAbsolute once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_move_linear_absolute(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_MoveLinearAbsolute_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McMoveLinearAbsolute::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.position = c.Position;
    b.velocity = c.Velocity;
    b.acceleration = c.Acceleration;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.coord_system = c.CoordSystem;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.transition_mode = TransitionMode::from_u8(c.TransitionMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.transition_parameter = c.TransitionParameter;
    b.done = c.Done;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Done = false;
            c.Active = false;
            c.CommandAborted = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McMoveLinearRelative` (MC_MoveLinearRelative).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveLinearRelative_C {
    pub Execute: bool,
    pub Distance: [f64; 16],
    pub Velocity: f64,
    pub Acceleration: f64,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub CoordSystem: u8,
    pub BufferMode: u8,
    pub TransitionMode: u8,
    pub TransitionParameter: f64,
    pub Done: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_MoveLinearRelative once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_move_linear_relative(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_MoveLinearRelative_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McMoveLinearRelative::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.distance = c.Distance;
    b.velocity = c.Velocity;
    b.acceleration = c.Acceleration;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.coord_system = c.CoordSystem;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.transition_mode = TransitionMode::from_u8(c.TransitionMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.transition_parameter = c.TransitionParameter;
    b.done = c.Done;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Done = false;
            c.Active = false;
            c.CommandAborted = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McMoveDirectAbsolute` (MC_MoveDirectAbsolute).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveDirectAbsolute_C {
    pub Execute: bool,
    pub Position: [f64; 16],
    pub Velocity: f64,
    pub Acceleration: f64,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub CoordSystem: u8,
    pub BufferMode: u8,
    pub TransitionMode: u8,
    pub TransitionParameter: f64,
    pub Done: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_MoveDirectAbsolute once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_move_direct_absolute(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_MoveDirectAbsolute_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McMoveDirectAbsolute::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.position = c.Position;
    b.velocity = c.Velocity;
    b.acceleration = c.Acceleration;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.coord_system = c.CoordSystem;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.transition_mode = TransitionMode::from_u8(c.TransitionMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.transition_parameter = c.TransitionParameter;
    b.done = c.Done;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Done = false;
            c.Active = false;
            c.CommandAborted = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McMoveCircularAbsolute` (MC_MoveCircularAbsolute).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveCircularAbsolute_C {
    pub Execute: bool,
    pub CircMode: u8,
    pub AuxPoint: [f64; 16],
    pub EndPoint: [f64; 16],
    pub PathChoice: u8,
    pub Velocity: f64,
    pub Acceleration: f64,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub CoordSystem: u8,
    pub BufferMode: u8,
    pub TransitionMode: u8,
    pub TransitionParameter: f64,
    pub Done: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_MoveCircularAbsolute once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_move_circular_absolute(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_MoveCircularAbsolute_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McMoveCircularAbsolute::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.circ_mode = circ_mode(c.CircMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.aux_point = c.AuxPoint;
    b.end_point = c.EndPoint;
    b.path_choice_ccw = path_choice(c.PathChoice).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.velocity = c.Velocity;
    b.acceleration = c.Acceleration;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.coord_system = c.CoordSystem;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.transition_mode = TransitionMode::from_u8(c.TransitionMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.transition_parameter = c.TransitionParameter;
    b.done = c.Done;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Done = false;
            c.Active = false;
            c.CommandAborted = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McMoveCircularRelative` (MC_MoveCircularRelative).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_MoveCircularRelative_C {
    pub Execute: bool,
    pub CircMode: u8,
    pub AuxPoint: [f64; 16],
    pub EndPoint: [f64; 16],
    pub PathChoice: u8,
    pub Velocity: f64,
    pub Acceleration: f64,
    pub Deceleration: f64,
    pub Jerk: f64,
    pub CoordSystem: u8,
    pub BufferMode: u8,
    pub TransitionMode: u8,
    pub TransitionParameter: f64,
    pub Done: bool,
    pub Busy: bool,
    pub Active: bool,
    pub CommandAborted: bool,
    pub Error: bool,
    pub ErrorID: u16,
    /// Private state: zero-initialise, never write.
    pub _internal: [u64; 2],
}

/// Calls MC_MoveCircularRelative once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_move_circular_relative(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_MoveCircularRelative_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McMoveCircularRelative::default();
    let mut bad: Option<ErrorId> = None;
    b.execute = c.Execute;
    b.circ_mode = circ_mode(c.CircMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.aux_point = c.AuxPoint;
    b.end_point = c.EndPoint;
    b.path_choice_ccw = path_choice(c.PathChoice).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.velocity = c.Velocity;
    b.acceleration = c.Acceleration;
    b.deceleration = c.Deceleration;
    b.jerk = c.Jerk;
    b.coord_system = c.CoordSystem;
    b.buffer_mode = BufferMode::from_u8(c.BufferMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.transition_mode = TransitionMode::from_u8(c.TransitionMode).unwrap_or_else(|id| {
        bad.get_or_insert(id);
        Default::default()
    });
    b.transition_parameter = c.TransitionParameter;
    b.done = c.Done;
    b.busy = c.Busy;
    b.active = c.Active;
    b.command_aborted = c.CommandAborted;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    let (prev, cmd) = unpack(c._internal);
    b.core.prev_execute = prev;
    b.core.cmd = cmd;
    b.core.done = c.Done;
    b.core.busy = c.Busy;
    b.core.active = c.Active;
    b.core.command_aborted = c.CommandAborted;
    b.core.error = c.Error;
    b.core.error_id = err(c.ErrorID);
    if let Some(id) = bad {
        // An out-of-range enumeration refuses the command on the rising edge.
        if c.Execute && !b.core.prev_execute && !b.core.busy {
            c.Done = false;
            c.Active = false;
            c.CommandAborted = false;
            c.Busy = false;
            c.Error = true;
            c.ErrorID = id.code();
            c._internal = pack(true, b.core.cmd);
            return;
        }
    }
    b.call(e, group as usize);
    c.Done = b.done;
    c.Busy = b.busy;
    c.Active = b.active;
    c.CommandAborted = b.command_aborted;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c._internal = pack(b.core.prev_execute, b.core.cmd);
}

/// C view of `McGroupReadActualPosition` (MC_GroupReadActualPosition).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupReadActualPosition_C {
    pub Enable: bool,
    pub CoordSystem: u8,
    pub Valid: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    pub Position: [f64; 16],
}

/// Calls MC_GroupReadActualPosition once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_group_read_actual_position(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_GroupReadActualPosition_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McGroupReadActualPosition::default();
    b.enable = c.Enable;
    b.coord_system = c.CoordSystem;
    b.valid = c.Valid;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.position = c.Position;
    b.call(e, group as usize);
    c.Valid = b.valid;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c.Position = b.position;
}

/// C view of `McGroupReadActualVelocity` (MC_GroupReadActualVelocity).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupReadActualVelocity_C {
    pub Enable: bool,
    pub CoordSystem: u8,
    pub Valid: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    pub Velocity: [f64; 16],
    pub PathVelocity: f64,
}

/// Calls MC_GroupReadActualVelocity once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_group_read_actual_velocity(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_GroupReadActualVelocity_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McGroupReadActualVelocity::default();
    b.enable = c.Enable;
    b.coord_system = c.CoordSystem;
    b.valid = c.Valid;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.velocity = c.Velocity;
    b.path_velocity = c.PathVelocity;
    b.call(e, group as usize);
    c.Valid = b.valid;
    c.Busy = b.busy;
    c.Error = b.error;
    c.ErrorID = b.error_id.code();
    c.Velocity = b.velocity;
    c.PathVelocity = b.path_velocity;
}

/// C view of `McGroupReadStatus` (MC_GroupReadStatus).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct MC_GroupReadStatus_C {
    pub Enable: bool,
    pub Valid: bool,
    pub Busy: bool,
    pub Error: bool,
    pub ErrorID: u16,
    pub GroupMoving: bool,
    pub GroupHoming: bool,
    pub GroupErrorStop: bool,
    pub GroupStandby: bool,
    pub GroupStopping: bool,
    pub GroupDisabled: bool,
}

/// Calls MC_GroupReadStatus once (one PLC scan).
/// # Safety
/// See the module contract: pointers are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn mc_group_read_status(
    engine: *mut McEngine,
    group: u32,
    fb: *mut MC_GroupReadStatus_C,
) {
    let Some(e) = (unsafe { eng(engine) }) else {
        return;
    };
    // SAFETY: a non-null fb points to a live, writable block struct (caller contract).
    let Some(c) = (unsafe { fb.as_mut() }) else {
        return;
    };
    let mut b = McGroupReadStatus::default();
    b.enable = c.Enable;
    b.valid = c.Valid;
    b.busy = c.Busy;
    b.error = c.Error;
    b.error_id = err(c.ErrorID);
    b.group_moving = c.GroupMoving;
    b.group_homing = c.GroupHoming;
    b.group_error_stop = c.GroupErrorStop;
    b.group_standby = c.GroupStandby;
    b.group_stopping = c.GroupStopping;
    b.group_disabled = c.GroupDisabled;
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
}

// ---- constants (emitted as #define by cbindgen) ----

/// MC_BUFFER_MODE value.
pub const MC_ABORTING: u8 = 0;
/// MC_BUFFER_MODE value.
pub const MC_BUFFERED: u8 = 1;
/// MC_BUFFER_MODE value.
pub const MC_BLENDING_LOW: u8 = 2;
/// MC_BUFFER_MODE value.
pub const MC_BLENDING_PREVIOUS: u8 = 3;
/// MC_BUFFER_MODE value.
pub const MC_BLENDING_NEXT: u8 = 4;
/// MC_BUFFER_MODE value.
pub const MC_BLENDING_HIGH: u8 = 5;
/// MC_DIRECTION value.
pub const MC_POSITIVE_DIRECTION: u8 = 0;
/// MC_DIRECTION value.
pub const MC_SHORTEST_WAY: u8 = 1;
/// MC_DIRECTION value.
pub const MC_NEGATIVE_DIRECTION: u8 = 2;
/// MC_DIRECTION value.
pub const MC_CURRENT_DIRECTION: u8 = 3;
/// MC_TRANSITION_MODE value.
pub const MC_TM_NONE: u8 = 0;
/// MC_TRANSITION_MODE value.
pub const MC_TM_CORNER_DISTANCE: u8 = 3;
/// MC_TRANSITION_MODE TMMaxCornerDeviation.
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
/// ErrorID 0: None
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
/// ErrorID 30: Override factor negative or not finite.
pub const MC_ERR_INVALID_OVERRIDE: u16 = 30;
/// ErrorID 31: The profile planner found no profile for these inputs.
pub const MC_ERR_PLANNING_FAILED: u16 = 31;
/// ErrorID 32: ExecutionMode, StartMode or another enumerated input is out of range.
pub const MC_ERR_INVALID_MODE: u16 = 32;
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
