//! Variable-length arrays, `ARRAY [*] OF T` VAR_IN_OUTs (IEC 61131-3 edition 3, 6.5.3; issue #13,
//! TcUnit's array assertions): each run below goes through `ladderc run --sanitize` and checks the
//! values. One function sums arrays of different sizes and lower bounds, forwards its parameter to
//! another function, and a 2-D `ARRAY [*, *]` is summed row by row; an FB and FB methods take
//! `ARRAY [*]` in-outs (of INT, STRING, a STRUCT, an FB type, BOOL; a structure's array field);
//! an index past the actual upper bound reads zero, drops the write and is named at the end of the
//! run, with no byte outside the array touched; a TcUnit-shaped `AssertArrayEquals_INT` counts the
//! failed assertions. Wrong arguments are E1071, misplaced `ARRAY [*]` E1072, each located.

mod common;
use common::{rejected_heads, run_traced};

use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/varlen_arrays")
        .join(name)
}

/// `SumArr` of `[1..5]` (15) and of `[-2..0]` (60); `Fwd` passes its own `ARRAY [*]` on (600);
/// `Sum2` of `[1..2, 0..2]` weighs each row by its index: (1+2+3)*1 + (4+5+6)*2 = 36.
#[test]
fn one_function_sums_arrays_of_any_size_and_lower_bound() {
    let (trace, stderr) = run_traced(&fixture("sums.st"), 2, "p.s,p.t,p.u,p.w");
    assert_eq!(
        trace,
        "cycle,time_ms,p.s,p.t,p.u,p.w\n0,0,15,60,600,36\n1,10,15,60,600,36\n"
    );
    assert!(!stderr.contains("runtime:"), "{stderr}");
}

/// The FB's maximum (9 of `xs`, then 7 of the structure's `vals[3..4]`, the last call); its read
/// past the upper bound gives 0 and its write there is dropped (`xs[1]` stays 1, nothing after
/// the arrays changes), named at the end of the run as written (not by its hidden address
/// input); the methods count one failed assertion per
/// scan (`a` against `c`); `Cat` joins `ARRAY [*] OF STRING`, `SumPt` reads and writes STRUCT
/// elements, `RunAll` calls each FB element (1 + 1 + 1 per scan, summed), `AnyTrue` reads BOOLs.
#[test]
fn blocks_methods_and_element_types() {
    let (trace, stderr) = run_traced(
        &fixture("blocks.st"),
        2,
        "p.st.mx,p.st.last,p.su.fails,p.txt,p.q,p.ps[0].y,p.r,p.any,p.xs[1],p.h.vals[4]",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,p.st.mx,p.st.last,p.su.fails,p.txt,p.q,p.ps[0].y,p.r,p.any,p.xs[1],p.h.vals[4]\n\
         0,0,7,0,1,\"abcd\",7,42,3,1,1,7\n\
         1,10,7,0,2,\"abcd\",7,42,6,1,1,7\n"
    );
    assert!(
        stderr.contains(
            "runtime: pointer outside its variable dereferenced (first: data[UPPER_BOUND(data, 1) + 1] (an index outside the array passed) in Stats at blocks.st:16"
        ),
        "{stderr}"
    );
    assert!(
        stderr.contains("in Stats at blocks.st:16; zero read, write dropped)"),
        "{stderr}"
    );
}

/// `AssertEq(a, b)`: equal values at other bounds pass; `AssertEq(a, c)` fails once a scan.
#[test]
fn a_tcunit_shaped_array_assertion() {
    let (trace, _) = run_traced(&fixture("assertions.st"), 3, "p.su.fails");
    assert_eq!(trace, "cycle,time_ms,p.su.fails\n0,0,1\n1,10,2\n2,20,3\n");
}

const FUNC: &str = "FUNCTION SumArr : DINT\nVAR_IN_OUT a : ARRAY[*] OF INT; END_VAR\n\
                    SumArr := a[LOWER_BOUND(a, 1)];\nEND_FUNCTION\n";

