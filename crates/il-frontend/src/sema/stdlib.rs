//! The IEC 61131-3 standard library catalogue: standard functions with their generic signatures, the
//! type-conversion functions, and the standard function blocks with their inputs and outputs.
//!
//! Input: names as written (case-insensitive). Output: static descriptions ([`StdFunction`],
//! [`Conversion`], [`FbParam`] lists). Invariants: one table ([`FUNCTIONS`]) lists every standard
//! function; the parameters marked [`ParamTy::T`] of one function share one type (the function's generic
//! type, instantiated per call by `sema`); time arithmetic (`ADD_TIME` ...) is the table [`TIME_ARITH`].

use super::model::{Elementary, StdFb, Type};
use Elementary as E;

/// A generic type class of IEC 61131-3 (Figure 5 of edition 2 / Figure 11 of edition 3).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Class {
    /// Every type (SEL, MUX, MOVE).
    Any,
    /// Elementary types, strings, enumerations (comparisons, LIMIT, MAX, MIN).
    AnyElementary,
    /// ANY_NUM: integers and reals (ADD, ABS ...).
    AnyNum,
    /// ANY_REAL: REAL, LREAL (SQRT, SIN ...).
    AnyReal,
    /// ANY_INT: signed and unsigned integers (MOD).
    AnyInt,
    /// ANY_BIT: BOOL, BYTE, WORD, DWORD, LWORD (AND, SHL ...).
    AnyBit,
    /// STRING and WSTRING (LEN, LEFT, CONCAT ...).
    AnyString,
    /// ANY_INT, ANY_BIT and ANY_REAL: the types of edition 3's endianness conversions.
    AnyNumBit,
}

impl Class {
    /// The class's IEC name (`ANY_NUM`), for messages.
    pub fn name(self) -> &'static str {
        match self {
            Class::Any => "ANY",
            Class::AnyElementary => "ANY_ELEMENTARY",
            Class::AnyNum => "ANY_NUM",
            Class::AnyReal => "ANY_REAL",
            Class::AnyInt => "ANY_INT",
            Class::AnyBit => "ANY_BIT",
            Class::AnyString => "ANY_STRING",
            Class::AnyNumBit => "ANY_INT, ANY_BIT or ANY_REAL",
        }
    }
    /// Whether `ty` belongs to the class (`Type::Error` belongs to every class).
    pub fn contains(self, ty: &Type) -> bool {
        if ty.is_error() {
            return true;
        }
        match self {
            Class::Any => true,
            Class::AnyElementary => matches!(
                ty,
                Type::Elementary(_) | Type::Subrange { .. } | Type::String { .. } | Type::Enum(_)
            ),
            Class::AnyNum => ty.is_numeric(),
            Class::AnyReal => ty.is_real(),
            Class::AnyInt => ty.is_integer(),
            Class::AnyBit => ty.is_bit(),
            Class::AnyString => ty.is_string(),
            Class::AnyNumBit => ty.is_numeric() || ty.is_bit(),
        }
    }
    /// Whether an untyped integer literal may take a type of this class (it can be any ANY_NUM or ANY_BIT).
    pub fn accepts_int_literal(self) -> bool {
        !matches!(self, Class::AnyReal | Class::AnyString)
    }
    /// Whether an untyped real literal may take a type of this class.
    pub fn accepts_real_literal(self) -> bool {
        matches!(
            self,
            Class::Any | Class::AnyElementary | Class::AnyNum | Class::AnyReal
        )
    }
}

/// The type of a standard function parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamTy {
    /// The function's generic type `T`, which must belong to the class (all `T` parameters share it).
    T(Class),
    /// A parameter with its own, independent generic type of the class (`N` of SHL, `K` of MUX).
    Own(Class),
    /// A fixed type (`G : BOOL` of SEL).
    Fixed(Elementary),
}

/// The result type of a standard function.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ret {
    /// The generic type `T`.
    T,
    /// A fixed type (`INT` for LEN, `BOOL` for comparisons).
    Fixed(Elementary),
}

/// One formal input parameter of a standard function.
#[derive(Debug, Clone, Copy)]
pub struct Param {
    /// The formal name (`IN1`, `MN`, `G`), used in formal calls `LIMIT(MN := 0, ...)`.
    pub name: &'static str,
    /// Its type, generic or fixed.
    pub ty: ParamTy,
}

/// The most inputs one non-formal call of an extensible function (`ADD a, b, ...`, `MUX(k, ...)`,
/// `MAX(...)`) may pass (E1020 beyond). The generated C folds the inputs into one expression nested as
/// deep as their count, so an unbounded list would cost time quadratic in its length (and a C compiler
/// a recursion as deep); formal calls are bounded by [`StdFunction::param_index`].
pub const MAX_EXTENSIBLE_INPUTS: usize = 1000;

/// A standard function.
#[derive(Debug, Clone, Copy)]
pub struct StdFunction {
    /// The function's name, upper case (`LIMIT`).
    pub name: &'static str,
    /// The inputs in order; in IL the current result is the first one.
    pub params: &'static [Param],
    /// Extensible: the last parameter repeats (`IN1, IN2, IN3 ...` for ADD; `IN0, IN1, IN2 ...` for MUX);
    /// repeated names count on from the last one's number.
    pub extensible: bool,
    /// The result type.
    pub result: Ret,
    /// Whether `TIME_ARITH` overloads apply (ADD, SUB, MUL, DIV).
    pub time_arith: bool,
    /// One line on what the function computes (`"IN1 modulo IN2 (0 when IN2 = 0)"`), for tools that list
    /// the standard functions.
    pub doc: &'static str,
}

const fn p(name: &'static str, ty: ParamTy) -> Param {
    Param { name, ty }
}

use Class::*;
use ParamTy::{Fixed, Own, T};

