//! Value decoding of IEC 61131-3 literal spellings: integers (`1_000`, `2#1010`, `16#FF`), reals
//! (`1.5e-3`), durations (`1h2m3.5s`, `-1m_30s`), dates (`2001-04-09`), times of day (`11:36:15.20`),
//! dates and times (`2001-04-09-11:36:15.20`) and `$` escapes of character strings.
//!
//! Input: the text of one literal without its `T#`/`D#`/... prefix. Output: the value in the unit the
//! syntax tree uses (nanoseconds, days since 1970-01-01) or a one-line reason the spelling is invalid.
//! Invariants: pure functions, no panics, no allocation except for decoded strings.

/// Nanoseconds in one second.
pub const NS_PER_S: i128 = 1_000_000_000;
/// Nanoseconds in one day.
pub const NS_PER_DAY: i128 = 86_400 * NS_PER_S;

/// Why a literal spelling has no value.
pub type Invalid = String;

/// Decimal integer with optional sign and `_` separators (`-1_000`).
pub fn decimal_int(text: &str) -> Result<i128, Invalid> {
    let (neg, digits) = split_sign(text);
    let mut v: i128 = 0;
    let mut seen = false;
    for c in digits.chars() {
        if c == '_' {
            continue;
        }
        let d = c
            .to_digit(10)
            .ok_or_else(|| format!("`{c}` is not a decimal digit"))?;
        seen = true;
        v = v
            .checked_mul(10)
            .and_then(|v| v.checked_add(d as i128))
            .ok_or_else(|| "integer literal is too large".to_string())?;
    }
    if !seen {
        return Err("integer literal has no digits".into());
    }
    Ok(if neg { -v } else { v })
}

/// `2#1010`, `8#777`, `16#FF_FF`: `text` is the whole spelling including the base and `#`.
pub fn based_int(text: &str) -> Result<i128, Invalid> {
    let (base_txt, digits) = text
        .split_once('#')
        .ok_or_else(|| "missing `#` in based literal".to_string())?;
    let base: u32 = match base_txt {
        "2" => 2,
        "8" => 8,
        "16" => 16,
        other => return Err(format!("base {other} is not supported (use 2#, 8# or 16#)")),
    };
    let mut v: i128 = 0;
    let mut seen = false;
    for c in digits.chars() {
        if c == '_' {
            continue;
        }
        let d = c
            .to_digit(base)
            .ok_or_else(|| format!("`{c}` is not a base-{base} digit"))?;
        seen = true;
        v = v
            .checked_mul(base as i128)
            .and_then(|v| v.checked_add(d as i128))
            .ok_or_else(|| "integer literal is too large".to_string())?;
    }
    if !seen {
        return Err(format!("base-{base} literal has no digits"));
    }
    Ok(v)
}

/// Real with optional sign, `_` separators and exponent (`-12e-5`, `1_000.5`).
pub fn real(text: &str) -> Result<f64, Invalid> {
    let cleaned: String = text.chars().filter(|&c| c != '_').collect();
    cleaned
        .parse::<f64>()
        .map_err(|_| format!("`{text}` is not a valid real literal"))
}

fn split_sign(text: &str) -> (bool, &str) {
    if let Some(r) = text.strip_prefix('-') {
        (true, r)
    } else if let Some(r) = text.strip_prefix('+') {
        (false, r)
    } else {
        (false, text)
    }
}

/// A decimal number with an optional fraction, as (integer part, fraction digits) — `_` removed.
fn number_parts(text: &str) -> Option<(i128, &str)> {
    let (int_txt, frac) = match text.split_once('.') {
        Some((i, f)) => (i, f),
        None => (text, ""),
    };
    if int_txt.is_empty() || !frac.chars().all(|c| c.is_ascii_digit() || c == '_') {
        return None;
    }
    let mut v: i128 = 0;
    for c in int_txt.chars() {
        if c == '_' {
            continue;
        }
        v = v.checked_mul(10)?.checked_add(c.to_digit(10)? as i128)?;
    }
    Some((v, frac))
}

