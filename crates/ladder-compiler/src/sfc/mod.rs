//! Sequential Function Chart bodies (IEC 61131-3 2nd ed. 2.6) lowered to the IL syntax tree.
//!
//! Input: a POU's `<SFC>` element, the POU (interface) and the project index. Output: IL statements for
//! one scan of the chart and the hidden variables they use (one extra `VAR` block).
//! Invariants: every scan of a chart in IEC order ([`chart::ScanOrder::TransitionsFirst`]: PLCopen
//! XML and textual charts) runs, in this order (documented in the README):
//! 0. with CODESYS's SFCInit or SFCReset enabled and TRUE ([`flags`]), the chart's reset: initial
//!    steps active, the others inactive, step times 0 (SFCInit also keeps transitions from firing
//!    and the initial steps from the action control while TRUE);
//! 1. the LD/FBD elements of the body (connection-based conditions), then every transition condition,
//!    each into `__sfc_c<localId>`, all on the step flags as they were at the start of the scan;
//! 2. which transitions fire (`__sfc_f<localId>`): all predecessor steps active, condition TRUE, and no
//!    transition of higher priority sharing a predecessor step fires;
//! 3. all fired transitions deactivate their predecessors, then activate their successors (one
//!    evolution per scan, no cascade);
//! 4. step elapsed times (`Step.T`, a TON per step);
//! 5. action control for every action (IEC ACTION_CONTROL), then action bodies whose `A` is TRUE
//!    (an action of an FB instance, or one whose body is a chart of its own, is a `CAL` there).
//!
//! A chart read from a TwinCAT `.TcPOU` ([`chart::ScanOrder::ActionsFirst`]) runs in TwinCAT's and
//! CODESYS's documented "Processing Order in SFC" (Beckhoff infosys tc3_plc_intro; CODESYS SFC
//! help): 0, the step times, 5 (so the actions of the steps active since the end of the last
//! scan, the exit actions and final scans of the steps left then), and last 1 to 3, the
//! transition check (the step times after the evolution are not refreshed; a step left and
//! re-entered by one transition still restarts its time). A step activated in scan k runs its
//! actions from scan k+1; `Step.X` read after the chart is the next scan's activation (CODESYS's
//! `Step._x`).
//!
//! A chart may also be the body of a POU's action ([`crate::body`]): its hidden variables are then
//! renamed per action ([`names::in_action`]), except a flag variable ladderc declares
//! (`SFCReset`, one variable of the POU). A textual or TwinCAT chart also runs where a block derived
//! from its block calls `SUPER^()` (ladderc's `super_charts`): one scan per call, lowered again with
//! the derived block, its hidden variables the derived block's.
//!
//! `Step.X`, `Step.T`, `Action.Q` and `Action.A` in conditions and action bodies are renamed to the
//! hidden variables `__sfc_X_<step>`, `__sfc_T_<step>`, `__sfc_Q_<action>`, `__sfc_A_<action>`
//! (CODESYS's `Step._x` and `Step._t` to the same two); any other field of a step is one E1021.

pub mod action_vars;
pub mod actions;
pub mod chart;
pub mod flags;
pub mod il;
pub mod snippet;
pub mod st_bridge;
pub mod text;

use crate::context::Ctx;
use crate::graph::{self, Kind, Node, Wire};
use crate::lower::BodyLowering;
use crate::project::Index;
use crate::xml::Element;
use actions::Target;
use chart::{report, CondSource};
use diagnostics::{code, Diagnostics};
use il::{Hidden, Renames};
use il_frontend::ast::{IlStmt, Op, Pou, VarDecl};
use snippet::{Purpose, Snippets};

