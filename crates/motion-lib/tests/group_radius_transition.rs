//! Part 4 CircMode RADIUS against analytic geometry (the arc passes through the end
//! point, keeps its radius to 1e-9, turns the chosen way, stays within the path
//! velocity) and TMMaxCornerDeviation (the blend passes the corner at the given
//! distance, the axis velocity vector stays continuous, the limits hold).

use motion_lib::blocks::McPower;
use motion_lib::buffer::{BufferMode, TransitionMode};
use motion_lib::engine::Engine;
use motion_lib::error::ErrorId;
use motion_lib::group_blocks::*;
use motion_lib::path::CircMode;

mod group_common;
use group_common::{axes, vecn};

const DT: f64 = 0.001;

/// An enabled group of `n` axes (vmax 200, amax 2000, jmax 20000) standing at `at`.
fn group_at(n: usize, at: &[f64]) -> (Engine, usize) {
    let (mut e, ax, g) = axes(n);
    for (i, (a, at)) in ax.iter().zip(at).enumerate() {
        e.add_axis_to_group(g, *a, i).unwrap();
        McPower {
            enable: true,
            ..Default::default()
        }
        .call(&mut e, *a);
        e.set_position(*a, *at, false).unwrap();
    }
    e.group_enable(g).unwrap();
    (e, g)
}

fn radius_move(aux: &[f64], end: &[f64], ccw: bool) -> McMoveCircularAbsolute {
    McMoveCircularAbsolute {
        execute: true,
        circ_mode: CircMode::Radius,
        aux_point: vecn(aux),
        end_point: vecn(end),
        path_choice_ccw: ccw,
        velocity: 30.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        jerk: 10000.0,
        ..Default::default()
    }
}

