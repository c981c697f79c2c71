//! Round 25 of unseen projects (issue #13), B&R Automation Studio projects, run end to end through
//! `ladderc run`:
//! - a FOR or WHILE loop in both `PROGRAM _INIT` and `_CYCLIC` of one program folder (one
//!   `Main.st`, or `Init.st` and `Cyclic.st`) runs (before: E1010 "label `_ST_FOR1` is defined
//!   twice" and E1002 "`_ST_T1` is declared twice", names of ladderc's own that the source does not
//!   hold).
//! - two program folders whose private `Types.typ` (`Private="true"` in `IEC.prg`, Automation
//!   Studio's local data types) declare the same type alike each run with their own (before: E1002
//!   "`Recipe_typ` is declared twice").
//! - B&R's `runtime.fun` (`r_trig`, `f_trig`) and `standard.fun` (`R_TRIG`, `F_TRIG`) given together
//!   are both system-library stubs, one note W0021 each, and the standard R_TRIG runs (before:
//!   W1446 "hides the standard function block" and E1002).
//! - a program's actions kept in a package inside its folder (`<Object Type="Package">` in
//!   `IEC.prg`, nested packages listed in their `.pkg`) are the program's actions (before: E1060
//!   "action outside any POU" and an E1001 with W1431 at each call).
//! - a program folder's `.var` file gets the note W0020 of its program only (before: also W0018
//!   "read as global variables").

mod common;
use common::{column, in_dir, write_in};

const PRG_WITH_TYPES: &str = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Program SubType=\"IEC\" xmlns=\"http://br-automation.co.at/AS/Program\">\n  <Files>\n    <File Description=\"Init, cyclic, exit code\">Main.st</File>\n    <File Description=\"Local data types\" Private=\"true\">Types.typ</File>\n    <File Description=\"Local variables\" Private=\"true\">Variables.var</File>\n  </Files>\n</Program>\n";

/// `_INIT` fills an array with a FOR loop whose bound is computed (`SIZEOF(flags) - 1`: a hidden
/// temporary) and counts with a WHILE; `_CYCLIC` sums it with the same kinds of loop. The program
/// runs: `total` is 4 and `steps` 4 in every cycle, written as one `Main.st` and as `Init.st` plus
/// `Cyclic.st`. No diagnostic names a hidden label or temporary.
#[test]
fn loops_in_init_and_cyclic_of_one_program_run() {
    let init = "PROGRAM _INIT
\tFOR i := 0 TO SIZEOF(flags) - 1 DO
\t\tflags[i] := 1;
\tEND_FOR
\tk := 0;
\tWHILE k < 2 DO
\t\tk := k + 1;
\tEND_WHILE
END_PROGRAM
";
    let cyclic = "PROGRAM _CYCLIC
\ttotal := 0;
\tFOR i := 0 TO SIZEOF(flags) - 1 DO
\t\ttotal := total + flags[i];
\tEND_FOR
\tsteps := k;
\tWHILE steps < 4 DO
\t\tsteps := steps + 1;
\tEND_WHILE
END_PROGRAM
";
    let vars = "VAR
\tflags : ARRAY[0..3] OF USINT;
\ti : UINT;
\tk : INT;
\tsteps : INT;
\ttotal : USINT;
END_VAR
";
    for split in [false, true] {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        write_in(d, "Logical/Buttons/Buttons.var", vars);
        let mut args = vec!["run", "--lang", "st", "Logical/Buttons/Buttons.var"];
        if split {
            write_in(d, "Logical/Buttons/Init.st", init);
            write_in(d, "Logical/Buttons/Cyclic.st", cyclic);
            args.extend(["Logical/Buttons/Init.st", "Logical/Buttons/Cyclic.st"]);
        } else {
            write_in(
                d,
                "Logical/Buttons/Buttons.st",
                &format!("{init}\n{cyclic}"),
            );
            args.push("Logical/Buttons/Buttons.st");
        }
        args.extend([
            "--cycles",
            "3",
            "--watch",
            "Buttons.total,Buttons.steps,Buttons.k",
            "--trace",
            "-",
        ]);
        let (code, trace, stderr) = in_dir(d, &args);
        assert_eq!(code, Some(0), "split {split}: {stderr}");
        assert!(!stderr.contains("_ST_"), "{stderr}");
        assert_eq!(column(&trace, "Buttons.total"), vec![4.0; 3], "{trace}");
        assert_eq!(column(&trace, "Buttons.steps"), vec![4.0; 3], "{trace}");
        assert_eq!(column(&trace, "Buttons.k"), vec![2.0; 3], "{trace}");
    }
}

