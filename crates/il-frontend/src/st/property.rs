//! PROPERTYs of function blocks (CODESYS, TwinCAT, IEC 61131-3 edition 3 style): a name that reads
//! like a variable of the block, `inst.P`, but runs code, its Get accessor when read and its Set
//! accessor when written.
//!
//! Input: the text `PROPERTY [modifiers] P : T  GET <VAR blocks> <statements> END_GET
//! SET <VAR blocks> <statements> END_SET  END_PROPERTY` inside a FUNCTION_BLOCK of an `.st` file
//! (TwinCAT's `<Property>` and CODESYS's vendor data are turned into the same accessors by
//! ladder-compiler), and ST statements being lowered.
//! Output: each accessor is a METHOD of the block in the existing method machinery
//! ([`crate::actions`]): the Get accessor is the method `__GET_P` returning `T` (its result variable
//! is named `P`, so `P := x;` inside it sets the value read), the Set accessor the method `__SET_P`
//! with one input named `P` (the value written). `rewrite` turns the uses of a property in a
//! statement into calls of these methods before the statement is lowered: a read of `inst.P` (in
//! any expression), of `P` or `THIS^.P` inside the block, becomes a call of the getter put before
//! the statement and a read of its result; `inst.P := v;` (`P := v;` inside the block) becomes the
//! setter's call.
//! Invariants: inside an accessor the property's own name is the accessor's variable (the result
//! or the input), never a call of itself; a statement without properties is not touched; every
//! misuse is one located diagnostic and the statement is dropped: a write of a property without
//! Set or a read of one without Get (E0337), a property passed to a VAR_IN_OUT or an output, or a
//! component of it written (E0338), unless the property is a REFERENCE TO (or the component is
//! reached through `P^`): then the component is a variable, written or bound to an output or a
//! VAR_IN_OUT after the getter's call; likewise a property of an INTERFACE type, whose value
//! refers to an instance (`fut.executor.keepJob := TRUE;` sets keepJob of that instance). A property read in an ELSIF or WHILE condition is evaluated
//! where the condition is (the IF is split at that ELSIF, the loop tests it after calling the
//! getter); one in an UNTIL condition is a getter call in place, run before each test as a method
//! call there is (`super::lower::method_flow`; E0108 before issue #13's Session 36), and what
//! follows the property there (`UNTIL fut.executor.keepJob`) reaches the getter's result as a
//! call chain's rest does (`super::lower::call_chain`).

use super::ast::{
    Accessor, Arg, ArgDir, CondBranch, Expr, ExprKind, Place, PlaceBase, Stmt, StmtKind,
};
use super::file::{is_var_keyword, is_word, word, PendingMethod};
use super::infer::Env;
use super::lexer::{Tok, Token};
use super::types::MethodSig;
use crate::ast::{Ident, TypeRef, VarBlock, VarDecl, VarKind};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};
use std::collections::HashMap;
use std::ops::Range;

/// The prefix of a property's Get accessor as a method: `__GET_P`.
pub const GET_PREFIX: &str = "__GET_";
/// The prefix of a property's Set accessor as a method: `__SET_P`.
pub const SET_PREFIX: &str = "__SET_";

/// The method name of property `p`'s Get accessor.
pub fn getter(p: &str) -> String {
    format!("{GET_PREFIX}{}", p.to_ascii_uppercase())
}

/// The method name of property `p`'s Set accessor.
pub fn setter(p: &str) -> String {
    format!("{SET_PREFIX}{}", p.to_ascii_uppercase())
}

/// Whether a method is a property's accessor.
pub fn is_accessor(method: &str) -> bool {
    let m = method.to_ascii_uppercase();
    m.starts_with(GET_PREFIX) || m.starts_with(SET_PREFIX)
}

/// How a message names an action or method: "action `M`", or for a property's accessor "the Get
/// accessor of property `P`" (not its hidden name `__GET_P`).
pub fn describe_action(name: &str) -> String {
    let upper = name.to_ascii_uppercase();
    for (prefix, what) in [(GET_PREFIX, "Get"), (SET_PREFIX, "Set")] {
        if upper.starts_with(prefix) {
            return format!(
                "the {what} accessor of property `{}`",
                name.get(prefix.len()..).unwrap_or(name)
            );
        }
    }
    format!("action `{name}`")
}

