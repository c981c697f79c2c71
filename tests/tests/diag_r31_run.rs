//! Round 31 (issue #13), diagnostics found on real IL / PLCopen XML projects: one located error per
//! cause. A FUNCTION without a result type whose body assigns its name is one E0354 saying the
//! result type is missing (before: two or three back-end E2005 in IL words on an ST body); a second
//! function block box without an instance name, fed by a first one, gets its own E3016 in the same
//! run (before: shown only after the first was fixed); a ladder rung drawn in text is one E1091 at
//! the drawing's first line (before: one E0001 per `|`, `+` and `-`).

mod common;

use common::{check_text, run_text};

/// A PLCopen project whose function `Inv` has no `<returnType>` (an exporter dropped it) while its
/// ST body assigns `Inv` in both branches.
const INV_WITHOUT_RETURN_TYPE: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Inv" pouType="function">
      <interface>
        <inputVars><variable name="v"><type><INT/></type></variable></inputVars>
      </interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">IF v = 0 THEN
  Inv := 1;
ELSE
  Inv := 0 - v;
END_IF;</xhtml></ST></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#;

/// IEC 61131-3 ed. 3 6.6.2.2 and Beckhoff's "Object Function" page: a function's result is the
/// variable named after it, of the type declared after its name; without `<returnType>` the
/// function returns nothing (as TwinCAT compiles `FUNCTION F`), so `Inv := ...` has no variable.
/// Before: 3 back-end E2005 ("current result of unknown type" twice, "cannot resolve `Inv`");
/// now one E0354 at the first assignment, naming the missing result type.
#[test]
fn function_without_return_type_assigning_its_name_is_one_error() {
    let (code, lines) = check_text("inv.xml", INV_WITHOUT_RETURN_TYPE);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("inv.xml:11:3: error[E0354]"),
        "{lines:?}"
    );
    assert!(errors[0].contains("without a result type"), "{lines:?}");
    assert!(errors[0].contains("<returnType>"), "{lines:?}");
    assert!(!lines.iter().any(|l| l.contains("E2005")), "{lines:?}");
}

/// The same in ST text (`FUNCTION Inv` without `: INT`), called as a statement: one E0354, not the
/// back end's E2005.
#[test]
fn st_function_without_result_type_assigning_its_name_is_one_error() {
    let src = "FUNCTION Inv\nVAR_INPUT v : INT; END_VAR\nIF v = 0 THEN\n  Inv := 1;\nELSE\n  Inv := 0 - v;\nEND_IF;\nEND_FUNCTION\n\nPROGRAM Main\nVAR x : INT; END_VAR\nInv(v := x);\nEND_PROGRAM\n";
    let (code, lines) = check_text("inv.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("inv.st:4:3: error[E0354]"),
        "{lines:?}"
    );
    assert!(errors[0].contains("FUNCTION Inv : INT"), "{lines:?}");
}

/// With the result type declared the same body compiles and runs: `Inv(0)` is 1, `Inv(5)` is -5.
#[test]
fn the_same_function_with_its_result_type_runs() {
    let src = "FUNCTION Inv : INT\nVAR_INPUT v : INT; END_VAR\nIF v = 0 THEN\n  Inv := 1;\nELSE\n  Inv := 0 - v;\nEND_IF;\nEND_FUNCTION\n\nPROGRAM Main\nVAR x : INT; y : INT; END_VAR\ny := Inv(v := x);\nx := x + 5;\nEND_PROGRAM\n";
    let (trace, _) = run_text("inv.st", src, 3, "Main.y");
    let y = common::column(&trace, "Main.y");
    assert_eq!(y, vec![1.0, -5.0, -10.0], "{trace}");
}

/// An FBD body with two function block boxes without `instanceName`, the second (SR) fed by the
/// first's (TON) output. Each box's missing instance is a cause of its own. Before: only the TON's
/// E3016, the SR's after the TON was fixed; now both in one run, each at its own `<block>`.
#[test]
fn each_box_without_instance_name_is_reported_in_one_run() {
    let src = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Latch" pouType="program">
      <interface><localVars>
        <variable name="start"><type><BOOL/></type></variable>
        <variable name="q"><type><BOOL/></type></variable>
      </localVars></interface>
      <body><FBD>
        <inVariable localId="1"><connectionPointOut/><expression>start</expression></inVariable>
        <inVariable localId="2"><connectionPointOut/><expression>T#2s</expression></inVariable>
        <block localId="3" typeName="TON"><inputVariables>
          <variable formalParameter="IN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
          <variable formalParameter="PT"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
        </inputVariables><inOutVariables/><outputVariables>
          <variable formalParameter="Q"><connectionPointOut/></variable>
        </outputVariables></block>
        <inVariable localId="4"><connectionPointOut/><expression>FALSE</expression></inVariable>
        <block localId="5" typeName="SR"><inputVariables>
          <variable formalParameter="S1"><connectionPointIn><connection refLocalId="3" formalParameter="Q"/></connectionPointIn></variable>
          <variable formalParameter="R"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></variable>
        </inputVariables><inOutVariables/><outputVariables><variable formalParameter="Q1"><connectionPointOut/></variable></outputVariables></block>
        <outVariable localId="6"><connectionPointIn><connection refLocalId="5" formalParameter="Q1"/></connectionPointIn><expression>q</expression></outVariable>
      </FBD></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#;
    let (code, lines) = check_text("latch.xml", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 2, "{lines:?}");
    assert!(
        errors[0].starts_with("latch.xml:14:9: error[E3016]")
            && errors[0].contains("TON has no instance name"),
        "{lines:?}"
    );
    assert!(
        errors[1].starts_with("latch.xml:21:9: error[E3016]")
            && errors[1].contains("SR has no instance name"),
        "{lines:?}"
    );
}

