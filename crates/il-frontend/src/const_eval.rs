//! Constant expressions of declarations, evaluated while the declarations are parsed: an array
//! bound, a string length, a subrange bound (integers only) and the initial value of a variable or
//! constant (`EPS : LREAL := 16 * 2.2E-016;`, `C2 : REAL := C1 / 2.0;`, `T_MAX : TIME := T#1S +
//! T#500MS;`, `L : LREAL := LREAL#1.5 * 2;`).
//!
//! Input: a [`BoundExpr`] and the constants declared before it (by upper-case name). Output: its
//! value, a [`ConstNum`], or the reason it has none (the caller reports E0022 at the expression).
//! Invariants: no input panics (checked integer arithmetic, depth cap, finite reals only); the value
//! of a constant is kept in its declared type ([`as_declared`]), so that `C1 : REAL := 3;` makes
//! `C1 / 2` a REAL division (1.5), as IEC 61131-3 ed. 3 (7.3.2, constant expressions take the types
//! of their operands) types it; integers mixed with reals give reals, durations scale by numbers
//! (`T#1S * 2`) and add to durations, as the standard's arithmetic on ANY_MAGNITUDE does.

use crate::ast::{Literal, LiteralKind, TypeRef};
use crate::parser::BoundExpr;
use crate::sema::Elementary;
use std::collections::HashMap;

/// The value of a constant expression.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ConstNum {
    /// An integer (checked in the LINT range).
    Int(i128),
    /// A real (finite; a REAL constant holds the value rounded to 32 bits).
    Real(f64),
    /// A duration in nanoseconds (TIME, LTIME).
    Duration(i128),
}

thread_local! {
    /// The nanoseconds of one unit of a number converted to or from TIME in a constant expression
    /// (`DINT_TO_TIME(5)`, `TIME_TO_REAL(T#2S)`), set by [`set_time_number_unit`]: the target
    /// profile's, so that a constant converts as the run time does (milliseconds by default).
    static TIME_NUMBER_UNIT_NS: std::cell::Cell<i128> = const { std::cell::Cell::new(1_000_000) };
}

/// Sets the nanoseconds of one unit of a number converted to or from TIME (the target profile's
/// `time_number_unit`: 1_000_000 for milliseconds, 1_000_000_000 for seconds); returns the one set
/// before, to put back when the project is read. A value below 1 is taken as 1.
pub fn set_time_number_unit(ns: i64) -> i64 {
    let before = TIME_NUMBER_UNIT_NS.with(|u| u.replace(i128::from(ns.max(1))));
    i64::try_from(before).unwrap_or(1_000_000)
}

fn time_unit_ns() -> i128 {
    TIME_NUMBER_UNIT_NS.with(std::cell::Cell::get)
}

/// The constants known to the expressions of a text, by upper-case name; the values of
/// enumerations under [`enum_key`] of theirs.
pub type Constants = HashMap<String, ConstNum>;

/// The key of an enumeration's value among the [`Constants`] (`ENUM RUNNER_END`: a space, so no
/// constant's name): an integer bound may name it (`ARRAY[E_Task.First..E_Task.Last]`, the
/// qualifier blanked in `.st` text), as CODESYS and TwinCAT allow, while an initial value's
/// expression may not (an enumeration is no number in IEC 61131-3's arithmetic).
pub fn enum_key(value: &str) -> String {
    format!("ENUM {}", value.to_ascii_uppercase())
}

/// Adds the values of the enumeration `type_name` (`values`; implicit ones count on from the
/// previous, as sema numbers them) under [`enum_key`] of the value, where a value already known
/// (another enumeration's) is kept, and of `type_name.value` ([`enum_operand_value`]).
pub fn add_enum_values(consts: &mut Constants, type_name: &str, values: &[crate::ast::EnumValue]) {
    let mut next = 0i128;
    for v in values {
        let value = v.value.unwrap_or(next);
        next = value.saturating_add(1);
        consts
            .entry(enum_key(&v.name.name))
            .or_insert(ConstNum::Int(value));
        consts.insert(
            enum_key(&format!("{type_name}.{}", v.name.name)),
            ConstNum::Int(value),
        );
    }
}

