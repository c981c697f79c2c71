//! OpenPLC Editor v4 ladder POUs (`pous/programs/main.ld`): the POU's IEC declarations, then the
//! rungs as JSON (`{"name": "main", "rungs": [{"id", "comment", "nodes": [...], "edges": [...]}]}`,
//! the editor's React Flow graph), read as Structured Text.
//!
//! Input: the file's text and where its JSON starts (after the last `END_VAR`). Output: the same
//! text with the JSON blanked (line breaks kept) and ST written into the blanks, each token at or
//! after the JSON of the node it comes from (so a diagnostic of the ST front end points at the
//! node's line), after a `VAR` block of the variables the rungs need (`_v4_N`: power flow values,
//! edge detectors), and `END_PROGRAM` (`END_FUNCTION_BLOCK`, `END_FUNCTION`) when the file has
//! none. `None` when the JSON holds no `"rungs"` (an FBD body: E1073 as before).
//!
//! Semantics: those of the editor's own conversion to PLCopen XML (`ladder-xml.ts`), which the
//! editor hands to its compiler, read with IEC 61131-3 (edition 3, 8.2): the rungs run in their
//! order; inside a rung, every element after the elements that feed it (its edges), ties broken by
//! position (top first, then left), as ladderc orders a PLCopen LD network. Nodes: `powerRail`
//! (`left`: TRUE, `right`: the rung's end), `contact` (`default`, `negated`, `risingEdge`,
//! `fallingEdge`: the power in AND the variable, its negation, or the Q of an R_TRIG/F_TRIG of
//! it, called every scan), `coil` (`default`, `negated`, `set`, `reset`, `risingEdge`,
//! `fallingEdge`: the variable takes the power in, its negation, TRUE or FALSE while powered, or
//! the Q of an R_TRIG/F_TRIG of the power; the power flows on), `parallel` (`open` and `close` of a
//! branch: the OR of the power that reaches it), `block` (a function block instance or a function,
//! `data.variant.name`, called with the power reaching its pins and the `variable` nodes attached
//! to them by `data.block.id`/`handleId`; a block with `EN` runs only while EN is TRUE, its ENO is
//! EN; a function's result is its `OUT` pin, and a function whose `OUT` feeds nothing is not
//! called). Power from nowhere is FALSE.
//!
//! Invariants: never panics; nothing of the JSON reaches the text but names (IEC identifiers),
//! operands of a closed set of characters (`Start_Btn`, `%IX0.0`, `T#5s`, `16#FF`, `a.b[2]`, a
//! quoted string without quotes or line breaks) and the tokens written here; a file that cannot be
//! read is one located E1064 (malformed JSON, an unknown node, an edge to a node the rung lacks, a
//! loop, more than [`MAX_NODES`] nodes) or E1065 (a name or operand that is not one) and nothing of
//! it is compiled.

use diagnostics::{code, Code, Diagnostic, FileId, Span};
use serde_json::Value;
use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap, HashSet};

/// At most this many nodes in one file (a bound against hostile input).
pub const MAX_NODES: usize = 20_000;

/// At most this many edges in one file.
pub const MAX_EDGES: usize = 40_000;

type Fail = Box<Diagnostic>;

/// The hint of a file the editor would not have written.
const HINT: &str = "open the POU in OpenPLC Editor and save it again, or give the PLCopen XML the editor generates (build/<target>/src/plc.xml)";

/// The ST text of the ladder POU `src`, whose JSON body starts at `start`; `None` when the JSON has
/// no rungs (not a ladder body).
pub fn read(file: FileId, src: &str, start: usize) -> Option<Result<String, Fail>> {
    let end = json_end(src, start);
    let json = &src[start..end];
    let value: Value = match serde_json::from_str(json) {
        Ok(v) => v,
        Err(_) if !json.contains("\"rungs\"") => return None,
        Err(e) => {
            let at = start + offset_of(json, e.line(), e.column());
            // (the position is the diagnostic's own, in the file)
            let what = e.to_string();
            let what = what.split(" at line ").next().unwrap_or_default();
            return Some(Err(fail(
                code::E1064,
                file,
                at,
                format!("the ladder JSON is not well-formed: {what}"),
            )));
        }
    };
    value.get("rungs")?;
    Some(translate(file, src, start, end, &value))
}

/// Where the JSON body that starts at `start` ends: before the POU's closing keyword, if the file
/// has one (the editor closes the POU after the JSON: `}` then `END_PROGRAM`).
pub fn json_end(src: &str, start: usize) -> usize {
    let mut body = src[start..].trim_end();
    for end in ["END_PROGRAM", "END_FUNCTION_BLOCK", "END_FUNCTION"] {
        let cut = body.len().saturating_sub(end.len());
        if body.get(cut..).is_some_and(|t| t.eq_ignore_ascii_case(end)) {
            body = body[..cut].trim_end();
            break;
        }
    }
    start + body.len()
}

