//! Lowering one graphical body (LD or FBD) to IL statements.
//!
//! Input: the [`Graph`] of a body, the POU's variable types and the project [`Index`].
//! Output: IL statements (network after network) and the hidden variables they need (edge-detection
//! instances, temporaries), declared in one extra `VAR` block by the caller.
//!
//! Semantics, per network (the rules users expect of a PLC, which naive LD-to-ST converters break):
//! every element is evaluated where it stands in the network's evaluation order (data flow, ties
//! broken top to bottom, then left to right), as Beremiz generates it:
//! 1. Phase 1 evaluates what comes before the first write: blocks in data-flow order (a block before
//!    anything that reads its outputs; chained blocks in order), edge detectors, and every value used
//!    more than once is stored in a temporary, so it is computed exactly once.
//! 2. Phase 2 writes coils and output variables. Parallel coils fed by one power flow share a single
//!    evaluation (`LD ...` then `ST a`, `ST b`). A contact reads its variable where it stands: one
//!    before a coil of its variable (a feedback, a seal-in) sees the value from before the coil, one
//!    after it (a lower rung sharing a contact with the coil's) sees what the coil wrote (child module
//!    `lower_reads`); a block or edge contact placed after a coil runs after it (child module
//!    `lower_emit`), so it too reads what the coil wrote, and an edge detector still runs once.
//! 3. Jumps and returns come last, with the same capture rule.
//!
//! A feedback loop is cut at an in-out variable or a function block instance on it (the reader sees
//! the previous value), else at the box evaluated first, which reads a function box's previous result
//! from a hidden `__loop_<localId>` (child module `lower_feedback`, IEC 61131-3 ed. 2 4.1.3); a loop
//! through nothing that holds a value is E3010 and the network is skipped. Hidden names start with `__`, which IEC identifiers cannot:
//! `__trig_<localId>` edge detectors, `__tmp_<TYPE>_<n>` temporaries (reused from network to network),
//! `__out_<localId>` results of functions called under EN, `__skip_<localId>` EN labels.
//!
//! ST written inside the body (expressions in contacts and input variables, CODESYS EXECUTE boxes)
//! is lowered by the child module `lower_st` (`lower_st.rs`); blocks are built by `lower_block`
//! (`lower_block.rs`), a lowered network becomes IL in `lower_emit` (`lower_emit.rs`) and double
//! coils are reported by `lower_double` (`lower_double.rs`).
//!
//! Invariants: every emitted instruction carries the span of the XML element it comes from; a network
//! that cannot be lowered is reported (with POU, network and localId) and skipped, the others are still
//! lowered.

use crate::catalogue::{self, Family, OperatorBlock, ResultRule};
use crate::context::{Ctx, Where};
use crate::graph::{self, Edge, Graph, InPin, Kind, Storage, Wire};
use crate::project::{Index, PouSig};
use crate::values;
use diagnostics::{code, Code, Diagnostic, Span};
use il_frontend::ast::{
    Accessor, AddressSize, ArgDir, CallArgs, Condition, FormalArg, Ident, IlStmt, InstrKind,
    Instruction, Literal, LiteralKind, Op, Operand, PouKind, TypeDef, TypeRef, VarDecl, VarKind,
    VarRef,
};
use il_frontend::name_index::NameIndex;
use il_frontend::st::PouLowering;
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use std::borrow::Cow;
use std::collections::{BTreeMap, BinaryHeap};

#[path = "lower_block.rs"]
mod lower_block;
#[path = "lower_double.rs"]
mod lower_double;
#[path = "lower_emit.rs"]
mod lower_emit;
#[path = "lower_feedback.rs"]
mod lower_feedback;
#[path = "lower_order.rs"]
mod lower_order;
#[path = "lower_reads.rs"]
mod lower_reads;
#[path = "lower_st.rs"]
mod lower_st;
use lower_order::{deps_map, kahn, net_deps};

type ValId = usize;

#[derive(Debug, Clone)]
enum Val {
    Const(bool),
    Leaf { op: Operand, neg: bool },
    And(ValId, ValId),
    Or(Vec<ValId>),
    Not(ValId),
}

#[derive(Debug, Clone)]
enum Ty {
    Known(TypeRef),
    WeakInt,
    WeakReal,
    Unknown,
}

enum WriteKind {
    St { neg: bool },
    Set,
    Reset,
}

struct Write {
    target: Operand,
    kind: WriteKind,
    val: ValId,
    span: Span,
    /// The place of the writing element in the network's evaluation order (see
    /// [`NetLowering::pos`]).
    at: usize,
    /// An output variable wired to the result of a function box called under EN: the box's ENO and
    /// the label after the write. The write is skipped when ENO is FALSE, so the variable keeps its
    /// value (see [`NetLowering::en_results`]).
    guard: Option<(ValId, String)>,
}

enum Control {
    Jump(Ident, ValId, Span),
    Return(ValId, Span),
}

enum FuncForm {
    Operator(OperatorBlock),
    NonFormal,
    Formal,
}

enum Action {
    Trig {
        inst: String,
        clk: ValId,
        span: Span,
    },
    Fb {
        inst: VarRef,
        args: Vec<(Ident, ValId)>,
        en: Option<ValId>,
        /// A standard or user FB: EN is passed as the call's `EN :=` (the instance's ENO then
        /// follows it); other blocks (motion) are called conditionally (`CALC`).
        en_arg: bool,
        span: Span,
    },
    Func {
        name: Ident,
        form: FuncForm,
        args: Vec<(Ident, ValId)>,
        en: Option<ValId>,
        result: Operand,
        /// With EN: a hidden variable of the result type that is never written, so it holds the
        /// type's initial value; stored into `result` before EN is tested, so a box that does not
        /// run passes that value on (a function has no memory).
        initial: Option<Operand>,
        /// A user function's ENO, stored by the call (`ENO => __eno_<localId>`) into this hidden
        /// BOOL, FALSE when EN is FALSE: what the box's ENO pin carries.
        eno: Option<Operand>,
        skip_label: String,
        span: Span,
    },
    /// The ST code of a CODESYS EXECUTE box, already IL: run when `en` is TRUE.
    Execute {
        code: Vec<IlStmt>,
        en: Option<ValId>,
        skip_label: String,
        span: Span,
    },
    Label(Ident),
}

