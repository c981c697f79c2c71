//! Constructs of real projects that were still rejected or mishandled after issue #13's first rounds,
//! each closed end to end through `ladderc run` (traces checked cycle by cycle): partial access to bits
//! and bytes (`x.3`, `x.%X3`, `x.%B1`) in ST, IL, LD and FBD, and the others added below.

mod common;
use common::ladderc;

use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/lang_gaps")
        .join(name)
}

/// `ladderc run FILE --cycles N --sanitize --watch WATCH --trace -`: the trace (standard output)
/// and standard error; asserts exit 0.
fn run(file: &Path, cycles: u32, watch: &str) -> (String, String) {
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(file)
        .args([
            "--cycles",
            &cycles.to_string(),
            "--sanitize",
            "--trace",
            "-",
        ])
        .args(["--watch", watch])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("Sanitizer"), "{stderr}");
    (String::from_utf8_lossy(&out.stdout).into_owned(), stderr)
}

/// `ladderc check` of `src` written to `dir/name`: exit code and the diagnostic lines (short
/// format), with the temporary folder left out.
fn check_text(name: &str, src: &str) -> (Option<i32>, Vec<String>) {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join(name);
    std::fs::write(&f, src).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&f)
        .output()
        .unwrap();
    let prefix = format!("{}/", dir.path().display());
    let lines = String::from_utf8_lossy(&out.stderr)
        .lines()
        .filter(|l| l.contains("error[") || l.contains("warning["))
        .map(|l| l.replace(&prefix, ""))
        .collect();
    (out.status.code(), lines)
}

// ------------------------------------------------------------------ 1. partial access

#[test]
fn partial_access_reads_and_writes_bits_bytes_and_words_in_st_and_il() {
    // w = 16#0005: b0 = w.0 (1), b2 = w.%X2 (1); w.15 := TRUE, then w.0 toggles each cycle:
    // 16#8004, 16#8005, ...; n = -1 with bit 3 cleared is -9; hi = w.%B1 = 16#80; d.%W1 := w puts w
    // in the high word; q AT %QW0: q.1 := w.0 (after the toggle) and q.%X4 := TRUE. IL: flags = 4:
    // seen := flags.2; flags.7 toggles; R flags.%X2 while seen
    let (trace, _) = run(
        &fixture("partial_access.st"),
        3,
        "main.w,main.b0,main.b2,main.n,main.hi,main.d,%QW0,il_side.flags,il_side.seen",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,main.w,main.b0,main.b2,main.n,main.hi,main.d,%QW0,il_side.flags,il_side.seen\n\
         0,0,32772,1,1,-9,128,2147745792,16,128,1\n\
         1,10,32773,0,1,-9,128,2147811328,18,0,0\n\
         2,20,32772,1,1,-9,128,2147745792,16,128,0\n"
    );
}

#[test]
fn partial_access_in_ld_contacts_coils_and_fbd_variables() {
    // LD: flags = 4; flags.5 := flags.2; S out.%X0 on flags.5; R flags.2 on out.0: cycle 0 ends with
    // flags = 16#20, then flags.2 is 0 so flags.5 drops: 0. FBD: bit3 := w.%X3 (w = 8), w.%B1 := 16#A5
    let (trace, _) = run(
        &fixture("partial_access.xml"),
        3,
        "ladder.flags,ladder.out,fbd.w,fbd.bit3",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,ladder.flags,ladder.out,fbd.w,fbd.bit3\n\
         0,0,32,1,42248,1\n\
         1,10,0,1,42248,1\n\
         2,20,0,1,42248,1\n"
    );
}

#[test]
fn partial_access_out_of_range_or_without_bits_is_one_located_e1029_each() {
    let src = "PROGRAM main\nVAR\n w : WORD;\n b : BOOL;\n r : REAL;\n bb : BYTE;\nEND_VAR\n \
               w.16 := TRUE;\n bb := w.%B2;\n r.0 := TRUE;\n b := b.0;\n w.99999999999 := b;\n\
               END_PROGRAM\n";
    let (code, lines) = check_text("bad.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        vec![
            "bad.st:8:4: error[E1029]: `w.16` is out of range: WORD has bits 0 to 15 (hint: WORD has 16 bits, numbered 0 (the least significant) to 15)",
            "bad.st:9:10: error[E1029]: `w.%B2` is out of range: WORD has bytes 0 to 1 (hint: WORD has 16 bits, numbered 0 (the least significant) to 15)",
            "bad.st:10:4: error[E1029]: `r` is REAL, which has no bits to access with `.0` (hint: partial access (`x.3`, `x.%X3`, `x.%B1`) works on integers and BYTE, WORD, DWORD, LWORD)",
            "bad.st:11:9: error[E1029]: `b` is BOOL, which has no bits to access with `.0` (hint: partial access (`x.3`, `x.%X3`, `x.%B1`) works on integers and BYTE, WORD, DWORD, LWORD)",
            "bad.st:12:4: error[E1029]: `w.99999999999` is out of range: WORD has bits 0 to 15 (hint: WORD has 16 bits, numbered 0 (the least significant) to 15)",
        ]
    );
    // the same in IL: one error at the access
    let il = "PROGRAM main\nVAR\n w : WORD;\nEND_VAR\n LD w.%X16\n ST w.0\nEND_PROGRAM\n";
    let (code, lines) = check_text("bad.il", il);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("bad.il:5:7: error[E1029]"),
        "{lines:?}"
    );
}

// ------------------------------------------------------------------ 2. keyword names in XML IL bodies

#[test]
fn keyword_named_variables_in_an_xml_il_body_are_one_e1031_at_each_declaration() {
    // `on` and `task` are IL keywords: the body's `LD on`, `ST task` were E0011 at every use; now,
    // as in an .il file, the reserved names are reported once, at their declarations, with the POU
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture("keyword_names_il.xml"))
        .args(["--cycles", "1"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 2, "{stderr}");
    assert!(
        errors[0].ends_with("keyword_names_il.xml:10:25: error[E1031]: `on` is reserved in IEC 61131-3 (a keyword): it cannot name a variable [POU `main`] (hint: rename the variable, for example `xon`)"),
        "{stderr}"
    );
    assert!(
        errors[1].contains("keyword_names_il.xml:11:25: error[E1031]: `task` is reserved"),
        "{stderr}"
    );
}
