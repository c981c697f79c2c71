//! Edition 3's long date types, LDATE, LTOD (LTIME_OF_DAY) and LDT (LDATE_AND_TIME) (IEC 61131-3
//! edition 3, 6.4.2 Table 10: signed 64-bit nanoseconds since 1970-01-01, or since midnight):
//! declared, written as literals, driven by a stimulus, traced, converted (to their short forms,
//! to the date and time of day of an LDT, to numbers in nanoseconds, to and from STRING),
//! compared, and in the typed arithmetic of Table 36 (`ADD_LDT_LTIME`, `SUB_LDT_LDT`,
//! `CONCAT_LDATE_LTOD`), in ST and in IL, run under the sanitizers. Before: E1003 "unknown type
//! `LDT`" (the sweeps' ST test files declare them). Every conversion of the catalogue, these
//! included, is run by `conversions_run.rs`.

mod common;
use common::{check_text, column, run_stimulated, run_text};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/long_dates")
        .join(name)
}

fn field(trace: &str, row: usize, name: &str) -> String {
    let mut lines = trace.lines();
    let head = common::split_csv(lines.next().unwrap());
    let i = head.iter().position(|h| h == name).unwrap();
    common::split_csv(lines.nth(row).unwrap())[i].clone()
}

/// log.st: a batch of 90 minutes and 500 ns from its start; the first scan from the declared
/// start (2024-02-28 23:00, a leap year: it ends on the 29th), the second from a start the
/// stimulus gives in LDT# text.
#[test]
fn a_batch_log_in_long_dates_runs_to_the_nanosecond() {
    let (trace, _) = run_stimulated(
        &fixture("log.st"),
        2,
        "1,Main.start,LDT#2023-12-31-12:00:00\n",
        "Main.finish,Main.day,Main.atTime,Main.shortDay,Main.shortAt,Main.shortFinish,Main.again,Main.took,Main.ns,Main.text,Main.parsed,Main.sameDay,Main.later",
    );
    let want = [
        (
            "Main.finish",
            "LDT#2024-02-29-00:30:00.0000005",
            "LDT#2023-12-31-13:30:00.0000005",
        ),
        ("Main.day", "LDATE#2024-02-29", "LDATE#2023-12-31"),
        (
            "Main.atTime",
            "LTOD#00:30:00.0000005",
            "LTOD#13:30:00.0000005",
        ),
        ("Main.shortDay", "D#2024-02-29", "D#2023-12-31"),
        (
            "Main.shortAt",
            "TOD#00:30:00.0000005",
            "TOD#13:30:00.0000005",
        ),
        (
            "Main.shortFinish",
            "DT#2024-02-29-00:30:00.0000005",
            "DT#2023-12-31-13:30:00.0000005",
        ),
        (
            "Main.again",
            "LDT#2024-02-29-00:30:00.0000005",
            "LDT#2023-12-31-13:30:00.0000005",
        ),
        ("Main.took", "T#5400000000500ns", "T#5400000000500ns"),
        (
            "Main.text",
            "LDT#2024-02-29-00:30:00.0000005",
            "LDT#2023-12-31-13:30:00.0000005",
        ),
        (
            "Main.parsed",
            "LDT#2024-02-29-00:30:00.0000005",
            "LDT#2023-12-31-13:30:00.0000005",
        ),
        // the first batch ends the next day; the second does not end after 2024-02-29
        ("Main.sameDay", "0", "1"),
        ("Main.later", "1", "0"),
    ];
    for (name, first, second) in want {
        assert_eq!(
            field(&trace, 0, name).trim_matches('"'),
            first,
            "{name}: {trace}"
        );
        assert_eq!(
            field(&trace, 1, name).trim_matches('"'),
            second,
            "{name}: {trace}"
        );
    }
    // LTOD as a number: nanoseconds since midnight (00:30:00.0000005, 13:30:00.0000005)
    assert_eq!(
        column(&trace, "Main.ns"),
        [1_800_000_000_500.0, 48_600_000_000_500.0]
    );
}

/// IL: an LDT literal loaded, an LTIME added (ADD's LDT overload), the day taken; the long
/// spellings of the type names and literal prefixes.
#[test]
fn il_loads_adds_and_converts_long_dates() {
    let src = "PROGRAM Main
VAR
  t : LDATE_AND_TIME;
  d : LDATE;
  clock : LTIME_OF_DAY := LTIME_OF_DAY#23:59:59.999999999;
  n : ULINT;
END_VAR
  LD LDATE_AND_TIME#1970-01-01-00:00:00
  ADD LTIME#1d1ns
  ST t
  LDT_TO_LDATE
  ST d
  LD clock
  LTOD_TO_ULINT
  ST n
END_PROGRAM
";
    let (trace, _) = run_text("long.il", src, 1, "Main.t,Main.d,Main.clock,Main.n");
    assert_eq!(
        trace.lines().nth(1).unwrap(),
        "0,0,LDT#1970-01-02-00:00:00.000000001,LDATE#1970-01-02,LTOD#23:59:59.999999999,86399999999999"
    );
}

/// A DATE widens to an LDATE where one is expected (as TIME to LTIME), but an LDT does not
/// narrow to a DT without its conversion. Edition-2 projects that name a variable `ldt` or
/// `ldate` keep compiling: the names are not reserved. (`DATE_TO_LDT`, which IEC 61131-3 edition
/// 3 does not list, was E1019 until round 27: CODESYS and TwinCAT convert every date and time type
/// to every other, `misc_r27_run.rs`.)
#[test]
fn long_dates_widen_but_never_narrow_silently() {
    let (code, lines) = check_text(
        "narrow.st",
        "PROGRAM Main
VAR
  d : DATE;
  ld : LDATE;
  dt1 : DT;
  ldt1 : LDT;
  ldate : INT := 3;
END_VAR
ld := d;
ldate := ldate + 1;
dt1 := ldt1;
ldt1 := DATE_TO_LDT(d);
END_PROGRAM
",
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("narrow.st:11:1: error[E1006]: cannot store LDT into DT"),
        "{lines:?}"
    );
}
