//! Textual SFC (the `INITIAL_STEP`/`STEP`/`TRANSITION`/`ACTION` body of an ST POU) lowered by the same code
//! as a PLCopen XML `<SFC>` body.
//!
//! Input: the `.st` file text, the body's byte range, the POU (interface) and the parsed units of the
//! program. Output: the IL statements and hidden declarations of [`super::lower_chart`].
//! Invariants: the chart is read by [`il_frontend::st::sfc::read`] and turned into the [`Chart`] the XML
//! reader builds, with small in-memory elements standing for the `<action>` associations, the `<ST>`/`<IL>`
//! condition and action bodies (their text segments point into the `.st` file, so every span of the
//! lowered code and every diagnostic is located in the `.st` file); no second SFC semantics.

use super::chart::{
    report, Association, Chart, CondSource, ScanOrder, Step, StepAction, Transition,
};
use crate::context::Ctx;
use crate::project::{Index, PouSig};
use crate::xml::{Arena, Element, SegKind, TextSeg};
use diagnostics::{code, Diagnostics};
use il_frontend::ast::{CompilationUnit, IlStmt, LibraryElement, Pou, PouKind, VarDecl, VarKind};
use il_frontend::st::sfc::{self, TextCondition};
use il_frontend::{FileId, Span};
use std::ops::Range;

/// The project index of parsed units (ST/IL files): POU interfaces, data types and global variables.
pub fn index_of_units(units: &[CompilationUnit]) -> Index {
    let mut index = Index::default();
    let globals = |b: &il_frontend::ast::VarBlock, index: &mut Index| {
        for v in &b.vars {
            index.globals.insert(v.name.key(), v.ty.clone());
        }
    };
    for item in units.iter().flat_map(|u| u.items.iter()) {
        match item {
            LibraryElement::DataTypes(ts) => {
                for t in ts {
                    index.types.insert(t.name.key(), t.clone());
                }
            }
            LibraryElement::Pou(p) => {
                let (pins, internals) = p
                    .var_blocks
                    .iter()
                    .flat_map(|b| {
                        b.vars
                            .iter()
                            .map(move |v| (v.name.name.clone(), b.kind, v.ty.clone()))
                    })
                    .partition(|(_, k, _)| {
                        matches!(k, VarKind::Input | VarKind::Output | VarKind::InOut)
                    });
                index.pous.insert(
                    p.name.key(),
                    PouSig {
                        kind: p.kind,
                        name: p.name.name.clone(),
                        pins,
                        ret: p.return_type.clone(),
                        internals,
                        actions: Vec::new(),
                    },
                );
            }
            LibraryElement::GlobalVars(b) => globals(b, &mut index),
            LibraryElement::Configuration(c) => {
                for b in c
                    .globals
                    .iter()
                    .chain(c.resources.iter().flat_map(|r| r.globals.iter()))
                {
                    globals(b, &mut index);
                }
            }
            LibraryElement::Action(_) => {}
        }
    }
    // the methods of function blocks (property accessors too: `p^.Start` in a transition's
    // condition calls `Start`'s Get accessor), as the ST lowering of conditions and actions
    // needs them; before round 32 none, so a property read there was E1011
    let blocks: std::collections::HashMap<String, &Pou> = units
        .iter()
        .flat_map(|u| u.items.iter())
        .filter_map(|item| match item {
            LibraryElement::Pou(p) => Some((p.name.key(), p)),
            _ => None,
        })
        .collect();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        if let LibraryElement::Action(a) = item {
            if let Some(inputs) = &a.method_inputs {
                let sig = method_sig(a, inputs, blocks.get(&a.pou.key()).copied());
                index.method_sigs.entry(a.pou.key()).or_default().push(sig);
            }
        }
    }
    // the actions of programs and function blocks (`ACTIONS` blocks after the POU, CODESYS and
    // TwinCAT), which a chart names in its associations
    for item in units.iter().flat_map(|u| u.items.iter()) {
        if let LibraryElement::Action(a) = item {
            // (an action TwinCAT keeps before a method is read as a method without inputs)
            if a.method_inputs.as_ref().is_none_or(|m| m.is_empty()) {
                if let Some(sig) = index.pous.get_mut(&a.pou.key()) {
                    sig.actions.push(a.name.name.clone());
                }
            }
        }
    }
    index
}

