//! TwinCAT 3 SFC bodies (issue #13, round 24): a `.TcPOU` whose body is `<SFC>` (CODESYS's
//! serialized `SFCImplementationObject` archive: `SFCSegment`, `SFCStep`, `SFCTransition`,
//! `SFCBranch`, `SFCJump`, `SFCMacro`, their attributes keyed by GUID) is read as textual SFC
//! (`crates/ladder-compiler/src/twincat_sfc.rs`) and run by the SFC lowering of PLCopen XML and
//! textual charts, end to end through `ladderc run` (before: one E0321 per POU, "the body ... is in
//! SFC, which ladderc cannot read in a TwinCAT source file"):
//! - steps, the initial step, a transition by ST expression and one by a `<Transition>` object, an
//!   alternative branch (two sequences, left first), jumps, CODESYS's entry / step / exit actions
//!   of a step (`<Action>` children of the POU), IEC associations (N, S) and the SFC settings' flags
//!   (SFCReset), checked scan by scan;
//! - what the archive holds that ladderc cannot map exactly (an attribute it does not know set to
//!   a value, a parallel branch where none can stand, a timed qualifier whose duration it cannot find) is one located
//!   E0321 naming it;
//! - an alternative branch whose sequences end with steps, one transition under it (CODESYS's
//!   form; before: E0321 for the whole body);
//! - in an `.st` file too, a textual chart runs the actions of the `ACTIONS` block after its POU
//!   (before: E0304 at the block, E3122 at each association).
//!
//! The fixture `fixtures/twincat_sfc/MAIN.TcPOU` is written for these tests (README there), in the
//! layout of the public projects read (TimKers/TwincatTest: ten SFC charts, 3.1.4024). Record of
//! that project's 12 `.TcPOU` files with an SFC chart (`ladderc check PLC/PLC.plcproj`): before, 12
//! E0321; now the 8 charts of POU bodies check clean (FB_EnclosureConditioningSFC,
//! FB_PowerModeConditioningSFC, FB_DehumidifySFC, FB_BatteryConditioningSFC, FB_HeatpumpOperation,
//! FB_HeatpumpInit, FB_HeatPumpSystem with its macro, UpdateSFC; W3402 for their SFCTip and
//! SFCCurrentStep flags), and the 4 charts that are the body of an ACTION (FB_BMS.BMSSFC,
//! FB_Janitza.ReadDataSFC, FB_Teltonika.ReadDataSFC, old.BMSInit) stay one E0321 each.

mod common;
use common::{check_text, ladderc};

use std::path::{Path, PathBuf};

fn fixture() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/twincat_sfc/MAIN.TcPOU")
}

const WATCH: &str = "MAIN.nLevel,MAIN.nIdle,MAIN.nEntry,MAIN.nFill,MAIN.nExit,MAIN.nLamp,\
                     MAIN.bLamp,MAIN.__sfc_X_Idle,MAIN.__sfc_X_Fill,MAIN.__sfc_X_Drain";

/// `ladderc run MAIN.TcPOU` for `cycles` scans of 10 ms with `stimulus`: the trace's rows, each
/// the watched values in [`WATCH`] order.
fn run(stimulus: &str, cycles: u32) -> Vec<Vec<i64>> {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, format!("cycle,variable,value\n{stimulus}")).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture())
        .args([
            "--cycles",
            &cycles.to_string(),
            "--cycle-ms",
            "10",
            "--stimulus",
        ])
        .arg(&stim)
        .args(["--trace", "-", "--watch", WATCH])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .skip(1)
        .filter(|l| l.starts_with(|c: char| c.is_ascii_digit()))
        .map(|l| {
            l.split(',')
                .skip(2)
                .map(|v| v.parse::<i64>().unwrap())
                .collect()
        })
        .collect()
}

