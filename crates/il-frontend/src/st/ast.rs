//! The Structured Text syntax tree: what [`super::parser`] produces and [`super::lower`] turns into IL.
//!
//! Invariants: every node carries the span of its source text; names keep the user's spelling and
//! compare case-insensitively (they are [`crate::ast::Ident`]s); literals, direct addresses and typed
//! enum values reuse the IL tree's nodes, so they print and type exactly as in IL. A construct the
//! parser could not read becomes [`ExprKind::Error`] (already reported), never a panic.

use crate::ast::{DirectAddress, Ident, Literal};
use crate::Span;
use serde::Serialize;

/// A statement with the span of its whole text (up to and including its `;`, when present).
#[derive(Debug, Clone, Serialize)]
pub struct Stmt {
    pub kind: StmtKind,
    pub span: Span,
}

/// (Variants differ in size; a tree is built once per body, boxing would only add indirection.)
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, Serialize)]
pub enum StmtKind {
    /// `target := value;` (also the result of a FUNCTION: `Name := value;`).
    Assign {
        target: Place,
        value: Expr,
    },
    /// `inst(IN := x, Q => y);` (FB instance call) or `F(x);` (function call as a statement).
    Call {
        callee: Place,
        args: Vec<Arg>,
    },
    /// `IF c THEN ... ELSIF c2 THEN ... ELSE ... END_IF;`
    If {
        branches: Vec<CondBranch>,
        else_body: Option<Vec<Stmt>>,
    },
    /// `CASE sel OF 1, 2: ... 3..5: ... ELSE ... END_CASE;`
    Case {
        selector: Expr,
        arms: Vec<CaseArm>,
        else_body: Option<Vec<Stmt>>,
    },
    /// `FOR i := from TO to BY step DO ... END_FOR;`
    For {
        control: Ident,
        from: Expr,
        to: Expr,
        by: Option<Expr>,
        body: Vec<Stmt>,
    },
    /// `WHILE c DO ... END_WHILE;`
    While {
        cond: Expr,
        body: Vec<Stmt>,
    },
    /// `REPEAT ... UNTIL c END_REPEAT;`
    Repeat {
        body: Vec<Stmt>,
        until: Expr,
    },
    Exit,
    /// `CONTINUE;` (edition 3): the next iteration of the innermost loop.
    Continue,
    Return,
    /// `;` alone.
    Empty,
}

/// `IF`/`ELSIF` condition with its statements.
#[derive(Debug, Clone, Serialize)]
pub struct CondBranch {
    pub cond: Expr,
    pub body: Vec<Stmt>,
    pub span: Span,
}

/// `1, 2, 5..7: statements`.
#[derive(Debug, Clone, Serialize)]
pub struct CaseArm {
    pub labels: Vec<CaseLabel>,
    pub body: Vec<Stmt>,
    pub span: Span,
}

#[derive(Debug, Clone, Serialize)]
pub enum CaseLabel {
    Value(Expr),
    /// `lower..upper` (inclusive).
    Range(Expr, Expr),
}

/// An assignable place or a call target: `x`, `s.a[i + 1].b`, `inst.Q`, `%QX0.1`.
#[derive(Debug, Clone, Serialize)]
pub struct Place {
    pub base: PlaceBase,
    pub accessors: Vec<Accessor>,
    pub span: Span,
}

#[derive(Debug, Clone, Serialize)]
pub enum PlaceBase {
    Name(Ident),
    Address(DirectAddress),
}

#[derive(Debug, Clone, Serialize)]
pub enum Accessor {
    Field(Ident),
    /// `[i, j + 1]`: index expressions.
    Index(Vec<Expr>),
}

/// One call argument: `x` (non-formal), `IN := x`, `Q => y`, `NOT Q => y`.
#[derive(Debug, Clone, Serialize)]
pub struct Arg {
    pub name: Option<Ident>,
    pub dir: ArgDir,
    pub value: Expr,
    pub span: Span,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum ArgDir {
    Input,
    /// `=>`; `negated` for `NOT Q => y`.
    Output {
        negated: bool,
    },
}

#[derive(Debug, Clone, Serialize)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

#[derive(Debug, Clone, Serialize)]
pub enum ExprKind {
    Literal(Literal),
    /// A variable, a field, an element, an FB output; also a bare enumerated value `red`.
    Place(Place),
    /// `Color#red`.
    EnumValue {
        type_name: Ident,
        value: Ident,
    },
    Unary {
        op: UnaryOp,
        operand: Box<Expr>,
    },
    Binary {
        op: BinaryOp,
        left: Box<Expr>,
        right: Box<Expr>,
    },
    /// `F(a, b)` / `F(IN := a)`: a function call (an FB instance in an expression is an error of the
    /// lowering, with a hint).
    Call {
        name: Ident,
        args: Vec<Arg>,
    },
    /// Text that could not be read (a diagnostic was reported).
    Error,
}

/// Dropping a tree frees it with a loop: the left operands of a chain `a + b + c ...` nest as deep as
/// the chain is long, and the compiler's recursive drop would overflow the stack on a long line.
impl Drop for Expr {
    fn drop(&mut self) {
        let mut stack = Vec::new();
        take_operands(&mut self.kind, &mut stack);
        while let Some(mut e) = stack.pop() {
            take_operands(&mut e.kind, &mut stack);
        }
    }
}

/// Moves the operands of a binary or unary node out (leaving [`ExprKind::Error`] behind) so that
/// dropping the node does not recurse into them.
fn take_operands(kind: &mut ExprKind, stack: &mut Vec<Expr>) {
    let mut take = |b: &mut Box<Expr>| {
        if matches!(b.kind, ExprKind::Binary { .. } | ExprKind::Unary { .. }) {
            let span = b.span;
            stack.push(std::mem::replace(
                &mut **b,
                Expr {
                    kind: ExprKind::Error,
                    span,
                },
            ));
        }
    };
    match kind {
        ExprKind::Binary { left, right, .. } => {
            take(left);
            take(right);
        }
        ExprKind::Unary { operand, .. } => take(operand),
        _ => {}
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum UnaryOp {
    Neg,
    Plus,
    Not,
}

/// Binary operators, lowest precedence first: `OR`, `XOR`, `AND`/`&`, `=`/`<>`, comparisons,
/// `+`/`-`, `*`/`/`/`MOD`, `**`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum BinaryOp {
    Or,
    Xor,
    And,
    Eq,
    Ne,
    Lt,
    Gt,
    Le,
    Ge,
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Power,
}

impl BinaryOp {
    /// How the operator is written in ST (for messages).
    pub fn spelling(self) -> &'static str {
        match self {
            BinaryOp::Or => "OR",
            BinaryOp::Xor => "XOR",
            BinaryOp::And => "AND",
            BinaryOp::Eq => "=",
            BinaryOp::Ne => "<>",
            BinaryOp::Lt => "<",
            BinaryOp::Gt => ">",
            BinaryOp::Le => "<=",
            BinaryOp::Ge => ">=",
            BinaryOp::Add => "+",
            BinaryOp::Sub => "-",
            BinaryOp::Mul => "*",
            BinaryOp::Div => "/",
            BinaryOp::Mod => "MOD",
            BinaryOp::Power => "**",
        }
    }
}

impl Place {
    /// A plain name without accessors.
    pub fn name(&self) -> Option<&Ident> {
        match (&self.base, self.accessors.is_empty()) {
            (PlaceBase::Name(n), true) => Some(n),
            _ => None,
        }
    }
}