/// The number of an enumerated value that is the initial value of a constant (`N : INT :=
/// E_Topic.COUNT_OF;`, `E_Topic#COUNT_OF`, or `COUNT_OF` alone when no constant has that name),
/// so that the constant may bound an array as one with a literal value does (CODESYS and TwinCAT
/// take a value of an enumeration without `{attribute 'strict'}` as its number). `None` when the
/// operand names no enumeration's value of `consts`.
pub fn enum_operand_value(consts: &Constants, op: &crate::ast::Operand) -> Option<ConstNum> {
    use crate::ast::{Accessor, Operand};
    let key = match op {
        Operand::EnumValue(e) => enum_key(&format!("{}.{}", e.type_name.name, e.value.name)),
        Operand::Var(v) => match &v.accessors[..] {
            [] if !consts.contains_key(&v.base.name.to_ascii_uppercase()) => enum_key(&v.base.name),
            [Accessor::Field(value)] => enum_key(&format!("{}.{}", v.base.name, value.name)),
            _ => return None,
        },
        _ => return None,
    };
    consts.get(&key).copied()
}

impl ConstNum {
    /// The literal that holds this value as an initial value.
    pub fn literal_kind(self) -> LiteralKind {
        match self {
            ConstNum::Int(v) => LiteralKind::Int(v),
            ConstNum::Real(v) => LiteralKind::Real(v),
            ConstNum::Duration(v) => LiteralKind::Duration(v),
        }
    }

    /// The value of a literal, when it is a number or a duration (`LREAL#2` is the real 2.0).
    pub fn of_literal(lit: &Literal) -> Option<ConstNum> {
        let prefix = lit
            .type_prefix
            .as_ref()
            .map(|p| Elementary::from_name(&p.name));
        let real_prefix = matches!(prefix, Some(Some(e)) if e.is_real());
        match lit.kind {
            LiteralKind::Int(v) if real_prefix => Some(ConstNum::Real(v as f64)),
            LiteralKind::Int(v) if matches!(prefix, None | Some(Some(_))) => Some(ConstNum::Int(v)),
            LiteralKind::Real(v) if v.is_finite() => Some(ConstNum::Real(v)),
            LiteralKind::Duration(v) => Some(ConstNum::Duration(v)),
            _ => None,
        }
    }
}

/// `value` in the type `ty` a constant is declared with: an integer becomes a real in a REAL or
/// LREAL constant, a REAL's value is rounded to 32 bits; a value of another kind than the type's
/// (a real for an INT, a number for a TIME) is `None` (sema reports the initial value). A type that
/// is not elementary (an alias, an enumeration) keeps the value as it is.
pub fn as_declared(value: ConstNum, ty: &TypeRef) -> Option<ConstNum> {
    let TypeRef::Named(name) = ty else {
        return Some(value);
    };
    let Some(e) = Elementary::from_name(&name.name) else {
        return Some(value);
    };
    match value {
        ConstNum::Int(v) if e.is_real() => as_declared(ConstNum::Real(v as f64), ty),
        ConstNum::Real(v) if e == Elementary::Real => Some(ConstNum::Real(f64::from(v as f32))),
        ConstNum::Real(_) if e.is_real() => Some(value),
        ConstNum::Int(_) if !e.is_duration() && !e.is_date() => Some(value),
        ConstNum::Duration(_) if e.is_duration() => Some(value),
        _ => None,
    }
}

/// Evaluates `e` with `consts` known; the error says why there is no value. `integers`: an integer
/// expression (a bound, a length), which names integer constants only.
pub fn eval(e: &BoundExpr, consts: &Constants, integers: bool) -> Result<ConstNum, String> {
    eval_at(e, &Known { consts, integers }, 0)
}

/// The constants an expression may name.
struct Known<'a> {
    consts: &'a Constants,
    integers: bool,
}

