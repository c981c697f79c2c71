//! Language features through the whole chain: user FBs and functions, standard functions, conversions,
//! structures, arrays, enumerations, strings, located variables of every size.

mod support;
use support::*;

#[test]
fn user_function_block_and_function_with_outputs() {
    let src = "FUNCTION scale : INT
VAR_INPUT
  x : INT;
  k : INT := 3;
END_VAR
VAR_OUTPUT
  twice : INT;
END_VAR
  LD x
  MUL 2
  ST twice
  LD x
  MUL k
  ST scale
END_FUNCTION
FUNCTION_BLOCK latch
VAR_INPUT
  set : BOOL;
  reset : BOOL;
END_VAR
VAR_OUTPUT
  q : BOOL;
  hits : INT;
END_VAR
  LD set
  ANDN reset
  S q
  LD reset
  R q
  LD set
  JMPCN skip
  LD hits
  ADD 1
  ST hits
  LD set
skip:
END_FUNCTION_BLOCK
PROGRAM main
VAR
  l : latch;
  y : INT;
  y0 : INT;
  t : INT;
  lit : BOOL;
  n : INT;
END_VAR
  LD %IW0
  WORD_TO_INT
  ST y0
  scale(x := y0, k := 5, twice => t)
  ST y
  CAL l(set := %IX2.0, reset := %IX2.1, q => lit)
  LD l.hits
  ST n
END_PROGRAM
";
    let b = build_src(src);
    let stim = "0,%IW0,7\n1,%IX2.0,1\n2,%IX2.0,0\n3,%IX2.1,1\n";
    let rows = run(
        &b,
        5,
        10.0,
        stim,
        &["main.y", "main.t", "main.lit", "main.n"],
    );
    assert_eq!(column(&rows, "main.y"), ["35", "35", "35", "35", "35"]);
    assert_eq!(column(&rows, "main.t"), ["14", "14", "14", "14", "14"]);
    assert_eq!(column(&rows, "main.lit"), ["0", "1", "1", "0", "0"]);
    assert_eq!(column(&rows, "main.n"), ["0", "1", "1", "1", "1"]);
}

#[test]
fn standard_functions_and_conversions() {
    let src = "PROGRAM main
VAR
  sel : INT;
  lim : INT;
  mx : INT;
  mux : INT;
  r2i : INT;
  i2r : REAL;
  bcd : INT;
  tobcd : WORD;
  shl : WORD;
  rol : BYTE;
  ab : DINT;
  sq : LREAL;
  tms : DINT;
  t : TIME;
  cmp : BOOL;
END_VAR
  LD %IX0.0
  SEL 10, 20
  ST sel
  LD 0
  LIMIT 150, 100
  ST lim
  LD 3
  MAX 9, -2
  ST mx
  LD 2
  MUX 100, 200, 300
  ST mux
  LD 2.5
  REAL_TO_INT
  ST r2i
  LD -7
  INT_TO_REAL
  ST i2r
  LD 16#1234
  WORD_BCD_TO_INT
  ST bcd
  LD 1234
  INT_TO_BCD_WORD
  ST tobcd
  LD 16#00F0
  SHL 4
  ST shl
  LD 16#81
  ROL 1
  ST rol
  LD -5
  ABS
  ST ab
  LD 2.0
  SQRT
  ST sq
  LD T#1500ms
  TIME_TO_DINT
  ST tms
  LD 250
  DINT_TO_TIME
  ST t
  LD 5
  GT 3
  AND( 1
  LT 2
  )
  ST cmp
END_PROGRAM
";
    let b = build_src(src);
    let rows = run(
        &b,
        2,
        10.0,
        "1,%IX0.0,1\n",
        &[
            "main.sel",
            "main.lim",
            "main.mx",
            "main.mux",
            "main.r2i",
            "main.i2r",
            "main.bcd",
            "main.tobcd",
            "main.shl",
            "main.rol",
            "main.ab",
            "main.sq",
            "main.tms",
            "main.t",
            "main.cmp",
        ],
    );
    assert_eq!(
        rows[1][2..].join(","),
        "10,100,9,300,2,-7,1234,4660,3840,3,5,1.4142135623730951,1500,T#250ms,1"
    );
    assert_eq!(rows[2][2], "20");
}

