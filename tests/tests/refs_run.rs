//! Issue #13 (helper `refs`): references and pointers compile and run.
//! - IEC 61131-3 edition 3 references (6.4.4.10): `REF_TO T` variables, structure fields, inputs
//!   and array elements, `REF(x)` of a variable, an array element or a structure field, `r^`
//!   read and written (`r^.field`, `r^[i]`), `NULL`, `=` / `<>`, assignment between references.
//! - CODESYS and TwinCAT `POINTER TO T` (`ADR(x)`, `p^`, `p := 0`, `p <> 0`) and `REFERENCE TO T`
//!   (read and written by its own name, bound by passing a variable or by `r REF= x`,
//!   `__ISVALIDREF(r)`), in `.st`, PLCopen XML (`<pointer>`, `REFERENCE TO X`) and TwinCAT files.
//! - A NULL dereference at run time reads zero, drops the write and is reported once at the end of
//!   the run with the place of the first (`runtime: NULL reference dereferenced (first: r^ in
//!   main; ...)`): no NULL pointer is ever dereferenced in C (the runs use `--sanitize`).
//! - What stays refused, one located diagnostic each: `REF` of a VAR_TEMP, of a FUNCTION's
//!   variable, of a VAR_IN_OUT, of a located variable or a bit (they could dangle or have no
//!   address: E0305), arithmetic on a pointer other than `p + n` / `p - n` (E0305), `^` on what is
//!   no reference (E1021), a reference to a type holding references stored into one to another type
//!   (E1006), a VAR_IN_OUT of a reference type (E0305). (Pointer indexing, byte arithmetic,
//!   ordering and conversions between pointer types run since issue #13's pointer round:
//!   `tests/tests/pointer_index_run.rs`.)
//!
//! Before: every such declaration was E0305 and the POU's body was not compiled.

mod common;
use common::{column, rejected_heads, run_traced, run_traced_files};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    common::repo_root()
        .join("tests/tests/fixtures/refs")
        .join(name)
}

/// A reference walks over `levels[1..4]` as `slot` changes: each scan adds the element it refers
/// to into `total` and increments it through the reference. An array of references to the two
/// tanks picks one by `slot MOD 2`; `t^.level` and `t^.alarm` write its fields; a reference to the
/// whole array reads `whole^[1]`; `t = watched[0]` compares two references, `cursor = NULL` one
/// with NULL (FALSE: it was just set).
#[test]
fn a_reference_walks_over_an_array_and_writes_through_fields() {
    let (trace, _) = run_traced(
        &fixture("ref_walk.st"),
        5,
        "main.total,main.levels[1],main.levels[2],main.tanks[0].level,main.tanks[1].level,main.first,main.same,main.none",
    );
    assert_eq!(
        column(&trace, "main.total"),
        [10.0, 30.0, 60.0, 100.0, 111.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "main.levels[1]"),
        [11.0, 11.0, 11.0, 11.0, 12.0]
    );
    assert_eq!(
        column(&trace, "main.levels[2]"),
        [20.0, 21.0, 21.0, 21.0, 21.0]
    );
    assert_eq!(
        column(&trace, "main.tanks[0].level"),
        [5.0, 5.0, 10.0, 10.0, 15.0]
    );
    assert_eq!(
        column(&trace, "main.tanks[1].level"),
        [0.0, 5.0, 5.0, 10.0, 10.0]
    );
    assert_eq!(column(&trace, "main.first"), [11.0, 11.0, 11.0, 11.0, 12.0]);
    assert_eq!(column(&trace, "main.same"), [1.0, 0.0, 1.0, 0.0, 1.0]);
    assert_eq!(column(&trace, "main.none"), [0.0; 5]);
}

