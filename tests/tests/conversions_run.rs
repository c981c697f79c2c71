//! Every conversion function of the sema catalogue (`X_TO_Y`, `TRUNC`, `BCD_TO_*`, `*_TO_BCD`, the
//! `DATE_AND_TIME`/`TIME_OF_DAY` spellings) run end to end: a generated IL program per source type
//! goes through `ladderc run --sanitize` (C compiled with -fsanitize=undefined,address and executed),
//! and every result of the trace is compared with the IEC 61131-3 result of a table of inputs
//! (halves, negatives, limits, NaN and infinities). The rules (crates/c-backend/README.md,
//! "Conversions"): REAL/LREAL to integers round to nearest with halves to even and saturate, NaN gives
//! 0; TRUNC truncates toward zero and saturates; integers wrap to the target width; TIME and TOD
//! convert from and to milliseconds (a REAL to TIME rounded to whole milliseconds, halves to even), DT and DATE seconds, edition 3's LDT, LDATE and LTOD
//! nanoseconds (a number to DATE keeps all its seconds, to TOD the time of day; DT and LDT convert to the
//! date and the time of day of either length; CODESYS's DATE_TO_DT is the date at midnight,
//! TOD_TO_TIME the duration since midnight, TIME_TO_TOD the duration's time of day); LREAL to REAL rounds to nearest and overflows to an
//! infinity.

mod common;
use common::ladderc;

use il_frontend::sema::stdlib::conversion;
use il_frontend::sema::Elementary;
use std::collections::BTreeMap;

