//! Round 29 of unseen projects (issue #13): CODESYS V2.3 exports, comparisons and configurations,
//! run end to end through `ladderc run` and `ladderc check`:
//! - the symbolic names of a CODESYS V2.3 PLC configuration (`_SYMBOLIC_NAME: 'Lamp'` with
//!   `_IECADR: %QX0.0`, `_BIT 0: %IX1.0.0 'Start_Btn' '...'`) are global variables at their
//!   addresses, typed by the size letter (before: the section skipped with W1442, then one E1001
//!   per use and POU: 122 in StarLeG/PLC110_KD);
//! - a bit string compared with a number counts as its unsigned integer (`udint = word` as
//!   UDINT, W1436), as in arithmetic and in a store (before: E1005 speaking of IL's current
//!   result);
//! - a direct address with an unknown size letter (`%IR3.0`) names the letter (before: "expected
//!   numbers separated by dots");
//! - two CONFIGURATIONs of one name are one E1002 at the second (before: accepted, the trace
//!   repeating `Config0.instance0.n`);
//! - a task whose INTERVAL is longer than the scan cycle is one note W1457 (before: the program
//!   ran every k-th cycle, silently).

mod common;
use common::{check_text, column, in_dir, run_stimulated_files, write_in};

/// A CODESYS V2.3 export of a PLC configuration (a module with a named bit output channel, a
/// byte input channel with two named bits and a named word output channel) and of PLC_PRG,
/// which uses the names and declares none of them.
const V23_IO: &str = "PLC_CONFIGURATION
_GLOBAL
_VERSION: 3
_AUTOADR: 1
_END_GLOBAL

_MODULE: '3S'
_SECTION_NAME: 'Root'
_INDEX_IN_PARENT: '-1'
_MODULE_NAME: 'Demo'
_IECIN: %IB0
_IECOUT: %QB0
_COMMENT: ''

_CHANNEL
_SECTION_NAME: 'BitOutput'
_INDEX_IN_PARENT: '1'
_SYMBOLIC_NAME: 'Lamp'
_COMMENT: 'a lamp'
_CHANNEL_MODE: 'Q'
_IECADR: %QX0.0
_END_CHANNEL

_CHANNEL
_SECTION_NAME: 'ByteInput'
_INDEX_IN_PARENT: '2'
_SYMBOLIC_NAME: ''
_COMMENT: '8 inputs'
_CHANNEL_MODE: 'I'
_IECADR: %IB1.0

_PARAMETER
_PARAM 1: 0, 'Enter name'
_END_PARAMETER
_BIT 0: %IX1.0.0 'Start_Btn' 'start button'
_BIT 1: %IX1.0.1 '' 'Bit 1'
_BIT 2: %IX1.0.2 'Stop_Btn' 'stop button'
_END_CHANNEL

_CHANNEL
_SECTION_NAME: 'WordOutput'
_INDEX_IN_PARENT: '3'
_SYMBOLIC_NAME: 'Speed_Out'
_COMMENT: ''
_CHANNEL_MODE: 'Q'
_IECADR: %QW2.0
_END_CHANNEL
_END_MODULE
PLC_END

(* @NESTEDCOMMENTS := 'Yes' *)
(* @PATH := '' *)
(* @OBJECTFLAGS := '0, 8' *)
PROGRAM PLC_PRG
VAR
    n : UINT;
END_VAR
(* @END_DECLARATION := '0' *)
IF Start_Btn THEN
    Lamp := TRUE;
END_IF;
IF Stop_Btn THEN
    Lamp := FALSE;
END_IF;
IF Lamp THEN
    n := n + 100;
END_IF;
Speed_Out := n;
END_PROGRAM
";

