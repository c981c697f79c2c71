//! Round 33: Beremiz and OpenPLC semantics under the OpenPLC profile (`--profile openplc`).
//!
//! - **TIME as a number.** IEC 61131-3 leaves the unit of `REAL_TO_TIME`, `DINT_TO_TIME`,
//!   `TIME_TO_REAL` ... open. The profile's `time_number_unit` fixes it: milliseconds by default (as
//!   CODESYS and TwinCAT), seconds under `--profile openplc`, as matiec (`lib/C/iec_std_lib.h`:
//!   `__real_to_time`, `__int_to_time`, `__time_to_real`), which Beremiz and OpenPLC compile with.
//!   A Beremiz or OpenPLC project compiled with milliseconds gets one W1465 at its first such
//!   conversion. Before: milliseconds under every profile, silently (a YAPLC library's
//!   `REAL_TO_TIME(ms / 1000.0)` timer ran 1000 times shorter).
//! - **SFC action control.** The profile's `sfc_action_control`: `iec` by default (IEC 61131-3 ed. 2
//!   2.6.4.5, the ACTION_CONTROL block: an action's body runs once more in the scan its step is
//!   left, the final scan; an initial step's P action runs in the first scan), `beremiz` under
//!   `--profile openplc` (matiec's generated chart code: a body runs only while its step is active,
//!   and an initial step counts as active before the first scan, so its P action waits for the
//!   step's next activation). Before: the final scan under every profile, so a Beremiz chart whose
//!   N actions pass a timer's Q out with `=>` stopped where Beremiz cycles on.

mod common;

use common::{check_text, in_dir, text_column, write_in};

/// `ladderc run FILE --cycles N --trace - --watch WATCH` (and `extra`) in a temporary folder: the
/// trace; asserts exit 0.
fn run(name: &str, src: &str, cycles: u32, watch: &str, extra: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), name, src);
    let cycles = cycles.to_string();
    let mut args = vec![
        "run",
        name,
        "--cycles",
        &cycles,
        "--cycle-ms",
        "20",
        "--trace",
        "-",
        "--watch",
        watch,
    ];
    args.extend_from_slice(extra);
    let (code, trace, stderr) = in_dir(dir.path(), &args);
    assert_eq!(code, Some(0), "{stderr}");
    trace
}

/// The first cycle in which column `name` is `1`.
fn first_true(trace: &str, name: &str) -> Option<usize> {
    text_column(trace, name).iter().position(|v| v == "1")
}