#[test]
fn structures_arrays_enumerations_and_strings() {
    let src = "TYPE
  mode : (idle, running, fault);
  point : STRUCT
    x : INT := 4;
    y : INT;
  END_STRUCT;
END_TYPE
PROGRAM main
VAR
  m : mode;
  p : point;
  arr : ARRAY [1..4] OF INT;
  i : INT := 1;
  total : INT;
  name : STRING[5] := 'abc';
  longer : STRING;
  is_running : BOOL;
END_VAR
  LD i
  MUL 10
  ST arr[i]
  LD total
  ADD arr[i]
  ST total
  LD i
  ADD 1
  ST i
  LD m
  EQ running
  ST is_running
  LD running
  ST m
  LD p.x
  ADD 1
  ST p.x
  LD 'abcdefgh'
  ST name
END_PROGRAM
";
    let b = build_src(src);
    let rows = run(
        &b,
        3,
        10.0,
        "",
        &[
            "main.arr[1]",
            "main.arr[2]",
            "main.total",
            "main.is_running",
            "main.m",
            "main.p.x",
            "main.name",
        ],
    );
    assert_eq!(column(&rows, "main.arr[1]"), ["10", "10", "10"]);
    assert_eq!(column(&rows, "main.arr[2]"), ["0", "20", "20"]);
    assert_eq!(column(&rows, "main.total"), ["10", "30", "60"]);
    assert_eq!(column(&rows, "main.is_running"), ["0", "1", "1"]);
    assert_eq!(column(&rows, "main.m"), ["1", "1", "1"]);
    assert_eq!(column(&rows, "main.p.x"), ["5", "6", "7"]);
    // STRING[5] keeps 5 bytes of the 8
    assert_eq!(
        column(&rows, "main.name"),
        ["\"abcde\"", "\"abcde\"", "\"abcde\""]
    );
}

#[test]
fn array_index_out_of_range_is_defined_and_reported() {
    let src = "PROGRAM main
VAR
  arr : ARRAY [0..2] OF INT;
  i : INT := 7;
END_VAR
  LD 5
  ST arr[i]
END_PROGRAM
";
    let b = build_src(src);
    let out = c_backend::run(
        &b.exe,
        &c_backend::RunOptions {
            cycles: 1,
            watch: vec!["main.arr[0]".into()],
            ..Default::default()
        },
    )
    .unwrap();
    assert!(out.success(), "{}", out.stderr);
    assert_eq!(out.stdout, "cycle,time_ms,main.arr[0]\n0,0,5\n");
    assert!(
        out.stderr.contains("array index out of range"),
        "{}",
        out.stderr
    );
}

#[test]
fn located_variables_of_every_size_alias_the_process_image() {
    let src = "PROGRAM main
VAR
  b AT %QB1 : BYTE;
  w AT %QW1 : WORD;
  d AT %QD1 : DINT;
  r AT %MD2 : REAL;
  inw AT %IW3 : INT;
  bit AT %QX0.7 : BOOL;
END_VAR
  LD 16#AB
  ST b
  LD 16#1234
  ST w
  LD -2
  ST d
  LD 1.5
  ST r
  LD inw
  ADD 1
  ST inw
  LD TRUE
  ST bit
END_PROGRAM
";
    let b = build_src(src);
    let rows = run(
        &b,
        1,
        10.0,
        "0,%IW3,65535\n",
        &[
            "%QB1", "%QB2", "%QB3", "%QW1", "%QD1", "%MD2", "main.r", "main.inw", "%IW3", "%QB0",
            "main.d",
        ],
    );
    // element numbering: %QW1 is bytes 2..3, %QD1 bytes 4..7, little endian
    assert_eq!(
        rows[1][2..].join(","),
        "171,52,18,4660,4294967294,1069547520,1.5,0,0,128,-2"
    );
}

#[test]
fn string_conversions() {
    let src = "PROGRAM main
VAR
  s : STRING;
  t : STRING;
  u : STRING;
  b : STRING;
  i : INT;
  r : REAL;
  d : TIME;
  bad : INT;
END_VAR
  LD -42
  INT_TO_STRING
  ST s
  LD 2.5
  REAL_TO_STRING
  ST t
  LD T#1500ms
  TIME_TO_STRING
  ST u
  LD TRUE
  BOOL_TO_STRING
  ST b
  LD ' 123 '
  STRING_TO_INT
  ST i
  LD '0.25'
  STRING_TO_REAL
  ST r
  LD 'T#2s'
  STRING_TO_TIME
  ST d
  LD 'x1'
  STRING_TO_INT
  ST bad
END_PROGRAM
";
    let b = build_src(src);
    let out = c_backend::run(
        &b.exe,
        &c_backend::RunOptions {
            cycles: 1,
            watch: [
                "main.s", "main.t", "main.u", "main.b", "main.i", "main.r", "main.d", "main.bad",
            ]
            .iter()
            .map(|s| s.to_string())
            .collect(),
            ..Default::default()
        },
    )
    .unwrap();
    assert!(out.success(), "{}", out.stderr);
    assert_eq!(
        out.stdout.lines().nth(1).unwrap(),
        "0,0,\"-42\",\"2.5\",\"T#1500ms\",\"TRUE\",123,0.25,T#2000ms,0"
    );
    assert!(
        out.stderr.contains("conversion out of range"),
        "{}",
        out.stderr
    );
}

