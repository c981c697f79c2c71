//! Issue #13, twelfth round (helper `small3`): small constructs that stopped real TwinCAT and
//! CODESYS projects, each through `ladderc run` on fixtures written here
//! (`tests/tests/fixtures/lang_left_r12/`):
//! - **REAL, LREAL and TIME constant expressions** in declarations (`EPS : LREAL := 16 * 2.2E-016;`,
//!   `C2 : REAL := GVL_Const.C1 / 2;`, `T_MAX : TIME := T_BASE + T#500MS;`, `LREAL#1.5 / 3`), also
//!   naming the constants of another file's global list, qualified or not. Before: E0011 at the
//!   first real or duration operand.
//! - **Empty formal arguments** (`Add3(a := , b := 1)`, `t(IN := , PT := T#30MS)`, IL `CAL a(step
//!   := , on_ := TRUE)`), as TwinCAT and CODESYS editors write an unconnected pin: the input is left
//!   out of the call (a block's keeps its value, a function's takes its initial value). Before:
//!   E0107 (ST), E0011 (IL). An in-out left unconnected, empty or omitted, is E1033 (CODESYS's
//!   C0039); before, the block read through a null pointer at run time.
//! - **`SIZEOF(x)` / `SIZEOF(T)`** (CODESYS, TwinCAT) in ST: C's `sizeof` of the variable or type in
//!   the generated C, typed by its context as an integer literal. Before: E1019.
//! - **`MEMCPY`, `MEMMOVE`, `MEMSET`, `MEMCMP`** (Tc2_System; CODESYS `SysMemCpy` ...) on
//!   variables named by `ADR(x)`: the count is clipped at run time to the bytes of the variables
//!   (from an array element to the end of its array) and a clip is reported at the end of the run;
//!   a pointer whose variable cannot be known is E1035. Before: E1003 (unknown function).
//! - **`ADR(x)` as the initial value of a `POINTER TO` / `REF_TO` variable** (`p : POINTER TO INT
//!   := ADR(a);`, `ADR(arr[3])`, `ADR(pair.y)`) of a variable of the same POU: the C initialises the
//!   pointer with the address. Before: E0305.
//! - **A comma after the last formal argument** (`fb(a := x, q => y, );`) and **an empty
//!   declaration** (`x : LREAL := 630.0;;`), as TwinCAT accepts them. Before: E3106 + E0107, E0011.
//! - **`ON`, `WITH` and `TASK` as variable names** (IEC 61131-3 reserves them for textual
//!   configurations only; CODESYS and TwinCAT accept them): warning W1418. Before: E1031.

mod common;
use common::{check_text, run_traced, run_traced_files, write_file};
use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/lang_left_r12")
        .join(name)
}

// ------------------------------------------------------------------ 1. constant expressions

/// GVL_Const.st: C1 : REAL := 3 (the REAL 3.0), EPS := 16 * 2.2E-016, T_MAX := T_BASE + T#500MS,
/// HALF := LREAL#1.5 / 3, N := 4. Main.st: C2 := GVL_Const.C1 / 2 = 1.5 (a REAL division: C1 is
/// REAL), C3 := C2 * N - 0.5 = 5.5, T_STEP := GVL_Const.T_MAX / 3 * 2 = T#1S, T_SHORT := -T#100MS +
/// T_STEP * 0.2 = T#100MS (the sign binds tighter than +), which times the TON: Q after 100 ms.
#[test]
fn real_lreal_and_time_constant_expressions_run_across_global_lists() {
    let files = [fixture("consts/GVL_Const.st"), fixture("consts/Main.st")];
    let files: Vec<&Path> = files.iter().map(PathBuf::as_path).collect();
    let (trace, _) = run_traced_files(
        &files,
        11,
        "Main.x,Main.q,Main.e,Main.h,Main.tAcc,Main.timer.PT,Main.done",
    );
    let lines: Vec<&str> = trace.lines().collect();
    assert_eq!(
        lines[0],
        "cycle,time_ms,Main.x,Main.q,Main.e,Main.h,Main.tAcc,Main.timer.PT,Main.done"
    );
    assert_eq!(lines[1], "0,0,7,3,3.52e-15,2,T#1000ms,T#100ms,0");
    assert_eq!(lines[2], "1,10,8.5,3,3.52e-15,2,T#2000ms,T#100ms,0");
    assert_eq!(lines[10], "9,90,20.5,3,3.52e-15,2,T#10000ms,T#100ms,0");
    assert_eq!(lines[11], "10,100,22,3,3.52e-15,2,T#11000ms,T#100ms,1");
}

