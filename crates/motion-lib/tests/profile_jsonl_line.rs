//! `plan_jsonl` (the `ladderc motion plan` back end) and straight lines in N axes.

use motion_lib::profile::line::{path_limits, Line};
use motion_lib::profile::{plan_jsonl, Limits};
use serde_json::Value;

const INPUT: &str = r#"{"kind": "rest", "p0": -2862.4958482247066, "v0": 0.0, "a0": 0.0, "p1": -344.71613673501633, "v1": 0.0, "vmax": 71.19648842444575, "amax": 9.488249292368122, "dmax": 9.488249292368122, "jmax": 3.750756973755056, "duration": 45.39715649802294, "monotone": true}

{"kind": "abort", "p0": 3771.828884870618, "v0": 5.771036688020145, "a0": 1.3215014722216147, "p1": 2926.217224442621, "v1": 0.0, "vmax": 22.912899907062723, "amax": 2.1093128192674735, "dmax": 2.1093128192674735, "jmax": 0.744904207726339, "duration": 57.10074762406526, "monotone": false}
{"kind": "line3", "start": [-690.0058518558299, -334.14453281173974, 3389.4929654951884], "end": [2634.557317482607, -3542.823838814935, -2018.924203124166], "vmax": [58.659810177766815, 48.51531304495412, 12.182497971230486], "amax": [1.8331874666057184, 5.521416704176279, 4.553164108868343], "jmax": [4.704947985718179, 1.0175658798941138, 2.900740698528456], "duration": 449.7735324497883}
"#;

#[test]
fn plan_jsonl_recomputes_durations_and_lists_phases() {
    let out = plan_jsonl(INPUT).unwrap();
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 3, "blank lines are skipped");
    let want: Vec<f64> = INPUT
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            serde_json::from_str::<Value>(l).unwrap()["duration"]
                .as_f64()
                .unwrap()
        })
        .collect();
    for (line, want) in lines.iter().zip(want) {
        let v: Value = serde_json::from_str(line).unwrap();
        let d = v["duration"].as_f64().unwrap();
        assert!((d - want).abs() < 1e-6 * want, "{d} vs {want}");
        let phases = v["phases"].as_array().unwrap();
        assert!(!phases.is_empty() && phases.len() <= 9);
        let sum: f64 = phases.iter().map(|p| p[0].as_f64().unwrap()).sum();
        assert!((sum - d).abs() < 1e-9 * d);
        assert!(v["kind"].is_string(), "the input fields are kept");
    }
}

#[test]
fn plan_jsonl_reports_the_line_of_a_bad_problem() {
    let err = plan_jsonl("\n{\"kind\": \"rest\", \"p0\": 1}\n").unwrap_err();
    assert!(err.starts_with("line 2:"), "{err}");
    assert!(err.contains("missing or non-numeric field"), "{err}");
    let err = plan_jsonl("not json").unwrap_err();
    assert!(err.starts_with("line 1:"), "{err}");
    let bad_limits = r#"{"p0": 0, "p1": 1, "vmax": -1, "amax": 1, "jmax": 1}"#;
    assert!(plan_jsonl(bad_limits)
        .unwrap_err()
        .contains("invalid limits"));
}

#[test]
fn line_reaches_the_end_within_every_axis_limit() {
    let axes = [
        Limits {
            vmax: 10.0,
            amax: 2.0,
            dmax: 3.0,
            jmax: 5.0,
        },
        Limits {
            vmax: 4.0,
            amax: 8.0,
            dmax: 8.0,
            jmax: 40.0,
        },
        Limits {
            vmax: 7.0,
            amax: 1.0,
            dmax: 1.5,
            jmax: 0.0,
        },
    ];
    let (start, end) = ([1.0, -2.0, 0.5], [41.0, 28.0, 0.5]);
    let line = Line::plan(&start, &end, &axes).unwrap();
    assert!((line.length() - 50.0).abs() < 1e-12);
    // Axis 2 does not move: it limits nothing.
    let lim = line.limits();
    assert!((lim.vmax - (10.0 / 0.8f64).min(4.0 / 0.6)).abs() < 1e-12);
    assert!((lim.amax - (2.0 / 0.8f64).min(8.0 / 0.6)).abs() < 1e-12);
    assert!((lim.jmax - (5.0 / 0.8f64).min(40.0 / 0.6)).abs() < 1e-12);
    let mut pos = [0.0; 3];
    let n = 2000;
    for i in 0..=n {
        let t = line.duration() * i as f64 / n as f64;
        let s = line.at(t, &mut pos);
        for (k, ax) in axes.iter().enumerate() {
            let u = line.unit()[k].abs();
            assert!(s.v.abs() * u <= ax.vmax * (1.0 + 1e-9));
            assert!(s.a.abs() * u <= ax.amax.max(ax.dmax) * (1.0 + 1e-9));
        }
        assert_eq!(pos[2], 0.5);
    }
    line.at(line.duration() + 1.0, &mut pos);
    for k in 0..3 {
        assert!((pos[k] - end[k]).abs() < 1e-9, "{pos:?}");
    }
}

#[test]
fn line_inputs_are_checked() {
    let ax = Limits {
        vmax: 1.0,
        amax: 1.0,
        dmax: 1.0,
        jmax: 1.0,
    };
    assert!(Line::plan(&[0.0, 0.0], &[1.0], &[ax, ax]).is_err());
    assert!(Line::plan(&[0.0], &[1.0], &[ax, ax]).is_err());
    assert!(Line::plan(&[f64::NAN], &[1.0], &[ax]).is_err());
    assert!(path_limits(&[1.0], &[Limits { vmax: 0.0, ..ax }]).is_err());
    // A line of length 0 takes no time.
    let line = Line::plan(&[3.0, 4.0], &[3.0, 4.0], &[ax, ax]).unwrap();
    assert_eq!(line.duration(), 0.0);
}
