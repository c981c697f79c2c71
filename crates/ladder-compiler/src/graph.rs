//! The graphical body (LD or FBD) as a graph: nodes by localId, wires, networks, evaluation order.
//!
//! Input: the `<LD>` or `<FBD>` element. Output: [`Graph`] with one [`Node`] per element (comments
//! dropped), every wire resolved to a node index (dangling ones reported as E3006), networks (connected
//! components, connectors joined to their continuations by name) in execution order.
//! Order (documented in the README): networks by the smallest non-zero `executionOrderId` of their
//! elements (a body numbered from 0, its ids distinct, counts 0 as the first position:
//! `numbered_from_zero`), networks without one after them by the row, then x, of their first output
//! element, as Beremiz orders them ([`crate::network_order`]);
//! inside a network, data flow first, ties broken the same way, then by localId (an element without
//! a number in a numbered body where its first numbered reader runs: `lower_order`).
//! Invariants: every [`Wire::from`] indexes [`Graph::nodes`]; every node but a power rail belongs to exactly
//! one network (rails join no rungs and are in none);
//! a duplicate localId (E3014), an element without localId (E3013) or an unsupported element (E3012) is
//! reported and left out of the graph.

use crate::context::Ctx;
use crate::xml::Element;
use diagnostics::{code, Diagnostic, Span};
use rustc_hash::FxHashMap;
use std::borrow::Cow;
use std::collections::HashMap;

/// A name or text of the graph: borrowed from the XML text (no allocation per element), owned only
/// where it was decoded (entities, several text pieces) or made up (SFC conditions).
pub type Text<'x> = Cow<'x, str>;

/// The `edge` attribute of a contact, coil or block pin (transition-sensing elements, IEC 61131-3 4.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Edge {
    /// No `edge` attribute (or `none`): the element passes the level.
    None,
    /// `edge="rising"`: a positive transition-sensing contact/coil (`-|P|-`), TRUE for one scan when the
    /// value rises.
    Rising,
    /// `edge="falling"`: a negative transition-sensing contact/coil (`-|N|-`), TRUE for one scan when it
    /// falls.
    Falling,
}

/// The `storage` attribute of a coil: plain, latching set or latching reset.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Storage {
    /// `-( )-`: the coil takes the power flow's value (or its negation for `-(/)-`).
    None,
    /// `-(S)-`: the variable is set to TRUE while power flows, and kept.
    Set,
    /// `-(R)-`: the variable is reset to FALSE while power flows, and kept.
    Reset,
}

/// One wire end: the source node and, for blocks, the source output pin.
#[derive(Debug, Clone)]
pub struct Wire<'x> {
    /// Index in [`Graph::nodes`] of the element the wire comes from.
    pub from: usize,
    /// The source block's output pin (`formalParameter` of the `<connection>`); `None` for a single-output
    /// element.
    pub pin: Option<Text<'x>>,
    /// The `<connection>` element.
    pub span: Span,
}

/// A block input (or in-out) pin.
#[derive(Debug, Clone)]
pub struct InPin<'x> {
    /// The pin's formal parameter name (`IN`, `PT`, `EN`).
    pub name: Text<'x>,
    /// `negated="true"`: the pin inverts the value (a circle on the pin).
    pub negated: bool,
    /// Edge detection on the pin: with `edge="rising"` (`"falling"`) the block sees TRUE only in the scan
    /// in which the wired value rises (falls), through a hidden R_TRIG (F_TRIG).
    pub edge: Edge,
    /// The wires into the pin (OR-combined when several, as in LD).
    pub wires: Vec<Wire<'x>>,
    /// The pin's `<variable>` element.
    pub span: Span,
    /// Declared under `<inOutVariables>`: the pin is a VAR_IN_OUT of the block.
    pub in_out: bool,
}

/// A block output pin.
#[derive(Debug, Clone)]
pub struct OutPin<'x> {
    /// The pin's formal parameter name (`Q`, `ET`, `OUT`, `ENO`).
    pub name: Text<'x>,
    /// `negated="true"`: the pin inverts the value.
    pub negated: bool,
}

