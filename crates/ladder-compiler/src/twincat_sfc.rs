//! A TwinCAT 3 SFC body (`<Implementation><SFC><XmlArchive>`: CODESYS's serialized object archive,
//! `SFCImplementationObject` > `SFCSegment` > `SFCElementList` of `SFCStep`, `SFCTransition`,
//! `SFCBranch`, `SFCJump` and `SFCMacro` objects) read as IEC 61131-3 textual SFC, so that the SFC
//! lowering of textual and PLCopen XML charts runs it (no second SFC engine).
//!
//! Input: the `<SFC>` element, the POU's `<Transition>` children (name and ST body) and the body's
//! name (for messages). Output: [`NwlBody`] tokens: `INITIAL_STEP`/`STEP name: action(qualifier);
//! END_STEP` and `TRANSITION FROM a TO b := condition; END_TRANSITION`, each at the offset of the
//! archive object it comes from (so a diagnostic points at the step's or transition's lines); the
//! words of a condition taken from a `<Transition>` object also carry where they stand in the
//! object (`Tok::from`: the word in its ST text, or its LD/FBD network's element), where
//! `twincat` has the diagnostics in them shown; first the mark
//! `crate::sfc::text::VENDOR_ORDER_MARK`, so that the chart runs in TwinCAT's "Processing Order
//! in SFC" (actions first, the transition check last: `crate::sfc::chart::ScanOrder`).
//! What the archive holds, read from the real files (the attributes of an object sit in
//! `<l2 n="Attributes">`, keyed by GUID, each with a `Value` and a `DefaultValue`):
//! - `38391c6d-...`: the name of a step, jump target, macro, branch or associated action; the
//!   condition of a transition (an ST expression, or the name of a `<Transition>` object);
//! - `7d894980-...`: the comment (ignored); `6844a48e-...`: a step is the initial step;
//! - `a6b08bd8-...`, `700a583f-...`, `a2621e18-...`: a step's entry, step (main) and exit action
//!   (CODESYS's step actions, written `__ENTRY`/`__ACTIVE`/`__EXIT`, see
//!   `il_frontend::st::sfc::VENDOR_QUALIFIERS`); `e174fc0d-...`: an IEC association's qualifier;
//! - `23bdaa98-...`: a branch is parallel (`TRUE`);
//! - a segment is a sequence; a branch holds segments side by side: an alternative branch when
//!   each segment begins with a transition (after a step); sequences that end with steps share
//!   the transition after the branch (one per step); a parallel branch (after a transition) when
//!   each segment begins with a step: the transition before it activates the first step of each
//!   (`TO (a, b)`), and the transition after it leaves the last steps of all at once
//!   (`FROM (x, y)`, IEC 61131-3 2.6.3 simultaneous divergence and convergence); a macro is its
//!   segment, in place.
//!
//! The archive carries its own table of attribute names (`SFCAttributeDescription`: GUID ->
//! `Identifier`, `MainAction`, `InitStep` ...): each GUID above must have the name ladderc reads it
//! as, and an attribute ladderc does not read is named by it in the error.
//!
//! Invariants: never guesses: any other attribute whose value is not its default, an embedded
//! (unnamed) action or transition, a parallel branch's sequence that does not end with one step, a
//! timed qualifier (its duration's attribute
//! is not known), an element out of sequence or a jump to no step is one located E0321 naming it.

use crate::twincat_nwl::{tok, NwlBody, Tok};
use crate::xml::Element;
use diagnostics::{code, Diagnostic, FileId, Span};

type Res<T> = Result<T, Box<Diagnostic>>;

const NAME: &str = "38391c6d-6d4a-42f8-8ee7-9f45e5adafa8";
const COMMENT: &str = "7d894980-aeea-405c-a0f6-e2b26429c58f";
const INITIAL: &str = "6844a48e-46c2-4cc8-a185-a478f3b99cc0";
const ENTRY: &str = "a6b08bd8-b696-47e3-9cbf-7408b61c9ff8";
const ACTIVE: &str = "700a583f-b4d4-43e4-8c14-629c7cd3bec8";
const EXIT: &str = "a2621e18-7de3-4ea6-ae6d-89e9e0b7befd";
const QUALIFIER: &str = "e174fc0d-80b0-4a9e-a530-ca239c249a50";
const PARALLEL: &str = "23bdaa98-72ec-41f7-817b-9dede5697086";

/// The hint of a transition condition that is not one expression.
const HINT_CONDITION: &str =
    "write the condition as one ST expression (or a transition object holding one)";