/// A CODESYS V2.3 export's PLC configuration names its channels and bits: `Start_Btn`
/// (`_BIT 0: %IX1.0.0`), `Stop_Btn` (`_BIT 2`), `Lamp` (`%QX0.0`) and `Speed_Out` (`%QW2.0`, a
/// WORD) are global variables at those addresses. Start latches the lamp at cycle 2, stop resets it
/// at 5, the word output counts while the lamp is on; the stimulus drives the names and the addresses read the same values. Before, the section
/// was skipped (W1442) and each use was E1001 "undeclared name".
#[test]
fn v23_plc_configuration_symbolic_names_are_globals_at_their_addresses() {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "Project.EXP", V23_IO);
    let file = dir.path().join("Project.EXP");
    let stim = "2,Start_Btn,1\n3,Start_Btn,0\n5,Stop_Btn,1\n6,Stop_Btn,0\n";
    let (trace, stderr) = run_stimulated_files(
        &[&file],
        &["--cycle-ms", "10"],
        6,
        stim,
        "Lamp,%QX0.0,%IX1.0.0,Speed_Out,%QW2.0",
    );
    assert!(!stderr.contains("E1001"), "{stderr}");
    // one note: the names read, the rest skipped
    let notes: Vec<&str> = stderr.lines().filter(|l| l.contains("W1442")).collect();
    assert_eq!(notes.len(), 1, "{stderr}");
    assert!(
        notes[0].contains("Project.EXP:1:1:") && notes[0].contains("4 symbolic name(s)"),
        "{stderr}"
    );
    // (one row per cycle, from cycle 0)
    assert_eq!(column(&trace, "Lamp"), [0.0, 0.0, 1.0, 1.0, 1.0, 0.0]);
    assert_eq!(column(&trace, "%QX0.0"), [0.0, 0.0, 1.0, 1.0, 1.0, 0.0]);
    assert_eq!(column(&trace, "%IX1.0.0"), [0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
    assert_eq!(
        column(&trace, "Speed_Out"),
        [0.0, 0.0, 100.0, 200.0, 300.0, 300.0]
    );
    assert_eq!(
        column(&trace, "%QW2.0"),
        [0.0, 0.0, 100.0, 200.0, 300.0, 300.0]
    );
}

/// A symbolic name is located at its own place in the configuration: a name also declared in the
/// export's global variable list is one E1002 at the list's declaration, whose "first declared"
/// label points at the name inside the PLC configuration (line 35, column 19 of `_BIT 0: %IX1.0.0
/// 'Start_Btn'` is `Start_Btn`).
#[test]
fn v23_plc_configuration_names_are_located_in_the_section() {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "Project.EXP", V23_IO);
    write_in(
        dir.path(),
        "Globals.EXP",
        "(* @GLOBAL_VARIABLE_LIST := 'Globals' *)\nVAR_GLOBAL\n    Start_Btn : BOOL;\nEND_VAR\n",
    );
    let (code, _, stderr) = in_dir(dir.path(), &["check", "Project.EXP", "Globals.EXP"]);
    assert_eq!(code, Some(1), "{stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].starts_with("Globals.EXP:3:5: error[E1002]")
            && errors[0].contains("`Start_Btn` is declared twice"),
        "{stderr}"
    );
    // the label (human format): the name inside its quotes in the configuration
    let out = common::ladderc()
        .current_dir(dir.path())
        .args(["check", "Project.EXP", "Globals.EXP"])
        .output()
        .unwrap();
    let human = String::from_utf8_lossy(&out.stderr);
    let at = human
        .find("Project.EXP:35:19")
        .expect("the first declaration located");
    assert!(human[at..].contains("first declared here"), "{human}");
}

/// A named channel at an address that is no IEC 61131-3 direct address (`%IR3.0`, an OWEN
/// target's REAL area) is one E0006 at the address in the configuration, naming the size letter;
/// a bit named `'Bit 1'` (no identifier) is one E1086 at the name; neither is declared, and the
/// program's other names still resolve (no E1001).
#[test]
fn v23_plc_configuration_names_that_cannot_be_declared_are_one_located_error_each() {
    let src = V23_IO.replace(
        "_SYMBOLIC_NAME: 'Speed_Out'\n_COMMENT: ''\n_CHANNEL_MODE: 'Q'\n_IECADR: %QW2.0",
        "_SYMBOLIC_NAME: 'Temp_In'\n_COMMENT: ''\n_CHANNEL_MODE: 'I'\n_IECADR: %IR3.0",
    );
    let src = src.replace("Speed_Out := n;", "").replace(
        "_BIT 1: %IX1.0.1 '' 'Bit 1'",
        "_BIT 1: %IX1.0.1 'Bit 1' 'Bit 1'",
    );
    let (code, lines) = check_text("Project.EXP", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 2, "{lines:?}");
    assert!(
        errors
            .iter()
            .any(|e| e.starts_with("Project.EXP:36:19: error[E1086]")
                && e.contains("`Bit 1` is no IEC 61131-3 identifier")),
        "{lines:?}"
    );
    assert!(
        errors
            .iter()
            .any(|e| e.starts_with("Project.EXP:46:10: error[E0006]")
                && e.contains("`Temp_In`")
                && e.contains("size letter `R`")),
        "{lines:?}"
    );
}

