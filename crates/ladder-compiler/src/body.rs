//! A POU's `<body>`: dispatches on the language. LD and FBD are lowered through [`crate::graph`] and
//! [`crate::lower`], and so is a CODESYS CFC chart (read by `crate::codesys_cfc`); SFC through [`crate::sfc`]; IL is parsed in place by the IL front end; ST is parsed
//! and lowered to IL by [`crate::st_body`]. Every POU is lowered and checked, whether a program
//! instance reaches it or not, as in ST text (before round 29 of issue #13 an ST POU that no program
//! instance reached was skipped unchecked with W3004, no longer raised).
//!
//! Output: the body's statements and, when the lowering needed hidden variables (edge detectors,
//! temporaries, chart state), one extra `VAR` (LD/FBD/SFC) or `VAR_TEMP` (ST) block holding them.
//!
//! Input: the POU's `<body>` element, its declarations (already read into the [`Pou`]) and the project
//! [`Index`]. Invariants: a missing `<body>` is an empty body; a body language ladderc does not read is
//! reported (E3012) and gives no statements, so the rest of the project still compiles; every
//! statement's span points into the XML element it came from.

use crate::context::Ctx;
use crate::graph;
use crate::lower::BodyLowering;
use crate::project::Index;
use crate::sfc::il::Renames;
use crate::xml::Element;
use diagnostics::{code, Diagnostic, Diagnostics, XmlContext};
use il_frontend::ast::{Action, Ident, IlStmt, Pou, VarBlock, VarDecl};
use std::collections::{HashMap, HashSet};

/// The body of one POU in the IL syntax tree, with the hidden variables its lowering needs.
pub fn lower_pou_body(
    ctx: &mut Ctx,
    index: &Index,
    pou_el: &Element,
    pou: &Pou,
) -> (Vec<IlStmt>, Vec<VarBlock>) {
    let Some(body) = pou_el.child("body") else {
        return (Vec::new(), Vec::new());
    };
    // a CODESYS CFC chart (vendor data beside an empty `<ST>`) is the body (`codesys_cfc`)
    let Some(lang) = crate::codesys_cfc::body_chart(body).or_else(|| {
        body.children
            .iter()
            .find(|c| !matches!(c.name(), "documentation" | "addData"))
    }) else {
        return (Vec::new(), Vec::new());
    };
    let span = ctx.tag(lang);
    let name = &pou.name.name;
    let xml_ctx = XmlContext {
        pou: Some(name.clone()),
        ..Default::default()
    };
    // CODESYS exports a program's or FB's actions (called from its body as `Act();`) in the POU's
    // standard `<actions>`: an ST body lowers its ST actions where it calls them (`st_actions`);
    // actions in IL, LD, FBD or SFC (and the ST actions of a body in another language) are lowered
    // to IL here, copied where the body calls them (`CAL Act` in IL, an action box in LD/FBD) and
    // linked for calls through an instance. The actions of an SFC body are its chart's
    // (`crate::sfc`).
    let mut st_actions: Vec<(Ident, &Element)> = Vec::new();
    let mut acts = lower_actions(ctx, index, pou_el, pou, lang.name(), &mut st_actions);
    let is_var = var_test(pou, index);
    let mut next = 0;
    let mut inline = |ctx: &mut Ctx, mut stmts: Vec<IlStmt>| {
        if acts.il.is_empty() {
            return stmts;
        }
        // `CAL Prog.Act` inside `Prog`: its own action (CODESYS)
        il_frontend::actions::drop_own_name(&mut stmts, pou, &acts.il, &is_var);
        il_frontend::actions::inline_calls(stmts, &acts.il, &is_var, "__A", &mut next, ctx.diags)
    };
    match lang.name() {
        "LD" | "FBD" | "CFC" => {
            let g = if lang.name() == "CFC" {
                crate::codesys_cfc::read(ctx, lang, name)
            } else {
                graph::read(ctx, lang, name)
            };
            let mut low = BodyLowering::new(index, pou, span).calling_actions();
            // a box named after an action is `CAL Act` (lower_block.rs): the action runs there
            let stmts = low.lower(ctx, &g);
            let stmts = inline(ctx, stmts);
            let hidden = low.hidden_vars();
            let mut blocks = acts.blocks;
            if !hidden.is_empty() {
                blocks.push(VarBlock::locals(hidden, span));
            }
            (stmts, blocks)
        }
        "IL" => {
            let stmts = crate::il_body::parse(ctx, lang, pou);
            (inline(ctx, stmts), acts.blocks)
        }
        "ST" => {
            let il: Vec<(Ident, Vec<IlStmt>)> = acts
                .names
                .iter()
                .map(|n| (n.clone(), acts.il[&n.key()].clone()))
                .collect();
            let (stmts, temps) = crate::st_body::lower(ctx, index, lang, pou, &st_actions, &il);
            for d in std::mem::take(&mut acts.pending) {
                let known = ctx
                    .diags
                    .iter()
                    .any(|e| e.code == d.code && e.span == d.span && e.message == d.message);
                if !known {
                    ctx.report(d);
                }
            }
            let mut blocks = acts.blocks;
            blocks.extend(temps);
            (stmts, blocks)
        }
        "SFC" => {
            let (stmts, mut hidden) = crate::sfc::lower(ctx, index, pou_el, pou, lang);
            // the chart calls the actions whose body is a chart of their own (`CAL Act`)
            let stmts = inline(ctx, stmts);
            let mut blocks = acts.blocks;
            // a flag variable declared implicitly (`SFCReset`) is one variable of the POU, also
            // when a chart of its actions declared it
            hidden.retain(|v| {
                !blocks
                    .iter()
                    .flat_map(|b| b.vars.iter())
                    .any(|d| d.name.key() == v.name.key())
            });
            if !hidden.is_empty() {
                blocks.push(VarBlock::locals(hidden, span));
            }
            (stmts, blocks)
        }
        other => {
            ctx.report(
                Diagnostic::error(
                    code::E3012,
                    format!("body language <{other}> of POU `{name}` is not supported"),
                )
                .at(span)
                .with_xml(xml_ctx),
            );
            (Vec::new(), Vec::new())
        }
    }
}

