//! Motion programs: a reference program of paper B's moves, paper B's moves, ruckig's time-optimal durations, dialects, errors.

use pmac_backend::model::{AxisDef, CoordSystem, Dialect, LinearMove, MoveMode, Transition};
use pmac_backend::program::{self, ProgramOptions};
use pmac_backend::scurve::{project, RestToRest};
use pmac_backend::verify::{max_deviation, program_move_times, reconstruct_program};
use pmac_backend::TrajectorySource;

/// The ruckig oracle (its time-optimal durations), kept with the motion library's tests.
fn oracle() -> String {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../motion-lib/tests/data/ruckig-profiles.jsonl"
    );
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn xyz() -> CoordSystem {
    let axis = |motor, name| AxisDef {
        motor,
        name,
        counts_per_unit: 1000.0,
    };
    CoordSystem {
        number: 1,
        axes: vec![axis(1, 'X'), axis(2, 'Y'), axis(3, 'Z')],
    }
}

/// Paper B's three targets with the given per-axis speeds, a = d = 5, j = 2.
fn paper_b(speeds: [f64; 3], transitions: [Transition; 3]) -> Vec<LinearMove> {
    let targets = [
        [1600.0, 1200.0, 800.0],
        [2200.0, 3800.0, 5000.0],
        [4500.0, 4200.0, 4800.0],
    ];
    (0..3)
        .map(|i| LinearMove {
            target: targets[i].to_vec(),
            velocity: speeds[i],
            acceleration: 5.0,
            deceleration: 5.0,
            jerk: 2.0,
            mode: MoveMode::Abs,
            transition: transitions[i],
        })
        .collect()
}

const STOPS: [Transition; 3] = [Transition::ExactStop; 3];

/// The expected Turbo PMAC motion program of paper B's three moves (exact stops, per-axis speeds 40, 70,
/// 40, a = d = 5, j = 2, 1000 counts per unit). Times in ms: S-curve time TS = a/j, acceleration time
/// TA = TS + v/a; F is the vector speed at which the dominant axis moves at its speed.
const REFERENCE_PROGRAM: &str = "\
&1 #1->1000X #2->1000Y #3->1000Z
OPEN PROG 1 CLEAR
LINEAR ABS FRAX(X,Y,Z)
TS2500 TA10500 F53.852 X1600 Y1200 Z800 DWELL0
TA16500 F82.932 X2200 Y3800 Z5000 DWELL0
TA10500 F40.749 X4500 Y4200 Z4800 DWELL0
CLOSE
&1 B1 R
";

