//! Shared helpers of the group tests: an engine with a group and its axes, position
//! arrays by identity.
#![allow(dead_code)]

use motion_lib::axis::AxisConfig;
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::profile::Limits;

/// A 1 ms engine (queue depth 4) with `n` axes (vmax 200, amax = dmax 2000, jmax 20000)
/// and one empty group: (engine, axes, group).
pub fn axes(n: usize) -> (Engine, Vec<usize>, usize) {
    let mut e = Engine::new(EngineConfig {
        cycle: 0.001,
        queue_depth: 4,
    })
    .unwrap();
    let cfg = AxisConfig {
        limits: Limits {
            vmax: 200.0,
            amax: 2000.0,
            dmax: 2000.0,
            jmax: 20000.0,
        },
        ..AxisConfig::default()
    };
    let v: Vec<usize> = (0..n).map(|_| e.add_axis(cfg).unwrap()).collect();
    let g = e.add_group();
    (e, v, g)
}

/// A position array with `x` for the first identities, 0 elsewhere.
pub fn vecn(x: &[f64]) -> [f64; 16] {
    let mut v = [0.0; 16];
    v[..x.len()].copy_from_slice(x);
    v
}
