//! References in bodies (IEC 61131-3 edition 3, 6.4.4.10; CODESYS/TwinCAT pointers and
//! `REFERENCE TO`): the type of `REF(x)` / `ADR(x)` / `NULL`, the dereference `r^`, pointer
//! arithmetic (`p + n` / `p - n` in bytes, `p - q`, comparisons), a pointer stored into a pointer to
//! another type (W1425), the variables whose address may not be taken, and `SIZEOF(x)` /
//! `SIZEOF(T)` (the bytes of a variable or type in the generated C). `p[i]` is typed in
//! `places.rs`.
//!
//! Input: operands and accesses of one body. Output: their types and diagnostics. Invariants: a
//! reference is only ever made to storage that outlives every reference to it: a variable of a
//! program or function block instance, a global, or what another reference refers to; `REF` of a
//! VAR_TEMP, of any variable of a FUNCTION (the standard's rule: they live for one call), of a
//! VAR_IN_OUT (it may be the caller's temporary), of a located variable or of a bit of a variable
//! is one E0305 at the operand. Moving a pointer is allowed because the C bounds every access
//! through it to the variable it was made from (c-backend `emit/refs.rs`); converting one is
//! allowed only between types that hold no reference, so that no reference is made from bytes.

use super::body::{Body, Ty};
use super::model::*;
use super::places::Place;
use super::stdlib::StdFunction;
use crate::ast::{self, Accessor, PouKind, RefOperand, VarKind};
use diagnostics::code;

/// Whether standard function `f` takes `t` for a parameter of class `c`: its class's types, and
/// references for the comparisons (`r = NULL`, `r1 <> r2`: whether they stand for the same
/// address; `p < q`: the addresses ordered, meaningful for two pointers into one variable).
pub(super) fn class_admits(f: &str, c: super::stdlib::Class, t: &Type) -> bool {
    c.contains(t)
        || (matches!(t, Type::Ref(_)) && matches!(f, "EQ" | "NE" | "LT" | "LE" | "GT" | "GE"))
}

/// The chain of blocks (upper-case, root first) of user block `fb`, read from its class variable
/// (`crate::st::base_view`); `None` for a block that no block extends and that extends none.
fn fb_chain(model: &Model, fb: &Type) -> Option<Vec<String>> {
    let Type::Fb(FbType::User(id)) = fb else {
        return None;
    };
    crate::st::base_view::class_chain(&model.pou(*id).vars.first()?.name)
}

/// Whether a reference to `from` may be stored where a reference to `to` is expected: `from` is
/// a block that EXTENDS `to` (directly or through others; IEC 61131-3 edition 3, 6.6.5: a derived
/// instance stands wherever its base may). With `down`, also the other way (only the hidden views
/// of `crate::st::base_view`, after their class was tested).
pub(super) fn substitutes(model: &Model, from: &Type, to: &Type, down: bool) -> bool {
    let (Type::Ref(f), Type::Ref(t)) = (from, to) else {
        return false;
    };
    let (Some(fc), Some(tc)) = (fb_chain(model, f), fb_chain(model, t)) else {
        return false;
    };
    let is_prefix = |a: &[String], b: &[String]| b.len() >= a.len() && b[..a.len()] == *a;
    is_prefix(&tc, &fc) || (down && is_prefix(&fc, &tc))
}

impl Body<'_, '_> {
    /// A VAR_IN_OUT declared as a reference (`VAR_IN_OUT total : REFERENCE TO DINT`): refused, one
    /// E0305 at the argument (a VAR_IN_OUT is already passed by reference).
    pub(super) fn in_out_reference(&mut self, param: &str, callee: &str, span: crate::Span) {
        self.a
            .error(
                code::E0305,
                span,
                format!("`{param}` of `{callee}` is a VAR_IN_OUT of a reference type: not supported"),
            )
            .label("passed here")
            .hint("declare it `VAR_IN_OUT total : DINT` (passed by reference already) or `VAR_INPUT total : REFERENCE TO DINT`");
    }
    /// Arithmetic on a reference other than `p + n`, `p - n` and `p - q` (`p * 2`, `p AND 3`):
    /// refused, one E0305.
    pub(super) fn pointer_arithmetic(&mut self, f: &str, tn: &str, span: crate::Span) {
        self.a
            .error(
                code::E0305,
                span,
                format!("`{f}` on a reference ({tn}): only a byte count may be added to or subtracted from a pointer"),
            )
            .label("this is a reference")
            .hint("move a pointer with `p + n` / `p - n` (n bytes, e.g. `p + SIZEOF(p^)`) or index it (`p[i]`); compare pointers with `=`, `<>`, `<` ...");
    }