/// The hidden names of the chart.
pub mod names {
    /// `__sfc_X_<step>`: the step's active flag (`Step.X`).
    pub fn x(step: &str) -> String {
        format!("__sfc_X_{step}")
    }
    /// `__sfc_T_<step>`: the step's elapsed time (`Step.T`).
    pub fn t(step: &str) -> String {
        format!("__sfc_T_{step}")
    }
    /// `__sfc_TT_<step>`: the TON instance that measures the step's elapsed time.
    pub fn timer(step: &str) -> String {
        format!("__sfc_TT_{step}")
    }
    /// `__sfc_c<id>`: the value of transition `id`'s condition.
    pub fn cond(id: &str) -> String {
        format!("__sfc_c{}", super::sanitize(id))
    }
    /// `__sfc_f<id>`: whether transition `id` fires this scan.
    pub fn fire(id: &str) -> String {
        format!("__sfc_f{}", super::sanitize(id))
    }
    /// `__sfc_Q_<action>`: the action's `Q` (active).
    pub fn q(action: &str) -> String {
        format!("__sfc_Q_{action}")
    }
    /// `__sfc_A_<action>`: the action's `A` (execute).
    pub fn a(action: &str) -> String {
        format!("__sfc_A_{action}")
    }
    /// `__sfc_<part>_<action>`: one internal variable of the action control (`Sin`, `Qm` ...).
    pub fn action_part(action: &str, part: &str) -> String {
        format!("__sfc_{part}_{action}")
    }
    /// Whether `name` is the memory of an action's final scan (`__sfc_Qm_<action>`, also in the
    /// chart of a POU's action, [`in_action`]): the chart has an action IEC's final scan runs again.
    pub fn is_final_scan_memory(name: &str) -> bool {
        name.strip_prefix("__sfc_")
            .is_some_and(|rest| rest.starts_with("Qm_") || rest.contains("__Qm_"))
    }
    /// The name a hidden variable `hidden` of the chart of action `action` (a POU's action whose
    /// body is SFC) takes in the POU: `__sfc_X_Fill` of action `Sequence` is
    /// `__sfc_Sequence__X_Fill`. An identifier never holds two underscores in a row, so the name
    /// of the action ends at the first `__`, and the charts of two actions never share a variable.
    pub fn in_action(action: &str, hidden: &str) -> String {
        let rest = hidden
            .strip_prefix("__sfc_")
            .unwrap_or_else(|| hidden.trim_start_matches('_'));
        format!("__sfc_{action}__{rest}")
    }
}

fn sanitize(id: &str) -> String {
    id.chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect()
}

/// `Step.T` counts up to this (100000 days) and then stays there.
const STEP_TIME_LIMIT_NS: i128 = 100_000 * 86_400 * 1_000_000_000;

/// Lowers an `<SFC>` body: the statements and the hidden declarations.
pub fn lower(
    ctx: &mut Ctx,
    index: &Index,
    pou_el: &Element,
    pou: &Pou,
    sfc: &Element,
) -> (Vec<IlStmt>, Vec<VarDecl>) {
    let pou_name = pou.name.name.clone();
    if pou.kind == il_frontend::ast::PouKind::Function {
        report(
            ctx,
            code::E3125,
            ctx.tag(sfc),
            &pou_name,
            None,
            format!(
                "function `{pou_name}` is a sequential function chart: a function keeps no state \
                 between calls, so it cannot remember its active steps (make it a function block or a program)"
            ),
        );
        return (Vec::new(), Vec::new());
    }
    let mut chart = chart::read(ctx, sfc, &pou_name);
    chart.flags = flags::read(ctx, pou_el);
    lower_chart(ctx, index, pou_el, pou, sfc, chart)
}