/// A source value: an integer (BOOL, integers, bit strings, BCD), a real, a duration or date in
/// nanoseconds, a string.
#[derive(Clone, Debug)]
enum V {
    I(i128),
    R(f64),
    T(i128),
    S(&'static str),
    /// A CHAR or WCHAR (edition 3): its code.
    C(i128),
}

/// The inputs of one source type: the IL literal (or None: computed in the body) and its value.
fn inputs(ty: &str) -> Vec<(String, V)> {
    let ints = |lo: i128, hi: i128| -> Vec<(String, V)> {
        let mut v = vec![lo, hi, 0, 1, 100];
        if lo < 0 {
            v.extend([-1, -100]);
        }
        v.into_iter()
            .map(|x| (format!("{ty}#{x}"), V::I(x)))
            .collect()
    };
    let time = |p: &str| -> Vec<(String, V)> {
        [
            ("1500ms", 1_500_000_000i128),
            ("-2s", -2_000_000_000),
            ("1ms500us", 1_500_000),
            ("-1ms500us", -1_500_000),
            ("2ms500us", 2_500_000),
            ("0ms", 0),
        ]
        .iter()
        .map(|(l, ns)| (format!("{p}#{l}"), V::T(*ns / 1000 * 1000)))
        .collect()
    };
    let real = |p: &str, extra: &[f64]| -> Vec<(String, V)> {
        let mut v = vec![
            2.5, -2.5, 0.5, -0.5, 1.5, 3.5, 3.7, -3.7, 127.5, 128.5, -128.5, 255.5, 32767.5,
            -32768.5, 65535.5, 1.0e10, -1.0e10, 3.0e38,
        ];
        v.extend_from_slice(extra);
        let mut out: Vec<(String, V)> = v
            .into_iter()
            .map(|x| {
                let val = if p == "REAL" { x as f32 as f64 } else { x };
                (format!("{p}#{}", real_literal(x)), V::R(val))
            })
            .collect();
        out.push(("inf".into(), V::R(f64::INFINITY)));
        out.push(("-inf".into(), V::R(f64::NEG_INFINITY)));
        out.push(("nan".into(), V::R(f64::NAN)));
        out
    };
    match ty {
        "BOOL" => vec![("FALSE".into(), V::I(0)), ("TRUE".into(), V::I(1))],
        "SINT" => ints(-128, 127),
        "INT" => ints(-32768, 32767),
        "DINT" => ints(i32::MIN as i128, i32::MAX as i128),
        "LINT" => ints(i64::MIN as i128, i64::MAX as i128),
        "USINT" | "BYTE" => ints(0, 255),
        "UINT" | "WORD" => ints(0, 65535),
        "UDINT" | "DWORD" => ints(0, u32::MAX as i128),
        "ULINT" | "LWORD" => ints(0, u64::MAX as i128),
        "REAL" => real("REAL", &[2147483648.0, -2147483648.0, 1.0e30]),
        "LREAL" => real(
            "LREAL",
            &[
                2147483647.5,
                2147483646.5,
                -2147483648.5,
                4294967295.5,
                4294967294.5,
                9.3e18,
                -9.3e18,
                1.9e19,
                1.0e300,
                4.0e38,
                3.4028235e38,
            ],
        ),
        "TIME" => time("T"),
        "LTIME" => time("LTIME"),
        "DATE" => vec![
            ("D#2024-01-31".into(), V::T(19753 * 86_400_000_000_000)),
            ("D#1970-01-01".into(), V::T(0)),
        ],
        "TOD" => vec![
            ("TOD#12:30:00.5".into(), V::T(45_000_500_000_000)),
            ("TOD#00:00:00".into(), V::T(0)),
        ],
        "DT" => vec![
            (
                "DT#2024-01-31-12:30:00".into(),
                V::T(19753 * 86_400_000_000_000 + 45_000_000_000_000),
            ),
            ("DT#1969-12-31-23:00:00".into(), V::T(-3_600_000_000_000)),
        ],
        // edition 3's long forms: the same values, their numbers in nanoseconds
        "LDATE" => vec![
            ("LDATE#2024-01-31".into(), V::T(19753 * 86_400_000_000_000)),
            ("LDATE#1969-12-31".into(), V::T(-86_400_000_000_000)),
        ],
        "LTOD" => vec![
            ("LTOD#12:30:00.000000005".into(), V::T(45_000_000_000_005)),
            ("LTOD#00:00:00".into(), V::T(0)),
        ],
        "LDT" => vec![
            (
                "LDT#2024-01-31-12:30:00.25".into(),
                V::T(19753 * 86_400_000_000_000 + 45_000_250_000_000),
            ),
            ("LDT#1969-12-31-23:00:00".into(), V::T(-3_600_000_000_000)),
        ],
        // edition 3's characters (their code); a NUL is the empty string's STRING_TO_CHAR
        "CHAR" => [
            ("CHAR#'A'", 65),
            ("CHAR#'$FF'", 255),
            ("CHAR#'$''", 39),
            ("','", 44),
        ]
        .iter()
        .map(|(l, c)| (l.to_string(), V::C(*c)))
        .collect(),
        "WCHAR" => [
            ("WCHAR#\"A\"", 65),
            ("WCHAR#\"$20AC\"", 0x20AC),
            ("WCHAR#\"$00E9\"", 0xE9),
            ("\"$\"\"", 34),
        ]
        .iter()
        .map(|(l, c)| (l.to_string(), V::C(*c)))
        .collect(),
        "STRING" => [
            "42",
            " -7 ",
            "300",
            "abc",
            "2.5",
            "TRUE",
            "FALSE",
            "T#1500ms",
            "D#2024-01-31",
            "TOD#12:30:00",
            "DT#2024-01-31-12:30:00",
            "LDT#2024-01-31-12:30:00",
            "",
        ]
        .iter()
        .map(|s| (format!("'{s}'"), V::S(s)))
        .collect(),
        other => panic!("no inputs for {other}"),
    }
}

/// An IEC real literal (always with a decimal point) that reads back as `x`.
fn real_literal(x: f64) -> String {
    if x.abs() < 1e16 {
        format!("{x:?}")
    } else {
        let e = format!("{x:e}");
        let (m, exp) = e.split_once('e').unwrap();
        let m = if m.contains('.') {
            m.to_string()
        } else {
            format!("{m}.0")
        };
        format!("{m}E{exp}")
    }
}

fn bits(t: &str) -> u32 {
    Elementary::from_name(t).map(|e| e.bit_width()).unwrap()
}
fn signed(t: &str) -> bool {
    matches!(t, "SINT" | "INT" | "DINT" | "LINT")
}
fn wrap(x: i128, t: &str) -> i128 {
    let n = bits(t);
    if t == "BOOL" {
        return (x != 0) as i128;
    }
    let m = x & ((1i128 << n) - 1);
    if signed(t) && m >= 1i128 << (n - 1) {
        m - (1i128 << n)
    } else {
        m
    }
}
fn limits(t: &str) -> (i128, i128) {
    let n = bits(t);
    if signed(t) {
        (-(1i128 << (n - 1)), (1i128 << (n - 1)) - 1)
    } else {
        (0, (1i128 << n) - 1)
    }
}
/// REAL to integer: halves to even, saturated, NaN 0.
fn round_sat(x: f64, t: &str, trunc: bool) -> i128 {
    if x.is_nan() {
        return 0;
    }
    let r = if trunc {
        x.trunc()
    } else {
        x.round_ties_even()
    };
    let (lo, hi) = limits(t);
    if r < lo as f64 {
        lo
    } else if r >= hi as f64 + 1.0 {
        hi
    } else {
        r as i128
    }
}

/// The expected value of `f(x)` into type `t`, as the trace prints it (None: compared as a real).
#[derive(Debug)]
enum Want {
    Text(String),
    Real(f64),
    Ns(i128),
}

fn real_of(t: &str, x: f64) -> Want {
    Want::Real(if t == "REAL" { x as f32 as f64 } else { x })
}

fn is_time(t: &str) -> bool {
    matches!(t, "TIME" | "LTIME")
}
fn is_date(t: &str) -> bool {
    matches!(t, "DATE" | "TOD" | "DT" | "LDATE" | "LTOD" | "LDT")
}
/// The edition-2 date type whose kind of value `t` holds (LDATE: DATE ...).
fn kind(t: &str) -> &str {
    t.strip_prefix('L').filter(|k| is_date(k)).unwrap_or(t)
}
/// The nanoseconds of one unit of the number a date converts to and from: seconds for DT and
/// DATE, milliseconds for TOD, nanoseconds for LDATE, LTOD and LDT.
fn date_unit(t: &str) -> i128 {
    match t {
        "TOD" => 1_000_000,
        "LDATE" | "LTOD" | "LDT" => 1,
        _ => 1_000_000_000,
    }
}
/// A number converted to TOD or LTOD keeps the time of day; to DATE or LDATE all of it, the part
/// below a day too (CODESYS and TwinCAT store a DATE as a DWORD of seconds and copy the number;
/// round 29 of issue #13, before: floored to the day; `values_r29_run.rs`).
fn within_day(t: &str, ns: i128) -> i128 {
    let day = 86_400_000_000_000i128;
    match kind(t) {
        "TOD" => ns.rem_euclid(day),
        _ => ns,
    }
}
fn is_real(t: &str) -> bool {
    matches!(t, "REAL" | "LREAL")
}

fn duration_text(ns: i128) -> String {
    let (s, m) = if ns < 0 { ("-", -ns) } else { ("", ns) };
    if m % 1_000_000 == 0 {
        format!("T#{s}{}ms", m / 1_000_000)
    } else if m % 1000 == 0 {
        format!("T#{s}{}us", m / 1000)
    } else {
        format!("T#{s}{m}ns")
    }
}

fn date_text(t: &str, ns: i128) -> String {
    let day = ns.div_euclid(86_400_000_000_000);
    let rem = ns.rem_euclid(86_400_000_000_000);
    let (y, mo, d) = civil(day as i64);
    let s = rem / 1_000_000_000;
    let frac = rem % 1_000_000_000;
    let mut clock = format!("{:02}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60);
    if frac != 0 {
        clock.push_str(format!(".{frac:09}").trim_end_matches('0'));
    }
    match t {
        "DATE" => format!("D#{y:04}-{mo:02}-{d:02}"),
        "LDATE" => format!("LDATE#{y:04}-{mo:02}-{d:02}"),
        "TOD" | "LTOD" => format!("{t}#{clock}"),
        _ => format!("{t}#{y:04}-{mo:02}-{d:02}-{clock}"),
    }
}

fn civil(z: i64) -> (i64, u32, u32) {
    let z = z + 719468;
    let era = z.div_euclid(146097);
    let doe = z.rem_euclid(146097);
    let yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    (yoe + era * 400 + (m <= 2) as i64, m, d)
}

/// A CHAR's or WCHAR's trace value (the runtime's `ladderc_format_value`): `CHAR#'A'`,
/// `WCHAR#"A"`, `$'` (`$"`) and `$$` escaped, a control character (and a WCHAR's surrogate) as
/// `$hh` (`$hhhh`).
fn char_text(t: &str, code: i128) -> String {
    let wide = t == "WCHAR";
    let q = if wide { '"' } else { '\'' };
    let c = code as u32;
    let body = match char::from_u32(c) {
        Some(ch) if ch == '$' || ch == q => format!("${ch}"),
        Some(ch) if !(c < 0x20 || (0x7F..0xA0).contains(&c)) => ch.to_string(),
        _ if wide => format!("${c:04X}"),
        _ => format!("${c:02X}"),
    };
    format!("{t}#{q}{body}{q}")
}
fn is_char(t: &str) -> bool {
    matches!(t, "CHAR" | "WCHAR")
}

fn string_to(s: &str, t: &str) -> Want {
    if is_char(t) {
        // edition 3: the first character (NUL of an empty string)
        return Want::Text(char_text(t, s.chars().next().map_or(0, |c| c as i128)));
    }
    let s = s.trim();
    let int = s.parse::<i128>().ok();
    match t {
        "BOOL" => Want::Text(
            match s {
                "TRUE" | "1" => "1",
                _ => "0",
            }
            .into(),
        ),
        _ if is_real(t) => real_of(t, s.parse::<f64>().unwrap_or(0.0)),
        _ if is_time(t) => Want::Ns(match s {
            "T#1500ms" => 1_500_000_000,
            _ => 0,
        }),
        _ if is_date(t) => {
            // a long form reads its own prefix and the short one's
            let ns = match (kind(t), s) {
                ("DATE", "D#2024-01-31") => 19753 * 86_400_000_000_000,
                ("TOD", "TOD#12:30:00") => 45_000_000_000_000,
                ("DT", "DT#2024-01-31-12:30:00") => 19753 * 86_400_000_000_000 + 45_000_000_000_000,
                ("DT", "LDT#2024-01-31-12:30:00") if t == "LDT" => {
                    19753 * 86_400_000_000_000 + 45_000_000_000_000
                }
                _ => 0,
            };
            Want::Text(date_text(t, ns))
        }
        _ if signed(t) => Want::Text(wrap(int.unwrap_or(0), t).to_string()),
        _ => Want::Text(wrap(int.filter(|v| *v >= 0).unwrap_or(0), t).to_string()),
    }
}

fn to_string_of(from: &str, x: &V) -> Want {
    Want::Text(match x {
        V::I(v) if from == "BOOL" => (if *v != 0 { "TRUE" } else { "FALSE" }).into(),
        V::I(v) => v.to_string(),
        V::R(r) => return Want::Real(*r), // the text is parsed back
        V::T(ns) if is_time(from) => duration_text(*ns),
        V::T(ns) => date_text(from, *ns),
        V::S(s) => s.to_string(),
        // the one-character string; a WCHAR beyond U+00FF a `?` (as WSTRING_TO_STRING)
        V::C(c) => char::from_u32(*c as u32)
            .filter(|_| *c <= 0xFF)
            .unwrap_or('?')
            .to_string(),
    })
}

/// The expected result of the conversion `name` (from `from` into `to`) of `x`.
fn expected(name: &str, from: &str, to: &str, x: &V) -> Want {
    let trunc = name == "TRUNC";
    if name.contains("BCD") {
        let V::I(v) = x else { unreachable!() };
        if name.contains("BCD_TO") {
            // decode: every nibble a digit, else 0
            let mut r = 0i128;
            let mut mul = 1i128;
            let mut b = *v;
            let mut ok = true;
            while b > 0 {
                let d = b & 15;
                ok &= d <= 9;
                r += d * mul;
                mul *= 10;
                b >>= 4;
            }
            return Want::Text(wrap(if ok { r } else { 0 }, to).to_string());
        }
        // encode: negative or too many digits for the target gives 0
        let digits = bits(to) / 4;
        if *v < 0 || *v >= 10i128.pow(digits) {
            return Want::Text("0".into());
        }
        let s = v.to_string();
        return Want::Text(i128::from_str_radix(&s, 16).unwrap().to_string());
    }
    if to == "STRING" {
        return to_string_of(from, x);
    }
    match x {
        V::S(s) => string_to(s, to),
        // WCHAR_TO_CHAR: a code beyond U+00FF is `?`; to a number, the code
        V::C(c) if to == "CHAR" && *c > 0xFF => Want::Text(char_text(to, '?' as i128)),
        V::C(c) if is_char(to) => Want::Text(char_text(to, *c)),
        V::C(c) => Want::Text(wrap(*c, to).to_string()),
        // a number to a character: its code, wrapped as to BYTE (WORD)
        V::I(v) if is_char(to) => Want::Text(char_text(to, wrap(*v, to))),
        V::I(v) => {
            if is_real(to) {
                real_of(to, *v as f64)
            } else if is_time(to) {
                Want::Ns(wrap(v * 1_000_000, "LINT"))
            } else if is_date(to) {
                Want::Text(date_text(
                    to,
                    within_day(to, wrap(v * date_unit(to), "LINT")),
                ))
            } else {
                Want::Text(wrap(*v, to).to_string())
            }
        }
        V::R(r) => {
            if to == "BOOL" {
                Want::Text(((*r != 0.0) as u8).to_string())
            } else if is_real(to) {
                real_of(to, *r)
            } else if to == "TIME" {
                // TIME counts whole milliseconds as CODESYS and TwinCAT (round 34,
                // `time_number_unit` "ms"): the number is rounded first, halves to even
                let ms = if r.is_nan() { *r } else { r.round_ties_even() };
                Want::Ns(round_sat(ms * 1e6, "LINT", false))
            } else if is_time(to) {
                // LTIME keeps the fraction of a millisecond
                Want::Ns(round_sat(r * 1e6, "LINT", false))
            } else if is_date(to) {
                let ns = round_sat(r * date_unit(to) as f64, "LINT", false);
                Want::Text(date_text(to, within_day(to, ns)))
            } else {
                Want::Text(round_sat(*r, to, trunc).to_string())
            }
        }
        V::T(ns) => {
            if is_time(from) {
                if is_time(to) {
                    Want::Ns(*ns)
                } else if is_date(to) {
                    // the same point of the time line from 1970-01-01-00:00 (round 27): TIME_TO_TOD
                    // (CODESYS) the time of day of the duration, TIME_TO_DATE its day,
                    // TIME_TO_DT the instant
                    let day = 86_400_000_000_000i128;
                    Want::Text(match kind(to) {
                        "DATE" => date_text(to, ns.div_euclid(day) * day),
                        "TOD" => date_text(to, ns.rem_euclid(day)),
                        _ => date_text(to, *ns),
                    })
                } else if is_real(to) {
                    real_of(to, *ns as f64 / 1e6)
                } else {
                    Want::Text(wrap(ns / 1_000_000, to).to_string())
                }
            } else if to == "BOOL" {
                Want::Text(((*ns != 0) as u8).to_string())
            } else if is_time(to) {
                // TOD_TO_TIME (CODESYS): the duration since midnight
                Want::Ns(*ns)
            } else if is_real(to) {
                real_of(to, *ns as f64 / date_unit(from) as f64)
            } else if !is_date(to) {
                // DT and DATE count seconds, TOD milliseconds (CODESYS, TwinCAT, OSCAT), the
                // long forms nanoseconds (edition 3)
                Want::Text(wrap(ns / date_unit(from), to).to_string())
            } else {
                let day = 86_400_000_000_000i128;
                Want::Text(match kind(to) {
                    "DATE" => date_text(to, ns.div_euclid(day) * day),
                    "TOD" => date_text(to, ns.rem_euclid(day)),
                    _ => date_text(to, *ns),
                })
            }
        }
    }
}

fn parse_real(s: &str) -> f64 {
    let s = s.trim_matches('"');
    match s {
        "inf" => f64::INFINITY,
        "-inf" => f64::NEG_INFINITY,
        "nan" | "-nan" => f64::NAN,
        _ => s.parse().unwrap_or_else(|_| panic!("not a real: {s}")),
    }
}

fn parse_ns(s: &str) -> i128 {
    let b = s
        .strip_prefix("T#")
        .unwrap_or_else(|| panic!("not a TIME: {s}"));
    let (neg, b) = match b.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, b),
    };
    let (num, mul) = if let Some(n) = b.strip_suffix("ms") {
        (n, 1_000_000)
    } else if let Some(n) = b.strip_suffix("us") {
        (n, 1000)
    } else {
        (b.strip_suffix("ns").unwrap(), 1)
    };
    let v: i128 = num.parse::<i128>().unwrap() * mul;
    if neg {
        -v
    } else {
        v
    }
}