fn eval_at(e: &BoundExpr, consts: &Known, depth: u32) -> Result<ConstNum, String> {
    if depth > 64 {
        return Err("the expression is nested too deeply".into());
    }
    match e {
        BoundExpr::Int(v, _) => Ok(ConstNum::Int(*v)),
        BoundExpr::Real(v, _) => Ok(ConstNum::Real(*v)),
        BoundExpr::Duration(v, _) => Ok(ConstNum::Duration(*v)),
        BoundExpr::NoValue(why, _) => Err(why.clone()),
        BoundExpr::NotNumber(_) => {
            Err("only numbers and durations (T#...) make constant expressions".into())
        }
        BoundExpr::Name(n) => match consts.consts.get(&n.name.to_ascii_uppercase()).or_else(|| {
            consts
                .consts
                .get(&enum_key(&n.name.replacen('#', ".", 1)))
                .filter(|_| consts.integers)
        }) {
            Some(v) if !consts.integers || matches!(v, ConstNum::Int(_)) => Ok(*v),
            Some(_) => Err(format!("`{}` is not an integer constant", n.name)),
            None => Err(missing_constant(&n.name)),
        },
        BoundExpr::Neg(a, _) => match eval_at(a, consts, depth + 1)? {
            ConstNum::Int(v) => int(v.checked_neg()),
            ConstNum::Real(v) => Ok(ConstNum::Real(-v)),
            ConstNum::Duration(v) => duration(v.checked_neg()),
        },
        BoundExpr::Bin(op, a, b) => {
            let (a, b) = (
                eval_at(a, consts, depth + 1)?,
                eval_at(b, consts, depth + 1)?,
            );
            binary(*op, a, b)
        }
        BoundExpr::Call(f, args, _) => {
            if !computed(&f.name) {
                return Err(not_computed(&f.name));
            }
            let args = args
                .iter()
                .map(|a| eval_at(a, consts, depth + 1))
                .collect::<Result<Vec<_>, _>>()?;
            call(&f.name, &args)
        }
    }
}

/// The standard function `f` (IEC 61131-3 ed. 3, Tables 22-29: numerical, selection and type
/// conversion functions) of the constant arguments `args`. A real result may be NaN or infinite
/// (`LOG(-1)`, TwinCAT's way to write NaN): it is the value the function gives at run time.
fn call(f: &str, args: &[ConstNum]) -> Result<ConstNum, String> {
    let upper = f.to_ascii_uppercase();
    let arity = |n: usize| {
        if args.len() == n {
            Ok(())
        } else {
            Err(format!("`{f}` takes {n} argument(s), {} given", args.len()))
        }
    };
    let real_arg =
        |k: usize| number(args[k]).ok_or_else(|| format!("`{f}` takes a number, not a duration"));
    let math: Option<fn(f64) -> f64> = match upper.as_str() {
        "SQRT" => Some(f64::sqrt),
        "LN" => Some(f64::ln),
        "LOG" => Some(f64::log10),
        "EXP" => Some(f64::exp),
        "SIN" => Some(f64::sin),
        "COS" => Some(f64::cos),
        "TAN" => Some(f64::tan),
        "ASIN" => Some(f64::asin),
        "ACOS" => Some(f64::acos),
        "ATAN" => Some(f64::atan),
        _ => None,
    };
    if let Some(m) = math {
        arity(1)?;
        return Ok(ConstNum::Real(m(real_arg(0)?)));
    }
    match upper.as_str() {
        "ABS" => {
            arity(1)?;
            match args[0] {
                ConstNum::Int(v) => int(v.checked_abs()),
                ConstNum::Real(v) => Ok(ConstNum::Real(v.abs())),
                ConstNum::Duration(v) => duration(v.checked_abs()),
            }
        }
        "EXPT" => {
            arity(2)?;
            Ok(ConstNum::Real(real_arg(0)?.powf(real_arg(1)?)))
        }
        "ATAN2" => {
            arity(2)?;
            Ok(ConstNum::Real(real_arg(0)?.atan2(real_arg(1)?)))
        }
        "MIN" | "MAX" if !args.is_empty() => {
            let max = upper == "MAX";
            let mut best = args[0];
            for &a in &args[1..] {
                let better = match (best, a) {
                    (ConstNum::Int(b), ConstNum::Int(a)) => (a > b) == max && a != b,
                    (ConstNum::Duration(b), ConstNum::Duration(a)) => (a > b) == max && a != b,
                    (ConstNum::Duration(_), _) | (_, ConstNum::Duration(_)) => {
                        return Err(format!("`{f}` compares numbers or durations, not both"));
                    }
                    (b, a) => {
                        let (b, a) = (number(b).unwrap_or(0.0), number(a).unwrap_or(0.0));
                        (a > b) == max && a != b
                    }
                };
                if better {
                    best = a;
                }
            }
            Ok(best)
        }
        "LIMIT" => {
            arity(3)?;
            let lo = call("MAX", &args[..2])?;
            call("MIN", &[lo, args[2]])
        }
        "SHL" | "SHR" | "ROL" | "ROR" => {
            arity(2)?;
            let (ConstNum::Int(v), ConstNum::Int(n)) = (args[0], args[1]) else {
                return Err(format!("`{f}` shifts an integer by an integer"));
            };
            if !(0..=63).contains(&n) || v < 0 {
                return Err(format!("`{f}` of this value is computed at run time"));
            }
            // (the bits beyond the constant's type are dropped where the value is stored)
            let v = v as u64;
            let n = n as u32;
            int(Some(i128::from(match upper.as_str() {
                "SHL" => v.checked_shl(n).unwrap_or(0),
                "SHR" => v >> n,
                "ROL" if v <= u64::from(u32::MAX) => u64::from((v as u32).rotate_left(n % 32)),
                "ROR" if v <= u64::from(u32::MAX) => u64::from((v as u32).rotate_right(n % 32)),
                _ => return Err(format!("`{f}` of this value is computed at run time")),
            })))
        }
        "TRUNC" => {
            arity(1)?;
            to_int(real_arg(0)?.trunc(), f).map(ConstNum::Int)
        }
        _ => convert(&upper, f, args),
    }
}

