//! Lowering of PLCopen block calls (paper A). Runs after the semantic check of the user's program (which
//! typed every `CAL` against the block prelude) and before C generation.
//!
//! Input: compilation units whose POUs declare instances of template blocks (or arrays of them, whose
//! elements are called `CAL fbMove[i](...)`) and `CAL` them; the library;
//! the TM window; a strategy. Output: the units with every such `CAL` replaced, the hidden TM views declared,
//! the instance types turned into plain structs (see `prelude`), plus the C of the embedded functions and a
//! per-block report. Invariants: with the IL method a call becomes input transfer + one `FUNC Name()` +
//! output transfer; with the template method exactly one `FUNC Name_n()` (behind a `JMPC`/`JMPCN` around it
//! for `CALC`/`CALCN`); nothing is generated for a call that failed the legality checks.

use crate::library::Library;
use crate::template::{Direction, Param, Template, TypeClass};
use crate::tm::{self, TmLayout};
use diagnostics::{code, Diagnostic, Diagnostics, Span};
use il_frontend::ast::*;
use std::collections::{BTreeMap, HashMap};

/// How block calls are lowered.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Strategy {
    /// Paper A method 1: TM transfers + a static-library function.
    Il,
    /// Paper A method 2: one FUNC; the function synthesised from the template.
    Template,
    /// Per block type: the IL method when the block fits the TM area and is called at
    /// [`AUTO_IL_MIN_CALLS`] or more sites (one shared static function is then smaller than that many
    /// synthesised ones); the template method otherwise.
    Auto,
}

/// See [`Strategy::Auto`].
pub const AUTO_IL_MIN_CALLS: usize = 3;

/// Where the TM area lies in the %M area, and how %M addresses count.
#[derive(Debug, Clone, Copy)]
pub struct TmWindow {
    /// Byte offset of the TM area in %M (must be a multiple of 8).
    pub offset: u32,
    /// Size of the TM area in bytes.
    pub bytes: u32,
    /// `true`: `%MD5` is the sixth double word (bytes 20..24); `false`: `%MD5` starts at byte 5.
    pub element_addressing: bool,
}

/// The chosen method for one block type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// IL-instruction method: TM transfers and one FUNC of a static-library function.
    Il,
    /// Parameter-template method: one FUNC of a function synthesised per call.
    Template,
}

/// One head local of a synthesised function: `c_type local = <value of source>;`. An array parameter
/// gives one head local per element, named `local[k]` (`Pos_1[0]`, `Pos_1[1]` ...), consecutive and from
/// index 0: the C backend declares them as one array `c_type local[len]` initialised element by element.
#[derive(Debug, Clone)]
pub struct HeadLocal {
    /// The local's C type.
    pub c_type: &'static str,
    /// The local's name.
    pub local: String,
    /// The parameter's class.
    pub class: TypeClass,
    /// The operand the local is initialised from (a bound argument, or the instance's own field).
    pub source: Operand,
}

/// One feedback assignment of a synthesised function's tail: `<target> = local;` (`local` may be an array
/// element, `Pos_1[2]`).
#[derive(Debug, Clone)]
pub struct Feedback {
    /// Where the output goes.
    pub target: Operand,
    /// The local holding the output.
    pub local: String,
    /// The parameter's class.
    pub class: TypeClass,
    /// `NOT Done => x`.
    pub negated: bool,
}

/// A template-method function: head + library body + tail, to be rendered inside its POU's context (the
/// head reads and the tail writes the POU's own variables).
#[derive(Debug, Clone)]
pub struct Synthesized {
    /// The function's C name.
    pub name: String,
    /// The POU it belongs to (whose variables it reads and writes).
    pub pou: String,
    /// The block's FuncNum.
    pub func_num: u32,
    /// The head: one local per parameter value.
    pub head: Vec<HeadLocal>,
    /// The template's own locals: `(C type, name)`.
    pub locals: Vec<(String, String)>,
    /// The library body with every abbreviation renamed to its head local.
    pub body: String,
    /// The tail: the outputs written back.
    pub tail: Vec<Feedback>,
    /// The call in the user's source.
    pub call_span: Span,
}

/// What one block type cost, for `--report`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BlockReport {
    /// The block type.
    pub block: String,
    /// The method its calls were lowered by.
    pub method: Method,
    /// How many calls.
    pub calls: usize,
    /// TM bytes of the block's layout (IL method; 0 for the template method).
    pub tm_bytes: u32,
    /// IL instructions the calls of this block lowered to, in total.
    pub il_instructions: usize,
}

