//! The one boundary between the SFC lowering and the Structured Text front end: "lower this ST boolean
//! expression" and "lower this ST statement list" to IL statements.
//!
//! Input: the language element (`<ST>`) holding the text, the POU and the project index.
//! Output: IL statements (for an expression, the value is left in the current result) and the hidden
//! declarations they need; `None` after reporting a diagnostic.
//! Invariants: positions in diagnostics point into the XML file (the text is rebuilt with
//! [`crate::il_body::embedded_text`], byte `k` of the text is byte `base + k` of the file).

use crate::context::Ctx;
use crate::project::Index;
use crate::xml::Element;
use diagnostics::{code, Diagnostic, XmlContext};
use il_frontend::ast::{IlStmt, Pou, VarDecl};

/// What the ST text is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StPart {
    /// A boolean expression (a transition condition).
    Expression,
    /// A statement list (an action body).
    Statements,
}

/// Lowers an ST snippet of an SFC body to IL.
pub fn lower(
    ctx: &mut Ctx,
    _index: &Index,
    pou: &Pou,
    lang: &Element,
    part: StPart,
) -> Option<(Vec<IlStmt>, Vec<VarDecl>)> {
    let what = match part {
        StPart::Expression => "transition condition",
        StPart::Statements => "action",
    };
    ctx.report(
        Diagnostic::error(
            code::E3129,
            format!(
                "ST {what} in the SFC of `{}` cannot be lowered: this build has no ST front end",
                pou.name.name
            ),
        )
        .at(ctx.text_span(lang))
        .with_xml(XmlContext {
            pou: Some(pou.name.name.clone()),
            ..Default::default()
        }),
    );
    None
}