/// Whether [`call`] computes the function named `f` (its arguments are evaluated first only then:
/// `LEN(x)` is reported as a call, not as `x`).
pub(crate) fn computed(f: &str) -> bool {
    const NAMES: [&str; 21] = [
        "SQRT", "LN", "LOG", "EXP", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "ATAN2", "EXPT",
        "ABS", "MIN", "MAX", "LIMIT", "TRUNC", "SHL", "SHR", "ROL", "ROR",
    ];
    let up = f.to_ascii_uppercase();
    NAMES.contains(&up.as_str())
        || up
            .rsplit_once("_TO_")
            .map(|(_, t)| t)
            .or_else(|| up.strip_prefix("TO_"))
            .and_then(Elementary::from_name)
            .is_some()
}

fn not_computed(f: &str) -> String {
    format!(
        "`{f}(...)` is a call: only standard numeric functions of constants (SQRT, LOG, MAX, \
         TO_REAL, ...) and SIZEOF are computed in a constant expression"
    )
}

/// A type conversion `X_TO_Y(v)`, `TO_Y(v)` (CODESYS, TwinCAT) or `Y_TRUNC(v)` of a number to a
/// number type: a real goes to an integer rounded to the nearest, halves to even (IEC 60559, as
/// the run time converts).
fn convert(upper: &str, f: &str, args: &[ConstNum]) -> Result<ConstNum, String> {
    let target = upper
        .rsplit_once("_TO_")
        .map(|(_, t)| t)
        .or_else(|| upper.strip_prefix("TO_"));
    let Some(e) = target.and_then(Elementary::from_name) else {
        return Err(not_computed(f));
    };
    if args.len() != 1 {
        return Err(format!("`{f}` takes 1 argument, {} given", args.len()));
    }
    // a duration to a number counts its milliseconds (the profile's unit), as the run time
    // converts (truncated toward zero for an integer: TIME_TO_DINT(T#1500US) = 1)
    let unit = time_unit_ns();
    let v = match (args[0], e.is_duration()) {
        (ConstNum::Duration(d), false) if e.is_real() => ConstNum::Real(d as f64 / unit as f64),
        (ConstNum::Duration(d), false) => ConstNum::Int(d / unit),
        (v, _) => v,
    };
    if e.is_real() {
        let x = number(v).ok_or_else(|| format!("`{f}` converts a number, not a duration"))?;
        return Ok(ConstNum::Real(if e == Elementary::Real {
            f64::from(x as f32)
        } else {
            x
        }));
    }
    // a number to TIME or LTIME counts milliseconds (the profile's unit), as the run time
    // converts (`TO_TIME(0)`, `UDINT_TO_TIME(1000)` = T#1S); a duration stays
    if e.is_duration() {
        return match v {
            ConstNum::Int(i) => duration(i.checked_mul(unit)),
            ConstNum::Real(x) => {
                // TIME under milliseconds holds whole milliseconds (CODESYS, TwinCAT: TIME is
                // a count of ms and REAL_TO_<type> rounds to the nearest integer), as the run
                // time's `ladderc_real_to_time`; LTIME and seconds (matiec) keep nanoseconds
                let x = if e == Elementary::Time && unit == 1_000_000 {
                    x.round_ties_even()
                } else {
                    x
                };
                let ns = (x * unit as f64).round_ties_even();
                to_int(ns, f).and_then(|n| duration(Some(n)))
            }
            ConstNum::Duration(d) => duration(Some(d)),
        };
    }
    if !(e.is_integer() || e.is_bit()) {
        return Err(format!(
            "`{f}` is computed at run time, not in a constant expression"
        ));
    }
    let i = match v {
        ConstNum::Int(i) => i,
        ConstNum::Real(x) => to_int(x.round_ties_even(), f)?,
        ConstNum::Duration(_) => return Err(format!("`{f}` converts a number, not a duration")),
    };
    match e.int_range() {
        Some((lo, hi)) if i < lo || i > hi => {
            Err(format!("`{f}({i})` is out of {}'s range", e.name()))
        }
        _ => Ok(ConstNum::Int(i)),
    }
}

