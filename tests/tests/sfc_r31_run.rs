//! SFC charts of round 31 (issue #13), found in vetorres-uma/TC3_Lampara's SFC lamp blocks:
//! - a TwinCAT chart of one step (initial step, its action, a transition and a jump back to it:
//!   valid SFC, IEC 61131-3 ed. 2 2.6.3, a transition may lead back to the step it leaves) runs its
//!   action; before, its `<Action>` objects were refused (E0304 at an unrelated line of the XML
//!   archive) and the step named an unknown action (E3122);
//! - `Step.x` and `Step.t` in the actions of a chart's POU (a TwinCAT `<Action>`, an `ACTIONS`
//!   block after a textual chart) read the step's active flag and elapsed time (IEC 61131-3 ed. 3
//!   8.3.2, ed. 2 2.6.2: `step.X`, `step.T`; Beckhoff Infosys "Implicit variables" and CODESYS
//!   "Implicit Variables": `<stepname>.x`, `<stepname>.t`); before: E1001 "undeclared name";
//! - an initial value read from another variable in a POU whose body is a chart is computed at
//!   run time with W1433, as in an ST POU (README "Source text details"); before: E1025;
//! - `SUPER^()` in a block derived from a block whose body is a chart (textual or TwinCAT) runs one
//!   scan of the base's chart in the derived instance (Beckhoff infosys "SUPER"), found in
//!   x-PPU_PLC-Reconfiguration's control primitives; before: E0303.
//!
//! The TwinCAT files are written here, archive object by archive object (the attribute GUIDs are
//! the ones `ladder_compiler::twincat_sfc` documents).

mod common;
use common::{check_text, column, run_stimulated};

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

/// A step: its name, whether it is the initial step, its step action (`MainAction`, empty for
/// none) and its IEC associations (action, qualifier).
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

/// The trace rows of `watch`'s values, the cycle and time columns left out.
fn rows(trace: &str) -> Vec<String> {
    trace
        .lines()
        .skip(1)
        .filter(|l| l.starts_with(|c: char| c.is_ascii_digit()))
        .map(|l| l.split(',').skip(2).collect::<Vec<_>>().join(","))
        .collect()
}

/// `ladderc run` of `src` written to `dir/name` with the stimulus rows `stimulus`, 10 ms scans.
fn run_file(name: &str, src: &str, cycles: u32, stimulus: &str, watch: &str) -> (String, String) {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join(name);
    std::fs::write(&file, src).unwrap();
    run_stimulated(&file, cycles, stimulus, watch)
}

