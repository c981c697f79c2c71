//! The resolved model that `sema` produces: the contract read by the C backend and the other back ends.
//!
//! Input: nothing (plain data). Output: [`Model`]: user types, POUs with their resolved variables,
//! configurations, global variables, and per-instruction typing/resolution keyed by the instruction's span.
//! Invariants: a [`PouId`] indexes `Model::pous` (source order over all units); a [`TypeId`] indexes
//! `Model::types`; aliases are resolved (no `Type` names an alias); when the analysis reported no error, no
//! `Type` in the model is [`Type::Error`] and every current-result type is concrete (untyped literals were
//! given the type their context fixed, else the default `DINT`/`LREAL`, see README_sema.md).

use crate::ast::{AddressSize, Area, DirectAddress, PouKind, VarKind};
use crate::Span;
use rustc_hash::{FxHashMap, FxHashSet};
use serde::Serialize;

/// Index of a POU in [`Model::pous`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct PouId(pub u32);

/// Index of a user data type in [`Model::types`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct TypeId(pub u32);

/// The elementary types of IEC 61131-3.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub enum Elementary {
    /// `BOOL`: one bit, FALSE/TRUE.
    Bool,
    /// `SINT`: 8-bit signed integer.
    Sint,
    /// `INT`: 16-bit signed integer.
    Int,
    /// `DINT`: 32-bit signed integer (the default type of an untyped integer literal).
    Dint,
    /// `LINT`: 64-bit signed integer.
    Lint,
    /// `USINT`: 8-bit unsigned integer.
    Usint,
    /// `UINT`: 16-bit unsigned integer.
    Uint,
    /// `UDINT`: 32-bit unsigned integer.
    Udint,
    /// `ULINT`: 64-bit unsigned integer.
    Ulint,
    /// `BYTE`: bit string of 8.
    Byte,
    /// `WORD`: bit string of 16.
    Word,
    /// `DWORD`: bit string of 32.
    Dword,
    /// `LWORD`: bit string of 64.
    Lword,
    /// `REAL`: 32-bit IEEE 754 float.
    Real,
    /// `LREAL`: 64-bit IEEE 754 float (the default type of an untyped real literal).
    Lreal,
    /// `TIME`: a duration, stored in nanoseconds.
    Time,
    /// `LTIME`: a long duration, stored in nanoseconds.
    Ltime,
    /// `DATE`: a calendar date, stored as days since 1970-01-01.
    Date,
    /// `TOD` / `TIME_OF_DAY`: nanoseconds since midnight.
    Tod,
    /// `DT` / `DATE_AND_TIME`: nanoseconds since 1970-01-01T00:00:00.
    Dt,
    /// `LDATE` (IEC 61131-3 edition 3): a calendar date, nanoseconds since 1970-01-01 (its
    /// midnight); as a number, nanoseconds.
    Ldate,
    /// `LTOD` / `LTIME_OF_DAY` (edition 3): nanoseconds since midnight; as a number, nanoseconds.
    Ltod,
    /// `LDT` / `LDATE_AND_TIME` (edition 3): nanoseconds since 1970-01-01T00:00:00; as a number,
    /// nanoseconds.
    Ldt,
    /// `CHAR` (IEC 61131-3 edition 3, Table 10): a single-byte character (ISO 8859-1, as a
    /// STRING's characters here), its code 0..255.
    Char,
    /// `WCHAR` (edition 3): a double-byte character (UCS-2, as a WSTRING's), its code 0..65535.
    Wchar,
}

use Elementary as E;

impl Elementary {
    /// Every elementary type, in declaration order.
    pub const ALL: [Elementary; 25] = [
        E::Bool,
        E::Sint,
        E::Int,
        E::Dint,
        E::Lint,
        E::Usint,
        E::Uint,
        E::Udint,
        E::Ulint,
        E::Byte,
        E::Word,
        E::Dword,
        E::Lword,
        E::Real,
        E::Lreal,
        E::Time,
        E::Ltime,
        E::Date,
        E::Tod,
        E::Dt,
        E::Ldate,
        E::Ltod,
        E::Ldt,
        E::Char,
        E::Wchar,
    ];

    /// The canonical IEC name (`TOD`, `DT`: the short forms).
    pub fn name(self) -> &'static str {
        match self {
            E::Bool => "BOOL",
            E::Sint => "SINT",
            E::Int => "INT",
            E::Dint => "DINT",
            E::Lint => "LINT",
            E::Usint => "USINT",
            E::Uint => "UINT",
            E::Udint => "UDINT",
            E::Ulint => "ULINT",
            E::Byte => "BYTE",
            E::Word => "WORD",
            E::Dword => "DWORD",
            E::Lword => "LWORD",
            E::Real => "REAL",
            E::Lreal => "LREAL",
            E::Time => "TIME",
            E::Ltime => "LTIME",
            E::Date => "DATE",
            E::Tod => "TOD",
            E::Dt => "DT",
            E::Ldate => "LDATE",
            E::Ltod => "LTOD",
            E::Ldt => "LDT",
            E::Char => "CHAR",
            E::Wchar => "WCHAR",
        }
    }

    /// Looks up a type name, case-insensitively; accepts the long forms `TIME_OF_DAY`, `DATE_AND_TIME`.
    pub fn from_name(name: &str) -> Option<Elementary> {
        if name.eq_ignore_ascii_case("TIME_OF_DAY") {
            return Some(E::Tod);
        }
        if name.eq_ignore_ascii_case("DATE_AND_TIME") {
            return Some(E::Dt);
        }
        if name.eq_ignore_ascii_case("LTIME_OF_DAY") {
            return Some(E::Ltod);
        }
        if name.eq_ignore_ascii_case("LDATE_AND_TIME") {
            return Some(E::Ldt);
        }

        Elementary::ALL
            .into_iter()
            .find(|e| e.name().eq_ignore_ascii_case(name))
    }

    /// Storage size in bits (BOOL: 1; TIME: 64 (nanoseconds); DATE/TOD/DT: 64).
    pub fn bit_width(self) -> u32 {
        match self {
            E::Bool => 1,
            E::Sint | E::Usint | E::Byte | E::Char => 8,
            E::Int | E::Uint | E::Word | E::Wchar => 16,
            E::Dint | E::Udint | E::Dword | E::Real => 32,
            E::Lint | E::Ulint | E::Lword | E::Lreal => 64,
            E::Time | E::Ltime | E::Date | E::Tod | E::Dt | E::Ldate | E::Ltod | E::Ldt => 64,
        }
    }
    /// Storage size in bytes (BOOL: 1).
    pub fn size_bytes(self) -> u32 {
        self.bit_width().div_ceil(8)
    }
    /// SINT INT DINT LINT (and REAL LREAL TIME LTIME, which are signed too).
    pub fn is_signed(self) -> bool {
        matches!(
            self,
            E::Sint | E::Int | E::Dint | E::Lint | E::Real | E::Lreal | E::Time | E::Ltime
        )
    }
    /// ANY_INT: signed and unsigned integers.
    pub fn is_integer(self) -> bool {
        matches!(
            self,
            E::Sint | E::Int | E::Dint | E::Lint | E::Usint | E::Uint | E::Udint | E::Ulint
        )
    }
    /// ANY_SINT: SINT INT DINT LINT.
    pub fn is_signed_integer(self) -> bool {
        matches!(self, E::Sint | E::Int | E::Dint | E::Lint)
    }
    /// ANY_UNSIGNED: USINT UINT UDINT ULINT.
    pub fn is_unsigned_integer(self) -> bool {
        matches!(self, E::Usint | E::Uint | E::Udint | E::Ulint)
    }
    /// ANY_REAL.
    pub fn is_real(self) -> bool {
        matches!(self, E::Real | E::Lreal)
    }
    /// ANY_NUM = ANY_INT + ANY_REAL.
    pub fn is_numeric(self) -> bool {
        self.is_integer() || self.is_real()
    }
    /// ANY_BIT = BOOL BYTE WORD DWORD LWORD.
    pub fn is_bit(self) -> bool {
        matches!(self, E::Bool | E::Byte | E::Word | E::Dword | E::Lword)
    }
    /// ANY_DURATION = TIME LTIME.
    pub fn is_duration(self) -> bool {
        matches!(self, E::Time | E::Ltime)
    }
    /// ANY_DATE = DATE TOD DT LDATE LTOD LDT.
    pub fn is_date(self) -> bool {
        matches!(self, E::Date | E::Tod | E::Dt | E::Ldate | E::Ltod | E::Ldt)
    }
    /// The edition-2 type a date type holds the same kind of value as: DATE for DATE and LDATE,
    /// TOD for TOD and LTOD, DT for DT and LDT (`None` for the others). Both are stored alike
    /// (nanoseconds); they differ in the number they convert to (see `stdlib::conversion_allowed`).
    pub fn date_kind(self) -> Option<Elementary> {
        match self {
            E::Date | E::Ldate => Some(E::Date),
            E::Tod | E::Ltod => Some(E::Tod),
            E::Dt | E::Ldt => Some(E::Dt),
            _ => None,
        }
    }
    /// ANY_CHAR = CHAR WCHAR (edition 3).
    pub fn is_char(self) -> bool {
        matches!(self, E::Char | E::Wchar)
    }
    /// LDATE, LTOD, LDT: the date types whose number is nanoseconds.
    pub fn is_long_date(self) -> bool {
        matches!(self, E::Ldate | E::Ltod | E::Ldt)
    }
    /// The value range of an integer type (`None` for other types); BYTE..LWORD give their unsigned range.
    pub fn int_range(self) -> Option<(i128, i128)> {
        Some(match self {
            E::Sint => (i8::MIN as i128, i8::MAX as i128),
            E::Int => (i16::MIN as i128, i16::MAX as i128),
            E::Dint => (i32::MIN as i128, i32::MAX as i128),
            E::Lint => (i64::MIN as i128, i64::MAX as i128),
            E::Usint | E::Byte => (0, u8::MAX as i128),
            E::Uint | E::Word => (0, u16::MAX as i128),
            E::Udint | E::Dword => (0, u32::MAX as i128),
            E::Ulint | E::Lword => (0, u64::MAX as i128),
            E::Bool => (0, 1),
            _ => return None,
        })
    }
}

