//! The bugs users report against LD-to-ST converters, each through a small hand-written TC6 file:
//! parallel coils share one evaluation of the rung, a block runs before anything reads its outputs,
//! chained blocks run in data-flow order. Plus the other LD/FBD elements and their diagnostics.

mod common;

use common::{compile, dump_unit, fixture};

fn lines(text: &str) -> Vec<&str> {
    text.lines().map(str::trim).collect()
}

fn pos(ls: &[&str], line: &str) -> usize {
    ls.iter()
        .position(|l| *l == line)
        .unwrap_or_else(|| panic!("`{line}` not in:\n{}", ls.join("\n")))
}

#[test]
fn parallel_coils_share_one_evaluation_and_contacts_read_where_they_stand() {
    let (unit, diags) = compile("parallel_coils.xml", &fixture("parallel_coils.xml"));
    assert_eq!(diags, "");
    let il = dump_unit(&unit);
    let ls = lines(&il);
    // The rung's logic is evaluated exactly once ...
    assert_eq!(ls.iter().filter(|l| **l == "LD Start").count(), 1, "{il}");
    // ... and both coils store that one current result, one after the other.
    let st_motor = pos(&ls, "ST Motor");
    assert_eq!(ls[st_motor + 1], "ST Lamp", "{il}");
    assert_eq!(ls[st_motor - 1], "ANDN Stop", "{il}");
    // The seal-in contact (before the Motor coil, shared with the branch below) is captured before
    // Motor is written; the branch's own contact on Motor (below the coil) reads what it wrote
    // (round 30: each contact reads its variable where it stands, as Beremiz generates it).
    let capture = pos(&ls, "LD Motor");
    assert!(capture < st_motor, "{il}");
    assert!(ls[capture + 1].starts_with("ST __tmp_BOOL_"), "{il}");
    let was = pos(&ls, "ST WasRunning");
    assert!(was > st_motor, "{il}");
    assert_eq!(ls[was - 1], "AND Motor", "{il}");
    assert_eq!(ls[was - 2], format!("LD {}", &ls[capture + 1][3..]), "{il}");
    insta::assert_snapshot!(il);
}

#[test]
fn a_block_runs_before_its_readers_whatever_the_drawing_order() {
    let (unit, diags) = compile(
        "block_before_readers.xml",
        &fixture("block_before_readers.xml"),
    );
    assert_eq!(diags, "");
    let il = dump_unit(&unit);
    let ls = lines(&il);
    let call = ls
        .iter()
        .position(|l| l.starts_with("CAL T1("))
        .expect("T1 called");
    assert!(call < pos(&ls, "LD T1.Q"), "{il}");
    assert!(call < pos(&ls, "LD T1.ET"), "{il}");
    insta::assert_snapshot!(il);
}

#[test]
fn contacts_naming_a_block_output_read_it_after_the_block() {
    let (unit, diags) = compile("named_outputs.xml", &fixture("named_outputs.xml"));
    assert_eq!(diags, "");
    let il = dump_unit(&unit);
    let ls = lines(&il);
    let t1 = ls.iter().position(|l| l.starts_with("CAL T1(")).unwrap();
    assert!(t1 < pos(&ls, "AND T1.Q"), "{il}");
    assert!(
        pos(&ls, "AND T1.Q") < pos(&ls, "CAL C1(CU := __tmp_BOOL_0)"),
        "{il}"
    );
    // The self-resetting pulse reads P1.Q before calling P1: the previous scan's value.
    let p1 = ls.iter().position(|l| l.starts_with("CAL P1(")).unwrap();
    assert!(pos(&ls, "LDN P1.Q") < p1, "{il}");
    insta::assert_snapshot!(il);
}

#[test]
fn chained_blocks_run_in_data_flow_order() {
    let (unit, diags) = compile("chained_blocks.xml", &fixture("chained_blocks.xml"));
    assert_eq!(diags, "");
    let il = dump_unit(&unit);
    let ls = lines(&il);
    let add = pos(&ls, "ADD B");
    let mul = pos(&ls, "MUL 3");
    let gt = pos(&ls, "GT Limit");
    let ctu = ls.iter().position(|l| l.starts_with("CAL C1(")).unwrap();
    assert!(add < mul && mul < gt && gt < ctu, "{il}");
    insta::assert_snapshot!(il);
}

