//! CODESYS and TwinCAT semantics of round 34 (issue #13), found by running real TwinCAT projects
//! side by side with hand-written models:
//! - **REAL to TIME.** In CODESYS and TwinCAT TIME is a 32-bit count of milliseconds (LTIME the
//!   64-bit count of nanoseconds), and `REAL_TO_<type>` "rounds the Real value ... to the nearest
//!   integer value", the only exceptions being STRING, BOOL, REAL and LREAL (Beckhoff infosys,
//!   tc3_plc_intro, "REAL/LREAL_TO_<type>"). Under the default profile (`time_number_unit` "ms",
//!   the CODESYS/TwinCAT rule) ladderc now rounds a real converted to TIME to whole milliseconds,
//!   halves to even as its other REAL to integer conversions; LTIME keeps nanoseconds, and
//!   `--profile openplc` (matiec's seconds) keeps the fraction. Found in Beckhoff-JP/various_blinker's
//!   `TIMEMUL` (`REAL_TO_TIME(TIME_TO_REAL(period) * duty)`: T#1333400024ns instead of T#1s333ms).
//! - **TwinCAT's processing order in SFC.** TwinCAT 3 and CODESYS ("Processing Order in SFC",
//!   Beckhoff infosys tc3_plc_intro; CODESYS SFC help) run in each cycle the exit actions, entry
//!   actions, step time and step actions, IEC actions, and last the transition check, so a step a
//!   transition activates in cycle k runs its actions from cycle k+1, and an IEC action runs once
//!   more "in the next cycle" after its step is left. IEC 61131-3 leaves the scan open. A chart
//!   read from a `.TcPOU` now runs in that order; textual and PLCopen XML charts keep ladderc's
//!   order (transitions at the start of the scan). Found in vetorres-uma/TC3_Lampara's SFC lamp
//!   (lit one scan early).
//!
//! The TwinCAT chart is written here, archive object by archive object (the attribute GUIDs are
//! the ones `ladder_compiler::twincat_sfc` documents).

mod common;
use common::{run_stimulated, run_text};

/// The column `name` of a trace, one text per scan.
fn col(trace: &str, name: &str) -> Vec<String> {
    let mut lines = trace.lines();
    let head: Vec<&str> = lines.next().unwrap_or("").split(',').collect();
    let k = head
        .iter()
        .position(|h| *h == name)
        .unwrap_or_else(|| panic!("no column {name}: {trace}"));
    lines
        .filter(|l| l.starts_with(|c: char| c.is_ascii_digit()))
        .map(|l| l.split(',').nth(k).unwrap_or("").to_string())
        .collect()
}

const REAL_TO_TIME_SRC: &str = "\
PROGRAM P
VAR
    half : REAL := 1.5;
    t1 : TIME;
    n1 : DINT;
    eq : BOOL;
    t2 : TIME;
    t3 : TIME;
    t4 : TIME;
    lt : LTIME;
    duty : REAL := 0.3333;
    c1 : TIME := REAL_TO_TIME(2.5);
