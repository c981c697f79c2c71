//! TwinCAT 3 SFC charts with a parallel branch (issue #13, round 30): a `SFCBranch` whose
//! `Parallel` attribute is `TRUE` (after a transition, each sequence beginning with a step) is
//! read as IEC 61131-3's simultaneous divergence and convergence (2.6.3): the transition before
//! the branch activates the first step of every sequence at once (`TO (a, b)`), and the
//! transition under the branch fires only when the last steps of all sequences are active
//! (`FROM (x, y)`), then leaves them all. Before: one E0321 per chart ("the branch has attribute
//! `Parallel` ... set to `TRUE`: a parallel branch, which ladderc does not read in a TwinCAT
//! chart"), in round 29's x-PPU_PLC-Reconfiguration (`MAIN`, `xPPU_Automatic`, both now read).
//!
//! The fixture `fixtures/twincat_sfc/P_Parallel.TcPOU` is written for this test (README there).

mod common;
use common::{check_text, ladderc};

use std::path::{Path, PathBuf};

fn fixture() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/twincat_sfc/P_Parallel.TcPOU")
}

/// `Wait` -> `bGo` -> parallel (`StepA` -> `bA` -> `StepA2` | `StepB`) -> `bDone` -> `Wait`, each
/// step action counting its scans. Scan by scan, in TwinCAT's processing order (round 34; Beckhoff
/// infosys and CODESYS "Processing Order in SFC": the actions of the steps active at the scan's
/// start first, the transition check last; a CODESYS step action does not run in the scan after
/// its step is left):
/// - scan 1, `bGo`: `Wait` is left, `StepA` and `StepB` both become active; they count from
///   scan 2 (1, 1);
/// - scans 3-4, `bDone` TRUE: the convergence does not fire, `StepA2` is not active yet;
/// - scan 5, `bA`: `StepA` and `StepB` count (4, 4), then `StepA2` becomes active (the
///   convergence sees `StepA2` inactive in this scan's check);
/// - scan 6: `StepA2` counts 1, `StepB` 5; both are active and `bDone` holds: both are left,
///   `Wait` is active, and nothing counts any more.
#[test]
fn a_parallel_branch_activates_every_sequence_and_its_convergence_waits_for_all() {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n1,P_Parallel.bGo,1\n2,P_Parallel.bGo,0\n3,P_Parallel.bDone,1\n\
         5,P_Parallel.bA,1\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture())
        .args(["--cycles", "9", "--cycle-ms", "10", "--stimulus"])
        .arg(&stim)
        .args([
            "--trace",
            "-",
            "--watch",
            "P_Parallel.nA,P_Parallel.nA2,P_Parallel.nB,P_Parallel.__sfc_X_Wait,\
             P_Parallel.__sfc_X_StepA,P_Parallel.__sfc_X_StepA2,P_Parallel.__sfc_X_StepB",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let rows: Vec<String> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .skip(1)
        .filter(|l| l.starts_with(|c: char| c.is_ascii_digit()))
        .map(|l| l.split(',').skip(2).collect::<Vec<_>>().join(","))
        .collect();
    // nA, nA2, nB, Wait.X, StepA.X, StepA2.X, StepB.X
    assert_eq!(
        rows,
        [
            // TwinCAT's processing order (round 34): each step's actions from the scan after
            // its transition
            "0,0,0,1,0,0,0",
            "0,0,0,0,1,0,1",
            "1,0,1,0,1,0,1",
            "2,0,2,0,1,0,1",
            "3,0,3,0,1,0,1",
            "4,0,4,0,0,1,1",
            "4,1,5,1,0,0,0",
            "4,1,5,1,0,0,0",
            "4,1,5,1,0,0,0",
        ]
    );
}

/// The archive object `<o t="SFCStep">` named `name`, cut out of `src` (the fixture writes each
/// object's closing `</o>` at its opening's indentation).
fn without_step(src: &str, name: &str) -> String {
    let at = src.find(&format!("\"{name}\"")).unwrap();
    let open = src[..at].rfind("<o t=\"SFCStep\">").unwrap();
    let line = src[..open].rfind('\n').unwrap() + 1;
    let indent = &src[line..open];
    let close = src[open..].find(&format!("\n{indent}</o>\n")).unwrap() + open;
    format!("{}{}", &src[..line], &src[close + indent.len() + 6..])
}

/// A sequence of a parallel branch that ends with its transition (here `bA`, with the step after
/// it taken out) leaves nothing for the convergence to wait for: one located E0321 that says so
/// (not a chart that never converges).
#[test]
fn a_parallel_sequence_that_does_not_end_with_a_step_is_one_located_error() {
    let src = std::fs::read_to_string(fixture()).unwrap();
    let cut = without_step(&src, "StepA2");
    assert!(cut.contains("\"StepA\"") && !cut.contains("\"StepA2\""));
    let (code, lines) = check_text("P_Parallel.TcPOU", &cut);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("P_Parallel.TcPOU:")
            && lines[0].contains("error[E0321]")
            && lines[0].contains("a sequence of a parallel branch that does not end with one step"),
        "{lines:?}"
    );
}
