//! Variables whose type is an INTERFACE (CODESYS, TwinCAT; IEC 61131-3 edition 3, 6.6.6.5 "interface
//! as a variable type"): `itf : I_Shape;` holds any instance of a function block that implements
//! `I_Shape` (itself or through a base it EXTENDS), and `itf.Area()` runs the method of the block the
//! instance really is (dynamic dispatch).
//!
//! Input: every interface with the function blocks that implement it ([`table`], from
//! [`super::inherit::flatten`]) and the ST statements being lowered (`rewrite`).
//! Output: each interface `I` is also a hidden STRUCT named `I` (so `itf : I`, `ARRAY[1..3] OF I`,
//! `VAR_INPUT`, `VAR_IN_OUT`, `VAR_GLOBAL` of it are ordinary variables for sema and C):
//! - `__TAG : UINT`: which block the instance is (a number per block, `0` unassigned);
//! - `__R_<FB> : REF_TO <FB>` for each block that implements `I`: the instance (only the one of the
//!   tag is non-NULL);
//! - `__M_<M> : T` for each method returning `T` (its result, read after the call: the parser reads
//!   `itf.M()` as `itf.__M_M`, as for any instance), properties' accessors included;
//! - `__UNASSIGNED : REF_TO I`, always NULL: what a call through an unassigned interface reads.
//!
//! The statements using them are rewritten before they are lowered: `itf := inst;` sets the tag and
//! the references (`REF(inst)`), `itf := 0;` clears them; `itf.M(args);` is a CASE on the tag calling
//! `itf.__R_<FB>^.M(args)` and copying its result; `itf = 0`, `itf <> 0` test the tag, `i1 = i2`
//! the tags and the references; an instance passed to an input of interface type is assigned to the
//! input before the call. An interface variable's initial value (`itf : I := inst;`,
//! `itfs : ARRAY[1..2] OF I := [fb1, fb2];`) is such an assignment: a POU's when it first runs
//! ([`initial_values`]), a global list's once before the first cycle ([`global_initial_values`],
//! run by `super::fb_init`'s hidden program).
//! Invariants: a call through an unassigned interface (tag 0) calls nothing: its result reads 0 and
//! the run reports "NULL reference dereferenced (first: itf.__UNASSIGNED^ in POU)" at its end, like
//! a NULL `REF_TO`, and goes on; an instance may only be assigned where its address may be taken
//! (`REF`: no VAR_IN_OUT, temporary or function variable, sema's E0305); assigning what does not
//! implement the interface is one E0340.

use super::ast::{Accessor, Arg, ArgDir, BinaryOp, CaseArm, CaseLabel, Expr, ExprKind, Place};
use super::ast::{PlaceBase, Stmt, StmtKind};
use super::file::PendingMethod;
use super::infer::Env;
use super::inherit::InterfaceOop;
use super::types::MethodSig;
use crate::ast::{
    CompilationUnit, Ident, LibraryElement, LiteralKind, PouKind, RefKind, TypeDecl, TypeDef,
    TypeRef, VarDecl,
};
use crate::Span;
use diagnostics::{code, Diagnostic, Diagnostics};
use std::collections::{HashMap, HashSet};

/// The hidden field that tells which block an interface variable holds (`0`: none).
pub const TAG: &str = "__TAG";
/// The hidden, always NULL reference a call through an unassigned interface reads.
pub const UNASSIGNED: &str = "__UNASSIGNED";

/// The hidden call the parser reads `r ?= e;` as (`r := ?=(e)`, IEC 61131-3 ed. 3, 6.6.6.7
/// assignment attempt), rewritten by `rewrite`.
pub const ATTEMPT: &str = "?=";

/// The operand of `r ?= e;` (`e`), when `value` is the parser's hidden call.
fn attempt_operand(value: &Expr) -> Option<&Expr> {
    match &value.kind {
        ExprKind::Call { name, args } if name.name == ATTEMPT && args.len() == 1 => {
            Some(&args[0].value)
        }
        _ => None,
    }
}

/// The hidden field holding an instance of block `fb`: `__R_<FB>`.
fn ref_field(fb: &str) -> String {
    format!("__R_{}", fb.to_ascii_uppercase())
}

/// The variable of the caller holding the result, of an interface type, of method `m` called
/// through the interface at `at` (the call's callee).
fn interface_result(at: Span, m: &str) -> String {
    format!("__IR_{}_{}", at.start, m.to_ascii_uppercase())
}

/// The type of the result of method `m` (a property's Get accessor included) called through a
/// value of type `t`, when `t` is an interface and the result is an interface too: such a
/// result is no field of the interface's hidden structure but a variable of the caller
/// ([`interface_result`]), so `env.member` does not know it (`ifut.executor.keepJob` with
/// `PROPERTY executor : I_Job` of interface `I_Future`).
pub(super) fn interface_result_type(env: &Env<'_>, t: &TypeRef, m: &str) -> Option<TypeRef> {
    let TypeRef::Named(n) = env.resolve(t) else {
        return None;
    };
    env.decls
        .interfaces
        .get(&n.key())?
        .interface_results
        .iter()
        .find(|(k, _)| k.eq_ignore_ascii_case(m))
        .map(|(_, ty)| ty.clone())
}

/// An interface as variables of its type see it.
#[derive(Debug, Clone)]
pub struct Interface {
    /// Its name as declared.
    pub name: Ident,
    /// The blocks that implement it (directly, through a base, or through an interface that
    /// extends it) with their tags, in declaration order.
    pub classes: Vec<(Ident, u32)>,
    /// Its methods and those of the interfaces it extends (properties as their accessors).
    pub methods: Vec<MethodSig>,
    /// Its own key and those of the interfaces it extends (an `I2 EXTENDS I1` value is an `I1`).
    pub within: Vec<String>,
    /// The methods (upper-case) whose result is of an interface type, with that type: their
    /// result is no field of the structure (it would hold itself); a call through the interface
    /// copies it into a variable of the caller (`interface_result`).
    pub interface_results: Vec<(String, TypeRef)>,
    /// The ABSTRACT blocks (upper case) that implement it: no instance is of them, so their own
    /// text never runs (each derived block runs its copy, where THIS^ is the derived block); a
    /// `THIS^` of theirs given to the interface is no error.
    pub abstract_classes: Vec<String>,
}

/// Whether `t` is an interface type or an array of one.
fn names_interface(t: &TypeRef, interfaces: &HashMap<String, &InterfaceOop>) -> bool {
    match t {
        TypeRef::Named(n) => interfaces.contains_key(&n.key()),
        TypeRef::Array { element, .. } => names_interface(element, interfaces),
        _ => false,
    }
}

impl Interface {
    fn tag_of(&self, fb: &str) -> Option<u32> {
        self.classes
            .iter()
            .find(|(c, _)| c.name.eq_ignore_ascii_case(fb))
            .map(|c| c.1)
    }
}

/// The interface `key` and all it extends (keys), itself first.
fn closure(key: &str, interfaces: &HashMap<String, &InterfaceOop>) -> Vec<String> {
    let mut out = Vec::new();
    let mut todo = vec![key.to_string()];
    let mut seen = HashSet::new();
    while let Some(k) = todo.pop() {
        if !seen.insert(k.clone()) || seen.len() > 100 {
            continue;
        }
        if let Some(i) = interfaces.get(&k) {
            todo.extend(i.extends.iter().map(Ident::key));
        }
        out.push(k);
    }
    out
}