const NUM2: &[Param] = &[p("IN1", T(AnyNum)), p("IN2", T(AnyNum))];
const INT2: &[Param] = &[p("IN1", T(AnyInt)), p("IN2", T(AnyInt))];
const BIT2: &[Param] = &[p("IN1", T(AnyBit)), p("IN2", T(AnyBit))];
const ELEM2: &[Param] = &[p("IN1", T(AnyElementary)), p("IN2", T(AnyElementary))];
const NUM1: &[Param] = &[p("IN", T(AnyNum))];
const REAL1: &[Param] = &[p("IN", T(AnyReal))];
const SHIFT: &[Param] = &[p("IN", T(AnyBit)), p("N", Own(AnyInt))];
const fn fx2(a: Elementary, b: Elementary) -> [Param; 2] {
    [p("IN1", Fixed(a)), p("IN2", Fixed(b))]
}
const TIME_NUM: &[Param] = &[p("IN1", Fixed(E::Time)), p("IN2", Own(AnyNum))];
const LTIME_NUM: &[Param] = &[p("IN1", Fixed(E::Ltime)), p("IN2", Own(AnyNum))];
const STR1: &[Param] = &[p("IN", T(AnyString))];
const STR2: &[Param] = &[p("IN1", T(AnyString)), p("IN2", T(AnyString))];
const STR_L: &[Param] = &[p("IN", T(AnyString)), p("L", Own(AnyInt))];
const STR_LP: &[Param] = &[
    p("IN", T(AnyString)),
    p("L", Own(AnyInt)),
    p("P", Own(AnyInt)),
];

const fn f(
    name: &'static str,
    params: &'static [Param],
    extensible: bool,
    result: Ret,
    doc: &'static str,
) -> StdFunction {
    StdFunction {
        name,
        params,
        extensible,
        result,
        time_arith: false,
        doc,
    }
}

const fn ft(
    name: &'static str,
    params: &'static [Param],
    extensible: bool,
    doc: &'static str,
) -> StdFunction {
    StdFunction {
        name,
        params,
        extensible,
        result: Ret::T,
        time_arith: true,
        doc,
    }
}

