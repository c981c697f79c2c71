//! wip
pub mod values;
pub mod xml;
