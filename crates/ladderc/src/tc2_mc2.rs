//! Beckhoff Tc2_MC2 spellings of the PLCopen motion blocks, read as ladderc's own pins.
//!
//! Input: the user's parsed units (before the semantic checks) and the block library. Output: the
//! same units with each call argument and instance field written in a Tc2_MC2 spelling renamed to the
//! pin it stands for (`fbPower(Enable_Positive := TRUE)` -> `EnablePositive`), and one located E1041
//! for each Tc2_MC2 pin the simulated axis has no counterpart for (the argument, or the store into
//! the pin, is then dropped, so that no E1011, E1015 or E1006 follows it). The METHODs no POU
//! calls, checked on their own, are read the same way ([`read_method_spellings`]), so that a call
//! gets one diagnostic wherever it stands. Invariants: only instances of library blocks declared in the POU (or the METHOD) are
//! touched; spans stay where the user wrote the names.
//!
//! Tc2_MC2 also lets a motion block's `Acceleration` and `Deceleration` be left out or 0: "the
//! standard acceleration from the axis configuration is applied" (Infosys, MC_MoveAbsolute,
//! MC_MoveVelocity, MC_Halt, MC_Stop inputs). ladderc's counterpart of that configuration is the
//! axes file, so such an input is bound to the configured limit of the axis the call names, read
//! when the block runs from a table of the axes' limits by the `AxisNo` of the call's `Axis`
//! (`__TC2_ACC[Axis.AxisNo]`): an `AXIS_REF` inside a function block is another axis in each
//! instance ([`crate::axis_links`]). Without an axes file the input stays unbound (E4023, as before).
//!
//! Per Beckhoff Infosys (Tc2_MC2 > Function blocks > Administrative > MC_Power), MC_Power's inputs
//! are `Enable`, `Enable_Positive`, `Enable_Negative`, `Override` (LREAL percent, default 100.0) and
//! `BufferMode`; its outputs `Status`, `Busy`, `Active`, `Error`, `ErrorID`. `Override` becomes a
//! hidden MC_SetOverride call after the MC_Power call ([`crate::tc2_override`]); written by name
//! (`fbPower.Override := x;`), it is a hidden field that the calls pass and that a call's own
//! `Override` argument sets. `Options` of the
//! motion blocks (`ST_*Options`) and MC_Power's `Busy`/`Active` have no counterpart in ladderc's
//! axis. An array of block instances (`aPower[i](...)`) is read like one instance.

use crate::axes::AxisConfig;
use diagnostics::{code, Diagnostic, Diagnostics};
use il_frontend::ast::{
    Accessor, ArgDir, CallArgs, CompilationUnit, Condition, FormalArg, Ident, IlStmt, Initializer,
    InstrKind, LibraryElement, LiteralKind, Op, Operand, TypeDef, TypeRef, VarDecl, VarRef,
};
use param_passing::library::Library;
use std::collections::HashMap;

/// (block, Tc2_MC2 pin, ladderc pin); the Tc2 pin upper case.
const SPELLINGS: &[(&str, &str, &str)] = &[
    ("MC_POWER", "ENABLE_POSITIVE", "EnablePositive"),
    ("MC_POWER", "ENABLE_NEGATIVE", "EnableNegative"),
    // CODESYS SM3_Basic (helpme-codesys.com, SM3_Basic > MC_Power: "bRegulatorRealState: the
    // power stage has been switched on", "bDriveStartRealState": the quick stop is released);
    // ladderc's axis has one power state, its `Status`
    ("MC_POWER", "BREGULATORREALSTATE", "Status"),
    ("MC_POWER", "BDRIVESTARTREALSTATE", "Status"),
    // SM3_Basic MC_SetPosition's `Mode` (FALSE absolute, TRUE relative)
    ("MC_SETPOSITION", "MODE", "Relative"),
];

/// CODESYS SM3_Basic MC_Power's inputs that take part in the power: the axis is ready to move
/// when `Enable`, `bRegulatorOn` (the power stage) and `bDriveStart` (no quick stop) are all TRUE
/// (helpme-codesys.com, SM3_Basic > MC_Power).
const SM3_POWER_INPUTS: &[&str] = &["BREGULATORON", "BDRIVESTART"];