/// `value.frac * unit` in integer nanoseconds (fraction truncated below 1 ns).
fn scaled(int: i128, frac: &str, unit: i128) -> Option<i128> {
    let mut total = int.checked_mul(unit)?;
    let mut scale = unit;
    for c in frac.chars().filter(|&c| c != '_') {
        scale /= 10;
        if scale == 0 {
            break;
        }
        total = total.checked_add(c.to_digit(10)? as i128 * scale)?;
    }
    Some(total)
}

/// The body of a `T#`/`TIME#` literal (`1h2m3.5s`, `-1m_30s`, `1h_15m_30s_60ms`) in nanoseconds.
pub fn duration(text: &str) -> Result<i128, Invalid> {
    let (neg, body) = split_sign(text);
    let bad = || format!("`{text}` is not a valid duration (write e.g. T#1h2m3s or T#1.5s)");
    if body.is_empty() {
        return Err("duration has no value (write e.g. T#100ms)".into());
    }
    let b = body.as_bytes();
    let mut i = 0;
    let mut total: i128 = 0;
    let mut components = 0;
    while i < b.len() {
        if b[i] == b'_' && components > 0 {
            i += 1;
            continue;
        }
        let start = i;
        while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'_' || b[i] == b'.') {
            i += 1;
        }
        let num = &body[start..i];
        if num.is_empty() {
            return Err(bad());
        }
        let ustart = i;
        while i < b.len() && b[i].is_ascii_alphabetic() {
            i += 1;
        }
        let unit = match body[ustart..i].to_ascii_lowercase().as_str() {
            "d" => NS_PER_DAY,
            "h" => 3_600 * NS_PER_S,
            "m" => 60 * NS_PER_S,
            "s" => NS_PER_S,
            "ms" => 1_000_000,
            "us" => 1_000,
            "ns" => 1,
            "" => {
                return Err(format!(
                    "`{text}`: a duration needs a unit (d, h, m, s, ms, us, ns)"
                ))
            }
            u => {
                return Err(format!(
                    "`{u}` is not a duration unit (d, h, m, s, ms, us, ns)"
                ))
            }
        };
        let (int, frac) = number_parts(num).ok_or_else(bad)?;
        total = scaled(int, frac, unit)
            .and_then(|v| total.checked_add(v))
            .ok_or_else(|| "duration is too large".to_string())?;
        components += 1;
    }
    Ok(if neg { -total } else { total })
}

/// Days since 1970-01-01 of a proleptic Gregorian date (Howard Hinnant's `days_from_civil`).
pub fn days_from_civil(y: i64, m: u32, d: u32) -> i64 {
    let y = if m <= 2 { y - 1 } else { y };
    let era = if y >= 0 { y } else { y - 399 } / 400;
    let yoe = y - era * 400;
    let m = m as i64;
    let doy = (153 * (if m > 2 { m - 3 } else { m + 9 }) + 2) / 5 + d as i64 - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    era * 146_097 + doe - 719_468
}

fn days_in_month(y: i64, m: u32) -> u32 {
    match m {
        1 | 3 | 5 | 7 | 8 | 10 | 12 => 31,
        4 | 6 | 9 | 11 => 30,
        _ if (y % 4 == 0 && y % 100 != 0) || y % 400 == 0 => 29,
        _ => 28,
    }
}

fn small_number(t: &str) -> Option<i64> {
    if t.is_empty() || t.len() > 9 || !t.bytes().all(|c| c.is_ascii_digit()) {
        return None;
    }
    t.parse().ok()
}

/// `2001-04-09` as days since 1970-01-01.
pub fn date(text: &str) -> Result<i64, Invalid> {
    let bad = || format!("`{text}` is not a valid date (write D#yyyy-mm-dd)");
    let mut parts = text.split('-');
    let (Some(y), Some(m), Some(d), None) =
        (parts.next(), parts.next(), parts.next(), parts.next())
    else {
        return Err(bad());
    };
    let (y, m, d) = (
        small_number(y).ok_or_else(bad)?,
        small_number(m).ok_or_else(bad)? as u32,
        small_number(d).ok_or_else(bad)? as u32,
    );
    if !(1..=12).contains(&m) || d == 0 || d > days_in_month(y, m) {
        return Err(format!("`{text}`: no such day"));
    }
    Ok(days_from_civil(y, m, d))
}

