//! `il-gen`: writes the random IL projects of [`ladderc_tests::il_gen`] for the matiec differential run.
//! Input: `il-gen FIRST_SEED COUNT OUT_DIR`. Output: `OUT_DIR/gen_SEED.il` for the seeds FIRST_SEED ..
//! FIRST_SEED + COUNT - 1, and their paths on stdout, one a line. Exit 2 on a usage error or when a
//! file of that name is already there (it is not overwritten).
//! Invariant: a seed's file is the same on every run.
#![forbid(unsafe_code)]

fn main() {
    ladderc_tests::write_seeds_main("il-gen", "il", ladderc_tests::il_gen::generate);
}