/// Every standard function except the conversions (see [`conversion`]).
pub static FUNCTIONS: &[StdFunction] = &[
    // arithmetic
    ft("ADD", NUM2, true, "IN1 + IN2 + ...; also ADD_TIME, ADD_TOD_TIME, ADD_DT_TIME"),
    ft("SUB", NUM2, false, "IN1 - IN2; also SUB_TIME, SUB_DATE_DATE, SUB_TOD_TIME, SUB_TOD_TOD, SUB_DT_TIME, SUB_DT_DT"),
    ft("MUL", NUM2, true, "IN1 * IN2 * ...; also MUL_TIME (TIME * ANY_NUM)"),
    ft("DIV", NUM2, false, "IN1 / IN2 (integers: truncated toward zero); also DIV_TIME (TIME / ANY_NUM)"),
    f("MOD", INT2, false, Ret::T, "IN1 modulo IN2 (0 when IN2 = 0)"),
    f("EXPT", &[p("IN1", T(AnyReal)), p("IN2", Own(AnyNum))], false, Ret::T, "IN1 ** IN2"),
    f("MOVE", &[p("IN", T(Any))], false, Ret::T, "the input unchanged"),
    // numeric functions
    f("ABS", NUM1, false, Ret::T, "absolute value"),
    f("SQRT", REAL1, false, Ret::T, "square root"),
    // edition 3: whether a real is a number (neither NaN nor an infinity), whether a bit string
    // holds BCD (every nibble 0..9)
    f("IS_VALID", REAL1, false, Ret::Fixed(E::Bool), "TRUE unless IN is NaN or an infinity"),
    f("IS_VALID_BCD", &[p("IN", T(AnyBit))], false, Ret::Fixed(E::Bool), "TRUE when every 4-bit digit of IN is 0..9"),
    f("LN", REAL1, false, Ret::T, "natural logarithm"),
    f("LOG", REAL1, false, Ret::T, "logarithm base 10"),
    f("EXP", REAL1, false, Ret::T, "natural exponential"),
    f("SIN", REAL1, false, Ret::T, "sine (radians)"),
    f("COS", REAL1, false, Ret::T, "cosine (radians)"),
    f("TAN", REAL1, false, Ret::T, "tangent (radians)"),
    f("ASIN", REAL1, false, Ret::T, "arc sine"),
    f("ACOS", REAL1, false, Ret::T, "arc cosine"),
    f("ATAN", REAL1, false, Ret::T, "arc tangent"),
    // comparisons (extensible: IN1 > IN2 AND IN2 > IN3 ...)
    f("GT", ELEM2, true, Ret::Fixed(E::Bool), "IN1 > IN2 > ..."),
    f("GE", ELEM2, true, Ret::Fixed(E::Bool), "IN1 >= IN2 >= ..."),
    f("EQ", ELEM2, true, Ret::Fixed(E::Bool), "IN1 = IN2 = ..."),
    f("NE", ELEM2, false, Ret::Fixed(E::Bool), "IN1 <> IN2"),
    f("LE", ELEM2, true, Ret::Fixed(E::Bool), "IN1 <= IN2 <= ..."),
    f("LT", ELEM2, true, Ret::Fixed(E::Bool), "IN1 < IN2 < ..."),
    // bitwise / boolean
    f("AND", BIT2, true, Ret::T, "bitwise AND"),
    f("OR", BIT2, true, Ret::T, "bitwise OR"),
    f("XOR", BIT2, true, Ret::T, "bitwise exclusive OR"),
    f("NOT", &[p("IN", T(AnyBit))], false, Ret::T, "bitwise complement"),
    // bit shifts
    f("SHL", SHIFT, false, Ret::T, "shift left by N bits, zero fill"),
    f("SHR", SHIFT, false, Ret::T, "shift right by N bits, zero fill"),
    f("ROL", SHIFT, false, Ret::T, "rotate left by N bits"),
    f("ROR", SHIFT, false, Ret::T, "rotate right by N bits"),
    // selection
    f("SEL", &[p("G", Fixed(E::Bool)), p("IN0", T(Any)), p("IN1", T(Any))], false, Ret::T, "IN0 if G is FALSE, else IN1"),
    f("MAX", ELEM2, true, Ret::T, "the largest input"),
    f("MIN", ELEM2, true, Ret::T, "the smallest input"),
    f(
        "LIMIT",
        &[p("MN", T(AnyElementary)), p("IN", T(AnyElementary)), p("MX", T(AnyElementary))],
        false,
        Ret::T,
        "IN bounded to MN..MX",
    ),
    f("MUX", &[p("K", Own(AnyInt)), p("IN0", T(Any)), p("IN1", T(Any))], true, Ret::T, "the K-th of IN0, IN1, ..."),
    // character strings (positions count from 1; see the C backend README for out-of-range arguments)
    f("LEN", STR1, false, Ret::Fixed(E::Int), "the length of IN in characters"),
    f("LEFT", STR_L, false, Ret::T, "the leftmost L characters of IN"),
    f("RIGHT", STR_L, false, Ret::T, "the rightmost L characters of IN"),
    f("MID", STR_LP, false, Ret::T, "L characters of IN from the P-th"),
    f("CONCAT", STR2, true, Ret::T, "IN1, IN2, ... one after the other"),
    f(
        "INSERT",
        &[p("IN1", T(AnyString)), p("IN2", T(AnyString)), p("P", Own(AnyInt))],
        false,
        Ret::T,
        "IN2 inserted into IN1 after its P-th character",
    ),
    f("DELETE", STR_LP, false, Ret::T, "IN without the L characters from the P-th"),
    f(
        "REPLACE",
        &[p("IN1", T(AnyString)), p("IN2", T(AnyString)), p("L", Own(AnyInt)), p("P", Own(AnyInt))],
        false,
        Ret::T,
        "IN1 with its L characters from the P-th replaced by IN2",
    ),
    f("FIND", STR2, false, Ret::Fixed(E::Int), "the position of the first IN2 in IN1 (0: none)"),
    // time and date functions with typed names (the overloads of TIME_ARITH, callable by name)
    f("ADD_TIME", &fx2(E::Time, E::Time), false, Ret::Fixed(E::Time), "TIME + TIME"),
    f("ADD_LTIME", &fx2(E::Ltime, E::Ltime), false, Ret::Fixed(E::Ltime), "LTIME + LTIME"),
    f("ADD_TOD_TIME", &fx2(E::Tod, E::Time), false, Ret::Fixed(E::Tod), "TOD + TIME"),
    f("ADD_DT_TIME", &fx2(E::Dt, E::Time), false, Ret::Fixed(E::Dt), "DT + TIME"),
    f("SUB_TIME", &fx2(E::Time, E::Time), false, Ret::Fixed(E::Time), "TIME - TIME"),
    f("SUB_LTIME", &fx2(E::Ltime, E::Ltime), false, Ret::Fixed(E::Ltime), "LTIME - LTIME"),
    f("SUB_DATE_DATE", &fx2(E::Date, E::Date), false, Ret::Fixed(E::Time), "DATE - DATE"),
    f("SUB_TOD_TIME", &fx2(E::Tod, E::Time), false, Ret::Fixed(E::Tod), "TOD - TIME"),
    f("SUB_TOD_TOD", &fx2(E::Tod, E::Tod), false, Ret::Fixed(E::Time), "TOD - TOD"),
    f("SUB_DT_TIME", &fx2(E::Dt, E::Time), false, Ret::Fixed(E::Dt), "DT - TIME"),
    f("SUB_DT_DT", &fx2(E::Dt, E::Dt), false, Ret::Fixed(E::Time), "DT - DT"),
    f("MUL_TIME", TIME_NUM, false, Ret::Fixed(E::Time), "TIME * ANY_NUM"),
    f("MUL_LTIME", LTIME_NUM, false, Ret::Fixed(E::Ltime), "LTIME * ANY_NUM"),
    f("DIV_TIME", TIME_NUM, false, Ret::Fixed(E::Time), "TIME / ANY_NUM (0 for a zero divisor)"),
    f("DIV_LTIME", LTIME_NUM, false, Ret::Fixed(E::Ltime), "LTIME / ANY_NUM (0 for a zero divisor)"),
    f("CONCAT_DATE_TOD", &fx2(E::Date, E::Tod), false, Ret::Fixed(E::Dt), "the DT of a DATE at a TOD"),
    // edition 3's long dates (Table 36)
    f("ADD_LTOD_LTIME", &fx2(E::Ltod, E::Ltime), false, Ret::Fixed(E::Ltod), "LTOD + LTIME"),
    f("ADD_LDT_LTIME", &fx2(E::Ldt, E::Ltime), false, Ret::Fixed(E::Ldt), "LDT + LTIME"),
    f("SUB_LDATE_LDATE", &fx2(E::Ldate, E::Ldate), false, Ret::Fixed(E::Ltime), "LDATE - LDATE"),
    f("SUB_LTOD_LTIME", &fx2(E::Ltod, E::Ltime), false, Ret::Fixed(E::Ltod), "LTOD - LTIME"),
    f("SUB_LTOD_LTOD", &fx2(E::Ltod, E::Ltod), false, Ret::Fixed(E::Ltime), "LTOD - LTOD"),
    f("SUB_LDT_LTIME", &fx2(E::Ldt, E::Ltime), false, Ret::Fixed(E::Ldt), "LDT - LTIME"),
    f("SUB_LDT_LDT", &fx2(E::Ldt, E::Ldt), false, Ret::Fixed(E::Ltime), "LDT - LDT"),
    f("CONCAT_LDATE_LTOD", &fx2(E::Ldate, E::Ltod), false, Ret::Fixed(E::Ldt), "the LDT of an LDATE at an LTOD"),
    // CODESYS and TwinCAT: `TIME()` is the time since the controller started (here the scan
    // clock, the time of the current cycle, as the timers read it)
    f("TIME", &[], false, Ret::Fixed(E::Time), "the time since start (the scan clock; CODESYS, TwinCAT)"),
    // CODESYS's `LTIME()`: the same clock as an LTIME (its help: "the time since system start,
    // in nanoseconds")
    f("LTIME", &[], false, Ret::Fixed(E::Ltime), "the time since start as an LTIME (the scan clock; CODESYS)"),
    // edition 3 (Table 37): dates and times from their parts; an invalid part gives 0 and the range flag
    f(
        "CONCAT_DATE",
        &[p("YEAR", Own(AnyInt)), p("MONTH", Own(AnyInt)), p("DAY", Own(AnyInt))],
        false,
        Ret::Fixed(E::Date),
        "the DATE of a year, month (1..12) and day (1..31)",
    ),
    f(
        "CONCAT_TOD",
        &[p("HOUR", Own(AnyInt)), p("MINUTE", Own(AnyInt)), p("SECOND", Own(AnyInt)), p("MILLISECOND", Own(AnyInt))],
        false,
        Ret::Fixed(E::Tod),
        "the TOD of an hour (0..23), minute, second (0..59) and millisecond (0..999)",
    ),
    f(
        "CONCAT_DT",
        &[
            p("YEAR", Own(AnyInt)),
            p("MONTH", Own(AnyInt)),
            p("DAY", Own(AnyInt)),
            p("HOUR", Own(AnyInt)),
            p("MINUTE", Own(AnyInt)),
            p("SECOND", Own(AnyInt)),
            p("MILLISECOND", Own(AnyInt)),
        ],
        false,
        Ret::Fixed(E::Dt),
        "the DT of CONCAT_DATE and CONCAT_TOD's parts",
    ),
    f(
        "CONCAT_LTOD",
        &[p("HOUR", Own(AnyInt)), p("MINUTE", Own(AnyInt)), p("SECOND", Own(AnyInt)), p("MILLISECOND", Own(AnyInt))],
        false,
        Ret::Fixed(E::Ltod),
        "the LTOD of an hour (0..23), minute, second (0..59) and millisecond (0..999)",
    ),
    f(
        "CONCAT_LDT",
        &[
            p("YEAR", Own(AnyInt)),
            p("MONTH", Own(AnyInt)),
            p("DAY", Own(AnyInt)),
            p("HOUR", Own(AnyInt)),
            p("MINUTE", Own(AnyInt)),
            p("SECOND", Own(AnyInt)),
            p("MILLISECOND", Own(AnyInt)),
        ],
        false,
        Ret::Fixed(E::Ldt),
        "the LDT of CONCAT_DATE and CONCAT_LTOD's parts",
    ),
    f("DAY_OF_WEEK", &[p("IN", Fixed(E::Date))], false, Ret::Fixed(E::Int), "the day of the week of a DATE: 0 Sunday ... 6 Saturday"),
    // edition 3: endianness conversions (on any host: the bytes in memory, not the value, are ordered)
    f("TO_BIG_ENDIAN", &[p("IN", T(AnyNumBit))], false, Ret::T, "the value whose bytes in memory are IN's, most significant first"),
    f("TO_LITTLE_ENDIAN", &[p("IN", T(AnyNumBit))], false, Ret::T, "the value whose bytes in memory are IN's, least significant first"),
    f("FROM_BIG_ENDIAN", &[p("IN", T(AnyNumBit))], false, Ret::T, "the value whose bytes, most significant first, are IN's in memory"),
    f("FROM_LITTLE_ENDIAN", &[p("IN", T(AnyNumBit))], false, Ret::T, "the value whose bytes, least significant first, are IN's in memory"),
];

