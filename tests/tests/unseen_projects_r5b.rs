//! Gaps the fifth acceptance run of issue #13 left (`tests/unseen_projects_r5.rs` has the rest), each a
//! minimal reproduction written here, through `ladderc run` or `ladderc check`:
//! - source files in Windows-1252 / ISO-8859-1, as CODESYS, TwinCAT and TIA Portal save them (three
//!   ST files of `AutomatisierungsLabor/PlcDigitalTwinAutoTest` have umlauts in comments): an `.st`
//!   file that is not UTF-8 is read as Windows-1252 with note W0305, a PLCopen XML file is read in the
//!   encoding its declaration names, UTF-16 with a byte-order mark is read; diagnostics count lines and
//!   columns in the decoded text and JSON byte offsets in the file. Before, each was E9001 "not valid
//!   UTF-8", exit 2;
//! - `MAIN.x` from another POU (CODESYS, TwinCAT; 25 TwinCAT "Pick and Place Unit" files): a variable
//!   of the program's one instance, read and written, with warning W1413; a program with no instance
//!   or several in the configuration stays E1001, saying which. Before, always E1001.

mod common;
use common::ladderc;
use std::path::{Path, PathBuf};
use std::process::Output;

/// `bytes` written to a new temporary folder as `name`: the folder (kept alive by the caller) and the path.
fn write(name: &str, bytes: &[u8]) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join(name);
    std::fs::write(&f, bytes).unwrap();
    (dir, f)
}

/// `ladderc --message-format FORMAT run FILE --cycles 1 --sanitize --trace - --watch WATCH`.
fn run(file: &Path, format: &str, watch: &str) -> Output {
    ladderc()
        .args(["--message-format", format, "run"])
        .arg(file)
        .args([
            "--cycles",
            "1",
            "--sanitize",
            "--trace",
            "-",
            "--watch",
            watch,
        ])
        .output()
        .unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// The program of the encoding tests, with `Ä` (a string literal and comments) as the caller spells it:
/// `a` is the literal `'Ä'`, `b` the escape `'$C4'` (IEC 61131-3's code of `Ä`), `eq` whether they are
/// equal.
fn umlaut_program(a_umlaut: &[u8], u_umlaut: &[u8]) -> Vec<u8> {
    let mut s = Vec::new();
    s.extend_from_slice(b"PROGRAM main\nVAR\n  a : STRING := '");
    s.extend_from_slice(a_umlaut);
    s.extend_from_slice(b"'; (* Sch");
    s.extend_from_slice(u_umlaut);
    s.extend_from_slice(
        b"tz K1 *)\n  b : STRING := '$C4';\n  eq : BOOL;\nEND_VAR\neq := a = b;\nEND_PROGRAM\n",
    );
    s
}

/// A TIA Portal / CODESYS text file in Windows-1252 (`Ä` is the byte 0xC4, `ü` 0xFC) runs: the note
/// W0305 says how it was read and where the first byte that is not UTF-8 is, and the string literal
/// `'Ä'` has the value of `'$C4'` and of `'Ä'` in the same file saved as UTF-8 (the same trace).
#[test]
fn a_windows_1252_st_file_runs_with_a_note_and_its_umlaut_is_the_escape() {
    let (_d, latin) = write("motor.st", &umlaut_program(b"\xC4", b"\xFC"));
    let out = run(&latin, "short", "main.a,main.b,main.eq");
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert_eq!(
        text(&out.stdout),
        "cycle,time_ms,main.a,main.b,main.eq\n0,0,\"Ä\",\"Ä\",1\n"
    );
    let notes: Vec<&str> = stderr.lines().filter(|l| l.contains("[W0305]")).collect();
    assert_eq!(notes.len(), 1, "{stderr}");
    assert!(
        notes[0].contains("motor.st:3:18: note[W0305]: not valid UTF-8 from here on: the file is read as Windows-1252"),
        "{stderr}"
    );
    let (_e, utf8) = write("motor.st", &umlaut_program("Ä".as_bytes(), "ü".as_bytes()));
    let same = run(&utf8, "short", "main.a,main.b,main.eq");
    assert_eq!(same.status.code(), Some(0), "{}", text(&same.stderr));
    assert_eq!(same.stdout, out.stdout);
    assert!(!text(&same.stderr).contains("W0305"));
}

/// An error after umlauts in a Windows-1252 file: the human excerpt shows the decoded line, line and
/// column count characters, and JSON's `byte_start` is the offset of the name in the file's bytes.
#[test]
fn diagnostics_after_umlauts_point_at_the_line_column_and_byte_of_the_file() {
    let src: &[u8] = b"PROGRAM main\nVAR (* Z\xE4hler f\xFCr Gr\xFC\xDFe *)\n  n : INT;\nEND_VAR\n\
(* \xC4nderung: \x80 *) n := n + 1; zz := 1;\nEND_PROGRAM\n";
    let (_d, f) = write("count.st", src);
    let human = ladderc().args(["check"]).arg(&f).output().unwrap();
    assert_eq!(human.status.code(), Some(1));
    let h = text(&human.stderr);
    assert!(
        h.contains("5 │ (* Änderung: € *) n := n + 1; zz := 1;"),
        "{h}"
    );
    assert!(h.contains("count.st:5:31"), "{h}");
    let json = ladderc()
        .args(["--message-format", "json", "check"])
        .arg(&f)
        .output()
        .unwrap();
    let errors: Vec<serde_json::Value> = text(&json.stderr)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .filter(|v: &serde_json::Value| v["severity"] == "error")
        .collect();
    assert_eq!(errors.len(), 1, "{}", text(&json.stderr));
    let e = &errors[0];
    assert_eq!(
        (e["code"].as_str(), e["line"].as_u64(), e["column"].as_u64()),
        (Some("E1001"), Some(5), Some(31))
    );
    let at = src.windows(2).position(|w| w == b"zz").unwrap() as u64;
    assert_eq!(
        (e["byte_start"].as_u64(), e["byte_end"].as_u64()),
        (Some(at), Some(at + 2))
    );
    // the note points at the first umlaut (`ä` of `Zähler`, line 2 column 9) and counts it as one byte
    let note: serde_json::Value = text(&json.stderr)
        .lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap())
        .find(|v| v["code"] == "W0305")
        .unwrap();
    assert_eq!(
        (note["line"].as_u64(), note["column"].as_u64()),
        (Some(2), Some(9))
    );
    assert_eq!(
        note["byte_start"].as_u64(),
        Some(src.iter().position(|&b| b == 0xE4).unwrap() as u64)
    );
}

