//! Issue #14's acceptance, tried as its tester would: four IL programs written for this test (not
//! copies of the other motion tests) run through `ladderc run --trace`. For each, every axis's set
//! velocity, acceleration and jerk (differences of the set-point trace, 1 ms cycles) stay within the
//! axes file's limits in every cycle (1e-9 relative), and the end positions are the ones PLCopen
//! prescribes:
//! - software-limit recovery: a velocity move in the negative direction stops exactly at the limit
//!   (ErrorStop, ErrorID 101); after MC_Reset a relative move and a velocity move further out are refused
//!   (ErrorID 27) and an absolute move back into the range ends Done at its target;
//! - an aborting MC_MoveAbsolute whose braking would overshoot the positive limit is refused (ErrorID 29)
//!   with the running move untouched; a later aborting move that fits takes over and ends at its target;
//! - a buffered MC_MoveRelative after an MC_MoveAbsolute counts from where the absolute move ends
//!   (PLCopen Part 1: relative to the position when the command becomes active), then a BlendingLow
//!   relative move continues from there;
//! - a 3-axis group with unequal axis limits, its blocks asking for more velocity, acceleration and jerk
//!   than the axes have (the library caps them): corners in TMNone, TMCornerDistance and TMMaxCornerDeviation,
//!   BufferModes Aborting, Buffered and BlendingLow/Previous/Next/High; TMStartVelocity and
//!   TMConstantVelocity refused with ErrorID 59; the TMNone corners passed at rest, the deviation blend
//!   passing its corner at the deviation asked for.

mod common;
use common::ladderc;

/// (axis name, velocity, max(acceleration, deceleration), jerk) of an axes file.
type Lim = (&'static str, f64, f64, f64);

struct Run {
    header: Vec<String>,
    rows: Vec<Vec<f64>>,
    stderr: String,
}

impl Run {
    fn col(&self, name: &str) -> Vec<f64> {
        let k = self
            .header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name}"));
        self.rows.iter().map(|r| r[k]).collect()
    }
}

fn run(name: &str, program: &str, axes: &str, cycles: u32, watch: &[&str], lims: &[Lim]) -> Run {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join(format!("{name}.il"));
    std::fs::write(&src, program).unwrap();
    std::fs::write(dir.path().join(format!("{name}.axes.json")), axes).unwrap();
    let trace = dir.path().join("t.csv");
    let mut cols: Vec<String> = watch.iter().map(|w| w.to_string()).collect();
    for (a, ..) in lims {
        for s in ["position", "velocity", "acceleration"] {
            cols.push(format!("axis.{a}.{s}"));
        }
    }
    let out = ladderc()
        .arg("run")
        .arg(&src)
        .args(["--cycles", &cycles.to_string(), "--watch", &cols.join(",")])
        .arg("--trace")
        .arg(&trace)
        .output()
        .unwrap();
    common::assert_ok(&out);
    let text = std::fs::read_to_string(&trace).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_string)
        .collect();
    let rows: Vec<Vec<f64>> = lines
        .map(|l| {
            l.split(',')
                .map(|x| match x {
                    "TRUE" => 1.0,
                    "FALSE" => 0.0,
                    _ => x.parse::<f64>().unwrap_or(f64::NAN),
                })
                .collect()
        })
        .collect();
    let r = Run {
        header,
        rows,
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    };
    check_limits(&r, lims, 0.001);
    r
}

/// Every cycle of every axis: |v| <= vmax, |a| <= amax, |dv| <= amax dt, |da| <= jmax dt.
fn check_limits(r: &Run, lims: &[Lim], dt: f64) {
    let rel = 1.0 + 1e-9;
    for &(a, vmax, amax, jmax) in lims {
        let v = r.col(&format!("axis.{a}.velocity"));
        let acc = r.col(&format!("axis.{a}.acceleration"));
        let (mut pv, mut pa, mut pj) = (0.0f64, 0.0f64, 0.0f64);
        for i in 0..v.len() {
            assert!(
                v[i].abs() <= vmax * rel,
                "{a} row {i}: |v| {} > {vmax}",
                v[i]
            );
            assert!(
                acc[i].abs() <= amax * rel,
                "{a} row {i}: |a| {} > {amax}",
                acc[i]
            );
            if i > 0 {
                let dv = (v[i] - v[i - 1]).abs();
                let da = (acc[i] - acc[i - 1]).abs();
                assert!(dv <= amax * dt * rel + 1e-12, "{a} row {i}: |dv| {dv}");
                assert!(da <= jmax * dt * rel + 1e-12, "{a} row {i}: |da| {da}");
                pv = pv.max(v[i].abs());
                pa = pa.max(acc[i].abs());
                pj = pj.max(da / dt);
            }
        }
        eprintln!(
            "{a}: peak |v| {pv:.6} (limit {vmax}), |a| {pa:.6} ({amax}), |j| {pj:.6} ({jmax})"
        );
    }
}

