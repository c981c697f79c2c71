//! Per-cycle cost of the engine: ns per axis per cycle with 10,000 axes, each running a
//! jerk-limited MoveAbsolute (the common case), and with every axis at standstill.
//! Run: `cargo bench -p motion-lib --bench engine_bench`.

use std::time::Instant;

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::{McMoveAbsolute, McPower};
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::profile::Limits;

fn main() {
    let n = 10_000;
    let cycles = 2_000;
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let cfg = AxisConfig {
        limits: Limits {
            vmax: 1000.0,
            amax: 1000.0,
            dmax: 1000.0,
            jmax: 10000.0,
        },
        ..AxisConfig::default()
    };
    for _ in 0..n {
        e.add_axis(cfg).unwrap();
    }
    let standstill = measure(&mut e, 500) / n as f64;
    let mut blocks = vec![McMoveAbsolute::default(); n];
    for (i, b) in blocks.iter_mut().enumerate() {
        McPower {
            enable: true,
            ..Default::default()
        }
        .call(&mut e, i);
        *b = McMoveAbsolute {
            execute: true,
            position: 1000.0 + i as f64,
            velocity: 500.0,
            acceleration: 1000.0,
            deceleration: 1000.0,
            jerk: 10000.0,
            ..Default::default()
        };
        b.call(&mut e, i);
    }
    let moving = measure(&mut e, cycles) / n as f64;
    let moving_axes = (0..n)
        .filter(|&i| e.set_velocity_of(i).unwrap() != 0.0)
        .count();
    println!("engine_bench: {n} axes, {cycles} cycles of 1 ms");
    println!("  moving (MoveAbsolute, {moving_axes} axes still moving at the end): {moving:.1} ns per axis per cycle");
    println!("  standstill: {standstill:.1} ns per axis per cycle");
    println!(
        "  goal: <= 100 ns per axis per cycle ({})",
        if moving <= 100.0 { "met" } else { "NOT met" }
    );
}

fn measure(e: &mut Engine, cycles: usize) -> f64 {
    let t = Instant::now();
    for _ in 0..cycles {
        e.step();
    }
    t.elapsed().as_nanos() as f64 / cycles as f64
}
