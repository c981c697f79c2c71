//! The parameter templates: one XML file per PLCopen block (schema in `templates/README.md`).
//!
//! Input: a template file's text. Output: a validated [`Template`] or diagnostics (E40xx) that point into the
//! template file. Invariants of a returned template: parameter names and abbreviations are unique
//! (case-insensitively for names), abbreviations are C identifiers that are not C keywords, every class
//! agrees with its IEC type, and body/feedback texts keep their byte offsets in the file. An array parameter
//! (`class="array"`) has a scalar element class (not struct), an element type of that class and a length
//! in `1..=MAX_ARRAY_LEN`; its `class` field is the element class and `array` its shape.

use crate::xml::{self, Element};
use diagnostics::{code, Diagnostic, Diagnostics, FileId, Span};

/// How a parameter passes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// Read by the block (`:=`).
    Input,
    /// Written by the block (`=>`).
    Output,
    /// Read and written by the block (`AXIS_REF`, `AXES_GROUP_REF`).
    InOut,
    /// Hidden per-instance state the library keeps between scans (not visible to programs).
    State,
}

/// Paper A's parameter classes, refined by size: they fix the TM slot size and the transfer instructions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TypeClass {
    /// BOOL (1 byte).
    Bool,
    /// 8-bit values (1 byte).
    Byte,
    /// 16-bit values (2 bytes).
    Word,
    /// 32-bit values (4 bytes).
    Dword,
    /// REAL (4 bytes).
    Real,
    /// LREAL (8 bytes).
    Lreal,
    /// 64-bit state words.
    Lword,
    /// Passed as a base address (an axis or group reference: its index in the motion engine).
    Struct,
}

impl TypeClass {
    /// Bytes a parameter of this class takes in the TM area.
    pub fn tm_bytes(self) -> u32 {
        match self {
            TypeClass::Bool | TypeClass::Byte => 1,
            TypeClass::Word => 2,
            TypeClass::Dword | TypeClass::Real | TypeClass::Struct => 4,
            TypeClass::Lreal | TypeClass::Lword => 8,
        }
    }
    fn parse(s: &str) -> Option<Self> {
        Some(match s {
            "bool" => TypeClass::Bool,
            "byte" => TypeClass::Byte,
            "word" => TypeClass::Word,
            "dword" => TypeClass::Dword,
            "real" => TypeClass::Real,
            "lreal" => TypeClass::Lreal,
            "lword" => TypeClass::Lword,
            "struct" => TypeClass::Struct,
            _ => return None,
        })
    }
}

/// The IEC types a class admits, with the C type a head local gets.
pub fn c_type_of(iec_type: &str, class: TypeClass) -> Option<&'static str> {
    let t = iec_type.to_ascii_uppercase();
    let c = match (class, t.as_str()) {
        (TypeClass::Bool, "BOOL") => "uint8_t",
        (TypeClass::Byte, "BYTE" | "USINT") => "uint8_t",
        (TypeClass::Byte, "SINT") => "int8_t",
        (
            TypeClass::Byte,
            "MC_BUFFER_MODE" | "MC_DIRECTION" | "MC_TRANSITION_MODE" | "MC_CIRC_MODE",
        ) => "uint8_t",
        (
            TypeClass::Byte,
            "MC_CIRC_PATHCHOICE" | "MC_COORD_SYSTEM" | "MC_EXECUTION_MODE" | "MC_START_MODE",
        ) => "uint8_t",
        (TypeClass::Word, "WORD" | "UINT") => "uint16_t",
        (TypeClass::Word, "INT") => "int16_t",
        (TypeClass::Dword, "DWORD" | "UDINT") => "uint32_t",
        (TypeClass::Dword, "DINT") => "int32_t",
        (TypeClass::Real, "REAL") => "float",
        (TypeClass::Lreal, "LREAL") => "double",
        (TypeClass::Lword, "LWORD" | "ULINT") => "uint64_t",
        (
            TypeClass::Struct,
            "AXIS_REF" | "AXES_GROUP_REF" | "AXIS_GROUP_REF" | "MC_CAM_REF" | "MC_CAM_ID",
        ) => "uint32_t",
        _ => return None,
    };
    Some(c)
}

