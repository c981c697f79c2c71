//! Running the engine on its own thread, with a lock-free hand-over to the PLC scan.
//!
//! Input: the PLC scan's blocks (copied, inputs and block state) sent through a bounded
//! queue; the engine thread applies each received block call, then steps one cycle.
//! Output: the updated blocks (outputs and state) sent back through a second queue.
//! Invariants: the hand-over is two `crossbeam_queue::ArrayQueue`s (bounded, lock-free push
//! and pop, no allocation per message; one producer and one consumer per direction, so
//! neither side ever blocks the other); a block has at most one call in flight, so no call is ever dropped or
//! reordered; the engine thread owns the [`Engine`] and gives it back on `stop`.
//! In scan mode (calling `Engine::step` from the scan) everything is deterministic; here
//! a call takes effect at the first cycle boundary after it arrives.

use crossbeam_queue::ArrayQueue;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use crate::blocks::*;
use crate::engine::Engine;
use crate::group_blocks::*;

/// What a block acts on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// One axis (single-axis blocks, MC_GearOut / MC_CamOut: the slave).
    Axis(usize),
    /// One axes group (Part 4 blocks).
    Group(usize),
    /// Master and slave axes (GearIn, CamIn, CamTableSelect).
    MasterSlave(usize, usize),
}

macro_rules! any_block {
    ($( $var:ident($ty:ty) => |$b:ident, $e:ident, $t:ident| $call:expr ;)*) => {
        /// Any PLCopen block, by value (what crosses the thread boundary).
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub enum AnyBlock {
            $(
                #[doc = concat!("A [`", stringify!($ty), "`] with its inputs and outputs, in transit between the scan and the engine thread.")]
                $var($ty),
            )*
        }

        impl AnyBlock {
            /// Calls the block on `engine`; a target of the wrong kind does nothing.
            pub fn call(&mut self, engine: &mut Engine, target: Target) {
                match self {
                    $( AnyBlock::$var($b) => {
                        let $e = engine;
                        let $t = target;
                        $call
                    } )*
                }
            }
        }
    };
}

any_block! {
    Power(McPower) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    Home(McHome) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    Stop(McStop) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    Halt(McHalt) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    MoveAbsolute(McMoveAbsolute) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    MoveRelative(McMoveRelative) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    MoveAdditive(McMoveAdditive) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    MoveVelocity(McMoveVelocity) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    Reset(McReset) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    ReadActualPosition(McReadActualPosition) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    ReadActualVelocity(McReadActualVelocity) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    ReadStatus(McReadStatus) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    ReadAxisError(McReadAxisError) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    SetPosition(McSetPosition) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    SetOverride(McSetOverride) => |b, e, t| if let Target::Axis(a) = t { b.call(e, a) };
    GearIn(McGearIn) => |b, e, t| if let Target::MasterSlave(m, s) = t { b.call(e, m, s) };
    GearOut(McGearOut) => |b, e, t| if let Target::Axis(a) = t { b.call_gear_out(e, a) };
    CamOut(McCamOut) => |b, e, t| if let Target::Axis(a) = t { b.call_cam_out(e, a) };
    CamTableSelect(McCamTableSelect) => |b, e, t| if let Target::MasterSlave(m, s) = t { b.call(e, m, s) };
    CamIn(McCamIn) => |b, e, t| if let Target::MasterSlave(m, s) = t { b.call(e, m, s) };
    AddAxisToGroup(McAddAxisToGroup) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    RemoveAxisFromGroup(McRemoveAxisFromGroup) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    UngroupAllAxes(McUngroupAllAxes) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    GroupEnable(McGroupEnable) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    GroupDisable(McGroupDisable) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    GroupReset(McGroupReset) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    GroupStop(McGroupStop) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    GroupHome(McGroupHome) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    GroupHalt(McGroupHalt) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    MoveLinearAbsolute(McMoveLinearAbsolute) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    MoveLinearRelative(McMoveLinearRelative) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    MoveDirectAbsolute(McMoveDirectAbsolute) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    MoveCircularAbsolute(McMoveCircularAbsolute) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    MoveCircularRelative(McMoveCircularRelative) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    GroupReadActualPosition(McGroupReadActualPosition) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    GroupReadActualVelocity(McGroupReadActualVelocity) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
    GroupReadStatus(McGroupReadStatus) => |b, e, t| if let Target::Group(g) = t { b.call(e, g) };
}