/// A `<Transition>` object of the POU, which a transition of the chart names: its condition as
/// ST text, and where each piece of that text stands in the file.
#[derive(Debug, Default)]
pub(crate) struct TransitionObject {
    /// The object's name (`Name` attribute).
    pub name: String,
    /// Its ST text (`Name := expr;` or an expression), or its LD/FBD network's tokens joined by
    /// blanks.
    pub text: String,
    /// Pieces of `text` read from one place of the file, in order: (offset in `text`, offset in the
    /// file, whether the piece is the file's text there byte for byte: an ST text; a network's token
    /// stands at its element). None: the text's place is not known.
    pub pieces: Vec<(usize, usize, bool)>,
}

impl TransitionObject {
    /// Where byte `pos` of [`TransitionObject::text`] stands in the file.
    fn file_offset(&self, pos: usize) -> Option<usize> {
        let k = self.pieces.partition_point(|p| p.0 <= pos).checked_sub(1)?;
        let (start, at, same) = self.pieces[k];
        Some(if same { at + (pos - start) } else { at })
    }

    /// The byte range of the condition in `body` (the object's text with its comments blanked,
    /// [`strip_comments`]): blanks and a trailing `;` dropped, and the `Name :=` that assigns the
    /// transition's own name.
    fn condition_range(&self, body: &str) -> (usize, usize) {
        let trimmed = |s: usize, e: usize| {
            let part = body.get(s..e).unwrap_or("");
            let lead = part.len() - part.trim_start().len();
            (s + lead, s + part.trim_end().len())
        };
        let (mut s, mut e) = trimmed(0, body.len());
        if body.get(..e).is_some_and(|b| b.ends_with(';')) {
            (s, e) = trimmed(s, e - 1);
        }
        let name = self.name.as_str();
        let assigned = body
            .get(s..s + name.len())
            .filter(|p| !name.is_empty() && p.eq_ignore_ascii_case(name))
            .and_then(|_| {
                let rest = body.get(s + name.len()..e)?;
                let after = rest.trim_start().strip_prefix(":=")?;
                Some(e - after.len())
            });
        if let Some(from) = assigned {
            (s, e) = trimmed(from, e);
        }
        (s, e)
    }
}

/// One attribute of an archive object: its GUID, value and default (unquoted), and the offset of
/// its `Value`.
struct Attr {
    guid: String,
    value: String,
    default: String,
    at: usize,
}

/// A step of the chart.
struct StepOut {
    name: String,
    initial: bool,
    at: usize,
    /// (action name, qualifier as written into the text)
    actions: Vec<(String, String)>,
}

/// A transition of the chart: from one step, or from the last steps of a parallel branch's
/// sequences (their simultaneous convergence), to one step, or to the first steps of a parallel
/// branch's sequences (its simultaneous divergence).
struct TransOut {
    from: Vec<usize>,
    to: Vec<usize>,
    /// The jump target when it ends in a jump (resolved once every step is known).
    jump: Option<(String, usize)>,
    cond: Vec<Tok>,
    at: usize,
}

/// Where the sequence being read stands.
#[derive(Clone)]
enum Open {
    /// At the start of the chart: nothing before.
    Start,
    /// After a step, or after the steps that end the sequences of an alternative branch: the next
    /// transition leaves them (one transition per step, as CODESYS merges them).
    Steps(Vec<usize>),
    /// After transitions (of one or more branches): the next step is where they lead.
    Trans(Vec<usize>),
    /// After a parallel branch: the steps that end its sequences; the next transition leaves them
    /// all at once (IEC 61131-3 2.6.3, simultaneous convergence).
    Parallel(Vec<usize>),
    /// After a jump: the sequence ends.
    Closed,
}

struct Reader<'t> {
    file: FileId,
    what: &'t str,
    /// The archive's own table of attribute names (`SFCAttributeDescription`: GUID -> identifier).
    names: Vec<(String, String)>,
    /// The POU's `<Transition>` objects.
    objects: &'t [TransitionObject],
    steps: Vec<StepOut>,
    trans: Vec<TransOut>,
}

