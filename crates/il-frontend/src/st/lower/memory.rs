//! `MEMCPY`, `MEMMOVE`, `MEMSET` and `MEMCMP` (Tc2_System: `MEMCPY(destAddr := ADR(a), srcAddr :=
//! ADR(b), n := SIZEOF(a))`; CODESYS SysMem: `SysMemCpy(pDest, pSrc, udiCount)` ...) in ST
//! expressions and statements.
//!
//! Input: a call of one of those names that no user POU declares, with its arguments (positional,
//! or formal by the Tc2_System or SysMem parameter names). Output: one [`Operand::Mem`] naming the
//! variables the pointer arguments point to, loaded into the current result. Invariants: a pointer
//! argument is accepted as `ADR(x)` / `REF(x)` of a variable, an element or a field, so the object
//! it points into is known when the C is generated and the count can be bounded by it
//! (`emit::memory` in the C backend), or as a `POINTER TO` / `REF_TO` variable (a field, an element)
//! whose bounded reference carries the variable it was made from, bounding the count at run time;
//! either one moved by a byte offset (`ADR(x) + n`, `p - n`, a chain `p + i - 1` read as
//! `p + (i - 1)`); any other pointer (other arithmetic, a call's result) is one E1035 at the
//! argument; a wrong number of
//! arguments or an unknown parameter name is one E1035 at the call.

use super::super::ast::{Arg, Expr, ExprKind};
use super::{ld, PouLowering};
use crate::ast::{self as il, MemFunc, Operand};
use crate::Span;
use diagnostics::{code, Diagnostic, Diagnostics};

/// The memory function `name` calls, with its parameter names (Tc2_System, then SysMem).
pub(super) fn mem_function(name: &str) -> Option<(MemFunc, [&'static str; 3], [&'static str; 3])> {
    let up = name.to_ascii_uppercase();
    let copy = (["destAddr", "srcAddr", "n"], ["pDest", "pSrc", "udiCount"]);
    Some(match up.as_str() {
        "MEMCPY" | "SYSMEMCPY" => (MemFunc::Copy, copy.0, copy.1),
        "MEMMOVE" | "SYSMEMMOVE" => (MemFunc::Move, copy.0, copy.1),
        "MEMSET" | "SYSMEMSET" => (
            MemFunc::Set,
            ["destAddr", "fillByte", "n"],
            ["pDest", "udiValue", "udiCount"],
        ),
        "MEMCMP" | "SYSMEMCMP" => (
            MemFunc::Compare,
            ["pBuf1", "pBuf2", "n"],
            ["pBuffer1", "pBuffer2", "udiCount"],
        ),
        _ => return None,
    })
}

