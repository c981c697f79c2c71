//! Constructs of the thirteenth acceptance run of issue #13 (2026-12-04, branch `round13`).
//!
//! **The round.** Public units no earlier round had tried, checked and run as a new user would
//! (`ladderc run FILES --cycles 5`, or `check`; snapshots of 2026-12-04), and programs never seen run
//! side by side with matiec (`scripts/matiec-diff.sh`, iec2c 6bb2c33). TwinCAT 3 projects:
//! zhaoshutao/HEPSCollimator, HEPSPLC, IAMWPLC, PSPLC, PWFACLM_PLC, TEST; ericocruz/ST01_State_machine,
//! msabbir007/PLC_Carwashing_Plant, stdaw/lift-hazi, iiisc/SDT200---Styrteknik,
//! martinmollaian/plc-automation-project. OpenPLC / Beremiz: Sub-Hank/PLC-Traffic-Light-Control,
//! tomas-lp/tpa-lab2-montecarlo, iruqqoyah/ICDFA_ACIS, nikhilv2/SPLC_Runtime. Other ST:
//! benniredds/ProgettoAx_A_B (SIMATIC AX), nni537014-collab/st, ghaith/rusty_avr (RuSTy),
//! anderssandstrom/ecmc_plugin_strucpp (STruCpp), jubnzv/iec-checker's `test/st` (50 files). IL text:
//! PickStone78/plc-demo `test.il`, hiperiondev/librelogic_newvm `test.il`, `test2.il`. IL of manuals,
//! reproduced (their text is not redistributable): Beckhoff TwinCAT 2 PLC Control "Instruction List
//! (IL)", Schneider Electric Machine Expert "Instruction List (IL) Language", IEC 61131-3's table of IL
//! instruction fields, an IL tutorial (two programs), the K5 / Kollmorgen KAS workbench help (`&`,
//! `BEGIN_IL`).
//!
//! | | units | run (or check) and behave | rejected, naming what is missing or wrong | ladderc gap |
//! |---|---|---|---|---|
//! | before | 30 (11 TwinCAT, 4 OpenPLC/Beremiz, 5 other ST, 3 IL files, 7 IL/ST of manuals) | 13 | 10 | 7 |
//! | after | 30 | 13 | 16 | 1: a TwinCAT SFC body (iiisc, E0321) |
//!
//! Gaps of this round, fixed here: a program's variable read by the program's name with an integer
//! literal beside it (`UserMode.fGap / 2`, zhaoshutao/TEST and HEPSPLC: E1012 "LINT_TO_LREAL converts
//! from LINT, not LREAL"); a based literal run into the keyword after it (`16#D013THEN`,
//! zhaoshutao/IAMWPLC: E0103 and E0100); `USING ns;` (SIMATIC AX: the file read as IL, W0001, E0007)
//! now W1421, and a task declared by its kind (`TASK Main : ProgramCycle;`) one E1048; a project's own
//! `MC_Power` ... (ecmc_plugin_strucpp: E1002 against ladderc's `<PLCopen blocks>`); `BEGIN_IL` ...
//! `END_IL` in an ST body (one error per ST line, now one E1046). The rejections name: Beckhoff
//! libraries (Tc2_SoE `FB_SoERead`, Tc2_ModbusSrv `FB_MBReadRegs`, Tc2_SerialCom `ComBuffer`, Tc2_System
//! `NT_StartProcess`, Tc2_Utilities `TC_Restart`, Tc2_SUPS's UPS blocks, Tc2_MC2's `MC_Jog` and
//! `NcToPlc` members, E1003/E1042), SIMATIC AX's task kinds (E1048), errors of the sources themselves
//! (a block instance declared twice, E1002; a configuration naming a program the file lacks, E1024;
//! initial values with units `0.5 ft`, E3011; `gvl.timer1sec;` as a statement, E0106; a GVL the
//! repository lacks, E1001; an example reading an output its library block lacks, E1011; `DT` as a
//! variable name, E1031), RuSTy's bit access by a variable (`%Xpin`) and non-IEC IL dialects (`%O:0`,
//! `%i0/4`, `JMP?`: E0006, E0001). Side by side with matiec: the seven IL/ST programs and an OpenPLC
//! text SFC are in the matiec_diff corpus (`r13_*`), each agreeing in every value; OpenPLC programs of
//! nikhilv2 (100 cycles), tomas-lp (600) and Sub-Hank (400) agree too (not redistributable: no licence).
//!
//! Each test is a small reproduction written here, run through `ladderc run` (C compiled with
//! the sanitizers) or `ladderc check`. The repositories' and manuals' texts are not copied here.

