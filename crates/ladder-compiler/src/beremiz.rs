//! Beremiz project folders: what the configuration-tree nodes ("confnodes") beside `plc.xml` add to the
//! program.
//!
//! A Beremiz project is a folder: `plc.xml` (PLCopen TC6 XML), `beremiz.xml`, and one sub-folder
//! `NAME@TYPE` per confnode (`c_code@c_ext`, `py_ext_0@py_ext`, `modbus_0@modbus`, ...), each with a
//! `baseconfnode.xml` (`<BaseParams Name=... IEC_Channel=...>`) and files of its own. Beremiz adds the
//! variables some confnodes declare to the configuration's globals (its `CTNGlobalInstances`): the
//! `<variables>` of a C extension's `cfile.xml` and of a Python file's `pyfile.xml`, and an MQTT
//! client's `MQTT_STATUS_<channel>` (INT).
//!
//! Input: the text of one confnode file (the caller reads the folder). Output: the declared globals as
//! [`VarDecl`]s whose spans point into that file, and the span of the first code section that holds
//! code (C or Python: it does not run in ladderc). Invariants: never panics on bad input; a variable
//! that cannot be read is one located E0320 and is left out, the others are still returned; a STRING
//! variable's initial value without quotes is the text itself, as Beremiz quotes it.

use crate::context::Ctx;
use crate::values;
use crate::xml::{self, Element};
use diagnostics::{code, Diagnostic, Diagnostics, FileId, Span};
use il_frontend::ast::{
    CompilationUnit, Ident, Initializer, LibraryElement, TypeRef, VarBlock, VarDecl, VarKind,
};

/// What one code file of a confnode (`cfile.xml` or `pyfile.xml`) holds.
#[derive(Debug, Default)]
pub struct CodeFile {
    /// Its `<variables>`, as configuration globals.
    pub globals: Vec<VarDecl>,
    /// The first section that holds code (`<globals>`, `<initFunction>`, ...), or a variable's
    /// `onchange` callback: the span and the section's name.
    pub code: Option<(Span, String)>,
}

/// The sections of a `cfile.xml` (C extension) and a `pyfile.xml` (Python file) that hold code.
const CODE_SECTIONS: [&str; 11] = [
    "includes",
    "globals",
    "initFunction",
    "cleanUpFunction",
    "retrieveFunction",
    "publishFunction",
    "init",
    "cleanup",
    "start",
    "stop",
    "python",
];

/// The confnode's `BaseParams`: its name and IEC channel (`baseconfnode.xml`). `None` when the file
/// is not well-formed or has no `BaseParams` root.
pub fn base_params(text: &str) -> Option<(String, Option<u32>)> {
    let arena = xml::Arena::new();
    let (root, _) = xml::parse(text, &arena);
    let root = root?;
    if root.name() != "BaseParams" {
        return None;
    }
    let name = root.attr("Name").unwrap_or_default().trim().to_string();
    let channel = root.attr("IEC_Channel").and_then(|c| c.trim().parse().ok());
    Some((name, channel))
}

/// The root element's name and its start tag's span (for a warning located at the confnode's own
/// file); `None` when the text is not well-formed XML.
pub fn root_tag(file: FileId, text: &str) -> Option<(String, Span)> {
    let arena = xml::Arena::new();
    let (root, err) = xml::parse(text, &arena);
    if err.is_some() {
        return None;
    }
    let root = root?;
    let end = root.tag_end().min(text.len());
    Some((
        root.name().to_string(),
        Span::new(file, root.tag_start().min(end), end),
    ))
}

/// Reads a `cfile.xml` or `pyfile.xml`: its variables (`<variable name= type= initial=>`) and whether
/// a section holds code. A file that is not well-formed, or a variable without a valid name or type,
/// is one E0320 at the place.
pub fn code_file(file: FileId, text: &str, diags: &mut Diagnostics) -> CodeFile {
    let arena = xml::Arena::new();
    let (root, err) = xml::parse(text, &arena);
    let mut ctx = Ctx::new(file, text, diags);
    if let Some(e) = err {
        let span = ctx.span(e.pos, e.pos);
        ctx.report(
            Diagnostic::error(
                code::E0320,
                format!(
                    "the confnode file is not well-formed XML: {}; its variables are not declared",
                    e.message
                ),
            )
            .at(span)
            .with_hint(
                "repair or remove the file (Beremiz rewrites it when the confnode is saved)",
            ),
        );
        return CodeFile::default();
    }
    let Some(root) = root else {
        return CodeFile::default();
    };
    let mut out = CodeFile::default();
    for list in root.children_named("variables") {
        for v in list.children_named("variable") {
            if let Some(d) = variable(&mut ctx, v) {
                out.globals.push(d);
            }
            if out.code.is_none() {
                if let Some(cb) = v.attr("onchange").filter(|c| !c.trim().is_empty()) {
                    out.code = Some((
                        ctx.attr_span(v, "onchange"),
                        format!("onchange=\"{}\"", cb.trim()),
                    ));
                }
            }
        }
    }
    if out.code.is_none() {
        for section in root.children.iter() {
            if !CODE_SECTIONS.contains(&section.name()) {
                continue;
            }
            let holds_code = !section.text_ref().trim().is_empty()
                || section.walk().any(|e| !e.text_ref().trim().is_empty());
            if holds_code {
                out.code = Some((ctx.tag(section), format!("<{}>", section.name())));
                break;
            }
        }
    }
    out
}

