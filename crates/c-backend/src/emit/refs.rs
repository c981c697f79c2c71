//! References in C (IEC 61131-3 edition 3 `REF_TO`, CODESYS/TwinCAT `POINTER TO` and
//! `REFERENCE TO`): a reference is an `IEC_REF`, a bounded pointer: the address and byte size of
//! the variable it was made from (NULL and 0 for NULL) and a byte offset into it.
//!
//! Input: sema's reference types and operands (`REF(x)`, `NULL`, `r^`, `p[i]`, `p + n`, and
//! `SIZEOF(x)`, the C `sizeof` of what a reference would refer to). Output: C expressions.
//! Invariants: a reference is only ever made from a whole variable that lives as long as the
//! program (sema refuses `REF` of temporaries, function variables, VAR_IN_OUT and located
//! variables), or from an element of such an array variable (then it is made from the whole array,
//! so that indexing may reach the other elements). Pointer arithmetic (`p + n`, bytes) and indexing
//! (`p[i]`, the i-th element after `p^`) only move the offset; the C pointer is formed only by the
//! runtime's `ladderc_deref`, after checking that the `sizeof` bytes of the access lie inside the
//! variable and are aligned for their type. The access is what is read or written: with the
//! array indexes and structure fields that follow a dereference (`p^[i].x`) it is that element or
//! field, not the whole target, so a pointer to a larger array than the variable reaches each
//! element the variable has. A NULL reference, or one moved outside its variable,
//! reads zero and a write through it is dropped (both into a zeroed scratch object of the target
//! type, `ladderc_null_<n>`), and the run-time error flag `LADDERC_ERR_NULL_REF` or
//! `LADDERC_ERR_POINTER` is set with the place of the first one: no byte outside a variable is ever
//! reached, whatever the index or offset. A call through an unassigned interface variable reads
//! such a NULL reference and is reported as that call.

use super::scope::{Place, Scope};
use super::Gen;
use crate::ctypes;
use diagnostics::Span;
use il_frontend::ast::{Accessor, Operand, RefOperand, SizeOfOperand, VarRef};
use il_frontend::sema::{Elementary, Type};

