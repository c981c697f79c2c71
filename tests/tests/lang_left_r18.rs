//! Issue #13, round 18 (helper `stleft`): the ST / CODESYS / TwinCAT language items the last closing
//! note left, each through `ladderc run` on fixtures written here
//! (`tests/tests/fixtures/lang_left_r18/`, see its README for the public projects they reproduce):
//! - **`SIZEOF(T)` and `SIZEOF(v)` in constant expressions** (array bounds, string lengths, `VAR
//!   CONSTANT` values; TcUnit's `ARRAY[0..((N * (SIZEOF(ST_ADSLogStringMessage) + K)) - 1)] OF
//!   BYTE`): the bytes of the type in the C ladderc generates, computed while the declarations are
//!   read (`crates/il-frontend/src/type_sizes.rs`), the same number as the run-time `SIZEOF` (C's
//!   `sizeof`) for structures with padding, a structure that EXTENDS another, a union, strings,
//!   pointers, enumerations and arrays, types of another file in any order. A function block, an
//!   unknown type and another call are one E0022 each saying why. Before: E0011 at the `(`.
//! - **An ANY input's `.pValue`** (CODESYS/TwinCAT `__SYSTEM.AnyType`): a `POINTER TO BYTE` to the
//!   argument's bytes, bounded by the argument (ladderc's bounded pointers), so `In.pValue[i]`,
//!   `MEMCPY(ADR(buf), In.pValue, In.diSize)`, `MEMSET(In.pValue, 0, In.diSize)` and byte loops
//!   read and write the caller's variable, and any index outside it reads 0 and drops the write
//!   (clean under `--sanitize`). A function whose body reads `.pValue` gets a third hidden input
//!   `In__PVALUE`, given `ADR(x)` by each call. A literal or expression argument stays E1068 (it has
//!   no storage), a variable that has no address for the whole run (a FUNCTION's variable, a
//!   VAR_TEMP) E0305, a variable whose type holds a reference or an FB instance E1068. Before:
//!   E1068 at `.pValue`.
//! - **ANY inputs of METHODs** (as a FUNCTION's: `.diSize`, `.TypeClass`, `.pValue`), called
//!   through an instance (`rec.Record(3, w)`, formal or positional), inside the block (`Record(1,
//!   n)`, `THIS^.Record(...)`), and an ANY input **passed on** to another ANY input (a function's
//!   or a method's: its size, class and address go with it; a narrower family is E1068). Before:
//!   E1003 "unknown type `ANY`" in a method, E1068 for an input passed on.
//! - **A VAR_INST structured initial value of several fields** computed from the instance
//!   (`cfg : ST_Cfg := (b := THIS^.x, a := 1, c := 2.5, d := THIS^.y * 2);`, an instance's several
//!   inputs `(nIn := THIS^.x, nScale := 10)`): the computed fields are assigned once per instance,
//!   the constant ones stay the declaration's. Two computed fields next to each other are one
//!   E1075 (no room to write the assignment in place). Before: E0001 at each `^`.
//! - **A string literal over several lines** in a declaration (`s : STRING(500) := 'User-Agent:
//!   X<line break>Accept: */*';`, Keiji01/TwinCAT3's `FB_TestHTTP_HeaderAuth`): IEC 61131-3 has no
//!   line break in a string literal (it is written `$N`), so it stays one E0003, but the literal
//!   now ends at its closing quote (when that quote ends the declaration or statement, within 64
//!   lines) and the rest of the file is read as written. Before: E0003 and a cascade (31 error
//!   lines on that file, 2 after).
//! - **FB_init arguments on a METHOD's own instances** (`p : Randomizer(_low, _low + nWidth);` in
//!   a method's VAR, stefanbesler/struckig's tests write 17 of them): CODESYS creates such an
//!   instance again at each call, so the method starts with its `FB_init(TRUE, FALSE, args)` (after
//!   the initial values computed before the declaration), formal or positional arguments. Before:
//!   E0329 "this instance of `Randomizer` is not one ladderc initialises". A type without FB_init
//!   stays E0329, now saying that the instance is a METHOD's.
//! - **VAR_STAT in a METHOD** (CODESYS "VAR_STAT": in a method, one copy per method shared by all
//!   the block's instances, kept between calls, initialised once): the global
//!   `__STAT_<BLOCK>___M_<METHOD>_<NAME>`, in a `.st` block, a TwinCAT `<Method>` and a method file
//!   of its own (`Block.Method.st`). Before: E1067 (read as VAR). A PROPERTY accessor's VAR_STAT
//!   stays E1067.

