//! WSTRING end to end (issue #13): `"..."` literals, WSTRING variables and the string functions on
//! them, and every conversion of the sema catalogue that takes or gives a WSTRING, through
//! `ladderc run --sanitize`.
//!
//! The rules (crates/c-backend/README.md, "Semantics"): a STRING holds single-byte characters, ISO
//! 8859-1 (ladderc stores literals, `$E9` included, one byte per character and reads stimuli so);
//! `STRING_TO_WSTRING` makes each byte the character of its code, `WSTRING_TO_STRING` each character
//! U+0000-U+00FF its byte and any other `?` (a surrogate pair one `?`); `X_TO_WSTRING` is the text of `X_TO_STRING`, `WSTRING_TO_X`
//! reads the text as `STRING_TO_X` does.
//!
//! Two tables: every catalogue conversion against its STRING twin on the same inputs (the results must
//! be the same text or value), and explicit cases with their expected trace values.

mod common;

use il_frontend::sema::stdlib::{conversion, ConvTarget};
use il_frontend::sema::{Elementary, Type};
use std::collections::BTreeMap;

fn is_wide(t: &Type) -> bool {
    matches!(t, Type::String { wide: true, .. })
}

fn name_of(t: &Type) -> String {
    match t {
        Type::String { wide: false, .. } => "STRING".into(),
        Type::String { wide: true, .. } => "WSTRING".into(),
        t => t.elementary().expect("elementary").name().into(),
    }
}

/// Every `X_TO_WSTRING` and `WSTRING_TO_X` the catalogue accepts, as (name, from, to).
fn wide_conversions() -> Vec<(String, String, String)> {
    let mut names: Vec<String> = Elementary::ALL
        .iter()
        .map(|e| e.name().to_string())
        .collect();
    names.push("STRING".into());
    let mut out = Vec::new();
    for n in &names {
        for (a, b) in [(n.as_str(), "WSTRING"), ("WSTRING", n.as_str())] {
            let c = format!("{a}_TO_{b}");
            let Some(conv) = conversion(&c) else { continue };
            let ConvTarget::Fixed(to) = &conv.to else {
                continue;
            };
            let from = conv.from.as_ref().expect("a typed source");
            assert!(is_wide(from) || is_wide(to), "{c}");
            out.push((c, name_of(from), name_of(to)));
        }
    }
    out
}

/// ST literals of a source type (each a value `X_TO_STRING` prints exactly).
fn literals(ty: &str) -> Vec<String> {
    let l: &[&str] = match ty {
        "BOOL" => &["TRUE", "FALSE"],
        "SINT" => &["SINT#-128", "SINT#127"],
        "INT" => &["INT#-32768", "INT#1234"],
        "DINT" => &["DINT#-7", "DINT#2147483647"],
        "LINT" => &["LINT#-9223372036854775808", "LINT#42"],
        "USINT" | "BYTE" => &["255", "0"],
        "UINT" | "WORD" => &["65535", "7"],
        "UDINT" | "DWORD" => &["4294967295", "1"],
        "ULINT" | "LWORD" => &["18446744073709551615", "100"],
        "REAL" => &["REAL#2.5", "REAL#-0.1"],
        "LREAL" => &["LREAL#1.0E300", "LREAL#-3.25"],
        "TIME" => &["T#1500ms", "T#-2s"],
        "LTIME" => &["LTIME#1ms500us", "LTIME#0ms"],
        "DATE" => &["D#2024-01-31", "D#1970-01-01"],
        "TOD" => &["TOD#12:30:00.5", "TOD#00:00:00"],
        "DT" => &["DT#2024-01-31-12:30:00", "DT#1969-12-31-23:00:00"],
        "LDATE" => &["LDATE#2024-01-31", "LDATE#1970-01-01"],
        "LTOD" => &["LTOD#12:30:00.000000005", "LTOD#00:00:00"],
        "LDT" => &["LDT#2024-01-31-12:30:00", "LDT#1969-12-31-23:00:00"],
        "STRING" => &["'abc'", "''"],
        // edition 3's characters (a WCHAR beyond U+00FF is `?` in a STRING: not its twin)
        "CHAR" => &["'A'", "CHAR#'$FF'"],
        "WCHAR" => &["\"A\"", "WCHAR#\"$00E9\""],
        other => panic!("no literals for {other}"),
    };
    l.iter().map(|s| s.to_string()).collect()
}

/// Texts read by `WSTRING_TO_X` (and `STRING_TO_X` for the twin).
const TEXTS: &[&str] = &[
    "42",
    " -7 ",
    "300",
    "abc",
    "2.5",
    "TRUE",
    "T#1s500ms",
    "D#2024-01-31",
    "TOD#12:30:00.5",
    "DT#2024-01-31-12:30:00",
    "LDT#2024-01-31-12:30:00",
    "",
];

