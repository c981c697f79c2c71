//! Every redistributable real project of `tests/corpus/` (see its ATTRIBUTION.md) through the
//! `ladderc` binary: programs run a few cycles (C compiled with sanitizers and executed), files that
//! need what the export does not contain (vendor library types, POINTER TO) or that are not valid
//! IEC 61131-3 are rejected with exit 1, every error located (`file:line:col: error[CODE]`), and
//! naming what is missing. `.st` files are Structured Text (issue #13.1): they run too, and the
//! TwinCAT math library checks with one located E1019 per IronPLC intrinsic it calls.

mod common;
use common::ladderc;

use std::path::{Path, PathBuf};

/// `tests/corpus` of the workspace: the folder beside the `Cargo.lock` above this crate.
fn corpus_dir() -> PathBuf {
    let here = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let root = here
        .ancestors()
        .find(|a| a.join("Cargo.lock").is_file())
        .expect("the workspace root (Cargo.lock) above CARGO_MANIFEST_DIR");
    root.join("tests/corpus")
}

fn file(name: &str) -> PathBuf {
    let p = corpus_dir().join(name);
    assert!(p.is_file(), "{} is missing", p.display());
    p
}

/// Runs a project for `cycles` cycles; returns the trace.
fn runs(name: &str, cycles: u32) -> String {
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .arg("run")
        .arg(file(name))
        .args(["--cycles", &cycles.to_string(), "--sanitize", "--trace"])
        .arg(&trace)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{name}: {err}");
    assert!(!err.contains("runtime error"), "{name}: {err}");
    let text = std::fs::read_to_string(&trace).unwrap();
    assert_eq!(text.lines().count(), cycles as usize + 1, "{name}: {text}");
    text
}

/// Checks a file that must be rejected: exit 1, every error line located in the file itself, each
/// code among `codes`; returns the error lines.
fn rejected(name: &str, codes: &[&str]) -> Vec<String> {
    let out = ladderc()
        .args([
            "--message-format",
            "short",
            "--max-diagnostics",
            "0",
            "check",
        ])
        .arg(file(name))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(1), "{name}: {err}");
    let errors: Vec<String> = err
        .lines()
        .filter(|l| l.contains(": error["))
        .map(str::to_string)
        .collect();
    assert!(!errors.is_empty(), "{name}: {err}");
    let prefix = format!("{}:", file(name).display());
    for e in &errors {
        let rest = e
            .strip_prefix(&prefix)
            .unwrap_or_else(|| panic!("{name}: not located in the file: {e}"));
        let mut parts = rest.splitn(3, ':');
        let line: u32 = parts.next().unwrap().parse().expect("a line number");
        let col: u32 = parts.next().unwrap().parse().expect("a column number");
        assert!(line > 0 && col > 0, "{e}");
        assert!(
            codes.iter().any(|c| e.contains(&format!("error[{c}]"))),
            "{name}: unexpected code: {e}"
        );
    }
    errors
}

#[test]
fn openplc_dancing_lights_ld_runs() {
    let t = runs("godardhi0_dancinglights_plc.xml", 5);
    assert!(t.starts_with("cycle,time_ms,"), "{t}");
}

#[test]
fn idaholab_spemmcra_ld_runs() {
    runs("idaholab_SPEMMCRA_plc.xml", 5);
}

#[test]
fn codesys_s7rtt_st_motion_runs() {
    runs("feecat_S7RTT.xml", 3);
}

#[test]
fn wago_e_cockpit_export_runs() {
    let t = runs("AandIF_e-COCKPIT_python_scripting_plc.xml", 3);
    assert_eq!(t, "cycle,time_ms,PLC_PRG.i\n0,0,1\n1,10,2\n2,20,3\n");
}

