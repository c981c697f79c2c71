//! The files a compilation reads, with line tables for 1-based line/column lookup.
//!
//! Input: the texts of the files. Output: 1-based line/column positions of byte offsets, and back.
//! Invariants: a file's line table is built on its first use (a build without diagnostics never
//! needs it: 800 KB for 100,000 IL lines, crates/ladderc/BENCHMARKS.md, Round 17) from the text as
//! it is then; the text is not meant to change after the file is added.

use crate::span::FileId;

/// One file: its name (as diagnostics show it), its text and its line table.
#[derive(Debug, Clone)]
pub struct SourceFile {
    /// The name diagnostics show (a path as given, `<stdin>`, `<PLCopen blocks>`).
    pub name: String,
    /// The text.
    pub text: String,
    /// Bytes of the file on disk before `text`: 3 when a UTF-8 byte-order mark was dropped
    /// ([`SourceMap::add_file`]), else 0. Spans count in `text`; JSON's `byte_start`/`byte_end` add it, so
    /// that they are offsets into the file.
    pub byte_base: u32,
    /// How the file's bytes were decoded into `text` ([`SourceMap::add_decoded`]); JSON's byte offsets
    /// count in this encoding.
    pub encoding: FileEncoding,
    /// [`line_starts`] of `text`, built on first use.
    line_starts: std::sync::OnceLock<Vec<usize>>,
}

/// The encoding a file was read in: how an offset into the decoded text maps to one into the file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FileEncoding {
    /// UTF-8 (the text's bytes are the file's; offsets above the text pass through).
    #[default]
    Utf8,
    /// One byte per character (ISO-8859-1, Windows-1252).
    SingleByte,
    /// UTF-16 (two bytes per code unit).
    Utf16,
}

impl SourceFile {
    /// A file (its line table is built when first needed).
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> Self {
        SourceFile {
            name: name.into(),
            text: text.into(),
            byte_base: 0,
            encoding: FileEncoding::Utf8,
            line_starts: std::sync::OnceLock::new(),
        }
    }
    /// The offset in the file on disk of byte offset `offset` of the text (clamped to the text): the
    /// dropped byte-order mark plus the offset counted in the file's [`FileEncoding`].
    pub fn file_offset(&self, offset: u32) -> u32 {
        if self.encoding == FileEncoding::Utf8 {
            return offset.saturating_add(self.byte_base);
        }
        let offset = self.floor_char_boundary(offset as usize);
        let counted = match self.encoding {
            FileEncoding::Utf8 => offset,
            FileEncoding::SingleByte => self.text[..offset].chars().count(),
            FileEncoding::Utf16 => self.text[..offset].encode_utf16().count() * 2,
        };
        (counted as u32).saturating_add(self.byte_base)
    }
    /// 1-based line and 1-based column (in characters) of byte offset `offset` (clamped to the text).
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let mut offset = offset.min(self.text.len());
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        let starts = self.line_starts();
        let line = match starts.binary_search(&offset) {
            Ok(l) => l,
            Err(l) => l - 1,
        };
        let col = self.text[starts[line]..offset].chars().count();
        (line + 1, col + 1)
    }
    /// Byte offset of a 1-based line and column (column in characters); clamps to the text.
    pub fn offset_of(&self, line: usize, col: usize) -> usize {
        let Some(&start) = self.line_starts().get(line.saturating_sub(1)) else {
            return self.text.len();
        };
        let rest = &self.text[start..];
        rest.char_indices()
            .nth(col.saturating_sub(1))
            .map(|(i, _)| start + i)
            .unwrap_or(self.text.len())
    }
    /// The largest character boundary at or before `offset` (clamped to the text).
    pub fn floor_char_boundary(&self, offset: usize) -> usize {
        let mut offset = offset.min(self.text.len());
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        offset
    }
    /// The byte offset of each line's start.
    pub fn line_starts(&self) -> &[usize] {
        self.line_starts.get_or_init(|| line_starts(&self.text))
    }
}

