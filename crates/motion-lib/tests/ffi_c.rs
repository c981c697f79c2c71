//! Builds tests/c/power_move.c with the system C compiler (-std=c99 -Wall -Wextra -Werror)
//! against include/motion_lib.h and the crate's staticlib, runs it, and expects
//! MC_Power + MC_MoveAbsolute to reach Done.
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

#[test]
fn c_program_powers_and_moves_to_done() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lib = staticlib();
    assert!(lib.exists(), "{} missing", lib.display());
    let tmp = std::env::temp_dir().join(format!("motion_lib_c_{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    let exe = tmp.join("power_move");
    let out = Command::new("cc")
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror"])
        .arg("-I")
        .arg(dir.join("include"))
        .arg(dir.join("tests/c/power_move.c"))
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
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "C program failed ({:?}): {}{}",
        run.status,
        stdout,
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(stdout.starts_with("Done after "), "{stdout}");
    assert!(stdout.contains("at 250.000000"), "{stdout}");
    let _ = std::fs::remove_dir_all(&tmp);
}
