//! The IL syntax tree: what the parser produces, what the ladder compiler lowers rungs into, what the
//! semantic checks and the C backend read.
//!
//! Input: built by [`crate::parser`] (IL text), [`crate::st::lower`] (ST) and the ladder compiler (PLCopen
//! XML). Output: read by [`crate::sema`], [`mod@crate::print`] and the back ends.
//!
//! Invariants: every node has the span of its source text (for lowered ladder, the span of the XML element
//! it came from); identifiers keep the user's spelling in `name` and compare by [`Ident::key`] (IEC names are
//! case-insensitive); the tree holds no resolved information (types, symbols): that is `sema`'s output.

use crate::Span;
use serde::Serialize;

/// A name as written, with its span. Compare with [`Ident::key`] or [`Ident::is`].
#[derive(Debug, Clone, Serialize)]
pub struct Ident {
    /// The identifier as the user spelled it (case kept for messages and printing; compare with
    /// [`Ident::key`]).
    pub name: String,
    /// Where the name stands in the source (for lowered PLCopen XML, the element it came from).
    pub span: Span,
}

impl Ident {
    /// An identifier with the given spelling and span.
    pub fn new(name: impl Into<String>, span: Span) -> Self {
        Ident {
            name: name.into(),
            span,
        }
    }
    /// The case-folded name used for lookups (IEC identifiers are case-insensitive).
    pub fn key(&self) -> String {
        self.name.to_ascii_uppercase()
    }
    /// Whether this name equals `other`, ignoring ASCII case (IEC 61131-3 names are case-insensitive).
    pub fn is(&self, other: &str) -> bool {
        self.name.eq_ignore_ascii_case(other)
    }
}

impl PartialEq for Ident {
    /// Equal names, ignoring case and span.
    fn eq(&self, other: &Self) -> bool {
        self.name.eq_ignore_ascii_case(&other.name)
    }
}

/// One source file's library elements, in source order.
#[derive(Debug, Clone, Default, Serialize)]
pub struct CompilationUnit {
    /// The `TYPE` blocks, POUs, configurations and global variable blocks, in source order.
    pub items: Vec<LibraryElement>,
    /// The enumerations declared under `{attribute 'to_string'}` (CODESYS, TwinCAT): `TO_STRING`
    /// of one of their values gives the value's name, not its number.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub to_string_types: Vec<Ident>,
    /// The enumerations declared under `{attribute 'strict'}` (CODESYS, TwinCAT): their values are
    /// no integers (without it, W1439 converts between them).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub strict_types: Vec<Ident>,
    /// The places of the variables of declaration-only blocks (B&R's `.fun` files) named with a
    /// keyword, an elementary type or a standard block (`Type`, `Configuration`, `string` of B&R's
    /// own libraries): accepted as names, read only in `blk(Type := x)` and `blk.Type`.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub keyword_parameters: Vec<Span>,
}

impl CompilationUnit {
    /// The type declarations of every `TYPE` block, in source order.
    pub fn type_decls(&self) -> impl Iterator<Item = &TypeDecl> {
        self.items
            .iter()
            .filter_map(|i| match i {
                LibraryElement::DataTypes(ts) => Some(ts.iter()),
                _ => None,
            })
            .flatten()
    }
}

/// One top-level element of a source file (IEC 61131-3 library element: data types, POU, configuration).
#[derive(Debug, Clone, Serialize)]
pub enum LibraryElement {
    /// A `TYPE ... END_TYPE` block with its declarations, in order.
    DataTypes(Vec<TypeDecl>),
    /// A `PROGRAM`, `FUNCTION_BLOCK` or `FUNCTION`.
    Pou(Pou),
    /// A `CONFIGURATION ... END_CONFIGURATION` with its resources, tasks and program instances.
    Configuration(Configuration),
    /// `VAR_GLOBAL` outside a configuration (accepted as an extension; it belongs to every program).
    GlobalVars(VarBlock),
    /// An action of a program or function block (CODESYS, Beremiz, RuSTy), compiled on its own so that
    /// another POU can call it (`inst.Act();`, `CAL inst.Act`). [`crate::actions::link`] merges the
    /// actions that are called from outside their POU into it and drops this element: sema and the
    /// back end never see it.
    Action(Action),
}

impl LibraryElement {
    /// Its variable blocks: a POU's, a global list, a configuration's and its resources' globals;
    /// none for data types and actions.
    pub fn var_blocks(&self) -> Vec<&VarBlock> {
        match self {
            LibraryElement::Pou(p) => p.var_blocks.iter().collect(),
            LibraryElement::GlobalVars(b) => vec![b],
            LibraryElement::Configuration(c) => c
                .globals
                .iter()
                .chain(c.resources.iter().flat_map(|r| r.globals.iter()))
                .collect(),
            LibraryElement::DataTypes(_) | LibraryElement::Action(_) => Vec::new(),
        }
    }
}

/// An action of a program or function block, lowered to IL in the scope of its POU.
#[derive(Debug, Clone, Serialize)]
pub struct Action {
    /// The POU the action belongs to.
    pub pou: Ident,
    /// The action's name.
    pub name: Ident,
    /// The action's statements (labels unique within the POU).
    pub body: Vec<IlStmt>,
    /// Temporaries the lowering of the statements needs (a `VAR_TEMP` block), if any.
    pub temps: Option<VarBlock>,
    /// For a METHOD (edition 3): its VAR_INPUT names in order. A call's arguments are then passed
    /// to the block's hidden variables `__M_<METHOD>_<name>` (positional ones in this order), see
    /// [`crate::actions`]. `None` for an action.
    pub method_inputs: Option<Vec<Ident>>,
    /// For a METHOD: its VAR_OUTPUT names in order, bound by the positional arguments after the
    /// inputs (IEC 61131-3 ed. 3, 6.6.1.4.2: a non-formal call gives every parameter of the
    /// definition in order); empty for an action.
    #[serde(skip)]
    pub method_outputs: Vec<Ident>,
    /// For a METHOD: its VAR_INPUTs that start again at each call (IEC 61131-3 ed. 3, 6.6.1.2;
    /// CODESYS, TwinCAT), each with whether it is a reference or pointer. A call that does not give
    /// one passes its initial value (the never-written `__MD_<METHOD>_<name>`), or NULL for a
    /// reference: an input left out does not keep the previous call's value or binding.
    #[serde(skip)]
    pub method_defaults: Vec<(Ident, bool)>,
    /// Diagnostics of the lowering, reported only when the action is linked (an action never called
    /// from outside its POU is checked where its POU calls it, as before).
    #[serde(skip)]
    pub diagnostics: Vec<diagnostics::Diagnostic>,
    /// For a METHOD or a property's accessor declared `PRIVATE` or `PROTECTED` (IEC 61131-3 ed.
    /// 3, 6.6.5; CODESYS "Method"): who may call it, checked by [`crate::actions::link`] at each
    /// call through an instance. `None`: PUBLIC (or INTERNAL), callable from anywhere.
    #[serde(skip)]
    pub access: Option<MemberAccess>,
}

