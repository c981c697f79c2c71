//! A user FUNCTION's input of a generic type, `In : ANY;` (`ANY_NUM`, `ANY_INT` ...: CODESYS online
//! help "ANY and `ANY_<type>`", TwinCAT likewise): the function accepts an argument of any type of
//! the family and sees, instead of the value, its description `__SYSTEM.AnyType`: `In.diSize` (the
//! argument's size in bytes), `In.TypeClass` (its class, compared with `__SYSTEM.TYPE_CLASS.TYPE_INT`
//! ...) and `In.pValue` (its address).
//!
//! What ladderc compiles (safe and bounded): `In.diSize`, `In.TypeClass` and `In.pValue`. The
//! input is hidden inputs of the function, `In__DISIZE : DINT`, `In__TYPECLASS : INT` and, when
//! the function's body reads `In.pValue` or passes `In` on to another ANY input,
//! `In__PVALUE : POINTER TO BYTE` ([`split_decls`]; a METHOD's likewise, before it joins its
//! block: [`split_method_inputs`]; a FUNCTION_BLOCK's likewise, always with the address: Beckhoff
//! Infosys "ANY and `ANY_<type>`" allows ANY inputs in function blocks from TwinCAT 3.1 build 4026,
//! CODESYS "Data Type: ANY" too). A block instance's call `inst(In := x)` gives the address for
//! that call only (call-scoped, so `x` may be a VAR_TEMP or a method's variable, or the caller's
//! own ANY input passed on), reset to NULL when the call returns; size and class stay the last
//! call's, as any input does. A call
//! `F(In := x)` (formal or positional) passes `SIZEOF(x)`, the class of `x`'s type and `ADR(x)`
//! ([`rewrite`], before the statement is lowered), so `.pValue` is a bounded pointer to the
//! argument's bytes (sema refuses, E0305, an argument with no address for the whole run, as `ADR`
//! of it; a call of the block's own METHOD passes the address for the call only, so there a
//! method's VAR or a VAR_TEMP may be given: `address_for_one_call`). A call may give any variable, element or field; an argument that is no variable (a
//! literal, an expression) is E1068, as is an argument outside the input's family (`ANY_NUM` given
//! a BOOL). `In` read as a value (`ADR(In)`, `SIZEOF(In)`) is E1068 in the function.
//!
//! Input: the parsed units (before the declarations are indexed), then each ST statement being
//! lowered. Output: the functions' ANY inputs split; the statements rewritten.
//! Invariants: only VAR_INPUTs of the ANY family of FUNCTIONs, FUNCTION_BLOCKs and METHODs are split; a statement without such a
//! call or use is not touched; a rewritten statement holds no rewritable part any more (the
//! lowering may run the rewrite again on it).

use super::ast::{Accessor, Arg, ArgDir, Expr, ExprKind, Place, PlaceBase, Stmt, StmtKind};
use super::infer::Env;
use crate::ast::{CompilationUnit, Ident, LibraryElement, LiteralKind, PouKind, TypeRef, VarKind};
use diagnostics::{code, Diagnostic, Diagnostics};

/// The hidden input holding an ANY input's size.
pub const SIZE: &str = "__DISIZE";
/// The hidden input holding an ANY input's type class.
pub const CLASS: &str = "__TYPECLASS";
/// The hidden input holding an ANY input's address, a bounded `POINTER TO BYTE` (declared only
/// by a function whose body reads `.pValue`).
pub const VALUE: &str = "__PVALUE";

/// The generic types an input may have, with the elementary types each accepts (`None`: any type).
fn family(ty: &str) -> Option<Option<&'static [&'static str]>> {
    const INT: &[&str] = &[
        "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT",
    ];
    const REAL: &[&str] = &["REAL", "LREAL"];
    const NUM: &[&str] = &[
        "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "REAL", "LREAL",
    ];
    const BIT: &[&str] = &["BOOL", "BYTE", "WORD", "DWORD", "LWORD"];
    Some(match ty.to_ascii_uppercase().as_str() {
        "ANY" | "ANY_DERIVED" | "ANY_ELEMENTARY" => None,
        "ANY_INT" => Some(INT),
        "ANY_REAL" => Some(REAL),
        "ANY_NUM" | "ANY_MAGNITUDE" => Some(NUM),
        "ANY_BIT" => Some(BIT),
        _ => return None,
    })
}

