//! Round 28 of unseen projects (issue #13): B&R-style `#ifdef` lines in ST text, end to end through
//! `ladderc check` / `ladderc run`:
//! - a text with an unclosed `#ifdef` and a character beyond ASCII after it is one located E1058
//!   (before: a panic, exit 101, in four files of a SIMATIC AX machine project with Italian
//!   comments: the blanked section was one byte shorter per `è`);
//! - the text after an unclosed `#ifdef` is compiled as if the line were not there: E1058 alone,
//!   not a missing `END_VAR` of a blanked declaration block;
//! - a `#ifdef` line inside a `(* ... *)` or `/* ... */` comment is text of the comment
//!   (IEC 61131-3 ed. 3 6.1.5: comments have no meaning) (before: the "section" swallowed the
//!   comment's `*)`, then E0002, E1058 and a note that the file was read as IL).

mod common;
use common::{check_text, column, run_text};

/// An unclosed `#ifdef` in a declaration block with `è` in a later comment: exit 1, one E1058 at
/// the directive (line 4, column 9), and nothing else: the rest of the text compiles.
#[test]
fn an_unclosed_ifdef_before_non_ascii_text_is_one_located_error() {
    let src = "PROGRAM Main
    VAR
        x : INT;
        #ifdef OPTION_A
        y : INT;
    END_VAR
    x := 1; // è perché
END_PROGRAM
";
    let (code, lines) = check_text("unclosed.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("unclosed.st:4:9: error[E1058]"),
        "{lines:?}"
    );
}

/// A closed section holding `è` keeps every later position: the error after it is located at
/// its own line and column (the blanked text has as many bytes as the original).
#[test]
fn a_blanked_section_with_non_ascii_text_keeps_later_positions() {
    let src = "PROGRAM Main
VAR
  x : INT;
END_VAR
#ifdef NOT_SET
  x := 2; (* è, à, ü *)
#endif
  x := undeclared;
END_PROGRAM
";
    let (code, lines) = check_text("pos.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(errors[0].starts_with("pos.st:8:8: error["), "{lines:?}");
}

/// `#ifdef` / `#endif` lines inside a block comment and a `/* */` comment are not directives: the
/// program runs and the commented-out "section" is not read (x = 5); a `(*` inside a string opens
/// no comment, so the real `#ifdef NOT_SET` section after it is left out (n = 13, the string's
/// length).
#[test]
fn a_directive_inside_a_comment_or_string_is_text() {
    let src = "PROGRAM Main
VAR
  x : INT;
  n : INT;
  s : STRING := '(* no comment';
END_VAR
#ifdef NOT_SET
  x := 77;
#endif
(*
#ifdef PROFINET
  x := 99;
*)
/*
#endif
*/
  x := 5;
  n := LEN(s);
END_PROGRAM
";
    let (trace, stderr) = run_text("comment.st", src, 2, "Main.x,Main.n");
    assert!(!stderr.contains("E1058"), "{stderr}");

    assert_eq!(column(&trace, "Main.x"), vec![5.0, 5.0], "{trace}");
    assert_eq!(column(&trace, "Main.n"), vec![13.0, 13.0], "{trace}");
}