/// The interfaces of the program (`interfaces`), each with the blocks of `blocks` (name, whether it
/// has no instances, the interfaces it and its bases implement) that implement it; declares each
/// interface's hidden structure (see the module documentation) in `units`.
pub fn table(
    units: &mut [CompilationUnit],
    blocks: &[(Ident, bool, Vec<Ident>)],
    interfaces: &HashMap<String, &InterfaceOop>,
) -> Vec<Interface> {
    let mut keys: Vec<&String> = interfaces.keys().collect();
    keys.sort();
    let mut out = Vec::new();
    let mut types = Vec::new();
    for key in keys {
        let i = interfaces[key];
        let within = closure(key, interfaces);
        let span = i.name.span;
        let classes: Vec<(Ident, u32)> = blocks
            .iter()
            .enumerate()
            .filter(|(_, (_, none, implements))| {
                !none
                    && implements
                        .iter()
                        .any(|x| closure(&x.key(), interfaces).contains(key))
            })
            .map(|(k, (name, _, _))| (name.clone(), k as u32 + 1))
            .collect();
        let abstract_classes: Vec<String> = blocks
            .iter()
            .filter(|(_, none, implements)| {
                *none
                    && implements
                        .iter()
                        .any(|x| closure(&x.key(), interfaces).contains(key))
            })
            .map(|(name, _, _)| name.key())
            .collect();
        let mut methods: Vec<&PendingMethod> = Vec::new();
        for k in &within {
            for m in interfaces.get(k).map_or(&[][..], |x| &x.methods[..]) {
                if !methods.iter().any(|x| x.name.key() == m.name.key()) {
                    methods.push(m);
                }
            }
        }
        let named = |n: &str| TypeRef::Named(Ident::new(n, span));
        let reference = |target: TypeRef| TypeRef::Ref {
            kind: RefKind::RefTo,
            target: Box::new(target),
            span,
        };
        let mut fields = vec![
            VarDecl::new(Ident::new(TAG, span), named("UINT"), span),
            VarDecl::new(Ident::new("__QUERIED", span), named("BOOL"), span),
            VarDecl::new(
                Ident::new(UNASSIGNED, span),
                reference(named(&i.name.name)),
                span,
            ),
        ];
        for (c, _) in &classes {
            fields.push(VarDecl::new(
                Ident::new(ref_field(&c.name), span),
                reference(TypeRef::Named(c.clone())),
                span,
            ));
        }
        let mut interface_results = Vec::new();
        for m in &methods {
            if let Some(r) = &m.ret {
                if names_interface(&r.ty, interfaces) {
                    // a result holding an interface would make the structure hold itself
                    interface_results.push((m.name.key(), r.ty.clone()));
                    continue;
                }
                fields.push(VarDecl::new(
                    Ident::new(crate::actions::method_result(&m.name.name), span),
                    r.ty.clone(),
                    span,
                ));
            }
        }
        types.push(TypeDecl {
            name: i.name.clone(),
            def: TypeDef::Struct { fields },
            union: false,
            span,
        });
        out.push(Interface {
            name: i.name.clone(),
            interface_results,
            classes,
            methods: methods.iter().map(|m| MethodSig::of(m)).collect(),
            within,
            abstract_classes,
        });
    }
    if let (Some(u), false) = (units.first_mut(), types.is_empty()) {
        u.items.insert(0, LibraryElement::DataTypes(types));
    }
    out
}

/// The initial value of an interface variable of a POU: `itf : I_Shape := fbCircle;`.
#[derive(Debug, Clone)]
pub struct Init {
    /// The name of the POU that declares it (its span identifies the POU); `None` for a
    /// variable of a global list (assigned before the first cycle: [`global_initial_values`]).
    pub pou: Option<Span>,
    /// The interface variable.
    pub var: Ident,
    /// The element of an ARRAY OF an interface (`itfs : ARRAY[0..1] OF I_Lamp := [fb1, fb2];`):
    /// its index; `None` for a plain interface variable.
    pub index: Option<i128>,
    /// The instance (or interface) it starts with.
    pub value: crate::ast::VarRef,
}

/// The hidden flag of a function block or program whose interface variables have their initial
/// values: set once they are assigned.
pub const INIT_FLAG: &str = "__ITF_INIT";

/// The assignments `itf := inst;` (`itfs[k] := inst;`) that give interface variables their initial
/// values `inits`; `None` after an E0336 (an instance written with an index).
fn assignments(inits: &[&Init], diags: &mut Diagnostics) -> Option<Vec<Stmt>> {
    let mut body = Vec::new();
    for i in inits {
        let v = &i.value;
        let mut accessors = Vec::new();
        for a in v.accessors.iter() {
            match a {
                crate::ast::Accessor::Field(f) => accessors.push(Accessor::Field(f.clone())),
                crate::ast::Accessor::Deref(s) => accessors.push(Accessor::Deref(*s)),
                crate::ast::Accessor::Index(_) => {
                    diags.push(
                        Diagnostic::error(
                            code::E0336,
                            format!(
                                "`{}`: an initial value with an index is not compiled",
                                i.var.name
                            ),
                        )
                        .at(v.span)
                        .with_primary_label("an array element")
                        .with_hint(format!("assign it in the body (`{} := ...;`)", i.var.name)),
                    );
                    return None;
                }
            }
        }
        let value = Place {
            base: PlaceBase::Name(v.base.clone()),
            accessors,
            span: v.span,
        };
        let target = Place {
            base: PlaceBase::Name(i.var.clone()),
            accessors: i
                .index
                .map(|k| vec![Accessor::Index(vec![int(k, v.span)])])
                .unwrap_or_default(),
            span: i.var.span,
        };
        body.push(assign(target, place_expr(value, v.span), v.span));
    }
    Some(body)
}

/// The statements that give the interface variables of the global lists their initial values
/// (`aItf : ARRAY[1..2] OF I_Log := [GVL_Dev.fbCyl1.fbLog, fbP];` in a TwinCAT GVL: Beckhoff
/// Infosys "Interface": an interface variable is assigned an instance): run by
/// `super::fb_init`'s hidden program once before the first cycle, before any FB_init, as
/// TwinCAT assigns initial values before it calls FB_init. The instances are globals or parts of
/// them (the value names no POU's variable), whose addresses are fixed for the whole run.
pub fn global_initial_values(inits: &[Init], diags: &mut Diagnostics) -> Vec<Stmt> {
    let globals: Vec<&Init> = inits.iter().filter(|i| i.pou.is_none()).collect();
    assignments(&globals, diags).unwrap_or_default()
}