/// The longest array parameter: the motion library's position arrays hold 16 entries (one per
/// identity in the group).
pub const MAX_ARRAY_LEN: u32 = 16;

/// The shape of an array parameter: IEC `ARRAY [low..low+len-1] OF <element type>`; C `T name[len]`,
/// element `k` is IEC index `low + k`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ArrayShape {
    /// The number of elements.
    pub len: u32,
    /// The IEC index of the first element.
    pub low: i64,
}

impl ArrayShape {
    /// The IEC index of C element `k`.
    pub fn iec_index(&self, k: u32) -> i64 {
        self.low + i64::from(k)
    }
}

/// One `<param>` of a template.
#[derive(Debug, Clone)]
pub struct Param {
    /// The IEC name (`Position`).
    pub name: String,
    /// The abbreviation the body uses (`Pos`).
    pub abbr: String,
    /// Input, output, in-out or state.
    pub direction: Direction,
    /// The class of the value, or of every element for an array parameter.
    pub class: TypeClass,
    /// The IEC type of the value, or of every element for an array parameter.
    pub iec_type: String,
    /// `Some` for an array parameter (`class="array"`).
    pub array: Option<ArrayShape>,
    /// Whether a call must bind it.
    pub required: bool,
    /// Default value as an IEC literal text (`FALSE`, `0.0`, `0`), used when an optional input is not bound
    /// (for an array: the value of every element).
    pub default: Option<String>,
    /// The `<param>` element.
    pub span: Span,
}

impl Param {
    /// The C type of the value (of one element for an array).
    pub fn c_type(&self) -> &'static str {
        c_type_of(&self.iec_type, self.class).unwrap_or("uint8_t")
    }
    /// Number of values: the array length, 1 for a scalar.
    pub fn values(&self) -> u32 {
        self.array.map_or(1, |a| a.len)
    }
    /// Bytes the parameter takes in the TM area (the elements of an array contiguously).
    pub fn tm_bytes(&self) -> u32 {
        self.class.tm_bytes() * self.values()
    }
    /// The IEC type programs see: the element type, or `ARRAY [l..h] OF <element type>`.
    pub fn iec_declared(&self, element: &str) -> String {
        match self.array {
            Some(a) => format!("ARRAY [{}..{}] OF {element}", a.low, a.iec_index(a.len - 1)),
            None => element.to_string(),
        }
    }
}

/// A local the body declares through the template (`<local name="cmd" ctype="double"/>`).
#[derive(Debug, Clone)]
pub struct Local {
    /// The local's name.
    pub name: String,
    /// Its C type.
    pub c_type: String,
    /// The `<local>` element.
    pub span: Span,
}

/// C text from the template with the file offset of its first byte (for mapping errors back).
#[derive(Debug, Clone)]
pub struct CText {
    /// The text.
    pub text: String,
    /// Where it is in the file.
    pub span: Span,
    /// `span.start + i` is the file offset of `text[i]` (a CDATA section).
    pub verbatim: bool,
    /// The runs the text was joined from: (offset in `text`, offset in the file, bytes of the file, verbatim).
    pub pieces: Vec<(usize, usize, usize, bool)>,
}

impl CText {
    /// The file span of `text[start..end]`: exact inside verbatim runs; a whole entity reference otherwise.
    pub fn span_of(&self, start: usize, end: usize) -> Span {
        let file = self.span.file;
        let locate = |at: usize, is_end: bool| -> Option<usize> {
            let k = self
                .pieces
                .iter()
                .rposition(|&(t, ..)| if is_end { t < at } else { t <= at })?;
            let (t, f, len, verbatim) = self.pieces[k];
            Some(if verbatim {
                f + (at - t).min(len)
            } else if is_end {
                f + len
            } else {
                f
            })
        };
        match (locate(start, false), locate(end.max(start), true)) {
            (Some(s), Some(e)) if e >= s => Span::new(file, s, e),
            (Some(s), _) => Span::new(file, s, s),
            _ => self.span,
        }
    }
}