/// Lowers a chart already read (from an `<SFC>` element or from textual SFC, [`text`]). `pou_el` holds
/// the POU's `<actions>` and `<transitions>`; `sfc` is the body element (its start tag locates
/// chart-wide diagnostics; its LD/FBD elements are read only for connection-based conditions).
pub fn lower_chart<'e, 'a>(
    ctx: &mut Ctx,
    index: &Index,
    pou_el: &'e Element<'a>,
    pou: &Pou,
    sfc: &Element,
    chart: chart::Chart<'e, 'a>,
) -> (Vec<IlStmt>, Vec<VarDecl>) {
    let pou_name = pou.name.name.clone();
    let mut hidden = Hidden::default();
    let mut out: Vec<IlStmt> = Vec::new();
    let body_span = ctx.tag(sfc);
    // Actions are known before any body is lowered (ST needs their names for `Action.Q`).
    let acts = actions::collect(ctx, pou_el, pou, index, &chart.steps, &chart.associations);
    let decls = st_bridge::declarations(index, pou.span);
    let step_names: Vec<String> = chart.steps.iter().map(|s| s.name.clone()).collect();
    let action_names: Vec<String> = acts.iter().filter_map(|a| a.name.clone()).collect();
    let st = st_bridge::StLowering::new(decls, pou, &step_names, &action_names);
    let mut snippets = Snippets::new(index, pou, st);

    // Step flags first (the initial ones start TRUE).
    for s in &chart.steps {
        let init = s.initial.then(|| il::lit_bool(true, s.span));
        hidden.declare(&names::x(&s.name), "BOOL", init, s.span);
        hidden.declare(&names::t(&s.name), "TIME", None, s.span);
    }

    // CODESYS's SFCInit / SFCReset: the chart's reset, before anything reads the steps.
    let ctl = flags::control(ctx, pou, &chart.flags, &mut hidden);
    let rst = reset(&chart.steps, &ctl, &mut hidden, &mut out);

    // Step times, refreshed with this scan's clock before the conditions read them.
    step_times(&chart.steps, &mut hidden, &mut out);

    // Where the transitions' part of the scan begins (moved after the actions' part for a chart
    // in TwinCAT's order, `ScanOrder::ActionsFirst`).
    let transitions_start = out.len();

    // 1. Conditions.
    let connected: Vec<&chart::Transition> = chart
        .transitions
        .iter()
        .filter(|t| matches!(t.cond, CondSource::Connection(_)))
        .collect();
    if !chart.network_elements.is_empty() || !connected.is_empty() {
        networks(ctx, index, pou, sfc, &chart, &mut hidden, &mut out);
    }
    let named_transitions: Vec<&Element> = pou_el
        .child("transitions")
        .map(|t| t.children_named("transition").collect())
        .unwrap_or_default();
    let mut usable = vec![true; chart.transitions.len()];
    let mut evaluated: std::collections::HashMap<String, bool> = std::collections::HashMap::new();
    for (ti, t) in chart.transitions.iter().enumerate() {
        let c = names::cond(&t.id);
        hidden.declare(&c, "BOOL", None, t.span);
        hidden.declare(&names::fire(&t.id), "BOOL", None, t.span);
        let owner = format!("transition {}", t.id);
        match t.cond {
            CondSource::Connection(_) => {}
            CondSource::Inline(lang, name) => {
                let purpose = Purpose::Condition { result: &c, name };
                match snippets.lower(ctx, lang, purpose, &mut hidden, &owner) {
                    Some(code) => out.extend(code),
                    None => usable[ti] = false,
                }
            }
            CondSource::Reference(name, nspan) => {
                let body = named_transitions.iter().find(|e| {
                    e.attr("name")
                        .is_some_and(|n| n.trim().eq_ignore_ascii_case(name))
                });
                if let Some(tr) = body {
                    let lang = tr.child("body").and_then(|b| {
                        b.children
                            .iter()
                            .find(|c| !matches!(c.name(), "documentation" | "addData"))
                    });
                    let Some(lang) = lang else {
                        report(
                            ctx,
                            code::E3130,
                            ctx.tag(tr),
                            &pou_name,
                            None,
                            format!("named transition `{name}` has no body"),
                        );
                        usable[ti] = false;
                        continue;
                    };
                    // A named transition is evaluated once per scan, however many use it.
                    let nv = format!("__sfc_n_{}", sanitize(name));
                    let key = name.to_ascii_uppercase();
                    if !evaluated.contains_key(&key) {
                        hidden.declare(&nv, "BOOL", None, t.span);
                        let purpose = Purpose::Condition { result: &nv, name };
                        let owner = format!("named transition `{name}`");
                        let ok = match snippets.lower(ctx, lang, purpose, &mut hidden, &owner) {
                            Some(code) => {
                                out.extend(code);
                                true
                            }
                            None => false,
                        };
                        evaluated.insert(key.clone(), ok);
                    }
                    if evaluated[&key] {
                        out.push(il::op(Op::Ld, il::var(&nv, t.span)));
                        out.push(il::op(Op::St, il::var(&c, t.span)));
                    } else {
                        usable[ti] = false;
                    }
                } else if let Some(op) = declared_bool(index, pou, name, nspan) {
                    out.push(il::op(Op::Ld, op));
                    out.push(il::op(Op::St, il::var(&c, t.span)));
                } else {
                    report(
                        ctx,
                        code::E3130,
                        nspan,
                        &pou_name,
                        Some(&t.id),
                        format!(
                            "transition {} refers to `{name}`, which is neither a named transition of \
                             the POU nor a BOOL variable",
                            t.id
                        ),
                    );
                    usable[ti] = false;
                }
            }
        }
    }

    // 2. Which transitions fire.
    // The transitions leaving each step, in order: a transition yields to the earlier ones that share
    // a step with it (looking at every earlier transition made 50,000 steps quadratic).
    let mut leaving: Vec<Vec<usize>> = vec![Vec::new(); chart.steps.len()];
    for (ti, t) in chart.transitions.iter().enumerate() {
        for &p in &t.pre {
            if let Some(l) = leaving.get_mut(p) {
                l.push(ti);
            }
        }
    }
    for (ti, t) in chart.transitions.iter().enumerate() {
        let f = names::fire(&t.id);
        let span = t.span;
        if !usable[ti] {
            out.push(il::op(Op::Ld, il::lit_bool(false, span)));
            out.push(il::op(Op::St, il::var(&f, span)));
            continue;
        }
        let mut first = true;
        for &s in &t.pre {
            let x = il::var(&names::x(&chart.steps[s].name), span);
            out.push(il::op(if first { Op::Ld } else { Op::And }, x));
            first = false;
        }
        out.push(il::op(Op::And, il::var(&names::cond(&t.id), span)));
        if let Some(init) = &ctl.init {
            out.push(il::opn(Op::And, init.clone()));
        }
        let mut earlier: Vec<usize> = t
            .pre
            .iter()
            .filter_map(|&p| leaving.get(p))
            .flat_map(|l| l.iter().copied().take_while(|&h| h < ti))
            .collect();
        earlier.sort_unstable();
        earlier.dedup();
        for h in earlier {
            let h = &chart.transitions[h];
            out.push(il::opn(Op::And, il::var(&names::fire(&h.id), span)));
        }
        out.push(il::op(Op::St, il::var(&f, span)));
    }

    // 3. Evolution: deactivate, then activate.
    for t in &chart.transitions {
        out.push(il::op(Op::Ld, il::var(&names::fire(&t.id), t.span)));
        for &s in &t.pre {
            out.push(il::op(
                Op::R,
                il::var(&names::x(&chart.steps[s].name), t.span),
            ));
        }
    }
    for t in &chart.transitions {
        out.push(il::op(Op::Ld, il::var(&names::fire(&t.id), t.span)));
        for &s in &t.post {
            out.push(il::op(
                Op::S,
                il::var(&names::x(&chart.steps[s].name), t.span),
            ));
        }
    }

    // 4. Step times, after the evolution: a step activated in this scan starts from 0 now. A step
    // left and re-entered by the same transition (a loop on itself) restarts too: its timer sees
    // IN = FALSE once before the regular call.
    let mut self_loops: Vec<Vec<&chart::Transition>> = vec![Vec::new(); chart.steps.len()];
    for t in &chart.transitions {
        let mut pre = t.pre.clone();
        pre.sort_unstable();
        pre.dedup();
        for si in pre {
            if t.post.contains(&si) {
                if let Some(l) = self_loops.get_mut(si) {
                    l.push(t);
                }
            }
        }
    }
    for (si, s) in chart.steps.iter().enumerate() {
        let loops = std::mem::take(&mut self_loops[si]);
        if loops.is_empty() {
            continue;
        }
        let k = format!("__sfc_K_{}", s.name);
        hidden.declare(&k, "BOOL", None, s.span);
        out.push(il::op(Op::Ld, il::var(&names::x(&s.name), s.span)));
        for t in loops {
            out.push(il::opn(Op::And, il::var(&names::fire(&t.id), s.span)));
        }
        out.push(il::op(Op::St, il::var(&k, s.span)));
        out.push(il::call(
            &names::timer(&s.name),
            vec![
                ("IN", il::var(&k, s.span)),
                ("PT", il::lit_time(STEP_TIME_LIMIT_NS, s.span)),
            ],
            s.span,
        ));
    }
    if chart.order == chart::ScanOrder::TransitionsFirst {
        step_times(&chart.steps, &mut hidden, &mut out);
    }
    // (in TwinCAT's order the step times of the next scan's start are the refresh: a step
    // activated now has `Step.T` = 0 in its first scan of actions, as in IEC order)
    let actions_start = out.len();

    // 5. Actions: control, then bodies. While SFCInit holds the chart, the action control sees
    // its initial steps inactive (they stay active for conditions and bodies).
    if let Some(init) = &ctl.init {
        mask_initial(&chart.steps, init, Op::R, &mut out);
    }
    for a in &acts {
        actions::control(a, &chart.steps, rst.as_ref(), &mut hidden, &mut out);
    }
    if let Some(init) = &ctl.init {
        mask_initial(&chart.steps, init, Op::S, &mut out);
    }
    for a in &acts {
        let code = match &a.target {
            Target::Variable(_) => continue,
            Target::Call(inst_action) => vec![IlStmt::Instr(il_frontend::ast::Instruction {
                kind: il_frontend::ast::InstrKind::Call {
                    cond: il_frontend::ast::Condition::Always,
                    instance: Box::new(inst_action.clone()),
                    args: il_frontend::ast::CallArgs::None,
                },
                span: a.span,
            })],
            Target::Body(lang) => {
                match snippets.lower(ctx, lang, Purpose::Action, &mut hidden, &a.display) {
                    Some(code) => {
                        action_vars::warn_overwritten(ctx, &acts, &code, &a.display, &pou_name);
                        code
                    }
                    None => continue,
                }
            }
        };
        let skip = format!("__sfc_skip_{}", a.key);
        out.push(il::op(Op::Ld, il::var(&names::a(&a.key), a.span)));
        out.push(il::jump_if_false(&skip, a.span));
        out.extend(code);
        out.push(il::label(&skip, a.span));
    }
    if chart.order == chart::ScanOrder::ActionsFirst {
        // TwinCAT's processing order: the actions' part, then the transitions' part
        out[transitions_start..].rotate_left(actions_start - transitions_start);
    }

    // Chart names in conditions and bodies.
    let mut renames = Renames::default();
    for s in &chart.steps {
        step_flags(&mut renames, &s.name);
    }
    for a in &acts {
        if let Some(n) = &a.name {
            let k = n.to_ascii_uppercase();
            renames
                .fields
                .insert((k.clone(), "Q".into()), names::q(&a.key));
            renames.fields.insert((k, "A".into()), names::a(&a.key));
        }
    }
    for v in snippets.finish(body_span) {
        hidden.push(v);
    }
    renames.apply(&mut out);
    ctx.diags.extend(unknown_step_flags(&renames));
    (out, hidden.vars)
}

