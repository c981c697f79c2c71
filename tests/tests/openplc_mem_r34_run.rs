//! Round 34 (OpenPLC memory areas), through `ladderc run` and `ladderc check`:
//! - Under `--profile openplc` %M has one image per size, as %I and %Q already had
//!   (`"memory_per_size": true` in `crates/c-backend/profiles/openplc.json`): `%MX0.1` is not a bit of
//!   `%MW0`. matiec (Beremiz, OpenPLC) gives every located variable storage of its own (`__MW0`,
//!   `__MX0_1`) and the OpenPLC runtime binds %MW, %MD and %ML to buffers of their own
//!   (`int_memory`, `dint_memory`, `lint_memory`). Before, a `VAR_GLOBAL CONSTANT LIMIT_V AT %MW0 :
//!   INT := 50` beside a flag `AT %MX0.1` written FALSE read 48 (SaxatileStoner/SFWE511-SemesterProject:
//!   its flow threshold 50 became 5, 55 columns apart from matiec).
//! - Under the default profile (one %M image, CODESYS's and TwinCAT's model; IEC 61131-3 leaves it to
//!   the implementation) the sharing stays, and `check` now says so: W1473 when a CONSTANT's bits are
//!   those of a variable a body writes (IEC 61131-3 ed. 2 2.4.3: a CONSTANT cannot be modified),
//!   W1472 when two variables of different sizes share bits and a body writes one. Before, nothing.

mod common;

use common::{column, in_dir, write_in};

/// A constant word at `%MW0` and a flag at its bit 1 written TRUE and FALSE in turn; a word
/// `level` at `%MW1` written 7 and `bit0` at `%MX2.0` (bit 0 of `%MW1` in one image) read; a word
/// and a byte of it that no body writes (`shown`, `view`: a view, no warning).
const MEMORY: &str = r#"PROGRAM p
  VAR_EXTERNAL CONSTANT
    LIMIT_V : INT;
  END_VAR
  VAR_EXTERNAL
    flag : BOOL;
    level : INT;
    bit0 : BOOL;
    view : BYTE;
    shown : WORD;
  END_VAR
  VAR
    n : INT;
    v : INT;
    b : BOOL;
    seen : BOOL;
  END_VAR
  n := n + 1;
  flag := (n MOD 2) = 1;
  level := 7;
  b := bit0;
  seen := view > 0 OR shown > 0;
  v := LIMIT_V;
END_PROGRAM

CONFIGURATION c
  VAR_GLOBAL CONSTANT
    LIMIT_V AT %MW0 : INT := 50;
  END_VAR
  VAR_GLOBAL
    flag AT %MX0.1 : BOOL;
    level AT %MW1 : INT;
    bit0 AT %MX2.0 : BOOL;
    shown AT %MW2 : WORD;
    view AT %MB4 : BYTE;
  END_VAR
  RESOURCE r ON PLC
    TASK t(INTERVAL := T#10ms, PRIORITY := 0);
    PROGRAM inst WITH t : p;
  END_RESOURCE
END_CONFIGURATION
"#;

/// `ladderc run mem.st --cycles 4` with `extra` arguments: the trace of the constant as read, the
/// bit read and the words and bit by address.
fn run(extra: &[&str]) -> (String, String) {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "mem.st", MEMORY);
    let mut args = vec![
        "run",
        "mem.st",
        "--cycles",
        "4",
        "--trace",
        "-",
        "--watch",
        "inst.v,inst.b,%MW0,%MW1,%MX2.0",
    ];
    args.extend_from_slice(extra);
    let (code, trace, stderr) = in_dir(dir.path(), &args);
    assert_eq!(code, Some(0), "{stderr}");
    (trace, stderr)
}

/// `ladderc check mem.st` with `extra` arguments: the warning lines.
fn check(extra: &[&str]) -> Vec<String> {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "mem.st", MEMORY);
    let mut args = vec!["check", "mem.st"];
    args.extend_from_slice(extra);
    let (code, _, stderr) = in_dir(dir.path(), &args);
    assert_eq!(code, Some(0), "{stderr}");
    stderr
        .lines()
        .filter(|l| l.contains("warning["))
        .map(str::to_string)
        .collect()
}

