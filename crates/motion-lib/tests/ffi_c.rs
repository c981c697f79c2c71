//! Builds the C programs in tests/c (power_move.c, block_frames.c) with the system C
//! compiler (-std=c99 -Wall -Wextra -Werror)
//! against include/motion_lib.h and the crate's staticlib and runs them: MC_Power +
//! MC_MoveAbsolute to Done, then every kind of block frame of the C ABI.
//!
//! Finding the staticlib: `cargo test` compiles the library with all its crate types, so
//! the staticlib of the current sources is the newest `libmotion_lib*.a` in the profile's
//! `deps` directory (target/<profile>/deps, next to this test's executable; cargo does not
//! copy it up to target/<profile>/ for `cargo test`). If there is none (another runner),
//! the test builds it with `cargo build -p motion-lib --lib` into the same target
//! directory.

use std::path::{Path, PathBuf};
use std::process::Command;

fn newest_staticlib(deps: &Path) -> Option<PathBuf> {
    std::fs::read_dir(deps)
        .ok()?
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("libmotion_lib") && n.ends_with(".a"))
        })
        .max_by_key(|p| p.metadata().and_then(|m| m.modified()).ok())
}

fn staticlib() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    let deps = exe.parent().unwrap();
    if let Some(lib) = newest_staticlib(deps) {
        return lib;
    }
    let profile_dir = deps.parent().unwrap();
    let target = profile_dir.parent().unwrap();
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let st = Command::new(cargo)
        .args(["build", "-p", "motion-lib", "--lib"])
        .env("CARGO_TARGET_DIR", target)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .status()
        .unwrap();
    assert!(st.success());
    target.join("debug/libmotion_lib.a")
}

/// Compiles tests/c/`name`.c against the header and the staticlib, runs it and returns
/// its standard output (the test fails when it does not compile or exits non-zero).
fn build_and_run(name: &str) -> String {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lib = staticlib();
    assert!(lib.exists(), "{} missing", lib.display());
    let tmp = std::env::temp_dir().join(format!("motion_lib_c_{name}_{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    let exe = tmp.join(name);
    let out = Command::new("cc")
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror"])
        .arg("-I")
        .arg(dir.join("include"))
        .arg(dir.join(format!("tests/c/{name}.c")))
        .arg(&lib)
        .args(["-lpthread", "-ldl", "-lm", "-o"])
        .arg(&exe)
        .output()
        .expect("system cc runs");
    assert!(
        out.status.success(),
        "cc failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let run = Command::new(&exe).output().unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout).into_owned();
    assert!(
        run.status.success(),
        "C program failed ({:?}): {}{}",
        run.status,
        stdout,
        String::from_utf8_lossy(&run.stderr)
    );
    let _ = std::fs::remove_dir_all(&tmp);
    stdout
}

#[test]
fn c_program_powers_and_moves_to_done() {
    let stdout = build_and_run("power_move");
    assert!(stdout.starts_with("Done after "), "{stdout}");
    assert!(stdout.contains("at 250.000000"), "{stdout}");
}

/// tests/c/block_frames.c: every kind of block frame through the C ABI (Execute-type
/// with Done and with InVelocity, MC_Stop and MC_GroupStop holding, immediate, Enable),
/// refused enumerations, CircMode RADIUS and the transition modes.
#[test]
fn c_program_drives_every_block_frame() {
    let stdout = build_and_run("block_frames");
    assert_eq!(stdout.trim(), "frames ok");
}

/// tests/c/abi_contract.c: the ABI version, every struct's size on both sides, the status codes for NULL
/// and invalid handles and arguments and bad indices, and the panic guard.
#[test]
fn c_program_checks_the_abi_contract() {
    let stdout = build_and_run("abi_contract");
    let header =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("include/motion_lib.h"))
            .unwrap();
    // Every struct of the header is size-checked by the C program.
    let structs: Vec<&str> = header
        .split("typedef struct ")
        .skip(1)
        .filter_map(|t| t.split_whitespace().next())
        .filter(|n| n.starts_with("MC_") && n.ends_with("_C"))
        .collect();
    let c = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/c/abi_contract.c"),
    )
    .unwrap();
    for s in &structs {
        assert!(
            c.contains(&format!("SIZE({s})")),
            "abi_contract.c does not check {s}"
        );
    }
    assert_eq!(
        stdout.trim(),
        format!("abi ok, {} struct sizes", structs.len())
    );
}