/// The interface of method `a` of a block (`inputs`: its VAR_INPUT and VAR_IN_OUT names), read
/// from the hidden variables its block got for it (`__M_<METHOD>_<var>`, result `__M_<METHOD>`).
fn method_sig(
    a: &il_frontend::ast::Action,
    inputs: &[il_frontend::ast::Ident],
    block: Option<&Pou>,
) -> il_frontend::st::types::MethodSig {
    use il_frontend::actions::{method_result, method_var};
    let declared = |name: &str, kind: Option<VarKind>| {
        block.is_some_and(|p| {
            p.var_blocks
                .iter()
                .filter(|b| kind.is_none_or(|k| b.kind == k))
                .flat_map(|b| b.vars.iter())
                .any(|v| v.name.name.eq_ignore_ascii_case(name))
        })
    };
    let names = |xs: &[il_frontend::ast::Ident]| xs.iter().map(|i| i.name.clone()).collect();
    il_frontend::st::types::MethodSig {
        name: a.name.name.clone(),
        inputs: names(inputs),
        in_outs: inputs
            .iter()
            .filter(|i| declared(&method_var(&a.name.name, &i.name), Some(VarKind::InOut)))
            .map(|i| i.name.clone())
            .collect(),
        constant_in_outs: Vec::new(),
        outputs: names(&a.method_outputs),
        returns: declared(&method_result(&a.name.name), None),
        overloaded: false,
    }
}

/// An element holding `src[r]` as its text (an `<ST>` or `<IL>` body).
fn text_element<'a>(arena: &'a Arena, name: &'a str, src: &'a str, r: Range<usize>) -> Element<'a> {
    let el = Element::new(name, r.start, r.start, r.end);
    let text = arena.slice(vec![TextSeg {
        text: src.get(r.clone()).unwrap_or(""),
        start: r.start,
        end: r.end,
        kind: SegKind::CData,
    }]);
    Element::with_segments(el, text, arena)
}

/// An element of start tag `raw_tag` (whose name is `name`) over `at`.
fn element<'a>(name: &'a str, raw_tag: &'a str, at: Range<usize>) -> Element<'a> {
    let el = Element::new(raw_tag, at.start, at.end, at.end);
    debug_assert_eq!(el.name(), name);
    el
}

/// Escapes an attribute value for a synthesized start tag.
fn attr_value(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('"', "&quot;")
        .replace('<', "&lt;")
}

