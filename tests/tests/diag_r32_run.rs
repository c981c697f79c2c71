//! Round 32 (issue #13), order and cascade diagnostics found on real TwinCAT and ST projects: the
//! order of declarations carries no meaning (an instance's initial value naming the inputs of a
//! block declared later, a global initial value naming a constant declared later in the same
//! configuration), and one cause gives one error (a constant no file declares: one E0022 at its
//! first use; a member of a missing EXTENDS base: the E0330 only; a library-qualified enumeration
//! value: the library's E1032; named values on a REAL base: the E0011 only).

mod common;

use common::{check_files, check_text, column, run_text};

/// IEC 61131-3 ed. 3 declares POUs at configuration level in no order (6.1, 6.6) and lets an
/// instance's declaration give its inputs' initial values (`fb : FB_Conn := (nBase := 5)`, as
/// TwinCAT does in Beckhoff's TF6310 TCP sample, `aConnections : ARRAY[..] OF
/// FB_ServerConnection := [(sPrefix := 'SERVER1::'), ...]`). Before: three E1025 "FB_Conn has no
/// field or input `nBase`" because FB_Conn is declared after the program (passing when the order
/// was swapped); now it runs with the given inputs, an instance and an array of instances.
#[test]
fn instance_initial_values_name_inputs_of_a_block_declared_later() {
    let src = "PROGRAM Main\nVAR\n  one : FB_Conn := (nBase := 5);\n  arr : ARRAY[1..2] OF FB_Conn := [(nBase := 10), (nBase := 20)];\n  total : INT;\nEND_VAR\none();\narr[1]();\narr[2]();\ntotal := one.nOut + arr[1].nOut + arr[2].nOut;\nEND_PROGRAM\n\nFUNCTION_BLOCK FB_Conn\nVAR_INPUT\n  nBase : INT := 1;\nEND_VAR\nVAR_OUTPUT\n  nOut : INT;\nEND_VAR\nnOut := nOut + nBase;\nEND_FUNCTION_BLOCK\n";
    let (trace, _) = run_text("later.st", src, 3, "Main.total,Main.arr[2].nOut");
    assert_eq!(column(&trace, "Main.total"), [35.0, 70.0, 105.0]);
    assert_eq!(column(&trace, "Main.arr[2].nOut"), [20.0, 40.0, 60.0]);
}

/// A configuration's VAR_GLOBAL naming, as its initial value, a VAR_GLOBAL CONSTANT the same
/// configuration declares further down (itself computed from one declared after it), and a
/// resource's global naming that configuration's constant: IEC 61131-3 ed. 3 (6.5.1, 6.4.4.1.2)
/// takes a constant expression as an initial value with no textual order, and SIMATIC AX compiles
/// Siemens' ae-demo-rack sample so. Before: E1025 "`DEFAULT_STEP` is not a constant known here";
/// now stepSize is 10, bonus 6, and the program adds 16 per cycle.
#[test]
fn configuration_global_initial_value_names_a_constant_declared_later() {
    let src = "CONFIGURATION Cell\n    VAR_GLOBAL\n        stepSize : INT := DEFAULT_STEP;\n    END_VAR\n    VAR_GLOBAL CONSTANT\n        DEFAULT_STEP : INT := BASE_STEP * 2;\n        BASE_STEP : INT := 5;\n    END_VAR\n    RESOURCE Cpu ON PLC\n        VAR_GLOBAL\n            bonus : INT := BASE_STEP + 1;\n        END_VAR\n        TASK Cyclic(INTERVAL := T#10ms, PRIORITY := 1);\n        PROGRAM Counter WITH Cyclic : Prog;\n    END_RESOURCE\nEND_CONFIGURATION\n\nPROGRAM Prog\nVAR_EXTERNAL\n    stepSize : INT;\n    bonus : INT;\nEND_VAR\nVAR\n    total : INT;\nEND_VAR\n    total := total + stepSize + bonus;\nEND_PROGRAM\n";
    let (trace, _) = run_text("cell.st", src, 3, "Counter.total");
    assert_eq!(column(&trace, "Counter.total"), [16.0, 32.0, 48.0]);
}

/// A constant that no file given declares (a library's, `MAX_STRING_LENGTH` of Tc3_PLCopen_OpcUa
/// used 19 times in Beckhoff's TF6100 client sample) is one cause: one E0022 at its first use,
/// counting the uses, worded as a name declared nowhere. Before: one E0022 per use (5 here), each
/// "is not an integer constant declared before", as if the order were the fault.
#[test]
fn constant_declared_nowhere_is_one_error_at_its_first_use() {
    let src = "PROGRAM main\nVAR\n  a : ARRAY[1..MISSING_K] OF INT;\n  b : ARRAY[1..MISSING_K] OF INT;\n  s : STRING(MISSING_K);\n  t : STRING(MISSING_K);\nEND_VAR\na[1] := 1;\nEND_PROGRAM\n";
    let (code, lines) = check_text("k.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("k.st:3:16: error[E0022]: constant expression `MISSING_K`: `MISSING_K` names no constant with a value in the files given (4 uses)"),
        "{lines:?}"
    );
    assert!(lines[0].contains("--lib"), "{lines:?}");
}

