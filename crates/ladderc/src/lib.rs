//! ladderc as a library: the pipeline that the `ladderc` command line drives.
//!
//! Input: source files (IL, ST, PLCopen TC6 XML), an axes file, a target profile and parameter templates.
//! Output: diagnostics, the lowered IL, the C project and the block report. The binary (`src/main.rs`) only
//! calls [`cli::main`].
//!
//! Modules: [`pipeline`] (load, check, lower, generate C), [`cli`] (arguments and dispatch), [`axes`] (the
//! axes file), [`motion_link`] (the motion library that generated programs link), [`output`] (atomic
//! writes), [`plot`], [`pmac_out`] and [`report`].
#![forbid(unsafe_code)]

pub mod axes;
pub mod cli;
pub mod fuzzing;
pub mod motion_link;
pub mod output;
pub mod pipeline;
pub mod plot;
pub mod pmac_out;
pub mod report;
