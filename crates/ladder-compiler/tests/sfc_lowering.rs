//! SFC bodies lowered to IL: the scan structure (conditions, firing with priorities, evolution, step
//! times, action control, action bodies), reviewed as IL snapshots, and the SFC diagnostics.

mod common;

use common::{compile, dump_unit};

fn sfc_fixture(name: &str) -> String {
    let path = format!(
        "{}/../../tests/tests/fixtures/sfc/{name}",
        env!("CARGO_MANIFEST_DIR")
    );
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn lines(text: &str) -> Vec<&str> {
    text.lines().map(str::trim).collect()
}

/// The lines from the last `from` before the first `to`, up to that `to`.
fn section<'a>(ls: &[&'a str], from: &str, to: &str) -> Vec<&'a str> {
    let end = ls
        .iter()
        .position(|l| *l == to)
        .unwrap_or_else(|| panic!("`{to}` not in:\n{}", ls.join("\n")));
    let start = ls[..end]
        .iter()
        .rposition(|l| *l == from)
        .unwrap_or_else(|| panic!("`{from}` not before `{to}`"));
    ls[start..=end].to_vec()
}

/// A program `P` with the given SFC elements and variables.
fn program(vars: &str, sfc: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <types><dataTypes/><pous>
    <pou name="P" pouType="program">
      <interface><localVars>{vars}</localVars></interface>
      <body><SFC>{sfc}</SFC></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>"#
    )
}

#[test]
fn two_step_chart_lowers_to_the_documented_scan() {
    let xml = program(
        r#"<variable name="go"><type><BOOL/></type></variable><variable name="lamp"><type><BOOL/></type></variable>"#,
        r#"<step localId="1" name="Idle" initialStep="true"/>
        <transition localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
          <condition><inline name=""><IL><xhtml:p>LD go</xhtml:p></IL></inline></condition></transition>
        <step localId="3" name="On"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></step>
        <actionBlock localId="4"><connectionPointIn><connection refLocalId="3"/></connectionPointIn>
          <action localId="0" qualifier="N"><reference name="lamp"/></action></actionBlock>
        <transition localId="5"><connectionPointIn><connection refLocalId="3"/></connectionPointIn>
          <condition><inline name=""><IL><xhtml:p>LDN go</xhtml:p></IL></inline></condition></transition>
        <jumpStep localId="6" targetName="Idle"><connectionPointIn><connection refLocalId="5"/></connectionPointIn></jumpStep>"#,
    );
    let (unit, diags) = compile("two_steps.xml", &xml);
    assert_eq!(diags, "");
    let il = dump_unit(&unit);
    let ls = lines(&il);
    // The initial step starts active, the others inactive.
    assert!(ls.contains(&"__sfc_X_Idle : BOOL := TRUE;"), "{il}");
    assert!(ls.contains(&"__sfc_X_On : BOOL;"), "{il}");
    // Every condition is evaluated before any transition fires, and every firing is decided before
    // any step changes: one evolution per scan.
    let cond = ls.iter().position(|l| *l == "ST __sfc_c5").unwrap();
    let first_fire = ls.iter().position(|l| *l == "ST __sfc_f2").unwrap();
    let first_change = ls.iter().position(|l| *l == "R __sfc_X_Idle").unwrap();
    assert!(
        cond < first_fire && ls.iter().rposition(|l| *l == "ST __sfc_f5").unwrap() < first_change
    );
    // Deactivations before activations.
    assert!(first_change < ls.iter().position(|l| *l == "S __sfc_X_On").unwrap());
    insta::assert_snapshot!(il);
}

