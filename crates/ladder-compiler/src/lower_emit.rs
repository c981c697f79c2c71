//! Emission, for [`super`]: the values of one lowered network become IL statements: values used more
//! than once stored in temporaries, phase 1 (labels, the blocks and edge detectors placed before the
//! first write, shared values), phase 2 (coil and output writes sharing one evaluation, each contact
//! read where it stands: `lower_reads`; a block or edge detector placed after a write runs after it,
//! before the next one), then jumps and returns ([`NetLowering::emit`]).
//!
//! Input: the network's value table and actions (each with its place in the evaluation order),
//! built by [`super`]. Output: IL statements appended to the body. Invariants: every value is
//! computed exactly once per network; every action (block call, edge detector) is emitted exactly
//! once, in evaluation order; every statement carries the span of the element it comes from.

use super::*;

/// One step of a network's writes (phase 2): a box or edge detector placed after the first write
/// (index into the actions), or a write group.
#[derive(Clone, Copy)]
enum Step {
    Act(usize),
    Group(usize),
}

impl NetLowering<'_, '_> {
    pub(super) fn children(&self, v: ValId) -> Vec<ValId> {
        match &self.vals[v] {
            Val::And(a, b) => vec![*a, *b],
            Val::Or(vs) => vs.clone(),
            Val::Not(a) => vec![*a],
            _ => Vec::new(),
        }
    }

    pub(super) fn count_uses(&mut self) {
        let add = |uses: &mut Vec<u32>, v: ValId| uses[v] += 1;
        let mut uses = std::mem::take(&mut self.uses);
        for v in 0..self.vals.len() {
            for c in self.children(v) {
                add(&mut uses, c);
            }
        }
        for a in &self.actions {
            match a {
                Action::Trig { clk, .. } => add(&mut uses, *clk),
                Action::Fb { args, en, .. } | Action::Func { args, en, .. } => {
                    for (_, v) in args {
                        add(&mut uses, *v);
                    }
                    if let Some(e) = en {
                        add(&mut uses, *e);
                    }
                }
                Action::Execute { en, .. } => {
                    if let Some(e) = en {
                        add(&mut uses, *e);
                    }
                }
                Action::Label(_) => {}
            }
        }
        for (_, val) in self.write_groups() {
            add(&mut uses, val);
        }
        for c in &self.controls {
            match c {
                Control::Jump(_, v, _) | Control::Return(v, _) => add(&mut uses, *v),
            }
        }
        self.uses = uses;
    }

    /// Consecutive writes of one value (and one guard: none, or the same) with no box or edge
    /// detector placed between them form a group: one evaluation, several stores.
    pub(super) fn write_groups(&self) -> Vec<(std::ops::Range<usize>, ValId)> {
        let mut out: Vec<(std::ops::Range<usize>, ValId)> = Vec::new();
        for (i, w) in self.writes.iter().enumerate() {
            match out.last_mut() {
                Some((r, v))
                    if *v == w.val
                        && self.writes[r.start].guard.as_ref().map(|g| g.0)
                            == w.guard.as_ref().map(|g| g.0)
                        && !self.action_between(self.writes[r.end - 1].at, w.at) =>
                {
                    r.end = i + 1
                }
                _ => out.push((i..i + 1, w.val)),
            }
        }
        out
    }

    /// Whether a box or edge detector (not a label) stands after place `from` and up to place `to`:
    /// it runs between two writes there, so they are no one group.
    fn action_between(&self, from: usize, to: usize) -> bool {
        self.actions
            .iter()
            .zip(&self.action_at)
            .any(|(a, &at)| !matches!(a, Action::Label(_)) && from < at && at <= to)
    }

    /// A value that can be used as an operand without evaluating anything.
    pub(super) fn direct(&self, v: ValId) -> Option<(Operand, bool)> {
        if let Some(t) = &self.temps[v] {
            return Some((t.clone(), false));
        }
        match &self.vals[v] {
            Val::Const(b) => Some((bool_lit(*b, self.spans[v]), false)),
            Val::Leaf { op, neg } => Some((op.clone(), *neg)),
            _ => None,
        }
    }

    pub(super) fn is_trivial(&self, v: ValId) -> bool {
        matches!(self.direct(v), Some((_, false)))
    }

