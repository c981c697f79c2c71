//! Single-axis and group state machines: every transition of PLCopen Part 1 fig. 2 and
//! of Part 4 exercised through the blocks; illegal commands rejected with their ErrorID.

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::*;
use motion_lib::buffer::{BufferMode, Direction};
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::error::ErrorId;
use motion_lib::fsm::{check_axis, check_group, AxisCmd, AxisState, GroupCmd, GroupState};
use motion_lib::sync::CamTable;

fn engine() -> (Engine, usize) {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let a = e.add_axis(AxisConfig::default()).unwrap();
    (e, a)
}

fn mv(pos: f64) -> McMoveAbsolute {
    McMoveAbsolute {
        execute: true,
        position: pos,
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        jerk: 10000.0,
        ..Default::default()
    }
}

fn run_until(e: &mut Engine, max: usize, mut f: impl FnMut(&mut Engine) -> bool) {
    for _ in 0..max {
        e.step();
        if f(e) {
            return;
        }
    }
    panic!("condition not reached");
}

#[test]
fn axis_transitions_through_blocks() {
    let (mut e, a) = engine();
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Disabled);
    // Disabled: motion rejected.
    let mut m = mv(10.0);
    m.call(&mut e, a);
    assert!(m.error && m.error_id == ErrorId::AxisDisabled);
    // Disabled -> Standstill.
    let mut p = McPower {
        enable: true,
        ..Default::default()
    };
    p.call(&mut e, a);
    assert!(p.status && p.valid);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Standstill);
    // Standstill -> Homing -> Standstill.
    let mut h = McHome {
        execute: true,
        position: 5.0,
        ..Default::default()
    };
    h.call(&mut e, a);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Homing);
    let mut m2 = mv(1.0);
    m2.call(&mut e, a);
    assert_eq!(m2.error_id, ErrorId::AxisHoming);
    run_until(&mut e, 10, |e| {
        h.call(e, a);
        h.done
    });
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Standstill);
    assert!((e.actual_position(a).unwrap() - 5.0).abs() < 1e-12);
    // Standstill -> DiscreteMotion -> Standstill (Done).
    let mut m = mv(20.0);
    m.call(&mut e, a);
    assert!(m.busy && m.active);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::DiscreteMotion);
    // Home while moving: rejected.
    let mut h2 = McHome {
        execute: true,
        ..Default::default()
    };
    h2.call(&mut e, a);
    assert_eq!(h2.error_id, ErrorId::NotStandstill);
    run_until(&mut e, 5000, |e| {
        m.call(e, a);
        m.done
    });
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Standstill);
    assert!((e.set_position_of(a).unwrap() - 20.0).abs() < 1e-9);
    // Standstill -> ContinuousMotion (MoveVelocity) -> DiscreteMotion (MoveAbsolute aborting).
    let mut v = McMoveVelocity {
        execute: true,
        velocity: 50.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        direction: Direction::Positive,
        ..Default::default()
    };
    v.call(&mut e, a);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::ContinuousMotion);
    run_until(&mut e, 1000, |e| {
        v.call(e, a);
        v.in_velocity
    });
    assert!((e.set_velocity_of(a).unwrap() - 50.0).abs() < 1e-9);
    // GearOut while not synchronized: rejected.
    let mut go = McGearOut {
        execute: true,
        ..Default::default()
    };
    go.call_gear_out(&mut e, a);
    assert_eq!(go.error_id, ErrorId::NotSynchronized);
    let mut m = mv(100.0);
    m.call(&mut e, a);
    v.call(&mut e, a);
    assert!(v.command_aborted && !v.busy);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::DiscreteMotion);
    // DiscreteMotion -> Stopping; motion rejected while Stopping; Stopping -> Standstill
    // only on Done AND NOT Execute.
    let mut s = McStop {
        execute: true,
        deceleration: 1000.0,
        ..Default::default()
    };
    s.call(&mut e, a);
    m.call(&mut e, a);
    assert!(m.command_aborted);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Stopping);
    let mut m3 = mv(0.0);
    m3.call(&mut e, a);
    assert_eq!(m3.error_id, ErrorId::AxisStopping);
    run_until(&mut e, 1000, |e| {
        s.call(e, a);
        s.done
    });
    for _ in 0..3 {
        e.step();
        s.call(&mut e, a);
    }
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Stopping);
    s.execute = false;
    s.call(&mut e, a);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Standstill);
    // Standstill -> SynchronizedMotion (GearIn) -> ContinuousMotion (GearOut).
    let master = e.add_axis(AxisConfig::default()).unwrap();
    let mut pm = McPower {
        enable: true,
        ..Default::default()
    };
    pm.call(&mut e, master);
    let mut mvm = McMoveVelocity {
        execute: true,
        velocity: 10.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    mvm.call(&mut e, master);
    // (a ratio whose product with the master's axis limits leaves room in the slave's: 1/2
    // of an axis like the slave; ErrorID 34 otherwise)
    let mut gi = McGearIn {
        execute: true,
        ratio_numerator: 1.0,
        ratio_denominator: 2.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    gi.call(&mut e, master, a);
    assert!(gi.busy, "{:?}", gi.error_id);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::SynchronizedMotion);
    run_until(&mut e, 2000, |e| {
        mvm.call(e, master);
        gi.call(e, master, a);
        gi.in_gear
    });
    e.step();
    assert!(
        (e.set_velocity_of(a).unwrap() - 0.5 * e.set_velocity_of(master).unwrap()).abs() < 1e-6,
        "{} {}",
        e.set_velocity_of(a).unwrap(),
        e.set_velocity_of(master).unwrap()
    );
    let mut go = McGearOut {
        execute: true,
        ..Default::default()
    };
    go.call_gear_out(&mut e, a);
    assert!(go.done);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::ContinuousMotion);
    gi.call(&mut e, master, a);
    assert!(gi.command_aborted);
    // Any state -> ErrorStop on an axis error; commands rejected; Reset -> Standstill.
    e.raise_axis_error(a, ErrorId::ExternalError).unwrap();
    assert_eq!(e.axis_state(a).unwrap(), AxisState::ErrorStop);
    let mut m4 = mv(0.0);
    m4.call(&mut e, a);
    assert_eq!(m4.error_id, ErrorId::AxisErrorStop);
    let mut r = McReset {
        execute: true,
        ..Default::default()
    };
    r.call(&mut e, a);
    assert_eq!(r.error_id, ErrorId::AxisStillMoving);
    run_until(&mut e, 5000, |e| e.set_velocity_of(a).unwrap() == 0.0);
    let mut r = McReset {
        execute: true,
        ..Default::default()
    };
    r.call(&mut e, a);
    assert!(r.done);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Standstill);
    // Power off -> Disabled; in ErrorStop power off stays ErrorStop, Reset -> Disabled.
    e.raise_axis_error(a, ErrorId::ExternalError).unwrap();
    p.enable = false;
    p.call(&mut e, a);
    assert!(!p.status);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::ErrorStop);
    let mut r = McReset {
        execute: true,
        ..Default::default()
    };
    r.call(&mut e, a);
    assert!(r.done, "{:?}", r.error_id);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Disabled);
    // Power on, move, power off -> Disabled with CommandAborted.
    p.enable = true;
    p.call(&mut e, a);
    let mut m = mv(0.0);
    m.call(&mut e, a);
    e.step();
    p.enable = false;
    p.call(&mut e, a);
    m.call(&mut e, a);
    assert!(m.command_aborted);
    assert_eq!(e.axis_state(a).unwrap(), AxisState::Disabled);
}

