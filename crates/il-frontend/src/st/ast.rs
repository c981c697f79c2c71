//! The Structured Text syntax tree: what [`super::parser`] produces and [`super::lower`] turns into IL.
//!
//! Input: built by [`super::parser`] from ST text. Output: read by [`super::infer`] (types of
//! expressions) and [`super::lower`] (IL instructions).
//!
//! Invariants: every node carries the span of its source text; names keep the user's spelling and
//! compare case-insensitively (they are [`crate::ast::Ident`]s); literals, direct addresses and typed
//! enum values reuse the IL tree's nodes, so they print and type exactly as in IL. A construct the
//! parser could not read becomes [`ExprKind::Error`] (already reported), never a panic.

use crate::ast::{DirectAddress, Ident, Literal, LiteralKind};
use crate::Span;
use serde::Serialize;

/// A statement with the span of its whole text (up to and including its `;`, when present).
#[derive(Debug, Clone, Serialize)]
pub struct Stmt {
    /// What the statement does.
    pub kind: StmtKind,
    /// The statement's text, up to and including its `;` when present.
    pub span: Span,
}

/// (Variants differ in size; a tree is built once per body, boxing would only add indirection.)
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, Serialize)]
pub enum StmtKind {
    /// `target := value;` (also the result of a FUNCTION: `Name := value;`).
    Assign {
        /// The variable written (or the FUNCTION's own name for its result).
        target: Place,
        /// The value assigned.
        value: Expr,
    },
    /// `inst(IN := x, Q => y);` (FB instance call) or `F(x);` (function call as a statement).
    Call {
        /// The FB instance or function called.
        callee: Place,
        /// The arguments in written order.
        args: Vec<Arg>,
    },
    /// `IF c THEN ... ELSIF c2 THEN ... ELSE ... END_IF;`
    If {
        /// The `IF` branch and the `ELSIF` branches, in order.
        branches: Vec<CondBranch>,
        /// The `ELSE` statements, if there is an `ELSE`.
        else_body: Option<Vec<Stmt>>,
    },
    /// `CASE sel OF 1, 2: ... 3..5: ... ELSE ... END_CASE;`
    Case {
        /// The value compared with the labels (an integer or enumerated expression).
        selector: Expr,
        /// The `labels: statements` arms, in order.
        arms: Vec<CaseArm>,
        /// The `ELSE` statements, if there is an `ELSE`.
        else_body: Option<Vec<Stmt>>,
    },
    /// `FOR i := from TO to BY step DO ... END_FOR;`
    For {
        /// The control variable (`i`); for an element or member, the variable it is part of.
        control: Ident,
        /// The control variable when it is an array element or a structure member (`Offset[1]`,
        /// `st.i`: CODESYS and TwinCAT accept it, see `lower::for_control`); `None` for a name.
        element: Option<Place>,
        /// The start value, assigned before the first iteration.
        from: Expr,
        /// The end value (inclusive).
        to: Expr,
        /// The `BY` step; `None` means 1.
        by: Option<Expr>,
        /// The loop body.
        body: Vec<Stmt>,
    },
    /// `WHILE c DO ... END_WHILE;`
    While {
        /// The condition, tested before each iteration.
        cond: Expr,
        /// The loop body.
        body: Vec<Stmt>,
    },
    /// `REPEAT ... UNTIL c END_REPEAT;`
    Repeat {
        /// The loop body, run at least once.
        body: Vec<Stmt>,
        /// Statements run before each test of `until`, also after a CONTINUE: the ExST assignments
        /// of the condition (`UNTIL (n := n + 1) >= 10`; empty otherwise).
        setup: Vec<Stmt>,
        /// The condition that ends the loop, tested after each iteration.
        until: Expr,
    },
    /// `EXIT;`: leave the innermost loop.
    Exit,
    /// `CONTINUE;` (edition 3): the next iteration of the innermost loop.
    Continue,
    /// `RETURN;`: leave the POU.
    Return,
    /// `;` alone.
    Empty,
    /// `name:` before a statement (CODESYS and TwinCAT ST; IEC 61131-3 has jumps in IL, LD and
    /// FBD only): the target of `JMP name;`.
    Label(Ident),
    /// `JMP name;` (CODESYS and TwinCAT ST): go on at the label `name:` of the same body.
    Jump(Ident),
    /// `x;`, a name alone (CODESYS, TwinCAT: no effect, W1431 from the parser): does nothing, but
    /// its name must be declared (E1001 otherwise).
    Named(Place),
}

/// `IF`/`ELSIF` condition with its statements.
#[derive(Debug, Clone, Serialize)]
pub struct CondBranch {
    /// The condition (a BOOL expression).
    pub cond: Expr,
    /// The statements run when it holds.
    pub body: Vec<Stmt>,
    /// From `IF`/`ELSIF` to the end of the branch's statements.
    pub span: Span,
}

