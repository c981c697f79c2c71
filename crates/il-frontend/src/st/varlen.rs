//! Variable-length arrays, `ARRAY [*] OF T` and `ARRAY [*, *] OF T` (IEC 61131-3 edition 3, 6.5.3;
//! CODESYS and TwinCAT "ARRAY OF" likewise): a VAR_IN_OUT of a FUNCTION, FUNCTION_BLOCK or METHOD
//! whose bounds are those of the array each call passes, read at run time with `LOWER_BOUND(x, d)`
//! and `UPPER_BOUND(x, d)`. TcUnit's array assertions are written so.
//!
//! How it is compiled: the parameter is a run-time descriptor of the actual array, three kinds of
//! hidden inputs that replace it in the same place among the parameters ([`split_decls`]):
//! `x__VLA : POINTER TO T` (the array's address, a bounded reference whose size is the whole
//! array: `ADR(arr)` at the call), and per dimension `d` its bounds `x__LB<d>`, `x__UB<d> : DINT`.
//! [`rewrite`] then changes each ST statement:
//! - a call that passes an array to such a parameter (formal or positional; a function, an FB
//!   instance, a method of an instance or of the block itself) passes `ADR(arr)` and the array's
//!   bounds (constants of its declared type), or forwards the descriptor of an `ARRAY [*]`
//!   parameter of the calling POU; an array of another element type or rank, no array, an
//!   expression or a missing argument is E1071;
//! - `x[i]` is `x__VLA[i - x__LB1]`; `x[i, j]` is `x__VLA[SEL(<every index within its bounds>, -1,
//!   <row-major offset>)]` (each index is then evaluated twice: W1432 when one calls a function).
//!   An index outside the actual bounds
//!   is thus an access outside the pointer's variable: zero read, write dropped, the first one
//!   named at the end of the run; no byte outside the array is ever reached;
//! - `LOWER_BOUND(x, d)` / `UPPER_BOUND(x, d)` are `x__LB<d>` / `x__UB<d>`;
//! - `x` used in any other way (a whole value, `SIZEOF`, a fixed-size parameter) is E1072.
//!
//! Input: the parsed units and pending bodies (before the declarations are indexed), then each ST
//! statement being lowered. Output: the declarations split; the statements rewritten.
//! Invariants: only VAR_IN_OUTs of FUNCTIONs, FUNCTION_BLOCKs and METHODs whose every dimension is
//! `*` are split; a statement is looked at without recursion first, and one of more than
//! `MAX_NODES` nodes (already E0109) is left as it is (any other `ARRAY [*]` reaches sema, which reports E1072); a statement that holds
//! no such parameter and no call of a POU that has one is not touched; a rewritten statement holds
//! no rewritable part any more.

use super::ast::{
    Accessor, Arg, ArgDir, BinaryOp, Expr, ExprKind, Place, PlaceBase, Stmt, StmtKind,
};
use super::file::PendingBody;
use super::infer::Env;
use crate::ast::{
    CompilationUnit, Ident, LibraryElement, LiteralKind, PouKind, RefKind, TypeRef, VarBlock,
    VarDecl, VarKind,
};
use crate::Span;
use diagnostics::{code, Diagnostic, Diagnostics};

mod parts;
use parts::{binary, call, calls_something, int, name_expr, same, text};

/// The suffix of the hidden input holding the actual array's address.
pub const ADDRESS: &str = "__VLA";
/// The address of an array passed to a FUNCTION's or METHOD's `ARRAY [*]` in-out: `ADR` for one
/// call ([`crate::ast::RefOperand::call_scoped`]), so that it may be a variable that lives for one
/// call (a function's, a method's VAR, a VAR_TEMP, a VAR_IN_OUT). No identifier can be written so
/// (IEC names do not start with two underscores).
pub const CALL_ADDRESS: &str = "__VLA_ADR";
/// The suffix (then the dimension, from 1) of the hidden inputs holding the lower bounds.
pub const LOWER: &str = "__LB";
/// The suffix (then the dimension, from 1) of the hidden inputs holding the upper bounds.
pub const UPPER: &str = "__UB";

/// Whether `ty` is `ARRAY [*, ...] OF T` with `*` in every dimension.
fn is_variable(ty: &TypeRef) -> bool {
    matches!(ty, TypeRef::Array { dims, .. } if !dims.is_empty() && dims.iter().all(|d| d.is_variable()))
}

