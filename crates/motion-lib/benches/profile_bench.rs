//! Plan time of `motion_lib::profile` against rsruckig on the oracle problems, side by
//! side in one run, and the per-cycle sampling cost of `Profile::at`.
//!
//! Run: `cargo bench -p motion-lib --bench profile_bench` (`PROFILE_BENCH_ROUNDS=N`,
//! default 5). For each oracle problem (rest, blend, abort: one axis; line3: a 3-axis
//! straight line, ours `Line::plan` with its geometry and projected limits against
//! rsruckig's 1-D `calculate` on the same path problem) both planners run in interleaved
//! rounds; in each round a problem is timed in `BATCHES` pairs of batches of `REPS`
//! plans, ours and rsruckig's alternating (the order flips per round), and the best batch
//! of each planner counts, which filters out the preemptions of a shared machine. Per problem the
//! ratio ours / rsruckig is the median over the rounds; the report gives, per kind, the
//! median plan time of each planner and the median of the per-problem ratios.
#![forbid(unsafe_code)]

use motion_lib::profile::line::{path_limits, Line};
use motion_lib::profile::{Limits, Profile, State};
use rsruckig::prelude::*;
use serde_json::Value;
use std::hint::black_box;
use std::time::Instant;

const REPS: u32 = 40;
const BATCHES: usize = 6;

struct Problem {
    kind: String,
    start: State,
    target_p: f64,
    target_v: f64,
    lim: Limits,
    line: Option<(Vec<f64>, Vec<f64>, Vec<Limits>)>,
}

fn oracle() -> String {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/ruckig-profiles.jsonl"
    );
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn f(v: &Value, k: &str) -> f64 {
    v[k].as_f64().unwrap_or(0.0)
}

fn fs(v: &Value, k: &str) -> Vec<f64> {
    v[k].as_array()
        .map(|a| a.iter().filter_map(Value::as_f64).collect())
        .unwrap_or_default()
}

fn problems() -> Vec<Problem> {
    oracle()
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let v: Value = serde_json::from_str(l).expect("oracle line is JSON");
            let kind = v["kind"].as_str().unwrap_or("").to_string();
            if kind == "line3" {
                let (s, e) = (fs(&v, "start"), fs(&v, "end"));
                let axes: Vec<Limits> = (0..3)
                    .map(|i| Limits {
                        vmax: fs(&v, "vmax")[i],
                        amax: fs(&v, "amax")[i],
                        dmax: fs(&v, "amax")[i],
                        jmax: fs(&v, "jmax")[i],
                    })
                    .collect();
                let d: Vec<f64> = s.iter().zip(&e).map(|(a, b)| b - a).collect();
                let len = d.iter().map(|x| x * x).sum::<f64>().sqrt();
                let unit: Vec<f64> = d.iter().map(|x| x / len).collect();
                let lim = path_limits(&unit, &axes).expect("valid limits");
                Problem {
                    kind,
                    start: State::default(),
                    target_p: len,
                    target_v: 0.0,
                    lim,
                    line: Some((s, e, axes)),
                }
            } else {
                Problem {
                    kind,
                    start: State {
                        p: f(&v, "p0"),
                        v: f(&v, "v0"),
                        a: f(&v, "a0"),
                    },
                    target_p: f(&v, "p1"),
                    target_v: f(&v, "v1"),
                    lim: Limits {
                        vmax: f(&v, "vmax"),
                        amax: f(&v, "amax"),
                        dmax: f(&v, "dmax"),
                        jmax: f(&v, "jmax"),
                    },
                    line: None,
                }
            }
        })
        .collect()
}

fn ruckig_input(pb: &Problem) -> InputParameter<1> {
    let mut input = InputParameter::new(None);
    let (amax, amin) = if pb.target_p >= pb.start.p {
        (pb.lim.amax, -pb.lim.dmax)
    } else {
        (pb.lim.dmax, -pb.lim.amax)
    };
    input.current_position[0] = pb.start.p;
    input.current_velocity[0] = pb.start.v;
    input.current_acceleration[0] = pb.start.a;
    input.target_position[0] = pb.target_p;
    input.target_velocity[0] = pb.target_v;
    input.max_velocity[0] = pb.lim.vmax;
    input.max_acceleration[0] = amax;
    input.min_acceleration = Some(daov_stack![amin]);
    input.max_jerk[0] = pb.lim.jmax;
    input
}

/// Nanoseconds per call of `a` and of `b`: `BATCHES` pairs of batches of `REPS` calls,
/// alternating a and b (the order flips with `flip`), and the best batch of each. Pairs
/// this close in time see the same load, and the best batch is one without preemption.
fn time_pair(mut a: impl FnMut(), mut b: impl FnMut(), flip: bool) -> (f64, f64) {
    let (mut best_a, mut best_b) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..BATCHES {
        if flip {
            best_b = best_b.min(batch(&mut b));
            best_a = best_a.min(batch(&mut a));
        } else {
            best_a = best_a.min(batch(&mut a));
            best_b = best_b.min(batch(&mut b));
        }
    }
    (best_a, best_b)
}

