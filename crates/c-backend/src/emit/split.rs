//! Long POU bodies as several C functions (issue #12: `cc -O2` takes time that grows faster than linearly
//! in the size of one C function, mostly in RTL PRE, alias walking and liveness).
//!
//! Input: a POU's top-level IL statements and the sema model. Output: a [`Plan`] (where the parts start,
//! which labels are entered from another part) and, through [`Gen::emit_parts`], the part functions,
//! their frame struct and the body function that runs them. Invariants: a body of at most
//! [`Gen::part_limit`] instruction units is not split (its C is unchanged); parts are cut only between
//! top-level statements, never where the current result is a whole array; the current-result locals of
//! a part are loaded from the frame when it starts and stored back when it ends, so every value a later
//! part reads is the one the unsplit function would read; a jump to a label of another part returns the
//! label's number to the body function, which calls that part again with it (`switch (entry)` to the
//! label); `RET` returns -1. Planning and emission are linear in the body's size.

use super::body::Body;
use super::scope::Scope;
use super::Gen;
use il_frontend::ast::{CallArgs, IlStmt, InstrKind};
use il_frontend::sema::{InstrId, Type};
use std::collections::{BTreeMap, HashMap, HashSet};
use std::fmt::Write as _;

/// The default largest body (in instruction units, see [`weight`]) compiled as one C function; longer
/// bodies are cut into parts of about this size. Measured in `crates/c-backend/README.md`.
pub const DEFAULT_PART_LIMIT: usize = 1000;

/// The environment variable that overrides [`DEFAULT_PART_LIMIT`] (0: never split); for tests.
pub const PART_LIMIT_ENV: &str = "LADDERC_BODY_PART";

/// The part limit in effect: `$LADDERC_BODY_PART` when it is a number, else the default.
pub fn part_limit() -> usize {
    std::env::var(PART_LIMIT_ENV)
        .ok()
        .and_then(|s| s.trim().parse().ok())
        .unwrap_or(DEFAULT_PART_LIMIT)
}

/// Labels jumped to from another part: upper-case name -> (the label's part, its number, from 1).
pub type PartLabels = HashMap<String, (usize, u32)>;

/// Where a body is cut.
pub struct Plan {
    /// The index of the first top-level statement of each part (the first is 0).
    pub starts: Vec<usize>,
    /// Labels jumped to from another part.
    pub labels: PartLabels,
}

impl Plan {
    /// The part holding top-level statement `i`.
    fn part_of(&self, i: usize) -> usize {
        self.starts.partition_point(|&s| s <= i) - 1
    }
}

/// What a split body needs besides its statements.
pub struct Frame {
    /// The C name of the frame struct (`P_main_FRAME`).
    pub name: String,
    /// The prefix of the part functions' names (`P_main_BODY_PART_`); the part number follows.
    pub prefix: String,
    /// The first parameter of a part (`P_main *self, `), empty for a FUNCTION.
    pub self_param: String,
    /// The argument passed for it (`self, `), empty for a FUNCTION.
    pub self_arg: &'static str,
    /// Frame members: (declaration, name, whether it is copied from the body function's parameter of
    /// the same name; the others are initialised in the frame by the prelude).
    pub members: Vec<(String, String, bool)>,
    /// The statement that leaves the body function (`return;`, `return fr.v_f;`).
    pub leave: String,
}

/// An instruction's size for planning: 1, plus one per call argument, plus its nested list.
fn weight(stmt: &IlStmt) -> usize {
    // Most statements have no nested list: no stack for them.
    let mut n = 0;
    let mut stack = Vec::new();
    let mut next = Some(stmt);
    while let Some(s) = next.take().or_else(|| stack.pop()) {
        let IlStmt::Instr(i) = s else { continue };
        n += 1;
        let args = match &i.kind {
            InstrKind::Deferred { body, .. } => {
                stack.extend(body.iter());
                continue;
            }
            InstrKind::Call { args, .. } => args,
            InstrKind::FunctionCall { args, .. } => &**args,
            _ => continue,
        };
        n += match args {
            CallArgs::None => 0,
            CallArgs::NonFormal(a) => a.len(),
            CallArgs::Formal(a) => a.len(),
        }
    }
    n
}

/// The labels and jumps of top-level statement `stmt` (nested lists included), by top-level index.
fn labels_and_jumps<'a>(
    stmt: &'a IlStmt,
    labels: &mut Vec<String>,
    jumps: &mut Vec<&'a il_frontend::ast::Instruction>,
) {
    // Most statements have no nested list: no stack for them.
    let mut stack = Vec::new();
    let mut next = Some(stmt);
    while let Some(s) = next.take().or_else(|| stack.pop()) {
        match s {
            IlStmt::Label(l) => labels.push(l.key()),
            IlStmt::Instr(i) => match &i.kind {
                InstrKind::Deferred { body, .. } => stack.extend(body.iter()),
                InstrKind::Jump { .. } => jumps.push(i),
                _ => {}
            },
        }
    }
}