mod common;
use common::{check_files, column, ladderc};
use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/lang_left_r18")
        .join(name)
}

/// `ladderc run FILES --cycles N --sanitize --trace - --watch WATCH`: the trace; asserts exit 0 and
/// no sanitizer report.
fn run_files(files: &[PathBuf], cycles: u32, watch: &str) -> String {
    common::run_stimulated_files(files, &[], cycles, "", watch).0
}

// ------------------------------------------------------------------ 1. SIZEOF in constants

/// sizeof/: `Main.st` measures the types of `Types.st` (given after it, or before) in `VAR CONSTANT`
/// values and array bounds, and each constant is compared with the run-time `SIZEOF` of a variable
/// of that type: `cX` (the constant) equals `rX` (C's `sizeof`) for each. The numbers are the
/// README's memory model on a 64-bit host: `ST_Record` EXTENDS `ST_Header` (LREAL, BYTE) with one
/// BYTE more, flattened: 16; `ST_LogMessage` DWORD + two STRINGs of 258: 520, so TcUnit's ring
/// buffer of 4 messages of 520 + 4 bytes is 2096.
#[test]
fn sizeof_in_constant_expressions_is_the_run_time_size() {
    let names = [
        "Record", "Mixed", "Raw", "Samples", "Mode", "Lreal", "String", "Buffer", "Copy", "Ring",
    ];
    let watch: Vec<String> = names
        .iter()
        .flat_map(|n| [format!("Main.c{n}"), format!("Main.r{n}")])
        .collect();
    for files in [["Main.st", "Types.st"], ["Types.st", "Main.st"]] {
        let files: Vec<PathBuf> = files
            .iter()
            .map(|f| fixture(&format!("sizeof/{f}")))
            .collect();
        let trace = run_files(&files, 1, &watch.join(","));
        for n in names {
            let (c, r) = (
                column(&trace, &format!("Main.c{n}")),
                column(&trace, &format!("Main.r{n}")),
            );
            assert_eq!(c, r, "{n}: the constant and the run-time SIZEOF differ");
        }
        let sizes: Vec<f64> = names
            .iter()
            .map(|n| column(&trace, &format!("Main.c{n}"))[0])
            .collect();
        if cfg!(target_pointer_width = "64") {
            assert_eq!(
                sizes,
                [16., 832., 8., 40., 4., 16., 258., 832., 832., 2096.],
                "{trace}"
            );
        }
    }
}

/// One file: a type declared after the array its size bounds, a string length, and a constant
/// computed from a SIZEOF constant.
#[test]
fn sizeof_of_a_type_declared_later_in_the_same_file() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("later.st");
    std::fs::write(
        &src,
        "PROGRAM Main\nVAR CONSTANT\n    N_PAIR : UDINT := SIZEOF(ST_Pair);\n    N_TWICE : UDINT := N_PAIR * 2;\nEND_VAR\n\
         VAR\n    aPairs : ARRAY[1..N_TWICE] OF BYTE;\n    sName : STRING(SIZEOF(ST_Pair));\n    nLen : INT;\n    nPairs, nPair : UDINT;\n    pair : ST_Pair;\nEND_VAR\n\
         sName := 'abcdefghijklmnopqrstuvwxyz';\nnLen := LEN(sName);\nnPairs := SIZEOF(aPairs);\nnPair := SIZEOF(pair);\nEND_PROGRAM\n\n\
         TYPE ST_Pair :\nSTRUCT\n    a : INT;\n    b : DINT;\nEND_STRUCT;\nEND_TYPE\n",
    )
    .unwrap();
    let trace = run_files(&[src], 1, "Main.nLen,Main.nPairs,Main.nPair");
    // INT, 2 bytes of padding, DINT: 8 bytes; a STRING(8) keeps 8 characters
    assert_eq!(column(&trace, "Main.nPair"), [8.]);
    assert_eq!(column(&trace, "Main.nPairs"), [16.]);
    assert_eq!(column(&trace, "Main.nLen"), [8.]);
}

