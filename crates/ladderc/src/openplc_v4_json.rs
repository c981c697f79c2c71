//! OpenPLC Editor v4 `project.json` files that hold their POUs inline (`data.pous[].data`: the
//! POU's `name`, `variables` and `body`, as the editor saved projects before it moved POUs to
//! `pous/*.st|*.ld`), and `.json` inputs that are no such project.
//!
//! Input: the file's text. Output: Structured Text of the same length, line breaks kept, with the
//! JSON blanked and each POU written into the blanks, each token at or after the JSON it comes
//! from (so a diagnostic of the ST front end points into `project.json`): the POU's header at its
//! `name`, its declarations at its `variables` (grouped by class in the editor's order: external,
//! input, output, inout, local, temp), an ST body (`"body": {"language": "st", "value": "..."}`)
//! decoded at the very place of its JSON string, a Ladder body (`"value": {"rungs": [...]}`) read
//! by [`crate::openplc_v4_ld`] as a `.ld` file's JSON, then the POU's closing keyword. The
//! configuration, global variables and data types are read by [`crate::openplc_v4`] as for a
//! project folder.
//!
//! Invariants: never panics; nothing of the JSON reaches the text but the ST bodies and names,
//! types, addresses and literals that [`crate::openplc_v4`] accepts; a POU that cannot be read
//! (FBD or SFC: E1073; another language, an entry that is not a name, type, address or literal, a
//! layout with no room for the declarations: E1074; a ladder body: E1064, E1065) is one located
//! error, and then nothing of the file is compiled. A `.json` input that is no v4 project is one
//! E1074 at its start: it is never read as ST.

use crate::openplc_v4::{is_address, is_literal, is_name, type_text};
use diagnostics::{code, Code, Diagnostic, Diagnostics, FileId, Span};
use serde_json::Value;

/// At most this many POUs are read from one file (as [`crate::openplc_v4::MAX_FILES`]).
pub const MAX_POUS: usize = crate::openplc_v4::MAX_FILES;

/// How deep the JSON is walked (serde_json's own recursion limit).
const MAX_DEPTH: usize = 128;

/// A JSON value's place in the text.
struct J {
    start: usize,
    end: usize,
    kind: K,
}

enum K {
    /// Members: the key's raw text and the value.
    Obj(Vec<(String, J)>),
    Arr(Vec<J>),
    Str,
    Other,
}

impl J {
    /// The member `key` (the last one, as serde_json keeps it).
    fn get(&self, key: &str) -> Option<&J> {
        match &self.kind {
            K::Obj(m) => m.iter().rev().find(|(k, _)| k == key).map(|(_, v)| v),
            _ => None,
        }
    }
    fn items(&self) -> &[J] {
        match &self.kind {
            K::Arr(a) => a,
            _ => &[],
        }
    }
    /// The text of a string value, decoded.
    fn text(&self, src: &str) -> Option<String> {
        matches!(self.kind, K::Str)
            .then(|| serde_json::from_str(&src[self.start..self.end]).ok())
            .flatten()
    }
}

/// The places of the values of `src` (JSON that serde_json has read).
struct Scanner<'a> {
    b: &'a [u8],
    at: usize,
}

