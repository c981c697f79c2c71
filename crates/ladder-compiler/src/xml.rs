//! A small element tree over the XML text, with byte positions kept.
//!
//! Input: the XML text (a leading UTF-8 byte-order mark is skipped, positions still count it).
//! Output: [`Element`]s with local names (namespace prefixes dropped), decoded attribute values and text
//! segments; every element knows the byte range of its start tag and of its whole extent.
//! Invariants: all offsets are byte offsets into the original text (BOM included); text segments keep
//! their raw position so that bodies embedded in the XML can be mapped back (see [`Element::text`]).
//! A malformed document yields the tree read so far plus the error position: the caller reports it
//! (a start tag's attributes are checked by `crate::xml_attrs`).
//! Left out of the tree: empty `<relPosition>` and `<connectionPointOut>` elements, which nothing reads
//! (see `unread`).
//!
//! Storage: the elements, their child lists, text segments and decoded strings live in an [`Arena`]
//! that the caller owns next to the text: building the tree allocates a few large blocks instead of one
//! block per element, and freeing it frees those blocks (a 10,000-rung project has 630,000 elements, 455,000
//! of them kept).

use quick_xml::events::Event;
use quick_xml::Reader;
use std::borrow::Cow;

/// Where a document's tree is stored (see the module documentation); create one per document, next
/// to its text, and pass it to [`parse`]. The tree borrows it.
#[derive(Default)]
pub struct Arena(bumpalo::Bump);

impl Arena {
    /// An empty arena.
    pub fn new() -> Self {
        Self::default()
    }
    /// Moves `items` into the arena: a list of children (or text segments) for an element built in
    /// memory rather than read from a document.
    pub fn slice<T>(&self, items: Vec<T>) -> &[T] {
        self.0.alloc_slice_fill_iter(items)
    }
    /// Copies `text` into the arena.
    pub fn str(&self, text: &str) -> &str {
        self.0.alloc_str(text)
    }
}

/// One attribute: local name, decoded value, byte range of the raw value.
#[derive(Debug, Clone)]
pub struct Attr<'a> {
    /// The local name (`xmlns:xhtml` -> `xhtml`), borrowed from the text.
    pub name: &'a str,
    /// The value with entities decoded (in the [`Arena`]).
    pub value: &'a str,
    /// Byte offset of the raw value's first character (after the quote).
    pub start: usize,
    /// Byte offset just after the raw value (before the closing quote).
    pub end: usize,
}

/// How a piece of text was written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SegKind {
    /// Plain character data (no entity inside: entities are separate segments).
    Text,
    /// The content of a `<![CDATA[ ... ]]>` section.
    CData,
    /// An entity or character reference such as `&lt;` (decoded into `text`).
    Entity,
}

/// A piece of character data: decoded text and the raw byte range it came from.
#[derive(Debug, Clone, Copy)]
pub struct TextSeg<'a> {
    /// The text, entities decoded (borrowed from the document, or decoded into the [`Arena`]).
    pub text: &'a str,
    /// Byte offset of the raw piece in the document.
    pub start: usize,
    /// Byte offset just after the raw piece.
    pub end: usize,
    /// Plain text, CDATA or an entity.
    pub kind: SegKind,
}

/// One XML element: name, attributes, children and text, with byte positions in the document.
///
/// 56 bytes (a 10,000-rung project keeps 455,000 of them, and they are the largest share of the pages
/// its build touches): the text segments and the decoded attributes, which most elements of a graphical
/// body do not have, sit behind one pointer ([`Element::segments`]); the positions are `u32` (documents
/// of 4 GiB or more are refused by [`parse`], as [`diagnostics::Span`] holds `u32` offsets too); the
/// local name is a range of the raw start tag ([`Element::name`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct Element<'a> {
    /// The raw start tag between `<` and `>` (the `/` of an empty tag dropped): the name and the
    /// attributes are read from it.
    pub raw_tag: &'a str,
    /// The child elements, in document order (in the [`Arena`]).
    pub children: &'a [Element<'a>],
    /// The text segments and decoded attributes, when the element has any (in the [`Arena`]).
    pub(crate) extra: Option<&'a Extra<'a>>,
    /// Byte offset of the start tag's `<`.
    pub(crate) tag_start: u32,
    /// Byte offset just after the start tag's `>`.
    pub(crate) tag_end: u32,
    /// Byte offset just after the end tag (or the empty tag).
    pub(crate) end: u32,
    /// The local name's byte range in `raw_tag` (`0..0` for a name that does not fit: longer than
    /// 65,535 bytes or starting past that, which no schema element does).
    pub(crate) name_at: u16,
    pub(crate) name_end: u16,
}

/// What few elements have: direct text, attributes with entities.
#[derive(Debug, Default)]
pub(crate) struct Extra<'a> {
    /// Direct character data, in order (leading whitespace-only pieces are dropped).
    text: &'a [TextSeg<'a>],
    /// The attributes whose values hold entities, decoded once.
    decoded_attrs: &'a [Attr<'a>],
}

/// A parse failure: message and byte position.
#[derive(Debug, Clone)]
pub struct XmlError {
    /// What the XML reader reported.
    pub message: String,
    /// Byte offset in the document where it stopped.
    pub pos: usize,
}

