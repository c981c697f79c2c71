//! Round 33 of unseen projects (issue #13), plain Structured Text points, run end to end through
//! `ladderc run` / `ladderc check`:
//! - a PROGRAM's initial value computed at run time (W1433, `mode : INT := base;`) is assigned
//!   before the first cycle, so a stimulus row at cycle 0 sets the variable (README: stimulus rows
//!   are "applied before that cycle"; before: the value was assigned at the program's first run,
//!   after the cycle-0 row, which it overwrote);
//! - an `.st` file of expression or call statements outside any POU (`table[k];`, `F(a, b);`) is
//!   one E0307 (before: read as IL, an E0011 and an E0007 per line);
//! - a VAR_INPUT block written before its `PROGRAM` header is one E1102 at the block, its names'
//!   uses in the program not reported again (before: W0001 and an E1001 per use);
//! - an empty 4CONTROL `CONST ... END_CONST` in a `.cst` file is the one E1095 of a non-empty one
//!   (before: read as IL, "unknown function `CONST`");
//! - an S7-SCL block (`FUNCTION_BLOCK "Counter"`, a quoted block name) is one E0023 naming SCL,
//!   also with SCL's `CONST` section (before: E1095 naming 4CONTROL, or three scattered errors).

mod common;
use common::{check_text, column, run_stimulated};

/// A cycle-0 stimulus row of a variable whose initial value reads another variable (W1433, as
/// CODESYS and TwinCAT initialise it: when the instance is initialised) sets it for cycle 0, as it
/// does for a variable with a literal initial value; the value computed at initialisation holds
/// when no row is given (`other`). Before round 33 the program's first run computed `mode` after
/// the row was applied: cycle 0 saw `mode = 1`, not 5.
#[test]
fn cycle0_stimulus_wins_over_a_run_time_initial_value() {
    let src = "PROGRAM main
VAR
    base : INT := 1;
    mode : INT := base;
    other : INT := base + 10;
    plain : INT := 1;
    seen_mode : INT;
    seen_plain : INT;
    seen_other : INT;
END_VAR
seen_mode := mode;
seen_plain := plain;
seen_other := other;
mode := mode + 1;
END_PROGRAM
";
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("mode.st");
    std::fs::write(&file, src).unwrap();
    let (trace, err) = run_stimulated(
        &file,
        3,
        "0,main.mode,5\n0,main.plain,5\n",
        "main.mode,main.seen_mode,main.seen_plain,main.seen_other",
    );
    assert!(err.contains("W1433"), "{err}");
    assert_eq!(column(&trace, "main.seen_mode"), [5.0, 6.0, 7.0], "{trace}");
    assert_eq!(column(&trace, "main.mode"), [6.0, 7.0, 8.0], "{trace}");
    assert_eq!(
        column(&trace, "main.seen_plain"),
        [5.0, 5.0, 5.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "main.seen_other"),
        [11.0, 11.0, 11.0],
        "{trace}"
    );
}

/// The same in a function block instance of the program: its computed initial value is assigned
/// when the instance is initialised, before cycle 0, so the row `0,main.fb.limit,7` holds at
/// cycle 0 (this already worked; kept with the program's case).
#[test]
fn cycle0_stimulus_of_a_block_instance_with_a_run_time_initial_value() {
    let src = "FUNCTION_BLOCK FB_Limit
VAR
    base : INT := 2;
    limit : INT := base * 2;
END_VAR
VAR_OUTPUT
    seen : INT;
END_VAR
seen := limit;
END_FUNCTION_BLOCK
PROGRAM main
VAR
    fb : FB_Limit;
    out : INT;
END_VAR
fb();
out := fb.seen;
END_PROGRAM
";
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("limit.st");
    std::fs::write(&file, src).unwrap();
    let (trace, _) = run_stimulated(&file, 2, "0,main.fb.limit,7\n", "main.out");
    assert_eq!(column(&trace, "main.out"), [7.0, 7.0], "{trace}");
}

