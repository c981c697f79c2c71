//! Generates the LR parser from `src/grammar.lalrpop` into `OUT_DIR`.
#![forbid(unsafe_code)]
fn main() {
    lalrpop::Configuration::new()
        .use_cargo_dir_conventions()
        .process()
        .unwrap();
}
