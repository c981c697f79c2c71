//! A small element tree over quick-xml for the template files, with byte spans kept.
//!
//! Input: the text of one XML file. Output: the root [`Element`] or one diagnostic at the byte where the
//! XML is malformed. Invariants: every span is a byte range of the input; text and CDATA are concatenated in
//! document order with their start offset kept (`text_offset`) so that C bodies can be mapped back.

use diagnostics::{code, Diagnostic, FileId, Span};
use quick_xml::events::Event;
use quick_xml::Reader;

#[derive(Debug, Clone)]
pub struct Attr {
    pub name: String,
    pub value: String,
    pub span: Span,
}

#[derive(Debug, Clone)]
pub struct Element {
    pub name: String,
    pub attrs: Vec<Attr>,
    pub children: Vec<Element>,
    /// Text and CDATA content, in document order.
    pub segments: Vec<TextSegment>,
    pub span: Span,
}

/// One run of character data. `verbatim` runs are exact slices of the file: `offset + i` is the file offset of
/// `text[i]` (CDATA sections, and text without entity references).
#[derive(Debug, Clone)]
pub struct TextSegment {
    pub text: String,
    pub offset: usize,
    /// Bytes of the file the run came from (`text.len()` for a verbatim run; the entity reference's length).
    pub src_len: usize,
    pub verbatim: bool,
}

impl Element {
    pub fn attr(&self, name: &str) -> Option<&Attr> {
        self.attrs.iter().find(|a| a.name == name)
    }
    pub fn children_named<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Element> + 'a {
        self.children.iter().filter(move |c| c.name == name)
    }
    /// The one segment that is not blank, if there is exactly one (a body written as one CDATA section).
    pub fn significant_segment(&self) -> Option<&TextSegment> {
        let mut it = self.segments.iter().filter(|s| !s.text.trim().is_empty());
        let first = it.next()?;
        it.next().is_none().then_some(first)
    }
    pub fn child(&self, name: &str) -> Option<&Element> {
        self.children.iter().find(|c| c.name == name)
    }
}

fn local_name(raw: &[u8]) -> String {
    let s = String::from_utf8_lossy(raw);
    match s.rsplit_once(':') {
        Some((_, l)) => l.to_string(),
        None => s.into_owned(),
    }
}

fn malformed(file: FileId, at: usize, len: usize, msg: impl std::fmt::Display) -> Box<Diagnostic> {
    Box::new(Diagnostic::error(code::E4001, format!("malformed XML: {msg}"))
        .at(Span::new(file, at, at + len))
        .with_hint(
            "fix the XML syntax of the template file (elements must be closed and properly nested)",
        ))
}

/// Elements nested deeper than this are refused (E0210): the tree is built with an explicit stack, but it
/// is cloned, dropped and walked recursively, so its depth must stay small. Real template files nest 4 levels.
pub const MAX_DEPTH: usize = 256;

