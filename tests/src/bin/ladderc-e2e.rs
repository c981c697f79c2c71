//! The `ladderc` command line, built inside the end-to-end test package so that its suites can name it
//! (`env!("CARGO_BIN_EXE_ladderc-e2e")`, see `tests/common`). Input: arguments; output: what `ladderc`
//! does. Invariant: identical to `crates/ladderc/src/main.rs`; the suites run it with `argv[0] = ladderc`.
#![forbid(unsafe_code)]

fn main() {
    std::process::exit(ladderc::cli::main());
}
