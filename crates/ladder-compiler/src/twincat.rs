//! TwinCAT 3 source files: the one-object-per-file XML that TwinCAT 3's PLC projects keep on disk
//! (`NAME.TcPOU`, `NAME.TcDUT`, `NAME.TcGVL`, `NAME.TcIO`, `NAME.TcTTO`), root `<TcPlcObject>`, with
//! the declaration text in `<Declaration><![CDATA[...]]>` and an ST body in
//! `<Implementation><ST><![CDATA[...]]>`; a POU's `<Method>`, `<Action>` and `<Property>` children
//! carry their own declaration and implementation the same way.
//!
//! Input: the XML text of one file. Output: for a POU, DUT, GVL or interface, the same text as IEC
//! 61131-3 source (as [`crate::codesys_v2`]): every byte outside the declaration and body texts
//! blanked (line breaks kept, so every line and column is the file's own), with `END_METHOD`,
//! `END_PROGRAM`/`END_FUNCTION_BLOCK`/`END_FUNCTION`, the `ACTIONS` block's keywords and
//! `END_INTERFACE` (after an interface's `<Method>` declarations, each closed by `END_METHOD`) written into blank places of the markup after the texts they close; for a GVL also
//! its name (its members are reachable qualified, `GVL.x`); for a task (`.TcTTO`) its name, cycle
//! time, priority and the programs it calls. A body in LD or FBD (TwinCAT's network list `<NWL>`)
//! is read as ST by `twincat_nwl`, a body in CFC by `twincat_cfc`, a POU's body in SFC as
//! textual SFC by `twincat_sfc` (its `<Transition>` children the conditions it names), their tokens
//! written into the blank markup of their own elements (so a diagnostic points at the operand's or
//! box's line), after a VAR block of the temporaries they need; the words of a chart's condition
//! taken from a `<Transition>` object are written into the chart and listed in
//! [`TcObject::Source`]'s `moved`, so that a diagnostic in them is shown in the object. Invariants: never panics; an
//! action's or method's body in SFC is one located E0321 naming it, a graphical element not understood one located E0325/E0326,
//! an action whose networks need temporaries one E0327 (an action has no declarations); a file whose
//! root is not `<TcPlcObject>` gives `None`.

use crate::codesys_v2::{local_name, root_name, Source};
use crate::twincat_cfc;
use crate::twincat_nwl::{self, NwlBody};
use crate::twincat_sfc::{self, TransitionObject};
use crate::xml::{self, Element};
use diagnostics::{code, Diagnostic, FileId, Span};

/// What a TwinCAT 3 object file holds, read.
#[derive(Debug, Clone, PartialEq)]
pub enum TcObject {
    /// A POU, DUT, GVL or interface (or an object without IEC text, such as a visualisation: blank)
    /// as IEC 61131-3 source, the file's length and line breaks kept.
    Source {
        /// The text, to be parsed as an `.st` file.
        text: String,
        /// The name of a global variable list (`<GVL Name="GVL_Main">`): its `VAR_GLOBAL` blocks are
        /// that list, so `GVL_Main.x` reaches a member.
        list: Option<String>,
        /// Notes on what was read otherwise than TwinCAT runs it (W0322: `AT %I*` variables read as
        /// plain variables), and the E0321 of a POU whose own body (SFC, IL) cannot be read: its
        /// declaration, its methods' and its properties' declarations are in `text` (callers are
        /// checked against them), its actions and the bodies are not.
        notes: Vec<Diagnostic>,
        /// Words written into the chart of an SFC body that stand elsewhere in the file (a
        /// condition taken from a `<Transition>` object), for
        /// `diagnostics::Diagnostics::read_moved`: a diagnostic in them is shown where they stand.
        moved: Vec<diagnostics::MovedText>,
    },
    /// A task (`.TcTTO`).
    Task(TcTask),
}

/// One TwinCAT task: `<Task Name="PlcTask"><CycleTime>10000</CycleTime><Priority>20</Priority>
/// <PouCall><Name>MAIN</Name></PouCall></Task>`.
#[derive(Debug, Clone, PartialEq)]
pub struct TcTask {
    /// The task's name.
    pub name: String,
    /// The `<Task>` start tag (byte range).
    pub span: (usize, usize),
    /// The cycle time in microseconds (`<CycleTime>`), when it is a positive integer.
    pub cycle_us: Option<u64>,
    /// `<Priority>`.
    pub priority: Option<u32>,
    /// The programs called, in order, with the byte range of each `<Name>`'s text.
    pub programs: Vec<(String, (usize, usize))>,
}