#[test]
fn big_endian_byte_addressed_msb0_profile() {
    let profile = c_backend::TargetProfile {
        byte_order: c_backend::ByteOrder::Big,
        bit_numbering: c_backend::BitNumbering::Msb0,
        address_unit: c_backend::AddressUnit::Byte,
        ..Default::default()
    };
    let (units, model, map) = frontend(
        "PROGRAM main
VAR
  w AT %QW1 : WORD;
END_VAR
  LD 16#1234
  ST w
  LD TRUE
  ST %QX0.0
END_PROGRAM
",
    );
    let p = generate_with(&units, &model, &map, &profile, &Default::default());
    assert!(p
        .file("ladderc_config.h")
        .unwrap()
        .contains("#define LADDERC_BIG_ENDIAN 1"));
    let b = build_program(p);
    let rows = run(&b, 1, 10.0, "", &["%QB0", "%QB1", "%QB2", "%QW1"]);
    // %QW1 starts at byte 1 (byte addressing), most significant byte first; %QX0.0 is the top bit
    assert_eq!(rows[1][2..].join(","), "128,18,52,4660");
}

#[test]
fn in_out_parameters_of_function_blocks_and_functions() {
    let src = "FUNCTION bump : BOOL
VAR_IN_OUT
  v : INT;
END_VAR
VAR_INPUT
  step : INT;
END_VAR
VAR_TEMP
  tmp : INT;
END_VAR
  LD v
  ADD step
  ST tmp
  LD tmp
  ST v
  LD TRUE
  ST bump
END_FUNCTION
FUNCTION_BLOCK acc
VAR_IN_OUT
  total : DINT;
END_VAR
VAR_INPUT
  x : DINT;
END_VAR
VAR_TEMP
  t : DINT := 1;
END_VAR
  LD total
  ADD x
  ADD t
  ST total
END_FUNCTION_BLOCK
PROGRAM main
VAR
  a : acc;
  sum : DINT;
  n : INT := 1;
  ok : BOOL;
END_VAR
  CAL a(total := sum, x := 10)
  bump(v := n, step := 2)
  ST ok
END_PROGRAM
";
    let b = build_src(src);
    let rows = run(&b, 3, 10.0, "", &["main.sum", "main.n", "main.ok"]);
    assert_eq!(column(&rows, "main.sum"), ["11", "22", "33"]);
    assert_eq!(column(&rows, "main.n"), ["3", "5", "7"]);
    assert_eq!(column(&rows, "main.ok"), ["1", "1", "1"]);
}