END_VAR
t1 := REAL_TO_TIME(half);
n1 := TIME_TO_DINT(t1);
eq := t1 = T#2ms;
t2 := REAL_TO_TIME(TIME_TO_REAL(T#2S) * (1.0 - duty));
t3 := LREAL_TO_TIME(-0.4);
t4 := REAL_TO_TIME(half + 1.0);
lt := LREAL_TO_LTIME(1.5);
END_PROGRAM
";

/// `REAL_TO_TIME(1.5)` is T#2ms (TIME_TO_DINT 2, equal to T#2ms), the blinker's
/// `REAL_TO_TIME(2000.0 * 0.6667)` T#1s333ms, `LREAL_TO_TIME(-0.4)` T#0ms, 2.5 (a half: to even)
/// T#2ms at run time and in a declaration's constant expression, and `LREAL_TO_LTIME(1.5)` keeps
/// its nanoseconds (LTIME#1.5ms). Before round 34: T#1500us, 1, FALSE, T#1333400024ns, T#-400us,
/// T#2500us (and the constant T#2500us), the LTIME as now.
#[test]
fn real_to_time_rounds_to_whole_milliseconds_ltime_keeps_nanoseconds() {
    let (trace, stderr) = run_text(
        "p.st",
        REAL_TO_TIME_SRC,
        1,
        "P.t1,P.n1,P.eq,P.t2,P.t3,P.t4,P.c1,P.lt",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(col(&trace, "P.t1"), ["T#2ms"], "{trace}");
    assert_eq!(col(&trace, "P.n1"), ["2"], "{trace}");
    assert_eq!(col(&trace, "P.eq"), ["1"], "{trace}");
    assert_eq!(col(&trace, "P.t2"), ["T#1333ms"], "{trace}");
    assert_eq!(col(&trace, "P.t3"), ["T#0ms"], "{trace}");
    assert_eq!(col(&trace, "P.t4"), ["T#2ms"], "{trace}");
    assert_eq!(col(&trace, "P.c1"), ["T#2ms"], "{trace}");
    assert_eq!(col(&trace, "P.lt"), ["T#1500us"], "{trace}");
}

const NAME: &str = "38391c6d-6d4a-42f8-8ee7-9f45e5adafa8";
const INITIAL: &str = "6844a48e-46c2-4cc8-a185-a478f3b99cc0";
const MAIN_ACTION: &str = "700a583f-b4d4-43e4-8c14-629c7cd3bec8";
const QUALIFIER: &str = "e174fc0d-80b0-4a9e-a530-ca239c249a50";

/// One `SFCAttribute` of an archive object.
fn attr(guid: &str, value: &str) -> String {
    format!(
        "<o><v n=\"AttributeId\">{{{guid}}}</v><o n=\"Value\" t=\"StringValue\">\
         <v n=\"Value\">\"{value}\"</v><v n=\"DefaultValue\">\"\"</v></o></o>\n"
    )
}

/// A step: its name, whether it is the initial step, its step action (empty for none) and its
/// IEC associations (action, qualifier).
fn step(name: &str, initial: bool, main: &str, iec: &[(&str, &str)]) -> String {
    let assocs: String = iec
        .iter()
        .map(|(a, q)| {
            format!(
                "<o><l2 n=\"Attributes\" cet=\"SFCAttribute\">\n{}{}</l2></o>\n",
                attr(NAME, a),
                attr(QUALIFIER, q)
            )
        })
        .collect();
    let initial = if initial {
        format!(
            "<o><v n=\"AttributeId\">{{{INITIAL}}}</v><o n=\"Value\" t=\"BoolValue\">\
             <v n=\"Value\">\"TRUE\"</v><v n=\"DefaultValue\">\"FALSE\"</v></o></o>\n"
        )
    } else {
        String::new()
    };
    format!(
        "<o t=\"SFCStep\">\n<n n=\"EmbeddedMainAction\" />\n\
         <o n=\"ElementList\" t=\"SFCElementList\">\n<l2 n=\"InnerList\" cet=\"SFCActionAssociation\">\n\
         {assocs}</l2>\n</o>\n<l2 n=\"Attributes\" cet=\"SFCAttribute\">\n{}{initial}{}</l2>\n</o>\n",
        attr(NAME, name),
        attr(MAIN_ACTION, main)
    )
}

/// A transition whose condition is the ST expression `cond`.
fn transition(cond: &str) -> String {
    format!(
        "<o t=\"SFCTransition\">\n<n n=\"EmbeddedTransition\" />\n\
         <l2 n=\"Attributes\" cet=\"SFCAttribute\">\n{}</l2>\n</o>\n",
        attr(NAME, cond)
    )
}

/// A jump to `target`.
fn jump(target: &str) -> String {
    format!(
        "<o t=\"SFCJump\">\n<l2 n=\"Attributes\" cet=\"SFCAttribute\">\n{}</l2>\n</o>\n",
        attr(NAME, target)
    )
}

/// A `.TcPOU` of declaration `decl`, an SFC body of the archive objects `elements` (in sequence)
/// and the ST actions `actions` (name, text).
fn tc_pou(name: &str, decl: &str, elements: &[String], actions: &[(&str, &str)]) -> String {
    let actions: String = actions
        .iter()
        .map(|(n, st)| {
            format!(
                "    <Action Name=\"{n}\" Id=\"{{00000000-0000-0000-0000-000000000001}}\">\n\
                 <Implementation>\n<ST><![CDATA[{st}]]></ST>\n</Implementation>\n</Action>\n"
            )
        })
        .collect();
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n\
         <TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4024.12\">\n\
         <POU Name=\"{name}\" Id=\"{{00000000-0000-0000-0000-000000000002}}\" SpecialFunc=\"None\">\n\
         <Declaration><![CDATA[{decl}]]></Declaration>\n<Implementation>\n<SFC>\n<XmlArchive>\n<Data>\n\
         <o xml:space=\"preserve\" t=\"SFCImplementationObject\">\n<o n=\"Root\" t=\"SFCSegment\">\n\
         <o n=\"ElementList\" t=\"SFCElementList\">\n<l2 n=\"InnerList\">\n{}</l2>\n</o>\n</o>\n</o>\n\
         </Data>\n</XmlArchive>\n</SFC>\n</Implementation>\n{actions}</POU>\n</TcPlcObject>\n",
        elements.concat()
    )
}

const CHART_WATCH: &str = "P_Chart.nCount,P_Chart.tS1,P_Chart.bS1,P_Chart.__sfc_X_S1";

/// A one-scan pulse of `bGo` at stimulus cycle 2 (trace row 2, the third scan).
const CHART_STIMULUS: &str = "2,P_Chart.bGo,1\n3,P_Chart.bGo,0\n";

/// `S0` (initial) -> `bGo` -> `S1` (IEC action `aCount` N: `nCount := nCount + 1`; step action
/// `aS1` copying `S1.t` and `S1.x`) -> `S1.t >= T#30ms` -> jump `S0`, scans of 10 ms, `bGo`
/// TRUE in the scan of row 2 only. In TwinCAT's order the transition check of row 2 activates
/// `S1` at the end of that scan (`S1._x` TRUE in row 2's trace, the activation for the next
/// cycle); its actions run from row 3 with `S1.t` 0, 10, 20, 30 ms; the check of row 6 (`S1.t`
/// = 30 ms) leaves it, and `aCount` runs once more in row 7 (IEC's final scan, TwinCAT's "second
/// time - but only in the next cycle - after the step has been deactivated"): the count runs
/// from row 3 to row 7. Before round 34 (transitions at the start of the scan): `S1` active and
/// counting from row 2, left at the start of row 5, the count from row 2 to row 5 (4 scans), and
/// `aS1`'s copies one scan earlier.
#[test]
fn a_twincat_chart_runs_a_step_s_actions_from_the_scan_after_its_transition() {
    let src = tc_pou(
        "P_Chart",
        "PROGRAM P_Chart\nVAR\n\tbGo : BOOL;\n\tnCount : INT;\n\ttS1 : TIME;\n\tbS1 : BOOL;\nEND_VAR\n",
        &[
            step("S0", true, "", &[]),
            transition("bGo"),
            step("S1", false, "aS1", &[("aCount", "N")]),
            transition("S1.t >= T#30ms"),
            jump("S0"),
        ],
        &[
            ("aCount", "nCount := nCount + 1;"),
            ("aS1", "tS1 := S1.t;\nbS1 := S1.x;"),
        ],
    );
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("P_Chart.TcPOU");
    std::fs::write(&file, &src).unwrap();
    let (trace, stderr) = run_stimulated(&file, 10, CHART_STIMULUS, CHART_WATCH);
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(
        col(&trace, "P_Chart.nCount"),
        ["0", "0", "0", "1", "2", "3", "4", "5", "5", "5"],
        "{trace}"
    );
    assert_eq!(
        col(&trace, "P_Chart.__sfc_X_S1"),
        ["0", "0", "1", "1", "1", "1", "0", "0", "0", "0"],
        "{trace}"
    );
    assert_eq!(
        col(&trace, "P_Chart.tS1"),
        [
            "T#0ms", "T#0ms", "T#0ms", "T#0ms", "T#10ms", "T#20ms", "T#30ms", "T#30ms", "T#30ms",
            "T#30ms"
        ],
        "{trace}"
    );
    assert_eq!(
        col(&trace, "P_Chart.bS1"),
        ["0", "0", "0", "1", "1", "1", "1", "1", "1", "1"],
        "{trace}"
    );
}

/// The same chart as textual SFC keeps ladderc's (IEC) order: `S1` active and counting in the
/// scan `bGo` fires (row 2), `S1.t` 0, 10, 20 ms, left at the start of row 5 (`S1.t` = 30 ms)
/// with the final scan there. Unchanged by round 34.
#[test]
fn a_textual_chart_keeps_transitions_at_the_start_of_the_scan() {
    let src = "PROGRAM P_Chart\nVAR\n\tbGo : BOOL;\n\tnCount : INT;\n\ttS1 : TIME;\n\tbS1 : BOOL;\nEND_VAR\n\
               INITIAL_STEP S0 :\nEND_STEP\nTRANSITION FROM S0 TO S1 := bGo;\nEND_TRANSITION\n\
               STEP S1 :\n\taCount(N);\n\taS1(N);\nEND_STEP\n\
               TRANSITION FROM S1 TO S0 := S1.T >= T#30ms;\nEND_TRANSITION\n\
               ACTION aCount :\n\tnCount := nCount + 1;\nEND_ACTION\n\
               ACTION aS1 :\n\ttS1 := S1.T;\n\tbS1 := S1.X;\nEND_ACTION\nEND_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("p_chart.st");
    std::fs::write(&file, src).unwrap();
    let (trace, stderr) = run_stimulated(&file, 8, CHART_STIMULUS, CHART_WATCH);
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(
        col(&trace, "P_Chart.nCount"),
        ["0", "0", "1", "2", "3", "4", "4", "4"],
        "{trace}"
    );
    assert_eq!(
        col(&trace, "P_Chart.__sfc_X_S1"),
        ["0", "0", "1", "1", "1", "0", "0", "0"],
        "{trace}"
    );
}