#[test]
fn axis_error_aborts_buffered_commands_with_error_and_clears_queue() {
    let (mut e, a) = engine();
    McPower {
        enable: true,
        ..Default::default()
    }
    .call(&mut e, a);
    let mut m1 = mv(10.0);
    let mut m2 = McMoveAbsolute {
        buffer_mode: BufferMode::Buffered,
        ..mv(20.0)
    };
    let mut m3 = McMoveAbsolute {
        buffer_mode: BufferMode::Buffered,
        ..mv(30.0)
    };
    m1.call(&mut e, a);
    m2.call(&mut e, a);
    m3.call(&mut e, a);
    assert_eq!(e.queued(a).unwrap(), 2);
    assert!(m2.busy && !m2.active);
    e.step();
    e.raise_axis_error(a, ErrorId::ExternalError).unwrap();
    for m in [&mut m1, &mut m2, &mut m3] {
        m.call(&mut e, a);
        assert!(m.error && m.error_id == ErrorId::ExternalError);
    }
    assert_eq!(e.queued(a).unwrap(), 0);
    let mut re = McReadAxisError {
        enable: true,
        ..Default::default()
    };
    re.call(&mut e, a);
    assert_eq!(re.axis_error_id, ErrorId::ExternalError);
}

#[test]
fn full_queue_rejects_never_drops() {
    let mut e = Engine::new(EngineConfig {
        cycle: 0.001,
        queue_depth: 2,
    })
    .unwrap();
    let a = e.add_axis(AxisConfig::default()).unwrap();
    McPower {
        enable: true,
        ..Default::default()
    }
    .call(&mut e, a);
    let mut blocks: Vec<McMoveAbsolute> = (0..4)
        .map(|i| McMoveAbsolute {
            buffer_mode: BufferMode::Buffered,
            ..mv(10.0 * (i + 1) as f64)
        })
        .collect();
    for b in blocks.iter_mut() {
        b.call(&mut e, a);
    }
    assert!(blocks[0].active);
    assert!(blocks[1].busy && blocks[2].busy);
    assert!(blocks[3].error && blocks[3].error_id == ErrorId::QueueFull);
    run_until(&mut e, 20000, |e| {
        for b in blocks.iter_mut() {
            b.call(e, a);
        }
        blocks[2].done
    });
    assert!((e.set_position_of(a).unwrap() - 30.0).abs() < 1e-9);
}

