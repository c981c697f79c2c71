//! CODESYS's and TwinCAT's `FB_init` method, run once per function block instance before the first
//! cycle, with the arguments of the instance's declaration (`fb : FB_X(nSize := 10);`).
//!
//! What the vendors document, and ladderc follows (Beckhoff Infosys "Methods FB_init, FB_reinit and
//! FB_exit", "Behavior with derived function blocks"; CODESYS online help "Method: FB_Init,
//! FB_Reinit, FB_Exit"): on a first download (a cold start, what a simulation run is) every
//! instance's FB_init runs implicitly, after its variables have their initial values, with
//! `bInitRetains := TRUE, bInCopyCode := FALSE`; the extra inputs of FB_init get the declaration's
//! arguments (positional ones in FB_init's order after those two); an instance inside another
//! block is initialised before the block that holds it; for a block that EXTENDS another, the
//! base's FB_init runs first, then the block's own (which has the base's parameters, and maybe
//! more: each base version gets the arguments its own inputs name). FB_reinit runs only after an
//! online change copied an instance and FB_exit only before one is removed (a new download, an
//! online change): a simulation does neither, so neither is called (a note, W0345, says so).
//!
//! Input: the units after every ST body and method is lowered (each method an
//! [`Action`] with `method_inputs`; a base's FB_init a hidden method
//! `__S<level>_FB_INIT`, see [`super::inherit`]) and the FB_init arguments read by
//! [`super::fb_init_args`]. Output: each PROGRAM or FUNCTION_BLOCK that holds instances to
//! initialise gets a hidden method [`ACTION`] that initialises them in declaration order (for each:
//! its own instances first, through its [`ACTION`], then its bases' FB_init, then its FB_init, then
//! the inputs its declaration's structured initial value sets, again, and its methods marked
//! `{attribute 'call_after_init'}`; an array element by element, a structure field by field), and
//! one hidden PROGRAM [`PROGRAM`] does so for the global variables (after it assigns the global
//! lists' interface variables their instances and computes their run-time initial values),
//! then runs every program's [`ACTION`] and its own initial values computed at run time (its
//! `method_inits::INIT_PREFIX` method, `pou_inits`; a program that a configuration
//! instantiates twice computes them when each instance first runs). The C backend runs that
//! program once, before the first cycle (before the cycle-0 stimulus), never in a cycle.
//! Invariants: a project without FB_init methods or computed initial values is unchanged; every
//! argument that goes nowhere is one E0329 naming it; an array of more than [`MAX_ELEMENTS`]
//! instances to initialise, or a POU needing more than [`MAX_STATEMENTS`] calls, is E0345; a
//! program whose instances need it and that a configuration instantiates twice is E0347.

use super::ast::{Accessor, Arg, ArgDir, Expr, ExprKind, Place, PlaceBase, Stmt, StmtKind};
use super::fb_init_args::DeclArgs;
use super::file::PendingBody;
use super::types::MethodSig;
use crate::ast::{
    Action, CompilationUnit, Ident, Initializer, LibraryElement, LiteralKind, Operand, Pou,
    PouKind, TypeRef, VarBlock, VarKind,
};
use crate::Span;
use diagnostics::{code, Diagnostic, Diagnostics, Severity};
use std::collections::{HashMap, HashSet};

/// The hidden method of a PROGRAM or FUNCTION_BLOCK that initialises its instances.
pub const ACTION: &str = "__FBINIT";
/// The hidden program that initialises the global instances and runs every program's
/// [`ACTION`]: run once by the C backend before the first cycle.
pub const PROGRAM: &str = "__FBINIT_ALL";
/// The most elements of one array of instances that are initialised one by one.
pub const MAX_ELEMENTS: u128 = 4096;

/// The most initialisation statements of one POU (arrays of structures of arrays multiply).
pub const MAX_STATEMENTS: usize = 65_536;

/// The two inputs every FB_init has (Beckhoff compiler error C0119 when one is missing).
const SYSTEM_INPUTS: [&str; 2] = ["bInitRetains", "bInCopyCode"];

/// What a function block runs when one of its instances is initialised.
#[derive(Default, Clone)]
struct Block {
    /// Its bases' FB_init versions, root first: hidden method name and inputs.
    bases: Vec<(String, Vec<String>)>,
    /// Its FB_init's inputs (its own, or the nearest base's).
    fb_init: Option<Vec<String>>,
    /// Its methods marked `{attribute 'call_after_init'}` (with the block): run after FB_init.
    after_init: Vec<String>,
    /// The hidden methods that compute its methods' VAR_INST initial values
    /// ([`super::method_inits::INIT_PREFIX`]): run before its bases' FB_init.
    inst_inits: Vec<String>,
    /// Its VAR_INPUT names (upper case): a declaration's structured initial value of one is set
    /// again after FB_init.
    inputs: HashSet<String>,
    /// The lower bound of each one-dimensional array VAR_INPUT (upper-case name): an array
    /// initial value of one (`MaxVelocity := [ 1.2, 0.6 ]`, Struckig's examples) is set again
    /// element by element.
    array_inputs: HashMap<String, i128>,
}

impl Block {
    /// Whether an instance runs anything when it is initialised.
    fn runs(&self) -> bool {
        self.fb_init.is_some() || !self.after_init.is_empty() || !self.inst_inits.is_empty()
    }
}