/// First row where `col` is 1.
fn first_true(r: &Run, col: &str) -> usize {
    r.col(col)
        .iter()
        .position(|x| *x == 1.0)
        .unwrap_or_else(|| panic!("{col} never TRUE\n{}", r.stderr))
}

const RECOVER: &str = "PROGRAM recover
VAR
    pw : MC_Power;
    drive : MC_MoveVelocity;
    rst : MC_Reset;
    further : MC_MoveRelative;
    outward : MC_MoveVelocity;
    back : MC_MoveAbsolute;
    phase : INT := 0;
END_VAR
    CAL pw(Axis := X1, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE)
    (* phase 0: 25 mm/s towards the negative limit at -20 *)
    LD pw.Status
    AND( phase
    EQ 0
    )
    ST drive.Execute
    CAL drive(Axis := X1, Velocity := 25.0, Acceleration := 150.0, Deceleration := 150.0, Jerk := 1500.0,
              Direction := mcNegativeDirection)
    LD drive.Error
    AND( phase
    EQ 0
    )
    JMPCN p1
    LD 1
    ST phase
p1:
    LD phase
    EQ 1
    ST rst.Execute
    CAL rst(Axis := X1)
    LD rst.Done
    AND( phase
    EQ 1
    )
    JMPCN p2
    LD 2
    ST phase
p2:
    (* phase 2: further out is refused (relative and velocity), back into the range works *)
    LD phase
    EQ 2
    ST further.Execute
    CAL further(Axis := X1, Distance := -5.0, Velocity := 20.0, Acceleration := 100.0, Deceleration := 100.0,
                Jerk := 1000.0)
    LD phase
    EQ 2
    ST outward.Execute
    CAL outward(Axis := X1, Velocity := 5.0, Acceleration := 100.0, Deceleration := 100.0, Jerk := 1000.0,
                Direction := mcNegativeDirection)
    LD phase
    EQ 2
    ST back.Execute
    CAL back(Axis := X1, Position := 12.5, Velocity := 30.0, Acceleration := 100.0, Deceleration := 100.0,
             Jerk := 1000.0)
END_PROGRAM
";

const RECOVER_AXES: &str = r#"{ "cycle_ms": 1, "queue_depth": 4,
  "axes": [ { "name": "X1", "unit": "mm", "velocity": 50, "acceleration": 200, "deceleration": 120,
              "jerk": 2000, "software_limits": { "negative": -20, "positive": 30 } } ] }
"#;

#[test]
fn software_limit_error_reset_refused_further_out_and_back_into_range() {
    let r = run(
        "recover",
        RECOVER,
        RECOVER_AXES,
        4000,
        &[
            "recover.phase",
            "recover.drive.Error",
            "recover.drive.ErrorID",
            "recover.rst.Done",
            "recover.further.Error",
            "recover.further.ErrorID",
            "recover.outward.Error",
            "recover.outward.ErrorID",
            "recover.back.Done",
            "recover.back.Busy",
        ],
        &[("X1", 50.0, 200.0, 2000.0)],
    );
    let p = r.col("axis.X1.position");
    let v = r.col("axis.X1.velocity");
    let low = p.iter().copied().fold(f64::INFINITY, f64::min);
    assert!(low >= -20.0 - 1e-9, "lowest position {low}");
    // stopped exactly at the limit, at rest, ErrorID 101 (SoftwareLimitNegative)
    let e = first_true(&r, "recover.drive.Error");
    assert_eq!(r.col("recover.drive.ErrorID")[e], 101.0);
    assert!(
        (p[e - 1] + 20.0).abs() < 1e-9 && v[e - 1].abs() < 1e-12,
        "{}",
        p[e - 1]
    );
    // reset, then both moves further out refused before any motion
    first_true(&r, "recover.rst.Done");
    let f = first_true(&r, "recover.further.Error");
    assert_eq!(r.col("recover.further.ErrorID")[f], 27.0);
    let o = first_true(&r, "recover.outward.Error");
    assert_eq!(r.col("recover.outward.ErrorID")[o], 27.0);
    assert!((p[f - 1] + 20.0).abs() < 1e-9);
    // back into the range: Done at 12.5 (PLCopen: Done when the set position reached Position)
    let d = first_true(&r, "recover.back.Done");
    assert!((p[d - 1] - 12.5).abs() < 1e-9, "{}", p[d - 1]);
    assert!((p.last().unwrap() - 12.5).abs() < 1e-9);
}