/// Arguments that do not fit: another element type, another rank, no array, a missing in-out.
#[test]
fn arguments_that_do_not_fit_are_e1071() {
    let src = format!(
        "{FUNC}PROGRAM main\nVAR d : ARRAY[1..3] OF DINT; m : ARRAY[1..2, 1..2] OF INT; s : DINT; k : INT; END_VAR\n\
         s := SumArr(a := d);\ns := SumArr(m);\ns := SumArr(k);\ns := SumArr();\nEND_PROGRAM\n"
    );
    assert_eq!(
        rejected_heads("args.st", &src),
        vec![
            "args.st:7:18: error[E1071]: the `ARRAY [*]` in-out `a` of `SumArr` is `ARRAY [*] OF INT`: `ARRAY [1..3] OF DINT` does not fit",
            "args.st:8:13: error[E1071]: the `ARRAY [*]` in-out `a` of `SumArr` is `ARRAY [*] OF INT`: `ARRAY [1..2, 1..2] OF INT` does not fit",
            "args.st:9:13: error[E1071]: the `ARRAY [*]` in-out `a` of `SumArr` is `ARRAY [*] OF INT`: `INT` does not fit",
            "args.st:10:6: error[E1071]: the `ARRAY [*]` in-out `a` of `SumArr` is not given",
        ]
    );
}

/// The parameter used as a whole (also given to a fixed-size parameter), a wrong dimension, a wrong
/// number of indexes: E1072 at each.
#[test]
fn whole_uses_and_wrong_dimensions_are_e1072() {
    let src = "FUNCTION Fixed : DINT\nVAR_IN_OUT f : ARRAY[1..3] OF INT; END_VAR\nFixed := 1;\nEND_FUNCTION\n\
               FUNCTION SumArr : DINT\nVAR_IN_OUT a : ARRAY[*] OF INT; END_VAR\n\
               VAR copy : ARRAY[1..3] OF INT; END_VAR\ncopy := a;\nSumArr := Fixed(a);\n\
               SumArr := UPPER_BOUND(a, 2) + a[1, 2];\nEND_FUNCTION\n";
    assert_eq!(
        rejected_heads("uses.st", src),
        vec![
            "uses.st:8:9: error[E1072]: `a` is a variable-length array (`ARRAY [*]`): it is used by element, with LOWER_BOUND/UPPER_BOUND, or passed to another `ARRAY [*]` in-out",
            "uses.st:9:17: error[E1072]: `a` is a variable-length array (`ARRAY [*]`): it is used by element, with LOWER_BOUND/UPPER_BOUND, or passed to another `ARRAY [*]` in-out",
            "uses.st:10:11: error[E1072]: `UPPER_BOUND(a, ...)`: `a` has 1 dimension; the dimension must be an integer literal from 1 to 1",
            "uses.st:10:31: error[E1072]: `a` has 1 dimension: 2 indexes given",
        ]
    );
}

/// `ARRAY [*]` outside a VAR_IN_OUT (a VAR, a TYPE, a PROGRAM's in-out) and mixed with fixed bounds.
#[test]
fn misplaced_variable_length_arrays_are_e1072() {
    let src = "FUNCTION_BLOCK Bad\nVAR buf : ARRAY[*] OF INT; END_VAR\n\
               VAR_IN_OUT mix : ARRAY[1..2, *] OF INT; END_VAR\nEND_FUNCTION_BLOCK\n\
               TYPE row : ARRAY[*] OF INT; END_TYPE\n\
               PROGRAM main\nVAR_IN_OUT pio : ARRAY[*] OF INT; END_VAR\nEND_PROGRAM\n";
    let place = "a variable-length array `ARRAY [*]` is allowed only as a VAR_IN_OUT of a FUNCTION, FUNCTION_BLOCK or METHOD (IEC 61131-3 edition 3, 6.5.3)";
    assert_eq!(
        rejected_heads("placed.st", src),
        vec![
            format!("placed.st:2:17: error[E1072]: {place}"),
            "placed.st:3:30: error[E1072]: a variable-length array has `*` in every dimension or in none".to_string(),
            format!("placed.st:5:18: error[E1072]: {place}"),
            format!("placed.st:7:24: error[E1072]: {place}"),
        ]
    );
}

