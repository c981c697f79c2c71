//! Issue #13, eleventh round (helper `small`): forms of real CODESYS and TwinCAT projects that were
//! refused, each through `ladderc run` (or `check`) on small inputs written here, in every input kind
//! that can carry it:
//! - **A PROGRAM called from another POU** (`P();`, `P(in := x, out => y);` in ST, `CAL P(in := x)`
//!   in IL, `P.out` read after it): the call runs the program's body once on its one instance (the
//!   implicit one without a configuration, the configuration's one instance, or, when the
//!   configuration does not instantiate it, an instance of its own that only the calls run), with
//!   warning W1417. A program that a task runs and a POU calls runs twice a cycle: CODESYS's manual
//!   ("Object: Program", Calling a program) keeps a program's values from one call to the next
//!   whichever POU calls it. Two instances, a call of itself or a call from a FUNCTION (which
//!   CODESYS refuses too) is E3135. Before: E1018 in ST, E1001 in IL.
//! - **`AND_THEN` / `OR_ELSE`** (CODESYS, TwinCAT): compiled with short-circuit evaluation (the
//!   right operand's calls and indexes run only when the left does not decide), with warning W0324
//!   once per text. Before: E0324 at each operator.

mod common;
use common::{check_text, column, rejected_heads, run_traced, run_traced_files, write_file};

const COUNTER: &str = "PROGRAM Counter\nVAR_INPUT inc : INT := 1; END_VAR\n\
                       VAR_OUTPUT total : INT; big : BOOL; END_VAR\n\
                       total := total + inc;\nbig := total > 5;\nEND_PROGRAM\n";

// ------------------------------------------------------------------ 1. programs called by POUs

/// Without a configuration every program runs once a cycle in source order (Counter, then Main),
/// and Main's calls run Counter twice more on the same instance: `Counter(inc := 2, big => flag)`
/// passes 2 (kept for the bare `Counter();` after it and for the scan's own run next cycle, as
/// inputs keep their values) and reads `big`; IL's `CAL Counter(inc := 2)` in a third program runs
/// it once more.
#[test]
fn a_program_called_from_st_and_il_runs_on_its_one_instance() {
    let dir = tempfile::tempdir().unwrap();
    let st = write_file(
        dir.path(),
        "calls.st",
        &format!(
            "{COUNTER}PROGRAM Main\nVAR seen : INT; flag : BOOL; END_VAR\n\
             Counter(inc := 2, big => flag);\nseen := Counter.total;\nCounter();\nEND_PROGRAM\n"
        ),
    );
    let (trace, stderr) = run_traced(&st, 3, "Counter.total,Main.seen,Main.flag");
    assert_eq!(
        trace,
        "cycle,time_ms,Counter.total,Main.seen,Main.flag\n0,0,5,3,0\n1,10,11,9,1\n2,20,17,15,1\n"
    );
    assert!(
        stderr.contains(
            "calls.st:9:1: warning[W1417]: program `Counter` called from another POU (a CODESYS \
             and TwinCAT extension: it runs on the program's one instance)"
        ),
        "{stderr}"
    );
    assert_eq!(stderr.matches("W1417").count(), 1, "once per POU: {stderr}");
    let il = write_file(
        dir.path(),
        "calls.il",
        "PROGRAM MainIl\nVAR seen : INT; END_VAR\nCAL Counter(inc := 2)\nLD Counter.total\n\
         ST seen\nEND_PROGRAM\n",
    );
    let (trace, _) = run_traced_files(&[&st, &il], 3, "Counter.total,Main.seen,MainIl.seen");
    assert_eq!(
        trace,
        "cycle,time_ms,Counter.total,Main.seen,MainIl.seen\n0,0,7,3,7\n1,10,15,11,15\n2,20,23,19,23\n"
    );
}