/// Integer constant expressions keep integer arithmetic, and a leading sign applies to its operand
/// only: `-N + 1` = -3, `-(N + 1) * 2` = -10, `ARRAY[-N..-N+1]` has indexes -4 and -3.
#[test]
fn a_sign_in_a_constant_expression_binds_to_its_operand() {
    let dir = tempfile::tempdir().unwrap();
    let f = write_file(
        dir.path(),
        "neg.st",
        "PROGRAM Main\nVAR CONSTANT N : INT := 4; END_VAR\n\
         VAR a : INT := -N + 1; b : INT := -(N + 1) * 2; c : ARRAY[-N..-N+1] OF INT; END_VAR\n\
         c[-3] := a + b;\nEND_PROGRAM\n",
    );
    let (trace, _) = run_traced(&f, 1, "Main.a,Main.b,Main.c[-3]");
    assert_eq!(
        trace,
        "cycle,time_ms,Main.a,Main.b,Main.c[-3]\n0,0,-3,-10,-13\n"
    );
}

/// What has no value is one located E0022 each: a duration times a duration, a REAL constant as an
/// array bound (bounds take integers), a date in an expression.
#[test]
fn constant_expressions_without_a_value_are_one_located_e0022_each() {
    let src = "PROGRAM Main\nVAR CONSTANT\n  C1 : REAL := 2.5;\n  BAD : TIME := T#1S * T#2S;\n\
               END_VAR\nVAR a : ARRAY[1..C1] OF INT; d : TIME := D#2024-01-01 + T#1S; END_VAR\n\
               END_PROGRAM\n";
    let (code, lines) = check_text("e.st", src);
    assert_eq!(code, Some(1));
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split_once(" (hint").unwrap().0)
        .collect();
    assert_eq!(
        heads,
        vec![
            "e.st:4:17: error[E0022]: constant expression `T#1S * T#2S`: durations only add to and subtract from durations",
            "e.st:6:18: error[E0022]: constant expression `C1`: `C1` is not an integer constant",
            "e.st:6:42: error[E0022]: constant expression `D#2024-01-01 + T#1S`: only numbers and durations (T#...) make constant expressions",
        ]
    );
}

// ------------------------------------------------------------------ 5. configuration keywords as names

/// `ON` toggles each cycle and counts its TRUE cycles, in ST and in IL; `WITH` and `TASK` name
/// variables too. One W1418 at each declaration; a configuration's own `RESOURCE ... ON` and
/// `PROGRAM ... WITH` still read as keywords.
#[test]
fn on_with_and_task_name_variables_with_w1418() {
    let dir = tempfile::tempdir().unwrap();
    let st = write_file(
        dir.path(),
        "on.st",
        "PROGRAM Main\nVAR ON : BOOL; WITH : INT; task : INT; END_VAR\nON := NOT ON;\n\
         IF ON THEN WITH := WITH + 1; END_IF\ntask := WITH * 10;\nEND_PROGRAM\n",
    );
    let (trace, stderr) = run_traced(&st, 3, "Main.ON,Main.WITH,Main.task");
    assert_eq!(
        trace,
        "cycle,time_ms,Main.ON,Main.WITH,Main.task\n0,0,1,1,10\n1,10,0,1,10\n2,20,1,2,20\n"
    );
    assert!(
        stderr.contains(
            "on.st:2:5: warning[W1418]: `ON` is a keyword of IEC 61131-3 configurations (`RESOURCE r \
             ON cpu`): accepted as a variable name, as CODESYS and TwinCAT do"
        ),
        "{stderr}"
    );
    assert_eq!(stderr.matches("W1418").count(), 3, "{stderr}");
    let il = write_file(
        dir.path(),
        "on.il",
        "PROGRAM Main\nVAR ON : BOOL; n : INT; END_VAR\nLD ON\nSTN ON\nJMPCN skip\nLD n\nADD 1\n\
         ST n\nskip:\nEND_PROGRAM\n\
         CONFIGURATION Cell\nRESOURCE Cpu ON PLC\nTASK Fast (INTERVAL := T#10MS);\n\
         PROGRAM Inst WITH Fast : Main;\nEND_RESOURCE\nEND_CONFIGURATION\n",
    );
    let (trace, stderr) = run_traced(&il, 3, "Inst.ON,Inst.n");
    assert_eq!(
        trace,
        "cycle,time_ms,Inst.ON,Inst.n\n0,0,1,0\n1,10,0,1\n2,20,1,1\n"
    );
    assert_eq!(stderr.matches("W1418").count(), 1, "{stderr}");
}

