//! The typed counters of IEC 61131-3 edition 2/3 (CTU_DINT ... CTUD_ULINT) end to end: counting on rising
//! edges, loading and resetting, and saturation at the limits of their own type (not INT's).

mod support;
use support::*;

#[test]
fn ctu_dint_counts_past_the_int_range_and_saturates_at_the_dint_maximum() {
    let b = build_src(
        "PROGRAM main
VAR
  cu : BOOL;
  r : BOOL;
  c : CTU_DINT;
  cv : DINT;
  q : BOOL;
END_VAR
  CAL c(CU := cu, R := r, PV := 40000)
  LD c.CV
  ST cv
  LD c.Q
  ST q
END_PROGRAM
",
    );
    // CV preset just below 40000, then near the DINT maximum (through the stimulus).
    let stim = "0,main.c.CV,39999\n1,main.cu,1\n2,main.cu,0\n3,main.c.CV,2147483646\n3,main.cu,1\n4,main.cu,0\n5,main.cu,1\n6,main.cu,0\n7,main.cu,1\n8,main.r,1\n";
    let rows = run(&b, 9, 10.0, stim, &["main.cv", "main.q"]);
    assert_eq!(
        column(&rows, "main.cv"),
        [
            "39999",
            "40000",
            "40000",
            "2147483647",
            "2147483647",
            "2147483647",
            "2147483647",
            "2147483647",
            "0"
        ]
    );
    assert_eq!(
        column(&rows, "main.q"),
        ["0", "1", "1", "1", "1", "1", "1", "1", "0"]
    );
}

#[test]
fn ctd_udint_loads_pv_counts_down_and_stops_at_zero() {
    let b = build_src(
        "PROGRAM main
VAR
  cd : BOOL;
  ld : BOOL;
  c : CTD_UDINT;
  cv : UDINT;
  q : BOOL;
END_VAR
  CAL c(CD := cd, LD := ld, PV := 3000000000)
  LD c.CV
  ST cv
  LD c.Q
  ST q
END_PROGRAM
",
    );
    let stim = "0,main.ld,1\n1,main.ld,0\n1,main.cd,1\n2,main.cd,0\n3,main.c.CV,1\n3,main.cd,1\n4,main.cd,0\n5,main.cd,1\n";
    let rows = run(&b, 6, 10.0, stim, &["main.cv", "main.q"]);
    assert_eq!(
        column(&rows, "main.cv"),
        ["3000000000", "2999999999", "2999999999", "0", "0", "0"]
    );
    assert_eq!(column(&rows, "main.q"), ["0", "0", "0", "1", "1", "1"]);
}

#[test]
fn ctud_lint_and_ulint_count_both_ways_with_their_own_types() {
    let b = build_src(
        "PROGRAM main
VAR
  cu : BOOL;
  cd : BOOL;
  a : CTUD_LINT;
  u : CTUD_ULINT;
  d : CTUD_DINT;
  x : CTU_ULINT;
  y : CTD_LINT;
  z : CTU_LINT;
  w : CTD_DINT;
  v : CTUD_UDINT;
  av : LINT;
  uv : ULINT;
  qd : BOOL;
END_VAR
  CAL a(CU := cu, CD := cd, PV := 2)
  CAL u(CU := cu, CD := cd, PV := 18446744073709551615)
  CAL d(CU := cu, CD := cd)
  CAL x(CU := cu)
  CAL y(CD := cd)
  CAL z(CU := cu)
  CAL w(CD := cd)
  CAL v(CU := cu)
  LD a.CV
  ST av
  LD u.CV
  ST uv
  LD u.QD
  ST qd
END_PROGRAM
",
    );
    // up, up, down, down, down (a goes negative, u stops at 0), both edges at once (ignored)
    let stim = "1,main.cu,1\n2,main.cu,0\n3,main.cu,1\n4,main.cu,0\n5,main.cd,1\n6,main.cd,0\n7,main.cd,1\n8,main.cd,0\n9,main.cd,1\n10,main.cd,0\n11,main.cu,1\n11,main.cd,1\n";
    let rows = run(&b, 12, 10.0, stim, &["main.av", "main.uv", "main.qd"]);
    assert_eq!(
        column(&rows, "main.av"),
        ["0", "1", "1", "2", "2", "1", "1", "0", "0", "-1", "-1", "-1"]
    );
    assert_eq!(
        column(&rows, "main.uv"),
        ["0", "1", "1", "2", "2", "1", "1", "0", "0", "0", "0", "0"]
    );
    assert_eq!(
        column(&rows, "main.qd"),
        ["1", "0", "0", "0", "0", "0", "0", "1", "1", "1", "1", "1"]
    );
}
