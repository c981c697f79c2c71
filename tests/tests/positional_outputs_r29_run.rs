//! Round 29 of issue #13: a call of a block that lists every parameter by position, outputs
//! included, in declaration order: IEC 61131-3 ed. 2 Table 53's `CAL C10(%IX10, FALSE, A, OUT, B)`
//! (C10 a CTU: CU, R, PV receive `%IX10`, `FALSE`, `A`; `OUT` receives Q and `B` CV), ed. 3
//! 6.6.1.4.2 ("a non-formal call lists the parameters in the order of the declaration"). The
//! arguments at output positions are the variables the outputs are written to after the call, as
//! `Q => OUT`. Before: E1020 ("not in IL's CAL nor for a standard block") for IL and for ST calls of
//! standard blocks. Run end to end through `ladderc run` (C built with the sanitizers in
//! `run_stimulated`).

mod common;
use common::{check_text, column, run_stimulated, run_text};

/// The standard's own example, in IL: `CAL cnt(pulse, FALSE, limit, full, value)` counts the
/// rising edges of `pulse` into `value` and sets `full` at the limit, as the formal call does.
#[test]
fn il_cal_of_a_standard_block_with_every_parameter_by_position_writes_its_outputs() {
    let positional = "PROGRAM Main
VAR
  cnt : CTU;
  pulse : BOOL;
  limit : INT := 3;
  full : BOOL;
  value : INT;
END_VAR
  LD pulse
  NOT
  ST pulse
  CAL cnt(pulse, FALSE, limit, full, value)
END_PROGRAM
";
    let (code, lines) = check_text("cal.il", positional);
    assert_eq!(code, Some(0), "{lines:?}");
    let named = positional.replace(
        "CAL cnt(pulse, FALSE, limit, full, value)",
        "CAL cnt(CU := pulse, R := FALSE, PV := limit, Q => full, CV => value)",
    );
    for src in [positional, named.as_str()] {
        let (trace, stderr) = run_text("cal.il", src, 8, "Main.value,Main.full");
        assert!(!stderr.contains("error["), "{stderr}");
        assert_eq!(
            column(&trace, "Main.value"),
            vec![1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0],
            "{trace}"
        );
        assert_eq!(
            column(&trace, "Main.full"),
            vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
            "{trace}"
        );
    }
}

/// A TON by position in IL (IN, PT, Q, ET): the elapsed time reaches the TIME variable, Q the
/// BOOL; and a user block with locals between its parameters: the locals take no position.
#[test]
fn timer_and_user_block_by_position_in_il() {
    let src = "FUNCTION_BLOCK Scale
VAR_INPUT
  x : INT;
END_VAR
VAR
  calls : INT;
END_VAR
VAR_OUTPUT
  doubled : INT;
END_VAR
VAR_INPUT
  offset : INT;
END_VAR
VAR_OUTPUT
  n : INT;
END_VAR
  LD calls
  ADD 1
  ST calls
  ST n
  LD x
  MUL 2
  ADD offset
  ST doubled
END_FUNCTION_BLOCK

PROGRAM Main
VAR
  t : TON;
  go : BOOL;
  done : BOOL;
  el : TIME;
  elms : DINT;
  s : Scale;
  v : INT := 5;
  out : INT;
  count : INT;
END_VAR
  CAL t(go, T#50ms, done, el)
  LD el
  TIME_TO_DINT
  ST elms
  CAL s(v, out, 100, count)
END_PROGRAM
";
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("main.il");
    std::fs::write(&file, src).unwrap();
    let (trace, stderr) = run_stimulated(
        &file,
        10,
        "2,Main.go,TRUE\n",
        "Main.done,Main.elms,Main.out,Main.count",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    // 10 ms scans; go from cycle 2: elapsed 0 at the first scan that sees it (cycle 2), 50 ms and Q
    // five scans on (cycle 7)
    assert_eq!(
        column(&trace, "Main.elms"),
        vec![0.0, 0.0, 0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 50.0, 50.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "Main.done"),
        vec![0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
        "{trace}"
    );
    // `s(v, out, 100, count)`: x := v, doubled => out, offset := 100, n => count
    assert_eq!(column(&trace, "Main.out"), vec![110.0; 10], "{trace}");
    assert_eq!(
        column(&trace, "Main.count"),
        (1..=10).map(f64::from).collect::<Vec<_>>(),
        "{trace}"
    );
}

/// The same form in ST for a standard block: `cnt(pulse, FALSE, limit, full, value);`.
#[test]
fn st_call_of_a_standard_block_with_every_parameter_by_position() {
    let src = "PROGRAM Main
VAR
  cnt : CTD;
  pulse : BOOL;
  empty : BOOL;
  left : INT;
END_VAR
pulse := NOT pulse;
cnt(pulse, FALSE, 2, empty, left);
END_PROGRAM
";
    let (trace, stderr) = run_text("main.st", src, 6, "Main.left,Main.empty");
    assert!(!stderr.contains("error["), "{stderr}");
    // CTD with LD FALSE counts down from 0: CV -1, -1, -2, ... and Q (CV <= 0) TRUE throughout
    assert_eq!(
        column(&trace, "Main.left"),
        vec![-1.0, -1.0, -2.0, -2.0, -3.0, -3.0],
        "{trace}"
    );
    assert_eq!(column(&trace, "Main.empty"), vec![1.0; 6], "{trace}");
}

/// What stays an error: a count between the inputs and all the parameters (E1020 saying how many
/// a full list has), an output position given a constant (it receives a value: E1020's neighbour
/// for a formal `Q => 1`), and an output of a type the variable cannot hold.
#[test]
fn wrong_positional_lists_stay_located_errors() {
    let base = "PROGRAM Main
VAR
  cnt : CTU;
  pulse : BOOL;
  full : BOOL;
  value : INT;
  big : SINT;
END_VAR
  CAL cnt(ARGS)
END_PROGRAM
";
    let (code, lines) = check_text("a.il", &base.replace("ARGS", "pulse, FALSE, 3, full"));
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("a.il:9:28: error[E1020]"),
        "{lines:?}"
    );
    assert!(
        errors[0].contains("lists all its parameters in order (5 in all)"),
        "{lines:?}"
    );

    let (code, lines) = check_text(
        "b.il",
        &base.replace("ARGS", "pulse, FALSE, 3, TRUE, value"),
    );
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(errors[0].starts_with("b.il:9:28:"), "{lines:?}");

    let (code, lines) = check_text("c.il", &base.replace("ARGS", "pulse, FALSE, 3, full, big"));
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(errors[0].starts_with("c.il:9:34:"), "{lines:?}");
}
