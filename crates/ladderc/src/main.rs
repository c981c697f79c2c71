//! The `ladderc` command line. Input: arguments; output: files, diagnostics on stderr, an exit code
//! (0 success, 1 diagnostics errors, 2 usage or I/O errors). All work is done by the `ladderc` library
//! ([`ladderc::cli::main`]).
#![forbid(unsafe_code)]

/// jemalloc instead of glibc's malloc: the front ends allocate many small names, lists and tree nodes
/// (about 200 allocations per ladder rung); with glibc, `malloc`/`free` were 13 % of the CPU time of
/// `ladderc build` on 10,000 rungs (crates/ladderc/BENCHMARKS.md, Round 10 (ladder)). jemalloc rather
/// than mimalloc: the same CPU time there, and it keeps freed pages for reuse, where mimalloc returned
/// them and faulted them in again (the 1,000,000-line IL POU peaked 48 MiB higher with mimalloc).
#[cfg(not(target_env = "msvc"))]
#[global_allocator]
static GLOBAL: tikv_jemallocator::Jemalloc = tikv_jemallocator::Jemalloc;

fn main() {
    std::process::exit(ladderc::cli::main());
}
