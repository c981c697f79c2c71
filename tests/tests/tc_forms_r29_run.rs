//! Round 29 of issue #13: TwinCAT dialect forms seen in unseen TwinCAT 3 projects.
//!
//! - Tc2_Standard's counters count in WORD (Beckhoff Infosys, Tc2_Standard > CTU, CTD, CTUD:
//!   `PV : WORD`, `CV : WORD`; CTD counts down "as long as CV is greater than 0"; CODESYS's
//!   Standard library likewise): `CTU`, `CTD`, `CTUD` of a TwinCAT object or CODESYS file are
//!   those blocks. Before: IEC's INT counters, a false E1006 for `w := c.CV;` with `w : WORD`.
//! - `fbPower.Override := x;` of an MC_Power instance whose calls also pass `Override` (Infosys
//!   Tc2_MC2 > MC_Power: `Override : LREAL`): an input written by name between calls. Before:
//!   E1015 naming the output `Error`, E1006 "INT into BOOL" and E1041.
//! - `VAR_GENERIC CONSTANT` (Infosys TC3 PLC, "Generic constant variables - VAR_GENERIC
//!   CONSTANT", TwinCAT 3.1.4026): read without parse errors (rounds 29-30: one located E1081 per
//!   block and per `<...>` instance; compiled since round 31, `generic_r31_run.rs`). Before:
//!   seven parse errors (E0106, E0001) and none saying what is not supported.
//! - A bound's constant qualified by a library's namespace and its parameter list
//!   (`ARRAY[1..Tc3_Lib.Params.n]`): E1032 naming the library, as in a type. Before: E0022
//!   "`n` is not an integer constant declared before".

mod common;
use common::{check_files, column, ladderc, run_stimulated};

fn tc_pou(name: &str, declaration: &str, body: &str) -> String {
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>
<TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4026.0\">
  <POU Name=\"{name}\" Id=\"{{00000000-0000-4000-8000-000000000001}}\" SpecialFunc=\"None\">
    <Declaration><![CDATA[{declaration}]]></Declaration>
    <Implementation>
      <ST><![CDATA[{body}]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
"
    )
}

const COUNTERS_DECL: &str = "PROGRAM MAIN
VAR
	pulse : BOOL;
	n : INT;
	down : CTD;
	up : CTU;
	both : CTUD;
	wDown : WORD;
	wUp : WORD;
	wBoth : WORD;
	upDone : BOOL;
END_VAR
";

const COUNTERS_BODY: &str = "n := n + 1;
pulse := NOT pulse;
down(CD := pulse, LOAD := n = 1, PV := 2);
wDown := down.CV;
up(CU := pulse, RESET := FALSE, PV := 40000);
wUp := up.CV;
upDone := up.Q;
both(CU := FALSE, CD := pulse, RESET := FALSE, LOAD := FALSE, PV := 65535);
wBoth := both.CV;";

/// A TwinCAT object's CTD, CTU and CTUD count in WORD: `w := c.CV` with `w : WORD` checks, the
/// preset 40000 (beyond INT) and 65535 are WORD values, and the counters stop at 0 instead of
/// going negative (Tc2_Standard CTD: "decremented by 1 as long as CV is greater than 0"): CTD
/// loaded with 2 reads 2, 2, 1, 1, 0 and then stays 0; a CTUD counting down from 0 stays 0.
/// Before: E1006 "cannot store INT into WORD" at each `w := c.CV;`.
#[test]
fn twincat_counters_count_in_word_and_stop_at_zero() {
    let dir = tempfile::tempdir().unwrap();
    let main = dir.path().join("MAIN.TcPOU");
    std::fs::write(&main, tc_pou("MAIN", COUNTERS_DECL, COUNTERS_BODY)).unwrap();
    let (trace, stderr) =
        run_stimulated(&main, 8, "", "MAIN.wDown,MAIN.wUp,MAIN.wBoth,MAIN.upDone");
    assert!(!stderr.contains("error["), "{stderr}");
    // pulse TRUE at scans 0, 2, 4, 6: a rising edge there (the first is the load's scan)
    assert_eq!(
        column(&trace, "MAIN.wDown"),
        [2.0, 2.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0]
    );
    assert_eq!(
        column(&trace, "MAIN.wUp"),
        [1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0]
    );
    assert_eq!(column(&trace, "MAIN.wBoth"), [0.0; 8]);
    assert_eq!(column(&trace, "MAIN.upDone"), [0.0; 8]);
}

/// The same counters in an IEC 61131-3 `.st` file stay IEC's INT counters: `w := c.CV` with
/// `w : WORD` is E1006 there (the INT counter's CV is no WORD), as before this round.
#[test]
fn iec_counters_stay_int_in_st_files() {
    let st = format!(
        "{}{}\nEND_PROGRAM\n",
        COUNTERS_DECL.replace("PROGRAM MAIN", "PROGRAM Main"),
        "n := n + 1;
pulse := NOT pulse;
down(CD := pulse, LD := n = 1, PV := 2);
wDown := down.CV;
up(CU := pulse, R := FALSE, PV := 400);
wUp := up.CV;
both(CU := FALSE, CD := pulse, R := FALSE, LD := FALSE, PV := 600);
wBoth := both.CV;"
    );
    let (code, lines) = check_files(&[("main.st", &st)]);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 3, "{lines:?}");
    assert!(
        lines
            .iter()
            .all(|l| l.contains("error[E1006]: cannot store INT into WORD")),
        "{lines:?}"
    );
}

