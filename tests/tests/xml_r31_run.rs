//! Round 31 (PLCopen XML, found in real projects never seen before), through `ladderc check` and
//! `ladderc run`:
//! - W3400 ("written by network N and again by network M; the later one wins every scan") is for a
//!   double coil whose first write is never seen. A network that reads the variable before writing
//!   it (`X := X * 2` after `X := X + 1`), or a network between the two writers that reads it, makes
//!   the first write count: no W3400. Before, a working sequencer of three networks
//!   `Sequence := SEL(..., Sequence, next)` (crebosh/OpenPLC-LD-Core-Concepts) was told its first
//!   networks had no effect.
//! - A file that is not well-formed XML is one E3001: an ST body cut at an unescaped `<` gives no
//!   errors of its own (XML 1.0, 1.2: after a fatal error the document's content is not passed on).
//!   Before, two follow-on ST errors (E0100, E0105) came first (Project-AGRAFE's generated model).

mod common;
use common::{check_text, column, run_text};

/// One FBD network: `dst := OP(src, k)` as an input variable, a constant, a block and an output
/// variable, with local ids from `id` and laid out at row `row`.
fn network(id: u32, row: i64, src: &str, op: &str, k: &str, dst: &str) -> String {
    let y = row * 100;
    format!(
        r#"<inVariable localId="{a}"><position x="10" y="{y}"/><connectionPointOut/><expression>{src}</expression></inVariable>
<inVariable localId="{b}"><position x="10" y="{y2}"/><connectionPointOut/><expression>{k}</expression></inVariable>
<block localId="{c}" typeName="{op}"><position x="100" y="{y}"/>
  <inputVariables>
    <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="{a}"/></connectionPointIn></variable>
    <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="{b}"/></connectionPointIn></variable>
  </inputVariables><inOutVariables/>
  <outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
</block>
<outVariable localId="{d}"><position x="200" y="{y}"/><connectionPointIn><connection refLocalId="{c}" formalParameter="OUT"/></connectionPointIn><expression>{dst}</expression></outVariable>
"#,
        a = id,
        b = id + 1,
        c = id + 2,
        d = id + 3,
        y2 = y + 30,
    )
}

/// A project of one program `P` (INT variables `X`, `Y`, `A`, `B`) whose FBD body is `networks`.
fn project(networks: &[String]) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="P" pouType="program">
      <interface><localVars>
        <variable name="X"><type><INT/></type></variable>
        <variable name="Y"><type><INT/></type></variable>
        <variable name="A"><type><INT/></type><initialValue><simpleValue value="3"/></initialValue></variable>
        <variable name="B"><type><INT/></type><initialValue><simpleValue value="5"/></initialValue></variable>
      </localVars></interface>
      <body><FBD>
{}      </FBD></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="C"><resource name="R"><task name="T" priority="0" interval="T#10ms"><pouInstance name="inst" typeName="P"/></task></resource></configuration></configurations></instances>
</project>
"#,
        networks.concat()
    )
}

/// The W3400 lines of a check.
fn w3400(name: &str, src: &str) -> Vec<String> {
    let (code, lines) = check_text(name, src);
    assert_eq!(code, Some(0), "{lines:?}");
    lines.into_iter().filter(|l| l.contains("W3400")).collect()
}

/// `X := X + 1` in network 1, `X := X * 2` in network 2: network 2 works on network 1's result
/// (X = 2, 6, 14, 30 over four scans: (0 + 1) * 2, (2 + 1) * 2, ...), so W3400 does not say that
/// network 1 has no effect. Before: W3400 at network 2's output variable.
#[test]
fn a_chain_that_reads_the_earlier_networks_result_is_no_double_write() {
    let src = project(&[
        network(1, 0, "X", "ADD", "1", "X"),
        network(11, 1, "X", "MUL", "2", "X"),
    ]);
    assert_eq!(w3400("chain.xml", &src), Vec::<String>::new());
    let (trace, stderr) = run_text("chain.xml", &src, 4, "inst.X");
    assert!(!stderr.contains("W3400"), "{stderr}");
    assert_eq!(column(&trace, "inst.X"), vec![2.0, 6.0, 14.0, 30.0]);
}