/// The byte offset of 1-based `line` and `column` in `text`, clamped to it.
pub(crate) fn offset_of(text: &str, line: usize, column: usize) -> usize {
    let mut at = 0;
    for (k, l) in text.split_inclusive('\n').enumerate() {
        if k + 1 == line {
            return (at + column.saturating_sub(1))
                .min(at + l.len())
                .min(text.len());
        }
        at += l.len();
    }
    text.len()
}

fn fail(code: Code, file: FileId, at: usize, msg: String) -> Fail {
    let hint = if code == code::E1065 {
        "name a variable of the POU (`Start`, `Motor.Run`, `%QX0.0`) or, at a block input, a literal (`10`, `T#5s`), in the editor"
    } else {
        HINT
    };
    Box::new(
        Diagnostic::error(code, msg)
            .at(Span::new(file, at, at + 1))
            .with_primary_label("here in the ladder JSON")
            .with_hint(hint),
    )
}

/// An IEC 61131-3 identifier.
fn is_name(s: &str) -> bool {
    let mut c = s.chars();
    c.next()
        .is_some_and(|f| f.is_ascii_alphabetic() || f == '_')
        && c.all(|x| x.is_ascii_alphanumeric() || x == '_')
        && !s.contains("__")
        && s.len() <= 127
}

/// One ST operand: a variable (`a`, `a.b`, `a[2]`, `%IX0.0`) or a literal (`10`, `T#5s`,
/// `16#FF`, `TRUE`, `'text'`), of characters that cannot end or open anything else.
fn is_operand(s: &str) -> bool {
    if s.len() > 255 || s.is_empty() {
        return false;
    }
    if let Some(inner) = s.strip_prefix('\'').and_then(|x| x.strip_suffix('\'')) {
        return inner
            .chars()
            .all(|c| c.is_ascii() && !c.is_ascii_control() && c != '\'');
    }
    s.chars()
        .all(|c| c.is_ascii_alphanumeric() || "_#.+-:%[]".contains(c))
}

/// An operand that names a variable (what a contact reads and a coil writes).
fn is_variable(s: &str) -> bool {
    is_operand(s)
        && s.chars()
            .next()
            .is_some_and(|c| c.is_ascii_alphabetic() || c == '_' || c == '%')
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Left,
    Right,
    Contact,
    Coil,
    Block,
    Variable,
    Parallel,
}

struct Node<'v> {
    kind: Kind,
    v: &'v Value,
    /// Where its JSON is (its `id`).
    at: usize,
    /// Its position, for the order of elements that do not feed each other.
    key: (i64, i64),
}

/// The ST tokens being written and the variables they need.
struct Gen {
    file: FileId,
    /// Tokens and the offset each belongs at.
    words: Vec<(String, usize)>,
    /// Hidden variables: name, type.
    temps: Vec<(String, &'static str)>,
}

impl Gen {
    fn temp(&mut self, ty: &'static str) -> String {
        let name = format!("_v4_{}", self.temps.len() + 1);
        self.temps.push((name.clone(), ty));
        name
    }
    fn emit(&mut self, at: usize, toks: &[&str]) {
        self.words
            .extend(toks.iter().map(|t| ((*t).to_string(), at)));
    }
}

fn str_of<'v>(v: &'v Value, path: &[&str]) -> Option<&'v str> {
    let mut cur = v;
    for p in path {
        cur = cur.get(p)?;
    }
    cur.as_str()
}

fn translate(
    file: FileId,
    src: &str,
    start: usize,
    end: usize,
    value: &Value,
) -> Result<String, Fail> {
    let json = &src[start..end];
    let Some(rungs) = value.get("rungs").and_then(Value::as_array) else {
        return Err(fail(
            code::E1064,
            file,
            start,
            "the ladder JSON's `rungs` is not a list".into(),
        ));
    };
    let (mut nodes, mut edges) = (0usize, 0usize);
    for r in rungs {
        nodes += r.get("nodes").and_then(Value::as_array).map_or(0, Vec::len);
        edges += r.get("edges").and_then(Value::as_array).map_or(0, Vec::len);
    }
    if nodes > MAX_NODES || edges > MAX_EDGES {
        return Err(fail(
            code::E1064,
            file,
            start,
            format!("the ladder holds {nodes} nodes and {edges} edges, more than ladderc reads ({MAX_NODES} nodes, {MAX_EDGES} edges)"),
        ));
    }
    let mut g = Gen {
        file,
        words: Vec::new(),
        temps: Vec::new(),
    };
    let ids = id_offsets(json);
    let mut cursor = 0;
    for (k, r) in rungs.iter().enumerate() {
        let rung_at = match r
            .get("id")
            .and_then(Value::as_str)
            .and_then(|id| find(&ids, id, cursor))
        {
            Some(at) => at,
            None => cursor,
        };
        cursor = rung_at;
        rung(&mut g, &ids, start, r, k + 1, rung_at)?;
    }
    Ok(lay_out(src, start, end, &g))
}