/// One of edition 3's functions with outputs, `SPLIT_DATE`, `SPLIT_TOD`, `SPLIT_LTOD`, `SPLIT_DT`,
/// `SPLIT_LDT` (Table 36): the input `IN` and the parts it splits into, each an ANY_INT output.
#[derive(Debug, Clone, Copy)]
pub struct Split {
    /// The function's name, upper case.
    pub name: &'static str,
    /// The type of `IN`.
    pub input: Elementary,
    /// The outputs in order (a subset of [`SPLIT_PARTS`]).
    pub outputs: &'static [&'static str],
}

/// Every part a SPLIT function gives, in the order of `ladderc_split`'s array, with its range
/// (DATE and DT span 1677-09-22 .. 2262-04-11 here, int64 nanoseconds).
pub const SPLIT_PARTS: [(&str, i128, i128); 7] = [
    ("YEAR", 1677, 2262),
    ("MONTH", 1, 12),
    ("DAY", 1, 31),
    ("HOUR", 0, 23),
    ("MINUTE", 0, 59),
    ("SECOND", 0, 59),
    ("MILLISECOND", 0, 999),
];

const DATE_PARTS: &[&str] = &["YEAR", "MONTH", "DAY"];
const TOD_PARTS: &[&str] = &["HOUR", "MINUTE", "SECOND", "MILLISECOND"];
const DT_PARTS: &[&str] = &[
    "YEAR",
    "MONTH",
    "DAY",
    "HOUR",
    "MINUTE",
    "SECOND",
    "MILLISECOND",
];

/// Edition 3's SPLIT functions (Table 36; the 4diac FORTE and trust-platform signatures).
pub const SPLITS: [Split; 5] = [
    Split {
        name: "SPLIT_DATE",
        input: E::Date,
        outputs: DATE_PARTS,
    },
    Split {
        name: "SPLIT_TOD",
        input: E::Tod,
        outputs: TOD_PARTS,
    },
    Split {
        name: "SPLIT_LTOD",
        input: E::Ltod,
        outputs: TOD_PARTS,
    },
    Split {
        name: "SPLIT_DT",
        input: E::Dt,
        outputs: DT_PARTS,
    },
    Split {
        name: "SPLIT_LDT",
        input: E::Ldt,
        outputs: DT_PARTS,
    },
];

/// A SPLIT function by name, case-insensitively.
pub fn split(name: &str) -> Option<&'static Split> {
    SPLITS.iter().find(|f| f.name.eq_ignore_ascii_case(name))
}

/// Whether the standard function `name` (upper case, as [`StdFunction::name`]) is one edition 3 added
/// to edition 2's (Table 37's `CONCAT_DATE`, `CONCAT_TOD`, `CONCAT_DT`, `DAY_OF_WEEK`): libraries
/// written for edition 2 (OSCAT) declare functions of these names, and a call of the name calls the
/// project's own FUNCTION.
pub fn edition3_only(name: &str) -> bool {
    matches!(
        name,
        "CONCAT_DATE"
            | "CONCAT_TOD"
            | "CONCAT_DT"
            | "CONCAT_LTOD"
            | "CONCAT_LDT"
            | "DAY_OF_WEEK"
            | "TO_BIG_ENDIAN"
            | "TO_LITTLE_ENDIAN"
            | "FROM_BIG_ENDIAN"
            | "FROM_LITTLE_ENDIAN"
    )
}

