//! Shared helpers of the profile tests: a seeded generator and random problems.
#![allow(dead_code)]

use motion_lib::profile::{Limits, State};

/// splitmix64: a small deterministic generator (no dependency).
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((self.next() >> 11) as f64 / (1u64 << 53) as f64)
    }
    pub fn chance(&mut self, p: f64) -> bool {
        self.range(0.0, 1.0) < p
    }
}

#[derive(Clone, Copy, Debug)]
pub struct Problem {
    pub start: State,
    pub target_p: f64,
    pub target_v: f64,
    pub lim: Limits,
}

/// A random problem; `beyond_limits`: start velocity/acceleration up to 1.5x the limits;
/// `trapezoidal`: jmax 0 or infinite.
pub fn random_problem(rng: &mut Rng, beyond_limits: bool, trapezoidal: bool) -> Problem {
    let lim = Limits {
        vmax: rng.range(0.5, 100.0),
        amax: rng.range(0.2, 20.0),
        dmax: rng.range(0.2, 20.0),
        jmax: if trapezoidal {
            if rng.chance(0.5) {
                0.0
            } else {
                f64::INFINITY
            }
        } else {
            rng.range(0.1, 100.0)
        },
    };
    let amx = lim.amax.max(lim.dmax);
    let f = if beyond_limits { 1.5 } else { 1.0 };
    let start = State {
        p: rng.range(-1000.0, 1000.0),
        v: if rng.chance(0.2) {
            0.0
        } else {
            rng.range(-f, f) * lim.vmax
        },
        a: if rng.chance(0.3) || trapezoidal {
            0.0
        } else {
            rng.range(-f, f) * amx
        },
    };
    let dist = match rng.next() % 4 {
        0 => rng.range(-1000.0, 1000.0),
        1 => rng.range(-10.0, 10.0),
        2 => rng.range(-0.01, 0.01),
        _ => 0.0,
    };
    let target_v = if rng.chance(0.4) {
        0.0
    } else {
        rng.range(-1.0, 1.0) * lim.vmax
    };
    Problem {
        start,
        target_p: start.p + dist,
        target_v,
        lim,
    }
}
