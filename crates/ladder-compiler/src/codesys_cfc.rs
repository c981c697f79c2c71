//! CODESYS V3 CFC bodies in a PLCopen XML export: read as FBD in CODESYS's execution order.
//!
//! TC6 XML has no CFC body. CODESYS V3 ("Export PLCopenXML") writes a POU or action drawn in the
//! Continuous Function Chart editor as an empty `<ST>` body (or none) followed by the chart in
//! vendor data: `<body><ST><xhtml/></ST><addData><data
//! name="http://www.3s-software.com/plcopenxml/cfc"><CFC>...</CFC></data></addData></body>`. The
//! chart's elements are FBD's (`inVariable`, `outVariable`, `inOutVariable`, `block`, `connector`,
//! `continuation`, `jump`, `label`, `return`, `comment`), each executing one with its
//! `executionOrderId` (from 0), and its wires pass through unnamed wire points: a `<connector>`
//! that no `<continuation>` continues, whose input `<connection>` names the source's output pin in
//! `formalParameter` (the variable's name for an input variable, `""` for an operator's result).
//!
//! [`read`] collapses the chart into [`crate::graph`]'s model: wire points are bypassed (a wire
//! into one comes from its source, with the source's pin), a function block's output read
//! anywhere is the instance's output variable (`TON_0.Q`, an input variable: it holds what the
//! call wrote, the previous cycle's value when the reader runs before the box), and every
//! executing element is a network of its own with the operator and function boxes that feed it;
//! the networks run in `executionOrderId` order, as CODESYS runs the chart (CODESYS online help,
//! "CFC Execution Order": in both the auto data flow mode and the explicit execution order mode
//! the elements are numbered and run in that order; "Automatic Execution Order by Data Flow").
//! Where that cannot be kept exactly (an operator box that runs after an element reading its
//! result; one operator box feeding elements between which other elements run) it is W1448 at
//! the element, and the boxes run where their result is read.
//! [`unread_charts`] reports the charts no reader reads (a method's, a transition's: E0321).
//!
//! Input: a body's `<CFC>` element, or the root element of a PLCopen project. Output: a
//! [`Graph`]; E0321 per unread chart at its `<CFC>` (or its `<data>`), naming what owns it, and the
//! `<data>` elements of every chart, which the project's W3002 (vendor data ignored) leaves out.
//! Invariants: never panics; walks are iterative, a chain of wire points is followed at most as
//! many steps as the chart has elements (a loop of them is E1059); every element is located in
//! diagnostics by POU and localId; an element the FBD reader does not know is its E3012; wire
//! points belong to no network.

use crate::context::Ctx;
use crate::graph::{self, Graph, Kind, Node, Wire};
use crate::xml::Element;
use diagnostics::{code, Diagnostic, Span, XmlContext};
use std::borrow::Cow;
use std::collections::{HashMap, HashSet};

/// The `name` of the vendor data that holds a CODESYS CFC chart.
const CFC_DATA: &str = "http://www.3s-software.com/plcopenxml/cfc";

/// A node's order key ([`Node::order_key`]).
type OrderKey = (u32, i64, i64, u64);

/// What owns a body: its kind (`POU`, `action`, ...) and its name.
type Owner<'a> = (&'static str, &'a str);

