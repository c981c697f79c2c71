//! Generated TC6 0201 projects for benchmarks and scale tests.
//!
//! Input: a rung count. Output: the XML text of one program `main` whose LD body has that many rungs,
//! cycling through four rung shapes: series/parallel contacts driving two parallel coils, a TON timer
//! with its output coil, a GT compare block driving a coil, and an LT compare block with a negated
//! contact. Invariants: every localId is unique, every wire resolves, variables are declared.

use std::fmt::Write as _;

/// A valid TC6 0201 project with `rungs` rungs (contacts, coils, TON timers, GT/LT blocks).
pub fn generate(rungs: usize) -> String {
    let mut vars = String::new();
    let mut body = String::new();
    let mut id = 0usize;
    let mut next = || {
        id += 1;
        id
    };
    for r in 0..rungs {
        let y = r * 100;
        let _ = writeln!(
            vars,
            "            <variable name=\"a{r}\"><type><BOOL/></type></variable>\n            <variable name=\"b{r}\"><type><BOOL/></type></variable>\n            <variable name=\"q{r}\"><type><BOOL/></type></variable>"
        );
        let rail = next();
        let _ = writeln!(
            body,
            "          <leftPowerRail localId=\"{rail}\" height=\"40\" width=\"3\"><position x=\"10\" y=\"{y}\"/><connectionPointOut formalParameter=\"\"><relPosition x=\"3\" y=\"20\"/></connectionPointOut></leftPowerRail>"
        );
        match r % 4 {
            0 => {
                let (c1, c3, c2, k1, k2, rr) = (next(), next(), next(), next(), next(), next());
                let _ = writeln!(
                    vars,
                    "            <variable name=\"p{r}\"><type><BOOL/></type></variable>"
                );
                let _ = write!(
                    body,
                    "          {}\n          {}\n          {}\n          {}\n          {}\n          {}\n",
                    contact(c1, 40, y, &[rail], &format!("a{r}"), false),
                    contact(c3, 40, y + 30, &[rail], &format!("p{r}"), false),
                    contact(c2, 80, y, &[c1, c3], &format!("b{r}"), true),
                    coil(k1, 120, y, c2, &format!("q{r}")),
                    coil(k2, 120, y + 30, c2, &format!("p{r}")),
                    right_rail(rr, 160, y, &[k1, k2]),
                );
            }
            1 => {
                let (c1, iv, tm, k1, rr) = (next(), next(), next(), next(), next());
                let _ = writeln!(vars, "            <variable name=\"t{r}\"><type><derived name=\"TON\"/></type></variable>");
                let _ = write!(
                    body,
                    "          {}\n          <inVariable localId=\"{iv}\" height=\"30\" width=\"40\"><position x=\"40\" y=\"{}\"/><connectionPointOut><relPosition x=\"40\" y=\"15\"/></connectionPointOut><expression>T#{}ms</expression></inVariable>\n          {}\n          {}\n          {}\n",
                    contact(c1, 40, y, &[rail], &format!("a{r}"), false),
                    y + 40,
                    100 + r % 900,
                    block(tm, "TON", Some(&format!("t{r}")), 80, y, &[("IN", c1, None), ("PT", iv, None)], &["Q", "ET"]),
                    coil_pin(k1, 140, y, tm, "Q", &format!("q{r}")),
                    right_rail(rr, 180, y, &[k1]),
                );
            }
            2 | 3 => {
                let op = if r % 4 == 2 { "GT" } else { "LT" };
                let (iv1, iv2, cmp, c1, k1, rr) = (next(), next(), next(), next(), next(), next());
                let _ = writeln!(
                    vars,
                    "            <variable name=\"n{r}\"><type><INT/></type></variable>"
                );
                let _ = write!(
                    body,
                    "          <inVariable localId=\"{iv1}\" height=\"30\" width=\"40\"><position x=\"20\" y=\"{}\"/><connectionPointOut><relPosition x=\"40\" y=\"15\"/></connectionPointOut><expression>n{r}</expression></inVariable>\n          <inVariable localId=\"{iv2}\" height=\"30\" width=\"40\"><position x=\"20\" y=\"{}\"/><connectionPointOut><relPosition x=\"40\" y=\"15\"/></connectionPointOut><expression>{}</expression></inVariable>\n          {}\n          {}\n          {}\n          {}\n",
                    y + 10,
                    y + 40,
                    r % 100,
                    block(cmp, op, None, 70, y, &[("IN1", iv1, None), ("IN2", iv2, None)], &["OUT"]),
                    contact_from_pin(c1, 110, y, cmp, "OUT", &format!("a{r}"), r % 4 == 3),
                    coil(k1, 150, y, c1, &format!("q{r}")),
                    right_rail(rr, 190, y, &[k1]),
                );
            }
            _ => unreachable!(),
        }
    }
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="ladderc" productName="testgen" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="generated"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types>
    <dataTypes/>
    <pous>
      <pou name="main" pouType="program">
        <interface>
          <localVars>
{vars}          </localVars>
        </interface>
        <body>
          <LD>
{body}          </LD>
        </body>
      </pou>
    </pous>
  </types>
  <instances>
    <configurations>
      <configuration name="config">
        <resource name="res">
          <task name="cyclic" priority="1" interval="T#10ms">
            <pouInstance name="main_instance" typeName="main"/>
          </task>
        </resource>
      </configuration>
    </configurations>
  </instances>
</project>
"#
    )
}