/// The object of a TwinCAT 3 file, or the E0321 that says why it cannot be read; `None` when the
/// file's root is not `<TcPlcObject>` (or the XML is not well-formed: the caller reports that).
pub fn object_source(file: FileId, text: &str) -> Option<Result<TcObject, Box<Diagnostic>>> {
    if root_name(text).is_none_or(|n| local_name(n) != "TcPlcObject") {
        return None;
    }
    let arena = xml::Arena::new();
    let (root, err) = xml::parse(text, &arena);
    if err.is_some() {
        return None;
    }
    let root = root?;
    let mut out = Source::blank(text);
    // the E0321 of a POU whose own body is refused (its declarations are kept)
    let mut refused: Vec<Diagnostic> = Vec::new();
    let mut list = None;
    // the declaration texts (byte ranges): bounds there may name a list's constant qualified
    let declarations: Vec<(usize, usize)> = root
        .walk()
        .filter(|e| e.name() == "Declaration")
        .map(|e| (e.tag_end(), e.end()))
        .collect();
    for obj in root.children {
        match obj.name() {
            "POU" => {
                if let Err(d) = pou(file, &mut out, obj, &mut refused) {
                    return Some(Err(d));
                }
            }
            "DUT" => {
                if let Some(d) = obj.child("Declaration") {
                    out.copy(d);
                }
            }
            "GVL" => {
                if let Some(d) = obj.child("Declaration") {
                    out.copy(d);
                }
                list = obj.attr("Name").map(str::to_string);
            }
            "Itf" => {
                if let Some(d) = obj.child("Declaration") {
                    let mut at = out.copy(d);
                    // its methods' declarations, each closed by END_METHOD, and its properties'
                    // (`PROPERTY P : T GET END_GET SET END_SET END_PROPERTY`, one accessor per
                    // `<Get>` / `<Set>`): their signatures are checked against the blocks that
                    // implement the interface, and calls through interface variables use them
                    let methods: Vec<&Element> = obj
                        .children
                        .iter()
                        .filter(|c| matches!(c.name(), "Method" | "Property"))
                        .collect();
                    let no_room = || {
                        unreadable(
                            file,
                            obj,
                            "TwinCAT interface has no room for its keywords".into(),
                            "check the file: its markup was changed by hand",
                        )
                    };
                    for (k, m) in methods.iter().enumerate() {
                        let Some(md) = m.child("Declaration") else {
                            continue;
                        };
                        let next = methods.get(k + 1).map_or(obj.end(), |n| n.tag_start());
                        at = out.copy(md);
                        if m.name() == "Property" {
                            let accessors = property_accessors(m);
                            for (j, acc) in accessors.iter().enumerate() {
                                let acc_next = accessors.get(j + 1).map_or(next, |n| n.tag_start());
                                let (open, close) = if acc.name() == "Get" {
                                    ("GET", "END_GET")
                                } else {
                                    ("SET", "END_SET")
                                };
                                let placed = out
                                    .place(at, acc_next, open)
                                    .and_then(|w| out.place(w, acc_next, close));
                                match placed {
                                    Some(w) => at = w,
                                    None => return Some(Err(no_room())),
                                }
                            }
                        }
                        let end = if m.name() == "Property" {
                            "END_PROPERTY"
                        } else {
                            "END_METHOD"
                        };
                        match out.place(at, next, end) {
                            Some(w) => at = w,
                            None => return Some(Err(no_room())),
                        }
                    }
                    out.place_last(at, "END_INTERFACE");
                }
            }
            "Task" => return Some(Ok(TcObject::Task(task(obj)))),
            _ => {}
        }
    }
    let moved = out.take_moved();
    let mut text = out.finish();
    let unlinked = unlink_io(&mut text);
    for &(s, e) in &declarations {
        unqualify_bounds(&mut text, s, e);
    }
    let notes = unlinked
        .first()
        .map(|&(s, e)| {
            Diagnostic::new(
                code::W0322,
                diagnostics::Severity::Note,
                format!(
                    "{} `AT %I*`/`%Q*`/`%M*` declaration(s) read as plain variables: TwinCAT links \
                     them to I/O in the system configuration (.tsproj), which ladderc does not read",
                    unlinked.len()
                ),
            )
            .at(Span::new(file, s, e))
            .with_hint(
                "set such inputs with --stimulus and read outputs with --watch, by the variable's \
                 name; write a full address (`AT %IX0.0`) to place one in the process image",
            )
        })
        .into_iter()
        .chain(refused)
        .collect();
    Some(Ok(TcObject::Source {
        text,
        list,
        notes,
        moved,
    }))
}

