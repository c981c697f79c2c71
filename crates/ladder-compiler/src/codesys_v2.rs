//! CODESYS V2.3 object files: the one-object-per-file XML that CODESYS V2.3's version control (ENI)
//! and its per-object export write (`NAME.pou.xml`, `NAME.dut.xml`, `NAME.gvl.xml`), whose root is
//! `<pou>`, `<dut>` or `<gvl>` (not a PLCopen `<project>`), with the declaration text in
//! `<interface>` and an ST or IL body in `<st><body>` (`<il><body>`), the POU's actions in
//! `<action>` elements.
//!
//! Input: the XML text of one file. Output: the same text as IEC 61131-3 source: every byte outside the
//! declaration and body texts blanked (line breaks kept, so every line and column of the source is the
//! file's own), with `END_PROGRAM`/`END_FUNCTION_BLOCK`/`END_FUNCTION` and the `ACTIONS` block's
//! keywords written into blank places of the markup after the texts they close. The caller parses it
//! as an `.st` file. Invariants: never panics; a body in a graphical language (LD, FBD, CFC, SFC) is one
//! located E0321 naming it; a file that is not such an object file gives `None`.

use crate::xml::{self, Element, SegKind};
use diagnostics::{code, Diagnostic, FileId, Span};

/// The name of the document's root element, read without parsing the document: the first start tag
/// after a byte-order mark, the XML declaration, processing instructions, comments and a DOCTYPE.
/// `None` when the beginning is anything else (the caller then parses the document to decide).
pub(crate) fn root_name(text: &str) -> Option<&str> {
    let mut rest = text.strip_prefix('\u{feff}').unwrap_or(text);
    loop {
        rest = rest.trim_start();
        if let Some(r) = rest.strip_prefix("<?") {
            rest = &r[r.find("?>")? + 2..];
        } else if let Some(r) = rest.strip_prefix("<!--") {
            rest = &r[r.find("-->")? + 3..];
        } else if rest.starts_with("<!") {
            // a DOCTYPE: with an internal subset (`[`) the caller parses the document
            let end = rest.find('>')?;
            if rest[..end].contains('[') {
                return None;
            }
            rest = &rest[end + 1..];
        } else {
            let r = rest.strip_prefix('<')?;
            let end = r
                .find(|c: char| c.is_ascii_whitespace() || c == '>' || c == '/')
                .unwrap_or(r.len());
            return Some(&r[..end]).filter(|n| !n.is_empty());
        }
    }
}

/// `name` without its namespace prefix (`plc:pou` -> `pou`).
pub(crate) fn local_name(name: &str) -> &str {
    name.rsplit(':').next().unwrap_or(name)
}

/// The text of a CODESYS V2.3 object file as IEC 61131-3 source (same length and line breaks as the
/// file), or the E0321 that says why it cannot be read; `None` when the file is no such object file
/// (its root is not `<pou>`, `<dut>` or `<gvl>` with an `<interface>` child, or has a namespace).
pub fn object_source(file: FileId, text: &str) -> Option<Result<String, Box<Diagnostic>>> {
    // Every XML file passes here: a PLCopen project is told apart by its root's name alone, so that it
    // is not parsed twice (the whole tree of a 22 MB project cost 0.03-0.04 s before this check).
    if root_name(text).is_some_and(|n| !matches!(local_name(n), "pou" | "dut" | "gvl")) {
        return None;
    }
    let arena = xml::Arena::new();
    let (root, err) = xml::parse(text, &arena);
    if err.is_some() {
        return None;
    }
    let root = root?;
    if !matches!(root.name(), "pou" | "dut" | "gvl")
        || root.attr("xmlns").is_some()
        || root.child("interface").is_none()
    {
        return None;
    }
    let mut out = Source::blank(text);
    let name = child_text(&root, "name");
    let interface = root.child("interface")?;
    out.copy(interface);
    if root.name() != "pou" {
        return Some(Ok(out.finish()));
    }
    let header = interface.text_ref();
    let end_keyword = match header
        .split(|c: char| !c.is_ascii_alphanumeric() && c != '_')
        .find(|w| !w.is_empty())
        .map(str::to_ascii_uppercase)
        .as_deref()
    {
        Some("PROGRAM") => "END_PROGRAM",
        Some("FUNCTION_BLOCK") => "END_FUNCTION_BLOCK",
        Some("FUNCTION") => "END_FUNCTION",
        _ => {
            return Some(Err(unreadable(
                file,
                interface,
                format!(
                    "CODESYS V2.3 object file of POU `{name}`: its <interface> does not begin with \
                     PROGRAM, FUNCTION_BLOCK or FUNCTION"
                ),
            )))
        }
    };
    let mut at = match body_of(file, &root, &name) {
        Ok(Some(body)) => out.copy(body),
        Ok(None) => interface.end(),
        Err(d) => return Some(Err(d)),
    };
    let actions: Vec<(&Element, String, &Element)> = {
        let mut v = Vec::new();
        for action in root.children_named("action") {
            let action_name = child_text(action, "name");
            match body_of(file, action, &format!("{name}.{action_name}")) {
                Ok(Some(b)) => v.push((action, action_name, b)),
                Ok(None) => {}
                Err(d) => return Some(Err(d)),
            }
        }
        v
    };
    if actions.is_empty() {
        out.place_last(at, end_keyword);
        return Some(Ok(out.finish()));
    }
    // the POU's end, `ACTIONS` and each `ACTION name:` go into the markup before the action's body
    // (its `<name>` line has room); the last keyword may have to follow the file's end
    let mut written = Some(at);
    for (k, (_, action_name, body)) in actions.iter().enumerate() {
        let start = body.tag_start();
        if k == 0 {
            written = written
                .and_then(|w| out.place(w, start, end_keyword))
                .and_then(|w| out.place(w, start, "ACTIONS"));
        }
        written = written.and_then(|w| out.place(w, start, &format!("ACTION {action_name}:")));
        at = out.copy(body);
        written = written.map(|_| at);
        if k + 1 < actions.len() {
            written =
                written.and_then(|w| out.place(w, actions[k + 1].2.tag_start(), "END_ACTION"));
        }
    }
    let Some(w) = written else {
        return Some(Err(unreadable(
            file,
            &root,
            format!("CODESYS V2.3 object file of POU `{name}` has no room for its keywords"),
        )));
    };
    out.place_last(w, "END_ACTION END_ACTIONS");
    Some(Ok(out.finish()))
}

