//! MC_GearIn within the slave's limits (README "Gearing"): a ratio whose product with the master's
//! axis limits leaves nothing of the slave's is refused with ErrorID 34 before anything moves; a
//! ratio that leaves room couples, and with the master accelerating at its own limits the slave's
//! set velocity and acceleration stay within the slave's limits every cycle.

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::*;
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::error::ErrorId;
use motion_lib::fsm::AxisState;
use motion_lib::profile::Limits;

fn axis(vmax: f64, amax: f64, jmax: f64) -> AxisConfig {
    AxisConfig {
        limits: Limits {
            vmax,
            amax,
            dmax: amax,
            jmax,
        },
        ..AxisConfig::default()
    }
}

/// An engine with a powered master (100 u/s, 1000 u/s², 10000 u/s³) and a powered slave with the
/// given limits.
fn engine(slave: AxisConfig) -> (Engine, usize, usize, McPower, McPower) {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let m = e.add_axis(axis(100.0, 1000.0, 10000.0)).unwrap();
    let s = e.add_axis(slave).unwrap();
    let (mut pm, mut ps) = (
        McPower {
            enable: true,
            ..Default::default()
        },
        McPower {
            enable: true,
            ..Default::default()
        },
    );
    pm.call(&mut e, m);
    ps.call(&mut e, s);
    e.step();
    (e, m, s, pm, ps)
}

fn gear(num: f64) -> McGearIn {
    McGearIn {
        execute: true,
        ratio_numerator: num,
        ratio_denominator: 1.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        jerk: 10000.0,
        ..Default::default()
    }
}

#[test]
fn a_ratio_that_leaves_nothing_of_the_slaves_limits_is_refused_with_34() {
    // the same limits as the master: a ratio of 1 uses all of them, 2 twice as much
    for (num, slave) in [
        (2.0, axis(100.0, 1000.0, 10000.0)),
        (1.0, axis(100.0, 1000.0, 10000.0)),
        // velocity fits, acceleration does not
        (0.5, axis(100.0, 400.0, 10000.0)),
        // velocity and acceleration fit, jerk does not
        (0.5, axis(100.0, 1000.0, 4000.0)),
        // a negative ratio counts by its size
        (-2.0, axis(100.0, 1000.0, 10000.0)),
    ] {
        let (mut e, m, s, ..) = engine(slave);
        let mut gi = gear(num);
        gi.call(&mut e, m, s);
        assert!(gi.error, "ratio {num}: not refused");
        assert_eq!(gi.error_id, ErrorId::GearBeyondSlaveLimits, "ratio {num}");
        assert_eq!(gi.error_id.code(), 34);
        assert_eq!(
            e.axis_state(s).unwrap(),
            AxisState::Standstill,
            "ratio {num}"
        );
    }
}

#[test]
fn a_ratio_that_fits_keeps_the_slave_within_its_limits_while_the_master_runs_at_its_own() {
    let slave = axis(100.0, 1000.0, 10000.0);
    let (mut e, m, s, ..) = engine(slave);
    let mut gi = gear(-0.6);
    gi.call(&mut e, m, s);
    assert!(gi.busy && !gi.error, "{:?}", gi.error_id);
    // the master accelerates at its limits to its full velocity, then reverses
    let mut mv = McMoveVelocity {
        execute: true,
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        jerk: 10000.0,
        ..Default::default()
    };
    let (mut vmax, mut amax) = (0.0f64, 0.0f64);
    let mut in_gear = false;
    for cycle in 0..3000 {
        if cycle == 1500 {
            mv = McMoveVelocity {
                direction: motion_lib::buffer::Direction::Negative,
                ..mv
            };
            mv.execute = false;
            mv.call(&mut e, m);
            mv.execute = true;
        }
        mv.call(&mut e, m);
        gi.call(&mut e, m, s);
        in_gear |= gi.in_gear;
        e.step();
        vmax = vmax.max(e.set_velocity_of(s).unwrap().abs());
        amax = amax.max(e.set_acceleration_of(s).unwrap().abs());
    }
    assert!(in_gear, "never in gear");
    assert!(
        vmax <= slave.limits.vmax * (1.0 + 1e-9),
        "slave velocity {vmax}"
    );
    assert!(
        amax <= slave.limits.amax * (1.0 + 1e-9),
        "slave acceleration {amax}"
    );
    // the slave followed: 0.6 of the master's 100 u/s
    assert!(vmax >= 59.0, "slave velocity {vmax}");
}
