//! Follow-on errors and messages of TwinCAT object-oriented code found in public projects (issue
//! #13, round 30), end to end:
//! - `__QUERYINTERFACE` / `__QUERYPOINTER` on variables whose interface comes from a library that
//!   is not given (Tc3_BA2's `I_BA_EventObject`): the missing types are the one cause, E1003 at
//!   their declarations (before: E1019 "unknown function `__QUERYINTERFACE`" besides them, or,
//!   where the project declares interfaces, E0341 "no interface variable" without naming the type);
//! - a function block whose base is missing (TcUnit's `FB_TestSuite`): its methods' VAR_INST
//!   instances with FB_init arguments are no further error (before: one E0329 each, 69 in a TcUnit
//!   test library), while a block whose base is given still runs their FB_init;
//! - E0335 shows a method's ANY input as written (`Value : ANY`), not ladderc's hidden inputs;
//! - `udint OR byte`: the bit string widens into the integer's bits (W1438; before: E1005);
//! - `ton : TON;` in a TwinCAT object is accepted with W1456 (Beckhoff Infosys, "Shading rules":
//!   a function block and a variable may be named the same; before: E1031), and runs.

mod common;
use common::{check_files, check_text, column, run_text, run_traced};

/// The error lines of a check (short format), each up to its hint.
fn errors(src: &str) -> Vec<String> {
    let (code, lines) = check_text("app.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    lines
        .iter()
        .filter(|l| l.contains("error["))
        .map(|l| {
            l.split_once(" (hint")
                .map_or(l.clone(), |(h, _)| h.to_string())
        })
        .collect()
}

/// Beckhoff-JP/GearDemo's pattern (`FutureMCStopCreator.destroy_future`): the operand of
/// `__QUERYPOINTER` is of an interface named through a library that is not given
/// (`jobmgmt.InterfaceFuture`): that library's E1032 is the one cause. Found by round 30's
/// side-by-side figures: the first version of the rewrite above gave an E0341 at each of the
/// project's 12 queries besides it (before round 30: an E1019 "unknown function").
#[test]
fn querypointer_on_a_library_qualified_interface_is_the_librarys_error_only() {
    let src = "FUNCTION_BLOCK FutureStop\nVAR\n    n : INT;\nEND_VAR\nEND_FUNCTION_BLOCK\n\n\
FUNCTION_BLOCK Creator\nMETHOD destroy_future : BOOL\nVAR_INPUT\n    future : jobmgmt.InterfaceFuture;\n\
END_VAR\nVAR\n    p : POINTER TO FutureStop;\nEND_VAR\nIF __QUERYPOINTER(future, p) THEN\n\
    destroy_future := TRUE;\nEND_IF\nEND_METHOD\nEND_FUNCTION_BLOCK\n\n\
PROGRAM main\nVAR\n    c : Creator;\nEND_VAR\nEND_PROGRAM\n";
    let errs = errors(src);
    assert_eq!(errs.len(), 1, "{errs:?}");
    assert!(
        errs[0].contains("app.st:10:14: error[E1032]") && errs[0].contains("`jobmgmt`"),
        "{errs:?}"
    );
}

/// TF8040's pattern (`F_AcknowledgeEventClass`): both operands of `__QUERYINTERFACE` are of
/// interfaces of a library that is not given, in a project that declares no interface. Before:
/// the two E1003 and E1019 "unknown function `__QUERYINTERFACE`" (a cascade: ladderc has the
/// operator). Now the two E1003, nothing else.
#[test]
fn queryinterface_on_missing_interfaces_is_the_missing_types_only() {
    let src = "FUNCTION F_Ack : BOOL\nVAR\n    iObj : I_Lib_Object;\n    iEvt : I_Lib_EventObject;\nEND_VAR\n\
IF __QUERYINTERFACE(iObj, iEvt) THEN\n    F_Ack := TRUE;\nEND_IF\nEND_FUNCTION\n";
    let errs = errors(src);
    assert_eq!(
        errs,
        [
            "app.st:3:12: error[E1003]: unknown type `I_Lib_Object`",
            "app.st:4:12: error[E1003]: unknown type `I_Lib_EventObject`",
        ],
        "{errs:?}"
    );
}

/// The same where the project declares an interface of its own (the rewrite of interface
/// variables runs): before, E0341 "the second operand of `__QUERYINTERFACE` is no interface
/// variable", the missing type named nowhere (TF8040 Concepts). Now the E1003 of the missing
/// type, at its declaration; `__QUERYPOINTER` likewise.
#[test]
fn queryinterface_with_project_interfaces_names_the_missing_type() {
    let src = "INTERFACE I_Own\nEND_INTERFACE\n\
FUNCTION F_Ack : BOOL\nVAR\n    iOwn : I_Own;\n    iEvt : I_Lib_EventObject;\n    p : POINTER TO INT;\nEND_VAR\n\
IF __QUERYINTERFACE(iOwn, iEvt) THEN\n    F_Ack := TRUE;\nEND_IF\n\
F_Ack := __QUERYPOINTER(iEvt, p);\nEND_FUNCTION\n";
    let errs = errors(src);
    assert_eq!(
        errs,
        ["app.st:6:12: error[E1003]: unknown type `I_Lib_EventObject`"],
        "{errs:?}"
    );
}

/// A block with an FB_init taking a name, and a test block whose METHOD keeps one in its
/// VAR_INST with an FB_init argument (lcls-new-motion's TcUnit tests); `base` is the EXTENDS
/// clause of the test block.
fn suite(base: &str) -> String {
    format!(
        "FUNCTION_BLOCK FB_Stage\nVAR\n    nId : INT;\nEND_VAR\n\
METHOD FB_init : BOOL\nVAR_INPUT\n    bInitRetains : BOOL;\n    bInCopyCode : BOOL;\n    nStage : INT;\nEND_VAR\n\
nId := nStage;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\n\
FUNCTION_BLOCK FB_Test{base}\nVAR_OUTPUT\n    nSeen : INT;\nEND_VAR\n\
METHOD PRIVATE T1\nVAR_INST\n    stage : FB_Stage(nStage := 8);\nEND_VAR\n\
nSeen := stage.nId;\nEND_METHOD\nT1();\nEND_FUNCTION_BLOCK\n"
    )
}

/// The test block EXTENDS a base the files do not declare (TcUnit's `FB_TestSuite`): the E0330
/// alone. Before: E0330 and E0329 "this instance of `FB_Stage` is not one ladderc initialises"
/// at the VAR_INST instance (69 of lcls-new-motion's 89 errors).
#[test]
fn missing_base_is_one_error_not_one_per_fb_init_argument() {
    let errs = errors(&suite(" EXTENDS FB_TestSuite"));
    assert_eq!(errs.len(), 1, "{errs:?}");
    assert!(
        errs[0].starts_with("app.st:15:32: error[E0330]: `FB_Test` EXTENDS `FB_TestSuite`"),
        "{errs:?}"
    );
}

/// With the base given, the method's VAR_INST instance gets its FB_init argument before the
/// first cycle (Beckhoff Infosys "Methods FB_init, FB_reinit and FB_exit"): `nSeen` is 8 from the
/// first cycle on. (Guards the fix above: only a broken chain's arguments are dropped.)
#[test]
fn given_base_still_runs_the_method_instances_fb_init() {
    let src = format!(
        "FUNCTION_BLOCK FB_TestSuite\nVAR\n    nTests : INT;\nEND_VAR\nEND_FUNCTION_BLOCK\n\n{}\n\
PROGRAM MAIN\nVAR\n    t : FB_Test;\n    n : INT;\nEND_VAR\nt();\nn := t.nSeen;\nEND_PROGRAM\n",
        suite(" EXTENDS FB_TestSuite")
    );
    let (trace, _) = run_text("app.st", &src, 3, "MAIN.n");
    assert_eq!(column(&trace, "MAIN.n"), [8.0, 8.0, 8.0], "{trace}");
}

/// An implementing method whose input is `Value : ANY` where the interface has `ANY_STRING`
/// (Tc3_UnitTest's FB_StringBuilder): the mismatch is real (E0335), and the message shows the
/// method as written. Before: `M_ToAny(Value__DISIZE : DINT, Value__TYPECLASS_ANY : INT,
/// Value__PVALUE : POINTER TO BYTE) : BOOL`.
#[test]
fn e0335_shows_an_any_input_as_written() {
    let src = "INTERFACE I_Builder\nMETHOD M_ToAny : BOOL\nVAR_INPUT\n    Value : ANY_STRING;\nEND_VAR\nEND_METHOD\nEND_INTERFACE\n\n\
FUNCTION_BLOCK FB_Builder IMPLEMENTS I_Builder\n\
METHOD M_ToAny : BOOL\nVAR_INPUT\n    Value : ANY;\n    nMax : INT;\nEND_VAR\n\
M_ToAny := Value.diSize > nMax;\nEND_METHOD\nEND_FUNCTION_BLOCK\n";
    let errs = errors(src);
    assert_eq!(
        errs,
        ["app.st:10:8: error[E0335]: method `M_ToAny` of `FB_Builder` is `M_ToAny(Value : ANY, nMax : INT) : BOOL`, but interface `I_Builder` declares `M_ToAny(Value : ANY_STRING) : BOOL`"],
        "{errs:?}"
    );
}

/// An integer beside a narrower bit string in `AND` / `OR` (KimRo's Blowfish:
/// `SHL(data, 8) OR (key[j] AND 16#FF)` of a UDINT `data` and a BYTE key): the bit string widens
/// into the integer's bit pattern, zero-filled, and the result is that integer, as ladderc
/// already counts an integer given to a bit-string function (W1438, CODESYS and TwinCAT). Before:
/// E1005 "OR of UDINT and BYTE". A signed INT keeps its bits (`-1 AND 16#0F` is 15) and a BYTE
/// 16#80 stays 128 (no sign extension).
#[test]
fn integer_or_narrower_bit_string_works_on_the_integers_bits() {
    let src = "PROGRAM MAIN\nVAR\n    data : UDINT := 16#100;\n    key : BYTE := 16#0F;\n    high : BYTE := 16#80;\n\
    minus : INT := -1;\n    zero : INT;\n    r : UDINT;\n    j, m : INT;\nEND_VAR\n\
r := SHL(data, 8) OR (key AND 16#FF);\ndata := data + 1;\nj := minus AND key;\nm := zero OR high;\nEND_PROGRAM\n";
    let (code, lines) = check_text("bits.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(
        lines.len() == 1 && lines[0].starts_with("bits.st:11:6: warning[W1438]: SHL of UDINT"),
        "{lines:?}"
    );
    let (trace, _) = run_text("bits.st", src, 2, "MAIN.r,MAIN.j,MAIN.m");
    assert_eq!(column(&trace, "MAIN.r"), [65551.0, 65807.0], "{trace}");
    assert_eq!(column(&trace, "MAIN.j"), [15.0, 15.0], "{trace}");
    assert_eq!(column(&trace, "MAIN.m"), [128.0, 128.0], "{trace}");
}

/// A bit string wider than the integer (`INT AND DWORD`) stays E1005: the integer would have to
/// be sign- or zero-extended, which neither IEC 61131-3 nor ladderc's rule above decides.
#[test]
fn integer_and_wider_bit_string_stays_e1005() {
    let src = "PROGRAM MAIN\nVAR\n    n : INT;\n    d : DWORD;\n    r : DWORD;\nEND_VAR\nr := n AND d;\nEND_PROGRAM\n";
    let errs = errors(src);
    assert_eq!(errs.len(), 1, "{errs:?}");
    assert!(
        errs[0].starts_with("app.st:7:12: error[E1005]: AND of INT and DWORD"),
        "{errs:?}"
    );
}

/// A TwinCAT object whose variables are named like the standard blocks they are instances of
/// (bstiffler582/TcHmi_WebSockets' `ton : TON;`).
const TON_NAMED_TON: &str = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  <POU Name=\"MAIN\" Id=\"{00000000-0000-4000-8000-000000000010}\" SpecialFunc=\"None\">\n    <Declaration><![CDATA[PROGRAM MAIN\nVAR\n\tton : TON;\n\tr_trig : R_TRIG;\n\tstart, done : BOOL;\n\tedges : INT;\n\tother : TON;\nEND_VAR\n]]></Declaration>\n    <Implementation>\n      <ST><![CDATA[start := TRUE;\nton(IN := start, PT := T#30MS);\ndone := ton.Q;\nr_trig(CLK := done);\nIF r_trig.Q THEN\n\tedges := edges + 1;\nEND_IF\nother(IN := done, PT := T#10MS);]]></ST>\n    </Implementation>\n  </POU>\n</TcPlcObject>\n";

/// `ton : TON;` and `r_trig : R_TRIG;` in a `.TcPOU`: TwinCAT accepts a variable named like a
/// block (Beckhoff Infosys, TwinCAT 3 PLC, "Shading rules"; its "Keywords" list has no block), so
/// ladderc does, with one W1456 per such declaration; the instances run (`ton.Q` after 30 ms,
/// one rising edge counted, another TON beside them unaffected). Before: E1031 for each.
#[test]
fn twincat_variable_named_like_its_standard_block_runs() {
    let (code, lines) = check_files(&[("MAIN.TcPOU", TON_NAMED_TON)]);
    assert_eq!(code, Some(0), "{lines:?}");
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("MAIN.TcPOU");
    std::fs::write(&file, TON_NAMED_TON).unwrap();
    let out = common::ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&file)
        .output()
        .unwrap();
    let warnings = common::diagnostic_heads(&out.stderr, dir.path(), true);
    assert_eq!(
        warnings,
        [
            "MAIN.TcPOU:6:2: warning[W1456]: `ton` is the name of a standard function block, which IEC 61131-3 reserves: accepted as a variable name, as TwinCAT does",
            "MAIN.TcPOU:7:2: warning[W1456]: `r_trig` is the name of a standard function block, which IEC 61131-3 reserves: accepted as a variable name, as TwinCAT does",
        ],
        "{warnings:?}"
    );
    let (trace, _) = run_traced(&file, 6, "MAIN.done,MAIN.edges,MAIN.other.Q");
    assert_eq!(
        column(&trace, "MAIN.done"),
        [0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "MAIN.edges"),
        [0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "MAIN.other.Q"),
        [0.0, 0.0, 0.0, 0.0, 1.0, 1.0],
        "{trace}"
    );
}

