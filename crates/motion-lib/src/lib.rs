//! motion-lib: the PLCopen motion library.
//!
//! Input: axis limits and motion commands; output: time-optimal set-point
//! trajectories. Modules:
//! - [`profile`]: time-optimal jerk-limited 1-D profiles and straight lines in N axes
//!   (the mathematics, with no PLC interface).

pub mod profile;
