//! pmac-backend: turns planned motion into what a Delta Tau PMAC (Turbo PMAC or Power PMAC) accepts.
//!
//! Input: a coordinate system ([`model::CoordSystem`]) plus either a list of straight moves with jerk-limited
//! limits ([`model::LinearMove`]) or a sampled trajectory ([`model::Trajectory`], or any
//! [`model::TrajectorySource`]). These types are this crate's own; the motion library's output is adapted to them.
//! Output: motion-program text ([`program::write`]), PVT segments and their text ([`pvt::segments`],
//! [`pvt::to_lines`]), streaming of that text through a [`transport::Transport`] ([`pvt::stream`]), and checks
//! that the emitted text reproduces the input motion ([`verify`]).
//! Transports: a file, a `gpascii`-style TCP line protocol (Power PMAC) and the Turbo PMAC Ethernet protocol.
//! Invariants: nothing here panics on bad input; invalid input gives a [`diagnostics::Diagnostic`] with an
//! `E7xxx` code. No real controller was available while this was written: the protocol follows the manuals and
//! is tested against a loopback simulator.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod compare;
pub mod error;
pub mod model;
pub mod numfmt;
pub mod program;
pub mod pvt;
pub mod scurve;
pub mod transport;
pub mod verify;

pub use error::PmacError;
pub use model::{
    AxisDef, CoordSystem, Dialect, LinearMove, MoveMode, Trajectory, TrajectorySource, Transition,
};
