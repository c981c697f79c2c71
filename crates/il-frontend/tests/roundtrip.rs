//! Print -> parse round trips: the printed IL parses back to an equal tree and printing is a fixed point.
mod common;

#[test]
fn rich_sample_parses_cleanly_and_round_trips() {
    let src = include_str!("samples/rich.il");
    let p = common::parse("rich.il", src);
    assert_eq!(p.short(), "");
    let printed = common::assert_round_trip("rich.il", src);
    insta::assert_snapshot!(printed);
}
