//! Double coils: one variable written by two plain coils (or output variables) of a graphical body,
//! for [`super`].
//!
//! Input: the body's [`Graph`]. Output: warnings only, the lowering is unchanged. W3400 when two
//! networks write the variable and no network from the first writer's next one up to the second
//! writer's own reads it (the later network wins every scan; a read between, or a read-modify-write
//! `X := X + 1` in the later network, makes the first write count); W1423 when two writers of one
//! network do (the one written last in the network's write order wins every scan, the other never
//! shows). Invariants: set and reset coils are never counted (latching from several rungs is their
//! use); a function box's result under EN is not counted (written only when the box runs); two
//! writers fed by the same power flow (parallel coils on one wire, or one coil behind the other in
//! series) always write the same value and are not reported; each variable is reported at most once
//! per rule.

use super::*;

/// A plain coil or output variable: the variable it writes (key: blanks dropped, upper-cased), as
/// written, and its span.
fn plain_write<'g>(g: &'g Graph, i: usize) -> Option<(String, &'g str, Span)> {
    let (var, span) = match &g.nodes[i].kind {
        Kind::Coil {
            var,
            var_span,
            storage: Storage::None,
            ..
        } => (var, *var_span),
        // written only when a function box under EN runs (see `NetLowering::en_results`): it
        // overrides nothing while the box is off
        Kind::OutVar { .. } if BodyLowering::from_function_under_en(g, i) => return None,
        Kind::OutVar {
            expr, expr_span, ..
        } => (expr, *expr_span),
        _ => return None,
    };
    // Blanks dropped, ASCII upper-cased: one pass, one allocation.
    let mut key = String::with_capacity(var.len());
    key.extend(
        var.chars()
            .filter(|c| !c.is_whitespace())
            .map(|c| c.to_ascii_uppercase()),
    );
    (!key.is_empty()).then(|| (key, var.trim(), span))
}

/// Whether writers `a` and `b` always write the same value: the same wires in (parallel coils on
/// one power flow), or one fed straight from the other (coils in series), neither negated.
fn same_power_flow(g: &Graph, a: usize, b: usize) -> bool {
    let negated = |i: usize| match &g.nodes[i].kind {
        Kind::Coil { negated, edge, .. } => *negated || *edge != Edge::None,
        Kind::OutVar { negated, .. } => *negated,
        _ => true,
    };
    if negated(a) || negated(b) {
        return false;
    }
    let sources = |i: usize| {
        let mut v: Vec<(usize, Option<String>)> = g.nodes[i]
            .input
            .iter()
            .map(|w| {
                (
                    w.from,
                    w.pin.as_ref().map(|p| p.trim().to_ascii_uppercase()),
                )
            })
            .collect();
        v.sort();
        v
    };
    let (sa, sb) = (sources(a), sources(b));
    (!sa.is_empty() && sa == sb)
        || sb.iter().all(|(from, _)| *from == a) && !sb.is_empty()
        || sa.iter().all(|(from, _)| *from == b) && !sa.is_empty()
}

/// What element `i` reads, blanks dropped and upper-cased: a contact's variable, an input or in-out
/// variable's expression (`Sequence = 1`, `X`); `None` for an element that reads no variable by
/// name.
fn read_text(g: &Graph, i: usize) -> Option<String> {
    let text = match &g.nodes[i].kind {
        Kind::Contact { var, .. } => var,
        Kind::InVar { expr, .. } | Kind::InOutVar { expr, .. } => expr,
        _ => return None,
    };
    Some(
        text.chars()
            .filter(|c| !c.is_whitespace())
            .map(|c| c.to_ascii_uppercase())
            .collect(),
    )
}

/// Whether `text` (blanks dropped, upper case) names the variable `key` (same form) as a whole
/// name: not as part of a longer identifier or as a member of another variable (`X` is in `X+1`,
/// `X.Q` and `A[X]`, not in `MAX` or `FB.X`).
fn mentions(text: &str, key: &str) -> bool {
    let name_char = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '%' || c == '#';
    text.match_indices(key).any(|(at, _)| {
        let before = text[..at].chars().next_back();
        let after = text[at + key.len()..].chars().next();
        !before.is_some_and(|c| name_char(c) || c == '.') && !after.is_some_and(name_char)
    })
}

