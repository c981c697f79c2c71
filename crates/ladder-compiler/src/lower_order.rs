//! The order of one network's elements, for [`super`]: Kahn's topological order over the wires
//! (block pins, connector/continuation pairs, and a contact or input variable naming an output of a
//! block instance of the same network), ties broken by the documented order key.
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
    let mut heap = BinaryHeap::with_capacity(net.len());
    for (k, &i) in net.iter().enumerate() {
        if indeg[k] == 0 {
            heap.push(std::cmp::Reverse((g.nodes[i].order_key(), i)));
        }
    }
    let mut order = Vec::with_capacity(net.len());
    while let Some(std::cmp::Reverse((_, i))) = heap.pop() {
        order.push(i);
        let Some(si) = slot(i) else { continue };
        let from = edges.partition_point(|e| e.0 < si);
        for &(s, u) in &edges[from..] {
            if s != si {
                break;
            }
            if let Some(k) = slot(u) {
                indeg[k] -= 1;
                if indeg[k] == 0 {
                    heap.push(std::cmp::Reverse((g.nodes[u].order_key(), u)));
                }
            }
        }
    }
    order
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
