//! End to end: IL -> C -> executable (strict warnings, sanitizers) -> trace.

mod support;
use support::*;

#[test]
fn ctu_counts_rising_edges_and_sets_q_at_pv() {
    let b = build_src(
        "PROGRAM main
VAR
  pulse AT %IX0.0 : BOOL;
  ctr : CTU;
  count : INT;
  done : BOOL;
END_VAR
  CAL ctr(CU := pulse, R := %IX0.1, PV := 3)
  LD ctr.CV
  ST count
  LD ctr.Q
  ST done
  ST %QX0.0
END_PROGRAM
",
    );
    // pulse high on cycles 1-2, 4, 6-7, 9; reset on cycle 11
    let stim = "cycle,variable,value\n1,%IX0.0,TRUE\n3,%IX0.0,FALSE\n4,%IX0.0,1\n5,%IX0.0,0\n6,main.pulse,1\n8,main.pulse,0\n9,%IX0.0,1\n10,%IX0.0,0\n11,%IX0.1,1\n12,%IX0.1,0\n";
    let rows = run(&b, 13, 10.0, stim, &["main.count", "main.done", "%QX0.0"]);
    assert_eq!(
        column(&rows, "main.count"),
        ["0", "1", "1", "1", "2", "2", "3", "3", "3", "4", "4", "0", "0"]
    );
    assert_eq!(
        column(&rows, "main.done"),
        ["0", "0", "0", "0", "0", "0", "1", "1", "1", "1", "1", "0", "0"]
    );
    assert_eq!(column(&rows, "%QX0.0"), column(&rows, "main.done"));
}

#[test]
fn ton_q_rises_exactly_when_pt_has_elapsed_on_the_scan_clock() {
    let b = build_src(
        "PROGRAM main
VAR
  start AT %IX0.0 : BOOL;
  tmr : TON;
  q : BOOL;
  et : TIME;
END_VAR
  LD start
  IN tmr
  LD tmr.Q
  ST q
  LD tmr.ET
  ST et
END_PROGRAM
",
    );
    // PT is set once through the FB input operator before the scan starts? No: set it by stimulus.
    let stim = "0,main.tmr.PT,T#30ms\n2,%IX0.0,TRUE\n8,%IX0.0,FALSE\n";
    let rows = run(&b, 10, 10.0, stim, &["main.q", "main.et"]);
    // IN rises at cycle 2 (20 ms): Q at cycle 5 (50 ms), exactly 30 ms later; IN falls at cycle 8
    assert_eq!(
        column(&rows, "main.q"),
        ["0", "0", "0", "0", "0", "1", "1", "1", "0", "0"]
    );
    assert_eq!(
        column(&rows, "main.et"),
        [
            "T#0ms", "T#0ms", "T#0ms", "T#10ms", "T#20ms", "T#30ms", "T#30ms", "T#30ms", "T#0ms",
            "T#0ms"
        ]
    );
    assert_eq!(
        column(&rows, "time_ms"),
        ["0", "10", "20", "30", "40", "50", "60", "70", "80", "90"]
    );
}

