//! Round 28 of unseen projects (issue #13), semantics found by the sweep, run end to end through
//! `ladderc run`:
//! - a POU that declares its own `EN` input (`VAR_INPUT EN : BOOL`) has that input for its enable,
//!   as IEC 61131-3 (ed.3 6.6.1.6) and matiec (add_en_eno_param_decl) read it: a block's call
//!   stores the value into the instance and the body runs only while it is TRUE (and reads it); a
//!   function's body does not run with EN FALSE (its result is its type's initial value); a
//!   declared `ENO` output is TRUE when the body starts and FALSE when it does not run, in ST and
//!   IL (before: a block's call was gated but the declared input never written, so the body read
//!   FALSE; a function with `EN := FALSE` ran its body);
//! - CONFIGURATIONs that declare no program instance (the empty `config`/`resource1` Beremiz
//!   writes into every export): every PROGRAM runs as without a configuration, with W1453 at the
//!   configuration (before: nothing ran, silently, and `--watch Main.n` was "unknown variable");
//! - a PLCopen `<pou pouType="function">` without `<returnType>` is a function without result, as
//!   `FUNCTION F` is in ST (before: E3013);
//! - two configurations (or two resources) each with a program instance `P1`: their variables are
//!   traced as `CfgA.P1.n` and `CfgB.P1.n`, and the unqualified `--watch P1.n` is a usage error
//!   listing both (before: two trace columns named `P1.n`, `--watch P1.n` silently the first one,
//!   `CfgB.P1.n` unknown);
//!
//! (IL's `CAL cnt(pulse, FALSE, limit, full, value)` listing every parameter of a standard block
//! by position, IEC 61131-3 ed. 2 Table 53, runs since round 29: `positional_outputs_r29_run.rs`.)

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

/// A block with its own `en` input: the call `a(en := go, ...)` writes `go` into `a.en`, and the
/// body runs (and counts) only while it is TRUE, reading TRUE there.
#[test]
fn declared_en_of_a_block_is_written_and_gates_its_body() {
    let src = "FUNCTION_BLOCK Acc
VAR_INPUT
  en : BOOL;
  inc : INT;
END_VAR
VAR_OUTPUT
  total : INT;
  calls : INT;
END_VAR
calls := calls + 1;
IF en THEN
  total := total + inc;
END_IF;
END_FUNCTION_BLOCK

FUNCTION_BLOCK Gate
VAR_INPUT
  EN : BOOL := TRUE;
  x : INT;
END_VAR
VAR_OUTPUT
  y : INT;
  sawEn : BOOL;
END_VAR
sawEn := EN;
y := x * 2;
END_FUNCTION_BLOCK

PROGRAM Main
VAR
  a : Acc;
  g : Gate;
  k : INT;
  go : BOOL;
END_VAR
k := k + 1;
go := k >= 3 AND k <= 4;
a(en := go, inc := 3);
g(EN := go, x := k);
END_PROGRAM
";
    let (trace, _) = run_text(
        "acc.st",
        src,
        5,
        "Main.go,Main.a.en,Main.a.calls,Main.a.total,Main.g.EN,Main.g.sawEn,Main.g.y",
    );
    assert_eq!(
        column(&trace, "Main.go"),
        vec![0.0, 0.0, 1.0, 1.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "Main.a.en"),
        vec![0.0, 0.0, 1.0, 1.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "Main.a.calls"),
        vec![0.0, 0.0, 1.0, 2.0, 2.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "Main.a.total"),
        vec![0.0, 0.0, 3.0, 6.0, 6.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "Main.g.EN"),
        vec![0.0, 0.0, 1.0, 1.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "Main.g.sawEn"),
        vec![0.0, 0.0, 1.0, 1.0, 1.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "Main.g.y"),
        vec![0.0, 0.0, 6.0, 8.0, 8.0],
        "{trace}"
    );
}