#[derive(Debug)]
struct Request {
    slot: usize,
    block: AnyBlock,
    target: Target,
}

#[derive(Debug)]
struct Response {
    slot: usize,
    block: AnyBlock,
}

/// The scan side of the hand-over. The program keeps its block instances in a slice
/// indexed by slot; each scan it calls [`ScanLink::receive`] (outputs of finished calls),
/// runs its logic (reads outputs, writes inputs), then [`ScanLink::call`] per block.
pub struct ScanLink {
    tx: Arc<ArrayQueue<Request>>,
    rx: Arc<ArrayQueue<Response>>,
    in_flight: Vec<bool>,
    stop: Arc<AtomicBool>,
    cycles: Arc<AtomicU64>,
    thread: Option<JoinHandle<Engine>>,
}

impl ScanLink {
    /// Sends block `slot` to the engine unless its previous call is still in flight
    /// (then this scan's call is skipped: inputs are levels/edges kept in the block).
    /// Returns true when sent.
    pub fn call(&mut self, slot: usize, block: &AnyBlock, target: Target) -> bool {
        if slot >= self.in_flight.len() || self.in_flight[slot] {
            return false;
        }
        match self.tx.push(Request {
            slot,
            block: *block,
            target,
        }) {
            Ok(()) => {
                self.in_flight[slot] = true;
                true
            }
            Err(_) => false,
        }
    }

    /// Copies every answered call back into `blocks[slot]` (outputs and block state).
    pub fn receive(&mut self, blocks: &mut [AnyBlock]) {
        while let Some(r) = self.rx.pop() {
            if let Some(b) = blocks.get_mut(r.slot) {
                *b = r.block;
            }
            if let Some(f) = self.in_flight.get_mut(r.slot) {
                *f = false;
            }
        }
    }

    /// Engine cycles stepped so far.
    pub fn cycles(&self) -> u64 {
        self.cycles.load(Ordering::Acquire)
    }

    /// Stops the engine thread and returns the engine.
    pub fn stop(mut self) -> Option<Engine> {
        self.stop.store(true, Ordering::Release);
        self.thread.take().and_then(|t| t.join().ok())
    }
}

/// Moves `engine` onto its own thread stepping every cycle (`engine.config().cycle`);
/// `slots` is the number of block instances the scan uses.
pub fn spawn(mut engine: Engine, slots: usize) -> ScanLink {
    let depth = slots.max(1);
    let requests = Arc::new(ArrayQueue::<Request>::new(depth));
    let responses = Arc::new(ArrayQueue::<Response>::new(depth));
    let (req_rx, resp_tx) = (requests.clone(), responses.clone());
    let stop = Arc::new(AtomicBool::new(false));
    let cycles = Arc::new(AtomicU64::new(0));
    let (stop2, cycles2) = (stop.clone(), cycles.clone());
    let period = Duration::from_secs_f64(engine.config().cycle);
    let thread = std::thread::spawn(move || {
        let mut next = Instant::now() + period;
        while !stop2.load(Ordering::Acquire) {
            // At most one call per slot is in flight, so the answer channel (depth =
            // slots) always has room: push never fails for lack of space.
            while let Some(mut r) = req_rx.pop() {
                r.block.call(&mut engine, r.target);
                let _ = resp_tx.push(Response {
                    slot: r.slot,
                    block: r.block,
                });
            }
            engine.step();
            cycles2.store(engine.cycles(), Ordering::Release);
            let now = Instant::now();
            if next > now {
                std::thread::sleep(next - now);
            }
            next += period;
        }
        engine
    });
    ScanLink {
        tx: requests,
        rx: responses,
        in_flight: vec![false; slots],
        stop,
        cycles,
        thread: Some(thread),
    }
}