/// The IL that gives the interface variables of `p` their initial values (`inits`, all of `p`),
/// then the variables whose initial value is computed at run time (`computed`, assignments):
/// in a FUNCTION at each call, in a FUNCTION_BLOCK or PROGRAM the first time its body or one of
/// its methods runs (behind the hidden flag [`INIT_FLAG`], declared in `p`). CODESYS and TwinCAT
/// assign them before the first cycle; here a call through them before the POU first runs finds
/// them unassigned. Empty when `inits` is.
pub fn initial_values(
    decls: &super::Declarations,
    p: &mut crate::ast::Pou,
    inits: &[&Init],
    computed: Vec<Stmt>,
    diags: &mut Diagnostics,
) -> Vec<crate::ast::IlStmt> {
    let span = match (inits.first(), computed.first()) {
        (Some(first), _) => first.var.span,
        (None, Some(s)) => s.span,
        (None, None) => return Vec::new(),
    };
    let Some(mut body) = assignments(inits, diags) else {
        return Vec::new();
    };
    // the run-time initial values of other variables (`n : UDINT := MIN(250000, k / 25);`,
    // `super::pou_inits::pou_run_time_inits`), in declaration order
    body.extend(computed);
    let stmts = if p.kind == PouKind::Function {
        body
    } else {
        let flag = Place {
            base: PlaceBase::Name(Ident::new(INIT_FLAG, span)),
            accessors: Vec::new(),
            span,
        };
        p.var_blocks.push(crate::ast::VarBlock::locals(
            vec![VarDecl::new(
                Ident::new(INIT_FLAG, span),
                TypeRef::Named(Ident::new("BOOL", span)),
                span,
            )],
            span,
        ));
        body.insert(0, assign(flag.clone(), bool_lit(true, span), span));
        vec![Stmt {
            kind: StmtKind::If {
                branches: vec![super::ast::CondBranch {
                    cond: Expr {
                        kind: ExprKind::Unary {
                            op: super::ast::UnaryOp::Not,
                            operand: Box::new(place_expr(flag, span)),
                        },
                        span,
                    },
                    body,
                    span,
                }],
                else_body: None,
            },
            span,
        }]
    };
    let mut low = super::PouLowering::new(decls, p).with_prefix("_ITF_");
    let il = low.statements(&stmts, diags);
    if let Some(t) = low.finish(span) {
        p.var_blocks.push(t);
    }
    il
}

/// The methods of `i` for a message: `Area, Scale`.
fn shown_methods(i: &Interface) -> String {
    let names: Vec<&str> = i
        .methods
        .iter()
        .filter(|m| !super::property::is_accessor(&m.name))
        .map(|m| m.name.as_str())
        .collect();
    if names.is_empty() {
        "none".into()
    } else {
        names.join(", ")
    }
}

// ------------------------------------------------------------------ building statements

fn field(p: &Place, name: &str, span: Span) -> Place {
    let mut q = p.clone();
    q.accessors.push(Accessor::Field(Ident::new(name, span)));
    q
}

fn deref(p: &Place, span: Span) -> Place {
    let mut q = p.clone();
    q.accessors.push(Accessor::Deref(span));
    q
}

fn place_expr(p: Place, span: Span) -> Expr {
    Expr {
        kind: ExprKind::Place(p),
        span,
    }
}

fn int(v: i128, span: Span) -> Expr {
    Expr::literal(LiteralKind::Int(v), span)
}

fn null(span: Span) -> Expr {
    place_expr(
        Place {
            base: PlaceBase::Name(Ident::new("NULL", span)),
            accessors: Vec::new(),
            span,
        },
        span,
    )
}

fn bool_lit(v: bool, span: Span) -> Expr {
    Expr::literal(LiteralKind::Bool(v), span)
}

fn binary(op: BinaryOp, left: Expr, right: Expr, span: Span) -> Expr {
    Expr {
        kind: ExprKind::Binary {
            op,
            left: Box::new(left),
            right: Box::new(right),
        },
        span,
    }
}

fn assign(target: Place, value: Expr, span: Span) -> Stmt {
    Stmt {
        kind: StmtKind::Assign { target, value },
        span,
    }
}

/// Whether `e` is `0` or `NULL` (CODESYS compares and assigns interfaces so).
fn is_zero(env: &Env<'_>, e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Literal(l) => matches!(l.kind, LiteralKind::Int(0)),
        ExprKind::Place(p) => {
            p.accessors.is_empty()
                && p.name()
                    .is_some_and(|n| n.is("NULL") && env.var_type(n).is_none())
        }
        _ => false,
    }
}

/// The rewriting of one statement (see [`rewrite`]).
struct Rewriter<'a, 'd> {
    env: &'a Env<'a>,
    diags: &'d mut Diagnostics,
    changed: bool,
    /// The statements `__QUERYINTERFACE` / `__QUERYPOINTER` run before the statement.
    before: Vec<Stmt>,
    /// Whether the expression being rewritten runs once, just after `before` (not an ELSIF,
    /// WHILE or UNTIL condition).
    hoistable: bool,
    /// The temporaries declared (see [`rewrite`]).
    temps: Vec<VarDecl>,
    first: usize,
}

/// Whether `s` itself (an assignment's value, a call's arguments, a control statement's
/// conditions; not the statements it holds) calls `__QUERYINTERFACE` or `__QUERYPOINTER`: such a
/// statement is rewritten even where the project declares no interface (its operands then name a
/// type declared nowhere, E1003, or are no interface variables, E0341), never left as a call of
/// a function nothing declares (before round 30, E1019 "unknown function `__QUERYINTERFACE`").
fn queries_interface(s: &Stmt) -> bool {
    fn in_expr(e: &Expr, depth: usize) -> bool {
        if depth > 256 {
            return false;
        }
        match &e.kind {
            ExprKind::Call { name, args } => {
                name.is("__QUERYINTERFACE")
                    || name.is("__QUERYPOINTER")
                    || args.iter().any(|a| in_expr(&a.value, depth + 1))
            }
            ExprKind::Unary { operand, .. } => in_expr(operand, depth + 1),
            ExprKind::Binary { left, right, .. } => {
                in_expr(left, depth + 1) || in_expr(right, depth + 1)
            }
            _ => false,
        }
    }
    match &s.kind {
        StmtKind::Assign { value, .. } => in_expr(value, 0),
        StmtKind::Call { args, .. } => args.iter().any(|a| in_expr(&a.value, 0)),
        k => k.control_exprs().iter().any(|e| in_expr(e, 0)),
    }
}

/// `s` with its uses of interface variables rewritten (see the module documentation): the
/// statements to lower instead, or `None` when `s` uses none in what it evaluates itself (nested
/// statements are rewritten when they are lowered).
/// `first` numbers the temporaries it declares (`_ITF_A<n>`, returned with the statements: the
/// interface a FUNCTION's input receives); the caller's temporaries so far, so names never repeat.
pub(super) fn rewrite(
    env: &Env<'_>,
    s: &Stmt,
    first: usize,
    diags: &mut Diagnostics,
) -> Option<(Vec<Stmt>, Vec<VarDecl>)> {
    let attempt =
        matches!(&s.kind, StmtKind::Assign { value, .. } if attempt_operand(value).is_some());
    if env.decls.interfaces.is_empty()
        && env.decls.bases.is_empty()
        && !attempt
        && !queries_interface(s)
    {
        return None;
    }
    let mut r = Rewriter {
        env,
        diags,
        changed: false,
        before: Vec::new(),
        hoistable: true,
        temps: Vec::new(),
        first,
    };
    let out = r.stmt(s);
    r.changed.then_some((out, r.temps))
}

impl Rewriter<'_, '_> {
    /// The interface a value of type `t` is, if it is one.
    fn interface(&self, t: &TypeRef) -> Option<&Interface> {
        let TypeRef::Named(n) = self.env.resolve(t) else {
            return None;
        };
        self.env.decls.interfaces.get(&n.key())
    }

    fn place_interface(&self, p: &Place) -> Option<&Interface> {
        self.interface(&self.place_type(p)?)
    }

    /// The type of place `p`: the POU's variables (`Env::place_type`), or one of the
    /// temporaries this statement's rewriting declared (a bare name).
    fn place_type(&self, p: &Place) -> Option<TypeRef> {
        self.env
            .place_type(p)
            .or_else(|| match (&p.base, p.accessors.is_empty()) {
                (PlaceBase::Name(n), true) => self
                    .temps
                    .iter()
                    .find(|t| t.name.key() == n.key())
                    .map(|t| t.ty.clone()),
                _ => None,
            })
    }

