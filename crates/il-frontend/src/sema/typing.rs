//! IEC typing rules: implicit widening, assignability, the common type of generic inputs, literal typing,
//! and the untyped-literal type variables (integer literals are untyped until their context fixes a type).
//!
//! Input: resolved [`Type`]s and AST literals. Output: yes/no answers, common types, literal types.
//! Invariants: `Type::Error` is compatible with everything (it silences follow-on errors); widening never
//! loses information (edition 3, Figure 11): no implicit narrowing.

use super::model::{ConstValue, Elementary, Type};
use crate::ast::{Literal, LiteralKind};
use crate::Span;
use Elementary as E;

/// Whether a value of `from` converts implicitly (without loss) to `to`.
pub fn widens(from: Elementary, to: Elementary) -> bool {
    if from == to {
        return true;
    }
    match from {
        E::Sint => matches!(to, E::Int | E::Dint | E::Lint | E::Real | E::Lreal),
        E::Int => matches!(to, E::Dint | E::Lint | E::Real | E::Lreal),
        E::Dint => matches!(to, E::Lint | E::Lreal),
        E::Usint => matches!(
            to,
            E::Uint | E::Udint | E::Ulint | E::Int | E::Dint | E::Lint | E::Real | E::Lreal
        ),
        E::Uint => matches!(
            to,
            E::Udint | E::Ulint | E::Dint | E::Lint | E::Real | E::Lreal
        ),
        E::Udint => matches!(to, E::Ulint | E::Lint | E::Lreal),
        E::Real => to == E::Lreal,
        E::Bool => matches!(to, E::Byte | E::Word | E::Dword | E::Lword),
        E::Byte => matches!(to, E::Word | E::Dword | E::Lword),
        E::Word => matches!(to, E::Dword | E::Lword),
        E::Dword => to == E::Lword,
        E::Time => to == E::Ltime,
        // edition 3's long date types hold the same nanoseconds (IEC 61131-3 edition 3, 6.4.2)
        E::Date => to == E::Ldate,
        E::Tod => to == E::Ltod,
        E::Dt => to == E::Ldt,
        _ => false,
    }
}

/// Whether a value of type `from` may be stored into (or passed as) `to`.
pub fn assignable(from: &Type, to: &Type) -> bool {
    if from.is_error() || to.is_error() || from == to {
        return true;
    }
    match (from, to) {
        (Type::String { wide: a, .. }, Type::String { wide: b, .. }) => a == b,
        (
            Type::Array {
                dims: da,
                element: ea,
            },
            Type::Array {
                dims: db,
                element: eb,
            },
        ) => da.len() == db.len() && da.iter().zip(db).all(|(a, b)| a.len() == b.len()) && ea == eb,
        // NULL into any reference; a reference to the same type; a reference to an array into
        // a reference to its element type (the first element, as C's arrays decay: `pData :
        // POINTER TO LREAL := ADR(samples)`, CODESYS and TwinCAT). Other pointer types only
        // through `pointer_reinterprets` (sema: `coerce`, with W1425).
        (Type::Ref(a), Type::Ref(b)) => a.is_error() || a == b || decays_to(a, b),
        (Type::Ref(_), _) | (_, Type::Ref(_)) => false,
        _ => match (from.elementary(), to.elementary()) {
            (Some(f), Some(t)) => widens(f, t),
            _ => false,
        },
    }
}

/// Whether an array of `from` (any dimensions, nested arrays too) has `to` as its element type.
pub fn decays_to(from: &Type, to: &Type) -> bool {
    match from {
        Type::Array { element, .. } => **element == *to || decays_to(element, to),
        _ => false,
    }
}

/// Whether a reference to `from` may be stored into a reference to `to` that reads the same bytes
/// as another type (`b : POINTER TO ULINT := ADR(x)` of an LREAL `x`, CODESYS and TwinCAT; IEC
/// 61131-3 keeps references typed): only between types that hold no reference and no function
/// block instance (see [`holds_no_reference`]), so that no reference can be forged from bytes.
pub fn pointer_reinterprets(from: &Type, to: &Type, model: &super::model::Model) -> bool {
    match (from, to) {
        (Type::Ref(a), Type::Ref(b)) => {
            !a.is_error()
                && !b.is_error()
                && holds_no_reference(a, model)
                && holds_no_reference(b, model)
        }
        _ => false,
    }
}

