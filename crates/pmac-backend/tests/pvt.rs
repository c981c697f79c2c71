//! PVT: segments from paper B's jerk-limited motion, their text, and reconstruction within 1e-6 of the travel.

mod common;

use common::{cs, paper_b, sampled, stop_move};
use pmac_backend::model::{Dialect, FnSource, Trajectory, TrajectorySource};
use pmac_backend::pvt::{self, PvtOptions};
use pmac_backend::verify::{max_deviation, reconstruct_pvt};

fn travel(tr: &Trajectory) -> f64 {
    tr.axes
        .iter()
        .map(|ax| {
            let lo = ax.iter().map(|s| s.p).fold(f64::INFINITY, f64::min);
            let hi = ax.iter().map(|s| s.p).fold(f64::NEG_INFINITY, f64::max);
            hi - lo
        })
        .fold(0.0, f64::max)
}

#[test]
fn paper_b_pvt_reproduces_the_trajectory() {
    let input = sampled(&paper_b(), 0.001);
    let opts = PvtOptions::default();
    let segs = pvt::segments(&input, opts.segment_ms / 1000.0).unwrap();
    let text = pvt::to_lines(&cs(&['X', 'Y', 'Z']), &segs, &opts)
        .unwrap()
        .join("\n");
    let curve = reconstruct_pvt(&text, &['X', 'Y', 'Z'], &[0.0; 3], opts.velocity_time_ms).unwrap();
    assert_eq!(curve.segment_count(), segs.len());
    assert!((curve.duration() - input.duration()).abs() < 1e-9);
    let dev = max_deviation(&curve, &input, input.cycle_s);
    let tol = 1e-6 * travel(&input);
    assert!(dev <= tol, "PVT deviates by {dev}, tolerance {tol}");
    eprintln!(
        "paper B: {} segments, max deviation {dev:e} (tolerance {tol:e})",
        segs.len()
    );
}

#[test]
fn a_wrong_velocity_is_caught_by_the_reconstruction() {
    let input = sampled(&paper_b()[..1], 0.001);
    let opts = PvtOptions::default();
    let segs = pvt::segments(&input, 0.01).unwrap();
    let mut lines = pvt::to_lines(&cs(&['X', 'Y', 'Z']), &segs, &opts).unwrap();
    // Halve the X velocity of one cruise segment.
    let i = lines.len() / 2;
    let (x, rest) = lines[i].split_once(' ').unwrap();
    let (p, v) = x.split_once(':').unwrap();
    lines[i] = format!("{p}:{} {rest}", v.parse::<f64>().unwrap() / 2.0);
    let curve = reconstruct_pvt(&lines.join("\n"), &['X', 'Y', 'Z'], &[0.0; 3], 1000.0).unwrap();
    assert!(max_deviation(&curve, &input, 0.001) > 1e-6 * travel(&input));
}

#[test]
fn short_move_pvt_text() {
    // 0.2 units in X and Y at v 1, a 10, j 100: a short S-curve, cut into 30 ms segments.
    let moves = [stop_move(vec![0.2, -0.1], 1.0, 10.0, 100.0)];
    let input = sampled(&moves, 0.001);
    let opts = PvtOptions {
        segment_ms: 30.0,
        ..PvtOptions::default()
    };
    let segs = pvt::segments(&input, 0.03).unwrap();
    let c = cs(&['X', 'Y']);
    let turbo = pvt::to_lines(&c, &segs, &opts).unwrap().join("\n");
    // The last segment is shorter and gets its own PVT time.
    assert!(
        turbo.lines().filter(|l| l.starts_with("PVT")).count() == 2,
        "{turbo}"
    );
    insta::assert_snapshot!("short_move_pvt_turbo", turbo);
    // Velocity unit: Isx90 = 1 ms means units per ms (a thousandth of units per second). The travel is only
    // 0.2 units, so 1e-6 of it needs more than the default 6 decimals.
    let per_ms = PvtOptions {
        velocity_time_ms: 1.0,
        dialect: Dialect::Power,
        decimals: 9,
        ..opts.clone()
    };
    let power = pvt::to_lines(&c, &segs, &per_ms).unwrap().join("\n");
    insta::assert_snapshot!("short_move_pvt_power_per_ms", power);
    let curve = reconstruct_pvt(&power, &['X', 'Y'], &[0.0; 2], 1.0).unwrap();
    // Exact at every segment end (to the printed decimals) ...
    let mut t = 0.0;
    for s in &segs {
        t += s.duration_s;
        for (got, want) in curve.state(t).iter().zip(&s.end) {
            assert!(
                (got.0 - want.0).abs() <= 1e-6 * travel(&input),
                "at {t}: {got:?} vs {want:?}"
            );
        }
    }
    // ... and between them within the Hermite bound for the jerk steps inside segments
    // (here the jerk flips from +100 to -100 inside 30 ms segments: up to 200 * 0.03^3 / 192).
    let bound = pvt::hermite_error_bound(200.0, 0.03);
    let dev = max_deviation(&curve, &input, 0.001);
    assert!(
        dev > 1e-6 * travel(&input) && dev <= bound,
        "deviation {dev}, bound {bound}"
    );
}

#[test]
fn function_sources_are_accepted() {
    // A cubic in time on one axis: PVT (cubic Hermite) is exact for it anywhere.
    let src = FnSource {
        axes: 1,
        duration: 0.095,
        state: |t: f64| vec![(t * t * t - t, 3.0 * t * t - 1.0)],
    };
    let segs = pvt::segments(&src, 0.01).unwrap();
    assert_eq!(segs.len(), 10);
    assert!((segs[9].duration_s - 0.005).abs() < 1e-12);
    let text = pvt::to_lines(
        &cs(&['A']),
        &segs,
        &PvtOptions {
            decimals: 12,
            ..Default::default()
        },
    )
    .unwrap()
    .join("\n");
    let curve = reconstruct_pvt(&text, &['A'], &[0.0], 1000.0).unwrap();
    // Starting at rest differs from the source's -1 start velocity only in the first segment.
    let late = FnSource {
        axes: 1,
        duration: 0.095,
        state: |t: f64| curve.state(t.max(0.01)),
    };
    let exact = FnSource {
        axes: 1,
        duration: 0.095,
        state: |t: f64| src.state(t.max(0.01)),
    };
    assert!(max_deviation(&late, &exact, 0.0005) < 1e-9);
}

#[test]
fn bad_trajectories_give_e7003() {
    let input = sampled(&paper_b()[..1], 0.001);
    assert_eq!(pvt::segments(&input, 0.0025).unwrap_err().code(), "E7003");
    assert_eq!(pvt::segments(&input, 0.0).unwrap_err().code(), "E7003");
    let mut ragged = input.clone();
    ragged.axes[1].pop();
    assert_eq!(pvt::segments(&ragged, 0.01).unwrap_err().code(), "E7003");
    let segs = pvt::segments(&input, 0.01).unwrap();
    assert_eq!(
        pvt::to_lines(&cs(&['X', 'Y']), &segs, &PvtOptions::default())
            .unwrap_err()
            .code(),
        "E7003"
    );
}