/// Runs a circular block to Done; returns the positions of every cycle and the largest
/// path speed.
fn trace(e: &mut Engine, g: usize, m: &mut McMoveCircularAbsolute) -> (Vec<[f64; 3]>, f64) {
    m.call(e, g);
    assert!(m.busy, "{:?}", m.error_id);
    let (mut pts, mut vmax) = (Vec::new(), 0.0_f64);
    for _ in 0..100_000 {
        e.step();
        m.call(e, g);
        let p = e.group_position(g).unwrap();
        pts.push([p[0], p[1], p[2]]);
        vmax = vmax.max(e.group_velocity(g).unwrap().1);
        if m.done {
            return (pts, vmax);
        }
    }
    panic!("circle not done");
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

#[test]
fn radius_mode_picks_the_short_arc_turning_the_chosen_way() {
    // (10, 0) -> (0, 10), radius 10 about +Z: counter-clockwise the centre is (0, 0)
    // (the quarter through the first quadrant); clockwise the centre is (10, 10).
    for (ccw, centre) in [(true, [0.0, 0.0, 0.0]), (false, [10.0, 10.0, 0.0])] {
        let (mut e, g) = group_at(2, &[10.0, 0.0]);
        let (pts, vmax) = trace(
            &mut e,
            g,
            &mut radius_move(&[0.0, 0.0, 10.0], &[0.0, 10.0], ccw),
        );
        let dev = pts
            .iter()
            .map(|p| (dist(*p, centre) - 10.0).abs())
            .fold(0.0, f64::max);
        assert!(dev < 1e-9, "ccw {ccw}: radius deviates {dev}");
        let end = *pts.last().unwrap();
        assert!(dist(end, [0.0, 10.0, 0.0]) < 1e-9, "{end:?}");
        assert!(vmax <= 30.0 * (1.0 + 1e-9), "{vmax}");
        // Turning direction: the angle about the centre grows (ccw) or falls (cw),
        // and a quarter circle is all it turns.
        let ang = |p: [f64; 3]| (p[1] - centre[1]).atan2(p[0] - centre[0]);
        let mut turned = 0.0;
        let mut prev = ang([10.0, 0.0, 0.0]);
        for p in &pts {
            let mut d = ang(*p) - prev;
            if d > std::f64::consts::PI {
                d -= 2.0 * std::f64::consts::PI;
            } else if d < -std::f64::consts::PI {
                d += 2.0 * std::f64::consts::PI;
            }
            assert!(if ccw { d >= -1e-12 } else { d <= 1e-12 }, "direction");
            turned += d;
            prev = ang(*p);
        }
        let quarter = std::f64::consts::FRAC_PI_2;
        assert!((turned.abs() - quarter).abs() < 1e-9, "{turned}");
    }
}

#[test]
fn radius_mode_in_a_tilted_plane_and_relative() {
    // Plane through (0,0,0) with normal (0, -1, 1) / sqrt 2 * 5: radius 5. Chord from the
    // origin to (6, 2, 2) (in the plane: (6,2,2).(0,-1,1) = 0), length sqrt 44 < 10.
    let s = 5.0 / 2.0_f64.sqrt();
    let n = [0.0, -s, s];
    let (mut e, g) = group_at(3, &[0.0, 0.0, 0.0]);
    let (pts, _) = trace(&mut e, g, &mut radius_move(&n, &[6.0, 2.0, 2.0], true));
    let end = *pts.last().unwrap();
    assert!(dist(end, [6.0, 2.0, 2.0]) < 1e-9, "{end:?}");
    // Analytic centre: chord midpoint + h * unit(n x w), h = sqrt(r^2 - |w|^2 / 4).
    let w = [6.0, 2.0, 2.0];
    let nu = [0.0, -1.0 / 2.0_f64.sqrt(), 1.0 / 2.0_f64.sqrt()];
    let c = [
        nu[1] * w[2] - nu[2] * w[1],
        nu[2] * w[0] - nu[0] * w[2],
        nu[0] * w[1] - nu[1] * w[0],
    ];
    let cl = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
    let h = (25.0 - 44.0 / 4.0_f64).sqrt();
    let centre = [
        3.0 + h * c[0] / cl,
        1.0 + h * c[1] / cl,
        1.0 + h * c[2] / cl,
    ];
    for p in &pts {
        assert!((dist(*p, centre) - 5.0).abs() < 1e-9, "{p:?}");
        // In the plane.
        assert!((p[1] * nu[1] + p[2] * nu[2]).abs() < 1e-9);
    }
    // Relative: the same arc again from (6, 2, 2), AuxPoint stays the normal vector.
    let mut r = McMoveCircularRelative {
        execute: true,
        circ_mode: CircMode::Radius,
        aux_point: vecn(&n),
        end_point: vecn(&[6.0, 2.0, 2.0]),
        path_choice_ccw: true,
        velocity: 30.0,
        acceleration: 1000.0,
        deceleration: 1000.0,
        ..Default::default()
    };
    r.call(&mut e, g);
    assert!(r.busy, "{:?}", r.error_id);
    for _ in 0..100_000 {
        e.step();
        r.call(&mut e, g);
        if r.done {
            break;
        }
    }
    let p = e.group_position(g).unwrap();
    assert!(dist([p[0], p[1], p[2]], [12.0, 4.0, 4.0]) < 1e-9, "{p:?}");
}

#[test]
fn radius_mode_refuses_undefined_circles() {
    let (mut e, g) = group_at(2, &[0.0, 0.0]);
    for (aux, end) in [
        ([0.0, 0.0, 4.0], [10.0, 0.0]), // chord 10 > diameter 8
        ([0.0, 0.0, 0.0], [1.0, 0.0]),  // no normal, no radius
        ([0.0, 0.0, 5.0], [0.0, 0.0]),  // start = end: centre undefined
    ] {
        let mut m = radius_move(&aux, &end, true);
        m.call(&mut e, g);
        assert!(m.error, "{aux:?} {end:?}");
        assert_eq!(m.error_id, ErrorId::InvalidCircle);
    }
}

fn line(x: &[f64], tm: TransitionMode, p: f64) -> McMoveLinearAbsolute {
    McMoveLinearAbsolute {
        execute: true,
        position: vecn(x),
        velocity: 50.0,
        acceleration: 500.0,
        deceleration: 500.0,
        jerk: 5000.0,
        transition_mode: tm,
        transition_parameter: p,
        ..Default::default()
    }
}

/// Two lines meeting at `corner` (from the origin, then to `end`) with the transition on
/// the second; returns the closest approach to the corner, the largest per-cycle change
/// of an axis velocity, the largest path speed and the end position.
fn corner_run(
    corner: [f64; 2],
    end: [f64; 2],
    tm: TransitionMode,
    p: f64,
) -> (f64, f64, f64, [f64; 2]) {
    let (mut e, g) = group_at(2, &[0.0, 0.0]);
    let mut a = line(&corner, TransitionMode::None, 0.0);
    let mut b = McMoveLinearAbsolute {
        buffer_mode: BufferMode::BlendingLow,
        ..line(&end, tm, p)
    };
    a.call(&mut e, g);
    b.call(&mut e, g);
    assert!(a.busy && b.busy, "{:?}", b.error_id);
    let (mut closest, mut jump, mut vmax) = (f64::INFINITY, 0.0_f64, 0.0_f64);
    let mut prev = [0.0; 2];
    for _ in 0..100_000 {
        e.step();
        a.call(&mut e, g);
        b.call(&mut e, g);
        let pos = e.group_position(g).unwrap();
        let (v, speed) = e.group_velocity(g).unwrap();
        closest = closest.min(((pos[0] - corner[0]).powi(2) + (pos[1] - corner[1]).powi(2)).sqrt());
        for i in 0..2 {
            jump = jump.max((v[i] - prev[i]).abs());
            prev[i] = v[i];
        }
        vmax = vmax.max(speed);
        if b.done {
            return (closest, jump, vmax, [pos[0], pos[1]]);
        }
    }
    panic!("lines not done");
}

#[test]
fn max_corner_deviation_bounds_the_blend() {
    // Corners of 90, 45 (sharp turn 135) and 135 degrees (gentle turn 45).
    for end in [[100.0, 100.0], [30.0, 70.0], [200.0, 70.0]] {
        let dev = 2.0;
        let (closest, jump, vmax, at) =
            corner_run([100.0, 0.0], end, TransitionMode::MaxCornerDeviation, dev);
        // The blend passes the corner at exactly the deviation (its midpoint): no
        // sample comes nearer, and the nearest sample is within the sampling error
        // (at most 0.05 per cycle along the clothoid blend) of it.
        assert!(closest >= dev * (1.0 - 1e-9), "{end:?}: {closest}");
        assert!(closest <= dev * (1.0 + 5e-4), "{end:?}: {closest}");
        // Axis velocity vector continuous: every change within acceleration * dt (10 %
        // margin for the discrete evaluation), path speed within the block velocity.
        assert!(jump <= 500.0 * DT * 1.1, "{end:?}: {jump}");
        assert!(vmax <= 50.0 * (1.0 + 1e-9), "{vmax}");
        assert!((at[0] - end[0]).abs() < 1e-6 && (at[1] - end[1]).abs() < 1e-6);
    }
    // Without a transition the path goes through the corner, where it stops: no speed is
    // feasible at a sharp corner (the velocity vector would step).
    let (closest, jump, _, _) = corner_run([100.0, 0.0], [100.0, 100.0], TransitionMode::None, 0.0);
    assert!(
        closest < 1e-6 && jump <= 500.0 * DT * (1.0 + 1e-9),
        "{closest} {jump}"
    );
}

#[test]
fn unsupported_transition_modes_are_refused() {
    for v in [1u8, 2, 5, 255] {
        assert_eq!(
            TransitionMode::from_u8(v),
            Err(ErrorId::InvalidTransitionMode),
            "{v}"
        );
    }
    assert_eq!(
        TransitionMode::from_u8(4),
        Ok(TransitionMode::MaxCornerDeviation)
    );
    // A negative deviation is refused too.
    let (mut e, g) = group_at(2, &[0.0, 0.0]);
    let mut a = line(&[100.0, 0.0], TransitionMode::None, 0.0);
    a.call(&mut e, g);
    let mut b = line(&[100.0, 100.0], TransitionMode::MaxCornerDeviation, -1.0);
    b.call(&mut e, g);
    assert_eq!(b.error_id, ErrorId::InvalidTransitionMode);
}