    /// The type named in the declaration of the variable `p` starts with, when that type is
    /// declared nowhere (no elementary type, type, POU or standard block): a vendor library's
    /// interface ladderc does not have (`iEvt : I_BA_EventObject;` of Tc3_BA2).
    fn undeclared_type(&self, p: &Place) -> Option<Ident> {
        let PlaceBase::Name(n) = &p.base else {
            return None;
        };
        let TypeRef::Named(t) = self.env.var_type(n)? else {
            return None;
        };
        let known = crate::sema::model::Elementary::from_name(&t.name.to_ascii_uppercase())
            .is_some()
            || self.env.decls.type_decl(&t.name).is_some()
            || self.env.decls.pou(&t.name).is_some()
            || self.env.decls.interfaces.contains_key(&t.key())
            || crate::sema::model::StdFb::from_name(&t.name).is_some();
        // (a `__` name is a library-qualified type whose library was reported, E1032: unknown
        // too, and already said)
        (!known).then_some(t)
    }

    /// A query whose operands' types (`missing`) are declared nowhere: those types are the one
    /// cause, reported as sema reports them (E1003 at the declaration, once each:
    /// [`Diagnostics::push`] drops sema's equal one, and none is added when sema's is there), not
    /// the operator; the query reads FALSE (nothing else reported for it: no E1007 for an IF
    /// whose condition it is). The E1003s are made here because sema does not run when the
    /// lowering finds errors (as for a method chain on such a type, `lower::call_chain`).
    fn missing_interfaces(&mut self, missing: &[Ident], span: Span) -> Option<Expr> {
        for missing in missing {
            let here = Some(missing.span);
            // an error already made at the type's name (its E1003, or the E1032 of the library
            // that qualifies it, `jobmgmt.InterfaceFuture`) is the one cause
            let at_name = |d: &Diagnostic| {
                d.severity == diagnostics::Severity::Error
                    && d.span.is_some_and(|s| {
                        s.file == missing.span.file
                            && s.start >= missing.span.start
                            && s.start <= missing.span.end
                    })
            };
            if missing.name.starts_with("__")
                || self
                    .diags
                    .iter()
                    .any(|d| d.code == code::E1003 && d.span == here || at_name(d))
            {
                continue;
            }
            self.diags.push(
                Diagnostic::error(code::E1003, format!("unknown type `{}`", missing.name))
                    .at(missing.span)
                    .with_primary_label("no such type")
                    .with_hint(
                        "declare it in a TYPE block or as a FUNCTION_BLOCK, or use an elementary type",
                    ),
            );
        }
        Some(bool_lit(false, span))
    }

    fn expr_interface(&self, e: &Expr) -> Option<&Interface> {
        match &e.kind {
            ExprKind::Place(p) => self.place_interface(p),
            _ => None,
        }
    }

    /// `THIS^` when `e` is `THIS` itself (read by the parser as `ADR(THIS^)`; `REF(THIS^)` too)
    /// in a function block or class that declares no variable `THIS`: the reference to the
    /// instance (edition 3 and SIMATIC AX: `REF_TO` the class; CODESYS: `POINTER TO` the block)
    /// stands for the instance where an interface is expected (`Item := THIS;` in a method
    /// returning an interface the class implements, `handler.Action(te := THIS)`: before round
    /// 28, E1006 and E1012).
    fn this_instance(&self, e: &Expr) -> Option<Expr> {
        let ExprKind::Call { name, args } = &e.kind else {
            return None;
        };
        let [arg] = args.as_slice() else {
            return None;
        };
        if !(name.is("ADR") || name.is("REF")) || arg.name.is_some() {
            return None;
        }
        let ExprKind::Place(p) = &arg.value.kind else {
            return None;
        };
        let PlaceBase::Name(n) = &p.base else {
            return None;
        };
        let this = n.is("THIS")
            && matches!(p.accessors.as_slice(), [Accessor::Deref(_)])
            && self.env.pou_kind == PouKind::FunctionBlock
            && self.env.var_type(n).is_none();
        this.then(|| arg.value.clone())
    }

    /// The function block type of an instance `e` (a place whose type is a user block).
    fn block_of(&self, e: &Expr) -> Option<Ident> {
        if let Some(inst) = self.this_instance(e) {
            return self.block_of(&inst);
        }
        let ExprKind::Place(p) = &e.kind else {
            return None;
        };
        // `THIS^`: the block being lowered (`registry.Add(THIS^)`)
        if let (PlaceBase::Name(n), [Accessor::Deref(_)]) = (&p.base, p.accessors.as_slice()) {
            if n.is("THIS")
                && self.env.pou_kind == PouKind::FunctionBlock
                && self.env.var_type(n).is_none()
            {
                return Some(self.env.pou_name.clone());
            }
        }
        let TypeRef::Named(n) = self.env.resolve(&self.env.place_type(p)?) else {
            return None;
        };
        let pou = self.env.decls.pou(&n.name)?;
        (pou.kind == PouKind::FunctionBlock).then(|| Ident::new(&pou.name, n.span))
    }

    fn stmt(&mut self, s: &Stmt) -> Vec<Stmt> {
        let span = s.span;
        let mut s = s.clone();
        match &mut s.kind {
            StmtKind::Assign { target, value } if attempt_operand(value).is_some() => {
                let mut src = attempt_operand(value)
                    .cloned()
                    .unwrap_or_else(|| value.clone());
                self.compare(&mut src);
                self.changed = true;
                let out = self.attempt(target, &src, span);
                let mut all = std::mem::take(&mut self.before);
                all.extend(out);
                return all;
            }
            StmtKind::Assign { target, value } => {
                // `itf.__M___GET_EXECUTOR.keepJob := v;` after the getter's call: a component
                // of the instance the result refers to (lowered again: the property's setter)
                if let Some(r) = self.interface_result_read(target) {
                    *target = r;
                    self.changed = true;
                }
                self.indexes(target);
                if let Some(i) = self.place_interface(target).cloned() {
                    if let Some(out) = self.assign_interface(target, &i, value, span) {
                        self.changed = true;
                        return out;
                    }
                }
                self.compare(value);
            }
            StmtKind::Call { callee, args } => {
                if let Some(out) = self.dispatch(callee, args, span) {
                    self.changed = true;
                    return out;
                }
                let inputs = self.interface_inputs(callee, args);
                if !inputs.is_empty() {
                    self.changed = true;
                    self.before.extend(inputs);
                }
                for a in args.iter_mut() {
                    self.compare(&mut a.value);
                }
            }
            StmtKind::If { branches, .. } => {
                for (k, b) in branches.iter_mut().enumerate() {
                    self.hoistable = k == 0;
                    self.compare(&mut b.cond);
                }
            }
            StmtKind::Case { selector, .. } => self.compare(selector),
            StmtKind::For { from, to, by, .. } => {
                self.compare(from);
                self.compare(to);
                if let Some(b) = by {
                    self.compare(b);
                }
            }
            StmtKind::While { cond, .. } => {
                self.hoistable = false;
                self.compare(cond);
            }
            StmtKind::Repeat { until, .. } => {
                self.hoistable = false;
                self.compare(until);
            }
            _ => {}
        }
        let mut out = std::mem::take(&mut self.before);
        out.push(s);
        out
    }