/// Tc2_MC2 pins without a counterpart: (block or `*` for every block, pin, what it would need).
const NO_COUNTERPART: &[(&str, &str, &str)] = &[
    (
        "MC_POWER",
        "OVERRIDE",
        "ladderc reads `Override` only as an argument of an unconditional MC_Power call (it then \
         sets MC_SetOverride); read the override from your own variable, or call MC_SetOverride",
    ),
    (
        "MC_POWER",
        "BUFFERMODE",
        "ladderc's MC_Power has no buffer mode",
    ),
    (
        "MC_POWER",
        "BUSY",
        "ladderc's MC_Power has no Busy output (read Status)",
    ),
    (
        "MC_POWER",
        "ACTIVE",
        "ladderc's MC_Power has no Active output (read Status)",
    ),
    (
        "*",
        "OPTIONS",
        "the Tc2_MC2 option structures (ST_*Options)",
    ),
];

/// Renames the Tc2_MC2 spellings in every POU of `units`; reports E1041 for pins with no counterpart.
/// Sets `axes.tc2_tables` when a default reads the tables of the axes' limits.
pub fn read_spellings(
    units: &mut [CompilationUnit],
    lib: &Library,
    axes: &mut AxisConfig,
    diags: &mut Diagnostics,
) {
    let tables = std::cell::Cell::new(false);
    // the declared types: the structures that hold an AXIS_REF, Tc2_MC2's UDINT ErrorID
    // (`tc2_error_id`)
    let (structs, global_types) = declared_types(units);
    // (the structures and function blocks whose instances hold an AXIS_REF)
    let holders = crate::tc2_axis_ref::axis_holders(units, &structs);
    let globals = global_axes(units, &holders);
    for u in units.iter_mut() {
        for item in &mut u.items {
            // `eDir : MC_Direction := MC_Direction.MC_Shortest_Way;`
            match item {
                LibraryElement::Pou(p) => p
                    .var_blocks
                    .iter_mut()
                    .flat_map(|b| b.vars.iter_mut())
                    .for_each(|v| init_enum_values(v.init.as_mut())),
                LibraryElement::GlobalVars(b) => b
                    .vars
                    .iter_mut()
                    .for_each(|v| init_enum_values(v.init.as_mut())),
                _ => {}
            }
            let LibraryElement::Pou(p) = item else {
                continue;
            };
            crate::tc2_axis_ref::read_members(p, &globals, &holders, diags);
            let blocks: Vec<&il_frontend::ast::VarBlock> = p.var_blocks.iter().collect();
            let hidden = read_body(
                &blocks,
                &mut p.body,
                (&global_types, &structs),
                lib,
                axes,
                &tables,
                diags,
            );
            if !hidden.is_empty() {
                crate::block_temps::add_hidden_vars(p, hidden);
            }
        }
    }
    axes.tc2_tables |= tables.get() || globals.homed_read.get();
}

/// The Tc2_MC2 spellings of one body whose variables are `blocks`: its pins renamed, one E1041
/// per pin with no counterpart; returns the hidden variables the body now needs.
fn read_body(
    blocks: &[&il_frontend::ast::VarBlock],
    body: &mut Vec<IlStmt>,
    (global_types, structs): (&HashMap<String, TypeRef>, &crate::tc2_axis_ref::Structs),
    lib: &Library,
    axes: &AxisConfig,
    tables: &std::cell::Cell<bool>,
    diags: &mut Diagnostics,
) -> Vec<VarDecl> {
    let mut hidden = Vec::new();
    let instances: HashMap<String, String> = blocks
        .iter()
        .flat_map(|b| b.vars.iter())
        // an instance, or an array of them (`aPower : ARRAY [1..2] OF MC_Power`, called
        // `aPower[i](...)`)
        .filter_map(|v| {
            param_passing::lower::instance_block(&v.ty, lib)
                .map(|(tpl, _)| (v.name.key(), tpl.block.clone()))
        })
        .collect();
    if instances.is_empty() {
        return hidden;
    }
    let mut vars = global_types.clone();
    vars.extend(
        blocks
            .iter()
            .flat_map(|b| b.vars.iter())
            .map(|v| (v.name.key(), v.ty.clone())),
    );
    let types = crate::tc2_error_id::Types {
        vars,
        structs: structs.clone(),
    };
    let cx = Cx {
        inst: &instances,
        lib,
        axes,
        tables,
        types: &types,
    };
    stmts(body, &cx, &mut hidden, diags);
    hidden
}