/// The text content of `el`'s child `name` (`<name>assertTrue</name>`), trimmed.
fn child_text(el: &Element, name: &str) -> String {
    el.child(name)
        .map(|c| c.text_ref().trim().to_string())
        .unwrap_or_default()
}

/// The `<body>` of `el`'s ST or IL body element (`<st><body>`, `<il><body>`); `Ok(None)` when it has
/// none; E0321 when the body is in another language.
fn body_of<'e, 'a>(
    file: FileId,
    el: &'e Element<'a>,
    what: &str,
) -> Result<Option<&'e Element<'a>>, Box<Diagnostic>> {
    let Some(lang) = el.children.iter().find(|c| c.child("body").is_some()) else {
        return Ok(None);
    };
    if !lang.name().eq_ignore_ascii_case("st") && !lang.name().eq_ignore_ascii_case("il") {
        return Err(unreadable(
            file,
            lang,
            format!(
                "CODESYS V2.3 object file: the body of `{what}` is <{}>, which ladderc cannot read \
                 in this format (it reads <st> and <il> bodies)",
                lang.name()
            ),
        ));
    }
    Ok(lang.child("body"))
}

fn unreadable(file: FileId, el: &Element, msg: String) -> Box<Diagnostic> {
    Box::new(
        Diagnostic::error(code::E0321, msg)
            .at(Span::new(file, el.tag_start(), el.tag_end()))
            .with_hint(
                "export the project from CODESYS as PLCopen XML (Project > Export PLCopenXML) or as \
                 text (.EXP), and give ladderc that file",
            ),
    )
}

/// Whether `line` (the start of a line) ends inside a `//` comment: a `//` outside string literals
/// and `(* *)` comments.
fn line_comment_open(line: &[u8]) -> bool {
    let mut quote = None;
    let mut block = false;
    let mut i = 0;
    while i < line.len() {
        let (c, next) = (line[i], line.get(i + 1).copied());
        match quote {
            Some(_) if c == b'$' => i += 1, // an escape: `$'` stays in the literal
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if block && c == b'*' && next == Some(b')') => {
                block = false;
                i += 1;
            }
            None if block => {}
            None if c == b'(' && next == Some(b'*') => {
                block = true;
                i += 1;
            }
            None if c == b'/' && next == Some(b'/') => return true,
            None if c == b'\'' || c == b'"' => quote = Some(c),
            None => {}
        }
        i += 1;
    }
    false
}

/// The file's text being turned into source: bytes outside the copied texts are blank.
pub(crate) struct Source {
    bytes: Vec<u8>,
    /// Texts written here that stand elsewhere in the file ([`Source::place_moved`]).
    moved: Vec<diagnostics::MovedText>,
}

impl Source {
    /// Every byte blank but the line breaks (a multi-byte character becomes as many blanks).
    pub(crate) fn blank(text: &str) -> Source {
        Source {
            bytes: text
                .bytes()
                .map(|b| if b == b'\n' || b == b'\r' { b } else { b' ' })
                .collect(),
            moved: Vec::new(),
        }
    }

    /// Copies `el`'s text (CDATA and character data; an entity as its character, padded with blanks)
    /// into place; returns the offset just after the last piece.
    pub(crate) fn copy(&mut self, el: &Element) -> usize {
        let mut end = el.tag_end();
        for seg in el.segments() {
            let (start, stop) = (
                seg.start.min(self.bytes.len()),
                seg.end.min(self.bytes.len()),
            );
            let room = stop.saturating_sub(start);
            let text = seg.text.as_bytes();
            // text and CDATA pieces are the raw bytes; an entity is shorter than its reference
            if text.len() > room || (seg.kind != SegKind::Entity && text.len() != room) {
                continue;
            }
            let from = start;
            self.bytes[from..from + text.len()].copy_from_slice(text);
            end = end.max(from + text.len());
        }
        end
    }

