//! The binary image downloaded to the drive: a versioned header, a CRC-32, the two pools.
//!
//! Input: a [`Program`] (encode) or bytes (decode). Output: bytes, or a program equal to the encoded one.
//! Layout (all integers little-endian; documented with offsets in the crate README):
//! header `"LDSI"`, version u16 (= 1), header size u16 (= 16), payload length u32, CRC-32 (IEEE) of the
//! payload u32; payload: 16 params i32, 50 MD initial values i32, velocity/acceleration/deceleration/
//! jog velocity i32, events per cycle u16, motion count u16, event count u16, reserved u16 (0), the Motion
//! pool (first event u16, event count u16 each) and the Event pool (condition count u8, action count u8,
//! then 23-byte conditions and 13-byte actions).
//! Invariants: `decode(encode(p)) == p` for every valid program; decode never panics and returns a program
//! only if it passes [`Program::validate`].

use crate::program::*;
use diagnostics::{code, Code, Diagnostic};
use std::fmt;

/// The four bytes an image starts with (`LDSI`); `run` and `debug` recognise an image by them.
pub const MAGIC: [u8; 4] = *b"LDSI";
/// Layout version written into the header; decode refuses any other (E6021).
pub const VERSION: u16 = 1;
/// Bytes of the header: magic, version, header size, payload length, CRC-32.
pub const HEADER_LEN: usize = 16;
/// Bytes of one encoded value (`a` source u8 + arg i32, op u8, `b` source u8 + arg i32).
pub const VALUE_LEN: usize = 11;
/// Bytes of one encoded condition: lhs value, comparison u8, rhs value.
pub const CONDITION_LEN: usize = 2 * VALUE_LEN + 1;
/// Bytes of one encoded action: kind u8, index u8, value.
pub const ACTION_LEN: usize = 2 + VALUE_LEN;
/// Bytes of the fixed part of the payload (params, init, settings, counts).
pub const FIXED_PAYLOAD_LEN: usize = 16 * 4 + 50 * 4 + 4 * 4 + 8;

#[derive(Debug, Clone, PartialEq, Eq)]
/// Why bytes are not a loadable image (diagnostic codes E6020..E6023).
pub enum ImageError {
    /// Shorter than a header or wrong magic bytes.
    BadMagic,
    /// The header's layout version (this one is not [`VERSION`]).
    UnsupportedVersion(u16),
    /// The payload length field disagrees with the file, or the CRC does not match.
    Corrupt(String),
    /// Valid header and CRC but content that breaks the layout or the pool invariants.
    Malformed(String),
}

impl ImageError {
    /// The diagnostic code: E6020 bad magic, E6021 version, E6022 corrupt, E6023 malformed.
    pub fn code(&self) -> Code {
        match self {
            ImageError::BadMagic => code::E6020,
            ImageError::UnsupportedVersion(_) => code::E6021,
            ImageError::Corrupt(_) => code::E6022,
            ImageError::Malformed(_) => code::E6023,
        }
    }
    /// The error as an error diagnostic with its code and message (no source location).
    pub fn to_diagnostic(&self) -> Diagnostic {
        Diagnostic::error(self.code(), self.to_string())
    }
}

impl fmt::Display for ImageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ImageError::BadMagic => write!(f, "not a drive script image (no `LDSI` header)"),
            ImageError::UnsupportedVersion(v) => {
                write!(f, "drive script image version {v} is not supported (this tool reads version {VERSION})")
            }
            ImageError::Corrupt(m) => write!(f, "drive script image is corrupt: {m}"),
            ImageError::Malformed(m) => write!(f, "malformed drive script image: {m}"),
        }
    }
}

impl std::error::Error for ImageError {}

/// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320, init and final XOR 0xFFFFFFFF), as used by zlib.
pub fn crc32(data: &[u8]) -> u32 {
    const TABLE: [u32; 256] = {
        let mut t = [0u32; 256];
        let mut i = 0;
        while i < 256 {
            let mut c = i as u32;
            let mut k = 0;
            while k < 8 {
                c = if c & 1 != 0 {
                    0xEDB8_8320 ^ (c >> 1)
                } else {
                    c >> 1
                };
                k += 1;
            }
            t[i] = c;
            i += 1;
        }
        t
    };
    let mut crc = 0xFFFF_FFFFu32;
    for &b in data {
        crc = TABLE[((crc ^ b as u32) & 0xFF) as usize] ^ (crc >> 8);
    }
    crc ^ 0xFFFF_FFFF
}

