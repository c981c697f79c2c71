//! Edition 3's character types CHAR and WCHAR (IEC 61131-3 edition 3, 6.4.2 Table 10: a
//! single-byte and a double-byte character; literals Table 6 and 7, `CHAR#'A'`, `WCHAR#"A"`, or
//! `'A'` / `"A"` where a character is expected; initial value NUL), run end to end:
//! - declared as variables, array elements, structure members, FB inputs and outputs, with
//!   initial values, escapes (`$41`, `$'`, `$N`), traced in the literal form `CHAR#'A'`,
//!   `WCHAR#"€"` (before: E1003 "unknown type `CHAR`");
//! - compared by code (`=`, `<>`, `<`, `>=`, MAX) (before: E1003);
//! - converted as Table 22 says: `CHAR_TO_BYTE`, `BYTE_TO_CHAR`, `USINT_TO_CHAR`,
//!   `WCHAR_TO_WORD`, `CHAR_TO_WCHAR`, `WCHAR_TO_CHAR` (`?` beyond U+00FF), `CHAR_TO_STRING`,
//!   `STRING_TO_CHAR` (the first character), `WSTRING_TO_WCHAR`, `TO_CHAR`, `TO_BYTE`
//!   (before: E1019 unknown function); every conversion of the catalogue with them runs in
//!   `conversions_run.rs` and `wstring_run.rs`;
//! - `s[i]`, the i-th character of a STRING (a CHAR) or a WSTRING (a WCHAR), 1-based, read and
//!   written (before: E1021 "`s` is STRING, not an array"); an index outside 1..LEN(s) is a
//!   run-time error reported as array indexes are (NUL read, write dropped), a constant one
//!   outside the declared length E1050;
//! - `CONCAT` with CHAR and WCHAR inputs (edition 3's ANY_CHARS) (before: E1006);
//! - driven by stimuli in the literal form (before: E1003);
//! - bad literals and mixed types rejected with one located diagnostic each;
//! - and edition 3's `IS_VALID` (a REAL or LREAL neither NaN nor infinite) and `IS_VALID_BCD`
//!   (a bit string of 4-bit digits 0..9) (before: E1019 unknown function).

mod common;
use common::{check_text, run_stimulated, run_text};

fn field(trace: &str, row: usize, name: &str) -> String {
    let mut lines = trace.lines();
    let head = common::split_csv(lines.next().unwrap());
    let i = head
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name}: {trace}"));
    let v = common::split_csv(lines.nth(row).unwrap())[i].clone();
    // a field holding `"` or `,` is quoted (split_csv keeps the outer quotes)
    v.strip_prefix('"')
        .and_then(|v| v.strip_suffix('"'))
        .map_or(v.clone(), str::to_string)
}

/// Each `(variable, value)` in the first traced scan of `src` (program `Main`).
fn check_scan(name: &str, src: &str, want: &[(&str, &str)]) -> String {
    let watch: Vec<String> = want.iter().map(|(v, _)| format!("Main.{v}")).collect();
    let (trace, stderr) = run_text(name, src, 1, &watch.join(","));
    for (v, w) in want {
        assert_eq!(field(&trace, 0, &format!("Main.{v}")), *w, "{v}: {trace}");
    }
    stderr
}

