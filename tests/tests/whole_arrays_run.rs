//! Whole arrays through `ladderc run`: IL `LD a` / `ST b` of an array, an array field of a structure, a
//! structure holding an array, a two-dimensional array, an array FB input and output, an array FUNCTION input (C arrays do not
//! assign, so the C copies them); the trace names a two-dimensional element `"inst.g2[1,1]"`, quoted.

mod common;
use common::{assert_ok, ladderc};

const PROGRAM: &str = "TYPE
  row : ARRAY[1..3] OF DINT;
  rec : STRUCT
    vals : row;
    n : INT;
  END_STRUCT;
  grid : ARRAY[0..1, 0..1] OF INT;
END_TYPE
FUNCTION total : DINT
  VAR_INPUT
    r : row;
  END_VAR
  LD r[1]
  ADD r[2]
  ADD r[3]
  ST total
END_FUNCTION
FUNCTION_BLOCK holder
  VAR_INPUT
    inrow : row;
  END_VAR
  VAR_OUTPUT
    outrow : row;
  END_VAR
  LD inrow
  ST outrow
END_FUNCTION_BLOCK
PROGRAM main
  VAR
    tick : INT;
    a : row := [1, 2, 3];
    b : row;
    r1 : rec;
    r2 : rec;
    g1 : grid := [1, 2, 3, 4];
    g2 : grid;
    h : holder;
    c : row;
    t : DINT;
  END_VAR
  LD tick
  ADD 1
  ST tick
  INT_TO_DINT
  ST a[2]
  LD a
  ST b
  ST r1.vals
  LD r1
  ST r2
  LD g1
  ST g2
  LD tick
  ST g1[1, 1]
  CAL h(
    inrow := b
  )
  LD h.outrow
  ST c
  LD c
  total
  ST t
END_PROGRAM
CONFIGURATION cfg
  RESOURCE res ON PLC
    TASK tsk (INTERVAL := T#10ms, PRIORITY := 0);
    PROGRAM inst WITH tsk : main;
  END_RESOURCE
END_CONFIGURATION
";

/// The fields of a CSV line (quoted fields keep their commas).
fn fields(line: &str) -> Vec<String> {
    let mut out = vec![String::new()];
    let mut quoted = false;
    for ch in line.chars() {
        match ch {
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(String::new()),
            _ => out.last_mut().unwrap().push(ch),
        }
    }
    out
}

#[test]
fn whole_arrays_copy_in_il_structures_and_fb_parameters() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("arrays.il");
    std::fs::write(&src, PROGRAM).unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .arg("run")
        .arg(&src)
        .args(["--cycles", "3", "--sanitize", "--trace"])
        .arg(&trace)
        .output()
        .unwrap();
    assert_ok(&out);
    let text = std::fs::read_to_string(&trace).unwrap();
    assert!(
        text.lines().next().unwrap().contains(",\"inst.g2[1,1]\","),
        "{text}"
    );
    let rows: Vec<Vec<String>> = text.lines().map(fields).collect();
    let col = |name: &str| -> Vec<&str> {
        let i = rows[0].iter().position(|h| h == name).unwrap();
        rows[1..].iter().map(|r| r[i].as_str()).collect()
    };
    // a[2] := tick, then b, r1.vals, r2.vals, h.inrow, h.outrow and c are copies of a
    for name in [
        "inst.b[2]",
        "inst.r1.vals[2]",
        "inst.r2.vals[2]",
        "inst.h.outrow[2]",
        "inst.c[2]",
    ] {
        assert_eq!(col(name), ["1", "2", "3"], "{name}");
    }
    assert_eq!(col("inst.c[3]"), ["3", "3", "3"]);
    // an array FUNCTION input: 1 + tick + 3
    assert_eq!(col("inst.t"), ["5", "6", "7"]);
    // g2 is copied before g1[1,1] is written: its initial 4, then the previous tick
    assert_eq!(col("inst.g2[1,1]"), ["4", "1", "2"]);
    assert_eq!(col("inst.g2[0,1]"), ["2", "2", "2"]);
}
