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
//! outside is unchanged. An action of a PROGRAM called from another POU (`PLC_PRG.Act();`) is linked
//! the same way, the call becoming `CAL PLC_PRG(__ACTION_ACT := TRUE)` on the program's one
//! instance (sema and the C backend resolve the program's name to it; a program that the
//! configuration does not instantiate has one instance of its own, run only by such calls); when
//! the program has several instances (a configuration that instantiates it twice) the call is
//! E3135. Inside the program itself, `PLC_PRG.Act();` is its own call `Act();`, inlined before
//! `link` runs (`st::lower::own_name`, [`drop_own_name`]); what reaches `link` so (an IL call with
//! arguments, `CAL PLC_PRG.Act(x := 1)`) stays E3135.
//! An instance that is a program's variable, named through the program (`MAIN.inst.M();`, a
//! property's accessor called for `MAIN.inst.P := v;`; CODESYS and TwinCAT, W1413), is linked as
//! the instance it names, from any POU.

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

/// The name of the action (or method) whose statements label `label` starts in its POU's body
/// (`__ACT_<NAME>`, see [`link`]), upper-case; `None` for any other label (the label after them,
/// `__ACT_END<round>`, gives `END<round>`).
pub fn action_of_label(label: &str) -> Option<&str> {
    label.strip_prefix(LABEL_PREFIX)
}

/// The actions [`link`] read, and which it linked (POU and action, upper-case): what
/// [`with_uncalled`] needs to check those nothing calls.
#[derive(Debug, Default)]
pub struct Linked {
    actions: HashMap<String, Vec<Action>>,
    linked: Vec<(String, String)>,
}

impl Linked {
    /// The METHODs (and property accessors) that [`link`] did not link into their POU, with the
    /// upper-case name of their POU: those [`with_uncalled`] links for a check only. A pass that
    /// reads vendor spellings in the POUs' bodies before the check reads these bodies too, so
    /// that a call in a METHOD gets the diagnostics it gets in a body.
    pub fn uncalled_methods_mut(&mut self) -> impl Iterator<Item = (&str, &mut Action)> {
        let Linked { actions, linked } = self;
        let linked = &*linked;
        actions.iter_mut().flat_map(move |(pou, list)| {
            list.iter_mut()
                .filter(move |a| {
                    a.method_inputs.is_some()
                        && !linked.iter().any(|(p, n)| p == pou && *n == a.name.key())
                })
                .map(move |a| (pou.as_str(), a))
        })
    }
}

/// Links the calls of actions from other POUs and drops every [`LibraryElement::Action`] of
/// `units` (see the module documentation); returns what it read for [`with_uncalled`].
pub fn link(units: &mut [CompilationUnit], diags: &mut Diagnostics) -> Linked {
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
    let mut linked = Vec::new();
    if !actions.is_empty() {
        link_with(units, &actions, &mut linked, None, diags);
    }
    Linked { actions, linked }
}

