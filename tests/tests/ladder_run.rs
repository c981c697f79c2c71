//! Ladder and FBD projects through `ladderc run`, cycle by cycle: the three wrong-code bugs users report
//! against LD-to-ST converters (parallel coils re-evaluating their shared path, block outputs read before
//! the block runs, chained blocks called in the wrong order) and extensible comparison blocks. Each test
//! states the trace a correct compiler gives; the buggy lowering gives a different row, named in the test.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../crates/ladder-compiler/tests/fixtures")
        .join(name)
}

/// Runs `ladderc run` on a fixture with a stimulus; returns the trace rows (header dropped) as
/// vectors of cells, without the `cycle,time_ms` columns.
fn run(
    fixture_name: &str,
    stimulus: &str,
    cycles: u32,
    cycle_ms: u32,
    watch: &str,
) -> Vec<Vec<String>> {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, stimulus).unwrap();
    let trace = dir.path().join("trace.csv");
    let out = common::ladderc()
        .arg("run")
        .arg(fixture(fixture_name))
        .args([
            "--cycles",
            &cycles.to_string(),
            "--cycle-ms",
            &cycle_ms.to_string(),
        ])
        .arg("--stimulus")
        .arg(&stim)
        .arg("--trace")
        .arg(&trace)
        .args(["--watch", watch, "--sanitize"])
        .output()
        .unwrap();
    common::assert_ok(&out);
    let text = std::fs::read_to_string(&trace).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    assert_eq!(header, format!("cycle,time_ms,{watch}"));
    lines
        .map(|l| l.split(',').skip(2).map(str::to_string).collect())
        .collect()
}

fn row(cells: &[&str]) -> Vec<String> {
    cells.iter().map(|c| c.to_string()).collect()
}

#[test]
fn parallel_coils_get_one_evaluation_and_each_contact_reads_where_it_stands() {
    // Rung: (Start OR Motor) AND NOT Stop drives coils Motor and Lamp; a parallel branch, fed by the
    // seal-in contact Motor, reads Motor again into WasRunning. A converter that re-evaluates the shared
    // path per coil sets WasRunning in the very cycle Start is pressed. The seal-in contact stands
    // before the Motor coil (a feedback: the value from before the rung); the branch's own contact on
    // Motor stands below the coil and reads what it wrote, as Beremiz generates it (round 30, before:
    // the value from before the rung, so WasRunning stayed TRUE in the cycle Stop cleared Motor;
    // `ld_r30_run.rs`).
    let rows = run(
        "parallel_coils.xml",
        "cycle,variable,value\n1,main.Start,1\n2,main.Start,0\n4,main.Stop,1\n5,main.Stop,0\n",
        7,
        10,
        "main.Motor,main.Lamp,main.WasRunning",
    );
    let want = [
        ["0", "0", "0"], // idle
        ["1", "1", "0"], // Start pressed: Motor and Lamp on; the seal-in contact saw Motor from before
        ["1", "1", "1"], // sealed in
        ["1", "1", "1"],
        ["0", "0", "0"], // Stop: both coils off in the same cycle; the lower contact sees Motor off
        ["0", "0", "0"],
        ["0", "0", "0"],
    ];
    let want: Vec<Vec<String>> = want.iter().map(|r| row(r)).collect();
    assert_eq!(rows, want);
}

#[test]
fn a_timer_block_runs_before_the_coil_that_reads_its_output() {
    // TON T1 (PT = 500 ms) drawn below the rung that reads T1.Q. At 100 ms per cycle with Go from cycle 0,
    // ET reaches 500 ms in cycle 5 and Done must be TRUE in that same cycle; reading Q before calling
    // the block would show it one cycle late.
    let rows = run(
        "block_before_readers.xml",
        "cycle,variable,value\n0,main.Go,1\n",
        8,
        100,
        "main.Done,main.Elapsed",
    );
    let done: Vec<&str> = rows.iter().map(|r| r[0].as_str()).collect();
    assert_eq!(done, ["0", "0", "0", "0", "0", "1", "1", "1"], "{rows:?}");
    let first_done = done.iter().position(|d| *d == "1").unwrap();
    assert_eq!(rows[first_done][1], "T#500ms", "{rows:?}");
    assert_eq!(rows[first_done - 1][1], "T#400ms", "{rows:?}");
}

#[test]
fn chained_blocks_run_in_data_flow_order() {
    // ADD -> MUL -> GT -> CTU drawn right to left. With Limit 10 and B 1: (A + 1) * 3 > 10 when A >= 3.
    // Each rise of A past 3 must count in the same cycle; a wrong call order counts a cycle late or
    // compares a stale product.
    let stimulus = "cycle,variable,value\n0,main.Limit,10\n0,main.B,1\n0,main.A,0\n\
                    1,main.A,3\n2,main.A,0\n3,main.A,5\n4,main.A,1\n5,main.A,2\n6,main.A,4\n";
    let rows = run("chained_blocks.xml", stimulus, 8, 10, "main.Count");
    let count: Vec<&str> = rows.iter().map(|r| r[0].as_str()).collect();
    assert_eq!(count, ["0", "1", "1", "2", "2", "2", "3", "3"], "{rows:?}");
}