/// Idle (initial, `aIdle` N) -> `bStart` -> Fill (entry `aFillEntry`, step action `aFill`: +10,
/// exit `aFillExit`) -> the branch's left sequence, the `<Transition>` object `T_Full`
/// (`nLevel >= 50`) -> Drain (step action `aDrain`: -20, `aLamp` S) -> `nLevel <= 0;` -> the jump
/// back to Idle. Each scan runs in TwinCAT's and CODESYS's documented "Processing Order in SFC"
/// (Beckhoff infosys tc3_plc_intro, CODESYS SFC help; round 34, before: IEC order, the transitions
/// first): first the actions of the steps active at the scan's start (exit actions of the steps
/// left in the scan before, entry actions, step actions, IEC actions), last the transition check,
/// which reads what the actions wrote in this scan. So a transition that fires in scan k activates
/// its step for scan k+1 (`Step.X` in the trace is already the new step's at the end of scan k):
/// the entry and step actions run from scan k+1, the exit action (not the step action) of the step
/// left runs in scan k+1, N once more in scan k+1 (its final scan), S on after.
#[test]
fn a_twincat_chart_runs_its_steps_transitions_branch_jump_and_step_actions() {
    let rows = run("2,MAIN.bStart,1\n3,MAIN.bStart,0\n", 12);
    // nLevel, nIdle, nEntry, nFill, nExit, nLamp, bLamp, Idle.X, Fill.X, Drain.X
    let expected: [[i64; 10]; 12] = [
        [0, 1, 0, 0, 0, 0, 0, 1, 0, 0],
        [0, 2, 0, 0, 0, 0, 0, 1, 0, 0],
        // bStart: aIdle runs (Idle still active), then the transition activates Fill
        [0, 3, 0, 0, 0, 0, 0, 0, 1, 0],
        // Fill's entry and step action; aIdle's final scan
        [10, 4, 1, 1, 0, 0, 0, 0, 1, 0],
        [20, 4, 1, 2, 0, 0, 0, 0, 1, 0],
        [30, 4, 1, 3, 0, 0, 0, 0, 1, 0],
        [40, 4, 1, 4, 0, 0, 0, 0, 1, 0],
        // aFill brings nLevel to 50, then T_Full (50 >= 50, read after the actions) activates Drain
        [50, 4, 1, 5, 0, 0, 0, 0, 0, 1],
        // Fill's exit action, not its step action; Drain's step action, aLamp set
        [30, 4, 1, 5, 1, 1, 1, 0, 0, 1],
        [10, 4, 1, 5, 1, 2, 1, 0, 0, 1],
        // aDrain brings nLevel to -10, then `nLevel <= 0` takes the jump to Idle
        [-10, 4, 1, 5, 1, 3, 1, 1, 0, 0],
        // aIdle again; aLamp stays set
        [-10, 5, 1, 5, 1, 4, 1, 1, 0, 0],
    ];
    assert_eq!(rows.len(), expected.len());
    for (k, (row, want)) in rows.iter().zip(expected.iter()).enumerate() {
        assert_eq!(row.as_slice(), want.as_slice(), "scan {k}");
    }
}