#[test]
fn state_tables_reject_each_illegal_command() {
    use AxisState::*;
    let all = [
        Disabled,
        Standstill,
        Homing,
        DiscreteMotion,
        ContinuousMotion,
        SynchronizedMotion,
        Stopping,
        ErrorStop,
    ];
    let cmds = [
        AxisCmd::Discrete,
        AxisCmd::Continuous,
        AxisCmd::Synchronized,
        AxisCmd::SyncOut,
        AxisCmd::Home,
        AxisCmd::Stop,
    ];
    let mut legal = 0;
    for s in all {
        for c in cmds {
            match check_axis(s, c) {
                Ok(t) => {
                    legal += 1;
                    assert_eq!(t, c.target());
                }
                Err(e) => assert!(e.is_error()),
            }
        }
    }
    assert_eq!(
        check_axis(ErrorStop, AxisCmd::Stop),
        Err(ErrorId::AxisErrorStop)
    );
    assert_eq!(
        check_axis(Disabled, AxisCmd::Discrete),
        Err(ErrorId::AxisDisabled)
    );
    assert_eq!(
        check_axis(Stopping, AxisCmd::Continuous),
        Err(ErrorId::AxisStopping)
    );
    assert_eq!(
        check_axis(Homing, AxisCmd::Synchronized),
        Err(ErrorId::AxisHoming)
    );
    assert_eq!(
        check_axis(DiscreteMotion, AxisCmd::Home),
        Err(ErrorId::NotStandstill)
    );
    assert_eq!(
        check_axis(ContinuousMotion, AxisCmd::SyncOut),
        Err(ErrorId::NotSynchronized)
    );
    assert_eq!(check_axis(Stopping, AxisCmd::Stop), Ok(Stopping));
    // 4 motion states x 4 motion classes - SyncOut in 3 + Home in Standstill + Stop in 5.
    assert_eq!(legal, 4 * 3 + 1 + 1 + 6);
    use GroupState::*;
    assert_eq!(
        check_group(GroupDisabled, GroupCmd::Motion),
        Err(ErrorId::GroupDisabled)
    );
    assert_eq!(
        check_group(GroupStandby, GroupCmd::Configure),
        Err(ErrorId::GroupNotDisabled)
    );
    assert_eq!(
        check_group(GroupErrorStop, GroupCmd::Motion),
        Err(ErrorId::GroupErrorStop)
    );
    assert_eq!(
        check_group(GroupStopping, GroupCmd::Motion),
        Err(ErrorId::GroupStopping)
    );
    assert_eq!(
        check_group(GroupMoving, GroupCmd::Disable),
        Err(ErrorId::GroupMoving)
    );
    assert_eq!(
        check_group(GroupErrorStop, GroupCmd::Reset),
        Ok(GroupStandby)
    );
    assert_eq!(check_group(GroupMoving, GroupCmd::Stop), Ok(GroupStopping));
    assert_eq!(check_group(GroupStandby, GroupCmd::Motion), Ok(GroupMoving));
    assert_eq!(check_group(GroupStandby, GroupCmd::Home), Ok(GroupHoming));
    assert_eq!(check_group(GroupHoming, GroupCmd::Stop), Ok(GroupStopping));
    assert_eq!(
        check_group(GroupHoming, GroupCmd::Motion),
        Err(ErrorId::GroupHoming)
    );
    assert_eq!(
        check_group(GroupDisabled, GroupCmd::Home),
        Err(ErrorId::GroupDisabled)
    );
}