/// Looks up a standard function (not a conversion) by name, case-insensitively. Also the edition 2
/// spellings `MULTIME`/`DIVTIME` (edition 3: `MUL_TIME`/`DIV_TIME`) and the typed names of the
/// overloaded functions (`ADD_INT`, `MAX_REAL`, `SEL_TIME`, `MUX_INT_DINT`; see [`typed_name`]), which
/// give the generic function.
pub fn function(name: &str) -> Option<&'static StdFunction> {
    let exact = |n: &str| FUNCTIONS.iter().find(|f| f.name.eq_ignore_ascii_case(n));
    if let Some(f) = exact(name) {
        return Some(f);
    }
    if name.eq_ignore_ascii_case("MULTIME") {
        return exact("MUL_TIME");
    }
    if name.eq_ignore_ascii_case("DIVTIME") {
        return exact("DIV_TIME");
    }
    typed_name(name).map(|(f, _)| f)
}

/// A typed name of an overloaded standard function (IEC 61131-3 edition 2, 2.5.1.4; the names matiec
/// and CODESYS read): `ADD_INT` is ADD with its generic type T fixed to INT, `MUX_INT_DINT` is MUX with
/// K : INT and T : DINT (`K` is only checked to be ANY_INT). The function and the type of T; `None`
/// when the function has no generic T or the type is not of its class.
///
/// TwinCAT's Tc2_Standard names its WSTRING string functions `WLEN`, `WLEFT`, `WRIGHT`, `WMID`,
/// `WCONCAT`, `WINSERT`, `WDELETE`, `WREPLACE`, `WFIND` (Beckhoff Infosys, Tc2_Standard, "WMID":
/// `FUNCTION WMID : WSTRING(255)`, inputs `STR`, `LEN`, `POS`, as MID's): each is its string
/// function with T fixed to WSTRING, [`tc2_wstring_function`].
pub fn typed_name(name: &str) -> Option<(&'static StdFunction, Type)> {
    let up = name.to_ascii_uppercase();
    if let Some(base) = tc2_wstring_function(&up) {
        let f = FUNCTIONS.iter().find(|f| f.name == base)?;
        return Some((f, conv_type("WSTRING")?));
    }
    let (base, ty) = up.split_once('_')?;
    let f = FUNCTIONS.iter().find(|f| f.name == base)?;
    let ty = if f.name == "MUX" {
        let (k, t) = ty.split_once('_')?;
        conv_type(k).filter(|k| k.is_integer())?;
        t
    } else {
        ty
    };
    let t = conv_type(ty)?;
    let class = f.params.iter().find_map(|p| match p.ty {
        ParamTy::T(c) => Some(c),
        _ => None,
    })?;
    class.contains(&t).then_some((f, t))
}

/// The string function a Tc2_Standard WSTRING function (`WMID`, upper case) is, with T fixed to
/// WSTRING ([`typed_name`]).
pub fn tc2_wstring_function(up: &str) -> Option<&'static str> {
    const STRING_FUNCTIONS: [&str; 9] = [
        "LEN", "LEFT", "RIGHT", "MID", "CONCAT", "INSERT", "DELETE", "REPLACE", "FIND",
    ];
    let rest = up.strip_prefix('W')?;
    STRING_FUNCTIONS.into_iter().find(|f| *f == rest)
}

impl StdFunction {
    /// The name of the `i`-th input (extensible functions number on: `IN3`, `IN4` ...).
    pub fn param_name(&self, i: usize) -> String {
        if let Some(p) = self.params.get(i) {
            return p.name.to_string();
        }
        let last = self.params.last().map(|p| p.name).unwrap_or("IN");
        let digits = last.trim_start_matches(|c: char| !c.is_ascii_digit());
        let stem = &last[..last.len() - digits.len()];
        let n: usize = digits.parse().unwrap_or(0);
        format!("{stem}{}", n + (i + 1 - self.params.len()))
    }
    /// The type of the `i`-th input (repeats the last for extensible functions); `None` past the end.
    pub fn param_ty(&self, i: usize) -> Option<ParamTy> {
        match self.params.get(i) {
            Some(p) => Some(p.ty),
            None if self.extensible => self.params.last().map(|p| p.ty),
            None => None,
        }
    }
    /// The index of a formal input name (`IN3` of an extensible function too; a string function's
    /// input also by its CODESYS/TwinCAT name, [`vendor_string_param`]).
    pub fn param_index(&self, name: &str) -> Option<usize> {
        let own = |name: &str| {
            self.params
                .iter()
                .position(|p| p.name.eq_ignore_ascii_case(name))
        };
        if let Some(i) = own(name) {
            return Some(i);
        }
        if let Some(i) = vendor_string_param(self.name, name).and_then(own) {
            return Some(i);
        }
        if !self.extensible {
            return None;
        }
        (self.params.len()..self.params.len() + 64)
            .find(|&i| self.param_name(i).eq_ignore_ascii_case(name))
    }
}

/// An overload of ADD/SUB/MUL/DIV on times and dates: `(name, operator, IN1, IN2, result)`; `None` for
/// IN2 means any ANY_NUM (MUL_TIME, DIV_TIME).
pub static TIME_ARITH: &[(&str, &str, E, Option<E>, E)] = &[
    ("ADD_TIME", "ADD", E::Time, Some(E::Time), E::Time),
    ("ADD_LTIME", "ADD", E::Ltime, Some(E::Ltime), E::Ltime),
    ("ADD_TOD_TIME", "ADD", E::Tod, Some(E::Time), E::Tod),
    ("ADD_DT_TIME", "ADD", E::Dt, Some(E::Time), E::Dt),
    ("SUB_TIME", "SUB", E::Time, Some(E::Time), E::Time),
    ("SUB_LTIME", "SUB", E::Ltime, Some(E::Ltime), E::Ltime),
    ("SUB_DATE_DATE", "SUB", E::Date, Some(E::Date), E::Time),
    ("SUB_TOD_TIME", "SUB", E::Tod, Some(E::Time), E::Tod),
    ("SUB_TOD_TOD", "SUB", E::Tod, Some(E::Tod), E::Time),
    ("SUB_DT_TIME", "SUB", E::Dt, Some(E::Time), E::Dt),
    ("SUB_DT_DT", "SUB", E::Dt, Some(E::Dt), E::Time),
    ("MUL_TIME", "MUL", E::Time, None, E::Time),
    ("MUL_LTIME", "MUL", E::Ltime, None, E::Ltime),
    ("DIV_TIME", "DIV", E::Time, None, E::Time),
    ("DIV_LTIME", "DIV", E::Ltime, None, E::Ltime),
    ("ADD_LTOD_LTIME", "ADD", E::Ltod, Some(E::Ltime), E::Ltod),
    ("ADD_LDT_LTIME", "ADD", E::Ldt, Some(E::Ltime), E::Ldt),
    ("SUB_LDATE_LDATE", "SUB", E::Ldate, Some(E::Ldate), E::Ltime),
    ("SUB_LTOD_LTIME", "SUB", E::Ltod, Some(E::Ltime), E::Ltod),
    ("SUB_LTOD_LTOD", "SUB", E::Ltod, Some(E::Ltod), E::Ltime),
    ("SUB_LDT_LTIME", "SUB", E::Ldt, Some(E::Ltime), E::Ldt),
    ("SUB_LDT_LDT", "SUB", E::Ldt, Some(E::Ldt), E::Ltime),
];

