//! Constructs of the eighth acceptance run of issue #13 (2026-12-03, branch `lang6`).
//!
//! ROUND8_HEADER
//!
//! Each test is a minimal reproduction written here (`tests/fixtures/unseen/`), run through
//! `ladderc run` (C compiled with the sanitizers) or `ladderc check`.

mod common;
use common::{check_text, ladderc};
use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/unseen")
        .join(name)
}

/// `ladderc run FILE` (10 ms scans, C built with the sanitizers) with `stimulus` rows
/// (`cycle,variable,value`), tracing `watch`: the trace; asserts exit 0.
fn run(file: &Path, cycles: u32, stimulus: &str, watch: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, format!("cycle,variable,value\n{stimulus}")).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(file)
        .args([
            "--cycles",
            &cycles.to_string(),
            "--cycle-ms",
            "10",
            "--sanitize",
        ])
        .arg("--stimulus")
        .arg(&stim)
        .args(["--trace", "-", "--watch", watch])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{file:?}: {stderr}");
    assert!(!stderr.contains("Sanitizer"), "{stderr}");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// A branch of a simultaneous sequence that ends in a jump back to a step of its own branch
/// (CODESYS connects the jump to the simultaneous convergence; before, E3128 "<jumpStep> cannot
/// precede a transition"): the branch loops (Stir, Pause, Stir ...), the transition after the
/// convergence waits for the other branch only (Heat, cycle 8), and leaves the looping branch
/// running, as IEC 61131-3 deactivates only a transition's immediately preceding steps.
#[test]
fn a_parallel_branch_ending_in_a_jump_back_into_itself_loops_beside_the_convergence() {
    let trace = run(
        &fixture("codesys_parallel_branch_jump.xml"),
        13,
        "1,Tank.start,TRUE\n2,Tank.start,FALSE\n3,Tank.pulse,TRUE\n4,Tank.pulse,FALSE\n\
         5,Tank.full,TRUE\n6,Tank.full,FALSE\n6,Tank.pulse2,TRUE\n7,Tank.pulse2,FALSE\n\
         8,Tank.hot,TRUE\n9,Tank.hot,FALSE\n10,Tank.empty,TRUE\n11,Tank.empty,FALSE\n",
        "Tank.__sfc_X_Idle,Tank.__sfc_X_Fill,Tank.__sfc_X_Heat,Tank.__sfc_X_Stir,\
         Tank.__sfc_X_Pause,Tank.__sfc_X_Drain,Tank.__sfc_X_Done,Tank.stirring,Tank.heating",
    );
    // hot in cycle 8 fires with Heat alone (the looping branch is in Stir or Pause, either way)
    assert_eq!(
        trace,
        "cycle,time_ms,Tank.__sfc_X_Idle,Tank.__sfc_X_Fill,Tank.__sfc_X_Heat,Tank.__sfc_X_Stir,\
         Tank.__sfc_X_Pause,Tank.__sfc_X_Drain,Tank.__sfc_X_Done,Tank.stirring,Tank.heating\n\
         0,0,1,0,0,0,0,0,0,0,0\n\
         1,10,0,1,0,1,0,0,0,1,0\n\
         2,20,0,1,0,1,0,0,0,1,0\n\
         3,30,0,1,0,0,1,0,0,0,0\n\
         4,40,0,1,0,0,1,0,0,0,0\n\
         5,50,0,0,1,0,1,0,0,0,1\n\
         6,60,0,0,1,1,0,0,0,1,1\n\
         7,70,0,0,1,1,0,0,0,1,1\n\
         8,80,0,0,0,1,0,1,0,1,0\n\
         9,90,0,0,0,1,0,1,0,1,0\n\
         10,100,0,0,0,1,0,0,1,1,0\n\
         11,110,0,0,0,1,0,0,1,1,0\n\
         12,120,0,0,0,1,0,0,1,1,0\n"
    );
}

/// A jump that leaves its branch of a simultaneous sequence is IEC 61131-3's unsafe SFC: one E3128
/// at the jump's target, with a hint; a simultaneous convergence whose every branch ends in a jump
/// can never fire (unreachable): E3128 at the convergence.
#[test]
fn a_jump_out_of_a_parallel_branch_or_a_convergence_of_jumps_only_is_e3128() {
    let src = std::fs::read_to_string(fixture("codesys_parallel_branch_jump.xml")).unwrap();
    let (code, lines) = check_text(
        "unsafe.xml",
        &src.replace("targetName=\"Stir\"", "targetName=\"Drain\""),
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0]
            .starts_with("unsafe.xml:98:48: error[E3128]: jump to step `Drain` leaves its branch")
            && lines[0].contains("[POU `Tank`, localId 27]")
            && lines[0].contains("hint: end the branch at the simultaneous convergence"),
        "{lines:?}"
    );
    let (code, lines) = check_text(
        "jumps_only.xml",
        &src.replacen(
            "<connectionPointIn><connection refLocalId=\"14\" formalParameter=\"sfc\" /></connectionPointIn>\n",
            "",
            1,
        ),
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines.iter().any(|l| l.contains(
            "error[E3128]: every branch of this simultaneous convergence ends in a jump"
        ) && l.contains("localId 40")),
        "{lines:?}"
    );
}

/// A STRING's initial value in the double quotes of a WSTRING literal, as an OpenPLC Editor project
/// of the round writes it (`<simpleValue value="&quot;1234&quot;"/>` for a `<string/>`): Beremiz
/// generates `'"1234"'` from it, the text itself with its quotes, so ladderc reads it the same way
/// (before, E1025 "this initial value is not a STRING"). A value in the type's own quotes stays a
/// literal; a WSTRING's value in double quotes too; text without quotes is the string itself.
#[test]
fn a_string_initial_value_without_its_own_quotes_is_the_text_itself_as_beremiz_reads_it() {
    let trace = run(
        &fixture("beremiz_string_init.xml"),
        2,
        "",
        "instance0.n_code,instance0.n_plain,instance0.n_quoted,instance0.n_wide,instance0.open_,\
         instance0.same",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,instance0.n_code,instance0.n_plain,instance0.n_quoted,instance0.n_wide,\
         instance0.open_,instance0.same\n0,0,6,4,4,2,1,1\n1,10,6,4,4,2,1,1\n"
    );
}