/// One `PROPERTY ... END_PROPERTY` block of a function block's text.
#[derive(Debug, Clone)]
pub struct PropertyText {
    /// The property's name as written.
    pub name: String,
    /// Byte range of the name.
    pub name_range: Range<usize>,
    /// End of the type after `Name :`.
    pub ty_end: usize,
    /// The Get accessor: its variable blocks and its statements (byte ranges).
    pub get: Option<(Range<usize>, Range<usize>)>,
    /// The Set accessor, likewise.
    pub set: Option<(Range<usize>, Range<usize>)>,
    /// Byte range of the whole block, `PROPERTY` to `END_PROPERTY`.
    pub whole: Range<usize>,
    /// The property's access specifier (`PROPERTY PRIVATE P`; none: PUBLIC).
    pub access: Option<crate::ast::Access>,
    /// The Get accessor's own (`GET PROTECTED`), overriding the property's.
    pub get_access: Option<crate::ast::Access>,
    /// The Set accessor's own.
    pub set_access: Option<crate::ast::Access>,
}

/// The `PROPERTY` blocks among a function block's body tokens. A block without `: type` on its
/// line, without `END_PROPERTY` or without any accessor is left out (the caller reports it, E0100).
pub(super) fn scan_properties(src: &str, toks: &[Token]) -> Vec<PropertyText> {
    let n = toks.len();
    let mut out = Vec::new();
    let mut k = 0;
    while k < n {
        if !is_word(src, &toks[k], "PROPERTY") {
            k += 1;
            continue;
        }
        let mut h = super::file::member_name_at(src, toks, k);
        let Some(name_tok) = toks.get(h).filter(|t| t.tok == Tok::Ident) else {
            k += 1;
            continue;
        };
        if toks.get(h + 1).is_none_or(|t| t.tok != Tok::Colon) {
            k += 1;
            continue;
        }
        let access = super::file::member_access(src, &toks[k + 1..h]);
        h += 2;
        // the type ends with its line (`PROPERTY P : INT` then the accessors)
        let line_end = src
            .get(name_tok.range.end..)
            .and_then(|r| r.find(['\n', '\r']))
            .map_or(src.len(), |k| name_tok.range.end + k);
        let stop = |t: &Token| {
            t.range.start >= line_end
                || t.tok == Tok::Semi
                || ["GET", "SET", "END_PROPERTY"]
                    .iter()
                    .any(|w| is_word(src, t, w))
                || is_var_keyword(&word(src, t).to_ascii_uppercase())
        };
        let mut ty_end = None;
        while h < n && !matches!(toks[h].tok, Tok::Eof) && !stop(&toks[h]) {
            ty_end = Some(toks[h].range.end);
            h += 1;
        }
        let Some(ty_end) = ty_end else {
            k += 1;
            continue;
        };
        if toks.get(h).is_some_and(|t| t.tok == Tok::Semi) {
            h += 1;
        }
        let mut get = None;
        let mut set = None;
        let (mut get_access, mut set_access) = (None, None);
        let mut end = None;
        while h < n && !matches!(toks[h].tok, Tok::Eof) {
            if is_word(src, &toks[h], "END_PROPERTY") {
                end = Some(h);
                break;
            }
            let (slot, close, slot_access) = if is_word(src, &toks[h], "GET") {
                (&mut get, "END_GET", &mut get_access)
            } else if is_word(src, &toks[h], "SET") {
                (&mut set, "END_SET", &mut set_access)
            } else {
                h += 1;
                continue;
            };
            h += 1;
            // an accessor's own access modifier (TwinCAT: `SET` declared `PROTECTED`): kept
            let from = h;
            while h + 1 < n
                && ["PUBLIC", "PRIVATE", "PROTECTED", "INTERNAL"]
                    .iter()
                    .any(|w| is_word(src, &toks[h], w))
            {
                h += 1;
            }
            *slot_access = super::file::member_access(src, &toks[from..h]);
            let decl_start = toks.get(h).map_or(0, |t| t.range.start);
            let (after, vars_end) = super::file::skip_var_blocks(src, toks, h);
            h = after;
            let decl_end = vars_end.unwrap_or(decl_start);
            let mut e = h;
            while e < n
                && !is_word(src, &toks[e], close)
                && !is_word(src, &toks[e], "END_PROPERTY")
                && !matches!(toks[e].tok, Tok::Eof)
            {
                e += 1;
            }
            let stmts_end = toks
                .get(e)
                .map_or(decl_end, |t| t.range.start.max(decl_end));
            *slot = Some((decl_start..decl_end, decl_end..stmts_end));
            h = if toks.get(e).is_some_and(|t| is_word(src, t, close)) {
                e + 1
            } else {
                e
            };
        }
        let Some(e) = end else {
            break;
        };
        if get.is_none() && set.is_none() {
            // no accessor: not a property ladderc can read (the caller reports it)
            k = e + 1;
            continue;
        }
        out.push(PropertyText {
            name: word(src, name_tok).to_string(),
            name_range: name_tok.range.clone(),
            ty_end,
            get,
            set,
            whole: toks[k].range.start..toks[e].range.end,
            access,
            get_access,
            set_access,
        });
        k = e + 1;
    }
    out
}