/// See the module documentation. `pending` holds the FB_init arguments of every file.
/// `declared`: the blocks (upper-case names) whose text declares an FB_init, also those that are
/// not compiled (their own error is reported: arguments for their instances are no E0329 more);
/// `interface_globals`: the assignments that give the global lists' interface variables their
/// instances (`super::interface_vars::global_initial_values`), run first.
pub fn add_init_calls(
    units: &mut [CompilationUnit],
    pending: &[PendingBody],
    (declared, interface_globals): (&HashSet<String>, Vec<Stmt>),
    decls: &mut super::Declarations,
    diags: &mut Diagnostics,
) {
    let mut args: HashMap<(crate::FileId, u32), (&DeclArgs, bool)> = pending
        .iter()
        .flat_map(|pb| pb.fb_init_args.iter())
        .map(|a| ((a.ty.file, a.ty.start), (a, false)))
        .collect();
    // the FB_init of each block, from its lowered methods
    let mut blocks: HashMap<String, Block> = HashMap::new();
    let mut never_called: Vec<(Ident, Ident)> = Vec::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        let LibraryElement::Action(a) = item else {
            continue;
        };
        let Some(inputs) = &a.method_inputs else {
            continue;
        };
        let inputs: Vec<String> = inputs.iter().map(|i| i.name.clone()).collect();
        let name = a.name.key();
        let b = blocks.entry(a.pou.key()).or_default();
        if name == "FB_INIT" {
            b.fb_init = Some(inputs);
        } else if name.starts_with("__S") && name.ends_with("_FB_INIT") {
            b.bases.push((a.name.name.clone(), inputs));
        } else if name.starts_with(super::method_inits::INIT_PREFIX) {
            b.inst_inits.push(a.name.name.clone());
        } else if (name == "FB_EXIT" || name == "FB_REINIT")
            // (an inherited method is the base's text: noted once)
            && !never_called.iter().any(|(_, m)| m.span == a.name.span)
        {
            never_called.push((a.pou.clone(), a.name.clone()));
        }
    }
    for b in blocks.values_mut() {
        // `__S00_...` before `__S01_...`: root first
        b.bases.sort();
    }
    // `{attribute 'call_after_init'}` methods: no inputs (CODESYS, TwinCAT: a compile error)
    for pb in pending.iter().filter(|pb| !pb.after_init.is_empty()) {
        let Some(pou) = pb.pou_name(units).cloned() else {
            continue;
        };
        for m in &pb.after_init {
            let inputs = units
                .iter()
                .flat_map(|u| u.items.iter())
                .find_map(|i| match i {
                    LibraryElement::Action(a) if a.pou.is(&pou.name) && a.name.is(&m.name) => {
                        a.method_inputs.as_ref().map(Vec::len)
                    }
                    _ => None,
                });
            match inputs {
                Some(0) => blocks
                    .entry(pou.key())
                    .or_default()
                    .after_init
                    .push(m.name.clone()),
                Some(_) => diags.push(
                    Diagnostic::error(
                        code::E0346,
                        format!(
                            "method `{}` of `{}` is marked call_after_init but has inputs",
                            m.name, pou.name
                        ),
                    )
                    .at(m.span)
                    .with_primary_label("called after initialisation, without arguments")
                    .with_hint("a call_after_init method runs with no arguments (CODESYS and TwinCAT refuse its VAR_INPUTs too): read what it needs from the block's variables"),
                ),
                None => {}
            }
        }
    }
    for (pou, m) in never_called {
        diags.push(
            Diagnostic::new(
                code::W0345,
                Severity::Note,
                format!(
                    "`{}.{}` is never called in a simulation",
                    pou.name, m.name
                ),
            )
            .at(m.span)
            .with_primary_label("not called")
            .with_hint(if m.is("FB_exit") {
                "CODESYS and TwinCAT call FB_exit before an instance is removed (a new download, an online change); a run of ladderc starts once and is never replaced"
            } else {
                "CODESYS and TwinCAT call FB_reinit after an online change copied the instance; a run of ladderc has no online change"
            }),
        );
    }
    let has_fb_init = blocks.values().any(Block::runs);
    for item in units.iter().flat_map(|u| u.items.iter()) {
        if let LibraryElement::Pou(p) = item {
            if let Some(b) = blocks.get_mut(&p.name.key()) {
                b.inputs = p
                    .var_blocks
                    .iter()
                    .filter(|b| b.kind == VarKind::Input)
                    .flat_map(|b| b.vars.iter().map(|v| v.name.key()))
                    .filter(|n| !n.starts_with("__"))
                    .collect();
                b.array_inputs = p
                    .var_blocks
                    .iter()
                    .filter(|b| b.kind == VarKind::Input)
                    .flat_map(|b| b.vars.iter())
                    .filter_map(|v| match &v.ty {
                        TypeRef::Array { dims, .. } if dims.len() == 1 => {
                            Some((v.name.key(), dims[0].lower))
                        }
                        _ => None,
                    })
                    .collect();
            }
        }
    }
    // a type whose missing FB_init is worth an E0329: a block of the project whose text has none,
    // or a standard block (an unknown type, or a block not compiled, has its own error)
    let project_fbs: HashSet<String> = units
        .iter()
        .flat_map(|u| u.items.iter())
        .filter_map(|i| match i {
            LibraryElement::Pou(p) if p.kind == PouKind::FunctionBlock => Some(p.name.key()),
            _ => None,
        })
        .collect();
    let data_types: HashSet<String> = units
        .iter()
        .flat_map(CompilationUnit::type_decls)
        .map(|t| t.name.key())
        .collect();
    let reportable = |t: &str| {
        let key = t.to_ascii_uppercase();
        (project_fbs.contains(&key) && !declared.contains(&key))
            || data_types.contains(&key)
            || crate::sema::StdFb::from_name(&key).is_some()
    };
    // the global lists' initial values computed at run time (`pou_inits::global_run_time_inits`)
    let global_inits = pending
        .iter()
        .any(|pb| pb.name_start == usize::MAX && !pb.var_inits.is_empty());
    if !has_fb_init && args.is_empty() && !global_inits && interface_globals.is_empty() {
        return;
    }
    // every POU's kind and variables
    let mut pous: HashMap<String, (PouKind, Vec<VarBlock>)> = HashMap::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        if let LibraryElement::Pou(p) = item {
            pous.entry(p.name.key())
                .or_insert_with(|| (p.kind, p.var_blocks.clone()));
        }
    }
    // the structures' fields: an instance in a structure is initialised too
    let mut structs: HashMap<String, Vec<crate::ast::VarDecl>> = HashMap::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        if let LibraryElement::DataTypes(ts) = item {
            for t in ts {
                if let crate::ast::TypeDef::Struct { fields } = &t.def {
                    structs
                        .entry(t.name.key())
                        .or_insert_with(|| fields.clone());
                }
            }
        }
    }
    let types = Types {
        pous: &pous,
        structs: &structs,
        blocks: &blocks,
    };
    // which blocks, programs and structures hold instances to initialise
    let mut holds: HashMap<String, bool> = HashMap::new();
    for k in pous.keys().chain(structs.keys()) {
        types.holds(k, &mut holds, &mut HashSet::new());
    }
    let mut gen = Gen {
        reportable: &reportable,
        types: &types,
        holds: &holds,
        args: &mut args,
        diags,
        overflowed: false,
    };
    // the statements of each POU's ACTION, and of the hidden program
    let mut bodies: Vec<(String, Vec<Stmt>)> = Vec::new();
    let mut globals = Vec::new();
    let mut programs = Vec::new();
    // the instances of each program in the configurations (`PROGRAM i1 WITH t : P;`)
    let mut configured: HashMap<String, Vec<Ident>> = HashMap::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        if let LibraryElement::Configuration(c) = item {
            for p in c.resources.iter().flat_map(|r| r.programs.iter()) {
                configured
                    .entry(p.type_name.key())
                    .or_default()
                    .push(p.name.clone());
            }
        }
    }
    for item in units.iter().flat_map(|u| u.items.iter()) {
        match item {
            LibraryElement::Pou(p) if p.kind != PouKind::Function => {
                let stmts = gen.members(&p.var_blocks);
                // a program's own initial values computed at run time (its `INIT_PREFIX`
                // method, `pou_inits`): assigned here too, before the first cycle's stimulus,
                // as a block's are when its instance is initialised (round 33; before, at the
                // program's first run, after the cycle-0 stimulus, which they overwrote)
                let own_inits = match blocks.get(&p.name.key()) {
                    Some(b) if p.kind == PouKind::Program => b.inst_inits.clone(),
                    _ => Vec::new(),
                };
                if stmts.is_empty() && own_inits.is_empty() {
                    continue;
                }
                if p.kind == PouKind::Program {
                    // the hidden program calls the program's ACTION on its one instance
                    if let Some(list) = configured.get(&p.name.key()).filter(|l| l.len() > 1) {
                        if stmts.is_empty() {
                            // (each instance computes its own values when it first runs)
                            continue;
                        }
                        gen.diags.push(
                            Diagnostic::error(
                                code::E0347,
                                format!(
                                    "program `{}` has {} instances ({}): the FB_init of the instances it declares is not run",
                                    p.name.name,
                                    list.len(),
                                    list.iter()
                                        .map(|i| format!("`{}`", i.name))
                                        .collect::<Vec<_>>()
                                        .join(", ")
                                ),
                            )
                            .at(list[1].span)
                            .with_primary_label("a second instance")
                            .with_label(p.name.span, "declares instances with FB_init")
                            .with_hint("ladderc runs FB_init on a program's one instance: instantiate the program once, or move its instances into a function block that each program instance holds"),
                        );
                        continue;
                    }
                    programs.push((p.name.clone(), !stmts.is_empty(), own_inits));
                }
                if !stmts.is_empty() {
                    bodies.push((p.name.key(), stmts));
                }
            }
            LibraryElement::GlobalVars(b) => globals.extend(gen.members(std::slice::from_ref(b))),
            LibraryElement::Configuration(c) => {
                globals.extend(gen.members(&c.globals));
                for r in &c.resources {
                    globals.extend(gen.members(&r.globals));
                }
            }
            _ => {}
        }
    }
    // arguments no instance took: a declaration of no function block's instance (a method's
    // variable, a structure's field, an unknown type)
    let mut left: Vec<&DeclArgs> = args
        .values()
        .filter(|(_, used)| !used)
        .map(|(a, _)| *a)
        .collect();
    left.sort_by_key(|a| (a.span.file, a.span.start));
    // (a declaration in no POU or list that was read: its POU's own errors are reported)
    let read: Vec<Span> = units
        .iter()
        .flat_map(|u| u.items.iter())
        .filter_map(|i| match i {
            LibraryElement::Pou(p) => Some(p.span),
            LibraryElement::GlobalVars(b) => Some(b.span),
            _ => None,
        })
        .collect();
    for a in left {
        let within = read
            .iter()
            .any(|r| r.file == a.span.file && r.start <= a.span.start && a.span.end <= r.end);
        if !within {
            continue;
        }
        let has = blocks
            .get(&a.ty_name.to_ascii_uppercase())
            .is_some_and(|b| b.fb_init.is_some());
        if !has && !reportable(&a.ty_name) {
            // (an unknown type, or a block not compiled: their own error is reported)
            continue;
        }
        if has && a.in_uncompiled_method {
            // (a method of a block whose base is missing, not compiled: the E0330 is the cause;
            // arguments FB_init cannot take at all are still reported below)
            continue;
        }
        if !has && a.args.is_empty() && a.elements.is_empty() {
            // `c : FB_Count();` in a METHOD's VAR (as in a program's): the empty list of a block
            // without FB_init passes nothing (TwinCAT accepts it wherever the instance is)
            continue;
        }
        // a METHOD's own instance (struckig's `p : Randomizer(_positionDist);`): CODESYS makes
        // it again, FB_init included, at each call of the method
        let in_method = pending.iter().flat_map(|pb| &pb.methods).any(|m| {
            m.blocks.iter().any(|b| {
                b.span.file == a.span.file
                    && b.span.start <= a.span.start
                    && a.span.end <= b.span.end
            })
        });
        let message = if has && in_method {
            format!("this instance of `{}` is a METHOD's variable: CODESYS and TwinCAT create it again, FB_init with these arguments, at each call; ladderc initialises only the instances in programs, function blocks and global lists", a.ty_name)
        } else if has {
            format!("this instance of `{}` is not one ladderc initialises (only the instances in programs, function blocks and global lists are)", a.ty_name)
        } else {
            format!(
                "`{}` has no FB_init method to take these arguments",
                a.ty_name
            )
        };
        let mut d = unplaced(a, message);
        if has && in_method {
            d = d.with_hint(format!(
                "declare the instance in the block's VAR (initialised once, with its FB_init), or call its FB_init in the method: `inst.FB_init(bInitRetains := FALSE, bInCopyCode := FALSE, ...)`; `{}`'s FB_init takes the arguments after those two",
                a.ty_name
            ));
        }
        diags.push(d);
    }
    // the global lists' initial values computed at run time (`pou_inits::global_run_time_inits`):
    // first, in the order of the files, before the global instances' FB_init
    let mut computed = Vec::new();
    for pb in pending.iter().filter(|pb| pb.name_start == usize::MAX) {
        for (file, text, base, prefixed) in &pb.var_inits {
            let at = Span::new(*file, *base, *base);
            let reader = Pou {
                class: false,
                kind: PouKind::Program,
                name: Ident::new(PROGRAM, at),
                return_type: None,
                var_blocks: Vec::new(),
                body: Vec::new(),
                span: at,
            };
            let mut stmts = super::parse_statements_of(*file, text, *base, &reader, diags);
            super::init_fields::prefix_fields(&mut stmts, prefixed);
            computed.extend(stmts);
        }
    }
    if !computed.is_empty() || !interface_globals.is_empty() {
        let mut first = interface_globals;
        first.append(&mut computed);
        first.append(&mut globals);
        globals = first;
    }
    if bodies.is_empty() && globals.is_empty() && programs.is_empty() {
        return;
    }
    for (key, _) in &bodies {
        decls
            .methods
            .entry(key.clone())
            .or_default()
            .push(MethodSig {
                name: ACTION.to_string(),
                inputs: Vec::new(),
                in_outs: Vec::new(),
                constant_in_outs: Vec::new(),
                outputs: Vec::new(),
                returns: false,
                overloaded: false,
            });
    }
    let bodies: HashMap<String, Vec<Stmt>> = bodies.into_iter().collect();
    let mut span = None;
    for unit in units.iter_mut() {
        let mut actions = Vec::new();
        for item in &unit.items {
            let LibraryElement::Pou(p) = item else {
                continue;
            };
            let Some(stmts) = bodies.get(&p.name.key()) else {
                continue;
            };
            if actions.iter().any(|a: &Action| a.pou.is(&p.name.name)) {
                continue;
            }
            span.get_or_insert(p.name.span);
            actions.push(lower(decls, p, stmts, diags));
        }
        unit.items
            .extend(actions.into_iter().map(LibraryElement::Action));
    }
    // the hidden program: the global instances, then each program's instances
    let Some(span) = span
        .or_else(|| programs.first().map(|p| p.0.span))
        .or_else(|| globals.first().map(|s| s.span))
    else {
        return;
    };
    let mut hidden = Pou {
        class: false,
        kind: PouKind::Program,
        name: Ident::new(PROGRAM, span),
        return_type: None,
        var_blocks: Vec::new(),
        body: Vec::new(),
        span,
    };
    let mut low = super::PouLowering::new(decls, &hidden);
    let mut body = low.statements(&globals, diags);
    if let Some(t) = low.finish(span) {
        hidden.var_blocks.push(t);
    }
    // each program's instances, then its own computed initial values (a block's order)
    for (p, instances, own_inits) in programs {
        let methods = instances
            .then(|| ACTION.to_string())
            .into_iter()
            .chain(own_inits);
        for m in methods {
            body.push(crate::ast::IlStmt::Instr(crate::ast::Instruction {
                kind: crate::ast::InstrKind::Call {
                    cond: crate::ast::Condition::Always,
                    instance: Box::new(crate::ast::VarRef {
                        base: p.clone(),
                        accessors: vec![crate::ast::Accessor::Field(Ident::new(m, p.span))].into(),
                        span: p.span,
                    }),
                    args: crate::ast::CallArgs::None,
                },
                span: p.span,
            }));
        }
    }
    hidden.body = body;
    if let Some(unit) = units.last_mut() {
        unit.items.push(LibraryElement::Pou(hidden));
    }
}