/// Indexes at the ends of LINT (read 0, write dropped, no byte outside reached under the
/// sanitizers); `m[0, 2]` of `[0..1, 0..1]` is out of its second dimension although its row-major
/// offset (2) lies inside the array: dropped, `mm[1, 0]` stays 0; an element passed to a fixed
/// in-out (`Inc(v := a[1])`) is incremented in the caller's array; an element as a CASE selector.
#[test]
fn indexes_out_of_the_actual_bounds_are_harmless_and_named() {
    let (trace, stderr) = run_traced(
        &fixture("edges.st"),
        1,
        "p.big,p.neg,p.ok,p.xs[1],p.xs[2],p.xs[3],p.q1,p.q2,p.r10",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,p.big,p.neg,p.ok,p.xs[1],p.xs[2],p.xs[3],p.q1,p.q2,p.r10\n\
         0,0,100,0,5,4,5,3,0,7,0\n"
    );
    assert!(
        stderr.contains("runtime: pointer outside its variable dereferenced (first: a[k] (an index outside the array passed) in Poke at edges.st:11;"),
        "{stderr}"
    );
}

/// A TwinCAT block (`.TcPOU`) whose `<Method>` takes two `ARRAY [*] OF BOOL` in-outs, as TcUnit's
/// `AssertArrayEquals_BOOL`: equal arrays at other bounds pass, different values fail, different
/// sizes fail with their message; two failures a scan.
#[test]
fn a_twincat_method_with_variable_length_in_outs() {
    let (trace, _) = common::run_traced_files(
        &[&fixture("FB_ArraySuite.TcPOU"), &fixture("MAIN.st")],
        2,
        "MAIN.suite.Failed,MAIN.suite.LastMessage",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,MAIN.suite.Failed,MAIN.suite.LastMessage\n\
         0,0,2,\"a = d, size of arrays not matching.\"\n\
         1,10,4,\"a = d, size of arrays not matching.\"\n"
    );
}

