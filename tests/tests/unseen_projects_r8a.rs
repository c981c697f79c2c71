//! Issue #13, eighth round (helper `lang5`): four forms real projects write that ladderc refused.
//! Each case is a small program written here, in `tests/fixtures/unseen/`, run through `ladderc run`
//! (traces) or `ladderc check`:
//! - **`END_STRUCT END_TYPE` without `;`** (CODESYS and TwinCAT DUTs, `(A, B) END_TYPE`,
//!   `T : INT (0..100) END_TYPE`): IEC 61131-3's grammar ends each type declaration with `;`, so it
//!   is warning W0013, and the types work. Before: E0011 "expected `;` before `END_TYPE`".
//! - **An XML POU whose interface declares `POINTER TO` / `REFERENCE TO`** (a CODESYS export):
//!   then one E0305 for the POU and the body not compiled; since the `refs` helper the body is
//!   compiled and what stays refused (a VAR_IN_OUT of a reference type, since issue #13's pointer
//!   round; pointer arithmetic too before it) is located. Before: E3012 per
//!   declaration and a cascade from the body (`^`).
//! - **Hierarchical direct addresses** (`%IX1.0.0`, `%IW0.0`, `%QW0.0.0.0`): each distinct one is
//!   a slot of its own after the profile's area (see the c-backend README, "Hierarchical
//!   addresses"); stimulus and trace name it by its text, and two variables at one address alias
//!   (ST and XML). Before: E2002.
//! - **VAR_ACCESS** in a configuration (IEC 61131-3 access paths) of an ST or IL file, and a PLCopen
//!   XML configuration's `<accessVars>`: each path is checked (E0308, located) and its name is a
//!   trace/stimulus name; READ_ONLY refuses a stimulus. Before: E0019 (XML: not read).

mod common;
use common::{column, ladderc, run_traced, unseen_fixture};

/// `ladderc check FILE` (short format): exit code and the error and warning lines.
fn check(name: &str) -> (Option<i32>, Vec<String>) {
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(unseen_fixture(name))
        .output()
        .unwrap();
    let lines = String::from_utf8_lossy(&out.stderr)
        .lines()
        .filter(|l| l.contains("error[") || l.contains("warning["))
        .map(str::to_string)
        .collect();
    (out.status.code(), lines)
}

/// The tank fills by 20 per scan up to the structure's initial `high_limit` (80), then the
/// enumeration's FULL state sets the flag: the structure, the enumeration and the subrange all come
/// from TYPE blocks whose last declaration has no `;`. Each of the three gets W0013 at its `END_TYPE`.
#[test]
fn codesys_types_without_semicolon_before_end_type_run() {
    let (trace, stderr) = run_traced(
        &unseen_fixture("codesys_types_without_semicolon.st"),
        7,
        "PLC_PRG.tank.level,PLC_PRG.tank.filling,PLC_PRG.tank_full",
    );
    assert_eq!(
        column(&trace, "PLC_PRG.tank.level"),
        [0.0, 20.0, 40.0, 60.0, 80.0, 80.0, 80.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "PLC_PRG.tank.filling"),
        [1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "PLC_PRG.tank_full"),
        [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0],
        "{trace}"
    );
    let w: Vec<&str> = stderr.lines().filter(|l| l.contains("W0013")).collect();
    assert_eq!(w.len(), 3, "{stderr}");
    for at in [
        ":9:1: warning[W0013]",
        ":11:43: warning[W0013]",
        ":13:31: warning[W0013]",
    ] {
        assert!(w.iter().any(|l| l.contains(at)), "{at}: {stderr}");
    }
}

/// A `;` missing between two declarations of one TYPE block is still a syntax error: only the one
/// before `END_TYPE` is supplied.
#[test]
fn only_the_semicolon_before_end_type_is_supplied() {
    let (code, lines) = common::check_text(
        "two.st",
        "TYPE A : INT END_TYPE\nTYPE B : INT; C : BOOL D : INT; END_TYPE\nPROGRAM p\nVAR x : A; END_VAR\nx := 1;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines
            .iter()
            .any(|l| l.contains("two.st:1:14: warning[W0013]")),
        "{lines:?}"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.contains("two.st:2:") && l.contains("error[E0011]")),
        "{lines:?}"
    );
}

/// The function block declares `pSamples : POINTER TO INT` and `total : REFERENCE TO DINT` (a
/// VAR_IN_OUT), and its body steps the pointer with `SIZEOF`. Since the `refs` helper the body is
/// compiled (`tests/tests/refs_run.rs`); since issue #13's pointer round the step
/// (`pSamples + SIZEOF(...)`) and `ADR` of an array passed for a pointer to INT compile too
/// (`tests/tests/pointer_index_run.rs`), and what CODESYS allows and ladderc refuses is one located
/// error: a VAR_IN_OUT of a reference type. Before: one E0305 for the POU, its body not compiled;
/// then three errors (the step, the array's address, the VAR_IN_OUT).
#[test]
fn xml_pou_with_pointer_declarations_is_one_located_error() {
    let (code, lines) = check("codesys_pointer_fb.xml");
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].contains("codesys_pointer_fb.xml:60:58: error[E0305]"),
        "{}",
        errors[0]
    );
    assert!(
        errors[0]
            .contains("`total` of `FB_Average` is a VAR_IN_OUT of a reference type: not supported"),
        "{}",
        errors[0]
    );
}

