//! The IL body checker: the type of the current result (CR) at every instruction, labels and jumps,
//! simple and deferred operators, stores, `S`/`R`, unused results and unreachable code.
//!
//! Input: one POU's body and its variable table (from `decls`). Output: the [`InstrFacts`] of every
//! instruction in `Model::instrs` (by identity), diagnostics. Invariants: the body is walked twice: a silent first pass
//! records the CR types that backward jumps bring to their labels, the second pass (which reports) joins
//! at each label the fall-through, the forward jumps and those recorded backward jumps; untyped literals
//! are type variables ([`LitVars`]) resolved once the whole body is seen.
//! Calls are in `calls.rs`, operands and variable access in `places.rs`.

use super::model::*;
use super::typing::LitVars;
use super::Analyzer;
use crate::ast::{self, Condition, IlStmt, InstrKind, Op};
use crate::Span;
use diagnostics::code;
use rustc_hash::FxHashMap as HashMap;

/// A current-result type during the walk: a resolved type or an untyped literal's type variable.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Ty {
    Known(Type),
    Lit(usize),
}

impl Ty {
    pub(super) const ERROR: Ty = Ty::Known(Type::Error);
    pub(super) fn is_error(&self) -> bool {
        matches!(self, Ty::Known(Type::Error))
    }
}

/// The current result at a point of the body.
#[derive(Debug, Clone)]
pub(super) struct Cr {
    /// `None`: undefined (nothing loaded yet).
    pub(super) ty: Option<Ty>,
    /// The instruction that computed the value if no instruction has used it yet.
    pub(super) fresh: Option<Span>,
    /// Paths of different types met at a label: reported when the value is read (an `LD` right after
    /// the label makes the clash harmless).
    pub(super) clash: Option<Box<Clash>>,
}

/// Two paths bringing different types to a label.
#[derive(Debug, Clone)]
pub(super) struct Clash {
    label: ast::Ident,
    a: (Span, String),
    b: (Span, String),
    types: (String, String),
}

/// The walk state: reachability and current result.
#[derive(Debug, Clone)]
pub(super) struct State {
    pub(super) reach: bool,
    pub(super) cr: Cr,
    /// The last instruction walked (the source of a fall-through into a label).
    pub(super) last: Option<Span>,
    /// An unreachable-code warning was given since the last reachable point.
    pub(super) warned_unreachable: bool,
}

impl State {
    /// At the start of a body or nested list: reachable, no current result.
    fn start() -> State {
        State {
            reach: true,
            cr: Cr {
                ty: None,
                fresh: None,
                clash: None,
            },
            last: None,
            warned_unreachable: false,
        }
    }
}

/// A statement list being walked: the body, or the nested list of an open `OP(`.
struct Frame<'t> {
    stmts: std::slice::Iter<'t, IlStmt>,
    st: State,
    open: Option<Box<Open<'t>>>,
}

/// An `OP(` whose nested list is being walked.
struct Open<'t> {
    instr: &'t ast::Instruction,
    /// Index of its record in `Body::recs` (reserved at the opening: pre-order).
    slot: usize,
    rec: Rec,
    /// The outer current result (`None` for `LD(`).
    outer: Option<Ty>,
}

/// A recorded instruction (types may still be literal variables).
#[derive(Debug, Clone, Default)]
pub(super) struct Rec {
    pub(super) cr_before: Option<Ty>,
    pub(super) cr_after: Option<Ty>,
    pub(super) operand: Option<Ty>,
    pub(super) callee: Option<Callee>,
    /// For generic callees: the instantiated type and the result type (patched into `callee`).
    pub(super) callee_tys: Option<(Ty, Ty)>,
    pub(super) args: Vec<(ArgBinding, Ty)>,
}

/// The length at which a body's list of pending records (grown by doubling from empty: a power of two)
/// gets room for all the rest of the body at once (see [`Body::record`]).
const LONG_PENDING: usize = 4096;

/// The facts index of a record not stored yet.
pub(super) const PENDING: u32 = u32::MAX;

impl Rec {
    /// Whether a type of the record is a literal variable (its type is fixed only at the body's end).
    fn has_literal_types(&self) -> bool {
        let lit = |t: &Ty| matches!(t, Ty::Lit(_));
        [&self.cr_before, &self.cr_after, &self.operand]
            .into_iter()
            .any(|t| t.as_ref().is_some_and(lit))
            || self
                .callee_tys
                .as_ref()
                .is_some_and(|(a, b)| lit(a) || lit(b))
            || self.args.iter().any(|(_, t)| lit(t))
    }
}

struct LabelDef {
    span: Span,
    /// Position in walk order.
    pos: usize,
}

/// A jump into a label as seen in a walk.
#[derive(Debug, Clone)]
struct Edge {
    from: Span,
    pos: usize,
    ty: Option<Ty>,
}

