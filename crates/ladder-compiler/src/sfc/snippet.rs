//! The bodies inside a chart: transition conditions and action bodies written in IL, ST, LD or FBD,
//! lowered to IL statements that can be pasted into the POU body.
//!
//! Input: a language element (`<IL>`, `<ST>`, `<LD>`, `<FBD>`) and what it is (condition, action).
//! Output: IL statements; a condition ends with its value stored into the given hidden variable.
//! Invariants: each sub-body gets its own prefix `__s<k>_` for its labels and for the hidden variables
//! its LD/FBD lowering declares (edge detectors, temporaries), so two bodies never share an edge
//! detector or a label; an LD/FBD condition writes a coil (or output variable) named after the
//! transition, which is renamed to the condition variable.

use super::il::{self, Hidden, Renames};
use super::st_bridge::{Delivered, StLowering, StPart};
use crate::context::Ctx;
use crate::graph::{self, Graph};
use crate::lower::BodyLowering;
use crate::project::Index;
use crate::xml::Element;
use diagnostics::code;
use il_frontend::ast::{IlStmt, Op, Pou};

/// Lowers the bodies inside a chart (transition conditions, action bodies) in any language into the POU's
/// IL, with unique labels and hidden names.
pub struct Snippets<'i> {
    /// The project's POU interfaces, types and globals.
    pub index: &'i Index,
    /// The POU the chart belongs to.
    pub pou: &'i Pou,
    st: StLowering<'i>,
    count: usize,
}

/// What a body is for.
pub enum Purpose<'s> {
    /// A condition: its value goes to `result`; `name` is the transition's name an LD/FBD body writes.
    Condition {
        /// The hidden BOOL variable the condition's value is stored into.
        result: &'s str,
        /// The transition's name as the body writes it (its coil or `Name :=`).
        name: &'s str,
    },
    /// An action body: run as written, its labels renamed.
    Action,
}

impl<'i> Snippets<'i> {
    /// A snippet lowering for the chart of `pou`, sharing `st`'s ST state.
    pub fn new(index: &'i Index, pou: &'i Pou, st: StLowering<'i>) -> Self {
        Snippets {
            index,
            pou,
            st,
            count: 0,
        }
    }

    /// The temporaries of the ST snippets (declared once for the whole chart).
    pub fn finish(self, span: il_frontend::Span) -> Vec<il_frontend::ast::VarDecl> {
        self.st.finish(span)
    }

    fn next_prefix(&mut self) -> String {
        self.count += 1;
        format!("__s{}_", self.count)
    }

    /// Lowers one body. `owner` describes it in diagnostics ("transition 3", "action Fill").
    pub fn lower(
        &mut self,
        ctx: &mut Ctx,
        lang: &Element,
        purpose: Purpose,
        hidden: &mut Hidden,
        owner: &str,
    ) -> Option<Vec<IlStmt>> {
        let pou_name = self.pou.name.name.clone();
        let span = ctx.tag(lang);
        let prefix = self.next_prefix();
        let mut renames = Renames {
            label_prefix: prefix.clone(),
            ..Default::default()
        };
        // IL leaves a condition in the current result; LD/FBD write the transition's name.
        let mut delivered = Delivered::CurrentResult;
        let mut stmts = match lang.name() {
            "IL" => crate::il_body::parse(ctx, lang, self.pou),
            "ST" => {
                let (part, name) = match purpose {
                    Purpose::Condition { name, .. } => (StPart::Expression, name),
                    Purpose::Action => (StPart::Statements, ""),
                };
                let (stmts, how) = self.st.lower(ctx, &pou_name, lang, part, name)?;
                delivered = how;
                stmts
            }
            "LD" | "FBD" => {
                delivered = Delivered::Assigned;
                let g: Graph = graph::read(ctx, lang, &pou_name);
                let mut low = BodyLowering::new(self.index, self.pou, span);
                let stmts = low.lower(ctx, &g);
                for mut v in low.hidden_vars() {
                    let new = format!("{prefix}{}", v.name.name.trim_start_matches('_'));
                    renames.bases.insert(v.name.key(), new.clone());
                    v.name.name = new;
                    hidden.push(v);
                }
                stmts
            }
            other => {
                super::chart::report(
                    ctx,
                    code::E3125,
                    span,
                    &pou_name,
                    None,
                    format!("{owner}: a <{other}> body inside an SFC is not supported"),
                );
                return None;
            }
        };
        if let Purpose::Condition { result, name } = purpose {
            if delivered == Delivered::Assigned && name.is_empty() {
                super::chart::report(
                    ctx,
                    code::E3126,
                    span,
                    &pou_name,
                    None,
                    format!(
                        "{owner}: an {} condition needs a name, written by its coil, output variable \
                         or assignment",
                        lang.name()
                    ),
                );
                return None;
            }
            if !name.is_empty() {
                renames
                    .bases
                    .insert(name.to_ascii_uppercase(), result.to_string());
            }
            if delivered == Delivered::CurrentResult {
                stmts.push(il::op(Op::St, il::var(result, span)));
            }
        }
        renames.apply(&mut stmts);
        Some(stmts)
    }
}