#[test]
fn codesys_home_automation_export_names_its_vendor_libraries() {
    let errors = rejected(
        "MichielVanwelsenaere_HomeAutomation_CoDeSys3_PLCopen.xml",
        // E3009: library types (references and pointers compile since issue #13's `refs`
        // helper; before, one E0305 per POU declaring POINTER TO, its body not compiled). The
        // POUs in the vendor data of the device's resource are compiled too (round 7). The 26
        // blocks that EXTENDS another in the vendor data of their interface compile with their
        // bases (round 24; before, E0303 each), and their `ADR('auto')` (the address of a
        // string literal, round 24; before E0305) too; E0330: the 9 that IMPLEMENTS an
        // interface of the MQTT library, not in the file
        &["E3009", "E0330"],
    );
    let all = errors.join("\n");
    // the CODESYS-specific parts that are read now: no error about them any more
    for gone in [
        "interval",
        "typeName",
        "array dimension",
        "<derived> type",
        "POINTER TO",
        "pointer dereference",
        "error[E1011]",
    ] {
        assert!(!all.contains(gone), "{gone}: {all}");
    }
    // what the export genuinely lacks: library types, named as the file names them
    assert!(
        all.contains("`FB_OUTPUT_BINARY_MQTT` IMPLEMENTS `MQTT.MQTT_SUBSCRIBE_CALLBACK`, which names no INTERFACE of the project"),
        "{all}"
    );
    assert!(!all.contains("error[E0303]"), "{all}");
    for lib in [
        "`JSONVAR`",
        "`MQTT.QoS`",
        "`WagoAppDALI.",
        "`SysCom.SysComSettings`",
    ] {
        assert!(all.contains(lib), "{lib}: {all}");
    }
    // `ADR('auto')` passed to `StrEquals` in the bodies of the blocks that EXTEND another
    // (compiled since round 24) is the address of the literal's hidden copy: no E0305
    assert!(!all.contains("error[E0305]"), "{all}");
    // Standard.TON is the IEC timer, not a missing library type
    assert!(!all.contains("Standard.TON"), "{all}");
}

#[test]
fn il_parser_test1_is_rejected_for_its_set_without_operand() {
    let e = rejected("hiperiondev_il_parser_test1.il", &["E1016"]);
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(
        e[0].contains("test1.il:24:1: error[E1016]: S without operand"),
        "{e:?}"
    );
}

#[test]
fn il_parser_test2_is_rejected_for_its_semicolon_comments() {
    let e = rejected("hiperiondev_il_parser_test2.il", &["E0007"]);
    assert!(
        e.iter()
            .all(|l| l.contains("`;` comments are not IEC 61131-3")),
        "{e:?}"
    );
}

/// The ST text files: each is a program (or, for Tc2_Math, a library) that should run or check once
/// `.st` files are read as Structured Text.
fn st_runs(name: &str) {
    runs(name, 3);
}

#[test]
fn st_spemmcra_plc() {
    st_runs("idaholab_SPEMMCRA_plc.st");
}

#[test]
fn st_spemmcra_dnp3_microgrid() {
    st_runs("idaholab_SPEMMCRA_DNP3_Microgrid.st");
}

#[test]
fn st_ironplc_getting_started() {
    st_runs("ironplc_getting_started.st");
}

#[test]
fn st_ironplc_quickstart_timer() {
    st_runs("ironplc_quickstart_timer.st");
}

#[test]
fn st_ironplc_quickstart_helloworld() {
    st_runs("ironplc_quickstart_helloworld.st");
}

#[test]
fn st_ironplc_motor() {
    st_runs("ironplc_motor.st");
}

#[test]
fn st_ironplc_tc2_math_library() {
    rejected("ironplc_Tc2_Math.st", &["E1019"]);
}

// trust-platform (MIT OR Apache-2.0): tutorials and examples written for another IEC 61131-3
// runtime, found in issue #13's fourth acceptance run.

const TRUST: &str = "johannesPettersson80_trust-platform_";

/// `ladderc run` of several corpus files together for `cycles` cycles of 10 ms, watching `watch`:
/// the trace.
fn runs_together(names: &[&str], cycles: u32, watch: &str) -> String {
    let paths: Vec<_> = names.iter().map(|n| file(n)).collect();
    let refs: Vec<&Path> = paths.iter().map(|p| p.as_ref()).collect();
    common::run_traced_files(&refs, cycles, watch).0
}

