//! The `ladderc` command line. Input: arguments; output: files, diagnostics on stderr, an exit code
//! (0 success, 1 diagnostics errors, 2 usage or I/O errors). All work is done by the `ladderc` library
//! ([`ladderc::cli::main`]).
#![forbid(unsafe_code)]

/// mimalloc instead of glibc's malloc: the front ends allocate many small names, lists and tree nodes
/// (about 200 allocations per ladder rung); with glibc, `malloc`/`free` were 13 % of the CPU time of
/// `ladderc build` on 10,000 rungs (crates/ladderc/BENCHMARKS.md, round 10). Transparent huge pages stay
/// off (`no_thp`): with them the system time of that build went up several times (page compaction).
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    std::process::exit(ladderc::cli::main());
}