/// Two program folders (`ProgA`, `ProgB`, each with `IEC.prg`) whose private `Types.typ` declare
/// `Recipe_typ` alike (a program copied to another folder): each program runs with its own
/// `recipe` (ProgA counts by 1, ProgB by 10). Two private declarations of one name that differ
/// are each program's own since round 34 (before: one E1002).
#[test]
fn two_programs_with_the_same_private_type_run() {
    let types = "TYPE
\tRecipe_typ : STRUCT
\t\tspeed : REAL;
\t\tcount : INT;
\tEND_STRUCT;
END_TYPE
";
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (prog, step) in [("ProgA", 1), ("ProgB", 10)] {
        write_in(d, &format!("Logical/{prog}/IEC.prg"), PRG_WITH_TYPES);
        write_in(d, &format!("Logical/{prog}/Types.typ"), types);
        write_in(
            d,
            &format!("Logical/{prog}/Variables.var"),
            "VAR\n\trecipe : Recipe_typ;\nEND_VAR\n",
        );
        write_in(
            d,
            &format!("Logical/{prog}/Main.st"),
            &format!("PROGRAM _CYCLIC\n\trecipe.count := recipe.count + {step};\nEND_PROGRAM\n"),
        );
    }
    let mut args = vec!["run", "--lang", "st"];
    let files = [
        "Logical/ProgA/Main.st",
        "Logical/ProgA/Types.typ",
        "Logical/ProgA/Variables.var",
        "Logical/ProgB/Main.st",
        "Logical/ProgB/Types.typ",
        "Logical/ProgB/Variables.var",
    ];
    args.extend(files);
    args.extend([
        "--cycles",
        "3",
        "--watch",
        "ProgA.recipe.count,ProgB.recipe.count",
        "--trace",
        "-",
    ]);
    let (code, trace, stderr) = in_dir(d, &args);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("E1002"), "{stderr}");
    assert_eq!(
        column(&trace, "ProgA.recipe.count"),
        vec![1.0, 2.0, 3.0],
        "{trace}"
    );
    assert_eq!(
        column(&trace, "ProgB.recipe.count"),
        vec![10.0, 20.0, 30.0],
        "{trace}"
    );
    // declarations that differ: each program its own (round 34, `br_r34_run.rs`; before: one
    // E1002 at the second, ladderc kept one namespace of types)
    write_in(
        d,
        "Logical/ProgB/Types.typ",
        "TYPE\n\tRecipe_typ : STRUCT\n\t\tcount : INT;\n\tEND_STRUCT;\nEND_TYPE\n",
    );
    let (code, trace, stderr) = in_dir(d, &args);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(
        column(&trace, "ProgB.recipe.count"),
        vec![10.0, 20.0, 30.0],
        "{trace}"
    );
}