#[test]
fn trust_platform_hello_counter_counts_each_cycle() {
    let t = runs_together(
        &[&format!("{TRUST}01_hello_counter.st")],
        3,
        "HelloCounter.count",
    );
    assert_eq!(
        t,
        "cycle,time_ms,HelloCounter.count\n0,0,1\n1,10,2\n2,20,3\n"
    );
}

#[test]
fn trust_platform_traffic_light_changes_phase_when_its_ton_elapses() {
    // TON of 500 ms at 10 ms cycles: Q at cycle 50; the timer is reset for one cycle (IN FALSE)
    // and restarts at cycle 52, so the next phases come at cycles 102 and 154
    let t = runs_together(
        &[&format!("{TRUST}03_traffic_light.st")],
        160,
        "TrafficLight.phase,TrafficLight.green",
    );
    let changes: Vec<&str> = t
        .lines()
        .skip(1)
        .scan(String::new(), |last, l| {
            let phase = l.split(',').nth(2).unwrap().to_string();
            let changed = *last != phase;
            *last = phase;
            Some(changed.then_some(l))
        })
        .flatten()
        .collect();
    assert_eq!(
        changes,
        vec!["0,0,0,0", "50,500,1,0", "102,1020,2,0", "154,1540,3,1"]
    );
}

#[test]
fn trust_platform_pid_loop_runs() {
    let t = runs_together(
        &[&format!("{TRUST}07_pid_loop.st")],
        2,
        "PidLoop.error,PidLoop.control_output",
    );
    assert_eq!(
        t,
        "cycle,time_ms,PidLoop.error,PidLoop.control_output\n0,0,10,17.1\n1,10,9.658001,11.615182\n"
    );
}

#[test]
fn trust_platform_configuration_and_program_in_two_files_run() {
    let t = runs_together(
        &[
            &format!("{TRUST}opcua_config.st"),
            &format!("{TRUST}opcua_main.st"),
        ],
        2,
        "TankLevel,PumpRunning",
    );
    // the globals of config.st, read by main.st through VAR_EXTERNAL: 42.5 is not above 50
    assert_eq!(
        t,
        "cycle,time_ms,TankLevel,PumpRunning\n0,0,42.5,0\n1,10,42.5,0\n"
    );
}

#[test]
fn trust_platform_var_config_of_an_unnominated_variable_is_a_located_e0306() {
    // its VAR_CONFIG (in Configuration.st) places `Counter` and `CounterLatched` of Main.st, which
    // are declared without `AT %M*`/`%Q*`: IEC 61131-3 6.5.6 (and CODESYS) place only variables
    // nominated with `*`. The entries are applied across the two files (before: "no program
    // `MainProgram` in this file").
    let names = [
        format!("{TRUST}memory_marker_counter_Configuration.st"),
        format!("{TRUST}memory_marker_counter_Main.st"),
    ];
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .args(names.iter().map(|n| file(n)))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err =
        String::from_utf8_lossy(&out.stderr).replace(&format!("{}/", corpus_dir().display()), "");
    let heads: Vec<&str> = err
        .lines()
        .filter(|l| l.contains("error["))
        .map(|l| l.split_once(" (hint").unwrap().0)
        .collect();
    assert_eq!(
        heads,
        vec![
            format!("{TRUST}memory_marker_counter_Configuration.st:5:5: error[E0306]: this VAR_CONFIG entry cannot be applied: `Counter` is not declared AT %M*"),
            format!("{TRUST}memory_marker_counter_Configuration.st:6:5: error[E0306]: this VAR_CONFIG entry cannot be applied: `CounterLatched` is not declared AT %Q*"),
        ]
    );
}

