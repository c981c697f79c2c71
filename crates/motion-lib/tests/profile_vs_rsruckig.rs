//! Side-by-side check against rsruckig (the Rust port of ruckig) on seeded random
//! problems: wherever rsruckig finds a trajectory, the planner must find one of the
//! same duration (1e-6 relative).

mod profile_common;
use motion_lib::profile::Profile;
use profile_common::{random_problem, Problem, Rng};
use rsruckig::prelude::*;

/// rsruckig's duration for `pb`, or None when it reports an error.
fn ruckig_duration(otg: &mut Ruckig<1, IgnoreErrorHandler>, pb: &Problem) -> Option<f64> {
    ruckig_duration_at_least(otg, pb, None)
}

/// rsruckig's duration for `pb` with a minimum duration.
fn ruckig_duration_at_least(
    otg: &mut Ruckig<1, IgnoreErrorHandler>,
    pb: &Problem,
    minimum: Option<f64>,
) -> Option<f64> {
    let mut input = InputParameter::new(None);
    let lim = &pb.lim;
    // Acceleration bounds in the direction of travel (amax) and against it (dmax).
    let (amax, amin) = if pb.target_p >= pb.start.p {
        (lim.amax, -lim.dmax)
    } else {
        (lim.dmax, -lim.amax)
    };
    input.current_position[0] = pb.start.p;
    input.current_velocity[0] = pb.start.v;
    input.current_acceleration[0] = pb.start.a;
    input.target_position[0] = pb.target_p;
    input.target_velocity[0] = pb.target_v;
    input.max_velocity[0] = lim.vmax;
    input.max_acceleration[0] = amax;
    input.min_acceleration = Some(daov_stack![amin]);
    input.max_jerk[0] = if lim.is_trapezoidal() {
        f64::INFINITY
    } else {
        lim.jmax
    };
    input.minimum_duration = minimum;
    let mut traj = Trajectory::new(None);
    match otg.calculate(&input, &mut traj) {
        Ok(RuckigResult::Working) | Ok(RuckigResult::Finished) => Some(traj.get_duration()),
        _ => None,
    }
}

fn compare(seed: u64, n: usize, beyond: bool, trapezoidal: bool) {
    let mut otg = Ruckig::<1, IgnoreErrorHandler>::new(None, 0.001);
    let mut rng = Rng(seed);
    let (mut both, mut ruckig_failed) = (0, 0);
    for _ in 0..n {
        let pb = random_problem(&mut rng, beyond, trapezoidal);
        let Some(want) = ruckig_duration(&mut otg, &pb) else {
            ruckig_failed += 1;
            continue;
        };
        let got = Profile::position(pb.start, pb.target_p, pb.target_v, &pb.lim)
            .unwrap_or_else(|e| panic!("{pb:?}: {e} (rsruckig: {want})"))
            .duration();
        assert!(
            (got - want).abs() <= 1e-6 * want.max(1e-3),
            "{pb:?}: duration {got}, rsruckig {want}"
        );
        both += 1;
    }
    eprintln!("seed {seed}: {both} durations equal to rsruckig's, {ruckig_failed} problems rsruckig rejects");
    assert!(both >= n * 9 / 10, "rsruckig solved only {both} of {n}");
}

#[test]
fn jerk_limited_durations_equal_rsruckig() {
    compare(11, 20_000, false, false);
}

#[test]
fn jerk_limited_from_beyond_limits_equal_rsruckig() {
    compare(12, 5_000, true, false);
}

#[test]
fn trapezoidal_durations_equal_rsruckig() {
    compare(13, 5_000, false, true);
}