/// `udiLastState = q_wState` (a UDINT compared with a WORD, Lugaresi's MQTT client) compares as
/// UDINT, with W1436 as `u = (w + 0)` and the store `x := w` have: 70000 is not 4464 (70000
/// modulo 65536), so the comparison is no WORD comparison; `w1 = w2` stays a WORD comparison,
/// without W1436. Before: E1005 "EQ of UDINT and WORD: the operand does not match the current
/// result".
#[test]
fn a_bit_string_compared_with_a_number_counts_as_its_unsigned_integer() {
    let src = "PROGRAM main
VAR
    w : WORD := 4464; w2 : WORD := 4464; u : UDINT := 70000; x : UDINT;
    same, below, words : BOOL;
END_VAR
same := u = w;
below := w < u;
words := w = w2;
x := w;
u := u - 65536;
END_PROGRAM
";
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "cmp.st", src);
    let file = dir.path().join("cmp.st");
    let (trace, stderr) = run_stimulated_files(
        &[&file],
        &["--cycle-ms", "10"],
        2,
        "",
        "main.same,main.below,main.words,main.x",
    );
    let w1436: Vec<&str> = stderr.lines().filter(|l| l.contains("W1436")).collect();
    assert_eq!(w1436.len(), 1, "{stderr}");
    assert!(w1436[0].contains("cmp.st:6:13:"), "{stderr}");
    assert!(!stderr.contains("error["), "{stderr}");
    // cycle 1: 70000 vs 4464; cycle 2: 4464 vs 4464
    assert_eq!(column(&trace, "main.same"), [0.0, 1.0]);
    assert_eq!(column(&trace, "main.below"), [1.0, 0.0]);
    assert_eq!(column(&trace, "main.words"), [1.0, 1.0]);
    assert_eq!(column(&trace, "main.x"), [4464.0, 4464.0]);
}

/// An INT compared with a WORD stays one E1005 (no type holds both INT and UINT implicitly, as
/// `i := w` stays E1006), at the WORD, in the words of an ST expression: the right operand does
/// not match the left one (before: "the current result", IL's word).
#[test]
fn an_int_compared_with_a_word_stays_one_error_in_st_words() {
    let (code, lines) = check_text(
        "cmp.st",
        "PROGRAM main\nVAR i : INT; w : WORD; b : BOOL; END_VAR\nb := i = w;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("cmp.st:3:10: error[E1005]") && !errors[0].contains("current result"),
        "{lines:?}"
    );
}

/// `ai0 AT %IR3.0 : REAL` (kaapyth0n/OWEN): one E0006 at the address, naming the size letter `R`
/// and IEC's X B W D L (before: "is not a valid location: expected numbers separated by dots",
/// though the location `3.0` is fine).
#[test]
fn an_unknown_size_letter_is_named() {
    let (code, lines) = check_text(
        "io.st",
        "PROGRAM main\nVAR\n    ai0 AT %IR3.0 : REAL;\n    x : REAL;\nEND_VAR\nx := ai0;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("io.st:3:12: error[E0006]")
            && errors[0].contains("size letter `R`")
            && errors[0].contains("X, B, W, D, L")
            && !errors[0].contains("numbers separated by dots"),
        "{lines:?}"
    );
}

