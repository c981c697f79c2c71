//! Software position limits: refused targets and paths, velocity moves that stop at the
//! limit, recovery with MC_Reset; buffered MC_MoveRelative / MC_MoveAdditive bases; InVelocity
//! shown before a buffered successor takes over.

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::*;
use motion_lib::buffer::{BufferMode, Direction};
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::error::ErrorId;
use motion_lib::fsm::AxisState;
use motion_lib::profile::Limits;

const LIM: Limits = Limits {
    vmax: 100.0,
    amax: 100.0,
    dmax: 100.0,
    jmax: 1000.0,
};

fn axis(limits: Option<(f64, f64)>) -> (Engine, usize) {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let cfg = AxisConfig {
        limits: LIM,
        sw_limit_neg: limits.map_or(0.0, |l| l.0),
        sw_limit_pos: limits.map_or(0.0, |l| l.1),
        sw_limits_enabled: limits.is_some(),
        ..AxisConfig::default()
    };
    let a = e.add_axis(cfg).unwrap();
    let mut p = McPower {
        enable: true,
        ..Default::default()
    };
    p.call(&mut e, a);
    assert!(p.status);
    (e, a)
}

fn mv(pos: f64) -> McMoveAbsolute {
    McMoveAbsolute {
        execute: true,
        position: pos,
        velocity: 100.0,
        acceleration: 100.0,
        deceleration: 100.0,
        jerk: 1000.0,
        ..Default::default()
    }
}

fn vel(v: f64) -> McMoveVelocity {
    McMoveVelocity {
        execute: true,
        velocity: v,
        acceleration: 100.0,
        deceleration: 100.0,
        jerk: 1000.0,
        direction: Direction::Positive,
        ..Default::default()
    }
}

/// Steps until `done` (calling `call` each scan); returns the highest position seen.
fn run(e: &mut Engine, a: usize, max: usize, mut call: impl FnMut(&mut Engine) -> bool) -> f64 {
    let mut top = f64::NEG_INFINITY;
    for _ in 0..max {
        e.step();
        top = top.max(e.set_position_of(a).unwrap());
        if call(e) {
            return top;
        }
    }
    panic!("not reached in {max} cycles");
}

#[test]
fn target_beyond_the_limit_is_refused_before_any_motion() {
    let (mut e, a) = axis(Some((-10.0, 50.0)));
    let mut m = mv(60.0);
    m.call(&mut e, a);
    assert!(m.error && m.error_id == ErrorId::TargetBeyondSoftwareLimit);
    e.step();
    assert_eq!(e.set_position_of(a).unwrap(), 0.0);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Standstill);
}

#[test]
fn overshooting_path_is_refused_and_the_running_move_goes_on() {
    let (mut e, a) = axis(Some((-10.0, 50.0)));
    // On the way to 49 (inside the range): past 20 the axis is fast.
    let mut first = mv(49.0);
    first.call(&mut e, a);
    run(&mut e, a, 10_000, |e| {
        first.call(e, a);
        e.set_position_of(a).unwrap() >= 20.0
    });
    let here = e.set_position_of(a).unwrap();
    let v = e.set_velocity_of(a).unwrap();
    assert!(v > 30.0, "{v}");
    // Aborting to a target inside the range behind the axis, with a gentle jerk (100
    // mm/s^3; the axis still accelerates): the time-optimal path runs past the limit 50
    // before it turns back.
    let mut back = McMoveAbsolute {
        buffer_mode: BufferMode::Aborting,
        jerk: 100.0,
        ..mv(here - 5.0)
    };
    back.call(&mut e, a);
    assert!(back.error, "{:?}", back.error_id);
    assert_eq!(back.error_id, ErrorId::PathBeyondSoftwareLimit);
    // The running move was not aborted and ends at 45, inside the range.
    let top = run(&mut e, a, 10_000, |e| {
        first.call(e, a);
        first.done
    });
    assert!(top <= 49.0 + 1e-9, "{top}");
    assert!((e.set_position_of(a).unwrap() - 49.0).abs() < 1e-9);
}

#[test]
fn velocity_move_stops_at_the_limit_and_the_axis_recovers() {
    let (mut e, a) = axis(Some((-10.0, 50.0)));
    let mut v = vel(40.0);
    v.call(&mut e, a);
    assert!(v.busy);
    let mut saw_in_velocity = false;
    let top = run(&mut e, a, 10_000, |e| {
        v.call(e, a);
        saw_in_velocity |= v.in_velocity;
        v.error
    });
    assert!(saw_in_velocity);
    // Braked with the axis's deceleration and jerk: at rest exactly at the limit.
    assert!(top <= 50.0 + 1e-9, "{top}");
    assert!((e.set_position_of(a).unwrap() - 50.0).abs() < 1e-9);
    assert!(e.set_velocity_of(a).unwrap().abs() < 1e-9);
    assert_eq!(v.error_id, ErrorId::SoftwareLimitPositive);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::ErrorStop);
    // MC_Reset: Standstill, and it stays there.
    let mut r = McReset {
        execute: true,
        ..Default::default()
    };
    r.call(&mut e, a);
    assert!(r.done, "{:?}", r.error_id);
    for _ in 0..100 {
        e.step();
        assert_eq!(e.axis_state(a).unwrap(), AxisState::Standstill);
    }
    // Further out: refused.
    let mut out = mv(55.0);
    out.call(&mut e, a);
    assert_eq!(out.error_id, ErrorId::TargetBeyondSoftwareLimit);
    let mut outv = vel(10.0);
    outv.call(&mut e, a);
    assert_eq!(outv.error_id, ErrorId::TargetBeyondSoftwareLimit);
    // Back into the range: works.
    let mut back = mv(20.0);
    back.call(&mut e, a);
    assert!(back.busy, "{:?}", back.error_id);
    run(&mut e, a, 10_000, |e| {
        back.call(e, a);
        back.done
    });
    assert!((e.set_position_of(a).unwrap() - 20.0).abs() < 1e-9);
}