/// The Tc2_MC2 spellings of the METHODs that no POU calls (`methods`: each with the upper-case
/// name of its POU), which `Session::check_uncalled` checks on their own after [`read_spellings`]
/// read the POUs' bodies: a call of a motion block in such a METHOD gets the diagnostics it gets
/// in a body (`fbHalt(Options := o)` is E1041 in both, before: E1011 in the METHOD, issue #13
/// round 30). Reads them with the POU's variables (its motion block instances) and the METHOD's
/// own; the hidden variables they need are the METHOD's (it is checked, never compiled). Reports
/// only what `diags` does not hold yet (a METHOD its own POU calls was read inlined there).
pub fn read_method_spellings<'a>(
    units: &[CompilationUnit],
    methods: impl Iterator<Item = (&'a str, &'a mut il_frontend::ast::Action)>,
    lib: &Library,
    axes: &mut AxisConfig,
    diags: &mut Diagnostics,
) {
    let tables = std::cell::Cell::new(false);
    let (structs, global_types) = declared_types(units);
    let mut found = Diagnostics::new();
    for (pou, m) in methods {
        let Some(owner) = units
            .iter()
            .flat_map(|u| u.items.iter())
            .find_map(|i| match i {
                LibraryElement::Pou(p) if p.name.key() == pou => Some(p),
                _ => None,
            })
        else {
            continue;
        };
        let blocks: Vec<&il_frontend::ast::VarBlock> =
            owner.var_blocks.iter().chain(m.temps.iter()).collect();
        let hidden = read_body(
            &blocks,
            &mut m.body,
            (&global_types, &structs),
            lib,
            axes,
            &tables,
            &mut found,
        );
        if !hidden.is_empty() {
            let span = m.name.span;
            m.temps
                .get_or_insert_with(|| il_frontend::ast::VarBlock {
                    access: None,
                    name: None,
                    kind: il_frontend::ast::VarKind::Temp,
                    constant: false,
                    retain: false,
                    vars: Vec::new(),
                    span,
                })
                .vars
                .extend(hidden);
        }
    }
    for d in found.into_iter() {
        let known = diags
            .iter()
            .any(|e| e.code == d.code && e.span == d.span && e.message == d.message);
        if !known {
            diags.push(d);
        }
    }
    axes.tc2_tables |= tables.get();
}

/// What the walk over a POU's body knows.
struct Cx<'a> {
    /// Upper-case instance name -> its block's name.
    inst: &'a HashMap<String, String>,
    lib: &'a Library,
    axes: &'a AxisConfig,
    /// A default read the tables of the axes' limits ([`AxisConfig::tc2_tables`]).
    tables: &'a std::cell::Cell<bool>,
    /// The declared types (for `ErrorID => nUdint`).
    types: &'a crate::tc2_error_id::Types,
}

/// The fields of every structure type (by type key, each field's type by its key) and the type of
/// every global variable (by key), as declared in `units`.
pub(crate) type DeclaredTypes = (
    HashMap<String, HashMap<String, TypeRef>>,
    HashMap<String, TypeRef>,
);

/// See [`DeclaredTypes`]: the structures' fields and the globals' types of `units`.
pub(crate) fn declared_types(units: &[CompilationUnit]) -> DeclaredTypes {
    let mut structs: HashMap<String, HashMap<String, TypeRef>> = HashMap::new();
    let mut globals: HashMap<String, TypeRef> = HashMap::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        match item {
            LibraryElement::DataTypes(ts) => {
                for t in ts {
                    if let TypeDef::Struct { fields } = &t.def {
                        structs.insert(
                            t.name.key(),
                            fields
                                .iter()
                                .map(|f| (f.name.key(), f.ty.clone()))
                                .collect(),
                        );
                    }
                }
            }
            LibraryElement::GlobalVars(b) => {
                globals.extend(b.vars.iter().map(|v| (v.name.key(), v.ty.clone())))
            }
            _ => {}
        }
    }
    (structs, globals)
}

