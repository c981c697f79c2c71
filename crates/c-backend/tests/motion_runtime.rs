//! The motion runtime file (`ladderc_motion.c`): engine creation from the axis configuration, the step
//! hook, the trace arrays; it compiles strictly against the motion library's header.

use c_backend::motion::{MotionAxis, MotionGroup, MotionRuntime};

fn runtime() -> MotionRuntime {
    let axis = |name: &str, v: f64| MotionAxis {
        name: name.into(),
        velocity_limit: v,
        acceleration_limit: 1000.0,
        deceleration_limit: 500.0,
        jerk_limit: 0.0,
        sw_limits: None,
        modulo_period: 0.0,
        following_error_limit: 0.0,
    };
    let mut y = axis("Y1", 50.0);
    y.sw_limits = Some((100.0, -100.0));
    y.modulo_period = 360.0;
    MotionRuntime {
        cycle_seconds: 0.001,
        queue_depth: 8,
        axes: vec![axis("X1", 100.0), y],
        groups: vec![MotionGroup {
            name: "G1".into(),
            members: vec![(0, 0), (1, 1)],
        }],
        header: include_str!("../../motion-lib/include/motion_lib.h").into(),
    }
}

#[test]
fn the_runtime_creates_axes_and_groups_in_configuration_order() {
    let rt = runtime();
    let files = rt.files();
    assert_eq!(files[1].0, "motion_lib.h");
    insta::assert_snapshot!(files[0].1);
}

#[test]
fn each_axis_has_seven_watchable_columns() {
    let e = runtime().watch_entries();
    // seven per axis (set values, a capped MC_Stop), two per group (lowered junction speeds)
    assert_eq!(e.len(), 14 + 2 * runtime().groups.len());
    assert!(e
        .iter()
        .any(|x| x.contains("\"axis.X1.stop_decel_requested\"")));
    assert!(e
        .iter()
        .any(|x| x.contains("\"group.") && x.contains(".junction_requested\"")));
    assert_eq!(
        e[7],
        "{ \"axis.Y1.position\", LADDERC_T_LREAL, (void *)&ladderc_axis_position[1], NULL, 0, 0 }"
    );
    assert!(runtime()
        .declarations()
        .contains("extern IEC_LREAL ladderc_axis_velocity[2];"));
}

#[test]
fn the_runtime_compiles_with_strict_warnings() {
    compiles_strictly(runtime());
}

/// A program that uses PLCopen blocks without any configured axis or group (the blocks then report
/// an invalid axis): its runtime still compiles with -Wextra -Werror (no loop `i < 0u`).
#[test]
fn a_runtime_without_axes_compiles_with_strict_warnings() {
    let mut rt = runtime();
    rt.axes.clear();
    rt.groups.clear();
    compiles_strictly(rt);
}

fn compiles_strictly(rt: MotionRuntime) {
    let dir = tempfile::tempdir().unwrap();
    let mut files = rt.files();
    files.extend(c_backend::runtime::files());
    files.push((
        "ladderc_config.h".into(),
        c_backend::config_header(&c_backend::TargetProfile::default()),
    ));
    for (p, c) in &files {
        std::fs::write(dir.path().join(p), c).unwrap();
    }
    let out = std::process::Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()))
        .args([
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-pedantic",
            "-c",
            "ladderc_motion.c",
        ])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
