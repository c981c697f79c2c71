//! Action associations and action control (IEC 61131-3 2nd ed. 2.6.4, the ACTION_CONTROL block).
//!
//! Input: the chart's associations (step, `<action>` element, or a CODESYS entry/step/exit action
//! of the step's vendor data), the POU's named actions (`<actions>`), the actions of the function
//! block instances it declares, and declared variables. Output: the actions in first-association order, each with the steps that
//! drive each qualifier and its durations; then the IL that computes every action's `Q` (active) and
//! `A` (execute: `Q`, plus one final scan after the non-P part of `Q` falls, plus the P1/P0 pulses)
//! from the step flags. Under Beremiz's action control ([`ActionControl::Beremiz`], the target
//! profile's `sfc_action_control`, set once per project by [`set_action_control`]) `A` has no final
//! scan and an initial step's P and P1 pulses wait for its next activation, as matiec does.
//! Invariants: one action control per action, whatever the number of associations (their qualifier
//! inputs are OR-combined, as IEC requires); timed qualifiers have a duration (else E3123); a name
//! that is neither a named action nor a declared BOOL variable is E3122.

use super::chart::{report, Association, Step, StepAction};
use super::il::{self, Hidden};
use super::names;
use crate::context::Ctx;
use crate::values;
use crate::xml::Element;
use diagnostics::code;
use il_frontend::ast::{IlStmt, LiteralKind, Op, Operand, Pou, TypeRef};
use il_frontend::Span;

/// Which tool's action control the charts follow (the target profile's `sfc_action_control`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ActionControl {
    /// IEC 61131-3 ed. 2 2.6.4.5 (ed. 3 6.7.4.6), the ACTION_CONTROL block: a body runs once more
    /// in the scan its `Q` falls (the final scan); an initial step becomes active in the first
    /// scan, so its P (P1) action runs then.
    #[default]
    Iec,
    /// Beremiz and OpenPLC (matiec's generated chart code, `generate_c_sfc.cc`): a body runs only
    /// while its action is active, and a step's `prev_state` starts equal to its `X`, so an
    /// initial step's P (P1) action runs only on a later activation.
    Beremiz,
}

thread_local! {
    /// The action control of the charts lowered now ([`set_action_control`]).
    static ACTION_CONTROL: std::cell::Cell<ActionControl> = const { std::cell::Cell::new(ActionControl::Iec) };
}

/// Sets the action control the charts of the project being read follow (the target profile's);
/// returns the one set before, to put back when the project is read.
pub fn set_action_control(c: ActionControl) -> ActionControl {
    ACTION_CONTROL.with(|a| a.replace(c))
}

/// An action qualifier (IEC 61131-3 2nd ed. 2.6.4.4, table 45): how an association's step drives the action.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Qualifier {
    /// `N` (or none): non-stored, active while the step is active.
    N,
    /// `R`: overriding reset of a stored action.
    R,
    /// `S`: set (stored), active until reset.
    S,
    /// `L`: time limited, active while the step is, at most for the duration.
    L,
    /// `D`: time delayed, active once the step has been active for the duration.
    D,
    /// `P`: pulse, one scan when the step becomes active.
    P,
    /// `P1`: pulse on the step's rising edge (edition 3).
    P1,
    /// `P0`: pulse on the step's falling edge (edition 3).
    P0,
    /// `SD`: stored and time delayed.
    SD,
    /// `DS`: delayed and stored.
    DS,
    /// `SL`: stored and time limited.
    SL,
    /// A CODESYS step action (vendor data, [`super::chart::StepAction::Active`]): executed while
    /// the step is active, with no final scan (not a qualifier one can write).
    StepAction,
}