/// The hidden method [`ACTION`] of `p`: its statements lowered where `p`'s names are visible.
fn lower(decls: &super::Declarations, p: &Pou, stmts: &[Stmt], diags: &mut Diagnostics) -> Action {
    let mut low = super::PouLowering::new(decls, p);
    let mut body = low.statements(stmts, diags);
    // its temporaries get names of their own (the body's lowering made the same ones)
    let mut rename: HashMap<String, String> = HashMap::new();
    let temps = low.finish(p.name.span).map(|mut t| {
        t.kind = VarKind::Temp;
        for v in &mut t.vars {
            let new = format!("{ACTION}_{}", v.name.name.trim_start_matches('_'));
            rename.insert(v.name.key(), new.clone());
            v.name.name = new;
        }
        t
    });
    crate::rename::Renames {
        bases: rename,
        ..Default::default()
    }
    .apply(&mut body);
    Action {
        pou: p.name.clone(),
        name: Ident::new(ACTION, p.name.span),
        body: crate::actions::instantiate(&body, "__FBI_L", p.name.span),
        temps,
        method_inputs: Some(Vec::new()),
        method_outputs: Vec::new(),
        method_defaults: Vec::new(),
        diagnostics: Vec::new(),
        access: None,
    }
}

/// The declarations [`Gen`] walks: blocks and programs, structures, and what blocks run.
struct Types<'a> {
    pous: &'a HashMap<String, (PouKind, Vec<VarBlock>)>,
    structs: &'a HashMap<String, Vec<crate::ast::VarDecl>>,
    blocks: &'a HashMap<String, Block>,
}