/// The accessors of a property read from an `.st` text, as methods of its block (see the module
/// documentation); diagnostics of their declarations point into the file.
pub(super) fn pending_accessors(
    file: FileId,
    src: &str,
    p: &PropertyText,
    diags: &mut Diagnostics,
) -> Vec<PendingMethod> {
    // `P : TYPE` read as the declaration `VAR P : TYPE; END_VAR` in place (the name is at least 9
    // bytes into the file: after `PROPERTY `)
    let Some(decl) = src.get(p.name_range.start..p.ty_end) else {
        return Vec::new();
    };
    let Some(base) = p.name_range.start.checked_sub(4) else {
        return Vec::new();
    };
    let text = format!("VAR {decl};END_VAR");
    let Some(value) = super::file::read_var_blocks(file, &text, base, diags)
        .into_iter()
        .flat_map(|b| b.vars)
        .next()
    else {
        return Vec::new();
    };
    let name = Ident::new(
        &p.name,
        Span::new(file, p.name_range.start, p.name_range.end),
    );
    // (an accessor's VAR_INST, TwinCAT: kept in the instance, as a method's)
    let mut inst = Vec::new();
    // (and its VAR_INST initial values computed at run time, `fbView : FB_View := (ipList :=
    // THIS^.fbList);` in fisothemes/TwinCat-Dynamic-Collections: at its first call, see
    // `method_inits`)
    let mut once = Vec::new();
    let mut part = |(decls, stmts): &(Range<usize>, Range<usize>), diags: &mut Diagnostics| {
        let t = super::method_inits::member_text(
            file,
            src,
            decls.clone(),
            stmts.clone(),
            name.span,
            diags,
        );
        inst.extend(t.inst);
        once.push(t.once);
        (t.blocks, t.text, t.base)
    };
    let get = p.get.as_ref().map(|g| part(g, diags));
    let set = p.set.as_ref().map(|s| part(s, diags));
    let mut out = accessor_methods(&name, &value.ty, get, set);
    for (m, once) in out.iter_mut().zip(once) {
        m.inst = inst.clone();
        m.once = once;
    }
    out
}

/// The methods of a property `name : ty` with the given accessors (each: its variable blocks, its
/// statements' text and their offset in the file): `__GET_P` returning `ty` into a result named
/// `P`, `__SET_P` with the input `P`.
pub fn accessor_methods(
    name: &Ident,
    ty: &TypeRef,
    get: Option<(Vec<VarBlock>, String, usize)>,
    set: Option<(Vec<VarBlock>, String, usize)>,
) -> Vec<PendingMethod> {
    let mut out = Vec::new();
    if let Some((blocks, text, base)) = get {
        out.push(PendingMethod {
            name: Ident::new(getter(&name.name), name.span),
            ret: Some(VarDecl::new(name.clone(), ty.clone(), name.span)),
            blocks,
            text,
            base,
            inst: Vec::new(),
            once: Vec::new(),
            local_inits: Vec::new(),
            overloaded: false,
            access: None,
        });
    }
    if let Some((mut blocks, text, base)) = set {
        blocks.insert(
            0,
            VarBlock {
                access: None,
                name: None,
                kind: VarKind::Input,
                constant: false,
                retain: false,
                vars: vec![VarDecl::new(name.clone(), ty.clone(), name.span)],
                span: name.span,
            },
        );
        out.push(PendingMethod {
            name: Ident::new(setter(&name.name), name.span),
            ret: None,
            blocks,
            text,
            base,
            inst: Vec::new(),
            once: Vec::new(),
            local_inits: Vec::new(),
            overloaded: false,
            access: None,
        });
    }
    out
}

/// Which accessors a property has.
#[derive(Debug, Clone, Copy)]
struct Prop {
    get: bool,
    set: bool,
}

/// Where a place names a property: its base (`P` inside the block), or the field at this index of
/// its accessors (`inst.P`, `a[i].fb.P`).
#[derive(Debug, Clone, Copy)]
enum At {
    Base,
    Field(usize),
    /// `PRG.P` inside program `PRG` (or its actions and methods): the program's own property
    /// named through the program's name, its first accessor.
    Own,
}

/// The rewriting of one statement (see [`rewrite`]).
struct Rewriter<'a, 'd> {
    env: &'a Env<'a>,
    /// The methods of the block being lowered (its own properties' accessors among them).
    own: &'a HashMap<String, MethodSig>,
    /// The getter calls to run before the statement.
    calls: Vec<Stmt>,
    /// Reads become getter calls in place (an UNTIL condition: `super::lower::method_flow` runs
    /// them before each test), not calls before the statement.
    in_place: bool,
    changed: bool,
    diags: &'d mut Diagnostics,
}