/// What a graphical element is (PLCopen TC6 `<ld>`/`<fbd>`/common elements).
#[derive(Debug, Clone)]
pub enum Kind<'x> {
    /// `<leftPowerRail>`: the source of power flow (TRUE) at the left of a rung.
    LeftRail,
    /// `<rightPowerRail>`: the right end of a rung; nothing is computed there.
    RightRail,
    /// `<contact>`: reads a BOOL variable into the power flow (series when chained, parallel when wires
    /// join).
    Contact {
        /// The variable read, as written in `<variable>`.
        var: Text<'x>,
        /// The `<variable>` text.
        var_span: Span,
        /// `negated="true"`: a normally closed contact `-|/|-`.
        negated: bool,
        /// Transition sensing (`-|P|-`, `-|N|-`).
        edge: Edge,
        /// A vendor's comparison contact, not PLCopen TC6: `typeName="EQ_UDINT"` and the second
        /// operand in `<variable1>` (beta591414/-CMC-): the type name and where it is written.
        compare: Option<(Text<'x>, Span)>,
    },
    /// `<coil>`: writes the power flow into a BOOL variable.
    Coil {
        /// The variable written, as written in `<variable>`.
        var: Text<'x>,
        /// The `<variable>` text.
        var_span: Span,
        /// `negated="true"`: a negated coil `-(/)-`.
        negated: bool,
        /// Plain, set (`-(S)-`) or reset (`-(R)-`).
        storage: Storage,
        /// Transition sensing (`-(P)-`, `-(N)-`).
        edge: Edge,
    },
    /// `<block>`: a function, function block instance or operator box (boxed: inline, its data made
    /// every `Node` 232 bytes, and a graph holds one `Node` per element).
    Block(Box<Block<'x>>),
    /// `<inVariable>`: an FBD variable or constant read into the network.
    InVar {
        /// The `<expression>` text: a variable, a field, a constant (`T#5s`, `16#FF`).
        expr: Text<'x>,
        /// The `<expression>` text.
        expr_span: Span,
        /// `negated="true"`: the value is inverted.
        negated: bool,
    },
    /// `<outVariable>`: an FBD variable written from the network.
    OutVar {
        /// The `<expression>` text: the variable written.
        expr: Text<'x>,
        /// The `<expression>` text.
        expr_span: Span,
        /// `negated="true"`: the inverted value is written.
        negated: bool,
    },
    /// `<inOutVariable>`: written from its input (if wired), then read on its output.
    InOutVar {
        /// The `<expression>` text: the variable.
        expr: Text<'x>,
        /// The `<expression>` text.
        expr_span: Span,
        /// `negatedIn="true"`: the input value is inverted before it is written.
        negated_in: bool,
        /// `negatedOut="true"`: the value read is inverted.
        negated_out: bool,
    },
    /// `<connector>`: a named wire end; its value continues at the continuations of that name.
    Connector {
        /// The connector's name (matched case-insensitively).
        name: Text<'x>,
    },
    /// `<continuation>`: the other end of a named connector.
    Continuation {
        /// The name of the connector it continues.
        name: Text<'x>,
    },
    /// `<jump>`: jump to a label when its input is TRUE (IL `JMPC`).
    Jump {
        /// The target label.
        label: Text<'x>,
        /// The `label` attribute.
        label_span: Span,
    },
    /// `<label>`: a jump target.
    Label {
        /// The label's name.
        label: Text<'x>,
        /// The `label` attribute.
        label_span: Span,
    },
    /// `<return>`: leave the POU when its input is TRUE (IL `RETC`).
    Return,
}

/// A `<block>` element's data ([`Kind::Block`]).
#[derive(Debug, Clone)]
pub struct Block<'x> {
    /// `typeName`: the function or FB type (`TON`, `ADD`, a user POU).
    pub type_name: Text<'x>,
    /// The `typeName` attribute.
    pub type_span: Span,
    /// `instanceName` and its span, for function blocks.
    pub instance: Option<(Text<'x>, Span)>,
    /// Input and in-out pins in document order.
    pub inputs: Vec<InPin<'x>>,
    /// Output pins in document order.
    pub outputs: Vec<OutPin<'x>>,
    /// The ST statements of a CODESYS `EXECUTE` box (its vendor data's `<STCode>`), laid out so
    /// that byte `k` is byte `base + k` of the file; `None` for every other block.
    pub code: Option<crate::il_body::EmbeddedText>,
}

/// One graphical element of an LD/FBD body, with its position and input wires.
#[derive(Debug, Clone)]
pub struct Node<'x> {
    /// The `localId` attribute as written (trimmed).
    pub id: Text<'x>,
    /// The localId as a number (`u64::MAX` when it is not one), for ordering.
    pub num: u64,
    /// What the element is, with its element-specific data.
    pub kind: Kind<'x>,
    /// The element's start tag.
    pub span: Span,
    /// The `executionOrderId` attribute, if given (0 counts as absent for ordering; a body numbered
    /// from 0 has every id raised by one when read).
    pub exec_order: Option<u32>,
    /// `<position x>`, in the editor's units (rounded toward zero).
    pub x: i64,
    /// `<position y>`, in the editor's units.
    pub y: i64,
    /// Wires into the single input of non-block elements (OR-combined when several).
    pub input: Vec<Wire<'x>>,
    /// Whether the element has a `<connectionPointIn>` at all.
    pub has_input: bool,
    /// Whether that point holds at least one `<connection>` (even a dangling one).
    pub wired: bool,
}

impl<'x> Node<'x> {
    /// Every wire into this node (block pins included).
    pub fn all_wires(&self) -> Vec<&Wire<'x>> {
        self.wires().collect()
    }
    /// The same wires as [`Node::all_wires`], in the same order, without collecting them.
    pub fn wires(&self) -> impl Iterator<Item = &Wire<'x>> {
        let pins: &[InPin<'x>] = match &self.kind {
            Kind::Block(b) => &b.inputs,
            _ => &[],
        };
        self.input
            .iter()
            .chain(pins.iter().flat_map(|p| p.wires.iter()))
    }
    /// Execution order key: non-zero `executionOrderId`, then y, then x, then the numeric localId.
    pub fn order_key(&self) -> (u32, i64, i64, u64) {
        (
            self.exec_order.filter(|o| *o > 0).unwrap_or(u32::MAX),
            self.y,
            self.x,
            self.num,
        )
    }
}

/// An LD or FBD body read as a graph: [`read`]'s output, [`crate::lower`]'s input.
pub struct Graph<'x> {
    /// Every non-comment element, in document order; [`Wire::from`] indexes this.
    pub nodes: Vec<Node<'x>>,
    /// Networks in execution order; each lists its node indexes in increasing order.
    pub networks: Vec<Vec<usize>>,
    /// For each continuation node, the connector nodes of the same name.
    pub continuation_sources: HashMap<usize, Vec<usize>>,
}

/// `str::trim` of an attribute value or a text: the value itself when it starts and ends with a
/// printable ASCII character (nearly always), without `trim`'s Unicode checks.
fn trim(s: &str) -> &str {
    match s.as_bytes() {
        [first, .., last] if (0x21..0x7f).contains(first) && (0x21..0x7f).contains(last) => s,
        [one] if (0x21..0x7f).contains(one) => s,
        _ => s.trim(),
    }
}