impl<'a> Element<'a> {
    /// An element with start tag `raw_tag` (between `<` and `>`, without the `/` of an empty tag) at
    /// byte `tag_start`, the tag ending before `tag_end`, the element before `end`; no children, no text.
    /// Positions past `u32::MAX` are cut to it (a document that large is refused by [`parse`]).
    pub fn new(raw_tag: &'a str, tag_start: usize, tag_end: usize, end: usize) -> Self {
        let (at, name_end) = tag_name_range(raw_tag);
        let (name_at, name_end) = match (u16::try_from(at), u16::try_from(name_end)) {
            (Ok(a), Ok(e)) => (a, e),
            _ => (0, 0),
        };
        Element {
            raw_tag,
            children: &[],
            extra: None,
            tag_start: offset(tag_start),
            tag_end: offset(tag_end),
            end: offset(end),
            name_at,
            name_end,
        }
    }
    /// The local name (`xhtml:p` -> `p`), borrowed from the text.
    #[inline]
    pub fn name(&self) -> &'a str {
        self.raw_tag
            .get(self.name_at as usize..self.name_end as usize)
            .unwrap_or("")
    }
    /// Byte offset of the start tag's `<`.
    #[inline]
    pub fn tag_start(&self) -> usize {
        self.tag_start as usize
    }
    /// Byte offset just after the start tag's `>`.
    #[inline]
    pub fn tag_end(&self) -> usize {
        self.tag_end as usize
    }
    /// Byte offset just after the end tag (or the empty tag).
    #[inline]
    pub fn end(&self) -> usize {
        self.end as usize
    }
    /// An element with the given text segments and no attribute holding an entity (for bodies built in
    /// memory rather than read from a document); the other fields as given in `el`.
    pub fn with_segments(el: Element<'a>, text: &'a [TextSeg<'a>], arena: &'a Arena) -> Self {
        Element {
            extra: Some(arena.0.alloc(Extra {
                text,
                decoded_attrs: &[],
            })),
            ..el
        }
    }
    /// Direct character data, in order (leading whitespace-only pieces are dropped).
    pub fn segments(&self) -> &'a [TextSeg<'a>] {
        self.extra.map_or(&[], |x| x.text)
    }
    /// The attributes whose values hold entities, decoded once (usually none).
    fn decoded_attrs(&self) -> &'a [Attr<'a>] {
        self.extra.map_or(&[], |x| x.decoded_attrs)
    }
    /// An attribute's value (entities decoded), by local name.
    pub fn attr(&self, name: &str) -> Option<&'a str> {
        // (No `str::contains(name)` pre-check: its substring search costs more than scanning a
        // start tag's few attributes.)
        let raw = scan_attrs(self.raw_tag).find(|(n, _, _)| *n == name)?;
        let value = &self.raw_tag[raw.1..raw.2];
        if !has_amp(value) {
            return Some(value);
        }
        self.decoded_attrs()
            .iter()
            .find(|a| a.name == name)
            .map(|a| a.value)
    }
    /// The values of several attributes (entities decoded) in one pass over the start tag: slot `k` holds
    /// what [`Element::attr`] would give for `names[k]` (the first attribute of that local name).
    #[inline]
    pub fn attrs<const N: usize>(&self, names: [&str; N]) -> [Option<&'a str>; N] {
        self.attrs_and_ranges(names)
            .map(|a| a.map(|(value, _)| value))
    }
    /// [`Element::attrs`] with each value's byte range in the document: slot `k` holds what
    /// [`Element::attr_and_range`] would give for `names[k]`. (Inlined: [`Element::attrs`] then drops
    /// the ranges at no cost.)
    #[inline]
    pub fn attrs_and_ranges<const N: usize>(
        &self,
        names: [&str; N],
    ) -> [Option<(&'a str, (usize, usize))>; N] {
        let mut out = [None; N];
        // An empty name is never found (every scanned name has a character): it does not count.
        let mut left = names.iter().filter(|n| !n.is_empty()).count();
        if left == 0 {
            return out;
        }
        for (n, s, e) in scan_attrs(self.raw_tag) {
            // Length and first byte before the full compare (a `memcmp` call): most attribute names
            // of a tag differ from each wanted one in one of them.
            let Some(k) = names.iter().position(|x| {
                x.len() == n.len() && x.as_bytes().first() == n.as_bytes().first() && *x == n
            }) else {
                continue;
            };
            if out[k].is_some() {
                continue;
            }
            let value = &self.raw_tag[s..e];
            let range = (self.tag_start() + 1 + s, self.tag_start() + 1 + e);
            out[k] = if has_amp(value) {
                self.decoded_attrs()
                    .iter()
                    .find(|a| a.start == range.0)
                    .map(|a| (a.value, range))
            } else {
                Some((value, range))
            };
            left -= 1;
            if left == 0 {
                break;
            }
        }
        out
    }
    /// [`Element::attr`] and [`Element::attr_range`] of one attribute, found in one pass.
    pub fn attr_and_range(&self, name: &str) -> Option<(&str, (usize, usize))> {
        let (_, s, e) = scan_attrs(self.raw_tag).find(|(n, _, _)| *n == name)?;
        let range = (self.tag_start() + 1 + s, self.tag_start() + 1 + e);
        let value = &self.raw_tag[s..e];
        if !has_amp(value) {
            return Some((value, range));
        }
        self.decoded_attrs()
            .iter()
            .find(|a| a.start == range.0)
            .map(|a| (a.value, range))
    }
    /// The byte range of an attribute's raw value in the document.
    pub fn attr_range(&self, name: &str) -> Option<(usize, usize)> {
        let (_, start, end) = scan_attrs(self.raw_tag).find(|(n, _, _)| *n == name)?;
        Some((self.tag_start() + 1 + start, self.tag_start() + 1 + end))
    }
    /// The first direct child with local name `name`.
    pub fn child(&self, name: &str) -> Option<&Element<'a>> {
        self.children.iter().find(|c| c.name() == name)
    }
    /// The direct children with local name `name`, in document order.
    pub fn children_named<'s>(
        &'s self,
        name: &'s str,
    ) -> impl Iterator<Item = &'s Element<'a>> + 's {
        self.children.iter().filter(move |c| c.name() == name)
    }
    /// The decoded direct text, all segments joined.
    pub fn text(&self) -> String {
        self.text_ref().into_owned()
    }
    /// The same text as [`Element::text`], borrowed when it is one segment (the usual case).
    pub fn text_ref(&self) -> Cow<'a, str> {
        match self.segments() {
            [] => Cow::Borrowed(""),
            [one] => Cow::Borrowed(one.text),
            many => Cow::Owned(many.iter().map(|s| s.text).collect()),
        }
    }
    /// Every descendant (depth first, self excluded).
    pub fn descendants(&self) -> Vec<&Element<'a>> {
        self.walk().collect()
    }
    /// The same elements in the same order as [`Element::descendants`], without collecting them
    /// (the stack holds one iterator per open level).
    pub fn walk(&self) -> impl Iterator<Item = &Element<'a>> {
        let mut stack = vec![self.children.iter()];
        std::iter::from_fn(move || loop {
            let top = stack.last_mut()?;
            match top.next() {
                Some(e) => {
                    stack.push(e.children.iter());
                    return Some(e);
                }
                None => {
                    stack.pop();
                }
            }
        })
    }
}

/// Whether an attribute value holds a `&` (values are short: a byte loop, no `memchr` call).
fn has_amp(value: &str) -> bool {
    value.bytes().any(|b| b == b'&')
}

