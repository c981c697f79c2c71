//! Where the tests find the corpus: real files written by other people.
//!
//! Input: a path relative to the corpus root (`01_beremiz_first_steps.xml`, `il/18_il_parser_test1.il`) and
//! the environment: `LADDERC_CORPUS` (a folder laid out like the corpus) and `LADDERC_REQUIRE_CORPUS`.
//! Output: the path of the file, or `None` after printing a skip line.
//! Invariants: a bundled file (under a permissive licence, in `files/`) is always found; any other file is
//! read only from `$LADDERC_CORPUS`; once `LADDERC_CORPUS` is set, a missing file or folder is a panic
//! (never a silent skip), and with `LADDERC_REQUIRE_CORPUS=1` an unset `LADDERC_CORPUS` is one too.

#![warn(missing_docs)]
#![forbid(unsafe_code)]

use std::io::Write;
use std::path::{Path, PathBuf};

/// The variable naming the corpus folder.
pub const ENV: &str = "LADDERC_CORPUS";
/// When `1`, an unset [`ENV`] fails the tests that need it instead of skipping them (CI sets it).
pub const REQUIRE_ENV: &str = "LADDERC_REQUIRE_CORPUS";

/// The folder of the bundled files (same layout as the corpus).
pub fn bundled_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("files")
}

/// The folder named by `LADDERC_CORPUS`, or `None` when it is unset or empty.
///
/// # Panics
/// When it is set but not a folder, or unset while `LADDERC_REQUIRE_CORPUS=1`.
pub fn dir() -> Option<PathBuf> {
    match std::env::var_os(ENV).filter(|v| !v.is_empty()) {
        Some(v) => {
            let d = PathBuf::from(v);
            assert!(d.is_dir(), "{ENV}={} is not a folder", d.display());
            Some(d)
        }
        None => {
            let required = std::env::var_os(REQUIRE_ENV).is_some_and(|v| v == "1");
            assert!(
                !required,
                "{REQUIRE_ENV}=1 but {ENV} is unset: the corpus tests would be skipped"
            );
            None
        }
    }
}

/// Prints the skip line of a test that needs `what` from the corpus. It goes straight to the process's
/// standard error, past the test harness's capture, so that a passing run still shows it.
pub fn skip(what: &str) {
    // The test harness names each test's thread after the test.
    let thread = std::thread::current();
    let test = thread.name().unwrap_or("a test");
    let _ = writeln!(
        std::io::stderr(),
        "skipped ({ENV} unset): {test} needs {what}, which is not bundled; set {ENV} to the corpus folder"
    );
}

/// The corpus file `rel`: the bundled copy, else the file in `$LADDERC_CORPUS`; `None` (after printing
/// the skip line) when it is not bundled and `LADDERC_CORPUS` is unset.
///
/// # Panics
/// When `LADDERC_CORPUS` is set and the file is not in it (see also [`dir`]).
pub fn file(rel: &str) -> Option<PathBuf> {
    let bundled = bundled_dir().join(rel);
    if bundled.is_file() {
        return Some(bundled);
    }
    let Some(d) = dir() else {
        skip(rel);
        return None;
    };
    let p = d.join(rel);
    assert!(
        p.is_file(),
        "corpus file {rel} not found in {ENV}={}",
        d.display()
    );
    Some(p)
}

/// The text of the corpus file `rel` (see [`fn@file`]).
pub fn read(rel: &str) -> Option<String> {
    let p = file(rel)?;
    Some(std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display())))
}

/// The corpus file `rel`, which the caller requires.
///
/// # Panics
/// When it is neither bundled nor in `$LADDERC_CORPUS`.
pub fn path(rel: &str) -> PathBuf {
    file(rel).unwrap_or_else(|| {
        panic!("corpus file {rel} is not bundled: set {ENV} to the corpus folder")
    })
}

/// The files of the corpus folder `sub` (`""` for the root) whose names end in one of `exts`: the bundled
/// ones and, when `LADDERC_CORPUS` is set, those of that folder, sorted by name, each name once (the
/// bundled copy first).
pub fn list(sub: &str, exts: &[&str]) -> Vec<PathBuf> {
    let mut dirs = vec![bundled_dir().join(sub)];
    if let Some(d) = dir() {
        let d = d.join(sub);
        assert!(d.is_dir(), "{ENV} has no folder {sub:?}: {}", d.display());
        dirs.push(d);
    }
    let mut out: Vec<PathBuf> = Vec::new();
    for d in dirs {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in entries {
            let p = e.unwrap_or_else(|e| panic!("{}: {e}", d.display())).path();
            let name = p.file_name().map(|n| n.to_string_lossy().into_owned());
            let Some(name) = name else { continue };
            if p.is_file()
                && exts.iter().any(|x| name.ends_with(x))
                && !out.iter().any(|q| q.file_name() == p.file_name())
            {
                out.push(p);
            }
        }
    }
    out.sort_by(|a, b| a.file_name().cmp(&b.file_name()));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bundled_files_are_found_whatever_the_environment() {
        for rel in [
            "il/18_il_parser_test1.il",
            "il/19_il_parser_test2.il",
            "il/25_echidna_blink.il",
            "il/26_echidna_ctu.il",
            "24_feecat_S7RTT_codesys_st_motion.xml",
        ] {
            let p = file(rel).expect("bundled");
            assert!(p.starts_with(bundled_dir()), "{}", p.display());
        }
        let il = list("il", &[".il", ".st"]);
        assert!(il.iter().any(|p| p.ends_with("il/18_il_parser_test1.il")));
        assert!(!list("", &[".xml"])
            .iter()
            .any(|p| p.ends_with("ATTRIBUTION.md")));
    }

    #[test]
    fn a_file_that_is_not_bundled_is_skipped_or_must_exist() {
        // Depends on the environment the suite runs in: unset -> None, set -> the file must be there.
        match dir() {
            None => assert_eq!(file("01_beremiz_first_steps.xml"), None),
            Some(d) => {
                let p = file("01_beremiz_first_steps.xml").expect("in the corpus");
                assert!(p.starts_with(d));
                let missing = std::panic::catch_unwind(|| file("no_such_file.xml"));
                assert!(missing.is_err(), "a missing file of a set corpus panics");
            }
        }
    }
}
