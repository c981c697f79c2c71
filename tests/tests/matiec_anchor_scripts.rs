//! The matiec anchor scripts (scripts/build-matiec.sh, scripts/matiec-anchor.sh) without matiec:
//! input: the scripts run with bash and a controlled environment; output: their exit codes and messages.
//! Invariant: the anchor says so and exits 0 when there is no iec2c; the build needs MATIEC_SRC (exit 2).
use std::path::PathBuf;
use std::process::Command;

fn script(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../scripts")
        .join(name)
}

#[test]
fn anchor_without_iec2c_says_so_and_exits_0() {
    let out = Command::new("bash")
        .arg(script("matiec-anchor.sh"))
        .env("IEC2C", "/nonexistent/iec2c")
        .output()
        .expect("bash runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "stdout: {stdout}");
    assert!(
        stdout.contains("no iec2c at /nonexistent/iec2c; nothing measured"),
        "stdout: {stdout}"
    );
    assert!(
        stdout.contains("scripts/build-matiec.sh"),
        "stdout: {stdout}"
    );
}

#[test]
fn build_without_matiec_src_is_a_usage_error() {
    let empty = tempfile::tempdir().expect("temp dir");
    for src in [None, Some(empty.path())] {
        let mut cmd = Command::new("bash");
        cmd.arg(script("build-matiec.sh")).env_remove("MATIEC_SRC");
        if let Some(dir) = src {
            cmd.env("MATIEC_SRC", dir);
        }
        let out = cmd.output().expect("bash runs");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "stderr: {stderr}");
        assert!(
            stderr.contains("set MATIEC_SRC to a clone of https://github.com/beremiz/matiec"),
            "stderr: {stderr}"
        );
    }
}