/// `11:36:15.20` as nanoseconds since midnight. `11:36` (no seconds, as CODESYS writes and
/// accepts it: `TOD#12:00`) is 11:36:00; the callers warn about it (W1445, see [`lacks_seconds`]).
pub fn time_of_day(text: &str) -> Result<i64, Invalid> {
    let bad = || format!("`{text}` is not a valid time of day (write TOD#hh:mm:ss.ff)");
    let mut parts = text.split(':');
    let (Some(h), Some(m), s, None) = (parts.next(), parts.next(), parts.next(), parts.next())
    else {
        return Err(bad());
    };
    let s = s.unwrap_or("0");
    let h = small_number(h).ok_or_else(bad)?;
    let m = small_number(m).ok_or_else(bad)?;
    let (sec, frac) = number_parts(s).ok_or_else(bad)?;
    if h > 23 || m > 59 || sec > 59 || s.starts_with('.') {
        return Err(format!("`{text}`: hour, minute or second out of range"));
    }
    let secs = (h * 3600 + m * 60) as i128 + sec;
    let ns = scaled(secs, frac, NS_PER_S).ok_or_else(bad)?;
    Ok(ns as i64)
}

/// `2001-04-09-11:36:15.20` as nanoseconds since 1970-01-01T00:00:00.
pub fn date_and_time(text: &str) -> Result<i128, Invalid> {
    let bad = || format!("`{text}` is not a valid date and time (write DT#yyyy-mm-dd-hh:mm:ss)");
    // The date has exactly two `-`; the third separates the time of day.
    let mut dashes = text.match_indices('-').map(|(i, _)| i);
    let (_, _, Some(cut)) = (dashes.next(), dashes.next(), dashes.next()) else {
        return Err(bad());
    };
    let days = date(&text[..cut]).map_err(|_| bad())?;
    let tod = time_of_day(&text[cut + 1..]).map_err(|_| bad())?;
    Ok(days as i128 * NS_PER_DAY + tod as i128)
}

/// A time-of-day or date-and-time literal's text (`TOD#12:00`, `DT#1970-1-1-00:00`, with or without
/// its prefix) whose time has hours and minutes but no seconds: IEC 61131-3's grammar
/// (`daytime ::= day_hour ':' day_minute ':' day_second`) requires the seconds, CODESYS accepts the
/// literal without them (its own exports and OSCAT write `TOD#12:00`), read as `:00` with W1445.
pub fn lacks_seconds(text: &str) -> bool {
    let body = text.rsplit_once('#').map_or(text, |(_, b)| b).trim();
    let time = body.rsplit('-').next().unwrap_or(body);
    time.matches(':').count() == 1
}

