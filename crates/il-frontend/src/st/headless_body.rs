//! A POU's declarations and statements with no POU header around them: a CODESYS (or TwinCAT)
//! function block copied out of its editor without the `FUNCTION_BLOCK name` line the editor
//! shows above the declarations, and without `END_FUNCTION_BLOCK` (the editor writes none), so
//! the file starts with `VAR_INPUT ... END_VAR` (sometimes after a line holding the block's name
//! alone) and then holds the body's statements. IEC 61131-3 ed. 3, 6.5.1 and Annex B.0: a
//! POU's declarations and body stand between its header and its `END_*` keyword, and a file
//! holds POU, type, configuration and global declarations only.
//!
//! Input: the file's text, its tokens, the POUs [`super::file`]'s scan found and the tokens it
//! found outside every block (among them statements). Output: the `VAR` blocks outside every
//! POU that no POU header follows (those after the last POU, or all of them in a file without
//! one) and the header the hint of E0307 proposes. Invariant: with these blocks blanked along
//! with the statements, the file's one cause gets one error (E0307): the IL parser does not read
//! the blocks as an interface before a header (E1102) or as global variables (W0018). A
//! `VAR_INPUT` block a POU header follows keeps its E1102 (the header is there, the block is
//! misplaced); `VAR_GLOBAL`, `VAR_CONFIG` and `VAR_ACCESS` blocks are declarations a file may
//! hold outside POUs and stay.

use super::file::{is_var_keyword, is_word, word, PouText};
use super::lexer::{Tok, Token};
use std::ops::Range;

/// The declarations of a body written without its POU header: the byte ranges of its `VAR`
/// blocks and the header to add.
pub(super) struct HeadlessBody {
    /// `VAR ... END_VAR` blocks outside every POU, no POU header after them.
    pub blocks: Vec<Range<usize>>,
    /// `FUNCTION_BLOCK` when a block is `VAR_INPUT`, `VAR_OUTPUT` or `VAR_IN_OUT` (a program
    /// has no interface in CODESYS's editor), `PROGRAM` otherwise.
    pub kind: &'static str,
    /// The name alone on the text's first line before the blocks (`FB_Mover`), if written.
    pub name: Option<String>,
}

impl HeadlessBody {
    /// The hint of E0307 for statements outside any POU, `fallback` naming the POU when the text
    /// does not (the file's stem).
    pub fn hint(&self, fallback: &str) -> String {
        let name = self.name.as_deref().unwrap_or(fallback);
        let (kind, where_) = (
            self.kind,
            if self.name.is_some() {
                "instead of the line holding its name alone"
            } else {
                "above its first VAR block"
            },
        );
        format!(
            "this file is a CODESYS body without its header: write `{kind} {name}` {where_} and `END_{kind}` after its last statement (IEC 61131-3 ed. 3, 6.5.1: declarations and body stand between a POU's header and its end)"
        )
    }
}

/// The headless body of a text whose tokens `toks` hold statements outside any POU (`stray`:
/// indexes of the tokens outside every block), `pous` the POUs found: `None` when every `VAR`
/// block outside POUs has a POU header after it.
pub(super) fn find(
    src: &str,
    toks: &[Token],
    pous: &[PouText],
    stray: &[usize],
) -> Option<HeadlessBody> {
    // the blocks after the end of the last POU (its `END_*` keyword starts at `body.end`)
    let after = pous.iter().map(|p| p.body.end).max().unwrap_or(0);
    let mut blocks = Vec::new();
    let mut interface = false;
    let mut i = toks.partition_point(|t| t.range.start < after);
    // each step moves `i` forward (one token, or past a block's end), so the walk ends
    while let Some(t) = toks.get(i).filter(|t| !matches!(t.tok, Tok::Eof)) {
        let w = word(src, t).to_ascii_uppercase();
        if w == "TYPE" || w == "CONFIGURATION" {
            i = block_end(src, toks, i, &format!("END_{w}")) + 1;
        } else if is_var_keyword(&w) {
            let e = block_end(src, toks, i, "END_VAR");
            if !matches!(w.as_str(), "VAR_GLOBAL" | "VAR_CONFIG" | "VAR_ACCESS") {
                interface |= matches!(w.as_str(), "VAR_INPUT" | "VAR_OUTPUT" | "VAR_IN_OUT");
                let end = toks.get(e).map_or(t.range.end, |t| t.range.end);
                blocks.push(t.range.start..end);
            }
            i = e + 1;
        } else {
            i += 1;
        }
    }
    let first_block = blocks.first()?.start;
    // `FB_Mover` alone on its line, before the blocks
    let name = stray
        .first()
        .and_then(|&k| toks.get(k))
        .filter(|t| t.tok == Tok::Ident && t.range.end <= first_block)
        .filter(|t| {
            let before = src.get(..t.range.start).unwrap_or("");
            let line_start = before.rfind('\n').map_or(0, |n| n + 1);
            let rest = src.get(t.range.end..).unwrap_or("");
            let line_end = rest.find('\n').map_or(src.len(), |n| t.range.end + n);
            src.get(line_start..line_end).map(str::trim) == Some(word(src, t))
        })
        .map(|t| word(src, t).to_string());
    Some(HeadlessBody {
        blocks,
        kind: if interface {
            "FUNCTION_BLOCK"
        } else {
            "PROGRAM"
        },
        name,
    })
}

/// The index of the first token `end` after token `i` (the last token when none).
fn block_end(src: &str, toks: &[Token], i: usize, end: &str) -> usize {
    (i + 1..toks.len())
        .find(|&k| is_word(src, &toks[k], end))
        .unwrap_or(toks.len().saturating_sub(1))
}