impl std::fmt::Display for Elementary {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The IEC standard function blocks (see `stdlib::fb_params` for their inputs and outputs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum StdFb {
    /// `R_TRIG`: Q is TRUE for one call when CLK rises.
    RTrig,
    /// `F_TRIG`: Q is TRUE for one call when CLK falls.
    FTrig,
    /// `SR`: set-dominant bistable (S1, R -> Q1).
    Sr,
    /// `RS`: reset-dominant bistable (S, R1 -> Q1).
    Rs,
    /// `TON`: on-delay timer (IN, PT -> Q, ET).
    Ton,
    /// `TOF`: off-delay timer (IN, PT -> Q, ET).
    Tof,
    /// `TP`: pulse timer (IN, PT -> Q, ET).
    Tp,
    /// CTU (counter on INT, PV: INT, CV: INT).
    Ctu,
    /// `CTD`: down counter on INT (CD, LD, PV -> Q, CV).
    Ctd,
    /// `CTUD`: up/down counter on INT (CU, CD, R, LD, PV -> QU, QD, CV).
    Ctud,
    /// The typed counters of edition 2/3: `CTU_DINT` ... `CTUD_ULINT` (PV and CV of that type).
    CtuDint,
    /// `CTU_LINT`: CTU with PV and CV of type LINT (count up on CU).
    CtuLint,
    /// `CTU_UDINT`: CTU with PV and CV of type UDINT (count up on CU).
    CtuUdint,
    /// `CTU_ULINT`: CTU with PV and CV of type ULINT (count up on CU).
    CtuUlint,
    /// `CTD_DINT`: CTD with PV and CV of type DINT (count down on CD).
    CtdDint,
    /// `CTD_LINT`: CTD with PV and CV of type LINT (count down on CD).
    CtdLint,
    /// `CTD_UDINT`: CTD with PV and CV of type UDINT (count down on CD).
    CtdUdint,
    /// `CTD_ULINT`: CTD with PV and CV of type ULINT (count down on CD).
    CtdUlint,
    /// `CTUD_DINT`: CTUD with PV and CV of type DINT (count up on CU and down on CD).
    CtudDint,
    /// `CTUD_LINT`: CTUD with PV and CV of type LINT (count up on CU and down on CD).
    CtudLint,
    /// `CTUD_UDINT`: CTUD with PV and CV of type UDINT (count up on CU and down on CD).
    CtudUdint,
    /// `CTUD_ULINT`: CTUD with PV and CV of type ULINT (count up on CU and down on CD).
    CtudUlint,
    /// `CTU` of CODESYS's Standard and TwinCAT's Tc2_Standard library, with PV and CV of type WORD
    /// (Beckhoff Infosys, Tc2_Standard > CTU: `PV : WORD`, `CV : WORD`): the CTU of a CODESYS or
    /// TwinCAT file ([`StdFb::in_vendor_file`]); its name is `CTU`.
    CtuWord,
    /// `CTD` of CODESYS's Standard and TwinCAT's Tc2_Standard library (PV and CV of type WORD; CV
    /// counts down while greater than 0, Infosys Tc2_Standard > CTD); its name is `CTD`.
    CtdWord,
    /// `CTUD` of CODESYS's Standard and TwinCAT's Tc2_Standard library (PV and CV of type WORD);
    /// its name is `CTUD`.
    CtudWord,
    /// `TON_LTIME` (edition 3 Table 46; CODESYS's and TwinCAT's `LTON`): TON with PT and ET of type LTIME.
    TonLtime,
    /// `TOF_LTIME` (edition 3 Table 46; CODESYS's and TwinCAT's `LTOF`): TOF with PT and ET of type LTIME.
    TofLtime,
    /// `TP_LTIME` (edition 3 Table 46; CODESYS's and TwinCAT's `LTP`): TP with PT and ET of type LTIME.
    TpLtime,
}

impl StdFb {
    /// Every standard function block, in declaration order.
    pub const ALL: [StdFb; 28] = [
        StdFb::RTrig,
        StdFb::FTrig,
        StdFb::Sr,
        StdFb::Rs,
        StdFb::Ton,
        StdFb::Tof,
        StdFb::Tp,
        StdFb::Ctu,
        StdFb::Ctd,
        StdFb::Ctud,
        StdFb::CtuDint,
        StdFb::CtuLint,
        StdFb::CtuUdint,
        StdFb::CtuUlint,
        StdFb::CtdDint,
        StdFb::CtdLint,
        StdFb::CtdUdint,
        StdFb::CtdUlint,
        StdFb::CtudDint,
        StdFb::CtudLint,
        StdFb::CtudUdint,
        StdFb::CtudUlint,
        StdFb::CtuWord,
        StdFb::CtdWord,
        StdFb::CtudWord,
        StdFb::TonLtime,
        StdFb::TofLtime,
        StdFb::TpLtime,
    ];
    /// The IEC name, upper case (`R_TRIG`, `CTU_DINT`; the INT counters are `CTU`, `CTD`, `CTUD`).
    pub fn name(self) -> &'static str {
        match self {
            StdFb::RTrig => "R_TRIG",
            StdFb::FTrig => "F_TRIG",
            StdFb::Sr => "SR",
            StdFb::Rs => "RS",
            StdFb::Ton => "TON",
            StdFb::Tof => "TOF",
            StdFb::Tp => "TP",
            StdFb::Ctu => "CTU",
            StdFb::Ctd => "CTD",
            StdFb::Ctud => "CTUD",
            StdFb::CtuDint => "CTU_DINT",
            StdFb::CtuLint => "CTU_LINT",
            StdFb::CtuUdint => "CTU_UDINT",
            StdFb::CtuUlint => "CTU_ULINT",
            StdFb::CtdDint => "CTD_DINT",
            StdFb::CtdLint => "CTD_LINT",
            StdFb::CtdUdint => "CTD_UDINT",
            StdFb::CtdUlint => "CTD_ULINT",
            StdFb::CtudDint => "CTUD_DINT",
            StdFb::CtudLint => "CTUD_LINT",
            StdFb::CtudUdint => "CTUD_UDINT",
            StdFb::CtudUlint => "CTUD_ULINT",
            StdFb::CtuWord => "CTU",
            StdFb::CtdWord => "CTD",
            StdFb::CtudWord => "CTUD",
            StdFb::TonLtime => "TON_LTIME",
            StdFb::TofLtime => "TOF_LTIME",
            StdFb::TpLtime => "TP_LTIME",
        }
    }
    /// For a counter, its kind (up, down, up/down) and the type of PV and CV.
    pub fn counter(self) -> Option<(CounterKind, Elementary)> {
        use CounterKind::{Down, Up, UpDown};
        use Elementary as E;
        Some(match self {
            StdFb::Ctu => (Up, E::Int),
            StdFb::CtuDint => (Up, E::Dint),
            StdFb::CtuLint => (Up, E::Lint),
            StdFb::CtuUdint => (Up, E::Udint),
            StdFb::CtuUlint => (Up, E::Ulint),
            StdFb::Ctd => (Down, E::Int),
            StdFb::CtdDint => (Down, E::Dint),
            StdFb::CtdLint => (Down, E::Lint),
            StdFb::CtdUdint => (Down, E::Udint),
            StdFb::CtdUlint => (Down, E::Ulint),
            StdFb::Ctud => (UpDown, E::Int),
            StdFb::CtudDint => (UpDown, E::Dint),
            StdFb::CtudLint => (UpDown, E::Lint),
            StdFb::CtudUdint => (UpDown, E::Udint),
            StdFb::CtudUlint => (UpDown, E::Ulint),
            StdFb::CtuWord => (Up, E::Word),
            StdFb::CtdWord => (Down, E::Word),
            StdFb::CtudWord => (UpDown, E::Word),
            _ => return None,
        })
    }
    /// For a timer, its family (`TON`, `TOF`, `TP`) and whether PT and ET are LTIME.
    pub fn timer(self) -> Option<(StdFb, bool)> {
        Some(match self {
            StdFb::Ton | StdFb::Tof | StdFb::Tp => (self, false),
            StdFb::TonLtime => (StdFb::Ton, true),
            StdFb::TofLtime => (StdFb::Tof, true),
            StdFb::TpLtime => (StdFb::Tp, true),
            _ => return None,
        })
    }
    /// The other names of standard FBs: edition 3's `CTU_INT`, `CTD_INT`, `CTUD_INT` (the INT
    /// counters) and `TON_TIME`, `TOF_TIME`, `TP_TIME` (the TIME timers), and the names CODESYS's
    /// Standard64 and TwinCAT's Tc2_Standard give the LTIME timers, `LTON`, `LTOF`, `LTP`
    /// ([`StdFb::is_vendor_name`]).
    const ALIASES: [(&'static str, StdFb); 9] = [
        ("CTU_INT", StdFb::Ctu),
        ("CTD_INT", StdFb::Ctd),
        ("CTUD_INT", StdFb::Ctud),
        ("TON_TIME", StdFb::Ton),
        ("TOF_TIME", StdFb::Tof),
        ("TP_TIME", StdFb::Tp),
        ("LTON", StdFb::TonLtime),
        ("LTOF", StdFb::TofLtime),
        ("LTP", StdFb::TpLtime),
    ];
    /// `LTON`, `LTOF`, `LTP`: names of standard FBs that are a vendor library's, not IEC 61131-3's;
    /// they stay free for variables (`ltp : REAL`) and a project's own block of such a name is no
    /// W1446.
    pub fn is_vendor_name(name: &str) -> bool {
        ["LTON", "LTOF", "LTP"]
            .iter()
            .any(|n| n.eq_ignore_ascii_case(name))
    }
    /// The block a CODESYS or TwinCAT file means by this one: the WORD counters of CODESYS's
    /// Standard and TwinCAT's Tc2_Standard library for `CTU`, `CTD`, `CTUD` (Beckhoff Infosys,
    /// Tc2_Standard > CTU, CTD, CTUD: `PV : WORD`, `CV : WORD`; CODESYS online help, Standard
    /// library > CTU likewise); any other block is itself (`CTU_INT` stays IEC's INT counter).
    pub fn in_vendor_file(self) -> StdFb {
        match self {
            StdFb::Ctu => StdFb::CtuWord,
            StdFb::Ctd => StdFb::CtdWord,
            StdFb::Ctud => StdFb::CtudWord,
            other => other,
        }
    }
    /// Case-insensitive lookup; `CTU_INT` etc. map to the INT counters, `TON_TIME` etc. to the TIME
    /// timers, `LTON` etc. to the LTIME timers.
    pub fn from_name(name: &str) -> Option<StdFb> {
        if let Some(&(_, f)) = Self::ALIASES
            .iter()
            .find(|(a, _)| a.eq_ignore_ascii_case(name))
        {
            return Some(f);
        }
        StdFb::ALL
            .into_iter()
            .find(|f| f.name().eq_ignore_ascii_case(name))
    }
}

/// The three counter families (CTU, CTD, CTUD), whatever their count type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum CounterKind {
    /// CTU, CTU_*: counts up on CU, Q when CV >= PV.
    Up,
    /// CTD, CTD_*: counts down on CD, Q when CV <= 0.
    Down,
    /// CTUD, CTUD_*: both, with QU and QD.
    UpDown,
}

/// The type of an FB instance.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum FbType {
    /// One of the IEC standard function blocks (`TON`, `CTU` ...).
    Standard(StdFb),
    /// A user `FUNCTION_BLOCK` of the model.
    User(PouId),
}

/// A resolved type.
///
/// `Clone` and `PartialEq` are written out (the same as derived): their elementary case, nearly every
/// type a body's instructions carry, is inlined where they are used; the rest is out of line. The
/// equality is the derived one (equal variants with equal fields), so the derived `Hash` agrees with it.
#[allow(clippy::derived_hash_with_manual_eq)]
#[derive(Debug, Eq, Hash, Serialize)]
pub enum Type {
    /// `BOOL`, `INT`, `TIME` ...
    Elementary(Elementary),
    /// `STRING[len]` / `WSTRING[len]`; an unsized declaration has the target profile's default
    /// `len` ([`default_string_len`]: 80 unless the profile says otherwise).
    String {
        /// `WSTRING` (UTF-16) rather than `STRING` (bytes).
        wide: bool,
        /// The capacity in characters.
        len: u32,
    },
    /// `ARRAY [l..u, ...] OF element`.
    Array {
        /// The dimensions in order.
        dims: Vec<Dim>,
        /// The element type.
        element: Box<Type>,
    },
    /// A user structure (`Model::types[id]` is a `UserTypeDef::Struct`).
    Struct(TypeId),
    /// A user enumeration (named, or an inline `(a, b)` given a synthetic entry in `Model::types`).
    Enum(TypeId),
    /// `INT (0..100)`: a subrange of an integer type (named subranges are resolved to this). The bounds
    /// are boxed: subranges are rare, and unboxed `i128`s would make every `Type` (three in each
    /// instruction's facts) 48 bytes instead of 32.
    Subrange {
        /// The integer type the subrange restricts.
        base: Elementary,
        /// The smallest allowed value (inclusive).
        lower: Box<i128>,
        /// The largest allowed value (inclusive).
        upper: Box<i128>,
    },
    /// An FB instance.
    Fb(FbType),
    /// A reference to a variable of the boxed type (`REF_TO T`, `POINTER TO T`, `REFERENCE TO T`): in C
    /// the variable's address, or NULL. NULL itself (`NULL`, a pointer's `0`) is a reference to
    /// [`Type::Error`], which fits every reference type.
    Ref(Box<Type>),
    /// Stands for a type sema could not determine (a diagnostic was reported); silences follow-on errors.
    Error,
}