/// `1, 2, 5..7: statements`.
#[derive(Debug, Clone, Serialize)]
pub struct CaseArm {
    /// The labels (values and ranges) that select the arm.
    pub labels: Vec<CaseLabel>,
    /// The statements run when a label matches.
    pub body: Vec<Stmt>,
    /// From the first label to the end of the arm's statements.
    pub span: Span,
}

/// One `CASE` label.
#[derive(Debug, Clone, Serialize)]
pub enum CaseLabel {
    /// A single value: `3`, `red`, `-1`.
    Value(Expr),
    /// `lower..upper` (inclusive).
    Range(Expr, Expr),
}

impl StmtKind {
    /// The expressions a control statement evaluates itself (IF/ELSIF conditions, the CASE
    /// selector and labels, FOR bounds and step, WHILE and UNTIL conditions), not those of the
    /// statements it holds; empty for other statements (an assignment's or call's own parts are
    /// their callers' to take).
    pub fn control_exprs(&self) -> Vec<&Expr> {
        let mut out = Vec::new();
        match self {
            StmtKind::If { branches, .. } => out.extend(branches.iter().map(|b| &b.cond)),
            StmtKind::Case { selector, arms, .. } => {
                out.push(selector);
                for l in arms.iter().flat_map(|a| a.labels.iter()) {
                    match l {
                        CaseLabel::Value(e) => out.push(e),
                        CaseLabel::Range(a, b) => out.extend([a, b]),
                    }
                }
            }
            StmtKind::For { from, to, by, .. } => {
                out.extend([from, to]);
                out.extend(by.iter());
            }
            StmtKind::While { cond, .. } => out.push(cond),
            StmtKind::Repeat { until, .. } => out.push(until),
            _ => {}
        }
        out
    }

    /// [`Self::control_exprs`], to rewrite them.
    pub fn control_exprs_mut(&mut self) -> Vec<&mut Expr> {
        let mut out = Vec::new();
        match self {
            StmtKind::If { branches, .. } => out.extend(branches.iter_mut().map(|b| &mut b.cond)),
            StmtKind::Case { selector, arms, .. } => {
                out.push(selector);
                for l in arms.iter_mut().flat_map(|a| a.labels.iter_mut()) {
                    match l {
                        CaseLabel::Value(e) => out.push(e),
                        CaseLabel::Range(a, b) => out.extend([a, b]),
                    }
                }
            }
            StmtKind::For { from, to, by, .. } => {
                out.extend([from, to]);
                out.extend(by.iter_mut());
            }
            StmtKind::While { cond, .. } => out.push(cond),
            StmtKind::Repeat { until, .. } => out.push(until),
            _ => {}
        }
        out
    }
}

/// An assignable place or a call target: `x`, `s.a[i + 1].b`, `inst.Q`, `%QX0.1`.
#[derive(Debug, Clone, Serialize)]
pub struct Place {
    /// The variable name or direct address first.
    pub base: PlaceBase,
    /// The `.field` and `[index]` parts after the base, in order.
    pub accessors: Vec<Accessor>,
    /// The whole place text.
    pub span: Span,
}

/// What a place starts with.
#[derive(Debug, Clone, Serialize)]
pub enum PlaceBase {
    /// A variable, FB instance or function name.
    Name(Ident),
    /// A direct address: `%QX0.1 := TRUE;`.
    Address(DirectAddress),
}

/// One step of a place after its base.
#[derive(Debug, Clone, Serialize)]
pub enum Accessor {
    /// `.name`: a structure field or an FB instance's input/output.
    Field(Ident),
    /// `[i, j + 1]`: index expressions.
    Index(Vec<Expr>),
    /// `^`: the variable a reference or pointer refers to (the span of the `^`).
    Deref(crate::Span),
    /// `(args)` after a method (or function) name inside a place, where more accessors follow:
    /// `stack.Get(i).Pop()`, `list.Item(2).Value := 5;`, `n.Next()^.Value` (CODESYS, TwinCAT
    /// call chains). Only the parser makes it; the lowering replaces it (`lower::call_chain`)
    /// by the call and a temporary holding the result, before anything else reads the place.
    Call {
        /// The call's arguments in written order.
        args: Vec<Arg>,
        /// From `(` to `)`.
        span: crate::Span,
    },
}

/// One call argument: `x` (non-formal), `IN := x`, `Q => y`, `NOT Q => y`.
#[derive(Debug, Clone, Serialize)]
pub struct Arg {
    /// The formal parameter (`IN` in `IN := x`); `None` for a non-formal (positional) argument.
    pub name: Option<Ident>,
    /// Input (`:=` or positional) or output (`=>`).
    pub dir: ArgDir,
    /// The value passed, or the variable an output is written to.
    pub value: Expr,
    /// The whole argument text.
    pub span: Span,
}

