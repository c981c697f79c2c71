//! `p : POINTER TO INT := ADR(a);` (CODESYS, TwinCAT): a reference variable whose initial value is
//! the address of another variable of its POU, or of a global variable.
//!
//! Input: the declarations of one POU or of the global variables (the parse keeps `ADR(path)` as
//! the initial value, a name with fields and constant subscripts, also as an element of a
//! structure or instance initializer at any depth: `o : FB_O := (inner := (pL := ADR(y)))`) and
//! the variables declared from them. Output: the reference's initial value as a
//! [`ConstValue::Address`] (the C initialises it with the address, `emit::init`), or one located
//! error. Invariants: the address is taken only of storage that lives as long as the reference: a
//! variable of the same POU that is not located, not a VAR_IN_OUT and not a VAR_TEMP unless the
//! reference is one too, or a global variable that is not located (named directly, through a
//! VAR_EXTERNAL or qualified by its list, `GVL.x`); fields are structure fields or an instance's
//! variables, subscripts are in their bounds, and the variable's type is the reference's target
//! type, an array of it, or (W1425) another type holding no reference (E0305, E1006 otherwise). A
//! global variable's address initial value (TwinCAT's `fb : FB_M := (pLamp := ADR(GVL.lamp))` in a
//! GVL) is set once every global is declared (`global_address_initial_values`). The elements of
//! an array's initial value (`[ADR(a), ADR(b)]`, `[(p := ADR(a))]`) each start so, their place a
//! step `[i]` of [`AddressInit::within`]. In a structure's field declaration no address is taken
//! (E0305): never dropped silently.

use super::model::*;
use super::Analyzer;
use crate::ast::{self, Accessor, LiteralKind, Operand, VarKind};
use diagnostics::{code, Span};

/// The address an `ADR(path)` initial value stands for: the steps from its base variable, the
/// base's name, the global it is when it is one, and the type names (from, to) when the pointer
/// reads the variable as another type (W1425).
struct AddressOf {
    steps: Vec<AddressStep>,
    base: String,
    global: Option<GlobalRef>,
    reinterpreted: Option<(String, String)>,
}

/// An address found in an initial value: the steps to the reference, the row-major positions
/// of its array steps, the address.
type Found = (Vec<String>, Vec<usize>, ConstValue);

/// Where the base variable of an `ADR(path)` initial value is looked up.
#[derive(Clone, Copy)]
enum Scope<'a> {
    /// The variables of a POU (then the global variables).
    Pou(&'a [Variable]),
    /// A structure's field declaration: no address is taken.
    Struct,
    /// The global variables, every one declared.
    Globals,
}

/// Whether `init` holds an `ADR(...)` anywhere.
fn holds_address(init: &ast::Initializer) -> bool {
    match init {
        ast::Initializer::Value(Operand::Ref(r)) => r.of.is_some(),
        ast::Initializer::Value(_) => false,
        ast::Initializer::Array(elements, _) => elements.iter().any(|e| holds_address(&e.value)),
        ast::Initializer::Struct(elements, _) => elements.iter().any(|(_, v)| holds_address(v)),
    }
}

/// Puts `value` at the fields `path` inside the initial value `slot` (a structure's or an
/// instance's field values, created where missing); a step `[i]...` of `path` (an element of an
/// array, see [`element_step`]) takes the next row-major position of `positions`.
fn insert_at(
    slot: &mut Option<ConstValue>,
    path: &[String],
    positions: &[usize],
    value: ConstValue,
) {
    let Some((first, rest)) = path.split_first() else {
        *slot = Some(value);
        return;
    };
    if first.starts_with('[') {
        let Some((&at, later)) = positions.split_first() else {
            return;
        };
        if !matches!(slot, Some(ConstValue::Array(_))) {
            *slot = Some(ConstValue::Array(Vec::new()));
        }
        let Some(ConstValue::Array(values)) = slot else {
            return;
        };
        if values.len() <= at {
            // (an empty value is the element type's default: `emit::init`)
            values.resize(at + 1, ConstValue::Struct(Vec::new()));
        }
        let mut inner = Some(std::mem::replace(
            &mut values[at],
            ConstValue::Struct(Vec::new()),
        ));
        insert_at(&mut inner, rest, later, value);
        if let Some(v) = inner {
            values[at] = v;
        }
        return;
    }
    if !matches!(slot, Some(ConstValue::Struct(_))) {
        *slot = Some(ConstValue::Struct(Vec::new()));
    }
    let Some(ConstValue::Struct(values)) = slot else {
        return;
    };
    let i = match values
        .iter()
        .position(|(n, _)| n.eq_ignore_ascii_case(first))
    {
        Some(i) => i,
        None => {
            values.push((first.clone(), ConstValue::Struct(Vec::new())));
            values.len() - 1
        }
    };
    let mut inner = Some(std::mem::replace(
        &mut values[i].1,
        ConstValue::Struct(Vec::new()),
    ));
    insert_at(&mut inner, rest, positions, value);
    if let Some(v) = inner {
        values[i].1 = v;
    }
}