/// Blanks each `AT %I*`, `AT %Q*` and `AT %M*` of the IEC text (outside comments and strings),
/// so that the variable is a plain one, and writes `VAR PERSISTENT` as `VAR RETAIN`; returns the
/// byte ranges of the `AT` placeholders.
fn unlink_io(text: &mut String) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let n = b.len();
    let mut found = Vec::new();
    // `PERSISTENT` after VAR, VAR_GLOBAL (or RETAIN, CONSTANT): start, and whether RETAIN is written
    let mut persistent: Vec<(usize, bool)> = Vec::new();
    let mut prev_word: &[u8] = b"";
    let mut i = 0;
    while i < n {
        if let Some(after) = skip_comment_or_string(b, i, n) {
            i = after;
            continue;
        }
        match b[i] {
            c if c.is_ascii_alphabetic() || c == b'_' => {
                let start = i;
                while i < n && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                    i += 1;
                }
                let word = &b[start..i];
                if word.eq_ignore_ascii_case(b"PERSISTENT")
                    && [&b"VAR"[..], b"VAR_GLOBAL", b"RETAIN", b"CONSTANT"]
                        .iter()
                        .any(|w| prev_word.eq_ignore_ascii_case(w))
                {
                    let mut k = i;
                    while k < n && b[k].is_ascii_whitespace() {
                        k += 1;
                    }
                    let retain_next = b
                        .get(k..k + 6)
                        .is_some_and(|w| w.eq_ignore_ascii_case(b"RETAIN"));
                    persistent.push((
                        start,
                        retain_next || prev_word.eq_ignore_ascii_case(b"RETAIN"),
                    ));
                }
                prev_word = word;
                let word_is_at = i - start == 2 && word.eq_ignore_ascii_case(b"AT");
                let preceded = start == 0 || !b[start - 1].is_ascii_alphanumeric();
                if word_is_at && preceded {
                    let mut k = i;
                    while k < n && (b[k] == b' ' || b[k] == b'\t') {
                        k += 1;
                    }
                    if k + 2 < n
                        && b[k] == b'%'
                        && matches!(b[k + 1].to_ascii_uppercase(), b'I' | b'Q' | b'M')
                        && b[k + 2] == b'*'
                    {
                        found.push((start, k + 3));
                        i = k + 3;
                    }
                }
            }
            _ => i += 1,
        }
    }
    if !found.is_empty() || !persistent.is_empty() {
        let mut bytes = std::mem::take(text).into_bytes();
        for &(s, e) in &found {
            bytes[s..e].fill(b' ');
        }
        // PERSISTENT (TwinCAT, CODESYS: kept over a download too) is read as RETAIN, the same length
        for &(s, retain) in &persistent {
            let with: &[u8; 10] = if retain { b"          " } else { b"RETAIN    " };
            bytes[s..s + 10].copy_from_slice(with);
        }
        // only ASCII was blanked
        *text = String::from_utf8(bytes).unwrap_or_default();
    }
    found
}

/// Blanks the list name of each qualified constant (`GVL_Param.cMax` in `ARRAY[1..GVL_Param.cMax]`,
/// `STRING(GVL.N)`, `DINT(GVL.A..GVL.B)`) inside brackets and parentheses of the declaration text at
/// `start..end`, so the constant is looked up by its name among the constants of every file given
/// (the IEC bound grammar has no qualified names; positions stay the file's own). An initial value
/// (after `:=`, to the declaration's `;`) is left as written: its qualified names are variables
/// (`fb : FB := (p := ADR(GVL_IO.HWIO.Lamp))`, a path the checks resolve), not bounds.
fn unqualify_bounds(text: &mut String, start: usize, end: usize) {
    let b = text.as_bytes();
    let end = end.min(b.len());
    let mut blanks = Vec::new();
    let mut depth = 0usize;
    let mut in_initial_value = false;
    let mut i = start.min(end);
    while i < end {
        if let Some(after) = skip_comment_or_string(b, i, end) {
            i = after;
            continue;
        }
        match b[i] {
            b':' if depth == 0 && b.get(i + 1) == Some(&b'=') => {
                in_initial_value = true;
                i += 2;
            }
            b';' if depth == 0 => {
                in_initial_value = false;
                i += 1;
            }
            b'{' => i = find_from(b, i + 1, b"}").map_or(end, |e| e + 1),
            b'[' | b'(' => {
                depth += 1;
                i += 1;
            }
            b']' | b')' => {
                depth = depth.saturating_sub(1);
                i += 1;
            }
            c if c.is_ascii_alphabetic() || c == b'_' => {
                let word = i;
                while i < end && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                    i += 1;
                }
                let next_is_name = b
                    .get(i + 1)
                    .is_some_and(|c| c.is_ascii_alphabetic() || *c == b'_');
                if depth > 0 && !in_initial_value && b.get(i) == Some(&b'.') && next_is_name {
                    blanks.push((word, i + 1));
                    i += 1;
                }
            }
            _ => i += 1,
        }
    }
    if !blanks.is_empty() {
        let mut bytes = std::mem::take(text).into_bytes();
        for (s, e) in blanks {
            bytes[s..e].fill(b' ');
        }
        *text = String::from_utf8(bytes).unwrap_or_default();
    }
}