/// `__SYSTEM.TYPE_CLASS`'s values, in CODESYS's order (compared by name in the source; the numbers
/// are what `--watch` shows).
const CLASSES: &[&str] = &[
    "TYPE_BOOL",
    "TYPE_BIT",
    "TYPE_BYTE",
    "TYPE_WORD",
    "TYPE_DWORD",
    "TYPE_LWORD",
    "TYPE_SINT",
    "TYPE_INT",
    "TYPE_DINT",
    "TYPE_LINT",
    "TYPE_USINT",
    "TYPE_UINT",
    "TYPE_UDINT",
    "TYPE_ULINT",
    "TYPE_REAL",
    "TYPE_LREAL",
    "TYPE_STRING",
    "TYPE_WSTRING",
    "TYPE_TIME",
    "TYPE_DATE",
    "TYPE_DATEANDTIME",
    "TYPE_TIMEOFDAY",
    "TYPE_POINTER",
    "TYPE_REFERENCE",
    "TYPE_SUBRANGE",
    "TYPE_ENUM",
    "TYPE_ARRAY",
    "TYPE_PARAMS",
    "TYPE_USERDEF",
    "TYPE_NONE",
    "TYPE_ANY",
    "TYPE_ANYBIT",
    "TYPE_ANYDATE",
    "TYPE_ANYINT",
    "TYPE_ANYNUM",
    "TYPE_ANYREAL",
    "TYPE_LAZY",
    "TYPE_LTIME",
];

fn class_number(name: &str) -> Option<i128> {
    CLASSES
        .iter()
        .position(|c| c.eq_ignore_ascii_case(name))
        .map(|k| k as i128)
}

/// The class of a value of type `ty` (elementary names, then the kind of the type).
fn class_of(env: &Env, ty: &TypeRef) -> i128 {
    let named = |n: &str| {
        let up = n.to_ascii_uppercase();
        let class = match up.as_str() {
            "DT" | "DATE_AND_TIME" | "LDT" => "TYPE_DATEANDTIME",
            "TOD" | "TIME_OF_DAY" | "LTOD" => "TYPE_TIMEOFDAY",
            "LDATE" => "TYPE_DATE",
            _ => "",
        };
        if !class.is_empty() {
            return class_number(class);
        }
        class_number(&format!("TYPE_{up}"))
    };
    match ty {
        TypeRef::Named(n) => named(&n.name).unwrap_or_else(|| {
            if env
                .decls
                .types
                .get(&n.key())
                .is_some_and(|t| matches!(t.def, crate::ast::TypeDef::Enum { .. }))
            {
                class_number("TYPE_ENUM").unwrap_or(0)
            } else {
                class_number("TYPE_USERDEF").unwrap_or(0)
            }
        }),
        TypeRef::String { wide, .. } => {
            class_number(if *wide { "TYPE_WSTRING" } else { "TYPE_STRING" }).unwrap_or(0)
        }
        TypeRef::Array { .. } => class_number("TYPE_ARRAY").unwrap_or(0),
        TypeRef::Subrange { .. } => class_number("TYPE_SUBRANGE").unwrap_or(0),
        TypeRef::Enum { .. } => class_number("TYPE_ENUM").unwrap_or(0),
        TypeRef::Ref { kind, .. } => class_number(if *kind == crate::ast::RefKind::Reference {
            "TYPE_REFERENCE"
        } else {
            "TYPE_POINTER"
        })
        .unwrap_or(0),
    }
}

/// Splits each ANY-family VAR_INPUT of every FUNCTION and FUNCTION_BLOCK into its hidden inputs
/// (see the module documentation): size and class, and the address when the function's body
/// (`body_of` its name's position) needs it (`reads_address`; a block's always). The split inputs
/// keep their order among the others.
pub fn split_decls<'b>(
    units: &mut [CompilationUnit],
    body_of: &dyn Fn(crate::Span) -> Option<&'b str>,
) {
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        let LibraryElement::Pou(p) = item else {
            continue;
        };
        // (a FUNCTION_BLOCK's always with the address: its methods and actions may read it too)
        let block = match p.kind {
            PouKind::Function => false,
            PouKind::FunctionBlock => true,
            _ => continue,
        };
        let body = body_of(p.name.span).unwrap_or("");
        for b in p.var_blocks.iter_mut() {
            split_block(b, body, block);
        }
    }
}

/// Whether the statements `text` need the address of the ANY input `name`: they read
/// `name.pValue`, or pass `name` itself on (to another ANY input, which may read it).
fn reads_address(text: &str, name: &str) -> bool {
    let (text, name) = (text.to_ascii_lowercase(), name.to_ascii_lowercase());
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let mut from = 0;
    while let Some(k) = text[from..].find(&name) {
        let at = from + k;
        from = at + name.len();
        if text[..at].chars().next_back().is_some_and(ident)
            || text[from..].chars().next().is_some_and(ident)
        {
            continue;
        }
        let rest = text[from..].trim_start();
        match rest.strip_prefix('.') {
            Some(field) if field.trim_start().starts_with("pvalue") => return true,
            Some(_) => {}
            // `name` alone: passed on (or an error reported where it is used)
            None => return true,
        }
    }
    false
}

