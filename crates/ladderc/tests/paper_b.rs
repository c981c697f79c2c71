//! Paper B's experiment end to end: `examples/paper-b` run through the `ladderc` binary (compiled C program +
//! motion library), its trace, plot, PMAC program and PVT checked against the paper and PLCopen's rules.
//!
//! Input: the example projects (read in place). Output: none (assertions). Invariant: every figure is
//! computed from what the binary wrote (trace, program text); nothing is a hard-coded expectation except
//! the paper's own numbers (targets, junction speeds) and closed-form profile times derived in the README.

use pmac_backend::model::{Sample, Trajectory};
use std::path::{Path, PathBuf};
use std::process::Command;

fn ladderc() -> Command {
    Command::new(env!("CARGO_BIN_EXE_ladderc"))
}

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The trace as named columns.
fn columns(csv: &str) -> Vec<(String, Vec<f64>)> {
    let mut lines = csv.lines();
    let header: Vec<String> = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_string)
        .collect();
    let mut cols = vec![Vec::new(); header.len()];
    for l in lines {
        for (i, v) in l.split(',').enumerate() {
            cols[i].push(v.parse::<f64>().unwrap());
        }
    }
    header.into_iter().zip(cols).collect()
}

fn col<'a>(cols: &'a [(String, Vec<f64>)], name: &str) -> &'a [f64] {
    &cols
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(name))
        .unwrap_or_else(|| panic!("no column {name}"))
        .1
}

/// The traced motion of `axes` as a trajectory sampled every `cycle_s`.
fn trajectory(cols: &[(String, Vec<f64>)], axes: &[&str], cycle_s: f64) -> Trajectory {
    Trajectory {
        cycle_s,
        axes: axes
            .iter()
            .map(|a| {
                let p = col(cols, &format!("axis.{a}.position"));
                let v = col(cols, &format!("axis.{a}.velocity"));
                let acc = col(cols, &format!("axis.{a}.acceleration"));
                (0..p.len())
                    .map(|i| Sample {
                        p: p[i],
                        v: v[i],
                        a: acc[i],
                    })
                    .collect()
            })
            .collect(),
    }
}

#[test]
fn pmac_pvt_of_a_run_reproduces_the_traced_motion() {
    let dir = tempfile::tempdir().unwrap();
    let (trace, pvt) = (dir.path().join("t.csv"), dir.path().join("m.pvt"));
    let out = ladderc()
        .arg("run")
        .arg(repo().join("examples/motion/move.il"))
        .args([
            "--cycles",
            "2200",
            "--watch",
            "main.at_100,main.back",
            "--trace",
        ])
        .arg(&trace)
        .arg("--pmac-pvt")
        .arg(&pvt)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cols = columns(&std::fs::read_to_string(&trace).unwrap());
    // the axis columns were added for the PVT
    let traj = trajectory(&cols, &["X1"], 0.002);
    let text = std::fs::read_to_string(&pvt).unwrap();
    assert!(text.contains("PVT10"), "{}", &text[..200.min(text.len())]);
    let curve = pmac_backend::verify::reconstruct_pvt(&text, &['X'], &[0.0], 1000.0).unwrap();
    // travel: 100 out, 40 back
    let worst = pmac_backend::verify::max_deviation(&traj, &curve, 0.002);
    assert!(worst <= 1e-6 * 140.0, "PVT deviates by {worst}");
    assert_eq!(curve.segment_count(), 2200 / 5);
}