    /// `p + n` / `p - n` (CODESYS, TwinCAT pointer arithmetic: `n` counts bytes): a reference of
    /// `p`'s type, when the first input is a reference and the second an integer; `p - q` of two
    /// references: their distance in bytes, a DWORD (CODESYS); `None` when the call is not that. The moved pointer is checked when it is dereferenced (c-backend refs.rs).
    pub(super) fn pointer_step(
        &mut self,
        f: &StdFunction,
        args: &[(Ty, crate::Span)],
    ) -> Option<super::calls::Inst> {
        if !matches!(f.name, "ADD" | "SUB") || args.len() != 2 {
            return None;
        }
        let Ty::Known(p) = self.norm(&args[0].0) else {
            return None;
        };
        if !matches!(&p, Type::Ref(target) if !target.is_error()) {
            return None;
        }
        let ok = match self.norm(&args[1].0) {
            // `p - q`: the bytes from q to p, meaningful for two pointers into one variable; a
            // DWORD, as CODESYS documents ("the result of the difference between two pointers is
            // of type DWORD, even on 64-bit platforms")
            Ty::Known(Type::Ref(_)) if f.name == "SUB" => {
                return Some(super::calls::Inst {
                    name: f.name,
                    t: Ty::Known(p),
                    result: Ty::Known(Type::Elementary(Elementary::Dword)),
                });
            }
            // a byte count: an integer, or a bit string (CODESYS: `p + DWORD#1`; an address
            // is a DWORD in CODESYS V2.3, an __XWORD in V3)
            Ty::Known(t) => {
                t.is_error()
                    || t.is_integer()
                    || matches!(
                        t.elementary(),
                        Some(
                            Elementary::Byte
                                | Elementary::Word
                                | Elementary::Dword
                                | Elementary::Lword
                        )
                    )
            }
            Ty::Lit(v) => self
                .lits
                .bind(v, &Type::Elementary(Elementary::Lint))
                .is_ok(),
        };
        if !ok {
            let d = self.describe(&args[1].0);
            let tn = self.a.type_name(&p);
            self.a
                .error(
                    code::E1004,
                    args[1].1,
                    format!(
                        "{} of {tn} and {d}: a pointer moves by an integer number of bytes",
                        f.name
                    ),
                )
                .label(format!("this is {d}"))
                .hint("add a byte count: `p + SIZEOF(p^)`, `p + i * SIZEOF(T)`");
            return Some(super::calls::Inst {
                name: f.name,
                t: Ty::ERROR,
                result: Ty::ERROR,
            });
        }
        Some(super::calls::Inst {
            name: f.name,
            t: Ty::Known(p.clone()),
            result: Ty::Known(p),
        })
    }

    /// W1425, once per POU: a reference stored into a reference to another type, which reads the
    /// same bytes as that type (CODESYS and TwinCAT convert pointers freely; IEC 61131-3 keeps
    /// references typed).
    pub(super) fn pointer_reinterpreted(&mut self, from: &Type, to: &Type, at: crate::Span) {
        if self.a.silent
            || self.a.passing_any_address
            || !self.a.reinterpreting_pous.insert(self.pou)
        {
            return;
        }
        let (f, t) = (self.a.type_name(from), self.a.type_name(to));
        self.a
            .warning(
                code::W1425,
                at,
                format!("{f} stored into {t}: the pointer reads the same bytes as another type (its other uses in this POU are not reported)"),
            )
            .label(format!("this is {f}"))
            .hint("IEC 61131-3 keeps references typed; CODESYS and TwinCAT convert pointers freely. Accesses stay inside the variable the pointer was made from and must be aligned for the new type");
    }

