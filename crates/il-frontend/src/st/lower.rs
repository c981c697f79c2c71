//! ST statements and expressions to IL instructions (skeleton: the API is final, see ST_API.md).

use super::ast::{Expr, Stmt};
use super::types::Declarations;
use crate::ast::{Ident, IlStmt, Pou, TypeRef, VarBlock, VarDecl, VarKind};
use crate::Span;
use diagnostics::{code, Diagnostic, Diagnostics};
use std::collections::HashMap;

/// The lowering state of one POU: shared by every ST snippet lowered into that POU, so labels and
/// temporaries stay unique.
pub struct PouLowering<'d> {
    decls: &'d Declarations,
    pou: Ident,
    vars: HashMap<String, TypeRef>,
    temps: Vec<VarDecl>,
    next_label: u32,
}

impl<'d> PouLowering<'d> {
    pub fn new(decls: &'d Declarations, pou: &Pou) -> Self {
        let mut vars = HashMap::new();
        for b in &pou.var_blocks {
            for v in &b.vars {
                vars.insert(v.name.key(), v.ty.clone());
            }
        }
        PouLowering {
            decls,
            pou: pou.name.clone(),
            vars,
            temps: Vec::new(),
            next_label: 0,
        }
    }
    /// Makes a variable the POU will have (but `pou.var_blocks` did not list when [`Self::new`] ran)
    /// visible to the lowering, e.g. SFC step flags.
    pub fn declare(&mut self, name: &str, ty: TypeRef) {
        self.vars.insert(name.to_ascii_uppercase(), ty);
    }
    /// A label no other snippet of this POU uses: `_ST_<WHAT><n>`.
    pub fn fresh_label(&mut self, what: &str, span: Span) -> Ident {
        self.next_label += 1;
        Ident::new(format!("_ST_{what}{}", self.next_label), span)
    }
    /// Lowers a statement list.
    pub fn statements(&mut self, stmts: &[Stmt], diags: &mut Diagnostics) -> Vec<IlStmt> {
        let _ = self.decls;
        if let Some(s) = stmts.first() {
            diags.push(
                Diagnostic::error(code::E3100, format!("ST lowering of POU `{}` is not available yet", self.pou.name))
                    .at(s.span),
            );
        }
        Vec::new()
    }
    /// Lowers an expression: the instructions leave its value in the current result.
    pub fn expression(&mut self, e: &Expr, diags: &mut Diagnostics) -> Vec<IlStmt> {
        diags.push(Diagnostic::error(code::E3100, "ST lowering is not available yet").at(e.span));
        Vec::new()
    }
    /// Lowers a condition (a BOOL expression): the instructions leave it in the current result.
    pub fn condition(&mut self, e: &Expr, diags: &mut Diagnostics) -> Vec<IlStmt> {
        self.expression(e, diags)
    }
    /// The temporaries declared so far.
    pub fn temporaries(&self) -> &[VarDecl] {
        &self.temps
    }
    /// The `VAR_TEMP` block holding the temporaries (none when no temporary was needed).
    pub fn finish(self, span: Span) -> Option<VarBlock> {
        (!self.temps.is_empty()).then(|| VarBlock {
            kind: VarKind::Temp,
            constant: false,
            retain: false,
            vars: self.temps,
            span,
        })
    }
}