/// The restricting access specifier of a method or property accessor, and where it is declared.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MemberAccess {
    /// `PRIVATE` or `PROTECTED`.
    pub access: Access,
    /// The function block or class that declares the member (upper-case name; a derived block's
    /// copy of an inherited member keeps its base's).
    pub owner: String,
    /// The owner's name as written.
    pub owner_name: String,
    /// The member's name as written (a property's, for its accessors).
    pub member: String,
    /// The member's name in its declaration.
    pub at: Span,
    /// `METHOD` or `PROPERTY`.
    pub what: &'static str,
}

// ---------------------------------------------------------------- types

/// A type as written in a declaration.
#[derive(Debug, Clone, Serialize)]
pub enum TypeRef {
    /// An elementary type (`INT`), a standard or user FB type (`TON`), or a user data type.
    Named(Ident),
    /// `STRING`, `STRING[20]`, `WSTRING(10)`.
    String {
        /// `WSTRING` (UTF-16 characters) rather than `STRING` (bytes).
        wide: bool,
        /// The declared maximum length in characters (`STRING[20]` -> 20); `None` takes the default (254).
        length: Option<u32>,
        /// The whole type text, from the keyword to the closing bracket.
        span: Span,
    },
    /// `ARRAY [1..10, 0..3] OF INT`.
    Array {
        /// One `lower..upper` range per dimension, in order.
        dims: Vec<ArrayDim>,
        /// The element type after `OF`.
        element: Box<TypeRef>,
        /// The whole type text, from `ARRAY` to the element type.
        span: Span,
    },
    /// `INT (0..100)`.
    Subrange {
        /// The elementary integer type the range restricts (`INT` in `INT (0..100)`).
        base: Ident,
        /// The smallest allowed value (inclusive).
        lower: i128,
        /// The largest allowed value (inclusive).
        upper: i128,
        /// The whole type text.
        span: Span,
    },
    /// An inline enumeration `(red, green)`, also with fixed values `(zero, alfa := 10, bravo)` as
    /// CODESYS documents for implicit enumerations.
    Enum {
        /// The values in order.
        values: Vec<EnumValue>,
        /// From `(` to `)`.
        span: Span,
    },
    /// A reference: `REF_TO INT` (IEC 61131-3 edition 3, 6.4.4.10), `POINTER TO INT` or
    /// `REFERENCE TO INT` (CODESYS, TwinCAT). See [`RefKind`] for how the three differ.
    Ref {
        /// How the reference was written (what its uses mean).
        kind: RefKind,
        /// The type referred to.
        target: Box<TypeRef>,
        /// The whole type text, from the keyword to the end of the target type.
        span: Span,
    },
}

/// How a reference type was written. All three are one thing once compiled (the address of a
/// variable, or NULL); they differ in the source: `REF_TO` and `POINTER TO` are read with `r^` and
/// set with `REF(x)` / `ADR(x)`, a `REFERENCE TO` variable is read and written as the variable it
/// refers to (the ST lowering adds the `^`) and is set with `r REF= x` or by passing `x` to it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum RefKind {
    /// `REF_TO T` (edition 3).
    RefTo,
    /// `POINTER TO T` (CODESYS, TwinCAT).
    Pointer,
    /// `REFERENCE TO T` (CODESYS, TwinCAT): dereferenced where it is used.
    Reference,
}

impl RefKind {
    /// The keywords as written (`REF_TO`, `POINTER TO`, `REFERENCE TO`).
    pub fn keyword(self) -> &'static str {
        match self {
            RefKind::RefTo => "REF_TO",
            RefKind::Pointer => "POINTER TO",
            RefKind::Reference => "REFERENCE TO",
        }
    }
}

impl TypeRef {
    /// The source span of the type text (the name's span for [`TypeRef::Named`]).
    pub fn span(&self) -> Span {
        match self {
            TypeRef::Named(i) => i.span,
            TypeRef::String { span, .. }
            | TypeRef::Array { span, .. }
            | TypeRef::Subrange { span, .. }
            | TypeRef::Enum { span, .. }
            | TypeRef::Ref { span, .. } => *span,
        }
    }
}

/// One dimension of an `ARRAY` type: `1..10`. Bounds are inclusive; sema checks `lower <= upper`.
#[derive(Debug, Clone, Serialize)]
pub struct ArrayDim {
    /// The first valid index (inclusive).
    pub lower: i128,
    /// The last valid index (inclusive).
    pub upper: i128,
    /// The `lower..upper` text.
    pub span: Span,
}

impl ArrayDim {
    /// The bound both ends of a variable-length dimension `*` hold (`ARRAY [*] OF T`, IEC 61131-3
    /// edition 3, 6.5.3): the bounds are the caller's, known at run time only. Such a dimension is
    /// compiled only in a VAR_IN_OUT of an ST FUNCTION, FUNCTION_BLOCK or METHOD
    /// (`st::varlen` replaces it before sema); sema reports any other as E1072.
    pub const VARIABLE: i128 = i128::MIN;

    /// Whether this is a variable-length dimension `*`.
    pub fn is_variable(&self) -> bool {
        self.lower == Self::VARIABLE && self.upper == Self::VARIABLE
    }
}

/// `TYPE name : ... ; END_TYPE` entry.
#[derive(Debug, Clone, Serialize)]
pub struct TypeDecl {
    /// The type name being declared.
    pub name: Ident,
    /// What the name stands for: an alias/subrange/array, a structure or an enumeration.
    pub def: TypeDef,
    /// A structure written `UNION ... END_UNION` (CODESYS, TwinCAT): its members share one storage.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub union: bool,
    /// From the name to the terminating `;` (or `END_STRUCT;`).
    pub span: Span,
}

