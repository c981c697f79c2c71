//! The whole IL-to-C pipeline in one call, for the `ladderc build` / `ladderc run` commands.
//!
//! Input: IL source files (name, text). Output: the [`CProgram`] (and, with [`build_il`], the compiled
//! executable), diagnostics from every stage in `diags` (files registered in `map` for rendering).
//! Invariants: stops before generation when parsing or analysis reported an error; instructions outside
//! any POU form the implicit `PROGRAM main` (the parser's W0001), so `--watch main.x` works for bare files.

use crate::{generate, toolchain, BuildError, BuildOptions, CProgram, Options, TargetProfile};
use diagnostics::{Diagnostics, SourceMap};
use std::path::{Path, PathBuf};

/// Parses, analyses and generates C for the given IL files.
pub fn compile_il(
    map: &mut SourceMap,
    inputs: &[(String, String)],
    profile: &TargetProfile,
    opts: &Options,
    diags: &mut Diagnostics,
) -> Option<CProgram> {
    let mut units = Vec::with_capacity(inputs.len());
    for (name, text) in inputs {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let file = map.add(name.clone(), text.to_string());
        units.push(il_frontend::parse(file, text, diags));
    }
    if diags.has_errors() {
        return None;
    }
    let model = il_frontend::sema::analyze(&units, diags);
    if diags.has_errors() {
        return None;
    }
    generate(&units, &model, profile, opts, diags)
}

/// [`compile_il`], then writes the project into `dir` and compiles it. `Ok(None)`: the sources had errors
/// (see `diags`); `Err`: writing or compiling failed.
pub fn build_il(
    map: &mut SourceMap,
    inputs: &[(String, String)],
    profile: &TargetProfile,
    opts: &Options,
    dir: &Path,
    build: &BuildOptions,
    diags: &mut Diagnostics,
) -> Result<Option<PathBuf>, BuildError> {
    match compile_il(map, inputs, profile, opts, diags) {
        Some(p) => toolchain::build_with(&p, dir, build).map(Some),
        None => Ok(None),
    }
}
