//! The raw trace of the scan harness (`program --trace-raw`) turned into the CSV trace.
//!
//! Input: the byte stream the harness writes with `--trace-raw`: the CSV text of every non-REAL field
//! (formatted by the harness), and in place of each REAL/LREAL value a marker byte and its raw bits in
//! host byte order ([`F64`] + 8 bytes, [`F32`] + 4 bytes); [`ESC`] + a byte stands for that byte of text
//! (a name or a string holding a marker byte), [`SAME`] is a float equal to its column's in the row before
//! and [`EOR`] ends a row.
//! Output: the CSV bytes, identical to the trace the harness writes without `--trace-raw`: a REAL/LREAL is
//! the harness's `format_real`, the shortest `%.{P}g` (P from 15 to 17 for LREAL, 6 to 9 for REAL) that
//! reads back to the same value, computed here from ryu's shortest digits.
//! Invariants: the fast path (ryu) is taken only where its digits provably equal the `%g` loop's: normal
//! values that are not a power of two (a symmetric rounding interval), and for REAL at most 6 digits;
//! every other value takes the exact path, the harness's loop itself on Rust's exact formatting. Each
//! float column keeps its last bits and text, so an unchanged value is copied, not formatted again. No
//! allocation per row once the first row has been seen.

use std::io::{self, Read, Write};

/// Marker: an LREAL value follows (8 bytes).
pub const F64: u8 = 1;
/// Marker: a REAL value follows (4 bytes).
pub const F32: u8 = 2;
/// Marker: the next byte is text.
pub const ESC: u8 = 3;
/// Marker: end of a row (a newline in the CSV).
pub const EOR: u8 = 4;
/// Marker: the float of this column in the row before, again.
pub const SAME: u8 = 5;

/// The longest text of a float (`-2.2250738585072014e-308` is 24 bytes).
const TEXT_MAX: usize = 32;

#[derive(Clone, Copy)]
struct Cached {
    bits: u64,
    len: u8,
    text: [u8; TEXT_MAX],
}

/// Converts a raw trace from `input` into CSV on `out`; returns the bytes written.
pub fn convert(mut input: impl Read, out: &mut impl Write) -> io::Result<u64> {
    let mut conv = Converter::default();
    let mut buf = vec![0u8; 1 << 16];
    let mut have = 0usize;
    let mut csv = Vec::with_capacity(1 << 17);
    let mut written = 0u64;
    loop {
        let n = input.read(&mut buf[have..])?;
        let end = n == 0;
        have += n;
        let used = conv.feed(&buf[..have], &mut csv);
        buf.copy_within(used..have, 0);
        have -= used;
        if csv.len() >= 1 << 16 || end {
            out.write_all(&csv)?;
            written += csv.len() as u64;
            csv.clear();
        }
        if end {
            if have > 0 {
                return Err(io::Error::new(
                    io::ErrorKind::UnexpectedEof,
                    "the raw trace ends inside a value",
                ));
            }
            out.flush()?;
            return Ok(written);
        }
    }
}

/// Converts a whole raw trace held in memory.
pub fn convert_bytes(raw: &[u8]) -> io::Result<Vec<u8>> {
    let mut out = Vec::with_capacity(raw.len());
    convert(raw, &mut out)?;
    Ok(out)
}

#[derive(Default)]
struct Converter {
    /// Per float column of a row, in order: the last value and its text.
    cache: Vec<Option<Cached>>,
    /// The float column the next marker belongs to.
    column: usize,
    ryu: ryu::Buffer,
}