/// Whether `text` is empty or only whitespace (`str::trim` would leave nothing): a byte loop for the
/// usual ASCII indentation, the char test only past a non-ASCII byte.
fn is_blank(text: &str) -> bool {
    // `char::is_whitespace` also counts U+000B, which `u8::is_ascii_whitespace` does not.
    match text
        .bytes()
        .position(|b| !(b.is_ascii_whitespace() || b == 0x0b))
    {
        None => true,
        Some(i) if !text.as_bytes()[i].is_ascii() => text[i..].trim().is_empty(),
        Some(_) => false,
    }
}

/// The byte range in a raw tag of the element name's local part (`contact localId="1"` -> `contact`,
/// `xhtml:p` -> `p`).
fn tag_name_range(raw: &str) -> (usize, usize) {
    // One forward pass: the name ends at whitespace or `/`, its local part starts after its last `:`.
    let b = raw.as_bytes();
    let (mut start, mut end) = (0, 0);
    while end < b.len() && !(b[end].is_ascii_whitespace() || b[end] == b'/') {
        if b[end] == b':' {
            start = end + 1;
        }
        end += 1;
    }
    (start, end)
}

/// A byte offset as an element stores it ([`parse`] refuses documents of 4 GiB or more, so every
/// offset of a parsed document fits).
fn offset(pos: usize) -> u32 {
    u32::try_from(pos).unwrap_or(u32::MAX)
}

/// Decodes the five predefined entities and character references; `None` for anything else.
pub fn decode_entity(name: &str) -> Option<String> {
    Some(match name {
        "lt" => "<".into(),
        "gt" => ">".into(),
        "amp" => "&".into(),
        "quot" => "\"".into(),
        "apos" => "'".into(),
        _ => {
            let num = name.strip_prefix('#')?;
            let code = match num.strip_prefix('x').or_else(|| num.strip_prefix('X')) {
                Some(hex) => u32::from_str_radix(hex, 16).ok()?,
                None => num.parse().ok()?,
            };
            char::from_u32(code)?.to_string()
        }
    })
}

/// Decodes entities inside an attribute value (quick-xml leaves them escaped).
fn decode_attr_value(raw: &str) -> Cow<'_, str> {
    if !raw.contains('&') {
        return Cow::Borrowed(raw);
    }
    let mut out = String::with_capacity(raw.len());
    let mut rest = raw;
    while let Some(i) = rest.find('&') {
        out.push_str(&rest[..i]);
        let after = &rest[i + 1..];
        match after
            .find(';')
            .and_then(|j| decode_entity(&after[..j]).map(|d| (j, d)))
        {
            Some((j, d)) => {
                out.push_str(&d);
                rest = &after[j + 1..];
            }
            None => {
                out.push('&');
                rest = after;
            }
        }
    }
    out.push_str(rest);
    Cow::Owned(out)
}

/// The attributes of a raw start tag: local name and the byte range of the raw value inside the tag.
///
/// Byte loops only (this runs for every attribute lookup, so it avoids char decoding and `rfind`).
fn scan_attrs(raw_tag: &str) -> AttrScan<'_> {
    let bytes = raw_tag.as_bytes();
    // The element name ends at the first separator (a table lookup per byte).
    let mut i = 0;
    while i < bytes.len() && class(bytes[i]) & NAME_END == 0 {
        i += 1;
    }
    if i < bytes.len() && !bytes[i].is_ascii() {
        // A non-ASCII character before the first separator: the rare slow path (Unicode whitespace).
        // (`char::is_whitespace` also counts U+000B, hence the 0x0b above.)
        i = raw_tag
            .find(|c: char| c.is_whitespace() || c == '/')
            .unwrap_or(raw_tag.len());
    }
    AttrScan { raw: raw_tag, i }
}

/// ASCII whitespace as `u8::is_ascii_whitespace` counts it (space, tab, LF, FF, CR).
const SPACE: u8 = 1;
/// `=`.
const EQ: u8 = 2;
/// `:`.
const COLON: u8 = 4;
/// `/`.
const SLASH: u8 = 8;
/// What ends an element name for [`scan_attrs`]: ASCII whitespace, U+000B, `/`, a non-ASCII byte.
const NAME_END: u8 = 16;

/// The byte classes of [`AttrScan`]'s loops, one table lookup per byte.
static CLASS: [u8; 256] = {
    let mut t = [0u8; 256];
    t[b' ' as usize] = SPACE;
    t[b'\t' as usize] = SPACE;
    t[b'\n' as usize] = SPACE;
    t[0x0c] = SPACE;
    t[b'\r' as usize] = SPACE;
    t[b'=' as usize] = EQ;
    t[b':' as usize] = COLON;
    t[b'/' as usize] = SLASH;
    let mut b = 0;
    while b < 256 {
        if t[b] & (SPACE | SLASH) != 0 || b == 0x0b || b >= 0x80 {
            t[b] |= NAME_END;
        }
        b += 1;
    }
    t
};

#[inline(always)]
fn class(b: u8) -> u8 {
    CLASS[b as usize]
}

/// [`scan_attrs`]'s iterator: a plain struct (a `from_fn` closure was not inlined into its callers,
/// and its loops tested each byte against several characters).
struct AttrScan<'t> {
    raw: &'t str,
    i: usize,
}

impl<'t> Iterator for AttrScan<'t> {
    type Item = (&'t str, usize, usize);
    #[inline]
    fn next(&mut self) -> Option<Self::Item> {
        let bytes = self.raw.as_bytes();
        let mut i = self.i;
        loop {
            while i < bytes.len() && class(bytes[i]) & (SPACE | SLASH) != 0 {
                i += 1;
            }
            let name_start = i;
            // The local part starts after the last `:` of the qualified name.
            let mut local_start = i;
            // One test per byte: a `:` (its class is `COLON` alone) moves the local part's start.
            while i < bytes.len() {
                let c = class(bytes[i]);
                if c & (SPACE | EQ | COLON) != 0 {
                    if c != COLON {
                        break;
                    }
                    local_start = i + 1;
                }
                i += 1;
            }
            if name_start == i {
                self.i = i;
                return None;
            }
            let name = &self.raw[local_start..i];
            while i < bytes.len() && class(bytes[i]) & SPACE != 0 {
                i += 1;
            }
            if i >= bytes.len() || bytes[i] != b'=' {
                continue;
            }
            i += 1;
            while i < bytes.len() && class(bytes[i]) & SPACE != 0 {
                i += 1;
            }
            if i >= bytes.len() || (bytes[i] != b'"' && bytes[i] != b'\'') {
                self.i = i;
                return None;
            }
            let quote = bytes[i];
            i += 1;
            let vstart = i;
            while i < bytes.len() && bytes[i] != quote {
                i += 1;
            }
            let vend = i.min(bytes.len());
            self.i = i + 1;
            return Some((name, vstart, vend));
        }
    }
}

/// The attributes with entities in their value, decoded (`None` when there is none).
fn decoded_attrs<'a>(raw_tag: &'a str, tag_pos: usize, arena: &'a Arena) -> Option<&'a Extra<'a>> {
    memchr::memchr(b'&', raw_tag.as_bytes())?;
    let attrs: Vec<Attr<'a>> = scan_attrs(raw_tag)
        .filter(|(_, s, e)| raw_tag[*s..*e].contains('&'))
        .map(|(name, s, e)| Attr {
            name,
            value: match decode_attr_value(&raw_tag[s..e]) {
                Cow::Borrowed(v) => v,
                Cow::Owned(v) => arena.str(&v),
            },
            start: tag_pos + 1 + s,
            end: tag_pos + 1 + e,
        })
        .collect();
    if attrs.is_empty() {
        return None;
    }
    Some(arena.0.alloc(Extra {
        text: &[],
        decoded_attrs: arena.slice(attrs),
    }))
}

