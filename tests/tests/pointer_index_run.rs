//! Issue #13 (helper `ptridx`): pointer indexing and pointer arithmetic, bounded, so that Struckig
//! (stefanbesler/struckig, TwinCAT's port of ruckig; GPLv3, so the fixtures are our own small
//! texts reproducing its constructs, none of its code) compiles.
//! - `p[i]` on a `POINTER TO T` is the i-th T after `p^` (Beckhoff Infosys "POINTER TO", CODESYS
//!   help "Pointer"), read and written, counted from 0 whatever the lower bound of the array the
//!   pointer was made from; `ADR(array)` of an array of T is a `POINTER TO T` (its first element);
//!   methods and functions take `POINTER TO LREAL` inputs and index them (Struckig's `Roots`,
//!   `BubbleSortLreal`).
//! - `p + n` / `p - n` move a pointer by n BYTES (CODESYS pointer arithmetic: `p + SIZEOF(p^)`);
//!   pointers compare with `=`, `<>`, `<`, `<=` ... (their addresses); `ADR(p[i])` and a pointer
//!   made from an array element (`ADR(buf[3])`) move within the whole array.
//! - A pointer stored into a pointer to another type reads the same bytes (W1425 once per POU;
//!   only between types holding no reference and no FB instance): Struckig's `LrealBits`.
//! - A pointer is bounded (`IEC_REF`: the address and size of the variable it was made from and
//!   an offset): an access outside that variable, or misaligned for its type, reads 0, drops the
//!   write and is named at the end of the run, as a NULL dereference is. Every run here uses
//!   `--sanitize` (address, undefined): clean for any index.
//!
//! Before: `p[i]` on a pointer was E1021 (not an array), `p + n` and `p < q` E0305, `ADR(array)`
//! into a `POINTER TO LREAL` and `POINTER TO ULINT := ADR(lreal)` E1006/E1012. Struckig's own
//! library (`ladderc check --max-diagnostics 0 Struckig.plcproj`, its two BYTE FOR counters made
//! INT so that checking goes past them): 287 errors, 166 of them on pointers (E1012 x99, E1021
//! x51, E1006 x16), before; 122 after, none on pointers (what remains is listed in the README,
//! "Struckig").

mod common;
use common::{check_text, column, rejected_heads, run_traced};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    common::repo_root()
        .join("tests/tests/fixtures/pointer_index")
        .join(name)
}

/// `Poly.Eval(ADR(coeffs), 3, x)` evaluates 2x^3 - 3x^2 + 5 by indexing its `POINTER TO LREAL`
/// input (4, 9, 32 for x = 1, 2, 3); `Slope` passes `ADR` of the block's own `deriv` to `Deri`,
/// which writes the derivative's coefficients through its `out` pointer (6, -6, 0), and then to
/// `Eval` (6x^2 - 6x: 0, 12, 36). `SortIdx` orders the indices of `times[1..5]` through two
/// pointers (`data[idx[j]]`, 0-based), counting the swaps (the inversions: 6, then 7 once
/// times[1] is the largest).
#[test]
fn methods_and_functions_index_pointer_inputs() {
    let (trace, _) = run_traced(
        &fixture("poly_sort.st"),
        3,
        "Main.value,Main.slope,Main.swaps,Main.order[0],Main.order[1],Main.order[2],\
         Main.order[3],Main.order[4],Main.p.deriv[0],Main.p.deriv[1],Main.p.deriv[2]",
    );
    assert_eq!(column(&trace, "Main.value"), [4.0, 9.0, 32.0], "{trace}");
    assert_eq!(column(&trace, "Main.slope"), [0.0, 12.0, 36.0]);
    assert_eq!(column(&trace, "Main.swaps"), [6.0, 7.0, 7.0]);
    let order: Vec<Vec<f64>> = (0..5)
        .map(|i| column(&trace, &format!("Main.order[{i}]")))
        .collect();
    let scan = |k: usize| order.iter().map(|c| c[k]).collect::<Vec<f64>>();
    assert_eq!(scan(0), [3.0, 1.0, 4.0, 0.0, 2.0]);
    assert_eq!(scan(1), [3.0, 1.0, 4.0, 2.0, 0.0]);
    assert_eq!(scan(2), [3.0, 1.0, 4.0, 2.0, 0.0]);
    assert_eq!(column(&trace, "Main.p.deriv[0]"), [6.0; 3]);
    assert_eq!(column(&trace, "Main.p.deriv[1]"), [-6.0; 3]);
    assert_eq!(column(&trace, "Main.p.deriv[2]"), [0.0; 3]);
}