/// The right-hand side of a `TYPE` entry (IEC 61131-3 derived data types, 2.3.3).
#[derive(Debug, Clone, Serialize)]
pub enum TypeDef {
    /// `T : INT := 5;`, `T : ARRAY [..] OF INT := [...]`, `T : INT (0..9)`, `T : STRING[8]`.
    Alias {
        /// The type the new name stands for.
        ty: TypeRef,
        /// The default initial value of variables of this type (`:= 5`), if written.
        init: Option<Initializer>,
    },
    /// `STRUCT a : INT; b : BOOL; END_STRUCT`: a structure with named fields.
    Struct {
        /// The fields in declaration order (each with its type and optional initial value).
        fields: Vec<VarDecl>,
    },
    /// `(red, green := 5, blue) := green`: an enumeration with its values.
    Enum {
        /// The values in declaration order.
        values: Vec<EnumValue>,
        /// The default value (`:= green` after the list), if written; otherwise the first value.
        init: Option<Ident>,
    },
}

/// One value of an enumerated type, `red` or `red := 3`.
#[derive(Debug, Clone, Serialize)]
pub struct EnumValue {
    /// The value's name.
    pub name: Ident,
    /// `red := 3` (an extension most tools accept).
    pub value: Option<i128>,
}

// ---------------------------------------------------------------- literals and operands

/// A constant written in the source: `5`, `INT#5`, `2.5`, `TRUE`, `T#1s`, `'text'`.
#[derive(Debug, Clone, Serialize)]
pub struct Literal {
    /// The decoded value.
    pub kind: LiteralKind,
    /// The `INT#` / `REAL#` / `BOOL#` prefix of a typed literal, if written.
    pub type_prefix: Option<Ident>,
    /// The literal as written, prefix included.
    pub span: Span,
}

/// The decoded value of a literal (IEC 61131-3 2.2); units are fixed: nanoseconds for durations and times
/// of day.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum LiteralKind {
    /// Any integer literal (decimal, `2#`, `8#`, `16#`), sign applied.
    Int(i128),
    /// `2.5`, `1.0E-3`: any real literal.
    Real(f64),
    /// `TRUE` / `FALSE`, also after a prefix (`BOOL#TRUE`; `BOOL#1` is an `Int` with a `BOOL` prefix).
    Bool(bool),
    /// `T#`/`TIME#`/`LTIME#` duration in nanoseconds (sign applied).
    Duration(i128),
    /// `D#`/`DATE#`: days since 1970-01-01.
    Date(i64),
    /// `TOD#`/`TIME_OF_DAY#`: nanoseconds since midnight.
    TimeOfDay(i64),
    /// `DT#`/`DATE_AND_TIME#`: nanoseconds since 1970-01-01T00:00:00.
    DateAndTime(i128),
    /// `'...'` (wide = false) or `"..."` (wide = true), `$` escapes already decoded.
    String {
        /// `true` for a `"..."` WSTRING literal, `false` for a `'...'` STRING literal.
        wide: bool,
        /// The characters with `$` escapes decoded (`'$N'` holds a newline).
        value: String,
    },
}

/// `%IX0.1`, `%QW3`, `%MD10`, `%I*` (location left open).
#[derive(Debug, Clone, Serialize)]
pub struct DirectAddress {
    /// The memory area: `I` (inputs), `Q` (outputs) or `M` (markers).
    pub area: Area,
    /// The size letter: `X` (or none), `B`, `W`, `D`, `L`.
    pub size: AddressSize,
    /// The dotted numbers (`%IX1.2.3` -> [1, 2, 3]); empty for `%I*`.
    pub path: Vec<u32>,
    /// The `%...` text.
    pub span: Span,
}

/// The area letter of a direct address (IEC 61131-3 2.4.1.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum Area {
    /// `%I`: an input of the process image.
    Input,
    /// `%Q`: an output of the process image.
    Output,
    /// `%M`: a memory (marker) location.
    Memory,
}

/// The size letter of a direct address (IEC 61131-3 2.4.1.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum AddressSize {
    /// No size letter: a bit (`%I0.1`), as `X`.
    Bit,
    /// `B`: 8 bits.
    Byte,
    /// `W`: 16 bits.
    Word,
    /// `D`: 32 bits.
    DWord,
    /// `L`: 64 bits.
    LWord,
}

/// A variable access: `x`, `inst.Q`, `arr[3]`, `s.a[i].b`.
#[derive(Debug, Clone, Serialize)]
pub struct VarRef {
    /// The variable (or FB instance) named first.
    pub base: Ident,
    /// The `.field` and `[index]` parts after the base, in order.
    pub accessors: Accessors,
    /// The whole access text.
    pub span: Span,
}

/// The `.field` and `[index]` parts of a [`VarRef`]: a `Vec<Accessor>` held in one pointer, and no
/// allocation when empty (most operands are plain variables). It reads as a `Vec` (`Deref`); writing
/// through `DerefMut` (`push`, `pop` ...) allocates the list if it has none. `Debug` and `Serialize` print
/// the list, as a `Vec` would. Build one with `Vec::into` or [`Accessors::default`] (empty).
#[derive(Clone, Default)]
// The box is the point: one word in every operand instead of a `Vec`'s three (or a boxed slice's two); the
// extra allocation is paid only by the accesses that have parts.
#[allow(clippy::box_collection)]
pub struct Accessors(Option<Box<Vec<Accessor>>>);

/// What an empty [`Accessors`] reads as.
static NO_ACCESSORS: Vec<Accessor> = Vec::new();

impl Accessors {
    /// The parts as a `Vec`, taking them out.
    pub fn into_vec(self) -> Vec<Accessor> {
        self.0.map(|b| *b).unwrap_or_default()
    }
}

impl std::ops::Deref for Accessors {
    type Target = Vec<Accessor>;
    fn deref(&self) -> &Vec<Accessor> {
        self.0.as_deref().unwrap_or(&NO_ACCESSORS)
    }
}

impl std::ops::DerefMut for Accessors {
    fn deref_mut(&mut self) -> &mut Vec<Accessor> {
        self.0.get_or_insert_with(Box::default)
    }
}

impl From<Vec<Accessor>> for Accessors {
    fn from(v: Vec<Accessor>) -> Self {
        if v.is_empty() {
            Accessors(None)
        } else {
            Accessors(Some(Box::new(v)))
        }
    }
}