/// A parameter template (`templates/*.xml`): the block's interface and the C body its calls run.
#[derive(Debug, Clone)]
pub struct Template {
    /// Block type name, as in IEC (`MC_MoveAbsolute`).
    pub block: String,
    /// The number the generated head assigns to `FuncNum` (paper A).
    pub func_num: u32,
    /// The parameters, in file order.
    pub params: Vec<Param>,
    /// The body's locals.
    pub locals: Vec<Local>,
    /// The C body.
    pub body: CText,
    /// The template file.
    pub file: FileId,
    /// The `<blockTemplate>` element.
    pub span: Span,
}

impl Template {
    /// The parameter `name` (case-insensitive).
    pub fn param(&self, name: &str) -> Option<&Param> {
        self.params
            .iter()
            .find(|p| p.name.eq_ignore_ascii_case(name))
    }
    /// Inputs and in-outs: what a program binds with `:=`.
    pub fn inputs(&self) -> impl Iterator<Item = &Param> {
        self.params
            .iter()
            .filter(|p| matches!(p.direction, Direction::Input | Direction::InOut))
    }
    /// The outputs.
    pub fn outputs(&self) -> impl Iterator<Item = &Param> {
        self.params
            .iter()
            .filter(|p| p.direction == Direction::Output)
    }
    /// Outputs and state: what the instance keeps between scans and the library reads back.
    pub fn carried(&self) -> impl Iterator<Item = &Param> {
        self.params
            .iter()
            .filter(|p| matches!(p.direction, Direction::Output | Direction::State))
    }
}

/// C keywords, which no abbreviation or local may be.
pub const C_KEYWORDS: &[&str] = &[
    "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else",
    "enum", "extern", "float", "for", "goto", "if", "inline", "int", "long", "register",
    "restrict", "return", "short", "signed", "sizeof", "static", "struct", "switch", "typedef",
    "union", "unsigned", "void", "volatile", "while", "_Bool",
];

/// Whether `s` is a C identifier.
pub fn is_c_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// The longest abbreviation (the head's local adds `_` and the call number; C99 keeps 63 characters).
pub const MAX_ABBR_LEN: usize = 24;

/// Paper A's abbreviation rule, as this schema fixes it: 1 to [`MAX_ABBR_LEN`] ASCII letters and digits,
/// starting with a letter. No `_` (the head's locals are `abbr_<call number>` and every name the generator
/// or the runtime defines contains `_`, so no abbreviation can meet them), no `$`, no other character.
/// Template locals and the locals a body declares follow the same rule.
pub fn is_abbreviation(s: &str) -> bool {
    (1..=MAX_ABBR_LEN).contains(&s.len())
        && s.as_bytes()[0].is_ascii_alphabetic()
        && s.bytes().all(|b| b.is_ascii_alphanumeric())
}

/// The macros without `_` that the C headers of the generated program define (`stdio.h`, `stdlib.h`,
/// `stdint.h`, `stddef.h`, `string.h`, `math.h`, `stdarg.h`, `stdbool.h`; `gcc -dM -E`), and `errno` and
/// `assert`. A local of such a name is expanded by the preprocessor: `isnan` as a local let the body call
/// the function-like macro `isnan(x)`, outside the functions a body may call.
pub const C_HEADER_MACROS: &[&str] = &[
    "stdin",
    "stdout",
    "stderr",
    "EOF",
    "BUFSIZ",
    "NAN",
    "INFINITY",
    "offsetof",
    "isnan",
    "isinf",
    "isfinite",
    "isnormal",
    "signbit",
    "fpclassify",
    "isgreater",
    "isgreaterequal",
    "isless",
    "islessequal",
    "islessgreater",
    "isunordered",
    "errno",
    "assert",
];

