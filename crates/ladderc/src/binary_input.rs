//! Input files that are not text: one error saying what the file is, before its bytes are decoded.
//!
//! A CODESYS V3 project (`.project`) is a binary archive (it starts with the 16 bytes of a fixed
//! GUID, `23 89 ED 33 14 BD 93 4B 8D A9 5D 91 08 C5 32 35`; older ones and `.projectarchive` files are
//! ZIP archives), and it is what CODESYS repositories hold. Decoded as Windows-1252 its bytes were
//! read as ST or IL, and the first error was a false one ("this file is Siemens SCL"). A file is
//! taken as binary when it holds a NUL byte in its first 8,000 bytes (the test git applies,
//! `buffer_is_binary`; no IL, ST or XML text holds NUL), unless it starts with a UTF-16 byte-order
//! mark (UTF-16 text has NUL bytes; [`crate::encoding`] reads it).
//!
//! Input: the path as given and the file's bytes. Output: E1093 (an error, exit 1 like E1049's
//! encrypted TwinCAT file: the file was read, its content is no program) with what the file is and
//! how to get text from it, or `None` for text. Invariants: looks at the first 8,000 bytes only;
//! never panics.

use diagnostics::{code, Diagnostic};
use std::path::Path;

/// The first bytes of a CODESYS V3 `.project` file.
const CODESYS_PROJECT_MAGIC: [u8; 16] = [
    0x23, 0x89, 0xED, 0x33, 0x14, 0xBD, 0x93, 0x4B, 0x8D, 0xA9, 0x5D, 0x91, 0x08, 0xC5, 0x32, 0x35,
];

/// The first bytes of a ZIP archive (a local file header).
const ZIP_MAGIC: [u8; 4] = *b"PK\x03\x04";

/// How many bytes are searched for a NUL (git's `FIRST_FEW_BYTES`).
const FIRST_FEW_BYTES: usize = 8000;

/// E1093 (without a location: the caller places it at the file's start) when `bytes` are not text.
pub fn not_text(path: &Path, bytes: &[u8]) -> Option<Diagnostic> {
    if bytes.starts_with(&[0xFF, 0xFE]) || bytes.starts_with(&[0xFE, 0xFF]) {
        return None;
    }
    let head = &bytes[..bytes.len().min(FIRST_FEW_BYTES)];
    let codesys_magic = bytes.starts_with(&CODESYS_PROJECT_MAGIC);
    if !codesys_magic && !head.contains(&0) {
        return None;
    }
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let zip = bytes.starts_with(&ZIP_MAGIC);
    let codesys = codesys_magic || matches!(ext.as_deref(), Some("project" | "projectarchive"));
    let export_hint =
        "open the project in CODESYS and export it as PLCopen XML (Project > Export PLCopenXML), \
                       then give ladderc that .xml file";
    let (message, label, hint) = if codesys {
        (
            "a binary CODESYS V3 project, not a source file: ladderc cannot read CODESYS's project archive",
            if codesys_magic {
                "the bytes of a CODESYS V3 .project"
            } else if zip {
                "a ZIP archive"
            } else {
                "binary content (NUL bytes)"
            },
            export_hint,
        )
    } else if zip {
        (
            "a ZIP archive, not a source file: ladderc reads IL, ST and PLCopen XML text",
            "a ZIP archive",
            "unpack it and give ladderc the source files (.st, .il, .xml) or the project's folder",
        )
    } else {
        (
            "not a text file (it holds NUL bytes): ladderc reads IL, ST and PLCopen XML text",
            "binary content",
            "give the source files (.st, .il, .xml); a text saved as UTF-16 without a byte-order mark: save it as UTF-8",
        )
    };
    Some(
        Diagnostic::error(code::E1093, message)
            .with_primary_label(label)
            .with_hint(hint),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_text() {
        assert!(not_text(Path::new("a.st"), b"PROGRAM p END_PROGRAM").is_none());
        assert!(not_text(Path::new("a.st"), &[0xFF, 0xFE, b'P', 0]).is_none());
        assert!(not_text(Path::new("a.st"), &[]).is_none());
    }

    #[test]
    fn a_codesys_project_is_named() {
        let mut b = CODESYS_PROJECT_MAGIC.to_vec();
        b.extend_from_slice(b"#Jy more bytes");
        let d = not_text(Path::new("x.bin"), &b).expect("binary");
        assert!(d.message.contains("CODESYS V3 project"), "{}", d.message);
        let d = not_text(Path::new("x.project"), b"PK\x03\x04\x14\0\0\0").expect("binary");
        assert!(d.message.contains("CODESYS V3 project"), "{}", d.message);
    }

    #[test]
    fn other_binaries_are_not_text() {
        let d = not_text(Path::new("x.st"), b"ab\0cd").expect("binary");
        assert!(d.message.contains("not a text file"), "{}", d.message);
        let d = not_text(Path::new("x.zip"), b"PK\x03\x04\x14\0").expect("binary");
        assert!(d.message.contains("ZIP archive"), "{}", d.message);
    }
}