/// The pending bodies with each METHOD's ANY-family VAR_INPUTs split as a function's are
/// ([`split_decls`]; always with the address), before the methods join their blocks (their hidden
/// inputs become `__M_<METHOD>_<In>__DISIZE` ...), an INTERFACE's methods too (so that the blocks
/// implementing them match them; a call through an interface is refused by [`rewrite`]); `None`
/// when no method has one.
pub fn split_method_inputs(
    pending: &[super::file::PendingBody],
) -> Option<Vec<super::file::PendingBody>> {
    let any_input = |m: &super::file::PendingMethod| {
        m.blocks
            .iter()
            .any(|b| b.kind == VarKind::Input && b.vars.iter().any(|v| is_any(&v.ty)))
    };
    let has = |pb: &super::file::PendingBody| {
        pb.methods.iter().any(any_input)
            || matches!(pb.oop.as_deref(), Some(super::inherit::Oop::Interface(i)) if i.methods.iter().any(any_input))
    };
    if !pending.iter().any(has) {
        return None;
    }
    let mut out = pending.to_vec();
    for pb in out.iter_mut() {
        for m in pb.methods.iter_mut() {
            for b in m.blocks.iter_mut() {
                // always with the address: an override and the method it overrides share one
                // signature, whichever of them reads `.pValue`
                split_block(b, &m.text, true);
            }
        }
        if let Some(super::inherit::Oop::Interface(i)) = pb.oop.as_deref_mut() {
            for m in i.methods.iter_mut() {
                for b in m.blocks.iter_mut() {
                    split_block(b, "", true);
                }
            }
        }
    }
    Some(out)
}

/// Splits the ANY-family variables of `b`, a VAR_INPUT block, into their hidden inputs (the
/// address of those whose address the statements `body` need, [`reads_address`], or of every one
/// when `always_address`).
fn split_block(b: &mut crate::ast::VarBlock, body: &str, always_address: bool) {
    if b.kind != VarKind::Input || !b.vars.iter().any(|v| is_any(&v.ty)) {
        return;
    }
    let mut vars = Vec::with_capacity(b.vars.len() + 2);
    for v in std::mem::take(&mut b.vars) {
        if !is_any(&v.ty) {
            vars.push(v);
            continue;
        }
        // (the class input's name ends with the generic type: `In__TYPECLASS_ANY_NUM`, which
        // the calls check their argument against)
        let generic = match &v.ty {
            TypeRef::Named(n) => n.name.to_ascii_uppercase(),
            _ => "ANY".into(),
        };
        for (suffix, ty) in [
            (SIZE.to_string(), "DINT"),
            (format!("{CLASS}_{generic}"), "INT"),
        ] {
            let mut h = v.clone();
            h.name = Ident::new(format!("{}{suffix}", v.name.name), v.name.span);
            h.ty = TypeRef::Named(Ident::new(ty, v.name.span));
            h.init = None;
            vars.push(h);
        }
        if always_address || reads_address(body, &v.name.name) {
            let mut h = v.clone();
            let at = v.name.span;
            h.name = Ident::new(format!("{}{VALUE}", v.name.name), at);
            h.ty = TypeRef::Ref {
                kind: crate::ast::RefKind::Pointer,
                target: Box::new(TypeRef::Named(Ident::new("BYTE", at))),
                span: at,
            };
            h.init = None;
            vars.push(h);
        }
    }
    b.vars = vars;
}

/// `ADR(x)`, the address [`Rewrite::call`] gives a hidden address input, made for one call
/// (`ADR` becomes [`super::varlen::CALL_ADDRESS`], call-scoped): what a call of the block's own
/// METHOD passes, since the method reads it during that call only (its `In__PVALUE` is reset to
/// NULL when the call returns, `PouLowering::method_call`); `None` for any other value (an ANY
/// input passed on: the caller's own address input).
pub(super) fn address_for_one_call(value: &Expr) -> Option<Expr> {
    let ExprKind::Call { name, args } = &value.kind else {
        return None;
    };
    if !name.is("ADR") || args.len() != 1 || args[0].name.is_some() {
        return None;
    }
    Some(Expr {
        kind: ExprKind::Call {
            name: Ident::new(super::varlen::CALL_ADDRESS, name.span),
            args: args.clone(),
        },
        span: value.span,
    })
}

/// Whether `input` is the hidden address input of an ANY input (`In__PVALUE`).
pub fn is_address_input(input: &str) -> bool {
    input.len() > VALUE.len()
        && input
            .get(input.len() - VALUE.len()..)
            .is_some_and(|end| end.eq_ignore_ascii_case(VALUE))
}

fn is_any(ty: &TypeRef) -> bool {
    matches!(ty, TypeRef::Named(n) if family(&n.name).is_some())
}

/// One input of a function with ANY inputs: its name, and for an ANY input its generic type
/// (`ANY_NUM` ...) and the name of its hidden class input.
type Input = (String, Option<(String, String)>);

/// What a call with ANY inputs calls: its name for messages, its inputs in declaration order
/// (each split ANY input once by its own name), and the names of its hidden address inputs
/// (upper-case, as the call names them).
struct Callee {
    name: String,
    inputs: Vec<Input>,
    addresses: Vec<String>,
    /// A FUNCTION_BLOCK instance: the address is made for the call only (call-scoped, reset to
    /// NULL when the call returns: `PouLowering::call_statement`).
    instance: bool,
}

/// The inputs of function `f` (see [`Callee`]); `None` when `f` is no function with ANY inputs.
fn inputs_of(env: &Env, f: &str) -> Option<Callee> {
    let i = env.decls.pou(f)?;
    if i.kind != PouKind::Function {
        return None;
    }
    split_inputs(f, i.vars.iter().map(|(n, k, _)| (n.as_str(), *k)), "")
}