/// The checker of one body.
pub(super) struct Body<'a, 'd> {
    pub(super) a: &'a mut Analyzer<'d>,
    pub(super) pou: PouId,
    /// A FUNCTION's result variable was written (ST/S/R/=> into its name).
    pub(super) result_written: bool,
    pub(super) lits: LitVars,
    /// Every instruction of the body in walk order (pre-order), with the index of its facts in
    /// `Model::instrs` once known ([`PENDING`] until then).
    pub(super) recs: Vec<(InstrId, Span, u32)>,
    /// The records whose types still depend on literal variables (resolved when the body is done),
    /// by their position in `recs`. Records without them are stored in the model at once, so a long
    /// body keeps 24 bytes per instruction instead of a whole record.
    pub(super) pending: Vec<(usize, Rec)>,
    labels: HashMap<String, LabelDef>,
    /// Jumps seen in this pass, by upper-case label.
    edges: HashMap<String, Vec<Edge>>,
    /// Backward jumps of the previous pass, resolved: (from, type) by upper-case label.
    backward: HashMap<String, Vec<(Span, Option<Type>)>>,
    /// Position counter (statements in walk order).
    pos: usize,
    /// The generic type a typed name fixes (`ADD_INT`: INT) for the call being instantiated: literals
    /// alone take it instead of their default type.
    pub(super) typed_generic: Option<Type>,
    /// The hidden `REFERENCE TO` inputs of the block's own methods that a call binds to what may
    /// live for one call (a VAR_IN_OUT, a temporary: `crate::st::refs::REF_ASSIGN_CALL`), by
    /// upper-case name: no reference may be kept through them (E0305).
    pub(super) scoped_refs: std::collections::HashSet<String>,
    /// `ADR(v)` of a FUNCTION's own variable in the operand the last `LD` read (`sema::refs`):
    /// its `ST` into anything but a variable of the function is W1444.
    pub(super) call_address: Option<crate::Span>,
    /// Whether the operands being read are the arguments of a `CAL` of an instance (which keeps
    /// them): `ADR` of a VAR_TEMP of a program or block is refused there (`sema::refs`).
    pub(super) instance_args: bool,
    /// Whether the last `LD` loaded the never-written initial value of a method's variable
    /// (`__MD_<M>_<X>`): the `ST` after it restarts the variable at the method's start, no copy
    /// the user wrote (no W1437 for an instance restarted so).
    pub(super) loaded_method_default: bool,
    /// Whether the walk is in the statements of the block's `FB_init` / `FB_reinit` (behind their
    /// `__ACT_` label, `crate::actions`): writes of the block's own inputs there set up the
    /// instance, no W1411 (`places`).
    pub(super) in_instance_setup: bool,
}

