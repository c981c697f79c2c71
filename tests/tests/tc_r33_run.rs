//! Round 33 of issue #13: TwinCAT points found in public TwinCAT 3 projects, end to end.
//! - an LD/FBD operator box typed as its symbol (`-`, saved with call type `Minus`) and a CFC box
//!   `-` or `>` compute the operator, as the box `SUB` (`Sub`) or `GT` does (Beckhoff Infosys, TC3
//!   PLC, "Arithmetic operators": `SUB` is ST's `-`; before: E0325 "box `-` of call type `Minus`,
//!   which ladderc does not read" and E0326 "box `-` does not name a function";
//!   Beckhoff-JP/various_blinker);
//! - a property of a program's instance written and read through the program's name from another
//!   program (`MAIN.inst.Flag := TRUE;`, CODESYS and TwinCAT accept the program's name as
//!   qualifier, README W1413) runs the property's Set and Get accessors (before: E1011 "FB_Lamp
//!   has no input or output `__SET_FLAG`" with an empty list of parameters; 50 such errors in
//!   Dariusz791/Twincat3-Oop); a member a block truly lacks lists the block's variables in the
//!   hint, never an empty list;
//! - a `.TcPOU` in TwinCAT's old `<Single>` archive form is one located E3002 saying what it is and
//!   how to re-save it (before: "root element is <Single>, expected a PLCopen <project>").

mod common;
use common::{check_files, check_text, column, run_stimulated_files, run_text};
use std::path::PathBuf;

fn fixture(rel: &str) -> PathBuf {
    common::repo_root()
        .join("tests/tests/fixtures/twincat_graphical")
        .join(rel)
}

/// The trace of `file`'s text (written to a temporary `name`) run with `stimulus`.
fn trace_of(name: &str, text: &str, cycles: u32, stimulus: &str, watch: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join(name);
    std::fs::write(&file, text).unwrap();
    run_stimulated_files(
        &[file.as_path()],
        &["--cycle-ms", "10"],
        cycles,
        stimulus,
        watch,
    )
    .0
}

/// P_Edges (LD) counts edges with three `ADD` boxes (`n := n + 1`). Saved with each box typed `-`
/// (call type `Minus`, as TwinCAT 3.1.4024/4026 save a box the engineer typed as `-`) it counts
/// down: nRises is minus the number of rising edges at every cycle, and the trace is the one of
/// the boxes saved as `SUB`/`Sub`; `+`/`Plus` gives the trace of `ADD`/`Add`. Before: E0325 "box
/// `-` of call type `Minus`, which ladderc does not read", once per network.
#[test]
fn an_ld_box_typed_as_its_symbol_computes_the_operator() {
    let edges = std::fs::read_to_string(fixture("edges/P_Edges.TcPOU")).unwrap();
    assert_eq!(edges.matches("<v n=\"BoxType\">\"ADD\"</v>").count(), 3);
    let saved_as = |box_type: &str, call: &str| {
        edges
            .replace(
                "<v n=\"BoxType\">\"ADD\"</v>",
                &format!("<v n=\"BoxType\">\"{box_type}\"</v>"),
            )
            .replace(
                "<v n=\"CallType\" t=\"Operator\">Add</v>",
                &format!("<v n=\"CallType\" t=\"Operator\">{call}</v>"),
            )
    };
    let stimulus = "3,P_Edges.bIn,1\n6,P_Edges.bIn,0\n8,P_Edges.bIn,1\n9,P_Edges.bIn,0\n";
    let watch = "P_Edges.bIn,P_Edges.nRises,P_Edges.nFalls";
    let run = |text: &str| trace_of("P_Edges.TcPOU", text, 12, stimulus, watch);
    let minus = run(&saved_as("-", "Minus"));
    assert_eq!(minus, run(&saved_as("SUB", "Sub")));
    let rises = column(&minus, "P_Edges.nRises");
    let want: Vec<f64> = (0..12)
        .map(|c| match c {
            0..=2 => 0.0,
            3..=7 => -1.0,
            _ => -2.0,
        })
        .collect();
    assert_eq!(rises, want, "{minus}");
    assert_eq!(run(&saved_as("+", "Plus")), run(&edges));
}