/// The hidden inputs of the variable-length in-out `v`, in order.
fn hidden(v: &VarDecl) -> Vec<VarDecl> {
    let TypeRef::Array {
        dims,
        element,
        span,
    } = &v.ty
    else {
        return vec![v.clone()];
    };
    let at = v.name.span;
    let decl = |name: String, ty: TypeRef| VarDecl {
        name: Ident::new(name, at),
        location: None,
        ty,
        init: None,
        edge: None,
        span: v.span,
    };
    let mut out = vec![decl(
        format!("{}{ADDRESS}", v.name.name),
        TypeRef::Ref {
            kind: RefKind::Pointer,
            target: element.clone(),
            span: *span,
        },
    )];
    for d in 1..=dims.len() {
        for suffix in [LOWER, UPPER] {
            out.push(decl(
                format!("{}{suffix}{d}", v.name.name),
                TypeRef::Named(Ident::new("DINT", at)),
            ));
        }
    }
    out
}

/// Splits every variable-length VAR_IN_OUT among `blocks` into its hidden inputs, keeping the
/// order of the parameters (a block is cut where its kind changes). Whether one was split. (Also
/// called by the PLCopen XML reader on the interfaces it reads.)
pub fn split_blocks(blocks: &mut Vec<VarBlock>) -> bool {
    if !blocks
        .iter()
        .any(|b| b.kind == VarKind::InOut && b.vars.iter().any(|v| is_variable(&v.ty)))
    {
        return false;
    }
    let mut out: Vec<VarBlock> = Vec::with_capacity(blocks.len() + 2);
    for b in std::mem::take(blocks) {
        if b.kind != VarKind::InOut || !b.vars.iter().any(|v| is_variable(&v.ty)) {
            out.push(b);
            continue;
        }
        let mut run: Option<VarBlock> = None;
        for v in &b.vars {
            let (kind, vars) = if is_variable(&v.ty) {
                (VarKind::Input, hidden(v))
            } else {
                (VarKind::InOut, vec![v.clone()])
            };
            match &mut run {
                Some(r) if r.kind == kind => r.vars.extend(vars),
                _ => {
                    out.extend(run.take());
                    run = Some(VarBlock {
                        access: None,
                        name: None,
                        kind,
                        constant: false,
                        retain: false,
                        vars,
                        span: b.span,
                    });
                }
            }
        }
        out.extend(run);
    }
    *blocks = out;
    true
}

/// Splits the variable-length in-outs of every FUNCTION and FUNCTION_BLOCK of `units` and of every
/// method of `pending` (see the module documentation). The bodies when a method changed.
pub fn split_decls(
    units: &mut [CompilationUnit],
    pending: &[PendingBody],
) -> Option<Vec<PendingBody>> {
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        if let LibraryElement::Pou(p) = item {
            if matches!(p.kind, PouKind::Function | PouKind::FunctionBlock) {
                split_blocks(&mut p.var_blocks);
            }
        }
    }
    if !pending.iter().any(|pb| {
        pb.methods.iter().any(|m| {
            m.blocks
                .iter()
                .any(|b| b.kind == VarKind::InOut && b.vars.iter().any(|v| is_variable(&v.ty)))
        })
    }) {
        return None;
    }
    let mut out = pending.to_vec();
    for m in out.iter_mut().flat_map(|pb| pb.methods.iter_mut()) {
        split_blocks(&mut m.blocks);
    }
    Some(out)
}

/// Whether some POU of the project has a variable-length in-out (else [`rewrite`] has nothing to
/// do).
pub fn in_project(decls: &super::Declarations) -> bool {
    decls.pous.values().any(|i| {
        i.vars
            .iter()
            .any(|(n, _, _)| n.to_ascii_uppercase().ends_with(ADDRESS))
    })
}

/// One parameter of a called POU as the source sees it.
enum Param {
    /// An input, output or fixed in-out, by name.
    Plain(String),
    /// A variable-length in-out: its name, its rank and its element type.
    Variable {
        name: String,
        rank: usize,
        element: TypeRef,
    },
}

