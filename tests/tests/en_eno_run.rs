//! EN and ENO of standard functions and conversions in formal calls (issue #13), the form Beremiz and
//! OpenPLC write for every block of an LD network (`_TMP := ULINT_TO_INT(EN := TRUE, IN := x,
//! ENO => _TMP_ENO); IF _TMP_ENO THEN y := _TMP; END_IF;`), through `ladderc run`: ENO is EN (a
//! standard function that runs always completes), and with EN FALSE the function is not executed and
//! gives its type's initial value (IEC 61131-3; matiec does the same). Before, ENO was never written,
//! so the `IF` above never ran: the network's logic was dropped without a diagnostic.

mod common;
use common::ladderc;

#[test]
fn en_gates_standard_functions_and_conversions_and_eno_follows_it() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("en.st");
    std::fs::write(
        &file,
        "PROGRAM main\nVAR\n  en : BOOL := TRUE;\n  u : ULINT := 70000;\n  sum : INT;\n  ok : BOOL;\n  \
         conv_out : INT;\n  conv_eno : BOOL;\n  copied : INT := -1;\n  s : STRING;\n  s_eno : BOOL;\nEND_VAR\n  \
         sum := ADD(EN := en, IN1 := 1, IN2 := 2, ENO => ok);\n  \
         conv_out := ULINT_TO_INT(EN := en, IN := u, ENO => conv_eno);\n  \
         IF conv_eno THEN\n    copied := conv_out;\n  END_IF;\n  \
         s := CONCAT(EN := en, IN1 := 'a', IN2 := 'b', ENO => s_eno);\nEND_PROGRAM\n",
    )
    .unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, "1,main.en,FALSE\n1,main.u,5\n2,main.en,TRUE\n").unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .arg("run")
        .arg(&file)
        .args(["--cycles", "3", "--sanitize", "--stimulus"])
        .arg(&stim)
        .arg("--trace")
        .arg(&trace)
        .args([
            "--watch",
            "main.sum,main.ok,main.conv_out,main.conv_eno,main.copied,main.s,main.s_eno",
        ])
        .output()
        .unwrap();
    common::assert_ok(&out);
    // cycle 0: EN TRUE, 70000 wraps to INT 4464 and is copied; cycle 1: EN FALSE, nothing runs, the
    // results are the initial values, ENO FALSE, `copied` keeps 4464; cycle 2: EN TRUE again, 5.
    assert_eq!(
        std::fs::read_to_string(&trace).unwrap(),
        "cycle,time_ms,main.sum,main.ok,main.conv_out,main.conv_eno,main.copied,main.s,main.s_eno\n\
         0,0,3,1,4464,1,4464,\"ab\",1\n\
         1,10,0,0,0,0,4464,\"\",0\n\
         2,20,3,1,5,1,5,\"ab\",1\n"
    );
}

/// EN must be BOOL, ENO a writable BOOL: located errors, as for any input or output.
#[test]
fn en_and_eno_of_a_conversion_are_type_checked() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("bad.st");
    std::fs::write(
        &file,
        "PROGRAM main\nVAR\n  n : INT;\n  r : INT;\nEND_VAR\n  \
         r := DINT_TO_INT(EN := n, IN := 5);\n  r := DINT_TO_INT(IN := 5, ENO => n);\nEND_PROGRAM\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&file)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("bad.st:6:26: error[E1023]"), "{stderr}");
    assert!(stderr.contains("bad.st:7:29: error[E1006]"), "{stderr}");
    assert!(!stderr.contains("has no parameter `EN`"), "{stderr}");
}
