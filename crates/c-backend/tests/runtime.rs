//! The C runtime on its own: tests/c/rt_test.c compiled against ladderc_rt.c with warnings as errors and
//! sanitizers, once per byte order / bit numbering.

use c_backend::{runtime, BitNumbering, ByteOrder, TargetProfile};
use std::process::Command;

fn run_c_tests(profile: &TargetProfile, expect_big: bool) {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (name, text) in runtime::files() {
        std::fs::write(d.join(name), text).unwrap();
    }
    std::fs::write(
        d.join("ladderc_config.h"),
        c_backend::config_header(profile),
    )
    .unwrap();
    let test = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/c/rt_test.c");
    let exe = d.join("rt_test");
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let out = Command::new(cc)
        .args([
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-pedantic",
            "-g",
            "-fsanitize=address,undefined",
            "-fno-sanitize-recover=all",
        ])
        .arg(format!("-DEXPECT_BIG={}", u8::from(expect_big)))
        .arg(format!("-I{}", d.display()))
        .arg("-o")
        .arg(&exe)
        .arg(test)
        .arg(d.join("ladderc_rt.c"))
        .arg("-lm")
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "compile failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let run = Command::new(&exe).output().unwrap();
    assert!(
        run.status.success(),
        "runtime checks failed:\n{}{}",
        String::from_utf8_lossy(&run.stdout),
        String::from_utf8_lossy(&run.stderr)
    );
    assert_eq!(String::from_utf8_lossy(&run.stdout), "runtime ok\n");
}

#[test]
fn runtime_checks_pass_little_endian_lsb0() {
    run_c_tests(&TargetProfile::default(), false);
}

#[test]
fn runtime_checks_pass_big_endian_msb0() {
    let p = TargetProfile {
        byte_order: ByteOrder::Big,
        bit_numbering: BitNumbering::Msb0,
        ..TargetProfile::default()
    };
    run_c_tests(&p, true);
}
