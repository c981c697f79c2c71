//! Round 26 of unseen projects (issue #13), CODESYS exports (V2.3 `.EXP`, V3 PLCopen XML, OSCAT),
//! run end to end through `ladderc run`:
//! - a time-of-day or date-and-time literal without seconds (`TOD#12:00`, `TIME_OF_DAY#9:0`,
//!   `DT#1970-1-1-00:00`, as CODESYS's own exports and OSCAT write them) is read with the seconds
//!   zero and one warning W1445 per literal, alike in an ST declaration, an ST statement, IL and a
//!   PLCopen XML initial value (before: refused with three codes for one cause, E0005 in a
//!   declaration, E0103 in a statement, E3011 "not a literal or a constant name" in XML);
//! - a CODESYS V2.3 SFC export's step with its own statements (`STEP Work: m := m + 1; END_STEP`,
//!   an embedded step action) runs them while the step is active (before: read as IEC action
//!   associations, one E3123 per statement and one E0302 per step);
//! - a V2.3 `MACRO ... END_MACRO` object is skipped with one note W1442, as a visualisation is
//!   (before: read as IL, one E0011 per line);
//! - CODESYS's `DATE_TO_DT`, `TOD_TO_TIME` and `TIME_TO_TOD` convert (before: E1019);
//! - `ADR(x)` into a DWORD input: still E1012 (integer addresses are refused by design), with a
//!   hint that says why and what to declare instead (before: "use a value of type DWORD", which
//!   the program already did).

mod common;
use common::{check_text, column, run_text, run_traced_files, text_column};

/// `TOD#12:00` in a statement, `TIME_OF_DAY#9:0` and `DT#1970-1-1-00:00` in declarations (ST):
/// each is read with zero seconds and warned about once, at the literal (W1445).
#[test]
fn st_time_of_day_without_seconds_runs_with_one_warning_each() {
    let src = "PROGRAM PLC_PRG
VAR
  tStart : TIME_OF_DAY := TIME_OF_DAY#9:0;
  td : TOD := TOD#13:30:00;
  stamp : DT := DT#1970-1-1-00:00;
  pm : BOOL;
  late : BOOL;
  noon : TOD;
END_VAR
pm := td >= TOD#12:00;
late := td > tStart AND stamp = DT#1970-01-01-00:00:00;
noon := TOD#12:00;
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "tod.st",
        src,
        1,
        "PLC_PRG.pm,PLC_PRG.late,PLC_PRG.tStart,PLC_PRG.noon",
    );
    assert_eq!(column(&trace, "PLC_PRG.pm"), vec![1.0], "{trace}");
    assert_eq!(column(&trace, "PLC_PRG.late"), vec![1.0], "{trace}");
    assert_eq!(text_column(&trace, "PLC_PRG.tStart"), vec!["TOD#09:00:00"]);
    assert_eq!(text_column(&trace, "PLC_PRG.noon"), vec!["TOD#12:00:00"]);
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("W1445")).collect();
    assert_eq!(warnings.len(), 4, "{stderr}");
    assert!(
        warnings[0].contains("tod.st:3:27: warning[W1445]: `TIME_OF_DAY#9:0` has no seconds"),
        "{stderr}"
    );
    assert!(!stderr.contains("error["), "{stderr}");
}

