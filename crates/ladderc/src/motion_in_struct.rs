//! Motion block instances called through a structure field (E1053).
//!
//! Input: the user's parsed units (IL, before the semantic checks) and the block library.
//! Output: one located E1053 per call whose instance path passes through a structure field and
//! ends at an instance of a library (motion) block: `stAxis.fbPower(...)`,
//! `aStations[i].fbMove(...)`. Invariants: nothing is changed; calls of instances declared in a
//! POU, a global list or an array of instances (`fbMove[i](...)`, which param-passing lowers) are
//! not reported, nor paths that name no declared variable (the semantic checks report those).
//!
//! Why: param-passing lowers the calls of instances a POU or a global list declares, also of
//! their array elements; an instance inside a structure would reach the C compiler unlowered
//! (before: an E1018 "is MC_Power, not an FB instance" from the check of the lowered program,
//! which reads as if the program were wrong).

use diagnostics::{code, Diagnostic, Diagnostics};
use il_frontend::ast::{
    Accessor, CompilationUnit, IlStmt, InstrKind, LibraryElement, TypeRef, VarRef,
};
use param_passing::library::Library;
use std::collections::HashMap;

/// Reports the calls of motion blocks held in structures (see the module header).
pub fn report(units: &[CompilationUnit], lib: &Library, diags: &mut Diagnostics) {
    let (structs, globals) = crate::tc2_mc2::declared_types(units);
    if structs.is_empty() {
        return;
    }
    for item in units.iter().flat_map(|u| u.items.iter()) {
        let LibraryElement::Pou(p) = item else {
            continue;
        };
        let mut vars = globals.clone();
        vars.extend(
            p.var_blocks
                .iter()
                .flat_map(|b| b.vars.iter())
                .map(|v| (v.name.key(), v.ty.clone())),
        );
        let cx = Cx {
            structs: &structs,
            vars: &vars,
            lib,
        };
        calls(&p.body, &cx, diags);
    }
}

struct Cx<'a> {
    structs: &'a HashMap<String, HashMap<String, TypeRef>>,
    vars: &'a HashMap<String, TypeRef>,
    lib: &'a Library,
}

fn calls(body: &[IlStmt], cx: &Cx, diags: &mut Diagnostics) {
    for s in body {
        let IlStmt::Instr(i) = s else { continue };
        match &i.kind {
            InstrKind::Call { instance, .. } => {
                if let Some(block) = held_in_struct(instance, cx) {
                    diags.push(
                        Diagnostic::error(
                            code::E1053,
                            format!(
                                "`{}` is an instance of {block} inside a structure: ladderc \
                                 calls motion blocks declared in a POU, a global list or an array",
                                path(instance)
                            ),
                        )
                        .at(instance.span)
                        .with_hint(format!(
                            "declare the instance in the program or function block (`x : {block};`), \
                             one per axis in an array, or in a function block kept in an array \
                             (see `ladderc explain E1053`)"
                        )),
                    );
                }
            }
            InstrKind::Deferred { body, .. } => calls(body, cx, diags),
            _ => {}
        }
    }
}

/// The block `v` is an instance of, when its path passes through a structure field.
fn held_in_struct(v: &VarRef, cx: &Cx) -> Option<String> {
    let mut ty = cx.vars.get(&v.base.key())?;
    let mut through_struct = false;
    for a in v.accessors.iter() {
        ty = match (a, ty) {
            (Accessor::Index(_), TypeRef::Array { element, .. }) => element,
            (Accessor::Field(f), TypeRef::Named(t)) => {
                through_struct = true;
                cx.structs.get(&t.key())?.get(&f.key())?
            }
            _ => return None,
        };
    }
    match ty {
        TypeRef::Named(t) if through_struct => cx.lib.get(&t.name).map(|tpl| tpl.block.clone()),
        _ => None,
    }
}

/// `stAxis.fbPower`, `aStations[..].fbMove`: the path as the user wrote its names.
fn path(v: &VarRef) -> String {
    let mut out = v.base.name.clone();
    for a in v.accessors.iter() {
        match a {
            Accessor::Field(f) => {
                out.push('.');
                out.push_str(&f.name);
            }
            Accessor::Index(_) => out.push_str("[..]"),
            Accessor::Deref(_) => out.push('^'),
        }
    }
    out
}