/// Reads the `<SFC>` element `sfc` of the body named `what`; `objects`: the POU's `<Transition>`
/// children.
pub(crate) fn lower(
    file: FileId,
    sfc: &Element,
    what: &str,
    objects: &[TransitionObject],
    pou: &Element,
) -> Res<NwlBody> {
    let flags = flags(pou);
    let root = sfc
        .child("XmlArchive")
        .and_then(|a| a.child("Data"))
        .and_then(|d| d.children.iter().find(|o| o.name() == "o"))
        .filter(|o| o.attr("t") == Some("SFCImplementationObject"));
    let Some(root) = root else {
        return Err(fail(
            file,
            sfc,
            format!("the SFC body of `{what}` holds no SFCImplementationObject archive"),
        ));
    };
    let Some(segment) = root
        .children
        .iter()
        .find(|o| o.name() == "o" && o.attr("n") == Some("Root"))
    else {
        return Err(fail(
            file,
            root,
            format!("the SFC body of `{what}` has no root segment"),
        ));
    };
    let names = descriptions(sfc);
    // the archive's table names the attributes ladderc reads as it reads them, or it is not read
    for (guid, meaning) in [
        (NAME, "Name"),
        (COMMENT, "Comment"),
        (INITIAL, "InitStep"),
        (ENTRY, "EntryAction"),
        (ACTIVE, "MainAction"),
        (EXIT, "ExitAction"),
        (QUALIFIER, "Qualifier"),
        (PARALLEL, "Parallel"),
    ] {
        if let Some((_, id)) = names.iter().find(|(g, _)| g == guid) {
            if !id.eq_ignore_ascii_case(meaning) {
                return Err(fail(
                    file,
                    root,
                    format!(
                        "the archive of `{what}` names attribute {{{guid}}} `{id}`, which ladderc \
                         reads as `{meaning}`"
                    ),
                ));
            }
        }
    }
    let mut r = Reader {
        file,
        what,
        names,
        objects,
        steps: Vec::new(),
        trans: Vec::new(),
    };
    let end = r.segment(segment, Open::Start)?;
    if let Open::Trans(open) = end {
        let t = &r.trans[open[0]];
        return Err(Box::new(
            Diagnostic::error(
                code::E0321,
                format!(
                    "TwinCAT SFC body of `{what}`: the chart ends with a transition that leads to no \
                     step"
                ),
            )
            .at(Span::new(file, t.at, t.at))
            .with_hint("end the sequence with a jump to a step"),
        ));
    }
    // jumps: to a step of the chart by name
    for k in 0..r.trans.len() {
        if let Some((target, at)) = r.trans[k].jump.take() {
            let Some(s) = r
                .steps
                .iter()
                .position(|s| s.name.eq_ignore_ascii_case(&target))
            else {
                return Err(Box::new(
                    Diagnostic::error(
                        code::E0321,
                        format!(
                            "TwinCAT SFC body of `{what}`: a jump to `{target}`, which is no step of \
                             the chart"
                        ),
                    )
                    .at(Span::new(file, at, at))
                    .with_hint("jump to the name of a step of the same chart"),
                ));
            };
            r.trans[k].to = vec![s];
        }
    }
    let mut body = r.text();
    // the chart's enabled flags, for the SFC lowering (`crate::sfc::text`), and the variables
    // TwinCAT declares for them when the POU does not (so its methods and actions can use them)
    let declaration = pou
        .child("Declaration")
        .map(|d| d.text())
        .unwrap_or_default();
    // a TwinCAT chart runs in TwinCAT's processing order (actions first, transition check last)
    let mut head = vec![Tok {
        text: crate::sfc::text::VENDOR_ORDER_MARK.to_string(),
        at: 0,
        from: None,
    }];
    for (name, declare, at) in flags {
        let var = format!("SFC{name}");
        head.push(Tok {
            text: format!(
                "(*{} {name} {} {at}*)",
                crate::sfc::text::FLAG_MARK,
                u8::from(declare)
            ),
            at: 0,
            from: None,
        });
        if declare && !declares(&declaration, &var) {
            if let Some(ty) = flag_type(&name) {
                body.temps.push((var, ty.to_string()));
            }
        }
    }
    head.append(&mut body.toks);
    body.toks = head;
    Ok(body)
}

/// The type TwinCAT gives the variable of an SFC flag it declares implicitly (`Tip` -> `SFCTip`).
fn flag_type(flag: &str) -> Option<&'static str> {
    Some(match flag.to_ascii_lowercase().as_str() {
        "init" | "reset" | "pause" | "quiterror" | "error" | "trans" | "tip" | "tipmode"
        | "enablelimit" => "BOOL",
        "currentstep" | "errorstep" | "errorpou" => "STRING",
        _ => return None,
    })
}

/// Whether the declaration text declares `var` (`var :` or `var,` after a blank or line start).
fn declares(declaration: &str, var: &str) -> bool {
    let text = strip_comments(declaration).to_ascii_lowercase();
    let var = var.to_ascii_lowercase();
    let b = text.as_bytes();
    let mut from = 0;
    while let Some(k) = text[from..].find(&var) {
        let s = from + k;
        let e = s + var.len();
        let before = s == 0 || !(b[s - 1].is_ascii_alphanumeric() || b[s - 1] == b'_');
        let after = text[e..].trim_start();
        if before && (after.starts_with(':') && !after.starts_with(":=") || after.starts_with(','))
        {
            return true;
        }
        from = e;
    }
    false
}