/// Reports every CODESYS CFC chart of the project that [`read`] does not read (E0321) and returns
/// the tag starts of the `<data>` elements of all charts.
pub(crate) fn unread_charts(ctx: &mut Ctx, root: &Element) -> HashSet<usize> {
    let mut reported = HashSet::new();
    // (element, what owns the bodies below it: kind and name; the POU it is in; whether a body
    // directly below it is read by `crate::body`: a POU's, and an action's of a POU whose body is
    // not SFC)
    let mut stack: Vec<(&Element, Option<Owner>, Option<&str>, bool)> =
        vec![(root, None, None, false)];
    while let Some((e, owner, pou, body_read)) = stack.pop() {
        let owner = match (owner_kind(e.name()), e.attr("name")) {
            (Some(kind), Some(name)) => Some((kind, name.trim())),
            _ => owner,
        };
        let pou = match (e.name(), e.attr("name")) {
            ("pou", Some(name)) => Some(name.trim()),
            _ => pou,
        };
        if e.name() == "body" && body_read && body_chart(e).is_some() {
            // read as FBD by `crate::body`
            reported.extend(charts_data(e).map(Element::tag_start));
        } else if e.name() == "body" {
            for data in e
                .children_named("addData")
                .flat_map(|a| a.children_named("data"))
                .filter(|d| d.attr("name").map(str::trim) == Some(CFC_DATA))
            {
                reported.insert(data.tag_start());
                let at = data.child("CFC").unwrap_or(data);
                let (kind, name) = owner.unwrap_or(("POU", "?"));
                ctx.report(
                    Diagnostic::error(
                        code::E0321,
                        format!(
                            "the body of {kind} `{name}` is a CODESYS CFC chart, which ladderc does not read: it is not compiled"
                        ),
                    )
                    .at(ctx.tag(at))
                    .with_primary_label("CODESYS's CFC chart (vendor data; the <ST> body beside it is empty)")
                    .with_xml(XmlContext {
                        pou: Some(pou.unwrap_or(name).to_string()),
                        ..Default::default()
                    })
                    .with_hint("draw the body in FBD or LD, or write it in ST or IL, in CODESYS and export PLCopen XML again: ladderc reads those"),
                );
            }
        }
        let sfc_pou = e.name() == "pou" && language(e.child("body")) == Some("SFC");
        stack.extend(e.children.iter().rev().map(|c| {
            // for an action (and its `<actions>`): whether its POU's body is not SFC (the actions
            // of an SFC body are its chart's); for a body: whether `crate::body` reads it
            let read = match (e.name(), c.name()) {
                ("pou", "body") => true,
                ("pou", "actions") => !sfc_pou,
                ("actions", "action") | ("action", "body") => body_read,
                _ => false,
            };
            (c, owner, pou, read)
        }));
    }
    reported
}

/// The `<data>` elements of `body` that hold a CODESYS CFC chart.
fn charts_data<'e, 'x>(body: &'e Element<'x>) -> impl Iterator<Item = &'e Element<'x>> {
    body.children_named("addData")
        .flat_map(|a| a.children_named("data"))
        .filter(|d| d.attr("name").map(str::trim) == Some(CFC_DATA))
}

/// The name of a body's language element (`ST`, `FBD`, `SFC`, ...), if it has one.
fn language<'e>(body: Option<&'e Element>) -> Option<&'e str> {
    body?
        .children
        .iter()
        .find(|c| !matches!(c.name(), "documentation" | "addData"))
        .map(Element::name)
}

/// The CODESYS CFC chart that is the body `body`: its `<CFC>` element, when the body's vendor data
/// holds one and the body has no language element or an `<ST>` without text (CODESYS's
/// placeholder). A chart beside a written body is not it (E0321 by [`unread_charts`]).
pub(crate) fn body_chart<'e, 'x>(body: &'e Element<'x>) -> Option<&'e Element<'x>> {
    let chart = charts_data(body).find_map(|d| d.child("CFC"))?;
    let lang = body
        .children
        .iter()
        .find(|c| !matches!(c.name(), "documentation" | "addData"));
    match lang {
        None => Some(chart),
        Some(st)
            if st.name() == "ST"
                && std::iter::once(st)
                    .chain(st.walk())
                    .all(|e| e.text_ref().trim().is_empty()) =>
        {
            Some(chart)
        }
        Some(_) => None,
    }
}

/// Reads the chart `cfc` (see [`body_chart`]) of POU `pou` as an FBD graph whose networks run in
/// the chart's execution order (module header).
pub(crate) fn read<'x>(ctx: &mut Ctx, cfc: &Element<'x>, pou: &str) -> Graph<'x> {
    let mut g = graph::read(ctx, cfc, pou);
    // CODESYS numbers from 0; the FBD model counts 0 as "no number" (`graph::read` has already
    // raised a chart numbered 0..n with distinct ids; raising every id once more keeps the order,
    // and covers a chart of one element or with a repeated id)
    for n in &mut g.nodes {
        n.exec_order = n.exec_order.map(|o| o.saturating_add(1));
    }
    let points = wire_points(&g);
    bypass_wire_points(ctx, &mut g, &points, pou);
    read_instance_outputs(&mut g);
    g.networks = networks(ctx, &g, &points, pou);
    g
}