impl PouLowering<'_> {
    /// Lowers `name(args)` (see the module documentation); `false` when `name` is none of them.
    pub(super) fn memory_call(
        &mut self,
        name: &il::Ident,
        args: &[Arg],
        span: Span,
        out: &mut Vec<il::IlStmt>,
        diags: &mut Diagnostics,
    ) -> bool {
        let Some((func, tc, sys)) = mem_function(&name.name) else {
            return false;
        };
        // every refusal shows the call written out with the three parameter names
        let usage = format!(
            "write `{}({} := ADR(...), {} := ..., {} := ...)`",
            func.name(),
            tc[0],
            tc[1],
            tc[2]
        );
        let refuse = |diags: &mut Diagnostics, at: Span, msg: String, label: &str| {
            diags.push(
                Diagnostic::error(code::E1035, msg)
                    .at(at)
                    .with_primary_label(label)
                    .with_hint(usage.as_str()),
            );
        };
        // the three arguments in parameter order
        let mut slots: [Option<&Expr>; 3] = [None, None, None];
        let formal = args.iter().any(|a| a.name.is_some());
        for (k, a) in args.iter().enumerate() {
            let at = match &a.name {
                Some(n) => tc
                    .iter()
                    .position(|p| n.is(p))
                    .or_else(|| sys.iter().position(|p| n.is(p))),
                None if !formal => Some(k).filter(|&k| k < 3),
                None => None,
            };
            match at {
                Some(i) if slots[i].is_none() => slots[i] = Some(&a.value),
                _ => {
                    refuse(
                        diags,
                        a.span,
                        format!("`{}` has no such argument", name.name),
                        "not a parameter",
                    );
                    self.poisoned = true;
                    out.push(ld(super::int_lit(0, span), span));
                    return true;
                }
            }
        }
        let [Some(first), Some(second), Some(count)] = slots else {
            refuse(
                diags,
                span,
                format!("`{}` takes three arguments", name.name),
                "arguments missing",
            );
            self.poisoned = true;
            out.push(ld(super::int_lit(0, span), span));
            return true;
        };
        let dest = self.pointed_variable(func, first, out, diags);
        let (src, fill) = if func == MemFunc::Set {
            (None, Some(self.operand(second, None, out, diags)))
        } else {
            (self.pointed_variable(func, second, out, diags), None)
        };
        let count = self.operand(count, None, out, diags);
        let through_pointer = [
            dest.as_ref().is_some_and(|d| d.1),
            src.as_ref().is_some_and(|s| s.1),
        ];
        let offsets = [
            dest.as_ref().and_then(|d| d.2.clone()),
            src.as_ref().and_then(|s| s.2.clone()),
        ];
        let (dest, src) = (dest.map(|d| d.0), src.map(|s| s.0));
        let (Some(dest), true) = (dest, func == MemFunc::Set || src.is_some()) else {
            self.poisoned = true;
            out.push(ld(super::int_lit(0, span), span));
            return true;
        };
        out.push(ld(
            Operand::Mem(Box::new(il::MemCall {
                func,
                dest,
                src,
                through_pointer,
                offsets,
                fill,
                count,
                span,
            })),
            span,
        ));
        true
    }

    /// Whether `p` is a POINTER TO / REF_TO variable, or a place the lowering cannot type (an
    /// undeclared name, a member it cannot see): passed as a pointer, so that the checks name
    /// what is wrong with it (E1001, or E1035 "is not a pointer") instead of one E1035 here that
    /// stops every check of the project.
    fn pointer_or_untyped(&self, p: &super::super::ast::Place) -> bool {
        let env = self.env();
        match env.place_type(p).map(|t| env.resolve(&t)) {
            Some(il::TypeRef::Ref {
                kind: il::RefKind::Pointer | il::RefKind::RefTo,
                ..
            }) => true,
            Some(_) => false,
            None => true,
        }
    }

    /// Whether `x` is an address a byte offset may move: `ADR(place)` / `REF(place)`, or a
    /// pointer variable (or a name the lowering cannot type, such as an undeclared one: the
    /// checks report it, E1001 or E1035 "is not a pointer").
    fn is_address_term(&self, x: &Expr) -> bool {
        match &x.kind {
            ExprKind::Call { name, args } => {
                super::super::refs::is_address_of(name)
                    && matches!(
                        &args[..],
                        [Arg {
                            name: None,
                            value: Expr {
                                kind: ExprKind::Place(_),
                                ..
                            },
                            ..
                        }]
                    )
            }
            ExprKind::Place(p) => self.pointer_or_untyped(p),
            _ => false,
        }
    }

    /// A chain of three or more terms joined by + and - that holds one address term, added
    /// (`p + i - 1`, `ADR(buf) + n - i`, `i + ADR(buf) - 1`), regrouped as `address + offset`
    /// with the other terms in their order (`p + (i - 1)`): ST's + and - have one precedence and
    /// are evaluated from the left (IEC 61131-3 ed. 2, 3.3.1, Table 55; ed. 3, Table 71), and
    /// TwinCAT counts a pointer byte-wise (Beckhoff Infosys, TwinCAT PLC Control "Pointer": "A
    /// pointer is counted byte-wise"; TE1200 SA0065), so the address moved on by `i` and back by
    /// 1 is the address moved on by `i - 1` (an offset computed as UDINT, as in the written
    /// `p + (i - 1)`). `None` for a
    /// chain of two terms (read as written), for no or several address terms, an address
    /// subtracted, or a first offset term subtracted (`ADR(x) - n + m`: before the address).
    fn address_then_offset(&self, e: &Expr) -> Option<Expr> {
        use super::super::ast::BinaryOp;
        // the chain's terms, right to left along its left spine (iterative: no recursion)
        let mut terms: Vec<(bool, &Expr)> = Vec::new();
        let mut at = e;
        while let ExprKind::Binary { op, left, right } = &at.kind {
            match op {
                BinaryOp::Add => terms.push((false, right)),
                BinaryOp::Sub => terms.push((true, right)),
                _ => break,
            }
            at = left;
        }
        terms.push((false, at));
        terms.reverse();
        if terms.len() < 3 {
            return None;
        }
        let mut addresses = terms
            .iter()
            .enumerate()
            .filter(|(_, (_, t))| self.is_address_term(t));
        let (k, (minus, _)) = addresses.next()?;
        if *minus || addresses.next().is_some() {
            return None;
        }
        let address = terms[k].1.clone();
        let mut rest = terms
            .iter()
            .enumerate()
            .filter(|(i, _)| *i != k)
            .map(|(_, t)| *t);
        let (first_minus, first) = rest.next()?;
        if first_minus {
            return None;
        }
        let offset = rest.fold(first.clone(), |acc, (minus, t)| {
            let span = acc.span.to(t.span);
            Expr {
                kind: ExprKind::Binary {
                    op: if minus { BinaryOp::Sub } else { BinaryOp::Add },
                    left: Box::new(acc),
                    right: Box::new(t.clone()),
                },
                span,
            }
        });
        Some(Expr {
            kind: ExprKind::Binary {
                op: BinaryOp::Add,
                left: Box::new(address),
                right: Box::new(offset),
            },
            span: e.span,
        })
    }

    /// The variable a pointer argument points to: `ADR(x)` / `REF(x)` of a place (`false`), or a
    /// `POINTER TO` / `REF_TO` variable itself (`true`: its value is the address, bounded at run
    /// time); anything else is one E1035 (its object, so the bytes it may reach, cannot be known).
    fn pointed_variable(
        &mut self,
        func: MemFunc,
        e: &Expr,
        out: &mut Vec<il::IlStmt>,
        diags: &mut Diagnostics,
    ) -> Option<(il::VarRef, bool, Option<Operand>)> {
        // `p + i - 1`, `ADR(buf) + n - i` (OC_Core's byte swap): + and - chain left to right,
        // so the address moved on by `i` and back by 1 is the address moved on by `i - 1`
        if let Some(regrouped) = self.address_then_offset(e) {
            return self.pointed_variable(func, &regrouped, out, diags);
        }
        // `p - n` of a pointer variable (a pointer to a text's end moved back over its last n
        // characters, RoddenLab's RIGHT of a big string): the moved pointer, held in a
        // temporary, is bounded as any pointer (moved before its variable: no room, the count
        // clipped to 0 and reported at the end of the run)
        if let ExprKind::Binary {
            op: super::super::ast::BinaryOp::Sub,
            left,
            ..
        } = &e.kind
        {
            if let ExprKind::Place(p) = &left.kind {
                let env = self.env();
                let pointer = matches!(
                    env.place_type(p).map(|t| env.resolve(&t)),
                    Some(il::TypeRef::Ref {
                        kind: il::RefKind::Pointer | il::RefKind::RefTo,
                        ..
                    })
                );
                if pointer {
                    let ty = self.temp_type(left, None);
                    let t = self.temp(ty, e.span);
                    self.value(e, out, diags);
                    out.push(super::simple(
                        il::Op::St,
                        false,
                        Some(super::var_operand(&t)),
                        e.span,
                    ));
                    let v = il::VarRef {
                        base: t,
                        accessors: Default::default(),
                        span: e.span,
                    };
                    return Some((v, true, None));
                }
            }
        }
        // `ADR(buf) + n`, `n + ADR(buf)` (Tc2_System code writes into a buffer from an offset):
        // the variable, and the offset in bytes (the C clips the count to the bytes after it)
        if let ExprKind::Binary {
            op: super::super::ast::BinaryOp::Add,
            left,
            right,
        } = &e.kind
        {
            let (address, offset) = if self.is_address_term(left) {
                (left, right)
            } else if self.is_address_term(right) {
                (right, left)
            } else {
                (left, left)
            };
            if !std::ptr::eq(address, offset) {
                let (v, through, _) = self.pointed_variable(func, address, out, diags)?;
                let udint = il::TypeRef::Named(il::Ident::new("UDINT", offset.span));
                let o = self.operand(offset, Some(&udint), out, diags);
                return Some((v, through, Some(o)));
            }
        }
        if let ExprKind::Place(p) = &e.kind {
            if self.pointer_or_untyped(p) {
                if let Some(Operand::Var(v)) = self.place_operand(p, out, diags) {
                    return Some((v, true, None));
                }
                return None;
            }
        }
        if let ExprKind::Call { name, args } = &e.kind {
            // `ADR('text')`: the literal's hidden copy
            if let ([a], true) = (&args[..], name.is("ADR")) {
                if a.name.is_none() {
                    if let Some(v) = self.literal_copy(&a.value, out) {
                        return Some((v, false, None));
                    }
                }
            }
            if super::super::refs::is_address_of(name) {
                if let [Arg {
                    name: None,
                    value:
                        Expr {
                            kind: ExprKind::Place(p),
                            ..
                        },
                    ..
                }] = &args[..]
                {
                    if let Some(Operand::Var(v)) = self.place_operand(p, out, diags) {
                        return Some((v, false, None));
                    }
                    return None;
                }
            }
        }
        diags.push(
            Diagnostic::error(
                code::E1035,
                format!(
                    "{}: the variable this pointer points into cannot be known",
                    func.name()
                ),
            )
            .at(e.span)
            .with_primary_label("not `ADR(variable)` or a pointer variable")
            .with_hint("pass `ADR(x)` of the variable itself (an element or a field too), `ADR(x) + n` (n bytes into it), or a POINTER TO variable: ladderc bounds the count by the variable the address belongs to"),
        );
        None
    }
}
