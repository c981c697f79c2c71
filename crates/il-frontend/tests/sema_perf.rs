//! Size: sema is linear in the body length; a generated 50,000-line program analyses cleanly and fast.

use diagnostics::{Diagnostics, FileId};

fn analyse_generated(lines: usize, pous: usize) -> (std::time::Duration, usize, Diagnostics) {
    let src = il_frontend::testgen::generate(lines, pous);
    let mut diags = Diagnostics::new();
    let unit = il_frontend::parse(FileId(0), &src, &mut diags);
    assert!(diags.is_empty());
    let start = std::time::Instant::now();
    let model = il_frontend::sema::analyze(&[unit], &mut diags);
    (start.elapsed(), model.instrs.len(), diags)
}

#[test]
fn generated_50k_line_program_analyses_cleanly_in_linear_time() {
    let (small, n_small, d) = analyse_generated(10_000, 1);
    let warnings: Vec<String> = d
        .iter()
        .map(|x| format!("{}: {}", x.code, x.message))
        .collect();
    // The generator stores every result it computes, declares every name and keeps types consistent.
    assert!(d.iter().all(|x| x.code.0 == "W1001"), "{warnings:#?}");
    let (big, n_big, _) = analyse_generated(50_000, 1);
    assert!(n_big > 4 * n_small, "{n_small} vs {n_big} instructions");
    // Five times the input must not take much more than five times as long (quadratic would be ~25x);
    // generous for a debug build on a shared machine.
    assert!(
        big < small * 15 + std::time::Duration::from_millis(500),
        "10k: {small:?}, 50k: {big:?}"
    );
    assert!(
        big < std::time::Duration::from_secs(20),
        "50k lines took {big:?}"
    );
    eprintln!(
        "sema: 10k lines {small:?}, 50k lines {big:?}, {} diagnostics at 10k",
        d.len()
    );
}