impl Qualifier {
    /// The qualifier of the `qualifier` attribute (case-insensitive, blank means `N`); `None` for an
    /// unknown one.
    pub fn parse(s: &str) -> Option<Qualifier> {
        Some(match s.trim().to_ascii_uppercase().as_str() {
            "" | "N" => Qualifier::N,
            "R" => Qualifier::R,
            "S" => Qualifier::S,
            "L" => Qualifier::L,
            "D" => Qualifier::D,
            "P" => Qualifier::P,
            "P1" => Qualifier::P1,
            "P0" => Qualifier::P0,
            "SD" => Qualifier::SD,
            "DS" => Qualifier::DS,
            "SL" => Qualifier::SL,
            _ => return None,
        })
    }
    /// Whether the qualifier needs a duration (`L`, `D`, `SD`, `DS`, `SL`).
    pub fn timed(self) -> bool {
        matches!(
            self,
            Qualifier::L | Qualifier::D | Qualifier::SD | Qualifier::DS | Qualifier::SL
        )
    }
    fn tag(self) -> &'static str {
        match self {
            Qualifier::N => "N",
            Qualifier::R => "R",
            Qualifier::S => "S",
            Qualifier::L => "L",
            Qualifier::D => "D",
            Qualifier::P => "P",
            Qualifier::P1 => "P1",
            Qualifier::P0 => "P0",
            Qualifier::SD => "SD",
            Qualifier::DS => "DS",
            Qualifier::SL => "SL",
            Qualifier::StepAction => "SA",
        }
    }
}

/// What an action does when it executes.
pub enum Target<'e, 'a> {
    /// A body (its language element): runs while `A` is TRUE.
    Body(&'e Element<'a>),
    /// A BOOL variable: gets the action's `Q` every scan.
    Variable(Operand),
    /// An action of a function block instance (`Motor.ACT_Stop`, CODESYS): called (`CAL
    /// Motor.ACT_Stop`) while `A` is TRUE, as a body would run.
    Call(il_frontend::ast::VarRef),
}

/// One action of the chart with every association that drives it.
pub struct Action<'e, 'a> {
    /// The hidden-name suffix (`Fill`, or `b6_0` for the first inline action of block 6).
    pub key: String,
    /// How the engineer names it ("action `Fill`", "inline action 1 of action block 6").
    pub display: String,
    /// The user-visible name (`Fill.Q`), when it has one.
    pub name: Option<String>,
    /// What it does: run a body or drive a BOOL variable.
    pub target: Target<'e, 'a>,
    /// (qualifier, step index, duration) per association.
    pub uses: Vec<(Qualifier, usize, Option<Operand>)>,
    /// The first association's element.
    pub span: Span,
}

fn is_bool_var(pou: &Pou, index: &crate::project::Index, name: &str) -> Option<bool> {
    let key = name.to_ascii_uppercase();
    let ty = pou
        .var_blocks
        .iter()
        .flat_map(|b| b.vars.iter())
        .find(|v| v.name.key() == key)
        .map(|v| &v.ty)
        .or_else(|| index.globals.get(&key))?;
    Some(matches!(ty, TypeRef::Named(n) if n.is("BOOL")))
}

