//! Structured Text source files end to end (`ladderc check/run` on `.st`, `.txt`, `-`): the real files
//! of `tests/corpus/st` (IronPLC, MIT), the language choice (`--lang`, detection, one E0300 for ST in an
//! IL file), ST as real programs write it (functional XOR/MOD/MAX, formal LIMIT, user functions,
//! literals into subranges), IL extensible functions with several operands, and pragmas (W0300 for
//! code that does not run, W0301 notes). Results are compared with what IEC 61131-3 gives.

mod common;
use common::{ladderc, write_file};

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Output, Stdio};

fn st_corpus(name: &str) -> PathBuf {
    common::repo_root().join("tests/corpus/st").join(name)
}

/// Runs `ladderc ARGS`, with `stdin` as standard input when given.
fn cmd(args: &[&str], stdin: Option<&str>) -> Output {
    let mut c = ladderc();
    c.args(args)
        .stdin(if stdin.is_some() {
            Stdio::piped()
        } else {
            Stdio::null()
        })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let mut child = c.spawn().unwrap();
    if let Some(text) = stdin {
        child
            .stdin
            .take()
            .unwrap()
            .write_all(text.as_bytes())
            .unwrap();
    }
    child.wait_with_output().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The trace of a successful `run` (printed on standard output): one map per row, column -> value.
fn trace(o: &Output) -> Vec<std::collections::HashMap<String, String>> {
    assert_eq!(o.status.code(), Some(0), "{}", stderr(o));
    let text = String::from_utf8_lossy(&o.stdout);
    let mut lines = text.lines();
    let head: Vec<String> = lines
        .next()
        .expect("a trace header")
        .split(',')
        .map(String::from)
        .collect();
    lines
        .map(|l| {
            head.iter()
                .cloned()
                .zip(l.split(',').map(|v| v.trim_matches('"').to_string()))
                .collect()
        })
        .collect()
}

/// The values of `col` over the rows.
fn column(rows: &[std::collections::HashMap<String, String>], col: &str) -> Vec<String> {
    rows.iter()
        .map(|r| {
            r.get(col)
                .cloned()
                .unwrap_or_else(|| panic!("no column {col}"))
        })
        .collect()
}

/// `(severity, code)` of each diagnostic of a `--message-format json` run.
fn diags(o: &Output) -> Vec<(String, String, u64)> {
    stderr(o)
        .lines()
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        // diagnostics, not the summary record
        .filter(|v| v["kind"] != "summary")
        .map(|v| {
            (
                v["severity"].as_str().unwrap_or("").to_string(),
                v["code"].as_str().unwrap_or("").to_string(),
                v["line"].as_u64().unwrap_or(0),
            )
        })
        .collect()
}

fn errors(o: &Output) -> Vec<(String, u64)> {
    diags(o)
        .into_iter()
        .filter(|d| d.0 == "error")
        .map(|d| (d.1, d.2))
        .collect()
}

// ------------------------------------------------------------------ the corpus of real .st files

#[test]
fn corpus_programs_run_with_iec_results() {
    // IronPLC's getting-started counter: one increment per 100 ms task cycle.
    let p = st_corpus("getting_started.st");
    let rows = trace(&cmd(
        &[
            "run",
            p.to_str().unwrap(),
            "--cycles",
            "5",
            "--cycle-ms",
            "100",
        ],
        None,
    ));
    assert_eq!(
        column(&rows, "plc_task_instance.Counter"),
        ["1", "2", "3", "4", "5"]
    );

    // TON with IN = NOT Button = TRUE from t = 0: Q rises when ET reaches PT = 500 ms.
    let p = st_corpus("quickstart_timer.st");
    let rows = trace(&cmd(
        &[
            "run",
            p.to_str().unwrap(),
            "--cycles",
            "8",
            "--cycle-ms",
            "100",
            "--watch",
            "plc_task_instance.Buzzer",
        ],
        None,
    ));
    assert_eq!(
        column(&rows, "plc_task_instance.Buzzer"),
        ["0", "0", "0", "0", "0", "1", "1", "1"]
    );

    // The start/stop latch: MotorContactor := (Start OR MotorContactor) AND Stop (Stop is NC).
    let dir = tempfile::tempdir().unwrap();
    let stim = write_file(
        dir.path(),
        "s.csv",
        "cycle,variable,value\n0,plc_task_instance.StopButton,1\n2,plc_task_instance.StartButton,1\n\
         3,plc_task_instance.StartButton,0\n5,plc_task_instance.StopButton,0\n",
    );
    let p = st_corpus("motor.st");
    let rows = trace(&cmd(
        &[
            "run",
            p.to_str().unwrap(),
            "--cycles",
            "7",
            "--cycle-ms",
            "100",
            "--stimulus",
            stim.to_str().unwrap(),
            "--watch",
            "plc_task_instance.MotorContactor",
        ],
        None,
    ));
    assert_eq!(
        column(&rows, "plc_task_instance.MotorContactor"),
        ["0", "0", "1", "1", "1", "0", "0"]
    );

    let p = st_corpus("steel_thread.st");
    let rows = trace(&cmd(&["run", p.to_str().unwrap(), "--cycles", "1"], None));
    assert_eq!(column(&rows, "main.y"), ["42"]);

    let p = st_corpus("wstring_ops.st");
    let rows = trace(&cmd(&["run", p.to_str().unwrap(), "--cycles", "1"], None));
    assert_eq!(column(&rows, "main.c"), ["foobar"]);
    assert_eq!(column(&rows, "main.n"), ["3"]);
    assert_eq!(column(&rows, "main.eq"), ["0"]);

    let p = st_corpus("uses_bool_to_string.st");
    let rows = trace(&cmd(&["run", p.to_str().unwrap(), "--cycles", "1"], None));
    assert_eq!(column(&rows, "main.okTrue"), ["1"]);
    assert_eq!(column(&rows, "main.okFalse"), ["1"]);

    let p = st_corpus("quickstart_helloworld.st");
    let rows = trace(&cmd(&["run", p.to_str().unwrap(), "--cycles", "1"], None));
    assert_eq!(column(&rows, "main.Buzzer"), ["1"]);

    // Buzzer AT %QX1 := NOT Button AT %IX1.
    let stim = write_file(dir.path(), "m.csv", "1,%IX1,1\n");
    let p = st_corpus("main.st");
    let rows = trace(&cmd(
        &[
            "run",
            p.to_str().unwrap(),
            "--cycles",
            "2",
            "--cycle-ms",
            "100",
            "--stimulus",
            stim.to_str().unwrap(),
            "--watch",
            "%QX1",
        ],
        None,
    ));
    assert_eq!(column(&rows, "%QX1"), ["1", "0"]);
}

#[test]
fn corpus_libraries_check() {
    for f in [
        "first_steps_func_avg_val.st",
        "first_steps_data_type_decl.st",
        "var_temp.st",
        "array_of_string.st",
        "c_style_block_comment.st",
        "sized_string_contexts.st",
        "time_function_decl.st",
        "Tc2_System.st",
    ] {
        let p = st_corpus(f);
        let o = cmd(
            &["check", p.to_str().unwrap(), "--message-format", "json"],
            None,
        );
        assert_eq!(o.status.code(), Some(0), "{f}: {}", stderr(&o));
        assert!(errors(&o).is_empty(), "{f}");
    }
}

#[test]
fn corpus_files_needing_what_is_missing_get_one_located_error() {
    // Beremiz's first steps as IronPLC keeps it (ST POUs and one in textual SFC, compiled): only the
    // program its configuration instantiates is missing from the file.
    let p = st_corpus("first_steps.st");
    let o = cmd(
        &["check", p.to_str().unwrap(), "--message-format", "json"],
        None,
    );
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(errors(&o), [("E1024".to_string(), 174)], "{}", stderr(&o));

    // `PI` comes from TwinCAT's Tc2_System library.
    let p = st_corpus("uses_pi.st");
    let o = cmd(
        &["check", p.to_str().unwrap(), "--message-format", "json"],
        None,
    );
    assert_eq!(o.status.code(), Some(1));
    let e = errors(&o);
    assert_eq!(e.len(), 1, "{}", stderr(&o));
    assert_eq!(e[0].0, "E1001");
    assert!(stderr(&o).contains("`PI`"));
}

// ------------------------------------------------------------------ languages and inputs

const MIXED: &str = "\
TYPE Level : INT (0..100); END_TYPE
FUNCTION add3 : INT
VAR_INPUT a, b, c : INT; END_VAR
  add3 := a + b + c;
END_FUNCTION
FUNCTION_BLOCK latch
VAR_INPUT s : BOOL; END_VAR
VAR_OUTPUT q : BOOL; END_VAR
  LD s
  OR q
  ST q
END_FUNCTION_BLOCK
PROGRAM main
VAR n : INT; lv : Level; l : latch; x : BOOL; mx : INT; m : INT; END_VAR
  n := n + 1;
  lv := 5;
  l(s := n > 3);
  x := XOR(l.q, TRUE);
  mx := MAX(n, 2, 7);
  m := LIMIT(MN := 0, IN := n, MX := 10) + add3(1, 2, 3) + MOD(n, 2);
END_PROGRAM
";

/// The expected trace of [`MIXED`] over `cycles` cycles, computed with IEC semantics.
fn mixed_expected(cycles: i32) -> Vec<[i32; 5]> {
    let mut q = false;
    (1..=cycles)
        .map(|n| {
            q = q || n > 3;
            let x = q ^ true;
            let mx = n.max(2).max(7);
            let m = n.clamp(0, 10) + 6 + n % 2;
            [n, 5, x as i32, mx, m]
        })
        .collect()
}

fn check_mixed(o: &Output, cycles: i32) {
    let rows = trace(o);
    let got: Vec<[i32; 5]> = rows
        .iter()
        .map(|r| {
            let v = |c: &str| r[c].parse::<i32>().unwrap();
            [
                v("main.n"),
                v("main.lv"),
                v("main.x"),
                v("main.mx"),
                v("main.m"),
            ]
        })
        .collect();
    assert_eq!(got, mixed_expected(cycles));
}

const WATCH: &str = "main.n,main.lv,main.x,main.mx,main.m";

#[test]
fn st_file_with_functional_calls_il_body_and_subrange_literal_runs() {
    let dir = tempfile::tempdir().unwrap();
    let p = write_file(dir.path(), "mixed.st", MIXED);
    let o = cmd(
        &[
            "run",
            p.to_str().unwrap(),
            "--cycles",
            "6",
            "--watch",
            WATCH,
        ],
        None,
    );
    check_mixed(&o, 6);
}

#[test]
fn txt_and_no_extension_are_detected_with_a_note() {
    let dir = tempfile::tempdir().unwrap();
    let p = write_file(dir.path(), "mixed.txt", MIXED);
    let o = cmd(
        &[
            "run",
            p.to_str().unwrap(),
            "--cycles",
            "4",
            "--watch",
            WATCH,
            "--message-format",
            "json",
        ],
        None,
    );
    check_mixed(&o, 4);
    let notes: Vec<_> = diags(&o).into_iter().filter(|d| d.1 == "W0302").collect();
    assert_eq!(notes.len(), 1);
    assert_eq!(notes[0].0, "note");
    assert!(stderr(&o).contains("Structured Text"), "{}", stderr(&o));

    let il = write_file(
        dir.path(),
        "prog",
        "PROGRAM p\nVAR n : INT; END_VAR\n  LD n\n  ADD 2\n  ST n\nEND_PROGRAM\n",
    );
    let o = cmd(
        &[
            "run",
            il.to_str().unwrap(),
            "--cycles",
            "2",
            "--message-format",
            "json",
        ],
        None,
    );
    assert_eq!(column(&trace(&o), "p.n"), ["2", "4"]);
    assert!(
        stderr(&o).contains("instruction list (IL) (detected"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn lang_forces_the_language_and_st_in_il_is_one_error() {
    let dir = tempfile::tempdir().unwrap();
    // An .il file holding ST: one E0300 for the file, naming every ST body, no cascade.
    let p = write_file(dir.path(), "mixed.il", MIXED);
    let o = cmd(
        &["check", p.to_str().unwrap(), "--message-format", "json"],
        None,
    );
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(errors(&o), [("E0300".to_string(), 4)], "{}", stderr(&o));
    assert!(stderr(&o).contains("main"), "{}", stderr(&o));
    // `--lang st` reads the same file as ST, and it runs.
    let o = cmd(
        &[
            "run",
            p.to_str().unwrap(),
            "--lang",
            "st",
            "--cycles",
            "3",
            "--watch",
            WATCH,
        ],
        None,
    );
    check_mixed(&o, 3);
    // `--lang il` on an .st file: the same single diagnostic.
    let p = write_file(dir.path(), "m.st", MIXED);
    let o = cmd(
        &[
            "check",
            "--lang",
            "il",
            p.to_str().unwrap(),
            "--message-format",
            "json",
        ],
        None,
    );
    assert_eq!(errors(&o), [("E0300".to_string(), 4)], "{}", stderr(&o));
}

#[test]
fn dash_reads_standard_input() {
    // Detected from the content, named <stdin>.
    let o = cmd(
        &["run", "-", "--cycles", "3", "--watch", WATCH],
        Some(MIXED),
    );
    check_mixed(&o, 3);
    let o = cmd(
        &["check", "-", "--message-format", "short"],
        Some("PROGRAM p\nVAR x : INT; END_VAR\n  x := y;\nEND_PROGRAM\n"),
    );
    assert_eq!(o.status.code(), Some(1));
    let e = stderr(&o);
    assert!(e.contains("<stdin>:3:8: error[E1001]"), "{e}");
    // With --lang il, standard input is IL.
    let o = cmd(
        &["run", "-", "--lang", "il", "--cycles", "2"],
        Some("PROGRAM p\nVAR n : INT; END_VAR\n  LD n\n  ADD 3\n  ST n\nEND_PROGRAM\n"),
    );
    assert_eq!(column(&trace(&o), "p.n"), ["3", "6"]);
}

// ------------------------------------------------------------------ IL extensible functions

#[test]
fn il_extensible_functions_take_several_operands() {
    // IEC 61131-3: `ADD b, c` is ADD(CR, b, c); `GT b, c` is GT(CR, b, c) = CR > b AND b > c.
    let src = "PROGRAM main\nVAR n : INT; m : INT; a : INT; g : BOOL; e : BOOL; END_VAR\n\
               LD n\nADD 1\nST n\n\
               LD n\nMAX 2, 7\nST m\n\
               LD n\nADD 10, 100\nST a\n\
               LD 5\nGT n, 2\nST g\n\
               LD n\nEQ 3, n\nST e\n\
               END_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    let p = write_file(dir.path(), "ext.il", src);
    let rows = trace(&cmd(&["run", p.to_str().unwrap(), "--cycles", "7"], None));
    for (k, r) in rows.iter().enumerate() {
        let n = k as i32 + 1;
        assert_eq!(r["main.m"], n.max(7).to_string());
        assert_eq!(r["main.a"], (n + 110).to_string());
        assert_eq!(r["main.g"], ((5 > n && n > 2) as i32).to_string());
        assert_eq!(r["main.e"], ((n == 3) as i32).to_string());
    }
    // A non-extensible operator with two operands is one E0301.
    let p = write_file(
        dir.path(),
        "bad.il",
        "PROGRAM main\nVAR n : INT; END_VAR\nLD n\nSUB 1, 2\nST n\nEND_PROGRAM\n",
    );
    let o = cmd(
        &["check", p.to_str().unwrap(), "--message-format", "json"],
        None,
    );
    assert_eq!(errors(&o), [("E0301".to_string(), 4)], "{}", stderr(&o));
}

// ------------------------------------------------------------------ pragmas

#[test]
fn pragmas_are_never_dropped_silently() {
    let src = "{attribute 'qualified_only'}\nPROGRAM main\nVAR go : BOOL := TRUE; out : BOOL; n : INT; END_VAR\n\
               IF go THEN\n  {SetFbVar(OUT, 1)}\n  n := n + 1;\nEND_IF;\n\
               {{ if (x) { y(); } }}\n{warning 'check me'}\nEND_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    let p = write_file(dir.path(), "pragmas.st", src);
    let o = cmd(
        &[
            "run",
            p.to_str().unwrap(),
            "--cycles",
            "2",
            "--message-format",
            "json",
        ],
        None,
    );
    let rows = trace(&o);
    // The C code did not run: `out` stays FALSE; the ST around it did.
    assert_eq!(column(&rows, "main.out"), ["0", "0"]);
    assert_eq!(column(&rows, "main.n"), ["1", "2"]);
    let mut d = diags(&o);
    d.sort_by_key(|x| x.2);
    assert_eq!(
        d,
        [
            ("note".to_string(), "W0301".to_string(), 1),
            ("warning".to_string(), "W0300".to_string(), 5),
            ("warning".to_string(), "W0300".to_string(), 8),
            ("note".to_string(), "W0301".to_string(), 9),
        ],
        "{}",
        stderr(&o)
    );
    assert!(stderr(&o).contains("SetFbVar(OUT, 1)"), "{}", stderr(&o));
    assert!(stderr(&o).contains("does not run"), "{}", stderr(&o));
}

// ------------------------------------------------------------------ FBD literals typed by context

#[test]
fn fbd_literals_take_the_type_of_their_destination() {
    // `5` -> MOVE -> INT, `-3` -> MOVE -> SINT, `7` -> MOVE -> a subrange of INT, `MAX(9, 4)` -> INT:
    // the untyped literals take the destination's type (IEC 61131-3), not DINT. A string literal
    // with `#` and `$` escapes in an <expression> is a literal.
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/fbd_literals.xml");
    let rows = trace(&cmd(
        &[
            "run",
            p.to_str().unwrap(),
            "--cycles",
            "1",
            "--watch",
            "main.I,main.S,main.L,main.C,main.T,main.M",
        ],
        None,
    ));
    let r = &rows[0];
    assert_eq!(r["main.I"], "5");
    assert_eq!(r["main.S"], "-3");
    assert_eq!(r["main.L"], "7");
    assert_eq!(r["main.C"], "2");
    assert_eq!(r["main.T"], "Step #1 $5 'ok'");
    assert_eq!(r["main.M"], "9");
}

#[test]
fn methods_and_textual_sfc_are_one_diagnostic_each() {
    // (a METHOD of a function block is compiled since issue #13's last gaps, a PROPERTY with its
    // GET/SET accessors too: this one has none, its statements stand in the PROPERTY itself)
    let src = "FUNCTION_BLOCK Motor\nVAR speed : INT; END_VAR\n  PROPERTY PUBLIC Speed : INT\n    Speed := speed;\n  END_PROPERTY\n  speed := speed + 1;\nEND_FUNCTION_BLOCK\n\
               PROGRAM main\nVAR m : Motor; END_VAR\n  m();\nEND_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    let p = write_file(dir.path(), "oop.st", src);
    let o = cmd(
        &["check", p.to_str().unwrap(), "--message-format", "json"],
        None,
    );
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(errors(&o), [("E0100".to_string(), 3)], "{}", stderr(&o));
}

#[test]
fn function_without_inputs_is_called_with_empty_parentheses() {
    // `five()` reads no current result: y = 5 + 1 (before, E1007 and E1020).
    let src = "FUNCTION five : INT\n  five := 5;\nEND_FUNCTION\n\
               PROGRAM main\nVAR y : INT; END_VAR\n  y := five() + 1;\nEND_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    let p = write_file(dir.path(), "five.st", src);
    let rows = trace(&cmd(&["run", p.to_str().unwrap(), "--cycles", "1"], None));
    assert_eq!(column(&rows, "main.y"), ["6"]);
}