#[test]
fn selection_priorities_block_lower_priority_transitions() {
    let (unit, diags) = compile("sequence.xml", &sfc_fixture("sequence.xml"));
    assert_eq!(diags, "");
    let il = dump_unit(&unit);
    let ls = lines(&il);
    // Order at the divergence: 7 (priority="1"), then 5 (x=10), then 6 (x=200).
    let f7 = section(&ls, "LD __sfc_X_Choose", "ST __sfc_f7");
    assert_eq!(f7, ["LD __sfc_X_Choose", "AND __sfc_c7", "ST __sfc_f7"]);
    let f5 = section(&ls, "LD __sfc_X_Choose", "ST __sfc_f5");
    assert_eq!(
        f5,
        [
            "LD __sfc_X_Choose",
            "AND __sfc_c5",
            "ANDN __sfc_f7",
            "ST __sfc_f5"
        ]
    );
    let f6 = section(&ls, "LD __sfc_X_Choose", "ST __sfc_f6");
    assert_eq!(
        f6,
        [
            "LD __sfc_X_Choose",
            "AND __sfc_c6",
            "ANDN __sfc_f7",
            "ANDN __sfc_f5",
            "ST __sfc_f6"
        ]
    );
    // The simultaneous convergence needs both branches.
    let f18 = section(&ls, "LD __sfc_X_P1b", "ST __sfc_f18");
    assert_eq!(
        f18,
        [
            "LD __sfc_X_P1b",
            "AND __sfc_X_P2",
            "AND __sfc_c18",
            "ST __sfc_f18"
        ]
    );
    // The simultaneous divergence activates both branches.
    let s11 = section(&ls, "LD __sfc_f11", "S __sfc_X_P2");
    assert_eq!(s11, ["LD __sfc_f11", "S __sfc_X_P1", "S __sfc_X_P2"]);
    insta::assert_snapshot!(il);
}

#[test]
fn action_control_follows_the_standard_block() {
    let (unit, diags) = compile("actions.xml", &sfc_fixture("actions.xml"));
    assert_eq!(diags, "");
    let il = dump_unit(&unit);
    // Step.T and Action names in bodies are renamed to the hidden variables.
    assert!(il.contains("LD __sfc_T_S1\n"), "{il}");
    assert!(!il.contains("S1.T"), "{il}");
    insta::assert_snapshot!(il);
}

#[test]
fn other_languages_and_chart_names_are_renamed() {
    let (unit, diags) = compile("languages.xml", &sfc_fixture("languages.xml"));
    assert_eq!(diags, "");
    let il = dump_unit(&unit);
    let ls = lines(&il);
    // The contact network wired to transition 2 writes its condition.
    assert_eq!(
        section(&ls, "LD start", "ST __sfc_c2"),
        ["LD start", "ST __sfc_c2"]
    );
    // The FBD named transition writes `Done`, renamed to its hidden condition.
    assert!(ls.contains(&"ST __sfc_n_Done"), "{il}");
    // `Run.Q` in the LD action is the action's Q.
    assert!(ls.contains(&"LD __sfc_Q_Run"), "{il}");
    insta::assert_snapshot!(il);
}

#[test]
fn emitted_il_parses_back() {
    for f in ["sequence.xml", "actions.xml", "languages.xml"] {
        let (unit, diags) = compile(f, &sfc_fixture(f));
        assert_eq!(diags, "");
        let il = dump_unit(&unit);
        let mut map = diagnostics::SourceMap::new();
        let file = map.add("back.il", il.as_str());
        let mut d = diagnostics::Diagnostics::new();
        let _ = il_frontend::parse(file, &il, &mut d);
        assert!(!d.has_errors(), "{f}: {il}");
    }
}

#[test]
fn chart_mistakes_are_reported_in_the_engineers_terms() {
    let (_, diags) = compile("errors.xml", &sfc_fixture("errors.xml"));
    for code in [
        "E3120", "W1464", "E3122", "E3123", "E3124", "E3125", "E3126", "E3127", "E3128", "E3130",
        "E3131",
    ] {
        assert!(diags.contains(code), "{code} missing:\n{diags}");
    }
    insta::assert_snapshot!(diags);
}

/// The text of one POU in the emitted IL.
fn pou_il<'a>(il: &'a str, header: &str) -> &'a str {
    let start = il
        .find(header)
        .unwrap_or_else(|| panic!("`{header}` not in:\n{il}"));
    let end = il[start..]
        .find("\nEND_FUNCTION_BLOCK")
        .map_or(il.len(), |e| start + e);
    &il[start..end]
}