/// Deeper documents are refused (no PLCopen file comes close; the limit keeps recursion bounded).
pub const MAX_DEPTH: usize = 256;

/// Parses the document into `arena`; returns the root element (if any start tag was read) and the first
/// error.
///
/// A document of [`MAX_LEN`] bytes or more is not read: no element, and an error at position 0 (element
/// positions are `u32`, as are [`diagnostics::Span`]'s).
pub fn parse<'a>(xml: &'a str, arena: &'a Arena) -> (Option<Element<'a>>, Option<XmlError>) {
    parse_up_to(xml, arena, MAX_LEN)
}

/// The largest document [`parse`] reads is one byte shorter: 4 GiB.
pub const MAX_LEN: usize = u32::MAX as usize;

/// [`parse`], refusing documents of `max_len` bytes or more.
fn parse_up_to<'a>(
    xml: &'a str,
    arena: &'a Arena,
    max_len: usize,
) -> (Option<Element<'a>>, Option<XmlError>) {
    if xml.len() >= max_len {
        let err = XmlError {
            message: format!(
                "the document is {} bytes long; XML files are read up to {} bytes",
                xml.len(),
                max_len - 1
            ),
            pos: 0,
        };
        return (None, Some(err));
    }
    let base = if xml.starts_with('\u{feff}') { 3 } else { 0 };
    let body = &xml[base..];
    if let Some(root) = parse_plain(body, base, arena) {
        return (root, None);
    }
    parse_quick_xml(body, base, arena)
}

/// A start tag's element (`raw`: between `<` and `>`, the `/` of an empty tag dropped) at byte `pos`
/// of the body (`<`), its tag ending before `after`.
fn start_element<'a>(
    raw: &'a str,
    base: usize,
    pos: usize,
    after: usize,
    arena: &'a Arena,
) -> Element<'a> {
    plain_element(raw, base, pos, after, decoded_attrs(raw, base + pos, arena))
}

/// [`start_element`] with the decoded attributes given (none when the tag holds no `&`).
fn plain_element<'a>(
    raw: &'a str,
    base: usize,
    pos: usize,
    after: usize,
    extra: Option<&'a Extra<'a>>,
) -> Element<'a> {
    Element {
        extra,
        ..Element::new(raw, base + pos, base + after, base + after)
    }
}

/// XML whitespace as quick-xml counts it (names end there).
fn xml_space(b: u8) -> bool {
    matches!(b, b' ' | b'\r' | b'\n' | b'\t')
}

/// The bytes a start tag's scan stops at: `>`, the two quotes and `&`.
static TAG_STOPS: [bool; 256] = {
    let mut t = [false; 256];
    t[b'>' as usize] = true;
    t[b'"' as usize] = true;
    t[b'\'' as usize] = true;
    t[b'&' as usize] = true;
    t
};

/// The first `>` outside quotes at or after `p`, and whether the tag holds a `&` (in or out of
/// quotes); `None` when the document ends first. A byte loop: tags are short, so it beats a `memchr3`
/// call per quote.
fn tag_end(b: &[u8], mut k: usize) -> Option<(usize, bool)> {
    let mut amp = false;
    let mut quote = 0u8;
    loop {
        while k < b.len() && !TAG_STOPS[b[k] as usize] {
            k += 1;
        }
        match (quote, *b.get(k)?) {
            (_, b'&') => amp = true,
            (0, b'>') => return Some((k, amp)),
            (0, c) => quote = c,
            (s, c) if s == c => quote = 0,
            _ => {}
        }
        k += 1;
    }
}

/// The first `<` or `&` at or after `i`: the first bytes by a loop (usually indentation), the rest by
/// `memchr2`.
fn next_markup(b: &[u8], i: usize) -> Option<usize> {
    let near = b.len().min(i + 32);
    match b[i..near].iter().position(|&c| c == b'<' || c == b'&') {
        Some(k) => Some(i + k),
        None => memchr::memchr2(b'<', b'&', &b[near..]).map(|k| near + k),
    }
}

