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
//! - [`ffi`]: the C ABI, the only `unsafe` code of the project.
//!
//! Invariants: no commanded motion exceeds an axis's velocity, acceleration or jerk limit
//! (a request above them is lowered and, for groups, reported); the engine is
//! deterministic and its cycle allocates nothing; bad block inputs give an ErrorID
//! ([`error::ErrorId`]), never a panic; only [`ffi`] contains `unsafe` code. Every public
//! item is documented (`missing_docs`).
#![deny(unsafe_code)]
#![warn(missing_docs)]

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
