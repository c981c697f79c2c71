//! Per-cycle cost of the engine, ns per moving axis per cycle, side by side with
//! rsruckig's sampling of the same moves, in one run.
//!
//! Run: `cargo bench -p motion-lib --bench engine_bench`. 10,000 axes each run a
//! jerk-limited MC_MoveAbsolute (distances 1000 to 11000, so every axis is still moving
//! at the end); the engine's `step` (set points, status, queues, software limits, the
//! simulated drives) is timed in rounds of `ROUND` cycles, interleaved with rounds of the
//! anchor: rsruckig's `Trajectory::at_time` for the same 10,000 moves planned by
//! rsruckig, one sample per axis per cycle (the least a ruckig-based engine does per
//! cycle). Times are the thread's CPU time (`/proc/thread-self/schedstat`, so that the
//! other processes of a shared machine do not count; wall time where it is missing).
//! The report gives the median over the rounds of each and of the per-round ratio.
#![forbid(unsafe_code)]

use std::hint::black_box;
use std::time::Instant;

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::{McMoveAbsolute, McPower};
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::profile::Limits;
use rsruckig::prelude::*;

const AXES: usize = 10_000;
const ROUND: usize = 250;
const ROUNDS: usize = 8;

/// The thread's CPU time in ns (falls back to wall time).
fn cpu_ns(wall: &Instant) -> u64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse().ok())
        .unwrap_or_else(|| wall.elapsed().as_nanos() as u64)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let wall = Instant::now();
    let lim = Limits {
        vmax: 1000.0,
        amax: 1000.0,
        dmax: 1000.0,
        jmax: 10000.0,
    };
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let cfg = AxisConfig {
        limits: lim,
        ..AxisConfig::default()
    };
    for _ in 0..AXES {
        e.add_axis(cfg).unwrap();
    }
    let t0 = cpu_ns(&wall);
    for _ in 0..ROUND {
        e.step();
    }
    let standstill = (cpu_ns(&wall) - t0) as f64 / (ROUND * AXES) as f64;
    let target = |i: usize| 1000.0 + i as f64;
    let mut otg = Ruckig::<1, IgnoreErrorHandler>::new(None, 0.001);
    let mut trajs = Vec::with_capacity(AXES);
    for i in 0..AXES {
        McPower {
            enable: true,
            ..Default::default()
        }
        .call(&mut e, i);
        McMoveAbsolute {
            execute: true,
            position: target(i),
            velocity: 500.0,
            acceleration: 1000.0,
            deceleration: 1000.0,
            jerk: 10000.0,
            ..Default::default()
        }
        .call(&mut e, i);
        let mut input = InputParameter::new(None);
        input.target_position[0] = target(i);
        input.max_velocity[0] = 500.0;
        input.max_acceleration[0] = 1000.0;
        input.max_jerk[0] = 10000.0;
        let mut traj = Trajectory::new(None);
        otg.calculate(&input, &mut traj).expect("rsruckig plans");
        trajs.push(traj);
    }
    let dt = e.config().cycle;
    let (mut ours, mut theirs, mut ratios) = (Vec::new(), Vec::new(), Vec::new());
    let mut cycle = 0usize;
    let (mut p, mut v, mut a, mut j, section) = (
        daov_stack![0.0],
        daov_stack![0.0],
        daov_stack![0.0],
        daov_stack![0.0],
        0usize,
    );
    for round in 0..ROUNDS {
        let mut run_engine = || {
            let t = cpu_ns(&wall);
            for _ in 0..ROUND {
                e.step();
            }
            (cpu_ns(&wall) - t) as f64 / (ROUND * AXES) as f64
        };
        let mut run_ruckig = || {
            let t = cpu_ns(&wall);
            for c in 0..ROUND {
                let time = (cycle + c + 1) as f64 * dt;
                for traj in &trajs {
                    traj.at_time(
                        time,
                        &mut Some(&mut p),
                        &mut Some(&mut v),
                        &mut Some(&mut a),
                        &mut Some(&mut j),
                        &mut Some(section),
                    );
                    black_box(&p);
                }
            }
            (cpu_ns(&wall) - t) as f64 / (ROUND * AXES) as f64
        };
        let (o, r) = if round % 2 == 0 {
            let o = run_engine();
            (o, run_ruckig())
        } else {
            let r = run_ruckig();
            (run_engine(), r)
        };
        cycle += ROUND;
        ours.push(o);
        theirs.push(r);
        ratios.push(o / r);
    }
    let moving = (0..AXES)
        .filter(|&i| e.set_velocity_of(i).unwrap() != 0.0)
        .count();
    let ours = median(ours);
    println!(
        "engine_bench: {AXES} axes, {ROUNDS} interleaved rounds of {ROUND} cycles of 1 ms (CPU time)"
    );
    println!(
        "  engine step, moving (MoveAbsolute, {moving} axes still moving at the end): {ours:.1} ns per axis per cycle"
    );
    println!(
        "  rsruckig Trajectory::at_time, same moves:        {:.1} ns per axis per cycle",
        median(theirs)
    );
    println!(
        "  median ratio engine / rsruckig sampling:         {:.2}",
        median(ratios)
    );
    println!(
        "  engine step, standstill:                          {standstill:.1} ns per axis per cycle"
    );
    println!(
        "  goal: <= 25 ns per moving axis per cycle ({})",
        if ours <= 25.0 { "met" } else { "NOT met" }
    );
}