    /// `target ?= src;` (IEC 61131-3 ed. 3, 6.6.6.7 assignment attempt): `target`, an interface,
    /// takes the instance `src` (an interface or an instance) holds when its block implements
    /// it, else NULL (as `__QUERYINTERFACE`); `target`, a `REF_TO C` of a class or block, takes
    /// the instance `src` holds when it is a `C` or derives from it, else NULL. Anything else is
    /// one E1083.
    fn attempt(&mut self, target: &Place, src: &Expr, span: Span) -> Vec<Stmt> {
        let fail = |this: &mut Self, msg: String, label: &str, hint: &str| {
            this.diags.push(
                Diagnostic::error(code::E1083, msg)
                    .at(span)
                    .with_primary_label(label.to_string())
                    .with_hint(hint.to_string()),
            );
            Vec::new()
        };
        // a FUNCTION's result of an interface or reference type (`state ?= GetPayload();`, as
        // SIMATIC AX writes it: ed. 3, 6.6.6.7 takes any expression of such a type; round 31,
        // before: E1083): computed into a temporary of that type first, then attempted from
        // it, as the two-step form `p := GetPayload(); state ?= p;` (one level: the temporary
        // is a place)
        if matches!(src.kind, ExprKind::Call { .. }) && self.this_instance(src).is_none() {
            if let Some(ty) = self.env.expr(src).known().cloned() {
                let by_reference = matches!(self.env.resolve(&ty), TypeRef::Ref { .. });
                if by_reference || self.interface(&ty).is_some() {
                    let temp = Ident::new(
                        format!("_ITF_A{}", self.first + self.temps.len() + 1),
                        src.span,
                    );
                    self.temps.push(VarDecl::new(temp.clone(), ty, src.span));
                    let place = Place {
                        base: PlaceBase::Name(temp),
                        accessors: Vec::new(),
                        span: src.span,
                    };
                    let mut before = self.stmt(&assign(place.clone(), src.clone(), span));
                    let out = self.attempt(target, &place_expr(place, src.span), span);
                    before.extend(std::mem::take(&mut self.before));
                    before.extend(out);
                    return before;
                }
            }
        }
        // a call whose result type is not known here (a function no file declares, a missing
        // library's `AxUnit.Mocking.GetPayload()`): left as a plain assignment, so the call's
        // own error is the one reported (round 31, before: E1083 and that error, one cause)
        if matches!(src.kind, ExprKind::Call { .. })
            && self.this_instance(src).is_none()
            && self.env.expr(src).known().is_none()
        {
            return vec![assign(target.clone(), src.clone(), span)];
        }
        let ExprKind::Place(sp) = &src.kind else {
            return fail(
                self,
                "the right side of an assignment attempt `?=` is no variable, instance or function or method result".into(),
                "not an interface or reference",
                "write `r ?= itf;` with an interface, an instance, a reference or a function or method returning one",
            );
        };
        if self.place_interface(target).is_some() {
            let args = [
                Arg {
                    name: None,
                    dir: ArgDir::Input,
                    value: src.clone(),
                    span: src.span,
                },
                Arg {
                    name: None,
                    dir: ArgDir::Input,
                    value: place_expr(target.clone(), target.span),
                    span: target.span,
                },
            ];
            if self.place_interface(sp).is_none() && self.block_of(src).is_none() {
                return fail(
                    self,
                    "an assignment attempt `?=` to an interface takes an interface or an instance"
                        .into(),
                    "neither an interface nor an instance",
                    "assign an interface variable or a function block or class instance",
                );
            }
            let _ = self.query(&Ident::new("__QUERYINTERFACE", span), &args, span);
            return std::mem::take(&mut self.before);
        }
        let class = match self.env.place_type(target).map(|t| self.env.resolve(&t)) {
            Some(TypeRef::Ref { target: t, .. }) => match *t {
                TypeRef::Named(n) => self
                    .env
                    .decls
                    .pou(&n.name)
                    .filter(|p| p.kind == PouKind::FunctionBlock)
                    .map(|p| p.name.clone()),
                _ => None,
            },
            _ => None,
        };
        let Some(class) = class else {
            return fail(
                self,
                "an assignment attempt `?=` writes an interface or a REF_TO a class or function block".into(),
                "not an interface or reference to a class",
                "declare the variable on the left as an interface or as `REF_TO` a class or function block",
            );
        };
        // whether block `k` is `class` or derives from it
        let bases = &self.env.decls.bases;
        let fits = |k: &str| {
            k.eq_ignore_ascii_case(&class)
                || bases
                    .get(&k.to_ascii_uppercase())
                    .is_some_and(|b| b.iter().any(|x| x.eq_ignore_ascii_case(&class)))
        };
        if let Some(si) = self.place_interface(sp).cloned() {
            let arms = si
                .classes
                .iter()
                .filter(|(k, _)| fits(&k.name))
                .map(|(k, tag)| CaseArm {
                    labels: vec![CaseLabel::Value(int((*tag).into(), span))],
                    body: vec![assign(
                        target.clone(),
                        place_expr(field(sp, &ref_field(&k.name), span), span),
                        span,
                    )],
                    span,
                })
                .collect();
            return vec![Stmt {
                kind: StmtKind::Case {
                    selector: place_expr(field(sp, TAG, span), span),
                    arms,
                    else_body: Some(vec![assign(target.clone(), null(span), span)]),
                },
                span,
            }];
        }
        // a reference or an instance: its type is known when compiling
        let (block, is_ref) = match self.place_type(sp).map(|t| self.env.resolve(&t)) {
            Some(TypeRef::Ref { target: t, .. }) => match *t {
                TypeRef::Named(n) => (Some(n.name), true),
                _ => (None, true),
            },
            _ => (self.block_of(src).map(|b| b.name), false),
        };
        let Some(block) = block else {
            return fail(
                self,
                "an assignment attempt `?=` to a reference takes an interface, an instance or a reference".into(),
                "neither an interface, an instance nor a reference",
                "assign an interface variable, a class or function block instance, or a REF_TO one",
            );
        };
        let downcast = bases
            .get(&class.to_ascii_uppercase())
            .is_some_and(|b| b.iter().any(|x| x.eq_ignore_ascii_case(&block)));
        if downcast && is_ref {
            return fail(
                self,
                format!("an assignment attempt from a `REF_TO {block}` to a `REF_TO {class}` is not supported"),
                "the instance's own class is not known when compiling",
                "ladderc's references do not carry their instance's class: hold the instance in an interface variable and attempt from it",
            );
        }
        let value = if !fits(&block) {
            null(span)
        } else if is_ref {
            src.clone()
        } else {
            Expr {
                kind: ExprKind::Call {
                    name: Ident::new("REF", span),
                    args: vec![Arg {
                        name: None,
                        dir: ArgDir::Input,
                        value: src.clone(),
                        span,
                    }],
                },
                span,
            }
        };
        vec![assign(target.clone(), value, span)]
    }

