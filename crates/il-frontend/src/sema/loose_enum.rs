//! Enumerations without `{attribute 'strict'}` used as integers (CODESYS, TwinCAT): `CASE nErr OF
//! E_Err.Timeout: ...` of an INT `nErr`, `AbortErrorId(errorId := E_Err.Timeout)` into an INT
//! input, `ErrorCode := _errorId` storing an INT into an enumeration.
//!
//! IEC 61131-3 (ed. 3, 6.4.4.3) types enumerations strongly: a value is no number. CODESYS and
//! TwinCAT convert between an enumeration and an integer implicitly unless the type is declared
//! under `{attribute 'strict'}` (their DUT editor adds it; older code and libraries such as Struckig
//! have none). ladderc does so, with one W1439 per POU; a strict enumeration keeps IEC's rule,
//! except that its value is stored into an integer (or a real) that holds every value and is
//! compared with one (Beckhoff Infosys, "Attribute 'strict'": compile errors for arithmetic and for
//! storing into the enumeration only). Beside an integer or a real that holds every value the
//! enumerated value counts as that type (`u = E.a` of a UINT).
//!
//! An integer initial value of a loose enumeration (`Kind : ActionEnum := 0;`, B&R's own
//! `MpAlarmX.typ`: `Type : MpAlarmXActionEnum := 0;`) is taken as the assignment `e := 0;` is (before
//! issue #13's round 34 it was E1025 while the assignment was W1439): the value of that number, or
//! the number itself when no value has it (CODESYS and TwinCAT hold a non-strict enumeration as
//! its integer base type; Automation Studio compiles its libraries' such initial values), with
//! one W1439 per enumeration; a strict enumeration's stays E1025 (`decls`).
//!
//! Input: the types an assignment, an input or a generic function (comparison, arithmetic) sees,
//! or an initial value and its declared type.
//! Output: whether they meet through the enumeration's number, and W1439 once per POU (once per
//! enumeration for initial values). Invariant:
//! an enumerated value is held as a DINT (c-backend), so an integer is stored into a loose
//! enumeration only where it widens to DINT, and a value leaves it only into an integer that holds
//! every value declared.

use super::body::Body;
use super::decls::Consts;
use super::model::{ConstValue, Elementary, Model, Type, UserTypeDef};
use super::typing::{literal_type, widens, LitType};
use super::Analyzer;
use crate::ast::{LiteralKind, Operand};
use crate::Span;
use diagnostics::code;

/// The values of `t` if it is an enumeration declared without `{attribute 'strict'}`.
fn loose_values<'m>(model: &'m Model, t: &Type) -> Option<&'m [(String, i128)]> {
    let Type::Enum(id) = t else { return None };
    let ut = model.user_type(*id);
    match &ut.def {
        UserTypeDef::Enum { values, .. } if !ut.strict => Some(values),
        _ => None,
    }
}

/// The values of `t` if it is an enumeration, strict or not.
fn enum_values<'m>(model: &'m Model, t: &Type) -> Option<&'m [(String, i128)]> {
    let Type::Enum(id) = t else { return None };
    match &model.user_type(*id).def {
        UserTypeDef::Enum { values, .. } => Some(values),
        _ => None,
    }
}

/// Whether `t` is an enumeration declared without `{attribute 'strict'}`.
pub(super) fn is_loose(model: &Model, t: &Type) -> bool {
    loose_values(model, t).is_some()
}

/// The integer type a loose enumeration counts as beside integers: INT (CODESYS's and TwinCAT's
/// default base type) when every value fits it, else DINT.
pub(super) fn number_type(model: &Model, t: &Type) -> Type {
    let fits_int = loose_values(model, t).is_some_and(|vs| {
        vs.iter()
            .all(|(_, v)| i128::from(i16::MIN) <= *v && *v <= i128::from(i16::MAX))
    });
    if fits_int {
        Type::INT
    } else {
        Type::DINT
    }
}