mod common;
use common::{rejected_heads, run_traced_files};

fn write(dir: &tempfile::TempDir, name: &str, text: &str) -> std::path::PathBuf {
    let f = dir.path().join(name);
    std::fs::write(&f, text).unwrap();
    f
}

/// A program's variable read by the program's name (`UserMode.maxGap`, W1413) beside an integer
/// literal, in the program itself and in another: the literal takes the variable's type (LREAL),
/// as beside any variable. Before: E1012 "LINT_TO_LREAL converts from LINT, not LREAL" for each
/// such expression (zhaoshutao/TEST, `IF Pos_LeftTopLin > UserMode.max_UserGapPositionNew/2 THEN`).
#[test]
fn a_program_variable_by_the_program_s_name_types_the_literal_beside_it() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(
        &dir,
        "gap.st",
        "PROGRAM UserMode\nVAR\n  maxGap : LREAL := 200;\n  pos : LREAL := 90;\n  over : BOOL;\n  half : LREAL;\n  n : INT := 7;\nEND_VAR\n\
         pos := pos + 5;\nover := pos > UserMode.maxGap/2;\nhalf := UserMode.maxGap/2 + UserMode.n/2;\nEND_PROGRAM\n\
         PROGRAM main\nVAR\n  quarter : LREAL;\n  k : INT;\nEND_VAR\nUserMode();\nquarter := UserMode.maxGap/4;\nk := UserMode.n * 3 - 1;\nEND_PROGRAM\n",
    );
    let (trace, stderr) = run_traced_files(
        &[&f],
        4,
        "UserMode.pos,UserMode.over,UserMode.half,main.quarter,main.k",
    );
    // UserMode runs twice a cycle (its own task without a CONFIGURATION, and main's call, W1417):
    // pos += 10; over once pos > 100. half: 200 / 2 + (7 / 2 = 3, an integer division) = 103
    assert_eq!(
        trace,
        "cycle,time_ms,UserMode.pos,UserMode.over,UserMode.half,main.quarter,main.k\n\
         0,0,100,0,103,50,20\n1,10,110,1,103,50,20\n2,20,120,1,103,50,20\n3,30,130,1,103,50,20\n"
    );
    assert!(!stderr.contains("E1012"), "{stderr}");
}

/// A based literal written against the keyword after it (`16#D013THEN`, as zhaoshutao/IAMWPLC's
/// MAIN has it, which TwinCAT compiles): the literal ends at its last digit, as the longest-token
/// rule reads it (matiec too: fixture `matiec_diff/r13_based_then_keyword.st`). Before: E0103 "`T`
/// is not a base-16 digit" and E0100 "expected `THEN`".
#[test]
fn a_based_literal_ends_before_the_keyword_it_runs_into() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(
        &dir,
        "diag.st",
        "PROGRAM main\nVAR\n  diag : WORD;\n  status : INT;\n  n : INT;\n  b : BYTE;\nEND_VAR\n\
         n := n + 1;\nIF n MOD 2 = 0 THEN diag := 16#D013; ELSE diag := 16#D012; END_IF;\n\
         IF diag = 16#D013THEN\n  status := 2;\nELSIF diag = 2#1101000000010010THEN\n  status := 1;\nEND_IF;\n\
         b := 16#0F;\nIF n > 2 AND b = 8#17THEN b := 16#F0; END_IF;\nEND_PROGRAM\n",
    );
    let (trace, _) = run_traced_files(&[&f], 4, "main.diag,main.status,main.b");
    assert_eq!(
        trace,
        "cycle,time_ms,main.diag,main.status,main.b\n0,0,53266,1,15\n1,10,53267,2,15\n2,20,53266,1,240\n3,30,53267,2,240\n"
    );
}

