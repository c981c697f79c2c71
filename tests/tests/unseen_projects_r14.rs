//! Ladder diagrams of the fourteenth acceptance run of issue #13 (2026-12-04, branch `round14`).
//!
//! **The round.** Public OpenPLC Editor / Beremiz projects (PLCopen XML `tc6_0201`, `plc.xml`) that
//! no earlier round had tried, with LD or FBD bodies, run as a new user would (`ladderc run FILE
//! --cycles 20`, inputs driven with `--stimulus`, values checked against the rungs; snapshots of
//! 2026-12-04): 1ioo/FactoryIO-Weight-Sorter, riverobruno/TPLA, charliehernandez97/WaterIrrigation
//! (two projects), jtuttas/CBasicModel (FBD), jtuttas/IHKBand (FBD), estidlore/parking-automation,
//! lsofia20/auto-segundo-examen, lsofia20/auto-workshop-4, kbuaaaaaa/COTS_ICS_Security,
//! Anubhab-lang/Redes, sakunamary/Roaster_s7-200 (two projects, LD and FBD). Beside them, two of
//! text bodies: AlessioP04/automatic-system (SFC and ST) and denisynx/WaterTank-Automation (ST).
//!
//! | | LD/FBD files | run and behave | rejected, naming what is missing or wrong | ladderc gap |
//! |---|---|---|---|---|
//! | before | 13 (12 repositories) | 9 | 2 | 2 |
//! | after | 13 | 10 | 2 | 1: 1ioo (below) |
//! | after Session 33 | 13 | 11 | 2 | 0 |
//!
//! Gap of this round, fixed here: an output variable wired to the result of a function box with EN
//! was written every scan with the box's last result, so Anubhab-lang/Redes's `Erro` (clamped at 0
//! by `MOVE` under `EN := Erro < 0`) was 0 in every scan (and W3400 claimed the later network
//! "wins every scan"); it is now written only when the box runs. Fixed in Session 33:
//! 1ioo/FactoryIO-Weight-Sorter chains `GT` -> `LE` by EN into a TON's IN; with EN FALSE ladderc's
//! box kept its last result, so the TON stayed on after the box left the scale and the sorter
//! re-latched its `SendRight` coil. A box that does not run now passes its result type's initial
//! value on, as matiec (OpenPLC) and Schneider's EN/ENO rule ("the outputs of the function are set
//! to 0") give it and as ladderc's ST calls already did: IEC 61131-3 gives functions no memory,
//! so a result kept from an earlier scan is not a function's (`chain_under_en.xml`, below).
//!
//! The rejections: a variable the project never declares (`Height_Out` written by an output
//! variable of kbuaaaaaa's `water_tank`, E1001 located at the element) and the blocks of an OpenPLC
//! board library the file does not hold (`I2C_OLED`, `I2C_AHT20` of sakunamary's `I2C_test`, E3009).
//! denisynx's ST body writes an undeclared `Pump` (E1001); AlessioP04's SFC runs.
//!
//! One difference from the Beremiz/OpenPLC code generator, closed in Session 33: these editors draw
//! one left power rail for the whole body, and ladderc joined every rung hanging on it into one
//! network, evaluated before any of its coils was written, so a rung read the coils of the rungs
//! above it one scan late (sakunamary's roaster dropped its latches one scan after STOP). A rail now
//! joins no rungs: each rung is a network, run top to bottom as IEC 61131-3 and Beremiz run them, and
//! STOP drops every latch in its own scan. Inside one rung a contact still reads the value from before
//! the rung (`crates/ladder-compiler/README.md`).
//!
//! Two projects are MIT-licensed and copied unchanged (`tests/fixtures/unseen/r14/`, with their
//! licences and `README.md`); the rejections are reproduced here in small files of our own.

mod common;
use common::{column, rejected_heads, run_stimulated};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/unseen/r14")
        .join(name)
        .join("plc.xml")
}

/// The value of column `name` after `cycle`.
fn at(trace: &str, name: &str, cycle: usize) -> f64 {
    column(trace, &format!("instance0.{name}"))[cycle]
}