impl Clone for Type {
    #[inline]
    fn clone(&self) -> Type {
        match self {
            Type::Elementary(e) => Type::Elementary(*e),
            other => other.clone_other(),
        }
    }
}

impl PartialEq for Type {
    #[inline]
    fn eq(&self, other: &Type) -> bool {
        match (self, other) {
            (Type::Elementary(a), Type::Elementary(b)) => a == b,
            (Type::Elementary(_), _) | (_, Type::Elementary(_)) => false,
            _ => self.eq_other(other),
        }
    }
}

impl Type {
    /// [`Clone::clone`] of the cases other than [`Type::Elementary`].
    #[inline(never)]
    fn clone_other(&self) -> Type {
        match self {
            Type::Elementary(e) => Type::Elementary(*e),
            Type::String { wide, len } => Type::String {
                wide: *wide,
                len: *len,
            },
            Type::Array { dims, element } => Type::Array {
                dims: dims.clone(),
                element: element.clone(),
            },
            Type::Struct(id) => Type::Struct(*id),
            Type::Enum(id) => Type::Enum(*id),
            Type::Subrange { base, lower, upper } => Type::Subrange {
                base: *base,
                lower: lower.clone(),
                upper: upper.clone(),
            },
            Type::Fb(f) => Type::Fb(*f),
            Type::Ref(t) => Type::Ref(t.clone()),
            Type::Error => Type::Error,
        }
    }
    /// [`PartialEq::eq`]: equal variants with equal fields.
    #[inline(never)]
    fn eq_other(&self, other: &Type) -> bool {
        match (self, other) {
            (Type::Elementary(a), Type::Elementary(b)) => a == b,
            (
                Type::String { wide, len },
                Type::String {
                    wide: wide2,
                    len: len2,
                },
            ) => wide == wide2 && len == len2,
            (
                Type::Array { dims, element },
                Type::Array {
                    dims: dims2,
                    element: element2,
                },
            ) => dims == dims2 && element == element2,
            (Type::Struct(a), Type::Struct(b)) | (Type::Enum(a), Type::Enum(b)) => a == b,
            (
                Type::Subrange { base, lower, upper },
                Type::Subrange {
                    base: base2,
                    lower: lower2,
                    upper: upper2,
                },
            ) => base == base2 && lower == lower2 && upper == upper2,
            (Type::Fb(a), Type::Fb(b)) => a == b,
            (Type::Ref(a), Type::Ref(b)) => a == b,
            (Type::Error, Type::Error) => true,
            _ => false,
        }
    }
}

/// One array dimension `lower..upper` (inclusive).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub struct Dim {
    /// The first index (inclusive).
    pub lower: i128,
    /// The last index (inclusive).
    pub upper: i128,
}

impl Dim {
    /// The number of elements (saturating).
    pub fn len(self) -> u128 {
        if self.upper < self.lower {
            0
        } else {
            self.upper.abs_diff(self.lower).saturating_add(1)
        }
    }
    /// Whether the dimension has no elements (`upper < lower`).
    pub fn is_empty(self) -> bool {
        self.len() == 0
    }
}

/// The capacity of every `STRING` and `WSTRING` in characters (the C runtime's `IEC_STRING` of 258
/// bytes, `IEC_WSTRING` of 512): a declared length is held up to it.
pub const STRING_CAPACITY: u32 = 254;

/// The default length of an unsized `STRING` when no target profile set one (80, as CODESYS and
/// TwinCAT).
pub const DEFAULT_STRING_LEN: u32 = 80;

thread_local! {
    /// The length of a `STRING`/`WSTRING` declared without one, set by [`set_default_string_len`]:
    /// the target profile's `default_string_length` (IEC 61131-3 ed. 3 leaves it to the
    /// implementation).
    static DEFAULT_STRING_LEN_NOW: std::cell::Cell<u32> = const { std::cell::Cell::new(DEFAULT_STRING_LEN) };
}

/// Sets the length of a `STRING`/`WSTRING` declared without one (the target profile's; cut to
/// 1..=[`STRING_CAPACITY`]); returns the one set before.
pub fn set_default_string_len(len: u32) -> u32 {
    DEFAULT_STRING_LEN_NOW.with(|d| d.replace(len.clamp(1, STRING_CAPACITY)))
}

/// The length of a `STRING`/`WSTRING` declared without one (see [`set_default_string_len`]).
pub fn default_string_len() -> u32 {
    DEFAULT_STRING_LEN_NOW.with(std::cell::Cell::get)
}

impl Type {
    /// `BOOL`, i.e. `Type::Elementary(Elementary::Bool)`.
    pub const BOOL: Type = Type::Elementary(E::Bool);
    /// `INT`, i.e. `Type::Elementary(Elementary::Int)`.
    pub const INT: Type = Type::Elementary(E::Int);
    /// `DINT`, i.e. `Type::Elementary(Elementary::Dint)`.
    pub const DINT: Type = Type::Elementary(E::Dint);
    /// `REAL`, i.e. `Type::Elementary(Elementary::Real)`.
    pub const REAL: Type = Type::Elementary(E::Real);
    /// `LREAL`, i.e. `Type::Elementary(Elementary::Lreal)`.
    pub const LREAL: Type = Type::Elementary(E::Lreal);
    /// `TIME`, i.e. `Type::Elementary(Elementary::Time)`.
    pub const TIME: Type = Type::Elementary(E::Time);

    /// The elementary type `e` as a [`Type`].
    pub fn elem(e: Elementary) -> Type {
        Type::Elementary(e)
    }

    /// The elementary type, looking through subranges (a subrange behaves as its base in expressions).
    pub fn elementary(&self) -> Option<Elementary> {
        match self {
            Type::Elementary(e) => Some(*e),
            Type::Subrange { base, .. } => Some(*base),
            _ => None,
        }
    }
    /// Whether this is [`Type::Error`] (already reported; checks skip it).
    pub fn is_error(&self) -> bool {
        matches!(self, Type::Error)
    }
    /// `BOOL` (or a subrange of it).
    pub fn is_bool(&self) -> bool {
        self.elementary() == Some(E::Bool)
    }
    /// ANY_INT, looking through subranges.
    pub fn is_integer(&self) -> bool {
        self.elementary().is_some_and(Elementary::is_integer)
    }
    /// ANY_REAL.
    pub fn is_real(&self) -> bool {
        self.elementary().is_some_and(Elementary::is_real)
    }
    /// ANY_NUM.
    pub fn is_numeric(&self) -> bool {
        self.elementary().is_some_and(Elementary::is_numeric)
    }
    /// ANY_BIT (BOOL BYTE WORD DWORD LWORD).
    pub fn is_bit(&self) -> bool {
        self.elementary().is_some_and(Elementary::is_bit)
    }
    /// Signed integer, real or duration.
    pub fn is_signed(&self) -> bool {
        self.elementary().is_some_and(Elementary::is_signed)
    }
    /// `STRING` or `WSTRING`.
    pub fn is_string(&self) -> bool {
        matches!(self, Type::String { .. })
    }
    /// A function block instance.
    pub fn is_fb(&self) -> bool {
        matches!(self, Type::Fb(_))
    }
    /// Bit width of an elementary type or subrange (`None` for strings, arrays, structs, FBs; enums: 32).
    pub fn bit_width(&self) -> Option<u32> {
        match self {
            Type::Enum(_) => Some(32),
            _ => self.elementary().map(Elementary::bit_width),
        }
    }

    /// How the type is written in IEC source (user types need the model for their names: see
    /// [`Model::type_name`]).
    pub fn describe(&self, model: &Model) -> String {
        model.type_name(self)
    }
}

/// A constant value (initial values, enum values, literal operands after typing).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum ConstValue {
    /// `TRUE` / `FALSE`.
    Bool(bool),
    /// Any integer or bit-string value.
    Int(i128),
    /// A REAL or LREAL value.
    Real(f64),
    /// TIME/LTIME in nanoseconds.
    Duration(i128),
    /// Days since 1970-01-01.
    Date(i64),
    /// Nanoseconds since midnight.
    TimeOfDay(i64),
    /// Nanoseconds since 1970-01-01T00:00:00.
    DateAndTime(i128),
    /// A `STRING` / `WSTRING` value.
    String {
        /// `WSTRING` rather than `STRING`.
        wide: bool,
        /// The characters, escapes decoded.
        value: String,
    },
    /// The `index`-th value of enumeration `ty` (its integer value is `Model::types[ty]`'s).
    Enum {
        /// The enumeration (`Model::types[ty]`).
        ty: TypeId,
        /// The value's position in its declaration.
        index: usize,
    },
    /// Array elements in row-major order, repeats expanded (may be shorter than the array: rest is default).
    Array(Vec<ConstValue>),
    /// Struct fields or FB instance parameters by name as written (`(PT := T#1s)`).
    Struct(Vec<(String, ConstValue)>),
    /// `p : POINTER TO INT := ADR(a);` (CODESYS, TwinCAT): the address of a variable of the same
    /// POU (see `sema::decls` for what is accepted).
    Address(AddressInit),
}

/// The initial value `ADR(path)` of a reference variable of a POU or of a global variable.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AddressInit {
    /// The reference variable's own name (its C lvalue ends with it); of a field or input of an
    /// instance or structure (`fbM : FB_M := (pLamp := ADR(lamp))`), the instance's name.
    pub of_var: String,
    /// The fields from `of_var` to the reference (`["pLamp"]`), an array's element as its
    /// zero-based subscripts (`["[1]", "pLamp"]`, `["[0][2]"]`); empty: `of_var` itself.
    pub within: Vec<String>,
    /// The variable of the same POU, or the global variable, the address is taken of.
    pub base: String,
    /// The global variable `base` is, when it is one (its C name is not the POU's).
    pub global: Option<GlobalRef>,
    /// Its fields and zero-based element offsets, in order.
    pub steps: Vec<AddressStep>,
}

/// One step of an [`AddressInit`] path.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum AddressStep {
    /// `.name`: a structure field.
    Field(String),
    /// `[i, j]`: the zero-based offsets of constant subscripts, one per dimension.
    Index(Vec<u64>),
}

/// A direct address `%IX0.1` / `%QW3` / `%MD10` (`path` empty for `%I*`).
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize)]
pub struct Location {
    /// `I`, `Q` or `M`.
    pub area: Area,
    /// `X`, `B`, `W`, `D` or `L` (none: `X`).
    pub size: AddressSize,
    /// The dotted location numbers (`%IX1.2` -> [1, 2]).
    pub path: Vec<u32>,
}