#[test]
fn axis_standing_beyond_a_limit_can_only_move_back() {
    let (mut e, a) = axis(None);
    let mut m = mv(80.0);
    m.call(&mut e, a);
    run(&mut e, a, 10_000, |e| {
        m.call(e, a);
        m.done
    });
    // The limits are switched on with the axis beyond the positive one.
    let cfg = AxisConfig {
        limits: LIM,
        sw_limit_neg: -10.0,
        sw_limit_pos: 50.0,
        sw_limits_enabled: true,
        ..AxisConfig::default()
    };
    e.configure_axis(a, cfg).unwrap();
    for _ in 0..10 {
        e.step();
    }
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Standstill);
    let mut further = mv(90.0);
    further.call(&mut e, a);
    assert_eq!(further.error_id, ErrorId::TargetBeyondSoftwareLimit);
    let mut back = mv(30.0);
    back.call(&mut e, a);
    assert!(back.busy, "{:?}", back.error_id);
    let mut top = 80.0_f64;
    run(&mut e, a, 10_000, |e| {
        back.call(e, a);
        top = top.max(e.set_position_of(a).unwrap());
        back.done
    });
    assert!(top <= 80.0 + 1e-9);
    assert!((e.set_position_of(a).unwrap() - 30.0).abs() < 1e-9);
}

#[test]
fn buffered_relative_counts_from_the_position_when_it_becomes_active() {
    let (mut e, a) = axis(None);
    let mut first = mv(300.0);
    first.call(&mut e, a);
    for _ in 0..100 {
        e.step();
        first.call(&mut e, a);
    }
    // Execute while the axis is on its way (near 26.25 here); buffered: it starts at 300.
    let mut rel = McMoveRelative {
        execute: true,
        distance: 50.0,
        velocity: 100.0,
        acceleration: 100.0,
        deceleration: 100.0,
        jerk: 1000.0,
        buffer_mode: BufferMode::Buffered,
        ..Default::default()
    };
    rel.call(&mut e, a);
    assert!(rel.busy);
    let mut low = f64::INFINITY;
    let mut after = false;
    run(&mut e, a, 20_000, |e| {
        first.call(e, a);
        rel.call(e, a);
        if first.done {
            after = true;
        }
        if after {
            low = low.min(e.set_position_of(a).unwrap());
        }
        rel.done
    });
    assert!((e.set_position_of(a).unwrap() - 350.0).abs() < 1e-9);
    // It never drove back.
    assert!(low >= 300.0 - 1e-9, "{low}");
}

#[test]
fn buffered_additive_adds_to_the_predecessors_target() {
    let (mut e, a) = axis(None);
    let mut first = mv(100.0);
    first.call(&mut e, a);
    e.step();
    let mut add = McMoveAdditive {
        execute: true,
        distance: 25.0,
        velocity: 100.0,
        acceleration: 100.0,
        deceleration: 100.0,
        jerk: 1000.0,
        buffer_mode: BufferMode::Buffered,
        ..Default::default()
    };
    add.call(&mut e, a);
    run(&mut e, a, 20_000, |e| {
        first.call(e, a);
        add.call(e, a);
        add.done
    });
    assert!((e.set_position_of(a).unwrap() - 125.0).abs() < 1e-9);
}

#[test]
fn in_velocity_is_shown_before_a_buffered_successor_takes_over() {
    let (mut e, a) = axis(None);
    let mut v = vel(50.0);
    v.call(&mut e, a);
    let mut next = McMoveAbsolute {
        buffer_mode: BufferMode::Buffered,
        ..mv(500.0)
    };
    next.call(&mut e, a);
    assert!(next.busy && !next.active);
    let mut in_velocity_scans = 0;
    run(&mut e, a, 20_000, |e| {
        v.call(e, a);
        next.call(e, a);
        if v.in_velocity {
            in_velocity_scans += 1;
            assert!(!next.active);
        }
        next.active
    });
    assert!(in_velocity_scans >= 1);
    assert!(v.command_aborted);
    // A successor given after InVelocity starts too (not left in the buffer).
    let (mut e, a) = axis(None);
    let mut v = vel(50.0);
    v.call(&mut e, a);
    run(&mut e, a, 20_000, |e| {
        v.call(e, a);
        v.in_velocity
    });
    let mut next = McMoveAbsolute {
        buffer_mode: BufferMode::Buffered,
        ..mv(500.0)
    };
    next.call(&mut e, a);
    run(&mut e, a, 20_000, |e| {
        v.call(e, a);
        next.call(e, a);
        next.done
    });
    assert!((e.set_position_of(a).unwrap() - 500.0).abs() < 1e-9);
}