/// Where each `"id": "VALUE"` of `json` is (the offsets of VALUE, in order), found in one pass.
fn id_offsets(json: &str) -> HashMap<&str, Vec<usize>> {
    let mut map: HashMap<&str, Vec<usize>> = HashMap::new();
    let mut from = 0;
    while let Some(k) = json.get(from..).and_then(|t| t.find("\"id\"")) {
        let after = from + k + 4;
        from = after;
        let rest = &json[after..];
        let Some(rest) = rest.trim_start().strip_prefix(':') else {
            continue;
        };
        let Some(value) = rest.trim_start().strip_prefix('"') else {
            continue;
        };
        let at = json.len() - value.len();
        if let Some(end) = value.find(['"', '\\']) {
            if value[end..].starts_with('"') {
                map.entry(&value[..end]).or_default().push(at);
            }
        }
    }
    map
}

/// The offset of the id `id` at or after `from`.
fn find(ids: &HashMap<&str, Vec<usize>>, id: &str, from: usize) -> Option<usize> {
    let list = ids.get(id)?;
    let k = list.partition_point(|&at| at < from);
    list.get(k).copied()
}

/// The statements of rung `k` (1-based) into `g`.
fn rung(
    g: &mut Gen,
    ids: &HashMap<&str, Vec<usize>>,
    base: usize,
    r: &Value,
    k: usize,
    rung_at: usize,
) -> Result<(), Fail> {
    let file = g.file;
    let here = |at: usize| base + at;
    let bad =
        |at: usize, msg: String| fail(code::E1064, file, base + at, format!("rung {k}: {msg}"));
    let empty = Vec::new();
    let (Some(nodes_v), Some(edges_v)) = (
        r.get("nodes")
            .and_then(Value::as_array)
            .or(r.get("nodes").is_none().then_some(&empty)),
        r.get("edges")
            .and_then(Value::as_array)
            .or(r.get("edges").is_none().then_some(&empty)),
    ) else {
        return Err(bad(rung_at, "its `nodes` or `edges` is not a list".into()));
    };
    // the nodes, by id
    let mut nodes: Vec<Node> = Vec::with_capacity(nodes_v.len());
    let mut by_id: HashMap<&str, usize> = HashMap::new();
    for n in nodes_v {
        let id = n.get("id").and_then(Value::as_str).unwrap_or("");
        let at = find(ids, id, rung_at).unwrap_or(rung_at);
        let ty = n.get("type").and_then(Value::as_str).unwrap_or("");
        let kind = match ty {
            "powerRail" => match str_of(n, &["data", "variant"]) {
                Some("left") => Kind::Left,
                Some("right") => Kind::Right,
                other => {
                    return Err(bad(
                        at,
                        format!("a power rail of variant `{}` (left or right expected)", other.unwrap_or("").escape_debug()),
                    ))
                }
            },
            "contact" => Kind::Contact,
            "coil" => Kind::Coil,
            "block" => Kind::Block,
            "variable" => Kind::Variable,
            "parallel" => Kind::Parallel,
            other => {
                return Err(bad(
                    at,
                    format!("a node of type `{}`, which ladderc does not read (powerRail, contact, coil, block, variable, parallel)", other.escape_debug()),
                ))
            }
        };
        if id.is_empty() || by_id.insert(id, nodes.len()).is_some() {
            return Err(bad(
                at,
                format!("a node without an id of its own (`{}`)", id.escape_debug()),
            ));
        }
        let pos = |c: &str| {
            n.get("position")
                .and_then(|p| p.get(c))
                .and_then(Value::as_f64)
                .map_or(0, |f| (f * 16.0) as i64)
        };
        nodes.push(Node {
            kind,
            v: n,
            at,
            key: (pos("y"), pos("x")),
        });
    }
    // the power edges: (source, its handle) into each node's handle
    let mut ins: Vec<Vec<(usize, String, String)>> = vec![Vec::new(); nodes.len()];
    let mut succ: Vec<Vec<usize>> = vec![Vec::new(); nodes.len()];
    let mut used_pins: Vec<Vec<String>> = vec![Vec::new(); nodes.len()];
    let mut seen_pins: HashSet<(usize, String)> = HashSet::new();
    for e in edges_v {
        let s = e.get("source").and_then(Value::as_str).unwrap_or("");
        let t = e.get("target").and_then(Value::as_str).unwrap_or("");
        let at = e
            .get("id")
            .and_then(Value::as_str)
            .and_then(|id| find(ids, id, rung_at))
            .unwrap_or(rung_at);
        let (Some(&si), Some(&ti)) = (by_id.get(s), by_id.get(t)) else {
            let missing = if by_id.contains_key(s) { t } else { s };
            return Err(bad(
                at,
                format!(
                    "an edge names the node `{}`, which the rung does not hold",
                    missing.escape_debug()
                ),
            ));
        };
        // a block's variables are attached by their `data.block` (as the editor converts them)
        if nodes[si].kind == Kind::Variable || nodes[ti].kind == Kind::Variable {
            continue;
        }
        if nodes[ti].kind == Kind::Left || nodes[si].kind == Kind::Right {
            return Err(bad(
                at,
                "an edge into the left power rail or out of the right one".into(),
            ));
        }
        let handle = |key: &str, block: bool| -> Result<String, Fail> {
            let h = e.get(key).and_then(Value::as_str).unwrap_or("");
            if !block {
                return Ok(String::new());
            }
            if !is_name(h) {
                return Err(fail(
                    code::E1065,
                    file,
                    here(at),
                    format!(
                        "rung {k}: an edge at the block pin `{}`, which is not a pin name",
                        h.escape_debug()
                    ),
                ));
            }
            Ok(h.to_string())
        };
        let sh = handle("sourceHandle", nodes[si].kind == Kind::Block)?;
        let th = handle("targetHandle", nodes[ti].kind == Kind::Block)?;
        if !sh.is_empty() && seen_pins.insert((si, sh.to_ascii_uppercase())) {
            used_pins[si].push(sh.clone());
        }
        ins[ti].push((si, sh, th));
        succ[si].push(ti);
    }
    // the variables at block pins: inputs (operands) and outputs (variables written)
    let mut pin_in: Vec<Vec<(String, String, usize)>> = vec![Vec::new(); nodes.len()];
    let mut pin_out: Vec<Vec<(String, String, usize)>> = vec![Vec::new(); nodes.len()];
    for n in nodes.iter().filter(|n| n.kind == Kind::Variable) {
        let name = str_of(n.v, &["data", "variable", "name"])
            .unwrap_or("")
            .trim();
        if name.is_empty() {
            continue;
        }
        let block = str_of(n.v, &["data", "block", "id"]).unwrap_or("");
        let pin = str_of(n.v, &["data", "block", "handleId"]).unwrap_or("");
        let Some(&b) = by_id.get(block).filter(|&&b| nodes[b].kind == Kind::Block) else {
            return Err(bad(
                n.at,
                format!(
                    "the variable `{}` is attached to no block of the rung",
                    name.escape_debug()
                ),
            ));
        };
        let output = str_of(n.v, &["data", "variant"]) == Some("output");
        if !is_name(pin)
            || !(if output {
                is_variable(name)
            } else {
                is_operand(name)
            })
        {
            return Err(fail(
                code::E1065,
                file,
                here(n.at),
                format!(
                    "rung {k}: `{}` at the block pin `{}` is not {}",
                    name.escape_debug(),
                    pin.escape_debug(),
                    if output {
                        "a variable"
                    } else {
                        "a variable or a literal"
                    }
                ),
            ));
        }
        let list = if output {
            &mut pin_out[b]
        } else {
            &mut pin_in[b]
        };
        list.push((pin.to_string(), name.to_string(), n.at));
    }
    // data flow first, then top to bottom, left to right (as a PLCopen network)
    let mut indeg: Vec<usize> = vec![0; nodes.len()];
    for s in &succ {
        for &t in s {
            indeg[t] += 1;
        }
    }
    let mut ready: BinaryHeap<Reverse<((i64, i64), usize)>> = nodes
        .iter()
        .enumerate()
        .filter(|(i, n)| n.kind != Kind::Variable && indeg[*i] == 0)
        .map(|(i, n)| Reverse((n.key, i)))
        .collect();
    let mut order = Vec::with_capacity(nodes.len());
    while let Some(Reverse((_, i))) = ready.pop() {
        order.push(i);
        for &t in &succ[i] {
            indeg[t] -= 1;
            if indeg[t] == 0 {
                ready.push(Reverse((nodes[t].key, t)));
            }
        }
    }
    let elements = nodes.iter().filter(|n| n.kind != Kind::Variable).count();
    if order.len() < elements {
        let mut done = vec![false; nodes.len()];
        for &i in &order {
            done[i] = true;
        }
        let at = (0..nodes.len())
            .find(|&i| nodes[i].kind != Kind::Variable && !done[i])
            .map_or(rung_at, |i| nodes[i].at);
        return Err(bad(at, "its connections form a loop".into()));
    }
    // the statements, element by element
    let mut out: Vec<HashMap<String, String>> = vec![HashMap::new(); nodes.len()];
    for i in order {
        let n = &nodes[i];
        let at = here(n.at);
        let power = |g: &mut Gen, from: &[&(usize, String, String)]| -> Result<String, Fail> {
            let mut vals: Vec<&str> = Vec::new();
            let mut seen: HashSet<&str> = HashSet::new();
            for (s, sh, _) in from {
                let Some(v) = out[*s].get(&sh.to_ascii_uppercase()) else {
                    return Err(bad(
                        n.at,
                        format!("an edge from the block pin `{sh}`, which is not an output"),
                    ));
                };
                if seen.insert(v) {
                    vals.push(v);
                }
            }
            Ok(or_of(g, at, &vals))
        };
        let all: Vec<&(usize, String, String)> = ins[i].iter().collect();
        let variable = || -> Result<String, Fail> {
            let name = str_of(n.v, &["data", "variable", "name"])
                .unwrap_or("")
                .trim();
            if !is_variable(name) {
                let what = if n.kind == Kind::Contact {
                    "contact"
                } else {
                    "coil"
                };
                return Err(fail(
                    if name.is_empty() {
                        code::E1064
                    } else {
                        code::E1065
                    },
                    file,
                    at,
                    if name.is_empty() {
                        format!("rung {k}: a {what} without a variable")
                    } else {
                        format!(
                            "rung {k}: the {what} variable `{}` is not a variable name",
                            name.escape_debug()
                        )
                    },
                ));
            }
            Ok(name.to_string())
        };
        let variant = str_of(n.v, &["data", "variant"]).unwrap_or("default");
        let unknown_variant = |what: &str| {
            bad(
                n.at,
                format!(
                    "a {what} of variant `{}`, which ladderc does not read",
                    variant.escape_debug()
                ),
            )
        };
        match n.kind {
            Kind::Left => {
                out[i].insert(String::new(), "TRUE".into());
            }
            Kind::Right | Kind::Parallel => {
                let p = power(g, &all)?;
                out[i].insert(String::new(), p);
            }
            Kind::Variable => {}
            Kind::Contact => {
                let name = variable()?;
                let p = power(g, &all)?;
                let t = match variant {
                    "default" | "" => {
                        let t = g.temp("BOOL");
                        g.emit(at, &[&t, ":=", &p, "AND", &name, ";"]);
                        t
                    }
                    "negated" => {
                        let t = g.temp("BOOL");
                        g.emit(at, &[&t, ":=", &p, "AND", "NOT", &name, ";"]);
                        t
                    }
                    "risingEdge" | "fallingEdge" => {
                        let e = g.temp(if variant == "risingEdge" {
                            "R_TRIG"
                        } else {
                            "F_TRIG"
                        });
                        let t = g.temp("BOOL");
                        let q = format!("{e}.Q");
                        g.emit(at, &[&e, "(", "CLK", ":=", &name, ")", ";"]);
                        g.emit(at, &[&t, ":=", &p, "AND", &q, ";"]);
                        t
                    }
                    _ => return Err(unknown_variant("contact")),
                };
                out[i].insert(String::new(), t);
            }
            Kind::Coil => {
                let name = variable()?;
                let p = power(g, &all)?;
                match variant {
                    "default" | "" => g.emit(at, &[&name, ":=", &p, ";"]),
                    "negated" => g.emit(at, &[&name, ":=", "NOT", &p, ";"]),
                    "set" | "reset" => {
                        let v = if variant == "set" { "TRUE" } else { "FALSE" };
                        g.emit(at, &["IF", &p, "THEN", &name, ":=", v, ";", "END_IF", ";"]);
                    }
                    "risingEdge" | "fallingEdge" => {
                        let e = g.temp(if variant == "risingEdge" {
                            "R_TRIG"
                        } else {
                            "F_TRIG"
                        });
                        let q = format!("{e}.Q");
                        g.emit(
                            at,
                            &[&e, "(", "CLK", ":=", &p, ")", ";", &name, ":=", &q, ";"],
                        );
                    }
                    _ => return Err(unknown_variant("coil")),
                }
                out[i].insert(String::new(), p);
            }
            Kind::Block => {
                let outs = block(
                    g,
                    n,
                    k,
                    &ins[i],
                    &pin_in[i],
                    &pin_out[i],
                    &used_pins[i],
                    &out,
                    base,
                )?;
                out[i] = outs;
            }
        }
    }
    Ok(())
}