/// Lowers the textual SFC body `src[body]` of `pou` (file `file`): its code, its hidden variables and
/// the names of its steps (whose `Step.X`/`Step.T` the POU's own actions may read, renamed by
/// [`super::rename_step_flags`] once they are inlined). Diagnostics go to `diags`; a chart with
/// errors in its structure gives no code.
pub fn lower(
    file: FileId,
    src: &str,
    body: Range<usize>,
    pou: &Pou,
    index: &Index,
    diags: &mut Diagnostics,
) -> (Vec<IlStmt>, Vec<VarDecl>, Vec<String>) {
    let pou_name = pou.name.name.clone();
    // Holds the in-memory elements built below.
    let arena = Arena::new();
    let (tc, found) = sfc::read(file, src, body.clone());
    let broken = !found.is_empty();
    for d in found {
        diags.push(d);
    }
    let mut ctx = Ctx::new(file, src, diags);
    if pou.kind == PouKind::Function {
        report(
            &mut ctx,
            code::E3125,
            Span::new(file, pou.name.span.start as usize, pou.name.span.end as usize),
            &pou_name,
            None,
            format!(
                "function `{pou_name}` is a sequential function chart: a function keeps no state \
                 between calls, so it cannot remember its active steps (make it a function block or a program)"
            ),
        );
        return (Vec::new(), Vec::new(), Vec::new());
    }
    if broken {
        return (Vec::new(), Vec::new(), Vec::new());
    }
    // Start tags of the in-memory elements (the attribute readers parse them).
    let action_tags: Vec<String> = tc
        .actions
        .iter()
        .map(|a| format!("action name=\"{}\"", attr_value(&a.name)))
        .collect();
    let assoc_tags: Vec<Vec<(String, String)>> = per_association(&tc.steps, |_, a| {
        let mut t = format!("action qualifier=\"{}\"", attr_value(&a.qualifier));
        if let Some(d) = &a.time {
            let text = src.get(d.clone()).unwrap_or("").trim();
            t.push_str(&format!(" duration=\"{}\"", attr_value(text)));
        }
        if !a.indicators.is_empty() {
            let names: Vec<&str> = a
                .indicators
                .iter()
                .map(|r| src.get(r.clone()).unwrap_or("").trim())
                .collect();
            t.push_str(&format!(" indicator=\"{}\"", attr_value(&names.join(","))));
        }
        (t, format!("reference name=\"{}\"", attr_value(&a.action)))
    });

    // <pou><actions><action name=..><body><ST>..</ST></body></action>...</actions></pou>
    let actions: Vec<Element> = tc
        .actions
        .iter()
        .zip(&action_tags)
        .map(|(a, tag)| {
            let mut body_el = element("body", "body", a.name_range.clone());
            body_el.children = arena.slice(vec![text_element(
                &arena,
                body_lang(src, &a.body),
                src,
                a.body.clone(),
            )]);
            let mut act = element("action", tag, a.name_range.clone());
            act.children = arena.slice(vec![body_el]);
            act
        })
        .collect();
    let mut actions_el = element("actions", "actions", body.start..body.start);
    actions_el.children = arena.slice(actions);
    let mut pou_el = element("pou", "pou", body.start..body.start);
    pou_el.children = arena.slice(vec![actions_el]);

    let conds: Vec<Element> = tc
        .transitions
        .iter()
        .map(|t| match &t.cond {
            TextCondition::Expression(r) => text_element(&arena, "ST", src, r.clone()),
            TextCondition::Instructions(r) => text_element(&arena, "IL", src, r.clone()),
        })
        .collect();
    let assocs: Vec<Vec<Element>> = per_association(&tc.steps, |(k, j), a| {
        let (tag, rtag) = &assoc_tags[k][j];
        let mut el = element("action", tag, a.range.clone());
        el.children = arena.slice(vec![element(
            "reference",
            rtag,
            a.range.start..a.range.start,
        )]);
        el
    });

    // a step action's element holds the name of the action it runs (as an XML chart's attribute)
    let vendor_names: Vec<Vec<Option<Element>>> = per_association(&tc.steps, |_, a| {
        vendor_kind(&a.qualifier).map(|_| {
            let r = a.range.start..a.range.start + a.action.len();
            text_element(&arena, "attribute", src, r)
        })
    });
    let span = |r: &Range<usize>| Span::new(file, r.start, r.end);
    let steps: Vec<Step> = tc
        .steps
        .iter()
        .enumerate()
        .map(|(k, s)| Step {
            id: (k + 1).to_string(),
            name: s.name.clone(),
            initial: s.initial,
            span: span(&s.name_range),
        })
        .collect();
    let first_transition = tc.steps.len() + 1;
    let mut transitions: Vec<Transition> = tc
        .transitions
        .iter()
        .zip(&conds)
        .enumerate()
        .map(|(k, (t, c))| Transition {
            id: (first_transition + k).to_string(),
            span: span(&t.range),
            cond: CondSource::Inline(c, ""),
            pre: t.from.clone(),
            post: t.to.clone(),
            order: (t.priority.unwrap_or(u32::MAX), 0, 0, 0, k as u64),
        })
        .collect();
    transitions.sort_by_key(|t| t.order);
    let mut associations = Vec::new();
    // CODESYS's step actions (`__ENTRY`/`__ACTIVE`/`__EXIT`, as the TwinCAT reader writes them)
    // first, as for an XML chart's vendor data: every exit action, then every entry action, then
    // every step action, steps in text order; each stands for the action it names
    let mut vendor: Vec<(StepAction, usize, &Element)> = Vec::new();
    for (k, (s, names)) in tc.steps.iter().zip(&vendor_names).enumerate() {
        for (a, el) in s.associations.iter().zip(names) {
            if let (Some(kind), Some(el)) = (vendor_kind(&a.qualifier), el) {
                vendor.push((kind, k, el));
            }
        }
    }
    vendor.sort_by_key(|v| v.0);
    for (i, (kind, k, el)) in vendor.into_iter().enumerate() {
        associations.push(Association {
            step: k,
            block_id: tc.steps[k].name.clone(),
            index: i,
            el,
            vendor: Some(kind),
        });
    }
    for (k, (s, els)) in tc.steps.iter().zip(&assocs).enumerate() {
        for (i, (el, a)) in els.iter().zip(&s.associations).enumerate() {
            if vendor_kind(&a.qualifier).is_some() {
                continue;
            }
            associations.push(Association {
                step: k,
                block_id: s.name.clone(),
                index: i,
                el,
                vendor: None,
            });
        }
    }
    // a step no transition leaves is a final step (W1464, as for XML charts), but an initial
    // step that no transition enters either is a network of one step, always active (IEC 61131-3
    // Annex F's gravel example): no warning
    for (k, s) in tc.steps.iter().enumerate() {
        let lone_initial = s.initial && !transitions.iter().any(|t| t.post.contains(&k));
        if !lone_initial && !transitions.iter().any(|t| t.pre.contains(&k)) {
            super::chart::warn_final_step(&mut ctx, span(&s.name_range), &pou_name, None, &s.name);
        }
    }
    let chart = Chart {
        steps,
        transitions,
        associations,
        network_elements: Vec::new(),
        flags: flag_marks(file, src, &body),
        order: scan_order(src, &body),
    };
    let sfc_el = element("SFC", "SFC", body.start..body.start);
    let step_names = chart.steps.iter().map(|s| s.name.clone()).collect();
    let (code, hidden) = super::lower_chart(&mut ctx, index, &pou_el, pou, &sfc_el, chart);
    (code, hidden, step_names)
}

