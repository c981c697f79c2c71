//! Support code of the end-to-end suites that is also a tool of its own.
//!
//! Input: a seed. Output: [`il_gen::generate`], a random valid IEC 61131-3 IL project (TYPE,
//! FUNCTIONs, FUNCTION_BLOCKs, PROGRAMs and a CONFIGURATION) for the cycle-by-cycle comparison with
//! matiec (`tests/tests/matiec_diff.rs`, `scripts/matiec-fuzz.sh`), and [`st_gen::generate`], its
//! Structured Text sibling (`scripts/matiec-fuzz.sh --lang st`). Invariant: the same seed gives the
//! same text on every machine.
#![forbid(unsafe_code)]

pub mod il_gen;
pub mod st_gen;

use std::path::PathBuf;

/// The `main` of the generator binaries (`il-gen`, `st-gen`): `TOOL FIRST_SEED COUNT OUT_DIR` writes
/// `OUT_DIR/gen_SEED.EXT` for the seeds FIRST_SEED .. FIRST_SEED + COUNT - 1 and prints their paths,
/// one a line. Exit 2 on a usage error or when a file of that name is already there (it is never
/// overwritten).
pub fn write_seeds_main(tool: &str, ext: &str, generate: fn(u64) -> String) {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let parsed = match args.as_slice() {
        [first, count, out] => first
            .parse::<u64>()
            .ok()
            .zip(count.parse::<u64>().ok())
            .map(|(f, c)| (f, c, PathBuf::from(out))),
        _ => None,
    };
    let Some((first, count, out)) = parsed else {
        eprintln!("usage: {tool} FIRST_SEED COUNT OUT_DIR");
        std::process::exit(2);
    };
    if let Err(e) = std::fs::create_dir_all(&out) {
        eprintln!("error: {}: {e}", out.display());
        std::process::exit(2);
    }
    for seed in first..first.saturating_add(count) {
        let path = out.join(format!("gen_{seed}.{ext}"));
        // a file that is already there is never overwritten
        let written = std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&path)
            .and_then(|mut f| std::io::Write::write_all(&mut f, generate(seed).as_bytes()));
        if let Err(e) = written {
            eprintln!("error: {}: {e}", path.display());
            std::process::exit(2);
        }
        println!("{}", path.display());
    }
}