/// The values a bit string `t` holds as an unsigned number (BYTE 0..255 ... LWORD); `None` for
/// BOOL and every other type.
fn bit_string_range(t: Elementary) -> Option<(i128, i128)> {
    let bits = match t {
        Elementary::Byte => 8,
        Elementary::Word => 16,
        Elementary::Dword => 32,
        Elementary::Lword => 64,
        _ => return None,
    };
    Some((0, (1i128 << bits) - 1))
}

/// The integers a real type holds exactly: up to 2^24 in magnitude (REAL), 2^53 (LREAL).
fn exact_integer_range(t: Elementary) -> Option<(i128, i128)> {
    let bits = match t {
        Elementary::Real => 24,
        Elementary::Lreal => 53,
        _ => return None,
    };
    Some((-(1i128 << bits), 1i128 << bits))
}

/// The values `t` holds as numbers: an integer's range, a bit string's unsigned range, the
/// integers a real holds exactly; `None` for every other type.
fn number_range(t: Elementary) -> Option<(i128, i128)> {
    if t.is_integer() {
        t.int_range()
    } else if t.is_real() {
        exact_integer_range(t)
    } else {
        bit_string_range(t)
    }
}

/// The type a loose enumeration `t` counts as beside a value of the elementary type `other`: an
/// integer (`IF m_primitiveId = E_Ids.empty` of a UINT, `CASE nType OF E_Type.white:`), a real
/// (`GetNumeric(i) = E_Modes.automatic` of an LREAL) or a bit string (`nFlags AND
/// E_State.eUnknown` of a DWORD: Infosys, SA0058's example): `other`, when it holds every value
/// the enumeration declares (TwinCAT and CODESYS convert its number implicitly, as an integer
/// of its base type, Infosys "Attribute 'strict'").
///
/// `compared`: `t` is compared with that value (`=`, `<>`, `<`..., a CASE label): then a strict
/// enumeration counts so too, as `{attribute 'strict'}` makes errors only of arithmetic and of
/// storing other values into the enumeration (Infosys "Attribute 'strict'"; x-PPU's
/// `IF prevStepIdx = ESpecialStepIds.unset` of an INT under `strict`).
pub(super) fn type_beside(
    model: &Model,
    t: &Type,
    other: Elementary,
    compared: bool,
) -> Option<Type> {
    let (lo, hi) = number_range(other)?;
    let values = if compared {
        enum_values(model, t)
    } else {
        loose_values(model, t)
    };
    values?
        .iter()
        .all(|(_, v)| lo <= *v && *v <= hi)
        .then_some(Type::Elementary(other))
}

/// Whether a value of `from` may be stored into `to` through an enumeration's number: an
/// enumeration into an integer or a bit string that holds all its values (`d : DWORD := eFlags`;
/// a strict one too: Beckhoff's `{attribute 'strict'}` forbids arithmetic with the enumeration and
/// storing other values into it, not storing its values into an integer), an integer that widens
/// to DINT into a loose enumeration.
pub(super) fn assignable_loose(model: &Model, from: &Type, to: &Type) -> bool {
    if let (Some(values), Some(t)) = (enum_values(model, from), to.elementary()) {
        let range = match (t.is_integer(), t.int_range()) {
            (true, Some(r)) => Some(r),
            _ => bit_string_range(t),
        };
        if let Some((lo, hi)) = range {
            return values.iter().all(|(_, v)| lo <= *v && *v <= hi);
        }
    }
    // also into a real that holds each value exactly (`rValue := E_Type.white;` of an LREAL:
    // its base integer widens to LREAL in TwinCAT, x-PPU's `Value.Numeric`; a strict one too,
    // as into an integer)
    if let (Some(values), Some((lo, hi))) = (
        enum_values(model, from),
        to.elementary().and_then(exact_integer_range),
    ) {
        return values.iter().all(|(_, v)| lo <= *v && *v <= hi);
    }
    if let (Some(f), true) = (from.elementary(), is_loose(model, to)) {
        return f.is_integer() && widens(f, Elementary::Dint);
    }
    false
}

