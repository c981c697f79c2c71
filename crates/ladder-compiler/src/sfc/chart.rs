//! The chart of an `<SFC>` body: steps, transitions with the steps before and after them, action
//! associations, and the LD/FBD elements that feed connection-based conditions.
//!
//! Input: the `<SFC>` element. Output: a [`Chart`] where every transition knows its predecessor steps
//! (through selection divergences and simultaneous convergences) and its successor steps (through
//! selection convergences, simultaneous divergences and jump steps), in priority order. A transition
//! after a selection convergence of steps and jump steps (CODESYS's alternative branches) is one
//! transition per step (`<id>`, `<id>_1` ...), the jumps left out. A jump that ends a branch of a
//! simultaneous sequence and loops back into that branch is left out of the simultaneous convergence
//! it is connected to (see `pre_steps`).
//! Invariants: only well-formed parts are kept: a transition whose predecessors or successors cannot be
//! resolved is reported (E3120 dangling connection, E3128 invalid structure) and dropped; every step
//! index in the chart is valid; step names are unique identifiers (E3131).

use crate::context::Ctx;
use crate::xml::Element;
use diagnostics::{code, Code, Diagnostic, Span, XmlContext};
use std::collections::{HashMap, HashSet};

/// The SFC element kinds (everything else in the body is an LD/FBD element).
pub const SFC_ELEMENTS: &[&str] = &[
    "step",
    "macroStep",
    "transition",
    "selectionDivergence",
    "selectionConvergence",
    "simultaneousDivergence",
    "simultaneousConvergence",
    "jumpStep",
    "actionBlock",
];

/// One `<step>` of the chart (IEC 61131-3 2.6.2): its flag `Step.X` and elapsed time `Step.T` become hidden
/// variables.
#[derive(Debug, Clone)]
pub struct Step {
    /// The `localId` attribute.
    pub id: String,
    /// The `name` attribute: the step's identifier (unique in the chart, E3131).
    pub name: String,
    /// `initialStep="true"`: active at the first scan.
    pub initial: bool,
    /// The `<step>` start tag.
    pub span: Span,
}