/// A pump started by a push button on remote I/O (`%IX1.0.0`, stop `%IX1.0.1`), its speed from an
/// analog input (`%IW0.0`) to an analog output (`%QW0.0.0.0`): the stimulus sets the hierarchical
/// inputs by their text, the trace reads the outputs so, and `start_again`, declared at the same
/// address as `start_pb`, reads the same bit.
#[test]
fn hierarchical_addresses_run_and_alias() {
    let trace = common::run_with_stimulus(
        &unseen_fixture("hierarchical_addresses.st"),
        7,
        "0,%IW0.0,400\n1,%IX1.0.0,TRUE\n2,%IX1.0.0,FALSE\n3,%IW0.0,800\n4,%IX1.0.1,TRUE\n5,%IX1.0.1,FALSE\n",
        &[
            "pump_station.running",
            "pump_station.starts",
            "pump_station.start_again",
            "%QW0.0.0.0",
            "%QX1.0.0",
            "%ix1.0.0",
        ],
    );
    assert_eq!(
        column(&trace, "pump_station.running"),
        [0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "pump_station.start_again"),
        [0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "pump_station.starts"),
        [0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "%QW0.0.0.0"),
        [0.0, 100.0, 100.0, 200.0, 0.0, 0.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "%QX1.0.0"),
        [0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0],
        "{trace}"
    );
}

/// Distinct hierarchical addresses never share bytes: `%MW0.1` is not `%MW0.0` nor `%MW0`, and
/// `%MB0.0` is not `%MW0.0`.
#[test]
fn distinct_hierarchical_addresses_do_not_overlap() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("slots.st");
    std::fs::write(
        &f,
        "PROGRAM p\nVAR\n  a AT %MW0.0 : INT;\n  b AT %MW0.1 : INT;\n  c AT %MW0 : INT;\n  d AT %MB0.0 : BYTE;\n  e AT %MX0.0.0 : BOOL;\n  f AT %MX0.0.1 : BOOL;\nEND_VAR\na := 1111; b := 2222; c := 3333; d := 16#44; e := TRUE; f := FALSE;\nEND_PROGRAM\n",
    )
    .unwrap();
    let (trace, _) = run_traced(&f, 1, "%MW0.0,%MW0.1,%MW0,%MB0.0,%MX0.0.0,%MX0.0.1");
    assert_eq!(
        trace.lines().nth(1),
        Some("0,0,1111,2222,3333,68,1,0"),
        "{trace}"
    );
}

