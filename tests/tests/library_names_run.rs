//! Names of the libraries a TwinCAT project links, as ladderc reads them.
//!
//! A function block that EXTENDS a block of a library ladderc does not have (TwinCAT's
//! `EXTENDS TcBaseModuleRegistered`, ziyuEngineer/TwinCAT's Portal project) is not compiled, with one
//! E0330 naming the base. The base may declare the FB_init that its instances' declaration
//! arguments (`m : FB_Module(nObjectId := ...)`) go to, so those arguments are no second error;
//! before, each such instance was also an E0329 ("has no FB_init method"). A block whose project
//! base is known and declares no FB_init still gets its E0329.
//!
//! `Tc2_System.MEMMOVE(...)` (fisothemes/TwinCat-Dynamic-Collections' FB_Array_List): ladderc
//! provides Tc2_System's memory functions, so the qualifier is dropped before them as Tc2_Standard's
//! is; before, it was E1032 ("`Tc2_System` is neither a variable nor a library ladderc provides").
//! Before any other name of the library (`Tc2_System.F_GetVersion`) it stays that E1032, which names
//! the library.

mod common;
use common::{rejected_heads, run_traced};

#[test]
fn instances_of_a_block_with_a_library_base_are_no_second_error() {
    let heads = rejected_heads(
        "lib.st",
        "FUNCTION_BLOCK FB_Module EXTENDS TcBaseModuleRegistered\nVAR_INPUT x : INT; END_VAR\n\
         END_FUNCTION_BLOCK\nFUNCTION_BLOCK FB_Base\nVAR_INPUT y : INT; END_VAR\nEND_FUNCTION_BLOCK\n\
         FUNCTION_BLOCK FB_Derived EXTENDS FB_Base\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR\n\
         m : FB_Module(nObjectId := 16#01010010);\n  d : FB_Derived(nId := 3);\nEND_VAR\n\
         m(x := 1);\nd(y := 2);\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        [
            "lib.st:1:34: error[E0330]: `FB_Module` EXTENDS `TcBaseModuleRegistered`, which names no function block of the project",
            "lib.st:12:17: error[E0329]: `FB_Derived` has no FB_init method to take these arguments",
        ]
    );
}

/// MEMMOVE of a[0..2] onto a[1..3] (overlapping) through the `Tc2_System.` qualifier.
#[test]
fn tc2_system_memory_functions_run_with_their_qualifier() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("mm.st");
    std::fs::write(
        &f,
        "PROGRAM Main\nVAR a : ARRAY[0..3] OF INT := [1, 2, 3, 4]; END_VAR\n\
         Tc2_System.MEMMOVE(ADR(a[1]), ADR(a[0]), 3 * SIZEOF(a[0]));\nEND_PROGRAM\n",
    )
    .unwrap();
    let (trace, _) = run_traced(&f, 1, "Main.a[0],Main.a[1],Main.a[2],Main.a[3]");
    assert_eq!(trace.lines().nth(1), Some("0,0,1,1,2,3"), "{trace}");
    let heads = rejected_heads(
        "ads.st",
        "PROGRAM Main\nVAR b : BOOL; END_VAR\nb := Tc2_System.F_GetVersion(1);\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        ["ads.st:3:6: error[E1032]: `Tc2_System` is neither a variable nor a library ladderc provides"]
    );
}

/// A name qualified by a library and its namespace (`SysFile.SysTypes.RTS_IEC_HANDLE`, TcUnit's
/// FB_FileControl), as a variable's type, a METHOD's result type and in a call: one E1032 naming
/// the library, hinting at the name used; before, E1032 and then E0011 "expected `;` before `.`"
/// at every declaration, the method's result type unreported.
#[test]
fn a_name_qualified_by_library_and_namespace_is_one_e1032() {
    let heads = rejected_heads(
        "sysfile.st",
        "FUNCTION_BLOCK FB_File\nVAR\n  h : SysFile.SysTypes.RTS_IEC_HANDLE;\n  n : INT;\nEND_VAR\n\
         METHOD PUBLIC Close : SysFile.SysTypes.RTS_IEC_RESULT\nClose := SysFile.SysTypes.Go(h);\n\
         END_METHOD\nn := n + 1;\nEND_FUNCTION_BLOCK\n",
    );
    assert_eq!(
        heads,
        ["sysfile.st:3:7: error[E1032]: `SysFile` is neither a variable nor a library ladderc provides"]
    );
    let (_, lines) = common::check_text(
        "sysfile.st",
        "PROGRAM Main\nVAR h : SysFile.SysTypes.RTS_IEC_HANDLE; END_VAR\nEND_PROGRAM\n",
    );
    assert!(
        lines[0].contains("`RTS_IEC_HANDLE` comes from another library"),
        "{lines:?}"
    );
}