/// A boolean attribute's value (`true` or `1`, surrounding blanks ignored).
fn truthy(v: Option<&str>) -> bool {
    v.is_some_and(|v| trim(v) == "true" || trim(v) == "1")
}

/// The `edge` attribute's value.
fn edge_of(v: Option<&str>) -> Edge {
    match v.map(trim) {
        Some("rising") => Edge::Rising,
        Some("falling") => Edge::Falling,
        _ => Edge::None,
    }
}

/// The wires of one `<connectionPointIn>` (none without one), in their final list: each wire's
/// [`Wire::from`] holds, until [`read`] resolves it, the index in `refs.ids` of its `refLocalId`
/// (borrowed from the XML text). One list per input, built once: no second list of raw wires per node.
fn raw_wires<'x>(
    ctx: &Ctx,
    point: Option<&Element<'x>>,
    refs: &mut WireRefs<'x>,
    ids: &LocalIds<'x>,
) -> Vec<Wire<'x>> {
    point
        .map(|p| {
            p.children_named("connection")
                .map(|c| {
                    let [ref_id, pin] = c.attrs(["refLocalId", "formalParameter"]);
                    let r = trim(ref_id.unwrap_or_default());
                    refs.ids.push(r);
                    // an element read already (the usual case: editors wire from left to right) is
                    // its node now, while its id and the table are in the cache
                    refs.found.push(
                        ids.get(r)
                            .and_then(|k| u32::try_from(k + 1).ok())
                            .unwrap_or(0),
                    );
                    Wire {
                        from: refs.ids.len() - 1,
                        pin: pin.map(trim).filter(|s| !s.is_empty()).map(Cow::Borrowed),
                        span: ctx.tag(c),
                    }
                })
                .collect()
        })
        .unwrap_or_default()
}

/// An `<expression>` written on a connection point instead of a wire (PLCopen TC6: `connectionPointIn`
/// holds either `<connection>`s or one `<expression>`, `connectionPointOut` may hold one `<expression>`;
/// CODESYS V3 LD writes a box output assigned to a variable as
/// `<connectionPointOut><expression>state</expression></connectionPointOut>`). [`read`] turns each
/// into the element it stands for, right after the element that holds it.
enum Pending<'x> {
    /// An input point's expression: read into the point through the wire whose index in
    /// [`WireRefs`] is given (resolved once the `<inVariable>` standing for it is a node).
    In(usize, (Text<'x>, Span)),
    /// An output point's expression (with the block pin's name): the value written to it.
    Out(Option<Text<'x>>, (Text<'x>, Span)),
}

/// The text of a connection point's `<expression>` and its span, if it has a non-blank one.
fn expression_of<'x>(ctx: &Ctx, point: &Element<'x>) -> Option<(Text<'x>, Span)> {
    point.child("expression")?;
    let (text, span) = text_of(ctx, point, "expression");
    (!text.is_empty()).then_some((text, span))
}

/// An element name of no graphical body, its first element's tag and localId, and how many there are.
type Unsupported<'x> = (&'x str, (Span, Option<&'x str>), usize);

/// W1449: the expression `x` of a connection point is not read, `why`.
fn unread_expression(ctx: &mut Ctx, x: &(Text<'_>, Span), why: &str, pou: &str) {
    ctx.report(
        Diagnostic::warning(
            code::W1449,
            format!(
                "expression `{}` on a connection point is not read: {why}",
                x.0
            ),
        )
        .at(x.1)
        .with_hint("keep either the wires or the expression on the point (`ladderc explain W1449`)")
        .with_xml(diagnostics::XmlContext {
            pou: Some(pou.to_string()),
            local_id: None,
            network: None,
        }),
    );
}

/// A wire into a point whose source is not read yet: [`Pending::In`] sets its node.
fn pending_wire<'x>(refs: &mut WireRefs<'x>, pin: Option<Text<'x>>, span: Span) -> Wire<'x> {
    refs.ids.push("");
    refs.found.push(0);
    Wire {
        from: refs.ids.len() - 1,
        pin,
        span,
    }
}

/// The `refLocalId` of every wire read by [`raw_wires`], by [`Wire::from`] until [`read`] resolves
/// the wires.
struct WireRefs<'x> {
    /// The `refLocalId` as written (trimmed).
    ids: Vec<&'x str>,
    /// Its node + 1 when that element was read before the wire (a later element's id, or an id of no
    /// element, is looked up once every element is read: 0).
    found: Vec<u32>,
}

/// A `<position>` coordinate in the editor's units, rounded toward zero (0 when absent or not a number).
fn coord(v: Option<&str>) -> i64 {
    let Some(v) = v.map(trim) else { return 0 };
    // Short integers (the usual case) are exact as f64 too: the same value without the float parser,
    // read digit by digit (at most 15 digits: no overflow).
    if v.len() <= 15 && !v.is_empty() {
        let digits = v.bytes().try_fold(0i64, |n, b| {
            b.is_ascii_digit().then(|| n * 10 + i64::from(b - b'0'))
        });
        if let Some(n) = digits {
            return n;
        }
    }
    v.parse::<f64>().map(|v| v as i64).unwrap_or(0)
}

fn text_of<'x>(ctx: &Ctx, e: &Element<'x>, child: &str) -> (Text<'x>, Span) {
    match e.child(child) {
        Some(c) => (
            match c.text_ref() {
                Cow::Borrowed(t) => Cow::Borrowed(trim(t)),
                Cow::Owned(t) => Cow::Owned(trim(&t).to_string()),
            },
            ctx.text_span(c),
        ),
        None => (Cow::Borrowed(""), ctx.tag(e)),
    }
}