/// A rung drawn in text (the semigraphic form IEC 61131-3 uses for its LD figures, ed. 3 8.2),
/// under a comment that itself holds dashes. Before: W0302 "read as IL", then 19 E0001 "unexpected
/// character", most with the hint "IL has no infix operators"; now one E1091 at the drawing's first
/// line, saying it is a ladder diagram drawn in text.
#[test]
fn a_rung_drawn_in_text_is_one_error_at_its_first_line() {
    let src = "(* --- start/stop rung --- *)\n\n| %IX0    %QX0\n+--[ ]--+--( )--\n| %IX1  |\n+--[ ]--+\n|\n";
    for name in ["rung.txt", "rung.il", "rung.st"] {
        let (code, lines) = check_text(name, src);
        assert_eq!(code, Some(1), "{name}: {lines:?}");
        let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
        assert_eq!(errors.len(), 1, "{name}: {lines:?}");
        assert!(
            errors[0].starts_with(&format!("{name}:3:1: error[E1091]")),
            "{name}: {lines:?}"
        );
        assert!(
            errors[0].contains("ladder diagram drawn in text"),
            "{lines:?}"
        );
    }
}

/// IL whose comment holds a drawn rung, and whose code has a real slip (`LD a b`), keeps its own
/// error: the drawing in a comment is no reason for E1091.
#[test]
fn a_rung_drawn_in_a_comment_changes_nothing() {
    let src = "(* | a    q\n   +--[ ]--( )-- *)\nPROGRAM P\nVAR a : BOOL; q : BOOL; END_VAR\nLD a\nST q\nEND_PROGRAM\n";
    let (trace, _) = run_text("p.il", src, 1, "P.q");
    assert_eq!(common::column(&trace, "P.q"), vec![0.0], "{trace}");
    let (code, lines) = check_text("bad.il", &src.replace("LD a\n", "LD a a\n"));
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(!lines.iter().any(|l| l.contains("E1091")), "{lines:?}");
}

/// A program whose first FBD network has a TON box without `instanceName` (fed by undeclared `a`)
/// and whose second network reads undeclared `c`, next to a second program whose ST body reads
/// undeclared `z`. The box's E3016 and the undeclared names are separate causes at separate
/// places. Before: the E3016 alone (the checks did not run once reading the file had errors), the
/// E1001 on the next run after the box was fixed; now the E3016 and one E1001 for `c` and one for
/// `z` in one run, and nothing for the box's own wires (its `Q` feeds `q`: no follow-on error).
#[test]
fn names_undeclared_elsewhere_are_reported_with_a_box_without_instance_name() {
    let src = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Pump" pouType="program">
      <interface><localVars>
        <variable name="q"><type><BOOL/></type></variable>
        <variable name="r"><type><BOOL/></type></variable>
      </localVars></interface>
      <body><FBD>
        <inVariable localId="1"><connectionPointOut/><expression>a</expression></inVariable>
        <inVariable localId="2"><connectionPointOut/><expression>T#1s</expression></inVariable>
        <block localId="3" typeName="TON"><inputVariables>
          <variable formalParameter="IN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
          <variable formalParameter="PT"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
        </inputVariables><inOutVariables/><outputVariables>
          <variable formalParameter="Q"><connectionPointOut/></variable>
        </outputVariables></block>
        <outVariable localId="4"><connectionPointIn><connection refLocalId="3" formalParameter="Q"/></connectionPointIn><expression>q</expression></outVariable>
        <inVariable localId="7"><connectionPointOut/><expression>c</expression></inVariable>
        <outVariable localId="8"><connectionPointIn><connection refLocalId="7"/></connectionPointIn><expression>r</expression></outVariable>
      </FBD></body>
    </pou>
    <pou name="Valve" pouType="program">
      <interface><localVars>
        <variable name="open"><type><BOOL/></type></variable>
      </localVars></interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">open := z;</xhtml></ST></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#;
    let (code, lines) = check_text("pump.xml", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 3, "{lines:?}");
    assert!(
        errors
            .iter()
            .any(|e| e.starts_with("pump.xml:14:9: error[E3016]")
                && e.contains("TON has no instance name")),
        "{lines:?}"
    );
    assert!(
        errors
            .iter()
            .any(|e| e.starts_with("pump.xml:21:66: error[E1001]") && e.contains("`c`")),
        "{lines:?}"
    );
    assert!(
        errors.iter().any(|e| e.starts_with("pump.xml:29:69:")
            && e.contains("error[E1001]")
            && e.contains("`z`")),
        "{lines:?}"
    );
}