/// The uses of properties in `s` as calls of their accessors: the getter calls to run first and
/// the statement that reads their results (or calls the setter); `None` when `s` uses no property
/// in the expressions it evaluates itself (nested statements are rewritten when they are lowered).
/// `own` are the methods of the function block being lowered (empty outside a block).
pub(super) fn rewrite(
    env: &Env<'_>,
    own: &HashMap<String, MethodSig>,
    s: &Stmt,
    diags: &mut Diagnostics,
) -> Option<(Vec<Stmt>, Stmt)> {
    let mut r = Rewriter {
        env,
        own,
        calls: Vec::new(),
        in_place: false,
        changed: false,
        diags,
    };
    if !r.uses(s) {
        return None;
    }
    let mut rest = s.clone();
    r.stmt(&mut rest);
    r.changed.then_some((r.calls, rest))
}

/// Whether expression `e` reads a property (an SFC transition's condition is lowered as a
/// statement then, so that [`rewrite`] runs the getters first).
pub(super) fn reads_any(env: &Env<'_>, own: &HashMap<String, MethodSig>, e: &Expr) -> bool {
    let mut diags = Diagnostics::new();
    let r = Rewriter {
        env,
        own,
        calls: Vec::new(),
        in_place: false,
        changed: false,
        diags: &mut diags,
    };
    r.reads_property(e)
}

fn field(name: String, span: Span) -> Accessor {
    Accessor::Field(Ident::new(name, span))
}

impl Rewriter<'_, '_> {
    /// Property `n` of the block being lowered, where no variable has that name.
    fn own_prop(&self, n: &Ident) -> Option<Prop> {
        if self.env.vars.contains_key(&n.key()) {
            return None;
        }
        let get = self.own.contains_key(&getter(&n.name));
        let set = self.own.contains_key(&setter(&n.name));
        (get || set).then_some(Prop { get, set })
    }

    /// Property `f` of a value of type `t` (an instance of a function block that declares it).
    fn member_prop(&self, t: &TypeRef, f: &Ident) -> Option<Prop> {
        let TypeRef::Named(fb) = self.env.resolve(t) else {
            return None;
        };
        let methods = self.env.decls.methods.get(&fb.key())?;
        if self.env.member(t, f).is_some() {
            return None;
        }
        let has = |m: String| methods.iter().any(|x| x.name.eq_ignore_ascii_case(&m));
        let get = has(getter(&f.name));
        let set = has(setter(&f.name));
        (get || set).then_some(Prop { get, set })
    }

    /// Whether a write to `p` past its property `name` (at `at`) goes through the property's
    /// value to a variable: the property is a `REFERENCE TO`, or a `^` follows it.
    fn writes_through(&self, p: &Place, at: At, name: &Ident) -> bool {
        let next = match at {
            At::Base => 0,
            At::Own => 1,
            At::Field(k) => k + 1,
        };
        if matches!(p.accessors.get(next), Some(Accessor::Deref(_))) {
            return true;
        }
        let result = Ident::new(
            crate::actions::method_result(&getter(&name.name)),
            name.span,
        );
        let ty = match at {
            At::Base | At::Own => self.env.var_type(&result),
            At::Field(k) => {
                let prefix = Place {
                    base: p.base.clone(),
                    accessors: p.accessors[..k].to_vec(),
                    span: p.span,
                };
                self.env.place_type(&prefix).and_then(|t| {
                    self.env.member(&t, &result).or_else(|| {
                        super::interface_vars::interface_result_type(
                            self.env,
                            &t,
                            &getter(&name.name),
                        )
                    })
                })
            }
        };
        ty.is_some_and(|t| match self.env.resolve(&t) {
            TypeRef::Ref {
                kind: crate::ast::RefKind::Reference,
                ..
            } => true,
            // an interface value refers to an instance (Beckhoff Infosys, TwinCAT 3 PLC,
            // "Interface"; CODESYS likewise): `fut.executor.keepJob := TRUE;` with `PROPERTY
            // executor : I_Job` calls keepJob's Set accessor of the instance it refers to
            TypeRef::Named(n) => self.env.decls.interfaces.contains_key(&n.key()),
            _ => false,
        })
    }

    /// Whether `p` is a component of the property `name` found at `at` (not the property
    /// itself) that is written through the property's value: a REFERENCE TO (or a pointer
    /// dereferenced, `P^.x`), so the component is a variable ([`Self::writes_through`]).
    fn component_through(&self, p: &Place, at: At, name: &Ident) -> bool {
        let whole = match at {
            At::Base => p.accessors.is_empty(),
            At::Own => p.accessors.len() == 1,
            At::Field(k) => k + 1 == p.accessors.len(),
        };
        !whole && self.writes_through(p, at, name)
    }