/// `FB_Accumulate`'s `REFERENCE TO DINT` input is bound to `energy` by the call and adds 3 to it
/// each scan; `spare`'s is never bound (`__ISVALIDREF` FALSE, nothing written). The program's own
/// `meter` is bound by `REF=` in the scan `energy` reaches 6, then reads and writes `water`.
#[test]
fn a_reference_to_input_writes_the_callers_variable() {
    let (trace, _) = run_traced(
        &fixture("reference_input.st"),
        4,
        "main.energy,main.water,main.reading,main.meter_ok,main.acc.bound,main.spare.bound",
    );
    assert_eq!(
        column(&trace, "main.energy"),
        [3.0, 6.0, 9.0, 12.0],
        "{trace}"
    );
    assert_eq!(column(&trace, "main.water"), [100.0, 101.0, 102.0, 103.0]);
    assert_eq!(column(&trace, "main.reading"), [0.0, 101.0, 102.0, 103.0]);
    assert_eq!(column(&trace, "main.meter_ok"), [0.0, 0.0, 1.0, 1.0]);
    assert_eq!(column(&trace, "main.acc.bound"), [1.0; 4]);
    assert_eq!(column(&trace, "main.spare.bound"), [0.0; 4]);
}

/// A `REFERENCE TO` field of a structure, bound with `l.target REF= x`, doubles `x` each scan
/// through `l.target := l.target * l.gain`; a block's `REFERENCE TO` output, bound inside it to its
/// `REFERENCE TO` input, is written by the caller (`pick.chosen := pick.chosen + 1` adds to `y`).
#[test]
fn reference_to_fields_and_outputs_read_and_write_their_variables() {
    let (trace, _) = run_traced(
        &fixture("reference_fields.st"),
        3,
        "main.x,main.y,main.v,main.ok",
    );
    assert_eq!(column(&trace, "main.x"), [10.0, 20.0, 40.0], "{trace}");
    assert_eq!(column(&trace, "main.y"), [2.0, 3.0, 4.0]);
    assert_eq!(column(&trace, "main.v"), [2.0, 3.0, 4.0]);
    assert_eq!(column(&trace, "main.ok"), [1.0; 3]);
}

/// Instances called through references: `a` gets 1 through a pointer and 10 through `FB_User`'s
/// `REFERENCE TO FB_Cnt` input each scan, `b` 2 through the same pointer moved to it; a standard
/// TON called through `rt^(...)` reaches its 20 ms in the third scan.
#[test]
fn function_blocks_are_called_through_references() {
    let (trace, _) = run_traced(
        &fixture("fb_through_reference.st"),
        4,
        "main.a.n,main.b.n,main.q",
    );
    assert_eq!(
        column(&trace, "main.a.n"),
        [11.0, 22.0, 33.0, 44.0],
        "{trace}"
    );
    assert_eq!(column(&trace, "main.b.n"), [2.0, 4.0, 6.0, 8.0]);
    assert_eq!(column(&trace, "main.q"), [0.0, 0.0, 1.0, 1.0]);
}

/// In the second scan `r` is NULL: `got := r^` reads 0 and `r^ := got + 1` is dropped (`value`
/// stays 8); the run goes on, and its end names the first NULL dereference.
#[test]
fn a_null_dereference_reads_zero_drops_the_write_and_is_reported() {
    let (trace, stderr) = run_traced(&fixture("null_deref.st"), 3, "main.got,main.value");
    assert_eq!(column(&trace, "main.got"), [7.0, 0.0, 8.0], "{trace}");
    assert_eq!(column(&trace, "main.value"), [8.0, 8.0, 9.0]);
    assert!(
        stderr.contains(
            "runtime: NULL reference dereferenced (first: r^ in main at null_deref.st:17; zero read, write dropped)"
        ),
        "{stderr}"
    );
}

/// `ADR` of two structures passed to a block's `POINTER TO` input (and `0`, which the block
/// skips with `target <> 0`), `p^.field` inside it, and a pointer to an array written by `pb^[2]`.
#[test]
fn pointers_with_adr_read_and_write_their_variables() {
    let (trace, _) = run_traced(
        &fixture("pointers.st"),
        4,
        "main.conveyor.speed,main.conveyor.running,main.mixer.speed,main.buffer[2],main.valid",
    );
    assert_eq!(
        column(&trace, "main.conveyor.speed"),
        [5.0, 10.0, 15.0, 20.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "main.conveyor.running"),
        [0.0, 0.0, 1.0, 1.0]
    );
    assert_eq!(column(&trace, "main.mixer.speed"), [5.0, 10.0, 15.0, 20.0]);
    assert_eq!(column(&trace, "main.buffer[2]"), [10.0, 20.0, 30.0, 40.0]);
    assert_eq!(column(&trace, "main.valid"), [1.0; 4]);
}