impl Param {
    fn name(&self) -> &str {
        match self {
            Param::Plain(n) | Param::Variable { name: n, .. } => n,
        }
    }
}

/// The parameters that bind positional arguments, from the (split) names and types in declaration
/// order: each variable-length in-out once, by its own name. `None` when none is variable-length.
fn collapse(params: Vec<(String, Option<TypeRef>)>) -> Option<Vec<Param>> {
    let mut out = Vec::with_capacity(params.len());
    let mut any = false;
    let mut k = 0;
    while k < params.len() {
        let (name, ty) = &params[k];
        let up = name.to_ascii_uppercase();
        if let (Some(base), Some(TypeRef::Ref { target, .. })) = (up.strip_suffix(ADDRESS), ty) {
            let base = &name[..base.len()];
            let mut rank = 0;
            while params
                .get(k + 1 + 2 * rank)
                .is_some_and(|(n, _)| n.eq_ignore_ascii_case(&format!("{base}{LOWER}{}", rank + 1)))
            {
                rank += 1;
            }
            if rank > 0 {
                out.push(Param::Variable {
                    name: base.to_string(),
                    rank,
                    element: (**target).clone(),
                });
                any = true;
                k += 1 + 2 * rank;
                continue;
            }
        }
        out.push(Param::Plain(name.clone()));
        k += 1;
    }
    any.then_some(out)
}

/// The rank and element type of the variable-length parameter `name` of the POU being lowered.
fn own(env: &Env, name: &str) -> Option<(usize, TypeRef)> {
    let up = name.to_ascii_uppercase();
    if env.vars.contains_key(&up) {
        return None;
    }
    let Some(TypeRef::Ref { target, .. }) = env.vars.get(&format!("{up}{ADDRESS}")) else {
        return None;
    };
    let rank = (1..)
        .take_while(|d| env.vars.contains_key(&format!("{up}{LOWER}{d}")))
        .count();
    (rank > 0).then(|| (rank, (**target).clone()))
}

/// Operators a vendor's compiler knows without a declaration (lowered on their own, not
/// [`crate::sema::stdlib`] functions): a variable-length array passed whole to one stays E1072.
const OPERATORS: &[&str] = &[
    "SIZEOF",
    "XSIZEOF",
    "ADR",
    "ADRINST",
    "BITADR",
    "REF",
    "MEMCPY",
    "MEMMOVE",
    "MEMSET",
    "MEMCMP",
    "SYSMEMCPY",
    "SYSMEMMOVE",
    "SYSMEMSET",
    "SYSMEMCMP",
    "LOWER_BOUND",
    "UPPER_BOUND",
    "__NEW",
    "__DELETE",
    "__ISVALIDREF",
    "__QUERYINTERFACE",
    "__QUERYPOINTER",
];

/// Whether `callee` names a function nothing declares (no POU, method, variable, type, standard
/// function, conversion or operator of that name): sema reports it (E1019).
fn unknown_function(env: &Env, callee: &Place) -> bool {
    let PlaceBase::Name(n) = &callee.base else {
        return false;
    };
    let own_method = || {
        env.decls
            .methods
            .get(&env.pou_name.name.to_ascii_uppercase())
            .is_some_and(|ms| ms.iter().any(|m| n.is(&m.name)))
    };
    callee.accessors.is_empty()
        && env.decls.pou(&n.name).is_none()
        && env.var_type(n).is_none()
        && env.decls.type_decl(&n.name).is_none()
        && crate::sema::stdlib::function(&n.name).is_none()
        && crate::sema::stdlib::conversion(&n.name).is_none()
        && !OPERATORS.iter().any(|o| n.is(o))
        && !own_method()
}

/// What a call calls, as far as the lifetime of the descriptors it is given matters.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Callee {
    /// A FUNCTION or a METHOD: the descriptor is read during the call only (a method's hidden
    /// inputs stay in the instance, but only the method reads them, and every call gives them).
    OneCall,
    /// An FB instance: the descriptor stays in the instance, and its methods and actions may read
    /// it between calls: it must refer to storage that lives as long as the program.
    Block,
}