/// Renames `Step.X` and `Step.T` of the chart's `steps` in `stmts` to the chart's hidden variables
/// (as [`lower_chart`] does in its own conditions and actions): for the POU's own actions (an
/// `ACTIONS` block after the POU, a TwinCAT POU's `<Action>` objects) once the chart's `CAL`s of
/// them are inlined. IEC 61131-3 ed. 3 8.3.2 (ed. 2 2.6.2): `step.X`, `step.T`; Beckhoff Infosys
/// "Implicit variables" and CODESYS "Implicit Variables": `<stepname>.x`, `<stepname>.t`, readable
/// in every action of the SFC object, and `._x`, `._t` (`step_flags`).
/// A field of a step that is none of its flags is one E1021 in `diags` (`unknown_step_flags`).
pub fn rename_step_flags(stmts: &mut [IlStmt], steps: &[String], diags: &mut Diagnostics) {
    if steps.is_empty() {
        return;
    }
    let mut renames = Renames::default();
    for s in steps {
        step_flags(&mut renames, s);
    }
    renames.apply(stmts);
    diags.extend(unknown_step_flags(&renames));
}

/// One E1021 per `Step.Field` whose field is none of a step's flags (`Fill.Foo`), at the field,
/// naming the step and the flags it has (before round 33: E1001 "undeclared name `Fill`" at the
/// step, which is declared: it is the chart's). The reference itself was renamed to the step's
/// active flag, so nothing else is reported for it.
fn unknown_step_flags(renames: &Renames) -> Vec<diagnostics::Diagnostic> {
    renames
        .unknown_fields
        .borrow_mut()
        .drain(..)
        .map(|(step, field)| {
            diagnostics::Diagnostic::error(
                code::E1021,
                format!("step `{}` has no flag `{}`", step.name, field.name),
            )
            .at(field.span)
            .with_primary_label("unknown step flag")
            .with_hint("a step's flags are `X` (active) and `T` (time since it became active), IEC 61131-3 ed. 2 2.6.2, and CODESYS's and TwinCAT's `_x` and `_t`")
        })
        .collect()
}

