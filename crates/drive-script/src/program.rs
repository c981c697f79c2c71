//! The compiled program: plain data only (the Motion pool and the Event pool plus Param/Init values).
//!
//! Input: built by the compiler or decoded from an image. Output: read by the interpreter and the image encoder.
//! Invariants (checked by the compiler and by the decoder, relied on by the interpreter):
//! `motions[m].first_event + motions[m].event_count <= events.len()`, Motions cover the Event pool in order,
//! every Motion has at least one Event, operand and action indices are in range, `NextMotionID`/`Jump`/`Loop`
//! targets exist, and unused condition/action slots are `Default` so derived equality compares programs.

use crate::limits::{MAX_ACTIONS, MAX_CONDITIONS, MEMORY_WORDS, PARAMS};
use std::fmt;

/// Where an operand's value comes from. `arg` of the [`Operand`] is the constant or the index.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[repr(u8)]
pub enum Source {
    /// A literal (`arg` is the value).
    #[default]
    Const = 0,
    /// `P<arg>`.
    Param = 1,
    /// `MD<arg>`.
    Mem = 2,
    /// `DI_<arg>` (from the pass snapshot).
    DigitalIn = 3,
    /// `DO_<arg>` (the live output image).
    DigitalOut = 4,
    /// `ActualPosition` (snapshot), pulses.
    ActualPosition = 5,
    /// `ActualVelocity` (snapshot), pulses/s.
    ActualVelocity = 6,
    /// `ActualCurrent` (snapshot), mA.
    ActualCurrent = 7,
    /// `TimerDone_<arg>` (snapshot).
    TimerDone = 8,
    /// `MotionState` (snapshot): 0 standstill, 1 moving, 2 homing, 3 fault.
    MotionState = 9,
    /// `MotionDone` (snapshot): 1 when no motion command is running.
    MotionDone = 10,
    /// `Homed` (snapshot).
    Homed = 11,
    /// `MathError`: 1 once a division or modulo by zero happened (sticky until written to 0 by `MathError=0`).
    MathError = 12,
}

impl Source {
    /// The source stored as byte `v` in an image; None for a byte no source has (the decoder rejects it).
    pub fn from_u8(v: u8) -> Option<Source> {
        use Source::*;
        Some(match v {
            0 => Const,
            1 => Param,
            2 => Mem,
            3 => DigitalIn,
            4 => DigitalOut,
            5 => ActualPosition,
            6 => ActualVelocity,
            7 => ActualCurrent,
            8 => TimerDone,
            9 => MotionState,
            10 => MotionDone,
            11 => Homed,
            12 => MathError,
            _ => return None,
        })
    }
}

/// One read: a constant, a register or a snapshot value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Operand {
    /// Where the value is read from.
    pub source: Source,
    /// The literal for [`Source::Const`], the register or bit index for P/MD/DI/DO/TimerDone, 0 otherwise.
    pub arg: i32,
}

impl Operand {
    /// The literal `v`.
    pub const fn konst(v: i32) -> Operand {
        Operand {
            source: Source::Const,
            arg: v,
        }
    }
}

/// Arithmetic or bitwise operator of a [`Value`]; `None` means the value is just its first operand.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[repr(u8)]
pub enum ArithOp {
    #[default]
    /// No operator: the value is `a` (`b` is unused and 0).
    None = 0,
    /// `a + b`, 32-bit wrapping.
    Add = 1,
    /// `a - b`, 32-bit wrapping (also `-x`, stored as `0 - x`).
    Sub = 2,
    /// `a * b`, 32-bit wrapping.
    Mul = 3,
    /// `a / b`, truncating; by zero gives 0 and sets `MathError`.
    Div = 4,
    /// `a % b` (sign of `a`); by zero gives 0 and sets `MathError`.
    Rem = 5,
    /// Bitwise `a & b`.
    And = 6,
    /// Bitwise `a | b`.
    Or = 7,
    /// Bitwise `a ^ b` (also `~x`, stored as `x ^ -1`).
    Xor = 8,
}