impl Analyzer<'_> {
    /// Checks one POU body and stores its instruction infos in the model.
    pub(crate) fn check_body(&mut self, id: PouId, pou: &ast::Pou) {
        let mut labels = HashMap::default();
        let mut pos = 0;
        let any_backward = self.collect_labels(&pou.body, &mut labels, &mut pos);
        let mut b = Body {
            a: self,
            pou: id,
            lits: LitVars::default(),
            // One record per instruction: `pos` counts the statements in walk order (labels too), so
            // the list is never regrown (each regrowth copied it into fresh pages).
            recs: Vec::with_capacity(pos),
            pending: Vec::new(),
            labels,
            edges: HashMap::default(),
            backward: HashMap::default(),
            pos: 0,
            result_written: false,
            typed_generic: None,
            scoped_refs: Default::default(),
            call_address: None,
            instance_args: false,
            loaded_method_default: false,
            in_instance_setup: false,
        };
        b.scope_reference_inputs(&pou.body);
        // Pass 1, silent: what the backward jumps bring. Without backward jumps it would find nothing
        // (its only other effects, name resolutions and `result_written`, pass 2 repeats), so it is
        // skipped.
        let mut backward: HashMap<String, Vec<(Span, Option<Type>)>> = HashMap::default();
        if any_backward {
            b.a.silent = true;
            b.walk_top(&pou.body);
            b.a.silent = false;
        }
        let edges = std::mem::take(&mut b.edges);
        for (label, es) in edges {
            let Some(def) = b.labels.get(&label) else {
                continue;
            };
            let lpos = def.pos;
            for e in es.into_iter().filter(|e| e.pos >= lpos) {
                let ty = e.ty.map(|t| b.resolve(&t));
                backward
                    .entry(label.clone())
                    .or_default()
                    .push((e.from, ty));
            }
        }
        // Pass 2, reporting.
        b.backward = backward;
        b.lits = LitVars::default();
        b.recs.clear();
        b.pending.clear();
        b.pos = 0;
        b.in_instance_setup = false;
        b.walk_top(&pou.body);
        for (slot, r) in std::mem::take(&mut b.pending) {
            let facts = b.finish(r);
            b.recs[slot].2 = b.a.model.instrs.intern(facts);
        }
        let recs = std::mem::take(&mut b.recs);
        let mut order = Vec::with_capacity(recs.len());
        b.a.model.instrs.start_body();
        for (id, span, facts) in recs {
            b.a.model.instrs.insert_interned(id, span, facts);
            order.push(id);
        }
        b.a.model.pous[id.0 as usize].instrs = order;
        if pou.kind == ast::PouKind::Function
            && pou.return_type.is_some()
            && !b.result_written
            && !pou.body.is_empty()
        {
            self.warning(
                code::W1003,
                pou.name.span,
                format!("function `{}` never sets its result", pou.name.name),
            )
            .label("the function's name is never written in its body")
            .hint(format!(
                "assign the result: `{0} := ...;` in ST, `ST {0}` in IL (it is 0/FALSE/empty otherwise)",
                pou.name.name
            ));
        }
    }

    /// Labels of a body in walk order (nested lists included), with an explicit stack: nesting depth is
    /// not limited by the thread's stack. Returns whether a jump goes to a label defined before it (in
    /// walk order, as `Body::walk_top` counts positions).
    fn collect_labels(
        &mut self,
        body: &[IlStmt],
        labels: &mut HashMap<String, LabelDef>,
        pos: &mut usize,
    ) -> bool {
        let mut any_backward = false;
        let mut stack: Vec<std::slice::Iter<'_, IlStmt>> = vec![body.iter()];
        while let Some(top) = stack.last_mut() {
            let Some(s) = top.next() else {
                stack.pop();
                continue;
            };
            *pos += 1;
            match s {
                IlStmt::Label(l) => {
                    if let Some(prev) = labels.get(&l.key()) {
                        let first = prev.span;
                        self.error(
                            code::E1010,
                            l.span,
                            format!("label `{}` is defined twice", l.name),
                        )
                        .label("defined again here")
                        .also(first, "first defined here")
                        .hint("rename one of the labels; jumps go to the first one");
                        continue;
                    }
                    labels.insert(
                        l.key(),
                        LabelDef {
                            span: l.span,
                            pos: *pos,
                        },
                    );
                }
                IlStmt::Instr(i) => match &i.kind {
                    InstrKind::Deferred { body, .. } => stack.push(body.iter()),
                    InstrKind::Jump { label, .. } => {
                        any_backward |= labels.contains_key(&label.key());
                    }
                    _ => {}
                },
            }
        }
        any_backward
    }
}

/// The number of instructions of a body, nested lists included (an explicit stack: depth is not limited
/// by the thread's stack).
pub(super) fn count_instrs(body: &[IlStmt]) -> usize {
    let mut n = 0;
    let mut stack: Vec<std::slice::Iter<'_, IlStmt>> = vec![body.iter()];
    while let Some(top) = stack.last_mut() {
        match top.next() {
            None => {
                stack.pop();
            }
            Some(IlStmt::Label(_)) => {}
            Some(IlStmt::Instr(i)) => {
                n += 1;
                if let InstrKind::Deferred { body, .. } = &i.kind {
                    stack.push(body.iter());
                }
            }
        }
    }
    n
}

impl Body<'_, '_> {
    pub(super) fn pou(&self) -> &Pou {
        &self.a.model.pous[self.pou.0 as usize]
    }