/// The document read without quick-xml, when it keeps to the subset that generated and most
/// exported files use: elements, attributes, text without `&`, comments, CDATA sections, the XML
/// declaration and processing instructions. `None` as soon as anything else turns up (an entity or
/// character reference, a DOCTYPE, an end tag that does not match, an element left open, nesting past
/// [`MAX_DEPTH`], a tag cut off by the end): [`parse_quick_xml`] then reads the document and reports
/// what is wrong. On the subset both give the same tree (tests compare them), with byte positions
/// taken the way quick-xml 0.38 reports them.
fn parse_plain<'a>(body: &'a str, base: usize, arena: &'a Arena) -> Option<Option<Element<'a>>> {
    let b = body.as_bytes();
    if b.starts_with(&[0xef, 0xbb, 0xbf]) {
        // A second byte-order mark: quick-xml drops it too.
        return None;
    }
    let mut tree = Builder::new(arena, body.len());
    // The names of the open elements as quick-xml compares them with end tags (up to whitespace).
    let mut open: Vec<&[u8]> = Vec::new();
    let mut i = 0;
    loop {
        // Text up to the next markup (usually a few bytes of indentation: a byte loop, then memchr).
        let next = next_markup(b, i);
        let end = next.unwrap_or(b.len());
        if end > i {
            tree.text(body, base, i, end);
        }
        let lt = match next {
            None => break,
            Some(k) if b[k] == b'&' => return None,
            Some(k) => k,
        };
        let p = lt + 1;
        match *b.get(p)? {
            b'!' if b[p..].starts_with(b"!--") => {
                // A comment ends at the first `>` after `--`, at least 5 bytes after the `!`.
                let k = memchr::memchr_iter(b'>', &b[p..])
                    .find(|&k| k > 4 && b[p..p + k].ends_with(b"--"))?;
                i = p + k + 1;
            }
            b'!' if b[p..].starts_with(b"![CDATA[") => {
                let k =
                    memchr::memchr_iter(b'>', &b[p..]).find(|&k| b[p..p + k].ends_with(b"]]"))?;
                let after = p + k + 1;
                tree.push_text(TextSeg {
                    text: &body[lt + 9..after - 3],
                    start: base + lt + 9,
                    end: base + after - 3,
                    kind: SegKind::CData,
                });
                i = after;
            }
            b'!' => return None,
            b'?' => {
                // `?>` ends it; `<?>` is an error for quick-xml.
                let k =
                    memchr::memchr_iter(b'>', &b[p..]).find(|&k| k > 0 && b[p + k - 1] == b'?')?;
                if k < 2 {
                    return None;
                }
                i = p + k + 1;
            }
            b'/' => {
                let k = b[p..]
                    .iter()
                    .position(|&c| matches!(c, b'>' | b'"' | b'\''))?;
                if b[p + k] != b'>' {
                    return None;
                }
                let content = &b[p + 1..p + k];
                let name = match content.iter().rposition(|&c| !xml_space(c)) {
                    Some(e) => &content[..e + 1],
                    None => content,
                };
                if open.pop()? != name {
                    return None;
                }
                let after = p + k + 1;
                tree.close(Some(base + after));
                i = after;
            }
            c => {
                if !(c.is_ascii_alphabetic() || c == b'_' || c == b':' || !c.is_ascii()) {
                    return None;
                }
                // The tag ends at the first `>` outside quotes.
                let (gt, amp) = tag_end(b, p)?;
                let after = gt + 1;
                let content = &body[p..gt];
                let element = |raw: &'a str| {
                    let decoded = if amp {
                        decoded_attrs(raw, base + lt, arena)
                    } else {
                        None
                    };
                    plain_element(raw, base, lt, after, decoded)
                };
                if crate::xml_attrs::fault(content.strip_suffix('/').unwrap_or(content)).is_some() {
                    // not well-formed: quick-xml's reading reports it
                    return None;
                }
                match content.strip_suffix('/') {
                    Some(raw) => tree.attach(element(raw)),
                    None => {
                        if tree.stack.len() >= MAX_DEPTH {
                            return None;
                        }
                        let cb = content.as_bytes();
                        let name_end = cb.iter().position(|&c| xml_space(c)).unwrap_or(cb.len());
                        open.push(&cb[..name_end]);
                        tree.open(element(content));
                    }
                }
                i = after;
            }
        }
    }
    if tree.is_open() {
        return None;
    }
    Some(tree.finish())
}

/// The document read with quick-xml: any document, errors included.
fn parse_quick_xml<'a>(
    body: &'a str,
    base: usize,
    arena: &'a Arena,
) -> (Option<Element<'a>>, Option<XmlError>) {
    // quick-xml drops a byte-order mark at the start of what it reads without counting it in its
    // positions; further marks (the caller strips the first) are skipped here, however many, so
    // that every position stays a byte offset into `body` on a character boundary.
    let rest = body.trim_start_matches('\u{feff}');
    let (body, base) = (rest, base + (body.len() - rest.len()));
    let mut reader = Reader::from_str(body);
    reader.config_mut().trim_text(false);
    let mut tree = Builder::new(arena, body.len());
    loop {
        let pos = reader.buffer_position() as usize;
        let ev = match reader.read_event() {
            Ok(ev) => ev,
            Err(e) => {
                let err = XmlError {
                    message: e.to_string(),
                    pos: base + reader.error_position() as usize,
                };
                return (tree.finish(), Some(err));
            }
        };
        let after = reader.buffer_position() as usize;
        match ev {
            Event::Start(_) | Event::Empty(_) => {
                let raw = &body[pos + 1..after.saturating_sub(1).max(pos + 1)];
                let raw = raw.strip_suffix('/').unwrap_or(raw);
                if let Some((at, message)) = crate::xml_attrs::fault(raw) {
                    let err = XmlError {
                        message,
                        pos: base + pos + 1 + at,
                    };
                    return (tree.finish(), Some(err));
                }
                let el = start_element(raw, base, pos, after, arena);
                if matches!(ev, Event::Start(_)) {
                    if tree.stack.len() >= MAX_DEPTH {
                        let err = XmlError {
                            message: format!("elements nested deeper than {MAX_DEPTH} levels"),
                            pos: base + pos,
                        };
                        return (tree.finish(), Some(err));
                    }
                    tree.open(el);
                } else {
                    tree.attach(el);
                }
            }
            Event::End(_) => {
                tree.close(Some(base + after));
            }
            Event::Text(_) => tree.text(body, base, pos, after),
            Event::CData(_) => tree.push_text(TextSeg {
                text: &body[pos + 9..after - 3],
                start: base + pos + 9,
                end: base + after - 3,
                kind: SegKind::CData,
            }),
            Event::GeneralRef(r) if tree.is_open() => {
                let name = String::from_utf8_lossy(r.as_ref()).into_owned();
                let text = decode_entity(&name).unwrap_or_else(|| format!("&{name};"));
                tree.push_text(TextSeg {
                    text: arena.str(&text),
                    start: base + pos,
                    end: base + after,
                    kind: SegKind::Entity,
                });
            }
            Event::Eof => break,
            _ => {}
        }
    }
    let unclosed = tree
        .stack
        .last()
        .map(|e| (e.name().to_string(), e.tag_start()));
    let root = tree.finish();
    let err = unclosed.map(|(name, pos)| XmlError {
        message: format!("element <{name}> is never closed"),
        pos,
    });
    (root, err)
}

/// Whether a finished element is left out of its parent's children: an empty `<relPosition>` or
/// `<connectionPointOut>` (no children, once its own `<relPosition>` is left out; no text; no
/// entity-decoded attribute). Nothing reads them: a wire names its source by `refLocalId`, where a
/// pin is drawn does not matter, and neither has a `localId` in the schema. They are 28 % of the
/// elements of a typical LD body (175,000 of the 630,000 of the generated 10,000 rungs): at 56 bytes
/// each, 9.8 MB of fresh pages. The document is still checked in full; the root is always kept.
fn unread(el: &Element) -> bool {
    matches!(el.name(), "relPosition" | "connectionPointOut")
        && el.children.is_empty()
        && el.extra.is_none()
}

