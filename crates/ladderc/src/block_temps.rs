//! Temporaries passed to a PLCopen block call kept as instance variables.
//!
//! Input: the user's parsed units (IL, before the semantic checks) and the block library.
//! Output: in each program and function block, every `VAR_TEMP` variable that is an argument of
//! a library block call (`fbReset(Axis := Axis1, Execute := bReset AND Axis1.Status.Error)`: the
//! ST lowering stores the expression in a temporary `__st_t1`), or an index of the called
//! element or of an argument (`fbMove[i + 1](Axis := axes[i + 1])`), moved into a `VAR` block.
//! Invariants: nothing else moves; a temporary is written before it is read in the same call (the
//! ST lowering's and, by IEC 61131-3, the user's), so keeping its value between calls changes no
//! result.
//!
//! Why: the template method renders each block call as a C function of its own that reads the
//! POU's variables through the instance (`self->`); a `VAR_TEMP` is a C local of the POU's body
//! and was out of that function's sight (the C compiler failed with "`v__st_t1` undeclared").

use il_frontend::ast::{
    Accessor, CallArgs, CompilationUnit, IlStmt, InstrKind, LibraryElement, Operand, PouKind,
    VarBlock, VarKind,
};
use param_passing::library::Library;
use std::collections::HashSet;

/// Moves the temporaries passed to block calls into `VAR` (see the module header).
pub fn keep(units: &mut [CompilationUnit], lib: &Library) {
    for u in units.iter_mut() {
        for item in &mut u.items {
            let LibraryElement::Pou(p) = item else {
                continue;
            };
            if p.kind == PouKind::Function {
                continue;
            }
            let instances: HashSet<String> = p
                .var_blocks
                .iter()
                .flat_map(|b| b.vars.iter())
                // an instance, or an array of them (`fbMove : ARRAY [0..2] OF MC_MoveAbsolute`)
                .filter(|v| param_passing::lower::instance_block(&v.ty, lib).is_some())
                .map(|v| v.name.key())
                .collect();
            if instances.is_empty() {
                continue;
            }
            let mut passed = HashSet::new();
            args(&p.body, &instances, &mut passed);
            let mut moved = Vec::new();
            for b in p.var_blocks.iter_mut().filter(|b| b.kind == VarKind::Temp) {
                let (keep, temp): (Vec<_>, Vec<_>) = std::mem::take(&mut b.vars)
                    .into_iter()
                    .partition(|v| passed.contains(&v.name.key()));
                b.vars = temp;
                moved.extend(keep);
            }
            if !moved.is_empty() {
                add_hidden_vars(p, moved);
            }
        }
    }
}

fn args(body: &[IlStmt], instances: &HashSet<String>, out: &mut HashSet<String>) {
    for s in body {
        let IlStmt::Instr(i) = s else { continue };
        match &i.kind {
            InstrKind::Deferred { body, .. } => args(body, instances, out),
            InstrKind::Call {
                instance,
                args: CallArgs::Formal(list),
                ..
            } if instances.contains(&instance.base.key()) => {
                // the element's index (`fbMove[i + 1]` indexes with a temporary) and every
                // variable an argument names, with its own indexes (`axes[i + 1]`)
                for a in instance.accessors.iter() {
                    accessor_vars(a, out);
                }
                for a in list {
                    if let Operand::Var(v) = &a.value {
                        out.insert(v.base.key());
                        for a in v.accessors.iter() {
                            accessor_vars(a, out);
                        }
                    }
                }
            }
            _ => {}
        }
    }
}

/// The variables an index names (`[i, __st_t2]`), with their own indexes.
fn accessor_vars(a: &Accessor, out: &mut HashSet<String>) {
    if let Accessor::Index(ix) = a {
        for o in ix {
            if let Operand::Var(v) = o {
                out.insert(v.base.key());
                for a in v.accessors.iter() {
                    accessor_vars(a, out);
                }
            }
        }
    }
}

/// Adds `vars` to `pou` as a VAR block of its own (variables a rewrite introduces: kept in the
/// instance, declared at the POU's name).
pub(crate) fn add_hidden_vars(
    pou: &mut il_frontend::ast::Pou,
    vars: Vec<il_frontend::ast::VarDecl>,
) {
    let span = pou.name.span;
    pou.var_blocks.push(VarBlock {
        access: None,
        name: None,
        kind: VarKind::Local,
        constant: false,
        retain: false,
        vars,
        span,
    });
}