fn run_st(dir: &std::path::Path, src: &str) -> BTreeMap<String, String> {
    common::run_one_scan(dir, "w.st", src).0
}

/// Every WSTRING conversion of the catalogue gives what its STRING twin gives, on the same inputs.
#[test]
fn every_wstring_conversion_matches_its_string_twin() {
    let convs = wide_conversions();
    // every elementary type and STRING, both directions (STRING_TO_WSTRING, WSTRING_TO_STRING once each)
    assert!(convs.len() >= 38, "{convs:?}");
    let mut decl = String::new();
    let mut body = String::new();
    let mut pairs = Vec::new();
    for (c, (name, from, to)) in convs.iter().enumerate() {
        if to == "WSTRING" {
            // X_TO_WSTRING(x) against X_TO_STRING(x); STRING_TO_WSTRING against the identity
            for (k, lit) in literals(from).iter().enumerate() {
                decl.push_str(&format!("  w{c}_{k} : WSTRING;\n  s{c}_{k} : STRING;\n"));
                body.push_str(&format!("  w{c}_{k} := {name}({lit});\n"));
                if from == "STRING" {
                    body.push_str(&format!("  s{c}_{k} := {lit};\n"));
                } else {
                    body.push_str(&format!("  s{c}_{k} := {from}_TO_STRING({lit});\n"));
                }
                pairs.push((format!("w{c}_{k}"), format!("s{c}_{k}"), name.clone()));
            }
        } else {
            // WSTRING_TO_X(w) against STRING_TO_X(s) on the same text
            for (k, t) in TEXTS.iter().enumerate() {
                decl.push_str(&format!("  w{c}_{k} : {to};\n  s{c}_{k} : {to};\n"));
                if to == "STRING" {
                    body.push_str(&format!("  w{c}_{k} := {name}(\"{t}\");\n"));
                    body.push_str(&format!("  s{c}_{k} := '{t}';\n"));
                } else {
                    body.push_str(&format!("  w{c}_{k} := {name}(\"{t}\");\n"));
                    body.push_str(&format!("  s{c}_{k} := STRING_TO_{to}('{t}');\n"));
                }
                pairs.push((
                    format!("w{c}_{k}"),
                    format!("s{c}_{k}"),
                    format!("{name}({t:?})"),
                ));
            }
        }
    }
    let src = format!("PROGRAM main\nVAR\n{decl}END_VAR\n{body}END_PROGRAM\n");
    let dir = tempfile::tempdir().unwrap();
    let col = run_st(dir.path(), &src);
    let mut failures = Vec::new();
    for (w, s, what) in &pairs {
        let (gw, gs) = (&col[&format!("main.{w}")], &col[&format!("main.{s}")]);
        if gw != gs {
            failures.push(format!("{what}: WSTRING gives {gw}, STRING gives {gs}"));
        }
    }
    assert!(pairs.len() > 150, "{} pairs", pairs.len());
    assert!(
        failures.is_empty(),
        "{} of {} differ:\n{}",
        failures.len(),
        pairs.len(),
        failures.join("\n")
    );
}

