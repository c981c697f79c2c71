//! CODESYS's implicit SFC flags (issue #13: nothing dropped silently). A CODESYS export enables the
//! flags of a chart in the vendor data of its POU or action (`SFCSettings/Flags`, `Use="true"`);
//! before, ladderc read `SFCInit` and `SFCReset` as plain variables and the chart's reset did
//! nothing. The fixture is written here (`tests/fixtures/unseen/codesys_sfc_flags.xml`): program
//! `Chain` (an SFC body: Init -> S1 -> S2 on `go`, S2 -> Init on `back`; Init runs `Count` (N),
//! S2 sets `lamp` (S); SFCInit declared implicitly, SFCReset in the interface, SFCPause enabled)
//! and program `Seq` (its action `Steps`, an SFC body called every scan: A -> B -> C on `go`, A
//! runs `Tally` (N); both flags declared in the interface, enabled in the action's own settings).
//! Each test runs `ladderc run` (C compiled with the sanitizers) or `ladderc check`:
//! - SFCReset TRUE for one scan puts the chart back in its initial step, resets the stored action
//!   and step times, and the chart goes on from there in the same scan (Init's action runs);
//! - SFCInit held TRUE keeps the chart in its initial step, runs none of its actions and fires no
//!   transition until it is released;
//! - the same for a chart that is the body of an action;
//! - an enabled flag ladderc does not implement is one located W3402 (exit 0); an enabled flag
//!   without a BOOL variable is E3403.

mod common;
use common::{check_text, ladderc, run_stimulated};
use std::path::{Path, PathBuf};

fn fixture() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/unseen/codesys_sfc_flags.xml")
}

/// [`run_stimulated`] of the fixture, asserting also that nothing was reported as an error.
fn run(cycles: u32, stimulus: &str, watch: &str) -> (String, String) {
    let (trace, stderr) = run_stimulated(&fixture(), cycles, stimulus, watch);
    assert!(!stderr.contains("error"), "{stderr}");
    (trace, stderr)
}

const CHAIN: &str = "Chain.__sfc_X_Init,Chain.__sfc_X_S1,Chain.__sfc_X_S2,Chain.lamp,Chain.n,\
                     Chain.__sfc_T_Init";

/// `go` from cycle 1 to 2 takes the chart to S2 (lamp set) by cycle 2; SFCReset TRUE in cycle 4
/// only: Init again, lamp reset, S2 left, Init's Count runs in that scan (n 3) and the next; `go`
/// in cycle 6 leaves Init as before (Count's final scan, n 5).
#[test]
fn sfc_reset_for_one_scan_goes_back_to_the_initial_step_and_continues() {
    let (trace, _) = run(
        9,
        "1,Chain.go,TRUE\n3,Chain.go,FALSE\n4,Chain.SFCReset,TRUE\n5,Chain.SFCReset,FALSE\n\
         6,Chain.go,TRUE\n",
        CHAIN,
    );
    assert_eq!(
        trace,
        format!(
            "cycle,time_ms,{}\n\
             0,0,1,0,0,0,1,T#0ms\n\
             1,10,0,1,0,0,2,T#10ms\n\
             2,20,0,0,1,1,2,T#10ms\n\
             3,30,0,0,1,1,2,T#10ms\n\
             4,40,1,0,0,0,3,T#0ms\n\
             5,50,1,0,0,0,4,T#10ms\n\
             6,60,0,1,0,0,5,T#20ms\n\
             7,70,0,0,1,1,5,T#20ms\n\
             8,80,0,0,1,1,5,T#20ms\n",
            CHAIN.replace(' ', "")
        )
    );
}

/// `go` stays TRUE from cycle 1: S2 by cycle 2. SFCInit (declared implicitly, as the settings'
/// `Declare="true"` asks) TRUE from cycle 4 to 6: Init active, S1/S2 inactive, lamp reset, Init.T
/// 0, Count not run (n stays 2) and no transition fires although `go` is TRUE; released in cycle 7,
/// the chart leaves Init in that scan.
#[test]
fn sfc_init_held_keeps_the_chart_in_its_initial_step_until_released() {
    let (trace, _) = run(
        10,
        "1,Chain.go,TRUE\n4,Chain.SFCInit,TRUE\n7,Chain.SFCInit,FALSE\n",
        CHAIN,
    );
    assert_eq!(
        trace,
        format!(
            "cycle,time_ms,{}\n\
             0,0,1,0,0,0,1,T#0ms\n\
             1,10,0,1,0,0,2,T#10ms\n\
             2,20,0,0,1,1,2,T#10ms\n\
             3,30,0,0,1,1,2,T#10ms\n\
             4,40,1,0,0,0,2,T#0ms\n\
             5,50,1,0,0,0,2,T#0ms\n\
             6,60,1,0,0,0,2,T#0ms\n\
             7,70,0,1,0,0,2,T#10ms\n\
             8,80,0,0,1,1,2,T#10ms\n\
             9,90,0,0,1,1,2,T#10ms\n",
            CHAIN.replace(' ', "")
        )
    );
}