/// The rounds of [`link`] over `units`: `linked_before` holds the actions already linked (and
/// gets those linked now); `seed`, for [`with_uncalled`]: the first round links every action not
/// linked yet as if called, with its round labels numbered from `seed` (so they differ from the
/// ones [`link`] gave).
fn link_with(
    units: &mut [CompilationUnit],
    actions: &HashMap<String, Vec<Action>>,
    linked_before: &mut Vec<(String, String)>,
    seed: Option<usize>,
    diags: &mut Diagnostics,
) {
    let mut kinds: HashMap<String, PouKind> = HashMap::new();
    // each POU's text, for the access check of code a derived block inherits (`check_access`)
    let mut pou_spans: HashMap<String, crate::Span> = HashMap::new();
    // every POU's variables (upper-case names): `Table.Motor.Stop` walks into instances
    let mut pou_vars: HashMap<String, HashMap<String, TypeRef>> = HashMap::new();
    let mut globals: HashMap<String, TypeRef> = HashMap::new();
    // the names of the named global variable lists (`GVL.fbA.M()`)
    let mut lists: std::collections::HashSet<String> = std::collections::HashSet::new();
    // the instances of each program (upper-case type name -> instance names); without a
    // configuration every program runs as its one implicit instance
    let mut instances: HashMap<String, Vec<Ident>> = HashMap::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        let mut add = |b: &VarBlock| {
            for v in &b.vars {
                globals.insert(v.name.key(), v.ty.clone());
            }
            if let Some(list) = &b.name {
                lists.insert(list.key());
            }
        };
        match item {
            LibraryElement::Pou(p) => {
                kinds.insert(p.name.key(), p.kind);
                pou_spans.insert(p.name.key(), p.span);
                pou_vars.insert(
                    p.name.key(),
                    p.var_blocks
                        .iter()
                        .flat_map(|b| b.vars.iter())
                        .map(|v| (v.name.key(), v.ty.clone()))
                        .collect(),
                );
            }
            LibraryElement::GlobalVars(b) => add(b),
            LibraryElement::Configuration(c) => {
                for p in c.resources.iter().flat_map(|r| r.programs.iter()) {
                    instances
                        .entry(p.type_name.key())
                        .or_default()
                        .push(p.name.clone());
                }
                c.globals.iter().for_each(&mut add);
                c.resources
                    .iter()
                    .flat_map(|r| r.globals.iter())
                    .for_each(&mut add);
            }
            // a structure's fields, so that `p.axis.Act` walks into an instance held in a STRUCT
            // (a property read `p.axis.P` calls its accessor method so)
            LibraryElement::DataTypes(ts) => {
                for t in ts {
                    if let crate::ast::TypeDef::Struct { fields } = &t.def {
                        pou_vars.entry(t.name.key()).or_insert_with(|| {
                            fields
                                .iter()
                                .map(|f| (f.name.key(), f.ty.clone()))
                                .collect()
                        });
                    }
                }
            }
            LibraryElement::Action(_) => {}
        }
    }
    // In rounds: the calls are rewritten and the called actions noted per function block
    // (upper-case names), then linked into their blocks; a linked action's own calls of actions
    // are rewritten in the next round.
    for round in 0.. {
        let mut called: HashMap<String, Vec<String>> = HashMap::new();
        if round == 0 && seed.is_some() {
            for (pou, list) in actions {
                for a in list {
                    if !linked_before.contains(&(pou.clone(), a.name.key())) {
                        called.entry(pou.clone()).or_default().push(a.name.key());
                    }
                }
            }
        }
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
                lists: &lists,
                pou_vars: &pou_vars,
                kinds: &kinds,
                actions,
                instances: &instances,
                pou_spans: &pou_spans,
                caller: p.name.key(),
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
            attach(p, linked, seed.unwrap_or(0) + round, diags);
        }
        if !progress {
            break;
        }
    }
}

/// Puts the actions `linked` into `p`: a hidden input flag each, the dispatch at the start of its
/// body and the actions' statements after it (labels of round `round`); their lowering's
/// diagnostics are reported (once).
fn attach(p: &mut crate::ast::Pou, linked: Vec<Action>, round: usize, diags: &mut Diagnostics) {
    let span = p.span;
    let end = Ident::new(format!("{LABEL_PREFIX}END{round}"), span);
    let mut body = Vec::new();
    let mut tail = vec![jump(Condition::Always, &end, span)];
    let mut flags = Vec::new();
    for a in linked {
        let s = a.name.span;
        let flag = VarRef {
            base: Ident::new(flag_name(&a.name), s),
            accessors: Default::default(),
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
        access: None,
        name: None,
        kind: VarKind::Input,
        constant: false,
        retain: false,
        vars: flags,
        span,
    });
}

/// The units of `units` (after [`link`]) with each action [`link`] did not link (called from no
/// other POU) linked into its POU as if another POU called it, for a check only: an action or
/// METHOD nothing calls is checked as when it is called (issue #13: `check` runs every check
/// `build` runs). `None` when every action is linked. The units returned are for a second
/// semantic analysis, never compiled.
pub fn with_uncalled(
    units: &[CompilationUnit],
    linked: &Linked,
    diags: &mut Diagnostics,
) -> Option<Vec<CompilationUnit>> {
    let all = linked.actions.values().map(Vec::len).sum::<usize>();
    if all == linked.linked.len() {
        return None;
    }
    let mut out = units.to_vec();
    let mut before = linked.linked.clone();
    link_with(&mut out, &linked.actions, &mut before, Some(1000), diags);
    Some(out)
}