/// Whether the bytes of a value of type `t` hold no reference and no function block instance
/// (elementary values, strings, enumerations, and arrays and structures of these).
pub fn holds_no_reference(t: &Type, model: &super::model::Model) -> bool {
    fn go(t: &Type, model: &super::model::Model, depth: u32) -> bool {
        if depth > 64 {
            return false;
        }
        match t {
            Type::Ref(_) | Type::Fb(_) | Type::Error => false,
            Type::Array { element, .. } => go(element, model, depth + 1),
            Type::Struct(id) => match &model.user_type(*id).def {
                super::model::UserTypeDef::Struct { fields } => {
                    fields.iter().all(|f| go(&f.ty, model, depth + 1))
                }
                _ => false,
            },
            _ => true,
        }
    }
    go(t, model, 0)
}

/// Whether a value of type `t` holds (as what it refers to, an array's element or a structure's
/// field, at any depth) a type that was not found: that type's own error (E1003) is the cause of
/// what it makes fail, not the use.
pub fn holds_unknown(t: &Type, model: &super::model::Model) -> bool {
    fn go(t: &Type, model: &super::model::Model, depth: u32) -> bool {
        if depth > 64 {
            return false;
        }
        match t {
            Type::Error => true,
            Type::Ref(target) => go(target, model, depth + 1),
            Type::Array { element, .. } => go(element, model, depth + 1),
            Type::Struct(id) => match &model.user_type(*id).def {
                super::model::UserTypeDef::Struct { fields } => {
                    fields.iter().any(|f| go(&f.ty, model, depth + 1))
                }
                _ => false,
            },
            _ => false,
        }
    }
    go(t, model, 0)
}

/// The type all `types` widen to, if one of them is that type (`INT` and `DINT` give `DINT`).
pub fn common_type(types: &[Type]) -> Option<Type> {
    let first = types.iter().find(|t| !t.is_error())?;
    // The usual case, without the list of normalised types: all the same type.
    if types.iter().filter(|t| !t.is_error()).all(|t| t == first) {
        return Some(first.clone());
    }
    // Subranges count as their base.
    let norm = |t: &Type| match t.elementary() {
        Some(e) if !t.is_string() => Type::Elementary(e),
        _ => t.clone(),
    };
    let norms: Vec<Type> = types.iter().filter(|t| !t.is_error()).map(norm).collect();
    if norms.iter().all(|t| *t == norm(first)) {
        return Some(
            if types.iter().filter(|t| !t.is_error()).all(|t| t == first) {
                first.clone()
            } else {
                norm(first)
            },
        );
    }
    norms
        .iter()
        .find(|cand| norms.iter().all(|t| assignable(t, cand)))
        .cloned()
}

/// What a literal's type is before context.
#[derive(Debug, Clone, PartialEq)]
pub enum LitType {
    /// A typed literal (`INT#5`, `T#1s`, `TRUE`, `'text'`) or one whose kind fixes its type.
    Known(Type),
    /// An untyped integer literal with its value.
    Int(i128),
    /// An untyped real literal, with its value.
    Real(f64),
    /// An untyped one-character string literal (`wide`: `"A"`): a STRING, or edition 3's CHAR
    /// where one is expected.
    Char(bool),
}

/// A problem with a typed literal.
pub struct LitError {
    /// What is wrong (`INT#40000 is out of range for INT`).
    pub message: String,
    /// How to fix it.
    pub hint: String,
}

/// A date, time-of-day or date-and-time literal's type: its long form (`LDATE#`, `LTOD#`,
/// `LDT#`: the parser's canonical prefix) or `short`.
fn long_or(prefix: Option<(String, Option<Elementary>)>, short: Elementary) -> Elementary {
    match prefix.and_then(|(_, e)| e) {
        Some(e) if e.is_long_date() && e.date_kind() == Some(short) => e,
        _ => short,
    }
}