/// Groups the associations into actions (first-association order).
pub fn collect<'e, 'a>(
    ctx: &mut Ctx,
    pou_el: &'e Element<'a>,
    pou: &Pou,
    index: &crate::project::Index,
    steps: &[Step],
    assocs: &[Association<'e, 'a>],
) -> Vec<Action<'e, 'a>> {
    let pou_name = pou.name.name.as_str();
    let named: Vec<&'e Element<'a>> = pou_el
        .child("actions")
        .map(|a| a.children_named("action").collect())
        .unwrap_or_default();
    let mut out: Vec<Action> = Vec::new();
    for a in assocs {
        let span = ctx.tag(a.el);
        let (q, duration) = match a.vendor {
            Some(StepAction::Exit) => (Qualifier::P0, None),
            Some(StepAction::Entry) => (Qualifier::P1, None),
            Some(StepAction::Active) => (Qualifier::StepAction, None),
            None => match qualifier_of(ctx, a, pou, index, steps, span) {
                Some(qd) => qd,
                None => continue,
            },
        };
        let step_name = &steps[a.step].name;
        // Which action.
        // the action a CODESYS step action names is its attribute's text
        let reference: Option<(String, Span)> = match a.vendor {
            Some(_) => Some((a.el.text_ref().trim().to_string(), span)),
            None => a.el.child("reference").map(|r| {
                (
                    r.attr("name").unwrap_or_default().trim().to_string(),
                    ctx.attr_span(r, "name"),
                )
            }),
        };
        let (key, display, name, target) = if let Some((n, nspan)) = &reference {
            let (n, nspan) = (n.as_str(), *nspan);
            if let Some(call) = instance_action(pou, index, n, nspan) {
                // `__` cannot occur in a name the chart's actions take (E3122), so no key clashes
                let k = n.replace('.', "__");
                out_push(
                    &mut out,
                    Action {
                        key: k,
                        display: format!("action `{n}`"),
                        name: None,
                        target: Target::Call(call),
                        uses: vec![(q, a.step, duration)],
                        span,
                    },
                );
                continue;
            }
            if !values::is_ident(n) || n.contains("__") {
                report(
                    ctx,
                    code::E3122,
                    nspan,
                    pou_name,
                    Some(&a.block_id),
                    format!(
                        "step `{step_name}` names action `{n}`, which is not an IEC identifier"
                    ),
                );
                continue;
            }
            if let Some(act) = named.iter().find(|e| {
                e.attr("name")
                    .is_some_and(|x| x.trim().eq_ignore_ascii_case(n))
            }) {
                let Some(lang) = act.child("body").and_then(|b| {
                    b.children
                        .iter()
                        .find(|c| !matches!(c.name(), "documentation" | "addData"))
                }) else {
                    report(
                        ctx,
                        code::E3122,
                        ctx.tag(act),
                        pou_name,
                        None,
                        format!("action `{n}` has no body"),
                    );
                    continue;
                };
                // an action whose body is a chart of its own (CODESYS) is lowered once for the
                // POU (`crate::body`), its state the POU's: the chart calls it (`CAL Act`)
                let target = if lang.name() == "SFC" {
                    Target::Call(il::var_ref(n, nspan))
                } else {
                    Target::Body(lang)
                };
                (
                    n.to_string(),
                    format!("action `{n}`"),
                    Some(n.to_string()),
                    target,
                )
            } else if index.pous.get(&pou.name.key()).is_some_and(|sig| {
                sig.kind != il_frontend::ast::PouKind::Function
                    && sig.actions.iter().any(|x| x.eq_ignore_ascii_case(n))
            }) {
                // an action of the POU written outside the chart (an `ACTIONS` block of an ST
                // file, a TwinCAT `<Action>`): the chart calls it (`CAL Act`), as an action of
                // its own POU
                (
                    n.to_string(),
                    format!("action `{n}`"),
                    Some(n.to_string()),
                    Target::Call(il::var_ref(n, nspan)),
                )
            } else {
                match is_bool_var(pou, index, n) {
                    Some(true) if values::is_ident(n) => (
                        n.to_string(),
                        format!("boolean action `{n}`"),
                        None,
                        Target::Variable(il::var(n, nspan)),
                    ),
                    Some(_) => {
                        report(
                            ctx,
                            code::E3122,
                            nspan,
                            pou_name,
                            Some(&a.block_id),
                            format!(
                                "step `{step_name}` names `{n}` as an action: it is a variable, but not \
                                 BOOL (only BOOL variables can be actions)"
                            ),
                        );
                        continue;
                    }
                    None => {
                        report(
                            ctx,
                            code::E3122,
                            nspan,
                            pou_name,
                            Some(&a.block_id),
                            format!(
                                "step `{step_name}` names action `{n}`, which is neither an action \
                                 of the POU nor a BOOL variable"
                            ),
                        );
                        continue;
                    }
                }
            }
        } else if let Some(lang) = a.el.child("inline").and_then(|i| {
            i.children
                .iter()
                .find(|c| !matches!(c.name(), "documentation" | "addData"))
        }) {
            (
                format!("b{}_{}", super::sanitize(&a.block_id), a.index),
                format!(
                    "inline action {} of action block {}",
                    a.index + 1,
                    a.block_id
                ),
                None,
                Target::Body(lang),
            )
        } else {
            report(
                ctx,
                code::E3122,
                span,
                pou_name,
                Some(&a.block_id),
                "<action> without a <reference> or an <inline> body".to_string(),
            );
            continue;
        };
        out_push(
            &mut out,
            Action {
                key,
                display,
                name,
                target,
                uses: vec![(q, a.step, duration)],
                span,
            },
        );
    }
    out
}