#[test]
fn corpus_02_traffic_light_chart_lowers() {
    let Some(xml) = common::corpus("02_beremiz_svghmi_traffic_light.xml") else {
        return;
    };
    let (unit, diags) = compile("02_beremiz_svghmi_traffic_light.xml", &xml);
    // Only the missing SVGHMI library type remains, and (round 32) W1461 at the three writes of the
    // Boolean action ORANGE_LIGHT in other actions' bodies.
    assert!(
        diags
            .lines()
            .all(|l| l.contains("E3009") || l.contains("W1461")),
        "{diags}"
    );
    assert_eq!(diags.matches("W1461").count(), 3, "{diags}");
    let il = dump_unit(&unit);
    let seq = pou_il(&il, "FUNCTION_BLOCK traffic_light_sequence");
    // The initial step, the D T#2s association on the BOOL variable STOP_CARS, and the named FBD
    // action BLINK_ORANGE_LIGHT executed under its A flag.
    assert!(seq.contains("__sfc_X_Standstill : BOOL := TRUE;"), "{seq}");
    assert!(seq.contains("PT := T#2s)"), "{seq}");
    assert!(seq.contains("ST STOP_CARS"), "{seq}");
    assert!(
        seq.contains("LD __sfc_A_BLINK_ORANGE_LIGHT\n    JMPCN __sfc_skip_BLINK_ORANGE_LIGHT"),
        "{seq}"
    );
    insta::assert_snapshot!(seq);
}

#[test]
fn inline_ld_and_named_il_conditions_write_their_transition() {
    let ld = r#"<LD>
        <leftPowerRail localId="1"/>
        <contact localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>go</variable></contact>
        <contact localId="3" negated="true"><connectionPointIn><connection refLocalId="2"/></connectionPointIn><variable>Run.X</variable></contact>
        <coil localId="4"><connectionPointIn><connection refLocalId="3"/></connectionPointIn><variable>Start</variable></coil>
      </LD>"#;
    let xml = program(
        r#"<variable name="go"><type><BOOL/></type></variable>"#,
        &format!(
            r#"<step localId="1" name="Idle" initialStep="true"/>
        <transition localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
          <condition><inline name="Start">{ld}</inline></condition></transition>
        <step localId="3" name="Run"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></step>
        <transition localId="5"><connectionPointIn><connection refLocalId="3"/></connectionPointIn>
          <condition><reference name="Stop"/></condition></transition>
        <jumpStep localId="6" targetName="Idle"><connectionPointIn><connection refLocalId="5"/></connectionPointIn></jumpStep>"#
        ),
    )
    .replace(
        "<body><SFC>",
        "<transitions><transition name=\"Stop\"><body><IL><xhtml:p>LDN go\nAND Run.X</xhtml:p></IL></body></transition></transitions><body><SFC>",
    );
    let (unit, diags) = compile("inline_ld.xml", &xml);
    assert_eq!(diags, "");
    let il = dump_unit(&unit);
    let ls = lines(&il);
    // The coil named after the inline condition writes the condition; Run.X reads the step flag.
    assert_eq!(
        section(&ls, "LD go", "ST __sfc_c2"),
        ["LD go", "ANDN __sfc_X_Run", "ST __sfc_c2"]
    );
    // The IL named transition leaves its value in the current result.
    assert_eq!(
        section(&ls, "LDN go", "ST __sfc_n_Stop"),
        ["LDN go", "AND __sfc_X_Run", "ST __sfc_n_Stop"]
    );
    insta::assert_snapshot!(il);
}

#[test]
fn durations_may_be_variables_and_indicators_are_accepted() {
    let xml = program(
        r#"<variable name="go"><type><BOOL/></type></variable><variable name="horn"><type><BOOL/></type></variable>
           <variable name="done"><type><BOOL/></type></variable><variable name="tHorn"><type><TIME/></type></variable>"#,
        r#"<step localId="1" name="Idle" initialStep="true"/>
        <actionBlock localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
          <action localId="0" qualifier="L" duration="tHorn" indicator="done"><reference name="horn"/></action></actionBlock>
        <transition localId="3"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
          <condition><reference name="go"/></condition></transition>
        <jumpStep localId="4" targetName="Idle"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></jumpStep>"#,
    );
    let (unit, diags) = compile("durations.xml", &xml);
    assert_eq!(diags, "");
    let il = dump_unit(&unit);
    let ls = lines(&il);
    // A BOOL variable as the condition, the limit timer on the variable duration.
    assert_eq!(
        section(&ls, "LD go", "ST __sfc_c3"),
        ["LD go", "ST __sfc_c3"]
    );
    assert!(
        ls.contains(&"CAL __sfc_L_horn(IN := __sfc_X_Idle, PT := tHorn)"),
        "{il}"
    );
    assert_eq!(
        section(&ls, "LD __sfc_X_Idle", "ST __sfc_Q_horn"),
        ["LD __sfc_X_Idle", "ANDN __sfc_L_horn.Q", "ST __sfc_Q_horn"]
    );
    // The indicator variable is the action's business: the chart does not write it.
    assert!(!ls.contains(&"ST done"), "{il}");
}
