//! The standard string functions end to end (IL -> C -> strict build with sanitizers -> trace): results
//! cycle by cycle, truncation to declared lengths and the 254-character capacity, and the documented
//! out-of-range fallbacks (with the runtime's end-of-run flag).

mod support;
use support::*;

/// Runs `body` (IL instructions using `s`, `t` : STRING and `n`, `m` : INT inputs, storing into `r` and
/// `k`) over the stimulus and returns the traced columns `r` and `k`.
fn run_body(
    decls: &str,
    body: &str,
    cycles: u64,
    stim: &str,
) -> (Vec<String>, Vec<String>, String) {
    let src = format!(
        "PROGRAM main
VAR
  s : STRING;
  t : STRING;
  n : INT;
  m : INT;
  r : STRING;
  k : INT;
{decls}
END_VAR
{body}
END_PROGRAM
"
    );
    let b = build_src(&src);
    let rows = run(&b, cycles, 10.0, stim, &["main.r", "main.k"]);
    let stderr = run_stderr(&b, cycles, stim);
    (column(&rows, "main.r"), column(&rows, "main.k"), stderr)
}

/// The program's stderr for a run (the runtime reports its sticky flags there).
fn run_stderr(b: &Built, cycles: u64, stim: &str) -> String {
    let stim_path = b.dir.path().join("stim2.csv");
    std::fs::write(&stim_path, stim).unwrap();
    let out = c_backend::run(
        &b.exe,
        &c_backend::RunOptions {
            cycles,
            cycle_ms: 10.0,
            stimulus: Some(stim_path),
            trace: Some(b.dir.path().join("trace2.csv")),
            watch: vec!["main.r".into()],
        },
    )
    .expect("run");
    out.stderr
}

fn q(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| format!("\"{s}\"")).collect()
}

#[test]
fn len_and_find_count_characters_from_one() {
    let (_, k, _) = run_body(
        "",
        "  LD s\n  LEN\n  ST k\n",
        3,
        "0,main.s,\n1,main.s,abc\n2,main.s,hello world\n",
    );
    assert_eq!(k, ["0", "3", "11"]);
    let (_, k, err) = run_body(
        "",
        "  LD s\n  FIND t\n  ST k\n",
        5,
        "0,main.s,abcabc\n0,main.t,ca\n1,main.t,x\n2,main.t,\n3,main.t,abcabcd\n4,main.t,abc\n",
    );
    assert_eq!(k, ["3", "0", "0", "0", "1"]);
    assert!(!err.contains("out of range"), "{err}");
}

#[test]
fn left_right_mid_with_in_range_and_out_of_range_arguments() {
    // cycle: n (L), m (P)
    let stim = "0,main.s,ABCDE\n0,main.n,2\n0,main.m,2\n1,main.n,9\n2,main.n,0\n3,main.n,-1\n";
    let (r, _, err) = run_body("", "  LD s\n  LEFT n\n  ST r\n", 4, stim);
    assert_eq!(r, q(&["AB", "ABCDE", "", ""]));
    assert!(
        err.contains("string length or position out of range"),
        "{err}"
    );
    let (r, _, _) = run_body("", "  LD s\n  RIGHT n\n  ST r\n", 4, stim);
    assert_eq!(r, q(&["DE", "ABCDE", "", ""]));
    // MID(IN, L, P): P = 2; then P out of range
    let stim = "0,main.s,ABCDE\n0,main.n,3\n0,main.m,2\n1,main.n,10\n2,main.m,6\n3,main.m,7\n4,main.m,0\n5,main.m,5\n";
    let (r, _, err) = run_body("", "  LD s\n  MID n, m\n  ST r\n", 6, stim);
    assert_eq!(r, q(&["BCD", "BCDE", "", "", "", "E"]));
    assert!(err.contains("out of range"), "{err}");
    // in range only: no flag
    let (_, _, err) = run_body("", "  LD s\n  MID n, m\n  ST r\n", 2, stim);
    assert!(!err.contains("out of range"), "{err}");
}

