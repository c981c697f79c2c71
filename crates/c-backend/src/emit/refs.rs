//! References in C (IEC 61131-3 edition 3 `REF_TO`, CODESYS/TwinCAT `POINTER TO` and
//! `REFERENCE TO`): a reference is an `IEC_REF` (`void *`) holding the address of the variable it refers to,
//! or NULL.
//!
//! Input: sema's reference types and operands (`REF(x)`, `NULL`, `r^`, and `SIZEOF(x)`, the C
//! `sizeof` of what a reference would refer to). Output: C expressions.
//! Invariants: a reference holds only NULL or the address of a whole variable of its target type
//! that lives as long as the program (sema refuses `REF` of temporaries, function variables,
//! VAR_IN_OUT and located variables, and all pointer arithmetic), so a non-NULL reference is always
//! valid to read and write through. A dereference goes through `ladderc_deref`: a NULL reference
//! reads zero and a write through it is dropped (both into a zeroed scratch object of the target
//! type, `ladderc_null_<n>`), and the run-time error flag `LADDERC_ERR_NULL_REF` is set with the
//! place of the first one; no NULL pointer is ever dereferenced in C. A call through an unassigned
//! interface variable reads such a NULL reference and is reported as that call.

use super::scope::{Place, Scope};
use super::Gen;
use crate::{ctypes, mangle};
use diagnostics::Span;
use il_frontend::ast::{RefOperand, SizeOfOperand, VarRef};
use il_frontend::sema::Type;

impl Gen<'_> {
    /// The value of `REF(x)` / `ADR(x)` / `NULL` as a C `void *` expression.
    pub(super) fn reference_value(&mut self, scope: &Scope, r: &RefOperand) -> Option<String> {
        let Some(v) = &r.of else {
            return Some("((IEC_REF)0)".into());
        };
        match self.place(scope, v)? {
            Place::Mem { lv, .. } => Some(cfmt!("((IEC_REF)&{lv})")),
            Place::Loc { .. } | Place::Part { .. } => {
                // sema refuses it (E0305); no address of the process image is handed out
                self.unsupported(r.span, "a reference to a located variable or a bit");
                None
            }
        }
    }

    /// `SIZEOF(x)` / `SIZEOF(T)`: C's `sizeof` of the variable's lvalue or of the type's C type
    /// (`IEC_INT[4]` for an array), so the figure is the generated C's own (a STRING of any declared
    /// length is one `IEC_STRING`, a struct is padded as the C compiler pads it). A located variable
    /// or a bit of a variable is its elementary type's size.
    pub(super) fn size_of(&mut self, scope: &Scope, s: &SizeOfOperand) -> Option<String> {
        // a bare name that is no variable here is a type (sema: `size_of_type`)
        self.quiet += 1;
        let place = self.place(scope, &s.of);
        self.quiet -= 1;
        if place.is_none() && s.of.accessors.is_empty() {
            if let Some(ty) = self.model.type_named(&s.of.base.name) {
                let base = ctypes::base(self.model, &ty)?;
                let dims = ctypes::dims(&ty);
                return Some(cfmt!("sizeof({base}{dims})"));
            }
        }
        match self.place_or_located_array(scope, &s.of)? {
            Place::Mem { lv, .. } => Some(cfmt!("sizeof({lv})")),
            Place::Loc { ty, .. } | Place::Part { ty, .. } => {
                // a located array: the C type's size (`IEC_INT[5]`), as a named array's
                let base = ctypes::base(self.model, &ty)?;
                let dims = ctypes::dims(&ty);
                Some(cfmt!("sizeof({base}{dims})"))
            }
        }
    }

    /// `lv^`: the variable the reference `lv` (of type `ty`) refers to. `v` and `at` name the
    /// place for the run-time message (`r^` in POU `main`).
    pub(super) fn deref_place(
        &mut self,
        scope: &Scope,
        lv: &str,
        ty: &Type,
        v: &VarRef,
        at: usize,
        span: Span,
    ) -> Option<Place> {
        let Type::Ref(target) = ty else {
            self.unsupported(span, "`^` on a value that is not a reference");
            return None;
        };
        let target = (**target).clone();
        let base = ctypes::base(self.model, &target)?;
        let dims = ctypes::dims(&target);
        let scratch = self.null_scratch(&base, &dims);
        let path = il_frontend::print::var_ref_text(&VarRef {
            base: v.base.clone(),
            accessors: v.accessors.iter().take(at + 1).cloned().collect(),
            span: v.span,
        });
        let pou = scope
            .pou
            .map(|(p, _)| p.name.clone())
            .unwrap_or_else(|| "the configuration".into());
        // the hidden, always NULL reference a call through an unassigned interface variable reads
        // (il_frontend::st::interface_vars): named by the variable, not by the hidden field
        let unassigned = cfmt!(".{}^", il_frontend::st::interface_vars::UNASSIGNED);
        let site = match path.strip_suffix(unassigned.as_str()) {
            Some(itf) => cfmt!("a call through the unassigned interface {itf} in {pou}"),
            None => cfmt!("{path} in {pou}"),
        };
        let site = mangle::c_string(site.as_bytes());
        Some(Place::Mem {
            lv: cfmt!(
                "(*({base} (*){dims})ladderc_deref({lv}, &{scratch}, sizeof {scratch}, {site}))"
            ),
            ty: target,
        })
    }

    /// The name of the zeroed scratch object of C type `base dims` that a NULL dereference reads
    /// and writes (declared once per type, at file scope: see [`Self::null_scratch_decls`]).
    fn null_scratch(&mut self, base: &str, dims: &str) -> String {
        let key = cfmt!("{base}{dims}");
        if let Some(i) = self.null_refs.iter().position(|(k, _)| *k == key) {
            return cfmt!("ladderc_null_{i}");
        }
        let name = cfmt!("ladderc_null_{}", self.null_refs.len());
        self.null_refs
            .push((key, cfmt!("static {base} {name}{dims};")));
        name
    }

    /// The declarations of the scratch objects used so far, one per line.
    pub(super) fn null_scratch_decls(&self) -> String {
        let mut s = String::new();
        for (_, d) in &self.null_refs {
            s.push_str(d);
            s.push('\n');
        }
        s
    }
}
