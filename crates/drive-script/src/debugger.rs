//! Breakpoint list of the debugger: 4 user breakpoints plus 1 temporary breakpoint for single step.
//!
//! Input: add/delete/enable requests (from the terminal debugger or a test) and the interpreter's current
//! point. Output: whether the interpreter must stop at that point. Invariants: at most
//! [`USER_BREAKPOINTS`] user entries (a fifth is refused with [`BreakpointError::Full`]); the temporary entry
//! is armed by `step`/`pause` only and disarms itself when it stops the interpreter.

use crate::limits::USER_BREAKPOINTS;
use std::fmt;

/// Which half of an Event a point is in front of.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Phase {
    /// Before the IF: the conditions have not been evaluated yet.
    BeforeIf,
    /// Before the THEN: the IF held and the actions have not run yet.
    BeforeThen,
}

/// A point of the script: before the IF or before the THEN of an Event of a Motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Location {
    /// Motion number (MOTION m).
    pub motion: u16,
    /// Event number within the Motion (EVENT e).
    pub event: u16,
    /// Before the IF or before the THEN.
    pub phase: Phase,
}

impl Location {
    /// Where execution starts: Motion 0, Event 0, before the IF.
    pub const START: Location = Location {
        motion: 0,
        event: 0,
        phase: Phase::BeforeIf,
    };
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let p = match self.phase {
            Phase::BeforeIf => "IF",
            Phase::BeforeThen => "THEN",
        };
        write!(f, "Motion {} Event {} before {p}", self.motion, self.event)
    }
}

/// One list entry.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Breakpoint {
    /// The point the interpreter stops in front of.
    pub at: Location,
    /// A disabled entry keeps its number but never stops the interpreter.
    pub enabled: bool,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
/// Why a breakpoint request was refused.
pub enum BreakpointError {
    /// All user entries are in use.
    Full,
    /// No user breakpoint with this number.
    NoSuchBreakpoint(usize),
    /// The location is not a point of the program.
    NoSuchLocation(Location),
}

impl fmt::Display for BreakpointError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BreakpointError::Full => write!(
                f,
                "all {USER_BREAKPOINTS} breakpoints are in use (the fifth entry is reserved for single step): delete one first"
            ),
            BreakpointError::NoSuchBreakpoint(n) => write!(f, "no breakpoint number {n}"),
            BreakpointError::NoSuchLocation(l) => write!(f, "the script has no {l}"),
        }
    }
}

impl std::error::Error for BreakpointError {}

/// The five-entry list: 4 user entries and the temporary single-step entry.
#[derive(Debug, Clone, Default)]
pub struct Breakpoints {
    user: [Option<Breakpoint>; USER_BREAKPOINTS],
    /// The temporary entry: armed by step/pause, it stops at the next point reached.
    temp_armed: bool,
    /// Cached: is any entry able to stop the interpreter (keeps the hot path to one test).
    active: bool,
}

impl Breakpoints {
    fn refresh(&mut self) {
        self.active = self.temp_armed || self.user.iter().flatten().any(|b| b.enabled);
    }

    /// Adds an enabled breakpoint; returns its number (0..4). Adding an existing location returns its number.
    pub(crate) fn add(&mut self, at: Location) -> Result<usize, BreakpointError> {
        if let Some(i) = self.user.iter().position(|b| b.map(|b| b.at) == Some(at)) {
            if let Some(b) = self.user[i].as_mut() {
                b.enabled = true;
            }
            self.refresh();
            return Ok(i);
        }
        let slot = self
            .user
            .iter()
            .position(|b| b.is_none())
            .ok_or(BreakpointError::Full)?;
        self.user[slot] = Some(Breakpoint { at, enabled: true });
        self.refresh();
        Ok(slot)
    }

    /// Frees user entry `n` (its number may be reused by `add`); `NoSuchBreakpoint` if it is free or out of
    /// range.
    pub fn delete(&mut self, n: usize) -> Result<(), BreakpointError> {
        match self.user.get_mut(n) {
            Some(b @ Some(_)) => {
                *b = None;
                self.refresh();
                Ok(())
            }
            _ => Err(BreakpointError::NoSuchBreakpoint(n)),
        }
    }

    /// Enables or disables user entry `n`; `NoSuchBreakpoint` if it is free or out of range.
    pub fn set_enabled(&mut self, n: usize, enabled: bool) -> Result<(), BreakpointError> {
        match self.user.get_mut(n) {
            Some(Some(b)) => {
                b.enabled = enabled;
                self.refresh();
                Ok(())
            }
            _ => Err(BreakpointError::NoSuchBreakpoint(n)),
        }
    }

    /// The user entries by number (`None` = free).
    pub fn list(&self) -> &[Option<Breakpoint>; USER_BREAKPOINTS] {
        &self.user
    }

    /// True while the temporary entry (single step, pause) is armed: the interpreter stops at the next point
    /// it reaches.
    pub fn temp_armed(&self) -> bool {
        self.temp_armed
    }

    pub(crate) fn arm_temp(&mut self) {
        self.temp_armed = true;
        self.active = true;
    }

    pub(crate) fn disarm_temp(&mut self) {
        self.temp_armed = false;
        self.refresh();
    }

    #[inline]
    pub(crate) fn active(&self) -> bool {
        self.active
    }

    /// Must the interpreter stop at `at`? Disarms the temporary entry when it is the reason.
    pub(crate) fn hit(&mut self, at: Location) -> bool {
        if self.temp_armed {
            self.disarm_temp();
            return true;
        }
        self.user.iter().flatten().any(|b| b.enabled && b.at == at)
    }
}