impl Types<'_> {
    /// Whether the block, program or structure `key` holds an instance that needs initialising
    /// (memoised in `memo`; `visiting` cuts a cycle of types, which sema reports).
    fn holds(
        &self,
        key: &str,
        memo: &mut HashMap<String, bool>,
        visiting: &mut HashSet<String>,
    ) -> bool {
        if let Some(&h) = memo.get(key) {
            return h;
        }
        if !visiting.insert(key.to_string()) {
            return false;
        }
        let vars: Vec<&crate::ast::VarDecl> = match (self.pous.get(key), self.structs.get(key)) {
            (Some((_, blocks)), _) => blocks
                .iter()
                .filter(|b| initialised(b.kind))
                .flat_map(|b| b.vars.iter().filter(|v| !hidden(b.kind, v)))
                .collect(),
            (None, Some(fields)) => fields.iter().collect(),
            _ => Vec::new(),
        };
        let h = vars.iter().any(|v| self.needs(&v.ty, memo, visiting));
        visiting.remove(key);
        memo.insert(key.to_string(), h);
        h
    }

    /// Whether a variable of type `ty` needs initialising: an instance of a block that runs
    /// FB_init (or call_after_init methods) or holds such an instance, a structure holding one,
    /// an array of either.
    fn needs(
        &self,
        ty: &TypeRef,
        memo: &mut HashMap<String, bool>,
        visiting: &mut HashSet<String>,
    ) -> bool {
        match ty {
            TypeRef::Named(n) => {
                let k = n.key();
                match self.pous.get(&k) {
                    Some((PouKind::FunctionBlock, _)) => {
                        self.blocks.get(&k).is_some_and(Block::runs)
                            || self.holds(&k, memo, visiting)
                    }
                    Some(_) => false,
                    None => self.structs.contains_key(&k) && self.holds(&k, memo, visiting),
                }
            }
            TypeRef::Array { element, .. } => self.needs(element, memo, visiting),
            _ => false,
        }
    }

    /// [`Types::needs`] once every type is in `memo`.
    fn needs_known(&self, ty: &TypeRef, memo: &HashMap<String, bool>) -> bool {
        let mut memo = memo.clone();
        self.needs(ty, &mut memo, &mut HashSet::new())
    }
}