impl Location {
    /// The location of a parsed direct address.
    pub fn of(a: &DirectAddress) -> Location {
        Location {
            area: a.area,
            size: a.size,
            path: a.path.clone(),
        }
    }
    /// The elementary type the address holds (`X`: BOOL, `B`: BYTE, `W`: WORD, `D`: DWORD, `L`: LWORD).
    pub fn elementary(&self) -> Elementary {
        match self.size {
            AddressSize::Bit => E::Bool,
            AddressSize::Byte => E::Byte,
            AddressSize::Word => E::Word,
            AddressSize::DWord => E::Dword,
            AddressSize::LWord => E::Lword,
        }
    }
}

/// A declared variable (POU variable, struct field, or global).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Variable {
    /// As written.
    pub name: String,
    /// The declaration's span.
    pub span: Span,
    /// The section it was declared in (`VAR_INPUT` ...); `Local` for struct fields.
    pub kind: VarKind,
    /// The resolved type.
    pub ty: Type,
    /// Declared in a `CONSTANT` block: writes are errors.
    pub constant: bool,
    /// Declared in a `RETAIN` block.
    pub retain: bool,
    /// `AT %IX0.1`.
    pub location: Option<Location>,
    /// The declared initial value (after a user type's own default when the declaration gives none:
    /// `None` means the type's default, zero/FALSE/first enum value/empty string).
    pub init: Option<ConstValue>,
    /// `R_EDGE` / `F_EDGE` of a BOOL input of a function block (`None` anywhere else; misplaced
    /// qualifiers are reported, E1100/E1101, and dropped).
    pub edge: Option<crate::ast::Edge>,
}

impl Variable {
    /// Whether the variable is called `name`, ignoring case.
    pub fn is(&self, name: &str) -> bool {
        self.name.eq_ignore_ascii_case(name)
    }
}

/// A user data type.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct UserType {
    /// As written (inline enums get `__ENUM_<n>`).
    pub name: String,
    /// The declaration's span (the name in `TYPE ... END_TYPE`).
    pub span: Span,
    /// Structure, enumeration or alias.
    pub def: UserTypeDef,
    /// A structure declared `UNION ... END_UNION`: its fields share one storage (C `union`).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub union: bool,
    /// An enumeration declared under `{attribute 'to_string'}` (CODESYS, TwinCAT): `TO_STRING` /
    /// `TO_WSTRING` of its values give their names; without it, their numbers.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub to_string: bool,
    /// An enumeration declared under `{attribute 'strict'}` (CODESYS, TwinCAT): its values are no
    /// integers; without it, an enumerated value and an integer convert into each other (W1439).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub strict: bool,
}

/// What a user data type is, resolved.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum UserTypeDef {
    /// Fields are `Variable`s of kind `Local`.
    Struct {
        /// The fields in declaration order.
        fields: Vec<Variable>,
    },
    /// Values as written with their integer values (implicit ones count on from the previous);
    /// `default` indexes `values`.
    Enum {
        /// `(name, value)` in declaration order.
        values: Vec<(String, i128)>,
        /// The default value: `:= v` after the list, else the first (index into `values`).
        default: usize,
    },
    /// `TYPE T : INT := 5;`: the resolved target (uses of `T` are replaced by it) and its initial value.
    Alias {
        /// The resolved type the alias stands for.
        target: Type,
        /// The alias' default initial value (`:= 5`), if declared.
        init: Option<ConstValue>,
    },
}

/// A program, function block or function.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Pou {
    /// The POU name as written.
    pub name: String,
    /// From the POU keyword to `END_*`.
    pub span: Span,
    /// `PROGRAM`, `FUNCTION_BLOCK` or `FUNCTION`.
    pub kind: PouKind,
    /// A FUNCTION's result type.
    pub return_type: Option<Type>,
    /// All declared variables in declaration order (inputs, outputs, in-outs, locals, temps, externals).
    /// A FUNCTION's implicit result variable is not listed (it is `return_type`); `EN`/`ENO` are implicit
    /// BOOLs not listed either (see README_sema.md).
    pub vars: Vec<Variable>,
    /// For each `VAR_EXTERNAL` (index into `vars`), the global it is bound to.
    pub externals: Vec<(usize, GlobalRef)>,
    /// The body's instructions in source pre-order (a deferred `AND( ... )` before the instructions of
    /// its nested list): keys into `Model::instrs` (stored once, there).
    pub instrs: Vec<InstrId>,
    /// Name (any case) -> index into `vars` (built by [`Pou::set_vars`]): lookups in constant time,
    /// from a table small enough to stay in the cache ([`crate::name_index`]).
    #[serde(skip)]
    pub var_index: crate::name_index::NameIndex,
    /// Declared `CLASS` (IEC 61131-3 ed. 3, 6.6.5): its instances are not called, only their
    /// methods.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub class: bool,
    /// The access specifiers of its variables (upper-case name), as [`crate::ast::VarBlock::access`]
    /// gives them: a PRIVATE or PROTECTED one is not reached as `inst.x` from another POU.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub access: Vec<(String, crate::ast::Access)>,
}

/// Calls `f` with the ASCII upper-case form of `name` (the key of the name tables), without allocating
/// when `name` is upper case already or at most 64 bytes long.
pub fn with_upper<R>(name: &str, f: impl FnOnce(&str) -> R) -> R {
    let bytes = name.as_bytes();
    if !bytes.iter().any(u8::is_ascii_lowercase) {
        return f(name);
    }
    let mut buf = [0u8; 64];
    if let Some(dst) = buf.get_mut(..bytes.len()) {
        for (d, s) in dst.iter_mut().zip(bytes) {
            *d = s.to_ascii_uppercase();
        }
        // Upper-casing ASCII letters keeps the text valid UTF-8.
        if let Ok(up) = std::str::from_utf8(dst) {
            return f(up);
        }
    }
    f(&name.to_ascii_uppercase())
}

impl Pou {
    /// Sets the variables (names unique, case-insensitively) and indexes them by name.
    pub fn set_vars(&mut self, vars: Vec<Variable>) {
        let mut index = crate::name_index::NameIndex::with_capacity(vars.len());
        for (i, v) in vars.iter().enumerate() {
            index.insert(&v.name, i, |p| vars[p].name.as_str());
        }
        self.var_index = index;
        self.vars = vars;
    }
    /// The index in `vars` of a variable, by name (case-insensitive).
    pub fn var_position(&self, name: &str) -> Option<usize> {
        if self.var_index.len() == self.vars.len() {
            self.var_index.find(name, |p| self.vars[p].name.as_str())
        } else {
            self.vars.iter().position(|v| v.is(name))
        }
    }
    /// A variable by name (case-insensitive).
    pub fn var(&self, name: &str) -> Option<&Variable> {
        self.var_position(name).map(|i| &self.vars[i])
    }
    /// The `VAR_INPUT` variables, in declaration order (the order of non-formal call arguments).
    pub fn inputs(&self) -> impl Iterator<Item = &Variable> {
        self.vars.iter().filter(|v| v.kind == VarKind::Input)
    }
    /// The `VAR_OUTPUT` variables, in declaration order.
    pub fn outputs(&self) -> impl Iterator<Item = &Variable> {
        self.vars.iter().filter(|v| v.kind == VarKind::Output)
    }
    /// The `VAR_IN_OUT` variables, in declaration order.
    pub fn in_outs(&self) -> impl Iterator<Item = &Variable> {
        self.vars.iter().filter(|v| v.kind == VarKind::InOut)
    }
}

/// A variable a body writes, by its declaration ([`Model::written`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum WrittenVar {
    /// `Model::pous[pou].vars[index]`, not a `VAR_EXTERNAL`.
    Pou {
        /// The POU declaring it.
        pou: PouId,
        /// Index into its `vars`.
        index: usize,
    },
    /// A global (through a `VAR_EXTERNAL`, or a free global used directly).
    Global(GlobalRef),
}

/// Where a global variable lives.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum GlobalRef {
    /// `Model::globals[i]` (a `VAR_GLOBAL` block outside any configuration).
    Free(usize),
    /// `Model::configurations[c].globals[i]`.
    Configuration {
        /// Index into `Model::configurations`.
        config: usize,
        /// Index into that configuration's `globals`.
        index: usize,
    },
    /// `Model::configurations[c].resources[r].globals[i]`.
    Resource {
        /// Index into `Model::configurations`.
        config: usize,
        /// Index into that configuration's `resources`.
        resource: usize,
        /// Index into that resource's `globals`.
        index: usize,
    },
}

/// A named global variable list (a CODESYS/TwinCAT GVL: `<globalVars name="GVL">`). Its members are
/// ordinary globals, also reachable qualified as `GVL.member`; lists of the same name (the sections of
/// one CODESYS list) are one list.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GlobalList {
    /// The list's name as first declared (`GVL` in `<globalVars name="GVL">`).
    pub name: String,
    /// The first declaration's name.
    pub span: Span,
    /// The list's variables, in declaration order over all its sections (each an ordinary global).
    pub members: Vec<GlobalRef>,
}

/// A resolved `CONFIGURATION` (IEC 61131-3 2.7.1).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Configuration {
    /// The configuration's name as written.
    pub name: String,
    /// From `CONFIGURATION` to `END_CONFIGURATION`.
    pub span: Span,
    /// Its `VAR_GLOBAL` variables (referenced by [`GlobalRef::Configuration`]).
    pub globals: Vec<Variable>,
    /// Its resources (at least one: a configuration without `RESOURCE` gets one).
    pub resources: Vec<Resource>,
}

/// A resolved `RESOURCE`: one processing unit with its tasks and program instances.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Resource {
    /// The resource's name as written.
    pub name: String,
    /// From `RESOURCE` to `END_RESOURCE`.
    pub span: Span,
    /// Its `VAR_GLOBAL` variables (referenced by [`GlobalRef::Resource`]).
    pub globals: Vec<Variable>,
    /// Its tasks; [`ProgramInstance::task`] indexes this.
    pub tasks: Vec<Task>,
    /// Its program instances, in source order.
    pub programs: Vec<ProgramInstance>,
}

/// A resolved `TASK`: how often (or on which event) its programs run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Task {
    /// The task's name as written.
    pub name: String,
    /// The `TASK` declaration.
    pub span: Span,
    /// `INTERVAL := T#10ms` in nanoseconds (a literal; `None` when absent or given by a variable).
    pub interval_ns: Option<u64>,
    /// `SINGLE := var` (event task): the variable's name as written.
    pub single: Option<String>,
    /// `PRIORITY := n` (0 when absent).
    pub priority: u32,
}

/// A resolved `PROGRAM inst WITH task : Type (...)`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ProgramInstance {
    /// The instance name as written.
    pub name: String,
    /// The declaration.
    pub span: Span,
    /// `PROGRAM RETAIN`: the instance's variables are retentive.
    pub retain: bool,
    /// Index into the resource's `tasks`; `None` when no `WITH` (runs in the background).
    pub task: Option<usize>,
    /// The program POU instantiated.
    pub pou: PouId,
    /// `(in := x, out => y)` bound to the program's parameters.
    pub args: Vec<ProgramArg>,
}

/// One argument of a program instance.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ProgramArg {
    /// The program's parameter (index into its `vars`).
    pub param: usize,
    /// `=>`: the program's output is copied to the value (a global or an address).
    pub output: bool,
    /// What the parameter is connected to.
    pub value: ProgramArgValue,
}

/// What a program instance's parameter is connected to.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum ProgramArgValue {
    /// A global variable.
    Global(GlobalRef),
    /// A direct address (`%IX0.1`).
    Address(Location),
    /// A constant (`in := 5`).
    Const(ConstValue),
}

