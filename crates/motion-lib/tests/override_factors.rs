//! MC_SetOverride VelFactor, AccFactor and JerkFactor: a running move re-plans with the
//! scaled limits from its current state (position, velocity and acceleration continuous,
//! the jerk within the limit in force) and reaches its target; VelFactor 0 holds the move
//! on its way until the factor returns; MC_Stop is not overridden; bad factors are
//! refused.

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::*;
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::error::ErrorId;

const DT: f64 = 0.001;
const AMAX: f64 = 500.0;
const JMAX: f64 = 5000.0;

fn powered() -> (Engine, usize) {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let a = e.add_axis(AxisConfig::default()).unwrap();
    McPower {
        enable: true,
        ..Default::default()
    }
    .call(&mut e, a);
    (e, a)
}

fn move_to(p: f64) -> McMoveAbsolute {
    McMoveAbsolute {
        execute: true,
        position: p,
        velocity: 50.0,
        acceleration: AMAX,
        deceleration: AMAX,
        jerk: JMAX,
        ..Default::default()
    }
}

/// Runs `mv` to Done; `at(cycle, engine)` may call blocks. Returns the per-cycle set
/// accelerations and the number of cycles.
fn run(
    e: &mut Engine,
    a: usize,
    mv: &mut McMoveAbsolute,
    mut at: impl FnMut(usize, &mut Engine),
) -> (Vec<f64>, usize) {
    mv.call(e, a);
    let mut acc = vec![e.set_acceleration_of(a).unwrap()];
    let mut prev_v = e.set_velocity_of(a).unwrap();
    for k in 0..20_000 {
        at(k, e);
        e.step();
        mv.call(e, a);
        let (v, ac) = (
            e.set_velocity_of(a).unwrap(),
            e.set_acceleration_of(a).unwrap(),
        );
        // Velocity continuous (bounded by the largest acceleration).
        assert!((v - prev_v).abs() <= AMAX * DT * (1.0 + 1e-9) + 1e-12);
        prev_v = v;
        acc.push(ac);
        if mv.done {
            return (acc, k + 1);
        }
    }
    panic!("move not done");
}

fn max_jerk(acc: &[f64]) -> f64 {
    acc.windows(2)
        .map(|w| (w[1] - w[0]).abs() / DT)
        .fold(0.0, f64::max)
}

#[test]
fn acc_and_jerk_factor_replan_a_cruising_move() {
    let (mut e, a) = powered();
    let (_, plain) = run(&mut e, a, &mut move_to(100.0), |_, _| {});
    let (mut e, a) = powered();
    let mut o = McSetOverride {
        enable: true,
        vel_factor: 1.0,
        acc_factor: 0.5,
        jerk_factor: 0.25,
        ..Default::default()
    };
    let change = 400; // cruising at 50 by then (two 0.1 s jerk phases)
    let (acc, n) = run(&mut e, a, &mut move_to(100.0), |k, e| {
        if k == change {
            assert!(
                (e.set_velocity_of(a).unwrap() - 50.0).abs() < 1e-9,
                "cruising"
            );
            o.call(e, a);
            assert!(o.enabled && o.busy && !o.error);
        }
    });
    assert!((e.set_position_of(a).unwrap() - 100.0).abs() < 1e-9);
    let after = &acc[change + 1..];
    let amax_after = after.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    assert!(amax_after <= 0.5 * AMAX * (1.0 + 1e-9), "{amax_after}");
    assert!(
        amax_after > 0.49 * AMAX,
        "the scaled limit is used: {amax_after}"
    );
    assert!(
        max_jerk(after) <= 0.25 * JMAX * (1.0 + 1e-6),
        "{}",
        max_jerk(after)
    );
    assert!(max_jerk(&acc) <= JMAX * (1.0 + 1e-6));
    assert!(n > plain, "lower limits take longer: {n} vs {plain}");
    assert_eq!(e.override_factors(a).unwrap(), (1.0, 0.5, 0.25));
}