fn put_value(out: &mut Vec<u8>, v: &Value) {
    out.push(v.a.source as u8);
    out.extend_from_slice(&v.a.arg.to_le_bytes());
    out.push(v.op as u8);
    out.push(v.b.source as u8);
    out.extend_from_slice(&v.b.arg.to_le_bytes());
}

/// Encodes a program (assumed valid: the compiler's output always is).
pub fn encode(p: &Program) -> Vec<u8> {
    let mut pl = Vec::with_capacity(FIXED_PAYLOAD_LEN + p.motions.len() * 4 + p.events.len() * 64);
    for v in p.params.iter().chain(p.init.iter()) {
        pl.extend_from_slice(&v.to_le_bytes());
    }
    let s = &p.settings;
    for v in [s.velocity, s.acceleration, s.deceleration, s.jog_velocity] {
        pl.extend_from_slice(&v.to_le_bytes());
    }
    for v in [
        s.events_per_cycle,
        p.motions.len() as u16,
        p.events.len() as u16,
        0,
    ] {
        pl.extend_from_slice(&v.to_le_bytes());
    }
    for m in &p.motions {
        pl.extend_from_slice(&m.first_event.to_le_bytes());
        pl.extend_from_slice(&m.event_count.to_le_bytes());
    }
    for e in &p.events {
        pl.push(e.cond_count);
        pl.push(e.act_count);
        for c in e.conditions() {
            put_value(&mut pl, &c.lhs);
            pl.push(c.cmp as u8);
            put_value(&mut pl, &c.rhs);
        }
        for a in e.actions() {
            pl.push(a.kind as u8);
            pl.push(a.index);
            put_value(&mut pl, &a.value);
        }
    }
    let mut out = Vec::with_capacity(HEADER_LEN + pl.len());
    out.extend_from_slice(&MAGIC);
    out.extend_from_slice(&VERSION.to_le_bytes());
    out.extend_from_slice(&(HEADER_LEN as u16).to_le_bytes());
    out.extend_from_slice(&(pl.len() as u32).to_le_bytes());
    out.extend_from_slice(&crc32(&pl).to_le_bytes());
    out.extend_from_slice(&pl);
    out
}

struct Reader<'a> {
    data: &'a [u8],
    pos: usize,
}

impl Reader<'_> {
    fn bytes(&mut self, n: usize) -> Result<&[u8], ImageError> {
        let end = self.pos.checked_add(n).filter(|e| *e <= self.data.len());
        let Some(end) = end else {
            return Err(ImageError::Malformed(format!(
                "payload ends at byte {} but {n} more bytes are needed",
                self.data.len()
            )));
        };
        let s = &self.data[self.pos..end];
        self.pos = end;
        Ok(s)
    }
    fn u8(&mut self) -> Result<u8, ImageError> {
        Ok(self.bytes(1)?[0])
    }
    fn u16(&mut self) -> Result<u16, ImageError> {
        let b = self.bytes(2)?;
        Ok(u16::from_le_bytes([b[0], b[1]]))
    }
    fn i32(&mut self) -> Result<i32, ImageError> {
        let b = self.bytes(4)?;
        Ok(i32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    }
    fn operand(&mut self) -> Result<Operand, ImageError> {
        let s = self.u8()?;
        let source = Source::from_u8(s)
            .ok_or_else(|| ImageError::Malformed(format!("unknown operand source {s}")))?;
        Ok(Operand {
            source,
            arg: self.i32()?,
        })
    }
    fn value(&mut self) -> Result<Value, ImageError> {
        let a = self.operand()?;
        let o = self.u8()?;
        let op = ArithOp::from_u8(o)
            .ok_or_else(|| ImageError::Malformed(format!("unknown operator {o}")))?;
        let b = self.operand()?;
        Ok(Value { a, op, b })
    }
}