/// The variable blocks whose instances are initialised: not VAR_IN_OUT, VAR_EXTERNAL (another
/// POU's instance) or VAR_TEMP (made anew at each call).
fn initialised(kind: VarKind) -> bool {
    matches!(
        kind,
        VarKind::Local | VarKind::Input | VarKind::Output | VarKind::Global
    )
}

/// Whether `v`, of a block of `kind`, is a hidden variable of ladderc whose instances are not
/// initialised; a method's VAR_INST (`__M_<METHOD>_<VAR>` in a VAR block, see
/// `super::file::add_method_vars`) is an instance of the block like its own.
fn hidden(kind: VarKind, v: &crate::ast::VarDecl) -> bool {
    v.name.name.starts_with("__") && !(kind == VarKind::Local && v.name.name.starts_with("__M_"))
}

/// The block type of an instance or of an array's elements.
fn instance_type(ty: &TypeRef) -> Option<&Ident> {
    match ty {
        TypeRef::Named(n) => Some(n),
        TypeRef::Array { element, .. } => match element.as_ref() {
            TypeRef::Named(n) => Some(n),
            _ => None,
        },
        _ => None,
    }
}

/// The E0329 of arguments that go nowhere.
fn unplaced(a: &DeclArgs, message: String) -> Diagnostic {
    Diagnostic::error(code::E0329, message)
        .at(a.span)
        .with_primary_label("FB_init arguments")
        .with_label(a.ty, "instance type")
        .with_hint(format!(
            "the arguments go to the extra VAR_INPUTs of `{}`'s `METHOD FB_init` (after bInitRetains and bInCopyCode); or give the instance's inputs initial values: `: {} := (input := value);`",
            a.ty_name, a.ty_name
        ))
}

/// Builds the initialisation statements.
struct Gen<'a, 'd> {
    reportable: &'a dyn Fn(&str) -> bool,
    types: &'a Types<'a>,
    holds: &'a HashMap<String, bool>,
    args: &'a mut HashMap<(crate::FileId, u32), (&'d DeclArgs, bool)>,
    diags: &'a mut Diagnostics,
    /// E0345 for too many statements was reported.
    overflowed: bool,
}

impl Gen<'_, '_> {
    /// The statements that initialise the instances declared in `blocks`, in declaration order.
    fn members(&mut self, blocks: &[VarBlock]) -> Vec<Stmt> {
        let mut out = Vec::new();
        for b in blocks.iter().filter(|b| initialised(b.kind)) {
            for v in &b.vars {
                if hidden(b.kind, v) {
                    continue;
                }
                let args = instance_type(&v.ty).and_then(|t| {
                    self.args.get_mut(&(t.span.file, t.span.start)).map(|e| {
                        e.1 = true;
                        e.0
                    })
                });
                let place = Place {
                    base: PlaceBase::Name(v.name.clone()),
                    accessors: Vec::new(),
                    span: v.name.span,
                };
                self.place(&place, &v.ty, &v.name, args, v.init.as_ref(), &mut out);
            }
        }
        out
    }