/// The statements of one block: its call with the power and variables at its input pins, the
/// variables at its output pins, and the values of the pins power flows from (by upper-case pin).
#[allow(clippy::too_many_arguments)]
fn block(
    g: &mut Gen,
    n: &Node,
    k: usize,
    ins: &[(usize, String, String)],
    pin_in: &[(String, String, usize)],
    pin_out: &[(String, String, usize)],
    used: &[String],
    out: &[HashMap<String, String>],
    base: usize,
) -> Result<HashMap<String, String>, Fail> {
    let file = g.file;
    let at = base + n.at;
    let bad = |c: Code, msg: String| fail(c, file, at, format!("rung {k}: {msg}"));
    let ty = str_of(n.v, &["data", "variant", "name"]).unwrap_or("");
    if !is_name(ty) {
        return Err(bad(
            code::E1065,
            format!(
                "a block of type `{}`, which is not a name",
                ty.escape_debug()
            ),
        ));
    }
    let kind = str_of(n.v, &["data", "variant", "type"]).unwrap_or("");
    let is_fb = match kind {
        "function-block" => true,
        "function" => false,
        other => {
            return Err(bad(
                code::E1064,
                format!("the block `{ty}` is a `{}`, which ladderc does not call from a rung (function-block or function)", other.escape_debug()),
            ))
        }
    };
    // the declared order of the pins, for the call's arguments
    let declared: HashMap<String, usize> =
        n.v.get("data")
            .and_then(|d| d.get("variant"))
            .and_then(|v| v.get("variables"))
            .and_then(Value::as_array)
            .map(|vs| {
                let mut rank = HashMap::new();
                for (j, v) in vs.iter().enumerate() {
                    if let Some(name) = v.get("name").and_then(Value::as_str) {
                        rank.entry(name.to_ascii_uppercase()).or_insert(j);
                    }
                }
                rank
            })
            .unwrap_or_default();
    let rank = |p: &str| {
        declared
            .get(&p.to_ascii_uppercase())
            .copied()
            .unwrap_or(usize::MAX)
    };
    // the inputs: pin (as written), value
    // the power at each input pin (upper case: as written, the values in edge order)
    let mut powers: Vec<(String, &str, Vec<&str>)> = Vec::new();
    let mut pin_index: HashMap<String, usize> = HashMap::new();
    let mut seen: HashSet<(usize, &str)> = HashSet::new();
    for (s, sh, pin) in ins {
        let Some(v) = out[*s].get(&sh.to_ascii_uppercase()) else {
            return Err(bad(
                code::E1064,
                format!("an edge from the block pin `{sh}`, which is not an output"),
            ));
        };
        let key = pin.to_ascii_uppercase();
        let j = *pin_index.entry(key.clone()).or_insert_with(|| {
            powers.push((key, pin.as_str(), Vec::new()));
            powers.len() - 1
        });
        if seen.insert((j, v.as_str())) {
            powers[j].2.push(v);
        }
    }
    let mut args: Vec<(String, String)> = Vec::new();
    for (_, pin, vals) in &powers {
        let v = or_of(g, at, vals);
        args.push(((*pin).to_string(), v));
    }
    for (pin, name, _) in pin_in {
        if pin_index
            .insert(pin.to_ascii_uppercase(), usize::MAX)
            .is_some()
        {
            return Err(bad(
                code::E1064,
                format!("the pin `{pin}` of the block `{ty}` is connected twice"),
            ));
        }
        args.push((pin.clone(), name.clone()));
    }
    args.sort_by_key(|(p, _)| rank(p));
    let en = args
        .iter()
        .position(|(p, _)| p.eq_ignore_ascii_case("EN"))
        .map(|j| args.remove(j).1);
    let mut call: Vec<String> = Vec::new();
    let callee = if is_fb {
        let inst = str_of(n.v, &["data", "variable", "name"])
            .unwrap_or("")
            .trim();
        if !is_name(inst) {
            return Err(bad(
                if inst.is_empty() {
                    code::E1064
                } else {
                    code::E1065
                },
                format!(
                    "the function block `{ty}` has no instance name (`{}`)",
                    inst.escape_debug()
                ),
            ));
        }
        inst.to_string()
    } else {
        ty.to_string()
    };
    call.extend([callee.clone(), "(".into()]);
    for (j, (p, v)) in args.iter().enumerate() {
        if j > 0 {
            call.push(",".into());
        }
        call.extend([p.clone(), ":=".into(), v.clone()]);
    }
    call.push(")".into());
    let eno = en.clone().unwrap_or_else(|| "TRUE".into());
    let mut values: HashMap<String, String> = HashMap::new();
    let powered: Vec<&str> = used
        .iter()
        .map(String::as_str)
        .filter(|p| !p.eq_ignore_ascii_case("ENO"))
        .collect();
    // the statements inside the EN condition
    let mut body: Vec<String> = Vec::new();
    let mut after: Vec<String> = Vec::new();
    let mut before: Vec<String> = Vec::new();
    if is_fb {
        body.extend(call.iter().cloned());
        body.push(";".into());
        for (pin, name, _) in pin_out {
            if pin.eq_ignore_ascii_case("ENO") {
                after.extend([name.clone(), ":=".into(), eno.clone(), ";".into()]);
            } else {
                body.extend([
                    name.clone(),
                    ":=".into(),
                    format!("{callee}.{pin}"),
                    ";".into(),
                ]);
            }
        }
        for p in powered {
            let t = g.temp("BOOL");
            after.extend([t.clone(), ":=".into(), format!("{callee}.{p}"), ";".into()]);
            values.insert(p.to_ascii_uppercase(), t);
        }
    } else {
        if let Some(p) = powered.iter().find(|p| !p.eq_ignore_ascii_case("OUT")) {
            return Err(bad(
                code::E1064,
                format!("the output pin `{p}` of the function `{ty}`: ladderc reads a function's result (OUT) and ENO"),
            ));
        }
        let result_vars: Vec<&String> = pin_out
            .iter()
            .filter(|(p, _, _)| p.eq_ignore_ascii_case("OUT"))
            .map(|(_, v, _)| v)
            .collect();
        let feeds_power = powered.iter().any(|p| p.eq_ignore_ascii_case("OUT"));
        if feeds_power {
            let t = g.temp("BOOL");
            if en.is_some() {
                before.extend([t.clone(), ":=".into(), "FALSE".into(), ";".into()]);
            }
            body.extend([t.clone(), ":=".into()]);
            body.extend(call.iter().cloned());
            body.push(";".into());
            for v in &result_vars {
                body.extend([(*v).clone(), ":=".into(), t.clone(), ";".into()]);
            }
            values.insert("OUT".into(), t);
        } else if let Some((first, rest)) = result_vars.split_first() {
            body.extend([(*first).clone(), ":=".into()]);
            body.extend(call.iter().cloned());
            body.push(";".into());
            for v in rest {
                body.extend([(*v).clone(), ":=".into(), (*first).clone(), ";".into()]);
            }
        }
        for (pin, name, _) in pin_out {
            if pin.eq_ignore_ascii_case("ENO") {
                after.extend([name.clone(), ":=".into(), eno.clone(), ";".into()]);
            } else if !pin.eq_ignore_ascii_case("OUT") {
                return Err(bad(
                    code::E1064,
                    format!("the output pin `{pin}` of the function `{ty}`: ladderc reads a function's result (OUT) and ENO"),
                ));
            }
        }
    }
    let words: Vec<String> = before
        .into_iter()
        .chain(match (&en, body.is_empty()) {
            (_, true) => Vec::new(),
            (None, false) => body,
            (Some(en), false) => {
                let mut w = vec!["IF".to_string(), en.clone(), "THEN".into()];
                w.extend(body);
                w.extend(["END_IF".into(), ";".into()]);
                w
            }
        })
        .chain(after)
        .collect();
    let refs: Vec<&str> = words.iter().map(String::as_str).collect();
    g.emit(at, &refs);
    values.insert("ENO".into(), eno);
    Ok(values)
}