fn conns(from: &[usize]) -> String {
    from.iter()
        .map(|f| format!("<connection refLocalId=\"{f}\"/>"))
        .collect()
}

fn contact(id: usize, x: usize, y: usize, from: &[usize], var: &str, negated: bool) -> String {
    format!(
        "<contact localId=\"{id}\" height=\"15\" width=\"21\" negated=\"{negated}\"><position x=\"{x}\" y=\"{y}\"/><connectionPointIn><relPosition x=\"0\" y=\"8\"/>{}</connectionPointIn><connectionPointOut><relPosition x=\"21\" y=\"8\"/></connectionPointOut><variable>{var}</variable></contact>",
        conns(from)
    )
}

fn contact_from_pin(
    id: usize,
    x: usize,
    y: usize,
    from: usize,
    pin: &str,
    var: &str,
    negated: bool,
) -> String {
    format!(
        "<contact localId=\"{id}\" height=\"15\" width=\"21\" negated=\"{negated}\"><position x=\"{x}\" y=\"{y}\"/><connectionPointIn><relPosition x=\"0\" y=\"8\"/><connection refLocalId=\"{from}\" formalParameter=\"{pin}\"/></connectionPointIn><connectionPointOut><relPosition x=\"21\" y=\"8\"/></connectionPointOut><variable>{var}</variable></contact>"
    )
}

fn coil(id: usize, x: usize, y: usize, from: usize, var: &str) -> String {
    format!(
        "<coil localId=\"{id}\" height=\"15\" width=\"21\" negated=\"false\"><position x=\"{x}\" y=\"{y}\"/><connectionPointIn><relPosition x=\"0\" y=\"8\"/><connection refLocalId=\"{from}\"/></connectionPointIn><connectionPointOut><relPosition x=\"21\" y=\"8\"/></connectionPointOut><variable>{var}</variable></coil>"
    )
}

fn coil_pin(id: usize, x: usize, y: usize, from: usize, pin: &str, var: &str) -> String {
    format!(
        "<coil localId=\"{id}\" height=\"15\" width=\"21\" negated=\"false\"><position x=\"{x}\" y=\"{y}\"/><connectionPointIn><relPosition x=\"0\" y=\"8\"/><connection refLocalId=\"{from}\" formalParameter=\"{pin}\"/></connectionPointIn><connectionPointOut><relPosition x=\"21\" y=\"8\"/></connectionPointOut><variable>{var}</variable></coil>"
    )
}

fn right_rail(id: usize, x: usize, y: usize, from: &[usize]) -> String {
    let pins: String = from
        .iter()
        .map(|f| format!("<connectionPointIn><relPosition x=\"0\" y=\"20\"/><connection refLocalId=\"{f}\"/></connectionPointIn>"))
        .collect();
    format!("<rightPowerRail localId=\"{id}\" height=\"40\" width=\"3\"><position x=\"{x}\" y=\"{y}\"/>{pins}</rightPowerRail>")
}

fn block(
    id: usize,
    ty: &str,
    instance: Option<&str>,
    x: usize,
    y: usize,
    inputs: &[(&str, usize, Option<&str>)],
    outputs: &[&str],
) -> String {
    let inst = instance
        .map(|i| format!(" instanceName=\"{i}\""))
        .unwrap_or_default();
    let ins: String = inputs
        .iter()
        .map(|(p, from, pin)| {
            let fp = pin.map(|q| format!(" formalParameter=\"{q}\"")).unwrap_or_default();
            format!("<variable formalParameter=\"{p}\"><connectionPointIn><relPosition x=\"0\" y=\"20\"/><connection refLocalId=\"{from}\"{fp}/></connectionPointIn></variable>")
        })
        .collect();
    let outs: String = outputs
        .iter()
        .map(|p| format!("<variable formalParameter=\"{p}\"><connectionPointOut><relPosition x=\"60\" y=\"20\"/></connectionPointOut></variable>"))
        .collect();
    format!("<block localId=\"{id}\" typeName=\"{ty}\"{inst} height=\"60\" width=\"60\"><position x=\"{x}\" y=\"{y}\"/><inputVariables>{ins}</inputVariables><inOutVariables/><outputVariables>{outs}</outputVariables></block>")
}