    /// The statements that initialise what `place` (a variable `name` of type `ty`, declared with
    /// FB_init arguments `args` and initial value `init`) holds: an instance, the instances in a
    /// structure's fields, an array's elements one by one.
    fn place(
        &mut self,
        place: &Place,
        ty: &TypeRef,
        name: &Ident,
        args: Option<&DeclArgs>,
        init: Option<&Initializer>,
        out: &mut Vec<Stmt>,
    ) {
        let needs = self.types.needs_known(ty, self.holds);
        match ty {
            TypeRef::Array { dims, element, .. } => {
                if !needs || dims.iter().any(|d| d.upper < d.lower) {
                    return;
                }
                let count = dims.iter().fold(1u128, |n, d| {
                    n.saturating_mul(
                        d.upper.saturating_sub(d.lower).saturating_add(1).max(0) as u128
                    )
                });
                // each element's arguments (CODESYS): `OF FB_X(a := 1)` the same for every
                // element, `OF FB_X[(a := 1), (a := 2)]` one list per element in index order
                // (the last dimension fastest), a single list for all of them
                let lists: Vec<DeclArgs> = match args {
                    Some(a) if a.elements.is_empty() => vec![a.clone()],
                    Some(a) => a
                        .elements
                        .iter()
                        .map(|(args, span)| DeclArgs {
                            args: args.clone(),
                            span: *span,
                            elements: Vec::new(),
                            ..a.clone()
                        })
                        .collect(),
                    None => Vec::new(),
                };
                if let Some(a) = args.filter(|a| a.elements.len() > 1) {
                    if a.elements.len() as u128 != count {
                        self.diags.push(
                            Diagnostic::error(
                                code::E0350,
                                format!(
                                    "{} FB_init argument lists for the {count} elements of `{}`",
                                    a.elements.len(),
                                    name.name
                                ),
                            )
                            .at(a.span)
                            .with_primary_label("one list per element")
                            .with_label(name.span, "array of instances")
                            .with_hint("give one `(...)` per element, in index order, or a single list that every element takes"),
                        );
                        return;
                    }
                }
                if count > MAX_ELEMENTS {
                    let what = match element.as_ref() {
                        TypeRef::Named(t) => format!("`{}`", t.name),
                        _ => "elements".to_string(),
                    };
                    self.diags.push(
                        Diagnostic::error(
                            code::E0345,
                            format!(
                                "`{}` holds {count} instances of {what} whose FB_init ladderc would run one by one",
                                name.name
                            ),
                        )
                        .at(name.span)
                        .with_primary_label("too many instances to initialise")
                        .with_hint(format!("ladderc initialises at most {MAX_ELEMENTS} elements of one array; split the array, or initialise the elements in the first cycle")),
                    );
                    return;
                }
                let mut index: Vec<i128> = dims.iter().map(|d| d.lower).collect();
                let mut nth = 0usize;
                loop {
                    let mut at = place.clone();
                    at.accessors.push(Accessor::Index(
                        index.iter().map(|&i| int(i, name.span)).collect(),
                    ));
                    let own = match lists.len() {
                        0 => None,
                        1 => lists.first(),
                        _ => lists.get(nth),
                    };
                    nth += 1;
                    self.place(&at, element, name, own, None, out);
                    if out.len() > MAX_STATEMENTS {
                        // (arrays in arrays: reported once, where the limit is reached)
                        if !self.overflowed {
                            self.overflowed = true;
                            self.diags.push(
                                Diagnostic::error(
                                    code::E0345,
                                    format!(
                                        "`{}` holds more instances whose FB_init ladderc would run one by one than it initialises ({MAX_STATEMENTS} calls)",
                                        name.name
                                    ),
                                )
                                .at(name.span)
                                .with_primary_label("too many instances to initialise")
                                .with_hint("split the arrays, or initialise the elements in the first cycle"),
                            );
                        }
                        return;
                    }
                    // the next index, last dimension fastest; done when the first wraps
                    let mut d = dims.len();
                    let done = loop {
                        if d == 0 {
                            break true;
                        }
                        d -= 1;
                        if index[d] < dims[d].upper {
                            index[d] += 1;
                            break false;
                        }
                        index[d] = dims[d].lower;
                    };
                    if done {
                        break;
                    }
                }
            }
            TypeRef::Named(t)
                if self.types.structs.contains_key(&t.key())
                    && !self.types.pous.contains_key(&t.key()) =>
            {
                if let Some(a) = args {
                    self.diags.push(unplaced(
                        a,
                        format!(
                            "`{}` is a structure: FB_init arguments go to function block instances",
                            a.ty_name
                        ),
                    ));
                }
                if !needs {
                    return;
                }
                let fields = self.types.structs[&t.key()].clone();
                for f in &fields {
                    let mut at = place.clone();
                    at.accessors.push(Accessor::Field(f.name.clone()));
                    let args = instance_type(&f.ty).and_then(|t| {
                        self.args.get_mut(&(t.span.file, t.span.start)).map(|e| {
                            e.1 = true;
                            e.0
                        })
                    });
                    self.place(&at, &f.ty, &f.name, args, f.init.as_ref(), out);
                }
            }
            TypeRef::Named(t) => {
                let block = self.types.blocks.get(&t.key()).cloned().unwrap_or_default();
                let given = match args {
                    Some(_) if block.fb_init.is_none() && !(self.reportable)(&t.name) => Vec::new(),
                    // `fb : FB_Count();` (TwinCAT accepts the empty list of a block without
                    // FB_init: nothing to pass)
                    Some(a)
                        if block.fb_init.is_none()
                            && a.args.is_empty()
                            && a.elements.is_empty() =>
                    {
                        Vec::new()
                    }
                    Some(a) if block.fb_init.is_none() => {
                        self.diags.push(unplaced(
                            a,
                            format!(
                                "`{}` has no FB_init method to take these arguments",
                                a.ty_name
                            ),
                        ));
                        Vec::new()
                    }
                    Some(a) => self.bind(a, block.fb_init.as_deref().unwrap_or(&[])),
                    None => Vec::new(),
                };
                if needs {
                    self.instance(place, t, &block, &given, out);
                    self.initial_inputs(place, &block, init, out);
                }
            }
            _ => {}
        }
    }

