//! Paper B's group experiment at library level: three MC_MoveLinearAbsolute on three
//! axes with BufferModes Aborting, BlendingLow, BlendingHigh.

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::McPower;
use motion_lib::buffer::{BufferMode, TransitionMode};
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::fsm::{AxisState, GroupState};
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
    /// Largest change of the path speed in one cycle.
    max_speed_step: f64,
    /// Path speeds while block 2 was active.
    block2: Vec<f64>,
    cycles: u64,
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
    let mut prev_speed = 0.0;
    let mut block2 = Vec::new();
    let mut max_speed_step: f64 = 0.0;
    for _ in 0..200_000 {
        eng.step();
        let (v, speed) = eng.group_velocity(g).unwrap();
        max_speed = max_speed.max(speed);
        max_speed_step = max_speed_step.max((speed - prev_speed).abs());
        prev_speed = speed;
        for i in 0..3 {
            max_jump = max_jump.max((v[i] - prev_v[i]).abs());
            prev_v[i] = v[i];
        }
        if b[1].active {
            block2.push(speed);
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
        max_speed_step,
        block2,
        cycles: eng.cycles(),
    }
}

#[test]
fn paper_b_junction_speeds_40_then_70_then_stop() {
    let t = run(TransitionMode::None, 0.0);
    assert_eq!(t.junction.len(), 3);
    // Speed at Done of block 1 = min(40, 55); of block 2 = max(55, 70); block 3 stops.
    assert!((t.junction[0] - 40.0).abs() < 0.05, "A: {}", t.junction[0]);
    assert!((t.junction[1] - 70.0).abs() < 0.05, "B: {}", t.junction[1]);
    assert!(t.junction[2].abs() < 1e-9, "C: {}", t.junction[2]);
    assert!(t.max_speed <= 70.0 + 1e-6);
    // The path speed is continuous through both junctions (successors start from the
    // junction state): it never changes by more than acceleration * cycle.
    assert!(
        t.max_speed_step <= 5.0 * 0.01 + 1e-9,
        "{}",
        t.max_speed_step
    );
    // Block 2 cruises at its own velocity 55 and speeds up to 70 only at its end
    // (55 -> 70 at a = 5, j = 2 takes 5.5 s).
    let at_55 = t
        .block2
        .iter()
        .filter(|v| (**v - 55.0).abs() < 1e-6)
        .count();
    let above = t.block2.iter().filter(|v| **v > 55.0 + 1e-6).count();
    assert!(at_55 * 2 > t.block2.len(), "{at_55} of {}", t.block2.len());
    assert!((above as f64) * 0.01 < 6.0, "{above} cycles above 55");
    for (e, w) in t.end.iter().zip([4500.0, 4200.0, 4800.0]) {
        assert!((e - w).abs() < 1e-6, "end {e} vs {w}");
    }
    assert!(t.cycles > 100);
}

#[test]
fn corner_distance_keeps_axis_velocity_continuous() {
    let sharp = run(TransitionMode::None, 0.0);
    let round = run(TransitionMode::CornerDistance, 100.0);
    // Without a blend the direction change makes the axis velocities jump at the corner.
    assert!(sharp.max_jump > 10.0, "{}", sharp.max_jump);
    // With the blend every axis's velocity changes by at most the path acceleration
    // (5) * dt per cycle: the velocity vector is continuous and within the limits
    // (10 % margin for the discrete evaluation).
    assert!(round.max_jump <= 5.0 * 0.01 * 1.1, "{}", round.max_jump);
    for (e, w) in round.end.iter().zip([4500.0, 4200.0, 4800.0]) {
        assert!((e - w).abs() < 1e-6, "end {e} vs {w}");
    }
}
