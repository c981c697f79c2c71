//! The drive-side interpreter: runs a [`Program`] one bounded slice per main-loop call.
//!
//! Input: a validated program and, at every [`Interpreter::cycle`] call, the [`Drive`]. Output: drive
//! commands, MD/DO writes, and a [`CycleResult`] saying why the slice ended.
//! Invariants: execution starts at Motion 0, Event 0; a Motion pass starts when Event 0 of a Motion is reached
//! by wrap-around, by `NextMotionID` or at start, and its first IF evaluation takes a [`Snapshot`] of the drive
//! that every read of drive values in the pass uses; a slice evaluates at most `EventsPerCycle` IFs and ends
//! at the end of a pass or on `NextMotionID`, so it never blocks; while stopped at a breakpoint nothing of the
//! script runs, and resuming continues exactly at the stopped point (a stop before THEN runs that THEN
//! without evaluating the IF again). 32-bit arithmetic wraps; `/` and `%` by zero give 0 and set `MathError`.

use crate::debugger::{BreakpointError, Breakpoints, Location, Phase};
use crate::drive::{Drive, MotionState};
use crate::limits::*;
use crate::program::*;

/// The drive values a Motion pass sees, taken at the start of the pass.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Snapshot {
    /// `ActualPosition`, pulses.
    pub position: i32,
    /// `ActualVelocity`, pulses/s.
    pub velocity: i32,
    /// `ActualCurrent`, mA.
    pub current: i32,
    /// Digital inputs, bit n = `DI_n`.
    pub inputs: u32,
    /// Bit n = `TimerDone_n`.
    pub timer_done: u8,
    /// `MotionState` (and `MotionDone` = Standstill).
    pub motion_state: MotionState,
    /// `Homed`.
    pub homed: bool,
}

/// Why a [`Interpreter::cycle`] call returned.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CycleResult {
    /// The Events-per-cycle budget is used up; the pass continues next call.
    Budget,
    /// The last Event of the Motion was done; the next call starts a new pass (new snapshot).
    EndOfPass,
    /// `NextMotionID` switched Motion; the next call starts its first pass.
    MotionChanged(u16),
    /// Stopped at this point (breakpoint, step or pause); nothing runs until `resume`/`step`.
    Stopped(Location),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
struct Timer {
    armed: bool,
    deadline: u32,
}

/// What conditions and actions read and write (kept apart from the program so both can be borrowed).
#[derive(Debug, Clone)]
struct Registers {
    params: [i32; PARAMS],
    memory: [i32; MEMORY_WORDS],
    math_error: bool,
    timers: [Timer; TIMERS],
    snapshot: Snapshot,
}

/// The interpreter state of one drive.
#[derive(Debug, Clone)]
pub struct Interpreter {
    program: Program,
    r: Registers,
    at: Location,
    pass_pending: bool,
    started: bool,
    breakpoints: Breakpoints,
    stopped: bool,
    /// Resuming from a stop: do not stop again at the same point before running it.
    skip_stop_once: bool,
    events_evaluated: u64,
}

enum Next {
    Motion(u16),
    Event(u16),
}

impl Interpreter {
    /// A fresh interpreter at Motion 0, Event 0 with parameters at their defaults and MD words at their
    /// initial values. Fails on a program that breaks the pool invariants.
    pub fn new(program: Program) -> Result<Interpreter, String> {
        program.validate()?;
        Ok(Interpreter {
            r: Registers {
                params: program.params,
                memory: program.init,
                math_error: false,
                timers: [Timer::default(); TIMERS],
                snapshot: Snapshot::default(),
            },
            program,
            at: Location::START,
            pass_pending: true,
            started: false,
            breakpoints: Breakpoints::default(),
            stopped: false,
            skip_stop_once: false,
            events_evaluated: 0,
        })
    }

    /// The program being run.
    pub fn program(&self) -> &Program {
        &self.program
    }
    /// The next point to run (or the point stopped at).
    pub fn location(&self) -> Location {
        self.at
    }
    /// True while stopped at a breakpoint, step or pause (nothing of the script runs until `resume` or
    /// `step`).
    pub fn is_stopped(&self) -> bool {
        self.stopped
    }
    /// The drive values of the current Motion pass (taken at its first IF).
    pub fn snapshot(&self) -> &Snapshot {
        &self.r.snapshot
    }
    /// IF evaluations so far (each counts against `EventsPerCycle` in its slice).
    pub fn events_evaluated(&self) -> u64 {
        self.events_evaluated
    }
    /// The sticky `MathError` flag: a `/` or `%` by zero happened since it was last cleared.
    pub fn math_error(&self) -> bool {
        self.r.math_error
    }
    /// Parameter `P<i>`; None past `P15`.
    pub fn param(&self, i: usize) -> Option<i32> {
        self.r.params.get(i).copied()
    }
    /// Memory word `MD<i>`; None past `MD49`.
    pub fn memory(&self, i: usize) -> Option<i32> {
        self.r.memory.get(i).copied()
    }
    /// All parameters `P0..P15`.
    pub fn params(&self) -> &[i32; PARAMS] {
        &self.r.params
    }
    /// All memory words `MD0..MD49`.
    pub fn memory_words(&self) -> &[i32; MEMORY_WORDS] {
        &self.r.memory
    }
    /// Writes a parameter (the PC or the debugger); false if the index is out of range.
    pub fn set_param(&mut self, i: usize, v: i32) -> bool {
        self.r.params.get_mut(i).map(|p| *p = v).is_some()
    }
    /// Writes a memory word (the debugger); false if the index is out of range.
    pub fn set_memory(&mut self, i: usize, v: i32) -> bool {
        self.r.memory.get_mut(i).map(|p| *p = v).is_some()
    }