/// A CODESYS export: `<pointer>` to an array as a block input (summed by `pSamples^[i]`), a
/// `REFERENCE TO DINT` input written by its name, a data type whose field is a pointer, and a
/// `POINTER TO INT` declared in the VAR block the program's ST body starts with, which increments
/// `samples[0]` each scan (so the sums of the first three samples grow by one more each scan).
#[test]
fn plcopen_xml_pointer_and_reference_types_run() {
    let (trace, _) = run_traced(
        &fixture("codesys_refs.xml"),
        3,
        "PLC_PRG.grand_total,PLC_PRG.out,PLC_PRG.samples[0]",
    );
    assert_eq!(
        column(&trace, "PLC_PRG.grand_total"),
        [7.0, 15.0, 24.0],
        "{trace}"
    );
    assert_eq!(column(&trace, "PLC_PRG.samples[0]"), [2.0, 3.0, 4.0]);
    assert_eq!(column(&trace, "PLC_PRG.out"), [40.0, 40.0, 40.0]);
}

/// TwinCAT files: a `REFERENCE TO UDINT` input written by the block's body and by its method, a
/// `POINTER TO` a structure, and a structure that points to its own type (`stA.pNext^.nValue`).
#[test]
fn twincat_references_pointers_and_methods_run() {
    let dir = fixture("twincat");
    let (trace, _) = run_traced_files(
        &[
            &dir.join("MAIN.TcPOU"),
            &dir.join("FB_Buffer.TcPOU"),
            &dir.join("ST_Sample.TcDUT"),
        ],
        3,
        "MAIN.nCount,MAIN.nBumped,MAIN.stA.nValue,MAIN.stA.bSeen,MAIN.stB.nValue,MAIN.nChain",
    );
    assert_eq!(column(&trace, "MAIN.nCount"), [11.0, 22.0, 33.0], "{trace}");
    assert_eq!(column(&trace, "MAIN.nBumped"), [11.0, 22.0, 33.0]);
    assert_eq!(column(&trace, "MAIN.stA.nValue"), [2.0, 4.0, 6.0]);
    assert_eq!(column(&trace, "MAIN.stA.bSeen"), [1.0, 1.0, 1.0]);
    assert_eq!(column(&trace, "MAIN.stB.nValue"), [1.0, 2.0, 3.0]);
    assert_eq!(column(&trace, "MAIN.nChain"), [3.0, 6.0, 9.0]);
}

/// What a reference may not refer to, and what may not be done with one: one located diagnostic
/// each, nothing more.
#[test]
fn dangling_references_and_pointer_arithmetic_are_located_errors() {
    let src = "FUNCTION f : INT\nVAR_INPUT x : INT; END_VAR\nVAR r : REF_TO INT; END_VAR\nr := REF(x);\nf := r^;\nEND_FUNCTION\n\
FUNCTION_BLOCK fb\nVAR_IN_OUT io : INT; END_VAR\nVAR r : REF_TO INT; END_VAR\nr := REF(io);\nEND_FUNCTION_BLOCK\n\
PROGRAM main\nVAR\n  p : POINTER TO INT;\n  q : POINTER TO INT;\n  r : REF_TO INT;\n  i : INT;\n  b AT %IX0.0 : BOOL;\n  rb : REF_TO BOOL;\n  w : WORD;\n  lt : BOOL;\nEND_VAR\nVAR_TEMP t : INT; END_VAR\n\
p := ADR(i);\np := p * 2;\nlt := p AND q;\nr := REF(t);\nrb := REF(b);\nrb := REF(w.3);\ni := i^;\nrb := REF(p);\np := p + 1.5;\ni := f(1);\nEND_PROGRAM\n";
    assert_eq!(
        rejected_heads("refs.st", src),
        [
            "refs.st:4:6: error[E0305]: a reference to `x` is not allowed: the variables of a FUNCTION live for one call (IEC 61131-3, 6.4.4.10)",
            "refs.st:10:6: error[E0305]: a reference to `io` is not allowed: a VAR_IN_OUT may stand for a temporary variable of the caller",
            // `p + n` / `p - n` (bytes), `p[i]`, `p < q` and pointers to other types are
            // allowed since issue #13's pointer round (tests/tests/pointer_index_run.rs): other
            // arithmetic on a pointer, a pointer to a type holding references and a pointer
            // moved by a non-integer stay errors
            "refs.st:25:6: error[E0305]: `MUL` on a reference (REF_TO INT): only a byte count may be added to or subtracted from a pointer",
            "refs.st:26:7: error[E0305]: `AND` on a reference (REF_TO INT): only a byte count may be added to or subtracted from a pointer",
            "refs.st:27:6: error[E0305]: a reference to `t` is not allowed: a VAR_TEMP variable lives for one call (IEC 61131-3, 6.4.4.10)",
            "refs.st:28:7: error[E0305]: a reference to `b` is not allowed: a located variable lives in the process image, which has no references",
            "refs.st:29:7: error[E0305]: a reference to `w.3` is not allowed: a bit or part of a variable has no address",
            "refs.st:30:6: error[E1021]: `i` is INT, not a reference: `^` cannot follow it",
            "refs.st:31:1: error[E1006]: cannot store REF_TO REF_TO INT into REF_TO BOOL",
            "refs.st:32:10: error[E1004]: ADD of REF_TO INT and a real literal: a pointer moves by an integer number of bytes",
        ]
    );
}