/// The branch's right sequence: `bAbort` in Fill runs Fill's exit action and jumps to Idle (the
/// left sequence's `T_Full` is FALSE, so it has no say); a second start enters Fill again (its
/// entry action again). The POU's SFC settings enable SFCReset: TRUE resets the chart to Idle and
/// the stored action `aLamp` (one final scan, as IEC's action control gives). In TwinCAT's
/// processing order (as the test above): Fill.X is set by the transition at the end of a scan, the
/// actions it starts or ends run from the next scan.
#[test]
fn the_other_sequence_of_the_branch_jumps_back_and_sfc_reset_resets_the_chart() {
    let stim = "2,MAIN.bStart,1\n3,MAIN.bStart,0\n4,MAIN.bAbort,1\n5,MAIN.bAbort,0\n\
                6,MAIN.bStart,1\n7,MAIN.bStart,0\n14,MAIN.SFCReset,1\n15,MAIN.SFCReset,0\n";
    let rows = run(stim, 17);
    let col = |k: usize| rows.iter().map(|r| r[k]).collect::<Vec<_>>();
    // Fill.X: scans 2-3 (aborted at 4), then 6-8
    assert_eq!(col(8), [0, 0, 1, 1, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0]);
    // nEntry: each entry into Fill (scans 3 and 7); nExit: each exit (the abort at 4 in scan 5,
    // T_Full at 9 in scan 10)
    assert_eq!(col(2)[3..10], [1, 1, 1, 1, 2, 2, 2]);
    assert_eq!(col(4)[3..11], [0, 0, 1, 1, 1, 1, 1, 2]);
    // nLevel: +10 in Fill from scan 3 (aFill runs in scan 4 before bAbort is checked; kept over
    // the abort), again from scan 7, -20 in Drain from scan 10
    assert_eq!(
        col(0)[..13],
        [0, 0, 0, 10, 20, 20, 20, 30, 40, 50, 30, 10, -10]
    );
    // aLamp (S) runs from scan 10 until SFCReset at scan 14 (its final scan), then never again
    assert_eq!(col(5)[12..], [3, 4, 5, 5, 5]);
    assert_eq!(col(7)[14..], [1, 1, 1], "SFCReset: the initial step");
}

/// What ladderc cannot map exactly is one located E0321 naming it, never a guess: a timed
/// qualifier (the archive's duration attribute is not known), a parallel branch (the branch's
/// `Parallel` attribute, named by the archive's own table of attributes), a table that names an
/// attribute otherwise than ladderc reads it, an attribute ladderc does not know that is not at
/// its default value.
#[test]
fn what_the_archive_holds_that_ladderc_cannot_map_is_one_located_error() {
    let src = std::fs::read_to_string(fixture()).unwrap();
    let timed = src.replacen("<v n=\"Value\">\"S\"</v>", "<v n=\"Value\">\"L\"</v>", 1);
    assert_ne!(timed, src);
    let (code, lines) = check_text("MAIN.TcPOU", &timed);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("error[E0321]")
            && lines[0].contains("qualifier `L`")
            && lines[0].contains("MAIN.TcPOU:"),
        "{lines:?}"
    );
    let parallel = src.replacen(
        "<o t=\"SFCBranch\">\n",
        "<o t=\"SFCBranch\">\n<l2 n=\"Attributes\" cet=\"SFCAttribute\"><o>\
         <v n=\"AttributeId\">{23bdaa98-72ec-41f7-817b-9dede5697086}</v><o n=\"Value\" \
         t=\"BoolValue\"><v n=\"Value\">\"TRUE\"</v><v n=\"DefaultValue\">\"FALSE\"</v></o>\
         </o></l2>\n",
        1,
    );
    assert_ne!(parallel, src);
    let (code, lines) = check_text("MAIN.TcPOU", &parallel);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        // (round 30: a parallel branch is read, `twincat_sfc_r30_run.rs`; this one follows a step,
        // where a parallel branch cannot stand)
        lines[0].contains("error[E0321]")
            && lines[0].contains("a parallel branch that does not follow a transition"),
        "{lines:?}"
    );
    // the archive's own table of attribute names must name each attribute as ladderc reads it
    let renamed = src.replacen("\"MainAction\"", "\"EntryAction\"", 1);
    assert_ne!(renamed, src);
    let (code, lines) = check_text("MAIN.TcPOU", &renamed);
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines.len() == 1 && lines[0].contains("which ladderc reads as `MainAction`"),
        "{lines:?}"
    );
    let unknown = src.replacen(
        "{6844a48e-46c2-4cc8-a185-a478f3b99cc0}",
        "{0badf00d-46c2-4cc8-a185-a478f3b99cc0}",
        1,
    );
    let (code, lines) = check_text("MAIN.TcPOU", &unknown);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("error[E0321]")
            && lines[0].contains("{0badf00d-46c2-4cc8-a185-a478f3b99cc0}")
            && lines[0].contains("`TRUE`"),
        "{lines:?}"
    );
}

