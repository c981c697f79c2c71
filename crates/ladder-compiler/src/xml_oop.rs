//! CODESYS's object orientation in a PLCopen XML export ("Export PLCopenXML", CODESYS V3): every
//! INTERFACE of the project as `<Interface name="I">` in the vendor data block
//! `addData/data[.../plcopenxml/interface]` (its `<Methods><Method name="M"><interface>`, its
//! `<Properties><Property name="P"><interface><returnType>` with `<GetAccessor>` / `<SetAccessor>`,
//! and the interfaces it extends in `<Inheritance><Extends>`), and a function block's `EXTENDS` /
//! `IMPLEMENTS` in the vendor data of its `<interface>`,
//! `addData/data[.../pouinheritance]/Inheritance` with `<Extends>` and `<Implements>` elements.
//!
//! Input: the project's elements and the POU headers read by [`crate::project`]. Output: the same
//! pending ST bodies an `.st` or TwinCAT file gives (`il_frontend::st::file::PendingBody`): an
//! interface is a body with no text and an `Oop::Interface`, a POU of an ST body is its body text
//! (spans in the XML file), its methods and properties, its ST actions and, for a block that
//! inherits, an `Oop::Block`. The ST front end then flattens and checks them
//! (`il_frontend::st::inherit`, `interface_vars`) as it does for text: one OOP machinery.
//! Invariants: only a file with OOP vendor data changes its path (its ST POUs go to the ST front
//! end, so that calls through interface variables dispatch); a POU whose body or an action is not
//! ST stays with the XML lowering (and a block of that kind that inherits is one E0303).

use crate::context::Ctx;
use crate::xml::Element;
use il_frontend::ast::{Ident, Pou, PouKind};
use il_frontend::st::file::{PendingBody, PendingMethod};
use il_frontend::st::inherit::{BlockOop, InterfaceOop, Oop};

/// Whether a vendor data block's name is CODESYS's interface block.
fn is_interface_block(name: &str) -> bool {
    name.ends_with("/plcopenxml/interface")
}

/// The `<Interface>` elements of the project's vendor data and of the application resources'
/// (`resources`: a whole-application export keeps its objects there).
pub(crate) fn interface_elements<'b, 'a>(
    root: &'b Element<'a>,
    resources: &[&'b Element<'a>],
) -> Vec<&'b Element<'a>> {
    std::iter::once(root)
        .chain(resources.iter().copied())
        .flat_map(|e| e.children_named("addData"))
        .flat_map(|a| a.children_named("data"))
        .filter(|d| d.attr("name").is_some_and(is_interface_block))
        .flat_map(|d| d.children_named("Interface"))
        .collect()
}

/// The `<Inheritance>` element of a POU (`interface/addData/data[.../pouinheritance]`), when it
/// names a base or an interface.
pub(crate) fn inheritance_element<'b, 'a>(p: &'b Element<'a>) -> Option<&'b Element<'a>> {
    p.child("interface")
        .into_iter()
        .flat_map(|i| i.children_named("addData"))
        .flat_map(|a| a.children_named("data"))
        .filter(|d| {
            d.attr("name")
                .is_some_and(|n| n.ends_with("/pouinheritance"))
        })
        .flat_map(|d| d.children_named("Inheritance"))
        .find(|inh| {
            inh.children
                .iter()
                .any(|c| matches!(c.name(), "Extends" | "Implements"))
        })
}

/// The names of the `<name>` children of `inh` (`Extends`, `Implements`), each where it is
/// written; one element may list several, separated by commas.
fn names(ctx: &Ctx, inh: &Element, name: &str) -> Vec<Ident> {
    let mut out = Vec::new();
    for e in inh.children_named(name) {
        let Some(seg) = e.segments().first() else {
            continue;
        };
        let text = e.text_ref();
        // the offsets of the text's pieces are the file's when it is one plain piece
        let plain = e.segments().len() == 1 && seg.text == text.as_ref();
        let mut at = 0;
        for part in text.split(',') {
            let lead = part.len() - part.trim_start().len();
            let word = part.trim();
            if !word.is_empty() {
                let span = if plain {
                    let s = seg.start + at + lead;
                    ctx.span(s, s + word.len())
                } else {
                    ctx.text_span(e)
                };
                out.push(Ident::new(word, span));
            }
            at += part.len() + 1;
        }
    }
    out
}

/// The `EXTENDS` and `IMPLEMENTS` of a function block, from its `<Inheritance>`.
pub(crate) fn block_oop(ctx: &Ctx, inh: &Element) -> BlockOop {
    BlockOop {
        extends: names(ctx, inh, "Extends"),
        implements: names(ctx, inh, "Implements"),
        ..BlockOop::default()
    }
}

/// The `EXTENDS EXTENDS A IMPLEMENTS B` text of an `<Inheritance>`, for a diagnostic.
pub(crate) fn clause(inh: &Element) -> String {
    inh.children
        .iter()
        .filter(|c| matches!(c.name(), "Extends" | "Implements"))
        .map(|c| format!("{} {}", c.name().to_ascii_uppercase(), c.text_ref().trim()))
        .collect::<Vec<_>>()
        .join(" ")
}