/// P_Cooler (CFC) holds a cooler on between `rSet - rBand` and `rSet + rBand` with boxes `SUB`,
/// `ADD` and `GT`. Drawn with the symbols (`-`, `+`, `>`: a CFC box saves only its text) it runs
/// with the same trace. Before: E0326 "box `-` does not name a function".
#[test]
fn a_cfc_box_typed_as_its_symbol_computes_the_operator() {
    let cooler = std::fs::read_to_string(fixture("cfc/P_Cooler.TcPOU")).unwrap();
    let symbols = cooler
        .replace("<v n=\"Text\">\"SUB\"</v>", "<v n=\"Text\">\"-\"</v>")
        .replace("<v n=\"Text\">\"ADD\"</v>", "<v n=\"Text\">\"+\"</v>")
        .replace("<v n=\"Text\">\"GT\"</v>", "<v n=\"Text\">\"&gt;\"</v>");
    assert_ne!(symbols, cooler);
    let stimulus = "5,P_Cooler.rTemp,13.5\n15,P_Cooler.rTemp,12\n20,P_Cooler.rTemp,10.5\n";
    let watch = "P_Cooler.rTemp,P_Cooler.bCooler";
    let run = |text: &str| trace_of("P_Cooler.TcPOU", text, 25, stimulus, watch);
    let drawn = run(&symbols);
    assert_eq!(drawn, run(&cooler));
    // on above 13 (cycle 5), held at 12, off below 11 (cycle 20)
    let on = column(&drawn, "P_Cooler.bCooler");
    assert!(
        (0..25).all(|c| on[c] == f64::from(u8::from((5..20).contains(&c)))),
        "{drawn}"
    );
}

const FB_LAMP: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4024.12">
  <POU Name="FB_Lamp" Id="{33000000-0000-0000-0000-000000000001}" SpecialFunc="None">
    <Declaration><![CDATA[FUNCTION_BLOCK FB_Lamp
VAR
    bOn : BOOL;
    nSets : INT;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[]]></ST>
    </Implementation>
    <Property Name="Lit" Id="{33000000-0000-0000-0000-000000000002}">
      <Declaration><![CDATA[PROPERTY Lit : BOOL]]></Declaration>
      <Get Name="Get" Id="{33000000-0000-0000-0000-000000000003}">
        <Declaration><![CDATA[VAR
END_VAR
]]></Declaration>
        <Implementation>
          <ST><![CDATA[Lit := bOn;]]></ST>
        </Implementation>
      </Get>
      <Set Name="Set" Id="{33000000-0000-0000-0000-000000000004}">
        <Declaration><![CDATA[VAR
END_VAR
]]></Declaration>
        <Implementation>
          <ST><![CDATA[bOn := Lit;
nSets := nSets + 1;]]></ST>
        </Implementation>
      </Set>
    </Property>
  </POU>
</TcPlcObject>
"#;

/// `.TcPOU` text of PROGRAM `name` with `decls` and the ST `body`.
fn program(name: &str, decls: &str, body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4024.12">
  <POU Name="{name}" Id="{{33000000-0000-0000-0000-0000000000{n:02}}}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM {name}
VAR
{decls}
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[{body}]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
"#,
        n = name.len()
    )
}

const TASK: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4024.12">
  <Task Name="PlcTask" Id="{33000000-0000-0000-0000-0000000000f0}">
    <CycleTime>10000</CycleTime>
    <Priority>20</Priority>
    <PouCall><Name>MAIN</Name></PouCall>
    <PouCall><Name>PANEL</Name></PouCall>
  </Task>
</TcPlcObject>
"#;

