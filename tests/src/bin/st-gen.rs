//! `st-gen`: writes the random ST projects of [`ladderc_tests::st_gen`] for the matiec differential run.
//! Input: `st-gen FIRST_SEED COUNT OUT_DIR`. Output: `OUT_DIR/gen_SEED.st` for the seeds FIRST_SEED ..
//! FIRST_SEED + COUNT - 1, and their paths on stdout, one a line. Exit 2 on a usage error or when a
//! file of that name is already there (it is not overwritten).
//! Invariant: a seed's file is the same on every run.
#![forbid(unsafe_code)]

use std::path::PathBuf;

fn main() {
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
        eprintln!("usage: st-gen FIRST_SEED COUNT OUT_DIR");
        std::process::exit(2);
    };
    if let Err(e) = std::fs::create_dir_all(&out) {
        eprintln!("error: {}: {e}", out.display());
        std::process::exit(2);
    }
    for seed in first..first.saturating_add(count) {
        let path = out.join(format!("gen_{seed}.st"));
        // a file that is already there is never overwritten
        let written = std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&path)
            .and_then(|mut f| {
                std::io::Write::write_all(&mut f, ladderc_tests::st_gen::generate(seed).as_bytes())
            });
        if let Err(e) = written {
            eprintln!("error: {}: {e}", path.display());
            std::process::exit(2);
        }
        println!("{}", path.display());
    }
}