const OVERSHOOT: &str = "PROGRAM over
VAR
    pw : MC_Power;
    pos : MC_ReadActualPosition;
    go : MC_MoveAbsolute;
    late : MC_MoveAbsolute;
    fits : MC_MoveAbsolute;
END_VAR
    CAL pw(Axis := X1, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE)
    CAL pos(Axis := X1, Enable := TRUE)
    CAL go(Axis := X1, Execute := pw.Status, Position := 90.0, Velocity := 100.0, Acceleration := 100.0,
           Deceleration := 100.0, Jerk := 1000.0)
    (* at 30 mm, still speeding up: a target at 95 with a 10 mm/s^2 deceleration would brake far past 100 *)
    LD pos.Position
    GT 30.0
    AND go.Busy
    ST late.Execute
    CAL late(Axis := X1, Position := 95.0, Velocity := 100.0, Acceleration := 100.0, Deceleration := 10.0,
             Jerk := 1000.0, BufferMode := mcAborting)
    (* once refused: an aborting move to 60 that fits (it overshoots 60 and comes back, within the range) *)
    CAL fits(Axis := X1, Execute := late.Error, Position := 60.0, Velocity := 100.0, Acceleration := 100.0,
             Deceleration := 100.0, Jerk := 1000.0, BufferMode := mcAborting)
END_PROGRAM
";

const OVERSHOOT_AXES: &str = r#"{ "cycle_ms": 1, "queue_depth": 4,
  "axes": [ { "name": "X1", "unit": "mm", "velocity": 100, "acceleration": 100, "deceleration": 100,
              "jerk": 1000, "software_limits": { "negative": -50, "positive": 100 } } ] }
"#;

#[test]
fn an_aborting_move_that_would_overshoot_the_limit_is_refused_and_the_running_move_goes_on() {
    let r = run(
        "over",
        OVERSHOOT,
        OVERSHOOT_AXES,
        5000,
        &[
            "over.go.Busy",
            "over.go.CommandAborted",
            "over.late.Error",
            "over.late.ErrorID",
            "over.late.Busy",
            "over.fits.Done",
        ],
        &[("X1", 100.0, 100.0, 1000.0)],
    );
    let p = r.col("axis.X1.position");
    let v = r.col("axis.X1.velocity");
    let high = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    assert!(high <= 100.0 + 1e-9, "highest position {high}");
    let e = first_true(&r, "over.late.Error");
    assert_eq!(r.col("over.late.ErrorID")[e], 29.0);
    assert!(
        r.col("over.late.Busy").iter().all(|b| *b == 0.0),
        "never Busy"
    );
    // the refusal changed nothing: `go` still Busy, not aborted, the velocity still rising
    assert_eq!(r.col("over.go.Busy")[e], 1.0);
    assert_eq!(r.col("over.go.CommandAborted")[e], 0.0);
    assert!(v[e] > v[e - 1] && v[e - 1] > v[e - 2], "still accelerating");
    // `fits` takes over and ends at 60; `go` was aborted (it never reached 90)
    let d = first_true(&r, "over.fits.Done");
    assert!((p[d - 1] - 60.0).abs() < 1e-9, "{}", p[d - 1]);
    assert!(r.col("over.go.CommandAborted").contains(&1.0));
    assert!(
        high > 60.0 && high < 90.0,
        "overshot 60 within the range: {high}"
    );
}

const BUFREL: &str = "PROGRAM bufrel
VAR
    pw : MC_Power;
    abs1 : MC_MoveAbsolute;
    rel1 : MC_MoveRelative;
    rel2 : MC_MoveRelative;
