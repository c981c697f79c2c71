//! motion-lib: the PLCopen motion library.
//!
//! Input: axis limits and motion commands; output: time-optimal set-point
//! trajectories. Modules:
//! - [`profile`]: time-optimal jerk-limited 1-D profiles and straight lines in N axes
//!   (the mathematics, with no PLC interface).
//! - [`axis`], [`fsm`], [`buffer`], [`cmd`], [`engine`], [`sync`], [`path`], [`group`]:
//!   the runtime (axes, state machines, buffers, interpolation).
//! - [`blocks`], [`group_blocks`]: the PLCopen function blocks, called once per scan.
//! - [`remote`]: the engine on its own thread with a lock-free hand-over to the scan.
//! - [`ffi`]: the C ABI (the only `unsafe` code of the project).
#![deny(unsafe_code)]

pub mod profile;

pub mod axis;
pub mod blocks;
pub mod buffer;
pub mod cmd;
pub mod engine;
pub mod error;
// The C ABI is the one module that may use `unsafe` (every block documents its safety contract).
#[allow(unsafe_code)]
pub mod ffi;
pub mod fsm;
pub mod group;
pub mod group_blocks;
pub mod path;
pub mod remote;
pub mod sync;