#[test]
fn tank_filling_and_mixing_sequence_runs_through_its_states() {
    // Syed337/PLC-Tank-Filling-Mixing-System (MIT): START fills three tanks until each level cuts
    // its valve, then 10 s of transfer (TON), 10 s of mixing (TON), drain until tank 4 is empty;
    // 1 s cycles
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n0,main.START,1\n1,main.START,0\n2,main.PV_TANK_1,25\n\
         2,main.PV_TANK_2,20\n2,main.PV_TANK_3,30\n2,main.PV_TANK_4,50\n26,main.PV_TANK_4,0\n",
    )
    .unwrap();
    let out = ladderc()
        .arg("run")
        .arg(file("Syed337_PLC-Tank-Filling-Mixing-System_main.st"))
        .args([
            "--cycles",
            "30",
            "--cycle-ms",
            "1000",
            "--sanitize",
            "--trace",
            "-",
        ])
        .arg("--stimulus")
        .arg(&stim)
        .args([
            "--watch",
            "main.STATE,main.VALVE_X,main.VALVE_OUT_XYZ,main.MIXER,main.VALVE_DRAIN,main.SYSTEM_ON",
        ])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let trace = String::from_utf8_lossy(&out.stdout);
    // the cycles where STATE changes
    let mut last = String::new();
    let changes: Vec<&str> = trace
        .lines()
        .skip(1)
        .filter(|l| {
            let s = l.split(',').nth(2).unwrap().to_string();
            let changed = s != last;
            last = s;
            changed
        })
        .collect();
    assert_eq!(
        changes,
        vec![
            "0,0,1,1,0,0,0,1",
            "2,2000,2,0,0,0,0,1",
            "13,13000,3,0,1,0,0,1",
            "24,24000,4,0,0,1,0,1",
            "26,26000,5,0,0,0,1,1",
            "27,27000,0,0,0,0,0,0",
        ]
    );
}

#[test]
fn a_watched_name_with_a_wrong_prefix_suggests_the_variable() {
    // watching the global `PumpRunning` as `Main.PumpRunning` (the program that uses it): before, the
    // error said "use --list", an option `ladderc run` does not have
    let out = ladderc()
        .arg("run")
        .arg(file(&format!("{TRUST}opcua_config.st")))
        .arg(file(&format!("{TRUST}opcua_main.st")))
        .args(["--cycles", "2", "--watch", "Main.PumpRunning"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("error: --watch: unknown variable `Main.PumpRunning`: did you mean `PumpRunning`? (a run without --watch traces every variable; a built program lists them with --list)"),
        "{err}"
    );
}

#[test]
fn tree_sitter_conveyor_latches_counts_and_stops() {
    // HeytalePazguato/tree-sitter-iec61131-3-st examples/conveyor.st (MIT): start/stop latch, parts
    // counted on rising edges of the outfeed sensor, E-stop forces the motor off and the fault lamp on
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n1,Conveyor.start_button,TRUE\n2,Conveyor.start_button,FALSE\n\
         3,Conveyor.outfeed_sensor,TRUE\n4,Conveyor.outfeed_sensor,FALSE\n5,Conveyor.outfeed_sensor,TRUE\n\
         6,Conveyor.stop_button,TRUE\n7,Conveyor.stop_button,FALSE\n7,Conveyor.start_button,TRUE\n\
         8,Conveyor.estop_button,TRUE\n",
    )
    .unwrap();
    let out = ladderc()
        .arg("run")
        .arg(file(
            "HeytalePazguato_tree-sitter-iec61131-3-st_conveyor.st",
        ))
        .args(["--cycles", "10", "--sanitize", "--trace", "-", "--stimulus"])
        .arg(&stim)
        .args([
            "--watch",
            "Conveyor.motor_run,Conveyor.fault_lamp,Conveyor.parts_counted",
        ])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "cycle,time_ms,Conveyor.motor_run,Conveyor.fault_lamp,Conveyor.parts_counted\n\
         0,0,0,0,0\n1,10,1,0,0\n2,20,1,0,0\n3,30,1,0,1\n4,40,1,0,1\n5,50,1,0,2\n\
         6,60,0,0,2\n7,70,1,0,2\n8,80,0,1,2\n9,90,0,1,2\n"
    );
}

