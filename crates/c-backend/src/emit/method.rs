//! Template-method functions (paper A, method 2) rendered inside their POU.
//!
//! Input: the [`PouMethod`]s of the parameter-passing stage: a head (one C local per block parameter,
//! initialised from an IEC operand of the POU), the library body (C text that only uses those locals,
//! the template's own locals and the motion runtime), a tail (feedback assignments of locals to IEC
//! operands). Output: in `program.c`, a prototype `static void NAME(POU_STRUCT *self);` before the POU
//! functions and its definition after them; a `FUNC NAME()` in that POU's body calls `NAME(self)`.
//! Invariants: head values and feedback targets are rendered by the same operand/place code as IL
//! instructions (so globals, located variables, fields and conversions behave exactly as in `LD`/`ST`);
//! a method is only callable from its own POU (a PROGRAM or FUNCTION_BLOCK). Head locals named
//! `base[k]` (consecutive, `k` = 0, 1, ...) are the elements of one array parameter: they become one C
//! array `c_type base[n] = { ... };` initialised element by element; feedback from `base[k]` reads the
//! element.

use super::scope::Scope;
use super::values::convert;
use super::Gen;
use crate::{mangle, PouMethod};
use diagnostics::{code, Diagnostic};
use il_frontend::ast::PouKind;
use il_frontend::sema::{Elementary as E, PouId, Type};
use std::fmt::Write as _;

/// The IEC type whose C representation is `c_type` (a head local's declared type).
fn iec_type_of(c_type: &str, boolean: bool) -> Option<Type> {
    let e = match c_type {
        "uint8_t" if boolean => E::Bool,
        "uint8_t" => E::Usint,
        "int8_t" => E::Sint,
        "uint16_t" => E::Uint,
        "int16_t" => E::Int,
        "uint32_t" => E::Udint,
        "int32_t" => E::Dint,
        "uint64_t" => E::Ulint,
        "int64_t" => E::Lint,
        "float" => E::Real,
        "double" => E::Lreal,
        _ => return None,
    };
    Some(Type::Elementary(e))
}

/// `Some((base, k))` when a head local names element `k` of an array local (`Pos_1[3]`).
fn array_element(local: &str) -> Option<(&str, usize)> {
    let (base, rest) = local.split_once('[')?;
    let k = rest.strip_suffix(']')?.parse().ok()?;
    let ident = base.bytes().next().is_some_and(|b| !b.is_ascii_digit())
        && base.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_');
    ident.then_some((base, k))
}

/// Writes the declaration of a completed array local `(base, C type, element values)`.
fn flush_array(c: &mut String, array: Option<(String, String, Vec<String>)>) {
    if let Some((base, ty, elems)) = array {
        let _ = writeln!(
            c,
            "    {ty} {base}[{}] = {{\n        {}\n    }};",
            elems.len(),
            elems.join(",\n        ")
        );
    }
}

