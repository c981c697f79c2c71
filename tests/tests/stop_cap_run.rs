//! MC_Stop's Deceleration and Jerk capped to the axis limits and reported, end to end through
//! `ladderc run`: an IL program runs an axis at 40 mm/s, stops it with an MC_Stop asking for
//! 5000 mm/s^2 and 100000 mm/s^3 (axis limits 100 and 1000), moves again, and stops it with an
//! MC_Stop within the limits. The trace's `axis.X1.stop_*` columns show the first stop's figures
//! in exactly one row, the run summary names the block, and every cycle keeps the limits.

mod common;
use common::column;
use common::ladderc;

const PROGRAM: &str = "PROGRAM cap
VAR
    pw : MC_Power;
    run : MC_MoveVelocity;
    hard : MC_Stop;
    again : MC_MoveVelocity;
    soft : MC_Stop;
    powered : BOOL;
    step : INT := 0;
END_VAR
    CAL pw(Axis := X1, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE, Status => powered)
    (* step 0: 40 mm/s; once reached, step 1: a stop asking for more than the axis has *)
    LD powered
    AND( step
    EQ 0
    )
    ST run.Execute
    CAL run(Axis := X1, Velocity := 40.0, Acceleration := 100.0, Deceleration := 100.0, Jerk := 1000.0)
    LD run.InVelocity
    AND( step
    EQ 0
    )
    JMPCN s1
    LD 1
    ST step
s1:
    LD step
    EQ 1
    ST hard.Execute
    CAL hard(Axis := X1, Deceleration := 5000.0, Jerk := 100000.0)
    (* step 2: move again; once at speed, step 3: a stop within the limits (not reported) *)
    LD step
    EQ 2
    ST again.Execute
    CAL again(Axis := X1, Velocity := 40.0, Acceleration := 100.0, Deceleration := 100.0, Jerk := 1000.0)
    LD again.InVelocity
    AND( step
    EQ 2
    )
    JMPCN s3
    LD 3
    ST step
s3:
    LD step
    EQ 3
    ST soft.Execute
    CAL soft(Axis := X1, Deceleration := 50.0, Jerk := 0.0)
    (* after Done, step 2 from the next scan on: hard's Execute falls (the axis leaves
       Stopping) before again rises *)
    LD hard.Done
    AND( step
    EQ 1
    )
    JMPCN s4
    LD 2
    ST step
s4:
END_PROGRAM
";

const AXES: &str = r#"{ "cycle_ms": 1, "queue_depth": 4,
  "axes": [ { "name": "X1", "unit": "mm", "velocity": 100, "acceleration": 100, "deceleration": 100,
              "jerk": 1000 } ] }
"#;

#[test]
fn a_stop_beyond_the_axis_limits_is_capped_and_reported() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("cap.il");
    std::fs::write(&src, PROGRAM).unwrap();
    std::fs::write(dir.path().join("cap.axes.json"), AXES).unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .arg("run")
        .arg(&src)
        .args([
            "--cycles",
            "3000",
            "--watch",
            "cap.step,cap.hard.Busy,cap.hard.Done,cap.soft.Busy,cap.soft.Done,axis.X1.velocity,\
             axis.X1.acceleration,axis.X1.stop_decel_requested,axis.X1.stop_decel_reached,\
             axis.X1.stop_jerk_requested,axis.X1.stop_jerk_reached",
            "--trace",
        ])
        .arg(&trace)
        .output()
        .unwrap();
    common::assert_ok(&out);
    let t = std::fs::read_to_string(&trace).unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    let v = column(&t, "axis.X1.velocity");
    let a = column(&t, "axis.X1.acceleration");
    // both stops ran to Done
    assert!(column(&t, "cap.hard.Done").contains(&1.0));
    assert!(column(&t, "cap.soft.Done").contains(&1.0), "{stderr}");
    // every cycle within the axis limits (1 ms)
    for i in 1..v.len() {
        assert!(a[i].abs() <= 100.0 * (1.0 + 1e-9), "row {i}: a {}", a[i]);
        assert!((a[i] - a[i - 1]).abs() <= 1000.0 * 0.001 * (1.0 + 1e-9) + 1e-12);
        assert!((v[i] - v[i - 1]).abs() <= 100.0 * 0.001 * (1.0 + 1e-9) + 1e-12);
    }
    // one reported row: the hard stop's first cycle
    let req = column(&t, "axis.X1.stop_decel_requested");
    let rows: Vec<usize> = (0..req.len()).filter(|&i| req[i] != 0.0).collect();
    assert_eq!(rows.len(), 1, "one capped stop: {rows:?}");
    let r = rows[0];
    assert_eq!(req[r], 5000.0);
    assert_eq!(column(&t, "axis.X1.stop_decel_reached")[r], 100.0);
    assert_eq!(column(&t, "axis.X1.stop_jerk_requested")[r], 100000.0);
    assert_eq!(column(&t, "axis.X1.stop_jerk_reached")[r], 1000.0);
    // the row is the stop's first braking cycle: the velocity falls from 40 there
    assert!(
        (v[r - 1] - 40.0).abs() < 1e-9 && v[r] < 40.0,
        "{} {}",
        v[r - 1],
        v[r]
    );
    let busy = column(&t, "cap.hard.Busy");
    assert!(
        busy[r] == 1.0 && busy[r - 1] == 0.0,
        "Busy rises in that row"
    );
    // the run summary names the axis, the block, the figures
    let line = stderr
        .lines()
        .find(|l| l.contains("MC_Stop"))
        .unwrap_or_else(|| panic!("no summary line: {stderr}"));
    assert!(
        line.contains("axis X1: MC_Stop cap.hard at cycle")
            && line.contains("deceleration requested 5000 mm/s^2, reached 100 mm/s^2")
            && line.contains("jerk requested 100000 mm/s^3, reached 1000 mm/s^3"),
        "{line}"
    );
    assert_eq!(
        stderr.lines().filter(|l| l.contains("MC_Stop")).count(),
        1,
        "only the capped stop: {stderr}"
    );
}