    /// The property a place names (or starts with: `inst.P.x`), its name and where it stands.
    fn find(&self, p: &Place) -> Option<(At, Prop, Ident)> {
        if let PlaceBase::Name(n) = &p.base {
            if let Some(pr) = self.own_prop(n) {
                return Some((At::Base, pr, n.clone()));
            }
            // `PRG.P := v;` inside program `PRG`: its own property, the accessors of the running
            // instance (CODESYS and TwinCAT accept the qualified name anywhere)
            if let (Some(Accessor::Field(f)), true) = (
                p.accessors.first(),
                self.env.pou_kind == crate::ast::PouKind::Program
                    && n.is(&self.env.pou_name.name)
                    && !self.env.vars.contains_key(&n.key()),
            ) {
                if let Some(pr) = self.own_prop(f) {
                    return Some((At::Own, pr, f.clone()));
                }
            }
        }
        for (k, a) in p.accessors.iter().enumerate() {
            let Accessor::Field(f) = a else { continue };
            let prefix = Place {
                base: p.base.clone(),
                accessors: p.accessors[..k].to_vec(),
                span: p.span,
            };
            // `PRG.P`: a property of a program (CODESYS, TwinCAT), on its one instance
            let program = match (&p.base, k) {
                (PlaceBase::Name(n), 0) if !self.env.vars.contains_key(&n.key()) => self
                    .env
                    .decls
                    .pous
                    .get(&n.key())
                    .filter(|i| i.kind == crate::ast::PouKind::Program)
                    .map(|_| TypeRef::Named(n.clone())),
                _ => None,
            };
            if let Some(t) = self.env.place_type(&prefix).or(program) {
                if let Some(pr) = self.member_prop(&t, f) {
                    return Some((At::Field(k), pr, f.clone()));
                }
            }
        }
        None
    }

    /// `place` with the property at `at` replaced by the accessor method `m` (dropping what follows
    /// when `keep_rest` is false).
    fn with_member(p: &Place, at: At, m: String, span: Span, keep_rest: bool) -> Place {
        match at {
            At::Base => Place {
                base: PlaceBase::Name(Ident::new(m, span)),
                accessors: if keep_rest {
                    p.accessors.clone()
                } else {
                    Vec::new()
                },
                span: p.span,
            },
            At::Own => Place {
                base: PlaceBase::Name(Ident::new(m, span)),
                accessors: if keep_rest {
                    p.accessors[1..].to_vec()
                } else {
                    Vec::new()
                },
                span: p.span,
            },
            At::Field(k) => {
                let mut accessors = p.accessors[..k].to_vec();
                accessors.push(field(m, span));
                if keep_rest {
                    accessors.extend(p.accessors[k + 1..].iter().cloned());
                }
                Place {
                    base: p.base.clone(),
                    accessors,
                    span: p.span,
                }
            }
        }
    }

    /// The read of place `p`, whose property at `at` has the Get accessor `getter` (`inst.__GET_P`),
    /// as a getter call that stands where the read is (an UNTIL condition): the call alone for the
    /// property itself (`UNTIL inst.P`); for an access going on past the property (`UNTIL
    /// fut.executor.keepJob`, `fut.worker.count > 2`, `a.P[i]`, `a.Ptr^.x`) the call chain
    /// `fut.__GET_EXECUTOR().keepJob`, whose rest reaches the getter's result as the rest of
    /// any method's chain does (`super::lower::call_chain`: an interface or `REFERENCE TO`
    /// result is the instance it refers to, a property of it its accessors again). Before issue
    /// #13's round 34 the rest was dropped: the condition read the getter's result itself (E1006
    /// "cannot store I_Job into BOOL").
    fn getter_in_place(p: &Place, at: At, getter: Place, span: Span) -> Expr {
        let next = match at {
            At::Base => 0,
            At::Own => 1,
            At::Field(k) => k + 1,
        };
        let rest = p.accessors.get(next..).unwrap_or_default();
        if rest.is_empty() {
            return super::lower::method_flow::method_call_expr(getter, Vec::new(), span);
        }
        let mut chain = getter;
        let name_end = match chain.accessors.last() {
            Some(Accessor::Field(m)) => m.span,
            _ => match &chain.base {
                PlaceBase::Name(n) => n.span,
                PlaceBase::Address(_) => chain.span,
            },
        };
        chain.accessors.push(Accessor::Call {
            args: Vec::new(),
            span: Span {
                start: name_end.end,
                ..name_end
            },
        });
        chain.accessors.extend(rest.iter().cloned());
        Expr {
            span,
            kind: ExprKind::Place(chain),
        }
    }

    fn error(&mut self, c: diagnostics::Code, span: Span, msg: String, hint: &str) {
        self.changed = true;
        self.diags.push(
            Diagnostic::error(c, msg)
                .at(span)
                .with_hint(hint.to_string()),
        );
    }

