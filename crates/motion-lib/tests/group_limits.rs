//! Group moves against the axes' limits: software limits checked on the planned path
//! (line end points, an arc's bulge, a buffered circle from where it really starts) before
//! any motion, and the arc speed lowered by the axes' acceleration and jerk limits
//! (centripetal v^2 / r and its jerk v^3 / r^2), reported as a reduction.
//!
//! Input: 2-axis X/Y groups with software limits [-10, 10] (or none) and 1 ms cycles.
//! Output: ErrorIDs 27 / 29 / 60 with no motion; for arcs, every cycle's axis acceleration
//! and jerk within the limits, and the `ArcSpeed` reduction with the speed requested and
//! reached, also in `group_junction_now` in the cycle the arc starts.

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::McPower;
use motion_lib::buffer::BufferMode;
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::error::ErrorId;
use motion_lib::fsm::GroupState;
use motion_lib::group::ReductionReason;
use motion_lib::group_blocks::{
    McAddAxisToGroup, McGroupEnable, McMoveCircularAbsolute, McMoveLinearAbsolute,
};
use motion_lib::path::{CircMode, Vecn};
use motion_lib::profile::Limits;

const LIM: Limits = Limits {
    vmax: 100.0,
    amax: 200.0,
    dmax: 200.0,
    jmax: 2000.0,
};

fn group(sw: Option<f64>) -> (Engine, usize, [usize; 2]) {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let g = e.add_group();
    let mut axes = [0; 2];
    for (i, ax) in axes.iter_mut().enumerate() {
        let cfg = AxisConfig {
            limits: LIM,
            sw_limit_neg: -sw.unwrap_or(0.0),
            sw_limit_pos: sw.unwrap_or(0.0),
            sw_limits_enabled: sw.is_some(),
            ..AxisConfig::default()
        };
        *ax = e.add_axis(cfg).unwrap();
        let mut p = McPower {
            enable: true,
            ..Default::default()
        };
        p.call(&mut e, *ax);
        let mut add = McAddAxisToGroup {
            execute: true,
            axis: *ax,
            ident_in_group: i,
            ..Default::default()
        };
        add.call(&mut e, g);
        assert!(add.done);
    }
    let mut en = McGroupEnable {
        execute: true,
        ..Default::default()
    };
    en.call(&mut e, g);
    assert!(en.done);
    (e, g, axes)
}

fn xy(x: f64, y: f64) -> Vecn {
    let mut v = [0.0; 16];
    v[0] = x;
    v[1] = y;
    v
}

fn line(x: f64, y: f64) -> McMoveLinearAbsolute {
    McMoveLinearAbsolute {
        execute: true,
        position: xy(x, y),
        velocity: 50.0,
        acceleration: 200.0,
        deceleration: 200.0,
        jerk: 2000.0,
        ..Default::default()
    }
}

/// A half circle about the centre `c` from the current point to `end` (CENTER mode).
fn arc(c: (f64, f64), end: (f64, f64), v: f64) -> McMoveCircularAbsolute {
    McMoveCircularAbsolute {
        execute: true,
        circ_mode: CircMode::Center,
        aux_point: xy(c.0, c.1),
        end_point: xy(end.0, end.1),
        path_choice_ccw: true,
        velocity: v,
        acceleration: 200.0,
        deceleration: 200.0,
        jerk: 2000.0,
        ..Default::default()
    }
}

fn run_line_to(e: &mut Engine, g: usize, x: f64, y: f64) {
    let mut b = line(x, y);
    for _ in 0..20_000 {
        b.call(e, g);
        if b.done {
            return;
        }
        assert!(!b.error, "{:?}", b.error_id);
        e.step();
    }
    panic!("the line did not end");
}

#[test]
fn a_line_whose_end_point_leaves_the_range_is_refused_before_any_motion() {
    let (mut e, g, axes) = group(Some(10.0));
    let mut b = line(5.0, 12.0);
    b.call(&mut e, g);
    assert!(b.error && !b.busy);
    assert_eq!(b.error_id, ErrorId::TargetBeyondSoftwareLimit);
    e.step();
    assert_eq!(e.group_state(g).unwrap(), GroupState::GroupStandby);
    for a in axes {
        assert_eq!(e.set_position_of(a).unwrap(), 0.0);
    }
    // Inside the range it runs.
    run_line_to(&mut e, g, 5.0, 9.0);
    assert!((e.set_position_of(axes[1]).unwrap() - 9.0).abs() < 1e-12);
}

