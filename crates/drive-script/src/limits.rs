//! Every fixed limit of the script language and of the drive-side pools.
//!
//! Input: none. Output: constants used by the compiler (capacity checks), the image decoder (validation)
//! and the interpreter (array sizes). Invariant: all are small enough that an index fits in a `u8`
//! (motions/events in a `u16`), so the image layout never truncates.

/// User parameters `P0..P15` (32-bit signed).
pub const PARAMS: usize = 16;
/// Memory words `MD0..MD49` (32-bit signed).
pub const MEMORY_WORDS: usize = 50;
/// Digital inputs `DI_0..DI_15`.
pub const DIGITAL_INPUTS: usize = 16;
/// Digital outputs `DO_0..DO_15`.
pub const DIGITAL_OUTPUTS: usize = 16;
/// Timers `TimerSet_0..TimerSet_7` / `TimerDone_0..TimerDone_7` (milliseconds).
pub const TIMERS: usize = 8;
/// Motion pool capacity (`MOTION 0` .. `MOTION 31`).
pub const MAX_MOTIONS: usize = 32;
/// Event pool capacity (all Motions together).
pub const MAX_EVENTS: usize = 256;
/// Events per Motion (an Event number fits the pool).
pub const MAX_EVENTS_PER_MOTION: usize = MAX_EVENTS;
/// Conditions in one IF statement.
pub const MAX_CONDITIONS: usize = 4;
/// Actions in one THEN statement.
pub const MAX_ACTIONS: usize = 8;
/// Debugger: user breakpoints (the fifth list entry is the temporary single-step breakpoint).
pub const USER_BREAKPOINTS: usize = 4;
/// Default interpreter budget: Events evaluated per main-loop call.
pub const DEFAULT_EVENTS_PER_CYCLE: u16 = 32;
/// Upper bound accepted for `EventsPerCycle`.
pub const MAX_EVENTS_PER_CYCLE: u16 = 1024;
