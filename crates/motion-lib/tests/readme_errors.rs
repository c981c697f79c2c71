//! The README's ErrorID table lists every ErrorId with its value.

use motion_lib::error::ErrorId;

#[test]
fn readme_lists_every_error_id() {
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    for e in ErrorId::ALL {
        let row = format!("| {} | `{:?}` |", e.code(), e);
        assert!(readme.contains(&row), "README lacks the row {row}");
        assert_eq!(ErrorId::from_code(e.code()), *e);
    }
}
