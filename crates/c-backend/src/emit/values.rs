//! C expressions for IEC values: conversions between elementary types and process-image access.
//!
//! Input: C expressions with their IEC types, located places. Output: C expressions of the requested
//! type. Invariants: integer conversions wrap without implementation-defined casts, REAL to integer
//! conversions saturate through the runtime, located data is read and written through the byte-order
//! aware `ladderc_load`/`ladderc_store` helpers; every expression is fully parenthesised.

use crate::ctypes;
use crate::profile::Located;
use il_frontend::ast::Area;
use il_frontend::sema::{Elementary, Type};
use std::borrow::Cow;

use Elementary as E;

/// Size in bytes used to access a located variable of type `ty` (None: not an elementary type).
pub fn access_bytes(ty: &Type) -> Option<u32> {
    let e = match ty {
        Type::Enum(_) => return Some(4),
        _ => ty.elementary()?,
    };
    Some(e.size_bytes())
}

/// The bytes a located variable of type `ty` at an address of size `size` takes: an elementary
/// type's (or an enumeration's) width, or for an array of them (at a byte, word, double or long
/// word address, never a bit) its elements' widths times their number, a BOOL element one byte
/// (as CODESYS and TwinCAT lay out `ARRAY OF BOOL AT %MB`). `None`: no layout in the process
/// image (structures, strings, blocks, arrays of them, more than 4 GiB).
pub fn located_bytes(ty: &Type, size: il_frontend::ast::AddressSize) -> Option<u32> {
    match ty {
        Type::Array { dims, element } if size != il_frontend::ast::AddressSize::Bit => {
            let each = if element.is_bool() {
                1
            } else {
                access_bytes(element)?
            };
            let count = dims.iter().try_fold(1u128, |n, d| n.checked_mul(d.len()))?;
            u32::try_from(count.checked_mul(u128::from(each))?).ok()
        }
        Type::Array { .. } => None,
        _ => access_bytes(ty),
    }
}

pub fn area_array(area: Area) -> &'static str {
    match area {
        Area::Input => "ladderc_I",
        Area::Output => "ladderc_Q",
        Area::Memory => "ladderc_M",
    }
}

/// Converts a C expression of IEC type `from` to IEC type `to` (implicit conversions: widening, BOOL).
pub fn convert(expr: &str, from: &Type, to: &Type) -> String {
    if let Some(s) = char_as_string(expr, from, to) {
        return s;
    }
    match conversion(from, to) {
        Some((f, t)) => convert_elementary(expr, f, t),
        None => expr.to_string(),
    }
}

/// [`convert`] that borrows `expr` when its text stays.
pub fn convert_cow<'e>(expr: &'e str, from: &Type, to: &Type) -> Cow<'e, str> {
    if let Some(s) = char_as_string(expr, from, to) {
        return Cow::Owned(s);
    }
    match conversion(from, to) {
        Some((f, t)) if f != t => Cow::Owned(convert_elementary(expr, f, t)),
        _ => Cow::Borrowed(expr),
    }
}

/// [`convert`] of an expression the caller gives away: returned as it is (no copy) when its text
/// stays.
pub fn convert_owned(expr: String, from: &Type, to: &Type) -> String {
    if let Some(s) = char_as_string(&expr, from, to) {
        return s;
    }
    match conversion(from, to) {
        Some((f, t)) if f != t => convert_elementary(&expr, f, t),
        _ => expr,
    }
}

/// A CHAR (WCHAR) where a string is expected (sema allows it in edition 3's CONCAT only): its
/// one-character STRING (WSTRING).
fn char_as_string(expr: &str, from: &Type, to: &Type) -> Option<String> {
    let Type::String { wide, .. } = to else {
        return None;
    };
    Some(match (from.elementary()?, wide) {
        (E::Char, false) => cfmt!("ladderc_char_to_str({expr})"),
        (E::Char, true) => cfmt!("ladderc_wchar_to_wstr((IEC_WCHAR)({expr}))"),
        (E::Wchar, true) => cfmt!("ladderc_wchar_to_wstr({expr})"),
        (E::Wchar, false) => cfmt!("ladderc_char_to_str(ladderc_wchar_to_char({expr}))"),
        _ => return None,
    })
}

/// The elementary types [`convert`] converts between; `None` when the text stays.
fn conversion(from: &Type, to: &Type) -> Option<(Elementary, Elementary)> {
    if from == to {
        return None;
    }
    let fe = match from {
        Type::Enum(_) => Some(E::Dint),
        t => t.elementary(),
    };
    let te = match to {
        Type::Enum(_) => Some(E::Dint),
        t => t.elementary(),
    };
    // otherwise strings keep their text here (capacities apply when a string is stored), and so
    // does anything that is not elementary on one side
    fe.zip(te)
}