/// The OR of the step flags associated with qualifier `q`, as one operand (a hidden variable when
/// several steps); `None` when no association uses `q`.
/// The qualifier and duration of an `<action>` of an action block, its indicators checked; `None`
/// (reported) when one is wrong.
fn qualifier_of(
    ctx: &mut Ctx,
    a: &Association,
    pou: &Pou,
    index: &crate::project::Index,
    steps: &[Step],
    span: Span,
) -> Option<(Qualifier, Option<Operand>)> {
    let pou_name = pou.name.name.as_str();
    let q_text = a.el.attr("qualifier").unwrap_or("N");
    let Some(q) = Qualifier::parse(q_text) else {
        report(
            ctx,
            code::E3123,
            ctx.attr_span(a.el, "qualifier"),
            pou_name,
            Some(&a.block_id),
            format!(
                "action qualifier `{}` is not one of N R S L D P P1 P0 SD DS SL",
                q_text.trim()
            ),
        );
        return None;
    };
    let duration = match a
        .el
        .attr("duration")
        .map(str::trim)
        .filter(|d| !d.is_empty())
    {
        Some(d) => {
            let ds = ctx.attr_span(a.el, "duration");
            let op = values::literal(d, ds)
                .filter(|l| matches!(l.kind, LiteralKind::Duration(_)))
                .map(Operand::literal)
                .or_else(|| values::duration(d).map(|ns| il::lit_time(ns, ds)))
                .or_else(|| values::var_ref(d, ds).map(Operand::Var));
            if op.is_none() {
                report(
                    ctx,
                    code::E3123,
                    ds,
                    pou_name,
                    Some(&a.block_id),
                    format!("action duration `{d}` is neither a TIME literal nor a variable"),
                );
                return None;
            }
            op
        }
        None => None,
    };
    if q.timed() && duration.is_none() {
        report(
            ctx,
            code::E3123,
            span,
            pou_name,
            Some(&a.block_id),
            format!(
                "qualifier {} needs a duration (for example duration=\"T#2s\")",
                q.tag()
            ),
        );
        return None;
    }
    // Indicator variables (IEC 61131-3 2nd ed. 2.6.4.2 field "d", 3rd ed. 6.7.4): declared
    // BOOL variables, which the action's body sets (the chart does not drive them)
    let mut bad_indicator = false;
    for ind in
        a.el.attr("indicator")
            .unwrap_or_default()
            .split(',')
            .map(str::trim)
            .filter(|n| !n.is_empty())
    {
        let ispan = ctx.attr_span(a.el, "indicator");
        if !(values::is_ident(ind) && is_bool_var(pou, index, ind) == Some(true)) {
            report(
                ctx,
                code::E3122,
                ispan,
                pou_name,
                Some(&a.block_id),
                format!(
                    "indicator `{ind}` of an action of step `{}` is not a declared BOOL variable",
                    steps[a.step].name
                ),
            );
            bad_indicator = true;
        }
    }
    if bad_indicator {
        return None;
    }
    Some((q, duration))
}

/// Adds `act` to the actions, or its association to the action of the same key already there.
fn out_push<'e, 'a>(out: &mut Vec<Action<'e, 'a>>, act: Action<'e, 'a>) {
    let k = act.key.to_ascii_uppercase();
    match out.iter_mut().find(|x| x.key.to_ascii_uppercase() == k) {
        Some(x) => x.uses.extend(act.uses),
        None => out.push(act),
    }
}

