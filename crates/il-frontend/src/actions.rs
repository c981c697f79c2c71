//! Actions called from outside their POU (CODESYS, TwinCAT, Beremiz, RuSTy): `inst.Act();` in ST,
//! `CAL inst.Act` in IL, with the function block instance's state, once per call.
//!
//! The ST front ends lower each action of a program or function block twice: in place where its own
//! POU calls it (`Act();`, see [`crate::st::PouLowering::set_actions`]), and on its own, as a
//! [`LibraryElement::Action`]. [`link`] runs when every unit is read, before sema: for each call of an
//! action through an instance of its function block it
//! - gives the function block a hidden input flag `__ACTION_<NAME> : BOOL` and puts the action's
//!   statements after its body, behind a dispatch at the start of the body: with the flag set the
//!   call runs the action (which first clears the flag) instead of the body;
//! - rewrites the call `CAL inst.Act(args)` into `CAL inst(args, __ACTION_<NAME> := TRUE)`: the
//!   arguments are passed as in a call of the instance (CODESYS: `Inst.Reset(In := FALSE)`), then
//!   the action runs once.
//!
//! Every [`LibraryElement::Action`] is then dropped: a POU none of whose actions is called from
//! outside is unchanged. An action of a PROGRAM called from another POU (`PLC_PRG.Act();`) is E3135:
//! ladderc runs each program as its own instance and no POU can call another program.

use crate::ast::{
    Accessor, Action, ArgDir, CallArgs, CompilationUnit, Condition, FormalArg, Ident, IlStmt,
    InstrKind, Instruction, LibraryElement, Literal, LiteralKind, Op, Operand, PouKind, TypeRef,
    VarBlock, VarDecl, VarKind, VarRef,
};
use diagnostics::{code, Diagnostic, Diagnostics};
use std::collections::HashMap;

/// The prefix of the hidden input flag that selects an action (`__ACTION_RESET`). A valid IEC
/// identifier never starts with two underscores, so the flag cannot clash with a user's name.
pub const FLAG_PREFIX: &str = "__ACTION_";

/// The label that starts an action's statements in its POU's body.
const LABEL_PREFIX: &str = "__ACT_";

