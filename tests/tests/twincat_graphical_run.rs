//! TwinCAT 3 graphical bodies (issue #13): the LD/FBD network list `<NWL>` and the CFC chart `<CFC>`
//! of a `.TcPOU`, read as ST in place (`crates/ladder-compiler/src/twincat_nwl.rs`,
//! `twincat_cfc.rs`) and run end to end through `ladderc run`. The fixtures under
//! `fixtures/twincat_graphical/` are written for these tests (README there): an LD program and an
//! FBD function block whose logic is also written in ST (both runs must trace the same values, and
//! the values must be the ones the networks say), edge contacts and a return, a CFC chart listed
//! against its data flow, and one rejected body per diagnostic.
//!
//! Record of the public projects (README "TwinCAT 3 projects"): the 66 `.plcproj` files of today's
//! snapshots of tcunit/TcUnit, stefanbesler/struckig, benhar-dev/tc3-object-simple-packml,
//! Keiji01/TwinCAT3, MatheusNespolo/TwinCAT, SeanyCash/TwinCAT_CNC, ziyuEngineer/TwinCAT,
//! ergouliu/Twincat, tjkin1201/Twincat, 50 scans each, before and after this change. Their `.TcPOU`
//! files hold 15 LD/FBD network lists (12 in Keiji01/TwinCAT3, 3 in MatheusNespolo/TwinCAT), one
//! CFC chart (MatheusNespolo's) and no SFC body.
//!
//! | | run | rejected | first error a graphical body (E0321) |
//! |---|---|---|---|
//! | before (graphical bodies E0321) | 22 | 44 | 8 |
//! | LD/FBD read | 25 | 41 | 1 (the CFC chart) |
//! | CFC read too | 26 | 40 | 0 |
//!
//! The four that run now: the three with Keiji01's `FB_Clock` (an LD blinker of two TONs; Safety
//! Junction TEST's `bEnableClockEK1960_0000` is 1 s off, 1 s on) and MatheusNespolo's refrigerator
//! (its CFC `MAIN` switches `GVL_Var.Compressor` on above 13 and off below 11 degrees as its ST
//! simulation warms and cools `GVL_Var.TempAtual`). The other four the network lists stopped now
//! stop later, at a Beckhoff library type (E1003: `T_AmsNetId`, `FB_S_UPS_CX51x0`,
//! `FB_WritePersistentData`) or at an ST chained assignment in another POU (E0104), after all their
//! network lists were read.

mod common;
use common::{column, diagnostic_heads, ladderc};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/twincat_graphical")
        .join(rel)
}

const WATCH: &str = "MAIN.bMotor,MAIN.bIdle,MAIN.bSeen,MAIN.bPulse,MAIN.bEdge,MAIN.nCount,\
                     MAIN.nCopy,MAIN.bDone,MAIN.nNotSkipped,MAIN.bLamp,MAIN.bNever,MAIN.bAlways";

/// Start at cycle 2 (for two cycles), stop at cycle 40 (for two cycles).
const STIMULUS: &str = "cycle,variable,value\n2,MAIN.bStart,1\n4,MAIN.bStart,0\n\
                        40,MAIN.bStop,1\n42,MAIN.bStop,0\n";

/// `ladderc run FILES` for 50 scans of 10 ms with [`STIMULUS`], C built with the sanitizers: the trace.
fn run(files: &[PathBuf]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, STIMULUS).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .args(files)
        .args(["--cycles", "50", "--cycle-ms", "10", "--sanitize"])
        .arg("--stimulus")
        .arg(&stim)
        .args(["--trace", "-", "--watch", WATCH])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{files:?}: {stderr}");
    assert!(!stderr.contains("Sanitizer"), "{stderr}");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn ld_trace() -> String {
    run(&[fixture("blink/MAIN.TcPOU"), fixture("blink/FB_Blink.TcPOU")])
}

fn bools(trace: &str, name: &str) -> Vec<bool> {
    column(trace, name).iter().map(|&v| v != 0.0).collect()
}

#[test]
fn ld_and_fbd_networks_trace_what_the_same_logic_in_st_traces() {
    let ld = ld_trace();
    let st = run(&[fixture("blink_st/blink.st")]);
    for name in WATCH.split(',') {
        assert_eq!(column(&ld, name), column(&st, name), "{name}");
    }
    // the logic is not idle: the motor runs, the blinker blinks, the counter counts
    assert!(column(&ld, "MAIN.nCount").iter().any(|&n| n >= 5.0));
}

