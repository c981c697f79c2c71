//! Issue #13, seventh acceptance round (helper `lang4`): public repositories no earlier round had
//! tried (OpenPLC Editor and Beremiz projects, matiec examples, a CODESYS V3.5 SP21 device export,
//! a static checker's ST test suite, TwinCAT ST sources, non-IEC IL dialects). Each case is a minimal
//! reproduction written here, in `tests/fixtures/unseen/`, run through `ladderc run` (traces) or
//! `ladderc check`:
//! - **POUs and data types in a configuration resource's vendor data.** CODESYS V3.5 SP17 and
//!   later (WAGO e!COCKPIT too) export a device's application as the resource under `<instances>`,
//!   with the POUs (`addData/data[.../pou]/pou`) and data types (`.../datatype`) inside that
//!   resource's `<addData>`, `<types>` left empty. Before, those POUs were not read and the task's
//!   `pouInstance` was E1024 "unknown program".

mod common;
use common::{column, run_traced};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    common::repo_root()
        .join("tests/tests/fixtures/unseen")
        .join(name)
}

/// The program, its function block and its structure type all come from the resource's vendor
/// data; the task (20 ms, scans of 10 ms) runs the program every second scan, and the block counts
/// up to the structure's initial `High` (5) and wraps to 0.
#[test]
fn codesys_device_export_reads_pous_and_types_from_the_resource_vendor_data() {
    let (trace, _) = run_traced(
        &fixture("codesys_device_resource_pous.xml"),
        14,
        "PLC_PRG.counter",
    );
    let counter = column(&trace, "PLC_PRG.counter");
    assert_eq!(
        counter,
        [1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0, 5.0, 5.0, 0.0, 0.0, 1.0, 1.0],
        "{trace}"
    );
}
