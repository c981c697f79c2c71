//! Semantic analysis of IL: symbols, types, current-result typing, labels, calls.
//!
//! Input: the parsed [`crate::ast::CompilationUnit`]s of one program (one namespace of POUs and types).
//! Output: the resolved [`model::Model`] and diagnostics (codes E1xxx/W1xxx).
//! Invariants: one mistake gives one diagnostic: an unresolvable name gives the `Error` type, which
//! silences every check that would follow from it.

pub mod model;

pub use model::*;