    /// The debugger's breakpoint list.
    pub fn breakpoints(&self) -> &Breakpoints {
        &self.breakpoints
    }
    /// Adds a user breakpoint at a point of the program; the fifth is refused.
    pub fn add_breakpoint(&mut self, at: Location) -> Result<usize, BreakpointError> {
        if self
            .program
            .event(at.motion as usize, at.event as usize)
            .is_none()
        {
            return Err(BreakpointError::NoSuchLocation(at));
        }
        self.breakpoints.add(at)
    }
    /// Deletes user breakpoint `n`.
    pub fn delete_breakpoint(&mut self, n: usize) -> Result<(), BreakpointError> {
        self.breakpoints.delete(n)
    }
    /// Enables or disables user breakpoint `n` (it keeps its number).
    pub fn enable_breakpoint(&mut self, n: usize, enabled: bool) -> Result<(), BreakpointError> {
        self.breakpoints.set_enabled(n, enabled)
    }
    /// Leaves a stop: the next `cycle` continues exactly at the stopped point.
    pub fn resume(&mut self) {
        if self.stopped {
            self.stopped = false;
            self.skip_stop_once = true;
        }
    }
    /// Single step: arms the temporary breakpoint and resumes, so the interpreter runs the current point
    /// (IF or THEN) and stops at the next point it reaches.
    pub fn step(&mut self) {
        self.breakpoints.arm_temp();
        self.resume();
    }
    /// Stops at the next point reached (no effect while already stopped).
    pub fn pause(&mut self) {
        if !self.stopped {
            self.breakpoints.arm_temp();
        }
    }

    fn start(&mut self, drive: &mut (impl Drive + ?Sized)) {
        let s = self.program.settings;
        drive.set_velocity(s.velocity);
        drive.set_acceleration(s.acceleration);
        drive.set_deceleration(s.deceleration);
        drive.set_jog_velocity(s.jog_velocity);
        self.started = true;
    }

    fn take_snapshot(&mut self, drive: &(impl Drive + ?Sized)) {
        let now = drive.now_ms();
        let mut done = 0u8;
        for (i, t) in self.r.timers.iter().enumerate() {
            if t.armed && (now.wrapping_sub(t.deadline) as i32) >= 0 {
                done |= 1 << i;
            }
        }
        self.r.snapshot = Snapshot {
            position: drive.actual_position(),
            velocity: drive.actual_velocity(),
            current: drive.actual_current(),
            inputs: drive.digital_inputs(),
            timer_done: done,
            motion_state: drive.motion_state(),
            homed: drive.homed(),
        };
    }

    /// One main-loop call: runs at most `EventsPerCycle` Events, never blocks.
    pub fn cycle(&mut self, drive: &mut (impl Drive + ?Sized)) -> CycleResult {
        if !self.started {
            self.start(drive);
        }
        if self.stopped {
            return CycleResult::Stopped(self.at);
        }
        let mut budget = self.program.settings.events_per_cycle;
        loop {
            if self.breakpoints.active() && !self.skip_stop_once && self.breakpoints.hit(self.at) {
                self.stopped = true;
                return CycleResult::Stopped(self.at);
            }
            self.skip_stop_once = false;
            let motion = self.program.motions[self.at.motion as usize];
            let idx = motion.first_event as usize + self.at.event as usize;
            match self.at.phase {
                Phase::BeforeIf => {
                    if budget == 0 {
                        return CycleResult::Budget;
                    }
                    budget -= 1;
                    if self.pass_pending {
                        self.take_snapshot(drive);
                        self.pass_pending = false;
                    }
                    self.events_evaluated += 1;
                    let ev = &self.program.events[idx];
                    let mut holds = true;
                    for c in &ev.conditions[..ev.cond_count as usize] {
                        if !self.r.condition(c, drive) {
                            holds = false;
                            break;
                        }
                    }
                    if holds {
                        self.at.phase = Phase::BeforeThen;
                    } else if let Some(r) = self.advance(motion) {
                        return r;
                    }
                }
                Phase::BeforeThen => {
                    let ev = &self.program.events[idx];
                    let mut next = None;
                    for a in &ev.actions[..ev.act_count as usize] {
                        if let Some(n) = self.r.action(a, drive) {
                            next = Some(n);
                        }
                    }
                    match next {
                        Some(Next::Motion(m)) => {
                            self.at = Location {
                                motion: m,
                                event: 0,
                                phase: Phase::BeforeIf,
                            };
                            self.pass_pending = true;
                            return CycleResult::MotionChanged(m);
                        }
                        Some(Next::Event(e)) => {
                            self.at.event = e;
                            self.at.phase = Phase::BeforeIf;
                        }
                        None => {
                            if let Some(r) = self.advance(motion) {
                                return r;
                            }
                        }
                    }
                }
            }
        }
    }

