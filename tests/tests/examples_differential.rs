//! Issue #5's differential acceptance on the bundled examples: every example that uses motion blocks runs
//! with `--strategy il` and `--strategy template` and gives identical traces (every program variable and
//! every axis's set position, velocity and acceleration), cycle by cycle. The TM views exist only with the
//! IL method and are left out of the comparison.

mod common;
use common::ladderc;
use std::path::Path;

/// The trace of a run, as rows of cells, without the IL method's TM view columns.
fn trace(src: &Path, axes: &Path, strategy: &str, cycles: u32, dir: &Path) -> Vec<Vec<String>> {
    let trace = dir.join(format!("{strategy}.csv"));
    let out = ladderc()
        .arg("run")
        .arg(src)
        .arg("--axes")
        .arg(axes)
        .args([
            "--cycles",
            &cycles.to_string(),
            "--strategy",
            strategy,
            "--trace",
        ])
        .arg(&trace)
        .output()
        .unwrap();
    common::assert_ok(&out);
    let text = std::fs::read_to_string(&trace).unwrap();
    let rows: Vec<Vec<String>> = text
        .lines()
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    let keep: Vec<usize> = (0..rows[0].len())
        .filter(|&i| !rows[0][i].contains("TM__"))
        .collect();
    rows.iter()
        .map(|r| keep.iter().map(|&i| r[i].clone()).collect())
        .collect()
}

#[test]
fn every_motion_example_runs_identically_with_both_methods() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples");
    let examples = [
        ("motion/move.il", "motion/move.axes.json", 2200),
        ("paper-b/paper_b.il", "paper-b/paper_b.axes.json", 20_000),
        (
            "paper-b/paper_b_corner.il",
            "paper-b/paper_b.axes.json",
            20_000,
        ),
        (
            "paper-b/paper_b_exact.il",
            "paper-b/paper_b.axes.json",
            20_000,
        ),
        (
            "paper-b/paper_b_pmac_md.il",
            "paper-b/paper_b.axes.json",
            20_000,
        ),
    ];
    for (src, axes, cycles) in examples {
        let dir = tempfile::tempdir().unwrap();
        let (src, axes) = (root.join(src), root.join(axes));
        let il = trace(&src, &axes, "il", cycles, dir.path());
        let template = trace(&src, &axes, "template", cycles, dir.path());
        assert_eq!(il.len(), cycles as usize + 1, "{}", src.display());
        assert!(il[0].iter().any(|c| c.starts_with("axis.")), "{:?}", il[0]);
        assert_eq!(il[0], template[0], "{}: columns", src.display());
        for (k, (a, b)) in il.iter().zip(&template).enumerate() {
            assert_eq!(a, b, "{}: row {k} differs", src.display());
        }
        // The motion really happens: some axis position changes over the run.
        let pos = il[0].iter().position(|c| c.ends_with(".position")).unwrap();
        assert_ne!(
            il[1][pos],
            il[il.len() - 1][pos],
            "{}: nothing moved",
            src.display()
        );
    }
}