/// Types a literal; checks typed literals (`INT#40000`) against their type's range.
pub fn literal_type(lit: &Literal) -> Result<LitType, LitError> {
    let prefix = lit
        .type_prefix
        .as_ref()
        .map(|p| (p.name.clone(), Elementary::from_name(&p.name)));
    match (&lit.kind, prefix) {
        (LiteralKind::Int(v), None) => Ok(LitType::Int(*v)),
        (LiteralKind::Int(v), Some((_, Some(e)))) if e.is_real() => {
            let _ = v;
            Ok(LitType::Known(Type::Elementary(e)))
        }
        // a character by its code (`CHAR#16#80`, `WCHAR#16#20AC`): a CHAR is one byte, a WCHAR
        // two (IEC 61131-3 ed. 3 Table 10; before round 27: E1017 for every code)
        (LiteralKind::Int(v), Some((_, Some(e)))) if e.is_char() => {
            let hi: i128 = if e == E::Wchar { 0xFFFF } else { 0xFF };
            if (0..=hi).contains(v) {
                Ok(LitType::Known(Type::Elementary(e)))
            } else {
                Err(LitError {
                    message: format!("character code {v} does not fit {}", e.name()),
                    hint: format!(
                        "a {} holds the codes 0..{hi} (16#{hi:X}){}",
                        e.name(),
                        if e == E::Wchar {
                            ""
                        } else {
                            "; use WCHAR# for a wider code"
                        }
                    ),
                })
            }
        }
        (LiteralKind::Int(v), Some((name, Some(e)))) => match e.int_range() {
            Some((lo, hi)) if *v >= lo && *v <= hi => Ok(LitType::Known(Type::Elementary(e))),
            Some((lo, hi)) => Err(LitError {
                message: format!("literal {v} does not fit {}", e.name()),
                hint: format!(
                    "{} holds {lo}..{hi}; use a wider type such as {}",
                    name.to_ascii_uppercase(),
                    wider_for(*v)
                ),
            }),
            None => Err(LitError {
                message: format!("an integer literal cannot have type {}", e.name()),
                hint: "write the literal in the type's own syntax (T#5s, D#2024-01-01 ...)".into(),
            }),
        },
        // A real literal beyond LREAL's range (1.8E308) or a REAL# one beyond REAL's (3.4E38) would
        // silently become an infinity.
        // (A NaN comes from a constant expression only, `LOG(-1)`: it is the value itself.)
        (LiteralKind::Real(v), p)
            if v.is_infinite()
                || p.as_ref().is_some_and(|(_, e)| *e == Some(E::Real))
                    && v.abs() > f64::from(f32::MAX) =>
        {
            let ty = if v.is_finite() { "REAL" } else { "LREAL" };
            Err(LitError {
                message: format!("real literal beyond the range of {ty}"),
                hint: format!(
                    "{ty} holds magnitudes up to {}; write a smaller value",
                    if v.is_finite() {
                        "3.4028235E38"
                    } else {
                        "1.7976931348623157E308"
                    }
                ),
            })
        }
        (LiteralKind::Real(v), None) => Ok(LitType::Real(*v)),
        (LiteralKind::Real(_), Some((_, Some(e)))) if e.is_real() => {
            Ok(LitType::Known(Type::Elementary(e)))
        }
        (LiteralKind::Real(_), Some((_, Some(e)))) => Err(LitError {
            message: format!("a real literal cannot have type {}", e.name()),
            hint: "use REAL# or LREAL#, or an integer literal".into(),
        }),
        (LiteralKind::Bool(_), _) => Ok(LitType::Known(Type::BOOL)),
        (LiteralKind::Duration(_), p) => Ok(LitType::Known(Type::Elementary(
            if p.is_some_and(|(n, _)| {
                n.eq_ignore_ascii_case("LTIME") || n.eq_ignore_ascii_case("LT")
            }) {
                E::Ltime
            } else {
                E::Time
            },
        ))),
        (LiteralKind::Date(_), p) => Ok(LitType::Known(Type::Elementary(long_or(p, E::Date)))),
        (LiteralKind::TimeOfDay(_), p) => Ok(LitType::Known(Type::Elementary(long_or(p, E::Tod)))),
        (LiteralKind::DateAndTime(_), p) => Ok(LitType::Known(Type::Elementary(long_or(p, E::Dt)))),
        // edition 3's typed characters: `CHAR#'A'`, `WCHAR#"A"` (one character; a CHAR's up
        // to U+00FF)
        (LiteralKind::String { value, .. }, Some((name, Some(e)))) if e.is_char() => {
            let mut cs = value.chars();
            match (cs.next(), cs.next()) {
                (Some(c), None) if e == E::Wchar || u32::from(c) <= 0xFF => {
                    Ok(LitType::Known(Type::Elementary(e)))
                }
                (Some(c), None) => Err(LitError {
                    message: format!("`{c}` is no single-byte character for CHAR"),
                    hint: "a CHAR holds U+0000-U+00FF; use WCHAR#\"...\" for other characters"
                        .into(),
                }),
                _ => Err(LitError {
                    message: format!(
                        "a {} literal holds exactly one character, `{value}` has {}",
                        name.to_ascii_uppercase(),
                        value.chars().count()
                    ),
                    hint: "write one character, e.g. CHAR#'A', or CHAR#'$00' for NUL; use a STRING for text"
                        .into(),
                }),
            }
        }
        (LiteralKind::String { wide, value }, None) if value.chars().count() == 1 => {
            Ok(LitType::Char(*wide))
        }
        (LiteralKind::String { wide, value }, _) => Ok(LitType::Known(Type::String {
            wide: *wide,
            len: value.chars().count().max(1) as u32,
        })),
        (_, Some((name, None))) => Err(LitError {
            message: format!("unknown literal type prefix `{name}#`"),
            hint: "use an elementary type name such as INT#, REAL#, BOOL#".into(),
        }),
    }
}

