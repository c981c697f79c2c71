//! ST bodies in PLCopen XML: lowered in place, diagnostics point into the XML file and name the POU.

mod common;

use common::{compile, dump_unit};

fn project(body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Ctl" pouType="program"><interface><localVars>
      <variable name="a"><type><INT/></type></variable>
      <variable name="b"><type><INT/></type></variable>
      <variable name="ok"><type><BOOL/></type></variable>
    </localVars></interface>
    <body><ST><xhtml:p>{body}</xhtml:p></ST></body></pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#
    )
}

#[test]
fn st_body_is_lowered_with_entities_and_cdata() {
    let xml = project(
        "IF a &lt;&gt; b AND a &gt;= 0 THEN ok := a &lt;= 10; END_IF;<![CDATA[ b := a * 2;]]>",
    );
    let (unit, diags) = compile("st.xml", &xml);
    assert_eq!(diags, "");
    insta::assert_snapshot!(dump_unit(&unit));
}

#[test]
fn st_syntax_errors_point_into_the_xml_and_name_the_pou() {
    let xml = project("a := ;\nb := 2 &lt;&gt; ;\nok := TRUE;");
    let (unit, diags) = compile("st.xml", &xml);
    insta::assert_snapshot!(diags);
    assert!(diags.contains("[POU `Ctl`]"), "{diags}");
    // The good statement is still lowered.
    assert!(dump_unit(&unit).contains("ST ok"));
    // Line 12 of the XML is the `<body>` line: the column points at `;` after `a :=`.
    let line = xml.lines().position(|l| l.contains("a := ;")).unwrap() + 1;
    assert!(diags.contains(&format!("st.xml:{line}:")), "{diags}");
}