#[test]
fn contacts_coils_set_reset_and_the_power_rail() {
    let t = ld_trace();
    let motor = bools(&t, "MAIN.bMotor");
    // network 1: (bStart OR bMotor) AND NOT bStop latches from cycle 2 to cycle 40
    let want: Vec<bool> = (0..50).map(|c| (2..40).contains(&c)).collect();
    assert_eq!(motor, want);
    // its negated coil
    let idle = bools(&t, "MAIN.bIdle");
    assert!(idle.iter().zip(&motor).all(|(i, m)| i != m));
    // networks 2 and 3: set coil on bStart, reset coil on bStop
    assert_eq!(bools(&t, "MAIN.bSeen"), want);
    // network 10 is commented out: bNever stays FALSE; network 11's coil sits on the power rail
    assert!(bools(&t, "MAIN.bNever").iter().all(|b| !b));
    assert!(bools(&t, "MAIN.bAlways").iter().all(|b| *b));
}

#[test]
fn function_block_boxes_en_eno_branches_and_the_fbd_blinker() {
    let t = ld_trace();
    // FB_Blink (FBD): enabled at cycle 2, 30 ms low (TON_1), then high until TON_2's 20 ms have
    // elapsed (the scan after), and again; stopped at cycle 40
    let pulse = bools(&t, "MAIN.bPulse");
    let highs: Vec<usize> = (0..50).filter(|&c| pulse[c]).collect();
    assert_eq!(
        highs,
        [5, 6, 7, 12, 13, 14, 19, 20, 21, 26, 27, 28, 33, 34, 35]
    );
    // network 5: the branch of R_TRIG's Q is the coil bEdge and the EN of ADD (nCount + 1), whose
    // ENO is the EN of MOVE (nCopy := nCount)
    let edge = bools(&t, "MAIN.bEdge");
    let rising: Vec<usize> = (0..50)
        .filter(|&c| pulse[c] && (c == 0 || !pulse[c - 1]))
        .collect();
    assert_eq!((0..50).filter(|&c| edge[c]).collect::<Vec<_>>(), rising);
    let count = column(&t, "MAIN.nCount");
    let mut n = 0.0;
    for c in 0..50 {
        if edge[c] {
            n += 1.0;
        }
        assert_eq!(count[c], n, "cycle {c}");
    }
    assert_eq!(column(&t, "MAIN.nCopy"), count);
    // the action box (ACT_Lamp, LD): bMotor AND bPulse
    let (lamp, motor) = (bools(&t, "MAIN.bLamp"), bools(&t, "MAIN.bMotor"));
    assert!((0..50).all(|c| lamp[c] == (motor[c] && pulse[c])));
}

#[test]
fn a_jump_skips_the_networks_up_to_its_label() {
    let t = ld_trace();
    // network 7 jumps to `Skip` (network 9) once nCount >= 3 (network 6): network 8, which counts
    // the scans, runs until then and never after
    let done = bools(&t, "MAIN.bDone");
    let count = column(&t, "MAIN.nCount");
    assert!((0..50).all(|c| done[c] == (count[c] >= 3.0)));
    let first_done = done.iter().position(|d| *d).expect("done");
    let scans = column(&t, "MAIN.nNotSkipped");
    for (c, &s) in scans.iter().enumerate() {
        let want = (c.min(first_done - 1) + 1) as f64;
        assert_eq!(s, want, "cycle {c}");
    }
    // the networks after the label still run: the lamp follows the blinker after the jump too
    assert!((first_done..50).any(|c| bools(&t, "MAIN.bLamp")[c]));
}

#[test]
fn edge_contacts_and_a_return_coil() {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n3,P_Edges.bIn,1\n6,P_Edges.bIn,0\n8,P_Edges.bIn,1\n9,P_Edges.bIn,0\n\
         12,P_Edges.bHold,1\n15,P_Edges.bHold,0\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture("edges/P_Edges.TcPOU"))
        .args(["--cycles", "18", "--cycle-ms", "10", "--sanitize"])
        .arg("--stimulus")
        .arg(&stim)
        .args(["--trace", "-", "--watch"])
        .arg("P_Edges.bIn,P_Edges.nRises,P_Edges.nFalls,P_Edges.nAfter")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let t = String::from_utf8_lossy(&out.stdout);
    // a rising-edge contact (P) counts the scans where bIn became TRUE, a falling-edge one (N)
    // those where it became FALSE
    let b = bools(&t, "P_Edges.bIn");
    let (mut rises, mut falls) = (0.0, 0.0);
    let (r, f) = (column(&t, "P_Edges.nRises"), column(&t, "P_Edges.nFalls"));
    for c in 0..18 {
        let before = c > 0 && b[c - 1];
        rises += f64::from(u8::from(b[c] && !before));
        falls += f64::from(u8::from(!b[c] && before));
        assert_eq!((r[c], f[c]), (rises, falls), "cycle {c}");
    }
    assert_eq!((rises, falls), (2.0, 2.0));
    // network 3 returns while bHold (cycles 12 to 14): network 4 does not count those scans
    let after = column(&t, "P_Edges.nAfter");
    let want: Vec<f64> = (0..18)
        .map(|c: i32| f64::from(c.min(11) + 1 + (c - 14).max(0)))
        .collect();
    assert_eq!(after, want);
}