/// Located diagnostic context: the POU and the element's localId.
fn at(pou: &str, node: &Node) -> XmlContext {
    XmlContext {
        pou: Some(pou.to_string()),
        local_id: Some(node.id.to_string()),
        network: None,
    }
}

/// The wire points of the chart: the `<connector>`s that no `<continuation>` continues.
fn wire_points(g: &Graph) -> HashSet<usize> {
    let continued: HashSet<usize> = g.continuation_sources.values().flatten().copied().collect();
    (0..g.nodes.len())
        .filter(|i| matches!(g.nodes[*i].kind, Kind::Connector { .. }) && !continued.contains(i))
        .collect()
}

/// Every wire from a wire point comes from the point's source instead, with the source's pin (an
/// operator's `""` is its one result, an input variable's pin is its name: no pin).
fn bypass_wire_points(ctx: &mut Ctx, g: &mut Graph, points: &HashSet<usize>, pou: &str) {
    let limit = g.nodes.len();
    // the source of each wire point, followed through chains of points
    let mut source: HashMap<usize, Option<Wire>> = HashMap::new();
    let mut sorted: Vec<usize> = points.iter().copied().collect();
    sorted.sort_unstable();
    for &p in &sorted {
        let mut at_point = p;
        let mut found = None;
        for _ in 0..=limit {
            let n = &g.nodes[at_point];
            let [w] = n.input.as_slice() else {
                break;
            };
            if points.contains(&w.from) {
                at_point = w.from;
                continue;
            }
            found = Some(w.clone());
            break;
        }
        if found.is_none() {
            let n = &g.nodes[p];
            let why = if n.input.len() > 1 {
                "is wired to several sources"
            } else if n.input.is_empty() {
                "is wired to no source"
            } else {
                "leads to a wire point without one source, or is on a loop of wire points"
            };
            ctx.report(
                Diagnostic::error(
                    code::E1059,
                    format!("CFC wire point (connector, localId {}) {why}", n.id),
                )
                .at(n.span)
                .with_primary_label("a <connector> without continuation: a point on a wire")
                .with_xml(at(pou, n))
                .with_hint("open the chart in CODESYS, draw the wire from one output to this input again and export PLCopen XML again"),
            );
        }
        source.insert(p, found);
    }
    for w in g.nodes.iter_mut().flat_map(node_wires) {
        // a point without source was reported above; its consumer reads nothing
        if let Some(Some(src)) = source.get(&w.from) {
            w.from = src.from;
            w.pin = src.pin.clone();
        }
    }
    // the pin of a wire from anything but a block names no output; `""` is the block's result
    let single: Vec<bool> = g
        .nodes
        .iter()
        .map(|n| !matches!(n.kind, Kind::Block(_)))
        .collect();
    for w in g.nodes.iter_mut().flat_map(node_wires) {
        if single[w.from] || w.pin.as_deref().is_some_and(|p| p.trim().is_empty()) {
            w.pin = None;
        }
    }
}

/// The wires into a node, mutable: its input and its block pins.
fn node_wires<'n, 'x>(n: &'n mut Node<'x>) -> impl Iterator<Item = &'n mut Wire<'x>> {
    let pins: &mut [graph::InPin<'x>] = match &mut n.kind {
        Kind::Block(b) => &mut b.inputs,
        _ => &mut [],
    };
    n.input
        .iter_mut()
        .chain(pins.iter_mut().flat_map(|p| p.wires.iter_mut()))
}