/// A walk `p := p + SIZEOF(p^)` while `p <= pEnd` sums the six DINTs (210, then 751 and 752 as
/// buf[6] becomes 600 and buf[2] grows); one DINT back from one past the end is the last element;
/// `mid := ADR(buf[3])` reads `mid[-1]` and `mid[1]` (20 + 40 * 1000, growing with buf[2]);
/// `ADR(mid[2])` is buf[5] (50), after `mid`; `q[1]` writes buf[6]; `ADR(buf[1]) = ADR(buf)`;
/// `pEnd - first` is 20 bytes (five DINTs). `ps[k].x` / `ps[k].y` write the points through a
/// `POINTER TO Pt` (x is k plus the last scan's sy); `py := ADR(ps[1].y)` keeps the whole array,
/// so `py^ + py[1]` is pts[1].y + pts[2].x (12, 24, 36).
#[test]
fn pointer_arithmetic_counts_bytes_and_pointers_compare() {
    let (trace, _) = run_traced(
        &fixture("pointer_step.st"),
        3,
        "Main.sum,Main.count,Main.back,Main.around,Main.viaAdr,Main.ordered,Main.same,\
         Main.buf[6],Main.buf[2],Main.dist,Main.sy,Main.pts[2].x,Main.pts[1].y",
    );
    assert_eq!(column(&trace, "Main.sum"), [210.0, 751.0, 752.0], "{trace}");
    assert_eq!(column(&trace, "Main.count"), [6.0; 3]);
    assert_eq!(column(&trace, "Main.back"), [60.0, 600.0, 600.0]);
    assert_eq!(column(&trace, "Main.around"), [40020.0, 40021.0, 40022.0]);
    assert_eq!(column(&trace, "Main.viaAdr"), [50.0; 3]);
    assert_eq!(column(&trace, "Main.ordered"), [1.0; 3]);
    assert_eq!(column(&trace, "Main.same"), [1.0; 3]);
    assert_eq!(column(&trace, "Main.buf[6]"), [600.0; 3]);
    assert_eq!(column(&trace, "Main.buf[2]"), [21.0, 22.0, 23.0]);
    assert_eq!(column(&trace, "Main.dist"), [20.0; 3]);
    assert_eq!(column(&trace, "Main.pts[1].y"), [10.0; 3]);
    assert_eq!(column(&trace, "Main.pts[2].x"), [2.0, 14.0, 26.0]);
    assert_eq!(column(&trace, "Main.sy"), [12.0, 24.0, 36.0]);
}

/// The bits of 1.0, 2.0, 4.0 through a `POINTER TO ULINT` started as `ADR(x)` of a FUNCTION's
/// input, and back (one less in the exponent halves it); a DINT's bytes through a `POINTER TO
/// BYTE` (byte 1 written: 16#1122AB44); a 2x3 array of INT through a `POINTER TO INT`, row by
/// row (`pi[5]` is grid[1,2], `pi[4]` writes grid[1,1]). Each conversion is one W1425 per POU.
#[test]
fn pointers_to_another_type_read_the_same_bytes() {
    let (trace, _) = run_traced(
        &fixture("pointer_casts.st"),
        3,
        "Main.bits,Main.back,Main.half,Main.packed,Main.b0,Main.b3,Main.last,Main.corner",
    );
    assert_eq!(
        column(&trace, "Main.bits"),
        [
            4607182418800017408.0,
            4611686018427387904.0,
            4616189618054758400.0
        ],
        "{trace}"
    );
    assert_eq!(column(&trace, "Main.back"), [1.0, 2.0, 4.0]);
    assert_eq!(column(&trace, "Main.half"), [0.5, 1.0, 2.0]);
    assert_eq!(column(&trace, "Main.packed"), [f64::from(0x1122_AB44); 3]);
    assert_eq!(column(&trace, "Main.b0"), [68.0; 3]);
    assert_eq!(column(&trace, "Main.b3"), [17.0; 3]);
    assert_eq!(column(&trace, "Main.last"), [6.0; 3]);
    assert_eq!(column(&trace, "Main.corner"), [60.0; 3]);
    let (code, lines) = check_text(
        "casts.st",
        &std::fs::read_to_string(fixture("pointer_casts.st")).unwrap(),
    );
    assert_eq!(code, Some(0), "{lines:?}");
    let w1425: Vec<&String> = lines.iter().filter(|l| l.contains("W1425")).collect();
    assert_eq!(w1425.len(), 3, "{lines:?}");
    assert!(
        w1425[0]
            .starts_with("casts.st:11:29: warning[W1425]: REF_TO LREAL stored into REF_TO ULINT"),
        "{lines:?}"
    );
    assert!(
        w1425[2].starts_with("casts.st:45:5: warning[W1425]: REF_TO DINT stored into REF_TO BYTE"),
        "{lines:?}"
    );
}