/// A PLCopen XML project as TIA Portal and older CODESYS versions write it: `encoding="ISO-8859-1"` (or
/// `windows-1252`) and 8-bit umlauts in the documentation, a comment and a string literal. It is read in
/// the declared encoding (no note), and `'Ä'` equals `'$C4'`. The same bytes declared UTF-8 are not
/// UTF-8: read as Windows-1252 with the note.
#[test]
fn an_xml_project_is_read_in_the_encoding_its_declaration_names() {
    let project = |encoding: &str| -> Vec<u8> {
        let mut x = format!("<?xml version=\"1.0\" encoding=\"{encoding}\"?>\n").into_bytes();
        x.extend_from_slice(
            b"<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">\n\
<contentHeader name=\"Motorschaltung\"/><types><dataTypes/><pous>\n\
<pou name=\"main\" pouType=\"program\"><interface><localVars>\
<variable name=\"a\"><type><string/></type></variable>\
<variable name=\"eq\"><type><BOOL/></type></variable></localVars></interface>\n\
<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">(* Sch\xFCtz \x80 *)\na := '\xC4'; eq := a = '$C4';</xhtml></ST></body>\n\
<documentation><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">Gr\xFC\xDFe</xhtml></documentation></pou>\n\
</pous></types><instances><configurations/></instances></project>\n",
        );
        x
    };
    for encoding in ["ISO-8859-1", "windows-1252", "UTF-8"] {
        let (_d, f) = write("tia.xml", &project(encoding));
        let out = run(&f, "short", "main.a,main.eq");
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{encoding}: {stderr}");
        assert_eq!(
            text(&out.stdout),
            "cycle,time_ms,main.a,main.eq\n0,0,\"Ä\",1\n",
            "{encoding}"
        );
        assert_eq!(
            stderr.contains("note[W0305]"),
            encoding == "UTF-8",
            "{encoding}: {stderr}"
        );
    }
}