#[test]
fn concat_is_extensible_and_truncates_to_the_declared_length() {
    let (r, _, err) = run_body(
        "  short : STRING[5];\n  u : STRING;",
        "  LD s\n  CONCAT t, '-', s\n  ST r\n  ST short\n  LD short\n  ST u\n  LD u\n  CONCAT '!'\n  ST r\n",
        2,
        "0,main.s,ab\n0,main.t,cd\n1,main.s,x\n",
    );
    // short = first 5 of 'abcd-ab' -> 'abcd-' then r := short + '!'
    assert_eq!(r, q(&["abcd-!", "xcd-x!"]));
    assert!(err.contains("string truncated"), "{err}");
}

#[test]
fn concat_to_the_capacity_truncates_at_254_characters() {
    // `big` is declared at the capacity: an unsized STRING holds only the default length (80,
    // round 34's `default_string_length`).
    let long = "x".repeat(200);
    let (_, k, err) = run_body(
        "  big : STRING(254);",
        "  LD s\n  CONCAT s\n  ST big\n  LD big\n  LEN\n  ST k\n",
        2,
        &format!("0,main.s,{long}\n1,main.s,abc\n"),
    );
    assert_eq!(k, ["254", "6"]);
    assert!(err.contains("string truncated"), "{err}");
}

#[test]
fn insert_delete_replace() {
    let stim = "0,main.s,ABCDE\n0,main.t,xy\n0,main.n,2\n1,main.n,0\n2,main.n,5\n3,main.n,6\n4,main.n,-3\n";
    let (r, _, err) = run_body("", "  LD s\n  INSERT t, n\n  ST r\n", 5, stim);
    assert_eq!(
        r,
        q(&["ABxyCDE", "xyABCDE", "ABCDExy", "ABCDExy", "xyABCDE"])
    );
    assert!(err.contains("out of range"), "{err}");
    // DELETE(IN, L := n, P := m)
    let stim = "0,main.s,ABCDE\n0,main.n,2\n0,main.m,2\n1,main.n,10\n2,main.m,6\n3,main.m,7\n4,main.n,-1\n";
    let (r, _, _) = run_body("", "  LD s\n  DELETE n, m\n  ST r\n", 5, stim);
    assert_eq!(r, q(&["ADE", "A", "ABCDE", "ABCDE", "ABCDE"]));
    // REPLACE(IN1, IN2, L := n, P := m)
    let stim = "0,main.s,ABCDE\n0,main.t,xyz\n0,main.n,2\n0,main.m,2\n1,main.n,0\n2,main.n,9\n3,main.m,6\n4,main.m,0\n";
    let (r, _, err) = run_body("", "  LD s\n  REPLACE t, n, m\n  ST r\n", 5, stim);
    assert_eq!(r, q(&["AxyzDE", "AxyzBCDE", "Axyz", "ABCDExyz", "ABCDE"]));
    assert!(err.contains("out of range"), "{err}");
}

#[test]
fn formal_calls_comparisons_and_move_of_strings() {
    let (r, k, _) = run_body(
        "  lt : BOOL;\n  eq : BOOL;",
        "  MID(IN := s, L := 2, P := 3)\n  ST r\n  LD s\n  LT t\n  ST lt\n  LD s\n  EQ t\n  ST eq\n  LD lt\n  BOOL_TO_INT\n  MUL 10\n  ST k\n  LD eq\n  BOOL_TO_INT\n  ADD k\n  ST k\n  MOVE(IN := r)\n  ST r\n",
        4,
        "0,main.s,abcd\n0,main.t,abd\n1,main.t,abcd\n2,main.t,abc\n3,main.s,\n",
    );
    assert_eq!(r, q(&["cd", "cd", "cd", ""]));
    // k = 10 * (s < t) + (s = t)
    assert_eq!(k, ["10", "1", "0", "10"]);
}

#[test]
fn wstring_functions_work_on_utf16_units() {
    let b = build_src(
        "PROGRAM main
VAR
  w : WSTRING;
  r : WSTRING;
  k : INT;
END_VAR
  LD w
  CONCAT \"-\", w
  ST r
  LD r
  FIND \"-\"
  ST k
END_PROGRAM
",
    );
    let rows = run(
        &b,
        2,
        10.0,
        "0,main.w,été\n1,main.w,ab\n",
        &["main.r", "main.k"],
    );
    assert_eq!(column(&rows, "main.r"), q(&["été-été", "ab-ab"]));
    assert_eq!(column(&rows, "main.k"), ["4", "3"]);
}

