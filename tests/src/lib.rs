//! Support code of the end-to-end suites that is also a tool of its own.
//!
//! Input: a seed. Output: [`il_gen::generate`], a random valid IEC 61131-3 IL project (TYPE,
//! FUNCTIONs, FUNCTION_BLOCKs, PROGRAMs and a CONFIGURATION) for the cycle-by-cycle comparison with
//! matiec (`tests/tests/matiec_diff.rs`, `scripts/matiec-fuzz.sh`), and [`st_gen::generate`], its
//! Structured Text sibling (`scripts/matiec-fuzz.sh --lang st`). Invariant: the same seed gives the
//! same text on every machine.
#![forbid(unsafe_code)]

pub mod il_gen;
pub mod st_gen;