/// A function block's instance, an unknown type and another call have no size in a constant
/// expression: one E0022 each, saying why.
#[test]
fn sizeof_without_a_value_is_one_located_error_each() {
    let src = "FUNCTION_BLOCK FB_Worker\nVAR\n    n : INT;\nEND_VAR\nn := n + 1;\nEND_FUNCTION_BLOCK\n\n\
               PROGRAM Main\nVAR\n    aBlock : ARRAY[0..SIZEOF(FB_Worker)] OF BYTE;\n    aNothing : ARRAY[0..SIZEOF(ST_Missing) - 1] OF BYTE;\n    aCall : ARRAY[0..LEN(x)] OF BYTE;\n    n : UDINT;\nEND_VAR\nn := 1;\nEND_PROGRAM\n";
    let (code, lines) = check_files(&[("bad.st", src)]);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        [
            "bad.st:10:23: error[E0022]: constant expression `SIZEOF(FB_Worker)`: `FB_Worker` is a function block: the size of its instance is known in code (`SIZEOF(x)` in a body), not while declarations are read",
            "bad.st:11:25: error[E0022]: constant expression `SIZEOF(ST_Missing) - 1`: the size of `ST_Missing` is not known (no data type or variable of that name declared before, in this file or another given file)",
            "bad.st:12:22: error[E0022]: constant expression `LEN(x)`: `LEN(...)` is a call: only standard numeric functions of constants (SQRT, LOG, MAX, TO_REAL, ...) and SIZEOF are computed in a constant expression",
        ]
    );
}

// ------------------------------------------------------------------ 2. an ANY input's .pValue

/// any_pvalue.st: `F_Checksum` adds the bytes of its ANY argument through `Data.pValue[i]` for i
/// below `Data.diSize` (a DINT 16#01020304: 10; an ARRAY OF INT [1, 2, 3, 4]: 10; one element, 4;
/// a STRING 'AB': ladderc's IEC_STRING, a 2-byte length then the characters: 2 + 65 + 66 = 133);
/// `F_CopyOut` MEMCPYs its argument into a local buffer and reads one byte at `nIndex`; `F_Poke`
/// writes a byte of the caller's UINT through `.pValue`; `F_Clear` MEMSETs the caller's array
/// (cycle 2). Indexes -1, 2 (past the UINT's 2 bytes) and the largest DINT read 0 and drop the
/// write, named once at the end of the run.
#[test]
fn an_any_inputs_pvalue_is_a_bounded_pointer_to_the_argument() {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n1,Main.nIndex,-1\n2,Main.nIndex,2\n3,Main.nIndex,2147483647\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture("any_pvalue.st"))
        .args(["--cycles", "4", "--sanitize", "--stimulus"])
        .arg(&stim)
        .args([
            "--trace",
            "-",
            "--watch",
            "Main.nSumW,Main.nSumArr,Main.nSumElem,Main.nSumText,Main.nCopy,Main.nFar,Main.n,Main.xCleared,Main.arr[1]",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("Sanitizer"), "{stderr}");
    // no W1425: the hidden address is a POINTER TO BYTE to any argument by design
    assert!(!stderr.contains("warning"), "{stderr}");
    assert!(
        stderr.contains("runtime: pointer outside its variable dereferenced (first: Src.pValue[nIndex] in F_CopyOut at any_pvalue.st:34; zero read, write dropped)"),
        "{stderr}"
    );
    let trace = String::from_utf8_lossy(&out.stdout);
    assert_eq!(column(&trace, "Main.nSumW"), [10., 10., 10., 10.]);
    assert_eq!(column(&trace, "Main.nSumArr"), [10., 10., 10., 0.]);
    assert_eq!(column(&trace, "Main.nSumElem"), [4., 4., 4., 0.]);
    assert_eq!(column(&trace, "Main.nSumText"), [133., 133., 133., 133.]);
    // 16#0A0B: bytes 16#0B, 16#0A; the first scan's F_Poke makes it 16#0AFF
    assert_eq!(
        column(&trace, "Main.nCopy"),
        [11010., 255010., 255010., 255010.]
    );
    assert_eq!(
        column(&trace, "Main.nFar"),
        [11011., 255000., 255000., 255000.]
    );
    assert_eq!(column(&trace, "Main.n"), [2815., 2815., 2815., 2815.]);
    assert_eq!(column(&trace, "Main.xCleared"), [0., 0., 1., 1.]);
    assert_eq!(column(&trace, "Main.arr[1]"), [2., 2., 0., 0.]);
}