/// The step of an [`AddressInit::within`] path to the element at row-major position `at` of an
/// array of dimensions `dims`: its zero-based subscripts, `[1][0]` (as the C writes them).
fn element_step(dims: &[Dim], at: usize) -> String {
    let mut rest = at as u128;
    let mut subs = vec![0u128; dims.len()];
    for (d, dim) in dims.iter().enumerate().rev() {
        let len = dim.len().max(1);
        subs[d] = rest % len;
        rest /= len;
    }
    subs.iter().map(|s| format!("[{s}]")).collect()
}

impl Analyzer<'_> {
    /// Sets the `ADR(path)` initial values of `out`, declared from `blocks` (see the module
    /// documentation); `pou`: the kind of the POU, `None` for a structure (a global list's are
    /// set by `global_address_initial_values`).
    pub(super) fn address_initial_values(
        &mut self,
        blocks: &[ast::VarBlock],
        out: &mut [Variable],
        pou: Option<ast::PouKind>,
    ) {
        for d in blocks.iter().flat_map(|b| &b.vars) {
            let Some(init) = d.init.as_ref().filter(|i| holds_address(i)) else {
                continue;
            };
            let Some(i) = out.iter().position(|v| v.span == d.name.span) else {
                continue;
            };
            let scope = match pou {
                Some(_) => Scope::Pou(out),
                None => Scope::Struct,
            };
            let var = out[i].clone();
            let found = self.addresses_in(init, &var, scope);
            for (within, positions, address) in found {
                insert_at(&mut out[i].init, &within, &positions, address);
            }
        }
    }

    /// Sets the `ADR(path)` initial values of the global variables declared by `units` (VAR_GLOBAL
    /// of the file, of a configuration or of a resource), once every global is declared: the
    /// address of a global, as TwinCAT initialises a GVL's `fbLamp : FB_Lamp := (pLamp :=
    /// ADR(GVL_IO.bLamp))`.
    pub(super) fn global_address_initial_values(&mut self, units: &[ast::CompilationUnit]) {
        let mut blocks: Vec<&ast::VarBlock> = Vec::new();
        for unit in units {
            for item in &unit.items {
                match item {
                    ast::LibraryElement::GlobalVars(b) => blocks.push(b),
                    ast::LibraryElement::Configuration(c) => {
                        blocks.extend(&c.globals);
                        for r in &c.resources {
                            blocks.extend(&r.globals);
                        }
                    }
                    _ => {}
                }
            }
        }
        for d in blocks.iter().flat_map(|b| &b.vars) {
            let Some(init) = d.init.as_ref().filter(|i| holds_address(i)) else {
                continue;
            };
            let Some(r) = self.global_declared_at(d.name.span) else {
                continue;
            };
            let var = self.model.global(r).clone();
            let found = self.addresses_in(init, &var, Scope::Globals);
            let slot = &mut self.global_mut(r).init;
            for (within, positions, address) in found {
                insert_at(slot, &within, &positions, address);
            }
        }
    }

    /// The global variable declared at `span`.
    fn global_declared_at(&self, span: Span) -> Option<GlobalRef> {
        if let Some(i) = self.model.globals.iter().position(|g| g.span == span) {
            return Some(GlobalRef::Free(i));
        }
        for (config, c) in self.model.configurations.iter().enumerate() {
            if let Some(index) = c.globals.iter().position(|g| g.span == span) {
                return Some(GlobalRef::Configuration { config, index });
            }
            for (resource, r) in c.resources.iter().enumerate() {
                if let Some(index) = r.globals.iter().position(|g| g.span == span) {
                    return Some(GlobalRef::Resource {
                        config,
                        resource,
                        index,
                    });
                }
            }
        }
        None
    }

    fn global_mut(&mut self, r: GlobalRef) -> &mut Variable {
        match r {
            GlobalRef::Free(i) => &mut self.model.globals[i],
            GlobalRef::Configuration { config, index } => {
                &mut self.model.configurations[config].globals[index]
            }
            GlobalRef::Resource {
                config,
                resource,
                index,
            } => &mut self.model.configurations[config].resources[resource].globals[index],
        }
    }

    /// The field or input `name` of a value of type `ty` (a structure's field, an instance's
    /// variable other than a VAR_IN_OUT): its name as declared and its type.
    fn member_of(&self, ty: &Type, name: &str) -> Option<(String, Type)> {
        match ty {
            Type::Struct(id) => match &self.model.user_type(*id).def {
                UserTypeDef::Struct { fields } => fields
                    .iter()
                    .find(|f| f.name.eq_ignore_ascii_case(name))
                    .map(|f| (f.name.clone(), f.ty.clone())),
                _ => None,
            },
            Type::Fb(FbType::User(id)) => self.model.pous[id.0 as usize]
                .vars
                .iter()
                .find(|v| v.is(name) && v.kind != VarKind::InOut)
                .map(|v| (v.name.clone(), v.ty.clone())),
            _ => None,
        }
    }

    /// The addresses of the `ADR(path)` in the initial value `init` of `var` (at any depth of its
    /// structure or instance initializers), each with the fields from `var` to the reference it
    /// starts (`["inner", "pL"]`); reports what cannot start so.
    fn addresses_in(
        &mut self,
        init: &ast::Initializer,
        var: &Variable,
        scope: Scope<'_>,
    ) -> Vec<Found> {
        let mut found = Vec::new();
        let mut within = Vec::new();
        let mut positions = Vec::new();
        self.collect_addresses(
            init,
            &var.ty,
            var,
            scope,
            (&mut within, &mut positions),
            &mut found,
        );
        found
    }

    fn collect_addresses(
        &mut self,
        init: &ast::Initializer,
        ty: &Type,
        var: &Variable,
        scope: Scope<'_>,
        (within, positions): (&mut Vec<String>, &mut Vec<usize>),
        found: &mut Vec<Found>,
    ) {
        match init {
            ast::Initializer::Value(Operand::Ref(r)) => {
                let Some(path) = &r.of else { return };
                let Type::Ref(target) = ty else {
                    // a variable's own type is checked with its initial value (`decls`)
                    if !within.is_empty() {
                        let mut field = var.name.clone();
                        for f in within.iter() {
                            if !f.starts_with('[') {
                                field.push('.');
                            }
                            field.push_str(f);
                        }
                        let t = self.type_name(ty);
                        self.error(
                            code::E1006,
                            r.span,
                            format!("cannot store an address into {t}"),
                        )
                        .label("initial value")
                        .hint(format!(
                            "`{field}` is no POINTER TO, REF_TO or REFERENCE TO"
                        ));
                    }
                    return;
                };
                let mut name = var.name.clone();
                for f in within.iter() {
                    if !f.starts_with('[') {
                        name.push('.');
                    }
                    name.push_str(f);
                }
                let reference = Variable {
                    name,
                    ..var.clone()
                };
                match self.address_of(path, &reference, target, scope) {
                    Ok(a) => {
                        if let Some((from, to)) = &a.reinterpreted {
                            self.reinterpreted_initial_value(r.span, from, to);
                        }
                        let address = ConstValue::Address(AddressInit {
                            of_var: var.name.clone(),
                            within: within.clone(),
                            base: a.base,
                            global: a.global,
                            steps: a.steps,
                        });
                        found.push((within.clone(), positions.clone(), address));
                    }
                    Err((code, message)) => {
                        self.error(code, r.span, message)
                            .label("initial value")
                            .hint("start it as `ADR(x)` of a variable of the same POU or a global variable whose type it refers to, or set it in the body (`p := ADR(x);`)");
                    }
                }
            }
            ast::Initializer::Value(_) => {}
            ast::Initializer::Struct(elements, _) => {
                for (name, value) in elements {
                    // no such field: E1025 from `decls`
                    let Some((field, field_ty)) = self.member_of(ty, &name.name) else {
                        continue;
                    };
                    within.push(field);
                    self.collect_addresses(
                        value,
                        &field_ty,
                        var,
                        scope,
                        (within, positions),
                        found,
                    );
                    within.pop();
                }
            }
            ast::Initializer::Array(elements, _) => {
                // (an array's initial value given to what is no array: E1025 from `decls`)
                let Type::Array { dims, element } = ty else {
                    return;
                };
                if matches!(scope, Scope::Struct) {
                    // one error for the array, at its first address
                    for e in elements {
                        if self.refuse_addresses_in(&e.value, var) {
                            break;
                        }
                    }
                    return;
                }
                // `[ADR(a), ADR(b)]` (CODESYS, TwinCAT): each element's address in its place
                // (too many values: E1025 from `decls`)
                let total = dims.iter().fold(1u128, |n, d| n.saturating_mul(d.len()));
                let mut at = 0usize;
                for e in elements {
                    let repeat = e.repeat.unwrap_or(1) as usize;
                    if holds_address(&e.value) {
                        for k in at..at.saturating_add(repeat) {
                            if k as u128 >= total {
                                break;
                            }
                            within.push(element_step(dims, k));
                            positions.push(k);
                            self.collect_addresses(
                                &e.value,
                                element,
                                var,
                                scope,
                                (within, positions),
                                found,
                            );
                            positions.pop();
                            within.pop();
                        }
                    }
                    at = at.saturating_add(repeat);
                }
            }
        }
    }

    /// E0305 at the first `ADR(...)` of `init`, an element of an array's initial value in a
    /// structure type's field declaration; whether there is one.
    fn refuse_addresses_in(&mut self, init: &ast::Initializer, var: &Variable) -> bool {
        match init {
            ast::Initializer::Value(Operand::Ref(r)) if r.of.is_some() => {
                let text =
                    r.of.as_ref()
                        .map(crate::print::var_ref_text)
                        .unwrap_or_default();
                self.error(
                    code::E0305,
                    r.span,
                    format!(
                        "`{}` cannot start as `ADR({text})`: a structure's field does not start as an address",
                        var.name
                    ),
                )
                .label("initial value")
                .hint("give the address in the initial value of a variable of the structure type (`s : ST := (ps := [ADR(x)]);`), or set it in the body");
                true
            }
            ast::Initializer::Value(_) => false,
            ast::Initializer::Array(elements, _) => elements
                .iter()
                .any(|e| self.refuse_addresses_in(&e.value, var)),
            ast::Initializer::Struct(elements, _) => elements
                .iter()
                .any(|(_, v)| self.refuse_addresses_in(v, var)),
        }
    }

    /// W1425 at `span`: an `ADR(x)` initial value makes a pointer read `x` as another type.
    fn reinterpreted_initial_value(&mut self, span: Span, from: &str, to: &str) {
        self.warning(
            code::W1425,
            span,
            format!("{from} stored into {to}: the pointer reads the same bytes as another type"),
        )
        .label("initial value")
        .hint("IEC 61131-3 keeps references typed; CODESYS and TwinCAT convert pointers freely. Accesses stay inside the variable the pointer was made from and must be aligned for the new type");
    }

    /// The global variable `path` starts with (`x`, or `GVL.x` qualified by its list), and how
    /// many of its accessors name it.
    fn global_base(&self, path: &ast::VarRef) -> Option<(GlobalRef, usize)> {
        if let Some(list) = self.model.global_list(&path.base.name) {
            if let Some(Accessor::Field(m)) = path.accessors.first() {
                return list
                    .members
                    .iter()
                    .find(|r| m.is(&self.model.global(**r).name))
                    .map(|r| (*r, 1));
            }
        }
        self.find_global(&path.base.name).map(|r| (r, 0))
    }

    /// The address `path` stands for, or the error to report.
    fn address_of(
        &self,
        path: &ast::VarRef,
        reference: &Variable,
        target: &Type,
        scope: Scope<'_>,
    ) -> Result<AddressOf, (diagnostics::Code, String)> {
        let text = crate::print::var_ref_text(path);
        let refuse = |why: &str| {
            Err((
                code::E0305,
                format!("`{}` cannot start as `ADR({text})`: {why}", reference.name),
            ))
        };
        let own = match scope {
            Scope::Struct => {
                return refuse("a structure's field does not start as an address");
            }
            Scope::Pou(out) => out.iter().find(|v| path.base.is(&v.name)),
            Scope::Globals => None,
        };
        // a variable of the POU (not a VAR_EXTERNAL), else a global variable
        let (base, global, skip) = match own.filter(|v| v.kind != VarKind::External) {
            Some(v) => (v.clone(), None, 0),
            None => match self.global_base(path) {
                Some((r, skip)) => (self.model.global(r).clone(), Some(r), skip),
                None if matches!(scope, Scope::Globals) => {
                    return refuse(&format!("`{}` is no global variable", path.base.name))
                }
                None => {
                    return refuse(&format!(
                        "`{}` is no variable of this POU and no global variable",
                        path.base.name
                    ))
                }
            },
        };
        if base.location.is_some() {
            return refuse("a located variable lives in the process image, which has no address");
        }
        if base.kind == VarKind::InOut {
            return refuse("a VAR_IN_OUT has no storage of this POU");
        }
        if base.kind == VarKind::Temp && reference.kind != VarKind::Temp {
            return refuse("a VAR_TEMP variable lives for one call");
        }
        let mut ty = base.ty.clone();
        let mut steps = Vec::new();
        for acc in path.accessors.iter().skip(skip) {
            match acc {
                Accessor::Field(f) => {
                    let Some((name, field)) = self.member_of(&ty, &f.name) else {
                        return refuse(&format!(
                            "`{}` is no field of a structure or an instance there",
                            f.name
                        ));
                    };
                    steps.push(AddressStep::Field(name));
                    ty = field;
                }
                Accessor::Index(subs) => {
                    let Type::Array { dims, element } = &ty else {
                        return refuse("a subscript on what is no array");
                    };
                    if dims.len() != subs.len() {
                        return refuse("the subscripts do not match the array's dimensions");
                    }
                    let mut offsets = Vec::new();
                    for (d, s) in dims.iter().zip(subs) {
                        let Operand::Literal(l) = s else {
                            return refuse("subscripts must be integer literals");
                        };
                        let LiteralKind::Int(v) = l.kind else {
                            return refuse("subscripts must be integer literals");
                        };
                        if v < d.lower || v > d.upper {
                            return refuse(&format!(
                                "subscript {v} is outside {}..{}",
                                d.lower, d.upper
                            ));
                        }
                        offsets.push(u64::try_from(v - d.lower).unwrap_or(0));
                    }
                    steps.push(AddressStep::Index(offsets));
                    ty = (**element).clone();
                }
                Accessor::Deref(_) => return refuse("a dereference has no fixed address"),
            }
        }
        let mut address = AddressOf {
            steps,
            base: base.name.clone(),
            global,
            reinterpreted: None,
        };
        let (from, to) = (
            Type::Ref(Box::new(ty.clone())),
            Type::Ref(Box::new(target.clone())),
        );
        if &ty != target
            && !ty.is_error()
            && !target.is_error()
            && !super::typing::decays_to(&ty, target)
        {
            let names = (self.type_name(&from), self.type_name(&to));
            if super::typing::pointer_reinterprets(&from, &to, &self.model) {
                address.reinterpreted = Some(names);
                return Ok(address);
            }
            let (from, to) = names;
            return Err((code::E1006, format!("cannot store {from} into {to}")));
        }
        Ok(address)
    }
}