impl FromIterator<Accessor> for Accessors {
    fn from_iter<I: IntoIterator<Item = Accessor>>(iter: I) -> Self {
        iter.into_iter().collect::<Vec<_>>().into()
    }
}

impl<'a> IntoIterator for &'a Accessors {
    type Item = &'a Accessor;
    type IntoIter = std::slice::Iter<'a, Accessor>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl<'a> IntoIterator for &'a mut Accessors {
    type Item = &'a mut Accessor;
    type IntoIter = std::slice::IterMut<'a, Accessor>;
    fn into_iter(self) -> Self::IntoIter {
        match &mut self.0 {
            Some(v) => v.iter_mut(),
            None => [].iter_mut(),
        }
    }
}

impl std::fmt::Debug for Accessors {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Debug::fmt(&**self, f)
    }
}

impl Serialize for Accessors {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        (**self).serialize(s)
    }
}

/// One step of a variable access after its base name.
#[derive(Debug, Clone, Serialize)]
pub enum Accessor {
    /// `.name`: a structure field or an FB instance's input/output.
    Field(Ident),
    /// `[i, j]`: array subscripts, one per dimension.
    Index(Vec<Operand>),
    /// `^`: the variable a reference or pointer refers to (edition 3 `r^`, CODESYS `p^`); the span is
    /// the `^` (for a `REFERENCE TO` variable, the name: the lowering adds it).
    Deref(Span),
}

/// The partial access a field name stands for (IEC 61131-3 3rd edition, 6.5.2.2 "partial access of ANY_BIT
/// variables"): `x.3` and `x.%X3` name bit 3, `x.%B1` byte 1, `x.%W0` word 0, `x.%D1` double word 1,
/// `x.%L0` long word 0 of an integer or bit-string variable. The parsers keep such an access as an
/// [`Accessor::Field`] whose name is the text after the dot (`3`, `%X3`); this reads it back. An index
/// too large for `u32` is `u32::MAX` (out of range for every type). `None`: an ordinary field name.
pub fn partial_access(field: &str) -> Option<(AddressSize, u32)> {
    let (size, digits) = match field.strip_prefix('%') {
        Some(rest) => {
            let mut chars = rest.chars();
            let size = match chars.next()?.to_ascii_uppercase() {
                'X' => AddressSize::Bit,
                'B' => AddressSize::Byte,
                'W' => AddressSize::Word,
                'D' => AddressSize::DWord,
                'L' => AddressSize::LWord,
                _ => return None,
            };
            (size, chars.as_str())
        }
        None => (AddressSize::Bit, field),
    };
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    Some((size, digits.parse::<u32>().unwrap_or(u32::MAX)))
}

impl AddressSize {
    /// The width in bits of a partial access or direct address of this size (`X`: 1 ... `L`: 64).
    pub fn bits(self) -> u32 {
        match self {
            AddressSize::Bit => 1,
            AddressSize::Byte => 8,
            AddressSize::Word => 16,
            AddressSize::DWord => 32,
            AddressSize::LWord => 64,
        }
    }
}

/// What an IL instruction works on.
///
/// Literals and typed enumerated values are boxed: they are rarer than variables, and inline their 16-byte
/// aligned `i128` values and second name would make every operand (and so every statement of a body)
/// larger; an operand has the size of a [`VarRef`].
#[derive(Debug, Clone, Serialize)]
pub enum Operand {
    /// A constant: `LD 5`, `ADD T#1s` (build one with [`Operand::literal`]).
    Literal(Box<Literal>),
    /// A (possibly structured or indexed) variable: `LD x`, `ST inst.IN`.
    Var(VarRef),
    /// A direct address: `LD %IX0.1`.
    Address(DirectAddress),
    /// An enumerated value written with its type, `Color#red` (a plain `red` parses as a `Var`; build one
    /// with [`Operand::enum_value`]).
    EnumValue(Box<EnumOperand>),
    /// A reference value: `REF(x)` / `ADR(x)` (the address of variable `x`) or `NULL` (no variable).
    Ref(Box<RefOperand>),
    /// `SIZEOF(x)` / `SIZEOF(T)` (CODESYS, TwinCAT): the bytes variable `x` or type `T` takes in the
    /// generated C (a UDINT).
    SizeOf(Box<SizeOfOperand>),
    /// `MEMCPY`, `MEMMOVE`, `MEMSET`, `MEMCMP` (Tc2_System; CODESYS SysMem's `SysMemCpy` ...) on
    /// the variables that `ADR(x)` arguments name, bounded by their sizes.
    Mem(Box<MemCall>),
}

/// Which memory function a [`MemCall`] is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum MemFunc {
    /// `MEMCPY(destAddr, srcAddr, n)`.
    Copy,
    /// `MEMMOVE(destAddr, srcAddr, n)`.
    Move,
    /// `MEMSET(destAddr, fillByte, n)`.
    Set,
    /// `MEMCMP(pBuf1, pBuf2, n)`: 0 when equal, -1 or 1 as the first differing byte compares.
    Compare,
}

impl MemFunc {
    /// The Tc2_System name.
    pub fn name(self) -> &'static str {
        match self {
            MemFunc::Copy => "MEMCPY",
            MemFunc::Move => "MEMMOVE",
            MemFunc::Set => "MEMSET",
            MemFunc::Compare => "MEMCMP",
        }
    }
}

/// The payload of [`Operand::Mem`]: a memory function on known variables.
#[derive(Debug, Clone, Serialize)]
pub struct MemCall {
    /// Which function.
    pub func: MemFunc,
    /// The variable the first pointer argument points to (`a` of `ADR(a)`, an element or field).
    pub dest: VarRef,
    /// The variable of the second pointer argument (MEMCPY, MEMMOVE, MEMCMP).
    pub src: Option<VarRef>,
    /// `dest` (and `src`) is a pointer variable (`POINTER TO`/`REF_TO`) passed as it is, whose
    /// value is the address: the call works on the bytes from where it points to the end of the
    /// variable it was made from (a bounded reference carries both). False: `ADR(dest)`.
    pub through_pointer: [bool; 2],
    /// A byte offset added to `ADR(dest)` / `ADR(src)` (`MEMMOVE(ADR(buf) + n, ...)`, a plain
    /// operand): the call works on the bytes of the variable from that offset on.
    #[serde(skip_serializing_if = "no_offsets")]
    pub offsets: [Option<Operand>; 2],
    /// The fill byte (MEMSET) and the byte count, plain operands.
    pub fill: Option<Operand>,
    /// The number of bytes.
    pub count: Operand,
    /// The whole call text.
    pub span: Span,
}

