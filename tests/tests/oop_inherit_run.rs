//! Edition 3 inheritance (issue #13): `FUNCTION_BLOCK Child EXTENDS Base`, `SUPER^()`,
//! `SUPER^.M()`, late binding of methods called inside inherited code, `INTERFACE` and `IMPLEMENTS`,
//! `FINAL` and `ABSTRACT`, run end to end through `ladderc run` on files written for these tests
//! (`fixtures/oop/`): a chain of three levels split over two files, and one pair of blocks with an
//! interface both as an `.st` file and as TwinCAT 3 object files (`.TcPOU`, `.TcIO`). Each refused
//! construct is one located diagnostic (E0330-E0336, E0340).

mod common;
use common::{column, rejected_heads, run_traced, run_traced_files};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/oop")
        .join(rel)
}

/// FB_Top EXTENDS FB_Mid EXTENDS FB_Base (in another file, FB_Mid declared after FB_Top): each
/// body runs its base's through `SUPER^()`; FB_Base's body calls `THIS^.Note(1)` and FB_Mid's
/// `Note(code := 5)`, which on a FB_Top instance is FB_Top's override (late binding: `+ 2`), on a
/// FB_Mid instance FB_Base's; `Twice` of FB_Top adds 1000 to FB_Mid's `SUPER^.Twice(v)`; the
/// derived instances' inherited variables are traced as `top.count`.
#[test]
fn a_three_level_chain_runs_bases_through_super_and_late_binds_overridden_methods() {
    let (trace, stderr) = run_traced_files(
        &[&fixture("chain.st"), &fixture("chain_base.st")],
        3,
        "Main.mid.count,Main.mid.log,Main.top.count,Main.top.log,Main.top.extra,Main.r",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    // FB_Mid: count += 2 (FB_Base's body), log: Note(1) then Note(5), both FB_Base's
    assert_eq!(column(&trace, "Main.mid.count"), [2.0, 4.0, 6.0]);
    assert_eq!(column(&trace, "Main.mid.log"), [15.0, 515.0, 515.0]);
    // FB_Top: FB_Mid's body, then FB_Base's, run on the FB_Top instance: FB_Top's Note each time
    assert_eq!(column(&trace, "Main.top.count"), [3.0, 6.0, 9.0]);
    assert_eq!(column(&trace, "Main.top.log"), [37.0, 737.0, 737.0]);
    assert_eq!(column(&trace, "Main.top.extra"), [1.0, 2.0, 3.0]);
    assert_eq!(column(&trace, "Main.r"), [1010.0, 1010.0, 1010.0]);
}

const PAIR_WATCH: &str = "MAIN.fbDimmer.bLit,MAIN.fbDimmer.nSwitched,MAIN.fbDimmer.nLevel,MAIN.bOk";

/// FB_Dimmer EXTENDS FB_Lamp IMPLEMENTS I_Switch: the inherited method `Switch` (the interface's,
/// checked) lights the lamp for 5 cycles; the dimmer's body runs the lamp's (`SUPER^()`, counting
/// lit cycles) and ramps its own level.
fn assert_pair_trace(trace: &str) {
    assert_eq!(
        column(trace, "MAIN.fbDimmer.bLit"),
        [1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0]
    );
    assert_eq!(
        column(trace, "MAIN.bOk"),
        column(trace, "MAIN.fbDimmer.bLit")
    );
    assert_eq!(
        column(trace, "MAIN.fbDimmer.nSwitched"),
        [1.0, 2.0, 3.0, 4.0, 5.0, 5.0, 5.0]
    );
    assert_eq!(
        column(trace, "MAIN.fbDimmer.nLevel"),
        [25.0, 50.0, 75.0, 100.0, 100.0, 0.0, 0.0]
    );
}

#[test]
fn the_same_blocks_as_st_and_as_twincat_files_give_the_same_trace() {
    let (st, stderr) = run_traced(&fixture("pair.st"), 7, PAIR_WATCH);
    assert!(!stderr.contains("error"), "{stderr}");
    assert_pair_trace(&st);
    let tc: Vec<PathBuf> = [
        "I_Switch.TcIO",
        "FB_Lamp.TcPOU",
        "FB_Dimmer.TcPOU",
        "MAIN.TcPOU",
    ]
    .iter()
    .map(|f| fixture(&format!("twincat/{f}")))
    .collect();
    let files: Vec<&Path> = tc.iter().map(PathBuf::as_path).collect();
    let (twincat, stderr) = run_traced_files(&files, 7, PAIR_WATCH);
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(twincat, st);
}

const BASE: &str =
    "FUNCTION_BLOCK FB_Base\nVAR_INPUT n : INT; END_VAR\nVAR_OUTPUT q : INT; END_VAR\nq := n;\n\
METHOD Get : INT\nVAR_INPUT k : INT; END_VAR\nGet := q + k;\nEND_METHOD\nEND_FUNCTION_BLOCK\n";

fn heads(src: &str) -> Vec<String> {
    rejected_heads("oop.st", &format!("{BASE}{src}"))
}

#[test]
fn an_interface_method_missing_or_of_another_signature_is_one_located_error() {
    let itf = "INTERFACE I_Get\nMETHOD Get : INT\nVAR_INPUT k : INT; END_VAR\nEND_METHOD\nEND_INTERFACE\n\
INTERFACE I_Stop EXTENDS I_Get\nMETHOD Stop\nEND_METHOD\nEND_INTERFACE\n";
    // inherited from FB_Base, with the interface's signature: accepted, the method runs; FB_D's
    // body (empty) replaces FB_Base's, which would run only through `SUPER^()`: q stays 0
    let ok = format!(
        "{BASE}{itf}FUNCTION_BLOCK FB_D EXTENDS FB_Base IMPLEMENTS I_Get\nEND_FUNCTION_BLOCK\n\
PROGRAM Main\nVAR d : FB_D; r : INT; END_VAR\nd(n := 4);\nr := d.Get(k := 3);\nEND_PROGRAM\n"
    );
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("ok.st");
    std::fs::write(&f, ok).unwrap();
    let (trace, _) = run_traced(&f, 2, "Main.r,Main.d.q,Main.d.n");
    assert_eq!(column(&trace, "Main.r"), [3.0, 3.0]);
    assert_eq!(column(&trace, "Main.d.q"), [0.0, 0.0]);
    assert_eq!(column(&trace, "Main.d.n"), [4.0, 4.0]);
    // I_Stop extends I_Get: Stop is missing
    assert_eq!(
        heads(&format!(
            "{itf}FUNCTION_BLOCK FB_D EXTENDS FB_Base IMPLEMENTS I_Stop\nEND_FUNCTION_BLOCK\n"
        )),
        ["oop.st:19:48: error[E0335]: `FB_D` IMPLEMENTS `I_Stop` but has no method `Stop`"]
    );
    // Get returns INT in the interface, DINT in the block
    assert_eq!(
        heads(&format!(
            "{itf}FUNCTION_BLOCK FB_E IMPLEMENTS I_Get\nMETHOD Get : DINT\nVAR_INPUT k : INT; END_VAR\nGet := k;\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
        )),
        ["oop.st:20:8: error[E0335]: method `Get` of `FB_E` is `Get(k : INT) : DINT`, but interface `I_Get` declares `Get(k : INT) : INT`"]
    );
    assert_eq!(
        heads("FUNCTION_BLOCK FB_F IMPLEMENTS I_None\nEND_FUNCTION_BLOCK\n"),
        ["oop.st:10:32: error[E0330]: `FB_F` IMPLEMENTS `I_None`, which names no INTERFACE of the project"]
    );
}

#[test]
fn each_refused_inheritance_is_one_located_diagnostic() {
    assert_eq!(
        heads("FUNCTION_BLOCK FB_X EXTENDS FB_Nowhere\nq := 1;\nEND_FUNCTION_BLOCK\n"),
        ["oop.st:10:29: error[E0330]: `FB_X` EXTENDS `FB_Nowhere`, which names no function block of the project"]
    );
    assert_eq!(
        heads("FUNCTION_BLOCK A EXTENDS B\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK B EXTENDS A\nEND_FUNCTION_BLOCK\n"),
        [
            "oop.st:10:26: error[E0331]: `A` extends itself through its bases: A -> B -> A",
            "oop.st:12:26: error[E0331]: `B` extends itself through its bases: B -> A -> B"
        ]
    );
    assert_eq!(
        heads("FUNCTION_BLOCK FINAL FB_F\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK FB_G EXTENDS FB_F\nEND_FUNCTION_BLOCK\n"),
        ["oop.st:12:29: error[E0332]: `FB_G` EXTENDS `FB_F`, which is FINAL"]
    );
    assert_eq!(
        heads("FUNCTION_BLOCK FB_D EXTENDS FB_Base\nVAR n : INT; END_VAR\nq := n;\nEND_FUNCTION_BLOCK\n"),
        ["oop.st:11:5: error[E0334]: `FB_D` declares `n`, which its base `FB_Base` declares already"]
    );
    assert_eq!(
        heads("FUNCTION_BLOCK ABSTRACT FB_A EXTENDS FB_Base\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR a : FB_A; END_VAR\na(n := 1);\nEND_PROGRAM\n"),
        ["oop.st:13:9: error[E0333]: `a` is an instance of `FB_A`, which is ABSTRACT"]
    );
    assert_eq!(
        heads("FUNCTION_BLOCK FB_S\nVAR x : INT; END_VAR\nSUPER^();\nEND_FUNCTION_BLOCK\n"),
        ["oop.st:12:6: error[E0108]: `SUPER^` in a POU that extends no function block"]
    );
}

/// A variable of an interface type (a reference with dynamic dispatch) is one error at its type;
/// the body of its POU is not compiled, so its uses give nothing more.
/// A variable of an interface type holds an instance of a block that implements it (see
/// `oop_interface_run.rs`): FB_Base does not implement I_Get (E0340 at the value), and an
/// interface variable's initial value other than 0 or an instance is E0336.
#[test]
fn an_interface_variable_given_what_does_not_implement_it_or_an_initial_value_is_one_located_error()
{
    assert_eq!(
        heads("INTERFACE I_Get\nMETHOD Get : INT\nVAR_INPUT k : INT; END_VAR\nEND_METHOD\nEND_INTERFACE\n\
PROGRAM Main\nVAR b : FB_Base; itf : I_Get; j : I_Get := 5; r : INT; END_VAR\nitf := b;\nr := itf.Get(k := 1);\nEND_PROGRAM\n"),
        [
            "oop.st:16:31: error[E0336]: `j` of interface type `I_Get` has an initial value that is not compiled",
            "oop.st:17:8: error[E0340]: function block `FB_Base` does not implement interface `I_Get`",
        ]
    );
}

/// CODESYS's PLCopen XML writes EXTENDS / IMPLEMENTS in the vendor data of the POU's
/// interface (`data name=".../pouinheritance"`, `<Inheritance><Extends>`): compiled as in ST
/// text (`codesys_xml_oop_run.rs`), so a base the file does not declare is the ST front end's one
/// E0330 at the `<Extends>` text (no error per inherited name, nor for the interface it names).
#[test]
fn inheritance_in_codesys_plcopen_xml_of_a_missing_base_is_one_located_error() {
    let fixture =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/real_gaps/xml_methods.xml");
    let src = std::fs::read_to_string(fixture).unwrap().replacen(
        "</interface>",
        "<addData><data name=\"http://www.3s-software.com/plcopenxml/pouinheritance\" handleUnknown=\"implementation\">\
         <Inheritance><Extends>FB_Base</Extends><Implements>I_Axis</Implements></Inheritance></data></addData></interface>",
        1,
    );
    let errors: Vec<String> = rejected_heads("inh.xml", &src)
        .into_iter()
        .filter(|l| l.contains("error["))
        .collect();
    assert_eq!(
        errors,
        ["inh.xml:14:137: error[E0330]: `FB_Axis` EXTENDS `FB_Base`, which names no function block of the project [POU `FB_Axis`]"]
    );
}

/// TwinCAT projects write `IMPLEMENTS I_HMI;` (a `;` after the clause), derived blocks whose only
/// code is their methods (no body: read as ST, not as an empty IL body), and bases of a library's
/// namespace (`EXTENDS TcUnit.FB_TestSuite`): the first two compile and run; the third is one
/// E0330 naming the qualified base, without a cascade from its methods' declarations: the
/// instance initialised with FB_init arguments (`FB_Base(n := 1)`) is its own one E0329, found
/// before the declarations are parsed.
#[test]
fn a_semicolon_after_the_clause_a_block_of_methods_only_and_a_library_base() {
    let itf = "INTERFACE I_Get\nMETHOD Get : INT\nVAR_INPUT k : INT; END_VAR\nEND_METHOD\nEND_INTERFACE\n";
    let src = format!(
        "{BASE}{itf}FUNCTION_BLOCK FB_M EXTENDS FB_Base IMPLEMENTS I_Get;\n\
METHOD Get : INT\nVAR_INPUT k : INT; END_VAR\nGet := SUPER^.Get(k) * 10;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\
PROGRAM Main\nVAR m : FB_M; r : INT; END_VAR\nm(n := 2);\nr := m.Get(k := 1);\nEND_PROGRAM\n"
    );
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("m.st");
    std::fs::write(&f, src).unwrap();
    let (trace, stderr) = run_traced(&f, 1, "Main.r");
    assert!(!stderr.contains("error"), "{stderr}");
    // FB_M has no body: FB_Base's (q := n) does not run, q stays 0
    assert_eq!(column(&trace, "Main.r"), [10.0]);
    assert_eq!(
        heads("FUNCTION_BLOCK FB_T EXTENDS TcUnit.FB_TestSuite\nMETHOD Test\nVAR_INST x : FB_Base(n := 1) := (n := 2); END_VAR\nx();\nEND_METHOD\nEND_FUNCTION_BLOCK\n"),
        [
            "oop.st:10:29: error[E0330]: `FB_T` EXTENDS `TcUnit.FB_TestSuite`, which names no function block of the project",
            "oop.st:12:21: error[E0329]: `FB_Base` has no FB_init method to take these arguments",
        ]
    );
}

/// Without `--watch`, the trace holds the variables the program declares and none of the
/// compiler's own (method locals, class tags: a name part starting with `__`, which no IEC
/// identifier does); `--watch` still names one, and `ladderc run` passes `--list` no such name.
#[test]
fn the_default_trace_leaves_out_the_compilers_own_variables() {
    let out = common::ladderc()
        .args(["--message-format", "short", "run"])
        .args([fixture("chain.st"), fixture("chain_base.st")])
        .args(["--cycles", "2", "--trace", "-"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let trace = String::from_utf8_lossy(&out.stdout);
    let header: Vec<String> = common::split_csv(trace.lines().next().unwrap());
    assert!(
        header
            .iter()
            .all(|h| !h.split('.').any(|p| p.starts_with("__"))),
        "{header:?}"
    );
    for want in ["Main.top.count", "Main.top.log", "Main.top.extra", "Main.r"] {
        assert!(header.iter().any(|h| h == want), "{want} in {header:?}");
    }
    assert_eq!(column(&trace, "Main.top.count"), [3.0, 6.0]);
    // a hidden variable is still there for --watch: Twice's input `v` of the last call
    let (hidden, _) = run_traced_files(
        &[&fixture("chain.st"), &fixture("chain_base.st")],
        1,
        "Main.top.__M_TWICE_V",
    );
    assert_eq!(column(&hidden, "Main.top.__M_TWICE_V"), [5.0]);
}