/// Parses `text` into an element tree.
pub fn parse(file: FileId, text: &str) -> Result<Element, Box<Diagnostic>> {
    // Every leading byte-order mark is skipped: quick-xml drops one at the start of what it reads
    // without counting it in its positions, which would shift every span after it.
    let body = text.trim_start_matches('\u{feff}');
    let bom = text.len() - body.len();
    let mut reader = Reader::from_str(body);
    reader.config_mut().trim_text(false);
    let mut stack: Vec<Element> = Vec::new();
    let mut root: Option<Element> = None;
    loop {
        let before = reader.buffer_position() as usize + bom;
        let ev = reader
            .read_event()
            .map_err(|e| malformed(file, reader.error_position() as usize + bom, 1, e))?;
        let after = reader.buffer_position() as usize + bom;
        match ev {
            Event::Start(e) | Event::Empty(e) => {
                // Bytes, not a `str` slice: `after - 2` may fall inside a multi-byte character.
                let is_empty = after >= 2 && text.as_bytes().get(after - 2..after) == Some(b"/>");
                let mut attrs = Vec::new();
                for a in e.attributes() {
                    let a = a.map_err(|err| malformed(file, before, after - before, err))?;
                    let value = a
                        .unescape_value()
                        .map_err(|err| malformed(file, before, after - before, err))?
                        .into_owned();
                    let name = local_name(a.key.as_ref());
                    // Locate the attribute's value inside the tag for a precise span.
                    let tag = &text[before..after];
                    let span = tag
                        .find(&format!("{name}="))
                        .map(|i| Span::new(file, before + i, before + i + name.len()))
                        .unwrap_or(Span::new(file, before, after));
                    attrs.push(Attr { name, value, span });
                }
                if !is_empty && stack.len() >= MAX_DEPTH {
                    return Err(Box::new(
                        Diagnostic::error(
                            code::E0210,
                            format!("template elements nested deeper than {MAX_DEPTH} levels"),
                        )
                        .at(Span::new(file, before, after))
                        .with_primary_label(format!("level {}", stack.len() + 1))
                        .with_hint("a template file nests <templates>, <template>, <param>/<body> and little else: remove the extra nesting"),
                    ));
                }
                let el = Element {
                    name: local_name(e.name().as_ref()),
                    attrs,
                    children: Vec::new(),
                    segments: Vec::new(),
                    span: Span::new(file, before, after),
                };
                if is_empty {
                    match stack.last_mut() {
                        Some(parent) => parent.children.push(el),
                        None => root = Some(el),
                    }
                } else {
                    stack.push(el);
                }
            }
            Event::End(_) => {
                let mut el = stack
                    .pop()
                    .ok_or_else(|| malformed(file, before, after - before, "unexpected end tag"))?;
                el.span.end = after as u32;
                match stack.last_mut() {
                    Some(parent) => parent.children.push(el),
                    None => root = Some(el),
                }
            }
            Event::Text(t) => {
                if let Some(el) = stack.last_mut() {
                    let s = t
                        .decode()
                        .map_err(|err| malformed(file, before, after - before, err))?;
                    let text = s.into_owned();
                    el.segments.push(TextSegment {
                        src_len: text.len(),
                        text,
                        offset: before,
                        verbatim: true,
                    });
                }
            }
            Event::CData(t) => {
                if let Some(el) = stack.last_mut() {
                    let s = String::from_utf8_lossy(t.as_ref()).into_owned();
                    el.segments.push(TextSegment {
                        src_len: s.len(),
                        text: s,
                        offset: before + "<![CDATA[".len(),
                        verbatim: true,
                    });
                }
            }
            Event::GeneralRef(r) => {
                if let Some(el) = stack.last_mut() {
                    let name = String::from_utf8_lossy(r.as_ref()).into_owned();
                    let ch = match name.as_str() {
                        "lt" => "<".to_string(),
                        "gt" => ">".to_string(),
                        "amp" => "&".to_string(),
                        "quot" => "\"".to_string(),
                        "apos" => "'".to_string(),
                        n if n.starts_with('#') => {
                            let num = if let Some(h) = n.strip_prefix("#x") {
                                u32::from_str_radix(h, 16).ok()
                            } else {
                                n[1..].parse().ok()
                            };
                            num.and_then(char::from_u32)
                                .map(String::from)
                                .ok_or_else(|| {
                                    malformed(
                                        file,
                                        before,
                                        after - before,
                                        "bad character reference",
                                    )
                                })?
                        }
                        _ => {
                            return Err(malformed(
                                file,
                                before,
                                after - before,
                                format!("unknown entity `&{name};`"),
                            ))
                        }
                    };
                    el.segments.push(TextSegment {
                        text: ch,
                        offset: before,
                        src_len: after - before,
                        verbatim: false,
                    });
                }
            }
            Event::Eof => break,
            _ => {}
        }
    }
    if let Some(open) = stack.last() {
        return Err(malformed(
            file,
            open.span.start as usize,
            open.span.len(),
            format!("element <{}> is not closed", open.name),
        ));
    }
    root.ok_or_else(|| malformed(file, 0, 0, "the file has no root element"))
}