#[test]
fn initialisers_and_more_operators() {
    let src = "TYPE
  level : (low := 10, high := 20);
  cell : STRUCT
    v : INT := 3;
    lit : BOOL;
  END_STRUCT;
END_TYPE
VAR_GLOBAL
  shared : CTU;
END_VAR
FUNCTION_BLOCK pulse_count
VAR_INPUT
  x : BOOL;
END_VAR
VAR_OUTPUT
  n : INT := 100;
END_VAR
VAR
  edge : R_TRIG;
END_VAR
  LD x
  CLK edge
  LD edge.Q
  JMPCN out
  LD n
  ADD 1
  ST n
out:
  LD TRUE
  ST ENO
END_FUNCTION_BLOCK
FUNCTION_BLOCK tick
VAR_OUTPUT
  n : INT;
END_VAR
  LD n
  ADD 1
  ST n
END_FUNCTION_BLOCK
PROGRAM main
VAR_EXTERNAL
  shared : CTU;
END_VAR
VAR
  arr : ARRAY [0..3] OF INT := [1, 2, 2(7)];
  cells : ARRAY [1..2] OF cell;
  counters : ARRAY [1..2] OF pulse_count;
  lv : level;
  sub : INT (5..9);
  tmr : TON := (PT := T#20ms);
  sr1 : SR;
  rs1 : RS;
  t : TIME;
  d : TIME;
  m : INT;
  x : INT;
  ne : BOOL;
  nested : INT;
  calc_runs : INT;
  c1 : tick;
  c2 : tick;
END_VAR
  LD %IX0.0
  S1 sr1
  LD %IX0.1
  R sr1
  LD %IX0.0
  S rs1
  LD %IX0.1
  R1 rs1
  LD %IX0.0
  CAL counters[1](x := %IX0.0)
  LD %IX0.0
  CU shared
  LD T#1s
  ADD T#500ms
  MUL 3
  ST t
  LD T#1s
  MUL 1.5
  DIV 2
  ST d
  LD 17
  MOD 5
  XOR 16#F
  ST m
  LD 5
  ADD( 2
  MUL 3
  )
  ST nested
  LD arr[3]
  NE 7
  ST ne
  LD TRUE
  ST tmr.IN
  CAL tmr
  LD %IX0.0
  CALC c1
  LD %IX0.0
  CALCN c2
  LD calc_runs
  ADD 1
  ST calc_runs
  LD sub
  LE 5
  RETCN
  LD 99
  ST x
END_PROGRAM
";
    let b = build_src(src);
    let rows = run(
        &b,
        3,
        10.0,
        "1,%IX0.0,1\n2,%IX0.0,0\n2,%IX0.1,1\n",
        &[
            "main.arr[0]",
            "main.arr[1]",
            "main.arr[2]",
            "main.arr[3]",
            "main.cells[2].v",
            "main.counters[1].n",
            "main.counters[2].n",
            "main.lv",
            "main.sub",
            "main.tmr.PT",
            "main.sr1.Q1",
            "main.rs1.Q1",
            "shared.CV",
            "main.t",
            "main.d",
            "main.m",
            "main.nested",
            "main.ne",
            "main.x",
            "main.tmr.Q",
            "main.calc_runs",
            "main.c1.n",
            "main.c2.n",
        ],
    );
    let row = |c: usize| rows[c + 1][2..].join(",");
    assert_eq!(
        row(0),
        "1,2,7,7,3,100,100,10,5,T#20ms,0,0,0,T#4500ms,T#750ms,13,11,0,99,0,1,0,1"
    );
    assert_eq!(
        row(1),
        "1,2,7,7,3,101,100,10,5,T#20ms,1,1,1,T#4500ms,T#750ms,13,11,0,99,0,2,1,1"
    );
    // cycle 2: IX0.0 off, IX0.1 on: SR resets, RS resets; the timer has run 20 ms
    assert_eq!(
        row(2),
        "1,2,7,7,3,101,100,10,5,T#20ms,0,0,1,T#4500ms,T#750ms,13,11,0,99,1,3,1,2"
    );
}

#[test]
fn non_formal_cal_and_negated_outputs() {
    let src = "PROGRAM main
VAR
  tmr : TON;
  not_q : BOOL;
  q : BOOL;
END_VAR
  CAL tmr(%IX0.0, T#20ms)
  CAL tmr(IN := %IX0.0, NOT Q => not_q, Q => q)
END_PROGRAM
";
    let b = build_src(src);
    let rows = run(&b, 4, 10.0, "1,%IX0.0,1\n", &["main.q", "main.not_q"]);
    assert_eq!(column(&rows, "main.q"), ["0", "0", "0", "1"]);
    assert_eq!(column(&rows, "main.not_q"), ["1", "1", "1", "0"]);
}

#[test]
fn function_parameters_need_not_be_used() {
    let src = "FUNCTION constant_one : INT
VAR_INPUT
  ignored : INT;
END_VAR
VAR_OUTPUT
  unused_out : BOOL;
END_VAR
  LD 1
  ST constant_one
END_FUNCTION
PROGRAM main
VAR
  x : INT;
END_VAR
  constant_one(ignored := 5)
  ST x
END_PROGRAM
";
    let b = build_src(src);
    let rows = run(&b, 1, 10.0, "", &["main.x"]);
    assert_eq!(column(&rows, "main.x"), ["1"]);
}

#[test]
fn wstrings_hold_unicode_and_compare() {
    let src = "PROGRAM main
VAR
  w : WSTRING[4] := \"h\u{e9}\";
  v : WSTRING;
  same : BOOL;
END_VAR
  LD \"caf\u{e9} \u{1F600}!\"
  ST w
  ST v
  LD w
  EQ v
  ST same
END_PROGRAM
";
    let b = build_src(src);
    let out = c_backend::run(
        &b.exe,
        &c_backend::RunOptions {
            cycles: 1,
            watch: vec!["main.w".into(), "main.v".into(), "main.same".into()],
            ..Default::default()
        },
    )
    .unwrap();
    assert!(out.success(), "{}", out.stderr);
    // WSTRING[4] keeps 4 UTF-16 units: "caf\u{e9}"
    assert_eq!(
        out.stdout.lines().nth(1).unwrap(),
        "0,0,\"caf\u{e9}\",\"caf\u{e9} \u{1F600}!\",0"
    );
    // stimulus in UTF-8
    let rows = run(&b, 1, 10.0, "0,main.v,\"\u{e9}t\u{e9}\"\n", &["main.v"]);
    assert_eq!(column(&rows, "main.v"), ["\"caf\u{e9} \u{1F600}!\""]);
}
