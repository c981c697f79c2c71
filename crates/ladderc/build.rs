//! Builds the motion library that generated programs link, so that an installed `ladderc` carries it.
//!
//! Input: the sources of `crates/motion-lib` (beside this crate) and cargo's build-script environment.
//! Output: `$OUT_DIR/libmotion_lib.a`, a RELEASE static library of motion-lib for `$TARGET` (fat LTO, one
//! codegen unit, opt-level "s", panic=unwind because every C entry point catches panics), which
//! `src/motion_link.rs` embeds with `include_bytes!`.
//! Invariants: the nested cargo uses its own target directory under `$OUT_DIR` (no lock shared with the
//! outer build, and incremental across builds); the script reruns only when motion-lib's sources,
//! manifest or the lock file change. `LADDERC_PREBUILT_MOTION_LIB=/path/libmotion_lib.a` skips the nested
//! build and embeds that archive instead (for packagers and offline cross builds).

use std::path::{Path, PathBuf};
use std::process::Command;

fn main() {
    let manifest_dir =
        PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets it"));
    let out_dir = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets it"));
    let motion = manifest_dir.join("../motion-lib");
    let dest = out_dir.join("libmotion_lib.a");
    println!("cargo:rerun-if-env-changed=LADDERC_PREBUILT_MOTION_LIB");
    if let Some(pre) = std::env::var_os("LADDERC_PREBUILT_MOTION_LIB").filter(|v| !v.is_empty()) {
        let pre = PathBuf::from(pre);
        println!("cargo:rerun-if-changed={}", pre.display());
        std::fs::copy(&pre, &dest)
            .unwrap_or_else(|e| panic!("LADDERC_PREBUILT_MOTION_LIB={}: {e}", pre.display()));
        return;
    }
    // `cargo clippy` only checks (it links no executable) in a build-script folder of its own: it gets an
    // empty placeholder instead of a second release build; an executable holding the placeholder would
    // report E9050 (see motion_link::library).
    println!("cargo:rerun-if-env-changed=RUSTC_WORKSPACE_WRAPPER");
    if std::env::var("RUSTC_WORKSPACE_WRAPPER").is_ok_and(|w| w.contains("clippy-driver")) {
        copy_bytes_if_changed(b"", &dest);
        return;
    }
    for watched in ["src", "Cargo.toml", "include"] {
        println!("cargo:rerun-if-changed={}", motion.join(watched).display());
    }
    let lock = manifest_dir.join("../../Cargo.lock");
    if lock.is_file() {
        println!("cargo:rerun-if-changed={}", lock.display());
    }
    let target = std::env::var("TARGET").expect("cargo sets it");
    let target_dir = out_dir.join("motion-lib-target");
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut cmd = Command::new(cargo);
    cmd.args([
        "rustc",
        "--lib",
        "--release",
        "--crate-type",
        "staticlib",
        "--offline",
    ])
    .arg("--manifest-path")
    .arg(motion.join("Cargo.toml"))
    .arg("--target")
    .arg(&target)
    .arg("--target-dir")
    .arg(&target_dir)
    .args([
        "--config",
        "profile.release.lto=true",
        "--config",
        "profile.release.codegen-units=1",
        "--config",
        "profile.release.opt-level=\"s\"",
        "--config",
        "profile.release.panic=\"unwind\"",
        "--config",
        "profile.release.debug=false",
        "--config",
        "profile.release.debug-assertions=false",
        "--config",
        "profile.release.overflow-checks=false",
    ])
    // The outer build's wrappers (clippy-driver) and flags are not the library's.
    .env_remove("RUSTC_WORKSPACE_WRAPPER")
    .env_remove("CARGO_ENCODED_RUSTFLAGS")
    .env_remove("CARGO_TARGET_DIR")
    .env_remove("CARGO_BUILD_TARGET_DIR")
    .env("CARGO_BUILD_BUILD_DIR", &target_dir)
    .env_remove("CARGO_BUILD_TARGET");
    let status = cmd
        .status()
        .unwrap_or_else(|e| panic!("cannot start cargo for motion-lib: {e}"));
    assert!(
        status.success(),
        "building the release motion library failed ({status}); set LADDERC_PREBUILT_MOTION_LIB to a \
         prebuilt libmotion_lib.a to skip this step"
    );
    let built = target_dir
        .join(&target)
        .join("release")
        .join("libmotion_lib.a");
    copy_if_changed(&built, &dest);
}

/// Copies `from` to `to` unless they already hold the same bytes (keeps `to`'s mtime, so that the
/// `include_bytes!` of an unchanged library does not recompile the crate).
fn copy_if_changed(from: &Path, to: &Path) {
    let new = std::fs::read(from).unwrap_or_else(|e| panic!("{}: {e}", from.display()));
    copy_bytes_if_changed(&new, to);
}

fn copy_bytes_if_changed(new: &[u8], to: &Path) {
    if std::fs::read(to).ok().as_deref() != Some(new) {
        std::fs::write(to, new).unwrap_or_else(|e| panic!("{}: {e}", to.display()));
    }
}