/// What an instruction calls.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize)]
pub enum Callee {
    /// A standard function (`ADD`, `SEL`, `LIMIT` ...) or a simple operator mapped onto one (the operator
    /// `ADD x` is `Std { name: "ADD", ty: INT, .. }`); `ty` is the type the generic parameters were
    /// instantiated with, `result` the function's result type (BOOL for comparisons).
    Std {
        /// The standard function's canonical name (`ADD`, `LIMIT`).
        name: &'static str,
        /// The type its generic parameters were instantiated with.
        ty: Type,
        /// The result type (BOOL for comparisons).
        result: Type,
    },
    /// `X_TO_Y`, `TRUNC`, `BCD_TO_*`, `*_TO_BCD`.
    Conversion {
        /// The function name as written upper case (`INT_TO_REAL`).
        name: String,
        /// How the value is converted.
        kind: ConversionKind,
        /// The source type.
        from: Type,
        /// The target type.
        to: Type,
    },
    /// A user `FUNCTION` of the model.
    UserFunction(PouId),
    /// `CAL inst`, `S1 inst`, `IN tmr`, and `S`/`R` with an FB instance operand: `input` is the input the
    /// operator writes (`None` for `CAL`).
    FbInstance {
        /// The instance's FB type.
        fb: FbType,
        /// The input the operator writes (`IN` for `IN tmr`); `None` for `CAL`.
        input: Option<String>,
    },
    /// `FUNC Name()`: an embedded C function; the current result is unchanged.
    Embedded {
        /// The C function's name.
        name: String,
    },
}

/// How a type conversion function converts (IEC 61131-3 2.5.1.5.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum ConversionKind {
    /// `INT_TO_REAL`, `REAL_TO_INT` (rounds to nearest, IEC), `DINT_TO_INT` (truncates bits) ...
    Plain,
    /// `TRUNC` / `REAL_TO_INT` written as `TRUNC`: toward zero.
    Trunc,
    /// `BCD_TO_INT`, `WORD_BCD_TO_INT`: decode binary-coded decimal.
    FromBcd,
    /// `INT_TO_BCD`: encode to binary-coded decimal.
    ToBcd,
}

/// Where a call argument's value comes from.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize)]
pub enum ArgSource {
    /// The current result (first input of a function called as an IL operator).
    CurrentResult,
    /// The `i`-th written argument (in `CallArgs::NonFormal` or `CallArgs::Formal`).
    Written(usize),
}

/// One call argument bound to its formal parameter.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize)]
pub struct ArgBinding {
    /// The formal parameter's canonical name (`IN`, `MN`, `IN0` ...).
    pub param: String,
    /// `true` for `=>` outputs.
    pub output: bool,
    /// The formal parameter's type (instantiated for generic standard functions).
    pub ty: Type,
    /// Where the value comes from.
    pub source: ArgSource,
}

/// The identity of one instruction of the analysed units: its address. Spans cannot be the key: lowered
/// code (ladder rungs, ST statements) gives several instructions the span of the one element they came
/// from. A model is valid for exactly the units it was computed from (not for clones of them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct InstrId(usize);

impl InstrId {
    /// The identity of `instruction` (its address; valid while the analysed units are alive and unmoved).
    pub fn of(instruction: &crate::ast::Instruction) -> Self {
        InstrId(instruction as *const crate::ast::Instruction as usize)
    }
}

/// What sema knows about one instruction (`Model::instrs[&InstrId::of(instruction)]`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InstrInfo {
    /// The instruction's span (for messages and tools; not unique).
    pub span: Span,
    /// The current result before the instruction (`None`: undefined, e.g. at the start of a body).
    pub cr_before: Option<Type>,
    /// The current result after it (`None`: undefined, e.g. after an unconditional `JMP`/`RET`).
    pub cr_after: Option<Type>,
    /// The operand's type (for a deferred operator, the nested list's value); for an untyped literal
    /// operand, the type its context fixed.
    pub operand: Option<Type>,
    /// What the instruction calls (functions, FB instances, operators mapped onto standard functions), if
    /// anything.
    pub callee: Option<Callee>,
    /// Call arguments bound to parameters, in evaluation order (function calls, `CAL` with arguments).
    pub args: Vec<ArgBinding>,
}

impl InstrInfo {
    /// The span and the facts (everything else).
    pub fn split(self) -> (Span, InstrFacts) {
        let InstrInfo {
            span,
            cr_before,
            cr_after,
            operand,
            callee,
            args,
        } = self;
        (
            span,
            InstrFacts {
                cr_before,
                cr_after,
                operand,
                callee,
                args,
            },
        )
    }
}

/// What sema knows about an instruction apart from its span: the fields of [`InstrInfo`] but `span`.
/// Shared by all the instructions with equal facts ([`InstrTable`]).
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize)]
pub struct InstrFacts {
    /// See [`InstrInfo::cr_before`].
    pub cr_before: Option<Type>,
    /// See [`InstrInfo::cr_after`].
    pub cr_after: Option<Type>,
    /// See [`InstrInfo::operand`].
    pub operand: Option<Type>,
    /// See [`InstrInfo::callee`].
    pub callee: Option<Callee>,
    /// See [`InstrInfo::args`].
    pub args: Vec<ArgBinding>,
}

/// One instruction's info as [`Model::instrs`] gives it: its span and its (shared) facts. It derefs to
/// the facts, so `info.cr_after` and `info.callee` read as on an [`InstrInfo`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InstrRef<'m> {
    /// The instruction's span (for messages and tools; not unique).
    pub span: Span,
    /// Everything else sema knows about it.
    pub facts: &'m InstrFacts,
}

impl std::ops::Deref for InstrRef<'_> {
    type Target = InstrFacts;
    fn deref(&self) -> &InstrFacts {
        self.facts
    }
}

impl InstrRef<'_> {
    /// An owned copy, as sema recorded it.
    pub fn to_info(&self) -> InstrInfo {
        let f = self.facts.clone();
        InstrInfo {
            span: self.span,
            cr_before: f.cr_before,
            cr_after: f.cr_after,
            operand: f.operand,
            callee: f.callee,
            args: f.args,
        }
    }
}

/// Serialised as the [`InstrInfo`] it stands for (same fields, same order).
impl Serialize for InstrRef<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut st = s.serialize_struct("InstrInfo", 6)?;
        st.serialize_field("span", &self.span)?;
        st.serialize_field("cr_before", &self.facts.cr_before)?;
        st.serialize_field("cr_after", &self.facts.cr_after)?;
        st.serialize_field("operand", &self.facts.operand)?;
        st.serialize_field("callee", &self.facts.callee)?;
        st.serialize_field("args", &self.facts.args)?;
        st.end()
    }
}

/// What a name used in a body refers to (`Model::names[&var_ref.base.span]`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum NameRef {
    /// `Model::pous[pou].vars[index]` of the POU the body belongs to (a `VAR_EXTERNAL` too: see
    /// `Pou::externals` for its global).
    Var(usize),
    /// The function's own name used as its result variable (`ST WEIGH` in FUNCTION WEIGH).
    FunctionResult,
    /// The implicit `EN` input / `ENO` output of a function or FB.
    En,
    /// See [`NameRef::En`].
    Eno,
    /// A `VAR_GLOBAL` outside any configuration, used directly.
    Global(GlobalRef),
    /// An enumerated value written without its type (`red`).
    EnumValue {
        /// The enumeration.
        ty: TypeId,
        /// The value's position in its declaration.
        index: usize,
    },
}

/// Everything sema resolved.
#[derive(Debug, Clone, Default, Serialize)]
pub struct Model {
    /// User data types, indexed by [`TypeId`] (inline enumerations included).
    pub types: Vec<UserType>,
    /// All POUs of the analysed units in source order, indexed by [`PouId`].
    pub pous: Vec<Pou>,
    /// The configurations in source order.
    pub configurations: Vec<Configuration>,
    /// `VAR_GLOBAL` blocks outside configurations.
    pub globals: Vec<Variable>,
    /// The named global variable lists (CODESYS/TwinCAT GVLs) of every scope, in source order.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub global_lists: Vec<GlobalList>,
    /// The list (index into `global_lists`) each member of a named list belongs to.
    #[serde(skip)]
    pub list_of_global: FxHashMap<GlobalRef, usize>,
    /// Upper-case member name -> the lists (indexes into `global_lists`) declaring it, in order.
    #[serde(skip)]
    pub lists_of_name: FxHashMap<String, Vec<usize>>,
    /// Whether a body reads `inst.ENO` of an FB instance, or writes `ENO =>` of a user FB's call
    /// (then every call stores the instance's ENO, and user FB instances keep the ENO their body
    /// sets; otherwise only standard FB calls with EN store it).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub fb_eno_read: bool,
    /// The `s[i]` on a STRING or WSTRING read as CODESYS and TwinCAT do (a BYTE or WORD at offset
    /// `i`, 0 the first; [`crate::sema::CodesysFiles`]): the spans of their index operands.
    #[serde(skip)]
    pub byte_indexes: FxHashSet<Span>,
    /// The programs whose variables other POUs use by name (`MAIN.x`, W1413; each has one instance):
    /// the C declares their instance in the header.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub programs_used_by_name: Vec<PouId>,
    /// Keyed by the instruction's identity ([`InstrId::of`]).
    pub instrs: InstrTable,
    /// The variables a body writes (`ST`, `S`, `R`, an ST assignment, an output `=>`), by their
    /// declaration: a POU's own variable, or the global a `VAR_EXTERNAL` or a direct use names (read
    /// by the C generator's overlap warnings on located variables, `c_backend::emit::overlaps`).
    /// A member of a named list written as `GVL.x`, a `VAR_IN_OUT` argument and a write through a
    /// reference are not recorded.
    #[serde(skip)]
    pub written: FxHashSet<WrittenVar>,
    /// What each variable name in the bodies refers to, keyed by the span of `VarRef::base` (operands,
    /// call arguments, indexes, CAL instances); from [`crate::sema::analyze_for_code`], only the uses
    /// of a function's name as its result.
    pub names: SpanTable<NameRef>,
}

/// The instruction infos by identity. Each instruction stores its identity, its span and the index of
/// its [`InstrFacts`] (24 bytes); the facts themselves are stored once per distinct value (a program has
/// few: `BOOL` before and after, an `INT` addition ...), so the table grows by 24 bytes per instruction
/// instead of the size of a whole [`InstrInfo`] (232 bytes).
/// Lookups: readers walk the bodies in the order sema recorded them and pass the position after the
/// previous instruction ([`InstrTable::get_near`]), which finds the next one at once; while the ids came
/// in increasing order a lookup bisects; otherwise the first lookup that needs it builds a hash index
/// (instruction addresses are not in order across bodies, and sema never needs it).
/// Invariants: `pool[facts[i]] == i` for every stored facts value, and `simple[k] == i` for every key
/// `k` in `simple`, `k` being the `simple_key` of facts equal to `facts[i]`; every entry's index is below
/// `facts.len()`; `sorted` says whether the ids are strictly increasing; `index`, once built, maps each
/// id to its last entry (an id inserted twice: the later info counts; sema records each instruction
/// once).
#[derive(Debug, Clone, Default)]
pub struct InstrTable {
    entries: Vec<(InstrId, Span, u32)>,
    unsorted: bool,
    index: std::sync::OnceLock<FxHashMap<InstrId, u32>>,
    facts: Vec<InstrFacts>,
    pool: FxHashMap<InstrFacts, u32>,
    /// The pool's entries whose facts have a [`simple_key`] (most: elementary types, no callee or a
    /// standard function on elementary types, no arguments), by that key: found without hashing and
    /// comparing whole facts.
    simple: FxHashMap<SimpleKey, u32>,
    /// Whether an id may have been stored twice ([`InstrTable::insert`] was used; sema records through
    /// `insert_interned`, each instruction once): then only the hint and the index find an id.
    repeats: bool,
    /// The position of each body's first instruction, by id ([`InstrTable::start_body`]): a reader
    /// starting a body finds its first instruction here when its hint is still in another body.
    starts: FxHashMap<InstrId, u32>,
    /// Set by [`InstrTable::start_body`] until the next instruction is stored.
    body_starts: bool,
}