/// Adds 1 over the cuts that separate `a` and `b` (a cut at `c` separates them when `min < c <= max`).
fn cover(d: &mut [i32], a: usize, b: usize) {
    let (lo, hi) = (a.min(b), a.max(b));
    if lo < hi {
        d[lo + 1] += 1;
        d[hi + 1] -= 1;
    }
}

impl Gen<'_> {
    /// Where to cut `body` into parts of about `limit` instruction units (`None`: one function). A cut
    /// goes before a top-level instruction whose current result is not an array, at the first such
    /// place after `limit` units that no jump crosses, or after `2 * limit` units the first place no
    /// jump carrying an array crosses.
    pub(super) fn plan_parts(&self, body: &[IlStmt]) -> Option<Plan> {
        let limit = self.part_limit;
        if limit == 0 {
            return None;
        }
        // (per-statement tables of 4 bytes: a 1,000,000-statement body has 1,000,000 entries in each)
        let weights: Vec<u32> = body
            .iter()
            .map(|s| u32::try_from(weight(s)).unwrap_or(u32::MAX))
            .collect();
        if weights.iter().map(|&w| w as usize).sum::<usize>() <= limit {
            return None;
        }
        let n = body.len();
        let mut label_at: HashMap<String, usize> = HashMap::new();
        let mut jumps: Vec<(usize, String, bool)> = Vec::new();
        let mut cut_ok = vec![false; n + 1];
        let mut hint = 0;
        let is_array = |t: &Option<Type>| matches!(t, Some(Type::Array { .. }));
        let mut labels = Vec::new();
        let mut js = Vec::new();
        for (i, s) in body.iter().enumerate() {
            if let IlStmt::Instr(instr) = s {
                if let Some((at, info)) = self.model.instrs.get_near(InstrId::of(instr), hint) {
                    hint = at + 1;
                    cut_ok[i] = !is_array(&info.cr_before);
                }
            }
            labels.clear();
            js.clear();
            labels_and_jumps(s, &mut labels, &mut js);
            for l in labels.drain(..) {
                label_at.entry(l).or_insert(i);
            }
            for j in &js {
                let InstrKind::Jump { label, .. } = &j.kind else {
                    continue;
                };
                let array = self
                    .model
                    .instrs
                    .get_near(InstrId::of(j), hint)
                    .is_some_and(|(_, x)| is_array(&x.cr_before));
                jumps.push((i, label.key(), array));
            }
        }
        // soft: cuts some jump crosses; hard: cuts a jump carrying a whole array crosses
        let mut soft = vec![0i32; n + 2];
        let mut hard = vec![0i32; n + 2];
        for (at, key, array) in &jumps {
            if let Some(&l) = label_at.get(key) {
                cover(&mut soft, *at, l);
                if *array {
                    cover(&mut hard, *at, l);
                }
            }
        }
        let mut starts = vec![0];
        let (mut acc, mut s, mut h) = (0usize, 0i32, 0i32);
        for i in 1..n {
            acc += weights[i - 1] as usize;
            s += soft[i];
            h += hard[i];
            if acc >= limit && cut_ok[i] && h == 0 && (s == 0 || acc >= 2 * limit) {
                starts.push(i);
                acc = 0;
            }
        }
        if starts.len() < 2 {
            return None;
        }
        let mut plan = Plan {
            starts,
            labels: HashMap::new(),
        };
        let mut next = 0u32;
        for (at, key, _) in jumps {
            let Some(&l) = label_at.get(&key) else {
                continue;
            };
            let part = plan.part_of(l);
            if plan.part_of(at) != part && !plan.labels.contains_key(&key) {
                next += 1;
                plan.labels.insert(key, (part, next));
            }
        }
        Some(plan)
    }

    /// Writes a split body: the frame struct, one function per part, then the body function: `head`
    /// (its signature line), the zeroed frame `fr`, `prelude` (the code that initialises the locals in
    /// the frame), the copies of the parameters into the frame, and the calls of the parts.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn emit_parts(
        &mut self,
        c: &mut String,
        head: &str,
        prelude: &str,
        scope: &Scope,
        targets: HashSet<String>,
        body: &[IlStmt],
        plan: &Plan,
        frame: &Frame,
        reserve: usize,
    ) {
        let mut targets = targets;
        let nparts = plan.starts.len();
        let fname = &frame.name;
        let mut entries: Vec<Vec<(u32, &str)>> = vec![Vec::new(); nparts];
        for (key, (part, id)) in &plan.labels {
            entries[*part].push((*id, key.as_str()));
        }
        // Each part is written to `c` as soon as it is generated, so the body's C is never held twice
        // (43 MB for a 1,000,000-line POU); the frame struct, which needs every part's locals, is
        // inserted before the parts afterwards. A local carried in the frame is known when the first
        // part that declares it is written: its frame member is that part's declaration.
        let at = c.len();
        let mut carried: BTreeMap<String, String> = BTreeMap::new();
        let mut out = String::with_capacity(reserve);
        for (k, &start) in plan.starts.iter().enumerate() {
            let end = plan.starts.get(k + 1).copied().unwrap_or(body.len());
            let mut b = Body::new(scope, 1, "-1".to_string());
            out.clear();
            b.out = std::mem::take(&mut out);
            b.targets = std::mem::take(&mut targets);
            b.part = Some((k, &plan.labels));
            self.stmts(&mut b, &body[start..end]);
            targets = std::mem::take(&mut b.targets);
            for (name, decl) in &b.crs {
                if !name.starts_with("cr_array_") {
                    let d = decl.split(" = ").next().unwrap_or(decl);
                    carried.entry(name.clone()).or_insert_with(|| d.to_string());
                }
            }
            let _ = writeln!(
                c,
                "static int {}{}({}{fname} *fr, int entry) {{",
                frame.prefix,
                k + 1,
                frame.self_param
            );
            for (name, decl) in &b.crs {
                match carried.get(name) {
                    Some(d) => {
                        let _ = writeln!(c, "    {d} = fr->{name};");
                    }
                    None => {
                        let _ = writeln!(c, "    {decl}");
                    }
                }
            }
            for name in b.crs.keys() {
                let _ = writeln!(c, "    (void){name};");
            }
            if b.exits {
                c.push_str("    int next_ = 0;\n");
            }
            if !frame.self_arg.is_empty() {
                c.push_str("    (void)self;\n");
            }
            c.push_str("    (void)fr;\n    (void)entry;\n");
            let entry = &mut entries[k];
            if !entry.is_empty() {
                entry.sort_unstable();
                c.push_str("    switch (entry) {\n");
                for (id, key) in entry.iter() {
                    let _ = writeln!(c, "    case {id}: goto {};", crate::mangle::label(key));
                }
                c.push_str("    default: break;\n    }\n");
            }
            c.push_str(&b.out);
            if b.exits {
                c.push_str("exit_:\n");
            }
            for name in b.crs.keys().filter(|n| carried.contains_key(*n)) {
                let _ = writeln!(c, "    fr->{name} = {name};");
            }
            c.push_str(if b.exits {
                "    return next_;\n}\n\n"
            } else {
                "    return 0;\n}\n\n"
            });
            out = std::mem::take(&mut b.out);
        }
        let mut st = String::new();
        st.push_str("typedef struct {\n");
        for (decl, _, _) in &frame.members {
            let _ = writeln!(st, "    {decl};");
        }
        if scope.uses_en.get() {
            st.push_str("    IEC_BOOL v_en;\n    IEC_BOOL v_eno;\n");
        }
        for d in carried.values() {
            let _ = writeln!(st, "    {d};");
        }
        if frame.members.is_empty() && carried.is_empty() && !scope.uses_en.get() {
            st.push_str("    char unused_;\n");
        }
        let _ = writeln!(st, "}} {fname};\n");
        c.insert_str(at, &st);
        c.push_str(head);
        let _ = writeln!(c, "    {fname} fr;\n    memset(&fr, 0, sizeof fr);");
        c.push_str(prelude);
        for (_, name, _) in frame.members.iter().filter(|m| m.2) {
            let _ = writeln!(c, "    memcpy(&fr.{name}, &{name}, sizeof fr.{name});");
        }
        if scope.uses_en.get() {
            c.push_str("    fr.v_en = 1;\n    fr.v_eno = 1;\n");
        }
        if !frame.self_arg.is_empty() {
            c.push_str("    (void)self;\n");
        }
        let (prefix, arg, leave) = (&frame.prefix, frame.self_arg, &frame.leave);
        if plan.labels.is_empty() {
            for k in 1..=nparts {
                let _ = writeln!(c, "    if ({prefix}{k}({arg}&fr, 0) < 0) {leave}");
            }
        } else {
            c.push_str("    {\n        int part_ = 1, entry_ = 0;\n        for (;;) {\n");
            c.push_str("            int next_;\n            switch (part_) {\n");
            for k in 1..=nparts {
                let _ = writeln!(
                    c,
                    "            case {k}: next_ = {prefix}{k}({arg}&fr, entry_); break;"
                );
            }
            c.push_str("            default: next_ = -1; break;\n            }\n");
            c.push_str("            if (next_ < 0) break;\n            entry_ = next_;\n");
            c.push_str("            if (next_ == 0) { part_++; continue; }\n");
            c.push_str("            switch (next_) {\n");
            let mut ids: Vec<(u32, usize)> = plan.labels.values().map(|&(p, id)| (id, p)).collect();
            ids.sort_unstable();
            for (id, p) in ids {
                let _ = writeln!(c, "            case {id}: part_ = {}; break;", p + 1);
            }
            c.push_str("            default: break;\n            }\n        }\n    }\n");
        }
        let _ = writeln!(c, "    {leave}\n}}\n");
    }
}
