//! Single-axis block behaviour: relative/additive targets, ContinuousUpdate, velocity
//! blending, Halt, software limits, override, SetPosition, a real Drive.

use motion_lib::axis::{AxisConfig, Drive};
use motion_lib::blocks::*;
use motion_lib::buffer::BufferMode;
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::error::ErrorId;
use motion_lib::fsm::AxisState;

fn powered(cfg: AxisConfig) -> (Engine, usize) {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let a = e.add_axis(cfg).unwrap();
    McPower {
        enable: true,
        ..Default::default()
    }
    .call(&mut e, a);
    (e, a)
}

fn until(e: &mut Engine, max: usize, mut f: impl FnMut(&mut Engine) -> bool) {
    for _ in 0..max {
        e.step();
        if f(e) {
            return;
        }
    }
    panic!("condition not reached");
}

fn rel(d: f64, bm: BufferMode) -> McMoveRelative {
    McMoveRelative {
        execute: true,
        distance: d,
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        buffer_mode: bm,
        ..Default::default()
    }
}

#[test]
fn relative_adds_to_set_position_additive_to_last_target() {
    let (mut e, a) = powered(AxisConfig::default());
    let mut m = McMoveAbsolute {
        execute: true,
        position: 100.0,
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    m.call(&mut e, a);
    for _ in 0..100 {
        e.step();
    }
    let here = e.set_position_of(a).unwrap();
    // Additive (aborting): last commanded target 100 + 10 = 110.
    let mut add = McMoveAdditive {
        execute: true,
        distance: 10.0,
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    add.call(&mut e, a);
    m.call(&mut e, a);
    assert!(m.command_aborted);
    until(&mut e, 5000, |e| {
        add.call(e, a);
        add.done
    });
    assert!((e.set_position_of(a).unwrap() - 110.0).abs() < 1e-9);
    assert!(here < 100.0);
    // Relative from the set position.
    let mut r = rel(-30.0, BufferMode::Aborting);
    r.call(&mut e, a);
    until(&mut e, 5000, |e| {
        r.call(e, a);
        r.done
    });
    assert!((e.set_position_of(a).unwrap() - 80.0).abs() < 1e-9);
}

#[test]
fn continuous_update_retargets_while_busy() {
    let (mut e, a) = powered(AxisConfig::default());
    let mut m = McMoveAbsolute {
        execute: true,
        continuous_update: true,
        position: 100.0,
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    m.call(&mut e, a);
    for _ in 0..200 {
        e.step();
        m.call(&mut e, a);
    }
    m.position = 50.0;
    until(&mut e, 5000, |e| {
        m.call(e, a);
        m.done
    });
    assert!((e.set_position_of(a).unwrap() - 50.0).abs() < 1e-9);
    // MoveVelocity with ContinuousUpdate changes the velocity.
    let mut v = McMoveVelocity {
        execute: true,
        continuous_update: true,
        velocity: 20.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    v.call(&mut e, a);
    until(&mut e, 1000, |e| {
        v.call(e, a);
        v.in_velocity
    });
    v.velocity = 40.0;
    v.call(&mut e, a);
    assert!(!v.in_velocity);
    until(&mut e, 1000, |e| {
        v.call(e, a);
        v.in_velocity
    });
    assert!((e.set_velocity_of(a).unwrap() - 40.0).abs() < 1e-9);
}

#[test]
fn after_move_velocity_blending_starts_at_in_velocity_from_v1() {
    let (mut e, a) = powered(AxisConfig::default());
    let mut v = McMoveVelocity {
        execute: true,
        velocity: 30.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    let mut m = McMoveAbsolute {
        execute: true,
        position: 100.0,
        velocity: 60.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        buffer_mode: BufferMode::BlendingNext,
        ..Default::default()
    };
    v.call(&mut e, a);
    m.call(&mut e, a);
    assert!(m.busy && !m.active);
    let mut v_at_start = None;
    until(&mut e, 20000, |e| {
        v.call(e, a);
        m.call(e, a);
        if m.active && v_at_start.is_none() {
            v_at_start = Some(e.set_velocity_of(a).unwrap());
            assert!(v.command_aborted);
        }
        m.done
    });
    assert!((v_at_start.unwrap() - 30.0).abs() < 1.0);
    assert!((e.set_position_of(a).unwrap() - 100.0).abs() < 1e-9);
}

#[test]
fn halt_is_discrete_and_abortable() {
    let (mut e, a) = powered(AxisConfig::default());
    let mut v = McMoveVelocity {
        execute: true,
        velocity: 50.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    v.call(&mut e, a);
    for _ in 0..100 {
        e.step();
    }
    let mut h = McHalt {
        execute: true,
        deceleration: 100.0,
        ..Default::default()
    };
    h.call(&mut e, a);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::DiscreteMotion);
    e.step();
    let mut m = McMoveAbsolute {
        execute: true,
        position: 0.0,
        velocity: 10.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    m.call(&mut e, a);
    h.call(&mut e, a);
    assert!(h.command_aborted && !h.done);
}

#[test]
fn software_limits() {
    let cfg = AxisConfig {
        sw_limits_enabled: true,
        sw_limit_pos: 100.0,
        sw_limit_neg: -100.0,
        ..AxisConfig::default()
    };
    let (mut e, a) = powered(cfg);
    let mut m = McMoveAbsolute {
        execute: true,
        position: 150.0,
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    m.call(&mut e, a);
    assert_eq!(m.error_id, ErrorId::TargetBeyondSoftwareLimit);
    let mut v = McMoveVelocity {
        execute: true,
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    v.call(&mut e, a);
    until(&mut e, 5000, |e| {
        e.axis_state(a).unwrap() == AxisState::ErrorStop
    });
    v.call(&mut e, a);
    assert!(v.error && v.error_id == ErrorId::SoftwareLimitPositive);
    assert_eq!(e.axis_error(a).unwrap(), ErrorId::SoftwareLimitPositive);
}

#[test]
fn override_scales_velocity_and_set_position_shifts() {
    let (mut e, a) = powered(AxisConfig::default());
    let mut v = McMoveVelocity {
        execute: true,
        velocity: 40.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    v.call(&mut e, a);
    until(&mut e, 1000, |e| {
        v.call(e, a);
        v.in_velocity
    });
    let mut o = McSetOverride {
        enable: true,
        vel_factor: 0.5,
        ..Default::default()
    };
    o.call(&mut e, a);
    assert!(o.enabled);
    for _ in 0..200 {
        e.step();
    }
    assert!((e.set_velocity_of(a).unwrap() - 20.0).abs() < 1e-9);
    let mut bad = McSetOverride {
        enable: true,
        vel_factor: -1.0,
        ..Default::default()
    };
    bad.call(&mut e, a);
    assert_eq!(bad.error_id, ErrorId::InvalidOverride);
    let mut sp = McSetPosition {
        execute: true,
        position: 1000.0,
        ..Default::default()
    };
    sp.call(&mut e, a);
    assert!(sp.done);
    assert!((e.set_position_of(a).unwrap() - 1000.0).abs() < 1e-9);
    e.step();
    assert!(
        e.set_position_of(a).unwrap() > 1000.0,
        "motion continues from the new origin"
    );
}

/// A drive that lags one cycle and can fault.
struct LagDrive {
    on: bool,
    p: f64,
    v: f64,
    fault: Option<u16>,
}

impl Drive for LagDrive {
    fn set_enable(&mut self, on: bool) {
        self.on = on;
    }
    fn enabled(&self) -> bool {
        self.on
    }
    fn write(&mut self, p: f64, v: f64, _a: f64) {
        self.p = p;
        self.v = v;
    }
    fn actual_position(&self) -> f64 {
        self.p
    }
    fn actual_velocity(&self) -> f64 {
        self.v
    }
    fn fault(&self) -> Option<u16> {
        self.fault
    }
    fn reset_fault(&mut self) {
        self.fault = None;
    }
}

#[test]
fn real_drive_follows_the_set_point() {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let a = e
        .add_axis_with_drive(
            AxisConfig::default(),
            Box::new(LagDrive {
                on: false,
                p: 5.0,
                v: 0.0,
                fault: None,
            }),
        )
        .unwrap();
    assert_eq!(e.actual_position(a).unwrap(), 5.0);
    let mut p = McPower {
        enable: true,
        ..Default::default()
    };
    p.call(&mut e, a);
    assert!(p.status);
    let mut m = McMoveRelative {
        execute: true,
        distance: 1.0,
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    m.call(&mut e, a);
    until(&mut e, 1000, |e| {
        m.call(e, a);
        m.done
    });
    e.step();
    assert!((e.actual_position(a).unwrap() - 6.0).abs() < 1e-9);
    assert_eq!(e.drive_fault_code(a).unwrap(), 0);
}

#[test]
fn bad_configurations_are_refused_with_their_codes() {
    use motion_lib::axis::{AxisKind, ConfigError};
    use motion_lib::profile::Limits;
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let bad_limits = AxisConfig {
        limits: Limits {
            vmax: 0.0,
            amax: 1.0,
            dmax: 1.0,
            jmax: 0.0,
        },
        ..AxisConfig::default()
    };
    assert_eq!(e.add_axis(bad_limits), Err(ConfigError::InvalidLimits));
    let bad_sw = AxisConfig {
        sw_limits_enabled: true,
        sw_limit_neg: 1.0,
        sw_limit_pos: -1.0,
        ..AxisConfig::default()
    };
    assert_eq!(e.add_axis(bad_sw).unwrap_err().code(), "E5002");
    let bad_mod = AxisConfig {
        kind: AxisKind::Modulo { period: 0.0 },
        ..AxisConfig::default()
    };
    assert_eq!(e.add_axis(bad_mod).unwrap_err().code(), "E5003");
    let bad_fe = AxisConfig {
        following_error_limit: f64::NAN,
        ..AxisConfig::default()
    };
    assert_eq!(e.add_axis(bad_fe).unwrap_err().code(), "E5004");
    assert_eq!(
        Engine::new(EngineConfig {
            cycle: 0.0,
            queue_depth: 1
        })
        .err()
        .map(|c| c.code()),
        Some("E5005")
    );
    assert_eq!(e.axis_count(), 0);
}

#[test]
fn engine_is_deterministic() {
    let run = || {
        let (mut e, a) = powered(AxisConfig::default());
        let mut m1 = McMoveAbsolute {
            execute: true,
            position: 30.0,
            velocity: 80.0,
            acceleration: 900.0,
            deceleration: 700.0,
            jerk: 9000.0,
            ..Default::default()
        };
        let mut m2 = McMoveAbsolute {
            buffer_mode: BufferMode::BlendingHigh,
            position: 60.0,
            ..m1
        };
        let mut trace = Vec::new();
        for k in 0..3000 {
            m1.call(&mut e, a);
            m2.call(&mut e, a);
            if k == 700 {
                let mut v = McMoveVelocity {
                    execute: true,
                    velocity: 10.0,
                    acceleration: 100.0,
                    deceleration: 100.0,
                    ..Default::default()
                };
                v.call(&mut e, a);
            }
            e.step();
            trace.push((
                e.set_position_of(a).unwrap().to_bits(),
                e.set_velocity_of(a).unwrap().to_bits(),
            ));
        }
        trace
    };
    assert_eq!(run(), run());
}