    /// The index expressions of a place, rewritten.
    fn indexes(&mut self, p: &mut Place) {
        for a in p.accessors.iter_mut() {
            if let Accessor::Index(ix) = a {
                for x in ix.iter_mut() {
                    self.read(x);
                }
            }
        }
    }

    /// Rewrites the property reads of an expression (arguments and indexes first).
    fn read(&mut self, e: &mut Expr) {
        match &mut e.kind {
            ExprKind::Unary { operand, .. } => self.read(operand),
            ExprKind::Binary { left, right, .. } => {
                self.read(left);
                self.read(right);
            }
            ExprKind::Call { name, args } => {
                let in_outs = self.in_outs_of_function(name);
                let name = name.clone();
                self.args(&name.name, args, &in_outs);
            }
            ExprKind::Place(p) => {
                self.indexes(p);
                let Some((at, prop, name)) = self.find(p) else {
                    return;
                };
                if !prop.get {
                    let span = p.span;
                    self.error(
                        code::E0337,
                        span,
                        format!("property `{}` has no Get accessor: it cannot be read", name.name),
                        "give the property a Get accessor, or read the variable its Set accessor writes",
                    );
                    e.kind = ExprKind::Error;
                    return;
                }
                let callee = Self::with_member(p, at, getter(&name.name), name.span, false);
                if self.in_place {
                    *e = Self::getter_in_place(p, at, callee, e.span);
                    self.changed = true;
                    return;
                }
                let key = place_key(&callee);
                let known = key.is_some()
                    && self.calls.iter().any(|c| {
                        matches!(&c.kind, StmtKind::Call { callee: k, .. } if place_key(k) == key)
                    });
                if !known {
                    self.calls.push(Stmt {
                        kind: StmtKind::Call {
                            callee,
                            args: Vec::new(),
                        },
                        span: p.span,
                    });
                }
                let result = crate::actions::method_result(&getter(&name.name));
                *p = Self::with_member(p, at, result, name.span, true);
                self.changed = true;
            }
            _ => {}
        }
    }

    /// The VAR_IN_OUT parameters of the function `name` (upper-case).
    fn in_outs_of_function(&self, name: &Ident) -> Vec<String> {
        in_out_names(self.env.decls.pou(&name.name))
    }

    /// Rewrites a call's arguments: inputs are reads; a property passed to a VAR_IN_OUT
    /// (`in_outs`: the callee's parameters in order, the in-outs' names upper-case, others empty)
    /// or receiving an output is E0338.
    fn args(&mut self, callee: &str, args: &mut [Arg], in_outs: &[String]) {
        let mut positional = 0;
        for a in args.iter_mut() {
            let in_out = match &a.name {
                Some(n) => in_outs.iter().any(|k| !k.is_empty() && n.key() == *k),
                None => {
                    positional += 1;
                    in_outs.get(positional - 1).is_some_and(|k| !k.is_empty())
                }
            };
            let output = matches!(a.dir, ArgDir::Output { .. });
            let is_prop = match &a.value.kind {
                ExprKind::Place(p) => self.find(p).map(|(at, _, n)| {
                    let through = (in_out || output) && self.component_through(p, at, &n);
                    (n, through)
                }),
                _ => None,
            };
            if let Some((_, true)) = &is_prop {
                // `fb(Q => stAxis.nErr)` with `PROPERTY stAxis : REFERENCE TO ST_Status`: the
                // getter runs before the call, and the output (or the VAR_IN_OUT) is the
                // component of what its result refers to, a variable, as an assignment to it is
                // (`Self::stmt`; TwinCAT: ESS tc_mca_std_lib `SercosErrId => stAxis.stStatus..`)
                self.read(&mut a.value);
                continue;
            }
            if let (Some((n, _)), true) = (&is_prop, in_out || output) {
                let what = if in_out { "a VAR_IN_OUT" } else { "an output" };
                self.error(
                    code::E0338,
                    a.value.span,
                    format!(
                        "property `{}` cannot be passed to {what} of `{callee}`: a property is code, not a variable",
                        n.name
                    ),
                    "copy the property into a variable, pass that, and write the variable back to the property after the call",
                );
                // the mark the lowering reads: an `ExprKind::Error` argument is reported, so
                // a plain VAR_IN_OUT given it has no E1088 besides
                a.value.kind = ExprKind::Error;
            } else if output {
                if let ExprKind::Place(p) = &mut a.value.kind {
                    self.indexes(p);
                }
            } else {
                self.read(&mut a.value);
            }
        }
    }

