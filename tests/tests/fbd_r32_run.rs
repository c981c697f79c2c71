//! FBD, SFC and Beremiz points of round 32 (issue #13), found in zarekvane/beremiz3 and
//! MrVeka/OpenPLC-I2C:
//! - a feedback loop drawn with wires only (an `AND` whose `OUT` feeds its own `IN1`, an `OR`/`AND`
//!   latch) runs, the box evaluated first reading the other box's result of the previous scan
//!   (IEC 61131-3 ed. 2 4.1.3, feedback paths: explicit loops are allowed in FBD, the feedback value
//!   is the previous evaluation's, the initial value at the first); before: E3010 and the network
//!   skipped;
//! - a byte that is not UTF-8 in a Beremiz confnode file (`cfile.xml`) is read as Windows-1252 with
//!   note W0305 at the byte, as in `plc.xml`; before: one E9001 without a place, a hint about the
//!   path's permissions, exit 2 and nothing checked;
//! - a BOOL variable that is an SFC action and is written in another action's body gets W1461 at
//!   the write (its action control sets it each scan, IEC 61131-3 ed. 2 2.6.4.5 a)); the values
//!   stay the standard's; before: nothing said.

mod common;
use common::{check_text, column, in_dir, run_stimulated, write_in};

/// A PLCopen TC6 project with one program `main` (BOOL locals `vars`) whose body is `fbd`.
fn project(vars: &[&str], fbd: &str) -> String {
    let decls: String = vars
        .iter()
        .map(|v| format!("<variable name=\"{v}\"><type><BOOL/></type></variable>"))
        .collect();
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-12-07T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="main" pouType="program">
      <interface><localVars>{decls}</localVars></interface>
      <body><FBD>
{fbd}
      </FBD></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="C"><resource name="R">
    <task name="t" priority="0" interval="T#10ms"><pouInstance name="inst" typeName="main"/></task>
  </resource></configuration></configurations></instances>
</project>
"#
    )
}

/// An input variable element.
fn input(id: u32, y: i64, name: &str) -> String {
    format!(
        "<inVariable localId=\"{id}\"><position x=\"10\" y=\"{y}\"/><connectionPointOut/>\
         <expression>{name}</expression></inVariable>\n"
    )
}

/// An output variable element fed by `OUT` of block `from`.
fn output(id: u32, y: i64, name: &str, from: u32) -> String {
    format!(
        "<outVariable localId=\"{id}\"><position x=\"400\" y=\"{y}\"/><connectionPointIn>\
         <connection refLocalId=\"{from}\" formalParameter=\"OUT\"/></connectionPointIn>\
         <expression>{name}</expression></outVariable>\n"
    )
}

/// A function box at `x` whose inputs are (pin, source localId, source pin or "" for a variable,
/// negated).
fn boxed(id: u32, x: i64, ty: &str, ins: &[(&str, u32, &str, bool)]) -> String {
    let pins: String = ins
        .iter()
        .map(|(pin, from, fpin, neg)| {
            let fp = if fpin.is_empty() {
                String::new()
            } else {
                format!(" formalParameter=\"{fpin}\"")
            };
            format!(
                "<variable formalParameter=\"{pin}\" negated=\"{neg}\"><connectionPointIn>\
                 <connection refLocalId=\"{from}\"{fp}/></connectionPointIn></variable>"
            )
        })
        .collect();
    format!(
        "<block localId=\"{id}\" typeName=\"{ty}\"><position x=\"{x}\" y=\"0\"/>\
         <inputVariables>{pins}</inputVariables><inOutVariables/><outputVariables>\
         <variable formalParameter=\"OUT\"><connectionPointOut/></variable></outputVariables></block>\n"
    )
}

fn write_temp(name: &str, text: &str) -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join(name);
    std::fs::write(&p, text).unwrap();
    (dir, p)
}

/// The standard's start/stop latch drawn with wires only (IEC 61131-3 ed. 2 figure 23 a)):
/// `run := OR(start, previous AND) AND NOT stop`, the OR box (left, evaluated first) reading the
/// AND box's result of the previous scan. It latches on a one-scan `start` pulse and drops on a
/// one-scan `stop` pulse. Before round 32: E3010 "feedback loop without a variable" and the network
/// skipped (`run` stayed FALSE).
#[test]
fn a_latch_drawn_with_wires_only_keeps_its_state_from_scan_to_scan() {
    let fbd = [
        input(1, 10, "start"),
        input(2, 60, "stop"),
        boxed(
            4,
            100,
            "OR",
            &[("IN1", 1, "", false), ("IN2", 5, "OUT", false)],
        ),
        boxed(
            5,
            200,
            "AND",
            &[("IN1", 4, "OUT", false), ("IN2", 2, "", true)],
        ),
        output(6, 10, "run", 5),
    ]
    .concat();
    let (_d, file) = write_temp("latch.xml", &project(&["start", "stop", "run"], &fbd));
    let (trace, stderr) = run_stimulated(
        &file,
        10,
        "2,inst.start,1\n3,inst.start,0\n6,inst.stop,1\n7,inst.stop,0\n",
        "inst.run",
    );
    assert!(!stderr.contains("E3010"), "{stderr}");
    assert_eq!(
        column(&trace, "inst.run"),
        [0., 0., 1., 1., 1., 1., 0., 0., 0., 0.],
        "{trace}"
    );
}