/// Names no abbreviation or local may take: C keywords, the head's `FuncNum`, the method's `self`, the
/// names a body may use from C and the motion library.
pub fn is_reserved_name(s: &str) -> bool {
    C_KEYWORDS.contains(&s)
        || matches!(
            s,
            "FuncNum" | "self" | "main" | "bool" | "true" | "false" | "NULL"
        )
        || C_HEADER_MACROS.contains(&s)
        || crate::cbody::C_BASICS.contains(&s)
        || crate::library::runtime_symbol_set().contains(s)
}

/// The scalar C types a `<local>` may have (the motion library's block structs are the rest of the list).
pub const LOCAL_C_SCALARS: &[&str] = &[
    "uint8_t", "int8_t", "uint16_t", "int16_t", "uint32_t", "int32_t", "uint64_t", "int64_t",
    "float", "double", "bool",
];

/// Whether `ctype` is on the closed list of `<local>` C types.
pub fn is_local_c_type(ctype: &str) -> bool {
    LOCAL_C_SCALARS.contains(&ctype) || crate::library::header_struct_types().contains(ctype)
}

/// An IEC 61131-3 identifier as block and parameter names must be: an ASCII letter, then letters, digits
/// and single underscores, not ending in `_`, at most 64 characters.
pub fn is_iec_identifier(s: &str) -> bool {
    let b = s.as_bytes();
    (1..=64).contains(&b.len())
        && b[0].is_ascii_alphabetic()
        && b.iter().all(|c| c.is_ascii_alphanumeric() || *c == b'_')
        && !s.contains("__")
        && !s.ends_with('_')
}

/// Why a block name cannot name a C function (the IL method defines `void <name>(void)` with external
/// linkage, the template method `<name>_<n>`), or `None` when it can.
fn block_name_problem(name: &str) -> Option<&'static str> {
    let lower = name.to_ascii_lowercase();
    if !is_iec_identifier(name) {
        Some("an IEC identifier (an ASCII letter, then letters, digits and single `_`)")
    } else if !name.bytes().any(|b| b.is_ascii_uppercase()) {
        // Every C library function is lower case: a name with an upper-case letter cannot replace one.
        Some("a name with at least one upper-case letter (C library functions are all lower case)")
    } else if lower.starts_with("ladderc")
        || lower.starts_with("iec_")
        || C_KEYWORDS.contains(&name)
    {
        Some("a name outside the generator's reserved `ladderc`/`IEC_` prefixes")
    } else if crate::library::runtime_symbol_set().iter().any(|r| {
        // C names are case-sensitive: `MC_Halt` does not meet the library's `mc_halt`.
        r == name
            || r.strip_prefix(name)
                .and_then(|rest| rest.strip_prefix('_'))
                .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
    }) {
        Some("a name that no motion-library symbol has (the C function would clash with it)")
    } else if C_HEADER_MACROS.contains(&name) || matches!(name, "NULL" | "FILE") {
        // `void NAN(void)` would be expanded by the preprocessor
        Some("a name that is no macro or type of the C headers (`NAN`, `EOF`, `FILE` ...)")
    } else {
        None
    }
}