/// `fbPower.Override := x;` / `y := fbPower.Override;` of an MC_Power instance called
/// unconditionally in `body`: the field is a hidden LREAL (100.0 until written,
/// [`crate::tc2_override::written_field`]) that the calls then pass as their `Override`. A call
/// that passes `Override := v` itself stores `v` into the field first, as it sets the input of the
/// instance (IEC 61131-3 ed. 3, 6.6.1.2: an input keeps the value last given, by a call or by
/// `inst.in := v;`, TwinCAT likewise). Returns the instances (their keys) and the hidden
/// variables' names.
fn override_fields(
    body: &mut [IlStmt],
    inst: &HashMap<String, String>,
    hidden: &mut Vec<VarDecl>,
) -> HashMap<String, String> {
    let is_power = |k: &str| {
        inst.get(k)
            .is_some_and(|b| b.eq_ignore_ascii_case("MC_POWER"))
    };
    let field = |v: &VarRef| {
        matches!(v.accessors.as_slice(), [Accessor::Field(f)] if f.key() == "OVERRIDE")
            && is_power(&v.base.key())
    };
    // the instances whose every call is unconditional
    let mut calls: HashMap<String, bool> = HashMap::new();
    let mut written: HashMap<String, Ident> = HashMap::new();
    for s in body.iter() {
        let IlStmt::Instr(i) = s else { continue };
        match &i.kind {
            InstrKind::Call {
                instance,
                args,
                cond,
            } if instance.accessors.is_empty() && is_power(&instance.base.key()) => {
                let plain = matches!(cond, Condition::Always);
                let ok = calls.entry(instance.base.key()).or_insert(true);
                *ok &= plain;
            }
            InstrKind::Simple {
                op: il_frontend::ast::Op::St,
                operand: Some(Operand::Var(v)),
                ..
            } if field(v) => {
                written.insert(v.base.key(), v.base.clone());
            }
            _ => {}
        }
    }
    let mut names = HashMap::new();
    for (key, base) in written {
        if calls.get(&key) != Some(&true) {
            continue;
        }
        let (name, decl) = crate::tc2_override::written_field(&base);
        if !hidden.iter().any(|h| h.name.key() == decl.name.key()) {
            hidden.push(decl);
        }
        names.insert(key, name);
    }
    if names.is_empty() {
        return names;
    }
    for s in body.iter_mut() {
        let IlStmt::Instr(i) = s else { continue };
        if let InstrKind::Simple {
            operand: Some(Operand::Var(v)),
            ..
        } = &mut i.kind
        {
            if let Some(name) = names.get(&v.base.key()).filter(|_| field(v)) {
                v.base = Ident::new(name, v.base.span);
                v.accessors = Vec::new().into();
            }
        }
    }
    names
}