/// The chart of action `Steps` (flags enabled in the action's own settings, variables declared
/// in the POU): C by cycle 2; SFCReset in cycle 3 only puts it back in A, where Tally runs (n 3,
/// 4); `go` again from cycle 5 takes it to C by cycle 6; SFCInit in cycles 7 and 8 holds it in A
/// without running Tally, and it leaves A in cycle 9.
#[test]
fn the_flags_reset_and_hold_the_chart_of_an_sfc_action() {
    let watch = "Seq.__sfc_Steps__X_A,Seq.__sfc_Steps__X_B,Seq.__sfc_Steps__X_C,Seq.n";
    let (trace, _) = run(
        11,
        "1,Seq.go,TRUE\n3,Seq.go,FALSE\n3,Seq.SFCReset,TRUE\n4,Seq.SFCReset,FALSE\n\
         5,Seq.go,TRUE\n7,Seq.SFCInit,TRUE\n9,Seq.SFCInit,FALSE\n",
        watch,
    );
    assert_eq!(
        trace,
        format!(
            "cycle,time_ms,{watch}\n\
             0,0,1,0,0,1\n\
             1,10,0,1,0,2\n\
             2,20,0,0,1,2\n\
             3,30,1,0,0,3\n\
             4,40,1,0,0,4\n\
             5,50,0,1,0,5\n\
             6,60,0,0,1,5\n\
             7,70,1,0,0,5\n\
             8,80,1,0,0,5\n\
             9,90,0,1,0,5\n\
             10,100,0,0,1,5\n"
        )
    );
}

/// Without `Use="true"` the flags are plain variables, as in CODESYS: SFCReset set in cycle 4
/// changes nothing.
#[test]
fn a_flag_that_is_not_enabled_is_a_plain_variable() {
    let src = std::fs::read_to_string(fixture()).unwrap();
    let off = src.replacen(
        "<Reset Declare=\"false\" Use=\"true\" />",
        "<Reset Declare=\"false\" Use=\"false\" />",
        1,
    );
    assert_ne!(off, src);
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("off.xml");
    std::fs::write(&file, off).unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n1,Chain.go,TRUE\n3,Chain.go,FALSE\n4,Chain.SFCReset,TRUE\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["run"])
        .arg(&file)
        .args(["--cycles", "6", "--cycle-ms", "10", "--stimulus"])
        .arg(&stim)
        .args(["--trace", "-", "--watch", "Chain.__sfc_X_S2,Chain.lamp"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let trace = String::from_utf8_lossy(&out.stdout);
    assert!(trace.ends_with("4,40,1,1\n5,50,1,1\n"), "{trace}");
}

/// SFCPause is enabled and not implemented: one W3402 at its element (line 83), with the POU,
/// exit code 0; the flags without `Use="true"` (EnableLimit, Error, CurrentStep) say nothing, and
/// the settings are read vendor data (no W3002 for them).
#[test]
fn an_enabled_flag_ladderc_does_not_implement_is_one_located_warning() {
    let src = std::fs::read_to_string(fixture()).unwrap();
    let (code, lines) = check_text("flags.xml", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(
        lines,
        [
            "flags.xml:83:17: warning[W3402]: SFC flag `SFCPause` is enabled but ladderc does not \
          implement it: the variable is a plain variable [POU `Chain`] (hint: ladderc implements \
          SFCInit and SFCReset; drive what `SFCPause` would do from the program, or disable the \
          flag in the SFC settings)"
        ],
    );
    // a second enabled one is a second warning, in the action's settings too
    let two = src.replacen(
        "<CurrentStep Declare=\"true\" Use=\"false\" />",
        "<CurrentStep Declare=\"true\" Use=\"true\" />",
        1,
    );
    let (code, lines) = check_text("flags.xml", &two);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[1].starts_with("flags.xml:153:21: warning[W3402]: SFC flag `SFCCurrentStep`")
            && lines[1].contains("[POU `Seq`]"),
        "{lines:?}"
    );
}

/// An enabled flag whose variable is not BOOL, or that is neither declared nor declared
/// implicitly, is one E3403 each, located at the declaration or the flag's element.
#[test]
fn an_enabled_flag_without_a_bool_variable_is_a_located_error() {
    let src = std::fs::read_to_string(fixture()).unwrap();
    let int = src.replacen(
        "<variable name=\"SFCReset\"><type><BOOL /></type></variable>",
        "<variable name=\"SFCReset\"><type><INT /></type></variable>",
        1,
    );
    let (code, lines) = check_text("flags.xml", &int);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with(
            "flags.xml:17:29: error[E3403]: SFC flag `SFCReset` is enabled, but \
             the POU declares `SFCReset` with a type other than BOOL [POU `Chain`]"
        ),
        "{lines:?}"
    );
    let undeclared = src.replacen(
        "<Init Declare=\"true\" Use=\"true\" />",
        "<Init Declare=\"false\" Use=\"true\" />",
        1,
    );
    let (code, lines) = check_text("flags.xml", &undeclared);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with(
            "flags.xml:81:17: error[E3403]: SFC flag `SFCInit` is enabled (Use) \
             but neither declared in POU `Chain` nor declared implicitly"
        ),
        "{lines:?}"
    );
}

/// The POU's settings serve its body's chart and the chart of an SFC action without settings of
/// its own (`Sub`, added to `Chain`): still one W3402, and the implicitly declared `SFCInit` is one
/// variable of the POU, holding both charts.
#[test]
fn charts_sharing_the_pou_settings_give_one_warning_and_one_flag_variable() {
    let src = std::fs::read_to_string(fixture()).unwrap();
    let sub = "<action name=\"Sub\"><body><SFC>\
               <step localId=\"1\" initialStep=\"true\" name=\"Only\"><position x=\"0\" y=\"0\" />\
               </step></SFC></body></action>\n          <action name=\"Count\">";
    let with_sub = src.replacen(
        "<action name=\"Count\">\n            <body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">n := n + 1;",
        &format!("{sub}\n            <body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">n := n + 1;"),
        1,
    );
    assert_ne!(with_sub, src);
    let (code, lines) = check_text("flags.xml", &with_sub);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("warning[W3402]: SFC flag `SFCPause`"),
        "{lines:?}"
    );
}