/// What `.pValue` cannot point into is one located error each: a block's VAR_IN_OUT may stand for
/// a temporary of its caller (E0305), a literal has no storage (E1068), a variable holding a
/// pointer or an FB instance could be forged through its bytes (E1068). A FUNCTION's own variable
/// given to an ANY input is its address during the call, as `ADR` of it is since round 27
/// (CODESYS; before: E0305), and so is a VAR_TEMP since round 29 (`tc_oop_r29_run.rs`; before:
/// E0305 "a VAR_TEMP variable lives for one call").
#[test]
fn pvalue_of_an_argument_without_lasting_storage_is_refused() {
    let f = "FUNCTION F_Sum : DINT\nVAR_INPUT\n    Data : ANY;\nEND_VAR\nF_Sum := BYTE_TO_DINT(Data.pValue[0]);\nEND_FUNCTION\n\n";
    let (code, lines) = check_files(&[(
        "temp.st",
        &format!(
            "{f}FUNCTION F_Outer : DINT\nVAR\n    nLocal : DINT := 7;\nEND_VAR\nF_Outer := F_Sum(nLocal);\nEND_FUNCTION\n\n\
             PROGRAM Main\nVAR\n    b : DINT;\nEND_VAR\nVAR_TEMP\n    t : INT;\nEND_VAR\nb := F_Sum(t) + F_Outer();\nEND_PROGRAM\n\n\
             FUNCTION_BLOCK FB_InOut\nVAR_IN_OUT\n    io : INT;\nEND_VAR\nVAR\n    s : DINT;\nEND_VAR\ns := F_Sum(io);\nEND_FUNCTION_BLOCK\n"
        ),
    )]);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        [
            "temp.st:32:12: error[E0305]: a reference to `io` is not allowed: a VAR_IN_OUT may stand for a temporary variable of the caller",
        ]
    );
    let (code, lines) = check_files(&[(
        "literal.st",
        &format!("{f}PROGRAM Main\nVAR\n    a : DINT;\nEND_VAR\na := F_Sum(5);\nEND_PROGRAM\n"),
    )]);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        ["literal.st:12:12: error[E1068]: the ANY input `Data` of `F_Sum` takes a variable"]
    );
    // bytes written through `.pValue` could forge a pointer or a block's own members
    let (code, lines) = check_files(&[(
        "refs.st",
        &format!("TYPE ST_P : STRUCT p : POINTER TO INT; END_STRUCT; END_TYPE\n{f}PROGRAM Main\nVAR\n    s : ST_P;\n    t : TON;\n    b : DINT;\nEND_VAR\nb := F_Sum(s) + F_Sum(t);\nEND_PROGRAM\n"),
    )]);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        [
            "refs.st:15:12: error[E1068]: `Data.pValue` of `F_Sum` cannot point into a ST_P: it holds a reference or a function block instance",
            "refs.st:15:23: error[E1068]: `Data.pValue` of `F_Sum` cannot point into a TON: it holds a reference or a function block instance",
        ]
    );
}

// ------------------------------------------------------------------ 3. VAR_STAT in a METHOD