/// The time/date overload of `op` for a first input of type `in1`, if any.
pub fn time_overloads(
    op: &str,
    in1: Elementary,
) -> impl Iterator<Item = &'static (&'static str, &'static str, E, Option<E>, E)> + '_ {
    TIME_ARITH
        .iter()
        .filter(move |t| t.1.eq_ignore_ascii_case(op) && t.2 == in1)
}

/// A conversion function: `INT_TO_REAL`, `TRUNC`, `BCD_TO_INT`, `INT_TO_BCD`, `WORD_BCD_TO_INT` ...
#[derive(Debug, Clone, PartialEq)]
pub struct Conversion {
    /// The input type: `Some` for `X_TO_Y`; `None` when generic (TRUNC: ANY_REAL, BCD_TO_INT: ANY_BIT).
    pub from: Option<Type>,
    /// The class the input must belong to (ANY for `X_TO_Y`, whose `from` fixes it).
    pub from_class: Class,
    /// The output type.
    pub to: ConvTarget,
    /// How the value is converted (plain, truncating, BCD).
    pub kind: super::model::ConversionKind,
}

/// The output of a conversion.
#[derive(Debug, Clone, PartialEq)]
pub enum ConvTarget {
    /// A fixed output type (`REAL` in `INT_TO_REAL`).
    Fixed(Type),
    /// `*_TO_BCD` written without the bit-string type: BYTE/WORD/DWORD/LWORD by the input's width.
    BcdOfWidth,
}

fn conv_type(name: &str) -> Option<Type> {
    match name {
        "STRING" => Some(Type::String {
            wide: false,
            len: super::model::default_string_len(),
        }),
        "WSTRING" => Some(Type::String {
            wide: true,
            len: super::model::default_string_len(),
        }),
        n => Elementary::from_name(n).map(Type::Elementary),
    }
}

/// Whether `X_TO_Y` exists: numbers, bit strings and BOOL convert among themselves; TIME/LTIME convert
/// with integers, reals, bit strings and BOOL (milliseconds); DT, DATE and TOD convert with numbers
/// and bit strings (CODESYS, TwinCAT, matiec, OSCAT: DT and DATE as seconds since 1970-01-01, TOD
/// as milliseconds since midnight; edition 3's LDT, LDATE and LTOD as nanoseconds); every date and
/// time type (TIME, LTIME, DATE, LDATE, TOD, LTOD, DT, LDT) converts to every other, as the same
/// point of the time line from 1970-01-01-00:00 (CODESYS's and TwinCAT's `TOD_TO_DT`,
/// `TIME_TO_DATE`, `DT_TO_TOD` ...; a DATE at its midnight, a TOD or a duration counted from
/// midnight; to DATE the day, to TOD the time of day); everything elementary converts to and from
/// STRING/WSTRING.
pub fn conversion_allowed(from: &Type, to: &Type) -> bool {
    let (f, t) = (from.elementary(), to.elementary());
    match (f, t) {
        (None, None) => from.is_string() && to.is_string(),
        (None, Some(_)) => from.is_string(),
        (Some(_), None) => to.is_string(),
        (Some(f), Some(t)) => {
            let plain = |e: E| e.is_numeric() || e.is_bit();
            // durations and bit strings too (TIME_TO_DWORD, DWORD_TO_TIME: matiec, CODESYS, OSCAT)
            let time_like = |e: E| e.is_duration() || e.is_date();
            (plain(f) && plain(t))
                || (f.is_duration() && plain(t))
                || (t.is_duration() && plain(f))
                // every date and time type to every other: edition 3's Table 22 (LDT_TO_DATE,
                // DT_TO_TOD, LTIME_TO_TIME ...), CODESYS's and TwinCAT's tables 16 and 17
                // (TIME/LTIME_TO_DATE/DT/TOD/LDATE/LDT/LTOD, DATE/DT/TOD_TO_<type>: DATE_TO_DT,
                // TOD_TO_DT, TOD_TO_DATE ...); the value is the same point of the time line from
                // 1970-01-01-00:00 (a TOD and a duration counted from its midnight, a DATE at its
                // midnight): to DATE the day, to TOD the time of day (`TOD_TO_DT(TOD#10:00)` is
                // DT#1970-01-01-10:00:00, `DT_TO_TIME` the time since 1970)
                || (time_like(f) && time_like(t))
                || (f.is_date() && plain(t))
                || (t.is_date() && plain(f))
                || (f == t)
                // edition 3's characters (Table 22 and CODESYS's): with each other, with the
                // integers and the bit strings but BOOL (their code)
                || (f.is_char() && (t.is_char() || code_of_char(t)))
                || (t.is_char() && code_of_char(f))
        }
    }
}

/// The types a CHAR or WCHAR converts to and from as its code: the integers, and the bit strings
/// but BOOL.
fn code_of_char(e: E) -> bool {
    e.is_integer() || (e.is_bit() && e != E::Bool)
}

/// `TO_STRING`, `TO_WSTRING` and `TO_<integer or bit string>` of an enumerated value, as CODESYS and
/// TwinCAT document them ("TO_STRING/TO_WSTRING for enumeration variables", "Attribute
/// 'to_string'"): the value's number (its name under `{attribute 'to_string'}` for the strings).
/// IEC 61131-3 defines no conversion of an enumerated type; only the overloaded `TO_` forms take one.
pub fn enum_conversion_allowed(from: &Type, to: &Type, kind: super::model::ConversionKind) -> bool {
    matches!(from, Type::Enum(_))
        && kind == super::model::ConversionKind::Plain
        && (to.is_string()
            || to
                .elementary()
                .is_some_and(|e| e.is_integer() || (e.is_bit() && e != E::Bool)))
}

