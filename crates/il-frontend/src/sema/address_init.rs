//! `p : POINTER TO INT := ADR(a);` (CODESYS, TwinCAT): a reference variable whose initial value is
//! the address of another variable of its POU.
//!
//! Input: the declarations of one POU (the parse keeps `ADR(path)` as the initial value, a name
//! with fields and constant subscripts) and the variables declared from them. Output: the
//! reference's initial value as a [`ConstValue::Address`] (the C initialises it with the address,
//! `emit::init`), or one located error. Invariants: the address is taken only of storage that lives
//! as long as the reference: a variable of the same POU that is not located, not a VAR_IN_OUT or
//! VAR_EXTERNAL (no storage of the POU) and not a VAR_TEMP unless the reference is one too; fields
//! are structure fields, subscripts are in their bounds, and the variable's type is the
//! reference's target type, an array of it, or (W1425) another type holding no reference (E0305,
//! E1006 otherwise). In a global variable list or a structure no
//! address is taken (E0305): their storage is laid out apart from the POUs'.

use super::model::*;
use super::Analyzer;
use crate::ast::{self, Accessor, LiteralKind, Operand, VarKind};
use diagnostics::{code, Span};

/// The steps of an `ADR(path)` initial value from its base variable, and the type names (from, to)
/// when the pointer reads the variable as another type (W1425).
type AddressOf = (Vec<AddressStep>, Option<(String, String)>);