/// The spans of the actions [`link`] did not link (the first and last instruction of each), for
/// keeping the diagnostics of [`with_uncalled`]'s check that are theirs.
pub fn uncalled_spans(linked: &Linked) -> Vec<crate::Span> {
    let mut out = Vec::new();
    for (pou, list) in &linked.actions {
        for a in list {
            if linked.linked.contains(&(pou.clone(), a.name.key())) {
                continue;
            }
            // a plain ACTION is checked where its own POU calls it (inlined there, so [`link`]
            // never links it); only METHODs and property accessors are checked on their own
            if a.method_inputs.is_none() {
                continue;
            }
            let spans: Vec<crate::Span> = a
                .body
                .iter()
                .filter_map(|s| match s {
                    IlStmt::Instr(i) => Some(i.span),
                    IlStmt::Label(_) => None,
                })
                .collect();
            // (the instructions of the method's own file: an inlined call may bring others)
            let Some(file) = spans.first().map(|s| s.file) else {
                continue;
            };
            let own = spans.iter().filter(|s| s.file == file);
            let (Some(f), Some(l)) = (
                own.clone().min_by_key(|s| s.start),
                own.max_by_key(|s| s.end),
            ) else {
                continue;
            };
            out.push(f.to(*l));
        }
    }
    out
}

/// The hidden input flag of an action.
fn flag_name(action: &Ident) -> String {
    format!("{FLAG_PREFIX}{}", action.name.to_ascii_uppercase())
}

/// What a POU's calls are resolved against.
/// Reports (E1021, at the member's name) a call `inst.M()` (or a property's `inst.P`) of a
/// PRIVATE or PROTECTED member from a POU that may not call it (IEC 61131-3 ed. 3, 6.6.5;
/// CODESYS "Method": PRIVATE only within its own block, PROTECTED also within the blocks
/// derived from it, at any depth, through any instance).
fn check_access(
    m: &crate::ast::MemberAccess,
    name: &str,
    instance: &VarRef,
    scope: &Scope<'_>,
    diags: &mut Diagnostics,
) {
    if scope.caller == m.owner {
        return;
    }
    // written in the owner's own text, inherited into a derived block (`Compare` of `Account`
    // calling `other.Secret()`, run by a `Savings EXTENDS Account`): the owner's code (IEC 61131-3
    // ed. 3, 6.6.5: access is decided by the class that declares the code)
    let at = instance.span;
    if scope.pou_spans.get(&m.owner).is_some_and(|s| {
        s.file == at.file && s.start <= at.start && at.end <= s.end && s.start < s.end
    }) {
        return;
    }
    if m.access == crate::ast::Access::Protected {
        // the caller's chain of bases, read from its class variable (`base_view::class_var`)
        let derived = scope.pou_vars.get(&scope.caller).is_some_and(|vars| {
            vars.keys()
                .filter_map(|v| crate::st::base_view::class_chain(v))
                .any(|chain| chain.contains(&m.owner))
        });
        if derived {
            return;
        }
    }
    let span = match instance.accessors.last() {
        Some(Accessor::Field(f)) => f.span,
        _ => instance.span,
    };
    let what = if crate::st::property::is_accessor(name) {
        let get = name
            .to_ascii_uppercase()
            .starts_with(crate::st::property::GET_PREFIX);
        let which = if get { "Get" } else { "Set" };
        format!("the {which} accessor of PROPERTY `{}`", m.member)
    } else {
        format!("METHOD `{}`", m.member)
    };
    let who = match m.access {
        crate::ast::Access::Protected => {
            format!(
                "callable only in `{}` and the blocks extending it",
                m.owner_name
            )
        }
        _ => format!("callable only in `{}` itself", m.owner_name),
    };
    diags.push(
        Diagnostic::error(
            code::E1021,
            format!(
                "{what} is {} to `{}`: {who}",
                m.access.keyword(),
                m.owner_name
            ),
        )
        .at(span)
        .with_primary_label(format!("{} {}", m.access.keyword(), m.what))
        .with_label(m.at, format!("declared {} here", m.access.keyword()))
        .with_hint(format!(
            "call a PUBLIC method of `{}` that uses it, or declare it PUBLIC",
            m.owner_name
        )),
    );
}

struct Scope<'a> {
    locals: &'a HashMap<String, TypeRef>,
    globals: &'a HashMap<String, TypeRef>,
    /// The names of the named global variable lists (upper-case).
    lists: &'a std::collections::HashSet<String>,
    /// Every POU's variables by upper-case POU and variable name.
    pou_vars: &'a HashMap<String, HashMap<String, TypeRef>>,
    kinds: &'a HashMap<String, PouKind>,
    actions: &'a HashMap<String, Vec<Action>>,
    instances: &'a HashMap<String, Vec<Ident>>,
    /// Each POU's text (by upper-case name): code inherited by a derived block keeps its spans
    /// in its base's text (`st::inherit`).
    pou_spans: &'a HashMap<String, crate::Span>,
    /// The calling POU (upper-case name).
    caller: String,
}

