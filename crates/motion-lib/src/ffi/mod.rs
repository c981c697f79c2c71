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

// The C calls, by subject. They come after the shared plumbing so that its macros are in scope.
mod axis_blocks;
mod constants;
mod engine;
mod group_blocks;
mod sync_blocks;
pub use axis_blocks::*;
pub use constants::*;
pub use engine::*;
pub use group_blocks::*;
pub use sync_blocks::*;

/// `sizeof` of the ABI structs by name (see [`mc_sizeof`]); every `#[repr(C)]` struct of the C ABI is
/// listed (test `ffi_c::c_program_checks_the_abi_contract` compares each with the C compiler's `sizeof`).
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
