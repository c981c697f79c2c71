//! The IL parser: runs [`crate::layout`] and the lalrpop grammar (`grammar.lalrpop`), builds the
//! [`crate::ast`] and turns syntax errors into E0xxx diagnostics.
//!
//! Input: source text (a whole file, or an instruction list alone with the offset of its first byte in
//! the file it comes from). Output: the syntax tree; every problem is a diagnostic, never a panic.
//! Invariants: spans are `base + local offset`; each syntax error is reported once (the grammar skips to
//! the end of the line, the `;` of a declaration, or the `END_*` of a block, then continues); the grammar
//! is lenient where a precise message helps (an operator without its operand parses, then is reported
//! here as "expected an operand after `LD`").

use crate::ast::*;
pub use crate::const_eval::{ConstNum, Constants};
use crate::layout::Layout;
use crate::lexer::{LineTok, TimeValue, Tok, Word};
use diagnostics::{code, Code, Diagnostic, Diagnostics, FileId, Severity, Span};
use lalrpop_util::{ErrorRecovery, ParseError};
use std::collections::HashMap;

#[allow(
    clippy::all,
    clippy::pedantic,
    unused_parens,
    unused_imports,
    dead_code
)]
mod grammar {
    include!(concat!(env!("OUT_DIR"), "/grammar.rs"));
}

/// What the grammar's start rule produces.
pub enum Parsed {
    /// A whole file (started by [`Tok::UnitStart`]).
    Unit(TopParts),
    /// An instruction list alone (started by [`Tok::BodyStart`]).
    Body(Vec<IlStmt>),
}

/// One top-level item while collecting a compilation unit.
pub enum TopItem {
    /// An empty line or a line the grammar skipped after a reported error.
    Nothing,
    /// Boxed: a POU or configuration is large and rare, and every parser stack slot has the size of
    /// the largest item.
    Element(Box<LibraryElement>),
    /// A `VAR*` block outside any POU (global, or collected into the implicit program).
    Vars(VarBlock),
    /// An instruction or label outside any POU (collected into the implicit program).
    Stmt(IlStmt),
}

/// The compilation unit being collected; bare instructions and non-global `VAR` blocks go to the
/// implicit program (see [`crate::parse_named`]).
#[derive(Default)]
pub struct TopParts {
    /// The library elements in source order (the implicit program is inserted later).
    pub items: Vec<LibraryElement>,
    /// Index in `items` where the implicit program goes, with its parts.
    pub implicit: Option<(usize, Vec<VarBlock>, Vec<IlStmt>)>,
    /// The span of the first bare instruction or `VAR` block (where warning W0001 points).
    pub first_bare: Option<Span>,
}

impl TopParts {
    /// Files one top-level item: elements and `VAR_GLOBAL` blocks to `items`, the rest to the implicit
    /// program.
    pub fn add(&mut self, item: TopItem) {
        let at = self.items.len();
        match item {
            TopItem::Nothing => {}
            TopItem::Element(e) => self.items.push(*e),
            TopItem::Vars(v) if v.kind == VarKind::Global => {
                self.items.push(LibraryElement::GlobalVars(v))
            }
            TopItem::Vars(v) => {
                self.first_bare.get_or_insert(v.span);
                self.implicit
                    .get_or_insert_with(|| (at, Vec::new(), Vec::new()))
                    .1
                    .push(v)
            }
            TopItem::Stmt(s) => {
                let span = match &s {
                    IlStmt::Label(i) => i.span,
                    IlStmt::Instr(i) => i.span,
                };
                self.first_bare.get_or_insert(span);
                self.implicit
                    .get_or_insert_with(|| (at, Vec::new(), Vec::new()))
                    .2
                    .push(s)
            }
        }
    }
}

/// One item of a POU while collecting it.
pub enum PouItem {
    /// An instruction or label; `None` for an empty or skipped line.
    Stmt(Option<IlStmt>),
    /// A `VAR*` block (after the first instruction it is error E0015).
    Vars(VarBlock),
}

/// A POU's variable blocks and body while the grammar collects them.
#[derive(Default)]
pub struct PouParts {
    /// The `VAR*` blocks in source order.
    pub vars: Vec<VarBlock>,
    /// The instruction list in source order.
    pub body: Vec<IlStmt>,
}

/// One item of a configuration or resource (large items boxed: see [`TopItem::Element`]).
pub enum ConfigItem {
    /// `VAR_GLOBAL` inside the configuration or resource.
    Vars(VarBlock),
    /// A `RESOURCE ... END_RESOURCE`.
    Resource(Box<Resource>),
    /// A `TASK` declaration.
    Task(Box<Task>),
    /// A `PROGRAM inst WITH task : Type` declaration.
    Program(Box<ProgramInstance>),
    /// An empty line or a line skipped after an error.
    Nothing,
}

/// Simple operator as written: the operator, its `N` modifier, the keyword (for messages).
pub type SimpleOp = (Op, bool, Word);

/// The simple operator a word stands for (the grammar's `SimpleOp` rule for the words of
/// [`Word::is_simple_op`]; `&` and `&N` are not words), `None` for any other word.
pub fn simple_op(word: Word) -> Option<SimpleOp> {
    use Word as W;
    let (op, negated) = match word {
        W::Ld => (Op::Ld, false),
        W::Ldn => (Op::Ld, true),
        W::St => (Op::St, false),
        W::Stn => (Op::St, true),
        W::S => (Op::S, false),
        W::R => (Op::R, false),
        W::And => (Op::And, false),
        W::Andn => (Op::And, true),
        W::Or => (Op::Or, false),
        W::Orn => (Op::Or, true),
        W::Xor => (Op::Xor, false),
        W::Xorn => (Op::Xor, true),
        W::Not => (Op::Not, false),
        W::Add => (Op::Add, false),
        W::Sub => (Op::Sub, false),
        W::Mul => (Op::Mul, false),
        W::Div => (Op::Div, false),
        W::Mod => (Op::Mod, false),
        W::Gt => (Op::Gt, false),
        W::Ge => (Op::Ge, false),
        W::Eq => (Op::Eq, false),
        W::Ne => (Op::Ne, false),
        W::Le => (Op::Le, false),
        W::Lt => (Op::Lt, false),
        _ => return None,
    };
    Some((op, negated, word))
}

/// An element of a structure initializer after its first (see `Ctx::struct_elements`).
pub enum StructItem {
    /// `name := value`.
    Named((Ident, Initializer)),
    /// A value alone, continuing the bracketless array of the element before it.
    Bare(Initializer, Span),
}

/// Parser state shared by the grammar actions.
pub struct Ctx<'s> {
    /// The file spans point into.
    pub file: FileId,
    /// The text being parsed (without the `base` offset).
    pub src: &'s str,
    /// The byte offset of `src` in the file (a PLCopen XML `<IL>` body's position).
    pub base: usize,
    /// Syntax problems found by the grammar actions, in order.
    pub diags: Vec<Diagnostic>,
    /// Numeric and duration constants declared so far in the text (`VAR_GLOBAL CONSTANT` / `VAR
    /// CONSTANT` with a literal or constant-expression initial value), by upper-case name: what a
    /// constant expression may name.
    pub consts: Constants,
    /// The declarations being read are in a `CONSTANT` block (their integer values go to `consts`).
    pub in_constant_block: bool,
    /// The types of the variables declared so far in the POU being read, by upper-case name: what
    /// `SIZEOF(v)` in a constant expression measures ([`Ctx::const_call`]).
    pub sized_vars: HashMap<String, TypeRef>,
    /// The same for the global variables declared so far in the text (kept from POU to POU).
    pub sized_globals: HashMap<String, TypeRef>,
}

/// An enumerated value as written: its name and, when given, its value's expression with the
/// expression's start and end offsets (see [`Ctx::enum_values`]).
pub type RawEnumValue = (Ident, Option<(BoundExpr, usize, usize)>);

/// An integer constant expression in an array bound or a string length, as parsed (see
/// [`Ctx::bound`]).
#[derive(Debug)]
pub enum BoundExpr {
    /// An integer literal, sign applied.
    Int(i128, Span),
    /// A real literal (`2.2E-016`, `LREAL#1.5`, `REAL#2`), sign applied.
    Real(f64, Span),
    /// A duration literal (`T#500MS`) in nanoseconds.
    Duration(i128, Span),
    /// Another literal (`D#2024-01-01`, `'text'`): no value in a constant expression.
    NotNumber(Span),
    /// A named constant.
    Name(Ident),
    /// `-e`.
    Neg(Box<BoundExpr>, Span),
    /// `a op b`, `op` one of `+ - * /` and `%` for MOD.
    Bin(u8, Box<BoundExpr>, Box<BoundExpr>),
    /// An operand without a value, and why (`SIZEOF(FB_X)`: a function block's size).
    NoValue(String, Span),
    /// `F(a, b)`: a standard function of constant arguments (`SQRT(2.0)`, `MAX(A, B)`,
    /// `TO_REAL(LOG(-1))`), computed by `const_eval`.
    Call(Ident, Vec<BoundExpr>, Span),
}

/// A bound expression is as deep as the user wrote it (`1+1+...`, `-(-(...))`): it is dropped with an
/// explicit stack, never by recursion (200,000 terms overflowed the stack in the derived drop).
impl Drop for BoundExpr {
    fn drop(&mut self) {
        fn take_children(e: &mut BoundExpr, stack: &mut Vec<BoundExpr>) {
            let leaf = || BoundExpr::Int(0, Span::default());
            match e {
                BoundExpr::Neg(a, _) => stack.push(std::mem::replace(&mut **a, leaf())),
                BoundExpr::Bin(_, a, b) => {
                    stack.push(std::mem::replace(&mut **a, leaf()));
                    stack.push(std::mem::replace(&mut **b, leaf()));
                }
                BoundExpr::Call(_, args, _) => stack.append(args),
                BoundExpr::Int(..)
                | BoundExpr::Real(..)
                | BoundExpr::Duration(..)
                | BoundExpr::NotNumber(_)
                | BoundExpr::NoValue(..)
                | BoundExpr::Name(_) => {}
            }
        }
        let mut stack = Vec::new();
        take_children(self, &mut stack);
        while let Some(mut e) = stack.pop() {
            take_children(&mut e, &mut stack);
        }
    }
}