/// The elements being read: open ones on `stack`, finished children of open ones in `done`, text
/// segments of open ones in `texts`.
///
/// Children and text segments wait in the shared lists until their element closes, then move into
/// the arena, exactly sized.
struct Builder<'a> {
    arena: &'a Arena,
    stack: Vec<Element<'a>>,
    /// Where each open element's children start in `done` (parallel to `stack`).
    starts: Vec<usize>,
    done: Vec<Element<'a>>,
    /// Where each open element's text segments start in `texts` (parallel to `stack`).
    text_starts: Vec<usize>,
    texts: Vec<TextSeg<'a>>,
    root: Option<Element<'a>>,
}

impl<'a> Builder<'a> {
    /// A builder for a document of `len` bytes. `done` gets room for one finished element per 256
    /// bytes up front (the generated 10,000 rungs hold 67,500 at once, one per 340 bytes, in their
    /// body): growing it by doubling copied every pending element into fresh pages each time (6 % of
    /// the page faults of `ladderc build` on those rungs). Pages of the reserve that are never written
    /// are never touched.
    fn new(arena: &'a Arena, len: usize) -> Self {
        Builder {
            arena,
            stack: Vec::new(),
            starts: Vec::new(),
            done: Vec::with_capacity(len / 256),
            text_starts: Vec::new(),
            texts: Vec::new(),
            root: None,
        }
    }
    fn open(&mut self, el: Element<'a>) {
        self.starts.push(self.done.len());
        self.text_starts.push(self.texts.len());
        self.stack.push(el);
    }
    fn is_open(&self) -> bool {
        !self.stack.is_empty()
    }
    /// Whether the innermost open element has text already.
    fn top_has_text(&self) -> bool {
        self.text_starts
            .last()
            .is_some_and(|&start| self.texts.len() > start)
    }
    /// The character data `body[pos..after]` (no entity in it) of the innermost open element.
    fn text(&mut self, body: &'a str, base: usize, pos: usize, after: usize) {
        let raw = &body[pos..after];
        // Indentation between elements is dropped; whitespace after the first text of an
        // element is kept (it belongs to an embedded body).
        if self.is_open() && (self.top_has_text() || !is_blank(raw)) {
            self.push_text(TextSeg {
                text: raw,
                start: base + pos,
                end: base + after,
                kind: SegKind::Text,
            });
        }
    }
    /// A text segment of the innermost open element (dropped when none is open).
    fn push_text(&mut self, seg: TextSeg<'a>) {
        if self.is_open() {
            self.texts.push(seg);
        }
    }
    /// Closes the innermost open element (its end moved to `end` when given).
    fn close(&mut self, end: Option<usize>) {
        if let Some(mut el) = self.stack.pop() {
            let start = self.starts.pop().unwrap_or(self.done.len());
            let text_start = self.text_starts.pop().unwrap_or(self.texts.len());
            let text_start = text_start.min(self.texts.len());
            if text_start < self.texts.len() {
                // Plain copies (the types are `Copy`): one `memcpy`, not an element-wise drain.
                let text = self.arena.0.alloc_slice_copy(&self.texts[text_start..]);
                self.texts.truncate(text_start);
                el.extra = Some(self.arena.0.alloc(Extra {
                    text,
                    decoded_attrs: el.decoded_attrs(),
                }));
            }
            let start = start.min(self.done.len());
            if start < self.done.len() {
                el.children = self.arena.0.alloc_slice_copy(&self.done[start..]);
                self.done.truncate(start);
            }
            if let Some(end) = end {
                el.end = offset(end);
            }
            self.attach(el);
        }
    }
    /// A finished element: a child of the innermost open element (unless [`unread`]), or the root
    /// (the first one only).
    #[inline]
    fn attach(&mut self, el: Element<'a>) {
        if self.stack.is_empty() {
            if self.root.is_none() {
                self.root = Some(el);
            }
        } else if !unread(&el) {
            self.done.push(el);
        }
    }
    /// Closes every element still open and returns the root.
    fn finish(mut self) -> Option<Element<'a>> {
        while !self.stack.is_empty() {
            self.close(None);
        }
        self.root
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn documents_at_the_length_limit_are_refused_without_a_tree() {
        let xml = "<a><b x=\"1\"/></a>";
        let arena = Arena::new();
        let (root, err) = parse_up_to(xml, &arena, xml.len());
        assert!(root.is_none());
        let err = err.expect("refused");
        assert_eq!(err.pos, 0);
        let limit = format!("read up to {} bytes", xml.len() - 1);
        assert!(err.message.contains(&limit), "{}", err.message);
        let (root, err) = parse_up_to(xml, &arena, xml.len() + 1);
        assert!(err.is_none());
        let a = root.unwrap();
        assert_eq!((a.tag_start(), a.tag_end(), a.end()), (0, 3, xml.len()));
        assert_eq!(a.children[0].name(), "b");
        assert_eq!(a.children[0].attr("x"), Some("1"));
    }

    #[test]
    fn a_name_too_long_for_the_element_reads_as_empty_and_its_attributes_still_read() {
        // 70,000 bytes of name: past the `u16` range of `Element::name`; both readers agree.
        let long = "n".repeat(70_000);
        for xml in [
            format!("<r><{long} a=\"1\"/></r>"),
            format!("<r><{long} a=\"1\"/><x>&lt;</x></r>"),
        ] {
            let arena = Arena::new();
            let (root, err) = parse(&xml, &arena);
            assert!(err.is_none());
            let r = root.unwrap();
            assert_eq!(r.name(), "r");
            assert_eq!(r.children[0].name(), "");
            assert_eq!(r.children[0].attr("a"), Some("1"));
            assert_eq!(r.children[0].end(), 3 + long.len() + 9);
        }
        // A name that ends within range but is prefixed past it: the local part after a long prefix.
        let xml = format!("<r><{long}:p/></r>");
        let arena = Arena::new();
        let (root, _) = parse(&xml, &arena);
        assert_eq!(root.unwrap().children[0].name(), "");
    }