/// The inputs of the FUNCTION_BLOCK instance a call statement calls (`inst(...)`, `a[i](...)`,
/// `s.fb(...)`), its own (not its methods' hidden `__M_<M>_<In>`); `None` when the block has no
/// ANY input.
fn instance_inputs(env: &Env, callee: &Place) -> Option<Callee> {
    let TypeRef::Named(b) = env.resolve(&env.place_type(callee)?) else {
        return None;
    };
    let i = env.decls.pou(&b.name)?;
    if i.kind != PouKind::FunctionBlock {
        return None;
    }
    let mut c = split_inputs(
        &b.name,
        i.vars
            .iter()
            .filter(|(n, _, _)| {
                !n.to_ascii_uppercase()
                    .starts_with(crate::actions::METHOD_PREFIX)
            })
            .map(|(n, k, _)| (n.as_str(), *k)),
        "",
    )?;
    c.instance = true;
    Some(c)
}

/// Whether `input` is the hidden address input of a FUNCTION_BLOCK's own ANY input (`In__PVALUE`),
/// not of one of its methods' (`__M_<M>_In__PVALUE`).
pub fn is_block_address_input(input: &str) -> bool {
    is_address_input(input)
        && !input
            .to_ascii_uppercase()
            .starts_with(crate::actions::METHOD_PREFIX)
}

/// The callee of a call inside an expression, `F(...)`: a function, or a method of the block
/// being lowered, with ANY inputs.
fn callee_of_call(env: &Env, name: &Ident) -> Option<Callee> {
    inputs_of(env, &name.name).or_else(|| {
        let own = Place {
            base: PlaceBase::Name(name.clone()),
            accessors: Vec::new(),
            span: name.span,
        };
        method_inputs_of(env, &own)
    })
}

/// The inputs of the method a call statement's callee names (`inst.M`, or `M` / `THIS^.M` of the
/// block being lowered), read from its block's hidden variables `__M_<M>_<input>`; `None` when it
/// is no method with ANY inputs.
fn method_inputs_of(env: &Env, callee: &Place) -> Option<Callee> {
    method_inputs_typed(env, callee, None)
}

/// The type of an expression, as the lowering knows it.
type TypeOf<'t> = &'t dyn Fn(&Expr) -> Option<TypeRef>;

/// [`method_inputs_of`], the block of any other callee (`p^.M`, `a[i].M`, `inst.sub.M`) found
/// by `type_of` its place before the method's name.
fn method_inputs_typed(env: &Env, callee: &Place, type_of: Option<TypeOf<'_>>) -> Option<Callee> {
    let PlaceBase::Name(n) = &callee.base else {
        return None;
    };
    let (block, method) = match callee.accessors.as_slice() {
        [] if env.pou_kind == PouKind::FunctionBlock && env.var_type(n).is_none() => {
            (env.pou_name.name.clone(), n)
        }
        [Accessor::Deref(_), Accessor::Field(m)] if n.is("THIS") => (env.pou_name.name.clone(), m),
        [Accessor::Field(m)] => match env.var_type(n).map(|t| env.resolve(&t)) {
            Some(TypeRef::Named(b)) => (b.name, m),
            _ => return None,
        },
        [prefix @ .., Accessor::Field(m)] => {
            let owner = Expr {
                kind: ExprKind::Place(Place {
                    base: callee.base.clone(),
                    accessors: prefix.to_vec(),
                    span: callee.span,
                }),
                span: callee.span,
            };
            match type_of.and_then(|t| t(&owner)).map(|t| env.resolve(&t)) {
                Some(TypeRef::Named(b)) => (b.name, m),
                _ => return None,
            }
        }
        _ => return None,
    };
    let i = env.decls.pou(&block)?;
    if i.kind != PouKind::FunctionBlock {
        return None;
    }
    let prefix = crate::actions::method_var(&method.name, "");
    split_inputs(
        &format!("{block}.{}", method.name),
        i.vars.iter().map(|(n, k, _)| (n.as_str(), *k)),
        &prefix,
    )
}

/// Whether the place before the method's name in `callee` has no function block type that
/// [`method_inputs_typed`] can read (an INTERFACE, an unknown type).
fn method_block_unknown(
    env: &Env,
    callee: &Place,
    type_of: &dyn Fn(&Expr) -> Option<TypeRef>,
) -> bool {
    let Some((Accessor::Field(_), prefix)) = callee.accessors.split_last() else {
        return false;
    };
    let owner_type = if prefix.is_empty() {
        let PlaceBase::Name(n) = &callee.base else {
            return true;
        };
        env.var_type(n)
    } else {
        type_of(&Expr {
            kind: ExprKind::Place(Place {
                base: callee.base.clone(),
                accessors: prefix.to_vec(),
                span: callee.span,
            }),
            span: callee.span,
        })
    };
    match owner_type.map(|t| env.resolve(&t)) {
        Some(TypeRef::Named(b)) => env
            .decls
            .pou(&b.name)
            .is_none_or(|i| i.kind != PouKind::FunctionBlock),
        _ => true,
    }
}