/// How many entries after and before its hint [`InstrTable::get_near`] looks at before the index.
const NEAR: usize = 32;

/// The key of the facts of most instructions ([`simple_key`]): the three types, each absent (0) or
/// elementary (its index + 1), one byte each, and for a standard function on elementary types (the
/// operators `ADD x`, `GT 5` ...: [`Callee::Std`]) its type and result type in two more bytes, and its
/// name's address and length (the names are `&'static str`s of the function tables: equal names at two
/// addresses are two keys of the same facts, which the table then stores once all the same, through
/// the pool).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
struct SimpleKey {
    types: u64,
    std_name: (usize, usize),
}

/// The [`SimpleKey`] of `f`; `None` when it has arguments, a callee other than a standard function on
/// elementary types, or another type.
fn simple_key(f: &InstrFacts) -> Option<SimpleKey> {
    if !f.args.is_empty() {
        return None;
    }
    fn byte(t: Option<&Type>) -> Option<u64> {
        match t {
            None => Some(0),
            Some(Type::Elementary(e)) => Some(*e as u64 + 1),
            Some(_) => None,
        }
    }
    let types = byte(f.cr_before.as_ref())?
        | byte(f.cr_after.as_ref())? << 8
        | byte(f.operand.as_ref())? << 16;
    match &f.callee {
        None => Some(SimpleKey {
            types,
            std_name: (0, 0),
        }),
        Some(Callee::Std { name, ty, result }) => Some(SimpleKey {
            types: types | byte(Some(ty))? << 24 | byte(Some(result))? << 32 | 1 << 40,
            std_name: (name.as_ptr() as usize, name.len()),
        }),
        Some(_) => None,
    }
}

impl InstrTable {
    /// Stores the info of instruction `id` (a second insert under `id` replaces it for lookups).
    pub fn insert(&mut self, id: InstrId, info: InstrInfo) {
        self.repeats = true;
        let (span, facts) = info.split();
        let ix = self.intern(facts);
        self.insert_interned(id, span, ix);
    }
    /// The index of `facts` in the shared store (stored first if new).
    pub(crate) fn intern(&mut self, facts: InstrFacts) -> u32 {
        if let Some(key) = simple_key(&facts) {
            return match self.simple.get(&key) {
                Some(&ix) => {
                    // Facts with a key own no memory (elementary types, a `&'static` name, no
                    // arguments) unless their empty argument list has room: then there is nothing
                    // to free, and the drop's calls through every field (most of sema's dropping of
                    // types) are skipped.
                    if facts.args.capacity() == 0 {
                        std::mem::forget(facts);
                    }
                    ix
                }
                None => {
                    let ix = self.intern_in_pool(facts);
                    self.simple.insert(key, ix);
                    ix
                }
            };
        }
        self.intern_in_pool(facts)
    }
    fn intern_in_pool(&mut self, facts: InstrFacts) -> u32 {
        match self.pool.get(&facts) {
            Some(&ix) => ix,
            None => {
                let ix = self.facts.len() as u32;
                self.facts.push(facts.clone());
                self.pool.insert(facts, ix);
                ix
            }
        }
    }
    /// [`InstrTable::insert`] with facts already interned (`ix` from [`InstrTable::intern`]).
    pub(crate) fn insert_interned(&mut self, id: InstrId, span: Span, ix: u32) {
        if let Some(&(last, _, _)) = self.entries.last() {
            self.unsorted |= last >= id;
        }
        let at = self.entries.len() as u32;
        if std::mem::take(&mut self.body_starts) {
            self.starts.insert(id, at);
        }
        self.entries.push((id, span, ix));
        if let Some(index) = self.index.get_mut() {
            index.insert(id, at);
        }
    }
    fn position(&self, id: InstrId) -> Option<usize> {
        if !self.unsorted {
            return self.entries.binary_search_by_key(&id, |e| e.0).ok();
        }
        let index = self.index.get_or_init(|| {
            let mut index = FxHashMap::default();
            index.reserve(self.entries.len());
            for (i, e) in self.entries.iter().enumerate() {
                index.insert(e.0, i as u32);
            }
            index
        });
        index.get(&id).map(|&i| i as usize)
    }
    fn view(&self, &(_, span, ix): &(InstrId, Span, u32)) -> InstrRef<'_> {
        InstrRef {
            span,
            facts: &self.facts[ix as usize],
        }
    }
    /// The info of instruction `id`.
    pub fn get(&self, id: &InstrId) -> Option<InstrRef<'_>> {
        self.position(*id).map(|i| self.view(&self.entries[i]))
    }
    /// The info of `id` and its position, trying position `hint` first: a reader walking a body in the
    /// order sema recorded it passes the position after the previous instruction's.
    /// When the entry at `hint` is another instruction and the ids are not in order, the 32 entries
    /// after and before it are tried next (a reader that takes a short stretch of a body in another
    /// order than sema, such as the C back end at an `AND(` list, lands a few entries off), then the
    /// bodies' first instructions, before the hash index is built.
    pub fn get_near(&self, id: InstrId, hint: usize) -> Option<(usize, InstrRef<'_>)> {
        let i = match self.entries.get(hint) {
            // An id recorded twice (never by sema) is found through the index: the later entry counts.
            Some(e)
                if e.0 == id
                    && self
                        .index
                        .get()
                        .is_none_or(|x| x.len() >= self.entries.len()) =>
            {
                hint
            }
            _ => match self.near(id, hint) {
                Some(i) => i,
                None => self.position(id)?,
            },
        };
        Some((i, self.view(&self.entries[i])))
    }
    /// The position of `id` among the [`NEAR`] entries after `hint` and the [`NEAR`] before it, or as
    /// the first instruction of a body, when
    /// no id can have been stored twice (only [`InstrTable::insert`] may repeat one; sema never does)
    /// and the table is not in id order (there bisecting is as quick).
    fn near(&self, id: InstrId, hint: usize) -> Option<usize> {
        if self.repeats || !self.unsorted {
            return None;
        }
        let len = self.entries.len();
        let after = hint.saturating_add(1).min(len)..hint.saturating_add(1 + NEAR).min(len);
        let before = hint.saturating_sub(NEAR).min(len)..hint.min(len);
        let found = |r: std::ops::Range<usize>| {
            let start = r.start;
            self.entries[r]
                .iter()
                .position(|e| e.0 == id)
                .map(|k| start + k)
        };
        found(after)
            .or_else(|| found(before))
            .or_else(|| self.starts.get(&id).map(|&at| at as usize))
    }
    /// The next instruction stored begins a body (sema calls this before storing each POU's
    /// instructions).
    pub(crate) fn start_body(&mut self) {
        self.body_starts = true;
    }
    /// Makes room for `additional` more instructions.
    pub fn reserve(&mut self, additional: usize) {
        self.entries.reserve(additional);
    }
    /// The number of instructions recorded.
    pub fn len(&self) -> usize {
        self.entries.len()
    }
    /// Whether the table is empty.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }
    /// Whether instruction `id` has an info.
    pub fn contains_key(&self, id: &InstrId) -> bool {
        self.position(*id).is_some()
    }
    /// The instructions and their infos, in insertion order.
    pub fn iter(&self) -> impl Iterator<Item = (&InstrId, InstrRef<'_>)> {
        self.entries.iter().map(|e| (&e.0, self.view(e)))
    }
    /// The infos in insertion order.
    pub fn values(&self) -> impl Iterator<Item = InstrRef<'_>> {
        self.entries.iter().map(|e| self.view(e))
    }
    /// The number of distinct [`InstrFacts`] stored.
    pub fn distinct_facts(&self) -> usize {
        self.facts.len()
    }
}

/// Serialised as a map from instruction id to [`InstrInfo`], as before the facts were shared.
impl Serialize for InstrTable {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_map(self.iter())
    }
}

/// A map keyed by span ([`KeyTable`]).
pub type SpanTable<V> = KeyTable<Span, V>;

/// A key of a [`KeyTable`]: hashable, and with an order in which keys usually arrive.
pub trait TableKey: Copy + Eq + std::hash::Hash {
    /// The comparison key (spans: file, start, end; instruction ids: address).
    type Order: Ord;
    /// This key's position in the usual arrival order.
    fn order(&self) -> Self::Order;
}

impl TableKey for Span {
    type Order = (u32, u32, u32);
    fn order(&self) -> Self::Order {
        (self.file.0, self.start, self.end)
    }
}

impl TableKey for InstrId {
    type Order = usize;
    fn order(&self) -> usize {
        self.0
    }
}

/// A map stored as one vector in insertion order (source order of the bodies), so that reading the
/// values body by body touches memory in order and a value is stored once, without the spare room of a
/// hash table. While the keys come in increasing order (spans: sema walks each body in source order)
/// the vector is sorted and searched by bisection; the first key out of order builds a hash index, used
/// from then on.
/// Invariants: one entry per key (a second insert under a key replaces the value, as a map does);
/// without `index`, `entries` is sorted strictly by [`TableKey::order`]; with it, `index[key]` is the
/// position of the key's entry.
#[derive(Debug, Clone)]
pub struct KeyTable<K, V> {
    entries: Vec<(K, V)>,
    index: Option<FxHashMap<K, u32>>,
}

impl<K, V> Default for KeyTable<K, V> {
    fn default() -> Self {
        KeyTable {
            entries: Vec::new(),
            index: None,
        }
    }
}

fn span_key<K: TableKey>(k: &K) -> K::Order {
    k.order()
}

