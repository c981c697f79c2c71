//! A POU's `<body>`: dispatches on the language. LD and FBD are lowered through [`crate::graph`] and
//! [`crate::lower`]; SFC through [`crate::sfc`]; IL is parsed in place by the IL front end; ST is parsed
//! and lowered to IL by [`crate::st_body`]; an ST POU that no program instance reaches only gets warning
//! W3004.
//!
//! Output: the body's statements and, when the lowering needed hidden variables (edge detectors,
//! temporaries, chart state), one extra `VAR` (LD/FBD/SFC) or `VAR_TEMP` (ST) block holding them;
//! `None` for an unused ST POU, which is left out.
//!
//! Input: the POU's `<body>` element, its declarations (already read into the [`Pou`]) and the project
//! [`Index`]. Invariants: a missing `<body>` is an empty body; a body language ladderc does not read is
//! reported (E3012) and gives no statements, so the rest of the project still compiles; every
//! statement's span points into the XML element it came from.

use crate::context::Ctx;
use crate::graph;
use crate::lower::BodyLowering;
use crate::project::Index;
use crate::xml::Element;
use diagnostics::{code, Diagnostic, XmlContext};
use il_frontend::ast::{Ident, IlStmt, Pou, VarBlock};

/// The body of one POU in the IL syntax tree, with the hidden variables its lowering needs.
pub fn lower_pou_body(
    ctx: &mut Ctx,
    index: &Index,
    pou_el: &Element,
    pou: &Pou,
    used: bool,
) -> Option<(Vec<IlStmt>, Option<VarBlock>)> {
    let Some(body) = pou_el.child("body") else {
        return Some((Vec::new(), None));
    };
    let Some(lang) = body
        .children
        .iter()
        .find(|c| !matches!(c.name, "documentation" | "addData"))
    else {
        return Some((Vec::new(), None));
    };
    let span = ctx.tag(lang);
    let name = &pou.name.name;
    let xml_ctx = XmlContext {
        pou: Some(name.clone()),
        ..Default::default()
    };
    // CODESYS exports a program's or FB's actions (called from its body as `Act();`) in the POU's
    // standard `<actions>`: an ST body inlines its ST actions where it calls them (`st_actions`);
    // the others are compiled only for SFC bodies
    let mut st_actions: Vec<(Ident, &Element)> = Vec::new();
    let mut other_actions: Vec<&Element> = Vec::new();
    if lang.name != "SFC" {
        for a in pou_el
            .child("actions")
            .into_iter()
            .flat_map(|a| a.children_named("action"))
        {
            let st = a
                .child("body")
                .and_then(|b| b.child("ST"))
                .filter(|_| lang.name == "ST");
            match (st, a.attr("name").map(str::trim)) {
                (Some(st), Some(n)) if !n.is_empty() => {
                    st_actions.push((Ident::new(n, ctx.attr_span(a, "name")), st))
                }
                _ => other_actions.push(a),
            }
        }
        if let Some(first) = other_actions.first() {
            let count = other_actions.len();
            let action = first.attr("name").unwrap_or("?").to_string();
            ctx.report(
                Diagnostic::warning(
                    code::W3401,
                    format!(
                        "POU `{name}` has {count} action{} (`{action}` ...) that ladderc does not compile here",
                        if count == 1 { "" } else { "s" }
                    ),
                )
                .at(ctx.tag(first))
                .with_primary_label("action of a program or function block")
                .with_hint("actions are compiled as the actions of an SFC chart, and as ST actions of an ST body (called as `Act();` from the body, or as `inst.Act();` / `CAL inst.Act` from other POUs); a call of this one is an unknown function (E1019)")
                .with_xml(xml_ctx.clone()),
            );
        }
    }
    match lang.name {
        "LD" | "FBD" => {
            let g = graph::read(ctx, lang, name);
            let mut low = BodyLowering::new(index, pou, span);
            let stmts = low.lower(ctx, &g);
            let hidden = low.hidden_vars();
            let block = (!hidden.is_empty()).then_some(VarBlock::locals(hidden, span));
            Some((stmts, block))
        }
        "IL" => Some((crate::il_body::parse(ctx, lang, name), None)),
        "ST" if !used => {
            ctx.report(
                Diagnostic::warning(
                    code::W3004,
                    format!("POU `{name}` (ST) is not used by any program instance and is skipped"),
                )
                .at(span)
                .with_xml(xml_ctx),
            );
            None
        }
        "ST" => {
            let (stmts, temps) = crate::st_body::lower(ctx, index, lang, pou, &st_actions);
            Some((stmts, temps))
        }
        "SFC" => {
            let (stmts, hidden) = crate::sfc::lower(ctx, index, pou_el, pou, lang);
            let block = (!hidden.is_empty()).then_some(VarBlock::locals(hidden, span));
            Some((stmts, block))
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
            Some((Vec::new(), None))
        }
    }
}