/// An index of a 2-D `ARRAY [*]` that calls a function is evaluated twice: W1432 at it (the
/// program still compiles); a variable index is no warning.
#[test]
fn a_2d_index_calling_a_function_is_w1432() {
    let src = "FUNCTION Row : DINT\nRow := 1;\nEND_FUNCTION\n\
               FUNCTION Fill : BOOL\nVAR_IN_OUT m : ARRAY[*, *] OF INT; END_VAR\nVAR k : DINT := 1; END_VAR\n\
               m[Row(), 1] := 0;\nm[k, 1] := 0;\nFill := TRUE;\nEND_FUNCTION\n";
    let (code, lines) = common::check_text("twice.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split_once(" (hint").map_or(l.as_str(), |(h, _)| h))
        .collect();
    assert_eq!(
        heads,
        vec!["twice.st:7:3: warning[W1432]: this index of `m` (a 2-dimensional `ARRAY [*]`) calls a function: it is evaluated twice"]
    );
}

/// TcUnit's own pattern: `MyTests EXTENDS Suite`, each test METHOD declaring its arrays in its VAR
/// (they live for the method's call) and calling the inherited `AssertEq`: one pass and one
/// failure a scan. Before the call-scoped address, each argument was E0305.
#[test]
fn test_methods_pass_their_own_arrays_to_an_inherited_assertion() {
    let (trace, _) = run_traced(&fixture("inherited.st"), 2, "p.t.fails,p.t.passes");
    assert_eq!(
        trace,
        "cycle,time_ms,p.t.fails,p.t.passes\n0,0,1,1\n1,10,2,2\n"
    );
}

/// A FUNCTION's own VAR array (5+6+7+8), a function's fixed VAR_IN_OUT passed on (1+2), a
/// program's VAR_TEMP (4+4+4) to a function's `ARRAY [*]` (read during the call only); a block's
/// `ARRAY [*]` passed on to a function (1+2).
#[test]
fn arrays_that_live_for_one_call_go_to_functions() {
    let (trace, _) = run_traced(&fixture("one_call.st"), 2, "p.s1,p.s2,p.s3,p.s4");
    assert_eq!(
        trace,
        "cycle,time_ms,p.s1,p.s2,p.s3,p.s4\n0,0,26,3,12,3\n1,10,26,3,12,3\n"
    );
}

/// An FB keeps its `ARRAY [*]` in the instance (its methods may read it between calls): a
/// program's VAR_TEMP given to it is E0305, a function's `ARRAY [*]` passed on to it E1071.
#[test]
fn a_block_takes_only_arrays_that_live_as_long_as_the_program() {
    let keeper =
        "FUNCTION_BLOCK Keeper\nVAR_IN_OUT data : ARRAY[*] OF INT; END_VAR\nEND_FUNCTION_BLOCK\n";
    let temp = format!(
        "{keeper}PROGRAM main\nVAR k : Keeper; END_VAR\nVAR_TEMP t : ARRAY[1..3] OF INT; END_VAR\n\
         k(data := t);\nEND_PROGRAM\n"
    );
    assert_eq!(
        rejected_heads("temp.st", &temp),
        vec!["temp.st:7:11: error[E0305]: a reference to `t` is not allowed: a VAR_TEMP variable lives for one call (IEC 61131-3, 6.4.4.10)"]
    );
    let forward = format!(
        "{keeper}FUNCTION Fwd : DINT\nVAR_IN_OUT a : ARRAY[*] OF INT; END_VAR\n\
         VAR_EXTERNAL gk : Keeper; END_VAR\ngk(data := a);\nEND_FUNCTION\n"
    );
    assert_eq!(
        rejected_heads("fwd.st", &forward),
        vec!["fwd.st:7:12: error[E1071]: the `ARRAY [*]` in-out `data` of `gk` keeps its array in the instance: `a` of a function or method may be an array that lives for one call"]
    );
}

/// An IL `CAL` of a block with an `ARRAY [*]` in-out (declared in ST): one E1071 naming the
/// in-out, not an unknown parameter listing the hidden inputs.
#[test]
fn an_il_call_of_a_variable_length_in_out_is_e1071() {
    let dir = tempfile::tempdir().unwrap();
    let st = dir.path().join("keeper.st");
    let il = dir.path().join("main.il");
    std::fs::write(
        &st,
        "FUNCTION_BLOCK Keeper\nVAR_IN_OUT data : ARRAY[*] OF INT; END_VAR\nVAR_OUTPUT n : DINT; END_VAR\n\
         n := UPPER_BOUND(data, 1);\nEND_FUNCTION_BLOCK\n",
    )
    .unwrap();
    std::fs::write(
        &il,
        "PROGRAM main\nVAR k : Keeper; xs : ARRAY[1..4] OF INT; END_VAR\nCAL k(data := xs)\nEND_PROGRAM\n",
    )
    .unwrap();
    let out = common::ladderc()
        .args(["--message-format", "short", "check"])
        .args([&st, &il])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        common::diagnostic_heads(&out.stderr, dir.path(), true),
        vec!["main.il:3:7: error[E1071]: `data` of Keeper is an `ARRAY [*]` in-out: only calls in Structured Text pass a variable-length array"]
    );
}

/// A statement of 100,000 operators that also reads an `ARRAY [*]` element: E0109 (more than 1,000
/// operations) as for any array, and no crash (the rewrite looks at it without recursion and
/// leaves it; before, copying it overflowed the stack).
#[test]
fn a_very_long_statement_with_a_variable_length_array_is_rejected_without_a_crash() {
    let chain = vec!["k"; 100_000].join(" + ");
    let src = format!(
        "FUNCTION SumArr : DINT\nVAR_IN_OUT a : ARRAY[*] OF INT; END_VAR\nVAR k : DINT := 1; END_VAR\n\
         SumArr := {chain} + a[LOWER_BOUND(a, 1)];\nEND_FUNCTION\n"
    );
    let (code, lines) = common::check_text("chain.st", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(lines[0].contains("error[E0109]"), "{lines:?}");
}

/// Struckig's tests call TcUnit's `AssertArrayEquals_LREAL(otg.CurrentPosition, NewPosition, 1E-9,
/// message := '...')`: the arrays by position, in a call that names a later argument (CODESYS's
/// mixed form). Before, both in-outs were E1071 "not given" (62 errors in Struckig_unittest). The
/// sum of |a[i] - b[i]| + Delta over [0..2] is 0.5 + 3 * 0.25 = 1.25; the upper bound is 2.
#[test]
fn positional_arrays_in_a_call_that_names_a_later_argument() {
    let (trace, stderr) = run_traced(&fixture("mixed_positional.st"), 1, "main.d.sum,main.d.n");
    assert_eq!(trace, "cycle,time_ms,main.d.sum,main.d.n\n0,0,1.25,2\n");
    assert!(!stderr.contains("error["), "{stderr}");
}