/// TC3_Lampara's one-step charts: `S0` (initial) with an IEC association `aCount(N)`, the
/// transition `bGo` and a jump back to `S0`; `aCount` counts its scans. The chart checks clean
/// and the action runs in every scan, also while the transition leaves `S0` and enters it again.
/// Before round 31: exit 1, E3122 "step `S0` names action `aCount`, which is neither an action
/// of the POU nor a BOOL variable" and E0304 "an ACTIONS block is supported only right after a
/// POU whose body is ST or IL", located at an unrelated `DefaultValue` line of the archive.
#[test]
fn a_one_step_twincat_chart_runs_its_action() {
    let src = tc_pou(
        "P_One",
        "PROGRAM P_One\nVAR\n\tbGo : BOOL;\n\tnCount : INT;\nEND_VAR\n",
        &[
            step("S0", true, "", &[("aCount", "N")]),
            transition("bGo"),
            jump("S0"),
        ],
        &[("aCount", "nCount := nCount + 1;")],
    );
    let (code, lines) = check_text("P_One.TcPOU", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(lines.iter().all(|l| !l.contains("error[")), "{lines:?}");
    let (trace, _) = run_file(
        "P_One.TcPOU",
        &src,
        5,
        "2,P_One.bGo,1\n3,P_One.bGo,0\n",
        "P_One.nCount,P_One.__sfc_X_S0",
    );
    assert_eq!(rows(&trace), ["1,1", "2,1", "3,1", "4,1", "5,1"]);
}

/// The same chart with the step action TC3_Lampara writes (`MainAction` `a_Lamp`, a CODESYS step
/// action) reading the step's flag: `bLamp := S0.x AND bButton;` follows the button in every scan
/// (before round 31: E3122 + E0304, and E1001 "undeclared name `S0`").
#[test]
fn a_one_step_chart_s_step_action_reads_its_step_flag() {
    let src = tc_pou(
        "FB_Lamp",
        "FUNCTION_BLOCK FB_Lamp\nVAR_INPUT\n\tbButton : BOOL;\n\tbGo : BOOL;\nEND_VAR\n\
         VAR_OUTPUT\n\tbLamp : BOOL;\nEND_VAR\n",
        &[
            step("S0", true, "a_Lamp", &[]),
            transition("bGo"),
            jump("S0"),
        ],
        &[("a_Lamp", "bLamp := S0.x AND bButton;")],
    );
    let main =
        "PROGRAM MAIN\nVAR\n\tbButton : BOOL;\n\tlamp : FB_Lamp;\n\tbLamp : BOOL;\nEND_VAR\n\
                lamp(bButton := bButton);\nbLamp := lamp.bLamp;\nEND_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("FB_Lamp.TcPOU"), &src).unwrap();
    std::fs::write(dir.path().join("main.st"), main).unwrap();
    let (trace, stderr) = common::run_stimulated_files(
        &[dir.path().join("main.st"), dir.path().join("FB_Lamp.TcPOU")],
        &["--cycle-ms", "10"],
        6,
        "2,MAIN.bButton,1\n4,MAIN.bButton,0\n",
        "MAIN.bLamp",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "MAIN.bLamp"), [0.0, 0.0, 1.0, 1.0, 0.0, 0.0]);
}