/// estidlore/parking-automation: the entry barrier opens while a car coming in holds a ticket and
/// stays open 3 s (TOF `TofIn`, PT T#3000ms) after; the exit barrier likewise for a paid ticket;
/// switching the system off drops the `isComingIn`/`isComingOut` coils (each `x := x AND
/// isSystemOn`) and with them the tickets; the counters are reset while the system is on (their R is
/// `isSystemOn`), so `carsCameIn`/`carsCameOut` stay 0. The task runs every 20 ms: on even cycles.
#[test]
fn an_openplc_car_park_opens_and_closes_its_barriers() {
    let p = "instance0";
    let stimulus = format!(
        "0,{p}.isSystemOn,1\n0,{p}.isComingIn,1\n0,{p}.hasTicket,1\n10,{p}.isComingIn,0\n\
         20,{p}.isComingOut,1\n20,{p}.hasPaid,1\n100,{p}.isSystemOn,0\n"
    );
    let watch = [
        "isComingIn",
        "hasTicket",
        "isBarrierInOpen",
        "TofIn_ET",
        "isComingOut",
        "hasPaid",
        "isBarrierOutOpen",
        "carsCameIn",
        "carsCameOut",
    ]
    .map(|v| format!("{p}.{v}"))
    .join(",");
    let (trace, _) = run_stimulated(&fixture("parking"), 420, &stimulus, &watch);
    // entry: open from the first scan; the ticket drops with the car at 100 ms, the TOF holds 3 s
    assert_eq!(at(&trace, "isBarrierInOpen", 0), 1.0);
    assert_eq!(at(&trace, "hasTicket", 8), 1.0);
    assert_eq!(at(&trace, "hasTicket", 10), 0.0);
    assert_eq!(at(&trace, "isBarrierInOpen", 308), 1.0);
    assert_eq!(at(&trace, "isBarrierInOpen", 310), 0.0);
    // the ET output wired to an output variable: 2 s after the falling edge (t = 100 ms + 2000 ms)
    let et = trace.lines().nth(1 + 210).unwrap();
    assert!(et.contains(",T#2000ms,"), "{et}");
    // exit: open at 200 ms; the system switched off at 1 s drops the car and the payment, the
    // barrier closes 3 s later
    assert_eq!(at(&trace, "isBarrierOutOpen", 18), 0.0);
    assert_eq!(at(&trace, "isBarrierOutOpen", 20), 1.0);
    assert_eq!(at(&trace, "isComingOut", 98), 1.0);
    assert_eq!(at(&trace, "isComingOut", 100), 0.0);
    assert_eq!(at(&trace, "hasPaid", 100), 0.0);
    assert_eq!(at(&trace, "isBarrierOutOpen", 398), 1.0);
    assert_eq!(at(&trace, "isBarrierOutOpen", 400), 0.0);
    assert!(column(&trace, "instance0.carsCameIn")
        .iter()
        .all(|&c| c == 0.0));
    assert!(column(&trace, "instance0.carsCameOut")
        .iter()
        .all(|&c| c == 0.0));
}

/// sakunamary/Roaster_s7-200: RUN, heat and cooling push-buttons each toggle a latch (a rising-edge
/// contact sets it, a second press sets the `*_run` coil that breaks the latch, the falling edge
/// resets that coil); `system_out` is a TON of 2 s on the run latch; STOP drops every latch.
#[test]
fn an_openplc_roaster_toggles_its_latches_with_edge_contacts() {
    let p = "instance0";
    let rows = [
        (0, "RUN_BUTTON", 1),
        (4, "RUN_BUTTON", 0),
        (50, "heat_BUTTON", 1),
        (54, "heat_BUTTON", 0),
        (60, "cooling_BUTTON", 1),
        (64, "cooling_BUTTON", 0),
        (100, "heat_BUTTON", 1),
        (104, "heat_BUTTON", 0),
        (250, "STOP_BUTTON", 1),
        (254, "STOP_BUTTON", 0),
    ];
    let stimulus: String = rows
        .iter()
        .map(|(c, v, x)| format!("{c},{p}.{v},{x}\n"))
        .collect();
    let watch = [
        "RUN_STATUS",
        "system_out",
        "heat_out",
        "cooling_out",
        "stop_status",
        "sys_run",
        "heat_run",
    ]
    .map(|v| format!("{p}.{v}"))
    .join(",");
    let (trace, _) = run_stimulated(&fixture("roaster"), 270, &stimulus, &watch);
    let states = |cycle: usize| {
        [
            "RUN_STATUS",
            "system_out",
            "heat_out",
            "cooling_out",
            "stop_status",
        ]
        .map(|v| at(&trace, v, cycle) as u8)
    };
    assert_eq!(
        states(0),
        [1, 0, 0, 0, 0],
        "RUN pressed: the run latch sets"
    );
    assert_eq!(states(40), [1, 0, 0, 0, 0], "released: it holds");
    assert_eq!(states(56), [1, 0, 1, 0, 0], "heat pressed: its latch sets");
    assert_eq!(states(66), [1, 0, 1, 1, 0], "cooling pressed too");
    assert_eq!(states(106), [1, 0, 0, 1, 0], "heat pressed again: off");
    assert_eq!(states(190), [1, 0, 0, 1, 0], "TON of 2 s still running");
    assert_eq!(states(210), [1, 1, 0, 1, 0], "TON elapsed: system_out");
    assert_eq!(
        states(250),
        [0, 0, 0, 0, 1],
        "STOP: every latch drops in the same scan (its rung reads stop_status below the STOP rung)"
    );
    assert_eq!(
        states(256),
        [0, 0, 0, 0, 0],
        "STOP released: every latch stays off"
    );
    assert_eq!(states(268), [0, 0, 0, 0, 0]);
    // the second heat press set heat_run for the scan of its rising edge, which broke the latch in
    // the next scan; the falling edge reset it. RUN was pressed once: sys_run never set
    assert_eq!(at(&trace, "heat_run", 98), 0.0);
    assert_eq!(at(&trace, "heat_run", 100), 1.0);
    assert_eq!(at(&trace, "heat_run", 102), 0.0);
    assert!(column(&trace, "instance0.sys_run")
        .iter()
        .all(|&c| c == 0.0));
}