#[test]
fn an_arc_whose_bulge_leaves_the_range_is_refused_while_its_end_points_are_inside() {
    let (mut e, g, axes) = group(Some(10.0));
    run_line_to(&mut e, g, 6.0, 0.0);
    // Half circle about (0, 0) from (6, 0) to (-6, 0) counter-clockwise: it passes (0, 6),
    // inside. About (0, 4) with radius sqrt(52) = 7.2 it would pass y = 11.2: outside.
    let mut bad = arc((0.0, 4.0), (-6.0, 0.0), 20.0);
    bad.call(&mut e, g);
    assert!(bad.error && !bad.busy, "{bad:?}");
    assert_eq!(bad.error_id, ErrorId::PathBeyondSoftwareLimit);
    e.step();
    assert_eq!(e.set_position_of(axes[0]).unwrap(), 6.0);
    assert_eq!(e.set_position_of(axes[1]).unwrap(), 0.0);
    let mut ok = arc((0.0, 0.0), (-6.0, 0.0), 20.0);
    let mut top: f64 = 0.0;
    for _ in 0..20_000 {
        ok.call(&mut e, g);
        if ok.done {
            break;
        }
        assert!(!ok.error, "{:?}", ok.error_id);
        e.step();
        top = top.max(e.set_position_of(axes[1]).unwrap());
    }
    assert!(ok.done);
    assert!((top - 6.0).abs() < 1e-3, "top {top}");
    assert!((e.set_position_of(axes[0]).unwrap() + 6.0).abs() < 1e-9);
}

#[test]
fn a_buffered_arc_is_checked_from_where_it_starts() {
    let (mut e, g, _) = group(Some(10.0));
    // A line to (0, 6), then buffered arcs from its end: about (6, 6) to (12, 6) ends
    // outside (27); about (3, 6) to (6, 6) over the top stays inside.
    let mut l = line(0.0, 6.0);
    l.call(&mut e, g);
    assert!(l.busy);
    let mut far = arc((6.0, 6.0), (12.0, 6.0), 20.0);
    far.buffer_mode = BufferMode::Buffered;
    far.call(&mut e, g);
    assert_eq!(far.error_id, ErrorId::TargetBeyondSoftwareLimit);
    let mut bulge = arc((3.0, 6.0), (6.0, 6.0), 20.0);
    bulge.buffer_mode = BufferMode::Buffered;
    bulge.path_choice_ccw = false;
    // Clockwise about (3, 6) from (0, 6): over the top, y up to 9 (inside).
    bulge.call(&mut e, g);
    assert!(bulge.busy, "{bulge:?}");
    // From the bulge's end (6, 6) clockwise about (6, 0) to (6, -6): both ends inside,
    // the arc passes x = 12.
    let mut big = arc((6.0, 0.0), (6.0, -6.0), 20.0);
    big.buffer_mode = BufferMode::Buffered;
    big.path_choice_ccw = false;
    big.call(&mut e, g);
    assert!(big.error && !big.busy);
    assert_eq!(big.error_id, ErrorId::PathBeyondSoftwareLimit);
    for _ in 0..20_000 {
        l.call(&mut e, g);
        bulge.call(&mut e, g);
        if bulge.done {
            break;
        }
        assert!(!bulge.error, "{:?}", bulge.error_id);
        e.step();
    }
    assert!(bulge.done);
}

/// Runs an arc to its end and checks every axis's acceleration and jerk cycle to cycle.
fn arc_within_limits(e: &mut Engine, g: usize, axes: [usize; 2], b: &mut McMoveCircularAbsolute) {
    let dt = e.config().cycle;
    let mut prev: Option<[f64; 2]> = None;
    for _ in 0..200_000 {
        b.call(e, g);
        if b.done {
            return;
        }
        assert!(!b.error, "{:?}", b.error_id);
        e.step();
        let a = [
            e.set_acceleration_of(axes[0]).unwrap(),
            e.set_acceleration_of(axes[1]).unwrap(),
        ];
        for i in 0..2 {
            assert!(a[i].abs() <= LIM.amax * (1.0 + 1e-9), "a {}", a[i]);
            if let Some(p) = prev {
                let j = (a[i] - p[i]).abs() / dt;
                assert!(j <= LIM.jmax * (1.0 + 1e-9), "jerk {j}");
            }
        }
        prev = Some(a);
    }
    panic!("the arc did not end");
}

