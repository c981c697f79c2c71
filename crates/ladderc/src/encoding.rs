//! How a source file's bytes become text.
//!
//! Input: the bytes of one file (IL, ST or PLCopen XML). Output: the text, the encoding it was read in
//! and whether that was a guess ([`Decoded`]), or why it cannot be read ([`Undecodable`]).
//! Rules, in order: a byte-order mark decides (UTF-8; UTF-16 little or big endian); an XML declaration's
//! `encoding` is honoured (UTF-8; ISO-8859-1, Latin-1, Windows-1252 and US-ASCII are read as
//! Windows-1252, as browsers do: TIA Portal declares ISO-8859-1 and writes `€` as 0x80); any other
//! declared encoding is readable only when the file is plain ASCII. A file that is valid UTF-8 is UTF-8.
//! Otherwise (CODESYS, TwinCAT and TIA Portal save Windows-1252 text: umlauts in comments and strings) it
//! is read as Windows-1252, and [`Decoded::fallback_at`] gives the first byte that is not UTF-8 so that the
//! caller can say so (note W0305). Windows-1252 maps every byte to a character (its five unused bytes to
//! the C1 controls of the same value), so that fallback never fails and each character is one byte of the
//! file.

use diagnostics::FileEncoding;

/// A file's text and how it was read.
#[derive(Debug)]
pub struct Decoded {
    /// The text, without a byte-order mark.
    pub text: String,
    /// The encoding of the file's bytes.
    pub encoding: FileEncoding,
    /// Bytes of the file before `text` (a byte-order mark).
    pub byte_base: u32,
    /// The text was not valid UTF-8 and declared no other encoding: read as Windows-1252. The byte
    /// offset in `text` of the character decoded from the first byte that is not UTF-8.
    pub fallback_at: Option<usize>,
}

/// Why a file cannot be read as text: a one-line message and a hint.
#[derive(Debug, PartialEq)]
pub struct Undecodable {
    /// What is wrong (without the file name).
    pub message: String,
    /// What to do.
    pub hint: String,
}

/// The characters of Windows-1252 bytes 0x80-0x9F (its five unused bytes as the C1 control of the same
/// value, as the WHATWG encoding standard does).
const CP1252_HIGH: [char; 32] = [
    '\u{20AC}', '\u{0081}', '\u{201A}', '\u{0192}', '\u{201E}', '\u{2026}', '\u{2020}', '\u{2021}',
    '\u{02C6}', '\u{2030}', '\u{0160}', '\u{2039}', '\u{0152}', '\u{008D}', '\u{017D}', '\u{008F}',
    '\u{0090}', '\u{2018}', '\u{2019}', '\u{201C}', '\u{201D}', '\u{2022}', '\u{2013}', '\u{2014}',
    '\u{02DC}', '\u{2122}', '\u{0161}', '\u{203A}', '\u{0153}', '\u{009D}', '\u{017E}', '\u{0178}',
];

/// The character of one Windows-1252 byte.
pub fn cp1252_char(b: u8) -> char {
    match b {
        0x80..=0x9F => CP1252_HIGH[usize::from(b - 0x80)],
        _ => char::from(b),
    }
}

/// Windows-1252 bytes as text.
pub fn decode_cp1252(bytes: &[u8]) -> String {
    let mut s = String::with_capacity(bytes.len() + bytes.len() / 8);
    s.extend(bytes.iter().map(|&b| cp1252_char(b)));
    s
}