    /// The type of `REF(x)` / `ADR(x)` (a reference to `x`'s type) or `NULL` (a reference to
    /// [`Type::Error`], which fits every reference).
    pub(super) fn reference_operand(&mut self, r: &RefOperand) -> Ty {
        let Some(v) = &r.of else {
            return Ty::Known(Type::Ref(Box::new(Type::Error)));
        };
        let place = self.resolve_var(v);
        if place.ty.is_error() {
            return Ty::ERROR;
        }
        if !r.call_scoped && self.scoped_refs.contains(&v.base.key()) {
            let input = shown_method_var(&v.base.name);
            // as written: `block.n`, not the hidden `__M_CALC_BLOCK^.n`
            let path = crate::print::var_ref_text(v)
                .replacen(&format!("{}^", v.base.name), input, 1)
                .replacen(&v.base.name, input, 1);
            self.a
                .error(
                    code::E0305,
                    r.span,
                    format!("a reference to `{path}` is not allowed: the method's `{input}` may refer to a VAR_IN_OUT or a temporary of a caller, which lives for one call"),
                )
                .label("a reference kept through it")
                .hint(format!("`{input}` is given a VAR_IN_OUT (or a temporary) of a calling method and is read during the call only: pass it on to a method of the block, or copy the value"));
            return Ty::ERROR;
        }
        if r.address_of
            && self.call_variable(v)
            && !(self.instance_args && self.pou().kind != PouKind::Function)
        {
            // `ADR(v)` of a FUNCTION's input or local, or of a VAR_TEMP (a method's VAR and
            // VAR_TEMP are its block's) (CODESYS, TwinCAT): the address is valid during the call
            // (the variable is an automatic variable of the C function; CODESYS and TwinCAT keep
            // them on the stack too); IEC 61131-3's REF() refuses it, CODESYS only warns against
            // letting it out of the call
            self.call_address = Some(r.span);
            return Ty::Known(Type::Ref(Box::new(place.ty)));
        }
        if let Some(why) = self.not_referable(v, r.call_scoped) {
            let path = crate::print::var_ref_text(v);
            // a method's variable as written (`block.Pmin`, not `__M_GET_BLOCK.Pmin`)
            let path = if v.base.name.starts_with(crate::actions::METHOD_PREFIX) {
                path.replacen(&v.base.name, shown_method_var(&v.base.name), 1)
            } else {
                path
            };
            self.a
                .error(
                    code::E0305,
                    r.span,
                    format!("a reference to `{path}` is not allowed: {why}"),
                )
                .label("its address is taken here")
                .hint("refer to a variable of the program or block instance, or to a global (they live as long as the program)");
            return Ty::ERROR;
        }
        Ty::Known(Type::Ref(Box::new(place.ty)))
    }

    /// Finds [`Body::scoped_refs`]: the hidden inputs a call-scoped `LD REF(v)` / `ST __M_M_X` pair
    /// binds to a `v` that may live for one call, or that is reached through another such input
    /// (`AddInterval(block.A)` inside `CalculateBlock(block)`), to a fixpoint.
    pub(super) fn scope_reference_inputs(&mut self, body: &[ast::IlStmt]) {
        use ast::{IlStmt, InstrKind, Op};
        let mut bindings: Vec<(String, &ast::VarRef)> = Vec::new();
        for w in body.windows(2) {
            let (
                IlStmt::Instr(ast::Instruction {
                    kind:
                        InstrKind::Simple {
                            op: Op::Ld,
                            negate: false,
                            operand: Some(ast::Operand::Ref(r)),
                        },
                    ..
                }),
                IlStmt::Instr(ast::Instruction {
                    kind:
                        InstrKind::Simple {
                            op: Op::St,
                            negate: false,
                            operand: Some(ast::Operand::Var(x)),
                        },
                    ..
                }),
            ) = (&w[0], &w[1])
            else {
                continue;
            };
            if let (true, Some(v), true) = (
                r.call_scoped,
                &r.of,
                x.accessors.is_empty() && x.base.name.starts_with(crate::actions::METHOD_PREFIX),
            ) {
                bindings.push((x.base.key(), v));
            }
        }
        if bindings.is_empty() {
            return;
        }
        loop {
            let mut grown = false;
            for (x, v) in &bindings {
                if !self.scoped_refs.contains(x)
                    && (self.scoped_refs.contains(&v.base.key())
                        || self.not_referable(v, false).is_some())
                {
                    self.scoped_refs.insert(x.clone());
                    grown = true;
                }
            }
            if !grown {
                break;
            }
        }
    }