/// The actions of a POU lowered to IL (see [`lower_actions`]).
#[derive(Default)]
struct LoweredActions {
    /// Upper-case name -> statements, with their own calls of actions already copied in.
    il: HashMap<String, Vec<IlStmt>>,
    /// The names of `il`, in document order.
    names: Vec<Ident>,
    /// What they need declared in the POU: the hidden variables of LD/FBD actions (edge detectors,
    /// temporaries; one set per action, shared by every place it runs, like the POU's own
    /// variables) and the temporaries of ST actions of a body in another language.
    blocks: Vec<VarBlock>,
    /// The diagnostics of the ST actions of an ST body, lowered once more for the other actions
    /// that call them: reported after the body, unless the body's own lowering reported them.
    pending: Vec<diagnostics::Diagnostic>,
}

/// Reads the `<actions>` of a POU whose body is `body_lang` (not SFC): ST actions of an ST body go to
/// `st_actions` (the ST lowering inlines them); every other action with a name and an IL, LD, FBD,
/// SFC or ST body is lowered to IL, and also handed to [`il_frontend::actions::link`] (through
/// `ctx.actions`) for calls through an instance. An SFC body is one scan of its chart
/// ([`crate::sfc::lower_chart`]), whose hidden variables (steps, step times, action control) are
/// the POU's, renamed per action ([`crate::sfc::names::in_action`]); its SFC flags are read from
/// the action's vendor data, else the POU's ([`crate::sfc::flags`]). What is left (no name, a body
/// in no known language) is W3401.
fn lower_actions<'e, 'a>(
    ctx: &mut Ctx,
    index: &Index,
    pou_el: &'e Element<'a>,
    pou: &Pou,
    body_lang: &str,
    st_actions: &mut Vec<(Ident, &'e Element<'a>)>,
) -> LoweredActions {
    let name = &pou.name.name;
    let xml_ctx = XmlContext {
        pou: Some(name.clone()),
        ..Default::default()
    };
    let mut raw: Vec<(Ident, Vec<IlStmt>)> = Vec::new();
    let mut hidden: Vec<VarDecl> = Vec::new();
    let mut st_other: Vec<(Ident, &Element)> = Vec::new();
    // the ST actions of an ST body, for the other actions that call them
    let mut st_inline: Vec<(Ident, &Element)> = Vec::new();
    let mut unsupported: Vec<(&Element, String)> = Vec::new();
    for a in pou_el
        .child("actions")
        .into_iter()
        .flat_map(|a| a.children_named("action"))
    {
        let Some(n) = a
            .attr("name")
            .map(str::trim)
            .filter(|n| !n.is_empty() && crate::values::is_ident(n))
        else {
            if body_lang != "SFC" {
                unsupported.push((a, "it has no name that is an identifier".into()));
            }
            continue;
        };
        let id = Ident::new(n, ctx.attr_span(a, "name"));
        let Some(b) = a.child("body").and_then(|b| {
            crate::codesys_cfc::body_chart(b).or_else(|| {
                b.children
                    .iter()
                    .find(|c| !matches!(c.name(), "documentation" | "addData"))
            })
        }) else {
            if body_lang != "SFC" {
                raw.push((id, Vec::new()));
            }
            continue;
        };
        match b.name() {
            // the other actions of an SFC body are its chart's (`crate::sfc`)
            _ if body_lang == "SFC" && b.name() != "SFC" => {}
            "ST" if body_lang == "ST" => {
                st_actions.push((id.clone(), b));
                st_inline.push((id, b));
            }
            "ST" => st_other.push((id, b)),
            "IL" => raw.push((id, crate::il_body::parse(ctx, b, pou))),
            "LD" | "FBD" | "CFC" => {
                let g = if b.name() == "CFC" {
                    crate::codesys_cfc::read(ctx, b, name)
                } else {
                    graph::read(ctx, b, name)
                };
                let mut low = BodyLowering::new(index, pou, ctx.tag(b)).calling_actions();
                let mut stmts = low.lower(ctx, &g);
                let mut renames = Renames::default();
                for mut v in low.hidden_vars() {
                    let new = format!(
                        "__A_{}_{}",
                        n.to_ascii_uppercase(),
                        v.name.name.trim_start_matches('_')
                    );
                    renames.bases.insert(v.name.key(), new.clone());
                    v.name.name = new;
                    hidden.push(v);
                }
                renames.apply(&mut stmts);
                raw.push((id, stmts));
            }
            "SFC" if n.contains("__") => unsupported.push((
                a,
                "the name of an action whose body is SFC holds no two underscores in a row (they separate the action's name in its chart's hidden variables)".into(),
            )),
            "SFC" => {
                // one scan of the chart per call; its state (steps, timers, action control) is
                // the POU's, namespaced by the action so two charts never share a name
                let mut chart = crate::sfc::chart::read(ctx, b, name);
                // its SFC flags: the action's own settings, else the POU's
                chart.flags = crate::sfc::flags::read(ctx, a);
                if chart.flags.is_empty() {
                    chart.flags = crate::sfc::flags::read(ctx, pou_el);
                }
                let (mut stmts, vars) = crate::sfc::lower_chart(ctx, index, pou_el, pou, b, chart);
                let mut renames = Renames::default();
                for mut v in vars {
                    if !v.name.name.starts_with("__") {
                        // a flag CODESYS declares implicitly (`SFCReset`): the POU's one variable
                        if !hidden.iter().any(|h| h.name.key() == v.name.key()) {
                            hidden.push(v);
                        }
                        continue;
                    }
                    let new = crate::sfc::names::in_action(n, &v.name.name);
                    renames.bases.insert(v.name.key(), new.clone());
                    v.name.name = new;
                    hidden.push(v);
                }
                renames.apply(&mut stmts);
                raw.push((id, stmts));
            }
            other => unsupported.push((a, format!("its body is <{other}>"))),
        }
    }
    let mut out = LoweredActions::default();
    if !st_other.is_empty() {
        let (lowered, blocks, local) =
            lower_st_actions(ctx, index, pou, &st_other, &raw, "_ST_", ctx.tag(pou_el));
        raw.extend(lowered);
        out.blocks.extend(blocks);
        for d in local {
            ctx.report_in_pou(d, name);
        }
    }
    // An ST body inlines its ST actions itself; the actions in other languages that call one
    // (`Reset();` in an EXECUTE box of an FBD action, `CAL Reset` in IL) get a copy in IL.
    let mut inline_only: Vec<(Ident, Vec<IlStmt>)> = Vec::new();
    if !st_inline.is_empty() && !raw.is_empty() {
        let (lowered, blocks, local) =
            lower_st_actions(ctx, index, pou, &st_inline, &raw, "_STA_", ctx.tag(pou_el));
        inline_only = lowered;
        out.blocks.extend(blocks);
        out.pending = local
            .into_iter()
            .map(|d| {
                if d.xml.is_none() {
                    d.with_xml(xml_ctx.clone())
                } else {
                    d
                }
            })
            .collect();
    }
    if !hidden.is_empty() {
        out.blocks.push(VarBlock::locals(hidden, ctx.tag(pou_el)));
    }
    if let Some((first, why)) = unsupported.first() {
        let count = unsupported.len();
        let action = first.attr("name").unwrap_or("?").to_string();
        ctx.report(
            Diagnostic::warning(
                code::W3401,
                format!(
                    "POU `{name}` has {count} action{} (`{action}` ...) that ladderc does not compile: {why}",
                    if count == 1 { "" } else { "s" }
                ),
            )
            .at(ctx.tag(first))
            .with_primary_label("action of a program or function block")
            .with_hint("actions with a name and an IL, ST, LD, FBD or SFC body are compiled (called as `Act();` / `CAL Act` / a box `Act` from the POU's body, or as `inst.Act();` / `CAL inst.Act` from other POUs); a call of this one is an unknown function (E1019)")
            .with_xml(xml_ctx.clone()),
        );
    }
    if raw.is_empty() {
        return out;
    }
    let is_var = var_test(pou, index);
    let raw_map: HashMap<String, Vec<IlStmt>> = inline_only
        .iter()
        .chain(raw.iter())
        .map(|(n, b)| (n.key(), b.clone()))
        .collect();
    let mut next = 0;
    for (n, mut body) in raw {
        il_frontend::actions::drop_own_name(&mut body, pou, &raw_map, &is_var);
        let body = il_frontend::actions::inline_calls(
            body, &raw_map, &is_var, "__P", &mut next, ctx.diags,
        );
        let span = n.span;
        ctx.actions.push(Action {
            pou: pou.name.clone(),
            name: n.clone(),
            body: il_frontend::actions::instantiate(
                &body,
                &format!("__AL_{}_", n.name.to_ascii_uppercase()),
                span,
            ),
            temps: None,
            method_inputs: None,
            method_outputs: Vec::new(),
            method_defaults: Vec::new(),
            diagnostics: Vec::new(),
            access: None,
        });
        out.il.insert(n.key(), body);
        out.names.push(n);
    }
    out
}