    /// Stores the shared sub-values of `v` (used more than once) into temporaries, innermost first.
    /// Walks each value once: a child already in a temporary is not walked again (walking it again
    /// made a lattice of contacts, each fed by the two before it, cost time exponential in its length).
    /// A block with an EN input: evaluates EN and jumps past the block to `skip_label` when it is FALSE
    /// (the caller places the label after the block). Nothing without EN.
    pub(super) fn skip_unless_en(
        &mut self,
        en: Option<ValId>,
        skip_label: &str,
        span: Span,
        out: &mut Vec<IlStmt>,
    ) {
        if let Some(e) = en {
            self.prepare(e, out);
            // a write guarded by this box's ENO reads the EN stored here, as the box saw it
            if self.guards.contains(&e) && !matches!(self.vals[e], Val::Const(_)) {
                self.materialise(e, out);
            }
            self.eval(e, out);
            out.push(instr(
                InstrKind::Jump {
                    cond: Condition::IfFalse,
                    label: Ident::new(skip_label, span),
                },
                span,
            ));
        }
    }

    pub(super) fn prepare(&mut self, v: ValId, out: &mut Vec<IlStmt>) {
        for c in self.children(v) {
            if self.temps[c].is_some() {
                continue;
            }
            if self.uses[c] > 1 && !self.is_trivial(c) {
                self.materialise(c, out);
            } else {
                self.prepare(c, out);
            }
        }
    }

    /// Evaluates `v` once into a temporary; later uses read the temporary.
    pub(super) fn materialise(&mut self, v: ValId, out: &mut Vec<IlStmt>) {
        if self.temps[v].is_some() {
            return;
        }
        self.prepare(v, out);
        let ty = match self.ty(v) {
            Ty::Known(t) => t,
            _ => bool_ty(self.spans[v]),
        };
        let t = self.alloc_temp(&ty);
        self.eval(v, out);
        out.push(simple(Op::St, false, Some(t.clone()), self.spans[v]));
        self.temps[v] = Some(t);
    }

    /// An operand holding `v` (stored in a temporary first when it is an expression).
    pub(super) fn operand(&mut self, v: ValId, out: &mut Vec<IlStmt>) -> Operand {
        match self.direct(v) {
            Some((op, false)) => op,
            _ => {
                self.materialise(v, out);
                self.temps[v]
                    .clone()
                    .unwrap_or_else(|| bool_lit(false, self.spans[v]))
            }
        }
    }

    /// Loads `v` into the current result (shared sub-values must already be prepared).
    pub(super) fn eval(&self, v: ValId, out: &mut Vec<IlStmt>) {
        let span = self.spans[v];
        if let Some((op, neg)) = self.direct(v) {
            out.push(simple(Op::Ld, neg, Some(op), span));
            return;
        }
        match &self.vals[v] {
            Val::And(a, b) => {
                self.eval(*a, out);
                self.apply(Op::And, *b, out);
            }
            Val::Or(vs) => {
                self.eval(vs[0], out);
                for x in &vs[1..] {
                    self.apply(Op::Or, *x, out);
                }
            }
            Val::Not(a) => {
                self.eval(*a, out);
                out.push(simple(Op::Not, false, None, span));
            }
            Val::Const(_) | Val::Leaf { .. } => {}
        }
    }

    /// `AND x` / `ANDN x` / `AND( ... )`.
    pub(super) fn apply(&self, op: Op, v: ValId, out: &mut Vec<IlStmt>) {
        let span = self.spans[v];
        if let Some((operand, neg)) = self.direct(v) {
            out.push(simple(op, neg, Some(operand), span));
            return;
        }
        let mut body = Vec::new();
        self.eval(v, &mut body);
        // Hoist the nested list's first load onto the opening line: `AND( a` ... `)`.
        let mut operand = None;
        if let Some(IlStmt::Instr(Instruction {
            kind:
                InstrKind::Simple {
                    op: Op::Ld,
                    negate,
                    operand: Some(o),
                },
            span: s,
        })) = body.first()
        {
            let (negate, o, s) = (*negate, o.clone(), *s);
            body.remove(0);
            if negate {
                body.insert(0, simple(Op::Not, false, None, s));
            }
            operand = Some(o);
        }
        out.push(instr(
            InstrKind::Deferred {
                op,
                negate: false,
                operand: operand.map(Box::new),
                body,
                close: span,
            },
            span,
        ));
    }

