//! The motion library's static library (`libmotion_lib.a`) that generated programs link.
//!
//! Input: the environment (`LADDERC_MOTION_LIB`). Output: the library's bytes, or an E9050 diagnostic.
//! ladderc carries the library: `build.rs` builds motion-lib as a release static library for the target
//! ladderc is built for (LTO, one codegen unit, opt-level "s", panic=unwind), and it is embedded here, so an
//! installed `ladderc` needs no source tree and no environment variable. `LADDERC_MOTION_LIB=FILE`
//! replaces it (a library built with other settings, or for a debugger).
//! Invariant: the bytes returned are those of a regular file or of the embedded archive, never empty
//! (the archive is empty only in a `cargo clippy` build, which links no executable).

use diagnostics::{code, Diagnostic};
use std::borrow::Cow;
use std::path::PathBuf;

/// The environment variable that replaces the embedded library.
pub const ENV: &str = "LADDERC_MOTION_LIB";

/// The release static library built by `build.rs` for ladderc's own target.
pub static EMBEDDED: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/libmotion_lib.a"));

/// How the embedded library's std was built (`build.rs`): `trimmed` (std rebuilt from rust-src without its
/// backtrace symbolizer, panic=unwind kept), `full` (the toolchain's prebuilt std), `prebuilt`
/// (`LADDERC_PREBUILT_MOTION_LIB`) or `none` (the empty placeholder of a clippy build).
pub const EMBEDDED_STD: &str = env!("LADDERC_MOTION_LIB_STD");

/// The motion library's C header (`motion_lib.h`), as generated from motion-lib's C ABI.
pub const HEADER: &str = include_str!("../../motion-lib/include/motion_lib.h");

/// Where the library comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Source {
    /// `$LADDERC_MOTION_LIB`.
    Override(PathBuf),
    /// The archive embedded in ladderc.
    Embedded,
}

/// The library to link: `$LADDERC_MOTION_LIB` when set, else the embedded one.
pub fn source() -> Source {
    match std::env::var_os(ENV).filter(|v| !v.is_empty()) {
        Some(v) => Source::Override(PathBuf::from(v)),
        None => Source::Embedded,
    }
}

/// The library's bytes (see [`source`]).
pub fn library() -> Result<Cow<'static, [u8]>, Box<Diagnostic>> {
    match source() {
        Source::Embedded if EMBEDDED.is_empty() => Err(Box::new(
            Diagnostic::error(
                code::E9050,
                "this ladderc was built without the motion library (a `cargo clippy` build)",
            )
            .with_hint(format!(
                "use a ladderc built by cargo build or cargo install, or set {ENV}"
            )),
        )),
        Source::Embedded => Ok(Cow::Borrowed(EMBEDDED)),
        Source::Override(p) => match std::fs::read(&p) {
            Ok(bytes) if p.is_file() && !bytes.is_empty() => Ok(Cow::Owned(bytes)),
            Ok(_) | Err(_) => Err(Box::new(
                Diagnostic::error(
                    code::E9050,
                    format!(
                        "{ENV} is set to {}, which is not a readable, non-empty file",
                        p.display()
                    ),
                )
                .with_hint(format!(
                    "unset {ENV} to link the motion library built into ladderc, or point it at a \
                     libmotion_lib.a (cargo build -p motion-lib --release)"
                )),
            )),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_embedded_library_is_an_archive_with_the_c_abi() {
        assert!(EMBEDDED.starts_with(b"!<arch>\n"), "not an ar archive");
        // the entry points the generated C calls are defined in it
        let find = |s: &[u8]| EMBEDDED.windows(s.len()).any(|w| w == s);
        assert!(find(b"mc_engine_step"));
        assert!(HEADER.contains("mc_engine_step"));
    }
}
