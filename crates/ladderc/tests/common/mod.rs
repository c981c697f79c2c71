//! Helpers shared by the CLI's end-to-end tests: the binary, the shared corpus, exit-status checks.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The `ladderc` binary under test.
pub fn ladderc() -> Command {
    Command::new(env!("CARGO_BIN_EXE_ladderc"))
}

/// A file of `shared/corpus` beside the repository (or beside an ancestor: worktrees nest deeper).
pub fn corpus(name: &str) -> PathBuf {
    let here = Path::new(env!("CARGO_MANIFEST_DIR"));
    here.ancestors()
        .map(|a| a.join("shared/corpus").join(name))
        .find(|p| p.is_file())
        .unwrap_or_else(|| here.join("../../../shared/corpus").join(name))
}

/// Asserts that a run exited with 0, showing its standard error otherwise.
pub fn assert_ok(out: &Output) {
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
