//! `MEMCPY`, `MEMMOVE`, `MEMSET` and `MEMCMP` (Tc2_System; CODESYS SysMem's `SysMemCpy` ...) in
//! bodies: the types of their operands and of their result.
//!
//! Input: one [`ast::MemCall`], whose pointer arguments the ST lowering has already reduced to the
//! variables `ADR(x)` named, or to POINTER TO / REF_TO variables passed as they are (a pointer
//! whose variable cannot be known is refused there, E1035).
//! Output: the call's type (DINT for MEMCMP, UDINT for the others) and diagnostics. Invariants: the
//! variables resolve (E1001 otherwise) and have storage of their own: no located variable or bit
//! (E0305, as `ADR` of them); a written destination is writable (a CONSTANT is E1026, an input
//! W1411, as an assignment); the count and the fill byte are integers or bit strings (E1012). The
//! bounds themselves are C's (`emit::memory` clips the count to the variables' sizes at run time).

use super::body::{Body, Ty};
use super::model::*;
use crate::ast::{self, MemCall, MemFunc, Operand};
use diagnostics::code;

impl Body<'_, '_> {
    /// The type of `MEMCPY(...)` and its kin; see the module documentation.
    pub(super) fn mem_operand(&mut self, m: &MemCall) -> Ty {
        let what = m.func.name();
        let dest = if m.func == MemFunc::Compare || m.through_pointer[0] {
            self.read_operand(&Operand::Var(m.dest.clone()))
        } else {
            Ty::Known(self.write_place(&Operand::Var(m.dest.clone()), what))
        };
        let src = m
            .src
            .as_ref()
            .map(|s| self.read_operand(&Operand::Var(s.clone())));
        let mut ok = !dest.is_error() && !src.as_ref().is_some_and(Ty::is_error);
        // a pointer variable passed as it is: its value is the address (the ST lowering took only
        // POINTER TO / REF_TO variables there)
        let pointers = [
            Some((&dest, &m.dest)).filter(|_| m.through_pointer[0]),
            src.as_ref()
                .zip(m.src.as_ref())
                .filter(|_| m.through_pointer[1]),
        ];
        for (t, v) in pointers.into_iter().flatten() {
            if !matches!(
                self.norm(t),
                Ty::Known(Type::Ref(_)) | Ty::Known(Type::Error)
            ) {
                let path = crate::print::var_ref_text(v);
                self.a
                    .error(
                        code::E1035,
                        v.span,
                        format!("{what}: `{path}` is not a pointer"),
                    )
                    .label("its value is no address")
                    .hint("pass `ADR(x)` of a variable, or a POINTER TO variable");
                ok = false;
            }
        }
        let objects = [
            Some(&m.dest).filter(|_| !m.through_pointer[0]),
            m.src.as_ref().filter(|_| !m.through_pointer[1]),
        ];
        for v in objects.into_iter().flatten() {
            if let Some(why) = self.no_storage_of_its_own(v) {
                let path = crate::print::var_ref_text(v);
                self.a
                    .error(
                        code::E0305,
                        v.span,
                        format!("{what} of `{path}` is not allowed: {why}"),
                    )
                    .label("its address is taken here")
                    .hint("copy whole variables, array elements or structure fields");
                ok = false;
            }
        }
        for (o, role) in std::iter::once((&m.count, "byte count"))
            .chain(m.fill.as_ref().map(|f| (f, "fill byte")))
            .chain(m.offsets.iter().flatten().map(|o| (o, "byte offset")))
        {
            let t = self.read_operand(o);
            let want = if role == "fill byte" {
                Type::Elementary(Elementary::Byte)
            } else {
                Type::Elementary(Elementary::Udint)
            };
            let fits = match self.norm(&t) {
                Ty::Known(k) => k.is_error() || k.is_integer() || k.is_bit(),
                Ty::Lit(_) => self.coerce(&t, &want, o.span(), |_, _, _| {}),
            };
            if !fits {
                let tn = match self.norm(&t) {
                    Ty::Known(k) => self.a.type_name(&k),
                    Ty::Lit(_) => "a real".to_string(),
                };
                self.a
                    .error(
                        code::E1012,
                        o.span(),
                        format!("the {role} of {what} is {tn}, not an integer"),
                    )
                    .label(format!("this is {tn}"))
                    .hint("give an integer (`SIZEOF(x)` counts the bytes of a variable)");
                ok = false;
            }
        }
        if !ok {
            return Ty::ERROR;
        }
        Ty::Known(Type::Elementary(if m.func == MemFunc::Compare {
            Elementary::Dint
        } else {
            Elementary::Udint
        }))
    }

    /// Why the bytes of `v` cannot be copied to or from (`None`: they can): a bit or part of a
    /// variable, or a located variable (the process image is read and written through the
    /// profile's byte order, never through an address).
    fn no_storage_of_its_own(&self, v: &ast::VarRef) -> Option<&'static str> {
        if let Some(why) = super::refs::through_reference_or_part(v) {
            return why;
        }
        let pou = self.pou();
        let located = pou
            .var_position(&v.base.name)
            .map(|i| pou.vars[i].location.is_some())
            .unwrap_or(false);
        located.then_some("a located variable lives in the process image, which has no address")
    }
}