/// Whether `value` is one IEC literal of `class` (the `default` of an optional input): it is pasted into the
/// block's IL declaration, so nothing else may pass.
fn is_default_literal(value: &str, class: TypeClass) -> bool {
    let v = value.trim();
    let integer = |v: &str| -> Option<i128> {
        let digits = v.strip_prefix(['+', '-']).unwrap_or(v);
        if digits.is_empty()
            || !digits.bytes().all(|b| b.is_ascii_digit() || b == b'_')
            || digits.starts_with('_')
        {
            return None;
        }
        let n: i128 = digits.replace('_', "").parse().ok()?;
        Some(if v.starts_with('-') { -n } else { n })
    };
    match class {
        TypeClass::Bool => matches!(
            v.to_ascii_uppercase().as_str(),
            "TRUE" | "FALSE" | "0" | "1"
        ),
        TypeClass::Byte => {
            integer(v).is_some_and(|n| (-128..=255).contains(&n))
                || crate::prelude::ENUM_CONSTANTS
                    .iter()
                    .any(|(c, _)| c.eq_ignore_ascii_case(v))
        }
        TypeClass::Word => integer(v).is_some_and(|n| (-32768..=65535).contains(&n)),
        TypeClass::Dword => {
            integer(v).is_some_and(|n| (-(1i128 << 31)..(1i128 << 32)).contains(&n))
        }
        TypeClass::Lword => integer(v).is_some_and(|n| (0..(1i128 << 64)).contains(&n)),
        TypeClass::Real | TypeClass::Lreal => {
            let body = v.strip_prefix(['+', '-']).unwrap_or(v);
            !body.is_empty()
                && body.as_bytes()[0].is_ascii_digit()
                && body.bytes().all(|b| {
                    b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-' | b'_')
                })
                && body
                    .replace('_', "")
                    .parse::<f64>()
                    .is_ok_and(f64::is_finite)
        }
        TypeClass::Struct => false,
    }
}

fn need_attr<'a>(el: &'a Element, name: &str, diags: &mut Diagnostics) -> Option<&'a xml::Attr> {
    let a = el.attr(name);
    if a.is_none() {
        diags.push(
            Diagnostic::error(
                code::E4003,
                format!("<{}> lacks the attribute `{name}`", el.name),
            )
            .at(el.span)
            .with_hint(format!(
                "add {name}=\"...\" (see templates/README.md for the schema)"
            )),
        );
    }
    a
}

fn abbreviation_error(attr: &xml::Attr, what: &str) -> Diagnostic {
    Diagnostic::error(
        code::E4206,
        format!("{what} `{}` does not follow the abbreviation rules", attr.value.escape_debug()),
    )
    .at(attr.span)
    .with_hint(format!(
        "1 to {MAX_ABBR_LEN} ASCII letters and digits, starting with a letter (no `_`, no `$`); not a C keyword, `FuncNum`, `self` or a motion-library name"
    ))
}

fn bad_value(attr: &xml::Attr, expected: &str) -> Diagnostic {
    Diagnostic::error(
        code::E4004,
        format!("`{}` is not a valid value for `{}`", attr.value, attr.name),
    )
    .at(attr.span)
    .with_hint(format!("use {expected}"))
}