/// A wire from an output of a function block instance reads the instance's output variable
/// (`TON_0.Q`): a new input variable node, so the box runs at its own place in the execution order
/// and its reader at its own, before or after it.
fn read_instance_outputs(g: &mut Graph) {
    for i in 0..g.nodes.len() {
        let wires: Vec<(usize, usize)> = {
            let n = &g.nodes[i];
            let pins: &[graph::InPin] = match &n.kind {
                Kind::Block(b) => &b.inputs,
                _ => &[],
            };
            let mut out = Vec::new();
            for (k, w) in n
                .input
                .iter()
                .chain(pins.iter().flat_map(|p| p.wires.iter()))
                .enumerate()
            {
                if matches!(&g.nodes[w.from].kind, Kind::Block(b) if b.instance.is_some()) {
                    out.push((k, w.from));
                }
            }
            out
        };
        for (k, src) in wires {
            let Some((var, negated, span)) = ({
                let Kind::Block(b) = &g.nodes[src].kind else {
                    continue;
                };
                let Some(w) = node_wire(&g.nodes[i], k) else {
                    continue;
                };
                let out = match &w.pin {
                    Some(p) => b
                        .outputs
                        .iter()
                        .find(|o| o.name.eq_ignore_ascii_case(p.trim())),
                    None => b.outputs.first(),
                };
                let pin = w.pin.clone().or_else(|| out.map(|o| o.name.clone()));
                b.instance.as_ref().zip(pin).map(|((inst, _), pin)| {
                    (
                        format!("{}.{}", inst.trim(), pin.trim()),
                        out.is_some_and(|o| o.negated),
                        w.span,
                    )
                })
            }) else {
                continue;
            };
            let s = &g.nodes[src];
            let node = Node {
                id: s.id.clone(),
                num: s.num,
                kind: Kind::InVar {
                    expr: Cow::Owned(var),
                    expr_span: span,
                    negated,
                },
                span: s.span,
                exec_order: None,
                x: s.x,
                y: s.y,
                input: Vec::new(),
                has_input: false,
                wired: false,
            };
            g.nodes.push(node);
            let new = g.nodes.len() - 1;
            if let Some(w) = node_wires(&mut g.nodes[i]).nth(k) {
                w.from = new;
                w.pin = None;
            }
        }
    }
}

/// The `k`-th wire into node `n` (input, then block pins).
fn node_wire<'n, 'x>(n: &'n Node<'x>, k: usize) -> Option<&'n Wire<'x>> {
    n.wires().nth(k)
}

/// Whether node `n` runs at its own place in the execution order: a function block call, a
/// variable written, a jump, label or return, an operator or function box whose result no element
/// reads (called for its effect).
fn executes(g: &Graph, read: &HashSet<usize>, n: usize) -> bool {
    match &g.nodes[n].kind {
        Kind::Block(b) => b.instance.is_some() || !read.contains(&n),
        Kind::OutVar { .. }
        | Kind::InOutVar { .. }
        | Kind::Jump { .. }
        | Kind::Label { .. }
        | Kind::Return
        | Kind::Connector { .. } => true,
        _ => false,
    }
}