/// Only a keyword ends a based literal early: `16#FG` and `16#D013ELSE` (`E` is a hex digit, so the
/// literal would be `16#D013E` and `LSE` no keyword) stay one located E0103 each.
#[test]
fn a_based_literal_with_a_wrong_digit_is_still_e0103() {
    let heads = rejected_heads(
        "bad.st",
        "PROGRAM main\nVAR w : WORD; END_VAR\nw := 16#FG;\nIF w = 16#D013ELSE w := 1; END_IF;\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads[0],
        "bad.st:3:6: error[E0103]: invalid literal: `G` is not a base-16 digit"
    );
    assert!(
        heads[1]
            .starts_with("bad.st:4:8: error[E0103]: invalid literal: `L` is not a base-16 digit"),
        "{heads:?}"
    );
}

/// `BEGIN_IL` ... `END_IL` in an ST body (the K5 / Kollmorgen KAS workbench's IL section) is one
/// located E1046 and the POU's body is not compiled. Before: the body was read as IL (W0303) and
/// each ST line was an error of its own (E0011, E0007).
#[test]
fn an_il_section_inside_an_st_body_is_one_e1046() {
    let heads = rejected_heads(
        "kw.st",
        "PROGRAM kw\nVAR var1, var2 : BOOL; END_VAR\nvar1 := NOT var1;\n  BEGIN_IL\n   LD   var1\n   ST   var2\nEND_IL\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        ["kw.st:4:3: error[E1046]: `kw`: `BEGIN_IL` ... `END_IL` (an instruction list section inside an ST body) is a workbench extension, not IEC 61131-3"]
    );
}

/// `USING Siemens.Simatic.S71500.Tasks;` (IEC 61131-3 ed. 3 namespaces; benniredds/ProgettoAx_A_B, a
/// SIMATIC AX project) is one W1421 warning and ignored: a program that uses nothing from the
/// namespace runs. Before: the file was read as IL (W0001 "instructions outside any POU", E0007 for
/// the `;`).
#[test]
fn a_using_directive_is_one_warning_and_ignored() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(
        &dir,
        "main.st",
        "USING System.Timer;\nUSING Siemens.Simatic.S71500.Tasks, AxUnit;\n\nPROGRAM main\nVAR\n  n : INT;\n  q : BOOL;\nEND_VAR\n\
         n := n + 2;\nq := n > 4;\nEND_PROGRAM\n",
    );
    let (trace, stderr) = run_traced_files(&[&f], 3, "main.n,main.q");
    assert_eq!(
        trace,
        "cycle,time_ms,main.n,main.q\n0,0,2,0\n1,10,4,0\n2,20,6,1\n"
    );
    assert!(
        stderr.contains("main.st:1:1: warning[W1421]: `USING System.Timer`: no file of the project declares this namespace (a library's); the directive is ignored"),
        "{stderr}"
    );
    assert!(
        stderr
            .contains("main.st:2:1: warning[W1421]: `USING Siemens.Simatic.S71500.Tasks, AxUnit`"),
        "{stderr}"
    );
    assert!(
        !stderr.contains("W0001") && !stderr.contains("E0007"),
        "{stderr}"
    );
}

/// What only the namespace declares is reported where it is used, naming it (E1003), each error
/// located; the directive itself stays a warning.
#[test]
fn a_block_only_the_namespace_declares_is_named_where_it_is_used() {
    let heads = rejected_heads(
        "ax.st",
        "PROGRAM main\nUSING Siemens.Simatic.S71500.Clocks;\nVAR\n  clock : LocalClock;\n  n : INT;\nEND_VAR\n\
         n := n + 1;\nEND_PROGRAM\n",
    );
    assert_eq!(heads.len(), 2, "{heads:?}");
    assert!(
        heads[0].starts_with("ax.st:2:1: warning[W1421]"),
        "{heads:?}"
    );
    assert_eq!(
        heads[1],
        "ax.st:4:11: error[E1003]: unknown type `LocalClock`"
    );
}