/// The OR of the power values `vals` (FALSE for none): one of them, or a new variable holding it.
fn or_of(g: &mut Gen, at: usize, vals: &[&str]) -> String {
    match vals {
        [] => "FALSE".into(),
        [one] => (*one).to_string(),
        _ => {
            let t = g.temp("BOOL");
            g.emit(at, &[&t, ":="]);
            for (j, v) in vals.iter().enumerate() {
                if j > 0 {
                    g.emit(at, &["OR"]);
                }
                g.emit(at, &[v]);
            }
            g.emit(at, &[";"]);
            t
        }
    }
}

/// The keyword that closes the POU `decls` declares.
fn closer(decls: &str) -> &'static str {
    decls
        .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .find_map(|w| match w.to_ascii_uppercase().as_str() {
            "PROGRAM" => Some("END_PROGRAM"),
            "FUNCTION_BLOCK" => Some("END_FUNCTION_BLOCK"),
            "FUNCTION" => Some("END_FUNCTION"),
            _ => None,
        })
        .unwrap_or("END_PROGRAM")
}

/// Writes `word` into the first run of blanks of `bytes[from..to]` that holds it with a blank on
/// each side; the offset after it.
pub(crate) fn place(bytes: &mut [u8], from: usize, to: usize, word: &str) -> Option<usize> {
    let need = word.len() + 2;
    let to = to.min(bytes.len());
    let mut run = 0;
    for i in from.min(to)..to {
        if bytes[i] == b' ' {
            run += 1;
            if run == need {
                let at = i + 2 - need;
                bytes[at..at + word.len()].copy_from_slice(word.as_bytes());
                return Some(at + word.len());
            }
        } else {
            run = 0;
        }
    }
    None
}