/// The program without the set-up lines before the axis definitions (`CLOSE`, `DELETE GATHER`, `I5190=1000`)
/// and with every feedrate masked (`F` is rounded down now, pmac.md rounds to nearest), checked separately.
fn masked_motion(text: &str) -> (String, Vec<f64>) {
    let body = &text[text.find("&1 #").expect("axis definitions")..];
    let mut feeds = Vec::new();
    let masked: Vec<String> = body
        .lines()
        .map(|l| {
            l.split(' ')
                .map(
                    |w| match w.strip_prefix('F').and_then(|v| v.parse::<f64>().ok()) {
                        Some(f) => {
                            feeds.push(f);
                            "F*".to_string()
                        }
                        None => w.to_string(),
                    },
                )
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect();
    (masked.join("\n"), feeds)
}

fn assert_times(got: &[f64], want: &[f64]) {
    assert_eq!(got.len(), want.len(), "{got:?}");
    for (g, w) in got.iter().zip(want) {
        assert!(
            (g - w).abs() <= 1e-3,
            "move time {g} s, expected {w} s (all: {got:?})"
        );
    }
}

#[test]
fn pmac_md_example_is_reproduced() {
    // The reference program's F values (53.852, 82.932, 40.749) and TA values (10500, 16500, 10500)
    // are the projections of per-axis speeds 40, 70, 40 (not the 40, 55, 70 of paper B's table; see the next test).
    let text = program::write(&xyz(), &paper_b([40.0, 70.0, 40.0], STOPS), Dialect::Turbo).unwrap();
    let (ours, our_feeds) = masked_motion(&text);
    let (reference, ref_feeds) = masked_motion(REFERENCE_PROGRAM);
    assert_eq!(ours, reference);
    for (f, r) in our_feeds.iter().zip(&ref_feeds) {
        assert!(f <= r && r - f <= 1e-3, "F{f} against the reference's F{r}");
    }
    assert!(
        text.starts_with("CLOSE\nDELETE GATHER\nI5190=1000\n&1 #"),
        "{text}"
    );
    assert_times(&program_move_times(&text).unwrap(), &[50.5, 76.5, 68.0]);
    // The reference text itself gives the same times.
    assert_times(
        &program_move_times(REFERENCE_PROGRAM).unwrap(),
        &[50.5, 76.5, 68.0],
    );
    insta::assert_snapshot!("paper_b_pmac_md_turbo", text);
}

#[test]
fn paper_b_table_speeds() {
    // Paper B's table: 40, 55, 70 mm/s. Dominant axes X (1600), Z (4200), X (2300):
    // 1600/40 + 40/5 + 5/2 = 50.5; 4200/55 + 55/5 + 2.5 = 89.864; 2300/70 + 70/5 + 2.5 = 49.357.
    let moves = paper_b([40.0, 55.0, 70.0], STOPS);
    let text = program::write(&xyz(), &moves, Dialect::Turbo).unwrap();
    assert_times(
        &program_move_times(&text).unwrap(),
        &[50.5, 4200.0 / 55.0 + 13.5, 2300.0 / 70.0 + 16.5],
    );
    insta::assert_snapshot!("paper_b_table_turbo", text);
    let power = program::write(&xyz(), &moves, Dialect::Power).unwrap();
    assert_times(
        &program_move_times(&power).unwrap(),
        &[50.5, 4200.0 / 55.0 + 13.5, 2300.0 / 70.0 + 16.5],
    );
    insta::assert_snapshot!("paper_b_table_power", power);
}

/// The planned jerk-limited motion of exact-stop moves, one after the other.
struct Planned {
    legs: Vec<(Vec<f64>, Vec<f64>, RestToRest, f64)>,
}

impl TrajectorySource for Planned {
    fn axis_count(&self) -> usize {
        self.legs[0].0.len()
    }
    fn duration(&self) -> f64 {
        self.legs.iter().map(|l| l.2.duration()).sum()
    }
    fn state(&self, t: f64) -> Vec<(f64, f64)> {
        let mut t0 = 0.0;
        for (i, (from, to, r, len)) in self.legs.iter().enumerate() {
            let last = i + 1 == self.legs.len();
            if t <= t0 + r.duration() || last {
                let (s, v) = r.eval(t - t0);
                return from
                    .iter()
                    .zip(to)
                    .map(|(a, b)| (a + (b - a) * s / len, (b - a) * v / len))
                    .collect();
            }
            t0 += r.duration();
        }
        unreachable!("legs is not empty")
    }
}

fn planned(moves: &[LinearMove]) -> Planned {
    let mut from = vec![0.0; 3];
    let mut legs = Vec::new();
    for m in moves {
        let delta: Vec<f64> = m.target.iter().zip(&from).map(|(a, b)| a - b).collect();
        let v = |x| vec![x; 3];
        let (len, lim) = project(
            &delta,
            &v(m.velocity),
            &v(m.acceleration),
            &v(m.deceleration),
            &v(m.jerk),
        )
        .unwrap();
        legs.push((
            from.clone(),
            m.target.clone(),
            RestToRest::plan(len, &lim),
            len,
        ));
        from = m.target.clone();
    }
    Planned { legs }
}

#[test]
fn program_motion_follows_the_jerk_limited_plan() {
    for (speeds, dialect) in [
        ([40.0, 70.0, 40.0], Dialect::Turbo),
        ([40.0, 55.0, 70.0], Dialect::Turbo),
        ([40.0, 55.0, 70.0], Dialect::Power),
    ] {
        let moves = paper_b(speeds, STOPS);
        let text = program::write(&xyz(), &moves, dialect).unwrap();
        let pmac = reconstruct_program(&text, None, 0.01).unwrap();
        let plan = planned(&moves);
        // Move by move, the program's times equal the plan's to 1 ms.
        let times = program_move_times(&text).unwrap();
        assert_eq!(times.len(), plan.legs.len());
        for (t, leg) in times.iter().zip(&plan.legs) {
            assert!(
                (t - leg.2.duration()).abs() <= 1e-3,
                "{t} vs {}",
                leg.2.duration()
            );
        }
        // Within what 1 ms of travel at the highest axis speed covers (F is rounded to 3 decimals).
        let dev = max_deviation(&pmac, &plan, 0.05);
        eprintln!("speeds {speeds:?}: program vs plan, max deviation {dev:e}");
        assert!(dev < 70.0 * 1e-3, "deviation {dev} for {speeds:?}");
    }
}

#[test]
fn rest_to_rest_matches_ruckig_through_the_program() {
    // One axis, rest to rest: the written program's move time equals ruckig's time-optimal duration.
    let text = oracle();
    let cs = CoordSystem {
        number: 2,
        axes: vec![AxisDef {
            motor: 4,
            name: 'X',
            counts_per_unit: 100.0,
        }],
    };
    let mut checked = 0;
    let mut worst: f64 = 0.0;
    for line in text.lines() {
        let o: serde_json::Value = serde_json::from_str(line).unwrap();
        if o["kind"] != "rest" {
            continue;
        }
        let f = |k: &str| o[k].as_f64().unwrap();
        let m = LinearMove {
            target: vec![f("p1")],
            velocity: f("vmax"),
            acceleration: f("amax"),
            deceleration: f("dmax"),
            jerk: f("jmax"),
            mode: MoveMode::Abs,
            transition: Transition::ExactStop,
        };
        let opts = ProgramOptions {
            start: Some(vec![f("p0")]),
            ..Default::default()
        };
        let prog = program::write_with(&cs, &[m], &opts).unwrap();
        let times = pmac_backend::verify::parse_program(&prog, Some(&[f("p0")])).unwrap();
        let spans = times.move_spans();
        assert_eq!(spans.len(), 1);
        let got = spans[0].1 - spans[0].0;
        // Turbo TA/TS are whole ms, rounded up (each ramp grows by less than 2 ms; a move too short for its
        // TA is stretched to it); F is rounded down (at most 0.5 ms longer).
        assert!(
            got - f("duration") >= -1e-9 && got - f("duration") <= 4.5e-3,
            "{line}: program gives {got}"
        );
        worst = worst.max((got - f("duration")).abs());
        checked += 1;
    }
    eprintln!("{checked} rest problems, worst move-time difference {worst:e} s");
    assert!(checked >= 100, "only {checked} rest problems");
}

#[test]
fn line_projection_matches_ruckig() {
    // Three axes, per-axis limits projected onto the line: same duration as ruckig's optimum along the line.
    let text = oracle();
    let mut checked = 0;
    let mut worst: f64 = 0.0;
    for line in text.lines() {
        let o: serde_json::Value = serde_json::from_str(line).unwrap();
        if o["kind"] != "line3" {
            continue;
        }
        let arr = |k: &str| -> Vec<f64> {
            o[k].as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect()
        };
        let delta: Vec<f64> = arr("end")
            .iter()
            .zip(arr("start"))
            .map(|(e, s)| e - s)
            .collect();
        let (len, lim) = project(
            &delta,
            &arr("vmax"),
            &arr("amax"),
            &arr("amax"),
            &arr("jmax"),
        )
        .unwrap();
        let r = RestToRest::plan(len, &lim);
        let want = o["duration"].as_f64().unwrap();
        assert!(
            (r.duration() - want).abs() <= 1e-6 * want,
            "{line}: {}",
            r.duration()
        );
        worst = worst.max((r.duration() - want).abs() / want);
        checked += 1;
    }
    eprintln!("{checked} line3 problems, worst relative duration difference {worst:e}");
    assert!(checked >= 100);
}

#[test]
fn blended_moves_have_no_dwell_between_them() {
    let blend = |v| Transition::Blend {
        junction_velocity: v,
    };
    // Paper B's buffer modes: BlendingLow after block 1 (min(40,55)), BlendingHigh after block 2.
    let moves = paper_b(
        [40.0, 55.0, 70.0],
        [blend(40.0), blend(70.0), Transition::ExactStop],
    );
    let turbo = program::write(&xyz(), &moves, Dialect::Turbo).unwrap();
    assert_eq!(turbo.matches("DWELL0").count(), 1);
    insta::assert_snapshot!("paper_b_blended_turbo", turbo);
    let power = program::write(&xyz(), &moves, Dialect::Power).unwrap();
    assert_eq!(power.matches("dwell0").count(), 1);
    insta::assert_snapshot!("paper_b_blended_power", power);
    // The commanded motion passes through the end point and stops there; corners are blended, not stopped at.
    let tr = reconstruct_program(&turbo, None, 0.01).unwrap();
    let end = tr.state(tr.duration());
    for (k, want) in [4500.0, 4200.0, 4800.0].iter().enumerate() {
        assert!((end[k].0 - want).abs() < 1e-6 && end[k].1.abs() < 1e-9);
    }
    let times = program_move_times(&turbo).unwrap();
    let exact: f64 = program_move_times(
        &program::write(&xyz(), &paper_b([40.0, 55.0, 70.0], STOPS), Dialect::Turbo).unwrap(),
    )
    .unwrap()
    .iter()
    .sum();
    assert!(
        times.iter().sum::<f64>() < exact,
        "blending must be faster than stopping"
    );
}

#[test]
fn incremental_moves_and_mode_switches() {
    let mut moves = paper_b([40.0, 55.0, 70.0], STOPS);
    // Move 2 as an increment from move 1's end.
    moves[1].mode = MoveMode::Inc;
    moves[1].target = vec![600.0, 2600.0, 4200.0];
    let text = program::write(&xyz(), &moves, Dialect::Turbo).unwrap();
    let abs = program::write(&xyz(), &paper_b([40.0, 55.0, 70.0], STOPS), Dialect::Turbo).unwrap();
    assert_eq!(
        program_move_times(&text).unwrap(),
        program_move_times(&abs).unwrap()
    );
    insta::assert_snapshot!("paper_b_inc_turbo", text);
}

#[test]
fn asymmetric_deceleration_is_declared_before_the_dwell() {
    let mut moves = paper_b([40.0, 55.0, 70.0], STOPS);
    moves.truncate(1);
    moves[0].deceleration = 2.5;
    let text = program::write(&xyz(), &moves, Dialect::Turbo).unwrap();
    // Accel: TA = 40/5 + 5/2 = 10.5 s, TS 2.5 s; decel: 40/2.5 + 2.5/2 = 17.25 s, TS 1.25 s.
    assert!(
        text.contains("TS2500 TA10500 F53.851 X1600 Y1200 Z800 TS1250 TA17250 DWELL0"),
        "{text}"
    );
    let t = program_move_times(&text).unwrap();
    assert_times(&t, &[1600.0 / 40.0 + (10.5 + 17.25) / 2.0]);
}

#[test]
fn invalid_input_gives_diagnostics() {
    let mut moves = paper_b([40.0, 55.0, 70.0], STOPS);
    moves[2].target.pop();
    let e = program::write(&xyz(), &moves, Dialect::Turbo).unwrap_err();
    assert_eq!(e.code(), "E7002");
    assert!(e.diagnostic().message.contains("move 3"), "{e}");
    let mut moves = paper_b([40.0, 55.0, 70.0], STOPS);
    moves[0].velocity = -1.0;
    assert_eq!(
        program::write(&xyz(), &moves, Dialect::Turbo)
            .unwrap_err()
            .code(),
        "E7002"
    );
    let mut cs = xyz();
    cs.axes[2].motor = 1;
    assert_eq!(
        program::write(&cs, &moves, Dialect::Turbo)
            .unwrap_err()
            .code(),
        "E7001"
    );
    let opts = ProgramOptions {
        start: Some(vec![0.0]),
        ..Default::default()
    };
    assert_eq!(
        program::write_with(&xyz(), &paper_b([1.0; 3], STOPS), &opts)
            .unwrap_err()
            .code(),
        "E7001"
    );
}

#[test]
fn zero_length_moves_are_skipped() {
    let mut moves = paper_b([40.0, 55.0, 70.0], STOPS);
    moves.insert(1, moves[0].clone());
    let text = program::write(&xyz(), &moves, Dialect::Turbo).unwrap();
    assert_eq!(program_move_times(&text).unwrap().len(), 3);
}

#[test]
fn write_to_writes_the_same_text() {
    let moves = paper_b([40.0, 55.0, 70.0], STOPS);
    let mut out = Vec::new();
    program::write_to(&mut out, &xyz(), &moves, &ProgramOptions::default()).unwrap();
    assert_eq!(
        String::from_utf8(out).unwrap(),
        program::write(&xyz(), &moves, Dialect::Turbo).unwrap()
    );
    struct Broken;
    impl std::io::Write for Broken {
        fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
            Err(std::io::Error::other("disk full"))
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }
    let e = program::write_to(&mut Broken, &xyz(), &moves, &ProgramOptions::default()).unwrap_err();
    assert_eq!(e.code(), "E7005");
    assert!(e.diagnostic().message.contains("disk full"));
}

#[test]
fn blended_program_respects_axis_limits() {
    // Every axis stays within its speed (up to F's rounding) and acceleration limits through the blends.
    let blend = |v| Transition::Blend {
        junction_velocity: v,
    };
    let moves = paper_b(
        [40.0, 55.0, 70.0],
        [blend(40.0), blend(70.0), Transition::ExactStop],
    );
    for dialect in [Dialect::Turbo, Dialect::Power] {
        let text = program::write(&xyz(), &moves, dialect).unwrap();
        let tr = reconstruct_program(&text, None, 0.01).unwrap();
        let (mut vmax, mut amax): (f64, f64) = (0.0, 0.0);
        for axis in &tr.axes {
            for s in axis {
                vmax = vmax.max(s.v.abs());
                amax = amax.max(s.a.abs());
            }
        }
        assert!(vmax <= 70.0 * (1.0 + 1e-5), "{dialect:?}: speed {vmax}");
        assert!(
            amax <= 5.0 * (1.0 + 1e-5),
            "{dialect:?}: acceleration {amax}"
        );
        assert!(
            amax > 4.99,
            "{dialect:?}: some blend uses the full acceleration ({amax})"
        );
    }
}
