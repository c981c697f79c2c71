//! Name resolution and value access inside one POU (or a configuration): IEC operands to C expressions.
//!
//! Input: an operand (variable reference, direct address, literal, enum value) and the POU's resolved
//! variables. Output: a [`Place`] (a C lvalue, or a located process-image access) and C value expressions
//! of a requested IEC type. Invariants: reads and writes of located data go through the byte-order-aware
//! runtime helpers; array indexes go through `ladderc_index` (out-of-range: element 0 and an error flag);
//! every produced expression is fully parenthesised.

use super::values::{convert_owned, load_expr, located_bytes, store_expr};
use super::Gen;
use crate::ctypes;
use crate::mangle;
use crate::profile::Located;
use diagnostics::{code, Diagnostic, Span};
use il_frontend::ast::{
    Accessor, AddressSize, Literal, LiteralKind, Operand, PouKind, VarKind, VarRef,
};
use il_frontend::sema::{
    with_upper, Elementary, FbType, GlobalRef, Pou, PouId, Type, UserTypeDef, Variable,
};
use std::collections::HashMap;

use Elementary as E;

/// Where a value lives.
#[derive(Debug, Clone)]
pub enum Place {
    /// A C lvalue (`self->v_x`, `(*v_io)`, `g_x`, `self->v_t.Q`).
    Mem { lv: String, ty: Type },
    /// A located variable or a direct address in the process image; `at`, for an element of a
    /// located array, is a C expression of the element's byte offset from `loc` (already checked
    /// against the array's bounds, so the bytes are inside the array).
    Loc {
        loc: Located,
        ty: Type,
        at: Option<String>,
    },
    /// A partial access `x.3`, `x.%B1` (3rd edition): `width` bits from bit `shift` (LSB 0) of `whole`,
    /// an integer or bit string, read as `ty` (BOOL, BYTE, WORD, DWORD, LWORD) and written back into it.
    Part {
        whole: Box<Place>,
        shift: u32,
        width: u32,
        ty: Type,
    },
    /// CODESYS/TwinCAT `s[i]` of a STRING (a BYTE) or a WSTRING (a WORD): the code at offset
    /// `index` (a C expression) of the string `lv`, whose declared length is `cap`; read and
    /// written through `ladderc_str_byte_get/_set` (`ladderc_wstr_word_...`), which keep LEN(s).
    StrByte {
        lv: String,
        index: String,
        cap: u32,
        site: String,
        ty: Type,
    },
}

impl Place {
    pub fn ty(&self) -> &Type {
        match self {
            Place::Mem { ty, .. }
            | Place::Loc { ty, .. }
            | Place::Part { ty, .. }
            | Place::StrByte { ty, .. } => ty,
        }
    }
}

/// The variables visible in a body: a POU's own, or (for configuration code) none.
pub struct Scope<'m> {
    pub pou: Option<(&'m Pou, PouId)>,
    /// The C lvalue of each of the POU's variables seen from its body ([`own_var_lvalue`]), by index.
    lvalues: Vec<String>,
    externals: HashMap<usize, GlobalRef>,
    /// Configuration code (task intervals, program instance arguments): its configuration index.
    pub config: Option<(usize, usize)>,
    /// Set when the body reads or writes the implicit `EN` / `ENO`.
    pub uses_en: std::cell::Cell<bool>,
    /// A split body (see `split`): the C locals of the POU live in the frame `fr`.
    framed: bool,
}

impl<'m> Scope<'m> {
    pub fn for_pou(pou: &'m Pou, id: PouId) -> Self {
        // Names are looked up in the POU's own index (`Pou::var_position`, built by sema): no second
        // upper-cased copy of every name (32,500 for the 10,000 generated rungs).
        let lvalues = pou
            .vars
            .iter()
            .map(|v| own_var_lvalue(pou.kind, v))
            .collect();
        Scope {
            pou: Some((pou, id)),
            lvalues,
            externals: pou.externals.iter().copied().collect(),
            config: None,
            uses_en: std::cell::Cell::new(false),
            framed: false,
        }
    }
    /// For a split body: the POU's C locals (VAR_TEMP; every variable of a FUNCTION, its result, and
    /// `EN`/`ENO`) are read through the frame pointer `fr` of the part functions.
    pub fn frame(&mut self) {
        let Some((pou, _)) = self.pou else { return };
        for (i, v) in pou.vars.iter().enumerate() {
            // Only a function's variables and temporaries move into the frame: no name for the rest.
            let (open, close) = match (pou.kind, v.kind) {
                (PouKind::Function, VarKind::Output | VarKind::InOut) => ("(*fr->", ")"),
                (PouKind::Function, _) | (_, VarKind::Temp) => ("fr->", ""),
                _ => continue,
            };
            self.lvalues[i] = cfmt!("{open}{}{close}", mangle::var(&v.name));
        }
        self.framed = true;
    }
    /// The C name of a local of the body function (`fr->` in front when the body is split).
    fn local(&self, name: String) -> String {
        if self.framed {
            cfmt!("fr->{name}")
        } else {
            name
        }
    }
    pub fn for_config(config: usize, resource: usize) -> Self {
        Scope {
            pou: None,
            lvalues: Vec::new(),
            externals: HashMap::new(),
            config: Some((config, resource)),
            uses_en: std::cell::Cell::new(false),
            framed: false,
        }
    }
}

