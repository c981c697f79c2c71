//! Group state machine (Part 4) through the group blocks; circular and direct moves;
//! the group reads.

use motion_lib::blocks::{McMoveAbsolute, McPower};
use motion_lib::buffer::BufferMode;
use motion_lib::engine::Engine;
use motion_lib::error::ErrorId;
use motion_lib::fsm::{AxisState, GroupState};
use motion_lib::group_blocks::*;
use motion_lib::path::CircMode;

mod group_common;
use group_common::{axes, vecn};

fn lin(x: &[f64], bm: BufferMode) -> McMoveLinearAbsolute {
    McMoveLinearAbsolute {
        execute: true,
        position: vecn(x),
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        jerk: 10000.0,
        buffer_mode: bm,
        ..Default::default()
    }
}

fn step_until(e: &mut Engine, max: usize, mut f: impl FnMut(&mut Engine) -> bool) {
    for _ in 0..max {
        e.step();
        if f(e) {
            return;
        }
    }
    panic!("condition not reached");
}

#[test]
fn group_transitions_and_rejections() {
    let (mut e, ax, g) = axes(2);
    let st = |e: &Engine| e.group_state(g).unwrap();
    assert_eq!(st(&e), GroupState::GroupDisabled);
    // Motion in GroupDisabled rejected.
    let mut m = lin(&[10.0, 10.0], BufferMode::Aborting);
    m.call(&mut e, g);
    assert_eq!(m.error_id, ErrorId::GroupDisabled);
    for (i, a) in ax.iter().enumerate() {
        let mut add = McAddAxisToGroup {
            execute: true,
            axis: *a,
            ident_in_group: i,
            ..Default::default()
        };
        add.call(&mut e, g);
        assert!(add.done);
    }
    // Same identity twice / axis twice rejected.
    let mut dup = McAddAxisToGroup {
        execute: true,
        axis: ax[0],
        ident_in_group: 0,
        ..Default::default()
    };
    dup.call(&mut e, g);
    assert_eq!(dup.error_id, ErrorId::InvalidIdentInGroup);
    let mut dup = McAddAxisToGroup {
        execute: true,
        axis: ax[0],
        ident_in_group: 5,
        ..Default::default()
    };
    dup.call(&mut e, g);
    assert_eq!(dup.error_id, ErrorId::AxisAlreadyInGroup);
    // Enable needs powered axes.
    let mut en = McGroupEnable {
        execute: true,
        ..Default::default()
    };
    en.call(&mut e, g);
    assert_eq!(en.error_id, ErrorId::GroupAxesNotReady);
    for a in &ax {
        McPower {
            enable: true,
            ..Default::default()
        }
        .call(&mut e, *a);
    }
    let mut en = McGroupEnable {
        execute: true,
        ..Default::default()
    };
    en.call(&mut e, g);
    assert!(en.done);
    assert_eq!(st(&e), GroupState::GroupStandby);
    // Configuration only in GroupDisabled.
    let mut rm = McRemoveAxisFromGroup {
        execute: true,
        ident_in_group: 1,
        ..Default::default()
    };
    rm.call(&mut e, g);
    assert_eq!(rm.error_id, ErrorId::GroupNotDisabled);
    // Single-axis motion on a grouped axis rejected.
    let mut single = McMoveAbsolute {
        execute: true,
        position: 1.0,
        velocity: 1.0,
        acceleration: 1.0,
        deceleration: 1.0,
        ..Default::default()
    };
    single.call(&mut e, ax[0]);
    assert_eq!(single.error_id, ErrorId::AxisInGroup);
    // Standby -> Homing -> Standby; motion rejected while homing.
    let mut home = McGroupHome {
        execute: true,
        position: vecn(&[1.0, 2.0]),
        ..Default::default()
    };
    home.call(&mut e, g);
    assert!(home.busy && home.active, "{:?}", home.error_id);
    assert_eq!(st(&e), GroupState::GroupHoming);
    assert_eq!(e.axis_state(ax[0]).unwrap(), AxisState::Homing);
    let mut m = lin(&[10.0, 10.0], BufferMode::Aborting);
    m.call(&mut e, g);
    assert_eq!(m.error_id, ErrorId::GroupHoming);
    let mut home2 = McGroupHome {
        execute: true,
        ..Default::default()
    };
    home2.call(&mut e, g);
    assert_eq!(home2.error_id, ErrorId::GroupHoming);
    e.step();
    home.call(&mut e, g);
    assert!(home.done);
    assert_eq!(st(&e), GroupState::GroupStandby);
    assert_eq!(e.axis_state(ax[1]).unwrap(), AxisState::Standstill);
    assert_eq!(e.group_position(g).unwrap()[..2], [1.0, 2.0]);
    // Standby -> Moving (axes SynchronizedMotion) -> Standby.
    let mut m = lin(&[10.0, 20.0], BufferMode::Aborting);
    m.call(&mut e, g);
    assert!(m.active);
    assert_eq!(st(&e), GroupState::GroupMoving);
    assert_eq!(e.axis_state(ax[0]).unwrap(), AxisState::SynchronizedMotion);
    let mut dis = McGroupDisable {
        execute: true,
        ..Default::default()
    };
    dis.call(&mut e, g);
    assert_eq!(dis.error_id, ErrorId::GroupMoving);
    let mut home3 = McGroupHome {
        execute: true,
        ..Default::default()
    };
    home3.call(&mut e, g);
    assert_eq!(home3.error_id, ErrorId::GroupMoving);
    step_until(&mut e, 5000, |e| {
        m.call(e, g);
        m.done
    });
    assert_eq!(st(&e), GroupState::GroupStandby);
    assert_eq!(e.axis_state(ax[1]).unwrap(), AxisState::Standstill);
    let mut rp = McGroupReadActualPosition {
        enable: true,
        ..Default::default()
    };
    rp.call(&mut e, g);
    assert!(
        rp.valid && (rp.position[0] - 10.0).abs() < 1e-9 && (rp.position[1] - 20.0).abs() < 1e-9
    );
    // Moving -> Stopping; motion rejected; Stopping -> Standby on Done AND NOT Execute.
    let mut m = lin(&[100.0, 20.0], BufferMode::Aborting);
    m.call(&mut e, g);
    for _ in 0..100 {
        e.step();
    }
    let mut rv = McGroupReadActualVelocity {
        enable: true,
        ..Default::default()
    };
    rv.call(&mut e, g);
    assert!(rv.path_velocity > 10.0);
    let mut stop = McGroupStop {
        execute: true,
        deceleration: 1000.0,
        ..Default::default()
    };
    stop.call(&mut e, g);
    m.call(&mut e, g);
    assert!(m.command_aborted);
    assert_eq!(st(&e), GroupState::GroupStopping);
    let mut m2 = lin(&[0.0, 0.0], BufferMode::Aborting);
    m2.call(&mut e, g);
    assert_eq!(m2.error_id, ErrorId::GroupStopping);
    step_until(&mut e, 5000, |e| {
        stop.call(e, g);
        stop.done
    });
    e.step();
    stop.call(&mut e, g);
    assert_eq!(st(&e), GroupState::GroupStopping);
    stop.execute = false;
    stop.call(&mut e, g);
    assert_eq!(st(&e), GroupState::GroupStandby);
    // Halt: Moving -> Standby via Done.
    let mut m = lin(&[0.0, 0.0], BufferMode::Aborting);
    m.call(&mut e, g);
    for _ in 0..50 {
        e.step();
    }
    let mut h = McGroupHalt {
        execute: true,
        deceleration: 1000.0,
        ..Default::default()
    };
    h.call(&mut e, g);
    assert!(h.active);
    step_until(&mut e, 5000, |e| {
        h.call(e, g);
        h.done
    });
    assert_eq!(st(&e), GroupState::GroupStandby);
    let (v, _) = e.group_velocity(g).unwrap();
    assert_eq!(v[0], 0.0);
    // Axis error while moving: GroupErrorStop, buffered moves fail, motion rejected.
    let mut a1 = lin(&[50.0, 50.0], BufferMode::Aborting);
    let mut a2 = lin(&[60.0, 50.0], BufferMode::Buffered);
    a1.call(&mut e, g);
    a2.call(&mut e, g);
    assert_eq!(e.group_queued(g).unwrap(), 1);
    for _ in 0..20 {
        e.step();
    }
    e.raise_axis_error(ax[1], ErrorId::ExternalError).unwrap();
    a1.call(&mut e, g);
    a2.call(&mut e, g);
    assert!(a1.error && a2.error);
    assert_eq!(a2.error_id, ErrorId::GroupAxisError);
    assert_eq!(e.group_queued(g).unwrap(), 0);
    assert_eq!(st(&e), GroupState::GroupErrorStop);
    let mut rs = McGroupReadStatus {
        enable: true,
        ..Default::default()
    };
    rs.call(&mut e, g);
    assert!(rs.group_error_stop && !rs.group_moving);
    let mut m = lin(&[0.0, 0.0], BufferMode::Aborting);
    m.call(&mut e, g);
    assert_eq!(m.error_id, ErrorId::GroupErrorStop);
    step_until(&mut e, 5000, |e| e.group_velocity(g).unwrap().1 == 0.0);
    e.step();
    let mut r = McGroupReset {
        execute: true,
        ..Default::default()
    };
    r.call(&mut e, g);
    assert!(r.done, "{:?}", r.error_id);
    assert_eq!(st(&e), GroupState::GroupStandby);
    assert_eq!(e.axis_state(ax[1]).unwrap(), AxisState::Standstill);
    // Standby -> Disabled; configuration allowed again; ungroup.
    let mut dis = McGroupDisable {
        execute: true,
        ..Default::default()
    };
    dis.call(&mut e, g);
    assert!(dis.done);
    assert_eq!(st(&e), GroupState::GroupDisabled);
    let mut rm = McRemoveAxisFromGroup {
        execute: true,
        ident_in_group: 1,
        ..Default::default()
    };
    rm.call(&mut e, g);
    assert!(rm.done);
    assert_eq!(e.group_of(ax[1]).unwrap(), None);
    let mut un = McUngroupAllAxes {
        execute: true,
        ..Default::default()
    };
    un.call(&mut e, g);
    assert!(un.done);
    assert_eq!(e.group_of(ax[0]).unwrap(), None);
}