/// The SFC flags the POU's settings enable (`<ObjectProperties>` > `SFCProperty` > `Flags`: a
/// flag's name, then its `Use` and `Declare`), each with whether TwinCAT declares its variable and
/// the offset of its name; settings that defer to the project's defaults (`UseDefaults`) are read
/// the same way: TwinCAT saves the defaults in force with the POU.
fn flags(pou: &Element) -> Vec<(String, bool, usize)> {
    let Some(prop) = pou
        .child("ObjectProperties")
        .and_then(|p| p.child("XmlArchive"))
        .and_then(|a| a.child("Data"))
        .and_then(|d| {
            d.children
                .iter()
                .find(|o| o.name() == "o" && o.attr("t") == Some("SFCProperty"))
        })
    else {
        return Vec::new();
    };
    let v = |o: &Element, n: &str| {
        o.children
            .iter()
            .find(|c| c.name() == "v" && c.attr("n") == Some(n))
            .map(|c| c.text_ref().trim().eq_ignore_ascii_case("true"))
    };
    // `UseDefaults` (the POU's "use defaults" box, ticked for every chart TwinCAT creates) defers
    // to the project's SFC settings, which TwinCAT copies into the properties of each SFC object
    // it creates (Beckhoff Infosys, PLC project properties, "Category SFC": "Each new SFC object
    // automatically has the configured settings in its properties") and saves beside the box:
    // the `Flags` list below is the settings in force, read as a POU's own; no list is TwinCAT's
    // factory setting, no flag used
    let mut out = Vec::new();
    for d in prop
        .children
        .iter()
        .filter(|c| c.name() == "d2" && c.attr("n") == Some("Flags"))
    {
        let mut name: Option<(String, usize)> = None;
        for c in d.children.iter() {
            match c.name() {
                "v" => name = Some((c.text_ref().trim().to_string(), c.tag_start())),
                "o" => {
                    if let Some((n, at)) = name.take() {
                        if v(c, "Use") == Some(true) && crate::values::is_ident(&n) {
                            let n = n.strip_prefix("SFC").unwrap_or(&n).to_string();
                            out.push((n, v(c, "Declare") == Some(true), at));
                        }
                    }
                }
                _ => {}
            }
        }
    }
    out
}

fn fail(file: FileId, el: &Element, msg: String) -> Box<Diagnostic> {
    Box::new(
        Diagnostic::error(code::E0321, format!("TwinCAT SFC body: {msg}"))
            .at(Span::new(file, el.tag_start(), el.tag_end()))
            .with_hint(
                "export the POU from TwinCAT as PLCopen XML (right-click > Export PLCopenXML) and \
                 give ladderc that file, or write the chart without it",
            ),
    )
}

/// The text of a `<v>`: a quoted string (`"..."`, backslash escapes) unquoted.
fn unquote(raw: &str) -> String {
    let t = raw.trim();
    let Some(inner) = t.strip_prefix('"').and_then(|t| t.strip_suffix('"')) else {
        return t.to_string();
    };
    let mut out = String::new();
    let mut chars = inner.chars();
    while let Some(c) = chars.next() {
        if c == '\\' {
            match chars.next() {
                Some('n') => out.push('\n'),
                Some('r') => out.push('\r'),
                Some('t') => out.push('\t'),
                Some(o) => out.push(o),
                None => {}
            }
        } else {
            out.push(c);
        }
    }
    out
}

/// The attributes of an archive object.
fn attributes(o: &Element) -> Vec<Attr> {
    let mut out = Vec::new();
    for list in o
        .children
        .iter()
        .filter(|c| c.name() == "l2" && c.attr("n") == Some("Attributes"))
    {
        for a in list.children.iter().filter(|c| c.name() == "o") {
            let v = |parent: &Element, n: &str| {
                parent
                    .children
                    .iter()
                    .find(|c| c.name() == "v" && c.attr("n") == Some(n))
                    .map(|c| (unquote(&c.text_ref()), c.tag_start()))
            };
            let Some((guid, _)) = v(a, "AttributeId") else {
                continue;
            };
            let value = a
                .children
                .iter()
                .find(|c| c.name() == "o" && c.attr("n") == Some("Value"));
            let (value, at) = value
                .and_then(|val| v(val, "Value"))
                .unwrap_or((String::new(), a.tag_start()));
            let default = a
                .children
                .iter()
                .find(|c| c.name() == "o" && c.attr("n") == Some("Value"))
                .and_then(|val| v(val, "DefaultValue"))
                .map(|d| d.0)
                .unwrap_or_default();
            out.push(Attr {
                guid: guid.trim_matches(['{', '}']).to_ascii_lowercase(),
                value,
                default,
                at,
            });
        }
    }
    out
}

