//! The rules a real Turbo / Power PMAC imposes on the text, checked on whole outputs:
//! - no on-line command while a rotary buffer is open (Turbo Software Reference, `OPEN ROTARY` and
//!   `B{constant}`: `B0` sent to an open buffer is a B-axis move), `DELETE GATHER` before `DEFINE ROT`
//!   (User Manual, "Rotary Motion Program Buffers");
//! - the program starts once the look-ahead is in the buffer, not after the whole stream;
//! - Turbo `TA`/`TS` in whole milliseconds (the controller rounds them when it executes them), rounded so that
//!   no axis limit is exceeded, and the resulting move-time error is bounded;
//! - the feedrate time unit is stated (`I5190=1000`, `Coord[1].FeedTime=1000`).

mod common;

use common::{cs, paper_b, sampled};
use pmac_backend::model::{AxisDef, CoordSystem, Dialect, LinearMove, MoveMode, Transition};
use pmac_backend::program::{self, ProgramOptions};
use pmac_backend::pvt::{self, PvtOptions, StreamOptions};
use pmac_backend::scurve::{project, RestToRest};
use pmac_backend::transport::FileTransport;
use pmac_backend::verify;

/// Every line sent while a rotary buffer is open must be a buffer line: a move, a mode or a time. The
/// commands that would be misread there (`&n`, `B0`, `R`, `A`, I-variables, `DEFINE`, `DELETE`) never appear.
fn assert_no_online_command_in_open_buffer(text: &str) {
    let mut open = false;
    for (i, line) in text.lines().enumerate() {
        let u = line.trim().to_ascii_uppercase();
        if u == "OPEN ROT" || u == "OPEN ROTARY" {
            assert!(!open, "line {}: buffer opened twice", i + 1);
            open = true;
        } else if u == "CLOSE" {
            open = false;
        } else if open {
            let first = u.split_whitespace().next().unwrap_or("");
            let ok = first == "ABS"
                || first == "INC"
                || first.starts_with("PVT")
                || (first.len() > 1
                    && "XYZABCUVW".contains(&first[..1])
                    && first[1..].starts_with(|c: char| c.is_ascii_digit() || c == '-')
                    && first.contains(':'));
            assert!(ok, "line {} `{line}` is not a buffer line", i + 1);
            assert!(
                !u.contains('&') && !u.contains('='),
                "line {}: `{line}`",
                i + 1
            );
        }
    }
    assert!(!open, "the buffer is left open");
}

fn xyz() -> CoordSystem {
    cs(&['X', 'Y', 'Z'])
}

#[test]
fn paper_b_rotary_file_starts_after_the_look_ahead_and_keeps_the_buffer_rules() {
    // Paper B's three moves (exact stops) at 1 ms: about 19,000 PVT lines of 6 words in DEFINE ROT 2048.
    let traj = sampled(&paper_b(), 0.001);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("paper_b.pvt");
    let report = pvt::write_file(&xyz(), &traj, &PvtOptions::default(), &path).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    assert_no_online_command_in_open_buffer(&text);
    let lines: Vec<&str> = text.lines().collect();
    let gather = lines.iter().position(|l| *l == "DELETE GATHER").unwrap();
    let define = lines
        .iter()
        .position(|l| *l == "&1 DEFINE ROT 2048")
        .unwrap();
    assert!(gather < define, "DELETE GATHER comes before DEFINE ROT");
    assert!(lines.contains(&"I5190=1000"), "velocities are per second");
    // 2048 words / 6 words per line (X p:v Y p:v Z p:v) = 341 lines before the program starts.
    assert_eq!(report.started_after, Some(341));
    let run = lines.iter().position(|l| *l == "&1 R").unwrap();
    let open = lines.iter().position(|l| *l == "OPEN ROT").unwrap();
    assert_eq!(
        run - 1 - (open + 1),
        341,
        "buffer lines before the run command"
    );
    assert!(report.lines_sent > 18_900, "{report:?}");
    assert_eq!(
        &lines[run - 1..=run + 1],
        ["CLOSE", "&1 R", "OPEN ROT"],
        "the run command is given with the buffer closed"
    );
    assert_eq!(lines.last(), Some(&"CLOSE"));
}

#[test]
fn a_short_stream_runs_after_closing() {
    let traj = sampled(&paper_b()[..1], 0.001);
    let segs = pvt::segments(&traj, 0.5).unwrap()[..5].to_vec();
    for dialect in [Dialect::Turbo, Dialect::Power] {
        let mut t = FileTransport::new(Vec::new());
        let opts = PvtOptions {
            dialect,
            segment_ms: 500.0,
            ..PvtOptions::default()
        };
        let report = pvt::stream(&xyz(), &segs, &opts, &StreamOptions::default(), &mut t).unwrap();
        let text = String::from_utf8(t.into_inner()).unwrap();
        assert_no_online_command_in_open_buffer(&text);
        assert_eq!(report.started_after, Some(report.lines_sent));
        let tail: Vec<&str> = text.lines().rev().take(2).collect();
        let want = match dialect {
            Dialect::Turbo => ["&1 R", "CLOSE"],
            Dialect::Power => ["&1 r", "close"],
        };
        assert_eq!(tail, want, "{text}");
    }
}

#[test]
fn an_explicit_look_ahead_is_kept() {
    let traj = sampled(&paper_b()[..1], 0.001);
    let segs = pvt::segments(&traj, 0.01).unwrap();
    let mut t = FileTransport::new(Vec::new());
    let so = StreamOptions {
        lookahead_lines: Some(50),
        ..StreamOptions::default()
    };
    let report = pvt::stream(&xyz(), &segs, &PvtOptions::default(), &so, &mut t).unwrap();
    assert_eq!(report.started_after, Some(50));
    assert_no_online_command_in_open_buffer(&String::from_utf8(t.into_inner()).unwrap());
}