/// What parameter passing produced.
#[derive(Debug, Default)]
pub struct Lowered {
    /// The user's units with every block call lowered.
    pub units: Vec<CompilationUnit>,
    /// Static-library functions (IL method), by block name, with their TM layouts.
    pub static_functions: BTreeMap<String, TmLayout>,
    /// The template-method functions, one per call.
    pub synthesized: Vec<Synthesized>,
    /// Per block type, what it cost.
    pub reports: Vec<BlockReport>,
}

/// The name of a block type's TM view of one parameter (a hidden located variable).
pub fn tm_view_name(block: &str, param: &str) -> String {
    format!("TM__{block}__{param}")
}

/// The TM layout of a block for the IL method: the template's parameters ordered by value size (largest
/// first, stable; an array counts by its element) so that every value, and every array element, is aligned
/// to its size while the area stays contiguous.
pub fn il_layout(t: &Template, window: &TmWindow) -> Result<TmLayout, (u32, u32)> {
    let mut params: Vec<Param> = t.params.clone();
    params.sort_by_key(|p| std::cmp::Reverse(p.class.tm_bytes()));
    tm::layout_params(&params, window.bytes)
}

/// The IEC type of a TM slot of `p` (bool class: the 0/1 byte).
fn slot_type(p: &Param) -> &'static str {
    match (p.class, p.iec_type.to_ascii_uppercase().as_str()) {
        (TypeClass::Bool, _) => "BYTE",
        (TypeClass::Byte, "SINT") => "SINT",
        (TypeClass::Byte, "BYTE") => "BYTE",
        (TypeClass::Byte, _) => "USINT",
        (TypeClass::Word, "INT") => "INT",
        (TypeClass::Word, "UINT") => "UINT",
        (TypeClass::Word, _) => "WORD",
        (TypeClass::Dword, "DINT") => "DINT",
        (TypeClass::Dword, "DWORD") => "DWORD",
        (TypeClass::Dword, _) => "UDINT",
        (TypeClass::Real, _) => "REAL",
        (TypeClass::Lreal, _) => "LREAL",
        (TypeClass::Lword, _) => "LWORD",
        (TypeClass::Struct, _) => "UDINT",
    }
}

fn address(window: &TmWindow, offset: u32, class: TypeClass, span: Span) -> DirectAddress {
    let bytes = class.tm_bytes();
    let size = match bytes {
        1 => AddressSize::Byte,
        2 => AddressSize::Word,
        4 => AddressSize::DWord,
        _ => AddressSize::LWord,
    };
    let byte = window.offset + offset;
    let index = if window.element_addressing {
        byte / bytes
    } else {
        byte
    };
    DirectAddress {
        area: Area::Memory,
        size,
        path: vec![index],
        span,
    }
}

// ------------------------------------------------------------------ small AST builders

fn id(name: &str, span: Span) -> Ident {
    Ident::new(name, span)
}

fn var(name: &str, span: Span) -> Operand {
    Operand::Var(VarRef {
        base: id(name, span),
        accessors: Default::default(),
        span,
    })
}

fn field(inst: &VarRef, name: &str) -> Operand {
    let mut r = inst.clone();
    r.accessors.push(Accessor::Field(id(name, inst.span)));
    Operand::Var(r)
}

/// The scalar inputs a call binds: each is stored into the instance's own field with the call, so
/// that an input the next call leaves out keeps this value (IEC 61131-3, 6.6.3.4: `rst(Axis := ax,
/// Execute := TRUE);` then `rst(Axis := ax);` keeps Execute TRUE), and `rst.Execute` reads it.
fn bound_inputs<'t>(t: &'t Template, args: &'t CallArgs) -> impl Iterator<Item = &'t Param> {
    let list: &[FormalArg] = match args {
        CallArgs::Formal(list) => list,
        _ => &[],
    };
    let names: Vec<&Ident> = list
        .iter()
        .filter(|a| a.dir == ArgDir::Input)
        .map(|a| &a.name)
        .collect();
    t.params.iter().filter(move |p| {
        p.direction == Direction::Input
            && p.array.is_none()
            && p.class != TypeClass::Struct
            && names.iter().any(|n| n.is(&p.name))
    })
}

/// Element `index` of an array operand (a variable; anything else is returned unchanged).
fn element(array: &Operand, index: i64) -> Operand {
    match array {
        Operand::Var(v) => {
            let mut v = v.clone();
            v.accessors
                .push(Accessor::Index(vec![int_lit(i128::from(index), v.span)]));
            Operand::Var(v)
        }
        other => other.clone(),
    }
}