/// The archive's table of attribute descriptions (`<d2 n="Attributes" cvt="SFCAttributeDescription">`:
/// a GUID, then its description with its `Identifier`), lower-case GUID and identifier.
fn descriptions(sfc: &Element) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for d in sfc
        .walk()
        .filter(|e| e.name() == "d2" && e.attr("cvt") == Some("SFCAttributeDescription"))
    {
        let mut guid: Option<String> = None;
        for c in d.children.iter() {
            match c.name() {
                "v" => {
                    guid = Some(
                        c.text_ref()
                            .trim()
                            .trim_matches(['{', '}'])
                            .to_ascii_lowercase(),
                    )
                }
                "o" => {
                    let id = c
                        .children
                        .iter()
                        .find(|v| v.name() == "v" && v.attr("n") == Some("Identifier"))
                        .map(|v| unquote(&v.text_ref()));
                    if let (Some(g), Some(id)) = (guid.take(), id) {
                        out.push((g, id));
                    }
                }
                _ => {}
            }
        }
    }
    out
}

/// The element list of an object (`<o n="ElementList"><l2 n="InnerList">` children), each with its
/// type: its own `t`, else the list's element type `cet` (the archive leaves out the `t` of an
/// element of the list's one type).
fn inner<'e, 'a>(o: &'e Element<'a>) -> Vec<(&'e Element<'a>, &'a str)> {
    o.children
        .iter()
        .filter(|c| c.name() == "o" && c.attr("n") == Some("ElementList"))
        .flat_map(|l| l.children.iter())
        .filter(|c| c.name() == "l2" && c.attr("n") == Some("InnerList"))
        .flat_map(|l| {
            let cet = l.attr("cet").unwrap_or("");
            l.children
                .iter()
                .filter(|c| c.name() == "o")
                .map(move |c| (c, c.attr("t").unwrap_or(cet)))
        })
        .collect()
}