/// Links the calls of actions from other POUs and drops every [`LibraryElement::Action`] of
/// `units` (see the module documentation).
pub fn link(units: &mut [CompilationUnit], diags: &mut Diagnostics) {
    let mut actions: HashMap<String, Vec<Action>> = HashMap::new();
    for u in units.iter_mut() {
        if !u
            .items
            .iter()
            .any(|i| matches!(i, LibraryElement::Action(_)))
        {
            continue;
        }
        for item in std::mem::take(&mut u.items) {
            match item {
                LibraryElement::Action(a) => actions.entry(a.pou.key()).or_default().push(a),
                other => u.items.push(other),
            }
        }
    }
    if actions.is_empty() {
        return;
    }
    let mut kinds: HashMap<String, PouKind> = HashMap::new();
    let mut globals: HashMap<String, TypeRef> = HashMap::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        let mut add = |b: &VarBlock| {
            for v in &b.vars {
                globals.insert(v.name.key(), v.ty.clone());
            }
        };
        match item {
            LibraryElement::Pou(p) => {
                kinds.insert(p.name.key(), p.kind);
            }
            LibraryElement::GlobalVars(b) => add(b),
            LibraryElement::Configuration(c) => {
                c.globals.iter().for_each(&mut add);
                c.resources
                    .iter()
                    .flat_map(|r| r.globals.iter())
                    .for_each(&mut add);
            }
            LibraryElement::DataTypes(_) | LibraryElement::Action(_) => {}
        }
    }
    // In rounds: the calls are rewritten and the called actions noted per function block
    // (upper-case names), then linked into their blocks; a linked action's own calls of actions
    // are rewritten in the next round.
    let mut linked_before: Vec<(String, String)> = Vec::new();
    for round in 0.. {
        let mut called: HashMap<String, Vec<String>> = HashMap::new();
        for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
            let LibraryElement::Pou(p) = item else {
                continue;
            };
            let mut locals: HashMap<String, TypeRef> = HashMap::new();
            for v in p.var_blocks.iter().flat_map(|b| b.vars.iter()) {
                locals.insert(v.name.key(), v.ty.clone());
            }
            let scope = Scope {
                locals: &locals,
                globals: &globals,
                kinds: &kinds,
                actions: &actions,
            };
            rewrite_calls(&mut p.body, &scope, &mut called, diags);
        }
        // the callees: flags, dispatch and the actions' statements
        let mut progress = false;
        for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
            let LibraryElement::Pou(p) = item else {
                continue;
            };
            let key = p.name.key();
            let Some(names) = called.get(&key) else {
                continue;
            };
            let Some(list) = actions.get(&key) else {
                continue;
            };
            let linked: Vec<Action> = list
                .iter()
                .filter(|a| {
                    names.contains(&a.name.key())
                        && !linked_before.contains(&(key.clone(), a.name.key()))
                })
                .cloned()
                .collect();
            if linked.is_empty() {
                continue;
            }
            linked_before.extend(linked.iter().map(|a| (key.clone(), a.name.key())));
            progress = true;
            let span = p.span;
            let end = Ident::new(format!("{LABEL_PREFIX}END{round}"), span);
            let mut body = Vec::new();
            let mut tail = vec![jump(Condition::Always, &end, span)];
            let mut flags = Vec::new();
            for a in linked {
                let s = a.name.span;
                let flag = VarRef {
                    base: Ident::new(flag_name(&a.name), s),
                    accessors: Vec::new(),
                    span: s,
                };
                let label = Ident::new(
                    format!("{LABEL_PREFIX}{}", a.name.name.to_ascii_uppercase()),
                    s,
                );
                flags.push(VarDecl::new(
                    flag.base.clone(),
                    TypeRef::Named(Ident::new("BOOL", s)),
                    s,
                ));
                body.push(simple(Op::Ld, Operand::Var(flag.clone()), s));
                body.push(jump(Condition::IfTrue, &label, s));
                tail.push(IlStmt::Label(label));
                tail.push(simple(Op::Ld, bool_lit(false, s), s));
                tail.push(simple(Op::St, Operand::Var(flag), s));
                tail.extend(a.body);
                tail.push(jump(Condition::Always, &end, s));
                if let Some(t) = a.temps {
                    p.var_blocks.push(t);
                }
                for d in a.diagnostics {
                    let known = diags
                        .iter()
                        .any(|e| e.code == d.code && e.span == d.span && e.message == d.message);
                    if !known {
                        diags.push(d);
                    }
                }
            }
            tail.push(IlStmt::Label(end));
            body.append(&mut p.body);
            body.append(&mut tail);
            p.body = body;
            p.var_blocks.push(VarBlock {
                name: None,
                kind: VarKind::Input,
                constant: false,
                retain: false,
                vars: flags,
                span,
            });
        }
        if !progress {
            break;
        }
    }
}

/// The hidden input flag of an action.
fn flag_name(action: &Ident) -> String {
    format!("{FLAG_PREFIX}{}", action.name.to_ascii_uppercase())
}

/// What a POU's calls are resolved against.
struct Scope<'a> {
    locals: &'a HashMap<String, TypeRef>,
    globals: &'a HashMap<String, TypeRef>,
    kinds: &'a HashMap<String, PouKind>,
    actions: &'a HashMap<String, Vec<Action>>,
}