/// Parses a conversion function name.
pub fn conversion(name: &str) -> Option<Conversion> {
    use super::model::ConversionKind as K;
    let up = name.to_ascii_uppercase();
    if up == "TRUNC" {
        return Some(Conversion {
            from: None,
            from_class: AnyReal,
            to: ConvTarget::Fixed(Type::DINT),
            kind: K::Trunc,
        });
    }
    // edition 3: TRUNC_INT (overloaded on ANY_REAL), REAL_TRUNC_INT (typed)
    if let Some(t) = up.strip_prefix("TRUNC_") {
        let to = conv_type(t).filter(|t| t.is_integer())?;
        return Some(Conversion {
            from: None,
            from_class: AnyReal,
            to: ConvTarget::Fixed(to),
            kind: K::Trunc,
        });
    }
    if let Some((a, b)) = up.split_once("_TRUNC_") {
        let from = conv_type(a).filter(|t| t.is_real())?;
        let to = conv_type(b).filter(|t| t.is_integer())?;
        return Some(Conversion {
            from: Some(from),
            from_class: AnyReal,
            to: ConvTarget::Fixed(to),
            kind: K::Trunc,
        });
    }
    // edition 3: TO_INT, TO_STRING ... (overloaded on the input's type, the rules of X_TO_Y)
    if let Some(t) = up.strip_prefix("TO_") {
        let to = conv_type(t)?;
        return Some(Conversion {
            from: None,
            from_class: Any,
            to: ConvTarget::Fixed(to),
            kind: K::Plain,
        });
    }
    let (a, b) = up.split_once("_TO_")?;
    // BCD_TO_INT, WORD_BCD_TO_INT
    if a == "BCD" || a.ends_with("_BCD") {
        let to = conv_type(b).filter(|t| t.is_integer())?;
        let from = if a == "BCD" {
            None
        } else {
            Some(conv_type(&a[..a.len() - 4]).filter(|t| t.is_bit() && !t.is_bool())?)
        };
        return Some(Conversion {
            from,
            from_class: AnyBit,
            to: ConvTarget::Fixed(to),
            kind: K::FromBcd,
        });
    }
    // INT_TO_BCD, INT_TO_BCD_WORD
    if b == "BCD" || b.starts_with("BCD_") {
        let from = conv_type(a).filter(|t| t.is_integer())?;
        let to = if b == "BCD" {
            ConvTarget::BcdOfWidth
        } else {
            ConvTarget::Fixed(conv_type(&b[4..]).filter(|t| t.is_bit() && !t.is_bool())?)
        };
        return Some(Conversion {
            from: Some(from),
            from_class: AnyInt,
            to,
            kind: K::ToBcd,
        });
    }
    // REAL_TRUNC_INT is spelled TRUNC_INT in edition 3: accept `REAL_TO_INT` family only here.
    let from = conv_type(a)?;
    let to = conv_type(b)?;
    if !conversion_allowed(&from, &to) {
        return None;
    }
    Some(Conversion {
        from: Some(from),
        from_class: Any,
        to: ConvTarget::Fixed(to),
        kind: K::Plain,
    })
}

/// The bit string of the same width as an integer type (`INT_TO_BCD` gives WORD).
pub fn bcd_of_width(int: Elementary) -> Elementary {
    match int.bit_width() {
        8 => E::Byte,
        16 => E::Word,
        32 => E::Dword,
        _ => E::Lword,
    }
}

/// Direction of a standard FB parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dir {
    /// `VAR_INPUT` of the standard FB.
    Input,
    /// `VAR_OUTPUT` of the standard FB.
    Output,
}

/// A standard FB parameter.
#[derive(Debug, Clone, Copy)]
pub struct FbParam {
    /// The parameter's name (`IN`, `PT`, `Q`, `ET`).
    pub name: &'static str,
    /// Input or output.
    pub dir: Dir,
    /// Its type (`PV`/`CV` of the typed counters take the counter's type).
    pub ty: Elementary,
}

const fn i(name: &'static str, ty: Elementary) -> FbParam {
    FbParam {
        name,
        dir: Dir::Input,
        ty,
    }
}
const fn o(name: &'static str, ty: Elementary) -> FbParam {
    FbParam {
        name,
        dir: Dir::Output,
        ty,
    }
}

const TRIG: &[FbParam] = &[i("CLK", E::Bool), o("Q", E::Bool)];
const SR: &[FbParam] = &[i("S1", E::Bool), i("R", E::Bool), o("Q1", E::Bool)];
const RS: &[FbParam] = &[i("S", E::Bool), i("R1", E::Bool), o("Q1", E::Bool)];
const TIMER: &[FbParam] = &[
    i("IN", E::Bool),
    i("PT", E::Time),
    o("Q", E::Bool),
    o("ET", E::Time),
];
const LTIMER: &[FbParam] = &[
    i("IN", E::Bool),
    i("PT", E::Ltime),
    o("Q", E::Bool),
    o("ET", E::Ltime),
];
const fn ctu(t: Elementary) -> [FbParam; 5] {
    [
        i("CU", E::Bool),
        i("R", E::Bool),
        i("PV", t),
        o("Q", E::Bool),
        o("CV", t),
    ]
}
const fn ctd(t: Elementary) -> [FbParam; 5] {
    [
        i("CD", E::Bool),
        i("LD", E::Bool),
        i("PV", t),
        o("Q", E::Bool),
        o("CV", t),
    ]
}
const fn ctud(t: Elementary) -> [FbParam; 8] {
    [
        i("CU", E::Bool),
        i("CD", E::Bool),
        i("R", E::Bool),
        i("LD", E::Bool),
        i("PV", t),
        o("QU", E::Bool),
        o("QD", E::Bool),
        o("CV", t),
    ]
}
const CTU: &[FbParam] = &ctu(E::Int);
const CTD: &[FbParam] = &ctd(E::Int);
const CTUD: &[FbParam] = &ctud(E::Int);