/// The byte offset of each line's start in `text`: `\n`, `\r\n` and a lone `\r` (old Mac OS) each end
/// one line, as in the language server protocol. Every diagnostic format and the language server count
/// lines with this one table.
pub fn line_starts(text: &str) -> Vec<usize> {
    let b = text.as_bytes();
    // Room for lines of 8 bytes or more (IL averages 11, XML 40), so that the table is not regrown
    // (each regrowth copied it into fresh pages: 8 MB more for a 1,000,000-line file); the room not
    // used is never touched and is given back below (a large table shrinks where it is).
    let mut starts = Vec::with_capacity(1 + b.len() / 8);
    starts.push(0);
    // memchr finds the line ends a word at a time (a byte loop cost about 10 instructions per byte:
    // 6 % of `ladderc build` on 2,000 rungs of XML).
    for i in memchr::memchr2_iter(b'\n', b'\r', b) {
        if b[i] == b'\n' || b.get(i + 1) != Some(&b'\n') {
            starts.push(i + 1);
        }
    }
    starts.shrink_to_fit();
    starts
}

/// All files of one compilation; a [`FileId`] indexes into it.
#[derive(Debug, Default, Clone)]
pub struct SourceMap {
    files: Vec<SourceFile>,
}

impl SourceMap {
    /// An empty map.
    pub fn new() -> Self {
        Self::default()
    }
    /// Adds a file; its id.
    pub fn add(&mut self, name: impl Into<String>, text: impl Into<String>) -> FileId {
        self.files.push(SourceFile::new(name, text));
        FileId(self.files.len() as u32 - 1)
    }
    /// Adds a file as read from disk: a leading UTF-8 byte-order mark is dropped from the text (positions
    /// count from the character after it) and kept in [`SourceFile::byte_base`]; its id.
    pub fn add_file(&mut self, name: impl Into<String>, text: &str) -> FileId {
        let (text, base) = match text.strip_prefix('\u{feff}') {
            Some(rest) => (rest, '\u{feff}'.len_utf8() as u32),
            None => (text, 0),
        };
        let mut f = SourceFile::new(name, text);
        f.byte_base = base;
        self.files.push(f);
        FileId(self.files.len() as u32 - 1)
    }
    /// [`SourceMap::add_file`] for a text the caller owns: it is moved into the map, not copied (a
    /// byte-order mark is removed in place).
    pub fn add_file_owned(&mut self, name: impl Into<String>, mut text: String) -> FileId {
        let bom = '\u{feff}'.len_utf8();
        let base = if text.starts_with('\u{feff}') {
            text.drain(..bom);
            bom as u32
        } else {
            0
        };
        let mut f = SourceFile::new(name, text);
        f.byte_base = base;
        self.files.push(f);
        FileId(self.files.len() as u32 - 1)
    }
    /// Adds a file decoded from `encoding` (without its byte-order mark, which took `byte_base` bytes of
    /// the file); its id. JSON's byte offsets are then offsets into the file's bytes.
    pub fn add_decoded(
        &mut self,
        name: impl Into<String>,
        text: String,
        encoding: FileEncoding,
        byte_base: u32,
    ) -> FileId {
        let mut f = SourceFile::new(name, text);
        f.byte_base = byte_base;
        f.encoding = encoding;
        self.files.push(f);
        FileId(self.files.len() as u32 - 1)
    }
    /// The file `id` (which this map gave out).
    pub fn get(&self, id: FileId) -> &SourceFile {
        &self.files[id.0 as usize]
    }
    /// Every file with its id, in the order they were added.
    pub fn files(&self) -> impl Iterator<Item = (FileId, &SourceFile)> {
        self.files
            .iter()
            .enumerate()
            .map(|(i, f)| (FileId(i as u32), f))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Offsets into a decoded file count its bytes: one per character (Windows-1252), two per UTF-16
    /// code unit plus the byte-order mark; UTF-8 adds the dropped mark only.
    #[test]
    fn file_offsets_count_the_bytes_of_the_file_as_encoded() {
        let text = "ä€x\n𝄞y".to_string();
        let y = text.find('y').unwrap() as u32;
        let mut m = SourceMap::new();
        let single = m.add_decoded("a", text.clone(), FileEncoding::SingleByte, 0);
        let wide = m.add_decoded("b", text.clone(), FileEncoding::Utf16, 2);
        let utf8 = m.add_file("c", &format!("\u{feff}{text}"));
        assert_eq!(m.get(single).file_offset(y), 5);
        assert_eq!(m.get(wide).file_offset(y), 2 + 2 * 6);
        assert_eq!(m.get(utf8).file_offset(y), 3 + y);
        // inside a character: its start
        assert_eq!(m.get(single).file_offset(1), 0);
        assert_eq!(m.get(single).file_offset(1000), 6);
    }

    #[test]
    fn lf_crlf_and_a_lone_cr_each_end_one_line() {
        assert_eq!(line_starts("a\nb\r\nc\rd\r"), [0, 2, 5, 7, 9]);
        let f = SourceFile::new("x", "a\rb\r\nc");
        assert_eq!(f.line_col(2), (2, 1));
        assert_eq!(f.line_col(5), (3, 1));
        assert_eq!(f.offset_of(3, 1), 5);
    }
}

#[cfg(test)]
mod add_file_tests {
    use super::*;

