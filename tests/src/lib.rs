//! Support code of the end-to-end suites that is also a tool of its own.
//!
//! Input: a seed. Output: [`il_gen::generate`], a random valid IEC 61131-3 IL project (TYPE,
//! FUNCTIONs, FUNCTION_BLOCKs, PROGRAMs and a CONFIGURATION) for the cycle-by-cycle comparison with
//! matiec (`tests/tests/matiec_diff.rs`, `scripts/matiec-fuzz.sh`). Invariant: the same seed gives the
//! same text on every machine.
#![forbid(unsafe_code)]

pub mod il_gen;