impl Scope<'_> {
    /// The action `instance` names (`inst.Act`, `insts[i].Act`): the function block's name key and
    /// the action, when the instance's declared type is a function block that has that action.
    fn action_of(&self, instance: &VarRef) -> Option<(String, &Action)> {
        let (Accessor::Field(act), prefix) = instance.accessors.split_last()? else {
            return None;
        };
        let key = instance.base.key();
        let mut ty = self.locals.get(&key).or_else(|| self.globals.get(&key))?;
        for a in prefix {
            match (a, ty) {
                (Accessor::Index(_), TypeRef::Array { element, .. }) => ty = element,
                _ => return None,
            }
        }
        let TypeRef::Named(fb) = ty else {
            return None;
        };
        let action = self
            .actions
            .get(&fb.key())?
            .iter()
            .find(|a| a.name.is(&act.name))?;
        Some((fb.key(), action))
    }

    /// `Prog.Act` where `Prog` names a program with that action (and nothing local or global).
    fn program_action(&self, instance: &VarRef) -> Option<&Action> {
        let [Accessor::Field(act)] = instance.accessors.as_slice() else {
            return None;
        };
        let key = instance.base.key();
        if self.locals.contains_key(&key)
            || self.globals.contains_key(&key)
            || self.kinds.get(&key) != Some(&PouKind::Program)
        {
            return None;
        }
        self.actions
            .get(&key)?
            .iter()
            .find(|a| a.name.is(&act.name))
    }
}

fn rewrite_calls(
    body: &mut [IlStmt],
    scope: &Scope,
    called: &mut HashMap<String, Vec<String>>,
    diags: &mut Diagnostics,
) {
    for s in body.iter_mut() {
        let IlStmt::Instr(i) = s else { continue };
        let span = i.span;
        // (a CAL is a statement of its own: never inside a deferred operator's nested list)
        let InstrKind::Call { instance, args, .. } = &mut i.kind else {
            continue;
        };
        if let Some(a) = scope.program_action(instance) {
            if diags
                .iter()
                .any(|d| d.code == code::E3135 && d.span == Some(instance.span))
            {
                continue;
            }
            diags.push(
                Diagnostic::error(
                    code::E3135,
                    format!(
                        "action `{}` of program `{}` is called from another POU",
                        a.name.name, a.pou.name
                    ),
                )
                .at(instance.span)
                .with_primary_label("action of a program")
                .with_label(a.name.span, "action declared here")
                .with_hint(format!(
                    "call it from `{}` itself (`{}();`), or make `{}` a FUNCTION_BLOCK and call the action through an instance",
                    a.pou.name, a.name.name, a.pou.name
                )),
            );
            continue;
        }
        let Some((fb, action)) = scope.action_of(instance) else {
            continue;
        };
        if matches!(args, CallArgs::NonFormal(_)) {
            continue;
        }
        let act_span = match instance.accessors.last() {
            Some(Accessor::Field(f)) => f.span,
            _ => span,
        };
        let flag = FormalArg {
            name: Ident::new(flag_name(&action.name), act_span),
            dir: ArgDir::Input,
            value: bool_lit(true, act_span),
            span: act_span,
        };
        let names = called.entry(fb).or_default();
        if !names.contains(&action.name.key()) {
            names.push(action.name.key());
        }
        instance.accessors.pop();
        match args {
            CallArgs::Formal(list) => list.push(flag),
            _ => *args = CallArgs::Formal(vec![flag]),
        }
    }
}

fn bool_lit(v: bool, span: diagnostics::Span) -> Operand {
    Operand::literal(Literal {
        kind: LiteralKind::Bool(v),
        type_prefix: None,
        span,
    })
}

fn simple(op: Op, operand: Operand, span: diagnostics::Span) -> IlStmt {
    IlStmt::Instr(Instruction {
        kind: InstrKind::Simple {
            op,
            negate: false,
            operand: Some(operand),
        },
        span,
    })
}

fn jump(cond: Condition, label: &Ident, span: diagnostics::Span) -> IlStmt {
    IlStmt::Instr(Instruction {
        kind: InstrKind::Jump {
            cond,
            label: label.clone(),
        },
        span,
    })
}
