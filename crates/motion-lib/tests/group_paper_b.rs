//! Paper B's group experiment at library level: three MC_MoveLinearAbsolute on three
//! axes with BufferModes Aborting, BlendingLow, BlendingHigh.

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::McPower;
use motion_lib::buffer::{BufferMode, TransitionMode};
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::fsm::{AxisState, GroupState};
use motion_lib::group::{Reduction, ReductionReason};
use motion_lib::group_blocks::{McAddAxisToGroup, McGroupEnable, McMoveLinearAbsolute};
use motion_lib::profile::Limits;

fn setup(cycle: f64) -> (Engine, usize, [usize; 3]) {
    let mut eng = Engine::new(EngineConfig {
        cycle,
        queue_depth: 4,
    })
    .unwrap();
    let cfg = AxisConfig {
        limits: Limits {
            vmax: 500.0,
            amax: 100.0,
            dmax: 100.0,
            jmax: 100.0,
        },
        ..AxisConfig::default()
    };
    let axes = [
        eng.add_axis(cfg).unwrap(),
        eng.add_axis(cfg).unwrap(),
        eng.add_axis(cfg).unwrap(),
    ];
    let g = eng.add_group();
    let mut pw = [McPower::default(); 3];
    for (i, a) in axes.iter().enumerate() {
        pw[i].enable = true;
        pw[i].call(&mut eng, *a);
        assert!(pw[i].status);
        let mut add = McAddAxisToGroup {
            execute: true,
            axis: *a,
            ident_in_group: i,
            ..Default::default()
        };
        add.call(&mut eng, g);
        assert!(add.done, "{:?}", add.error_id);
    }
    let mut en = McGroupEnable {
        execute: true,
        ..Default::default()
    };
    en.call(&mut eng, g);
    assert!(en.done);
    assert_eq!(eng.group_state(g).unwrap(), GroupState::GroupStandby);
    (eng, g, axes)
}

fn block(
    target: [f64; 3],
    v: f64,
    bm: BufferMode,
    tm: TransitionMode,
    d: f64,
) -> McMoveLinearAbsolute {
    let mut position = [0.0; 16];
    position[..3].copy_from_slice(&target);
    McMoveLinearAbsolute {
        execute: true,
        position,
        velocity: v,
        acceleration: 5.0,
        deceleration: 5.0,
        jerk: 2.0,
        buffer_mode: bm,
        transition_mode: tm,
        transition_parameter: d,
        ..Default::default()
    }
}

struct Trace {
    /// Path speed when each block reported Done (the junction speeds), and the end.
    junction: Vec<f64>,
    end: [f64; 3],
    max_speed: f64,
    max_jump: f64,
    cycles: u64,
    reductions: Vec<Reduction>,
}

fn run(tm: TransitionMode, d: f64) -> Trace {
    let dt = 0.01;
    let (mut eng, g, axes) = setup(dt);
    let mut b = [
        block([1600.0, 1200.0, 800.0], 40.0, BufferMode::Aborting, tm, d),
        block(
            [2200.0, 3800.0, 5000.0],
            55.0,
            BufferMode::BlendingLow,
            tm,
            d,
        ),
        block(
            [4500.0, 4200.0, 4800.0],
            70.0,
            BufferMode::BlendingHigh,
            tm,
            d,
        ),
    ];
    for blk in b.iter_mut() {
        blk.call(&mut eng, g);
        assert!(blk.busy && !blk.error, "{:?}", blk.error_id);
    }
    assert!(b[0].active && !b[1].active && !b[2].active);
    let mut junction = Vec::new();
    let mut was_done = [false; 3];
    let mut max_speed: f64 = 0.0;
    let mut max_jump: f64 = 0.0;
    let mut prev_v = [0.0; 3];
    for _ in 0..200_000 {
        eng.step();
        let (v, speed) = eng.group_velocity(g).unwrap();
        max_speed = max_speed.max(speed);
        for i in 0..3 {
            max_jump = max_jump.max((v[i] - prev_v[i]).abs());
            prev_v[i] = v[i];
        }
        for (k, blk) in b.iter_mut().enumerate() {
            blk.call(&mut eng, g);
            // Busy, Done, Error, CommandAborted exclusive.
            let n = [blk.busy, blk.done, blk.error, blk.command_aborted]
                .iter()
                .filter(|x| **x)
                .count();
            assert_eq!(n, 1);
            if blk.done && !was_done[k] {
                was_done[k] = true;
                junction.push(speed);
            }
        }
        if was_done[2] {
            break;
        }
    }
    for a in axes {
        assert_eq!(eng.axis_state(a).unwrap(), AxisState::Standstill);
    }
    assert_eq!(eng.group_state(g).unwrap(), GroupState::GroupStandby);
    let p = eng.group_position(g).unwrap();
    Trace {
        junction,
        end: [p[0], p[1], p[2]],
        max_speed,
        max_jump,
        cycles: eng.cycles(),
        reductions: eng.group_reductions(g).unwrap().0.to_vec(),
    }
}

#[test]
fn paper_b_tmnone_corners_are_passed_at_rest_and_reported() {
    let t = run(TransitionMode::None, 0.0);
    assert_eq!(t.junction.len(), 3);
    // TMNone at a corner: no speed is feasible (the velocity vector would step), so the
    // junction speeds 40 and 70 are lowered to 0 and reported.
    for j in &t.junction {
        assert!(j.abs() < 1e-9, "junction {j}");
    }
    assert_eq!(t.reductions.len(), 2, "{:?}", t.reductions);
    for (r, (block, want)) in t.reductions.iter().zip([(2, 40.0), (3, 70.0)]) {
        assert_eq!(r.block, block);
        assert!((r.requested - want).abs() < 1e-9, "{r:?}");
        assert_eq!(r.reached, 0.0);
        assert_eq!(r.reason, ReductionReason::Corner);
    }
    assert!(t.max_speed <= 70.0 + 1e-6);
    // Axis velocities change by at most the block acceleration * cycle.
    assert!(t.max_jump <= 5.0 * 0.01 * (1.0 + 1e-9), "{}", t.max_jump);
    for (e, w) in t.end.iter().zip([4500.0, 4200.0, 4800.0]) {
        assert!((e - w).abs() < 1e-6, "end {e} vs {w}");
    }
    assert!(t.cycles > 100);
}

#[test]
fn corner_distance_reaches_the_paper_speeds_where_the_axes_allow() {
    // Corner distance 150 mm: the blends' curvature allows the full 40 at A and 70 at B on
    // these axes (100 mm/s^2, 100 mm/s^3), so nothing is lowered.
    let round = run(TransitionMode::CornerDistance, 150.0);
    assert!(round.reductions.is_empty(), "{:?}", round.reductions);
    // Every axis's velocity changes by at most its acceleration limit * dt per cycle.
    assert!(round.max_jump <= 100.0 * 0.01, "{}", round.max_jump);
    for (e, w) in round.end.iter().zip([4500.0, 4200.0, 4800.0]) {
        assert!((e - w).abs() < 1e-6, "end {e} vs {w}");
    }
    // A tiny corner distance cannot take 40 mm/s: lowered to the blend's limit, reported.
    let tight = run(TransitionMode::CornerDistance, 1.0);
    assert_eq!(tight.reductions.len(), 2, "{:?}", tight.reductions);
    for r in &tight.reductions {
        assert_eq!(r.reason, ReductionReason::Blend);
        assert!(r.reached > 0.0 && r.reached < r.requested, "{r:?}");
    }
    assert!(tight.max_jump <= 100.0 * 0.01, "{}", tight.max_jump);
}