/// An `<Interface>` as the pending body of an `INTERFACE` (no text; its methods' and properties'
/// signatures); `None` (and one E3013) for one without a name that is an identifier.
pub(crate) fn interface(ctx: &mut Ctx, el: &Element) -> Option<PendingBody> {
    let Some(name) = el
        .attr("name")
        .map(str::trim)
        .filter(|n| crate::values::is_ident(n))
    else {
        ctx.error(
            diagnostics::code::E3013,
            ctx.tag(el),
            "interface without a valid `name`",
        );
        return None;
    };
    let name = Ident::new(name, ctx.attr_span(el, "name"));
    let mut methods: Vec<PendingMethod> = Vec::new();
    // `<Methods><Method>` and `<Properties><Property>` (CODESYS), or the members directly under
    // the interface, or in its own vendor data blocks (`.../method`, `.../property`) as a
    // block's are
    let members = |container: &'static str, item: &'static str| {
        el.children_named(container)
            .chain(
                el.children_named("addData")
                    .flat_map(|a| a.children_named("data")),
            )
            .flat_map(move |c| c.children_named(item))
            .chain(el.children_named(item))
            .collect::<Vec<_>>()
    };
    for m in members("Methods", "Method") {
        let Some(mname) = m
            .attr("name")
            .map(str::trim)
            .filter(|n| crate::values::is_ident(n))
        else {
            continue;
        };
        let mut ret = None;
        let mut blocks = Vec::new();
        if let Some(iface) = m.child("interface") {
            crate::project::read_interface(ctx, iface, &mut ret, &mut blocks);
        }
        let ident = Ident::new(mname, ctx.attr_span(m, "name"));
        methods.push(PendingMethod {
            ret: ret.map(|ty| il_frontend::ast::VarDecl::new(ident.clone(), ty, ident.span)),
            name: ident,
            blocks,
            text: String::new(),
            base: m.tag_end(),
            inst: Vec::new(),
            once: Vec::new(),
            local_inits: Vec::new(),
            overloaded: false,
            access: None,
        });
    }
    for p in members("Properties", "Property") {
        let Some(pname) = p
            .attr("name")
            .map(str::trim)
            .filter(|n| crate::values::is_ident(n))
        else {
            continue;
        };
        let mut ty = None;
        if let Some(iface) = p.child("interface") {
            crate::project::read_interface(ctx, iface, &mut ty, &mut Vec::new());
        }
        let Some(ty) = ty else { continue };
        let has_get = p.child("GetAccessor").is_some();
        let has_set = p.child("SetAccessor").is_some();
        // (no accessor written: the property is read and written)
        let both = !has_get && !has_set;
        let accessor = |on: bool| (on || both).then(|| (Vec::new(), String::new(), p.tag_end()));
        let ident = Ident::new(pname, ctx.attr_span(p, "name"));
        methods.extend(il_frontend::st::property::accessor_methods(
            &ident,
            &ty,
            accessor(has_get),
            accessor(has_set),
        ));
    }
    let extends = el
        .children_named("Inheritance")
        .flat_map(|inh| names(ctx, inh, "Extends"))
        .collect();
    let mut pb = PendingBody::empty(ctx.file, name.span.start as usize);
    pb.base = el.tag_end();
    pb.oop = Some(Box::new(Oop::Interface(InterfaceOop {
        name,
        extends,
        methods,
    })));
    Some(pb)
}

/// The pending ST body of the POU `p` (header `pou`), with its methods `methods` and its
/// inheritance `oop`, when its body and all its actions are ST; `None` otherwise.
pub(crate) fn pending_body(
    ctx: &Ctx,
    p: &Element,
    pou: &Pou,
    methods: Vec<PendingMethod>,
    oop: Option<BlockOop>,
) -> Option<PendingBody> {
    let st = |holder: &Element| -> Option<(String, usize)> {
        let lang = match holder.child("body") {
            None => return Some((String::new(), holder.tag_end())),
            // a CODESYS CFC chart beside its empty `<ST>` is read as FBD (`codesys_cfc`)
            Some(b) if crate::codesys_cfc::body_chart(b).is_some() => return None,
            Some(b) => b
                .children
                .iter()
                .find(|c| !matches!(c.name(), "documentation" | "addData")),
        };
        let Some(lang) = lang else {
            return Some((String::new(), holder.tag_end()));
        };
        if lang.name() != "ST" {
            return None;
        }
        let mut t = crate::il_body::embedded_text(lang);
        crate::st_body::join_split_operators(&mut t.text, t.base, ctx.xml);
        Some((t.text, t.base))
    };
    let (mut text, base) = st(p)?;
    // the declaration blocks the body begins with are the POU's (`st_body::body_declarations`)
    let n = crate::st_body::leading_var_blocks(&text);
    if n > 0 {
        let blank: String = text[..n]
            .chars()
            .map(|c| if matches!(c, '\n' | '\r') { c } else { ' ' })
            .collect();
        text.replace_range(..n, &blank);
    }
    let mut actions = Vec::new();
    for a in p
        .children_named("actions")
        .flat_map(|a| a.children_named("action"))
    {
        let name = a.attr("name").map(str::trim).unwrap_or("");
        if !crate::values::is_ident(name) {
            return None;
        }
        let (t, b) = st(a)?;
        actions.push((Ident::new(name, ctx.attr_span(a, "name")), t, b));
    }
    let mut pb = PendingBody::empty(ctx.file, pou.name.span.start as usize);
    pb.base = base;
    pb.text = text;
    pb.actions = actions;
    pb.methods = methods;
    pb.oop = oop
        .filter(|_| pou.kind == PouKind::FunctionBlock)
        .map(|b| Box::new(Oop::Block(b)));
    Some(pb)
}