/// The positional parameters of the POU `callee` calls, when one is variable-length.
fn params_of(env: &Env, callee: &Place) -> Option<(Vec<Param>, Callee)> {
    let PlaceBase::Name(n) = &callee.base else {
        return None;
    };
    let interface = |i: &super::PouInterface| {
        collapse(
            i.vars
                .iter()
                .filter(|(n, k, _)| {
                    // (a method's hidden inputs are the method's, not the block's)
                    matches!(k, VarKind::Input | VarKind::InOut)
                        && !n
                            .to_ascii_uppercase()
                            .starts_with(crate::actions::METHOD_PREFIX)
                })
                .map(|(n, _, t)| (n.clone(), Some(t.clone())))
                .collect(),
        )
    };
    let block_of = |n: &Ident| match env.var_type(n).map(|t| env.resolve(&t)) {
        Some(TypeRef::Named(t)) => env
            .decls
            .pou(&t.name)
            .filter(|i| i.kind == PouKind::FunctionBlock),
        _ => None,
    };
    let block_at = |p: &Place| match env.place_type(p).map(|t| env.resolve(&t)) {
        Some(TypeRef::Named(t)) => env
            .decls
            .pou(&t.name)
            .filter(|i| i.kind == PouKind::FunctionBlock),
        _ => None,
    };
    let method = |block: &super::PouInterface, m: &Ident| {
        let sig = env
            .decls
            .methods
            .get(&block.name.to_ascii_uppercase())?
            .iter()
            .find(|s| m.is(&s.name))?;
        collapse(
            sig.inputs
                .iter()
                .map(|v| {
                    let hidden = crate::actions::method_var(&sig.name, v);
                    let ty = block
                        .var(&hidden)
                        .map(|t| t.2.clone())
                        .or_else(|| env.vars.get(&hidden).cloned());
                    (v.clone(), ty)
                })
                .collect(),
        )
    };
    match callee.accessors.as_slice() {
        [] => {
            if let Some(b) = block_of(n) {
                return interface(b).map(|p| (p, Callee::Block));
            }
            if let Some(i) = env.decls.pou(&n.name) {
                if i.kind == PouKind::Function {
                    return interface(i).map(|p| (p, Callee::OneCall));
                }
            }
            // a method of the block being lowered, `M(...)` / `THIS^.M(...)`
            let block = env.decls.pou(&env.pou_name.name)?;
            method(block, n).map(|p| (p, Callee::OneCall))
        }
        // a method of an instance (`inst.M(b)`), an instance selected by index or field
        // (`fs[i](a := b)`, `s.fb(a := b)`), or a method of one (`fs[i].M(b)`): ordinary ST
        // calls (IEC 61131-3 ed. 3, 6.5.3)
        [.., last] => {
            if let Some(b) = block_at(callee) {
                return interface(b).map(|p| (p, Callee::Block));
            }
            let Accessor::Field(m) = last else {
                return None;
            };
            let owner = Place {
                base: callee.base.clone(),
                accessors: callee.accessors[..callee.accessors.len() - 1].to_vec(),
                span: callee.span,
            };
            method(block_at(&owner)?, m).map(|p| (p, Callee::OneCall))
        }
    }
}

/// Rewrites `s` (see the module documentation): `None` when nothing in it is a variable-length
/// parameter or a call that passes one. Errors are reported, and the statement is then dropped
/// (`Some(None)`).
pub fn rewrite(
    env: &Env,
    type_of: &dyn Fn(&Expr) -> Option<TypeRef>,
    s: &Stmt,
    diags: &mut Diagnostics,
) -> Option<Option<Stmt>> {
    if !needs(env, s) {
        return None;
    }
    let mut r = Rewrite {
        env,
        type_of,
        changed: false,
        failed: false,
        diags,
    };
    let mut out = s.clone();
    match &mut out.kind {
        StmtKind::Assign { target, value } => {
            r.place(target);
            r.expr(value);
        }
        StmtKind::Call { callee, args } => {
            r.place(callee);
            let callee = callee.clone();
            r.call(&callee, args);
        }
        kind => {
            if let StmtKind::For {
                element: Some(p), ..
            } = kind
            {
                r.place(p);
            }
            for e in kind.control_exprs_mut() {
                r.expr(e);
            }
        }
    }
    if r.failed {
        return Some(None);
    }
    r.changed.then_some(Some(out))
}