/// Which way an ST call argument passes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum ArgDir {
    /// `IN := x` or positional `x`.
    Input,
    /// `=>`; `negated` for `NOT Q => y`.
    Output {
        /// `NOT Q => y`: the inverted output is stored.
        negated: bool,
    },
}

/// An ST expression with its span.
#[derive(Debug, Clone, Serialize)]
pub struct Expr {
    /// What the expression computes.
    pub kind: ExprKind,
    /// The expression's text.
    pub span: Span,
}

/// What an ST expression is (IEC 61131-3 3.3.1, table 55).
#[derive(Debug, Clone, Serialize)]
pub enum ExprKind {
    /// A constant: `5`, `T#1s`, `'text'`, `INT#3`.
    Literal(Literal),
    /// A variable, a field, an element, an FB output; also a bare enumerated value `red`.
    Place(Place),
    /// `Color#red`.
    EnumValue {
        /// The enumerated type before `#`.
        type_name: Ident,
        /// The value after `#`.
        value: Ident,
    },
    /// `-x`, `+x`, `NOT x`.
    Unary {
        /// The operator.
        op: UnaryOp,
        /// What it applies to.
        operand: Box<Expr>,
    },
    /// `a + b`, `x AND y`, `a ** 2` ...
    Binary {
        /// The operator.
        op: BinaryOp,
        /// The left operand.
        left: Box<Expr>,
        /// The right operand.
        right: Box<Expr>,
    },
    /// `F(a, b)` / `F(IN := a)`: a function call (an FB instance in an expression is an error of the
    /// lowering, with a hint).
    Call {
        /// The function's name.
        name: Ident,
        /// The arguments in written order.
        args: Vec<Arg>,
    },
    /// Text that could not be read (a diagnostic was reported).
    Error,
}

impl Expr {
    /// An untyped literal of `kind` (what a rewrite of the tree inserts: `0`, `TRUE`).
    pub fn literal(kind: LiteralKind, span: Span) -> Expr {
        Expr {
            kind: ExprKind::Literal(Literal {
                kind,
                type_prefix: None,
                span,
            }),
            span,
        }
    }
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

/// The unary operators of ST.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum UnaryOp {
    /// `-x`: arithmetic negation.
    Neg,
    /// `+x`: no effect (kept for printing and checks).
    Plus,
    /// `NOT x`: Boolean or bitwise complement.
    Not,
}

/// Binary operators, lowest precedence first: `OR`, `XOR`, `AND`/`&`, `=`/`<>`, comparisons,
/// `+`/`-`, `*`/`/`/`MOD`, `**`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum BinaryOp {
    /// `OR`: Boolean or bitwise OR (lowest precedence).
    Or,
    /// `XOR`: exclusive OR.
    Xor,
    /// `AND` or `&`: Boolean or bitwise AND.
    And,
    /// `=`: equality (BOOL result).
    Eq,
    /// `<>`: inequality.
    Ne,
    /// `<`: less than.
    Lt,
    /// `>`: greater than.
    Gt,
    /// `<=`: less or equal.
    Le,
    /// `>=`: greater or equal.
    Ge,
    /// `+`: addition (also TIME and date arithmetic).
    Add,
    /// `-`: subtraction.
    Sub,
    /// `*`: multiplication.
    Mul,
    /// `/`: division (integers: truncated toward zero).
    Div,
    /// `MOD`: remainder of integer division.
    Mod,
    /// `**`: exponentiation, lowered to `EXPT` (highest precedence).
    Power,
    /// `AND_THEN` (CODESYS, TwinCAT; not IEC 61131-3): Boolean AND whose right operand is evaluated
    /// only when the left is TRUE (precedence of `AND`).
    AndThen,
    /// `OR_ELSE` (CODESYS, TwinCAT; not IEC 61131-3): Boolean OR whose right operand is evaluated
    /// only when the left is FALSE (precedence of `OR`).
    OrElse,
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
            BinaryOp::AndThen => "AND_THEN",
            BinaryOp::OrElse => "OR_ELSE",
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

    /// The expressions inside its accessors, in order: each index of `[i, j + 1]`, each argument
    /// of a method's call `.M(x)`.
    pub fn accessor_exprs(&self) -> impl Iterator<Item = &Expr> {
        self.accessors.iter().flat_map(|a| {
            let (index, args): (&[Expr], &[Arg]) = match a {
                Accessor::Index(ix) => (ix, &[]),
                Accessor::Call { args, .. } => (&[], args),
                _ => (&[], &[]),
            };
            index.iter().chain(args.iter().map(|a| &a.value))
        })
    }
}