/// `X_TO_Y` semantics: integers wrap to the target width, REAL to integer rounds to nearest (halves
/// to even) and saturates, LREAL to REAL overflows to an infinity, TIME and LTIME to/from numbers
/// count the profile's unit (milliseconds by default; a real number to TIME rounds to whole
/// milliseconds there, LTIME keeps nanoseconds: `TimeNumberUnit::rounds_real_to_time`), TOD milliseconds, DT and DATE seconds since 1970-01-01 (a number to DATE keeps the seconds
/// below a day, see [`within_day`]), anything to BOOL is `<> 0`.
pub fn convert_elementary(x: &str, f: Elementary, t: Elementary) -> String {
    if f == t {
        return x.to_string();
    }
    let ct = ctypes::elementary(t);
    let time_like = |e: Elementary| e.is_duration() || e.is_date();
    if (f, t) == (E::Wchar, E::Char) {
        // a code a CHAR cannot hold: '?' (as WSTRING_TO_STRING), and the range flag
        return cfmt!("ladderc_wchar_to_char({x})");
    }
    if t == E::Bool {
        return cfmt!("((IEC_BOOL)(({x}) != 0))");
    }
    if f.is_real() {
        if f == E::Lreal && t == E::Real {
            return cfmt!("ladderc_lreal_to_real({x})");
        }
        if t.is_real() {
            return cfmt!("(({ct})({x}))");
        }
        if t == E::Time {
            // a whole number of milliseconds under "ms" (`ladderc_real_to_time`)
            return cfmt!("ladderc_real_to_time((double)({x}))");
        }
        if time_like(t) {
            let (_, unit_real) = number_unit(t);
            return within_day(
                &cfmt!("(({ct})ladderc_real_to_int((double)({x}) * {unit_real}, INT64_MIN, INT64_MAX))"),
                t,
            );
        }
        return real_to_int(&cfmt!("(double)({x})"), t);
    }
    if time_like(f) {
        if time_like(t) {
            // the same point of the time line from 1970-01-01-00:00 (`stdlib::conversion_allowed`):
            // to a date its day, to a time of day its time of day (a DATE's is midnight, a TOD's
            // and a duration's day 1970-01-01); the rest keeps its nanoseconds (TIME <-> LTIME,
            // DATE, TOD or TIME to DT, DT to TIME ...)
            return match t.date_kind() {
                Some(E::Date) if f.date_kind() != Some(E::Date) => {
                    cfmt!("ladderc_dt_to_date({x})")
                }
                Some(E::Tod) if f.date_kind() != Some(E::Tod) => cfmt!("ladderc_dt_to_tod({x})"),
                _ => cfmt!("(({ct})({x}))"),
            };
        }
        let (unit, unit_real) = number_unit(f);
        if t.is_real() {
            return cfmt!("(({ct})((double)({x}) / {unit_real}))");
        }
        return int_to_int(&cfmt!("(({x}) / {unit})"), t);
    }
    // f is an integer, a bit string or BOOL
    if t.is_real() {
        return cfmt!("(({ct})({x}))");
    }
    if time_like(t) {
        let (unit, _) = number_unit(t);
        return within_day(
            &cfmt!("(({ct})ladderc_mul_IEC_LINT((IEC_LINT)({x}), {unit}))"),
            t,
        );
    }
    int_to_int(x, t)
}

/// A number converted to TOD (LTOD) keeps the time of day (modulo one day), as a TOD variable
/// holds nothing else. A number converted to DATE (LDATE) keeps all of its seconds (nanoseconds),
/// the part below a whole day too: CODESYS and TwinCAT store a DATE as a DWORD of seconds since
/// 1970-01-01 and their `<number>_TO_DATE` copies the number into it (Beckhoff infosys, "DATE/DT_TO_<type>":
/// "TwinCAT saves the date internally in a DWORD in seconds since 1 January 1970"; CODESYS online
/// help, date and time conversion operators: DATE and DT use the same memory format, a DWORD),
/// so `UINT_TO_DATE(35) > UINT_TO_DATE(0)` and `DATE_TO_UDINT(UDINT_TO_DATE(115))` is 115
/// (IEC 61131-3 leaves these conversions to the implementation). A date's time line conversions
/// (`DT_TO_DATE`, `TIME_TO_DATE`) keep only the day ([`convert_elementary`]).
fn within_day(ns: &str, t: Elementary) -> String {
    match t.date_kind() {
        Some(E::Tod) => cfmt!("ladderc_dt_to_tod({ns})"),
        _ => ns.to_string(),
    }
}