impl Gen<'_> {
    /// The value of `REF(x)` / `ADR(x)` / `NULL` as a C `IEC_REF` expression. An address taken
    /// through a pointer keeps the variable that pointer was made from: `ADR(p^)` is `p`,
    /// `ADR(p[i])` is `p` moved by i elements, `ADR(ps[i].y)` moved on to the field `y` (see
    /// [`Self::through_pointer`]); `ADR(a[i])` of an array element refers into the whole array `a`.
    pub(super) fn reference_value(&mut self, scope: &Scope, r: &RefOperand) -> Option<String> {
        let Some(v) = &r.of else {
            return Some("ladderc_ref(NULL, 0)".into());
        };
        if let Some(moved) = self.through_pointer(scope, v) {
            return moved;
        }
        match self.place(scope, v)? {
            Place::Mem { lv, .. } => {
                if let Some(whole) = self.enclosing_array(scope, v) {
                    return Some(cfmt!(
                        "ladderc_ref_in((void *)&({whole}), sizeof({whole}), (const void *)&({lv}))"
                    ));
                }
                Some(cfmt!("ladderc_ref((void *)&({lv}), sizeof({lv}))"))
            }
            Place::Loc { .. } | Place::Part { .. } | Place::StrByte { .. } => {
                // sema refuses it (E0305); no address of the process image is handed out
                self.unsupported(r.span, "a reference to a located variable or a bit");
                None
            }
        }
    }

    /// `ADR(path)` when `path` goes through a pointer (its last `p^` or `p[i]`, followed by fields
    /// and array indexes only): that pointer, moved by i elements for `p[i]`, then by the byte
    /// offset of the rest of the path inside the pointer's target type, measured on the target
    /// type's scratch object (so no access is made: `ADR` of a place outside the variable is a
    /// pointer outside it, a fault only when dereferenced). `None` when `path` goes through no
    /// pointer; `Some(None)` when its C cannot be generated (reported).
    fn through_pointer(&mut self, scope: &Scope, v: &VarRef) -> Option<Option<String>> {
        for k in (0..v.accessors.len()).rev() {
            let index = match &v.accessors[k] {
                Accessor::Deref(_) if !(k == 0 && v.base.is("THIS")) => None,
                Accessor::Index(ix) if ix.len() == 1 => Some(&ix[0]),
                _ => continue,
            };
            let prefix = VarRef {
                base: v.base.clone(),
                accessors: v.accessors[..k].to_vec().into(),
                span: v.span,
            };
            self.quiet += 1;
            let place = self.place(scope, &prefix);
            self.quiet -= 1;
            let Some(Place::Mem {
                lv,
                ty: Type::Ref(target),
            }) = place
            else {
                continue;
            };
            let rest = &v.accessors[k + 1..];
            // an index after the pointer is checked against its array (named as written)
            let site = if rest.iter().any(|a| matches!(a, Accessor::Index(_))) {
                self.site(scope, &il_frontend::print::var_ref_text(v), v.span)
            } else {
                String::new()
            };
            return Some(self.moved_pointer(scope, &lv, &target, index, rest, (v.span, &site)));
        }
        None
    }

    /// The pointer `lv` (to `target`) moved by `index` elements and then to the place `rest`
    /// (fields and array indexes) inside its target; `at`: the access's span, and the site an
    /// index of `rest` out of range reports (a C string literal).
    fn moved_pointer(
        &mut self,
        scope: &Scope,
        lv: &str,
        target: &Type,
        index: Option<&Operand>,
        rest: &[Accessor],
        at: (Span, &str),
    ) -> Option<String> {
        let (span, site) = at;
        let base = ctypes::base(self.model, target)?;
        let dims = ctypes::dims(target);
        let (scratch, _) = self.null_scratch(&base, &dims);
        let mut p = match index {
            None => lv.to_string(),
            Some(i) => {
                let i = self.value(scope, i, &Type::Elementary(Elementary::Lint))?;
                cfmt!("ladderc_ref_index({lv}, (int64_t)({i}), sizeof {scratch})")
            }
        };
        if !rest.is_empty() {
            let mut at = Place::Mem {
                lv: scratch.clone(),
                ty: target.clone(),
            };
            for acc in rest {
                let Place::Mem { lv: l, ty } = at else {
                    return None;
                };
                at = match acc {
                    Accessor::Field(f) => self.field(&l, &ty, f)?,
                    Accessor::Index(ix) => self.index(scope, &l, &ty, ix, span, site)?,
                    Accessor::Deref(d) => {
                        self.unsupported(*d, "this address");
                        return None;
                    }
                };
            }
            let Place::Mem { lv: inner, .. } = at else {
                return None;
            };
            p = cfmt!(
                "ladderc_ref_add({p}, (int64_t)((const unsigned char *)&({inner}) - (const unsigned char *)&{scratch}))"
            );
        }
        Some(p)
    }

    /// The C lvalue of the array variable whose element `v` is (the array of its last index, when
    /// no reference is followed on the way: `buf[i]`, `s.rows[i].x`), the object a reference to
    /// `v` is made from.
    fn enclosing_array(&mut self, scope: &Scope, v: &VarRef) -> Option<String> {
        if v.accessors.iter().any(|a| matches!(a, Accessor::Deref(_))) {
            return None;
        }
        let k = v
            .accessors
            .iter()
            .rposition(|a| matches!(a, Accessor::Index(_)))?;
        let whole = VarRef {
            base: v.base.clone(),
            accessors: v.accessors[..k].to_vec().into(),
            span: v.span,
        };
        self.quiet += 1;
        let place = self.place(scope, &whole);
        self.quiet -= 1;
        match place? {
            Place::Mem {
                lv,
                ty: Type::Array { .. },
            } => Some(lv),
            _ => None,
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
            Place::Loc { ty, .. } | Place::Part { ty, .. } | Place::StrByte { ty, .. } => {
                // a located array: the C type's size (`IEC_INT[5]`), as a named array's
                let base = ctypes::base(self.model, &ty)?;
                let dims = ctypes::dims(&ty);
                Some(cfmt!("sizeof({base}{dims})"))
            }
        }
    }

    /// `lv^`: the variable the reference `lv` (of type `ty`) refers to; with `index`, `lv[i]`, the
    /// i-th element of the reference's target type after `lv^` (TwinCAT `p[i]` on a `POINTER TO
    /// T`). `v` and `at` name the place for the run-time message (`r^` in POU `main`).
    ///
    /// The array indexes and structure fields that follow in `v` (`p^[i]`, `p^[i].x`, `p^.rows[j]`)
    /// are taken into the access (see [`Self::inside_target`]): only the bytes of the element or
    /// field reached must lie inside the variable the reference was made from, not the whole
    /// target. So a `POINTER TO ARRAY[0..65535] OF T` given `ADR` of a shorter array reads and
    /// writes each element that array has (CODESYS's usual way to pass an array of any length,
    /// CODESYS online help "Pointer"); an element past its end is the run-time pointer error.
    /// Returns the place and how many of the following accessors it took.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn deref_place(
        &mut self,
        scope: &Scope,
        lv: &str,
        ty: &Type,
        v: &VarRef,
        at: usize,
        span: Span,
        index: Option<&Operand>,
    ) -> Option<(Place, usize)> {
        let Type::Ref(target) = ty else {
            self.unsupported(span, "`^` on a value that is not a reference");
            return None;
        };
        let target = (**target).clone();
        let base = ctypes::base(self.model, &target)?;
        let dims = ctypes::dims(&target);
        let (scratch, _) = self.null_scratch(&base, &dims);
        let rest = v.accessors.get(at + 1..).unwrap_or_default();
        let index_site = if rest.iter().any(|a| matches!(a, Accessor::Index(_))) {
            self.site(scope, &il_frontend::print::var_ref_text(v), v.span)
        } else {
            String::new()
        };
        let inside = self.inside_target(scope, &scratch, &target, rest, span, &index_site)?;
        let taken = inside.as_ref().map_or(0, |(_, _, n)| *n);
        let path = self.written(v, at + taken);
        // the hidden, always NULL reference a call through an unassigned interface variable reads
        // (il_frontend::st::interface_vars): named by the variable, not by the hidden field nor the
        // hidden fields read through it (`.__TAG`)
        let unassigned = cfmt!(".{}^", il_frontend::st::interface_vars::UNASSIGNED);
        let what = match path.find(unassigned.as_str()).map(|k| &path[..k]) {
            Some(itf) => cfmt!("a call through the unassigned interface {itf}"),
            None => match varlen_array(&v.base.name) {
                // an `ARRAY [*]` in-out's element (il_frontend::st::varlen): named as written
                Some(array) => {
                    let written = self.lines.text(v.span).map(str::to_string);
                    let written = written.unwrap_or_else(|| cfmt!("{array}[...]"));
                    cfmt!("{written} (an index outside the array passed)")
                }
                None => path,
            },
        };
        let site = self.site(scope, &what, v.span);
        let mut r = match index {
            None => lv.to_string(),
            Some(i) => {
                let i = self.value(scope, i, &Type::Elementary(Elementary::Lint))?;
                cfmt!("ladderc_ref_index({lv}, (int64_t)({i}), sizeof {scratch})")
            }
        };
        let (reached, offset) = match inside {
            Some((ty, offset, _)) => (ty, Some(offset)),
            None => (target, None),
        };
        if let Some(offset) = offset {
            r = cfmt!("ladderc_ref_add({r}, (int64_t)({offset}))");
        }
        let base = ctypes::base(self.model, &reached)?;
        let dims = ctypes::dims(&reached);
        let (scratch, align) = self.null_scratch(&base, &dims);
        let place = Place::Mem {
            lv: cfmt!(
                "(*({base} (*){dims})ladderc_deref({r}, sizeof {scratch}, offsetof({align}, t), &{scratch}, {site}))"
            ),
            ty: reached,
        };
        Some((place, taken))
    }

    /// The array indexes and structure fields at the start of `rest` that lead from a
    /// reference's target (of type `target`) into one of its elements or fields, measured on the
    /// target type's scratch object `scratch` (so nothing is accessed): the type reached, the C
    /// expression of its byte offset in the target, and how many accessors were taken. `None`
    /// when `rest` starts with none (a further dereference, a pointer's `p[i]`, a string's
    /// character, a partial access `.3`, or a member of a function block instance are left to
    /// the caller). Each index is checked against its declared bounds as for any array
    /// (`ladderc_index`, `site`), so the offset stays inside the target type.
    fn inside_target(
        &mut self,
        scope: &Scope,
        scratch: &str,
        target: &Type,
        rest: &[Accessor],
        span: Span,
        site: &str,
    ) -> Option<Option<(Type, String, usize)>> {
        let mut lv = scratch.to_string();
        let mut ty = target.clone();
        let mut taken = 0;
        for acc in rest {
            let next = match (acc, &ty) {
                (Accessor::Index(ix), Type::Array { .. }) => {
                    self.index(scope, &lv, &ty, ix, span, site)?
                }
                (Accessor::Field(f), Type::Struct(_))
                    if il_frontend::ast::partial_access(&f.name).is_none() =>
                {
                    self.field(&lv, &ty, f)?
                }
                _ => break,
            };
            let Place::Mem { lv: l, ty: t } = next else {
                break;
            };
            lv = l;
            ty = t;
            taken += 1;
        }
        if taken == 0 {
            return Some(None);
        }
        let offset = cfmt!("(const unsigned char *)&({lv}) - (const unsigned char *)&{scratch}");
        Some(Some((ty, offset, taken)))
    }

    /// The name of the zeroed scratch object of C type `base dims` that a NULL dereference reads
    /// and writes, and of the structure whose member `t` has that type (its `offsetof` is the
    /// type's alignment in C99), declared once per type, at file scope: see
    /// [`Self::null_scratch_decls`].
    fn null_scratch(&mut self, base: &str, dims: &str) -> (String, String) {
        let key = cfmt!("{base}{dims}");
        let i = match self.null_refs.iter().position(|(k, _)| *k == key) {
            Some(i) => i,
            None => {
                let i = self.null_refs.len();
                self.null_refs.push((
                    key,
                    cfmt!(
                        "static {base} ladderc_null_{i}{dims};\ntypedef struct {{ char c; {base} t{dims}; }} ladderc_align_{i};"
                    ),
                ));
                i
            }
        };
        (cfmt!("ladderc_null_{i}"), cfmt!("ladderc_align_{i}"))
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

/// The `ARRAY [*]` in-out whose hidden address input is `name` (`data__VLA` or `data__VLA_ADR`:
/// `data`), if it is one.
fn varlen_array(name: &str) -> Option<&str> {
    use il_frontend::st::varlen::{ADDRESS, CALL_ADDRESS};
    name.strip_suffix(CALL_ADDRESS)
        .or_else(|| name.strip_suffix(ADDRESS))
        .filter(|a| !a.is_empty())
}