/// A TON box whose `instanceName` `T1` the POU does not declare, and another network reading
/// `T1.Q`: the missing declaration is one cause, one E3016 at the instance name; the read of
/// `T1.Q` gets no E1001 of its own (the checks now run after an E3016, this test keeps them from
/// repeating it), while undeclared `c` elsewhere is still reported.
#[test]
fn a_read_of_an_undeclared_box_instance_is_no_second_error() {
    let src = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Pump" pouType="program">
      <interface><localVars>
        <variable name="go"><type><BOOL/></type></variable>
        <variable name="q"><type><BOOL/></type></variable>
        <variable name="r"><type><BOOL/></type></variable>
      </localVars></interface>
      <body><FBD>
        <inVariable localId="1"><connectionPointOut/><expression>go</expression></inVariable>
        <inVariable localId="2"><connectionPointOut/><expression>T#1s</expression></inVariable>
        <block localId="3" typeName="TON" instanceName="T1"><inputVariables>
          <variable formalParameter="IN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
          <variable formalParameter="PT"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
        </inputVariables><inOutVariables/><outputVariables>
          <variable formalParameter="Q"><connectionPointOut/></variable>
        </outputVariables></block>
        <inVariable localId="5"><connectionPointOut/><expression>T1.Q</expression></inVariable>
        <outVariable localId="6"><connectionPointIn><connection refLocalId="5"/></connectionPointIn><expression>q</expression></outVariable>
        <inVariable localId="7"><connectionPointOut/><expression>c</expression></inVariable>
        <outVariable localId="8"><connectionPointIn><connection refLocalId="7"/></connectionPointIn><expression>r</expression></outVariable>
      </FBD></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#;
    let (code, lines) = check_text("t1.xml", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 2, "{lines:?}");
    assert!(
        errors.iter().any(|e| e.starts_with("t1.xml:15:")
            && e.contains("error[E3016]")
            && e.contains("instance `T1` of TON is not declared")),
        "{lines:?}"
    );
    assert!(
        errors.iter().any(|e| e.starts_with("t1.xml:23:")
            && e.contains("error[E1001]")
            && e.contains("`c`")),
        "{lines:?}"
    );
    assert!(
        !lines
            .iter()
            .any(|l| l.contains("`T1`") && l.contains("E1001")),
        "{lines:?}"
    );
}

/// An AND box fed by undeclared `a` and by undeclared `b` through a negated input
/// (`negated="true"`), `a` read again in a second network, and a second program reading
/// undeclared `z`. Each undeclared name is one E1001 per POU: `a` and `b` at the box's inputs,
/// `z` in the other program, and no second E1001 for `a` in the second network. Before: `a`
/// alone (`b` under its NOT was not looked at, and the checks did not run after the box's error,
/// so `z` came on the next run).
#[test]
fn undeclared_box_inputs_and_names_elsewhere_come_in_one_run_once_each() {
    let src = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Safety" pouType="program">
      <interface><localVars>
        <variable name="ok"><type><BOOL/></type></variable>
        <variable name="r"><type><BOOL/></type></variable>
      </localVars></interface>
      <body><FBD>
        <inVariable localId="10"><connectionPointOut/><expression>a</expression></inVariable>
        <inVariable localId="11"><connectionPointOut/><expression>b</expression></inVariable>
        <block localId="1" typeName="AND"><inputVariables>
          <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="10"/></connectionPointIn></variable>
          <variable formalParameter="IN2" negated="true"><connectionPointIn><connection refLocalId="11"/></connectionPointIn></variable>
        </inputVariables><inOutVariables/><outputVariables>
          <variable formalParameter="OUT"><connectionPointOut/></variable>
        </outputVariables></block>
        <outVariable localId="12"><connectionPointIn><connection refLocalId="1" formalParameter="OUT"/></connectionPointIn><expression>ok</expression></outVariable>
        <inVariable localId="20"><connectionPointOut/><expression>a</expression></inVariable>
        <outVariable localId="21"><connectionPointIn><connection refLocalId="20"/></connectionPointIn><expression>r</expression></outVariable>
      </FBD></body>
    </pou>
    <pou name="Valve" pouType="program">
      <interface><localVars>
        <variable name="open"><type><BOOL/></type></variable>
      </localVars></interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">open := z;</xhtml></ST></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#;
    let (code, lines) = check_text("safety.xml", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 3, "{lines:?}");
    for (at, name) in [
        ("safety.xml:12:", "`a`"),
        ("safety.xml:13:", "`b`"),
        ("safety.xml:29:", "`z`"),
    ] {
        assert!(
            errors
                .iter()
                .any(|e| e.starts_with(at) && e.contains("error[E1001]") && e.contains(name)),
            "{at} {name}: {lines:?}"
        );
    }
}