/// Where the comment (`(* ... *)`, `// ...`) or string (`'...'`, `"..."`, with `$` escapes, ending at
/// its line at the latest) that starts at `i` ends: the index just after it (`end` when a comment is not
/// closed); `None` when none starts at `i`.
fn skip_comment_or_string(b: &[u8], i: usize, end: usize) -> Option<usize> {
    match b[i] {
        b'(' if b.get(i + 1) == Some(&b'*') => {
            Some(find_from(b, i + 2, b"*)").map_or(end, |e| e + 2))
        }
        b'/' if b.get(i + 1) == Some(&b'/') => Some(find_from(b, i + 2, b"\n").unwrap_or(end)),
        q @ (b'\'' | b'"') => {
            let mut k = i + 1;
            while k < end && b[k] != q && b[k] != b'\n' {
                k += if b[k] == b'$' { 2 } else { 1 };
            }
            Some(k + 1)
        }
        _ => None,
    }
}

/// The offset of `pat` in `b` at or after `from`.
fn find_from(b: &[u8], from: usize, pat: &[u8]) -> Option<usize> {
    b.get(from..)?
        .windows(pat.len())
        .position(|w| w == pat)
        .map(|p| p + from)
}

/// The task of a `<Task>` element.
fn task(el: &Element) -> TcTask {
    let number = |name: &str| el.child(name).map(|c| c.text_ref().trim().to_string());
    TcTask {
        name: el.attr("Name").unwrap_or("PlcTask").to_string(),
        span: (el.tag_start(), el.tag_end()),
        cycle_us: number("CycleTime")
            .and_then(|t| t.parse::<u64>().ok())
            .filter(|&c| c > 0),
        priority: number("Priority").and_then(|t| t.parse::<u32>().ok()),
        programs: el
            .children_named("PouCall")
            .filter_map(|c| c.child("Name"))
            .map(|n| {
                let raw = n.text_ref();
                let name = raw.trim().to_string();
                let lead = raw.len() - raw.trim_start().len();
                let start = n.tag_end() + lead;
                (name.clone(), (start, start + name.len()))
            })
            .filter(|(n, _)| !n.is_empty())
            .collect(),
    }
}

/// The first word of a declaration, upper case, after blanks, pragmas (`{attribute ...}`) and
/// comments (`(* *)`, which nest as in IEC 61131-3 edition 3 and TwinCAT, `/* */`, `//`).
fn first_keyword(text: &str) -> String {
    let mut rest = text;
    loop {
        rest = rest.trim_start();
        if let Some(r) = rest.strip_prefix('{') {
            rest = r.find('}').map_or("", |e| &r[e + 1..]);
        } else if rest.starts_with("(*") {
            rest = after_nested_comment(rest);
        } else if let Some(r) = rest.strip_prefix("/*") {
            rest = r.find("*/").map_or("", |e| &r[e + 2..]);
        } else if let Some(r) = rest.strip_prefix("//") {
            rest = r.find('\n').map_or("", |e| &r[e..]);
        } else {
            break;
        }
    }
    rest.split(|c: char| !c.is_ascii_alphanumeric() && c != '_')
        .next()
        .unwrap_or("")
        .to_ascii_uppercase()
}

/// The text after the `(* ... *)` comment `text` starts with, comments inside it nested (`(* a (* b
/// *) c *)` ends after `c *)`); empty when it does not end.
fn after_nested_comment(text: &str) -> &str {
    let b = text.as_bytes();
    let mut depth = 0usize;
    let mut i = 0;
    while i + 1 < b.len() {
        match (b[i], b[i + 1]) {
            (b'(', b'*') => {
                depth += 1;
                i += 2;
            }
            (b'*', b')') => {
                depth -= 1;
                i += 2;
                if depth == 0 {
                    return &text[i..];
                }
            }
            _ => i += 1,
        }
    }
    ""
}