impl Scanner<'_> {
    fn ws(&mut self) {
        while self.at < self.b.len() && self.b[self.at].is_ascii_whitespace() {
            self.at += 1;
        }
    }
    fn string_end(&mut self) -> Option<usize> {
        // at the opening quote
        self.at += 1;
        while self.at < self.b.len() {
            match self.b[self.at] {
                b'\\' => self.at += 2,
                b'"' => {
                    self.at += 1;
                    return Some(self.at);
                }
                _ => self.at += 1,
            }
        }
        None
    }
    fn value(&mut self, depth: usize) -> Option<J> {
        if depth > MAX_DEPTH {
            return None;
        }
        self.ws();
        let start = self.at;
        match *self.b.get(self.at)? {
            b'{' => {
                self.at += 1;
                let mut members = Vec::new();
                loop {
                    self.ws();
                    match *self.b.get(self.at)? {
                        b'}' => break,
                        b',' => self.at += 1,
                        b'"' => {
                            let k0 = self.at + 1;
                            let k1 = self.string_end()? - 1;
                            let key = String::from_utf8_lossy(&self.b[k0..k1]).into_owned();
                            self.ws();
                            (*self.b.get(self.at)? == b':').then_some(())?;
                            self.at += 1;
                            members.push((key, self.value(depth + 1)?));
                        }
                        _ => return None,
                    }
                }
                self.at += 1;
                Some(J {
                    start,
                    end: self.at,
                    kind: K::Obj(members),
                })
            }
            b'[' => {
                self.at += 1;
                let mut items = Vec::new();
                loop {
                    self.ws();
                    match *self.b.get(self.at)? {
                        b']' => break,
                        b',' => self.at += 1,
                        _ => items.push(self.value(depth + 1)?),
                    }
                }
                self.at += 1;
                Some(J {
                    start,
                    end: self.at,
                    kind: K::Arr(items),
                })
            }
            b'"' => {
                let end = self.string_end()?;
                Some(J {
                    start,
                    end,
                    kind: K::Str,
                })
            }
            _ => {
                while self.at < self.b.len() && !b",]} \t\r\n".contains(&self.b[self.at]) {
                    self.at += 1;
                }
                (self.at > start).then_some(J {
                    start,
                    end: self.at,
                    kind: K::Other,
                })
            }
        }
    }
}

/// Whether `src` is a JSON object (what a content-detected input is checked for).
pub fn is_json_object(src: &str) -> bool {
    src.trim_start().starts_with('{') && serde_json::from_str::<serde::de::IgnoredAny>(src).is_ok()
}

/// Whether a well-formed JSON `v` is an OpenPLC Editor v4 project (`"meta": {"type":
/// "plc-project"}` or `plc-library`).
pub fn is_v4_project(v: &Value) -> bool {
    v.get("meta")
        .and_then(|m| m.get("type"))
        .and_then(Value::as_str)
        .is_some_and(|k| matches!(k, "plc-project" | "plc-library"))
}

fn error(code: Code, file: FileId, at: usize, msg: String, label: &str, hint: &str) -> Diagnostic {
    Diagnostic::error(code, msg)
        .at(Span::new(file, at, at + 1))
        .with_primary_label(label)
        .with_hint(hint)
}

/// The hint of an entry the editor would not have written.
const HINT: &str = "open the project in OpenPLC Editor and save it again, or give the PLCopen XML the editor generates (build/<target>/src/plc.xml)";

/// The ST text of the `.json` input `src` (file `file`, shown as `shown`): `Some` for an OpenPLC
/// Editor v4 project whose inline POUs were all read; `None` after its errors otherwise (a file
/// that is no v4 project is one E1074).
pub fn read(file: FileId, src: &str, shown: &str, diags: &mut Diagnostics) -> Option<String> {
    let value: Value = match serde_json::from_str(src) {
        Ok(v) => v,
        Err(e) => {
            let at = offset_of(src, e.line(), e.column());
            let what = e.to_string();
            let what = what.split(" at line ").next().unwrap_or_default();
            diags.push(error(
                code::E1074,
                file,
                at,
                format!("{shown} is not well-formed JSON ({what}): it is no OpenPLC Editor v4 project ladderc reads"),
                "reading stopped here",
                HINT,
            ));
            return None;
        }
    };
    if !is_v4_project(&value) {
        diags.push(error(
            code::E1074,
            file,
            0,
            format!("{shown} is JSON but no OpenPLC Editor v4 project (`\"meta\": {{\"type\": \"plc-project\"}}`): ladderc reads no other JSON"),
            "not a project.json",
            "give the project's sources (.st, .il, PLCopen .xml), its folder, or the project.json of an OpenPLC Editor v4 project",
        ));
        return None;
    }
    let root = Scanner {
        b: src.as_bytes(),
        at: 0,
    }
    .value(0)?;
    let pous = root
        .get("data")
        .and_then(|d| d.get("pous"))
        .map(J::items)
        .unwrap_or_default();
    if pous.is_empty() {
        let at = root
            .get("data")
            .and_then(|d| d.get("pous"))
            .map_or(0, |j| j.start);
        diags.push(error(
            code::E1074,
            file,
            at,
            format!("{shown} holds no POU (`data.pous` is empty) and its folder no POU file under pous/"),
            "no POU here",
            "give the project's folder with its pous/ files, or its generated PLCopen XML (build/<target>/src/plc.xml)",
        ));
        return None;
    }
    let mut bytes: Vec<u8> = src
        .bytes()
        .map(|b| if b == b'\n' || b == b'\r' { b } else { b' ' })
        .collect();
    let mut cursor = 0;
    let mut failed = false;
    let starts: Vec<usize> = pous.iter().map(|p| p.start).collect();
    for (k, pou) in pous.iter().enumerate().take(MAX_POUS) {
        // what follows the POU's body may take the blanks up to the next POU's body
        let limit = pous
            .get(k + 1)
            .and_then(body_of)
            .map_or(src.len(), |(b, _)| b.start.max(starts[k + 1]));
        match write_pou(file, src, pou, &mut bytes, cursor, limit) {
            Ok(after) => cursor = after,
            Err(d) => {
                diags.push(*d);
                failed = true;
            }
        }
    }
    if failed {
        return None;
    }
    // only ASCII was written over blanks, and every byte of the JSON was blanked alone
    Some(String::from_utf8(bytes).unwrap_or_default())
}

