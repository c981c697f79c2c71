//! Positions and document names between the language server protocol and ladderc.
//!
//! Input: LSP positions (line, UTF-16 code unit), `file://` URIs; ladderc byte offsets and paths.
//! Output: the other form. Invariants: offsets returned lie on character boundaries inside the text
//! (a position past a line's end is clamped to it, a line past the end to the text's end).

use std::path::{Path, PathBuf};

/// Byte offset of an LSP position (`character` counts UTF-16 code units). Lines end at `\n`, `\r\n` or
/// a lone `\r`, as the protocol says (and as [`diagnostics::line_starts`] counts them).
pub fn offset(text: &str, line: u32, character: u32) -> usize {
    let starts = diagnostics::line_starts(text);
    let Some(&start) = starts.get(line as usize) else {
        return text.len();
    };
    let end = line_end(text, &starts, line as usize);
    let mut units = 0u32;
    for (i, c) in text[start..end].char_indices() {
        if units >= character {
            return start + i;
        }
        units += c.len_utf16() as u32;
    }
    end
}

/// The end of line `line` (before its line end) in `text` whose line starts are `starts`.
fn line_end(text: &str, starts: &[usize], line: usize) -> usize {
    let Some(&next) = starts.get(line + 1) else {
        return text.len();
    };
    let b = text.as_bytes();
    let mut end = next;
    if end > starts[line] && b[end - 1] == b'\n' {
        end -= 1;
    }
    if end > starts[line] && b[end - 1] == b'\r' {
        end -= 1;
    }
    end
}

/// LSP position (line, UTF-16 column) of a byte offset (clamped to the text, and back to a boundary).
/// For many look-ups in one text, build one [`LineIndex`].
pub fn position(text: &str, offset: usize) -> (u32, u32) {
    LineIndex::new(text).position(offset)
}

/// Line starts of a text, for many position look-ups in one text (each then costs a binary search and
/// the length of one line, not a scan from the start).
pub struct LineIndex<'a> {
    text: &'a str,
    starts: Vec<usize>,
}

impl<'a> LineIndex<'a> {
    /// The index of `text`'s line starts.
    pub fn new(text: &'a str) -> Self {
        LineIndex {
            text,
            starts: diagnostics::line_starts(text),
        }
    }

    /// [`position`] of `offset`, the same answer.
    pub fn position(&self, offset: usize) -> (u32, u32) {
        let mut offset = offset.min(self.text.len());
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        let line = self.starts.partition_point(|&s| s <= offset) - 1;
        let col = self.text[self.starts[line]..offset]
            .chars()
            .map(|c| c.len_utf16() as u32)
            .sum();
        (line as u32, col)
    }
}

/// The path of a `file://` URI (percent-escapes decoded); `None` for other schemes.
pub fn uri_to_path(uri: &str) -> Option<PathBuf> {
    let rest = uri.strip_prefix("file://")?;
    // `file:///x` (empty host) or `file://localhost/x`.
    let rest = rest.strip_prefix("localhost").unwrap_or(rest);
    let bytes = rest.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' && i + 2 < bytes.len() {
            if let Some(b) = std::str::from_utf8(&bytes[i + 1..i + 3])
                .ok()
                .and_then(|h| u8::from_str_radix(h, 16).ok())
            {
                out.push(b);
                i += 3;
                continue;
            }
        }
        out.push(bytes[i]);
        i += 1;
    }
    String::from_utf8(out).ok().map(PathBuf::from)
}

/// The `file://` URI of an absolute path (characters outside the unreserved set percent-escaped).
pub fn path_to_uri(path: &Path) -> String {
    let mut s = String::from("file://");
    for b in path.to_string_lossy().bytes() {
        if b.is_ascii_alphanumeric() || b"/-._~".contains(&b) {
            s.push(b as char);
        } else {
            s.push_str(&format!("%{b:02X}"));
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lone_cr_and_crlf_end_lines_as_the_protocol_says() {
        let text = "a\rbc\r\nd\ne\r";
        assert_eq!(offset(text, 1, 0), 2);
        assert_eq!(offset(text, 1, 9), 4, "clamped before the \\r\\n");
        assert_eq!(offset(text, 2, 0), 6);
        assert_eq!(offset(text, 3, 1), 9, "clamped before the lone \\r");
        assert_eq!(offset(text, 4, 0), text.len());
        assert_eq!(position(text, 3), (1, 1));
        assert_eq!(position(text, 8), (3, 0));
        assert_eq!(position(text, text.len()), (4, 0));
    }

    #[test]
    fn utf16_columns_round_trip() {
        let text = "a\nx€y𝄞z\n";
        // '€' is one UTF-16 unit and 3 bytes, '𝄞' two units and 4 bytes.
        assert_eq!(offset(text, 1, 0), 2);
        assert_eq!(offset(text, 1, 2), 2 + 1 + 3);
        assert_eq!(offset(text, 1, 5), 2 + 1 + 3 + 1 + 4);
        assert_eq!(position(text, 2 + 1 + 3 + 1 + 4), (1, 5));
        assert_eq!(
            offset(text, 1, 99),
            text.len() - 1,
            "clamped to the line end"
        );
        assert_eq!(offset(text, 9, 0), text.len(), "clamped to the text end");
        assert_eq!(
            position(text, 3),
            (1, 1),
            "inside a character: back to its start"
        );
    }

    #[test]
    fn uris_and_paths() {
        let p = Path::new("/tmp/my project/pump #2.il");
        let u = path_to_uri(p);
        assert_eq!(u, "file:///tmp/my%20project/pump%20%232.il");
        assert_eq!(uri_to_path(&u).unwrap(), p);
        assert_eq!(uri_to_path("untitled:1"), None);
    }
}