/// Two networks that write X from other variables only, neither reading X: the first write is
/// never seen (X = B + 1 = 6 every scan, not A + 1 = 4), and W3400 says so at the second one, naming
/// network 1. With a network between them that reads X into Y, the first write is seen (Y = 4) and
/// nothing is said. The rule starts again from the later writer: a fourth network writing X again,
/// with no read after the third, is W3400 naming network 3.
#[test]
fn a_double_write_is_reported_unless_a_network_between_reads_it() {
    let plain = project(&[
        network(1, 0, "A", "ADD", "1", "X"),
        network(11, 1, "B", "ADD", "1", "X"),
    ]);
    let warned = w3400("double.xml", &plain);
    assert_eq!(warned.len(), 1, "{warned:?}");
    assert!(
        warned[0].contains("`X` is written by network 1 (localId 4) and again by network 2"),
        "{warned:?}"
    );
    let (trace, _) = run_text("double.xml", &plain, 2, "inst.X");
    assert_eq!(column(&trace, "inst.X"), vec![6.0, 6.0]);

    let read_between = project(&[
        network(1, 0, "A", "ADD", "1", "X"),
        network(11, 1, "X", "ADD", "0", "Y"),
        network(21, 2, "B", "ADD", "1", "X"),
    ]);
    assert_eq!(w3400("between.xml", &read_between), Vec::<String>::new());
    let (trace, _) = run_text("between.xml", &read_between, 2, "inst.X,inst.Y");
    assert_eq!(column(&trace, "inst.Y"), vec![4.0, 4.0]);
    assert_eq!(column(&trace, "inst.X"), vec![6.0, 6.0]);

    let again = project(&[
        network(1, 0, "A", "ADD", "1", "X"),
        network(11, 1, "X", "ADD", "0", "Y"),
        network(21, 2, "B", "ADD", "1", "X"),
        network(31, 3, "A", "SUB", "1", "X"),
    ]);
    let warned = w3400("again.xml", &again);
    assert_eq!(warned.len(), 1, "{warned:?}");
    assert!(
        warned[0].contains("`X` is written by network 3 (localId 24) and again by network 4"),
        "{warned:?}"
    );
}

/// A variable whose name starts with the written one's (`XA` for `X`) is no read of it: W3400 stays.
#[test]
fn a_longer_name_is_no_read_of_the_variable() {
    let src = project(&[
        network(1, 0, "A", "ADD", "1", "X"),
        network(11, 1, "B", "ADD", "1", "Y"),
        network(21, 2, "Y", "ADD", "1", "X"),
    ])
    .replace(
        "<variable name=\"Y\">",
        "<variable name=\"XA\"><type><INT/></type></variable><variable name=\"Y\">",
    );
    // network 2 reads `B` and writes `Y`; network 3 reads `Y`: X itself is read nowhere
    let warned = w3400("names.xml", &src);
    assert_eq!(warned.len(), 1, "{warned:?}");
    let with_xa = src.replace("<expression>B</expression>", "<expression>XA</expression>");
    assert_eq!(w3400("names2.xml", &with_xa).len(), 1);
}

/// An ST body with an unescaped `<` (`WHILE (i)<(n) DO`, as a generator wrote it) makes the file
/// not well-formed: one E3001 where the XML reader stops, and nothing from the ST text cut there.
/// Before: E0100 "expected `)`" and E0105 "IF is not closed" first, then E3001.
#[test]
fn an_unescaped_less_than_in_st_is_one_xml_error() {
    let src = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="P" pouType="program">
      <interface><localVars>
        <variable name="en"><type><BOOL/></type></variable>
        <variable name="i"><type><INT/></type></variable>
      </localVars></interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">IF en THEN
  WHILE (i)<(n) DO
    i := i + 1;
  END_WHILE;
END_IF;</xhtml></ST></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#;
    let (code, lines) = check_text("cut.xml", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(lines[0].starts_with("cut.xml:12:"), "{lines:?}");
    assert!(
        lines[0].contains("error[E3001]: the XML file is not well-formed"),
        "{lines:?}"
    );
}