/// The body's value and its language (lower case) of the POU entry `pou`.
fn body_of(pou: &J) -> Option<(&J, Option<&J>)> {
    let data = pou.get("data")?;
    let body = data.get("body")?;
    match body.kind {
        K::Obj(_) => Some((body.get("value")?, body.get("language"))),
        _ => Some((body, None)),
    }
}

/// The byte offset of 1-based `line` and `column` in `text`, clamped to its last byte.
fn offset_of(text: &str, line: usize, column: usize) -> usize {
    crate::openplc_v4_ld::offset_of(text, line, column).min(text.len().saturating_sub(1))
}

type Fail = Box<Diagnostic>;

/// The class keywords of the editor's variable classes, in the order the editor writes them
/// (`generateIecVariablesToString`).
const CLASSES: [(&str, &str); 7] = [
    ("global", "VAR_GLOBAL"),
    ("external", "VAR_EXTERNAL"),
    ("input", "VAR_INPUT"),
    ("output", "VAR_OUTPUT"),
    ("inout", "VAR_IN_OUT"),
    ("local", "VAR"),
    ("temp", "VAR_TEMP"),
];

/// Writes the POU `pou` into `bytes` from `cursor` on (what follows its body before `limit`);
/// the offset after it.
fn write_pou(
    file: FileId,
    src: &str,
    pou: &J,
    bytes: &mut [u8],
    cursor: usize,
    limit: usize,
) -> Result<usize, Fail> {
    let bad = |at: usize, msg: String| {
        Box::new(error(
            code::E1074,
            file,
            at,
            format!("project.json: {msg}"),
            "this entry",
            HINT,
        ))
    };
    let data = pou
        .get("data")
        .ok_or_else(|| bad(pou.start, "a POU without `data` is not read".into()))?;
    let name_j = data.get("name");
    let name = name_j.and_then(|n| n.text(src)).unwrap_or_default();
    let name_at = name_j.map_or(data.start, |n| n.start);
    if !is_name(&name) {
        return Err(bad(
            name_at,
            format!("the POU name `{}` is not read", name.escape_debug()),
        ));
    }
    let kind = pou
        .get("type")
        .and_then(|t| t.text(src))
        .unwrap_or_default();
    let (keyword, closer) = match kind.as_str() {
        "program" => ("PROGRAM", "END_PROGRAM"),
        "function-block" => ("FUNCTION_BLOCK", "END_FUNCTION_BLOCK"),
        "function" => ("FUNCTION", "END_FUNCTION"),
        _ => {
            return Err(bad(
                pou.get("type").map_or(pou.start, |t| t.start),
                format!(
                    "the kind `{}` of POU `{name}` is not read",
                    kind.escape_debug()
                ),
            ))
        }
    };
    // (the header is one line, as the ST reader wants it: at the POU's entry, where it has room)
    let mut header = format!("{keyword} {name}");
    if keyword == "FUNCTION" {
        let ret = data.get("returnType");
        let ty = ret.and_then(|r| {
            let v: Value = serde_json::from_str(&src[r.start..r.end]).ok()?;
            match &v {
                Value::String(s) => is_name(s).then(|| s.clone()),
                _ => type_text(&v),
            }
        });
        let Some(ty) = ty else {
            return Err(bad(
                ret.map_or(name_at, |r| r.start),
                format!("the return type of FUNCTION `{name}` is not read"),
            ));
        };
        header.push_str(&format!(" : {ty}"));
    }
    let mut words: Vec<(String, usize)> = vec![(header, pou.start)];
    // the declarations, grouped by class
    let vars = data.get("variables").map(J::items).unwrap_or_default();
    let mut groups: Vec<Vec<(Vec<String>, usize)>> = vec![Vec::new(); CLASSES.len()];
    for v in vars {
        let value: Value = serde_json::from_str(&src[v.start..v.end]).unwrap_or(Value::Null);
        let at = v.get("name").map_or(v.start, |n| n.start);
        let vname = value.get("name").and_then(Value::as_str).unwrap_or("");
        let class = value
            .get("class")
            .and_then(Value::as_str)
            .unwrap_or("local")
            .to_ascii_lowercase();
        let Some(g) = CLASSES.iter().position(|(c, _)| *c == class) else {
            return Err(bad(
                at,
                format!(
                    "the class `{}` of variable `{}` of `{name}` is not read",
                    class.escape_debug(),
                    vname.escape_debug()
                ),
            ));
        };
        let ty = value.get("type").and_then(type_text);
        let (true, Some(ty)) = (is_name(vname), ty) else {
            return Err(bad(
                at,
                format!(
                    "variable `{}` of `{name}` is not read",
                    vname.escape_debug()
                ),
            ));
        };
        let mut decl = vec![vname.to_string()];
        match value.get("location").and_then(Value::as_str).map(str::trim) {
            Some("") | None => {}
            Some(a) if is_address(a) => decl.extend(["AT".into(), a.to_string()]),
            Some(a) => {
                return Err(bad(
                    at,
                    format!(
                        "the location `{}` of `{vname}` in `{name}` is not read",
                        a.escape_debug()
                    ),
                ))
            }
        }
        decl.extend([":".into(), ty]);
        let init = crate::openplc_v4::initial_value(&value);
        match init.as_deref().map(str::trim) {
            Some("") | None => {}
            Some(i) if is_literal(i) => decl.extend([":=".into(), i.to_string()]),
            Some(i) => {
                return Err(bad(
                    at,
                    format!(
                        "the initial value `{}` of `{vname}` in `{name}` is not read",
                        i.escape_debug()
                    ),
                ))
            }
        }
        decl.push(";".into());
        groups[g].push((decl, at));
    }
    for (g, list) in groups.iter().enumerate() {
        let Some(first) = list.first() else { continue };
        words.push((CLASSES[g].1.into(), first.1));
        for (decl, at) in list {
            words.extend(decl.iter().map(|w| (w.clone(), *at)));
        }
        words.push(("END_VAR".into(), list.last().map_or(first.1, |l| l.1)));
    }
    // the body
    let Some((body, lang_j)) = body_of(pou) else {
        return Err(bad(data.start, format!("the POU `{name}` has no `body`")));
    };
    let lang = lang_j
        .or(data.get("language"))
        .and_then(|l| l.text(src))
        .unwrap_or_default()
        .to_ascii_lowercase();
    let lang_at = lang_j.map_or(body.start, |l| l.start);
    let no_room = || {
        bad(
            name_at,
            format!("the POU `{name}` leaves no room for its declarations before its body (its entries are not in the editor's order: name, variables, body)"),
        )
    };
    let mut at = cursor;
    match (lang.as_str(), &body.kind) {
        ("st", K::Str) => {
            let content = body.start + 1;
            for (w, pref) in &words {
                at = crate::openplc_v4_ld::place(bytes, (*pref).max(at), content, w)
                    .or_else(|| crate::openplc_v4_ld::place(bytes, at, content, w))
                    .ok_or_else(no_room)?;
            }
            let text = decode_in_place(&src[content..body.end - 1]);
            bytes[content..content + text.len()].copy_from_slice(text.as_bytes());
            let end = body.end;
            crate::openplc_v4_ld::place(bytes, end, limit, closer)
                .ok_or_else(|| bad(body.start, format!("the POU `{name}` leaves no room for its `{closer}` after its body")))
        }
        ("ld", K::Obj(_)) => {
            // the POU's text up to `limit`, its ladder JSON in place: read as a `.ld` file
            for (w, pref) in &words {
                at = crate::openplc_v4_ld::place(bytes, (*pref).max(at), body.start, w)
                    .or_else(|| crate::openplc_v4_ld::place(bytes, at, body.start, w))
                    .ok_or_else(no_room)?;
            }
            let mut part = bytes[cursor..limit].to_vec();
            part[body.start - cursor..body.end - cursor]
                .copy_from_slice(&src.as_bytes()[body.start..body.end]);
            let part = String::from_utf8(part).unwrap_or_default();
            let shift = |mut d: Fail| {
                if let Some(s) = d.span.as_mut() {
                    let by = u32::try_from(cursor).unwrap_or(u32::MAX);
                    s.start = s.start.saturating_add(by);
                    s.end = s.end.saturating_add(by);
                }
                d
            };
            let text = match crate::openplc_v4_ld::read(file, &part, body.start - cursor) {
                Some(Ok(t)) => t,
                Some(Err(d)) => return Err(shift(d)),
                None => {
                    return Err(bad(
                        body.start,
                        format!("the ladder body of `{name}` holds no `rungs`"),
                    ))
                }
            };
            // what did not fit in the JSON's blanks follows it: into the blanks before `limit`
            let over = text.len() - part.len();
            let split = body.end - cursor;
            bytes[cursor..body.end].copy_from_slice(&text.as_bytes()[..split]);
            let mut after = body.end;
            for w in words_of(&text[split..split + over]) {
                after = crate::openplc_v4_ld::place(bytes, after, limit, w).ok_or_else(|| {
                    bad(body.start, format!("the POU `{name}` leaves no room for the statements of its rungs"))
                })?;
            }
            Ok(after)
        }
        ("fbd" | "sfc", _) => Err(Box::new(error(
            code::E1073,
            file,
            body.start,
            format!("an OpenPLC Editor v4 graphical body ({}) of `{name}`, which ladderc does not read", lang.to_ascii_uppercase()),
            "the body starts here",
            "give the PLCopen XML the editor generates for the project (build/<target>/src/plc.xml), or write the POU in ST or Ladder",
        ))),
        _ => Err(Box::new(error(
            code::E1074,
            file,
            lang_at,
            format!("project.json: the body of `{name}` (language `{}`) is not read", lang.escape_debug()),
            "this body",
            "ladderc reads the ST and Ladder bodies of a project.json: write the POU in ST, or give the PLCopen XML the editor generates (build/<target>/src/plc.xml)",
        ))),
    }
}

