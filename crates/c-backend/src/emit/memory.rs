//! `MEMCPY`, `MEMMOVE`, `MEMSET` and `MEMCMP` in C, bounded by the variables they work on.
//!
//! Input: an [`Operand::Mem`](il_frontend::ast::Operand::Mem), whose pointer arguments name
//! variables (`ADR(x)`) or pointer variables passed as they are (their bounded reference gives the
//! address and the room at run time: `ladderc_ref_at`, `ladderc_ref_room`). Output: a call of the runtime's
//! `ladderc_mem_move` / `ladderc_mem_set` / `ladderc_mem_cmp` with, for each variable, its address
//! and its room: the bytes from that address to the end of the variable, `sizeof` of a whole
//! variable or field, and for an array element (`ADR(buf[i])`) the bytes from the element to the
//! end of its array (`(char *)&buf + sizeof buf - (char *)&buf[i]`). Invariants: the runtime clips
//! the count to the smaller room, so no byte outside the named variables is ever read or written
//! (ASan-clean whatever the count), and reports the first clip at the end of the run.

use super::scope::{Place, Scope};
use super::Gen;
use il_frontend::ast::{Accessor, MemCall, MemFunc, VarRef};
use il_frontend::sema::{Elementary, Type};

impl Gen<'_> {
    /// The C value of `m` (IEC_UDINT, or IEC_DINT for MEMCMP).
    pub(super) fn memory_call(&mut self, scope: &Scope, m: &MemCall) -> Option<String> {
        let (dst, d_room) = self.mem_object(scope, &m.dest, m.through_pointer[0], m)?;
        let (dst, d_room) = self.offset(scope, dst, d_room, m.offsets[0].as_ref())?;
        let count = self.value(scope, &m.count, &Type::Elementary(Elementary::Ulint))?;
        let site = self.site(scope, m.func.name(), m.span);
        match m.func {
            MemFunc::Set => {
                let fill = m.fill.as_ref()?;
                let fill = self.value(scope, fill, &Type::Elementary(Elementary::Ulint))?;
                Some(cfmt!(
                    "ladderc_mem_set({dst}, {d_room}, (uint64_t)({fill}), (uint64_t)({count}), {site})"
                ))
            }
            MemFunc::Copy | MemFunc::Move | MemFunc::Compare => {
                let (src, s_room) =
                    self.mem_object(scope, m.src.as_ref()?, m.through_pointer[1], m)?;
                let (src, s_room) = self.offset(scope, src, s_room, m.offsets[1].as_ref())?;
                let f = if m.func == MemFunc::Compare {
                    "ladderc_mem_cmp"
                } else {
                    "ladderc_mem_move"
                };
                Some(cfmt!(
                    "{f}({dst}, {d_room}, {src}, {s_room}, (uint64_t)({count}), {site})"
                ))
            }
        }
    }

    /// `addr` and `room` moved `offset` bytes on (`ADR(buf) + n`): no room left when the offset
    /// is at or past the end (a negative one, as an unsigned count, is past it), so the runtime
    /// clips the count to 0 and reports it; the address is then the variable's own (never
    /// formed outside it).
    fn offset(
        &mut self,
        scope: &Scope,
        addr: String,
        room: String,
        offset: Option<&il_frontend::ast::Operand>,
    ) -> Option<(String, String)> {
        let Some(o) = offset else {
            return Some((addr, room));
        };
        let n = self.value(scope, o, &Type::Elementary(Elementary::Ulint))?;
        let n = cfmt!("((uint64_t)({n}))");
        Some((
            cfmt!("(void *)((char *)({addr}) + ({n} < (uint64_t)({room}) ? {n} : 0))"),
            cfmt!("({n} < (uint64_t)({room}) ? (size_t)((uint64_t)({room}) - {n}) : (size_t)0)"),
        ))
    }

    /// The address of `v` and its room (see the module documentation); with `through_pointer`, `v`
    /// is a pointer variable and both come from its bounded reference at run time (the bytes from
    /// where it points to the end of the variable it was made from; none for NULL or a pointer moved
    /// outside it).
    fn mem_object(
        &mut self,
        scope: &Scope,
        v: &VarRef,
        through_pointer: bool,
        m: &MemCall,
    ) -> Option<(String, String)> {
        if through_pointer {
            let Place::Mem {
                lv,
                ty: Type::Ref(_),
            } = self.place(scope, v)?
            else {
                self.unsupported(m.span, "a memory function on a pointer that is no variable");
                return None;
            };
            return Some((
                cfmt!("ladderc_ref_at({lv})"),
                cfmt!("ladderc_ref_room({lv})"),
            ));
        }
        let Place::Mem { lv, .. } = self.place(scope, v)? else {
            self.unsupported(m.span, "a memory function on a located variable or a bit");
            return None;
        };
        let addr = cfmt!("(void *)&({lv})");
        if let Some((Accessor::Index(_), rest)) = v.accessors.split_last() {
            let whole = VarRef {
                base: v.base.clone(),
                accessors: rest.to_vec().into(),
                span: v.span,
            };
            // only an array's element (`p[i]` of a pointer is its own `sizeof`: the runtime
            // checked those bytes)
            if let Some(Place::Mem {
                lv: wl,
                ty: Type::Array { .. },
            }) = self.place(scope, &whole)
            {
                return Some((
                    addr,
                    cfmt!(
                        "(size_t)(((const char *)&({wl}) + sizeof({wl})) - (const char *)&({lv}))"
                    ),
                ));
            }
        }
        Some((addr, cfmt!("sizeof({lv})")))
    }
}
