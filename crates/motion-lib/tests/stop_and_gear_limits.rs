//! MC_Stop and MC_GearIn against the axis limits, cycle by cycle: a stop asking for more
//! deceleration and jerk than the axis has is capped to the axis's; a stop with a low jerk
//! given while the axis accelerates towards its velocity limit gets the axis's jerk (else the
//! velocity would pass the limit); a slave coupled to an accelerating master (ratio times the
//! master's limits within half the slave's) catches up within its own limits.
//!
//! Input: 1 ms cycles, axis limits vmax 100, amax = dmax 1000, jmax 10000.
//! Output: assertions on every cycle's set velocity, acceleration and its change.

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::{McGearIn, McMoveVelocity, McPower, McStop};
use motion_lib::buffer::Direction;
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::fsm::AxisState;
use motion_lib::profile::Limits;

const LIM: Limits = Limits {
    vmax: 100.0,
    amax: 1000.0,
    dmax: 1000.0,
    jmax: 10000.0,
};

fn axis(e: &mut Engine, l: Limits) -> usize {
    let a = e
        .add_axis(AxisConfig {
            limits: l,
            ..AxisConfig::default()
        })
        .unwrap();
    let mut p = McPower {
        enable: true,
        ..Default::default()
    };
    p.call(e, a);
    a
}

/// Checks one cycle of `a` against `l` (previous acceleration in `prev`).
fn within(e: &Engine, a: usize, l: &Limits, prev: &mut Option<f64>) {
    let dt = e.config().cycle;
    let v = e.set_velocity_of(a).unwrap();
    let acc = e.set_acceleration_of(a).unwrap();
    assert!(v.abs() <= l.vmax * (1.0 + 1e-9), "v {v}");
    assert!(acc.abs() <= l.amax.max(l.dmax) * (1.0 + 1e-9), "a {acc}");
    if let Some(p) = *prev {
        let j = (acc - p).abs() / dt;
        assert!(j <= l.jmax * (1.0 + 1e-9), "jerk {j}");
    }
    *prev = Some(acc);
}

fn run_velocity(e: &mut Engine, a: usize, v: f64, cycles: usize) -> McMoveVelocity {
    let mut m = McMoveVelocity {
        execute: true,
        velocity: v,
        acceleration: 1000.0,
        deceleration: 1000.0,
        jerk: 10000.0,
        direction: Direction::Positive,
        ..Default::default()
    };
    for _ in 0..cycles {
        m.call(e, a);
        e.step();
    }
    m
}

#[test]
fn a_stop_asking_for_more_than_the_axis_has_is_capped_to_the_axis_limits() {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let a = axis(&mut e, LIM);
    let mut m = run_velocity(&mut e, a, 100.0, 500);
    assert!((e.set_velocity_of(a).unwrap() - 100.0).abs() < 1e-9);
    let mut stop = McStop {
        execute: true,
        deceleration: 1.0e5,
        jerk: 1.0e7,
        ..Default::default()
    };
    let mut prev = Some(e.set_acceleration_of(a).unwrap());
    let mut cycles = 0;
    let mut reported = Vec::new();
    for _ in 0..10_000 {
        m.call(&mut e, a);
        stop.call(&mut e, a);
        if stop.done {
            break;
        }
        e.step();
        cycles += 1;
        within(&e, a, &LIM, &mut prev);
        if let Some(r) = e.stop_reduction_now(a).unwrap() {
            reported.push((cycles, r));
        }
    }
    assert!(stop.done && m.command_aborted);
    // The cap is reported as a reduction: in the stop's first cycle only, and counted.
    assert_eq!(reported.len(), 1, "{reported:?}");
    let (at, r) = reported[0];
    assert_eq!(at, 1);
    assert_eq!(
        (r.deceleration_requested, r.deceleration_reached),
        (1.0e5, 1000.0)
    );
    assert_eq!((r.jerk_requested, r.jerk_reached), (1.0e7, 10000.0));
    let (kept, count) = e.stop_reductions(a).unwrap();
    assert_eq!((kept.len(), count), (1, 1));
    // A stop within the limits (Jerk 0 = the axis's) is not a reduction.
    stop.execute = false;
    stop.call(&mut e, a);
    let mut m2 = run_velocity(&mut e, a, 50.0, 1);
    for _ in 0..400 {
        m2.call(&mut e, a);
        e.step();
    }
    let mut soft = McStop {
        execute: true,
        deceleration: 500.0,
        jerk: 0.0,
        ..Default::default()
    };
    assert!(
        (e.set_velocity_of(a).unwrap() - 50.0).abs() < 1e-9,
        "moving again"
    );
    soft.call(&mut e, a);
    e.step();
    assert!(soft.busy, "{:?}", soft.error_id);
    assert_eq!(e.stop_reduction_now(a).unwrap(), None);
    assert_eq!(e.stop_reductions(a).unwrap().1, 1);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Stopping);
    // With the axis's own limits: 0.1 s of jerk, 0.1 s of deceleration, 0.1 s of jerk
    // (100 = 1000 * 0.1 + 1000 * 0.1 / 2 * 2), about 200 cycles (not 1 or 2).
    assert!((195..=205).contains(&cycles), "{cycles} cycles");
}

