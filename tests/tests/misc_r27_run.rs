//! Round 27 of unseen projects (issue #13), miscellaneous: what real programs need, run end to end
//! through `ladderc run`:
//! - a variable-length array (`ARRAY [*]`) in-out passed in the call of an instance selected by
//!   index (`fs[i](a := b)`), of an instance in a structure, and to a method of such an instance
//!   (`ms[1].Sum(b)`): ordinary Structured Text (IEC 61131-3 ed. 3, 6.5.3) (before: E1071 "only
//!   calls in Structured Text pass a variable-length array");
//! - `ADR(x)` / `REF(x)` as elements of an array's initial value (`p : ARRAY[0..1] OF POINTER TO
//!   INT := [ADR(a), ADR(b)];`), also with NULL elements, two dimensions, inside a structure's
//!   initial value, in VAR_GLOBAL, in a block's VAR, and an array of instances or structures whose
//!   elements start pointer inputs (`[(pin := ADR(k)), (pin := ADR(j))]`) (before: E0305);
//! - every date and time type converts to every other (`TOD_TO_DT`, `TIME_TO_DATE`, `DATE_TO_TOD`,
//!   `DT_TO_TIME`, `TOD_TO_LDT` ...; CODESYS's and TwinCAT's conversion tables 16 and 17, edition
//!   3's Table 22), as the same point of the time line from 1970-01-01-00:00 (before: E1019 for
//!   all but DT to DATE/TOD, DATE to DT and TOD/TIME).

mod common;
use common::{check_text, column, run_text, text_column};

/// `fs[i](a := b)` in a FOR loop, `fs : ARRAY[0..2] OF FB` whose in-out is `ARRAY [*] OF INT`:
/// each element sees the bounds of the array it is given (UPPER_BOUND 9 for `b`, 4 for `c`), and
/// its writes through the in-out reach the caller's array (three increments per scan of `b`).
/// A method of an element, `ms[1].Sum(b)` (positional) and `ms[2].Sum(v := c)` (formal), sums the
/// array it is given; an instance inside a structure (`st.f(a := c)`) likewise.
#[test]
fn a_variable_length_array_goes_to_an_instance_selected_by_index() {
    let src = "FUNCTION_BLOCK FB_Inc
VAR_IN_OUT a : ARRAY[*] OF INT; END_VAR
VAR_OUTPUT n : DINT; END_VAR
VAR k : DINT; END_VAR
n := UPPER_BOUND(a, 1);
FOR k := LOWER_BOUND(a, 1) TO UPPER_BOUND(a, 1) DO a[k] := a[k] + 1; END_FOR
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_Sum
METHOD Sum : DINT
VAR_IN_OUT v : ARRAY[*] OF INT; END_VAR
VAR k : DINT; END_VAR
FOR k := LOWER_BOUND(v, 1) TO UPPER_BOUND(v, 1) DO Sum := Sum + v[k]; END_FOR
END_METHOD
END_FUNCTION_BLOCK
TYPE ST_Holder : STRUCT f : FB_Inc; END_STRUCT; END_TYPE
PROGRAM Main
VAR
  fs : ARRAY[0..2] OF FB_Inc;
  ms : ARRAY[1..2] OF FB_Sum;
  st : ST_Holder;
  b : ARRAY[0..9] OF INT;
  c : ARRAY[1..4] OF INT;
  i : INT;
  n0, n1, n2, ns, s1, s2 : DINT;
END_VAR
FOR i := 0 TO 2 DO fs[i](a := b); END_FOR
fs[1](a := c);
st.f(a := c);
n0 := fs[0].n; n1 := fs[1].n; n2 := fs[2].n; ns := st.f.n;
s1 := ms[1].Sum(b);
s2 := ms[2].Sum(v := c);
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "vla_elements.st",
        src,
        2,
        "Main.n0,Main.n1,Main.n2,Main.ns,Main.s1,Main.s2,Main.b[9],Main.c[4]",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.n0"), vec![9.0, 9.0]);
    // fs[1] was last given c (1..4)
    assert_eq!(column(&trace, "Main.n1"), vec![4.0, 4.0]);
    assert_eq!(column(&trace, "Main.n2"), vec![9.0, 9.0]);
    assert_eq!(column(&trace, "Main.ns"), vec![4.0, 4.0]);
    // b: three increments per scan; c: two (fs[1] and st.f)
    assert_eq!(column(&trace, "Main.b[9]"), vec![3.0, 6.0]);
    assert_eq!(column(&trace, "Main.c[4]"), vec![2.0, 4.0]);
    assert_eq!(column(&trace, "Main.s1"), vec![30.0, 60.0]);
    assert_eq!(column(&trace, "Main.s2"), vec![8.0, 16.0]);
}

