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
use super::st_bridge::{self, StPart};
use crate::context::Ctx;
use crate::graph::{self, Graph};
use crate::lower::BodyLowering;
use crate::project::Index;
use crate::xml::Element;
use diagnostics::code;
use il_frontend::ast::{IlStmt, Op, Pou};

pub struct Snippets<'i> {
    pub index: &'i Index,
    pub pou: &'i Pou,
    count: usize,
}

/// What a body is for.
pub enum Purpose<'s> {
    /// A condition: its value goes to `result`; `name` is the transition's name an LD/FBD body writes.
    Condition {
        result: &'s str,
        name: &'s str,
    },
    Action,
}

impl<'i> Snippets<'i> {
    pub fn new(index: &'i Index, pou: &'i Pou) -> Self {
        Snippets {
            index,
            pou,
            count: 0,
        }
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
        let mut stmts = match lang.name {
            "IL" => crate::il_body::parse(ctx, lang, &pou_name),
            "ST" => {
                let part = match purpose {
                    Purpose::Condition { .. } => StPart::Expression,
                    Purpose::Action => StPart::Statements,
                };
                let (stmts, vars) = st_bridge::lower(ctx, self.index, self.pou, lang, part)?;
                for mut v in vars {
                    if v.name.name.starts_with("__") {
                        let new = format!("{prefix}{}", &v.name.name[2..]);
                        renames.bases.insert(v.name.key(), new.clone());
                        v.name.name = new;
                    }
                    hidden.push(v);
                }
                stmts
            }
            "LD" | "FBD" => {
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
            match lang.name {
                "LD" | "FBD" => {
                    if name.is_empty() {
                        super::chart::report(
                            ctx,
                            code::E3126,
                            span,
                            &pou_name,
                            None,
                            format!(
                                "{owner}: an {} condition needs a name, written by its coil or output \
                                 variable",
                                lang.name
                            ),
                        );
                        return None;
                    }
                    renames
                        .bases
                        .insert(name.to_ascii_uppercase(), result.to_string());
                }
                _ => stmts.push(il::op(Op::St, il::var(result, span))),
            }
        }
        renames.apply(&mut stmts);
        Some(stmts)
    }
}