    /// An owned text gives the same file as a borrowed one, byte-order mark or not, and is moved in.
    /// The word-at-a-time search gives the table of the byte-by-byte definition, also for line ends
    /// at every position of long texts (memchr switches to vector code past 16-32 bytes) and for `\r`
    /// and `\n` at the very end.
    #[test]
    fn line_starts_agree_with_the_byte_by_byte_definition() {
        fn by_bytes(b: &[u8]) -> Vec<usize> {
            let mut starts = vec![0];
            for (i, &c) in b.iter().enumerate() {
                if c == b'\n' || (c == b'\r' && b.get(i + 1) != Some(&b'\n')) {
                    starts.push(i + 1);
                }
            }
            starts
        }
        let ends = ["\n", "\r\n", "\r", "\r\r\n", "\n\r", ""];
        let mut text = String::new();
        for k in 0..400usize {
            text.push_str(&"x".repeat(k % 71));
            text.push_str(ends[k % ends.len()]);
            assert_eq!(line_starts(&text), by_bytes(text.as_bytes()), "{k}");
        }
        assert!(line_starts(&text).len() > 300);
    }

    /// The line table is built on the first position asked for, not when the file is added.
    #[test]
    fn the_line_table_is_built_on_first_use() {
        let mut m = SourceMap::new();
        let id = m.add("a.il", "LD a\r\nST b\n\nAND c");
        let f = m.get(id);
        assert!(f.line_starts.get().is_none());
        assert_eq!(f.line_col(7), (2, 2));
        assert_eq!(
            f.line_starts.get().map(Vec::as_slice),
            Some(&[0, 6, 11, 12][..])
        );
        assert_eq!(f.offset_of(4, 5), 16);
        assert_eq!(f.line_starts(), line_starts(&f.text));
    }

    #[test]
    fn owned_and_borrowed_texts_give_the_same_file() {
        for text in ["\u{feff}LD a\nST b\n", "LD a\nST b\n", "\u{feff}", ""] {
            let mut m = SourceMap::new();
            let a = m.add_file("a.il", text);
            let owned = text.to_string();
            let ptr = owned.as_ptr();
            let b = m.add_file_owned("a.il", owned);
            let (fa, fb) = (m.get(a), m.get(b));
            assert_eq!(
                (&fa.text, fa.byte_base, fa.line_starts()),
                (&fb.text, fb.byte_base, fb.line_starts()),
                "{text:?}"
            );
            assert!(!fb.text.starts_with('\u{feff}'));
            if !text.starts_with('\u{feff}') && !text.is_empty() {
                assert_eq!(fb.text.as_ptr(), ptr, "moved, not copied");
            }
        }
    }
}