fn int_lit(v: i128, span: Span) -> Operand {
    Operand::literal(Literal {
        kind: LiteralKind::Int(v),
        type_prefix: None,
        span,
    })
}

fn instr(kind: InstrKind, span: Span) -> IlStmt {
    IlStmt::Instr(Instruction { kind, span })
}

fn simple(op: Op, negate: bool, operand: Option<Operand>, span: Span) -> IlStmt {
    instr(
        InstrKind::Simple {
            op,
            negate,
            operand,
        },
        span,
    )
}

// ------------------------------------------------------------------ the pass

struct BlockUse<'a> {
    template: &'a Template,
    calls: usize,
    first_call: Span,
}

/// A variable that holds instances of a template block: the block's name, and how many arrays
/// deep the instances lie (0: the variable is one instance; 1: `fbPower : ARRAY [1..4] OF
/// MC_Power;`, each element its own instance, called as `fbPower[i](...)`; 2: an array of arrays,
/// `fbPower[i][j](...)`).
#[derive(Debug, Clone)]
struct InstanceVar {
    block: String,
    depth: usize,
}

/// The template block a declared type holds instances of (`MC_Power`, `ARRAY [..] OF MC_Power`,
/// arrays of arrays of it), with the number of array levels around it.
pub fn instance_block<'l>(ty: &TypeRef, lib: &'l Library) -> Option<(&'l Template, usize)> {
    let mut depth = 0;
    let mut ty = ty;
    while let TypeRef::Array { element, .. } = ty {
        depth += 1;
        ty = element;
    }
    match ty {
        TypeRef::Named(t) => lib.get(&t.name).map(|tpl| (tpl, depth)),
        _ => None,
    }
}

/// The block a declared type holds instances of (see [`instance_block`]).
fn instance_var(ty: &TypeRef, lib: &Library) -> Option<InstanceVar> {
    instance_block(ty, lib).map(|(tpl, depth)| InstanceVar {
        block: tpl.block.clone(),
        depth,
    })
}

/// Instances of template blocks declared in a POU (and in global blocks): variable key -> block.
fn instances(
    unit_globals: &HashMap<String, InstanceVar>,
    pou: &Pou,
    lib: &Library,
) -> HashMap<String, InstanceVar> {
    let mut m = unit_globals.clone();
    for b in &pou.var_blocks {
        for v in &b.vars {
            if let Some(iv) = instance_var(&v.ty, lib) {
                m.insert(v.name.key(), iv);
            }
        }
    }
    m
}

/// The block a call's instance is an instance of: a plain instance called as itself, or an
/// element of an array of instances (`fbMove[i]`, one subscript list per array level, any index
/// expression: the generated code reads and writes that element's fields, so each element keeps
/// its own state).
fn called_block<'m>(
    instances: &'m HashMap<String, InstanceVar>,
    instance: &VarRef,
) -> Option<&'m str> {
    let iv = instances.get(&instance.base.key())?;
    let fits = instance.accessors.len() == iv.depth
        && instance
            .accessors
            .iter()
            .all(|a| matches!(a, Accessor::Index(_)));
    fits.then_some(iv.block.as_str())
}

fn calls_in<'a>(body: &'a [IlStmt], out: &mut Vec<&'a Instruction>) {
    for s in body {
        if let IlStmt::Instr(i) = s {
            match &i.kind {
                InstrKind::Call { .. } => out.push(i),
                InstrKind::Deferred { body, .. } => calls_in(body, out),
                _ => {}
            }
        }
    }
}