/// Decodes and validates an image.
pub fn decode(bytes: &[u8]) -> Result<Program, ImageError> {
    if bytes.len() < HEADER_LEN || bytes[..4] != MAGIC {
        return Err(ImageError::BadMagic);
    }
    let version = u16::from_le_bytes([bytes[4], bytes[5]]);
    if version != VERSION {
        return Err(ImageError::UnsupportedVersion(version));
    }
    let header_len = u16::from_le_bytes([bytes[6], bytes[7]]) as usize;
    if header_len != HEADER_LEN {
        return Err(ImageError::Corrupt(format!(
            "header size {header_len} instead of {HEADER_LEN}"
        )));
    }
    let len = u32::from_le_bytes([bytes[8], bytes[9], bytes[10], bytes[11]]) as usize;
    let stored = u32::from_le_bytes([bytes[12], bytes[13], bytes[14], bytes[15]]);
    let payload = &bytes[HEADER_LEN..];
    if payload.len() != len {
        return Err(ImageError::Corrupt(format!(
            "the header announces {len} payload bytes but the file holds {}",
            payload.len()
        )));
    }
    let computed = crc32(payload);
    if computed != stored {
        return Err(ImageError::Corrupt(format!(
            "CRC-32 mismatch: header 0x{stored:08X}, payload 0x{computed:08X}"
        )));
    }
    let mut r = Reader {
        data: payload,
        pos: 0,
    };
    let mut p = Program::default();
    for v in p.params.iter_mut() {
        *v = r.i32()?;
    }
    for v in p.init.iter_mut() {
        *v = r.i32()?;
    }
    p.settings.velocity = r.i32()?;
    p.settings.acceleration = r.i32()?;
    p.settings.deceleration = r.i32()?;
    p.settings.jog_velocity = r.i32()?;
    p.settings.events_per_cycle = r.u16()?;
    let motions = r.u16()? as usize;
    let events = r.u16()? as usize;
    if r.u16()? != 0 {
        return Err(ImageError::Malformed("reserved field is not 0".into()));
    }
    if motions > crate::limits::MAX_MOTIONS || events > crate::limits::MAX_EVENTS {
        return Err(ImageError::Malformed(format!(
            "{motions} Motions / {events} Events exceed the pool capacities"
        )));
    }
    for _ in 0..motions {
        p.motions.push(Motion {
            first_event: r.u16()?,
            event_count: r.u16()?,
        });
    }
    for _ in 0..events {
        let mut e = Event {
            cond_count: r.u8()?,
            act_count: r.u8()?,
            ..Default::default()
        };
        if e.cond_count as usize > crate::limits::MAX_CONDITIONS
            || e.act_count as usize > crate::limits::MAX_ACTIONS
        {
            return Err(ImageError::Malformed(format!(
                "an Event with {} conditions and {} actions exceeds the Event capacity",
                e.cond_count, e.act_count
            )));
        }
        for i in 0..e.cond_count as usize {
            let lhs = r.value()?;
            let c = r.u8()?;
            let cmp = Compare::from_u8(c)
                .ok_or_else(|| ImageError::Malformed(format!("unknown comparison {c}")))?;
            let rhs = r.value()?;
            e.conditions[i] = Condition { lhs, cmp, rhs };
        }
        for i in 0..e.act_count as usize {
            let k = r.u8()?;
            let kind = ActionKind::from_u8(k)
                .ok_or_else(|| ImageError::Malformed(format!("unknown action {k}")))?;
            let index = r.u8()?;
            let value = r.value()?;
            e.actions[i] = Action { kind, index, value };
        }
        p.events.push(e);
    }
    if r.pos != payload.len() {
        return Err(ImageError::Malformed(format!(
            "{} trailing bytes after the Event pool",
            payload.len() - r.pos
        )));
    }
    p.validate().map_err(ImageError::Malformed)?;
    Ok(p)
}

#[cfg(test)]
mod tests {
    use super::crc32;

    #[test]
    fn crc32_matches_the_standard_check_value() {
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
        assert_eq!(crc32(b""), 0);
    }
}
