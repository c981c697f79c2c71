//! The order of an LD/FBD body's separate networks (rungs), for [`crate::graph`].
//!
//! Input: the body's nodes and its networks (node indexes, each in increasing order, power rails in
//! none). Output: the same networks sorted into execution order.
//!
//! Order (documented in the README, "The order of separate networks"):
//! 1. networks holding an element with a non-zero `executionOrderId`, by the smallest such id;
//! 2. the others by their place on the sheet, the place of a network being its first *output*
//!    element (coil, output or in-out variable with a wire in, jump, return) in row order: rows top
//!    to bottom, elements less than [`ROW_TOLERANCE`] units apart in y on one row, a row left to
//!    right. This is how Beremiz/OpenPLC Editor write a POU's LD/FBD body as ST (`PLCGenerator.py`,
//!    `ComputeProgram`: the `outVariables&coils` sorted with `SortInstances`, "same row when
//!    `abs(ay - by) < 10`, else by y; on a row by x"), and IEC 61131-3 ed. 2 4.1.3 ("networks are
//!    evaluated top to bottom") read on the rungs, whose coil ends the rung on its row. A network
//!    without an output element (a label, a box whose outputs drive nothing) takes the place of its
//!    top-most, then left-most element;
//! 3. ties by the first element in document order (counting the left rail a rung hangs on), then the
//!    network's first node.
//!
//! Invariants: the sort key is a total order (the rows are fixed once, before sorting: no
//! non-transitive tolerance comparison reaches the sort), and every network keeps its nodes.
//! Limit: a network is run as a whole, so a network whose outputs lie on rows around another
//! network's output runs entirely at its first output's place (Beremiz interleaves the two).

use crate::graph::{Kind, Node};

/// Two elements whose `y` differ by less than this are on one row (Beremiz's `SortInstances`).
pub const ROW_TOLERANCE: i64 = 10;

/// A network's sort key: the smallest non-zero `executionOrderId` (`u32::MAX` without one), the
/// rank of its place, its first element in document order, its first node.
type NetKey = (u32, usize, usize, usize);

/// Whether `n` ends a rung: the elements whose place orders the networks.
fn is_output(n: &Node<'_>) -> bool {
    match n.kind {
        Kind::Coil { .. } | Kind::OutVar { .. } | Kind::Jump { .. } | Kind::Return => true,
        Kind::InOutVar { .. } => n.wired,
        _ => false,
    }
}

/// Sorts `nets` into execution order (see the module header).
pub fn sort(nodes: &[Node<'_>], nets: &mut [Vec<usize>]) {
    // the first element in document order, counting the rail a rung hangs on (a rung drawn
    // after its rail and a label without position keep their document order)
    let first = |net: &Vec<usize>| {
        net.iter()
            .flat_map(|&i| {
                std::iter::once(i).chain(
                    nodes[i]
                        .wires()
                        .map(|w| w.from)
                        .filter(|&f| matches!(nodes[f].kind, Kind::LeftRail)),
                )
            })
            .min()
            .unwrap_or(usize::MAX)
    };
    // The places: every output of every network, or the top-most element of a network without one,
    // as (y, x, network).
    let mut places: Vec<(i64, i64, usize)> = Vec::new();
    for (k, net) in nets.iter().enumerate() {
        let before = places.len();
        places.extend(
            net.iter()
                .filter(|&&i| is_output(&nodes[i]))
                .map(|&i| (nodes[i].y, nodes[i].x, k)),
        );
        if places.len() == before {
            if let Some((y, x)) = net.iter().map(|&i| (nodes[i].y, nodes[i].x)).min() {
                places.push((y, x, k));
            }
        }
    }
    places.sort_unstable();
    // Rows: a row starts at the first place more than the tolerance below the row's first place.
    let mut rows: Vec<(usize, i64, i64, usize)> = Vec::with_capacity(places.len());
    let mut row = 0usize;
    let mut row_top = places.first().map_or(0, |p| p.0);
    for &(y, x, k) in &places {
        if y.saturating_sub(row_top) >= ROW_TOLERANCE {
            row += 1;
            row_top = y;
        }
        rows.push((row, x, y, k));
    }
    rows.sort_unstable();
    // A network's rank: the rank of its first place.
    let mut rank = vec![usize::MAX; nets.len()];
    for (r, &(_, _, _, k)) in rows.iter().enumerate() {
        if rank[k] == usize::MAX {
            rank[k] = r;
        }
    }
    let mut keyed: Vec<(NetKey, Vec<usize>)> = nets
        .iter_mut()
        .enumerate()
        .map(|(k, net)| {
            let exec = net
                .iter()
                .filter_map(|&i| nodes[i].exec_order.filter(|o| *o > 0))
                .min()
                .unwrap_or(u32::MAX);
            let key = (
                exec,
                rank[k],
                first(net),
                net.first().copied().unwrap_or(usize::MAX),
            );
            (key, std::mem::take(net))
        })
        .collect();
    // keys are unique (`net[0]` is in one network only), so the order is the same as a stable sort's
    keyed.sort_unstable_by_key(|(key, _)| *key);
    for (slot, (_, net)) in nets.iter_mut().zip(keyed) {
        *slot = net;
    }
}