/// The file's text with the JSON (`start..end`) blanked and `g`'s words written into it, each at
/// or after its node; what does not fit goes on lines of its own after the JSON.
fn lay_out(src: &str, start: usize, end: usize, g: &Gen) -> String {
    let mut bytes: Vec<u8> = src.as_bytes().to_vec();
    for b in &mut bytes[start..end] {
        if *b != b'\n' && *b != b'\r' {
            *b = b' ';
        }
    }
    let mut words: Vec<(String, usize)> = Vec::new();
    if !g.temps.is_empty() {
        words.push(("VAR".into(), start));
        for (name, ty) in &g.temps {
            words.extend([
                (name.clone(), start),
                (":".into(), start),
                ((*ty).to_string(), start),
                (";".into(), start),
            ]);
        }
        words.push(("END_VAR".into(), start));
    }
    words.extend(g.words.iter().cloned());
    if src[end..].trim().is_empty() {
        words.push((closer(&src[..start]).into(), end));
    }
    let mut cursor = start;
    let mut overflow: Vec<u8> = Vec::new();
    for (word, pref) in words {
        if overflow.is_empty() {
            let from = pref.max(cursor).min(end);
            if let Some(after) = place(&mut bytes, from, end, &word)
                .or_else(|| place(&mut bytes, cursor, end, &word))
            {
                cursor = after;
                continue;
            }
            overflow.push(b'\n');
        }
        overflow.extend_from_slice(word.as_bytes());
        overflow.push(if word == ";" { b'\n' } else { b' ' });
    }
    if !overflow.is_empty() {
        overflow.push(b'\n');
        bytes.splice(end..end, overflow);
    }
    // only ASCII was written over blanks, and every byte of the JSON was blanked alone
    String::from_utf8(bytes).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(json: &str) -> Option<Result<String, Fail>> {
        let src = format!("PROGRAM main\nVAR\n  A : BOOL;\nEND_VAR\n{json}\n");
        let start = src.find('{').unwrap();
        read(FileId(0), &src, start)
    }

    #[test]
    fn shapes_the_editor_does_not_write_are_one_error_or_an_empty_body() {
        for json in [
            r#"{"rungs": 5}"#,
            r#"{"rungs": [1, "x", null, {"nodes": {}, "edges": []}]}"#,
            r#"{"rungs": [{"nodes": [{"id": 1, "type": "contact"}]}]}"#,
            r#"{"rungs": [{"nodes": [{"id": "b", "type": "block", "data": {"variant": "TON"}}]}]}"#,
            r#"{"rungs": [{"nodes": [{"id": "b", "type": "block", "position": {"x": 1e308, "y": -1e308},
                "data": {"variant": {"name": "ADD", "type": "function"}}},
                {"id": "v", "type": "variable", "data": {"variant": "output", "variable": {"name": "A"},
                 "block": {"id": "b", "handleId": "Q"}}}]}]}"#,
            r#"{"rungs": [{"nodes": [{"id": "c", "type": "coil", "data": {"variant": "pulse", "variable": {"name": "A"}}}]}]}"#,
            r#"{"rungs": [{"nodes": [{"id": "c", "type": "coil", "data": {"variable": {"name": "A"}}},
                {"id": "c", "type": "coil", "data": {"variable": {"name": "A"}}}]}]}"#,
            r#"{"rungs": [{"id": "r", "nodes": [], "edges": [{"source": "x"}]}]}"#,
            r#"{"rungs": [{"id": "r\"", "nodes": [{"id": "\u00e9", "type": "coil",
                "data": {"variable": {"name": "'caf\u00e9'"}}}]}]}"#,
        ] {
            match text(json) {
                // (the JSON blanked: nothing of it but names is left)
                Some(Ok(t)) => assert!(t.is_ascii() && !t.contains('{'), "{t}"),
                Some(Err(d)) => assert!(d.span.is_some(), "{d:?}"),
                None => panic!("{json}"),
            }
        }
    }

    #[test]
    fn only_names_and_operands_of_the_json_reach_the_text() {
        let json = r#"{"name": "main", "rungs": [{"id": "r1", "nodes": [
            {"id": "L", "type": "powerRail", "data": {"variant": "left"}},
            {"id": "c", "type": "contact", "data": {"variant": "negated", "variable": {"name": "A"}}},
            {"id": "k", "type": "coil", "data": {"variant": "set", "variable": {"name": "A"}}}],
            "edges": [{"source": "L", "target": "c"}, {"source": "c", "target": "k"}]}]}"#;
        let t = text(json).unwrap().unwrap();
        let body: Vec<&str> = t[t.find("END_VAR").unwrap() + 7..]
            .split_whitespace()
            .collect();
        assert_eq!(
            body.join(" "),
            "VAR _v4_1 : BOOL ; END_VAR _v4_1 := TRUE AND NOT A ; \
             IF _v4_1 THEN A := TRUE ; END_IF ; END_PROGRAM"
        );
        // a JSON without room for the statements: they follow it, in order
        let compact: String = json.split_whitespace().collect::<Vec<_>>().join("");
        let t = text(&compact).unwrap().unwrap();
        let body: Vec<&str> = t[t.find("END_VAR").unwrap() + 7..]
            .split_whitespace()
            .collect();
        assert_eq!(body.first(), Some(&"VAR"));
        assert_eq!(body.last(), Some(&"END_PROGRAM"));
        assert!(body.contains(&"NOT") && !t.contains("powerRail"), "{t}");
        // an FBD body (one `rung`) is not read here
        assert!(text(r#"{"name": "main", "rung": {"nodes": [], "edges": []}}"#).is_none());
    }
}