/// The same literal in IL (`LD TOD#12:00`) and in a PLCopen XML initial value
/// (`TIME_OF_DAY#3:0`, as CODESYS V3.3 exported OSCAT): read alike, warned alike (W1445).
#[test]
fn il_and_xml_time_of_day_without_seconds_read_alike() {
    let il = "PROGRAM Main
VAR
  t : TOD;
END_VAR
  LD TOD#12:00
  ST t
END_PROGRAM
";
    let (trace, stderr) = run_text("tod.il", il, 1, "Main.t");
    assert_eq!(
        text_column(&trace, "Main.t"),
        vec!["TOD#12:00:00"],
        "{stderr}"
    );
    assert!(
        stderr.contains("tod.il:5:6: warning[W1445]: `TOD#12:00` has no seconds"),
        "{stderr}"
    );

    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="ladderc" productName="tests" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="tod"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Main" pouType="program">
      <interface><localVars>
        <variable name="dst"><type><TOD/></type><initialValue><simpleValue value="TIME_OF_DAY#3:0"/></initialValue></variable>
        <variable name="d"><type><DT/></type><initialValue><simpleValue value="DT#1970-1-1-00:00"/></initialValue></variable>
        <variable name="early"><type><BOOL/></type></variable>
      </localVars></interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">early := dst &lt; TOD#4:00;</xhtml></ST></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#;
    let (trace, stderr) = run_text("tod.xml", xml, 1, "Main.dst,Main.d,Main.early");
    assert_eq!(
        text_column(&trace, "Main.dst"),
        vec!["TOD#03:00:00"],
        "{stderr}"
    );
    assert_eq!(
        text_column(&trace, "Main.d"),
        vec!["DT#1970-01-01-00:00:00"],
        "{stderr}"
    );
    assert_eq!(column(&trace, "Main.early"), vec![1.0], "{trace}");
    // the two initial values and the body's literal: one warning each, no E3011
    assert_eq!(stderr.matches("warning[W1445]").count(), 3, "{stderr}");
    assert!(
        stderr.contains("`TIME_OF_DAY#3:0` has no seconds"),
        "{stderr}"
    );
    assert!(!stderr.contains("E3011"), "{stderr}");
}

