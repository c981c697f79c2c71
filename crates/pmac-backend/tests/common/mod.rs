//! Test helpers: coordinate systems, paper B's moves, and the planned jerk-limited motion sampled exactly.
#![allow(dead_code)]

use pmac_backend::model::{
    AxisDef, CoordSystem, LinearMove, MoveMode, Sample, Trajectory, Transition,
};
use pmac_backend::scurve::{project, RestToRest};

pub fn cs(names: &[char]) -> CoordSystem {
    CoordSystem {
        number: 1,
        axes: names
            .iter()
            .enumerate()
            .map(|(i, &name)| AxisDef {
                motor: i as u32 + 1,
                name,
                counts_per_unit: 1000.0,
            })
            .collect(),
    }
}

/// Paper B's three targets with per-axis speeds 40, 55, 70, a = d = 5, j = 2, exact stops.
pub fn paper_b() -> Vec<LinearMove> {
    let targets = [
        [1600.0, 1200.0, 800.0],
        [2200.0, 3800.0, 5000.0],
        [4500.0, 4200.0, 4800.0],
    ];
    let speeds = [40.0, 55.0, 70.0];
    (0..3)
        .map(|i| stop_move(targets[i].to_vec(), speeds[i], 5.0, 2.0))
        .collect()
}

pub fn stop_move(target: Vec<f64>, v: f64, a: f64, j: f64) -> LinearMove {
    LinearMove {
        target,
        velocity: v,
        acceleration: a,
        deceleration: a,
        jerk: j,
        mode: MoveMode::Abs,
        transition: Transition::ExactStop,
    }
}

/// The time-optimal exact-stop motion through `moves` from the origin, sampled every `cycle_s` (exact values).
pub fn sampled(moves: &[LinearMove], cycle_s: f64) -> Trajectory {
    let n = moves[0].target.len();
    let mut from = vec![0.0; n];
    let mut legs = Vec::new();
    for m in moves {
        let delta: Vec<f64> = m.target.iter().zip(&from).map(|(a, b)| a - b).collect();
        let v = |x| vec![x; n];
        let (len, lim) = project(
            &delta,
            &v(m.velocity),
            &v(m.acceleration),
            &v(m.deceleration),
            &v(m.jerk),
        )
        .unwrap();
        legs.push((from.clone(), delta, RestToRest::plan(len, &lim), len));
        from = m.target.clone();
    }
    let total: f64 = legs.iter().map(|l| l.2.duration()).sum();
    let count = (total / cycle_s).ceil() as usize;
    let mut axes = vec![Vec::with_capacity(count + 1); n];
    let mut leg = 0;
    let mut t0 = 0.0;
    for i in 0..=count {
        let t = (i as f64 * cycle_s).min(total);
        while leg + 1 < legs.len() && t > t0 + legs[leg].2.duration() {
            t0 += legs[leg].2.duration();
            leg += 1;
        }
        let (start, delta, r, len) = &legs[leg];
        let (s, v) = r.eval(t - t0);
        let a = r.acceleration(t - t0);
        for k in 0..n {
            let u = delta[k] / len;
            axes[k].push(Sample {
                p: start[k] + u * s,
                v: u * v,
                a: u * a,
            });
        }
    }
    Trajectory { cycle_s, axes }
}