    #[test]
    fn keeps_positions_of_tags_attributes_cdata_and_entities() {
        let xml = "\u{feff}<a x=\"1&amp;2\"><b:p>LD x&lt;<![CDATA[ST y]]></b:p></a>";
        let arena = Arena::new();
        let (root, err) = parse(xml, &arena);
        assert!(err.is_none());
        let a = root.unwrap();
        assert_eq!(a.name(), "a");
        assert_eq!(a.tag_start(), 3);
        assert_eq!(a.attr("x"), Some("1&2"));
        let (s, e) = a.attr_range("x").unwrap();
        assert_eq!(&xml[s..e], "1&amp;2");
        let p = a.child("p").unwrap();
        assert_eq!(p.text(), "LD x<ST y");
        assert_eq!(p.text_ref(), "LD x<ST y");
        let segs: Vec<_> = p.segments().iter().map(|s| &xml[s.start..s.end]).collect();
        assert_eq!(segs, ["LD x", "&lt;", "ST y"]);
        assert_eq!(p.segments()[2].kind, SegKind::CData);
    }

    #[test]
    fn attrs_in_one_pass_match_attr_one_by_one() {
        let xml = "<a x=\"1\" p:y=\"a&amp;b\" x=\"2\" z='3' w=\"&lt;\"/>";
        let arena = Arena::new();
        let (root, err) = parse(xml, &arena);
        assert!(err.is_none());
        let a = root.unwrap();
        let names = ["y", "x", "absent", "z", "w"];
        let got = a.attrs(names);
        assert_eq!(got, [Some("a&b"), Some("1"), None, Some("3"), Some("<")]);
        assert_eq!(a.attrs(["", "z", ""]), [None, Some("3"), None]);
        for n in names {
            assert_eq!(
                a.attr_and_range(n),
                a.attr(n).map(|v| (v, a.attr_range(n).unwrap())),
                "{n}"
            );
        }
        for (k, n) in names.iter().enumerate() {
            assert_eq!(got[k], a.attr(n), "{n}");
        }
        let ranged = a.attrs_and_ranges(names);
        for (k, n) in names.iter().enumerate() {
            assert_eq!(ranged[k], a.attr_and_range(n), "{n}");
        }
        assert_eq!(a.attrs_and_ranges(["", "z"])[0], None);
    }

    #[test]
    fn scans_attributes_of_odd_start_tags() {
        let all = |tag: &str| -> Vec<(String, String)> {
            scan_attrs(tag)
                .map(|(n, s, e)| (n.to_string(), tag[s..e].to_string()))
                .collect()
        };
        let pairs = |v: &[(&str, &str)]| -> Vec<(String, String)> {
            v.iter()
                .map(|(a, b)| (a.to_string(), b.to_string()))
                .collect()
        };
        assert_eq!(
            all("a x=\"1\" xmlns:p = 'two words' p:q=\"\"/"),
            pairs(&[("x", "1"), ("p", "two words"), ("q", "")])
        );
        // A name without a value is skipped; an unquoted value ends the scan.
        assert_eq!(all("a flag x=\"1\" y=2 z=\"3\""), pairs(&[("x", "1")]));
        // An unterminated value runs to the end of the tag.
        assert_eq!(all("a x=\"1"), pairs(&[("x", "1")]));
        assert_eq!(all("a x="), pairs(&[]));
        assert_eq!(all("a"), pairs(&[]));
        assert_eq!(all(""), pairs(&[]));
        assert_eq!(all("a\tx='1'\ny=\"2\""), pairs(&[("x", "1"), ("y", "2")]));
        // Only the element name ends at Unicode whitespace; attribute names end at ASCII whitespace.
        assert_eq!(all("\u{e9}l\u{2003}x=\"1\""), pairs(&[("\u{2003}x", "1")]));
    }

    #[test]
    fn one_text_segment_is_borrowed_several_are_joined() {
        let xml = "<a><v> x1 </v><w>a&amp;b</w><e/></a>";
        let arena = Arena::new();
        let (root, err) = parse(xml, &arena);
        assert!(err.is_none());
        let a = root.unwrap();
        let v = a.child("v").unwrap().text_ref();
        assert!(matches!(v, Cow::Borrowed(" x1 ")), "{v:?}");
        assert_eq!(a.child("w").unwrap().text_ref(), "a&b");
        assert_eq!(a.child("e").unwrap().text_ref(), "");
    }

    #[test]
    fn elements_stay_small() {
        // 455,000 of them kept for 10,000 rungs: every 8 bytes are 3.6 MB of fresh pages.
        assert_eq!(std::mem::size_of::<Element>(), 56);
        // Text and entity-holding attributes hang off one pointer, set only where they exist.
        let arena = Arena::new();
        let (root, _) = parse("<a x=\"1\"><b>t</b><c y=\"&amp;\"/></a>", &arena);
        let a = root.unwrap();
        assert!(a.extra.is_none());
        assert_eq!(a.children[0].segments()[0].text, "t");
        assert_eq!(a.children[1].attr("y"), Some("&"));
        assert!(a.children[1].segments().is_empty());
    }

    #[test]
    fn walks_descendants_depth_first_in_document_order() {
        let arena = Arena::new();
        let (root, _) = parse("<r><a><b/><c><d/></c></a><e/></r>", &arena);
        let r = root.unwrap();
        let names: Vec<_> = r.walk().map(|e| e.name()).collect();
        assert_eq!(names, ["a", "b", "c", "d", "e"]);
        let listed: Vec<_> = r.descendants().iter().map(|e| e.name()).collect();
        assert_eq!(listed, names);
    }

    #[test]
    fn empty_rel_positions_and_connection_points_out_are_left_out() {
        // The second document has an entity in text: the quick-xml reader builds it.
        for tail in ["", "<t>a &amp; b</t>"] {
            let doc = format!(
                "<r><c><relPosition x=\"1\" y=\"2\"/><connectionPointOut><relPosition x=\"3\" y=\"4\"/></connectionPointOut>\
                 <connectionPointOut formalParameter=\"Q\"/><connection refLocalId=\"1\"/></c>\
                 <connectionPointOut><addData/></connectionPointOut><relPosition>t</relPosition>\
                 <relPosition a=\"&lt;\"/>{tail}</r>"
            );
            let arena = Arena::new();
            let (root, err) = parse(&doc, &arena);
            assert!(err.is_none(), "{tail}");
            let r = root.unwrap();
            let names: Vec<_> = r.walk().map(|e| e.name()).collect();
            let mut want = vec![
                "c",
                "connection",
                "connectionPointOut",
                "addData",
                "relPosition",
                "relPosition",
            ];
            if !tail.is_empty() {
                want.push("t");
            }
            assert_eq!(names, want, "{tail}");
            // Positions of the kept elements still count the dropped ones.
            let conn = r.children[0].children[0];
            assert_eq!(
                &doc[conn.tag_start()..conn.end()],
                "<connection refLocalId=\"1\"/>"
            );
        }
        // The root is kept whatever it is.
        let arena = Arena::new();
        let (root, _) = parse("<relPosition/>", &arena);
        assert_eq!(root.unwrap().name(), "relPosition");
    }