/// The most nodes [`needs`] walks in one statement: a longer expression is already E0109 (more
/// than 1,000 operations) and is not rewritten (nor copied: its copy would recurse as deep).
const MAX_NODES: usize = 4_000;

/// Whether `s`'s own expressions name a variable-length parameter of the POU being lowered or call
/// a POU that has one: looked at without recursion and without copying.
fn needs(env: &Env, s: &Stmt) -> bool {
    let mut stack: Vec<&Expr> = Vec::new();
    let mut places: Vec<&Place> = Vec::new();
    let mut calls: Vec<(Place, &Vec<Arg>)> = Vec::new();
    match &s.kind {
        StmtKind::Assign { target, value } => {
            places.push(target);
            stack.push(value);
        }
        StmtKind::Call { callee, args } => {
            places.push(callee);
            calls.push((callee.clone(), args));
        }
        kind => {
            if let StmtKind::For {
                element: Some(p), ..
            } = kind
            {
                places.push(p);
            }
            stack.extend(kind.control_exprs());
        }
    }
    let (mut nodes, mut found) = (0, false);
    loop {
        nodes += 1;
        if nodes > MAX_NODES {
            return false;
        }
        if let Some((callee, args)) = calls.pop() {
            found = found || params_of(env, &callee).is_some();
            stack.extend(args.iter().map(|a| &a.value));
            continue;
        }
        if let Some(p) = places.pop() {
            if let PlaceBase::Name(n) = &p.base {
                found = found || own(env, &n.name).is_some();
            }
            stack.extend(p.accessor_exprs());
            continue;
        }
        let Some(e) = stack.pop() else {
            return found;
        };
        match &e.kind {
            ExprKind::Place(p) => places.push(p),
            ExprKind::Unary { operand, .. } => stack.push(operand),
            ExprKind::Binary { left, right, .. } => {
                stack.push(left);
                stack.push(right);
            }
            ExprKind::Call { name, args } => calls.push((
                Place {
                    base: PlaceBase::Name(name.clone()),
                    accessors: Vec::new(),
                    span: name.span,
                },
                args,
            )),
            _ => {}
        }
    }
}

struct Rewrite<'a, 'e> {
    env: &'a Env<'e>,
    type_of: &'a dyn Fn(&Expr) -> Option<TypeRef>,
    changed: bool,
    failed: bool,
    diags: &'a mut Diagnostics,
}

impl Rewrite<'_, '_> {
    fn refuse(&mut self, code: diagnostics::Code, at: Span, msg: String, label: &str, hint: &str) {
        self.diags.push(
            Diagnostic::error(code, msg)
                .at(at)
                .with_primary_label(label)
                .with_hint(hint),
        );
        self.failed = true;
    }

    /// Rewrites `e` and what it holds; operator chains are walked with a stack (a chain of
    /// 100,000 operators does not recurse).
    fn expr(&mut self, e: &mut Expr) {
        let mut stack: Vec<&mut Expr> = vec![e];
        while let Some(e) = stack.pop() {
            if let ExprKind::Call { name, args } = &e.kind {
                if let Some(b) = self.bound(name, args, e.span) {
                    *e = b;
                    self.changed = true;
                    continue;
                }
            }
            match &mut e.kind {
                ExprKind::Place(p) => self.place(p),
                ExprKind::Unary { operand, .. } => stack.push(operand),
                ExprKind::Binary { left, right, .. } => {
                    stack.push(left);
                    stack.push(right);
                }
                ExprKind::Call { name, args } => {
                    let callee = Place {
                        base: PlaceBase::Name(name.clone()),
                        accessors: Vec::new(),
                        span: name.span,
                    };
                    self.call(&callee, args);
                }
                _ => {}
            }
        }
    }