/// A CODESYS V2.3 SFC program exported as text: each step holds its own ST statements (an
/// embedded step action), `TRANSITION FROM a TO b:= expr END_TRANSITION`. The statements run in
/// every scan their step is active: `n` counts in `Init`, `m` in `Work`, and the chart goes back
/// to `Init` when `m >= 2`.
#[test]
fn v23_sfc_step_statements_are_the_step_action() {
    let src = "(* @NESTEDCOMMENTS := 'Yes' *)
(* @PATH := '' *)
(* @OBJECTFLAGS := '0, 8' *)
(* @SYMFILEFLAGS := '2048' *)
PROGRAM Seq
VAR
\tn : INT;
\tm : INT;
\tgo : BOOL := TRUE;
\tlog : ARRAY[1..3] OF INT;
END_VAR
(* @END_DECLARATION := '0' *)

INITIAL_STEP Init:
n := n + 1;

END_STEP
(* @SFCMAXTIME := '' *)
(* @SFCMINTIME := '' *)
(* @SFCCOMMENT := '' *)
TRANSITION FROM Init TO Work:=
go
END_TRANSITION
STEP Work:
IF m < 100 THEN
\tm := m + 1;
END_IF;
END_STEP
(* @SFCMAXTIME := '' *)
(* @SFCMINTIME := '' *)
(* @SFCCOMMENT := '' *)
TRANSITION FROM Work TO Init:=
m >= 2
END_TRANSITION

END_PROGRAM
";
    let (trace, stderr) = run_text(
        "SEQ.EXP",
        src,
        6,
        "Seq.n,Seq.m,Seq.__sfc_X_Init,Seq.__sfc_X_Work",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    let (n, m) = (column(&trace, "Seq.n"), column(&trace, "Seq.m"));
    let (init, work) = (
        column(&trace, "Seq.__sfc_X_Init"),
        column(&trace, "Seq.__sfc_X_Work"),
    );
    for k in 0..6 {
        // exactly one step active, and only the active step's counter moved in that scan
        assert_eq!(init[k] + work[k], 1.0, "{trace}");
        let (dn, dm) = if k == 0 {
            (n[0], m[0])
        } else {
            (n[k] - n[k - 1], m[k] - m[k - 1])
        };
        assert_eq!((dn, dm), (init[k], work[k]), "cycle {k}: {trace}");
    }
    // it went round: Work twice (m reached 2), back to Init, then Work again
    assert_eq!(m[5], 4.0, "{trace}");
    assert_eq!(n[5], 2.0, "{trace}");
}

/// A V2.3 `MACRO` object exported beside the POUs (menu name and batch commands) holds no code:
/// one note W1442 naming it, and the program beside it runs.
#[test]
fn v23_macro_object_is_skipped_with_one_note() {
    let dir = tempfile::tempdir().unwrap();
    let main = dir.path().join("MAIN.EXP");
    let mac = dir.path().join("BUILD.EXP");
    std::fs::write(
        &main,
        "(* @NESTEDCOMMENTS := 'Yes' *)
(* @PATH := '' *)
PROGRAM PLC_PRG
VAR
\tn : INT;
END_VAR
(* @END_DECLARATION := '0' *)
n := n + 1;
END_PROGRAM
",
    )
    .unwrap();
    std::fs::write(
        &mac,
        "MACRO
MacroName: 'Rebuild'
MacroMenu: 'Rebuild'
MacroCmd: 'project rebuild'
MacroCmd: 'project expmul out\\'
END_MACRO

",
    )
    .unwrap();
    let (trace, stderr) = run_traced_files(&[&main, &mac], 2, "PLC_PRG.n");
    assert_eq!(column(&trace, "PLC_PRG.n"), vec![1.0, 2.0], "{stderr}");
    assert!(
        stderr.contains(
            "BUILD.EXP:1:1: note[W1442]: a macro (`Rebuild`) exported by CODESYS V2.3: no code, skipped"
        ),
        "{stderr}"
    );
    assert!(!stderr.contains("E0011"), "{stderr}");
    assert!(!stderr.contains("W0001"), "{stderr}");
}

/// CODESYS's date and time conversions (its online help, "Conversion: DATE, DT, TOD" and "Time
/// conversion"): `DATE_TO_DT` is the date at midnight, `TOD_TO_TIME` the duration since
/// midnight, `TIME_TO_TOD` the duration's time of day (modulo a day, as a number to TOD).
#[test]
fn codesys_date_and_time_conversions_run() {
    let src = "PROGRAM PLC_PRG
VAR
  td : TOD := TOD#01:00:00;
  d : DATE := D#2020-01-02;
  t : TIME;
  x : DT;
  back : TOD;
  wrapped : TOD;
  later : BOOL;
END_VAR
t := TOD_TO_TIME(td);
x := DATE_TO_DT(d);
back := TIME_TO_TOD(t + T#30m);
wrapped := TIME_TO_TOD(T#25h);
later := DT_TO_DATE(x + T#5h) = d;
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "conv.st",
        src,
        1,
        "PLC_PRG.t,PLC_PRG.x,PLC_PRG.back,PLC_PRG.wrapped,PLC_PRG.later",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(text_column(&trace, "PLC_PRG.t"), vec!["T#3600000ms"]);
    assert_eq!(
        text_column(&trace, "PLC_PRG.x"),
        vec!["DT#2020-01-02-00:00:00"]
    );
    assert_eq!(text_column(&trace, "PLC_PRG.back"), vec!["TOD#01:30:00"]);
    assert_eq!(text_column(&trace, "PLC_PRG.wrapped"), vec!["TOD#01:00:00"]);
    assert_eq!(column(&trace, "PLC_PRG.later"), vec![1.0], "{trace}");
}

/// `dwAdr := ADR(w)` into a DWORD input (CODESYS V2.3's ADR gives a DWORD): refused by design
/// (ladderc keeps addresses only in bounded pointers), one E1012 whose hint says so and names the
/// declaration to write, `POINTER TO WORD`.
#[test]
fn adr_into_a_dword_input_says_why_and_what_to_declare() {
    let src = "FUNCTION_BLOCK Sender
VAR_INPUT
\tdwAdr : DWORD;
END_VAR
VAR_OUTPUT
\tok : BOOL;
END_VAR
ok := dwAdr <> 0;
END_FUNCTION_BLOCK
PROGRAM PLC_PRG
VAR
\tw : WORD := 5;
\ts : Sender;
END_VAR
s(dwAdr := ADR(w));
END_PROGRAM
";
    let (code, lines) = check_text("adr.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    let e = errors[0];
    assert!(
        e.starts_with("adr.st:15:12: error[E1012]: dwAdr of Sender is DWORD, not REF_TO WORD"),
        "{e}"
    );
    assert!(e.contains("never in an integer such as DWORD"), "{e}");
    assert!(e.contains("declare it `POINTER TO WORD`"), "{e}");
    assert!(!e.contains("use a value of type DWORD"), "{e}");
}
