//! `SIZEOF` in IL bodies, as TwinCAT's help shows it (Infosys, TwinCAT 2 PLC Control, "SIZEOF",
//! example in IL: `LD arr1` / `SIZEOF` / `ST var1`, the result 10 for an `ARRAY[0..4] OF INT`).
//!
//! Input: a parsed IL body. Output: the same body where each `LD x` directly followed by a
//! `SIZEOF` call without arguments is one `LD SIZEOF(x)` ([`Operand::SizeOf`], as ST's `SIZEOF(x)`
//! lowers), the `SIZEOF` line dropped. Invariant: nothing else changes; a `SIZEOF` after anything
//! else (an expression, `LDN`, a literal) stays a call, which sema reports (E1019), since its
//! operand must be a variable, not a value.

use crate::ast::{CallArgs, IlStmt, InstrKind, LibraryElement, Op, Operand, SizeOfOperand};

/// Folds `LD x` + `SIZEOF` in every POU body of `items` (and in their nested lists).
pub fn fold_items(items: &mut [LibraryElement]) {
    for item in items {
        if let LibraryElement::Pou(p) = item {
            fold(&mut p.body);
        }
    }
}

/// Folds `LD x` + `SIZEOF` into `LD SIZEOF(x)` in `body` and its nested lists.
pub fn fold(body: &mut Vec<IlStmt>) {
    let mut i = 1;
    while i < body.len() {
        if let IlStmt::Instr(ins) = &mut body[i] {
            if let InstrKind::Deferred { body: nested, .. } = &mut ins.kind {
                fold(nested);
            }
        }
        let is_sizeof = matches!(
            &body[i],
            IlStmt::Instr(ins) if matches!(&ins.kind, InstrKind::FunctionCall { name, args }
                if name.is("SIZEOF") && matches!(**args, CallArgs::None))
        );
        if is_sizeof {
            let call_span = match &body[i] {
                IlStmt::Instr(ins) => ins.span,
                IlStmt::Label(l) => l.span,
            };
            if let IlStmt::Instr(prev) = &mut body[i - 1] {
                let span = prev.span.to(call_span);
                if let InstrKind::Simple {
                    op: Op::Ld,
                    negate: false,
                    operand: Some(operand @ Operand::Var(_)),
                } = &mut prev.kind
                {
                    if let Operand::Var(v) = operand {
                        *operand = Operand::SizeOf(Box::new(SizeOfOperand {
                            of: v.clone(),
                            span,
                        }));
                    }
                    prev.span = span;
                    body.remove(i);
                    continue;
                }
            }
        }
        i += 1;
    }
    if let Some(IlStmt::Instr(ins)) = body.first_mut() {
        if let InstrKind::Deferred { body: nested, .. } = &mut ins.kind {
            fold(nested);
        }
    }
}
