//! CODESYS V3's object orientation in a PLCopen XML export ("Export PLCopenXML", issue #13,
//! round 24), run end to end through `ladderc run` on exports written for these tests
//! (`fixtures/codesys_xml_oop/`, modelled on the export's layout):
//! - every INTERFACE of the project is an `<Interface name="I">` in the vendor data block
//!   `.../plcopenxml/interface` (its `<Methods><Method>`, `<Properties><Property>`, and the
//!   interfaces it extends in `<Inheritance><Extends>`): a type the file defines, compiled
//!   (before: W3002, and each use of the type a false E3009 "probably comes from a library");
//! - a block's EXTENDS / IMPLEMENTS in `.../pouinheritance` are compiled as in ST text: SUPER^(),
//!   SUPER^.M(), overridden and inherited methods, calls through an interface variable and an
//!   array of interface references dispatch on the instance (before: one E0303, the body not
//!   compiled); the project runs as the same project written in ST does;
//! - a block missing an interface's method is one located E0335 in the XML file, once when two
//!   interfaces it implements reach the same one (before: E0303; the ST path reported it twice);
//! - a block that inherits but whose body is not ST is still one E0303 (the ST front end
//!   flattens text only).

mod common;
use common::{check_text, column, run_text};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/codesys_xml_oop")
        .join(rel)
}

fn fixture_text(rel: &str) -> String {
    std::fs::read_to_string(fixture(rel)).unwrap()
}

const WATCH: &str = "PLC_PRG.plain.count,PLC_PRG.fast.count,PLC_PRG.fast.extra,PLC_PRG.viaItf,\
PLC_PRG.sum,PLC_PRG.label,PLC_PRG.plain.bumps,PLC_PRG.fast.bumps,PLC_PRG.gauge.level";

/// `shapes.xml`: FB_Counter IMPLEMENTS I_Step (which EXTENDS I_Named), FB_FastCounter EXTENDS
/// FB_Counter (its body runs the base's through `SUPER^()`, its `Bump` overrides the base's and
/// calls it through `SUPER^.Bump`, its `Label` is inherited), FB_Gauge IMPLEMENTS I_Step, I_Named;
/// PLC_PRG calls `Bump` through an interface variable holding the derived instance and through an
/// `ARRAY[1..3] OF I_Step` holding one instance of each block.
#[test]
fn interfaces_and_inheritance_in_vendor_data_compile_and_run() {
    let (trace, stderr) = run_text("shapes.xml", &fixture_text("shapes.xml"), 3, WATCH);
    assert!(!stderr.contains("error"), "{stderr}");
    assert!(!stderr.contains("E3009"), "{stderr}");
    // the derived body runs the base's (count) then its own (extra)
    assert_eq!(column(&trace, "PLC_PRG.fast.count"), [1.0, 2.0, 3.0]);
    assert_eq!(column(&trace, "PLC_PRG.fast.extra"), [10.0, 20.0, 30.0]);
    assert_eq!(column(&trace, "PLC_PRG.plain.count"), [1.0, 2.0, 3.0]);
    // step := fast; step.Bump(n := 1): the override, SUPER^.Bump(2) + 100
    assert_eq!(column(&trace, "PLC_PRG.viaItf"), [102.0, 106.0, 110.0]);
    // all[i].Bump(n := 1) over plain, fast and gauge: each block's own method
    assert_eq!(column(&trace, "PLC_PRG.plain.bumps"), [1.0, 2.0, 3.0]);
    assert_eq!(column(&trace, "PLC_PRG.fast.bumps"), [4.0, 8.0, 12.0]);
    assert_eq!(column(&trace, "PLC_PRG.gauge.level"), [-1.0, -2.0, -3.0]);
    assert_eq!(column(&trace, "PLC_PRG.sum"), [104.0, 108.0, 112.0]);
    // gauge's own Label (7) and the one fast inherits from FB_Counter (1)
    assert_eq!(column(&trace, "PLC_PRG.label"), [71.0, 71.0, 71.0]);
}

