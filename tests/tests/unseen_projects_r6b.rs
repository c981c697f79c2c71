//! Issue #13, sixth acceptance round (helper `lang2`): 22 public repositories no earlier round had
//! tried (OpenPLC Editor and Beremiz projects, their generated `plc.st`, plain ST files, an ST test
//! suite), and IEC 61131-3's single-byte STRING. Each case is a minimal reproduction written here, in
//! `tests/fixtures/unseen/`, run through `ladderc run` (traces) or `ladderc check`:
//! - **STRING holds single-byte characters** (IEC 61131-3; WSTRING double-byte). A STRING literal's
//!   characters U+0000-U+00FF are one byte each, ISO 8859-1 as CODESYS stores them: `LEN('Köln')` is 4,
//!   `'Köln'` equals `'K$F6ln'`, LEFT/MID/RIGHT/FIND count characters, comparisons order by code
//!   (`'z' < 'é'`), STRING_TO_WSTRING/WSTRING_TO_STRING map byte to character; the trace writes each
//!   byte as its character in UTF-8 and a stimulus is read back so; the generated C holds the bytes as
//!   octal escapes (valid `-std=c99 -Werror`). Before, the C held UTF-8: `LEN('Köln')` was 5 and
//!   FIND counted bytes. In ST, IL and PLCopen XML alike.
//! - A character beyond U+00FF in a STRING literal (`'€'`, Greek, Chinese) is warning **W1416** at the
//!   literal, once per literal, and is stored as `?`; the same text in a WSTRING keeps it. Before, no
//!   warning (the UTF-8 bytes were stored).
//! - `name : TYPE AT %addr` (the location after the type, as one of the round's files writes it) kept
//!   its one E0011 per declaration, with a hint that shows the IEC order `name AT %addr : TYPE`; since
//!   the eleventh round (OpenPLC Editor v4 writes its `.st` files so) it is read as the IEC order with
//!   warning W0016 at each location (`tests/tests/unseen_projects_r11.rs`).

mod common;
use common::{check_text, ladderc, run_traced, run_with_stimulus, split_csv, unseen_fixture};

/// The values of cycle `cycle`'s row of a trace, by column name; a quoted field (a string) without
/// its quotes.
fn row(trace: &str, cycle: usize) -> std::collections::HashMap<String, String> {
    let mut lines = trace.lines();
    let header = split_csv(lines.next().unwrap());
    let values = split_csv(lines.nth(cycle).unwrap()).into_iter().map(|v| {
        match v.strip_prefix('"').and_then(|v| v.strip_suffix('"')) {
            Some(inner) => inner.replace("\"\"", "\""),
            None => v,
        }
    });
    header.into_iter().zip(values).collect()
}

/// Every string function counts ISO 8859-1 characters as one byte each, the literal and its `$hh`
/// escape are the same text, and the trace shows the characters in UTF-8.
#[test]
fn st_strings_hold_one_byte_per_latin1_character() {
    let watch = [
        "main.city",
        "main.escaped",
        "main.same",
        "main.n_city",
        "main.greeting",
        "main.n_greeting",
        "main.at_o",
        "main.first2",
        "main.middle",
        "main.last3",
        "main.before",
        "main.wide",
        "main.n_wide",
        "main.narrow",
        "main.short",
        "main.from_input",
        "main.n_input",
        "main.degrees",
    ];
    let trace = run_with_stimulus(
        &unseen_fixture("single_byte_strings.st"),
        1,
        "0,main.from_input,Straße\n",
        &watch,
    );
    let r = row(&trace, 0);
    let want = [
        ("main.city", "Köln"),
        ("main.escaped", "Köln"),
        ("main.same", "1"),
        ("main.n_city", "4"),
        ("main.greeting", "Grüße aus Köln"),
        ("main.n_greeting", "14"),
        ("main.at_o", "12"),
        ("main.first2", "Gr"),
        ("main.middle", "üße "),
        ("main.last3", "öln"),
        ("main.before", "1"),
        ("main.wide", "Grüße aus Köln"),
        ("main.n_wide", "14"),
        ("main.narrow", "Größe"),
        ("main.short", "Äöü"),
        ("main.from_input", "Straße"),
        ("main.n_input", "6"),
        ("main.degrees", "20°C"),
    ];
    for (name, value) in want {
        assert_eq!(r[name], value, "{name} in\n{trace}");
    }
}

/// The same rule in IL: `LD '°C'` / `LEN` is 2, FIND finds `°` at its character position.
#[test]
fn il_strings_hold_one_byte_per_latin1_character() {
    let (trace, _) = run_traced(
        &unseen_fixture("single_byte_strings.il"),
        1,
        "main.unit,main.n,main.text,main.at_deg,main.same",
    );
    let r = row(&trace, 0);
    assert_eq!(r["main.unit"], "°C", "{trace}");
    assert_eq!(r["main.n"], "2", "{trace}");
    assert_eq!(r["main.text"], "Temperatur 20°C", "{trace}");
    assert_eq!(r["main.at_deg"], "14", "{trace}");
    assert_eq!(r["main.same"], "1", "{trace}");
}

