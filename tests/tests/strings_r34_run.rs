//! Round 34: the length of a STRING/WSTRING declared without one (the target profile's
//! `default_string_length`: 80 by default, as CODESYS and TwinCAT, 126 under `--profile openplc`,
//! as matiec's `STR_MAX_LEN`), and W1468 at a `STRING(n)` declared longer than the 254 characters
//! every string holds (README, memory model).

mod common;
use common::*;

/// An 80-character text and CONCATs of it into an unsized STRING, a FUNCTION result of type STRING,
/// a WSTRING and an explicit STRING(80).
const DEFAULT_LENGTHS: &str = "FUNCTION F : STRING
VAR_INPUT a : STRING; END_VAR
F := CONCAT(a, 'xyz');
END_FUNCTION

PROGRAM P
VAR
    s : STRING; x : STRING; y : STRING(80); r : STRING; w : WSTRING; z : STRING(200);
    n1, n2, n3, n4, n5, n6 : INT;
END_VAR
s := '12345678901234567890123456789012345678901234567890123456789012345678901234567890';
x := CONCAT(s, 'abc');  n1 := LEN(x);
r := F(s);              n2 := LEN(r);
w := WCONCAT(\"12345678901234567890123456789012345678901234567890\", \"12345678901234567890123456789012345678901234567890\");
n3 := WLEN(w);
y := CONCAT(s, 'abc');  n4 := LEN(y);
z := CONCAT(s, CONCAT(s, 'abc')); n5 := LEN(z);
s := CONCAT(s, s);      n6 := LEN(s);
END_PROGRAM
";

/// A STRING, a FUNCTION result of type STRING and a WSTRING declared without a length hold 80
/// characters (TwinCAT 3 manual, STRING/WSTRING: "If no size is specified, 80 bytes are reserved by
/// default"; CODESYS likewise; IEC 61131-3 ed. 3 leaves the default to the implementation), cut
/// like an explicit STRING(80); a STRING(200) holds 163. Before: 83, 83, 100 (254 characters).
#[test]
fn unsized_strings_hold_80_characters_by_default() {
    let (trace, stderr) = run_text(
        "default_len.st",
        DEFAULT_LENGTHS,
        2,
        "P.n1,P.n2,P.n3,P.n4,P.n5,P.n6",
    );
    for (name, want) in [
        ("P.n1", 80.0),
        ("P.n2", 80.0),
        ("P.n3", 80.0),
        ("P.n4", 80.0),
        ("P.n5", 163.0),
        ("P.n6", 80.0),
    ] {
        assert_eq!(column(&trace, name), vec![want, want], "{name}: {trace}");
    }
    assert!(stderr.contains("runtime: string truncated"), "{stderr}");
}

/// Under `--profile openplc` an unsized STRING holds 126 characters, matiec's `STR_MAX_LEN`
/// (`lib/C/iec_types.h`), so 83 and 100 characters fit and 160 are cut to 126. Before: 254.
#[test]
fn unsized_strings_hold_matiec_length_under_openplc() {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "p.st", DEFAULT_LENGTHS);
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "p.st",
            "--profile",
            "openplc",
            "--cycles",
            "1",
            "--trace",
            "-",
            "--watch",
            "P.n1,P.n2,P.n3,P.n4,P.n5,P.n6",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    for (name, want) in [
        ("P.n1", 83.0),
        ("P.n2", 83.0),
        ("P.n3", 100.0),
        ("P.n4", 80.0),
        ("P.n5", 163.0),
        ("P.n6", 126.0),
    ] {
        assert_eq!(column(&trace, name), vec![want], "{name}: {trace}");
    }
}

/// A profile file may set `default_string_length`; a value beyond the 254-character capacity is
/// refused when the profile is read.
#[test]
fn a_profile_sets_the_default_string_length() {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "p.st", DEFAULT_LENGTHS);
    let profile = |len: u32| {
        format!(
            "{{\"name\": \"short\", \"input_bytes\": 256, \"output_bytes\": 256, \"memory_bytes\": 4096,
              \"byte_order\": \"little\", \"bit_numbering\": \"lsb0\", \"address_unit\": \"element\",
              \"tm_offset\": 3840, \"tm_bytes\": 256, \"alignment\": 1, \"default_string_length\": {len}}}"
        )
    };
    write_in(dir.path(), "short.json", &profile(10));
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "p.st",
            "--profile",
            "short.json",
            "--cycles",
            "1",
            "--trace",
            "-",
            "--watch",
            "P.n1,P.n2,P.n4",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&trace, "P.n1"), vec![10.0], "{trace}");
    assert_eq!(column(&trace, "P.n2"), vec![10.0], "{trace}");
    // `s` holds 10 characters, so the STRING(80) gets 13
    assert_eq!(column(&trace, "P.n4"), vec![13.0], "{trace}");
    write_in(dir.path(), "long.json", &profile(300));
    let (code, _, stderr) = in_dir(dir.path(), &["check", "p.st", "--profile", "long.json"]);
    assert_ne!(code, Some(0), "{stderr}");
    assert!(
        stderr.contains("default_string_length must be between 1 and 254"),
        "{stderr}"
    );
}

/// `STRING(400)` and `WSTRING(511)` (TwinCAT accepts them) hold 254 characters in ladderc's memory
/// model: one W1468 at each declaration's type, none at `STRING(254)`; the run cuts a 300-character
/// text to 254. Before: `check` said nothing.
#[test]
fn string_declared_beyond_capacity_is_w1468_at_the_declaration() {
    let long = "x".repeat(300);
    let src = format!(
        "PROGRAM P
VAR
    s : STRING(400);
    w : WSTRING(511);
    ok : STRING(254);
    n : INT;
END_VAR
s := '{long}';
n := LEN(s);
END_PROGRAM
"
    );
    let (code, lines) = check_text("long.st", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0]
            .starts_with("long.st:3:9: warning[W1468]: `STRING(400)` holds at most 254 characters"),
        "{lines:?}"
    );
    assert!(
        lines[1].starts_with(
            "long.st:4:9: warning[W1468]: `WSTRING(511)` holds at most 254 characters"
        ),
        "{lines:?}"
    );
    let (trace, _) = run_text("long.st", &src, 1, "P.n");
    assert_eq!(column(&trace, "P.n"), vec![254.0], "{trace}");
}
