//! Software limits end to end through `ladderc run`: an IL program drives an axis at constant velocity
//! towards its positive software limit (the axis brakes and stops exactly at it, ErrorStop with ErrorID
//! 100), resets it with MC_Reset, tries a move further out (refused, ErrorID 27) and moves back into the
//! range (Done). Every figure is read from the trace the binary wrote.

mod common;
use common::column;
use common::ladderc;

const PROGRAM: &str = "PROGRAM lim
VAR
    pw : MC_Power;
    run : MC_MoveVelocity;
    rst : MC_Reset;
    out : MC_MoveAbsolute;
    back : MC_MoveAbsolute;
    powered : BOOL;
    step : INT := 0;
END_VAR
    CAL pw(Axis := X1, Enable := TRUE, EnablePositive := TRUE, EnableNegative := TRUE, Status => powered)
    (* step 0: run towards the limit at 40 mm/s until the velocity move ends in an error *)
    LD powered
    AND( step
    EQ 0
    )
    ST run.Execute
    CAL run(Axis := X1, Velocity := 40.0, Acceleration := 100.0, Deceleration := 100.0, Jerk := 1000.0)
    LD run.Error
    AND( step
    EQ 0
    )
    JMPCN no_error
    LD 1
    ST step
no_error:
    (* step 1: reset *)
    LD step
    EQ 1
    ST rst.Execute
    CAL rst(Axis := X1)
    LD rst.Done
    JMPCN no_reset
    LD 2
    ST step
no_reset:
    (* step 2: further out is refused, back into the range works *)
    LD step
    EQ 2
    ST out.Execute
    CAL out(Axis := X1, Position := 55.0, Velocity := 40.0, Acceleration := 100.0, Deceleration := 100.0,
            Jerk := 1000.0)
    LD step
    EQ 2
    ST back.Execute
    CAL back(Axis := X1, Position := 20.0, Velocity := 40.0, Acceleration := 100.0, Deceleration := 100.0,
             Jerk := 1000.0)
END_PROGRAM
";

const AXES: &str = r#"{ "cycle_ms": 1, "queue_depth": 4,
  "axes": [ { "name": "X1", "unit": "mm", "velocity": 100, "acceleration": 100, "deceleration": 100,
              "jerk": 1000, "software_limits": { "negative": -10, "positive": 50 } } ] }
"#;

#[test]
fn velocity_move_stops_at_the_limit_reset_and_back_into_range() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("lim.il");
    std::fs::write(&src, PROGRAM).unwrap();
    std::fs::write(dir.path().join("lim.axes.json"), AXES).unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .arg("run")
        .arg(&src)
        .args([
            "--cycles",
            "5000",
            "--watch",
            "lim.step,lim.run.Error,lim.run.ErrorID,lim.rst.Done,lim.out.Error,lim.out.ErrorID,\
             lim.back.Done,axis.X1.position,axis.X1.velocity",
            "--trace",
        ])
        .arg(&trace)
        .output()
        .unwrap();
    common::assert_ok(&out);
    let t = std::fs::read_to_string(&trace).unwrap();
    let p = column(&t, "axis.X1.position");
    let v = column(&t, "axis.X1.velocity");
    let step = column(&t, "lim.step");
    // never past the limit; stopped exactly at it
    let top = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    assert!(top <= 50.0 + 1e-9, "highest position {top}");
    let err_row = column(&t, "lim.run.ErrorID")
        .iter()
        .position(|e| *e == 100.0)
        .expect("ErrorID 100 (SoftwareLimitPositive)");
    // a row's block outputs come from the scan before that cycle's engine step: the axis state they
    // report is the row before
    let at = err_row - 1;
    assert!((p[at] - 50.0).abs() < 1e-9, "{}", p[at]);
    assert!(v[at].abs() < 1e-9);
    // reset and step 2 reached; further out refused with ErrorID 27
    assert!(step.contains(&2.0));
    assert!(column(&t, "lim.out.ErrorID").contains(&27.0));
    // back into the range: Done at 20
    let done = column(&t, "lim.back.Done");
    let d = done.iter().position(|x| *x == 1.0).expect("back Done");
    assert!((p[d - 1] - 20.0).abs() < 1e-9, "{}", p[d - 1]);
    eprintln!(
        "software limit run: stopped at {} (limit 50) in row {at}, back at 20 in row {}",
        p[at],
        d - 1
    );
}
