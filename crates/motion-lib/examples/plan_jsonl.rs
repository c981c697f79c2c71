//! Reads problems in the oracle's JSON-lines format on stdin and writes them back with
//! ruckig-comparable `duration` and `phases` recomputed by this library
//! (`motion_lib::profile::plan_jsonl`); used to check profiles with exact arithmetic
//! (`tests/data/check_exact.py`).
#![forbid(unsafe_code)]

use std::io::Read;

fn main() {
    let mut text = String::new();
    std::io::stdin().read_to_string(&mut text).expect("stdin");
    match motion_lib::profile::plan_jsonl(&text) {
        Ok(out) => print!("{out}"),
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    }
}
