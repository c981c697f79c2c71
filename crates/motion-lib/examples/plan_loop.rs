//! Plans the oracle problems of one kind in a loop, for profiling the planner with
//! callgrind (`valgrind --tool=callgrind target/release/examples/plan_loop rest 100`).
//!
//! Arguments: the kind (`rest`, `blend`, `abort`, `line3` or `all`) and the number of
//! passes over the problems (default 100). Prints the sum of the durations.
//! With `PLAN_LOOP_TIME` set: the median over the problems of the best of 6 batches of 40
//! plans (a rough figure for trying changes; the bench is the measurement).
#![forbid(unsafe_code)]

use motion_lib::profile::line::Line;
use motion_lib::profile::{Limits, Profile, State};
use serde_json::Value;
use std::hint::black_box;

fn f(v: &Value, k: &str) -> f64 {
    v[k].as_f64().unwrap_or(0.0)
}

fn fs(v: &Value, k: &str) -> Vec<f64> {
    v[k].as_array()
        .map(|a| a.iter().filter_map(Value::as_f64).collect())
        .unwrap_or_default()
}

enum Problem {
    Axis(State, f64, f64, Limits),
    Line(Vec<f64>, Vec<f64>, Vec<Limits>),
}

fn main() {
    let mut args = std::env::args().skip(1);
    let kind = args.next().unwrap_or_else(|| "all".into());
    let passes: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(100);
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/ruckig-profiles.jsonl"
    );
    let text = std::fs::read_to_string(path).expect("oracle file");
    let problems: Vec<Problem> = text
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| serde_json::from_str::<Value>(l).expect("JSON"))
        .filter(|v| kind == "all" || v["kind"].as_str() == Some(kind.as_str()))
        .map(|v| {
            if v["kind"].as_str() == Some("line3") {
                let axes = (0..3)
                    .map(|i| Limits {
                        vmax: fs(&v, "vmax")[i],
                        amax: fs(&v, "amax")[i],
                        dmax: fs(&v, "amax")[i],
                        jmax: fs(&v, "jmax")[i],
                    })
                    .collect();
                Problem::Line(fs(&v, "start"), fs(&v, "end"), axes)
            } else {
                let start = State {
                    p: f(&v, "p0"),
                    v: f(&v, "v0"),
                    a: f(&v, "a0"),
                };
                let lim = Limits {
                    vmax: f(&v, "vmax"),
                    amax: f(&v, "amax"),
                    dmax: f(&v, "dmax"),
                    jmax: f(&v, "jmax"),
                };
                Problem::Axis(start, f(&v, "p1"), f(&v, "v1"), lim)
            }
        })
        .collect();
    let plan = |pb: &Problem| -> f64 {
        match pb {
            Problem::Axis(start, p1, v1, lim) => Profile::position(
                black_box(*start),
                black_box(*p1),
                black_box(*v1),
                black_box(lim),
            )
            .as_ref()
            .map(|p| black_box(p).duration())
            .unwrap_or(0.0),
            Problem::Line(s, e, axes) => Line::plan(black_box(s), black_box(e), black_box(axes))
                .as_ref()
                .map(|l| black_box(l).duration())
                .unwrap_or(0.0),
        }
    };
    let mut sum = 0.0;
    if std::env::var_os("PLAN_LOOP_TIME").is_some() {
        // Like the bench: per problem, the best of 6 batches of 40 plans; the median.
        let mut per: Vec<f64> = problems
            .iter()
            .map(|pb| {
                (0..6)
                    .map(|_| {
                        let t0 = std::time::Instant::now();
                        for _ in 0..40 {
                            sum += plan(pb);
                        }
                        t0.elapsed().as_nanos() as f64 / 40.0
                    })
                    .fold(f64::INFINITY, f64::min)
            })
            .collect();
        per.sort_by(f64::total_cmp);
        println!(
            "{kind}: median {:.1} ns per plan ({sum})",
            per[per.len() / 2]
        );
        return;
    }
    for _ in 0..passes {
        for pb in &problems {
            sum += plan(pb);
        }
    }
    println!(
        "{} problems x {passes}: sum of durations {sum}",
        problems.len()
    );
}