// ------------------------------------------------------------------ 4. empty formal arguments

/// Add3(a := , b := r MOD 7, c := ): a and c take their initial values 10 and 100; the TON's
/// `IN :=` keeps the TRUE of its first call, so Q rises after 30 ms.
#[test]
fn empty_formal_arguments_leave_the_input_out_of_the_call_in_st() {
    let (trace, _) = run_traced(
        &fixture("empty_args.st"),
        5,
        "Main.r,Main.t.IN,Main.t.ET,Main.q",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.r,Main.t.IN,Main.t.ET,Main.q\n0,0,110,1,T#0ms,0\n1,10,115,1,T#10ms,0\n\
         2,20,113,1,T#20ms,0\n3,30,111,1,T#30ms,1\n4,40,116,1,T#30ms,1\n"
    );
}

/// IL: `CAL a(step := 2, on_ := TRUE)` once, then `CAL a(step := , on_ := TRUE)`: step keeps 2
/// (not its initial value 5), so total grows by 2 each cycle.
#[test]
fn empty_formal_arguments_leave_the_input_out_of_the_call_in_il() {
    let (trace, _) = run_traced(
        &fixture("empty_args.il"),
        3,
        "Main.a.total,Main.a.step,Main.r",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.a.total,Main.a.step,Main.r\n0,0,2,2,0\n1,10,4,2,4\n2,20,6,2,6\n"
    );
}

/// An in-out has no value to keep: left empty or omitted, it is one located E1033 per call.
#[test]
fn an_in_out_left_unconnected_is_e1033() {
    let fb = "FUNCTION_BLOCK Bump\nVAR_IN_OUT counter : INT; END_VAR\nVAR_INPUT step : INT := 1; END_VAR\n\
              counter := counter + step;\nEND_FUNCTION_BLOCK\n";
    let (code, lines) = check_text(
        "io.st",
        &format!(
            "{fb}PROGRAM Main\nVAR b : Bump; n : INT; END_VAR\nb(counter := , step := 2);\nb();\n\
             b(counter := n, step := );\nEND_PROGRAM\n"
        ),
    );
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        vec![
            "io.st:8:1: error[E1033]: VAR_IN_OUT `counter` of Bump is not connected in this call of `b` (hint: connect it to a variable in every call: `b(counter := ...)`)",
            "io.st:9:1: error[E1033]: VAR_IN_OUT `counter` of Bump is not connected in this call of `b` (hint: connect it to a variable in every call: `b(counter := ...)`)",
        ]
    );
    let (code, lines) = check_text(
        "io.il",
        &format!("{}PROGRAM Main\nVAR b : Bump; n : INT; END_VAR\nCAL b(counter := , step := 2)\nEND_PROGRAM\n", fb.replace("counter := counter + step;", "LD counter\nADD step\nST counter")),
    );
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("io.il:10:1: error[E1033]"),
        "{lines:?}"
    );
}

// ------------------------------------------------------------------ 2. SIZEOF

/// The CODESYS help's example (`SIZEOF` of ARRAY[0..4] OF INT into an INT: 10), the element count
/// `SIZEOF(a) / SIZEOF(a[0])`, a struct padded as C pads it (BOOL, LREAL, WORD: 24 bytes, by
/// variable and by type name, the latter into a USINT), elementary type names and a field (8 + 2 +
/// 1), a STRING[20] (an `IEC_STRING` of ladderc's memory model: 2 + 255 + 1 padding bytes = 258),
/// a two-dimensional array and one element (24 + 4).
#[test]
fn sizeof_gives_the_bytes_of_variables_and_types_in_the_generated_c() {
    let (trace, _) = run_traced(
        &fixture("sizeof.st"),
        1,
        "Main.nSize,Main.nElems,Main.nData,Main.nType,Main.nParts,Main.nText,Main.nGrid",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.nSize,Main.nElems,Main.nData,Main.nType,Main.nParts,Main.nText,\
         Main.nGrid\n0,0,10,5,24,24,11,258,28\n"
    );
}