impl<K: TableKey, V> KeyTable<K, V> {
    fn position(&self, span: &K) -> Option<usize> {
        match &self.index {
            Some(index) => index.get(span).map(|&i| i as usize),
            None => self
                .entries
                .binary_search_by_key(&span_key(span), |(s, _)| span_key(s))
                .ok(),
        }
    }
    /// The value at `span`.
    pub fn get(&self, span: &K) -> Option<&V> {
        self.position(span).map(|i| &self.entries[i].1)
    }
    /// The value at `span` and its position, trying position `hint` first: a reader walking a body in
    /// source order passes the position after the previous instruction's and finds the next one at once.
    pub fn get_near(&self, span: K, hint: usize) -> Option<(usize, &V)> {
        match self.entries.get(hint) {
            Some((s, v)) if *s == span => Some((hint, v)),
            _ => {
                let i = self.position(&span)?;
                Some((i, &self.entries[i].1))
            }
        }
    }
    /// Stores the value at `span`; returns the value it replaces.
    pub fn insert(&mut self, span: K, value: V) -> Option<V> {
        if self.index.is_none() {
            let in_order = self
                .entries
                .last()
                .is_none_or(|(last, _)| span_key(last) < span_key(&span));
            if in_order {
                self.entries.push((span, value));
                return None;
            }
            let mut index = FxHashMap::default();
            index.reserve(self.entries.capacity());
            index.extend(
                self.entries
                    .iter()
                    .enumerate()
                    .map(|(i, (s, _))| (*s, i as u32)),
            );
            self.index = Some(index);
        }
        let next = self.entries.len() as u32;
        let index = self.index.get_or_insert_with(FxHashMap::default);
        match index.get(&span) {
            Some(&i) => Some(std::mem::replace(&mut self.entries[i as usize].1, value)),
            None => {
                index.insert(span, next);
                self.entries.push((span, value));
                None
            }
        }
    }
    /// Makes room for `additional` more values.
    pub fn reserve(&mut self, additional: usize) {
        self.entries.reserve(additional);
        if let Some(index) = &mut self.index {
            index.reserve(additional);
        }
    }
    /// The number of entries.
    pub fn len(&self) -> usize {
        self.entries.len()
    }
    /// Whether the table is empty.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }
    /// Whether `span` has a value.
    pub fn contains_key(&self, span: &K) -> bool {
        self.position(span).is_some()
    }
    /// The spans and values, in insertion order.
    pub fn iter(&self) -> impl Iterator<Item = (&K, &V)> {
        self.entries.iter().map(|(s, v)| (s, v))
    }
    /// The values in insertion order.
    pub fn values(&self) -> impl Iterator<Item = &V> {
        self.entries.iter().map(|(_, v)| v)
    }
}

/// Serialised as a map from key to value, as the map it stands for.
impl<K: TableKey + Serialize, V: Serialize> Serialize for KeyTable<K, V> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_map(self.iter())
    }
}

impl Model {
    /// The POU with id `id`.
    pub fn pou(&self, id: PouId) -> &Pou {
        &self.pous[id.0 as usize]
    }
    /// A POU's id by name (case-insensitive).
    pub fn pou_by_name(&self, name: &str) -> Option<PouId> {
        self.pous
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case(name))
            .map(|i| PouId(i as u32))
    }
    /// The user type with id `id`.
    pub fn user_type(&self, id: TypeId) -> &UserType {
        &self.types[id.0 as usize]
    }
    /// The type a bare type name stands for, as `SIZEOF(T)` names it: an elementary type, `STRING` /
    /// `WSTRING` (their default length), a user type (an alias: its target), a
    /// standard or user function block.
    pub fn type_named(&self, name: &str) -> Option<Type> {
        if let Some(e) = Elementary::from_name(name) {
            return Some(Type::Elementary(e));
        }
        if name.eq_ignore_ascii_case("STRING") || name.eq_ignore_ascii_case("WSTRING") {
            return Some(Type::String {
                wide: name.eq_ignore_ascii_case("WSTRING"),
                len: default_string_len(),
            });
        }
        if let Some(id) = self.type_by_name(name) {
            return Some(match &self.user_type(id).def {
                UserTypeDef::Struct { .. } => Type::Struct(id),
                UserTypeDef::Enum { .. } => Type::Enum(id),
                UserTypeDef::Alias { target, .. } => target.clone(),
            });
        }
        if let Some(fb) = StdFb::from_name(name) {
            return Some(Type::Fb(FbType::Standard(fb)));
        }
        self.pou_by_name(name)
            .filter(|id| self.pou(*id).kind == PouKind::FunctionBlock)
            .map(|id| Type::Fb(FbType::User(id)))
    }
    /// A user type's id by name (case-insensitive).
    pub fn type_by_name(&self, name: &str) -> Option<TypeId> {
        self.types
            .iter()
            .position(|t| t.name.eq_ignore_ascii_case(name))
            .map(|i| TypeId(i as u32))
    }
    /// The info of an instruction of the analysed units.
    pub fn instr(&self, instruction: &crate::ast::Instruction) -> Option<InstrRef<'_>> {
        self.instrs.get(&InstrId::of(instruction))
    }
    /// The info of an instruction by its identity (see [`Pou::instrs`]).
    pub fn instr_by_id(&self, id: InstrId) -> Option<InstrRef<'_>> {
        self.instrs.get(&id)
    }
    /// A global by reference.
    pub fn global(&self, r: GlobalRef) -> &Variable {
        match r {
            GlobalRef::Free(i) => &self.globals[i],
            GlobalRef::Configuration { config, index } => {
                &self.configurations[config].globals[index]
            }
            GlobalRef::Resource {
                config,
                resource,
                index,
            } => &self.configurations[config].resources[resource].globals[index],
        }
    }
    /// The named global variable list `name` (a CODESYS GVL), case-insensitively.
    pub fn global_list(&self, name: &str) -> Option<&GlobalList> {
        self.global_lists
            .iter()
            .find(|l| l.name.eq_ignore_ascii_case(name))
    }
    /// Every global variable: outside configurations, then each configuration's and its resources'.
    pub fn global_refs(&self) -> Vec<GlobalRef> {
        let mut v: Vec<GlobalRef> = (0..self.globals.len()).map(GlobalRef::Free).collect();
        for (config, c) in self.configurations.iter().enumerate() {
            v.extend((0..c.globals.len()).map(|index| GlobalRef::Configuration { config, index }));
            for (resource, r) in c.resources.iter().enumerate() {
                v.extend((0..r.globals.len()).map(|index| GlobalRef::Resource {
                    config,
                    resource,
                    index,
                }));
            }
        }
        v
    }
    /// The name a global is known by outside the POUs: `List.x` for a member of a named global
    /// variable list (two lists may both declare `x`), the plain name otherwise. The trace and
    /// `--watch` use it, and the C back end mangles it into the global's C name.
    pub fn global_qualified_name(&self, r: GlobalRef) -> String {
        let name = &self.global(r).name;
        match self.list_of_global.get(&r) {
            Some(&l) => format!("{}.{name}", self.global_lists[l].name),
            None => name.clone(),
        }
    }
    /// The names of the global variable lists that declare a variable `name` (case-insensitive), in
    /// list order: two or more make an unqualified use of `name` ambiguous.
    pub fn lists_declaring(&self, name: &str) -> Vec<&GlobalList> {
        if self.global_lists.len() < 2 {
            return Vec::new();
        }
        with_upper(name, |key| {
            self.lists_of_name
                .get(key)
                .map(|ls| ls.iter().map(|&l| &self.global_lists[l]).collect())
                .unwrap_or_default()
        })
    }
    /// The member `member` of a global variable list.
    pub fn list_member(&self, list: &GlobalList, member: &str) -> Option<GlobalRef> {
        list.members
            .iter()
            .copied()
            .find(|&r| self.global(r).name.eq_ignore_ascii_case(member))
    }
    /// The IEC spelling of a type (`INT`, `STRING[20]`, `ARRAY [0..9] OF INT`, `TON`, a user type's name).
    pub fn type_name(&self, ty: &Type) -> String {
        match ty {
            Type::Elementary(e) => e.name().to_string(),
            Type::String { wide, len } => {
                let kw = if *wide { "WSTRING" } else { "STRING" };
                if *len == default_string_len() {
                    kw.to_string()
                } else {
                    format!("{kw}[{len}]")
                }
            }
            Type::Array { dims, element } => {
                let d: Vec<String> = dims
                    .iter()
                    .map(|d| format!("{}..{}", d.lower, d.upper))
                    .collect();
                format!("ARRAY [{}] OF {}", d.join(", "), self.type_name(element))
            }
            Type::Struct(id) | Type::Enum(id) => self
                .types
                .get(id.0 as usize)
                .map(|t| t.name.clone())
                .unwrap_or_else(|| "?".into()),
            Type::Subrange { base, lower, upper } => format!("{base} ({lower}..{upper})"),
            Type::Fb(FbType::Standard(f)) => f.name().to_string(),
            Type::Fb(FbType::User(id)) => self
                .pous
                .get(id.0 as usize)
                .map(|p| p.name.clone())
                .unwrap_or_else(|| "?".into()),
            Type::Ref(t) if t.is_error() => "NULL".into(),
            Type::Ref(t) => format!("REF_TO {}", self.type_name(t)),
            Type::Error => "<error>".into(),
        }
    }
}

#[cfg(test)]
mod type_tests {
    use super::*;

    /// The written-out `Clone` and `PartialEq` of [`Type`]: a clone equals its original, every
    /// variant differs from every other, and a different field makes a different type.
    #[test]
    fn types_clone_and_compare_field_by_field() {
        let array = |upper: i128, element: Type| Type::Array {
            dims: vec![Dim { lower: 0, upper }],
            element: Box::new(element),
        };
        let subrange = |upper: i128| Type::Subrange {
            base: Elementary::Int,
            lower: Box::new(0),
            upper: Box::new(upper),
        };
        let all = [
            Type::BOOL,
            Type::INT,
            Type::String {
                wide: false,
                len: 10,
            },
            Type::String {
                wide: true,
                len: 10,
            },
            Type::String {
                wide: false,
                len: 11,
            },
            array(3, Type::INT),
            array(4, Type::INT),
            array(3, Type::BOOL),
            Type::Struct(TypeId(0)),
            Type::Struct(TypeId(1)),
            Type::Enum(TypeId(0)),
            subrange(100),
            subrange(99),
            Type::Fb(FbType::Standard(StdFb::RTrig)),
            Type::Fb(FbType::User(PouId(0))),
            Type::Error,
        ];
        for (i, a) in all.iter().enumerate() {
            assert_eq!(&a.clone(), a);
            assert_eq!(format!("{:?}", a.clone()), format!("{a:?}"));
            for (j, b) in all.iter().enumerate() {
                assert_eq!(a == b, i == j, "{a:?} == {b:?}");
            }
        }
    }
}

#[cfg(test)]
mod span_table_tests {
    use super::*;
    use diagnostics::FileId;

    fn sp(file: u32, start: usize, end: usize) -> Span {
        Span::new(FileId(file), start, end)
    }

    #[test]
    fn in_order_inserts_are_found_by_bisection() {
        let mut t = SpanTable::default();
        for i in 0..100 {
            assert_eq!(t.insert(sp(0, i * 10, i * 10 + 4), i), None);
        }
        assert!(t.index.is_none(), "no index while the spans come in order");
        assert_eq!(t.len(), 100);
        assert_eq!(t.get(&sp(0, 370, 374)), Some(&37));
        assert_eq!(t.get(&sp(0, 370, 375)), None);
        assert!(t.contains_key(&sp(0, 990, 994)));
        // The hint is used when it points at the span, and ignored when it does not.
        assert_eq!(t.get_near(sp(0, 50, 54), 5), Some((5, &5)));
        assert_eq!(t.get_near(sp(0, 50, 54), 99), Some((5, &5)));
        assert_eq!(t.get_near(sp(0, 50, 54), 1000), Some((5, &5)));
        assert_eq!(t.get_near(sp(1, 50, 54), 5), None);
    }

    #[test]
    fn out_of_order_and_repeated_spans_behave_as_a_map() {
        let mut t = SpanTable::default();
        t.insert(sp(1, 0, 4), "a");
        t.insert(sp(1, 10, 14), "b");
        // Another file with a lower id, then a repeated span: map semantics throughout.
        assert_eq!(t.insert(sp(0, 5, 9), "c"), None);
        assert!(t.index.is_some());
        assert_eq!(t.insert(sp(1, 0, 4), "a2"), Some("a"));
        assert_eq!(t.len(), 3);
        assert_eq!(t.get(&sp(1, 0, 4)), Some(&"a2"));
        assert_eq!(t.get(&sp(0, 5, 9)), Some(&"c"));
        assert_eq!(t.get(&sp(1, 10, 14)), Some(&"b"));
        let order: Vec<&str> = t.values().copied().collect();
        assert_eq!(
            order,
            ["a2", "b", "c"],
            "insertion order, replaced in place"
        );
        // A repeat of the last span (not greater than it) also replaces.
        let mut u = SpanTable::default();
        u.insert(sp(0, 0, 1), 1);
        assert_eq!(u.insert(sp(0, 0, 1), 2), Some(1));
        assert_eq!(u.len(), 1);
        assert_eq!(u.get(&sp(0, 0, 1)), Some(&2));
    }