/// Whether a [`MemCall`] has no offsets (left out of the AST's JSON, as before offsets).
fn no_offsets(o: &[Option<Operand>; 2]) -> bool {
    o.iter().all(Option::is_none)
}

/// The payload of [`Operand::SizeOf`].
#[derive(Debug, Clone, Serialize)]
pub struct SizeOfOperand {
    /// The variable (an element or field too) or, as a bare name that names no variable, the type
    /// whose size is taken.
    pub of: VarRef,
    /// The whole `SIZEOF(x)` text.
    pub span: Span,
}

/// The payload of [`Operand::Ref`]: the address of a variable, or NULL.
#[derive(Debug, Clone, Serialize)]
pub struct RefOperand {
    /// The variable referred to (`x` of `REF(x)`, an element or field too); `None` for `NULL` (and a
    /// pointer set to `0`).
    pub of: Option<VarRef>,
    /// The whole `REF(x)` / `ADR(x)` / `NULL` text.
    pub span: Span,
    /// Made for one call only: the address of an array passed to a FUNCTION's or METHOD's
    /// `ARRAY [*]` in-out (`st::varlen`), which nothing reads after the call; it may then refer to
    /// a variable that lives for one call (a FUNCTION's, a VAR_TEMP, a method's VAR, a VAR_IN_OUT).
    #[serde(skip)]
    pub call_scoped: bool,
    /// Written `ADR(x)` (CODESYS, TwinCAT), not `REF(x)`: it may take the address of a
    /// FUNCTION's variable, valid during the call (`sema::refs`).
    #[serde(skip)]
    pub address_of: bool,
}

/// An enumerated value written with its type, `Color#red`: the payload of [`Operand::EnumValue`].
#[derive(Debug, Clone, Serialize)]
pub struct EnumOperand {
    /// The enumerated type before `#`.
    pub type_name: Ident,
    /// The value after `#`.
    pub value: Ident,
    /// The whole `Type#value` text.
    pub span: Span,
}

impl Operand {
    /// The operand's source span.
    pub fn span(&self) -> Span {
        match self {
            Operand::Literal(l) => l.span,
            Operand::Var(v) => v.span,
            Operand::Address(a) => a.span,
            Operand::EnumValue(e) => e.span,
            Operand::Ref(r) => r.span,
            Operand::SizeOf(s) => s.span,
            Operand::Mem(m) => m.span,
        }
    }
    /// A literal operand.
    pub fn literal(l: Literal) -> Operand {
        Operand::Literal(Box::new(l))
    }
    /// A typed enumerated value, `type_name#value`, spanning `span`.
    pub fn enum_value(type_name: Ident, value: Ident, span: Span) -> Operand {
        Operand::EnumValue(Box::new(EnumOperand {
            type_name,
            value,
            span,
        }))
    }
    /// A reference to `of` (`REF(x)`; `NULL` when `of` is `None`), spanning `span`: neither made
    /// for one call ([`RefOperand::call_scoped`]) nor written `ADR(x)` ([`RefOperand::address_of`]).
    pub fn reference(of: Option<VarRef>, span: Span) -> Operand {
        Operand::Ref(Box::new(RefOperand {
            of,
            span,
            call_scoped: false,
            address_of: false,
        }))
    }
}

// ---------------------------------------------------------------- declarations

/// The section keyword of a variable block (IEC 61131-3 2.4.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum VarKind {
    /// `VAR`: a local variable, kept between calls in programs and FBs.
    Local,
    /// `VAR_INPUT`: an input parameter.
    Input,
    /// `VAR_OUTPUT`: an output parameter.
    Output,
    /// `VAR_IN_OUT`: a parameter passed by reference.
    InOut,
    /// `VAR_TEMP`: a local variable reinitialised at each call.
    Temp,
    /// `VAR_GLOBAL`: a global variable (in a configuration, resource or at top level).
    Global,
    /// `VAR_EXTERNAL`: a reference to a global variable declared elsewhere.
    External,
}

/// `VAR_INPUT CONSTANT RETAIN ... END_VAR`.
#[derive(Debug, Clone, Serialize)]
pub struct VarBlock {
    /// The name of a CODESYS/TwinCAT global variable list (`<globalVars name="GVL">`), whose members
    /// are also reachable qualified (`GVL.x`); `None` for every IEC declaration block.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<Ident>,
    /// The section keyword (`VAR`, `VAR_INPUT`, ...).
    pub kind: VarKind,
    /// `CONSTANT`: the variables cannot be written.
    pub constant: bool,
    /// `RETAIN`: the variables keep their values across a warm restart.
    pub retain: bool,
    /// The declared variables, one per name, in order.
    pub vars: Vec<VarDecl>,
    /// From the section keyword to `END_VAR`.
    pub span: Span,
    /// The access specifier of a class's or function block's variable block (IEC 61131-3 ed. 3,
    /// 6.6.5: `VAR PUBLIC`, `VAR PRIVATE` ...; a class's `VAR` without one is PROTECTED): a
    /// PRIVATE or PROTECTED variable is not reachable as `inst.x` from another POU, a PUBLIC
    /// one is (no W1412). `None` for every other block (a function block's plain `VAR`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub access: Option<Access>,
}

/// A restricting access specifier of a variable block (IEC 61131-3 ed. 3, 6.6.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Access {
    /// `PUBLIC`, or `INTERNAL` (the namespace is the whole project): reachable from anywhere.
    Public,
    /// `PRIVATE`: only inside the class (or function block) that declares it.
    Private,
    /// `PROTECTED`: inside the class and the classes that extend it.
    Protected,
}

impl Access {
    /// The keyword (`PRIVATE`, `PROTECTED`).
    pub fn keyword(self) -> &'static str {
        match self {
            Access::Public => "PUBLIC",
            Access::Private => "PRIVATE",
            Access::Protected => "PROTECTED",
        }
    }
}

impl VarBlock {
    /// A plain `VAR` block (no list name, not CONSTANT, not RETAIN) of `vars`, as the lowerings
    /// add for the hidden variables they introduce (SFC step flags, action flags, temporaries).
    pub fn locals(vars: Vec<VarDecl>, span: Span) -> VarBlock {
        VarBlock {
            access: None,
            name: None,
            kind: VarKind::Local,
            constant: false,
            retain: false,
            vars,
            span,
        }
    }
}