/// The steps' flags in the actions of a two-step TwinCAT chart: `Idle` -> `bGo` -> `Fill` ->
/// `bDone` -> jump `Idle`. `Fill`'s step action copies `Fill.t` and `Fill.x`, and `Idle.x`
/// (inactive there); `Idle`'s copies `Idle.x`. Scan by scan (10 ms; a stimulus row of cycle `n`
/// shows from the trace's row `n + 1`), in TwinCAT's processing order (round 34: the actions
/// first, the transition check last): `bGo` enters `Fill` at the end of its scan, whose action
/// runs from the next scan with the time counting 0, 10, 20 ms, and `bDone` leaves it at the end
/// of its scan (the action does not run in the scan after, the copies keep their values). Before round 31: E1001 "undeclared name
/// `Fill`".
#[test]
fn step_x_and_step_t_in_a_twincat_chart_s_actions_are_the_step_s_flag_and_time() {
    let src = tc_pou(
        "P_Flags",
        "PROGRAM P_Flags\nVAR\n\tbGo : BOOL;\n\tbDone : BOOL;\n\ttFill : TIME;\n\tbFillX : BOOL;\n\
         \tbIdleInFill : BOOL;\n\tbIdleX : BOOL;\nEND_VAR\n",
        &[
            step("Idle", true, "aIdle", &[]),
            transition("bGo"),
            step("Fill", false, "aFill", &[]),
            transition("bDone"),
            jump("Idle"),
        ],
        &[
            ("aIdle", "bIdleX := Idle.x;"),
            (
                "aFill",
                "tFill := Fill.t;\nbFillX := Fill.X;\nbIdleInFill := Idle.x;",
            ),
        ],
    );
    let (trace, stderr) = run_file(
        "P_Flags.TcPOU",
        &src,
        7,
        "2,P_Flags.bGo,1\n3,P_Flags.bGo,0\n5,P_Flags.bDone,1\n6,P_Flags.bDone,0\n",
        "P_Flags.tFill,P_Flags.bFillX,P_Flags.bIdleInFill,P_Flags.bIdleX,P_Flags.__sfc_X_Fill",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    // tFill (ms), Fill.x copy, Idle.x seen in Fill, Idle.x copy, Fill active
    assert_eq!(
        rows(&trace),
        [
            "T#0ms,0,0,1,0",
            "T#0ms,0,0,1,0",
            // TwinCAT's processing order (round 34): `Fill`'s action from the scan after
            // `bGo`'s, its flag set at the end of `bGo`'s scan
            "T#0ms,0,0,1,1",
            "T#0ms,1,0,1,1",
            "T#10ms,1,0,1,1",
            "T#20ms,1,0,1,0",
            "T#20ms,1,0,1,0",
        ]
    );
}

/// The same flags in a textual chart's `ACTIONS` block (CODESYS's and TwinCAT's form of a
/// chart's actions in an `.st` file): `S1.T` and `S1.X` in `aRun`. Before round 31: E1001
/// "undeclared name `S1`" (only the chart's own `ACTION ... END_ACTION` elements read them).
#[test]
fn step_flags_in_an_actions_block_after_a_textual_chart() {
    let src = "PROGRAM P_Text\nVAR\n\tgo : BOOL;\n\ttRun : TIME;\n\tbRun : BOOL;\nEND_VAR\n\
               INITIAL_STEP S0 :\nEND_STEP\nTRANSITION FROM S0 TO S1 := go;\nEND_TRANSITION\n\
               STEP S1 :\n\taRun(N);\nEND_STEP\nTRANSITION FROM S1 TO S0 := NOT go;\nEND_TRANSITION\n\
               END_PROGRAM\nACTIONS\nACTION aRun:\ntRun := S1.T;\nbRun := S1.X;\nEND_ACTION\n\
               END_ACTIONS\n";
    let (trace, stderr) = run_file(
        "p_text.st",
        src,
        5,
        "2,P_Text.go,1\n",
        "P_Text.tRun,P_Text.bRun",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(
        rows(&trace),
        ["T#0ms,0", "T#0ms,0", "T#0ms,1", "T#10ms,1", "T#20ms,1"]
    );
}

/// TC3_Lampara's `ManiobrasPendientes : UINT := ManiobrasTotales;` in a block whose body is a
/// chart: the initial value is read from the other variable when the instance is initialised,
/// with one W1433 (as in an ST block), in a TwinCAT chart and in a textual one. Before round 31:
/// E1025 "`nTotal` is not a constant known here".
#[test]
fn an_initial_value_read_from_another_variable_in_a_chart_s_block_is_computed_at_run_time() {
    let decl = "FUNCTION_BLOCK FB_Count\nVAR_INPUT\n\tbPress : BOOL;\nEND_VAR\n\
                VAR\n\tnTotal : UINT := 3;\n\tnLeft : UINT := nTotal;\nEND_VAR\n";
    let tc = tc_pou(
        "FB_Count",
        decl,
        &[
            step("S0", true, "aCount", &[]),
            transition("FALSE"),
            jump("S0"),
        ],
        &[(
            "aCount",
            "IF bPress AND nLeft > 0 THEN\n\tnLeft := nLeft - 1;\nEND_IF",
        )],
    );
    let st = format!(
        "{decl}INITIAL_STEP S0 :\n\taCount(N);\nEND_STEP\nTRANSITION FROM S0 TO S0 := FALSE;\n\
         END_TRANSITION\nACTION aCount:\nIF bPress AND nLeft > 0 THEN\n\tnLeft := nLeft - 1;\n\
         END_IF;\nEND_ACTION\nEND_FUNCTION_BLOCK\n"
    );
    let main = "PROGRAM MAIN\nVAR\n\tbPress : BOOL;\n\tc : FB_Count;\n\tnLeft : UINT;\nEND_VAR\n\
                c(bPress := bPress);\nnLeft := c.nLeft;\nEND_PROGRAM\n";
    for (name, text) in [
        ("FB_Count.TcPOU", tc.as_str()),
        ("fb_count.st", st.as_str()),
    ] {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join(name), text).unwrap();
        std::fs::write(dir.path().join("main.st"), main).unwrap();
        let (code, lines) = common::check_files(&[(name, text), ("main.st", main)]);
        assert_eq!(code, Some(0), "{name}: {lines:?}");
        let (trace, stderr) = common::run_stimulated_files(
            &[dir.path().join("main.st"), dir.path().join(name)],
            &["--cycle-ms", "10"],
            6,
            "2,MAIN.bPress,1\n",
            "MAIN.nLeft",
        );
        let w: Vec<&str> = stderr.lines().filter(|l| l.contains("W1433")).collect();
        assert_eq!(w.len(), 1, "{name}: {stderr}");
        assert!(w[0].contains("`nLeft`"), "{name}: {stderr}");
        assert!(!stderr.contains("error["), "{name}: {stderr}");
        assert_eq!(
            column(&trace, "MAIN.nLeft"),
            [3.0, 3.0, 2.0, 1.0, 0.0, 0.0],
            "{name}"
        );
    }
}

/// A block whose body is a three-step chart (`Idle` -> `Run` -> `Done` -> `Idle`, each transition
/// on `go`; `Run` counts its scans in `n` by an N action) and two blocks derived from it.
const BASE_CHART: &str = "FUNCTION_BLOCK Base
VAR_INPUT
    go : BOOL;
END_VAR
VAR_OUTPUT
    n : INT;
END_VAR
INITIAL_STEP Idle:
END_STEP
TRANSITION FROM Idle TO Run := go;
END_TRANSITION
STEP Run:
    Count(N);
END_STEP
TRANSITION FROM Run TO Done := go;
END_TRANSITION
STEP Done:
END_STEP
TRANSITION FROM Done TO Idle := go;
END_TRANSITION
ACTION Count:
    n := n + 1;
END_ACTION
END_FUNCTION_BLOCK
";

/// `SUPER^()` in a block derived from a block whose body is a chart runs one scan of the base's
/// chart, its steps kept in the derived block's instance, and the derived block's body then
/// reads the steps' flags (`Idle.X`); a derived block that never calls `SUPER^()` runs no chart
/// (its `n` stays 0). Beckhoff infosys "SUPER": `SUPER^()` calls the body of the base's
/// function block; CODESYS online help "SUPER" says the same. Checked scan by scan: `go` TRUE
/// for one scan moves the chart one step on. Before round 31: E0303 "SUPER^() runs the body of
/// `Base`, which is SFC: not supported" (x-PPU_PLC-Reconfiguration's control primitives).
#[test]
fn super_call_of_a_base_whose_body_is_a_chart_runs_one_scan_of_it() {
    let src = format!(
        "{BASE_CHART}
FUNCTION_BLOCK Derived EXTENDS Base
VAR_OUTPUT
    idleX, runX, doneX : BOOL;
END_VAR
SUPER^();
idleX := Idle.X;
runX := Run.X;
doneX := Done.X;
END_FUNCTION_BLOCK

FUNCTION_BLOCK Plain EXTENDS Base
VAR_OUTPUT
    m : INT;
END_VAR
m := m + 1;
END_FUNCTION_BLOCK

PROGRAM Main
VAR
    d : Derived;
    p : Plain;
    go : BOOL;
    i, r, dn : BOOL;
    cnt, pn, pm : INT;
END_VAR
d(go := go);
i := d.idleX; r := d.runX; dn := d.doneX; cnt := d.n;
p(go := go);
pn := p.n; pm := p.m;
END_PROGRAM
"
    );
    let (trace, stderr) = run_file(
        "super_chart.st",
        &src,
        9,
        "1,Main.go,TRUE\n2,Main.go,FALSE\n4,Main.go,TRUE\n5,Main.go,FALSE\n6,Main.go,TRUE\n7,Main.go,FALSE\n",
        "Main.go,Main.i,Main.r,Main.dn,Main.cnt,Main.pn,Main.pm",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    // go, Idle.X, Run.X, Done.X, the base's count (N action of Run, one last scan as it is left),
    // the plain block's count (no chart: 0) and its own body's count
    assert_eq!(
        rows(&trace),
        [
            "0,1,0,0,0,0,1",
            "1,0,1,0,1,0,2",
            "0,0,1,0,2,0,3",
            "0,0,1,0,3,0,4",
            "1,0,0,1,4,0,5",
            "0,0,0,1,4,0,6",
            "1,1,0,0,4,0,7",
            "0,1,0,0,4,0,8",
            "0,1,0,0,4,0,9",
        ],
        "{trace}"
    );
}

/// A `.TcPOU` of declaration `decl` and ST body `body`.
fn tc_st_pou(name: &str, decl: &str, body: &str) -> String {
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n\
         <TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4024.12\">\n\
         <POU Name=\"{name}\" Id=\"{{00000000-0000-0000-0000-000000000003}}\" SpecialFunc=\"None\">\n\
         <Declaration><![CDATA[{decl}]]></Declaration>\n<Implementation>\n<ST><![CDATA[{body}]]></ST>\n\
         </Implementation>\n</POU>\n</TcPlcObject>\n"
    )
}

/// The TwinCAT form of x-PPU_PLC-Reconfiguration's control primitives: a base block whose body
/// is a TwinCAT chart (`.TcPOU` `<SFC>`, three steps advanced by `bGo`, `S1` counting its scans
/// by the action `aCount`) and a derived block (ST) whose body is `SUPER^();` then reads the step
/// flags. One scan of the chart per call, scan by scan. Before round 31: E0303 "SUPER^() runs
/// the body of `FB_Base`, which is SFC: not supported", 15 of them in x-PPU.
#[test]
fn super_call_of_a_twincat_chart_base_runs_one_scan_of_it() {
    let base = tc_pou(
        "FB_Base",
        "FUNCTION_BLOCK FB_Base\nVAR_INPUT\n\tbGo : BOOL;\nEND_VAR\nVAR_OUTPUT\n\tnCount : INT;\nEND_VAR\n",
        &[
            step("S0", true, "", &[]),
            transition("bGo"),
            step("S1", false, "", &[("aCount", "N")]),
            transition("bGo"),
            step("S2", false, "", &[]),
            transition("bGo"),
            jump("S0"),
        ],
        &[("aCount", "nCount := nCount + 1;")],
    );
    let derived = tc_st_pou(
        "FB_Derived",
        "FUNCTION_BLOCK FB_Derived EXTENDS FB_Base\nVAR_OUTPUT\n\tb0, b1, b2 : BOOL;\nEND_VAR\n",
        "SUPER^();\nb0 := S0.X;\nb1 := S1.X;\nb2 := S2.X;\n",
    );
    let main = tc_st_pou(
        "MAIN",
        "PROGRAM MAIN\nVAR\n\tfb : FB_Derived;\n\tgo, x0, x1, x2 : BOOL;\n\tn : INT;\nEND_VAR\n",
        "fb(bGo := go);\nx0 := fb.b0;\nx1 := fb.b1;\nx2 := fb.b2;\nn := fb.nCount;\n",
    );
    let dir = tempfile::tempdir().unwrap();
    let files: Vec<std::path::PathBuf> = [
        ("FB_Base.TcPOU", &base),
        ("FB_Derived.TcPOU", &derived),
        ("MAIN.TcPOU", &main),
    ]
    .iter()
    .map(|(n, src)| {
        let p = dir.path().join(n);
        std::fs::write(&p, src).unwrap();
        p
    })
    .collect();
    let (trace, stderr) = common::run_stimulated_files(
        &files,
        &["--cycle-ms", "10"],
        6,
        "1,MAIN.go,TRUE\n2,MAIN.go,FALSE\n3,MAIN.go,TRUE\n4,MAIN.go,TRUE\n",
        "MAIN.x0,MAIN.x1,MAIN.x2,MAIN.n",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(
        rows(&trace),
        // S0, S1, S2 active, the scans counted by S1's N action (one last scan after S1 is left);
        // `go` stays TRUE from scan 3: one step per scan; TwinCAT's processing order (round
        // 34): a step's actions from the scan after its transition
        ["1,0,0,0", "0,1,0,0", "0,1,0,1", "0,0,1,2", "1,0,0,3", "0,1,0,3"],
        "{trace}"
    );
}
