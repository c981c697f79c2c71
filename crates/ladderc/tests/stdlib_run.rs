//! The IEC string functions through the whole `ladderc` pipeline: an FBD program (fixture
//! `fbd_strings.xml`: CONCAT, LEN, MID, RIGHT, REPLACE blocks) built with sanitizers and run cycle by
//! cycle, and the matiec STD_TEST corpus file (15), whose string blocks are all known now.

use std::path::{Path, PathBuf};
use std::process::Command;

fn ladderc() -> Command {
    Command::new(env!("CARGO_BIN_EXE_ladderc"))
}

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures")
        .join(name)
}

fn corpus(rel: &str) -> PathBuf {
    let here = Path::new(env!("CARGO_MANIFEST_DIR"));
    for dir in here.ancestors() {
        let p = dir.join("shared/corpus").join(rel);
        if p.exists() {
            return p;
        }
    }
    panic!("corpus file {rel} not found above {}", here.display());
}

#[test]
fn fbd_string_blocks_run_cycle_by_cycle_with_truncation() {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "0,main.A,abcd\n0,main.B,xyz\n0,main.N,2\n1,main.N,4\n2,main.A,hello\n3,main.N,-1\n",
    )
    .unwrap();
    let trace = dir.path().join("trace.csv");
    let out = ladderc()
        .arg("run")
        .arg(fixture("fbd_strings.xml"))
        .args(["--cycles", "4", "--sanitize", "--stimulus"])
        .arg(&stim)
        .arg("--trace")
        .arg(&trace)
        .args([
            "--watch",
            "main.JOINED,main.LENGTH,main.MIDDLE,main.TAIL,main.SWAPPED",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let text = std::fs::read_to_string(&trace).unwrap();
    // JOINED is STRING[6]: CONCAT(A, '-', B) truncated; LENGTH = LEN of the untruncated CONCAT;
    // MIDDLE = MID(A, 2, N); TAIL = RIGHT(B, N); SWAPPED = REPLACE(A, B, 2, N); N = -1 is out of range
    // (MID gives '', RIGHT gives '', REPLACE gives A unchanged).
    assert_eq!(
        text,
        "cycle,time_ms,main.JOINED,main.LENGTH,main.MIDDLE,main.TAIL,main.SWAPPED\n\
         0,0,\"abcd-x\",8,\"bc\",\"yz\",\"axyzd\"\n\
         1,10,\"abcd-x\",8,\"d\",\"xyz\",\"abcxyz\"\n\
         2,20,\"hello-\",9,\"lo\",\"xyz\",\"helxyz\"\n\
         3,30,\"hello-\",9,\"\",\"\",\"hello\"\n"
    );
    assert!(stderr.contains("runtime: string truncated"), "{stderr}");
    assert!(
        stderr.contains("runtime: string length or position out of range"),
        "{stderr}"
    );
}

/// Corpus file 15 uses CONCAT, LEN, MID, RIGHT, LEFT, INSERT, DELETE, REPLACE, FIND: none is unknown
/// any more. What `check` still reports is a genuine type error of the file: in TEST_FROM_STRINGS a
/// MUX mixes the INT results of LEN/FIND with the BOOL results of two EQ blocks (IEC 61131-3 has no
/// implicit BOOL to INT conversion).
#[test]
fn corpus_std_test_has_no_unknown_function_left() {
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(corpus("15_matiec_STD_TEST_tc6v1_fbd.xml"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].contains("error[E1005]: MUX of INT and BOOL"),
        "{stderr}"
    );
    assert!(!stderr.contains("E1019"), "{stderr}");
}

/// With the two EQ blocks of that MUX replaced by FIND (INT, same inputs) in a temporary copy, the whole
/// file checks clean.
#[test]
fn corpus_std_test_checks_clean_once_its_mux_is_well_typed() {
    let text = std::fs::read_to_string(corpus("15_matiec_STD_TEST_tc6v1_fbd.xml")).unwrap();
    let mut patched = text.clone();
    for id in ["75", "76"] {
        let eq = format!(
            r#"<block localId="{id}" height="60" width="63" instanceName="" typeName="EQ">"#
        );
        assert_eq!(patched.matches(&eq).count(), 1, "block {id}");
        patched = patched.replace(&eq, &eq.replace("\"EQ\"", "\"FIND\""));
    }
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("std_test.xml");
    std::fs::write(&file, patched).unwrap();
    let out = ladderc().arg("check").arg(&file).output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