/// UTF-16 with a byte-order mark (Windows Notepad's "Unicode"), little and big endian, runs; JSON's byte
/// offsets count two bytes per character and the mark.
#[test]
fn utf16_files_with_a_byte_order_mark_are_read() {
    let src = "PROGRAM main\nVAR a : STRING := 'Ä'; eq : BOOL; END_VAR\neq := a = '$C4'; q := 1;\nEND_PROGRAM\n";
    for le in [true, false] {
        let mut b = if le {
            vec![0xFF, 0xFE]
        } else {
            vec![0xFE, 0xFF]
        };
        for u in src.encode_utf16() {
            b.extend(if le { u.to_le_bytes() } else { u.to_be_bytes() });
        }
        let (_d, f) = write("wide.st", &b);
        let out = ladderc()
            .args(["--message-format", "json", "check"])
            .arg(&f)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(1));
        let e: serde_json::Value =
            serde_json::from_str(text(&out.stderr).lines().next().unwrap()).unwrap();
        assert_eq!(
            (e["code"].as_str(), e["line"].as_u64(), e["column"].as_u64()),
            (Some("E1001"), Some(3), Some(18))
        );
        let at = 2 + 2 * src[..src.find(" q :=").unwrap() + 1].encode_utf16().count() as u64;
        assert_eq!(e["byte_start"].as_u64(), Some(at));
        let fixed = src.replace(" q := 1;", "");
        let mut b = if le {
            vec![0xFF, 0xFE]
        } else {
            vec![0xFE, 0xFF]
        };
        for u in fixed.encode_utf16() {
            b.extend(if le { u.to_le_bytes() } else { u.to_be_bytes() });
        }
        let (_e, f) = write("wide.st", &b);
        let out = run(&f, "short", "main.a,main.eq");
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        assert_eq!(
            text(&out.stdout),
            "cycle,time_ms,main.a,main.eq\n0,0,\"Ä\",1\n"
        );
    }
}

/// What cannot be decoded stays an I/O error (E9001, exit 2) that says why: an encoding ladderc does not
/// read, declared by a file that is not ASCII, and a UTF-16 mark on bytes that are not UTF-16. The same
/// unknown declaration on a plain ASCII file is no obstacle.
#[test]
fn undecodable_files_are_e9001_saying_why() {
    let cases: [(&str, &[u8], &str); 2] = [
        (
            "sjis.xml",
            b"<?xml version=\"1.0\" encoding=\"Shift_JIS\"?>\n<project>\x82\xA0</project>\n",
            "declares encoding `Shift_JIS`, which ladderc does not read",
        ),
        (
            "odd.st",
            b"\xFF\xFEP\x00R",
            "starts with a UTF-16 (little-endian) byte-order mark but is not valid UTF-16",
        ),
    ];
    for (name, bytes, want) in cases {
        let (_d, f) = write(name, bytes);
        let out = ladderc()
            .args(["--message-format", "short", "check"])
            .arg(&f)
            .output()
            .unwrap();
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(
            stderr.contains("error[E9001]") && stderr.contains(want),
            "{stderr}"
        );
    }
    let (_d, f) = write(
        "ascii.xml",
        b"<?xml version=\"1.0\" encoding=\"Shift_JIS\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">\n\
<contentHeader name=\"p\"/><types><dataTypes/><pous>\n\
<pou name=\"main\" pouType=\"program\"><interface><localVars><variable name=\"n\"><type><INT/></type></variable></localVars></interface>\n\
<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">n := n + 2;</xhtml></ST></body></pou>\n\
</pous></types><instances><configurations/></instances></project>\n",
    );
    let out = run(&f, "short", "main.n");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "cycle,time_ms,main.n\n0,0,2\n");
}

/// The program and function block of the `MAIN.x` tests: the block reads `Main.provided`, reads and
/// writes `Main.count`, and a function reads `Main.count` too; `config` is appended.
fn main_x(config: &str) -> String {
    format!(
        "PROGRAM Main\nVAR provided : BOOL; count : INT; s : Stack; seen : INT; END_VAR\n\
         provided := NOT provided;\n  s();\n  seen := Twice();\nEND_PROGRAM\n\
         FUNCTION_BLOCK Stack\nVAR ok : BOOL; END_VAR\n  ok := Main.provided;\n\
         IF Main.provided THEN Main.count := Main.count + 1; END_IF;\nEND_FUNCTION_BLOCK\n\
         FUNCTION Twice : INT\n  Twice := Main.count * 2;\nEND_FUNCTION\n{config}"
    )
}