impl ArithOp {
    /// The operator stored as byte `v` in an image; `Option::None` for an unknown byte.
    pub fn from_u8(v: u8) -> Option<ArithOp> {
        use ArithOp::*;
        Some(match v {
            0 => None,
            1 => Add,
            2 => Sub,
            3 => Mul,
            4 => Div,
            5 => Rem,
            6 => And,
            7 => Or,
            8 => Xor,
            _ => return Option::None,
        })
    }
    /// The script's spelling of the operator (`""` for [`ArithOp::None`]), for listings and the debugger.
    pub fn symbol(self) -> &'static str {
        match self {
            ArithOp::None => "",
            ArithOp::Add => "+",
            ArithOp::Sub => "-",
            ArithOp::Mul => "*",
            ArithOp::Div => "/",
            ArithOp::Rem => "%",
            ArithOp::And => "&",
            ArithOp::Or => "|",
            ArithOp::Xor => "^",
        }
    }
}

/// A value: `a` or `a <op> b` (one operator at most: three-address form).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Value {
    /// First (or only) operand.
    pub a: Operand,
    /// The operator, or [`ArithOp::None`] for a plain operand.
    pub op: ArithOp,
    /// Second operand (a constant 0 when `op` is None).
    pub b: Operand,
}

impl Value {
    /// The constant value `v`.
    pub const fn konst(v: i32) -> Value {
        Value {
            a: Operand::konst(v),
            op: ArithOp::None,
            b: Operand::konst(0),
        }
    }
    /// The value of operand `a` alone.
    pub const fn of(a: Operand) -> Value {
        Value {
            a,
            op: ArithOp::None,
            b: Operand::konst(0),
        }
    }
}

/// Signed comparison of a condition.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[repr(u8)]
pub enum Compare {
    #[default]
    /// `=` / `==`: equal.
    Eq = 0,
    /// `<>` / `!=`: not equal (a lone value `x` in an IF means `x <> 0`).
    Ne = 1,
    /// `<`: less than (signed).
    Lt = 2,
    /// `<=`: less than or equal (signed).
    Le = 3,
    /// `>`: greater than (signed).
    Gt = 4,
    /// `>=`: greater than or equal (signed).
    Ge = 5,
}

impl Compare {
    /// The comparison stored as byte `v` in an image; None for an unknown byte.
    pub fn from_u8(v: u8) -> Option<Compare> {
        use Compare::*;
        Some(match v {
            0 => Eq,
            1 => Ne,
            2 => Lt,
            3 => Le,
            4 => Gt,
            5 => Ge,
            _ => return None,
        })
    }
    /// The script's spelling of the comparison (`=`, `<>`, ...).
    pub fn symbol(self) -> &'static str {
        match self {
            Compare::Eq => "=",
            Compare::Ne => "<>",
            Compare::Lt => "<",
            Compare::Le => "<=",
            Compare::Gt => ">",
            Compare::Ge => ">=",
        }
    }
}

/// One condition of an IF statement: `lhs cmp rhs`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Condition {
    /// Left-hand value.
    pub lhs: Value,
    /// How the two values are compared (signed 32-bit).
    pub cmp: Compare,
    /// Right-hand value.
    pub rhs: Value,
}

/// The drive command or register write an action performs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[repr(u8)]
pub enum ActionKind {
    /// `MD<index> = value`.
    #[default]
    WriteMem = 0,
    /// `DO_<index> = value` (non-zero is HIGH).
    WriteOutput = 1,
    /// `Velocity = value` (profile velocity, pulses/s).
    SetVelocity = 2,
    /// `Acceleration = value` (pulses/s²).
    SetAcceleration = 3,
    /// `Deceleration = value` (pulses/s²).
    SetDeceleration = 4,
    /// `JogVelocity = value` (pulses/s).
    SetJogVelocity = 5,
    /// `SetPosition = value`: redefine the actual position (no motion).
    SetPosition = 6,
    /// `VelocityMove = value`: run at a signed velocity.
    VelocityMove = 7,
    /// `RelativeTargetPosition = value`: move by a signed distance.
    RelativeMove = 8,
    /// `AbsoluteTargetPosition = value`: move to a position.
    AbsoluteMove = 9,
    /// `Jog = value`: >0 positive, <0 negative, 0 stop, at `JogVelocity`.
    Jog = 10,
    /// `Homing = value`: start homing with method `value`.
    Homing = 11,
    /// `Stop`: decelerate to standstill.
    Stop = 12,
    /// `TimerSet_<index> = value` milliseconds.
    TimerSet = 13,
    /// `NextMotionID = <index>`: after this Event, continue at Motion `index`, Event 0.
    NextMotion = 14,
    /// `Jump = <index>`: after this Event, continue at Event `index` of this Motion.
    Jump = 15,
    /// `Loop(MD<index>) = value`: decrement `MD<index>`; if still > 0, continue at Event `value` after this Event.
    Loop = 16,
    /// `MathError = value`: write the sticky math-error flag (0 clears it).
    WriteMathError = 17,
}