/// A small deterministic generator (no test dependency needed).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Log-uniform in [lo, hi].
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + self.next() * (hi.ln() - lo.ln())).exp()
    }
}

#[test]
fn turbo_times_are_whole_ms_and_keep_every_limit() {
    let one = CoordSystem {
        number: 1,
        axes: vec![AxisDef {
            motor: 1,
            name: 'X',
            counts_per_unit: 1000.0,
        }],
    };
    let mut rng = Lcg(7);
    let mut worst_time: f64 = 0.0;
    for _ in 0..150 {
        let (v, a, j) = (
            rng.log(1.0, 500.0),
            rng.log(1.0, 5000.0),
            rng.log(1.0, 50_000.0),
        );
        let d = rng.log(0.01, 2000.0);
        let m = LinearMove {
            target: vec![d],
            velocity: v,
            acceleration: a,
            deceleration: a,
            jerk: j,
            mode: MoveMode::Abs,
            transition: Transition::ExactStop,
        };
        let text = program::write_with(&one, &[m], &ProgramOptions::default()).unwrap();
        for w in text.split_whitespace() {
            for key in ["TA", "TS"] {
                if let Some(val) = w
                    .strip_prefix(key)
                    .filter(|v| v.starts_with(|c: char| c.is_ascii_digit()))
                {
                    assert!(!val.contains('.'), "{w}: Turbo times are whole ms\n{text}");
                }
            }
        }
        // The exact optimum, and the controller's motion from the text.
        let (len, lim) = project(&[d], &[v], &[a], &[a], &[j]).unwrap();
        let exact = RestToRest::plan(len, &lim).duration();
        let tl = verify::parse_program(&text, None).unwrap();
        let got = tl.duration();
        assert!(
            got >= exact - 1e-9 && got - exact <= 4.5e-3,
            "v {v} a {a} j {j} d {d}: {got} s against {exact} s\n{text}"
        );
        worst_time = worst_time.max(got - exact);
        let motion = verify::reconstruct_program(&text, None, got / 5_000.0).unwrap();
        let samples = &motion.axes[0];
        for w in samples.windows(2) {
            assert!(
                w[0].v.abs() <= v * (1.0 + 1e-9),
                "velocity {} > {v}\n{text}",
                w[0].v
            );
            assert!(
                w[0].a.abs() <= a * (1.0 + 1e-6),
                "acceleration {} > {a}\n{text}",
                w[0].a
            );
            let jerk = (w[1].a - w[0].a).abs() / motion.cycle_s;
            // Sampled jerk of an exact S-ramp: within the limit up to the sampling of the ramp's corners.
            assert!(jerk <= j * (1.0 + 1e-6) + 1e-9, "jerk {jerk} > {j}\n{text}");
        }
    }
    eprintln!(
        "worst move-time increase from whole-ms TA/TS and a rounded-down F: {worst_time:e} s"
    );
}

#[test]
fn programs_state_their_feedrate_unit() {
    let turbo = program::write(&xyz(), &paper_b(), Dialect::Turbo).unwrap();
    let power = program::write(&xyz(), &paper_b(), Dialect::Power).unwrap();
    assert!(
        turbo.starts_with("CLOSE\nDELETE GATHER\nI5190=1000\n"),
        "{turbo}"
    );
    assert!(
        power.starts_with("close\nCoord[1].FeedTime=1000\n"),
        "{power}"
    );
    let cs7 = CoordSystem { number: 7, ..xyz() };
    assert!(program::write(&cs7, &paper_b(), Dialect::Turbo)
        .unwrap()
        .contains("\nI5790=1000\n"));
    assert_eq!(
        pvt::feed_time_setting(12, Dialect::Turbo, 60_000.0),
        "I6290=60000"
    );
}

#[test]
fn the_program_model_is_compared_with_the_plan() {
    use pmac_backend::compare::compare;
    // Exact stops: every move within the rounding of the plan, nothing to report.
    let stops = compare(&xyz(), &paper_b(), &ProgramOptions::default()).unwrap();
    assert_eq!(stops.move_times.len(), 3);
    assert!(stops.corners.is_empty());
    assert!(stops.worst_time_difference() <= 4.5e-3, "{stops:?}");
    assert!(stops.warnings().is_empty(), "{:?}", stops.warnings());
    // Paper B's blends: BlendingLow asks 40 at the first corner, the PMAC's LINEAR blend passes faster.
    let mut moves = paper_b();
    moves[0].transition = Transition::Blend {
        junction_velocity: 40.0,
    };
    moves[1].transition = Transition::Blend {
        junction_velocity: 70.0,
    };
    let blended = compare(&xyz(), &moves, &ProgramOptions::default()).unwrap();
    assert_eq!(blended.corners.len(), 2, "{blended:?}");
    assert_eq!(blended.corners[0].planned, 40.0);
    assert!(
        (blended.corners[0].program - 54.8).abs() < 0.1,
        "{blended:?}"
    );
    let warnings = blended.warnings();
    assert!(!warnings.is_empty());
    assert!(warnings.iter().all(|w| w.code.0 == "W7200"));
    assert!(
        warnings[0].message.contains("corner after move 1")
            && warnings[0].message.contains("40.000"),
        "{}",
        warnings[0].message
    );
}