/// Lowers every block call of `units`.
pub fn lower(
    units: &[CompilationUnit],
    lib: &Library,
    strategy: Strategy,
    window: &TmWindow,
    diags: &mut Diagnostics,
) -> Lowered {
    // Globals that are block instances.
    let mut globals = HashMap::new();
    for u in units {
        for item in &u.items {
            // (the global lists and configurations: a POU's variables are no globals)
            if matches!(item, LibraryElement::Pou(_)) {
                continue;
            }
            for b in item.var_blocks() {
                for v in &b.vars {
                    if let Some(iv) = instance_var(&v.ty, lib) {
                        globals.insert(v.name.key(), iv);
                    }
                }
            }
        }
    }
    // Count call sites per block type (for Auto) and check legality of every call first.
    let mut uses: BTreeMap<String, BlockUse> = BTreeMap::new();
    let errors_before = diags.error_count();
    for u in units {
        for item in &u.items {
            let LibraryElement::Pou(pou) = item else {
                continue;
            };
            let inst = instances(&globals, pou, lib);
            let mut calls = Vec::new();
            calls_in(&pou.body, &mut calls);
            for c in calls {
                let InstrKind::Call { instance, args, .. } = &c.kind else {
                    continue;
                };
                let Some(block) = called_block(&inst, instance) else {
                    continue;
                };
                let t = lib.get(block).expect("instances come from the library");
                check_call(t, pou, instance, args, c.span, diags);
                uses.entry(t.block.clone())
                    .or_insert(BlockUse {
                        template: t,
                        calls: 0,
                        first_call: c.span,
                    })
                    .calls += 1;
            }
        }
    }
    let mut out = Lowered::default();
    if diags.error_count() > errors_before {
        return out;
    }
    // Choose the method per block type and lay out the TM area.
    let mut methods: HashMap<String, (Method, Option<TmLayout>)> = HashMap::new();
    for (name, u) in &uses {
        let layout = il_layout(u.template, window);
        let method = match strategy {
            Strategy::Il => Method::Il,
            Strategy::Template => Method::Template,
            Strategy::Auto if layout.is_ok() && u.calls >= AUTO_IL_MIN_CALLS => Method::Il,
            Strategy::Auto => Method::Template,
        };
        match (method, layout) {
            (Method::Il, Err((needed, available))) => {
                diags.push(
                    Diagnostic::error(
                        code::E4020,
                        format!("block `{name}` needs {needed} bytes of TM area, but the target has {available}"),
                    )
                    .at(u.first_call)
                    .with_label(u.template.span, "parameters declared in this template")
                    .with_hint("enlarge `tm_bytes` in the target profile, or use --strategy template (no TM area)"),
                );
            }
            (Method::Il, Ok(l)) => {
                out.static_functions.insert(name.clone(), l.clone());
                methods.insert(name.to_ascii_uppercase(), (Method::Il, Some(l)));
            }
            (Method::Template, _) => {
                methods.insert(name.to_ascii_uppercase(), (Method::Template, None));
            }
        }
        out.reports.push(BlockReport {
            block: name.clone(),
            method,
            calls: u.calls,
            tm_bytes: methods
                .get(&name.to_ascii_uppercase())
                .and_then(|m| m.1.as_ref())
                .map_or(0, |l| l.total),
            il_instructions: 0,
        });
    }
    if diags.error_count() > errors_before {
        return out;
    }
    let mut site = 0usize;
    for u in units {
        let mut unit = u.clone();
        for item in &mut unit.items {
            let LibraryElement::Pou(pou) = item else {
                continue;
            };
            let inst = instances(&globals, pou, lib);
            let mut cx = PouLowering {
                lib,
                window,
                methods: &methods,
                instances: &inst,
                pou_name: pou.name.name.clone(),
                used_views: BTreeMap::new(),
                site: &mut site,
                synthesized: &mut out.synthesized,
                counts: HashMap::new(),
            };
            let body = std::mem::take(&mut pou.body);
            pou.body = cx.lower_body(body);
            let views = std::mem::take(&mut cx.used_views);
            for (block, n) in cx.counts {
                if let Some(r) = out
                    .reports
                    .iter_mut()
                    .find(|r| r.block.eq_ignore_ascii_case(&block))
                {
                    r.il_instructions += n;
                }
            }
            if !views.is_empty() {
                let span = pou.name.span;
                let vars = views
                    .into_values()
                    .map(|(name, addr, ty)| VarDecl {
                        name: id(&name, span),
                        location: Some(addr),
                        ty: TypeRef::Named(id(ty, span)),
                        init: None,
                        edge: None,
                        span,
                    })
                    .collect();
                pou.var_blocks.push(VarBlock::locals(vars, span));
            }
        }
        out.units.push(unit);
    }
    out
}

