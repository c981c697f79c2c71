//! The IL syntax tree: what the parser produces, what the ladder compiler lowers rungs into, what the
//! semantic checks and the C backend read.
//!
//! Invariants: every node has the span of its source text (for lowered ladder, the span of the XML element
//! it came from); identifiers keep the user's spelling in `name` and compare by [`Ident::key`] (IEC names are
//! case-insensitive); the tree holds no resolved information (types, symbols): that is `sema`'s output.

use crate::Span;
use serde::Serialize;

/// A name as written, with its span. Compare with [`Ident::key`] or [`Ident::is`].
#[derive(Debug, Clone, Serialize)]
pub struct Ident {
    pub name: String,
    pub span: Span,
}

impl Ident {
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
    pub items: Vec<LibraryElement>,
}

#[derive(Debug, Clone, Serialize)]
pub enum LibraryElement {
    DataTypes(Vec<TypeDecl>),
    Pou(Pou),
    Configuration(Configuration),
    /// `VAR_GLOBAL` outside a configuration (accepted as an extension; it belongs to every program).
    GlobalVars(VarBlock),
}

// ---------------------------------------------------------------- types

/// A type as written in a declaration.
#[derive(Debug, Clone, Serialize)]
pub enum TypeRef {
    /// An elementary type (`INT`), a standard or user FB type (`TON`), or a user data type.
    Named(Ident),
    /// `STRING`, `STRING[20]`, `WSTRING(10)`.
    String {
        wide: bool,
        length: Option<u32>,
        span: Span,
    },
    /// `ARRAY [1..10, 0..3] OF INT`.
    Array {
        dims: Vec<ArrayDim>,
        element: Box<TypeRef>,
        span: Span,
    },
    /// `INT (0..100)`.
    Subrange {
        base: Ident,
        lower: i128,
        upper: i128,
        span: Span,
    },
    /// An inline enumeration `(red, green)`.
    Enum { values: Vec<Ident>, span: Span },
}

impl TypeRef {
    pub fn span(&self) -> Span {
        match self {
            TypeRef::Named(i) => i.span,
            TypeRef::String { span, .. }
            | TypeRef::Array { span, .. }
            | TypeRef::Subrange { span, .. }
            | TypeRef::Enum { span, .. } => *span,
        }
    }
}

#[derive(Debug, Clone, Serialize)]
pub struct ArrayDim {
    pub lower: i128,
    pub upper: i128,
    pub span: Span,
}

/// `TYPE name : ... ; END_TYPE` entry.
#[derive(Debug, Clone, Serialize)]
pub struct TypeDecl {
    pub name: Ident,
    pub def: TypeDef,
    pub span: Span,
}

#[derive(Debug, Clone, Serialize)]
pub enum TypeDef {
    /// `T : INT := 5;`, `T : ARRAY [..] OF INT := [...]`, `T : INT (0..9)`, `T : STRING[8]`.
    Alias {
        ty: TypeRef,
        init: Option<Initializer>,
    },
    Struct {
        fields: Vec<VarDecl>,
    },
    Enum {
        values: Vec<EnumValue>,
        init: Option<Ident>,
    },
}

#[derive(Debug, Clone, Serialize)]
pub struct EnumValue {
    pub name: Ident,
    /// `red := 3` (an extension most tools accept).
    pub value: Option<i128>,
}

// ---------------------------------------------------------------- literals and operands

#[derive(Debug, Clone, Serialize)]
pub struct Literal {
    pub kind: LiteralKind,
    /// The `INT#` / `REAL#` / `BOOL#` prefix of a typed literal, if written.
    pub type_prefix: Option<Ident>,
    pub span: Span,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum LiteralKind {
    /// Any integer literal (decimal, `2#`, `8#`, `16#`), sign applied.
    Int(i128),
    Real(f64),
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
        wide: bool,
        value: String,
    },
}

