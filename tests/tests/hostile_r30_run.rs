//! Round 30's crash (issue #13): a description pragma after a declaration (`{ DE:"Насос" }`, the
//! form CODESYS-based editors such as Eliwell FREE Studio write) whose text puts a multi-byte
//! character across its seventh byte panicked (exit 101: the B&R redundancy-pragma test sliced the
//! text at byte 7). Found by round 30's sweep on a description in Cyrillic, and on a binary
//! CODESYS V3 `.project` given to ladderc as text.

mod common;
use common::{check_text, run_text};

/// The pragma is read like any other description: one note W0301, and the program runs.
#[test]
fn a_description_pragma_in_cyrillic_is_a_note_and_the_program_runs() {
    let src = "PROGRAM main\nVAR\n    pump : BOOL;    { DE:\"Насос\" }\nEND_VAR\npump := TRUE;\nEND_PROGRAM\n";
    let (code, lines) = check_text("main.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 0, "{lines:?}");
    let (trace, stderr) = run_text("main.st", src, 2, "main.pump");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let rows: Vec<&str> = trace.lines().skip(1).collect();
    assert_eq!(rows, ["0,0,1", "1,10,1"], "{trace}");
}

/// Every split of a multi-byte character across the pragma's first bytes, and the redundancy
/// pragma's own form with one: a diagnostic or none, never a panic.
#[test]
fn a_multi_byte_character_anywhere_in_a_short_pragma_does_not_panic() {
    for pad in 0..9 {
        for text in [
            format!("{{{}Ü}}", "a".repeat(pad)),
            format!("{{REDUND{}é_ERROR}}", "_".repeat(pad % 2)),
            format!("{{ {}:\"ä\" }}", "K".repeat(pad + 1)),
        ] {
            let src =
                format!("PROGRAM main\nVAR\n    x : INT; {text}\nEND_VAR\nx := 1;\nEND_PROGRAM\n");
            let (code, lines) = check_text("main.st", &src);
            assert!(matches!(code, Some(0 | 1)), "{text}: {code:?} {lines:?}");
        }
    }
}