/// Legality of one call, before any code is generated.
fn check_call(
    t: &Template,
    pou: &Pou,
    instance: &VarRef,
    args: &CallArgs,
    span: Span,
    diags: &mut Diagnostics,
) {
    let formal: &[FormalArg] = match args {
        CallArgs::Formal(f) => f,
        CallArgs::None => &[],
        CallArgs::NonFormal(a) => {
            diags.push(
                Diagnostic::error(
                    code::E4021,
                    format!(
                        "`{}` is called with positional arguments",
                        instance.base.name
                    ),
                )
                .at(a.first().map_or(span, |o| o.span()))
                .with_hint(format!(
                    "PLCopen blocks take formal arguments: CAL {}(Axis := ..., Execute := ...)",
                    instance.base.name
                )),
            );
            return;
        }
    };
    for a in formal {
        let Some(p) = t.param(&a.name.name) else {
            continue;
        }; // unknown names: sema reports them
        if matches!(a.dir, ArgDir::Output { .. })
            && !matches!(a.value, Operand::Var(_) | Operand::Address(_))
        {
            diags.push(
                Diagnostic::error(
                    code::E4022,
                    format!(
                        "a constant is bound to the output `{}` of `{}`",
                        p.name, t.block
                    ),
                )
                .at(a.value.span())
                .with_hint("bind outputs to variables: `Done => done_flag`"),
            );
        }
        if p.array.is_some() && !matches!(a.value, Operand::Var(_)) {
            diags.push(
                Diagnostic::error(
                    code::E4104,
                    format!(
                        "`{}` of `{}` is an array: bind an array variable, not a single value",
                        p.name, t.block
                    ),
                )
                .at(a.value.span())
                .with_hint(format!(
                    "declare `{} : {};` and bind it: `{} := {}`",
                    p.abbr.to_ascii_lowercase(),
                    p.iec_declared(&crate::prelude::declared_type(p)),
                    p.name,
                    p.abbr.to_ascii_lowercase()
                )),
            );
            continue;
        }
        if p.direction == Direction::InOut && !matches!(a.value, Operand::Var(_)) {
            diags.push(
                Diagnostic::error(
                    code::E4022,
                    format!(
                        "`{}` of `{}` needs a variable, not a constant",
                        p.name, t.block
                    ),
                )
                .at(a.value.span())
                .with_hint("bind VAR_IN_OUT parameters such as Axis to a variable (an AXIS_REF)"),
            );
        }
    }
    // A required input must be bound in the call, in another call of the instance, or stored into
    // the instance (`ST mv.Position`).
    let stored = stored_fields(&pou.body, &instance.base);
    for p in t.params.iter().filter(|p| p.required) {
        let bound = formal.iter().any(|a| a.name.is(&p.name));
        if !bound && !stored.iter().any(|f| f.eq_ignore_ascii_case(&p.name)) {
            diags.push(
                Diagnostic::error(
                    code::E4023,
                    format!(
                        "required input `{}` of `{}` (instance `{}`) is not bound",
                        p.name, t.block, instance.base.name
                    ),
                )
                .at(span)
                .with_hint(format!("add `{} := ...` to the call", p.name)),
            );
        }
    }
}

/// The fields of instance `inst` that `body` stores into (whole, or an element of an array field)
/// or binds in a call of it.
fn stored_fields(body: &[IlStmt], inst: &Ident) -> Vec<String> {
    let mut out = Vec::new();
    for s in body {
        let IlStmt::Instr(i) = s else { continue };
        match &i.kind {
            InstrKind::Simple {
                op: Op::St | Op::S | Op::R,
                operand: Some(Operand::Var(v)),
                ..
            } if v.base == *inst => {
                // `ST mv.Position` or, for an array input, `ST mv.Position[0]`; of an array of
                // instances, `ST mv[i].Position` (some element's)
                let lead = v
                    .accessors
                    .iter()
                    .take_while(|a| matches!(a, Accessor::Index(_)))
                    .count();
                let fields = &v.accessors[lead..];
                if let [Accessor::Field(f)] | [Accessor::Field(f), Accessor::Index(_)] = fields {
                    out.push(f.name.clone());
                }
            }
            // another call of the instance that binds the input: an input a call leaves out keeps
            // the value the last call gave it (IEC 61131-3, 6.6.3.4: `rst(Axis := ax);` before
            // `rst(Axis := ax, Execute := go);`)
            InstrKind::Call {
                instance,
                args: CallArgs::Formal(f),
                ..
            } if instance.base == *inst => out.extend(
                f.iter()
                    .filter(|a| a.dir == ArgDir::Input)
                    .map(|a| a.name.name.clone()),
            ),
            InstrKind::Deferred { body, .. } => out.extend(stored_fields(body, inst)),
            _ => {}
        }
    }
    out
}

