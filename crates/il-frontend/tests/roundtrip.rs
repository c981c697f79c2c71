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

/// `print::body` output parses back through `parse_body` to an equal instruction list.
#[test]
fn body_printing_round_trips_through_parse_body() {
    let p = common::parse("rich.il", include_str!("samples/rich.il"));
    let mut checked = 0;
    for item in &p.unit.items {
        let il_frontend::ast::LibraryElement::Pou(pou) = item else {
            continue;
        };
        let text = il_frontend::print::body(&pou.body);
        let mut diags = diagnostics::Diagnostics::new();
        let again = il_frontend::parse_body(diagnostics::FileId(0), &text, 0, &mut diags);
        assert!(diags.is_empty(), "{diags:?}\n{text}");
        assert_eq!(common::shape(&pou.body), common::shape(&again), "{text}");
        assert_eq!(il_frontend::print::body(&again), text);
        checked += 1;
    }
    assert_eq!(checked, 3);
}
