//! Expression types for the ST lowering: just enough typing to declare temporaries and to choose
//! between a function call and an FB call. IL sema does the real checking on the lowered IL.
//!
//! Input: ST expressions, the POU's variables, [`Declarations`], the standard catalogue
//! (`sema::stdlib`). Output: [`Ty`]: a declared type as written, an untyped literal, or unknown.
//! Invariants: never fails: anything it cannot type is [`Ty::Unknown`] (sema reports the real cause);
//! aliases are followed at most 16 levels.

use super::ast::{Accessor, BinaryOp, Expr, ExprKind, Place, PlaceBase, UnaryOp};
use super::types::Declarations;
use crate::ast::{AddressSize, Ident, LiteralKind, PouKind, TypeDef, TypeRef};
use crate::sema::model::{Elementary, StdFb};
use crate::sema::stdlib::{self, ConvTarget, ParamTy, Ret};
use crate::Span;
use std::collections::HashMap;

/// The type of an expression as far as the lowering needs it.
#[derive(Debug, Clone)]
pub enum Ty {
    /// A declared type, as written (follow aliases with [`Env::resolve`]).
    Known(TypeRef),
    /// An integer literal without prefix: takes the type of its context.
    IntLit,
    /// A real literal without prefix: takes the real type of its context.
    RealLit,
    /// Not known here (an error sema reports, or a name the lowering does not look into).
    Unknown,
}

impl Ty {
    /// The type, when it is known.
    pub fn known(&self) -> Option<&TypeRef> {
        match self {
            Ty::Known(t) => Some(t),
            _ => None,
        }
    }
}

/// The type named `name` (`INT`, `TON`, a user type).
pub fn named(name: &str, span: Span) -> TypeRef {
    TypeRef::Named(Ident::new(name, span))
}

fn elem_ref(e: Elementary, span: Span) -> TypeRef {
    named(e.name(), span)
}

/// What the typing looks names up in.
pub struct Env<'a> {
    /// The program's data types, POU interfaces and globals.
    pub decls: &'a Declarations,
    /// The POU's variables (upper-case name -> type).
    pub vars: &'a HashMap<String, TypeRef>,
    /// The POU being lowered (its name is its result variable in a FUNCTION).
    pub pou_name: &'a Ident,
    /// Whether the POU is a FUNCTION, FUNCTION_BLOCK or PROGRAM.
    pub pou_kind: PouKind,
    /// A FUNCTION's result type.
    pub pou_ret: Option<&'a TypeRef>,
}