/// The text of a file's bytes (see the module header for the rules).
pub fn decode(bytes: Vec<u8>) -> Result<Decoded, Undecodable> {
    if let Some(rest) = bytes.strip_prefix(&[0xFF, 0xFE]) {
        return utf16(rest, u16::from_le_bytes, "little");
    }
    if let Some(rest) = bytes.strip_prefix(&[0xFE, 0xFF]) {
        return utf16(rest, u16::from_be_bytes, "big");
    }
    let bom = bytes.starts_with(&[0xEF, 0xBB, 0xBF]);
    let declared = if bom { None } else { declared_encoding(&bytes) };
    if let Some(label) = declared {
        match label.to_ascii_lowercase().as_str() {
            // a file without a UTF-16 byte-order mark whose declaration starts in 8-bit characters is
            // not UTF-16, whatever it says (an editor converted it and kept the declaration)
            "utf-8" | "utf8" | "utf-16" | "utf16" | "utf-16le" | "utf-16be" => {}
            "iso-8859-1" | "iso8859-1" | "iso_8859-1" | "latin1" | "latin-1" | "l1"
            | "windows-1252" | "cp1252" | "x-cp1252" | "us-ascii" | "ascii" => {
                return Ok(Decoded {
                    text: decode_cp1252(&bytes),
                    encoding: FileEncoding::SingleByte,
                    byte_base: 0,
                    fallback_at: None,
                });
            }
            _ if bytes.is_ascii() => {}
            _ => {
                return Err(Undecodable {
                    message: format!(
                        "declares encoding `{label}`, which ladderc does not read (it reads UTF-8, \
                         UTF-16, ISO-8859-1 and Windows-1252)"
                    ),
                    hint: "save the file as UTF-8 and declare `encoding=\"UTF-8\"`".into(),
                });
            }
        }
    }
    match String::from_utf8(bytes) {
        Ok(mut text) => {
            let byte_base = if bom {
                text.drain(..3);
                3
            } else {
                0
            };
            Ok(Decoded {
                text,
                encoding: FileEncoding::Utf8,
                byte_base,
                fallback_at: None,
            })
        }
        Err(e) => {
            let bytes = e.into_bytes();
            let skip = if bom { 3 } else { 0 };
            let text = decode_cp1252(&bytes[skip..]);
            // the first byte that is not UTF-8 is at `valid_up_to` of the file; its character's offset
            let first = std::str::from_utf8(&bytes[skip..])
                .err()
                .map_or(0, |e| e.valid_up_to());
            let at = bytes[skip..skip + first]
                .iter()
                .map(|&b| cp1252_char(b).len_utf8())
                .sum();
            Ok(Decoded {
                text,
                encoding: FileEncoding::SingleByte,
                byte_base: skip as u32,
                fallback_at: Some(at),
            })
        }
    }
}

/// UTF-16 text (after its byte-order mark) with `unit` reading one code unit of the given byte order.
fn utf16(bytes: &[u8], unit: fn([u8; 2]) -> u16, order: &str) -> Result<Decoded, Undecodable> {
    let bad = || Undecodable {
        message: format!(
            "starts with a UTF-16 ({order}-endian) byte-order mark but is not valid UTF-16"
        ),
        hint: "save the file as UTF-8".into(),
    };
    if !bytes.len().is_multiple_of(2) {
        return Err(bad());
    }
    let units = bytes.chunks_exact(2).map(|c| unit([c[0], c[1]]));
    let text: Result<String, _> = char::decode_utf16(units).collect();
    Ok(Decoded {
        text: text.map_err(|_| bad())?,
        encoding: FileEncoding::Utf16,
        byte_base: 2,
        fallback_at: None,
    })
}