/// The nodes of a body by `localId`, as written (`"7"` and `"07"` are two ids).
///
/// The usual id, a decimal number written without a leading zero (editors number elements 1, 2, 3 ...),
/// is found in a list indexed by its value: ids and the wires that name them come in about document
/// order, so the list is read where it was just written, where a hash map of 70,000 ids (3 MB for
/// 10,000 rungs) missed the cache on nearly every wire. Any other id, or a number past
/// `8 * elements + 64` (kept from sizing the list), is in a hash map.
struct LocalIds<'x> {
    /// Node index + 1 by id value (0: no node).
    by_number: Vec<u32>,
    /// Ids past `by_number`'s reach: another spelling of a number, a number too large, not a number.
    other: FxHashMap<&'x str, usize>,
    /// The largest id value `by_number` may hold, plus one.
    limit: usize,
}

impl<'x> LocalIds<'x> {
    /// An empty table for a body of `elements` child elements.
    fn new(elements: usize) -> Self {
        LocalIds {
            by_number: Vec::with_capacity(elements + 2),
            other: FxHashMap::default(),
            limit: elements.saturating_mul(8).saturating_add(64),
        }
    }
    /// `id`'s value when it is a decimal number without sign, blank or leading zero, below `limit`
    /// (its spelling is then the only one of that value).
    fn number(&self, id: &str) -> Option<usize> {
        let b = id.as_bytes();
        if b.is_empty() || b.len() > 9 || (b[0] == b'0' && b.len() > 1) {
            return None;
        }
        let n = b.iter().try_fold(0usize, |n, &c| {
            c.is_ascii_digit().then(|| n * 10 + usize::from(c - b'0'))
        })?;
        (n < self.limit).then_some(n)
    }
    /// The node of `id`.
    fn get(&self, id: &str) -> Option<usize> {
        if let Some(&k) = self.number(id).and_then(|n| self.by_number.get(n)) {
            if k > 0 {
                return Some(k as usize - 1);
            }
        }
        self.other.get(id).copied()
    }
    /// Records `node` as the node of `id` (not yet recorded).
    fn insert(&mut self, id: &'x str, node: usize) {
        match (self.number(id), u32::try_from(node + 1)) {
            (Some(n), Ok(k)) => {
                if self.by_number.len() <= n {
                    self.by_number.resize(n + 1, 0);
                }
                self.by_number[n] = k;
            }
            _ => {
                self.other.insert(id, node);
            }
        }
    }
}

/// Whether a body's `executionOrderId`s (`ids`, sorted here) number its elements from 0: at least
/// two of them, all different, one of them 0. Then 0 is the first position, not "no order": CFC
/// editors number from 0 (Beckhoff Infosys, TC3 PLC CFC "Command Move to Beginning": the selected
/// elements get "the lowest numbers starting with 0"; CODESYS CFC likewise) and the TC6 schema's
/// `executionOrderId` is a plain `xsd:unsignedLong`. Beremiz and the OpenPLC Editor write 0 on every
/// element (no order chosen): repeated zeros, and a lone 0, stay "no order".
fn numbered_from_zero(ids: &mut [u32]) -> bool {
    ids.sort_unstable();
    ids.len() >= 2 && ids[0] == 0 && ids.windows(2).all(|w| w[0] != w[1])
}