fn stmts(body: &mut Vec<IlStmt>, cx: &Cx, hidden: &mut Vec<VarDecl>, diags: &mut Diagnostics) {
    let inst = cx.inst;
    let fields = override_fields(body, inst, hidden);
    let mut after: Vec<(usize, Vec<IlStmt>)> = Vec::new();
    // the stores into a pin with no counterpart (`fbPower.Busy := x;`): reported once (E1041)
    // and left out, as a store leaves the current result as it is
    let mut dropped = std::collections::HashSet::new();
    for (k, s) in body.iter_mut().enumerate() {
        let IlStmt::Instr(i) = s else { continue };
        match &mut i.kind {
            InstrKind::Simple {
                op,
                operand: Some(o),
                ..
            } => {
                let store = matches!(op, Op::St | Op::S | Op::R);
                if store && matches!(o, Operand::Var(v) if missing_pin(v, inst)) {
                    dropped.insert(k);
                }
                operand(o, inst, diags)
            }
            InstrKind::Deferred {
                operand: o, body, ..
            } => {
                if let Some(o) = o {
                    operand(o, inst, diags);
                }
                stmts(body, cx, hidden, diags);
            }
            InstrKind::Call {
                instance,
                args,
                cond,
            } => {
                let element = instance
                    .accessors
                    .iter()
                    .all(|a| matches!(a, Accessor::Index(_)));
                if let (Some(block), true) = (inst.get(&instance.base.key()), element) {
                    if let CallArgs::Formal(list) = args {
                        let unconditional = matches!(cond, Condition::Always);
                        if block.eq_ignore_ascii_case("MC_POWER") {
                            if let Some((decl, code)) = sm3_power(instance, list) {
                                if !hidden.iter().any(|h| h.name.key() == decl.name.key()) {
                                    hidden.push(decl);
                                }
                                after.push((k, code));
                            }
                        }
                        let mut scale = None;
                        // the instance's `Override` field (`override_fields`) and the value the
                        // call gives it
                        let field = fields.get(&instance.base.key());
                        let mut given = None;
                        list.retain_mut(|a| {
                            let pin = a.name.key();
                            if let Some(new) = spelling(block, &pin) {
                                a.name.name = new.to_string();
                                return true;
                            }
                            if pin == "OVERRIDE" && field.is_some() {
                                given = Some(a.value.clone());
                                return false;
                            }
                            // `Override := 100.0` is the unscaled velocity: MC_Power without it
                            if pin == "OVERRIDE" && is_hundred(&a.value) {
                                return false;
                            }
                            if pin == "OVERRIDE"
                                && block.eq_ignore_ascii_case("MC_POWER")
                                && unconditional
                            {
                                scale = Some(a.value.clone());
                                return false;
                            }
                            match missing(block, &pin) {
                                Some(what) => {
                                    diags.push(e1041(block, &a.name.name, what, a.name.span));
                                    false
                                }
                                None => true,
                            }
                        });
                        // the `Override` field the program writes (`override_fields`)
                        let mut stored = Vec::new();
                        if let Some(name) = field {
                            let at = instance.span;
                            if let Some(value) = given {
                                stored = crate::tc2_override::store_field(value, name, at);
                            }
                            scale.get_or_insert_with(|| {
                                Operand::Var(VarRef {
                                    base: Ident::new(name, at),
                                    accessors: Vec::new().into(),
                                    span: at,
                                })
                            });
                        }
                        if let Some(value) = scale {
                            let axis = list.iter().find(|a| a.name.key() == "AXIS");
                            if let Some(axis) = axis {
                                let declared = cx.types.vars.get(&instance.base.key());
                                let (decls, code) = crate::tc2_override::set_override(
                                    instance,
                                    declared,
                                    &axis.value,
                                    value,
                                );
                                for d in decls {
                                    if !hidden.iter().any(|h| h.name.key() == d.name.key()) {
                                        hidden.push(d);
                                    }
                                }
                                stored.extend(code);
                            }
                        }
                        if !stored.is_empty() {
                            after.push((k + 1, stored));
                        }
                        axis_defaults(block, list, instance.span, cx);
                        if unconditional {
                            let (decls, code) =
                                crate::tc2_error_id::widen(instance, list, cx.types);
                            for d in decls {
                                if !hidden.iter().any(|h| h.name.key() == d.name.key()) {
                                    hidden.push(d);
                                }
                            }
                            if !code.is_empty() {
                                after.push((k + 1, code));
                            }
                        }
                    }
                } else {
                    var(instance, inst, diags);
                }
                if let CallArgs::Formal(list) = args {
                    list.iter_mut()
                        .for_each(|a| operand(&mut a.value, inst, diags));
                }
            }
            InstrKind::FunctionCall { args, .. } => match &mut **args {
                CallArgs::Formal(list) => list
                    .iter_mut()
                    .for_each(|a| operand(&mut a.value, inst, diags)),
                CallArgs::NonFormal(ops) => ops.iter_mut().for_each(|o| operand(o, inst, diags)),
                CallArgs::None => {}
            },
            _ => {}
        }
    }
    // the code after the calls, in the order pushed, and the stores left out
    after.sort_by_key(|(at, _)| *at);
    let mut after = after.into_iter().peekable();
    let old = std::mem::take(body);
    for (k, s) in old.into_iter().enumerate() {
        while let Some((_, code)) = after.next_if(|(at, _)| *at == k) {
            body.extend(code);
        }
        if !dropped.contains(&k) {
            body.push(s);
        } else if let IlStmt::Instr(i) = &s {
            body.push(crate::tc2_axis_ref::no_store(i.span));
        }
    }
    for (_, code) in after {
        body.extend(code);
    }
}