/// The renames of one step's flags: `Step.X` and `Step._X` to its active flag, `Step.T` and
/// `Step._T` to its elapsed time. CODESYS and TwinCAT ("Implicit Variables", CODESYS SFC help and
/// Beckhoff Infosys) keep `_x` as the activation status for the next cycle, copied to `x` at the
/// start of a cycle, and `_t` as an internal copy of `t`: ladderc's chart decides the next cycle's
/// steps (scan order 3) before any action runs (5), so its one flag is both, and a `Step._x :=
/// TRUE` written by an action or another POU activates the step from the next scan on, as
/// CODESYS's forcing does.
fn step_flags(renames: &mut Renames, step: &str) {
    let k = step.to_ascii_uppercase();
    for (field, _) in il_frontend::st::sfc::STEP_FIELDS {
        let to = if field.ends_with('X') {
            names::x(step)
        } else {
            names::t(step)
        };
        renames.fields.insert((k.clone(), field.into()), to);
    }
    renames.closed_bases.insert(k, names::x(step));
}

/// The chart's reset by CODESYS's SFCInit / SFCReset (either TRUE, `__sfc_rst`): the initial steps
/// active, every other step inactive, every step timer stopped and `Step.T` zero, so that the
/// initial steps count from 0 again in this scan. Returns `__sfc_rst` (it also resets the stored
/// actions, [`actions::control`]), or `None` when neither flag is enabled.
fn reset(
    steps: &[chart::Step],
    ctl: &flags::Control,
    hidden: &mut Hidden,
    out: &mut Vec<IlStmt>,
) -> Option<il_frontend::ast::Operand> {
    let flags: Vec<&il_frontend::ast::Operand> = ctl.init.iter().chain(&ctl.reset).collect();
    let (first, rest) = flags.split_first()?;
    let span = steps.first().map(|s| s.span).unwrap_or_default();
    let (rst, tin) = ("__sfc_rst", "__sfc_tin");
    hidden.declare(rst, "BOOL", None, span);
    hidden.declare(tin, "BOOL", None, span);
    out.push(il::op(Op::Ld, (*first).clone()));
    for f in rest {
        out.push(il::op(Op::Or, (*f).clone()));
    }
    out.push(il::op(Op::St, il::var(rst, span)));
    for s in steps {
        let (x, t) = (names::x(&s.name), names::t(&s.name));
        out.push(il::op(Op::Ld, il::var(rst, s.span)));
        let set = if s.initial { Op::S } else { Op::R };
        out.push(il::op(set, il::var(&x, s.span)));
        out.push(il::sel(
            il::var(&t, s.span),
            il::lit_time(0, s.span),
            s.span,
        ));
        out.push(il::op(Op::St, il::var(&t, s.span)));
        // the timer sees IN = FALSE in a reset scan (then the step's flag, in `step_times`)
        out.push(il::op(Op::Ld, il::var(&x, s.span)));
        out.push(il::opn(Op::And, il::var(rst, s.span)));
        out.push(il::op(Op::St, il::var(tin, s.span)));
        out.push(il::call(
            &names::timer(&s.name),
            vec![
                ("IN", il::var(tin, s.span)),
                ("PT", il::lit_time(STEP_TIME_LIMIT_NS, s.span)),
            ],
            s.span,
        ));
    }
    Some(il::var(rst, span))
}