/// The same reading in an `.st` file: a textual chart's association may name an action of the
/// `ACTIONS` block after its POU (CODESYS's text form; before: E0304 "an ACTIONS block is
/// supported only right after a POU whose body is ST", and E3122 at the association); the chart
/// calls it while its step is active (N: once more after).
#[test]
fn a_textual_chart_runs_the_actions_of_the_actions_block_after_its_pou() {
    let src = "PROGRAM main
VAR
  go : BOOL;
  n, m : INT;
END_VAR
INITIAL_STEP Wait: Count(N); END_STEP
TRANSITION FROM Wait TO Work := go; END_TRANSITION
STEP Work: Twice(N); END_STEP
TRANSITION FROM Work TO Wait := m >= 6; END_TRANSITION
END_PROGRAM
ACTIONS
ACTION Count:
  n := n + 1;
END_ACTION
ACTION Twice:
  m := m + 2;
END_ACTION
END_ACTIONS
";
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("chart.st");
    std::fs::write(&file, src).unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, "cycle,variable,value\n2,main.go,1\n3,main.go,0\n").unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(&file)
        .args(["--cycles", "8", "--cycle-ms", "10", "--stimulus"])
        .arg(&stim)
        .args(["--trace", "-", "--watch", "main.n,main.m"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let rows: Vec<String> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .skip(1)
        .map(|l| l.split(',').skip(2).collect::<Vec<_>>().join(","))
        .collect();
    // n counts Wait's scans (and its final scan at 2); m += 2 per Work scan (2, 3, 4), then once
    // more (the final scan at 5), Wait again from 5
    assert_eq!(
        rows,
        ["1,0", "2,0", "3,2", "3,4", "3,6", "4,8", "5,8", "6,8"],
        "{stderr}"
    );
}

/// An alternative branch whose sequences end with steps (CODESYS draws one transition under the
/// branch; fixture `P_Merge.TcPOU`): the transition after the branch leaves whichever of them is
/// active, as the PLCopen XML reader merges CODESYS's branches (before: E0321 for the whole body).
#[test]
fn an_alternative_branch_of_sequences_ending_in_steps_has_one_transition_after_it() {
    let file = fixture().with_file_name("P_Merge.TcPOU");
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n1,P_Merge.bGo,1\n2,P_Merge.bGo,0\n3,P_Merge.bDone,1\n\
         4,P_Merge.bDone,0\n5,P_Merge.bGo,1\n5,P_Merge.bLeft,1\n6,P_Merge.bGo,0\n8,P_Merge.bDone,1\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(&file)
        .args(["--cycles", "10", "--cycle-ms", "10", "--stimulus"])
        .arg(&stim)
        .args([
            "--trace",
            "-",
            "--watch",
            "P_Merge.nLeft,P_Merge.nRight,P_Merge.__sfc_X_Wait,P_Merge.__sfc_X_Left,\
             P_Merge.__sfc_X_Right",
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
    // nLeft, nRight, Wait.X, Left.X, Right.X: the right sequence first (bLeft FALSE), bDone leaves
    // Right; then the left one, bDone leaves Left
    assert_eq!(
        rows,
        [
            "0,0,1,0,0",
            "0,0,0,0,0",
            // TwinCAT's processing order (round 34): a step's actions from the scan after its
            // transition
            "0,0,0,0,1",
            "0,1,1,0,0",
            "0,1,1,0,0",
            "0,1,0,0,0",
            "0,1,0,1,0",
            "1,1,0,1,0",
            "2,1,1,0,0",
            "2,1,1,0,0"
        ]
    );
}