/// The nanoseconds of one unit of the number a duration or date converts to and from: for TIME
/// and LTIME the target profile's unit (`LADDERC_TIME_UNIT_NS` of `ladderc_config.h`: milliseconds,
/// as CODESYS, TwinCAT and OSCAT count them, or seconds, as matiec, under `--profile openplc`;
/// IEC 61131-3 leaves it open); milliseconds for TOD, seconds for DT and DATE (since 1970-01-01),
/// as CODESYS, TwinCAT and OSCAT count them (`DT_TO_UDINT`, `TOD_TO_DWORD(t) / 3600000` for the
/// hour); nanoseconds for edition 3's LDATE, LTOD and LDT (IEC 61131-3 edition 3, Table 10: their
/// value is in nanoseconds); as a C integer and as a C double.
fn number_unit(e: Elementary) -> (&'static str, &'static str) {
    match e {
        E::Dt | E::Date => ("INT64_C(1000000000)", "1e9"),
        E::Ldate | E::Ltod | E::Ldt => ("INT64_C(1)", "1.0"),
        E::Time | E::Ltime => ("LADDERC_TIME_UNIT_NS", "((double)LADDERC_TIME_UNIT_NS)"),
        _ => ("INT64_C(1000000)", "1e6"),
    }
}

fn int_to_int(x: &str, t: Elementary) -> String {
    let ct = ctypes::elementary(t);
    match t.bit_width() {
        8 if t.is_signed() => cfmt!("ladderc_wrap_i8((uint64_t)({x}))"),
        16 if t.is_signed() => cfmt!("ladderc_wrap_i16((uint64_t)({x}))"),
        32 if t.is_signed() => cfmt!("ladderc_wrap_i32((uint64_t)({x}))"),
        64 if t.is_signed() => cfmt!("ladderc_wrap_i64((uint64_t)({x}))"),
        _ => cfmt!("(({ct})(uint64_t)({x}))"),
    }
}

/// A double expression to an integer or bit-string type (rounded to nearest, saturated).
pub fn real_to_int(d: &str, t: Elementary) -> String {
    let ct = ctypes::elementary(t);
    if t.is_signed_integer() {
        let (lo, hi) = match t.bit_width() {
            8 => ("INT8_MIN", "INT8_MAX"),
            16 => ("INT16_MIN", "INT16_MAX"),
            32 => ("INT32_MIN", "INT32_MAX"),
            _ => ("INT64_MIN", "INT64_MAX"),
        };
        cfmt!("(({ct})ladderc_real_to_int({d}, {lo}, {hi}))")
    } else {
        let hi = match t.bit_width() {
            1 => "1",
            8 => "UINT8_MAX",
            16 => "UINT16_MAX",
            32 => "UINT32_MAX",
            _ => "UINT64_MAX",
        };
        cfmt!("(({ct})ladderc_real_to_uint({d}, {hi}))")
    }
}

/// Loads a located value of type `ty`.
pub fn load_expr(loc: &Located, at: Option<&str>, ty: &Type) -> String {
    let area = area_array(loc.area);
    if let Some(bit) = loc.bit {
        let v = cfmt!("ladderc_load_bit({area}, {}, {bit})", loc.offset);
        return if ty.is_bool() {
            v
        } else {
            convert(&v, &Type::BOOL, ty)
        };
    }
    let raw = cfmt!(
        "ladderc_load({area}, {}, {})",
        byte_offset(loc, at),
        loc.bytes
    );
    let e = match ty {
        Type::Enum(_) => E::Dint,
        t => t.elementary().unwrap_or(E::Lword),
    };
    match e {
        E::Bool => cfmt!("((IEC_BOOL)({raw} != 0))"),
        E::Real => cfmt!("ladderc_bits_to_real((uint32_t){raw})"),
        E::Lreal => cfmt!("ladderc_bits_to_lreal({raw})"),
        _ => int_to_int(&raw, e),
    }
}

/// Stores `value` (of type `ty`) into a located place.
pub fn store_expr(loc: &Located, at: Option<&str>, ty: &Type, value: &str) -> String {
    let area = area_array(loc.area);
    if let Some(bit) = loc.bit {
        let v = if ty.is_bool() {
            value.to_string()
        } else {
            cfmt!("((IEC_BOOL)(({value}) != 0))")
        };
        return cfmt!("ladderc_store_bit({area}, {}, {bit}, {v});", loc.offset);
    }
    let e = ty.elementary().unwrap_or(E::Dint);
    let raw = match e {
        E::Real => cfmt!("(uint64_t)ladderc_real_to_bits({value})"),
        E::Lreal => cfmt!("ladderc_lreal_to_bits({value})"),
        _ => cfmt!("(uint64_t)({value})"),
    };
    cfmt!(
        "ladderc_store({area}, {}, {}, {raw});",
        byte_offset(loc, at),
        loc.bytes
    )
}

/// The C offset of a located place: the address's, plus an array element's (`at`).
fn byte_offset(loc: &Located, at: Option<&str>) -> String {
    match at {
        None => loc.offset.to_string(),
        Some(at) => cfmt!("(uint32_t)({}u + {at})", loc.offset),
    }
}