#[test]
fn extensible_comparison_blocks_compare_neighbouring_inputs() {
    // GT(A, B, C) = A > B AND B > C; EQ(A, B, C) = A = B AND B = C.
    let stimulus = "cycle,variable,value\n\
                    0,main.A,3\n0,main.B,2\n0,main.C,1\n\
                    1,main.C,2\n\
                    2,main.A,5\n2,main.B,1\n2,main.C,3\n\
                    3,main.A,4\n3,main.B,4\n3,main.C,4\n\
                    4,main.C,5\n";
    let rows = run(
        "extensible_compare.xml",
        stimulus,
        5,
        10,
        "main.Falling,main.Same",
    );
    let want: Vec<Vec<String>> = [
        ["1", "0"], // 3 > 2 > 1
        ["0", "0"], // 3 > 2, 2 > 2 fails
        ["0", "0"], // 5 > 1, 1 > 3 fails (a two-input GT would say TRUE)
        ["0", "1"], // all equal
        ["0", "0"], // 4 = 4, 4 = 5 fails
    ]
    .iter()
    .map(|r| row(r))
    .collect();
    assert_eq!(rows, want);
}

#[test]
fn corpus_01_counters_in_ld_fbd_il_and_st_agree_cycle_by_cycle() {
    // Beremiz "first steps": the same counter (count up each scan, load 17 while Reset) written in LD,
    // FBD, IL and ST, all called by an FBD program with one task of 100 ms. They must give the same
    // output in every cycle; the program's AverageVal (ST function) averages the five counters.
    let Some(file) = common::corpus_file("01_beremiz_first_steps.xml") else {
        return;
    };
    let p = "plc_task_instance";
    let counters = ["CounterLD0", "CounterFBD0", "CounterIL0", "CounterST0"];
    let mut watch: Vec<String> = counters.iter().map(|c| format!("{p}.{c}.OUT")).collect();
    watch.extend((1..=5).map(|i| format!("{p}.Cnt{i}")));
    watch.push(format!("{p}.AVCnt"));
    let watch = watch.join(",");
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        format!(
            "cycle,variable,value\n3,{p}.Reset,1\n5,{p}.Reset,0\n9,{p}.Reset,1\n10,{p}.Reset,0\n"
        ),
    )
    .unwrap();
    let trace = dir.path().join("trace.csv");
    let out = common::ladderc()
        .arg("run")
        .arg(&file)
        .args(["--cycles", "14", "--cycle-ms", "100", "--stimulus"])
        .arg(&stim)
        .arg("--trace")
        .arg(&trace)
        .args(["--watch", &watch, "--sanitize"])
        .output()
        .unwrap();
    common::assert_ok(&out);
    let text = std::fs::read_to_string(&trace).unwrap();
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').skip(2).collect())
        .collect();
    assert_eq!(rows.len(), 14);
    // The expected counter: +1 per scan from 0, 17 while Reset.
    let mut want = 0i64;
    for (cycle, r) in rows.iter().enumerate() {
        let reset = (3..5).contains(&cycle) || cycle == 9;
        want = if reset { 17 } else { want + 1 };
        for (k, c) in counters.iter().enumerate() {
            assert_eq!(r[k], want.to_string(), "cycle {cycle}: {c}\n{text}");
        }
        let cnt: Vec<f64> = r[4..9].iter().map(|v| v.parse().unwrap()).collect();
        let avg: f64 = r[9].parse().unwrap();
        assert!(
            (avg - cnt.iter().sum::<f64>() / 5.0).abs() < 1e-4,
            "cycle {cycle}: {r:?}"
        );
    }
}

#[test]
fn corpus_24_codesys_st_motion_library_builds_to_c_that_compiles() {
    // CODESYS ST functions with array inputs (passed by value) and vendor addData: `ladderc build`
    // writes the C project, and its Makefile builds it warning-free with the system compiler.
    let dir = tempfile::tempdir().unwrap();
    let out_dir = dir.path().join("out");
    let out = common::ladderc()
        .arg("build")
        .arg(common::corpus("24_feecat_S7RTT_codesys_st_motion.xml"))
        .arg("-o")
        .arg(&out_dir)
        .output()
        .unwrap();
    common::assert_ok(&out);
    let make = Command::new("make")
        .args(["-s", "CFLAGS=-std=c99 -Wall -Wextra -Werror -O1"])
        .current_dir(&out_dir)
        .output()
        .unwrap();
    assert!(
        make.status.success(),
        "{}",
        String::from_utf8_lossy(&make.stderr)
    );
    assert!(out_dir.join("program").is_file());
}
