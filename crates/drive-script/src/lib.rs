//! drive-script: a compact logic script for servo drives (paper C, issue #7).
//!
//! Input: script text (`S:: ... ;` statements: PARAM, INIT, MOTION/EVENT/IF/THEN blocks).
//! Output: a [`Program`] (Motion pool + Event pool, plain data), its binary image, a cycle-sliced
//! [`Interpreter`] driving any [`Drive`], a breakpoint debugger and CLI entry points.
//! Invariants: no function panics on bad input (script or image); the interpreter never blocks: each
//! [`Interpreter::cycle`] call evaluates at most `EventsPerCycle` Events.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod cli;
pub mod compiler;
pub(crate) mod lexer;
pub mod limits;
pub mod program;

pub use compiler::{compile, compile_str, Compiled, DebugInfo, EventLines};
pub use program::*;
pub mod debugger;
pub mod drive;
pub mod image;
pub mod interpreter;
pub mod motion_drive;

pub use debugger::{Breakpoint, BreakpointError, Breakpoints, Location, Phase};
pub use drive::{CycleDrive, Drive, MotionState, SimDrive};
pub use image::{decode, encode, ImageError};
pub use interpreter::{CycleResult, Interpreter, Snapshot};
pub use motion_drive::MotionLibDrive;