/// `inst.Act` where `inst` is a function block instance of the POU (or a global one, or an
/// instance inside one: `Table.Motor.ACT_Stop`) whose type has the action `Act` (CODESYS names an
/// instance's action in an action block): the call.
fn instance_action(
    pou: &Pou,
    index: &crate::project::Index,
    name: &str,
    span: Span,
) -> Option<il_frontend::ast::VarRef> {
    use il_frontend::ast::Accessor;
    let r = values::var_ref(name, span)?;
    let (Accessor::Field(act), path) = r.accessors.split_last()? else {
        return None;
    };
    let key = r.base.key();
    let mut ty = pou
        .var_blocks
        .iter()
        .flat_map(|b| b.vars.iter())
        .find(|v| v.name.key() == key)
        .map(|v| &v.ty)
        .or_else(|| index.globals.get(&key))?;
    // `Table.Motor.ACT_Stop`: an instance inside an instance (CODESYS)
    for a in path {
        let (Accessor::Field(f), TypeRef::Named(fb)) = (a, ty) else {
            return None;
        };
        let sig = index.pous.get(&fb.key())?;
        ty = sig
            .pins
            .iter()
            .chain(&sig.internals)
            .find(|(n, _, _)| f.is(n))
            .map(|(_, _, t)| t)?;
    }
    let TypeRef::Named(fb) = ty else {
        return None;
    };
    let sig = index.pous.get(&fb.key())?;
    (sig.kind == il_frontend::ast::PouKind::FunctionBlock && sig.actions.iter().any(|x| act.is(x)))
        .then_some(r)
}

fn input(
    act: &Action,
    q: Qualifier,
    steps: &[Step],
    hidden: &mut Hidden,
    out: &mut Vec<IlStmt>,
) -> Option<Operand> {
    let span = act.span;
    let mut flags: Vec<usize> = act.uses.iter().filter(|u| u.0 == q).map(|u| u.1).collect();
    flags.sort_unstable();
    flags.dedup();
    match flags.as_slice() {
        [] => None,
        [s] => Some(il::var(&names::x(&steps[*s].name), span)),
        [first, rest @ ..] => {
            let v = names::action_part(&act.key, &format!("{}in", q.tag()));
            hidden.declare(&v, "BOOL", None, span);
            out.push(il::op(
                Op::Ld,
                il::var(&names::x(&steps[*first].name), span),
            ));
            for s in rest {
                out.push(il::op(Op::Or, il::var(&names::x(&steps[*s].name), span)));
            }
            out.push(il::op(Op::St, il::var(&v, span)));
            Some(il::var(&v, span))
        }
    }
}

fn duration_of(act: &Action, q: Qualifier) -> Option<Operand> {
    act.uses.iter().find(|u| u.0 == q).and_then(|u| u.2.clone())
}