/// method_stat/: two instances of a TwinCAT block draw tickets from their method's VAR_STAT
/// `nTicket` (initialised once to 1000): each call adds one whichever instance calls; the method's
/// VAR `nLocal` starts at 5 at each call, the block's `nOwnCalls` counts per instance. Station B
/// draws a second ticket from cycle 1 on. The static array `aHistory` keeps the tickets by number
/// MOD 4.
#[test]
fn var_stat_of_a_method_is_shared_by_every_instance() {
    let files = [
        fixture("method_stat/FB_Station.TcPOU"),
        fixture("method_stat/Main.st"),
    ];
    let trace = run_files(
        &files,
        3,
        "Main.nA,Main.nB,__STAT_FB_STATION___M_NEXTTICKET_NTICKET,__STAT_FB_STATION___M_NEXTTICKET_AHISTORY[1]",
    );
    assert_eq!(column(&trace, "Main.nA"), [1001601., 1003602., 1006603.]);
    assert_eq!(column(&trace, "Main.nB"), [1002601., 1005603., 1008605.]);
    assert_eq!(
        column(&trace, "__STAT_FB_STATION___M_NEXTTICKET_NTICKET"),
        [1002., 1005., 1008.]
    );
    assert_eq!(
        column(&trace, "__STAT_FB_STATION___M_NEXTTICKET_AHISTORY[1]"),
        [1001., 1005., 1005.]
    );
}

/// The same in a method exported to a file of its own (`Counter.Next.st`, CODESYS export scripts).
#[test]
fn var_stat_of_a_method_in_a_file_of_its_own() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    let files = [
        write(
            "Counter.st",
            "FUNCTION_BLOCK Counter\nVAR\n    n : INT;\nEND_VAR\nEND_FUNCTION_BLOCK\n",
        ),
        write(
            "Counter.Next.st",
            "METHOD Next : INT\nVAR_STAT\n    nCalls : INT;\nEND_VAR\nnCalls := nCalls + 1;\nNext := nCalls;\n",
        ),
        write(
            "Main.st",
            "PROGRAM Main\nVAR\n    a, b : Counter;\n    ra, rb : INT;\nEND_VAR\nra := a.Next();\nrb := b.Next();\nEND_PROGRAM\n",
        ),
    ];
    let trace = run_files(&files, 2, "Main.ra,Main.rb");
    assert_eq!(column(&trace, "Main.ra"), [1., 3.]);
    assert_eq!(column(&trace, "Main.rb"), [2., 4.]);
}

// ------------------------------------------------------------------ 3. ANY inputs of METHODs

/// any_method.st: `FB_Recorder.Record(nTag, Value : ANY)` keeps the argument's size, class and
/// byte sum (through `F_ByteSum(Value)`, the ANY input passed on with its address):
/// `rec.Record(3, w)` of a DINT is 3000 + 4 * 10 + 1 (the first entry); `rec.Record(Value :=
/// aBytes, nTag := 4)` of an ARRAY[0..2] OF BYTE is 4000 + 30 + 2 (class TYPE_ARRAY, 26);
/// `RecordTwice(n)` of a UINT calls `Record(1, Number)` and `THIS^.Record(nTag := 2, Value :=
/// Number)` inside the block: 1023 + 2024, the byte sum 16#0B + 16#0A = 21; `F_Forward(w)` of a
/// function passes its ANY_NUM input on to `F_ByteSum`'s ANY: 10 * 10 + 4.
#[test]
fn any_inputs_of_methods_and_any_inputs_passed_on() {
    let trace = run_files(
        &[fixture("any_method.st")],
        2,
        "Main.nA,Main.nB,Main.nLastClass,Main.nC,Main.nD,Main.rec.nLastSum,Main.rec.nEntries",
    );
    assert_eq!(column(&trace, "Main.nA"), [3041., 3045.]);
    assert_eq!(column(&trace, "Main.nB"), [4033., 4037.]);
    assert_eq!(column(&trace, "Main.nLastClass"), [26., 26.]);
    assert_eq!(column(&trace, "Main.nC"), [3047., 3055.]);
    assert_eq!(column(&trace, "Main.nD"), [104., 104.]);
    assert_eq!(column(&trace, "Main.rec.nLastSum"), [21., 21.]);
    assert_eq!(column(&trace, "Main.rec.nEntries"), [4., 8.]);
}