#[test]
fn tia_portal_scl_exercise_is_one_error_naming_the_dialect() {
    // AutomatisierungsLabor/PlcDigitalTwinAutoTest (MIT): a TIA Portal SCL exercise saved as
    // test.st (`"DigInput".F1`, `#...`, `CONSTANT ... = ...`); before, 50 errors (the cap)
    let errors = rejected(
        "AutomatisierungsLabor_PlcDigitalTwinAutoTest_Silosteuerung_test.st",
        &["E0023"],
    );
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(
        errors[0].contains(":21:9: error[E0023]: this file is Siemens SCL (TIA Portal)"),
        "{errors:?}"
    );
}

#[test]
fn openplc_tutorial_xor_and_xnor_ld_follows_both_truth_tables() {
    // virajdesai0309/OpenPLC_Tutorials (MIT), an OpenPLC Editor LD lesson: OUTPUT_0 := INPUT_0 XOR
    // INPUT_1 and OUTPUT_1 := INPUT_2 XNOR INPUT_3, each as two contact branches in parallel (issue
    // #13, sixth round); its task runs every 20 ms, so one scan per 20 ms cycle
    let mut stimulus = String::new();
    for k in 0..4 {
        let (a, b) = ((k >> 1) & 1, k & 1);
        stimulus.push_str(&format!(
            "{k},instance0.INPUT_0,{a}\n{k},instance0.INPUT_1,{b}\n\
             {k},instance0.INPUT_2,{a}\n{k},instance0.INPUT_3,{b}\n"
        ));
    }
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, format!("cycle,variable,value\n{stimulus}")).unwrap();
    let out = ladderc()
        .arg("run")
        .arg(file(
            "virajdesai0309_OpenPLC_Tutorials_05_XOR_and_XNOR_Gate_plc.xml",
        ))
        .args([
            "--cycles",
            "4",
            "--cycle-ms",
            "20",
            "--sanitize",
            "--trace",
            "-",
        ])
        .arg("--stimulus")
        .arg(&stim)
        .args([
            "--watch",
            "instance0.INPUT_0,instance0.INPUT_1,instance0.OUTPUT_0,instance0.OUTPUT_1",
        ])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "cycle,time_ms,instance0.INPUT_0,instance0.INPUT_1,instance0.OUTPUT_0,instance0.OUTPUT_1\n\
         0,0,0,0,0,1\n1,20,0,1,1,0\n2,40,1,0,1,0\n3,60,1,1,0,1\n"
    );
}

const TANK_STATION: &str = "azizhamoudam-code_plc-tank-filling-station_";

