//! Parameter passing for PLCopen blocks (paper A): every call of a PLCopen block, from IL or from a ladder
//! block, is lowered by one of two strategies.
//!
//! - IL-instruction method: input transfer into the TM area by IL, one `FUNC Name()`, output transfer back;
//!   the C function is a complete static-library function that reads and writes only the TM area.
//! - Parameter-template method: one `FUNC Name()`; its C function is synthesised from an XML template
//!   (generated head + library body + generated feedback tail).
//!
//! Stages here: `xml` (element tree with spans) -> `template` (schema, validation) -> `cbody` (lexical and
//! name checks of a body) -> `ccheck` (a user template's function compiled alone) -> `tm` (slot layout).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod cbody;
pub mod ccheck;
pub mod library;
pub mod lower;
pub mod prelude;
pub mod static_lib;
pub mod template;
pub mod tm;
mod xml;

pub use template::{Direction, Param, Template, TypeClass};