/// A textual SFC as the OpenPLC Editor exports it (Sub-Hank/PLC-Traffic-Light-Control's `moteur.st`,
/// reproduced) runs: the action stored (S) in the initial step runs the
/// timers in every later scan, N actions set the lamps, the transitions are `:= expr`. Red 2 s, green
/// 3 s, amber 1 s (at 20 ms a scan: each change one scan after the timer's Q). The same program is in
/// the matiec_diff corpus (`r13_sfc_light.st`), agreeing with matiec over 700 scans.
#[test]
fn an_openplc_text_sfc_with_a_stored_action_runs() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(
        &dir,
        "light.st",
        "PROGRAM light\n  VAR\n    red AT %QX0.0 : BOOL;\n    amber AT %QX0.1 : BOOL;\n    green AT %QX0.2 : BOOL;\n  END_VAR\n\
         \x20 VAR\n    in_red : BOOL; in_green : BOOL; in_amber : BOOL;\n    t_red : TON; t_green : TON; t_amber : TON;\n  END_VAR\n\
         \x20 INITIAL_STEP S_Red:\n    red(N);\n    in_red(N);\n    TIMERS(S);\n  END_STEP\n\
         \x20 ACTION TIMERS:\n    t_red(IN := in_red, PT := T#2s);\n    t_green(IN := in_green, PT := T#3s);\n    t_amber(IN := in_amber, PT := T#1s);\n  END_ACTION\n\
         \x20 TRANSITION FROM S_Red TO S_Green\n    := t_red.Q;\n  END_TRANSITION\n\
         \x20 STEP S_Green:\n    green(N);\n    in_green(N);\n  END_STEP\n\
         \x20 TRANSITION FROM S_Green TO S_Amber\n    := t_green.Q;\n  END_TRANSITION\n\
         \x20 STEP S_Amber:\n    amber(N);\n    in_amber(N);\n  END_STEP\n\
         \x20 TRANSITION FROM S_Amber TO S_Red\n    := t_amber.Q;\n  END_TRANSITION\nEND_PROGRAM\n",
    );
    let out = common::ladderc()
        .args(["run"])
        .arg(&f)
        .args(["--cycles", "700", "--cycle-ms", "20", "--trace", "-"])
        .args(["--watch", "light.red,light.green,light.amber"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let trace = String::from_utf8_lossy(&out.stdout);
    // the scans where the lamps change
    let mut changes = Vec::new();
    let mut last = String::new();
    for line in trace.lines().skip(1) {
        let (scan, lamps) = line.split_once(',').unwrap();
        let lamps = lamps.split_once(',').unwrap().1.to_string();
        if lamps != last {
            changes.push(format!("{scan}:{lamps}"));
            last = lamps;
        }
    }
    assert_eq!(
        changes,
        [
            "0:1,0,0",
            "101:0,1,0",
            "252:0,0,1",
            "303:1,0,0",
            "404:0,1,0",
            "555:0,0,1",
            "606:1,0,0"
        ]
    );
}

/// A project that declares its own `MC_Power` (and its own axis type), as the motion library of
/// anderssandstrom/ecmc_plugin_strucpp does for the ecmc runtime: the block is the project's, run as
/// written. Before: E1002 "`MC_Power` is declared twice", first declared in `<PLCopen blocks>`,
/// ladderc's own library block, which the project never asked for.
#[test]
fn a_project_s_own_mc_power_is_not_ladderc_s_library_block() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(
        &dir,
        "own_motion.st",
        "TYPE MY_AXIS_REF :\nSTRUCT\n  AxisIndex : DINT;\n  Enabled : BOOL;\nEND_STRUCT;\nEND_TYPE\n\n\
         FUNCTION_BLOCK MC_Power\nVAR_INPUT\n  Enable : BOOL;\nEND_VAR\nVAR_IN_OUT\n  Axis : MY_AXIS_REF;\nEND_VAR\n\
         VAR_OUTPUT\n  Status : BOOL;\nEND_VAR\nAxis.Enabled := Enable;\nStatus := Enable AND Axis.AxisIndex > 0;\nEND_FUNCTION_BLOCK\n\n\
         PROGRAM main\nVAR\n  ax : MY_AXIS_REF := (AxisIndex := 2);\n  pwr : MC_Power;\n  n : INT;\n  on : BOOL;\nEND_VAR\n\
         n := n + 1;\npwr(Enable := n >= 2, Axis := ax);\non := pwr.Status;\nEND_PROGRAM\n",
    );
    let (trace, stderr) = run_traced_files(&[&f], 3, "main.on,main.ax.Enabled");
    assert_eq!(
        trace,
        "cycle,time_ms,main.on,main.ax.Enabled\n0,0,0,0\n1,10,1,1\n2,20,1,1\n"
    );
    assert!(!stderr.contains("E1002"), "{stderr}");
}