impl Converter {
    /// Converts the complete items at the start of `data`; returns how many bytes were used (the rest is an
    /// item cut by the end of the chunk).
    fn feed(&mut self, data: &[u8], csv: &mut Vec<u8>) -> usize {
        let mut i = 0;
        while i < data.len() {
            let plain = text_run(&data[i..]);
            csv.extend_from_slice(&data[i..i + plain]);
            i += plain;
            let Some(&marker) = data.get(i) else { break };
            let size = match marker {
                F64 => 9,
                F32 => 5,
                ESC => 2,
                _ => 1,
            };
            if i + size > data.len() {
                break;
            }
            match marker {
                F64 => {
                    let mut b = [0u8; 8];
                    b.copy_from_slice(&data[i + 1..i + 9]);
                    self.float(u64::from_ne_bytes(b), false, csv);
                }
                F32 => {
                    let mut b = [0u8; 4];
                    b.copy_from_slice(&data[i + 1..i + 5]);
                    self.float(u64::from(u32::from_ne_bytes(b)), true, csv);
                }
                ESC => csv.push(data[i + 1]),
                SAME => self.same(csv),
                _ => {
                    csv.push(b'\n');
                    self.column = 0;
                }
            }
            i += size;
        }
        i
    }

    /// The float of the current column in the row before (nothing when there was none: the harness never
    /// writes SAME for a column's first value).
    fn same(&mut self, csv: &mut Vec<u8>) {
        if let Some(Some(c)) = self.cache.get(self.column) {
            csv.extend_from_slice(&c.text[..c.len as usize]);
        }
        self.column += 1;
    }

    fn float(&mut self, bits: u64, single: bool, csv: &mut Vec<u8>) {
        let column = self.column;
        self.column += 1;
        if self.cache.len() <= column {
            self.cache.resize(column + 1, None);
        }
        if let Some(c) = &self.cache[column] {
            if c.bits == bits {
                csv.extend_from_slice(&c.text[..c.len as usize]);
                return;
            }
        }
        let start = csv.len();
        if single {
            format_real_with(f32::from_bits(bits as u32), &mut self.ryu, csv);
        } else {
            format_lreal_with(f64::from_bits(bits), &mut self.ryu, csv);
        }
        let text = &csv[start..];
        let mut c = Cached {
            bits,
            len: text.len() as u8,
            text: [0; TEXT_MAX],
        };
        c.text[..text.len()].copy_from_slice(text);
        self.cache[column] = Some(c);
    }
}

/// The length of the text at the start of `data`: up to its first marker byte (0x01 to 0x05), or all of
/// it. Eight bytes at a time: a word holds a byte below 6 when `(x - 0x06..06) & !x & 0x80..80` is not 0.
fn text_run(data: &[u8]) -> usize {
    const ONES: u64 = 0x0101_0101_0101_0101;
    let mut k = 0;
    for chunk in data.chunks_exact(8) {
        let mut w = [0u8; 8];
        w.copy_from_slice(chunk);
        let x = u64::from_le_bytes(w);
        if x.wrapping_sub(ONES * 6) & !x & (ONES * 0x80) != 0 {
            break;
        }
        k += 8;
    }
    k + data[k..]
        .iter()
        .position(|b| (F64..=SAME).contains(b))
        .unwrap_or(data.len() - k)
}

/// An LREAL as the harness's `format_real(v, 0)` writes it.
pub fn format_lreal(v: f64, out: &mut Vec<u8>) {
    format_lreal_with(v, &mut ryu::Buffer::new(), out)
}

/// A REAL as the harness's `format_real(v, 1)` writes it.
pub fn format_real(v: f32, out: &mut Vec<u8>) {
    format_real_with(v, &mut ryu::Buffer::new(), out)
}

fn format_lreal_with(v: f64, ryu: &mut ryu::Buffer, out: &mut Vec<u8>) {
    if special(
        v.is_nan(),
        v.is_infinite(),
        v == 0.0,
        v.is_sign_negative(),
        out,
    ) {
        return;
    }
    let bits = v.to_bits();
    if v.is_normal() && bits & ((1 << 52) - 1) != 0 {
        let d = Decimal::parse(ryu.format_finite(v));
        d.write_g(15.max(d.len as i32), out);
    } else {
        exact_g(
            |p| format!("{:.*e}", (p - 1) as usize, v),
            |s| s.parse() == Ok(v),
            15..=17,
            out,
        );
    }
}

