//! IL in and out: IL bodies embedded in the XML are parsed with positions in the XML file, and the
//! emitted IL of every lowered project parses back to the same tree (spans aside).

mod common;

use common::{compile, corpus, fixture};
use diagnostics::{Diagnostics, FileId};
use ladder_compiler::ast::{IlStmt, LibraryElement};

#[test]
fn embedded_il_spans_point_into_the_xml() {
    let xml = fixture("il_bodies.xml");
    let (unit, diags) = compile("il_bodies.xml", &xml);
    // The broken body's syntax error points into the XML and names its POU.
    assert_eq!(diags.lines().count(), 1, "{diags}");
    assert!(
        diags.starts_with("il_bodies.xml:30:") && diags.contains("[POU `Broken`]"),
        "{diags}"
    );
    let pous: Vec<_> = unit
        .items
        .iter()
        .filter_map(|i| match i {
            LibraryElement::Pou(p) => Some(p),
            _ => None,
        })
        .collect();
    assert_eq!(pous.len(), 4);
    for (p, expected) in pous.iter().zip([
        ["LD a", "GT 5", "ST c"],
        ["LD a", "LT 5", "ST c"],
        ["LD a", "EQ 7", "ST c"],
    ]) {
        let texts: Vec<&str> = p
            .body
            .iter()
            .map(|s| match s {
                IlStmt::Instr(i) => xml[i.span.range()].trim(),
                IlStmt::Label(l) => &xml[l.span.range()],
            })
            .collect();
        assert_eq!(texts, expected, "POU {}", p.name.name);
    }
}

#[test]
fn corpus_il_body_lines_map_to_the_xml() {
    let Some(xml) = corpus("01_beremiz_first_steps.xml") else {
        return;
    };
    let (unit, _) = compile("01.xml", &xml);
    let il = unit
        .items
        .iter()
        .find_map(|i| match i {
            LibraryElement::Pou(p) if p.name.name == "CounterIL" => Some(p),
            _ => None,
        })
        .unwrap();
    let jump = il
        .body
        .iter()
        .find_map(|s| match s {
            IlStmt::Instr(i) if xml[i.span.range()].starts_with("JMPC") => Some(i),
            _ => None,
        })
        .expect("JMPC found at its XML position");
    assert_eq!(xml[jump.span.range()].trim(), "JMPC ResetCnt");
}

/// The tree as JSON with every span removed.
fn shape(unit: &ladder_compiler::ast::CompilationUnit) -> serde_json::Value {
    fn strip(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Object(m) => {
                let is_span = m.len() == 3
                    && m.contains_key("file")
                    && m.contains_key("start")
                    && m.contains_key("end");
                if is_span {
                    *v = serde_json::Value::Null;
                } else {
                    m.values_mut().for_each(strip);
                }
            }
            serde_json::Value::Array(a) => a.iter_mut().for_each(strip),
            _ => {}
        }
    }
    let mut v = serde_json::to_value(unit).unwrap();
    strip(&mut v);
    v
}

fn first_difference(a: &serde_json::Value, b: &serde_json::Value, path: String) -> Option<String> {
    use serde_json::Value::*;
    match (a, b) {
        (Object(x), Object(y)) => {
            for (k, v) in x {
                match y.get(k) {
                    Some(w) => {
                        if let Some(d) = first_difference(v, w, format!("{path}.{k}")) {
                            return Some(d);
                        }
                    }
                    None => return Some(format!("{path}.{k} (only after re-parsing)")),
                }
            }
            (x.len() != y.len()).then(|| format!("{path}: keys differ"))
        }
        (Array(x), Array(y)) => {
            for (i, (v, w)) in x.iter().zip(y).enumerate() {
                if let Some(d) = first_difference(v, w, format!("{path}[{i}]")) {
                    return Some(d);
                }
            }
            (x.len() != y.len()).then(|| format!("{path}: {} vs {} elements", x.len(), y.len()))
        }
        _ => (a != b).then(|| format!("{path}: re-parsed {a} vs lowered {b}")),
    }
}

fn round_trip(name: &str, xml: &str) {
    let (unit, _) = compile(name, xml);
    let text = ladder_compiler::emit_il(&unit);
    let mut diags = Diagnostics::new();
    let back = il_frontend::parse(FileId(1), &text, &mut diags);
    assert!(
        !diags.has_errors(),
        "{name}: emitted IL does not parse: {diags:?}\n{text}"
    );
    let (a, b) = (shape(&back), shape(&unit));
    if let Some(d) = first_difference(&a, &b, String::new()) {
        panic!("{name}: re-parsed tree differs at {d}\n{text}");
    }
}

#[test]
fn emitted_il_parses_back_to_the_same_tree() {
    for f in [
        "parallel_coils.xml",
        "block_before_readers.xml",
        "chained_blocks.xml",
        "features.xml",
        "v1_bom_types.xml",
        "il_bodies.xml",
    ] {
        round_trip(f, &fixture(f));
    }
    for f in [
        "01_beremiz_first_steps.xml",
        "02_beremiz_svghmi_traffic_light.xml",
        "04_beremiz_ethercat_wago_higen_MC.xml",
        "05_beremiz_ethercat_wago_sanyo_MC.xml",
        "08_openplc_samples_OpenSWat.xml",
        "09_openplc_samples_vc999v3.xml",
        "10_openplc_samples_esp8266celsius.xml",
        "11_openplc_samples_PT_Motor_PID_Wave_fbd.xml",
        "14_matiec_LD_TEST_tc6v1.xml",
        "15_matiec_STD_TEST_tc6v1_fbd.xml",
        "24_feecat_S7RTT_codesys_st_motion.xml",
    ] {
        if let Some(xml) = corpus(f) {
            round_trip(f, &xml);
        }
    }
    round_trip("gen.xml", &ladder_compiler::testgen::generate(8));
}
