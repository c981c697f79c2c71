//! Calls of a PROGRAM from another POU (CODESYS, TwinCAT; not IEC 61131-3): `CAL P(in := x)` in
//! IL, `P(in := x);` in ST (lowered to the same `CAL`).
//!
//! Input: a `CAL` whose instance is a plain name that is no variable of the POU but a PROGRAM.
//! Output: the place of the program's one instance (its type is the program, so the arguments are
//! checked as an FB instance's), the program recorded in [`Model::programs_used_by_name`] (the C
//! backend gives other POUs its instance), warning W1417 once per POU and program.
//! Invariants: the instance is the configuration's one instance of the program, or its implicit one
//! without a configuration; a program that the configuration does not instantiate has one instance
//! of its own, run only by such calls (CODESYS: a program in no task runs only where called). A
//! program instantiated twice (which instance is meant?), calling itself (unbounded recursion), or
//! called from a FUNCTION (CODESYS and TwinCAT allow calls from programs and function blocks only)
//! is E3135, as its actions called so are. CODESYS's manual ("Object: Program", Calling a
//! program): programs and function blocks can call a program, whose values are kept also when the
//! next call comes from another POU; so a program that a task runs and a POU calls runs twice.

use super::body::Body;
use super::model::*;
use crate::ast::VarRef;
use diagnostics::code;

impl Body<'_, '_> {
    /// The program called by `CAL instance(...)`, when `instance` names one (and no variable).
    pub(super) fn called_program(&self, instance: &VarRef) -> Option<PouId> {
        if !instance.accessors.is_empty() || self.pou().var(&instance.base.name).is_some() {
            return None;
        }
        self.a
            .pou_names
            .get(&instance.base.key())
            .copied()
            .filter(|id| self.a.model.pous[id.0 as usize].kind == crate::ast::PouKind::Program)
    }

    /// Checks a call of program `id` from this POU (see the module documentation); `None` after
    /// E3135.
    pub(super) fn program_call(&mut self, instance: &VarRef, id: PouId) -> Option<Type> {
        let name = self.a.model.pous[id.0 as usize].name.clone();
        let several = self.program_instances(id);
        let (why, hint) = if id == self.pou {
            (
                format!("`{name}` calls itself, which would never end"),
                "a program runs again in its task's next cycle: remove the call, or loop inside the program (FOR, WHILE)".to_string(),
            )
        } else if self.pou().kind == crate::ast::PouKind::Function {
            (
                format!("a FUNCTION has no state between calls, so it may not run program `{name}` (CODESYS and TwinCAT refuse it too)"),
                "call the program from a program or a function block".to_string(),
            )
        } else if several > 1 {
            (
                format!("program `{name}` has {several} instances in the configuration: the call does not say which one"),
                format!("give `{name}` one instance in the configuration, or make it a FUNCTION_BLOCK and call an instance of it"),
            )
        } else {
            return self.program_called(instance, id, &name);
        };
        self.a
            .error(
                code::E3135,
                instance.span,
                format!("program `{name}` cannot be called here: {why}"),
            )
            .label("call of a program")
            .hint(hint);
        None
    }

    /// Records a valid call of program `id` (named `name`) and warns once per POU and program.
    fn program_called(&mut self, instance: &VarRef, id: PouId, name: &str) -> Option<Type> {
        if !self.a.model.programs_used_by_name.contains(&id) {
            self.a.model.programs_used_by_name.push(id);
        }
        let key = (
            self.pou.0,
            format!("program {}", instance.base.key()),
            "W1417".to_string(),
        );
        if !self.a.silent && self.a.internal_accessed.insert(key) {
            self.a
                .warning(
                    code::W1417,
                    instance.span,
                    format!("program `{name}` called from another POU (a CODESYS and TwinCAT extension: it runs on the program's one instance)"),
                )
                .label("call of a program")
                .hint("IEC 61131-3 runs programs only from tasks; for portable code make it a FUNCTION_BLOCK and call an instance of it");
        }
        Some(Type::Fb(FbType::User(id)))
    }
}