    #[test]
    fn with_upper_gives_the_upper_case_key() {
        assert_eq!(with_upper("Motor_1", str::to_string), "MOTOR_1");
        assert_eq!(with_upper("ALREADY", str::to_string), "ALREADY");
        let long = "a".repeat(100);
        assert_eq!(with_upper(&long, str::to_string), "A".repeat(100));
        assert_eq!(with_upper("grün", str::to_string), "GRüN");
    }
}

#[cfg(test)]
mod instr_table_tests {
    use super::*;

    fn info(start: u32, ty: Type) -> InstrInfo {
        InstrInfo {
            span: Span::new(crate::FileId(0), start as usize, start as usize + 1),
            cr_before: None,
            cr_after: Some(ty),
            operand: None,
            callee: None,
            args: Vec::new(),
        }
    }

    /// Ids out of order (bodies are separate allocations): lookups still find every instruction, with a
    /// right or a wrong hint, and equal facts are stored once.
    #[test]
    fn lookups_in_and_out_of_order() {
        let mut t = InstrTable::default();
        for (id, start) in [(30, 0), (40, 1), (10, 2), (20, 3)] {
            let ty = if start % 2 == 0 {
                Type::BOOL
            } else {
                Type::INT
            };
            t.insert(InstrId(id), info(start, ty));
        }
        assert_eq!(t.len(), 4);
        assert_eq!(t.distinct_facts(), 2);
        for (pos, (id, start)) in [(30, 0), (40, 1), (10, 2), (20, 3)].into_iter().enumerate() {
            assert_eq!(t.get(&InstrId(id)).unwrap().span.start, start);
            let (at, near) = t.get_near(InstrId(id), pos).unwrap();
            assert_eq!((at, near.span.start), (pos, start));
            let (at, far) = t.get_near(InstrId(id), (pos + 1) % 4).unwrap();
            assert_eq!((at, far.span.start), (pos, start));
        }
        assert!(t.get(&InstrId(15)).is_none());
        assert!(!t.contains_key(&InstrId(50)));
        // Inserted after the index was built: found through it.
        t.insert(InstrId(5), info(9, Type::INT));
        assert_eq!(t.get(&InstrId(5)).unwrap().cr_after, Some(Type::INT));
    }

    /// Sema's way in (each id once, out of order across bodies): a hint up to `NEAR` entries off finds
    /// the instruction without building the index; one further off, or an absent id, goes through the
    /// index, which then answers as before.
    #[test]
    fn a_hint_a_few_entries_off_finds_the_instruction_without_the_index() {
        let mut t = InstrTable::default();
        let ix = t.intern(info(0, Type::BOOL).split().1);
        // two bodies: ids 1000.. then 10.. (a separate allocation at a lower address)
        let ids: Vec<usize> = (0..100)
            .map(|k| 1000 + 8 * k)
            .chain((0..100).map(|k| 10 + 8 * k))
            .collect();
        for (pos, &id) in ids.iter().enumerate() {
            t.insert_interned(InstrId(id), Span::new(crate::FileId(0), pos, pos + 1), ix);
        }
        for (pos, &id) in ids.iter().enumerate() {
            for hint in [
                pos,
                pos + 1,
                pos + NEAR,
                pos.saturating_sub(1),
                pos.saturating_sub(NEAR),
            ] {
                let (at, r) = t.get_near(InstrId(id), hint).unwrap();
                assert_eq!((at, r.span.start), (pos, pos as u32), "id {id} hint {hint}");
            }
        }
        assert!(
            t.index.get().is_none(),
            "no lookup within NEAR builds the index"
        );
        // further off, and absent: the index, built once, finds it (or nothing)
        assert_eq!(t.get_near(InstrId(10), 0).map(|(at, _)| at), Some(100));
        assert!(t.index.get().is_some());
        assert!(t.get_near(InstrId(11), 100).is_none());
        assert!(t.get_near(InstrId(11), 5000).is_none());
        assert_eq!(t.get_near(InstrId(1008), 50).map(|(at, _)| at), Some(1));
        assert_eq!(
            t.get_near(InstrId(1008), usize::MAX).map(|(at, _)| at),
            Some(1)
        );
    }

    /// With each body's start marked (as sema does), a reader whose hint is still in another body finds
    /// a body's first instruction without the index; other far lookups still build it.
    #[test]
    fn a_body_s_first_instruction_is_found_from_anywhere() {
        let mut t = InstrTable::default();
        let ix = t.intern(info(0, Type::BOOL).split().1);
        let bodies: [Vec<usize>; 3] = [
            (0..100).map(|k| 1000 + 8 * k).collect(),
            (0..100).map(|k| 10 + 8 * k).collect(),
            (0..100).map(|k| 5000 + 8 * k).collect(),
        ];
        for body in &bodies {
            t.start_body();
            for &id in body {
                let at = t.len();
                t.insert_interned(InstrId(id), Span::new(crate::FileId(0), at, at + 1), ix);
            }
        }
        // the C back end's order: the last body first, then the first, then the middle one
        for (b, hint) in [(2, 0), (0, 300), (1, 100), (1, 0)] {
            let (at, _) = t.get_near(InstrId(bodies[b][0]), hint).unwrap();
            assert_eq!(at, 100 * b);
        }
        assert!(t.index.get().is_none());
        assert_eq!(t.get_near(InstrId(18), 250).map(|(at, _)| at), Some(101));
        assert!(t.index.get().is_some());
    }

    /// Facts with a small key (elementary or no types, no callee or a standard function on elementary
    /// types, no arguments) and without one (another type, another callee) are each stored once and
    /// read back as given; facts differing in any one of the three types, or in the function, are
    /// different.
    #[test]
    fn equal_facts_are_stored_once_with_or_without_a_small_key() {
        let types = [
            None,
            Some(Type::BOOL),
            Some(Type::INT),
            Some(Type::String {
                wide: false,
                len: 8,
            }),
        ];
        let mut all = Vec::new();
        for a in &types {
            for b in &types {
                for c in &types {
                    for callee in [
                        None,
                        Some(Callee::Embedded { name: "f".into() }),
                        Some(Callee::Std {
                            name: "ADD",
                            ty: Type::INT,
                            result: Type::INT,
                        }),
                        Some(Callee::Std {
                            name: "GT",
                            ty: Type::INT,
                            result: Type::BOOL,
                        }),
                        Some(Callee::Std {
                            name: "GT",
                            ty: Type::String {
                                wide: false,
                                len: 8,
                            },
                            result: Type::BOOL,
                        }),
                    ] {
                        all.push(InstrFacts {
                            cr_before: a.clone(),
                            cr_after: b.clone(),
                            operand: c.clone(),
                            callee,
                            args: Vec::new(),
                        });
                    }
                }
            }
        }
        let mut t = InstrTable::default();
        for round in 0..2 {
            for (i, f) in all.iter().enumerate() {
                let id = InstrId(round * all.len() + i);
                let ix = t.intern(f.clone());
                t.insert_interned(id, Span::new(diagnostics::FileId(0), i, i), ix);
                assert_eq!(t.get(&id).unwrap().facts, f, "{f:?}");
            }
            assert_eq!(t.distinct_facts(), all.len());
        }
        assert!(simple_key(&all[0]).is_some() && simple_key(&all[1]).is_none());
        assert!(simple_key(&all[2]).is_some() && simple_key(&all[4]).is_none());
        // the same standard function named by a string at another address: a second key, the same
        // stored facts
        let mut moved = all[2].clone();
        let add: &'static str = Box::leak(String::from("ADD").into_boxed_str());
        if let Some(Callee::Std { name, .. }) = &mut moved.callee {
            *name = add;
        }
        assert_ne!(simple_key(&moved), simple_key(&all[2]));
        assert_eq!(t.intern(moved.clone()), t.intern(all[2].clone()));
        assert_eq!(t.distinct_facts(), all.len());
        // differing in the function, its type or its result: other facts
        let mut gt_bool = all[3].clone();
        if let Some(Callee::Std { result, .. }) = &mut gt_bool.callee {
            *result = Type::INT;
        }
        assert_ne!(t.intern(gt_bool), t.intern(all[3].clone()));
    }

    /// In increasing order the table bisects; an id recorded twice answers with the later info.
    #[test]
    fn sorted_lookups_and_a_repeated_id() {
        let mut t = InstrTable::default();
        for id in 1..=100 {
            t.insert(InstrId(id), info(id as u32, Type::BOOL));
        }
        assert_eq!(t.get(&InstrId(57)).unwrap().span.start, 57);
        t.insert(InstrId(57), info(999, Type::INT));
        let later = t.get(&InstrId(57)).unwrap();
        assert_eq!(
            (later.span.start, later.cr_after.clone()),
            (999, Some(Type::INT))
        );
        let (at, near) = t.get_near(InstrId(57), 56).unwrap();
        assert_eq!((at, near.span.start), (100, 999));
    }
}

#[cfg(test)]
mod var_index_tests {
    use super::*;
    use diagnostics::FileId;

    fn pou_with(names: &[&str]) -> Pou {
        let vars = names
            .iter()
            .enumerate()
            .map(|(i, n)| Variable {
                name: n.to_string(),
                span: Span::new(FileId(0), i, i + 1),
                kind: VarKind::Local,
                ty: Type::Elementary(Elementary::Int),
                constant: false,
                retain: false,
                location: None,
                init: None,
                edge: None,
            })
            .collect();
        let mut pou = Pou {
            name: "P".into(),
            span: Span::new(FileId(0), 0, 1),
            kind: PouKind::Program,
            return_type: None,
            vars: Vec::new(),
            externals: Vec::new(),
            instrs: Vec::new(),
            var_index: Default::default(),
            class: false,
            access: Vec::new(),
        };
        pou.set_vars(vars);
        pou
    }

    #[test]
    fn variables_are_found_by_name_in_any_case() {
        let names: Vec<String> = (0..300).map(|i| format!("Var_{i}")).collect();
        let refs: Vec<&str> = names.iter().map(String::as_str).collect();
        let pou = pou_with(&refs);
        for (i, n) in names.iter().enumerate() {
            assert_eq!(pou.var_position(n), Some(i));
            assert_eq!(pou.var_position(&n.to_ascii_uppercase()), Some(i));
            assert_eq!(pou.var_position(&n.to_ascii_lowercase()), Some(i));
        }
        for absent in ["Var_300", "Var_", "", "var_1x", "x"] {
            assert_eq!(pou.var_position(absent), None, "{absent}");
        }
        assert_eq!(pou.var("VAR_7").map(|v| v.name.as_str()), Some("Var_7"));
    }

    #[test]
    fn variables_added_after_the_index_are_found_by_search() {
        let mut pou = pou_with(&["a", "b"]);
        let mut extra = pou.vars[0].clone();
        extra.name = "Late".into();
        pou.vars.push(extra);
        assert_eq!(pou.var_position("LATE"), Some(2));
        assert_eq!(pou.var_position("B"), Some(1));
    }
}