/// One declared name (`a, b : INT := 3;` yields two `VarDecl`s sharing type and initial value).
#[derive(Debug, Clone, Serialize)]
pub struct VarDecl {
    /// The declared name.
    pub name: Ident,
    /// `AT %IX0.1`.
    pub location: Option<DirectAddress>,
    /// The declared type.
    pub ty: TypeRef,
    /// The initial value (`:= 3`), if written.
    pub init: Option<Initializer>,
    /// `R_EDGE` / `F_EDGE` after the type (edge-triggered BOOL input of a function block).
    pub edge: Option<Edge>,
    /// The declaration text, from the name (or the first name of a list) to the `;`.
    pub span: Span,
}

/// The edge qualifier of an input declaration: the input reads TRUE only in the call in which its value
/// rose (`R_EDGE`) or fell (`F_EDGE`), as if an implicit R_TRIG/F_TRIG instance filtered it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Edge {
    /// `R_EDGE`: TRUE in the call in which the input rose.
    Rising,
    /// `F_EDGE`: TRUE in the call in which the input fell.
    Falling,
}

impl Edge {
    /// The keyword: `R_EDGE` or `F_EDGE`.
    pub fn keyword(self) -> &'static str {
        match self {
            Edge::Rising => "R_EDGE",
            Edge::Falling => "F_EDGE",
        }
    }
}

impl VarDecl {
    /// A declaration without location or initial value. Code that synthesises declarations (temporaries,
    /// hidden state) uses this and the `with_*` builders, so new fields of `VarDecl` do not break it.
    pub fn new(name: Ident, ty: TypeRef, span: Span) -> Self {
        VarDecl {
            name,
            location: None,
            ty,
            init: None,
            edge: None,
            span,
        }
    }

    /// Sets the initial value.
    pub fn with_init(mut self, init: Initializer) -> Self {
        self.init = Some(init);
        self
    }

    /// Sets the `R_EDGE` / `F_EDGE` qualifier.
    pub fn with_edge(mut self, edge: Edge) -> Self {
        self.edge = Some(edge);
        self
    }

    /// Sets the `AT %...` location.
    pub fn with_location(mut self, location: DirectAddress) -> Self {
        self.location = Some(location);
        self
    }
}

/// The initial value of a declaration (`:= ...`), IEC 61131-3 2.4.2.
#[derive(Debug, Clone, Serialize)]
pub enum Initializer {
    /// A literal, an enum value, or a named constant.
    Value(Operand),
    /// `[1, 2, 3(0)]`: elements with optional repeat counts.
    Array(Vec<ArrayInitElement>, Span),
    /// `(a := 1, b := TRUE)`; also FB instance parameter initialisation `tmr : TON := (PT := T#1s)`.
    Struct(Vec<(Ident, Initializer)>, Span),
}

/// One element of an array initialiser: `5` or `3(0)` (three zeros).
#[derive(Debug, Clone, Serialize)]
pub struct ArrayInitElement {
    /// The repeat count `n` of `n(value)`; `None` for a single element.
    pub repeat: Option<u32>,
    /// The value (repeated `repeat` times).
    pub value: Initializer,
}

// ---------------------------------------------------------------- POUs

/// The kind of program organisation unit (IEC 61131-3 2.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum PouKind {
    /// `PROGRAM`: instantiated by a configuration, or run as the implicit main program.
    Program,
    /// `FUNCTION_BLOCK`: has state; called through instances with `CAL`.
    FunctionBlock,
    /// `FUNCTION`: no state; returns one value through the current result.
    Function,
}

/// A program organisation unit (POU): header, variable blocks and IL body.
#[derive(Debug, Clone, Serialize)]
pub struct Pou {
    /// `PROGRAM`, `FUNCTION_BLOCK` or `FUNCTION`.
    pub kind: PouKind,
    /// The POU name (the type name for function blocks and programs).
    pub name: Ident,
    /// The result type of a FUNCTION.
    pub return_type: Option<TypeRef>,
    /// The `VAR*` blocks in source order.
    pub var_blocks: Vec<VarBlock>,
    /// The instruction list: for lowered LD/FBD networks, the rungs one after the other.
    pub body: Vec<IlStmt>,
    /// From the POU keyword to `END_*`.
    pub span: Span,
    /// Declared `CLASS ... END_CLASS` (IEC 61131-3 ed. 3, 6.6.5): a function block without a body,
    /// whose instances are not called (`inst();` is E1018), only their methods.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub class: bool,
}

/// A body is a list of labels and instructions (a label may stand alone on its line, or before `END_*`).
#[derive(Debug, Clone, Serialize)]
pub enum IlStmt {
    /// `name:` - a jump target.
    Label(Ident),
    /// An IL instruction.
    Instr(Instruction),
}

/// One IL instruction with its span.
#[derive(Debug, Clone, Serialize)]
pub struct Instruction {
    /// What the instruction does.
    pub kind: InstrKind,
    /// The instruction's text (for a deferred operator, from the operator to the closing `)`).
    pub span: Span,
}

/// Dropping an instruction frees its nested lists (`ADD( ... )` inside `AND( ...)` ...) with a loop:
/// they nest as deep as the source does, and the compiler's recursive drop would overflow the stack.
impl Drop for Instruction {
    fn drop(&mut self) {
        let InstrKind::Deferred { body, .. } = &mut self.kind else {
            return;
        };
        let mut lists = vec![std::mem::take(body)];
        while let Some(list) = lists.pop() {
            for mut s in list {
                if let IlStmt::Instr(Instruction {
                    kind: InstrKind::Deferred { body, .. },
                    ..
                }) = &mut s
                {
                    lists.push(std::mem::take(body));
                }
            }
        }
    }
}

/// Simple operators, with the `N` modifier folded into `negate` (`LDN`, `ANDN`, `STN`, `&N`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum Op {
    /// `LD x`: load x into the current result (`LDN`: its negation).
    Ld,
    /// `ST x`: store the current result into x (`STN`: its negation).
    St,
    /// `S x`: set x if the current result is TRUE.
    S,
    /// `R x`: reset x if the current result is TRUE.
    R,
    /// `AND x` / `&`: current result AND x (`ANDN`: AND NOT x); a series contact in a rung.
    And,
    /// `OR x`: current result OR x (`ORN`: OR NOT x); a parallel branch in a rung.
    Or,
    /// `XOR x`: current result XOR x.
    Xor,
    /// `NOT` (no operand): invert the current result.
    Not,
    /// `ADD x`: current result + x.
    Add,
    /// `SUB x`: current result - x.
    Sub,
    /// `MUL x`: current result * x.
    Mul,
    /// `DIV x`: current result / x.
    Div,
    /// `MOD x`: remainder of current result / x.
    Mod,
    /// `GT x`: current result > x (BOOL result).
    Gt,
    /// `GE x`: current result >= x.
    Ge,
    /// `EQ x`: current result = x.
    Eq,
    /// `NE x`: current result <> x.
    Ne,
    /// `LE x`: current result <= x.
    Le,
    /// `LT x`: current result < x.
    Lt,
}

