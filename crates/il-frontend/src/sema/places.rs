//! Operands and variable access inside a body: name lookup (POU variables, the function's result, EN/ENO,
//! globals, enumerated values, `MAIN.x` of a program with one instance), field and index access, literal
//! typing, writability, stores.
//!
//! Input: AST operands. Output: their types (literal variables for untyped literals) and diagnostics.
//! Invariants: each unresolvable name gives one E1001 and the type `Error`; a write to a constant, an
//! input of the POU, an FB instance's output, or a literal is reported once at the operand.

use super::body::{Body, Ty};
use super::model::*;
use super::stdlib::{fb_params, Dir};
use super::typing::{assignable, literal_type, BindError, LitType};
use crate::ast::{self, Access, Accessor, Area, Operand, PouKind, VarKind, VarRef};
use crate::Span;
use diagnostics::{code, Code, Diagnostic, Severity};

/// Why a variable cannot be written (messages are built only when a write is reported).
#[derive(Debug, Clone, Copy)]
pub(super) enum ReadOnly {
    /// A CONSTANT variable (declared at `decl`).
    Constant { decl: Span },
    /// A VAR_INPUT of the POU itself (or EN: no declaration).
    PouInput { decl: Option<Span> },
    /// An output of an FB instance: the field access `accessors[at]`.
    FbOutput { at: usize },
    /// An enumerated value.
    EnumValue,
}

const HINT_CONST: &str = "write another variable, or drop CONSTANT from its declaration";
const HINT_INPUT: &str = "write a local copy, or declare the variable VAR_IN_OUT / VAR_OUTPUT";
const HINT_INPUT_WRITE: &str = "IEC 61131-3 makes inputs read-only inside the POU; ladderc, like CODESYS, \
     TwinCAT and matiec, writes the POU's own copy (the caller's variable is not changed). For portable \
     code write a local copy, or declare it VAR_IN_OUT / VAR_OUTPUT";
const HINT_FB_OUTPUT: &str =
    "outputs of an FB instance are written by the instance itself; read them (`LD inst.Q` in IL, `x := inst.Q;` in ST), or give the block an input";
const HINT_ENUM: &str = "store into a variable";

/// A resolved variable access.
#[derive(Debug, Clone)]
pub(super) struct Place {
    pub(super) ty: Type,
    pub(super) read_only: Option<ReadOnly>,
}

impl Place {
    fn error() -> Place {
        Place {
            ty: Type::Error,
            read_only: None,
        }
    }
}

impl Body<'_, '_> {
    /// The type of an operand that is read.
    pub(super) fn read_operand(&mut self, o: &Operand) -> Ty {
        match o {
            Operand::Literal(l) => self.literal(l),
            Operand::Var(v) => Ty::Known(self.resolve_var(v).ty),
            Operand::Address(a) => Ty::Known(Type::Elementary(Location::of(a).elementary())),
            Operand::EnumValue(e) => Ty::Known(self.enum_value(&e.type_name, &e.value)),
            Operand::Ref(r) => self.reference_operand(r),
            Operand::SizeOf(s) => self.size_of_operand(s),
            Operand::Mem(m) => self.mem_operand(m),
        }
    }

    fn literal(&mut self, l: &ast::Literal) -> Ty {
        self.a.check_single_byte(l);
        match literal_type(l) {
            Ok(LitType::Known(t)) => Ty::Known(t),
            Ok(LitType::Int(v)) => Ty::Lit(self.lits.new_int(v, l.span)),
            Ok(LitType::Real(v)) => Ty::Lit(self.lits.new_real(v, l.span)),
            Ok(LitType::Char(wide)) => Ty::Lit(self.lits.new_char(wide, l.span)),
            Err(e) => {
                self.a
                    .error(code::E1017, l.span, e.message)
                    .label("out of range")
                    .hint(e.hint);
                Ty::ERROR
            }
        }
    }

    fn enum_value(&mut self, type_name: &ast::Ident, value: &ast::Ident) -> Type {
        let Some(&id) = self.a.type_names.get(&type_name.key()) else {
            // one cause, one error: its first use reported once every body is checked, with the
            // count of the others (`Analyzer::report_unknown_enums`)
            let span = type_name.span;
            if !self.a.silent && self.a.unknown_enum_uses.insert((span.file, span.start)) {
                let key = type_name.key();
                match self.a.unknown_enums.iter_mut().find(|e| e.0 == key) {
                    Some(e) => e.3 += 1,
                    None => self
                        .a
                        .unknown_enums
                        .push((key, type_name.name.clone(), span, 0)),
                }
            }
            return Type::Error;
        };
        match &self.a.model.types[id.0 as usize].def {
            UserTypeDef::Enum { values, .. } if values.iter().any(|(n, _)| value.is(n)) => {
                Type::Enum(id)
            }
            UserTypeDef::Enum { .. } => {
                self.a
                    .error(
                        code::E1001,
                        value.span,
                        format!("`{}` is not a value of {}", value.name, type_name.name),
                    )
                    .label("unknown enumerated value")
                    .hint(format!(
                        "use one of the values declared for {}",
                        type_name.name
                    ));
                Type::Error
            }
            _ => {
                self.a
                    .error(
                        code::E1001,
                        type_name.span,
                        format!("`{}` is not an enumeration", type_name.name),
                    )
                    .label("not an enumerated type")
                    .hint("Type#value needs an enumerated type");
                Type::Error
            }
        }
    }

    /// The implicit (inline) enumerations the variables of the POU being checked are of (also as
    /// array elements; an inherited variable and a method's hidden ones are the POU's variables).
    /// Whether type `name` is a B&R program's private type (`Conveyor.MachineStateEnum`, named so
    /// by ladderc's B&R reader: a `.typ` file in a program folder, whose name another declaration
    /// also takes) of a program other than the current POU: its values are not seen here, as
    /// Automation Studio keeps a program's local data types to it (round 34).
    fn private_to_another_program(&self, name: &str) -> bool {
        let Some((program, _)) = name.split_once('.') else {
            return false;
        };
        let own = self.pou().name.as_str();
        let own = own.strip_suffix(crate::BR_PROGRAM_SUFFIX).unwrap_or(own);
        !program.eq_ignore_ascii_case(own)
            && self.a.pou_names.keys().any(|k| {
                k.strip_suffix(crate::BR_PROGRAM_SUFFIX).unwrap_or(k)
                    == program.to_ascii_uppercase()
            })
    }

    fn own_implicit_enums(&self) -> Vec<TypeId> {
        fn enum_of(t: &Type) -> Option<TypeId> {
            match t {
                Type::Enum(id) => Some(*id),
                Type::Array { element, .. } => enum_of(element),
                _ => None,
            }
        }
        self.pou()
            .vars
            .iter()
            .filter_map(|v| enum_of(&v.ty))
            .collect()
    }