/// ruckig synchronises to the first possible duration >= the requested one: where it
/// gives exactly the requested duration, `with_duration` must succeed; where it jumps
/// past a blocked interval, `with_duration` must report the duration unreachable.
#[test]
fn with_duration_agrees_with_rsruckig_minimum_duration() {
    let mut otg = Ruckig::<1, IgnoreErrorHandler>::new(None, 0.001);
    let mut rng = Rng(14);
    let (mut equal, mut blocked) = (0, 0);
    for i in 0..5_000 {
        let pb = random_problem(&mut rng, false, i % 5 == 0);
        let Some(t_min) = ruckig_duration(&mut otg, &pb) else {
            continue;
        };
        let t = t_min * rng.range(1.0, 2.0) + rng.range(0.0, 1.0);
        let Some(want) = ruckig_duration_at_least(&mut otg, &pb, Some(t)) else {
            continue;
        };
        let got = Profile::with_duration(pb.start, pb.target_p, pb.target_v, &pb.lim, t);
        if (want - t).abs() <= 1e-9 * t {
            let got = got.unwrap_or_else(|e| panic!("{pb:?} t = {t}: {e}"));
            assert!((got.duration() - t).abs() <= 1e-9 * t);
            equal += 1;
        } else {
            assert!(want > t, "{pb:?}: rsruckig {want} < {t}");
            assert!(
                got.is_err(),
                "{pb:?}: planned {t} where rsruckig needs {want}"
            );
            blocked += 1;
        }
    }
    eprintln!("with_duration vs rsruckig: {equal} equal, {blocked} blocked");
    assert!(equal > 3_000);
}

/// Velocity profiles against rsruckig's velocity interface (same acceleration bounds:
/// `amax` in the direction of the target velocity, `dmax` against it).
#[test]
fn velocity_durations_equal_rsruckig() {
    let mut otg = Ruckig::<1, IgnoreErrorHandler>::new(None, 0.001);
    let mut rng = Rng(15);
    let mut both = 0;
    for i in 0..10_000 {
        let pb = random_problem(&mut rng, i % 2 == 0, i % 7 == 0);
        let lim = &pb.lim;
        let dir = if pb.target_v != 0.0 {
            pb.target_v.signum()
        } else if pb.start.v != 0.0 {
            pb.start.v.signum()
        } else {
            1.0
        };
        let (amax, amin) = if dir > 0.0 {
            (lim.amax, -lim.dmax)
        } else {
            (lim.dmax, -lim.amax)
        };
        let mut input = InputParameter::new(None);
        input.control_interface = ControlInterface::Velocity;
        input.current_position[0] = pb.start.p;
        input.current_velocity[0] = pb.start.v;
        input.current_acceleration[0] = pb.start.a;
        input.target_velocity[0] = pb.target_v;
        input.max_velocity[0] = lim.vmax.max(pb.start.v.abs());
        input.max_acceleration[0] = amax;
        input.min_acceleration = Some(daov_stack![amin]);
        input.max_jerk[0] = if lim.is_trapezoidal() {
            f64::INFINITY
        } else {
            lim.jmax
        };
        let mut traj = Trajectory::new(None);
        let Ok(RuckigResult::Working | RuckigResult::Finished) = otg.calculate(&input, &mut traj)
        else {
            continue;
        };
        let want = traj.get_duration();
        let got = Profile::velocity(pb.start, pb.target_v, lim)
            .unwrap_or_else(|e| panic!("{pb:?}: {e}"))
            .duration();
        assert!(
            (got - want).abs() <= 1e-6 * want.max(1e-3),
            "{pb:?}: duration {got}, rsruckig {want}"
        );
        both += 1;
    }
    eprintln!("velocity: {both} durations equal to rsruckig's");
    assert!(both > 9_000);
}

/// Rest-to-rest moves of every length (short triangular, trapezoidal, mixed, cruising),
/// asymmetric acceleration limits.
#[test]
fn rest_to_rest_durations_equal_rsruckig() {
    use motion_lib::profile::{Limits, State};
    let mut otg = Ruckig::<1, IgnoreErrorHandler>::new(None, 0.001);
    let mut rng = Rng(16);
    for _ in 0..10_000 {
        let lim = Limits {
            vmax: rng.range(0.5, 100.0),
            amax: rng.range(0.2, 20.0),
            dmax: rng.range(0.2, 20.0),
            jmax: rng.range(0.1, 100.0),
        };
        let start = State {
            p: rng.range(-100.0, 100.0),
            v: 0.0,
            a: 0.0,
        };
        let dist = 10f64.powf(rng.range(-6.0, 4.0)) * if rng.chance(0.5) { 1.0 } else { -1.0 };
        let pb = Problem {
            start,
            target_p: start.p + dist,
            target_v: 0.0,
            lim,
        };
        let want = ruckig_duration(&mut otg, &pb).expect("rsruckig plans rest to rest");
        let got = Profile::position(pb.start, pb.target_p, 0.0, &lim)
            .unwrap()
            .duration();
        assert!(
            (got - want).abs() <= 1e-9 * want.max(1e-3),
            "{pb:?}: duration {got}, rsruckig {want}"
        );
    }
}