/// An array of another element type given to an element's `ARRAY [*] OF INT` in-out is still the
/// one located E1071 of a mismatch (no cascade), not the "only calls in Structured Text" one.
#[test]
fn a_mismatched_array_to_an_indexed_instance_is_one_e1071() {
    let src = "FUNCTION_BLOCK FB_Inc
VAR_IN_OUT a : ARRAY[*] OF INT; END_VAR
a[0] := 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR fs : ARRAY[0..1] OF FB_Inc; r : ARRAY[0..3] OF REAL; END_VAR
fs[1](a := r);
END_PROGRAM
";
    let (code, lines) = check_text("vla_bad.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(errors[0].contains("vla_bad.st:7:"), "{lines:?}");
    assert!(errors[0].contains("E1071"), "{lines:?}");
    assert!(errors[0].contains("does not fit"), "{lines:?}");
}

/// `[ADR(a), ADR(b)]` and `[REF(a), NULL, REF(arr[3])]` start each element pointing where written
/// (NULL stays NULL); a two-dimensional array row by row; `(ps := [ADR(b), ADR(arr[2])], n := 9)`
/// inside a structure's initial value keeps its constant field; a VAR_GLOBAL array of addresses of
/// globals; an array of structures each starting its own reference (`[(p := REF(b)), (p :=
/// REF(a), k := 7)]`, the unnamed field keeping its declared initial value).
#[test]
fn addresses_start_the_elements_of_an_array() {
    let src = "TYPE ST_P : STRUCT ps : ARRAY[1..2] OF POINTER TO INT; n : INT; END_STRUCT; END_TYPE
TYPE ST_Q : STRUCT p : REF_TO INT; k : INT := 5; END_STRUCT; END_TYPE
VAR_GLOBAL g1 : INT := 100; g2 : INT := 200; gp : ARRAY[0..1] OF POINTER TO INT := [ADR(g2), ADR(g1)]; END_VAR
PROGRAM Main
VAR
  a : INT := 3; b : INT := 4; arr : ARRAY[0..3] OF INT := [10, 20, 30, 40];
  p : ARRAY[0..1] OF POINTER TO INT := [ADR(a), ADR(b)];
  s : ST_P := (ps := [ADR(b), ADR(arr[2])], n := 9);
  r : ARRAY[0..2] OF REF_TO INT := [REF(a), NULL, REF(arr[3])];
  m : ARRAY[0..1, 0..1] OF POINTER TO INT := [ADR(a), ADR(b), ADR(arr[0]), ADR(arr[1])];
  q : ARRAY[0..1] OF ST_Q := [(p := REF(b)), (p := REF(a), k := 7)];
  x, xs, y, z, w, v : INT; isnull : BOOL;
END_VAR
x := p[0]^ + p[1]^;
xs := s.ps[1]^ + s.ps[2]^ + s.n;
y := r[0]^ + r[2]^; isnull := r[1] = 0;
z := m[0,0]^ * 1000 + m[0,1]^ * 100 + m[1,0]^ + m[1,1]^;
w := gp[0]^ - gp[1]^;
v := q[0].p^ * 10 + q[1].p^ + q[0].k * 100 + q[1].k * 1000;
p[1]^ := 40;
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "adr_array.st",
        src,
        2,
        "Main.x,Main.xs,Main.y,Main.z,Main.w,Main.v,Main.isnull,Main.b",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), vec![7.0, 43.0]);
    assert_eq!(column(&trace, "Main.xs")[0], 4.0 + 30.0 + 9.0);
    assert_eq!(column(&trace, "Main.y"), vec![43.0, 43.0]);
    assert_eq!(column(&trace, "Main.z")[0], 3000.0 + 400.0 + 10.0 + 20.0);
    assert_eq!(column(&trace, "Main.w"), vec![100.0, 100.0]);
    assert_eq!(column(&trace, "Main.v")[0], 40.0 + 3.0 + 500.0 + 7000.0);
    assert_eq!(column(&trace, "Main.isnull"), vec![1.0, 1.0]);
    // the write through p[1] reached b
    assert_eq!(column(&trace, "Main.b"), vec![40.0, 40.0]);
}