/// A real already rounded or truncated as an integer (checked in LINT's range).
fn to_int(x: f64, f: &str) -> Result<i128, String> {
    if x.is_finite() && x.abs() < 9.2e18 {
        Ok(x as i128)
    } else {
        Err(format!("`{f}` of this value has no integer result"))
    }
}

/// An integer result, checked in the widest integer type (LINT); bounds are narrowed by the caller.
fn int(v: Option<i128>) -> Result<ConstNum, String> {
    v.filter(|v| i64::try_from(*v).is_ok())
        .map(ConstNum::Int)
        .ok_or_else(|| "the value overflows".into())
}

/// A duration result, checked in LTIME's range (64-bit nanoseconds).
fn duration(v: Option<i128>) -> Result<ConstNum, String> {
    v.filter(|v| i64::try_from(*v).is_ok())
        .map(ConstNum::Duration)
        .ok_or_else(|| "the duration overflows".into())
}

fn real(v: f64) -> Result<ConstNum, String> {
    if v.is_finite() {
        Ok(ConstNum::Real(v))
    } else {
        Err("the value overflows".into())
    }
}

/// A duration scaled by a real, truncated toward zero nanoseconds.
fn scaled(v: f64) -> Result<ConstNum, String> {
    if !v.is_finite() || v.abs() >= i64::MAX as f64 {
        return Err("the duration overflows".into());
    }
    Ok(ConstNum::Duration(v.trunc() as i128))
}

fn number(v: ConstNum) -> Option<f64> {
    match v {
        ConstNum::Int(v) => Some(v as f64),
        ConstNum::Real(v) => Some(v),
        ConstNum::Duration(_) => None,
    }
}

/// `a op b`, `op` one of `+ - * /` and `%` for MOD.
fn binary(op: u8, a: ConstNum, b: ConstNum) -> Result<ConstNum, String> {
    use ConstNum::{Duration as D, Int as I, Real as R};
    let by_zero = || Err("division by zero".to_string());
    match (a, b) {
        (I(a), I(b)) => match op {
            b'+' => int(a.checked_add(b)),
            b'-' => int(a.checked_sub(b)),
            b'*' => int(a.checked_mul(b)),
            // AND, OR, XOR of a data type's named values (`White := Red OR Green`)
            b'&' => int(Some(a & b)),
            b'|' => int(Some(a | b)),
            b'^' => int(Some(a ^ b)),
            _ if b == 0 => by_zero(),
            b'/' => int(a.checked_div(b)),
            _ => int(a.checked_rem(b)),
        },
        (D(a), D(b)) => match op {
            b'+' => duration(a.checked_add(b)),
            b'-' => duration(a.checked_sub(b)),
            _ => Err("durations only add to and subtract from durations".into()),
        },
        // TIME * number, number * TIME, TIME / number (IEC 61131-3 ed. 3, Table 30: MUL_TIME,
        // DIV_TIME); the nanoseconds are truncated toward zero
        (D(t), I(n)) | (I(n), D(t)) if op == b'*' => duration(t.checked_mul(n)),
        (D(t), R(n)) | (R(n), D(t)) if op == b'*' => scaled(t as f64 * n),
        (D(_), I(0)) if op == b'/' => by_zero(),
        (D(t), I(n)) if op == b'/' => duration(t.checked_div(n)),
        (D(_), R(n)) if op == b'/' && n == 0.0 => by_zero(),
        (D(t), R(n)) if op == b'/' => scaled(t as f64 / n),
        (D(_), _) | (_, D(_)) => {
            Err("a duration is only added to a duration or scaled by a number".into())
        }
        (a, b) => {
            let (Some(a), Some(b)) = (number(a), number(b)) else {
                return Err("a duration is only added to a duration or scaled by a number".into());
            };
            match op {
                b'+' => real(a + b),
                b'-' => real(a - b),
                b'*' => real(a * b),
                b'/' if b == 0.0 => by_zero(),
                b'/' => real(a / b),
                b'&' | b'|' | b'^' => Err("AND, OR and XOR take integers".into()),
                _ => Err("MOD takes integers".into()),
            }
        }
    }
}