/// The inputs and outputs of a standard FB, in IEC order (inputs first).
pub fn fb_params(fb: StdFb) -> &'static [FbParam] {
    match fb {
        StdFb::RTrig | StdFb::FTrig => TRIG,
        StdFb::Sr => SR,
        StdFb::Rs => RS,
        StdFb::Ton | StdFb::Tof | StdFb::Tp => TIMER,
        StdFb::TonLtime | StdFb::TofLtime | StdFb::TpLtime => LTIMER,
        StdFb::Ctu => CTU,
        StdFb::Ctd => CTD,
        StdFb::Ctud => CTUD,
        StdFb::CtuDint => &const { ctu(E::Dint) },
        StdFb::CtuLint => &const { ctu(E::Lint) },
        StdFb::CtuUdint => &const { ctu(E::Udint) },
        StdFb::CtuUlint => &const { ctu(E::Ulint) },
        StdFb::CtdDint => &const { ctd(E::Dint) },
        StdFb::CtdLint => &const { ctd(E::Lint) },
        StdFb::CtdUdint => &const { ctd(E::Udint) },
        StdFb::CtdUlint => &const { ctd(E::Ulint) },
        StdFb::CtudDint => &const { ctud(E::Dint) },
        StdFb::CtudLint => &const { ctud(E::Lint) },
        StdFb::CtudUdint => &const { ctud(E::Udint) },
        StdFb::CtudUlint => &const { ctud(E::Ulint) },
        StdFb::CtuWord => &const { ctu(E::Word) },
        StdFb::CtdWord => &const { ctd(E::Word) },
        StdFb::CtudWord => &const { ctud(E::Word) },
    }
}

/// The IEC 61131-3 name of a standard FB's parameter written by its CODESYS/TwinCAT name, `None`
/// when `name` is no such name. CODESYS's Standard and TwinCAT's Tc2_Standard library call the
/// counters' R and LD `RESET` and `LOAD` (`CTU(CU, RESET, PV)`, `CTD(CD, LOAD, PV)`,
/// `CTUD(CU, CD, RESET, LOAD, PV)`; CODESYS online help "CTU", Beckhoff Infosys "Tc2_Standard CTU")
/// and the bistables' inputs `SR(SET1, RESET)`, `RS(SET, RESET1)`. The instance keeps the IEC
/// names; these are only other names for the same inputs, in calls and in `inst.RESET`.
pub fn vendor_param_alias(fb: StdFb, name: &str) -> Option<&'static str> {
    let alias = match name.trim().to_ascii_uppercase().as_str() {
        "RESET" => "R",
        "LOAD" => "LD",
        "SET1" => "S1",
        "SET" => "S",
        "RESET1" => "R1",
        _ => return None,
    };
    fb_params(fb)
        .iter()
        .any(|p| p.dir == Dir::Input && p.name == alias)
        .then_some(alias)
}

/// The IEC name of a string function's input that CODESYS's Standard library and TwinCAT's
/// Tc2_Standard name otherwise: `LEFT(STR, SIZE)`, `RIGHT(STR, SIZE)`, `MID(STR, LEN, POS)`,
/// `FIND(STR1, STR2)`, `CONCAT(STR1, STR2)`, `INSERT(STR1, STR2, POS)`, `DELETE(STR, LEN, POS)`,
/// `REPLACE(STR1, STR2, LEN, POS)`, `LEN(STR)` (CODESYS online help "String functions", Beckhoff
/// Infosys "Tc2_Standard: LEFT" ...), in the same order as IEC 61131-3's `IN`, `IN1`, `IN2`, `L`, `P`.
pub fn vendor_string_param(function: &str, name: &str) -> Option<&'static str> {
    const STRING_FUNCTIONS: [&str; 9] = [
        "LEFT", "RIGHT", "MID", "FIND", "CONCAT", "INSERT", "DELETE", "REPLACE", "LEN",
    ];
    if !STRING_FUNCTIONS
        .iter()
        .any(|f| f.eq_ignore_ascii_case(function))
    {
        return None;
    }
    Some(match name.trim().to_ascii_uppercase().as_str() {
        "STR" => "IN",
        "STR1" => "IN1",
        "STR2" => "IN2",
        "SIZE" | "LEN" => "L",
        "POS" => "P",
        _ => return None,
    })
}

/// Documentation of a standard FB (one line).
pub fn fb_doc(fb: StdFb) -> &'static str {
    match fb {
        StdFb::RTrig => "Q is TRUE for one call on a rising edge of CLK",
        StdFb::FTrig => "Q is TRUE for one call on a falling edge of CLK",
        StdFb::Sr => "set-dominant bistable: Q1 := S1 OR (NOT R AND Q1)",
        StdFb::Rs => "reset-dominant bistable: Q1 := NOT R1 AND (S OR Q1)",
        StdFb::Ton => "on-delay timer: Q goes TRUE when IN has been TRUE for PT",
        StdFb::Tof => "off-delay timer: Q stays TRUE for PT after IN goes FALSE",
        StdFb::Tp => "pulse timer: Q is TRUE for PT from a rising edge of IN",
        StdFb::TonLtime => "on-delay timer on LTIME: Q goes TRUE when IN has been TRUE for PT",
        StdFb::TofLtime => "off-delay timer on LTIME: Q stays TRUE for PT after IN goes FALSE",
        StdFb::TpLtime => "pulse timer on LTIME: Q is TRUE for PT from a rising edge of IN",
        StdFb::Ctu
        | StdFb::CtuDint
        | StdFb::CtuLint
        | StdFb::CtuUdint
        | StdFb::CtuUlint
        | StdFb::CtuWord => "up counter: CV counts rising edges of CU, Q := CV >= PV, R resets",
        StdFb::Ctd
        | StdFb::CtdDint
        | StdFb::CtdLint
        | StdFb::CtdUdint
        | StdFb::CtdUlint
        | StdFb::CtdWord => {
            "down counter: CV counts down on rising edges of CD, Q := CV <= 0, LD loads PV"
        }
        StdFb::Ctud
        | StdFb::CtudDint
        | StdFb::CtudLint
        | StdFb::CtudUdint
        | StdFb::CtudUlint
        | StdFb::CtudWord => "up/down counter: QU := CV >= PV, QD := CV <= 0",
    }
}