/// `p[k]` for k = -2, 1, 4, 7 (before, inside, one past and far past `data[0..3]`), `p[kMax]` and
/// `p[-kMax]` (the largest LINT: no overflow), `p + kMax`, every index from -50 to 50 read and
/// written, a `POINTER TO LREAL` one byte into `data` (misaligned) and a NULL pointer indexed:
/// reads outside give 0, writes outside are dropped, only `data`'s four elements change (each
/// +1 per scan; `p[1] := -1.0` in the scan k is 1), `guardLow` and `guardHigh` never do. The end
/// of the run names the first NULL and the first pointer fault.
#[test]
fn out_of_bounds_pointer_accesses_read_zero_and_drop_the_write() {
    let (trace, stderr) = run_traced(
        &fixture("pointer_faults.st"),
        4,
        "Main.guardLow[0],Main.guardLow[1],Main.data[0],Main.data[1],Main.data[2],Main.data[3],\
         Main.guardHigh[0],Main.guardHigh[1],Main.got,Main.huge,Main.beyond,Main.misaligned,\
         Main.nul,Main.total",
    );
    assert_eq!(column(&trace, "Main.guardLow[0]"), [111.0; 4], "{trace}");
    assert_eq!(column(&trace, "Main.guardLow[1]"), [222.0; 4]);
    assert_eq!(column(&trace, "Main.guardHigh[0]"), [333.0; 4]);
    assert_eq!(column(&trace, "Main.guardHigh[1]"), [444.0; 4]);
    assert_eq!(column(&trace, "Main.data[0]"), [2.0, 3.0, 4.0, 5.0]);
    assert_eq!(column(&trace, "Main.data[1]"), [3.0, 0.0, 1.0, 2.0]);
    assert_eq!(column(&trace, "Main.data[2]"), [4.0, 5.0, 6.0, 7.0]);
    assert_eq!(column(&trace, "Main.data[3]"), [5.0, 6.0, 7.0, 8.0]);
    assert_eq!(column(&trace, "Main.got"), [0.0, 3.0, 0.0, 0.0]);
    assert_eq!(column(&trace, "Main.total"), [14.0, 14.0, 18.0, 22.0]);
    for c in ["Main.huge", "Main.beyond", "Main.misaligned", "Main.nul"] {
        assert_eq!(column(&trace, c), [0.0; 4], "{c}");
    }
    assert!(
        stderr.contains(
            "runtime: pointer outside its variable dereferenced (first: p[k] in Main at pointer_faults.st:27; zero read, write dropped)"
        ),
        "{stderr}"
    );
    assert!(
        stderr.contains(
            "runtime: NULL reference dereferenced (first: np[3] in Main at pointer_faults.st:46; zero read, write dropped)"
        ),
        "{stderr}"
    );
}