    /// Writes ` keyword` into the first blank stretch of one line between `from` and `to`; returns
    /// the offset after it, or `None` when there is no room.
    /// A `//` comment open at `from` (a TwinCAT declaration `PROPERTY P : INT // free places`
    /// ends so) puts the keyword on a later line.
    pub(crate) fn place(&mut self, from: usize, to: usize, keyword: &str) -> Option<usize> {
        let need = keyword.len() + 2;
        let to = to.min(self.bytes.len());
        let from = from.min(to);
        let line_start = self.bytes[..from]
            .iter()
            .rposition(|&b| b == b'\n')
            .map_or(0, |i| i + 1);
        let from = if line_comment_open(&self.bytes[line_start..from]) {
            from + self.bytes[from..to].iter().position(|&b| b == b'\n')?
        } else {
            from
        };
        let mut run = 0;
        for i in from..to {
            if self.bytes[i] == b' ' {
                run += 1;
                if run == need {
                    // one blank before the keyword, one after it
                    let start = i + 2 - need;
                    self.bytes[start..start + keyword.len()].copy_from_slice(keyword.as_bytes());
                    return Some(start + keyword.len());
                }
            } else {
                run = 0;
            }
        }
        None
    }

    /// [`Source::place`] for a word that stands at `original` in the file (a chart's condition
    /// taken from another object of the file): where it is written is recorded, so that a
    /// diagnostic in it is shown where it stands ([`Source::take_moved`]); `group`: the text it
    /// belongs to.
    pub(crate) fn place_moved(
        &mut self,
        from: usize,
        to: usize,
        word: &str,
        original: usize,
        group: u32,
    ) -> Option<usize> {
        let end = self.place(from, to, word)?;
        let at = end - word.len();
        if let (Ok(at), Ok(len), Ok(from)) = (
            u32::try_from(at),
            u32::try_from(word.len()),
            u32::try_from(original),
        ) {
            self.moved.push(diagnostics::MovedText {
                at,
                len,
                from,
                group,
            });
        }
        Some(end)
    }

    /// The texts written by [`Source::place_moved`], for `diagnostics::Diagnostics::read_moved`.
    pub(crate) fn take_moved(&mut self) -> Vec<diagnostics::MovedText> {
        std::mem::take(&mut self.moved)
    }

    /// [`Source::place`] up to the end of the text, else after it (on a line of its own).
    pub(crate) fn place_last(&mut self, from: usize, keyword: &str) {
        if self.place(from, self.bytes.len(), keyword).is_none() {
            self.bytes.push(b'\n');
            self.bytes.extend_from_slice(keyword.as_bytes());
            self.bytes.push(b'\n');
        }
    }

    pub(crate) fn finish(self) -> String {
        // only ASCII was written over blanks, and copied texts are whole UTF-8 pieces
        String::from_utf8(self.bytes).unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_root_name_is_read_past_declarations_comments_and_doctypes() {
        let cases = [
            (
                "<?xml version=\"1.0\"?>\n<project xmlns=\"x\">",
                Some("project"),
            ),
            (
                "\u{feff}<?xml version=\"1.0\"?><!-- a > b --><pou>",
                Some("pou"),
            ),
            ("<!DOCTYPE gvl SYSTEM \"g.dtd\">\r\n  <gvl>", Some("gvl")),
            ("<?xml?><?style x?>\n<dut/>", Some("dut")),
            ("<plc:pou xmlns:plc=\"x\">", Some("plc:pou")),
            ("<!DOCTYPE pou [ <!ENTITY e \"x\"> ]><pou>", None),
            ("", None),
            ("text before <pou>", None),
            ("<!-- never closed", None),
        ];
        for (text, root) in cases {
            assert_eq!(root_name(text), root, "{text:?}");
        }
        assert_eq!(local_name("plc:pou"), "pou");
        assert_eq!(local_name("pou"), "pou");
    }

    #[test]
    fn a_plcopen_project_is_no_object_file_and_an_object_file_still_is() {
        let project = "<?xml version=\"1.0\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"></project>";
        assert!(object_source(FileId(0), project).is_none());
        let pou = "<?xml version=\"1.0\"?>\n<pou><name>P</name><interface>PROGRAM P\nVAR x : INT; END_VAR\n</interface><st><body>x := x + 1;</body></st></pou>";
        let text = object_source(FileId(0), pou)
            .expect("an object file")
            .expect("readable");
        assert_eq!(text.len(), pou.len());
        assert!(
            text.contains("PROGRAM P")
                && text.contains("x := x + 1;")
                && text.contains("END_PROGRAM")
        );
    }
}
