//! C spellings of IEC types and constant values.
//!
//! Input: resolved [`Type`]s and [`ConstValue`]s from the sema model. Output: C type names, declarators,
//! literal expressions of an exact C type. Invariants: every literal is emitted with an explicit cast or
//! suffix of its IEC type's C type, integer literals never overflow their C spelling (the most negative
//! values are written as `(-MAX - 1)`), reals are written in round-trip precision.

use crate::mangle;
use il_frontend::sema::{ConstValue, Elementary, FbType, Model, StdFb, Type};

use Elementary as E;

/// The runtime typedef of an elementary type.
pub fn elementary(e: Elementary) -> &'static str {
    match e {
        E::Bool => "IEC_BOOL",
        E::Sint => "IEC_SINT",
        E::Int => "IEC_INT",
        E::Dint => "IEC_DINT",
        E::Lint => "IEC_LINT",
        E::Usint => "IEC_USINT",
        E::Uint => "IEC_UINT",
        E::Udint => "IEC_UDINT",
        E::Ulint => "IEC_ULINT",
        E::Byte => "IEC_BYTE",
        E::Word => "IEC_WORD",
        E::Dword => "IEC_DWORD",
        E::Lword => "IEC_LWORD",
        E::Real => "IEC_REAL",
        E::Lreal => "IEC_LREAL",
        E::Time => "IEC_TIME",
        E::Ltime => "IEC_LTIME",
        E::Date => "IEC_DATE",
        E::Tod => "IEC_TOD",
        E::Dt => "IEC_DT",
        E::Ldate => "IEC_LDATE",
        E::Ltod => "IEC_LTOD",
        E::Ldt => "IEC_LDT",
        E::Char => "IEC_CHAR",
        E::Wchar => "IEC_WCHAR",
    }
}

/// The harness's type tag (`LADDERC_T_INT`).
pub fn type_tag(e: Elementary) -> &'static str {
    match e {
        E::Bool => "LADDERC_T_BOOL",
        E::Sint => "LADDERC_T_SINT",
        E::Int => "LADDERC_T_INT",
        E::Dint => "LADDERC_T_DINT",
        E::Lint => "LADDERC_T_LINT",
        E::Usint => "LADDERC_T_USINT",
        E::Uint => "LADDERC_T_UINT",
        E::Udint => "LADDERC_T_UDINT",
        E::Ulint => "LADDERC_T_ULINT",
        E::Byte => "LADDERC_T_BYTE",
        E::Word => "LADDERC_T_WORD",
        E::Dword => "LADDERC_T_DWORD",
        E::Lword => "LADDERC_T_LWORD",
        E::Real => "LADDERC_T_REAL",
        E::Lreal => "LADDERC_T_LREAL",
        E::Time => "LADDERC_T_TIME",
        E::Ltime => "LADDERC_T_LTIME",
        E::Date => "LADDERC_T_DATE",
        E::Tod => "LADDERC_T_TOD",
        E::Dt => "LADDERC_T_DT",
        E::Ldate => "LADDERC_T_LDATE",
        E::Ltod => "LADDERC_T_LTOD",
        E::Ldt => "LADDERC_T_LDT",
        E::Char => "LADDERC_T_CHAR",
        E::Wchar => "LADDERC_T_WCHAR",
    }
}

/// The runtime type whose ordering helpers (`ladderc_gt_<T>`) compare values of `e`.
pub fn ordered_helper_type(e: Elementary) -> &'static str {
    match e {
        E::Bool | E::Usint | E::Byte | E::Char => "IEC_USINT",
        E::Uint | E::Word | E::Wchar => "IEC_UINT",
        E::Udint | E::Dword => "IEC_UDINT",
        E::Ulint | E::Lword => "IEC_ULINT",
        E::Sint => "IEC_SINT",
        E::Int => "IEC_INT",
        E::Dint => "IEC_DINT",
        E::Real => "IEC_REAL",
        E::Lreal => "IEC_LREAL",
        E::Lint | E::Time | E::Ltime | E::Date | E::Tod | E::Dt | E::Ldate | E::Ltod | E::Ldt => {
            "IEC_LINT"
        }
    }
}

/// The runtime type whose wrapping arithmetic (`ladderc_add_<T>`) applies to `e` (None: plain C operators,
/// for REAL/LREAL).
pub fn arith_helper_type(e: Elementary) -> Option<&'static str> {
    match e {
        E::Real | E::Lreal => None,
        E::Bool | E::Usint | E::Byte | E::Char => Some("IEC_USINT"),
        E::Uint | E::Word | E::Wchar => Some("IEC_UINT"),
        E::Udint | E::Dword => Some("IEC_UDINT"),
        E::Ulint | E::Lword => Some("IEC_ULINT"),
        E::Sint => Some("IEC_SINT"),
        E::Int => Some("IEC_INT"),
        E::Dint => Some("IEC_DINT"),
        E::Lint | E::Time | E::Ltime | E::Date | E::Tod | E::Dt | E::Ldate | E::Ltod | E::Ldt => {
            Some("IEC_LINT")
        }
    }
}