/// A block with a declared EN that is called without it runs by the instance's own EN (its
/// initial value, or what the program stored into it), in ST and in IL.
#[test]
fn declared_en_of_a_block_gates_a_call_without_it() {
    let src = "FUNCTION_BLOCK Cnt
VAR_INPUT
  EN : BOOL := TRUE;
END_VAR
VAR_OUTPUT
  n : INT;
END_VAR
n := n + 1;
END_FUNCTION_BLOCK

PROGRAM Main
VAR
  c : Cnt;
  k : INT;
END_VAR
k := k + 1;
c.EN := k <> 2;
c();
END_PROGRAM

PROGRAM Other
VAR
  d : Cnt;
END_VAR
  LD FALSE
  ST d.EN
  CAL d
END_PROGRAM
";
    let (trace, _) = run_text("cnt.st", src, 3, "Main.c.n,Other.d.n");
    assert_eq!(column(&trace, "Main.c.n"), vec![1.0, 1.0, 2.0], "{trace}");
    assert_eq!(column(&trace, "Other.d.n"), vec![0.0, 0.0, 0.0], "{trace}");
}

/// A function with its own `EN` input: with EN FALSE its body does not run and its result is
/// its type's initial value (0), as for the implicit EN; with EN TRUE the body reads TRUE.
#[test]
fn declared_en_of_a_function_skips_its_body() {
    let src = "FUNCTION Dbl : INT
VAR_INPUT
  EN : BOOL := TRUE;
  x : INT;
END_VAR
IF EN THEN
  Dbl := x * 2;
ELSE
  Dbl := -1;
END_IF;
END_FUNCTION

PROGRAM Main
VAR
  k : INT;
  go : BOOL;
  r1 : INT;
  r2 : INT := 5;
  r3 : INT;
END_VAR
k := k + 1;
go := k = 2;
r1 := Dbl(EN := go, x := 7);
r3 := Dbl(x := 4);
END_PROGRAM

PROGRAM IlMain
VAR
  go : BOOL;
  r : INT := 9;
END_VAR
  LD go
  NOT
  ST go
  Dbl 10
  ST r
END_PROGRAM
";
    let (trace, _) = run_text("dbl.st", src, 3, "Main.r1,Main.r3,IlMain.go,IlMain.r");
    assert_eq!(column(&trace, "Main.r1"), vec![0.0, 14.0, 0.0], "{trace}");
    assert_eq!(column(&trace, "Main.r3"), vec![8.0, 8.0, 8.0], "{trace}");
    assert_eq!(column(&trace, "IlMain.go"), vec![1.0, 0.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "IlMain.r"), vec![20.0, 0.0, 20.0], "{trace}");
}

/// A declared `ENO` output: TRUE when the body starts (the body may reset it), FALSE when EN
/// keeps the body from running; `ENO => v` reads it, of a block and of a function.
#[test]
fn declared_eno_is_true_when_the_body_runs_and_false_when_not() {
    let src = "FUNCTION_BLOCK Chk
VAR_INPUT
  EN : BOOL;
  x : INT;
END_VAR
VAR_OUTPUT
  ENO : BOOL;
END_VAR
IF x > 3 THEN
  ENO := FALSE;
END_IF;
END_FUNCTION_BLOCK

FUNCTION FChk : INT
VAR_INPUT
  EN : BOOL;
  x : INT;
END_VAR
VAR_OUTPUT
  ENO : BOOL;
END_VAR
FChk := x;
IF x > 3 THEN
  ENO := FALSE;
END_IF;
END_FUNCTION

PROGRAM Main
VAR
  c : Chk;
  k : INT;
  ok : BOOL := TRUE;
  fok : BOOL := TRUE;
  r : INT;
END_VAR
k := k + 1;
c(EN := k <> 2, x := k, ENO => ok);
r := FChk(EN := k <> 2, x := k, ENO => fok);
END_PROGRAM
";
    let (trace, _) = run_text("chk.st", src, 4, "Main.ok,Main.fok,Main.r");
    assert_eq!(
        column(&trace, "Main.ok"),
        vec![1.0, 0.0, 1.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "Main.fok"),
        vec![1.0, 0.0, 1.0, 0.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "Main.r"),
        vec![1.0, 0.0, 3.0, 4.0],
        "{trace}"
    );
}