/// With a configuration: Counter's one instance `C1` runs in the task after `M`, and M's function
/// block calls it first (`Counter(inc := 10)` in FB Caller), so it runs twice a cycle (+10 twice);
/// Helper, which no resource instantiates, has an instance of its own that only M's call runs
/// (every second cycle), traced under its name.
#[test]
fn a_configured_program_called_by_a_block_runs_twice_and_one_in_no_task_only_when_called() {
    let dir = tempfile::tempdir().unwrap();
    let f = write_file(
        dir.path(),
        "cfg.st",
        "PROGRAM Counter\nVAR_INPUT inc : INT := 1; END_VAR\nVAR_OUTPUT total : INT; END_VAR\n\
         total := total + inc;\nEND_PROGRAM\n\
         PROGRAM Helper\nVAR_INPUT k : INT; END_VAR\nVAR_OUTPUT runs : INT; last : INT; END_VAR\n\
         runs := runs + 1;\nlast := k;\nEND_PROGRAM\n\
         FUNCTION_BLOCK Caller\nVAR_OUTPUT seen : INT; END_VAR\n\
         Counter(inc := 10);\nseen := Counter.total;\nEND_FUNCTION_BLOCK\n\
         PROGRAM Main\nVAR c : Caller; n : INT; END_VAR\nn := n + 1;\nc();\n\
         IF n MOD 2 = 0 THEN\n  Helper(k := n);\nEND_IF;\nEND_PROGRAM\n\
         CONFIGURATION Cfg\nRESOURCE Res ON PLC\nTASK Fast(INTERVAL := T#10ms, PRIORITY := 1);\n\
         PROGRAM M WITH Fast : Main;\nPROGRAM C1 WITH Fast : Counter;\nEND_RESOURCE\n\
         END_CONFIGURATION\n",
    );
    let (trace, _) = run_traced(&f, 4, "M.c.seen,C1.total,Helper.runs,Helper.last");
    assert_eq!(
        trace,
        "cycle,time_ms,M.c.seen,C1.total,Helper.runs,Helper.last\n\
         0,0,10,20,0,0\n1,10,30,40,1,2\n2,20,50,60,1,2\n3,30,70,80,2,4\n"
    );
}

/// Two instances (which one?), a program calling itself (never ends) and a call from a FUNCTION
/// (no state; CODESYS refuses it too): one E3135 each, at the call.
#[test]
fn program_calls_without_one_instance_or_from_a_function_are_one_e3135_each() {
    let src = "PROGRAM Counter\nVAR total : INT; END_VAR\ntotal := total + 1;\nEND_PROGRAM\n\
               PROGRAM Loop\nLoop();\nEND_PROGRAM\n\
               FUNCTION F : INT\nCounter();\nF := 1;\nEND_FUNCTION\n\
               PROGRAM Main\nVAR x : INT; END_VAR\nCounter();\nx := F();\nEND_PROGRAM\n\
               CONFIGURATION Cfg\nRESOURCE Res ON PLC\nTASK Fast(INTERVAL := T#10ms, PRIORITY := 1);\n\
               PROGRAM M WITH Fast : Main;\nPROGRAM A WITH Fast : Counter;\n\
               PROGRAM B WITH Fast : Counter;\nPROGRAM L WITH Fast : Loop;\nEND_RESOURCE\n\
               END_CONFIGURATION\n";
    assert_eq!(
        rejected_heads("errs.st", src),
        vec![
            "errs.st:6:1: error[E3135]: program `Loop` cannot be called here: `Loop` calls itself, \
             which would never end",
            "errs.st:9:1: error[E3135]: program `Counter` cannot be called here: a FUNCTION has no \
             state between calls, so it may not run program `Counter` (CODESYS and TwinCAT refuse \
             it too)",
            "errs.st:14:1: error[E3135]: program `Counter` cannot be called here: program \
             `Counter` has 2 instances in the configuration: the call does not say which one",
        ]
    );
}

/// A PLCopen XML project whose task runs only `main`: its ST body calls program `adder` (an instance
/// of its own, run only by the call) and reads its output.
#[test]
fn a_program_called_from_a_plcopen_st_body_runs() {
    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="ladderc" productName="tests" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="calls"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="adder" pouType="program"><interface>
      <inputVars><variable name="step"><type><INT/></type></variable></inputVars>
      <outputVars><variable name="acc"><type><INT/></type></variable></outputVars>
    </interface><body><ST><xhtml:p><![CDATA[acc := acc + step;]]></xhtml:p></ST></body></pou>
    <pou name="main" pouType="program"><interface>
      <localVars><variable name="got"><type><INT/></type></variable></localVars>
    </interface><body><ST><xhtml:p><![CDATA[adder(step := 3);
got := adder.acc * 2;]]></xhtml:p></ST></body></pou>
  </pous></types>
  <instances><configurations><configuration name="cfg"><resource name="res">
    <task name="cyclic" priority="1" interval="T#10ms"><pouInstance name="main" typeName="main"/></task>
  </resource></configuration></configurations></instances>
</project>
"#;
    let dir = tempfile::tempdir().unwrap();
    let f = write_file(dir.path(), "calls.xml", xml);
    let (trace, _) = run_traced(&f, 3, "main.got,adder.acc");
    assert_eq!(
        trace,
        "cycle,time_ms,main.got,adder.acc\n0,0,6,3\n1,10,12,6\n2,20,18,9\n"
    );
}