#[test]
fn acc_factor_while_accelerating_has_no_acceleration_step() {
    let (mut e, a) = powered();
    let mut o = McSetOverride {
        enable: true,
        vel_factor: 1.0,
        acc_factor: 0.3,
        jerk_factor: 1.0,
        ..Default::default()
    };
    let change = 99; // at the acceleration peak (a = 500 after the 0.1 s jerk ramp)
    let (acc, _) = run(&mut e, a, &mut move_to(100.0), |k, e| {
        if k == change {
            assert!(e.set_acceleration_of(a).unwrap() > 0.95 * AMAX);
            o.call(e, a);
        }
    });
    assert!((e.set_position_of(a).unwrap() - 100.0).abs() < 1e-9);
    // The acceleration comes down with the jerk limit: no step.
    assert!(max_jerk(&acc) <= JMAX * (1.0 + 1e-6), "{}", max_jerk(&acc));
    // Once down (500 -> 150 at 5000/s^3: 0.07 s), it stays within the scaled limit.
    let settled = &acc[change + 1 + 80..];
    let m = settled.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    assert!(m <= 0.3 * AMAX * (1.0 + 1e-9), "{m}");
}

#[test]
fn factors_apply_to_later_moves_and_velocity_moves() {
    let (mut e, a) = powered();
    let mut o = McSetOverride {
        enable: true,
        vel_factor: 1.0,
        acc_factor: 0.2,
        jerk_factor: 0.0, // 0 stands for 1
        ..Default::default()
    };
    o.call(&mut e, a);
    assert_eq!(e.override_factors(a).unwrap(), (1.0, 0.2, 1.0));
    let mut v = McMoveVelocity {
        execute: true,
        velocity: 40.0,
        acceleration: AMAX,
        deceleration: AMAX,
        jerk: JMAX,
        ..Default::default()
    };
    v.call(&mut e, a);
    let mut peak: f64 = 0.0;
    for _ in 0..2000 {
        e.step();
        v.call(&mut e, a);
        peak = peak.max(e.set_acceleration_of(a).unwrap().abs());
        if v.in_velocity {
            break;
        }
    }
    assert!(v.in_velocity);
    assert!(
        peak <= 0.2 * AMAX * (1.0 + 1e-9) && peak > 0.19 * AMAX,
        "{peak}"
    );
    // A new AccFactor at constant velocity keeps InVelocity; a new VelFactor drops it
    // until the new velocity (40 * 0.5) is reached.
    // (Both blocks in the same scan, the override first.)
    o.acc_factor = 0.5;
    o.call(&mut e, a);
    v.call(&mut e, a);
    assert!(v.in_velocity);
    e.step();
    o.vel_factor = 0.5;
    o.call(&mut e, a);
    v.call(&mut e, a);
    assert!(!v.in_velocity && v.busy && v.active);
    for _ in 0..2000 {
        e.step();
        v.call(&mut e, a);
    }
    assert!(v.in_velocity && (e.set_velocity_of(a).unwrap() - 20.0).abs() < 1e-9);
    // Enable FALSE: outputs reset, the factors stay.
    o.enable = false;
    o.call(&mut e, a);
    assert!(!o.enabled && !o.busy && !o.error);
    assert_eq!(e.override_factors(a).unwrap(), (0.5, 0.5, 1.0));
}

#[test]
fn bad_factors_are_refused() {
    let (mut e, a) = powered();
    for (acc, jerk) in [
        (1.5, 1.0),
        (-0.1, 1.0),
        (f64::NAN, 1.0),
        (1.0, 2.0),
        (1.0, -1.0),
    ] {
        let mut o = McSetOverride {
            enable: true,
            vel_factor: 1.0,
            acc_factor: acc,
            jerk_factor: jerk,
            ..Default::default()
        };
        o.call(&mut e, a);
        assert!(o.error && !o.enabled && !o.busy, "{acc} {jerk}");
        assert_eq!(o.error_id, ErrorId::InvalidOverride);
    }
    assert_eq!(e.override_factors(a).unwrap(), (1.0, 1.0, 1.0));
}