/// The same declaration in an IEC 61131-3 text (`.st`) stays E1031: the standard reserves the
/// names of its blocks (2nd ed. Annex C) and matiec refuses them.
#[test]
fn st_variable_named_like_a_standard_block_stays_e1031() {
    let errs = errors(
        "PROGRAM MAIN\nVAR\n    ton : TON;\nEND_VAR\nton(IN := TRUE, PT := T#1S);\nEND_PROGRAM\n",
    );
    assert_eq!(
        errs,
        ["app.st:3:5: error[E1031]: `ton` is reserved in IEC 61131-3 (a standard function block): it cannot name a variable"],
        "{errs:?}"
    );
}

/// A non-formal call of a user FUNCTION leaving out trailing inputs that have initial values
/// (guanda's `WStrConcat("a", b)`, 30 calls): IEC 61131-3 (ed. 2, 2.5.1.1; ed. 3, 6.6.1.4.2) lets
/// only a formal call leave inputs out, and no Beckhoff or CODESYS page says otherwise, so it stays
/// one E1020 at the arguments; its hint now says how to write it (name the inputs given), where
/// before it only listed the inputs.
#[test]
fn non_formal_call_leaving_out_inputs_stays_e1020_with_the_formal_form() {
    let src = "FUNCTION F_Cat : STRING\nVAR_INPUT\n    a : STRING := '';\n    b : STRING := '';\n    c : STRING := 'z';\nEND_VAR\n\
F_Cat := CONCAT(CONCAT(a, b), c);\nEND_FUNCTION\n\
PROGRAM MAIN\nVAR\n    s : STRING;\nEND_VAR\ns := F_Cat('x', 'y');\nEND_PROGRAM\n";
    let (code, lines) = check_text("app.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        lines,
        ["app.st:13:12: error[E1020]: F_Cat takes 3 inputs, 2 given (hint: give its inputs in order: a, b, c; or name the ones given (`F_Cat(a := ..., b := ...)`): a formal call leaves the others at their initial values)"],
        "{lines:?}"
    );
}