/// What a block's typeName refers to.
enum BlockType<'a> {
    UserFb(&'a PouSig),
    UserFn(&'a PouSig),
    StdFb(&'static catalogue::StdFb),
    Motion,
    StdFn(catalogue::StdFunction),
}

/// The POU-level lowering state: variable types, hidden declarations, temporary pools.
pub struct BodyLowering<'i> {
    index: &'i Index,
    pou: String,
    /// The names the body can read, each with where its type is, in the order declared (the project's
    /// globals, the POU's variables, its result, then the hidden variables and temporaries of the
    /// lowering); a name declared again takes the later type. Found by name ignoring case through
    /// `var_index`: a table of positions, 512 KiB for the 32,500 variables of 10,000 rungs, where a
    /// map of owned upper-cased keys and inline types made it 7.9 MB, faulted in page by page and
    /// missed in the cache on every lookup.
    vars: Vec<(Cow<'i, str>, DeclaredType<'i>)>,
    /// Name (any case) -> position in `vars`.
    var_index: NameIndex,
    /// The types of the hidden variables and temporaries the lowering declared ([`DeclaredType::Made`]).
    made_types: Vec<TypeRef>,
    body_span: Span,
    hidden: Vec<VarDecl>,
    hidden_names: HashSet<String>,
    /// Type key -> (type, highest count used by one network).
    pools: BTreeMap<String, (TypeRef, usize)>,
    /// The POU, for the ST lowering of expressions written in contacts and input variables.
    pou_ast: &'i il_frontend::ast::Pou,
    /// That lowering, made at the first such expression.
    st: Option<PouLowering<'i>>,
    /// Node (of the graph being lowered) -> the hidden variable holding its expression's value
    /// (`None`: the expression was reported).
    exprs: HashMap<usize, Option<Operand>>,
    /// Whether the statements go where the POU's actions are inlined (a body or an action of a
    /// POU whose body is not SFC, `crate::body`): an action box, or `Act();` in an EXECUTE box,
    /// is then `CAL Act`.
    calls_actions: bool,
}

impl<'i> BodyLowering<'i> {
    /// The lowering state of `pou` (its variables and the project's globals known); `body_span` is the span
    /// of the body element, where hidden declarations point.
    pub fn new(
        index: &'i Index,
        pou: &'i il_frontend::ast::Pou,
        body_span: Span,
    ) -> BodyLowering<'i> {
        let declared: usize = pou.var_blocks.iter().map(|b| b.vars.len()).sum();
        let mut names = Names {
            vars: Vec::with_capacity(index.globals.len() + declared + 1),
            var_index: NameIndex::with_capacity(index.globals.len() + declared + 1),
        };
        for (k, t) in &index.globals {
            names.declare(Cow::Borrowed(k.as_str()), DeclaredType::Borrowed(t));
        }
        for b in &pou.var_blocks {
            for v in &b.vars {
                names.declare(
                    Cow::Borrowed(v.name.name.as_str()),
                    DeclaredType::Borrowed(&v.ty),
                );
            }
        }
        if let Some(r) = &pou.return_type {
            names.declare(
                Cow::Borrowed(pou.name.name.as_str()),
                DeclaredType::Borrowed(r),
            );
        }
        let Names { vars, var_index } = names;
        BodyLowering {
            index,
            pou: pou.name.name.clone(),
            vars,
            var_index,
            made_types: Vec::new(),
            body_span,
            hidden: Vec::new(),
            hidden_names: HashSet::default(),
            pools: BTreeMap::new(),
            pou_ast: pou,
            st: None,
            exprs: HashMap::default(),
            calls_actions: false,
        }
    }

    /// Lets the body call the POU's actions (see `calls_actions`): the caller inlines every `CAL
    /// Act` of the statements ([`il_frontend::actions::inline_calls`]).
    pub fn calling_actions(mut self) -> Self {
        self.calls_actions = true;
        self
    }

    /// Lowers every network of the graph, in order.
    pub fn lower(&mut self, ctx: &mut Ctx, g: &Graph) -> Vec<IlStmt> {
        self.check_jumps(ctx, g);
        self.check_double_writes(ctx, g);
        self.check_double_writes_in_networks(ctx, g);
        let mut pre = self.expressions(ctx, g);
        // About one statement per element in a ladder body: sized once instead of doubling (with
        // 10,000 rungs the list grows to 9 MB).
        let mut out = Vec::with_capacity(g.nodes.len());
        // One network state for the whole body: cleared per network, its lists keep their room.
        let mut nl = NetLowering::new(self, g, 0);
        for (n, net) in g.networks.iter().enumerate() {
            nl.reset(n + 1);
            if let Some(order) = nl.order(ctx, net) {
                let start = out.len();
                nl.build(ctx, &order);
                if let Some(span) = nl.too_deep {
                    ctx.report(
                        Diagnostic::error(
                            code::E3200,
                            format!(
                                "the network's logic nests more than {MAX_VALUE_DEPTH} levels deep"
                            ),
                        )
                        .at(span)
                        .with_primary_label("this element is past the limit")
                        .with_hint("split the rung: store a part in a variable (a coil) and read it with a contact in the next network")
                        .with_xml(
                            Where {
                                pou: nl.pou.pou.clone(),
                                network: Some(n + 1),
                                local_id: None,
                            }
                            .xml(),
                        ),
                    );
                    continue;
                }
                nl.emit(&mut out);
                // the expressions of the network's contacts and input variables, evaluated first
                // (after the network's labels, so a jump there evaluates them too)
                let code = std::mem::take(&mut pre[n]);
                if !code.is_empty() {
                    let at = start
                        + out[start..]
                            .iter()
                            .take_while(|s| matches!(s, IlStmt::Label(_)))
                            .count();
                    out.splice(at..at, code);
                }
            }
        }
        out
    }

    /// Whether node `i` is wired straight to a result pin of a function box (no instance) whose EN
    /// is wired.
    pub(super) fn from_function_under_en(g: &Graph, i: usize) -> bool {
        g.nodes[i]
            .input
            .iter()
            .any(|w| match &g.nodes[w.from].kind {
                Kind::Block(b) => {
                    b.instance.is_none()
                        && !w
                            .pin
                            .as_ref()
                            .is_some_and(|p| p.trim().eq_ignore_ascii_case("ENO"))
                        && b.inputs.iter().any(|p| {
                            p.name.trim().eq_ignore_ascii_case("EN") && !p.wires.is_empty()
                        })
                }
                _ => false,
            })
    }

    /// E3015 for every jump whose label no `<label>` of the body defines.
    fn check_jumps(&self, ctx: &mut Ctx, g: &Graph) {
        let labels: HashSet<String> = g
            .nodes
            .iter()
            .filter_map(|n| match &n.kind {
                Kind::Label { label, .. } => Some(label.to_ascii_uppercase()),
                _ => None,
            })
            .collect();
        for (net, nodes) in g.networks.iter().enumerate() {
            for &i in nodes {
                if let Kind::Jump { label, label_span } = &g.nodes[i].kind {
                    if !labels.contains(&label.to_ascii_uppercase()) {
                        let at = Where {
                            pou: self.pou.clone(),
                            network: Some(net + 1),
                            local_id: Some(g.nodes[i].id.to_string()),
                        };
                        ctx.report(
                            Diagnostic::error(
                                code::E3015,
                                format!("jump to label `{label}`, which this body does not define"),
                            )
                            .at(*label_span)
                            .with_xml(at.xml()),
                        );
                    }
                }
            }
        }
    }

    /// The hidden declarations (edge detectors first, then temporaries by type).
    pub fn hidden_vars(mut self) -> Vec<VarDecl> {
        let span = self.body_span;
        // the temporaries of the ST expressions (`_STX_T<n>`)
        if let Some(b) = self.st.take().and_then(|low| low.finish(span)) {
            self.hidden.extend(b.vars);
        }
        for (key, (ty, count)) in std::mem::take(&mut self.pools) {
            for i in 0..count {
                self.hidden.push(VarDecl {
                    name: Ident::new(temp_name(&key, i), span),
                    location: None,
                    ty: ty.clone(),
                    init: None,
                    edge: None,
                    span,
                });
            }
        }
        self.hidden
    }

    fn declare_hidden(&mut self, name: &str, ty: TypeRef, span: Span) {
        if self.hidden_names.insert(name.to_string()) {
            self.declare_made(name.to_string(), ty.clone());
            self.hidden.push(VarDecl {
                name: Ident::new(name, span),
                location: None,
                ty,
                init: None,
                edge: None,
                span,
            });
        }
    }

    fn declare_trig(&mut self, name: &str, falling: bool, span: Span) {
        if self.hidden_names.insert(name.to_string()) {
            let ty = if falling { "F_TRIG" } else { "R_TRIG" };
            self.declare_made(name.to_string(), TypeRef::Named(Ident::new(ty, span)));
            self.hidden.push(VarDecl {
                name: Ident::new(name, span),
                location: None,
                ty: TypeRef::Named(Ident::new(if falling { "F_TRIG" } else { "R_TRIG" }, span)),
                init: None,
                edge: None,
                span,
            });
        }
    }

    /// Makes `ty` the type of `name` (a hidden variable or a temporary) for later lookups.
    fn declare_made(&mut self, name: String, ty: TypeRef) {
        let made = DeclaredType::Made(self.made_types.len());
        self.made_types.push(ty);
        let mut names = Names {
            vars: std::mem::take(&mut self.vars),
            var_index: std::mem::take(&mut self.var_index),
        };
        names.declare(Cow::Owned(name), made);
        self.vars = names.vars;
        self.var_index = names.var_index;
    }

    /// The declared type of a plain name (hidden variables included), without copying it.
    fn declared(&self, name: &str) -> Option<&TypeRef> {
        let k = self.var_index.find(name, |p| self.vars[p].0.as_ref())?;
        match self.vars[k].1 {
            DeclaredType::Borrowed(t) => Some(t),
            DeclaredType::Made(k) => self.made_types.get(k),
        }
    }

    fn var_type(&self, v: &VarRef) -> Option<TypeRef> {
        let (mut ty, skip) = match self.declared(&v.base.name) {
            Some(t) => (t.clone(), 0),
            // `GVL.x`: a member of a named global variable list
            None => match (
                self.index.global_lists.get(&v.base.key()),
                v.accessors.first(),
            ) {
                (Some(list), Some(Accessor::Field(m))) => (list.get(&m.key())?.clone(), 1),
                _ => return None,
            },
        };
        for acc in v.accessors.iter().skip(skip) {
            ty = match acc {
                Accessor::Index(_) => match ty {
                    TypeRef::Array { element, .. } => *element,
                    _ => return None,
                },
                Accessor::Field(f) => self.field_type(&ty, f)?,
                Accessor::Deref(_) => match ty {
                    TypeRef::Ref { target, .. } => *target,
                    _ => return None,
                },
            };
        }
        Some(ty)
    }

    fn field_type(&self, ty: &TypeRef, field: &Ident) -> Option<TypeRef> {
        let span = field.span;
        if let Some((size, _)) = il_frontend::ast::partial_access(&field.name) {
            // `flags.2`, `w.%B1`: a part of an integer or bit string (sema checks the range)
            let t = match size {
                AddressSize::Bit => "BOOL",
                AddressSize::Byte => "BYTE",
                AddressSize::Word => "WORD",
                AddressSize::DWord => "DWORD",
                AddressSize::LWord => "LWORD",
            };
            return Some(named_type(t, span));
        }
        let TypeRef::Named(n) = ty else { return None };
        if let Some(fb) = catalogue::std_fb(&n.name) {
            return fb
                .inputs
                .iter()
                .chain(fb.outputs.iter())
                .find(|(p, _)| field.is(p))
                .map(|(_, t)| named_type(t, span));
        }
        if catalogue::is_motion_block(&n.name) {
            return catalogue::motion_pin_type(&field.name).map(|t| named_type(t, span));
        }
        if let Some(sig) = self.index.pous.get(&n.key()) {
            // an internal variable of an FB instance too (CODESYS, TwinCAT; W1412)
            return sig
                .pins
                .iter()
                .chain(&sig.internals)
                .find(|(p, _, _)| field.is(p))
                .map(|(_, _, t)| t.clone());
        }
        match self.index.types.get(&n.key()).map(|d| &d.def) {
            Some(TypeDef::Struct { fields }) => fields
                .iter()
                .find(|f| f.name == *field)
                .map(|f| f.ty.clone()),
            Some(TypeDef::Alias { ty, .. }) => self.field_type(ty, field),
            _ => None,
        }
    }

    fn is_fb_type(&self, ty: &TypeRef) -> bool {
        let TypeRef::Named(n) = ty else { return false };
        catalogue::std_fb(&n.name).is_some()
            || catalogue::is_motion_block(&n.name)
            || self
                .index
                .pous
                .get(&n.key())
                .is_some_and(|p| p.kind == PouKind::FunctionBlock)
    }
}

