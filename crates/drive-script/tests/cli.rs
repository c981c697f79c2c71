//! `build` and `run` library entry points: image file, CSV trace, run from an image, error exits.

use diagnostics::MessageFormat;
use drive_script::cli::{
    build, debug, debug_with_drive, run, run_with_drive, BuildArgs, DebugArgs, DriveKind, RunArgs,
    EXIT_IO, EXIT_OK, EXIT_REJECTED,
};

const PAPER: &str = "\
S:: INIT;
S:: Velocity = 100000;
S:: Acceleration = 1000000;
S:: Deceleration = 1000000;
S:: MOTION 0;
S:: EVENT 0;
S:: IF MD0 = 0;
S:: THEN DO_0=HIGH AND RelativeTargetPosition=10000 AND MD0 = 1;
";

fn text(v: Vec<u8>) -> String {
    String::from_utf8(v).unwrap()
}

#[test]
fn build_writes_an_image_that_run_accepts() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("paper.ds");
    let image = dir.path().join("paper.img");
    std::fs::write(&script, PAPER).unwrap();
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let args = BuildArgs {
        script: script.clone(),
        output: image.clone(),
        format: MessageFormat::Short,
    };
    assert_eq!(build(&args, &mut out, &mut err), EXIT_OK, "{}", text(err));
    // header 16 + fixed payload 288 + one Motion 4 + one Event (2 + one 23-byte condition + three 13-byte actions)
    assert_eq!(16 + 288 + 4 + 2 + 23 + 3 * 13, 372);
    let summary = text(out).replace(&dir.path().display().to_string(), "DIR");
    assert_eq!(
        summary,
        "DIR/paper.img: 1 Motions, 1 Events, 372 bytes (Motion pool 1/32, Event pool 1/256)\n"
    );
    let bytes = std::fs::read(&image).unwrap();
    assert_eq!(bytes.len(), 372);

    // Running the image and the script gives the same result.
    for input in [&image, &script] {
        let (mut out, mut err) = (Vec::new(), Vec::new());
        assert_eq!(
            run(&RunArgs::new(input.clone(), 500), &mut out, &mut err),
            EXIT_OK
        );
        assert_eq!(
            text(out),
            "500 cycles (500 ms): at Motion 0 Event 0 before IF; position 10000, velocity 0, DO 0x0001; 500 Events evaluated\n"
        );
    }
}

#[test]
fn run_writes_one_csv_row_per_cycle() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("paper.ds");
    let trace = dir.path().join("trace.csv");
    std::fs::write(&script, PAPER).unwrap();
    let mut args = RunArgs::new(script, 300);
    args.trace = Some(trace.clone());
    let (mut out, mut err) = (Vec::new(), Vec::new());
    assert_eq!(run(&args, &mut out, &mut err), EXIT_OK);
    let csv = std::fs::read_to_string(&trace).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 301);
    assert_eq!(
        lines[0],
        "cycle,time_ms,motion,event,phase,position,velocity,current,di,do,md0,md1,md2,md3,md4,md5,md6,md7"
    );
    assert!(lines[1].starts_with("0,1,0,0,IF,"), "{}", lines[1]);
    assert!(lines[1].ends_with(",0,1,1,0,0,0,0,0,0,0"), "{}", lines[1]);
    let positions: Vec<i32> = lines[1..]
        .iter()
        .map(|l| l.split(',').nth(5).unwrap().parse().unwrap())
        .collect();
    assert!(
        positions.windows(2).all(|w| w[0] <= w[1]),
        "the move is monotonic"
    );
    assert_eq!(*positions.last().unwrap(), 10000);
}

#[test]
fn rejected_script_and_missing_file_exit_codes_and_diagnostics() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.ds");
    std::fs::write(
        &bad,
        "S:: MOTION 0;\nS:: EVENT 0;\nS:: IF DI_0 OR DI_1;\nS:: THEN Stop;\n",
    )
    .unwrap();
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let args = BuildArgs {
        script: bad,
        output: dir.path().join("x.img"),
        format: MessageFormat::Short,
    };
    assert_eq!(build(&args, &mut out, &mut err), EXIT_REJECTED);
    let e = text(err).replace(&dir.path().display().to_string(), "DIR");
    assert_eq!(
        e,
        "DIR/bad.ds:3:13: error[E6009]: `OR` in a condition: conditions combine with AND only (hint: write one Event per alternative (same THEN), or use `|` to OR bits into one value)\n"
    );
    assert!(!dir.path().join("x.img").exists());

    let (mut out, mut err) = (Vec::new(), Vec::new());
    let mut args = RunArgs::new(dir.path().join("missing.ds"), 1);
    args.format = MessageFormat::Short;
    assert_eq!(run(&args, &mut out, &mut err), EXIT_IO);
    assert!(text(err).starts_with("error[E9001]: cannot read `"));
}