/// The OpenPLC Editor project header, an LD program `water_tank` with `vars` and `body`, and a task
/// running it every 20 ms.
fn openplc_ld(vars: &str, body: &str) -> String {
    format!(
        "<?xml version='1.0' encoding='utf-8'?>\n\
<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">\n\
<fileHeader companyName=\"t\" productName=\"r14\" productVersion=\"1\" creationDateTime=\"2026-12-04T00:00:00\"/>\n\
<contentHeader name=\"tank\"><coordinateInfo><fbd><scaling x=\"10\" y=\"10\"/></fbd><ld><scaling x=\"10\" y=\"10\"/></ld><sfc><scaling x=\"10\" y=\"10\"/></sfc></coordinateInfo></contentHeader>\n\
<types><dataTypes/><pous>\n\
<pou name=\"water_tank\" pouType=\"program\">\n\
<interface><localVars>\n{vars}</localVars></interface>\n\
<body><LD>\n{body}</LD></body>\n\
</pou>\n</pous></types>\n\
<instances><configurations><configuration name=\"Config0\"><resource name=\"Res0\">\n\
<task name=\"task0\" priority=\"0\" interval=\"T#20ms\"><pouInstance name=\"instance0\" typeName=\"water_tank\"/></task>\n\
</resource></configuration></configurations></instances>\n</project>\n"
    )
}

const RUNG: &str = "<leftPowerRail localId=\"1\"><position x=\"0\" y=\"0\"/><connectionPointOut formalParameter=\"\"/></leftPowerRail>\n\
<contact localId=\"2\" negated=\"false\"><position x=\"50\" y=\"0\"/><connectionPointIn><connection refLocalId=\"1\"/></connectionPointIn><connectionPointOut/><variable>Start</variable></contact>\n\
<coil localId=\"3\" negated=\"false\"><position x=\"150\" y=\"0\"/><connectionPointIn><connection refLocalId=\"2\"/></connectionPointIn><connectionPointOut/><variable>Pump</variable></coil>\n\
<rightPowerRail localId=\"4\"><position x=\"250\" y=\"0\"/><connectionPointIn><connection refLocalId=\"3\"/></connectionPointIn></rightPowerRail>\n";

const VARS: &str = "<variable name=\"Start\"><type><BOOL/></type></variable>\n\
<variable name=\"Height\"><type><INT/></type></variable>\n\
<variable name=\"Pump\"><type><BOOL/></type></variable>\n";

/// kbuaaaaaa/COTS_ICS_Security: an output variable of the LD body names a variable the POU never
/// declares. One located E1001 at the element (network and localId), exit 1.
#[test]
fn an_output_variable_naming_an_undeclared_variable_is_one_located_e1001() {
    let body = format!(
        "{RUNG}<inVariable localId=\"5\"><position x=\"50\" y=\"100\"/><connectionPointOut/><expression>Height</expression></inVariable>\n\
<outVariable localId=\"6\"><position x=\"150\" y=\"100\"/><connectionPointIn><connection refLocalId=\"5\"/></connectionPointIn><expression>Height_Out</expression></outVariable>\n"
    );
    let heads = rejected_heads("tank.xml", &openplc_ld(VARS, &body));
    assert_eq!(heads.len(), 1, "{heads:?}");
    assert!(
        heads[0].ends_with(
            "error[E1001]: undeclared name `Height_Out` [POU `water_tank`, network 2, localId 6]"
        ),
        "{heads:?}"
    );
    assert!(heads[0].starts_with("tank.xml:"), "{heads:?}");
}