/// An operand that is no variable or type name is one located E1034; an unknown name is E1001.
#[test]
fn sizeof_of_an_expression_is_e1034() {
    let (code, lines) = check_text(
        "s.st",
        "PROGRAM Main\nVAR n : UDINT; a : INT; END_VAR\nn := SIZEOF(a + 1);\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        vec!["s.st:3:6: error[E1034]: `SIZEOF` takes one variable or one type name (hint: write `SIZEOF(x)`, `SIZEOF(a[1])`, `SIZEOF(st.field)` or `SIZEOF(INT)`)"]
    );
    let (code, lines) = check_text(
        "u.st",
        "PROGRAM Main\nVAR n : UDINT; END_VAR\nn := SIZEOF(nothing);\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("u.st:3:13: error[E1001]: undeclared name `nothing`"),
        "{lines:?}"
    );
}

// ------------------------------------------------------------------ 3. MEMCPY and its kin

/// memory.st, each cycle: b := [1..10] + cycle; MEMSET fills a with 16#AA; MEMCPY of the 10 bytes
/// of b into a[5..9] is clipped to the 5 bytes left there (ok1 = 0, a[5..9] = b[0..4]); a struct
/// copied whole; SysMemCpy of b[2..5] into small (ok2 = 1); MEMCMP of the copied structs (0) and of
/// a[0] = 170 against b[0] (1); MEMMOVE of b[0..3] onto b[1..4] (overlapping: b[1] = b[0]). The
/// run is ASan/UBSan clean (`--sanitize`) and reports the clip once, naming its POU.
#[test]
fn memory_functions_are_bounded_by_their_variables() {
    let (trace, stderr) = run_traced(
        &fixture("memory.st"),
        2,
        "Main.a[0],Main.a[4],Main.a[5],Main.a[9],Main.ok1,Main.rec1.n,Main.rec1.r,Main.ok2,\
         Main.small[0],Main.small[3],Main.same,Main.diff,Main.b[0],Main.b[1],Main.b[4],Main.b[5]",
    );
    let lines: Vec<&str> = trace.lines().collect();
    assert_eq!(lines[1], "0,0,170,170,1,5,0,42,2.5,1,3,6,0,1,1,1,4,6");
    assert_eq!(lines[2], "1,10,170,170,2,6,0,43,2.5,1,4,7,0,1,2,2,5,7");
    assert!(
        stderr.contains(
            "runtime: memory function count beyond its variables (first: MEMCPY in Main at \
             memory.st:26; clipped to their size)"
        ),
        "{stderr}"
    );
    assert!(
        !stderr.contains("W1001"),
        "a statement call drops its result: {stderr}"
    );
}

