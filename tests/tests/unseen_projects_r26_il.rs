//! Round 26 of issue #13: Instruction List text as real projects write it.
//!
//! - A structure's field named by a keyword (`Type : INT;` in a STRUCT of an `.il` file, read and
//!   written as `r.Type`) is a field, as the ST reader already takes it (B&R's library types name
//!   fields `Type`, `String`) (before: E0008 "missing END_STRUCT" and ten more errors for the one
//!   name).

mod common;
use common::{column, run_text};

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
