//! Start states where the ruckig kernel finds no profile (found by the drive-script adapter at the end of a
//! braking ramp; rsruckig 3.0.1 fails on them too): the planner falls back to ramping the acceleration to
//! zero first, and the result reaches the target within the limits.

use motion_lib::profile::{Limits, Profile, State};

#[test]
fn end_of_braking_ramp_states_are_planned_by_the_fallback() {
    let lim = Limits {
        vmax: 1e5,
        amax: 1e6,
        dmax: 1e6,
        jmax: 1e8,
    };
    let start = State {
        p: 9986.809782194834,
        v: 4277.980650349764,
        a: -924984.3945007682,
    };
    for target in [20000.0, 10100.0] {
        let prof = Profile::position(start, target, 0.0, &lim).expect("a profile exists");
        let end = prof.end();
        assert!(
            (end.p - target).abs() <= 1e-9 * target.abs().max(1.0),
            "{end:?}"
        );
        assert!(end.v.abs() <= 1e-6 && end.a.abs() <= 1e-3, "{end:?}");
        // Limits hold on a fine sampling of the whole profile.
        let n = 20_000;
        for k in 0..=n {
            let s = prof.at(prof.duration() * k as f64 / n as f64);
            assert!(s.v.abs() <= lim.vmax * (1.0 + 1e-9));
            assert!(s.a.abs() <= lim.amax * (1.0 + 1e-9), "{s:?}");
        }
        // The first phase brings the acceleration to zero at full jerk.
        assert_eq!(prof.phases()[0].jerk, lim.jmax);
    }
}