#[test]
fn ton_with_a_cycle_time_that_does_not_divide_pt_rises_on_the_first_cycle_after_it() {
    let b = build_src(
        "PROGRAM main
VAR
  tmr : TON;
  q : BOOL;
END_VAR
  CAL tmr(IN := TRUE, PT := T#25ms)
  LD tmr.Q
  ST q
END_PROGRAM
",
    );
    let rows = run(&b, 5, 10.0, "", &["main.q"]);
    assert_eq!(column(&rows, "main.q"), ["0", "0", "0", "1", "1"]);
    // with a 2.5 ms cycle, Q rises at cycle 10 (25 ms)
    let rows = run(&b, 12, 2.5, "", &["main.q"]);
    let q = column(&rows, "main.q");
    assert_eq!(q.iter().position(|v| v == "1"), Some(10));
    assert_eq!(rows[11][1], "25");
}

#[test]
fn r_trig_pulses_for_exactly_one_cycle() {
    let b = build_src(
        "PROGRAM main
VAR
  trig : R_TRIG;
  ftrig : F_TRIG;
  pulse : BOOL;
  fall : BOOL;
END_VAR
  LD %IX0.0
  CLK trig
  CLK ftrig
  LD trig.Q
  ST pulse
  LD ftrig.Q
  ST fall
END_PROGRAM
",
    );
    let stim = "1,%IX0.0,1\n5,%IX0.0,0\n7,%IX0.0,1\n";
    let rows = run(&b, 9, 10.0, stim, &["main.pulse", "main.fall"]);
    assert_eq!(
        column(&rows, "main.pulse"),
        ["0", "1", "0", "0", "0", "0", "0", "1", "0"]
    );
    // F_TRIG (IEC: M starts FALSE) also fires on the first call with CLK FALSE
    assert_eq!(
        column(&rows, "main.fall"),
        ["1", "0", "0", "0", "0", "1", "0", "0", "0"]
    );
}

#[test]
fn int_arithmetic_wraps_like_int_and_real_stays_real() {
    let b = build_src(
        "PROGRAM main
VAR
  i : INT := 32767;
  s : SINT := -128;
  d : DINT;
  u : UINT;
  r : REAL := 1.0;
  lr : LREAL := 1.0;
  q : INT;
  z : INT;
  m : INT;
END_VAR
  LD i
  ADD 1
  ST i
  LD s
  SUB 1
  ST s
  LD 2147483647
  ADD 1
  ST d
  LD u
  SUB 1
  ST u
  LD r
  DIV 3.0
  ST r
  LD lr
  DIV 3.0
  ST lr
  LD -32768
  DIV -1
  ST q
  LD 7
  DIV z
  ST z
  LD -7
  MOD 3
  ST m
END_PROGRAM
",
    );
    let out = c_backend::run(
        &b.exe,
        &c_backend::RunOptions {
            cycles: 2,
            watch: [
                "main.i", "main.s", "main.d", "main.u", "main.r", "main.lr", "main.q", "main.z",
                "main.m",
            ]
            .iter()
            .map(|s| s.to_string())
            .collect(),
            ..Default::default()
        },
    )
    .unwrap();
    assert!(out.success(), "{}", out.stderr);
    let lines: Vec<&str> = out.stdout.lines().collect();
    assert_eq!(
        lines[0],
        "cycle,time_ms,main.i,main.s,main.d,main.u,main.r,main.lr,main.q,main.z,main.m"
    );
    assert_eq!(
        lines[1],
        "0,0,-32768,127,-2147483648,65535,0.33333334,0.3333333333333333,-32768,0,-1"
    );
    assert_eq!(
        lines[2],
        "1,10,-32767,126,-2147483648,65534,0.11111111,0.1111111111111111,-32768,0,-1"
    );
    // division by zero gives 0 and is reported once at the end
    assert!(out.stderr.contains("division by zero"), "{}", out.stderr);
}

#[test]
fn cal_with_literal_arguments_and_outputs() {
    let b = build_src(
        "PROGRAM main
VAR
  tp1 : TP;
  c : CTUD;
  pulse : BOOL;
  cv : INT;
  up : BOOL;
END_VAR
  CAL tp1(IN := TRUE, PT := T#20ms, Q => pulse)
  CAL c(CU := %IX0.0, CD := FALSE, R := FALSE, LD := FALSE, PV := 2, QU => up, CV => cv)
END_PROGRAM
",
    );
    let stim = "1,%IX0.0,1\n2,%IX0.0,0\n3,%IX0.0,1\n";
    let rows = run(&b, 5, 10.0, stim, &["main.pulse", "main.cv", "main.up"]);
    assert_eq!(column(&rows, "main.pulse"), ["1", "1", "0", "0", "0"]);
    assert_eq!(column(&rows, "main.cv"), ["0", "1", "1", "2", "2"]);
    assert_eq!(column(&rows, "main.up"), ["0", "0", "0", "1", "1"]);
}

/// The logic of corpus file 18 (nested `OR(` / `AND(` / `ORN(` on %I bits), evaluated in Rust.
fn corpus18_expected(i: &dyn Fn(u32, u32) -> bool) -> bool {
    let inner = i(0, 3) || (i(0, 2) || i(0, 1));
    let first = i(0, 4) || (i(1, 2) && inner);
    let second = i(0, 6) && (i(1, 0) || (i(0, 7) || !(i(0, 5) && inner)));
    first || second
}

#[test]
fn nested_deferred_operators_evaluate_as_written_corpus_18() {
    let text = std::fs::read_to_string(test_corpus::path("il/18_il_parser_test1.il")).unwrap();
    // The file is a bare body ending in `S` (no operand) and `ST %Q0.0`: wrap it in a PROGRAM and drop
    // the operand-less `S`, which is not IEC (the analysis rejects it).
    let body: Vec<&str> = text.lines().filter(|l| l.trim() != "S").collect();
    let src = format!("PROGRAM p\n{}\nEND_PROGRAM\n", body.join("\n"));
    let b = build_src(&src);
    let inputs = [
        (0, 1),
        (0, 2),
        (0, 3),
        (0, 4),
        (0, 5),
        (0, 6),
        (0, 7),
        (1, 0),
        (1, 2),
    ];
    let mut stim = String::new();
    for cycle in 0..(1u32 << inputs.len()) {
        for (k, (byte, bit)) in inputs.iter().enumerate() {
            stim.push_str(&format!("{cycle},%IX{byte}.{bit},{}\n", (cycle >> k) & 1));
        }
    }
    let rows = run(&b, 1 << inputs.len(), 1.0, &stim, &["%QX0.0"]);
    let q = column(&rows, "%QX0.0");
    let mut ones = 0;
    for cycle in 0..(1u32 << inputs.len()) {
        let bit = |byte: u32, bit: u32| {
            let k = inputs.iter().position(|x| *x == (byte, bit)).unwrap();
            (cycle >> k) & 1 == 1
        };
        let want = corpus18_expected(&bit);
        ones += usize::from(want);
        assert_eq!(
            q[cycle as usize],
            if want { "1" } else { "0" },
            "inputs {cycle:09b}"
        );
    }
    assert!(
        ones > 0 && ones < 512,
        "the expression must depend on the inputs"
    );
}

#[test]
fn jumps_labels_and_conditional_return() {
    let b = build_src(
        "PROGRAM main
VAR
  n : INT;
  sum : INT;
  k : INT;
END_VAR
  LD 0
  ST sum
  ST k
loop:
  LD k
  GE n
  JMPC done
  LD sum
  ADD k
  ST sum
  LD k
  ADD 1
  ST k
  JMP loop
done:
  LD sum
  GT 100
  RETC
  LD n
  ADD 1
  ST n
END_PROGRAM
",
    );
    let rows = run(&b, 20, 10.0, "", &["main.n", "main.sum"]);
    let n = column(&rows, "main.n");
    let sum = column(&rows, "main.sum");
    // each cycle sums 0..n-1 with the n it starts with, then counts n up unless the sum exceeds 100
    for (c, (n, s)) in n.iter().zip(&sum).enumerate() {
        let n: i64 = n.parse().unwrap();
        let s: i64 = s.parse().unwrap();
        let n_before = if s > 100 { n } else { n - 1 };
        assert_eq!(s, n_before * (n_before - 1) / 2, "cycle {c}");
    }
    assert_eq!(n.last().unwrap(), "15");
}
