//! The one boundary between the SFC lowering and the Structured Text front end (`il_frontend::st`):
//! "lower this ST boolean expression" and "lower this ST statement list" to IL statements.
//!
//! Input: the language element (`<ST>`) holding the text, and one [`StLowering`] per POU (all snippets
//! of a chart share it, so ST labels and temporaries never clash). Output: IL statements (for an
//! expression, the value is left in the current result) and, at the end, the temporaries.
//! Invariants: positions in diagnostics point into the XML file (the text is rebuilt with
//! [`crate::il_body::embedded_text`], byte `k` of the text is byte `base + k` of the file); the ST
//! lowering sees every step as a variable of a struct type with `X : BOOL` and `T : TIME`, and every
//! named action with `Q`/`A : BOOL`, so `Step.X` type-checks; the SFC renaming pass then maps them to
//! the hidden chart variables. Its labels and temporaries start with `_SFC_ST_` (the POU's own ST
//! actions, inlined beside the chart, have `_ST_` ones); a condition that reads a PROPERTY is
//! lowered as a statement into such a temporary (`il_frontend::st::PouLowering::condition`).

use crate::context::Ctx;
use crate::project::Index;
use crate::xml::Element;
use diagnostics::{Diagnostics, XmlContext};
use il_frontend::ast::{Ident, IlStmt, Pou, TypeDecl, TypeDef, TypeRef, VarDecl};
use il_frontend::st::{self, Declarations, PouLowering};
use il_frontend::Span;

/// What the ST text is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StPart {
    /// A boolean expression (a transition condition). `name` is the transition's name, which a
    /// statement form (`Name := expr;`) may assign instead.
    Expression,
    /// A statement list (an action body).
    Statements,
}

/// How the lowered code delivers a condition.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Delivered {
    /// The value is in the current result.
    CurrentResult,
    /// The code assigns the transition's name (renamed by the caller), or it is an action.
    Assigned,
}

const STEP_TYPE: &str = il_frontend::st::sfc::STEP_TYPE;
const ACTION_TYPE: &str = "__SFC_ACTION";

/// The declarations the ST lowering needs: the project's, plus the step and action flag types (declared
/// at `file_span`, the span of the first chart that asks). Built once per index.
pub fn declarations(index: &Index, file_span: Span) -> &Declarations {
    index
        .sfc_declarations
        .get_or_init(|| build_declarations(index, file_span))
}

fn build_declarations(index: &Index, file_span: Span) -> Declarations {
    let mut d = crate::st_body::declarations(index).clone();
    let field = |n: &str, t: &str| {
        VarDecl::new(
            Ident::new(n, file_span),
            TypeRef::Named(Ident::new(t, file_span)),
            file_span,
        )
    };
    d.add_type(il_frontend::st::sfc::step_type(file_span));
    d.add_type(TypeDecl {
        name: Ident::new(ACTION_TYPE, file_span),
        def: TypeDef::Struct {
            fields: vec![field("Q", "BOOL"), field("A", "BOOL")],
        },
        union: false,
        span: file_span,
    });
    d
}

/// The ST lowering of one chart.
pub struct StLowering<'d> {
    low: PouLowering<'d>,
}

impl<'d> StLowering<'d> {
    /// The ST lowering for `pou`'s chart: every step is declared as a variable with `.X` and `.T`, every
    /// action with `.Q` and `.A`, so ST bodies can read them.
    pub fn new(decls: &'d Declarations, pou: &Pou, steps: &[String], actions: &[String]) -> Self {
        // its labels and temporaries are `_SFC_ST_...`: the POU's own ST actions and methods,
        // lowered on their own and inlined beside the chart's code, have `_ST_...` ones (a
        // condition reading a property needs a temporary: round 32, before none did)
        let mut low = PouLowering::new(decls, pou).with_prefix("_SFC_ST_");
        let span = pou.span;
        for s in steps {
            low.declare(s, TypeRef::Named(Ident::new(STEP_TYPE, span)));
        }
        for a in actions {
            low.declare(a, TypeRef::Named(Ident::new(ACTION_TYPE, span)));
        }
        StLowering { low }
    }

    /// Lowers an ST snippet of the chart. `name` is the transition's name for a condition (may be
    /// empty). `None` when the text could not be lowered (diagnostics reported).
    pub fn lower(
        &mut self,
        ctx: &mut Ctx,
        pou_name: &str,
        lang: &Element,
        part: StPart,
        name: &str,
    ) -> Option<(Vec<IlStmt>, Delivered)> {
        let mut t = crate::il_body::embedded_text(lang);
        crate::st_body::join_split_operators(&mut t.text, t.base, ctx.xml);
        let mut local = Diagnostics::new();
        let result = match part {
            StPart::Statements => {
                let stmts = st::parse_statements(ctx.file, &t.text, t.base, &mut local);
                Some((self.low.statements(&stmts, &mut local), Delivered::Assigned))
            }
            StPart::Expression => {
                // Beremiz writes named ST transitions as `:= expr;`: blank the markers (positions kept).
                let trimmed = t.text.trim_start();
                if trimmed.starts_with(":=") {
                    let at = t.text.len() - trimmed.len();
                    t.text.replace_range(at..at + 2, "  ");
                    if let Some(semi) = t.text.rfind(';') {
                        if t.text[semi + 1..].trim().is_empty() {
                            t.text.replace_range(semi..semi + 1, " ");
                        }
                    }
                }
                let assigns = !name.is_empty() && t.text.contains(":=");
                if assigns {
                    self.low
                        .declare(name, TypeRef::Named(Ident::new("BOOL", ctx.tag(lang))));
                    let stmts = st::parse_statements(ctx.file, &t.text, t.base, &mut local);
                    Some((self.low.statements(&stmts, &mut local), Delivered::Assigned))
                } else {
                    st::parse_expression(ctx.file, &t.text, t.base, &mut local)
                        .map(|e| (self.low.condition(&e, &mut local), Delivered::CurrentResult))
                }
            }
        };
        let failed = local.has_errors();
        for d in local {
            let d = if d.xml.is_none() {
                d.with_xml(XmlContext {
                    pou: Some(pou_name.to_string()),
                    ..Default::default()
                })
            } else {
                d
            };
            ctx.report(d);
        }
        if failed {
            return None;
        }
        result
    }

    /// The temporaries the snippets needed.
    pub fn finish(self, span: Span) -> Vec<VarDecl> {
        self.low.finish(span).map(|b| b.vars).unwrap_or_default()
    }
}
