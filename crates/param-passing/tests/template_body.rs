//! Body checks report problems inside the template file, before any C compiler runs.

use diagnostics::{render, Diagnostics, MessageFormat, SourceMap};
use param_passing::cbody::{self, Scope};
use param_passing::template;
use std::collections::BTreeSet;

fn check(body: &str) -> String {
    let text = format!(
        r#"<blockTemplate name="MC_Demo" funcNum="7">
  <parameters>
    <param name="Execute" abbr="Ex" direction="input" class="bool" type="BOOL" required="true"/>
    <param name="Position" abbr="Pos" direction="input" class="lreal" type="LREAL" required="true"/>
    <param name="Done" abbr="Dn" direction="output" class="bool" type="BOOL"/>
  </parameters>
  <local name="cmd" ctype="MC_MoveAbsolute_C"/>
  <body><![CDATA[{body}]]></body>
</blockTemplate>"#
    );
    let mut map = SourceMap::new();
    let f = map.add("templates/MC_Demo.xml", text.clone());
    let mut diags = Diagnostics::new();
    let t = template::load(f, &text, &mut diags).expect("template loads");
    let mut declared: BTreeSet<String> = t.params.iter().map(|p| p.abbr.clone()).collect();
    declared.insert("FuncNum".into());
    declared.extend(t.locals.iter().map(|l| l.name.clone()));
    let runtime: BTreeSet<String> = ["mc_cmd", "mc_submit"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let embedded: BTreeSet<String> = ["MC_Power_1"].iter().map(|s| s.to_string()).collect();
    let scope = Scope {
        declared,
        runtime: &runtime,
        embedded_functions: &embedded,
    };
    let clean = cbody::check(&t.body, &scope, &t.block, &mut diags);
    assert_eq!(clean, diags.is_empty());
    render(&map, &diags.into_sorted(), MessageFormat::Short)
}

#[test]
fn a_body_using_only_declared_names_is_clean() {
    let out = check(
        "\n    cmd.target = Pos; /* comment with Unknown */ // and Other\n    if (Ex) { Dn = (uint8_t)mc_submit(FuncNum, &cmd, \"x(\"); }\n",
    );
    assert_eq!(out, "");
}

#[test]
fn undeclared_names_are_reported_once_each_at_their_first_use() {
    insta::assert_snapshot!(check("\n    Done = Position > 0.0;\n    Done = 1;\n"));
}

#[test]
fn unbalanced_brackets_and_unclosed_literals_point_into_the_template() {
    insta::assert_snapshot!(check(
        "\n    if (Ex) { Dn = 1;\n    mc_submit(FuncNum, &cmd, \"oops);\n"
    ));
}

#[test]
fn paper_a_rules_static_storage_and_calls_of_embedded_functions() {
    insta::assert_snapshot!(check("\n    static int n;\n    MC_Power_1();\n"));
}

#[test]
fn locals_declared_in_the_body_are_known() {
    assert_eq!(check("for (int i = 0; i < 3; i++) { double p = 0.0; uint8_t b = (uint8_t)i; (void)p; (void)b; }"), "");
}

#[test]
fn member_names_after_dot_and_arrow_are_not_free_names() {
    assert_eq!(check("cmd.anything = 1; (&cmd)->other = 2;"), "");
}
