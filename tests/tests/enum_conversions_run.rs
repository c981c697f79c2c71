//! Issue #13: conversions of enumerated values as CODESYS and TwinCAT document them (Beckhoff
//! Infosys "TO_STRING/TO_WSTRING for enumeration variables" and "Attribute 'to_string'", CODESYS
//! "Attribute: to_string"). `TO_STRING(eState)` / `TO_WSTRING(eState)` give the value's name when the
//! enumeration is declared under `{attribute 'to_string'}`, its number otherwise; `TO_INT(eState)`
//! and the other `TO_<integer or bit string>` give its number. IEC 61131-3 defines no conversion of
//! an enumerated type, so only these overloaded `TO_` forms take one (`TO_REAL` stays E1004).
//! Before: E1004 "IEC 61131-3 defines no such conversion" at each (TwinCAT projects log state
//! machines with `TO_STRING(eState)`: 24 uses in one mirrored project).

mod common;
use common::{column, ladderc, run_traced, run_traced_files};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    common::repo_root()
        .join("tests/tests/fixtures/enum_conversions")
        .join(name)
}

/// The short-format diagnostics of `ladderc check` on a fixture that must be rejected (exit 1).
fn rejected(name: &str) -> String {
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(fixture(name))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// to_string.st: `s : E_Sample` (under `{attribute 'to_string'}`, eInit := 0, eStart, eStop) is
/// eInit in scan 0 and eStop from scan 1; `p : E_Plain := C` (no attribute; A, B := 7, C) is 8.
/// `Pick(k)` returns eStart for k <= 1, eStop after. Each conversion, under the sanitizers.
#[test]
fn enumerated_values_convert_to_their_names_or_numbers() {
    let (trace, _) = run_traced(
        &fixture("to_string.st"),
        3,
        "Main.txt,Main.txt2,Main.txt3,Main.txt4,Main.w,Main.n,Main.d",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.txt,Main.txt2,Main.txt3,Main.txt4,Main.w,Main.n,Main.d\n\
         0,0,\"eInit\",\"8\",\"eStart\",\"eStart\",\"eInit\",8,0\n\
         1,10,\"eStop\",\"8\",\"eStart\",\"eStop\",\"eStop\",8,2\n\
         2,20,\"eStop\",\"8\",\"eStart\",\"eStop\",\"eStop\",8,2\n"
    );
    assert_eq!(column(&trace, "Main.n"), [8.0, 8.0, 8.0]);
}

/// The TwinCAT 3 form: the attribute in a `.TcDUT` above `TYPE E_Phase`, beside `qualified_only`
/// and `strict` (`qualified_only` stays a W0301 note; `strict` is read since Session 36: W1439 /
/// `tests/tests/codesys_loose_types_run.rs`), the conversions in a `.TcPOU`.
#[test]
fn a_twincat_enumeration_under_to_string_gives_names() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("E_Phase.TcDUT"), &fixture("MAIN.TcPOU")],
        1,
        "MAIN.nCurrentValue,MAIN.sCurrentValue,MAIN.wsCurrentValue,MAIN.sComponent,MAIN.wsComponent",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,MAIN.nCurrentValue,MAIN.sCurrentValue,MAIN.wsCurrentValue,MAIN.sComponent,MAIN.wsComponent\n\
         0,0,0,\"ePhaseIdle\",\"ePhaseIdle\",\"ePhaseFill\",\"ePhaseDrain\"\n"
    );
    assert!(
        !stderr.contains("'to_string'}` is informational"),
        "{stderr}"
    );
    assert!(
        stderr.contains("`{attribute 'qualified_only'}` is informational"),
        "{stderr}"
    );
    assert!(!stderr.contains("'strict'}` is informational"), "{stderr}");
}

/// `TO_REAL` of an enumerated value: no vendor documents it, IEC defines none: one located E1004.
#[test]
fn to_real_of_an_enumerated_value_is_e1004() {
    let err = rejected("to_real.st");
    assert!(
        err.contains("to_real.st:7:6: error[E1004]: TO_REAL cannot convert E_Valve"),
        "{err}"
    );
    assert_eq!(err.matches("error[").count(), 1, "{err}");
}

/// An enumerated value beyond 32 bits, written (`Huge := 99999999999`) or counted on from the one
/// before (`Beyond` after 2147483647): ladderc stores an enumeration as a DINT, so each is one
/// located E1017. Before: accepted, and `Huge` ran as 1215752191.
#[test]
fn an_enumerated_value_beyond_32_bits_is_e1017() {
    let err = rejected("too_big.st");
    assert!(
        err.contains("too_big.st:1:45: error[E1017]: enumerated value `Huge` = 99999999999 does not fit an enumeration's 32 bits"),
        "{err}"
    );
    assert!(
        err.contains(
            "too_big.st:6:31: error[E1017]: enumerated value `Beyond` = 2147483648 does not fit"
        ),
        "{err}"
    );
    assert_eq!(err.matches("error[").count(), 2, "{err}");
}
