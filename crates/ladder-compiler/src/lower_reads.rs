//! When a contact reads its variable, for [`super`]: in the network's evaluation order, the place of
//! the element, so a contact below (after) a coil of the same network reads what that coil wrote and
//! a contact before it (a feedback, like a seal-in contact) the value from before the coil.
//!
//! IEC 61131-3 (the graphic languages' "Evaluation of networks", ed. 2 4.1.3) evaluates an element once all of
//! its inputs are evaluated; a variable a later element writes and an earlier one reads is a feedback
//! variable, read with the value it had before. ladderc's evaluation order is the data flow, ties
//! broken top to bottom, then left to right (`lower_order`), Beremiz's and OpenPLC Editor's
//! (`PLCGenerator.py`: the coils and output variables sorted by position, `SortInstances`, one
//! statement each, reading its contacts' variables there). Before round 30 every contact of a network
//! read the value from before the network, so two rungs sharing one contact (one network) behaved
//! otherwise than the same rungs drawn with a contact each (two networks):
//! `tests/tests/ld_r30_run.rs`.
//!
//! Round 31 put function and block boxes and edge contacts (P/N) in the same order: one placed after
//! a coil runs after it (`lower_emit`), reading what the coil wrote (`tests/tests/ld_r31_run.rs`).
//!
//! Input: the network's values with [`NetLowering::pos`], its writes in order ([`Write::at`]) grouped
//! by [`NetLowering::write_groups`], each group at its step of phase 2 (boxes and edge detectors
//! placed after the first write are steps too), its jumps and returns, and the inputs of those boxes
//! and edge detectors with their steps. Output: [`ReadTimes`]: for each group, the contacts to store
//! in a temporary just before it writes (a later step reads them with the value before that write),
//! and which written values are evaluated only where they are written (they read a variable an
//! earlier group wrote). Invariants: walks each value once per reader (no recursion: an explicit
//! stack), stops at values already stored.

use super::*;

/// What [`NetLowering::read_times`] decides for one network.
pub(super) struct ReadTimes {
    /// Per write group (then one slot for the jumps and returns): the contacts to capture before it.
    pub(super) captures: Vec<Vec<ValId>>,
    /// Per final value (write groups, then jumps and returns): it reads what an earlier step wrote,
    /// so it is evaluated where it is used, not before the first write.
    pub(super) late: Vec<bool>,
}

impl NetLowering<'_, '_> {
    /// The variable (base name or address key) a leaf value reads.
    fn leaf_key(&self, v: ValId) -> Option<String> {
        match &self.vals[v] {
            Val::Leaf {
                op: op @ (Operand::Var(_) | Operand::Address(_)),
                ..
            } => Some(target_key(op)),
            _ => None,
        }
    }

    /// The leaves `v` reads, not through values already stored in temporaries.
    fn leaves(&self, v: ValId, seen: &mut HashSet<ValId>, acc: &mut Vec<ValId>) {
        let mut stack = vec![v];
        while let Some(x) = stack.pop() {
            if self.temps[x].is_some() || !seen.insert(x) {
                continue;
            }
            match &self.vals[x] {
                Val::Leaf { .. } => acc.push(x),
                Val::Const(_) => {}
                _ => stack.extend(self.children(x)),
            }
        }
    }

    /// `groups`: the write groups, each emitted at step `group_step[gi]`; `finals`: the values of
    /// the write groups, then those of the jumps and returns, each with the step where it is used
    /// (jumps and returns after every step); `action_reads`: the inputs of the boxes and edge
    /// detectors placed after the first write, each with its step.
    pub(super) fn read_times(
        &self,
        groups: &[(std::ops::Range<usize>, ValId)],
        group_step: &[usize],
        finals: &[(ValId, usize)],
        action_reads: &[(ValId, usize)],
    ) -> ReadTimes {
        let mut times = ReadTimes {
            captures: vec![Vec::new(); groups.len() + 1],
            late: vec![false; finals.len()],
        };
        // (step, place) of each write, per variable written
        let mut written: HashMap<String, Vec<(usize, usize)>> = HashMap::default();
        for (gi, (r, _)) in groups.iter().enumerate() {
            for w in &self.writes[r.clone()] {
                written
                    .entry(target_key(&w.target))
                    .or_default()
                    .push((group_step[gi], w.at));
            }
        }
        if groups.is_empty() || finals.len() + action_reads.len() <= 1 {
            // the usual one-coil rung: its own value is read before it writes
            return times;
        }
        // the last step reading each leaf
        let mut last_use: HashMap<ValId, usize> = HashMap::default();
        let readers = finals
            .iter()
            .enumerate()
            .map(|(fi, &(v, s))| (v, s, Some(fi)))
            .chain(action_reads.iter().map(|&(v, s)| (v, s, None)));
        for (v, step, fi) in readers {
            let mut seen = HashSet::default();
            let mut acc = Vec::new();
            self.leaves(v, &mut seen, &mut acc);
            for l in acc {
                let Some(ws) = self.leaf_key(l).and_then(|k| written.get(&k)) else {
                    continue;
                };
                // a write placed before the contact, by an earlier step: read after it
                if let Some(fi) = fi {
                    if ws.iter().any(|&(s, at)| s < step && at < self.pos[l]) {
                        times.late[fi] = true;
                    }
                }
                let last = last_use.entry(l).or_insert(step);
                *last = (*last).max(step);
            }
        }
        let mut captured: Vec<(usize, ValId)> = Vec::new();
        for (&l, &user) in &last_use {
            let Some(ws) = self.leaf_key(l).and_then(|k| written.get(&k)) else {
                continue;
            };
            // the first write placed after the contact: a step after it reads the value before it
            if let Some(s) = ws
                .iter()
                .filter(|&&(_, at)| at > self.pos[l])
                .map(|&(s, _)| s)
                .min()
            {
                if s < user {
                    if let Ok(g) = group_step.binary_search(&s) {
                        captured.push((g, l));
                    }
                }
            }
        }
        // in the order the contacts were made, whatever the map's order
        captured.sort_unstable();
        for (g, l) in captured {
            times.captures[g].push(l);
        }
        times
    }
}
