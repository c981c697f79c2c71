//! Bit strings counted as unsigned integers (CODESYS, TwinCAT): `n := coeffsCount - 1` of a BYTE,
//! `FOR i := 1 TO 5 DO` of a BYTE `i`, `PolyEval(p, degree, x)` passing a BYTE to an INT input,
//! `udint = word` (a comparison with a number; between bit strings they stay bit strings).
//!
//! IEC 61131-3 (ed. 3, 6.4.2 and Table 22) gives bit strings (BYTE, WORD, DWORD, LWORD) no arithmetic
//! and requires ANY_INT for a FOR control variable; CODESYS and TwinCAT count them as the unsigned
//! integer of the same width (BYTE as USINT, WORD as UINT, DWORD as UDINT, LWORD as ULINT), wrapping
//! around exactly as that type. ladderc does so, with one W1436 per POU (another IEC compiler refuses
//! the text). BOOL is no number here: its arithmetic stays E1004.
//!
//! Input: the types an arithmetic operator, a numeric standard function or an assignment sees.
//! Output: the unsigned type to count with, and W1436 once per POU. Invariant: a value only changes
//! type between types of one width (BYTE and USINT are both 8-bit unsigned in the generated C), or
//! widens from the unsigned type as IEC allows (USINT to INT).

use super::body::Body;
use super::model::{Elementary, Type};
use super::stdlib::Class;
use super::typing::widens;
use crate::Span;
use diagnostics::code;
use Elementary as E;

/// The unsigned integer a bit string counts as (`BYTE` -> `USINT`); `None` for other types and BOOL.
pub(super) fn counted_as(e: Elementary) -> Option<Elementary> {
    match e {
        E::Byte => Some(E::Usint),
        E::Word => Some(E::Uint),
        E::Dword => Some(E::Udint),
        E::Lword => Some(E::Ulint),
        _ => None,
    }
}

/// Whether a generic input of class `c` is arithmetic (a bit string in it counts as unsigned).
pub(super) fn is_arithmetic(c: Class) -> bool {
    matches!(c, Class::AnyNum | Class::AnyInt)
}

/// Whether `f` is a comparison (GT GE EQ NE LE LT): beside a number, a bit string compares as
/// its unsigned integer (`udint = word` as UDINT), as it counts in arithmetic and is stored.
pub(super) fn is_comparison(f: &str) -> bool {
    matches!(f, "GT" | "GE" | "EQ" | "NE" | "LE" | "LT")
}

/// Whether a value of `from` may be stored into `to` when bit strings count as unsigned integers:
/// a bit string into an integer or real its unsigned integer widens to (`BYTE` into `INT`), an
/// unsigned integer into a bit string of the same width or wider (`USINT` into `BYTE`).
pub(super) fn assignable_counted(from: &Type, to: &Type) -> bool {
    let (Some(f), Some(t)) = (from.elementary(), to.elementary()) else {
        return false;
    };
    if let Some(u) = counted_as(f) {
        if !t.is_bit() && widens(u, t) {
            return true;
        }
    }
    if let Some(u) = counted_as(t) {
        if f.is_unsigned_integer() && widens(f, u) {
            return true;
        }
    }
    false
}

impl Body<'_, '_> {
    /// W1436 at `at`, once per POU: the bit string `bits` counted as its unsigned integer.
    pub(super) fn bit_string_counted(&mut self, bits: Elementary, at: Span) {
        if self.a.silent || !self.a.counting_bit_string_pous.insert(self.pou) {
            return;
        }
        let b = bits.name();
        let u = counted_as(bits).map_or("an unsigned integer", Elementary::name);
        self.a
            .warning(
                code::W1436,
                at,
                format!("{b} counted as the unsigned integer {u}: IEC 61131-3 gives bit strings no arithmetic (its other uses in this POU are not reported)"),
            )
            .label(format!("this is {b}"))
            .hint(format!("compiled as CODESYS and TwinCAT do ({b} wraps around as {u}); declare the variable {u} for another IEC compiler"));
    }

    /// W1438 at `at`, once per POU: the integer `int` given to the bit-string function `f` (`AND`,
    /// `SHL` ...), which works on its bit pattern of the same width.
    pub(super) fn integer_as_bits(&mut self, f: &str, int: Elementary, at: Span) {
        if self.a.silent || !self.a.integer_bits_pous.insert(self.pou) {
            return;
        }
        let i = int.name();
        let b = bits_of(int).map_or("a bit string", Elementary::name);
        self.a
            .warning(
                code::W1438,
                at,
                format!("{f} of {i}: IEC 61131-3 defines bit-string functions for ANY_BIT only (its other uses in this POU are not reported)"),
            )
            .label(format!("this is {i}"))
            .hint(format!("compiled as CODESYS and TwinCAT do, on the {i}'s bit pattern as {b}; convert with {i}_TO_{b} for another IEC compiler"));
    }
}

/// The inputs of a bit-string function (`AND`, `OR`, `XOR`) that mix an integer and bit strings
/// no wider than it (`udint OR byte`, KimRo's Blowfish `SHL(data, 8) OR (key[j] AND 16#FF)`):
/// the bit strings widen into the integer's bit pattern (BYTE into DWORD, IEC 61131-3 ed. 3's
/// implicit bit-string widening, zero-filled) and take its type, so that the function works on
/// the integer's bits and gives that integer, as for an integer alone (W1438: CODESYS and
/// TwinCAT). A bit string wider than the integer (`int AND dword`: the integer would have to be
/// sign- or zero-extended) and integers without a common type are left as written (E1005).
pub(super) fn bits_beside_integer(known: &mut [(Type, Span)]) {
    let elementary: Vec<Option<Elementary>> = known.iter().map(|k| k.0.elementary()).collect();
    let Some(Some(int)) = elementary
        .iter()
        .find(|e| e.is_some_and(|e| bits_of(e).is_some()))
    else {
        return;
    };
    let Some(pattern) = bits_of(*int) else {
        return;
    };
    let fits = elementary.iter().all(|e| match e {
        Some(e) if *e == *int => true,
        Some(e) if e.is_bit() && *e != E::Bool => e.size_bytes() <= pattern.size_bytes(),
        _ => false,
    });
    let has_bits = elementary
        .iter()
        .any(|e| e.is_some_and(|e| e.is_bit() && e != E::Bool));
    if !fits || !has_bits {
        return;
    }
    for k in known.iter_mut() {
        k.0 = Type::Elementary(*int);
    }
}

/// The bit string of an integer's width (`INT` and `UINT` -> `WORD`); `None` for other types.
pub(super) fn bits_of(e: Elementary) -> Option<Elementary> {
    match e {
        E::Sint | E::Usint => Some(E::Byte),
        E::Int | E::Uint => Some(E::Word),
        E::Dint | E::Udint => Some(E::Dword),
        E::Lint | E::Ulint => Some(E::Lword),
        _ => None,
    }
}
