//! Reading the small pieces of IEC text that PLCopen XML keeps in attributes and `<expression>` elements:
//! variable accesses, direct addresses, literals (with type prefixes, durations, v1.0 `hh:mm:ss.ffffff`
//! intervals).
//!
//! Input: the decoded text and the span it came from. Output: [`il_frontend::ast::Operand`]s whose spans all equal
//! the given span (the XML element or attribute), or `None` when the text is not a single operand (the
//! caller reports E3011). Invariants: no panics on any input; integers out of range give `None`.

use il_frontend::ast::{
    Accessor, AddressSize, Area, DirectAddress, Ident, Literal, LiteralKind, Operand, VarRef,
};
use il_frontend::Span;

/// A STRING (`wide`: WSTRING) variable's initial value as Beremiz generates it: text that does not
/// start with its type's quote (`'`, `"` for WSTRING) is the string itself, to which Beremiz's
/// `PLCGenerator.ComputeValue` adds the quotes (OpenPLC Editor writes `1234`, a Python file's
/// confnode `localhost`); `None` for text in the type's quotes, a literal that [`operand`] reads.
pub fn string_as_written(text: &str, wide: bool, span: Span) -> Option<Operand> {
    if text.trim().starts_with(if wide { '"' } else { '\'' }) {
        return None;
    }
    Some(Operand::literal(Literal {
        kind: LiteralKind::String {
            wide,
            value: text.to_string(),
        },
        type_prefix: None,
        span,
    }))
}

/// Parses one operand: literal, direct address, `Type#value` enum value, or variable access.
pub fn operand(text: &str, span: Span) -> Option<Operand> {
    let t = text.trim();
    if t.is_empty() {
        return None;
    }
    // A plain name (the usual contact or coil) is no literal unless it is TRUE or FALSE: skip the
    // literal readers.
    if is_ident(t) && !t.eq_ignore_ascii_case("TRUE") && !t.eq_ignore_ascii_case("FALSE") {
        return var_ref(t, span).map(Operand::Var);
    }
    if let Some(l) = literal(t, span) {
        return Some(Operand::literal(l));
    }
    if t.starts_with('%') {
        return address(t, span).map(Operand::Address);
    }
    if let Some((ty, val)) = t.split_once('#') {
        if is_ident(ty) && is_ident(val) {
            return Some(Operand::enum_value(
                Ident::new(ty, span),
                Ident::new(val, span),
                span,
            ));
        }
        return None;
    }
    var_ref(t, span).map(Operand::Var)
}