impl<'s> Ctx<'s> {
    /// The file span of the local byte range `l..r`.
    pub fn span(&self, l: usize, r: usize) -> Span {
        Span::new(self.file, self.base + l, self.base + r)
    }
    /// The source text of the local byte range `l..r`.
    pub fn text(&self, l: usize, r: usize) -> &'s str {
        &self.src[l..r]
    }
    /// An identifier made of the local byte range `l..r`.
    pub fn ident(&self, l: usize, r: usize) -> Ident {
        Ident::new(&self.src[l..r], self.span(l, r))
    }
    fn error(&mut self, code: Code, msg: impl Into<String>, l: usize, r: usize) -> &mut Diagnostic {
        let d = Diagnostic::error(code, msg).at(self.span(l, r));
        self.diags.push(d);
        self.diags.last_mut().expect("just pushed")
    }
    fn hint(&mut self, code: Code, msg: impl Into<String>, l: usize, r: usize, hint: &str) {
        let d = self.error(code, msg, l, r);
        d.hint = Some(hint.to_string());
    }

    // ------------------------------------------------------------ nesting caps

    /// Reports E0211 or E0212 at `span` unless a report of the same cap already lies inside it (the
    /// cut is repeated every [`MAX_TYPE_NESTING`] levels of one declaration; it is reported once).
    fn too_deep(&mut self, code: Code, msg: String, span: Span, hint: &str) {
        let inside = |s: &Span| s.file == span.file && s.start >= span.start && s.end <= span.end;
        if self
            .diags
            .iter()
            .any(|d| d.code == code && d.span.as_ref().is_some_and(inside))
        {
            return;
        }
        let mut d = Diagnostic::error(code, msg).at(span);
        d.hint = Some(hint.to_string());
        self.diags.push(d);
    }

    /// `x : BOOL AT %QX0.0;`: the location written after the type, as OpenPLC Editor v4 writes the
    /// declarations of its `.st` files; IEC 61131-3 writes it between the name and the type. The
    /// declaration is read as `x AT %QX0.0 : BOOL;`, with warning W0016 at `AT %QX0.0`.
    pub fn location_after_type(&mut self, l: usize, r: usize) {
        let mut d = Diagnostic::warning(
            code::W0016,
            format!(
                "the location `{}` is written after the type: read as if it stood before the `:`",
                self.text(l, r)
            ),
        )
        .at(self.span(l, r))
        .with_primary_label("location after the type");
        d.hint = Some(
            "IEC 61131-3 writes the location between the name and the type (`name AT %QX0.0 : BOOL := FALSE;`); OpenPLC Editor v4 writes it after the type, and ladderc reads both".to_string(),
        );
        self.diags.push(d);
    }

    /// A dimension `*` of a variable-length array (`ARRAY [*, *] OF REAL`, IEC 61131-3 edition 3,
    /// 6.5.3): both bounds [`ArrayDim::VARIABLE`]. Where it is allowed (a VAR_IN_OUT of an ST POU)
    /// `st::varlen` compiles it; anywhere else sema reports E1072.
    pub fn variable_length_dim(&mut self, l: usize, r: usize) -> ArrayDim {
        ArrayDim {
            lower: ArrayDim::VARIABLE,
            upper: ArrayDim::VARIABLE,
            span: self.span(l, r),
        }
    }

    /// `ARRAY [dims] OF element`. Element types nested deeper than [`MAX_TYPE_NESTING`] are E0211 and
    /// cut to their innermost type, so that the tree the later stages walk (recursively) stays shallow.
    pub fn array_type(
        &mut self,
        dims: Vec<ArrayDim>,
        element: TypeRef,
        l: usize,
        r: usize,
    ) -> TypeRef {
        let span = self.span(l, r);
        let mut depth = 1;
        let mut t = &element;
        while let TypeRef::Array { element, .. } = t {
            depth += 1;
            t = element;
        }
        if depth <= MAX_TYPE_NESTING {
            return TypeRef::Array {
                dims,
                element: Box::new(element),
                span,
            };
        }
        self.too_deep(
            code::E0211,
            format!("array types nested more than {MAX_TYPE_NESTING} deep"),
            span,
            "declare the inner array as a named type (TYPE row : ARRAY [..] OF ...; END_TYPE), or use one \
             array with several dimensions: ARRAY [0..9, 0..9] OF INT",
        );
        // The innermost type, taken out level by level (no recursive drop of the chain).
        let mut t = element;
        while let TypeRef::Array { element, .. } = t {
            t = *element;
        }
        t
    }

    /// The elements of a structure initializer: `first`, then `rest`, where a bare value joins
    /// the element before it as the next element of an array written without brackets (CODESYS
    /// V2.3: `(id := 1, items := (a := 11), (a := 13))` is `items := [(a := 11), (a := 13)]`).
    pub fn struct_elements(
        &mut self,
        first: (Ident, Initializer),
        rest: Vec<StructItem>,
    ) -> Vec<(Ident, Initializer)> {
        let mut out = vec![first];
        // whether the last element's value is an array this function made
        let mut joined = false;
        for item in rest {
            match item {
                StructItem::Named(e) => {
                    out.push(e);
                    joined = false;
                }
                StructItem::Bare(value, span) => {
                    let Some((_, last)) = out.last_mut() else {
                        continue;
                    };
                    let element = ArrayInitElement {
                        repeat: None,
                        value,
                    };
                    match last {
                        Initializer::Array(elements, s) if joined => {
                            elements.push(element);
                            s.end = span.end;
                        }
                        _ => {
                            let before =
                                std::mem::replace(last, Initializer::Array(Vec::new(), span));
                            let start = init_span(&before).map_or(span.start, |s| s.start);
                            *last = Initializer::Array(
                                vec![
                                    ArrayInitElement {
                                        repeat: None,
                                        value: before,
                                    },
                                    element,
                                ],
                                Span { start, ..span },
                            );
                            joined = true;
                        }
                    }
                }
            }
        }
        out
    }

    /// An array or structure initializer. One nested deeper than [`MAX_TYPE_NESTING`] is E0212 and
    /// replaced by an empty one (the depth is measured with an explicit stack, bounded by the cap).
    pub fn nested_init(&mut self, init: Initializer) -> Initializer {
        let span = match &init {
            Initializer::Array(_, s) | Initializer::Struct(_, s) => *s,
            Initializer::Value(_) => return init,
        };
        let mut stack = vec![(&init, 1usize)];
        let mut deep = false;
        while let Some((i, d)) = stack.pop() {
            if d > MAX_TYPE_NESTING {
                deep = true;
                break;
            }
            match i {
                Initializer::Value(_) => {}
                Initializer::Array(es, _) => stack.extend(es.iter().map(|e| (&e.value, d + 1))),
                Initializer::Struct(fs, _) => stack.extend(fs.iter().map(|(_, v)| (v, d + 1))),
            }
        }
        if !deep {
            return init;
        }
        self.too_deep(
            code::E0212,
            format!("initializers nested more than {MAX_TYPE_NESTING} deep"),
            span,
            "give the inner values their own named types and constants, or flatten the data into one \
             array with several dimensions",
        );
        Initializer::Array(Vec::new(), span)
    }

    // ------------------------------------------------------------ instructions

    /// A [`Tok::SimpleLine`] (`LD x` passed on as one token, the operator at `l`, the name ending at
    /// `r`): what [`Ctx::simple`] builds of the operator and the plain variable operand.
    pub fn simple_line(
        &mut self,
        (op, nl, nr): (SimpleOp, usize, usize),
        l: usize,
        r: usize,
    ) -> Option<Instruction> {
        let operand = Operand::Var(VarRef {
            base: self.ident(nl, nr),
            accessors: Default::default(),
            span: self.span(nl, nr),
        });
        self.simple(op, Some(operand), l, r)
    }

    /// A [`Tok::SimpleIntLine`] (`ADD 5` passed on as one token, the operator at `l`, the literal
    /// at `nl..nr = r`): what [`Ctx::simple`] builds of the operator and the integer literal.
    pub fn simple_int_line(
        &mut self,
        (op, value, nl, nr): (SimpleOp, i128, usize, usize),
        l: usize,
        r: usize,
    ) -> Option<Instruction> {
        let literal = self.literal(LiteralKind::Int(value), None, nl, nr);
        self.simple(op, Some(Operand::literal(literal)), l, r)
    }

    /// Builds `LD x`, `ANDN y`, `NOT` ...; reports a missing operand (E0012), an operand after `NOT`
    /// (E0013) and extra operands (E0301), returning `None` when the line is unusable.
    pub fn simple(
        &mut self,
        (op, negate, _word): SimpleOp,
        operand: Option<Operand>,
        l: usize,
        r: usize,
    ) -> Option<Instruction> {
        match (op, &operand) {
            (Op::Not, Some(o)) => {
                let (os, oe) = self.local(o.span());
                self.hint(
                    code::E0013,
                    "`NOT` takes no operand",
                    os,
                    oe,
                    "`NOT` inverts the current result; to load an inverted value write `LDN`",
                );
            }
            (Op::Not | Op::S | Op::R, None) => {}
            (_, None) => {
                let kw = self.text(l, l + word_len(self.src, l));
                let what = if op == Op::St {
                    "a variable or address"
                } else {
                    "an operand"
                };
                self.hint(
                    code::E0012,
                    format!("expected {what} after `{kw}`"),
                    l,
                    r,
                    &format!("write what `{kw}` works on on the same line, e.g. `{kw} x`"),
                );
                return None;
            }
            _ => {}
        }
        // `NOT x` was reported: the tree keeps the recovered `NOT` (no second report downstream).
        let operand = if op == Op::Not { None } else { operand };
        Some(Instruction {
            kind: InstrKind::Simple {
                op,
                negate,
                operand,
            },
            span: self.span(l, r),
        })
    }

    /// `ADD b, c, d`: an extensible standard function (ADD, MUL, AND, OR, XOR, GT, GE, EQ, LE, LT)
    /// called with the current result as its first input and the operands as the next ones, as
    /// matiec reads it. Any other operator with several operands is E0300.
    pub fn extensible(
        &mut self,
        (op, negate, _word): SimpleOp,
        first: Operand,
        rest: Vec<Operand>,
        l: usize,
        r: usize,
    ) -> Option<Instruction> {
        let kw = self.text(l, l + word_len(self.src, l)).to_string();
        let name = match (op, negate) {
            (Op::Add, false) => "ADD",
            (Op::Mul, false) => "MUL",
            (Op::And, false) => "AND",
            (Op::Or, false) => "OR",
            (Op::Xor, false) => "XOR",
            (Op::Gt, false) => "GT",
            (Op::Ge, false) => "GE",
            (Op::Eq, false) => "EQ",
            (Op::Le, false) => "LE",
            (Op::Lt, false) => "LT",
            _ => {
                let (s, _) = self.local(rest[0].span());
                self.hint(
                    code::E0301,
                    format!("`{kw}` takes one operand"),
                    s.saturating_sub(1),
                    r,
                    "only the extensible functions ADD, MUL, AND, OR, XOR, GT, GE, EQ, LE, LT take a list of operands; compute the rest on further lines",
                );
                return None;
            }
        };
        let mut ops = vec![first];
        ops.extend(rest);
        let kw_span = self.span(l, l + kw.len());
        Some(Instruction {
            kind: InstrKind::FunctionCall {
                name: crate::ast::Ident::new(name, kw_span),
                args: Box::new(crate::ast::CallArgs::NonFormal(ops)),
            },
            span: self.span(l, r),
        })
    }

    /// Builds a deferred operator `AND( ... )`; reports an operator that cannot take a parenthesised
    /// operand (E0021).
    #[allow(clippy::too_many_arguments)]
    pub fn deferred(
        &mut self,
        (op, negate, word): SimpleOp,
        operand: Option<Operand>,
        body: Vec<IlStmt>,
        close: (usize, usize),
        l: usize,
        r: usize,
    ) -> Option<Instruction> {
        if !word.is_deferrable() && !matches!(word, Word::Ident) {
            let kw = self.text(l, l + word_len(self.src, l)).to_string();
            self.hint(
                code::E0021,
                format!("`{kw}` cannot take a parenthesised operand"),
                l,
                r.min(l + kw.len() + 1),
                "only AND, OR, XOR (and their N forms), &, ADD, SUB, MUL, DIV, MOD and the comparisons can be deferred",
            );
            return None;
        }
        Some(Instruction {
            kind: InstrKind::Deferred {
                op,
                negate,
                operand: operand.map(Box::new),
                body,
                close: self.span(close.0, close.1),
            },
            span: self.span(l, r),
        })
    }

    /// Builds `JMP label` / `JMPC` / `JMPCN`; reports a missing label (E0014).
    pub fn jump(
        &mut self,
        cond: Condition,
        label: Option<Ident>,
        l: usize,
        r: usize,
    ) -> Option<Instruction> {
        let Some(label) = label else {
            let kw = self.text(l, r).to_string();
            self.hint(
                code::E0014,
                format!("expected a label after `{kw}`"),
                l,
                r,
                &format!("write the label to jump to, e.g. `{kw} done`"),
            );
            return None;
        };
        Some(Instruction {
            kind: InstrKind::Jump { cond, label },
            span: self.span(l, r),
        })
    }

    /// Builds `RET` / `RETC` / `RETCN`; reports an operand (E0013).
    pub fn ret(
        &mut self,
        cond: Condition,
        operand: Option<Operand>,
        l: usize,
        _r: usize,
    ) -> Option<Instruction> {
        let kw_end = l + word_len(self.src, l);
        if let Some(o) = operand {
            let (os, oe) = self.local(o.span());
            let kw = self.text(l, kw_end).to_string();
            self.hint(
                code::E0013,
                format!("`{kw}` takes no operand"),
                os,
                oe,
                "remove the operand; the function result is the variable named like the function",
            );
        }
        Some(Instruction {
            kind: InstrKind::Return { cond },
            span: self.span(l, kw_end),
        })
    }

    /// Builds `CAL inst(...)` / `CALC` / `CALCN`; reports a missing instance (E0012).
    pub fn call(
        &mut self,
        cond: Condition,
        instance: Option<VarRef>,
        args: CallArgs,
        l: usize,
        r: usize,
    ) -> Option<Instruction> {
        let Some(instance) = instance else {
            let kw = self.text(l, l + word_len(self.src, l)).to_string();
            self.hint(
                code::E0012,
                format!("expected a function block instance after `{kw}`"),
                l,
                r,
                &format!("write the instance to call, e.g. `{kw} timer1(IN := start, PT := T#5s)`"),
            );
            return None;
        };
        Some(Instruction {
            kind: InstrKind::Call {
                cond,
                instance: Box::new(instance),
                args,
            },
            span: self.span(l, r),
        })
    }

    /// Builds `S1 inst`, `IN tmr`, `PT tmr` ...; reports a missing instance (E0012).
    pub fn fb_input(
        &mut self,
        op: FbInputOp,
        instance: Option<VarRef>,
        l: usize,
        r: usize,
    ) -> Option<Instruction> {
        let Some(instance) = instance else {
            let kw = self.text(l, r).to_string();
            self.hint(
                code::E0012,
                format!("expected a function block instance after `{kw}`"),
                l,
                r,
                &format!(
                    "`{kw}` stores the current result into input {} of an instance and calls it, e.g. `{kw} timer1`",
                    op.input_name()
                ),
            );
            return None;
        };
        Some(Instruction {
            kind: InstrKind::FbInput { op, instance },
            span: self.span(l, r),
        })
    }

    /// An instruction of `kind` spanning `l..r`.
    pub fn instr(&self, kind: InstrKind, l: usize, r: usize) -> Option<Instruction> {
        Some(Instruction {
            kind,
            span: self.span(l, r),
        })
    }

    // ------------------------------------------------------------ literals

    /// A literal of `kind` with its optional `TYPE#` prefix, spanning `l..r`.
    pub fn literal(&self, kind: LiteralKind, prefix: Option<Ident>, l: usize, r: usize) -> Literal {
        Literal {
            kind,
            type_prefix: prefix,
            span: self.span(l, r),
        }
    }

    /// `T#..`, `D#..`, ...: no prefix, except the long (`L`) forms, whose prefix is the canonical name.
    pub fn time_literal(&self, t: TimeValue, l: usize, r: usize) -> Literal {
        let hash = self.src[l..r].find('#').map_or(l, |i| l + i);
        let long = |name: &str| Some(Ident::new(name, self.span(l, hash)));
        let (kind, prefix) = match t {
            TimeValue::Duration(v, lg) => (
                LiteralKind::Duration(v),
                lg.then(|| long("LTIME")).flatten(),
            ),
            TimeValue::Date(v, lg) => (LiteralKind::Date(v), lg.then(|| long("LDATE")).flatten()),
            TimeValue::TimeOfDay(v, lg) => (
                LiteralKind::TimeOfDay(v),
                lg.then(|| long("LTOD")).flatten(),
            ),
            TimeValue::DateAndTime(v, lg) => (
                LiteralKind::DateAndTime(v),
                lg.then(|| long("LDT")).flatten(),
            ),
        };
        self.literal(kind, prefix, l, r)
    }

    /// A `T#`/`LTIME#` literal in a constant expression (a date or time of day has no value there).
    pub fn bound_time(&self, t: TimeValue, l: usize, r: usize) -> BoundExpr {
        match t {
            TimeValue::Duration(v, _) => BoundExpr::Duration(v, self.span(l, r)),
            _ => BoundExpr::NotNumber(self.span(l, r)),
        }
    }

    /// A typed literal in a constant expression (`LREAL#1.5`, `INT#2`, `REAL#3`).
    pub fn bound_typed(&self, lit: Literal) -> BoundExpr {
        match ConstNum::of_literal(&lit) {
            Some(ConstNum::Int(v)) => BoundExpr::Int(v, lit.span),
            Some(ConstNum::Real(v)) => BoundExpr::Real(v, lit.span),
            Some(ConstNum::Duration(v)) => BoundExpr::Duration(v, lit.span),
            None => BoundExpr::NotNumber(lit.span),
        }
    }

    // ------------------------------------------------------------ declarations

    /// Builds a POU; reports a result type on a program or FB (E0011, dropped).
    pub fn pou(
        &mut self,
        kind: PouKind,
        name: Ident,
        return_type: Option<TypeRef>,
        parts: PouParts,
        l: usize,
        r: usize,
    ) -> Pou {
        // `SIZEOF(v)` of the next POU's declarations no more sees this one's variables
        self.sized_vars.clear();
        // A FUNCTION without `: type` returns no value: TwinCAT compiles it (stefanbesler/struckig's
        // `FUNCTION INTERNAL Integrate`, whose results are its VAR_IN_OUTs), and the C backend
        // gives it a `void` C function; using its value is E0354 (`st::lower`).
        if kind != PouKind::Function {
            if let Some(t) = &return_type {
                let (s, e) = self.local(t.span());
                self.hint(
                    code::E0011,
                    "only a FUNCTION has a result type",
                    s,
                    e,
                    "remove `: type` after the name",
                );
            }
        }
        Pou {
            class: false,
            kind,
            name,
            return_type: if kind == PouKind::Function {
                return_type
            } else {
                None
            },
            var_blocks: parts.vars,
            // The body grew by doubling: up to half of it is spare room, which the rest of the
            // compilation can use instead (peak memory, #16).
            body: {
                let mut body = parts.body;
                body.shrink_to_fit();
                body
            },
            span: self.span(l, r),
        }
    }

    /// The statement of one line of a run ([`Tok::Lines`]): what the grammar's rule for its line
    /// token builds (`BodyItem`: `Instr EOL` of a `SIMPLE_LINE`, `SIMPLE_INT_LINE` or `JUMP_LINE`,
    /// a `LABEL_LINE`), `None` where that rule gives none.
    pub fn line_stmt(&mut self, (l, line, r): (usize, LineTok, usize)) -> Option<IlStmt> {
        match line {
            LineTok::Simple(op, nl, nr) => self.simple_line((op, nl, nr), l, r).map(IlStmt::Instr),
            LineTok::SimpleInt(op, v, nl, nr) => self
                .simple_int_line((op, v, nl, nr), l, r)
                .map(IlStmt::Instr),
            LineTok::Jump(c, nl, nr) => {
                let label = self.ident(nl, nr);
                self.jump(c, Some(label), l, r).map(IlStmt::Instr)
            }
            LineTok::Label(nl, nr) => Some(IlStmt::Label(self.ident(nl, nr))),
        }
    }

    /// Adds a run of plain lines ([`Tok::Lines`]) to a POU being collected, each line's statement
    /// ([`Ctx::line_stmt`]) with [`Ctx::pou_item`].
    pub fn pou_lines(
        &mut self,
        mut parts: PouParts,
        lines: Vec<(usize, LineTok, usize)>,
    ) -> PouParts {
        for line in lines {
            let stmt = self.line_stmt(line);
            parts = self.pou_item(parts, PouItem::Stmt(stmt));
        }
        parts
    }

    /// Adds one item to a POU being collected; a `VAR` block after the first instruction is error E0015.
    pub fn pou_item(&mut self, mut parts: PouParts, item: PouItem) -> PouParts {
        match item {
            PouItem::Stmt(Some(s)) => {
                if parts.body.len() == MEDIUM_BODY && parts.body.capacity() == MEDIUM_BODY {
                    parts.body.reserve_exact(LONG_BODY - MEDIUM_BODY);
                } else if parts.body.len() == LONG_BODY && parts.body.capacity() == LONG_BODY {
                    let hint = long_body_hint(&parts.body[0], &s, self.src.len() + self.base);
                    parts.body.reserve(hint);
                }
                parts.body.push(s)
            }
            PouItem::Stmt(None) => {}
            PouItem::Vars(v) => {
                if let Some(first) = parts.body.first() {
                    let first = match first {
                        IlStmt::Label(i) => i.span,
                        IlStmt::Instr(i) => i.span,
                    };
                    let (s, e) = self.local(v.span);
                    let s_end = (s + word_len(self.src, s)).min(e);
                    let d = self.error(code::E0015, "declarations after instructions", s, s_end);
                    d.primary_label = "this block follows the instruction list".into();
                    d.labels.push(diagnostics::Label {
                        span: first,
                        message: "the instruction list starts here".into(),
                    });
                    d.hint = Some("move the declaration block before the first instruction".into());
                }
                parts.vars.push(v);
            }
        }
        parts
    }

    /// `a -1`: a sum followed by a signed literal (`N-1` lexes as `N` and `-1`) is `a + (-1)` when the
    /// sign is written right there; anything else juxtaposed is E0022.
    pub fn bound_sum(&mut self, a: BoundExpr, b: BoundExpr, l: usize, r: usize) -> BoundExpr {
        if !self.text(l, r).starts_with(['+', '-']) {
            self.hint(
                code::E0022,
                "an operator is missing in this constant expression",
                l,
                r,
                "write + - * / or MOD between the operands",
            );
        }
        BoundExpr::Bin(b'+', Box::new(a), Box::new(b))
    }

    /// A type written as a name: TwinCAT's `BIT` (a structure's or block's one-bit member) is
    /// read as BOOL, which holds the same values (stored in a byte: SIZEOF of such a structure
    /// differs from TwinCAT's); a variable may still be named `bit`.
    pub fn named_type(&self, name: Ident) -> TypeRef {
        if name.name.eq_ignore_ascii_case("BIT") {
            return TypeRef::Named(Ident::new("BOOL", name.span));
        }
        if name.name.eq_ignore_ascii_case("PVOID") {
            // TwinCAT's untyped pointer (Infosys "PVOID", a pointer-sized address): a bounded
            // `POINTER TO BYTE` here, as `ADR(x)` gives it and MEMCPY takes it
            return TypeRef::Ref {
                kind: crate::ast::RefKind::Pointer,
                target: Box::new(TypeRef::Named(Ident::new("BYTE", name.span))),
                span: name.span,
            };
        }
        TypeRef::Named(name)
    }

    /// `name := ADR(of)` / `REF(of)` in a structure or instance initializer: the address of `of`;
    /// `name := SIZEOF(of)`: its size, a constant (another function is no initial value: E0022).
    pub fn address_element(
        &mut self,
        name: Ident,
        l: usize,
        n: usize,
        of: VarRef,
        r: usize,
    ) -> (Ident, Initializer) {
        let callee = self.ident(l, n);
        let span = self.span(l, r);
        if callee.is("SIZEOF") {
            // `nSize := SIZEOF(values)` (TwinCAT: a constant): the size in the generated C, as
            // in any constant expression (`Ctx::const_call`)
            let e = if of.accessors.is_empty() {
                self.const_call(l, n, vec![BoundExpr::Name(of.base)], r)
            } else {
                BoundExpr::NoValue(
                    "`SIZEOF(...)` is computed in a constant expression for a type or a variable's name".into(),
                    span,
                )
            };
            return (name, self.init_expr(e, l, r));
        }
        if !(callee.is("ADR") || callee.is("REF")) {
            self.hint(
                code::E0022,
                format!("`{}(...)` is computed at run time", callee.name),
                l,
                r,
                "an initial value is a constant, or `ADR(x)` / `REF(x)` of a variable of the POU; set this one in the body",
            );
        }
        let value = Initializer::Value(Operand::Ref(Box::new(crate::ast::RefOperand {
            of: Some(of),
            span,
            call_scoped: false,
            address_of: false,
        })));
        (name, value)
    }

    /// A call `F(args)` written at `l..r` in a constant expression, `F` at `l..n`. `SIZEOF(x)`: the
    /// bytes of the variable `x` declared before (in this POU, or a global of the text), else of
    /// the data type `x`, in the generated C ([`crate::type_sizes`]); `x` must be a name. Another
    /// call is a standard function that `const_eval` computes (or explains why not).
    pub fn const_call(&mut self, l: usize, n: usize, args: Vec<BoundExpr>, r: usize) -> BoundExpr {
        let span = self.span(l, r);
        let name = self.ident(l, n);
        if !name.name.eq_ignore_ascii_case("SIZEOF") {
            return BoundExpr::Call(name, args, span);
        }
        let [BoundExpr::Name(arg)] = args.as_slice() else {
            return BoundExpr::NoValue(
                "`SIZEOF(...)` is computed in a constant expression for a type or a variable's name".into(),
                span,
            );
        };
        let name = arg.name.clone();
        let key = name.to_ascii_uppercase();
        let layout = match self
            .sized_vars
            .get(&key)
            .or_else(|| self.sized_globals.get(&key))
        {
            Some(ty) => crate::type_sizes::of_type(ty, &self.consts),
            None => crate::type_sizes::of_type(&TypeRef::Named(arg.clone()), &self.consts),
        };
        match layout {
            Ok(l) => BoundExpr::Int(i128::from(l.size), span),
            Err(why) => BoundExpr::NoValue(why, span),
        }
    }

    /// Evaluates a bound expression written at `l..r` (checked integer arithmetic; `/` truncates).
    /// A name that is not an integer constant declared before, a division by zero or an overflow is
    /// one E0022 (none if a missing operator was already reported there), and `None`.
    pub fn bound(&mut self, e: BoundExpr, l: usize, r: usize) -> Option<i128> {
        self.const_expr(e, l, r, true)
    }

    /// A constant expression as an initial value (`c : INT := N * 2;`, `EPS : LREAL := 16 *
    /// 2.2E-016;`, `T_MAX : TIME := T#1S + T#500MS;`): its value as a literal spanning `l..r` (the
    /// integer 0 after an E0022; the type's range is checked by sema).
    pub fn init_expr(&mut self, e: BoundExpr, l: usize, r: usize) -> Initializer {
        let kind = self
            .const_value(e, l, r)
            .map_or(LiteralKind::Int(0), ConstNum::literal_kind);
        Initializer::Value(Operand::literal(Literal {
            kind,
            type_prefix: None,
            span: self.span(l, r),
        }))
    }

    /// An element of an array initialiser written as a constant expression at `l..r`: `N(7)`,
    /// where `N` is an integer constant declared before, is `N` repetitions of 7 (CODESYS and
    /// TwinCAT name the count so; a name that is neither such a constant nor a function ladderc
    /// computes is a missing constant, E0022); any other expression is one element (see
    /// [`Ctx::init_expr`]).
    pub fn array_element(&mut self, e: BoundExpr, l: usize, r: usize) -> ArrayInitElement {
        if let BoundExpr::Call(callee, args, _) = &e {
            if let ([BoundExpr::Name(of)], true) =
                (args.as_slice(), callee.is("ADR") || callee.is("REF"))
            {
                // `[ADR(a), ADR(b)]` (CODESYS, TwinCAT): an element that starts as the address of
                // a variable (`sema::address_init` checks it)
                let of = crate::ast::VarRef {
                    base: of.clone(),
                    accessors: Vec::new().into(),
                    span: of.span,
                };
                let address_of = callee.is("ADR");
                return self.address_array_element(of, address_of, l, r);
            }
        }
        // `N(7)` where `N` is a constant or no standard function ladderc computes: IEC 61131-3's
        // repetition; a count that names no constant of the files given (a list of another
        // project, dgwoOstjfn/Mem1) is the one error (E0022, counted with the name's other uses)
        // and the value one element, not a call
        let count = match &e {
            BoundExpr::Call(name, args, _) if args.len() == 1 => {
                match self.consts.get(&name.name.to_ascii_uppercase()) {
                    Some(ConstNum::Int(n)) => Some(u32::try_from(*n).ok()),
                    _ if !crate::const_eval::computed(&name.name) => {
                        let nl = (name.span.start as usize).saturating_sub(self.base);
                        let nr = (name.span.end as usize).saturating_sub(self.base);
                        let n = self.const_expr(BoundExpr::Name(name.clone()), nl, nr, true);
                        Some(n.and_then(|n| u32::try_from(n).ok()))
                    }
                    _ => None,
                }
            }
            _ => None,
        };
        let (repeat, value) = match (count, e) {
            (Some(n), mut e) => {
                let arg = match &mut e {
                    BoundExpr::Call(_, args, _) => args.pop(),
                    _ => None,
                };
                (n, arg.unwrap_or(BoundExpr::Int(0, self.span(l, r))))
            }
            (None, e) => (None, e),
        };
        ArrayInitElement {
            repeat,
            value: self.init_expr(value, l, r),
        }
    }

    /// `ADR(of)` / `REF(of)` written at `l..r` as an element of an array's initial value: the
    /// address of `of` (`sema::address_init` checks it); `address_of` when written `ADR`.
    pub fn address_array_element(
        &mut self,
        of: VarRef,
        address_of: bool,
        l: usize,
        r: usize,
    ) -> ArrayInitElement {
        ArrayInitElement {
            repeat: None,
            value: Initializer::Value(Operand::Ref(Box::new(crate::ast::RefOperand {
                of: Some(of),
                span: self.span(l, r),
                call_scoped: false,
                address_of,
            }))),
        }
    }

    /// `F(path)` written at `l..r` (`F` at `l..n`) as an element of an array's initial value:
    /// `ADR(path)` / `REF(path)` an address ([`Ctx::address_array_element`]); another function
    /// is no initial value (E0022).
    pub fn address_call_element(
        &mut self,
        l: usize,
        n: usize,
        of: VarRef,
        r: usize,
    ) -> ArrayInitElement {
        let callee = self.ident(l, n);
        if !(callee.is("ADR") || callee.is("REF")) {
            self.hint(
                code::E0022,
                format!("`{}(...)` is computed at run time", callee.name),
                l,
                r,
                "an initial value is a constant, or `ADR(x)` / `REF(x)` of a variable of the POU; set this one in the body",
            );
        }
        let address_of = callee.is("ADR");
        self.address_array_element(of, address_of, l, r)
    }

    /// `N(value)` in an array's initial value, `N` (at `l..r`) an integer constant declared
    /// before: `N` repetitions of `value`; another name is E0022 (one element then).
    pub fn named_repeat(&mut self, l: usize, r: usize, value: Initializer) -> ArrayInitElement {
        let name = self.ident(l, r);
        let repeat = self.const_expr(BoundExpr::Name(name), l, r, true);
        let repeat = repeat.and_then(|n| u32::try_from(n).ok());
        ArrayInitElement { repeat, value }
    }

    /// Evaluates `e` (see [`Ctx::bound`]); `dint`: the value must fit a DINT (a bound, a length),
    /// else a LINT.
    fn const_expr(&mut self, e: BoundExpr, l: usize, r: usize, dint: bool) -> Option<i128> {
        let value = self.evaluated(e, l, r, true)?.and_then(|v| match v {
            ConstNum::Int(v) if dint && i32::try_from(v).is_err() => {
                Err("the value overflows".to_string())
            }
            ConstNum::Int(v) => Ok(v),
            _ => Err("the value is not an integer".to_string()),
        });
        self.report_const(value, l, r, true)
    }

    /// Evaluates `e` as an initial value: a number or a duration (E0022 when it has none).
    fn const_value(&mut self, e: BoundExpr, l: usize, r: usize) -> Option<ConstNum> {
        let value = self.evaluated(e, l, r, false)?;
        self.report_const(value, l, r, false)
    }

    /// The value of `e` written at `l..r`, `None` when an E0022 was already reported inside it;
    /// `integers`: a bound or a length (see [`crate::const_eval::eval`]).
    fn evaluated(
        &mut self,
        e: BoundExpr,
        l: usize,
        r: usize,
        integers: bool,
    ) -> Option<Result<ConstNum, String>> {
        let here = self.span(l, r);
        if self.diags.iter().any(|d| {
            d.code == code::E0022
                && d.span
                    .is_some_and(|s| s.start >= here.start && s.end <= here.end)
        }) {
            return None;
        }
        Some(crate::const_eval::eval(&e, &self.consts, integers))
    }

    /// The value, or one E0022 at `l..r` saying why there is none (`integers`: in a bound or length).
    fn report_const<T>(
        &mut self,
        value: Result<T, String>,
        l: usize,
        r: usize,
        integers: bool,
    ) -> Option<T> {
        match value {
            Ok(v) => Some(v),
            Err(why) => {
                let text = self.text(l, r).trim().to_string();
                let hint = if crate::const_eval::is_missing_constant(&why) {
                    "declare the constant in a VAR_GLOBAL CONSTANT list given with the files, or write the number; a library's constant (TwinCAT's, CODESYS's): give the library's source project with --lib"
                } else if integers {
                    "use integer literals and integer constants (VAR CONSTANT or VAR_GLOBAL CONSTANT with an integer value, declared before in this file, or a VAR_GLOBAL CONSTANT list of another file given with it) with + - * / MOD, parentheses and SIZEOF(T) of a data type"
                } else {
                    "use literals (numbers, T#... durations) and constants (VAR CONSTANT or VAR_GLOBAL CONSTANT declared before in this file, or a VAR_GLOBAL CONSTANT list of another file given with it) with + - * / MOD, AND OR XOR of integers, parentheses and SIZEOF(T) of a data type"
                };
                self.hint(
                    code::E0022,
                    format!("constant expression `{text}`: {why}"),
                    l,
                    r,
                    hint,
                );
                None
            }
        }
    }

    /// Builds a `VAR*` block with its `CONSTANT` / `RETAIN` qualifiers.
    pub fn var_block(
        &mut self,
        kind: VarKind,
        quals: Vec<Word>,
        vars: Vec<VarDecl>,
        l: usize,
        r: usize,
    ) -> VarBlock {
        self.in_constant_block = false;
        if kind == VarKind::Global {
            for v in &vars {
                let name = v.name.name.to_ascii_uppercase();
                if let Some(ty) = self.sized_vars.remove(&name) {
                    self.sized_globals.insert(name, ty);
                }
            }
        }
        VarBlock {
            access: None,
            name: None,
            kind,
            constant: quals.contains(&Word::Constant),
            retain: quals.contains(&Word::Retain),
            vars,
            span: self.span(l, r),
        }
    }

    /// Builds one [`VarDecl`] per name of `a, b : T := v;`, sharing location, type, edge qualifier and
    /// initial value.
    #[allow(clippy::too_many_arguments)]
    pub fn var_decls(
        &mut self,
        names: Vec<Ident>,
        location: Option<DirectAddress>,
        ty: TypeRef,
        edge: Option<(usize, usize)>,
        init: Option<Initializer>,
        l: usize,
        r: usize,
    ) -> Vec<VarDecl> {
        // a generic constant of a block built with an instance's values (`FB_Buf<10>`:
        // `st::generic_blocks`): that value in place of its initial value
        let init = match crate::st::generic_blocks::instance_value(&names, self.in_constant_block) {
            Some(v) => Some(Initializer::Value(Operand::Literal(Box::new(Literal {
                kind: LiteralKind::Int(v),
                type_prefix: None,
                span: names.first().map(|n| n.span).unwrap_or_default(),
            })))),
            None => init,
        };
        // `R_EDGE` / `F_EDGE` (sema checks where they are allowed).
        let edge = edge.map(|(s, e)| {
            if self.text(s, e).eq_ignore_ascii_case("F_EDGE") {
                Edge::Falling
            } else {
                Edge::Rising
            }
        });
        if location.is_some() && names.len() > 1 {
            let (s, e) = self.local(names[1].span);
            self.hint(
                code::E0017,
                "one location (`AT`) for several names",
                s,
                e,
                "declare each located variable on its own line",
            );
        }
        for name in &names {
            self.sized_vars
                .insert(name.name.to_ascii_uppercase(), ty.clone());
        }
        if self.in_constant_block {
            let value = match &init {
                Some(Initializer::Value(Operand::Literal(lit))) => ConstNum::of_literal(lit),
                // `C3 : REAL := C1;`: a constant named before
                Some(Initializer::Value(Operand::Var(v)))
                    if v.accessors.is_empty()
                        && self.consts.contains_key(&v.base.name.to_ascii_uppercase()) =>
                {
                    self.consts.get(&v.base.name.to_ascii_uppercase()).copied()
                }
                // `N : INT := E_Topic.COUNT_OF;`: an enumeration's value, as its number
                Some(Initializer::Value(op)) => {
                    crate::const_eval::enum_operand_value(&self.consts, op)
                }
                _ => None,
            };
            if let Some(n) = value.and_then(|v| crate::const_eval::as_declared(v, &ty)) {
                for name in &names {
                    self.consts.insert(name.name.to_ascii_uppercase(), n);
                }
            }
        }
        // `e : (A := 1, B := 2) UDINT := 1;` (CODESYS, TwinCAT: an implicit enumeration, whose
        // values are numbers): an integer initial value is the value of that number
        let init = match (&ty, init) {
            (TypeRef::Enum { values, .. }, Some(Initializer::Value(Operand::Literal(lit))))
                if matches!(lit.kind, LiteralKind::Int(_)) && lit.type_prefix.is_none() =>
            {
                let LiteralKind::Int(n) = lit.kind else {
                    unreachable!()
                };
                let mut next = 0i128;
                let named = values.iter().find_map(|v| {
                    let number = v.value.unwrap_or(next);
                    next = number + 1;
                    (number == n).then(|| v.name.clone())
                });
                match named {
                    Some(name) => Some(Initializer::Value(Operand::Var(VarRef {
                        base: Ident::new(&name.name, lit.span),
                        accessors: Default::default(),
                        span: lit.span,
                    }))),
                    None => Some(Initializer::Value(Operand::Literal(lit))),
                }
            }
            (_, init) => init,
        };
        let span = self.span(l, r);
        names
            .into_iter()
            .map(|name| VarDecl {
                name,
                location: location.clone(),
                ty: ty.clone(),
                init: init.clone(),
                edge,
                span,
            })
            .collect()
    }

    /// `AT %IX1.1 : BOOL := TRUE;`: a located variable without a name, which IEC 61131-3 allows
    /// (the program reaches it through its address). It gets the name `AT_` and the address's
    /// letters and numbers (`AT_IX1_1`), so that it is declared, initialised and traced like any other.
    pub fn anonymous_located(
        &mut self,
        location: DirectAddress,
        ty: TypeRef,
        init: Option<Initializer>,
        l: usize,
        r: usize,
    ) -> Vec<VarDecl> {
        let (s, e) = self.local(location.span);
        let name: String = self
            .text(s, e)
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
            .collect();
        let name = Ident::new(format!("AT{name}"), location.span);
        vec![VarDecl {
            name,
            location: Some(location),
            ty,
            init,
            edge: None,
            span: self.span(l, r),
        }]
    }

    /// Converts `v` to the integer type the tree stores (a string length, a repeat count, a priority); out
    /// of range is error E0005 and gives `T::default()`.
    pub fn int_in<T>(&mut self, v: i128, what: &str, l: usize, r: usize) -> T
    where
        T: TryFrom<i128> + Default,
    {
        T::try_from(v).unwrap_or_else(|_| {
            self.hint(
                code::E0005,
                format!("{what} `{v}` is out of range"),
                l,
                r,
                &format!("write a non-negative {what} that fits the target"),
            );
            T::default()
        })
    }

    /// The values of an enumeration or of a data type with named values, in order: a value given
    /// as a constant expression is evaluated with the values named before it known by their names
    /// (`White := Red OR Green OR Blue`, IEC 61131-3 ed. 3, Table 11), and with the constants
    /// declared before; one that has no value is E0022 (and numbered as if it were left out).
    pub fn enum_values(&mut self, raw: Vec<RawEnumValue>) -> Vec<EnumValue> {
        let mut values: Vec<EnumValue> = Vec::with_capacity(raw.len());
        // the constants the values shadow while the list is read, restored after it
        let mut shadowed: Vec<(String, Option<ConstNum>)> = Vec::new();
        let mut next = 0i128;
        for (name, expr) in raw {
            let value = match expr {
                None => None,
                Some((BoundExpr::Int(v, _), _, _)) => Some(v),
                Some((e, l, r)) => self.const_expr(e, l, r, false),
            };
            let number = value.unwrap_or(next);
            next = number.saturating_add(1);
            let key = name.name.to_ascii_uppercase();
            if !shadowed.iter().any(|(k, _)| *k == key) {
                let before = self.consts.get(&key).copied();
                shadowed.push((key.clone(), before));
            }
            self.consts.insert(key, ConstNum::Int(number));
            values.push(EnumValue { name, value });
        }
        for (key, before) in shadowed {
            match before {
                Some(v) => self.consts.insert(key, v),
                None => self.consts.remove(&key),
            };
        }
        values
    }

    /// Checks the base type of an edition-3 data type with named values (`INT (Low := 1, High := 100)`,
    /// IEC 61131-3 6.4.4.3): ladderc reads it as an enumeration, so the base must be an elementary
    /// integer or bit-string type, else error E0011 at the base type's name (edition 3's Annex A
    /// allows any elementary base, `LREAL (Home := 0.0)`: a limit of ladderc). Then that E0011 is
    /// the one error of the type: the E0022 of its values up to `end` (`0.0` is no integer) are
    /// withdrawn (round 32, before: one more error per value). The values are kept as an
    /// enumeration's; the base type is not.
    pub fn named_values_base(&mut self, base: &Ident, l: usize, r: usize, end: usize) {
        const INTEGER_TYPES: [&str; 12] = [
            "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "BYTE", "WORD",
            "DWORD", "LWORD",
        ];
        if !INTEGER_TYPES.contains(&base.key().as_str()) {
            let values = self.span(r, end);
            self.diags.retain(|d| {
                d.code != code::E0022
                    || !d.span.is_some_and(|s| {
                        s.file == values.file && s.start >= values.start && s.end <= values.end
                    })
            });
            self.hint(
                code::E0011,
                format!("`{}` cannot carry named values in ladderc", base.name),
                l,
                r,
                "ladderc reads a data type with named values as an enumeration, on an integer or bit-string base (`INT (Low := 1, High := 100)`); for other values declare VAR_GLOBAL CONSTANTs of the base type",
            );
        }
    }

    // ------------------------------------------------------------ configurations

    /// Builds a configuration; tasks and programs written outside any `RESOURCE` go to a resource named
    /// after the configuration (also when there is no resource at all).
    pub fn configuration(
        &mut self,
        name: Ident,
        items: Vec<ConfigItem>,
        l: usize,
        r: usize,
    ) -> Configuration {
        let mut globals = Vec::new();
        let mut resources = Vec::new();
        let mut loose = Resource {
            name: name.clone(),
            on: None,
            globals: Vec::new(),
            tasks: Vec::new(),
            programs: Vec::new(),
            span: self.span(l, r),
        };
        for item in items {
            match item {
                ConfigItem::Vars(v) => globals.push(v),
                ConfigItem::Resource(res) => resources.push(*res),
                ConfigItem::Task(t) => loose.tasks.push(*t),
                ConfigItem::Program(p) => loose.programs.push(*p),
                ConfigItem::Nothing => {}
            }
        }
        if !loose.tasks.is_empty() || !loose.programs.is_empty() || resources.is_empty() {
            resources.push(loose);
        }
        Configuration {
            name,
            globals,
            resources,
            access: Vec::new(),
            span: self.span(l, r),
        }
    }

    /// Builds a resource; a nested `RESOURCE` is error E0011 (dropped).
    pub fn resource(
        &mut self,
        name: Ident,
        on: Option<Ident>,
        items: Vec<ConfigItem>,
        l: usize,
        r: usize,
    ) -> Resource {
        let mut res = Resource {
            name,
            on,
            globals: Vec::new(),
            tasks: Vec::new(),
            programs: Vec::new(),
            span: self.span(l, r),
        };
        for item in items {
            match item {
                ConfigItem::Vars(v) => res.globals.push(v),
                ConfigItem::Task(t) => res.tasks.push(*t),
                ConfigItem::Program(p) => res.programs.push(*p),
                ConfigItem::Resource(inner) => {
                    let (s, e) = self.local(inner.name.span);
                    self.hint(
                        code::E0011,
                        "a RESOURCE cannot contain another RESOURCE",
                        s,
                        e,
                        "close the first resource with END_RESOURCE",
                    );
                }
                ConfigItem::Nothing => {}
            }
        }
        res
    }

    /// Builds a task from its `INTERVAL`, `SINGLE`, `PRIORITY` settings; any other setting, or a priority
    /// that is not a non-negative integer, is error E0020.
    pub fn task(
        &mut self,
        name: Ident,
        settings: Vec<(Ident, Operand)>,
        l: usize,
        r: usize,
    ) -> Task {
        let mut task = Task {
            name,
            interval: None,
            single: None,
            priority: None,
            span: self.span(l, r),
        };
        for (key, value) in settings {
            let (s, e) = self.local(key.span.to(value.span()));
            match key.key().as_str() {
                "INTERVAL" => task.interval = Some(value),
                "SINGLE" => task.single = Some(value),
                "PRIORITY" => match &value {
                    Operand::Literal(l) if matches!(l.kind, LiteralKind::Int(p) if u32::try_from(p).is_ok()) => {
                        task.priority = match l.kind {
                            LiteralKind::Int(p) => u32::try_from(p).ok(),
                            _ => None,
                        }
                    }
                    _ => self.hint(
                        code::E0020,
                        "task priority must be a non-negative integer",
                        s,
                        e,
                        "write e.g. `PRIORITY := 1` (0 is the highest priority)",
                    ),
                },
                _ => self.hint(
                    code::E0020,
                    format!("`{}` is not a task setting", key.name),
                    s,
                    e,
                    "a TASK takes INTERVAL, SINGLE and PRIORITY",
                ),
            }
        }
        task
    }

    // ------------------------------------------------------------ errors

    fn local(&self, span: Span) -> (usize, usize) {
        (
            (span.start as usize).saturating_sub(self.base),
            (span.end as usize).saturating_sub(self.base),
        )
    }

    /// Reports a syntax error the grammar recovered from (lexer error tokens were reported already).
    pub fn recover(&mut self, e: ErrorRecovery<usize, Tok, ()>) {
        let (s, tok, end, expected) = match e.error {
            ParseError::UnrecognizedToken {
                token: (s, tok, end),
                expected,
            } => (s, tok, end, expected),
            ParseError::UnrecognizedEof { location, expected } => {
                (location, Tok::Eol, location, expected)
            }
            ParseError::ExtraToken {
                token: (s, tok, end),
            } => (s, tok, end, Vec::new()),
            ParseError::InvalidToken { location } => (location, Tok::Error, location, Vec::new()),
            ParseError::User { .. } => return,
        };
        if tok == Tok::Error {
            return;
        }
        // A run of lines is reported as its first line's token would be.
        let tok = match tok {
            Tok::Lines(mut lines) if !lines.is_empty() => lines.swap_remove(0).1.into_tok(),
            other => other,
        };
        // A simple, jump or label line is two tokens of the source: the error is at its first (the
        // second is skipped with the rest of the line, as it would be on its own).
        let (tok, end) = match tok {
            Tok::SimpleLine((_, _, w), ..) | Tok::SimpleIntLine((_, _, w), ..) => {
                (Tok::Word(w), s + word_len(self.src, s))
            }
            Tok::JumpLine(c, ..) => {
                let w = match c {
                    Condition::Always => Word::Jmp,
                    Condition::IfTrue => Word::Jmpc,
                    Condition::IfFalse => Word::Jmpcn,
                };
                (Tok::Word(w), s + word_len(self.src, s))
            }
            Tok::LabelLine(_, name_end) => (Tok::Word(Word::Ident), name_end),
            other => (other, end),
        };
        let text = self.text(s, end);
        let found = if end == s && tok != Tok::Eol {
            match &tok {
                Tok::Word(w) => format!("`{}`", w.spelling()),
                _ => "end of block".to_string(),
            }
        } else {
            tok.describe(text)
        };
        // where a declaration may start (after a `;`, or where the block may end), another `;` is
        // expected only as an empty declaration (which TwinCAT compiles): it is not what the text
        // lacks, so it is left out of the message
        let decl_start = expected
            .iter()
            .any(|x| x == "\"END_VAR\"" || x == "\"END_STRUCT\"");
        let expected: Vec<String> =
            if decl_start || self.src[..end_of_previous(self.src, s)].ends_with(';') {
                expected.into_iter().filter(|x| x != "\";\"").collect()
            } else {
                expected
            };
        let expect = summarize_expected(&expected);
        let eol_expected = expected.iter().any(|x| x == "EOL");
        let semi_expected = expected.iter().any(|x| x == "\";\"");
        let line_start = self.src[..s].rfind('\n').map_or(0, |i| i + 1);
        let before = self.src[line_start..s].trim();
        let at_line_start = before.is_empty() || before.ends_with(':');
        let only_assign =
            !expected.is_empty() && expected.iter().all(|x| x == "\":=\"" || x == "\"=>\"");
        let type_expected = expected.iter().any(|x| x == "\"ARRAY\"");
        let (msg, hint) = if type_expected {
            (
                format!("expected a type, found {found}"),
                "write a type such as INT, BOOL, TIME, STRING[10], ARRAY [1..10] OF INT or a declared type"
                    .to_string(),
            )
        } else if only_assign {
            (
                format!("expected `:=` or `=>` before {found}"),
                "the arguments of a call are all formal (`IN := x, Q => y`) or all non-formal (`x, y`)"
                    .to_string(),
            )
        } else if tok == Tok::RParen && eol_expected && at_line_start {
            (
                "unmatched `)`".to_string(),
                "a `)` on its own line closes a deferred operator such as `AND(`; remove it"
                    .to_string(),
            )
        } else if eol_expected && at_line_start && tok != Tok::Eol {
            (
                format!("unexpected {found}"),
                "expected an instruction, a label or a declaration block".to_string(),
            )
        } else if semi_expected && !eol_expected && tok != Tok::Semi {
            if text.eq_ignore_ascii_case("AT") {
                // `x : UINT AT %MW0;`: the location written after the type
                (
                    format!("expected `;` before {found}"),
                    "IEC 61131-3 writes the location between the name and the type: `name AT %MW0 : UINT := 0;`".to_string(),
                )
            } else {
                // `a : INT` and the next declaration on the following line: the `;` belongs after
                // the first, where the error is
                let at = end_of_previous(self.src, s);
                let decl_start = self.src[..at].rfind('\n').map_or(0, |i| i + 1);
                let decl = self.src[decl_start..at].trim();
                if at < s && !decl.is_empty() && decl.chars().count() <= 60 {
                    self.hint(
                        code::E0011,
                        format!("missing `;` after `{decl}` before {found}"),
                        at,
                        at,
                        &format!(
                            "end each declaration with `;` (`{decl};`): IEC 61131-3, CODESYS and TwinCAT require it"
                        ),
                    );
                    return;
                }
                (
                    format!("expected `;` before {found}"),
                    "end each declaration with `;`".to_string(),
                )
            }
        } else if tok == Tok::Eol {
            (
                format!("unexpected end of line; expected {expect}"),
                "complete the instruction or declaration on this line".to_string(),
            )
        } else if eol_expected {
            (
                format!("unexpected {found} after the instruction"),
                "an instruction ends at the end of its line: one operator and at most one operand per line"
                    .to_string(),
            )
        } else {
            (format!("unexpected {found}"), format!("expected {expect}"))
        };
        let (s, end) = if tok == Tok::Eol { (s, s) } else { (s, end) };
        // `RETAIN : BOOL;` in a VAR block: the qualifier keyword was read as the block's, and the
        // `:` is unexpected; the name is the problem
        if tok == Tok::Colon
            && !before.is_empty()
            && before
                .bytes()
                .all(|b| b.is_ascii_alphanumeric() || b == b'_')
            && crate::sema::reserved_name(before) == Some("a keyword")
        {
            let at = line_start
                + (self.src[line_start..s].len() - self.src[line_start..s].trim_start().len());
            self.hint(
                code::E1031,
                format!(
                    "`{before}` is reserved in IEC 61131-3 (a keyword): it cannot name a variable"
                ),
                at,
                at + before.len(),
                &format!("rename the variable, for example `x{before}`"),
            );
            return;
        }
        // a keyword where a variable's name is expected (`VAR TRUE : BOOL;`): say it is reserved
        let word = text.trim();
        if expect.starts_with("a name")
            && hint == format!("expected {expect}")
            && !word.to_ascii_uppercase().starts_with("END_")
            && !word.is_empty()
            && crate::sema::reserved_name(word).is_some()
        {
            let why = crate::sema::reserved_name(word).unwrap_or("a keyword");
            self.hint(
                code::E1031,
                format!("`{word}` is reserved in IEC 61131-3 ({why}): it cannot name a variable"),
                s,
                end,
                &format!("rename the variable, for example `x{word}`"),
            );
            return;
        }
        // a use of a variable whose reserved name was already reported at its declaration
        // (`VAR ON : BOOL;` then `LD ON`): E1031 is the one located error, no cascade
        let reported = format!("`{}` IS RESERVED", word.to_ascii_uppercase());
        if !word.is_empty()
            && self.diags.iter().any(|d| {
                d.code == code::E1031 && d.message.to_ascii_uppercase().starts_with(&reported)
            })
        {
            return;
        }
        self.hint(code::E0011, msg, s, end, &hint);
    }
}