/// Decodes the `$` escapes of a string body (without quotes). `wide` (`"..."`) takes `$hhhh`, a
/// single-byte string (`'...'`) takes `$hh`. Returns the value and the byte offsets (within `body`) and
/// reasons of invalid escapes (kept literally in the value).
pub fn unescape(body: &str, wide: bool) -> (String, Vec<(usize, usize, Invalid)>) {
    let mut out = String::with_capacity(body.len());
    let mut errors = Vec::new();
    let mut chars = body.char_indices().peekable();
    while let Some((i, c)) = chars.next() {
        if c != '$' {
            out.push(c);
            continue;
        }
        let Some(&(_, e)) = chars.peek() else {
            errors.push((
                i,
                i + 1,
                "`$` at the end of a string (write `$$` for a dollar sign)".into(),
            ));
            out.push('$');
            continue;
        };
        let simple = match e.to_ascii_uppercase() {
            '$' => Some('$'),
            '\'' => Some('\''),
            '"' => Some('"'),
            'L' | 'N' => Some('\n'),
            'P' => Some('\u{0C}'),
            'R' => Some('\r'),
            'T' => Some('\t'),
            _ => None,
        };
        if let Some(s) = simple {
            chars.next();
            out.push(s);
            continue;
        }
        let n = if wide { 4 } else { 2 };
        let hex: String = body[i + 1..].chars().take(n).collect();
        if hex.len() == n && hex.chars().all(|h| h.is_ascii_hexdigit()) {
            let v = u32::from_str_radix(&hex, 16).unwrap_or(0);
            match char::from_u32(v) {
                Some(ch) => out.push(ch),
                None => {
                    errors.push((i, i + 1 + n, format!("`${hex}` is not a character")));
                }
            }
            for _ in 0..n {
                chars.next();
            }
        } else {
            let end = i + 1 + e.len_utf8();
            errors.push((
                i,
                end,
                format!(
                    "`${e}` is not a string escape (use $$, $', $\", $L, $N, $P, $R, $T or ${})",
                    if wide { "hhhh" } else { "hh" }
                ),
            ));
            out.push('$');
        }
    }
    (out, errors)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integers() {
        assert_eq!(decimal_int("1_000"), Ok(1000));
        assert_eq!(decimal_int("-12"), Ok(-12));
        assert_eq!(decimal_int("+7"), Ok(7));
        assert_eq!(based_int("2#1010_1010"), Ok(0xAA));
        assert_eq!(based_int("8#777"), Ok(0o777));
        assert_eq!(based_int("16#a5"), Ok(0xA5));
        assert_eq!(based_int("16#FFFF_FFFF_FFFF_FFFF"), Ok(u64::MAX as i128));
        assert!(based_int("2#102")
            .unwrap_err()
            .contains("`2` is not a base-2 digit"));
        assert!(based_int("3#1").unwrap_err().contains("base 3"));
        assert!(decimal_int("999999999999999999999999999999999999999999").is_err());
    }

    #[test]
    fn reals() {
        assert_eq!(real("-12e-5"), Ok(-12e-5));
        assert_eq!(real("1_000.25"), Ok(1000.25));
        assert_eq!(real("23.6"), Ok(23.6));
    }

    #[test]
    fn durations() {
        let s = NS_PER_S;
        assert_eq!(duration("1h2m3.5s"), Ok(3723 * s + s / 2));
        assert_eq!(duration("1h_15m_30s_60ms"), Ok(4530 * s + 60_000_000));
        assert_eq!(duration("-1m_30s"), Ok(-90 * s));
        assert_eq!(duration("18ms"), Ok(18_000_000));
        assert_eq!(duration("1.5d"), Ok(NS_PER_DAY * 3 / 2));
        assert_eq!(duration("10us5ns"), Ok(10_005));
        assert_eq!(duration("1M"), Ok(60 * s));
        assert!(duration("1x")
            .unwrap_err()
            .contains("`x` is not a duration unit"));
        assert!(duration("5").unwrap_err().contains("needs a unit"));
        assert!(duration("").is_err());
    }

    #[test]
    fn dates_and_times() {
        assert_eq!(date("1970-01-01"), Ok(0));
        assert_eq!(date("2001-04-09"), Ok(11_421));
        assert_eq!(date("2000-02-29"), Ok(11_016));
        assert!(date("2001-02-29").is_err());
        assert!(date("2001-13-01").is_err());
        assert_eq!(
            time_of_day("11:36:15.20"),
            Ok((11 * 3600 + 36 * 60 + 15) * 1_000_000_000 + 200_000_000_i64)
        );
        assert!(time_of_day("24:00:00").is_err());
        assert_eq!(time_of_day("9:0"), Ok(9 * 3600 * 1_000_000_000));
        assert!(time_of_day("9").is_err());
        assert!(time_of_day("9:60").is_err());
        assert_eq!(date_and_time("1970-1-1-00:00"), Ok(0));
        assert!(lacks_seconds("TOD#12:00"));
        assert!(lacks_seconds("DT#1970-1-1-00:00"));
        assert!(!lacks_seconds("TOD#12:00:00"));
        assert!(!lacks_seconds("DT#1970-1-1-00:00:00"));
        assert_eq!(
            date_and_time("2001-04-09-11:36:15.20"),
            Ok(11_421 * NS_PER_DAY + (41_775 * NS_PER_S + 200_000_000))
        );
        assert!(date_and_time("2001-04-09").is_err());
    }

    #[test]
    fn string_escapes() {
        let (v, e) = unescape("a$$b$'c$L$N$P$R$T$41", false);
        assert_eq!(v, "a$b'c\n\n\u{0C}\r\tA");
        assert!(e.is_empty());
        let (v, e) = unescape("$\"x$0041", true);
        assert_eq!(v, "\"xA");
        assert!(e.is_empty());
        let (v, e) = unescape("a$qb", false);
        assert_eq!(v, "a$qb");
        assert_eq!(e.len(), 1);
        assert_eq!((e[0].0, e[0].1), (1, 3));
    }
}