fn enabled_group(n: usize) -> (Engine, Vec<usize>, usize) {
    let (mut e, ax, g) = axes(n);
    for (i, a) in ax.iter().enumerate() {
        e.add_axis_to_group(g, *a, i).unwrap();
        McPower {
            enable: true,
            ..Default::default()
        }
        .call(&mut e, *a);
    }
    e.group_enable(g).unwrap();
    (e, ax, g)
}

#[test]
fn circular_move_stays_on_the_circle() {
    let (mut e, _ax, g) = enabled_group(2);
    // Quarter circle centre (0,0) radius 10 from (10,0) to (0,10), counter-clockwise.
    let mut l = lin(&[10.0, 0.0], BufferMode::Aborting);
    l.call(&mut e, g);
    step_until(&mut e, 5000, |e| {
        l.call(e, g);
        l.done
    });
    let mut c = McMoveCircularAbsolute {
        execute: true,
        circ_mode: CircMode::Center,
        aux_point: vecn(&[0.0, 0.0]),
        end_point: vecn(&[0.0, 10.0]),
        path_choice_ccw: true,
        velocity: 20.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    c.call(&mut e, g);
    assert!(c.busy, "{:?}", c.error_id);
    let mut max_dev: f64 = 0.0;
    step_until(&mut e, 10000, |e| {
        let p = e.group_position(g).unwrap();
        max_dev = max_dev.max(((p[0] * p[0] + p[1] * p[1]).sqrt() - 10.0).abs());
        assert!(
            p[0] >= -1e-9 && p[1] >= -1e-9,
            "stays in the first quadrant"
        );
        c.call(e, g);
        c.done
    });
    assert!(max_dev < 1e-9, "{max_dev}");
    let p = e.group_position(g).unwrap();
    assert!(p[0].abs() < 1e-9 && (p[1] - 10.0).abs() < 1e-9);
    // Border mode through (10,0)... back: from (0,10) via (-10,0) to (0,-10).
    let mut b = McMoveCircularAbsolute {
        execute: true,
        aux_point: vecn(&[-10.0, 0.0]),
        end_point: vecn(&[0.0, -10.0]),
        velocity: 20.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    b.call(&mut e, g);
    let mut min_x: f64 = 0.0;
    step_until(&mut e, 10000, |e| {
        let p = e.group_position(g).unwrap();
        min_x = min_x.min(p[0]);
        b.call(e, g);
        b.done
    });
    assert!((min_x + 10.0).abs() < 1e-3, "{min_x}");
    // A tight circle asked for too much speed: the turn limits it so no axis exceeds
    // its acceleration limit (2000).
    let mut tight = McMoveCircularRelative {
        execute: true,
        circ_mode: CircMode::Center,
        aux_point: vecn(&[0.0, 1.0]),
        end_point: vecn(&[0.0, 2.0]),
        path_choice_ccw: true,
        velocity: 190.0,
        acceleration: 2000.0,
        deceleration: 2000.0,
        ..Default::default()
    };
    tight.call(&mut e, g);
    assert!(tight.busy, "{:?}", tight.error_id);
    let mut max_a: f64 = 0.0;
    let mut max_v: f64 = 0.0;
    step_until(&mut e, 10000, |e| {
        max_a = max_a.max(e.set_acceleration_of(_ax[0]).unwrap().abs());
        max_a = max_a.max(e.set_acceleration_of(_ax[1]).unwrap().abs());
        max_v = max_v.max(e.group_velocity(g).unwrap().1);
        tight.call(e, g);
        tight.done
    });
    assert!(max_a <= 2000.0 * (1.0 + 1e-9), "{max_a}");
    assert!(max_v < 190.0 * 0.5, "speed limited by the turn: {max_v}");
    // An end point off the circle is rejected.
    let mut bad = McMoveCircularAbsolute {
        execute: true,
        circ_mode: CircMode::Center,
        aux_point: vecn(&[0.0, 0.0]),
        end_point: vecn(&[3.0, 3.0]),
        velocity: 20.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    bad.call(&mut e, g);
    assert_eq!(bad.error_id, ErrorId::InvalidCircle);
}

#[test]
fn direct_move_and_relative_line() {
    let (mut e, ax, g) = enabled_group(3);
    let mut d = McMoveDirectAbsolute {
        execute: true,
        position: vecn(&[10.0, -5.0, 1.0]),
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    d.call(&mut e, g);
    step_until(&mut e, 5000, |e| {
        d.call(e, g);
        d.done
    });
    let p = e.group_position(g).unwrap();
    assert_eq!([p[0], p[1], p[2]], [10.0, -5.0, 1.0]);
    let mut r = McMoveLinearRelative {
        execute: true,
        distance: vecn(&[1.0, 1.0, 1.0]),
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    r.call(&mut e, g);
    let mut max_v: f64 = 0.0;
    step_until(&mut e, 5000, |e| {
        max_v = max_v.max(e.set_velocity_of(ax[0]).unwrap().abs());
        r.call(e, g);
        r.done
    });
    let p = e.group_position(g).unwrap();
    assert!((p[0] - 11.0).abs() < 1e-9 && (p[1] + 4.0).abs() < 1e-9 && (p[2] - 2.0).abs() < 1e-9);
    assert!(max_v <= 200.0);
    // Unsupported coordinate system and transition mode.
    let mut cs = McMoveLinearRelative {
        coord_system: 2,
        ..r
    };
    cs.execute = true;
    cs.core = Default::default();
    cs.call(&mut e, g);
    assert_eq!(cs.error_id, ErrorId::InvalidCoordSystem);
}

#[test]
fn power_off_of_a_member_stops_the_group_in_error() {
    let (mut e, ax, g) = enabled_group(2);
    let mut m = lin(&[100.0, 100.0], BufferMode::Aborting);
    m.call(&mut e, g);
    for _ in 0..50 {
        e.step();
    }
    let mut p = McPower {
        enable: false,
        ..Default::default()
    };
    p.call(&mut e, ax[0]);
    assert_eq!(e.axis_state(ax[0]).unwrap(), AxisState::Disabled);
    assert_eq!(e.group_state(g).unwrap(), GroupState::GroupErrorStop);
    m.call(&mut e, g);
    assert!(m.error && m.error_id == ErrorId::GroupAxisError);
    step_until(&mut e, 5000, |e| e.set_velocity_of(ax[1]).unwrap() == 0.0);
    assert_eq!(e.axis_state(ax[0]).unwrap(), AxisState::Disabled);
    assert_eq!(e.axis_state(ax[1]).unwrap(), AxisState::Standstill);
}

#[test]
fn full_group_queue_rejects_and_runs_the_rest() {
    let (mut e, _ax, g) = enabled_group(2);
    // Depth 4: one active + 4 buffered; the sixth is refused.
    let mut blocks: Vec<McMoveLinearAbsolute> = (0..6)
        .map(|i| {
            let bm = if i == 0 {
                BufferMode::Aborting
            } else {
                BufferMode::Buffered
            };
            lin(&[i as f64 + 1.0, 0.0], bm)
        })
        .collect();
    for b in blocks.iter_mut() {
        b.call(&mut e, g);
    }
    assert!(blocks[..5].iter().all(|b| b.busy));
    assert!(blocks[5].error && blocks[5].error_id == ErrorId::QueueFull);
    assert_eq!(e.group_queued(g).unwrap(), 4);
    step_until(&mut e, 20000, |e| {
        for b in blocks.iter_mut() {
            b.call(e, g);
        }
        blocks[4].done
    });
    assert!(blocks[..5].iter().all(|b| b.done));
    assert_eq!(e.group_position(g).unwrap()[0], 5.0);
}
