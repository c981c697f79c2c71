//! The IL files of the corpus: each parses (with precise, named diagnostics for the non-standard
//! constructs it uses), the short diagnostics and a structural summary are snapshotted (not the source:
//! the GPL files stay outside the repository), and the printed tree parses back to an equal tree.
//! Files 18 and 19 are bundled (MIT); the others are read from `$LADDERC_CORPUS` (skipped when unset).
mod common;

use il_frontend::ast::*;
use std::fmt::Write as _;

fn count_instructions(
    body: &[IlStmt],
    labels: &mut usize,
    kinds: &mut std::collections::BTreeMap<String, usize>,
) -> usize {
    let mut n = 0;
    for s in body {
        match s {
            IlStmt::Label(_) => *labels += 1,
            IlStmt::Instr(i) => {
                n += 1;
                let kind = match &i.kind {
                    InstrKind::Simple { op, negate, .. } => {
                        format!("{op:?}{}", if *negate { "N" } else { "" })
                    }
                    InstrKind::Deferred { op, body, .. } => {
                        n += count_instructions(body, labels, kinds);
                        format!("{op:?}(")
                    }
                    InstrKind::Jump { cond, .. } => format!("Jump{cond:?}"),
                    InstrKind::Return { cond } => format!("Return{cond:?}"),
                    InstrKind::Call { .. } => "Call".into(),
                    InstrKind::FunctionCall { name, .. } => format!("Function {}", name.name),
                    InstrKind::FbInput { op, .. } => format!("{op:?}"),
                    InstrKind::EmbeddedC { .. } => "EmbeddedC".into(),
                };
                *kinds.entry(kind).or_default() += 1;
            }
        }
    }
    n
}

fn summary(unit: &CompilationUnit) -> String {
    let mut out = String::new();
    for item in &unit.items {
        match item {
            LibraryElement::Pou(p) => {
                let vars: usize = p.var_blocks.iter().map(|b| b.vars.len()).sum();
                let mut labels = 0;
                let mut kinds = Default::default();
                let n = count_instructions(&p.body, &mut labels, &mut kinds);
                let _ = writeln!(
                    out,
                    "{:?} {}: {} var blocks, {vars} variables, {n} instructions, {labels} labels",
                    p.kind,
                    p.name.name,
                    p.var_blocks.len()
                );
                let kinds: Vec<String> = kinds.iter().map(|(k, v)| format!("{k} x{v}")).collect();
                let _ = writeln!(out, "    {}", kinds.join(", "));
            }
            other => {
                let _ = writeln!(
                    out,
                    "{}",
                    serde_json::to_value(other)
                        .unwrap()
                        .as_object()
                        .unwrap()
                        .keys()
                        .next()
                        .unwrap()
                );
            }
        }
    }
    out
}

fn check(file_name: &str) -> Option<String> {
    let src = test_corpus::read(&format!("il/{file_name}"))?;
    let parsed = common::parse(file_name, &src);
    assert!(
        !parsed.unit.items.is_empty(),
        "{file_name} gave an empty tree"
    );
    common::assert_round_trip(file_name, &src);
    Some(format!(
        "{}----- tree\n{}",
        parsed.short(),
        summary(&parsed.unit)
    ))
}

#[test]
fn corpus_has_the_nine_il_files() {
    let files = common::corpus_il();
    if test_corpus::dir().is_some() {
        assert_eq!(files.len(), 9, "{files:?}");
    } else {
        assert_eq!(
            files.len(),
            4,
            "the bundled files 18, 19, 25 and 26: {files:?}"
        );
        test_corpus::skip("il/17_*, il/20_*");
    }
}

#[test]
fn annex_f_cmd_monitor() {
    if let Some(s) = check("17_matiec_AnnexF_cmd_monitor_il.st") {
        insta::assert_snapshot!(s);
    }
}

#[test]
fn annex_f_fwd_rev_mon() {
    if let Some(s) = check("17_matiec_AnnexF_fwd_rev_mon_il.st") {
        insta::assert_snapshot!(s);
    }
}

#[test]
fn annex_f_stack_int() {
    if let Some(s) = check("17_matiec_AnnexF_stack_int_il.st") {
        insta::assert_snapshot!(s);
    }
}

#[test]
fn annex_f_weigh() {
    if let Some(s) = check("17_matiec_AnnexF_weigh_il.st") {
        insta::assert_snapshot!(s);
    }
}

#[test]
fn il_parser_test1_nested_deferred() {
    if let Some(s) = check("18_il_parser_test1.il") {
        insta::assert_snapshot!(s);
    }
}

#[test]
fn il_parser_test2_dialect() {
    if let Some(s) = check("19_il_parser_test2.il") {
        insta::assert_snapshot!(s);
    }
}

#[test]
fn echidna_blink() {
    if let Some(s) = check("25_echidna_blink.il") {
        insta::assert_snapshot!(s);
    }
}

#[test]
fn echidna_ctu_multi_line_formal_call() {
    if let Some(s) = check("26_echidna_ctu.il") {
        insta::assert_snapshot!(s);
    }
}

#[test]
fn strucpp_state_display() {
    if let Some(s) = check("20_strucpp_state-display.il") {
        insta::assert_snapshot!(s);
    }
}