END_VAR
    CAL pw(Axis := X1, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE)
    (* all three given in the same scan: rel1 waits for abs1, rel2 blends with rel1 *)
    CAL abs1(Axis := X1, Execute := pw.Status, Position := 120.0, Velocity := 60.0, Acceleration := 200.0,
             Deceleration := 150.0, Jerk := 2000.0)
    CAL rel1(Axis := X1, Execute := pw.Status, Distance := 35.0, Velocity := 40.0, Acceleration := 200.0,
             Deceleration := 150.0, Jerk := 2000.0, BufferMode := mcBuffered)
    CAL rel2(Axis := X1, Execute := pw.Status, Distance := 20.0, Velocity := 25.0, Acceleration := 200.0,
             Deceleration := 150.0, Jerk := 2000.0, BufferMode := mcBlendingLow)
END_PROGRAM
";

const BUFREL_AXES: &str = r#"{ "cycle_ms": 1, "queue_depth": 4,
  "axes": [ { "name": "X1", "unit": "mm", "velocity": 80, "acceleration": 200, "deceleration": 150,
              "jerk": 2000 } ] }
"#;

#[test]
fn a_buffered_relative_move_counts_from_where_the_absolute_move_ends() {
    let r = run(
        "bufrel",
        BUFREL,
        BUFREL_AXES,
        6000,
        &[
            "bufrel.abs1.Done",
            "bufrel.rel1.Busy",
            "bufrel.rel1.Active",
            "bufrel.rel1.Done",
            "bufrel.rel2.Done",
        ],
        &[("X1", 80.0, 200.0, 2000.0)],
    );
    let p = r.col("axis.X1.position");
    let v = r.col("axis.X1.velocity");
    // rel1 is Busy (buffered) long before it becomes Active at the end of abs1
    let busy = first_true(&r, "bufrel.rel1.Busy");
    let active = first_true(&r, "bufrel.rel1.Active");
    assert!(active > busy + 100, "busy {busy}, active {active}");
    // abs1 ends at rest at 120 and rel1 starts within that cycle (the row shows a few nm of it)
    let a = first_true(&r, "bufrel.abs1.Done");
    assert!((p[a - 1] - 120.0).abs() < 1e-6, "{}", p[a - 1]);
    // rel1 blends into rel2 at min(40, 25) mm/s: rel1 hands over at 155 at 25 mm/s (the row of its
    // Done is within the cycle's travel of it)
    let d1 = first_true(&r, "bufrel.rel1.Done");
    assert!(
        (p[d1 - 1] - 155.0).abs() <= 25.0 * 0.001,
        "rel1 ends at {}",
        p[d1 - 1]
    );
    assert!(
        (v[d1 - 1] - 25.0).abs() < 1e-9,
        "junction speed {}",
        v[d1 - 1]
    );
    // rel2 ends at rest at 120 + 35 + 20 (from the start position 0 it would be 55)
    let d2 = first_true(&r, "bufrel.rel2.Done");
    assert!(
        (p[d2 - 1] - 175.0).abs() < 1e-9,
        "rel2 ends at {}",
        p[d2 - 1]
    );
    assert!((p.last().unwrap() - 175.0).abs() < 1e-9 && v.last() == Some(&0.0));
}

const CORNERS: &str = "PROGRAM corners
VAR
    pwx : MC_Power;
    pwy : MC_Power;
    pwz : MC_Power;
    en : MC_GroupEnable;
    pos : MC_ReadActualPosition;
    m1 : MC_MoveLinearAbsolute;
    m2 : MC_MoveLinearAbsolute;
    m3 : MC_MoveLinearAbsolute;
    m4 : MC_MoveLinearAbsolute;
    m5 : MC_MoveLinearAbsolute;
    m6 : MC_MoveLinearAbsolute;
    m7 : MC_MoveLinearAbsolute;
    m8 : MC_MoveLinearAbsolute;
    m9 : MC_MoveLinearAbsolute;
    ab : MC_MoveLinearAbsolute;
    go : BOOL;
    q1 : ARRAY [0..5] OF LREAL := [100.0, 0.0, 0.0];
    q2 : ARRAY [0..5] OF LREAL := [100.0, 100.0, 0.0];
    q3 : ARRAY [0..5] OF LREAL := [0.0, 100.0, 50.0];
    q4 : ARRAY [0..5] OF LREAL := [0.0, 0.0, 50.0];
    q5 : ARRAY [0..5] OF LREAL := [50.0, 0.0, 0.0];
    q6 : ARRAY [0..5] OF LREAL := [50.0, 50.0, 50.0];
    q7 : ARRAY [0..5] OF LREAL := [0.0, 0.0, 0.0];
    q9 : ARRAY [0..5] OF LREAL := [20.0, 20.0, 20.0];
    qa : ARRAY [0..5] OF LREAL := [10.0, 30.0, 10.0];