/// The `encoding` of an XML declaration (`<?xml version="1.0" encoding="ISO-8859-1"?>`) at the start of
/// the bytes, if there is one.
fn declared_encoding(bytes: &[u8]) -> Option<&str> {
    let rest = bytes.strip_prefix(b"<?xml")?;
    if !rest.first().is_some_and(u8::is_ascii_whitespace) {
        return None;
    }
    // the declaration is short: look no further than its `?>`, and at most 256 bytes
    let end = rest.iter().take(256).position(|&b| b == b'>').unwrap_or(0);
    let decl = std::str::from_utf8(&rest[..end]).ok()?;
    let at = decl.find("encoding")?;
    let after = decl[at + "encoding".len()..]
        .trim_start()
        .strip_prefix('=')?;
    let after = after.trim_start();
    let quote = after.chars().next().filter(|c| *c == '"' || *c == '\'')?;
    let value = &after[1..];
    let close = value.find(quote)?;
    Some(&value[..close])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf8_text_is_read_as_it_is_and_a_bom_is_dropped() {
        let d = decode("a := 'ä';".as_bytes().to_vec()).unwrap();
        assert_eq!(
            (d.text.as_str(), d.encoding, d.byte_base),
            ("a := 'ä';", FileEncoding::Utf8, 0)
        );
        assert_eq!(d.fallback_at, None);
        let d = decode(b"\xEF\xBB\xBFx".to_vec()).unwrap();
        assert_eq!((d.text.as_str(), d.byte_base), ("x", 3));
    }

    #[test]
    fn text_that_is_not_utf8_is_windows_1252_and_says_where_it_stopped_being_utf8() {
        let d = decode(b"(* \xC3\xA4 *)\n(* Gr\xFC\xDFe \x80 *)".to_vec()).unwrap();
        assert_eq!(d.text, "(* Ã¤ *)\n(* Grüße € *)");
        assert_eq!(d.encoding, FileEncoding::SingleByte);
        assert_eq!(&d.text[d.fallback_at.unwrap()..], "üße € *)");
    }

    #[test]
    fn every_byte_has_a_character() {
        let all: Vec<u8> = (0..=255).collect();
        let text = decode_cp1252(&all);
        assert_eq!(text.chars().count(), 256);
        assert_eq!(cp1252_char(0x80), '€');
        assert_eq!(cp1252_char(0x81), '\u{81}');
        assert_eq!(cp1252_char(0xC4), 'Ä');
    }

    #[test]
    fn the_xml_declaration_is_honoured() {
        let latin = b"<?xml version=\"1.0\" encoding='ISO-8859-1'?>\n<a>\xC4</a>".to_vec();
        let d = decode(latin).unwrap();
        assert!(d.text.ends_with("<a>Ä</a>"));
        assert_eq!(
            (d.encoding, d.fallback_at),
            (FileEncoding::SingleByte, None)
        );
        // declared Latin-1 wins over bytes that happen to be UTF-8
        let d =
            decode(b"<?xml version=\"1.0\" encoding=\"windows-1252\"?><a>\xC3\xA4</a>".to_vec());
        assert!(d.unwrap().text.ends_with("<a>Ã¤</a>"));
        let d = decode(b"<?xml version=\"1.0\" encoding=\"UTF-8\"?><a>\xC3\xA4</a>".to_vec());
        assert!(d.unwrap().text.ends_with("<a>ä</a>"));
        // an encoding ladderc does not read: fine when the file is ASCII, an error otherwise
        assert!(decode(b"<?xml version=\"1.0\" encoding=\"Shift_JIS\"?><a/>".to_vec()).is_ok());
        let e = decode(b"<?xml version=\"1.0\" encoding=\"Shift_JIS\"?><a>\x82\xA0</a>".to_vec());
        assert!(e.unwrap_err().message.contains("`Shift_JIS`"));
    }

    #[test]
    fn utf16_with_a_byte_order_mark() {
        let mut le = vec![0xFF, 0xFE];
        let mut be = vec![0xFE, 0xFF];
        for u in "x := 'Ä';".encode_utf16() {
            le.extend(u.to_le_bytes());
            be.extend(u.to_be_bytes());
        }
        for b in [le, be] {
            let d = decode(b).unwrap();
            assert_eq!(
                (d.text.as_str(), d.encoding, d.byte_base),
                ("x := 'Ä';", FileEncoding::Utf16, 2)
            );
        }
        assert!(decode(vec![0xFF, 0xFE, 0x00, 0xD8]).is_err());
        assert!(decode(vec![0xFF, 0xFE, 0x41]).is_err());
    }
}