struct PouLowering<'a> {
    lib: &'a Library,
    window: &'a TmWindow,
    methods: &'a HashMap<String, (Method, Option<TmLayout>)>,
    instances: &'a HashMap<String, InstanceVar>,
    pou_name: String,
    /// TM views used in this POU: key -> (name, address, type).
    used_views: BTreeMap<String, (String, DirectAddress, &'static str)>,
    site: &'a mut usize,
    synthesized: &'a mut Vec<Synthesized>,
    counts: HashMap<String, usize>,
}

impl PouLowering<'_> {
    /// Lowers the block calls of a body, nested lists (`AND( ... )`) included. The nesting is
    /// walked with an explicit stack of open lists, so its depth is bounded by memory only.
    fn lower_body(&mut self, body: Vec<IlStmt>) -> Vec<IlStmt> {
        /// A nested list being lowered: its remaining input, its output so far, and the deferred
        /// instruction (with an empty body) it will become the body of.
        struct Open {
            input: std::vec::IntoIter<IlStmt>,
            out: Vec<IlStmt>,
            head: Option<IlStmt>,
        }
        let mut stack = vec![Open {
            input: body.into_iter(),
            out: Vec::new(),
            head: None,
        }];
        loop {
            let top = stack
                .last_mut()
                .expect("the outermost list stays until the end");
            let Some(mut s) = top.input.next() else {
                let done = stack.pop().expect("just looked at it");
                let Some(mut head) = done.head else {
                    return done.out;
                };
                if let IlStmt::Instr(Instruction {
                    kind: InstrKind::Deferred { body, .. },
                    ..
                }) = &mut head
                {
                    *body = done.out;
                }
                stack
                    .last_mut()
                    .expect("a nested list has a parent")
                    .out
                    .push(head);
                continue;
            };
            match &mut s {
                IlStmt::Instr(Instruction {
                    kind: InstrKind::Deferred { body, .. },
                    ..
                }) => {
                    let input = std::mem::take(body).into_iter();
                    stack.push(Open {
                        input,
                        out: Vec::new(),
                        head: Some(s),
                    });
                }
                IlStmt::Instr(Instruction {
                    kind:
                        InstrKind::Call {
                            cond,
                            instance,
                            args,
                        },
                    span,
                }) if called_block(self.instances, instance).is_some() => {
                    let (cond, span) = (*cond, *span);
                    let out = &mut top.out;
                    let block = called_block(self.instances, instance)
                        .expect("matched above")
                        .to_string();
                    let t = self.lib.get(&block).expect("known block");
                    let (method, layout) = self.methods[&block.to_ascii_uppercase()].clone();
                    *self.site += 1;
                    let skip = format!("SKIP__{}", *self.site);
                    let guarded = cond != Condition::Always;
                    let start = out.len();
                    if guarded {
                        let c = if cond == Condition::IfTrue {
                            Condition::IfFalse
                        } else {
                            Condition::IfTrue
                        };
                        out.push(instr(
                            InstrKind::Jump {
                                cond: c,
                                label: id(&skip, span),
                            },
                            span,
                        ));
                    }
                    match method {
                        Method::Il => self.il_call(
                            t,
                            layout.as_ref().expect("IL layout"),
                            instance,
                            args,
                            span,
                            out,
                        ),
                        Method::Template => self.template_call(t, instance, args, span, out),
                    }
                    if guarded {
                        out.push(IlStmt::Label(id(&skip, span)));
                    }
                    let n = out[start..]
                        .iter()
                        .filter(|s| matches!(s, IlStmt::Instr(_)))
                        .count();
                    *self.counts.entry(t.block.clone()).or_default() += n;
                }
                _ => top.out.push(s),
            }
        }
    }

    /// The TM view of value `k` of parameter `p` (`k` = 0 for a scalar; element `k` of an array).
    fn view(&mut self, t: &Template, layout: &TmLayout, p: &Param, k: u32, span: Span) -> Operand {
        let slot = layout.slot(&p.name).expect("every parameter has a slot");
        let name = match p.array {
            Some(_) => format!("{}__{k}", tm_view_name(&t.block, &p.name)),
            None => tm_view_name(&t.block, &p.name),
        };
        let addr = address(
            self.window,
            slot.offset + k * p.class.tm_bytes(),
            p.class,
            span,
        );
        self.used_views
            .entry(name.to_ascii_uppercase())
            .or_insert_with(|| (name.clone(), addr, slot_type(p)));
        var(&name, span)
    }

    /// The operand an input is taken from: the bound argument, else the instance's own field.
    fn input_source(p: &Param, instance: &VarRef, args: &CallArgs) -> Operand {
        if let CallArgs::Formal(f) = args {
            if let Some(a) = f
                .iter()
                .find(|a| a.name.is(&p.name) && a.dir == ArgDir::Input)
            {
                if p.array.is_none() || matches!(a.value, Operand::Var(_)) {
                    return a.value.clone();
                }
            }
        }
        field(instance, &p.name)
    }

    /// The operand a parameter's value comes from before the call: a bound argument for inputs, else the
    /// instance's own field (inputs' stored values, outputs' and state's previous values). A reference
    /// (struct class) passes its engine index field.
    fn source(p: &Param, instance: &VarRef, args: &CallArgs) -> Operand {
        let src = if matches!(p.direction, Direction::Input | Direction::InOut) {
            Self::input_source(p, instance, args)
        } else {
            field(instance, &p.name)
        };
        match (&src, p.class) {
            (Operand::Var(v), TypeClass::Struct) => {
                let mut v = v.clone();
                v.accessors.push(Accessor::Field(id(
                    crate::prelude::index_field(&p.iec_type),
                    v.span,
                )));
                Operand::Var(v)
            }
            _ => src,
        }
    }

    /// The operands of every value of `p`: the source itself for a scalar, its elements `[low]` ..
    /// `[low + len - 1]` for an array (the legality check made sure an array source is a variable).
    fn sources(p: &Param, instance: &VarRef, args: &CallArgs) -> Vec<Operand> {
        let src = Self::source(p, instance, args);
        match p.array {
            None => vec![src],
            Some(shape) => (0..shape.len)
                .map(|k| element(&src, shape.iec_index(k)))
                .collect(),
        }
    }

    fn il_call(
        &mut self,
        t: &Template,
        layout: &TmLayout,
        instance: &VarRef,
        args: &CallArgs,
        span: Span,
        out: &mut Vec<IlStmt>,
    ) {
        // 0. the bound inputs into the instance (kept for the next call that leaves them out)
        for p in bound_inputs(t, args) {
            let value = Self::input_source(p, instance, args);
            out.push(simple(Op::Ld, false, Some(value), span));
            out.push(simple(Op::St, false, Some(field(instance, &p.name)), span));
        }
        // 1. transfer into TM: inputs, then what the library reads back (previous outputs, state); an
        //    array element by element
        for p in t.inputs().chain(t.carried()) {
            for (k, src) in (0u32..).zip(Self::sources(p, instance, args)) {
                let dst = self.view(t, layout, p, k, span);
                match (p.class, &src) {
                    (TypeClass::Bool, Operand::Literal(l)) => {
                        let v = matches!(l.kind, LiteralKind::Bool(true) | LiteralKind::Int(1));
                        out.push(simple(Op::Ld, false, Some(int_lit(v as i128, span)), span));
                    }
                    (TypeClass::Bool, _) => {
                        let t = Operand::literal(Literal {
                            kind: LiteralKind::Bool(true),
                            type_prefix: None,
                            span,
                        });
                        out.push(simple(Op::Ld, false, Some(src.clone()), span));
                        out.push(simple(Op::Eq, false, Some(t), span));
                        out.push(instr(
                            InstrKind::FunctionCall {
                                name: id("BOOL_TO_BYTE", span),
                                args: Box::new(CallArgs::None),
                            },
                            span,
                        ));
                    }
                    _ => out.push(simple(Op::Ld, false, Some(src.clone()), span)),
                }
                out.push(simple(Op::St, false, Some(dst), span));
            }
        }
        // 2. the call of the static-library function
        out.push(instr(
            InstrKind::EmbeddedC {
                name: id(&t.block, span),
            },
            span,
        ));
        // 3. transfer out of TM: into the instance, then into the `=>` targets
        for p in t.carried() {
            let fields = Self::sources(p, instance, &CallArgs::None);
            for (k, inst_field) in (0u32..).zip(fields.iter()) {
                let src = self.view(t, layout, p, k, span);
                out.push(simple(Op::Ld, false, Some(src), span));
                if p.class == TypeClass::Bool {
                    out.push(simple(Op::Eq, false, Some(int_lit(1, span)), span));
                    out.push(simple(Op::S, false, Some(inst_field.clone()), span));
                    out.push(simple(Op::Not, false, None, span));
                    out.push(simple(Op::R, false, Some(inst_field.clone()), span));
                } else {
                    out.push(simple(Op::St, false, Some(inst_field.clone()), span));
                }
            }
            for (target, negated) in output_targets(p, args) {
                for (k, inst_field) in (0u32..).zip(fields.iter()) {
                    let target = match p.array {
                        Some(shape) => element(&target, shape.iec_index(k)),
                        None => target.clone(),
                    };
                    out.push(simple(Op::Ld, negated, Some(inst_field.clone()), span));
                    out.push(simple(Op::St, false, Some(target), span));
                }
            }
        }
    }

    fn template_call(
        &mut self,
        t: &Template,
        instance: &VarRef,
        args: &CallArgs,
        span: Span,
        out: &mut Vec<IlStmt>,
    ) {
        let n = *self.site;
        let name = format!("{}_{n}", t.block);
        let mut head = Vec::new();
        let mut tail = Vec::new();
        let bound: Vec<&Param> = bound_inputs(t, args).collect();
        for p in &t.params {
            let local = format!("{}_{n}", p.abbr);
            // An array becomes the elements `Pos_1[0]`, `Pos_1[1]` ... of one C array local.
            let local_of = |k: u32| match p.array {
                Some(_) => format!("{local}[{k}]"),
                None => local.clone(),
            };
            for (k, source) in (0u32..).zip(Self::sources(p, instance, args)) {
                head.push(HeadLocal {
                    c_type: p.c_type(),
                    local: local_of(k),
                    class: p.class,
                    source,
                });
            }
            // a bound input back into the instance after the call (kept for the next call that
            // leaves it out), inside the one function
            if bound.iter().any(|b| std::ptr::eq(*b, p)) {
                tail.push(Feedback {
                    target: field(instance, &p.name),
                    local: local_of(0),
                    class: p.class,
                    negated: false,
                });
            }
            if matches!(p.direction, Direction::Output | Direction::State) {
                let fields = Self::sources(p, instance, &CallArgs::None);
                for (k, f) in (0u32..).zip(fields) {
                    tail.push(Feedback {
                        target: f,
                        local: local_of(k),
                        class: p.class,
                        negated: false,
                    });
                }
                for (target, negated) in output_targets(p, args) {
                    for k in 0..p.values() {
                        let target = match p.array {
                            Some(shape) => element(&target, shape.iec_index(k)),
                            None => target.clone(),
                        };
                        tail.push(Feedback {
                            target,
                            local: local_of(k),
                            class: p.class,
                            negated,
                        });
                    }
                }
            }
        }
        let renames: HashMap<&str, String> = t
            .params
            .iter()
            .map(|p| (p.abbr.as_str(), format!("{}_{n}", p.abbr)))
            .collect();
        let body = rename_identifiers(&t.body.text, &renames);
        self.synthesized.push(Synthesized {
            name: name.clone(),
            pou: self.pou_name.clone(),
            func_num: t.func_num,
            head,
            locals: t
                .locals
                .iter()
                .map(|l| (l.c_type.clone(), l.name.clone()))
                .collect(),
            body,
            tail,
            call_span: span,
        });
        out.push(instr(
            InstrKind::EmbeddedC {
                name: id(&name, span),
            },
            span,
        ));
    }
}

