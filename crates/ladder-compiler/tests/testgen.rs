//! The generated benchmark project: valid TC6, and 10,000 rungs lower without a diagnostic.
//! (Timing lives in `benches/xml_to_il.rs`, not here.)

mod common;

use ladder_compiler::ast::{IlStmt, InstrKind, LibraryElement, Op, Operand};

fn coil_writes(unit: &ladder_compiler::ast::CompilationUnit) -> usize {
    let LibraryElement::Pou(main) = &unit.items[0] else {
        panic!("first item is the program")
    };
    main.body
        .iter()
        .filter(|s| {
            matches!(s, IlStmt::Instr(i) if matches!(&i.kind,
                InstrKind::Simple { op: Op::St, operand: Some(Operand::Var(v)), .. }
                    if v.base.name.starts_with('q')))
        })
        .count()
}

#[test]
fn small_generated_project_lowers_every_rung_shape() {
    let xml = ladder_compiler::testgen::generate(4);
    let (unit, diags) = common::compile("gen4.xml", &xml);
    assert_eq!(diags, "");
    assert_eq!(coil_writes(&unit), 4);
    insta::assert_snapshot!(common::dump_unit(&unit));
}

fn lower_generated(rungs: usize) {
    let xml = ladder_compiler::testgen::generate(rungs);
    let (unit, diags) = common::compile("gen.xml", &xml);
    assert_eq!(diags, "");
    assert_eq!(coil_writes(&unit), rungs);
    let LibraryElement::Pou(main) = &unit.items[0] else {
        panic!()
    };
    // Temporaries are reused from rung to rung: the hidden block stays small.
    let hidden = main.var_blocks.last().unwrap();
    assert!(
        hidden
            .vars
            .iter()
            .filter(|v| v.name.name.starts_with("__tmp"))
            .count()
            <= 4
    );
}

/// The benchmark's size. Unoptimised builds take several seconds for it (the XML alone is 22 MB), so
/// it runs with `cargo test --release`; the 1,000-rung variant below always runs.
#[test]
#[cfg_attr(debug_assertions, ignore)]
fn ten_thousand_rungs_lower_without_diagnostics() {
    lower_generated(10_000);
}

#[test]
fn a_thousand_rungs_lower_without_diagnostics() {
    lower_generated(1_000);
}