    /// The declaration's arguments bound to FB_init's extra inputs by name: `(input, value)`.
    fn bind(&mut self, a: &DeclArgs, inputs: &[String]) -> Vec<(String, Expr, Span)> {
        let extra: Vec<&String> = inputs
            .iter()
            .filter(|i| !SYSTEM_INPUTS.iter().any(|s| s.eq_ignore_ascii_case(i)))
            .collect();
        let mut out = Vec::new();
        let mut positional = extra.iter();
        for arg in &a.args {
            let param = match (&arg.dir, &arg.name) {
                (ArgDir::Input, Some(n)) => extra.iter().find(|i| n.is(i)).map(|i| (*i).clone()),
                (ArgDir::Input, None) => positional.next().map(|i| (*i).clone()),
                (ArgDir::Output { .. }, _) => None,
            };
            match param {
                Some(p) => out.push((p, arg.value.clone(), arg.span)),
                None => {
                    let what = match (&arg.dir, &arg.name) {
                        (ArgDir::Output { .. }, _) => {
                            "an output argument (`=>`) goes nowhere: FB_init has inputs only"
                                .to_string()
                        }
                        (_, Some(n)) => format!(
                            "argument `{}`: the FB_init method of `{}` has no such input",
                            n.name, a.ty_name
                        ),
                        (_, None) => format!(
                            "the FB_init method of `{}` takes {} argument(s) in a declaration",
                            a.ty_name,
                            extra.len()
                        ),
                    };
                    self.diags.push(
                        Diagnostic::error(code::E0329, what)
                            .at(arg.span)
                            .with_primary_label("no FB_init input for this argument")
                            .with_label(a.ty, "instance type")
                            .with_hint(if extra.is_empty() {
                                "its FB_init has only bInitRetains and bInCopyCode, which the system sets".to_string()
                            } else {
                                format!(
                                    "the inputs it takes: {}",
                                    extra.iter().map(|s| s.as_str()).collect::<Vec<_>>().join(", ")
                                )
                            }),
                    );
                }
            }
        }
        out
    }

    /// The statements that initialise the instance at `place` of block `t`: its own instances,
    /// its bases' FB_init, its FB_init (`given`: the declaration's arguments by input name).
    fn instance(
        &mut self,
        place: &Place,
        t: &Ident,
        block: &Block,
        given: &[(String, Expr, Span)],
        out: &mut Vec<Stmt>,
    ) {
        let span = place.span;
        if self.holds.get(&t.key()).copied().unwrap_or(false) {
            out.push(call(place, ACTION, Vec::new(), span));
        }
        // its methods' VAR_INST initial values, as its declarations' (before FB_init)
        for m in &block.inst_inits {
            out.push(call(place, m, Vec::new(), span));
        }
        let versions = block
            .bases
            .iter()
            .map(|(n, i)| (n.as_str(), i))
            .chain(block.fb_init.iter().map(|i| ("FB_init", i)));
        for (method, inputs) in versions {
            let mut args = Vec::new();
            for (k, sys) in SYSTEM_INPUTS.iter().enumerate() {
                if let Some(i) = inputs.iter().find(|i| i.eq_ignore_ascii_case(sys)) {
                    // a cold start: bInitRetains TRUE, bInCopyCode FALSE
                    args.push(arg(i, boolean(k == 0, span), span));
                }
            }
            for (name, value, at) in given {
                if let Some(i) = inputs.iter().find(|i| i.eq_ignore_ascii_case(name)) {
                    args.push(arg(i, value.clone(), *at));
                }
            }
            out.push(call(place, method, args, span));
        }
    }

    /// After FB_init, the inputs a declaration's structured initial value sets (`fb : FB_X :=
    /// (in1 := 99)`) get that value again, then the call_after_init methods run: the order the
    /// CODESYS help shows (`fbDoIt.FB_Init(); fbDoIt.in1 := 99; fbDoIt.FB_AfterInit();`); ladderc
    /// sets initial values before FB_init too, so FB_init sees them where CODESYS shows the
    /// default. Only literal, enumerated and plain-name values of inputs are set again.
    fn initial_inputs(
        &mut self,
        place: &Place,
        block: &Block,
        init: Option<&Initializer>,
        out: &mut Vec<Stmt>,
    ) {
        let span = place.span;
        if let (Some(Initializer::Struct(fields, _)), Some(_)) = (init, &block.fb_init) {
            for (field, value) in fields {
                if !block.inputs.contains(&field.key()) {
                    continue;
                }
                // an array input's initial value, element by element (repeats expanded)
                if let (Initializer::Array(elems, _), Some(lower)) =
                    (value, block.array_inputs.get(&field.key()))
                {
                    let mut k = *lower;
                    for e in elems {
                        for _ in 0..e.repeat.unwrap_or(1) {
                            if let Some(v) = initial_expr(&e.value, field.span) {
                                let mut target = place.clone();
                                target.accessors.push(Accessor::Field(field.clone()));
                                target
                                    .accessors
                                    .push(Accessor::Index(vec![int(k, field.span)]));
                                out.push(Stmt {
                                    kind: StmtKind::Assign { target, value: v },
                                    span: field.span,
                                });
                            }
                            k += 1;
                        }
                    }
                    continue;
                }
                let Initializer::Value(op) = value else {
                    continue;
                };
                let kind = match op {
                    Operand::Literal(l) => ExprKind::Literal((**l).clone()),
                    Operand::EnumValue(e) => ExprKind::EnumValue {
                        type_name: e.type_name.clone(),
                        value: e.value.clone(),
                    },
                    Operand::Var(r) if r.accessors.is_empty() => ExprKind::Place(Place {
                        base: PlaceBase::Name(r.base.clone()),
                        accessors: Vec::new(),
                        span: r.span,
                    }),
                    _ => continue,
                };
                let mut target = place.clone();
                target.accessors.push(Accessor::Field(field.clone()));
                out.push(Stmt {
                    kind: StmtKind::Assign {
                        target,
                        value: Expr {
                            kind,
                            span: field.span,
                        },
                    },
                    span: field.span,
                });
            }
        }
        for m in &block.after_init {
            out.push(call(place, m, Vec::new(), span));
        }
    }
}