    /// Emits one action (a label, an edge detector, a block call) where it runs.
    fn emit_action(&mut self, a: &Action, out: &mut Vec<IlStmt>) {
        match a {
            Action::Label(l) => out.push(IlStmt::Label(l.clone())),
            Action::Trig { inst, clk, span } => {
                let clk_op = self.operand(*clk, out);
                let inst = VarRef {
                    base: Ident::new(inst, *span),
                    accessors: Default::default(),
                    span: *span,
                };
                out.push(call(
                    Condition::Always,
                    inst,
                    vec![("CLK".into(), clk_op)],
                    *span,
                ));
            }
            Action::Fb {
                inst,
                args,
                en,
                en_arg,
                span,
            } => {
                let mut ops = Vec::new();
                if let (Some(e), true) = (en, en_arg) {
                    ops.push(("EN".to_string(), self.operand(*e, out)));
                }
                for (n, v) in args {
                    ops.push((n.name.clone(), self.operand(*v, out)));
                }
                let cond = match en {
                    Some(_) if *en_arg => Condition::Always,
                    Some(e) => {
                        self.prepare(*e, out);
                        self.eval(*e, out);
                        Condition::IfTrue
                    }
                    None => Condition::Always,
                };
                out.push(call(cond, inst.clone(), ops, *span));
            }
            Action::Func {
                name,
                form,
                args,
                en,
                result,
                initial,
                eno,
                skip_label,
                span,
            } => {
                let mut ops = Vec::new();
                for (n, v) in args {
                    ops.push((n.clone(), self.operand(*v, out)));
                }
                if let Some(init) = initial {
                    out.push(simple(Op::Ld, false, Some(init.clone()), *span));
                    out.push(simple(Op::St, false, Some(result.clone()), *span));
                }
                if let (Some(e), Some(_)) = (eno, en) {
                    // a call skipped by EN FALSE leaves ENO FALSE
                    out.push(simple(Op::Ld, false, Some(bool_lit(false, *span)), *span));
                    out.push(simple(Op::St, false, Some(e.clone()), *span));
                }
                self.skip_unless_en(*en, skip_label, *span, out);
                emit_function(name, form, ops, eno.as_ref(), *span, out);
                out.push(simple(Op::St, false, Some(result.clone()), *span));
                if en.is_some() {
                    out.push(IlStmt::Label(Ident::new(skip_label, *span)));
                }
            }
            Action::Execute {
                code,
                en,
                skip_label,
                span,
            } => {
                self.skip_unless_en(*en, skip_label, *span, out);
                out.extend(code.iter().cloned());
                if en.is_some() {
                    out.push(IlStmt::Label(Ident::new(skip_label, *span)));
                }
            }
        }
    }

    /// The values an action reads (its inputs, EN, an edge detector's CLK).
    fn action_reads(a: &Action) -> Vec<ValId> {
        match a {
            Action::Trig { clk, .. } => vec![*clk],
            Action::Fb { args, en, .. } | Action::Func { args, en, .. } => {
                args.iter().map(|(_, v)| *v).chain(*en).collect()
            }
            Action::Execute { en, .. } => en.iter().copied().collect(),
            Action::Label(_) => Vec::new(),
        }
    }