#[test]
fn edges_storage_connectors_en_eno_jumps_and_returns() {
    let (unit, diags) = compile("features.xml", &fixture("features.xml"));
    assert_eq!(diags, "");
    let il = dump_unit(&unit);
    // Hidden edge detectors are declared with names no IEC identifier can have.
    for v in [
        "__trig_2 : R_TRIG;",
        "__trig_4 : F_TRIG;",
        "__trig_7 : F_TRIG;",
        "__trig_10 : R_TRIG;",
    ] {
        assert!(il.contains(v), "{v} missing in\n{il}");
    }
    let ls = lines(&il);
    assert!(ls.contains(&"S Latch") && ls.contains(&"R Latch") && ls.contains(&"STN NotBtn"));
    assert!(pos(&ls, "JMPC Tail") < pos(&ls, "Tail:"));
    assert!(pos(&ls, "JMPCN __skip_33") < pos(&ls, "__skip_33:"));
    assert_eq!(ls[ls.len() - 2..], ["RET", "END_PROGRAM"]);
    insta::assert_snapshot!(il);
}

#[test]
fn graph_mistakes_are_reported_in_the_engineers_terms() {
    let (_, diags) = compile("errors.xml", &fixture("errors.xml"));
    for code in [
        "W3002", "W3003", "E3005", "E3006", "E3007", "E3008", "E3010", "E3011", "W3005", "E3014",
        "E3015", "E3016", "E3018",
    ] {
        assert!(diags.contains(code), "{code} missing in\n{diags}");
    }
    // undeclared inputs of a generic block are named (before: E3017, no input has a known type)
    assert!(
        diags.contains(
            "error[E1001]: undeclared name `Undeclared1` [POU `main`, network 10, localId 82]"
        ),
        "{diags}"
    );
    assert!(!diags.contains("E3017"), "{diags}");
    insta::assert_snapshot!(diags);
}

#[test]
fn loops_through_a_variable_or_an_instance_read_the_previous_value() {
    // CounterFBD of corpus file 01: ADD -> SEL -> Cnt (in-out variable) -> ADD.
    let Some(xml) = common::corpus("01_beremiz_first_steps.xml") else {
        return;
    };
    let (unit, _) = compile("01.xml", &xml);
    let il = dump_unit(&unit);
    let fbd = il.split("FUNCTION_BLOCK CounterFBD").nth(1).unwrap();
    let fbd = fbd.split("END_FUNCTION_BLOCK").next().unwrap();
    let ls = lines(fbd);
    assert!(pos(&ls, "ADD Cnt") < pos(&ls, "ST Cnt"), "{fbd}");
}

#[test]
fn human_diagnostics_show_the_xml_excerpt_and_the_element() {
    let xml = fixture("errors.xml");
    let mut map = diagnostics::SourceMap::new();
    let file = map.add("errors.xml", xml.as_str());
    let mut diags = diagnostics::Diagnostics::new();
    ladder_compiler::compile_xml(file, &xml, &mut diags);
    let e3005: Vec<_> = diags
        .into_sorted()
        .into_iter()
        .filter(|d| d.code.0 == "E3005")
        .collect();
    insta::assert_snapshot!(diagnostics::render_human(&map, &e3005));
}

#[test]
fn networks_run_by_execution_order_then_top_to_bottom() {
    let (unit, diags) = compile("network_order.xml", &fixture("network_order.xml"));
    assert!(
        diags.contains("W3002") && diags.contains("<vendorElement>"),
        "{diags}"
    );
    assert!(!diags.contains("error"), "{diags}");
    let il = dump_unit(&unit);
    let ls = lines(&il);
    let (first, second, third) = (
        pos(&ls, "ST First"),
        pos(&ls, "ST Second"),
        pos(&ls, "ST Third"),
    );
    assert!(first < second && second < third, "{il}");
}
