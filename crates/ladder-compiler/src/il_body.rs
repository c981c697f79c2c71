//! IL bodies embedded in the XML: the text of `<IL>` (inside `<xhtml:p>`, `<xhtml>`, CDATA, or bare),
//! rebuilt so that byte `k` of the text is byte `base + k` of the XML file, then parsed by
//! `il_frontend::parse_body`.
//!
//! Input: the `<IL>` element. Output: the body text and its base offset ([`EmbeddedText`]).
//! Invariants: the text is padded so positions map back exactly: the bytes between segments (such as
//! `]]>` / `<![CDATA[` markers) become spaces, and an entity such as `&lt;` becomes its character
//! followed by spaces up to the entity's length. Inside a string literal an entity is not padded (the
//! padding would change the string): positions after it on that line are then a few bytes early.

use crate::xml::{Element, SegKind};

/// An `<IL>` body's text laid out so that byte `k` of `text` is byte `base + k` of the XML file.
#[derive(Debug, Clone)]
pub struct EmbeddedText {
    /// The body text, padded (see the module header).
    pub text: String,
    /// Byte offset in the XML file of the text's first byte.
    pub base: usize,
}

/// The element that holds the body's text: the first one (the `<IL>` itself or a descendant) with
/// non-blank character data.
fn holder<'e, 'a>(e: &'e Element<'a>) -> Option<&'e Element<'a>> {
    if e.segments().iter().any(|s| !s.text.trim().is_empty()) {
        return Some(e);
    }
    e.children.iter().find_map(holder)
}

/// The text of the `<IL>` element `e` (empty when it holds no text).
pub fn embedded_text(e: &Element) -> EmbeddedText {
    let Some(h) = holder(e) else {
        return EmbeddedText {
            text: String::new(),
            base: e.tag_end(),
        };
    };
    let base = h.segments().first().map(|s| s.start).unwrap_or(h.tag_end());
    let mut text = String::new();
    let mut in_string: Option<char> = None;
    for seg in h.segments() {
        let want = seg.start - base;
        while text.len() < want {
            text.push(' ');
        }
        match seg.kind {
            SegKind::Text | SegKind::CData => {
                for c in seg.text.chars() {
                    match (in_string, c) {
                        (None, '\'' | '"') => in_string = Some(c),
                        (Some(q), c) if c == q => in_string = None,
                        _ => {}
                    }
                    text.push(c);
                }
            }
            SegKind::Entity => {
                text.push_str(seg.text);
                if in_string.is_none() {
                    while text.len() < seg.end - base {
                        text.push(' ');
                    }
                }
            }
        }
    }
    EmbeddedText { text, base }
}

/// Parses the IL body in place (spans point into the XML file); the parser's diagnostics name the POU.
/// A keyword declared as one of the POU's variables (`on`, `task`) reads as that name in the body: its
/// declaration gets the one E1031.
pub fn parse(
    ctx: &mut crate::context::Ctx,
    e: &Element,
    pou: &il_frontend::ast::Pou,
) -> Vec<il_frontend::ast::IlStmt> {
    let t = embedded_text(e);
    let mut local = diagnostics::Diagnostics::new();
    let declared: Vec<&str> = pou
        .var_blocks
        .iter()
        .flat_map(|b| b.vars.iter())
        .map(|v| v.name.name.as_str())
        .filter(|n| il_frontend::sema::reserved_name(n).is_some())
        .collect();
    let pou = pou.name.name.as_str();
    let body = il_frontend::parse_body_declared(ctx.file, &t.text, t.base, &mut local, &declared);
    for d in local {
        let d = if d.xml.is_none() {
            d.with_xml(diagnostics::XmlContext {
                pou: Some(pou.to_string()),
                ..Default::default()
            })
        } else {
            d
        };
        ctx.report(d);
    }
    body
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_positions_match_the_xml() {
        let xml = "<IL><p>LD a\nGT b &amp;&lt; <![CDATA[ST c]]></p></IL>";
        let arena = crate::xml::Arena::new();
        let (root, _) = crate::xml::parse(xml, &arena);
        let t = embedded_text(&root.unwrap());
        for word in ["LD a", "GT b", "ST c"] {
            let k = t.text.find(word).unwrap();
            assert_eq!(&xml[t.base + k..t.base + k + word.len()], word);
        }
        let k = t.text.find('<').unwrap();
        assert_eq!(&xml[t.base + k..t.base + k + 4], "&lt;");
    }
}