/// Loads and validates one template. Diagnostics go to `diags`; `None` when the file is unusable.
pub fn load(file: FileId, text: &str, diags: &mut Diagnostics) -> Option<Template> {
    let root = match xml::parse(file, text) {
        Ok(r) => r,
        Err(d) => {
            diags.push(*d);
            return None;
        }
    };
    if root.name != "blockTemplate" {
        diags.push(
            Diagnostic::error(
                code::E4002,
                format!("the root element is <{}>, not <blockTemplate>", root.name),
            )
            .at(root.span)
            .with_hint(
                "a template file holds one <blockTemplate name=\"MC_...\" funcNum=\"N\"> element",
            ),
        );
        return None;
    }
    let errors_before = diags.error_count();
    let block = need_attr(&root, "name", diags).and_then(|a| match block_name_problem(&a.value) {
        None => Some(a.value.clone()),
        Some(want) => {
            diags.push(
                Diagnostic::error(
                    code::E4207,
                    format!("block name `{}` is not allowed", a.value.escape_debug()),
                )
                .at(a.span)
                .with_hint(format!(
                    "use {want}, such as `MC_MoveAbsolute` or `ACME_Press`"
                )),
            );
            None
        }
    });
    let func_num = need_attr(&root, "funcNum", diags).and_then(|a| match a.value.parse::<u32>() {
        Ok(n) => Some(n),
        Err(_) => {
            diags.push(bad_value(a, "a non-negative integer"));
            None
        }
    });
    let mut params: Vec<Param> = Vec::new();
    if let Some(ps) = root.child("parameters") {
        for p in ps.children_named("param") {
            if let Some(param) = load_param(p, diags) {
                if let Some(prev) = params
                    .iter()
                    .find(|q| q.name.eq_ignore_ascii_case(&param.name))
                {
                    diags.push(
                        Diagnostic::error(
                            code::E4005,
                            format!("parameter `{}` is declared twice", param.name),
                        )
                        .at(param.span)
                        .with_label(prev.span, "first declared here")
                        .with_hint("remove one of the declarations"),
                    );
                } else if let Some(prev) = params.iter().find(|q| q.abbr == param.abbr) {
                    diags.push(
                        Diagnostic::error(
                            code::E4005,
                            format!("abbreviation `{}` is used twice", param.abbr),
                        )
                        .at(param.span)
                        .with_label(prev.span, "first used here")
                        .with_hint(
                            "each parameter needs its own abbreviation: it names the C local",
                        ),
                    );
                } else {
                    params.push(param);
                }
            }
        }
    } else {
        diags.push(
            Diagnostic::error(code::E4003, "<blockTemplate> has no <parameters> element")
                .at(root.span)
                .with_hint("list the block's parameters in <parameters><param .../></parameters>"),
        );
    }
    let mut locals = Vec::new();
    for l in root.children_named("local") {
        let (Some(n), Some(t)) = (need_attr(l, "name", diags), need_attr(l, "ctype", diags)) else {
            continue;
        };
        if !is_abbreviation(&n.value) || is_reserved_name(&n.value) {
            diags.push(abbreviation_error(n, "local"));
            continue;
        }
        if !is_local_c_type(&t.value) {
            diags.push(
                Diagnostic::error(
                    code::E4200,
                    format!(
                        "`{}` is not a C type a template local may have",
                        t.value.escape_debug()
                    ),
                )
                .at(t.span)
                .with_hint(format!(
                    "use one of {} or a block struct of motion_lib.h (`MC_MoveAbsolute_C` ...)",
                    LOCAL_C_SCALARS.join(", ")
                )),
            );
            continue;
        }
        if let Some(prev) = locals.iter().find(|q: &&Local| q.name == n.value) {
            diags.push(
                Diagnostic::error(
                    code::E4005,
                    format!("local `{}` is declared twice", n.value),
                )
                .at(n.span)
                .with_label(prev.span, "first declared here")
                .with_hint("remove one of the declarations"),
            );
            continue;
        }
        locals.push(Local {
            name: n.value.clone(),
            c_type: t.value.clone(),
            span: l.span,
        });
    }
    let body = match root.child("body") {
        Some(b) => ctext(b),
        None => {
            diags.push(
                Diagnostic::error(code::E4003, "<blockTemplate> has no <body> element")
                    .at(root.span)
                    .with_hint("put the library body (C that uses the abbreviations) in <body><![CDATA[ ... ]]></body>"),
            );
            None
        }
    };
    if diags.error_count() > errors_before {
        return None;
    }
    Some(Template {
        block: block?,
        func_num: func_num?,
        params,
        locals,
        body: body?,
        file,
        span: root.span,
    })
}

fn ctext(el: &Element) -> Option<CText> {
    let mut text = String::new();
    let mut pieces = Vec::new();
    for seg in &el.segments {
        pieces.push((text.len(), seg.offset, seg.src_len, seg.verbatim));
        text.push_str(&seg.text);
    }
    let verbatim = match el.significant_segment() {
        Some(seg) => seg.verbatim && el.segments.len() == 1,
        None => false,
    };
    let span = match (el.segments.first(), el.segments.last()) {
        (Some(a), Some(b)) => Span::new(el.span.file, a.offset, b.offset + b.src_len),
        _ => el.span,
    };
    Some(CText {
        text,
        span,
        verbatim,
        pieces,
    })
}