const AXES: &str = r#"{ "cycle_ms": 10, "axes": [ { "name": "X1", "velocity": 200, "acceleration": 1000, "deceleration": 1000, "jerk": 10000 } ] }"#;

/// `pw.Override := 20;` between calls that pass `Override := speed` (Infosys Tc2_MC2 MC_Power:
/// `Override : LREAL`): reading `pw.Override` gives the value last given, by the call (50) or by
/// the assignment (20, read before the next call gives 50 again). Before: E1015 "`Error` is an
/// output", E1006 "cannot store INT into BOOL" and E1041 on the one assignment.
#[test]
fn mc_power_override_written_between_calls_that_pass_it() {
    let dir = tempfile::tempdir().unwrap();
    let axes = dir.path().join("x.axes.json");
    std::fs::write(&axes, AXES).unwrap();
    let src = dir.path().join("main.st");
    std::fs::write(
        &src,
        "PROGRAM Main
VAR
  X1 : AXIS_REF;
  pw : MC_Power;
  speed : INT := 50;
  y : LREAL;
  n : INT;
END_VAR
n := n + 1;
pw(Axis := X1, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE, Override := speed);
y := pw.Override;
IF n = 3 THEN
  pw.Override := 20;
  y := pw.Override;
END_IF;
END_PROGRAM
",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(&src)
        .arg("--axes")
        .arg(&axes)
        .args(["--cycles", "5", "--trace", "-", "--watch", "Main.y,Main.n"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("error["), "{stderr}");
    let trace = String::from_utf8_lossy(&out.stdout);
    assert_eq!(column(&trace, "Main.n"), [1.0, 2.0, 3.0, 4.0, 5.0]);
    assert_eq!(column(&trace, "Main.y"), [50.0, 50.0, 20.0, 50.0, 50.0]);
}

/// A write into an MC_Power input that ladderc's axis has no counterpart for
/// (`pw.BufferMode := MC_Aborting;`, Tc2_MC2 MC_Power's `BufferMode`) is the one E1041 at the
/// pin. Before: E1015 "`Error` is an output of FB instance `pw`" and E1006 "cannot store USINT
/// into BOOL" besides (the pin was renamed to `Error` to silence its reads).
#[test]
fn a_write_into_a_pin_without_counterpart_is_e1041_only() {
    let dir = tempfile::tempdir().unwrap();
    let axes = dir.path().join("x.axes.json");
    std::fs::write(&axes, AXES).unwrap();
    let src = dir.path().join("main.st");
    std::fs::write(
        &src,
        "PROGRAM Main
VAR
  X1 : AXIS_REF;
  pw : MC_Power;
END_VAR
pw(Axis := X1, Enable := TRUE);
pw.BufferMode := MC_Aborting;
END_PROGRAM
",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&src)
        .arg("--axes")
        .arg(&axes)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(
        errors[0].contains("main.st:7:4: error[E1041]: Tc2_MC2's `BufferMode` of MC_Power"),
        "{errors:?}"
    );
}

const GENERIC_FB: &str = "FUNCTION_BLOCK FB_Multi
VAR_GENERIC CONSTANT
	nLen : UDINT := 1;
END_VAR
VAR
	aVal : ARRAY[0..nLen - 1] OF INT;
	i : UDINT;
END_VAR
VAR_OUTPUT
	nSum : INT;
END_VAR
";

/// A block with `VAR_GENERIC CONSTANT` and an instance `FB_Multi<3>`: read without a parse error
/// (the block's declarations and body, the instance's call and output as usual). Before round 29:
/// five E0106 and two E0001 (`<`, `>`); rounds 29 and 30: one E1081 at `VAR_GENERIC` and one at
/// `<3>`; since round 31 it compiles (`generic_r31_run.rs` runs such blocks).
#[test]
fn var_generic_constant_reads_without_parse_errors() {
    let fb = tc_pou(
        "FB_Multi",
        GENERIC_FB,
        "nSum := 0;
FOR i := 0 TO nLen - 1 DO
	aVal[i] := 2;
	nSum := nSum + aVal[i];
END_FOR",
    );
    let main = tc_pou(
        "MAIN",
        "PROGRAM MAIN
VAR
	fb : FB_Multi<3>;
	n : INT;
END_VAR
",
        "fb();\nn := fb.nSum;",
    );
    let (code, lines) = check_files(&[("FB_Multi.TcPOU", &fb), ("MAIN.TcPOU", &main)]);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(lines.is_empty(), "{lines:?}");
}

/// TwinCAT writes a generic block's IMPLEMENTS clause after its `VAR_GENERIC CONSTANT` block
/// (`END_VAR IMPLEMENTS I_Sized`): the clause is the block's (its method is the interface's), and
/// nothing is reported (rounds 29 and 30: the one E1081 of the generic block). Before: E0106
/// "after `END_VAR`, found name `IMPLEMENTS`" and more.
#[test]
fn implements_after_the_generic_block_is_the_blocks_clause() {
    let itf = "<?xml version=\"1.0\" encoding=\"utf-8\"?>
<TcPlcObject Version=\"1.1.0.1\">
  <Itf Name=\"I_Sized\" Id=\"{00000000-0000-4000-8000-000000000002}\">
    <Declaration><![CDATA[INTERFACE I_Sized
]]></Declaration>
    <Method Name=\"Size\" Id=\"{00000000-0000-4000-8000-000000000003}\">
      <Declaration><![CDATA[METHOD Size : UDINT
]]></Declaration>
    </Method>
  </Itf>
</TcPlcObject>
";
    let fb = "<?xml version=\"1.0\" encoding=\"utf-8\"?>
<TcPlcObject Version=\"1.1.0.1\">
  <POU Name=\"FB_Sized\" Id=\"{00000000-0000-4000-8000-000000000004}\" SpecialFunc=\"None\">
    <Declaration><![CDATA[FUNCTION_BLOCK FB_Sized
VAR_GENERIC CONSTANT
	nMax : UDINT := 4;
END_VAR IMPLEMENTS I_Sized
VAR
	aItems : ARRAY[0..nMax] OF INT;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[]]></ST>
    </Implementation>
    <Method Name=\"Size\" Id=\"{00000000-0000-4000-8000-000000000005}\">
      <Declaration><![CDATA[METHOD Size : UDINT
]]></Declaration>
      <Implementation>
        <ST><![CDATA[Size := nMax;]]></ST>
      </Implementation>
    </Method>
  </POU>
</TcPlcObject>
";
    let main = tc_pou(
        "MAIN",
        "PROGRAM MAIN
VAR
	fb : FB_Sized;
	itf : I_Sized := fb;
	n : UDINT;
END_VAR
",
        "n := itf.Size();",
    );
    let (code, lines) = check_files(&[
        ("I_Sized.TcIO", itf),
        ("FB_Sized.TcPOU", fb),
        ("MAIN.TcPOU", &main),
    ]);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(lines.is_empty(), "{lines:?}");
    // the same in a `.st` file, the block without methods
    let st = "INTERFACE I_Empty
END_INTERFACE

FUNCTION_BLOCK FB_Sized
VAR_GENERIC CONSTANT
\tnMax : UDINT := 4;
END_VAR IMPLEMENTS I_Empty
VAR
\taItems : ARRAY[0..nMax] OF INT;
END_VAR
END_FUNCTION_BLOCK
";
    let (code, lines) = check_files(&[("sized.st", st)]);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(lines.is_empty(), "{lines:?}");
}

/// `ARRAY[1..Tc3_Lib.Params.n]` in a TwinCAT object: one E1032 at `Tc3_Lib`, naming the library
/// and the bound; with the same library also in a type, one E1032 for the library (at its first
/// report). A list qualifier alone (`Params.n`) stays E0022, now naming `Params.n` as written.
/// Before: E0022 "`n` is not an integer constant declared before" for both bounds.
#[test]
fn library_qualified_bound_names_the_library() {
    let decl = |extra: &str| {
        format!(
            "PROGRAM MAIN
VAR
	aMovers : ARRAY[1..Tc3_Lib.Params.n] OF INT;
	aLocal : ARRAY[1..Params.n] OF INT;{extra}
	i : INT;
END_VAR
"
        )
    };
    let main = tc_pou("MAIN", &decl(""), "i := i + 1;");
    let (code, lines) = check_files(&[("MAIN.TcPOU", &main)]);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 2, "{lines:?}");
    let library = lines
        .iter()
        .find(|l| l.contains("E1032"))
        .unwrap_or_else(|| panic!("{lines:?}"));
    assert!(
        library.starts_with(
            "MAIN.TcPOU:6:21: error[E1032]: `Tc3_Lib` in the bound `Tc3_Lib.Params.n` is neither a global variable list nor a library ladderc provides"
        ),
        "{lines:?}"
    );
    let list = lines
        .iter()
        .find(|l| l.contains("E0022"))
        .unwrap_or_else(|| panic!("{lines:?}"));
    assert!(
        list.starts_with("MAIN.TcPOU:7:27: error[E0022]"),
        "{lines:?}"
    );
    assert!(
        list.contains("`Params.n` names no constant with a value in the files given"),
        "{lines:?}"
    );
    // the library also in a type: one E1032
    let main = tc_pou("MAIN", &decl("\n\tx : Tc3_Lib.ST_Thing;"), "i := i + 1;");
    let (code, lines) = check_files(&[("MAIN.TcPOU", &main)]);
    assert_eq!(code, Some(1), "{lines:?}");
    let e1032: Vec<_> = lines.iter().filter(|l| l.contains("E1032")).collect();
    assert_eq!(e1032.len(), 1, "{lines:?}");
    assert!(e1032[0].contains("`Tc3_Lib`"), "{lines:?}");
}