/// The networks: each executing element with the elements that feed it (operator and function
/// boxes, input variables), joined where one feeds several, in the order of their first executing
/// element's `executionOrderId`, then by position; W1448 where that order cannot be kept.
fn networks(ctx: &mut Ctx, g: &Graph, points: &HashSet<usize>, pou: &str) -> Vec<Vec<usize>> {
    let n = g.nodes.len();
    let mut parent: Vec<usize> = (0..n).collect();
    let mut read: HashSet<usize> = HashSet::new();
    for (i, node) in g.nodes.iter().enumerate() {
        if points.contains(&i) {
            continue;
        }
        for w in node.wires() {
            if !points.contains(&w.from) {
                union(&mut parent, i, w.from);
                read.insert(w.from);
            }
        }
    }
    for (c, srcs) in &g.continuation_sources {
        for s in srcs {
            union(&mut parent, *c, *s);
        }
    }
    let mut groups: Vec<Vec<usize>> = vec![Vec::new(); n];
    for i in 0..n {
        if !points.contains(&i) {
            let r = find(&mut parent, i);
            groups[r].push(i);
        }
    }
    let mut nets: Vec<(u32, OrderKey, Vec<usize>)> = groups
        .into_iter()
        .filter(|net| !net.is_empty())
        .map(|net| {
            let first = net
                .iter()
                .filter(|&&i| executes(g, &read, i))
                .filter_map(|&i| g.nodes[i].exec_order)
                .min()
                .unwrap_or(u32::MAX);
            let key = net
                .iter()
                .map(|&i| g.nodes[i].order_key())
                .min()
                .unwrap_or((u32::MAX, 0, 0, 0));
            (first, key, net)
        })
        .collect();
    nets.sort_by_key(|a| (a.0, a.1));
    // where the order is not kept: an element of another network runs between two executing
    // elements of one network; a box runs after an element that reads its result
    let ranges: Vec<(u32, u32)> = nets
        .iter()
        .map(|(_, _, net)| {
            let orders = net
                .iter()
                .filter(|&&i| executes(g, &read, i))
                .filter_map(|&i| g.nodes[i].exec_order);
            (orders.clone().min().unwrap_or(0), orders.max().unwrap_or(0))
        })
        .collect();
    for (k, (_, _, net)) in nets.iter().enumerate() {
        let (lo, hi) = ranges[k];
        let between = nets.iter().enumerate().find_map(|(j, (_, _, other))| {
            (j != k)
                .then(|| {
                    other.iter().copied().find(|&i| {
                        executes(g, &read, i)
                            && g.nodes[i].exec_order.is_some_and(|o| o > lo && o < hi)
                    })
                })
                .flatten()
        });
        if let Some(other) = between {
            let last = net
                .iter()
                .copied()
                .filter(|&i| executes(g, &read, i))
                .max_by_key(|&i| g.nodes[i].exec_order)
                .unwrap_or(net[0]);
            order_not_kept(
                ctx,
                g,
                last,
                pou,
                format!(
                    "it runs with the elements it shares an operator box with, before localId {} that CODESYS runs first",
                    g.nodes[other].id
                ),
            );
        }
        for &i in net {
            let (Kind::Block(_), Some(o)) = (&g.nodes[i].kind, g.nodes[i].exec_order) else {
                continue;
            };
            if executes(g, &read, i) {
                continue;
            }
            let earlier = net.iter().copied().find(|&c| {
                g.nodes[c].wires().any(|w| w.from == i)
                    && g.nodes[c].exec_order.is_some_and(|co| co < o)
            });
            if let Some(c) = earlier {
                order_not_kept(
                    ctx,
                    g,
                    i,
                    pou,
                    format!(
                        "localId {} reads its result before it runs: ladderc computes it there, CODESYS reads the result of the previous cycle",
                        g.nodes[c].id
                    ),
                );
            }
        }
    }
    nets.into_iter().map(|(_, _, net)| net).collect()
}

/// W1448 at node `i`.
fn order_not_kept(ctx: &mut Ctx, g: &Graph, i: usize, pou: &str, why: String) {
    let n = &g.nodes[i];
    let span: Span = n.span;
    ctx.report(
        Diagnostic::warning(
            code::W1448,
            format!(
                "CFC element localId {} does not run exactly at its executionOrderId: {why}",
                n.id
            ),
        )
        .at(span)
        .with_primary_label("its place in CODESYS's execution order")
        .with_xml(at(pou, n))
        .with_hint("in CODESYS, order the chart by data flow (CFC > Execution Order > Order by Data Flow) or store the box's result in a variable, and export PLCopen XML again"),
    );
}

fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

fn union(parent: &mut [usize], a: usize, b: usize) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    if ra != rb {
        parent[ra.max(rb)] = ra.min(rb);
    }
}

/// The words a diagnostic names an element with a body by (`pou`, `action`, `transition`, and a
/// CODESYS method or property accessor's `Method` / `Property`), or `None`.
fn owner_kind(element: &str) -> Option<&'static str> {
    match element {
        "pou" => Some("POU"),
        "action" => Some("action"),
        "transition" => Some("transition"),
        "Method" => Some("method"),
        "Property" => Some("property"),
        _ => None,
    }
}