/// Nanoseconds per call of `f` over one batch of `REPS` calls.
#[inline(always)]
fn batch(f: &mut impl FnMut()) -> f64 {
    let t = Instant::now();
    for _ in 0..REPS {
        f();
    }
    t.elapsed().as_nanos() as f64 / REPS as f64
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    if v.is_empty() {
        f64::NAN
    } else {
        v[v.len() / 2]
    }
}

fn main() {
    let problems = problems();
    let rounds: usize = std::env::var("PROFILE_BENCH_ROUNDS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(5)
        .max(1);
    let mut otg = Ruckig::<1, IgnoreErrorHandler>::new(None, 0.001);
    let mut traj = Trajectory::new(None);
    let inputs: Vec<InputParameter<1>> = problems.iter().map(ruckig_input).collect();
    // Our planners write into a slot reused from plan to plan, as rsruckig writes `traj`.
    let mut prof_slot = None;
    let mut line_slot = None;
    // times[problem][round] = (ours ns, rsruckig ns)
    let mut times = vec![Vec::with_capacity(rounds); problems.len()];
    for round in 0..rounds {
        for (k, pb) in problems.iter().enumerate() {
            let ours = || {
                if let Some((s, e, axes)) = &pb.line {
                    let line = Line::plan_into(
                        &mut line_slot,
                        black_box(s),
                        black_box(e),
                        black_box(axes),
                    );
                    black_box(&line);
                } else {
                    let prof = Profile::position_into(
                        &mut prof_slot,
                        black_box(pb.start),
                        black_box(pb.target_p),
                        black_box(pb.target_v),
                        black_box(&pb.lim),
                    );
                    black_box(&prof);
                }
            };
            let theirs = || {
                let result = otg.calculate(black_box(&inputs[k]), &mut traj);
                black_box(&result);
                black_box(&traj);
            };
            let pair = time_pair(ours, theirs, round % 2 == 1);
            times[k].push(pair);
        }
    }
    let mut max_dev: f64 = 0.0;
    for (pb, input) in problems.iter().zip(&inputs) {
        otg.calculate(input, &mut traj).expect("rsruckig plans");
        let d_ours = match &pb.line {
            Some((s, e, axes)) => Line::plan(s, e, axes).map(|l| l.duration()),
            None => {
                Profile::position(pb.start, pb.target_p, pb.target_v, &pb.lim).map(|p| p.duration())
            }
        }
        .unwrap_or(f64::NAN);
        max_dev = max_dev.max((d_ours - traj.get_duration()).abs() / traj.get_duration());
    }
    // Per problem: medians over the rounds.
    let rows: Vec<(&str, f64, f64, f64)> = problems
        .iter()
        .zip(&times)
        .map(|(pb, t)| {
            (
                pb.kind.as_str(),
                median(t.iter().map(|x| x.0).collect()),
                median(t.iter().map(|x| x.1).collect()),
                median(t.iter().map(|x| x.0 / x.1).collect()),
            )
        })
        .collect();
    if std::env::var_os("PROFILE_BENCH_DUMP").is_some() {
        for (k, r) in rows.iter().enumerate() {
            eprintln!("{k} {} {:.1} {:.1}", r.0, r.1, r.2);
        }
    }
    println!(
        "profile_bench: {} oracle problems, {rounds} rounds, best of {BATCHES} interleaved batches of {REPS} plans per planner",
        rows.len()
    );
    println!(
        "{:<6} {:>6} {:>10} {:>12} {:>13} {:>6}",
        "kind", "count", "ours ns", "rsruckig ns", "median ratio", "goal"
    );
    let mut worst: f64 = 0.0;
    for kind in ["rest", "blend", "abort", "line3", "all"] {
        let sel: Vec<_> = rows
            .iter()
            .filter(|r| kind == "all" || r.0 == kind)
            .collect();
        let ratio = median(sel.iter().map(|r| r.3).collect());
        worst = worst.max(ratio);
        println!(
            "{:<6} {:>6} {:>10.0} {:>12.0} {:>13.3} {:>6}",
            kind,
            sel.len(),
            median(sel.iter().map(|r| r.1).collect()),
            median(sel.iter().map(|r| r.2).collect()),
            ratio,
            if ratio <= 0.5 { "met" } else { "NOT met" }
        );
    }
    println!(
        "worst kind: {worst:.3} (goal <= 0.5 on every kind); max relative duration difference to rsruckig: {max_dev:.3e}"
    );

    // Per-cycle sampling cost: `at(t)` over a profile, one sample per 1 ms cycle.
    let pb = &problems[problems.len() / 3];
    let prof = Profile::position(pb.start, pb.target_p, pb.target_v, &pb.lim).expect("plans");
    let n = 1_000_000u32;
    let dt = prof.duration() * 1.2 / n as f64;
    let t0 = Instant::now();
    let mut acc = 0.0;
    for i in 0..n {
        acc += prof.at(black_box(i as f64 * dt)).p;
    }
    let at_ns = t0.elapsed().as_nanos() as f64 / n as f64;
    black_box(acc);
    println!(
        "Profile::at: {at_ns:.1} ns per sample ({} phases, {n} samples over 1.2 x duration)",
        prof.phases().len()
    );
}
