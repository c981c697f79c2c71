//! The well-formedness of a start tag's attributes, which the element tree's readers ([`crate::xml`])
//! do not otherwise check (quick-xml checks attributes only when they are iterated with checks).
//!
//! Input: a raw start tag, the text between `<` and `>` without the `/` of an empty tag.
//! Output: the first fault, as its byte offset in the tag and a one-line message, or `None`.
//! Invariants: one pass over the tag's bytes, no allocation unless there is a fault. What is checked
//! is XML 1.0's production for the attributes, `(S Attribute)* S?` with `Attribute ::= Name Eq
//! AttValue` (§3.1 [40], [41]): a name starting with a letter, `_`, `:` or a non-ASCII character
//! (§2.3 NameStartChar), then `=` and a value in single or double quotes holding no `<` (§2.3 [10]).
//! A document with such a fault is not well-formed, and an XML processor must report it (§1.2
//! "fatal error"): a file that writes `@_name="x"` or `name=x` is refused at its first fault,
//! instead of being read with its attributes missing. Non-ASCII name characters are accepted without
//! checking their Unicode class, and duplicate attributes are not looked for.

/// Whether `b` may start an attribute name (ASCII letters, `_`, `:`; any non-ASCII byte).
fn name_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_' || b == b':' || !b.is_ascii()
}

/// Whether `b` may continue an attribute name (adds digits, `-` and `.`).
fn name_char(b: u8) -> bool {
    name_start(b) || b.is_ascii_digit() || b == b'-' || b == b'.'
}

/// XML's white space (§2.3 [3]).
fn space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | b'\n')
}

/// The first fault of the attributes of `raw` (see the module documentation): its byte offset in
/// `raw` and what is wrong.
pub fn fault(raw: &str) -> Option<(usize, String)> {
    let b = raw.as_bytes();
    // the element name ends at the first white space
    let mut i = b.iter().position(|&c| space(c))?;
    loop {
        let spaced = i < b.len() && space(b[i]);
        while i < b.len() && space(b[i]) {
            i += 1;
        }
        if i >= b.len() {
            return None;
        }
        let start = i;
        if !spaced {
            return Some((
                start,
                "attributes must be separated by white space".to_string(),
            ));
        }
        if !name_start(b[i]) {
            let shown = word(raw, start);
            return Some((
                start,
                format!(
                    "attribute name `{shown}` does not start with a letter, `_` or `:` (XML 1.0, 2.3)"
                ),
            ));
        }
        while i < b.len() && name_char(b[i]) {
            i += 1;
        }
        let name = &raw[start..i];
        while i < b.len() && space(b[i]) {
            i += 1;
        }
        if i >= b.len() || b[i] != b'=' {
            return Some((
                start,
                format!("attribute `{}` has no `=` and value", word(raw, start)),
            ));
        }
        i += 1;
        while i < b.len() && space(b[i]) {
            i += 1;
        }
        let quote = match b.get(i) {
            Some(&q) if q == b'"' || q == b'\'' => q,
            _ => {
                return Some((
                    i.min(b.len()),
                    format!("the value of attribute `{name}` is not in quotes (XML 1.0, 3.1)"),
                ))
            }
        };
        let vstart = i + 1;
        let Some(len) = b[vstart..].iter().position(|&c| c == quote || c == b'<') else {
            return Some((i, format!("the value of attribute `{name}` is not closed")));
        };
        if b[vstart + len] == b'<' {
            return Some((
                vstart + len,
                format!("`<` in the value of attribute `{name}` (write `&lt;`)"),
            ));
        }
        i = vstart + len + 1;
    }
}

/// The text from `start` up to white space, `=` or a quote, at most 40 bytes (for a message).
fn word(raw: &str, start: usize) -> &str {
    let rest = &raw[start..];
    let end = rest
        .char_indices()
        .find(|&(k, c)| k >= 40 || c.is_whitespace() || matches!(c, '=' | '"' | '\''))
        .map_or(rest.len(), |(k, _)| k);
    &rest[..end]
}

#[cfg(test)]
mod tests {
    use super::fault;

    #[test]
    fn well_formed_tags_have_no_fault() {
        for raw in [
            "project",
            "project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"",
            "pou name='Main' pouType=\"program\"  ",
            "variable\n  name = \"x\"\taddress=\"%IX0.0\"",
            "xhtml:p xml:lang=\"en\" data-x.y_z=\"a > b\"",
            "a n=\"\"",
            "é ü=\"1\"",
        ] {
            assert_eq!(fault(raw), None, "{raw}");
        }
    }

    #[test]
    fn reports_the_first_fault_with_its_offset() {
        let f = fault("project @_xmlns=\"x\"").unwrap();
        assert_eq!(f.0, 8);
        assert!(f.1.contains("`@_xmlns`"), "{}", f.1);
        let f = fault("pou name=Other pouType=\"program\"").unwrap();
        assert_eq!(f.0, 9);
        assert!(f.1.contains("not in quotes"), "{}", f.1);
        assert_eq!(fault("a x=\"1\"y=\"2\"").unwrap().0, 7);
        assert_eq!(fault("a x").unwrap().0, 2);
        assert_eq!(fault("a x=\"1").unwrap().0, 4);
        assert_eq!(fault("a x=\"1<2\"").unwrap().0, 6);
        assert_eq!(fault("a 1x=\"1\"").unwrap().0, 2);
    }
}