/// `LD init; R/S` every initial step flag (`op`): hides them from the action control while SFCInit
/// holds the chart, then shows them again.
fn mask_initial(
    steps: &[chart::Step],
    init: &il_frontend::ast::Operand,
    op: Op,
    out: &mut Vec<IlStmt>,
) {
    let initial: Vec<&chart::Step> = steps.iter().filter(|s| s.initial).collect();
    if initial.is_empty() {
        return;
    }
    out.push(il::op(Op::Ld, init.clone()));
    for s in initial {
        out.push(il::op(op, il::var(&names::x(&s.name), s.span)));
    }
}

/// `Step.T`: a TON per step (IN = the step flag) gives the time since activation; `T` follows it while
/// the step is active and keeps its last value after. Called twice per scan (before the conditions,
/// with this scan's clock; after the evolution, to start the timers of the steps just activated), so
/// `T` is exact in conditions and in actions.
fn step_times(steps: &[chart::Step], hidden: &mut Hidden, out: &mut Vec<IlStmt>) {
    for s in steps {
        let (x, t, tt) = (names::x(&s.name), names::t(&s.name), names::timer(&s.name));
        hidden.declare(&tt, "TON", None, s.span);
        out.push(il::call(
            &tt,
            vec![
                ("IN", il::var(&x, s.span)),
                ("PT", il::lit_time(STEP_TIME_LIMIT_NS, s.span)),
            ],
            s.span,
        ));
        out.push(il::op(Op::Ld, il::var(&x, s.span)));
        out.push(il::sel(
            il::var(&t, s.span),
            il::field(&tt, "ET", s.span),
            s.span,
        ));
        out.push(il::op(Op::St, il::var(&t, s.span)));
    }
}