impl Gen<'_> {
    /// Refuses methods whose names are not plain C identifiers or clash with another function (E2007);
    /// they are dropped.
    pub fn check_methods(&mut self) {
        let mut seen = std::collections::HashSet::new();
        let methods = std::mem::take(&mut self.methods);
        for m in methods {
            let key = m.name.to_ascii_uppercase();
            if !mangle::is_valid_embedded_name(&m.name)
                || self.embedded.contains_key(&key)
                || !seen.insert(key)
            {
                self.diags.push(
                    Diagnostic::error(
                        code::E2007,
                        format!(
                            "invalid synthesised function name `{}` (not a plain C identifier, reserved, or supplied twice)",
                            m.name.escape_default()
                        ),
                    )
                    .at(m.span),
                );
                continue;
            }
            self.methods.push(m);
        }
    }

    /// Whether `FUNC name` calls a method.
    pub fn is_method(&self, name: &il_frontend::ast::Ident) -> bool {
        self.methods
            .iter()
            .any(|m| m.name.eq_ignore_ascii_case(&name.name))
    }

    /// The POU a method belongs to (a program or function block), or a reported error.
    fn method_pou(&mut self, m: &PouMethod) -> Option<PouId> {
        match self.model.pou_by_name(&m.pou) {
            Some(id) if self.model.pou(id).kind != PouKind::Function => Some(id),
            _ => {
                self.report_once(
                    Diagnostic::error(
                        code::E2005,
                        format!(
                            "the block call `{}` is in `{}`, which is not a PROGRAM or FUNCTION_BLOCK",
                            m.name, m.pou
                        ),
                    )
                    .at(m.span)
                    .with_hint("call PLCopen blocks from a PROGRAM or FUNCTION_BLOCK"),
                );
                None
            }
        }
    }

    /// Prototypes of the methods (before the POU functions), with what their bodies need.
    pub fn method_prototypes(&mut self, c: &mut String) {
        if self.methods.is_empty() {
            return;
        }
        c.push_str("/* Template-method functions (parameter passing) */\n#include \"motion_lib.h\"\nstruct McEngine *ladderc_motion_engine(void);\n");
        for i in 0..self.methods.len() {
            let m = self.methods[i].clone();
            if let Some(id) = self.method_pou(&m) {
                let s = self.pou_struct(&self.model.pou(id).clone());
                let _ = writeln!(c, "static void {}({s} *self);", m.name);
            }
        }
        c.push('\n');
    }

    /// Definitions of the methods.
    pub fn method_definitions(&mut self, c: &mut String) {
        for i in 0..self.methods.len() {
            let m = self.methods[i].clone();
            let Some(id) = self.method_pou(&m) else {
                continue;
            };
            let p = self.model.pou(id).clone();
            let scope = Scope::for_pou(self.model.pou(id), id);
            let s = self.pou_struct(&p);
            let _ = writeln!(c, "static void {}({s} *self) {{", m.name);
            let _ = writeln!(c, "    int FuncNum = {};", m.func_num);
            let mut arrays: Vec<(String, String, Vec<String>)> = Vec::new();
            for h in &m.head {
                let Some(want) = iec_type_of(&h.c_type, h.boolean) else {
                    self.unsupported(m.span, format!("a parameter of C type `{}`", h.c_type));
                    continue;
                };
                let v = self
                    .value(&scope, &h.source, &want)
                    .unwrap_or_else(|| "0".into());
                match array_element(&h.local) {
                    Some((base, k)) => {
                        let value = format!("({}){v}", h.c_type);
                        match arrays.last_mut() {
                            Some((b, _, elems)) if b == base && elems.len() == k => {
                                elems.push(value)
                            }
                            _ if k == 0 => {
                                flush_array(c, arrays.pop());
                                arrays.push((base.to_string(), h.c_type.clone(), vec![value]));
                            }
                            _ => self.unsupported(
                                m.span,
                                format!("array element `{}` out of order", h.local),
                            ),
                        }
                    }
                    None => {
                        flush_array(c, arrays.pop());
                        let _ = writeln!(c, "    {} {} = ({}){v};", h.c_type, h.local, h.c_type);
                    }
                }
            }
            flush_array(c, arrays.pop());
            for (ty, name) in &m.locals {
                let _ = writeln!(c, "    {ty} {name};");
            }
            c.push_str(&m.body);
            if !m.body.ends_with('\n') {
                c.push('\n');
            }
            for f in &m.tail {
                let Some(from) = iec_type_of(&f.c_type, f.boolean) else {
                    continue;
                };
                let Some(place) = self.operand_place(&scope, &f.target) else {
                    continue;
                };
                let value = if f.boolean {
                    let t = if f.negated { "==" } else { "!=" };
                    format!("(IEC_BOOL)({} {t} 0u)", f.local)
                } else {
                    convert(&f.local, &from, place.ty())
                };
                let _ = writeln!(c, "    {}", self.store(&place, &value));
            }
            for h in &m.head {
                match array_element(&h.local) {
                    Some((base, 0)) => {
                        let _ = writeln!(c, "    (void){base};");
                    }
                    Some(_) => {}
                    None => {
                        let _ = writeln!(c, "    (void){};", h.local);
                    }
                }
            }
            c.push_str("    (void)FuncNum;\n    (void)self;\n}\n\n");
        }
    }

    /// The C call of a method from `pou` (None: not a method).
    pub fn method_call(
        &mut self,
        name: &il_frontend::ast::Ident,
        pou: Option<PouId>,
    ) -> Option<String> {
        let m = self
            .methods
            .iter()
            .find(|m| m.name.eq_ignore_ascii_case(&name.name))?
            .clone();
        let own = self.model.pou_by_name(&m.pou);
        if own.is_none() || own != pou {
            self.report_once(
                Diagnostic::error(
                    code::E2005,
                    format!(
                        "`FUNC {}` is called outside `{}`, the POU it was synthesised for",
                        name.name, m.pou
                    ),
                )
                .at(name.span),
            );
            return Some(String::new());
        }
        Some(format!("{}(self);", m.name))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn array_element_locals_are_recognised_by_their_index() {
        assert_eq!(array_element("Pos_1[3]"), Some(("Pos_1", 3)));
        assert_eq!(array_element("Pos_1[0]"), Some(("Pos_1", 0)));
        assert_eq!(array_element("Pos_1"), None);
        assert_eq!(array_element("Pos_1[k]"), None);
        assert_eq!(array_element("1x[0]"), None);
        assert_eq!(array_element("a-b[0]"), None);
    }

    #[test]
    fn an_array_local_is_declared_with_its_elements_in_order() {
        let mut c = String::new();
        flush_array(&mut c, None);
        assert!(c.is_empty());
        flush_array(
            &mut c,
            Some((
                "Pos_1".into(),
                "double".into(),
                vec!["(double)a".into(), "(double)b".into()],
            )),
        );
        assert_eq!(
            c,
            "    double Pos_1[2] = {\n        (double)a,\n        (double)b\n    };\n"
        );
    }
}
