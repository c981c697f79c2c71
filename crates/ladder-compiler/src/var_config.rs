//! A configuration's `<configVars>` (TC6 XML 2.01, IEC 61131-3 3rd edition 6.5.6 VAR_CONFIG): the
//! entries that give one instance's `%I*` / `%Q*` / `%M*` placeholder its address, or a variable of
//! one instance its initial value.
//!
//! Input: a `<configVars>` element and its configuration's name. Output: one
//! [`il_frontend::st::file::ConfigEntry`] per readable `<configVariable>` in [`Ctx::var_config`],
//! applied with the `.st` files' entries once every input file is read (a copy of the program and of
//! each function block along the path per configured instance, see
//! `il_frontend::st::file::apply_var_config`).
//! Invariants: `instancePathAndName` is `[configuration.]resource.instance.variable` or
//! `instance.variable` (dots between IEC identifiers; the configuration's own name in front is
//! dropped); an entry that cannot be read is one E0306 located at its attribute, and nothing of it is
//! applied.

use crate::context::Ctx;
use crate::decls;
use crate::values;
use crate::xml::Element;
use diagnostics::{code, Diagnostic, Span};
use il_frontend::ast::Ident;
use il_frontend::st::file::ConfigEntry;

/// Reads the `<configVariable>` entries of `list`, a `<configVars>` of configuration `config`.
pub fn read(ctx: &mut Ctx, list: &Element, config: &str) {
    for v in list.children_named("configVariable") {
        if let Some(e) = entry(ctx, v, config) {
            ctx.var_config.push(e);
        }
    }
}

fn bad(ctx: &mut Ctx, span: Span, why: String) {
    ctx.diags.push(
        Diagnostic::error(
            code::E0306,
            format!("this VAR_CONFIG entry cannot be read: {why}"),
        )
        .at(span)
        .with_hint(
            "write instancePathAndName=\"resource.instance.variable\" with address=\"%QX0.1\" \
             (for a variable declared at %Q*), or an <initialValue>",
        ),
    );
}

fn entry(ctx: &mut Ctx, v: &Element, config: &str) -> Option<ConfigEntry> {
    let tag = ctx.tag(v);
    let Some((start, end)) = v.attr_range("instancePathAndName") else {
        bad(ctx, tag, "no `instancePathAndName`".to_string());
        return None;
    };
    let text = &ctx.xml[start..end];
    // each part with its span; surrounding blanks are not part of a name
    let mut path = Vec::new();
    let mut at = start;
    for part in text.split('.') {
        let lead = part.len() - part.trim_start().len();
        let name = part.trim();
        let span = ctx.span(at + lead, at + lead + name.len());
        if !values::is_ident(name) {
            bad(
                ctx,
                ctx.span(start, end),
                format!(
                    "`{}` is not an instance path (identifiers joined by dots)",
                    text.trim()
                ),
            );
            return None;
        }
        path.push(Ident::new(name, span));
        at += part.len() + 1;
    }
    if path.len() > 2 && path[0].name.eq_ignore_ascii_case(config) {
        path.remove(0);
    }
    if path.len() < 2 {
        bad(
            ctx,
            ctx.span(start, end),
            format!("`{}` names no variable of a program instance", text.trim()),
        );
        return None;
    }
    let location = match v.attr("address").map(str::trim).filter(|a| !a.is_empty()) {
        None => None,
        Some(a) => {
            let span = ctx.attr_span(v, "address");
            match values::address(a, span) {
                Some(d) if !d.path.is_empty() => Some(d),
                _ => {
                    bad(
                        ctx,
                        span,
                        format!("`{a}` is not a complete direct address (%IX0.0, %QW2, %MD4)"),
                    );
                    return None;
                }
            }
        }
    };
    let ty = v.child("type").and_then(|t| decls::type_ref(ctx, t));
    let init = v
        .child("initialValue")
        .and_then(|i| decls::initial_value(ctx, i, ty.as_ref()));
    if location.is_none() && init.is_none() {
        bad(
            ctx,
            tag,
            "neither an address nor an initial value".to_string(),
        );
        return None;
    }
    Some(ConfigEntry::new(path, location, init, ctx.span(start, end)))
}