/// Whether `callee` ends with the name of a method that some function block of the project
/// declares with ANY inputs (`x.y.M`, `p^.M`): a call [`rewrite`] must look at.
fn may_name_any_method(env: &Env, callee: &Place) -> bool {
    let Some(Accessor::Field(m)) = callee.accessors.last() else {
        return false;
    };
    let prefix = crate::actions::method_var(&m.name, "").to_ascii_uppercase();
    env.decls.pous.values().any(|i| {
        i.kind == PouKind::FunctionBlock
            && i.vars.iter().any(|(n, k, _)| {
                let up = n.to_ascii_uppercase();
                *k == VarKind::Input && up.starts_with(&prefix) && up.ends_with(SIZE)
            })
    })
}

/// [`Callee`] of the inputs among `vars` whose names start with `prefix` (upper-case compared),
/// the prefix left out; `None` when none of them is a split ANY input.
fn split_inputs<'v>(
    name: &str,
    vars: impl Iterator<Item = (&'v str, VarKind)>,
    prefix: &str,
) -> Option<Callee> {
    let mut out: Vec<Input> = Vec::new();
    let mut addresses = Vec::new();
    let mut any = false;
    let prefix = prefix.to_ascii_uppercase();
    for (name, kind) in vars {
        if kind != VarKind::Input {
            continue;
        }
        let up = name.to_ascii_uppercase();
        let Some(up) = up.strip_prefix(prefix.as_str()) else {
            continue;
        };
        let name = &name[prefix.len()..];
        if up.ends_with(SIZE) {
            continue;
        }
        if up.ends_with(VALUE) {
            addresses.push(up.to_string());
            continue;
        }
        match up.find(CLASS) {
            Some(k) if k > 0 => {
                let generic = up[k + CLASS.len()..].trim_start_matches('_').to_string();
                out.push((name[..k].to_string(), Some((generic, name.to_string()))));
                any = true;
            }
            _ => out.push((name.to_string(), None)),
        }
    }
    any.then(|| Callee {
        name: name.to_string(),
        inputs: out,
        addresses,
        instance: false,
    })
}

/// The hidden class input of the ANY input `base` among the POU's variables (upper-case keys).
fn class_var(env: &Env, base: &str) -> Option<String> {
    let prefix = format!("{}{CLASS}", base.to_ascii_uppercase());
    env.vars.keys().find(|k| k.starts_with(&prefix)).cloned()
}

/// Whether some FUNCTION or METHOD of the project has an ANY input (else [`rewrite`] has nothing
/// to do).
pub fn in_project(decls: &super::Declarations) -> bool {
    decls.pous.values().any(|i| {
        i.vars
            .iter()
            .any(|(n, k, _)| *k == VarKind::Input && n.to_ascii_uppercase().ends_with(SIZE))
    })
}

/// Whether `s`'s own expressions hold something [`rewrite`] changes: looked at without recursion
/// and without copying (a statement may hold an expression of a thousand operations).
fn needs(env: &Env, s: &Stmt) -> bool {
    let mut stack: Vec<&Expr> = Vec::new();
    let mut places: Vec<&Place> = Vec::new();
    match &s.kind {
        StmtKind::Assign { target, value } => {
            places.push(target);
            stack.push(value);
        }
        StmtKind::Call { callee, args } => {
            places.push(callee);
            if let PlaceBase::Name(n) = &callee.base {
                if callee.accessors.is_empty() && inputs_of(env, &n.name).is_some() {
                    return true;
                }
            }
            if method_inputs_of(env, callee).is_some()
                || may_name_any_method(env, callee)
                || instance_inputs(env, callee).is_some()
            {
                return true;
            }
            stack.extend(args.iter().map(|a| &a.value));
        }
        kind => stack.extend(kind.control_exprs()),
    }
    loop {
        if let Some(p) = places.pop() {
            if let PlaceBase::Name(n) = &p.base {
                let up = n.key();
                if up == "__SYSTEM"
                    || up == "TYPE_CLASS"
                    || (!env.vars.contains_key(&up)
                        && env.vars.contains_key(&format!("{up}{SIZE}")))
                {
                    return true;
                }
            }
            stack.extend(p.accessor_exprs());
            continue;
        }
        let Some(e) = stack.pop() else {
            return false;
        };
        match &e.kind {
            ExprKind::Place(p) => places.push(p),
            ExprKind::Unary { operand, .. } => stack.push(operand),
            ExprKind::Binary { left, right, .. } => {
                stack.push(left);
                stack.push(right);
            }
            ExprKind::Call { name, args } => {
                if callee_of_call(env, name).is_some() {
                    return true;
                }
                stack.extend(args.iter().map(|a| &a.value));
            }
            _ => {}
        }
    }
}