    /// The type of an operand that is written; reports literals, constants and read-only variables.
    pub(super) fn write_place(&mut self, o: &Operand, what: &str) -> Type {
        match o {
            Operand::Var(v) => {
                let p = self.resolve_var(v);
                self.note_written(v);
                // Only a FUNCTION has a result variable (looked up only there: the names table is big).
                if self.pou().kind == PouKind::Function
                    && self.a.model.names.get(&v.base.span) == Some(&NameRef::FunctionResult)
                {
                    self.result_written = true;
                }
                if let Some(ro) = p.read_only {
                    self.report_read_only(v, ro, what);
                }
                p.ty
            }
            Operand::Address(a) => {
                if a.area == Area::Input {
                    self.a
                        .error(
                            code::E1026,
                            a.span,
                            format!("{what} cannot write an input address"),
                        )
                        .label("%I is read-only")
                        .hint("write an output (%Q) or memory (%M) address");
                }
                Type::Elementary(Location::of(a).elementary())
            }
            Operand::Literal(_)
            | Operand::EnumValue(_)
            | Operand::Ref(_)
            | Operand::SizeOf(_)
            | Operand::Mem(_) => {
                self.a
                    .error(
                        code::E1026,
                        o.span(),
                        format!("{what} cannot write a constant value"),
                    )
                    .label("not a variable")
                    .hint("store into a variable");
                Type::Error
            }
        }
    }

    /// Records the declaration `v` (or the array or structure it is part of) writes in
    /// [`crate::sema::Model::written`]: the POU's own variable, or the global its `VAR_EXTERNAL` or
    /// its name binds (a member of a named list, `GVL.x`, is left out).
    fn note_written(&mut self, v: &VarRef) {
        let pou = self.pou;
        let written = match self.pou().var_position(&v.base.name) {
            Some(index) => match self.pou().externals.iter().find(|(i, _)| *i == index) {
                Some(&(_, global)) => WrittenVar::Global(global),
                None => WrittenVar::Pou { pou, index },
            },
            None => match self.a.free_globals.get(&v.base.key()) {
                Some(&i) => WrittenVar::Global(GlobalRef::Free(i)),
                None => return,
            },
        };
        self.a.model.written.insert(written);
    }

    fn report_read_only(&mut self, v: &VarRef, ro: ReadOnly, what: &str) {
        let qualified = self.is_list_access(v).then(|| path_text(v, 1));
        let name = qualified.as_ref().unwrap_or(&v.base.name);
        let pou = self.pou().name.clone();
        let hidden_field = v
            .accessors
            .iter()
            .any(|a| matches!(a, crate::ast::Accessor::Field(f) if f.name.starts_with("__")));
        if let ReadOnly::FbOutput { at } = ro {
            let result_field = v.accessors.len() == at + 2
                && matches!(&v.accessors[at + 1], crate::ast::Accessor::Field(f)
                    if f.name.starts_with(crate::actions::METHOD_PREFIX)
                        || f.is(crate::st::interface_vars::TAG));
            if result_field {
                // a call through an interface that is an instance's output (`d.itf.Get()`)
                // writes the interface's hidden result field (`d.itf.__M_GET`), and its tag when
                // it holds no instance (to 0, reading the NULL reference that reports it), not
                // the output itself: assigning it writes its references too, still E1015
                return;
            }
        }
        if let ReadOnly::PouInput { decl: Some(decl) } = ro {
            if v.base.name.starts_with(crate::actions::FLAG_PREFIX)
                || v.base.name.starts_with(crate::actions::METHOD_PREFIX)
                || hidden_field
            {
                // the hidden flag of an action called from another POU, reset by the action itself;
                // a method's hidden input, set by a call of the method inside its block; the
                // hidden fields of an interface input (its tag, a method's result) set by a call
                // through it
                return;
            }
            // IEC 61131-3 forbids it; CODESYS, TwinCAT and matiec (so Beremiz and OpenPLC projects)
            // accept it and write the POU's own copy of the input: so does ladderc, with a warning
            // at the first write of each input (the others write the same copy)
            // FB_init / FB_reinit storing their extra inputs into the block's own inputs
            // (`THIS^.src := src;`): the documented TwinCAT/CODESYS way to give an instance its
            // initial inputs, run once before its first call (`st::fb_init::is_instance_setup`)
            if self.in_instance_setup {
                return;
            }
            if self.a.silent || !self.a.written_inputs.insert(decl) {
                return;
            }
            drop(
                self.a
                    .warning(
                        code::W1411,
                        v.span,
                        format!("`{name}` is an input of `{pou}`, written inside it"),
                    )
                    .label(format!("{what} writes it here"))
                    .also(decl, "declared VAR_INPUT here")
                    .hint(HINT_INPUT_WRITE),
            );
            return;
        }
        if let ReadOnly::Constant { decl } = ro {
            if v.base.span == decl {
                // written at its own declared name: its initial value, computed when the
                // instance is initialised (`VAR_INPUT CONSTANT p : FB_X := (i := THIS^);`, an
                // instance's parameter, `st::pou_inits`), not a write of the program
                return;
            }
        }
        let (code, message, decl, hint): (Code, String, Option<(Span, &str)>, &str) = match ro {
            ReadOnly::Constant { decl } => (
                code::E1014,
                format!("`{name}` is a constant"),
                Some((decl, "declared CONSTANT here")),
                HINT_CONST,
            ),
            ReadOnly::PouInput { decl } => (
                code::E1015,
                format!("`{name}` is an input of `{pou}`, read-only inside it"),
                decl.map(|d| (d, "declared VAR_INPUT here")),
                HINT_INPUT,
            ),
            ReadOnly::FbOutput { at } => {
                let param = match &v.accessors[at] {
                    Accessor::Field(f) => f.name.clone(),
                    Accessor::Index(_) | Accessor::Deref(_) => String::new(),
                };
                (
                    code::E1015,
                    format!(
                        "`{param}` is an output of FB instance `{}`",
                        path_text(v, at)
                    ),
                    None,
                    HINT_FB_OUTPUT,
                )
            }
            ReadOnly::EnumValue => (
                code::E1026,
                format!("`{name}` is an enumerated value, not a variable"),
                None,
                HINT_ENUM,
            ),
        };
        let mut d = self
            .a
            .error(code, v.span, message)
            .label(format!("{what} writes it here"));
        if let Some((span, m)) = decl {
            d = d.also(span, m);
        }
        drop(d.hint(hint));
    }

    /// Stores (or passes) a value of type `from` into `to`; binds untyped literals.
    pub(super) fn coerce_store(&mut self, from: &Ty, to: &Type, target: Span, at: Span) -> bool {
        self.coerce(from, to, at, |b, f, t| {
            b.a.error(code::E1006, at, format!("cannot store {f} into {t}"))
                .label(format!("the current result is {f}"))
                .also(target, format!("this is {t}"))
                .hint(conversion_hint(f, t));
        })
    }