/// The smallest signed (or unsigned) type holding `v`, for hints.
pub fn wider_for(v: i128) -> &'static str {
    for e in [E::Sint, E::Int, E::Dint, E::Lint, E::Ulint] {
        if let Some((lo, hi)) = e.int_range() {
            if v >= lo && v <= hi {
                return e.name();
            }
        }
    }
    "LREAL"
}

/// The first character of a single-byte STRING's text beyond U+00FF (ISO 8859-1 holds U+0000-U+00FF,
/// one byte each) and how many such characters the text holds; `None` when every one fits.
pub fn beyond_single_byte(text: &str) -> Option<(char, usize)> {
    let mut wide = text.chars().filter(|&c| u32::from(c) > 0xFF);
    let first = wide.next()?;
    Some((first, 1 + wide.count()))
}

/// The constant value of a literal, converted to `ty` where the literal is an untyped number.
pub fn literal_value(lit: &Literal, ty: &Type) -> ConstValue {
    match &lit.kind {
        LiteralKind::Int(v) if ty.is_real() => ConstValue::Real(*v as f64),
        LiteralKind::Int(v) if ty.is_bool() => ConstValue::Bool(*v != 0),
        LiteralKind::Int(v) => ConstValue::Int(*v),
        LiteralKind::Real(r) => ConstValue::Real(*r),
        LiteralKind::Bool(b) => ConstValue::Bool(*b),
        LiteralKind::Duration(d) => ConstValue::Duration(*d),
        LiteralKind::Date(d) => ConstValue::Date(*d),
        LiteralKind::TimeOfDay(t) => ConstValue::TimeOfDay(*t),
        LiteralKind::DateAndTime(t) => ConstValue::DateAndTime(*t),
        // edition 3's characters: their code
        LiteralKind::String { value, .. } if ty.elementary().is_some_and(|e| e.is_char()) => {
            ConstValue::Int(value.chars().next().map_or(0, |c| i128::from(u32::from(c))))
        }
        LiteralKind::String { wide, value } => ConstValue::String {
            wide: *wide,
            value: value.clone(),
        },
    }
}

/// Why an untyped literal cannot take a type.
pub enum FitError {
    /// Wrong kind of type (a real literal for INT, an integer literal for TIME).
    Kind,
    /// Right kind, value out of range: the offending value.
    Range(i128),
}

/// Whether untyped integer literals with values `min..=max` (or a real literal) can take type `ty`.
/// Integer literals take any ANY_INT/ANY_BIT type holding the value (BOOL: 0 and 1) and any ANY_REAL.
pub fn literal_fits(min: i128, max: i128, real: bool, ty: &Type) -> Result<(), FitError> {
    if ty.is_error() {
        return Ok(());
    }
    if let Type::Subrange { lower, upper, .. } = ty {
        if real {
            return Err(FitError::Kind);
        }
        return if min < **lower {
            Err(FitError::Range(min))
        } else if max > **upper {
            Err(FitError::Range(max))
        } else {
            Ok(())
        };
    }
    let Some(e) = ty.elementary() else {
        return Err(FitError::Kind);
    };
    if e.is_real() {
        return Ok(());
    }
    if real {
        return Err(FitError::Kind);
    }
    match e.int_range() {
        Some((lo, hi)) => {
            if min < lo {
                Err(FitError::Range(min))
            } else if max > hi {
                Err(FitError::Range(max))
            } else {
                Ok(())
            }
        }
        None => Err(FitError::Kind),
    }
}

