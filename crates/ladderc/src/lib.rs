//! ladderc as a library: the pipeline that the `ladderc` command line drives.
//!
//! Input: source files (IL, ST, PLCopen TC6 XML), an axes file, a target profile and parameter templates.
//! Output: diagnostics, the lowered IL, the C project and the block report. The binary (`src/main.rs`) only
//! calls [`cli::main`].
//!
//! Modules: [`pipeline`] (load, check, lower, generate C), [`cli`] (arguments and dispatch), [`axes`] (the
//! axes file), [`motion_link`] (the motion library that generated programs link), [`output`] (writing
//! into the user's folder), [`depfile`], [`fuzzing`] (the fuzz harness), [`lsp`] (the language server),
//! [`plot`], [`pmac_out`], [`report`], [`progress`] (running a built program), [`trace_raw`] (its raw trace
//! turned into CSV), [`stdio`] (output that ends quietly on a closed pipe), [`summary`] (the final summary)
//! and [`xml_context`].
#![forbid(unsafe_code)]

pub mod axes;
pub mod cli;
pub mod depfile;
pub mod fuzzing;
pub mod lsp;
pub mod motion_link;
pub mod output;
pub mod pipeline;
pub mod plot;
pub mod pmac_out;
pub mod progress;
pub mod report;
pub mod stdio;
pub mod summary;
pub mod trace_raw;
pub mod xml_context;
