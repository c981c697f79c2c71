//! Round 32, x-PPU (TwinCAT 3, x-PPU_PLC-Reconfiguration with its Resi4MPM library): the constructs
//! its checking stumbled on, end to end through `ladderc run`.

mod common;
use common::{column, run_text};

/// A block whose PROPERTY returns a POINTER TO another block (TwinCAT: `PROPERTY PtrProcessManager :
/// POINTER TO ProcessManager`), read through the pointer in ST and in a textual SFC transition's
/// condition (`m_ptrPanelMgr^.Start`), and a method called through the dereferenced property
/// (`m_ptrServices^.PtrProcessManager^.RequestAbort()`).
const SERVICES: &str = "FUNCTION_BLOCK Panel\n\
VAR presses : INT; END_VAR\n\
PROPERTY Start : BOOL\nGET Start := presses > 2; END_GET\nEND_PROPERTY\n\
METHOD Press : INT\npresses := presses + 1; Press := presses;\nEND_METHOD\n\
END_FUNCTION_BLOCK\n\
FUNCTION_BLOCK Services\n\
VAR panel : Panel; END_VAR\n\
PROPERTY PtrPanel : POINTER TO Panel\nGET PtrPanel := ADR(panel); END_GET\nEND_PROPERTY\n\
END_FUNCTION_BLOCK\n\
FUNCTION_BLOCK Modes\n\
VAR_INPUT svc : POINTER TO Services; END_VAR\n\
VAR_OUTPUT running : INT; END_VAR\n\
INITIAL_STEP Idle: END_STEP\n\
STEP Run: Count(N); END_STEP\n\
ACTION Count: running := running + 1; END_ACTION\n\
TRANSITION FROM Idle TO Run := svc^.PtrPanel^.Start; END_TRANSITION\n\
TRANSITION FROM Run TO Idle := NOT svc^.PtrPanel^.Start; END_TRANSITION\n\
END_FUNCTION_BLOCK\n\
PROGRAM main\n\
VAR s : Services; ps : POINTER TO Services; modes : Modes; n : INT; started : BOOL; running : INT; END_VAR\n\
ps := ADR(s);\n\
n := ps^.PtrPanel^.Press();\n\
started := s.PtrPanel^.Start;\n\
modes(svc := ps);\n\
running := modes.running;\n\
END_PROGRAM\n";

/// Each scan presses once through `ps^.PtrPanel^.Press()` (the getter, then the method on what it
/// points to: n counts 1, 2, 3...); `Start` read through the pointer turns TRUE at the third press,
/// and the chart's transition reading it leaves Idle in that scan, its step Run counting from there.
/// Before round 32: E1011 "`Services` has no input or output `PtrPanel`" at the method call, and
/// E1011 "`Panel` has no input or output `Start`" at each transition (the textual SFC lowering knew
/// no method of any block, so no property either, and lowered a condition without the statement
/// rewrites that call a getter).
#[test]
fn a_pointer_property_is_read_and_called_through_in_st_and_in_a_transition() {
    let (trace, stderr) = run_text(
        "services.st",
        SERVICES,
        6,
        "main.n,main.started,main.running",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "main.n"), [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    assert_eq!(
        column(&trace, "main.started"),
        [0.0, 0.0, 1.0, 1.0, 1.0, 1.0]
    );
    assert_eq!(
        column(&trace, "main.running"),
        [0.0, 0.0, 1.0, 2.0, 3.0, 4.0]
    );
}