/// A TwinCAT object file's ST body (no task file: MAIN runs) calls P_Sub with an output
/// (`bOut => ok`) and guards a read of P_Sub's count with AND_THEN.
#[test]
fn twincat_programs_call_programs_and_use_and_then() {
    fn pou(name: &str, decl: &str, body: &str) -> String {
        format!(
            "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  \
             <POU Name=\"{name}\" Id=\"{{1}}\" SpecialFunc=\"None\">\n    \
             <Declaration><![CDATA[{decl}]]></Declaration>\n    <Implementation>\n      \
             <ST><![CDATA[{body}]]></ST>\n    </Implementation>\n  </POU>\n</TcPlcObject>\n"
        )
    }
    let dir = tempfile::tempdir().unwrap();
    let main = write_file(
        dir.path(),
        "MAIN.TcPOU",
        &pou(
            "MAIN",
            "PROGRAM MAIN\nVAR\n\tn : INT;\n\tarr : ARRAY[0..2] OF INT := [5, 6, 7];\n\tok : BOOL;\n\tv : INT;\nEND_VAR\n",
            "n := n + 1;\nP_Sub(nIn := n, bOut => ok);\nok := ok AND_THEN P_Sub.nCount > 1;\n\
             IF n > 2 OR_ELSE arr[n] > 5 THEN v := v + 1; END_IF",
        ),
    );
    let sub = write_file(
        dir.path(),
        "P_Sub.TcPOU",
        &pou(
            "P_Sub",
            "PROGRAM P_Sub\nVAR_INPUT\n\tnIn : INT;\nEND_VAR\nVAR_OUTPUT\n\tbOut : BOOL;\nEND_VAR\nVAR\n\tnCount : INT;\nEND_VAR\n",
            "nCount := nCount + 1;\nbOut := nIn > 1;",
        ),
    );
    // P_Sub runs only when MAIN calls it (once a cycle); arr[3] is never read
    let (trace, stderr) = run_traced_files(&[&main, &sub], 4, "MAIN.ok,MAIN.v,P_Sub.nCount");
    assert_eq!(
        trace,
        "cycle,time_ms,MAIN.ok,MAIN.v,P_Sub.nCount\n0,0,0,1,1\n1,10,1,2,2\n2,20,1,3,3\n3,30,1,4,4\n"
    );
    assert!(!stderr.contains("out of range"), "{stderr}");
    assert!(stderr.contains("warning[W0324]"), "{stderr}");
}

// ------------------------------------------------------------------ 2. AND_THEN / OR_ELSE

