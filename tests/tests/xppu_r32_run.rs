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

/// Enumerations beside numbers as x-PPU writes them: a strict one with a base type (`(...) UINT`
/// under `{attribute 'strict'}`) compared with a UINT, an INT (a negative value) and an LREAL
/// (`GetNumeric(i) = EOperatingModes.automatic`), used as CASE labels of a UINT selector, stored
/// into an LREAL and passed to a method's LREAL input; a loose one compared with a UINT.
const MODES: &str = "{attribute 'qualified_only'}\n{attribute 'strict'}\n\
TYPE EModes : (none := 0, automatic := 2, manual := 3) UINT; END_TYPE\n\
{attribute 'strict'}\nTYPE EStep : (unset := -1, start := 0) INT; END_TYPE\n\
TYPE EColor : (white := 1, black := 2); END_TYPE\n\
FUNCTION_BLOCK State\nVAR_OUTPUT numeric : LREAL; END_VAR\n\
METHOD SetNumeric : BOOL\nVAR_INPUT value : LREAL; END_VAR\nnumeric := value; SetNumeric := TRUE;\nEND_METHOD\n\
METHOD GetNumeric : LREAL\nGetNumeric := numeric;\nEND_METHOD\n\
END_FUNCTION_BLOCK\n\
PROGRAM main\n\
VAR n : UINT; step : INT := -1; st : State; auto : BOOL; unset : BOOL; label : INT; r : LREAL; white : BOOL; END_VAR\n\
n := n + 1;\n\
IF n = 2 THEN st.SetNumeric(EModes.automatic); ELSE st.SetNumeric(EModes.manual); END_IF;\n\
auto := st.GetNumeric() = EModes.automatic;\n\
unset := step = EStep.unset;\n\
IF n >= 3 THEN step := 0; END_IF;\n\
CASE n OF\n  EModes.automatic: label := 20;\n  EModes.manual: label := 30;\nELSE label := 0;\nEND_CASE;\n\
r := EModes.manual;\n\
white := n = EColor.white;\n\
END_PROGRAM\n";

/// Each comparison, CASE label, store and argument takes the enumerated value's number (W1439 once
/// per POU). TwinCAT's `{attribute 'strict'}` makes errors only of arithmetic with the enumeration
/// and of storing other values into it (Beckhoff Infosys, "Attribute 'strict'"), so comparing it
/// with a number and storing it into one compile there. Before round 32: E1005 "EQ of UINT and
/// EModes" (and "EQ of UINT and INT" at the CASE labels, of LREAL and EModes), E1006 "cannot store
/// EModes into LREAL", E1012 at the LREAL input; x-PPU had 32 such errors.
#[test]
fn enumerated_values_meet_numbers_in_comparisons_case_labels_stores_and_inputs() {
    let watch = "main.st.numeric,main.auto,main.unset,main.label,main.r,main.white";
    let (trace, stderr) = run_text("modes.st", MODES, 4, watch);
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(stderr.matches("W1439").count(), 1, "{stderr}");
    assert_eq!(column(&trace, "main.st.numeric"), [3.0, 2.0, 3.0, 3.0]);
    assert_eq!(column(&trace, "main.auto"), [0.0, 1.0, 0.0, 0.0]);
    assert_eq!(column(&trace, "main.unset"), [1.0, 1.0, 1.0, 0.0]);
    assert_eq!(column(&trace, "main.label"), [0.0, 20.0, 30.0, 0.0]);
    assert_eq!(column(&trace, "main.r"), [3.0; 4]);
    assert_eq!(column(&trace, "main.white"), [1.0, 0.0, 0.0, 0.0]);
}

