//! Parts of the `ARRAY [*]` rewrite ([`super`]): the expressions it builds (names, integer
//! literals, operations, calls), whether an index calls something (W1432), and how two declared
//! types compare and read in a message (E1071).
//!
//! Input: ST expressions and declared types. Output: new expressions, answers, texts.
//! Invariants: no function here recurses on an expression (chains can be long); types are
//! compared through aliases, names case-insensitively.

use crate::ast::{Ident, LiteralKind, TypeRef};
use crate::st::ast::{Accessor, Arg, ArgDir, BinaryOp, Expr, ExprKind, Place, PlaceBase};
use crate::st::infer::Env;
use crate::Span;

pub(super) fn name_expr(name: String, span: Span) -> Expr {
    Expr {
        kind: ExprKind::Place(Place {
            base: PlaceBase::Name(Ident::new(name, span)),
            accessors: Vec::new(),
            span,
        }),
        span,
    }
}

pub(super) fn int(v: i128, span: Span) -> Expr {
    Expr::literal(LiteralKind::Int(v), span)
}

pub(super) fn binary(op: BinaryOp, left: Expr, right: Expr, span: Span) -> Expr {
    Expr {
        kind: ExprKind::Binary {
            op,
            left: Box::new(left),
            right: Box::new(right),
        },
        span,
    }
}

pub(super) fn call(name: &str, values: Vec<Expr>, span: Span) -> Expr {
    Expr {
        kind: ExprKind::Call {
            name: Ident::new(name, span),
            args: values
                .into_iter()
                .map(|value| Arg {
                    name: None,
                    dir: ArgDir::Input,
                    value,
                    span,
                })
                .collect(),
        },
        span,
    }
}

/// Whether `e` calls a function or a method (walked with a stack: chains can be long).
pub(super) fn calls_something(e: &Expr) -> bool {
    let mut stack = vec![e];
    while let Some(e) = stack.pop() {
        match &e.kind {
            ExprKind::Call { .. } => return true,
            ExprKind::Unary { operand, .. } => stack.push(operand),
            ExprKind::Binary { left, right, .. } => {
                stack.push(left);
                stack.push(right);
            }
            ExprKind::Place(p) => {
                for a in &p.accessors {
                    match a {
                        Accessor::Call { .. } => return true,
                        Accessor::Index(ix) => stack.extend(ix.iter()),
                        _ => {}
                    }
                }
            }
            _ => {}
        }
    }
    false
}

/// Whether two types as written are the same type (through aliases; names case-insensitive).
pub(super) fn same(env: &Env, a: &TypeRef, b: &TypeRef) -> bool {
    match (env.resolve(a), env.resolve(b)) {
        (TypeRef::Named(x), TypeRef::Named(y)) => x == y,
        (
            TypeRef::String {
                wide: w1,
                length: l1,
                ..
            },
            TypeRef::String {
                wide: w2,
                length: l2,
                ..
            },
        ) => w1 == w2 && l1.unwrap_or(254) == l2.unwrap_or(254),
        (
            TypeRef::Array {
                dims: d1,
                element: e1,
                ..
            },
            TypeRef::Array {
                dims: d2,
                element: e2,
                ..
            },
        ) => {
            d1.len() == d2.len()
                && d1
                    .iter()
                    .zip(&d2)
                    .all(|(x, y)| x.lower == y.lower && x.upper == y.upper)
                && same(env, &e1, &e2)
        }
        (TypeRef::Ref { target: t1, .. }, TypeRef::Ref { target: t2, .. }) => same(env, &t1, &t2),
        (
            TypeRef::Subrange {
                base: b1,
                lower: l1,
                upper: u1,
                ..
            },
            TypeRef::Subrange {
                base: b2,
                lower: l2,
                upper: u2,
                ..
            },
        ) => b1 == b2 && l1 == l2 && u1 == u2,
        _ => false,
    }
}

/// How a type reads in a message.
pub(super) fn text(env: &Env, t: &TypeRef) -> String {
    match env.resolve(t) {
        TypeRef::Named(n) => n.name.to_ascii_uppercase(),
        TypeRef::String { wide, length, .. } => format!(
            "{}({})",
            if wide { "WSTRING" } else { "STRING" },
            length.unwrap_or(254)
        ),
        TypeRef::Array { dims, element, .. } => {
            let dims: Vec<String> = dims
                .iter()
                .map(|d| {
                    if d.is_variable() {
                        "*".to_string()
                    } else {
                        format!("{}..{}", d.lower, d.upper)
                    }
                })
                .collect();
            format!("ARRAY [{}] OF {}", dims.join(", "), text(env, &element))
        }
        TypeRef::Ref { kind, target, .. } => format!("{} {}", kind.keyword(), text(env, &target)),
        TypeRef::Subrange { base, .. } => format!("a subrange of {}", base.name),
        TypeRef::Enum { .. } => "an enumeration".into(),
    }
}