/// Copies a `<POU>`: its declaration and body, its methods (and properties, which the ST front end
/// reports) before the POU's end keyword, its actions in an `ACTIONS` block after it.
/// A POU's texts into `out`. A body of its own that cannot be read (SFC, IL) is its E0321 pushed on
/// `refused`: the POU, its methods and properties are written with their declarations alone (so
/// callers are checked against their signatures, not against nothing: one error for one cause),
/// its actions (which may use the SFC's steps) not at all. An action or method whose body cannot
/// be read is written without it, its E0321 pushed on `refused`.
fn pou(
    file: FileId,
    out: &mut Source,
    el: &Element,
    refused: &mut Vec<Diagnostic>,
) -> Result<(), Box<Diagnostic>> {
    let name = el.attr("Name").unwrap_or("?").to_string();
    let Some(decl) = el.child("Declaration") else {
        return Err(unreadable(
            file,
            el,
            format!("TwinCAT POU `{name}` has no <Declaration>"),
            HINT_DECLARATION,
        ));
    };
    let header = decl.text_ref();
    let (end_keyword, has_methods) = match first_keyword(&header).as_str() {
        "PROGRAM" => ("END_PROGRAM", true),
        "FUNCTION_BLOCK" => ("END_FUNCTION_BLOCK", true),
        "FUNCTION" => ("END_FUNCTION", false),
        _ => {
            return Err(unreadable(
                file,
                decl,
                format!(
                    "TwinCAT POU `{name}`: its <Declaration> does not begin with PROGRAM, \
                     FUNCTION_BLOCK or FUNCTION"
                ),
                HINT_DECLARATION,
            ))
        }
    };
    let mut at = out.copy(decl);
    let declarations_only = match body_of(file, el, &name, true) {
        Ok(Some(body)) => {
            at = write_body(file, out, at, &body, true)?;
            false
        }
        Ok(None) => false,
        Err(d) if d.code == code::E0321 => {
            refused.push(*d);
            true
        }
        Err(d) => return Err(d),
    };
    let members: Vec<&Element> = el
        .children
        .iter()
        .filter(|c| matches!(c.name(), "Method" | "Action" | "Property"))
        .filter(|c| !(declarations_only && c.name() == "Action"))
        .collect();
    // an action that comes before a method of a function block or a program is written as a
    // method without parameters (the POU's end must follow its last method); else actions follow
    // the POU's end
    let last_method = members
        .iter()
        .rposition(|m| m.name() != "Action")
        .map_or(0, |k| k + 1);
    let no_room = || {
        unreadable(
            file,
            el,
            format!("TwinCAT POU `{name}` has no room for its keywords"),
            "check the file: its markup was changed by hand",
        )
    };
    let mut in_actions = false;
    for (k, m) in members.iter().enumerate() {
        let m_name = m.attr("Name").unwrap_or("?");
        let what = format!("{name}.{m_name}");
        let next = members.get(k + 1).map_or(el.end(), |n| n.tag_start());
        match m.name() {
            "Action" => {
                // an action in SFC is written without its body (a call of it stays one), its
                // E0321 kept
                let body = match body_of(file, m, &what, false) {
                    Err(d) if d.code == code::E0321 => {
                        refused.push(*d);
                        None
                    }
                    b => b?,
                };
                // the keywords go into the markup before the body's text
                let limit = body.as_ref().map_or(next, Body::tag_end);
                if k >= last_method || !has_methods {
                    if !in_actions {
                        at = out
                            .place(at, limit, end_keyword)
                            .and_then(|w| out.place(w, limit, "ACTIONS"))
                            .ok_or_else(no_room)?;
                        in_actions = true;
                    }
                    at = out
                        .place(at, limit, &format!("ACTION {m_name}:"))
                        .ok_or_else(no_room)?;
                } else {
                    at = out
                        .place(at, limit, &format!("METHOD {m_name}"))
                        .ok_or_else(no_room)?;
                }
                if let Some(body) = body {
                    at = write_body(file, out, at, &body, false)?;
                }
                let end = if in_actions {
                    "END_ACTION"
                } else {
                    "END_METHOD"
                };
                at = out.place(at, next, end).ok_or_else(no_room)?;
            }
            "Method" => {
                if let Some(d) = m.child("Declaration") {
                    at = out.copy(d);
                }
                if !declarations_only {
                    match body_of(file, m, &what, true) {
                        Ok(Some(body)) => at = write_body(file, out, at, &body, true)?,
                        Ok(None) => {}
                        Err(d) if d.code == code::E0321 => refused.push(*d),
                        Err(d) => return Err(d),
                    }
                }
                at = out.place(at, next, "END_METHOD").ok_or_else(no_room)?;
            }
            _ => {
                // a PROPERTY: its declaration, then `GET <declaration> <body> END_GET` and the same
                // for `SET` (the ST front end compiles them as methods of a function block)
                if let Some(d) = m.child("Declaration") {
                    at = out.copy(d);
                }
                let accessors = property_accessors(m);
                for (j, acc) in accessors.iter().enumerate() {
                    let (open, close) = if acc.name() == "Get" {
                        ("GET", "END_GET")
                    } else {
                        ("SET", "END_SET")
                    };
                    let acc_next = accessors.get(j + 1).map_or(next, |n| n.tag_start());
                    let what = format!("{what}.{}", acc.name());
                    let decl = acc.child("Declaration");
                    let body = if declarations_only {
                        None
                    } else {
                        body_of(file, acc, &what, true)?
                    };
                    let limit = decl
                        .map(|d| d.tag_end())
                        .or(body.as_ref().map(Body::tag_end))
                        .unwrap_or(acc_next);
                    at = out.place(at, limit, open).ok_or_else(no_room)?;
                    if let Some(d) = decl {
                        at = out.copy(d);
                    }
                    if let Some(body) = body {
                        at = write_body(file, out, at, &body, true)?;
                    }
                    at = out.place(at, acc_next, close).ok_or_else(no_room)?;
                }
                at = out.place(at, next, "END_PROPERTY").ok_or_else(no_room)?;
            }
        }
    }
    if in_actions {
        out.place_last(at, "END_ACTIONS");
    } else {
        out.place_last(at, end_keyword);
    }
    Ok(())
}