impl ActionKind {
    /// The action kind stored as byte `v` in an image; None for an unknown byte.
    pub fn from_u8(v: u8) -> Option<ActionKind> {
        use ActionKind::*;
        Some(match v {
            0 => WriteMem,
            1 => WriteOutput,
            2 => SetVelocity,
            3 => SetAcceleration,
            4 => SetDeceleration,
            5 => SetJogVelocity,
            6 => SetPosition,
            7 => VelocityMove,
            8 => RelativeMove,
            9 => AbsoluteMove,
            10 => Jog,
            11 => Homing,
            12 => Stop,
            13 => TimerSet,
            14 => NextMotion,
            15 => Jump,
            16 => Loop,
            17 => WriteMathError,
            _ => return None,
        })
    }
}

/// One action of a THEN statement.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Action {
    /// What the action does.
    pub kind: ActionKind,
    /// MD/DO/timer index, or the target Motion/Event of `NextMotionID`/`Jump`; 0 when unused.
    pub index: u8,
    /// The value written or commanded (the Event target of `Loop`); a constant 0 when unused.
    pub value: Value,
}

/// An Event: a condition table (all must hold) and an action table run in order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Event {
    /// Conditions in use (1..=`MAX_CONDITIONS`); the IF holds when all of them hold.
    pub cond_count: u8,
    /// Actions in use (1..=`MAX_ACTIONS`), run in order by the THEN.
    pub act_count: u8,
    /// The condition table; slots past `cond_count` are `Default`.
    pub conditions: [Condition; MAX_CONDITIONS],
    /// The action table; slots past `act_count` are `Default`.
    pub actions: [Action; MAX_ACTIONS],
}

impl Event {
    /// The conditions in use (the IF).
    pub fn conditions(&self) -> &[Condition] {
        &self.conditions[..self.cond_count as usize]
    }
    /// The actions in use (the THEN), in execution order.
    pub fn actions(&self) -> &[Action] {
        &self.actions[..self.act_count as usize]
    }
}

/// A Motion: a contiguous run of the Event pool.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Motion {
    /// Index in the Event pool of this Motion's Event 0.
    pub first_event: u16,
    /// Number of Events of this Motion (at least 1); a pass runs them in order and wraps to Event 0.
    pub event_count: u16,
}

/// System settings from the Init block, applied to the drive when the script starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Settings {
    /// Profile velocity of moves, pulses/s (`Velocity`; magnitude used).
    pub velocity: i32,
    /// Profile acceleration, pulses/s² (`Acceleration`).
    pub acceleration: i32,
    /// Profile deceleration, pulses/s² (`Deceleration`).
    pub deceleration: i32,
    /// Jog and homing velocity, pulses/s (`JogVelocity`).
    pub jog_velocity: i32,
    /// The interpreter's budget: Events evaluated per main-loop call.
    pub events_per_cycle: u16,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            velocity: 10_000,
            acceleration: 100_000,
            deceleration: 100_000,
            jog_velocity: 5_000,
            events_per_cycle: crate::limits::DEFAULT_EVENTS_PER_CYCLE,
        }
    }
}

/// The whole compiled script.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Program {
    /// Default values of `P0..P15` (Param block).
    pub params: [i32; PARAMS],
    /// Initial values of `MD0..MD49` (Init block).
    pub init: [i32; MEMORY_WORDS],
    /// Drive settings of the Init block, applied when the script starts.
    pub settings: Settings,
    /// The Motion pool.
    pub motions: Vec<Motion>,
    /// The Event pool.
    pub events: Vec<Event>,
}

impl Default for Program {
    fn default() -> Self {
        Program {
            params: [0; PARAMS],
            init: [0; MEMORY_WORDS],
            settings: Settings::default(),
            motions: Vec::new(),
            events: Vec::new(),
        }
    }
}

impl Program {
    /// The Event `event` of Motion `motion`, if both exist.
    pub fn event(&self, motion: usize, event: usize) -> Option<&Event> {
        let m = self.motions.get(motion)?;
        if event >= m.event_count as usize {
            return None;
        }
        self.events.get(m.first_event as usize + event)
    }
}

