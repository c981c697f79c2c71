//! Integer constants of global variable lists in array bounds and string lengths (issue #13), as
//! CODESYS projects write them: the list in its own file (`GVL.st`, one object per file), the arrays
//! and strings in other files (a program, a `TYPE` STRUCT), a second list whose constant is an
//! expression of the first's; the same in one file with the list after its use; `STRING(N * 2)`
//! (CODESYS's parentheses) over constants; and in a CODESYS PLCopen XML export, a bound qualified by
//! the list's name (`GVL_Main.iLimit - 1`) whose CONSTANT section sits in the list's vendor data.
//! An IL program given with the `.st` list reads its bound the same way. Each run indexes the arrays
//! up to the constant bound and traces the values. A non-constant, a non-integer, a cycle between
//! constants and a bound that overflows are one located E0022 each.

mod common;
use common::{check_files, run_traced, run_traced_files};

use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/const_bounds")
        .join(name)
}

const WATCH: &str = "PLC_PRG.axes[4],PLC_PRG.sum,PLC_PRG.last_slot,PLC_PRG.data.pos[4],PLC_PRG.label,PLC_PRG.data.tag";

/// `axes[1..N_AXES]` (4) counts up by its index, `slots[0..N_SLOTS - 1]` (N_SLOTS = 4 * 2 + 1 = 9,
/// from the second list) has its last element counted, the STRUCT's `pos[1..N_AXES]` grows by 10 x
/// index, and `STRING(NAME_LEN)` (6) keeps the first 6 characters of 'ABCDEFGH'.
const EXPECTED: &str = "cycle,time_ms,PLC_PRG.axes[4],PLC_PRG.sum,PLC_PRG.last_slot,PLC_PRG.data.pos[4],PLC_PRG.label,PLC_PRG.data.tag\n\
     0,0,4,10,1,40,\"ABCDEF\",\"ABCDEF\"\n\
     1,10,8,20,2,80,\"ABCDEF\",\"ABCDEF\"\n\
     2,20,12,30,3,120,\"ABCDEF\",\"ABCDEF\"\n";

#[test]
fn constants_of_a_list_in_another_file_size_arrays_strings_and_struct_fields() {
    let (prg, dut, derived, gvl) = (
        fixture("PLC_PRG.st"),
        fixture("DUT_AxisData.st"),
        fixture("GVL_Derived.st"),
        fixture("GVL.st"),
    );
    // the lists after their users (each constant is then unknown where the file is first read) ...
    let (trace, _) = run_traced_files(&[&prg, &dut, &derived, &gvl], 3, WATCH);
    assert_eq!(trace, EXPECTED);
    // ... and before them: the same project
    let (trace, _) = run_traced_files(&[&gvl, &derived, &dut, &prg], 3, WATCH);
    assert_eq!(trace, EXPECTED);
}

#[test]
fn an_il_program_sized_by_a_constant_of_an_st_list() {
    let (trace, _) = run_traced_files(
        &[&fixture("counts.il"), &fixture("GVL.st")],
        2,
        "counts.per_axis[4],counts.last",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,counts.per_axis[4],counts.last\n0,0,5,5\n1,10,10,10\n"
    );
}

#[test]
fn a_list_after_its_use_in_one_file_and_a_string_length_expression() {
    // N_AXES = 3 declared after the program; `STRING(LEN * 2)` is 4 characters
    let (trace, _) = run_traced(
        &fixture("one_file.st"),
        2,
        "main.last,main.axes[3],main.text",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,main.last,main.axes[3],main.text\n\
         0,0,3,3,\"ABCD\"\n\
         1,10,6,6,\"ABCD\"\n"
    );
}

#[test]
fn a_bound_qualified_by_the_list_name_in_a_codesys_export() {
    // the CODESYS export of codesys_qualified_gvl.rs, whose PRG_ST gets an array
    // `aHist : ARRAY[0..GVL_Main.iLimit - 1] OF INT` (iLimit = 3, in the CONSTANT section that
    // CODESYS keeps in the list's vendor data) and writes aHist[iCount - 1] := 10 x iCount
    let src = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/fixtures/codesys/tc6_0200_qualified_gvl.xml"),
    )
    .unwrap();
    let decl = r#"<initialValue><simpleValue value="-1" /></initialValue></variable>"#;
    let body = "GVL_Main.xDone := GVL_Main.fbTimer.Q;</xhtml>";
    assert_eq!(src.matches(decl).count(), 1);
    assert_eq!(src.matches(body).count(), 1);
    let src = src
        .replace(
            decl,
            &format!(
                "{decl}\n<variable name=\"aHist\"><type><array><dimension lower=\"0\" \
                 upper=\"GVL_Main.iLimit - 1\" /><baseType><INT /></baseType></array></type></variable>"
            ),
        )
        .replace(
            body,
            "GVL_Main.xDone := GVL_Main.fbTimer.Q;\naHist[GVL_Main.iCount - 1] := GVL_Main.iCount * 10;</xhtml>",
        );
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("q.xml");
    std::fs::write(&f, src).unwrap();
    let (trace, _) = run_traced(&f, 4, "PRG_ST.aHist[0],PRG_ST.aHist[1],PRG_ST.aHist[2]");
    assert_eq!(
        trace,
        "cycle,time_ms,PRG_ST.aHist[0],PRG_ST.aHist[1],PRG_ST.aHist[2]\n\
         0,0,10,0,0\n\
         1,10,10,20,0\n\
         2,20,10,20,30\n\
         3,30,10,20,30\n"
    );
}

#[test]
fn non_constants_non_integers_cycles_and_overflows_are_one_located_error_each() {
    let gvl = "VAR_GLOBAL CONSTANT\n  A : INT := B + 1;\n  V : REAL := 2.5;\n  BIG : LINT := 4000000000;\nEND_VAR\n\
               VAR_GLOBAL\n  NC : INT := 3;\nEND_VAR\n";
    let gvl2 = "VAR_GLOBAL CONSTANT\n  B : INT := A + 1;\nEND_VAR\n";
    let prg = "PROGRAM main\nVAR\n  x : ARRAY[0..NC] OF INT;\n  y : ARRAY[0..V] OF INT;\n  \
               z : ARRAY[0..BIG] OF INT;\n  w : STRING(A);\nEND_VAR\nx[0] := 1;\nEND_PROGRAM\n";
    let (code, lines) = check_files(&[("main.st", prg), ("GVL.st", gvl), ("GVL2.st", gvl2)]);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        lines,
        vec![
            "main.st:3:16: error[E0022]: constant expression `NC`: `NC` names no constant with a value in the files given",
            "main.st:4:16: error[E0022]: constant expression `V`: `V` is not an integer constant",
            "main.st:5:16: error[E0022]: constant expression `BIG`: the value overflows",
            // (round 32: the cycle's `A`, without a value, is one error counting its uses)
            "main.st:6:14: error[E0022]: constant expression `A`: `A` names no constant with a value in the files given (2 uses)",
            "GVL.st:2:14: error[E0022]: constant expression `B + 1`: `B` names no constant with a value in the files given",
        ]
    );
}