/// An ANY input passed on to a narrower family, and a literal given to a method's ANY input: one
/// E1068 each.
#[test]
fn any_input_passed_on_to_a_narrower_family_is_e1068() {
    let (code, lines) = check_files(&[(
        "fwd.st",
        "FUNCTION F_Int : DINT\nVAR_INPUT\n    i : ANY_INT;\nEND_VAR\nF_Int := i.diSize;\nEND_FUNCTION\n\
         FUNCTION F_Num : DINT\nVAR_INPUT\n    x : ANY_NUM;\nEND_VAR\nF_Num := F_Int(x);\nEND_FUNCTION\n\
         FUNCTION_BLOCK FB_A\nMETHOD M : DINT\nVAR_INPUT\n    v : ANY;\nEND_VAR\nM := v.diSize;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\
         PROGRAM Main\nVAR\n    a : FB_A;\n    r : DINT;\nEND_VAR\nr := F_Num(r) + a.M(5);\nEND_PROGRAM\n",
    )]);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        [
            "fwd.st:11:16: error[E1068]: the input `i` of `F_Int` is ANY_INT: `x` (ANY_NUM) may hold a type it does not take",
            "fwd.st:26:21: error[E1068]: the ANY input `V` of `FB_A.M` takes a variable",
        ]
    );
}

// ------------------------------------------------------------------ 5. VAR_INST of several fields

/// var_inst_fields.st: `cfg`'s `b` and `d` are computed from the instance (7 and 3 * 2), `a` and
/// `c` are constants; the instance `child` gets `nIn` from the instance and `nScale` 10; all once
/// per instance (the second call sees `a` incremented, `b` not computed again although `x`
/// changed). `other` starts with `x := 20`.
#[test]
fn var_inst_structured_initial_value_of_several_fields() {
    let trace = run_files(&[fixture("var_inst_fields.st")], 2, "Main.r,Main.rOther");
    assert_eq!(column(&trace, "Main.r"), [107002708.5, 107003708.5]);
    assert_eq!(column(&trace, "Main.rOther"), [120004008.5, 120005008.5]);
}

/// Two computed fields next to each other: one E1075 at the second, nothing else.
#[test]
fn two_computed_fields_next_to_each_other_are_one_e1075() {
    let (code, lines) = check_files(&[(
        "pair.st",
        "TYPE ST_Pair : STRUCT a : INT; b : INT; END_STRUCT; END_TYPE\n\
         FUNCTION_BLOCK FB_X\nVAR\n    x : INT := 7;\n    y : INT := 3;\nEND_VAR\n\
         METHOD Get : INT\nVAR_INST\n    pair : ST_Pair := (a := THIS^.x, b := THIS^.y);\nEND_VAR\nGet := pair.a + pair.b;\nEND_METHOD\nEND_FUNCTION_BLOCK\n",
    )]);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        ["pair.st:9:38: error[E1075]: this field's initial value is computed next to another one: ladderc cannot place its assignment"]
    );
}

// ------------------------------------------------------------------ 6. a string over several lines

/// One E0003 at the string written over three lines (its `*/` is no comment), then the file is
/// read as written: the next error is the one of line 8.
#[test]
fn a_string_over_several_lines_is_one_error_and_the_file_goes_on() {
    let (code, lines) = check_files(&[(
        "header.st",
        "PROGRAM Main\nVAR\n    n : INT;\n    sHeader : STRING(200) := 'User-Agent: X\nContent-Type: application/json\nAccept: */*';\n\
         \x20   m : INT := 5;\n    k : INT := 1 2;\nEND_VAR\nn := m + LEN(sHeader);\nEND_PROGRAM\n",
    )]);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        [
            "header.st:4:30: error[E0003]: string is not closed on its line",
            "header.st:8:18: error[E0022]: an operator is missing in this constant expression",
        ]
    );
    // a quote forgotten on one line is not read into the next statement
    let (code, lines) = check_files(&[(
        "forgot.st",
        "PROGRAM Main\nVAR\n    s : STRING := 'abc;\n    t : STRING := 'def';\nEND_VAR\nEND_PROGRAM\n",
    )]);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines.first().map(String::as_str),
        Some("forgot.st:3:19: error[E0003]: string is not closed on its line")
    );
}

// ------------------------------------------------------------------ 4. FB_init on a method's instances

