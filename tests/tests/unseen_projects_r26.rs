//! Round 26 of issue #13: what real projects met, fixed outside the helpers' files.
//!
//! - A structure's field named by a keyword (`Type : INT;` in a STRUCT of an `.il` file, read and
//!   written as `r.Type`) is a field, as the ST reader already takes it (B&R's library types name
//!   fields `Type`, `String`) (before: E0008 "missing END_STRUCT" and ten more errors for the one
//!   name).
//! - An address outside the default profile's area that a built-in profile has room for (an
//!   OpenPLC program's `%QW200`) gets E2001 with a hint naming that profile (`--profile openplc`),
//!   and the program runs with it (before: the hint named only `--profile FILE.json`).

mod common;
use common::{column, in_dir, run_text, write_in};

/// `Type` and `String` as fields of a structure in an IL file: declared, loaded, stored.
#[test]
fn a_keyword_names_a_structure_field_in_il() {
    let src = "TYPE R : STRUCT Type : INT; String : INT; END_STRUCT; END_TYPE\n\
PROGRAM P\n\
VAR r : R; x : INT; y : INT; END_VAR\n\
LD r.Type\n\
ADD 1\n\
ST r.Type\n\
ST x\n\
LD r.String\n\
ADD 10\n\
ST r.String\n\
ST y\n\
END_PROGRAM\n";
    let (trace, stderr) = run_text("keyword_fields.il", src, 3, "P.x,P.y");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "P.x"), vec![1.0, 2.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "P.y"), vec![10.0, 20.0, 30.0], "{trace}");
}

/// `%QW200` does not fit the default profile's 256 bytes of %Q: E2001's hint names the built-in
/// profile that holds it, and with that profile the program runs.
#[test]
fn e2001_names_the_built_in_profile_with_room_for_the_address() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "prog.st",
        "PROGRAM prog\nVAR reg AT %QW200 : INT := 7; END_VAR\nreg := reg + 1;\nEND_PROGRAM\n",
    );
    let (code, _, stderr) = in_dir(dir.path(), &["check", "prog.st"]);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("error[E2001]")
            && stderr.contains("(the built-in `--profile openplc` has room for it)"),
        "{stderr}"
    );
    let (code, stdout, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "prog.st",
            "--profile",
            "openplc",
            "--cycles",
            "2",
            "--watch",
            "prog.reg",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        stdout.lines().nth(2).is_some_and(|l| l.ends_with(",9")),
        "{stdout}"
    );
}