    /// `target := value` where `target` is of interface `i`: the statements setting its tag and
    /// references; `None` when it is a plain copy of a value of the same interface (or not for
    /// this rewriting: sema reports it).
    fn assign_interface(
        &mut self,
        target: &Place,
        i: &Interface,
        value: &Expr,
        span: Span,
    ) -> Option<Vec<Stmt>> {
        let set = |tag: Expr, refs: &dyn Fn(&Ident) -> Expr| {
            let mut out = vec![assign(field(target, TAG, span), tag, span)];
            for (c, _) in &i.classes {
                out.push(assign(
                    field(target, &ref_field(&c.name), span),
                    refs(c),
                    span,
                ));
            }
            out
        };
        if is_zero(self.env, value) {
            return Some(set(int(0, span), &|_| null(span)));
        }
        let this = self.this_instance(value);
        let value = this.as_ref().unwrap_or(value);
        if let Some(j) = self.expr_interface(value).cloned() {
            if j.name.key() == i.name.key() {
                return None;
            }
            let ExprKind::Place(src) = &value.kind else {
                return None;
            };
            if !j.within.contains(&i.name.key()) {
                self.not_implemented(value.span, &j.name.name, "interface", i);
                return Some(Vec::new());
            }
            // an `I2 EXTENDS I1` value in an `I1`: the same tag, the references the two share
            let tag = place_expr(field(src, TAG, span), span);
            return Some(set(tag, &|c| {
                if j.tag_of(&c.name).is_some() {
                    place_expr(field(src, &ref_field(&c.name), span), span)
                } else {
                    null(span)
                }
            }));
        }
        let fb = self.block_of(value)?;
        let Some(tag) = i.tag_of(&fb.name) else {
            if i.abstract_classes.contains(&fb.name.to_ascii_uppercase()) {
                // an ABSTRACT block's own text (never run: see `abstract_classes`)
                return Some(set(int(0, span), &|_| null(span)));
            }
            self.not_implemented(value.span, &fb.name, "function block", i);
            return Some(Vec::new());
        };
        Some(set(int(tag.into(), span), &|c| {
            if c.name.eq_ignore_ascii_case(&fb.name) {
                Expr {
                    kind: ExprKind::Call {
                        name: Ident::new("REF", span),
                        args: vec![Arg {
                            name: None,
                            dir: ArgDir::Input,
                            value: value.clone(),
                            span,
                        }],
                    },
                    span,
                }
            } else {
                null(span)
            }
        }))
    }

    fn not_implemented(&mut self, at: Span, what: &str, kind: &str, i: &Interface) {
        self.diags.push(
            Diagnostic::error(
                code::E0340,
                format!(
                    "{kind} `{what}` does not implement interface `{}`",
                    i.name.name
                ),
            )
            .at(at)
            .with_primary_label(format!("not an `{}`", i.name.name))
            .with_hint(format!(
                "assign an instance of a block declared `IMPLEMENTS {}` (or extending one), another `{}`, or 0",
                i.name.name, i.name.name
            )),
        );
    }

    /// `itf.M(args);` where `itf` is of an interface with method `M`: a CASE on the tag that calls
    /// the method of the instance held and copies its result.
    fn dispatch(&mut self, callee: &Place, args: &[Arg], span: Span) -> Option<Vec<Stmt>> {
        let (Accessor::Field(m), prefix) = callee.accessors.split_last()? else {
            return None;
        };
        let itf = Place {
            base: callee.base.clone(),
            accessors: prefix.to_vec(),
            span: callee.span,
        };
        let i = self.place_interface(&itf)?.clone();
        let Some(sig) = i
            .methods
            .iter()
            .find(|x| x.name.eq_ignore_ascii_case(&m.name))
        else {
            self.diags.push(
                Diagnostic::error(
                    code::E0342,
                    format!("interface `{}` has no method `{}`", i.name.name, m.name),
                )
                .at(m.span)
                .with_primary_label("not a method of the interface")
                .with_hint(format!(
                    "call one of the methods `{}` declares (or those it extends): {}",
                    i.name.name,
                    shown_methods(&i)
                )),
            );
            return Some(Vec::new());
        };
        // a result of an interface type: copied into a variable of the caller, which the
        // statement reading `itf.M()` (the parser's `itf.__M_M`) reads instead
        let itf_result = i
            .interface_results
            .iter()
            .find(|(k, _)| *k == m.key())
            .map(|(_, ty)| {
                let name = interface_result(callee.span, &m.name);
                let at = Ident::new(&name, span);
                if self.env.var_type(&at).is_none() && !self.temps.iter().any(|t| t.name.is(&name))
                {
                    self.temps.push(VarDecl::new(at, ty.clone(), span));
                }
                Place {
                    base: PlaceBase::Name(Ident::new(name, span)),
                    accessors: Vec::new(),
                    span,
                }
            });
        let result = crate::actions::method_result(&sig.name);
        let mut arms = Vec::new();
        for (c, tag) in &i.classes {
            let inst = deref(&field(&itf, &ref_field(&c.name), span), span);
            let mut body = vec![Stmt {
                kind: StmtKind::Call {
                    callee: field(&inst, &m.name, m.span),
                    args: args.to_vec(),
                },
                span,
            }];
            if let Some(r) = &itf_result {
                body.push(assign(
                    r.clone(),
                    place_expr(field(&inst, &result, span), span),
                    span,
                ));
            } else if sig.returns {
                body.push(assign(
                    field(&itf, &result, span),
                    place_expr(field(&inst, &result, span), span),
                    span,
                ));
            }
            arms.push(CaseArm {
                labels: vec![CaseLabel::Value(int((*tag).into(), span))],
                body,
                span,
            });
        }
        // no instance: nothing runs, the result reads 0 through the NULL reference (reported)
        let none = deref(&field(&itf, UNASSIGNED, span), span);
        let mut else_body = vec![assign(
            field(&itf, TAG, span),
            place_expr(field(&none, TAG, span), span),
            span,
        )];
        if let Some(r) = &itf_result {
            else_body.push(assign(r.clone(), int(0, span), span));
        } else if sig.returns {
            else_body.push(assign(
                field(&itf, &result, span),
                place_expr(field(&none, &result, span), span),
                span,
            ));
        }
        Some(vec![Stmt {
            kind: StmtKind::Case {
                selector: place_expr(field(&itf, TAG, span), span),
                arms,
                else_body: Some(else_body),
            },
            span,
        }])
    }

    /// `fb(shape := inst)` where `shape` is an input of interface type (of a block, or of a
    /// method: `obj.Add(shape := inst)`, `Add(inst)` inside the block): `fb.shape := inst;` (as
    /// rewritten by [`Self::assign_interface`]) before the call, and the argument left out (the
    /// positional arguments after it are then named, so that they bind as before).
    fn interface_inputs(&mut self, callee: &Place, args: &mut Vec<Arg>) -> Vec<Stmt> {
        let params = self.call_inputs(callee);
        if !params.iter().any(|p| self.interface(&p.2).is_some()) {
            return Vec::new();
        }
        let mut before = Vec::new();
        let mut kept = Vec::new();
        let mut positional = Vec::new();
        for (k, a) in std::mem::take(args).into_iter().enumerate() {
            let param = match (&a.name, a.dir) {
                (_, ArgDir::Output { .. }) => None,
                (Some(n), _) => params.iter().find(|p| p.0.eq_ignore_ascii_case(&n.name)),
                (None, _) => params.get(k),
            };
            if let Some((name, target, ty)) = param {
                if let Some(i) = self.interface(ty).cloned() {
                    if let Some(stmts) = self.assign_interface(target, &i, &a.value, a.span) {
                        before.extend(stmts);
                        continue;
                    }
                }
                if a.name.is_none() {
                    positional.push((kept.len(), name.clone()));
                }
            }
            kept.push(a);
        }
        if !before.is_empty() {
            for (k, name) in positional {
                kept[k].name = Some(Ident::new(name, kept[k].span));
            }
        }
        *args = kept;
        before
    }