END_VAR
    CAL pwx(Axis := X1, Enable := TRUE)
    CAL pwy(Axis := Y1, Enable := TRUE)
    CAL pwz(Axis := Z1, Enable := TRUE)
    LD pwx.Status
    AND pwy.Status
    AND pwz.Status
    ST go
    CAL en(AxesGroup := G1, Execute := go)
    CAL pos(Axis := X1, Enable := TRUE)
    (* all queued in one scan (queue depth 16) *)
    CAL m1(AxesGroup := G1, Execute := en.Done, Position := q1, Velocity := 150.0, Acceleration := 400.0,
           Deceleration := 400.0, Jerk := 4000.0, BufferMode := mcAborting, TransitionMode := TMNone)
    CAL m2(AxesGroup := G1, Execute := en.Done, Position := q2, Velocity := 40.0, Acceleration := 400.0,
           Deceleration := 400.0, Jerk := 4000.0, BufferMode := mcBuffered, TransitionMode := TMNone)
    CAL m3(AxesGroup := G1, Execute := en.Done, Position := q3, Velocity := 30.0, Acceleration := 400.0,
           Deceleration := 400.0, Jerk := 4000.0, BufferMode := mcBlendingLow,
           TransitionMode := TMCornerDistance, TransitionParameter := 10.0)
    CAL m4(AxesGroup := G1, Execute := en.Done, Position := q4, Velocity := 90.0, Acceleration := 400.0,
           Deceleration := 400.0, Jerk := 4000.0, BufferMode := mcBlendingPrevious,
           TransitionMode := TMMaxCornerDeviation, TransitionParameter := 2.0)
    CAL m5(AxesGroup := G1, Execute := en.Done, Position := q5, Velocity := 40.0, Acceleration := 400.0,
           Deceleration := 400.0, Jerk := 4000.0, BufferMode := mcBlendingNext, TransitionMode := TMNone)
    CAL m6(AxesGroup := G1, Execute := en.Done, Position := q6, Velocity := 35.0, Acceleration := 400.0,
           Deceleration := 400.0, Jerk := 4000.0, BufferMode := mcBlendingHigh,
           TransitionMode := TMCornerDistance, TransitionParameter := 5.0)
    CAL m7(AxesGroup := G1, Execute := en.Done, Position := q7, Velocity := 35.0, Acceleration := 400.0,
           Deceleration := 400.0, Jerk := 4000.0, BufferMode := mcBlendingHigh, TransitionMode := TMStartVelocity,
           TransitionParameter := 5.0)
    CAL m8(AxesGroup := G1, Execute := en.Done, Position := q7, Velocity := 35.0, Acceleration := 400.0,
           Deceleration := 400.0, Jerk := 4000.0, BufferMode := mcBuffered, TransitionMode := TMConstantVelocity,
           TransitionParameter := 5.0)
    CAL m9(AxesGroup := G1, Execute := en.Done, Position := q9, Velocity := 30.0, Acceleration := 400.0,
           Deceleration := 400.0, Jerk := 4000.0, BufferMode := mcBuffered, TransitionMode := TMNone)
    (* while m9 runs from (50, 50, 50) towards (20, 20, 20): an aborting move once X passed 35 *)
    LD m9.Active
    AND( pos.Position
    LT 35.0
    )
    ST ab.Execute
    CAL ab(AxesGroup := G1, Execute := ab.Execute, Position := qa, Velocity := 30.0, Acceleration := 400.0,
           Deceleration := 400.0, Jerk := 4000.0, BufferMode := mcAborting, TransitionMode := TMNone)
END_PROGRAM
";

const CORNERS_AXES: &str = r#"{ "cycle_ms": 1, "queue_depth": 16,
  "axes": [ { "name": "X1", "unit": "mm", "velocity": 100, "acceleration": 200, "deceleration": 200, "jerk": 2000 },
            { "name": "Y1", "unit": "mm", "velocity": 80, "acceleration": 150, "deceleration": 120, "jerk": 1500 },
            { "name": "Z1", "unit": "mm", "velocity": 60, "acceleration": 100, "deceleration": 100, "jerk": 1000 } ],
  "groups": [ { "name": "G1", "axes": [ { "axis": "X1", "identity": "X" }, { "axis": "Y1", "identity": "Y" },
                                        { "axis": "Z1", "identity": "Z" } ] } ] }
"#;