impl Scope<'_> {
    /// The action `instance` names (`inst.Act`, `insts[i].Act`, `table.motor.Act`, an instance
    /// inside an instance as CODESYS allows): the function block's name key and the action, when
    /// the instance's declared type is a function block that has that action.
    fn action_of(&self, instance: &VarRef) -> Option<(String, &Action)> {
        let (Accessor::Field(act), prefix) = instance.accessors.split_last()? else {
            return None;
        };
        let key = instance.base.key();
        let (mut ty, prefix) = match self.locals.get(&key).or_else(|| self.globals.get(&key)) {
            Some(t) => (t, prefix),
            // `GVL.fbA.Act`: an instance of a named global variable list
            None if self.lists.contains(&key) => match prefix.split_first()? {
                (Accessor::Field(m), rest) => (self.globals.get(&m.key())?, rest),
                _ => return None,
            },
            // `MAIN.inst.M`, `MAIN.inst.P := v`: an instance of a program's variable named
            // through the program's one instance (CODESYS, TwinCAT; W1413), from any POU
            None if self.kinds.get(&key) == Some(&PouKind::Program) => {
                match prefix.split_first()? {
                    (Accessor::Field(m), rest) => (self.pou_vars.get(&key)?.get(&m.key())?, rest),
                    _ => return None,
                }
            }
            None => return None,
        };
        for a in prefix {
            match (a, ty) {
                (Accessor::Index(_), TypeRef::Array { element, .. }) => ty = element,
                (Accessor::Field(f), TypeRef::Named(fb)) => {
                    ty = self.pou_vars.get(&fb.key())?.get(&f.key())?;
                }
                // `r^.M`: the instance a reference refers to (an interface's dispatch calls so)
                (Accessor::Deref(_), TypeRef::Ref { target, .. }) => ty = target,
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
            // (a METHOD of a program: `PRG.M(x)`, CODESYS and TwinCAT)
            method_arguments(a, args, instance);
            // the program's one instance runs the action (CODESYS: `PLC_PRG.Reset();`), unless
            // the program has no instance or several, or calls itself by its name
            let key = a.pou.key();
            let why = match scope.instances.get(&key).map(Vec::as_slice) {
                // (`Prog.Act();` inside Prog is `Act();`, inlined before: `drop_own_name`,
                // `st::lower::own_name`; left here: an IL call with arguments)
                _ if scope.caller == key => Some(format!(
                    "`{}` {} its own action through its name",
                    a.pou.name,
                    if matches!(args, CallArgs::None) {
                        "calls"
                    } else {
                        "passes arguments to"
                    }
                )),
                // (a program in no resource has one instance of its own: `sema::program_calls`)
                Some([_]) | None => None,
                Some(list) => Some(format!(
                    "program `{}` has {} instances ({}): the call does not say which one",
                    a.pou.name,
                    list.len(),
                    list.iter()
                        .map(|i| format!("`{}`", i.name))
                        .collect::<Vec<_>>()
                        .join(", ")
                )),
            };
            match why {
                None if !matches!(args, CallArgs::NonFormal(_)) => {
                    let act_span = match instance.accessors.last() {
                        Some(Accessor::Field(f)) => f.span,
                        _ => span,
                    };
                    let flag = FormalArg {
                        name: Ident::new(flag_name(&a.name), act_span),
                        dir: ArgDir::Input,
                        value: bool_lit(true, act_span),
                        span: act_span,
                    };
                    let names = called.entry(key).or_default();
                    if !names.contains(&a.name.key()) {
                        names.push(a.name.key());
                    }
                    instance.accessors.pop();
                    match args {
                        CallArgs::Formal(list) => list.push(flag),
                        _ => *args = CallArgs::Formal(vec![flag]),
                    }
                }
                None => {}
                Some(why) => {
                    if diags
                        .iter()
                        .any(|d| d.code == code::E3135 && d.span == Some(instance.span))
                    {
                        continue;
                    }
                    // a property's accessor is named by the property (never `__GET_P`)
                    let what = crate::st::property::describe_action(&a.name.name);
                    let accessor = crate::st::property::is_accessor(&a.name.name);
                    let prop = a.name.name.get(crate::st::property::GET_PREFIX.len()..);
                    let (label, declared, hint) = match prop {
                        Some(p) if accessor => (
                            "property of a program",
                            "property declared here",
                            format!(
                                "use `{p}` from `{}` itself, or give the program one instance",
                                a.pou.name
                            ),
                        ),
                        _ => (
                            "action of a program",
                            "action declared here",
                            format!(
                                "call it from `{}` itself (`{}();`), or give the program one instance",
                                a.pou.name, a.name.name
                            ),
                        ),
                    };
                    diags.push(
                        Diagnostic::error(
                            code::E3135,
                            format!(
                                "{what} of program `{}` cannot be called here: {why}",
                                a.pou.name
                            ),
                        )
                        .at(instance.span)
                        .with_primary_label(label)
                        .with_label(a.name.span, declared)
                        .with_hint(hint),
                    );
                }
            }
            continue;
        }
        let Some((fb, action)) = scope.action_of(instance) else {
            continue;
        };
        if let Some(m) = &action.access {
            check_access(m, &action.name.name, instance, scope, diags);
        }
        method_arguments(action, args, instance);
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

/// A method's arguments (of an action with `method_inputs`) go to its hidden variables
/// `__M_<METHOD>_<input>`: positional ones in the order of its inputs.
fn method_arguments(action: &Action, args: &mut CallArgs, called: &VarRef) {
    let Some(inputs) = &action.method_inputs else {
        return;
    };
    let m = &action.name.name;
    match args {
        // the inputs and in-outs in order, then the outputs (IEC 61131-3 ed. 3, 6.6.1.4.2: a
        // non-formal call gives the parameters in the order of the definition; SIMATIC AX writes
        // `c.Get(x)` for a method whose only parameter is an output; before round 26: E1011)
        CallArgs::NonFormal(ops) if ops.len() <= inputs.len() + action.method_outputs.len() => {
            let outputs = action.method_outputs.iter().map(|o| (o, true));
            let list = std::mem::take(ops)
                .into_iter()
                .zip(inputs.iter().map(|i| (i, false)).chain(outputs))
                .map(|(value, (param, output))| FormalArg {
                    name: Ident::new(method_var(m, &param.name), value.span()),
                    dir: if output {
                        ArgDir::Output { negated: false }
                    } else {
                        ArgDir::Input
                    },
                    span: value.span(),
                    value,
                })
                .collect();
            *args = CallArgs::Formal(list);
        }
        CallArgs::Formal(list) => {
            for a in list.iter_mut() {
                if !a.name.is("EN") && !a.name.is("ENO") {
                    a.name.name = method_var(m, &a.name.name);
                }
            }
        }
        CallArgs::None if !action.method_defaults.is_empty() => {
            *args = CallArgs::Formal(Vec::new());
        }
        _ => {}
    }
    // the value inputs the call leaves out start again at their initial values
    if let CallArgs::Formal(list) = args {
        for (input, reference) in &action.method_defaults {
            let hidden = method_var(m, &input.name);
            if list.iter().any(|a| a.name.is(&hidden)) {
                continue;
            }
            let span = called.span;
            if *reference {
                // a reference left out refers to nothing (not to the previous call's variable)
                list.push(FormalArg {
                    name: Ident::new(hidden, span),
                    dir: ArgDir::Input,
                    value: Operand::Ref(Box::new(crate::ast::RefOperand {
                        of: None,
                        span,
                        call_scoped: false,
                        address_of: false,
                    })),
                    span,
                });
                continue;
            }
            // the instance's own default (`inst.__MD_M_X`; `called` is `inst.M`, or the
            // program's name)
            let mut value = called.clone();
            if value.accessors.is_empty() {
                value.accessors.push(Accessor::Field(Ident::new(
                    method_input_default(m, &input.name),
                    span,
                )));
            } else if let Some(Accessor::Field(f)) = value.accessors.last_mut() {
                *f = Ident::new(method_input_default(m, &input.name), span);
            }
            list.push(FormalArg {
                name: Ident::new(hidden, span),
                dir: ArgDir::Input,
                value: Operand::Var(value),
                span,
            });
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

/// A copy of an action's IL statements for one place it runs: every label (and jump target) gets
/// the prefix `tag`, so two copies in one POU never share a label, and `RET`/`RETC`/`RETCN` become
/// jumps to the copy's end (`<tag>END`): a return leaves the action, not the POU that runs it
/// (CODESYS). Used for actions written in IL, LD or FBD (PLCopen XML `<actions>`), inlined where
/// their POU calls them and linked for calls through an instance.
pub fn instantiate(body: &[IlStmt], tag: &str, span: diagnostics::Span) -> Vec<IlStmt> {
    let end = Ident::new(format!("{tag}END"), span);
    let mut returns = false;
    let mut out = body.to_vec();
    relabel(&mut out, tag, &end, &mut returns);
    if returns {
        out.push(IlStmt::Label(end));
    }
    out
}

fn relabel(stmts: &mut [IlStmt], tag: &str, end: &Ident, returns: &mut bool) {
    for s in stmts {
        match s {
            IlStmt::Label(l) => l.name = format!("{tag}{}", l.name),
            IlStmt::Instr(i) => match &mut i.kind {
                InstrKind::Jump { label, .. } => label.name = format!("{tag}{}", label.name),
                InstrKind::Return { cond } => {
                    *returns = true;
                    i.kind = InstrKind::Jump {
                        cond: *cond,
                        label: end.clone(),
                    };
                }
                InstrKind::Deferred { body, .. } => relabel(body, tag, end, returns),
                _ => {}
            },
        }
    }
}

/// Whether a name is one of the variables `p` declares (any case): the `is_var` of
/// [`inline_calls`] for a body of `p` or of one of its actions or methods.
pub fn declares(p: &crate::ast::Pou) -> impl Fn(&str) -> bool {
    let vars: std::collections::HashSet<String> = p
        .var_blocks
        .iter()
        .flat_map(|b| b.vars.iter().map(|v| v.name.key()))
        .collect();
    move |n: &str| vars.contains(&n.to_ascii_uppercase())
}

/// `CAL Prog.Act` (also `CALC`, `CALCN`) inside PROGRAM `Prog`, in its IL body or one of its
/// actions, becomes `CAL Act`: the program's own action, which [`inline_calls`] then puts in
/// place. CODESYS ("Object: Action") names an action `<program name>.<action name>`, the
/// program's name optional inside the program: the same call (before issue #13's round 26:
/// E3135). `actions` maps upper-case names to statements, as for [`inline_calls`]; `is_var`
/// tells the names a variable holds (a variable named like the program keeps the call).
pub fn drop_own_name(
    body: &mut [IlStmt],
    pou: &crate::ast::Pou,
    actions: &HashMap<String, Vec<IlStmt>>,
    is_var: &dyn Fn(&str) -> bool,
) {
    if pou.kind != PouKind::Program || is_var(&pou.name.name) {
        return;
    }
    for s in body.iter_mut() {
        let IlStmt::Instr(Instruction {
            kind: InstrKind::Call { instance, args, .. },
            ..
        }) = s
        else {
            continue;
        };
        let own = match instance.accessors.as_slice() {
            [Accessor::Field(act)] => {
                instance.base.is(&pou.name.name)
                    && actions.contains_key(&act.key())
                    && matches!(args, CallArgs::None)
            }
            _ => false,
        };
        if own {
            if let Some(Accessor::Field(act)) = instance.accessors.pop() {
                instance.span = act.span;
                instance.base = act;
            }
        }
    }
}

/// Inlines the calls of a POU's own IL-level actions in `body` (an IL body, or an action's
/// statements): `CAL Act` (no arguments, `Act` not a variable of the POU, see `is_var`) is replaced
/// by a copy of the action's statements ([`instantiate`], labels tagged `<prefix><n>_`), `CALC Act` /
/// `CALCN Act` by the copy behind a conditional jump. `actions` maps upper-case names to
/// statements; `next` numbers the copies of the POU. An action that calls itself (directly or
/// through another action) is E0106, at the call.
pub fn inline_calls(
    body: Vec<IlStmt>,
    actions: &HashMap<String, Vec<IlStmt>>,
    is_var: &dyn Fn(&str) -> bool,
    prefix: &str,
    next: &mut usize,
    diags: &mut Diagnostics,
) -> Vec<IlStmt> {
    let mut stack = Vec::new();
    inline_rec(body, actions, is_var, prefix, next, &mut stack, diags)
}

fn inline_rec(
    body: Vec<IlStmt>,
    actions: &HashMap<String, Vec<IlStmt>>,
    is_var: &dyn Fn(&str) -> bool,
    prefix: &str,
    next: &mut usize,
    stack: &mut Vec<String>,
    diags: &mut Diagnostics,
) -> Vec<IlStmt> {
    let mut out = Vec::with_capacity(body.len());
    for s in body {
        let target = match &s {
            IlStmt::Instr(Instruction {
                kind:
                    InstrKind::Call {
                        cond,
                        instance,
                        args,
                    },
                span,
            }) if instance.accessors.is_empty()
                && actions.contains_key(&instance.base.key())
                && !is_var(&instance.base.name)
                && (matches!(args, CallArgs::None)
                    || crate::st::lower::method_in_out::is_in_out_binding(
                        &instance.base.name,
                        args,
                    )) =>
            {
                Some((
                    *cond,
                    instance.base.key(),
                    instance.base.name.clone(),
                    *span,
                    args.clone(),
                ))
            }
            _ => None,
        };
        let Some((cond, key, written, span, args)) = target else {
            out.push(s);
            continue;
        };
        if stack.contains(&key) {
            // (the copies of a block's own method calls are tagged so, `inline_own_method_calls`)
            let upper = written.to_ascii_uppercase();
            let accessor = [
                crate::st::property::GET_PREFIX,
                crate::st::property::SET_PREFIX,
            ]
            .iter()
            .any(|p| upper.starts_with(p));
            let method = prefix == METHOD_CALL_PREFIX && !accessor;
            let d = if method {
                // (a METHOD's variables are the instance's hidden ones: one set per instance)
                Diagnostic::error(
                    code::E0106,
                    format!(
                        "method `{written}` calls itself (directly or through another method): ladderc does not compile recursive methods"
                    ),
                )
                .at(span)
                .with_primary_label("recursive method call")
                .with_hint("IEC 61131-3 forbids recursion (CODESYS and TwinCAT allow it in methods); ladderc keeps a method's variables once per instance, so a call cannot nest in itself: write the recursion as a loop with an explicit stack (an array)")
            } else {
                Diagnostic::error(
                    code::E0106,
                    format!(
                        "{} calls itself (directly or through another action)",
                        crate::st::property::describe_action(&written)
                    ),
                )
                .at(span)
                .with_primary_label("recursive action call")
                .with_hint("actions are inlined where they are called; they cannot recurse")
            };
            diags.push(d);
            continue;
        }
        *next += 1;
        let tag = format!("{prefix}{next}_");
        let mut copy = instantiate(&actions[&key], &tag, span);
        // a method's in-outs: the copy names the call's arguments
        crate::st::lower::method_in_out::bind_in_outs(&mut copy, &args);
        stack.push(key);
        let copy = inline_rec(copy, actions, is_var, prefix, next, stack, diags);
        stack.pop();
        let skip = Ident::new(format!("{tag}SKIP"), span);
        let guard = match cond {
            Condition::Always => None,
            Condition::IfTrue => Some(Condition::IfFalse),
            Condition::IfFalse => Some(Condition::IfTrue),
        };
        if let Some(c) = guard {
            out.push(jump(c, &skip, span));
        }
        out.extend(copy);
        if guard.is_some() {
            out.push(IlStmt::Label(skip));
        }
    }
    out
}

/// The hidden variable of a method's parameter or local `var`: `__M_<METHOD>_<VAR>`.
pub fn method_var(method: &str, var: &str) -> String {
    format!(
        "{METHOD_PREFIX}{}_{}",
        method.to_ascii_uppercase(),
        var.to_ascii_uppercase()
    )
}

/// The hidden, never written variable holding the initial value of a method's value input:
/// `__MD_<METHOD>_<INPUT>`, passed when a call does not give the input (see
/// [`crate::ast::Action::method_defaults`]).
pub fn method_input_default(method: &str, input: &str) -> String {
    format!(
        "__MD_{}_{}",
        method.to_ascii_uppercase(),
        input.to_ascii_uppercase()
    )
}

/// The hidden output holding a method's result: `__M_<METHOD>`.
pub fn method_result(method: &str) -> String {
    format!("{METHOD_PREFIX}{}", method.to_ascii_uppercase())
}

/// The tag of the copies of a function block's calls of its own methods (the `prefix` of
/// [`inline_calls`] for them).
pub const METHOD_CALL_PREFIX: &str = "__MC";

/// The prefix of a method's hidden variables (see [`method_var`]).
pub const METHOD_PREFIX: &str = "__M_";

thread_local! {
    /// The hidden names of the methods' variables declared by the compilation under way on this
    /// thread (`__M_TAKE_O`, `__MD_TAKE_O`, `__M_TAKE`, `__MZ_TAKE`) with the user's spelling
    /// (`Take.o`, `Take`): see [`remember_spellings`]; emptied as each compilation starts
    /// ([`forget_spellings`]).
    static SPELLINGS: std::cell::RefCell<std::collections::HashMap<String, String>> =
        std::cell::RefCell::new(std::collections::HashMap::new());
}

/// Forgets every spelling [`remember_spellings`] recorded on this thread: called as a compilation
/// starts reading its inputs, so that its messages show only its own methods' names (before round
/// 28 the table only grew: a language server's later compiles showed the names of methods no
/// longer declared, `Take.oVal` for a `__M_TAKE_OVAL` of another text).
pub fn forget_spellings() {
    SPELLINGS.with(|s| s.borrow_mut().clear());
}

/// Records how the user wrote method `method` and its variables `vars`, for [`shown_names`].
pub fn remember_spellings<'a>(method: &str, vars: impl Iterator<Item = &'a str>) {
    SPELLINGS.with(|s| {
        let mut s = s.borrow_mut();
        s.insert(method_result(method), method.to_string());
        s.insert(
            format!("__MZ_{}", method.to_ascii_uppercase()),
            method.to_string(),
        );
        for v in vars {
            let shown = format!("{method}.{v}");
            s.insert(method_input_default(method, v), shown.clone());
            s.insert(method_var(method, v), shown);
        }
    });
}

/// `text` (a diagnostic's message, label or hint) with each hidden name of a method's variable
/// (`__M_TAKE_O`, its default `__MD_TAKE_O`, the result `__M_TAKE`) shown as the user wrote it
/// (`Take.o`, `Take`; as recorded by [`remember_spellings`], else the hidden name without its
/// prefix, `TAKE.O`); `None` when `text` holds none. Before round 27 messages showed the hidden
/// names (E1012 `__M_TAKE_O of FB_User is ...`, E1080's chain).
pub fn shown_names(text: &str) -> Option<String> {
    if !text.contains("__M") {
        return None;
    }
    let bytes = text.as_bytes();
    let word = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    let mut changed = false;
    while i < bytes.len() {
        let starts = (i == 0 || !word(bytes[i - 1]))
            && ["__M_", "__MD_", "__MZ_"]
                .iter()
                .any(|p| text[i..].starts_with(p));
        if !starts {
            let c = text[i..].chars().next().unwrap_or(' ');
            out.push(c);
            i += c.len_utf8();
            continue;
        }
        let end = text[i..]
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .map_or(text.len(), |n| i + n);
        let hidden = &text[i..end];
        let known = SPELLINGS.with(|s| s.borrow().get(&hidden.to_ascii_uppercase()).cloned());
        let shown = known.unwrap_or_else(|| unknown_hidden(hidden));
        out.push_str(&shown);
        changed = true;
        i = end;
    }
    changed.then_some(out)
}

/// A hidden name [`remember_spellings`] did not record (a variable no longer declared): the
/// method's name as written, when a method whose name it starts with is known (the longest:
/// method names may hold `_`), then the variable's upper-case name (`M_MoveBy.RDISTANCE`); else
/// the name after its prefix.
fn unknown_hidden(hidden: &str) -> String {
    let upper = hidden.to_ascii_uppercase();
    let rest = ["__M_", "__MD_", "__MZ_"]
        .iter()
        .find_map(|p| upper.strip_prefix(p))
        .unwrap_or(&upper);
    let method = SPELLINGS.with(|s| {
        s.borrow()
            .iter()
            .filter(|(k, v)| k.starts_with(METHOD_PREFIX) && !v.contains('.'))
            .filter_map(|(k, v)| {
                let m = &k[METHOD_PREFIX.len()..];
                rest.strip_prefix(m)
                    .and_then(|r| r.strip_prefix('_'))
                    .filter(|r| !r.is_empty())
                    .map(|r| (m.len(), v.clone(), r.to_string()))
            })
            .max_by_key(|(n, _, _)| *n)
    });
    match method {
        Some((_, m, var)) => format!("{m}.{var}"),
        None => rest.to_string(),
    }
}

/// `d` with the hidden names of methods' variables in its message, labels, hint and notes shown
/// as the user wrote them ([`shown_names`]).
pub fn show_user_names(d: &mut diagnostics::Diagnostic) {
    let fix = |s: &mut String| {
        if let Some(n) = shown_names(s) {
            *s = n;
        }
    };
    fix(&mut d.message);
    fix(&mut d.primary_label);
    for l in &mut d.labels {
        fix(&mut l.message);
    }
    if let Some(h) = &mut d.hint {
        fix(h);
    }
    for n in &mut d.notes {
        fix(n);
    }
}