/// The same project written as ST text (`INTERFACE`, `EXTENDS`, `IMPLEMENTS`) gives the same
/// trace: the XML export goes through the same OOP machinery.
#[test]
fn the_export_runs_as_the_same_project_written_in_st() {
    let st = "INTERFACE I_Named
METHOD Label : INT
END_METHOD
END_INTERFACE
INTERFACE I_Step EXTENDS I_Named
METHOD Bump : INT
VAR_INPUT n : INT; END_VAR
END_METHOD
END_INTERFACE
FUNCTION_BLOCK FB_Counter IMPLEMENTS I_Step
VAR count : INT; bumps : INT; END_VAR
count := count + 1;
METHOD Bump : INT
VAR_INPUT n : INT; END_VAR
bumps := bumps + n;
Bump := bumps;
END_METHOD
METHOD Label : INT
Label := 1;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_FastCounter EXTENDS FB_Counter
VAR extra : INT; END_VAR
SUPER^();
extra := extra + 10;
METHOD Bump : INT
VAR_INPUT n : INT; END_VAR
Bump := SUPER^.Bump(n := n * 2) + 100;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_Gauge IMPLEMENTS I_Step, I_Named
VAR level : INT; END_VAR
METHOD Bump : INT
VAR_INPUT n : INT; END_VAR
level := level - n;
Bump := level;
END_METHOD
METHOD Label : INT
Label := 7;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM PLC_PRG
VAR
  plain : FB_Counter; fast : FB_FastCounter; gauge : FB_Gauge;
  step : I_Step; all : ARRAY[1..3] OF I_Step;
  i : INT; viaItf : INT; sum : INT; label : INT;
END_VAR
plain();
fast();
step := fast;
viaItf := step.Bump(n := 1);
all[1] := plain;
all[2] := fast;
all[3] := gauge;
sum := 0;
FOR i := 1 TO 3 DO
    sum := sum + all[i].Bump(n := 1);
END_FOR;
label := gauge.Label() * 10 + fast.Label();
END_PROGRAM
";
    let (from_st, stderr) = run_text("shapes.st", st, 3, WATCH);
    assert!(!stderr.contains("error"), "{stderr}");
    let (from_xml, _) = run_text("shapes.xml", &fixture_text("shapes.xml"), 3, WATCH);
    assert_eq!(from_xml, from_st);
}

/// The sweep's case (`switch.xml`): an interface only in vendor data, used as the type of a
/// block's input (`dev : ISwitchable`); the lamp implements its method and its property (`Count`,
/// a GET accessor), and the holder calls both through the input: no E3009, the lamp toggles.
#[test]
fn an_interface_in_vendor_data_is_a_type_of_the_file_with_methods_and_properties() {
    // an empty `<addData/>` after a method's interface (as CODESYS writes it) ignores nothing:
    // no W3002 (before: one "vendor data ignored" counting each)
    let src = fixture_text("switch.xml").replace("</returnType>", "</returnType><addData/>");
    assert!(src.contains("<addData/>"));
    let (code, lines) = check_text("switch.xml", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(!lines.iter().any(|l| l.contains("W3002")), "{lines:?}");
    assert!(
        !lines
            .iter()
            .any(|l| l.contains("E3009") || l.contains("E0303")),
        "{lines:?}"
    );
    let (trace, stderr) = run_text(
        "switch.xml",
        &fixture_text("switch.xml"),
        3,
        "PLC_PRG.holder.state,PLC_PRG.holder.seen,PLC_PRG.lamp.lit",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "PLC_PRG.holder.state"), [1.0, 0.0, 1.0]);
    assert_eq!(column(&trace, "PLC_PRG.lamp.lit"), [1.0, 0.0, 1.0]);
    assert_eq!(column(&trace, "PLC_PRG.holder.seen"), [1.0, 2.0, 3.0]);
}

/// FB_Gauge without its `Label` method: one E0335 at the `<Implements>` text that reaches
/// I_Named first (I_Step, which extends it), not one per interface naming it.
#[test]
fn a_missing_interface_method_is_one_located_error() {
    let src = fixture_text("shapes.xml");
    let at = src
        .find("<Method name=\"Label\" ObjectId=\"00000000-0000-0000-0000-000000000005\">")
        .unwrap();
    let end = at + src[at..].find("</Method>").unwrap() + "</Method>".len();
    let src = format!("{}{}", &src[..at], &src[end..]);
    let (code, lines) = check_text("nolabel.xml", &src);
    assert_eq!(code, Some(1));
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("nolabel.xml:112:29: error[E0335]: `FB_Gauge` IMPLEMENTS `I_Named` but has no method `Label`"),
        "{errors:?}"
    );
}

/// A block whose body is IL (not ST) declaring IMPLEMENTS in its vendor data: one E0303 at its
/// `<Inheritance>` naming the clause (inheritance is flattened in ST text).
#[test]
fn a_block_that_inherits_with_a_body_not_in_st_is_one_located_e0303() {
    let src = fixture_text("shapes.xml").replacen(
        "<ST>\n            <xhtml xmlns=\"http://www.w3.org/1999/xhtml\" />\n          </ST>",
        "<IL>\n            <xhtml xmlns=\"http://www.w3.org/1999/xhtml\">LD level\nST level</xhtml>\n          </IL>",
        1,
    );
    let (code, lines) = check_text("il.xml", &src);
    assert_eq!(code, Some(1));
    assert!(
        lines.iter().any(|l| l.starts_with(
            "il.xml:111:15: error[E0303]: `FB_Gauge` IMPLEMENTS I_Step IMPLEMENTS I_Named: inheritance is compiled for POUs whose body and actions are ST"
        )),
        "{lines:?}"
    );
}