/// The words of `text` (split at blanks outside quotes).
fn words_of(text: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let (mut start, mut quoted) = (None, false);
    for (i, c) in text.char_indices() {
        if c == '\'' {
            quoted = !quoted;
        }
        if c.is_whitespace() && !quoted {
            if let Some(s) = start.take() {
                out.push(&text[s..i]);
            }
        } else if start.is_none() {
            start = Some(i);
        }
    }
    if let Some(s) = start {
        out.push(&text[s..]);
    }
    out
}

/// The ST text of the JSON string content `raw` (without its quotes), as long as `raw` and each
/// character at the place of its JSON, as far as can be: an escape (`\n`, `\"`, `\u00e9`) is
/// followed by blanks to its length, except inside an ST string literal, where the blanks would
/// change the string (they follow its closing quote).
fn decode_in_place(raw: &str) -> String {
    #[derive(PartialEq)]
    enum S {
        Code,
        Str(char, bool),
        Block(char),
        Line,
    }
    let mut out = String::with_capacity(raw.len());
    let mut state = S::Code;
    let mut prev = ' ';
    let b = raw.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let (c, next) = if b[i] == b'\\' {
            escape(raw, i)
        } else {
            let c = raw[i..].chars().next().unwrap_or(' ');
            (c, i + c.len_utf8())
        };
        state = match state {
            S::Code => match c {
                '\'' | '"' => S::Str(c, false),
                '*' if prev == '(' => S::Block(')'),
                '*' if prev == '/' => S::Block('/'),
                '/' if prev == '/' => S::Line,
                _ => S::Code,
            },
            S::Str(q, true) => S::Str(q, false),
            S::Str(q, false) if c == '$' => S::Str(q, true),
            S::Str(q, false) if c == q => S::Code,
            S::Block(e) if c == e && prev == '*' => S::Code,
            S::Line if c == '\n' || c == '\r' => S::Code,
            s => s,
        };
        prev = if state == S::Code && prev == '*' && c == ')' {
            ' '
        } else {
            c
        };
        out.push(c);
        if !matches!(state, S::Str(..)) {
            while out.len() < next {
                out.push(' ');
            }
        }
        i = next;
    }
    // (a string left open: its text is cut at the JSON's end)
    while out.len() > raw.len() {
        out.pop();
    }
    while out.len() < raw.len() {
        out.push(' ');
    }
    out
}