fn type_key(ty: &TypeRef) -> String {
    match ty {
        TypeRef::Named(n) => n.key(),
        TypeRef::String { wide, length, .. } => format!(
            "{}{}",
            if *wide { "WSTRING" } else { "STRING" },
            length.map(|l| l.to_string()).unwrap_or_default()
        ),
        _ => "T".to_string(),
    }
}

fn temp_name(key: &str, i: usize) -> String {
    format!("__tmp_{key}_{i}")
}

/// `text` for a message: at most 60 characters, then `...` (an element may hold a whole program).
fn shown(text: &str) -> std::borrow::Cow<'_, str> {
    let text = text.trim();
    match text.char_indices().nth(60) {
        Some((at, _)) => format!("{}...", &text[..at]).into(),
        None => text.into(),
    }
}

fn sanitize(id: &str) -> String {
    id.chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect()
}

fn bool_ty(span: Span) -> TypeRef {
    TypeRef::Named(Ident::new("BOOL", span))
}

/// [`BodyLowering`]'s names while they are declared (see its `vars`).
struct Names<'i> {
    vars: Vec<(Cow<'i, str>, DeclaredType<'i>)>,
    var_index: NameIndex,
}

impl<'i> Names<'i> {
    /// Declares `name` with its type; a name declared before (any case) takes this type, keeping its
    /// place.
    fn declare(&mut self, name: Cow<'i, str>, ty: DeclaredType<'i>) {
        let vars = &self.vars;
        match self.var_index.find(&name, |p| vars[p].0.as_ref()) {
            Some(k) => self.vars[k].1 = ty,
            None => {
                self.vars.push((name, ty));
                let vars = &self.vars;
                let k = vars.len() - 1;
                self.var_index.insert(&vars[k].0, k, |p| vars[p].0.as_ref());
            }
        }
    }
}

/// Where a name's type is kept (see [`BodyLowering`]'s `vars`).
#[derive(Debug, Clone, Copy)]
enum DeclaredType<'i> {
    /// Declared in the POU or the project: borrowed from there.
    Borrowed(&'i TypeRef),
    /// A hidden variable or temporary of the lowering: `made_types[k]`.
    Made(usize),
}

/// The family of a known type (what [`family_of`] gives for `Ty::Known(ty)`), without a copy.
fn family_of_type(ty: &TypeRef) -> Option<Family> {
    match ty {
        TypeRef::Named(n) => catalogue::family(&n.name),
        TypeRef::String { .. } => Some(Family::String),
        TypeRef::Subrange { base, .. } => catalogue::family(&base.name),
        _ => None,
    }
}

fn family_of(ty: &Ty) -> Option<Family> {
    match ty {
        Ty::Known(TypeRef::Named(n)) => catalogue::family(&n.name),
        Ty::Known(TypeRef::String { .. }) => Some(Family::String),
        Ty::Known(TypeRef::Subrange { base, .. }) => catalogue::family(&base.name),
        Ty::WeakInt => Some(Family::Int),
        Ty::WeakReal => Some(Family::Real),
        _ => None,
    }
}