#[test]
fn an_action_reads_a_one_variable_en_where_it_is_used() {
    // ACT_Inc (LD) is ADD(EN := bA, n, 1) -> n; an action declares no variables, so EN is read at
    // the box (no element of the network writes bA)
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n3,P_ActionEn.bA,1\n6,P_ActionEn.bA,0\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture("action/P_ActionEn.TcPOU"))
        .args(["--cycles", "9", "--cycle-ms", "10", "--sanitize"])
        .arg("--stimulus")
        .arg(&stim)
        .args(["--trace", "-", "--watch", "P_ActionEn.bA,P_ActionEn.n"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let t = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        column(&t, "P_ActionEn.n"),
        [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0, 3.0]
    );
}

/// `ladderc check FILE`: exit code and the diagnostic heads (short format, folder left out).
fn check(file: &Path) -> (Option<i32>, Vec<String>) {
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(file)
        .output()
        .unwrap();
    let dir = file.parent().unwrap();
    (out.status.code(), diagnostic_heads(&out.stderr, dir, false))
}

#[test]
fn what_is_not_read_is_one_located_error_naming_the_element_and_its_network() {
    let cases = [
        (
            "P_Unknown.TcPOU",
            "P_Unknown.TcPOU:89:21: error[E0325]: TwinCAT LD/FBD body of `P_Unknown`, network 2: \
             element `BoxTreeCoilRange` is not one ladderc reads in a network list",
        ),
        (
            "P_Inject.TcPOU",
            "P_Inject.TcPOU:56:27: error[E0326]: TwinCAT LD/FBD body of `P_Inject`, network 1: \
             operand `bA; bB := TRUE` is not one ST operand (it holds `;`)",
        ),
        (
            "P_Back.TcPOU",
            "P_Back.TcPOU:93:29: error[E0325]: TwinCAT LD/FBD body of `P_Back`, network 2: jump \
             back to `Top` (network 1): ladderc reads forward jumps only",
        ),
        (
            "P_ActionAnd.TcPOU",
            "P_ActionAnd.TcPOU:120:23: error[E0327]: TwinCAT LD/FBD body of `P_ActionAnd.ACT_Inc`, \
             network 1: the EN of box `ADD` needs a variable of its own, and an action has no \
             declarations (nor can it read the value where it is used: an element of the network \
             writes it, or it is not one variable)",
        ),
    ];
    for (file, head) in cases {
        let path = fixture("errors").join(file);
        let (code, heads) = check(&path);
        assert_eq!(code, Some(1), "{file}");
        assert_eq!(heads, [head.to_string()], "{file}");
        // the place is the element named: its line holds it
        let line: usize = head.split(':').nth(1).unwrap().parse().unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        let at = text.lines().nth(line - 1).unwrap();
        let named = match file {
            "P_Unknown.TcPOU" => "BoxTreeCoilRange",
            "P_Inject.TcPOU" => "bA; bB := TRUE",
            "P_Back.TcPOU" => "\"Top\"",
            _ => "BoxTreeBox",
        };
        assert!(at.contains(named), "{file}:{line}: {at}");
    }
}

#[test]
fn an_error_of_the_st_front_end_points_at_the_operand_in_the_network() {
    let path = fixture("errors/P_Undeclared.TcPOU");
    let (code, heads) = check(&path);
    assert_eq!(code, Some(1));
    assert_eq!(heads.len(), 1, "{heads:?}");
    assert!(
        heads[0].contains("error[E1001]: undeclared name `bMissing`"),
        "{heads:?}"
    );
    let line: usize = heads[0].split(':').nth(1).unwrap().parse().unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(
        text.lines().nth(line - 1).unwrap().contains("\"bMissing\""),
        "line {line}"
    );
}