/// Explicit cases: literals with characters beyond Latin-1 and beyond the BMP, the string functions
/// on WSTRING, the narrowing rule and capacities.
#[test]
fn wstring_literals_functions_and_narrowing_give_the_iec_values() {
    let cases: &[(&str, &str, &str)] = &[
        // (type, expression, expected trace value)
        (
            "WSTRING",
            "\"h\u{e9}llo \u{4e16}\u{754c}\"",
            "\"h\u{e9}llo \u{4e16}\u{754c}\"",
        ),
        ("INT", "LEN(\"h\u{e9}llo \u{4e16}\u{754c}\")", "8"),
        // a character outside the BMP is two UTF-16 code units
        ("INT", "LEN(\"a\u{1f600}\")", "3"),
        (
            "WSTRING",
            "CONCAT(\"ab\", \"\u{3b1}\u{3b2}\", \"c\")",
            "\"ab\u{3b1}\u{3b2}c\"",
        ),
        (
            "WSTRING",
            "LEFT(\"\u{3b1}\u{3b2}\u{3b3}\", 2)",
            "\"\u{3b1}\u{3b2}\"",
        ),
        (
            "WSTRING",
            "RIGHT(\"\u{3b1}\u{3b2}\u{3b3}\", 1)",
            "\"\u{3b3}\"",
        ),
        (
            "WSTRING",
            "MID(\"\u{3b1}\u{3b2}\u{3b3}\u{3b4}\", 2, 2)",
            "\"\u{3b2}\u{3b3}\"",
        ),
        (
            "WSTRING",
            "INSERT(\"\u{3b1}\u{3b3}\", \"\u{3b2}\", 1)",
            "\"\u{3b1}\u{3b2}\u{3b3}\"",
        ),
        (
            "WSTRING",
            "DELETE(\"\u{3b1}\u{3b2}\u{3b3}\", 1, 2)",
            "\"\u{3b1}\u{3b3}\"",
        ),
        (
            "WSTRING",
            "REPLACE(\"\u{3b1}\u{3b2}\u{3b3}\", \"xy\", 1, 3)",
            "\"\u{3b1}\u{3b2}xy\"",
        ),
        ("INT", "FIND(\"\u{3b1}\u{3b2}\u{3b3}\", \"\u{3b3}\")", "3"),
        ("INT", "FIND(\"\u{3b1}\u{3b2}\u{3b3}\", \"z\")", "0"),
        ("BOOL", "\"\u{3b1}\" > \"z\"", "1"),
        ("WSTRING", "MAX(\"a\", \"\u{3b1}\", \"b\")", "\"\u{3b1}\""),
        // to STRING: one byte per character U+0000-U+00FF (LEN counts them), `?` for any other (a
        // surrogate pair is one character)
        ("STRING", "WSTRING_TO_STRING(\"abc\")", "\"abc\""),
        ("INT", "LEN(WSTRING_TO_STRING(\"caf\u{e9}\"))", "4"),
        ("STRING", "WSTRING_TO_STRING(\"\u{3b1}=1\")", "\"?=1\""),
        ("STRING", "WSTRING_TO_STRING(\"x\u{1f600}y\")", "\"x?y\""),
        ("INT", "LEN(WSTRING_TO_STRING(\"x\u{1f600}y\"))", "3"),
        // to WSTRING: each byte is the character of its code ($E9 is U+00E9 in a STRING literal)
        ("WSTRING", "STRING_TO_WSTRING('caf$E9')", "\"caf\u{e9}\""),
        ("INT", "LEN(STRING_TO_WSTRING('caf$E9'))", "4"),
        ("INT", "LEN(STRING_TO_WSTRING('$FF$01'))", "2"),
        ("INT", "LEN(STRING_TO_WSTRING('Gr\u{fc}\u{df}e'))", "5"),
        (
            "WSTRING",
            "WSTRING_TO_WSTRING(STRING_TO_WSTRING(WSTRING_TO_STRING(\"\u{4e16}\u{e9}\")))",
            "\"?\u{e9}\"",
        ),
        ("WSTRING", "STRING_TO_WSTRING('')", "\"\""),
        // numbers and times to WSTRING and back
        ("WSTRING", "INT_TO_WSTRING(-32768)", "\"-32768\""),
        ("WSTRING", "REAL_TO_WSTRING(2.5)", "\"2.5\""),
        ("WSTRING", "TIME_TO_WSTRING(T#1m30s)", "\"T#90000ms\""),
        ("WSTRING", "BOOL_TO_WSTRING(TRUE)", "\"TRUE\""),
        ("DINT", "WSTRING_TO_DINT(\" -7 \")", "-7"),
        ("INT", "WSTRING_TO_INT(\"\u{3b1}\")", "0"),
        ("LREAL", "WSTRING_TO_LREAL(\"2.5\")", "2.5"),
        ("TIME", "WSTRING_TO_TIME(\"T#2s\")", "T#2000ms"),
        ("BOOL", "WSTRING_TO_BOOL(\"TRUE\")", "1"),
        // capacity of the destination applies when the value is stored
        (
            "WSTRING[3]",
            "\"\u{3b1}\u{3b2}\u{3b3}\u{3b4}\"",
            "\"\u{3b1}\u{3b2}\u{3b3}\"",
        ),
    ];
    let mut decl = String::new();
    let mut body = String::new();
    for (k, (ty, expr, _)) in cases.iter().enumerate() {
        decl.push_str(&format!("  r{k} : {ty};\n"));
        body.push_str(&format!("  r{k} := {expr};\n"));
    }
    let src = format!("PROGRAM main\nVAR\n{decl}END_VAR\n{body}END_PROGRAM\n");
    let dir = tempfile::tempdir().unwrap();
    let col = run_st(dir.path(), &src);
    let mut failures = Vec::new();
    for (k, (_, expr, want)) in cases.iter().enumerate() {
        let got = &col[&format!("main.r{k}")];
        if got != want {
            failures.push(format!("{expr}: got {got}, want {want}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