/// Whether `v` names a Tc2_MC2 pin of an instance in `inst` that ladderc's block does not have
/// (`fbPower.Busy`, [`NO_COUNTERPART`]).
fn missing_pin(v: &VarRef, inst: &HashMap<String, String>) -> bool {
    let Some(block) = inst.get(&v.base.key()) else {
        return false;
    };
    match v
        .accessors
        .iter()
        .find(|a| !matches!(a, Accessor::Index(_)))
    {
        Some(Accessor::Field(f)) => {
            let pin = f.key();
            spelling(block, &pin).is_none() && missing(block, &pin).is_some()
        }
        _ => false,
    }
}

/// SM3_Basic's `MC_Power(Enable := e, bRegulatorOn := r, bDriveStart := d)`: the call's
/// `Enable` becomes a hidden BOOL set to `e AND r AND d` just before the call (the hidden
/// variable's declaration and that code), the two SM3 arguments are dropped. `None` when the call
/// names neither SM3 input (PLCopen's MC_Power, powered by `Enable` alone).
fn sm3_power(instance: &VarRef, list: &mut Vec<FormalArg>) -> Option<(VarDecl, Vec<IlStmt>)> {
    let is_sm3 = |a: &FormalArg| SM3_POWER_INPUTS.contains(&a.name.key().as_str());
    if !list.iter().any(is_sm3) {
        return None;
    }
    let at = instance.span;
    let name = format!("__SM3_ON_{}", instance.base.key());
    let mut terms: Vec<Operand> = Vec::new();
    let enable = list.iter_mut().find(|a| a.name.key() == "ENABLE");
    if let Some(e) = enable {
        terms.push(std::mem::replace(
            &mut e.value,
            Operand::Var(VarRef {
                base: Ident::new(&name, at),
                accessors: Vec::new().into(),
                span: at,
            }),
        ));
    }
    terms.extend(list.iter().filter(|a| is_sm3(a)).map(|a| a.value.clone()));
    list.retain(|a| !is_sm3(a));
    let simple = |op, o| {
        IlStmt::Instr(il_frontend::ast::Instruction {
            kind: InstrKind::Simple {
                op,
                negate: false,
                operand: Some(o),
            },
            span: at,
        })
    };
    let mut code = Vec::new();
    for (n, t) in terms.into_iter().enumerate() {
        code.push(simple(if n == 0 { Op::Ld } else { Op::And }, t));
    }
    code.push(simple(
        Op::St,
        Operand::Var(VarRef {
            base: Ident::new(&name, at),
            accessors: Vec::new().into(),
            span: at,
        }),
    ));
    let decl = VarDecl {
        name: Ident::new(&name, at),
        location: None,
        ty: TypeRef::Named(Ident::new("BOOL", at)),
        init: None,
        edge: None,
        span: at,
    };
    Some((decl, code))
}

fn operand(o: &mut Operand, inst: &HashMap<String, String>, diags: &mut Diagnostics) {
    if let Operand::Var(v) = o {
        enum_value(v);
        var(v, inst, diags);
    }
}

/// The qualified enumeration values of an initialiser (see [`enum_value`]).
fn init_enum_values(init: Option<&mut Initializer>) {
    match init {
        Some(Initializer::Value(Operand::Var(v))) => enum_value(v),
        Some(Initializer::Array(es, _)) => es
            .iter_mut()
            .for_each(|e| init_enum_values(Some(&mut e.value))),
        Some(Initializer::Struct(fs, _)) => {
            fs.iter_mut().for_each(|(_, i)| init_enum_values(Some(i)))
        }
        _ => {}
    }
}

/// `MC_Direction.MC_Shortest_Way` (an enumeration value qualified by its type, as TwinCAT
/// allows) -> `MC_Shortest_Way`.
fn enum_value(v: &mut VarRef) {
    let is_enum = param_passing::prelude::ENUM_TYPES
        .iter()
        .any(|t| v.base.name.eq_ignore_ascii_case(t));
    if let (true, [Accessor::Field(f)]) = (is_enum, v.accessors.as_slice()) {
        let known = param_passing::prelude::ENUM_CONSTANTS
            .iter()
            .any(|(c, _)| f.name.eq_ignore_ascii_case(c));
        if known {
            v.base = f.clone();
            v.accessors = Vec::new().into();
        }
    }
}