/// What `{attribute 'strict'}` forbids stays an error, one each: arithmetic with the enumeration
/// (E1004), storing a number or a literal into it (E1006).
#[test]
fn a_strict_enumeration_still_refuses_arithmetic_and_numbers_stored_into_it() {
    let src = "{attribute 'strict'}\nTYPE EModes : (none := 0, on := 1) UINT; END_TYPE\n\
               PROGRAM main\nVAR i : INT; e : EModes; u : UINT; END_VAR\n\
               i := EModes.on + 1;\ne := u;\ne := 1;\nEND_PROGRAM\n";
    let (code, lines) = common::check_text("strict.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split_once(" (hint").map_or(l.as_str(), |x| x.0))
        .collect();
    assert_eq!(
        heads,
        [
            "strict.st:5:6: error[E1004]: ADD is not defined for EModes",
            "strict.st:6:1: error[E1006]: cannot store UINT into EModes",
            "strict.st:7:1: error[E1006]: cannot store an integer literal into EModes",
        ]
    );
}

/// A chain of three blocks whose root's body is a chart (Resi4MPM's `ControlPrimitiveBase`, its
/// x-PPU primitives two levels below): the middle block's body and the last one's are `SUPER^();`
/// (Beckhoff Infosys "SUPER": `SUPER^()` runs the body of the base). The last block's call runs the
/// middle body, which runs one scan of the root's chart in the instance: its step Run counts once
/// per scan. Before round 32: E1019 "unknown function `__C000`" (the middle body, a hidden method
/// of the last block, did not see the chart's hidden action).
#[test]
fn super_runs_the_chart_of_a_base_two_levels_up() {
    let src = "FUNCTION_BLOCK Base\nVAR_OUTPUT k : INT; END_VAR\n\
               INITIAL_STEP Idle: END_STEP\nSTEP Run: Count(N); END_STEP\n\
               ACTION Count: k := k + 1; END_ACTION\n\
               TRANSITION FROM Idle TO Run := TRUE; END_TRANSITION\n\
               TRANSITION FROM Run TO Idle := k >= 3; END_TRANSITION\n\
               END_FUNCTION_BLOCK\n\
               FUNCTION_BLOCK ABSTRACT Mid EXTENDS Base\nSUPER^();\nEND_FUNCTION_BLOCK\n\
               FUNCTION_BLOCK Leaf EXTENDS Mid\nVAR_OUTPUT calls : INT; END_VAR\n\
               calls := calls + 1;\nSUPER^();\nEND_FUNCTION_BLOCK\n\
               PROGRAM main\nVAR leaf : Leaf; base : Base; k : INT; kb : INT; calls : INT; END_VAR\n\
               leaf();\nbase();\nk := leaf.k;\nkb := base.k;\ncalls := leaf.calls;\nEND_PROGRAM\n";
    let (trace, stderr) = run_text("chain.st", src, 6, "main.k,main.kb,main.calls");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "main.calls"), [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    // the same scans as an instance of the root itself: Idle -> Run in the first scan, Run's N
    // action counts, at k >= 3 Run is left (its action's last run, IEC 61131-3 2.6.4.5) and
    // entered again in the next scan
    assert_eq!(column(&trace, "main.kb"), [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    assert_eq!(column(&trace, "main.k"), column(&trace, "main.kb"));
}

/// A method with a result that calls itself (Resi4MPM's `METHOD GetExpression : IExpression`
/// calling `THIS^.GetExpression(...)` for the operands of the expression it builds) is the
/// documented E0106 (ladderc keeps a method's variables once per instance), one per call, at the
/// call; before round 32 the call was read as a call of the method's result variable: E1018
/// "`GetExpression` is IExpression, not an FB instance".
#[test]
fn a_method_calling_itself_for_its_result_is_e0106_at_the_call() {
    let src = "FUNCTION_BLOCK Calc\nMETHOD Fact : DINT\nVAR_INPUT n : DINT; END_VAR\n\
               IF n <= 1 THEN Fact := 1; ELSE Fact := n * THIS^.Fact(n - 1); END_IF;\n\
               END_METHOD\nEND_FUNCTION_BLOCK\n\
               PROGRAM main\nVAR c : Calc; r : DINT; END_VAR\nr := c.Fact(4);\nEND_PROGRAM\n";
    let (code, lines) = common::check_text("rec.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "rec.st:4:44: error[E0106]: method `Fact` calls itself (directly or through another \
             method)"
        ),
        "{lines:?}"
    );
}