impl fmt::Display for Operand {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let i = self.arg;
        match self.source {
            Source::Const => write!(f, "{i}"),
            Source::Param => write!(f, "P{i}"),
            Source::Mem => write!(f, "MD{i}"),
            Source::DigitalIn => write!(f, "DI_{i}"),
            Source::DigitalOut => write!(f, "DO_{i}"),
            Source::ActualPosition => f.write_str("ActualPosition"),
            Source::ActualVelocity => f.write_str("ActualVelocity"),
            Source::ActualCurrent => f.write_str("ActualCurrent"),
            Source::TimerDone => write!(f, "TimerDone_{i}"),
            Source::MotionState => f.write_str("MotionState"),
            Source::MotionDone => f.write_str("MotionDone"),
            Source::Homed => f.write_str("Homed"),
            Source::MathError => f.write_str("MathError"),
        }
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.op {
            ArithOp::None => write!(f, "{}", self.a),
            op => write!(f, "{} {} {}", self.a, op.symbol(), self.b),
        }
    }
}

impl fmt::Display for Condition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {} {}", self.lhs, self.cmp.symbol(), self.rhs)
    }
}

impl fmt::Display for Action {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = &self.value;
        let i = self.index;
        match self.kind {
            ActionKind::WriteMem => write!(f, "MD{i}={v}"),
            ActionKind::WriteOutput => write!(f, "DO_{i}={v}"),
            ActionKind::SetVelocity => write!(f, "Velocity={v}"),
            ActionKind::SetAcceleration => write!(f, "Acceleration={v}"),
            ActionKind::SetDeceleration => write!(f, "Deceleration={v}"),
            ActionKind::SetJogVelocity => write!(f, "JogVelocity={v}"),
            ActionKind::SetPosition => write!(f, "SetPosition={v}"),
            ActionKind::VelocityMove => write!(f, "VelocityMove={v}"),
            ActionKind::RelativeMove => write!(f, "RelativeTargetPosition={v}"),
            ActionKind::AbsoluteMove => write!(f, "AbsoluteTargetPosition={v}"),
            ActionKind::Jog => write!(f, "Jog={v}"),
            ActionKind::Homing => write!(f, "Homing={v}"),
            ActionKind::Stop => f.write_str("Stop"),
            ActionKind::TimerSet => write!(f, "TimerSet_{i}={v}"),
            ActionKind::NextMotion => write!(f, "NextMotionID={i}"),
            ActionKind::Jump => write!(f, "Jump={i}"),
            ActionKind::Loop => write!(f, "Loop(MD{i})={v}"),
            ActionKind::WriteMathError => write!(f, "MathError={v}"),
        }
    }
}

/// Renders the program back as script text (a disassembly): compiling it gives an equal program.
impl fmt::Display for Program {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "S:: PARAM;")?;
        for (i, p) in self.params.iter().enumerate() {
            if *p != 0 {
                writeln!(f, "S:: P{i} = {p};")?;
            }
        }
        writeln!(f, "S:: INIT;")?;
        for (i, v) in self.init.iter().enumerate() {
            if *v != 0 {
                writeln!(f, "S:: MD{i} = {v};")?;
            }
        }
        let s = &self.settings;
        writeln!(f, "S:: Velocity = {};", s.velocity)?;
        writeln!(f, "S:: Acceleration = {};", s.acceleration)?;
        writeln!(f, "S:: Deceleration = {};", s.deceleration)?;
        writeln!(f, "S:: JogVelocity = {};", s.jog_velocity)?;
        writeln!(f, "S:: EventsPerCycle = {};", s.events_per_cycle)?;
        for (m, motion) in self.motions.iter().enumerate() {
            writeln!(f, "S:: MOTION {m};")?;
            for e in 0..motion.event_count as usize {
                let ev = &self.events[motion.first_event as usize + e];
                writeln!(f, "S:: EVENT {e};")?;
                let conds: Vec<String> = ev.conditions().iter().map(|c| c.to_string()).collect();
                writeln!(f, "S:: IF {};", conds.join(" AND "))?;
                let acts: Vec<String> = ev.actions().iter().map(|a| a.to_string()).collect();
                writeln!(f, "S:: THEN {};", acts.join(" AND "))?;
            }
        }
        Ok(())
    }
}