/// Reads the body's elements. `pou` names the POU in diagnostics.
pub fn read<'x>(ctx: &mut Ctx, body: &Element<'x>, pou: &str) -> Graph<'x> {
    // At most one node per child element: no regrowth.
    let mut nodes = Vec::with_capacity(body.children.len());
    // Every wire's `refLocalId`, indexed by the wire's `from` until the wires are resolved below.
    let mut refs = WireRefs {
        ids: Vec::with_capacity(body.children.len()),
        found: Vec::with_capacity(body.children.len()),
    };
    // localId -> node index; the ids are borrowed from the XML text.
    let mut ids = LocalIds::new(body.children.len());
    // Elements of no PLCopen graphical body (name, first one's tag and localId, count) and reused
    // localIds (id, second use, first node, uses): one error each, not one per element (a file in
    // another schema, a generator that numbers every rung's right rail alike).
    let mut unsupported: Vec<Unsupported<'_>> = Vec::new();
    let mut reused: Vec<(&str, Span, usize, usize)> = Vec::new();
    // The `executionOrderId`s of the elements, in document order (see [`numbered_from_zero`]).
    let mut numbered: Vec<u32> = Vec::new();
    for e in body.children {
        let span = ctx.tag(e);
        if matches!(
            e.name(),
            "comment" | "addData" | "vendorElement" | "documentation"
        ) {
            continue;
        }
        // Every attribute read below, found in one pass over the start tag: the element's own ones in
        // `a`, `b`, `c` (an empty name is never found).
        let own: [&str; 3] = match e.name() {
            "contact" => ["negated", "edge", ""],
            "coil" => ["negated", "edge", "storage"],
            "inVariable" | "outVariable" => ["negated", "", ""],
            "inOutVariable" => ["negatedIn", "negatedOut", ""],
            "connector" | "continuation" => ["name", "", ""],
            "jump" | "label" => ["label", "", ""],
            "block" => ["typeName", "instanceName", ""],
            _ => ["", "", ""],
        };
        let [local_id, exec_order, a, b, c] =
            e.attrs(["localId", "executionOrderId", own[0], own[1], own[2]]);
        // `<expression>`s written on connection points instead of wires (see [`Pending`])
        let mut pending: Vec<Pending<'x>> = Vec::new();
        let kind = match e.name() {
            "leftPowerRail" => Kind::LeftRail,
            "rightPowerRail" => Kind::RightRail,
            "contact" => {
                let (var, var_span) = text_of(ctx, e, "variable");
                let compare = match (e.attr("typeName"), e.child("variable1")) {
                    (None, None) => None,
                    (name, _) => Some((Cow::Borrowed(name.map_or("", trim)), span)),
                };
                Kind::Contact {
                    var,
                    var_span,
                    negated: truthy(a),
                    edge: edge_of(b),
                    compare,
                }
            }
            "coil" => {
                let (var, var_span) = text_of(ctx, e, "variable");
                Kind::Coil {
                    var,
                    var_span,
                    negated: truthy(a),
                    storage: match c.map(trim) {
                        Some("set") => Storage::Set,
                        Some("reset") => Storage::Reset,
                        _ => Storage::None,
                    },
                    edge: edge_of(b),
                }
            }
            "inVariable" => {
                let (expr, expr_span) = text_of(ctx, e, "expression");
                Kind::InVar {
                    expr,
                    expr_span,
                    negated: truthy(a),
                }
            }
            "outVariable" => {
                let (expr, expr_span) = text_of(ctx, e, "expression");
                Kind::OutVar {
                    expr,
                    expr_span,
                    negated: truthy(a),
                }
            }
            "inOutVariable" => {
                let (expr, expr_span) = text_of(ctx, e, "expression");
                Kind::InOutVar {
                    expr,
                    expr_span,
                    negated_in: truthy(a),
                    negated_out: truthy(b),
                }
            }
            "connector" => Kind::Connector {
                name: Cow::Borrowed(trim(a.unwrap_or_default())),
            },
            "continuation" => Kind::Continuation {
                name: Cow::Borrowed(trim(a.unwrap_or_default())),
            },
            "jump" => Kind::Jump {
                label: Cow::Borrowed(trim(a.unwrap_or_default())),
                label_span: ctx.attr_span(e, "label"),
            },
            "label" => Kind::Label {
                label: Cow::Borrowed(trim(a.unwrap_or_default())),
                label_span: ctx.attr_span(e, "label"),
            },
            "return" => Kind::Return,
            "block" => {
                let mut inputs = Vec::new();
                let mut outputs = Vec::new();
                for (list, in_out) in [("inputVariables", false), ("inOutVariables", true)] {
                    for v in e
                        .child(list)
                        .into_iter()
                        .flat_map(|l| l.children_named("variable"))
                    {
                        let point = v.child("connectionPointIn");
                        let mut wires = raw_wires(ctx, point, &mut refs, &ids);
                        let [formal, negated, edge] =
                            v.attrs(["formalParameter", "negated", "edge"]);
                        if let Some(x) = point.and_then(|p| expression_of(ctx, p)) {
                            if wires.is_empty() {
                                wires.push(pending_wire(&mut refs, None, x.1));
                                pending.push(Pending::In(refs.ids.len() - 1, x));
                            } else {
                                unread_expression(ctx, &x, "the pin has wires too", pou);
                            }
                        }
                        inputs.push(InPin {
                            name: Cow::Borrowed(trim(formal.unwrap_or_default())),
                            negated: truthy(negated),
                            edge: edge_of(edge),
                            wires,
                            span: ctx.tag(v),
                            in_out,
                        });
                    }
                }
                for v in e
                    .child("outputVariables")
                    .into_iter()
                    .flat_map(|l| l.children_named("variable"))
                {
                    let [formal, negated] = v.attrs(["formalParameter", "negated"]);
                    if let Some(x) = v
                        .child("connectionPointOut")
                        .and_then(|p| expression_of(ctx, p))
                    {
                        pending.push(Pending::Out(
                            Some(Cow::Borrowed(trim(formal.unwrap_or_default()))),
                            x,
                        ));
                    }
                    outputs.push(OutPin {
                        name: Cow::Borrowed(trim(formal.unwrap_or_default())),
                        negated: truthy(negated),
                    });
                }
                let instance = b
                    .map(trim)
                    .filter(|s| !s.is_empty())
                    .map(|s| (Cow::Borrowed(s), ctx.attr_span(e, "instanceName")));
                let type_name: Text = Cow::Borrowed(trim(a.unwrap_or_default()));
                // CODESYS's EXECUTE box runs the ST code of its vendor data
                let code = if type_name.eq_ignore_ascii_case("EXECUTE") {
                    e.children_named("addData")
                        .flat_map(|d| d.children_named("data"))
                        .filter(|d| d.attr("name").is_some_and(|n| n.ends_with("/stcode")))
                        .flat_map(|d| d.children_named("STCode"))
                        .next()
                        .map(crate::il_body::embedded_text)
                } else {
                    None
                };
                Kind::Block(Box::new(Block {
                    type_name,
                    type_span: ctx.attr_span(e, "typeName"),
                    instance,
                    inputs,
                    outputs,
                    code,
                }))
            }
            other => {
                // one error per element name, reported below with the count
                match unsupported.iter_mut().find(|u| u.0 == other) {
                    Some(u) => u.2 += 1,
                    None => unsupported.push((other, (span, local_id), 1)),
                }
                continue;
            }
        };
        let Some(id) = local_id.map(trim).filter(|s| !s.is_empty()) else {
            ctx.error(
                code::E3013,
                span,
                format!("<{}> without a localId", e.name()),
            );
            continue;
        };
        if let Some(prev) = ids.get(id) {
            // one error per reused id, reported below with the number of uses
            match reused.iter_mut().find(|r| r.0 == id) {
                Some(r) => r.3 += 1,
                None => reused.push((id, span, prev, 2)),
            }
            continue;
        }
        let [x, y] = e
            .child("position")
            .map_or([None, None], |p| p.attrs(["x", "y"]));
        let point = e.child("connectionPointIn");
        ids.insert(id, nodes.len());
        let mut input = raw_wires(ctx, point, &mut refs, &ids);
        // a power rail's points carry no value of their own: an expression there means nothing
        let rail_node = matches!(kind, Kind::LeftRail | Kind::RightRail);
        if rail_node {
            for x in e
                .children
                .iter()
                .filter(|p| matches!(p.name(), "connectionPointIn" | "connectionPointOut"))
                .filter_map(|p| expression_of(ctx, p))
                .collect::<Vec<_>>()
            {
                unread_expression(ctx, &x, "a power rail's point carries no value", pou);
            }
        } else if !matches!(kind, Kind::Block(_)) {
            if let Some(x) = point.and_then(|p| expression_of(ctx, p)) {
                if input.is_empty() {
                    input.push(pending_wire(&mut refs, None, x.1));
                    pending.push(Pending::In(refs.ids.len() - 1, x));
                } else {
                    unread_expression(ctx, &x, "the point has wires too", pou);
                }
            }
            if let Some(x) = e
                .child("connectionPointOut")
                .and_then(|p| expression_of(ctx, p))
            {
                pending.push(Pending::Out(None, x));
            }
        }
        let wired = !input.is_empty();
        let exec_order = exec_order.and_then(|v| trim(v).parse().ok());
        numbered.extend(exec_order);
        let (x, y) = (coord(x), coord(y));
        let me = nodes.len();
        nodes.push(Node {
            id: Cow::Borrowed(id),
            num: id.parse().unwrap_or(u64::MAX),
            kind,
            span,
            exec_order,
            x,
            y,
            input,
            has_input: point.is_some(),
            wired,
        });
        // each expression on a connection point becomes the element it stands for: an
        // `<inVariable>` wired into the pin, an `<outVariable>` wired from it
        for (k, p) in pending.into_iter().enumerate() {
            let (kind, input) = match p {
                Pending::In(wire, (expr, expr_span)) => {
                    refs.found[wire] = u32::try_from(nodes.len() + 1).unwrap_or(0);
                    let kind = Kind::InVar {
                        expr,
                        expr_span,
                        negated: false,
                    };
                    (kind, Vec::new())
                }
                Pending::Out(pin, (expr, expr_span)) => {
                    refs.ids.push(id);
                    refs.found.push(u32::try_from(me + 1).unwrap_or(0));
                    let wire = Wire {
                        from: refs.ids.len() - 1,
                        pin,
                        span: expr_span,
                    };
                    let kind = Kind::OutVar {
                        expr,
                        expr_span,
                        negated: false,
                    };
                    (kind, vec![wire])
                }
            };
            let span = match &kind {
                Kind::InVar { expr_span, .. } | Kind::OutVar { expr_span, .. } => *expr_span,
                _ => span,
            };
            let wired = !input.is_empty();
            nodes.push(Node {
                // unique: a localId holds no `#`... and if one does, the generated names differ
                // by the pin's number
                id: Cow::Owned(format!("{id}#{k}")),
                num: u64::MAX,
                kind,
                span,
                exec_order,
                x,
                y,
                input,
                has_input: wired,
                wired,
            });
        }
    }
    if numbered_from_zero(&mut numbered) {
        for n in &mut nodes {
            n.exec_order = n.exec_order.map(|o| o.saturating_add(1));
        }
    }
    for (name, (span, local_id), n) in unsupported {
        let count = if n > 1 {
            format!(" ({n} elements)")
        } else {
            String::new()
        };
        ctx.report(
            Diagnostic::error(
                code::E3012,
                format!("element <{name}> is not supported in a graphical body{count}"),
            )
            .at(span)
            .with_xml(diagnostics::XmlContext {
                pou: Some(pou.to_string()),
                local_id: local_id.map(str::to_string),
                network: None,
            }),
        );
    }
    for (id, span, prev, uses) in reused {
        let prev_span = nodes.get(prev).map_or(span, |n| n.span);
        let times = if uses == 2 {
            "twice".to_string()
        } else {
            format!("{uses} times")
        };
        ctx.report(
            Diagnostic::error(code::E3014, format!("localId {id} is used {times}"))
                .at(span)
                .with_label(prev_span, "first used here")
                .with_xml(diagnostics::XmlContext {
                    pou: Some(pou.to_string()),
                    local_id: Some(id.to_string()),
                    network: None,
                }),
        );
    }
    // Resolve wires in place (`from`: an index in `refs` until now); a dangling one is reported and
    // dropped, in document order: a node's input, then its pins.
    let resolve = |ctx: &mut Ctx, wires: &mut Vec<Wire<'x>>, node_id: &str| {
        wires.retain_mut(|w| {
            if let Some(&k) = refs.found.get(w.from).filter(|&&k| k > 0) {
                w.from = k as usize - 1;
                return true;
            }
            let r = refs.ids[w.from];
            match ids.get(r) {
                Some(from) => {
                    w.from = from;
                    true
                }
                None => {
                    ctx.report(
                        Diagnostic::error(
                            code::E3006,
                            format!("connection to localId {r} which does not exist"),
                        )
                        .at(w.span)
                        .with_primary_label("dangling wire")
                        .with_hint("re-draw the wire in the editor, or set `refLocalId` to the localId of the element that drives it")
                        .with_xml(diagnostics::XmlContext {
                            pou: Some(pou.to_string()),
                            local_id: Some(node_id.to_string()),
                            network: None,
                        }),
                    );
                    false
                }
            }
        });
    };
    // One pass over the nodes (a 10,000-rung body holds 67,500 of them, 9 MB: each further pass
    // misses the cache on every node): their wires resolved, each node joined with its sources in
    // the networks' union-find, connectors and continuations noted.
    let mut parent: Vec<usize> = (0..nodes.len()).collect();
    // A power rail joins no networks: Beremiz and the OpenPLC Editor draw one left rail (and one
    // right rail) for the whole body, each rung on its own connection point, and each rung is a
    // network of its own, evaluated top to bottom (Schneider's IEC LD reference: a network is a group
    // of objects linked together "excluding the power rail", processed "from top to bottom"), so a rung reads the
    // coils written by the rungs above it in the same scan. Joined through the rails, every rung of
    // the body read the values from before the body (interlocked contactors both switched on).
    let rail: Vec<bool> = nodes
        .iter()
        .map(|n| matches!(n.kind, Kind::LeftRail | Kind::RightRail))
        .collect();
    let mut connector_nodes = Vec::new();
    let mut continuation_nodes = Vec::new();
    for (i, n) in nodes.iter_mut().enumerate() {
        resolve(ctx, &mut n.input, &n.id);
        match &mut n.kind {
            Kind::Block(b) => {
                for pin in &mut b.inputs {
                    resolve(ctx, &mut pin.wires, &n.id);
                }
            }
            Kind::Connector { .. } => connector_nodes.push(i),
            Kind::Continuation { .. } => continuation_nodes.push(i),
            _ => {}
        }
        if rail[i] {
            continue;
        }
        for w in n.wires() {
            if !rail.get(w.from).copied().unwrap_or(false) {
                union(i, w.from, &mut parent);
            }
        }
    }
    // Connectors and continuations.
    let mut connectors: FxHashMap<String, Vec<usize>> = FxHashMap::default();
    for &i in &connector_nodes {
        if let Kind::Connector { name } = &nodes[i].kind {
            connectors
                .entry(name.to_ascii_uppercase())
                .or_default()
                .push(i);
        }
    }
    let mut continuation_sources = HashMap::new();
    for &i in &continuation_nodes {
        let n = &nodes[i];
        if let Kind::Continuation { name } = &n.kind {
            match connectors.get(&name.to_ascii_uppercase()) {
                Some(c) => {
                    continuation_sources.insert(i, c.clone());
                }
                None => ctx.report(
                    Diagnostic::error(
                        code::E3006,
                        format!("continuation `{name}` has no connector of that name"),
                    )
                    .at(n.span)
                    .with_hint("add a connector with this name in the same POU, or rename the continuation")
                    .with_xml(diagnostics::XmlContext {
                        pou: Some(pou.to_string()),
                        local_id: Some(n.id.to_string()),
                        network: None,
                    }),
                ),
            }
        }
    }
    let networks = networks(&nodes, parent, &continuation_sources);
    Graph {
        nodes,
        networks,
        continuation_sources,
    }
}

fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

/// Joins the networks of nodes `a` and `b` (union-find over node indices). A root is always the
/// smallest index of its network, whatever order the joins come in.
fn union(a: usize, b: usize, parent: &mut [usize]) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    if ra != rb {
        parent[ra.max(rb)] = ra.min(rb);
    }
}

/// The networks in execution order, from the union-find `parent` of the wires (each node joined
/// with its sources by [`read`]) and the continuations' connectors `conts`.
fn networks(
    nodes: &[Node<'_>],
    mut parent: Vec<usize>,
    conts: &HashMap<usize, Vec<usize>>,
) -> Vec<Vec<usize>> {
    for (c, srcs) in conts {
        for s in srcs {
            union(*c, *s, &mut parent);
        }
    }
    // Groups indexed by their root (a node index): no hashing.
    let mut groups: Vec<Vec<usize>> = vec![Vec::new(); nodes.len()];
    for i in 0..nodes.len() {
        let r = find(&mut parent, i);
        groups[r].push(i);
    }
    // a power rail alone is no network (nothing is computed there; its rungs read it as TRUE)
    let mut nets: Vec<Vec<usize>> = groups
        .into_iter()
        .filter(|g| {
            !g.is_empty()
                && !g
                    .iter()
                    .all(|&i| matches!(nodes[i].kind, Kind::LeftRail | Kind::RightRail))
        })
        .collect();
    crate::network_order::sort(nodes, &mut nets);
    nets
}

/// Strongly connected components (iterative Tarjan) of the subgraph `net` with edges `deps[i]`
/// (`i` depends on each of `deps[i]`). Returns the components with more than one node or a self-loop.
pub fn cycles<S: std::hash::BuildHasher>(
    net: &[usize],
    deps: &HashMap<usize, Vec<usize>, S>,
) -> Vec<Vec<usize>> {
    let mut index: FxHashMap<usize, usize> = FxHashMap::default();
    let mut low: FxHashMap<usize, usize> = FxHashMap::default();
    let mut on_stack: FxHashMap<usize, bool> = FxHashMap::default();
    let mut stack: Vec<usize> = Vec::new();
    let mut out = Vec::new();
    let mut counter = 0;
    let empty = Vec::new();
    for &root in net {
        if index.contains_key(&root) {
            continue;
        }
        let mut work: Vec<(usize, usize)> = vec![(root, 0)];
        while let Some(&(v, child)) = work.last() {
            if child == 0 && !index.contains_key(&v) {
                index.insert(v, counter);
                low.insert(v, counter);
                counter += 1;
                stack.push(v);
                on_stack.insert(v, true);
            }
            let succ = deps.get(&v).unwrap_or(&empty);
            if child < succ.len() {
                let w = succ[child];
                if let Some(top) = work.last_mut() {
                    top.1 += 1;
                }
                if !index.contains_key(&w) {
                    work.push((w, 0));
                } else if on_stack.get(&w).copied().unwrap_or(false) {
                    let lw = index[&w];
                    let lv = low[&v];
                    low.insert(v, lv.min(lw));
                }
                continue;
            }
            work.pop();
            if let Some(&(parent, _)) = work.last() {
                let lv = low[&v];
                let lp = low[&parent];
                low.insert(parent, lp.min(lv));
            }
            if low[&v] == index[&v] {
                let mut comp = Vec::new();
                while let Some(w) = stack.pop() {
                    on_stack.insert(w, false);
                    comp.push(w);
                    if w == v {
                        break;
                    }
                }
                let self_loop = comp.len() == 1 && succ.contains(&v);
                if comp.len() > 1 || self_loop {
                    out.push(comp);
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    /// Wires to elements read before them (resolved as they are read), after them, to a duplicated
    /// localId (its first element), to nothing (E3006, dropped) and to another spelling of a number.
    #[test]
    fn wires_reach_earlier_and_later_elements_alike() {
        let xml = r#"<LD>
<leftPowerRail localId="1"/>
<contact localId="2"><connectionPointIn><connection refLocalId="1"/><connection refLocalId="3"/></connectionPointIn><variable>a</variable></contact>
<contact localId="3"><connectionPointIn><connection refLocalId="2"/><connection refLocalId="9"/></connectionPointIn><variable>b</variable></contact>
<contact localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>c</variable></contact>
<coil localId="x7"><connectionPointIn><connection refLocalId="2"/><connection refLocalId="07"/><connection refLocalId="x7"/></connectionPointIn><variable>q</variable></coil>
<coil localId="07"><connectionPointIn><connection refLocalId="3"/><connection refLocalId="7"/></connectionPointIn><variable>r</variable></coil>
</LD>"#;
        let arena = crate::xml::Arena::new();
        let (root, err) = crate::xml::parse(xml, &arena);
        assert!(err.is_none());
        let mut diags = diagnostics::Diagnostics::default();
        let mut ctx = crate::context::Ctx::new(diagnostics::FileId(0), xml, &mut diags);
        let g = read(&mut ctx, &root.expect("a body"), "P");
        let from = |node: usize| -> Vec<&str> {
            g.nodes[node]
                .input
                .iter()
                .map(|w| g.nodes[w.from].id.as_ref())
                .collect()
        };
        let ids: Vec<&str> = g.nodes.iter().map(|n| n.id.as_ref()).collect();
        assert_eq!(ids, ["1", "2", "3", "x7", "07"]);
        assert_eq!(from(1), ["1", "3"]);
        assert_eq!(from(2), ["2"]);
        assert_eq!(from(3), ["2", "07", "x7"]);
        assert_eq!(from(4), ["3"]);
        let codes: Vec<String> = diags.iter().map(|d| d.code.to_string()).collect();
        // the second localId 2, then the wires to 9 and to 7 (in document order)
        assert_eq!(codes, ["E3014", "E3006", "E3006"]);
    }

    #[test]
    fn local_ids_are_found_as_written_by_number_or_by_name() {
        let mut ids = super::LocalIds::new(4);
        // 4 elements: numbers below 8 * 4 + 64 = 96 are listed, the rest hashed
        for (k, id) in ["1", "07", "95", "96", "x1", "0", "+3", " 5", "123456789012"]
            .into_iter()
            .enumerate()
        {
            assert_eq!(ids.get(id), None, "{id}");
            ids.insert(id, k);
        }
        for (k, id) in ["1", "07", "95", "96", "x1", "0", "+3", " 5", "123456789012"]
            .into_iter()
            .enumerate()
        {
            assert_eq!(ids.get(id), Some(k), "{id}");
        }
        for absent in ["7", "01", "2", "3", "5", "94", "97", "", "x", "00"] {
            assert_eq!(ids.get(absent), None, "{absent}");
        }
        assert_eq!(ids.number("95"), Some(95));
        assert_eq!(ids.number("96"), None);
        assert_eq!(ids.number("07"), None);
    }

    use super::*;

    #[test]
    fn trim_is_str_trim() {
        for s in [
            "",
            "x",
            " x",
            "x ",
            " x ",
            "\u{b}x",
            "x\u{b}",
            "\u{a0}x",
            "x\u{2003}",
            "\u{e9}",
            " \u{e9} ",
            "ab",
            "a b",
            "\t1\n",
            "~",
            "\u{7f}",
            "\u{7f}a",
        ] {
            assert_eq!(trim(s), s.trim(), "{s:?}");
        }
    }

    #[test]
    fn coordinates_round_toward_zero_like_the_float_reading() {
        for (text, want) in [
            ("40", 40),
            (" 7 ", 7),
            ("-12", -12),
            ("12.9", 12),
            ("-12.9", -12),
            ("1e3", 1000),
            ("", 0),
            ("x", 0),
            ("123456789012345", 123_456_789_012_345),
            ("999999999999999", 999_999_999_999_999),
            ("007", 7),
            ("0", 0),
            ("+5", 5),
            ("4 0", 0),
            ("9007199254740993", 9_007_199_254_740_992),
        ] {
            assert_eq!(coord(Some(text)), want, "{text:?}");
        }
        assert_eq!(coord(None), 0);
    }

    #[test]
    fn finds_cycles_only_where_they_are() {
        let mut deps = HashMap::new();
        deps.insert(1, vec![2]);
        deps.insert(2, vec![3]);
        deps.insert(3, vec![1]);
        deps.insert(4, vec![1]);
        deps.insert(5, vec![5]);
        let mut c = cycles(&[1, 2, 3, 4, 5, 6], &deps);
        for comp in &mut c {
            comp.sort();
        }
        c.sort();
        assert_eq!(c, vec![vec![1, 2, 3], vec![5]]);
    }
}