/// How the TwinCAT reader (`crate::twincat_sfc`) passes on a chart's enabled SFC flags (its POU's
/// SFC settings): one comment per flag in the chart's body, `(*__SFC_FLAG Init 1 4711*)`: the
/// flag's name, whether TwinCAT declares its variable (1) and the offset of the setting in the file.
pub const FLAG_MARK: &str = "__SFC_FLAG";

/// How the TwinCAT reader (`crate::twincat_sfc`) says that a chart is TwinCAT's, so that it runs
/// in TwinCAT's processing order ([`ScanOrder::ActionsFirst`]): this comment in the chart's body.
pub const VENDOR_ORDER_MARK: &str = "(*__SFC_ORDER ActionsFirst*)";

/// The scan order of the chart in `src[body]`: TwinCAT's when the TwinCAT reader marked it
/// ([`VENDOR_ORDER_MARK`]), else IEC's (ladderc's order of textual and PLCopen XML charts).
fn scan_order(src: &str, body: &Range<usize>) -> ScanOrder {
    if src
        .get(body.clone())
        .is_some_and(|t| t.contains(VENDOR_ORDER_MARK))
    {
        ScanOrder::ActionsFirst
    } else {
        ScanOrder::TransitionsFirst
    }
}

/// The flags of the marks ([`FLAG_MARK`]) in `src[body]`.
fn flag_marks(file: FileId, src: &str, body: &Range<usize>) -> Vec<super::flags::Flag> {
    let text = src.get(body.clone()).unwrap_or("");
    let open = format!("(*{FLAG_MARK} ");
    let mut out = Vec::new();
    let mut from = 0;
    while let Some(k) = text[from..].find(&open) {
        let s = from + k + open.len();
        let Some(e) = text[s..].find("*)").map(|e| s + e) else {
            break;
        };
        from = e;
        let words: Vec<&str> = text[s..e].split_whitespace().collect();
        if let [name, declare, at] = words.as_slice() {
            let at = at.parse::<usize>().unwrap_or(body.start + s);
            let len = name.len();
            out.push(super::flags::Flag {
                name: format!("SFC{name}"),
                declare: *declare == "1",
                span: Span::new(file, at, at + len),
            });
        }
    }
    out
}

/// The CODESYS step action a vendor qualifier (`__ENTRY`, `__ACTIVE`, `__EXIT`) stands for.
fn vendor_kind(qualifier: &str) -> Option<StepAction> {
    match qualifier {
        "__ENTRY" => Some(StepAction::Entry),
        "__ACTIVE" => Some(StepAction::Active),
        "__EXIT" => Some(StepAction::Exit),
        _ => None,
    }
}

/// `ST` when the action body holds an ST statement (`:=` or `;`), else `IL` (instructions, one per line).
fn body_lang(src: &str, r: &Range<usize>) -> &'static str {
    let t = src.get(r.clone()).unwrap_or("");
    if t.contains(":=") || t.contains(';') {
        "ST"
    } else {
        "IL"
    }
}

/// `f` of each step's associations, in the chart's order, given (step, association) indices.
fn per_association<'s, T>(
    steps: &'s [sfc::TextStep],
    mut f: impl FnMut((usize, usize), &'s sfc::TextAssociation) -> T,
) -> Vec<Vec<T>> {
    steps
        .iter()
        .enumerate()
        .map(|(k, s)| {
            s.associations
                .iter()
                .enumerate()
                .map(|(j, a)| f((k, j), a))
                .collect()
        })
        .collect()
}