    /// Moves to the next Event's IF; at the end of the Motion wraps to Event 0 and ends the slice.
    #[inline]
    fn advance(&mut self, motion: Motion) -> Option<CycleResult> {
        self.at.phase = Phase::BeforeIf;
        if self.at.event + 1 >= motion.event_count {
            self.at.event = 0;
            self.pass_pending = true;
            Some(CycleResult::EndOfPass)
        } else {
            self.at.event += 1;
            None
        }
    }
}

impl Registers {
    #[inline]
    fn read(&self, o: &Operand, drive: &(impl Drive + ?Sized)) -> i32 {
        let i = o.arg as usize;
        let bit = |word: u32| ((word >> (i & 31)) & 1) as i32;
        match o.source {
            Source::Const => o.arg,
            Source::Param => self.params.get(i).copied().unwrap_or(0),
            Source::Mem => self.memory.get(i).copied().unwrap_or(0),
            Source::DigitalIn => bit(self.snapshot.inputs),
            Source::DigitalOut => bit(drive.digital_outputs()),
            Source::ActualPosition => self.snapshot.position,
            Source::ActualVelocity => self.snapshot.velocity,
            Source::ActualCurrent => self.snapshot.current,
            Source::TimerDone => bit(self.snapshot.timer_done as u32),
            Source::MotionState => self.snapshot.motion_state as i32,
            Source::MotionDone => (self.snapshot.motion_state == MotionState::Standstill) as i32,
            Source::Homed => self.snapshot.homed as i32,
            Source::MathError => self.math_error as i32,
        }
    }

    #[inline]
    fn value(&mut self, v: &Value, drive: &(impl Drive + ?Sized)) -> i32 {
        let a = self.read(&v.a, drive);
        if v.op == ArithOp::None {
            return a;
        }
        let b = self.read(&v.b, drive);
        match v.op {
            ArithOp::None => a,
            ArithOp::Add => a.wrapping_add(b),
            ArithOp::Sub => a.wrapping_sub(b),
            ArithOp::Mul => a.wrapping_mul(b),
            ArithOp::Div | ArithOp::Rem if b == 0 => {
                self.math_error = true;
                0
            }
            ArithOp::Div => a.wrapping_div(b),
            ArithOp::Rem => a.wrapping_rem(b),
            ArithOp::And => a & b,
            ArithOp::Or => a | b,
            ArithOp::Xor => a ^ b,
        }
    }

    #[inline]
    fn condition(&mut self, c: &Condition, drive: &(impl Drive + ?Sized)) -> bool {
        let l = self.value(&c.lhs, drive);
        let r = self.value(&c.rhs, drive);
        match c.cmp {
            Compare::Eq => l == r,
            Compare::Ne => l != r,
            Compare::Lt => l < r,
            Compare::Le => l <= r,
            Compare::Gt => l > r,
            Compare::Ge => l >= r,
        }
    }

    fn action(&mut self, a: &Action, drive: &mut (impl Drive + ?Sized)) -> Option<Next> {
        let i = a.index as usize;
        match a.kind {
            ActionKind::NextMotion => return Some(Next::Motion(a.index as u16)),
            ActionKind::Jump => return Some(Next::Event(a.index as u16)),
            ActionKind::Stop => {
                drive.stop();
                return None;
            }
            _ => {}
        }
        let v = self.value(&a.value, drive);
        match a.kind {
            ActionKind::WriteMem => {
                if let Some(m) = self.memory.get_mut(i) {
                    *m = v;
                }
            }
            ActionKind::WriteOutput => drive.set_digital_output(a.index, v != 0),
            ActionKind::SetVelocity => drive.set_velocity(v),
            ActionKind::SetAcceleration => drive.set_acceleration(v),
            ActionKind::SetDeceleration => drive.set_deceleration(v),
            ActionKind::SetJogVelocity => drive.set_jog_velocity(v),
            ActionKind::SetPosition => drive.set_position(v),
            ActionKind::VelocityMove => drive.velocity_move(v),
            ActionKind::RelativeMove => drive.relative_move(v),
            ActionKind::AbsoluteMove => drive.absolute_move(v),
            ActionKind::Jog => drive.jog(v),
            ActionKind::Homing => drive.home(v),
            ActionKind::TimerSet => {
                if let Some(t) = self.timers.get_mut(i) {
                    *t = Timer {
                        armed: true,
                        deadline: drive.now_ms().wrapping_add(v.max(0) as u32),
                    };
                }
            }
            ActionKind::Loop => {
                if let Some(m) = self.memory.get_mut(i) {
                    *m = m.wrapping_sub(1);
                    if *m > 0 {
                        return Some(Next::Event(v as u16));
                    }
                }
            }
            ActionKind::WriteMathError => self.math_error = v != 0,
            ActionKind::NextMotion | ActionKind::Jump | ActionKind::Stop => {}
        }
        None
    }
}
