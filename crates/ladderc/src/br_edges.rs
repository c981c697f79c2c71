//! B&R Automation Studio's edge operators `EDGEPOS(x)`, `EDGENEG(x)` and `EDGE(x)`: TRUE in the
//! call where `x` rose (fell, changed) since the previous call at the same place.
//!
//! Input: the user's parsed units (IL, ST already lowered: `LD x` then the operator with no other
//! argument). Output: each call in a PROGRAM or FUNCTION_BLOCK replaced by instructions on three
//! hidden BOOLs of its own (`__BR_EDGE<k>_IN`, `_M` the value at the previous call, `_Q`):
//! `ST IN`, the edge into `Q`, `LD IN ST M`, `LD Q`, so the current result is the edge as the
//! operator gives it. Invariants: the memory starts FALSE (a first call with `x` TRUE is a rising
//! edge, as a first R_TRIG call); a project that declares a POU of that name keeps its own; a
//! FUNCTION (no state between calls) keeps the call, and the checks report it (E1019); the
//! hidden names start with `__` (no user name can).

use il_frontend::ast::{
    CallArgs, CompilationUnit, Ident, IlStmt, InstrKind, Instruction, LibraryElement, Op, Operand,
    PouKind, TypeRef, VarDecl, VarRef,
};
use il_frontend::Span;

/// The operators: (name, negate the input, negate the memory, XOR instead of AND).
const OPERATORS: &[(&str, bool, bool, bool)] = &[
    ("EDGEPOS", false, true, false),
    ("EDGENEG", true, false, false),
    ("EDGE", false, false, true),
];

/// Rewrites the edge operators of every PROGRAM and FUNCTION_BLOCK (see the module header).
pub fn rewrite(units: &mut [CompilationUnit]) {
    let declared = |n: &str| {
        units
            .iter()
            .flat_map(|u| u.items.iter())
            .any(|i| matches!(i, LibraryElement::Pou(p) if p.name.name.eq_ignore_ascii_case(n)))
    };
    let wanted: Vec<&(&str, bool, bool, bool)> =
        OPERATORS.iter().filter(|o| !declared(o.0)).collect();
    if wanted.is_empty() {
        return;
    }
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        let LibraryElement::Pou(p) = item else {
            continue;
        };
        if p.kind == PouKind::Function {
            continue;
        }
        let mut count = 0usize;
        let mut hidden = Vec::new();
        stmts(&mut p.body, &wanted, &mut count, &mut hidden);
        if !hidden.is_empty() {
            crate::block_temps::add_hidden_vars(p, hidden);
        }
    }
}

fn stmts(
    body: &mut Vec<IlStmt>,
    wanted: &[&(&str, bool, bool, bool)],
    count: &mut usize,
    hidden: &mut Vec<VarDecl>,
) {
    let mut out = Vec::with_capacity(body.len());
    for mut s in std::mem::take(body) {
        if let IlStmt::Instr(i) = &mut s {
            if let InstrKind::Deferred { body: inner, .. } = &mut i.kind {
                stmts(inner, wanted, count, hidden);
            }
            if let InstrKind::FunctionCall { name, args } = &i.kind {
                let op = wanted.iter().find(|o| name.name.eq_ignore_ascii_case(o.0));
                if let (Some(op), CallArgs::None) = (op, &**args) {
                    *count += 1;
                    out.extend(edge(op, *count, i.span, hidden));
                    continue;
                }
            }
        }
        out.push(s);
    }
    *body = out;
}

/// The instructions of one operator call at `at`, the `k`-th of its POU; its hidden BOOLs pushed.
fn edge(
    &(_, not_in, not_m, xor): &(&str, bool, bool, bool),
    k: usize,
    at: Span,
    hidden: &mut Vec<VarDecl>,
) -> Vec<IlStmt> {
    let var = |what: &str| VarRef {
        base: Ident::new(format!("__BR_EDGE{k}_{what}"), at),
        accessors: Default::default(),
        span: at,
    };
    for what in ["IN", "M", "Q"] {
        hidden.push(VarDecl {
            name: var(what).base,
            location: None,
            ty: TypeRef::Named(Ident::new("BOOL", at)),
            init: None,
            edge: None,
            span: at,
        });
    }
    let simple = |op: Op, negate: bool, what: &str| {
        IlStmt::Instr(Instruction {
            kind: InstrKind::Simple {
                op,
                negate,
                operand: Some(Operand::Var(var(what))),
            },
            span: at,
        })
    };
    let combine = if xor { Op::Xor } else { Op::And };
    vec![
        simple(Op::St, false, "IN"),
        // rising: IN AND NOT M; falling: NOT IN AND M; any: IN XOR M
        simple(Op::Ld, not_in, "IN"),
        simple(combine, not_m, "M"),
        simple(Op::St, false, "Q"),
        simple(Op::Ld, false, "IN"),
        simple(Op::St, false, "M"),
        simple(Op::Ld, false, "Q"),
    ]
}
