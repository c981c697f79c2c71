//! Loading and validating parameter templates: good files load, bad ones give diagnostics inside the template.

use diagnostics::{render, Diagnostics, MessageFormat, SourceMap};
use param_passing::template::{self, Direction, TypeClass};
use param_passing::tm;

const GOOD: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<blockTemplate name="MC_Demo" funcNum="7">
  <parameters>
    <param name="Axis" abbr="Ax" direction="inout" class="struct" type="AXIS_REF" required="true"/>
    <param name="Execute" abbr="Ex" direction="input" class="bool" type="BOOL" required="true"/>
    <param name="Position" abbr="Pos" direction="input" class="lreal" type="LREAL" required="true"/>
    <param name="BufferMode" abbr="BM" direction="input" class="byte" type="MC_BUFFER_MODE" default="0"/>
    <param name="Done" abbr="Dn" direction="output" class="bool" type="BOOL"/>
    <param name="ErrorID" abbr="EID" direction="output" class="word" type="WORD"/>
  </parameters>
  <local name="tmp" ctype="double"/>
  <body><![CDATA[
    tmp = Pos * 2.0;
    Dn = (uint8_t)(Ex && tmp > 0.0);
  ]]></body>
</blockTemplate>
"#;

fn load(text: &str) -> (SourceMap, Option<template::Template>, Diagnostics) {
    let mut map = SourceMap::new();
    let f = map.add("templates/MC_Demo.xml", text);
    let mut diags = Diagnostics::new();
    let t = template::load(f, text, &mut diags);
    (map, t, diags)
}

fn short(map: &SourceMap, diags: Diagnostics) -> String {
    render(map, &diags.into_sorted(), MessageFormat::Short)
}

#[test]
fn a_good_template_loads_with_its_parameters_in_order() {
    let (_, t, diags) = load(GOOD);
    assert!(diags.is_empty(), "{diags:?}");
    let t = t.unwrap();
    assert_eq!(t.block, "MC_Demo");
    assert_eq!(t.func_num, 7);
    let names: Vec<_> = t
        .params
        .iter()
        .map(|p| (p.abbr.as_str(), p.direction, p.class))
        .collect();
    assert_eq!(
        names,
        vec![
            ("Ax", Direction::InOut, TypeClass::Struct),
            ("Ex", Direction::Input, TypeClass::Bool),
            ("Pos", Direction::Input, TypeClass::Lreal),
            ("BM", Direction::Input, TypeClass::Byte),
            ("Dn", Direction::Output, TypeClass::Bool),
            ("EID", Direction::Output, TypeClass::Word),
        ]
    );
    assert_eq!(t.param("bufferMODE").unwrap().default.as_deref(), Some("0"));
    assert_eq!(t.param("Position").unwrap().c_type(), "double");
    // The body keeps its position: its first byte is the byte after `<![CDATA[`.
    let at = GOOD.find("<![CDATA[").unwrap() + 9;
    assert_eq!(t.body.span.start as usize, at);
    assert!(t.body.verbatim);
    assert_eq!(&GOOD[t.body.span.range()], t.body.text);
}

#[test]
fn tm_slots_are_contiguous_and_sized_by_class() {
    let (_, t, _) = load(GOOD);
    let t = t.unwrap();
    let l = tm::layout(&t, 64).unwrap();
    let slots: Vec<_> = l
        .slots
        .iter()
        .map(|s| (s.param.as_str(), s.offset, s.bytes))
        .collect();
    assert_eq!(
        slots,
        vec![
            ("Axis", 0, 4),
            ("Execute", 4, 1),
            ("Position", 5, 8),
            ("BufferMode", 13, 1),
            ("Done", 14, 1),
            ("ErrorID", 15, 2)
        ]
    );
    assert_eq!(l.total, 17);
    assert_eq!(tm::layout(&t, 16), Err((17, 16)));
}

#[test]
fn malformed_xml_points_at_the_problem() {
    let (map, t, diags) =
        load("<blockTemplate name=\"X\" funcNum=\"1\">\n  <parameters>\n</blockTemplate>\n");
    assert!(t.is_none());
    insta::assert_snapshot!(short(&map, diags));
}

#[test]
fn schema_errors_are_all_reported_inside_the_template() {
    let bad = r#"<blockTemplate name="MC_Bad" funcNum="x">
  <parameters>
    <param name="Execute" direction="input" class="bool" type="BOOL"/>
    <param name="Position" abbr="Pos" direction="in" class="lreal" type="LREAL"/>
    <param name="Velocity" abbr="Vel" direction="input" class="real" type="LREAL"/>
    <param name="Accel" abbr="int" direction="input" class="real" type="REAL"/>
    <param name="Done" abbr="Dn" direction="output" class="bool" type="BOOL"/>
    <param name="done" abbr="Dn2" direction="output" class="bool" type="BOOL"/>
    <param name="Busy" abbr="Dn" direction="output" class="bool" type="BOOL"/>
    <param name="Error" abbr="Er" direction="output" class="bool" type="BOOL" required="true"/>
  </parameters>
</blockTemplate>
"#;
    let (map, t, diags) = load(bad);
    assert!(t.is_none());
    insta::assert_snapshot!(short(&map, diags));
}

#[test]
fn wrong_root_element_is_named() {
    let (map, _, diags) = load("<template name=\"MC_Power\"/>");
    insta::assert_snapshot!(short(&map, diags));
}