/// `fbPower.Enable_Positive` -> `fbPower.EnablePositive`; a pin with no counterpart is one E1041
/// (the name is kept: sema then has nothing more to say only if the pin exists, so the field is
/// renamed to the block's `Error` output, which every block has, to stop a second report; a store
/// into the pin is left out by `stmts`, as `Error` is a BOOL output that cannot be written).
fn var(v: &mut VarRef, inst: &HashMap<String, String>, diags: &mut Diagnostics) {
    let Some(block) = inst.get(&v.base.key()) else {
        return;
    };
    // `aPower[i].Active`: the pin after the element's subscript
    let pin = v
        .accessors
        .iter_mut()
        .find(|a| !matches!(a, Accessor::Index(_)));
    if let Some(Accessor::Field(f)) = pin {
        let pin = f.key();
        if let Some(new) = spelling(block, &pin) {
            f.name = new.to_string();
        } else if let Some(what) = missing(block, &pin) {
            diags.push(e1041(block, &f.name, what, f.span));
            f.name = "Error".into();
        }
    }
}

/// The Tc2_MC2 inputs of `block` that ladderc reads, with their types, for the language server:
/// the spellings of its own pins and MC_Power's `Override` (percent).
pub fn tc2_pins(block: &str) -> impl Iterator<Item = (&'static str, &'static str)> + '_ {
    const PINS: &[(&str, &str, &str)] = &[
        ("MC_POWER", "Enable_Positive", "BOOL"),
        ("MC_POWER", "Enable_Negative", "BOOL"),
        ("MC_POWER", "Override", "LREAL"),
    ];
    PINS.iter()
        .filter(move |(b, _, _)| b.eq_ignore_ascii_case(block))
        .map(|(_, p, t)| (*p, *t))
}

fn spelling(block: &str, pin: &str) -> Option<&'static str> {
    SPELLINGS
        .iter()
        .find(|(b, p, _)| b.eq_ignore_ascii_case(block) && *p == pin)
        .map(|(_, _, new)| *new)
}

fn missing(block: &str, pin: &str) -> Option<&'static str> {
    NO_COUNTERPART
        .iter()
        .find(|(b, p, _)| (b.eq_ignore_ascii_case(block) || *b == "*") && *p == pin)
        .map(|(_, _, what)| *what)
}

fn is_hundred(o: &Operand) -> bool {
    match o {
        Operand::Literal(l) => match l.kind {
            LiteralKind::Int(i) => i == 100,
            LiteralKind::Real(r) => r == 100.0,
            _ => false,
        },
        _ => false,
    }
}

fn e1041(block: &str, pin: &str, what: &str, span: il_frontend::Span) -> Diagnostic {
    Diagnostic::error(
        code::E1041,
        format!("Tc2_MC2's `{pin}` of {block} has no counterpart in ladderc's simulated axis"),
    )
    .at(span)
    .with_hint(format!(
        "{what}; leave the pin out (see `ladderc explain E1041`)"
    ))
}

/// Binds a left-out (or literal 0) required `Acceleration` / `Deceleration` to the configured
/// limit of the call's axis (see the module header): `__TC2_ACC[<axis>.AxisNo]`, the table of the
/// axes' limits, so that the axis an instance is linked to decides (an `AXIS_REF` inside a
/// function block is a different axis in each instance).
fn axis_defaults(block: &str, list: &mut Vec<FormalArg>, at: il_frontend::Span, cx: &Cx) {
    let Some(t) = cx.lib.get(block) else { return };
    if cx.axes.axes.is_empty() {
        return;
    }
    // (the coupled axis of MC_GearIn and its kin: the slave's dynamics, Infosys MC_GearInDyn
    // "the standard acceleration from the axis configuration")
    let axis = list
        .iter()
        .find(|a| a.name.key() == "AXIS")
        .or_else(|| list.iter().find(|a| a.name.key() == "SLAVE"))
        .and_then(|a| match &a.value {
            Operand::Var(v) => Some(v.clone()),
            _ => None,
        });
    let Some(axis) = axis else { return };
    for (pin, table) in [("ACCELERATION", "__TC2_ACC"), ("DECELERATION", "__TC2_DEC")] {
        let Some(p) = t.params.iter().find(|p| p.name.eq_ignore_ascii_case(pin)) else {
            continue;
        };
        if !p.required {
            continue;
        }
        let limit = || {
            let mut no = axis.clone();
            let mut acc = no.accessors.to_vec();
            acc.push(Accessor::Field(Ident::new("AxisNo", at)));
            no.accessors = acc.into();
            cx.tables.set(true);
            Operand::Var(VarRef {
                base: Ident::new(table, at),
                accessors: vec![Accessor::Index(vec![Operand::Var(no)])].into(),
                span: at,
            })
        };
        match list.iter_mut().find(|a| a.name.key() == pin) {
            Some(a) if is_zero(&a.value) => a.value = limit(),
            Some(_) => {}
            None => list.push(FormalArg {
                name: Ident::new(p.name.clone(), at),
                dir: ArgDir::Input,
                value: limit(),
                span: at,
            }),
        }
    }
}