/// The action control of one action: computes `Q` (and `A` for body actions, or the variable).
/// `chart_reset` (CODESYS's SFCInit / SFCReset, [`super::flags`]) resets the stored actions like
/// an `R` qualifier.
pub fn control(
    act: &Action,
    steps: &[Step],
    chart_reset: Option<&Operand>,
    hidden: &mut Hidden,
    out: &mut Vec<IlStmt>,
) {
    let span = act.span;
    let k = &act.key;
    let part = |p: &str| names::action_part(k, p);
    let v = |n: &str| il::var(n, span);
    let f = |inst: &str, pin: &str| il::field(inst, pin, span);
    let r = input(act, Qualifier::R, steps, hidden, out);
    let r = match (r, chart_reset) {
        (r, None) => r.unwrap_or(il::lit_bool(false, span)),
        (None, Some(c)) => c.clone(),
        (Some(r), Some(c)) => {
            let rr = part("Rr");
            hidden.declare(&rr, "BOOL", None, span);
            out.push(il::op(Op::Ld, r));
            out.push(il::op(Op::Or, c.clone()));
            out.push(il::op(Op::St, v(&rr)));
            v(&rr)
        }
    };
    // Terms of Q: each a list of (op, negate, operand) starting with LD.
    let mut terms: Vec<Vec<(Op, bool, Operand)>> = Vec::new();
    if let Some(n) = input(act, Qualifier::N, steps, hidden, out) {
        terms.push(vec![(Op::Ld, false, n)]);
    }
    if let Some(s) = input(act, Qualifier::S, steps, hidden, out) {
        let ff = part("S");
        hidden.declare(&ff, "RS", None, span);
        out.push(il::call(&ff, vec![("S", s), ("R1", r.clone())], span));
        terms.push(vec![(Op::Ld, false, f(&ff, "Q1"))]);
    }
    if let Some(l) = input(act, Qualifier::L, steps, hidden, out) {
        let t = part("L");
        hidden.declare(&t, "TON", None, span);
        let pt = duration_of(act, Qualifier::L).unwrap_or(il::lit_time(0, span));
        out.push(il::call(&t, vec![("IN", l.clone()), ("PT", pt)], span));
        terms.push(vec![(Op::Ld, false, l), (Op::And, true, f(&t, "Q"))]);
    }
    if let Some(d) = input(act, Qualifier::D, steps, hidden, out) {
        let t = part("D");
        hidden.declare(&t, "TON", None, span);
        let pt = duration_of(act, Qualifier::D).unwrap_or(il::lit_time(0, span));
        out.push(il::call(&t, vec![("IN", d), ("PT", pt)], span));
        terms.push(vec![(Op::Ld, false, f(&t, "Q"))]);
    }
    let control = ACTION_CONTROL.with(std::cell::Cell::get);
    // The rising edge of a pulse qualifier's step flags: Beremiz takes an initial step as active
    // before the first scan (no pulse then); IEC's R_TRIG starts FALSE (a pulse in the first scan).
    let rising = |q: Qualifier, x: Operand, hidden: &mut Hidden, out: &mut Vec<IlStmt>| {
        let initial = act
            .uses
            .iter()
            .any(|u| u.0 == q && steps.get(u.1).is_some_and(|s| s.initial));
        if control == ActionControl::Beremiz && initial {
            let (m, e) = (part(&format!("{}m", q.tag())), part(q.tag()));
            hidden.declare(&m, "BOOL", Some(il::lit_bool(true, span)), span);
            hidden.declare(&e, "BOOL", None, span);
            out.push(il::op(Op::Ld, x.clone()));
            out.push(il::opn(Op::And, v(&m)));
            out.push(il::op(Op::St, v(&e)));
            out.push(il::op(Op::Ld, x));
            out.push(il::op(Op::St, v(&m)));
            v(&e)
        } else {
            let t = part(q.tag());
            hidden.declare(&t, "R_TRIG", None, span);
            out.push(il::call(&t, vec![("CLK", x)], span));
            f(&t, "Q")
        }
    };
    // P is part of Q but gets no final scan (it runs exactly once per activation).
    let mut p_pulse: Option<Operand> = None;
    if let Some(p) = input(act, Qualifier::P, steps, hidden, out) {
        p_pulse = Some(rising(Qualifier::P, p, hidden, out));
    }
    if let Some(sd) = input(act, Qualifier::SD, steps, hidden, out) {
        let (ff, t) = (part("SDff"), part("SDt"));
        hidden.declare(&ff, "RS", None, span);
        hidden.declare(&t, "TON", None, span);
        let pt = duration_of(act, Qualifier::SD).unwrap_or(il::lit_time(0, span));
        out.push(il::call(&ff, vec![("S", sd), ("R1", r.clone())], span));
        out.push(il::call(&t, vec![("IN", f(&ff, "Q1")), ("PT", pt)], span));
        terms.push(vec![(Op::Ld, false, f(&t, "Q"))]);
    }
    if let Some(ds) = input(act, Qualifier::DS, steps, hidden, out) {
        let (t, ff) = (part("DSt"), part("DSff"));
        hidden.declare(&t, "TON", None, span);
        hidden.declare(&ff, "RS", None, span);
        let pt = duration_of(act, Qualifier::DS).unwrap_or(il::lit_time(0, span));
        out.push(il::call(&t, vec![("IN", ds), ("PT", pt)], span));
        out.push(il::call(
            &ff,
            vec![("S", f(&t, "Q")), ("R1", r.clone())],
            span,
        ));
        terms.push(vec![(Op::Ld, false, f(&ff, "Q1"))]);
    }
    if let Some(sl) = input(act, Qualifier::SL, steps, hidden, out) {
        let (ff, t) = (part("SLff"), part("SLt"));
        hidden.declare(&ff, "RS", None, span);
        hidden.declare(&t, "TON", None, span);
        let pt = duration_of(act, Qualifier::SL).unwrap_or(il::lit_time(0, span));
        out.push(il::call(&ff, vec![("S", sl), ("R1", r.clone())], span));
        out.push(il::call(&t, vec![("IN", f(&ff, "Q1")), ("PT", pt)], span));
        terms.push(vec![
            (Op::Ld, false, f(&ff, "Q1")),
            (Op::And, true, f(&t, "Q")),
        ]);
    }
    // Pulses (P1 on activation, P0 on deactivation): executed once, no final scan; a CODESYS
    // step action runs while its step is active, without a final scan either.
    let mut pulses: Vec<Operand> = Vec::new();
    if let Some(x) = input(act, Qualifier::StepAction, steps, hidden, out) {
        pulses.push(x);
    }
    if let Some(p1) = input(act, Qualifier::P1, steps, hidden, out) {
        pulses.push(rising(Qualifier::P1, p1, hidden, out));
    }
    if let Some(p0) = input(act, Qualifier::P0, steps, hidden, out) {
        // Falling edge with our own memory (F_TRIG's first call on FALSE would pulse).
        let (m, q) = (part("P0m"), part("P0"));
        hidden.declare(&m, "BOOL", None, span);
        hidden.declare(&q, "BOOL", None, span);
        out.push(il::op(Op::Ld, v(&m)));
        out.push(il::opn(Op::And, p0.clone()));
        out.push(il::op(Op::St, v(&q)));
        out.push(il::op(Op::Ld, p0));
        out.push(il::op(Op::St, v(&m)));
        pulses.push(v(&q));
    }
    // Q := OR of the terms.
    let q = names::q(k);
    hidden.declare(&q, "BOOL", None, span);
    if terms.is_empty() {
        out.push(il::op(Op::Ld, il::lit_bool(false, span)));
    }
    for (i, t) in terms.into_iter().enumerate() {
        let code: Vec<IlStmt> = t
            .into_iter()
            .map(|(o, n, x)| il::simple(o, n, Some(x), span))
            .collect();
        if i == 0 {
            out.extend(code);
        } else if code.len() == 1 {
            let IlStmt::Instr(ins) = &code[0] else {
                continue;
            };
            if let il_frontend::ast::InstrKind::Simple { operand, .. } = &ins.kind {
                out.push(il::simple(Op::Or, false, operand.clone(), span));
            }
        } else {
            out.push(il::deferred(Op::Or, code, span));
        }
    }
    // The part of Q that gets a final scan (everything but P), then Q itself.
    let qn = match p_pulse {
        Some(p) => {
            let qn = part("Qn");
            hidden.declare(&qn, "BOOL", None, span);
            out.push(il::op(Op::St, v(&qn)));
            out.push(il::op(Op::Ld, v(&qn)));
            out.push(il::op(Op::Or, p));
            out.push(il::op(Op::St, v(&q)));
            qn
        }
        None => {
            out.push(il::op(Op::St, v(&q)));
            q.clone()
        }
    };
    match &act.target {
        Target::Variable(var) => {
            out.push(il::op(Op::Ld, v(&q)));
            for p in pulses {
                out.push(il::op(Op::Or, p));
            }
            out.push(il::op(Op::St, var.clone()));
        }
        Target::Body(_) | Target::Call(_) if control == ActionControl::Beremiz => {
            // A := Q OR pulses: no final scan (Beremiz, matiec)
            let a = names::a(k);
            hidden.declare(&a, "BOOL", None, span);
            out.push(il::op(Op::Ld, v(&q)));
            for p in pulses {
                out.push(il::op(Op::Or, p));
            }
            out.push(il::op(Op::St, v(&a)));
        }
        Target::Body(_) | Target::Call(_) => {
            // A := Q OR final scan (the non-P part of Q was TRUE last scan) OR pulses.
            let (a, m) = (names::a(k), part("Qm"));
            hidden.declare(&a, "BOOL", None, span);
            hidden.declare(&m, "BOOL", None, span);
            out.push(il::op(Op::Ld, v(&m)));
            out.push(il::op(Op::Or, v(&q)));
            for p in pulses {
                out.push(il::op(Op::Or, p));
            }
            out.push(il::op(Op::St, v(&a)));
            out.push(il::op(Op::Ld, v(&qn)));
            out.push(il::op(Op::St, v(&m)));
        }
    }
}
