use diagnostics::{code, render, Diagnostic, MessageFormat, SourceMap, Span, XmlContext};

fn sample() -> (SourceMap, Vec<Diagnostic>) {
    let mut map = SourceMap::new();
    let f = map.add(
        "prog.il",
        "PROGRAM p\n  LD x\n  JMPC nowhere\nEND_PROGRAM\n",
    );
    let d = Diagnostic::error(code::E9001, "jump to an undefined label `nowhere`")
        .at(Span::new(f, 24, 31))
        .with_primary_label("no label of this name in `p`")
        .with_label(Span::new(f, 12, 16), "current result set here")
        .with_hint("declare the label `nowhere:` or jump to an existing one")
        .with_xml(XmlContext {
            pou: Some("p".into()),
            local_id: Some("7".into()),
            network: None,
        });
    (map, vec![d])
}

#[test]
fn short_rendering_is_one_line_with_position_code_context_and_hint() {
    let (map, diags) = sample();
    insta::assert_snapshot!(render(&map, &diags, MessageFormat::Short));
}

#[test]
fn json_rendering_has_one_based_positions_and_byte_range() {
    let (map, diags) = sample();
    let out = render(&map, &diags, MessageFormat::Json);
    let v: serde_json::Value = serde_json::from_str(out.trim_end()).unwrap();
    assert_eq!(v["line"], 3);
    assert_eq!(v["column"], 8);
    assert_eq!(v["byte_start"], 24);
    assert_eq!(v["labels"][0]["line"], 2);
    assert_eq!(v["local_id"], "7");
    insta::assert_snapshot!(out);
}

#[test]
fn human_rendering_shows_the_excerpt_labels_and_hint() {
    let (map, diags) = sample();
    insta::assert_snapshot!(render(&map, &diags, MessageFormat::Human));
}

#[test]
fn line_col_counts_characters_not_bytes() {
    let mut map = SourceMap::new();
    let f = map.add("u.il", "(* ü *) LD x\nST y");
    let file = map.get(f);
    assert_eq!(file.line_col(9), (1, 9));
    assert_eq!(file.line_col(14), (2, 1));
    assert_eq!(file.offset_of(2, 4), 17);
}

#[test]
fn every_code_has_a_title_and_explanation() {
    assert!(!diagnostics::all_codes().is_empty());
    for c in diagnostics::all_codes() {
        assert!(!c.title.is_empty());
        assert!(c.explanation.starts_with(&format!("# {}: ", c.code)));
        assert!(diagnostics::lookup(&c.code.0.to_lowercase()).is_some());
    }
}

#[test]
fn every_code_explains_how_to_fix_it() {
    for info in diagnostics::all_codes() {
        assert!(
            info.explanation.contains("## How to fix"),
            "{}: no `## How to fix` section",
            info.code
        );
    }
}

#[test]
fn a_diagnostic_without_its_own_hint_points_at_its_explanation_in_every_format() {
    let mut map = SourceMap::new();
    let f = map.add("x.il", "LD a\n");
    let d = Diagnostic::error(code::E1001, "undeclared name `a`").at(Span::new(f, 3, 4));
    for format in [
        MessageFormat::Human,
        MessageFormat::Short,
        MessageFormat::Json,
    ] {
        let text = render(&map, std::slice::from_ref(&d), format);
        assert!(
            text.contains("`ladderc explain E1001` shows causes and fixes"),
            "{format:?}: {text}"
        );
    }
    // A stage's own hint wins.
    let own = d.clone().with_hint("declare `a` in a VAR block");
    let text = render(&map, &[own], MessageFormat::Short);
    assert!(
        text.trim_end()
            .ends_with("(hint: declare `a` in a VAR block)"),
        "{text}"
    );
}

#[test]
fn texts_are_clipped_at_max_text_chars_characters_not_bytes() {
    let n = 1000; // MAX_TEXT_CHARS of diagnostic.rs
                  // at the limit, in ASCII (n bytes) and in 3-byte characters (3n bytes): kept whole
    let ascii = "a".repeat(n);
    let wide = "€".repeat(n);
    let d = Diagnostic::error(code::E9001, ascii.clone()).with_hint(wide.clone());
    assert_eq!(d.message, ascii);
    assert_eq!(d.hint.as_deref(), Some(wide.as_str()));
    // one character more: cut after n characters, with `…`
    let d = Diagnostic::error(code::E9001, "a".repeat(n + 1)).with_note("€".repeat(n + 1));
    assert_eq!(d.message, format!("{ascii}…"));
    assert_eq!(d.notes, vec![format!("{wide}…")]);
}
