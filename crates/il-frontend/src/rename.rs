//! The renaming pass over IL statements: variables by base name (`x` -> `__M_ADD_X`), one-field
//! variables by base and field (`Step.X` -> `__SFC_STEP_X`), and labels by a prefix.
//!
//! Input: statements and the maps. Output: the same statements, renamed in place.
//! The fields of a closed base that the maps do not name are recorded (`unknown_fields`) for the
//! caller to report, and renamed to the base's stand-in.
//! Invariants: function names and formal parameter names are never renamed; index operands are.

use crate::ast::{Accessor, CallArgs, Ident, IlStmt, InstrKind, Operand, VarRef};
use std::collections::HashMap;

/// What the renaming pass maps.
#[derive(Default)]
pub struct Renames {
    /// Upper-case base name -> new base name (whole variable, accessors kept).
    pub bases: HashMap<String, String>,
    /// (upper-case base, upper-case field) -> new variable (the accessor is dropped): `Step.X`.
    pub fields: HashMap<(String, String), String>,
    /// Prefix for every label and jump target (empty: labels kept).
    pub label_prefix: String,
    /// Upper-case names whose `CAL name` is not renamed: a block's method called inside another
    /// method that declares a variable of the same name (`Hash : DWORD` beside `THIS^.Hash(k)`).
    pub calls_kept: std::collections::HashSet<String>,
    /// Upper-case bases whose every field is in `fields` (a chart's steps) -> the variable a field
    /// of it that `fields` does not map is renamed to, after the field is recorded in
    /// `unknown_fields` (so the caller reports it once, and no "undeclared" follows).
    pub closed_bases: HashMap<String, String>,
    /// The (base, field) of each `Base.Field` of a closed base that `fields` does not map.
    pub unknown_fields: std::cell::RefCell<Vec<(Ident, Ident)>>,
}

impl Renames {
    /// Renames every name and label of `stmts` in place.
    pub fn apply(&self, stmts: &mut [IlStmt]) {
        for s in stmts {
            match s {
                IlStmt::Label(l) => self.label(l),
                IlStmt::Instr(i) => self.instr(&mut i.kind),
            }
        }
    }
    fn label(&self, l: &mut Ident) {
        if !self.label_prefix.is_empty() {
            l.name = format!("{}{}", self.label_prefix, l.name);
        }
    }
    fn instr(&self, k: &mut InstrKind) {
        match k {
            InstrKind::Simple { operand, .. } => {
                if let Some(o) = operand {
                    self.operand(o);
                }
            }
            InstrKind::Deferred { operand, body, .. } => {
                if let Some(o) = operand {
                    self.operand(o);
                }
                self.apply(body);
            }
            InstrKind::Jump { label, .. } => self.label(label),
            InstrKind::Return { .. } | InstrKind::EmbeddedC { .. } => {}
            InstrKind::Call { instance, args, .. } => {
                let kept =
                    instance.accessors.is_empty() && self.calls_kept.contains(&instance.base.key());
                if !kept {
                    self.var(instance);
                }
                self.args(args);
            }
            InstrKind::FunctionCall { args, .. } => self.args(args),
            InstrKind::FbInput { instance, .. } => self.var(instance),
        }
    }
    fn args(&self, a: &mut CallArgs) {
        match a {
            CallArgs::None => {}
            CallArgs::NonFormal(ops) => ops.iter_mut().for_each(|o| self.operand(o)),
            CallArgs::Formal(f) => f.iter_mut().for_each(|a| self.operand(&mut a.value)),
        }
    }
    /// Renames the variable of one operand (indexes included), also the one a reference value
    /// names (`REF(x[i])`, `r REF= x[i]` in a method: `x` and `i` its own variables).
    pub fn operand(&self, o: &mut Operand) {
        match o {
            Operand::Var(v) => self.var(v),
            // `ADR(pool[i])` in a method: `i` is the method's (renamed) input
            Operand::Ref(r) => {
                if let Some(v) = &mut r.of {
                    self.var(v);
                }
            }
            Operand::SizeOf(s) => self.var(&mut s.of),
            Operand::Mem(m) => {
                self.var(&mut m.dest);
                if let Some(v) = &mut m.src {
                    self.var(v);
                }
                if let Some(f) = &mut m.fill {
                    self.operand(f);
                }
                for o in m.offsets.iter_mut().flatten() {
                    self.operand(o);
                }
                self.operand(&mut m.count);
            }
            _ => {}
        }
    }
    fn var(&self, v: &mut VarRef) {
        for a in &mut v.accessors {
            if let Accessor::Index(ix) = a {
                ix.iter_mut().for_each(|o| self.operand(o));
            }
        }
        let key = v.base.key();
        if let [Accessor::Field(f)] = v.accessors.as_slice() {
            if let Some(new) = self.fields.get(&(key.clone(), f.key())) {
                v.base.name = new.clone();
                v.accessors.clear();
                return;
            }
        }
        if let (Some(Accessor::Field(f)), Some(new)) =
            (v.accessors.first(), self.closed_bases.get(&key))
        {
            self.unknown_fields
                .borrow_mut()
                .push((v.base.clone(), f.clone()));
            v.base.name = new.clone();
            v.accessors.remove(0);
            return;
        }
        if let Some(new) = self.bases.get(&key) {
            v.base.name = new.clone();
        }
    }
}