    /// `SIZEOF(x)` / `SIZEOF(T)` (CODESYS, TwinCAT): an unsigned integer typed by its context, as
    /// an integer literal is (CODESYS and TwinCAT give it the smallest unsigned type holding the
    /// size, which then widens to the context: `nSize : INT := SIZEOF(aArr)` is allowed there); the
    /// class is made with the value 1, which fits every integer type (the size itself is C's
    /// `sizeof`, known when the C compiles). A bare name that names no variable of the POU or
    /// global but a type is the type; anything else must resolve as a variable (E1001 otherwise).
    pub(super) fn size_of_operand(&mut self, s: &ast::SizeOfOperand) -> Ty {
        if self.size_of_type(&s.of).is_none() && self.resolve_var(&s.of).ty.is_error() {
            return Ty::ERROR;
        }
        Ty::Lit(self.lits.new_int(1, s.span))
    }

    /// The type `SIZEOF(v)` measures when `v` is a type name (no variable of that name is visible).
    pub(super) fn size_of_type(&self, v: &ast::VarRef) -> Option<Type> {
        if !v.accessors.is_empty() || self.is_visible_var(&v.base.name) {
            return None;
        }
        self.a.model.type_named(&v.base.name)
    }

    /// Whether `name` is a variable of the POU or a global it reaches without VAR_EXTERNAL.
    fn is_visible_var(&self, name: &str) -> bool {
        self.pou().var_position(name).is_some()
            || self.a.free_globals.contains_key(&name.to_ascii_uppercase())
    }

    /// Why the address of `v` may not be taken (`None`: it may). A `call_scoped` reference
    /// (read during one call only, see [`RefOperand::call_scoped`]) may refer to what lives for
    /// one call.
    /// Whether `v` is a variable (an element, a field) that lives for the call of the POU being
    /// checked: any variable of a FUNCTION, or a VAR_TEMP of a program or function block (a
    /// method's VAR and VAR_TEMP are VAR_TEMPs of its block: C locals of the block's body
    /// function, which runs the method); neither located nor reached through a reference, nor a
    /// bit of one.
    fn call_variable(&self, v: &ast::VarRef) -> bool {
        let pou = self.pou();
        through_reference_or_part(v).is_none()
            && pou.var_position(&v.base.name).is_some_and(|i| {
                pou.vars[i].location.is_none()
                    && (pou.kind == PouKind::Function || pou.vars[i].kind == VarKind::Temp)
            })
    }

    /// W1444: `ADR(v)` of a variable that lives for the call ([`Self::call_variable`], at `at`)
    /// stored by `ST o` into something that outlives the call: anything but a plain VAR /
    /// VAR_TEMP of the function, or a VAR_TEMP (a method's VAR) of the program or block.
    pub(super) fn call_address_stored(&mut self, at: crate::Span, o: &ast::Operand) {
        self.call_address = None;
        let pou = self.pou();
        let function = pou.kind == PouKind::Function;
        let local = matches!(o, ast::Operand::Var(x)
        if pou.var_position(&x.base.name).is_some_and(|i| {
            (pou.vars[i].kind == VarKind::Temp || (function && pou.vars[i].kind == VarKind::Local))
                && !x.accessors.iter().any(|a| matches!(a, Accessor::Deref(_)))
        }));
        if local {
            return;
        }
        let target = match o {
            ast::Operand::Var(x) => crate::print::var_ref_text(x),
            other => format!("{other:?}"),
        };
        let name = pou.name.clone();
        let what = if function {
            "a variable of FUNCTION"
        } else {
            "a VAR_TEMP (or a method's variable) of"
        };
        self.a
            .warning(
                code::W1444,
                o.span(),
                format!("`{target}` keeps the address of {what} `{name}`, which lives for one call"),
            )
            .label("the pointer leaves the call here")
            .also(at, "the address of the function's variable")
            .hint("use the pointer inside the call only; copy the value, or point to a variable of a program, a block instance or a global list");
    }