#[test]
fn codesys_tank_filling_station_runs_its_batch_faults_and_resets() {
    // azizhamoudam-code/plc-tank-filling-station (MIT, round 30): a CODESYS V3.5 project kept as
    // four `.st` files (a strict, qualified-only enumeration, the controller block, a plant
    // simulation, PLC_PRG), run together at the project's 100 ms. Worked out from the source:
    // the simulation's TON (`IN := NOT Q`, 100 ms) ticks in cycles 3k+1, +1 % per tick while
    // filling and -1.5 % while draining; Start at 2 -> FILLING at 2, inlet from 3, 80 % at 241;
    // MIXING at 242, mixer 243-342 (TON 10 s from 242, seen by the CASE one scan later);
    // DRAINING at 343, drain from 344, 9.5 % at 484 -> COMPLETE at 485; Reset at 500 -> IDLE;
    // E-stop 520-524 -> FAULT with code 3 at 520; a Reset at 522 while the E-stop is held keeps
    // it FAULT (the project's own test case 5); Reset at 530 after the release -> IDLE, code 0
    // (test case 6)
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n2,PLC_PRG.xStart,1\n3,PLC_PRG.xStart,0\n500,PLC_PRG.xReset,1\n\
         501,PLC_PRG.xReset,0\n520,PLC_PRG.xEmergencyStop,1\n522,PLC_PRG.xReset,1\n\
         523,PLC_PRG.xReset,0\n525,PLC_PRG.xEmergencyStop,0\n530,PLC_PRG.xReset,1\n\
         531,PLC_PRG.xReset,0\n",
    )
    .unwrap();
    let out = ladderc()
        .arg("run")
        .args(
            [
                "E_TankState",
                "FB_TankController",
                "FB_TankSimulation",
                "PLC_PRG",
            ]
            .map(|f| file(&format!("{TANK_STATION}{f}.st"))),
        )
        .args([
            "--cycles",
            "540",
            "--cycle-ms",
            "100",
            "--sanitize",
            "--trace",
            "-",
        ])
        .arg("--stimulus")
        .arg(&stim)
        .args([
            "--watch",
            "PLC_PRG.fbTank.eState,PLC_PRG.fbTank.xInletValve,PLC_PRG.fbTank.xMixer,\
             PLC_PRG.fbTank.xDrainValve,PLC_PRG.fbTank.nErrorCode,PLC_PRG.fbTank.xFault,\
             PLC_PRG.fbSimulation.fLevelPercent",
        ])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(!err.contains("runtime error"), "{err}");
    let trace = String::from_utf8_lossy(&out.stdout);
    let rows: Vec<Vec<&str>> = trace
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 540);
    // the cycles where the state or an output changes: cycle, eState, inlet, mixer, drain,
    // error code, fault
    let mut last = Vec::new();
    let mut changes = Vec::new();
    for r in &rows {
        let key = r[2..8].to_vec();
        if key != last {
            changes.push(format!("{},{}", r[0], key.join(",")));
            last = key;
        }
    }
    assert_eq!(
        changes,
        [
            "0,0,0,0,0,0,0",
            "2,1,0,0,0,0,0",
            "3,1,1,0,0,0,0",
            "242,2,0,0,0,0,0",
            "243,2,0,1,0,0,0",
            "343,3,0,0,0,0,0",
            "344,3,0,0,1,0,0",
            "485,4,0,0,0,0,0",
            "500,0,0,0,0,0,0",
            "520,5,0,0,0,3,1",
            "530,0,0,0,0,0,0",
        ]
    );
    let level = |cycle: usize| rows[cycle][8];
    assert_eq!(
        [
            level(3),
            level(4),
            level(7),
            level(241),
            level(346),
            level(484),
            level(539)
        ],
        ["0", "1", "2", "80", "78.5", "9.5", "9.5"]
    );
}

#[test]
fn codesys_ld_start_stop_latch_and_on_delay_run() {
    // AlejandroCMed/codesys-plc-fundamentals (MIT, round 30), a CODESYS V3.5 SP22 LD export
    // without positions, at its task's 20 ms: rung 1 latches xOrdenMarcha (xMarcha OR
    // xOrdenMarcha, AND NOT xParo); rung 2 runs TON_Retardo (PT T#5S) on xOrdenMarcha and drives
    // xMotor from its Q AND NOT xParo. Start at cycle 5 (100 ms): the latch at 5, the TON's 5 s
    // elapse at 5100 ms, cycle 255; the stop at 400 clears the latch, the timer and the motor.
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n5,PLC_PRG.xMarcha,1\n6,PLC_PRG.xMarcha,0\n400,PLC_PRG.xParo,1\n\
         401,PLC_PRG.xParo,0\n",
    )
    .unwrap();
    let out = ladderc()
        .arg("run")
        .arg(file(
            "AlejandroCMed_codesys-plc-fundamentals_04_MarchaParo_TON.xml",
        ))
        .args([
            "--cycles",
            "410",
            "--cycle-ms",
            "20",
            "--sanitize",
            "--trace",
            "-",
        ])
        .arg("--stimulus")
        .arg(&stim)
        .args(["--watch", "PLC_PRG.xOrdenMarcha,PLC_PRG.xMotor"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    let trace = String::from_utf8_lossy(&out.stdout);
    // the rows where the latch or the motor changes (one scan per cycle of the task's 20 ms)
    let mut last = String::new();
    let changes: Vec<&str> = trace
        .lines()
        .skip(1)
        .filter(|l| {
            let key = l.splitn(3, ',').nth(2).unwrap_or("").to_string();
            let changed = key != last;
            last = key;
            changed
        })
        .collect();
    assert_eq!(
        changes,
        ["0,0,0,0", "5,100,1,0", "255,5100,1,1", "400,8000,0,0"]
    );
}