/// B&R's `runtime.fun` declares `r_trig` and `standard.fun` `R_TRIG` (system-library stubs, no
/// statements); given together with a program that counts rising edges of `button` with an
/// `R_TRIG`, the program runs on ladderc's R_TRIG (presses 0, 1, 1, 1, 2, 2), each file has its
/// W0021 note, and nothing claims a stub replaces the standard block.
#[test]
fn runtime_and_standard_stubs_of_one_block_run_the_standard_block() {
    let stub = |name: &str| {
        format!(
            "FUNCTION_BLOCK {name} (*implemented in C*)\n\tVAR_INPUT\n\t\tCLK : BOOL;\n\tEND_VAR\n\tVAR_OUTPUT\n\t\tQ : BOOL;\n\tEND_VAR\n\tVAR\n\t\tM : BOOL;\n\tEND_VAR\nEND_FUNCTION_BLOCK\n"
        )
    };
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_in(d, "Logical/Libraries/runtime/runtime.fun", &stub("r_trig"));
    write_in(
        d,
        "Logical/Libraries/standard/standard.fun",
        &stub("R_TRIG"),
    );
    write_in(
        d,
        "Logical/Edge/Main.st",
        "PROGRAM _CYCLIC\n\tedge(CLK := button);\n\tIF edge.Q THEN\n\t\tpresses := presses + 1;\n\tEND_IF\nEND_PROGRAM\n",
    );
    write_in(
        d,
        "Logical/Edge/Variables.var",
        "VAR\n\tedge : R_TRIG;\n\tbutton : BOOL;\n\tpresses : INT;\nEND_VAR\n",
    );
    write_in(
        d,
        "stim.csv",
        "cycle,variable,value\n1,Edge.button,TRUE\n3,Edge.button,FALSE\n4,Edge.button,TRUE\n",
    );
    let (code, trace, stderr) = in_dir(
        d,
        &[
            "run",
            "--lang",
            "st",
            "Logical/Libraries/runtime/runtime.fun",
            "Logical/Libraries/standard/standard.fun",
            "Logical/Edge/Main.st",
            "Logical/Edge/Variables.var",
            "--cycles",
            "6",
            "--stimulus",
            "stim.csv",
            "--watch",
            "Edge.presses",
            "--trace",
            "-",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        !stderr.contains("W1446") && !stderr.contains("E1002"),
        "{stderr}"
    );
    assert_eq!(stderr.matches("note[W0021]").count(), 2, "{stderr}");
    assert_eq!(
        column(&trace, "Edge.presses"),
        vec![0.0, 1.0, 1.0, 1.0, 2.0, 2.0],
        "{trace}"
    );
}

/// Program `Cell` lists a package `Package` in its `IEC.prg`; the package's `Step.st` holds the
/// action `StepAction`, and a package `More` it lists in its `Package.pkg` holds `Double`. Both are
/// the program's actions: `StepAction;` and `Double();` in `_CYCLIC` run them (n = 1, 2, 3 and
/// m = 2, 4, 6), no E1060, no E1001. An actions file in a sub-folder the program does not list as
/// a package stays one E1060 (no cascade at the call: the call is then E1001 once).
#[test]
fn actions_in_a_package_of_the_program_folder_are_its_actions() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_in(
        d,
        "Logical/Cell/IEC.prg",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Program SubType=\"IEC\" xmlns=\"http://br-automation.co.at/AS/Program\">\n  <Objects>\n    <Object Type=\"File\" Description=\"Init, cyclic, exit code\">Main.st</Object>\n    <Object Type=\"File\" Description=\"Local variables\" Private=\"true\">Variables.var</Object>\n    <Object Type=\"Package\">Package</Object>\n  </Objects>\n</Program>\n",
    );
    write_in(
        d,
        "Logical/Cell/Package/Package.pkg",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Package xmlns=\"http://br-automation.co.at/AS/Package\">\n  <Objects>\n    <Object Type=\"File\">Step.st</Object>\n    <Object Type=\"Package\">More</Object>\n  </Objects>\n</Package>\n",
    );
    write_in(
        d,
        "Logical/Cell/Package/More/Package.pkg",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Package xmlns=\"http://br-automation.co.at/AS/Package\">\n  <Objects>\n    <Object Type=\"File\">Double.st</Object>\n  </Objects>\n</Package>\n",
    );
    write_in(
        d,
        "Logical/Cell/Main.st",
        "PROGRAM _CYCLIC\n\tStepAction;\n\tDouble();\nEND_PROGRAM\n",
    );
    write_in(
        d,
        "Logical/Cell/Variables.var",
        "VAR\n\tn : INT;\n\tm : INT;\nEND_VAR\n",
    );
    write_in(
        d,
        "Logical/Cell/Package/Step.st",
        "ACTION StepAction:\n\tn := n + 1;\nEND_ACTION\n",
    );
    write_in(
        d,
        "Logical/Cell/Package/More/Double.st",
        "ACTION Double:\n\tm := n * 2;\nEND_ACTION\n",
    );
    let mut args = vec![
        "run",
        "--lang",
        "st",
        "Logical/Cell/Main.st",
        "Logical/Cell/Variables.var",
        "Logical/Cell/Package/Step.st",
        "Logical/Cell/Package/More/Double.st",
    ];
    args.extend(["--cycles", "3", "--watch", "Cell.n,Cell.m", "--trace", "-"]);
    let (code, trace, stderr) = in_dir(d, &args);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        !stderr.contains("E1060") && !stderr.contains("W1431"),
        "{stderr}"
    );
    assert_eq!(column(&trace, "Cell.n"), vec![1.0, 2.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "Cell.m"), vec![2.0, 4.0, 6.0], "{trace}");
    // `More` no longer listed: its actions file belongs to no program
    write_in(
        d,
        "Logical/Cell/Package/Package.pkg",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Package xmlns=\"http://br-automation.co.at/AS/Package\">\n  <Objects>\n    <Object Type=\"File\">Step.st</Object>\n  </Objects>\n</Package>\n",
    );
    let (code, _, stderr) = in_dir(d, &args);
    assert_eq!(code, Some(1), "{stderr}");
    assert_eq!(stderr.matches("error[E1060]").count(), 1, "{stderr}");
    assert!(
        stderr.contains("Logical/Cell/Package/More/Double.st:1:1: error[E1060]"),
        "{stderr}"
    );
}

