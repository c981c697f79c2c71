//! The IL front end: IEC 61131-3 instruction list source in, a typed syntax tree and diagnostics out.
//!
//! Stages: `lexer` (logos, case-insensitive keywords) -> `parser` (lalrpop, with error recovery) -> [`ast`]
//! -> `sema` (symbols, types, current-result typing, labels). Every node carries a byte [`Span`].

pub mod ast;
pub mod lexer;
pub mod literal;

pub use diagnostics::{FileId, Span};