/// The end of the text before `at`, past blanks and one `(* comment *)` that ends there: where a
/// missing `;` belongs.
fn end_of_previous(src: &str, at: usize) -> usize {
    let at = at.min(src.len());
    let mut t = src[..at].trim_end();
    if t.ends_with("*)") {
        if let Some(open) = t.rfind("(*") {
            t = t[..open].trim_end();
        }
    }
    t.len()
}

/// A body that reaches this many statements (a power of two: the list's capacity then, grown by
/// doubling from empty) gets room for the rest of its text at once ([`long_body_hint`]).
const LONG_BODY: usize = 4096;

/// A body that reaches this many statements (a power of two, as [`LONG_BODY`]) gets room for
/// [`LONG_BODY`] at once, instead of being regrown (and copied) three times on the way: the room
/// not used is never touched, and [`Ctx::pou`] gives it back. The 50 POUs of 2,000 lines of the
/// benchmark copied 7 MB less (crates/ladderc/BENCHMARKS.md, Round 17).
const MEDIUM_BODY: usize = 256;

/// Room for the statements of a long body still to come, estimated from the bytes per statement
/// of its first [`LONG_BODY`] (`first` and `here`) and the text left up to `text_end`: the list of
/// a long body is then not regrown by doubling (each regrowth copied it into fresh pages: a
/// 1,000,000-line POU's 88 MB list touched about 90 MB more). The estimate reaches to the end of the
/// text, past the POU's end when other POUs follow; the room not used is never touched, and
/// [`Ctx::pou`] gives it back (`shrink_to_fit` keeps a large list where it is).
fn long_body_hint(first: &IlStmt, here: &IlStmt, text_end: usize) -> usize {
    let start = |s: &IlStmt| match s {
        IlStmt::Label(i) => i.span.start as usize,
        IlStmt::Instr(i) => i.span.start as usize,
    };
    let (first, here) = (start(first), start(here));
    // at least 4 bytes per statement (`l:` and a line end, `LD a`): a bound on the room asked for
    let per = (here.saturating_sub(first) / LONG_BODY).max(4);
    text_end.saturating_sub(here) / per + 1
}