/// A `.st` file of expression statements and a call statement with no POU around them (a
/// generated snippet, tkucic/plc_PremadeHashTable's `code.st`): one E0307 "statements outside any
/// POU" at the first line (before round 33: read as IL, an E0011 "unexpected `[`" and an E0007
/// "`;` comments" per line, 205 errors in the real file).
#[test]
fn expression_statements_outside_a_pou_are_one_e0307() {
    let src = "table[k];\ntable[1];\nDSUB(TRUE, dwNow, dwStart, result);\n";
    let (code, lines) = check_text("code.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("code.st:1:1: error[E0307]: statements outside any POU"),
        "{lines:?}"
    );
    assert!(!lines
        .iter()
        .any(|l| l.contains("E0007") || l.contains("E0011")));
}

/// VAR and VAR_INPUT blocks written before the `PROGRAM` header (iotrustlab/CrossPLC): one E1102 at
/// the VAR_INPUT keyword, naming the block and the POU to move it into; the program's uses of
/// `start` and `level` report nothing more (before round 33: W0001 "instructions outside any POU"
/// and an E1001 "undeclared name" per use, 12 in the real file).
#[test]
fn interface_block_before_the_program_header_is_one_error() {
    let src = "VAR
    level : REAL;
END_VAR
VAR_INPUT
    start : BOOL;
END_VAR
PROGRAM tank
    IF start THEN
        level := level + 1.0;
    END_IF;
END_PROGRAM
";
    let (code, lines) = check_text("tank.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "tank.st:4:1: error[E1102]: a VAR_INPUT block outside any POU: it belongs after a POU's header"
        ),
        "{lines:?}"
    );
    assert!(!lines
        .iter()
        .any(|l| l.contains("E1001") || l.contains("W0001")));
}

/// An empty 4CONTROL block of constants in a `.cst` file (MECT's `Resource1.cst`) is one E1095
/// naming 4CONTROL, as a non-empty one is (before round 33: read as IL, E1019 "unknown function
/// `CONST`" and `END_CONST`, W0001).
#[test]
fn empty_four_control_constants_file_is_one_e1095() {
    let (code, lines) = check_text("Resource1.cst", "CONST\n\n\t\nEND_CONST\n");
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("Resource1.cst:1:1: error[E1095]: `CONST ... END_CONST`"),
        "{lines:?}"
    );
}

/// An S7-SCL block with a quoted name, SCL's `CONST` section and `BEGIN`: one E0023 naming Siemens
/// SCL at the quoted header (before round 33: E1095 naming 4CONTROL at `CONST`); without the
/// `CONST` section the same one E0023 (before: E0307 inside the header, E0011, E0008).
#[test]
fn scl_block_with_quoted_name_is_one_e0023() {
    let with_const = "FUNCTION_BLOCK \"Counter\"
   VAR_INPUT
      start : Bool;
   END_VAR
   VAR
      count : Int;
   END_VAR
   CONST
      MAX_COUNT := 100;
   END_CONST
BEGIN
   IF start AND count < MAX_COUNT THEN
      count := count + 1;
   END_IF;
END_FUNCTION_BLOCK
";
    let without_const = "FUNCTION_BLOCK \"Counter\"
   VAR_INPUT
      start : Bool;
   END_VAR
BEGIN
   IF start THEN
      start := FALSE;
   END_IF;
END_FUNCTION_BLOCK
";
    for src in [with_const, without_const] {
        let (code, lines) = check_text("counter.scl", src);
        assert_eq!(code, Some(1), "{lines:?}");
        assert_eq!(lines.len(), 1, "{lines:?}");
        assert!(
            lines[0].starts_with("counter.scl:1:1: error[E0023]: this file is Siemens SCL"),
            "{lines:?}"
        );
        assert!(lines[0].contains("FUNCTION_BLOCK \"Counter\""), "{lines:?}");
    }
}
