//! Arrays located in the process image (`holding AT %MW100 : ARRAY[0..4] OF INT;`), as CODESYS and
//! TwinCAT projects declare register maps (Keiji01/TwinCAT3's `Array_EPB_TDA_INT AT%MB1100 :
//! ARRAY [0..20] OF INT`). Before: every use was E2005 ("a located variable of a non-elementary
//! type"). Each element lives at its bytes in the area, row by row as C lays out an array, and is
//! read and written through the profile's byte order like any located variable; an index out of
//! range gives the first element and the bounds flag, as for any array. Fixture:
//! `tests/tests/fixtures/located_arrays/registers.st`.

mod common;
use common::{check_text, run_stimulated, run_traced};
use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/located_arrays")
        .join(name)
}

/// registers.st, two scans: holding starts [1, 2, 7, 7, 7] and `holding[k]` with k = 7 (outside
/// 0..4) writes holding[0] = 99 with the bounds flag; `alias AT %MW101` is holding[1] (2); the 2x3
/// DINT grid gains i * 10 + j per scan, so grid[2,1] is 21 then 42; flags[3] toggles; outs[1] :=
/// 16#0203 is 515 and sets lamp (%QX2.1, bit 1 of its low byte 16#03) with W1400; scale[1] doubles
/// from -2.25; setpoint = holding[4] + alias = 9; SIZEOF(grid) is 6 DINTs = 24.
#[test]
fn located_array_elements_read_and_write_their_bytes() {
    let (trace, stderr) = run_traced(
        &fixture("registers.st"),
        2,
        "holding[0],holding[1],holding[4],alias,Main.corner,flags[3],Main.flag3,outs[1],lamp,\
         scale[0],scale[1],Main.setpoint,Main.bytes",
    );
    let rows: Vec<&str> = trace.lines().skip(1).collect();
    assert_eq!(
        rows,
        [
            "0,0,99,2,7,2,21,1,1,515,1,1.5,-4.5,9,24",
            "1,10,99,2,7,2,42,0,0,515,1,1.5,-9,9,24"
        ]
    );
    assert!(
        stderr.contains("runtime: array index out of range"),
        "{stderr}"
    );
    assert!(
        stderr.contains("registers.st:11:16: warning[W1400]: `lamp` at %QX2.1 shares output bits with `outs` at %QW0"),
        "{stderr}"
    );
}

/// An HMI writing a register: a stimulus names the element (`holding[2]`), as the trace does.
#[test]
fn a_stimulus_writes_a_located_array_element() {
    let (trace, _) = run_stimulated(
        &fixture("registers.st"),
        3,
        "1,holding[2],21\n",
        "holding[2],Main.fromHmi",
    );
    let rows: Vec<&str> = trace.lines().skip(1).collect();
    assert_eq!(rows, ["0,0,7,14", "1,10,21,42", "2,20,21,42"]);
}

/// A located array of a POU (`VAR loc AT %MW400 : ARRAY[1..2] OF UINT`) keeps its value in the
/// area from scan to scan.
#[test]
fn a_pou_s_located_array_keeps_its_value_in_the_area() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("pou.st");
    std::fs::write(
        &f,
        "PROGRAM Main\nVAR loc AT %MW400 : ARRAY[1..2] OF UINT; w AT %MW401 : UINT; END_VAR\n\
         loc[2] := loc[2] + 3;\nEND_PROGRAM\n\
         CONFIGURATION C RESOURCE R ON PLC TASK t(INTERVAL := T#10ms); PROGRAM Main WITH t : Main; \
         END_RESOURCE END_CONFIGURATION\n",
    )
    .unwrap();
    let (trace, _) = run_traced(&f, 3, "Main.w");
    let rows: Vec<&str> = trace.lines().skip(1).collect();
    assert_eq!(rows, ["0,0,3", "1,10,6", "2,20,9"]);
}

/// What stays refused, one located E2005/E2001 each: a whole located array as a value, an array at a
/// bit address (at its use), and an array that does not fit in its area (100 INTs at %MW2000 need
/// bytes 4000..4200 of the 4096).
#[test]
fn whole_located_arrays_bit_addresses_and_overflows_are_refused() {
    let (code, lines) = check_text(
        "bad.st",
        "VAR_GLOBAL\n  regs AT %MW100 : ARRAY[0..4] OF INT;\n  bits AT %MX1.0 : ARRAY[0..7] OF BOOL;\n\
         big AT %MW2000 : ARRAY[0..99] OF INT;\nEND_VAR\n\
         PROGRAM Main\nVAR copy : ARRAY[0..4] OF INT; END_VAR\ncopy := regs;\nbits[1] := TRUE;\n\
         big[0] := 1;\nEND_PROGRAM\n",
    );
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split_once(" (hint").map_or(l.as_str(), |h| h.0))
        .collect();
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        heads,
        [
            "bad.st:4:8: error[E2001]: address `%MW2000` is outside the %M area (4096 bytes in target profile `default`)",
            "bad.st:8:9: error[E2005]: the C backend does not support a whole located array (use its elements)",
            "bad.st:9:1: error[E2005]: the C backend does not support an array located at a bit address (give it a byte address, `%MB`)",
        ]
    );
}