/// The C lvalue of POU variable `v` seen from its own body (VAR_TEMP and FUNCTION variables are C
/// locals, the rest instance members).
pub fn own_var_lvalue(kind: PouKind, v: &Variable) -> String {
    // `open` v_<core> `close`, in one allocation (a POU's every variable gets one: 32,500 for the
    // 10,000 generated rungs).
    let (open, close) = match (kind, v.kind) {
        (PouKind::Function, VarKind::Output | VarKind::InOut) => ("(*v_", ")"),
        (PouKind::Function, _) | (_, VarKind::Temp) => ("v_", ""),
        (_, VarKind::InOut) => ("(*self->v_", ")"),
        _ => ("self->v_", ""),
    };
    let mut s = String::with_capacity(open.len() + v.name.len() + close.len());
    s.push_str(open);
    mangle::push_core(&mut s, &v.name);
    s.push_str(close);
    s
}

impl Gen<'_> {
    /// A construct this backend does not translate (E2005).
    pub fn unsupported(&mut self, span: Span, what: impl Into<String>) {
        let what = what.into();
        self.report_once(
            Diagnostic::error(code::E2005, cfmt!("the C backend does not support {what}"))
                .at(span)
                .with_primary_label("not supported here"),
        );
    }

    /// The C name of a global variable.
    pub fn global_name(&self, r: GlobalRef) -> String {
        // `List.x` for a list member: two lists may both declare `x`
        let name = self.model.global_qualified_name(r);
        match r {
            GlobalRef::Free(_) => mangle::global_free(&name),
            GlobalRef::Configuration { config, .. } => mangle::global_config(config, &name),
            GlobalRef::Resource {
                config, resource, ..
            } => mangle::global_resource(config, resource, &name),
        }
    }

    /// The place of a global (located globals alias the process image).
    pub fn global_place(&mut self, r: GlobalRef, span: Span) -> Option<Place> {
        let v = self.model.global(r).clone();
        if let Some(loc) = &v.location {
            return self.locate_var(&v, loc, span);
        }
        Some(Place::Mem {
            lv: self.global_name(r),
            ty: v.ty.clone(),
        })
    }

    fn locate_var(
        &mut self,
        v: &Variable,
        loc: &il_frontend::sema::Location,
        span: Span,
    ) -> Option<Place> {
        let Some(bytes) = located_bytes(&v.ty, loc.size) else {
            self.unsupported(
                span,
                if matches!(v.ty, Type::Array { .. }) && loc.size == AddressSize::Bit {
                    "an array located at a bit address (give it a byte address, `%MB`)"
                } else {
                    "a located variable of a non-elementary type"
                },
            );
            return None;
        };
        let addr = il_frontend::ast::DirectAddress {
            area: loc.area,
            size: loc.size,
            path: loc.path.clone(),
            span: self
                .address_spans
                .get(&(v.span, loc.path.is_empty()))
                .copied()
                .unwrap_or(v.span),
        };
        let bytes = if v.ty.is_bool() { None } else { Some(bytes) };
        match self.locate(&addr, bytes) {
            Ok(l) => Some(Place::Loc {
                loc: l,
                ty: v.ty.clone(),
                at: None,
            }),
            Err(d) => {
                self.report_once(*d);
                None
            }
        }
    }

    /// Reports a diagnostic unless the same code was already reported at the same span, or the
    /// generator is only probing (`quiet`).
    pub fn report_once(&mut self, d: Diagnostic) {
        if self.quiet > 0 {
            return;
        }
        let key = (d.code.0, d.span);
        if self.reported.insert(key) {
            self.diags.push(d);
        }
    }

    /// The position in `pou.vars` of the variable `name` denotes in the POU's body, `None` when it is
    /// not one of the POU's variables (the POU's name index, `Pou::var_position`).
    fn own_var(&self, pou: &Pou, name: &il_frontend::ast::Ident) -> Option<usize> {
        pou.var_position(&name.name)
    }

    /// Resolves the base name of a variable reference: `None` when no such name is visible,
    /// `Some(None)` when it is but its place could not be computed (a diagnostic was reported).
    fn base_place(
        &mut self,
        scope: &Scope,
        name: &il_frontend::ast::Ident,
    ) -> Option<Option<Place>> {
        if let Some((pou, _)) = scope.pou {
            if let Some(i) = self.own_var(pou, name) {
                let v = &pou.vars[i];
                if v.kind == VarKind::External {
                    if let Some(&g) = scope.externals.get(&i) {
                        return Some(self.global_place(g, name.span));
                    }
                }
                if let Some(loc) = &v.location {
                    let v = v.clone();
                    let loc = loc.clone();
                    return Some(self.locate_var(&v, &loc, name.span));
                }
                return Some(Some(Place::Mem {
                    lv: scope.lvalues[i].clone(),
                    ty: v.ty.clone(),
                }));
            }
            if pou.kind == PouKind::Function && pou.name.eq_ignore_ascii_case(&name.name) {
                if let Some(rt) = &pou.return_type {
                    return Some(Some(Place::Mem {
                        lv: scope.local(mangle::var(&pou.name)),
                        ty: rt.clone(),
                    }));
                }
            }
            let key = name.key();
            if key == "ENO" && pou.kind == PouKind::FunctionBlock && self.model.fb_eno_read {
                // the instance's own ENO, which the caller reads (set to TRUE before each call)
                return Some(Some(Place::Mem {
                    lv: "self->ENO".to_string(),
                    ty: Type::BOOL,
                }));
            }
            if key == "ENO" && pou.kind == PouKind::Function {
                // the caller's flag (`IEC_BOOL *ladderc_eno`), which `ENO =>` of the call reads
                return Some(Some(Place::Mem {
                    lv: cfmt!("(*{})", scope.local("ladderc_eno".to_string())),
                    ty: Type::BOOL,
                }));
            }
            if key == "EN" || key == "ENO" {
                scope.uses_en.set(true);
                return Some(Some(Place::Mem {
                    lv: scope.local(mangle::var(&key)),
                    ty: Type::BOOL,
                }));
            }
        }
        if let Some((c, r)) = scope.config {
            let cfg = &self.model.configurations[c];
            if let Some(index) = cfg.resources[r]
                .globals
                .iter()
                .position(|g| g.is(&name.name))
            {
                return Some(self.global_place(
                    GlobalRef::Resource {
                        config: c,
                        resource: r,
                        index,
                    },
                    name.span,
                ));
            }
            if let Some(index) = cfg.globals.iter().position(|g| g.is(&name.name)) {
                return Some(
                    self.global_place(GlobalRef::Configuration { config: c, index }, name.span),
                );
            }
        }
        if let Some(i) = with_upper(&name.name, |key| self.free_globals.get(key).copied()) {
            return Some(self.global_place(GlobalRef::Free(i), name.span));
        }
        None
    }

    /// The C variable of the one instance of program `name` (its implicit instance without a
    /// configuration or when the configuration has none), typed as the program; `None` when `name`
    /// is no program or has several instances.
    pub fn program_instance_place(&self, name: &str) -> Option<Place> {
        let id = self
            .model
            .pous
            .iter()
            .position(|p| p.kind == PouKind::Program && p.name.eq_ignore_ascii_case(name))?;
        let id = PouId(id as u32);
        let lv = if self.model.configurations.is_empty() {
            mangle::implicit_instance(&self.model.pou(id).name)
        } else {
            let mut found = Vec::new();
            for (ci, cfg) in self.model.configurations.iter().enumerate() {
                for (ri, r) in cfg.resources.iter().enumerate() {
                    for p in r.programs.iter().filter(|p| p.pou == id) {
                        found.push(mangle::program_instance(ci, ri, &p.name));
                    }
                }
            }
            match found.len() {
                // a program in no resource: its own instance, which calls from other POUs run
                // (defined with the scan when they use it, `scan::instances`)
                0 => mangle::implicit_instance(&self.model.pou(id).name),
                1 => found.pop()?,
                _ => return None,
            }
        };
        Some(Place::Mem {
            lv,
            ty: Type::Fb(FbType::User(id)),
        })
    }

    /// The place a variable reference denotes (None: an error was reported, or it is not a variable).
    pub fn place(&mut self, scope: &Scope, r: &VarRef) -> Option<Place> {
        let place = self.place_or_located_array(scope, r)?;
        if let Place::Loc {
            ty: Type::Array { .. },
            ..
        } = place
        {
            // its elements are addressed one by one (`located_index`); a whole located array is
            // no C object to copy or pass
            self.unsupported(r.span, "a whole located array (use its elements)");
            return None;
        }
        Some(place)
    }

    /// [`Self::place`], where a whole located array is a place too (for `SIZEOF`).
    pub(super) fn place_or_located_array(&mut self, scope: &Scope, r: &VarRef) -> Option<Place> {
        let mut base = self.base_place(scope, &r.base);
        let mut skip = 0;
        if let (None, Some((p, id)), Some(Accessor::Deref(_))) =
            (&base, scope.pou, r.accessors.first())
        {
            // `THIS^`: the instance running the body (sema checked it is a function block's)
            if r.base.is("THIS") && p.kind == il_frontend::ast::PouKind::FunctionBlock {
                base = Some(Some(Place::Mem {
                    lv: "(*self)".into(),
                    ty: Type::Fb(il_frontend::sema::FbType::User(id)),
                }));
                skip = 1;
            }
        }
        if base.is_none() {
            // `GVL.x`: a member of a named global variable list (CODESYS, TwinCAT)
            let member = match (self.model.global_list(&r.base.name), r.accessors.first()) {
                (Some(list), Some(Accessor::Field(m))) => self.model.list_member(list, &m.name),
                _ => None,
            };
            if let Some(g) = member {
                base = Some(self.global_place(g, r.base.span));
                skip = 1;
            }
        }
        if base.is_none() {
            // `CAL PLC_PRG(__ACTION_RESET := TRUE)`: a program's action called from another POU
            // runs on the program's one instance (sema checked the call); `MAIN.x` (W1413) is a
            // variable of that instance
            base = self.program_instance_place(&r.base.name).map(Some);
        }
        let Some(base) = base else {
            self.report_once(
                Diagnostic::error(
                    code::E2005,
                    cfmt!(
                        "the C backend cannot resolve `{}` (no variable of that name)",
                        r.base.name
                    ),
                )
                .at(r.base.span),
            );
            return None;
        };
        let mut place = base?;
        // accessors already taken by a dereference that reached into its target (`p^[i].x`)
        let mut taken = skip;
        for (at, acc) in r.accessors.iter().enumerate().skip(skip) {
            if at < taken {
                continue;
            }
            if let Accessor::Field(f) = acc {
                if let Some((size, index)) = il_frontend::ast::partial_access(&f.name) {
                    // `x.3`, `x.%B1`: sema checked the type and the range
                    let width = size.bits();
                    let Some(e) = place.ty().elementary() else {
                        self.unsupported(
                            r.span,
                            "a partial access of a value that is not elementary",
                        );
                        return None;
                    };
                    if index >= e.bit_width() / width {
                        self.unsupported(r.span, "a partial access out of range");
                        return None;
                    }
                    let ty = Type::Elementary(match size {
                        AddressSize::Bit => E::Bool,
                        AddressSize::Byte => E::Byte,
                        AddressSize::Word => E::Word,
                        AddressSize::DWord => E::Dword,
                        AddressSize::LWord => E::Lword,
                    });
                    place = Place::Part {
                        whole: Box::new(place),
                        shift: index * width,
                        width,
                        ty,
                    };
                    continue;
                }
            }
            let (lv, ty) = match place {
                Place::Mem { lv, ty } => (lv, ty),
                Place::Loc {
                    loc,
                    ty: ty @ Type::Array { .. },
                    at: None,
                } => {
                    let Accessor::Index(idx) = acc else {
                        self.unsupported(r.span, "fields of a located array");
                        return None;
                    };
                    let site = self.index_site(scope, r, at);
                    place = self.located_index(scope, loc, &ty, idx, r.span, &site)?;
                    continue;
                }
                Place::StrByte { .. } => {
                    self.unsupported(r.span, "fields or indexes of a string's byte");
                    return None;
                }
                Place::Loc { .. } | Place::Part { .. } => {
                    self.unsupported(r.span, "fields or indexes of a located variable");
                    return None;
                }
            };
            place = match acc {
                Accessor::Field(f) => self.field(&lv, &ty, f)?,
                // `p[i]` on a `POINTER TO T` (sema: one index): the i-th T after `p^`
                Accessor::Index(idx) if matches!(ty, Type::Ref(_)) && idx.len() == 1 => {
                    let (p, inside) =
                        self.deref_place(scope, &lv, &ty, r, at, r.span, idx.first())?;
                    taken = at + 1 + inside;
                    p
                }
                // edition 3: `s[i]`, the i-th character (1-based) of a STRING or a WSTRING; out
                // of 1..LEN(s) a NUL read and a write dropped (`ladderc_char_at`)
                // CODESYS, TwinCAT: the BYTE (WORD) at offset i, 0 the first (sema: `byte_indexes`)
                Accessor::Index(idx)
                    if matches!(ty, Type::String { .. })
                        && idx.len() == 1
                        && self.model.byte_indexes.contains(&idx[0].span()) =>
                {
                    let wide = matches!(ty, Type::String { wide: true, .. });
                    let site = self.index_site(scope, r, at);
                    let index = self.value(scope, &idx[0], &Type::Elementary(E::Lint))?;
                    Place::StrByte {
                        cap: ctypes::string_cap(&ty),
                        lv,
                        index,
                        site,
                        ty: Type::Elementary(if wide { E::Word } else { E::Byte }),
                    }
                }
                Accessor::Index(idx) if matches!(ty, Type::String { .. }) && idx.len() == 1 => {
                    let wide = matches!(ty, Type::String { wide: true, .. });
                    let site = self.index_site(scope, r, at);
                    let i = self.value(scope, &idx[0], &Type::Elementary(E::Lint))?;
                    let f = if wide {
                        "ladderc_wchar_at"
                    } else {
                        "ladderc_char_at"
                    };
                    Place::Mem {
                        lv: cfmt!("(*{f}(&({lv}), {i}, {site}))"),
                        ty: Type::Elementary(if wide { E::Wchar } else { E::Char }),
                    }
                }
                Accessor::Index(idx) => {
                    let site = self.index_site(scope, r, at);
                    self.index(scope, &lv, &ty, idx, r.span, &site)?
                }
                Accessor::Deref(span) => {
                    let (p, inside) = self.deref_place(scope, &lv, &ty, r, at, *span, None)?;
                    taken = at + 1 + inside;
                    p
                }
            };
        }
        Some(place)
    }

    pub(super) fn field(
        &mut self,
        lv: &str,
        ty: &Type,
        f: &il_frontend::ast::Ident,
    ) -> Option<Place> {
        match ty {
            Type::Struct(id) => {
                if let Some(v) = self.struct_field(*id, &f.name) {
                    return Some(Place::Mem {
                        lv: cfmt!("{lv}.{}", mangle::var(&v.name)),
                        ty: v.ty.clone(),
                    });
                }
            }
            Type::Fb(_) if f.is("ENO") => {
                // the ENO of the instance's last call (see `cal`; a user FB's struct has the member
                // when a body reads it)
                return Some(Place::Mem {
                    lv: format!("{lv}.ENO"),
                    ty: Type::BOOL,
                });
            }
            Type::Fb(FbType::Standard(fb)) => {
                let (_, params) = ctypes::std_fb(*fb);
                let name =
                    il_frontend::sema::stdlib::vendor_param_alias(*fb, &f.name).unwrap_or(&f.name);
                if let Some((n, e, _)) = params.iter().find(|p| p.0.eq_ignore_ascii_case(name)) {
                    return Some(Place::Mem {
                        lv: cfmt!("{lv}.{n}"),
                        ty: Type::Elementary(*e),
                    });
                }
            }
            Type::Fb(FbType::User(id)) => {
                if let Some(v) = self.pou_var(*id, &f.name) {
                    let name = mangle::var(&v.name);
                    let lv = if v.kind == VarKind::InOut {
                        cfmt!("(*{lv}.{name})")
                    } else {
                        cfmt!("{lv}.{name}")
                    };
                    return Some(Place::Mem {
                        lv,
                        ty: v.ty.clone(),
                    });
                }
            }
            _ => {}
        }
        self.report_once(
            Diagnostic::error(
                code::E2005,
                cfmt!(
                    "the C backend cannot resolve the field `{}` of a value of type {}",
                    f.name,
                    self.model.type_name(ty)
                ),
            )
            .at(f.span),
        );
        None
    }

    /// `lv[i, ...]`: each index checked against its bounds by `ladderc_index` (out of range: the
    /// first element, and the bounds flag with `site`, a C string literal naming the access, kept
    /// for the first one).
    pub(super) fn index(
        &mut self,
        scope: &Scope,
        lv: &str,
        ty: &Type,
        idx: &[Operand],
        span: Span,
        site: &str,
    ) -> Option<Place> {
        let mut lv = lv.to_string();
        let mut ty = ty.clone();
        let mut rest = idx;
        while !rest.is_empty() {
            let Type::Array { dims, element } = ty.clone() else {
                self.unsupported(span, "an index on a value that is not an array");
                return None;
            };
            for d in &dims {
                let Some((op, tail)) = rest.split_first() else {
                    self.unsupported(span, "a partially indexed multi-dimensional array");
                    return None;
                };
                let v = self.value(scope, op, &Type::Elementary(E::Lint))?;
                lv = cfmt!(
                    "{lv}[ladderc_index({v}, {}, {}, {site})]",
                    clamp64(d.lower),
                    clamp64(d.upper)
                );
                rest = tail;
            }
            ty = *element;
        }
        Some(Place::Mem { lv, ty })
    }

    /// The site of the index at accessor `at` of `r`: [`Self::written`] up to that index.
    fn index_site(&self, scope: &Scope, r: &VarRef, at: usize) -> String {
        self.site(scope, &self.written(r, at), r.span)
    }

    /// `r` up to its accessor `at`, as written: an index expression the ST lowering computed into
    /// a temporary (`temps[_ST_T1]`) is shown as its source text (`temps[i + 1]`).
    pub(super) fn written(&self, r: &VarRef, at: usize) -> String {
        let as_written = |op: &Operand| match op {
            Operand::Var(v) if v.accessors.is_empty() && is_temporary(&v.base.name) => {
                match self.lines.text(v.base.span) {
                    Some(text) => Operand::Var(VarRef {
                        base: il_frontend::ast::Ident::new(text.to_string(), v.base.span),
                        accessors: Default::default(),
                        span: v.span,
                    }),
                    None => op.clone(),
                }
            }
            _ => op.clone(),
        };
        // an ANY input's hidden address (il_frontend::st::any_inputs) as written: `In.pValue`
        let base = match r.base.name.strip_suffix(il_frontend::st::any_inputs::VALUE) {
            Some(input) if !input.is_empty() => {
                let shown = cfmt!("{input}.pValue");
                // the user's spelling (`Src.pValue`) where the source has it
                let written = [r.base.span, r.span].into_iter().find_map(|span| {
                    let t = self.lines.text(span)?.get(..shown.len())?;
                    t.eq_ignore_ascii_case(&shown).then(|| t.to_string())
                });
                let shown = written.unwrap_or(shown);
                il_frontend::ast::Ident::new(shown, r.base.span)
            }
            _ => r.base.clone(),
        };
        let upto = VarRef {
            base,
            accessors: r
                .accessors
                .iter()
                .take(at + 1)
                .map(|a| match a {
                    Accessor::Index(ix) => Accessor::Index(ix.iter().map(as_written).collect()),
                    other => other.clone(),
                })
                .collect(),
            span: r.span,
        };
        il_frontend::print::var_ref_text(&upto)
    }

    /// `a[i, j]` of a located array `a` (elementary elements, see [`located_bytes`]): the element
    /// at byte `((i - lo_i) * len_j + (j - lo_j)) * size` from the array's address, row by row as
    /// C lays out an array. Each index is checked as for any array (`ladderc_index`: out of range
    /// gives the first element and the bounds flag), so the access stays inside the array, whose
    /// bytes the generator checked against the area.
    fn located_index(
        &mut self,
        scope: &Scope,
        loc: Located,
        ty: &Type,
        idx: &[Operand],
        span: Span,
        site: &str,
    ) -> Option<Place> {
        let Type::Array { dims, element } = ty else {
            return None;
        };
        if idx.len() != dims.len() {
            self.unsupported(span, "a partially indexed located array");
            return None;
        }
        let size = located_bytes(element, AddressSize::Byte)?;
        let mut at = String::new();
        for (k, (d, op)) in dims.iter().zip(idx).enumerate() {
            let v = self.value(scope, op, &Type::Elementary(E::Lint))?;
            let i = cfmt!(
                "ladderc_index({v}, {}, {}, {site})",
                clamp64(d.lower),
                clamp64(d.upper)
            );
            at = if k == 0 {
                i
            } else {
                cfmt!("({at}) * {}u + {i}", d.len())
            };
        }
        Some(Place::Loc {
            loc: Located { bytes: size, ..loc },
            ty: (**element).clone(),
            at: Some(cfmt!("({at}) * {size}u")),
        })
    }

    /// The type an operand has by itself (literals: their prefix, else the given context type).
    pub fn operand_type(&mut self, scope: &Scope, op: &Operand, context: Option<&Type>) -> Type {
        match op {
            Operand::Var(r) => {
                if r.accessors.is_empty() && self.enum_of_name(scope, &r.base, context).is_some() {
                    return self
                        .enum_of_name(scope, &r.base, context)
                        .map(|(t, _)| Type::Enum(t))
                        .unwrap_or(Type::Error);
                }
                self.quiet += 1;
                let t = self.place(scope, r).map(|p| p.ty().clone());
                self.quiet -= 1;
                t.unwrap_or(Type::Error)
            }
            Operand::Address(a) => {
                Type::Elementary(il_frontend::sema::Location::of(a).elementary())
            }
            Operand::EnumValue(e) => self
                .model
                .type_by_name(&e.type_name.name)
                .map(Type::Enum)
                .unwrap_or(Type::Error),
            // typed by its context, as an integer literal (sema: `size_of_operand`)
            Operand::Mem(m) => Type::Elementary(if m.func == il_frontend::ast::MemFunc::Compare {
                E::Dint
            } else {
                E::Udint
            }),
            Operand::SizeOf(_) => match context {
                Some(c) if c.is_numeric() => c.clone(),
                _ => Type::Elementary(E::Udint),
            },
            Operand::Ref(r) => match &r.of {
                None => context
                    .filter(|c| matches!(c, Type::Ref(_)))
                    .cloned()
                    .unwrap_or(Type::Ref(Box::new(Type::Error))),
                Some(v) => {
                    self.quiet += 1;
                    let t = self.place(scope, v).map(|p| p.ty().clone());
                    self.quiet -= 1;
                    t.map_or(Type::Error, |t| Type::Ref(Box::new(t)))
                }
            },
            Operand::Literal(l) => {
                if let Some(p) = &l.type_prefix {
                    if let Some(e) = Elementary::from_name(&p.name) {
                        return Type::Elementary(e);
                    }
                }
                if let Some(c) = context {
                    return c.clone();
                }
                match &l.kind {
                    LiteralKind::Int(_) => Type::DINT,
                    LiteralKind::Real(_) => Type::LREAL,
                    LiteralKind::Bool(_) => Type::BOOL,
                    LiteralKind::Duration(_) => Type::TIME,
                    LiteralKind::Date(_) => Type::Elementary(E::Date),
                    LiteralKind::TimeOfDay(_) => Type::Elementary(E::Tod),
                    LiteralKind::DateAndTime(_) => Type::Elementary(E::Dt),
                    LiteralKind::String { wide, value } => Type::String {
                        wide: *wide,
                        len: value.len().max(1) as u32,
                    },
                }
            }
        }
    }

    /// `red` used as a value: (enum type, value index), when it is not a variable in scope.
    fn enum_of_name(
        &self,
        scope: &Scope,
        name: &il_frontend::ast::Ident,
        context: Option<&Type>,
    ) -> Option<(il_frontend::sema::TypeId, usize)> {
        if !self.has_enums {
            return None;
        }
        if scope
            .pou
            .is_some_and(|(p, _)| p.var_position(&name.name).is_some())
            || with_upper(&name.name, |key| self.free_globals.contains_key(key))
        {
            return None;
        }
        let find = |id: il_frontend::sema::TypeId| match &self.model.user_type(id).def {
            UserTypeDef::Enum { values, .. } => values
                .iter()
                .position(|(n, _)| n.eq_ignore_ascii_case(&name.name))
                .map(|i| (id, i)),
            _ => None,
        };
        if let Some(Type::Enum(id)) = context {
            if let Some(r) = find(*id) {
                return Some(r);
            }
        }
        (0..self.model.types.len())
            .map(|i| il_frontend::sema::TypeId(i as u32))
            .find_map(find)
    }

    /// Reads a place as a value of type `want` (the place's lvalue text is reused).
    pub fn read_owned(&self, place: Place, want: &Type) -> String {
        match place {
            Place::StrByte {
                lv,
                index,
                cap,
                site,
                ty,
            } => {
                let f = str_byte_fn(&ty);
                convert_owned(cfmt!("{f}_get(&({lv}), {index}, {cap}, {site})"), &ty, want)
            }
            Place::Mem { lv, ty } => convert_owned(lv, &ty, want),
            Place::Loc { loc, ty, at } => {
                convert_owned(load_expr(&loc, at.as_deref(), &ty), &ty, want)
            }
            Place::Part {
                whole,
                shift,
                width,
                ty,
            } => {
                let wt = whole.ty().clone();
                let x = self.read_owned(*whole, &wt);
                let ct = match ty.elementary() {
                    Some(e) => ctypes::elementary(e),
                    None => "IEC_BOOL",
                };
                convert_owned(
                    cfmt!(
                        "(({ct})((((uint64_t)({x})) >> {shift}) & {}))",
                        part_mask(width)
                    ),
                    &ty,
                    want,
                )
            }
        }
    }

    /// A statement storing `value` (a C expression of the place's type) into `place`.
    pub fn store(&self, place: &Place, value: &str) -> String {
        let mut s = String::with_capacity(64);
        self.write_store(&mut s, place, value);
        s
    }

    /// [`Gen::store`], written at the end of `out`.
    pub fn write_store(&self, out: &mut String, place: &Place, value: &str) {
        use std::fmt::Write as _;
        match place {
            Place::Mem { lv, ty } => match ty {
                Type::String { wide: false, .. } => {
                    let _ = write!(
                        out,
                        "{lv} = ladderc_str_cap({value}, {});",
                        ctypes::string_cap(ty)
                    );
                }
                Type::String { wide: true, .. } => {
                    let _ = write!(
                        out,
                        "{lv} = ladderc_wstr_cap({value}, {});",
                        ctypes::string_cap(ty)
                    );
                }
                // C arrays do not assign: a whole array (`b := a`, an array input) is copied
                Type::Array { .. } => {
                    let _ = write!(out, "memcpy({lv}, {value}, sizeof {lv});");
                }
                _ => {
                    out.push_str(lv);
                    out.push_str(" = ");
                    out.push_str(value);
                    out.push(';');
                }
            },
            Place::Loc { loc, ty, at } => out.push_str(&store_expr(loc, at.as_deref(), ty, value)),
            Place::StrByte {
                lv,
                index,
                cap,
                site,
                ty,
            } => {
                let f = str_byte_fn(ty);
                let _ = write!(out, "{f}_set(&({lv}), {index}, {cap}, {value}, {site});");
            }
            Place::Part {
                whole,
                shift,
                width,
                ..
            } => {
                // read, change the part, write the whole back (the whole's own store: a located
                // variable keeps its byte order)
                let wt = whole.ty().clone();
                let x = self.read_owned((**whole).clone(), &wt);
                let cw = match wt.elementary() {
                    Some(e) => ctypes::elementary(e),
                    None => "uint64_t",
                };
                let m = part_mask(*width);
                self.write_store(
                    out,
                    whole,
                    &cfmt!(
                        "(({cw})((((uint64_t)({x})) & ~({m} << {shift})) | ((((uint64_t)({value})) & {m}) << {shift})))"
                    ),
                );
            }
        }
    }

    /// [`Gen::store`] as one line of `b` (written in place).
    pub(super) fn store_line(&self, b: &mut super::body::Body, place: &Place, value: &str) {
        b.begin_line();
        self.write_store(&mut b.out, place, value);
        b.out.push('\n');
    }

    /// An operand's value as a C expression of type `want`.
    pub fn value(&mut self, scope: &Scope, op: &Operand, want: &Type) -> Option<String> {
        match op {
            Operand::Literal(l) => self.literal(l, want),
            Operand::Ref(r) => self.reference_value(scope, r),
            Operand::Mem(m) => {
                let from = self.operand_type(scope, op, None);
                let call = self.memory_call(scope, m)?;
                Some(convert_owned(call, &from, want))
            }
            Operand::SizeOf(s) => {
                let size = self.size_of(scope, s)?;
                let c = ctypes::base(self.model, want)
                    .filter(|_| want.is_numeric())
                    .unwrap_or_else(|| "IEC_UDINT".into());
                Some(cfmt!("(({c}){size})"))
            }
            Operand::Address(a) => {
                let e = il_frontend::sema::Location::of(a).elementary();
                match self.locate(a, None) {
                    Ok(loc) => Some(convert_owned(
                        load_expr(&loc, None, &Type::Elementary(e)),
                        &Type::Elementary(e),
                        want,
                    )),
                    Err(d) => {
                        self.report_once(*d);
                        None
                    }
                }
            }
            Operand::EnumValue(e) => {
                let (type_name, value) = (&e.type_name, &e.value);
                let id = self.model.type_by_name(&type_name.name);
                let v = id.and_then(|id| match &self.model.user_type(id).def {
                    UserTypeDef::Enum { values, .. } => values
                        .iter()
                        .find(|(n, _)| n.eq_ignore_ascii_case(&value.name))
                        .map(|v| v.1),
                    _ => None,
                });
                match v {
                    Some(v) => Some(ctypes::int_literal(E::Dint, v)),
                    None => {
                        self.unsupported(
                            value.span,
                            "this enumerated value (unknown type or value)",
                        );
                        None
                    }
                }
            }
            Operand::Var(r) => {
                if r.accessors.is_empty() {
                    if let Some((id, i)) = self.enum_of_name(scope, &r.base, Some(want)) {
                        let v = ctypes::enum_value(self.model, id, i).unwrap_or(0);
                        return Some(ctypes::int_literal(E::Dint, v));
                    }
                }
                let p = self.place(scope, r)?;
                Some(self.read_owned(p, want))
            }
        }
    }

    /// A literal as a C expression of type `want`.
    pub fn literal(&mut self, l: &Literal, want: &Type) -> Option<String> {
        let e = match want {
            Type::Enum(_) => E::Dint,
            Type::String { wide, .. } => {
                return match &l.kind {
                    LiteralKind::String { value, .. } if !*wide => {
                        Some(ctypes::string_value(value))
                    }
                    LiteralKind::String { value, .. } => Some(ctypes::wstring_value(value)),
                    _ => {
                        self.unsupported(l.span, "this literal as a string");
                        None
                    }
                };
            }
            t => match t.elementary() {
                Some(e) => e,
                None => {
                    self.unsupported(l.span, "a literal of this type");
                    return None;
                }
            },
        };
        let c = match &l.kind {
            LiteralKind::Int(i) => {
                if e.is_real() {
                    ctypes::real_literal(e, *i as f64)
                } else {
                    ctypes::int_literal(e, *i)
                }
            }
            LiteralKind::Real(r) => ctypes::real_literal(e, *r),
            LiteralKind::Bool(b) => ctypes::int_literal(e, i128::from(*b)),
            LiteralKind::Duration(ns) | LiteralKind::DateAndTime(ns) => {
                if e.is_real() {
                    ctypes::real_literal(e, *ns as f64 / 1e6)
                } else {
                    ctypes::int_literal(e, *ns)
                }
            }
            LiteralKind::TimeOfDay(ns) => ctypes::int_literal(e, i128::from(*ns)),
            LiteralKind::Date(days) => {
                ctypes::int_literal(e, i128::from(*days) * 86_400_000_000_000)
            }
            // edition 3's characters (`CHAR#'A'`, or `'A'` where a CHAR is expected): the code
            LiteralKind::String { value, .. } if e.is_char() => ctypes::int_literal(
                e,
                value.chars().next().map_or(0, |c| i128::from(u32::from(c))),
            ),
            LiteralKind::String { .. } => {
                self.unsupported(l.span, "a string literal where a number is expected");
                return None;
            }
        };
        Some(c)
    }
}

