//! Issue #13: what TwinCAT libraries write in their data types.
//! - `TYPE INTERNAL T : ...` (stefanbesler/struckig's `BlockInterval`): the access specifier is
//!   one W0304 note and the type compiles. Before: E0011 "unexpected `BlockInterval`" and a cascade
//!   over the STRUCT's fields.
//! - A STRUCT field whose type is qualified by a library ladderc does not provide
//!   (`ExpectedsTypeClass : IBaseLibrary.TypeClass;` in tcunit/TcUnit, `TYPE T_Generic :
//!   __SYSTEM.AnyType; END_TYPE` in fisothemes' collections): one located E1032 naming the library,
//!   as for a variable of such a type. Before: E0011 "expected `;` before `.`" and W0013.

mod common;
use common::{column, ladderc, rejected_heads, run_traced};

#[test]
fn a_type_with_an_access_specifier_compiles_with_one_note() {
    let fixture = common::repo_root().join("tests/tests/fixtures/type_qualifiers/internal_type.st");
    let (trace, _) = run_traced(&fixture, 3, "Main.b.Left,Main.b.Right,Main.b.IsUsed");
    assert_eq!(column(&trace, "Main.b.Left"), [0.5, 1.0, 1.5], "{trace}");
    assert_eq!(column(&trace, "Main.b.Right"), [1.5, 2.0, 2.5]);
    assert_eq!(column(&trace, "Main.b.IsUsed"), [0.0, 0.0, 1.0]);
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&fixture)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let notes: Vec<&str> = stderr.lines().filter(|l| l.contains("[W0304]")).collect();
    assert_eq!(notes.len(), 1, "{stderr}");
    assert!(
        notes[0].contains("internal_type.st:3:6:")
            && notes[0].contains("`TYPE INTERNAL` of `BlockInterval`: the modifier is ignored"),
        "{stderr}"
    );
}

#[test]
fn a_field_of_a_type_from_a_library_not_provided_is_one_located_e1032() {
    let src = "TYPE ST_AssertArrayResult :\nSTRUCT\n    ExpectedsSize : UDINT;\n    ExpectedsTypeClass : IBaseLibrary.TypeClass;\n    ActualsTypeClass : IBaseLibrary.TypeClass;\nEND_STRUCT;\nEND_TYPE\nTYPE T_Generic : __SYSTEM.AnyType; END_TYPE\nPROGRAM Main\nVAR\n  r : ST_AssertArrayResult;\nEND_VAR\nr.ExpectedsSize := 1;\nEND_PROGRAM\n";
    let heads = rejected_heads("assert.st", src);
    assert_eq!(
        heads,
        [
            "assert.st:4:26: error[E1032]: `IBaseLibrary` is neither a variable nor a library ladderc provides",
            "assert.st:8:18: error[E1032]: `__SYSTEM` is neither a variable nor a library ladderc provides",
        ],
        "{heads:#?}"
    );
}