/// A body of a POU, method or action.
enum Body<'e, 'a> {
    /// An ST text element (`<ST>`), copied in place.
    St(&'e Element<'a>),
    /// An LD/FBD network list (`<NWL>`) or a CFC chart (`<CFC>`) read as ST tokens, written into
    /// its own markup.
    Graph(&'e Element<'a>, NwlBody),
}

impl Body<'_, '_> {
    /// The end of the body's start tag (keywords before the body go before it).
    fn tag_end(&self) -> usize {
        match self {
            Body::St(e) | Body::Graph(e, _) => e.tag_end(),
        }
    }
}

/// The body of `el`'s `<Implementation>`: ST, LD/FBD (`<NWL>`, read by [`crate::twincat_nwl`]),
/// CFC (`<CFC>`, read by [`crate::twincat_cfc`]) or, for a POU, SFC (`<SFC>`, read by
/// [`crate::twincat_sfc`]); `declares`: whether the body can declare variables
/// (not an action's); `Ok(None)` without one; E0321 for a body in another language.
fn body_of<'e, 'a>(
    file: FileId,
    el: &'e Element<'a>,
    what: &str,
    declares: bool,
) -> Result<Option<Body<'e, 'a>>, Box<Diagnostic>> {
    let Some(imp) = el.child("Implementation") else {
        return Ok(None);
    };
    let Some(lang) = imp.children.first() else {
        return Ok(None);
    };
    if lang.name() == "ST" {
        return Ok(Some(Body::St(lang)));
    }
    if lang.name() == "NWL" {
        return Ok(Some(Body::Graph(
            lang,
            twincat_nwl::lower(file, lang, what, declares)?,
        )));
    }
    if lang.name() == "CFC" {
        return Ok(Some(Body::Graph(
            lang,
            twincat_cfc::lower(file, lang, what)?,
        )));
    }
    if lang.name() == "SFC" && declares && el.name() == "POU" {
        // the POU's transition objects, which the chart's transitions may name: an ST body, or
        // an LD/FBD one (x-PPU's `TAbort`, one FBD network assigning the transition's name; IEC
        // 61131-3 ed. 3 8.3.3 allows a transition condition in LD or FBD) read as its ST
        // statement when it needs no temporary (else the chart's E0321 says it is no expression)
        let objects: Vec<TransitionObject> = el
            .children_named("Transition")
            .map(|t| transition_object(file, t, what))
            .collect();
        return Ok(Some(Body::Graph(
            lang,
            twincat_sfc::lower(file, lang, what, &objects, el)?,
        )));
    }
    // SFC of an action or method, IL (TwinCAT's own forms)
    let language = lang.name();
    Err(unreadable(
        file,
        lang,
        format!(
            "TwinCAT object file: the body of `{what}` is in {language}, which ladderc cannot read in \
             a TwinCAT source file (it reads ST, LD/FBD and CFC bodies)"
        ),
        "export the POU from TwinCAT as PLCopen XML (right-click > Export PLCopenXML) and give \
         ladderc that file: it reads LD, FBD and SFC there",
    ))
}

/// A `<Transition>` object of the POU `what`, for [`twincat_sfc`]: its ST text where it stands
/// in the file (when the text is one piece of it), or its LD/FBD network read as ST (x-PPU's
/// `TAbort`, one FBD network assigning the transition's name; IEC 61131-3 ed. 3 8.3.3 allows a
/// transition condition in LD or FBD), each token at its network element, when it needs no
/// temporary (else the chart's E0321 says it is no expression).
fn transition_object(file: FileId, t: &Element, what: &str) -> TransitionObject {
    let name = t.attr("Name").unwrap_or("").trim().to_string();
    let body = t.child("Implementation");
    match (
        body.and_then(|i| i.child("ST")),
        body.and_then(|i| i.child("NWL")),
    ) {
        (Some(st), _) => {
            let text = st.text();
            // one CDATA or text piece: the text is the file's, byte for byte, from its start
            let pieces = match st.segments() {
                [one] if one.text.len() == text.len() && one.end - one.start == text.len() => {
                    vec![(0, one.start, true)]
                }
                _ => Vec::new(),
            };
            TransitionObject { name, text, pieces }
        }
        (None, Some(nwl)) => {
            match twincat_nwl::lower(file, nwl, &format!("{what}.{name}"), false) {
                Ok(b) if b.temps.is_empty() => {
                    let mut text = String::new();
                    let mut pieces = Vec::with_capacity(b.toks.len());
                    for tok in &b.toks {
                        if !text.is_empty() {
                            text.push(' ');
                        }
                        pieces.push((text.len(), tok.at, false));
                        text.push_str(&tok.text);
                    }
                    TransitionObject { name, text, pieces }
                }
                _ => TransitionObject {
                    name,
                    ..TransitionObject::default()
                },
            }
        }
        (None, None) => TransitionObject {
            name,
            ..TransitionObject::default()
        },
    }
}