/// Byte length of the word starting at `at` (an operator keyword).
fn word_len(src: &str, at: usize) -> usize {
    src[at..]
        .bytes()
        .take_while(|b| b.is_ascii_alphanumeric() || *b == b'_' || *b == b'&')
        .count()
}

/// The expected-token list of a syntax error in words (names and operands grouped).
fn summarize_expected(expected: &[String]) -> String {
    let has = |t: &str| expected.iter().any(|x| x == t);
    let mut parts: Vec<String> = Vec::new();
    let operand = has("IDENT") && has("INT");
    if operand {
        parts.push("an operand".into());
    } else if has("IDENT") {
        parts.push("a name".into());
    } else if has("INT") {
        parts.push("a number".into());
    }
    if has("EOL") {
        parts.push("end of line".into());
    }
    for x in expected {
        let t = x.trim_matches('"');
        if x.starts_with('"') && !parts.iter().any(|p| p.contains(t)) {
            let name_like = t
                .chars()
                .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_')
                && (crate::lexer::classify(t).is_name()
                    || matches!(t, "ON" | "TASK" | "WITH" | "CONFIGURATION" | "RESOURCE"));
            if (operand || has("IDENT")) && name_like {
                continue;
            }
            if matches!(t, "R_EDGE" | "F_EDGE") || (operand && matches!(t, "TRUE" | "FALSE")) {
                continue;
            }
            parts.push(format!("`{t}`"));
        }
    }
    if parts.is_empty() {
        return "something else".into();
    }
    if parts.len() > 6 {
        parts.truncate(6);
        parts.push("...".into());
    }
    parts.join(", ")
}