/// And in PLCopen XML: an initial value `'Ölstand'` is 7 characters.
#[test]
fn xml_string_initial_values_hold_one_byte_per_latin1_character() {
    let (trace, _) = run_traced(
        &unseen_fixture("single_byte_strings.xml"),
        1,
        "main.label,main.n,main.shown",
    );
    let r = row(&trace, 0);
    assert_eq!(r["main.label"], "Ölstand", "{trace}");
    assert_eq!(r["main.n"], "7", "{trace}");
    assert_eq!(r["main.shown"], "Ölstand 75 %", "{trace}");
}

/// The generated C holds a STRING's bytes of 16#80 and above as octal escapes: the sources are ASCII
/// (and `run` above compiled them with -std=c99 -Wall -Wextra -Werror).
#[test]
fn generated_c_escapes_the_bytes_of_latin1_characters() {
    let dir = tempfile::tempdir().unwrap();
    let out = ladderc()
        .arg("build")
        .arg(unseen_fixture("single_byte_strings.st"))
        .arg("-o")
        .arg(dir.path())
        .output()
        .unwrap();
    common::assert_ok(&out);
    let program = std::fs::read(dir.path().join("program.c")).unwrap();
    assert!(program.is_ascii(), "program.c holds bytes beyond ASCII");
    let text = String::from_utf8(program).unwrap();
    // 'Grüße aus ': ü is 16#FC (octal 374), ß 16#DF (octal 337), ten bytes
    assert!(
        text.contains(r#"ladderc_str_lit("Gr\374\337e aus ", 10)"#),
        "{text}"
    );
}

/// A character beyond U+00FF in a STRING literal: W1416 at the literal (once per literal, naming the
/// first such character and how many more), stored as `?`; a WSTRING keeps the text; exit 0.
#[test]
fn characters_beyond_latin1_in_a_string_literal_are_w1416_and_become_question_marks() {
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(unseen_fixture("wide_char_in_string.st"))
        .args(["--cycles", "2", "--sanitize", "--trace", "-"])
        .args([
            "--watch",
            "main.price,main.price_w,main.greek,main.n,main.n_w",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("[W1416]")).collect();
    assert_eq!(warnings.len(), 2, "{stderr}");
    assert!(
        warnings[0].contains("wide_char_in_string.st:5:21: warning[W1416]: `€` (U+20AC) is not a single-byte character"),
        "{stderr}"
    );
    assert!(warnings[0].contains("hint: write the text as a WSTRING literal"));
    assert!(
        warnings[1].contains(
            "wide_char_in_string.st:11:10: warning[W1416]: `Ω` (U+03A9) and 4 more characters"
        ),
        "{stderr}"
    );
    let trace = String::from_utf8_lossy(&out.stdout).into_owned();
    for cycle in 0..2 {
        let r = row(&trace, cycle);
        assert_eq!(r["main.price"], "Preis 5 ?", "{trace}");
        assert_eq!(r["main.price_w"], "Preis 5 €", "{trace}");
        assert_eq!(r["main.greek"], "?????", "{trace}");
        assert_eq!(r["main.n"], "9", "{trace}");
        assert_eq!(r["main.n_w"], "9", "{trace}");
    }
}

/// A stimulus value for a STRING with a character beyond U+00FF stops the run (exit 1, as every bad
/// stimulus row) with its file and line.
#[test]
fn a_stimulus_string_beyond_latin1_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, "cycle,variable,value\n0,main.from_input,€\n").unwrap();
    let out = ladderc()
        .arg("run")
        .arg(unseen_fixture("single_byte_strings.st"))
        .args(["--cycles", "1", "--stimulus"])
        .arg(&stim)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains(
            "stim.csv:2: a STRING holds the characters U+0000-U+00FF, one byte each; use a WSTRING"
        ),
        "{stderr}"
    );
}

/// Only literals of STRING are checked: the same characters in a WSTRING literal and in comments give
/// no W1416, and the Latin-1 ones in a STRING none either.
#[test]
fn wstring_literals_comments_and_latin1_give_no_w1416() {
    let (code, lines) = check_text(
        "ok.st",
        "PROGRAM main\nVAR w : WSTRING := \"Ω €\"; s : STRING := 'Ä°ß$FF'; END_VAR\n(* Ω € *)\nw := \"日本\";\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(lines.is_empty(), "{lines:?}");
}

/// `x : UINT AT %MW0 := 20;` (the location after the type): one W0016 per declaration at its
/// location, read as `x AT %MW0 : UINT := 20;` (issue #13's eleventh round: OpenPLC Editor v4 writes
/// its `.st` files so). Before that round, one E0011 per declaration with a hint showing the IEC
/// order, and before the sixth a hint that said only "end each declaration with `;`".
#[test]
fn a_location_after_the_type_is_one_w0016_per_declaration_with_the_iec_order() {
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(unseen_fixture("location_after_type.st"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("warning[")).collect();
    assert_eq!(warnings.len(), 2, "{stderr}");
    for (w, (at, loc)) in warnings.iter().zip([("5:24", "%MW0"), ("6:16", "%QX0.0")]) {
        assert!(
            w.contains(&format!("location_after_type.st:{at}: warning[W0016]: the location `AT {loc}` is written after the type: read as if it stood before the `:` (hint: IEC 61131-3 writes the location between the name and the type")),
            "{stderr}"
        );
    }
}