    /// `F(shape := inst)` where `shape` is a FUNCTION's input of interface type: a temporary of
    /// the interface, assigned before the statement, is passed instead (where the statement can
    /// run it first; elsewhere sema reports the mismatch).
    fn function_inputs(&mut self, name: &Ident, args: &mut [Arg]) {
        let Some(pou) = self.env.decls.pou(&name.name).cloned() else {
            return;
        };
        if pou.kind != PouKind::Function || !self.hoistable {
            return;
        }
        let params: Vec<_> = pou
            .params()
            .filter(|p| p.1 == crate::ast::VarKind::Input)
            .cloned()
            .collect();
        for (k, a) in args.iter_mut().enumerate() {
            let param = match (&a.name, a.dir) {
                (_, ArgDir::Output { .. }) => None,
                (Some(n), _) => params.iter().find(|p| p.0.eq_ignore_ascii_case(&n.name)),
                (None, _) => params.get(k),
            };
            let Some((_, _, ty)) = param else { continue };
            let Some(i) = self.interface(ty).cloned() else {
                continue;
            };
            if self.block_of(&a.value).is_none() {
                continue;
            }
            let span = a.span;
            let temp = Ident::new(format!("_ITF_A{}", self.first + self.temps.len() + 1), span);
            let place = Place {
                base: PlaceBase::Name(temp.clone()),
                accessors: Vec::new(),
                span,
            };
            let Some(stmts) = self.assign_interface(&place, &i, &a.value, span) else {
                continue;
            };
            self.temps
                .push(VarDecl::new(temp, TypeRef::Named(i.name.clone()), span));
            self.before.extend(stmts);
            a.value = place_expr(place, span);
            self.changed = true;
        }
    }

    /// The inputs a call statement of `callee` passes, in order: each one's name as the caller
    /// writes it, the place that holds it, its type. Empty when `callee` is no block instance and
    /// no method of one.
    fn call_inputs(&self, callee: &Place) -> Vec<(String, Place, TypeRef)> {
        let block = |t: &TypeRef| match self.env.resolve(t) {
            TypeRef::Named(n) => self
                .env
                .decls
                .pou(&n.name)
                .filter(|p| p.kind == PouKind::FunctionBlock)
                .cloned(),
            _ => None,
        };
        // an instance: its inputs
        if let Some(pou) = self.env.place_type(callee).and_then(|t| block(&t)) {
            return pou
                .params()
                .filter(|p| p.1 == crate::ast::VarKind::Input)
                .map(|(n, _, t)| (n.clone(), field(callee, n, callee.span), t.clone()))
                .collect();
        }
        // a method: its hidden inputs in the block
        let (pou, prefix, m) = match callee.accessors.split_last() {
            Some((Accessor::Field(m), rest)) => {
                let prefix = Place {
                    base: callee.base.clone(),
                    accessors: rest.to_vec(),
                    span: callee.span,
                };
                match self.env.place_type(&prefix).and_then(|t| block(&t)) {
                    Some(pou) => (pou, Some(prefix), m.clone()),
                    None => return Vec::new(),
                }
            }
            None => {
                let Some(m) = callee.name() else {
                    return Vec::new();
                };
                if self.env.pou_kind != PouKind::FunctionBlock || self.env.var_type(m).is_some() {
                    return Vec::new();
                }
                match self.env.decls.pou(&self.env.pou_name.name) {
                    Some(pou) => (pou.clone(), None, m.clone()),
                    None => return Vec::new(),
                }
            }
            _ => return Vec::new(),
        };
        let Some(sig) = self
            .env
            .decls
            .methods
            .get(&pou.name.to_ascii_uppercase())
            .and_then(|ms| ms.iter().find(|s| s.name.eq_ignore_ascii_case(&m.name)))
        else {
            return Vec::new();
        };
        sig.inputs
            .iter()
            .filter_map(|input| {
                let hidden = crate::actions::method_var(&sig.name, input);
                let ty = pou.var(&hidden)?.2.clone();
                let target = match &prefix {
                    Some(p) => field(p, &hidden, callee.span),
                    None => Place {
                        base: PlaceBase::Name(Ident::new(&hidden, callee.span)),
                        accessors: Vec::new(),
                        span: callee.span,
                    },
                };
                Some((input.clone(), target, ty))
            })
            .collect()
    }

    /// The variable holding the result, of an interface type, of the call through an interface
    /// that `p` reads (`itf.__M_NEXT` after `itf.Next()`), if `p` reads one; with what follows
    /// that result in `p` (`itf.__M___GET_EXECUTOR.keepJob`, a property of the interface a
    /// property returns, after its getter's call: the instance that result refers to).
    fn interface_result_read(&self, p: &Place) -> Option<Place> {
        let (at, m) = p.accessors.iter().enumerate().find_map(|(k, a)| match a {
            Accessor::Field(f) => f
                .name
                .strip_prefix(crate::actions::METHOD_PREFIX)
                .map(|m| (k, m)),
            _ => None,
        })?;
        let itf = Place {
            base: p.base.clone(),
            accessors: p.accessors[..at].to_vec(),
            span: p.span,
        };
        let i = self.place_interface(&itf)?;
        i.interface_results
            .iter()
            .any(|(k, _)| k.eq_ignore_ascii_case(m))
            .then(|| Place {
                base: PlaceBase::Name(Ident::new(interface_result(p.span, m), p.span)),
                accessors: p.accessors[at + 1..].to_vec(),
                span: p.span,
            })
    }

    /// Whether `p` reads the result of a call through an interface that E0342 refused
    /// (`itf.__M_M`, as the parser reads `itf.M()`): the statement is dropped, no error more.
    fn unknown_result(&self, p: &Place) -> bool {
        let Some((Accessor::Field(f), prefix)) = p.accessors.split_last() else {
            return false;
        };
        let Some(m) = f.name.strip_prefix(crate::actions::METHOD_PREFIX) else {
            return false;
        };
        let itf = Place {
            base: p.base.clone(),
            accessors: prefix.to_vec(),
            span: p.span,
        };
        self.place_interface(&itf)
            .is_some_and(|i| !i.methods.iter().any(|x| x.name.eq_ignore_ascii_case(m)))
    }