/// The character of the JSON escape at `i` of `raw` and the offset after it.
fn escape(raw: &str, i: usize) -> (char, usize) {
    let hex = |at: usize| {
        raw.get(at..at + 4)
            .and_then(|h| u32::from_str_radix(h, 16).ok())
    };
    match raw.as_bytes().get(i + 1) {
        Some(b'n') => ('\n', i + 2),
        Some(b'r') => ('\r', i + 2),
        Some(b't') => ('\t', i + 2),
        Some(b'b' | b'f') => (' ', i + 2),
        Some(b'u') => match hex(i + 2) {
            Some(hi @ 0xD800..=0xDBFF)
                if raw.get(i + 6..i + 8) == Some("\\u")
                    && hex(i + 8).is_some_and(|lo| (0xDC00..=0xDFFF).contains(&lo)) =>
            {
                let lo = hex(i + 8).unwrap_or(0xDC00);
                let c = 0x10000 + ((hi - 0xD800) << 10) + (lo - 0xDC00);
                (char::from_u32(c).unwrap_or('\u{fffd}'), i + 12)
            }
            Some(u) => (char::from_u32(u).unwrap_or('\u{fffd}'), i + 6),
            None => ('\u{fffd}', (i + 2).min(raw.len())),
        },
        Some(&c) if c.is_ascii() => (c as char, i + 2),
        _ => ('\\', i + 1),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escapes_keep_each_token_at_its_place() {
        let raw = r#"x := 1;\r\n// a \"c\"\r\ny := 'a\"b';\tz := 2;"#;
        let t = decode_in_place(raw);
        assert_eq!(t.len(), raw.len());
        // outside strings every character stays where its JSON is
        assert_eq!(&t[raw.find("y :=").unwrap()..][..4], "y :=");
        // inside a string no blank is added; after it the text is at its place again
        assert!(t.contains("'a\"b'"), "{t}");
        assert_eq!(&t[raw.find("z :=").unwrap()..][..4], "z :=");
        assert!(t.is_char_boundary(t.len()));
        // a hostile string: never panics, never longer than the JSON
        for raw in [r"\u12", r"\ud800\u", "'\\u00e9\\u00e9", r"\", "é\\"] {
            assert!(decode_in_place(raw).len() <= raw.len().max(3), "{raw}");
        }
    }

    #[test]
    fn only_v4_projects_are_read() {
        let mut diags = Diagnostics::new();
        assert!(read(FileId(0), r#"{"name": "x"}"#, "x.json", &mut diags).is_none());
        assert!(read(FileId(0), r#"{"meta": "#, "x.json", &mut diags).is_none());
        let codes: Vec<_> = diags.iter().map(|d| (d.code, d.span.is_some())).collect();
        assert_eq!(codes, [(code::E1074, true), (code::E1074, true)]);
    }
}
