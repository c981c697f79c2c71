//! Round 34, TwinCAT points of sweep 34a (issue #13), end to end through `ladderc run` /
//! `ladderc check`:
//! - an initial value combining integer constants with OR, XOR and AND (`(nMode := A OR B)` in an
//!   instance's structured initial value, `y : DWORD := A OR B;`): IEC 61131-3 ed. 3 6.5.1 (a
//!   constant expression), Beckhoff infosys "Declaring variables" (any valid ST expression);
//!   before: E0011 at the operator (a misleading "missing `;`" for a plain variable);
//! - `[N(7)]` with a constant `N` the files do not declare: one E0022 for the missing constant,
//!   counted with its use as an array bound (before: a further E0022 per element calling it "a
//!   call");
//! - `FUNCTION_BLOCK X EXTENDS` with no base name: one E0330 at EXTENDS saying the name is missing
//!   (before: "EXTENDS `VAR_INPUT`, which names no function block");
//! - `P_Log.M_Add('x')` inside the block that declares or inherits the property `P_Log` (an
//!   interface): the getter's value, then the method called on it (before: E1001 "undeclared name").

mod common;
use common::{check_text, column, run_text};

const CONFIG: &str = "
CONFIGURATION c
RESOURCE r ON PLC
TASK t(INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM p WITH t : main;
END_RESOURCE
END_CONFIGURATION
";

/// OR, XOR and AND of integer constants in initial values, bound as in ST (AND tighter than XOR,
/// XOR tighter than OR, `+` tighter than all three), also inside parentheses and in a block
/// instance's structured initial value (BCYEOH/project1's `(nMode := FOPEN_MODEAPPEND OR
/// FOPEN_MODETEXT)`). Before: E0011 "unexpected `OR`" in the instance's value, "missing `;` after
/// `y : DWORD := MODE_A` before `OR`" for a variable, the file not compiled.
#[test]
fn or_xor_and_of_constants_are_initial_values() {
    let src = format!(
        "VAR_GLOBAL CONSTANT
    MODE_A : DWORD := 16#0001;
    MODE_B : DWORD := 16#0002;
    C5 : DWORD := 5;
    C3 : DWORD := 3;
END_VAR
FUNCTION_BLOCK FB_Open
VAR_INPUT
    nMode : DWORD;
END_VAR
VAR_OUTPUT
    nSeen : DWORD;
END_VAR
nSeen := nMode;
END_FUNCTION_BLOCK
PROGRAM main
VAR
    fb : FB_Open := (nMode := MODE_A OR MODE_B);
    fbMasked : FB_Open := (nMode := C5 AND C3 XOR 16#10);
    seen : DWORD;
    masked : DWORD;
    y : DWORD := MODE_A OR MODE_B;
    x : DWORD := C5 AND C3;
    z : DWORD := (C5 OR C3) AND 16#6;
    w : DWORD := C5 + 1 AND 16#FE;
    v : DWORD := C5 XOR C3 OR 16#10;
    a : ARRAY [0..1] OF DWORD := [C5 OR 16#100, C3 & 1];
END_VAR
fb();
fbMasked();
seen := fb.nSeen;
masked := fbMasked.nSeen;
END_PROGRAM
{CONFIG}"
    );
    let (trace, stderr) = run_text(
        "init_or.st",
        &src,
        2,
        "p.seen,p.masked,p.y,p.x,p.z,p.w,p.v,p.a[0],p.a[1]",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    for (name, want) in [
        ("p.seen", 3.0),
        ("p.masked", 17.0),
        ("p.y", 3.0),
        ("p.x", 1.0),
        ("p.z", 6.0),
        ("p.w", 6.0),
        ("p.v", 22.0),
        ("p.a[0]", 261.0),
        ("p.a[1]", 1.0),
    ] {
        assert_eq!(column(&trace, name), [want, want], "{name}\n{trace}");
    }
}

/// `OR` of a REAL is no constant integer: one located E0022 naming AND, OR and XOR (not a syntax
/// error).
#[test]
fn or_of_a_real_is_one_e0022() {
    let src = format!(
        "PROGRAM main
VAR
    r : REAL := 1.5 OR 2;
END_VAR
END_PROGRAM
{CONFIG}"
    );
    let (code, lines) = check_text("init_or_real.st", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("init_or_real.st:3:17: error[E0022]")
            && errors[0].contains("AND, OR and XOR take integers"),
        "{lines:?}"
    );
}

/// `[g_cX(7)]` where `g_cX` is declared in none of the files given (a list of another project,
/// dgwoOstjfn/Mem1) is IEC 61131-3's repetition: the missing constant is one E0022 at its first use
/// (the array bound), counting its four uses. Before: that E0022 (2 uses) plus one E0022 per
/// initial value, "`g_cX(...)` is a call: only standard numeric functions ...". With the constant
/// declared the repetition runs (7, 7, 7).
#[test]
fn repetition_count_naming_a_missing_constant_is_one_error() {
    let src = format!(
        "FUNCTION_BLOCK FB_A
VAR
    a : ARRAY [1..g_cX] OF UINT := [g_cX(7)];
END_VAR
END_FUNCTION_BLOCK
PROGRAM main
VAR
    fb : FB_A;
    b : ARRAY [1..g_cX] OF UINT := [g_cX(7)];
END_VAR
fb();
END_PROGRAM
{CONFIG}"
    );
    let (code, lines) = check_text("repeat_missing.st", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("repeat_missing.st:3:19: error[E0022]")
            && lines[0].contains("`g_cX` names no constant")
            && lines[0].contains("(4 uses)")
            && !lines[0].contains("is a call"),
        "{lines:?}"
    );

    let declared = format!(
        "VAR_GLOBAL CONSTANT
    g_cX : INT := 3;
END_VAR
PROGRAM main
VAR
    b : ARRAY [1..g_cX] OF UINT := [g_cX(7)];
    r : REAL := SQRT(16.0) + 1.0;
END_VAR
END_PROGRAM
{CONFIG}"
    );
    let (trace, _) = run_text(
        "repeat_declared.st",
        &declared,
        1,
        "p.b[1],p.b[2],p.b[3],p.r",
    );
    for name in ["p.b[1]", "p.b[2]", "p.b[3]"] {
        assert_eq!(column(&trace, name), [7.0], "{name}");
    }
    assert_eq!(column(&trace, "p.r"), [5.0]);
}

/// `FUNCTION_BLOCK FB_T EXTENDS` followed by `VAR_INPUT` (PeterZerlauth/Tc3_Component's test
/// blocks; TwinCAT rejects it too): one E0330 at EXTENDS saying the base block's name is missing.
/// Before: "`FB_T` EXTENDS `VAR_INPUT`, which names no function block of the project" at VAR_INPUT.
#[test]
fn extends_without_a_name_says_the_name_is_missing() {
    let src = format!(
        "FUNCTION_BLOCK FB_T EXTENDS
VAR_INPUT
    x : INT;
END_VAR
x := x + 1;
END_FUNCTION_BLOCK
PROGRAM main
VAR
    fb : FB_T;
END_VAR
fb();
END_PROGRAM
{CONFIG}"
    );
    let (code, lines) = check_text("extends_nothing.st", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("extends_nothing.st:1:21: error[E0330]")
            && lines[0].contains("name of the base block is missing after EXTENDS")
            && !lines[0].contains("VAR_INPUT"),
        "{lines:?}"
    );
}

const LOG_BLOCKS: &str = "INTERFACE I_Log
METHOD M_Add : BOOL
VAR_INPUT s : STRING; END_VAR
END_METHOD
END_INTERFACE
FUNCTION_BLOCK FB_Log IMPLEMENTS I_Log
VAR_OUTPUT
    nCount : INT;
END_VAR
METHOD M_Add : BOOL
VAR_INPUT s : STRING; END_VAR
nCount := nCount + 1;
M_Add := TRUE;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_Base
VAR_OUTPUT
    fbLog : FB_Log;
END_VAR
PROPERTY P_Log : I_Log
GET
    P_Log := fbLog;
END_GET
END_PROPERTY
P_Log.M_Add('base');
END_FUNCTION_BLOCK
";

/// A method called on the interface a block's own property returns, `P_Log.M_Add('x');`, inside
/// the block that declares it (FB_Base, one call per scan), and in a derived block that inherits
/// it, bare, as `THIS^.P_Log.M_Add(...)` and with its result read (three calls per scan;
/// PeterZerlauth/Tc3_Component's `P_Event.M_AddSTRING(...)`). Beckhoff infosys "Property": inside
/// the block the property is named without a prefix. Before: E1001 "undeclared name `P_Log`".
#[test]
fn method_on_own_property_inside_the_block() {
    let src = format!(
        "{LOG_BLOCKS}
FUNCTION_BLOCK FB_Derived EXTENDS FB_Base
VAR_OUTPUT
    ok : BOOL;
END_VAR
P_Log.M_Add('x');
THIS^.P_Log.M_Add('y');
ok := P_Log.M_Add('z');
END_FUNCTION_BLOCK
PROGRAM main
VAR
    fbB : FB_Base;
    fbD : FB_Derived;
    nB : INT;
    nD : INT;
    ok : BOOL;
END_VAR
fbB();
fbD();
nB := fbB.fbLog.nCount;
nD := fbD.fbLog.nCount;
ok := fbD.ok;
END_PROGRAM
{CONFIG}"
    );
    let (trace, stderr) = run_text("own_property.st", &src, 3, "p.nB,p.nD,p.ok");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "p.nB"), [1.0, 2.0, 3.0]);
    assert_eq!(column(&trace, "p.nD"), [3.0, 6.0, 9.0]);
    assert_eq!(column(&trace, "p.ok"), [1.0, 1.0, 1.0]);
}