/// A pointer whose variable cannot be known (an address moved back; a pointer variable itself is
/// bounded by its reference since Session 34, `pointer_index_run`), a wrong argument list, a count
/// that is no integer and a located variable: one located error each.
#[test]
fn memory_functions_on_unknown_objects_are_refused() {
    let (code, lines) = check_text(
        "m.st",
        "PROGRAM Main\nVAR a, b : ARRAY[0..9] OF BYTE; p : POINTER TO BYTE; END_VAR\np := ADR(a);\n\
         MEMCPY(destAddr := ADR(a) - 1, srcAddr := ADR(b), n := SIZEOF(b));\nMEMSET(ADR(a), 1);\n\
         MEMCPY(dest := ADR(a), srcAddr := ADR(b), n := 1);\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        vec![
            "m.st:4:20: error[E1035]: MEMCPY: the variable this pointer points into cannot be known (hint: pass `ADR(x)` of the variable itself (an element or a field too), `ADR(x) + n` (n bytes into it), or a POINTER TO variable: ladderc bounds the count by the variable the address belongs to)",
            "m.st:5:1: error[E1035]: `MEMSET` takes three arguments (hint: write `MEMSET(destAddr := ADR(...), fillByte := ..., n := ...)`)",
            "m.st:6:8: error[E1035]: `MEMCPY` has no such argument (hint: write `MEMCPY(destAddr := ADR(...), srcAddr := ..., n := ...)`)",
        ]
    );
    let (code, lines) = check_text(
        "t.st",
        "PROGRAM Main\nVAR a, b : ARRAY[0..9] OF BYTE; x : REAL; q AT %MB10 : BYTE; END_VAR\n\
         MEMCPY(ADR(a), ADR(b), x);\nMEMSET(ADR(q), 0, 1);\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split_once(" (hint").unwrap().0)
        .collect();
    assert_eq!(
        heads,
        vec![
            "t.st:3:24: error[E1012]: the byte count of MEMCPY is REAL, not an integer",
            "t.st:4:12: error[E0305]: MEMSET of `q` is not allowed: a located variable lives in the process image, which has no address",
        ]
    );
}

// ------------------------------------------------------------------ 6. ADR(x) as an initial value

/// Main: p := ADR(a) (a = 5), q := REF(arr[3]) (3), r := ADR(pair.y) (0) written through from the
/// first cycle on (+1, +10, +2 a cycle); FB_Acc's pTotal := ADR(total) (100) in each instance.
#[test]
fn pointers_start_as_the_address_of_a_variable_of_their_pou() {
    let (trace, _) = run_traced(
        &fixture("address_init.st"),
        2,
        "Main.a,Main.arr[3],Main.pair.y,Main.acc.total,Main.x",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.a,Main.arr[3],Main.pair.y,Main.acc.total,Main.x\n\
         0,0,6,13,2,101,21\n1,10,7,23,4,102,34\n"
    );
}

/// What cannot start as an address: a type holding a reference, an unknown name, a subscript out of
/// bounds, a VAR_TEMP for a VAR pointer; one located error each. (A global list's pointer, `pg`,
/// was E0305 here before issue #13's round 26; it starts at the global now:
/// `tests/tests/initial_values_r26_run.rs`.)
#[test]
fn address_initial_values_that_cannot_hold_are_located_errors() {
    let src = "VAR_GLOBAL\n  g : INT;\n  pg : POINTER TO INT := ADR(g);\nEND_VAR\nPROGRAM Main\nVAR\n  \
               a : INT;\n  w : REF_TO INT;\n  arr : ARRAY[1..4] OF INT;\n  p1 : POINTER TO INT := ADR(w);\n  \
               p2 : POINTER TO INT := ADR(nothing);\n  p3 : POINTER TO INT := ADR(arr[7]);\nEND_VAR\n\
               VAR_TEMP t : INT; END_VAR\nVAR p5 : POINTER TO INT := ADR(t); END_VAR\na := 1;\nEND_PROGRAM\n";
    let (code, lines) = check_text("a.st", src);
    assert_eq!(code, Some(1));
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split_once(" (hint").unwrap().0)
        .collect();
    assert_eq!(
        heads,
        vec![
            // a pointer to another type holding no reference is W1425 since issue #13's pointer
            // round (tests/tests/pointer_index_run.rs); one to a reference stays an error
            "a.st:10:26: error[E1006]: cannot store REF_TO REF_TO INT into REF_TO INT",
            "a.st:11:26: error[E0305]: `p2` cannot start as `ADR(nothing)`: `nothing` is no variable of this POU and no global variable",
            "a.st:12:26: error[E0305]: `p3` cannot start as `ADR(arr[7])`: subscript 7 is outside 1..4",
            "a.st:15:28: error[E0305]: `p5` cannot start as `ADR(t)`: a VAR_TEMP variable lives for one call",
        ]
    );
}

// ------------------------------------------------------------------ trailing comma, `;;`

/// ax(fPos := fStop1 - 245.0, ..., fLast => last, ): the call runs (min, last = 5); fStop2's
/// declaration ends with `;;` and keeps its initial value.
#[test]
fn a_trailing_comma_after_formal_arguments_and_an_empty_declaration_are_read() {
    let (trace, _) = run_traced(
        &fixture("trailing_comma.st"),
        1,
        "Main.min,Main.last,Main.fStop2",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.min,Main.last,Main.fStop2\n0,0,1,5,630\n"
    );
    // a positional list ends there too since round 24 (before: E0107), as TwinCAT reads
    // Beckhoff's own `ADSLOGSTR(ADSLOG_MSGTYPE_WARN, 'msg', 'arg',);`: ADD of two inputs
    let (trace, _) = common::run_text(
        "p.st",
        "PROGRAM Main\nVAR a : INT; END_VAR\na := ADD(a, 1, );\nEND_PROGRAM\n",
        2,
        "Main.a",
    );
    assert_eq!(trace, "cycle,time_ms,Main.a\n0,0,1\n1,10,2\n");
}
