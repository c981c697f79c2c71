//! Access paths (`VAR_ACCESS` of a configuration, IEC 61131-3 2.7.1 / 6.8.2) in the watch table.
//!
//! Input: each configuration's [`AccessDecl`]s, the program instances, the sema model. Output: one
//! watch-table entry per access name (or per element of a structured one, `NAME.field`), aliasing
//! the variable its path names, and the names declared READ_ONLY (`ladderc_read_only[]`, which the
//! harness refuses to write from a stimulus).
//! Invariants: a path resolves through the configuration's own resources and program instances
//! (`res.prog.fb.var`, `prog.var`), its globals (`res.g`, `g`) or a direct address (`res.%IX1.1`);
//! the declared type is the variable's (its IEC name, or an alias of it). Anything else is one
//! E0308 at the entry, and the entry is left out. Access names are unique in a configuration.

use super::scan::{Instance, WatchLines};
use super::Gen;
use crate::mangle;
use diagnostics::{code, Diagnostic};
use il_frontend::ast::{AccessDecl, Configuration, Ident};
use il_frontend::sema::{FbType, GlobalRef, Type, UserTypeDef, Variable};
use std::collections::HashSet;

/// What an access path names: a variable and its C place, or a direct address.
enum Target<'m> {
    Var(&'m Variable, String),
    Field(Type, String),
}

impl<'a> Gen<'a> {
    /// The watch-table entries of every access path; returns the READ_ONLY access names.
    pub(super) fn access_entries(
        &mut self,
        configs: &[&Configuration],
        instances: &[Instance],
        out: &mut WatchLines,
    ) -> Vec<String> {
        let mut read_only = Vec::new();
        for (ci, cfg) in configs.iter().enumerate() {
            let mut seen = HashSet::new();
            for a in &cfg.access {
                if !seen.insert(a.name.key()) {
                    self.access_error(
                        a,
                        format!("the access name `{}` is declared twice", a.name.name),
                    );
                    continue;
                }
                if self.access_entry(ci, cfg, a, instances, out) && a.read_only {
                    read_only.push(a.name.name.clone());
                }
            }
        }
        read_only
    }

    fn access_error(&mut self, a: &AccessDecl, why: String) {
        self.report_once(
            Diagnostic::error(code::E0308, format!("access path `{}`: {why}", a.name.name))
                .at(a.span)
                .with_primary_label("this access path")
                .with_hint("name a variable of a program instance of this configuration (`resource.program.variable`), a global or a direct address, with its declared type"),
        );
    }

