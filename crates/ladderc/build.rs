//! Builds the motion library that generated programs link, so that an installed `ladderc` carries it.
//!
//! Input: the sources of `crates/motion-lib` (beside this crate) and cargo's build-script environment.
//! Output: `$OUT_DIR/libmotion_lib.a`, a RELEASE static library of motion-lib for `$TARGET` (fat LTO, one
//! codegen unit, opt-level "s", panic=unwind because every C entry point catches panics), which
//! `src/motion_link.rs` embeds with `include_bytes!`; with the `rust-src` component installed, std is
//! rebuilt for it without the backtrace symbolizer (`-Zbuild-std`, about 170 KB smaller; opt out with
//! `LADDERC_MOTION_LIB_FULL_STD=1`). `LADDERC_MOTION_LIB_STD` (a compile-time env of the crate) says which:
//! `trimmed`, `full`, `prebuilt` or `none` (the clippy placeholder).
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
        println!("cargo:rustc-env=LADDERC_MOTION_LIB_STD=prebuilt");
        return;
    }
    // `cargo clippy` only checks (it links no executable) in a build-script folder of its own: it gets an
    // empty placeholder instead of a second release build; an executable holding the placeholder would
    // report E9050 (see motion_link::library).
    println!("cargo:rerun-if-env-changed=RUSTC_WORKSPACE_WRAPPER");
    if std::env::var("RUSTC_WORKSPACE_WRAPPER").is_ok_and(|w| w.contains("clippy-driver")) {
        copy_bytes_if_changed(b"", &dest);
        println!("cargo:rustc-env=LADDERC_MOTION_LIB_STD=none");
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
    let built = target_dir
        .join(&target)
        .join("release")
        .join("libmotion_lib.a");
    // First choice: std rebuilt from `rust-src` without its backtrace symbolizer (about 170 KB of gimli,
    // addr2line and miniz_oxide that std's default panic hook keeps reachable), still with panic=unwind so
    // that every C entry point can catch a panic. Then the prebuilt std. Which one was used is recorded in
    // LADDERC_MOTION_LIB_STD ("trimmed" or "full") for `--report json`.
    println!("cargo:rerun-if-env-changed=LADDERC_MOTION_LIB_FULL_STD");
    let full_std_asked = std::env::var_os("LADDERC_MOTION_LIB_FULL_STD").is_some_and(|v| v == "1");
    let std_src = rust_src_std();
    if let Some(src) = &std_src {
        // rerun when rust-src is updated (a missing component is not watched: a watched missing path
        // would rerun this script, and rebuild ladderc, on every build)
        println!("cargo:rerun-if-changed={}", src.display());
    }
    let mut mode = "full";
    if !full_std_asked && std_src.is_some() {
        // offline first (std's own dependencies are usually in the local registry cache), then online
        for offline in [true, false] {
            if nested_build(&motion, &target, &target_dir, true, offline) {
                mode = "trimmed";
                break;
            }
        }
        if mode != "trimmed" {
            println!(
                "cargo:warning=the motion library was built with the prebuilt std (about 170 KB larger): \
                 the build with std from rust-src failed"
            );
        }
    }
    if mode == "full" {
        if std_src.is_none() && !full_std_asked {
            println!(
                "cargo:warning=rust-src is not installed: the motion library links the prebuilt std, with its \
                 backtrace symbolizer (about 170 KB); `rustup component add rust-src` and rebuild ladderc for \
                 the smaller library"
            );
        }
        assert!(
            nested_build(&motion, &target, &target_dir, false, true),
            "building the release motion library failed; set LADDERC_PREBUILT_MOTION_LIB to a prebuilt \
             libmotion_lib.a to skip this step"
        );
    }
    println!("cargo:rustc-env=LADDERC_MOTION_LIB_STD={mode}");
    copy_if_changed(&built, &dest);
}

/// `library/std/Cargo.toml` of the toolchain's `rust-src` component, if it is installed.
fn rust_src_std() -> Option<PathBuf> {
    let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
    let out = Command::new(rustc)
        .args(["--print", "sysroot"])
        .output()
        .ok()?;
    let sysroot = String::from_utf8(out.stdout).ok()?;
    let std = Path::new(sysroot.trim()).join("lib/rustlib/src/rust/library/std/Cargo.toml");
    std.is_file().then_some(std)
}

/// Builds motion-lib as a release static library (fat LTO, one codegen unit, opt-level "s", panic=unwind)
/// into `target_dir`; with `trimmed_std`, std is built from rust-src with the `panic-unwind` feature only
/// (`-Zbuild-std`, allowed on a stable toolchain by RUSTC_BOOTSTRAP for this nested build alone). Returns
/// whether it succeeded.
fn nested_build(
    motion: &Path,
    target: &str,
    target_dir: &Path,
    trimmed_std: bool,
    offline: bool,
) -> bool {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut cmd = Command::new(cargo);
    cmd.args(["rustc", "--lib", "--release", "--crate-type", "staticlib"]);
    if offline {
        cmd.arg("--offline");
    }
    cmd.arg("--manifest-path")
        .arg(motion.join("Cargo.toml"))
        .arg("--target")
        .arg(target)
        .arg("--target-dir")
        .arg(target_dir)
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
        ]);
    if trimmed_std {
        cmd.args([
            "-Zbuild-std=std,panic_unwind",
            "-Zbuild-std-features=panic-unwind",
        ])
        .env("RUSTC_BOOTSTRAP", "1");
    } else {
        cmd.env_remove("RUSTC_BOOTSTRAP");
    }
    // The outer build's wrappers (clippy-driver) and flags are not the library's.
    cmd.env_remove("RUSTC_WORKSPACE_WRAPPER")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env_remove("CARGO_TARGET_DIR")
        .env_remove("CARGO_BUILD_TARGET_DIR")
        .env("CARGO_BUILD_BUILD_DIR", target_dir)
        .env_remove("CARGO_BUILD_TARGET");
    cmd.status().is_ok_and(|s| s.success())
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