    /// `__QUERYINTERFACE(src, dst)` (CODESYS, TwinCAT: `dst` takes the instance `src` holds, or
    /// is for an FB instance, when its block implements `dst`'s interface, else 0) and
    /// `__QUERYPOINTER(src, p)` (`p : POINTER TO FB` takes the address of the instance `src`
    /// holds when it is an `FB`, else 0): the statements doing it run before the statement (in
    /// [`Self::before`]), which reads the BOOL result from the hidden `__QUERIED` of the interface
    /// variable (`dst`, `src`). Anything else is one E0341; `None` when `name` is no query.
    fn query(&mut self, name: &Ident, args: &[Arg], span: Span) -> Option<Expr> {
        let pointer = name.is("__QUERYPOINTER");
        if !pointer && !name.is("__QUERYINTERFACE") {
            return None;
        }
        let fail = |this: &mut Self, msg: String, hint: &str| {
            this.diags.push(
                Diagnostic::error(code::E0341, msg)
                    .at(span)
                    .with_primary_label("not compiled")
                    .with_hint(hint.to_string()),
            );
            Some(Expr {
                kind: ExprKind::Error,
                span,
            })
        };
        if !self.hoistable {
            return fail(
                self,
                format!(
                    "`{}` in an ELSIF, WHILE or UNTIL condition is not supported",
                    name.name
                ),
                "call it in a statement of its own (`ok := __QUERYINTERFACE(a, b);`) and test `ok`",
            );
        }
        let (Some(src), Some(dst), 2) = (args.first(), args.get(1), args.len()) else {
            return fail(
                self,
                format!("`{}` takes two operands", name.name),
                "write `__QUERYINTERFACE(itfSource, itfDest)` or `__QUERYPOINTER(itfSource, pDest)`",
            );
        };
        let (ExprKind::Place(sp), ExprKind::Place(dp)) = (&src.value.kind, &dst.value.kind) else {
            return fail(
                self,
                format!("`{}` takes two variables", name.name),
                "pass the interface (or instance) variable and the variable that receives it",
            );
        };
        if pointer {
            if let Some(missing) = self.undeclared_type(sp) {
                return self.missing_interfaces(&[missing], span);
            }
            let target = match self.env.place_type(dp).map(|t| self.env.resolve(&t)) {
                Some(TypeRef::Ref { target, .. }) => match *target {
                    TypeRef::Named(n) => Some(n),
                    _ => None,
                },
                _ => None,
            };
            let (Some(i), Some(fb)) = (self.place_interface(sp).cloned(), target) else {
                return fail(
                    self,
                    "`__QUERYPOINTER` takes an interface variable and a POINTER TO a function block".into(),
                    "declare the second operand `POINTER TO FB_X` for a block FB_X that implements the interface",
                );
            };
            let ok = field(sp, "__QUERIED", span);
            let mut arms = Vec::new();
            if let Some(tag) = i.tag_of(&fb.name) {
                arms.push(CaseArm {
                    labels: vec![CaseLabel::Value(int(tag.into(), span))],
                    body: vec![
                        assign(
                            dp.clone(),
                            place_expr(field(sp, &ref_field(&fb.name), span), span),
                            span,
                        ),
                        assign(ok.clone(), bool_lit(true, span), span),
                    ],
                    span,
                });
            }
            let else_body = vec![
                assign(dp.clone(), null(span), span),
                assign(ok.clone(), bool_lit(false, span), span),
            ];
            self.before.push(Stmt {
                kind: StmtKind::Case {
                    selector: place_expr(field(sp, TAG, span), span),
                    arms,
                    else_body: Some(else_body),
                },
                span,
            });
            return Some(place_expr(ok, span));
        }
        let missing: Vec<Ident> = [sp, dp]
            .iter()
            .filter_map(|p| self.undeclared_type(p))
            .collect();
        if !missing.is_empty() {
            return self.missing_interfaces(&missing, span);
        }
        let Some(di) = self.place_interface(dp).cloned() else {
            return fail(
                self,
                "the second operand of `__QUERYINTERFACE` is no interface variable".into(),
                "pass a variable whose type is the interface wanted",
            );
        };
        let ok = field(dp, "__QUERIED", span);
        let cleared = |this: &mut Self| {
            this.assign_interface(dp, &di, &int(0, span), span)
                .unwrap_or_default()
        };
        if let Some(si) = self.place_interface(sp).cloned() {
            // the instance `src` holds, when its block is also one of `dst`'s
            let mut arms = Vec::new();
            for (c, tag) in si
                .classes
                .iter()
                .filter(|(c, _)| di.tag_of(&c.name).is_some())
            {
                let mut body = vec![assign(field(dp, TAG, span), int((*tag).into(), span), span)];
                for (d, _) in &di.classes {
                    let f = ref_field(&d.name);
                    let v = if d.name.eq_ignore_ascii_case(&c.name) {
                        place_expr(field(sp, &f, span), span)
                    } else {
                        null(span)
                    };
                    body.push(assign(field(dp, &f, span), v, span));
                }
                body.push(assign(ok.clone(), bool_lit(true, span), span));
                arms.push(CaseArm {
                    labels: vec![CaseLabel::Value(int((*tag).into(), span))],
                    body,
                    span,
                });
            }
            let mut else_body = cleared(self);
            else_body.push(assign(ok.clone(), bool_lit(false, span), span));
            self.before.push(Stmt {
                kind: StmtKind::Case {
                    selector: place_expr(field(sp, TAG, span), span),
                    arms,
                    else_body: Some(else_body),
                },
                span,
            });
            return Some(place_expr(ok, span));
        }
        // an FB instance: known when compiling
        let implements = self
            .block_of(&src.value)
            .is_some_and(|fb| di.tag_of(&fb.name).is_some());
        let mut stmts = if implements {
            self.assign_interface(dp, &di, &src.value, span)
                .unwrap_or_default()
        } else {
            cleared(self)
        };
        stmts.push(assign(ok.clone(), bool_lit(implements, span), span));
        self.before.extend(stmts);
        Some(place_expr(ok, span))
    }

    /// The comparisons of interfaces inside `e`: `itf = 0` (`<> 0`, `NULL`) tests the tag,
    /// `i1 = i2` the tags and the references.
    /// The index expressions of place `p`, rewritten as [`Self::compare`] does an expression
    /// (`arr[ifut.executor.level]`: the index reads the result of a call through an interface,
    /// `ifut.__M___GET_EXECUTOR`, kept in a variable of the caller; before issue #13's round 34
    /// an index was left as it was: E1021 "I_Future has no field `__GET_EXECUTOR`").
    fn indexes(&mut self, p: &mut Place) {
        for a in p.accessors.iter_mut() {
            if let Accessor::Index(ix) = a {
                for x in ix.iter_mut() {
                    self.compare(x);
                }
            }
        }
    }

    fn compare(&mut self, e: &mut Expr) {
        let span = e.span;
        let replacement = match &mut e.kind {
            ExprKind::Binary { op, left, right } => {
                self.compare(left);
                self.compare(right);
                let op = *op;
                if !matches!(op, BinaryOp::Eq | BinaryOp::Ne) {
                    return;
                }
                let (li, ri) = (
                    self.expr_interface(left).cloned(),
                    self.expr_interface(right).cloned(),
                );
                let tag = |x: &Expr| match &x.kind {
                    ExprKind::Place(p) => place_expr(field(p, TAG, span), span),
                    _ => x.clone(),
                };
                match (li, ri) {
                    (Some(_), None) if is_zero(self.env, right) => {
                        binary(op, tag(left), int(0, span), span)
                    }
                    (None, Some(_)) if is_zero(self.env, left) => {
                        binary(op, int(0, span), tag(right), span)
                    }
                    (Some(a), Some(b)) => {
                        let (ExprKind::Place(l), ExprKind::Place(r)) = (&left.kind, &right.kind)
                        else {
                            return;
                        };
                        let mut all = binary(BinaryOp::Eq, tag(left), tag(right), span);
                        for (c, _) in a
                            .classes
                            .iter()
                            .filter(|(c, _)| b.tag_of(&c.name).is_some())
                        {
                            let f = ref_field(&c.name);
                            let same = binary(
                                BinaryOp::Eq,
                                place_expr(field(l, &f, span), span),
                                place_expr(field(r, &f, span), span),
                                span,
                            );
                            all = binary(BinaryOp::And, all, same, span);
                        }
                        if op == BinaryOp::Ne {
                            Expr {
                                kind: ExprKind::Unary {
                                    op: super::ast::UnaryOp::Not,
                                    operand: Box::new(all),
                                },
                                span,
                            }
                        } else {
                            all
                        }
                    }
                    _ => return,
                }
            }
            ExprKind::Unary { operand, .. } => {
                self.compare(operand);
                return;
            }
            ExprKind::Place(p) if self.unknown_result(p) => Expr {
                kind: ExprKind::Error,
                span,
            },
            ExprKind::Place(p) => {
                self.indexes(p);
                match self.interface_result_read(p) {
                    Some(r) => place_expr(r, span),
                    None => return,
                }
            }
            ExprKind::Call { name, args } => {
                for a in args.iter_mut() {
                    self.compare(&mut a.value);
                }
                self.function_inputs(name, args);
                let query = ["__QUERYINTERFACE", "__QUERYPOINTER"]
                    .iter()
                    .any(|q| name.is(q));
                match self.query(name, args, span) {
                    Some(result) if query => result,
                    _ => return,
                }
            }
            _ => return,
        };
        self.changed = true;
        *e = replacement;
    }
}
