//! Group moves against the axes' limits end to end through `ladderc run`: an IL program on an X/Y
//! group whose axes have software limits [-10, 10] moves to (6, 0); a line to (5, 12) is refused with
//! ErrorID 27 and an arc about (0, 4) to (-6, 0), whose bulge reaches y = 11.2 while both end points
//! are inside, with ErrorID 29, both before any motion; the arc about (0, 0) to (-6, 0) runs, its path
//! speed lowered by the centripetal acceleration from the requested 50 to sqrt(a / 2 * r) =
//! sqrt(50 * 6) mm/s, and the run summary and the trace's junction columns report that. Every figure
//! is read from the trace and the summary the binary wrote.

mod common;
use common::column;
use common::ladderc;

const PROGRAM: &str = "PROGRAM glim
VAR
    pw1 : MC_Power;
    pw2 : MC_Power;
    en : MC_GroupEnable;
    first : MC_MoveLinearAbsolute;
    out : MC_MoveLinearAbsolute;
    bad : MC_MoveCircularAbsolute;
    ok : MC_MoveCircularAbsolute;
    p1 : ARRAY [0..5] OF LREAL := [6.0, 0.0];
    pout : ARRAY [0..5] OF LREAL := [5.0, 12.0];
    cbad : ARRAY [0..5] OF LREAL := [0.0, 4.0];
    cok : ARRAY [0..5] OF LREAL := [0.0, 0.0];
    cend : ARRAY [0..5] OF LREAL := [-6.0, 0.0];
    powered : BOOL;
END_VAR
    CAL pw1(Axis := X1, Enable := TRUE)
    CAL pw2(Axis := Y1, Enable := TRUE)
    LD pw1.Status
    AND pw2.Status
    ST powered
    CAL en(AxesGroup := G1, Execute := powered)
    CAL first(AxesGroup := G1, Execute := en.Done, Position := p1, Velocity := 20.0, Acceleration := 100.0,
              Deceleration := 100.0, Jerk := 1000.0)
    CAL out(AxesGroup := G1, Execute := first.Done, Position := pout, Velocity := 20.0, Acceleration := 100.0,
            Deceleration := 100.0, Jerk := 1000.0)
    CAL bad(AxesGroup := G1, Execute := first.Done, CircMode := mcCenter, AuxPoint := cbad, EndPoint := cend,
            PathChoice := mcCounterClockwise, Velocity := 50.0, Acceleration := 100.0, Deceleration := 100.0,
            Jerk := 1000.0)
    CAL ok(AxesGroup := G1, Execute := bad.Error, CircMode := mcCenter, AuxPoint := cok, EndPoint := cend,
           PathChoice := mcCounterClockwise, Velocity := 50.0, Acceleration := 100.0, Deceleration := 100.0,
           Jerk := 1000.0)
END_PROGRAM
";

const AXES: &str = r#"{ "cycle_ms": 1, "queue_depth": 4,
  "axes": [ { "name": "X1", "unit": "mm", "velocity": 100, "acceleration": 100, "deceleration": 100,
              "jerk": 1000, "software_limits": { "negative": -10, "positive": 10 } },
            { "name": "Y1", "unit": "mm", "velocity": 100, "acceleration": 100, "deceleration": 100,
              "jerk": 1000, "software_limits": { "negative": -10, "positive": 10 } } ],
  "groups": [ { "name": "G1", "axes": [ { "axis": "X1", "identity": "X" }, { "axis": "Y1", "identity": "Y" } ] } ] }
"#;

#[test]
fn group_paths_keep_the_software_limits_and_a_tight_arc_is_slowed_and_reported() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("glim.il");
    std::fs::write(&src, PROGRAM).unwrap();
    std::fs::write(dir.path().join("glim.axes.json"), AXES).unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .arg("run")
        .arg(&src)
        .args([
            "--cycles",
            "6000",
            "--watch",
            "glim.first.Done,glim.out.Error,glim.out.ErrorID,glim.bad.Busy,glim.bad.ErrorID,\
             glim.ok.Active,glim.ok.Done,axis.X1.position,axis.Y1.position,axis.X1.velocity,\
             axis.Y1.velocity,group.G1.junction_requested,group.G1.junction_reached",
            "--trace",
        ])
        .arg(&trace)
        .output()
        .unwrap();
    common::assert_ok(&out);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let t = std::fs::read_to_string(&trace).unwrap();
    let x = column(&t, "axis.X1.position");
    let y = column(&t, "axis.Y1.position");
    // refused, never Busy, and nothing moved at the refusal
    assert!(column(&t, "glim.out.ErrorID").contains(&27.0));
    assert!(column(&t, "glim.bad.ErrorID").contains(&29.0));
    assert!(column(&t, "glim.bad.Busy").iter().all(|b| *b == 0.0));
    let refused = column(&t, "glim.bad.ErrorID")
        .iter()
        .position(|e| *e == 29.0)
        .unwrap();
    assert!((x[refused - 1] - 6.0).abs() < 1e-9 && y[refused - 1].abs() < 1e-9);
    // never outside the range; the good arc ends at (-6, 0)
    assert!(x.iter().chain(&y).all(|p| p.abs() <= 10.0 + 1e-9));
    let done = column(&t, "glim.ok.Done")
        .iter()
        .position(|d| *d == 1.0)
        .expect("the arc ends Done");
    assert!((x[done - 1] + 6.0).abs() < 1e-9 && y[done - 1].abs() < 1e-9);
    // the arc's speed: requested 50, reached sqrt(100 / 2 * 6)
    let reached_expected = (100.0_f64 / 2.0 * 6.0).sqrt();
    let req = column(&t, "group.G1.junction_requested");
    let got = column(&t, "group.G1.junction_reached");
    let rows: Vec<usize> = (0..req.len()).filter(|&i| req[i] > 0.0).collect();
    assert_eq!(rows.len(), 1, "one reduction row");
    assert_eq!(req[rows[0]], 50.0);
    assert!(
        (got[rows[0]] - reached_expected).abs() < 1e-9,
        "{}",
        got[rows[0]]
    );
    let vx = column(&t, "axis.X1.velocity");
    let vy = column(&t, "axis.Y1.velocity");
    let active = column(&t, "glim.ok.Active");
    let peak = (0..vx.len())
        .filter(|&i| active[i] == 1.0)
        .map(|i| vx[i].hypot(vy[i]))
        .fold(0.0_f64, f64::max);
    assert!(
        peak <= reached_expected * (1.0 + 1e-9) && peak > 0.99 * reached_expected,
        "path speed {peak} above {reached_expected}"
    );
    let line = stderr
        .lines()
        .find(|l| l.starts_with("motion: group G1: junction before glim.ok at cycle "))
        .unwrap_or_else(|| panic!("no reduction in the summary:\n{stderr}"));
    assert!(
        line.contains("requested 50 mm/s, reached 17.320508 mm/s"),
        "{line}"
    );
    eprintln!("group limits run: refused 27 and 29, arc at {peak:.6} of {reached_expected:.6} mm/s; {line}");
}