#[test]
fn a_low_jerk_stop_while_the_axis_accelerates_keeps_the_velocity_limit() {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let a = axis(&mut e, LIM);
    // Accelerating towards 100: 95 cycles in, v is about 45 and a 950; with a jerk of 100
    // the velocity would rise by 950^2 / 200 before braking.
    let mut m = run_velocity(&mut e, a, 100.0, 95);
    assert!(e.set_acceleration_of(a).unwrap() > 900.0);
    let mut stop = McStop {
        execute: true,
        deceleration: 1000.0,
        jerk: 100.0,
        ..Default::default()
    };
    let mut prev = Some(e.set_acceleration_of(a).unwrap());
    for _ in 0..100_000 {
        m.call(&mut e, a);
        stop.call(&mut e, a);
        if stop.done {
            break;
        }
        e.step();
        within(&e, a, &LIM, &mut prev);
    }
    assert!(stop.done);
}

#[test]
fn a_slave_coupled_to_an_accelerating_master_catches_up_within_its_limits() {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let slave = axis(&mut e, LIM);
    let ml = Limits {
        vmax: 25.0,
        amax: 250.0,
        dmax: 250.0,
        jmax: 2500.0,
    };
    let master = axis(&mut e, ml);
    let mut sv = McMoveVelocity {
        execute: true,
        velocity: 40.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        jerk: 10000.0,
        direction: Direction::Negative,
        ..Default::default()
    };
    let mut mv = McMoveVelocity {
        execute: true,
        velocity: 25.0,
        acceleration: 250.0,
        deceleration: 250.0,
        jerk: 2500.0,
        direction: Direction::Positive,
        ..Default::default()
    };
    let mut gear = McGearIn {
        ratio_numerator: 2.0,
        ratio_denominator: 1.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        jerk: 10000.0,
        ..Default::default()
    };
    let (mut ps, mut pm) = (None, None);
    for k in 0..3000 {
        // The slave runs at -40; the master starts at 100 and the gear couples at 110,
        // while the master accelerates.
        sv.call(&mut e, slave);
        mv.execute = k >= 100;
        mv.call(&mut e, master);
        gear.execute = k >= 110;
        gear.call(&mut e, master, slave);
        e.step();
        within(&e, slave, &LIM, &mut ps);
        within(&e, master, &ml, &mut pm);
    }
    assert!(gear.in_gear, "{gear:?}");
    let (vs, vm) = (
        e.set_velocity_of(slave).unwrap(),
        e.set_velocity_of(master).unwrap(),
    );
    assert!((vs - 2.0 * vm).abs() < 1e-9, "slave {vs} master {vm}");
}