/// A block's own VAR array of addresses of its variables is per instance; an array of instances
/// starts each one's pointer input at its own variable; a function's VAR array of addresses
/// starts at each call (a NULL element stays NULL).
#[test]
fn addresses_start_a_blocks_array_and_an_array_of_instances() {
    let src = "FUNCTION F_Own : INT
VAR c : INT := 6; ps : ARRAY[0..1] OF POINTER TO INT := [ADR(c), NULL]; END_VAR
F_Own := ps[0]^;
IF ps[1] = 0 THEN F_Own := F_Own + 100; END_IF
c := 0;
END_FUNCTION
FUNCTION_BLOCK FB_Read
VAR_INPUT pin : POINTER TO INT; END_VAR
VAR_OUTPUT s : INT; END_VAR
VAR a : INT := 5; b : INT := 6; ps : ARRAY[0..1] OF POINTER TO INT := [ADR(b), ADR(a)]; END_VAR
s := ps[0]^ * 10 + ps[1]^ + pin^ * 100;
END_FUNCTION_BLOCK
PROGRAM Main
VAR k : INT := 2; j : INT := 3; fbs : ARRAY[0..1] OF FB_Read := [(pin := ADR(k)), (pin := ADR(j))]; x, y, z : INT; END_VAR
fbs[0](); fbs[1]();
x := fbs[0].s; y := fbs[1].s;
z := F_Own();
END_PROGRAM
";
    let (trace, stderr) = run_text("adr_fb.st", src, 2, "Main.x,Main.y,Main.z");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), vec![265.0, 265.0]);
    assert_eq!(column(&trace, "Main.y"), vec![365.0, 365.0]);
    assert_eq!(column(&trace, "Main.z"), vec![106.0, 106.0]);
}

