//! CODESYS's implicit SFC flags (`SFCInit`, `SFCReset`, `SFCPause` ...), enabled per chart in the
//! vendor data of a POU or of an action (`addData/data[.../sfcsettings]/SFCSettings/Flags`, one
//! element per flag with `Use` and `Declare` attributes).
//!
//! Input: the `<pou>` or `<action>` element (read by [`read`]), then the chart's POU. Output: the
//! operands of the two flags ladderc implements ([`Control`]), the flag variables it declares, and
//! one located W3402 per enabled flag it does not implement (once per flag element, however
//! many charts share the settings).
//! Invariants: a flag works only when its `Use` is `true` (CODESYS: a flag must be declared and
//! activated; a variable named `SFCInit` that is not activated is a plain variable); its variable is
//! the POU's own declaration when there is one (it must be BOOL, else E3403), else ladderc declares
//! it as CODESYS does when `Declare` is `true` (else E3403). The semantics (the chart's reset at the
//! start of the scan, and SFCInit's hold) are in [`super::lower_chart`].

use crate::context::Ctx;
use crate::xml::Element;
use diagnostics::{code, Diagnostic, Span, XmlContext};
use il_frontend::ast::{Operand, Pou, TypeRef};

/// One flag of the export's SFC settings with `Use="true"`.
#[derive(Debug, Clone)]
pub struct Flag {
    /// The variable's name (`SFCInit` for `<Init>`, `SFCErrorAnalyzation` as written).
    pub name: String,
    /// `Declare="true"`: CODESYS declares the variable implicitly.
    pub declare: bool,
    /// The flag's element (`<Init Use="true" .../>`).
    pub span: Span,
}

/// The enabled flags in the vendor data of `el` (a `<pou>` or an `<action>`), in document order.
pub fn read(ctx: &Ctx, el: &Element) -> Vec<Flag> {
    let mut out = Vec::new();
    for data in el
        .children_named("addData")
        .flat_map(|a| a.children_named("data"))
        .filter(|d| {
            d.attr("name")
                .is_some_and(|n| n.trim().to_ascii_lowercase().ends_with("/sfcsettings"))
        })
    {
        for f in data
            .children_named("SFCSettings")
            .flat_map(|s| s.children_named("Flags"))
            .flat_map(|f| f.children.iter())
        {
            let on = |a: &str| {
                f.attr(a)
                    .is_some_and(|v| v.trim().eq_ignore_ascii_case("true"))
            };
            if !on("Use") || !crate::values::is_ident(f.name()) {
                continue;
            }
            let name = if f
                .name()
                .get(..3)
                .is_some_and(|p| p.eq_ignore_ascii_case("SFC"))
            {
                f.name().to_string()
            } else {
                format!("SFC{}", f.name())
            };
            out.push(Flag {
                name,
                declare: on("Declare"),
                span: ctx.tag(f),
            });
        }
    }
    out
}

/// The operands of the implemented flags of one chart.
#[derive(Debug, Clone, Default)]
pub struct Control {
    /// `SFCInit`: while TRUE, the chart is reset and held in its initial step.
    pub init: Option<Operand>,
    /// `SFCReset`: while TRUE, the chart is reset and then processed from its initial step.
    pub reset: Option<Operand>,
}

/// The flags of `flags` on the chart of `pou`: the operands of SFCInit and SFCReset (declaring
/// their variables in `hidden` when CODESYS would declare them implicitly), and W3402 for each
/// other enabled flag (once per flag element, however many charts share the settings).
pub fn control(
    ctx: &mut Ctx,
    pou: &Pou,
    flags: &[Flag],
    hidden: &mut super::il::Hidden,
) -> Control {
    let pou_name = pou.name.name.clone();
    let xml = || XmlContext {
        pou: Some(pou_name.clone()),
        ..Default::default()
    };
    let mut out = Control::default();
    for f in flags {
        let key = f.name.to_ascii_uppercase();
        let implemented = matches!(key.as_str(), "SFCINIT" | "SFCRESET");
        if !implemented {
            let msg = format!(
                "SFC flag `{}` is enabled but ladderc does not implement it: the variable is a plain variable",
                f.name
            );
            once(
                ctx,
                Diagnostic::warning(code::W3402, msg)
                    .at(f.span)
                    .with_xml(xml())
                    .with_hint(format!(
                        "ladderc implements SFCInit and SFCReset; drive what `{}` would do from the program, or disable the flag in the SFC settings",
                        f.name
                    )),
            );
            continue;
        }
        let declared = pou
            .var_blocks
            .iter()
            .flat_map(|b| b.vars.iter())
            .find(|v| v.name.key() == key);
        let usable = match declared {
            Some(v) => match &v.ty {
                TypeRef::Named(n) if n.is("BOOL") => Some(v.name.name.clone()),
                _ => {
                    once(
                        ctx,
                        Diagnostic::error(
                            code::E3403,
                            format!(
                                "SFC flag `{}` is enabled, but the POU declares `{}` with a type other than BOOL",
                                f.name, v.name.name
                            ),
                        )
                        .at(v.name.span)
                        .with_xml(xml())
                        .with_hint(format!("declare `{} : BOOL`", v.name.name)),
                    );
                    None
                }
            },
            None if f.declare => {
                hidden.declare(&f.name, "BOOL", None, f.span);
                Some(f.name.clone())
            }
            None => {
                once(
                    ctx,
                    Diagnostic::error(
                        code::E3403,
                        format!(
                            "SFC flag `{}` is enabled (Use) but neither declared in POU `{pou_name}` nor declared implicitly (Declare is not true)",
                            f.name
                        ),
                    )
                    .at(f.span)
                    .with_xml(xml())
                    .with_hint(format!(
                        "declare `{} : BOOL` in the POU, or set Declare=\"true\"",
                        f.name
                    )),
                );
                None
            }
        };
        let Some(var) = usable else { continue };
        let op = super::il::var(&var, f.span);
        if key == "SFCINIT" {
            out.init.get_or_insert(op);
        } else {
            out.reset.get_or_insert(op);
        }
    }
    out
}

/// Reports `d` unless the same code is already reported at the same place (the chart of a POU's
/// body and the charts of its actions share the POU's settings).
fn once(ctx: &mut Ctx, d: Diagnostic) {
    if !ctx
        .diags
        .iter()
        .any(|e| e.code == d.code && e.span == d.span && e.message == d.message)
    {
        ctx.report(d);
    }
}