fn type_text(ty: &Ty) -> String {
    match ty {
        Ty::Known(TypeRef::Named(n)) => n.name.clone(),
        Ty::Known(TypeRef::String { wide, .. }) => if *wide { "WSTRING" } else { "STRING" }.into(),
        Ty::Known(_) => "a structured type".into(),
        Ty::WeakInt => "an integer literal".into(),
        Ty::WeakReal => "a real literal".into(),
        Ty::Unknown => "an unknown type".into(),
    }
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

fn var_operand(name: &str, span: Span) -> Operand {
    Operand::Var(VarRef {
        base: Ident::new(name, span),
        accessors: Default::default(),
        span,
    })
}

fn field_operand(base: &VarRef, field: &str, span: Span) -> Operand {
    let mut v = base.clone();
    v.accessors.push(Accessor::Field(Ident::new(field, span)));
    v.span = span;
    Operand::Var(v)
}

fn bool_lit(b: bool, span: Span) -> Operand {
    Operand::literal(Literal {
        kind: LiteralKind::Bool(b),
        type_prefix: None,
        span,
    })
}

/// One network being lowered.
struct NetLowering<'a, 'i> {
    pou: &'a mut BodyLowering<'i>,
    g: &'a Graph<'a>,
    network: usize,
    vals: Vec<Val>,
    spans: Vec<Span>,
    temps: Vec<Option<Operand>>,
    uses: Vec<u32>,
    pin_vals: HashMap<(usize, String), ValId>,
    built: HashSet<usize>,
    poisoned: HashSet<usize>,
    actions: Vec<Action>,
    /// Per action: the place, in the network's evaluation order, of the element that made it (see
    /// [`Self::pos`]); a box or edge detector placed after a write runs after it (`lower_emit`).
    action_at: Vec<usize>,
    writes: Vec<Write>,
    controls: Vec<Control>,
    /// Temporaries used by this network, per type key.
    used: HashMap<String, usize>,
    /// Per value: how deeply its operands nest (a leaf is 0).
    depth: Vec<usize>,
    /// Per value: the place, in the network's evaluation order, of the element that made it (a
    /// contact's read of its variable happens there: see `lower_reads`).
    pos: Vec<usize>,
    /// The place of the element being built.
    cur_pos: usize,
    /// The first value that would have nested deeper than [`MAX_VALUE_DEPTH`] (reported as E3200).
    too_deep: Option<Span>,
    /// The result values (as read from the box's output pins, negated or not) of function boxes
    /// called under EN, each with the box's ENO. An output variable (or in-out variable) wired to
    /// one is written only when ENO is TRUE: a box that does not run leaves the variable as it was,
    /// as the vendors document for LD/FBD boxes with EN/ENO (Panasonic FPWIN Pro "EN/ENO": "the
    /// function result is not changed and the connected variable keeps its value") and as Beremiz /
    /// OpenPLC generate (`IF <box>_ENO THEN var := <box>_OUT; END_IF`). IEC 61131-3 only says the
    /// body is not executed and ENO is FALSE.
    en_results: HashMap<ValId, ValId>,
    /// The ENO values of [`Self::en_results`] that a write is guarded by: stored once, when the box
    /// is called, so the write sees the EN the box saw.
    guards: HashSet<ValId>,
    /// Function boxes whose result an earlier box of a loop made of wires only reads from the
    /// previous evaluation: each keeps its result in its hidden variable (`lower_feedback`).
    feedback_sources: HashSet<usize>,
}

/// The deepest nesting of a network's logic (contacts in series, parallel branches, negations) that
/// is lowered. Evaluation walks the nesting recursively, so this bounds the stack it uses; a deeper
/// network gets E3200 and its deepest part is lowered as FALSE.
pub const MAX_VALUE_DEPTH: usize = 2000;

impl<'a, 'i> NetLowering<'a, 'i> {
    fn new(pou: &'a mut BodyLowering<'i>, g: &'a Graph<'a>, network: usize) -> Self {
        NetLowering {
            pou,
            g,
            network,
            vals: Vec::new(),
            spans: Vec::new(),
            temps: Vec::new(),
            uses: Vec::new(),
            pin_vals: HashMap::default(),
            built: HashSet::default(),
            poisoned: HashSet::default(),
            actions: Vec::new(),
            action_at: Vec::new(),
            writes: Vec::new(),
            controls: Vec::new(),
            used: HashMap::default(),
            depth: Vec::new(),
            pos: Vec::new(),
            cur_pos: 0,
            too_deep: None,
            en_results: HashMap::default(),
            guards: HashSet::default(),
            feedback_sources: HashSet::default(),
        }
    }

    /// The guard of a write of `v` by the output element `id`: the ENO of the function box whose
    /// result `v` is, when that box has EN (see [`Self::en_results`]), and the label after the write.
    fn write_guard(&mut self, v: ValId, id: &str) -> Option<(ValId, String)> {
        let eno = *self.en_results.get(&v)?;
        self.guards.insert(eno);
        Some((eno, format!("__keep_{}", sanitize(id))))
    }

    /// The state for network `network` (1-based), as [`NetLowering::new`] makes it, keeping the
    /// capacity of every list and map.
    fn reset(&mut self, network: usize) {
        self.network = network;
        self.vals.clear();
        self.spans.clear();
        self.temps.clear();
        self.uses.clear();
        self.pin_vals.clear();
        self.built.clear();
        self.poisoned.clear();
        self.actions.clear();
        self.action_at.clear();
        self.writes.clear();
        self.controls.clear();
        self.used.clear();
        self.depth.clear();
        self.pos.clear();
        self.cur_pos = 0;
        self.too_deep = None;
        self.en_results.clear();
        self.guards.clear();
        self.feedback_sources.clear();
    }

    fn at(&self, node: usize) -> Where {
        Where {
            pou: self.pou.pou.clone(),
            network: Some(self.network),
            local_id: Some(self.g.nodes[node].id.to_string()),
        }
    }

    fn diag(&self, ctx: &mut Ctx, code: Code, node: usize, span: Span, msg: String) -> Diagnostic {
        let _ = ctx;
        Diagnostic::error(code, msg)
            .at(span)
            .with_xml(self.at(node).xml())
    }

    // ------------------------------------------------------------ ordering

    /// The evaluation order of the network's nodes, or `None` (E3010 reported) for a loop without a
    /// variable.
    fn order(&mut self, ctx: &mut Ctx, net: &[usize]) -> Option<Vec<usize>> {
        let g = self.g;
        // A contact or input variable that names an output of a block instance of this network
        // (`T1.Q`) reads it after the block runs, like a wire would.
        let mut implicit: HashSet<(usize, usize)> = HashSet::default();
        let instances: HashMap<String, usize> = net
            .iter()
            .filter_map(|&i| match &g.nodes[i].kind {
                Kind::Block(b) if b.instance.is_some() && self.is_fb_block(&b.type_name) => {
                    let (name, _) = b.instance.as_ref()?;
                    Some((name.to_ascii_uppercase(), i))
                }
                _ => None,
            })
            .collect();
        if !instances.is_empty() {
            for &i in net {
                let text = match &g.nodes[i].kind {
                    Kind::Contact { var, .. } => var,
                    Kind::InVar { expr, .. } => expr,
                    _ => continue,
                };
                let Some((base, _)) = text.split_once('.') else {
                    continue;
                };
                if let Some(&b) = instances.get(&base.trim().to_ascii_uppercase()) {
                    if b != i {
                        implicit.insert((i, b));
                    }
                }
            }
        }
        // Most networks have no loop: try the plain topological order first, straight from the
        // wires (no list per node).
        let order = kahn(g, net, net_deps(g, net, &implicit));
        if order.len() == net.len() {
            return Some(order);
        }
        // The same dependencies as a map, which the loop cutting below edits.
        let mut deps = deps_map(g, net, &implicit);
        // A loop is cut at a wire leaving a variable or a function block instance: the reader then
        // sees the value from the previous scan. Variables are preferred, then the wire that runs
        // furthest backwards (right to left), as drawn feedback wires do. A loop of wires and
        // function boxes only is cut at the box evaluated first (`lower_feedback`).
        loop {
            let comps = graph::cycles(net, &deps);
            if comps.is_empty() {
                break;
            }
            for comp in comps {
                let set: HashSet<usize> = comp.iter().copied().collect();
                let mut best: Option<((u8, i64, i64), usize, usize)> = None;
                for &t in &comp {
                    for &s in deps.get(&t).map(Vec::as_slice).unwrap_or(&[]) {
                        if !set.contains(&s) {
                            continue;
                        }
                        let rank = match &g.nodes[s].kind {
                            _ if implicit.contains(&(t, s)) => 3,
                            Kind::InOutVar { .. } => 2,
                            Kind::Block(b) if self.is_fb_block(&b.type_name) => 1,
                            _ => continue,
                        };
                        let key = (rank, g.nodes[s].x - g.nodes[t].x, -(g.nodes[s].y));
                        if best.as_ref().is_none_or(|(k, _, _)| key > *k) {
                            best = Some((key, t, s));
                        }
                    }
                }
                match best {
                    Some((_, t, s)) => {
                        if let Some(d) = deps.get_mut(&t) {
                            d.retain(|x| *x != s);
                        }
                    }
                    // wires only: cut at the box evaluated first (`lower_feedback`)
                    None => match self.feedback_cut(&comp, &deps) {
                        Some((t, s)) => {
                            self.feedback_sources.insert(s);
                            if let Some(d) = deps.get_mut(&t) {
                                d.retain(|x| *x != s);
                            }
                        }
                        None => {
                            self.report_loop(ctx, comp);
                            return None;
                        }
                    },
                }
            }
        }
        Some(kahn(
            g,
            net,
            deps.iter()
                .flat_map(|(&i, d)| d.iter().map(move |&s| (i, s))),
        ))
    }

    fn is_fb_block(&self, type_name: &str) -> bool {
        matches!(
            self.block_type(type_name),
            Some(BlockType::UserFb(_) | BlockType::StdFb(_) | BlockType::Motion)
        )
    }

    fn report_loop(&mut self, ctx: &mut Ctx, mut comp: Vec<usize>) {
        let g = self.g;
        comp.sort_by_key(|&i| g.nodes[i].order_key());
        let names: Vec<String> = comp
            .iter()
            .map(|&i| match &g.nodes[i].kind {
                Kind::Block(b) => format!("{} (localId {})", b.type_name, g.nodes[i].id),
                Kind::Contact { var, .. } => {
                    format!("contact `{}` (localId {})", var.trim(), g.nodes[i].id)
                }
                _ => format!("localId {}", g.nodes[i].id),
            })
            .collect();
        let first = comp[0];
        let mut d = self
            .diag(
                ctx,
                code::E3010,
                first,
                g.nodes[first].span,
                format!("feedback loop through nothing that holds a value: {}", names.join(" -> ")),
            )
            .with_hint(
                "put a function box, a function block instance or an in-out variable on the loop: it keeps the previous value",
            );
        for &i in &comp[1..] {
            d = d.with_label(g.nodes[i].span, "part of the loop");
        }
        ctx.report(d);
    }

    // ------------------------------------------------------------ values

    fn val(&mut self, v: Val, span: Span) -> ValId {
        let d = 1 + match &v {
            Val::And(a, b) => self.depth[*a].max(self.depth[*b]),
            Val::Or(vs) => vs.iter().map(|x| self.depth[*x]).max().unwrap_or(0),
            Val::Not(a) => self.depth[*a],
            Val::Const(_) | Val::Leaf { .. } => 0,
        };
        let (v, d) = if d > MAX_VALUE_DEPTH {
            self.too_deep.get_or_insert(span);
            (Val::Const(false), 0)
        } else if matches!(v, Val::Const(_) | Val::Leaf { .. }) {
            (v, 0)
        } else {
            (v, d)
        };
        self.depth.push(d);
        self.pos.push(self.cur_pos);
        self.vals.push(v);
        self.spans.push(span);
        self.temps.push(None);
        self.uses.push(0);
        self.vals.len() - 1
    }

    fn ty(&self, v: ValId) -> Ty {
        match &self.vals[v] {
            Val::Const(_) | Val::And(..) | Val::Or(_) => Ty::Known(bool_ty(self.spans[v])),
            Val::Not(a) => self.ty(*a),
            Val::Leaf { op, .. } => self.operand_ty(op),
        }
    }

    fn operand_ty(&self, op: &Operand) -> Ty {
        match op {
            Operand::Literal(l) => {
                if let Some(p) = &l.type_prefix {
                    return Ty::Known(TypeRef::Named(p.clone()));
                }
                let named = |n: &str| Ty::Known(TypeRef::Named(Ident::new(n, l.span)));
                match &l.kind {
                    LiteralKind::Int(_) => Ty::WeakInt,
                    LiteralKind::Real(_) => Ty::WeakReal,
                    LiteralKind::Bool(_) => named("BOOL"),
                    LiteralKind::Duration(_) => named("TIME"),
                    LiteralKind::Date(_) => named("DATE"),
                    LiteralKind::TimeOfDay(_) => named("TOD"),
                    LiteralKind::DateAndTime(_) => named("DT"),
                    LiteralKind::String { wide, .. } => Ty::Known(TypeRef::String {
                        wide: *wide,
                        length: None,
                        span: l.span,
                    }),
                }
            }
            Operand::Var(v) => self.pou.var_type(v).map(Ty::Known).unwrap_or(Ty::Unknown),
            Operand::Ref(_) => Ty::Unknown,
            Operand::SizeOf(s) => Ty::Known(TypeRef::Named(Ident::new("UDINT", s.span))),
            Operand::Mem(m) => Ty::Known(TypeRef::Named(Ident::new(
                if m.func == il_frontend::ast::MemFunc::Compare {
                    "DINT"
                } else {
                    "UDINT"
                },
                m.span,
            ))),
            Operand::Address(a) => Ty::Known(TypeRef::Named(Ident::new(
                match a.size {
                    AddressSize::Bit => "BOOL",
                    AddressSize::Byte => "BYTE",
                    AddressSize::Word => "WORD",
                    AddressSize::DWord => "DWORD",
                    AddressSize::LWord => "LWORD",
                },
                a.span,
            ))),
            Operand::EnumValue(e) => Ty::Known(TypeRef::Named(e.type_name.clone())),
        }
    }

    /// The value flowing out of `wire`'s source; `consumer` is the reading node (for diagnostics).
    fn wire_val(&mut self, ctx: &mut Ctx, w: &Wire, consumer: usize) -> Option<ValId> {
        let g = self.g;
        let src = &g.nodes[w.from];
        if self.poisoned.contains(&w.from) {
            return None;
        }
        if matches!(src.kind, Kind::LeftRail) {
            // a rail is no network's node (`graph::read`): power flow, TRUE
            return Some(self.val(Val::Const(true), src.span));
        }
        if !self.built.contains(&w.from) {
            // Only a cut loop gets here: read the previous value of the variable or instance output.
            match &src.kind {
                Kind::InOutVar {
                    expr, expr_span, ..
                } => {
                    let op = values::operand(expr, *expr_span)?;
                    return Some(self.val(Val::Leaf { op, neg: false }, src.span));
                }
                Kind::Block(b) if b.instance.is_some() => {
                    let (inst, inst_span) = b.instance.as_ref()?;
                    let inst = values::var_ref(inst, *inst_span)?;
                    let pin = match &w.pin {
                        Some(p) => p.clone(),
                        None => b.outputs.first()?.name.clone(),
                    };
                    let op = field_operand(&inst, &pin, w.span);
                    return Some(self.val(Val::Leaf { op, neg: false }, src.span));
                }
                Kind::Block(_) if self.feedback_sources.contains(&w.from) => {
                    return self.feedback_read(w.from, w);
                }
                _ => return None,
            }
        }
        let key = match &src.kind {
            Kind::Block(b) => {
                let outputs = &b.outputs;
                match &w.pin {
                    Some(p)
                        if outputs
                            .iter()
                            .any(|o| o.name.eq_ignore_ascii_case(p.trim()))
                            || !self.ld_power_flow_quirk(p, consumer) =>
                    {
                        p.to_ascii_uppercase()
                    }
                    None if outputs.len() == 1 => outputs[0].name.to_ascii_uppercase(),
                    // a contact or coil after a box (LD): the rung's power flow leaves the box by
                    // ENO, else by its first output (TON.Q), as CODESYS and TwinCAT draw it
                    _ if matches!(
                        g.nodes[consumer].kind,
                        Kind::Contact { .. } | Kind::Coil { .. }
                    ) =>
                    {
                        outputs
                            .iter()
                            .find(|o| o.name.eq_ignore_ascii_case("ENO"))
                            .or(outputs.first())
                            .map(|o| o.name.to_ascii_uppercase())
                            .unwrap_or_default()
                    }
                    _ => String::new(),
                }
            }
            _ => String::new(),
        };
        match self.pin_vals.get(&(w.from, key)) {
            Some(&v) => Some(v),
            None => {
                let msg = match (&src.kind, &w.pin) {
                    (Kind::Block(b), Some(p)) => {
                        format!(
                            "block {} (localId {}) has no output `{p}`",
                            b.type_name, src.id
                        )
                    }
                    _ => format!("localId {} has no output to connect", src.id),
                };
                let d = self.diag(ctx, code::E3018, consumer, w.span, msg);
                ctx.report(d);
                None
            }
        }
    }

    /// CODESYS/TwinCAT LD exports name the coil's own variable as the `formalParameter` of the wire
    /// from a box into the coil (`<connection refLocalId="26" formalParameter="isSorting"/>` into
    /// coil `isSorting`): when the box has no output of that name, the wire is the rung's power flow
    /// out of the box.
    fn ld_power_flow_quirk(&self, pin: &str, consumer: usize) -> bool {
        match &self.g.nodes[consumer].kind {
            Kind::Coil { var, .. } | Kind::Contact { var, .. } => {
                var.trim().eq_ignore_ascii_case(pin.trim())
            }
            _ => false,
        }
    }

    /// The OR of every wire into one input; `None` when nothing (usable) is connected.
    fn input_val(&mut self, ctx: &mut Ctx, wires: &[Wire], consumer: usize) -> Option<ValId> {
        // The common case, one wire: its value as is, no list.
        if let [w] = wires {
            return self.wire_val(ctx, w, consumer);
        }
        let mut vs = Vec::new();
        for w in wires {
            if let Some(v) = self.wire_val(ctx, w, consumer) {
                vs.push(v);
            }
        }
        match vs.len() {
            0 => None,
            1 => Some(vs[0]),
            _ => {
                if vs.iter().any(|v| matches!(self.vals[*v], Val::Const(true))) {
                    return Some(self.val(Val::Const(true), self.g.nodes[consumer].span));
                }
                Some(self.val(Val::Or(vs), self.g.nodes[consumer].span))
            }
        }
    }

    fn parse_var(&mut self, ctx: &mut Ctx, node: usize, text: &str, span: Span) -> Option<Operand> {
        if let Some(op) = self.pou.exprs.get(&node) {
            return op.clone();
        }
        match values::operand(text, span) {
            Some(op) => Some(op),
            None => {
                let what = if text.is_empty() {
                    "(empty)".to_string()
                } else {
                    format!("`{}`", shown(text))
                };
                let d = self.diag(
                    ctx,
                    code::E3011,
                    node,
                    span,
                    format!("{what} is not a variable, direct address or literal"),
                );
                ctx.report(d);
                None
            }
        }
    }

    /// `family_of(&self.ty(v))`, without building the type.
    fn val_family(&self, v: ValId) -> Option<Family> {
        match &self.vals[v] {
            Val::Const(_) | Val::And(..) | Val::Or(_) => Some(Family::Bool),
            Val::Not(a) => self.val_family(*a),
            Val::Leaf { op, .. } => self.operand_family(op),
        }
    }

    /// `family_of(&self.operand_ty(op))`, without copying a declared type.
    fn operand_family(&self, op: &Operand) -> Option<Family> {
        match op {
            Operand::Var(r) if r.accessors.is_empty() => {
                self.pou.declared(&r.base.name).and_then(family_of_type)
            }
            _ => family_of(&self.operand_ty(op)),
        }
    }

    fn check_bool(
        &mut self,
        ctx: &mut Ctx,
        node: usize,
        v: ValId,
        span: Span,
        what: std::fmt::Arguments,
    ) {
        if let Some(f) = self.val_family(v) {
            if f != Family::Bool {
                let ty = self.ty(v);
                let d = self
                    .diag(
                        ctx,
                        code::E3008,
                        node,
                        span,
                        format!(
                            "{what} needs BOOL power flow, but is driven by {}",
                            type_text(&ty)
                        ),
                    )
                    .with_hint("drive it from a BOOL: compare the value first (`GT`, `EQ`, ...)");
                ctx.report(d);
            }
        }
    }

    fn check_var_bool(
        &mut self,
        ctx: &mut Ctx,
        node: usize,
        op: &Operand,
        span: Span,
        what: std::fmt::Arguments,
    ) -> bool {
        if let Some(f) = self.operand_family(op) {
            if f != Family::Bool {
                let ty = self.operand_ty(op);
                let d = self.diag(
                    ctx,
                    code::E3008,
                    node,
                    span,
                    format!("{what} variable has type {}, not BOOL", type_text(&ty)),
                )
                .with_hint("contacts and coils take BOOL variables: use a compare block for other types");
                ctx.report(d);
                return false;
            }
        }
        true
    }

    fn trig(&mut self, name: String, falling: bool, clk: ValId, span: Span) -> ValId {
        self.pou.declare_trig(&name, falling, span);
        self.push_action(Action::Trig {
            inst: name.clone(),
            clk,
            span,
        });
        let inst = VarRef {
            base: Ident::new(&name, span),
            accessors: Default::default(),
            span,
        };
        self.val(
            Val::Leaf {
                op: field_operand(&inst, "Q", span),
                neg: false,
            },
            span,
        )
    }

    /// Adds an action made by the element being built, at its place in the evaluation order.
    fn push_action(&mut self, a: Action) {
        self.actions.push(a);
        self.action_at.push(self.cur_pos);
    }

    fn alloc_temp(&mut self, ty: &TypeRef) -> Operand {
        let key = type_key(ty);
        let n = self.used.entry(key.clone()).or_insert(0);
        let name = temp_name(&key, *n);
        *n += 1;
        let count = *n;
        let entry = self.pou.pools.entry(key).or_insert_with(|| (ty.clone(), 0));
        if count > entry.1 {
            // A new temporary: make its type known to later lookups.
            entry.1 = count;
            self.pou.declare_made(name.clone(), ty.clone());
        }
        var_operand(&name, self.pou.body_span)
    }

    // ------------------------------------------------------------ building

    fn build(&mut self, ctx: &mut Ctx, order: &[usize]) {
        for (k, &i) in order.iter().enumerate() {
            self.cur_pos = k;
            self.build_node(ctx, i);
            self.built.insert(i);
        }
    }

    fn build_node(&mut self, ctx: &mut Ctx, i: usize) {
        let g = self.g;
        let node = &g.nodes[i];
        let span = node.span;
        match &node.kind {
            Kind::LeftRail => {
                let v = self.val(Val::Const(true), span);
                self.pin_vals.insert((i, String::new()), v);
            }
            Kind::RightRail => {}
            Kind::Contact {
                var,
                var_span,
                negated,
                edge,
                compare,
            } => {
                if let Some((name, at)) = compare {
                    // the vendor's comparison contact: one error, nothing else read of it
                    let what = if name.is_empty() {
                        "a second operand (`<variable1>`)".to_string()
                    } else {
                        format!("`typeName=\"{name}\"`")
                    };
                    let d = self
                        .diag(
                            ctx,
                            code::E1054,
                            i,
                            *at,
                            format!("contact `{var}` compares ({what}): a vendor's comparison contact, not PLCopen TC6"),
                        )
                        .with_hint("a TC6 contact reads one BOOL variable: compare with a block (`EQ`, `GT`, ...) wired into the rung, or into a BOOL variable the contact reads");
                    ctx.report(d);
                    self.poisoned.insert(i);
                    return;
                }
                let input = self.input_val(ctx, &node.input, i);
                if input.is_none() && !node.wired {
                    if !g.nodes.iter().any(|n| n.wires().any(|w| w.from == i)) {
                        // a stray contact, wired on neither side (left in the editor; OpenPLC
                        // Editor and Beremiz generate nothing for it): it has no effect
                        let d = Diagnostic::warning(
                            code::W3003,
                            format!("contact `{var}` is connected to nothing and is skipped"),
                        )
                        .at(span)
                        .with_xml(self.at(i).xml());
                        ctx.report(d);
                        self.poisoned.insert(i);
                        return;
                    }
                    let d = self
                        .diag(
                            ctx,
                            code::E3005,
                            i,
                            span,
                            format!("contact `{var}` is not connected on its left side"),
                        )
                        .with_primary_label("no power can reach this contact")
                        .with_hint("wire the contact to the left power rail (directly or through other contacts), or delete it");
                    ctx.report(d);
                }
                if let Some(v) = input {
                    self.check_bool(ctx, i, v, span, format_args!("contact `{var}`"));
                }
                let Some(op) = self.parse_var(ctx, i, var, *var_span) else {
                    self.poisoned.insert(i);
                    return;
                };
                let bool_var =
                    self.check_var_bool(ctx, i, &op, *var_span, format_args!("contact `{var}`:"));
                let leaf = match edge {
                    // A contact passes BOOL power flow whatever its variable (IEC 61131-3 ed. 2
                    // 4.2.3): on a variable that is no BOOL (reported above, once) it passes FALSE,
                    // so the coil it feeds gets no second error naming a type that flows nowhere
                    _ if !bool_var => self.val(Val::Const(false), span),
                    Edge::None => self.val(Val::Leaf { op, neg: *negated }, span),
                    e => {
                        let read = self.val(Val::Leaf { op, neg: false }, span);
                        let name = format!("__trig_{}", sanitize(&node.id));
                        let q = self.trig(name, *e == Edge::Falling, read, span);
                        if *negated {
                            self.val(Val::Not(q), span)
                        } else {
                            q
                        }
                    }
                };
                let v = match input.map(|v| (v, &self.vals[v])) {
                    Some((_, Val::Const(true))) => leaf,
                    Some((v, _)) => self.val(Val::And(v, leaf), span),
                    None => self.val(Val::Const(false), span),
                };
                self.pin_vals.insert((i, String::new()), v);
            }
            Kind::Coil {
                var,
                var_span,
                negated,
                storage,
                edge,
            } => {
                let input = self.input_val(ctx, &node.input, i);
                let Some(v) = input else {
                    if !node.wired {
                        let d = self
                            .diag(
                                ctx,
                                code::E3005,
                                i,
                                span,
                                format!("coil `{var}` is not connected on its left side"),
                            )
                            .with_primary_label("this coil is never written")
                            .with_hint("wire the coil to the left power rail through its contacts, or delete it");
                        ctx.report(d);
                    }
                    self.poisoned.insert(i);
                    return;
                };
                self.check_bool(ctx, i, v, span, format_args!("coil `{var}`"));
                self.pin_vals.insert((i, String::new()), v);
                let Some(target) = self.parse_var(ctx, i, var, *var_span) else {
                    return;
                };
                self.check_var_bool(ctx, i, &target, *var_span, format_args!("coil `{var}`:"));
                let val = match edge {
                    Edge::None => v,
                    e => {
                        let name = format!("__trig_{}", sanitize(&node.id));
                        self.trig(name, *e == Edge::Falling, v, span)
                    }
                };
                let kind = match storage {
                    Storage::Set => WriteKind::Set,
                    Storage::Reset => WriteKind::Reset,
                    Storage::None => WriteKind::St { neg: *negated },
                };
                self.writes.push(Write {
                    target,
                    kind,
                    val,
                    span,
                    at: self.cur_pos,
                    guard: None,
                });
            }
            Kind::InVar {
                expr,
                expr_span,
                negated,
            } => {
                let Some(op) = self.parse_var(ctx, i, expr, *expr_span) else {
                    self.poisoned.insert(i);
                    return;
                };
                let v = self.val(Val::Leaf { op, neg: *negated }, span);
                self.pin_vals.insert((i, String::new()), v);
            }
            Kind::OutVar {
                expr,
                expr_span,
                negated,
            } => {
                let Some(v) = self.input_val(ctx, &node.input, i) else {
                    if !node.wired {
                        let d = Diagnostic::warning(
                            code::W3003,
                            format!("output variable `{expr}` has nothing connected and is never written"),
                        )
                        .at(span)
                        .with_xml(self.at(i).xml());
                        ctx.report(d);
                    }
                    return;
                };
                let Some(target) = self.parse_var(ctx, i, expr, *expr_span) else {
                    return;
                };
                self.check_assign(ctx, i, v, &target, span);
                let guard = self.write_guard(v, &node.id);
                self.writes.push(Write {
                    target,
                    kind: WriteKind::St { neg: *negated },
                    val: v,
                    span,
                    at: self.cur_pos,
                    guard,
                });
            }
            Kind::InOutVar {
                expr,
                expr_span,
                negated_in,
                negated_out,
            } => {
                let Some(op) = self.parse_var(ctx, i, expr, *expr_span) else {
                    self.poisoned.insert(i);
                    return;
                };
                let out = match self.input_val(ctx, &node.input, i) {
                    Some(v) => {
                        self.check_assign(ctx, i, v, &op, span);
                        let guard = self.write_guard(v, &node.id);
                        self.writes.push(Write {
                            target: op.clone(),
                            kind: WriteKind::St { neg: *negated_in },
                            val: v,
                            span,
                            at: self.cur_pos,
                            guard,
                        });
                        if *negated_in {
                            self.val(Val::Not(v), span)
                        } else {
                            v
                        }
                    }
                    None => self.val(Val::Leaf { op, neg: false }, span),
                };
                let out = if *negated_out {
                    self.val(Val::Not(out), span)
                } else {
                    out
                };
                self.pin_vals.insert((i, String::new()), out);
            }
            Kind::Connector { .. } => {
                if let Some(v) = self.input_val(ctx, &node.input, i) {
                    self.pin_vals.insert((i, String::new()), v);
                } else {
                    self.poisoned.insert(i);
                }
            }
            Kind::Continuation { .. } => {
                let srcs = g.continuation_sources.get(&i).cloned().unwrap_or_default();
                let wires: Vec<Wire> = srcs
                    .iter()
                    .map(|&s| Wire {
                        from: s,
                        pin: None,
                        span,
                    })
                    .collect();
                match self.input_val(ctx, &wires, i) {
                    Some(v) => {
                        self.pin_vals.insert((i, String::new()), v);
                    }
                    None => {
                        self.poisoned.insert(i);
                    }
                }
            }
            Kind::Jump { label, label_span } => {
                let v = self
                    .input_val(ctx, &node.input, i)
                    .unwrap_or_else(|| self.val(Val::Const(!node.has_input), span));
                self.controls
                    .push(Control::Jump(Ident::new(&**label, *label_span), v, span));
            }
            Kind::Return => {
                let v = self
                    .input_val(ctx, &node.input, i)
                    .unwrap_or_else(|| self.val(Val::Const(!node.has_input), span));
                self.controls.push(Control::Return(v, span));
            }
            Kind::Label { label, label_span } => {
                self.push_action(Action::Label(Ident::new(&**label, *label_span)));
            }
            Kind::Block { .. } => self.build_block(ctx, i),
        }
    }

    /// E3008 for an assignment of `v` to `target` when both types are known and incompatible.
    fn check_assign(&mut self, ctx: &mut Ctx, node: usize, v: ValId, target: &Operand, span: Span) {
        let from = self.ty(v);
        let to = self.operand_ty(target);
        if let (Some(f), Some(t)) = (family_of(&from), family_of(&to)) {
            if !catalogue::compatible(f, t) {
                let d = self.diag(
                    ctx,
                    code::E3008,
                    node,
                    span,
                    format!(
                        "{} value written to a variable of type {}",
                        type_text(&from),
                        type_text(&to)
                    ),
                )
                .with_hint("insert a conversion block (`INT_TO_REAL`, ...) or change the variable's type");
                ctx.report(d);
            }
        }
    }

    fn block_type(&self, name: &str) -> Option<BlockType<'i>> {
        let index: &'i Index = self.pou.index;
        if let Some(sig) = index.pous.get(&name.to_ascii_uppercase()) {
            return match sig.kind {
                PouKind::FunctionBlock => Some(BlockType::UserFb(sig)),
                PouKind::Function => Some(BlockType::UserFn(sig)),
                PouKind::Program => None,
            };
        }
        if let Some(fb) = catalogue::std_fb(name) {
            return Some(BlockType::StdFb(fb));
        }
        if catalogue::is_motion_block(name) {
            return Some(BlockType::Motion);
        }
        catalogue::std_function(name).map(BlockType::StdFn)
    }

    fn pin_type(bt: &BlockType, pin: &str, span: Span) -> Option<Option<TypeRef>> {
        // Some(None): pin exists, type unknown; None: no such pin.
        match bt {
            BlockType::UserFb(sig) | BlockType::UserFn(sig) => sig
                .pins
                .iter()
                .find(|(p, k, _)| p.eq_ignore_ascii_case(pin) && *k != VarKind::Output)
                .map(|(_, _, t)| Some(t.clone())),
            BlockType::StdFb(fb) => fb
                .inputs
                .iter()
                .find(|(p, _)| p.eq_ignore_ascii_case(pin))
                .map(|(_, t)| Some(named_type(t, span))),
            BlockType::Motion => Some(catalogue::motion_pin_type(pin).map(|t| named_type(t, span))),
            BlockType::StdFn(_) => Some(None),
        }
    }
}