/// Two CONFIGURATIONs named `Config0` (three OpenPLC projects given together, vjescy's
/// ICSHoneypot) are one E1002 at the second one's name, the first labelled (before: accepted,
/// the trace repeating the column `Config0.instance0.n` and `--watch` picking the first).
#[test]
fn two_configurations_of_one_name_are_one_error_at_the_second() {
    let src = "PROGRAM A
  VAR n : INT := 1; END_VAR
  n := n + 1;
END_PROGRAM

PROGRAM B
  VAR n : INT := 100; END_VAR
  n := n + 100;
END_PROGRAM

CONFIGURATION Config0
  RESOURCE Res0 ON PLC
    TASK task0(INTERVAL := T#10ms, PRIORITY := 0);
    PROGRAM instance0 WITH task0 : A;
  END_RESOURCE
END_CONFIGURATION

CONFIGURATION Config0
  RESOURCE Res0 ON PLC
    TASK task0(INTERVAL := T#10ms, PRIORITY := 0);
    PROGRAM instance0 WITH task0 : B;
  END_RESOURCE
END_CONFIGURATION
";
    let (code, lines) = check_text("two.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("two.st:18:15: error[E1002]")
            && errors[0].contains("configuration `Config0` is declared twice"),
        "{lines:?}"
    );
    // renamed, both run, each under its own name
    let dir = tempfile::tempdir().unwrap();
    let renamed = src.replacen(
        "CONFIGURATION Config0\n  RESOURCE Res0 ON PLC\n    TASK task0(INTERVAL := T#10ms, PRIORITY := 0);\n    PROGRAM instance0 WITH task0 : B;",
        "CONFIGURATION Config1\n  RESOURCE Res0 ON PLC\n    TASK task0(INTERVAL := T#10ms, PRIORITY := 0);\n    PROGRAM instance0 WITH task0 : B;",
        1,
    );
    write_in(dir.path(), "two.st", &renamed);
    let (trace, _) = run_stimulated_files(
        &[dir.path().join("two.st")],
        &["--cycle-ms", "10"],
        2,
        "",
        "Config0.instance0.n,Config1.instance0.n",
    );
    assert_eq!(column(&trace, "Config0.instance0.n"), [2.0, 3.0]);
    assert_eq!(column(&trace, "Config1.instance0.n"), [200.0, 300.0]);
}

/// A task of INTERVAL T#20ms run with `--cycle-ms 10` runs in every other cycle: one note W1457
/// at the task says so (before: silent, the counter's trace looking wrong); with `--cycle-ms 20`
/// there is no note and the counter counts every cycle.
#[test]
fn a_task_slower_than_the_cycle_is_one_note() {
    let src = "PROGRAM Counter
  VAR n : INT; END_VAR
  n := n + 1;
END_PROGRAM

CONFIGURATION Cfg
  RESOURCE Res ON PLC
    TASK slow(INTERVAL := T#20ms, PRIORITY := 1);
    TASK idle(INTERVAL := T#50ms, PRIORITY := 2);
    PROGRAM inst WITH slow : Counter;
  END_RESOURCE
END_CONFIGURATION
";
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "slow.st", src);
    let file = dir.path().join("slow.st");
    let (trace, stderr) = run_stimulated_files(&[&file], &["--cycle-ms", "10"], 6, "", "inst.n");
    let notes: Vec<&str> = stderr.lines().filter(|l| l.contains("W1457")).collect();
    // one note, for the task with a program (`idle` runs nothing)
    assert_eq!(notes.len(), 1, "{stderr}");
    assert!(
        notes[0].contains("slow.st:8:5:")
            && notes[0].contains("task `slow`")
            && notes[0].contains("one cycle of every 2"),
        "{stderr}"
    );
    assert_eq!(column(&trace, "inst.n"), [1.0, 1.0, 2.0, 2.0, 3.0, 3.0]);
    let (trace, stderr) = run_stimulated_files(&[&file], &["--cycle-ms", "20"], 3, "", "inst.n");
    assert!(!stderr.contains("W1457"), "{stderr}");
    assert_eq!(column(&trace, "inst.n"), [1.0, 2.0, 3.0]);
}
