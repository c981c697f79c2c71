//! Size: a generated 200,000-line POU parses quickly and completely (no size limits, linear time);
//! the 1,000,000-line variant runs in release builds only.
mod common;

use il_frontend::ast::{IlStmt, InstrKind, LibraryElement};

fn count(body: &[IlStmt]) -> usize {
    body.iter()
        .map(|s| match s {
            IlStmt::Instr(i) => match &i.kind {
                InstrKind::Deferred { body, .. } => 1 + count(body),
                _ => 1,
            },
            IlStmt::Label(_) => 1,
        })
        .sum()
}

fn parse_generated(lines: usize) -> std::time::Duration {
    let src = il_frontend::testgen::generate(lines, 1);
    let start = std::time::Instant::now();
    let p = common::parse("big.il", &src);
    let took = start.elapsed();
    assert_eq!(p.short(), "");
    let LibraryElement::Pou(pou) = &p.unit.items[0] else {
        panic!("expected a POU")
    };
    // Every body line is one statement, except the lines `)` and the argument lines of a multi-line CAL.
    let stmts = count(&pou.body);
    assert!(
        stmts > lines / 2 && stmts <= lines,
        "{stmts} statements for {lines} lines"
    );
    took
}

#[test]
fn generated_200k_line_pou_parses() {
    let took = parse_generated(200_000);
    // Generous bound for a debug build on a shared 2-core machine (a release build takes ~0.1 s).
    assert!(took.as_secs() < 60, "took {took:?}");
}

#[test]
#[cfg_attr(debug_assertions, ignore)]
fn generated_million_line_pou_parses() {
    let took = parse_generated(1_000_000);
    eprintln!("1,000,000 lines parsed in {took:?}");
    assert!(took.as_secs() < 30, "took {took:?}");
}

#[test]
fn generated_programs_round_trip() {
    let src = il_frontend::testgen::generate(300, 3);
    let p = common::parse("gen.il", &src);
    assert_eq!(p.short(), "");
    assert_eq!(p.unit.items.len(), 3);
    common::assert_round_trip("gen.il", &src);
}

#[test]
fn deeply_nested_deferred_operators_parse_and_print() {
    let depth = 2_000;
    let mut src = String::from("PROGRAM deep\n    LD a\n");
    for _ in 0..depth {
        src.push_str("    AND( a\n");
    }
    for _ in 0..depth {
        src.push_str("    )\n");
    }
    src.push_str("    ST a\nEND_PROGRAM\n");
    let p = common::parse("deep.il", &src);
    assert_eq!(p.short(), "");
    let printed = il_frontend::print::unit(&p.unit);
    assert_eq!(printed.matches("AND(").count(), depth);
}