    /// Checks `from` against `to`; calls `mismatch(from, to)` to report a type mismatch.
    pub(super) fn coerce(
        &mut self,
        from: &Ty,
        to: &Type,
        at: Span,
        mismatch: impl FnOnce(&mut Self, &str, &str),
    ) -> bool {
        let n = self.norm(from);
        match n {
            Ty::Known(t) => {
                if assignable(&t, to) || super::refs::substitutes(&self.a.model, &t, to, false) {
                    return true;
                }
                if super::typing::pointer_reinterprets(&t, to, &self.a.model) {
                    self.pointer_reinterpreted(&t, to, at);
                    return true;
                }
                if super::bit_arith::assignable_counted(&t, to) {
                    let bits = [&t, to]
                        .into_iter()
                        .filter_map(|x| x.elementary())
                        .find(|e| super::bit_arith::counted_as(*e).is_some());
                    if let Some(b) = bits {
                        self.bit_string_counted(b, at);
                    }
                    return true;
                }
                if super::loose_enum::assignable_loose(&self.a.model, &t, to) {
                    let e = if matches!(t, Type::Enum(_)) { &t } else { to };
                    self.enum_as_integer(&e.clone(), at);
                    return true;
                }
                let (f, tt) = (self.a.type_name(&t), self.a.type_name(to));
                mismatch(self, &f, &tt);
                false
            }
            Ty::Lit(v) => match self.lits.bind(v, to) {
                Ok(()) => true,
                Err(BindError::Range { value, span }) => {
                    let t = self.a.type_name(to);
                    let bounds = match to {
                        Type::Subrange { lower, upper, .. } => Some((**lower, **upper)),
                        _ => to.elementary().and_then(|e| e.int_range()),
                    };
                    let range = bounds
                        .map(|(lo, hi)| format!("{t} holds {lo}..{hi}"))
                        .unwrap_or_else(|| format!("the value must fit {t}"));
                    let _ = at;
                    self.a
                        .error(
                            code::E1017,
                            span,
                            format!("literal {value} does not fit {t}"),
                        )
                        .label(format!("used as {t}"))
                        .hint(format!("{range}; use a wider type or a value in range"));
                    false
                }
                Err(BindError::RealRange { span }) => {
                    let t = self.a.type_name(to);
                    self.a
                        .error(
                            code::E1017,
                            span,
                            format!("real literal beyond the range of {t}"),
                        )
                        .label(format!("used as {t}"))
                        .hint(format!(
                            "{t} holds magnitudes up to 3.4028235E38; write a smaller value or use LREAL"
                        ));
                    false
                }
                // CODESYS, TwinCAT: an integer literal into an enumeration without {attribute
                // 'strict'} (W1439)
                Err(BindError::Kind { .. })
                    if super::loose_enum::is_loose(&self.a.model, to)
                        && !self.lits.is_real(v)
                        && self.lits.bind(v, &Type::DINT).is_ok() =>
                {
                    self.enum_as_integer(to, at);
                    true
                }
                Err(BindError::Kind { .. }) => {
                    let (f, t) = (self.lits.describe(v), self.a.type_name(to));
                    mismatch(self, f, &t);
                    false
                }
            },
        }
    }

    /// If the operand is an FB instance, its type (without reporting anything else).
    pub(super) fn fb_instance_operand(&mut self, o: &Operand) -> Option<FbType> {
        let Operand::Var(v) = o else {
            return None;
        };
        let was = self.a.silent;
        self.a.silent = true;
        let p = self.resolve_var(v);
        self.a.silent = was;
        match p.ty {
            Type::Fb(fb) => Some(fb),
            _ => None,
        }
    }

    /// Whether `v` is `THIS^` in a function block that declares no variable `THIS`.
    fn is_this_instance(&self, v: &VarRef) -> bool {
        let pou = self.pou();
        v.base.is("THIS")
            && matches!(v.accessors.first(), Some(Accessor::Deref(_)))
            && pou.kind == crate::ast::PouKind::FunctionBlock
            && pou.var_position(&v.base.name).is_none()
    }

    /// Resolves a variable access (reports undeclared names and invalid accesses once).
    pub(super) fn resolve_var(&mut self, v: &VarRef) -> Place {
        let (mut place, skip) = match self.list_member(v) {
            // `THIS^` (edition 3, CODESYS, TwinCAT): the function block instance running the body,
            // whole (`REF(THIS^)`, `itf := THIS^`; its members are lowered to plain names)
            _ if self.is_this_instance(v) => (
                Place {
                    ty: Type::Fb(FbType::User(self.pou)),
                    read_only: None,
                },
                1,
            ),
            Some(Some(p)) => (p, 1),
            Some(None) => return Place::error(),
            None => match self.lookup_base(
                &v.base,
                v.accessors.is_empty(),
                // (a hidden member: `PRG.__MD_M_X`, a method's default the call passes)
                matches!(v.accessors.first(), Some(crate::ast::Accessor::Field(f)) if f.name.starts_with("__")),
            ) {
                Some(p) => (p, 0),
                None => return Place::error(),
            },
        };
        for (at, acc) in v.accessors.iter().enumerate().skip(skip) {
            if place.ty.is_error() {
                return Place::error();
            }
            match acc {
                Accessor::Field(f) => {
                    place = match self.field(&place, v, at, f) {
                        Some(p) => p,
                        None => return Place::error(),
                    };
                }
                // `p[i]` on a `POINTER TO T` (CODESYS, TwinCAT): refs.rs
                Accessor::Index(ixs) if matches!(place.ty, Type::Ref(_)) => {
                    place = match self.pointer_index(place, v, at, ixs) {
                        Some(p) => p,
                        None => return Place::error(),
                    };
                }
                // edition 3: `s[i]`, the i-th character of a STRING (a CHAR) or of a WSTRING (a
                // WCHAR), 1-based; checked against LEN(s) at run time
                Accessor::Index(ixs) if matches!(place.ty, Type::String { .. }) => {
                    let Type::String { wide, len } = place.ty else {
                        return Place::error();
                    };
                    if ixs.len() != 1 {
                        let path = path_text(v, at);
                        self.a
                            .error(
                                code::E1021,
                                v.span,
                                format!(
                                    "`{path}` is a string: one index gives a character, {} are given",
                                    ixs.len()
                                ),
                            )
                            .label("wrong number of indexes")
                            .hint("write s[i] for the i-th character (1 is the first)");
                        return Place::error();
                    }
                    self.index_operand(&ixs[0]);
                    // CODESYS, TwinCAT: the BYTE (WSTRING: WORD) at offset i, 0 the first, of
                    // the declared length and its terminator (CODESYS help "Data type: POINTER
                    // TO", "Index access to STRING"); checked against 0..length at run time
                    if super::is_codesys_file(ixs[0].span().file) {
                        let d = Dim {
                            lower: 0,
                            upper: i128::from(len.max(1)),
                        };
                        self.constant_byte_index_in_bounds(&ixs[0], &d, v, at);
                        self.a.model.byte_indexes.insert(ixs[0].span());
                        place = Place {
                            ty: Type::Elementary(if wide {
                                Elementary::Word
                            } else {
                                Elementary::Byte
                            }),
                            read_only: place.read_only,
                        };
                        continue;
                    }
                    let d = Dim {
                        lower: 1,
                        upper: i128::from(len.max(1)),
                    };
                    self.constant_index_in_bounds(&ixs[0], &d, v, at, true);
                    place = Place {
                        ty: Type::Elementary(if wide {
                            Elementary::Wchar
                        } else {
                            Elementary::Char
                        }),
                        read_only: place.read_only,
                    };
                }
                Accessor::Index(ixs) => {
                    let Type::Array { dims, element } = &place.ty else {
                        let path = path_text(v, at);
                        let t = self.a.type_name(&place.ty);
                        self.a
                            .error(
                                code::E1021,
                                v.span,
                                format!("`{path}` is {t}, not an array"),
                            )
                            .label("indexed here")
                            .hint("only arrays take [index]");
                        return Place::error();
                    };
                    let (ndims, element) = (dims.len(), (**element).clone());
                    if ndims != ixs.len() {
                        let path = path_text(v, at);
                        self.a
                            .error(
                                code::E1021,
                                v.span,
                                format!(
                                    "`{path}` has {ndims} dimension(s) but {} index(es) are given",
                                    ixs.len()
                                ),
                            )
                            .label("wrong number of indexes")
                            .hint("give one index per dimension: a[i, j]");
                        return Place::error();
                    }
                    for (ix, d) in ixs.iter().zip(dims.iter()) {
                        self.index_operand(ix);
                        self.constant_index_in_bounds(ix, d, v, at, false);
                    }
                    place = Place {
                        ty: element,
                        read_only: place.read_only,
                    };
                }
                Accessor::Deref(_) => {
                    place = match self.deref(place, v, at) {
                        Some(p) => p,
                        None => return Place::error(),
                    };
                }
            }
        }
        place
    }

