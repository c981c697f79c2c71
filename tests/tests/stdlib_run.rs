//! The IEC string functions through the whole `ladderc` pipeline: an FBD program (fixture
//! `fbd_strings.xml`: CONCAT, LEN, MID, RIGHT, REPLACE blocks) built with sanitizers and run cycle by
//! cycle, and the matiec STD_TEST corpus file (15), whose string blocks are all known now.

mod common;
use common::ladderc;

use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures")
        .join(name)
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
    let Some(file) = common::corpus_file("15_matiec_STD_TEST_tc6v1_fbd.xml") else {
        return;
    };
    let (_, stderr) = common::check_stderr(&file);
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].contains("error[E1005]: MUX of INT and BOOL"),
        "{stderr}"
    );
    assert!(!stderr.contains("E1019"), "{stderr}");
}

/// Corpus file 15 with the two EQ blocks of that MUX replaced by FIND (INT, same inputs), in a temporary
/// copy; `None` when the corpus is not configured (skipped).
fn std_test_well_typed() -> Option<String> {
    let file = common::corpus_file("15_matiec_STD_TEST_tc6v1_fbd.xml")?;
    let mut patched = std::fs::read_to_string(file).unwrap();
    for id in ["75", "76"] {
        let eq = format!(
            r#"<block localId="{id}" height="60" width="63" instanceName="" typeName="EQ">"#
        );
        assert_eq!(patched.matches(&eq).count(), 1, "block {id}");
        patched = patched.replace(&eq, &eq.replace("\"EQ\"", "\"FIND\""));
    }
    Some(patched)
}

/// With its MUX well typed, the file's only errors are what `build` also rejects: its located STRING
/// outputs (E2005, the C backend's memory model; `check` runs every check of `build`, issue #13.7); without
/// their addresses it checks clean.
#[test]
fn corpus_std_test_checks_clean_once_its_mux_is_well_typed() {
    let Some(text) = std_test_well_typed() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("std_test.xml");
    std::fs::write(&file, &text).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert!(!errors.is_empty());
    assert!(
        errors.iter().all(|l| l.contains("error[E2005]")),
        "{stderr}"
    );
    let mut text = text;
    for a in [
        "%QB0", "%QW1", "%IW0", "%QB3", "%QB4", "%QX7", "%QB10", "%QB2",
    ] {
        text = text.replace(&format!(r#" address="{a}""#), "");
    }
    std::fs::write(&file, text).unwrap();
    let out = ladderc().arg("check").arg(&file).output().unwrap();
    common::assert_ok(&out);
}

/// And it runs: MAIN_TEST steps TEST_NB through the tests of TEST_STRINGS_OPS (IN1 = '3.456789',
/// IN2 = '456', IN3 = 'abcdefgh', L = 3, P = 2), one per cycle. Its outputs are located STRINGs
/// (`RES_TO_STR AT %QB0 : STRING`, overlapping `RES_FROM_STR AT %QW1`), which the C backend's memory
/// model does not place (E2005), so the copy drops the `address` attributes.
#[test]
fn corpus_std_test_string_operations_run_cycle_by_cycle() {
    let Some(mut text) = std_test_well_typed() else {
        return;
    };
    for a in [
        "%QB0", "%QW1", "%IW0", "%QB3", "%QB4", "%QX7", "%QB10", "%QB2",
    ] {
        let attr = format!(r#" address="{a}""#);
        assert_eq!(text.matches(&attr).count(), 1, "{a}");
        text = text.replace(&attr, "");
    }
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("std_test.xml");
    std::fs::write(&file, text).unwrap();
    let trace = dir.path().join("trace.csv");
    let out = ladderc()
        .arg("run")
        .arg(&file)
        .args(["--cycles", "10", "--sanitize", "--trace"])
        .arg(&trace)
        .args([
            "--watch",
            "MAIN_INSTANCE.TEST_NB,MAIN_INSTANCE.STR_OPS_TEST_NAME,MAIN_INSTANCE.RES_STR_OPS,\
             MAIN_INSTANCE.RES_FROM_STR",
        ])
        .output()
        .unwrap();
    common::assert_ok(&out);
    let text = std::fs::read_to_string(&trace).unwrap();
    assert_eq!(
        text,
        "cycle,time_ms,MAIN_INSTANCE.TEST_NB,MAIN_INSTANCE.STR_OPS_TEST_NAME,\
         MAIN_INSTANCE.RES_STR_OPS,MAIN_INSTANCE.RES_FROM_STR\n\
         0,0,1,\"TEST_STRING_OPS : IN1\",\"3.456789\",8\n\
         1,10,2,\"TEST_STRING_OPS : IN2\",\"456\",3\n\
         2,20,3,\"TEST_STRING_OPS : IN3\",\"abcdefgh\",1\n\
         3,30,4,\"TEST_STRING_OPS : LEFT\",\"3.4\",3\n\
         4,40,5,\"TEST_STRING_OPS : RIGHT\",\"789\",3\n\
         5,50,6,\"TEST_STRING_OPS : MID\",\".45\",3\n\
         6,60,7,\"TEST_STRING_OPS : CONCAT\",\"3.456789456abcdefgh\",3\n\
         7,70,8,\"TEST_STRING_OPS : INSERT\",\"3.456456789\",3\n\
         8,80,9,\"TEST_STRING_OPS : DELETE\",\"36789\",3\n\
         9,90,10,\"TEST_STRING_OPS : REPLACE\",\"34566789\",3\n"
    );
}

/// FBD blocks of the typed counters and the named time functions (fixture `fbd_typed_counter.xml`:
/// CTU_UDINT with PV 2, MUL_TIME(T, 2)); the same with the 3rd edition's `CTU_INT` (= CTU).
#[test]
fn fbd_typed_counter_and_mul_time_blocks_run() {
    let udint = fixture("fbd_typed_counter.xml");
    let dir = tempfile::tempdir().unwrap();
    let int = dir.path().join("fbd_ctu_int.xml");
    let text = std::fs::read_to_string(&udint).unwrap();
    assert!(text.contains("CTU_UDINT"));
    std::fs::write(
        &int,
        text.replace("CTU_UDINT", "CTU_INT").replace("UDINT", "INT"),
    )
    .unwrap();
    for project in [udint, int] {
        typed_counter_run(&project, dir.path());
    }
}

fn typed_counter_run(project: &std::path::Path, dir: &std::path::Path) {
    let stim = dir.join("stim.csv");
    std::fs::write(
        &stim,
        "0,main.T,T#250ms\n1,main.PULSE,1\n2,main.PULSE,0\n3,main.PULSE,1\n",
    )
    .unwrap();
    let trace = dir.join("trace.csv");
    let out = ladderc()
        .arg("run")
        .arg(project)
        .args(["--cycles", "5", "--sanitize", "--stimulus"])
        .arg(&stim)
        .arg("--trace")
        .arg(&trace)
        .args(["--watch", "main.COUNT,main.DONE,main.T2"])
        .output()
        .unwrap();
    common::assert_ok(&out);
    assert_eq!(
        std::fs::read_to_string(&trace).unwrap(),
        "cycle,time_ms,main.COUNT,main.DONE,main.T2\n\
         0,0,0,0,T#500ms\n\
         1,10,1,0,T#500ms\n\
         2,20,1,0,T#500ms\n\
         3,30,2,1,T#500ms\n\
         4,40,2,1,T#500ms\n"
    );
}