#[test]
fn corrupt_image_is_rejected_with_e6022() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("p.ds");
    let image = dir.path().join("p.img");
    std::fs::write(&script, PAPER).unwrap();
    let args = BuildArgs {
        script,
        output: image.clone(),
        format: MessageFormat::Short,
    };
    assert_eq!(build(&args, &mut Vec::new(), &mut Vec::new()), EXIT_OK);
    let mut bytes = std::fs::read(&image).unwrap();
    let n = bytes.len();
    bytes[n - 1] ^= 0xFF;
    std::fs::write(&image, bytes).unwrap();
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let mut args = RunArgs::new(image, 1);
    args.format = MessageFormat::Short;
    assert_eq!(run(&args, &mut out, &mut err), EXIT_REJECTED);
    let e = text(err);
    assert!(
        e.starts_with("error[E6022]: drive script image is corrupt: CRC-32 mismatch"),
        "{e}"
    );
}

/// Velocity column of CSV row `row` (1 = first cycle).
fn trace_velocity(csv: &str, row: usize) -> String {
    csv.lines()
        .nth(row)
        .unwrap()
        .split(',')
        .nth(6)
        .unwrap()
        .to_string()
}

#[test]
fn run_drives_a_motion_lib_axis_by_default_and_the_simulated_drive_on_request() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("paper.ds");
    std::fs::write(&script, PAPER).unwrap();
    let mut velocities = Vec::new();
    for kind in [None, Some(DriveKind::MotionLib), Some(DriveKind::Sim)] {
        let trace = dir.path().join("t.csv");
        let mut args = RunArgs::new(script.clone(), 400);
        args.trace = Some(trace.clone());
        let (mut out, mut err) = (Vec::new(), Vec::new());
        let code = match kind {
            None => run(&args, &mut out, &mut err),
            Some(k) => run_with_drive(&args, k, &mut out, &mut err),
        };
        assert_eq!(code, EXIT_OK, "{}", text(err));
        assert!(
            text(out).contains("position 10000, velocity 0, DO 0x0001"),
            "{kind:?}"
        );
        velocities.push(trace_velocity(&std::fs::read_to_string(&trace).unwrap(), 1));
    }
    // First cycle of the move: motion-lib's jerk-limited start (j t²/2 = 1e8 · 1e-6 / 2 = 50 p/s)
    // against SimDrive's trapezoid (a t = 1e6 · 1e-3 = 1000 p/s).
    assert_eq!(velocities, ["50", "50", "1000"]);
}

#[test]
fn drive_kind_option_values() {
    assert_eq!(DriveKind::parse("motion-lib"), Some(DriveKind::MotionLib));
    assert_eq!(DriveKind::parse("Sim"), Some(DriveKind::Sim));
    assert_eq!(DriveKind::parse("pmac"), None);
    assert_eq!(DriveKind::default(), DriveKind::MotionLib);
}

#[test]
fn debug_runs_the_script_on_a_motion_lib_axis_by_default() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("paper.ds");
    std::fs::write(&script, PAPER).unwrap();
    let args = DebugArgs {
        script,
        format: MessageFormat::Short,
    };
    let commands =
        "run 1\nprint ActualVelocity\nrun 400\nprint ActualPosition\nset DI_3 = HIGH\nprint DI_3\nquit\n";
    let mut answers = Vec::new();
    for kind in [None, Some(DriveKind::Sim)] {
        let (mut out, mut err) = (Vec::new(), Vec::new());
        let code = match kind {
            None => debug(&args, &mut commands.as_bytes(), &mut out, &mut err),
            Some(k) => debug_with_drive(&args, k, &mut commands.as_bytes(), &mut out, &mut err),
        };
        assert_eq!(code, EXIT_OK);
        let out = text(out);
        assert!(out.contains("ActualPosition = 10000"), "{out}");
        assert!(out.contains("(ds) DI_3 = 1\n(ds) DI_3 = 1\n"), "{out}");
        answers.push(
            out.lines()
                .find_map(|l| l.strip_prefix("(ds) ActualVelocity = "))
                .unwrap()
                .to_string(),
        );
    }
    assert_eq!(answers, ["50", "1000"]);
}