    /// One access path's entries; false (after an E0308) when it names nothing or the wrong type.
    fn access_entry(
        &mut self,
        ci: usize,
        cfg: &Configuration,
        a: &AccessDecl,
        instances: &[Instance],
        out: &mut WatchLines,
    ) -> bool {
        let name = a.name.name.as_str();
        let mut path: &[Ident] = &a.path;
        // `res.` first: that resource only
        let mut resource = None;
        if let Some(ri) = path
            .first()
            .and_then(|p| cfg.resources.iter().position(|r| r.name == *p))
            .filter(|_| path.len() > 1 || a.address.is_some())
        {
            resource = Some(ri);
            path = &path[1..];
        }
        if let Some(addr) = &a.address {
            let ty = Type::Elementary(il_frontend::sema::Location::of(addr).elementary());
            if !self.access_type_matches(&a.type_name.name, &ty) {
                let t = self.model.type_name(&ty);
                self.access_error(
                    a,
                    format!(
                        "the address is {t}, the access path says {}",
                        a.type_name.name
                    ),
                );
                return false;
            }
            return match self.locate(addr, None) {
                Ok(loc) => {
                    out.line(&cfmt!(
                        "{{ {}, {}, NULL, {}, {}, {} }}",
                        mangle::c_string(name.as_bytes()),
                        crate::ctypes::type_tag(il_frontend::sema::Location::of(addr).elementary()),
                        super::values::area_array(loc.area),
                        loc.offset,
                        loc.bit.unwrap_or(0)
                    ));
                    true
                }
                Err(d) => {
                    self.report_once(*d);
                    false
                }
            };
        }
        let Some(first) = path.first() else {
            self.access_error(a, "the path names no variable".into());
            return false;
        };
        // position in `a.path` of `path[0]` (for the subscripts written after a name)
        let skip = a.path.len() - path.len();
        let model = self.model;
        // a global of the configuration (or of the resource named), with the fields and elements
        // after it (`State.Samples[3]`), or a program instance's variable (`prog.fb.x`)
        let global = model.global_refs().into_iter().find(|&r| {
            let in_scope = match r {
                GlobalRef::Configuration { config, .. } => config == ci && resource.is_none(),
                GlobalRef::Resource {
                    config,
                    resource: rr,
                    ..
                } => config == ci && resource.is_none_or(|x| x == rr),
                GlobalRef::Free(_) => resource.is_none(),
            };
            in_scope && model.global(r).name.eq_ignore_ascii_case(&first.name)
        });
        let inst = instances.iter().find(|i| {
            i.configured.is_some_and(|(c, r, p)| {
                c == ci
                    && resource.is_none_or(|x| x == r)
                    && model.configurations[c].resources[r].programs[p]
                        .name
                        .eq_ignore_ascii_case(&first.name)
            })
        });
        let (start, members, first_member) = match (inst, global) {
            (Some(inst), _) if path.len() > 1 => {
                let Some(v) = self.pou_var(inst.pou, &path[1].name) else {
                    let p = &model.pou(inst.pou).name;
                    self.access_error(
                        a,
                        format!("program `{p}` has no variable `{}`", path[1].name),
                    );
                    return false;
                };
                let lv = cfmt!("{}.{}", inst.c_name, mangle::var(&v.name));
                (
                    self.element(a, skip + 1, Target::Var(v, lv)),
                    &path[2..],
                    skip + 2,
                )
            }
            (_, Some(r)) => {
                let t = Target::Var(model.global(r), self.global_name(r));
                (self.element(a, skip, t), &path[1..], skip + 1)
            }
            _ => {
                let what = if path.len() == 1 {
                    "global variable"
                } else {
                    "program instance or global variable"
                };
                self.access_error(
                    a,
                    format!("no {what} `{}` in this configuration", first.name),
                );
                return false;
            }
        };
        let mut target = match start {
            Ok(t) => t,
            Err(why) => {
                self.access_error(a, why);
                return false;
            }
        };
        for (m, member) in members.iter().enumerate() {
            let mut lv = match &target {
                Target::Var(_, lv) | Target::Field(_, lv) => lv.clone(),
            };
            let ty = match &target {
                Target::Var(v, _) => v.ty.clone(),
                Target::Field(t, _) => t.clone(),
            };
            let next = match &ty {
                Type::Fb(FbType::User(id)) => self
                    .pou_var(*id, &member.name)
                    .map(|f| (f.ty.clone(), mangle::var(&f.name))),
                Type::Struct(id) => self
                    .struct_field(*id, &member.name)
                    .map(|f| (f.ty.clone(), mangle::var(&f.name))),
                Type::Fb(FbType::Standard(f)) => crate::ctypes::std_fb(*f)
                    .1
                    .iter()
                    .find(|(p, _, _)| p.eq_ignore_ascii_case(&member.name))
                    .map(|(p, e, _)| (Type::Elementary(*e), (*p).to_string())),
                _ => None,
            };
            let Some((t, field)) = next else {
                let tn = model.type_name(&ty);
                self.access_error(a, format!("`{tn}` has no member `{}`", member.name));
                return false;
            };
            lv = cfmt!("{lv}.{field}");
            target = match self.element(a, first_member + m, Target::Field(t, lv)) {
                Ok(t) => t,
                Err(why) => {
                    self.access_error(a, why);
                    return false;
                }
            };
        }
        let ty = match &target {
            Target::Var(v, _) => v.ty.clone(),
            Target::Field(t, _) => t.clone(),
        };
        if !self.access_type_matches(&a.type_name.name, &ty) {
            let t = model.type_name(&ty);
            self.access_error(
                a,
                format!(
                    "the variable is {t}, the access path says {}",
                    a.type_name.name
                ),
            );
            return false;
        }
        match target {
            Target::Var(v, lv) => self.watch_var(v, name, &lv, out),
            Target::Field(t, lv) => self.watch_value(name, &lv, &t, 0, out),
        }
        true
    }

    /// `target` indexed by the subscripts written after the path's name at position `k`
    /// (`Values[2]`): the element, its C place `lv[2 - lower]`; an error when it is no array,
    /// the count of subscripts is not its dimensions' or one is outside its bounds.
    fn element<'m>(
        &self,
        a: &AccessDecl,
        k: usize,
        target: Target<'m>,
    ) -> Result<Target<'m>, String> {
        let mut target = target;
        for (_, values, _) in a.subscripts.iter().filter(|s| s.0 == k) {
            let (ty, lv) = match &target {
                Target::Var(v, lv) => (v.ty.clone(), lv.clone()),
                Target::Field(t, lv) => (t.clone(), lv.clone()),
            };
            let Type::Array { dims, element } = &ty else {
                let t = self.model.type_name(&ty);
                return Err(format!("`{}` is {t}, not an array", a.path[k].name));
            };
            if dims.len() != values.len() {
                return Err(format!(
                    "`{}` has {} dimension(s), the path gives {} subscript(s)",
                    a.path[k].name,
                    dims.len(),
                    values.len()
                ));
            }
            let mut place = lv;
            for (d, v) in dims.iter().zip(values) {
                if !(d.lower..=d.upper).contains(v) {
                    return Err(format!(
                        "subscript {v} is outside the bounds {}..{} of `{}`",
                        d.lower, d.upper, a.path[k].name
                    ));
                }
                place = cfmt!("{place}[{}]", v - d.lower);
            }
            target = Target::Field((**element).clone(), place);
        }
        Ok(target)
    }

    /// Whether the declared type name `declared` is `ty` (its IEC name, or an alias of it).
    fn access_type_matches(&self, declared: &str, ty: &Type) -> bool {
        if self.model.type_name(ty).eq_ignore_ascii_case(declared) {
            return true;
        }
        match self.model.type_by_name(declared) {
            Some(id) => {
                matches!(&self.model.user_type(id).def, UserTypeDef::Alias { target, .. } if target == ty)
            }
            None => false,
        }
    }
}
