//! CODESYS (tc6_0200) exports through `ladderc run`: the task interval as an xsd:duration
//! (`PT0.05S`), array bounds given by named constants (a POU's VAR CONSTANT, a resource's VAR_GLOBAL
//! CONSTANT in an expression), a `pouInstance` with an empty `typeName` (the program of the same
//! name), `Standard.TON` for the IEC timer; and the located diagnostics of bad intervals and bounds.

mod common;
use common::ladderc;

use std::path::{Path, PathBuf};

fn fixture() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/codesys/tc6_0200_task_constants.xml")
}

#[test]
fn codesys_task_interval_constant_bounds_and_empty_type_name_run() {
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.csv");
    let out = ladderc()
        .arg("run")
        .arg(fixture())
        .args([
            "--cycles",
            "12",
            "--cycle-ms",
            "10",
            "--sanitize",
            "--trace",
        ])
        .arg(&trace)
        .args([
            "--watch",
            "PRG_MAIN.count,PRG_MAIN.arr[3],PRG_MAIN.big[4],PRG_MAIN.done",
        ])
        .output()
        .unwrap();
    common::assert_ok(&out);
    // PT0.05S at a 10 ms cycle: the task runs at cycles 0, 5 and 10; arr is ARRAY[0..ciN] (ciN = 3),
    // big is ARRAY[1..GC_SIZE * 2] (GC_SIZE = 2); the Standard.TON reaches PT = 100 ms at 100 ms.
    let text = std::fs::read_to_string(&trace).unwrap();
    let rows: Vec<&str> = text.lines().collect();
    assert_eq!(
        rows[0],
        "cycle,time_ms,PRG_MAIN.count,PRG_MAIN.arr[3],PRG_MAIN.big[4],PRG_MAIN.done"
    );
    assert_eq!(rows[1], "0,0,1,1,10,0");
    assert_eq!(rows[5], "4,40,1,1,10,0");
    assert_eq!(rows[6], "5,50,2,2,20,0");
    assert_eq!(rows[10], "9,90,2,2,20,0");
    assert_eq!(rows[11], "10,100,3,3,30,1");
}

fn check(xml: &str) -> (Option<i32>, String) {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("p.xml");
    std::fs::write(&f, xml).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&f)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn xsd_durations_are_validated_with_a_located_diagnostic() {
    let good = std::fs::read_to_string(fixture()).unwrap();
    let line = good
        .lines()
        .position(|l| l.contains("interval=\"PT0.05S\""))
        .unwrap()
        + 1;
    for (bad, why) in [
        ("PT1M30", "a number must be followed by a unit"),
        ("P1M", "years and months have no fixed length"),
        ("PT", "`T` must be followed by"),
        ("PT1S2M", "out of order"),
        ("-PT1S", "cannot be negative"),
        ("PT1.5M", "only the seconds may have a fraction"),
    ] {
        let (code, err) = check(&good.replace("PT0.05S", bad));
        assert_eq!(code, Some(1), "{bad}: {err}");
        let want = format!("p.xml:{line}:");
        let diag = err
            .lines()
            .find(|l| l.contains("error[E3400]"))
            .unwrap_or_else(|| panic!("{bad}: {err}"));
        assert!(diag.contains(&want), "{bad}: {diag}");
        assert!(diag.contains(why), "{bad}: {diag}");
        assert_eq!(err.matches("error[").count(), 1, "{bad}: {err}");
    }
    // the long form of IEC 60559 times: hours, minutes, seconds with a fraction
    let (code, err) = check(&good.replace("PT0.05S", "PT1H2M3.5S"));
    assert_eq!(code, Some(0), "{err}");
}

#[test]
fn an_unknown_constant_in_an_array_bound_is_named() {
    let good = std::fs::read_to_string(fixture()).unwrap();
    let (code, err) = check(&good.replace("upper=\"GC_SIZE * 2\"", "upper=\"GC_SIZ * 2\""));
    assert_eq!(code, Some(1), "{err}");
    let diag = err.lines().find(|l| l.contains("error[")).unwrap();
    assert!(diag.contains("error[E3401]"), "{diag}");
    assert!(diag.contains("unknown constant `GC_SIZ`"), "{diag}");
    assert!(diag.contains("p.xml:17:"), "{diag}");
    // a POU's constant is its own: another POU cannot size an array with it
    let other = good.replace(
        "<pou name=\"PRG_MAIN\"",
        "<pou name=\"FB_OTHER\" pouType=\"functionBlock\"><interface><localVars><variable name=\"a\"><type><array><dimension lower=\"0\" upper=\"ciN\" /><baseType><INT /></baseType></array></type></variable></localVars></interface><body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">a[0] := 1;</xhtml></ST></body></pou>\n      <pou name=\"PRG_MAIN\"",
    );
    let (code, err) = check(&other);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("unknown constant `ciN`"), "{err}");
}
