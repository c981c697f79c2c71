//! A method of a derived block (`EXTENDS`) whose declarations bound arrays by a constant of another
//! file's global list (issue #13; Struckig's tests: `ARRAY[0..ParameterList.MaxDoFs]` in methods
//! of TcUnit test suites, 17 E0022 in Struckig_unittest before). A derived block's method
//! diagnostics wait until its base is found (no cascade after E0330), and so did E0022, so the file
//! was not read again with the other files' constants known.

mod common;
use common::{column, run_traced_files};

use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/derived_bounds")
        .join(name)
}

#[test]
fn a_derived_blocks_method_bounds_by_another_files_constant() {
    let (suite, base, params) = (
        fixture("Suite.st"),
        fixture("Base.st"),
        fixture("Params.st"),
    );
    let (trace, stderr) =
        run_traced_files(&[&suite, &base, &params], 2, "main.s.upper,main.s.checks");
    // [0..Params.MaxDoFs] twice: 7 + 7; the inherited method runs once a scan
    assert_eq!(column(&trace, "main.s.upper"), [14.0, 14.0]);
    assert_eq!(column(&trace, "main.s.checks"), [1.0, 2.0]);
    assert!(!stderr.contains("error["), "{stderr}");
}
