//! Prints a generated PLCopen TC6 XML ladder project to stdout, so that `ladderc build` can be timed on
//! it: `cargo run --release -p ladder-compiler --example gen_ld -- RUNGS > p.xml`.
//! Input: the rung count (default 10000). Output: the text of `ladder_compiler::testgen::generate(RUNGS)`,
//! unchanged.
#![forbid(unsafe_code)]
use std::io::Write as _;

fn main() {
    let rungs: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(10_000);
    let xml = ladder_compiler::testgen::generate(rungs);
    let mut out = std::io::stdout().lock();
    if out.write_all(xml.as_bytes()).is_err() {
        std::process::exit(2);
    }
}
