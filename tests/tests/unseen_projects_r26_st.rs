//! Round 26 of unseen projects (issue #13), plain-text ST projects (SIMATIC AX, TwinCAT, CODESYS
//! exports, editors' samples), run end to end through `ladderc run`:
//! - a name qualified with a NAMESPACE declared in another file of the project
//!   (`Plant.Util.Twice(21)`, lib.st holding `NAMESPACE Plant.Util ... END_NAMESPACE`) names that
//!   function, and `USING Plant.Util;` of it is no W1421 (before: E1032 "`Plant` is neither a
//!   variable nor a library", with a hint to add POUs that were already there).

mod common;
use common::{in_dir, write_in};

/// IEC 61131-3 ed. 3 (6.9): a namespace is not tied to a file, and the files given together are
/// one project (SIMATIC AX puts `NAMESPACE Siemens.Ax` in one file and calls its function from
/// another). Qualified and after `USING`, both run.
#[test]
fn a_namespace_of_another_file_names_its_functions() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "lib.st",
        "NAMESPACE Plant.Util
    FUNCTION Twice : INT
        VAR_INPUT
            n : INT;
        END_VAR
        Twice := n * 2;
    END_FUNCTION
END_NAMESPACE
NAMESPACE Tools
    FUNCTION Inc : INT
        VAR_INPUT
            n : INT;
        END_VAR
        Inc := n + 1;
    END_FUNCTION
END_NAMESPACE
",
    );
    write_in(
        dir.path(),
        "main.st",
        "USING Tools;
PROGRAM Main
VAR
    a : INT;
    b : INT;
END_VAR
a := Plant.Util.Twice(21);
b := Inc(a) + Tools.Inc(0);
END_PROGRAM
",
    );
    let (code, out, err) = in_dir(
        dir.path(),
        &[
            "run", "lib.st", "main.st", "--cycles", "1", "--trace", "-", "--watch", "Main.a,Main.b",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("E1032") && !err.contains("W1421"), "{err}");
    assert_eq!(common::column(&out, "Main.a"), vec![42.0], "{out}");
    assert_eq!(common::column(&out, "Main.b"), vec![44.0], "{out}");
}