fn format_real_with(v: f32, ryu: &mut ryu::Buffer, out: &mut Vec<u8>) {
    if special(
        v.is_nan(),
        v.is_infinite(),
        v == 0.0,
        v.is_sign_negative(),
        out,
    ) {
        return;
    }
    let bits = v.to_bits();
    if v.is_normal() && bits & ((1 << 23) - 1) != 0 {
        let d = Decimal::parse(ryu.format_finite(v));
        if d.len <= 6 {
            d.write_g(6, out);
            return;
        }
    }
    // `(float)strtod(buf) == (float)v`: read as a double, then rounded to a float, as the harness does
    let wide = f64::from(v);
    let reads_back = |s: &str| s.parse::<f64>().is_ok_and(|r| r as f32 == v);
    exact_g(
        |p| format!("{:.*e}", (p - 1) as usize, wide),
        reads_back,
        6..=9,
        out,
    );
}

/// `nan`, `-nan`, `inf`, `-inf`, `0`, `-0` as glibc's `%g` writes them; false for any other value.
fn special(nan: bool, inf: bool, zero: bool, negative: bool, out: &mut Vec<u8>) -> bool {
    if !(nan || inf || zero) {
        return false;
    }
    if negative {
        out.push(b'-');
    }
    out.extend_from_slice(match (nan, inf) {
        (true, _) => b"nan",
        (_, true) => b"inf",
        _ => b"0",
    });
    true
}

/// The harness's loop: the first precision `p` whose correctly rounded `%.{p}e` reads back.
fn exact_g(
    sci: impl Fn(i32) -> String,
    reads_back: impl Fn(&str) -> bool,
    precisions: std::ops::RangeInclusive<i32>,
    out: &mut Vec<u8>,
) {
    let last = *precisions.end();
    for p in precisions {
        let s = sci(p);
        if p == last || reads_back(&s) {
            Decimal::parse(&s).write_g(p, out);
            return;
        }
    }
}

/// A finite non-zero decimal: `0.d1 d2 ... dn` times ten to `exp + 1`, i.e. `d1.d2...dn e exp`, without
/// leading or trailing zero digits.
struct Decimal {
    negative: bool,
    digits: [u8; 20],
    len: usize,
    exp: i32,
}

impl Decimal {
    /// Reads `-123.45`, `1e16`, `1.5e-7`, `1.2300e5` (ryu's and Rust's `{:e}` forms).
    fn parse(s: &str) -> Decimal {
        let b = s.as_bytes();
        let negative = b.first() == Some(&b'-');
        let body = if negative { &b[1..] } else { b };
        let (mantissa, e) = match body.iter().position(|&c| c == b'e' || c == b'E') {
            Some(k) => (&body[..k], parse_exp(&body[k + 1..])),
            None => (body, 0),
        };
        let mut d = Decimal {
            negative,
            digits: [0; 20],
            len: 0,
            exp: 0,
        };
        let mut before_point = 0i32;
        let mut seen_point = false;
        let mut leading = 0i32;
        for &c in mantissa {
            if c == b'.' {
                seen_point = true;
                continue;
            }
            if !seen_point {
                before_point += 1;
            }
            if d.len == 0 && c == b'0' {
                leading += 1;
                continue;
            }
            if d.len < d.digits.len() {
                d.digits[d.len] = c;
                d.len += 1;
            }
        }
        while d.len > 1 && d.digits[d.len - 1] == b'0' {
            d.len -= 1;
        }
        d.exp = before_point - 1 - leading + e;
        d
    }

