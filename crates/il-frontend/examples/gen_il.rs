//! Prints a generated IL program to stdout, so that other compilers can be run on the same text
//! (scripts/matiec-anchor.sh): `cargo run --release -p il-frontend --example gen_il -- LINES POUS > p.il`.
//! Input: body lines per POU and the number of POUs (defaults 2000 and 50). Output: the text of
//! `il_frontend::testgen::generate(LINES, POUS)`, unchanged.
#![forbid(unsafe_code)]
use std::io::Write as _;

fn main() {
    let mut args = std::env::args().skip(1);
    let lines: usize = args.next().and_then(|a| a.parse().ok()).unwrap_or(2000);
    let pous: usize = args.next().and_then(|a| a.parse().ok()).unwrap_or(50);
    let src = il_frontend::testgen::generate(lines, pous);
    let mut out = std::io::stdout().lock();
    if out.write_all(src.as_bytes()).is_err() {
        std::process::exit(2);
    }
}