impl Program {
    /// Checks every invariant the interpreter relies on (see the module header). The compiler's output
    /// always passes; the image decoder and [`crate::Interpreter::new`] call this on foreign data.
    pub fn validate(&self) -> Result<(), String> {
        use crate::limits::*;
        if self.motions.is_empty() {
            return Err("the Motion pool is empty".into());
        }
        if self.motions.len() > MAX_MOTIONS {
            return Err(format!(
                "{} Motions exceed the pool capacity {MAX_MOTIONS}",
                self.motions.len()
            ));
        }
        if self.events.len() > MAX_EVENTS {
            return Err(format!(
                "{} Events exceed the pool capacity {MAX_EVENTS}",
                self.events.len()
            ));
        }
        let s = &self.settings;
        if s.events_per_cycle == 0 || s.events_per_cycle > MAX_EVENTS_PER_CYCLE {
            return Err(format!(
                "EventsPerCycle {} is outside 1..={MAX_EVENTS_PER_CYCLE}",
                s.events_per_cycle
            ));
        }
        let mut next = 0usize;
        for (m, motion) in self.motions.iter().enumerate() {
            if motion.first_event as usize != next {
                return Err(format!(
                    "Motion {m} starts at Event pool entry {} instead of {next}",
                    motion.first_event
                ));
            }
            if motion.event_count == 0 {
                return Err(format!("Motion {m} has no Event"));
            }
            next += motion.event_count as usize;
        }
        if next != self.events.len() {
            return Err(format!(
                "the Motions cover {next} Events but the Event pool holds {}",
                self.events.len()
            ));
        }
        let operand_ok = |o: &Operand| -> bool {
            let i = o.arg;
            let lim = |n: usize| i >= 0 && (i as usize) < n;
            match o.source {
                Source::Const => true,
                Source::Param => lim(PARAMS),
                Source::Mem => lim(MEMORY_WORDS),
                Source::DigitalIn => lim(DIGITAL_INPUTS),
                Source::DigitalOut => lim(DIGITAL_OUTPUTS),
                Source::TimerDone => lim(TIMERS),
                _ => i == 0,
            }
        };
        let value_ok = |v: &Value| {
            operand_ok(&v.a)
                && operand_ok(&v.b)
                && (v.op != ArithOp::None || v.b == Operand::default())
        };
        for (m, motion) in self.motions.iter().enumerate() {
            for e in 0..motion.event_count as usize {
                let ev = &self.events[motion.first_event as usize + e];
                let at = format!("Motion {m} Event {e}");
                if ev.cond_count == 0 || ev.cond_count as usize > MAX_CONDITIONS {
                    return Err(format!(
                        "{at}: {} conditions (1..={MAX_CONDITIONS} allowed)",
                        ev.cond_count
                    ));
                }
                if ev.act_count == 0 || ev.act_count as usize > MAX_ACTIONS {
                    return Err(format!(
                        "{at}: {} actions (1..={MAX_ACTIONS} allowed)",
                        ev.act_count
                    ));
                }
                if ev.conditions[ev.cond_count as usize..]
                    .iter()
                    .any(|c| *c != Condition::default())
                    || ev.actions[ev.act_count as usize..]
                        .iter()
                        .any(|a| *a != Action::default())
                {
                    return Err(format!(
                        "{at}: unused condition or action slots are not empty"
                    ));
                }
                for c in ev.conditions() {
                    if !value_ok(&c.lhs) || !value_ok(&c.rhs) {
                        return Err(format!("{at}: condition `{c}` reads out of range"));
                    }
                }
                for a in ev.actions() {
                    if !value_ok(&a.value) {
                        return Err(format!("{at}: action `{a}` reads out of range"));
                    }
                    let i = a.index as usize;
                    let ok = match a.kind {
                        ActionKind::WriteMem => i < MEMORY_WORDS,
                        ActionKind::WriteOutput => i < DIGITAL_OUTPUTS,
                        ActionKind::TimerSet => i < TIMERS,
                        ActionKind::NextMotion => {
                            i < self.motions.len() && a.value == Value::default()
                        }
                        ActionKind::Jump => {
                            i < motion.event_count as usize && a.value == Value::default()
                        }
                        ActionKind::Loop => {
                            i < MEMORY_WORDS
                                && a.value.op == ArithOp::None
                                && a.value.a.source == Source::Const
                                && (0..motion.event_count as i32).contains(&a.value.a.arg)
                        }
                        ActionKind::Stop => i == 0 && a.value == Value::default(),
                        _ => i == 0,
                    };
                    if !ok {
                        return Err(format!(
                            "{at}: action `{a}` has an index or target out of range"
                        ));
                    }
                }
            }
        }
        Ok(())
    }
}