/// The catalogue: every conversion name sema accepts, with its source and target types (a generic
/// source, as TRUNC or BCD_TO_INT, is tried with each type it takes).
fn type_name(t: &il_frontend::sema::Type) -> String {
    match t {
        il_frontend::sema::Type::String { wide: false, .. } => "STRING".into(),
        il_frontend::sema::Type::String { wide: true, .. } => "WSTRING".into(),
        t => t.elementary().expect("an elementary type").name().into(),
    }
}

fn catalogue() -> Vec<(String, String, String)> {
    let mut names: Vec<String> = Elementary::ALL
        .iter()
        .map(|e| e.name().to_string())
        .collect();
    names.extend(
        [
            "STRING",
            "WSTRING",
            "TIME_OF_DAY",
            "DATE_AND_TIME",
            "LTIME_OF_DAY",
            "LDATE_AND_TIME",
        ]
        .map(String::from),
    );
    let canon = |n: &str| -> String {
        match n {
            "TIME_OF_DAY" => "TOD".into(),
            "DATE_AND_TIME" => "DT".into(),
            "LTIME_OF_DAY" => "LTOD".into(),
            "LDATE_AND_TIME" => "LDT".into(),
            n => n.into(),
        }
    };
    let mut out = Vec::new();
    let mut cands: Vec<String> = vec!["TRUNC".into()];
    for a in &names {
        cands.push(format!("BCD_TO_{a}"));
        cands.push(format!("{a}_TO_BCD"));
        for b in &names {
            cands.push(format!("{a}_TO_{b}"));
            cands.push(format!("{a}_BCD_TO_{b}"));
            cands.push(format!("{a}_TO_BCD_{b}"));
        }
    }
    for c in cands {
        let Some(conv) = conversion(&c) else {
            continue;
        };
        let to = match &conv.to {
            il_frontend::sema::stdlib::ConvTarget::Fixed(t) => type_name(t),
            il_frontend::sema::stdlib::ConvTarget::BcdOfWidth => String::new(),
        };
        let sources: Vec<String> = match &conv.from {
            Some(t) => vec![type_name(t)],
            None if c == "TRUNC" => vec!["REAL".into(), "LREAL".into()],
            None => vec!["BYTE".into(), "WORD".into(), "DWORD".into(), "LWORD".into()],
        };
        for s in sources {
            let s = canon(s.split('[').next().unwrap());
            let t = if to.is_empty() {
                match bits(&s) {
                    8 => "BYTE".to_string(),
                    16 => "WORD".into(),
                    32 => "DWORD".into(),
                    _ => "LWORD".into(),
                }
            } else {
                canon(to.split('[').next().unwrap())
            };
            out.push((c.clone(), s, t));
        }
    }
    out
}