    pub(super) fn emit(&mut self, out: &mut Vec<IlStmt>) {
        self.count_uses();
        let groups = self.write_groups();
        let mut actions = std::mem::take(&mut self.actions);
        // The evaluation order: labels, then the boxes and edge detectors placed before the
        // network's first write (phase 1), then the writes, each box or edge detector placed after
        // a write running after it, before the next write (an action placed where a write is, an
        // edge coil's detector, runs before it), as Beremiz writes one statement per element in
        // that order (`PLCGenerator.py`); jumps and returns last.
        let first_write = groups.first().map(|(r, _)| self.writes[r.start].at);
        let deferred: Vec<bool> = actions
            .iter()
            .zip(&self.action_at)
            .map(|(a, &at)| !matches!(a, Action::Label(_)) && first_write.is_some_and(|q| at > q))
            .collect();
        let mut steps: Vec<Step> = Vec::with_capacity(groups.len());
        let mut later = (0..actions.len()).filter(|&k| deferred[k]).peekable();
        let first_deferred_at = later.peek().map(|&k| self.action_at[k]);
        for (gi, (r, _)) in groups.iter().enumerate() {
            let at = self.writes[r.start].at;
            while let Some(k) = later.next_if(|&k| self.action_at[k] <= at) {
                steps.push(Step::Act(k));
            }
            steps.push(Step::Group(gi));
        }
        steps.extend(later.map(Step::Act));
        // Phase 1: labels, and the actions before the first write.
        for (k, a) in actions.iter().enumerate() {
            if !deferred[k] {
                self.emit_action(a, out);
            }
        }
        // Who reads what, at which step (jumps and returns after the last).
        let mut action_reads: Vec<(ValId, usize)> = Vec::new();
        let mut group_step = vec![0; groups.len()];
        for (s, step) in steps.iter().enumerate() {
            match *step {
                Step::Group(gi) => group_step[gi] = s,
                Step::Act(k) => {
                    action_reads.extend(Self::action_reads(&actions[k]).iter().map(|&v| (v, s)))
                }
            }
        }
        let mut finals: Vec<(ValId, usize)> = groups
            .iter()
            .enumerate()
            .map(|(gi, (_, v))| (*v, group_step[gi]))
            .collect();
        for c in &self.controls {
            match c {
                Control::Jump(_, v, _) | Control::Return(v, _) => finals.push((*v, steps.len())),
            }
        }
        // A contact reads its variable where it stands in the network (`lower_reads`): a value
        // that reads what an earlier group wrote is evaluated where it is written.
        let times = self.read_times(&groups, &group_step, &finals, &action_reads);
        // Shared values and captured writes are evaluated before the first write, but for a value
        // placed after a deferred action (it may read the action's outputs): evaluated at its step.
        for (&(v, _), &late) in finals.iter().zip(&times.late) {
            if late || first_deferred_at.is_some_and(|a| self.pos[v] >= a) {
                continue;
            }
            self.prepare(v, out);
            if self.uses[v] > 1 && !self.is_trivial(v) {
                self.materialise(v, out);
            }
        }
        // Phase 2: write, with the actions placed between the writes.
        for step in &steps {
            let gi = match *step {
                Step::Act(k) => {
                    self.emit_action(&actions[k], out);
                    continue;
                }
                Step::Group(gi) => gi,
            };
            let (r, v) = &groups[gi];
            // a later step reads these contacts with the value before this write
            if let Some(captures) = times.captures.get(gi) {
                for &l in captures {
                    self.materialise(l, out);
                }
            }
            // a write of a function box's result under EN: skipped when the box did not run
            let guard = self.writes[r.start].guard.clone();
            let span = self.writes[r.start].span;
            if let Some((eno, label)) = &guard {
                self.eval(*eno, out);
                out.push(instr(
                    InstrKind::Jump {
                        cond: Condition::IfFalse,
                        label: Ident::new(label, span),
                    },
                    span,
                ));
            }
            self.prepare(*v, out);
            if self.uses[*v] > 1 && !self.is_trivial(*v) {
                self.materialise(*v, out);
            }
            self.eval(*v, out);
            for w in &self.writes[r.clone()] {
                let (op, neg) = match w.kind {
                    WriteKind::St { neg } => (Op::St, neg),
                    WriteKind::Set => (Op::S, false),
                    WriteKind::Reset => (Op::R, false),
                };
                out.push(simple(op, neg, Some(w.target.clone()), w.span));
            }
            if let Some((_, label)) = guard {
                out.push(IlStmt::Label(Ident::new(&label, span)));
            }
        }
        // Phase 3: jumps and returns.
        let controls = std::mem::take(&mut self.controls);
        for c in &controls {
            match c {
                Control::Jump(_, v, _) | Control::Return(v, _) => self.prepare(*v, out),
            }
        }
        self.controls = controls;
        for c in &self.controls {
            match c {
                Control::Jump(label, v, span) => {
                    let cond = self.cond(*v, out);
                    out.push(instr(
                        InstrKind::Jump {
                            cond,
                            label: label.clone(),
                        },
                        *span,
                    ));
                }
                Control::Return(v, span) => {
                    let cond = self.cond(*v, out);
                    out.push(instr(InstrKind::Return { cond }, *span));
                }
            }
        }
        // The list's room serves the next network.
        actions.clear();
        self.actions = actions;
    }

    pub(super) fn cond(&self, v: ValId, out: &mut Vec<IlStmt>) -> Condition {
        if matches!(self.vals[v], Val::Const(true)) && self.temps[v].is_none() {
            return Condition::Always;
        }
        self.eval(v, out);
        Condition::IfTrue
    }
}
