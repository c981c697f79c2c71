//! Command handles: how a block follows the command it gave to the engine.
//!
//! Input: commands accepted by the engine. Output: a [`CmdId`] per command and its
//! [`CmdStatus`] as the engine advances it (Queued -> Active -> Done / Aborted / Error).
//! Invariants: a slot is reused only after its owner released it ([`CmdTable::release`]);
//! ids carry a generation, so a stale id never reads another command's status (it reads
//! `CmdStatus::Unknown`).

use crate::error::ErrorId;

/// Handle of one command in the engine.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CmdId {
    pub(crate) index: u32,
    pub(crate) gen: u32,
}

/// Life of a command.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum CmdStatus {
    /// Stale or released id.
    #[default]
    Unknown,
    /// Waiting in the buffer for its predecessor's release.
    Queued,
    /// Controls the axis (or group).
    Active,
    /// Completed (for Stop: stopped; the axis stays Stopping until the block's Execute falls).
    Done,
    /// Interrupted by another command or by power-off.
    Aborted,
    /// Failed with this ErrorID.
    Error(ErrorId),
}

impl CmdStatus {
    /// True for Done, Aborted and Error.
    pub fn is_final(self) -> bool {
        matches!(
            self,
            CmdStatus::Done | CmdStatus::Aborted | CmdStatus::Error(_)
        )
    }
}

#[derive(Clone, Copy, Debug, Default)]
struct Slot {
    gen: u32,
    live: bool,
    status: CmdStatus,
    /// InVelocity / InGear / InSync on the set value.
    in_target: bool,
    /// EndOfProfile pulse of a cam.
    end_of_profile: bool,
}

/// The slots of every live command.
#[derive(Clone, Debug, Default)]
pub struct CmdTable {
    slots: Vec<Slot>,
    free: Vec<u32>,
}

impl CmdTable {
    /// A table with room for `n` commands before it grows.
    pub fn with_capacity(n: usize) -> CmdTable {
        CmdTable {
            slots: Vec::with_capacity(n),
            free: Vec::with_capacity(n),
        }
    }

    /// A new command in state `status`.
    pub fn alloc(&mut self, status: CmdStatus) -> CmdId {
        let index = match self.free.pop() {
            Some(i) => i,
            None => {
                self.slots.push(Slot::default());
                (self.slots.len() - 1) as u32
            }
        };
        let s = &mut self.slots[index as usize];
        s.gen = s.gen.wrapping_add(1);
        s.live = true;
        s.status = status;
        s.in_target = false;
        s.end_of_profile = false;
        CmdId { index, gen: s.gen }
    }

    fn slot(&self, id: CmdId) -> Option<&Slot> {
        self.slots
            .get(id.index as usize)
            .filter(|s| s.live && s.gen == id.gen)
    }

    fn slot_mut(&mut self, id: CmdId) -> Option<&mut Slot> {
        self.slots
            .get_mut(id.index as usize)
            .filter(|s| s.live && s.gen == id.gen)
    }

    /// Status of command `id` ([`CmdStatus::Unknown`] for a released or stale id).
    pub fn status(&self, id: CmdId) -> CmdStatus {
        self.slot(id).map(|s| s.status).unwrap_or_default()
    }

    /// Sets the status of `id` (a released or stale id is ignored).
    pub fn set(&mut self, id: CmdId, status: CmdStatus) {
        if let Some(s) = self.slot_mut(id) {
            s.status = status;
        }
    }

    /// InVelocity / InGear / InSync of `id`: the set value reached the command's target.
    pub fn in_target(&self, id: CmdId) -> bool {
        self.slot(id).is_some_and(|s| s.in_target)
    }

    /// Sets or clears the in-target flag of `id` (ignored for a stale id).
    pub fn set_in_target(&mut self, id: CmdId, on: bool) {
        if let Some(s) = self.slot_mut(id) {
            s.in_target = on;
        }
    }

    /// EndOfProfile of a cam command `id`: TRUE in the cycle the master passed the table's end.
    pub fn end_of_profile(&self, id: CmdId) -> bool {
        self.slot(id).is_some_and(|s| s.end_of_profile)
    }

    /// Sets or clears the EndOfProfile flag of `id` (ignored for a stale id).
    pub fn set_end_of_profile(&mut self, id: CmdId, on: bool) {
        if let Some(s) = self.slot_mut(id) {
            s.end_of_profile = on;
        }
    }

    /// Frees the slot (the owner has seen the final status).
    pub fn release(&mut self, id: CmdId) {
        if let Some(s) = self.slot_mut(id) {
            s.live = false;
            s.status = CmdStatus::Unknown;
            self.free.push(id.index);
        }
    }

    /// Number of live commands.
    pub fn live(&self) -> usize {
        self.slots.len() - self.free.len()
    }
}