/// A configuration whose resource declares no program instance (as Beremiz exports it): the
/// PROGRAM runs as without a configuration, and W1453 at the configuration says so.
#[test]
fn empty_configuration_runs_the_programs_with_a_warning() {
    let src = "PROGRAM Main
VAR n : INT; END_VAR
n := n + 1;
END_PROGRAM
CONFIGURATION config
  RESOURCE resource1 ON PLC
  END_RESOURCE
END_CONFIGURATION
";
    let (trace, stderr) = run_text("empty.st", src, 3, "Main.n");
    assert_eq!(column(&trace, "Main.n"), vec![1.0, 2.0, 3.0], "{trace}");
    assert!(
        stderr.contains("empty.st:5:15: warning[W1453]: configuration `config` declares no program instance: PROGRAM `Main` runs each cycle as without a configuration"),
        "{stderr}"
    );
    let (code, lines) = check_text("empty.st", src);
    assert_eq!(code, Some(0));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(lines[0].contains("warning[W1453]"), "{lines:?}");
}

/// A PLCopen function without `<returnType>` is a function without result: it gives its values
/// through its outputs, as the same `FUNCTION Invert` in ST.
#[test]
fn plcopen_function_without_return_type_runs() {
    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="c" productName="p" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="n"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Negate" pouType="function">
      <interface>
        <inputVars><variable name="a"><type><BOOL/></type></variable></inputVars>
        <outputVars><variable name="q"><type><BOOL/></type></variable></outputVars>
      </interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">q := NOT a;</xhtml></ST></body>
    </pou>
    <pou name="Main" pouType="program">
      <interface><localVars>
        <variable name="x"><type><BOOL/></type></variable>
        <variable name="y"><type><BOOL/></type></variable>
      </localVars></interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">x := NOT x; Negate(a := x, q =&gt; y);</xhtml></ST></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#;
    let (trace, stderr) = run_text("neg.xml", xml, 3, "Main.x,Main.y");
    assert!(!stderr.contains("E3013"), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), vec![1.0, 0.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "Main.y"), vec![0.0, 1.0, 0.0], "{trace}");
}

const TWO_CONFIGS: &str = "PROGRAM Count
VAR_INPUT
  step : INT;
END_VAR
VAR_OUTPUT
  n : INT;
END_VAR
n := n + step;
END_PROGRAM

CONFIGURATION CfgA
  RESOURCE R1 ON PLC
    TASK t(INTERVAL := T#10ms, PRIORITY := 1);
    PROGRAM P1 WITH t : Count(step := 1);
    PROGRAM Solo WITH t : Count(step := 5);
  END_RESOURCE
END_CONFIGURATION

CONFIGURATION CfgB
  RESOURCE R1 ON PLC
    TASK t(INTERVAL := T#10ms, PRIORITY := 1);
    PROGRAM P1 WITH t : Count(step := 100);
  END_RESOURCE
END_CONFIGURATION
";

/// Two configurations each with an instance `P1`: the instances' variables are traced qualified
/// by their configuration (`CfgA.P1.n`, `CfgB.P1.n`), an instance name no other has stays as it
/// is (`Solo.n`), and each can be watched.
#[test]
fn clashing_instance_names_are_qualified_by_configuration() {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "two.st", TWO_CONFIGS);
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &["run", "two.st", "--cycles", "2", "--trace", "-"],
    );
    assert_eq!(code, Some(0), "{stderr}");
    let header = trace.lines().next().unwrap();
    assert_eq!(
        header, "cycle,time_ms,CfgA.P1.step,CfgA.P1.n,Solo.step,Solo.n,CfgB.P1.step,CfgB.P1.n",
        "{trace}"
    );
    let (trace, _) = run_text("two.st", TWO_CONFIGS, 2, "CfgB.P1.n,CfgA.P1.n,Solo.n");
    assert_eq!(column(&trace, "CfgB.P1.n"), vec![100.0, 200.0], "{trace}");
    assert_eq!(column(&trace, "CfgA.P1.n"), vec![1.0, 2.0], "{trace}");
    assert_eq!(column(&trace, "Solo.n"), vec![5.0, 10.0], "{trace}");
}

/// The unqualified `--watch P1.n` of two such instances is a usage error that lists both.
#[test]
fn ambiguous_unqualified_watch_is_a_usage_error() {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "two.st", TWO_CONFIGS);
    let (code, _, stderr) = in_dir(
        dir.path(),
        &["run", "two.st", "--cycles", "1", "--watch", "P1.n"],
    );
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("`P1.n` is ambiguous")
            && stderr.contains("`CfgA.P1.n`")
            && stderr.contains("`CfgB.P1.n`"),
        "{stderr}"
    );
}