/// The `C` / `CN` modifier of JMP, CAL, RET.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Condition {
    /// No modifier: `JMP`, `CAL`, `RET`.
    Always,
    /// `JMPC`: if the current result is TRUE.
    IfTrue,
    /// `JMPCN` (also `JMPNC` in some dialects): if the current result is FALSE.
    IfFalse,
}

/// The FB input operators `S1 R1 CLK CU CD PV IN PT`: store the current result into that input of the
/// instance and invoke it. (`S`/`R` with an FB instance operand are parsed as [`Op::S`]/[`Op::R`]; sema
/// turns them into this when the operand is an instance with an `S`/`R` input.)
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum FbInputOp {
    /// `S1 inst`: set-dominant input of SR.
    S1,
    /// `R1 inst`: reset-dominant input of RS.
    R1,
    /// `CLK inst`: the clock input of R_TRIG / F_TRIG.
    Clk,
    /// `CU inst`: count-up input of CTU / CTUD.
    Cu,
    /// `CD inst`: count-down input of CTD / CTUD.
    Cd,
    /// `PV inst`: preset value of a counter.
    Pv,
    /// `IN inst`: the input of a timer (TON, TOF, TP).
    In,
    /// `PT inst`: the preset time of a timer.
    Pt,
}

impl FbInputOp {
    /// The input parameter the operator writes.
    pub fn input_name(self) -> &'static str {
        match self {
            FbInputOp::S1 => "S1",
            FbInputOp::R1 => "R1",
            FbInputOp::Clk => "CLK",
            FbInputOp::Cu => "CU",
            FbInputOp::Cd => "CD",
            FbInputOp::Pv => "PV",
            FbInputOp::In => "IN",
            FbInputOp::Pt => "PT",
        }
    }
}

/// What an IL instruction does (IEC 61131-3 2.8.1, table 52): the operator with its modifiers and operands.
#[derive(Debug, Clone, Serialize)]
pub enum InstrKind {
    /// `LD x`, `ANDN y`, `ADD 5`, `NOT`, `S q` ...; `operand` is `None` only for `NOT` and for `S`/`R`
    /// written without an operand (a diagnostic in sema).
    Simple {
        /// The operator.
        op: Op,
        /// The `N` modifier (`ANDN`, `LDN`, `STN`).
        negate: bool,
        /// The operand after the operator.
        operand: Option<Operand>,
    },
    /// `AND( operand` ... `)`: the operator applied to the current result and the value of the nested list.
    /// The optional operand on the opening line is an implicit `LD` that starts the nested list.
    Deferred {
        /// The operator applied when the `)` closes.
        op: Op,
        /// The `N` modifier (`ANDN(`).
        negate: bool,
        /// The operand written on the opening line (an implicit `LD`); boxed, as a deferred operator is
        /// rarer than a simple one (see [`IlStmt`]'s size).
        operand: Option<Box<Operand>>,
        /// The nested instructions up to the matching `)`.
        body: Vec<IlStmt>,
        /// The span of the closing `)`.
        close: Span,
    },
    /// `JMP label`, `JMPC label`, `JMPCN label`.
    Jump {
        /// Unconditional, or on a TRUE/FALSE current result.
        cond: Condition,
        /// The target label.
        label: Ident,
    },
    /// `RET`, `RETC`, `RETCN`: leave the POU.
    Return {
        /// Unconditional, or on a TRUE/FALSE current result.
        cond: Condition,
    },
    /// `CAL inst(...)`, `CALC inst`, `CALCN inst(IN := x, Q => y)`.
    Call {
        /// Unconditional, or on a TRUE/FALSE current result.
        cond: Condition,
        /// The FB instance called (boxed: a call is rarer than a simple instruction, see [`IlStmt`]'s size).
        instance: Box<VarRef>,
        /// The parameter list, if any.
        args: CallArgs,
    },
    /// A function call as an operator: `SEL x, y` (the current result is the first argument) or `LIMIT(MN := 0, ...)`.
    FunctionCall {
        /// The function's name.
        name: Ident,
        /// Arguments after the current result (the current result is the first input); boxed, see
        /// [`IlStmt`]'s size.
        args: Box<CallArgs>,
    },
    /// `S1 inst`, `IN tmr`, `PT tmr` ...
    FbInput {
        /// Which input the current result is stored into.
        op: FbInputOp,
        /// The FB instance.
        instance: VarRef,
    },
    /// The extension `FUNC Name()`: call of an embedded C function (see `param-passing`).
    EmbeddedC {
        /// The C function's name.
        name: Ident,
    },
}

/// The parameter list of `CAL` or of a function call.
#[derive(Debug, Clone, Serialize)]
pub enum CallArgs {
    /// No parentheses or empty ones: `CAL inst`, `CAL inst()`.
    None,
    /// Positional arguments.
    NonFormal(Vec<Operand>),
    /// `name := value`, `name => var`, `NOT name => var`.
    Formal(Vec<FormalArg>),
}

/// One formal parameter assignment of a call: `IN := x`, `Q => y`, `NOT Q => y`.
#[derive(Debug, Clone, Serialize)]
pub struct FormalArg {
    /// The parameter's name.
    pub name: Ident,
    /// Input (`:=`) or output (`=>`) assignment.
    pub dir: ArgDir,
    /// The value passed, or the variable an output is written to.
    pub value: Operand,
    /// The whole `name := value` text.
    pub span: Span,
}

/// Which way a formal parameter passes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum ArgDir {
    /// `name := value`
    Input,
    /// `name => var`; `negated` for `NOT name => var`.
    Output {
        /// `NOT name => var`: the inverted output is stored.
        negated: bool,
    },
}

// ---------------------------------------------------------------- configurations