/// A SIMATIC AX configuration (benniredds/ProgettoAx_A_B's form): tasks declared by their kind
/// (`TASK Main : ProgramCycle;`, a type of the `Siemens.Simatic.S71500.Tasks` namespace) are one
/// E1048 each, at the kind; the programs they run are not reported again. Before: W0001
/// "instructions outside any POU", E0007 for the USING's `;`, one E0011 "unexpected `:`" per task.
#[test]
fn a_task_declared_by_its_kind_is_one_e1048() {
    let heads = rejected_heads(
        "configuration.st",
        "USING Siemens.Simatic.S71500.Tasks;\n\nCONFIGURATION Cfg\n    TASK MyStartupTask : Startup;\n    TASK MyProgramCycleTask : ProgramCycle;\n\n\
         \x20   PROGRAM P1 WITH MyStartupTask : Init;\n    PROGRAM P2 WITH MyProgramCycleTask : Main;\n\n\
         \x20   VAR_GLOBAL\n        myOutput AT %Q0.0 : BOOL;\n    END_VAR\nEND_CONFIGURATION\n\n\
         PROGRAM Init\nVAR_EXTERNAL\n  myOutput : BOOL;\nEND_VAR\nmyOutput := TRUE;\nEND_PROGRAM\n\n\
         PROGRAM Main\nVAR_EXTERNAL\n  myOutput : BOOL;\nEND_VAR\nmyOutput := NOT myOutput;\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        [
            "configuration.st:1:1: warning[W1421]: `USING Siemens.Simatic.S71500.Tasks`: no file of the project declares this namespace (a library's); the directive is ignored",
            "configuration.st:4:26: error[E1048]: task `MyStartupTask` is declared by its kind `Startup`, not by a schedule",
            "configuration.st:5:31: error[E1048]: task `MyProgramCycleTask` is declared by its kind `ProgramCycle`, not by a schedule",
        ]
    );
}

/// Only `BEGIN_IL` alone on its line opens an IL section: a variable named `begin_il` assigned at
/// the start of a line is a statement as any other.
#[test]
fn a_variable_named_begin_il_is_no_il_section() {
    let dir = tempfile::tempdir().unwrap();
    let f = write(
        &dir,
        "p.st",
        "PROGRAM p\nVAR begin_il : BOOL; n : INT; END_VAR\nbegin_il := n > 0; (* BEGIN_IL *)\nn := n + 1;\nEND_PROGRAM\n",
    );
    let (trace, stderr) = run_traced_files(&[&f], 2, "p.begin_il,p.n");
    assert_eq!(trace, "cycle,time_ms,p.begin_il,p.n\n0,0,0,1\n1,10,1,2\n");
    assert!(!stderr.contains("E1046"), "{stderr}");
}

/// `register^.%Xpin := TRUE;` (ghaith/rusty_avr, RuSTy's bit access by a variable): one located
/// E0103 saying what is wrong, a partial access taking a number (`x.%X3`). Before: "`%Xpin` is not a
/// direct address: the area must be I, Q or M".
#[test]
fn a_partial_access_by_a_variable_says_so() {
    let heads = rejected_heads(
        "avr.st",
        "FUNCTION setPin : DINT\nVAR_INPUT\n  register : REF_TO BYTE;\n  pin : DINT;\nEND_VAR\n\tregister^.%Xpin := TRUE;\nEND_FUNCTION\n",
    );
    assert_eq!(
        heads,
        ["avr.st:6:12: error[E0103]: invalid literal: `%Xpin` names its part by a variable: a partial access takes a number (`x.%X3`), as IEC 61131-3 writes it"]
    );
}