/// What stays E2002, each located with a hint: a variable larger than its hierarchical address's
/// size, a bit number above 7 in `%IX1.9`; and a run that names a hierarchical address the program
/// does not use is refused.
#[test]
fn unsupported_address_forms_stay_located_errors() {
    let (code, lines) = common::check_text(
        "bad.st",
        "PROGRAM p\nVAR\n  a AT %IW0.0 : DINT;\n  b AT %IX1.9 : BOOL;\nEND_VAR\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines.iter().any(|l| l.contains("bad.st:3:8: error[E2002]")
            && l.contains("holds 2 byte(s); the variable needs 4")),
        "{lines:?}"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.contains("bad.st:4:8: error[E2002]") && l.contains("bit number")),
        "{lines:?}"
    );
    let out = ladderc()
        .args(["run"])
        .arg(unseen_fixture("hierarchical_addresses.st"))
        .args(["--cycles", "1", "--watch", "%IX9.9.9"])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Access paths of an ST configuration: the stimulus sets `speed_setpoint` (READ_WRITE, the
/// program's `setpoint`), the ramp follows in steps of 10, and the trace reads it through
/// `belt_speed` (a member of an FB instance), `belt_running` (a structure's member, path without
/// the resource), `belt_drive.speed` (a whole structure) and `alarm_lamp` (a direct address).
#[test]
fn var_access_paths_are_trace_and_stimulus_names() {
    let trace = common::run_with_stimulus(
        &unseen_fixture("var_access.st"),
        9,
        "1,speed_setpoint,30\n5,speed_setpoint,0\n",
        &[
            "speed_setpoint",
            "belt_speed",
            "belt_running",
            "belt_drive.speed",
            "alarm_lamp",
            "line.setpoint",
        ],
    );
    let ramp = [0.0, 10.0, 20.0, 30.0, 30.0, 20.0, 10.0, 0.0, 0.0];
    assert_eq!(column(&trace, "belt_speed"), ramp, "{trace}");
    assert_eq!(column(&trace, "belt_drive.speed"), ramp, "{trace}");
    assert_eq!(
        column(&trace, "belt_running"),
        [0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0],
        "{trace}"
    );
    // the access name and the program's own variable are one variable
    assert_eq!(
        column(&trace, "speed_setpoint"),
        column(&trace, "line.setpoint"),
        "{trace}"
    );
    assert_eq!(column(&trace, "alarm_lamp"), [0.0; 9], "{trace}");
}

/// READ_ONLY (written, or by default) refuses a stimulus row, for the access name and for a member
/// of a structured one; the run stops before any cycle with the row's line.
#[test]
fn read_only_access_paths_refuse_writes() {
    for (name, row) in [
        ("belt_speed", "1,belt_speed,30"),
        ("belt_running", "1,belt_running,TRUE"),
        ("belt_drive.speed", "1,belt_drive.speed,5"),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let stim = dir.path().join("s.csv");
        std::fs::write(&stim, format!("cycle,variable,value\n{row}\n")).unwrap();
        let out = ladderc()
            .arg("run")
            .arg(unseen_fixture("var_access.st"))
            .args(["--cycles", "3", "--stimulus"])
            .arg(&stim)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{name}: {err}");
        assert!(
            err.contains(&format!("s.csv:2: `{name}` is a READ_ONLY access path")),
            "{name}: {err}"
        );
    }
}

/// The same in an IL file: the configuration's access paths read the counter and clear it.
#[test]
fn var_access_in_an_il_configuration() {
    let trace = common::run_with_stimulus(
        &unseen_fixture("var_access.il"),
        6,
        "3,clear_parts,TRUE\n4,clear_parts,FALSE\n",
        &["parts", "clear_parts"],
    );
    assert_eq!(
        column(&trace, "parts"),
        [1.0, 2.0, 3.0, 0.0, 1.0, 2.0],
        "{trace}"
    );
}

/// PLCopen XML (tc6_0201): a configuration's `<accessVars>` are the same access paths
/// (`direction="readWrite"`, `"readOnly"`, none = READ_ONLY).
#[test]
fn xml_access_vars_are_access_paths() {
    let trace = common::run_with_stimulus(
        &unseen_fixture("var_access_tc6.xml"),
        5,
        "0,fill_rate,30\n",
        &["fill_rate", "tank_level", "tank_high"],
    );
    assert_eq!(
        column(&trace, "tank_level"),
        [30.0, 60.0, 90.0, 120.0, 150.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "tank_high"),
        [0.0, 0.0, 0.0, 1.0, 1.0],
        "{trace}"
    );
}

/// Each wrong access path is one located E0308 saying what is wrong.
#[test]
fn wrong_access_paths_are_located_errors() {
    let src = std::fs::read_to_string(unseen_fixture("var_access.st")).unwrap().replace(
        "speed_setpoint : cpu.line.setpoint : INT READ_WRITE;",
        "speed_setpoint : cpu.line.setpoint : DINT READ_WRITE;\n        ghost : cpu.line.nothing : INT;\n        ghost2 : cpu.other.x : INT;\n        ghost3 : line.ramp.foo : INT;\n        speed_setpoint : line.setpoint : INT;",
    );
    let (code, lines) = common::check_text("access.st", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    let expect = [
        "access.st:44:9: error[E0308]: access path `speed_setpoint`: the variable is INT, the access path says DINT",
        "access.st:45:9: error[E0308]: access path `ghost`: program `conveyor` has no variable `nothing`",
        "access.st:46:9: error[E0308]: access path `ghost2`: no program instance or global variable `other` in this configuration",
        "access.st:47:9: error[E0308]: access path `ghost3`: `FB_Ramp` has no member `foo`",
        "access.st:48:9: error[E0308]: access path `speed_setpoint`: the access name `speed_setpoint` is declared twice",
    ];
    assert_eq!(lines.len(), expect.len(), "{lines:?}");
    for (l, e) in lines.iter().zip(expect) {
        assert!(l.starts_with(e), "{l}\nexpected {e}");
    }
    let (code, lines) = common::check_text(
        "dir.st",
        &std::fs::read_to_string(unseen_fixture("var_access.st"))
            .unwrap()
            .replace("INT READ_WRITE;", "INT READ_SOMETIMES;"),
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("dir.st:44:9: error[E0308]: this VAR_ACCESS entry cannot be read: the direction is READ_WRITE or READ_ONLY"),
        "{lines:?}"
    );
}

/// A PLCopen XML variable at a hierarchical address (`address="%IW2.0.1"`), reached both by its
/// address and by an access path that names the variable.
#[test]
fn xml_variable_at_a_hierarchical_address() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("h.xml");
    let src = std::fs::read_to_string(unseen_fixture("var_access_tc6.xml"))
        .unwrap()
        .replace(
            r#"<variable name="inflow"><type><INT/></type></variable>"#,
            r#"<variable name="inflow" address="%IW2.0.1"><type><INT/></type></variable>"#,
        );
    assert!(src.contains("%IW2.0.1"));
    std::fs::write(&f, src).unwrap();
    let trace = common::run_with_stimulus(
        &f,
        3,
        "0,%IW2.0.1,7\n",
        &["fill_rate", "tank_level", "%IW2.0.1"],
    );
    assert_eq!(column(&trace, "fill_rate"), [7.0, 7.0, 7.0], "{trace}");
    assert_eq!(column(&trace, "tank_level"), [7.0, 14.0, 21.0], "{trace}");
}