    /// `%.{p}g` of this decimal (which has at most `p` digits), trailing zeros removed as `%g` does.
    fn write_g(&self, p: i32, out: &mut Vec<u8>) {
        let digits = &self.digits[..self.len];
        if self.negative {
            out.push(b'-');
        }
        let x = self.exp;
        if x < -4 || x >= p {
            out.push(digits[0]);
            if digits.len() > 1 {
                out.push(b'.');
                out.extend_from_slice(&digits[1..]);
            }
            out.push(b'e');
            out.push(if x < 0 { b'-' } else { b'+' });
            let m = x.unsigned_abs();
            if m < 10 {
                out.push(b'0');
            }
            out.extend_from_slice(m.to_string().as_bytes());
        } else if x >= 0 {
            let int = x as usize + 1;
            for k in 0..int {
                out.push(*digits.get(k).unwrap_or(&b'0'));
            }
            if digits.len() > int {
                out.push(b'.');
                out.extend_from_slice(&digits[int..]);
            }
        } else {
            out.extend_from_slice(b"0.");
            for _ in 0..(-x - 1) {
                out.push(b'0');
            }
            out.extend_from_slice(digits);
        }
    }
}

fn parse_exp(b: &[u8]) -> i32 {
    let (neg, digits) = match b.first() {
        Some(b'-') => (true, &b[1..]),
        Some(b'+') => (false, &b[1..]),
        _ => (false, b),
    };
    let m = digits
        .iter()
        .fold(0i32, |a, &c| a * 10 + i32::from(c - b'0'));
    if neg {
        -m
    } else {
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The harness's `format_real` itself, on Rust's exact formatting: the reference of the fast path.
    fn reference_lreal(v: f64) -> String {
        let mut out = Vec::new();
        if !special(
            v.is_nan(),
            v.is_infinite(),
            v == 0.0,
            v.is_sign_negative(),
            &mut out,
        ) {
            exact_g(
                |p| format!("{:.*e}", (p - 1) as usize, v),
                |s| s.parse() == Ok(v),
                15..=17,
                &mut out,
            );
        }
        String::from_utf8(out).unwrap()
    }

    fn reference_real(v: f32) -> String {
        let mut out = Vec::new();
        if !special(
            v.is_nan(),
            v.is_infinite(),
            v == 0.0,
            v.is_sign_negative(),
            &mut out,
        ) {
            let wide = f64::from(v);
            let reads_back = |s: &str| s.parse::<f64>().is_ok_and(|r| r as f32 == v);
            exact_g(
                |p| format!("{:.*e}", (p - 1) as usize, wide),
                reads_back,
                6..=9,
                &mut out,
            );
        }
        String::from_utf8(out).unwrap()
    }

    fn lreal(v: f64) -> String {
        let mut out = Vec::new();
        format_lreal(v, &mut out);
        String::from_utf8(out).unwrap()
    }

    fn real(v: f32) -> String {
        let mut out = Vec::new();
        format_real(v, &mut out);
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn lreal_as_glibc_g_writes_it() {
        // the outputs of the harness's format_real (glibc printf and strtod), compiled and run
        for (v, text) in [
            (0.1, "0.1"),
            (0.1 + 0.2, "0.30000000000000004"),
            (100.0, "100"),
            (1e15, "1e+15"),
            (1e14, "100000000000000"),
            (123456789012345680.0, "1.2345678901234568e+17"),
            (0.0001, "0.0001"),
            (0.00001, "1e-05"),
            (-2.5e-300, "-2.5e-300"),
            (1.0 / 3.0, "0.3333333333333333"),
            (5e-324, "4.94065645841247e-324"),
            (-0.0, "-0"),
            (f64::INFINITY, "inf"),
            (f64::NEG_INFINITY, "-inf"),
            (f64::NAN, "nan"),
            (-f64::NAN, "-nan"),
            (2f64.powi(-25), "2.9802322387695312e-08"),
        ] {
            assert_eq!(lreal(v), text, "{v:e}");
        }
    }

    #[test]
    fn real_as_glibc_g_writes_it() {
        for (v, text) in [
            (0.1f32, "0.1"),
            (1.0f32 / 3.0, "0.33333334"),
            (16777216.0f32, "16777216"),
            (1e-7f32, "1e-07"),
            (-40.0f32, "-40"),
            (f32::MIN_POSITIVE / 8.0, "1.469368e-39"),
        ] {
            assert_eq!(real(v), text, "{v:e}");
        }
    }

    /// xorshift64*: a fixed, dependency-free sequence of bit patterns.
    fn patterns(n: usize) -> impl Iterator<Item = u64> {
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        (0..n).map(move |_| {
            x ^= x >> 12;
            x ^= x << 25;
            x ^= x >> 27;
            x.wrapping_mul(0x2545_F491_4F6C_DD1D)
        })
    }

    #[test]
    fn the_fast_path_equals_the_exact_loop_on_random_and_computed_values() {
        let mut values: Vec<f64> = patterns(200_000).map(f64::from_bits).collect();
        // values as a trace holds them: sums and products of short decimals, integration steps
        let mut p = 0.0f64;
        for k in 0..100_000 {
            p += 0.001 * (k % 97) as f64 * 1.7;
            values.push(p);
            values.push(p * 1e-6);
            values.push(k as f64 * 0.1);
            values.push((k as f64).sqrt());
        }
        for k in -1074..1024 {
            values.push(2f64.powi(k));
            values.push(2f64.powi(k) * 3.0);
        }
        for v in values {
            assert_eq!(lreal(v), reference_lreal(v), "{:#x}", v.to_bits());
        }
        for b in patterns(200_000) {
            let v = f32::from_bits(b as u32);
            assert_eq!(real(v), reference_real(v), "{:#x}", v.to_bits());
        }
    }

    #[test]
    fn a_text_run_ends_at_the_first_marker_and_nowhere_else() {
        let text: Vec<u8> = (0u8..=255).filter(|b| !(F64..=SAME).contains(b)).collect();
        for len in 0..40 {
            let run: Vec<u8> = text
                .iter()
                .cycle()
                .skip(len * 7)
                .take(len)
                .copied()
                .collect();
            assert_eq!(text_run(&run), len);
            for m in F64..=SAME {
                for at in 0..=len {
                    let mut v = run.clone();
                    v.insert(at, m);
                    v.push(F64);
                    assert_eq!(text_run(&v), at, "marker {m} at {at} of {len}");
                }
            }
        }
    }

    #[test]
    fn a_raw_trace_becomes_the_csv_cut_anywhere() {
        let mut raw = b"cycle,time_ms,a,b,s\x04".to_vec();
        let mut want = b"cycle,time_ms,a,b,s\n".to_vec();
        let mut last_f32 = 0;
        for k in 0..50u32 {
            let a = f64::from(k / 10) * 0.1;
            let b = k as f32 / 3.0;
            raw.extend_from_slice(format!("{k},{k},").as_bytes());
            if k % 10 == 0 {
                raw.push(F64);
                raw.extend_from_slice(&a.to_ne_bytes());
            } else {
                raw.push(SAME);
            }
            raw.push(b',');
            last_f32 = raw.len();
            raw.push(F32);
            raw.extend_from_slice(&b.to_ne_bytes());
            raw.extend_from_slice(b",\"x");
            raw.extend_from_slice(&[ESC, F64, ESC, EOR, ESC, SAME, b'\n']);
            raw.extend_from_slice(b"\"");
            raw.push(EOR);
            let mut row = format!("{k},{k},").into_bytes();
            format_lreal(a, &mut row);
            row.push(b',');
            format_real(b, &mut row);
            row.extend_from_slice(b",\"x\x01\x04\x05\n\"\n");
            want.extend_from_slice(&row);
        }
        assert_eq!(convert_bytes(&raw).unwrap(), want);
        // read one byte at a time: every item cut at every place
        struct OneByte<'a>(&'a [u8]);
        impl Read for OneByte<'_> {
            fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
                match self.0.split_first() {
                    Some((&b, rest)) if !buf.is_empty() => {
                        buf[0] = b;
                        self.0 = rest;
                        Ok(1)
                    }
                    _ => Ok(0),
                }
            }
        }
        let mut out = Vec::new();
        convert(OneByte(&raw), &mut out).unwrap();
        assert_eq!(out, want);
        // a stream cut inside a value is an error, not a short trace
        assert!(convert_bytes(&raw[..last_f32 + 3]).is_err());
    }
}