/// One `<variable name="x" type="INT" initial="0"/>` of a confnode file as a global declaration.
fn variable(ctx: &mut Ctx, v: &Element) -> Option<VarDecl> {
    let span = ctx.tag(v);
    let name = v.attr("name").unwrap_or_default().trim();
    if !values::is_ident(name) {
        ctx.report(
            Diagnostic::error(
                code::E0320,
                format!("confnode variable `{name}` has no valid IEC name; it is not declared"),
            )
            .at(ctx.attr_span(v, "name"))
            .with_hint("give the variable a name made of letters, digits and `_` in Beremiz"),
        );
        return None;
    }
    let name = Ident::new(name, ctx.attr_span(v, "name"));
    let ty_text = v.attr("type").unwrap_or_default().trim();
    let ty_span = ctx.attr_span(v, "type");
    let upper = ty_text.to_ascii_uppercase();
    let ty = match upper.as_str() {
        "STRING" | "WSTRING" => TypeRef::String {
            wide: upper == "WSTRING",
            length: None,
            span: ty_span,
        },
        _ if values::is_ident(ty_text) => TypeRef::Named(Ident::new(ty_text, ty_span)),
        _ => {
            ctx.report(
                Diagnostic::error(
                    code::E0320,
                    format!(
                        "confnode variable `{}` has no valid type (`{ty_text}`); it is not declared",
                        name.name
                    ),
                )
                .at(ty_span)
                .with_hint("give the variable an IEC type name (INT, BOOL, a data type of plc.xml)"),
            );
            return None;
        }
    };
    let init = match v.attr("initial").map(str::trim).filter(|i| !i.is_empty()) {
        None => None,
        Some(text) => {
            let ispan = ctx.attr_span(v, "initial");
            // a STRING's value without quotes is the text itself: Beremiz adds the quotes
            // (`PLCGenerator.ComputeValue`, which it applies to these configuration globals too:
            // `initial="localhost"` is built as `host : STRING := 'localhost';`)
            let as_written = match &ty {
                TypeRef::String { wide, .. } => v
                    .attr("initial")
                    .and_then(|raw| values::string_as_written(raw, *wide, ispan)),
                _ => None,
            };
            match as_written.or_else(|| values::operand(text, ispan)) {
                Some(op) => Some(Initializer::Value(op)),
                None => {
                    ctx.report(
                        Diagnostic::error(
                            code::E0320,
                            format!(
                                "the initial value `{text}` of confnode variable `{}` is not a literal",
                                name.name
                            ),
                        )
                        .at(ispan)
                        .with_hint("write an IEC literal: `0`, `TRUE`, `'text'`, `T#1s`"),
                    );
                    None
                }
            }
        }
    };
    Some(VarDecl {
        name,
        location: None,
        ty,
        init,
        edge: None,
        span,
    })
}

/// A global `name : INT;` that a confnode declares implicitly (an MQTT client's `MQTT_STATUS_<channel>`),
/// located at `span` (the confnode's `baseconfnode.xml`).
pub fn implicit_global(name: &str, ty: &str, span: Span) -> VarDecl {
    VarDecl {
        name: Ident::new(name, span),
        location: None,
        ty: TypeRef::Named(Ident::new(ty, span)),
        init: None,
        edge: None,
        span,
    }
}

/// Adds `vars` as a `VAR_GLOBAL` block of the unit's first configuration, as Beremiz adds the
/// confnodes' globals to it; a unit without a configuration gets them as top-level globals (which
/// every program sees).
pub fn add_globals(unit: &mut CompilationUnit, vars: Vec<VarDecl>) {
    let Some(first) = vars.first() else {
        return;
    };
    let block = VarBlock {
        access: None,
        name: None,
        kind: VarKind::Global,
        constant: false,
        retain: false,
        span: first.span,
        vars,
    };
    for item in unit.items.iter_mut() {
        if let LibraryElement::Configuration(c) = item {
            c.globals.push(block);
            return;
        }
    }
    unit.items.push(LibraryElement::GlobalVars(block));
}