/// method_fb_init.st: `Draw(nWidth)` declares `p : Randomizer(_low, _low + nWidth)` (positional,
/// from the block's variable and the method's input) and `q : Randomizer(nMin := 100, nMax :=
/// 101)`; both are created again at each call: `p` starts at 10 and steps by 3 within 10..10 +
/// nWidth, `q` wraps to 101, and `p.nInits` is 1 at every call (a fresh instance, one FB_init).
#[test]
fn fb_init_arguments_of_a_methods_own_instances_run_at_each_call() {
    let trace = run_files(
        &[fixture("method_fb_init.st")],
        2,
        "Main.nFirst,Main.nSecond,Main.test.nTotal",
    );
    assert_eq!(column(&trace, "Main.nFirst"), [1013101., 1013101.]);
    assert_eq!(column(&trace, "Main.nSecond"), [1011101., 1011101.]);
    assert_eq!(column(&trace, "Main.test.nTotal"), [2., 4.]);
}

/// A method's instance of a block without FB_init given arguments: E0329 saying so.
#[test]
fn fb_init_arguments_for_a_block_without_fb_init_stay_e0329() {
    let (code, lines) = check_files(&[(
        "nofbinit.st",
        "FUNCTION_BLOCK FB_Plain\nVAR\n    n : INT;\nEND_VAR\nEND_FUNCTION_BLOCK\n\
         FUNCTION_BLOCK FB_User\nMETHOD M : INT\nVAR\n    p : FB_Plain(5);\nEND_VAR\nM := p.n;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\
         PROGRAM Main\nVAR\n    u : FB_User;\n    r : INT;\nEND_VAR\nr := u.M();\nEND_PROGRAM\n",
    )]);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        ["nofbinit.st:9:17: error[E0329]: `FB_Plain` has no FB_init method to take these arguments"]
    );
}

/// any_method_override.st: a method with an ANY input called through `pA^` (a `POINTER TO FB_A`,
/// positional and formal) and on an array element: the call passes the size, class and address
/// as on an instance (was: no rewrite, the argument 7 landing in the size input). `pA` pointing to
/// an `FB_B` runs B's override, which reads the argument's first byte through `.pValue`
/// (7 -> 4 * 100 + 7; INT 5 -> 2 * 100 + 5). An ANY input given by position in a call that also
/// names an output (`b.Probe(i, big => bBig)`, and `THIS^.Probe(w, big => Forward)` passing an ANY
/// input on: fisothemes' form, was E1068 25 times there) reaches the input.
#[test]
fn a_methods_any_input_through_a_pointer_to_its_base_and_an_array_element() {
    let trace = run_files(
        &[fixture("any_method_override.st")],
        1,
        "Main.rA,Main.rB,Main.rViaA,Main.rViaB,Main.rFormal,Main.rElem,Main.rMixed,Main.bBig,Main.bFwdD,Main.bFwdI",
    );
    assert_eq!(
        trace.lines().nth(1),
        Some("0,0,4,407,4,407,205,205,2,0,1,0"),
        "{trace}"
    );
}

/// An INTERFACE's method with an ANY input: the block implementing it matches it (both split into
/// the same hidden inputs; was E0335 at every such method of fisothemes' collections after the
/// merge), a call on the instance runs, and a call through the interface is one E1068 (its
/// arguments would land in the hidden inputs), never compiled.
#[test]
fn a_methods_any_input_through_an_interface_is_refused() {
    let src = "INTERFACE I_Bag\nMETHOD Contains : BOOL\nVAR_INPUT\n    Item : ANY;\nEND_VAR\nEND_METHOD\nEND_INTERFACE\n\
FUNCTION_BLOCK FB_Bag IMPLEMENTS I_Bag\nMETHOD Contains : BOOL\nVAR_INPUT\n    Item : ANY;\nEND_VAR\nContains := Item.diSize = 4;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\
PROGRAM Main\nVAR\n    bag : FB_Bag;\n    itf : I_Bag;\n    d : DINT;\n    b : BOOL;\nEND_VAR\nitf := bag;\nb := itf.Contains(d);\nEND_PROGRAM\n";
    let (code, lines) = check_files(&[("bag.st", src)]);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "bag.st:24:6: error[E1068]: a method with ANY inputs called through a place"
        ),
        "{lines:?}"
    );
    let on_instance = src.replace("b := itf.Contains(d);", "d := 9;\nb := bag.Contains(d);");
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("bag.st");
    std::fs::write(&file, on_instance).unwrap();
    let trace = run_files(&[file], 1, "Main.b");
    assert_eq!(trace.lines().nth(1), Some("0,0,1"), "{trace}");
}