/// What [`lower_st_actions`] gives: the statements per action, the temporaries' block, the
/// diagnostics.
type LoweredSt = (Vec<(Ident, Vec<IlStmt>)>, Vec<VarBlock>, Diagnostics);

/// ST actions lowered to IL on their own (`prefix` names their labels and temporaries): the
/// statements per action, the temporaries' block, and the diagnostics. They call each other and
/// the actions of `il` (already IL) by name.
fn lower_st_actions(
    ctx: &mut Ctx,
    index: &Index,
    pou: &Pou,
    actions: &[(Ident, &Element)],
    il: &[(Ident, Vec<IlStmt>)],
    prefix: &'static str,
    span: il_frontend::Span,
) -> LoweredSt {
    let decls = crate::st_body::declarations(index);
    let mut local = Diagnostics::new();
    let parsed: Vec<(Ident, Vec<il_frontend::st::ast::Stmt>)> = actions
        .iter()
        .map(|(n, el)| {
            let mut t = crate::il_body::embedded_text(el);
            crate::st_body::join_split_operators(&mut t.text, t.base, ctx.xml);
            let stmts = il_frontend::st::parse_statements(ctx.file, &t.text, t.base, &mut local);
            (n.clone(), stmts)
        })
        .collect();
    let mut low = il_frontend::st::PouLowering::new(decls, pou).with_prefix(prefix);
    low.set_actions(parsed.clone());
    low.set_il_actions(il.to_vec());
    let lowered = parsed
        .iter()
        .map(|(n, stmts)| (n.clone(), low.statements(stmts, &mut local)))
        .collect();
    (lowered, low.finish(span).into_iter().collect(), local)
}

/// Whether a name is one of `pou`'s variables or a global of the project (case-insensitive).
///
/// The set of the POU's names is built on the first question: only bodies that call actions ask
/// (a 10,000-rung program has 32,500 variables and no action).
fn var_test<'p>(pou: &'p Pou, index: &'p Index) -> impl Fn(&str) -> bool + 'p {
    let pou_vars: std::cell::OnceCell<HashSet<String>> = std::cell::OnceCell::new();
    move |n: &str| {
        let pou_vars = pou_vars.get_or_init(|| {
            pou.var_blocks
                .iter()
                .flat_map(|b| b.vars.iter())
                .map(|v| v.name.key())
                .collect()
        });
        let k = n.to_ascii_uppercase();
        pou_vars.contains(&k) || index.globals.contains_key(&k)
    }
}
