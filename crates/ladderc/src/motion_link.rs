//! Finding the motion library's static library (`libmotion_lib.a`) that generated programs link.
//!
//! Input: the environment (`LADDERC_MOTION_LIB`) and the location of the running executable. Output: the
//! path of the library, or an E9050 diagnostic naming every place that was searched.
//! Search order: `$LADDERC_MOTION_LIB`; `libmotion_lib.a` beside the executable; the newest
//! `libmotion_lib*.a` in `deps/` beside it (cargo builds it there because motion-lib declares the
//! `staticlib` crate type and ladderc depends on it); the same two in the parent directory (test
//! executables live in `target/<profile>/deps`). Invariant: only existing regular files are returned.

use diagnostics::{code, Diagnostic};
use std::path::{Path, PathBuf};

/// The environment variable that overrides the search.
pub const ENV: &str = "LADDERC_MOTION_LIB";

fn newest_in(dir: &Path) -> Option<PathBuf> {
    std::fs::read_dir(dir)
        .ok()?
        .filter_map(Result::ok)
        .filter(|e| {
            let n = e.file_name();
            let n = n.to_string_lossy();
            n.starts_with("libmotion_lib") && n.ends_with(".a")
        })
        .filter_map(|e| {
            let m = e.metadata().ok()?;
            Some((m.modified().ok()?, e.path()))
        })
        .max_by_key(|(t, _)| *t)
        .map(|(_, p)| p)
}

/// The places searched beside an executable directory, in order.
fn candidates(exe_dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut dirs = vec![exe_dir.to_path_buf()];
    if let Some(parent) = exe_dir.parent() {
        dirs.push(parent.to_path_buf());
    }
    for d in dirs {
        out.push(d.join(c_backend::motion::STATICLIB));
        if let Some(p) = newest_in(&d.join("deps")) {
            out.push(p);
        }
        if d.file_name().is_some_and(|n| n == "deps") {
            if let Some(p) = newest_in(&d) {
                out.push(p);
            }
        }
    }
    out
}

/// Locates the static library (see the module header).
pub fn find() -> Result<PathBuf, Box<Diagnostic>> {
    if let Some(v) = std::env::var_os(ENV).filter(|v| !v.is_empty()) {
        let p = PathBuf::from(v);
        if p.is_file() {
            return Ok(p);
        }
        return Err(Box::new(
            Diagnostic::error(
                code::E9050,
                format!("{ENV} is set to {}, which is not a file", p.display()),
            )
            .with_hint("point it at libmotion_lib.a (cargo build -p motion-lib)"),
        ));
    }
    let exe = std::env::current_exe().ok();
    let exe_dir = exe.as_deref().and_then(Path::parent);
    let searched = exe_dir.map(candidates).unwrap_or_default();
    if let Some(p) = searched.iter().find(|p| p.is_file()) {
        return Ok(p.clone());
    }
    Err(Box::new(
        Diagnostic::error(
            code::E9050,
            "the program uses motion blocks, but the motion library libmotion_lib.a was not found",
        )
        .with_note(format!(
            "searched {ENV} and: {}",
            searched
                .iter()
                .map(|p| p.display().to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ))
        .with_hint(format!(
            "build it (cargo build -p motion-lib) and set {ENV}=/path/to/libmotion_lib.a"
        )),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_newest_archive_in_deps_wins_and_the_parent_is_searched() {
        let dir = tempfile::tempdir().unwrap();
        let deps = dir.path().join("deps");
        std::fs::create_dir(&deps).unwrap();
        std::fs::write(deps.join("libmotion_lib-old.a"), "old").unwrap();
        std::thread::sleep(std::time::Duration::from_millis(20));
        std::fs::write(deps.join("libmotion_lib-new.a"), "new").unwrap();
        std::fs::write(deps.join("libother.a"), "x").unwrap();
        let c = candidates(dir.path());
        assert_eq!(c[1], deps.join("libmotion_lib-new.a"));
        // from target/debug/deps (a test executable) the same archive is found
        let c = candidates(&deps);
        assert!(c.contains(&deps.join("libmotion_lib-new.a")), "{c:?}");
        assert!(c.contains(&dir.path().join("libmotion_lib.a")), "{c:?}");
    }
}
