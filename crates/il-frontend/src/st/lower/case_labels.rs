//! CASE labels that name a value of the selector's enumeration.
//!
//! IEC 61131-3 ed. 3, 7.3.3.3.3 (CASE): a case label is a constant (a literal, an enumerated
//! value, a constant expression) of the selector's type; ed. 2, B.3.2.2: `case_list_element ::=
//! subrange | signed_integer | enumerated_value`. A label is never a variable, so when the selector
//! is of an enumerated type, a bare label that names one of its values is that value, even where a
//! variable of the POU has the same name (`BG_OPEN:` of a `Mode` selector beside an input
//! `bg_open : BOOL`: IEC names ignore case; case-sensitive Automation Studio has no second
//! candidate at all). Before issue #13's round 34 the variable was read and compared with the
//! selector (a false E1005 "EQ of Mode and BOOL"). Elsewhere (`x := SEL_MANUAL;`) the variable
//! still wins, with the note W1430 (`PouLowering::shadowed_enum_value`).
//!
//! Input: a label expression and the selector's type. Output: the enumerated value the label
//! names, or `None` (the label is lowered as any other operand). Invariant: only a bare name
//! (no field, index or call) of a value the selector's enumeration declares is taken.

use super::super::ast::{Expr, ExprKind, Place, PlaceBase};
use super::PouLowering;
use crate::ast::{Ident, Operand, TypeRef};

impl PouLowering<'_> {
    /// The value of the enumeration `hint` (through aliases) that the bare name `e` names, as an
    /// operand `Type#Value`, whether or not a variable has that name too.
    pub(super) fn value_of_enumeration(&self, e: &Expr, hint: Option<&TypeRef>) -> Option<Operand> {
        let ExprKind::Place(Place {
            base: PlaceBase::Name(value),
            accessors,
            ..
        }) = &e.kind
        else {
            return None;
        };
        if !accessors.is_empty() {
            return None;
        }
        let TypeRef::Named(t) = self.env().resolve(hint?) else {
            return None;
        };
        let decl = self.decls.type_decl(&t.name)?;
        match &decl.def {
            crate::ast::TypeDef::Enum { values, .. }
                if values.iter().any(|v| v.name.is(&value.name)) =>
            {
                Some(Operand::enum_value(
                    Ident::new(decl.name.name.clone(), value.span),
                    value.clone(),
                    e.span,
                ))
            }
            _ => None,
        }
    }
}