    /// E1050 when the index is an integer literal outside the dimension's bounds (IEC 61131-3:
    /// an error; a computed index is checked at run time); for a string's character `s[i]`
    /// (`character`), outside 1..the declared length (a computed one is checked against LEN(s)
    /// at run time).
    fn constant_index_in_bounds(
        &mut self,
        ix: &Operand,
        d: &Dim,
        v: &VarRef,
        at: usize,
        character: bool,
    ) {
        let Operand::Literal(l) = ix else { return };
        let ast::LiteralKind::Int(k) = l.kind else {
            return;
        };
        if (d.lower..=d.upper).contains(&k) {
            return;
        }
        let path = path_text(v, at);
        let (message, label, hint) = if character {
            (
                format!(
                    "character {k} is outside the declared length 1..{} of `{path}`",
                    d.upper
                ),
                "outside the string",
                format!(
                    "s[i] is the i-th character, from 1 to the string's length; declare `{path}` longer to hold {k} characters"
                ),
            )
        } else {
            (
                format!(
                    "index {k} is outside the bounds {}..{} of `{path}`",
                    d.lower, d.upper
                ),
                "outside the array",
                format!(
                    "index with a value from {} to {}, or declare the array with bounds that hold {k}",
                    d.lower, d.upper
                ),
            )
        };
        self.a
            .error(code::E1050, l.span, message)
            .label(label)
            .hint(hint);
    }

    /// E1050 when the offset of a CODESYS/TwinCAT `s[i]` is an integer literal outside 0..the
    /// declared length (the place of the terminator the last).
    fn constant_byte_index_in_bounds(&mut self, ix: &Operand, d: &Dim, v: &VarRef, at: usize) {
        let Operand::Literal(l) = ix else { return };
        let ast::LiteralKind::Int(k) = l.kind else {
            return;
        };
        if (d.lower..=d.upper).contains(&k) {
            return;
        }
        let path = path_text(v, at);
        self.a
            .error(
                code::E1050,
                l.span,
                format!(
                    "offset {k} is outside the declared length 0..{} of `{path}`",
                    d.upper
                ),
            )
            .label("outside the string")
            .hint(format!(
                "in CODESYS and TwinCAT s[i] is the byte at offset i, 0 the first; declare `{path}` longer to hold offset {k}"
            ));
    }

    /// Checks one index of an array (or pointer) access: an integer.
    pub(super) fn index_operand(&mut self, ix: &Operand) {
        let t = self.read_operand(ix);
        let n = self.norm(&t);
        match n {
            Ty::Known(k) if k.is_error() || k.is_integer() => {}
            // CODESYS, TwinCAT: a bit string indexes as its unsigned integer (W1436)
            Ty::Known(Type::Elementary(e)) if super::bit_arith::counted_as(e).is_some() => {
                self.bit_string_counted(e, ix.span());
            }
            // CODESYS, TwinCAT: an enumeration without {attribute 'strict'} indexes as its
            // number (W1439)
            Ty::Known(t) if super::loose_enum::is_loose(&self.a.model, &t) => {
                self.enum_as_integer(&t, ix.span());
            }
            // a strict one too: {attribute 'strict'} forbids arithmetic and storing other values
            // (Infosys, Attribute 'strict'), not indexing (ISIS's `fParameters[eRWParameter.X]`)
            Ty::Known(t @ Type::Enum(_)) => {
                self.enum_as_integer(&t, ix.span());
            }
            Ty::Lit(var) => {
                // An index literal is a DINT unless it does not fit.
                if self.lits.bind(var, &Type::DINT).is_err() {
                    self.a
                        .error(code::E1021, ix.span(), "an array index must be an integer")
                        .label("not an integer")
                        .hint("index with an integer variable or literal");
                }
            }
            other => {
                let d = self.describe(&other);
                let hint = match &other {
                    Ty::Known(Type::Elementary(e)) if e.is_real() => {
                        format!("convert the index: {}_TO_DINT(...)", e.name())
                    }
                    _ => "convert the index to an integer: TO_DINT(...)".to_string(),
                };
                self.a
                    .error(
                        code::E1021,
                        ix.span(),
                        format!("an array index must be an integer, not {d}"),
                    )
                    .label(format!("this is {d}"))
                    .hint(hint);
            }
        }
    }

    /// Whether `v` is a qualified access to a global variable list, `GVL.x` (CODESYS, TwinCAT): its base
    /// names a list and nothing else visible in the POU (a variable of that name wins).
    pub(super) fn is_list_access(&self, v: &VarRef) -> bool {
        let base = &v.base;
        if self.a.model.global_lists.is_empty() || self.a.model.global_list(&base.name).is_none() {
            return false;
        }
        let pou = self.pou();
        !(pou.var_position(&base.name).is_some()
            || (pou.kind == PouKind::Function && base.is(&pou.name))
            || (pou.kind != PouKind::Program && (base.is("EN") || base.is("ENO")))
            || self.a.free_globals.contains_key(&base.key())
            || self.a.find_global(&base.name).is_some())
    }