/// sakunamary/Roaster_s7-200 `I2C_test`: a block of an OpenPLC board library (`I2C_AHT20`, the
/// Arduino I2C sensor blocks of the editor's library) that the file does not hold. One located E3009
/// naming the type, exit 1; the rest of the body is not reported.
#[test]
fn a_block_of_an_openplc_board_library_is_one_located_e3009() {
    let vars = format!(
        "{VARS}<variable name=\"AHT20\"><type><derived name=\"I2C_AHT20\"/></type></variable>\n\
<variable name=\"temp\"><type><REAL/></type></variable>\n"
    );
    let body = format!(
        "{RUNG}<block localId=\"7\" typeName=\"I2C_AHT20\" instanceName=\"AHT20\"><position x=\"100\" y=\"100\"/>\n\
<inputVariables><variable formalParameter=\"EN\"><connectionPointIn><connection refLocalId=\"2\"/></connectionPointIn></variable></inputVariables>\n\
<inOutVariables/><outputVariables><variable formalParameter=\"TEMP\"><connectionPointOut/></variable></outputVariables></block>\n\
<outVariable localId=\"8\"><position x=\"250\" y=\"100\"/><connectionPointIn><connection refLocalId=\"7\" formalParameter=\"TEMP\"/></connectionPointIn><expression>temp</expression></outVariable>\n"
    );
    let heads = rejected_heads("i2c.xml", &openplc_ld(&vars, &body));
    assert_eq!(heads.len(), 1, "{heads:?}");
    assert!(
        heads[0].contains("error[E3009]: type `I2C_AHT20` is not defined in this project"),
        "{heads:?}"
    );
    assert!(heads[0].starts_with("i2c.xml:"), "{heads:?}");
}

/// Anubhab-lang/Redes (reproduced in `clamp_under_en.xml`): an output variable wired to the result
/// of a function box with EN is written only when EN is TRUE (the box runs), so `erro := setpoint -
/// temp` is clamped at 0 by `MOVE(EN := erro < 0, IN := 0)` only when it is negative, as Beremiz /
/// OpenPLC generate it (`IF MOVE_ENO THEN erro := MOVE_OUT; END_IF`) and the vendors document ("the
/// connected variable keeps its value"). Before: the box's last result (0) was written every scan,
/// `erro` and `power` stayed 0, and W3400 said the later network "wins every scan".
#[test]
fn an_output_of_a_function_box_under_en_is_written_only_when_it_runs() {
    let f = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/unseen/r14/clamp_under_en.xml");
    let p = "instance0";
    let stimulus = format!("0,{p}.setpoint,100\n0,{p}.temp,60\n4,{p}.temp,150\n8,{p}.temp,90\n");
    let (trace, stderr) = run_stimulated(&f, 12, &stimulus, &format!("{p}.erro,{p}.power"));
    // 100 - 60 = 40 (not clamped), 100 - 150 = -50 clamped to 0, 100 - 90 = 10
    assert_eq!(
        trace,
        "cycle,time_ms,instance0.erro,instance0.power\n\
         0,0,40,120\n1,10,40,120\n2,20,40,120\n3,30,40,120\n\
         4,40,0,0\n5,50,0,0\n6,60,0,0\n7,70,0,0\n\
         8,80,10,30\n9,90,10,30\n10,100,10,30\n11,110,10,30\n"
    );
    assert!(!stderr.contains("W3400"), "{stderr}");
}

/// 1ioo/FactoryIO-Weight-Sorter (a repository without a licence; reproduced in
/// `chain_under_en.xml`): a `GT` box under `EN := AtScale` feeds a TON's IN. While the box is on the
/// scale the TON times and `SendRight` comes on; when `AtScale` drops, the box does not run and
/// passes FALSE (BOOL's initial value) on, so the TON resets and `SendRight` drops. The output
/// variable `Heavy`, wired straight to the box, is not written and keeps TRUE. Before: the box kept
/// its last result TRUE, the TON stayed on and `SendRight` stayed latched.
#[test]
fn a_function_box_that_does_not_run_passes_its_initial_value_on() {
    let f = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/unseen/r14/chain_under_en.xml");
    let p = "instance0";
    let stimulus = format!("0,{p}.AtScale,TRUE\n0,{p}.Weight,9\n6,{p}.AtScale,FALSE\n");
    let (trace, _) = run_stimulated(
        &f,
        10,
        &stimulus,
        &format!("{p}.Heavy,{p}.Settle.ET,{p}.SendRight"),
    );
    assert_eq!(
        trace,
        "cycle,time_ms,instance0.Heavy,instance0.Settle.ET,instance0.SendRight\n\
         0,0,1,T#0ms,0\n1,10,1,T#10ms,0\n2,20,1,T#20ms,0\n3,30,1,T#30ms,1\n\
         4,40,1,T#30ms,1\n5,50,1,T#30ms,1\n\
         6,60,1,T#0ms,0\n7,70,1,T#0ms,0\n8,80,1,T#0ms,0\n9,90,1,T#0ms,0\n"
    );
}
