//! The `ladderc` command line. Input: arguments; output: files, diagnostics on stderr, an exit code
//! (0 success, 1 diagnostics errors, 2 usage or I/O errors). All work is done by the `ladderc` library
//! ([`ladderc::cli::main`]).
#![forbid(unsafe_code)]

fn main() {
    std::process::exit(ladderc::cli::main());
}