/// A literal, enumerated or plain-name initial value as an expression (`None` for others).
fn initial_expr(value: &Initializer, span: Span) -> Option<Expr> {
    let Initializer::Value(op) = value else {
        return None;
    };
    let kind = match op {
        Operand::Literal(l) => ExprKind::Literal((**l).clone()),
        Operand::EnumValue(e) => ExprKind::EnumValue {
            type_name: e.type_name.clone(),
            value: e.value.clone(),
        },
        Operand::Var(r) if r.accessors.is_empty() => ExprKind::Place(Place {
            base: PlaceBase::Name(r.base.clone()),
            accessors: Vec::new(),
            span: r.span,
        }),
        _ => return None,
    };
    Some(Expr { kind, span })
}

/// Whether a pragma is `{attribute 'call_after_init'}` (applied, so not reported as ignored).
pub fn is_call_after_init(pragma: &str) -> bool {
    let p = pragma.to_ascii_lowercase();
    p.contains("attribute") && p.contains("'call_after_init'")
}

/// Whether the text before `at` (a keyword) ends with a `{attribute 'call_after_init'}`, among
/// the pragmas written just above it.
fn marked_before(src: &str, at: usize) -> bool {
    let mut t = src.get(..at).unwrap_or("").trim_end();
    while t.ends_with('}') {
        let Some(open) = t.rfind('{') else {
            return false;
        };
        if is_call_after_init(&t[open..]) {
            return true;
        }
        t = t[..open].trim_end();
    }
    false
}

/// The methods of the function block `p` that `{attribute 'call_after_init'}` marks, the block
/// marked too (Beckhoff, CODESYS: the attribute goes on both; a method marked in a block that is
/// not is W0346, not called).
pub(super) fn after_init_methods(
    file: crate::FileId,
    src: &str,
    p: &super::file::PouText,
    diags: &mut Diagnostics,
) -> Vec<Ident> {
    let marked: Vec<&super::file::MethodText> = p
        .methods
        .iter()
        .filter(|m| marked_before(src, m.whole.start))
        .collect();
    if marked.is_empty() {
        return Vec::new();
    }
    // the keyword before the name (and its modifier)
    let mut lo = p.name_range.start.saturating_sub(200);
    while !src.is_char_boundary(lo) {
        lo -= 1;
    }
    let head = src.get(lo..p.name_range.start).unwrap_or("");
    let Some(k) = head.to_ascii_uppercase().rfind("FUNCTION_BLOCK") else {
        return Vec::new();
    };
    let block = marked_before(src, lo + k);
    let mut out = Vec::new();
    for m in marked {
        let span = Span::new(file, m.name_range.start, m.name_range.end);
        if block {
            out.push(Ident::new(&m.name, span));
        } else {
            diags.push(
                Diagnostic::warning(
                    code::W0346,
                    format!(
                        "method `{}` is marked call_after_init, but `{}` is not: it is not called after initialisation",
                        m.name, p.name
                    ),
                )
                .at(span)
                .with_primary_label("not called implicitly")
                .with_hint(format!("CODESYS and TwinCAT need the attribute on the block too: write {{attribute 'call_after_init'}} above FUNCTION_BLOCK {}", p.name)),
            );
        }
    }
    out
}

/// `place.method(args);`
fn call(place: &Place, method: &str, args: Vec<Arg>, span: Span) -> Stmt {
    let mut callee = place.clone();
    callee
        .accessors
        .push(Accessor::Field(Ident::new(method, span)));
    Stmt {
        kind: StmtKind::Call { callee, args },
        span,
    }
}

fn arg(name: &str, value: Expr, span: Span) -> Arg {
    Arg {
        name: Some(Ident::new(name, span)),
        dir: ArgDir::Input,
        value,
        span,
    }
}

fn boolean(b: bool, span: Span) -> Expr {
    Expr::literal(LiteralKind::Bool(b), span)
}

fn int(i: i128, span: Span) -> Expr {
    Expr::literal(LiteralKind::Int(i), span)
}

/// Whether a method runs only to set up an instance (`FB_init`, `FB_reinit`, and a base's
/// `__S<level>_FB_INIT` / `__S<level>_FB_REINIT`): its writes of the block's own inputs give the
/// instance its initial inputs (Beckhoff Infosys "Methods FB_init, FB_reinit and FB_exit": the
/// additional inputs of FB_init initialise the instance; CODESYS "Method: FB_Init, FB_Reinit,
/// FB_Exit"), so sema gives no W1411 there (round 34).
pub fn is_instance_setup(name: &str) -> bool {
    let u = name.to_ascii_uppercase();
    let own = match u.strip_prefix("__S") {
        Some(rest) => {
            let rest = rest.trim_start_matches(|c: char| c.is_ascii_digit());
            rest.strip_prefix('_').unwrap_or(rest)
        }
        None => u.as_str(),
    };
    own == "FB_INIT" || own == "FB_REINIT"
}

/// Whether a method is one the runtime calls with every argument (`FB_init`, `FB_reinit`,
/// `FB_exit`, and a base's `__S<level>_FB_INIT`): its inputs get no per-call defaults.
pub fn is_special_method(name: &str) -> bool {
    let u = name.to_ascii_uppercase();
    u == "FB_INIT"
        || u == "FB_EXIT"
        || u == "FB_REINIT"
        || (u.starts_with("__S") && u.ends_with("_FB_INIT"))
}