/// A reference starts as NULL: `:= NULL` is accepted (and traced as nothing: the run shows `r`
/// still NULL through `r = NULL`), `:= 5` is one E0305 at the initial value.
#[test]
fn initial_values_of_references() {
    assert_eq!(
        rejected_heads(
            "init.st",
            "PROGRAM main\nVAR\n  x : INT;\n  r : REF_TO INT := 5;\nEND_VAR\nx := 1;\nEND_PROGRAM\n",
        ),
        // (`REF(x)` of a variable of the POU is accepted since issue #13's twelfth round:
        // tests/tests/lang_left_r12.rs)
        ["init.st:4:18: error[E0305]: a reference cannot have the initial value `5`"]
    );
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("null.st");
    std::fs::write(
        &f,
        "PROGRAM main\nVAR\n  r : REF_TO INT := NULL;\n  unset : BOOL;\nEND_VAR\nunset := r = NULL;\nEND_PROGRAM\n",
    )
    .unwrap();
    let (trace, _) = run_traced(&f, 1, "main.unset");
    assert_eq!(column(&trace, "main.unset"), [1.0], "{trace}");
}

/// Hostile depth: 100,000 `REF_TO` in one type and 100,000 `^` in one access are one located
/// error each (E0211, E0108), quickly, without a deep recursion or C that nests 100,000 calls.
#[test]
fn deep_references_are_bounded() {
    let n = 100_000;
    let types = format!(
        "PROGRAM main\nVAR\n  r : {}INT;\nEND_VAR\nEND_PROGRAM\n",
        "REF_TO ".repeat(n)
    );
    assert_eq!(
        rejected_heads("deep_types.st", &types),
        ["deep_types.st:3:7: error[E0211]: references to references nested more than 64 deep"]
    );
    let carets = "^".repeat(n);
    let derefs = format!(
        "PROGRAM main\nVAR\n  r : REF_TO INT;\n  x : INT;\nEND_VAR\nx := r{carets};\nr{carets} := 1;\nEND_PROGRAM\n"
    );
    assert_eq!(
        rejected_heads("deep_derefs.st", &derefs),
        [
            "deep_derefs.st:6:71: error[E0108]: more than 64 `^` in one access",
            "deep_derefs.st:7:66: error[E0108]: more than 64 `^` in one access",
        ]
    );
}

/// The C of references builds with `-std=c99 -Wall -Wextra -Werror` (the generated Makefile run
/// with those flags), and the NULL scratch objects and `ladderc_deref` are in it.
#[test]
fn reference_c_is_warning_free() {
    for name in ["ref_walk.st", "pointers.st", "reference_input.st"] {
        let (_dir, c) =
            common::build_and_make(&fixture(name), "-std=c99 -Wall -Wextra -Werror -O1");
        assert!(c.contains("ladderc_deref("), "{name}");
        assert!(c.contains("static IEC_"), "{name}: no NULL scratch object");
    }
}
