//! Benchmark (harness = false): image bytes per Event and interpreter nanoseconds per Event.
//!
//! Run with `cargo bench -p drive-script`. Prints one line per figure; the interpreter goal is < 50 ns per
//! Event. A no-op drive isolates the interpreter from the simulated drive's floating-point model.
#![forbid(unsafe_code)]

use drive_script::*;
use std::hint::black_box;
use std::time::Instant;

/// A drive whose commands cost nothing: measures the interpreter alone.
#[derive(Default)]
struct NullDrive {
    outputs: u32,
    last: i32,
}

impl Drive for NullDrive {
    fn actual_position(&self) -> i32 {
        1234
    }
    fn actual_velocity(&self) -> i32 {
        0
    }
    fn actual_current(&self) -> i32 {
        0
    }
    fn digital_inputs(&self) -> u32 {
        0b1010
    }
    fn digital_outputs(&self) -> u32 {
        self.outputs
    }
    fn set_digital_output(&mut self, index: u8, high: bool) {
        self.outputs = (self.outputs & !(1 << index)) | ((high as u32) << index);
    }
    fn motion_state(&self) -> MotionState {
        MotionState::Standstill
    }
    fn homed(&self) -> bool {
        true
    }
    fn now_ms(&self) -> u32 {
        0
    }
    fn set_velocity(&mut self, v: i32) {
        self.last = v;
    }
    fn set_acceleration(&mut self, a: i32) {
        self.last = a;
    }
    fn set_deceleration(&mut self, d: i32) {
        self.last = d;
    }
    fn set_jog_velocity(&mut self, v: i32) {
        self.last = v;
    }
    fn set_position(&mut self, p: i32) {
        self.last = p;
    }
    fn velocity_move(&mut self, v: i32) {
        self.last = v;
    }
    fn relative_move(&mut self, d: i32) {
        self.last = d;
    }
    fn absolute_move(&mut self, t: i32) {
        self.last = t;
    }
    fn jog(&mut self, d: i32) {
        self.last = d;
    }
    fn home(&mut self, m: i32) {
        self.last = m;
    }
    fn stop(&mut self) {}
}

fn compile(text: &str) -> Program {
    compile_str("bench.ds", text)
        .1
        .expect("bench script compiles")
        .program
}

/// One Motion of `n` Events, each `IF a AND b; THEN x AND y;`; `holds` chooses whether the IFs hold.
fn script(n: usize, holds: bool) -> String {
    let mut s = String::from(
        "S:: PARAM; S:: P0 = 10; S:: INIT; S:: EventsPerCycle = 1024; S:: MOTION 0;\n",
    );
    let cmp = if holds { ">=" } else { "<" };
    for e in 0..n {
        let m = e % 40;
        s.push_str(&format!(
            "S:: EVENT {e}; S:: IF DI_1 = HIGH AND ActualPosition {cmp} P0;\n\
             S:: THEN MD{m} = MD{m} + 1 AND DO_{} = MD{m} & 1;\n",
            e % 16
        ));
    }
    s
}

fn ns_per_event(p: Program, drive: &mut impl Drive) -> (f64, u64) {
    let mut i = Interpreter::new(p).unwrap();
    // Warm up, then time about 0.5 s.
    for _ in 0..1000 {
        i.cycle(drive);
    }
    let start_events = i.events_evaluated();
    let t = Instant::now();
    let mut calls = 0u64;
    while t.elapsed().as_millis() < 500 {
        for _ in 0..1000 {
            black_box(i.cycle(drive));
        }
        calls += 1000;
    }
    let events = i.events_evaluated() - start_events;
    (t.elapsed().as_nanos() as f64 / events as f64, calls)
}

fn main() {
    // Image size per Event.
    let empty = encode(&compile(
        "S:: MOTION 0; S:: EVENT 0; S:: IF TRUE; S:: THEN Stop;",
    ))
    .len();
    let paper = compile("S:: MOTION 0; S:: EVENT 0; S:: IF DI_0 = HIGH; S:: THEN DO_0=HIGH AND RelativeTargetPosition=10000;");
    let paper_len = encode(&paper).len();
    println!("image: header + fixed part + 1 Motion + minimal Event = {empty} bytes");
    println!(
        "image: the paper's Event (1 condition, 2 actions) = {} bytes",
        paper_len - (empty - (2 + 23 + 13))
    );
    let big = compile(&script(200, true));
    let big_len = encode(&big).len();
    println!(
        "image: 200 Events of 2 conditions + 2 actions = {big_len} bytes, {:.1} bytes per Event",
        (big_len - (empty - (2 + 23 + 13))) as f64 / 200.0
    );
    let three = compile(include_str!("../tests/scripts/three_motions.ds"));
    let three_len = encode(&three).len();
    println!(
        "image: three_motions.ds (13 Events) = {three_len} bytes, {:.1} bytes per Event beyond the fixed part",
        (three_len - 16 - 288 - 3 * 4) as f64 / 13.0
    );
    println!(
        "drive RAM: one Event struct = {} bytes, Event pool of 256 = {} bytes",
        std::mem::size_of::<Event>(),
        256 * std::mem::size_of::<Event>()
    );

    // Interpreter cost per Event.
    for (label, holds) in [
        ("IF false (both conditions evaluated)", false),
        ("IF true, THEN runs 2 actions", true),
    ] {
        let (ns, calls) = ns_per_event(compile(&script(64, holds)), &mut NullDrive::default());
        println!("interpreter, no-op drive, {label}: {ns:.1} ns per Event ({calls} cycle calls)");
    }
    let mut sim = SimDrive::new(1);
    sim.set_input(1, true);
    sim.set_position(1234);
    let (ns, _) = ns_per_event(compile(&script(64, true)), &mut sim);
    println!("interpreter, simulated drive, IF true, THEN runs 2 actions: {ns:.1} ns per Event");
    let (ns, _) = ns_per_event(three, &mut SimDrive::new(1));
    println!("interpreter, three_motions.ds on the simulated drive (idle in Motion 0): {ns:.1} ns per Event");

    // The motion-lib adapter: one main-loop tick during a move (engine step, block calls, reads) and one
    // move command (block call with a jerk-limited plan).
    let mut axis = MotionLibDrive::new(1);
    axis.set_velocity(1000);
    axis.relative_move(i32::MAX);
    let ticks = 200_000u32;
    let t = Instant::now();
    for _ in 0..ticks {
        axis.tick();
    }
    let ns = t.elapsed().as_nanos() as f64 / ticks as f64;
    black_box(axis.actual_position());
    println!("MotionLibDrive: {ns:.0} ns per tick while moving");
    let commands = 50_000i32;
    let t = Instant::now();
    for k in 0..commands {
        axis.absolute_move(black_box(k % 2) * 1000);
    }
    let ns = t.elapsed().as_nanos() as f64 / commands as f64;
    black_box(axis.motion_state());
    println!(
        "MotionLibDrive: {ns:.0} ns per move command (MC_MoveAbsolute aborting a running move)"
    );
}