const fn ctu(t: Elementary) -> [(&'static str, Elementary, bool); 5] {
    [
        ("CU", E::Bool, true),
        ("R", E::Bool, true),
        ("PV", t, true),
        ("Q", E::Bool, false),
        ("CV", t, false),
    ]
}
const fn ctd(t: Elementary) -> [(&'static str, Elementary, bool); 5] {
    [
        ("CD", E::Bool, true),
        ("LD", E::Bool, true),
        ("PV", t, true),
        ("Q", E::Bool, false),
        ("CV", t, false),
    ]
}
const fn ctud(t: Elementary) -> [(&'static str, Elementary, bool); 8] {
    [
        ("CU", E::Bool, true),
        ("CD", E::Bool, true),
        ("R", E::Bool, true),
        ("LD", E::Bool, true),
        ("PV", t, true),
        ("QU", E::Bool, false),
        ("QD", E::Bool, false),
        ("CV", t, false),
    ]
}

/// A standard FB's runtime struct and its public parameters `(name, type, is_input)` in IEC order.
pub fn std_fb(fb: StdFb) -> (&'static str, &'static [(&'static str, Elementary, bool)]) {
    const TRIG: &[(&str, E, bool)] = &[("CLK", E::Bool, true), ("Q", E::Bool, false)];
    const TIMER: &[(&str, E, bool)] = &[
        ("IN", E::Bool, true),
        ("PT", E::Time, true),
        ("Q", E::Bool, false),
        ("ET", E::Time, false),
    ];
    const LTIMER: &[(&str, E, bool)] = &[
        ("IN", E::Bool, true),
        ("PT", E::Ltime, true),
        ("Q", E::Bool, false),
        ("ET", E::Ltime, false),
    ];
    match fb {
        StdFb::RTrig => ("ladderc_R_TRIG", TRIG),
        StdFb::FTrig => ("ladderc_F_TRIG", TRIG),
        StdFb::Sr => (
            "ladderc_SR",
            &[
                ("S1", E::Bool, true),
                ("R", E::Bool, true),
                ("Q1", E::Bool, false),
            ],
        ),
        StdFb::Rs => (
            "ladderc_RS",
            &[
                ("S", E::Bool, true),
                ("R1", E::Bool, true),
                ("Q1", E::Bool, false),
            ],
        ),
        StdFb::Ton => ("ladderc_TON", TIMER),
        StdFb::Tof => ("ladderc_TOF", TIMER),
        StdFb::Tp => ("ladderc_TP", TIMER),
        StdFb::TonLtime => ("ladderc_TON_LTIME", LTIMER),
        StdFb::TofLtime => ("ladderc_TOF_LTIME", LTIMER),
        StdFb::TpLtime => ("ladderc_TP_LTIME", LTIMER),
        StdFb::Ctu => ("ladderc_CTU", &const { ctu(E::Int) }),
        StdFb::Ctd => ("ladderc_CTD", &const { ctd(E::Int) }),
        StdFb::Ctud => ("ladderc_CTUD", &const { ctud(E::Int) }),
        StdFb::CtuDint => ("ladderc_CTU_DINT", &const { ctu(E::Dint) }),
        StdFb::CtuLint => ("ladderc_CTU_LINT", &const { ctu(E::Lint) }),
        StdFb::CtuUdint => ("ladderc_CTU_UDINT", &const { ctu(E::Udint) }),
        StdFb::CtuUlint => ("ladderc_CTU_ULINT", &const { ctu(E::Ulint) }),
        StdFb::CtdDint => ("ladderc_CTD_DINT", &const { ctd(E::Dint) }),
        StdFb::CtdLint => ("ladderc_CTD_LINT", &const { ctd(E::Lint) }),
        StdFb::CtdUdint => ("ladderc_CTD_UDINT", &const { ctd(E::Udint) }),
        StdFb::CtdUlint => ("ladderc_CTD_ULINT", &const { ctd(E::Ulint) }),
        StdFb::CtudDint => ("ladderc_CTUD_DINT", &const { ctud(E::Dint) }),
        StdFb::CtudLint => ("ladderc_CTUD_LINT", &const { ctud(E::Lint) }),
        StdFb::CtudUdint => ("ladderc_CTUD_UDINT", &const { ctud(E::Udint) }),
        StdFb::CtudUlint => ("ladderc_CTUD_ULINT", &const { ctud(E::Ulint) }),
        StdFb::CtuWord => ("ladderc_CTU_WORD", &const { ctu(E::Word) }),
        StdFb::CtdWord => ("ladderc_CTD_WORD", &const { ctd(E::Word) }),
        StdFb::CtudWord => ("ladderc_CTUD_WORD", &const { ctud(E::Word) }),
    }
}

/// The C base type of `ty` (arrays: the element's), or `None` for `Type::Error`.
pub fn base(model: &Model, ty: &Type) -> Option<String> {
    let mut s = String::new();
    push_base(model, ty, &mut s).then_some(s)
}

/// Appends [`base`] of `ty` to `out`; `false` (nothing appended) where `base` is `None`.
pub fn push_base(model: &Model, ty: &Type, out: &mut String) -> bool {
    match ty {
        Type::Elementary(e) | Type::Subrange { base: e, .. } => out.push_str(elementary(*e)),
        Type::String { wide: false, .. } => out.push_str("IEC_STRING"),
        Type::String { wide: true, .. } => out.push_str("IEC_WSTRING"),
        Type::Array { element, .. } => return push_base(model, element, out),
        Type::Struct(id) => out.push_str(&mangle::user_type(&model.user_type(*id).name)),
        Type::Enum(_) => out.push_str("IEC_DINT"),
        Type::Fb(FbType::Standard(f)) => out.push_str(std_fb(*f).0),
        Type::Fb(FbType::User(id)) => out.push_str(&mangle::fb(&model.pou(*id).name)),
        // a reference: the address of its variable (see `emit::refs`)
        Type::Ref(_) => out.push_str("IEC_REF"),
        Type::Error => return false,
    }
    true
}

/// `[n1][n2]` for arrays (nested arrays flatten into more dimensions), empty otherwise.
pub fn dims(ty: &Type) -> String {
    let mut s = String::new();
    push_dims(ty, &mut s);
    s
}

/// Appends [`dims`] of `ty` to `out`.
pub fn push_dims(ty: &Type, out: &mut String) {
    let mut t = ty;
    while let Type::Array { dims, element } = t {
        for d in dims {
            out.push_str(&format!("[{}]", d.len().max(1)));
        }
        t = element;
    }
}

/// A declaration `T name[dims]` (without the semicolon).
pub fn declare(model: &Model, ty: &Type, name: &str) -> Option<String> {
    Some(format!("{} {name}{}", base(model, ty)?, dims(ty)))
}

/// An integer constant as a C expression of type `e` (wrapped into the type's range). The wrapped value
/// fits 64 bits and is printed as one (`i128` formatting costs several times more).
pub fn int_literal(e: Elementary, v: i128) -> String {
    let ct = elementary(e);
    match e {
        E::Bool => (if v != 0 { "1" } else { "0" }).to_string(),
        E::Real => cfmt!("((IEC_REAL){v}.0)"),
        E::Lreal => cfmt!("((IEC_LREAL){v}.0)"),
        E::Usint
        | E::Uint
        | E::Udint
        | E::Ulint
        | E::Byte
        | E::Word
        | E::Dword
        | E::Lword
        | E::Char
        | E::Wchar => {
            let bits = e.bit_width();
            let masked = (v as u128)
                & if bits >= 64 {
                    u64::MAX as u128
                } else {
                    (1u128 << bits) - 1
                };
            crate::cat(&["((", ct, ")UINT64_C(", &(masked as u64).to_string(), "))"])
        }
        _ => {
            let bits = e.bit_width().min(64);
            let m = (v as u128)
                & if bits >= 64 {
                    u64::MAX as u128
                } else {
                    (1u128 << bits) - 1
                };
            // sign-extend from `bits`
            let sv = if bits < 128 && m >> (bits - 1) & 1 == 1 {
                m as i128 - (1i128 << bits)
            } else {
                m as i128
            };
            if sv == i64::MIN as i128 {
                cfmt!("(({ct})(-INT64_C(9223372036854775807) - 1))")
            } else if sv < 0 {
                crate::cat(&["((", ct, ")-INT64_C(", &((-sv) as i64).to_string(), "))"])
            } else {
                crate::cat(&["((", ct, ")INT64_C(", &(sv as i64).to_string(), "))"])
            }
        }
    }
}

/// A real constant of type `e` (REAL or LREAL; other types get the value converted like a literal).
pub fn real_literal(e: Elementary, v: f64) -> String {
    let text = if v.is_finite() {
        let t = format!("{v:?}");
        if t.contains(['.', 'e', 'E']) {
            t
        } else {
            format!("{t}.0")
        }
    } else if v.is_nan() {
        "(0.0/0.0)".into()
    } else if v > 0.0 {
        "HUGE_VAL".into()
    } else {
        "(-HUGE_VAL)".into()
    };
    match e {
        E::Real => format!("((IEC_REAL){text})"),
        E::Lreal => format!("((IEC_LREAL){text})"),
        _ if e.is_integer() || e.is_bit() => int_literal(e, v.round() as i128),
        _ => format!("(({}){text})", elementary(e)),
    }
}

/// A constant as a C expression of elementary type `e` (None when the value does not fit such a type).
pub fn const_elementary(model: &Model, e: Elementary, v: &ConstValue) -> Option<String> {
    Some(match v {
        ConstValue::Bool(b) => int_literal(e, i128::from(*b)),
        ConstValue::Int(i) => {
            if e.is_real() {
                real_literal(e, *i as f64)
            } else if e.is_duration() && i.unsigned_abs() <= 9_000_000_000 {
                // an integer written for a TIME: the profile's unit (`LADDERC_TIME_UNIT_NS`,
                // milliseconds or seconds), as the conversions count; 9e9 s still fit 64 bits
                cfmt!("((IEC_LINT)INT64_C({i}) * LADDERC_TIME_UNIT_NS)")
            } else if e.is_duration() {
                int_literal(E::Lint, i.saturating_mul(1_000_000))
            } else {
                int_literal(e, *i)
            }
        }
        ConstValue::Real(r) => real_literal(e, *r),
        ConstValue::Duration(ns) | ConstValue::DateAndTime(ns) => int_literal(e, *ns),
        ConstValue::TimeOfDay(ns) => int_literal(e, i128::from(*ns)),
        ConstValue::Date(days) => int_literal(e, i128::from(*days) * 86_400_000_000_000),
        ConstValue::Enum { ty, index } => {
            let value = enum_value(model, *ty, *index)?;
            int_literal(e, value)
        }
        ConstValue::String { .. }
        | ConstValue::Array(_)
        | ConstValue::Struct(_)
        | ConstValue::Address(_) => return None,
    })
}

/// The integer value of the `index`-th enumerator of enum type `ty`.
pub fn enum_value(model: &Model, ty: il_frontend::sema::TypeId, index: usize) -> Option<i128> {
    match &model.types.get(ty.0 as usize)?.def {
        il_frontend::sema::UserTypeDef::Enum { values, .. } => values.get(index).map(|v| v.1),
        _ => None,
    }
}

/// The bytes of a STRING's text: one per character, its ISO 8859-1 code (U+0000-U+00FF, as CODESYS
/// stores a STRING); a character beyond U+00FF (sema's W1416) is `?`.
pub fn single_bytes(value: &str) -> Vec<u8> {
    value
        .chars()
        .map(|c| u8::try_from(u32::from(c)).unwrap_or(b'?'))
        .collect()
}

/// A string literal as an `IEC_STRING` value expression.
pub fn string_value(value: &str) -> String {
    let bytes = single_bytes(value);
    format!(
        "ladderc_str_lit({}, {})",
        mangle::c_string(&bytes),
        bytes.len()
    )
}

/// UTF-16 code units of a text as a C compound literal array and its length (`{0}` for empty text, so
/// that no null pointer is ever passed).
pub fn utf16_array(value: &str) -> (String, usize) {
    let units: Vec<u16> = value.encode_utf16().collect();
    if units.is_empty() {
        return ("(const uint16_t[]){0}".into(), 0);
    }
    let list: Vec<String> = units.iter().map(|u| format!("0x{u:04X}")).collect();
    (
        format!("(const uint16_t[]){{{}}}", list.join(", ")),
        units.len(),
    )
}

/// A literal as an `IEC_WSTRING` value expression.
pub fn wstring_value(value: &str) -> String {
    let (array, len) = utf16_array(value);
    format!("ladderc_wstr_lit({array}, {len})")
}

/// The capacity of a string type (bytes), capped at the runtime's.
pub fn string_cap(ty: &Type) -> u32 {
    match ty {
        Type::String { len, .. } => (*len).clamp(1, 254),
        _ => 254,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_literals_wrap_and_never_overflow_c() {
        assert_eq!(int_literal(E::Int, 5), "((IEC_INT)INT64_C(5))");
        assert_eq!(int_literal(E::Int, 32768), "((IEC_INT)-INT64_C(32768))");
        assert_eq!(int_literal(E::Int, -32768), "((IEC_INT)-INT64_C(32768))");
        assert_eq!(
            int_literal(E::Lint, i64::MIN as i128),
            "((IEC_LINT)(-INT64_C(9223372036854775807) - 1))"
        );
        assert_eq!(int_literal(E::Word, -1), "((IEC_WORD)UINT64_C(65535))");
        assert_eq!(int_literal(E::Bool, 7), "1");
    }

    #[test]
    fn real_literals_round_trip() {
        assert_eq!(real_literal(E::Lreal, 23.6), "((IEC_LREAL)23.6)");
        assert_eq!(real_literal(E::Real, 1.0), "((IEC_REAL)1.0)");
        assert_eq!(real_literal(E::Lreal, -12e-5), "((IEC_LREAL)-0.00012)");
    }
}