    /// `LOWER_BOUND(x, d)` / `UPPER_BOUND(x, d)` of a variable-length parameter `x`: its hidden
    /// bound; `None` for any other call.
    fn bound(&mut self, f: &Ident, args: &[Arg], span: Span) -> Option<Expr> {
        let suffix = if f.is("LOWER_BOUND") {
            LOWER
        } else if f.is("UPPER_BOUND") {
            UPPER
        } else {
            return None;
        };
        let array = args.first()?;
        let ExprKind::Place(p) = &array.value.kind else {
            return None;
        };
        let PlaceBase::Name(n) = &p.base else {
            return None;
        };
        if !p.accessors.is_empty() {
            return None;
        }
        let (rank, _) = own(self.env, &n.name)?;
        let dim = match args.get(1).map(|a| &a.value.kind) {
            Some(ExprKind::Literal(l)) => match l.kind {
                LiteralKind::Int(d) if args.len() == 2 && (1..=rank as i128).contains(&d) => {
                    Some(d)
                }
                _ => None,
            },
            _ => None,
        };
        let Some(dim) = dim else {
            self.refuse(
                code::E1072,
                span,
                format!(
                    "`{}({}, ...)`: `{}` has {rank} dimension{}; the dimension must be an integer literal from 1 to {rank}",
                    f.name.to_ascii_uppercase(),
                    n.name,
                    n.name,
                    if rank == 1 { "" } else { "s" }
                ),
                "dimension",
                "write the dimension as a literal: `LOWER_BOUND(x, 1)`",
            );
            return Some(int(0, span));
        };
        Some(name_expr(format!("{}{suffix}{dim}", n.name), span))
    }

    /// A place: its indexes rewritten; an element of a variable-length parameter read through its
    /// address; the parameter itself anywhere else E1072.
    fn place(&mut self, p: &mut Place) {
        for a in p.accessors.iter_mut() {
            match a {
                Accessor::Index(ix) => {
                    for e in ix.iter_mut() {
                        self.expr(e);
                    }
                }
                Accessor::Call { args, .. } => {
                    for a in args.iter_mut() {
                        self.expr(&mut a.value);
                    }
                }
                _ => {}
            }
        }
        let PlaceBase::Name(n) = &p.base else {
            return;
        };
        let Some((rank, _)) = own(self.env, &n.name) else {
            return;
        };
        let n = n.clone();
        let Some(Accessor::Index(ix)) = p.accessors.first() else {
            self.refuse(
                code::E1072,
                p.span,
                format!(
                    "`{}` is a variable-length array (`ARRAY [*]`): it is used by element, with LOWER_BOUND/UPPER_BOUND, or passed to another `ARRAY [*]` in-out",
                    n.name
                ),
                "used as a whole",
                "its size is known at run time only: copy or compare it element by element (`FOR i := LOWER_BOUND(x, 1) TO UPPER_BOUND(x, 1) DO ... END_FOR`)",
            );
            return;
        };
        if ix.len() != rank {
            self.refuse(
                code::E1072,
                p.span,
                format!(
                    "`{}` has {rank} dimension{}: {} index{} given",
                    n.name,
                    if rank == 1 { "" } else { "s" },
                    ix.len(),
                    if ix.len() == 1 { "" } else { "es" }
                ),
                "element",
                "give one index per dimension: `x[i, j]` for `ARRAY [*, *]`",
            );
            return;
        }
        if rank > 1 {
            if let Some(e) = ix.iter().find(|e| calls_something(e)) {
                // each index is evaluated twice (its bounds test, then the offset)
                self.diags.push(
                    Diagnostic::warning(
                        code::W1432,
                        format!(
                            "this index of `{}` (a {rank}-dimensional `ARRAY [*]`) calls a function: it is evaluated twice",
                            n.name
                        ),
                    )
                    .at(e.span)
                    .with_primary_label("evaluated twice")
                    .with_hint("store the index in a variable first (`k := F(); x[k, j] := ...`)"),
                );
            }
        }
        let span = p.span;
        let bound = |suffix: &str, d: usize| name_expr(format!("{}{suffix}{d}", n.name), span);
        let offset = |e: &Expr, d: usize| binary(BinaryOp::Sub, e.clone(), bound(LOWER, d), span);
        let index = if rank == 1 {
            offset(&ix[0], 1)
        } else {
            let mut inside: Option<Expr> = None;
            let mut linear: Option<Expr> = None;
            for (k, e) in ix.iter().enumerate() {
                let d = k + 1;
                let within = binary(
                    BinaryOp::And,
                    binary(BinaryOp::Ge, e.clone(), bound(LOWER, d), span),
                    binary(BinaryOp::Le, e.clone(), bound(UPPER, d), span),
                    span,
                );
                inside = Some(match inside {
                    None => within,
                    Some(i) => binary(BinaryOp::And, i, within, span),
                });
                linear = Some(match linear {
                    None => offset(e, d),
                    Some(l) => {
                        let len = binary(
                            BinaryOp::Add,
                            binary(BinaryOp::Sub, bound(UPPER, d), bound(LOWER, d), span),
                            int(1, span),
                            span,
                        );
                        binary(
                            BinaryOp::Add,
                            binary(BinaryOp::Mul, l, len, span),
                            offset(e, d),
                            span,
                        )
                    }
                });
            }
            let (Some(inside), Some(linear)) = (inside, linear) else {
                return;
            };
            call("SEL", vec![inside, int(-1, span), linear], span)
        };
        p.base = PlaceBase::Name(Ident::new(format!("{}{ADDRESS}", n.name), n.span));
        p.accessors[0] = Accessor::Index(vec![index]);
        self.changed = true;
    }