const TIME_NUMBERS: &str = "PROGRAM main
  VAR CONSTANT
    settle : TIME := UINT_TO_TIME(3);
  END_VAR
  VAR
    delay_ms : UDINT := 1500;
    pt : TIME;
    dwell : TON;
    done : BOOL;
    elapsed : REAL;
    whole : DINT;
    from_int : TIME;
    kept : TIME;
  END_VAR
  pt := REAL_TO_TIME(UDINT_TO_REAL(delay_ms) / 1000.0);
  dwell(IN := TRUE, PT := pt);
  done := dwell.Q;
  elapsed := TIME_TO_REAL(dwell.ET);
  whole := TIME_TO_DINT(T#2500ms);
  from_int := DINT_TO_TIME(2);
  kept := settle;
END_PROGRAM

CONFIGURATION cfg
  RESOURCE res ON PLC
    TASK tick(INTERVAL := T#20ms, PRIORITY := 0);
    PROGRAM inst WITH tick : main;
  END_RESOURCE
END_CONFIGURATION
";

const TIME_WATCH: &str = "inst.pt,inst.done,inst.elapsed,inst.whole,inst.from_int,inst.kept";

/// The default profile counts milliseconds: `REAL_TO_TIME(1.5)` is T#2ms (a whole number of
/// milliseconds, halves to even, as CODESYS and TwinCAT keep TIME; round 34, before: T#1.5ms,
/// `tests/tests/vendor_sem_r34_run.rs`), so the TON is done in the second scan (20 ms) with
/// `TIME_TO_REAL` of its ET 2.0; `TIME_TO_DINT(T#2500ms)` 2500, `DINT_TO_TIME(2)` T#2ms, the
/// constant `UINT_TO_TIME(3)` T#3ms. Unchanged by round 33.
#[test]
fn the_default_profile_counts_milliseconds() {
    let trace = run("units.st", TIME_NUMBERS, 3, TIME_WATCH, &[]);
    assert_eq!(text_column(&trace, "inst.pt")[0], "T#2ms", "{trace}");
    assert_eq!(first_true(&trace, "inst.done"), Some(1), "{trace}");
    assert_eq!(text_column(&trace, "inst.elapsed")[1], "2", "{trace}");
    assert_eq!(text_column(&trace, "inst.whole")[0], "2500", "{trace}");
    assert_eq!(text_column(&trace, "inst.from_int")[0], "T#2ms", "{trace}");
    assert_eq!(text_column(&trace, "inst.kept")[0], "T#3ms", "{trace}");
}

/// Under `--profile openplc` a number converted to or from TIME counts seconds, as matiec
/// (Beremiz, OpenPLC): `REAL_TO_TIME(1.5)` is T#1.5s, the TON runs 75 scans of 20 ms (done in cycle
/// 75), `TIME_TO_REAL` of its ET is 0.02 after one scan, `TIME_TO_DINT(T#2500ms)` is 2 (truncated
/// toward zero), `DINT_TO_TIME(2)` T#2s, and the constant expression `UINT_TO_TIME(3)` of a
/// declaration T#3s (the profile reaches the declarations' constant folding too). Before round
/// 33: the same values as the default profile (T#1.5ms, done in cycle 1).
#[test]
fn the_openplc_profile_counts_seconds_as_matiec() {
    let trace = run(
        "units.st",
        TIME_NUMBERS,
        80,
        TIME_WATCH,
        &["--profile", "openplc"],
    );
    assert_eq!(text_column(&trace, "inst.pt")[0], "T#1500ms", "{trace}");
    assert_eq!(first_true(&trace, "inst.done"), Some(75), "{trace}");
    assert_eq!(text_column(&trace, "inst.elapsed")[1], "0.02", "{trace}");
    assert_eq!(text_column(&trace, "inst.elapsed")[75], "1.5", "{trace}");
    assert_eq!(text_column(&trace, "inst.whole")[0], "2", "{trace}");
    assert_eq!(
        text_column(&trace, "inst.from_int")[0],
        "T#2000ms",
        "{trace}"
    );
    assert_eq!(text_column(&trace, "inst.kept")[0], "T#3000ms", "{trace}");
}

/// The preamble Beremiz and OpenPLC Editor write at the top of every generated `plc.st` (our own
/// text of it: the LOGLEVEL type and the LOGGER block).
const GENERATED_PREAMBLE: &str = "TYPE
  LOGLEVEL : (CRITICAL, WARNING, INFO, DEBUG) := INFO;
END_TYPE

FUNCTION_BLOCK LOGGER
  VAR_INPUT
    TRIG : BOOL;
    MSG : STRING;
    LEVEL : LOGLEVEL := INFO;
  END_VAR
  VAR
    TRIG0 : BOOL;
  END_VAR
  TRIG0 := TRIG;
END_FUNCTION_BLOCK

";

/// A `plc.st` generated by Beremiz or OpenPLC Editor (its LOGGER preamble) checked with the default
/// profile: one W1465 at the first conversion in a body (line 31, `REAL_TO_TIME`, column 9), none for the
/// other three, saying milliseconds against Beremiz's seconds and naming `--profile openplc`;
/// exit 0. Under `--profile openplc`, and for the same program without the preamble (not known
/// to be Beremiz's), nothing. Before round 33: no diagnostic at all.
#[test]
fn a_generated_plc_st_gets_one_w1465_at_its_first_conversion() {
    let src = format!("{GENERATED_PREAMBLE}{TIME_NUMBERS}");
    let (code, lines) = check_text("plc.st", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    let w: Vec<&String> = lines.iter().filter(|l| l.contains("W1465")).collect();
    assert_eq!(w.len(), 1, "{lines:?}");
    assert!(
        w[0].starts_with("plc.st:31:9: warning[W1465]: `REAL_TO_TIME` counts milliseconds here, seconds in Beremiz and OpenPLC"),
        "{lines:?}"
    );
    assert!(
        w[0].contains("LOGGER") && w[0].contains("--profile openplc"),
        "{lines:?}"
    );

    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "plc.st", &src);
    let (code, _, stderr) = in_dir(dir.path(), &["check", "plc.st", "--profile", "openplc"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("W1465"), "{stderr}");

    let (_, lines) = check_text("units.st", TIME_NUMBERS);
    assert!(!lines.iter().any(|l| l.contains("W1465")), "{lines:?}");
}

/// A Beremiz project folder (`beremiz.xml`, `plc.xml` with an ST program calling `TIME_TO_REAL`):
/// one W1465 in `plc.xml` at the call, naming the project folder. Before round 33: nothing.
#[test]
fn a_beremiz_project_folder_gets_w1465() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path();
    write_in(
        p,
        "beremiz.xml",
        "<?xml version='1.0' encoding='utf-8'?>\n<BeremizRoot URI_location=\"LOCAL://\"><TargetType/></BeremizRoot>\n",
    );
    write_in(
        p,
        "plc.xml",
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-12-07T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="main" pouType="program">
      <interface><localVars>
        <variable name="seconds"><type><REAL/></type></variable>
        <variable name="uptime"><type><TIME/></type></variable>
      </localVars></interface>
      <body><ST><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml"><![CDATA[uptime := uptime + T#10ms;
seconds := TIME_TO_REAL(uptime);]]></xhtml:p></ST></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="C"><resource name="R">
    <task name="t" priority="0" interval="T#10ms"><pouInstance name="inst" typeName="main"/></task>
  </resource></configuration></configurations></instances>
</project>
"#,
    );
    let (code, _, stderr) = in_dir(p, &["check", "."]);
    assert_eq!(code, Some(0), "{stderr}");
    let w: Vec<&str> = stderr.lines().filter(|l| l.contains("W1465")).collect();
    assert_eq!(w.len(), 1, "{stderr}");
    assert!(
        w[0].contains("plc.xml:") && w[0].contains("`TIME_TO_REAL`") && w[0].contains("plc.xml"),
        "{stderr}"
    );
    let (code, _, stderr) = in_dir(p, &["check", ".", "--profile", "openplc"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("W1465"), "{stderr}");
}

/// A relay of three stages (our own chart, the form of ounie-os/build_k1's "running horse"): each
/// stage's N action calls a TON and passes its Q out with `=>`; stage B clears lamp A once lamp B
/// is on; the initial step's P action counts the chart's starts.
const RELAY: &str = "FUNCTION_BLOCK Relay
  VAR_OUTPUT
    lampA : BOOL;
    lampB : BOOL;
    lampC : BOOL;
    starts : INT;
  END_VAR
  VAR
    dA : TON;
    dB : TON;
    dC : TON;
  END_VAR
  INITIAL_STEP Wait:
    Count(P);
    RunA(N);
  END_STEP
  ACTION Count:
    starts := starts + 1;
  END_ACTION
  ACTION RunA:
    dA(IN := TRUE, PT := T#40ms, Q => lampA);
  END_ACTION
  TRANSITION FROM Wait TO StageB
    := lampA;
  END_TRANSITION
  STEP StageB:
    RunB(N);
  END_STEP
  ACTION RunB:
    dB(IN := lampA, PT := T#40ms, Q => lampB);
    IF lampB THEN lampA := FALSE; END_IF;
  END_ACTION
  TRANSITION FROM StageB TO StageC
    := lampB;
  END_TRANSITION
  STEP StageC:
    RunC(N);
  END_STEP
  ACTION RunC:
    dC(IN := lampB, PT := T#40ms, Q => lampC);
  END_ACTION
  TRANSITION FROM StageC TO Wait
    := lampC;
  END_TRANSITION
END_FUNCTION_BLOCK

PROGRAM main
  VAR
    relay : Relay;
  END_VAR
  relay();
END_PROGRAM

CONFIGURATION cfg
  RESOURCE res ON PLC
    TASK tick(INTERVAL := T#20ms, PRIORITY := 0);
    PROGRAM inst WITH tick : main;
  END_RESOURCE
END_CONFIGURATION
";

const RELAY_WATCH: &str = "inst.relay.lampA,inst.relay.lampB,inst.relay.lampC,inst.relay.starts";

/// The default profile keeps IEC 61131-3's action control: when StageB is left (cycle 5, lamp B
/// on), its action runs once more (the final scan), its TON sees IN = lamp A = FALSE and clears
/// lamp B in cycle 6, so StageC's timer never starts and the chart stays in StageC; the initial
/// step's P action ran in the first scan (starts = 1 from cycle 0). Unchanged by round 33.
#[test]
fn the_default_profile_runs_the_final_scan() {
    let trace = run("relay.st", RELAY, 16, RELAY_WATCH, &[]);
    assert_eq!(first_true(&trace, "inst.relay.lampA"), Some(2), "{trace}");
    assert_eq!(first_true(&trace, "inst.relay.lampB"), Some(5), "{trace}");
    assert_eq!(text_column(&trace, "inst.relay.lampB")[6], "0", "{trace}");
    assert_eq!(first_true(&trace, "inst.relay.lampC"), None, "{trace}");
    assert!(
        text_column(&trace, "inst.relay.starts")
            .iter()
            .all(|v| v == "1"),
        "{trace}"
    );
}

/// Under `--profile openplc` the chart runs as in Beremiz (matiec): no final scan, so lamp B stays
/// on, lamp C follows 3 scans later (cycle 8), the chart returns to Wait in cycle 9 and the P
/// action counts that start (starts 0 until cycle 9, then 1): the initial step was active before
/// the first scan, so its P action did not run in cycle 0. Before round 33: as the default
/// profile (lamp C never on, starts 1 from cycle 0).
#[test]
fn the_openplc_profile_controls_actions_as_beremiz() {
    let trace = run(
        "relay.st",
        RELAY,
        16,
        RELAY_WATCH,
        &["--profile", "openplc"],
    );
    assert_eq!(first_true(&trace, "inst.relay.lampA"), Some(2), "{trace}");
    assert_eq!(first_true(&trace, "inst.relay.lampB"), Some(5), "{trace}");
    assert!(
        text_column(&trace, "inst.relay.lampB")[5..]
            .iter()
            .all(|v| v == "1"),
        "{trace}"
    );
    assert_eq!(first_true(&trace, "inst.relay.lampC"), Some(8), "{trace}");
    let starts = text_column(&trace, "inst.relay.starts");
    assert!(starts[..9].iter().all(|v| v == "0"), "{trace}");
    assert_eq!(starts[9], "1", "{trace}");
}

/// The relay chart in a `plc.st` generated by Beremiz or OpenPLC Editor (its LOGGER preamble),
/// checked with the default profile: one W1466 at the chart's first action association
/// (`Count(P)`, line 30, column 5), saying the actions follow IEC's action control, not Beremiz's,
/// and naming `--profile openplc`; exit 0. Under `--profile openplc`, and for the chart without
/// the preamble, nothing. Before round 33: no diagnostic at all.
#[test]
fn a_generated_plc_st_with_a_chart_gets_one_w1466() {
    let src = format!("{GENERATED_PREAMBLE}{RELAY}");
    let (code, lines) = check_text("plc.st", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("plc.st:30:5: warning[W1466]: this chart's actions follow IEC 61131-3's action control here"),
        "{lines:?}"
    );
    assert!(lines[0].contains("--profile openplc"), "{lines:?}");

    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "plc.st", &src);
    let (code, _, stderr) = in_dir(dir.path(), &["check", "plc.st", "--profile", "openplc"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("W1466"), "{stderr}");

    let (_, lines) = check_text("relay.st", RELAY);
    assert!(lines.is_empty(), "{lines:?}");
}
