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
        "10,100,9,300,3,-7,1234,4660,3840,3,5,1.4142135623730951,1500,T#250ms,1"
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
