//! Round 29 of unseen projects (issue #13), run-time values and unchecked POUs, end to end:
//! - a `POINTER TO ARRAY[0..N] OF T` (or `REFERENCE TO`) made from a shorter array reads and
//!   writes each element that array has through `p^[i]`, `p^[i].x`, `p^[i, j]`; only an element
//!   past its end is the run-time pointer error (before: the whole declared array was checked
//!   against the variable, so every element read 0 and every write was dropped; tkucic/UniTest's
//!   report totals all read 0). CODESYS passes arrays of any length so (online help "Pointer");
//! - a number converted to DATE or LDATE keeps the seconds (nanoseconds) below a whole day, as
//!   CODESYS and TwinCAT store a DATE as a DWORD of seconds since 1970 (Beckhoff infosys
//!   "DATE/DT_TO_<type>"; IEC 61131-3 leaves these conversions to the implementation) (before:
//!   cut to the day, so `UINT_TO_DATE(35) = UINT_TO_DATE(0)`);
//! - the POUs of a PLCopen XML file that no program instance uses are checked as the same POUs
//!   in ST text are (before: skipped unchecked with W3004, exit 0 with undeclared names inside);
//! - CODESYS's `LTIME()` is the scan clock, as `TIME()` is.

mod common;
use common::{check_text, column, ladderc, run_text};

const POINTERS: &str = "TYPE Pair : STRUCT a : INT; b : INT; END_STRUCT; END_TYPE
VAR_GLOBAL
  arr : ARRAY[0..3] OF INT := [1, 2, 3, 4];
  pairs : ARRAY[1..2] OF Pair := [(a := 10, b := 20), (a := 30, b := 40)];
  grid : ARRAY[1..2, 1..3] OF INT := [1, 2, 3, 4, 5, 6];
END_VAR
FUNCTION_BLOCK Summer
VAR_INPUT p : POINTER TO ARRAY[0..100] OF INT; n : INT; END_VAR
VAR_OUTPUT total : INT; END_VAR
VAR i : INT; END_VAR
total := 0;
FOR i := 0 TO n DO
  total := total + p^[i];
END_FOR;
p^[n] := p^[n] + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR
  s : Summer; t : INT; last : INT;
  q : POINTER TO ARRAY[1..1000] OF Pair; sb : INT; qa : INT;
  g : POINTER TO ARRAY[1..100, 1..3] OF INT;
  r : REFERENCE TO ARRAY[1..100, 1..3] OF INT;
  gx : INT; ry : INT; gw : INT;
END_VAR
s(p := ADR(arr), n := LAST_INDEX);
t := s.total;
last := arr[3];
q := ADR(pairs);
sb := q^[2].b + q^[1].a;
q^[2].a := q^[2].a + 1;
qa := pairs[2].a;
g := ADR(grid);
gx := g^[2, 3];
r REF= grid;
ry := r[2, 1];
g^[1, 2] := g^[1, 2] + 10;
gw := grid[1, 2];
END_PROGRAM
";

/// `p^[i]` through a `POINTER TO ARRAY[0..100] OF INT` given `ADR` of an `ARRAY[0..3]`: the four
/// elements are summed (10, then 11, 12 as `p^[3]` is incremented through the pointer each scan),
/// `q^[2].b` of a `POINTER TO ARRAY[1..1000] OF Pair` reads the field and `q^[2].a` is written,
/// a two-dimensional pointer and a `REFERENCE TO` read and write their elements; no run-time
/// error. Before: every read was 0 and every write dropped (t = 0, last = 4, sb = 0, qa = 30),
/// with "pointer outside its variable dereferenced (first: p^ in Summer ...)".
#[test]
fn pointer_to_a_larger_array_reaches_each_element_of_a_shorter_one() {
    let src = POINTERS.replace("LAST_INDEX", "3");
    let (trace, stderr) = run_text(
        "ptr.st",
        &src,
        3,
        "Main.t,Main.last,Main.sb,Main.qa,Main.gx,Main.ry,Main.gw",
    );
    assert_eq!(column(&trace, "Main.t"), vec![10.0, 11.0, 12.0], "{trace}");
    assert_eq!(column(&trace, "Main.last"), vec![5.0, 6.0, 7.0], "{trace}");
    assert_eq!(column(&trace, "Main.sb"), vec![50.0; 3], "{trace}");
    assert_eq!(column(&trace, "Main.qa"), vec![31.0, 32.0, 33.0], "{trace}");
    assert_eq!(column(&trace, "Main.gx"), vec![6.0; 3], "{trace}");
    assert_eq!(column(&trace, "Main.ry"), vec![4.0; 3], "{trace}");
    assert_eq!(column(&trace, "Main.gw"), vec![12.0, 22.0, 32.0], "{trace}");
    assert!(!stderr.contains("runtime:"), "{stderr}");
}