/// Writes a body into place from `at` (ST: its text where it is; LD/FBD: its temporaries' VAR
/// block when `declares`, then its tokens, each at or after the element it comes from, all inside
/// the `<NWL>` element; a token written after its element, because an earlier token stands
/// beyond it, is recorded as moved, so its diagnostics point at its element); the offset after it.
fn write_body(
    file: FileId,
    out: &mut Source,
    at: usize,
    body: &Body,
    declares: bool,
) -> Result<usize, Box<Diagnostic>> {
    let (nwl, lowered) = match body {
        Body::St(e) => return Ok(out.copy(e)),
        Body::Graph(e, l) => (e, l),
    };
    let fail = |what: &str| {
        Box::new(
            Diagnostic::error(
                code::E0327,
                format!("TwinCAT LD/FBD body: {what}"),
            )
            .at(Span::new(file, nwl.tag_start(), nwl.tag_end()))
            .with_hint("write the networks that use EN, branches, edges or jumps in ST, or the action as a METHOD"),
        )
    };
    let limit = nwl.end();
    let mut at = at.max(nwl.tag_start());
    let mut words: Vec<(String, usize, Option<usize>)> = Vec::new();
    if !lowered.temps.is_empty() {
        if !declares {
            return Err(fail(&format!(
                "the action `{}` has no declarations for the variables its networks need (EN, \
                 branches, edges, jumps)",
                lowered.what
            )));
        }
        words.push(("VAR".into(), 0, None));
        for (name, ty) in &lowered.temps {
            words.extend([
                (name.clone(), 0, None),
                (":".into(), 0, None),
                (ty.clone(), 0, None),
                (";".into(), 0, None),
            ]);
        }
        words.push(("END_VAR".into(), 0, None));
    }
    words.extend(lowered.toks.iter().map(|t| (t.text.clone(), t.at, t.from)));
    // a run of words that stand elsewhere in the file (a condition from a transition object) is
    // one text for the diagnostics placed there
    let mut group = 0u32;
    let mut moving = false;
    let mut late_at = None;
    for (text, pref, mut original) in words {
        let from = if pref > at && pref < limit { pref } else { at };
        // a word whose element lies before the words already written (a box's output operand,
        // written after the box's inputs, `fb(in := ..., out => x)`) cannot stand there: its
        // diagnostics are shown at its element (README "diagnostics": a network element's
        // diagnostic is located at that element)
        if original.is_none() && pref != 0 && pref < at && pref >= nwl.tag_start() {
            if late_at != Some(pref) {
                group += 1;
            }
            late_at = Some(pref);
            original = Some(pref);
        } else if late_at.take().is_some() {
            group += 1;
        }
        let mut place = |from: usize| match original {
            Some(o) => out.place_moved(from, limit, &text, o, group),
            None => out.place(from, limit, &text),
        };
        at = match place(from).or_else(|| place(at)) {
            Some(w) => w,
            None => return Err(fail(&format!("no room in the markup for `{text}`"))),
        };
        if moving && original.is_none() {
            group += 1;
        }
        moving = original.is_some();
    }
    Ok(at)
}

/// The hint of a POU that cannot be read for its declaration.
const HINT_DECLARATION: &str =
    "check the file: TwinCAT writes a POU's declaration text (PROGRAM, FUNCTION_BLOCK or FUNCTION) first";

fn unreadable(file: FileId, el: &Element, msg: String, hint: &str) -> Box<Diagnostic> {
    Box::new(
        Diagnostic::error(code::E0321, msg)
            .at(Span::new(file, el.tag_start(), el.tag_end()))
            .with_hint(hint),
    )
}