#[test]
fn vel_factor_slows_a_running_move_without_an_acceleration_step() {
    let (mut e, a) = powered();
    let (_, plain) = run(&mut e, a, &mut move_to(100.0), |_, _| {});
    let (mut e, a) = powered();
    let mut o = McSetOverride {
        enable: true,
        vel_factor: 0.5,
        ..Default::default()
    };
    let mut peak_after: f64 = 0.0;
    let (acc, n) = run(&mut e, a, &mut move_to(100.0), |k, e| {
        if k == 400 {
            o.call(e, a);
            assert!(o.enabled && !o.error);
        }
        if k > 700 {
            peak_after = peak_after.max(e.set_velocity_of(a).unwrap().abs());
        }
    });
    assert!((e.set_position_of(a).unwrap() - 100.0).abs() < 1e-9);
    assert!(
        (peak_after - 25.0).abs() < 1e-9,
        "cruises at 50 * 0.5: {peak_after}"
    );
    assert!(max_jerk(&acc) <= JMAX * (1.0 + 1e-6), "{}", max_jerk(&acc));
    let amax = acc.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    assert!(amax <= AMAX * (1.0 + 1e-9), "{amax}");
    assert!(n > plain);
}

#[test]
fn vel_factor_zero_holds_the_move_until_it_returns() {
    let (mut e, a) = powered();
    let mut o = McSetOverride {
        enable: true,
        vel_factor: 0.0,
        ..Default::default()
    };
    let mut held = 0;
    let mut mv = move_to(100.0);
    let (acc, _) = run(&mut e, a, &mut mv, |k, e| {
        if k == 300 {
            o.call(e, a);
        }
        if (800..3000).contains(&k) {
            // Standing on the way, still Busy, not Done.
            assert!(e.set_velocity_of(a).unwrap().abs() < 1e-12, "{k}");
            let p = e.set_position_of(a).unwrap();
            assert!(p > 1.0 && p < 99.0, "{p}");
            held += 1;
        }
        if k == 3000 {
            o.vel_factor = 1.0;
            o.call(e, a);
        }
    });
    assert_eq!(held, 2200);
    assert!((e.set_position_of(a).unwrap() - 100.0).abs() < 1e-9);
    assert!(max_jerk(&acc) <= JMAX * (1.0 + 1e-6), "{}", max_jerk(&acc));
}

#[test]
fn stop_is_not_overridden_and_factors_above_one_keep_the_axis_limit() {
    let (mut e, a) = powered();
    let mut v = McMoveVelocity {
        execute: true,
        velocity: 800.0,
        acceleration: 5000.0,
        deceleration: 5000.0,
        ..Default::default()
    };
    let mut o = McSetOverride {
        enable: true,
        vel_factor: 2.0,
        ..Default::default()
    };
    o.call(&mut e, a);
    v.call(&mut e, a);
    let mut vmax: f64 = 0.0;
    for _ in 0..2000 {
        e.step();
        v.call(&mut e, a);
        vmax = vmax.max(e.set_velocity_of(a).unwrap());
    }
    // 800 * 2 is capped by the axis limit 1000.
    assert!(v.in_velocity && (vmax - 1000.0).abs() < 1e-9, "{vmax}");
    // VelFactor 0 does not freeze MC_Stop.
    o.vel_factor = 0.0;
    o.call(&mut e, a);
    let mut stop = McStop {
        execute: true,
        deceleration: 5000.0,
        ..Default::default()
    };
    stop.call(&mut e, a);
    for _ in 0..2000 {
        e.step();
        stop.call(&mut e, a);
        if stop.done {
            break;
        }
    }
    assert!(stop.done && e.set_velocity_of(a).unwrap() == 0.0);
}
