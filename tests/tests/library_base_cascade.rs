//! A function block that EXTENDS a block of a library ladderc does not have (TwinCAT's
//! `EXTENDS TcBaseModuleRegistered`, ziyuEngineer/TwinCAT's Portal project) is not compiled, with one
//! E0330 naming the base. The base may declare the FB_init that its instances' declaration
//! arguments (`m : FB_Module(nObjectId := ...)`) go to, so those arguments are no second error;
//! before, each such instance was also an E0329 ("has no FB_init method"). A block whose project
//! base is known and declares no FB_init still gets its E0329.

mod common;
use common::rejected_heads;

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