/// A `<Property>`'s `<Get>` and `<Set>` children, in file order.
fn property_accessors<'e, 'a>(property: &'e Element<'a>) -> Vec<&'e Element<'a>> {
    property
        .children
        .iter()
        .filter(|c| matches!(c.name(), "Get" | "Set"))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const FB: &str = "<?xml version=\"1.0\" encoding=\"utf-8\"?>
<TcPlcObject Version=\"1.1.0.1\">
  <POU Name=\"FB_Count\" Id=\"{1}\" SpecialFunc=\"None\">
    <Declaration><![CDATA[{attribute 'x'}
FUNCTION_BLOCK FB_Count
VAR n : INT; END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[n := n + 1;]]></ST>
    </Implementation>
    <Method Name=\"Reset\" Id=\"{2}\">
      <Declaration><![CDATA[METHOD Reset : BOOL
]]></Declaration>
      <Implementation>
        <ST><![CDATA[n := 0;]]></ST>
      </Implementation>
    </Method>
    <Action Name=\"Twice\" Id=\"{3}\">
      <Implementation>
        <ST><![CDATA[n := n * 2;]]></ST>
      </Implementation>
    </Action>
  </POU>
</TcPlcObject>";

    #[test]
    fn a_function_block_keeps_its_positions_and_gets_its_keywords() {
        let Some(Ok(TcObject::Source { text, list, .. })) = object_source(FileId(0), FB) else {
            panic!("a TwinCAT POU");
        };
        assert_eq!(list, None);
        assert_eq!(text.len(), FB.len());
        assert_eq!(text.lines().count(), FB.lines().count());
        let at = |s: &str| text.find(s).unwrap_or_else(|| panic!("{s} in {text}"));
        assert_eq!(at("n := n + 1;"), FB.find("n := n + 1;").unwrap_or(0));
        assert!(at("METHOD Reset") < at("n := 0;"));
        assert!(at("n := 0;") < at("END_METHOD"));
        assert!(at("END_METHOD") < at("END_FUNCTION_BLOCK"));
        assert!(at("END_FUNCTION_BLOCK") < at("ACTIONS"));
        assert!(at("ACTION Twice:") < at("n := n * 2;"));
        assert!(at("n := n * 2;") < at("END_ACTION "));
        assert!(text.trim_end().ends_with("END_ACTIONS"));
    }

    #[test]
    fn a_task_file_gives_its_cycle_time_and_programs() {
        let tto = "<?xml version=\"1.0\"?>\n<TcPlcObject><Task Name=\"PlcTask\"><CycleTime>5000</CycleTime>\
                   <Priority>20</Priority><PouCall><Name> MAIN </Name></PouCall></Task></TcPlcObject>";
        let Some(Ok(TcObject::Task(t))) = object_source(FileId(0), tto) else {
            panic!("a task");
        };
        assert_eq!(
            (t.name.as_str(), t.cycle_us, t.priority),
            ("PlcTask", Some(5000), Some(20))
        );
        let (name, (s, e)) = &t.programs[0];
        assert_eq!((name.as_str(), &tto[*s..*e]), ("MAIN", "MAIN"));
    }

    #[test]
    fn an_empty_network_list_and_an_sfc_body_are_one_located_error_and_other_roots_are_not_twincat()
    {
        let ld = "<TcPlcObject><POU Name=\"P\"><Declaration><![CDATA[PROGRAM P]]></Declaration>\
                  <Implementation><NWL><XmlArchive/></NWL></Implementation></POU></TcPlcObject>";
        let Some(Err(d)) = object_source(FileId(0), ld) else {
            panic!("an error");
        };
        assert_eq!(d.code, code::E0325);
        assert!(d.message.contains("no network list"), "{}", d.message);
        // an SFC body: its E0321, the declaration kept
        let sfc = ld.replace("NWL", "SFC");
        let Some(Ok(TcObject::Source { text, notes, .. })) = object_source(FileId(0), &sfc) else {
            panic!("the declaration and the error");
        };
        assert_eq!(notes.len(), 1);
        assert_eq!(notes[0].code, code::E0321);
        assert!(
            notes[0].message.contains("SFC body")
                && notes[0].message.contains("SFCImplementationObject"),
            "{}",
            notes[0].message
        );
        assert!(
            text.contains("PROGRAM P") && text.contains("END_PROGRAM"),
            "{text}"
        );
        assert!(object_source(FileId(0), "<project/>").is_none());
        assert_eq!(first_keyword("(* c *) // x\n {a 'b'} program P"), "PROGRAM");
        // nested comments (TwinCAT, edition 3) and C-style ones
        assert_eq!(
            first_keyword("(* a\n(* b *)\nc *)\n/* d */ FUNCTION_BLOCK F"),
            "FUNCTION_BLOCK"
        );
        assert_eq!(first_keyword("(* (* never closed *)"), "");
    }

    #[test]
    fn io_links_are_blanked_outside_comments_and_strings() {
        let mut text = "b AT %I* : BOOL; (* x AT %Q* *) s : STRING := 'AT %M*'; q  at\t%Q* : INT; r AT%I* : INT; cat %I*"
            .to_string();
        let found = unlink_io(&mut text);
        assert_eq!(found.len(), 3);
        assert!(text.starts_with("b        : BOOL;"), "{text}");
        assert!(text.contains("(* x AT %Q* *)") && text.contains("'AT %M*'"));
        assert!(
            text.contains("q         : INT; r       : INT;") && text.ends_with("cat %I*"),
            "{text}"
        );
        let mut text =
            "a : ARRAY[1..GVL_P.cMax] OF STRING(GVL.N); t : DINT(GVL.A..GVL.B); y := s.x;"
                .to_string();
        let len = text.len();
        unqualify_bounds(&mut text, 0, len);
        assert_eq!(
            text,
            "a : ARRAY[1..      cMax] OF STRING(    N); t : DINT(    A..    B); y := s.x;"
        );
        let mut text = "VAR_GLOBAL PERSISTENT x : INT; END_VAR VAR RETAIN PERSISTENT y : INT; END_VAR persistent := 1;".to_string();
        assert!(unlink_io(&mut text).is_empty());
        assert_eq!(text, "VAR_GLOBAL RETAIN     x : INT; END_VAR VAR RETAIN            y : INT; END_VAR persistent := 1;");
    }
}