#[test]
fn a_three_axis_path_with_every_transition_and_buffer_mode_keeps_the_limits() {
    let r = run(
        "corners",
        CORNERS,
        CORNERS_AXES,
        24000,
        &[
            "corners.m1.Done",
            "corners.m2.Active",
            "corners.m3.Active",
            "corners.m4.Active",
            "corners.m5.Active",
            "corners.m6.Active",
            "corners.m6.Done",
            "corners.m7.Error",
            "corners.m7.ErrorID",
            "corners.m8.Error",
            "corners.m8.ErrorID",
            "corners.m9.Active",
            "corners.m9.CommandAborted",
            "corners.ab.Done",
            "corners.ab.Active",
        ],
        &[
            ("X1", 100.0, 200.0, 2000.0),
            ("Y1", 80.0, 150.0, 1500.0),
            ("Z1", 60.0, 100.0, 1000.0),
        ],
    );
    let x = r.col("axis.X1.position");
    let y = r.col("axis.Y1.position");
    let z = r.col("axis.Z1.position");
    let vx = r.col("axis.X1.velocity");
    let vy = r.col("axis.Y1.velocity");
    let vz = r.col("axis.Z1.velocity");
    let n = x.len();
    let dist = |i: usize, c: [f64; 3]| {
        ((x[i] - c[0]).powi(2) + (y[i] - c[1]).powi(2) + (z[i] - c[2]).powi(2)).sqrt()
    };
    let speed = |i: usize| (vx[i].powi(2) + vy[i].powi(2) + vz[i].powi(2)).sqrt();
    // nearest approach to `c` while block `a` or `b` is Active (the blend between them)
    let nearest = |c: [f64; 3], a: &str, b: &str| {
        let (ca, cb) = (r.col(a), r.col(b));
        (0..n)
            .filter(|&i| ca[i] == 1.0 || cb[i] == 1.0)
            .map(|i| dist(i, c))
            .fold(f64::INFINITY, f64::min)
    };
    // TMStartVelocity and TMConstantVelocity refused with ErrorID 59
    let e7 = first_true(&r, "corners.m7.Error");
    assert_eq!(r.col("corners.m7.ErrorID")[e7], 59.0);
    let e8 = first_true(&r, "corners.m8.Error");
    assert_eq!(r.col("corners.m8.ErrorID")[e8], 59.0);
    // TMNone corners (m1 -> m2 Buffered; m4 -> m5 BlendingNext) are passed at rest, exactly
    for c in [[100.0, 0.0, 0.0], [0.0, 0.0, 50.0]] {
        assert!(
            (0..n).any(|i| dist(i, c) < 1e-9 && speed(i) < 1e-9),
            "the path does not stop at the TMNone corner {c:?}"
        );
    }
    // TMCornerDistance 10 (m2 -> m3) and 5 (m5 -> m6): the blend cuts the corner, not farther
    // than the corner distance
    for (c, d, a, b) in [
        (
            [100.0, 100.0, 0.0],
            10.0,
            "corners.m2.Active",
            "corners.m3.Active",
        ),
        (
            [50.0, 0.0, 0.0],
            5.0,
            "corners.m5.Active",
            "corners.m6.Active",
        ),
    ] {
        let m = nearest(c, a, b);
        assert!(m > 0.05 && m < d, "corner {c:?}: nearest {m}");
    }
    // TMMaxCornerDeviation 2 (m3 -> m4): the path passes the corner at 2 mm (to the sampling)
    let m = nearest([0.0, 100.0, 50.0], "corners.m3.Active", "corners.m4.Active");
    assert!((m - 2.0).abs() < 0.01, "deviation {m}");
    // m9 is Buffered (m7 and m8 were refused), so m6 ends at rest at (50, 50, 50); m9 starts within
    // that cycle
    let d6 = first_true(&r, "corners.m6.Done");
    assert!((d6 - 3..d6).any(|i| dist(i, [50.0; 3]) < 1e-9 && speed(i) == 0.0));
    // the aborting move takes over from m9 (CommandAborted) and ends at (10, 30, 10), at rest
    first_true(&r, "corners.m9.CommandAborted");
    let d = first_true(&r, "corners.ab.Done");
    assert!(
        dist(d - 1, [10.0, 30.0, 10.0]) < 1e-9,
        "ab Done {}",
        dist(d - 1, [10.0, 30.0, 10.0])
    );
    assert!(dist(n - 1, [10.0, 30.0, 10.0]) < 1e-9 && speed(n - 1) == 0.0);
}
