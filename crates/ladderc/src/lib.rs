//! ladderc as a library: the IEC 61131-3 (IL, ST, PLCopen TC6 XML) to C pipeline that the `ladderc`
//! command line drives, as a typed, in-memory API.
//!
//! Input: sources as `(path, text)` pairs and [`Options`] (the axes file, target profile and parameter
//! templates may be given in memory too). Output, stage by stage ([`project`]): the diagnostics (values of
//! the [`diagnostics`] crate), the parsed and checked units, the lowered IL, the C files and the block
//! report. Invariant: nothing is read from the file system, written, or started as a process unless asked
//! ([`Project::with_disk_fallback`], [`Options::compile_templates`], [`GeneratedProject::write_to`],
//! [`c_backend::build_with`]). The binary (`src/main.rs`) only calls [`cli::main`], which parses the
//! arguments, runs this API and prints.
//!
//! # IL in memory to C
//!
//! ```
//! use ladderc::{Options, Project};
//!
//! let il = "PROGRAM blink\n\
//!           VAR\n    lamp AT %QX0.0 : BOOL;\nEND_VAR\n\
//!           LD lamp\n    STN lamp\n\
//!           END_PROGRAM\n";
//! // Nothing here exists on disk: the path only names the source and gives its language.
//! let checked = Project::from_sources([("plant/blink.il", il)], Options::default()).check()?;
//! assert!(checked.diagnostics().is_empty());
//! let lowered = checked.lower()?;
//! assert!(lowered.il().contains("STN lamp"));
//! let generated = lowered.generate()?;
//! let program_c = generated.c_file("program.c").expect("the program's C");
//! assert!(program_c.contains("blink"));
//! assert!(generated.headers().count() >= 1);
//! assert!(generated.files().any(|(name, _)| name == "Makefile"));
//! # Ok::<(), ladderc::Failed>(())
//! ```
//!
//! # A diagnostic as a value
//!
//! ```
//! use ladderc::{diagnostics::code, MessageFormat, Options, Project};
//!
//! let il = "PROGRAM p\nVAR\n    a : INT;\nEND_VAR\n    LD a\n    ADD undeclared\n    ST a\nEND_PROGRAM\n";
//! let failed = match Project::from_sources([("p.il", il)], Options::default()).compile() {
//!     Ok(_) => panic!("`undeclared` is not declared"),
//!     Err(failed) => failed,
//! };
//! let error = failed.errors().next().expect("one error");
//! assert_eq!(error.code, code::E1001);
//! assert_eq!(failed.line_col(error), Some((6, 9)));
//! assert!(failed.render(MessageFormat::Short).starts_with("p.il:6:9: error[E1001]"));
//! ```
//!
//! Modules: [`project`] (the typed API), [`pipeline`] (the stages on a [`pipeline::Session`]), [`cli`]
//! (arguments and dispatch), [`beremiz`] (Beremiz project folders as inputs), [`axes`] (the axes file), [`motion_link`] (the motion library that generated
//! programs link), [`output`] (writing into the user's folder), [`depfile`], [`fuzzing`] (the fuzz
//! harness), [`lsp`] (the language server), [`plot`], [`pmac_out`], [`report`], [`progress`] (running a
//! built program), [`trace_raw`] (its raw trace turned into CSV), [`stdio`] (output that ends quietly on a closed pipe), [`summary`] (the final summary)
//! and [`xml_context`]. Beckhoff Tc2_MC2 motion: [`tc2_mc2`] (spellings), [`tc2_axis_ref`] (AXIS_REF
//! members), [`tc2_override`] (MC_Power's Override), [`tc2_error_id`] (UDINT ErrorIDs), [`tc2_blocks`] (MC_MoveModulo, MC_Jog),
//! [`axis_links`] (each AXIS_REF its own axis), [`block_temps`] (expressions as block inputs);
//! `tool_semantics` (W1465, W1466: a Beremiz or OpenPLC project under a profile with other semantics);
//! `folder_walk` (the bounded, sorted walk of an AX or OpenPLC v4 project folder for its sources).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod apax;
pub mod axes;
pub mod axis_links;
pub mod beremiz;
pub mod binary_input;
pub mod block_temps;
pub mod br_case_fields;
pub mod br_edges;
pub mod br_private_types;
pub mod br_programs;
pub mod cli;
pub mod codesys_v23;
pub mod codesys_v23_io;
pub mod depfile;
pub mod encoding;
mod folder_walk;
pub mod fuzzing;
pub mod generic_blocks;
pub mod loop_guard;
pub mod lsp;
pub mod motion_in_struct;
pub mod motion_link;
pub mod nc_axes;
pub mod no_program;
pub mod openplc_v4;
pub mod openplc_v4_json;
pub mod openplc_v4_ld;
pub mod output;
pub mod pipeline;
pub mod plot;
pub mod pmac_out;
pub mod progress;
pub mod project;
pub mod report;
pub mod split_blocks;
pub mod stdio;
pub mod summary;
pub mod tc2_axis_ref;
pub mod tc2_blocks;
pub mod tc2_error_id;
pub mod tc2_mc2;
pub mod tc2_override;
pub mod text_lists;
mod textual_sfc;
mod tool_semantics;
pub mod trace_raw;
pub mod twincat;
pub mod user_libraries;
pub mod xml_context;

pub use c_backend;
pub use diagnostics;
pub use diagnostics::MessageFormat;
pub use il_frontend;
pub use pipeline::{Lang, Options};
pub use project::{
    AccessDirection, AccessPath, CheckedProject, Failed, GeneratedProject, LoweredProject,
    ParsedProject, Project,
};