#[test]
fn a_cfc_chart_runs_in_data_flow_order() {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n5,P_Cooler.rTemp,13.5\n15,P_Cooler.rTemp,12\n\
         20,P_Cooler.rTemp,10.5\n25,P_Cooler.rTemp,12\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture("cfc/P_Cooler.TcPOU"))
        .args(["--cycles", "30", "--cycle-ms", "10", "--sanitize"])
        .arg("--stimulus")
        .arg(&stim)
        .args(["--trace", "-", "--watch"])
        .arg("P_Cooler.rTemp,P_Cooler.bCooler,P_Cooler.bSeen,P_Cooler.bNotCool,P_Cooler.bLate")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let t = String::from_utf8_lossy(&out.stdout);
    // SR(SET1 := rTemp > rSet + rBand, RESET := rTemp < rSet - rBand), rSet 12, rBand 1: on above
    // 13, off below 11, held in between
    let temp = column(&t, "P_Cooler.rTemp");
    let cooler = bools(&t, "P_Cooler.bCooler");
    let mut on = false;
    for c in 0..30 {
        if temp[c] > 13.0 {
            on = true;
        } else if temp[c] < 11.0 {
            on = false;
        }
        assert_eq!(cooler[c], on, "cycle {c}");
    }
    assert!(cooler[5] && cooler[19] && !cooler[20]);
    // the set output stays TRUE once set; the negated pin gives the opposite of the cooler
    let seen = bools(&t, "P_Cooler.bSeen");
    assert!((0..30).all(|c| seen[c] == (c >= 5)));
    let not_cool = bools(&t, "P_Cooler.bNotCool");
    assert!((0..30).all(|c| not_cool[c] != cooler[c]));
    // the TON is listed before the SR box it reads, but runs after it (data flow): its IN is TRUE
    // from cycle 5, so its 30 ms have elapsed at cycle 8 (cycle 9 in list order)
    let late = bools(&t, "P_Cooler.bLate");
    let highs: Vec<usize> = (0..30).filter(|&c| late[c]).collect();
    assert_eq!(highs, (8..20).collect::<Vec<_>>());
}

#[test]
fn a_cfc_feedback_loop_is_one_located_error() {
    let path = fixture("errors/P_Loop.TcPOU");
    let (code, heads) = check(&path);
    assert_eq!(code, Some(1));
    assert_eq!(
        heads,
        [
            "P_Loop.TcPOU:17:19: error[E0325]: TwinCAT CFC body of `P_Loop`: a feedback loop \
          (ladderc reads charts without feedback)"
        ]
    );
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.lines().nth(16).unwrap().contains("CFCBoxElement"));
}

/// An SFC chart that is the body of an ACTION stays one located E0321 (a POU's SFC body is read
/// since round 24: `twincat_sfc_run.rs`); a POU's SFC body without its archive is one E0321 too.
#[test]
fn an_sfc_body_stays_one_located_e0321() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("P_Sfc.TcPOU");
    std::fs::write(
        &path,
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  \
         <POU Name=\"P_Sfc\">\n    <Declaration><![CDATA[PROGRAM P_Sfc\nVAR x : BOOL; END_VAR\n]]>\
         </Declaration>\n    <Implementation>\n      <ST><![CDATA[x := TRUE;]]></ST>\n    \
         </Implementation>\n    <Action Name=\"A\">\n    <Implementation>\n      <SFC>\n        \
         <XmlArchive />\n      </SFC>\n    </Implementation>\n    </Action>\n  </POU>\n</TcPlcObject>\n",
    )
    .unwrap();
    let (code, heads) = check(&path);
    assert_eq!(code, Some(1));
    assert_eq!(
        heads,
        ["P_Sfc.TcPOU:12:7: error[E0321]: TwinCAT object file: the body of `P_Sfc.A` is in SFC, which \
          ladderc cannot read in a TwinCAT source file (it reads ST, LD/FBD and CFC bodies)"]
    );
    let pou = "<?xml version=\"1.0\"?>\n<TcPlcObject>\n<POU Name=\"P_Sfc\"><Declaration><![CDATA[\
               PROGRAM P_Sfc]]></Declaration>\n<Implementation>\n<SFC><XmlArchive /></SFC>\
               </Implementation></POU></TcPlcObject>\n";
    std::fs::write(&path, pou).unwrap();
    let (code, heads) = check(&path);
    assert_eq!(code, Some(1));
    assert_eq!(
        heads,
        [
            "P_Sfc.TcPOU:5:1: error[E0321]: TwinCAT SFC body: the SFC body of `P_Sfc` holds no \
          SFCImplementationObject archive"
        ]
    );
}

/// TwinCAT's EXECUTE box (round 19, purushothaman2310/IEC61131-OOPS-TwiCAT; before: E0326 "box
/// `EXECUTE` has no input"): its ST statements (two, a comment, a line break written `\r\n` in the
/// archive) run in the scans its EN is TRUE.
#[test]
fn an_execute_box_runs_its_st_statements_when_en_is_true() {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n1,MAIN.bRun,1\n4,MAIN.bRun,0\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture("execute/MAIN.TcPOU"))
        .args(["--cycles", "6", "--sanitize", "--stimulus"])
        .arg(&stim)
        .args(["--trace", "-", "--watch", "MAIN.n,MAIN.nTwice"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("error["), "{stderr}");
    let trace = String::from_utf8_lossy(&out.stdout);
    assert_eq!(column(&trace, "MAIN.n"), [0.0, 1.0, 2.0, 3.0, 3.0, 3.0]);
    assert_eq!(
        column(&trace, "MAIN.nTwice"),
        [0.0, 2.0, 4.0, 6.0, 6.0, 6.0]
    );
}