    /// Whether the expressions `s` evaluates itself (not those of its nested statements) name a
    /// property: only then is the statement copied and rewritten.
    fn uses(&self, s: &Stmt) -> bool {
        let place = |p: &Place| {
            self.find(p).is_some()
                || p.accessors.iter().any(|a| {
                    matches!(a, Accessor::Index(ix) if ix.iter().any(|x| self.reads_property(x)))
                })
        };
        match &s.kind {
            StmtKind::Assign { target, value } => place(target) || self.reads_property(value),
            StmtKind::Call { callee, args } => {
                place(callee) || args.iter().any(|a| self.reads_property(&a.value))
            }
            StmtKind::If { branches, .. } => branches.iter().any(|b| self.reads_property(&b.cond)),
            StmtKind::Case { selector, .. } => self.reads_property(selector),
            StmtKind::For { from, to, by, .. } => {
                self.reads_property(from)
                    || self.reads_property(to)
                    || by.as_ref().is_some_and(|b| self.reads_property(b))
            }
            StmtKind::While { cond, .. } => self.reads_property(cond),
            StmtKind::Repeat { until, .. } => self.reads_property(until),
            _ => false,
        }
    }

    /// Whether an expression reads a property.
    fn reads_property(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Unary { operand, .. } => self.reads_property(operand),
            ExprKind::Binary { left, right, .. } => {
                self.reads_property(left) || self.reads_property(right)
            }
            ExprKind::Call { args, .. } => args.iter().any(|a| self.reads_property(&a.value)),
            ExprKind::Place(p) => {
                self.find(p).is_some()
                    || p.accessors.iter().any(|a| {
                        matches!(a, Accessor::Index(ix) if ix.iter().any(|x| self.reads_property(x)))
                    })
            }
            _ => false,
        }
    }

    fn stmt(&mut self, s: &mut Stmt) {
        let span = s.span;
        match &mut s.kind {
            StmtKind::Assign { target, value } => {
                if let Some((at, prop, name)) = self.find(target) {
                    let whole = match at {
                        At::Base => target.accessors.is_empty(),
                        At::Own => target.accessors.len() == 1,
                        At::Field(k) => k + 1 == target.accessors.len(),
                    };
                    if self.component_through(target, at, &name) {
                        // `a.Child.Value := 5;` with `PROPERTY Child : REFERENCE TO FB_Tree`
                        // (or `P^.x := 1;` of a POINTER TO): the getter runs, and the write goes
                        // to what its result refers to (CODESYS, TwinCAT)
                        let mut read = Expr {
                            span: target.span,
                            kind: ExprKind::Place(target.clone()),
                        };
                        self.read(&mut read);
                        if let ExprKind::Place(p) = &mut read.kind {
                            *target = std::mem::replace(
                                p,
                                Place {
                                    base: PlaceBase::Name(name.clone()),
                                    accessors: Vec::new(),
                                    span,
                                },
                            );
                        }
                        self.read(value);
                        return;
                    }
                    if !whole {
                        self.error(
                            code::E0338,
                            target.span,
                            format!("a component of property `{}` cannot be written: the property's value is a copy", name.name),
                            "read the property into a variable, change the component there, and write the variable to the property",
                        );
                        s.kind = StmtKind::Empty;
                        return;
                    }
                    if !prop.set {
                        self.error(
                            code::E0337,
                            target.span,
                            format!("property `{}` has no Set accessor: it cannot be written", name.name),
                            "give the property a Set accessor, or write the variable its Get accessor reads",
                        );
                        s.kind = StmtKind::Empty;
                        return;
                    }
                    self.indexes(target);
                    self.read(value);
                    let callee =
                        Self::with_member(target, at, setter(&name.name), name.span, false);
                    let arg = Arg {
                        name: Some(name.clone()),
                        dir: ArgDir::Input,
                        span: value.span,
                        value: value.clone(),
                    };
                    s.kind = StmtKind::Call {
                        callee,
                        args: vec![arg],
                    };
                    self.changed = true;
                    return;
                }
                self.indexes(target);
                self.read(value);
            }
            StmtKind::Call { callee, args } => {
                self.indexes(callee);
                // an FB instance's (or a function's) VAR_IN_OUT parameters, in order
                let iface = match self.env.place_type(callee) {
                    Some(t) => match self.env.resolve(&t) {
                        TypeRef::Named(n) => self.env.decls.pou(&n.name),
                        _ => None,
                    },
                    None => match (&callee.base, callee.accessors.is_empty()) {
                        (PlaceBase::Name(n), true) => self.env.decls.pou(&n.name),
                        _ => None,
                    },
                };
                let in_outs = in_out_names(iface);
                let name = match &callee.base {
                    PlaceBase::Name(n) => n.name.clone(),
                    PlaceBase::Address(_) => String::new(),
                };
                self.args(&name, args, &in_outs);
            }
            StmtKind::If {
                branches,
                else_body,
            } => {
                if let Some(first) = branches.first_mut() {
                    self.read(&mut first.cond);
                }
                // `ELSIF inst.P THEN`: the IF is split there, so the getter runs only when the
                // branches before it were not taken: `ELSE <IF inst.P THEN ...> END_IF`
                if let Some(k) = branches
                    .iter()
                    .skip(1)
                    .position(|b| self.reads_property(&b.cond))
                    .map(|k| k + 1)
                {
                    let tail: Vec<CondBranch> = branches.drain(k..).collect();
                    let inner_span = tail[0].span;
                    let inner = Stmt {
                        kind: StmtKind::If {
                            branches: tail,
                            else_body: else_body.take(),
                        },
                        span: inner_span.to(span),
                    };
                    *else_body = Some(vec![inner]);
                    self.changed = true;
                }
            }
            StmtKind::Case { selector, .. } => self.read(selector),
            StmtKind::For { from, to, by, .. } => {
                self.read(from);
                self.read(to);
                if let Some(b) = by {
                    self.read(b);
                }
            }
            StmtKind::While { cond, body } if self.reads_property(cond) => {
                // `WHILE c DO body END_WHILE` as `WHILE TRUE DO IF NOT c THEN EXIT; END_IF; body
                // END_WHILE`: the getters run before each test (CONTINUE goes to the test too)
                let cspan = cond.span;
                let test = Stmt {
                    kind: StmtKind::If {
                        branches: vec![CondBranch {
                            cond: Expr {
                                kind: ExprKind::Unary {
                                    op: super::ast::UnaryOp::Not,
                                    operand: Box::new(cond.clone()),
                                },
                                span: cspan,
                            },
                            body: vec![Stmt {
                                kind: StmtKind::Exit,
                                span: cspan,
                            }],
                            span: cspan,
                        }],
                        else_body: None,
                    },
                    span: cspan,
                };
                let mut new_body = vec![test];
                new_body.append(body);
                *body = new_body;
                *cond = Expr {
                    kind: ExprKind::Literal(crate::ast::Literal {
                        kind: crate::ast::LiteralKind::Bool(true),
                        type_prefix: None,
                        span: cspan,
                    }),
                    span: cspan,
                };
                self.changed = true;
            }
            StmtKind::Repeat { until, .. } if self.reads_property(until) => {
                // the getters called in the condition, which the lowering runs before each test
                // (after the body, also after a CONTINUE), as it does an instance's method call
                self.in_place = true;
                self.read(until);
                self.in_place = false;
            }
            _ => {}
        }
    }
}