/// The default type of an untyped literal that no context fixed: DINT (LINT, ULINT if too big), LREAL.
pub fn literal_default(min: i128, max: i128, real: bool) -> Type {
    if real {
        return Type::LREAL;
    }
    for e in [E::Dint, E::Lint, E::Ulint] {
        if literal_fits(min, max, false, &Type::Elementary(e)).is_ok() {
            return Type::Elementary(e);
        }
    }
    Type::Elementary(E::Lint)
}

/// Untyped-literal type variables: a union-find over literal occurrences whose type a context fixes.
#[derive(Debug, Default)]
pub struct LitVars {
    parent: Vec<usize>,
    info: Vec<LitInfo>,
}

#[derive(Debug, Clone)]
struct LitInfo {
    min: i128,
    max: i128,
    real: bool,
    /// The class is the result of an integer division of integer literals (`LD 7` / `DIV 2`):
    /// IEC 61131-3 makes it an integer (ANY_INT), so it never becomes a real type; stored into a
    /// real it takes the smallest integer type that widens to it.
    int_only: bool,
    bound: Option<Type>,
    /// The literals holding the smallest and the largest value, for diagnostics.
    min_span: Span,
    max_span: Span,
    /// The largest magnitude of the class's real literals (0 without any) and the literal holding it.
    real_max: f64,
    real_span: Span,
    /// An untyped one-character string literal (`'A'`: `Some(false)`, `"A"`: `Some(true)`): a
    /// STRING (WSTRING), or edition 3's CHAR (WCHAR) where one is expected.
    chars: Option<bool>,
}

impl LitInfo {
    /// A class of one literal at `span`: value 0, not real, no bound (the constructors of
    /// [`LitVars`] set what their literal gives).
    fn at(span: Span) -> Self {
        LitInfo {
            min: 0,
            max: 0,
            real: false,
            int_only: false,
            bound: None,
            min_span: span,
            max_span: span,
            real_max: 0.0,
            real_span: span,
            chars: None,
        }
    }
}

/// Whether a real value of magnitude `magnitude` fits `ty` without becoming an infinity: every value
/// fits LREAL (the literal parser already rejects the rest), REAL holds up to 3.4028235E38.
pub fn real_fits(magnitude: f64, ty: &Type) -> bool {
    ty.elementary() != Some(E::Real) || magnitude.is_nan() || magnitude <= f64::from(f32::MAX)
}

/// Result of trying to fix a literal variable's type.
pub enum BindError {
    /// The type is of the wrong kind for the literals (a real literal for an integer type, an integer
    /// literal for a string ...).
    Kind {
        /// One of the literals of the class.
        span: Span,
    },
    /// A real literal of the class is beyond REAL's range (`1.0E300` for a REAL).
    RealRange {
        /// The literal.
        span: Span,
    },
    /// A literal of the class does not fit the type's range (`300` for a SINT).
    Range {
        /// The value that does not fit.
        value: i128,
        /// The literal holding it.
        span: Span,
    },
}