/// What cannot start an element is one located error each: an address stored into an INT
/// element (E1006), an address of no variable (E0305), a value that is neither an address nor
/// NULL among addresses (E0305).
#[test]
fn a_bad_address_element_is_one_located_error() {
    let src = "PROGRAM Main
VAR a : INT := 3;
  q : ARRAY[0..1] OF INT := [ADR(a), 1];
  r : ARRAY[0..1] OF POINTER TO INT := [ADR(zz), ADR(a)];
END_VAR
a := 1;
END_PROGRAM
";
    let (code, lines) = check_text("adr_bad.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 2, "{lines:?}");
    assert!(
        errors[0].contains("adr_bad.st:3:") && errors[0].contains("E1006"),
        "{lines:?}"
    );
    assert!(
        errors[1].contains("adr_bad.st:4:")
            && errors[1].contains("E0305")
            && errors[1].contains("`r[0]` cannot start as `ADR(zz)`"),
        "{lines:?}"
    );
    let src = "PROGRAM Main
VAR a : INT := 3; b : INT; p : ARRAY[0..1] OF POINTER TO INT := [ADR(a), b]; END_VAR
b := 1;
END_PROGRAM
";
    let (code, lines) = check_text("adr_bad2.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("adr_bad2.st:2:") && lines[0].contains("E0305"),
        "{lines:?}"
    );
}

/// The date and time conversions, table-driven: each `(call, result type, expected value as the
/// trace prints it)`, from TOD#10:00:00, D#2020-01-02, DT#2020-01-02-03:04:05 and T#1d2h.
#[test]
fn every_date_and_time_type_converts_to_every_other() {
    let cases: &[(&str, &str, &str)] = &[
        ("TOD_TO_DT(t)", "DT", "DT#1970-01-01-10:00:00"),
        ("TOD_TO_DATE(t)", "DATE", "D#1970-01-01"),
        ("TOD_TO_TIME(t)", "TIME", "T#36000000ms"),
        ("TOD_TO_LDT(t)", "LDT", "LDT#1970-01-01-10:00:00"),
        ("TOD_TO_LDATE(t)", "LDATE", "LDATE#1970-01-01"),
        ("DATE_TO_TOD(d)", "TOD", "TOD#00:00:00"),
        ("DATE_TO_LTOD(d)", "LTOD", "LTOD#00:00:00"),
        ("DATE_TO_DT(d)", "DT", "DT#2020-01-02-00:00:00"),
        ("DATE_TO_TIME(d)", "TIME", "T#1577923200000ms"),
        ("DT_TO_DATE(dt1)", "DATE", "D#2020-01-02"),
        ("DT_TO_TOD(dt1)", "TOD", "TOD#03:04:05"),
        ("DT_TO_TIME(dt1)", "TIME", "T#1577934245000ms"),
        ("TIME_TO_DATE(tm)", "DATE", "D#1970-01-02"),
        ("TIME_TO_DT(tm)", "DT", "DT#1970-01-02-02:00:00"),
        ("TIME_TO_TOD(tm)", "TOD", "TOD#02:00:00"),
        ("LTIME_TO_DATE(TIME_TO_LTIME(tm))", "DATE", "D#1970-01-02"),
        ("LDT_TO_LTIME(DT_TO_LDT(dt1))", "LTIME", "T#1577934245000ms"),
        (
            "LTOD_TO_LDT(TOD_TO_LTOD(t))",
            "LDT",
            "LDT#1970-01-01-10:00:00",
        ),
        ("LDATE_TO_TOD(DATE_TO_LDATE(d))", "TOD", "TOD#00:00:00"),
        ("TO_DT(t)", "DT", "DT#1970-01-01-10:00:00"),
        (
            "CONCAT_DATE_TOD(DT_TO_DATE(dt1), LTOD_TO_TOD(TOD_TO_LTOD(t)))",
            "DT",
            "DT#2020-01-02-10:00:00",
        ),
    ];
    let mut decls = String::new();
    let mut body = String::new();
    let mut watch = Vec::new();
    for (k, (call, ty, _)) in cases.iter().enumerate() {
        decls.push_str(&format!("  r{k} : {ty};\n"));
        body.push_str(&format!("r{k} := {call};\n"));
        watch.push(format!("Main.r{k}"));
    }
    let src = format!(
        "PROGRAM Main
VAR
  t : TOD := TOD#10:00:00; d : DATE := D#2020-01-02;
  dt1 : DT := DT#2020-01-02-03:04:05; tm : TIME := T#1d2h;
{decls}END_VAR
{body}END_PROGRAM
"
    );
    let (trace, stderr) = run_text("conversions.st", &src, 1, &watch.join(","));
    assert!(!stderr.contains("error"), "{stderr}");
    for (k, (call, _, expected)) in cases.iter().enumerate() {
        assert_eq!(
            text_column(&trace, &format!("Main.r{k}")),
            vec![expected.to_string()],
            "{call}"
        );
    }
}