/// A text for a place without indexes (`INST.__GET_P`), to call one getter once per statement;
/// `None` for a place with indexes (each such read calls the getter).
fn place_key(p: &Place) -> Option<String> {
    let mut s = match &p.base {
        PlaceBase::Name(n) => n.key(),
        PlaceBase::Address(_) => return None,
    };
    for a in &p.accessors {
        match a {
            Accessor::Field(f) => {
                s.push('.');
                s.push_str(&f.key());
            }
            Accessor::Deref(_) => s.push('^'),
            Accessor::Index(_) | Accessor::Call { .. } => return None,
        }
    }
    Some(s)
}

/// For each parameter of `pou` in order, its upper-case name when it is a VAR_IN_OUT, else an empty
/// string (no POU: no parameters).
fn in_out_names(pou: Option<&super::types::PouInterface>) -> Vec<String> {
    pou.map(|p| {
        p.params()
            .map(|(n, k, _)| {
                if *k == VarKind::InOut {
                    n.to_ascii_uppercase()
                } else {
                    String::new()
                }
            })
            .collect()
    })
    .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn properties_are_found_with_their_accessors() {
        let src = "FUNCTION_BLOCK fb VAR x : INT; END_VAR\n\
                   PROPERTY PUBLIC Speed : INT\n GET VAR t : INT; END_VAR Speed := x; END_GET\n SET x := Speed; END_SET\nEND_PROPERTY\n\
                   PROPERTY Busy : BOOL GET Busy := x > 0; END_GET END_PROPERTY\nEND_FUNCTION_BLOCK";
        let (toks, _) = super::super::lexer::lex(src);
        let ps = scan_properties(src, &toks);
        assert_eq!(ps.len(), 2);
        assert_eq!(ps[0].name, "Speed");
        assert_eq!(&src[ps[0].name_range.start..ps[0].ty_end], "Speed : INT");
        let (d, s) = ps[0].get.clone().expect("a getter");
        assert_eq!(src[d].trim(), "VAR t : INT; END_VAR");
        assert_eq!(src[s].trim(), "Speed := x;");
        assert_eq!(
            src[ps[0].set.clone().expect("a setter").1].trim(),
            "x := Speed;"
        );
        assert!(ps[1].set.is_none());
        assert!(src[ps[1].whole.clone()].ends_with("END_PROPERTY"));
    }
}