impl Analyzer<'_> {
    /// Sets the `ADR(path)` initial values of `out`, declared from `blocks` (see the module
    /// documentation); `pou`: the kind of the POU, `None` for a structure or global list.
    pub(super) fn address_initial_values(
        &mut self,
        blocks: &[ast::VarBlock],
        out: &mut [Variable],
        pou: Option<ast::PouKind>,
    ) {
        for d in blocks.iter().flat_map(|b| &b.vars) {
            if let Some(ast::Initializer::Struct(elements, _)) = &d.init {
                self.address_elements(d, elements, out, pou);
                continue;
            }
            let Some(ast::Initializer::Value(Operand::Ref(r))) = &d.init else {
                continue;
            };
            let Some(path) = &r.of else { continue };
            let Some(i) = out.iter().position(|v| v.span == d.name.span) else {
                continue;
            };
            let Type::Ref(target) = out[i].ty.clone() else {
                continue;
            };
            match self.address_of(path, r.span, &out[i], &target, out, pou) {
                Ok((steps, reinterpreted)) => {
                    if let Some((from, to)) = reinterpreted {
                        self.reinterpreted_initial_value(r.span, &from, &to);
                    }
                    out[i].init = Some(ConstValue::Address(AddressInit {
                        of_var: out[i].name.clone(),
                        within: Vec::new(),
                        base: path.base.name.clone(),
                        steps,
                    }));
                }
                Err((code, message)) => {
                    self.error(code, r.span, message)
                        .label("initial value")
                        .hint("start it as `ADR(x)` of a variable of the same POU whose type it refers to, or set it in the body (`p := ADR(x);`)");
                }
            }
        }
    }

    /// The `name := ADR(path)` elements of the structure or instance initializer of `d` (CODESYS,
    /// TwinCAT: `fbM : FB_M := (pLamp := ADR(lamp));`): each a pointer field or input of the
    /// declared type that starts as the address of a variable of the POU, added to the variable's
    /// initial value (the other elements are there already, `decls`).
    fn address_elements(
        &mut self,
        d: &ast::VarDecl,
        elements: &[(ast::Ident, ast::Initializer)],
        out: &mut [Variable],
        pou: Option<ast::PouKind>,
    ) {
        let Some(i) = out.iter().position(|v| v.span == d.name.span) else {
            return;
        };
        for (name, value) in elements {
            let ast::Initializer::Value(Operand::Ref(r)) = value else {
                continue;
            };
            let Some(path) = &r.of else { continue };
            let field = match &out[i].ty {
                Type::Struct(id) => match &self.model.user_type(*id).def {
                    UserTypeDef::Struct { fields } => fields
                        .iter()
                        .find(|f| name.is(&f.name))
                        .map(|f| (f.name.clone(), f.ty.clone())),
                    _ => None,
                },
                Type::Fb(FbType::User(id)) => self.model.pous[id.0 as usize]
                    .vars
                    .iter()
                    .find(|v| v.is(&name.name) && v.kind != VarKind::InOut)
                    .map(|v| (v.name.clone(), v.ty.clone())),
                // reported by `decls` (no such field: E1025)
                _ => None,
            };
            // no such field: E1025 from `decls`; not a reference: E1006 below
            let Some((field, field_ty)) = field else {
                continue;
            };
            let Type::Ref(target) = field_ty.clone() else {
                let t = self.type_name(&field_ty);
                self.error(
                    code::E1006,
                    r.span,
                    format!("cannot store an address into {t}"),
                )
                .label("initial value")
                .hint(format!(
                    "`{field}` is no POINTER TO, REF_TO or REFERENCE TO"
                ));
                continue;
            };
            let reference = Variable {
                name: format!("{}.{field}", out[i].name),
                ..out[i].clone()
            };
            match self.address_of(path, r.span, &reference, &target, out, pou) {
                Ok((steps, reinterpreted)) => {
                    if let Some((from, to)) = reinterpreted {
                        self.reinterpreted_initial_value(r.span, &from, &to);
                    }
                    let address = ConstValue::Address(AddressInit {
                        of_var: out[i].name.clone(),
                        within: vec![field.clone()],
                        base: path.base.name.clone(),
                        steps,
                    });
                    match &mut out[i].init {
                        Some(ConstValue::Struct(values)) => values.push((field, address)),
                        other => *other = Some(ConstValue::Struct(vec![(field, address)])),
                    }
                }
                Err((code, message)) => {
                    self.error(code, r.span, message)
                        .label("initial value")
                        .hint("start it as `ADR(x)` of a variable of the same POU whose type it refers to, or set it in the body (`p := ADR(x);`)");
                }
            }
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

    /// The steps of `path` from its base variable, or the error to report.
    fn address_of(
        &self,
        path: &ast::VarRef,
        _span: Span,
        reference: &Variable,
        target: &Type,
        out: &[Variable],
        pou: Option<ast::PouKind>,
    ) -> Result<AddressOf, (diagnostics::Code, String)> {
        let text = crate::print::var_ref_text(path);
        let refuse = |why: &str| {
            Err((
                code::E0305,
                format!("`{}` cannot start as `ADR({text})`: {why}", reference.name),
            ))
        };
        if pou.is_none() {
            return refuse("only a variable of a POU starts as the address of another");
        }
        let Some(base) = out.iter().find(|v| path.base.is(&v.name)) else {
            return refuse(&format!("`{}` is no variable of this POU", path.base.name));
        };
        if base.location.is_some() {
            return refuse("a located variable lives in the process image, which has no address");
        }
        if matches!(base.kind, VarKind::InOut | VarKind::External) {
            return refuse("a VAR_IN_OUT or VAR_EXTERNAL has no storage of this POU");
        }
        if base.kind == VarKind::Temp && reference.kind != VarKind::Temp {
            return refuse("a VAR_TEMP variable lives for one call");
        }
        let mut ty = base.ty.clone();
        let mut steps = Vec::new();
        for acc in path.accessors.iter() {
            match acc {
                Accessor::Field(f) => {
                    let field = match &ty {
                        Type::Struct(id) => match &self.model.user_type(*id).def {
                            UserTypeDef::Struct { fields } => {
                                fields.iter().find(|x| f.is(&x.name)).map(|x| x.ty.clone())
                            }
                            _ => None,
                        },
                        _ => None,
                    };
                    let Some(field) = field else {
                        return refuse(&format!("`{}` is no field of a structure there", f.name));
                    };
                    steps.push(AddressStep::Field(f.name.clone()));
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
                return Ok((steps, Some(names)));
            }
            let (from, to) = names;
            return Err((code::E1006, format!("cannot store {from} into {to}")));
        }
        Ok((steps, None))
    }
}