#[test]
fn max_min_limit_order_strings_like_the_comparisons() {
    let (r, _, _) = run_body(
        "  lo : STRING;\n  hi : STRING;\n  mx : STRING;\n  mn : STRING;",
        "  LD s\n  MAX t, 'm'\n  ST mx\n  LD s\n  MIN t, 'm'\n  ST mn\n  LIMIT(MN := 'b', IN := s, MX := 'd')\n  ST r\n",
        3,
        "0,main.s,apple\n0,main.t,zoo\n1,main.s,cat\n1,main.t,ca\n2,main.s,dz\n",
    );
    assert_eq!(r, q(&["b", "cat", "d"]));
    let b = build_src(
        "PROGRAM main
VAR
  s : STRING;
  t : STRING;
  mx : STRING;
  mn : STRING;
END_VAR
  LD s
  MAX t, 'm'
  ST mx
  LD s
  MIN t, 'm'
  ST mn
END_PROGRAM
",
    );
    let rows = run(
        &b,
        2,
        10.0,
        "0,main.s,apple\n0,main.t,zoo\n1,main.s,cat\n1,main.t,ca\n",
        &["main.mx", "main.mn"],
    );
    assert_eq!(column(&rows, "main.mx"), q(&["zoo", "m"]));
    assert_eq!(column(&rows, "main.mn"), q(&["apple", "ca"]));
}

/// The generated C of the string functions (one call each, CONCAT folded).
#[test]
fn generated_c_of_string_functions() {
    let src = "PROGRAM main
VAR
  s : STRING[10];
  t : STRING;
  w : WSTRING;
  n : INT;
  r : STRING[8];
  rw : WSTRING;
END_VAR
  LD s
  LEN
  ST n
  LD s
  CONCAT t, 'x'
  ST r
  MID(IN := t, L := n, P := 2)
  ST r
  LD s
  REPLACE t, 1, n
  ST r
  LD w
  INSERT \"a\", 1
  ST rw
  LD w
  FIND \"a\"
  ST n
END_PROGRAM
";
    let (units, model, map) = frontend(src);
    let p = generate_with(
        &units,
        &model,
        &map,
        &Default::default(),
        &Default::default(),
    );
    let c = p.file("program.c").unwrap();
    let body = &c[c.find("void P_main_BODY").unwrap()..];
    let body = &body[..body.find("\n}\n").unwrap() + 3];
    insta::assert_snapshot!(body);
}

#[test]
fn string_to_date_tod_dt_read_iec_literals_with_or_without_prefix() {
    let b = build_src(
        "PROGRAM main
VAR
  s : STRING;
  d : DATE;
  tod1 : TOD;
  dt1 : DT;
  back : STRING;
END_VAR
  LD s
  STRING_TO_DATE
  ST d
  DATE_TO_STRING
  ST back
  LD s
  STRING_TO_TOD
  ST tod1
  LD s
  STRING_TO_DT
  ST dt1
END_PROGRAM
",
    );
    let stim = "0,main.s,D#2024-02-29\n1,main.s, 2024-03-01 \n2,main.s,TOD#12:30:15.5\n3,main.s,08:00:00\n4,main.s,DT#2024-01-31-23:59:59\n5,main.s,nonsense\n";
    let rows = run(
        &b,
        6,
        10.0,
        stim,
        &["main.d", "main.tod1", "main.dt1", "main.back"],
    );
    assert_eq!(
        column(&rows, "main.d"),
        [
            "D#2024-02-29",
            "D#2024-03-01",
            "D#1970-01-01",
            "D#1970-01-01",
            "D#1970-01-01",
            "D#1970-01-01"
        ]
    );
    assert_eq!(column(&rows, "main.back")[0], "\"D#2024-02-29\"");
    assert_eq!(
        column(&rows, "main.tod1"),
        [
            "TOD#00:00:00",
            "TOD#00:00:00",
            "TOD#12:30:15.5",
            "TOD#08:00:00",
            "TOD#00:00:00",
            "TOD#00:00:00"
        ]
    );
    assert_eq!(column(&rows, "main.dt1")[4], "DT#2024-01-31-23:59:59");
    assert_eq!(column(&rows, "main.dt1")[5], "DT#1970-01-01-00:00:00");
}
