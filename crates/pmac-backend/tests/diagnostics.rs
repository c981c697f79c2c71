//! The backend's errors as users see them (human rendering of the diagnostics, no source file involved).

mod common;

use common::{cs, paper_b};
use diagnostics::{render_human, Diagnostic, SourceMap};
use pmac_backend::{program, Dialect, PmacError};

fn human(errs: Vec<PmacError>) -> String {
    let diags: Vec<Diagnostic> = errs.into_iter().map(Diagnostic::from).collect();
    render_human(&SourceMap::default(), &diags)
}

#[test]
fn backend_errors_render() {
    let mut bad_move = paper_b();
    bad_move[1].target.truncate(2);
    let mut bad_cs = cs(&['X', 'Y', 'Z']);
    bad_cs.axes[2].name = 'Q';
    let errs = vec![
        program::write(&cs(&['X', 'Y', 'Z']), &bad_move, Dialect::Turbo).unwrap_err(),
        program::write(&bad_cs, &paper_b(), Dialect::Turbo).unwrap_err(),
        PmacError::controller("stdin:12:1: error #21: ILLEGAL CMD\r"),
    ];
    insta::assert_snapshot!("backend_errors_human", human(errs));
}