fn address_key(a: &il_frontend::ast::DirectAddress) -> String {
    format!("%{:?}{:?}{:?}", a.area, a.size, a.path)
}

fn target_key(op: &Operand) -> String {
    match op {
        Operand::Var(r) => r.base.key(),
        Operand::Address(a) => address_key(a),
        _ => String::new(),
    }
}

fn call(cond: Condition, inst: VarRef, args: Vec<(String, Operand)>, span: Span) -> IlStmt {
    let args = if args.is_empty() {
        CallArgs::None
    } else {
        CallArgs::Formal(
            args.into_iter()
                .map(|(n, v)| FormalArg {
                    name: Ident::new(n, span),
                    dir: ArgDir::Input,
                    span: v.span(),
                    value: v,
                })
                .collect(),
        )
    };
    instr(
        InstrKind::Call {
            cond,
            instance: Box::new(inst),
            args,
        },
        span,
    )
}

/// `eno`: where a formal call stores the function's ENO (`ENO => eno`).
fn emit_function(
    name: &Ident,
    form: &FuncForm,
    args: Vec<(Ident, Operand)>,
    eno: Option<&Operand>,
    span: Span,
    out: &mut Vec<IlStmt>,
) {
    match form {
        FuncForm::Operator(op) => {
            let mut it = args.into_iter();
            if let Some((_, first)) = it.next() {
                out.push(simple(Op::Ld, false, Some(first), span));
            }
            match op {
                OperatorBlock::Not => out.push(simple(Op::Not, false, None, span)),
                OperatorBlock::Move => {}
                OperatorBlock::Arith(o) | OperatorBlock::Logic(o) => {
                    for (_, a) in it {
                        out.push(simple(*o, false, Some(a), span));
                    }
                }
                // An extensible comparison is a chain: GT(a, b, c) = (a > b) AND (b > c).
                OperatorBlock::Compare(o) => {
                    let rest: Vec<Operand> = it.map(|(_, a)| a).collect();
                    if let Some(second) = rest.first() {
                        out.push(simple(*o, false, Some(second.clone()), span));
                    }
                    for pair in rest.windows(2) {
                        out.push(instr(
                            InstrKind::Deferred {
                                op: Op::And,
                                negate: false,
                                operand: Some(Box::new(pair[0].clone())),
                                body: vec![simple(*o, false, Some(pair[1].clone()), span)],
                                close: span,
                            },
                            span,
                        ));
                    }
                }
            }
        }
        FuncForm::NonFormal => {
            let mut it = args.into_iter();
            if let Some((_, first)) = it.next() {
                out.push(simple(Op::Ld, false, Some(first), span));
            }
            let rest: Vec<Operand> = it.map(|(_, a)| a).collect();
            out.push(instr(
                InstrKind::FunctionCall {
                    name: name.clone(),
                    args: Box::new(if rest.is_empty() {
                        CallArgs::None
                    } else {
                        CallArgs::NonFormal(rest)
                    }),
                },
                span,
            ));
        }
        FuncForm::Formal => {
            out.push(instr(
                InstrKind::FunctionCall {
                    name: name.clone(),
                    args: Box::new(CallArgs::Formal(
                        args.into_iter()
                            .map(|(n, v)| FormalArg {
                                name: n,
                                dir: ArgDir::Input,
                                span: v.span(),
                                value: v,
                            })
                            .chain(eno.map(|e| FormalArg {
                                name: Ident::new("ENO", span),
                                dir: ArgDir::Output { negated: false },
                                span,
                                value: e.clone(),
                            }))
                            .collect(),
                    )),
                },
                span,
            ));
        }
    }
}