impl Reader<'_> {
    fn err(&self, at: usize, msg: String, hint: &str) -> Box<Diagnostic> {
        Box::new(
            Diagnostic::error(
                code::E0321,
                format!("TwinCAT SFC body of `{}`: {msg}", self.what),
            )
            .at(Span::new(self.file, at, at))
            .with_hint(hint.to_string()),
        )
    }

    /// The attributes of `o` that ladderc reads (`known`, and the comment); any other one whose
    /// value is not its default is an error naming it.
    fn known_attributes(&self, o: &Element, kind: &str, known: &[&str]) -> Res<Vec<Attr>> {
        let attrs = attributes(o);
        for a in &attrs {
            if a.guid != COMMENT && !known.contains(&a.guid.as_str()) && a.value != a.default {
                let named = self
                    .names
                    .iter()
                    .find(|(g, _)| *g == a.guid)
                    .map_or(String::new(), |(_, n)| format!("`{n}` "));
                let what = if a.guid == PARALLEL {
                    "a parallel branch, which ladderc does not read in a TwinCAT chart".to_string()
                } else {
                    "which ladderc does not read".to_string()
                };
                return Err(self.err(
                    a.at,
                    format!(
                        "the {kind} has attribute {named}{{{}}} set to `{}`: {what}",
                        a.guid, a.value
                    ),
                    "clear that setting of the element in TwinCAT, or export the POU as PLCopen XML",
                ));
            }
        }
        Ok(attrs)
    }

    /// An embedded (unnamed) action or transition body (`<o n="EmbeddedMainAction">`): not read.
    fn no_embedded(&self, o: &Element, kind: &str) -> Res<()> {
        if let Some(e) = o
            .children
            .iter()
            .find(|c| c.name() == "o" && c.attr("n").is_some_and(|n| n.starts_with("Embedded")))
        {
            return Err(self.err(
                e.tag_start(),
                format!(
                    "the {kind} has an embedded body ({}), which ladderc does not read",
                    e.attr("n").unwrap_or("")
                ),
                "make the embedded body an action or transition of the POU and name it in the chart",
            ));
        }
        Ok(())
    }

    /// Reads the sequence of `segment` from `open`; where it stands after its last element.
    fn segment(&mut self, segment: &Element, mut open: Open) -> Res<Open> {
        for (o, kind) in inner(segment) {
            open = self.element(o, kind, open)?;
        }
        Ok(open)
    }

    fn element(&mut self, o: &Element, kind: &str, open: Open) -> Res<Open> {
        let at = o.tag_start();
        if matches!(open, Open::Closed) {
            return Err(self.err(
                at,
                format!("a {kind} follows a jump"),
                "a jump ends its sequence",
            ));
        }
        match kind {
            "SFCStep" => {
                let attrs =
                    self.known_attributes(o, "step", &[NAME, INITIAL, ENTRY, ACTIVE, EXIT])?;
                self.no_embedded(o, "step")?;
                let get = |g: &str| attrs.iter().find(|a| a.guid == g);
                let name = get(NAME)
                    .map(|a| a.value.trim().to_string())
                    .unwrap_or_default();
                if name.is_empty() {
                    return Err(self.err(at, "a step without a name".into(), "name the step"));
                }
                let initial = get(INITIAL).is_some_and(|a| a.value.eq_ignore_ascii_case("TRUE"));
                let mut actions = Vec::new();
                for (g, q) in [(ENTRY, "__ENTRY"), (ACTIVE, "__ACTIVE"), (EXIT, "__EXIT")] {
                    if let Some(a) = get(g).filter(|a| !a.value.trim().is_empty()) {
                        actions.push((a.value.trim().to_string(), q.to_string()));
                    }
                }
                for (assoc, _) in inner(o) {
                    let attrs =
                        self.known_attributes(assoc, "action association", &[NAME, QUALIFIER])?;
                    let get = |g: &str| attrs.iter().find(|a| a.guid == g);
                    let name = get(NAME)
                        .map(|a| a.value.trim().to_string())
                        .unwrap_or_default();
                    let q = get(QUALIFIER)
                        .map(|a| a.value.trim().to_ascii_uppercase())
                        .unwrap_or_default();
                    let q = if q.is_empty() { "N".to_string() } else { q };
                    if name.is_empty() {
                        return Err(self.err(
                            assoc.tag_start(),
                            "an action association without an action".into(),
                            "name the action",
                        ));
                    }
                    if !matches!(q.as_str(), "N" | "R" | "S" | "P" | "P0" | "P1") {
                        let why = if matches!(q.as_str(), "L" | "D" | "SD" | "DS" | "SL") {
                            "a timed qualifier, whose duration ladderc does not find in the archive"
                        } else {
                            "not an IEC action qualifier"
                        };
                        return Err(self.err(
                            assoc.tag_start(),
                            format!(
                                "the association of action `{name}` has qualifier `{q}`: {why}"
                            ),
                            "use N, S, R, P, P0 or P1, or export the POU as PLCopen XML",
                        ));
                    }
                    actions.push((name, q));
                }
                let k = self.steps.len();
                self.steps.push(StepOut {
                    name,
                    initial,
                    at,
                    actions,
                });
                match open {
                    Open::Start => {}
                    Open::Trans(ts) => {
                        for t in ts {
                            self.trans[t].to.push(k);
                        }
                    }
                    _ => {
                        return Err(self.err(
                            at,
                            format!(
                                "step `{}` follows a step without a transition",
                                self.steps[k].name
                            ),
                            "put a transition between two steps",
                        ))
                    }
                }
                Ok(Open::Steps(vec![k]))
            }
            "SFCTransition" => {
                let attrs = self.known_attributes(o, "transition", &[NAME])?;
                self.no_embedded(o, "transition")?;
                // after a step, or after the steps ending an alternative branch: one transition
                // from each (CODESYS merges them); after a parallel branch: one from them all
                let from: Vec<Vec<usize>> =
                    match open {
                        Open::Steps(from) => from.into_iter().map(|s| vec![s]).collect(),
                        Open::Parallel(from) => vec![from],
                        _ => return Err(self.err(
                            at,
                            "a transition that does not follow a step (two transitions in a row)"
                                .into(),
                            "put a step between two transitions",
                        )),
                    };
                let cond = attrs.iter().find(|a| a.guid == NAME);
                let (text, cat) = cond
                    .map(|a| (a.value.clone(), a.at))
                    .unwrap_or((String::new(), at));
                let cond = self.condition(&text, cat)?;
                let mut out = Vec::new();
                for from in from {
                    self.trans.push(TransOut {
                        from,
                        to: Vec::new(),
                        jump: None,
                        cond: cond.clone(),
                        at,
                    });
                    out.push(self.trans.len() - 1);
                }
                Ok(Open::Trans(out))
            }
            "SFCJump" => {
                let attrs = self.known_attributes(o, "jump", &[NAME])?;
                let target = attrs
                    .iter()
                    .find(|a| a.guid == NAME)
                    .map(|a| a.value.trim().to_string())
                    .unwrap_or_default();
                let Open::Trans(ts) = open else {
                    return Err(self.err(
                        at,
                        format!("a jump to `{target}` that does not follow a transition"),
                        "a jump ends a sequence after its transition",
                    ));
                };
                for t in ts {
                    self.trans[t].jump = Some((target.clone(), at));
                }
                Ok(Open::Closed)
            }
            "SFCMacro" => {
                // a macro shows part of the sequence folded into one box; it runs in place
                self.known_attributes(o, "macro", &[NAME])?;
                let Some(seg) = o
                    .children
                    .iter()
                    .find(|c| c.name() == "o" && c.attr("n") == Some("Segment"))
                else {
                    return Err(self.err(at, "a macro without a segment".into(), "check the file"));
                };
                self.segment(seg, open)
            }
            "SFCBranch" => {
                let attrs = self.known_attributes(o, "branch", &[NAME, PARALLEL])?;
                let segments = inner(o);
                if attrs
                    .iter()
                    .any(|a| a.guid == PARALLEL && a.value.trim().eq_ignore_ascii_case("TRUE"))
                {
                    return self.parallel(at, &segments, open);
                }
                let Open::Steps(ref before) = open else {
                    return Err(self.err(
                        at,
                        "an alternative branch that does not follow a step (a branch after a \
                         transition is parallel in TwinCAT)"
                            .into(),
                        "put the branch after a step, or make it parallel",
                    ));
                };
                if before.len() != 1 {
                    return Err(self.err(
                        at,
                        "a branch right after the steps that end another branch".into(),
                        "put a transition and a step between the two branches",
                    ));
                }
                // the sequences end with transitions (the branch's convergence is their common
                // next step), jumps, or steps (the transition after the branch leaves each)
                let mut after = Vec::new();
                let mut ends = Vec::new();
                for (seg, _) in segments {
                    let first = inner(seg).first().map_or("", |e| e.1);
                    if first != "SFCTransition" {
                        return Err(self.err(
                            seg.tag_start(),
                            format!(
                                "a branch whose sequence begins with {} (an alternative branch \
                                 begins each sequence with a transition)",
                                if first.is_empty() { "nothing" } else { first }
                            ),
                            "export the POU as PLCopen XML",
                        ));
                    }
                    match self.segment(seg, open.clone())? {
                        Open::Trans(ts) => after.extend(ts),
                        Open::Steps(ss) => ends.extend(ss),
                        _ => {}
                    }
                }
                match (after.is_empty(), ends.is_empty()) {
                    (true, true) => Ok(Open::Closed),
                    (false, true) => Ok(Open::Trans(after)),
                    (true, false) => Ok(Open::Steps(ends)),
                    (false, false) => Err(self.err(
                        at,
                        "an alternative branch some of whose sequences end with a step and others \
                         with a transition"
                            .into(),
                        "end every sequence of the branch alike",
                    )),
                }
            }
            other => Err(self.err(
                at,
                format!("an element of kind `{other}`, which ladderc does not read"),
                "export the POU as PLCopen XML",
            )),
        }
    }

    /// A parallel branch (IEC 61131-3 2.6.3, simultaneous divergence): after a transition, each
    /// sequence begins with a step that the transition activates, and ends with a step; the
    /// transition after the branch leaves the last steps of all sequences at once (simultaneous
    /// convergence). A sequence that ends in a jump or a transition is an error: its steps would
    /// never all be active for the convergence.
    fn parallel(&mut self, at: usize, segments: &[(&Element, &str)], open: Open) -> Res<Open> {
        let Open::Trans(before) = open else {
            return Err(self.err(
                at,
                "a parallel branch that does not follow a transition".into(),
                "a parallel branch begins after the transition that activates its sequences",
            ));
        };
        let mut ends = Vec::new();
        for (seg, _) in segments {
            let first = inner(seg).first().map_or("", |e| e.1);
            if first != "SFCStep" {
                return Err(self.err(
                    seg.tag_start(),
                    format!(
                        "a parallel branch whose sequence begins with {} (each sequence of a \
                         parallel branch begins with a step)",
                        if first.is_empty() { "nothing" } else { first }
                    ),
                    "begin the sequence with a step",
                ));
            }
            match self.segment(seg, Open::Trans(before.clone()))? {
                Open::Steps(ss) if ss.len() == 1 => ends.extend(ss),
                Open::Parallel(ss) => ends.extend(ss),
                _ => return Err(self.err(
                    seg.tag_start(),
                    "a sequence of a parallel branch that does not end with one step (it ends \
                         in a jump, a transition, or an alternative branch's steps)"
                        .into(),
                    "end each sequence of a parallel branch with one step: the transition after \
                         the branch leaves them all at once",
                )),
            }
        }
        if ends.is_empty() {
            return Err(self.err(
                at,
                "a parallel branch without sequences".into(),
                "check the file",
            ));
        }
        Ok(Open::Parallel(ends))
    }

    /// The tokens of a transition condition: the ST expression (a trailing `;` dropped), or the ST
    /// text of the `<Transition>` object it names (`Name := expr;` or an expression), each word of
    /// an object's text marked with where it stands in the file ([`Tok::from`]).
    fn condition(&self, text: &str, at: usize) -> Res<Vec<Tok>> {
        let t = text.trim();
        let Some(object) = self.objects.iter().find(|o| o.name.eq_ignore_ascii_case(t)) else {
            let body = strip_comments(t);
            let expr = body.trim().trim_end_matches(';').trim();
            if expr.is_empty() || expr.contains(';') || expr.contains(":=") {
                let what = if expr.is_empty() {
                    "a transition without a condition".to_string()
                } else {
                    format!("the transition condition `{t}` is not one boolean expression")
                };
                return Err(self.err(at, what, HINT_CONDITION));
            }
            return Ok(words(expr)
                .into_iter()
                .map(|(w, _)| Tok {
                    text: w,
                    at,
                    from: None,
                })
                .collect());
        };
        let body = strip_comments(&object.text);
        let (start, end) = object.condition_range(&body);
        let expr = body.get(start..end).unwrap_or("");
        if expr.is_empty() || expr.contains(';') || expr.contains(":=") {
            return Err(self.err(
                object.file_offset(start).unwrap_or(at),
                format!("the transition `{t}` is not one boolean expression"),
                HINT_CONDITION,
            ));
        }
        Ok(words(expr)
            .into_iter()
            .map(|(w, k)| Tok {
                text: w,
                at,
                from: object.file_offset(start + k),
            })
            .collect())
    }

    /// The textual chart, each element at its archive object.
    fn text(&self) -> NwlBody {
        let mut toks = Vec::new();
        // steps and transitions in archive order: transitions leaving one step keep their order
        // (a branch's sequences from left to right: CODESYS's priority)
        let mut items: Vec<(usize, bool, usize)> = self
            .steps
            .iter()
            .enumerate()
            .map(|(k, s)| (s.at, true, k))
            .chain(self.trans.iter().enumerate().map(|(k, t)| (t.at, false, k)))
            .collect();
        items.sort_by_key(|i| i.0);
        for (at, is_step, k) in items {
            if is_step {
                let s = &self.steps[k];
                toks.push(tok(if s.initial { "INITIAL_STEP" } else { "STEP" }, at));
                toks.push(tok(&s.name, at));
                toks.push(tok(":", at));
                for (a, q) in &s.actions {
                    toks.push(tok(&format!("{a}({q});"), at));
                }
                toks.push(tok("END_STEP", at));
            } else {
                let t = &self.trans[k];
                toks.push(tok("TRANSITION", at));
                toks.push(tok("FROM", at));
                self.step_list(&t.from, at, &mut toks);
                toks.push(tok("TO", at));
                self.step_list(&t.to, at, &mut toks);
                toks.push(tok(":=", at));
                toks.extend(t.cond.iter().cloned());
                toks.push(tok(";", at));
                toks.push(tok("END_TRANSITION", at));
            }
        }
        NwlBody {
            what: self.what.to_string(),
            temps: Vec::new(),
            toks,
        }
    }
}

