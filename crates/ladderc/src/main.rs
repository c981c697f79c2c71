//! The `ladderc` command line. Input: arguments; output: files, diagnostics on stderr, an exit code
//! (0 success, 1 diagnostics errors, 2 usage or I/O errors). All work is done by the library crates.

mod axes;
mod cli;
mod motion_link;
mod output;
mod pipeline;
mod plot;
mod pmac_out;
mod report;

fn main() {
    std::process::exit(cli::main());
}