    fn not_referable(&self, v: &ast::VarRef, call_scoped: bool) -> Option<&'static str> {
        if let Some(why) = through_reference_or_part(v) {
            return why;
        }
        let pou = self.pou();
        let var = pou.var_position(&v.base.name).map(|i| &pou.vars[i]);
        match var {
            Some(var) if var.location.is_some() => {
                Some("a located variable lives in the process image, which has no references")
            }
            Some(_) if call_scoped => None,
            Some(_) if pou.kind == PouKind::Function => {
                Some("the variables of a FUNCTION live for one call (IEC 61131-3, 6.4.4.10)")
            }
            Some(var) if var.kind == VarKind::Temp => {
                Some("a VAR_TEMP variable lives for one call (IEC 61131-3, 6.4.4.10)")
            }
            Some(var) if var.kind == VarKind::InOut => {
                Some("a VAR_IN_OUT may stand for a temporary variable of the caller")
            }
            None if pou.kind == PouKind::Function && v.base.is(&pou.name) => {
                Some("the result of a FUNCTION lives for one call")
            }
            _ => None,
        }
    }

    /// `p[i]` on a `POINTER TO T` (CODESYS, TwinCAT): the i-th T after `p^`, read and written as
    /// `p^` is (bounded at run time: c-backend refs.rs); one integer index (E1021 otherwise).
    pub(super) fn pointer_index(
        &mut self,
        place: Place,
        v: &ast::VarRef,
        at: usize,
        ixs: &[ast::Operand],
    ) -> Option<Place> {
        let Type::Ref(target) = place.ty else {
            return None;
        };
        if target.is_error() || ixs.len() != 1 {
            let path = super::places::path_text(v, at);
            let t = self.a.type_name(&Type::Ref(target));
            self.a
                .error(
                    code::E1021,
                    v.span,
                    format!("`{path}` is {t}: a pointer takes one index"),
                )
                .label("indexed here")
                .hint("`p[i]` is the i-th element after `p^`; index a pointer to an array as `p^[i, j]`");
            return None;
        }
        self.index_operand(&ixs[0]);
        Some(Place {
            ty: *target,
            read_only: None,
        })
    }

    /// `r^`: the variable `place` (a reference) refers to, writable whatever `place` is.
    pub(super) fn deref(&mut self, place: Place, v: &ast::VarRef, at: usize) -> Option<Place> {
        match place.ty {
            Type::Ref(target) if !target.is_error() => Some(Place {
                ty: *target,
                read_only: None,
            }),
            other => {
                let path = crate::print::var_ref_text(&ast::VarRef {
                    base: v.base.clone(),
                    accessors: v.accessors.iter().take(at).cloned().collect(),
                    span: v.span,
                });
                let t = self.a.type_name(&other);
                self.a
                    .error(
                        code::E1021,
                        v.span,
                        format!("`{path}` is {t}, not a reference: `^` cannot follow it"),
                    )
                    .label("dereferenced here")
                    .hint("only a REF_TO or POINTER TO variable is read with `^`");
                None
            }
        }
    }
}

/// A method's hidden variable `__M_<METHOD>_<VAR>` as the user wrote it (`<VAR>`, where the method's
/// name holds no `_`; else the hidden name after `__M_`).
fn shown_method_var(hidden: &str) -> &str {
    let rest = hidden
        .strip_prefix(crate::actions::METHOD_PREFIX)
        .unwrap_or(hidden);
    match rest.split_once('_') {
        Some((_, var)) if !var.is_empty() => var,
        _ => rest,
    }
}

/// What `v`'s accessors alone say of its address: `Some(None)` when it goes through a reference
/// (`r^.x`: what a reference refers to outlives it, and has storage of its own), `Some(Some(why))`
/// for a bit or part of a variable, which has no address; `None` when its base variable decides.
pub(super) fn through_reference_or_part(v: &ast::VarRef) -> Option<Option<&'static str>> {
    if v.accessors.iter().any(|a| matches!(a, Accessor::Deref(_))) {
        return Some(None);
    }
    v.accessors
        .iter()
        .any(|a| matches!(a, Accessor::Field(f) if ast::partial_access(&f.name).is_some()))
        .then_some(Some("a bit or part of a variable has no address"))
}