fn load_param(p: &Element, diags: &mut Diagnostics) -> Option<Param> {
    let name = need_attr(p, "name", diags);
    let abbr = need_attr(p, "abbr", diags);
    let dir = need_attr(p, "direction", diags);
    let class = need_attr(p, "class", diags);
    let ty = need_attr(p, "type", diags);
    let (name, abbr, dir, class, ty) = (name?, abbr?, dir?, class?, ty?);
    let direction = match dir.value.as_str() {
        "input" => Direction::Input,
        "output" => Direction::Output,
        "inout" => Direction::InOut,
        "state" => Direction::State,
        _ => {
            diags.push(bad_value(dir, "input, output, inout or state"));
            return None;
        }
    };
    let (class_attr, array) = if class.value == "array" {
        let shape = load_array_shape(p, class, &name.value, direction, diags)?;
        (
            p.attr("element").expect("checked by load_array_shape"),
            Some(shape),
        )
    } else {
        for extra in ["element", "length", "low"] {
            if let Some(a) = p.attr(extra) {
                diags.push(
                    Diagnostic::error(
                        code::E4100,
                        format!(
                            "`{extra}` is given for `{}`, which is not an array parameter",
                            name.value
                        ),
                    )
                    .at(a.span)
                    .with_label(class.span, "the class is not `array`")
                    .with_hint("write class=\"array\" element=\"<element class>\" length=\"N\", or drop the attribute"),
                );
                return None;
            }
        }
        (class, None)
    };
    let Some(class_v) = TypeClass::parse(&class_attr.value) else {
        diags.push(bad_value(
            class_attr,
            if array.is_some() {
                "bool, byte, word, dword, real or lreal (the class of every element)"
            } else {
                "bool, byte, word, dword, real, lreal, struct or array"
            },
        ));
        return None;
    };
    if array.is_some() && matches!(class_v, TypeClass::Struct | TypeClass::Lword) {
        diags.push(
            Diagnostic::error(
                code::E4101,
                format!(
                    "array `{}` has elements of class `{}`; arrays hold plain values",
                    name.value, class_attr.value
                ),
            )
            .at(class_attr.span)
            .with_hint("use bool, byte, word, dword, real or lreal elements (a reference is passed on its own)"),
        );
        return None;
    }
    if !is_iec_identifier(&name.value) {
        diags.push(
            Diagnostic::error(
                code::E4207,
                format!("parameter name `{}` is not an IEC identifier", name.value.escape_debug()),
            )
            .at(name.span)
            .with_hint("programs bind it by name: use an ASCII letter, then letters, digits and single `_`"),
        );
        return None;
    }
    if !is_abbreviation(&abbr.value) || is_reserved_name(&abbr.value) {
        diags.push(abbreviation_error(abbr, "abbreviation"));
        return None;
    }
    if c_type_of(&ty.value, class_v).is_none() {
        diags.push(
            Diagnostic::error(
                code::E4006,
                format!(
                    "type `{}` does not belong to class `{}`",
                    ty.value, class_attr.value
                ),
            )
            .at(ty.span)
            .with_label(class_attr.span, "class given here")
            .with_hint("bool: BOOL; byte: BYTE/USINT/SINT/MC_* enums; word: WORD/INT/UINT; dword: DWORD/DINT/UDINT; real: REAL; lreal: LREAL; struct: AXIS_REF/AXES_GROUP_REF (an array gives its element's class and type)"),
        );
        return None;
    }
    let required = match p.attr("required").map(|a| a.value.as_str()) {
        None | Some("false") => false,
        Some("true") => true,
        Some(_) => {
            diags.push(bad_value(p.attr("required").unwrap(), "true or false"));
            return None;
        }
    };
    let default = p.attr("default").map(|a| a.value.trim().to_string());
    if let (Some(d), Some(a)) = (&default, p.attr("default")) {
        if !matches!(direction, Direction::Output | Direction::State)
            && !is_default_literal(d, class_v)
        {
            diags.push(
                Diagnostic::error(
                    code::E4209,
                    format!("default `{}` is not a literal of class `{}`", a.value.escape_debug(), class_attr.value),
                )
                .at(a.span)
                .with_hint("bool: TRUE/FALSE/0/1; integer classes: a decimal integer in range (byte also an mc* constant); real, lreal: a decimal number; struct: no default"),
            );
            return None;
        }
    }
    if matches!(direction, Direction::Output | Direction::State) && (required || default.is_some())
    {
        let a = p.attr("required").or(p.attr("default")).unwrap();
        diags.push(
            Diagnostic::error(
                code::E4004,
                format!(
                    "output `{}` cannot be required or have a default",
                    name.value
                ),
            )
            .at(a.span)
            .with_hint("outputs are always optional variables; remove the attribute"),
        );
        return None;
    }
    Some(Param {
        name: name.value.clone(),
        abbr: abbr.value.clone(),
        direction,
        class: class_v,
        iec_type: ty.value.clone(),
        array,
        required,
        default,
        span: p.span,
    })
}