impl BodyLowering<'_> {
    /// W3400 when one variable (or %Q address) is assigned by plain coils or output variables of two
    /// networks: the later network silently overrides the earlier one every scan ("double coil").
    /// Set/reset coils are left alone (latching from several rungs is the normal use).
    pub(super) fn check_double_writes(&self, ctx: &mut Ctx, g: &Graph) {
        // the last plain writer of each variable so far: (network, node)
        let mut first: HashMap<String, (usize, usize)> = HashMap::default();
        let mut warned: HashSet<String> = HashSet::default();
        // what each network reads (contacts, input and in-out variables), blanks dropped, upper case
        let reads: Vec<Vec<String>> = g
            .networks
            .iter()
            .map(|nodes| nodes.iter().filter_map(|&i| read_text(g, i)).collect())
            .collect();
        for (net, nodes) in g.networks.iter().enumerate() {
            for &i in nodes {
                let (var, span) = match &g.nodes[i].kind {
                    Kind::Coil {
                        var,
                        var_span,
                        storage: Storage::None,
                        ..
                    } => (var, *var_span),
                    // written only when a function box under EN runs (see
                    // `NetLowering::en_results`): it overrides nothing while the box is off
                    Kind::OutVar { .. } if BodyLowering::from_function_under_en(g, i) => continue,
                    Kind::OutVar {
                        expr, expr_span, ..
                    } => (expr, *expr_span),
                    _ => continue,
                };
                // Blanks dropped, ASCII upper-cased: one pass, one allocation.
                let mut key = String::with_capacity(var.len());
                key.extend(
                    var.chars()
                        .filter(|c| !c.is_whitespace())
                        .map(|c| c.to_ascii_uppercase()),
                );
                if key.is_empty() {
                    continue;
                }
                match first.get(&key) {
                    None => {
                        first.insert(key, (net, i));
                    }
                    // a network after the first writer (the second writer's own included) reads
                    // the value: the first write is seen (a chain `X := X + 1`, then `X := X * 2`,
                    // as IEC 61131-3 runs networks in order); the later writer is now the one to
                    // compare with
                    Some(&(n0, _))
                        if n0 != net
                            && reads[n0 + 1..=net]
                                .iter()
                                .flatten()
                                .any(|text| mentions(text, &key)) =>
                    {
                        first.insert(key, (net, i));
                    }
                    Some(&(n0, i0)) if n0 != net && !warned.contains(&key) => {
                        warned.insert(key);
                        let at = Where {
                            pou: self.pou.clone(),
                            network: Some(net + 1),
                            local_id: Some(g.nodes[i].id.to_string()),
                        };
                        let first_span = match &g.nodes[i0].kind {
                            Kind::Coil { var_span, .. } => *var_span,
                            Kind::OutVar { expr_span, .. } => *expr_span,
                            _ => span,
                        };
                        ctx.report(
                            Diagnostic::warning(
                                code::W3400,
                                format!(
                                    "`{}` is written by network {} (localId {}) and again by network {}; the later one wins every scan",
                                    var.trim(),
                                    n0 + 1,
                                    g.nodes[i0].id,
                                    net + 1
                                ),
                            )
                            .at(span)
                            .with_primary_label("written again here")
                            .with_label(first_span, "first written here")
                            .with_hint("drive it from one network (OR the conditions), or use set/reset coils")
                            .with_xml(at.xml()),
                        );
                    }
                    _ => {}
                }
            }
        }
    }

    /// W1423 when two plain coils or output variables of one network write the same variable with
    /// different power flows: phase 2 writes them in the network's order (executionOrderId, then
    /// top to bottom, left to right), so the last one's value is the variable's after every scan and
    /// the other rung never shows (Beremiz's generator, which writes coil after coil from the top,
    /// ends with the same value). Often a copy-and-paste slip: a second lamp or contactor meant.
    pub(super) fn check_double_writes_in_networks(&self, ctx: &mut Ctx, g: &Graph) {
        for (net, nodes) in g.networks.iter().enumerate() {
            let mut writers: HashMap<String, Vec<usize>> = HashMap::default();
            let mut keys: Vec<String> = Vec::new();
            for &i in nodes {
                if let Some((key, _, _)) = plain_write(g, i) {
                    let list = writers.entry(key.clone()).or_default();
                    if list.is_empty() {
                        keys.push(key);
                    }
                    list.push(i);
                }
            }
            for key in keys {
                let mut list = writers.remove(&key).unwrap_or_default();
                if list.len() < 2 {
                    continue;
                }
                list.sort_by_key(|&i| g.nodes[i].order_key());
                let last = *list.last().expect("two writers");
                let Some(&hidden) = list[..list.len() - 1]
                    .iter()
                    .rev()
                    .find(|&&i| !same_power_flow(g, i, last))
                else {
                    continue;
                };
                let Some((_, var, span)) = plain_write(g, last) else {
                    continue;
                };
                let hidden_span = plain_write(g, hidden).map_or(span, |w| w.2);
                let at = Where {
                    pou: self.pou.clone(),
                    network: Some(net + 1),
                    local_id: Some(g.nodes[last].id.to_string()),
                };
                ctx.report(
                    Diagnostic::warning(
                        code::W1423,
                        format!(
                            "`{var}` is written twice in network {} (localId {} and {}); the write of localId {} comes last and wins every scan",
                            net + 1,
                            g.nodes[hidden].id,
                            g.nodes[last].id,
                            g.nodes[last].id
                        ),
                    )
                    .at(span)
                    .with_primary_label("written last here")
                    .with_label(hidden_span, "this value never shows")
                    .with_hint("give one of the coils its own variable, or OR both conditions into one coil")
                    .with_xml(at.xml()),
                );
            }
        }
    }
}