#[test]
fn a_tight_arc_runs_at_the_speed_its_curvature_allows_and_reports_it() {
    // Radius 1: the turn alone allows v <= sqrt(amax / 2 / r) = 10 and the jerk
    // v <= cbrt(jmax / 4 * r^2) = 7.94; the block asks for 50.
    let (mut e, g, axes) = group(None);
    run_line_to(&mut e, g, 1.0, 0.0);
    let mut b = arc((0.0, 0.0), (-1.0, 0.0), 50.0);
    b.call(&mut e, g);
    assert!(b.busy);
    e.step();
    let (req, reached) = e.group_junction_now(g).unwrap();
    assert_eq!(req, 50.0);
    let v_jerk = (LIM.jmax / 4.0_f64).cbrt();
    assert!((reached - v_jerk).abs() < 1e-9, "reached {reached}");
    let (list, count) = e.group_reductions(g).unwrap();
    let r = list.last().unwrap();
    assert_eq!(count, 1);
    assert_eq!(r.reason, ReductionReason::ArcSpeed);
    assert_eq!((r.requested, r.reached), (req, reached));
    assert_eq!(r.block, 2);
    let mut peak: f64 = 0.0;
    let dt = e.config().cycle;
    let mut prev: Option<[f64; 2]> = None;
    for _ in 0..20_000 {
        b.call(&mut e, g);
        if b.done {
            break;
        }
        e.step();
        assert_eq!(e.group_junction_now(g).unwrap(), (0.0, 0.0));
        peak = peak.max(e.group_velocity(g).unwrap().1);
        let a = [
            e.set_acceleration_of(axes[0]).unwrap(),
            e.set_acceleration_of(axes[1]).unwrap(),
        ];
        for i in 0..2 {
            assert!(a[i].abs() <= LIM.amax * (1.0 + 1e-9), "a {}", a[i]);
            if let Some(p) = prev {
                let j = (a[i] - p[i]).abs() / dt;
                assert!(j <= LIM.jmax * (1.0 + 1e-9), "jerk {j}");
            }
        }
        prev = Some(a);
    }
    assert!(b.done);
    assert!(
        peak <= v_jerk * (1.0 + 1e-9) && peak > 0.9 * v_jerk,
        "peak {peak}"
    );
}

#[test]
fn a_wide_arc_keeps_its_speed_and_reports_nothing() {
    let (mut e, g, axes) = group(None);
    run_line_to(&mut e, g, 100.0, 0.0);
    let mut b = arc((0.0, 0.0), (-100.0, 0.0), 5.0);
    arc_within_limits(&mut e, g, axes, &mut b);
    let (_, count) = e.group_reductions(g).unwrap();
    assert_eq!(count, 0);
}

#[test]
fn an_aborting_line_that_would_overshoot_is_refused_and_the_group_brakes_in_range() {
    let (mut e, g, axes) = group(Some(10.0));
    run_line_to(&mut e, g, -9.0, 0.0);
    // On the way along +X to 9 at 40 mm/s: an aborting line to 9.5 with a deceleration
    // of 20 cannot stop before x = 10 (40^2 / 40 = 40 from where it is).
    let mut first = line(9.0, 0.0);
    for _ in 0..2000 {
        first.call(&mut e, g);
        e.step();
        if e.group_velocity(g).unwrap().1 >= 40.0 {
            break;
        }
    }
    assert!(e.group_velocity(g).unwrap().1 >= 40.0);
    let mut over = line(9.5, 0.0);
    over.deceleration = 20.0;
    over.call(&mut e, g);
    let mut top: f64 = 0.0;
    for _ in 0..20_000 {
        over.call(&mut e, g);
        first.call(&mut e, g);
        e.step();
        top = top.max(e.set_position_of(axes[0]).unwrap());
        if e.group_state(g).unwrap() == GroupState::GroupStandby {
            break;
        }
    }
    assert!(over.error, "{over:?}");
    assert_eq!(over.error_id, ErrorId::PathBeyondSoftwareLimit);
    assert!(first.command_aborted);
    assert_eq!(e.group_state(g).unwrap(), GroupState::GroupStandby);
    assert!(top < 9.0, "top {top}");
}