/// The `element`, `length` and `low` attributes of an array parameter (E4102 when one is missing or bad).
fn load_array_shape(
    p: &Element,
    class: &xml::Attr,
    name: &str,
    direction: Direction,
    diags: &mut Diagnostics,
) -> Option<ArrayShape> {
    let missing = ["element", "length"]
        .into_iter()
        .find(|a| p.attr(a).is_none());
    if let Some(m) = missing {
        diags.push(
            Diagnostic::error(
                code::E4102,
                format!("array parameter `{name}` lacks the attribute `{m}`"),
            )
            .at(p.span)
            .with_label(class.span, "declared as an array here")
            .with_hint("an array parameter needs element=\"<element class>\" and length=\"N\" (low=\"L\" optional, default 0)"),
        );
        return None;
    }
    let length = p.attr("length").expect("checked above");
    let len = match length.value.trim().parse::<u32>() {
        Ok(n) if (1..=MAX_ARRAY_LEN).contains(&n) => n,
        _ => {
            diags.push(
                Diagnostic::error(
                    code::E4102,
                    format!(
                        "array `{name}`: length `{}` is not a number from 1 to {MAX_ARRAY_LEN}",
                        length.value
                    ),
                )
                .at(length.span)
                .with_hint(format!(
                    "the motion library's arrays hold at most {MAX_ARRAY_LEN} values (one per identity in the group)"
                )),
            );
            return None;
        }
    };
    let low = match p.attr("low") {
        None => 0,
        Some(a) => match a.value.trim().parse::<i64>() {
            // both bounds are DINTs, as IEC array bounds are
            Ok(l) if l >= i64::from(i32::MIN) && l + i64::from(len) - 1 <= i64::from(i32::MAX) => l,
            _ => {
                diags.push(
                    Diagnostic::error(
                        code::E4102,
                        format!(
                            "array `{name}`: lower bound `{}` is not an integer whose bounds fit a DINT",
                            a.value
                        ),
                    )
                    .at(a.span)
                    .with_hint("write low=\"0\" (the default) or another integer from -2147483648 to 2147483648 - length"),
                );
                return None;
            }
        },
    };
    if direction == Direction::InOut {
        diags.push(
            Diagnostic::error(
                code::E4103,
                format!("array `{name}` cannot be an in-out parameter"),
            )
            .at(p.attr("direction").map_or(p.span, |d| d.span))
            .with_hint("pass arrays as inputs (copied in) or outputs (copied back); in-out parameters are references"),
        );
        return None;
    }
    Some(ArrayShape { len, low })
}