thread_local! {
    /// The integer constants of the project's other files (their `VAR_GLOBAL CONSTANT` lists) that
    /// the bounds and lengths of the text being parsed may name: set for the time of one call of
    /// [`with_other_files_constants`], empty otherwise.
    static OTHER_FILES_CONSTANTS: std::cell::RefCell<Constants> =
        Default::default();
}

/// Runs `parse` with `constants` (upper-case name to value) known to every bound expression and
/// integer initial value it parses, as if declared before the text (a text's own constants of the
/// same name take their place from their declaration on).
pub fn with_other_files_constants<R>(constants: Constants, parse: impl FnOnce() -> R) -> R {
    let before = OTHER_FILES_CONSTANTS.with(|c| c.replace(constants));
    let result = parse();
    OTHER_FILES_CONSTANTS.with(|c| c.replace(before));
    result
}

/// The constants `unit` offers the project's other files: the names of its `VAR_GLOBAL CONSTANT`
/// lists (top level, configuration, resource) whose initial value is a numeric or duration literal
/// or a constant expression that evaluated (one with an E0022 among `diags` is left out), by
/// upper-case name, in their declared types. A POU's own `VAR CONSTANT` stays in its file.
pub fn global_integer_constants(unit: &CompilationUnit, diags: &Diagnostics) -> Constants {
    integer_constants(unit, diags, false)
}

