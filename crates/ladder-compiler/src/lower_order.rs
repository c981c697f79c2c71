//! The order of one network's elements, for [`super`]: Kahn's topological order over the wires
//! (block pins, connector/continuation pairs, and a contact or input variable naming an output of a
//! block instance of the same network), ties broken first by where the data flow needs a node (its
//! own `executionOrderId`, or for an unnumbered node the earliest one of the numbered nodes reading
//! it: [`needed_by`]), then by the documented order key.
//!
//! Input: the rung graph, a network's node indexes (increasing) and its implicit dependencies.
//! Output: the nodes in evaluation order, those on a loop left out (the caller then cuts the loop on
//! [`deps_map`] and runs [`kahn`] again). Invariants: the result depends only on the set of (node,
//! source) pairs with their multiplicity, not on the order they come in, so the wires read straight
//! from the graph ([`net_deps`], the usual loop-free network: no list per node) and the map give the
//! same order (tests below).

use super::*;

/// What each node of `net` depends on, as (node, source) pairs: its wires (block pins included), the
/// connectors of a continuation, then the block instance whose output it names (`implicit`), the same
/// pairs as [`deps_map`] holds (in another order, which [`kahn`] does not depend on).
pub(super) fn net_deps<'g>(
    g: &'g Graph,
    net: &'g [usize],
    implicit: &'g HashSet<(usize, usize)>,
) -> impl Iterator<Item = (usize, usize)> + 'g {
    net.iter()
        .flat_map(move |&i| {
            let conts = g
                .continuation_sources
                .get(&i)
                .map_or(&[][..], Vec::as_slice);
            g.nodes[i]
                .wires()
                .map(move |w| (i, w.from))
                .chain(conts.iter().map(move |&s| (i, s)))
        })
        .chain(implicit.iter().copied())
}

/// [`net_deps`] as a map from each node of `net` to its sources in order: the form the loop cutting of
/// [`NetLowering::order`] edits.
pub(super) fn deps_map(
    g: &Graph,
    net: &[usize],
    implicit: &HashSet<(usize, usize)>,
) -> HashMap<usize, Vec<usize>> {
    let mut deps: HashMap<usize, Vec<usize>> =
        HashMap::with_capacity_and_hasher(net.len(), Default::default());
    for &i in net {
        let mut d: Vec<usize> = g.nodes[i].wires().map(|w| w.from).collect();
        if let Some(srcs) = g.continuation_sources.get(&i) {
            d.extend(srcs);
        }
        deps.insert(i, d);
    }
    // one implicit source per node at most (the instance its text names)
    for &(i, b) in implicit {
        deps.entry(i).or_default().push(b);
    }
    deps
}

/// Kahn's algorithm over `net`, ties broken by the documented order key; nodes on a loop are left out.
/// `deps` gives (node, source) pairs; pairs outside `net` are ignored, a repeated pair counts twice.
/// The result does not depend on the order of the pairs (the edges are sorted, the heap orders ties).
pub(super) fn kahn(
    g: &Graph,
    net: &[usize],
    deps: impl IntoIterator<Item = (usize, usize)>,
) -> Vec<usize> {
    // Nodes are numbered by their place in `net` (networks list their nodes in increasing order, see
    // `Graph::networks`), so the counts and the reverse edges are plain lists: no hashing per node.
    debug_assert!(net.windows(2).all(|w| w[0] < w[1]));
    let slot = |i: usize| net.binary_search(&i).ok();
    let mut indeg: Vec<usize> = vec![0; net.len()];
    // Reverse edges as (source slot, user node), grouped by source below.
    // (room for one wire per node, the usual rung: no regrowth)
    let mut edges: Vec<(usize, usize)> = Vec::with_capacity(net.len());
    for (i, s) in deps {
        let Some(ti) = slot(i) else { continue };
        if let Some(si) = slot(s) {
            indeg[ti] += 1;
            edges.push((si, i));
        }
    }
    // Users of each source in any order: the heap decides the order.
    edges.sort_unstable();
    let needed = needed_by(g, net, &edges, &indeg);
    let key = |k: usize, i: usize| (needed[k], g.nodes[i].order_key());
    let mut heap = BinaryHeap::with_capacity(net.len());
    for (k, &i) in net.iter().enumerate() {
        if indeg[k] == 0 {
            heap.push(std::cmp::Reverse((key(k, i), i)));
        }
    }
    let mut order = Vec::with_capacity(net.len());
    while let Some(std::cmp::Reverse((_, i))) = heap.pop() {
        order.push(i);
        let Some(si) = slot(i) else { continue };
        for &(_, u) in users(&edges, si) {
            if let Some(k) = slot(u) {
                indeg[k] -= 1;
                if indeg[k] == 0 {
                    heap.push(std::cmp::Reverse((key(k, u), u)));
                }
            }
        }
    }
    order
}

/// The (source slot, user node) pairs of `edges` (sorted) whose source is slot `si`.
fn users(edges: &[(usize, usize)], si: usize) -> &[(usize, usize)] {
    let from = edges.partition_point(|e| e.0 < si);
    let to = edges.partition_point(|e| e.0 <= si);
    &edges[from..to]
}