/// TwinCAT object files: MAIN owns `lamp : FB_Lamp` (PROPERTY Lit, Get and Set; the setter counts
/// its calls) and sets it through its own name (`MAIN.lamp.Lit := bCmd;`); the program PANEL
/// reads it through MAIN's name (`bShown := MAIN.lamp.Lit;`) and writes it while bOff
/// (`MAIN.lamp.Lit := FALSE;`). Checks clean (W1413 notes only); cycle by cycle the setter runs
/// once per MAIN scan and once more per PANEL scan with bOff, and PANEL reads the value MAIN set
/// in the same scan. Before: E1011 "FB_Lamp has no input or output `__SET_LIT`" (and
/// `__GET_LIT`), hint "parameters of FB_Lamp: " (an empty list).
#[test]
fn a_property_through_the_program_name_runs_its_accessors() {
    let dir = tempfile::tempdir().unwrap();
    let files = [
        ("FB_Lamp.TcPOU", FB_LAMP.to_string()),
        (
            "MAIN.TcPOU",
            program(
                "MAIN",
                "    lamp : FB_Lamp;\n    bCmd : BOOL;",
                "MAIN.lamp.Lit := bCmd;",
            ),
        ),
        (
            "PANEL.TcPOU",
            program(
                "PANEL",
                "    bShown : BOOL;\n    bOff : BOOL;",
                "bShown := MAIN.lamp.Lit;\nIF bOff THEN\n    MAIN.lamp.Lit := FALSE;\nEND_IF",
            ),
        ),
        ("PlcTask.TcTTO", TASK.to_string()),
    ];
    let paths: Vec<PathBuf> = files
        .iter()
        .map(|(n, t)| {
            let p = dir.path().join(n);
            std::fs::write(&p, t).unwrap();
            p
        })
        .collect();
    let stimulus = "2,MAIN.bCmd,1\n5,PANEL.bOff,1\n6,PANEL.bOff,0\n";
    let (trace, stderr) = run_stimulated_files(
        &paths,
        &[],
        8,
        stimulus,
        "MAIN.bCmd,PANEL.bShown,MAIN.lamp.nSets",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert!(
        !stderr.contains("__SET_") && !stderr.contains("__GET_"),
        "{stderr}"
    );
    assert_eq!(
        column(&trace, "PANEL.bShown"),
        [0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "MAIN.lamp.nSets"),
        [1.0, 2.0, 3.0, 4.0, 5.0, 7.0, 8.0, 9.0],
        "{trace}"
    );
}

/// The same in one `.st` file: PROGRAM OTHER sets `MAIN.inst.Flag` and reads it back through
/// MAIN's name; the property's setter runs (the value read is the one written). Before: E1011
/// naming `__SET_FLAG` with an empty hint.
#[test]
fn a_property_through_the_program_name_runs_in_st() {
    let src = "FUNCTION_BLOCK FB_D
VAR b : BOOL; END_VAR
PROPERTY Flag : BOOL
GET
    Flag := b;
END_GET
SET
    b := Flag;
END_SET
END_PROPERTY
END_FUNCTION_BLOCK
PROGRAM MAIN
VAR inst : FB_D; seen : BOOL; END_VAR
seen := inst.Flag;
END_PROGRAM
PROGRAM OTHER
VAR back : BOOL; n : INT; END_VAR
n := n + 1;
MAIN.inst.Flag := n >= 3;
back := MAIN.inst.Flag;
END_PROGRAM
CONFIGURATION C
RESOURCE R ON PLC
TASK T(INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM MAIN WITH T : MAIN;
PROGRAM OTHER WITH T : OTHER;
END_RESOURCE
END_CONFIGURATION
";
    let (trace, stderr) = run_text("prop.st", src, 5, "OTHER.back,MAIN.seen");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "OTHER.back"), [0.0, 0.0, 1.0, 1.0, 1.0]);
    // MAIN runs first in the scan: it sees the value OTHER set in the scan before
    assert_eq!(column(&trace, "MAIN.seen"), [0.0, 0.0, 0.0, 1.0, 1.0]);
}

/// A member a derived block truly lacks (`m.SpeedSetpoint := 5.0;`, FB_Motor has no inputs or
/// outputs): one E1011 at the member, whose hint lists the block's variables (its own and its
/// base's), never an empty list. Before: hint "parameters of FB_Motor: ".
#[test]
fn an_unknown_member_lists_the_variables_of_the_block() {
    let src = "FUNCTION_BLOCK FB_Base
VAR bRun : BOOL; END_VAR
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_Motor EXTENDS FB_Base
VAR rSpeed : REAL; END_VAR
rSpeed := 1.0;
END_FUNCTION_BLOCK
PROGRAM MAIN
VAR m : FB_Motor; END_VAR
m.SpeedSetpoint := 5.0;
m();
END_PROGRAM
";
    let (code, lines) = check_text("motor.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    let e = errors[0];
    assert!(
        e.starts_with(
            "motor.st:10:3: error[E1011]: FB_Motor has no input or output `SpeedSetpoint`"
        ),
        "{e}"
    );
    assert!(e.contains("rSpeed") && e.contains("bRun"), "{e}");
    assert!(!e.contains("parameters of FB_Motor: )"), "{e}");
}

/// A `.TcPOU` saved in TwinCAT's old object archive form (root `<Single ...
/// Method="IArchivable">`) is one E3002 at the root saying what the file is and that it must be
/// re-saved in a current TwinCAT 3.1 or exported as PLCopen XML. Before: "root element is
/// <Single>, expected a PLCopen <project>".
#[test]
fn an_old_single_archive_is_named_as_such() {
    let text = r#"<?xml version="1.0" encoding="utf-8"?>
<Single xml:space="preserve" Type="{11f2245b-f54d-41e7-8df5-0dc5948f8965}" Method="IArchivable">
  <Single Name="MetaObject" Type="{81297157-7ec9-45ce-845e-84cab2b88ade}" Method="IArchivable">
    <Single Name="Name" Type="string">MAIN</Single>
  </Single>
</Single>
"#;
    let (code, lines) = check_files(&[("MAIN.TcPOU", text)]);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("MAIN.TcPOU:2:1: error[E3002]: a TwinCAT object saved in the old `<Single>` archive form"),
        "{lines:?}"
    );
    assert!(!lines[0].contains("PLCopen <project>"), "{lines:?}");
}