/// `MAIN.x` in a function block and a function (TwinCAT's PPU blocks read `Main.Stack_WPProvided`) of a
/// program that runs alone: the program's variables are read and written, and W1413 is given once per
/// POU and program.
#[test]
fn a_program_variable_is_read_and_written_from_other_pous_with_a_warning() {
    let (_d, f) = write("ppu.st", main_x("").as_bytes());
    let out = run(&f, "short", "Main.provided,Main.count,Main.s.ok,Main.seen");
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("warning[")).collect();
    assert_eq!(warnings.len(), 2, "{stderr}");
    assert!(
        warnings[0].contains("/ppu.st:9:9: warning[W1413]: a variable of program `Main` used as `Main.x` (a CODESYS and TwinCAT extension"),
        "{stderr}"
    );
    assert!(
        warnings[1].contains("/ppu.st:13:12: warning[W1413]"),
        "{stderr}"
    );
    let out = ladderc()
        .args(["run"])
        .arg(&f)
        .args([
            "--cycles",
            "4",
            "--trace",
            "-",
            "--watch",
            "Main.provided,Main.count,Main.s.ok,Main.seen",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    // count goes up when provided is TRUE (every other cycle); seen is twice the count
    assert_eq!(
        text(&out.stdout),
        "cycle,time_ms,Main.provided,Main.count,Main.s.ok,Main.seen\n\
         0,0,1,1,1,2\n1,10,0,1,0,2\n2,20,1,2,1,4\n3,30,0,2,0,4\n"
    );
}

/// With a configuration, `Main.x` is the variable of the one instance the configuration declares (`m1`);
/// with two instances, or none, it names no one variable: E1001 at `Main`, once per POU, saying which.
#[test]
fn a_program_variable_needs_exactly_one_instance_in_the_configuration() {
    let one = main_x(
        "CONFIGURATION c RESOURCE r ON PLC TASK t(INTERVAL := T#10ms); PROGRAM m1 WITH t : Main; \
         END_RESOURCE END_CONFIGURATION\n",
    );
    let (_d, f) = write("one.st", one.as_bytes());
    let out = ladderc()
        .args(["run"])
        .arg(&f)
        .args([
            "--cycles",
            "3",
            "--sanitize",
            "--trace",
            "-",
            "--watch",
            "m1.count,m1.seen",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "cycle,time_ms,m1.count,m1.seen\n0,0,1,2\n1,10,1,2\n2,20,2,4\n"
    );
    // (a program that the configuration does not instantiate has, since issue #13's eleventh
    // round, one instance of its own, which only calls from other POUs run: `Main.x` is its
    // variable, W1413; `tests/tests/lang_left_r11.rs`)
    let own = main_x(
        "PROGRAM Other VAR x : INT; END_VAR x := x + 1; END_PROGRAM\n\
         CONFIGURATION c RESOURCE r ON PLC TASK t(INTERVAL := T#10ms); PROGRAM o WITH t : Other; \
         END_RESOURCE END_CONFIGURATION\n",
    );
    let (code, lines) = common::check_text("cfg.st", &own);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(
        lines.iter().all(|l| l.contains("warning[W1413]")),
        "{lines:?}"
    );
    let src = main_x(
        "PROGRAM Other VAR x : INT; END_VAR x := x + 1; END_PROGRAM\n\
         CONFIGURATION c RESOURCE r ON PLC TASK t(INTERVAL := T#10ms); \
         PROGRAM m1 WITH t : Main; PROGRAM m2 WITH t : Main; END_RESOURCE END_CONFIGURATION\n",
    );
    let (code, lines) = common::check_text("cfg.st", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "cfg.st:9:9: error[E1001]: `Main` is a program with 2 instances in the configuration, \
             not one variable"
        ),
        "{lines:?}"
    );
    assert!(
        lines[1].starts_with("cfg.st:13:12: error[E1001]"),
        "{lines:?}"
    );
}

/// `LD Main.count` / `ST Main.count` in an instruction-list body: the same access as in ST.
#[test]
fn a_program_variable_is_read_and_written_from_an_il_body() {
    let src = "PROGRAM Main\nVAR count : INT; s : Stack; END_VAR\n  s();\nEND_PROGRAM\n\
               FUNCTION_BLOCK Stack\nVAR n : INT; END_VAR\n  LD Main.count\n  ADD 3\n  ST Main.count\n  ST n\n\
               END_FUNCTION_BLOCK\n";
    let (_d, f) = write("il.st", src.as_bytes());
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(&f)
        .args([
            "--cycles",
            "2",
            "--sanitize",
            "--trace",
            "-",
            "--watch",
            "Main.count,Main.s.n",
        ])
        .output()
        .unwrap();
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("/il.st:7:6: warning[W1413]"), "{stderr}");
    assert_eq!(
        text(&out.stdout),
        "cycle,time_ms,Main.count,Main.s.n\n0,0,3,3\n1,10,6,6\n"
    );
}