/// The same over two files of one project: the first use (by file) carries the error and the
/// count, the other file reports nothing more.
#[test]
fn constant_declared_nowhere_is_one_error_over_the_files() {
    let (code, lines) = check_files(&[
        (
            "a.st",
            "PROGRAM main\nVAR\n  a : ARRAY[1..N_MISSING] OF INT;\n  f : FB_B;\nEND_VAR\nf();\nEND_PROGRAM\n",
        ),
        (
            "b.st",
            "FUNCTION_BLOCK FB_B\nVAR\n  b : ARRAY[0..N_MISSING] OF BYTE;\n  c : STRING(N_MISSING);\nEND_VAR\nb[0] := 1;\nEND_FUNCTION_BLOCK\n",
        ),
    ]);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("a.st:3:16: error[E0022]")
            && errors[0]
                .contains("`N_MISSING` names no constant with a value in the files given (3 uses)"),
        "{lines:?}"
    );
}

/// A block whose EXTENDS base no file declares (a library's block, E0330) calls a method of a
/// member it inherits (`_logger.LogDelete(n)`, as Beckhoff's sACN sample does with Tc3_sACN's
/// FB_sACN_Receiver): the missing base is the one cause, as for the inherited `_count` beside it.
/// Before: an E1032 more calling `_logger` a library ladderc does not provide.
#[test]
fn member_of_a_missing_base_called_is_only_the_missing_base() {
    let src = "FUNCTION_BLOCK FB_Mine EXTENDS FB_LibReceiver\nVAR\n  n : INT;\nEND_VAR\n_logger.LogDelete(n);\n_count := _count + 1;\nn := n + 1;\nEND_FUNCTION_BLOCK\nPROGRAM main\nVAR\n  r : FB_Mine;\nEND_VAR\nr();\nEND_PROGRAM\n";
    let (code, lines) = check_text("base.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("base.st:1:32: error[E0330]"),
        "{lines:?}"
    );
    assert!(lines[0].contains("FB_LibReceiver"), "{lines:?}");
}

/// A library-qualified enumeration value, `Tc2_System.E_HRESULTAdsErr.INVALIDPARM` (Beckhoff
/// Infosys, TC3 PLC "Library namespace": `<namespace>.<element>`, as in Beckhoff's TF7xxx
/// samples), names the library as a qualified type does: one E1032 naming it and the
/// enumeration. Before: E1001 "undeclared name `Tc2_System`", hinting to declare it in a VAR
/// block.
#[test]
fn library_qualified_enumeration_value_is_the_library_error() {
    let src = "FUNCTION F_Check : DINT\nVAR_INPUT\n  n : INT;\nEND_VAR\nIF n < 0 THEN\n  F_Check := Tc2_System.E_HRESULTAdsErr.INVALIDPARM;\nELSIF n > 9 THEN\n  F_Check := Tc2_System.E_HRESULTAdsErr.TIMEOUT;\nEND_IF\nEND_FUNCTION\n";
    let (code, lines) = check_text("lib.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("lib.st:6:14: error[E1032]: `Tc2_System` is neither a variable nor a library ladderc provides"),
        "{lines:?}"
    );
    assert!(
        lines[0].contains("`E_HRESULTAdsErr.INVALIDPARM` comes from another library"),
        "{lines:?}"
    );
    assert!(!lines.iter().any(|l| l.contains("E1001")), "{lines:?}");
}

/// A data type with named values on an LREAL or LTIME base (edition 3's Annex A allows any
/// elementary base; SIMATIC AX's `POSITION : LREAL (ARMPOS1 := 100.0, ...)`) is a limit of
/// ladderc, which reads such a type as an enumeration: one E0011 per type, at its base. Before:
/// the E0011 and one E0022 "the value is not an integer" per value (9 errors for 2 types).
#[test]
fn named_values_on_a_real_or_duration_base_are_one_error_per_type() {
    let src = "TYPE\n    Position : LREAL (Home := 0.0, Target := 100.5, Park := 7.25) := Home;\n    Delay : LTIME (Gripper := LT#3s, Wip := LT#7s);\nEND_TYPE\n\nPROGRAM Main\nVAR\n    p : LREAL;\nEND_VAR\n    p := 1.0;\nEND_PROGRAM\n";
    let (code, lines) = check_text("named.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        lines
            .iter()
            .map(|l| l.split_once(" (hint").map_or(l.as_str(), |(h, _)| h))
            .collect::<Vec<_>>(),
        [
            "named.st:2:16: error[E0011]: `LREAL` cannot carry named values in ladderc",
            "named.st:3:13: error[E0011]: `LTIME` cannot carry named values in ladderc",
        ]
    );
}