/// `CONFIGURATION name ... END_CONFIGURATION` (IEC 61131-3 2.7.1).
#[derive(Debug, Clone, Serialize)]
pub struct Configuration {
    /// The configuration's name.
    pub name: Ident,
    /// `VAR_GLOBAL` blocks at configuration level.
    pub globals: Vec<VarBlock>,
    /// A configuration written without `RESOURCE` gets one resource named after the configuration.
    pub resources: Vec<Resource>,
    /// The access paths of its `VAR_ACCESS` blocks (IEC 61131-3 2.7.1 / 6.8.2).
    pub access: Vec<AccessDecl>,
    /// From `CONFIGURATION` to `END_CONFIGURATION`.
    pub span: Span,
}

/// One access path of a `VAR_ACCESS` block: `name : resource.program.fb.var : TYPE READ_WRITE;`
/// (or `name : resource.%IX1.1 : BOOL;`). The outside (the host, the trace) reaches the variable by
/// `name`; READ_ONLY (the default) refuses writes.
#[derive(Debug, Clone, Serialize)]
pub struct AccessDecl {
    /// The access name.
    pub name: Ident,
    /// The path's names, the resource's included when written (`res.prog.x` or `prog.x` or `g`).
    pub path: Vec<Ident>,
    /// Constant subscripts of the path's names (`Values[2]`, `prog.State.Samples[3]`): (the
    /// name's position in `path`, its subscripts, where they are written), in order.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub subscripts: Vec<(usize, Vec<i128>, Span)>,
    /// The direct address of a path to one (`res.%IX1.1`).
    pub address: Option<DirectAddress>,
    /// The declared type's name (a non-generic type).
    pub type_name: Ident,
    /// READ_ONLY (written or by default) rather than READ_WRITE.
    pub read_only: bool,
    /// The whole entry.
    pub span: Span,
}

/// `RESOURCE name ON PLC ... END_RESOURCE`: one processing unit with its tasks and programs.
#[derive(Debug, Clone, Serialize)]
pub struct Resource {
    /// The resource's name.
    pub name: Ident,
    /// `ON PLC`.
    pub on: Option<Ident>,
    /// `VAR_GLOBAL` blocks at resource level.
    pub globals: Vec<VarBlock>,
    /// The `TASK` declarations.
    pub tasks: Vec<Task>,
    /// The `PROGRAM` instances.
    pub programs: Vec<ProgramInstance>,
    /// From `RESOURCE` to `END_RESOURCE`.
    pub span: Span,
}

/// `TASK name (INTERVAL := T#10ms, PRIORITY := 1);` (IEC 61131-3 2.7.2).
#[derive(Debug, Clone, Serialize)]
pub struct Task {
    /// The task's name.
    pub name: Ident,
    /// `INTERVAL := T#10ms` (cyclic); a literal or a variable.
    pub interval: Option<Operand>,
    /// `SINGLE := trigger` (event task).
    pub single: Option<Operand>,
    /// `PRIORITY := n`: 0 is the highest.
    pub priority: Option<u32>,
    /// The whole `TASK` declaration.
    pub span: Span,
}

/// `PROGRAM inst WITH task : TypeName (in := x, out => y);`
#[derive(Debug, Clone, Serialize)]
pub struct ProgramInstance {
    /// The instance name.
    pub name: Ident,
    /// `RETAIN` after `PROGRAM`: the instance's variables are retentive.
    pub retain: bool,
    /// `WITH task`: the task that runs it; `None` without `WITH` (the program runs in the background).
    pub task: Option<Ident>,
    /// The program POU instantiated.
    pub type_name: Ident,
    /// `in := x` / `out => y` connections to globals or direct addresses.
    pub args: Vec<FormalArg>,
    /// The whole declaration.
    pub span: Span,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A body holds one `IlStmt` per line (the 1,000,000-line POU of issue #16): literals and typed
    /// enumerated values are boxed so that an operand is no larger than a variable access, a variable
    /// access keeps its accessors behind one pointer, and the rare big instructions (deferred operators,
    /// `CAL`, function calls) box their payloads. The sizes are pinned so that they cannot grow back
    /// unnoticed (they were 80-byte operands and 136-byte statements).
    #[test]
    fn statements_and_operands_stay_small() {
        use std::mem::size_of;
        assert_eq!(size_of::<Accessors>(), 8);
        assert!(size_of::<VarRef>() <= 64, "{}", size_of::<VarRef>());
        assert!(size_of::<Operand>() <= size_of::<VarRef>());
        assert!(size_of::<Option<Operand>>() <= 64);
        assert!(size_of::<IlStmt>() <= 88, "{}", size_of::<IlStmt>());
    }

    /// `Accessors` reads, prints and serialises as the `Vec` it stands for, empty or not, and is written
    /// through like one.
    #[test]
    fn accessors_behave_as_a_vec() {
        let span = Span::default();
        let field = |n: &str| Accessor::Field(Ident::new(n, span));
        let empty = Accessors::default();
        assert!(empty.is_empty());
        assert_eq!(format!("{empty:?}"), "[]");
        assert_eq!(serde_json::to_string(&empty).unwrap(), "[]");
        assert!(Accessors::from(Vec::new()).is_empty());
        assert!(empty.clone().into_vec().is_empty());
        assert_eq!((&empty).into_iter().count(), 0);

        let list = vec![field("a"), Accessor::Index(vec![])];
        let mut acc: Accessors = list.clone().into();
        assert_eq!(format!("{acc:?}"), format!("{list:?}"));
        assert_eq!(
            serde_json::to_string(&acc).unwrap(),
            serde_json::to_string(&list).unwrap()
        );
        acc.push(field("b"));
        assert_eq!(acc.len(), 3);
        for a in &mut acc {
            if let Accessor::Field(f) = a {
                f.name.push('x');
            }
        }
        let names: Vec<String> = acc
            .iter()
            .filter_map(|a| match a {
                Accessor::Field(f) => Some(f.name.clone()),
                Accessor::Index(_) | Accessor::Deref(_) => None,
            })
            .collect();
        assert_eq!(names, ["ax", "bx"]);
        assert_eq!(acc.clone().into_vec().len(), 3);

        let mut grown = Accessors::default();
        grown.push(field("c"));
        assert_eq!(format!("{grown:?}"), format!("{:?}", vec![field("c")]));
        let collected: Accessors = vec![field("d")].into_iter().collect();
        assert_eq!(collected.len(), 1);
    }
}