/// For each node of `net` (by slot), the position in the execution order where the data flow first
/// needs it: its own `executionOrderId` when it has one, else the earliest one among the elements
/// that read its value, directly or through other unnumbered elements (`u32::MAX` when none does).
/// [`kahn`] orders the ready nodes by this first, so an unnumbered element (an input variable, a
/// connector, a contact) is evaluated just before the first numbered element that reads it, after
/// the numbered elements before that one: a variable written by the element numbered 0 and read
/// through an unnumbered input variable by the element numbered 1 is read after the write. This is
/// RuSTy's rule (its `plc_xml` crate turns only numbered elements into statements and writes the
/// unnumbered ones into them as expressions) and CODESYS's ("Dialog: Properties: CFC Execution
/// Order": "The POUs and the outputs are numbered internally"; inputs have no number and are read
/// by the element they feed). A body with no number, or with every element numbered, keeps the
/// plain order key (Beremiz's all-zero files).
/// `edges` holds the (source slot, user node) pairs sorted, `indeg` each slot's count of sources.
fn needed_by(g: &Graph, net: &[usize], edges: &[(usize, usize)], indeg: &[usize]) -> Vec<u32> {
    let own: Vec<u32> = net.iter().map(|&i| g.nodes[i].order_key().0).collect();
    let numbered = own.iter().filter(|&&o| o != u32::MAX).count();
    if numbered == 0 || numbered == own.len() {
        return own;
    }
    let slot = |i: usize| net.binary_search(&i).ok();
    // A topological order of the slots (nodes on a loop are left out and keep their own number).
    let mut indeg = indeg.to_vec();
    let mut topo: Vec<usize> = (0..net.len()).filter(|&k| indeg[k] == 0).collect();
    let mut next = 0;
    while let Some(&si) = topo.get(next) {
        next += 1;
        for &(_, u) in users(edges, si) {
            if let Some(k) = slot(u) {
                indeg[k] -= 1;
                if indeg[k] == 0 {
                    topo.push(k);
                }
            }
        }
    }
    // Users come after their sources in `topo`: walking it backwards, each user's need is final
    // before its sources read it.
    let mut needed = own.clone();
    for &si in topo.iter().rev() {
        if own[si] != u32::MAX {
            continue;
        }
        needed[si] = users(edges, si)
            .iter()
            .filter_map(|&(_, u)| slot(u))
            .map(|k| needed[k])
            .min()
            .unwrap_or(u32::MAX);
    }
    needed
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::Ctx;
    use crate::xml;
    use diagnostics::{Diagnostics, FileId};

    /// Every network of `xml`'s LD/FBD bodies: the order from the wires read straight from the graph
    /// equals the order from the map, and from the map's pairs in reverse.
    fn orders_agree(text: &str) -> usize {
        let arena = xml::Arena::new();
        let (root, _) = xml::parse(text, &arena);
        let root = root.expect("a document");
        let mut diags = Diagnostics::default();
        let mut ctx = Ctx::new(FileId(0), text, &mut diags);
        let mut checked = 0;
        for body in root
            .walk()
            .filter(|e| e.name() == "LD" || e.name() == "FBD")
        {
            let g = graph::read(&mut ctx, body, "P");
            for net in &g.networks {
                // every second node of a network "names" the first node's instance: implicit pairs too
                let implicit: HashSet<(usize, usize)> = net
                    .iter()
                    .skip(1)
                    .step_by(2)
                    .map(|&i| (i, net[0]))
                    .collect();
                let direct = kahn(&g, net, net_deps(&g, net, &implicit));
                let map = deps_map(&g, net, &implicit);
                let mut pairs: Vec<(usize, usize)> = map
                    .iter()
                    .flat_map(|(&i, d)| d.iter().map(move |&s| (i, s)))
                    .collect();
                assert_eq!(direct, kahn(&g, net, pairs.iter().copied()));
                pairs.reverse();
                assert_eq!(direct, kahn(&g, net, pairs));
                let mut direct_pairs: Vec<_> = net_deps(&g, net, &implicit).collect();
                let mut map_pairs: Vec<_> = map
                    .iter()
                    .flat_map(|(&i, d)| d.iter().map(move |&s| (i, s)))
                    .collect();
                direct_pairs.sort_unstable();
                map_pairs.sort_unstable();
                assert_eq!(direct_pairs, map_pairs);
                checked += 1;
            }
        }
        checked
    }

    #[test]
    fn wires_read_straight_from_the_graph_order_like_the_map() {
        assert!(orders_agree(&crate::testgen::generate(40)) >= 40);
    }

    #[test]
    fn wires_read_straight_from_the_graph_order_like_the_map_on_every_fixture() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let mut files = Vec::new();
        // the repository's XML and, when `LADDERC_CORPUS` names it, the real-world corpus
        let mut dirs = vec![
            root.join("tests"),
            root.join("examples"),
            root.join("crates"),
        ];
        dirs.extend(std::env::var_os("LADDERC_CORPUS").map(std::path::PathBuf::from));
        while let Some(d) = dirs.pop() {
            for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {
                let p = e.path();
                if p.is_dir() && !p.ends_with("target") {
                    dirs.push(p);
                } else if p.extension().is_some_and(|x| x == "xml") {
                    files.push(p);
                }
            }
        }
        let mut networks = 0;
        for f in files {
            let Ok(text) = std::fs::read_to_string(&f) else {
                continue;
            };
            if xml::parse(&text, &xml::Arena::new()).1.is_some() {
                continue;
            }
            networks += orders_agree(&text);
        }
        assert!(networks > 60, "only {networks} networks in the fixtures");
    }
}