/// Declarations with and without initial values: NUL by default, `'A'` and `CHAR#'A'`, the
/// escapes `$41`, `$'`, `$$`, `$N`, `$0041`; array elements, structure members (with a default),
/// FB inputs and outputs; traced as literals (a control character as `$hh`, a field holding
/// `,` or `"` CSV-quoted).
#[test]
fn declared_initialised_and_traced_in_the_literal_form() {
    let src = "TYPE Rec : STRUCT key : CHAR := 'k'; wide : WCHAR; END_STRUCT; END_TYPE
FUNCTION_BLOCK Echo
VAR_INPUT c : CHAR; END_VAR
VAR_OUTPUT same : CHAR; wide : WCHAR; END_VAR
same := c;
wide := CHAR_TO_WCHAR(c);
END_FUNCTION_BLOCK
PROGRAM Main
VAR
  nul : CHAR;
  wnul : WCHAR;
  a : CHAR := 'A';
  typed : CHAR := CHAR#'B';
  hex : CHAR := '$43';
  quote : CHAR := '$'';
  dollar : CHAR := '$$';
  comma : CHAR := ',';
  nl : CHAR := '$N';
  latin : CHAR := 'é';
  euro : WCHAR := \"€\";
  wtyped : WCHAR := WCHAR#\"$0041\";
  dq : WCHAR := \"$\"\";
  letters : ARRAY[1..3] OF CHAR := ['x', 'y', CHAR#'z'];
  r : Rec;
  e : Echo;
  got : CHAR;
  gotw : WCHAR;
END_VAR
e(c := letters[2]);
got := e.same;
gotw := e.wide;
r.wide := \"ω\";
END_PROGRAM
";
    check_scan(
        "decl.st",
        src,
        &[
            ("nul", "CHAR#'$00'"),
            ("wnul", "WCHAR#\"$0000\""),
            ("a", "CHAR#'A'"),
            ("typed", "CHAR#'B'"),
            ("hex", "CHAR#'C'"),
            ("quote", "CHAR#'$''"),
            ("dollar", "CHAR#'$$'"),
            ("comma", "CHAR#','"),
            ("nl", "CHAR#'$0A'"),
            ("latin", "CHAR#'é'"),
            ("euro", "WCHAR#\"€\""),
            ("wtyped", "WCHAR#\"A\""),
            ("dq", "WCHAR#\"$\"\""),
            ("letters[3]", "CHAR#'z'"),
            ("r.key", "CHAR#'k'"),
            ("r.wide", "WCHAR#\"ω\""),
            ("got", "CHAR#'y'"),
            ("gotw", "WCHAR#\"y\""),
        ],
    );
}

/// Characters compare by their code: `=`, `<>`, `<`, `>=` ..., MAX and MIN, with literals and
/// with each other (the CHAR literal `'a'` takes its type from the variable it is compared with).
#[test]
fn characters_compare_by_code() {
    let src = "PROGRAM Main
VAR
  c : CHAR := 'm';
  d : CHAR := 'M';
  w : WCHAR := \"€\";
  lower, upper, eq, ne, wbig : BOOL;
  hi, lo : CHAR;
END_VAR
lower := c >= 'a' AND c <= 'z';
upper := d >= 'A' AND d <= 'Z' AND d < c;
eq := c = CHAR#'m';
ne := c <> d;
wbig := w > WCHAR#\"$00FF\";
hi := MAX(c, d, 'q');
lo := MIN(c, d, 'q');
END_PROGRAM
";
    check_scan(
        "cmp.st",
        src,
        &[
            ("lower", "1"),
            ("upper", "1"),
            ("eq", "1"),
            ("ne", "1"),
            ("wbig", "1"),
            ("hi", "CHAR#'q'"),
            ("lo", "CHAR#'M'"),
        ],
    );
}

/// Table 22 and edition 3's conversions: with BYTE and WORD and the integers (the code; a
/// number wraps to the character's width as to BYTE or WORD), between CHAR and WCHAR (a WCHAR
/// beyond U+00FF is `?` in a CHAR, with the range flag, as WSTRING_TO_STRING does), to the
/// one-character string and back (the first character, NUL of an empty string), and the
/// overloaded `TO_CHAR` / `TO_BYTE` / `TO_WCHAR`.
#[test]
fn conversions_of_table_22_give_the_code_and_the_first_character() {
    let src = "PROGRAM Main
VAR
  c : CHAR := 'A';
  w : WCHAR := \"€\";
  b : BYTE;
  wd : WORD;
  n : USINT;
  i : INT;
  fromb, wrapped, narrowed, first, empty, fromw, overloaded : CHAR;
  widened, wfirst, wfromword : WCHAR;
  s : STRING;
  ws : WSTRING;
  tb : BYTE;
END_VAR
b := CHAR_TO_BYTE(c);
fromb := BYTE_TO_CHAR(BYTE#16#61);
n := CHAR_TO_USINT(c);
i := CHAR_TO_INT(CHAR#'$FF');
wrapped := UINT_TO_CHAR(UINT#322);
wd := WCHAR_TO_WORD(w);
wfromword := WORD_TO_WCHAR(WORD#16#3A9);
widened := CHAR_TO_WCHAR(c);
narrowed := WCHAR_TO_CHAR(w);
s := CHAR_TO_STRING(c);
first := STRING_TO_CHAR('xyz');
empty := STRING_TO_CHAR('');
ws := WCHAR_TO_WSTRING(w);
wfirst := WSTRING_TO_WCHAR(\"ωx\");
fromw := WCHAR_TO_CHAR(\"é\");
overloaded := TO_CHAR(BYTE#66);
tb := TO_BYTE(c);
END_PROGRAM
";
    let stderr = check_scan(
        "conv.st",
        src,
        &[
            ("b", "65"),
            ("fromb", "CHAR#'a'"),
            ("n", "65"),
            ("i", "255"),
            ("wrapped", "CHAR#'B'"),
            ("wd", "8364"),
            ("wfromword", "WCHAR#\"Ω\""),
            ("widened", "WCHAR#\"A\""),
            ("narrowed", "CHAR#'?'"),
            ("s", "A"),
            ("first", "CHAR#'x'"),
            ("empty", "CHAR#'$00'"),
            ("ws", "€"),
            ("wfirst", "WCHAR#\"ω\""),
            ("fromw", "CHAR#'é'"),
            ("overloaded", "CHAR#'B'"),
            ("tb", "65"),
        ],
    );
    assert!(stderr.contains("conversion out of range"), "{stderr}");
}

/// `s[i]`: the i-th character of a STRING is a CHAR, of a WSTRING a WCHAR (1 is the first),
/// read and written, with a computed index too (an upper-casing loop).
#[test]
fn string_elements_are_characters_read_and_written() {
    let src = "PROGRAM Main
VAR
  s : STRING := 'hello, plc';
  ws : WSTRING := \"αβγ\";
  i : INT;
  second : CHAR;
  wlast : WCHAR;
END_VAR
second := s[2];
FOR i := 1 TO LEN(s) DO
  IF s[i] >= 'a' AND s[i] <= 'z' THEN
    s[i] := BYTE_TO_CHAR(USINT_TO_BYTE(CHAR_TO_USINT(s[i]) - 32));
  END_IF;
END_FOR;
wlast := ws[3];
ws[1] := \"Ω\";
END_PROGRAM
";
    check_scan(
        "index.st",
        src,
        &[
            ("second", "CHAR#'e'"),
            ("s", "HELLO, PLC"),
            ("wlast", "WCHAR#\"γ\""),
            ("ws", "Ωβγ"),
        ],
    );
}

/// An index outside 1..LEN(s) (the current length, not the capacity) is a run-time error
/// reported as an array index out of range is: where, which index, the range; the read gives
/// NUL, the write is dropped, the program goes on.
#[test]
fn a_string_index_outside_its_length_is_a_run_time_error() {
    let src = "PROGRAM Main
VAR
  s : STRING[10] := 'abc';
  k : INT := 5;
  got : CHAR := 'x';
  after : INT;
END_VAR
got := s[k];
s[k] := 'z';
after := 1;
END_PROGRAM
";
    let stderr = check_scan(
        "oob.st",
        src,
        &[("got", "CHAR#'$00'"), ("s", "abc"), ("after", "1")],
    );
    assert!(
        stderr.contains(
            "runtime: string index out of range (first: s[k] in Main at oob.st:8, index 5 outside 1..3; NUL read, write dropped)"
        ),
        "{stderr}"
    );
}

/// CONCAT takes characters among its inputs (edition 3: ANY_CHARS), each as its one-character
/// string, in ST and in IL.
#[test]
fn concat_joins_characters_as_one_character_strings() {
    let src = "PROGRAM Main
VAR
  c : CHAR := 'x';
  w : WCHAR := \"€\";
  s : STRING;
  ws : WSTRING;
END_VAR
s := CONCAT('ab', c, CHAR#'$41', 'cd');
ws := CONCAT(w, \"ab\", w);
END_PROGRAM
";
    check_scan("concat.st", src, &[("s", "abxAcd"), ("ws", "€ab€")]);
    let il = "PROGRAM Main
VAR
  c : CHAR := 'x';
  s : STRING;
END_VAR
  LD c
  CONCAT 'ab', c
  ST s
END_PROGRAM
";
    check_scan("concat.il", il, &[("s", "xabx")]);
}

/// A stimulus sets a CHAR in the literal form, quoted or bare (`CHAR#'$41'`, `'z'`, `,` inside
/// quotes), a WCHAR as `WCHAR#"€"`.
#[test]
fn stimuli_set_characters_in_the_literal_form() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("stim.st");
    std::fs::write(
        &file,
        "PROGRAM Main
VAR
  c : CHAR;
  w : WCHAR;
  code : USINT;
END_VAR
code := CHAR_TO_USINT(c);
END_PROGRAM
",
    )
    .unwrap();
    let (trace, _) = run_stimulated(
        &file,
        3,
        "cycle,variable,value\n0,Main.c,CHAR#'$41'\n1,Main.c,z\n2,Main.c,','\n0,Main.w,WCHAR#\"€\"\n",
        "Main.c,Main.w,Main.code",
    );
    assert_eq!(field(&trace, 0, "Main.c"), "CHAR#'A'");
    assert_eq!(field(&trace, 1, "Main.c"), "CHAR#'z'");
    assert_eq!(field(&trace, 2, "Main.c"), "CHAR#','");
    assert_eq!(field(&trace, 0, "Main.w"), "WCHAR#\"€\"");
    let codes: Vec<String> = (0..3).map(|r| field(&trace, r, "Main.code")).collect();
    assert_eq!(codes, ["65", "122", "44"]);
}

/// Bad input, one located diagnostic each: a CHAR literal of two characters (E1017), a
/// two-character string stored into a CHAR (E1006), arithmetic on a CHAR (E1004), a CHAR
/// stored into an INT without its conversion (E1006), a constant index outside the declared
/// length (E1050), two indexes on a string (E1021). The names CHAR and WCHAR are not reserved
/// (edition-2 projects name variables so).
#[test]
fn bad_literals_and_mixed_types_are_located_errors() {
    let (code, lines) = check_text(
        "bad.st",
        "PROGRAM Main
VAR
  c : CHAR;
  s : STRING[4] := 'ab';
  n : INT;
END_VAR
c := CHAR#'AB';
c := 'AB';
c := c + 1;
c := s[5];
n := c;
c := s[1, 2];
END_PROGRAM
",
    );
    assert_eq!(code, Some(1));
    let heads: Vec<String> = lines
        .iter()
        .map(|l| l.split(" (hint").next().unwrap().to_string())
        .collect();
    assert_eq!(
        heads,
        [
            "bad.st:7:6: error[E1017]: a CHAR literal holds exactly one character, `AB` has 2",
            "bad.st:8:1: error[E1006]: cannot store STRING[2] into CHAR",
            "bad.st:9:6: error[E1004]: ADD is not defined for CHAR",
            "bad.st:10:8: error[E1050]: character 5 is outside the declared length 1..4 of `s`",
            "bad.st:11:1: error[E1006]: cannot store CHAR into INT",
            "bad.st:12:6: error[E1021]: `s` is a string: one index gives a character, 2 are given",
        ],
        "{lines:?}"
    );
    let (code, lines) = check_text(
        "names.st",
        "PROGRAM Main
VAR
  char : INT := 1;
  wchar : CHAR := 'w';
END_VAR
char := char + 1;
END_PROGRAM
",
    );
    assert_eq!((code, lines), (Some(0), vec![]));
}

/// Edition 3's `IS_VALID`: TRUE for a REAL or LREAL that is a number, FALSE for NaN and the
/// infinities (an integer widens to a real, as SQRT's input, and is valid); `IS_VALID_BCD`: TRUE
/// when every 4-bit digit of the bit string is 0..9. A TIME is no input of either (E1004).
#[test]
fn is_valid_and_is_valid_bcd() {
    let src = "PROGRAM Main
VAR
  big : LREAL := 1.0E300;
  r : REAL := 2.5;
  inf, nan : LREAL;
  real_ok, inf_ok, nan_ok, neg_inf_ok, lreal_ok, bcd_word, bcd_byte, bcd_dword, bcd_zero : BOOL;
END_VAR
inf := big * big;
nan := inf - inf;
real_ok := IS_VALID(r);
inf_ok := IS_VALID(inf);
nan_ok := IS_VALID(nan);
neg_inf_ok := IS_VALID(-inf);
lreal_ok := IS_VALID(big);
bcd_word := IS_VALID_BCD(WORD#16#1234);
bcd_byte := IS_VALID_BCD(BYTE#16#1A);
bcd_dword := IS_VALID_BCD(DWORD#16#9990_00F0);
bcd_zero := IS_VALID_BCD(LWORD#0);
END_PROGRAM
";
    check_scan(
        "valid.st",
        src,
        &[
            ("real_ok", "1"),
            ("inf_ok", "0"),
            ("nan_ok", "0"),
            ("neg_inf_ok", "0"),
            ("lreal_ok", "1"),
            ("bcd_word", "1"),
            ("bcd_byte", "0"),
            ("bcd_dword", "0"),
            ("bcd_zero", "1"),
        ],
    );
    let (code, lines) = check_text(
        "valid_time.st",
        "PROGRAM Main
VAR
  t : TIME;
  ok : BOOL;
END_VAR
ok := IS_VALID(t);
ok := IS_VALID_BCD(t);
END_PROGRAM
",
    );
    assert_eq!(code, Some(1));
    let heads: Vec<&str> = lines
        .iter()
        .map(|l| l.split(" (hint").next().unwrap())
        .collect();
    assert_eq!(
        heads,
        [
            "valid_time.st:6:7: error[E1004]: IS_VALID is not defined for TIME",
            "valid_time.st:7:7: error[E1004]: IS_VALID_BCD is not defined for TIME",
        ]
    );
}