impl LitVars {
    /// A new variable for an untyped integer literal of value `v` at `span`; returns its index.
    pub fn new_int(&mut self, v: i128, span: Span) -> usize {
        self.push(LitInfo {
            min: v,
            max: v,
            ..LitInfo::at(span)
        })
    }
    /// A new variable for an untyped real literal of value `v` at `span`; returns its index.
    pub fn new_real(&mut self, v: f64, span: Span) -> usize {
        self.push(LitInfo {
            real: true,
            real_max: v.abs(),
            ..LitInfo::at(span)
        })
    }
    /// A new variable for an untyped one-character string literal (`wide`: `"A"`); returns its
    /// index.
    pub fn new_char(&mut self, wide: bool, span: Span) -> usize {
        self.push(LitInfo {
            chars: Some(wide),
            ..LitInfo::at(span)
        })
    }
    /// Whether `v`'s class is a one-character string literal.
    pub fn is_chars(&mut self, v: usize) -> bool {
        let r = self.find(v);
        self.info[r].chars.is_some()
    }
    fn push(&mut self, i: LitInfo) -> usize {
        self.parent.push(self.parent.len());
        self.info.push(i);
        self.parent.len() - 1
    }
    /// The representative of `v`'s class (union-find with path compression).
    pub fn find(&mut self, v: usize) -> usize {
        let mut r = v;
        while self.parent[r] != r {
            r = self.parent[r];
        }
        let mut c = v;
        while self.parent[c] != r {
            let n = self.parent[c];
            self.parent[c] = r;
            c = n;
        }
        r
    }
    /// The type the variable was bound to.
    pub fn bound(&mut self, v: usize) -> Option<Type> {
        let r = self.find(v);
        self.info[r].bound.clone()
    }
    /// Whether `v`'s class holds a real literal (then only ANY_REAL types fit).
    pub fn is_real(&mut self, v: usize) -> bool {
        let r = self.find(v);
        self.info[r].real
    }
    /// Marks `v`'s class as an integer division of integer literals (see `LitInfo::int_only`).
    pub fn set_int_only(&mut self, v: usize) {
        let r = self.find(v);
        self.info[r].int_only = true;
    }
    /// Fixes the type of an unbound variable (checks that every literal of the class fits). A class
    /// of integer division (`int_only`) asked to be a real type gets the smallest of INT, DINT,
    /// LINT that holds its literals and widens to that real type.
    pub fn bind(&mut self, v: usize, ty: &Type) -> Result<(), BindError> {
        let r = self.find(v);
        let i = &self.info[r];
        if i.int_only && i.bound.is_none() && !i.real {
            if let Some(real) = ty.elementary().filter(|e| e.is_real()) {
                let int = [E::Int, E::Dint, E::Lint].into_iter().find(|&e| {
                    widens(e, real)
                        && literal_fits(i.min, i.max, false, &Type::Elementary(e)).is_ok()
                });
                return match int {
                    Some(e) => {
                        self.info[r].bound = Some(Type::Elementary(e));
                        Ok(())
                    }
                    None => Err(BindError::Kind { span: i.min_span }),
                };
            }
        }
        if let Some(b) = &i.bound {
            return if assignable(b, ty) {
                Ok(())
            } else {
                Err(BindError::Kind { span: i.min_span })
            };
        }
        if let Some(wide) = i.chars {
            // a string of its kind, or (edition 3) the character of its kind
            let fits = match ty {
                Type::String { wide: w, .. } => *w == wide,
                Type::Error => true,
                t => t.elementary() == Some(if wide { E::Wchar } else { E::Char }),
            };
            if !fits {
                return Err(BindError::Kind { span: i.min_span });
            }
            self.info[r].bound = Some(ty.clone());
            return Ok(());
        }
        if !real_fits(i.real_max, ty) {
            return Err(BindError::RealRange { span: i.real_span });
        }
        match literal_fits(i.min, i.max, i.real, ty) {
            Ok(()) => {
                self.info[r].bound = Some(ty.clone());
                Ok(())
            }
            Err(FitError::Kind) => Err(BindError::Kind { span: i.min_span }),
            Err(FitError::Range(value)) => Err(BindError::Range {
                value,
                span: if value == i.min {
                    i.min_span
                } else {
                    i.max_span
                },
            }),
        }
    }
    /// Merges two unbound classes (a real literal makes the class real).
    pub fn unify(&mut self, a: usize, b: usize) -> usize {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return ra;
        }
        let ib = self.info[rb].clone();
        let ia = &mut self.info[ra];
        if ib.min < ia.min {
            ia.min = ib.min;
            ia.min_span = ib.min_span;
        }
        if ib.max > ia.max {
            ia.max = ib.max;
            ia.max_span = ib.max_span;
        }
        ia.real |= ib.real;
        if ib.real_max > ia.real_max {
            ia.real_max = ib.real_max;
            ia.real_span = ib.real_span;
        }
        ia.int_only |= ib.int_only;
        ia.chars = ia.chars.or(ib.chars);
        if ia.bound.is_none() {
            ia.bound = ib.bound;
        }
        self.parent[rb] = ra;
        ra
    }
    /// The final type: the bound one or the default.
    pub fn resolve(&mut self, v: usize) -> Type {
        let r = self.find(v);
        let i = &self.info[r];
        match (&i.bound, i.chars) {
            (Some(b), _) => b.clone(),
            (None, Some(wide)) => Type::String { wide, len: 1 },
            (None, None) => literal_default(i.min, i.max, i.real),
        }
    }
    /// Human description ("an integer literal").
    pub fn describe(&mut self, v: usize) -> &'static str {
        if self.is_chars(v) {
            "a string literal"
        } else if self.is_real(v) {
            "a real literal"
        } else {
            "an integer literal"
        }
    }
}
