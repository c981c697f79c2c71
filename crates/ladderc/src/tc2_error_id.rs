//! Beckhoff Tc2_MC2's `ErrorID : UDINT` stored from ladderc's `ErrorID : WORD`.
//!
//! Input: one library block call's formal arguments and what the POU knows of its variables' types
//! (IL, before the semantic checks). Output: each `ErrorID => target` whose target is declared as
//! a wider integer or bit string (`UDINT`, `DINT`, `DWORD` ...) written to a hidden `WORD` variable
//! instead, and the IL that stores it, converted, into the target after the call. Invariants: only
//! unconditional calls and targets whose type the POU's declarations give are touched; the hidden
//! names start with `__TC2_EID_` (a user cannot write them).
//!
//! Why: Infosys (Tc2_MC2, every motion block) declares `ErrorID : UDINT`, so TwinCAT projects bind
//! it to UDINT variables (`ErrorID => stMotionOut.nHaltErrorID`). ladderc's motion library reports
//! its ErrorIDs (all below 65536) as WORD, and IEC 61131-3 converts WORD to UDINT only explicitly
//! (E1012); the conversion written here is that explicit, lossless one.

use il_frontend::ast::{
    Accessor, CallArgs, FormalArg, Ident, IlStmt, InstrKind, Instruction, Op, Operand, TypeRef,
    VarDecl, VarRef,
};
use std::collections::HashMap;

/// The types the hidden WORD converts to, and the conversion's name.
const WIDER: &[(&str, &str)] = &[
    ("UDINT", "WORD_TO_UDINT"),
    ("DINT", "WORD_TO_DINT"),
    ("DWORD", "WORD_TO_DWORD"),
    ("ULINT", "WORD_TO_ULINT"),
    ("LINT", "WORD_TO_LINT"),
    ("LWORD", "WORD_TO_LWORD"),
];

/// What the POU's declarations say of types: its variables (and the globals), the structures'
/// fields; upper-case names.
pub struct Types {
    /// Variable -> its type.
    pub vars: HashMap<String, TypeRef>,
    /// Structure type -> its fields' types.
    pub structs: HashMap<String, HashMap<String, TypeRef>>,
}

impl Types {
    /// The elementary type name of `v` (`Motion_Out.nHaltErrorID` through the structure's field).
    fn of(&self, v: &VarRef) -> Option<String> {
        let mut ty = self.vars.get(&v.base.key())?;
        for a in v.accessors.iter() {
            let (Accessor::Field(f), TypeRef::Named(t)) = (a, ty) else {
                return None;
            };
            ty = self.structs.get(&t.key())?.get(&f.key())?;
        }
        match ty {
            TypeRef::Named(t) => Some(t.key()),
            _ => None,
        }
    }
}

/// For the call of `instance` with `args`: the hidden variables to declare and the IL to run after
/// the call (see the module header).
pub fn widen(
    instance: &VarRef,
    args: &mut [FormalArg],
    types: &Types,
) -> (Vec<VarDecl>, Vec<IlStmt>) {
    let mut decls = Vec::new();
    let mut code = Vec::new();
    for a in args.iter_mut() {
        let (il_frontend::ast::ArgDir::Output { negated: false }, true) =
            (a.dir, a.name.key() == "ERRORID")
        else {
            continue;
        };
        let Operand::Var(target) = &a.value else {
            continue;
        };
        let Some(ty) = types.of(target) else { continue };
        let Some((_, conv)) = WIDER.iter().find(|(t, _)| *t == ty) else {
            continue;
        };
        let at = a.value.span();
        let hidden = format!("__TC2_EID_{}", instance.base.key());
        let var = |name: &str| VarRef {
            base: Ident::new(name, at),
            accessors: Vec::new().into(),
            span: at,
        };
        let instr = |kind: InstrKind| IlStmt::Instr(Instruction { kind, span: at });
        let target = target.clone();
        a.value = Operand::Var(var(&hidden));
        decls.push(VarDecl {
            name: Ident::new(hidden.clone(), at),
            location: None,
            ty: TypeRef::Named(Ident::new("WORD", at)),
            init: None,
            edge: None,
            span: at,
        });
        code.push(instr(InstrKind::Simple {
            op: Op::Ld,
            negate: false,
            operand: Some(Operand::Var(var(&hidden))),
        }));
        code.push(instr(InstrKind::FunctionCall {
            name: Ident::new(*conv, at),
            args: Box::new(CallArgs::NonFormal(Vec::new())),
        }));
        code.push(instr(InstrKind::Simple {
            op: Op::St,
            negate: false,
            operand: Some(Operand::Var(target)),
        }));
    }
    (decls, code)
}