    /// A qualified access `GVL.x` to a member of a global variable list: `None` when `v` is not one,
    /// `Some(None)` when it is but names no member (reported: E1001 at the member, or at the list when
    /// no member is named).
    fn list_member(&mut self, v: &VarRef) -> Option<Option<Place>> {
        if !self.is_list_access(v) {
            return None;
        }
        let list = self.a.model.global_list(&v.base.name)?.clone();
        let Some(Accessor::Field(m)) = v.accessors.first() else {
            self.a
                .error(
                    code::E1001,
                    v.base.span,
                    format!("`{}` is a global variable list, not a variable", list.name),
                )
                .label("a list name")
                .also(list.span, "list declared here")
                .hint(format!(
                    "name one of its variables: {}.<variable>",
                    list.name
                ));
            return Some(None);
        };
        let Some(r) = self.a.model.list_member(&list, &m.name) else {
            let names: Vec<&str> = list
                .members
                .iter()
                .map(|&r| self.a.model.global(r).name.as_str())
                .collect();
            let shown = names.iter().take(8).copied().collect::<Vec<_>>().join(", ");
            let more = if names.len() > 8 { ", ..." } else { "" };
            self.a
                .error(
                    code::E1001,
                    m.span,
                    format!(
                        "global variable list `{}` has no variable `{}`",
                        list.name, m.name
                    ),
                )
                .label("not in this list")
                .also(list.span, "list declared here")
                .hint(format!("{} declares: {shown}{more}", list.name));
            return Some(None);
        };
        self.note_name(m.span, NameRef::Global(r));
        let g = self.a.model.global(r);
        Some(Some(Place {
            ty: g.ty.clone(),
            read_only: g.constant.then_some(ReadOnly::Constant { decl: g.span }),
        }))
    }

    /// The variable a name refers to in this POU.
    fn lookup_base(&mut self, base: &ast::Ident, plain: bool, hidden: bool) -> Option<Place> {
        let kind = self.pou().kind;
        let found = self
            .pou()
            .var_position(&base.name)
            .map(|index| (index, &self.pou().vars[index]))
            .map(|(index, var)| {
                let read_only = if var.constant {
                    Some(ReadOnly::Constant { decl: var.span })
                } else if var.kind == VarKind::Input {
                    Some(ReadOnly::PouInput {
                        decl: Some(var.span),
                    })
                } else {
                    None
                };
                (index, var.ty.clone(), read_only)
            });
        if let Some((index, ty, read_only)) = found {
            self.note_name(base.span, NameRef::Var(index));
            return Some(Place { ty, read_only });
        }
        if kind == PouKind::Function && base.is(&self.pou().name) {
            self.note_name(base.span, NameRef::FunctionResult);
            return Some(Place {
                ty: self.pou().return_type.clone().unwrap_or(Type::Error),
                read_only: None,
            });
        }
        if kind != PouKind::Program && (base.is("EN") || base.is("ENO")) {
            let en = base.is("EN");
            self.note_name(base.span, if en { NameRef::En } else { NameRef::Eno });
            return Some(Place {
                ty: Type::BOOL,
                read_only: en.then_some(ReadOnly::PouInput { decl: None }),
            });
        }
        if self.a.ambiguous_global(base) {
            return None;
        }
        if let Some(&i) = self.a.free_globals.get(&base.key()) {
            self.note_name(base.span, NameRef::Global(GlobalRef::Free(i)));
            let g = &self.a.model.globals[i];
            return Some(Place {
                ty: g.ty.clone(),
                read_only: g.constant.then_some(ReadOnly::Constant { decl: g.span }),
            });
        }
        if plain {
            if let Some(mut found) = self.a.enum_values.get(&base.key()).cloned() {
                if found.len() > 1 {
                    // an implicit enumeration is valid only in its own POU (CODESYS, "Data Type:
                    // Implicit Enumeration"): those of other POUs do not make a value ambiguous
                    let own = self.own_implicit_enums();
                    let visible: Vec<(TypeId, usize)> = found
                        .iter()
                        .copied()
                        .filter(|(id, _)| {
                            let n = &self.a.model.types[id.0 as usize].name;
                            let implicit = n.starts_with("__ENUM_")
                                || crate::st::implicit_enums::is_implicit(n);
                            (!implicit || own.contains(id)) && !self.private_to_another_program(n)
                        })
                        .collect();
                    if !visible.is_empty() && visible.len() < found.len() {
                        found = visible;
                    }
                }
                if found.len() > 1 {
                    let names: Vec<String> = found
                        .iter()
                        .map(|(id, _)| self.a.model.types[id.0 as usize].name.clone())
                        .collect();
                    // an implicit enumeration (`state : (IDLE, RUN);`) has no name to write
                    // before the value: only the context can tell (ST: `state := IDLE`,
                    // `state = IDLE`, `CASE state OF IDLE:`); CODESYS warns against writing the
                    // internal name `IMPLICIT_ENUM_<POU>_<variable>`
                    let implicit = names.iter().any(|n| {
                        n.starts_with("__ENUM_") || crate::st::implicit_enums::is_implicit(n)
                    });
                    if implicit {
                        self.a
                            .error(
                                code::E1051,
                                base.span,
                                format!(
                                    "`{}` is a value of several enumerations, and nothing here tells which",
                                    base.name
                                ),
                            )
                            .label("ambiguous: an implicit enumeration declares it")
                            .hint(format!(
                                "use it where its enumeration is known (`state := {0}`, `state = {0}`, `CASE state OF {0}:`), or declare a named TYPE and write Type#{0}",
                                base.name
                            ));
                        return None;
                    }
                    self.a
                        .error(
                            code::E1001,
                            base.span,
                            format!("`{}` is a value of several enumerations", base.name),
                        )
                        .label("ambiguous")
                        .hint(format!(
                            "write Type#{} with one of: {}",
                            base.name,
                            names.join(", ")
                        ));
                    return None;
                }
                self.note_name(
                    base.span,
                    NameRef::EnumValue {
                        ty: found[0].0,
                        index: found[0].1,
                    },
                );
                return Some(Place {
                    ty: Type::Enum(found[0].0),
                    read_only: Some(ReadOnly::EnumValue),
                });
            }
        }
        if let Some(place) = self.implicit_external(base) {
            return Some(place);
        }
        let program = self
            .a
            .pou_names
            .get(&base.key())
            .copied()
            .filter(|id| self.a.model.pous[id.0 as usize].kind == PouKind::Program);
        if let (Some(id), false) = (program, plain) {
            if self.program_instances(id) == 1 {
                return Some(self.program_place(base, id, hidden));
            }
        }
        if !self.a.silent
            && !self
                .a
                .undeclared_at
                .insert((base.span.file, base.span.start))
        {
            return None;
        }
        if program.is_some() && !self.a.silent {
            // `MAIN.x` (CODESYS/TwinCAT): one error per POU and program, its other uses unreported
            let key = (self.pou.0, format!("program {}", base.key()), String::new());
            if !self.a.internal_accessed.insert(key) {
                return None;
            }
        } else if !self.a.silent {
            // an undeclared name: one error per POU and name, at its first use (as C compilers
            // report an undeclared identifier once per function): a file of 51 undeclared names
            // used 109 times gives 51 errors
            let key = (
                self.pou.0,
                format!("undeclared {}", base.key()),
                String::new(),
            );
            if !self.a.internal_accessed.insert(key) {
                return None;
            }
        }
        let hint = self.similar_name(&base.name);
        let message = match program {
            Some(_) if plain => format!("`{}` is a program, not a variable", base.name),
            Some(id) => {
                let n = self.program_instances(id);
                let which = match n {
                    0 => "no instance".to_string(),
                    1 => "one instance".to_string(),
                    n => format!("{n} instances"),
                };
                format!(
                    "`{}` is a program with {which} in the configuration, not one variable (its other uses in this POU are not reported)",
                    base.name
                )
            }
            None => format!("undeclared name `{}`", base.name),
        };
        self.a
            .error(code::E1001, base.span, message)
            .label("not declared in this POU")
            .hint(hint);
        None
    }