/// A program folder's `Variables.var` is its program's (note W0020 at the program); the project's
/// `Global.var` is a global list (note W0018). Only these two notes: no W0018 "read as global
/// variables" for the program's own file.
#[test]
fn a_program_folder_var_file_is_noted_as_the_programs_only() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_in(
        d,
        "Logical/Global.var",
        "VAR\n\tlimit : INT := 3;\nEND_VAR\n",
    );
    write_in(
        d,
        "Logical/Count/Variables.var",
        "VAR\n\tn : INT;\nEND_VAR\n",
    );
    write_in(
        d,
        "Logical/Count/Main.st",
        "PROGRAM _CYCLIC\n\tIF n < limit THEN\n\t\tn := n + 1;\n\tEND_IF\nEND_PROGRAM\n",
    );
    let (code, trace, stderr) = in_dir(
        d,
        &[
            "run",
            "--lang",
            "st",
            "Logical/Global.var",
            "Logical/Count/Variables.var",
            "Logical/Count/Main.st",
            "--cycles",
            "4",
            "--watch",
            "Count.n",
            "--trace",
            "-",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(
        column(&trace, "Count.n"),
        vec![1.0, 2.0, 3.0, 3.0],
        "{trace}"
    );
    let w0018: Vec<&str> = stderr.lines().filter(|l| l.contains("W0018")).collect();
    assert_eq!(w0018.len(), 1, "{stderr}");
    assert!(w0018[0].starts_with("Logical/Global.var:1:1:"), "{stderr}");
    assert!(
        stderr.contains("Logical/Count/Main.st:1:9: note[W0020]"),
        "{stderr}"
    );
    assert!(
        !stderr.contains("Count/Variables.var:1:1: note[W0018]"),
        "{stderr}"
    );
}

/// A RETURN in `_INIT` ends `_INIT`, not the program's first cycle: `_CYCLIC` runs in cycle 1 too
/// (Automation Studio runs `_INIT` once before the cyclic part), so `n` counts 1, 2, 3 and the
/// statement after the RETURN never runs (`k` stays 1). (Before: the joined program returned, `n`
/// counted 0, 1, 2.)
#[test]
fn a_return_in_init_ends_init_and_cyclic_still_runs_in_the_first_cycle() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_in(
        d,
        "Logical/Counter/Counter.var",
        "VAR\n\tk : INT;\n\tn : INT;\nEND_VAR\n",
    );
    write_in(
        d,
        "Logical/Counter/Counter.st",
        "PROGRAM _INIT\n\tk := 1;\n\tIF k = 1 THEN\n\t\tRETURN;\n\tEND_IF\n\tk := 99;\nEND_PROGRAM\n\n\
         PROGRAM _CYCLIC\n\tn := n + 1;\nEND_PROGRAM\n",
    );
    let (code, trace, stderr) = in_dir(
        d,
        &[
            "run",
            "--lang",
            "st",
            "Logical/Counter/Counter.var",
            "Logical/Counter/Counter.st",
            "--cycles",
            "3",
            "--watch",
            "Counter.n,Counter.k",
            "--trace",
            "-",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&trace, "Counter.n"), [1.0, 2.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "Counter.k"), [1.0, 1.0, 1.0], "{trace}");
}