/// A FUNCTION that counts its calls (through a VAR_IN_OUT) guarded by AND_THEN and OR_ELSE: it
/// runs only when the left operand does not decide (3 calls a cycle, not 6); an index past the
/// array's end is never read; a WHILE condition guards its own index; the operators nest.
#[test]
fn and_then_and_or_else_evaluate_their_right_operand_only_when_needed() {
    let src = "FUNCTION Count : BOOL\nVAR_INPUT v : BOOL; END_VAR\nVAR_IN_OUT n : INT; END_VAR\n\
               n := n + 1;\nCount := v;\nEND_FUNCTION\n\
               PROGRAM Main\nVAR\n  i : INT := 2; arr : ARRAY[0..3] OF INT := [1, 2, 3, 4];\n  \
               calls : INT; a : BOOL; b : BOOL; c : BOOL; d : BOOL; k : INT;\nEND_VAR\n\
               i := i + 1;\n\
               a := i <= 3 AND_THEN arr[i] = 4;\n\
               b := FALSE AND_THEN Count(TRUE, calls);\n\
               c := TRUE OR_ELSE Count(FALSE, calls);\n\
               d := (i > 100 OR_ELSE Count(TRUE, calls)) AND_THEN (Count(FALSE, calls) OR_ELSE Count(TRUE, calls));\n\
               k := 0;\nWHILE k <= 3 AND_THEN arr[k] <> 3 DO\n  k := k + 1;\nEND_WHILE;\n\
               END_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    let f = write_file(dir.path(), "guards.st", src);
    let (trace, stderr) = run_traced(
        &f,
        3,
        "Main.i,Main.a,Main.b,Main.c,Main.d,Main.calls,Main.k",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,Main.i,Main.a,Main.b,Main.c,Main.d,Main.calls,Main.k\n\
         0,0,3,1,0,1,1,3,2\n1,10,4,0,0,1,1,6,2\n2,20,5,0,0,1,1,9,2\n"
    );
    assert!(!stderr.contains("out of range"), "{stderr}");
    assert_eq!(stderr.matches("warning[W0324]").count(), 1, "{stderr}");
    // the same with AND: the index runs past the array (the run says so) and Count runs always
    let plain = src.replace("AND_THEN", "AND").replace("OR_ELSE", "OR");
    let f = write_file(dir.path(), "plain.st", &plain);
    let out = common::ladderc()
        .args(["run"])
        .arg(&f)
        .args(["--cycles", "3", "--trace", "-", "--watch", "Main.calls"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("array index out of range"), "{stderr}");
    assert_eq!(
        column(&String::from_utf8_lossy(&out.stdout), "Main.calls"),
        [5.0, 10.0, 15.0]
    );
}

/// In a PLCopen XML ST body: the guarded call does not run when the left operand decides.
#[test]
fn and_then_in_a_plcopen_st_body_short_circuits() {
    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="ladderc" productName="tests" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="guards"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="tick" pouType="function"><interface><returnType><BOOL/></returnType>
      <inOutVars><variable name="n"><type><INT/></type></variable></inOutVars>
    </interface><body><ST><xhtml:p><![CDATA[n := n + 1;
tick := TRUE;]]></xhtml:p></ST></body></pou>
    <pou name="main" pouType="program"><interface>
      <localVars><variable name="cyc"><type><INT/></type></variable>
      <variable name="calls"><type><INT/></type></variable>
      <variable name="q"><type><BOOL/></type></variable></localVars>
    </interface><body><ST><xhtml:p><![CDATA[cyc := cyc + 1;
q := (cyc MOD 2 = 0) AND_THEN tick(n := calls);]]></xhtml:p></ST></body></pou>
  </pous></types>
  <instances><configurations><configuration name="cfg"><resource name="res">
    <task name="cyclic" priority="1" interval="T#10ms"><pouInstance name="main" typeName="main"/></task>
  </resource></configuration></configurations></instances>
</project>
"#;
    let dir = tempfile::tempdir().unwrap();
    let f = write_file(dir.path(), "guards.xml", xml);
    let (trace, _) = run_traced(&f, 4, "main.q,main.calls");
    assert_eq!(
        trace,
        "cycle,time_ms,main.q,main.calls\n0,0,0,0\n1,10,1,1\n2,20,0,1\n3,30,1,2\n"
    );
}

/// Operands that are not BOOL are one E3105 each. A method call in the right operand, from
/// outside the block and inside it, was E0108; it now runs only when the left operand does not
/// decide (`tests/tests/struckig_constructs_run.rs` runs it).
#[test]
fn method_calls_and_non_bool_operands_after_and_then_are_located_errors() {
    let src = "FUNCTION_BLOCK Fb\nVAR_OUTPUT n : INT; END_VAR\n\
               METHOD Ok : BOOL\nn := n + 1;\nOk := TRUE;\nEND_METHOD\n\
               METHOD Both : BOOL\nBoth := n > 0 AND_THEN Ok();\nEND_METHOD\nEND_FUNCTION_BLOCK\n\
               PROGRAM Main\nVAR f : Fb; x : BOOL; i : INT; END_VAR\n\
               x := x OR_ELSE f.Ok();\nx := i AND_THEN x;\nEND_PROGRAM\n";
    let (code, lines) = check_text("m.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let heads: Vec<&str> = lines
        .iter()
        .filter(|l| l.contains("error["))
        .map(|l| l.split_once(" (hint").map_or(l.as_str(), |(h, _)| h))
        .collect();
    assert_eq!(
        heads,
        vec![
            "m.st:14:6: error[E3105]: the operand of AND_THEN must be BOOL, but this expression \
             is INT",
        ]
    );
}

/// An action of a program in no resource, called from the configured program, runs on the
/// program's own instance (its body never runs: nothing calls the program itself). Before: E3135
/// "has no instance in the configuration".
#[test]
fn an_action_of_a_program_in_no_resource_runs_on_its_own_instance() {
    let dir = tempfile::tempdir().unwrap();
    let f = write_file(
        dir.path(),
        "act.st",
        "PROGRAM counter\nVAR n : INT; END_VAR\nn := n + 100;\nEND_PROGRAM\n\
         ACTIONS\nACTION Bump:\nn := n + 5;\nEND_ACTION\nEND_ACTIONS\n\
         PROGRAM other\nVAR m : INT; seen : INT; END_VAR\nm := m + 1;\n\
         IF m >= 2 THEN counter.Bump(); END_IF;\nseen := counter.n;\nEND_PROGRAM\n\
         CONFIGURATION Cfg\nRESOURCE Res ON PLC\nTASK Main(INTERVAL := T#10ms, PRIORITY := 1);\n\
         PROGRAM O WITH Main : other;\nEND_RESOURCE\nEND_CONFIGURATION\n",
    );
    let (trace, _) = run_traced(&f, 3, "O.seen,counter.n");
    assert_eq!(
        trace,
        "cycle,time_ms,O.seen,counter.n\n0,0,0,0\n1,10,5,5\n2,20,10,10\n"
    );
}

// ------------------------------------------------------------------ 3. `GVL.N` in text files

/// A CODESYS global variable list object exported as text (`GVL.txt`: `{attribute
/// 'qualified_only'}` and a CONSTANT list, one constant defined by another) is the list `GVL`: a
/// program's bounds (`ARRAY[1..GVL.nJoints]`, `STRING(GVL.MAX_SIZE)`) and body (`GVL.nJoints`)
/// name its constants qualified, in `.txt`, `.st` and `.il` files. Before: E0011 at the `.` of
/// the bound (the remaining wrong file of `unseen_projects_r10.rs`), E1001 at `GVL` in a body.
#[test]
fn qualified_list_constants_of_a_text_gvl_object_bound_arrays_and_run_in_bodies() {
    let dir = tempfile::tempdir().unwrap();
    let gvl_text = "{attribute 'qualified_only'}\nVAR_GLOBAL\nEND_VAR\nVAR_GLOBAL CONSTANT\n\
                    \tnJoints:INT:=5;\n\tMAX_SIZE:INT:=nJoints;\nEND_VAR\n";
    let gvl = write_file(dir.path(), "GVL.txt", gvl_text);
    let prg = write_file(
        dir.path(),
        "PLC_PRG.txt",
        "PROGRAM PLC_PRG\nVAR\n\tq : ARRAY[1..GVL.nJoints] OF REAL;\n\tname : STRING(GVL.MAX_SIZE);\n\
         \tn : INT;\n\tsum : INT;\nEND_VAR\n\
         n := GVL.nJoints;\nq[GVL.nJoints] := 1.5;\nsum := sum + GVL.MAX_SIZE * 2;\nname := 'abc';\n\
         END_PROGRAM\n",
    );
    let (trace, _) = run_traced_files(
        &[&gvl, &prg],
        2,
        "PLC_PRG.n,PLC_PRG.sum,PLC_PRG.q[5],PLC_PRG.name",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,PLC_PRG.n,PLC_PRG.sum,PLC_PRG.q[5],PLC_PRG.name\n\
         0,0,5,10,1.5,\"abc\"\n1,10,5,20,1.5,\"abc\"\n"
    );
    // `.st` and IL: the same list as `GVL.st`, an IL program bounded and reading it qualified
    let gvl_st = write_file(dir.path(), "GVL.st", gvl_text);
    let il = write_file(
        dir.path(),
        "main_il.il",
        "PROGRAM MainIl\nVAR\n  buf : ARRAY[0..GVL.nJoints] OF INT;\n  n : INT;\nEND_VAR\n\
         LD GVL.MAX_SIZE\nADD 1\nST n\nST buf[GVL.nJoints]\nEND_PROGRAM\n",
    );
    let (trace, _) = run_traced_files(&[&gvl_st, &il], 1, "MainIl.n,MainIl.buf[5]");
    assert_eq!(trace, "cycle,time_ms,MainIl.n,MainIl.buf[5]\n0,0,6,6\n");
}

/// A globals-only file named like a POU of the project (`Main.st` beside `PROGRAM Main`) gives
/// its list no name (the name is taken): its members are used unqualified, as before.
#[test]
fn a_globals_file_named_like_a_pou_stays_an_unnamed_list() {
    let dir = tempfile::tempdir().unwrap();
    let globals = write_file(
        dir.path(),
        "Main.st",
        "VAR_GLOBAL\n  level : INT := 7;\nEND_VAR\n",
    );
    let prg = write_file(
        dir.path(),
        "prog.st",
        "PROGRAM Main\nVAR_EXTERNAL level : INT; END_VAR\nVAR x : INT; END_VAR\n\
         x := level * 2;\nEND_PROGRAM\n",
    );
    let (trace, _) = run_traced_files(&[&globals, &prg], 1, "Main.x");
    assert_eq!(trace, "cycle,time_ms,Main.x\n0,0,14\n");
}

// ------------------------------------------------------------------ 4. instances with arguments

/// IEC 61131-3 edition 3's structured initial value of an instance (`t : TON := (PT := T#20ms)`,
/// `f : FB_X := (a := 1, k := 10)`, inputs and internal variables) runs; CODESYS's and TwinCAT's
/// `f : FB_X(a := 1);` passes FB_init arguments; FB_X has no FB_init (`fb_init_run.rs` runs those
/// that do): one E0329 at the argument list per declaration (named or positional), in `.st` and TwinCAT files, and nothing
/// else (a CASE label's call `1: f(a := 2);` is no declaration; `STRING(10)`, `INT(0..10)` are a
/// length and a subrange). Before: E0011 "unexpected `a`".
#[test]
fn structured_instance_values_run_and_fb_init_arguments_are_one_e0329_each() {
    let fb = "FUNCTION_BLOCK FB_X\nVAR_INPUT a : INT := 5; END_VAR\nVAR_OUTPUT q : INT; END_VAR\n\
              VAR k : INT; END_VAR\nq := a + k;\nEND_FUNCTION_BLOCK\n";
    let dir = tempfile::tempdir().unwrap();
    let f = write_file(
        dir.path(),
        "init.st",
        &format!(
            "{fb}PROGRAM Main\nVAR\n  t : TON := (PT := T#20ms);\n  f : FB_X := (a := 1, k := 10);\n  \
             q : INT; done : BOOL;\nEND_VAR\nt(IN := TRUE);\ndone := t.Q;\nf();\nq := f.q;\nEND_PROGRAM\n"
        ),
    );
    let (trace, _) = run_traced(&f, 3, "Main.q,Main.done");
    assert_eq!(
        trace,
        "cycle,time_ms,Main.q,Main.done\n0,0,11,0\n1,10,11,0\n2,20,11,1\n"
    );
    let src = format!(
        "{fb}PROGRAM Main\nVAR\n  f : FB_X(a := 1);\n  g : FB_X(2);\n  s : STRING(10);\n  \
         r : INT(0..10);\n  q : INT;\nEND_VAR\nCASE q OF\n  1: f(a := 2);\nEND_CASE;\n\
         q := f.q + g.q;\nEND_PROGRAM\n"
    );
    let want = |line: u32| {
        format!(
            "args.st:{line}:11: error[E0329]: `FB_X` has no FB_init method to take these arguments"
        )
    };
    assert_eq!(rejected_heads("args.st", &src), vec![want(9), want(10)]);
    // a TwinCAT object: the same, located in the .TcPOU
    let tc = write_file(
        dir.path(),
        "MAIN.TcPOU",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  \
         <POU Name=\"MAIN\" Id=\"{1}\" SpecialFunc=\"None\">\n    \
         <Declaration><![CDATA[PROGRAM MAIN\nVAR\n\tfbTon : TON(PT := T#1S);\nEND_VAR\n]]></Declaration>\n    \
         <Implementation>\n      <ST><![CDATA[fbTon(IN := TRUE);]]></ST>\n    </Implementation>\n  \
         </POU>\n</TcPlcObject>\n",
    );
    let out = common::ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&tc)
        .output()
        .unwrap();
    let heads = common::diagnostic_heads(&out.stderr, dir.path(), false);
    assert_eq!(out.status.code(), Some(1), "{heads:?}");
    assert_eq!(
        heads,
        ["MAIN.TcPOU:6:13: error[E0329]: `TON` has no FB_init method to take these arguments"]
    );
}

// ------------------------------------------------------------------ 5. subranges with named bounds

/// Subrange bounds that name integer constants or are constant expressions (`INT(cMin..cMax)`,
/// `UINT(0..cMax + 1)`, `DINT(-cMax..-cMin)`), also qualified by a list (`UINT(0..GVL.N)` in `.st`
/// and TwinCAT files): the range is the constants' values (a literal outside it is E1017 naming
/// the evaluated range). Before: E0011 at the name, E0001 at `+`.
#[test]
fn subranges_with_named_and_qualified_bounds_take_the_constants_values() {
    let dir = tempfile::tempdir().unwrap();
    let consts = "VAR_GLOBAL CONSTANT\n  cMin : INT := 2;\n  cMax : INT := 9;\nEND_VAR\n";
    let body = |assign: &str| {
        format!(
            "{consts}PROGRAM Main\nVAR\n  r : INT(cMin..cMax) := 3;\n  u : UINT(0..cMax + 1) := 10;\n  \
             w : DINT(-cMax..-cMin) := -5;\nEND_VAR\n{assign}\nEND_PROGRAM\n"
        )
    };
    let f = write_file(dir.path(), "ranges.st", &body("r := 9;\nu := 0;\nw := -9;"));
    let (trace, _) = run_traced(&f, 1, "Main.r,Main.u,Main.w");
    assert_eq!(trace, "cycle,time_ms,Main.r,Main.u,Main.w\n0,0,9,0,-9\n");
    let heads = rejected_heads("out.st", &body("r := 10;\nu := 11;\nw := -1;"));
    assert_eq!(
        heads,
        [
            "out.st:11:6: error[E1017]: literal 10 does not fit INT (2..9)",
            "out.st:12:6: error[E1017]: literal 11 does not fit UINT (0..10)",
            "out.st:13:6: error[E1017]: literal -1 does not fit DINT (-9..-2)",
        ]
    );
    // qualified by a list: a `.st` GVL object and a TwinCAT GVL
    let gvl = write_file(
        dir.path(),
        "GVL.st",
        "VAR_GLOBAL CONSTANT\n  nMax : INT := 5;\nEND_VAR\n",
    );
    let main = write_file(
        dir.path(),
        "main.st",
        "PROGRAM Main\nVAR\n  u : UINT(0..GVL.nMax) := 3;\nEND_VAR\nu := 5;\nEND_PROGRAM\n",
    );
    let (trace, _) = run_traced_files(&[&gvl, &main], 1, "Main.u");
    assert_eq!(trace, "cycle,time_ms,Main.u\n0,0,5\n");
    let tc_gvl = write_file(
        dir.path(),
        "GVL_Const.TcGVL",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  \
         <GVL Name=\"GVL_Const\" Id=\"{9}\">\n    <Declaration><![CDATA[{attribute 'qualified_only'}\n\
         VAR_GLOBAL CONSTANT\n\tcTop : INT := 4;\nEND_VAR\n]]></Declaration>\n  </GVL>\n</TcPlcObject>\n",
    );
    let tc_main = write_file(
        dir.path(),
        "MAIN.TcPOU",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  \
         <POU Name=\"MAIN\" Id=\"{1}\" SpecialFunc=\"None\">\n    \
         <Declaration><![CDATA[PROGRAM MAIN\nVAR\n\tnSlot : UINT(1..GVL_Const.cTop);\nEND_VAR\n]]></Declaration>\n    \
         <Implementation>\n      <ST><![CDATA[nSlot := 4;]]></ST>\n    </Implementation>\n  \
         </POU>\n</TcPlcObject>\n",
    );
    let (trace, _) = run_traced_files(&[&tc_gvl, &tc_main], 1, "MAIN.nSlot");
    assert_eq!(trace, "cycle,time_ms,MAIN.nSlot\n0,0,4\n");
}