    #[test]
    fn blank_text_is_what_trim_empties() {
        for t in [
            "",
            " ",
            "\n\t\r ",
            "\u{a0}",
            " \u{2003}\n",
            "\u{b}",
            "\u{c}",
        ] {
            assert!(is_blank(t), "{t:?}");
            assert!(t.trim().is_empty(), "{t:?}");
        }
        for t in ["x", "  x ", "\n\u{e9}", " \u{a0}x"] {
            assert!(!is_blank(t), "{t:?}");
            assert!(!t.trim().is_empty(), "{t:?}");
        }
    }

    /// Both readers on `xml` (after a byte-order mark): `Some` when the plain one read it, and then
    /// it must have built what quick-xml builds.
    fn both(xml: &str) -> Option<String> {
        let base = if xml.starts_with('\u{feff}') { 3 } else { 0 };
        let arena = Arena::new();
        let plain = parse_plain(&xml[base..], base, &arena)?;
        let (quick, err) = parse_quick_xml(&xml[base..], base, &arena);
        assert!(
            err.is_none(),
            "{xml:?}: plain reader took a document quick-xml rejects: {err:?}"
        );
        let (plain, quick) = (format!("{plain:?}"), format!("{quick:?}"));
        assert_eq!(plain, quick, "{xml:?}");
        Some(plain)
    }

    #[test]
    fn the_plain_reader_builds_what_quick_xml_builds() {
        let taken = [
            "<a/>",
            "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<a x=\"1\" y='2'>\n  <b>t x</b>\n</a>\n",
            "\u{feff}<a><b/></a>",
            "<a>  lead <!-- note -- --> tail<![CDATA[ x < y ]]>end</a >",
            "<a><!----><![CDATA[]]></a>",
            "<a q=\"x>y\" r='\"'>t</a>",
            "<p:a xmlns:p=\"u\"><p:b/>text\n  more\n</p:a>",
            "<a\n  x=\"1\"\n>\u{e9}\u{2003}</a\t>",
            "<a/ ><b></b></a/>",
            "<?pi x?><a><?pi?></a>",
            "",
            "just text",
            // `&` in attribute values (the tag scan notes it; the values are decoded), in and out of
            // quotes, next to a `>` and the other quote inside a value
            "<a x=\"1&amp;2\" y='&lt;&#x41;'><b z=\"'>&quot;\"/></a>",
            "<a x=\"&bogus;\" y=\"2\"/>",
        ];
        for xml in taken {
            assert!(both(xml).is_some(), "{xml:?} should take the plain path");
        }
        let generated = crate::testgen::generate(8);
        assert!(both(&generated).is_some());
        // Text and indentation longer than the byte loop's 32 bytes before the `memchr` search.
        let long = format!(
            "<a>{}<b>{}x</b>{}</a>",
            " ".repeat(40),
            "y".repeat(100),
            "\n".repeat(33)
        );
        assert!(both(&long).is_some());
        let left = [
            "<a>x &amp; y</a>",
            "<a>&</a>",
            "<!DOCTYPE a><a/>",
            "<a><b></a>",
            "<a></b>",
            "</a>",
            "<a>",
            "<a x=\"1>",
            "<a><!-- open",
            "<a><![CDATA[ open",
            "<a><?pi",
            "<?><a/>",
            "<a></a x=\"1\">",
            "<a>< b/></a>",
            "<1a></1a>",
            "<a><!-x --></a>",
            "<a><![cdata[x]]></a>",
            "\u{feff}\u{feff}<a/>",
            "<a>x<",
            // not well-formed attributes (`xml_attrs`): a stray `&`, a name starting with `@`
            "<a x=\"&bogus;\" & y=\"2\"/>",
            "<a @_x=\"1\"/>",
        ];
        // quick-xml must not be handed a leading mark (it drops it and its positions shift).
        for xml in [
            "\u{feff}\u{feff}A",
            "\u{feff}\u{feff}\u{feff}EJ",
            "\u{feff}\u{feff}\u{feff}\u{feff}<a>x</a>",
            "\u{feff}\u{feff}<a>x</a>",
            "\u{feff}\u{feff}<a><![CDATA[\u{e9}]]></a>",
        ] {
            let arena = Arena::new();
            let (root, _) = parse(xml, &arena);
            if let Some(root) = root {
                assert!(format!("{root:?}").len() < 10_000);
            }
        }
        for xml in left {
            assert!(both(xml).is_none(), "{xml:?} should be left to quick-xml");
        }
        let deep = format!(
            "{}{}",
            "<a>".repeat(MAX_DEPTH + 1),
            "</a>".repeat(MAX_DEPTH + 1)
        );
        assert!(both(&deep).is_none());
    }

    #[test]
    fn the_plain_reader_agrees_on_every_fixture_and_corpus_file() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let mut dirs = vec![
            root.join("crates/ladder-compiler/tests/fixtures"),
            root.join("crates/test-corpus/files"),
            root.join("tests/corpus"),
            root.join("tests/tests/fixtures"),
            root.join("templates"),
        ];
        if let Ok(c) = std::env::var("LADDERC_CORPUS") {
            dirs.push(c.into());
        }
        let mut files = Vec::new();
        while let Some(d) = dirs.pop() {
            for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {
                let p = e.path();
                if p.is_dir() {
                    dirs.push(p);
                } else if p.extension().is_some_and(|x| x == "xml") {
                    files.push(p);
                }
            }
        }
        assert!(files.len() > 20, "{} XML files found", files.len());
        for f in files {
            let Ok(text) = std::fs::read_to_string(&f) else {
                continue;
            };
            // Either reader may be the one that runs; when the plain one does, it matches.
            let _ = both(&text);
        }
    }

    #[test]
    fn refuses_absurd_nesting() {
        let xml = "<a>".repeat(MAX_DEPTH + 10);
        let arena = Arena::new();
        let (root, err) = parse(&xml, &arena);
        assert!(root.is_some());
        assert!(err.unwrap().message.contains("nested deeper"));
    }

    #[test]
    fn reports_malformed_documents_with_position() {
        let arena = Arena::new();
        let (root, err) = parse("<a><b></a>", &arena);
        assert!(root.is_some());
        let err = err.unwrap();
        assert!(err.pos > 0, "{err:?}");
    }
}