/// The `=>` targets a call binds to output `p`, with their `NOT`.
fn output_targets(p: &Param, args: &CallArgs) -> Vec<(Operand, bool)> {
    let CallArgs::Formal(f) = args else {
        return Vec::new();
    };
    f.iter()
        .filter(|a| a.name.is(&p.name))
        .filter_map(|a| match a.dir {
            ArgDir::Output { negated } => Some((a.value.clone(), negated)),
            ArgDir::Input => None,
        })
        .collect()
}

/// Renames free identifiers of C text (not members after `.`/`->`, not inside literals or comments).
pub fn rename_identifiers(text: &str, renames: &HashMap<&str, String>) -> String {
    let (toks, _) = crate::cbody::tokens(text);
    let mut out = String::with_capacity(text.len() + 16);
    let mut last = 0;
    for (k, t) in toks.iter().enumerate() {
        if t.kind != crate::cbody::Tok::Ident {
            continue;
        }
        let member = k > 0
            && (toks[k - 1].kind == crate::cbody::Tok::Punct(b'.')
                || (toks[k - 1].kind == crate::cbody::Tok::Punct(b'>')
                    && k > 1
                    && toks[k - 2].kind == crate::cbody::Tok::Punct(b'-')));
        if member {
            continue;
        }
        if let Some(new) = renames.get(&text[t.start..t.end]) {
            out.push_str(&text[last..t.start]);
            out.push_str(new);
            last = t.end;
        }
    }
    out.push_str(&text[last..]);
    out
}
