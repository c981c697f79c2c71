//! `st-gen`: writes the random ST projects of [`ladderc_tests::st_gen`] for the matiec differential run.
//! Input: `st-gen FIRST_SEED COUNT OUT_DIR`. Output: `OUT_DIR/gen_SEED.st` for the seeds FIRST_SEED ..
//! FIRST_SEED + COUNT - 1, and their paths on stdout, one a line. Exit 2 on a usage error or when a
//! file of that name is already there (it is not overwritten).
//! Invariant: a seed's file is the same on every run.
#![forbid(unsafe_code)]

fn main() {
    ladderc_tests::write_seeds_main("st-gen", "st", ladderc_tests::st_gen::generate);
}