impl Env<'_> {
    /// Follows named aliases (`TYPE T : INT; END_TYPE`) to what they stand for.
    pub fn resolve(&self, t: &TypeRef) -> TypeRef {
        let mut t = t.clone();
        for _ in 0..16 {
            let TypeRef::Named(n) = &t else { break };
            match self.decls.type_decl(&n.name).map(|d| &d.def) {
                Some(TypeDef::Alias { ty, .. }) => t = ty.clone(),
                _ => break,
            }
        }
        t
    }

    /// The elementary type of `t` (through aliases and subranges).
    pub fn elementary(&self, t: &TypeRef) -> Option<Elementary> {
        match self.resolve(t) {
            TypeRef::Named(n) => Elementary::from_name(&n.name),
            TypeRef::Subrange { base, .. } => Elementary::from_name(&base.name),
            _ => None,
        }
    }

    /// Whether `t` is an enumeration declared without `{attribute 'strict'}`: CODESYS and TwinCAT
    /// count with it as with its integer (Beckhoff Infosys, "Attribute 'strict'": only under the
    /// attribute is arithmetic on an enumeration variable a compile error).
    pub fn loose_enum(&self, t: &TypeRef) -> bool {
        match self.resolve(t) {
            TypeRef::Named(n) => {
                !self.decls.strict_enums.contains(&n.key())
                    && self
                        .decls
                        .type_decl(&n.name)
                        .is_some_and(|d| matches!(d.def, TypeDef::Enum { .. }))
            }
            _ => false,
        }
    }

    /// The type an untyped integer literal `lit` takes beside an operand of type `ty` (the other
    /// operand of an arithmetic or bit operation): `ty` when the literal fits it, else the smallest
    /// integer (bit string) type that `ty` implicitly widens to and that holds the literal (IEC
    /// 61131-3 ed. 3 6.6.1.6.2, implicit conversions; the literal's type is given by its context):
    /// `256 * b` with `b : USINT` is a UINT multiplication, as CODESYS, TwinCAT and B&R compute it
    /// in a wider integer. `None`: `lit` is no untyped integer literal, `ty` no plain integer or
    /// bit-string type (a subrange keeps its range checks), or the literal fits it or no type.
    pub fn literal_widened(&self, ty: &TypeRef, lit: &Expr) -> Option<TypeRef> {
        let ExprKind::Literal(l) = &lit.kind else {
            return None;
        };
        let LiteralKind::Int(v) = l.kind else {
            return None;
        };
        if l.type_prefix.is_some() {
            return None;
        }
        let TypeRef::Named(n) = self.resolve(ty) else {
            return None;
        };
        let e = Elementary::from_name(&n.name)?;
        let (lo, hi) = e.int_range()?;
        if e == Elementary::Bool || (lo..=hi).contains(&v) {
            return None;
        }
        use Elementary as E;
        // smallest first; of two of one size, the one of the operand's signedness first
        const ORDER: [Elementary; 12] = [
            E::Usint,
            E::Sint,
            E::Byte,
            E::Uint,
            E::Int,
            E::Word,
            E::Udint,
            E::Dint,
            E::Dword,
            E::Ulint,
            E::Lint,
            E::Lword,
        ];
        ORDER
            .into_iter()
            .filter(|c| *c != e && crate::sema::typing::widens(e, *c))
            .find(|c| c.int_range().is_some_and(|(lo, hi)| (lo..=hi).contains(&v)))
            .map(|c| elem_ref(c, lit.span))
    }

    /// Whether `name` is a variable of the POU (or a global, or the function's result).
    pub fn var_type(&self, name: &Ident) -> Option<TypeRef> {
        let key = name.key();
        if let Some(t) = self.vars.get(&key) {
            return Some(t.clone());
        }
        if self.pou_kind == PouKind::Function && name == self.pou_name {
            return self.pou_ret.cloned();
        }
        self.decls.globals.get(&key).cloned()
    }

    /// A value of an enumeration qualified by the type's name with a dot, `E_State.Init` (CODESYS and
    /// TwinCAT write it so; IEC 61131-3 writes `E_State#Init`): the type's and the value's names as
    /// declared, when `p` is no variable, no global list and the type declares the value.
    pub fn qualified_enum_value(&self, p: &Place) -> Option<(Ident, Ident)> {
        let (PlaceBase::Name(n), [Accessor::Field(v)]) = (&p.base, p.accessors.as_slice()) else {
            return None;
        };
        // a POU's own variable hides the type; a global of the type's name does not, where the
        // type declares the value (TwinCAT: `MachineMode.Auto` beside a `qualified_only` list's
        // `MachineMode`, reached as `GVL.MachineMode`)
        let own = self.vars.contains_key(&n.key())
            || (self.pou_kind == PouKind::Function && n == self.pou_name);
        if own || self.decls.global_lists.contains_key(&n.key()) {
            return None;
        }
        let decl = self.decls.types.get(&n.key())?;
        let TypeDef::Enum { values, .. } = &decl.def else {
            return None;
        };
        let value = values.iter().find(|e| e.name == *v)?;
        Some((
            Ident::new(decl.name.name.clone(), n.span),
            Ident::new(value.name.name.clone(), v.span),
        ))
    }

    /// The enumeration that declares a bare value `red`, if exactly one does.
    fn enum_of_value(&self, value: &Ident) -> Option<TypeRef> {
        let mut found = self.decls.types.values().filter(|d| {
            matches!(&d.def, TypeDef::Enum { values, .. } if values.iter().any(|v| v.name == *value))
        });
        let first = found.next()?;
        found
            .next()
            .is_none()
            .then(|| TypeRef::Named(first.name.clone()))
    }

    /// The type of a member `field` of a value of type `t` (struct field, FB input/output).
    pub fn member(&self, t: &TypeRef, field: &Ident) -> Option<TypeRef> {
        if let Some((size, _)) = crate::ast::partial_access(&field.name) {
            // `x.3`, `x.%B1`: a part of an integer or bit string (sema checks the range)
            let e = match size {
                AddressSize::Bit => Elementary::Bool,
                AddressSize::Byte => Elementary::Byte,
                AddressSize::Word => Elementary::Word,
                AddressSize::DWord => Elementary::Dword,
                AddressSize::LWord => Elementary::Lword,
            };
            return Some(elem_ref(e, field.span));
        }
        let TypeRef::Named(n) = self.resolve(t) else {
            return None;
        };
        if let Some(d) = self.decls.type_decl(&n.name) {
            if let TypeDef::Struct { fields } = &d.def {
                return fields
                    .iter()
                    .find(|f| f.name == *field)
                    .map(|f| f.ty.clone());
            }
            return None;
        }
        if let Some(p) = self.decls.pou(&n.name) {
            return p.var(&field.name).map(|v| v.2.clone());
        }
        let fb = StdFb::from_name(&n.name)?;
        stdlib::fb_params(fb)
            .iter()
            .find(|p| p.name.eq_ignore_ascii_case(&field.name))
            .map(|p| elem_ref(p.ty, field.span))
    }

    /// Whether `p`'s type is unknown because a part of it is of a type that nothing declares
    /// (`pos.v` with `pos : Lib.POS_REF`: the qualifier of a library ladderc provides is gone by
    /// now, `st::qualifiers`, so any other got its E1032; `x.a` with `x : Missing`: sema's E1003
    /// at the declaration): that error is the cause, not `p`'s use. An unqualified name that is
    /// a type ladderc adds later (`AXIS_REF`, `AXES_GROUP_REF`, the PLCopen motion blocks
    /// `MC_...` of its block library) is not judged here.
    pub fn of_unknown_type(&self, p: &Place) -> bool {
        let PlaceBase::Name(n) = &p.base else {
            return false;
        };
        let Some(mut t) = self.var_type(n) else {
            return false;
        };
        let unknown = |t: &TypeRef| match self.resolve(t) {
            TypeRef::Named(n) => {
                let added_later = n.is("AXIS_REF")
                    || n.is("AXES_GROUP_REF")
                    || n.name
                        .get(..3)
                        .is_some_and(|p| p.eq_ignore_ascii_case("MC_"));
                (n.name.contains('.') || n.name.starts_with("__") || !added_later)
                    && Elementary::from_name(&n.name).is_none()
                    && !n.is("STRING")
                    && !n.is("WSTRING")
                    && self.decls.type_decl(&n.name).is_none()
                    && self.decls.pou(&n.name).is_none()
                    && !self.decls.interfaces.contains_key(&n.key())
                    && StdFb::from_name(&n.name).is_none()
            }
            _ => false,
        };
        for acc in &p.accessors {
            if unknown(&t) {
                return true;
            }
            t = self.unreference(t);
            t = match acc {
                Accessor::Field(f) => match self.member(&t, f) {
                    Some(t) => t,
                    None => return false,
                },
                Accessor::Index(_) => match self.resolve(&t) {
                    TypeRef::Array { element, .. } => *element,
                    _ => return false,
                },
                Accessor::Deref(_) => match self.resolve(&t) {
                    TypeRef::Ref { target, .. } => *target,
                    _ => return false,
                },
                Accessor::Call { .. } => return false,
            };
        }
        unknown(&t)
    }

    /// The type of a place, or `None` when some part of it is unknown.
    pub fn place_type(&self, p: &Place) -> Option<TypeRef> {
        if let Some((t, _)) = self.qualified_enum_value(p) {
            return Some(TypeRef::Named(t));
        }
        let mut skip = 0;
        let mut t = match &p.base {
            PlaceBase::Name(n) => match self.var_type(n) {
                Some(t) => t,
                None => match (self.decls.global_lists.get(&n.key()), p.accessors.first()) {
                    // `GVL.x`: a member of a named global variable list
                    (Some(list), Some(Accessor::Field(m))) => {
                        skip = 1;
                        list.get(&m.key())?.clone()
                    }
                    _ if p.accessors.is_empty() => self.enum_of_value(n)?,
                    // `MAIN.x`: a variable of a program named by the program (W1413, a CODESYS
                    // and TwinCAT extension): typed as the program's member, so that a literal
                    // beside it (`MAIN.fGap / 2`) takes its type as beside any variable
                    _ if self
                        .decls
                        .pou(&n.name)
                        .is_some_and(|q| q.kind == PouKind::Program) =>
                    {
                        TypeRef::Named(n.clone())
                    }
                    _ => return None,
                },
            },
            PlaceBase::Address(a) => {
                let e = match a.size {
                    AddressSize::Bit => Elementary::Bool,
                    AddressSize::Byte => Elementary::Byte,
                    AddressSize::Word => Elementary::Word,
                    AddressSize::DWord => Elementary::Dword,
                    AddressSize::LWord => Elementary::Lword,
                };
                elem_ref(e, a.span)
            }
        };
        // a `REFERENCE TO` reads as the variable it refers to (the lowering adds the `^`)
        for acc in p.accessors.iter().skip(skip) {
            if !matches!(acc, Accessor::Deref(_)) {
                t = self.unreference(t);
            }
            t = match acc {
                Accessor::Field(f) => self.member(&t, f)?,
                Accessor::Index(_) => match self.resolve(&t) {
                    TypeRef::Array { element, .. } => *element,
                    _ => return None,
                },
                Accessor::Deref(_) => match self.resolve(&t) {
                    TypeRef::Ref { target, .. } => *target,
                    _ => return None,
                },
                // a call inside the place: typed once `lower::call_chain` has replaced it
                Accessor::Call { .. } => return None,
            };
        }
        Some(self.unreference(t))
    }

    /// The type a `REFERENCE TO T` stands for where it is used: `T` (any other type: itself).
    fn unreference(&self, t: TypeRef) -> TypeRef {
        // written out, or through a TYPE alias (which only a program with a `REFERENCE TO` has):
        // no copy of the type otherwise, this runs for every access
        let aliased = matches!(t, TypeRef::Named(_)) && self.decls.has_reference_to();
        if !aliased && !matches!(t, TypeRef::Ref { .. }) {
            return t;
        }
        match self.resolve(&t) {
            TypeRef::Ref {
                kind: crate::ast::RefKind::Reference,
                target,
                ..
            } => *target,
            _ => t,
        }
    }

    /// Where the `^` of each `REFERENCE TO` in place `p` goes (the source leaves it out): before
    /// written accessor `k` for each `k` returned, `p.accessors.len()` meaning after the last one.
    /// With `raw_last`, a reference the place ends with stands for itself (`r REF= x`,
    /// `__ISVALIDREF(r)`).
    pub fn implicit_derefs(&self, p: &Place, raw_last: bool) -> Vec<usize> {
        let mut out = Vec::new();
        let PlaceBase::Name(n) = &p.base else {
            return out;
        };
        let (mut t, skip) = match self.var_type(n) {
            Some(t) => (t, 0),
            None => match (self.decls.global_lists.get(&n.key()), p.accessors.first()) {
                (Some(list), Some(Accessor::Field(m))) => match list.get(&m.key()) {
                    Some(t) => (t.clone(), 1),
                    None => return out,
                },
                _ => return out,
            },
        };
        let len = p.accessors.len();
        for k in skip..=len {
            let next = p.accessors.get(k);
            let reference = matches!(
                self.resolve(&t),
                TypeRef::Ref {
                    kind: crate::ast::RefKind::Reference,
                    ..
                }
            );
            if reference && !matches!(next, Some(Accessor::Deref(_))) && !(raw_last && k == len) {
                out.push(k);
                t = self.unreference(t);
            }
            t = match next {
                None => break,
                Some(Accessor::Field(f)) => match self.member(&t, f) {
                    Some(m) => m,
                    None => break,
                },
                Some(Accessor::Index(_)) => match self.resolve(&t) {
                    TypeRef::Array { element, .. } => *element,
                    _ => break,
                },
                Some(Accessor::Deref(_)) => match self.resolve(&t) {
                    TypeRef::Ref { target, .. } => *target,
                    _ => break,
                },
                Some(Accessor::Call { .. }) => break,
            };
        }
        out
    }

    /// Whether `name` is an FB instance of the POU (a variable whose type is an FB type).
    pub fn is_fb_type(&self, t: &TypeRef) -> bool {
        match self.resolve(t) {
            TypeRef::Named(n) => {
                StdFb::from_name(&n.name).is_some()
                    || self
                        .decls
                        .pou(&n.name)
                        .is_some_and(|p| p.kind == PouKind::FunctionBlock)
            }
            _ => false,
        }
    }

    /// The type of an expression (linear in its size, no recursion: see [`Self::expr_cached`]).
    pub fn expr(&self, e: &Expr) -> Ty {
        self.expr_cached(e, &mut TypeCache::new())
    }

    /// The type of an expression, computed bottom-up with an explicit stack (a chain of 100,000
    /// operators neither recurses nor costs more than its size). Every subexpression's type is left
    /// in `cache`, keyed by the node's address: the caller keeps the tree alive and unchanged while
    /// the cache is in use, and clears it before a node could be freed and its address reused.
    pub fn expr_cached(&self, root: &Expr, cache: &mut TypeCache) -> Ty {
        if let Some(t) = cache.get(&key(root)) {
            return t.clone();
        }
        let mut stack: Vec<(&Expr, bool)> = vec![(root, false)];
        while let Some((e, children_done)) = stack.pop() {
            if children_done {
                let t = self.node(e, &|c: &Expr| {
                    cache.get(&key(c)).cloned().unwrap_or(Ty::Unknown)
                });
                cache.insert(key(e), t);
                continue;
            }
            if cache.contains_key(&key(e)) {
                continue;
            }
            stack.push((e, true));
            match &e.kind {
                ExprKind::Unary { operand, .. } => stack.push((operand, false)),
                ExprKind::Binary { left, right, .. } => {
                    stack.push((right, false));
                    stack.push((left, false));
                }
                ExprKind::Call { args, .. } => {
                    stack.extend(args.iter().map(|a| (&a.value, false)));
                }
                _ => {}
            }
        }
        cache.get(&key(root)).cloned().unwrap_or(Ty::Unknown)
    }

    /// The type of one node, given the types of its operands (`sub`).
    fn node(&self, e: &Expr, sub: &dyn Fn(&Expr) -> Ty) -> Ty {
        match &e.kind {
            ExprKind::Literal(l) => {
                if let Some(p) = &l.type_prefix {
                    return Ty::Known(named(&p.name, p.span));
                }
                let el = match &l.kind {
                    LiteralKind::Int(_) => return Ty::IntLit,
                    LiteralKind::Real(_) => return Ty::RealLit,
                    LiteralKind::Bool(_) => Elementary::Bool,
                    LiteralKind::Duration(_) => Elementary::Time,
                    LiteralKind::Date(_) => Elementary::Date,
                    LiteralKind::TimeOfDay(_) => Elementary::Tod,
                    LiteralKind::DateAndTime(_) => Elementary::Dt,
                    LiteralKind::String { wide, .. } => {
                        return Ty::Known(TypeRef::String {
                            wide: *wide,
                            length: None,
                            span: l.span,
                        })
                    }
                };
                Ty::Known(elem_ref(el, l.span))
            }
            ExprKind::Place(p) => self.place_type(p).map_or(Ty::Unknown, Ty::Known),
            ExprKind::EnumValue { type_name, .. } => Ty::Known(TypeRef::Named(type_name.clone())),
            ExprKind::Unary { op, operand } => {
                let t = sub(operand);
                match (op, t) {
                    (UnaryOp::Not, Ty::IntLit) => Ty::Unknown,
                    (_, t) => t,
                }
            }
            ExprKind::Binary { op, left, right } => {
                let (mut l, mut r) = (sub(left), sub(right));
                // `256 * b` (b : USINT): the literal in the type that holds it (`literal_widened`)
                if let Some(w) = l.known().and_then(|t| self.literal_widened(t, right)) {
                    r = Ty::Known(w);
                } else if let Some(w) = r.known().and_then(|t| self.literal_widened(t, left)) {
                    l = Ty::Known(w);
                }
                self.binary(*op, l, r, e.span)
            }
            ExprKind::Call { name, args } => self.call(name, args, e.span, sub),
            ExprKind::Error => Ty::Unknown,
        }
    }

    /// The type of an operation on `l` and `r`: of two elementary types, the one the other widens
    /// to (`i - lb` of an INT and a DINT is a DINT, as sema types it); else as [`unify`].
    fn common(&self, l: Ty, r: Ty) -> Ty {
        if let (Ty::Known(a), Ty::Known(b)) = (&l, &r) {
            if let (Some(ea), Some(eb)) = (self.elementary(a), self.elementary(b)) {
                if ea != eb && crate::sema::typing::widens(ea, eb) {
                    return r;
                }
            }
        }
        unify(l, r)
    }

    fn binary(&self, op: BinaryOp, l: Ty, r: Ty, span: Span) -> Ty {
        use BinaryOp::*;
        match op {
            Eq | Ne | Lt | Gt | Le | Ge => Ty::Known(elem_ref(Elementary::Bool, span)),
            Power => match l {
                Ty::IntLit | Ty::RealLit => Ty::RealLit,
                t => t,
            },
            Add | Sub | Mul | Div => {
                let le = l.known().and_then(|t| self.elementary(t));
                if let Some(le) = le.filter(|e| !e.is_numeric() && !e.is_bit()) {
                    let name = match op {
                        Add => "ADD",
                        Sub => "SUB",
                        Mul => "MUL",
                        _ => "DIV",
                    };
                    let re = r.known().and_then(|t| self.elementary(t));
                    for o in stdlib::time_overloads(name, le) {
                        if o.3.is_none() || o.3 == re {
                            return Ty::Known(elem_ref(o.4, span));
                        }
                    }
                }
                self.common(l, r)
            }
            Mod | And | Or | Xor => self.common(l, r),
            AndThen | OrElse => Ty::Known(elem_ref(Elementary::Bool, span)),
        }
    }

    fn call(
        &self,
        name: &Ident,
        args: &[super::ast::Arg],
        span: Span,
        sub: &dyn Fn(&Expr) -> Ty,
    ) -> Ty {
        if let Some(p) = self.decls.pou(&name.name) {
            if p.kind == PouKind::Function {
                return p.ret.clone().map_or(Ty::Unknown, Ty::Known);
            }
        }
        // references (see `super::refs`): `REF(x)` / `ADR(x)` refer to `x`, `__ISVALIDREF(r)` is BOOL
        if super::refs::is_address_of(name) {
            let target = match args {
                [a] => match &a.value.kind {
                    ExprKind::Place(p) => self.place_type(p),
                    _ => None,
                },
                _ => None,
            };
            return target.map_or(Ty::Unknown, |t| {
                Ty::Known(TypeRef::Ref {
                    kind: crate::ast::RefKind::RefTo,
                    target: Box::new(t),
                    span,
                })
            });
        }
        if name.is(super::refs::IS_VALID_REF) {
            return Ty::Known(elem_ref(Elementary::Bool, span));
        }
        // `SIZEOF(x)`: an unsigned integer typed by its context, as an integer literal is
        if name.is("SIZEOF") {
            return Ty::IntLit;
        }
        // TRUNC is ANY_REAL to ANY_INT (IEC 61131-3 edition 2): its integer type is its context's,
        // as matiec types it (`i := TRUNC(r)` is TRUNC to INT); the lowering writes `TRUNC_INT`
        if name.name.eq_ignore_ascii_case("TRUNC") {
            return Ty::IntLit;
        }
        if let Some(f) = stdlib::function(&name.name) {
            return match f.result {
                Ret::Fixed(e) => Ty::Known(elem_ref(e, span)),
                Ret::T => {
                    let mut t = Ty::Unknown;
                    for (i, a) in args.iter().enumerate() {
                        let idx = match &a.name {
                            Some(n) => f.param_index(&n.name),
                            None => Some(i),
                        };
                        if let Some(ParamTy::T(_)) = idx.and_then(|i| f.param_ty(i)) {
                            t = unify(t, sub(&a.value));
                        }
                    }
                    if f.time_arith {
                        if let Some(super::ast::Arg { value, .. }) = args.first() {
                            if let Some(le) = sub(value).known().and_then(|t| self.elementary(t)) {
                                if let Some(o) = stdlib::time_overloads(f.name, le).next() {
                                    return Ty::Known(elem_ref(o.4, span));
                                }
                            }
                        }
                    }
                    // a string function's result (CONCAT, LEFT, ...) is as long as the runtime
                    // holds: a temporary holding it cuts nothing (the store into a variable cuts to
                    // its declared length), whatever the default length of its inputs' type
                    match t {
                        Ty::Known(TypeRef::String { wide, span, .. }) => {
                            Ty::Known(TypeRef::String {
                                wide,
                                length: Some(crate::sema::model::STRING_CAPACITY),
                                span,
                            })
                        }
                        t => t,
                    }
                }
            };
        }
        if let Some(c) = stdlib::conversion(&name.name) {
            return match c.to {
                ConvTarget::Fixed(t) => match t.elementary() {
                    Some(e) => Ty::Known(elem_ref(e, span)),
                    None => Ty::Known(TypeRef::String {
                        wide: matches!(t, crate::sema::model::Type::String { wide: true, .. }),
                        length: None,
                        span,
                    }),
                },
                ConvTarget::BcdOfWidth => {
                    let from = c
                        .from
                        .and_then(|t| t.elementary())
                        .unwrap_or(Elementary::Int);
                    Ty::Known(elem_ref(stdlib::bcd_of_width(from), span))
                }
            };
        }
        if let Some(t) = stdlib::TIME_ARITH
            .iter()
            .find(|t| t.0.eq_ignore_ascii_case(&name.name))
        {
            return Ty::Known(elem_ref(t.4, span));
        }
        Ty::Unknown
    }
}

