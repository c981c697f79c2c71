//! Oracle test: every problem of /work/shared/oracle/ruckig-profiles.jsonl (ruckig 0.19.4
//! durations) must be planned with the same duration (1e-6 relative).

use motion_lib::profile::line::Line;
use motion_lib::profile::{Limits, Profile, State};
use serde_json::Value;

fn oracle() -> String {
    // The main repo sits at /work/main, worktrees at /work/wt/<name>: try both depths.
    let dir = env!("CARGO_MANIFEST_DIR");
    ["/../../../shared", "/../../../../shared"]
        .iter()
        .find_map(|up| {
            std::fs::read_to_string(format!("{dir}{up}/oracle/ruckig-profiles.jsonl")).ok()
        })
        .expect("oracle file /work/shared/oracle/ruckig-profiles.jsonl readable")
}

fn f(v: &Value, k: &str) -> f64 {
    v[k].as_f64().unwrap()
}

fn fs(v: &Value, k: &str) -> Vec<f64> {
    v[k].as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

/// Plans one oracle problem; returns (kind, planned duration, oracle duration).
fn plan(v: &Value) -> (String, f64, f64) {
    let kind = v["kind"].as_str().unwrap().to_string();
    let want = f(v, "duration");
    let got = if kind == "line3" {
        let axes: Vec<Limits> = (0..3)
            .map(|i| Limits {
                vmax: fs(v, "vmax")[i],
                amax: fs(v, "amax")[i],
                dmax: fs(v, "amax")[i],
                jmax: fs(v, "jmax")[i],
            })
            .collect();
        Line::plan(&fs(v, "start"), &fs(v, "end"), &axes).map_or(f64::NAN, |l| l.duration())
    } else {
        let start = State {
            p: f(v, "p0"),
            v: f(v, "v0"),
            a: f(v, "a0"),
        };
        let lim = Limits {
            vmax: f(v, "vmax"),
            amax: f(v, "amax"),
            dmax: f(v, "dmax"),
            jmax: f(v, "jmax"),
        };
        Profile::position(start, f(v, "p1"), f(v, "v1"), &lim).map_or(f64::NAN, |p| p.duration())
    };
    (kind, got, want)
}

#[test]
fn oracle_durations_match_ruckig() {
    let text = oracle();
    let mut total = 0;
    let mut bad = Vec::new();
    for line in text.lines().filter(|l| !l.trim().is_empty()) {
        let v: Value = serde_json::from_str(line).unwrap();
        let (kind, got, want) = plan(&v);
        total += 1;
        let ok = (got - want).abs() <= 1e-6 * want.abs().max(1e-9);
        if !ok {
            bad.push(format!("{kind}: got {got}, want {want}: {line}"));
        }
    }
    assert_eq!(total, 2000, "the oracle holds 2000 problems");
    eprintln!("oracle: {} of {total} durations match", total - bad.len());
    for b in bad.iter().take(10) {
        eprintln!("{b}");
    }
    assert!(bad.is_empty(), "{} mismatches", bad.len());
}