#[test]
fn output_rules_cycle_by_cycle() {
    let (mut e, a) = engine();
    McPower {
        enable: true,
        ..Default::default()
    }
    .call(&mut e, a);
    // Execute falls before completion: Done still shows for exactly one call.
    let mut m = McMoveRelative {
        execute: true,
        distance: 0.5,
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    m.call(&mut e, a);
    assert!(m.busy && m.active && !m.done);
    m.execute = false;
    let mut seen = 0;
    for _ in 0..2000 {
        e.step();
        m.call(&mut e, a);
        if m.done {
            seen += 1;
            assert!(!m.busy && !m.active && !m.error && !m.command_aborted);
        } else if seen > 0 {
            break;
        }
    }
    assert_eq!(
        seen, 1,
        "Done shown for exactly one cycle after Execute fell"
    );
    assert!(
        (e.set_position_of(a).unwrap() - 0.5).abs() < 1e-9,
        "falling Execute does not stop the motion"
    );
    // With Execute held, Done stays; it resets on the falling edge.
    let mut m = McMoveRelative {
        execute: true,
        distance: 0.5,
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    m.call(&mut e, a);
    run_until(&mut e, 2000, |e| {
        m.call(e, a);
        m.done
    });
    for _ in 0..5 {
        e.step();
        m.call(&mut e, a);
        assert!(m.done);
    }
    m.execute = false;
    m.call(&mut e, a);
    assert!(!m.done && !m.busy);
    // Error on bad input, reset on falling Execute.
    let mut bad = McMoveAbsolute {
        velocity: 0.0,
        ..mv(1.0)
    };
    bad.call(&mut e, a);
    assert!(bad.error && bad.error_id == ErrorId::InvalidVelocity && !bad.busy);
    bad.execute = false;
    bad.call(&mut e, a);
    assert!(!bad.error && bad.error_id == ErrorId::None);
    // Rising edges while Busy are ignored.
    let mut m = mv(50.0);
    m.call(&mut e, a);
    m.execute = false;
    m.call(&mut e, a);
    m.execute = true;
    m.position = -50.0;
    m.call(&mut e, a);
    run_until(&mut e, 5000, |e| {
        m.call(e, a);
        m.done
    });
    assert!((e.set_position_of(a).unwrap() - 50.0).abs() < 1e-9);
}

#[test]
fn blending_and_buffered_single_axis() {
    let (mut e, a) = engine();
    McPower {
        enable: true,
        ..Default::default()
    }
    .call(&mut e, a);
    let mut m1 = McMoveAbsolute {
        velocity: 50.0,
        ..mv(100.0)
    };
    let mut m2 = McMoveAbsolute {
        velocity: 80.0,
        buffer_mode: BufferMode::BlendingHigh,
        ..mv(200.0)
    };
    m1.call(&mut e, a);
    m2.call(&mut e, a);
    let mut at_done = None;
    let mut max_v1: f64 = 0.0;
    run_until(&mut e, 10000, |e| {
        m1.call(e, a);
        m2.call(e, a);
        if m1.active && e.set_position_of(a).unwrap() < 80.0 {
            max_v1 = max_v1.max(e.set_velocity_of(a).unwrap());
        }
        if m1.done && at_done.is_none() {
            at_done = Some(e.set_velocity_of(a).unwrap());
            assert!(m2.active);
        }
        m2.done
    });
    let v = at_done.unwrap();
    assert!((v - 80.0).abs() < 0.5, "junction {v}");
    // The first move cruises at its own velocity and speeds up only near its end.
    assert!((max_v1 - 50.0).abs() < 1e-9, "{max_v1}");
    // Buffered: successor starts at standstill.
    let mut m1 = McMoveAbsolute {
        velocity: 50.0,
        ..mv(300.0)
    };
    let mut m2 = McMoveAbsolute {
        buffer_mode: BufferMode::Buffered,
        ..mv(250.0)
    };
    m1.call(&mut e, a);
    m2.call(&mut e, a);
    let mut at_done = None;
    run_until(&mut e, 10000, |e| {
        m1.call(e, a);
        m2.call(e, a);
        if m1.done && at_done.is_none() {
            at_done = Some(e.set_velocity_of(a).unwrap());
        }
        m2.done
    });
    assert!(at_done.unwrap().abs() < 2.0);
    assert!((e.set_position_of(a).unwrap() - 250.0).abs() < 1e-9);
}

#[test]
fn modulo_directions() {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let cfg = AxisConfig {
        kind: motion_lib::axis::AxisKind::Modulo { period: 360.0 },
        ..AxisConfig::default()
    };
    let a = e.add_axis(cfg).unwrap();
    McPower {
        enable: true,
        ..Default::default()
    }
    .call(&mut e, a);
    let go = |e: &mut Engine, pos: f64, dir: Direction| -> f64 {
        let mut m = McMoveAbsolute {
            direction: dir,
            velocity: 500.0,
            ..mv(pos)
        };
        m.call(e, a);
        e.step();
        let start_v_sign = e.set_velocity_of(a).unwrap().signum();
        run_until(e, 10000, |e| {
            m.call(e, a);
            m.done
        });
        assert!((e.set_position_of(a).unwrap() - pos).abs() < 1e-6);
        start_v_sign
    };
    assert_eq!(go(&mut e, 90.0, Direction::Positive), 1.0);
    assert_eq!(go(&mut e, 80.0, Direction::Positive), 1.0); // the long way round
    assert_eq!(go(&mut e, 90.0, Direction::Negative), -1.0);
    assert_eq!(go(&mut e, 350.0, Direction::Shortest), -1.0);
    assert_eq!(go(&mut e, 10.0, Direction::Shortest), 1.0);
    assert_eq!(go(&mut e, 20.0, Direction::Current), 1.0);
}

#[test]
fn cam_follows_table() {
    let (mut e, slave) = engine();
    // The cam law must fit the slave's limits for any master motion within the master's
    // axis limits (ErrorID 33 otherwise): a master of at most 20 mm/s.
    let mut mc = AxisConfig::default();
    mc.limits.vmax = 20.0;
    mc.limits.amax = 1000.0;
    mc.limits.dmax = 1000.0;
    let master = e.add_axis(mc).unwrap();
    McPower {
        enable: true,
        ..Default::default()
    }
    .call(&mut e, slave);
    McPower {
        enable: true,
        ..Default::default()
    }
    .call(&mut e, master);
    let id = e.add_cam_table(CamTable::new(&[(0.0, 0.0), (10.0, 5.0), (20.0, 0.0)]).unwrap());
    let mut sel = McCamTableSelect {
        execute: true,
        cam_table: id,
        periodic: true,
        master_absolute: true,
        slave_absolute: true,
        ..Default::default()
    };
    sel.call(&mut e, master, slave);
    assert!(sel.done);
    let mut cam = McCamIn {
        execute: true,
        cam_table_id: sel.cam_table_id,
        periodic: true,
        master_absolute: true,
        slave_absolute: true,
        ..Default::default()
    };
    cam.call(&mut e, master, slave);
    assert!(cam.busy, "{:?}", cam.error_id);
    let mut mvm = McMoveVelocity {
        execute: true,
        velocity: 10.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    mvm.call(&mut e, master);
    let mut eop = 0;
    for _ in 0..2500 {
        e.step();
        cam.call(&mut e, master, slave);
        if cam.end_of_profile {
            eop += 1;
        }
    }
    assert!(cam.in_sync);
    let m = e.set_position_of(master).unwrap();
    let expect = e.cam_table(id).unwrap().eval(m.rem_euclid(20.0), true).0;
    assert!(
        (e.set_position_of(slave).unwrap() - expect).abs() < 1e-6,
        "{} {} {}",
        e.set_position_of(slave).unwrap(),
        expect,
        m
    );
    assert!(eop >= 1);
    let mut out = McCamOut {
        execute: true,
        ..Default::default()
    };
    out.call_cam_out(&mut e, slave);
    assert!(out.done);
}

#[test]
fn command_aborted_after_falling_execute_shows_one_cycle() {
    let (mut e, a) = engine();
    McPower {
        enable: true,
        ..Default::default()
    }
    .call(&mut e, a);
    let mut m1 = mv(100.0);
    m1.call(&mut e, a);
    m1.execute = false;
    e.step();
    m1.call(&mut e, a);
    assert!(
        m1.busy && m1.active,
        "a falling Execute does not stop the motion"
    );
    // A second block takes over: m1 shows CommandAborted for exactly one call.
    let mut m2 = mv(-100.0);
    m2.call(&mut e, a);
    e.step();
    m1.call(&mut e, a);
    assert!(m1.command_aborted && !m1.busy && !m1.active && !m1.done && !m1.error);
    e.step();
    m1.call(&mut e, a);
    assert!(!m1.command_aborted && !m1.busy);
    // With Execute held, CommandAborted stays until Execute falls.
    let mut m3 = mv(50.0);
    m3.call(&mut e, a);
    let mut m4 = mv(60.0);
    m4.call(&mut e, a);
    for _ in 0..3 {
        e.step();
        m3.call(&mut e, a);
        assert!(m3.command_aborted);
    }
    m3.execute = false;
    m3.call(&mut e, a);
    assert!(!m3.command_aborted);
    // Buffered block: Busy without Active while waiting.
    let mut m5 = McMoveAbsolute {
        buffer_mode: BufferMode::Buffered,
        ..mv(70.0)
    };
    m5.call(&mut e, a);
    assert!(m5.busy && !m5.active);
    run_until(&mut e, 10000, |e| {
        m4.call(e, a);
        m5.call(e, a);
        m5.active
    });
    assert!(m4.done && !m4.busy);
}