    /// A configuration or resource global used without a `VAR_EXTERNAL` declaration, as CODESYS and
    /// TwinCAT allow (a global variable list is visible in every POU). IEC 61131-3 requires the
    /// declaration; ladderc accepts the use and declares the external itself: the POU gets a
    /// `VAR_EXTERNAL` of the global's name and type (CONSTANT when the global is), and note W1410 says
    /// so once per POU and global.
    fn implicit_external(&mut self, base: &ast::Ident) -> Option<Place> {
        let r = self.a.find_global(&base.name)?;
        let g = self.a.model.global(r).clone();
        let pou_name = self.pou().name.clone();
        let kind = self.pou().kind;
        let pou = &mut self.a.model.pous[self.pou.0 as usize];
        let index = pou.vars.len();
        let mut vars = std::mem::take(&mut pou.vars);
        vars.push(Variable {
            name: g.name.clone(),
            span: base.span,
            kind: VarKind::External,
            ty: g.ty.clone(),
            constant: g.constant,
            retain: false,
            location: None,
            init: None,
            edge: None,
        });
        pou.set_vars(vars);
        pou.externals.push((index, r));
        let what = match kind {
            PouKind::Program => "program",
            PouKind::FunctionBlock => "function block",
            PouKind::Function => "function",
        };
        let ty = self.a.type_name(&g.ty);
        let constant = if g.constant { " CONSTANT" } else { "" };
        // given in the silent pass too: the declaration made here is found by every later use;
        // not of a POU ladderc made (`__FBINIT_ALL`, the global lists' computed initial values:
        // IEC names cannot hold `__`), which the user cannot declare anything in
        let hidden = pou_name.starts_with("__");
        self.a.diags.extend((!hidden).then(|| {
            Diagnostic::new(
                code::W1410,
                Severity::Note,
                format!(
                    "global `{}` is used in {what} `{pou_name}` without a VAR_EXTERNAL declaration",
                    g.name
                ),
            )
            .at(base.span)
            .with_primary_label("used here as a global")
            .with_label(g.span, "global declared here")
            .with_hint(format!(
                "CODESYS and TwinCAT allow this; IEC 61131-3 needs `VAR_EXTERNAL{constant} {} : {ty}; END_VAR` in the POU",
                g.name
            ))
        }));
        self.note_name(base.span, NameRef::Var(index));
        Some(Place {
            ty: g.ty,
            read_only: g.constant.then_some(ReadOnly::Constant { decl: g.span }),
        })
    }

    /// How many instances program `id` has: 1 without a configuration (it runs alone), else its
    /// `PROGRAM` declarations in every resource.
    /// A program the configuration does not instantiate has one instance of its own, which only
    /// other POUs' calls run (`sema::program_calls`).
    pub(super) fn program_instances(&self, id: PouId) -> usize {
        if self.a.model.configurations.is_empty() {
            return 1;
        }
        self.a
            .model
            .configurations
            .iter()
            .flat_map(|c| &c.resources)
            .flat_map(|r| &r.programs)
            .filter(|p| p.pou == id)
            .count()
            .max(1)
    }

    /// `MAIN.x` from any POU (CODESYS, TwinCAT): the one instance of program `id`, whose variables the
    /// field access reads and writes; warning W1413 once per POU and program.
    fn program_place(&mut self, base: &ast::Ident, id: PouId, hidden: bool) -> Place {
        if !self.a.model.programs_used_by_name.contains(&id) {
            self.a.model.programs_used_by_name.push(id);
        }
        let key = (
            self.pou.0,
            format!("program {}", base.key()),
            "W1413".to_string(),
        );
        if !self.a.silent && !hidden && self.a.internal_accessed.insert(key) {
            let name = self.a.model.pous[id.0 as usize].name.clone();
            self.a
                .warning(
                    code::W1413,
                    base.span,
                    format!("a variable of program `{name}` used as `{}.x` (a CODESYS and TwinCAT extension: the program's one instance)", base.name),
                )
                .label("program, not a variable")
                .hint("IEC 61131-3 gives other POUs no access to a program's variables; for portable code pass the value as an input, or use a global variable (VAR_GLOBAL / VAR_EXTERNAL)");
        }
        Place {
            ty: Type::Fb(FbType::User(id)),
            read_only: None,
        }
    }

    /// Records what a name refers to (in the reporting pass only).
    fn note_name(&mut self, span: Span, r: NameRef) {
        // `write_place` reads the function-result uses back (W1003): those are always recorded
        if !self.a.silent && (self.a.all_names || r == NameRef::FunctionResult) {
            self.a.model.names.insert(span, r);
        }
    }

    /// A hint naming a declared variable with a similar spelling, or how to declare.
    fn similar_name(&self, name: &str) -> String {
        let up = name.to_ascii_uppercase();
        if self
            .a
            .pou_names
            .get(&up)
            .is_some_and(|id| self.a.model.pous[id.0 as usize].kind == PouKind::Program)
        {
            // `MAIN.x` from another POU: CODESYS and TwinCAT programs are single instances whose
            // variables every POU can reach; ladderc does so when the program has one instance
            return format!(
                "`{name}.x` (CODESYS and TwinCAT) names a variable of the program's one instance: declare exactly one instance of `{name}` in the configuration, or pass the value as an input, or use a global variable (VAR_GLOBAL / VAR_EXTERNAL)"
            );
        }
        let is_fb_type = StdFb::from_name(name).is_some()
            || self
                .a
                .pou_names
                .get(&up)
                .is_some_and(|id| self.a.model.pous[id.0 as usize].kind != PouKind::Function);
        if is_fb_type {
            return format!(
                "`{name}` is a type: declare an instance (VAR inst : {name}; END_VAR) and use that"
            );
        }
        let limit = (up.len() / 3).clamp(1, 2);
        let up_chars = up.chars().count();
        // Names whose lengths differ by more than the limit are never that close: skip them before the
        // quadratic distance (a fuzzed name may be thousands of characters long).
        let best = self
            .pou()
            .vars
            .iter()
            .map(|v| v.name.as_str())
            .chain(self.a.model.globals.iter().map(|g| g.name.as_str()))
            .chain(self.a.model.global_lists.iter().map(|l| l.name.as_str()))
            .filter(|n| n.chars().count().abs_diff(up_chars) <= limit)
            .filter_map(|n| {
                let d = edit_distance(&n.to_ascii_uppercase(), &up);
                (d <= limit).then_some((d, n))
            })
            .min_by_key(|&(d, _)| d)
            .map(|(_, n)| n.to_string());
        match best {
            Some(b) => format!("did you mean `{b}`? otherwise declare `{name}` in a VAR block"),
            None => format!("declare `{name}` in a VAR block (or VAR_EXTERNAL for a global)"),
        }
    }