/// The reason of an E0022 for a name that no constant of the files given declares with a value
/// (a library's constant, `MAX_STRING_LENGTH` of Tc3_PLCopen_OpcUa; a variable; constants naming
/// each other in a cycle): [`missing_constant_name`] reads the name back.
fn missing_constant(name: &str) -> String {
    format!("`{name}` names no constant with a value in the files given")
}

/// Whether `why` (an E0022's reason) is that no constant of the files declares the name.
pub fn is_missing_constant(why: &str) -> bool {
    why.contains("` names no constant with a value ")
}

/// The name an E0022's message says no constant of the files declares ([`missing_constant`]).
fn missing_constant_name(message: &str) -> Option<&str> {
    let (head, _) = message.split_once("` names no constant with a value ")?;
    let (_, name) = head.rsplit_once(": `")?;
    Some(name)
}

/// One E0022 per constant that no file given declares, at its first use (by file and position),
/// its message counting the uses (`(5 uses)`) and a label at each other use, which is left out:
/// one missing name is one cause (README, "One cause, one diagnostic"), as an unknown type's
/// E1003 is (round 32, before: one E0022 per use, 19 for one library constant of a project).
pub fn one_error_per_missing_constant(diags: &mut diagnostics::Diagnostics) {
    // upper-case name -> the uses' (span, message), in the order reported
    let mut uses: HashMap<String, Vec<(diagnostics::Span, String)>> = HashMap::new();
    for d in diags.iter() {
        if d.code != diagnostics::code::E0022 {
            continue;
        }
        let (Some(span), Some(name)) = (d.span, missing_constant_name(&d.message)) else {
            continue;
        };
        uses.entry(name.to_ascii_uppercase())
            .or_default()
            .push((span, d.message.clone()));
    }
    let mut first: Vec<(diagnostics::Span, String, Vec<diagnostics::Span>)> = Vec::new();
    for (_, mut at) in uses {
        if at.len() < 2 {
            continue;
        }
        at.sort_by_key(|(s, _)| (s.file.0, s.start, s.end));
        at.dedup_by_key(|(s, _)| *s);
        let (span, message) = at.remove(0);
        first.push((span, message, at.into_iter().map(|(s, _)| s).collect()));
    }
    if first.is_empty() {
        return;
    }
    let left_out: std::collections::HashSet<diagnostics::Span> = first
        .iter()
        .flat_map(|(_, _, o)| o.iter().copied())
        .collect();
    diags.retain(|d| {
        d.code != diagnostics::code::E0022
            || missing_constant_name(&d.message).is_none()
            || !d.span.is_some_and(|s| left_out.contains(&s))
    });
    diags.update(|d| {
        let Some((_, _, others)) = first.iter().find(|(s, m, _)| {
            d.code == diagnostics::code::E0022 && d.span == Some(*s) && d.message == *m
        }) else {
            return;
        };
        d.message = format!("{} ({} uses)", d.message, others.len() + 1);
        for s in others {
            d.labels.push(diagnostics::Label {
                span: *s,
                message: "also used here".into(),
            });
        }
    });
}