impl Body<'_, '_> {
    /// W1439 at `at`, once per POU: the enumeration `t` and an integer met through its number.
    pub(super) fn enum_as_integer(&mut self, t: &Type, at: Span) {
        if self.a.silent || !self.a.loose_enum_pous.insert(self.pou) {
            return;
        }
        let n = self.a.type_name(t);
        let loose = is_loose(&self.a.model, t);
        self.a
            .warning(
                code::W1439,
                at,
                format!("the enumeration {n} used as an integer: IEC 61131-3 enumerations are no numbers (its other uses in this POU are not reported)"),
            )
            .label("an enumerated value and an integer meet here")
            .hint(if loose {
                format!("compiled as CODESYS and TwinCAT do for an enumeration without {{attribute 'strict'}} (its number); convert with TO_DINT or declare the variable {n} for another IEC compiler")
            } else {
                format!("an array index, a value stored into a number or compared with one: CODESYS and TwinCAT use the number of {n} so, also under {{attribute 'strict'}} (it forbids arithmetic and storing other values into the enumeration); write TO_DINT(...) for another IEC compiler")
            });
    }
}

impl Analyzer<'_> {
    /// The initial value of the loose enumeration `ty` that the integer `op` gives (a literal,
    /// typed or not, or an integer constant): `None` when `ty` is no loose enumeration or `op` no
    /// such integer (the caller checks it as any initial value); `Some(None)` after an error.
    /// W1439 once per enumeration (see the module documentation).
    pub(super) fn integer_initial_value(
        &mut self,
        op: &Operand,
        ty: &Type,
        consts: &Consts,
    ) -> Option<Option<ConstValue>> {
        let Type::Enum(id) = ty else { return None };
        let values = loose_values(&self.model, ty)?;
        let n = match op {
            Operand::Literal(lit) => match (literal_type(lit).ok()?, &lit.kind) {
                (LitType::Int(n), _) => n,
                (LitType::Known(t), LiteralKind::Int(n))
                    if t.elementary()
                        .is_some_and(|e| e.is_integer() && widens(e, Elementary::Dint)) =>
                {
                    *n
                }
                _ => return None,
            },
            // a name that is a value of the enumeration is that value (`decls`)
            Operand::Var(v)
                if v.accessors.is_empty() && !values.iter().any(|(name, _)| v.base.is(name)) =>
            {
                match consts.get(&v.base.key()) {
                    Some((t, ConstValue::Int(n)))
                        if t.elementary()
                            .is_some_and(|e| e.is_integer() && widens(e, Elementary::Dint)) =>
                    {
                        *n
                    }
                    _ => return None,
                }
            }
            _ => return None,
        };
        let tn = self.type_name(ty);
        let (lo, hi) = Elementary::Dint.int_range()?;
        if n < lo || n > hi {
            self.error(
                code::E1017,
                op.span(),
                format!("initial value {n} does not fit {tn}"),
            )
            .label("out of range")
            .hint(format!("{tn} is held as a DINT; use one of its values"));
            return Some(None);
        }
        let index = values.iter().position(|(_, v)| *v == n);
        let named = index
            .and_then(|i| values.get(i))
            .map(|(name, _)| format!("its value `{name}`"))
            .unwrap_or_else(|| format!("the number {n}, which none of its values has"));
        if !self.silent && self.loose_enum_inits.insert(*id) {
            self.warning(
                code::W1439,
                op.span(),
                format!("the enumeration {tn} initialised with an integer: IEC 61131-3 enumerations are no numbers (its other integer initial values are not reported)"),
            )
            .label(format!("taken as {named}"))
            .hint(format!("compiled as CODESYS, TwinCAT and B&R Automation Studio do for an enumeration without {{attribute 'strict'}}; write {tn}#<value> for another IEC compiler"));
        }
        Some(Some(match index {
            Some(index) => ConstValue::Enum { ty: *id, index },
            None => ConstValue::Int(n),
        }))
    }
}