    /// `.field` of a structure or FB instance.
    fn field(&mut self, place: &Place, v: &VarRef, at: usize, f: &ast::Ident) -> Option<Place> {
        if let Some((size, index)) = ast::partial_access(&f.name) {
            return self.partial(place, v, at, f, size, index);
        }
        match &place.ty {
            Type::Struct(id) => {
                let UserTypeDef::Struct { fields } = &self.a.model.types[id.0 as usize].def else {
                    return None;
                };
                if let Some(fv) = fields.iter().find(|x| x.is(&f.name)) {
                    return Some(Place {
                        ty: fv.ty.clone(),
                        read_only: place.read_only,
                    });
                }
                let t = self.a.model.types[id.0 as usize].name.clone();
                let names: Vec<String> = fields.iter().map(|x| x.name.clone()).collect();
                self.a
                    .error(
                        code::E1021,
                        f.span,
                        format!("{t} has no field `{}`", f.name),
                    )
                    .label("unknown field")
                    .hint(format!("fields of {t}: {}", names.join(", ")));
                None
            }
            Type::Fb(_) if f.is("ENO") => {
                // the ENO of the instance's last call (IEC 61131-3: FALSE when EN was FALSE)
                self.a.model.fb_eno_read = true;
                Some(Place {
                    ty: Type::BOOL,
                    read_only: Some(ReadOnly::FbOutput { at }),
                })
            }
            Type::Fb(FbType::User(id))
                if self.a.model.pous[id.0 as usize].kind == PouKind::Program =>
            {
                // `MAIN.x` (see `program_place`): every variable, read and written as CODESYS does
                let prog = &self.a.model.pous[id.0 as usize];
                if let Some(v) = prog.vars.iter().find(|v| v.is(&f.name)) {
                    return Some(Place {
                        ty: v.ty.clone(),
                        read_only: v.constant.then_some(ReadOnly::Constant { decl: v.span }),
                    });
                }
                let name = prog.name.clone();
                self.a
                    .error(
                        code::E1021,
                        f.span,
                        format!("program {name} has no variable `{}`", f.name),
                    )
                    .label("unknown variable")
                    .hint(format!(
                        "declare `{}` in {name}, or correct the name",
                        f.name
                    ));
                None
            }
            Type::Fb(fb) => {
                let params = fb_param_list(&self.a.model, *fb);
                let tname = self.a.type_name(&place.ty);
                // `ctu.RESET` (CODESYS/TwinCAT) is the IEC input `ctu.R`
                let alias = match fb {
                    FbType::Standard(s) => super::stdlib::vendor_param_alias(*s, &f.name),
                    FbType::User(_) => None,
                };
                match params
                    .iter()
                    .find(|p| f.is(&p.0) || alias == Some(p.0.as_str()))
                {
                    Some((_, dir, ty)) => {
                        // `VAR PRIVATE` / `VAR PROTECTED` of a class or block (IEC 61131-3 ed. 3,
                        // 6.6.5; a class's VAR without a specifier is PROTECTED): reached only
                        // from inside it; `VAR PUBLIC` from anywhere, without W1412
                        let access = match fb {
                            FbType::User(id) => self.a.model.pous[id.0 as usize]
                                .access
                                .iter()
                                .find(|(n, _)| f.is(n))
                                .map(|(_, a)| *a),
                            FbType::Standard(_) => None,
                        };
                        // (PROTECTED: also in a block derived from it, at any depth, through
                        // any instance: the caller's class variable names its chain of bases)
                        let inside = match fb {
                            FbType::User(id) if id.0 == self.pou.0 => true,
                            FbType::User(id) if access == Some(Access::Protected) => {
                                let base =
                                    self.a.model.pous[id.0 as usize].name.to_ascii_uppercase();
                                self.a.model.pous[self.pou.0 as usize].vars.iter().any(|v| {
                                    crate::st::base_view::class_chain(&v.name)
                                        .is_some_and(|chain| chain.contains(&base))
                                })
                            }
                            _ => false,
                        };
                        if let (Some(a @ (Access::Private | Access::Protected)), false) =
                            (access, inside)
                        {
                            let kind = if matches!(fb, FbType::User(id) if self.a.model.pous[id.0 as usize].class)
                            {
                                "class"
                            } else {
                                "function block"
                            };
                            self.a
                                .error(
                                    code::E1021,
                                    f.span,
                                    format!(
                                        "`{}` is a {} variable of {kind} {tname}: not reachable from outside it",
                                        f.name,
                                        a.keyword()
                                    ),
                                )
                                .label(format!("{} to {tname}", a.keyword()))
                                .hint(format!("read or write it in a method of {tname} (`inst.GetX()`), or declare it in a `VAR PUBLIC` block"));
                            return None;
                        }
                        let read_only = match dir {
                            ParamDir::Output => Some(ReadOnly::FbOutput { at }),
                            ParamDir::Input | ParamDir::InOut => place.read_only,
                            ParamDir::Internal if access == Some(Access::Public) || inside => {
                                place.read_only
                            }
                            ParamDir::Internal => {
                                // CODESYS and TwinCAT give access to internal variables (W1412,
                                // once per POU, block type and variable)
                                let key = (self.pou.0, tname.to_ascii_uppercase(), f.key());
                                // (not the hidden class a dispatch through a base reads)
                                // (nor a method input's default a call passes, `__MD_`)
                                let hidden = f.name.starts_with(crate::st::base_view::CLASS_PREFIX)
                                    || f.name.starts_with("__MD_");
                                if !self.a.silent && !hidden && self.a.internal_accessed.insert(key)
                                {
                                    self.a
                                        .warning(
                                            code::W1412,
                                            f.span,
                                            format!(
                                                "`{}` is internal to {tname}, used from outside",
                                                f.name
                                            ),
                                        )
                                        .label("not an input or output")
                                        .hint("IEC 61131-3 gives access only to the inputs and outputs of an FB instance; ladderc, like CODESYS and TwinCAT, accesses the instance's variable. For portable code declare it VAR_OUTPUT or VAR_INPUT");
                                }
                                place.read_only
                            }
                        };
                        Some(Place {
                            ty: ty.clone(),
                            read_only,
                        })
                    }
                    // the result of a method that does not exist (`c.Foo(1)` in an expression):
                    // the call itself is reported
                    None if f.name.starts_with(crate::actions::METHOD_PREFIX) => {
                        // ... unless the method exists (it was called: its flag is there) and
                        // returns nothing
                        let method = &f.name[crate::actions::METHOD_PREFIX.len()..];
                        let flag = format!("{}{method}", crate::actions::FLAG_PREFIX);
                        if params.iter().any(|p| p.0.eq_ignore_ascii_case(&flag)) {
                            self.a
                                .error(
                                    code::E1011,
                                    f.span,
                                    format!("method `{}` of {tname} returns no value", f.name.get(crate::actions::METHOD_PREFIX.len()..).unwrap_or("")),
                                )
                                .label("used as a value")
                                .hint("call it as a statement, or give the method a result type (`METHOD M : INT`) and assign it");
                        }
                        None
                    }
                    None => {
                        // (the hidden variables of actions and methods are not offered)
                        let names: Vec<String> = params
                            .iter()
                            .filter(|p| p.1 != ParamDir::Internal && !p.0.starts_with("__"))
                            .map(|p| p.0.clone())
                            .collect();
                        // a block without inputs or outputs: the variables it has (CODESYS and
                        // TwinCAT reach them, W1412), never an empty list
                        let hint = if names.is_empty() {
                            let vars: Vec<&str> = params
                                .iter()
                                .map(|p| p.0.as_str())
                                .filter(|n| !n.starts_with("__"))
                                .collect();
                            if vars.is_empty() {
                                format!("{tname} declares no variables")
                            } else {
                                format!(
                                    "{tname} has no inputs or outputs; its variables: {}",
                                    vars.join(", ")
                                )
                            }
                        } else {
                            format!("parameters of {tname}: {}", names.join(", "))
                        };
                        self.a
                            .error(
                                code::E1011,
                                f.span,
                                format!("{tname} has no input or output `{}`", f.name),
                            )
                            .label("unknown parameter")
                            .hint(hint);
                        None
                    }
                }
            }
            other => {
                let t = self.a.type_name(other);
                self.a
                    .error(
                        code::E1021,
                        f.span,
                        format!("`{}` is {t}, which has no fields", path_text(v, at)),
                    )
                    .label("field access here")
                    .hint("fields belong to structures and FB instances");
                None
            }
        }
    }
}