/// A declared BOOL variable (of the POU or global) named `name`, as an operand.
fn declared_bool(
    index: &Index,
    pou: &Pou,
    name: &str,
    span: il_frontend::Span,
) -> Option<il_frontend::ast::Operand> {
    let key = name.to_ascii_uppercase();
    let ty = pou
        .var_blocks
        .iter()
        .flat_map(|b| b.vars.iter())
        .find(|v| v.name.key() == key)
        .map(|v| &v.ty)
        .or_else(|| index.globals.get(&key))?;
    match ty {
        il_frontend::ast::TypeRef::Named(n) if n.is("BOOL") => {
            crate::values::var_ref(name, span).map(il_frontend::ast::Operand::Var)
        }
        _ => None,
    }
}

/// The LD/FBD elements of the chart body, with one output variable per connection-based condition
/// (`__sfc_c<localId>`), lowered as networks like an LD/FBD body.
fn networks(
    ctx: &mut Ctx,
    index: &Index,
    pou: &Pou,
    sfc: &Element,
    chart: &chart::Chart,
    hidden: &mut Hidden,
    out: &mut Vec<IlStmt>,
) {
    let pou_name = pou.name.name.clone();
    let body = Element {
        children: &chart.network_elements,
        ..*sfc
    };
    let mut g = graph::read(ctx, &body, &pou_name);
    let ids: std::collections::HashMap<String, usize> = g
        .nodes
        .iter()
        .enumerate()
        .map(|(i, n)| (n.id.to_string(), i))
        .collect();
    for t in &chart.transitions {
        let CondSource::Connection(c) = t.cond else {
            continue;
        };
        let conns: Vec<&Element> = c
            .children_named("connectionPointIn")
            .flat_map(|p| p.children_named("connection"))
            .chain(c.children_named("connection"))
            .collect();
        let mut wires = Vec::new();
        for conn in conns {
            let r = conn.attr("refLocalId").unwrap_or_default().trim();
            match ids.get(r) {
                Some(&from) => wires.push(Wire {
                    from,
                    pin: conn
                        .attr("formalParameter")
                        .map(str::trim)
                        .filter(|s| !s.is_empty())
                        .map(std::borrow::Cow::Borrowed),
                    span: ctx.tag(conn),
                }),
                None => report(
                    ctx,
                    code::E3120,
                    ctx.tag(conn),
                    &pou_name,
                    Some(&t.id),
                    format!(
                        "the condition of transition {} is connected to localId {r}, which is not an \
                         LD/FBD element of this chart",
                        t.id
                    ),
                ),
            }
        }
        if wires.is_empty() {
            report(
                ctx,
                code::E3126,
                t.span,
                &pou_name,
                Some(&t.id),
                format!("transition {} has an unconnected condition", t.id),
            );
            continue;
        }
        let idx = g.nodes.len();
        g.nodes.push(Node {
            id: t.id.clone().into(),
            num: u64::MAX,
            kind: Kind::OutVar {
                expr: names::cond(&t.id).into(),
                expr_span: t.span,
                negated: false,
            },
            span: t.span,
            exec_order: None,
            x: i64::MAX,
            y: i64::MAX,
            input: wires,
            has_input: true,
            wired: true,
        });
        // The condition joins the network(s) of its sources (merged when it reads several).
        let sources: Vec<usize> = g.nodes[idx].input.iter().map(|w| w.from).collect();
        let mut merged: Vec<usize> = Vec::new();
        let mut keep = Vec::new();
        for net in std::mem::take(&mut g.networks) {
            if sources.iter().any(|s| net.contains(s)) {
                if merged.is_empty() {
                    keep.push(Vec::new()); // placeholder at the first merged network's place
                }
                merged.extend(net);
            } else {
                keep.push(net);
            }
        }
        merged.push(idx);
        match keep.iter_mut().find(|n| n.is_empty()) {
            Some(slot) => *slot = merged,
            None => keep.push(merged),
        }
        g.networks = keep;
    }
    let mut low = BodyLowering::new(index, pou, ctx.tag(sfc));
    out.extend(low.lower(ctx, &g));
    for v in low.hidden_vars() {
        hidden.push(v);
    }
}
