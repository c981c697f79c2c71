//! ladder-compiler: PLCopen TC6 XML projects (tc6_0201, tc6_0200, v1.0) to the IL syntax tree.
//!
//! Input: the XML text of a project. Output: an [`ast::CompilationUnit`] with the project's data types,
//! POUs (LD and FBD networks lowered to IL, IL bodies parsed in place, ST bodies lowered to IL) and configurations, plus
//! diagnostics in the engineer's terms (POU, network, localId, XML line and column).
//! Invariants: never panics on bad input; every lowered node's span points at the XML element it came
//! from; the rest of the project still compiles when one POU cannot be lowered.
//!
//! Stages: [`xml`] (element tree with positions) -> [`project`] (declarations, configurations) ->
//! [`body`] per POU -> [`graph`] (networks, order) -> [`lower`] (IL statements).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod beremiz;
pub mod body;
pub mod catalogue;
pub(crate) mod codesys_cfc;
pub mod codesys_v2;
pub(crate) mod codesys_vla;
pub mod context;
pub mod decls;
pub mod graph;
pub mod il_body;
pub mod locate;
pub mod lower;
pub mod network_order;
pub mod project;
pub mod sfc;
pub mod st_body;
pub mod testgen;
pub mod twincat;
pub(crate) mod twincat_cfc;
pub(crate) mod twincat_nwl;
pub(crate) mod twincat_operators;
pub(crate) mod twincat_sfc;
pub mod values;
pub mod var_config;
pub mod xml;
mod xml_attrs;
pub(crate) mod xml_oop;

pub use il_frontend::ast;

use diagnostics::{code, Diagnostic, Diagnostics, FileId};

/// Reads a PLCopen XML project and lowers it to the IL syntax tree.
pub fn compile_xml(file: FileId, xml: &str, diags: &mut Diagnostics) -> ast::CompilationUnit {
    let (unit, entries, pending) = compile_xml_with_var_config(file, xml, diags);
    let mut units = [unit];
    if !pending.is_empty() {
        il_frontend::st::file::compile_pending(&mut units, &pending, diags);
    }
    il_frontend::st::file::apply_var_config(&mut units, entries, diags);
    let [unit] = units;
    unit
}

/// [`compile_xml`] without applying the configurations' `<configVars>` (VAR_CONFIG) and without
/// compiling the ST bodies left to the ST front end: the unit, the entries and those bodies, for a
/// caller that applies the entries once every input file is read
/// (`il_frontend::st::file::apply_var_config`), as they may name programs of other files, and
/// compiles the bodies with the other files' (`il_frontend::st::file::compile_pending`). The
/// bodies are those of a file with CODESYS's interfaces or inheritance in its vendor data
/// (`xml_oop`): its POUs of ST text, whose statements the unit leaves empty.
pub fn compile_xml_with_var_config(
    file: FileId,
    xml: &str,
    diags: &mut Diagnostics,
) -> (
    ast::CompilationUnit,
    Vec<il_frontend::st::file::ConfigEntry>,
    Vec<il_frontend::st::file::PendingBody>,
) {
    let arena = xml::Arena::new();
    let (root, err) = xml::parse(xml, &arena);
    let mut ctx = context::Ctx::new(file, xml, diags);
    let malformed = err.is_some();
    if let Some(e) = err {
        let span = ctx.span(e.pos, e.pos);
        ctx.report(
            Diagnostic::error(
                code::E3001,
                format!("the XML file is not well-formed: {}", e.message),
            )
            .at(span)
            .with_primary_label("the XML reader stopped here"),
        );
    }
    match root {
        // XML 1.0, 1.2 "fatal error": after one, a processor does not pass the document's content on
        // in the normal way. What was read up to the break is cut (an ST body ends mid-statement at an
        // unescaped `<`): its errors would be follow-ons of E3001, so nothing of it is read. (A
        // document that stopped before its first element has nothing to read either.)
        _ if malformed => (ast::CompilationUnit::default(), Vec::new(), Vec::new()),
        Some(r) => {
            let mut unit = project::read_project(&mut ctx, &r);
            unit.items.extend(
                std::mem::take(&mut ctx.actions)
                    .into_iter()
                    .map(ast::LibraryElement::Action),
            );
            // `ADR('text')` in ST bodies: the literals' hidden copies made global variables
            il_frontend::st::var_stat::hoist(std::slice::from_mut(&mut unit));
            (
                unit,
                std::mem::take(&mut ctx.var_config),
                std::mem::take(&mut ctx.pending),
            )
        }
        None => {
            let span = ctx.span(0, 0);
            ctx.error(
                code::E3002,
                span,
                "no <project> element: the file is empty or not XML",
            );
            (ast::CompilationUnit::default(), Vec::new(), Vec::new())
        }
    }
}

/// The unit as readable IL text (TYPE, POUs, CONFIGURATION), printed by `il_frontend::print`.
pub fn emit_il(unit: &ast::CompilationUnit) -> String {
    il_frontend::print::unit(unit)
}
