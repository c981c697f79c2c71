//! Input of hostile depth or length, on a thread with a 2 MB stack (the default test thread size):
//! long operator chains in ST type and lower in linear time without recursion, and their trees drop
//! without recursion; IL lists nested 100,000 deep are cut at the documented limit (E0200) and the
//! rest of the pipeline (sema, printing, dropping) never sees more.

mod st_common;

use diagnostics::{Diagnostics, SourceMap};

const STACK: usize = 2 << 20;

fn on_small_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new()
        .stack_size(STACK)
        .spawn(f)
        .unwrap()
        .join()
        .expect("no panic, no stack overflow")
}

const DECLS: &str = "PROGRAM p\nVAR a : INT; r : REAL; b : BOOL; END_VAR\nEND_PROGRAM\n";

/// Lowers `a := a + a + ... (n terms)` and returns the number of ADD instructions and diagnostics.
fn chain(n: usize, op: &str, var: &str) -> (usize, String) {
    let body = format!("{var} := {};", vec![var; n].join(op));
    let (il, diags) = st_common::compile(DECLS, "p", &body);
    (il.lines().filter(|l| !l.trim().is_empty()).count(), diags)
}

#[test]
fn a_chain_of_100000_additions_lowers_to_flat_il() {
    let (lines, diags) = on_small_stack(|| chain(100_000, " + ", "a"));
    // well typed, but longer than one expression may be (1,000 operations, for the C compiler's sake):
    // one E0109, and the chain is still read and lowered in full
    assert_eq!(diags.lines().count(), 1, "{diags}");
    assert!(diags.contains("error[E0109]"), "{diags}");
    // LD a, 99,999 x ADD a, ST a, plus the POU's frame
    assert!(lines > 100_000 && lines < 100_020, "{lines} lines of IL");
}

#[test]
fn chains_of_every_left_associative_operator_survive_a_small_stack() {
    for (op, var) in [
        (" - ", "a"),
        (" * ", "a"),
        (" AND ", "b"),
        (" OR ", "b"),
        (" ** ", "r"),
    ] {
        let (lines, diags) = on_small_stack(move || chain(20_000, op, var));
        assert!(lines > 20_000, "{op}: {lines} lines, {diags}");
        assert!(!diags.contains("panicked"), "{diags}");
    }
}

#[test]
fn typing_a_chain_is_linear_in_its_length() {
    // The work is counted in lowered instructions per term, not timed: 4x the terms, 4x the IL; the
    // quadratic typing took 2.6 s at 5,000 terms, this does 80,000 in the same test.
    let (small, _) = on_small_stack(|| chain(20_000, " + ", "a"));
    let (large, _) = on_small_stack(|| chain(80_000, " + ", "a"));
    assert!(large < 4 * small + 50, "{small} -> {large}");
}

fn nested_il(levels: usize) -> String {
    let mut s = String::from("PROGRAM p\nVAR a : INT; END_VAR\nLD a\n");
    for _ in 0..levels {
        s.push_str("ADD( a\n");
    }
    for _ in 0..levels {
        s.push_str(")\n");
    }
    s.push_str("ST a\nEND_PROGRAM\n");
    s
}

fn check_il(src: String) -> (Vec<String>, String) {
    let mut sm = SourceMap::new();
    let file = sm.add("deep.il", src.clone());
    let mut diags = Diagnostics::new();
    let unit = il_frontend::parse(file, &src, &mut diags);
    let _ = il_frontend::sema::analyze(std::slice::from_ref(&unit), &mut diags);
    let printed = il_frontend::print::unit(&unit);
    let codes = diags
        .into_sorted()
        .iter()
        .map(|d| d.code.0.to_string())
        .collect();
    (codes, printed)
}

#[test]
fn il_lists_nested_100000_deep_are_cut_at_the_limit_with_e0200() {
    let (codes, printed) = on_small_stack(|| check_il(nested_il(100_000)));
    assert_eq!(codes, ["E0200"], "one located diagnostic");
    let deepest = printed
        .lines()
        .filter(|l| l.trim_start().starts_with("ADD("))
        .count();
    // levels 1..=MAX keep their lists; the list at MAX + 1 is emptied (its instruction stays)
    assert_eq!(deepest, il_frontend::parser::MAX_NESTING + 1);
}

#[test]
fn il_lists_at_the_limit_are_accepted() {
    let (codes, _) = on_small_stack(|| check_il(nested_il(il_frontend::parser::MAX_NESTING)));
    assert!(codes.is_empty(), "{codes:?}");
}