#[test]
fn every_conversion_of_the_catalogue_runs_as_iec_61131_3_says() {
    let cat = catalogue();
    assert!(cat.len() > 400, "{} conversions", cat.len());
    // WSTRING conversions are compared with their STRING twins in wstring_run.rs.
    let (wide, plain): (Vec<_>, Vec<_>) = cat
        .iter()
        .partition(|(_, f, t)| f == "WSTRING" || t == "WSTRING");
    let mut by_source: BTreeMap<&str, Vec<(&str, &str)>> = BTreeMap::new();
    for (n, f, t) in &plain {
        by_source
            .entry(f.as_str())
            .or_default()
            .push((n.as_str(), t.as_str()));
    }
    let dir = tempfile::tempdir().unwrap();
    let mut checked = 0usize;
    let mut failures = Vec::new();
    let mut all = String::new();
    for (from, convs) in &by_source {
        let ins = inputs(from);
        let prog = format!("conv_{}", from.to_ascii_lowercase());
        let mut decl = String::new();
        let mut body = String::new();
        if is_real(from) {
            decl.push_str("  big : LREAL := LREAL#1.0E300;\n  huge : LREAL;\n  nanv : LREAL;\n");
            body.push_str("  LD big\n  MUL big\n  ST huge\n  SUB huge\n  ST nanv\n");
        }
        for (k, (lit, _)) in ins.iter().enumerate() {
            let (init, computed) = match lit.as_str() {
                "inf" => (None, Some("  LD huge\n")),
                "-inf" => (None, Some("  LD LREAL#0.0\n  SUB huge\n")),
                "nan" => (None, Some("  LD nanv\n")),
                _ => (Some(lit.as_str()), None),
            };
            let ty = if *from == "STRING" { "STRING" } else { from };
            match init {
                Some(l) => decl.push_str(&format!("  i{k} : {ty} := {l};\n")),
                None => {
                    decl.push_str(&format!("  i{k} : {ty};\n"));
                    body.push_str(computed.unwrap());
                    if *from == "REAL" {
                        body.push_str("  LREAL_TO_REAL\n");
                    }
                    body.push_str(&format!("  ST i{k}\n"));
                }
            }
        }
        for (c, (name, to)) in convs.iter().enumerate() {
            for k in 0..ins.len() {
                decl.push_str(&format!("  o{c}_{k} : {to};\n"));
                body.push_str(&format!("  LD i{k}\n  {name}\n  ST o{c}_{k}\n"));
            }
        }
        all.push_str(&format!(
            "PROGRAM {prog}\nVAR\n{decl}END_VAR\n{body}END_PROGRAM\n"
        ));
    }
    // one file, one C build: every program runs once per cycle
    let file = dir.path().join("conversions.il");
    std::fs::write(&file, &all).unwrap();
    let trace = dir.path().join("conversions.csv");
    let out = ladderc()
        .arg("run")
        .arg(&file)
        .args(["--cycles", "1", "--sanitize", "--trace"])
        .arg(&trace)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(
        !stderr.contains("runtime error") && !stderr.contains("Sanitizer"),
        "undefined behaviour: {stderr}"
    );
    let text = std::fs::read_to_string(&trace).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row = common::split_csv(lines.next().unwrap());
    let col: BTreeMap<&str, &str> = head
        .iter()
        .copied()
        .zip(row.iter().map(|s| s.as_str()))
        .collect();
    for (from, convs) in &by_source {
        let ins = inputs(from);
        let prog = format!("conv_{}", from.to_ascii_lowercase());
        for (c, (name, to)) in convs.iter().enumerate() {
            for (k, (lit, x)) in ins.iter().enumerate() {
                let got = col[format!("{prog}.o{c}_{k}").as_str()];
                let want = expected(name, from, to, x);
                let ok = match &want {
                    Want::Text(w) if *to == "STRING" => got == format!("\"{w}\""),
                    // a character's field is quoted when it holds `"` or `,` (split_csv keeps
                    // the outer quotes)
                    Want::Text(w) if is_char(to) && (w.contains('"') || w.contains(',')) => {
                        got == format!("\"{w}\"")
                    }
                    Want::Text(w) => got == w,
                    Want::Real(w) => {
                        let g = parse_real(got);
                        let single = *to == "REAL" || (*to == "STRING" && *from == "REAL");
                        (g.is_nan() && w.is_nan())
                            || if single {
                                g as f32 == *w as f32
                            } else {
                                g == *w
                            }
                    }
                    Want::Ns(w) => parse_ns(got) == *w,
                };
                checked += 1;
                if !ok {
                    failures.push(format!("{name}({lit}) -> {to}: got {got}, want {want:?}"));
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {checked} results differ:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(checked > 3000, "{checked} results checked");
    // The anchors of issue #13.6, spelled out.
    for (x, want) in [
        (2.5, 2),
        (-2.5, -2),
        (0.5, 0),
        (1.5, 2),
        (-0.5, 0),
        (3.5, 4),
    ] {
        match expected("REAL_TO_INT", "REAL", "INT", &V::R(x)) {
            Want::Text(t) => assert_eq!(t, want.to_string()),
            w => panic!("{w:?}"),
        }
    }
    assert!(!wide.is_empty());
}