    /// Walks a body with an explicit stack of nested lists (`OP( ... )`), so that nesting depth is not
    /// limited by the thread's stack.
    fn walk_top(&mut self, stmts: &[IlStmt]) {
        let mut stack: Vec<Frame<'_>> = vec![Frame {
            stmts: stmts.iter(),
            st: State::start(),
            open: None,
        }];
        while let Some(top) = stack.last_mut() {
            let Some(s) = top.stmts.next() else {
                let Some(done) = stack.pop() else { break };
                if let (Some(open), Some(parent)) = (done.open, stack.last_mut()) {
                    self.close_deferred(*open, done.st, &mut parent.st);
                }
                continue;
            };
            self.pos += 1;
            let st = &mut top.st;
            match s {
                IlStmt::Label(l) => {
                    if let Some(action) = crate::actions::action_of_label(&l.name) {
                        self.in_instance_setup = crate::st::fb_init::is_instance_setup(action);
                    }
                    self.enter_label(l, st)
                }
                IlStmt::Instr(i) => {
                    if !st.reach {
                        if !st.warned_unreachable {
                            self.a
                                .warning(code::W1002, i.span, "unreachable instruction")
                                .label("no jump or fall-through reaches this")
                                .hint("add a label that a jump targets, or remove the instruction");
                            st.warned_unreachable = true;
                        }
                        // Checked with an unknown current result, so that only names are reported.
                        st.reach = true;
                        st.cr = Cr {
                            ty: Some(Ty::ERROR),
                            fresh: None,
                            clash: None,
                        };
                    }
                    if let InstrKind::Deferred { body, .. } = &i.kind {
                        let (open, inner) = self.open_deferred(i, st);
                        stack.push(Frame {
                            stmts: body.iter(),
                            st: inner,
                            open: Some(Box::new(open)),
                        });
                    } else {
                        self.instr(i, st);
                        st.last = Some(i.span);
                    }
                }
            }
        }
    }

    /// Starts `OP( operand`: reads the outer CR, reserves the record slot, returns the nested state.
    fn open_deferred<'t>(&mut self, i: &'t ast::Instruction, st: &mut State) -> (Open<'t>, State) {
        let InstrKind::Deferred { op, operand, .. } = &i.kind else {
            unreachable!("open_deferred is called for deferred instructions")
        };
        let rec = Rec {
            cr_before: st.cr.ty.clone(),
            ..Rec::default()
        };
        let slot = self.recs.len();
        self.recs.push((InstrId::of(i), i.span, PENDING));
        let outer = if *op == Op::Ld {
            None
        } else {
            Some(self.use_cr(st, i.span, op_name(*op)))
        };
        let mut inner = State::start();
        if let Some(o) = operand {
            let t = self.read_operand(o);
            inner.cr.ty = Some(t);
        }
        (
            Open {
                instr: i,
                slot,
                rec,
                outer,
            },
            inner,
        )
    }

    /// Ends `OP( ... )`: applies the operator to the outer CR and the nested list's value.
    fn close_deferred(&mut self, open: Open<'_>, mut inner: State, st: &mut State) {
        let Open {
            instr: i,
            slot,
            mut rec,
            outer,
        } = open;
        let InstrKind::Deferred {
            op, negate, close, ..
        } = &i.kind
        else {
            return;
        };
        let value = self.use_cr(&mut inner, *close, "`)`");
        rec.operand = Some(value.clone());
        match outer {
            None => self.load(st, value, i.span),
            Some(cr) => {
                // Point at the start of `OP(` for the outer current result: an empty span there. The
                // keyword's length cannot be added to the start: a deferred operator lowered from ST or
                // XML carries the span of an expression whose text is not `OP(` (the sum cut a multi-byte
                // character: cargo-fuzz `st`, fuzz/regressions/st/).
                let head = Span::new(i.span.file, i.span.start as usize, i.span.start as usize);
                let res = self.operator(*op, *negate, cr, value, *close, head, &mut rec);
                st.cr.ty = Some(res);
                st.cr.fresh = Some(i.span);
            }
        }
        rec.cr_after = if st.reach { st.cr.ty.clone() } else { None };
        self.record(slot, rec);
        st.last = Some(i.span);
    }

    /// The CR at a label: the join of the fall-through and every jump to it.
    fn enter_label(&mut self, l: &ast::Ident, st: &mut State) {
        let key = l.key();
        // Only the first definition of a duplicated label is a jump target.
        let is_target = self.labels.get(&key).is_some_and(|d| d.span == l.span);
        let mut incoming: Vec<(Span, &'static str, Option<Ty>)> = Vec::new();
        // Unreachable code before the label does not fall through into it.
        if st.reach && !st.warned_unreachable {
            if let Some(last) = st.last {
                incoming.push((last, "falls through from here", st.cr.ty.clone()));
            } else {
                incoming.push((l.span, "start of the body", st.cr.ty.clone()));
            }
        }
        if is_target {
            for e in self.edges.get(&key).cloned().unwrap_or_default() {
                incoming.push((e.from, "jump from here", e.ty));
            }
            for (from, ty) in self.backward.get(&key).cloned().unwrap_or_default() {
                incoming.push((from, "jump from here", ty.map(Ty::Known)));
            }
        }
        st.reach = true;
        st.warned_unreachable = false;
        st.cr.fresh = None;
        st.cr.clash = None;
        if incoming.is_empty() {
            // Dead code after the label: silence it.
            st.cr.ty = Some(Ty::ERROR);
            return;
        }
        if incoming.iter().any(|(_, _, t)| t.is_none()) {
            st.cr.ty = None;
            return;
        }
        let mut acc: (Span, &'static str, Ty) = {
            let (s, w, t) = incoming[0].clone();
            (s, w, t.unwrap_or(Ty::ERROR))
        };
        for (span, what, ty) in incoming.into_iter().skip(1) {
            let ty = ty.unwrap_or(Ty::ERROR);
            match self.join(&acc.2, &ty) {
                Some(j) => acc.2 = j,
                None => {
                    let (ta, tb) = (self.describe(&acc.2), self.describe(&ty));
                    st.cr.clash = Some(Box::new(Clash {
                        label: l.clone(),
                        a: (acc.0, format!("{ta}: {}", acc.1)),
                        b: (span, format!("{tb}: {what}")),
                        types: (ta, tb),
                    }));
                    acc.2 = Ty::ERROR;
                    break;
                }
            }
        }
        st.cr.ty = Some(acc.2);
    }

    /// The join of two CR types at a label (`None`: a clash).
    fn join(&mut self, a: &Ty, b: &Ty) -> Option<Ty> {
        let a = self.norm(a);
        let b = self.norm(b);
        match (&a, &b) {
            (Ty::Known(Type::Error), _) | (_, Ty::Known(Type::Error)) => Some(Ty::ERROR),
            (Ty::Known(x), Ty::Known(y)) => (x == y).then(|| a.clone()),
            (Ty::Lit(v), Ty::Known(t)) | (Ty::Known(t), Ty::Lit(v)) => {
                self.lits.bind(*v, t).ok().map(|_| Ty::Known(t.clone()))
            }
            (Ty::Lit(x), Ty::Lit(y)) => Some(Ty::Lit(self.lits.unify(*x, *y))),
        }
    }

    /// A literal variable that was bound becomes its type.
    pub(super) fn norm(&mut self, t: &Ty) -> Ty {
        match t {
            Ty::Lit(v) => match self.lits.bound(*v) {
                Some(b) => Ty::Known(b),
                None => Ty::Lit(self.lits.find(*v)),
            },
            k => k.clone(),
        }
    }

    /// The final type (unbound literals get their default).
    pub(super) fn resolve(&mut self, t: &Ty) -> Type {
        match t {
            Ty::Known(k) => k.clone(),
            Ty::Lit(v) => self.lits.resolve(*v),
        }
    }

    pub(super) fn describe(&mut self, t: &Ty) -> String {
        match self.norm(t) {
            Ty::Known(k) => self.a.type_name(&k),
            Ty::Lit(v) => self.lits.describe(v).to_string(),
        }
    }

    /// [`Body::resolve`] of a type that is not needed afterwards (a known type moves, no copy).
    fn resolve_owned(&mut self, t: Ty) -> Type {
        match t {
            Ty::Known(k) => k,
            Ty::Lit(v) => self.lits.resolve(v),
        }
    }

    /// Stores the record of the instruction at `slot` of `recs`: in the model at once when its types
    /// are known, else when the body is done (its literal types are fixed by then). The silent first
    /// pass stores nothing.
    fn record(&mut self, slot: usize, rec: Rec) {
        if self.a.silent {
            return;
        }
        if rec.has_literal_types() {
            if self.pending.len() == LONG_PENDING && self.pending.capacity() == LONG_PENDING {
                // A long body: room for every instruction still to come (an upper bound), so that
                // the list is not regrown by doubling (each regrowth copied it into fresh pages);
                // the room not used is never touched, and the list goes when the body is done.
                self.pending
                    .reserve(self.recs.capacity().saturating_sub(slot));
            }
            self.pending.push((slot, rec));
        } else {
            let facts = self.finish(rec);
            self.recs[slot].2 = self.a.model.instrs.intern(facts);
        }
    }

    fn finish(&mut self, r: Rec) -> InstrFacts {
        let cr_before = r.cr_before.map(|t| self.resolve_owned(t));
        let cr_after = r.cr_after.map(|t| self.resolve_owned(t));
        let operand = r.operand.map(|t| self.resolve_owned(t));
        let mut callee = r.callee;
        if let Some((t, res)) = r.callee_tys {
            let (t, res) = (self.resolve_owned(t), self.resolve_owned(res));
            match &mut callee {
                Some(Callee::Std { ty, result, .. }) => {
                    *ty = t;
                    *result = res;
                }
                Some(Callee::Conversion { from, to, .. }) => {
                    *from = t;
                    *to = res;
                }
                _ => {}
            }
        }
        // Most instructions have no arguments: skip the collect's set-up for them.
        let args = if r.args.is_empty() {
            Vec::new()
        } else {
            r.args
                .into_iter()
                .map(|(mut b, t)| {
                    b.ty = self.resolve_owned(t);
                    b
                })
                .collect()
        };
        InstrFacts {
            cr_before,
            cr_after,
            operand,
            callee,
            args,
        }
    }

    /// Reads the CR (reports an undefined one); marks the value used.
    pub(super) fn use_cr(&mut self, st: &mut State, at: Span, what: &str) -> Ty {
        st.cr.fresh = None;
        if let Some(c) = st.cr.clash.take() {
            let (ta, tb) = &c.types;
            self.a
                .error(
                    code::E1008,
                    c.label.span,
                    format!(
                        "the current result at `{}` is {ta} on one path and {tb} on another",
                        c.label.name
                    ),
                )
                .label("paths meet here")
                .also(c.a.0, c.a.1)
                .also(c.b.0, c.b.1)
                .also(at, format!("{what} reads it here"))
                .hint("load a value after the label, or make every path bring the same type");
        }
        match &st.cr.ty {
            Some(t) => t.clone(),
            None => {
                self.a
                    .error(
                        code::E1007,
                        at,
                        format!("{what} reads the current result, but none is defined here"),
                    )
                    .label("no value loaded before this")
                    .hint("load a value first (LD x)");
                st.cr.ty = Some(Ty::ERROR);
                Ty::ERROR
            }
        }
    }

    /// Replaces the CR by a new value (warns when the old one was never used).
    pub(super) fn load(&mut self, st: &mut State, ty: Ty, at: Span) {
        // (not after a value that is already an error: an unknown function's E1019 says it all)
        if let Some(f) = st
            .cr
            .fresh
            .filter(|_| !st.cr.ty.as_ref().is_some_and(Ty::is_error))
            // (nor after an ST call statement of a function, which drops its result on purpose:
            // CODESYS, TwinCAT; `crate::st::dropped_results`)
            .filter(|f| !crate::st::dropped_results::is_dropped(*f))
        {
            self.a
                .warning(code::W1001, f, "this result is never used")
                .label("computed here")
                .also(at, "replaced here before any use")
                .hint("store it (ST x) or remove the instructions computing it");
        }
        st.cr.ty = Some(ty);
        st.cr.fresh = Some(at);
        st.cr.clash = None;
    }

    /// The CR must be BOOL (conditions, S, R).
    pub(super) fn check_bool(&mut self, ty: &Ty, at: Span, what: &str) {
        let n = self.norm(ty);
        match n {
            Ty::Known(Type::Error) => {}
            Ty::Known(t) if t.is_bool() => {}
            Ty::Lit(v) if self.lits.bind(v, &Type::BOOL).is_ok() => {}
            other => {
                let d = self.describe(&other);
                self.a
                    .error(
                        code::E1023,
                        at,
                        format!("{what} needs a BOOL current result, not {d}"),
                    )
                    .label(format!("the current result is {d}"))
                    .hint("compare first (GT, EQ ...) to get a BOOL");
            }
        }
    }

    fn instr(&mut self, i: &ast::Instruction, st: &mut State) {
        let mut rec = Rec {
            cr_before: st.cr.ty.clone(),
            ..Rec::default()
        };
        // Reserve the slot: pre-order (a deferred instruction before its nested list).
        let slot = self.recs.len();
        self.recs.push((InstrId::of(i), i.span, PENDING));
        match &i.kind {
            InstrKind::Simple {
                op,
                negate,
                operand,
            } => self.simple(i.span, *op, *negate, operand.as_ref(), st, &mut rec),
            // Handled by `open_deferred` / `close_deferred`.
            InstrKind::Deferred { .. } => {}
            InstrKind::Jump { cond, label } => {
                if *cond != Condition::Always {
                    let cr = self.use_cr(st, i.span, "a conditional jump");
                    self.check_bool(&cr, i.span, "a conditional jump");
                }
                match self.labels.get(&label.key()) {
                    None => {
                        self.a
                            .error(
                                code::E1009,
                                label.span,
                                format!("no label `{}` in `{}`", label.name, self.pou().name),
                            )
                            .label("undefined label")
                            .hint(
                                "define the label (`name:` before an instruction) or fix the name",
                            );
                    }
                    Some(_) => {
                        self.edges.entry(label.key()).or_default().push(Edge {
                            from: i.span,
                            pos: self.pos,
                            ty: st.cr.ty.clone(),
                        });
                    }
                }
                st.cr.fresh = None;
                if *cond == Condition::Always {
                    st.reach = false;
                    st.warned_unreachable = false;
                }
            }
            InstrKind::Return { cond } => {
                if *cond != Condition::Always {
                    let cr = self.use_cr(st, i.span, "a conditional return");
                    self.check_bool(&cr, i.span, "a conditional return");
                } else {
                    st.reach = false;
                    st.warned_unreachable = false;
                }
                st.cr.fresh = None;
            }
            InstrKind::Call {
                cond,
                instance,
                args,
            } => self.cal(i.span, *cond, instance, args, st, &mut rec),
            InstrKind::FunctionCall { name, args } => {
                self.function_call(i.span, name, args, false, st, &mut rec)
            }
            InstrKind::FbInput { op, instance } => {
                let cr = self.use_cr(st, i.span, op.input_name());
                self.fb_input(i.span, op.input_name(), instance, cr, &mut rec);
            }
            InstrKind::EmbeddedC { name } => {
                rec.callee = Some(Callee::Embedded {
                    name: name.name.clone(),
                });
            }
        }
        rec.cr_after = if st.reach { st.cr.ty.clone() } else { None };
        self.record(slot, rec);
    }

    fn simple(
        &mut self,
        span: Span,
        op: Op,
        negate: bool,
        operand: Option<&ast::Operand>,
        st: &mut State,
        rec: &mut Rec,
    ) {
        match op {
            Op::Ld => {
                let Some(o) = operand else {
                    self.a
                        .error(code::E1020, span, "LD needs an operand")
                        .label("nothing to load")
                        .hint("write LD x");
                    self.load(st, Ty::ERROR, span);
                    return;
                };
                self.call_address = None;
                self.loaded_method_default = matches!(o, crate::ast::Operand::Var(v)
                    if v.accessors.is_empty() && v.base.name.starts_with("__MD_"));
                let t = self.read_operand(o);
                if negate {
                    self.check_class_bit(&t, o.span(), "LDN");
                }
                // an FB instance loaded is only stored whole into another of its type (W1437,
                // at the ST); any other use is a type error there
                rec.operand = Some(t.clone());
                self.load(st, t, span);
                if matches!(o, crate::ast::Operand::Mem(_)) {
                    // `MEMCPY(...);` as a statement: its result (success) may be dropped, as a
                    // function call's
                    st.cr.fresh = None;
                }
            }
            Op::St => {
                let cr = self.use_cr(st, span, if negate { "STN" } else { "ST" });
                let Some(o) = operand else {
                    self.a
                        .error(code::E1020, span, "ST needs an operand")
                        .label("nothing to store into")
                        .hint("write ST x");
                    return;
                };
                if negate {
                    self.check_class_bit(&cr, span, "STN");
                }
                let mut place = self.write_place(o, "ST");
                if let Some(at) = self.call_address {
                    self.call_address_stored(at, o);
                }
                if place.is_fb() {
                    if matches!(&cr, Ty::Known(c) if *c == place) {
                        if !self.loaded_method_default {
                            self.instance_copied(o.span());
                        }
                    } else {
                        self.not_a_value(o);
                        place = Type::Error;
                    }
                }
                rec.operand = Some(Ty::Known(place.clone()));
                // the hidden view of a dispatch through a base (st::base_view): its class tested
                let view = matches!(o, crate::ast::Operand::Var(v)
                    if v.accessors.is_empty() && crate::st::base_view::is_view_name(&v.base.name));
                let down = view
                    && matches!(&cr, super::body::Ty::Known(t)
                        if super::refs::substitutes(&self.a.model, t, &place, true));
                if !down {
                    // `ST __M_M_In__PVALUE`: a method's ANY input given its argument's address
                    self.a.passing_any_address = matches!(o, crate::ast::Operand::Var(v)
                        if v.accessors.is_empty()
                            && crate::st::any_inputs::is_address_input(&v.base.name));
                    self.coerce_store(&cr, &place, o.span(), span);
                    self.a.passing_any_address = false;
                }
            }
            Op::S | Op::R => {
                let name = if op == Op::S { "S" } else { "R" };
                let Some(o) = operand else {
                    self.a
                        .error(code::E1016, span, format!("{name} without operand"))
                        .label(format!("{name} needs the variable to {}", if op == Op::S { "set" } else { "reset" }))
                        .hint(format!("write {name} x (x: BOOL), or {name} inst for an FB instance with a `{name}` input"));
                    st.cr.fresh = None;
                    return;
                };
                let cr = self.use_cr(st, span, name);
                if let Some(fb) = self.fb_instance_operand(o) {
                    self.fb_input_resolved(span, name, fb, o, cr, rec);
                    return;
                }
                self.check_bool(&cr, span, name);
                let place = self.write_place(o, name);
                rec.operand = Some(Ty::Known(place.clone()));
                if !place.is_error() && !place.is_bool() {
                    let t = self.a.type_name(&place);
                    self.a
                        .error(
                            code::E1006,
                            o.span(),
                            format!("{name} sets or resets a BOOL, not {t}"),
                        )
                        .label(format!("this is {t}"))
                        .hint("use ST to store other types");
                }
            }
            Op::Not => {
                let cr = self.use_cr(st, span, "NOT");
                // `NOT x` is reported by the parser (E0013); the operand is ignored here.
                let _ = operand;
                self.check_class_bit(&cr, span, "NOT");
                rec.callee = Some(Callee::Std {
                    name: "NOT",
                    ty: Type::Error,
                    result: Type::Error,
                });
                rec.callee_tys = Some((cr.clone(), cr.clone()));
                st.cr.ty = Some(cr);
                st.cr.fresh = Some(span);
            }
            _ => {
                let cr = self.use_cr(st, span, op_name(op));
                let Some(o) = operand else {
                    self.a
                        .error(
                            code::E1020,
                            span,
                            format!("{} needs an operand", op_name(op)),
                        )
                        .label("missing operand")
                        .hint(format!(
                            "write {} x, or {}( ... ) for a nested expression",
                            op_name(op),
                            op_name(op)
                        ));
                    st.cr.ty = Some(Ty::ERROR);
                    return;
                };
                let t = self.read_operand(o);
                rec.operand = Some(t.clone());
                let res = self.operator(op, negate, cr, t, o.span(), span, rec);
                st.cr.ty = Some(res);
                st.cr.fresh = Some(span);
            }
        }
    }

    /// W1437, once per POU: an FB instance stored whole into another instance of its block
    /// (CODESYS, TwinCAT: `a := b;` copies every variable of `b` into `a`).
    fn instance_copied(&mut self, at: Span) {
        if self.a.silent || !self.a.copying_instance_pous.insert(self.pou) {
            return;
        }
        self.a
            .warning(
                code::W1437,
                at,
                "a function block instance copied whole: IEC 61131-3 defines no assignment of instances (its other uses in this POU are not reported)",
            )
            .label("every variable of the instance is written")
            .hint("compiled as CODESYS and TwinCAT do (a copy of each variable, nested instances too); copy the inputs and outputs one by one for another IEC compiler");
    }

    fn not_a_value(&mut self, o: &ast::Operand) {
        self.a
            .error(code::E1021, o.span(), "an FB instance is not a value")
            .label("a function block instance")
            .hint("read or write its inputs and outputs (inst.Q), or call it with CAL");
    }

    /// Checks that `t` is ANY_BIT (N modifier, NOT, STN).
    fn check_class_bit(&mut self, t: &Ty, at: Span, what: &str) {
        let n = self.norm(t);
        match &n {
            Ty::Known(k) if k.is_error() || k.is_bit() => {}
            // CODESYS, TwinCAT: the complement of an integer's bit pattern (W1438)
            Ty::Known(Type::Elementary(e)) if super::bit_arith::bits_of(*e).is_some() => {
                let f = if what == "LDN" { "NOT" } else { what };
                self.integer_as_bits(f, *e, at);
            }
            Ty::Lit(v) if !self.lits.is_real(*v) => {}
            _ => {
                let d = self.describe(&n);
                self.a
                    .error(code::E1004, at, format!("{what} is not defined for {d}"))
                    .label(format!("this is {d}"))
                    .hint("negation needs a bit string (BOOL, BYTE, WORD, DWORD, LWORD)");
            }
        }
    }

    /// A binary operator (simple or deferred): CR `op` operand.
    #[allow(clippy::too_many_arguments)]
    fn operator(
        &mut self,
        op: Op,
        negate: bool,
        cr: Ty,
        operand: Ty,
        operand_span: Span,
        span: Span,
        rec: &mut Rec,
    ) -> Ty {
        let name = op_name(op);
        let f = match self.a.operator_functions.get_mut(op as usize) {
            Some(known) => *known.get_or_insert_with(|| super::stdlib::function(name)),
            None => super::stdlib::function(name),
        };
        let Some(f) = f else {
            return Ty::ERROR;
        };
        if negate {
            self.check_class_bit(&operand, operand_span, &format!("{name}N"));
        }
        // IEC 61131-3: integer literals are ANY_INT, so `LD 7` / `DIV 2` divides as integers (3),
        // even when the result is then stored into a REAL
        if matches!(op, Op::Div | Op::Mod) {
            if let (Ty::Lit(a), Ty::Lit(b)) = (self.norm(&cr), self.norm(&operand)) {
                if !self.lits.is_real(a) && !self.lits.is_real(b) {
                    let v = self.lits.unify(a, b);
                    self.lits.set_int_only(v);
                }
            }
        }
        let inst = self.instantiate(f, &[(cr, span), (operand, operand_span)], span);
        rec.callee = Some(Callee::Std {
            name: inst.name,
            ty: Type::Error,
            result: Type::Error,
        });
        rec.callee_tys = Some((inst.t.clone(), inst.result.clone()));
        inst.result
    }
}

/// The IEC name of a simple operator (as a standard function where there is one).
pub(super) fn op_name(op: Op) -> &'static str {
    match op {
        Op::Ld => "LD",
        Op::St => "ST",
        Op::S => "S",
        Op::R => "R",
        Op::And => "AND",
        Op::Or => "OR",
        Op::Xor => "XOR",
        Op::Not => "NOT",
        Op::Add => "ADD",
        Op::Sub => "SUB",
        Op::Mul => "MUL",
        Op::Div => "DIV",
        Op::Mod => "MOD",
        Op::Gt => "GT",
        Op::Ge => "GE",
        Op::Eq => "EQ",
        Op::Ne => "NE",
        Op::Le => "LE",
        Op::Lt => "LT",
    }
}