/// Where a transition's condition comes from.
#[derive(Debug, Clone, Copy)]
pub enum CondSource<'e, 'a> {
    /// `<inline>` body (its language element) and the inline's name (may be empty).
    Inline(&'e Element<'a>, &'e str),
    /// `<reference name="..">`: a named transition of the POU (or a BOOL variable).
    Reference(&'e str, Span),
    /// `<connectionPointIn>` wired to LD/FBD elements of the SFC body.
    Connection(&'e Element<'a>),
}

/// One `<transition>`: fires when all its predecessor steps are active and its condition is TRUE.
#[derive(Debug, Clone)]
pub struct Transition<'e, 'a> {
    /// The `localId` attribute.
    pub id: String,
    /// The `<transition>` start tag.
    pub span: Span,
    /// Where the condition comes from.
    pub cond: CondSource<'e, 'a>,
    /// Predecessor steps (all must be active), indexes into [`Chart::steps`].
    pub pre: Vec<usize>,
    /// Successor steps (all activated when it fires).
    pub post: Vec<usize>,
    /// `(priority attribute, non-zero executionOrderId, x, y, localId)`: smaller first.
    pub order: (u32, u32, i64, i64, u64),
}

/// One `<action>` of an action block.
#[derive(Debug, Clone)]
pub struct Association<'e, 'a> {
    /// The step (index into [`Chart::steps`]) whose action block holds the action.
    pub step: usize,
    /// The `localId` of the `<actionBlock>`.
    pub block_id: String,
    /// Position of the action in its block (0-based).
    pub index: usize,
    /// The `<action>` element (qualifier, duration, reference or inline body).
    pub el: &'e Element<'a>,
    /// A CODESYS step action of the step's vendor data instead (`el` is then its `<attribute>`,
    /// whose text names the action): which one.
    pub vendor: Option<StepAction>,
}

/// The actions CODESYS attaches to a step in its vendor data (`addData/data[.../sfc/element]`,
/// attributes by GUID), run as IEC qualifiers: entry (P1), the step action (while the step is
/// active, without the final scan of N) and exit (P0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum StepAction {
    /// Run once when the step is left (CODESYS runs every exit first).
    Exit,
    /// Run once when the step becomes active.
    Entry,
    /// Run in every scan the step is active.
    Active,
}

impl StepAction {
    /// CODESYS's attribute GUIDs (`.../sfc/element` vendor data of a `<step>`).
    const GUIDS: [(&'static str, StepAction); 3] = [
        ("a2621e18-7de3-4ea6-ae6d-89e9e0b7befd", StepAction::Exit),
        ("a6b08bd8-b696-47e3-9cbf-7408b61c9ff8", StepAction::Entry),
        ("700a583f-b4d4-43e4-8c14-629c7cd3bec8", StepAction::Active),
    ];
    /// How the engineer calls it.
    pub fn describe(self) -> &'static str {
        match self {
            StepAction::Exit => "exit action",
            StepAction::Entry => "entry action",
            StepAction::Active => "step action",
        }
    }
}

/// The CODESYS step actions of a `<step>` (see [`StepAction`]), with the `<attribute>` naming each.
fn step_actions<'e, 'a>(step: &'e Element<'a>) -> Vec<(StepAction, &'e Element<'a>)> {
    let mut out = Vec::new();
    for data in step
        .children_named("addData")
        .flat_map(|d| d.children_named("data"))
        .filter(|d| d.attr("name").is_some_and(|n| n.ends_with("/sfc/element")))
    {
        for attr in data
            .children_named("attributes")
            .flat_map(|a| a.children_named("attribute"))
        {
            let Some(guid) = attr.attr("guid") else {
                continue;
            };
            if let Some((_, k)) = StepAction::GUIDS.iter().find(|(g, _)| *g == guid.trim()) {
                if !attr.text_ref().trim().is_empty() {
                    out.push((*k, attr));
                }
            }
        }
    }
    out
}

/// An `<SFC>` body read as a chart: [`super::chart`]'s output, read by the SFC lowering.
pub struct Chart<'e, 'a> {
    /// The steps in document order; every step index in the chart points here.
    pub steps: Vec<Step>,
    /// In priority order (see [`Transition::order`]).
    pub transitions: Vec<Transition<'e, 'a>>,
    /// In action block order (non-zero executionOrderId, y, x, localId), then in block order.
    pub associations: Vec<Association<'e, 'a>>,
    /// The LD/FBD elements of the body (for connection-based conditions).
    pub network_elements: Vec<Element<'a>>,
    /// The SFC flags the export enables for the chart (CODESYS vendor data of the POU or action,
    /// [`super::flags::read`]); empty when read from the body alone.
    pub flags: Vec<super::flags::Flag>,
    /// In which order a scan runs the chart's transitions and actions.
    pub order: ScanOrder,
}

/// In which order one scan of a chart evaluates its transitions and runs its actions. IEC 61131-3
/// leaves it open (ed. 2 2.6.5 only says a step activated by a transition becomes active and its
/// actions run; it fixes no scan for that).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ScanOrder {
    /// ladderc's order for PLCopen XML and textual charts: the transitions are evaluated at the
    /// start of the scan, and a step activated by them runs its actions in the same scan.
    #[default]
    TransitionsFirst,
    /// TwinCAT 3 and CODESYS ("Processing Order in SFC", Beckhoff infosys tc3_plc_intro and the
    /// CODESYS SFC help): the actions of the active steps first (exit, entry, step time and step
    /// actions, IEC actions), the transition check last, so a step activated in scan k runs its
    /// actions from scan k+1 and a step left in scan k runs its exit action and the final scan of
    /// its IEC actions in scan k+1. Charts read from a TwinCAT `.TcPOU`.
    ActionsFirst,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum NodeKind {
    Step,
    Transition,
    SelDiv,
    SelConv,
    SimDiv,
    SimConv,
    Jump,
    ActionBlock,
    Macro,
}

struct Node<'e, 'a> {
    kind: NodeKind,
    el: &'e Element<'a>,
    id: String,
    inputs: Vec<(String, Span)>,
    step: Option<usize>,
}

pub(crate) fn report(
    ctx: &mut Ctx,
    code: Code,
    span: Span,
    pou: &str,
    id: Option<&str>,
    msg: String,
) {
    ctx.report(Diagnostic::error(code, msg).at(span).with_xml(XmlContext {
        pou: Some(pou.to_string()),
        local_id: id.map(str::to_string),
        network: None,
    }));
}

/// W1464 at a step that no transition follows (a final step). IEC 61131-3 (ed. 2 2.6.2-2.6.3,
/// ed. 3 6.7.2-6.7.3) asks for a transition between two steps, not for a successor of every step,
/// and Beremiz/matiec compile such a step (Acabaxi/Simple's Beremiz build holds four): it stays
/// active once reached, its actions running every scan. Before round 33 this was the error E3121.
pub(crate) fn warn_final_step(ctx: &mut Ctx, span: Span, pou: &str, id: Option<&str>, name: &str) {
    ctx.report(
        Diagnostic::warning(
            code::W1464,
            format!("step `{name}` has no following transition: once active it stays active"),
        )
        .at(span)
        .with_primary_label("a final step")
        .with_hint(
            "a step that ends its sequence is allowed (IEC 61131-3 asks for no successor); if \
             the chart should go on, connect a transition below the step",
        )
        .with_xml(XmlContext {
            pou: Some(pou.to_string()),
            local_id: id.map(str::to_string),
            network: None,
        }),
    );
}

fn pos(e: &Element, axis: &str) -> i64 {
    e.child("position")
        .and_then(|p| p.attr(axis))
        .and_then(|v| v.trim().parse::<f64>().ok())
        .map(|v| v as i64)
        .unwrap_or(0)
}

fn inputs(ctx: &Ctx, e: &Element) -> Vec<(String, Span)> {
    e.children_named("connectionPointIn")
        .flat_map(|p| p.children_named("connection"))
        .map(|c| {
            (
                c.attr("refLocalId").unwrap_or_default().trim().to_string(),
                ctx.tag(c),
            )
        })
        .collect()
}

/// Reads the chart. `pou` names the POU in diagnostics.
pub fn read<'e, 'a>(ctx: &mut Ctx, sfc: &'e Element<'a>, pou: &str) -> Chart<'e, 'a> {
    let mut nodes: Vec<Node> = Vec::new();
    let mut ids: HashMap<String, usize> = HashMap::new();
    let mut steps: Vec<Step> = Vec::new();
    let mut step_names: HashMap<String, usize> = HashMap::new();
    let mut network_elements = Vec::new();
    let mut all_ids: HashSet<String> = HashSet::new();
    for e in sfc.children.iter() {
        let kind = match e.name() {
            "step" => NodeKind::Step,
            "macroStep" => NodeKind::Macro,
            "transition" => NodeKind::Transition,
            "selectionDivergence" => NodeKind::SelDiv,
            "selectionConvergence" => NodeKind::SelConv,
            "simultaneousDivergence" => NodeKind::SimDiv,
            "simultaneousConvergence" => NodeKind::SimConv,
            "jumpStep" => NodeKind::Jump,
            "actionBlock" => NodeKind::ActionBlock,
            "comment" | "addData" | "vendorElement" | "documentation" => continue,
            _ => {
                if let Some(id) = e.attr("localId") {
                    all_ids.insert(id.trim().to_string());
                }
                network_elements.push(*e);
                continue;
            }
        };
        let span = ctx.tag(e);
        let Some(id) = e.attr("localId").map(str::trim).filter(|s| !s.is_empty()) else {
            report(
                ctx,
                code::E3013,
                span,
                pou,
                None,
                format!("<{}> without a localId", e.name()),
            );
            continue;
        };
        if ids.contains_key(id) || all_ids.contains(id) {
            report(
                ctx,
                code::E3014,
                span,
                pou,
                Some(id),
                format!("localId {id} is used twice"),
            );
            continue;
        }
        if kind == NodeKind::Macro {
            report(
                ctx,
                code::E3125,
                span,
                pou,
                Some(id),
                "macro steps are not supported: the sequence inside is not lowered".to_string(),
            );
        }
        let mut step = None;
        if kind == NodeKind::Step {
            let mut name = e.attr("name").unwrap_or_default().trim().to_string();
            let nspan = ctx.attr_span(e, "name");
            if !crate::values::is_ident(&name) || name.contains("__") {
                report(
                    ctx,
                    code::E3131,
                    nspan,
                    pou,
                    Some(id),
                    format!("step name `{name}` is not an IEC identifier"),
                );
                // kept under a name of its own (the build fails already), so the transitions and
                // jumps around it are not reported again
                if !name.is_empty() {
                    step_names.insert(name.to_ascii_uppercase(), steps.len());
                }
                name = format!("invalid_{}", super::sanitize(id));
            }
            if let Some(&prev) = step_names.get(&name.to_ascii_uppercase()) {
                let first: &Step = &steps[prev];
                ctx.report(
                    Diagnostic::error(code::E3131, format!("step name `{name}` is used twice"))
                        .at(nspan)
                        .with_label(first.span, "first used here")
                        .with_xml(XmlContext {
                            pou: Some(pou.to_string()),
                            local_id: Some(id.to_string()),
                            network: None,
                        }),
                );
                continue;
            }
            step_names.insert(name.to_ascii_uppercase(), steps.len());
            step = Some(steps.len());
            steps.push(Step {
                id: id.to_string(),
                name,
                initial: e
                    .attr("initialStep")
                    .is_some_and(|v| matches!(v.trim(), "true" | "1")),
                span,
            });
        }
        ids.insert(id.to_string(), nodes.len());
        all_ids.insert(id.to_string());
        nodes.push(Node {
            kind,
            el: e,
            id: id.to_string(),
            inputs: inputs(ctx, e),
            step,
        });
    }

    // Resolve inputs; E3120 for references to nothing. References to LD/FBD elements are only
    // meaningful for conditions, which are read separately.
    let mut resolved: Vec<Vec<usize>> = Vec::with_capacity(nodes.len());
    for n in &nodes {
        let mut r = Vec::new();
        for (ref_id, span) in &n.inputs {
            match ids.get(ref_id) {
                Some(&i) => r.push(i),
                None => {
                    let what = if all_ids.contains(ref_id) {
                        format!(
                            "<{}> is connected to localId {ref_id}, which is not an SFC element",
                            n.el.name()
                        )
                    } else {
                        format!("connection to localId {ref_id} which does not exist")
                    };
                    report(ctx, code::E3120, *span, pou, Some(&n.id), what);
                }
            }
        }
        resolved.push(r);
    }
    let mut consumers: Vec<Vec<usize>> = vec![Vec::new(); nodes.len()];
    for (i, r) in resolved.iter().enumerate() {
        for &from in r {
            consumers[from].push(i);
        }
    }

    let mut transitions = Vec::new();
    // jumps ending a simultaneous branch and convergences of jumps only, checked (and reported)
    // once however many transitions follow them
    let mut checked: HashMap<usize, bool> = HashMap::new();
    for (i, n) in nodes.iter().enumerate() {
        if n.kind != NodeKind::Transition {
            continue;
        }
        let span = ctx.tag(n.el);
        let mut pre = Vec::new();
        let mut ok = true;
        let mut seen = HashSet::new();
        // CODESYS ends the branches of an alternative branch with steps and jumps, merged by a
        // selection convergence that a transition follows: the transition leaves whichever of
        // those steps is active (a jump ends its branch, it feeds nothing): one transition each
        let branch_ends: Option<Vec<usize>> = match resolved[i].as_slice() {
            [c] if nodes[*c].kind == NodeKind::SelConv
                && !resolved[*c].is_empty()
                && resolved[*c]
                    .iter()
                    .all(|&f| matches!(nodes[f].kind, NodeKind::Step | NodeKind::Jump)) =>
            {
                Some(resolved[*c].iter().filter_map(|&f| nodes[f].step).collect())
            }
            _ => None,
        };
        if let Some(ends) = &branch_ends {
            pre.extend(ends.iter().take(1));
        } else {
            for &from in &resolved[i] {
                ok &= pre_steps(
                    ctx,
                    &nodes,
                    &resolved,
                    &step_names,
                    &mut checked,
                    from,
                    &mut pre,
                    &mut seen,
                    pou,
                );
            }
        }
        if branch_ends.as_ref().is_some_and(|e| e.is_empty()) {
            // only jumps reach the convergence: the transition can never fire
            continue;
        }
        if resolved[i].is_empty() {
            // Dangling inputs were reported as E3120 already.
            if n.inputs.is_empty() {
                report(
                    ctx,
                    code::E3128,
                    span,
                    pou,
                    Some(&n.id),
                    "transition without a preceding step".to_string(),
                );
            }
            ok = false;
        }
        let mut post = Vec::new();
        let mut seen = HashSet::new();
        ok &= post_steps(
            ctx,
            &nodes,
            &consumers,
            &step_names,
            i,
            &mut post,
            &mut seen,
            pou,
        );
        if ok && post.is_empty() {
            report(
                ctx,
                code::E3128,
                span,
                pou,
                Some(&n.id),
                "transition without a following step".to_string(),
            );
            ok = false;
        }
        let Some(cond) = condition(ctx, n.el, pou, &n.id) else {
            continue;
        };
        if !ok {
            continue;
        }
        pre.dedup();
        post.dedup();
        let num = |a: &str| {
            n.el.attr(a)
                .and_then(|v| v.trim().parse::<u32>().ok())
                .filter(|v| a == "priority" || *v > 0)
                .unwrap_or(u32::MAX)
        };
        let order = (
            num("priority"),
            num("executionOrderId"),
            pos(n.el, "x"),
            pos(n.el, "y"),
            n.id.parse().unwrap_or(u64::MAX),
        );
        // the copies for the other branch ends of a CODESYS convergence (`34_1`, `34_2`: no
        // localId has an underscore's place in a number, so the hidden names stay apart)
        for (k, &s) in branch_ends.iter().flatten().enumerate().skip(1) {
            transitions.push(Transition {
                id: format!("{}_{k}", n.id),
                span,
                cond,
                pre: vec![s],
                post: post.clone(),
                order,
            });
        }
        transitions.push(Transition {
            id: n.id.clone(),
            span,
            cond,
            pre,
            post,
            order,
        });
    }
    transitions.sort_by_key(|t| t.order);

    // Steps without a successor: final steps (W1464).
    for n in &nodes {
        if n.kind != NodeKind::Step {
            continue;
        }
        let has_successor = consumers[ids[&n.id]]
            .iter()
            .any(|&c| nodes[c].kind != NodeKind::ActionBlock);
        // an initial step that no transition enters or leaves is a network of its own, always
        // active (IEC 61131-3 Annex F's gravel example keeps its monitor actions in one)
        let lone_initial = n
            .step
            .is_some_and(|s| steps[s].initial && !transitions.iter().any(|t| t.post.contains(&s)));
        if !has_successor && !lone_initial {
            let name = n.step.map(|s| steps[s].name.clone()).unwrap_or_default();
            warn_final_step(ctx, ctx.tag(n.el), pou, Some(&n.id), &name);
        }
    }
    if !steps.is_empty() && !steps.iter().any(|s| s.initial) {
        report(
            ctx,
            code::E3124,
            ctx.tag(sfc),
            pou,
            None,
            "the chart has no initial step: no step would ever become active".to_string(),
        );
    }

    // Action associations, blocks in order.
    let mut blocks: Vec<(usize, (u32, i64, i64, u64))> = nodes
        .iter()
        .enumerate()
        .filter(|(_, n)| n.kind == NodeKind::ActionBlock)
        .map(|(i, n)| {
            let exec =
                n.el.attr("executionOrderId")
                    .and_then(|v| v.trim().parse::<u32>().ok())
                    .filter(|v| *v > 0)
                    .unwrap_or(u32::MAX);
            (
                i,
                (
                    exec,
                    pos(n.el, "y"),
                    pos(n.el, "x"),
                    n.id.parse().unwrap_or(u64::MAX),
                ),
            )
        })
        .collect();
    blocks.sort_by_key(|b| b.1);
    let mut associations = Vec::new();
    // CODESYS's step actions first, as CODESYS runs them before the IEC actions: every exit
    // action, then every entry action, then every step action, steps in document order
    let mut vendor: Vec<(StepAction, usize, &Element)> = Vec::new();
    for n in &nodes {
        let Some(step) = n.step.filter(|_| n.kind == NodeKind::Step) else {
            continue;
        };
        for (k, attr) in step_actions(n.el) {
            vendor.push((k, step, attr));
        }
    }
    vendor.sort_by_key(|v| v.0);
    for (k, (kind, step, attr)) in vendor.into_iter().enumerate() {
        associations.push(Association {
            step,
            block_id: steps[step].id.clone(),
            index: k,
            el: attr,
            vendor: Some(kind),
        });
    }
    for (i, _) in blocks {
        let n = &nodes[i];
        let step = match resolved[i].as_slice() {
            [s] if nodes[*s].step.is_some() => nodes[*s].step,
            [] if n.inputs.is_empty() => {
                report(
                    ctx,
                    code::E3120,
                    ctx.tag(n.el),
                    pou,
                    Some(&n.id),
                    "action block is not connected to a step".to_string(),
                );
                None
            }
            [] => None, // dangling: reported above
            _ => {
                report(
                    ctx,
                    code::E3128,
                    ctx.tag(n.el),
                    pou,
                    Some(&n.id),
                    "an action block must be connected to exactly one step".to_string(),
                );
                None
            }
        };
        let Some(step) = step else { continue };
        for (k, a) in n.el.children_named("action").enumerate() {
            associations.push(Association {
                step,
                block_id: n.id.clone(),
                index: k,
                el: a,
                vendor: None,
            });
        }
    }

    Chart {
        steps,
        transitions,
        associations,
        network_elements,
        flags: Vec::new(),
        order: ScanOrder::TransitionsFirst,
    }
}

/// The steps that must be active for a transition whose input comes from `from`. An explicit stack, not
/// recursion: a chain of divergences and convergences is as long as the file makes it (depth-first, in the
/// order of the connections, as a recursive walk would visit them).
///
/// A branch of a simultaneous sequence may end in a jump back to a step of its own branch (CODESYS
/// connects that jump to the simultaneous convergence): the branch loops and never reaches the
/// convergence, so the transition after it waits for the other branches only, and leaves the looping
/// branch active (IEC 61131-3: a transition deactivates its immediately preceding steps). A jump out
/// of its branch is IEC 61131-3's "unsafe" SFC and a convergence of jumps only its "unreachable"
/// one: both E3128.
#[allow(clippy::too_many_arguments)]
fn pre_steps(
    ctx: &mut Ctx,
    nodes: &[Node],
    resolved: &[Vec<usize>],
    step_names: &HashMap<String, usize>,
    checked: &mut HashMap<usize, bool>,
    from: usize,
    out: &mut Vec<usize>,
    seen: &mut HashSet<usize>,
    pou: &str,
) -> bool {
    let mut ok = true;
    let mut stack = vec![from];
    while let Some(from) = stack.pop() {
        if !seen.insert(from) {
            continue;
        }
        let n = &nodes[from];
        match n.kind {
            NodeKind::Step => {
                if let Some(s) = n.step {
                    out.push(s);
                }
            }
            NodeKind::SimConv
                if resolved[from]
                    .iter()
                    .any(|&f| nodes[f].kind == NodeKind::Jump) =>
            {
                let (jumps, rest): (Vec<usize>, Vec<usize>) = resolved[from]
                    .iter()
                    .partition(|&&f| nodes[f].kind == NodeKind::Jump);
                for &j in &jumps {
                    ok &= match checked.get(&j) {
                        Some(&loops) => loops,
                        None => {
                            let loops =
                                jump_loops_in_its_branch(ctx, nodes, resolved, step_names, j, pou);
                            checked.insert(j, loops);
                            loops
                        }
                    };
                }
                if rest.is_empty() && checked.insert(from, false).is_none() {
                    report(
                        ctx,
                        code::E3128,
                        ctx.tag(n.el),
                        pou,
                        Some(&n.id),
                        "every branch of this simultaneous convergence ends in a jump: the transition \
                         after it can never fire (IEC 61131-3's unreachable SFC)"
                            .to_string(),
                    );
                }
                ok &= !rest.is_empty();
                stack.extend(rest.iter().rev());
            }
            NodeKind::SelDiv | NodeKind::SimConv => {
                if resolved[from].is_empty() {
                    report(
                        ctx,
                        code::E3120,
                        ctx.tag(n.el),
                        pou,
                        Some(&n.id),
                        format!("<{}> has no input connection", n.el.name()),
                    );
                    ok = false;
                } else {
                    stack.extend(resolved[from].iter().rev());
                }
            }
            NodeKind::Macro => ok = false,
            _ => {
                report(
                    ctx,
                    code::E3128,
                    ctx.tag(n.el),
                    pou,
                    Some(&n.id),
                    format!(
                        "<{}> cannot precede a transition (a step, selection divergence or simultaneous \
                         convergence must)",
                        n.el.name()
                    ),
                );
                ok = false;
            }
        }
    }
    ok
}

/// Whether the jump `jump`, which ends a branch of a simultaneous sequence, jumps back to a step of
/// its own branch: a step met walking back from the jump along the connections, through nested
/// simultaneous sequences, up to the simultaneous divergence that opens the branch. Reports E3128
/// (unsafe: the jump leaves the simultaneous sequence) otherwise; an unknown target is E3127, reported
/// where the jump's transition is read.
fn jump_loops_in_its_branch(
    ctx: &mut Ctx,
    nodes: &[Node],
    resolved: &[Vec<usize>],
    step_names: &HashMap<String, usize>,
    jump: usize,
    pou: &str,
) -> bool {
    let n = &nodes[jump];
    let target = n.el.attr("targetName").unwrap_or_default().trim();
    let Some(&target_step) = step_names.get(&target.to_ascii_uppercase()) else {
        return false;
    };
    let mut seen = HashSet::new();
    // (node, depth of nested simultaneous sequences entered from below)
    let mut stack = vec![(jump, 0usize)];
    while let Some((at, depth)) = stack.pop() {
        if !seen.insert(at) {
            continue;
        }
        let node = &nodes[at];
        if node.step == Some(target_step) {
            return true;
        }
        let depth = match node.kind {
            NodeKind::SimConv => depth + 1,
            NodeKind::SimDiv if depth == 0 => continue, // the start of the jump's branch
            NodeKind::SimDiv => depth - 1,
            _ => depth,
        };
        stack.extend(resolved[at].iter().map(|&f| (f, depth)));
    }
    let span = ctx.attr_span(n.el, "targetName");
    ctx.report(
        Diagnostic::error(
            code::E3128,
            format!(
                "jump to step `{target}` leaves its branch of a simultaneous sequence: the other \
                 branches stay active beside the target (IEC 61131-3's unsafe SFC)"
            ),
        )
        .at(span)
        .with_hint(
            "end the branch at the simultaneous convergence and jump after the transition that \
             follows it, or jump back to a step of the same branch",
        )
        .with_xml(XmlContext {
            pou: Some(pou.to_string()),
            local_id: Some(n.id.clone()),
            network: None,
        }),
    );
    false
}

/// The steps a transition activates: its consumers, through convergences, divergences and jumps. An
/// explicit stack of (node, next consumer) frames, not recursion, in the order a recursive walk would take.
#[allow(clippy::too_many_arguments)]
fn post_steps(
    ctx: &mut Ctx,
    nodes: &[Node],
    consumers: &[Vec<usize>],
    step_names: &HashMap<String, usize>,
    from: usize,
    out: &mut Vec<usize>,
    seen: &mut HashSet<usize>,
    pou: &str,
) -> bool {
    let mut ok = true;
    let mut frames: Vec<(usize, usize)> = vec![(from, 0)];
    while let Some(frame) = frames.last_mut() {
        let Some(&c) = consumers[frame.0].get(frame.1) else {
            frames.pop();
            continue;
        };
        frame.1 += 1;
        if !seen.insert(c) {
            continue;
        }
        let n = &nodes[c];
        match n.kind {
            NodeKind::Step => out.extend(n.step),
            NodeKind::Jump => {
                let target = n.el.attr("targetName").unwrap_or_default().trim();
                match step_names.get(&target.to_ascii_uppercase()) {
                    Some(&s) => out.push(s),
                    None => {
                        report(
                            ctx,
                            code::E3127,
                            ctx.attr_span(n.el, "targetName"),
                            pou,
                            Some(&n.id),
                            format!("jump to step `{target}`, which this chart does not define"),
                        );
                        ok = false;
                    }
                }
            }
            NodeKind::SelConv | NodeKind::SimDiv => frames.push((c, 0)),
            NodeKind::Macro => ok = false,
            _ => {
                report(
                    ctx,
                    code::E3128,
                    ctx.tag(n.el),
                    pou,
                    Some(&n.id),
                    format!(
                        "<{}> cannot follow a transition (a step, jump, selection convergence or \
                         simultaneous divergence must)",
                        n.el.name()
                    ),
                );
                ok = false;
            }
        }
    }
    ok
}

fn condition<'e, 'a>(
    ctx: &mut Ctx,
    t: &'e Element<'a>,
    pou: &str,
    id: &str,
) -> Option<CondSource<'e, 'a>> {
    let c = t.child("condition");
    let found = c.and_then(|c| {
        if let Some(r) = c.child("reference") {
            let name = r.attr("name").unwrap_or_default().trim();
            return Some(CondSource::Reference(name, ctx.attr_span(r, "name")));
        }
        if let Some(i) = c.child("inline") {
            let lang = i
                .children
                .iter()
                .find(|e| !matches!(e.name(), "documentation" | "addData"))?;
            return Some(CondSource::Inline(
                lang,
                i.attr("name").unwrap_or_default().trim(),
            ));
        }
        if c.child("connectionPointIn").is_some() || c.child("connection").is_some() {
            return Some(CondSource::Connection(c));
        }
        None
    });
    if found.is_none() {
        report(
            ctx,
            code::E3126,
            ctx.tag(t),
            pou,
            Some(id),
            "transition without a condition (inline, reference or connection)".to_string(),
        );
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use diagnostics::{Diagnostics, SourceMap};

    fn names(c: &Chart, idx: &[usize]) -> Vec<String> {
        idx.iter().map(|&i| c.steps[i].name.clone()).collect()
    }

    #[test]
    fn transitions_see_through_divergences_convergences_and_jumps() {
        let xml = r#"<SFC>
          <step localId="1" name="A" initialStep="true"/>
          <simultaneousConvergence localId="9">
            <connectionPointIn><connection refLocalId="1"/></connectionPointIn>
            <connectionPointIn><connection refLocalId="2"/></connectionPointIn>
          </simultaneousConvergence>
          <step localId="2" name="B" initialStep="true"/>
          <selectionDivergence localId="3"><connectionPointIn><connection refLocalId="9"/></connectionPointIn></selectionDivergence>
          <transition localId="4"><position x="50" y="0"/><connectionPointIn><connection refLocalId="3"/></connectionPointIn>
            <condition><reference name="go"/></condition></transition>
          <transition localId="5"><position x="10" y="0"/><connectionPointIn><connection refLocalId="3"/></connectionPointIn>
            <condition><reference name="go"/></condition></transition>
          <simultaneousDivergence localId="6"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></simultaneousDivergence>
          <step localId="7" name="C"><connectionPointIn><connection refLocalId="6"/></connectionPointIn></step>
          <jumpStep localId="8" targetName="A"><connectionPointIn><connection refLocalId="6"/></connectionPointIn></jumpStep>
          <selectionConvergence localId="10"><connectionPointIn><connection refLocalId="5"/></connectionPointIn></selectionConvergence>
          <step localId="11" name="D"><connectionPointIn><connection refLocalId="10"/></connectionPointIn></step>
        </SFC>"#;
        let arena = crate::xml::Arena::new();
        let (root, err) = crate::xml::parse(xml, &arena);
        assert!(err.is_none());
        let root = root.unwrap();
        let mut map = SourceMap::new();
        let file = map.add("t.xml", xml);
        let mut diags = Diagnostics::new();
        let mut ctx = Ctx::new(file, xml, &mut diags);
        let c = read(&mut ctx, &root, "P");
        // Left to right: 5 (x=10) before 4 (x=50).
        let ids: Vec<&str> = c.transitions.iter().map(|t| t.id.as_str()).collect();
        assert_eq!(ids, ["5", "4"]);
        // Both need A and B (simultaneous convergence, then a selection divergence).
        assert_eq!(names(&c, &c.transitions[0].pre), ["A", "B"]);
        assert_eq!(names(&c, &c.transitions[1].pre), ["A", "B"]);
        // 5 leads through a selection convergence to D; 4 through a simultaneous divergence to C and
        // (by the jump) A.
        assert_eq!(names(&c, &c.transitions[0].post), ["D"]);
        assert_eq!(names(&c, &c.transitions[1].post), ["C", "A"]);
        // C and D have no following transition: final steps, a warning each.
        let codes: Vec<String> = diags.iter().map(|d| d.code.to_string()).collect();
        assert_eq!(codes, ["W1464", "W1464"], "{codes:?}");
    }
}