impl Reader<'_> {
    /// The steps a transition leaves or activates: one name, or `(a, b)` for several.
    fn step_list(&self, steps: &[usize], at: usize, toks: &mut Vec<Tok>) {
        match steps {
            [] => toks.push(tok("?", at)),
            [one] => toks.push(tok(&self.steps[*one].name, at)),
            many => {
                toks.push(tok("(", at));
                for (k, s) in many.iter().enumerate() {
                    if k > 0 {
                        toks.push(tok(",", at));
                    }
                    toks.push(tok(&self.steps[*s].name, at));
                }
                toks.push(tok(")", at));
            }
        }
    }
}

/// `text` with its `(* *)` and `//` comments blanked, byte for byte (line breaks and strings
/// kept): every other byte stays at its offset.
fn strip_comments(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = b.to_vec();
    let mut blank = |from: usize, to: usize| {
        for c in &mut out[from.min(b.len())..to.min(b.len())] {
            if *c != b'\n' && *c != b'\r' {
                *c = b' ';
            }
        }
    };
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'(' if b.get(i + 1) == Some(&b'*') => {
                let end = text[i + 2..].find("*)").map_or(b.len(), |e| i + 2 + e + 2);
                blank(i, end);
                i = end;
            }
            b'/' if b.get(i + 1) == Some(&b'/') => {
                let end = text[i..].find('\n').map_or(b.len(), |e| i + e);
                blank(i, end);
                i = end;
            }
            q @ (b'\'' | b'"') => {
                i += 1;
                while i < b.len() && b[i] != q {
                    i += if b[i] == b'$' { 2 } else { 1 };
                }
                i += 1;
            }
            _ => i += 1,
        }
    }
    // only whole characters were blanked (comments begin and end at ASCII bytes)
    String::from_utf8(out).unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned())
}

/// The words of an expression, split at white space outside strings (each fits on a line), each
/// with its byte offset in `text`.
fn words(text: &str) -> Vec<(String, usize)> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut start = 0;
    let mut quote: Option<char> = None;
    for (k, c) in text.char_indices() {
        match quote {
            Some(q) => {
                cur.push(c);
                if c == q {
                    quote = None;
                }
            }
            None if c.is_whitespace() => {
                if !cur.is_empty() {
                    out.push((std::mem::take(&mut cur), start));
                }
            }
            None => {
                if cur.is_empty() {
                    start = k;
                }
                if c == '\'' || c == '"' {
                    quote = Some(c);
                }
                cur.push(c);
            }
        }
    }
    if !cur.is_empty() {
        out.push((cur, start));
    }
    out
}
