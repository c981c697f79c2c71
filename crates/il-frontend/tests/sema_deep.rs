//! Deeply nested deferred lists (`AND( ... )` inside each other) do not overflow the stack: the checker
//! walks nested lists with an explicit stack (at the parser's limit, `parser::MAX_NESTING` levels).

mod sema_support;
use sema_support::analyze_src;

#[test]
fn three_thousand_nested_deferred_operators() {
    let depth = il_frontend::parser::MAX_NESTING;
    let mut src = String::from("PROGRAM P\nVAR\n  a, b : BOOL;\n  n : INT;\nEND_VAR\n  LD a\n");
    for _ in 0..depth {
        src.push_str("  AND( b\n");
    }
    for _ in 0..depth {
        src.push_str("  )\n");
    }
    src.push_str("  ST a\n  LD n\n  ADD( n\n  AND b\n  )\n  ST n\nEND_PROGRAM\n");
    let (m, d) = analyze_src(&src);
    // Only the innermost type error of the last expression; the deep nesting is fine.
    assert_eq!(d.matches("error[").count(), 1, "{d}");
    assert!(d.contains("E1005"), "{d}");
    let p = &m.pous[0];
    assert_eq!(p.instrs.len(), depth + 6);
    // Pre-order: the outermost `AND(` is the second instruction and reads the BOOL from `LD a`.
    let outer = m.instr_by_id(p.instrs[1]).unwrap();
    assert_eq!(outer.cr_before, Some(il_frontend::sema::Type::BOOL));
    assert_eq!(outer.cr_after, Some(il_frontend::sema::Type::BOOL));
}