/// The integer (and real, duration) constants of `unit` as [`global_integer_constants`], and with
/// `pous` also those of its POUs' `VAR CONSTANT` blocks: a file's own constants, offered to its
/// parse again when a bound named one declared after it (`ARRAY[0..TABLESIZE - 1]` above the
/// POU's `VAR CONSTANT TABLESIZE`, as CODESYS and TwinCAT resolve names, not order).
pub fn integer_constants(unit: &CompilationUnit, diags: &Diagnostics, pous: bool) -> Constants {
    integer_constants_knowing(unit, diags, pous, &Constants::new())
}

/// [`integer_constants`], with the enumerations' values of `known` (the project's other files'
/// constants: `N : INT := E_Topic.COUNT_OF;` of a TwinCAT DUT's enumeration).
pub fn integer_constants_knowing(
    unit: &CompilationUnit,
    diags: &Diagnostics,
    pous: bool,
    known: &Constants,
) -> Constants {
    let mut found = Constants::new();
    let failed = |span: Span| {
        diags.iter().any(|d| {
            d.code == code::E0022
                && d.span.is_some_and(|s| {
                    s.file == span.file && s.start >= span.start && s.end <= span.end
                })
        })
    };
    // a TwinCAT DUT's enumeration bounds the arrays of other objects, and gives the value of a
    // constant (`N : INT := E_Topic.COUNT_OF;`)
    for item in &unit.items {
        if let LibraryElement::DataTypes(types) = item {
            for t in types {
                if let TypeDef::Enum { values, .. } = &t.def {
                    crate::const_eval::add_enum_values(&mut found, &t.name.name, values);
                }
            }
        }
    }
    let mut add = |block: &VarBlock| {
        if !block.constant
            || !(block.kind == VarKind::Global || pous && block.kind == VarKind::Local)
        {
            return;
        }
        for v in &block.vars {
            let value = match &v.init {
                Some(Initializer::Value(Operand::Literal(lit))) => ConstNum::of_literal(lit),
                // `MAX_SIZE : INT := nJoints;`: a constant named before (CODESYS GVLs)
                Some(Initializer::Value(Operand::Var(r)))
                    if r.accessors.is_empty()
                        && found.contains_key(&r.base.name.to_ascii_uppercase()) =>
                {
                    found.get(&r.base.name.to_ascii_uppercase()).copied()
                }
                // `N : INT := E_Topic.COUNT_OF;` (an enumeration of the unit)
                Some(Initializer::Value(op)) => crate::const_eval::enum_operand_value(&found, op)
                    .or_else(|| crate::const_eval::enum_operand_value(known, op)),
                _ => None,
            };
            let value = value.and_then(|n| crate::const_eval::as_declared(n, &v.ty));
            if let Some(n) = value.filter(|_| !failed(v.span)) {
                found.insert(v.name.name.to_ascii_uppercase(), n);
            }
        }
    };
    for item in &unit.items {
        match item {
            LibraryElement::GlobalVars(b) => add(b),
            LibraryElement::Pou(p) if pous => p.var_blocks.iter().for_each(&mut add),
            LibraryElement::Configuration(c) => {
                c.globals.iter().for_each(&mut add);
                c.resources
                    .iter()
                    .flat_map(|r| &r.globals)
                    .for_each(&mut add);
            }
            _ => {}
        }
    }
    found
}