/// A NOT box whose input is its own output: the first scan reads the initial value (FALSE), so
/// `q` toggles every scan starting TRUE. An AND box fed by its own output (the shape of
/// zarekvane/beremiz3 `tests/svgui`, AND localId 96) compiles too. Before round 32: E3010.
#[test]
fn a_box_fed_by_its_own_output_reads_its_result_of_the_previous_scan() {
    let fbd = [
        boxed(3, 100, "NOT", &[("IN", 3, "OUT", false)]),
        output(4, 10, "q", 3),
        input(5, 100, "en"),
        boxed(
            6,
            100,
            "OR",
            &[("IN1", 6, "OUT", false), ("IN2", 5, "", false)],
        ),
        output(7, 110, "held", 6),
    ]
    .concat();
    let (_d, file) = write_temp("toggle.xml", &project(&["q", "en", "held"], &fbd));
    let (trace, _) = run_stimulated(&file, 6, "3,inst.en,1\n4,inst.en,0\n", "inst.q,inst.held");
    assert_eq!(
        column(&trace, "inst.q"),
        [1., 0., 1., 0., 1., 0.],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "inst.held"),
        [0., 0., 0., 1., 1., 1.],
        "{trace}"
    );
}

/// A Beremiz project whose C confnode (`cfile.xml`, declared UTF-8) holds the Windows-1252 byte
/// 0xB4 in a comment of its sketch: read as Windows-1252 with note W0305 at that byte (line 8),
/// its global `shared` declared, exit 0. Before round 32: `error[E9001]: cannot read
/// .../cfile.xml: stream did not contain valid UTF-8` without a place, the hint "check the path and
/// its permissions", exit 2 and nothing of the project checked.
#[test]
fn a_windows_1252_byte_in_a_confnode_file_is_a_located_note() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path();
    write_in(
        p,
        "beremiz.xml",
        "<?xml version='1.0' encoding='utf-8'?>\n<BeremizRoot URI_location=\"LOCAL://\"><TargetType/></BeremizRoot>\n",
    );
    let body = [
        input(1, 10, "shared"),
        "<outVariable localId=\"2\"><position x=\"400\" y=\"10\"/><connectionPointIn>\
         <connection refLocalId=\"1\"/></connectionPointIn><expression>copy</expression></outVariable>\n"
            .to_string(),
    ]
    .concat();
    let plc = project(&[], &body).replace(
        "<localVars></localVars>",
        "<localVars><variable name=\"copy\"><type><INT/></type></variable></localVars>\
         <externalVars><variable name=\"shared\"><type><INT/></type></variable></externalVars>",
    );
    write_in(p, "plc.xml", &plc);
    write_in(
        p,
        "c_ext_0@c_ext/baseconfnode.xml",
        "<?xml version='1.0' encoding='utf-8'?>\n<BaseParams IEC_Channel=\"0\" Name=\"c_ext_0\"/>\n",
    );
    write_in(
        p,
        "c_ext_0@c_ext/confnode.xml",
        "<?xml version='1.0' encoding='utf-8'?>\n<CExtension CFLAGS=\"\" LDFLAGS=\"\"/>\n",
    );
    let mut cfile = b"<?xml version='1.0' encoding='utf-8'?>\n\
<CFile xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">\n\
  <variables>\n\
    <variable name=\"shared\" type=\"INT\"/>\n\
  </variables>\n\
  <sketch>\n\
    <xhtml:p><![CDATA[\n\
// don"
        .to_vec();
    cfile.push(0xB4);
    cfile.extend_from_slice(
        b"t touch\nvoid sketch_loop() {}\n]]></xhtml:p>\n  </sketch>\n</CFile>\n",
    );
    std::fs::write(p.join("c_ext_0@c_ext/cfile.xml"), cfile).unwrap();
    let (code, _, stderr) = in_dir(p, &["check", "."]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("E9001"), "{stderr}");
    let notes: Vec<&str> = stderr.lines().filter(|l| l.contains("W0305")).collect();
    assert_eq!(notes.len(), 1, "{stderr}");
    assert!(
        notes[0].contains("c_ext_0@c_ext/cfile.xml:8:7:")
            && notes[0].contains("read as Windows-1252"),
        "{stderr}"
    );
}

const ACTION_VAR: &str = "PROGRAM main
VAR go : BOOL; lamp : BOOL; END_VAR
INITIAL_STEP Idle: Init(P); END_STEP
TRANSITION FROM Idle TO Run := go; END_TRANSITION
STEP Run: lamp(S); END_STEP
TRANSITION FROM Run TO Idle := NOT go; END_TRANSITION
ACTION Init: lamp := TRUE; END_ACTION
END_PROGRAM
";

/// `lamp` is a Boolean action (S in step `Run`) and the P action `Init` of the initial step writes
/// it: one W1461 at that write (line 7, column 14) naming the variable and the rule; the values
/// stay the standard's (the action control's Q every scan: TRUE in the first scan from `Init`,
/// FALSE after, since `Run` never becomes active). Before round 32: no diagnostic.
#[test]
fn a_boolean_action_written_in_another_action_is_a_warning_at_the_write() {
    let (code, lines) = check_text("sfc.st", ACTION_VAR);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("sfc.st:7:14: warning[W1461]: `lamp` is written here")
            && lines[0].contains("Boolean action")
            && lines[0].contains("every scan"),
        "{lines:?}"
    );
    let (_d, file) = write_temp("sfc.st", ACTION_VAR);
    let (trace, _) = run_stimulated(&file, 3, "", "main.lamp");
    assert_eq!(column(&trace, "main.lamp"), [1., 0., 0.], "{trace}");
}