fn clamp64(v: i128) -> String {
    let v = v.clamp(i64::MIN as i128 + 1, i64::MAX as i128);
    if v < 0 {
        cfmt!("-INT64_C({})", -v)
    } else {
        cfmt!("INT64_C({v})")
    }
}

/// The runtime's functions of a [`Place::StrByte`] of type `ty` (BYTE: a STRING's, WORD: a
/// WSTRING's).
fn str_byte_fn(ty: &Type) -> &'static str {
    if matches!(ty, Type::Elementary(E::Word)) {
        "ladderc_wstr_word"
    } else {
        "ladderc_str_byte"
    }
}

/// The C constant masking the low `width` bits of a `uint64_t` (a partial access, [`Place::Part`]).
fn part_mask(width: u32) -> String {
    if width >= 64 {
        "UINT64_MAX".to_string()
    } else {
        format!("((uint64_t){:#x}u)", (1u64 << width) - 1)
    }
}

/// Whether `name` is a temporary of the ST lowering (`_ST_T3`, `_STX_T1` inside LD/FBD, `_ITF_T2`,
/// `_ST_INIT_T1` in a B&R program's `_INIT`; see `il_frontend::st::lower`).
fn is_temporary(name: &str) -> bool {
    ["_ST_T", "_STX_T", "_ITF_T", "_ST_INIT_T", "_ST_EXIT_T"]
        .iter()
        .any(|p| {
            name.strip_prefix(p)
                .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
        })
}