/// Rewrites `s` (see the module documentation): `None` when nothing in it is an ANY input's call or
/// use. Errors are reported and the offending argument or place is left as written (its lowering
/// then reports nothing more of it: the statement is dropped when one is found).
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
            let function = match &callee.base {
                PlaceBase::Name(n) if callee.accessors.is_empty() => inputs_of(env, &n.name),
                _ => None,
            };
            match function
                .or_else(|| method_inputs_typed(env, callee, Some(type_of)))
                .or_else(|| instance_inputs(env, callee))
            {
                Some(c) => r.call(&c, args),
                // a method with ANY inputs on a place whose block is not known here (an
                // INTERFACE's method, a reference of another kind): its arguments would land
                // in the hidden inputs, so the call is refused
                None if may_name_any_method(env, callee)
                    && method_block_unknown(env, callee, type_of) =>
                {
                    r.failed = true;
                    r.diags.push(
                        Diagnostic::error(
                            code::E1068,
                            "a method with ANY inputs called through a place whose function block ladderc does not know here (an INTERFACE, a pointer of another type)",
                        )
                        .at(callee.span)
                        .with_primary_label("the block of this method is not known")
                        .with_hint("call the method on an instance of its function block (`inst.M(x)`, `THIS^.M(x)`, `pInst^.M(x)` with `pInst : POINTER TO FB_X`)"),
                    );
                }
                None => {}
            }
            for a in args.iter_mut() {
                r.expr(&mut a.value);
            }
        }
        kind => {
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

struct Rewrite<'a, 'e> {
    env: &'a Env<'e>,
    type_of: &'a dyn Fn(&Expr) -> Option<TypeRef>,
    changed: bool,
    failed: bool,
    diags: &'a mut Diagnostics,
}

impl Rewrite<'_, '_> {
    fn refuse(&mut self, at: crate::Span, msg: String, label: &str, hint: &str) {
        self.diags.push(
            Diagnostic::error(code::E1068, msg)
                .at(at)
                .with_primary_label(label)
                .with_hint(hint),
        );
        self.failed = true;
    }

    fn expr(&mut self, e: &mut Expr) {
        match &mut e.kind {
            ExprKind::Place(p) => {
                if let Some(v) = self.constant(p) {
                    *e = Expr::literal(LiteralKind::Int(v), e.span);
                    self.changed = true;
                } else {
                    self.place(p);
                }
            }
            ExprKind::Unary { operand, .. } => self.expr(operand),
            ExprKind::Binary { left, right, .. } => {
                self.expr(left);
                self.expr(right);
            }
            ExprKind::Call { name, args } => {
                if let Some(c) = callee_of_call(self.env, name) {
                    self.call(&c, args);
                }
                // (the hidden inputs the call was given are this rewrite's own `SIZEOF(x)`,
                // `ADR(x)` and class numbers: not rewritten again, even where the project
                // declares a FUNCTION of such a name with an ANY input, which would give them
                // hidden inputs of their own without end)
                for a in args
                    .iter_mut()
                    .filter(|a| !a.name.as_ref().is_some_and(is_hidden))
                {
                    self.expr(&mut a.value);
                }
            }
            _ => {}
        }
    }

    /// `__SYSTEM.TYPE_CLASS.TYPE_INT` (or `TYPE_CLASS.TYPE_INT`): the class's number, when no
    /// variable has the name.
    fn constant(&self, p: &Place) -> Option<i128> {
        let PlaceBase::Name(n) = &p.base else {
            return None;
        };
        let fields: Vec<&Ident> = p
            .accessors
            .iter()
            .map(|a| match a {
                Accessor::Field(f) => Some(f),
                _ => None,
            })
            .collect::<Option<_>>()?;
        let value = match (n.name.to_ascii_uppercase().as_str(), fields.as_slice()) {
            ("__SYSTEM", [t, v]) if t.is("TYPE_CLASS") => v,
            ("TYPE_CLASS", [v]) => v,
            _ => return None,
        };
        if self.env.var_type(n).is_some() {
            return None;
        }
        class_number(&value.name)
    }

    /// `In.diSize` / `In.TypeClass` of an ANY input `In` of the function being lowered: its hidden
    /// input; `In.pValue` or `In` alone: E1068.
    fn place(&mut self, p: &mut Place) {
        for a in p.accessors.iter_mut() {
            if let Accessor::Index(ix) = a {
                for e in ix.iter_mut() {
                    self.expr(e);
                }
            }
        }
        let PlaceBase::Name(n) = &p.base else {
            return;
        };
        if self.env.vars.contains_key(&n.key()) {
            return;
        }
        let size = format!("{}{SIZE}", n.key());
        if !self.env.vars.contains_key(&size) {
            return;
        }
        let Some(class) = class_var(self.env, &n.name) else {
            return;
        };
        let value = format!("{}{VALUE}", n.key());
        let field = match p.accessors.first() {
            Some(Accessor::Field(f)) if f.is("diSize") => size,
            Some(Accessor::Field(f)) if f.is("TypeClass") => class,
            Some(Accessor::Field(f)) if f.is("pValue") && self.env.vars.contains_key(&value) => {
                value
            }
            _ => {
                // once per input of the function (every use is dropped, the first reported)
                let at = match p.accessors.first() {
                    Some(Accessor::Field(f)) if f.is("pValue") => f.span,
                    _ => p.span,
                };
                let msg = format!(
                    "`{}` of `{}` is an ANY input: it is read through `.diSize`, `.TypeClass` and `.pValue`, not as a value",
                    n.name, self.env.pou_name.name
                );
                self.failed = true;
                if self
                    .diags
                    .iter()
                    .any(|d| d.code == code::E1068 && d.message == msg)
                {
                    return;
                }
                self.refuse(
                    at,
                    msg,
                    "the argument's value has no type here",
                    "read its bytes through `.pValue` (a POINTER TO BYTE to the argument: `In.pValue[i]`, `MEMCPY(ADR(buf), In.pValue, In.diSize)`), or give the function an input of the argument's own type (a VAR_IN_OUT to change it)",
                );
                return;
            }
        };
        p.base = PlaceBase::Name(Ident::new(field, n.span));
        p.accessors.remove(0);
        self.changed = true;
    }

    /// The hidden arguments that pass the caller's own ANY input `place` (a bare name) on to the
    /// ANY input `input` of `f`: its size, class and address inputs. `None` when `place` is no ANY
    /// input of the caller; an empty list after an E1068 (a family the target does not take, or
    /// an address the caller does not have: its body does not read `.pValue`).
    fn forwarded(
        &mut self,
        f: &Callee,
        place: &Place,
        input: &str,
        generic: &str,
        class_input: &str,
    ) -> Option<Vec<(String, Expr)>> {
        let PlaceBase::Name(n) = &place.base else {
            return None;
        };
        if !place.accessors.is_empty() || self.env.vars.contains_key(&n.key()) {
            return None;
        }
        let size = format!("{}{SIZE}", n.key());
        if !self.env.vars.contains_key(&size) {
            return None;
        }
        let class = class_var(self.env, &n.name)?;
        let own = class[n.key().len() + CLASS.len()..].trim_start_matches('_');
        let fits = match (family(generic).flatten(), family(own).flatten()) {
            (None, _) => true,
            (Some(to), Some(from)) => from.iter().all(|t| to.contains(t)),
            (Some(_), None) => false,
        };
        if !fits {
            self.refuse(
                place.span,
                format!(
                    "the input `{input}` of `{}` is {generic}: `{}` ({own}) may hold a type it does not take",
                    f.name, n.name
                ),
                "an ANY input passed on",
                &format!("pass it to an input of {own} or a wider family (ANY)"),
            );
            return Some(Vec::new());
        }
        let var = |name: String| Expr {
            kind: ExprKind::Place(Place {
                base: PlaceBase::Name(Ident::new(name, n.span)),
                accessors: Vec::new(),
                span: n.span,
            }),
            span: n.span,
        };
        let mut hidden = vec![
            (format!("{input}{SIZE}"), var(size)),
            (class_input.to_string(), var(class)),
        ];
        let value_input = format!("{input}{VALUE}");
        if f.addresses.contains(&value_input.to_ascii_uppercase()) {
            let own_value = format!("{}{VALUE}", n.key());
            if !self.env.vars.contains_key(&own_value) {
                self.refuse(
                    place.span,
                    format!(
                        "`{}` reads `{input}.pValue`: `{}` of `{}` has no address to pass on",
                        f.name, n.name, self.env.pou_name.name
                    ),
                    "an ANY input passed on",
                    "read `.pValue` of the input in the caller too (its address is passed only to a body that reads it), or pass a variable",
                );
                return Some(Vec::new());
            }
            hidden.push((value_input, var(own_value)));
        }
        Some(hidden)
    }

    /// A call of a function with ANY inputs: each argument of one replaced by its size and class.
    fn call(&mut self, f: &Callee, args: &mut Vec<Arg>) {
        let inputs = &f.inputs;
        // the positional arguments before the first named one (all of a non-formal call; the
        // leading ones of a call that mixes them, CODESYS's form, W1422)
        let leading = args.iter().take_while(|a| a.name.is_none()).count();
        let mut out = Vec::with_capacity(args.len() + 2);
        for (k, a) in std::mem::take(args).into_iter().enumerate() {
            let target = match &a.name {
                Some(n) => inputs.iter().find(|(i, _)| n.is(i)),
                None if k < leading && a.dir == ArgDir::Input => inputs.get(k),
                None => None,
            };
            let Some((input, Some((generic, class_input)))) = target else {
                // (a positional argument becomes formal: the hidden inputs moved the others)
                let mut a = a;
                if let (None, Some((input, None))) = (&a.name, target) {
                    a.name = Some(Ident::new(input.clone(), a.span));
                }
                out.push(a);
                continue;
            };
            let (input, generic, class_input) =
                (input.clone(), generic.clone(), class_input.clone());
            let ExprKind::Place(place) = &a.value.kind else {
                self.refuse(
                    a.value.span,
                    format!("the ANY input `{input}` of `{}` takes a variable", f.name),
                    "not a variable",
                    "pass a variable, an element or a field (its size and type class are passed): store the value in a variable first",
                );
                out.push(a);
                continue;
            };
            if let Some(hidden) = self.forwarded(f, place, &input, &generic, &class_input) {
                self.changed = true;
                // an ANY input of the caller passed on: its own hidden inputs
                out.extend(hidden.into_iter().map(|(name, value)| Arg {
                    name: Some(Ident::new(name, a.span)),
                    dir: ArgDir::Input,
                    value,
                    span: a.span,
                }));
                continue;
            }
            let Some(ty) = (self.type_of)(&a.value) else {
                // (an undeclared name: its own error comes from the lowering of the argument;
                // an element of an `ARRAY [*]`, typed once `varlen` has rewritten it: the
                // argument is left as it is, not counted as a change)
                let vla = match &place.base {
                    PlaceBase::Name(n) => {
                        let key = format!("{}{}", n.key(), super::varlen::ADDRESS);
                        (!place.accessors.is_empty() && self.env.vars.contains_key(&key))
                            .then(|| n.name.clone())
                    }
                    _ => None,
                };
                if let Some(array) = vla {
                    self.refuse(
                        a.value.span,
                        format!(
                            "an element of the `ARRAY [*]` `{array}` given to the ANY input `{input}` of `{}`",
                            f.name
                        ),
                        "its type is known only at run time here",
                        "copy the element into a variable of its type first, and pass that variable",
                    );
                }
                out.push(a);
                continue;
            };
            self.changed = true;
            if let Some(allowed) = family(&generic).flatten() {
                let elementary = self.env.elementary(&ty).map(|e| e.name().to_string());
                if !elementary
                    .as_deref()
                    .is_some_and(|e| allowed.iter().any(|x| x.eq_ignore_ascii_case(e)))
                {
                    self.refuse(
                        a.value.span,
                        format!(
                            "the input `{input}` of `{}` is {generic}: {} is not one of its types",
                            f.name,
                            elementary
                                .map_or("this argument's type".to_string(), |e| format!("`{e}`"))
                        ),
                        "argument",
                        &format!("pass a value of one of: {}", allowed.join(", ")),
                    );
                    out.push(a);
                    continue;
                }
            }
            let span = a.span;
            let size = Expr {
                kind: ExprKind::Call {
                    name: Ident::new("SIZEOF", span),
                    args: vec![Arg {
                        name: None,
                        dir: ArgDir::Input,
                        value: Expr {
                            kind: ExprKind::Place(place.clone()),
                            span: a.value.span,
                        },
                        span,
                    }],
                },
                span,
            };
            let class = Expr::literal(LiteralKind::Int(class_of(self.env, &ty)), span);
            let mut hidden = vec![(format!("{input}{SIZE}"), size), (class_input, class)];
            // `.pValue`: the argument's address, bounded by the argument (a variable, an element
            // or a field: sema refuses, E0305, what has no address for the whole run)
            let value_input = format!("{input}{VALUE}");
            if f.addresses.contains(&value_input.to_ascii_uppercase()) {
                // (an instance's: for the call only, so that `x` may be a VAR_TEMP or a method's
                // variable; the lowering resets it to NULL when the call returns)
                let adr = if f.instance {
                    super::varlen::CALL_ADDRESS
                } else {
                    "ADR"
                };
                let address = Expr {
                    kind: ExprKind::Call {
                        name: Ident::new(adr, span),
                        args: vec![Arg {
                            name: None,
                            dir: ArgDir::Input,
                            value: Expr {
                                kind: ExprKind::Place(place.clone()),
                                span: a.value.span,
                            },
                            span,
                        }],
                    },
                    span,
                };
                hidden.push((value_input, address));
            }
            for (name, value) in hidden {
                out.push(Arg {
                    name: Some(Ident::new(name, span)),
                    dir: ArgDir::Input,
                    value,
                    span,
                });
            }
        }
        *args = out;
    }
}

/// The ANY input as written that the hidden input `name` stands for, for messages that show a
/// signature (E0335): `Some(Some(("In", "ANY_NUM")))` for the class input `In__TYPECLASS_ANY_NUM`
/// (the input written `In : ANY_NUM`), `Some(None)` for the size and address inputs (shown through
/// the class input), `None` for any other input.
pub fn written_input(name: &str) -> Option<Option<(&str, String)>> {
    let up = name.to_ascii_uppercase();
    if [SIZE, VALUE]
        .iter()
        .any(|s| up.len() > s.len() && up.ends_with(s))
    {
        return Some(None);
    }
    let k = up.find(CLASS).filter(|k| *k > 0)?;
    let generic = up[k + CLASS.len()..].trim_start_matches('_');
    let generic = if generic.is_empty() { "ANY" } else { generic };
    Some(Some((name.get(..k)?, generic.to_string())))
}

/// Whether `name` is a hidden input of an ANY input (`In__DISIZE`, `In__TYPECLASS`, `In__PVALUE`).
fn is_hidden(name: &Ident) -> bool {
    let up = name.name.to_ascii_uppercase();
    [SIZE, CLASS, VALUE].iter().any(|s| up.ends_with(s))
}