fn is_zero(o: &Operand) -> bool {
    matches!(o, Operand::Literal(l) if matches!(l.kind, LiteralKind::Int(0)) || matches!(l.kind, LiteralKind::Real(r) if r == 0.0))
}

/// The project's global `AXIS_REF`s (in global variable lists and unnamed `VAR_GLOBAL` blocks).
fn global_axes(
    units: &[CompilationUnit],
    structs: &crate::tc2_axis_ref::Structs,
) -> crate::tc2_axis_ref::Axes {
    let mut globals = crate::tc2_axis_ref::Axes {
        paths: Vec::new(),
        lists: Vec::new(),
        homed_read: Default::default(),
        torque_noted: Default::default(),
    };
    for item in units.iter().flat_map(|u| u.items.iter()) {
        if let LibraryElement::GlobalVars(b) = item {
            let paths = crate::tc2_axis_ref::axis_paths(b.vars.iter(), structs);
            if let Some(list) = &b.name {
                for p in &paths {
                    let pair = (list.key(), p.root.key());
                    if !globals.lists.contains(&pair) {
                        globals.lists.push(pair);
                    }
                }
            }
            globals.paths.extend(paths);
        }
    }
    globals
}

/// The Tc2_MC2 (and SoftMotion) `AXIS_REF` members read in the bodies of `units` that
/// [`read_spellings`] has not read: those of the METHODs that `Session::check_uncalled` links
/// into their POUs to check them on their own (the POUs' other bodies were read before; a hidden
/// variable already declared is not declared again).
pub fn read_axis_members(units: &mut [CompilationUnit], diags: &mut Diagnostics) {
    sm3_axis_type(units);
    let (structs, _) = declared_types(units);
    let holders = crate::tc2_axis_ref::axis_holders(units, &structs);
    let globals = global_axes(units, &holders);
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        if let LibraryElement::Pou(p) = item {
            crate::tc2_axis_ref::read_members(p, &globals, &holders, diags);
        }
    }
}

/// CODESYS SoftMotion's axis type, `AXIS_REF_SM3` (SM3_Basic), is ladderc's simulated `AXIS_REF`:
/// renames it in every declaration of `units` (variables, fields, aliases, array elements and
/// reference targets).
pub fn sm3_axis_type(units: &mut [CompilationUnit]) {
    fn ty(t: &mut TypeRef) {
        match t {
            TypeRef::Named(i) if i.is("AXIS_REF_SM3") => i.name = "AXIS_REF".into(),
            TypeRef::Array { element, .. } => ty(element),
            TypeRef::Ref { target, .. } => ty(target),
            _ => {}
        }
    }
    let block = |b: &mut il_frontend::ast::VarBlock| b.vars.iter_mut().for_each(|v| ty(&mut v.ty));
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        match item {
            LibraryElement::Pou(p) => p.var_blocks.iter_mut().for_each(block),
            LibraryElement::GlobalVars(b) => block(b),
            LibraryElement::Configuration(c) => {
                c.globals.iter_mut().for_each(block);
                c.resources
                    .iter_mut()
                    .flat_map(|r| r.globals.iter_mut())
                    .for_each(block);
            }
            LibraryElement::DataTypes(ts) => {
                for t in ts {
                    match &mut t.def {
                        TypeDef::Struct { fields } => fields.iter_mut().for_each(|f| ty(&mut f.ty)),
                        TypeDef::Alias { ty: a, .. } => ty(a),
                        _ => {}
                    }
                }
            }
            LibraryElement::Action(_) => {}
        }
    }
}
