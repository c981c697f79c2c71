//! "No size limits" (issue #2): one POU far beyond the 64 KiB body limit of the classic open-source IL
//! compiler goes through parse + sema + C generation.
//!
//! Input: a 200,000-line single-POU program from `il_frontend::testgen` (about 2.3 MB of IL, one body).
//! Output: the C project; the test checks that there is no error and that every jump and label of the
//! source is in the C body, one for one. Timing and memory are measured by `benches/il_to_c.rs` (up to
//! 1,000,000 lines), not here: this test runs in debug builds in CI.

use c_backend::{Options, TargetProfile};
use diagnostics::{Diagnostics, FileId};

const LINES: usize = 200_000;

#[test]
fn a_200_000_line_pou_compiles_to_c_with_every_label_and_jump() {
    let src = il_frontend::testgen::generate(LINES, 1);
    assert!(src.len() > 64 * 1024 * 30, "far beyond a 64 KiB body");
    let jumps_in = src.matches("JMPC L").count();
    let labels_in = src.lines().filter(|l| is_label_line(l)).count();
    let cals_in = src.matches("CAL t").count();
    assert!(
        jumps_in > 5_000 && cals_in > 5_000,
        "the generator mixes jumps and calls"
    );
    assert_eq!(jumps_in, labels_in);

    let mut diags = Diagnostics::new();
    let units = [il_frontend::parse(FileId(0), &src, &mut diags)];
    let model = il_frontend::sema::analyze(&units, &mut diags);
    let program = c_backend::generate(
        &units,
        &model,
        &TargetProfile::default(),
        &Options::default(),
        &mut diags,
    );
    let errors: Vec<String> = diags
        .iter()
        .filter(|d| d.severity == diagnostics::Severity::Error)
        .take(3)
        .map(|d| format!("{d:?}"))
        .collect();
    assert!(errors.is_empty(), "errors: {errors:#?}");
    let program = program.expect("C is generated");
    let c = program.file("program.c").expect("program.c");

    // Each source label `Lk:` is one C label `L_lk:;`, each `JMPC Lk` one `goto L_lk;`.
    let labels_out = c
        .lines()
        .filter(|l| l.starts_with("L_l") && l.ends_with(":;"))
        .count();
    let gotos_out = c.matches("goto L_l").count();
    assert_eq!(labels_out, labels_in);
    assert_eq!(gotos_out, jumps_in);
    let last = labels_in - 1;
    assert!(c.contains(&format!("goto L_l{last};")));
    assert!(c.contains(&format!("\nL_l{last}:;")));
    // The whole body is one C function.
    assert_eq!(c.matches("void P_p0_BODY(P_p0 *self) {").count(), 1);
}

fn is_label_line(l: &str) -> bool {
    l.strip_suffix(':')
        .and_then(|n| n.strip_prefix('L'))
        .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
}