/// The same block asked for one element more (`n := 4`): `p^[4]` lies past the 4-element array,
/// so it reads 0 and its write is dropped (`arr[3]` stays 4), and the end of the run names that
/// access (`p^[i]`, the element, not the whole `p^`); the elements inside still read their values.
#[test]
fn pointer_to_a_larger_array_past_the_shorter_one_is_the_runtime_error() {
    let src = POINTERS.replace("LAST_INDEX", "4");
    let (trace, stderr) = run_text("ptr4.st", &src, 2, "Main.t,Main.last");
    assert_eq!(column(&trace, "Main.t"), vec![10.0, 10.0], "{trace}");
    assert_eq!(column(&trace, "Main.last"), vec![4.0, 4.0], "{trace}");
    assert!(
        stderr.contains("runtime: pointer outside its variable dereferenced (first: p^[i] in Summer at ptr4.st:13;"),
        "{stderr}"
    );
}

/// A number converted to DATE or LDATE keeps what lies below a whole day: `REAL_TO_DATE(115.4)` is
/// 115 seconds after 1970-01-01 and compares greater than `REAL_TO_DATE(85.4)`,
/// `UINT_TO_DATE(35) <> UINT_TO_DATE(0)`, `REAL_TO_LDATE(115.4)` is 115 ns. A DT converted to DATE
/// keeps only its day (86400) and a number to TOD its time of day (1 ms), as before. Before: a =
/// b = D#1970-01-01, g = FALSE, e = TRUE, n = 0, ln = 0.
#[test]
fn number_to_date_keeps_the_seconds_below_a_day() {
    let src = "PROGRAM Main
VAR
  a : DATE; b : DATE; g : BOOL; e : BOOL; n : UDINT;
  la : LDATE; ln : ULINT; dd : UDINT; td : UDINT; w : UDINT;
END_VAR
a := REAL_TO_DATE(115.4);
b := REAL_TO_DATE(85.4);
g := a > b;
e := UINT_TO_DATE(35) = UINT_TO_DATE(0);
n := DATE_TO_UDINT(a);
la := REAL_TO_LDATE(115.4);
ln := LDATE_TO_ULINT(la);
dd := DATE_TO_UDINT(DT_TO_DATE(DT#1970-01-02-00:00:05));
td := TOD_TO_UDINT(UDINT_TO_TOD(86400001));
w := DATE_TO_UDINT(DWORD_TO_DATE(DWORD#86401));
END_PROGRAM
";
    let (trace, _) = run_text(
        "dates.st",
        src,
        1,
        "Main.g,Main.e,Main.n,Main.ln,Main.dd,Main.td,Main.w",
    );
    assert_eq!(column(&trace, "Main.g"), vec![1.0], "{trace}");
    assert_eq!(column(&trace, "Main.e"), vec![0.0], "{trace}");
    assert_eq!(column(&trace, "Main.n"), vec![115.0], "{trace}");
    assert_eq!(column(&trace, "Main.ln"), vec![115.0], "{trace}");
    assert_eq!(column(&trace, "Main.dd"), vec![86400.0], "{trace}");
    assert_eq!(column(&trace, "Main.td"), vec![1.0], "{trace}");
    assert_eq!(column(&trace, "Main.w"), vec![86401.0], "{trace}");
}

const UNUSED_XML: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="unused">
    <coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo>
  </contentHeader>
  <types>
    <dataTypes/>
    <pous>
      <pou name="Scale" pouType="function">
        <interface><returnType><INT/></returnType>
          <inputVars><variable name="raw"><type><INT/></type></variable></inputVars>
        </interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">Scale := raw * GAIN_NAME;</xhtml></ST></body>
      </pou>
      <pou name="Limiter" pouType="functionBlock">
        <interface><outputVars><variable name="q"><type><BOOL/></type></variable></outputVars></interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">q := LEVEL_NAME &gt; 10;</xhtml></ST></body>
      </pou>
      <pou name="Main" pouType="program">
        <interface><localVars><variable name="n"><type><INT/></type></variable></localVars></interface>
        <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := n + 1;</xhtml></ST></body>
      </pou>
    </pous>
  </types>
  <instances>
    <configurations>
      <configuration name="C">
        <resource name="R">
          <task name="T" priority="1" interval="T#10ms"><pouInstance name="main" typeName="Main"/></task>
        </resource>
      </configuration>
    </configurations>
  </instances>
</project>
"#;

/// A function and a function block that the only program instance never uses, each reading an
/// undeclared name: one E1001 each, at the name, exit 1, as in ST text. Before: two W3004
/// "not used by any program instance and is skipped" and exit 0.
#[test]
fn unused_pous_of_a_plcopen_file_are_checked() {
    let src = UNUSED_XML
        .replace("GAIN_NAME", "gain")
        .replace("LEVEL_NAME", "level");
    let (code, lines) = check_text("unused.xml", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].starts_with("unused.xml:14:78: error[E1001]: undeclared name `gain`"),
        "{lines:?}"
    );
    assert!(
        lines[1].starts_with("unused.xml:18:68: error[E1001]: undeclared name `level`"),
        "{lines:?}"
    );
}

/// The same file with the names declared as inputs: the unused POUs compile with the program, the
/// run is clean and says nothing about them; `ladderc explain W3004` says the code is no longer
/// raised (before: it said ST was "not compiled yet" and advised rewriting the POU in IL, LD or
/// FBD).
#[test]
fn unused_pous_compile_and_w3004_is_explained_as_retired() {
    let src = UNUSED_XML
        .replace("GAIN_NAME", "raw")
        .replace("LEVEL_NAME", "Scale(5)");
    let (trace, stderr) = run_text("unused_ok.xml", &src, 3, "main.n");
    assert_eq!(column(&trace, "main.n"), vec![1.0, 2.0, 3.0], "{trace}");
    assert!(!stderr.contains("W3004"), "{stderr}");
    let out = ladderc().args(["explain", "W3004"]).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("no longer raised"), "{text}");
    assert!(!text.contains("not compile yet"), "{text}");
}

/// CODESYS's `LTIME()` (its help: the time since system start, in nanoseconds) is the scan clock
/// as `TIME()` is, as an LTIME: 0 in the first cycle, then 10 ms a cycle, and it takes no input
/// (before: E1019 "unknown function `LTIME`", 17 times in tkucic's CODESYS speed tests).
#[test]
fn ltime_function_is_the_scan_clock() {
    let src = "PROGRAM Main
VAR
  t : TIME;
  lt : LTIME;
  ms : LINT;
END_VAR
t := TIME();
lt := LTIME();
ms := LTIME_TO_LINT(LTIME() - LTIME#0ns);
END_PROGRAM
";
    let (trace, stderr) = run_text("clock.st", src, 4, "Main.ms,Main.lt,Main.t");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(
        column(&trace, "Main.ms"),
        vec![0.0, 10.0, 20.0, 30.0],
        "{trace}"
    );
    let (code, lines) = check_text("bad.st", &src.replace("lt := LTIME();", "lt := LTIME(5);"));
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("bad.st:8:7: error[E1020]")),
        "{lines:?}"
    );
}
