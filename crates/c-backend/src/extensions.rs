//! What the stages after the IL front end add to a generated program: the motion runtime and the
//! template-method functions (paper A, method 2), passed to [`crate::generate_with`].
//!
//! Input: built by the caller (ladderc's pipeline) from the axis configuration and the parameter-passing
//! lowering. Output: plain data; `emit::method` renders the functions, [`crate::motion`] the runtime.
//! Invariant: the types carry IL operands (not C text) for everything read from or written to the POU, so
//! the backend renders them exactly like IL instructions.

use crate::motion;

/// What the parameter-passing and motion stages add to a program (see [`crate::generate_with`]).
#[derive(Debug, Clone, Default)]
pub struct Extensions {
    /// The motion runtime (engine, axes, trace columns); `None` when the program uses no motion block.
    pub motion: Option<motion::MotionRuntime>,
    /// Template-method functions, each rendered inside its POU (see [`PouMethod`]).
    pub methods: Vec<PouMethod>,
}

/// A function synthesised for one block call by the parameter-template method, rendered as
/// `static void <name>(<POU struct> *self)`: head locals, template locals, body, feedback tail.
#[derive(Debug, Clone)]
pub struct PouMethod {
    /// The C name (a plain identifier), called by `FUNC <name>()` in the POU.
    pub name: String,
    /// The PROGRAM or FUNCTION_BLOCK whose variables the head reads and the tail writes.
    pub pou: String,
    /// The block's FuncNum (its template's `funcNum`).
    pub func_num: u32,
    /// The head: one local per input, from the call's operands.
    pub head: Vec<MethodLocal>,
    /// Extra locals of the body: `(C type, name)`.
    pub locals: Vec<(String, String)>,
    /// The template's body (C statements).
    pub body: String,
    /// The tail: the outputs written back.
    pub tail: Vec<MethodFeedback>,
    /// The call in the user's source.
    pub span: diagnostics::Span,
}

/// `c_type local = (c_type)<value of source>;` (`boolean`: a BOOL kept in a 0/1 `uint8_t`).
#[derive(Debug, Clone)]
pub struct MethodLocal {
    /// The local's C type.
    pub c_type: String,
    /// The local's name (the parameter's abbreviation).
    pub local: String,
    /// Whether it is a BOOL (kept as 0/1 in a `uint8_t`).
    pub boolean: bool,
    /// The value it starts with (the call's operand).
    pub source: il_frontend::ast::Operand,
}

/// `<target> = local;` (`negated`: `NOT Done => x`, for booleans).
#[derive(Debug, Clone)]
pub struct MethodFeedback {
    /// Where the output goes.
    pub target: il_frontend::ast::Operand,
    /// The local that holds the output.
    pub local: String,
    /// The local's C type.
    pub c_type: String,
    /// Whether it is a BOOL.
    pub boolean: bool,
    /// Whether the output is written negated (`NOT Done => x`).
    pub negated: bool,
}