/// Types of subexpressions by node (see [`Env::expr_cached`]).
pub type TypeCache = HashMap<NodeKey, Ty>;

/// A node of an expression tree while it lives: its address, with its span and kind. A lowering
/// drops the expressions it rewrote (a hoisted call's argument, a property read made a getter
/// call) and allocates others, which may get a freed node's address: with the address alone, a
/// new node read the type of the old one (round 32, x-PPU: `IF p^.Flag THEN` after a call that
/// hoisted `INT_TO_LREAL(p^.dist)` took the condition as the INT `p^.dist`, a false E3105, and
/// its condition for FALSE).
pub type NodeKey = (usize, Span, std::mem::Discriminant<ExprKind>);

fn key(e: &Expr) -> NodeKey {
    (
        e as *const Expr as usize,
        e.span,
        std::mem::discriminant(&e.kind),
    )
}

/// The type of a generic operation on two values: a typed side wins over a literal.
pub fn unify(a: Ty, b: Ty) -> Ty {
    match (a, b) {
        (Ty::Known(t), _) | (_, Ty::Known(t)) => Ty::Known(t),
        (Ty::RealLit, _) | (_, Ty::RealLit) => Ty::RealLit,
        (Ty::IntLit, _) | (_, Ty::IntLit) => Ty::IntLit,
        _ => Ty::Unknown,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::FileId;

    /// A node replaced in place (the same address: a lowering that drops a rewritten
    /// expression and allocates the next one where it was) is typed as what it now is, not
    /// from the cache entry of the node that was there (round 32, x-PPU's false E3105).
    #[test]
    fn a_node_at_a_reused_address_is_typed_again() {
        let decls = Declarations::default();
        let mut vars = HashMap::new();
        let file = FileId(0);
        vars.insert("DIST".to_string(), named("INT", Span::new(file, 0, 0)));
        vars.insert("FLAG".to_string(), named("BOOL", Span::new(file, 0, 0)));
        let pou = Ident::new("Main", Span::new(file, 0, 4));
        let env = Env {
            decls: &decls,
            vars: &vars,
            pou_name: &pou,
            pou_kind: PouKind::Program,
            pou_ret: None,
        };
        let mut diags = diagnostics::Diagnostics::new();
        let src = "dist        flag";
        let mut node = crate::st::parse_expression(file, &src[..4], 0, &mut diags).unwrap();
        let mut cache = TypeCache::new();
        let shown = |t: Ty| match t {
            Ty::Known(TypeRef::Named(i)) => i.name.to_ascii_uppercase(),
            other => format!("{other:?}"),
        };
        assert_eq!(shown(env.expr_cached(&node, &mut cache)), "INT");
        // the same place in memory now holds `flag`
        node = crate::st::parse_expression(file, &src[12..], 12, &mut diags).unwrap();
        assert_eq!(shown(env.expr_cached(&node, &mut cache)), "BOOL");
        assert!(diags.is_empty(), "{diags:?}");
    }
}