/// Parses `src` as tokens of `start` kind; diagnostics (lexer, layout, grammar) go to `diags`.
pub(crate) fn run(
    file: FileId,
    src: &str,
    base: usize,
    start: Tok,
    diags: &mut Diagnostics,
    declared: Vec<String>,
) -> Option<Parsed> {
    let mut layout = Layout::new(file, src, base, start).with_declared(declared);
    #[cfg(test)]
    if !tests::LINE_RUNS.get() {
        layout = layout.without_line_runs();
    }
    let mut ctx = Ctx {
        file,
        src,
        base,
        diags: Vec::new(),
        consts: OTHER_FILES_CONSTANTS.with(|c| c.borrow().clone()),
        in_constant_block: false,
        sized_vars: Default::default(),
        sized_globals: Default::default(),
    };
    let result = grammar::StartParser::new().parse(&mut ctx, &mut layout);
    let mut all = std::mem::take(&mut layout.diags);
    all.append(&mut ctx.diags);
    let parsed = match result {
        Ok(p) => Some(p),
        Err(e) => {
            ctx.recover(ErrorRecovery {
                error: e,
                dropped_tokens: Vec::new(),
            });
            all.append(&mut ctx.diags);
            None
        }
    };
    let mut parsed = parsed;
    match &mut parsed {
        Some(Parsed::Unit(top)) => {
            for item in &mut top.items {
                if let LibraryElement::Pou(p) = item {
                    cap_nesting(&mut p.body, src, base, &mut all);
                }
            }
            if let Some((_, _, body)) = &mut top.implicit {
                cap_nesting(body, src, base, &mut all);
            }
        }
        Some(Parsed::Body(body)) => cap_nesting(body, src, base, &mut all),
        None => {}
    }
    // Lexer/layout diagnostics and grammar diagnostics interleave by position.
    all.sort_by_key(|d| d.span.map(|s| (s.start, s.end)));
    one_error_per_list(src, base, &mut all);
    diags.extend(all);
    parsed
}

/// The text of `src` without its `(* ... *)` comments and strings (their bytes blanked): what
/// [`one_error_per_list`] counts parentheses in.
fn without_comments(src: &str) -> Vec<u8> {
    let b = src.as_bytes();
    let mut out = b.to_vec();
    let mut k = 0;
    while k < b.len() {
        let end = if b[k..].starts_with(b"(*") {
            src[k + 2..].find("*)").map_or(b.len(), |e| k + 2 + e + 2)
        } else if b[k..].starts_with(b"//") {
            src[k..].find('\n').map_or(b.len(), |e| k + e)
        } else if b[k] == b'\'' || b[k] == b'"' {
            let q = b[k];
            b[k + 1..]
                .iter()
                .position(|&c| c == q || c == b'\n')
                .map_or(b.len(), |e| k + 1 + e + 1)
                .min(b.len())
        } else {
            k += 1;
            continue;
        };
        for c in &mut out[k..end] {
            if *c != b'\n' {
                *c = b' ';
            }
        }
        k = end;
    }
    out
}

/// One error for one broken parenthesised IL list (issue #13: one cause, one diagnostic):
/// - after `expected `:=` or `=>`` in a formal CAL's argument list (`Q` alone on its line,
///   `=> done,` on the next: IEC 61131-3 ed. 2 B.2.2 puts one assignment on one line), the syntax
///   errors up to the list's `)` are left out;
/// - a `)` on its own line is no "unmatched `)`" when an earlier line that holds an error opened
///   a parenthesis (`ADD( %MF3` with an invalid operand: the grammar dropped that line, its `)`
///   matches it).
fn one_error_per_list(src: &str, base: usize, all: &mut Vec<Diagnostic>) {
    let local = |d: &Diagnostic| {
        d.span
            .map(|s| (s.start as usize).saturating_sub(base).min(src.len()))
    };
    let is = |d: &Diagnostic, start: &str| d.code == code::E0011 && d.message.starts_with(start);
    let broken_list = |d: &Diagnostic| is(d, "expected `:=` or `=>`");
    let unmatched = |d: &Diagnostic| is(d, "unmatched `)`");
    if !all.iter().any(|d| broken_list(d) || unmatched(d)) {
        return;
    }
    let text = without_comments(src);
    // the byte after the `)` that closes the list open at `from`
    let list_end = |from: usize| {
        let mut depth = 0usize;
        for (k, &c) in text.iter().enumerate().skip(from) {
            match c {
                b'(' => depth += 1,
                b')' if depth == 0 => return k + 1,
                b')' => depth -= 1,
                _ => {}
            }
        }
        text.len()
    };
    let mut quiet: Vec<(usize, usize)> = Vec::new();
    // the lines with an error that open more parentheses than they close: (line start, count)
    let mut openers: Vec<(usize, usize)> = Vec::new();
    for d in all.iter() {
        let Some(at) = local(d) else { continue };
        if broken_list(d) {
            quiet.push((at, list_end(at)));
        }
        if d.severity != diagnostics::Severity::Error || unmatched(d) {
            continue;
        }
        let start = src[..at].rfind('\n').map_or(0, |i| i + 1);
        let end = src[at..].find('\n').map_or(src.len(), |i| at + i);
        let line = &text[start..end];
        let open = line.iter().filter(|&&c| c == b'(').count();
        let close = line.iter().filter(|&&c| c == b')').count();
        if open > close && !openers.iter().any(|o| o.0 == start) {
            openers.push((start, open - close));
        }
    }
    all.retain(|d| {
        let Some(at) = local(d) else { return true };
        if d.code == code::E0011 && quiet.iter().any(|&(s, e)| at > s && at < e) {
            return false;
        }
        if unmatched(d) {
            if let Some(o) = openers.iter_mut().rev().find(|o| o.0 < at && o.1 > 0) {
                o.1 -= 1;
                return false;
            }
        }
        true
    });
}

/// The deepest nesting of parenthesised lists (`AND( ... ADD( ... ) ... )`) accepted in IL.
pub const MAX_NESTING: usize = 2000;

/// The deepest array type (`ARRAY [..] OF ARRAY [..] OF ...`, E0211) and initializer (`[[[...]]]`,
/// `(a := (b := ...))`, E0212) a declaration may nest. Types and initializers are walked recursively
/// by the semantic checks and the C generation; real programs nest a few levels.
pub const MAX_TYPE_NESTING: usize = 64;

/// Reports (E0200, once per body) and empties every nested list deeper than [`MAX_NESTING`], so
/// later stages (sema, C, and the C compiler's own parser) never see unbounded nesting. The walk
/// uses an explicit stack.
fn cap_nesting(body: &mut [IlStmt], src: &str, base: usize, diags: &mut Vec<Diagnostic>) {
    let mut reported = false;
    let mut stack: Vec<(&mut [IlStmt], usize)> = vec![(body, 0)];
    while let Some((list, depth)) = stack.pop() {
        for s in list.iter_mut() {
            let IlStmt::Instr(i) = s else { continue };
            let span = i.span;
            let InstrKind::Deferred { body, .. } = &mut i.kind else {
                continue;
            };
            if depth < MAX_NESTING {
                stack.push((body.as_mut_slice(), depth + 1));
                continue;
            }
            body.clear();
            if !reported {
                reported = true;
                // the label covers the operator up to its `(`, not the whole list
                let start = span.start as usize;
                let open = src
                    .get(start.saturating_sub(base)..)
                    .and_then(|t| t.find('('))
                    .map_or(span.end as usize, |k| start + k + 1);
                let span = Span::new(span.file, start, open.min(span.end as usize));
                diags.push(
                    Diagnostic::error(
                        code::E0200,
                        format!("parenthesised lists are nested more than {MAX_NESTING} deep"),
                    )
                    .at(span)
                    .with_primary_label(format!("level {}", depth + 1))
                    .with_hint(
                        "compute inner parts into variables first (`ST tmp`) and use them as operands",
                    ),
                );
            }
        }
    }
}

