//! cargo-fuzz target: the template front end through `ladderc::fuzzing::run` (spans on character boundaries,
//! bounded diagnostics output, no panic).
#![no_main]

use ladderc::fuzzing::{run, FrontEnd};
use libfuzzer_sys::fuzz_target;

fuzz_target!(
    init: ladderc::fuzzing::init_target(),
    |data: &[u8]| {
        run(FrontEnd::Template, data);
    }
);