    /// A call of a POU with variable-length in-outs: each array passed to one replaced by its
    /// descriptor (the other positional arguments made formal); the other arguments rewritten.
    fn call(&mut self, callee: &Place, args: &mut Vec<Arg>) {
        let rewritten = args
            .iter()
            .any(|a| a.name.as_ref().is_some_and(|n| n.key().ends_with(ADDRESS)));
        let params = if rewritten {
            // (a call this rewrite made: its descriptors are given)
            None
        } else {
            params_of(self.env, callee)
        };
        let Some((params, kind)) = params else {
            let unknown = unknown_function(self.env, callee);
            for a in args.iter_mut() {
                // a parameter of this POU passed whole to a function nobody declared: that
                // function's E1019 is the one error (its parameter may well be `ARRAY [*]`); the
                // argument is its address, as sema does not look at an unknown call's arguments
                if let (true, ExprKind::Place(p)) = (unknown, &a.value.kind) {
                    if let (PlaceBase::Name(n), true) = (&p.base, p.accessors.is_empty()) {
                        if own(self.env, &n.name).is_some() {
                            a.value = name_expr(format!("{}{ADDRESS}", n.name), a.value.span);
                            self.changed = true;
                            continue;
                        }
                    }
                }
                self.expr(&mut a.value);
            }
            return;
        };
        let called = match &callee.base {
            PlaceBase::Name(n) => {
                let mut s = n.name.clone();
                for a in &callee.accessors {
                    if let Accessor::Field(f) = a {
                        s.push('.');
                        s.push_str(&f.name);
                    }
                }
                s
            }
            PlaceBase::Address(_) => String::new(),
        };
        let mut out = Vec::with_capacity(args.len() + 4);
        let mut given = vec![false; params.len()];
        for (k, a) in std::mem::take(args).into_iter().enumerate() {
            let target = match &a.name {
                Some(n) => params.iter().position(|p| n.is(p.name())),
                // (also in a call that names later arguments, CODESYS's mixed form: the argument
                // at position k binds the k-th parameter, as for other calls; W1422 from the call)
                None if a.dir == ArgDir::Input => (k < params.len()).then_some(k),
                None => None,
            };
            let Some(t) = target else {
                let mut a = a;
                self.expr(&mut a.value);
                out.push(a);
                continue;
            };
            given[t] = true;
            let Param::Variable {
                name,
                rank,
                element,
            } = &params[t]
            else {
                let mut a = a;
                if a.name.is_none() {
                    a.name = Some(Ident::new(params[t].name(), a.span));
                }
                self.expr(&mut a.value);
                out.push(a);
                continue;
            };
            self.changed = true;
            if let Some(descriptor) = self.descriptor(&called, kind, name, *rank, element, &a) {
                out.extend(descriptor);
            } else {
                out.push(a);
            }
        }
        for (p, g) in params.iter().zip(&given) {
            if let (Param::Variable { name, .. }, false) = (p, g) {
                self.refuse(
                    code::E1071,
                    callee.span,
                    format!("the `ARRAY [*]` in-out `{name}` of `{called}` is not given"),
                    "call",
                    &format!("pass an array to it: `{called}({name} := myArray)`"),
                );
            }
        }
        *args = out;
    }