/// The implicit program's warning (W0001).
pub(crate) fn implicit_program_warning(at: Span, name: &str) -> Diagnostic {
    Diagnostic::new(
        code::W0001,
        Severity::Warning,
        "instructions outside any POU".to_string(),
    )
    .at(at)
    .with_primary_label(format!(
        "accepted as the body of an implicit `PROGRAM {name}`"
    ))
    .with_hint(format!(
        "wrap the instructions in `PROGRAM {name}` ... `END_PROGRAM` to silence this warning"
    ))
}

/// The span of an initializer written with brackets or parentheses.
fn init_span(i: &Initializer) -> Option<Span> {
    match i {
        Initializer::Array(_, s) | Initializer::Struct(_, s) => Some(*s),
        Initializer::Value(_) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    thread_local! {
        /// Whether [`run`]'s layout pass passes runs of plain lines as one token (this thread's
        /// parses; the tests below compare the two ways).
        pub(super) static LINE_RUNS: std::cell::Cell<bool> = const { std::cell::Cell::new(true) };
    }

    /// A syntax error at a simple, jump or label line (`LD x`, `ADD 5`, `JMPC l`, `l:` as one token)
    /// is the error at its first token: the same message, span and hint as for that token alone.
    #[test]
    fn an_error_at_a_simple_line_is_at_its_first_token() {
        let src = "FUNCTION f : INT\n  LDN x_1\n  ADD 5\n  JMPC l\n  l:\n";
        let report = |at: usize, tok: Tok, end: usize| {
            let mut ctx = Ctx {
                file: FileId(0),
                src,
                base: 0,
                diags: Vec::new(),
                consts: Default::default(),
                in_constant_block: false,
                sized_vars: Default::default(),
                sized_globals: Default::default(),
            };
            ctx.recover(ErrorRecovery {
                error: ParseError::UnrecognizedToken {
                    token: (at, tok, end),
                    expected: vec!["\"END_VAR\"".to_string(), "\";\"".to_string()],
                },
                dropped_tokens: Vec::new(),
            });
            ctx.diags
                .iter()
                .map(|d| format!("{} {} {:?} {:?}", d.code, d.message, d.span, d.hint))
                .collect::<Vec<_>>()
        };
        let find = |t: &str| src.find(t).expect("in the text");
        let cases = [
            (
                "LDN",
                Tok::SimpleLine((Op::Ld, true, Word::Ldn), find("x_1"), find("x_1") + 3),
                find("x_1") + 3,
                Tok::Word(Word::Ldn),
            ),
            (
                "ADD",
                Tok::SimpleIntLine((Op::Add, false, Word::Add), 5, find("5"), find("5") + 1),
                find("5") + 1,
                Tok::Word(Word::Add),
            ),
            (
                "JMPC",
                Tok::JumpLine(Condition::IfTrue, find("l\n"), find("l\n") + 1),
                find("l\n") + 1,
                Tok::Word(Word::Jmpc),
            ),
            (
                "l:",
                Tok::LabelLine(find("l:"), find("l:") + 1),
                find("l:") + 2,
                Tok::Word(Word::Ident),
            ),
        ];
        for (first, line, end, alone) in cases {
            let at = find(first);
            let first = first.trim_end_matches(':');
            let line = report(at, line, end);
            assert_eq!(line, report(at, alone, at + first.len()), "{first}");
            assert_eq!(line.len(), 1);
            assert!(line[0].contains(&format!("`{first}`")), "{line:?}");
        }
    }

    /// `src` parsed as a file and as an instruction list alone (at offset 3 of its file), with and
    /// without runs of plain lines ([`Tok::Lines`]): the trees (spans included) and the diagnostics,
    /// in the `Debug` notation.
    fn both_ways(src: &str) -> [String; 2] {
        [true, false].map(|runs| {
            LINE_RUNS.set(runs);
            let mut diags = Diagnostics::new();
            let unit = crate::parse(FileId(0), src, &mut diags);
            let body = crate::parse_body(FileId(0), src, 3, &mut diags);
            LINE_RUNS.set(true);
            format!("{unit:#?}\n{body:#?}\n{diags:#?}")
        })
    }

    /// Lines of IL around the plain ones a run takes (`LD x`, `ADD 5`, `JMPC l`, `l:`): each
    /// program of them parses to the same tree and diagnostics with and without runs.
    const LINES: &[&str] = &[
        "LD x",
        "ld X_1",
        "LDN  a",
        "ST\tb",
        "STN b",
        "ADD 5",
        "ADD 007",
        "SUB 0",
        "S q",
        "R q",
        "MOD n",
        "GT 99999999999999999999999999999999999999999",
        "JMPC l1",
        "JMP l2",
        "jmpcn L1",
        "l1:",
        "l2 :",
        "L1:  ",
        "NOT x",
        "NOT",
        "LD",
        "ST",
        "JMP",
        "JMPC 5",
        "RET",
        "LD x.y",
        "LD x.3",
        "LD a[1]",
        "LD a[i].b",
        "LD INT#5",
        "LD 1_000",
        "ADD -5",
        "ADD +5",
        "ADD 5.0",
        "ADD 1e3",
        "ADD 16#FF",
        "ADD 5x",
        "LD TRUE",
        "LD t#5s",
        "LD 'str'",
        "LD x (* c *)",
        "(* c *) LD x",
        "(* a\nb *) LD x",
        "LD x // c",
        "LD x ; c",
        "AND( b",
        "AND(",
        "OR c",
        ")",
        "CAL t0(IN := x, PT := T#1s)",
        "CAL t0(",
        "IN := x,",
        "Q => y",
        "CAL t0",
        "LD %IX0.1",
        "LD x, y",
        "ADD x, 5",
        "LD END_VAR",
        "LD ld",
        "l1: LD x",
        "LD ?",
        "LD x y",
        "ST 5",
        "LD x\u{feff}",
        "\u{feff}LD x",
        "LD \u{e9}",
        "LD _",
        "LD x__y",
        "LD\u{c}x",
        "x",
        "5",
        "VAR x : INT; END_VAR",
        "VAR",
        "END_VAR",
        "END_PROGRAM",
        "END_FUNCTION",
        "PROGRAM q",
        "FUNCTION g : INT",
        "TYPE t : INT; END_TYPE",
        "",
        "   ",
        "\t",
        "MOD(IN1 := a, IN2 := b)",
        "LIMIT(1, 5)",
        "IN x",
        "PT t",
        "END",
        "LDx",
        "LD:",
        "l1::",
        "l1 := 5",
        "JMPC l1 l2",
    ];

    #[test]
    fn runs_of_plain_lines_parse_as_their_lines() {
        let lines = LINES;
        let heads = [
            "",
            "PROGRAM p\n",
            "PROGRAM p\nVAR x : INT; END_VAR\n",
            "FUNCTION f : INT\n",
            "FUNCTION_BLOCK fb\nVAR_INPUT a : BOOL; END_VAR\n",
            "PROGRAM\n",
            "PROGRAM p :\n",
        ];
        let tails = [
            "",
            "END_PROGRAM\n",
            "END_FUNCTION",
            "END_PROGRAM\nPROGRAM q\nLD x\n",
        ];
        let ends = ["\n", "\r\n", "\n\n", " \t\n", "\r"];
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = |n: usize| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % n as u64) as usize
        };
        let mut with_runs = 0;
        for case in 0..2000 {
            let mut src = heads[next(heads.len())].to_string();
            for _ in 0..1 + next(24) {
                src += ["", "  ", "\t", " \t "][next(4)];
                // mostly plain lines, as real programs are
                src += if next(3) > 0 {
                    lines[next(20)]
                } else {
                    lines[next(lines.len())]
                };
                src += ends[if next(4) > 0 {
                    next(2)
                } else {
                    next(ends.len())
                }];
            }
            src += tails[next(tails.len())];
            let [runs, apart] = both_ways(&src);
            assert_eq!(runs, apart, "case {case}: {src:?}");
            with_runs += usize::from(
                crate::layout::Layout::new(FileId(0), &src, 0, Tok::UnitStart)
                    .any(|t| matches!(t, Ok((_, Tok::Lines(_), _)))),
            );
        }
        // the runs were taken, not only the general way
        assert!(with_runs > 500, "{with_runs} of 2000 programs had a run");
    }

    /// A run is at most 256 lines; a body of 5,000 plain lines (runs, the last one short, and the
    /// room a long body gets at 4,096 statements) parses as without runs.
    #[test]
    fn long_runs_parse_as_their_lines() {
        let mut src = "PROGRAM p\nVAR x : INT; END_VAR\n".to_string();
        for i in 0..5000 {
            src += match i % 4 {
                0 => "  LD x\n",
                1 => "  ADD 1\r\n",
                2 => "  JMPC l\n",
                _ => "l:\n",
            };
        }
        src += "END_PROGRAM\n";
        let [runs, apart] = both_ways(&src);
        assert!(runs == apart);
        let sizes: Vec<usize> = crate::layout::Layout::new(FileId(0), &src, 0, Tok::UnitStart)
            .filter_map(|t| match t {
                Ok((_, Tok::Lines(l), _)) => Some(l.len()),
                _ => None,
            })
            .collect();
        assert_eq!(sizes.len(), 20);
        assert!(sizes[..19].iter().all(|&n| n == 256));
        assert_eq!(sizes[19], 5000 - 19 * 256);
    }

    /// Blank lines are looked past once: 200,000 of them before a line that is not plain (after
    /// a run and at the start of a body) parse in linear time, as without runs.
    #[test]
    fn many_blank_lines_are_looked_past_once() {
        let blank = "  \n".repeat(200_000);
        let src = format!(
            "PROGRAM p\nVAR x : INT; END_VAR\n{blank}  LD x\n{blank}  LD x.y\nEND_PROGRAM\n"
        );
        let start = std::time::Instant::now();
        let [runs, apart] = both_ways(&src);
        assert!(runs == apart);
        // quadratic, this would be some 10^11 steps; linear, well under a second in a debug build
        assert!(start.elapsed().as_secs() < 60, "{:?}", start.elapsed());
    }

    /// A run of lines where the grammar does not take one is reported as its first line's token.
    #[test]
    fn an_error_at_a_run_is_at_its_first_line() {
        let src = "  LD x\n  ST y\n";
        let report = |tok: Tok| {
            let mut ctx = Ctx {
                file: FileId(0),
                src,
                base: 0,
                diags: Vec::new(),
                consts: Default::default(),
                in_constant_block: false,
                sized_vars: Default::default(),
                sized_globals: Default::default(),
            };
            ctx.recover(ErrorRecovery {
                error: ParseError::UnrecognizedToken {
                    token: (2, tok, src.len()),
                    expected: vec!["\"END_VAR\"".to_string()],
                },
                dropped_tokens: Vec::new(),
            });
            format!("{:?}", ctx.diags)
        };
        let ld = (Op::Ld, false, Word::Ld);
        let run = Tok::Lines(vec![
            (2, LineTok::Simple(ld, 5, 6), 6),
            (9, LineTok::Simple((Op::St, false, Word::St), 12, 13), 13),
        ]);
        let first = report(run);
        assert_eq!(first, report(Tok::SimpleLine(ld, 5, 6)));
        assert!(
            first.contains("unexpected `LD`") && first.contains("end: 4 "),
            "{first}"
        );
    }
}