/// A type from the catalogue as the IL parser would read it (`STRING` is not a plain name there).
fn named_type(name: &str, span: Span) -> TypeRef {
    match name {
        "STRING" | "WSTRING" => TypeRef::String {
            wide: name == "WSTRING",
            length: None,
            span,
        },
        _ => TypeRef::Named(Ident::new(name, span)),
    }
}

#[cfg(test)]
mod names_tests {
    use super::*;

    fn type_name(t: Option<&TypeRef>) -> Option<&str> {
        match t {
            Some(TypeRef::Named(n)) => Some(n.name.as_str()),
            _ => None,
        }
    }

    /// A name declared again in another case (a local over a global, a hidden variable) keeps its place
    /// and takes the later type, as the map of upper-cased keys it replaces did; lookups ignore case.
    #[test]
    fn a_name_declared_again_in_another_case_takes_the_later_type_in_its_place() {
        let int = TypeRef::Named(Ident::new("INT", Span::default()));
        let boolean = TypeRef::Named(Ident::new("BOOL", Span::default()));
        let mut names = Names {
            vars: Vec::new(),
            var_index: NameIndex::with_capacity(1),
        };
        names.declare(Cow::Borrowed("MOTOR_ON"), DeclaredType::Borrowed(&int));
        names.declare(Cow::Owned("__tmp_INT_0".into()), DeclaredType::Made(0));
        names.declare(Cow::Borrowed("Motor_On"), DeclaredType::Borrowed(&boolean));
        // growing past the first capacity keeps every name
        for i in 0..100 {
            names.declare(Cow::Owned(format!("x{i}")), DeclaredType::Made(1));
        }
        assert_eq!(names.vars.len(), 102);
        let at = |n: &str| names.var_index.find(n, |p| names.vars[p].0.as_ref());
        assert_eq!(at("motor_on"), Some(0));
        assert_eq!(at("__TMP_int_0"), Some(1));
        assert_eq!(at("X99"), Some(101));
        assert_eq!(at("motor"), None);
        assert!(matches!(
            names.vars[0].1,
            DeclaredType::Borrowed(t) if type_name(Some(t)) == Some("BOOL")
        ));
    }
}