    /// The formal arguments that pass the array of `a` to the variable-length in-out `name`; `None`
    /// (reported) when it does not fit.
    fn descriptor(
        &mut self,
        called: &str,
        kind: Callee,
        name: &str,
        rank: usize,
        element: &TypeRef,
        a: &Arg,
    ) -> Option<Vec<Arg>> {
        let span = a.span;
        let formal = |n: String, value: Expr| Arg {
            name: Some(Ident::new(n, span)),
            dir: ArgDir::Input,
            value,
            span,
        };
        let what = format!("the `ARRAY [*]` in-out `{name}` of `{called}`");
        let expected = format!(
            "ARRAY [{}] OF {}",
            vec!["*"; rank].join(", "),
            text(self.env, element)
        );
        let ExprKind::Place(place) = &a.value.kind else {
            self.refuse(
                code::E1071,
                a.value.span,
                format!("{what} takes an array variable"),
                "not a variable",
                "pass a declared array (a variable, a field, an FB output); store an expression's value in one first",
            );
            return None;
        };
        // another ARRAY [*] parameter of this POU: its descriptor passed on
        if let (PlaceBase::Name(n), true) = (&place.base, place.accessors.is_empty()) {
            if let Some((r, e)) = own(self.env, &n.name) {
                // a FUNCTION's or a METHOD's may be an array that lives for one call
                let lasting = self.env.pou_kind == PouKind::FunctionBlock
                    && self
                        .env
                        .decls
                        .pou(&self.env.pou_name.name)
                        .is_some_and(|b| {
                            b.var(&format!("{}{ADDRESS}", n.name))
                                .is_some_and(|v| v.1 == VarKind::Input)
                        });
                if kind == Callee::Block && !lasting {
                    self.refuse(
                        code::E1071,
                        a.value.span,
                        format!(
                            "{what} keeps its array in the instance: `{}` of a function or method may be an array that lives for one call",
                            n.name
                        ),
                        "passed on to a block",
                        "pass the block an array of a program, a block instance or a global list, or call a function or a method with it",
                    );
                    return None;
                }
                if r != rank || !same(self.env, &e, element) {
                    let got = format!(
                        "ARRAY [{}] OF {}",
                        vec!["*"; r].join(", "),
                        text(self.env, &e)
                    );
                    self.mismatch(&what, &expected, &got, a.value.span);
                    return None;
                }
                let mut v = vec![formal(
                    format!("{name}{ADDRESS}"),
                    name_expr(format!("{}{ADDRESS}", n.name), span),
                )];
                for d in 1..=rank {
                    for suffix in [LOWER, UPPER] {
                        v.push(formal(
                            format!("{name}{suffix}{d}"),
                            name_expr(format!("{}{suffix}{d}", n.name), span),
                        ));
                    }
                }
                return Some(v);
            }
        }
        let mut place = place.clone();
        self.place(&mut place);
        let value = Expr {
            kind: ExprKind::Place(place),
            span: a.value.span,
        };
        let Some(ty) = (self.type_of)(&a.value) else {
            // (an undeclared name: its own error comes from the lowering)
            return Some(vec![formal(format!("{name}{ADDRESS}"), value)]);
        };
        let TypeRef::Array {
            dims, element: e, ..
        } = self.env.resolve(&ty)
        else {
            let got = text(self.env, &ty);
            self.mismatch(&what, &expected, &got, a.value.span);
            return None;
        };
        if dims.len() != rank || !same(self.env, &e, element) {
            let got = text(self.env, &ty);
            self.mismatch(&what, &expected, &got, a.value.span);
            return None;
        }
        let address = match kind {
            Callee::OneCall => CALL_ADDRESS,
            Callee::Block => "ADR",
        };
        let mut v = vec![formal(
            format!("{name}{ADDRESS}"),
            call(address, vec![value], a.value.span),
        )];
        for (k, d) in dims.iter().enumerate() {
            v.push(formal(
                format!("{name}{LOWER}{}", k + 1),
                int(d.lower, span),
            ));
            v.push(formal(
                format!("{name}{UPPER}{}", k + 1),
                int(d.upper, span),
            ));
        }
        Some(v)
    }

    fn mismatch(&mut self, what: &str, expected: &str, got: &str, at: Span) {
        self.refuse(
            code::E1071,
            at,
            format!("{what} is `{expected}`: `{got}` does not fit"),
            "argument",
            "pass an array of the same element type and number of dimensions (its bounds may be any)",
        );
    }
}