/// Whether `s` is an IEC identifier: a letter or `_`, then letters, digits, `_` (ASCII).
pub fn is_ident(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// The deepest nesting of `[` in an access that is read (`None` beyond, so E3011): indexes are read
/// recursively, and `x[x[x[...]]]` 5,000 deep overflowed the stack.
pub const MAX_INDEX_DEPTH: usize = 64;

/// `a`, `a.b`, `a[1, i].c` (indexes are operands themselves, nested at most [`MAX_INDEX_DEPTH`] deep).
pub fn var_ref(t: &str, span: Span) -> Option<VarRef> {
    let t = t.trim();
    let mut depth = 0usize;
    for c in t.bytes() {
        match c {
            b'[' => {
                depth += 1;
                if depth > MAX_INDEX_DEPTH {
                    return None;
                }
            }
            b']' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    let end = t
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(t.len());
    let base = &t[..end];
    if !is_ident(base) {
        return None;
    }
    let mut rest = t[end..].trim_start();
    let mut accessors = Vec::new();
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix('.') {
            let r = r.trim_start();
            let e = r
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(r.len());
            // `flags.2`, `w.%X3`: a partial access (3rd edition), a field named `2` or `%X3`
            let e = match r.strip_prefix('%') {
                Some(p) => {
                    1 + p
                        .find(|c: char| !c.is_ascii_alphanumeric())
                        .unwrap_or(p.len())
                }
                None => e,
            };
            if !is_ident(&r[..e]) && il_frontend::ast::partial_access(&r[..e]).is_none() {
                return None;
            }
            accessors.push(Accessor::Field(Ident::new(&r[..e], span)));
            rest = r[e..].trim_start();
        } else if let Some(r) = rest.strip_prefix('[') {
            let close = matching_bracket(r)?;
            let mut idx = Vec::new();
            for part in split_top(&r[..close]) {
                idx.push(operand(part, span)?);
            }
            accessors.push(Accessor::Index(idx));
            rest = r[close + 1..].trim_start();
        } else {
            return None;
        }
    }
    Some(VarRef {
        base: Ident::new(base, span),
        accessors: accessors.into(),
        span,
    })
}

fn matching_bracket(s: &str) -> Option<usize> {
    let mut depth = 0usize;
    for (i, c) in s.char_indices() {
        match c {
            '[' => depth += 1,
            ']' if depth == 0 => return Some(i),
            ']' => depth -= 1,
            _ => {}
        }
    }
    None
}

fn split_top(s: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut depth = 0usize;
    let mut start = 0;
    for (i, c) in s.char_indices() {
        match c {
            '[' => depth += 1,
            ']' => depth = depth.saturating_sub(1),
            ',' if depth == 0 => {
                out.push(&s[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(&s[start..]);
    out
}

/// `%IX0.1`, `%QW3`, `%MD10`, `%I*`.
pub fn address(t: &str, span: Span) -> Option<DirectAddress> {
    let rest = t.strip_prefix('%')?;
    let mut chars = rest.chars();
    let area = match chars.next()?.to_ascii_uppercase() {
        'I' => Area::Input,
        'Q' => Area::Output,
        'M' => Area::Memory,
        _ => return None,
    };
    let rest = &rest[1..];
    let (size, rest) = match rest.chars().next().map(|c| c.to_ascii_uppercase()) {
        Some('X') => (AddressSize::Bit, &rest[1..]),
        Some('B') => (AddressSize::Byte, &rest[1..]),
        Some('W') => (AddressSize::Word, &rest[1..]),
        Some('D') => (AddressSize::DWord, &rest[1..]),
        Some('L') => (AddressSize::LWord, &rest[1..]),
        _ => (AddressSize::Bit, rest),
    };
    let path = if rest == "*" {
        Vec::new()
    } else {
        rest.split('.')
            .map(|p| p.parse::<u32>().ok())
            .collect::<Option<Vec<_>>>()?
    };
    Some(DirectAddress {
        area,
        size,
        path,
        span,
    })
}

fn lit(kind: LiteralKind, prefix: Option<&str>, span: Span) -> Literal {
    Literal {
        kind,
        type_prefix: prefix.map(|p| Ident::new(p, span)),
        span,
    }
}

/// A literal in IEC syntax, or `None`.
pub fn literal(t: &str, span: Span) -> Option<Literal> {
    let t = t.trim();
    if t.eq_ignore_ascii_case("TRUE") || t.eq_ignore_ascii_case("FALSE") {
        return Some(lit(
            LiteralKind::Bool(t.eq_ignore_ascii_case("TRUE")),
            None,
            span,
        ));
    }
    // Strings first: their text may hold `#` (`'Step #1'`) and `$` escapes.
    if let Some(s) = t.strip_prefix('\'').and_then(|s| s.strip_suffix('\'')) {
        return Some(lit(
            LiteralKind::String {
                wide: false,
                value: unescape_string(s)?,
            },
            None,
            span,
        ));
    }
    if let Some(s) = t.strip_prefix('"').and_then(|s| s.strip_suffix('"')) {
        return Some(lit(
            LiteralKind::String {
                wide: true,
                value: unescape_string(s)?,
            },
            None,
            span,
        ));
    }
    // edition 3's typed characters: `CHAR#'A'`, `WCHAR#"A"` (a character's own text may be `#`)
    for (prefix, name) in [("CHAR#", "CHAR"), ("WCHAR#", "WCHAR")] {
        let Some(rest) = t
            .get(..prefix.len())
            .filter(|p| p.eq_ignore_ascii_case(prefix))
            .map(|_| &t[prefix.len()..])
        else {
            continue;
        };
        let q = rest.chars().next()?;
        let body = rest.strip_prefix(q)?.strip_suffix(q)?;
        if q != '\'' && q != '"' {
            return None;
        }
        return Some(lit(
            LiteralKind::String {
                wide: q == '"',
                value: unescape_string(body)?,
            },
            Some(name),
            span,
        ));
    }
    if let Some((prefix, value)) = t.split_once('#') {
        let p = prefix.to_ascii_uppercase();
        match p.as_str() {
            "T" | "TIME" | "LTIME" | "LT" => {
                return duration(value).map(|d| lit(LiteralKind::Duration(d), None, span))
            }
            // edition 3's long forms keep their canonical name as the prefix (their type)
            "D" | "DATE" | "LDATE" | "LD" => {
                let long = p.starts_with('L').then_some("LDATE");
                return date(value).map(|d| lit(LiteralKind::Date(d), long, span));
            }
            "TOD" | "TIME_OF_DAY" | "LTOD" | "LTIME_OF_DAY" => {
                let long = p.starts_with('L').then_some("LTOD");
                return time_of_day(value).map(|n| lit(LiteralKind::TimeOfDay(n), long, span));
            }
            "DT" | "DATE_AND_TIME" | "LDT" | "LDATE_AND_TIME" => {
                let long = p.starts_with('L').then_some("LDT");
                let (d, tod) = value.rsplit_once('-')?;
                let days = date(d)?;
                let ns = time_of_day(tod)?;
                return Some(lit(
                    LiteralKind::DateAndTime(days as i128 * 86_400_000_000_000 + ns as i128),
                    long,
                    span,
                ));
            }
            "2" | "8" | "16" => {
                let radix = p.parse().ok()?;
                let v = i128::from_str_radix(&value.replace('_', ""), radix).ok()?;
                return Some(lit(LiteralKind::Int(v), None, span));
            }
            _ if is_type_prefix(&p) => {
                let mut inner = literal(value, span)?;
                if p == "BOOL" {
                    if let LiteralKind::Int(v @ (0 | 1)) = inner.kind {
                        inner.kind = LiteralKind::Bool(v == 1);
                    }
                }
                inner.type_prefix = Some(Ident::new(prefix, span));
                return Some(inner);
            }
            _ => return None,
        }
    }
    number(t).map(|k| lit(k, None, span))
}

fn is_type_prefix(p: &str) -> bool {
    matches!(
        p,
        "BOOL"
            | "SINT"
            | "INT"
            | "DINT"
            | "LINT"
            | "USINT"
            | "UINT"
            | "UDINT"
            | "ULINT"
            | "REAL"
            | "LREAL"
            | "BYTE"
            | "WORD"
            | "DWORD"
            | "LWORD"
    )
}

fn number(t: &str) -> Option<LiteralKind> {
    let (neg, digits) = match t.as_bytes().first()? {
        b'-' => (true, &t[1..]),
        b'+' => (false, &t[1..]),
        _ => (false, t),
    };
    if !digits.as_bytes().first()?.is_ascii_digit() {
        return None;
    }
    let clean = digits.replace('_', "");
    if clean.bytes().all(|b| b.is_ascii_digit()) {
        let v: i128 = clean.parse().ok()?;
        return Some(LiteralKind::Int(if neg { -v } else { v }));
    }
    if clean
        .bytes()
        .all(|b| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-'))
    {
        let v: f64 = clean.parse().ok()?;
        return Some(LiteralKind::Real(if neg { -v } else { v }));
    }
    None
}

fn unescape_string(s: &str) -> Option<String> {
    let mut out = String::new();
    let mut chars = s.chars();
    while let Some(c) = chars.next() {
        if c != '$' {
            out.push(c);
            continue;
        }
        match chars.next()? {
            'L' | 'l' | 'N' | 'n' => out.push('\n'),
            'R' | 'r' => out.push('\r'),
            'T' | 't' => out.push('\t'),
            'P' | 'p' => out.push('\x0c'),
            '$' => out.push('$'),
            '\'' => out.push('\''),
            '"' => out.push('"'),
            h1 => {
                let h2 = chars.next()?;
                let v = u32::from_str_radix(&format!("{h1}{h2}"), 16).ok()?;
                out.push(char::from_u32(v)?);
            }
        }
    }
    Some(out)
}

/// `1h2m3s4ms`, `0.5ms`, `-5s`, `1d_2h` -> nanoseconds; also the v1.0 `hh:mm:ss.ffffff` form.
pub fn duration(t: &str) -> Option<i128> {
    let t = t.trim();
    if t.contains(':') {
        return clock_duration(t);
    }
    let (neg, mut rest) = match t.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, t.strip_prefix('+').unwrap_or(t)),
    };
    let mut total: f64 = 0.0;
    let mut any = false;
    while !rest.is_empty() {
        rest = rest.trim_start_matches('_');
        if rest.is_empty() {
            break;
        }
        let num_end = rest
            .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '_'))
            .unwrap_or(rest.len());
        if num_end == 0 {
            return None;
        }
        let value: f64 = rest[..num_end].replace('_', "").parse().ok()?;
        rest = &rest[num_end..];
        let unit_end = rest
            .find(|c: char| !c.is_ascii_alphabetic())
            .unwrap_or(rest.len());
        let unit = rest[..unit_end].to_ascii_lowercase();
        rest = &rest[unit_end..];
        let scale = match unit.as_str() {
            "d" => 86_400e9,
            "h" => 3_600e9,
            "m" => 60e9,
            "s" => 1e9,
            "ms" => 1e6,
            "us" => 1e3,
            "ns" => 1.0,
            _ => return None,
        };
        total += value * scale;
        any = true;
    }
    if !any {
        return None;
    }
    let ns = total.round() as i128;
    Some(if neg { -ns } else { ns })
}

/// An integer constant expression: integer literals (`16#FF`, `1_000`, `INT#5`), named constants
/// resolved by `lookup`, `+ - * /` (division truncates; by zero is an error), unary minus and
/// parentheses. The error text says what is wrong (`unknown constant `N``).
pub fn const_int_expr(t: &str, lookup: &dyn Fn(&str) -> Option<i128>) -> Result<i128, String> {
    struct P<'a> {
        s: &'a [u8],
        i: usize,
        depth: u32,
        lookup: &'a dyn Fn(&str) -> Option<i128>,
    }
    impl P<'_> {
        fn ws(&mut self) {
            while self.i < self.s.len() && self.s[self.i].is_ascii_whitespace() {
                self.i += 1;
            }
        }
        fn peek(&mut self) -> Option<u8> {
            self.ws();
            self.s.get(self.i).copied()
        }
        fn sum(&mut self) -> Result<i128, String> {
            let mut v = self.product()?;
            while let Some(op @ (b'+' | b'-')) = self.peek() {
                self.i += 1;
                let r = self.product()?;
                v = if op == b'+' {
                    v.checked_add(r)
                } else {
                    v.checked_sub(r)
                }
                .ok_or("the value overflows")?;
            }
            Ok(v)
        }
        fn product(&mut self) -> Result<i128, String> {
            let mut v = self.unary()?;
            while let Some(op @ (b'*' | b'/')) = self.peek() {
                self.i += 1;
                let r = self.unary()?;
                v = if op == b'*' {
                    v.checked_mul(r).ok_or("the value overflows")?
                } else if r == 0 {
                    return Err("division by zero".into());
                } else {
                    v / r
                };
            }
            Ok(v)
        }
        fn unary(&mut self) -> Result<i128, String> {
            self.depth += 1;
            if self.depth > 64 {
                return Err("the expression is nested too deeply".into());
            }
            let r = match self.peek() {
                Some(b'-') => {
                    self.i += 1;
                    self.unary().map(|v| -v)
                }
                Some(b'+') => {
                    self.i += 1;
                    self.unary()
                }
                Some(b'(') => {
                    self.i += 1;
                    let v = self.sum()?;
                    if self.peek() != Some(b')') {
                        return Err("`)` expected".into());
                    }
                    self.i += 1;
                    Ok(v)
                }
                Some(c) if c.is_ascii_alphanumeric() || c == b'_' => {
                    let start = self.i;
                    while self.i < self.s.len()
                        && (self.s[self.i].is_ascii_alphanumeric()
                            || matches!(self.s[self.i], b'_' | b'#' | b'.'))
                    {
                        self.i += 1;
                    }
                    let word = std::str::from_utf8(&self.s[start..self.i]).unwrap_or_default();
                    if c.is_ascii_digit() || word.contains('#') {
                        match literal(word, Span::default()).map(|l| l.kind) {
                            Some(LiteralKind::Int(v)) => Ok(v),
                            _ => Err(format!("`{word}` is not an integer")),
                        }
                    } else {
                        (self.lookup)(word).ok_or_else(|| format!("unknown constant `{word}`"))
                    }
                }
                Some(c) => Err(format!("unexpected `{}`", c as char)),
                None => Err("a value is missing".into()),
            };
            self.depth -= 1;
            r
        }
    }
    let mut p = P {
        s: t.as_bytes(),
        i: 0,
        depth: 0,
        lookup,
    };
    let v = p.sum()?;
    match p.peek() {
        None => Ok(v),
        Some(c) => Err(format!("unexpected `{}`", c as char)),
    }
}

/// An xsd:duration (`PT0.05S`, `PT1H2M3.5S`, `P1DT2H`, tc6_0200/0201 task intervals) in nanoseconds.
/// Years and months have no fixed length and are refused; so are a negative sign, a fraction finer
/// than a nanosecond, an empty `PT`, and parts out of order. The error text says which.
pub fn xsd_duration(t: &str) -> Result<i128, String> {
    let t = t.trim();
    if t.starts_with('-') {
        return Err("a task interval cannot be negative".into());
    }
    let Some(mut rest) = t.strip_prefix('P') else {
        return Err("an xsd:duration starts with `P`".into());
    };
    let mut total: i128 = 0;
    let mut in_time = false;
    let mut any = false;
    // each unit may appear once, in this order
    let order = ["Y", "M", "W", "D", "TH", "TM", "TS"];
    let mut last = 0usize;
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix('T') {
            if in_time {
                return Err("`T` appears twice".into());
            }
            in_time = true;
            rest = r;
            if rest.is_empty() {
                return Err("`T` must be followed by hours, minutes or seconds".into());
            }
            continue;
        }
        let end = rest
            .find(|c: char| !(c.is_ascii_digit() || c == '.'))
            .ok_or("a number must be followed by a unit (H, M or S)")?;
        let (num, tail) = rest.split_at(end);
        if num.is_empty() {
            return Err(format!("a number is missing before `{}`", &tail[..1]));
        }
        let unit = tail.chars().next().unwrap_or_default().to_ascii_uppercase();
        rest = &tail[unit.len_utf8()..];
        let key = format!("{}{unit}", if in_time { "T" } else { "" });
        let Some(pos) = order.iter().position(|o| *o == key) else {
            return Err(format!("`{unit}` is not a unit here"));
        };
        if pos < last || (any && pos == last) {
            return Err("the parts are out of order or repeated".into());
        }
        last = pos;
        if matches!(key.as_str(), "Y" | "M") {
            return Err("years and months have no fixed length; write the interval in days, hours, minutes or seconds".into());
        }
        let (int, frac) = num.split_once('.').unwrap_or((num, ""));
        if (frac.contains('.')) || (int.is_empty() && frac.is_empty()) {
            return Err(format!("`{num}` is not a number"));
        }
        if !frac.is_empty() && key != "TS" {
            return Err("only the seconds may have a fraction".into());
        }
        if frac.len() > 9 {
            return Err("the fraction of a second is finer than a nanosecond".into());
        }
        let scale: i128 = match key.as_str() {
            "W" => 7 * 86_400_000_000_000,
            "D" => 86_400_000_000_000,
            "TH" => 3_600_000_000_000,
            "TM" => 60_000_000_000,
            _ => 1_000_000_000,
        };
        let whole: i128 = if int.is_empty() {
            0
        } else {
            int.parse().map_err(|_| format!("`{num}` is too large"))?
        };
        let frac_ns: i128 = if frac.is_empty() {
            0
        } else {
            format!("{frac:0<9}").parse().unwrap_or(0)
        };
        total = whole
            .checked_mul(scale)
            .and_then(|v| v.checked_add(frac_ns))
            .and_then(|v| v.checked_add(total))
            .filter(|v| *v <= i64::MAX as i128)
            .ok_or("the interval is too long")?;
        any = true;
    }
    if !any {
        return Err("the duration has no value".into());
    }
    Ok(total)
}

/// `00:00:00.100000` (the v1.0 schema's xsd:time intervals).
fn clock_duration(t: &str) -> Option<i128> {
    let parts: Vec<&str> = t.split(':').collect();
    if parts.len() != 3 {
        return None;
    }
    let h: i128 = parts[0].parse().ok()?;
    let m: i128 = parts[1].parse().ok()?;
    let s: f64 = parts[2].parse().ok()?;
    Some((h * 3600 + m * 60) * 1_000_000_000 + (s * 1e9).round() as i128)
}

fn date(t: &str) -> Option<i64> {
    let mut it = t.split('-');
    let y: i64 = it.next()?.parse().ok()?;
    let m: i64 = it.next()?.parse().ok()?;
    let d: i64 = it.next()?.parse().ok()?;
    if it.next().is_some() || !(1..=12).contains(&m) || !(1..=31).contains(&d) {
        return None;
    }
    // Days from civil (Howard Hinnant's algorithm).
    let y = if m <= 2 { y - 1 } else { y };
    let era = y.div_euclid(400);
    let yoe = y - era * 400;
    let mp = (m + 9) % 12;
    let doy = (153 * mp + 2) / 5 + d - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    Some(era * 146_097 + doe - 719_468)
}

/// `hh:mm:ss.ff`, or `hh:mm` without seconds as CODESYS writes it (`TIME_OF_DAY#3:0`; the
/// caller warns W1445).
fn time_of_day(t: &str) -> Option<i64> {
    let d = if t.matches(':').count() == 1 {
        clock_duration(&format!("{t}:0"))?
    } else {
        clock_duration(t)?
    };
    i64::try_from(d).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sp() -> Span {
        Span::default()
    }

    #[test]
    fn reads_literals() {
        let k = |t: &str| literal(t, sp()).map(|l| l.kind);
        assert_eq!(k("T#4s"), Some(LiteralKind::Duration(4_000_000_000)));
        assert_eq!(k("T#0.5ms"), Some(LiteralKind::Duration(500_000)));
        assert_eq!(
            k("TIME#1h2m"),
            Some(LiteralKind::Duration(3_720_000_000_000))
        );
        assert_eq!(k("2240.0"), Some(LiteralKind::Real(2240.0)));
        assert_eq!(k("-17"), Some(LiteralKind::Int(-17)));
        assert_eq!(k("16#FF"), Some(LiteralKind::Int(255)));
        assert_eq!(k("FALSE"), Some(LiteralKind::Bool(false)));
        assert_eq!(k("D#1970-01-02"), Some(LiteralKind::Date(1)));
        assert_eq!(
            k("'a$'b'"),
            Some(LiteralKind::String {
                wide: false,
                value: "a'b".into()
            })
        );
        assert_eq!(
            literal("INT#5", sp()).unwrap().type_prefix.unwrap().name,
            "INT"
        );
        assert!(literal("abc", sp()).is_none());
        assert_eq!(duration("00:00:00.100000"), Some(100_000_000));
        assert_eq!(xsd_duration("PT0.05S"), Ok(50_000_000));
        assert_eq!(xsd_duration("PT1H2M3.5S"), Ok(3_723_500_000_000));
        assert_eq!(xsd_duration("P1DT1S"), Ok(86_401_000_000_000));
        for bad in [
            "PT",
            "P",
            "PT1M1H",
            "P1M",
            "-PT1S",
            "PT0.0000000001S",
            "PT1.5M",
            "PTS",
            "PT5",
        ] {
            assert!(xsd_duration(bad).is_err(), "{bad}");
        }
        let c = |n: &str| (n == "N").then_some(8);
        assert_eq!(const_int_expr("N", &c), Ok(8));
        assert_eq!(const_int_expr(" (N - 1) * 2 + 16#10 ", &c), Ok(30));
        assert!(const_int_expr("M", &c)
            .unwrap_err()
            .contains("unknown constant `M`"));
        assert!(const_int_expr("N /0", &c).is_err());
        assert!(const_int_expr(&"(".repeat(1000), &c).is_err());
    }

    #[test]
    fn reads_variables_and_addresses() {
        let Some(Operand::Var(v)) = operand("Tmr.Q", sp()) else {
            panic!()
        };
        assert_eq!(v.base.name, "Tmr");
        assert_eq!(v.accessors.len(), 1);
        let Some(Operand::Var(v)) = operand("a[1, i].b", sp()) else {
            panic!()
        };
        assert_eq!(v.accessors.len(), 2);
        let Some(Operand::Address(a)) = operand("%QX0.1", sp()) else {
            panic!()
        };
        assert_eq!(
            (a.area, a.size, a.path),
            (Area::Output, AddressSize::Bit, vec![0, 1])
        );
        assert!(operand("a +", sp()).is_none());
        assert!(operand("", sp()).is_none());
        assert!(matches!(
            operand("Color#red", sp()),
            Some(Operand::EnumValue(_))
        ));
    }

    #[test]
    fn plain_names_are_variables_but_true_and_false_are_literals() {
        let Some(Operand::Var(v)) = operand(" a0 ", sp()) else {
            panic!()
        };
        assert_eq!((v.base.name.as_str(), v.accessors.len()), ("a0", 0));
        let Some(Operand::Var(v)) = operand("_x", sp()) else {
            panic!()
        };
        assert_eq!(v.base.name, "_x");
        for (text, want) in [("TRUE", true), ("false", false), ("True", true)] {
            let Some(Operand::Literal(l)) = operand(text, sp()) else {
                panic!("{text}")
            };
            assert!(
                matches!(l.kind, LiteralKind::Bool(b) if b == want),
                "{text}"
            );
        }
        assert!(matches!(operand("truex", sp()), Some(Operand::Var(_))));
    }
}