/// What stays refused, one located diagnostic each: two indexes on a pointer, a pointer moved by
/// a non-integer, arithmetic other than `+` / `-` on a pointer, the sum of two pointers, a
/// pointer to a structure holding a pointer stored into a `POINTER TO BYTE` (bytes written
/// through it could make a pointer), a pointer to a function block instance converted.
#[test]
fn what_pointer_arithmetic_still_refuses_is_located() {
    let src = "TYPE Node : STRUCT next : POINTER TO INT; v : INT; END_STRUCT; END_TYPE\n\
FUNCTION_BLOCK Fb\nVAR x : INT; END_VAR\nx := x + 1;\nEND_FUNCTION_BLOCK\n\
PROGRAM Main\nVAR\n  a : ARRAY[0..3] OF INT;\n  p : POINTER TO INT;\n  q : POINTER TO INT;\n  \
n : Node;\n  pb : POINTER TO BYTE;\n  f : Fb;\n  pi : POINTER TO INT;\n  d : DINT;\nEND_VAR\n\
p := ADR(a);\nq := p;\nd := p[1, 2];\np := p + 1.5;\np := p * 2;\nd := p + q;\npb := ADR(n);\npi := ADR(f);\nEND_PROGRAM\n";
    assert_eq!(
        rejected_heads("r.st", src),
        [
            "r.st:19:6: error[E1021]: `p` is REF_TO INT: a pointer takes one index",
            "r.st:20:10: error[E1004]: ADD of REF_TO INT and a real literal: a pointer moves by an integer number of bytes",
            "r.st:21:6: error[E0305]: `MUL` on a reference (REF_TO INT): only a byte count may be added to or subtracted from a pointer",
            "r.st:22:10: error[E1004]: ADD of REF_TO INT and REF_TO INT: a pointer moves by an integer number of bytes",
            "r.st:23:1: error[E1006]: cannot store REF_TO Node into REF_TO BYTE",
            "r.st:24:1: error[E1006]: cannot store REF_TO Fb into REF_TO INT",
        ]
    );
}

/// The C of the four programs compiles with `-std=c99 -Wall -Wextra -Werror -pedantic` (through
/// the generated Makefile, which keeps `-fno-strict-aliasing`), and every access through a
/// pointer goes through the checked `ladderc_deref`.
#[test]
fn pointer_c_is_warning_free() {
    for name in [
        "poly_sort.st",
        "pointer_step.st",
        "pointer_casts.st",
        "pointer_faults.st",
    ] {
        let (dir, c) =
            common::build_and_make(&fixture(name), "-Wall -Wextra -Werror -pedantic -O1");
        assert!(c.contains("ladderc_deref("), "{name}");
        let make = std::fs::read_to_string(dir.path().join("out/Makefile")).unwrap();
        assert!(make.contains("-fno-strict-aliasing"), "{make}");
    }
}

/// pointer_mem.st (lead, after the pointer round): `MEMCPY(pD, pS, 100)` with `POINTER TO INT`
/// variables (TcUnit's and fisothemes' collections pass pointers, not `ADR(x)`; before: E1035 at
/// each) copies only the bytes from where `pD` points (`dst[1]`) to the end of `dst`, so `guard`
/// beside it keeps 77 and the clip is reported; `MEMSET` through a `REF_TO` clears `dst[0]`; a NULL
/// pointer touches nothing; `MEMCMP` of a pointer and `ADR` of the same array is 0.
#[test]
fn memory_functions_take_pointer_variables_bounded_by_their_variable() {
    let (trace, stderr) = run_traced(
        &fixture("pointer_mem.st"),
        1,
        "Main.dst[0],Main.dst[1],Main.dst[2],Main.dst[3],Main.guard[0],Main.n2,Main.cmp",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.dst[0],Main.dst[1],Main.dst[2],Main.dst[3],Main.guard[0],Main.n2,Main.cmp\n\
         0,0,0,1,2,3,77,1,0\n"
    );
    assert!(
        stderr.contains("memory function count beyond its variables (first: MEMCPY in Main"),
        "{stderr}"
    );
}

/// An address moved back by arithmetic (`ADR(a) - 2`), or a value that is no pointer, is still one
/// E1035 (a pointer moved on, `p + n`, is n bytes into its variable since round 23:
/// `unseen_projects_r23.rs`; a pointer variable moved back, `p - n`, is bounded as the pointer it
/// makes since round 24: `unseen_projects_r24.rs`).
#[test]
fn a_memory_function_on_pointer_arithmetic_is_e1035() {
    let heads = rejected_heads(
        "memarith.st",
        "PROGRAM Main\nVAR a : ARRAY[0..3] OF INT; p : POINTER TO INT; n : UDINT; k : UDINT; END_VAR\n\
         p := ADR(a);\nn := MEMSET(ADR(a) - 2, 0, 2);\nn := MEMSET(k, 0, 2);\nEND_PROGRAM\n",
    );
    assert_eq!(heads.len(), 2, "{heads:?}");
    assert!(
        heads[0].starts_with("memarith.st:4:13: error[E1035]: MEMSET: the variable this pointer points into cannot be known"),
        "{heads:?}"
    );
    assert!(
        heads[1].starts_with("memarith.st:5:13: error[E1035]"),
        "{heads:?}"
    );
}