/// `%IX0.1`, `%QW3`, `%MD10`, `%I*` (location left open).
#[derive(Debug, Clone, Serialize)]
pub struct DirectAddress {
    pub area: Area,
    pub size: AddressSize,
    /// The dotted numbers (`%IX1.2.3` -> [1, 2, 3]); empty for `%I*`.
    pub path: Vec<u32>,
    pub span: Span,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum Area {
    Input,
    Output,
    Memory,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum AddressSize {
    /// No size letter: a bit (`%I0.1`), as `X`.
    Bit,
    Byte,
    Word,
    DWord,
    LWord,
}

/// A variable access: `x`, `inst.Q`, `arr[3]`, `s.a[i].b`.
#[derive(Debug, Clone, Serialize)]
pub struct VarRef {
    pub base: Ident,
    pub accessors: Vec<Accessor>,
    pub span: Span,
}

#[derive(Debug, Clone, Serialize)]
pub enum Accessor {
    Field(Ident),
    Index(Vec<Operand>),
}

/// What an IL instruction works on.
#[derive(Debug, Clone, Serialize)]
pub enum Operand {
    Literal(Literal),
    Var(VarRef),
    Address(DirectAddress),
    /// An enumerated value written with its type, `Color#red` (a plain `red` parses as a `Var`).
    EnumValue {
        type_name: Ident,
        value: Ident,
        span: Span,
    },
}

impl Operand {
    pub fn span(&self) -> Span {
        match self {
            Operand::Literal(l) => l.span,
            Operand::Var(v) => v.span,
            Operand::Address(a) => a.span,
            Operand::EnumValue { span, .. } => *span,
        }
    }
}

// ---------------------------------------------------------------- declarations

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum VarKind {
    Local,
    Input,
    Output,
    InOut,
    Temp,
    Global,
    External,
}

/// `VAR_INPUT CONSTANT RETAIN ... END_VAR`.
#[derive(Debug, Clone, Serialize)]
pub struct VarBlock {
    /// The name of a CODESYS/TwinCAT global variable list (`<globalVars name="GVL">`), whose members
    /// are also reachable qualified (`GVL.x`); `None` for every IEC declaration block.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<Ident>,
    pub kind: VarKind,
    pub constant: bool,
    pub retain: bool,
    pub vars: Vec<VarDecl>,
    pub span: Span,
}

/// One declared name (`a, b : INT := 3;` yields two `VarDecl`s sharing type and initial value).
#[derive(Debug, Clone, Serialize)]
pub struct VarDecl {
    pub name: Ident,
    /// `AT %IX0.1`.
    pub location: Option<DirectAddress>,
    pub ty: TypeRef,
    pub init: Option<Initializer>,
    /// `R_EDGE` / `F_EDGE` after the type (edge-triggered BOOL input of a function block).
    pub edge: Option<Edge>,
    pub span: Span,
}

/// The edge qualifier of an input declaration: the input reads TRUE only in the call in which its value
/// rose (`R_EDGE`) or fell (`F_EDGE`), as if an implicit R_TRIG/F_TRIG instance filtered it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Edge {
    Rising,
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

    pub fn with_init(mut self, init: Initializer) -> Self {
        self.init = Some(init);
        self
    }

    pub fn with_edge(mut self, edge: Edge) -> Self {
        self.edge = Some(edge);
        self
    }

    pub fn with_location(mut self, location: DirectAddress) -> Self {
        self.location = Some(location);
        self
    }
}

#[derive(Debug, Clone, Serialize)]
pub enum Initializer {
    /// A literal, an enum value, or a named constant.
    Value(Operand),
    /// `[1, 2, 3(0)]`: elements with optional repeat counts.
    Array(Vec<ArrayInitElement>, Span),
    /// `(a := 1, b := TRUE)`; also FB instance parameter initialisation `tmr : TON := (PT := T#1s)`.
    Struct(Vec<(Ident, Initializer)>, Span),
}

#[derive(Debug, Clone, Serialize)]
pub struct ArrayInitElement {
    pub repeat: Option<u32>,
    pub value: Initializer,
}

// ---------------------------------------------------------------- POUs

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum PouKind {
    Program,
    FunctionBlock,
    Function,
}

#[derive(Debug, Clone, Serialize)]
pub struct Pou {
    pub kind: PouKind,
    pub name: Ident,
    /// The result type of a FUNCTION.
    pub return_type: Option<TypeRef>,
    pub var_blocks: Vec<VarBlock>,
    pub body: Vec<IlStmt>,
    pub span: Span,
}

/// A body is a list of labels and instructions (a label may stand alone on its line, or before `END_*`).
#[derive(Debug, Clone, Serialize)]
pub enum IlStmt {
    Label(Ident),
    Instr(Instruction),
}

#[derive(Debug, Clone, Serialize)]
pub struct Instruction {
    pub kind: InstrKind,
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
    Ld,
    St,
    /// `S x`: set x if the current result is TRUE.
    S,
    /// `R x`: reset x if the current result is TRUE.
    R,
    And,
    Or,
    Xor,
    /// `NOT` (no operand): invert the current result.
    Not,
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Gt,
    Ge,
    Eq,
    Ne,
    Le,
    Lt,
}

/// The `C` / `CN` modifier of JMP, CAL, RET.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Condition {
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
    S1,
    R1,
    Clk,
    Cu,
    Cd,
    Pv,
    In,
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

#[derive(Debug, Clone, Serialize)]
pub enum InstrKind {
    /// `LD x`, `ANDN y`, `ADD 5`, `NOT`, `S q` ...; `operand` is `None` only for `NOT` and for `S`/`R`
    /// written without an operand (a diagnostic in sema).
    Simple {
        op: Op,
        negate: bool,
        operand: Option<Operand>,
    },
    /// `AND( operand` ... `)`: the operator applied to the current result and the value of the nested list.
    /// The optional operand on the opening line is an implicit `LD` that starts the nested list.
    Deferred {
        op: Op,
        negate: bool,
        operand: Option<Operand>,
        body: Vec<IlStmt>,
        close: Span,
    },
    Jump {
        cond: Condition,
        label: Ident,
    },
    Return {
        cond: Condition,
    },
    /// `CAL inst(...)`, `CALC inst`, `CALCN inst(IN := x, Q => y)`.
    Call {
        cond: Condition,
        instance: VarRef,
        args: CallArgs,
    },
    /// A function call as an operator: `SEL x, y` (the current result is the first argument) or `LIMIT(MN := 0, ...)`.
    FunctionCall {
        name: Ident,
        args: CallArgs,
    },
    /// `S1 inst`, `IN tmr`, `PT tmr` ...
    FbInput {
        op: FbInputOp,
        instance: VarRef,
    },
    /// The extension `FUNC Name()`: call of an embedded C function (see `param-passing`).
    EmbeddedC {
        name: Ident,
    },
}

#[derive(Debug, Clone, Serialize)]
pub enum CallArgs {
    None,
    /// Positional arguments.
    NonFormal(Vec<Operand>),
    /// `name := value`, `name => var`, `NOT name => var`.
    Formal(Vec<FormalArg>),
}

#[derive(Debug, Clone, Serialize)]
pub struct FormalArg {
    pub name: Ident,
    pub dir: ArgDir,
    pub value: Operand,
    pub span: Span,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum ArgDir {
    /// `name := value`
    Input,
    /// `name => var`; `negated` for `NOT name => var`.
    Output { negated: bool },
}

// ---------------------------------------------------------------- configurations

#[derive(Debug, Clone, Serialize)]
pub struct Configuration {
    pub name: Ident,
    pub globals: Vec<VarBlock>,
    /// A configuration written without `RESOURCE` gets one resource named after the configuration.
    pub resources: Vec<Resource>,
    pub span: Span,
}

#[derive(Debug, Clone, Serialize)]
pub struct Resource {
    pub name: Ident,
    /// `ON PLC`.
    pub on: Option<Ident>,
    pub globals: Vec<VarBlock>,
    pub tasks: Vec<Task>,
    pub programs: Vec<ProgramInstance>,
    pub span: Span,
}

#[derive(Debug, Clone, Serialize)]
pub struct Task {
    pub name: Ident,
    /// `INTERVAL := T#10ms` (cyclic); a literal or a variable.
    pub interval: Option<Operand>,
    /// `SINGLE := trigger` (event task).
    pub single: Option<Operand>,
    pub priority: Option<u32>,
    pub span: Span,
}

/// `PROGRAM inst WITH task : TypeName (in := x, out => y);`
#[derive(Debug, Clone, Serialize)]
pub struct ProgramInstance {
    pub name: Ident,
    pub retain: bool,
    pub task: Option<Ident>,
    pub type_name: Ident,
    pub args: Vec<FormalArg>,
    pub span: Span,
}