impl Body<'_, '_> {
    /// A partial access `x.3`, `x.%X3`, `x.%B1` ... (IEC 61131-3 3rd edition, 6.5.2.2): a bit, byte, word or
    /// double word of an integer or bit-string variable, read and written like a variable of type BOOL,
    /// BYTE, WORD, DWORD or LWORD. E1029 when the variable has no such part.
    fn partial(
        &mut self,
        place: &Place,
        v: &VarRef,
        at: usize,
        f: &ast::Ident,
        size: ast::AddressSize,
        index: u32,
    ) -> Option<Place> {
        let part = size.bits();
        let path = path_text(v, at);
        let t = self.a.type_name(&place.ty);
        let width = match &place.ty {
            Type::Elementary(e) if (e.is_integer() || e.is_bit()) && *e != Elementary::Bool => {
                e.bit_width()
            }
            _ => {
                self.a
                    .error(
                        code::E1029,
                        f.span,
                        format!("`{path}` is {t}, which has no bits to access with `.{}`", f.name),
                    )
                    .label("partial access here")
                    .hint("partial access (`x.3`, `x.%X3`, `x.%B1`) works on integers and BYTE, WORD, DWORD, LWORD");
                return None;
            }
        };
        let count = width / part;
        if part >= width || index >= count {
            let what = match size {
                ast::AddressSize::Bit => "bit",
                ast::AddressSize::Byte => "byte",
                ast::AddressSize::Word => "word",
                ast::AddressSize::DWord => "double word",
                ast::AddressSize::LWord => "long word",
            };
            let range = if part >= width {
                format!("{t} has {width} bits: a {what} is not a part of it")
            } else {
                format!("{t} has {what}s 0 to {}", count - 1)
            };
            self.a
                .error(
                    code::E1029,
                    f.span,
                    format!("`{path}.{}` is out of range: {range}", f.name),
                )
                .label("no such part")
                .hint(format!(
                    "{t} has {width} bits, numbered 0 (the least significant) to {}",
                    width - 1
                ));
            return None;
        }
        let ty = match size {
            ast::AddressSize::Bit => Type::BOOL,
            ast::AddressSize::Byte => Type::Elementary(Elementary::Byte),
            ast::AddressSize::Word => Type::Elementary(Elementary::Word),
            ast::AddressSize::DWord => Type::Elementary(Elementary::Dword),
            ast::AddressSize::LWord => Type::Elementary(Elementary::Lword),
        };
        Some(Place {
            ty,
            read_only: place.read_only,
        })
    }
}

/// How a parameter of an FB is passed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum ParamDir {
    Input,
    InOut,
    Output,
    /// A local variable of a user FB (not a parameter).
    Internal,
}

/// The parameters of an FB type: (name, direction, type), inputs first as declared.
pub(super) fn fb_param_list(model: &Model, fb: FbType) -> Vec<(String, ParamDir, Type)> {
    match fb {
        FbType::Standard(s) => fb_params(s)
            .iter()
            .map(|p| {
                let d = if p.dir == Dir::Input {
                    ParamDir::Input
                } else {
                    ParamDir::Output
                };
                (p.name.to_string(), d, Type::Elementary(p.ty))
            })
            .collect(),
        FbType::User(id) => model.pous[id.0 as usize]
            .vars
            .iter()
            .map(|v| {
                let d = match v.kind {
                    VarKind::Input => ParamDir::Input,
                    VarKind::InOut => ParamDir::InOut,
                    VarKind::Output => ParamDir::Output,
                    _ => ParamDir::Internal,
                };
                (v.name.clone(), d, v.ty.clone())
            })
            .collect(),
    }
}

/// The text of `v` up to (not including) accessor `upto`: `s.a[..]` (for messages).
pub(super) fn path_text(v: &VarRef, upto: usize) -> String {
    let mut p = v.base.name.clone();
    for acc in v.accessors.iter().take(upto) {
        match acc {
            Accessor::Field(f) => {
                p.push('.');
                p.push_str(&f.name);
            }
            Accessor::Index(_) => p.push_str("[..]"),
            Accessor::Deref(_) => p.push('^'),
        }
    }
    p
}

/// A hint for a type mismatch: the conversion function to use where there is one.
pub(super) fn conversion_hint(from: &str, to: &str) -> String {
    let plain = |s: &str| s.chars().all(|c| c.is_ascii_uppercase() || c == '_');
    // `dwAdr := ADR(w)` into a DWORD (CODESYS V2.3's ADR gives a DWORD): an address kept in an
    // integer is refused by design, as it would lose the bounds every pointer carries here
    if let Some(target) = from.strip_prefix("REF_TO ") {
        let integer = super::model::Elementary::from_name(to)
            .is_some_and(|e| e.is_integer() || (e.is_bit() && e != super::model::Elementary::Bool));
        if integer {
            return format!(
                "ladderc keeps an address only in a pointer, never in an integer such as {to} (a pointer here is bounded by the variable it points into); declare it `POINTER TO {target}` and read the value through `^`"
            );
        }
    }
    if plain(from) && plain(to) && super::stdlib::conversion(&format!("{from}_TO_{to}")).is_some() {
        format!("convert explicitly with {from}_TO_{to}")
    } else {
        format!("use a value of type {to}")
    }
}

/// Edit distance with adjacent transpositions (optimal string alignment), for "did you mean".
fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let mut d = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in d[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut v = (d[i - 1][j] + 1)
                .min(d[i][j - 1] + 1)
                .min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                v = v.min(d[i - 2][j - 2] + 1);
            }
            d[i][j] = v;
        }
    }
    d[a.len()][b.len()]
}
