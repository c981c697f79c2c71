//! The closed-form fast paths against rsruckig, and `Line::plan`'s path limits.
//!
//! Rest-to-rest moves (the rest and line kinds) are planned in closed form: a cruise at
//! vmax, both ramps triangular (one cube root) or both trapezoidal (one square root).
//! Random problems cover every case, with amax != dmax (the mixed case goes to the
//! kernel), distances from far below to far above the cruising distance, and both
//! directions; durations must equal rsruckig's to 1e-9 relative, every phase must keep
//! the limits and the end must be the target. Lines: the limits that `Line::plan` uses
//! equal `path_limits` of its unit vector (to rounding), including axes that do not move
//! and axes without a jerk limit, and no axis exceeds its own limits.

mod profile_common;
use motion_lib::profile::line::{path_limits, Line};
use motion_lib::profile::{Limits, Profile, State};
use profile_common::Rng;
use rsruckig::prelude::*;

fn ruckig_rest_to_rest(otg: &mut Ruckig<1, IgnoreErrorHandler>, d: f64, lim: &Limits) -> f64 {
    let mut input = InputParameter::new(None);
    let (amax, amin) = if d >= 0.0 {
        (lim.amax, -lim.dmax)
    } else {
        (lim.dmax, -lim.amax)
    };
    input.target_position[0] = d;
    input.max_velocity[0] = lim.vmax;
    input.max_acceleration[0] = amax;
    input.min_acceleration = Some(daov_stack![amin]);
    input.max_jerk[0] = lim.jmax;
    let mut traj = Trajectory::new(None);
    otg.calculate(&input, &mut traj).expect("rsruckig plans");
    traj.get_duration()
}

#[test]
fn rest_to_rest_closed_form_equals_rsruckig() {
    let mut otg = Ruckig::<1, IgnoreErrorHandler>::new(None, 0.001);
    let mut rng = Rng(0x5EED_0016);
    for k in 0..20_000 {
        let lim = Limits {
            vmax: rng.range(0.1, 100.0),
            amax: rng.range(0.1, 100.0),
            // Half of the problems with equal acceleration and deceleration.
            dmax: 0.0,
            jmax: rng.range(0.1, 1000.0),
        };
        let lim = Limits {
            dmax: if k % 2 == 0 {
                lim.amax
            } else {
                rng.range(0.1, 100.0)
            },
            ..lim
        };
        // The distance of a cruise-free move at vmax, scaled from 1e-4x to 10x.
        let scale = 10f64.powf(rng.range(-4.0, 1.0));
        let d = scale * lim.vmax * (lim.vmax / lim.amax + lim.vmax / lim.dmax + 1.0);
        let d = if rng.chance(0.5) { d } else { -d };
        let p0 = rng.range(-100.0, 100.0);
        let prof = Profile::position(
            State {
                p: p0,
                v: 0.0,
                a: 0.0,
            },
            p0 + d,
            0.0,
            &lim,
        )
        .unwrap_or_else(|e| panic!("{lim:?} d={d}: {e}"));
        let want = ruckig_rest_to_rest(&mut otg, d, &lim);
        let got = prof.duration();
        assert!(
            (got - want).abs() <= 1e-9 * want,
            "{lim:?} d={d}: duration {got} against rsruckig {want}"
        );
        let end = prof.end();
        assert!(
            (end.p - (p0 + d)).abs() <= 1e-9 * (1.0 + d.abs()),
            "{end:?}"
        );
        assert!(end.v.abs() <= 1e-9 * lim.vmax, "{end:?}");
        // The limits hold at every phase start and at the end (the extremes of a and v
        // of these profiles are at phase boundaries).
        let (a_hi, a_lo) = if d >= 0.0 {
            (lim.amax, lim.dmax)
        } else {
            (lim.dmax, lim.amax)
        };
        for (ph, st) in prof.phases().iter().zip(prof.phase_starts()) {
            assert!(ph.duration > 0.0 && ph.jerk.abs() <= lim.jmax * (1.0 + 1e-12));
            let e = st.integrate(ph.duration, ph.jerk);
            for s in [*st, e] {
                assert!(s.v.abs() <= lim.vmax * (1.0 + 1e-9), "{lim:?} d={d}: {s:?}");
                assert!(
                    s.a <= a_hi * (1.0 + 1e-9) && -s.a <= a_lo * (1.0 + 1e-9),
                    "{lim:?} d={d}: {s:?}"
                );
            }
        }
    }
}

#[test]
fn line_limits_are_the_projected_axis_limits() {
    let mut rng = Rng(0x11AE_0016);
    for k in 0..5_000 {
        let n = 1 + k % 6;
        let start: Vec<f64> = (0..n).map(|_| rng.range(-1000.0, 1000.0)).collect();
        let mut end: Vec<f64> = start.iter().map(|x| x + rng.range(-500.0, 500.0)).collect();
        // Some axes stand still.
        if n > 1 && k % 3 == 0 {
            end[0] = start[0];
        }
        let axes: Vec<Limits> = (0..n)
            .map(|i| Limits {
                vmax: rng.range(1.0, 100.0),
                amax: rng.range(1.0, 100.0),
                dmax: rng.range(1.0, 100.0),
                // Some axes without a jerk limit.
                jmax: if (k + i) % 5 == 0 {
                    0.0
                } else {
                    rng.range(1.0, 1000.0)
                },
            })
            .collect();
        let line = Line::plan(&start, &end, &axes).expect("plans");
        let want = path_limits(line.unit(), &axes).expect("valid");
        let got = line.limits();
        for (g, w) in [
            (got.vmax, want.vmax),
            (got.amax, want.amax),
            (got.dmax, want.dmax),
            (got.jmax, want.jmax),
        ] {
            assert!(
                g == w || (g - w).abs() <= 1e-12 * w,
                "line {k}: limits {got:?} against {want:?}"
            );
        }
        // Every axis within its own limits at the phase boundaries.
        let prof = line.profile();
        for (ph, st) in prof.phases().iter().zip(prof.phase_starts()) {
            let e = st.integrate(ph.duration, ph.jerk);
            for (u, ax) in line.unit().iter().zip(&axes) {
                let u = u.abs();
                for s in [*st, e] {
                    assert!(s.v * u <= ax.vmax * (1.0 + 1e-9), "line {k}: {s:?}");
                    assert!(s.a * u <= ax.amax * (1.0 + 1e-9), "line {k}: {s:?}");
                    assert!(-s.a * u <= ax.dmax * (1.0 + 1e-9), "line {k}: {s:?}");
                }
                if !ax.is_trapezoidal() {
                    assert!(ph.jerk.abs() * u <= ax.jmax * (1.0 + 1e-9), "line {k}");
                }
            }
        }
        assert!((prof.end().p - line.length()).abs() <= 1e-9 * (1.0 + line.length()));
    }
}