/// Under `--profile openplc` the constant reads 50 in every cycle, whatever the flag at `%MX0.1`,
/// and `bit0` at `%MX2.0` stays FALSE while `level` at `%MW1` is 7, as in matiec; `--watch %MW1`
/// names the word image (the runtime's address parser places %M per size too). Before, the
/// constant read 50 and 48 in turn and `bit0` was TRUE.
#[test]
fn openplc_memory_words_and_bits_are_apart() {
    let (trace, _) = run(&["--profile", "openplc"]);
    assert_eq!(column(&trace, "inst.v"), [50.0; 4], "{trace}");
    assert_eq!(column(&trace, "%MW0"), [50.0; 4], "{trace}");
    assert_eq!(column(&trace, "inst.b"), [0.0; 4], "{trace}");
    assert_eq!(column(&trace, "%MW1"), [7.0; 4], "{trace}");
    assert_eq!(column(&trace, "%MX2.0"), [0.0; 4], "{trace}");
}

/// Under the default profile `%MX0.1` is bit 1 of `%MW0` (the documented model): the flag written
/// FALSE in cycles 1 and 3 clears bit 1 of the constant (50 -> 48), and `bit0` is bit 0 of `level`
/// (7: TRUE). Unchanged by the round; `run` now shows the W1473 and W1472 of `check`.
#[test]
fn default_memory_words_and_bits_share_and_warn() {
    let (trace, stderr) = run(&[]);
    assert_eq!(
        column(&trace, "inst.v"),
        [50.0, 48.0, 50.0, 48.0],
        "{trace}"
    );
    assert_eq!(column(&trace, "inst.b"), [1.0; 4], "{trace}");
    assert_eq!(column(&trace, "%MX2.0"), [1.0; 4], "{trace}");
    assert!(stderr.contains("warning[W1473]"), "{stderr}");
}

/// `check` under the default profile: one W1473 for the constant and the written flag, at the
/// flag's address (line 31, column 13) naming both; one W1472 for `level` (written) and `bit0`,
/// at `bit0`'s address (line 33, column 13); nothing for `shown` and `view` (no body writes them)
/// and nothing else. Before, no warning at all.
#[test]
fn default_profile_warns_once_per_pair_sharing_written_memory() {
    let lines = check(&[]);
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "mem.st:31:13: warning[W1473]: CONSTANT `LIMIT_V` at %MW0 shares memory bits with `flag` at %MX0.1, which the program writes"
        ),
        "{lines:?}"
    );
    assert!(lines[0].contains("cannot be modified"), "{lines:?}");
    assert!(lines[0].contains("--profile openplc"), "{lines:?}");
    assert!(
        lines[1].starts_with(
            "mem.st:33:13: warning[W1472]: `bit0` at %MX2.0 shares memory bits with `level` at %MW1, and the program writes `level`"
        ),
        "{lines:?}"
    );
    assert!(lines[1].contains("--profile openplc"), "{lines:?}");
}

/// Under `--profile openplc` no variable shares memory bits: no W1472 or W1473.
#[test]
fn openplc_profile_gives_no_memory_overlap_warning() {
    let lines = check(&["--profile", "openplc"]);
    assert!(
        !lines
            .iter()
            .any(|l| l.contains("W1472") || l.contains("W1473")),
        "{lines:?}"
    );
}

/// A constant at the very word a written variable of the same size uses is W1473 too (whatever the
/// sizes), also under `--profile openplc`; two variables of one size both written are not W1472
/// (one variable under two names).
#[test]
fn a_constant_at_the_address_of_a_written_word_warns_in_every_profile() {
    let src = r#"PROGRAM p
  VAR CONSTANT
    k AT %MW10 : INT := 3;
  END_VAR
  VAR
    w AT %MW10 : INT;
    a AT %MW11 : INT;
    b AT %MW11 : INT;
  END_VAR
  w := 5;
  a := 1;
  b := 2;
END_PROGRAM
"#;
    for extra in [&[][..], &["--profile", "openplc"][..]] {
        let dir = tempfile::tempdir().unwrap();
        write_in(dir.path(), "same.st", src);
        let mut args = vec!["check", "same.st"];
        args.extend_from_slice(extra);
        let (code, _, stderr) = in_dir(dir.path(), &args);
        assert_eq!(code, Some(0), "{stderr}");
        let lines: Vec<&str> = stderr.lines().filter(|l| l.contains("warning[")).collect();
        assert_eq!(lines.len(), 1, "{extra:?}: {lines:?}");
        assert!(
            lines[0].starts_with(
                "same.st:6:10: warning[W1473]: CONSTANT `p.k` at %MW10 shares memory bits with `p.w` at %MW10"
            ),
            "{lines:?}"
        );
    }
}
